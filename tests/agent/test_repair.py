"""The planner's repair: whatever fails, the repaired program passes the checker and keeps everything that did not
depend on what failed."""

from __future__ import annotations

import json
import random
from typing import Any

import pytest

from physcensis.agent.base import AgentContext, Round
from physcensis.agent.planner import OfflinePlanner
from physcensis.agent.repair import repair_program
from physcensis.assets import default_catalogue
from physcensis.bench.prompt_suite import load_suite
from physcensis.program import check_program, parse_program
from physcensis.scene import Support

Entry = list[Any]
TABLE = Support(kind="table", size=(1.0, 0.8))
DINING = "a dining table set up for four people"
OWN_PROMPTS = [
    ("an office desk with a monitor, a keyboard, a mouse, a mug and a stack of three books", "table:0.8x1.4"),
    ("a vase in the middle with four cups around it", "table:1.0x1.0"),
    ("a tray with a teapot and two teacups on saucers", "table:0.8x0.8"),
    ("a bowl of apples next to a cutting board with a knife on it", "table:0.8x1.2"),
    ("three cups stacked inside one another beside a jar", "table:0.6x0.6"),
    ("sandwiches on plates and cups on saucers for a picnic", "table:1.0x1.0"),
    ("a bookshelf with books standing upright and a potted plant", "shelf:0.35x1.0"),
    ("a messy desk crammed with as many things as possible", "table:0.8x1.2"),
    ("a toothbrush in a cup and a spoon across its rim", "table:0.5x0.5"),
    ("a dinner for six people with a candle in the middle", "table:1.0x1.8"),
    ("a pen holder with six pens inside, a notebook with a pen on it and a lamp-free mug", "table:0.7x1.0"),
]
PAIRS_PER_PROGRAM = 12


def _cases() -> list[tuple[str, str, Support]]:
    suite = [
        (c["id"], c["prompt"], Support(kind=c["support"]["kind"], size=tuple(c["support"]["size"])))
        for c in load_suite()
    ]
    own = [(prompt[:30], prompt, Support.parse(support)) for prompt, support in OWN_PROMPTS]
    return suite + own


CASES = _cases()


@pytest.fixture(scope="module")
def planner() -> OfflinePlanner:
    return OfflinePlanner(default_catalogue())


# ---- an oracle of what depends on what, read from the JSON alone ----------------------------------------------------


def _strings(value: Any) -> set[str]:
    if isinstance(value, str):
        return {value}
    if isinstance(value, list):
        return set().union(*(_strings(v) for v in value)) if value else set()
    if isinstance(value, dict):
        return set().union(*(_strings(v) for v in value.values())) if value else set()
    return set()


def _subjects(entry: Entry) -> set[str]:
    return {entry[0]} if isinstance(entry[0], str) else {s for s in entry[0] if isinstance(s, str)}


def may_go(program: list[Entry], failed: set[str]) -> set[str]:
    """The failed ids and, transitively, every object or group with an entry naming one anywhere in its target or
    parameters; a GROUP once all its members are gone; the copies of gone members and of gone groups."""
    gone = set(failed)
    members: dict[str, list[str]] = {}
    for e in program:
        if len(e) == 4 and e[1] == "GROUP":
            members[e[0]] = list(e[2])
        elif len(e) == 4 and e[1] == "COPY-GROUP":
            members[e[0]] = [f"{m}-{e[0]}" for m in members[e[2]]]
    size = -1
    while size != len(gone):
        size = len(gone)
        for e in program:
            if len(e) == 4 and e[1] == "GROUP":
                if set(e[2]) <= gone:
                    gone.add(e[0])
            elif len(e) == 4 and (_strings(e[2:]) - {"root"}) & gone:
                gone |= _subjects(e)
            if len(e) == 4 and e[1] == "COPY-GROUP":
                source = members[e[2]]
                gone |= {f"{m}-{e[0]}" for m in source if m in gone or e[0] in gone}
    return gone


def _declared(program: list[Entry]) -> set[str]:
    return {e[0] for e in program if len(e) == 2}


def _groups(program: list[Entry]) -> set[str]:
    return {e[0] for e in program if len(e) == 4 and e[1] in ("GROUP", "COPY-GROUP")}


def _referenced(program: list[Entry]) -> set[str]:
    return set().union(*(_strings(e[2:]) for e in program if len(e) == 4))


