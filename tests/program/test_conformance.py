"""Every registered predicate is realised: its effect has a handler in its solver's table, and its own example,
solved with physics, gives a scene where the predicate's physical fact holds.

A predicate added to the registry with no handler, or whose handler does not do what it says, fails here.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TypeVar

import numpy as np
import pytest
import shapely

from physcensis.errors import PhyscensisError
from physcensis.geometry.footprints import rotate
from physcensis.ids import GROUP_PREFIX, ROOT_ID, copy_member_id
from physcensis.program import check_program, parse_program, registry
from physcensis.program.registry import (
    ALL_AXES,
    PREDICATES,
    Axis,
    Effect,
    ParamType,
    PredicateSpec,
    Role,
    Solver,
    YawMode,
)
from physcensis.scene import PlacedObject, Support
from physcensis.solver import layout, pipeline
from physcensis.solver.objects import quaternion_yaw
from physcensis.solver.physical import PhysicalSolver
from physcensis.solver.pipeline import Solution, solve

SUPPORT = Support(kind="table", size=(1.2, 1.6))
# The objects an example relates its subject to stand at these spots, in a zigzag (so no two are mirror images).
OTHER_SPOTS = [(-0.3 + 0.1 * (k % 2), -0.45 + 0.3 * k) for k in range(4)]
SUBJECT_SPOT = (0.25, 0.3)  # a subject related only to the support stands here
GROUP_SPOTS = [(0.25, 0.0), (0.25, -0.45)]  # where groups (copied, or moved as a whole) are put
GROUP_MEMBERS = ("plate_9", "fork_9")  # the members of a group an example only refers to
GAP_M = 0.05  # a subject completed beside its target stands this far from it
TOLERANCE_M = 0.01  # what the physics check lets an object move
TOLERANCE_RAD = math.radians(3.0)
# Descriptions the catalogue resolves, by the category part of an id (`fork_0` -> fork).
DESCRIPTIONS = {
    "phone": "a smartphone",
    "laptop": "a laptop computer",
    "mouse": "a computer mouse",
    "keyboard": "a computer keyboard",
    "monitor": "a computer monitor",
    "glass": "a drinking glass",
    "plate": "a dinner plate",
    "fork": "a fork",
    "knife": "a table knife",
    "book": "a hardcover book",
    "jar": "a glass jar",
    "chair": "a chair",
    "lamp": "a desk lamp",
    "pen": "a pen",
    "cup": "a coffee mug",
    "notebook": "a spiral notebook",
    "pen_holder": "a pen holder",
    "vase": "a flower vase",
}
HANDLER_TABLES: dict[Solver, Any] = {
    Solver.SPATIAL: layout.SPATIAL_HANDLERS,
    Solver.GROUP: layout.GROUP_HANDLERS,
    Solver.PHYSICAL: pipeline.PHYSICAL_HANDLERS,
}


# -- (1) the handler tables ----------------------------------------------------------------------------------------


def test_every_predicate_has_a_handler_in_its_solvers_table() -> None:
    for spec in PREDICATES.values():
        assert spec.effect in HANDLER_TABLES[spec.solver], (
            f"{spec.name}: the {spec.solver} solver has no handler for effect {spec.effect}"
        )


def test_every_handler_is_used_by_a_predicate_of_its_solver() -> None:
    used = {(spec.solver, spec.effect) for spec in PREDICATES.values()}
    for solver, table in HANDLER_TABLES.items():
        for effect in table:
            assert (solver, effect) in used, f"the {solver} solver handles {effect}, which no predicate has"
    assert set(layout.SOLVER_ENTRIES) == set(Solver)


def covers(table: Any, keys: type[Effect] | type[YawMode], what: str) -> None:
    """Assert that `table` has an entry for every member of `keys` and for nothing else, naming what is missing."""
    missing, extra = set(keys) - set(table), set(table) - set(keys)
    assert not missing, f"{what} has no entry for {sorted(k.value for k in missing)}: add one"
    assert not extra, f"{what} has entries for {sorted(map(str, extra))}, which are not in {keys.__name__}"


def test_every_yaw_mode_has_its_rule_and_its_hint() -> None:
    covers(layout.YAW_RULES, YawMode, "the spatial solver's YAW_RULES (solver/layout.py)")
    covers(pipeline.YAW_HINTS, YawMode, "the physical solver's YAW_HINTS (solver/pipeline.py)")


def test_covers_names_what_is_missing() -> None:
    with pytest.raises(AssertionError, match=r"^YAW_RULES has no entry for \['toward'\]: add one"):
        covers({m: None for m in YawMode if m is not YawMode.TOWARD}, YawMode, "YAW_RULES")


# -- (2) every predicate's own example, solved with physics --------------------------------------------------------


@dataclass
class Example:
    """A program built around one predicate's example: what it is made of and where the example entry is."""

    spec: PredicateSpec
    entries: list[list[Any]] = field(default_factory=list)
    index: int = 0  # 1-based entry number of the example itself
    spots: dict[str, tuple[float, float]] = field(default_factory=dict)  # object or group -> its PLACE-ON-BASE x, y
    groups: dict[str, list[str]] = field(default_factory=dict)  # groups made before the example -> their members

    @property
    def subject(self) -> Any:
        return self.spec.example[0]

    @property
    def target(self) -> Any:
        return self.spec.example[2]

    @property
    def params(self) -> dict[str, Any]:
        return dict(self.spec.example[3])

    def add(self, *entry: Any) -> None:
        self.entries.append(list(entry))

    def stand(self, oid: str, spot: tuple[float, float], facing: str = "FACING-FRONT") -> None:
        """Declare an object standing at a spot of the support, facing front (or as asked)."""
        self.add(oid, description(oid))
        self.place(oid, spot)
        self.add(oid, facing, ROOT_ID, {})

    def place(self, ref: str, spot: tuple[float, float]) -> None:
        self.spots[ref] = spot
        self.add(ref, "PLACE-ON-BASE", ROOT_ID, {"x": spot[0], "y": spot[1]})


