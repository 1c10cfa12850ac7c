"""`exports.json`: which scene a folder's exports were written from, so that a command using an export together with
the folder's scene.json can tell whether they belong together.

One record beside the exports serves every format. It holds the scene's identity (a hash of what the exports are
made of: the support, each placed object's id, asset, pose, mass, friction and centre of mass, and the asset
copies), each exported object's asset and pose (to say what changed), and the SHA-256 of every file each format
wrote. `export_scene` writes it; a scene folder is untrusted input, so it is read with bounds and validated, and
it is only a check of consistency: a forged record still meets the checks of the export itself.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Literal, cast

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from physcensis.bounded_json import shape_problem
from physcensis.errors import ExportMismatchError, PhyscensisError
from physcensis.fileio import BoundError, atomic_write_text, read_in_folder
from physcensis.scene import MAX_SCENE_BYTES, MAX_SCENE_OBJECTS, MAX_TEXT_CHARS, Scene, scene_from_json

MANIFEST = "exports.json"
MANIFEST_FORMAT: Literal["physcensis.exports/1"] = "physcensis.exports/1"
SCENE_FILE = "scene.json"
MAX_MANIFEST_BYTES = 16 * 2**20
MAX_MANIFEST_NESTING = 16  # brackets deep; a record nests 4
MAX_RECORDED_FILES = 100_000
POSITION_TOLERANCE_M = 1e-3  # the MJCF writes 6 significant digits: a written pose is within 1e-6 m of the scene's
ANGLE_TOLERANCE_RAD = 1e-2
# What of an object its exports are made of (description, category and placement are not in any export's physics).
_EXPORTED_FIELDS = {"id", "asset", "position", "quaternion", "mass", "friction", "com"}

Sha256 = Annotated[str, Field(pattern=r"^[0-9a-f]{64}$")]
Finite = Annotated[float, Field(allow_inf_nan=False)]
# The formats whose records in the registry (physcensis.export.EXPORT_FORMATS) say exports.json records them; any
# other key is refused. The registry imports this module, so this one cannot read it: test_format_registry.py checks.
FormatName = Literal["mjcf", "urdf", "glb", "usd"]


class _Record(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class RecordedObject(_Record):
    asset: Annotated[str, Field(max_length=MAX_TEXT_CHARS)]
    position: tuple[Finite, Finite, Finite]
    quaternion: tuple[Finite, Finite, Finite, Finite]


class RecordedExport(_Record):
    files: dict[Annotated[str, Field(max_length=1_000)], Sha256] = Field(max_length=MAX_RECORDED_FILES)


class Manifest(_Record):
    format: Literal["physcensis.exports/1"]
    scene: Sha256
    objects: dict[Annotated[str, Field(max_length=MAX_TEXT_CHARS)], RecordedObject] = Field(
        max_length=MAX_SCENE_OBJECTS
    )
    exports: dict[FormatName, RecordedExport]


@dataclass(frozen=True)
class Pose:
    """Where an object stands: its asset origin in the world and its [w, x, y, z] orientation."""

    position: tuple[float, ...]
    quaternion: tuple[float, ...]


def scene_identity(scene: Scene) -> str:
    """SHA-256 of what a scene's exports are made of; a scene.json edited only in its prompt, program or metrics
    keeps it."""
    made_of = {
        "support": scene.support.model_dump(mode="json"),
        "objects": sorted(
            (o.model_dump(mode="json", include=_EXPORTED_FIELDS) for o in scene.placed), key=lambda o: o["id"]
        ),
        "assets": {asset_id: copy.sha256 for asset_id, copy in scene.assets.items()},
    }
    text = json.dumps(made_of, sort_keys=True, separators=(",", ":"), allow_nan=False)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def scene_poses(scene: Scene) -> dict[str, Pose]:
    return {o.id: Pose(tuple(o.position), tuple(o.quaternion)) for o in scene.placed}


def reexport_hint(folder: Path, fmt: str) -> str:
    return f"re-export the scene: physcensis export {folder} --to {fmt} --out {folder}"


# -- writing ----------------------------------------------------------------------------------------------------------


def write_manifest(scene: Scene, out_dir: Path, written: Mapping[str, Path], earlier: Path | None = None) -> Path:
    """Record in `out_dir/exports.json` that the exports `written` (format -> the file or folder it made in
    `out_dir`) come from `scene`. The records of other formats in `earlier`'s exports.json (default `out_dir`'s) are
    kept when they were made from the same scene."""
    identity = scene_identity(scene)
    exports = {
        name: record for name, record in _earlier_records(earlier or out_dir, identity).items() if name not in written
    }
    for name, target in written.items():
        exports[cast("FormatName", name)] = RecordedExport(files=_file_hashes(out_dir, target))
    objects = {o.id: RecordedObject(asset=o.asset, position=o.position, quaternion=o.quaternion) for o in scene.placed}
    manifest = Manifest(format=MANIFEST_FORMAT, scene=identity, objects=objects, exports=exports)
    atomic_write_text(out_dir / MANIFEST, manifest.model_dump_json(indent=1) + "\n")
    return out_dir / MANIFEST


def _earlier_records(folder: Path, identity: str) -> dict[FormatName, RecordedExport]:
    try:
        manifest = read_manifest(folder)
    except ExportMismatchError:  # an unreadable record is replaced, not merged
        return {}
    return dict(manifest.exports) if manifest is not None and manifest.scene == identity else {}


def _file_hashes(out_dir: Path, target: Path) -> dict[str, str]:
    files = sorted(p for p in target.rglob("*") if p.is_file()) if target.is_dir() else [target]
    hashes = {}
    for path in files:
        with path.open("rb") as handle:
            hashes[path.relative_to(out_dir).as_posix()] = hashlib.file_digest(handle, "sha256").hexdigest()
    return hashes


# -- reading and checking ---------------------------------------------------------------------------------------------


def read_manifest(folder: Path) -> Manifest | None:
    """The folder's exports.json, or None when it has none (a folder written before exports carried one)."""
    if not os.path.lexists(folder / MANIFEST):
        return None
    try:
        data = read_in_folder(folder, MANIFEST, MAX_MANIFEST_BYTES)
    except BoundError as exc:
        raise ExportMismatchError(f"{folder}: {exc}") from None
    problem = shape_problem(data, MAX_MANIFEST_NESTING)
    if problem:
        raise ExportMismatchError(f"{folder / MANIFEST}: {problem}")
    try:
        return Manifest.model_validate_json(data)
    except ValidationError as exc:
        first = exc.errors()[0]
        where = ".".join(str(part) for part in first["loc"]) or "the record"
        raise ExportMismatchError(
            f"{folder / MANIFEST}: not an export record this version reads ({where}: {first['msg']})"
        ) from None


