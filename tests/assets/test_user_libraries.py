"""User libraries as first-class assets: named once for every command, pinned by id, copied into scene folders.

The library is built from real third-party meshes (pybullet_data's, installed with the `bullet` extra) and
trimesh-made ones with holes; scenes that use it must still render, export and settle after it is moved away.
"""

from __future__ import annotations

import json
import shutil
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
import trimesh
import yaml
from typer.testing import CliRunner

from physcensis.assets.catalogue import Catalogue, use_libraries
from physcensis.assets.errors import AssetError
from physcensis.assets.libraries import (
    CONFIG_ENV,
    LIBRARY_ENV,
    ConfigError,
    configured_libraries,
    forget_library,
    register_library,
)
from physcensis.cli import app
from physcensis.ids import pinned_id
from physcensis.program import check_program, parse_program
from physcensis.scene import load_scene

pybullet_data = pytest.importorskip("pybullet_data")
runner = CliRunner()


@pytest.fixture(autouse=True)
def _own_config(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, cache_dir: Path) -> Iterator[Path]:
    """Each test has its own (empty) config file and no library in the environment; the default catalogue is put
    back to the built-ins afterwards, so no other test sees these libraries."""
    config = tmp_path / "config" / "config.yaml"
    monkeypatch.setenv(CONFIG_ENV, str(config))
    monkeypatch.delenv(LIBRARY_ENV, raising=False)
    yield config
    monkeypatch.delenv(LIBRARY_ENV, raising=False)
    monkeypatch.setenv(CONFIG_ENV, str(tmp_path / "none.yaml"))
    use_libraries(())


def _open_bin() -> trimesh.Trimesh:
    """A 16 x 12 x 7 cm open bin with 1 cm walls (concave: it must keep its cavity)."""
    outer = trimesh.creation.box((0.16, 0.12, 0.07))
    inner = trimesh.creation.box((0.14, 0.10, 0.07))
    inner.apply_translation((0, 0, 0.01))
    return trimesh.boolean.difference([outer, inner], engine="manifold")


def _with_holes(mesh: trimesh.Trimesh, count: int) -> trimesh.Trimesh:
    """The mesh with `count` faces removed: holes, as scanned and exported meshes often have."""
    keep = np.ones(len(mesh.faces), dtype=bool)
    keep[np.linspace(0, len(mesh.faces) - 1, count).astype(int)] = False
    return trimesh.Trimesh(mesh.vertices, mesh.faces[keep], process=False)


def _library(folder: Path) -> Path:
    """pybullet_data's soccer ball and cube plus trimesh-made blocks, a jar with holes and an open bin."""
    meshes = folder / "meshes"
    meshes.mkdir(parents=True)
    data = Path(pybullet_data.getDataPath())
    for name in ("soccerball.obj", "soccerball.mtl", "cube.obj"):
        shutil.copy(data / name, meshes / name)
    block = trimesh.creation.box((0.12, 0.09, 0.04))
    (meshes / "block.stl").write_bytes(block.export(file_type="stl"))
    jar = _with_holes(trimesh.creation.cylinder(0.03, 0.1, sections=24), 3)
    (meshes / "jar.ply").write_bytes(jar.export(file_type="ply"))
    (meshes / "bin.obj").write_text(_open_bin().export(file_type="obj"))
    entries = [
        {"file": "meshes/soccerball.obj", "id": "lib_ball", "category": "soccer ball", "scale": 0.2},
        {"file": "meshes/cube.obj", "id": "lib_cube", "category": "toy block", "scale": 0.05},
        {"file": "meshes/block.stl", "id": "lib_block", "category": "wooden block", "description": "a pine block"},
        {"file": "meshes/jar.ply", "id": "lib_jar", "category": "jar", "description": "a red soda can"},
        {"file": "meshes/bin.obj", "id": "lib_bin", "category": "storage bin", "container": True},
    ]
    (folder / "library.yaml").write_text(yaml.safe_dump({"name": "test objects", "assets": entries}))
    return folder


