"""The planner's repair: whatever fails, the repaired program passes the checker; a failed holder is moved, not
dropped, with what rests on it; an object too large for its place takes a smaller variant; an object is dropped
only when it failed again, already placed anywhere, with no smaller variant; and something always stays."""

from __future__ import annotations

import json
import random
from typing import Any

import pytest

from physcensis.agent.base import AgentContext, Round
from physcensis.agent.loop import generate_scene
from physcensis.agent.planner import OfflinePlanner
from physcensis.agent.repair import EDGE_MARGIN_M, failure_reasons, repair_program, smallest_scene, waited_only
from physcensis.assets import default_catalogue
from physcensis.assets.catalogue import Catalogue
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


# ---- reading programs as JSON alone ----------------------------------------------------------------------------------

RESTING = ("PLACE-ON", "PLACE-IN")


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


def _declared(program: list[Entry]) -> set[str]:
    return {e[0] for e in program if len(e) == 2}


def _description(program: list[Entry], oid: str) -> str:
    return next(e[1] for e in program if len(e) == 2 and e[0] == oid)


def _groups(program: list[Entry]) -> set[str]:
    return {e[0] for e in program if len(e) == 4 and e[1] in ("GROUP", "COPY-GROUP")}


def _referenced(program: list[Entry]) -> set[str]:
    return set().union(*(_strings(e[2:]) for e in program if len(e) == 4))


def _own_failures(program: list[Entry], failed: set[str]) -> set[str]:
    """The failed declared objects that name no other failed declared object in their entries."""
    declared = _declared(program)
    waiting = {s for e in program if len(e) == 4 and _strings(e[2:]) & failed & declared for s in _subjects(e)}
    return (failed & declared) - waiting


def _anywhere(oid: str) -> Entry:
    return [oid, "PLACE-ANYWHERE", "root", {"stack": False, "pack": True}]


def _placed_anywhere(program: list[Entry], oid: str) -> bool:
    return any(len(e) == 4 and e[0] == oid and e[1] == "PLACE-ANYWHERE" for e in program)


def _assert_rests_after_holder(program: list[Entry], repaired: list[Entry], failed: set[str]) -> None:
    """Whatever rested on or in a failed object that is still there, and did not fail itself, still does, after the
    holder's own entries."""
    for entry in program:
        if len(entry) != 4 or entry[1] not in RESTING or entry[2] not in failed & _declared(repaired):
            continue
        if _subjects(entry) & failed:
            continue
        assert entry in repaired, f"{entry} lost its holder"
        holder_last = max(i for i, e in enumerate(repaired) if e[0] == entry[2])
        assert repaired.index(entry) > holder_last, f"{entry} comes before {entry[2]}"


def _assert_checked(repaired: list[Entry], support: Support, failed: set[str]) -> None:
    report = check_program(parse_program(repaired), support)
    assert report.ok, f"failed {sorted(failed)}:\n{report.feedback()}\n{json.dumps(repaired)}"


def _assert_first_repair(program: list[Entry], repaired: list[Entry], failed: set[str], support: Support) -> None:
    """A first failure drops no object: each that failed on its own is placed anywhere, what rests on it stays on
    it, and the program passes the checker."""
    assert _declared(repaired) == _declared(program), f"failed {sorted(failed)}"
    for oid in _own_failures(program, failed):
        assert _placed_anywhere(repaired, oid), f"{oid} is not placed anywhere"
    _assert_rests_after_holder(program, repaired, failed)
    _assert_checked(repaired, support, failed)


def _assert_second_repair(program: list[Entry], repaired: list[Entry], failed: set[str], support: Support) -> None:
    """A second failure (no smaller variant known) drops only failed objects that were already placed anywhere;
    nothing else is lost, something always stays, and the program passes the checker."""
    assert _declared(repaired), f"failed {sorted(failed)}: nothing left"
    if _declared(program) - failed:
        own = _own_failures(program, failed)
        may_drop = {oid for oid in own if _placed_anywhere(program, oid)}
        assert _declared(program) - may_drop <= _declared(repaired), f"failed {sorted(failed)}"
    _assert_checked(repaired, support, failed)


# ---- settings and groups ---------------------------------------------------------------------------------------------