def _assert_repaired(
    program: list[Entry], repaired: list[Entry], failed: set[str], support: Support, freed: frozenset[str] = frozenset()
) -> None:
    """Exactly what depends on the failed objects that were not `freed` is gone, and the rest passes the checker
    (nothing at all may be left)."""
    gone = may_go(program, failed - freed)
    assert _declared(repaired) == _declared(program) - gone, f"failed {sorted(failed)}"
    assert _groups(repaired) == _groups(program) - gone, f"failed {sorted(failed)}"
    if not _declared(repaired):
        assert repaired == [], "an empty program keeps no entries"
        return
    report = check_program(parse_program(repaired), support)
    assert report.ok, f"failed {sorted(failed)}:\n{report.feedback()}\n{json.dumps(repaired)}"


# ---- the reported case -----------------------------------------------------------------------------------------------


def _dining(planner: OfflinePlanner) -> list[Entry]:
    return planner.plan(AgentContext(DINING, TABLE, ()))


@pytest.mark.parametrize("failed", ["fork_0", "knife_0", "cup_0"])
def test_a_dropped_setting_item_takes_what_is_placed_by_it_and_the_group_keeps_the_rest(
    planner: OfflinePlanner, failed: str
) -> None:
    program = _dining(planner)
    repaired = repair_program(program, {failed}, set())
    report = check_program(parse_program(repaired), TABLE)
    assert report.ok, report.feedback()
    expected_gone = {
        "fork_0": {"fork_0", "knife_0", "cup_0"},  # the knife mirrors the fork, the cup lines up with the knife
        "knife_0": {"knife_0", "cup_0"},
        "cup_0": {"cup_0"},
    }[failed]
    members = next(e[2] for e in repaired if e[1:2] == ["GROUP"])
    assert members == [m for m in ["plate_0", "fork_0", "knife_0", "cup_0"] if m not in expected_gone]
    assert _declared(repaired) == _declared(program) - expected_gone
    assert sum(e[1] == "COPY-GROUP" for e in repaired if len(e) == 4) == 3  # every diner keeps a setting


def test_when_everything_depends_on_what_failed_nothing_is_left(planner: OfflinePlanner) -> None:
    assert repair_program(_dining(planner), {"plate_0"}, set()) == []


def test_a_group_that_loses_its_anchor_takes_its_first_member_as_anchor() -> None:
    program: list[Entry] = [
        ["a_0", "a plate"],
        ["a_0", "PLACE-ON-BASE", "root", {"x": 0.1, "y": 0.1}],
        ["a_0", "FACING-FRONT", "root", {}],
        ["b_0", "a fork"],
        ["b_0", "PLACE-ON-BASE", "root", {"x": 0.1, "y": -0.1}],
        ["b_0", "FACING-FRONT", "root", {}],
        ["group_a", "GROUP", ["a_0", "b_0"], {"anchor": "a_0"}],
        ["group_b", "COPY-GROUP", "group_a", {}],
        ["group_b", "PLACE-ON-BASE", "root", {"x": -0.2, "y": 0.0}],
    ]
    repaired = repair_program(program, {"a_0"}, {"a_0"})
    assert ["group_a", "GROUP", ["b_0"], {}] in repaired
    assert ["group_b", "COPY-GROUP", "group_a", {}] in repaired
    assert check_program(parse_program(repaired), TABLE).ok