@pytest.fixture(scope="module")
def library(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return _library(tmp_path_factory.mktemp("libraries") / "objects")


PINNED = {
    "support": {"kind": "table", "size": [0.8, 0.6]},
    "program": [
        ["block", "asset:lib_block"],
        ["block", "PLACE-ON-BASE", "root", {"x": 0.15, "y": 0.15}],
        ["block", "FACING-FRONT", "root", {}],
        ["bin", "asset:lib_bin"],
        ["bin", "PLACE-ON-BASE", "root", {"x": -0.15, "y": -0.15}],
        ["bin", "FACING-FRONT", "root", {}],
        ["cube", "asset:lib_cube a small toy block"],
        ["cube", "PLACE-ON", "block", {}],
        ["cube2", "asset:lib_cube"],
        ["cube2", "PLACE-ON", "cube", {}],
        ["jar", "asset:lib_jar"],
        ["jar", "PLACE-IN", "bin", {}],
        ["mug", "a white mug"],
        ["mug", "PLACE-ANYWHERE", "root", {}],
    ],
}


def _solve(tmp_path: Path, library: Path, program: dict = PINNED) -> Path:
    source = tmp_path / "program.json"
    source.write_text(json.dumps(program))
    out = tmp_path / "scene"
    result = runner.invoke(app, ["solve", str(source), "--out", str(out), "--library", str(library)])
    assert result.exit_code == 0, result.output
    return out


def test_pins_name_assets_exactly_and_unknown_pins_are_errors(library: Path) -> None:
    assert pinned_id("asset:lib_jar a jar") == "lib_jar" and pinned_id("Asset: lib_jar") == "lib_jar"
    assert pinned_id("a jar") is None and pinned_id("asset:") == ""
    catalogue = Catalogue([library])
    assert catalogue.resolve("asset:lib_jar").id == "lib_jar"  # although "a red soda can" would find a built-in too
    assert catalogue.resolve("asset:can_soda_red").id == "can_soda_red"  # built-ins can be pinned as well
    with pytest.raises(AssetError, match="no asset with id 'nope'"):
        catalogue.resolve("asset:nope")
    program = parse_program(
        json.dumps({"program": [["a", "asset:lib_jarr"], ["a", "PLACE-ANYWHERE", "root", {}], ["b", "asset:"]]})
    )
    problems = {(p.object, p.rule): p.message for p in check_program(program, assets=catalogue.id_set()).errors}
    assert "'lib_jar'" in problems["a", "unknown-asset"]  # with the close match
    assert ("b", "bad-asset-pin") in problems


def test_retrieval_puts_a_users_asset_first(library: Path) -> None:
    catalogue = Catalogue([library])
    assert catalogue.hits("lib_block")[0].asset_id == "lib_block"  # an id is a query too
    assert catalogue.hits("a pine block")[0].asset_id == "lib_block"  # its whole description
    assert catalogue.resolve("a red soda can").id == "lib_jar"  # the same description as a built-in: the user's wins
    assert Catalogue().resolve("a red soda can").id != "lib_jar"
    assert catalogue.hits("a bin")[0].asset_id == "lib_bin"  # a word of its name ("storage bin") is enough
    assert catalogue.hits("a soccer ball")[0].asset_id == "lib_ball"
    assert catalogue.hits("a tennis ball")[0].asset_id != "lib_ball"  # but not a name it does not have


def test_a_ranking_is_kept_until_a_library_changes_the_catalogue(
    library: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    catalogue = Catalogue()
    query = "a pine block on a desk"  # not an exact name: ranked by retrieval alone
    before = catalogue.hits(query)
    asked: list[str] = []
    search = catalogue.retriever.search
    monkeypatch.setattr(catalogue.retriever, "search", lambda text, k: asked.append(text) or search(text, k))
    assert catalogue.hits(query) == before and asked == []  # the same query: ranked once
    catalogue.add_library(library)
    assert "lib_block" not in [h.asset_id for h in before]
    assert catalogue.hits(query)[0].asset_id == "lib_block"  # ranked again, with the library's assets


@pytest.mark.slow
@pytest.mark.long
def test_a_scene_with_library_assets_works_without_the_library(tmp_path: Path, library: Path) -> None:
    out = _solve(tmp_path, library)
    scene = load_scene(out / "scene.json")
    assert {o.id for o in scene.placed} == {"block", "cube", "cube2", "bin", "jar", "mug"}
    assert sorted(scene.assets) == ["lib_bin", "lib_block", "lib_cube", "lib_jar"]  # built-ins are not copied
    assert all((out / record.file).is_file() for record in scene.assets.values())
    assert scene.assets["lib_jar"].source and scene.assets["lib_jar"].source.endswith("jar.ply")
    pose = {o.id: o.position for o in scene.placed}
    assert pose["cube"][2] == pytest.approx(pose["block"][2] + 0.04, abs=0.004)  # on the block's top
    assert pose["cube2"][2] == pytest.approx(pose["cube"][2] + 0.05, abs=0.004)  # a stack of two
    assert abs(pose["jar"][0] - pose["bin"][0]) < 0.07 and abs(pose["jar"][1] - pose["bin"][1]) < 0.05  # inside
    assert pose["jar"][2] < pose["bin"][2] + 0.03  # down on the bin's floor, not on its rim

    moved = tmp_path / "elsewhere"
    shutil.move(library, moved)
    try:
        assert not library.exists()
        rendered = runner.invoke(app, ["render", str(out), "--out", str(tmp_path / "view.png")])
        assert rendered.exit_code == 0, rendered.output
        exported = runner.invoke(app, ["export", str(out), "--to", "mjcf,urdf,glb", "--out", str(tmp_path / "exp")])
        assert exported.exit_code == 0, exported.output
        assert (tmp_path / "exp" / "mjcf").is_dir() and (tmp_path / "exp" / "scene.glb").stat().st_size > 1000
        settled = runner.invoke(app, ["eval", "settle", str(out), "--json"])
        assert settled.exit_code == 0, settled.output
        assert json.loads(settled.output)["mean_m"] < 0.002  # everything rests where it was placed
    finally:
        shutil.move(moved, library)


@pytest.mark.slow
def test_a_damaged_copy_is_refused_by_name(tmp_path: Path, library: Path) -> None:
    out = _solve(tmp_path, library)
    copy = out / "assets" / "lib_jar.npz"
    copy.write_bytes(copy.read_bytes()[:-10])
    result = runner.invoke(app, ["eval", "settle", str(out)])
    assert result.exit_code == 2
    assert "lib_jar.npz" in result.output and "does not match its hash" in result.output


def test_config_file_and_environment_name_libraries(tmp_path: Path, library: Path, _own_config: Path) -> None:
    assert configured_libraries() == []
    assert register_library(library) and not register_library(library)  # once
    assert configured_libraries() == [library.resolve()]
    assert yaml.safe_load(_own_config.read_text())["libraries"] == [str(library.resolve())]
    shown = runner.invoke(app, ["assets", "show", "lib_block", "--json"])  # no --library: the config names it
    assert shown.exit_code == 0, shown.output
    assert json.loads(shown.output)["id"] == "lib_block"
    assert forget_library(library) and configured_libraries() == []


def test_the_environment_names_libraries_for_every_command(
    tmp_path: Path, library: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv(LIBRARY_ENV, f"{library}:{library}")  # twice: loaded once
    source = tmp_path / "program.json"
    source.write_text(json.dumps({"program": [["b", "asset:lib_block"], ["b", "PLACE-ANYWHERE", "root", {}]]}))
    assert runner.invoke(app, ["check", str(source)]).exit_code == 0
    monkeypatch.delenv(LIBRARY_ENV)
    refused = runner.invoke(app, ["check", str(source)])
    assert refused.exit_code == 1 and "lib_block" in refused.output


def test_a_broken_config_or_library_is_a_clear_message(tmp_path: Path, _own_config: Path) -> None:
    _own_config.parent.mkdir(parents=True, exist_ok=True)
    _own_config.write_text("libraries: [unclosed")
    with pytest.raises(ConfigError, match="config.yaml"):
        configured_libraries()
    listed = runner.invoke(app, ["assets", "list", "--json"])  # the built-ins still work; the config is a warning
    assert listed.exit_code == 0 and "config.yaml" in listed.stderr
    _own_config.write_text("libraries: [" + str(tmp_path / "gone") + "]")
    listed = runner.invoke(app, ["assets", "list", "--json"])
    assert listed.exit_code == 0 and "gone" in listed.stderr and "not found" in listed.stderr
    source = tmp_path / "program.json"
    source.write_text(json.dumps({"program": [["b", "a block"], ["b", "PLACE-ANYWHERE", "root", {}]]}))
    missing = runner.invoke(app, ["solve", str(source), "--out", str(tmp_path / "o"), "--library", str(tmp_path)])
    assert missing.exit_code == 2 and "no library file" in missing.output


def test_generate_reads_the_users_objects_offline(tmp_path: Path, library: Path) -> None:
    out = tmp_path / "gen"
    result = runner.invoke(
        app, ["generate", "a soccer ball next to a storage bin", "--library", str(library), "--out", str(out)]
    )
    assert result.exit_code == 0, result.output
    used = {o.asset for o in load_scene(out / "scene.json").placed}
    assert {"lib_ball", "lib_bin"} <= used


def test_import_remembers_the_library_and_forget_drops_it(library: Path, _own_config: Path) -> None:
    imported = runner.invoke(app, ["assets", "import", str(library), "--json"])
    assert imported.exit_code == 0, imported.output
    report = json.loads(imported.stdout)
    assert {a["id"] for a in report["imported"]} == {"lib_ball", "lib_cube", "lib_block", "lib_jar", "lib_bin"}
    assert report["registered_in"] == str(_own_config)
    assert runner.invoke(app, ["assets", "show", "lib_jar"]).exit_code == 0  # no --library needed any more
    forgot = runner.invoke(app, ["assets", "forget", str(library)])
    assert forgot.exit_code == 0, forgot.output
    assert runner.invoke(app, ["assets", "show", "lib_jar"]).exit_code == 2
    again = runner.invoke(app, ["assets", "forget", str(library)])
    assert again.exit_code == 2 and "is not in" in again.output
    kept = runner.invoke(app, ["assets", "import", str(library), "--no-register"])
    assert kept.exit_code == 0 and configured_libraries() == []


def test_batch_scenes_use_the_library_and_carry_its_assets(tmp_path: Path, library: Path) -> None:
    prompts = tmp_path / "prompts.txt"
    prompts.write_text("a soccer ball next to a storage bin\n")
    out = tmp_path / "batch"
    result = runner.invoke(
        app, ["batch", str(prompts), "--out", str(out), "--export", "none", "--library", str(library)]
    )
    assert result.exit_code == 0, result.output
    (folder,) = (out / "scenes").iterdir()
    scene = load_scene(folder / "scene.json")
    assert {"lib_ball", "lib_bin"} <= {o.asset for o in scene.placed}
    assert (folder / "assets" / "lib_ball.npz").is_file() and "lib_ball" in scene.assets


def test_import_refuses_an_id_another_library_or_a_built_in_has(tmp_path: Path, library: Path) -> None:
    assert runner.invoke(app, ["assets", "import", str(library)]).exit_code == 0
    other = tmp_path / "other"
    (other / "meshes").mkdir(parents=True)
    trimesh.creation.box((0.05, 0.05, 0.05)).export(other / "meshes" / "cube.stl")
    entries = [
        {"file": "meshes/cube.stl", "id": "lib_block"},  # the first library's
        {"file": "meshes/cube.stl", "id": "mug_white"},  # a built-in's
        {"file": "meshes/cube.stl", "id": "my_cube"},
    ]
    (other / "library.yaml").write_text(yaml.safe_dump({"assets": entries}))
    result = runner.invoke(app, ["assets", "import", str(other), "--json"])
    assert result.exit_code == 1
    report = json.loads(result.stdout)
    assert [a["id"] for a in report["imported"]] == ["my_cube"]
    reasons = {f["reason"] for f in report["failed"]}
    assert any("'lib_block' is already used by" in r and "block.stl" in r for r in reasons)
    assert any("'mug_white' is already used by a built-in asset" in r for r in reasons)
    again = runner.invoke(app, ["assets", "import", str(library)])  # its own ids, imported before: no clash
    assert again.exit_code == 0, again.output


def test_the_gallery_of_a_library_shows_its_assets(tmp_path: Path, library: Path) -> None:
    out = tmp_path / "gallery.png"
    result = runner.invoke(app, ["assets", "gallery", "--library", str(library), "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert "(5 assets)" in result.output and out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