def _dining(planner: OfflinePlanner) -> list[Entry]:
    return planner.plan(AgentContext(DINING, TABLE, ()))


@pytest.mark.parametrize("failed", ["fork_0", "knife_0", "cup_0"])
def test_a_freed_setting_item_takes_what_is_placed_by_it_along_and_the_group_keeps_the_rest(
    planner: OfflinePlanner, failed: str
) -> None:
    program = _dining(planner)
    repaired = repair_program(program, {failed}, set())
    _assert_checked(repaired, TABLE, {failed})
    expected_freed = {
        "fork_0": {"fork_0", "knife_0", "cup_0"},  # the knife mirrors the fork, the cup lines up with the knife
        "knife_0": {"knife_0", "cup_0"},
        "cup_0": {"cup_0"},
    }[failed]
    members = next(e[2] for e in repaired if e[1:2] == ["GROUP"])
    assert members == [m for m in ["plate_0", "fork_0", "knife_0", "cup_0"] if m not in expected_freed]
    assert _declared(repaired) == _declared(program)  # moved, not dropped
    assert all(_anywhere(oid) in repaired for oid in expected_freed)
    assert sum(e[1] == "COPY-GROUP" for e in repaired if len(e) == 4) == 3  # every diner keeps a setting


def test_when_everything_depends_on_what_failed_again_something_is_left(planner: OfflinePlanner) -> None:
    program = _dining(planner)
    repaired = repair_program(program, {"plate_0"}, {"plate_0"})
    assert _declared(repaired) == _declared(program)  # the plate and what was placed by it stand anywhere
    _assert_checked(repaired, TABLE, {"plate_0"})


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
    assert _anywhere("a_0") in repaired
    _assert_checked(repaired, TABLE, {"a_0"})


REFERENCES: list[Entry] = [
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
    ["apple_0", "an apple"],
    [["apple_0", ["orange", 2]], "PLACE-IN", "bowl_0", {}],
]


def test_references_are_read_from_the_registry_not_from_predicate_names() -> None:
    """A parameter reference (SYMMETRY-ALONG's C), a copy of a copy, a group turned towards an object, a PLACE-IN
    with a count: each follows what it refers to."""
    assert check_program(parse_program(REFERENCES), TABLE).ok
    no_plate = repair_program(REFERENCES, {"plate_0"}, set())  # the knife mirrors through the plate: freed too
    assert _anywhere("plate_0") in no_plate and _anywhere("knife_0") in no_plate
    assert ["group_a", "GROUP", ["fork_0"], {}] in no_plate
    no_vase = repair_program(REFERENCES, {"vase_0"}, set())  # group_b turns to the vase: it and its copy go
    assert _groups(no_vase) == {"group_a"} and _anywhere("vase_0") in no_vase
    no_bowl = repair_program(REFERENCES, {"bowl_0"}, set())  # what is inside stays inside, counts too
    assert no_bowl[-3:] == [_anywhere("bowl_0"), ["apple_0", "an apple"], REFERENCES[-1]]
    for repaired, failed in ((no_plate, "plate_0"), (no_vase, "vase_0"), (no_bowl, "bowl_0")):
        _assert_first_repair(REFERENCES, repaired, {failed}, TABLE)


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
        _anywhere("apple_1"),
    ]
    _assert_checked(repaired, TABLE, {"apple_1"})


# ---- holders: moved, with what rests on them -------------------------------------------------------------------------

FELL = "fell during settling at each of the 6 best supported spots"
HOLDERS = [  # holder description, how things go on it, item description
    ("a rectangular wooden serving tray", "PLACE-ON", "a classic white ceramic coffee mug"),
    ("a small white tea tray", "PLACE-ON", "a small glass jar of strawberry jam with a gold lid"),
    ("a slatted wooden fruit crate", "PLACE-IN", "a shiny red apple"),
    ("a wide shallow wooden fruit bowl", "PLACE-IN", "an orange"),
    ("an open brown cardboard box", "PLACE-IN", "a red aluminium soda can"),
    ("a large open cardboard moving box", "PLACE-ON", "a thick red hardcover book lying flat"),
]


