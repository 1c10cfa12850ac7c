"""Every registered export format is realised as its record says, and everything that lists formats lists the
registry's.

(1) the records are well formed; (2) each format, exported from a solved scene into its scene folder, writes its
entry (a folder or a file) and its output file there and nothing else, and exports.json records what it wrote;
(3) fileio's names of the exports' entries (it sits below export/ and cannot read the registry) are the records',
so its overwrite rules, and the gallery's and the diversity scan's searches, treat each entry as an output;
(4) exports.json's format names, the CLI's options and their help are the registry's; (5) the physics the
exporters write (gravity, the floor) is the MuJoCo scene's.

A format added to the registry whose writer writes something else, or whose name or entry exports.json or fileio
does not know, fails here.
"""

from __future__ import annotations

import re
import shutil
import typing
from pathlib import Path
from typing import Any

import pytest
import typer

from physcensis import fileio
from physcensis.assets.catalogue import default_catalogue
from physcensis.cli import app
from physcensis.cli.options import EXPORT_TO_CHOICES
from physcensis.errors import ExportError
from physcensis.evaluation.diversity_files import find_scene_folders
from physcensis.export import (
    DEFAULT_FORMATS,
    EXPORT_FORMATS,
    FORMATS,
    OUTPUTS,
    available_formats,
    export_scene,
    parse_formats,
)
from physcensis.export.bodies import GRAVITY_M_S2, GROUND_FRICTION, GROUND_RGBA, export_scene_bodies
from physcensis.export.formats import KEYWORDS, ExportFormat
from physcensis.export.manifest import MANIFEST, SCENE_FILE, FormatName, read_manifest
from physcensis.export.mjcf_read import XML_FILE
from physcensis.gallery.cards import scene_folders
from physcensis.physics.mujoco_assets import ROLLING_FRICTION, TORSIONAL_FRICTION
from physcensis.physics.mujoco_engine import build_scene
from physcensis.scene import Scene, save_scene

REGISTERED = list(EXPORT_FORMATS.values())
ENTRIES = {f.entry for f in REGISTERED}
# The commands whose options take export formats, and the option.
FORMAT_OPTIONS = {("solve", "--export"), ("generate", "--export"), ("batch", "--export"), ("export", "--to")}


def _name(spec: ExportFormat) -> str:
    return spec.name


def _needs_available(spec: ExportFormat) -> None:
    if not spec.available():
        assert spec.extra is not None
        pytest.skip(f"{spec.name} export needs the {spec.extra.name} extra")


# -- (1) the records --------------------------------------------------------------------------------------------------


def test_the_records_are_well_formed() -> None:
    assert REGISTERED, "no export format is registered"
    assert FORMATS == tuple(f.name for f in REGISTERED)
    assert all(name == spec.name for name, spec in EXPORT_FORMATS.items())
    assert len(ENTRIES) == len(REGISTERED), "two formats write the same entry of a scene folder"
    assert OUTPUTS == {f.name: f.output for f in REGISTERED}
    assert DEFAULT_FORMATS == tuple(f.name for f in REGISTERED if f.extra is None)
    for spec in REGISTERED:
        assert spec.folder == ("/" in spec.output)
        assert spec.entry == spec.output.split("/")[0]
        assert spec.made_from in ("model", "bodies")
        assert spec.description and "\n" not in spec.description
        assert spec.help_line().startswith(f"{spec.name}: {spec.description}")
        if spec.extra is not None:
            assert spec.extra.name in spec.help_line()
    assert XML_FILE == EXPORT_FORMATS["mjcf"].output  # the MJCF reader reads what the MJCF record says it writes


@pytest.mark.parametrize(
    ("changes", "problem"),
    [
        ({"name": "all"}, "not all or none"),
        ({"name": "none"}, "not all or none"),
        ({"name": "Glb"}, "lower-case"),
        ({"output": "../scene.glb"}, "not FILE or FOLDER/FILE"),
        ({"output": "/tmp/scene.glb"}, "not FILE or FOLDER/FILE"),
        ({"output": "a/b/scene.glb"}, "not FILE or FOLDER/FILE"),
        ({"output": "."}, "not FILE or FOLDER/FILE"),
        ({"output": "glb/"}, "not FILE or FOLDER/FILE"),
        ({"description": "two\nlines"}, "one line"),
    ],
)
def test_a_malformed_record_is_refused(changes: dict[str, str], problem: str) -> None:
    fields = {"name": "glb2", "output": "scene2.glb", "description": "d", "write": EXPORT_FORMATS["glb"].write}
    with pytest.raises(ValueError, match=problem):
        ExportFormat(**(fields | changes), made_from="bodies")  # type: ignore[arg-type]


# -- (2) each format writes what its record says ----------------------------------------------------------------------


@pytest.mark.parametrize("spec", REGISTERED, ids=_name)
def test_every_format_writes_what_its_record_says(spec: ExportFormat, desk_scene: Scene, tmp_path: Path) -> None:
    _needs_available(spec)
    folder = tmp_path / "scene"
    save_scene(desk_scene, folder / SCENE_FILE)
    written = export_scene(desk_scene, folder, [spec.name])
    assert written == {spec.name: folder / spec.output}
    assert (folder / spec.output).is_file()
    entry = folder / spec.entry
    assert entry.is_dir() if spec.folder else entry.is_file()
    assert {p.name for p in folder.iterdir()} == {SCENE_FILE, spec.entry, MANIFEST}, "written beside its entry"

    manifest = read_manifest(folder)
    assert manifest is not None
    if spec.recorded:
        on_disk = {p.relative_to(folder).as_posix() for p in [entry, *entry.rglob("*")] if p.is_file()}
        assert set(manifest.exports[spec.name].files) == on_disk
        assert spec.output in on_disk
    else:
        assert spec.name not in manifest.exports

    # fileio takes the folder for physcensis's (each entry of the kind it writes under that name) ...
    assert fileio.owned_entries(folder) == {SCENE_FILE, spec.entry, MANIFEST}
    fileio.check_output_dir(folder)  # ... and writes into it again without --overwrite
    # ... and the gallery and the diversity scan never take an export for a scene folder.
    if spec.folder:
        shutil.copy(folder / SCENE_FILE, entry / SCENE_FILE)
    assert scene_folders(tmp_path) == [folder]
    assert find_scene_folders(tmp_path) == [folder]


