"""A scene folder's exports must belong to its scene.json: `demo` (and whatever loads the folder's MJCF) refuses an
export of another scene, an edited export or an edited scene.json in one line naming the file, before any work;
`export` refuses to write into a folder that holds another scene; the normal path still works."""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

import pytest
from typer.testing import CliRunner, Result

from physcensis.cli import app
from physcensis.errors import ExportMismatchError
from physcensis.export import export_scene
from physcensis.export.manifest import MANIFEST, scene_identity
from physcensis.robot.world import build_world
from physcensis.scene import load_scene, save_scene
from tests.robot.programs import solved_folder

runner = CliRunner()
TASK = "pick cup_0 place-on plate_0"
XML = Path("mjcf") / "scene.xml"


@pytest.fixture(scope="module")
def scene_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A table with a plate, a mug (cup_0) and a bowl, solved and written with its MJCF export."""
    return solved_folder("small_scene.json", tmp_path_factory.mktemp("consistency") / "scene")


@pytest.fixture(scope="module")
def other_dir(scene_dir: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Another scene's folder: the mug is mug_9 here, 20 cm further front, and the bowl 10 cm to the left."""
    folder = tmp_path_factory.mktemp("consistency-other") / "scene"
    shutil.copytree(scene_dir, folder)
    data = json.loads((folder / "scene.json").read_text())
    for obj in data["objects"]:
        if obj["id"] == "cup_0":
            obj["id"] = "mug_9"
            obj["position"][0] += 0.2
        if obj["id"] == "bowl_0":
            obj["position"][1] += 0.1
    (folder / "scene.json").write_text(json.dumps(data))
    export_scene(load_scene(folder / "scene.json"), folder, ["mjcf"])
    return folder


def _copy(folder: Path, tmp_path: Path, name: str = "scene") -> Path:
    shutil.copytree(folder, tmp_path / name)
    return tmp_path / name


def _snapshot(folder: Path) -> dict[str, tuple[int, int]]:
    return {str(p.relative_to(folder)): (p.stat().st_size, p.stat().st_mtime_ns) for p in sorted(folder.rglob("*"))}


def _one_error_line(result: Result) -> str:
    assert result.exit_code == 2, result.output
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), result.output
    return lines[0]


def _move_in_xml(folder: Path, object_id: str, x: float) -> None:
    xml = folder / XML
    text, count = re.subn(rf'(<body name="{object_id}" pos=")[^ "]+', rf"\g<1>{x}", xml.read_text())
    assert count == 1
    xml.write_text(text)


def _refusal(folder: Path) -> str:
    with pytest.raises(ExportMismatchError) as caught:
        build_world(folder)
    message = str(caught.value)
    assert "\n" not in message
    return message


# -- demo: the folder is checked where the command loads it, before any planning ---------------------------------


def test_demo_refuses_an_mjcf_copied_from_another_scene_in_one_line_and_writes_nothing(
    scene_dir: Path, other_dir: Path, tmp_path: Path
) -> None:
    """Today's code ran into a KeyError traceback (cup_0 is no body of the other scene's MJCF)."""
    folder = _copy(scene_dir, tmp_path)
    shutil.rmtree(folder / "mjcf")
    shutil.copytree(other_dir / "mjcf", folder / "mjcf")
    before = _snapshot(tmp_path)
    result = runner.invoke(app, ["demo", str(folder), "--task", TASK, "--images", "none", "--out", str(tmp_path / "o")])
    line = _one_error_line(result)
    assert str(folder / XML) in line and "cup_0" in line and "physcensis export" in line
    assert _snapshot(tmp_path) == before  # no output folder, nothing changed in the scene's


def test_an_mjcf_of_the_same_ids_on_other_poses_is_refused(scene_dir: Path, other_dir: Path, tmp_path: Path) -> None:
    """The worst case of today's code: demonstrations recorded silently on the other scene's poses."""
    folder = _copy(scene_dir, tmp_path)
    bowl = load_scene(other_dir / "scene.json").object("bowl_0").position
    xml = (folder / XML).read_text()
    (folder / XML).write_text(re.sub(r'(<body name="bowl_0" pos=")[^"]+', rf"\g<1>{bowl[0]} {bowl[1]} {bowl[2]}", xml))
    (folder / MANIFEST).unlink()  # even without the record, the poses are checked
    message = _refusal(folder)
    assert message.startswith(f"{folder / XML}: object bowl_0 stands 0.1 m from where scene.json puts it")


