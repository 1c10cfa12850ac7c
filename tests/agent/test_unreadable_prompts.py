"""A prompt the offline reading cannot read (it names no object, no diners, no kind of scene) is refused in one line
with exit code 2 and nothing written; asked for, the default scene comes instead, every object of it said to be the
planner's."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from physcensis.agent.planner import OfflinePlanner
from physcensis.api import generate
from physcensis.cli import app
from physcensis.errors import UnreadablePromptError

UNREADABLE = ["", "   ", "asdf qwerty zxcv", "🙂🙂🙂", "!!! ???", "1234 5678"]
READABLE = ["a tidy desk", "a mug", "a dinner for two", "two gizmos on a shelf", "a kitchen counter"]


@pytest.mark.parametrize("prompt", UNREADABLE)
def test_a_prompt_naming_nothing_is_refused_by_the_api(prompt: str) -> None:
    with pytest.raises(UnreadablePromptError, match="names no object"):
        generate(prompt)


def test_what_names_a_thing_or_a_scene_is_read() -> None:
    planner = OfflinePlanner()
    assert all(planner.reads(prompt) for prompt in READABLE)
    assert not any(planner.reads(prompt) for prompt in UNREADABLE)


def test_the_command_says_why_in_one_line_exits_2_and_writes_nothing(tmp_path: Path) -> None:
    out = tmp_path / "scene"
    result = CliRunner().invoke(app, ["generate", "asdf qwerty zxcv", "--out", str(out)])
    assert result.exit_code == 2
    assert "names no object" in result.output and "--default-scene" in result.output
    assert "Traceback" not in result.output
    assert not out.exists() or not any(out.iterdir())


@pytest.mark.slow
def test_the_default_scene_asked_for_is_said_to_be_the_planners(tmp_path: Path) -> None:
    out = tmp_path / "scene"
    result = CliRunner().invoke(app, ["generate", "asdf qwerty zxcv", "--default-scene", "--out", str(out)])
    assert result.exit_code == 0, result.output
    report = json.loads((out / "report.json").read_text())
    placed = {o["id"] for o in json.loads((out / "scene.json").read_text())["objects"] if o["status"] == "placed"}
    added = {row["id"] for row in report["generate"]["added"]}
    assert placed and placed == added  # nothing in it was asked for, and the report says so of every object
    assert all("names no object" in row["why"] for row in report["generate"]["added"])
    assert "added (not in the prompt)" in result.output
