"""Our own home prompt suite is well formed (fast, no solving), and the arrangement keys of its `expect` blocks
(inside, on, stacks, rows, around) judge hand-built scenes the way a reader of the sentence would."""

from __future__ import annotations

import math
from collections import Counter
from typing import Any

import pytest

from physcensis.assets import default_catalogue
from physcensis.bench.arrangement import check_arrangements
from physcensis.bench.prompt_suite import HOME_SUITE, SUITES, load_suite
from physcensis.program.registry import PlacementKind, placement_spec
from physcensis.scene import SUPPORT_KINDS, PlacedObject, Placement, Scene, Support
from physcensis.solver.objects import yaw_quaternion

HOME = load_suite(HOME_SUITE)
KNOWN_KEYS = {"min_objects", "categories", "relations", "stack_height", "fragile", "inside", "on", "stacks", "rows"}
KNOWN_KEYS |= {"around", "evenly_spaced", "regions"}
SUPPORT_WORDS = {"table", "desk", "counter", "shelf", "box", "floor"}


def test_the_home_suite_is_large_and_its_ids_unique() -> None:
    ids = [case["id"] for case in HOME]
    assert len(ids) >= 60
    assert len(set(ids)) == len(ids), [i for i, n in Counter(ids).items() if n > 1]
    assert SUITES["home"] == HOME_SUITE
    assert len({case["prompt"] for case in HOME}) == len(HOME)


def test_the_home_suite_shares_no_sentence_with_the_public_one() -> None:
    public = {case["prompt"] for case in load_suite(SUITES["public"])}
    assert not public & {case["prompt"] for case in HOME}


@pytest.mark.parametrize("case", HOME, ids=[c["id"] for c in HOME])
def test_home_case_is_well_formed(case: dict[str, Any]) -> None:
    assert set(case) == {"id", "prompt", "support", "expect"}
    Support(kind=case["support"]["kind"], size=tuple(case["support"]["size"]))  # raises when invalid
    expect = case["expect"]
    assert set(expect) <= KNOWN_KEYS, set(expect) - KNOWN_KEYS
    assert expect["min_objects"] >= 1
    counts = expect.get("categories", {})
    assert counts and all(isinstance(n, int) and n > 0 for n in counts.values())
    assert sum(counts.values()) <= expect["min_objects"]
    for item, holder, n in [*expect.get("inside", []), *expect.get("on", []), *expect.get("around", [])]:
        assert n > 0 and counts.get(item, 0) >= n and counts.get(holder, 0) >= 1, (item, holder, n)
    for category, sizes in [*expect.get("stacks", {}).items(), *expect.get("rows", {}).items()]:
        assert sizes and all(s > 0 for s in sizes) and counts.get(category, 0) >= sum(sizes), category


def test_every_category_named_by_the_home_suite_is_in_the_catalogue() -> None:
    categories = set(default_catalogue().categories())
    named: set[str] = set()
    for case in HOME:
        expect = case["expect"]
        named |= set(expect.get("categories", {}))
        for item, holder, _ in [*expect.get("inside", []), *expect.get("on", []), *expect.get("around", [])]:
            named |= {item, holder}
    assert named - categories == set()


def test_every_container_the_home_suite_fills_has_a_cavity() -> None:
    """`inside` asks for items resting in a container's cavity: some asset of each holder category must have one."""
    catalogue = default_catalogue()
    holders = {holder for case in HOME for _, holder, _ in case["expect"].get("inside", [])}
    hollow = {
        holder
        for holder in holders
        if any(catalogue.get(e.id).cavity is not None for e in catalogue.entries() if e.category == holder)
    }
    assert holders - hollow == set()


