"""Seeded variety: a prompt is a distribution of scenes, every one of them faithful to the words.

The planner draws every choice the prompt leaves open from the run's seed (agent/variety.py); what the words fix (a
number, a colour, a side) is never drawn, and `variety="none"` writes exactly the programs it wrote before variety
existed (`canonical_programs.json`, captured from that planner on the public suite and a third of the home suite).
"""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path
from typing import Any

import pytest

from physcensis.agent.base import AgentContext, Round
from physcensis.agent.planner import OfflinePlanner
from physcensis.agent.variety import Draws, Variety, parse_variety
from physcensis.assets import default_catalogue
from physcensis.bench.prompt_suite import SUITES, load_suite
from physcensis.errors import PhyscensisError
from physcensis.program import check_program, parse_program
from physcensis.scene import Support

CANONICAL = Path(__file__).with_name("canonical_programs.json")
TABLE = Support(kind="table", size=(1.2, 0.8))


_PLANNERS: dict[tuple[str, bool | None], OfflinePlanner] = {}


def _planner(variety: str = "normal", context: bool | None = None) -> OfflinePlanner:
    """One planner per setting (a planner serves many runs: each propose draws from its context's seed)."""
    key = (variety, context)
    if key not in _PLANNERS:
        _PLANNERS[key] = OfflinePlanner(default_catalogue(), variety=variety, context=context)
    return _PLANNERS[key]


def _program(
    prompt: str, seed: int, variety: str = "normal", support: Support = TABLE, context: bool | None = None
) -> list[Any]:
    planner = _planner(variety, context)
    return list(json.loads(planner.propose(AgentContext(prompt, support, (), seed=seed))))


def _declared(program: list[Any]) -> dict[str, str]:
    return {e[0]: e[1] for e in program if len(e) == 2 and isinstance(e[0], str)}


def _assets(program: list[Any], category: str) -> list[str]:
    catalogue = default_catalogue()
    return [catalogue.resolve(d).id for d in _declared(program).values() if catalogue.resolve(d).category == category]


def _cases() -> dict[str, dict[str, Any]]:
    return {f"{name}/{case['id']}": case for name in ("public", "home") for case in load_suite(SUITES[name])}


def test_variety_none_writes_the_canonical_programs() -> None:
    cases = _cases()
    expected = json.loads(CANONICAL.read_text())
    for key, program in expected.items():
        case = cases[key]
        support = Support(kind=case["support"]["kind"], size=tuple(case["support"]["size"]))
        assert _program(case["prompt"], 7, "none", support) == program, key  # the seed reaches only the solver


@pytest.mark.parametrize(
    "prompt",
    ["a dining table set up for four people", "some pens, a mug and a stack of books", "a desk with a lamp"],
)
def test_the_same_seed_gives_the_same_program_and_other_seeds_others(prompt: str) -> None:
    assert _program(prompt, 5) == _program(prompt, 5)
    programs = {json.dumps(_program(prompt, seed)) for seed in range(8)}
    assert len(programs) >= 6


def test_words_fix_what_they_say_and_the_seed_chooses_the_rest() -> None:
    reds, mugs = set(), set()
    catalogue = default_catalogue()
    for seed in range(12):
        red = _assets(_program("a red mug and a plate", seed), "mug")
        assert len(red) == 1 and "red" in catalogue.get(red[0]).description
        reds.add(red[0])
        mugs.update(_assets(_program("a mug and a plate", seed), "mug"))
    assert len(mugs) >= 4  # "a mug" may be any mug
    assert len(reds) >= 2 or len([a for a in catalogue.all() if a.category == "mug" and "red" in a.description]) < 2


def test_said_counts_stay_exact_and_loose_ones_are_drawn_within_their_range() -> None:
    few, plural = Counter(), Counter()
    for seed in range(10):
        assert len(_assets(_program("three mugs and a stack of 5 plates", seed), "mug")) == 3
        assert len(_assets(_program("three mugs and a stack of 5 plates", seed), "plate")) == 5
        few[len(_assets(_program("a few apples next to a laptop", seed), "apple"))] += 1
        plural[len(_assets(_program("a laptop and some pens", seed), "pen"))] += 1
    assert set(few) <= {2, 3, 4} and len(few) >= 2
    assert min(plural) >= 2 and len(plural) >= 2


def _stack_footprints(program: list[Any], category: str) -> list[float]:
    """The footprint areas of a stack's levels, bottom first (each entry rests on the one declared before)."""
    catalogue = default_catalogue()
    sizes = [catalogue.resolve(_declared(program)[oid]).size for oid in _declared(program) if oid.startswith(category)]
    return [x * y for x, y, _ in sizes]