def read_folder_scene(folder: Path) -> Scene:
    """The folder's scene.json, read as a file that came with the folder (no link, bounded, validated)."""
    try:
        text = read_in_folder(folder, SCENE_FILE, MAX_SCENE_BYTES).decode("utf-8-sig")
    except BoundError as exc:
        raise ExportMismatchError(f"{folder}: {exc}") from None
    except UnicodeDecodeError:
        raise ExportMismatchError(f"{folder / SCENE_FILE}: not UTF-8 text") from None
    return scene_from_json(text, str(folder / SCENE_FILE))


def check_scene_against_manifest(folder: Path, manifest: Manifest, scene: Scene, fmt: str) -> None:
    """Refuse a scene.json that changed after the folder's exports were written from it."""
    if manifest.scene != scene_identity(scene):
        raise ExportMismatchError(
            f"{folder / SCENE_FILE}: {_scene_change(manifest, scene)}; it changed after its exports were written, "
            f"or they were written from another scene; {reexport_hint(folder, fmt)}"
        )


def _scene_change(manifest: Manifest, scene: Scene) -> str:
    recorded = {oid: Pose(o.position, o.quaternion) for oid, o in manifest.objects.items()}
    moved = pose_difference(scene_poses(scene), recorded, MANIFEST)
    if moved is not None:
        return moved
    for obj in scene.placed:
        if manifest.objects[obj.id].asset != obj.asset:
            return f"object {obj.id} is {obj.asset}, {MANIFEST} has {manifest.objects[obj.id].asset}"
    return "the objects' masses, friction or centres of mass, the support or the asset copies differ from " + MANIFEST


def check_recorded_file(folder: Path, relative: str, data: bytes, record: RecordedExport | None, fmt: str) -> None:
    """Refuse a file of an export that is not the one written with the scene (when the export is recorded)."""
    if record is None:
        return
    expected = record.files.get(relative)
    if expected is None or hashlib.sha256(data).hexdigest() != expected:
        change = "was not written" if expected is None else "is not the file written"
        raise ExportMismatchError(
            f"{folder / relative}: {change} with this scene's exports ({MANIFEST}); it was edited or copied from "
            f"elsewhere; {reexport_hint(folder, fmt)}"
        )


def pose_difference(found: Mapping[str, Pose], expected: Mapping[str, Pose], expected_in: str) -> str | None:
    """The first way `found` disagrees with `expected` (ids, then positions, then orientations), in words."""
    missing = _first(name for name in expected if name not in found)
    if missing is not None:
        return f"has no object {missing} ({expected_in} places it)"
    extra = _first(name for name in found if name not in expected)
    if extra is not None:
        return f"holds an object {extra} that {expected_in} does not place"
    for name, pose in expected.items():
        distance = math.dist(pose.position, found[name].position)
        if not distance <= POSITION_TOLERANCE_M:
            return f"object {name} stands {distance:.3g} m from where {expected_in} puts it"
    for name, pose in expected.items():
        angle = quaternion_angle(pose.quaternion, found[name].quaternion)
        if not angle <= ANGLE_TOLERANCE_RAD:
            return f"object {name} is turned {math.degrees(angle):.3g} degrees from how {expected_in} puts it"
    return None


def quaternion_angle(a: Iterable[float], b: Iterable[float]) -> float:
    """The angle in radians of the rotation between two orientations (either sign of a quaternion is the same)."""
    a, b = tuple(a), tuple(b)
    norms = math.hypot(*a) * math.hypot(*b)
    if not norms > 1e-12:
        return math.pi
    dot = abs(sum(x * y for x, y in zip(a, b, strict=True))) / norms
    return 2.0 * math.acos(min(1.0, dot))


def refuse_other_scene(out: Path, scene: Scene) -> None:
    """Refuse to export `scene` into a folder whose scene.json is another scene (its exports would disagree)."""
    if not os.path.lexists(out / SCENE_FILE):
        return
    try:
        theirs = read_folder_scene(out)
    except PhyscensisError as exc:
        raise ExportMismatchError(
            f"{out}: holds a scene.json that cannot be read ({exc}); export into another folder"
        ) from None
    if scene_identity(theirs) == scene_identity(scene):
        return
    what = pose_difference(scene_poses(theirs), scene_poses(scene), "the scene being exported") or (
        "other assets, masses, friction, support or asset copies"
    )
    raise ExportMismatchError(
        f"{out}: holds another scene: its scene.json {what}; export into the scene's own folder or give another --out"
    )


def _first(names: Iterable[str]) -> str | None:
    return next(iter(names), None)
