"""What the prompt asked for and the scene lacks is said in the report and the printed summary, and the command
does not exit as a clean success."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from physcensis.agent.planner import OfflinePlanner
from physcensis.cli import app


def test_the_reading_counts_what_each_category_asks_for() -> None:
    planner = OfflinePlanner()
    assert planner.requested("three mugs, a few apples and some pens next to the laptop") == {
        "mug": 3,
        "apple": 2,  # "a few": two at least
        "pen": 2,
        "laptop": 1,
    }
    assert planner.requested("a stack of plates and a stack of 5 books")["plate"] == 2  # no height said
    assert planner.requested("a stack of plates and a stack of 5 books")["book"] == 5


def test_what_is_asked_is_filed_under_the_category_its_noun_names() -> None:
    """An adjective does not change what was asked for: the words "empty glass" best match an empty french press,
    which no glass is (the planner draws glasses, so counting a french press made a false "missing")."""
    planner = OfflinePlanner()
    assert planner.requested("a glass pitcher with two empty glasses in front of it") == {"pitcher": 1, "glass": 2}
    assert planner.requested("a toothbrush cup and a tumbler") == {"cup": 1, "glass": 1}


@pytest.mark.slow
@pytest.mark.long
def test_what_did_not_fit_is_said_and_the_run_is_not_a_clean_success(tmp_path: Path) -> None:
    out = tmp_path / "scene"
    args = ["generate", "twelve mugs and a laptop", "--support", "table:0.4x0.4", "--export", "none", "--out", str(out)]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 1, result.output
    missing = json.loads((out / "report.json").read_text())["generate"]["missing"]
    (mugs,) = [row for row in missing if row["category"] == "mug"]
    assert mugs["asked"] == 12 and mugs["placed"] < 12
    assert "asked for and not in the scene: mug" in " ".join(result.output.split())
