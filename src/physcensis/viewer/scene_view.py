"""What the viewer shows of a scene, as plain data: meshes with their colours, poses, the facts a click shows, and the
first camera (viewer/camera.py). Built from the scene file and its catalogue (the same assets the render and the
exports draw), in the project's frame (z up, the viewer in front at +x); no browser and no viser needed.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import trimesh

from physcensis.assets.catalogue import Catalogue
from physcensis.assets.model import RGBA, Asset
from physcensis.assets.supports import support_asset
from physcensis.bounded_json import load_json
from physcensis.errors import PhyscensisError
from physcensis.export.bodies import GROUND_RGBA, ground_slab, pose_matrix
from physcensis.fileio import BoundError, read_in_folder
from physcensis.scene import PlacedObject, Scene
from physcensis.viewer.camera import CameraPose, render_camera

SUPPORT = "support"
GROUND = "ground"
OBJECTS = "objects"  # scene-tree folder of the objects: /objects/<id>
MAX_REPORT_BYTES = 64 * 1024 * 1024
Pose = np.ndarray  # (7,) position and wxyz quaternion


class ViewerError(PhyscensisError):
    """The viewer cannot show what it was given (a scene, an episode, a pose)."""


@dataclass(frozen=True, eq=False)
class MeshPart:
    """One colour of a node's meshes, in the node's own frame."""

    vertices: np.ndarray  # (V, 3) float32
    faces: np.ndarray  # (F, 3) uint32
    rgb: tuple[int, int, int]  # 0..255
    opacity: float | None  # None: opaque


@dataclass(frozen=True)
class PlacementFact:
    """A placement record of the solve that moved the object: predicate, target and whether it held."""

    predicate: str
    target: str | None
    ok: bool | None
    requested: dict[str, Any] = field(default_factory=dict)

    def text(self) -> str:
        words = f"{self.predicate} {self.target}" if self.target else self.predicate
        if self.requested:
            words += " (" + ", ".join(f"{k}={v}" for k, v in sorted(self.requested.items())) + ")"
        return words + ("" if self.ok is not False else " - not met")


@dataclass(frozen=True)
class ObjectInfo:
    """What a click on an object shows."""

    id: str
    description: str
    asset: str
    category: str
    mass_kg: float
    friction: float
    com: tuple[float, float, float]
    placements: tuple[PlacementFact, ...]
    p_fail: float | None  # when the solve or a stability search measured it

    def markdown(self) -> str:
        com = ", ".join(f"{round(c * 1000, 1) + 0.0:.1f}" for c in self.com)  # + 0.0: no "-0.0"
        lines = [
            f"### {self.id}",
            f"*{self.description}*",
            "",
            f"- **asset**: `{self.asset}` ({self.category})",
            f"- **mass**: {self.mass_kg:.3f} kg",
            f"- **friction**: {self.friction:.3f}",
            f"- **centre of mass**: ({com}) mm in the object's frame",
            f"- **p_fail**: {'not measured' if self.p_fail is None else f'{self.p_fail:.3f}'}",
            "- **placed by**: " + ("; ".join(p.text() for p in self.placements) or "no placement recorded"),
        ]
        return "\n".join(lines)


@dataclass(frozen=True, eq=False)
class ViewNode:
    """A node of the viewer's scene tree (`name`, e.g. /objects/mug_0) with its meshes and its pose."""

    name: str
    id: str
    parts: tuple[MeshPart, ...]
    pose: Pose  # (7,) position and wxyz quaternion in the world
    info: ObjectInfo | None = None  # None for the support and the ground

    @property
    def pickable(self) -> bool:
        return self.info is not None


@dataclass(frozen=True, eq=False)
class SceneView:
    """Everything the viewer draws of one scene."""

    source: Path
    scene: Scene
    support: ViewNode
    ground: ViewNode | None
    objects: tuple[ViewNode, ...]
    failed: tuple[str, ...]  # objects the solve could not place: not drawn
    camera: CameraPose
    notes: tuple[str, ...] = ()  # what could not be read (an unreadable report.json), said as warnings

    def node(self, object_id: str) -> ViewNode:
        for node in self.objects:
            if node.id == object_id:
                return node
        raise ViewerError(f"the scene has no placed object {object_id!r}")

    def written_poses(self) -> dict[str, Pose]:
        return {node.id: node.pose.copy() for node in self.objects}

    def support_markdown(self) -> str:
        support = self.scene.support
        return (
            f"### {support.kind}\n\n- **top**: {support.size[0]:g} x {support.size[1]:g} m, "
            f"{support.top_height:g} m above the floor\n- **objects**: {len(self.objects)} placed"
            + (f", {len(self.failed)} failed ({', '.join(self.failed)})" if self.failed else "")
        )


def object_node_name(object_id: str) -> str:
    return f"/{OBJECTS}/{object_id}"


def coloured_parts(asset: Asset) -> tuple[MeshPart, ...]:
    """The asset's visual mesh as one part per colour (parts of one colour merged)."""
    groups: dict[tuple[float, ...], list[trimesh.Trimesh]] = {}
    for mesh, colour in asset.visual_parts():
        groups.setdefault(tuple(float(c) for c in colour), []).append(mesh)
    return tuple(mesh_part(_merged(meshes), colour) for colour, meshes in groups.items())


def mesh_part(mesh: trimesh.Trimesh, colour: RGBA | Sequence[float]) -> MeshPart:
    r, g, b, a = (float(c) for c in colour)
    return MeshPart(
        vertices=np.asarray(mesh.vertices, dtype=np.float32),
        faces=np.asarray(mesh.faces, dtype=np.uint32).reshape(-1, 3),
        rgb=(_byte(r), _byte(g), _byte(b)),
        opacity=None if a >= 1.0 else a,
    )