def description(oid: str) -> str:
    category = oid.rsplit("_", 1)[0]
    return DESCRIPTIONS.get(category, f"a {category.replace('_', ' ')}")


def named_ids(spec: PredicateSpec) -> tuple[list[str], list[str]]:
    """The objects and the groups the example names, in order (root and [category, count] items left out)."""
    subject, _, target, params = spec.example
    refs: list[Any] = [*(subject if isinstance(subject, list) else [subject])]
    refs += target if isinstance(target, list) else [target]
    refs += [
        params[p.name] for p in spec.params if p.type in (ParamType.REFERENCE, ParamType.OBJECT) and p.name in params
    ]
    names = list(dict.fromkeys(r for r in refs if isinstance(r, str) and r != ROOT_ID))
    return [n for n in names if not n.startswith(GROUP_PREFIX)], [n for n in names if n.startswith(GROUP_PREFIX)]


def build(spec: PredicateSpec) -> Example:
    """The example, with each object it names declared, the others standing apart, the groups it refers to made,
    and the axes the example leaves open for its subject completed with default rules."""
    example = Example(spec)
    objects, groups = named_ids(spec)
    new_group = example.subject if Role.NEW_GROUP in spec.subject else None
    for oid, spot in zip([o for o in objects if o != example.subject], OTHER_SPOTS, strict=False):
        example.stand(oid, spot)
    make_groups(example, [g for g in groups if g != new_group])
    completed = complete(example) if example.subject in objects else ([], [])
    if example.subject in objects:
        example.add(example.subject, description(example.subject))
    example.entries += completed[0]
    example.add(*[list(part) if isinstance(part, tuple) else part for part in spec.example])
    example.index = len(example.entries)
    example.entries += completed[1]
    if new_group is not None:  # a new group is moved apart from its members' own places
        example.place(new_group, GROUP_SPOTS[0])
    return example


