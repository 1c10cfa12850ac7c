"""The exports as users reach them: written by `solve`, and by `physcensis export` / `eval settle --engine bullet`."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from physcensis.cli import app
from physcensis.export import available_formats, parse_formats
from physcensis.scene import Scene, save_scene
from tests.conftest import EXAMPLES

runner = CliRunner()


@pytest.mark.slow
def test_solve_writes_every_available_format_and_lists_them_in_the_report(tmp_path: Path) -> None:
    out = tmp_path / "desk"
    result = runner.invoke(app, ["solve", str(EXAMPLES / "desk_basic.json"), "--out", str(out)])
    assert result.exit_code == 0, result.output
    report = json.loads((out / "report.json").read_text())
    assert set(report["exports"]) == set(available_formats())
    for main_file in report["exports"].values():
        assert (out / main_file).is_file()
    assert not [p for p in out.parent.iterdir() if p.name.startswith(".")]  # no staging left behind


def test_solve_export_option_limits_the_formats(tmp_path: Path) -> None:
    out = tmp_path / "desk"
    result = runner.invoke(app, ["solve", str(EXAMPLES / "desk_basic.json"), "--out", str(out), "--export", "glb"])
    assert result.exit_code == 0, result.output
    assert (out / "scene.glb").is_file() and not (out / "mjcf").exists() and not (out / "urdf").exists()


def test_unknown_export_format_is_refused_before_any_work(tmp_path: Path) -> None:
    result = runner.invoke(
        app, ["solve", str(EXAMPLES / "desk_basic.json"), "--out", str(tmp_path / "o"), "--export", "mjcf,fbx"]
    )
    assert result.exit_code == 2
    assert "fbx" in result.output and "Traceback" not in result.output
    assert not (tmp_path / "o").exists()


def test_parse_formats() -> None:
    assert parse_formats("all") == available_formats()
    assert parse_formats("none") == ()
    assert parse_formats("URDF, glb,urdf") == ("urdf", "glb")


def test_export_command_writes_the_asked_formats(desk_scene: Scene, tmp_path: Path) -> None:
    scene_file = save_scene(desk_scene, tmp_path / "scene.json")
    result = runner.invoke(
        app, ["export", str(scene_file), "--to", "mjcf", "--to", "urdf", "--out", str(tmp_path / "x")]
    )
    assert result.exit_code == 0, result.output
    assert (tmp_path / "x" / "mjcf" / "scene.xml").is_file()
    assert (tmp_path / "x" / "urdf" / "bodies.json").is_file()
    assert not (tmp_path / "x" / "scene.glb").exists()


def test_export_command_reports_a_bad_scene_in_one_line(tmp_path: Path) -> None:
    bad = tmp_path / "scene.json"
    bad.write_text('{"format": "physcensis.scene/1", "support": {"size": [1, -1]}}')
    result = runner.invoke(app, ["export", str(bad), "--to", "glb", "--out", str(tmp_path / "x")])
    assert result.exit_code == 2 and "support.size" in result.output and "Traceback" not in result.output


def test_eval_settle_with_bullet_engine(desk_scene: Scene, tmp_path: Path) -> None:
    pytest.importorskip("pybullet")
    scene_file = save_scene(desk_scene, tmp_path / "scene.json")
    result = runner.invoke(app, ["eval", "settle", str(scene_file), "--engine", "bullet", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["scenes"][0]["engine"] == "bullet"
    assert data["mean_m"] < 0.005
