"""Scene folders and results files as physcensis writes them, made by hand for the report's tests (no solving)."""

from __future__ import annotations

import json
import struct
import zlib
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

# A prompt that tries to close the page's data block and run a script: the report must show it as text.
HOSTILE = '</script><script>window.__pwned = 1</script><img src=x onerror="window.__pwned = 2"> & <!-- "quoted"'


def tiny_png(width: int = 4, height: int = 3, rgb: tuple[int, int, int] = (200, 120, 40)) -> bytes:
    """A real PNG of one colour (the browser test checks that images decode)."""

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    rows = b"".join(b"\x00" + bytes(rgb) * width for _ in range(height))
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b"")


def scene_folder(
    path: Path,
    *,
    prompt: str | None = "a mug on a coaster",
    report_prompt: str | None = None,
    metrics: Mapping[str, Any] | None = None,
    failed: Sequence[tuple[str, str]] = (),
    problems: Sequence[Mapping[str, Any]] = (),
    pending: Sequence[Mapping[str, Any]] = (),
    layout: bool = True,
    render: bool = True,
    batch: Mapping[str, Any] | None = None,
) -> Path:
    """A scene folder: scene.json, report.json, and render.png / layout.png / batch.json when asked."""
    path.mkdir(parents=True, exist_ok=True)
    metrics = dict(metrics if metrics is not None else {"settle_distance_m": 0.001, "objects_placed": 2})
    scene = {"format": "physcensis.scene/1", "seed": 7, "prompt": prompt, "objects": [], "metrics": metrics}
    objects = [{"id": oid, "status": "failed", "reason": why} for oid, why in failed]
    report: dict[str, Any] = {
        "ok": not failed and not pending,
        "problems": list(problems),
        "objects": objects,
        "pending": list(pending),
        "metrics": metrics,
    }
    if report_prompt is not None:
        report["generate"] = {"prompt": report_prompt, "rounds": 3, "seconds": 1.5, "vqa_score": None}
    (path / "scene.json").write_text(json.dumps(scene))
    (path / "report.json").write_text(json.dumps(report))
    if render:
        (path / "render.png").write_bytes(tiny_png(8, 6))
    if layout:
        (path / "layout.png").write_bytes(tiny_png(6, 6, (40, 90, 200)))
    if batch is not None:
        (path / "batch.json").write_text(json.dumps(batch))
    return path


def results_file(folder: Path, rows: Sequence[Mapping[str, Any]]) -> Path:
    """`eval compare`'s results.jsonl: one JSON object a line."""
    path = folder / "results.jsonl"
    path.write_text("".join(json.dumps(row) + "\n" for row in rows))
    return path


def row(
    prompt: str, method: str, seed: int, scene_dir: str, metrics: Mapping[str, Any], failures: Sequence[str] = ()
) -> dict[str, Any]:
    return {
        "prompt": prompt,
        "prompt_id": prompt.split()[1] if len(prompt.split()) > 1 else prompt,
        "method": method,
        "seed": seed,
        "scene_dir": scene_dir,
        "ok": not failures,
        "metrics": dict(metrics),
        "failures": list(failures),
    }


# Two boxes on a slab, as export/glb.py lays a scene out: a y-up root, one node per object named by its id.
GLB_OBJECTS = {"box_0": ((0.0, 0.0, 0.05), (200, 40, 40)), "box_1": ((0.25, 0.1, 0.05), (40, 160, 60))}


def tiny_glb() -> bytes:
    """A small real glb: a grey slab (the support) and GLB_OBJECTS, each a coloured box under a node named by id."""
    import numpy as np
    import trimesh

    from physcensis.export.glb import ROOT, Z_UP_TO_Y_UP

    def box(extents: tuple[float, float, float], rgb: tuple[int, int, int]) -> trimesh.Trimesh:
        mesh = trimesh.creation.box(extents=extents)
        material = trimesh.visual.material.PBRMaterial(baseColorFactor=[*rgb, 255], metallicFactor=0.0)
        mesh.visual = trimesh.visual.TextureVisuals(material=material)
        return mesh

    scene = trimesh.Scene()
    scene.graph.update(frame_from=scene.graph.base_frame, frame_to=ROOT, matrix=Z_UP_TO_Y_UP)
    parts = {"support": ((0.0, 0.0, -0.01), (170, 170, 180), (1.0, 0.7, 0.02))}
    parts |= {oid: (where, rgb, (0.1, 0.1, 0.1)) for oid, (where, rgb) in GLB_OBJECTS.items()}
    for node, (where, rgb, extents) in parts.items():
        transform = np.eye(4)
        transform[:3, 3] = where
        scene.graph.update(frame_from=ROOT, frame_to=node, matrix=transform)
        name = f"{node}_part0"
        scene.add_geometry(box(extents, rgb), node_name=name, geom_name=name, parent_node_name=node)
    return bytes(scene.export(file_type="glb"))


def glb_scene_folder(path: Path, *, prompt: str = "two boxes", glb: bytes | None = None) -> Path:
    """A scene folder with a scene.glb (tiny_glb) and the scene.json, report.json of its two placed objects (box_1 on
    box_0's right, with a p_fail measured), and one failed object the glb does not hold."""
    scene_folder(path, prompt=prompt)
    objects = [
        {
            "id": oid,
            "asset": f"cube_{k}",
            "category": "box",
            "description": f"box number {k}",
            "mass": 0.5 + k,
            "friction": 0.6,
            "status": "placed",
            "placement": {"predicate": "PLACE-ON-BASE", "target": "root"},
        }
        for k, oid in enumerate(GLB_OBJECTS)
    ]
    objects.append({"id": "lost_0", "asset": "cube_9", "status": "failed", "reason": "no room"})
    program = [["box_0", "a box"], ["box_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}], ["box_1", "a box"]]
    program.append(["box_1", "RIGHT-OF", "box_0", {}])
    metrics = {"objects_placed": 2, "placements": [{"object": "box_1", "predicate": "RIGHT-OF", "p_fail": 0.125}]}
    scene = {"format": "physcensis.scene/1", "seed": 3, "prompt": prompt, "objects": objects, "program": program}
    (path / "scene.json").write_text(json.dumps(scene | {"metrics": metrics}))
    report = {"ok": False, "objects": [{"id": "lost_0", "status": "failed", "reason": "no room"}], "metrics": metrics}
    (path / "report.json").write_text(json.dumps(report))
    (path / "scene.glb").write_bytes(tiny_glb() if glb is None else glb)
    return path
