"""A batch driver parses each prompt once and hands the parse to its workers with the tasks, so a worker never loads
spaCy for it."""

from __future__ import annotations

from typing import Any

import pytest

import physcensis.agent.parse as parse_module
from physcensis.agent.parse import NounPhrase, Parse, parse, remember
from physcensis.batch.prompts import Task
from physcensis.batch.worker import Options, Outcome, Parses, run_task

PROMPT = "a mug next to a book"
MUG = NounPhrase(0, "a mug", "mug", (), None, "one", 0, 5)
GIVEN = Parse(PROMPT, (MUG,), ())


@pytest.fixture(autouse=True)
def nothing_given(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(parse_module, "_given", {})


def test_a_given_parse_answers_for_its_text_only(monkeypatch: pytest.MonkeyPatch) -> None:
    def no_spacy() -> Any:
        raise AssertionError("spaCy was loaded")

    monkeypatch.setattr(parse_module, "_pipeline", no_spacy)
    remember(GIVEN)
    assert parse(PROMPT) is GIVEN
    with pytest.raises(AssertionError, match="spaCy was loaded"):
        parse("a different prompt")


def test_a_worker_task_uses_the_parse_it_was_handed() -> None:
    task = Task(key="k", prompt_id="p", prompt=PROMPT, support="table:0.6x0.5", seed=0)

    def maker(task: Task, options: Options) -> Outcome:
        return Outcome(task, {"same": parse(task.prompt) is GIVEN})

    assert run_task(task, Options(), maker, parsed=GIVEN).record == {"same": True}


def test_the_driver_parses_each_prompt_once_and_a_prompt_it_cannot_parse_goes_without(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    calls: list[str] = []

    def counted(text: str) -> Parse:
        calls.append(text)
        if text == "bad":
            raise ValueError("cannot parse")
        return Parse(text, (), ())

    monkeypatch.setattr(parse_module, "parse", counted)
    parses = Parses()
    first = parses.of(PROMPT)
    assert first is not None and first.text == PROMPT and parses.of(PROMPT) is first
    assert parses.of("bad") is None and parses.of("bad") is None
    assert calls == [PROMPT, "bad"]
