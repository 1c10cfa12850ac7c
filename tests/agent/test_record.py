"""A failed generate always leaves a record; repeated failed programs change the repair strategy; a time budget."""

from __future__ import annotations

import json
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from physcensis.agent.llm import LLMAgent
from physcensis.agent.loop import generate_scene, program_key
from physcensis.api import Generated, write_generated
from physcensis.feedback.messages import corrected_entry
from physcensis.fileio import OWNER_FILE
from physcensis.scene import Support

from .conftest import SECRET_KEY
from .fake_server import MUG_AND_BOOK, FakeOpenAI, Reply

pytestmark = pytest.mark.physics
SUPPORT = Support(kind="table", size=(0.6, 0.6))

# MUG_AND_BOOK with the book's placement misspelt: the checker suggests the fix.
MISSPELT: list[Any] = json.loads(MUG_AND_BOOK)
MISSPELT[4] = ["book_0", "PLACE-ON-BAS", "root", {}]
BROKEN = json.dumps(MISSPELT)
# The same program, other whitespace and key order: still the same program.
BROKEN_REFORMATTED = json.dumps(MISSPELT, indent=2).replace('"x": 0.0, "y": 0.0', '"y": 0.0, "x": 0.0')


def _agent(server: FakeOpenAI) -> LLMAgent:
    # no draft (test_hint.py tests it): these tests are about the record and the time budget, which a draft counts in
    return LLMAgent("test-model", base_url=server.base_url, backoff_s=0.01, hint="off")


def test_program_key_ignores_whitespace_and_key_order_but_not_content() -> None:
    assert program_key(BROKEN) == program_key(BROKEN_REFORMATTED)
    assert program_key(BROKEN) != program_key(MUG_AND_BOOK)
    assert program_key("no  program\nhere") == program_key("no program here")


def test_corrected_entry_applies_the_checkers_suggestion() -> None:
    problem = {"message": "unknown predicate 'PLACE-ON-BAS'; did you mean PLACE-ON-BASE?"}
    assert corrected_entry(["b", "PLACE-ON-BAS", "root", {}], problem) == ["b", "PLACE-ON-BASE", "root", {}]
    param = {"message": "PLACE-ON-BASE has no parameter 'xx'; did you mean 'x'? (its parameters: x, y)"}
    assert corrected_entry(["b", "PLACE-ON-BASE", "root", {"xx": 0.1}], param) == [
        "b",
        "PLACE-ON-BASE",
        "root",
        {"x": 0.1},
    ]
    assert corrected_entry(["b", "PLACE-ON", "root", {}], {"message": "PLACE-ON cannot target root"}) is None


def test_a_repeated_broken_program_gets_same_program_feedback_and_the_loop_drops_what_fails(
    fake_openai: Callable[..., FakeOpenAI], tmp_path: Path
) -> None:
    server = fake_openai(BROKEN, BROKEN_REFORMATTED, repeat_last=True)
    result = generate_scene("a mug and a book", _agent(server), support=SUPPORT, retries=5)
    second_user = server.messages[1][-1]["content"]
    assert "same program" not in second_user  # the first failure gets the ordinary feedback
    repeat = result.transcript[1]["feedback"]
    assert "Your reply is the same program as round 1, which failed because" in repeat
    assert '["book_0", "PLACE-ON-BASE", "root", {}]' in repeat  # the exact corrected entry
    assert "fewer objects" in repeat and "dropped from your program for you" in repeat
    # At the repeat the loop frees the failing book itself (PLACE-ANYWHERE) and that program solves.
    authors = [row["agent"] for row in result.transcript]
    assert authors == ["llm:test-model", "llm:test-model", "loop-repair"]
    assert result.ok and result.solution is not None
    assert {o.id for o in result.solution.scene.placed} == {"mug_0", "book_0"}
    assert len(server.requests) == 2
    out = write_generated(Generated(result, "a mug and a book", SUPPORT), tmp_path / "scene", exports=())
    rows = [json.loads(line) for line in (out / "transcript.jsonl").read_text().splitlines()]
    assert rows[1]["repeat_of_round"] == 1 and rows[-1]["feedback_kind"] == "success"
    assert all(row["usage"]["total_tokens"] > 0 for row in rows[:2])  # the fake server reports usage


def test_a_server_that_fails_every_round_leaves_a_failed_record_and_no_scene(
    fake_openai: Callable[..., FakeOpenAI], tmp_path: Path
) -> None:
    server = fake_openai("I cannot help with that.", "Still no program, sorry.", repeat_last=True)
    result = generate_scene("a mug", _agent(server), support=SUPPORT, retries=2)
    assert not result.ok and result.stop_reason == "retries"
    assert result.failure == "no program solved in 3 round(s) (feedback: grammar, grammar, grammar)"
    assert "same program as round 2" in result.transcript[2]["feedback"]
    assert "dropped from your program" not in result.transcript[2]["feedback"]  # nothing there to drop
    out = write_generated(Generated(result, "a mug", SUPPORT), tmp_path / "failed")
    assert {p.name for p in out.iterdir()} == {"transcript.jsonl", "report.json", OWNER_FILE}  # no scene
    report = json.loads((out / "report.json").read_text())
    assert report["ok"] is False
    run = report["generate"]
    assert run["stop_reason"] == "retries" and run["failure"] == result.failure
    assert [e["program"] for e in run["exchanges"]] == [
        "I cannot help with that.",
        "Still no program, sorry.",
        "Still no program, sorry.",
    ]
    assert all("could not be read as a program" in e["feedback"] for e in run["exchanges"])
    assert all(r["seconds"] >= 0 and r["usage"]["completion_tokens"] > 0 for r in run["requests"])
    assert len((out / "transcript.jsonl").read_text().splitlines()) == 3