def test_the_home_suite_covers_every_support_kind_and_the_issue_classes() -> None:
    kinds = Counter(case["support"]["kind"] for case in HOME)
    assert set(kinds) == set(SUPPORT_KINDS)
    keys = Counter(key for case in HOME for key in case["expect"])
    assert all(keys[key] >= 3 for key in ("inside", "on", "stacks", "rows", "around"))
    text = " ".join(case["prompt"] for case in HOME)
    phrasings = ["full of", "filled with", "holding", "carrying", "on it", "loaded with", "containing", "inside"]
    phrasings += ["into", "a pile of", "rows of", "columns", "pairs", "side by side", "in a row", "lined up"]
    phrasings += ["evenly spaced", "around"]
    assert [p for p in phrasings if p not in text] == []


# --- the arrangement keys on hand-built scenes ---------------------------------------------------------------------

ON = placement_spec(PlacementKind.ON).name
IN = placement_spec(PlacementKind.IN).name


def _object(oid: str, query: str, xyz: tuple[float, float, float], on: tuple[str, str] | None = None) -> PlacedObject:
    asset = default_catalogue().resolve(query)
    placement = Placement(predicate=on[0], target=on[1]) if on else None
    return PlacedObject(
        id=oid,
        description=asset.description,
        asset=asset.id,
        category=asset.category,
        position=xyz,
        quaternion=yaw_quaternion(0.0),
        mass=asset.mass,
        friction=0.5,
        placement=placement,
    )


def _scene(*objects: PlacedObject) -> Scene:
    return Scene(support=Support(kind="table", size=(1.2, 1.2)), objects=list(objects))


def _check(scene: Scene, expect: dict[str, Any]) -> list[str]:
    catalogue = default_catalogue()
    return check_arrangements(scene, expect, lambda o: catalogue.asset_for(o.asset, o.description))


def test_inside_counts_items_in_the_cavity_or_placed_in_it() -> None:
    bowl = _object("bowl", "a ceramic bowl", (0.0, 0.0, 0.0))
    floor = default_catalogue().asset_for(bowl.asset, bowl.description).cavity
    assert floor is not None
    in_cavity = _object("a0", "a red apple", (0.01, 0.0, floor.floor_height + 0.002))  # resting in it, no placement
    placed_in = _object("a1", "a red apple", (-0.01, 0.0, 0.06), on=(IN, "bowl"))
    beside = _object("a2", "a red apple", (0.3, 0.0, 0.0))
    scene = _scene(bowl, in_cavity, placed_in, beside)
    assert _check(scene, {"inside": [["apple", "bowl", 2]]}) == []
    assert _check(scene, {"inside": [["apple", "bowl", 3]]}) == ["2 x apple in a bowl, expected at least 3"]


def test_on_follows_a_stack_down_to_the_carrier() -> None:
    tray = _object("tray", "a serving tray", (0.0, 0.0, 0.0))
    saucer = _object("saucer", "a saucer", (0.0, 0.0, 0.02), on=(ON, "tray"))
    cup = _object("cup", "a tea cup", (0.0, 0.0, 0.04), on=(ON, "saucer"))
    loose = _object("cup2", "a tea cup", (0.4, 0.0, 0.0))
    tray_asset = default_catalogue().asset_for(tray.asset, tray.description)
    corner = (tray_asset.size[0] / 2 - 0.01, tray_asset.size[1] / 2 - 0.01, 0.0)
    beside = _object("cup3", "a tea cup", corner)  # on the table, over the tray's bounding box but not on the tray
    scene = _scene(tray, saucer, cup, loose, beside)
    assert _check(scene, {"on": [["cup", "tray", 1], ["cup", "saucer", 1]]}) == []
    assert _check(scene, {"on": [["cup", "tray", 2]]}) == ["1 x cup on a tray, expected at least 2"]


def test_stacks_are_told_apart_by_their_bottoms() -> None:
    def stack(prefix: str, x: float, height: int) -> list[PlacedObject]:
        return [
            _object(f"{prefix}{i}", "a white dinner plate", (x, 0.0, 0.02 * i), (ON, f"{prefix}{i - 1}") if i else None)
            for i in range(height)
        ]

    scene = _scene(*stack("a", -0.3, 4), *stack("b", 0.3, 3))
    assert _check(scene, {"stacks": {"plate": [4, 3]}}) == []
    assert _check(scene, {"stacks": {"plate": [4, 4]}}) == ["stacks of plate [4, 3] high, expected [4, 4]"]
    assert _check(scene, {"stacks": {"plate": [3, 3, 1]}}) != []  # two stacks, not three


