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