def make_groups(example: Example, groups: list[str]) -> None:
    """The first group holds two objects facing left (so a group's own yaw is not 0); any other is a copy of it,
    moved apart."""
    if not groups:
        return
    for member, spot in zip(GROUP_MEMBERS, OTHER_SPOTS[-len(GROUP_MEMBERS) :], strict=True):
        example.stand(member, spot, "FACING-LEFT")
    example.add(groups[0], "GROUP", list(GROUP_MEMBERS), {})
    example.groups[groups[0]] = list(GROUP_MEMBERS)
    for group, spot in zip(groups[1:], GROUP_SPOTS, strict=False):
        example.add(group, "COPY-GROUP", groups[0], {})
        example.place(group, spot)
        example.groups[group] = [copy_member_id(m, group) for m in GROUP_MEMBERS]


def complete(example: Example) -> tuple[list[list[Any]], list[list[Any]]]:
    """Default rules for the subject's axes the example leaves open, before and after the example: it stands on the
    support, beside its target (left of it, centred front to back, or in front of it when only x is open) or at its
    own spot when the target is the support, and faces front."""
    missing = open_axes(example.spec, example.params)
    subject, target = example.subject, example.target
    beside = isinstance(target, str) and target != ROOT_ID
    before: list[list[Any]] = []
    if Axis.HEIGHT in missing:
        where = (
            {}
            if beside
            else {
                name: value
                for name, value, axis in zip("xy", SUBJECT_SPOT, (Axis.X, Axis.Y), strict=True)
                if axis in missing
            }
        )
        before.append([subject, "PLACE-ON-BASE", ROOT_ID, where])
    if beside and Axis.Y in missing:
        before.append([subject, "LEFT-OF", target, {"distance": GAP_M}])
    if beside and Axis.X in missing:
        before.append(
            [subject, "ALIGN-CENTER-FB", target, {}]
            if Axis.Y in missing
            else [subject, "FRONT-OF", target, {"distance": GAP_M}]
        )
    after = [[subject, "FACING-FRONT", ROOT_ID, {}]] if Axis.YAW in missing else []
    return before, after


def open_axes(spec: PredicateSpec, params: dict[str, Any]) -> frozenset[Axis]:
    """The subject's axes the example leaves undetermined."""
    if spec.placement is not None and spec.placement.decides_everything:
        return frozenset()
    return ALL_AXES - spec.axes_determined(params)


def solved(example: Example) -> Solution:
    program = parse_program({"support": SUPPORT.model_dump(), "program": example.entries})
    report = check_program(program)
    assert report.ok, f"{example.spec.name}: the built program does not check:\n{report.feedback()}"
    solution = solve(program, seed=0)
    failed = {o.id: o.reason for o in solution.scene.objects if o.status != "placed"}
    assert not failed, f"{example.spec.name}: {failed}"
    return solution


# -- the facts -------------------------------------------------------------------------------------------------------


def footprint(solution: Solution, oid: str) -> shapely.Polygon:
    obj = solution.scene.object(oid)
    hull = solution.assets[oid].footprint()
    return shapely.Polygon(rotate(hull, np.array([quaternion_yaw(obj.quaternion)]))[0] + obj.position[:2])


def box(solution: Solution, example: Example, ref: str) -> tuple[float, float, float, float]:
    """(min_x, max_x, min_y, max_y) of an object, a group or the support, as the scene ends."""
    if ref == ROOT_ID:
        hx, hy = SUPPORT.half_extents
        return -hx, hx, -hy, hy
    members = example.groups.get(ref, [ref])
    min_x, min_y, max_x, max_y = shapely.union_all([footprint(solution, m) for m in members]).bounds
    return min_x, max_x, min_y, max_y