def test_a_nest_of_bowls_is_a_stack_but_apples_in_a_bowl_are_not() -> None:
    nest = [
        _object(f"n{i}", "a white cereal bowl", (0.0, 0.0, 0.03 * i), (IN, f"n{i - 1}") if i else None)
        for i in range(4)
    ]
    apples = [_object(f"a{i}", "a red apple", (0.3, 0.0, 0.02), (IN, "b")) for i in range(3)]
    scene = _scene(*nest, _object("b", "a white cereal bowl", (0.3, 0.0, 0.0)), *apples)
    assert _check(scene, {"stacks": {"bowl": [4]}}) == []
    assert _check(scene, {"stacks": {"apple": [2]}}) == ["stacks of apple [1, 1, 1] high, expected [2]"]


def test_rows_are_straight_lines_of_the_category() -> None:
    row = [_object(f"c{i}", "a tin can", (-0.3 + 0.15 * i, 0.2, 0.0)) for i in range(4)]
    second = [_object(f"d{i}", "a tin can", (-0.3 + 0.15 * i, -0.2, 0.0)) for i in range(3)]
    assert _check(_scene(*row, *second), {"rows": {"can": [4, 3]}}) == []
    scattered = [
        _object(f"s{i}", "a tin can", (0.3 * math.cos(2.4 * i), 0.3 * math.sin(2.4 * i), 0.0)) for i in range(4)
    ]
    assert _check(_scene(*scattered), {"rows": {"can": [4]}}) != []


def test_evenly_spaced_rows_have_equal_gaps() -> None:
    even = [_object(f"c{i}", "a white candle", (-0.45 + 0.3 * i, 0.0, 0.0)) for i in range(4)]
    assert _check(_scene(*even), {"rows": {"candle": [4]}, "evenly_spaced": ["candle"]}) == []
    bunched = [_object(f"c{i}", "a white candle", (x, 0.0, 0.0)) for i, x in enumerate((-0.45, -0.35, -0.25, 0.45))]
    assert _check(_scene(*bunched), {"rows": {"candle": [4]}}) == []
    assert _check(_scene(*bunched), {"evenly_spaced": ["candle"]}) == [
        "candle not evenly spaced (gaps [0.1, 0.1, 0.7] m)"
    ]


def test_around_needs_items_on_more_than_one_side() -> None:
    teapot = _object("pot", "a teapot", (0.0, 0.0, 0.0))
    ring = [
        _object(f"c{i}", "a tea cup", (0.2 * math.cos(i * math.pi / 2), 0.2 * math.sin(i * math.pi / 2), 0.0))
        for i in range(4)
    ]
    assert _check(_scene(teapot, *ring), {"around": [["cup", "teapot", 4]]}) == []
    one_side = [_object(f"c{i}", "a tea cup", (0.2, -0.15 + 0.1 * i, 0.0)) for i in range(4)]
    assert _check(_scene(teapot, *one_side), {"around": [["cup", "teapot", 4]]}) == [
        "0 x cup around a teapot, expected at least 4"
    ]


def test_sides_are_read_as_the_viewer_of_the_default_render_sees_them() -> None:
    laptop = _object("laptop", "a laptop", (0.0, 0.0, 0.0))
    notebook = _object("notebook", "a notebook", (0.25, 0.0, 0.0))  # +x: nearer the viewer
    pen = _object("pen", "a pen", (0.25, 0.2, 0.0))  # +y: the viewer's right
    scene = _scene(laptop, notebook, pen)
    assert _check(scene, {"sides": [["notebook", "front", "laptop"], ["pen", "right", "notebook"]]}) == []
    assert _check(scene, {"sides": [["laptop", "behind", "notebook"], ["notebook", "left", "pen"]]}) == []
    assert _check(scene, {"sides": [["pen", "left", "notebook"]]}) == [
        "no pen to the left of a notebook (as the viewer sees it)"
    ]
    # more in front than to the right: in front of the laptop, not to its right
    assert _check(scene, {"sides": [["notebook", "right", "laptop"]]}) != []