def test_references_are_read_from_the_registry_not_from_predicate_names() -> None:
    """A parameter reference (SYMMETRY-ALONG's C), a copy of a copy, a group turned towards an object, a PLACE-IN
    with a count: each goes with what it refers to."""
    program: list[Entry] = [
        ["plate_0", "a plate"],
        ["plate_0", "PLACE-ON-BASE", "root", {"x": 0.2, "y": 0.0}],
        ["plate_0", "FACING-FRONT", "root", {}],
        ["fork_0", "a fork"],
        ["fork_0", "PLACE-ON-BASE", "root", {"x": 0.2, "y": 0.15}],
        ["fork_0", "FACING-FRONT", "root", {}],
        ["knife_0", "a knife"],
        ["knife_0", "PLACE-ON-BASE", "root", {}],
        ["knife_0", "SYMMETRY-ALONG", "fork_0", {"C": "plate_0"}],
        ["knife_0", "FACING-FRONT", "root", {}],
        ["vase_0", "a vase"],
        ["vase_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
        ["vase_0", "FACING-FRONT", "root", {}],
        ["group_a", "GROUP", ["plate_0", "fork_0", "knife_0"], {"anchor": "plate_0"}],
        ["group_b", "COPY-GROUP", "group_a", {}],
        ["group_b", "PLACE-ON-BASE", "root", {"x": -0.2, "y": 0.0}],
        ["group_b", "FACING-TO", "vase_0", {}],
        ["group_c", "COPY-GROUP", "group_b", {}],
        ["group_c", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.25}],
        ["bowl_0", "a bowl"],
        ["bowl_0", "PLACE-ON-BASE", "root", {"x": -0.3, "y": 0.3}],
        ["bowl_0", "FACING-FRONT", "root", {}],
        [["apple_0", ["orange", 2]], "PLACE-IN", "bowl_0", {}],
        ["apple_0", "an apple"],
    ]
    program = [*program[:-2], program[-1], program[-2]]  # the apple is declared before it is dropped in
    assert check_program(parse_program(program), TABLE).ok
    no_plate = repair_program(program, {"plate_0"}, {"plate_0"})  # the knife mirrors through the plate
    assert _declared(no_plate) == {"fork_0", "vase_0", "bowl_0", "apple_0"}
    assert ["group_a", "GROUP", ["fork_0"], {}] in no_plate
    no_vase = repair_program(program, {"vase_0"}, {"vase_0"})  # group_b turns to the vase: it and its copy go
    assert _groups(no_vase) == {"group_a"} and "plate_0" in _declared(no_vase)
    no_bowl = repair_program(program, {"bowl_0"}, {"bowl_0"})  # what is inside goes with it, counts too
    assert not any(e[1] == "PLACE-IN" for e in no_bowl) and "apple_0" not in _declared(no_bowl)
    for repaired, failed in ((no_plate, "plate_0"), (no_vase, "vase_0"), (no_bowl, "bowl_0")):
        _assert_repaired(program, repaired, {failed}, TABLE)


def test_an_item_that_failed_leaves_the_container_and_is_freed() -> None:
    program: list[Entry] = [
        ["bowl_0", "a bowl"],
        ["bowl_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
        ["bowl_0", "FACING-FRONT", "root", {}],
        ["apple_0", "an apple"],
        ["apple_1", "an apple"],
        [["apple_0", "apple_1"], "PLACE-IN", "bowl_0", {}],
    ]
    repaired = repair_program(program, {"apple_1"}, set())
    assert repaired[-3:] == [
        [["apple_0"], "PLACE-IN", "bowl_0", {}],
        ["apple_1", "an apple"],
        ["apple_1", "PLACE-ANYWHERE", "root", {"stack": False}],
    ]
    assert check_program(parse_program(repaired), TABLE).ok


# ---- the property: every planner program, every object failing, and random pairs -------------------------------------


@pytest.mark.parametrize(("name", "prompt", "support"), CASES, ids=[c[0] for c in CASES])
def test_any_failure_leaves_a_checked_program_keeping_what_did_not_depend_on_it(
    planner: OfflinePlanner, name: str, prompt: str, support: Support
) -> None:
    program = planner.plan(AgentContext(prompt, support, ()))
    assert check_program(parse_program(program), support).ok
    objects = sorted(_declared(program))
    rng = random.Random(name)
    pairs = [set(rng.sample(objects, 2)) for _ in range(PAIRS_PER_PROGRAM)] if len(objects) > 1 else []
    for failed in [{oid} for oid in objects] + pairs:
        _assert_repaired(program, repair_program(program, failed, tried_free=failed), failed, support)
        first_try = repair_program(program, failed, tried_free=set())  # what nothing refers to is freed instead
        freeable = failed - _referenced(program)
        freed = frozenset(freeable - may_go(program, failed - freeable))  # unless it rests on a dropped one
        assert all([oid, "PLACE-ANYWHERE", "root", {"stack": False}] in first_try for oid in freed)
        _assert_repaired(program, first_try, failed, support, freed)


def test_an_enriched_program_repairs_the_same_way(planner: OfflinePlanner) -> None:
    first = json.dumps(_dining(planner))
    enriched = planner.enrich(json.loads(first), AgentContext(DINING, TABLE, (), (Round(first, "ok", True),), "enrich"))
    for oid in sorted(_declared(enriched)):
        _assert_repaired(enriched, repair_program(enriched, {oid}, {oid}), {oid}, TABLE)
