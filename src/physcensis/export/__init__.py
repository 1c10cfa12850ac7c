"""Scene exports for the simulators robotics people use: MJCF, URDF, glTF binary and USD.

`export_scene` writes the chosen formats into a folder, each one atomically:
`mjcf/scene.xml`, `urdf/bodies.json` (+ one URDF per object), `scene.glb`, `scene.usd`, and records which scene
they come from in `exports.json` (`manifest.py`).
"""

from __future__ import annotations

import importlib.util
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import TYPE_CHECKING

from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.errors import ExportError
from physcensis.export.manifest import refuse_other_scene, write_manifest
from physcensis.scene import Scene

if TYPE_CHECKING:  # the writers (and MuJoCo, pxr) are imported when a format is written
    from physcensis.export.bodies import ExportScene
    from physcensis.physics.mujoco_engine import BuiltScene

FORMATS: tuple[str, ...] = ("mjcf", "urdf", "glb", "usd")
OUTPUTS = {"mjcf": "mjcf/scene.xml", "urdf": "urdf/bodies.json", "glb": "scene.glb", "usd": "scene.usd"}
_TARGETS = {"mjcf": "mjcf", "urdf": "urdf", "glb": OUTPUTS["glb"], "usd": OUTPUTS["usd"]}  # what each writer makes
_EXTRAS = {"usd": ("pxr", "usd")}

__all__ = ["FORMATS", "OUTPUTS", "available_formats", "export_scene", "parse_formats"]


def available_formats() -> tuple[str, ...]:
    """The formats this installation can write (USD needs the `[usd]` extra)."""
    return tuple(f for f in FORMATS if f not in _EXTRAS or importlib.util.find_spec(_EXTRAS[f][0]) is not None)


def parse_formats(text: str | Iterable[str]) -> tuple[str, ...]:
    """`mjcf,urdf` / ["glb"] / "all" (every available format) / "none"; unknown or unavailable names are errors."""
    names = [n.strip().lower() for n in (text.split(",") if isinstance(text, str) else text) if n.strip()]
    if names in (["all"], []):
        return available_formats() if names else ()
    if names == ["none"]:
        return ()
    for name in names:
        if name not in FORMATS:
            raise ExportError(f"unknown export format {name!r}; choose from {', '.join(FORMATS)}, all or none")
        if name not in available_formats():
            module, extra = _EXTRAS[name]
            raise ExportError(f"{name} export needs the optional extra: pip install 'physcensis[{extra}]'")
    return tuple(dict.fromkeys(names))


def export_scene(
    scene: Scene,
    out_dir: str | Path,
    formats: Iterable[str] = FORMATS[:3],
    *,
    catalogue: Catalogue | None = None,
    built: BuiltScene | None = None,
    target: str | Path | None = None,
) -> dict[str, Path]:
    """Write `formats` of the scene's placed objects into `out_dir` and record them in its exports.json; returns
    format -> main file.

    `built` (a BuiltScene with visuals) saves rebuilding the MuJoCo model for MJCF. `target` is the folder the
    exports end up in when `out_dir` stages them (default `out_dir`): one that holds another scene's scene.json is
    refused (`ExportMismatchError`) before anything is written, and its exports.json's records of the formats not
    written now are kept.
    """
    from physcensis.export.bodies import export_scene_bodies

    formats = parse_formats(list(formats))
    catalogue = catalogue or default_catalogue()
    out_dir = Path(out_dir)
    final = Path(target) if target is not None else out_dir
    refuse_other_scene(final, scene)
    written: dict[str, Path] = {}
    bodies = export_scene_bodies(scene, catalogue) if set(formats) - {"mjcf"} else None
    for name in formats:
        if name == "mjcf":
            written[name] = _export_mjcf(scene, catalogue, built, out_dir / _TARGETS[name])
        elif bodies is not None:  # read whenever a format other than MJCF is asked for
            written[name] = _body_writer(name)(bodies, out_dir / _TARGETS[name])
    if written:
        write_manifest(scene, out_dir, {name: out_dir / _TARGETS[name] for name in written}, earlier=final)
    return written


def _export_mjcf(scene: Scene, catalogue: Catalogue, built: BuiltScene | None, out_dir: Path) -> Path:
    from physcensis.export.mjcf import export_mjcf
    from physcensis.physics.mujoco_engine import build_scene

    return export_mjcf(built or build_scene(scene, catalogue), out_dir)


def _body_writer(name: str) -> Callable[[ExportScene, Path], Path]:
    """The writer of a format made from the scene's bodies (imported only when that format is written)."""
    if name == "urdf":
        from physcensis.export.urdf import export_urdf

        return export_urdf
    if name == "glb":
        from physcensis.export.glb import export_glb

        return export_glb
    from physcensis.export.usd import export_usd

    return export_usd