def test_a_pose_edited_in_the_mjcf_is_refused(scene_dir: Path, tmp_path: Path) -> None:
    folder = _copy(scene_dir, tmp_path)
    _move_in_xml(folder, "cup_0", 0.11)
    message = _refusal(folder)
    assert message.startswith(f"{folder / XML}: object cup_0 stands 0.31 m from where scene.json puts it")
    assert message.endswith(f"physcensis export {folder} --to mjcf --out {folder}")


def test_a_scene_json_edited_after_the_export_is_refused(scene_dir: Path, tmp_path: Path) -> None:
    folder = _copy(scene_dir, tmp_path)
    scene = load_scene(folder / "scene.json")
    moved = scene.object("cup_0")
    moved.position = (moved.position[0] + 0.05, moved.position[1], moved.position[2])
    save_scene(scene, folder / "scene.json")
    message = _refusal(folder)
    assert message.startswith(f"{folder / 'scene.json'}: object cup_0 stands 0.05 m from where exports.json puts it")
    heavier = load_scene(scene_dir / "scene.json")
    heavier.object("bowl_0").mass *= 2  # no pose moved: the scene's identity still tells
    save_scene(heavier, folder / "scene.json")
    assert "masses, friction" in _refusal(folder)


def test_an_export_and_its_record_copied_from_another_scene_are_refused(
    scene_dir: Path, other_dir: Path, tmp_path: Path
) -> None:
    folder = _copy(scene_dir, tmp_path)
    shutil.rmtree(folder / "mjcf")
    shutil.copytree(other_dir / "mjcf", folder / "mjcf")
    shutil.copy(other_dir / MANIFEST, folder / MANIFEST)
    assert _refusal(folder).startswith(f"{folder / 'scene.json'}: has no object mug_9 (exports.json places it)")


def test_an_mjcf_edited_elsewhere_than_the_poses_is_refused_by_its_hash(scene_dir: Path, tmp_path: Path) -> None:
    folder = _copy(scene_dir, tmp_path)
    xml = folder / XML
    xml.write_text(xml.read_text().replace('mass="', 'mass="1', 1))
    assert _refusal(folder).startswith(f"{folder / XML}: is not the file written with this scene's exports")
    mesh = sorted((folder / "mjcf" / "meshes").iterdir())[0]
    shutil.copy(scene_dir / XML, xml)
    mesh.write_bytes(mesh.read_bytes()[:-50])  # one triangle less
    assert _refusal(folder).startswith(f"{folder / 'mjcf' / 'meshes' / mesh.name}: is not the file written")


def test_a_folder_written_before_exports_json_is_accepted_with_its_poses_checked(
    scene_dir: Path, tmp_path: Path
) -> None:
    folder = _copy(scene_dir, tmp_path)
    (folder / MANIFEST).unlink()
    world = build_world(folder)
    assert set(world.object_qpos) == {"plate_0", "cup_0", "bowl_0"}


def _doctype(text: str) -> str:
    return '<!DOCTYPE m [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;">]>\n' + text