def centre(b: tuple[float, float, float, float]) -> np.ndarray:
    return np.array([(b[0] + b[1]) / 2, (b[2] + b[3]) / 2])


def yaw_of(solution: Solution, example: Example, ref: str) -> float:
    """An object's yaw; a group's is its first member's (its anchor's)."""
    return quaternion_yaw(solution.scene.object(example.groups.get(ref, [ref])[0]).quaternion)


def turn_between(a: float, b: float) -> float:
    return abs((a - b + math.pi) % (2 * math.pi) - math.pi)


def chosen(solution: Solution, example: Example, name: str) -> float:
    """A parameter of the example entry as the solver left it (it may fine-tune it), or its default."""
    value = (solution.spatial.params if solution.spatial else {}).get(example.index, {}).get(name)
    if value is None:
        value = example.params.get(name)
    param = example.spec.param(name)
    return float(value if value is not None else (param.default if param and param.default is not None else 0.0))


def edge_holds(solution: Solution, example: Example) -> None:
    rule = example.spec.edge_rule()
    rows = {"x": (0, 1), "y": (2, 3)}[rule.axis]
    a, b = box(solution, example, example.subject), box(solution, example, example.target)
    edge = {
        "min": lambda bx: bx[rows[0]],
        "max": lambda bx: bx[rows[1]],
        "center": lambda bx: (bx[rows[0]] + bx[rows[1]]) / 2,
    }
    wanted = edge[rule.b_edge](b) + rule.direction * chosen(solution, example, "distance")
    assert edge[rule.a_edge](a) == pytest.approx(wanted, abs=TOLERANCE_M)
    if rule.direction:  # A lies wholly on its side of B (LEFT-OF: A.min_y >= B.max_y)
        assert rule.direction * (edge[rule.a_edge](a) - edge[rule.b_edge](b)) >= -TOLERANCE_M


def symmetry_holds(solution: Solution, example: Example) -> None:
    a, b = box(solution, example, example.subject), box(solution, example, example.target)
    c = box(solution, example, example.params["C"])
    assert np.allclose(centre(a), 2 * centre(c) - centre(b), atol=TOLERANCE_M)


def stands_on_the_support(solution: Solution, example: Example) -> None:
    obj = solution.scene.object(example.subject)
    assert obj.position[2] == pytest.approx(SUPPORT.top_height, abs=TOLERANCE_M)
    wanted = [example.params.get(axis) for axis in "xy"]
    got = centre(box(solution, example, example.subject))
    for value, at in zip(wanted, got, strict=True):
        if value is not None:
            assert at == pytest.approx(value, abs=TOLERANCE_M)


def yaw_holds(solution: Solution, example: Example) -> None:
    rule = example.spec.yaw_rule()
    yaw = yaw_of(solution, example, example.subject)
    offset = chosen(solution, example, "yaw_offset") if example.spec.param("yaw_offset") else 0.0
    wanted = fact_of(YAW_FACTS, rule.mode)(solution, example, rule.angle)
    if wanted is not None:
        assert turn_between(yaw, wanted + offset) <= TOLERANCE_RAD, (yaw, wanted + offset)


def _absolute(solution: Solution, example: Example, angle: float) -> float | None:
    return angle


def _toward(solution: Solution, example: Example, angle: float) -> float | None:
    dx, dy = centre(box(solution, example, example.target)) - centre(box(solution, example, example.subject))
    return math.atan2(dy, dx)


def _same(solution: Solution, example: Example, angle: float) -> float | None:
    return yaw_of(solution, example, example.target)


def _opposite(solution: Solution, example: Example, angle: float) -> float | None:
    return yaw_of(solution, example, example.target) + math.pi