def test_stacks_of_flat_things_may_mix_widest_at_the_bottom_and_sets_stay_one_kind() -> None:
    books, plates = Counter(), set()
    for seed in range(12):
        stack = _assets(_program("a stack of 4 books", seed), "book")
        assert len(stack) == 4
        books[tuple(stack)] += 1
        areas = _stack_footprints(_program("a stack of 4 books", seed), "book")
        assert areas == sorted(areas, reverse=True)  # a smaller book never carries a larger one
        dishes = _assets(_program("a stack of 5 plates", seed), "plate")
        assert len(dishes) == 5 and len(set(dishes)) == 1  # a stack of plates is a set
        plates.add(dishes[0])
    assert len(books) >= 6 and any(len(set(s)) > 1 for s in books) and any(len(set(s)) == 1 for s in books)
    assert len(plates) >= 3
    canonical = _assets(_program("a stack of 4 books", 0, "none"), "book")
    assert len(set(canonical)) == 1


def test_words_asking_for_different_things_get_different_things_at_any_variety() -> None:
    for variety in ("none", "normal"):
        boxes = _assets(_program("a stack of five gift boxes of different sizes", 3, variety), "box")
        assert len(set(boxes)) == 5, variety
        mugs = _assets(_program("four assorted mugs on a shelf", 3, variety), "mug")
        assert len(set(mugs)) == 4, variety


def test_a_pair_matches_and_a_count_of_things_takes_a_drawn_number_of_kinds() -> None:
    kinds = Counter()
    for seed in range(12):
        for variety in ("none", "normal"):
            chopsticks = _assets(_program("a bowl and a pair of chopsticks", seed, variety), "chopsticks")
            assert len(chopsticks) == 2 and len(set(chopsticks)) == 1, (seed, variety)
        glasses = _assets(_program("five wine glasses in a row", seed), "wine glass")
        assert len(glasses) == 5
        kinds[len(set(glasses))] += 1
    assert len(kinds) >= 3  # a matching set of five, or two or more kinds: the seed says


def test_a_count_of_several_kinds_splits_them_in_drawn_shares() -> None:
    """ "a dozen tennis balls": twelve, of a drawn number of the catalogue's kinds in drawn shares (nine and three, not
    always six and six), each kind drawn at least once; without variety every kind in turn."""
    floor = Support(kind="floor", size=(2.5, 2.0))
    canonical = Counter(_assets(_program("a dozen tennis balls on the floor", 0, "none", floor), "ball"))
    assert sum(canonical.values()) == 12 and max(canonical.values()) - min(canonical.values()) <= 1
    splits = set()
    for seed in range(20):
        balls = Counter(_assets(_program("a dozen tennis balls on the floor", seed, "normal", floor), "ball"))
        assert sum(balls.values()) == 12 and min(balls.values()) >= 1, (seed, balls)
        splits.add(tuple(sorted(balls.items())))
    assert len(splits) >= 10
    assert any(max(Counter(dict(s)).values()) - min(Counter(dict(s)).values()) > 1 for s in splits if len(s) > 1)


def test_place_settings_move_between_seeds_and_keep_their_pieces() -> None:
    layouts = set()
    for seed in range(8):
        program = _program("a dining table set up for four people", seed, context=False)
        assert not check_program(parse_program(json.dumps(program))).problems
        copies = [e for e in program if e[1] == "COPY-GROUP"]
        assert len(copies) == 3
        places = tuple(
            (e[3]["x"], e[3]["y"]) for e in program if str(e[0]).startswith("group_setting") and e[1] == "PLACE-ON-BASE"
        )
        layouts.add(places)
        assert set(_declared(program)) == {"plate_0", "fork_0", "knife_0", "cup_0"}
    assert len(layouts) == 8


def test_context_objects_are_added_said_and_can_be_turned_off() -> None:
    seen = 0
    for seed in range(10):
        planner = _planner()
        program = json.loads(
            planner.propose(AgentContext("a dining table set up for two people", TABLE, (), seed=seed))
        )
        declared = _declared(program)
        assert {row["id"] for row in planner.added} <= set(declared)
        assert all(row["why"] for row in planner.added)
        seen += len(planner.added)
        off = _program("a dining table set up for two people", seed, context=False)
        assert set(_declared(off)) == set(declared) - {row["id"] for row in planner.added}
    assert seen > 0
    for seed in range(6):  # a prompt naming no kind of scene gets nothing it did not ask for
        planner = _planner()
        planner.propose(AgentContext("a gizmo next to a mug and two frobnicators", TABLE, (), seed=seed))
        assert planner.added == []


