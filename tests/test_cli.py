from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from typer.testing import CliRunner

from physcensis.cli import app

from .conftest import EXAMPLES

runner = CliRunner()


def test_check_clean_program_exits_zero() -> None:
    result = runner.invoke(app, ["check", str(EXAMPLES / "dining_4.json")])
    assert result.exit_code == 0, result.output
    assert "0 errors" in result.output


def test_check_json_lists_problems_and_exits_one(tmp_path: Path) -> None:
    path = tmp_path / "bad.json"
    path.write_text('[["cup_0", "a cup"], ["cup_0", "PLACE-ON", "root", {}]]')
    result = runner.invoke(app, ["check", str(path), "--json"])
    assert result.exit_code == 1
    rows = json.loads(result.stdout)
    assert rows == [{"index": 2, "object": "cup_0", "severity": "error", "rule": "place-on-root",
                     "message": rows[0]["message"]}]
    assert set(rows[0]) >= {"index", "object", "severity", "message"}


def test_check_unreadable_file_exits_two_with_one_line(tmp_path: Path) -> None:
    result = runner.invoke(app, ["check", str(tmp_path / "nope.json")])
    assert result.exit_code == 2
    assert "cannot read" in result.output and "Traceback" not in result.output
    garbage = tmp_path / "garbage.txt"
    garbage.write_bytes(b"\xff\xfe\x00 not utf8")
    assert runner.invoke(app, ["check", str(garbage)]).exit_code == 2


def test_check_reads_stdin_and_support_option() -> None:
    text = '[["a","a cup"],["a","PLACE-ON-BASE","root",{"x":2,"y":0}],["a","FACING-FRONT","root"]]'
    assert runner.invoke(app, ["check", "-"], input=text).exit_code == 0
    result = runner.invoke(app, ["check", "-", "--support", "table:1x1"], input=text)
    assert result.exit_code == 1 and "off the support" in result.output
    bad_support = runner.invoke(app, ["check", "-", "--support", "table:one"], input=text)
    assert bad_support.exit_code == 2


def test_predicates_json_lists_the_registry() -> None:
    result = runner.invoke(app, ["predicates", "--json"])
    assert result.exit_code == 0
    names = [row["name"] for row in json.loads(result.stdout)]
    assert "PLACE-ON" in names and len(names) == 26


def test_console_script_runs_in_a_real_process() -> None:
    exe = Path(sys.executable).with_name("physcensis")
    done = subprocess.run([str(exe), "check", str(EXAMPLES / "desk_llm_style.txt")],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    missing = subprocess.run([str(exe), "check", "/no/such/file"], capture_output=True, text=True, timeout=120)
    assert missing.returncode == 2
    assert "Traceback" not in missing.stderr and len(missing.stderr.strip().splitlines()) == 1


def test_solve_writes_a_scene_folder(tmp_path: Path) -> None:
    out = tmp_path / "dining"
    result = runner.invoke(app, ["solve", str(EXAMPLES / "dining_4.json"), "--out", str(out), "--no-physics"])
    assert result.exit_code == 0, result.output
    assert {p.name for p in out.iterdir()} == {"scene.json", "report.json", "layout.png", ".physcensis.json"}
    assert "placed 16" in result.output


def test_solve_with_program_errors_exits_one_and_writes_nothing(tmp_path: Path) -> None:
    bad = tmp_path / "bad.json"
    bad.write_text('[["cup_0", "a cup"], ["cup_0", "PLACE-ON", "root", {}]]')
    result = runner.invoke(app, ["solve", str(bad), "--out", str(tmp_path / "out"), "--no-physics"])
    assert result.exit_code == 1 and "place" in result.output.lower()
    assert not (tmp_path / "out").exists()