def _random(solution: Solution, example: Example, angle: float) -> float | None:
    """A seeded draw: the scene keeps the layout's yaw, and another seed draws another."""
    yaw = yaw_of(solution, example, example.subject)
    assert solution.spatial is not None
    assert turn_between(yaw, solution.spatial.poses[example.subject].yaw) <= TOLERANCE_RAD
    program = parse_program({"support": SUPPORT.model_dump(), "program": example.entries})
    other = solve(program, seed=1, physics=False).scene.object(example.subject)
    assert turn_between(yaw, quaternion_yaw(other.quaternion)) > TOLERANCE_RAD
    return None


def _relative_side(solution: Solution, example: Example, angle: float) -> float | None:
    """Of its yaw and a quarter turn more, the one that lines A's box up better with B's."""
    b = box(solution, example, example.target)

    def lined_up(turn: float) -> float:
        shape = shapely.affinity.rotate(footprint(solution, example.subject), turn, use_radians=True)
        min_x, min_y, max_x, max_y = shape.bounds
        return max(0.0, min(max_x, b[1]) - max(min_x, b[0])) + max(0.0, min(max_y, b[3]) - max(min_y, b[2]))

    assert lined_up(0.0) >= lined_up(math.pi / 2) - TOLERANCE_M
    return None


YAW_FACTS: dict[YawMode, Callable[[Solution, Example, float], float | None]] = {
    YawMode.ABSOLUTE: _absolute,
    YawMode.TOWARD: _toward,
    YawMode.SAME: _same,
    YawMode.OPPOSITE: _opposite,
    YawMode.RANDOM: _random,
    YawMode.RELATIVE_SIDE: _relative_side,
}


def rests_on_the_target(solution: Solution, example: Example) -> None:
    obj, target = solution.scene.object(example.subject), solution.scene.object(example.target)
    assert footprint(solution, example.target).buffer(TOLERANCE_M).contains(shapely.Point(obj.position[:2]))
    top = target.position[2] + solution.assets[example.target].size[2]
    assert obj.position[2] == pytest.approx(top, abs=TOLERANCE_M)
    assert obj.placement is not None and obj.placement.target == example.target


def inside_the_container(solution: Solution, example: Example) -> None:
    items = [
        o
        for o in solution.scene.objects
        if o.placement and o.placement.target == example.target and o.placement.predicate == example.spec.name
    ]
    wanted = sum(n for _, n in example.subject if isinstance(n, int))
    assert len(items) == wanted
    container = solution.scene.object(example.target)
    cavity = solution.assets[example.target].cavity
    assert cavity is not None
    opening = footprint(solution, example.target)
    for item in items:
        assert opening.buffer(TOLERANCE_M).contains(shapely.Point(item.position[:2])), item.id
        assert container.position[2] - TOLERANCE_M <= item.position[2] <= container.position[2] + cavity.rim_height


def rests_somewhere(solution: Solution, example: Example) -> None:
    obj = solution.scene.object(example.subject)
    hx, hy = SUPPORT.half_extents
    assert abs(obj.position[0]) <= hx and abs(obj.position[1]) <= hy
    assert obj.position[2] >= SUPPORT.top_height - TOLERANCE_M


def moves_as_one(solution: Solution, example: Example) -> None:
    """The group's members keep their places relative to each other where the group is put."""
    members = list(example.target)
    home = {m: np.array(example.spots[m]) for m in members}
    placed = {m: np.array(solution.scene.object(m).position[:2]) for m in members}
    shift = placed[members[0]] - home[members[0]]
    assert np.linalg.norm(shift) > 0.1  # the group did move
    for m in members:
        assert np.allclose(placed[m] - home[m], shift, atol=TOLERANCE_M), m
    assert np.allclose(_bounds_centre(solution, members), example.spots[example.subject], atol=TOLERANCE_M)


def _bounds(solution: Solution, members: list[str]) -> tuple[float, float, float, float]:
    min_x, min_y, max_x, max_y = shapely.union_all([footprint(solution, m) for m in members]).bounds
    return min_x, max_x, min_y, max_y


