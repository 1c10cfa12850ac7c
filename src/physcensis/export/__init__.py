"""Scene exports for the simulators robotics people use: MJCF, URDF, glTF binary and USD.

`export_scene` writes the chosen formats into a folder, each one atomically: `mjcf/scene.xml`, `urdf/bodies.json`
(+ one URDF per object), `scene.glb`, `scene.usd`, and records which scene they come from in `exports.json`
(`manifest.py`).

`EXPORT_FORMATS` is the registry of formats, one record each (`formats.ExportFormat`), and the one list of them:
`parse_formats` and `available_formats` (so the `--export` / `--to` options), their help, `export_scene` and the
MJCF reader read it. Two lists below the registry name what it holds, and tests/export/test_format_registry.py
keeps them in step with it: `fileio.EXPORT_FOLDERS` / `EXPORT_FILES` (fileio sits below export/; its overwrite
rules and the gallery's search read them) and `manifest.FormatName` (this module imports the manifest).

Adding a format: its writer module, one record below with a `_write_*` function that imports the writer, its
entry's name in `fileio.EXPORT_FOLDERS` or `EXPORT_FILES`, and its name in `manifest.FormatName`.

This module imports no writer (nor MuJoCo, trimesh or pxr) until a format is written: the command line reads the
registry for its help.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from pathlib import Path
from types import MappingProxyType
from typing import TYPE_CHECKING

from physcensis.errors import ExportError
from physcensis.export.formats import ExportFormat, ExportSource, Extra

if TYPE_CHECKING:  # the catalogue, the writers (and MuJoCo, pxr) are imported when a format is written
    from physcensis.assets.catalogue import Catalogue
    from physcensis.export.bodies import ExportScene
    from physcensis.physics.mujoco_engine import BuiltScene
    from physcensis.scene import Scene

__all__ = [
    "EXPORT_FORMATS",
    "FORMATS",
    "OUTPUTS",
    "ExportFormat",
    "available_formats",
    "export_scene",
    "format_choices",
    "parse_formats",
]


# -- the writers: each imports its module (and MuJoCo, trimesh, pxr) only when its format is written -----------------


def _write_mjcf(source: ExportSource, target: Path) -> Path:
    from physcensis.export.mjcf import export_mjcf
    from physcensis.physics.mujoco_engine import build_scene

    return export_mjcf(source.built or build_scene(source.scene, source.catalogue), target)


def _write_urdf(source: ExportSource, target: Path) -> Path:
    from physcensis.export.urdf import export_urdf

    return export_urdf(_bodies(source), target)


def _write_glb(source: ExportSource, target: Path) -> Path:
    from physcensis.export.glb import export_glb

    return export_glb(_bodies(source), target)


def _write_usd(source: ExportSource, target: Path) -> Path:
    from physcensis.export.usd import export_usd

    return export_usd(_bodies(source), target)


def _bodies(source: ExportSource) -> ExportScene:
    if source.bodies is None:
        raise ValueError("a format made from the scene's bodies was given none (export_scene reads them)")
    return source.bodies


# -- the registry -----------------------------------------------------------------------------------------------------

_FORMATS = (
    ExportFormat(
        name="mjcf",
        output="mjcf/scene.xml",
        description="MuJoCo MJCF, mjcf/scene.xml with its meshes (free bodies with mass, friction and inertia)",
        write=_write_mjcf,
        made_from="model",
    ),
    ExportFormat(
        name="urdf",
        output="urdf/bodies.json",
        description="one URDF per object and bodies.json, the poses to load them at (PyBullet, Isaac)",
        write=_write_urdf,
        made_from="bodies",
    ),
    ExportFormat(
        name="glb",
        output="scene.glb",
        description="glTF binary with colours, for viewers, Blender and web pages",
        write=_write_glb,
        made_from="bodies",
    ),
    ExportFormat(
        name="usd",
        output="scene.usd",
        description="USD stage of UsdPhysics rigid bodies (Isaac Sim, Omniverse)",
        write=_write_usd,
        made_from="bodies",
        extra=Extra(name="usd", module="pxr"),
    ),
)
EXPORT_FORMATS: Mapping[str, ExportFormat] = MappingProxyType({f.name: f for f in _FORMATS})
FORMATS: tuple[str, ...] = tuple(EXPORT_FORMATS)  # the names, in the order "all" writes them
OUTPUTS = {f.name: f.output for f in _FORMATS}  # format -> its main file in a scene folder
# `export_scene`'s default: every format this package writes without an optional extra.
DEFAULT_FORMATS: tuple[str, ...] = tuple(f.name for f in _FORMATS if f.extra is None)
if len({f.entry for f in _FORMATS}) != len(_FORMATS):
    raise ValueError("two export formats write the same entry of a scene folder")


def available_formats() -> tuple[str, ...]:
    """The formats this installation can write (USD needs the `[usd]` extra)."""
    return tuple(f.name for f in _FORMATS if f.available())


def parse_formats(text: str | Iterable[str]) -> tuple[str, ...]:
    """`mjcf,urdf` / ["glb"] / "all" (every available format) / "none"; unknown or unavailable names are errors."""
    names = [n.strip().lower() for n in (text.split(",") if isinstance(text, str) else text) if n.strip()]
    if names in (["all"], []):
        return available_formats() if names else ()
    if names == ["none"]:
        return ()
    for name in names:
        spec = EXPORT_FORMATS.get(name)
        if spec is None:
            raise ExportError(f"unknown export format {name!r}; choose from {format_choices()}, all or none")
        if spec.extra is not None and not spec.available():
            raise ExportError(f"{name} export needs the optional extra: pip install 'physcensis[{spec.extra.name}]'")
    return tuple(dict.fromkeys(names))


def format_choices(separator: str = ", ") -> str:
    """The names `--export` / `--to` take, for help and error text: `mjcf, urdf, glb, usd`."""
    return separator.join(FORMATS)


# -- writing ----------------------------------------------------------------------------------------------------------


def export_scene(
    scene: Scene,
    out_dir: str | Path,
    formats: Iterable[str] = DEFAULT_FORMATS,
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
    from physcensis.assets.catalogue import default_catalogue
    from physcensis.export.bodies import export_scene_bodies
    from physcensis.export.manifest import refuse_other_scene, write_manifest

    chosen = [EXPORT_FORMATS[name] for name in parse_formats(list(formats))]
    catalogue = catalogue or default_catalogue()
    out_dir = Path(out_dir)
    final = Path(target) if target is not None else out_dir
    refuse_other_scene(final, scene)
    # The bodies are read once, before anything is written, whenever a format made from them is asked for.
    bodies = export_scene_bodies(scene, catalogue) if any(f.made_from == "bodies" for f in chosen) else None
    source = ExportSource(scene, catalogue, built, bodies)
    written = {f.name: f.write(source, out_dir / f.entry) for f in chosen}
    recorded = {f.name: out_dir / f.entry for f in chosen if f.recorded}
    if recorded:
        write_manifest(scene, out_dir, recorded, earlier=final)
    return written
