"""The offline planner reads prompts it has never seen and writes checked, solvable programs."""

from __future__ import annotations

import json

import pytest

from physcensis.agent.base import AgentContext, Round
from physcensis.agent.planner import OfflinePlanner
from physcensis.agent.reading import Lexicon, read_prompt
from physcensis.assets import default_catalogue
from physcensis.program import check_program, parse_program
from physcensis.scene import Support

TABLE = Support(kind="table", size=(1.0, 0.8))


@pytest.fixture(scope="module")
def lexicon() -> Lexicon:
    return Lexicon(default_catalogue())


def test_counts_and_nouns(lexicon: Lexicon) -> None:
    request = read_prompt("two mugs, 5 pencils, a pair of chopsticks, a few jars and three wine glasses", lexicon)
    counts = {m.category: m.count for m in request.mentions}
    assert counts == {"mug": 2, "pencil": 5, "chopsticks": 2, "jar": 3, "wine glass": 3}


def test_relations(lexicon: Lexicon) -> None:
    request = read_prompt("a basket full of apples and a notebook with a pen on it next to a lamp-free mug",
                          lexicon)
    by = {m.category: m for m in request.mentions}
    basket = request.mentions.index(by["basket"])
    assert request.mentions.index(by["apple"]) in by["basket"].contents
    assert by["pen"].on == request.mentions.index(by["notebook"])
    assert basket == 0
    stack = read_prompt("a stack of plates", lexicon)
    assert stack.mentions[0].stacked and stack.mentions[0].count == 4
    assert read_prompt("a dinner for six people", lexicon).diners == 6
    assert read_prompt("a cup balanced precariously on a book", lexicon).fragile


@pytest.mark.parametrize("prompt", [
    "a nightstand with a lamp-like vase, a phone and two books",
    "a sewing table with a basket of balls of yarn and scissors",
    "a tray with a teapot and two teacups on saucers",
    "three potted plants in a row",
    "a toddler's table with toy blocks stacked into a tower and a toy truck",
])
def test_unseen_prompts_give_clean_programs(prompt: str) -> None:
    text = OfflinePlanner().propose(AgentContext(prompt, TABLE, ()))
    program = parse_program(text)
    report = check_program(program, TABLE)
    assert report.ok, report.feedback()
    assert program.declarations


def test_unknown_noun_still_becomes_an_object() -> None:
    text = OfflinePlanner().propose(AgentContext("a table with three gizmos and a mug", TABLE, ()))
    program = json.loads(text)
    assert any(e[0].startswith("mug") for e in program)


def test_repair_frees_then_drops_what_failed() -> None:
    planner = OfflinePlanner()
    first = planner.propose(AgentContext("a cup on a book and a vase", TABLE, ()))
    program = json.loads(first)
    cup = next(e[0] for e in program if len(e) == 4 and e[1] == "PLACE-ON")
    history = (Round(first, f"- {cup} (PLACE-ON): no supported spot", False),)
    repaired = json.loads(planner.propose(AgentContext("a cup on a book and a vase", TABLE, (), history, "repair",
                                                         {"failed": cup, "freed": ""})))
    assert [cup, "PLACE-ANYWHERE", "root", {"stack": False}] in repaired
    assert check_program(parse_program(repaired), TABLE).ok
    history2 = (*history, Round(json.dumps(repaired), "failed again", False))
    dropped = json.loads(planner.propose(AgentContext("a cup on a book and a vase", TABLE, (), history2, "repair",
                                                        {"failed": cup, "freed": cup})))
    assert all(e[0] != cup for e in dropped)


def test_enrichment_adds_objects_to_the_same_program() -> None:
    planner = OfflinePlanner()
    first = planner.propose(AgentContext("an office desk with a laptop", TABLE, ()))
    history = (Round(first, "all placed", True),)
    more = json.loads(planner.propose(AgentContext("an office desk with a laptop", TABLE, (), history, "enrich")))
    assert len(more) > len(json.loads(first))
    assert check_program(parse_program(more), TABLE).ok