def copies_with_the_same_pose(solution: Solution, example: Example) -> None:
    """Each member has a copy, and the copies stand to each other as the members do (moved and turned as one)."""
    members = example.groups[example.target]
    copies = [copy_member_id(m, example.subject) for m in members]
    for member, copy in zip(members, copies, strict=True):
        assert solution.scene.object(copy).asset == solution.scene.object(member).asset
    anchor, anchor_copy = solution.scene.object(members[0]), solution.scene.object(copies[0])
    for member, copy in zip(members, copies, strict=True):
        assert np.allclose(
            _relative(solution.scene.object(member), anchor),
            _relative(solution.scene.object(copy), anchor_copy),
            atol=TOLERANCE_M,
        )
    assert np.allclose(_bounds_centre(solution, copies), example.spots[example.subject], atol=TOLERANCE_M)


def _relative(obj: PlacedObject, anchor: PlacedObject) -> np.ndarray:
    yaw = quaternion_yaw(anchor.quaternion)
    c, s = math.cos(-yaw), math.sin(-yaw)
    dx, dy = np.subtract(obj.position[:2], anchor.position[:2])
    return np.array([c * dx - s * dy, s * dx + c * dy, turn_between(quaternion_yaw(obj.quaternion), yaw)])


def _bounds_centre(solution: Solution, ids: list[str]) -> np.ndarray:
    return centre(_bounds(solution, ids))


FACTS: dict[Effect, Callable[[Solution, Example], None]] = {
    Effect.EDGE: edge_holds,
    Effect.SYMMETRY: symmetry_holds,
    Effect.BASE: stands_on_the_support,
    Effect.YAW: yaw_holds,
    Effect.ON: rests_on_the_target,
    Effect.IN: inside_the_container,
    Effect.ANYWHERE: rests_somewhere,
    Effect.GROUP: moves_as_one,
    Effect.COPY_GROUP: copies_with_the_same_pose,
}


Fact = TypeVar("Fact")


def fact_of(facts: Mapping[Any, Fact], key: Effect | YawMode) -> Fact:
    """The fact this test checks for an effect or a yaw mode; a clear failure when it has none yet."""
    if key not in facts:
        table = "FACTS" if isinstance(key, Effect) else "YAW_FACTS"
        pytest.fail(f"{type(key).__name__} {key.value} has no fact in {table} (tests/program/test_conformance.py)")
    return facts[key]


def test_a_missing_fact_is_a_clear_failure() -> None:
    with pytest.raises(pytest.fail.Exception, match=r"^YawMode toward has no fact in YAW_FACTS"):
        fact_of({}, YawMode.TOWARD)


def test_every_effect_and_yaw_mode_has_a_fact_checked_here() -> None:
    covers(FACTS, Effect, "FACTS (tests/program/test_conformance.py)")
    covers(YAW_FACTS, YawMode, "YAW_FACTS (tests/program/test_conformance.py)")


@pytest.mark.physics
@pytest.mark.parametrize("name", list(PREDICATES))
def test_the_example_of_every_predicate_solves_and_its_fact_holds(name: str) -> None:
    example = build(PREDICATES[name])
    fact_of(FACTS, example.spec.effect)(solved(example), example)


# -- (3) a predicate no solver handles -----------------------------------------------------------------------------


def _register(monkeypatch: pytest.MonkeyPatch, spec: PredicateSpec) -> None:
    monkeypatch.setitem(registry._BY_KEY, registry._key(spec.name), spec)


