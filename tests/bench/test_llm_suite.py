"""The LLM benchmark against a real local HTTP server (scripted): what it measures and the records it leaves."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from physcensis.api import generate
from physcensis.bench import __main__ as bench_main
from physcensis.bench.llm_suite import first_reply_clean, rounds_to_success, tokens_used
from physcensis.bench.prompt_suite import load_suite
from physcensis.scene import Support
from tests.agent.fake_server import FakeOpenAI, use_loopback_only

pytestmark = pytest.mark.physics


def _planner_program(case_id: str) -> str:
    """What the offline planner writes for a suite prompt: a reply a good model could give."""
    case = next(c for c in load_suite() if c["id"] == case_id)
    support = Support(kind=case["support"]["kind"], size=tuple(case["support"]["size"]))
    transcript = generate(case["prompt"], support=support, seed=0).transcript
    return str(next(row["program"] for row in transcript if row.get("feedback_kind") == "success"))


@pytest.mark.slow
@pytest.mark.long
def test_a_good_reply_and_a_broken_one_are_measured_and_both_leave_a_record(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    use_loopback_only(monkeypatch, "sk-test")
    good = _planner_program("books-stack-5")
    with FakeOpenAI([good]) as server:
        code = bench_main.main(
            [
                "llm",
                "--base-url",
                server.base_url,
                "--model",
                "fake-model",
                "--out",
                str(tmp_path / "good"),
                "--only",
                "books-stack-5",
                "--time-budget",
                "60",
                "--temperature",
                "0.2",
            ]
        )
        assert not any(body.get("stream") for body in server.requests)  # exact token counts: no streaming
        assert {body.get("temperature") for body in server.requests} == {0.2}
    assert code == 0
    record = json.loads((tmp_path / "good" / "llm.json").read_text())
    row = record["prompts"][0]
    assert row["first_reply_clean"] and row["expect_met"] and row["rounds_to_success"] == 1, row
    assert row["tokens"]["prompt_tokens"] > 0 and row["record"]
    assert record["summary"]["first_reply_clean"] == 1.0 and record["summary"]["expect_met"] == 1.0
    assert record["temperature"] == 0.2 and record["hint"] == "auto"
    assert (tmp_path / "good" / "books-stack-5" / "scene.json").is_file()

    with FakeOpenAI(["this is not a program"], repeat_last=True) as server:
        code = bench_main.main(
            [
                "llm",
                "--base-url",
                server.base_url,
                "--model",
                "fake-model",
                "--out",
                str(tmp_path / "bad"),
                "--only",
                "books-stack-5",
                "--time-budget",
                "20",
                "--hint",
                "off",  # the good run above keeps the default draft
            ]
        )
    assert code == 0
    row = json.loads((tmp_path / "bad" / "llm.json").read_text())["prompts"][0]
    assert not row["first_reply_clean"] and not row["expect_met"] and row["rounds_to_success"] is None, row
    folder = tmp_path / "bad" / "books-stack-5"
    assert row["record"] and not (folder / "scene.json").exists()
    assert json.loads((folder / "report.json").read_text())["ok"] is False


def test_measures_read_from_a_transcript() -> None:
    transcript = [
        {
            "round": 1,
            "agent": "llm",
            "feedback_kind": "grammar",
            "usage": {"prompt_tokens": 10, "completion_tokens": 3},
        },
        {"round": 2, "agent": "llm", "feedback_kind": "solver", "usage": None},
        {"round": 3, "agent": "llm", "feedback_kind": "success", "usage": {"prompt_tokens": 5, "completion_tokens": 2}},
    ]
    assert not first_reply_clean(transcript)
    assert first_reply_clean([{**transcript[1], "round": 1}])  # a solver failure: the reply itself was clean
    assert rounds_to_success(transcript) == 3 and rounds_to_success(transcript[:2]) is None
    assert tokens_used(transcript) == {"prompt_tokens": 15, "completion_tokens": 5}


def test_unknown_prompt_ids_are_refused(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exit_info:
        bench_main.main(["llm", "--base-url", "http://127.0.0.1:9/v1", "--model", "m", "--only", "no-such-prompt"])
    assert exit_info.value.code == 2 and "no-such-prompt" in capsys.readouterr().err


def test_a_round_the_loop_repaired_itself_is_not_the_models_success() -> None:
    transcript = [
        {"round": 1, "agent": "llm:m", "feedback_kind": "solver"},
        {"round": 2, "agent": "loop-repair", "feedback_kind": "success"},
    ]
    assert rounds_to_success(transcript) is None
    assert rounds_to_success([*transcript, {"round": 3, "agent": "llm:m", "feedback_kind": "success"}]) == 3