def _byte(value: float) -> int:
    return int(round(255 * min(1.0, max(0.0, value))))


def _merged(meshes: list[trimesh.Trimesh]) -> trimesh.Trimesh:
    if len(meshes) == 1:
        return meshes[0]
    vertices, faces, offset = [], [], 0
    for mesh in meshes:
        vertices.append(np.asarray(mesh.vertices))
        faces.append(np.asarray(mesh.faces) + offset)
        offset += len(mesh.vertices)
    return trimesh.Trimesh(np.vstack(vertices), np.vstack(faces), process=False)


def pose_of(obj: PlacedObject) -> Pose:
    return np.array([*obj.position, *obj.quaternion], dtype=float)


def _placement_facts(obj: PlacedObject, records: Sequence[Mapping[str, Any]]) -> tuple[PlacementFact, ...]:
    facts = [
        PlacementFact(
            predicate=str(r.get("predicate", "?")),
            target=None if r.get("target") is None else str(r.get("target")),
            ok=r.get("ok") if isinstance(r.get("ok"), bool) else None,
            requested=dict(r["requested"]) if isinstance(r.get("requested"), dict) else {},
        )
        for r in records
        if r.get("object") == obj.id
    ]
    if not facts and obj.placement is not None:  # a scene written without the solve's records
        facts.append(PlacementFact(obj.placement.predicate, obj.placement.target, None))
    return tuple(facts)


def _p_fail(object_id: str, records: Sequence[Mapping[str, Any]]) -> float | None:
    for record in records:
        value = record.get("p_fail")
        if record.get("object") == object_id and isinstance(value, int | float) and not isinstance(value, bool):
            return float(value)
    return None


def _records(*metrics: Mapping[str, Any] | None) -> list[Mapping[str, Any]]:
    """The placement records of the first metrics that hold any (report.json's, then scene.json's)."""
    for found in metrics:
        placements = found.get("placements") if isinstance(found, Mapping) else None
        if isinstance(placements, list) and placements:
            return [p for p in placements if isinstance(p, Mapping)]
    return []


def object_info(obj: PlacedObject, records: Sequence[Mapping[str, Any]]) -> ObjectInfo:
    return ObjectInfo(
        id=obj.id,
        description=obj.description,
        asset=obj.asset,
        category=obj.category,
        mass_kg=float(obj.mass),
        friction=float(obj.friction),
        com=(float(obj.com[0]), float(obj.com[1]), float(obj.com[2])),
        placements=_placement_facts(obj, records),
        p_fail=_p_fail(obj.id, records),
    )


def read_report(folder: Path) -> tuple[dict[str, Any] | None, str | None]:
    """The folder's report.json (None when it has none), or None and why it could not be read."""
    if not (folder / "report.json").exists():
        return None, None
    try:
        data = load_json(read_in_folder(folder, "report.json", MAX_REPORT_BYTES))
    except (BoundError, ValueError) as exc:
        return None, f"{folder / 'report.json'}: not read, so no predicates or p_fail from it ({exc})"
    if not isinstance(data, dict):
        return None, f"{folder / 'report.json'}: not a JSON object; not read"
    return data, None


def build_scene_view(
    scene: Scene, catalogue: Catalogue, source: Path, report: Mapping[str, Any] | None = None, notes: Sequence[str] = ()
) -> SceneView:
    """The viewer's description of `scene` (its placed objects, with the catalogue's meshes)."""
    report_metrics = report.get("metrics") if report else None
    records = _records(report_metrics if isinstance(report_metrics, Mapping) else None, scene.metrics)
    objects = []
    for obj in scene.placed:
        asset = catalogue.asset_for(obj.asset, obj.description)
        objects.append(
            ViewNode(object_node_name(obj.id), obj.id, coloured_parts(asset), pose_of(obj), object_info(obj, records))
        )
    identity = np.array([0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0])
    support = ViewNode(f"/{SUPPORT}", SUPPORT, coloured_parts(support_asset(scene.support)), identity)
    ground = None
    if scene.support.kind != "floor":
        ground = ViewNode(f"/{GROUND}", GROUND, (mesh_part(ground_slab(), GROUND_RGBA),), identity.copy())
    return SceneView(
        source=source,
        scene=scene,
        support=support,
        ground=ground,
        objects=tuple(objects),
        failed=tuple(o.id for o in scene.objects if o.status != "placed"),
        camera=render_camera(scene, catalogue, _world_points(objects)),
        notes=tuple(notes),
    )


def open_scene_view(path: Path, base: Catalogue | None = None) -> tuple[SceneView, Catalogue]:
    """A scene folder (or scene.json) as the viewer shows it, with its report's facts when there is one, and the
    catalogue that holds its assets (the folder's own copies first)."""
    from physcensis.output import open_scene

    scene, catalogue = open_scene(path, base)
    report, problem = read_report(scene_folder(path))
    return build_scene_view(scene, catalogue, path, report, [problem] if problem else []), catalogue


def scene_folder(path: Path) -> Path:
    """The folder of a scene argument (a scene folder, or its scene.json)."""
    return path if path.is_dir() else path.parent


def _world_points(objects: Sequence[ViewNode]) -> np.ndarray:
    """Every vertex of the objects' meshes, in the world."""
    points = [np.zeros((0, 3))]
    for node in objects:
        matrix = pose_matrix(node.pose[:3], node.pose[3:])
        points += [part.vertices.astype(float) @ matrix[:3, :3].T + matrix[:3, 3] for part in node.parts]
    return np.vstack(points)