# -- (3) fileio's names of the exports ------------------------------------------------------------------------------


def test_fileio_names_exactly_the_registrys_entries() -> None:
    folders = {f.entry for f in REGISTERED if f.folder}
    files = ENTRIES - folders
    assert fileio.EXPORT_FOLDERS == folders, "fileio.EXPORT_FOLDERS must name the folder of every folder format"
    assert fileio.EXPORT_FILES == files, "fileio.EXPORT_FILES must name the file of every one-file format"
    assert ENTRIES <= fileio.LEGACY_OUTPUTS
    assert folders <= fileio.FOLDER_OUTPUTS and not files & fileio.FOLDER_OUTPUTS
    assert not ENTRIES & fileio.SCENE_FILES, "an export would replace a scene folder's own file"
    assert {SCENE_FILE, MANIFEST} <= fileio.SCENE_FILES


@pytest.mark.parametrize("spec", REGISTERED, ids=_name)
def test_the_overwrite_rules_refuse_a_users_entry_of_the_other_kind(spec: ExportFormat, tmp_path: Path) -> None:
    """Even with --overwrite, a user's file where a format writes its folder (or a folder where it writes its file)
    is refused: replacing it would delete what is in it."""
    folder = tmp_path / "mine"
    folder.mkdir()
    (folder / "notes.txt").write_text("mine")
    if spec.folder:
        (folder / spec.entry).write_text("a file of mine")
    else:
        (folder / spec.entry).mkdir()
    kind = "folder" if spec.folder else "file"
    with pytest.raises(fileio.OutputError, match=re.escape(f"writes its {spec.entry} {kind}")):
        fileio.check_output_dir(folder, overwrite=True)


# -- (4) exports.json and the command line --------------------------------------------------------------------------


def test_exports_json_takes_the_recorded_formats() -> None:
    assert typing.get_args(FormatName) == tuple(f.name for f in REGISTERED if f.recorded), (
        "manifest.FormatName must name every format whose record says exports.json records it"
    )


def test_the_cli_takes_exactly_the_registrys_names() -> None:
    for spec in REGISTERED:
        if spec.available():
            assert parse_formats(spec.name) == parse_formats([spec.name.upper()]) == (spec.name,)
        else:
            with pytest.raises(ExportError, match="optional extra"):
                parse_formats(spec.name)
    assert parse_formats("all") == available_formats() == tuple(f.name for f in REGISTERED if f.available())
    assert parse_formats("none") == ()
    with pytest.raises(ExportError, match=re.escape(f"choose from {', '.join(FORMATS)}, all or none")):
        parse_formats("fbx")
    assert set(KEYWORDS).isdisjoint(FORMATS)
    assert EXPORT_TO_CHOICES == f"{', '.join(FORMATS)} or all"


def _options(command: Any, path: tuple[str, ...] = ()) -> dict[tuple[str, str], Any]:
    """(command path, option) -> the option, for every option of every command of the CLI (Typer's own click)."""
    found = {(" ".join(path), opt): param for param in command.params for opt in param.opts}
    for name, sub in getattr(command, "commands", {}).items():
        found |= _options(sub, (*path, name))
    return found


def test_every_option_that_takes_formats_lists_the_registrys() -> None:
    options = _options(typer.main.get_command(app))
    assert FORMAT_OPTIONS <= set(options)
    for key in FORMAT_OPTIONS:
        help_text = " ".join((getattr(options[key], "help", None) or "").split())
        shown = re.findall(r"\b[a-z][a-z0-9_]*\b", help_text)
        missing = [name for name in FORMATS if name not in shown]
        assert not missing, f"{' '.join(key)} --help does not list {missing}"
    to_help = " ".join((getattr(options[("export", "--to")], "help", None) or "").split())
    for spec in REGISTERED:
        assert spec.help_line() in to_help


# -- (5) the physics every format carries ---------------------------------------------------------------------------


def test_the_exporters_physics_is_the_mujoco_scenes(desk_scene: Scene) -> None:
    catalogue = default_catalogue()
    model = build_scene(desk_scene, catalogue, visual=False).model
    assert tuple(model.opt.gravity) == pytest.approx((0.0, 0.0, -GRAVITY_M_S2))
    ground = model.geom("support_ground")
    assert tuple(ground.friction) == pytest.approx((GROUND_FRICTION, TORSIONAL_FRICTION, ROLLING_FRICTION))
    assert tuple(ground.rgba) == pytest.approx(GROUND_RGBA, abs=1e-6)
    support = model.body("support").id
    export = export_scene_bodies(desk_scene, catalogue)
    frictions = {
        round(float(model.geom_friction[g][0]), 9)
        for g in range(model.ngeom)
        if model.geom_bodyid[g] == support and model.geom_contype[g]
    }
    assert frictions == {round(export.support_friction, 9)}