def test_draws_are_keyed_stable_and_canonical_when_off() -> None:
    off, on = Draws(Variety.NONE, 3), Draws(Variety.NORMAL, 3)
    items = list(range(10))
    assert off.order(items, "k") == items and off.count(4, 1, 9, "k") == 4 and off.uniform(0.5, 0, 1, "k") == 0.5
    assert on.order(items, "k") == on.order(items, "k") and sorted(on.order(items, "k")) == items
    assert on.order(items, "k") != Draws(Variety.NORMAL, 4).order(items, "k")
    counts = Counter(on.order(["heavy", "light"], "w", i, weights=[9.0, 1.0])[0] for i in range(400))
    assert counts["heavy"] > 300
    assert {Draws(Variety.WIDE, s).count(3, 2, 6, "c") for s in range(60)} == {2, 3, 4, 5, 6}
    with pytest.raises(PhyscensisError, match="variety 'lots'"):
        parse_variety("lots")


@pytest.mark.parametrize("variety", ["normal", "wide"])
def test_every_drawn_program_of_the_public_suite_checks_without_errors(variety: str) -> None:
    for case in load_suite(SUITES["public"]):
        support = Support(kind=case["support"]["kind"], size=tuple(case["support"]["size"]))
        for seed in (0, 1) if variety == "normal" else (2,):
            program = json.dumps(_program(case["prompt"], seed, variety, support))
            errors = check_program(parse_program(program)).errors
            assert errors == [], (case["id"], seed, [str(p) for p in errors])


def _failed_round(program: list[Any], oid: str) -> Round:
    return Round(json.dumps(program), f"{oid} failed", ok=False)


def test_a_failed_draw_is_drawn_afresh_then_with_the_canonical_choices_rather_than_dropped() -> None:
    prompt = "a laptop next to some pens, a stack of books and a mug"
    planner = _planner()
    first = _program(prompt, 4)
    pens = sorted(i for i in _declared(first) if i.startswith("pen_"))

    def retry(history: tuple[Round, ...], failed: str) -> list[Any]:
        context = AgentContext(prompt, TABLE, (), history=history, request="repair", notes={"failed": failed}, seed=4)
        return list(json.loads(planner.propose(context)))

    fresh = retry((_failed_round(first, pens[0]),), pens[0])  # another scene of the same prompt, nothing canonical
    assert fresh != first and fresh != _program(prompt, 4, "none")
    assert fresh == retry((_failed_round(first, pens[0]),), pens[0])  # and the same one every time
    assert any("drawn afresh" in note for note in planner.transcript_notes)

    mug = next(i for i in _declared(fresh) if i.startswith("mug_"))
    history = (_failed_round(first, pens[0]), _failed_round(fresh, mug))  # the fresh draw failed elsewhere
    redrawn = retry(history, mug)
    canonical = _program(prompt, 4, "none")
    assert _assets(fresh, "mug") != _assets(canonical, "mug")
    assert _assets(redrawn, "mug") == _assets(canonical, "mug")  # what failed: as the canonical scene has it
    assert _assets(redrawn, "book") == _assets(fresh, "book")  # the rest keeps its fresh draws
    assert any("drawn again with the canonical choices" in note for note in planner.transcript_notes)
    categories = Counter(default_catalogue().resolve(d).category for d in _declared(redrawn).values())
    assert {"laptop", "pen", "book", "mug"} <= set(categories)  # nothing asked for is dropped


def test_what_a_container_was_filled_with_as_many_as_fit_is_left_out_when_it_falls_out() -> None:
    """ "a bowl of apples": the apples are as many as the planner found room for; one that bounces out is left out
    of the same drawn scene (its bowl and the rest kept), while two stay. A said count is never thinned so."""
    planner = OfflinePlanner(default_catalogue(), variety="normal")

    def retry(prompt: str, program: list[Any], failed: list[str]) -> list[Any]:
        history = (_failed_round(program, failed[0]),)
        notes = {"failed": ",".join(failed)}
        context = AgentContext(prompt, TABLE, (), history=history, request="repair", notes=notes, seed=3)
        return list(json.loads(planner.propose(context)))

    prompt = "a bowl of green apples"
    first = list(json.loads(planner.propose(AgentContext(prompt, TABLE, (), seed=3))))
    apples = sorted(i for i in _declared(first) if i.startswith("apple_"))
    assert len(apples) >= 3
    fewer = retry(prompt, first, apples[:1])
    assert sorted(i for i in _declared(fewer) if i.startswith("apple_")) == apples[1:]
    assert _declared(fewer)["bowl_0"] == _declared(first)["bowl_0"]
    assert not any(apples[0] in json.dumps(e) for e in fewer)  # in no rule, nor in the PLACE-IN's list
    assert any("left out" in note for note in planner.transcript_notes)
    assert retry(prompt, fewer, apples[1 : len(apples) - 1]) != fewer  # two stay: never fewer
    said = "a bowl of five green apples"
    first = list(json.loads(planner.propose(AgentContext(said, TABLE, (), seed=3))))
    five = sorted(i for i in _declared(first) if i.startswith("apple_"))
    assert len(five) == 5 and len([i for i in _declared(retry(said, first, five[:1])) if i.startswith("apple_")]) == 5


