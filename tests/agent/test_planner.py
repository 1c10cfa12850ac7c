"""The offline planner reads prompts it has never seen and writes checked, solvable programs."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from physcensis.agent.base import AgentContext, Round
from physcensis.agent.planner import OfflinePlanner
from physcensis.agent.planning.scenes import scene_type
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
    request = read_prompt("a basket full of apples and a notebook with a pen on it next to a lamp-free mug", lexicon)
    by = {m.category: m for m in request.mentions}
    basket = request.mentions.index(by["basket"])
    assert request.mentions.index(by["apple"]) in by["basket"].contents
    assert by["pen"].on == request.mentions.index(by["notebook"])
    assert basket == 0
    stack = read_prompt("a stack of plates", lexicon)
    assert stack.mentions[0].stacked and stack.mentions[0].count == 4
    assert read_prompt("a dinner for six people", lexicon).diners == 6
    assert read_prompt("a cup balanced precariously on a book", lexicon).fragile


@pytest.mark.parametrize(
    "prompt",
    [
        "a nightstand with a lamp-like vase, a phone and two books",
        "a sewing table with a basket of balls of yarn and scissors",
        "a tray with a teapot and two teacups on saucers",
        "three potted plants in a row",
        "a toddler's table with toy blocks stacked into a tower and a toy truck",
    ],
)
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


def test_repair_frees_then_shrinks_then_drops_what_failed() -> None:
    """A failed object is placed anywhere first; failing again it takes a smaller variant of its kind; it is dropped
    only when it failed anywhere with no smaller variant left (agent/repair.py). (With variety, a first failure is
    drawn again before any of this: tests/agent/test_variety.py.)"""
    planner = OfflinePlanner(variety="none")
    prompt = "a cup on a book and a vase"
    first = planner.propose(AgentContext(prompt, TABLE, ()))
    program = json.loads(first)
    cup = next(e[0] for e in program if len(e) == 4 and e[1] == "PLACE-ON")
    history = (Round(first, f"- {cup} (PLACE-ON): fell during settling", False),)
    repaired = json.loads(
        planner.propose(AgentContext(prompt, TABLE, (), history, "repair", {"failed": cup, "freed": ""}))
    )
    assert [cup, "PLACE-ANYWHERE", "root", {"stack": False, "pack": True}] in repaired
    assert check_program(parse_program(repaired), TABLE).ok

    def footprint(description: str) -> float:
        size = planner.catalogue.resolve(description).size
        return float(size[0] * size[1])

    for _ in range(10):  # each failure a smaller cup, until none is left
        history = (*history, Round(json.dumps(repaired), f"- {cup} (PLACE-ANYWHERE): fell during settling", False))
        notes = {"failed": cup, "freed": cup}
        again = json.loads(planner.propose(AgentContext(prompt, TABLE, (), history, "repair", notes)))
        if all(e[0] != cup for e in again):
            break
        before, after = (next(e[1] for e in p if e[0] == cup and len(e) == 2) for p in (repaired, again))
        assert footprint(after) < footprint(before), "failing again takes a smaller variant"
        assert [cup, "PLACE-ANYWHERE", "root", {"stack": False, "pack": True}] in again
        repaired = again
    assert {e[0] for e in again if len(e) == 2} == {e[0] for e in program if len(e) == 2} - {cup}


def test_enrichment_adds_objects_to_the_same_program() -> None:
    planner = OfflinePlanner()
    first = planner.propose(AgentContext("an office desk with a laptop", TABLE, ()))
    history = (Round(first, "all placed", True),)
    more = json.loads(planner.propose(AgentContext("an office desk with a laptop", TABLE, (), history, "enrich")))
    assert len(more) > len(json.loads(first))
    assert check_program(parse_program(more), TABLE).ok


def _links(request_text: str, lexicon: Lexicon) -> dict[str, dict[str, object]]:
    request = read_prompt(request_text, lexicon)
    names = [m.category for m in request.mentions]

    def name(k: int | None) -> str | None:
        return None if k is None else names[k]

    return {
        m.category: {
            "on": name(m.on),
            "in": [names[j] for j in m.contents],
            "beside": name(m.beside),
            "around": name(m.around),
            "per": name(m.per),
            "centre": m.centre,
            "stacked": m.stacked,
        }
        for m in request.mentions
    }


def test_a_listed_content_goes_into_a_container_or_onto_a_surface(lexicon: Lexicon) -> None:
    basket = _links("a basket full of apples, oranges and bananas next to a mug", lexicon)
    assert basket["basket"]["in"] == ["apple", "orange", "banana"]
    assert basket["mug"]["in"] == [] and basket["basket"]["beside"] == "mug"  # the list ends at "next to"
    board = _links("a cutting board full of apples and oranges", lexicon)
    assert board["apple"]["on"] == board["orange"]["on"] == "cutting board" and board["cutting board"]["in"] == []
    assert _links("a pen holder with six pens inside", lexicon)["pen holder"]["in"] == ["pen"]


def test_neighbouring_mentions_are_linked_by_the_words_between_them(lexicon: Lexicon) -> None:
    assert _links("a cup inside a bowl in the middle", lexicon)["bowl"] == {
        "on": None,
        "in": ["cup"],
        "beside": None,
        "around": None,
        "per": None,
        "centre": True,
        "stacked": False,
    }
    assert _links("a knife on the edge of a cutting board", lexicon)["knife"]["on"] == "cutting board"
    pairs = _links("sandwiches on plates and cups on saucers", lexicon)
    assert (pairs["sandwich"]["on"], pairs["sandwich"]["per"]) == ("plate", "plate")
    assert (pairs["cup"]["on"], pairs["cup"]["per"]) == ("saucer", "saucer")
    assert _links("a pile of books and plates stacked", lexicon)["plate"]["stacked"]


def test_rims_and_rings_refer_back_to_an_earlier_mention(lexicon: Lexicon) -> None:
    rim = _links("a toothbrush in a cup and a spoon across its rim", lexicon)
    assert rim["cup"]["in"] == ["toothbrush"] and rim["spoon"]["on"] == "cup"
    ring = _links("a vase in the middle with four cups around it", lexicon)
    assert ring["vase"]["centre"] and ring["cup"]["around"] == "vase"


def test_a_ring_of_objects_faces_the_centre_piece_at_one_radius() -> None:
    program = OfflinePlanner().plan(AgentContext("a vase in the middle with four cups around it", TABLE, ()))
    assert ["vase_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}] in program
    spots = [e[3] for e in program if e[0].startswith("cup") and e[1] == "PLACE-ON-BASE"]
    assert len(spots) == 4 and len({round((s["x"] ** 2 + s["y"] ** 2) ** 0.5, 2) for s in spots}) == 1
    assert sum(e[1:3] == ["FACING-TO", "vase_0"] for e in program) == 4


def test_more_of_the_same_stand_in_a_row_from_one_grid_spot() -> None:
    program = OfflinePlanner().plan(AgentContext("three laptops", TABLE, ()))
    assert [e[0] for e in program if e[1] == "PLACE-ON-BASE" and e[3]] == ["laptop_0"]
    assert [e[:3] for e in program if e[1] == "RIGHT-OF"] == [
        ["laptop_1", "RIGHT-OF", "laptop_0"],
        ["laptop_2", "RIGHT-OF", "laptop_1"],
    ]


def test_each_diner_gets_a_copied_setting_facing_the_table() -> None:
    program = OfflinePlanner().plan(AgentContext("a dinner for five people", TABLE, ()))
    copies = {e[0] for e in program if e[1] == "COPY-GROUP"}
    seats = {e[0]: (e[3]["x"], e[3]["y"]) for e in program if e[0] in copies and e[1] == "PLACE-ON-BASE"}
    facings = {e[0]: e[1] for e in program if e[0] in copies and e[1].startswith("FACING-")}
    assert seats == {
        "group_setting_1": (-0.31, 0.0),
        "group_setting_2": (0.0, 0.21),
        "group_setting_3": (0.0, -0.21),
        "group_setting_4": (0.25, -0.21),
    }
    assert facings == {
        "group_setting_1": "FACING-FRONT",
        "group_setting_2": "FACING-RIGHT",
        "group_setting_3": "FACING-LEFT",
        "group_setting_4": "FACING-LEFT",
    }


@pytest.mark.parametrize("seed", range(3))
def test_a_napkin_named_at_a_laid_table_is_a_piece_of_every_setting(seed: int) -> None:
    prompt = "a table laid for four, every plate with a napkin beside it"
    program = OfflinePlanner(variety="normal").plan(AgentContext(prompt, TABLE, (), seed=seed))
    group = next(e for e in program if e[0] == "group_setting_0" and e[1] == "GROUP")
    napkin = next(oid for oid in group[2] if oid.startswith("napkin"))
    fork = next(oid for oid in group[2] if oid.startswith("fork"))
    assert [napkin, "RIGHT-OF", fork, {"distance": 0.015}] in program  # outside the fork, in every copy
    assert sum(e[1] == "COPY-GROUP" for e in program) == 3
    description = next(e[1] for e in program if e[0] == napkin and len(e) == 2)
    assert min(default_catalogue().resolve(description).size[:2]) <= 0.12  # folded narrow


@pytest.mark.parametrize(
    ("prompt", "depth", "facing"),
    [
        ("a shelf with a letter tray", 0.3, "FACING-LEFT"),  # 33-35 cm deep trays fit a 30 cm shelf only turned
        ("an office shelf with a desk organiser and a letter tray", 0.3, "FACING-LEFT"),
        ("a desk with a letter tray", 0.8, "FACING-FRONT"),
    ],
)
def test_a_lone_anchor_turns_when_only_then_it_fits_the_support(prompt: str, depth: float, facing: str) -> None:
    support = Support(kind="shelf" if "shelf" in prompt else "table", size=(depth, 1.0))
    program = json.loads(OfflinePlanner().propose(AgentContext(prompt, support, ())))
    tray = next(e[0] for e in program if e[0].startswith("letter_tray") and len(e) == 2)
    assert [tray, facing, "root", {}] in program
    size = default_catalogue().resolve(next(e[1] for e in program if e[0] == tray and len(e) == 2)).size
    assert (size[1] if facing == "FACING-LEFT" else size[0]) <= depth  # its depth on the support fits


@pytest.mark.parametrize(
    ("prompt", "height", "nested"),
    [
        ("a stack of four bowls", 4, True),
        ("three colanders stacked", 3, True),
        ("a stack of four plates", 4, False),
        ("a stack of three mugs", 3, False),
        ("a stack of four books", 4, False),
    ],
)
def test_a_stack_of_things_that_nest_is_a_nest(prompt: str, height: int, nested: bool) -> None:
    program = json.loads(OfflinePlanner().propose(AgentContext(prompt, TABLE, ())))
    into = [e for e in program if len(e) == 4 and e[1] == "PLACE-IN"]
    onto = [e for e in program if len(e) == 4 and e[1] == "PLACE-ON"]
    assert (len(into), len(onto)) == ((height - 1, 0) if nested else (0, height - 1))


@pytest.mark.parametrize(
    ("prompt", "item", "carrier"),
    [
        ("toy cars parked around a tower of toy blocks on the rug", "toy_car", "rug"),
        ("four cups around a teapot on a large tray", "cup", "tray"),
        ("apples arranged around a candle on a wooden board", "apple", "cutting_board"),
    ],
)
def test_things_around_a_piece_on_a_carrier_ring_it_on_that_carrier(prompt: str, item: str, carrier: str) -> None:
    support = Support(kind="floor", size=(1.5, 1.5)) if "rug" in prompt else TABLE
    program = json.loads(OfflinePlanner().propose(AgentContext(prompt, support, ())))
    ring = [e for e in program if len(e) == 4 and e[0].startswith(item) and e[1] == "PLACE-ON"]
    assert len(ring) >= 3 and all(e[2].startswith(carrier) for e in ring), program
    offsets = [(e[3]["x_offset"], e[3]["y_offset"]) for e in ring]
    bearings = sorted(math.atan2(y, x) % (2 * math.pi) for x, y in offsets)
    gaps = np.diff([*bearings, bearings[0] + 2 * math.pi])
    assert max(gaps) < math.pi  # on every side of the piece, not in a row


@pytest.mark.parametrize(
    ("prompt", "category", "least"),
    [
        ("a shelf full of books", "book", 8),
        ("a bookshelf packed with books", "book", 8),
        ("a shelf full of ring binders", "binder", 8),
    ],
)
def test_a_support_full_of_things_that_stand_upright_is_a_row_of_them(prompt: str, category: str, least: int) -> None:
    shelf = Support(kind="shelf", size=(0.3, 0.9))
    program = json.loads(OfflinePlanner().propose(AgentContext(prompt, shelf, ())))
    declared = [e for e in program if len(e) == 2 and e[0].startswith(category)]
    assert len(declared) >= least
    assert all(default_catalogue().resolve(e[1]).size[1] < 0.1 for e in declared)  # thin: standing on an edge


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("a bathroom counter with a toothbrush in a cup", "bathroom"),  # the room, not what its support is called
        ("a kitchen counter with a kettle", "kitchen"),
        ("a counter with a kettle", "kitchen"),
        ("a sink with a sponge", "bathroom"),
        ("a kitchen sink with a sponge", "kitchen"),
    ],
)
def test_the_room_a_prompt_names_decides_its_kind_of_scene(text: str, kind: str) -> None:
    assert scene_type(read_prompt(text, Lexicon(default_catalogue())), "table") == kind