def test_between_needs_the_subject_on_the_line_joining_the_two() -> None:
    candles = [_object(f"c{i}", "a white candle", (0.0, y, 0.0)) for i, y in enumerate((-0.3, 0.3))]
    vase = _object("vase", "a glass vase", (0.05, 0.02, 0.0))
    assert _check(_scene(*candles, vase), {"between": [["vase", "candle", "candle"]]}) == []
    aside = _object("vase", "a glass vase", (0.05, 0.45, 0.0))
    assert _check(_scene(*candles, aside), {"between": [["vase", "candle", "candle"]]}) == [
        "no vase between a candle and a candle"
    ]


def test_a_place_on_the_support_is_where_the_viewer_sees_it_and_reaches_its_edge() -> None:
    # the table is 1.2 m square: halves of 0.6 m; front +x, the viewer's left -y
    vase = _object("vase", "a glass vase", (0.45, -0.45, 0.0))  # front left, near both edges
    assert _check(_scene(vase), {"regions": [["vase", "front", "left", "corner"], ["vase", "edge"]]}) == []
    assert _check(_scene(vase), {"regions": [["vase", "left"], ["vase", "end"], ["vase", "corner"]]}) == []
    assert _check(_scene(vase), {"regions": [["vase", "back", "corner"]]}) == [
        "no vase back corner on the support (as the viewer sees it)"
    ]
    assert _check(_scene(vase), {"regions": [["vase", "right"]]}) != []
    middle = _object("vase", "a glass vase", (0.1, 0.05, 0.0))
    assert _check(_scene(middle), {"regions": [["vase", "edge"]]}) != []
    # a large thing near an edge reaches into the edge's band though its centre does not
    box = _object("box", "a large open green toolbox", (0.3, 0.0, 0.0))  # 0.55 m deep: its front at 0.575
    assert _check(_scene(box), {"regions": [["box", "front"]]}) == []


def test_the_reading_suite_is_large_covers_its_classes_and_names_catalogue_categories() -> None:
    cases = load_suite(SUITES["reading"])
    assert len(cases) >= 60 and len({c["id"] for c in cases}) == len(cases)
    classes = Counter(c["class"] for c in cases)
    assert set(classes) == {"head-noun", "contents", "carrier", "distribution", "sides", "between", "stacks-and-lids",
                            "counts", "places"} and min(classes.values()) >= 8  # fmt: skip
    known = set(default_catalogue().categories())
    for case in cases:
        expect = case["expect"]
        named = {*expect.get("categories", {}), *expect.get("max_categories", {})}
        named |= {x for key in ("sides", "between") for row in expect.get(key, []) for x in row if x not in SIDES}
        named |= {x for key in ("inside", "on") for row in expect.get(key, []) for x in row[:2]}
        named |= {row[0] for row in expect.get("relations", [])} | {row[2] for row in expect.get("relations", [])}
        assert named <= known, (case["id"], named - known)


SIDES = {"left", "right", "front", "behind"}


def test_max_categories_bounds_what_must_not_be_there() -> None:
    from physcensis.bench.prompt_suite import check_expectations

    jugs = [_object(k, "a glass water pitcher", (0.3 * n, 0.0, 0.0)) for n, k in enumerate("jk")]
    category = jugs[0].category
    assert f"2 x {category}, expected at most 1" in check_expectations(_scene(*jugs), {"max_categories": {category: 1}})
    assert not any("at most" in p for p in check_expectations(_scene(*jugs), {"max_categories": {category: 2}}))