def _holder_program(holder: str, how: str, item: str, placement: Entry) -> list[Entry]:
    items = [f"item_{k}" for k in range(3)]
    entries: list[Entry] = [["holder_0", holder], ["holder_0", *placement]]
    if placement[0] == "PLACE-ON-BASE":
        entries.append(["holder_0", "FACING-FRONT", "root", {}])
    entries.append(["lamp_0", "a desk lamp"])
    entries += [["lamp_0", "PLACE-ON-BASE", "root", {"x": 0.3, "y": 0.3}], ["lamp_0", "FACING-FRONT", "root", {}]]
    entries += [[oid, item] for oid in items]
    if how == "PLACE-IN":
        return [*entries, [items, "PLACE-IN", "holder_0", {}]]
    return entries + [[oid, "PLACE-ON", "holder_0", {}] for oid in items]


ON_BASE: Entry = ["PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}]


@pytest.mark.parametrize(("holder", "how", "item"), HOLDERS)
def test_a_failed_holder_is_placed_anywhere_and_what_it_carries_stays_on_it_after_it(
    holder: str, how: str, item: str
) -> None:
    program = _holder_program(holder, how, item, ON_BASE)
    items = {"item_0", "item_1", "item_2"}
    failed = {"holder_0"} | items  # the items failed because their holder was not there
    reasons = {"holder_0": FELL} | dict.fromkeys(items, "holder_0 is not in the scene (it failed or was never placed)")
    repaired = repair_program(program, failed, set(), reasons=reasons, catalogue=default_catalogue())
    assert _declared(repaired) == _declared(program)
    at = repaired.index(_anywhere("holder_0"))
    carried = [e for e in repaired if len(e) == 4 and e[1] == how]
    assert carried and all(e[2] == "holder_0" and repaired.index(e) > at for e in carried)
    assert _subjects(carried[0]) | set().union(*(_subjects(e) for e in carried)) == items
    assert ["lamp_0", "PLACE-ON-BASE", "root", {"x": 0.3, "y": 0.3}] in repaired  # what worked is untouched
    _assert_rests_after_holder(program, repaired, failed)
    _assert_checked(repaired, TABLE, failed)


@pytest.mark.parametrize(("holder", "how", "item"), HOLDERS)
def test_a_holder_sticking_out_past_one_edge_is_pulled_in_and_keeps_its_load(holder: str, how: str, item: str) -> None:
    program = _holder_program(holder, how, item, ["PLACE-ON-BASE", "root", {"x": 0.3, "y": -0.2}])
    reasons = {"holder_0": "sticks out 4.0 cm past the front edge; sticks out 1.5 cm past the right edge"}
    repaired = repair_program(program, {"holder_0"}, set(), reasons=reasons, support=TABLE)
    x, y = 0.3 - 0.04 - EDGE_MARGIN_M, -0.2 + 0.015 + EDGE_MARGIN_M
    assert ["holder_0", "PLACE-ON-BASE", "root", {"x": round(x, 3), "y": round(y, 3)}] in repaired
    assert [e for e in repaired if e[0] != "holder_0"] == [e for e in program if e[0] != "holder_0"]
    _assert_checked(repaired, TABLE, {"holder_0"})


@pytest.mark.parametrize(("holder", "how", "item"), HOLDERS)
def test_a_holder_that_fails_again_without_a_smaller_variant_is_dropped_and_its_load_freed(
    holder: str, how: str, item: str
) -> None:
    program = _holder_program(holder, how, item, ["PLACE-ANYWHERE", "root", {}])
    repaired = repair_program(program, {"holder_0"}, {"holder_0"}, reasons={"holder_0": FELL})  # no catalogue
    assert _declared(repaired) == _declared(program) - {"holder_0"}
    assert all(_anywhere(f"item_{k}") in repaired for k in range(3))
    _assert_checked(repaired, TABLE, {"holder_0"})


def test_a_stack_keeps_its_order_when_its_base_is_moved() -> None:
    books = [f"book_{k}" for k in range(4)]
    program: list[Entry] = [["book_0", "a thick red hardcover book lying flat"]]
    program += [["book_0", "PLACE-ON-BASE", "root", {}], ["book_0", "RIGHT-OF", "lamp_0", {"distance": 0.05}]]
    program += [["book_0", "ALIGN-CENTER-FB", "lamp_0", {}], ["book_0", "FACING-FRONT", "root", {}]]
    for below, above in zip(books, books[1:], strict=False):
        program += [[above, "a thick red hardcover book lying flat"], [above, "PLACE-ON", below, {}]]
    program = [["lamp_0", "a desk lamp"], ["lamp_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}], *program]
    program.insert(2, ["lamp_0", "FACING-FRONT", "root", {}])
    failed = set(books)
    reasons = {"book_0": "overlaps lamp_0 by 12.0 cm^2"} | {
        b: f"{a} is not in the scene" for a, b in zip(books, books[1:], strict=False)
    }
    repaired = repair_program(program, failed, set(), reasons=reasons)
    stack = [e for e in repaired if len(e) == 4 and e[1] == "PLACE-ON"]
    assert stack == [[b, "PLACE-ON", a, {}] for a, b in zip(books, books[1:], strict=False)]
    assert repaired.index(_anywhere("book_0")) < repaired.index(stack[0])
    _assert_checked(repaired, TABLE, failed)


def test_a_row_anchor_sticking_out_is_pulled_in_and_the_row_follows_it() -> None:
    shelf = Support(kind="shelf", size=(0.3, 1.0))
    program: list[Entry] = [
        ["binder_0", "a blue ring binder lying flat"],
        ["binder_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.4}],
        ["binder_0", "FACING-FRONT", "root", {}],
        ["binder_1", "a slim red binder lying flat"],
        ["binder_1", "PLACE-ON-BASE", "root", {}],
        ["binder_1", "RIGHT-OF", "binder_0", {"distance": 0.03}],
        ["binder_1", "ALIGN-CENTER-FB", "binder_0", {}],
        ["binder_1", "FACING-FRONT", "root", {}],
    ]
    reasons = {"binder_0": "sticks out 8.6 cm past the left edge", "binder_1": "sticks out 0.9 cm past the front edge"}
    repaired = repair_program(program, {"binder_0", "binder_1"}, set(), reasons=reasons, support=shelf)
    assert repaired[1] == ["binder_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": round(0.4 - 0.086 - EDGE_MARGIN_M, 3)}]
    assert repaired[3:] == program[3:]  # binder_1 stays in the row: it stuck out only because binder_0 did
    _assert_checked(repaired, shelf, {"binder_0"})


def test_what_only_overlaps_an_object_that_also_sticks_out_stays_where_it_is() -> None:
    program: list[Entry] = [
        ["tray_0", "a rectangular wooden serving tray"],
        ["tray_0", "PLACE-ON-BASE", "root", {"x": 0.3, "y": 0.0}],
        ["tray_0", "FACING-FRONT", "root", {}],
        ["vase_0", "a vase"],
        ["vase_0", "PLACE-ON-BASE", "root", {"x": 0.25, "y": 0.1}],
        ["vase_0", "FACING-FRONT", "root", {}],
    ]
    reasons = {
        "tray_0": "overlaps vase_0 by 30.0 cm^2; sticks out 5.0 cm past the front edge",
        "vase_0": "overlaps tray_0 by 30.0 cm^2",
    }
    repaired = repair_program(program, {"tray_0", "vase_0"}, set(), reasons=reasons, support=TABLE)
    assert repaired[3:] == program[3:]
    assert repaired[1] == ["tray_0", "PLACE-ON-BASE", "root", {"x": round(0.3 - 0.05 - EDGE_MARGIN_M, 3), "y": 0.0}]


# ---- smaller variants ------------------------------------------------------------------------------------------------


def _footprint(catalogue: Catalogue, description: str) -> float:
    size = catalogue.resolve(description).size
    return float(size[0] * size[1])


def _one(description: str, placement: Entry) -> list[Entry]:
    return [["thing_0", description], ["thing_0", *placement], ["thing_0", "FACING-FRONT", "root", {}]]


@pytest.mark.parametrize(
    "description",
    [
        "a large open cardboard moving box",
        "a folded white bath towel",
        "a large atlas lying flat",
        "a large bamboo tray",
    ],
)
def test_an_object_sticking_out_past_opposite_edges_takes_a_smaller_variant_of_its_kind(description: str) -> None:
    catalogue = default_catalogue()
    program = _one(description, ["PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.1}])
    reasons = {"thing_0": "sticks out 1.7 cm past the back edge; sticks out 1.7 cm past the front edge"}
    repaired = repair_program(program, {"thing_0"}, set(), reasons=reasons, catalogue=catalogue, support=TABLE)
    smaller = _description(repaired, "thing_0")
    assert catalogue.resolve(smaller).category == catalogue.resolve(description).category
    assert _footprint(catalogue, smaller) < _footprint(catalogue, description)
    assert repaired[1:] == program[1:]  # where it stands and how it faces stay


@pytest.mark.parametrize("description", ["an open brown cardboard box", "a thick grey towel folded in four"])
def test_nothing_large_enough_takes_the_smallest_variant_and_a_second_failure_the_next_smaller(
    description: str,
) -> None:
    catalogue = default_catalogue()
    program = _one(description, ["PLACE-ANYWHERE", "root", {"stack": False}])
    reasons = {"thing_0": "no free spot on the support: nothing there is large enough for it (0% covered)"}
    first = repair_program(program, {"thing_0"}, set(), reasons=reasons, catalogue=catalogue)
    same_kind = [
        a
        for a in catalogue.variants(description, 16)
        if a.category == catalogue.resolve(description).category and catalogue.resolve(a.description).id == a.id
    ]
    assert _description(first, "thing_0") == min(same_kind, key=lambda a: a.size[0] * a.size[1]).description
    again = repair_program(program, {"thing_0"}, {"thing_0"}, reasons={"thing_0": FELL}, catalogue=catalogue)
    assert _footprint(catalogue, _description(again, "thing_0")) < _footprint(catalogue, description)
    assert again[1:] == program[1:]


def test_an_object_already_placed_anywhere_takes_a_smaller_variant_and_keeps_its_own_parameters() -> None:
    catalogue = default_catalogue()
    program = _one("a large open cardboard moving box", ["PLACE-ANYWHERE", "root", {"messy": True, "stack": True}])[:2]
    repaired = repair_program(program, {"thing_0"}, set(), reasons={"thing_0": FELL}, catalogue=catalogue)
    assert _footprint(catalogue, _description(repaired, "thing_0")) < _footprint(catalogue, program[0][1])
    assert repaired[1] == program[1]
    no_catalogue = repair_program(program, {"thing_0"}, set(), reasons={"thing_0": FELL})
    assert no_catalogue == program  # freed again, as it was


def test_a_holder_that_found_no_room_goes_before_the_loose_things_with_its_load_after_it() -> None:
    program: list[Entry] = [["vase_0", "a vase"], ["vase_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}]]
    program += [["vase_0", "FACING-FRONT", "root", {}]]
    program += [[f"apple_{k}", "an apple"] for k in range(2)] + [_anywhere(f"apple_{k}") for k in range(2)]
    program += [["tray_0", "a small white tea tray"], _anywhere("tray_0"), ["mug_0", "a mug"]]
    program += [["mug_0", "PLACE-ON", "tray_0", {}]]
    reasons = {"tray_0": "no free spot on the support: nothing there is large enough for it (31% covered)"}
    repaired = repair_program(program, {"tray_0", "mug_0"}, set(), reasons=reasons)  # no smaller variant known
    assert repaired[3:5] == [["tray_0", "a small white tea tray"], _anywhere("tray_0")]
    assert repaired[-2:] == [["mug_0", "a mug"], ["mug_0", "PLACE-ON", "tray_0", {}]]
    assert program != repaired and sorted(map(json.dumps, program)) == sorted(map(json.dumps, repaired))
    _assert_checked(repaired, TABLE, {"tray_0"})


def test_a_centre_that_would_be_pulled_off_the_support_means_too_large() -> None:
    catalogue = default_catalogue()
    shelf = Support(kind="shelf", size=(0.3, 1.0))
    program = _one("a large open cardboard moving box", ["PLACE-ON-BASE", "root", {"x": 0.02, "y": 0.0}])
    reasons = {"thing_0": "sticks out 17.1 cm past the front edge"}
    repaired = repair_program(program, {"thing_0"}, set(), reasons=reasons, catalogue=catalogue, support=shelf)
    assert _footprint(catalogue, _description(repaired, "thing_0")) < _footprint(catalogue, program[0][1])
    assert repaired[1] == ["thing_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}]  # centred, not pulled off


def test_an_object_is_dropped_only_with_no_smaller_variant_after_failing_anywhere() -> None:
    catalogue = default_catalogue()
    smallest = "a rolled white towel"
    program = _one(smallest, ["PLACE-ANYWHERE", "root", {"stack": False}])
    program += [["mug_0", "a classic white ceramic coffee mug"], ["mug_0", "PLACE-ON-BASE", "root", {"x": 0, "y": 0}]]
    program += [["mug_0", "FACING-FRONT", "root", {}]]
    reasons = {"thing_0": "no free spot on the support: nothing there is large enough for it (40% covered)"}
    first = repair_program(program, {"thing_0"}, set(), reasons=reasons, catalogue=catalogue)
    assert "thing_0" in _declared(first)  # still a chance, anywhere
    again = repair_program(program, {"thing_0"}, {"thing_0"}, reasons=reasons, catalogue=catalogue)
    assert _declared(again) == {"mug_0"}


# ---- never nothing ---------------------------------------------------------------------------------------------------


def test_when_every_object_fails_for_good_the_smallest_version_of_the_scene_stays() -> None:
    catalogue = default_catalogue()
    smallest = [["towel_0", "a rolled white towel"], _anywhere("towel_0")]
    gone = {"towel_0"}
    assert repair_program(smallest, gone, gone, catalogue=catalogue) == smallest  # the last object is not dropped
    program: list[Entry] = []
    for k, description in enumerate(
        ["a folded white bath towel", "a thick grey towel folded in four", "a large atlas lying flat"]
    ):
        program += [[f"thing_{k}", description], [f"thing_{k}", "PLACE-ANYWHERE", "root", {"stack": False}]]
    failed = {"thing_0", "thing_1", "thing_2"}
    catalogue_less = repair_program(program, failed, failed)  # kinds are told apart by their descriptions
    assert catalogue_less == [entry for k in range(3) for entry in (program[2 * k], _anywhere(f"thing_{k}"))]
    repaired = smallest_scene(parse_program(program), catalogue)  # what is left when none has a smaller variant
    assert _declared(repaired) == {"thing_0", "thing_2"}  # one towel, one book
    for oid, description in (("thing_0", program[0][1]), ("thing_2", program[4][1])):
        assert _footprint(catalogue, _description(repaired, oid)) < _footprint(catalogue, description)
    _assert_checked(repaired, TABLE, failed)


def test_the_planner_never_answers_an_empty_program(planner: OfflinePlanner) -> None:
    prompt = "a bathroom shelf with three rolls of toilet paper stacked and a folded towel"
    shelf = Support(kind="shelf", size=(0.3, 0.6))
    context = AgentContext(prompt, shelf, (), (Round("[]", "the program is empty"),), "repair", {})
    program = planner.repair([], context)
    kinds = {default_catalogue().resolve(e[1]).category for e in program if len(e) == 2}
    assert kinds == {"toilet paper", "towel"}
    assert all(e[1] == "PLACE-ANYWHERE" for e in program if len(e) == 4)


# ---- the planner reads the reasons from the feedback -----------------------------------------------------------------


def test_failure_reasons_are_read_from_the_feedback_lines() -> None:
    text = (
        "The scene was solved but 2 object(s) could not be placed:\n"
        "- rug_0 (PLACE-ON-BASE): sticks out 10.1 cm past the front edge; sticks out 23.7 cm past the right edge\n"
        "- toy_block_0 (PLACE-ON): rug_0 is not in the scene (it failed or was never placed), so nothing can rest\n"
        "The floor is sparse (2% of its top is covered)."
    )
    reasons = failure_reasons(text)
    assert set(reasons) == {"rug_0", "toy_block_0"}
    assert reasons["rug_0"].startswith("sticks out 10.1 cm")
    assert waited_only([text]) == {"toy_block_0"}
    assert waited_only([text, "- toy_block_0 (PLACE-ON): fell during settling"]) == set()


def test_the_planner_pulls_a_stack_base_in_and_keeps_the_stack(planner: OfflinePlanner) -> None:
    prompt = "a shelf with a stack of three boxes and a vase"
    shelf = Support(kind="shelf", size=(0.35, 0.8))
    program = planner.plan(AgentContext(prompt, shelf, ()))
    stack = [e for e in program if len(e) == 4 and e[1] == "PLACE-ON"]
    base = next(e for e in program if len(e) == 4 and e[1] == "PLACE-ON-BASE" and e[0] == stack[0][2])
    above = [e[0] for e in stack]
    lines = [f"- {base[0]} (PLACE-ON-BASE): sticks out 2.0 cm past the front edge"]
    lines += [f"- {oid} (PLACE-ON): {base[0]} is not in the scene (it failed or was never placed)" for oid in above]
    notes = {"failed": ",".join([base[0], *above]), "freed": ""}
    context = AgentContext(prompt, shelf, (), (Round(json.dumps(program), "\n".join(lines)),), "repair", notes)
    repaired = planner.repair(program, context)
    moved = next(e for e in repaired if e[:2] == base[:2])
    assert moved[3]["x"] == round(base[3]["x"] - 0.02 - EDGE_MARGIN_M, 3)
    assert [e for e in repaired if len(e) == 4 and e[1] == "PLACE-ON"] == stack
    _assert_checked(repaired, shelf, set())


# ---- the loop keeps the best partial scene ---------------------------------------------------------------------------


class _Scripted:
    """An agent that sends the given replies in turn."""

    name = "scripted"

    def __init__(self, replies: list[str]) -> None:
        self.replies = list(replies)

    def propose(self, context: AgentContext) -> str:
        return self.replies.pop(0) if self.replies else "[]"


def test_the_loop_returns_the_round_that_placed_most_when_later_rounds_get_worse() -> None:
    small = Support(kind="table", size=(0.6, 0.6))
    rug = [["rug_0", "a red patterned area rug with a cream border and fringes"]]
    rug += [["rug_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}], ["rug_0", "FACING-FRONT", "root", {}]]
    mugs = [[f"mug_{k}", "a classic white ceramic coffee mug"] for k in range(3)]
    mugs += [[f"mug_{k}", "PLACE-ANYWHERE", "root", {}] for k in range(3)]
    replies = [json.dumps(rug + mugs), "[]", json.dumps(rug + mugs[:1] + mugs[3:4])]
    result = generate_scene("three mugs on a rug", _Scripted(replies), support=small, retries=3)
    assert result.solution is not None
    assert len(result.solution.scene.placed) == 3


# ---- the property: every planner program, every object failing, and random pairs -------------------------------------


@pytest.mark.parametrize(("name", "prompt", "support"), CASES, ids=[c[0] for c in CASES])
def test_any_failure_keeps_every_object_once_and_drops_only_what_failed_again_anywhere(
    planner: OfflinePlanner, name: str, prompt: str, support: Support
) -> None:
    program = planner.plan(AgentContext(prompt, support, ()))
    assert check_program(parse_program(program), support).ok
    objects = sorted(_declared(program))
    rng = random.Random(name)
    pairs = [set(rng.sample(objects, 2)) for _ in range(PAIRS_PER_PROGRAM)] if len(objects) > 1 else []
    for failed in [{oid} for oid in objects] + pairs + [set(objects)]:
        _assert_first_repair(program, repair_program(program, failed, tried_free=set()), failed, support)
        _assert_second_repair(program, repair_program(program, failed, tried_free=failed), failed, support)


def test_an_enriched_program_repairs_the_same_way(planner: OfflinePlanner) -> None:
    first = json.dumps(_dining(planner))
    enriched = planner.enrich(json.loads(first), AgentContext(DINING, TABLE, (), (Round(first, "ok", True),), "enrich"))
    for oid in sorted(_declared(enriched)):
        _assert_first_repair(enriched, repair_program(enriched, {oid}, set()), {oid}, TABLE)
        _assert_second_repair(enriched, repair_program(enriched, {oid}, {oid}), {oid}, TABLE)
