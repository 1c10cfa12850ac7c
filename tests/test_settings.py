"""A run's settings are one object built at the edge: the API, `generate` and `batch` take every option, under the same
names, and hand the settings on whole."""

from __future__ import annotations

import dataclasses
import inspect
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

import physcensis.api
import physcensis.batch
from physcensis.batch import BatchError, Options
from physcensis.cli import app
from physcensis.cli.batch import batch as batch_command
from physcensis.cli.options import RUN_FLAGS
from physcensis.cli.scenes import generate as generate_command
from physcensis.settings import BudgetSettings, ModelSettings, RunSettings, SettingsError, VarietySettings

runner = CliRunner()


def _parameters(command: Any) -> set[str]:
    return set(inspect.signature(command).parameters)


@pytest.mark.parametrize("command", [generate_command, batch_command], ids=["generate", "batch"])
def test_generate_and_batch_take_every_run_option(command: Any) -> None:
    assert set(RUN_FLAGS) <= _parameters(command)
    settings_names = {"llm_timeout": "llm_timeout_s", "time_budget": "time_budget_s"}
    assert {settings_names.get(n, n) for n in RUN_FLAGS} == set(RunSettings.option_names())


def test_every_option_has_one_name_across_the_concerns() -> None:
    names = RunSettings.option_names()
    assert len(names) == len(set(names))
    assert set(names) == {
        f.name for c in (ModelSettings, BudgetSettings, VarietySettings) for f in dataclasses.fields(c)
    }


def test_flat_options_round_trip_and_change_only_what_they_name() -> None:
    settings = RunSettings.from_options(llm="qwen", rounds=3, variety="wide", vlm_feedback="remarks")
    assert (settings.models.llm, settings.budget.rounds, settings.draws.variety) == ("qwen", 3, "wide")
    assert RunSettings.from_options(**settings.options()) == settings
    assert settings.replace(rounds=1).models == settings.models


@pytest.mark.parametrize(
    ("options", "named"),
    [
        ({"roundz": 2}, "unknown option 'roundz'"),
        ({"rounds": 0}, "rounds 0: give 1 or more"),
        ({"llm_timeout_s": float("nan")}, "llm_timeout_s must be a positive number of seconds"),
        ({"time_budget_s": -1}, "time_budget_s must be a positive number of seconds"),
        ({"temperature": 3}, "temperature 3: give a number from 0 to 2"),
        ({"variety": "huge"}, "variety 'huge': give one of none, normal, wide"),
        ({"structured": "maybe"}, "structured 'maybe': give one of auto, on, off"),
        ({"llm": " "}, "llm ' ': give a non-empty name"),
        ({"max_objects": 10**9}, "max_objects 1000000000: give 1 to"),
    ],
)
def test_a_bad_option_is_refused_naming_it(options: dict[str, Any], named: str) -> None:
    with pytest.raises(SettingsError, match=named.replace("(", r"\(")):
        RunSettings.from_options(**options)


def test_the_api_refuses_an_unknown_option_before_any_work(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(physcensis.api, "default_catalogue", lambda: pytest.fail("work started"))
    with pytest.raises(SettingsError, match="unknown option 'llm_timeout'"):
        physcensis.api.generate("a mug", llm_timeout=5)


def test_the_same_flags_give_the_same_settings_to_generate_and_batch(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    seen: dict[str, RunSettings] = {}

    def fake_generate(prompt: str, *, settings: RunSettings, **_: Any) -> Any:
        seen["generate"] = settings
        raise SettingsError("stop here")

    def fake_run_batch(specs: object, out: object, *, options: Options, **_: object) -> object:
        seen["batch"] = options.settings
        raise BatchError("stop here")

    monkeypatch.setattr(physcensis.api, "generate", fake_generate)
    monkeypatch.setattr(physcensis.batch, "run_batch", fake_run_batch)
    flags = ["--llm", "m", "--temperature", "0.2", "--rounds", "2", "--max-objects", "40", "--time-budget", "30"]
    flags += ["--vlm", "v", "--vlm-feedback", "remarks", "--variety", "wide", "--no-context", "--hint", "on"]
    prompts = tmp_path / "p.txt"
    prompts.write_text("a cup\n")
    runner.invoke(app, ["generate", "a cup", "--out", str(tmp_path / "g"), *flags])
    runner.invoke(app, ["batch", str(prompts), "--out", str(tmp_path / "b"), *flags])
    expected = RunSettings.from_options(
        llm="m", temperature=0.2, rounds=2, max_objects=40, time_budget_s=30.0, vlm="v", vlm_feedback="remarks"
    ).replace(variety="wide", context=False, hint="on")
    assert seen == {"generate": expected, "batch": expected}


def test_a_bad_flag_value_is_one_line_naming_the_flag(tmp_path: Path) -> None:
    result = runner.invoke(app, ["generate", "a cup", "--out", str(tmp_path / "g"), "--vlm-feedback", "loud"])
    assert result.exit_code == 2
    assert result.output.startswith("error: invalid value for --vlm-feedback: 'loud' is not one of score, remarks, off")


def test_the_batch_worker_hands_the_settings_to_generate_whole(monkeypatch: pytest.MonkeyPatch) -> None:
    from physcensis.batch.prompts import Task
    from physcensis.batch.worker import make_scene

    seen: dict[str, Any] = {}

    def fake_generate(prompt: str, **kwargs: Any) -> Any:
        seen.update(kwargs)
        raise SettingsError("stop here")

    monkeypatch.setattr(physcensis.api, "generate", fake_generate)
    options = Options.of(exports=("none",), rounds=2, temperature=0.1, vlm="v", time_budget_s=50.0)
    outcome = make_scene(Task("cup_000", "cup", "a cup", "table:0.6x0.6", seed=1), options)
    assert not outcome.ok and seen["settings"] is options.settings