def test_a_predicate_whose_effect_no_spatial_handler_takes_is_a_clear_error(monkeypatch: pytest.MonkeyPatch) -> None:
    spec = PredicateSpec(
        name="MIRROR-OF",
        effect=Effect.SYMMETRY,
        summary="A mirrors B through C",
        formula="A.center = 2 * C.center - B.center",
        subject=PREDICATES["SYMMETRY-ALONG"].subject,
        target=PREDICATES["SYMMETRY-ALONG"].target,
        params=PREDICATES["SYMMETRY-ALONG"].params,
        determines=frozenset({Axis.X, Axis.Y}),
    )
    _register(monkeypatch, spec)
    monkeypatch.setattr(
        layout, "SPATIAL_HANDLERS", {e: h for e, h in layout.SPATIAL_HANDLERS.items() if e is not Effect.SYMMETRY}
    )
    program = [
        ["plate_0", "a dinner plate"],
        ["plate_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
        ["plate_0", "FACING-FRONT", "root", {}],
        ["fork_0", "a fork"],
        ["fork_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.3}],
        ["fork_0", "FACING-FRONT", "root", {}],
        ["knife_0", "a table knife"],
        ["knife_0", "PLACE-ON-BASE", "root", {}],
        ["knife_0", "MIRROR-OF", "fork_0", {"C": "plate_0"}],
        ["knife_0", "FACING-FRONT", "root", {}],
    ]
    assert check_program(parse_program(program)).ok  # the checker reads it from the registry like any other
    with pytest.raises(PhyscensisError, match=r"^no spatial solver handles predicate MIRROR-OF \(effect symmetry\)$"):
        solve(program, physics=False)


def test_a_physical_predicate_without_a_handler_is_refused_before_any_placement(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(
        pipeline, "PHYSICAL_HANDLERS", {e: h for e, h in pipeline.PHYSICAL_HANDLERS.items() if e is not Effect.ANYWHERE}
    )
    placed: list[str] = []
    monkeypatch.setattr(PhysicalSolver, "place", lambda solver, request: placed.append(request.object_id))
    program = [
        ["book_0", "a hardcover book"],
        ["book_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
        ["book_0", "FACING-FRONT", "root", {}],
        ["cup_0", "a coffee mug"],
        ["cup_0", "PLACE-ON", "book_0", {}],
        ["vase_0", "a flower vase"],
        ["vase_0", "PLACE-ANYWHERE", "root", {}],
    ]
    with pytest.raises(
        PhyscensisError,
        match=r"^no physical solver handles predicate PLACE-ANYWHERE "
        r"\(effect anywhere\)$",
    ):
        solve(program)
    assert placed == []  # not even the cup that comes first


def test_a_yaw_mode_without_a_rule_is_a_clear_error(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(layout, "YAW_RULES", {m: r for m, r in layout.YAW_RULES.items() if m is not YawMode.TOWARD})
    program = [
        ["fork_0", "a fork"],
        ["fork_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.3}],
        ["fork_0", "FACING-FRONT", "root", {}],
        ["plate_0", "a dinner plate"],
        ["plate_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
        ["plate_0", "FACING-TO", "fork_0", {}],
    ]
    with pytest.raises(PhyscensisError, match=r"^no spatial solver handles predicate FACING-TO \(yaw mode toward\)$"):
        solve(program, physics=False)


def test_code_that_writes_programs_takes_its_predicate_names_from_the_registry() -> None:
    from physcensis.agent import planner
    from physcensis.agent.planning import entries
    from physcensis.program.registry import registered

    assert registered("LEFT-OF", "PLACE-IN") == ("LEFT-OF", "PLACE-IN")
    with pytest.raises(PhyscensisError, match="not registered predicates: LEFT-OFF"):
        registered("LEFT-OF", "LEFT-OFF")
    names = Path(entries.__file__)  # the planner's one list of the predicates it writes with
    for path in [Path(planner.__file__), *sorted(names.parent.glob("*.py"))]:
        source = path.read_text()
        written = set(re.findall(r'"([A-Z]+(?:-[A-Z]+)+)"', source))
        assert written <= set(PREDICATES), (path.name, written - set(PREDICATES))
        first_use = (
            source.index("registered(\n") + source[source.index("registered(\n") :].index(")") if path == names else 0
        )
        assert not re.search(r'"[A-Z]+(?:-[A-Z]+)+"', source[first_use:]), f"{path.name} spells a predicate out again"
