"""The offline reading as a small model's draft: every object the planner's program makes is listed once, with what
it rests on or in; the compact prompt's requests carry it under `auto`, the full prompt's do not, and `off`/`on`
override that."""

from __future__ import annotations

import json
import re
from collections.abc import Callable

import pytest

from physcensis.agent.base import AgentContext
from physcensis.agent.hint import draft_objects, reading_hint
from physcensis.agent.llm import LLMAgent
from physcensis.agent.planner import OfflinePlanner
from physcensis.program import parse_program
from physcensis.scene import Support

from .fake_server import MUG_AND_BOOK, FakeOpenAI

pytestmark = pytest.mark.timeout(30)

TABLE = Support(kind="table", size=(1.2, 0.8))


def _context(prompt: str) -> AgentContext:
    return AgentContext(prompt=prompt, support=TABLE, vocabulary=())


def test_group_copies_and_counted_contents_become_one_line_per_object() -> None:
    program = parse_program(
        json.dumps(
            [
                ["plate_0", "a dinner plate"],
                ["plate_0", "PLACE-ON-BASE", "root", {"x": 0.3, "y": 0.0}],
                ["cup_0", "a cup"],
                ["cup_0", "PLACE-ON", "plate_0", {}],
                ["group_s_0", "GROUP", ["plate_0", "cup_0"], {"anchor": "plate_0"}],
                ["group_s_1", "COPY-GROUP", "group_s_0", {}],
                ["group_s_1", "PLACE-ON-BASE", "root", {"x": -0.3, "y": 0.0}],
                ["bowl_0", "a fruit bowl"],
                ["bowl_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.2}],
                [[["apple", 2]], "PLACE-IN", "bowl_0", {}],
            ]
        )
    )
    drafted = [(d.object_id, d.description, d.rests) for d in draft_objects(program)]
    assert drafted == [
        ("plate_0", "a dinner plate", ""),
        ("cup_0", "a cup", "on plate_0"),
        ("bowl_0", "a fruit bowl", ""),
        ("plate_1", "a dinner plate", ""),
        ("cup_1", "a cup", "on plate_1"),  # the copy's cup rests on the copy's plate
        ("apple_0", "apple", "in bowl_0"),
        ("apple_1", "apple", "in bowl_0"),
    ]


@pytest.mark.parametrize(
    ("prompt", "counts"),
    [
        ("a dining table set up for four people", {"plate": 4, "fork": 4, "knife": 4}),
        ("a stack of 5 books", {"book": 5}),
        ("three apples in a bowl next to a mug", {"apple": 3, "bowl": 1, "mug": 1}),
    ],
)
def test_the_draft_lists_as_many_objects_as_the_planner_makes(prompt: str, counts: dict[str, int]) -> None:
    context = _context(prompt)
    drafted = draft_objects(parse_program(OfflinePlanner(variety="none").propose(context)))  # the draft is canonical
    ids = [d.object_id for d in drafted]
    assert len(ids) == len(set(ids))
    for category, n in counts.items():
        assert sum(1 for i in ids if i.rsplit("_", 1)[0] == category) == n
    hint = reading_hint(context)
    assert hint.objects == len(ids) and all(f"- {i}:" in hint.text for i in ids)


def test_a_stack_and_contents_say_what_each_object_rests_on_or_in() -> None:
    text = reading_hint(_context("a stack of 3 books and two apples in a bowl")).text
    assert "book_1: " in text and "(on book_0)" in text and "(on book_1)" in text
    assert text.count("(in bowl_0)") == 2


def _first_user_turn(server: FakeOpenAI, i: int = 0) -> str:
    return str(server.messages[i][1]["content"])


@pytest.mark.parametrize(
    ("prompt_style", "hint", "sent"),
    [("compact", "auto", True), ("full", "auto", False), ("compact", "off", False), ("full", "on", True)],
)
def test_auto_gives_the_draft_with_the_compact_prompt_and_on_and_off_override_it(
    fake_openai: Callable[..., FakeOpenAI], prompt_style: str, hint: str, sent: bool
) -> None:
    server = fake_openai(MUG_AND_BOOK)
    agent = LLMAgent("m", base_url=server.base_url, max_retries=0, prompt=prompt_style, hint=hint, structured="off")
    agent.propose(_context("a stack of 5 books"))
    text = _first_user_turn(server)
    assert ("book_4: " in text) is sent
    assert text.rstrip().endswith('"a stack of 5 books". Write the program for it.')  # the request stays last


def test_an_unknown_hint_mode_is_refused_with_the_choices() -> None:
    from physcensis.agent.base import AgentError

    with pytest.raises(AgentError, match="auto, on, off"):
        LLMAgent("m", base_url="http://127.0.0.1:9/v1", hint="maybe")


def test_standing_objects_carry_their_spot_in_the_solved_draft_copies_included() -> None:
    """A place setting's copies stand where the solved draft puts them: four plates at four different seats, each
    inside the table."""
    hint = reading_hint(_context("a dining table set up for four people"))
    spots = re.findall(r"- plate_\d: .*\(stands at x (-?\d+\.\d+), y (-?\d+\.\d+)\)", hint.text)
    assert len(spots) == 4 and len(set(spots)) == 4
    for x, y in spots:
        assert abs(float(x)) <= 0.6 and abs(float(y)) <= 0.4


def test_a_prompt_the_reader_finds_nothing_in_gives_no_draft() -> None:
    """The planner would write its default scene, which is no reading of the prompt: the model gets no draft and
    no count to meet."""
    assert reading_hint(_context("make it feel lived in")).objects == 0
    assert reading_hint(_context("make it feel lived in")).text == ""


def test_a_planner_that_fails_leaves_the_model_without_a_draft_not_without_a_run(
    fake_openai: Callable[..., FakeOpenAI], monkeypatch: pytest.MonkeyPatch
) -> None:
    def broken(self: OfflinePlanner, context: AgentContext) -> str:
        raise RuntimeError("a planner bug")

    monkeypatch.setattr(OfflinePlanner, "propose", broken)
    prompt = "a stack of 7 books beside a lamp"  # drafts are kept per request: one no other test asks for
    assert reading_hint(_context(prompt)).objects == 0
    server = fake_openai(MUG_AND_BOOK)
    agent = LLMAgent("m", base_url=server.base_url, max_retries=0, prompt="compact", hint="on", structured="off")
    agent.propose(_context(prompt))
    assert "rule-based reading" not in _first_user_turn(server)


def test_making_the_draft_counts_against_the_replys_time_limit(
    fake_openai: Callable[..., FakeOpenAI], monkeypatch: pytest.MonkeyPatch
) -> None:
    """A reply's wall-clock limit covers the draft made for it: after a 0.6 s draft, a server answering in 1.7 s
    misses a 2 s limit (it would make it if the draft were free)."""
    import time

    from physcensis.agent import hint as hint_module
    from physcensis.llm.client import LLMRequestError

    from .fake_server import Reply

    def slow(context: AgentContext, catalogue: object, planner: object) -> hint_module.Hint:
        time.sleep(0.6)
        return hint_module.Hint("A rule-based reading: - book_0: a book", 1)

    monkeypatch.setattr(hint_module, "_reading_hint", slow)
    server = fake_openai(Reply(content=MUG_AND_BOOK, delay_s=1.7))
    agent = LLMAgent("m", base_url=server.base_url, max_retries=0, prompt="compact", structured="off", timeout_s=2.0)
    with pytest.raises(LLMRequestError, match="no complete answer"):
        agent.propose(_context("a lone book on a slow day"))