def test_an_agent_error_is_recorded_too(fake_openai: Callable[..., FakeOpenAI], tmp_path: Path) -> None:
    server = fake_openai(Reply(status=400, error="model not found"))
    result = generate_scene("a mug", _agent(server), support=SUPPORT)
    assert not result.ok and result.stop_reason == "agent-error"
    assert result.failure is not None and result.failure.startswith("the agent failed:")
    out = write_generated(Generated(result, "a mug", SUPPORT), tmp_path / "err")
    report = json.loads((out / "report.json").read_text())
    assert report["ok"] is False and report["generate"]["stop_reason"] == "agent-error"
    assert "model not found" in report["generate"]["exchanges"][0]["error"]
    assert not (out / "scene.json").exists()


def test_a_failed_record_replaces_an_earlier_scene_but_not_a_users_folder(
    fake_openai: Callable[..., FakeOpenAI], tmp_path: Path
) -> None:
    good = generate_scene("a mug and a book", _agent(fake_openai(MUG_AND_BOOK)), support=SUPPORT)
    out = write_generated(Generated(good, "a mug and a book", SUPPORT), tmp_path / "scene", exports=())
    assert (out / "scene.json").exists()
    bad = generate_scene("a mug", _agent(fake_openai("no", repeat_last=True)), support=SUPPORT, retries=0)
    write_generated(Generated(bad, "a mug", SUPPORT), out)
    assert not (out / "scene.json").exists()  # the old scene does not pass for this run's
    assert json.loads((out / "report.json").read_text())["ok"] is False
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "notes.txt").write_text("keep me")
    with pytest.raises(Exception, match="not a physcensis output"):
        write_generated(Generated(bad, "a mug", SUPPORT), mine)
    assert {p.name for p in mine.iterdir()} == {"notes.txt"}


def test_the_time_budget_stops_a_slow_server_and_says_so(fake_openai: Callable[..., FakeOpenAI]) -> None:
    server = fake_openai("not a program", Reply(content="still not a program", delay_s=5.0), repeat_last=True)
    begun = time.perf_counter()
    result = generate_scene("a mug", _agent(server), support=SUPPORT, retries=10, time_budget_s=1.5)
    assert time.perf_counter() - begun < 4.0
    assert result.stop_reason == "time-budget" and not result.ok
    # The second (slow) request began within the budget and was cut when it ran out; no third.
    assert len(server.requests) == 2 and "error" in result.transcript[-1]
    assert result.failure == "the time budget of 1.5 s ran out after 1 round(s)"


def test_the_time_budget_cuts_a_request_that_would_outlast_it(fake_openai: Callable[..., FakeOpenAI]) -> None:
    server = fake_openai(Reply(content=MUG_AND_BOOK, delay_s=5.0), repeat_last=True)
    agent = LLMAgent("test-model", base_url=server.base_url, backoff_s=0.01, timeout_s=60.0, hint="off")
    begun = time.perf_counter()
    result = generate_scene("a mug", agent, support=SUPPORT, time_budget_s=0.5)
    assert time.perf_counter() - begun < 3.0  # not the 5 s reply, nor the 60 s request limit
    assert result.stop_reason == "time-budget" and not result.ok
    assert result.failure == "the time budget of 0.5 s ran out after 0 round(s)"
    assert "error" in result.transcript[0] and agent.timeout_s == 60.0  # recorded; the agent's limit restored


def test_the_time_budget_keeps_the_best_scene_so_far(fake_openai: Callable[..., FakeOpenAI]) -> None:
    server = fake_openai(MUG_AND_BOOK, Reply(content=MUG_AND_BOOK, delay_s=0.5), repeat_last=True)
    result = generate_scene("a mug and a book", _agent(server), support=SUPPORT, rounds=5, time_budget_s=0.3)
    assert result.stop_reason == "time-budget"
    assert result.ok and result.solution is not None and len(result.solution.scene.placed) == 2
    assert result.failure is not None and "time budget of 0.3 s" in result.failure


@pytest.mark.slow
@pytest.mark.long
def test_cli_failed_generate_writes_the_record_and_names_the_folder(
    fake_openai: Callable[..., FakeOpenAI], tmp_path: Path
) -> None:
    server = fake_openai(f"no program here ({SECRET_KEY} is not echoed)", repeat_last=True)
    out = tmp_path / "scene"
    exe = Path(sys.executable).with_name("physcensis")
    args = [str(exe), "generate", "a mug", "--llm", "fake-model", "--base-url", server.base_url, "--out", str(out)]
    done = subprocess.run(
        [*args, "--hint", "off", "--time-budget", "30"], capture_output=True, text=True, timeout=120, check=False
    )
    assert done.returncode == 1, done.stderr
    last = done.stderr.strip().splitlines()[-1]
    assert last.startswith("error: no scene could be generated (no program solved in") and str(out) in last
    assert (out / "transcript.jsonl").exists() and not (out / "scene.json").exists()
    report = (out / "report.json").read_text()
    assert json.loads(report)["ok"] is False
    assert SECRET_KEY not in report + (out / "transcript.jsonl").read_text() + done.stderr + done.stdout