HOSTILE_XML = {
    "entities": (_doctype, "DOCTYPE or ENTITY"),
    "an include": (lambda t: t.replace("<worldbody>", '<include file="/etc/hostname"/><worldbody>'), "<include>"),
    "a mesh from anywhere": (lambda t: re.sub(r'file="[^"]+"', 'file="/dev/zero"', t, count=1), "/dev/zero"),
    "a texture from a file": (lambda t: t.replace('builtin="checker"', 'file="/etc/hostname"'), "'file'"),
    "a huge texture": (lambda t: t.replace('width="64" height="64"', 'width="99999" height="99999"'), "width"),
    "a deep nest": (lambda t: t.replace("</worldbody>", "<body>" * 20 + "</body>" * 20 + "</worldbody>"), "deep"),
    "a frame shifting the objects": (
        lambda t: t.replace("<worldbody>", '<worldbody><frame pos="0 0 1">').replace(
            "</worldbody>", "</frame></worldbody>"
        ),
        "<frame>",
    ),
    "not XML": (lambda t: t[: len(t) // 2], "not well-formed XML"),
    "a NaN mass": (lambda t: re.sub(r'mass="[^"]+"', 'mass="nan"', t, count=1), "not finite"),
    "an absurd friction": (lambda t: re.sub(r'friction="[^" ]+', 'friction="1e300', t, count=1), "over 1e+09"),
}


@pytest.mark.parametrize("case", list(HOSTILE_XML))
def test_a_hostile_mjcf_is_refused_before_mujoco_reads_it(case: str, scene_dir: Path, tmp_path: Path) -> None:
    folder = _copy(scene_dir, tmp_path)
    (folder / MANIFEST).unlink()  # an old folder: only the file itself says what it is
    change, expected = HOSTILE_XML[case]
    (folder / XML).write_text(change((folder / XML).read_text()))
    message = _refusal(folder)
    assert message.startswith(str(folder / XML)) and expected in message


def test_a_linked_mesh_is_refused(scene_dir: Path, tmp_path: Path) -> None:
    folder = _copy(scene_dir, tmp_path)
    mesh = sorted((folder / "mjcf" / "meshes").iterdir())[0]
    mesh.unlink()
    mesh.symlink_to(scene_dir / "mjcf" / "meshes" / mesh.name)
    assert "is a symbolic link" in _refusal(folder)


def test_demo_batch_refuses_a_folder_of_scenes_holding_one_that_disagrees(
    scene_dir: Path, other_dir: Path, tmp_path: Path
) -> None:
    root = tmp_path / "scenes"
    _copy(scene_dir, root, "good")
    bad = _copy(scene_dir, root, "bad")
    shutil.copy(other_dir / XML, bad / XML)
    result = runner.invoke(
        app, ["demo-batch", str(root), "--task", TASK, "--images", "none", "--out", str(tmp_path / "o")]
    )
    assert str(bad / XML) in _one_error_line(result)
    assert not (tmp_path / "o").exists()


# -- export ---------------------------------------------------------------------------------------------------------


def test_export_refuses_a_folder_that_holds_another_scene_and_changes_nothing(
    scene_dir: Path, other_dir: Path, tmp_path: Path
) -> None:
    folder = _copy(scene_dir, tmp_path)
    before = _snapshot(tmp_path)
    result = runner.invoke(app, ["export", str(other_dir), "--to", "mjcf", "--out", str(folder)])
    line = _one_error_line(result)
    assert f"{folder}: holds another scene" in line and "mug_9" in line
    assert _snapshot(tmp_path) == before


def test_export_into_the_scenes_own_folder_again_works_and_keeps_the_other_records(
    scene_dir: Path, tmp_path: Path
) -> None:
    folder = _copy(scene_dir, tmp_path)
    scene = load_scene(folder / "scene.json")
    scene.prompt = "the same objects at the same poses, told otherwise"  # not what the exports are made of
    save_scene(scene, folder / "scene.json")
    glb = runner.invoke(app, ["export", str(folder), "--to", "glb", "--out", str(folder)])
    assert glb.exit_code == 0, glb.output
    mjcf = runner.invoke(app, ["export", str(folder / "scene.json"), "--to", "mjcf", "--out", str(folder)])
    assert mjcf.exit_code == 0, mjcf.output
    record = json.loads((folder / MANIFEST).read_text())
    assert record["scene"] == scene_identity(scene) and set(record["exports"]) == {"mjcf", "glb"}
    assert "scene.glb" in record["exports"]["glb"]["files"]
    assert set(build_world(folder).object_qpos) == {"plate_0", "cup_0", "bowl_0"}


def test_a_generated_folder_records_its_exports(scene_dir: Path) -> None:
    record = json.loads((scene_dir / MANIFEST).read_text())
    scene = load_scene(scene_dir / "scene.json")
    assert record["scene"] == scene_identity(scene)
    assert set(record["objects"]) == {o.id for o in scene.placed}
    assert {"mjcf/scene.xml"} < set(record["exports"]["mjcf"]["files"])
    assert MANIFEST in json.loads((scene_dir / ".physcensis.json").read_text())["entries"]