def test_the_planner_says_how_many_choices_of_assets_and_counts_the_words_left_open() -> None:
    planner = _planner("normal", context=False)
    floor = Support(kind="floor", size=(2.5, 2.0))
    planner.propose(AgentContext("a dozen baseballs spread over the garage floor", floor, (), seed=0))
    assert planner.open_choices == 1  # twelve said, and one baseball in the catalogue
    planner.propose(AgentContext("a dozen tennis balls spread over the garage floor", floor, (), seed=0))
    assert planner.open_choices > 1  # twelve said, but three tennis balls to draw from
    planner.propose(AgentContext("some pens and a mug", TABLE, (), seed=0))
    assert planner.open_choices >= 10  # which pens, how many, which mug
    canonical = _planner("none", context=False)
    canonical.propose(AgentContext("some pens and a mug", TABLE, (), seed=0))
    assert canonical.open_choices == 1


def test_different_things_in_a_stack_are_a_drawn_set_that_still_stacks() -> None:
    """ "assorted" flat things: every level another kind, largest at the bottom, each within a tenth of the one
    below; which kinds is the seed's when more than one such set exists."""
    catalogue = default_catalogue()
    sets = set()
    for seed in range(12):
        program = _program("a stack of three assorted books lying flat", seed)
        books = _assets(program, "book")
        assert len(books) == 3 and len(set(books)) == 3
        sizes = [sorted(catalogue.resolve(d).size[:2]) for d in _declared(program).values()]
        for upper, lower in zip(sizes[1:], sizes, strict=False):
            assert upper[0] <= 1.1 * lower[0] and upper[1] <= 1.1 * lower[1]
        sets.add(tuple(books))
    assert len(sets) >= 3


def test_a_lone_group_spreads_over_the_support_across_consecutive_seeds() -> None:
    """Twenty seeds put a lone stack in twenty places that keep their distance (an evenly spread sequence, not
    independent draws, which put two of twenty within 5 cm of each other more often than not)."""
    spots = []
    for seed in range(20):
        base = next(e for e in _program("a stack of four books", seed, context=False) if e[1] == "PLACE-ON-BASE")
        spots.append((base[3]["x"], base[3]["y"]))
    closest = min(((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) ** 0.5 for i, a in enumerate(spots) for b in spots[i + 1 :])
    assert closest >= 0.05
    assert max(abs(x) for x, _ in spots) > 0.15 and max(abs(y) for _, y in spots) > 0.1


def test_one_group_of_two_things_keeps_to_the_middle_of_a_large_table() -> None:
    """A stack of books with a mug beside it is one group: over twenty seeds it stands around the middle of the table,
    not always in the back half (it took one cell of a grid of two, the back one)."""
    spots = []
    for seed in range(20):
        program = _program("a stack of three books next to a mug", seed, context=False)
        base = next(e for e in program if e[1] == "PLACE-ON-BASE" and "x" in e[3])
        spots.append((base[3]["x"], base[3]["y"]))
    xs, ys = [x for x, _ in spots], [y for _, y in spots]
    assert abs(sum(xs) / len(xs)) < 0.08 and abs(sum(ys) / len(ys)) < 0.08, spots
    assert max(map(abs, xs)) <= 0.25 and max(map(abs, ys)) <= 0.17, spots  # the middle of a 1.2 x 0.8 m table


def test_a_drawn_book_row_leaves_room_for_the_rest_of_the_shelf() -> None:
    """A row of upright books of no said count stops short of the flat stack and the plant the prompt also asks
    for, whatever kinds of book the seed chose (the canonical row is as it was)."""
    shelf = Support(kind="shelf", size=(0.3, 0.9))
    prompt = "a shelf with rows of books standing upright, a few lying flat, and a small plant"
    catalogue = default_catalogue()
    for seed in range(10):
        declared = _declared(_program(prompt, seed, support=shelf, context=False))
        upright = [catalogue.resolve(d) for d in declared.values() if "upright" in catalogue.resolve(d).kind]
        assert len(upright) >= 8
        row = sum(a.size[1] + 0.003 for a in upright)
        assert row <= 0.9 - 0.2  # a flat book's width and a plant pot stay free
