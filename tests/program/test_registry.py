from __future__ import annotations

import pytest

from physcensis.errors import PhyscensisError
from physcensis.program.registry import (
    ALL_AXES,
    PREDICATES,
    Axis,
    EdgeRule,
    Effect,
    PlacementKind,
    PredicateSpec,
    Role,
    Solver,
    YawMode,
    YawRule,
    closest_name,
    lookup,
    placement_names,
    placement_spec,
)

DESIGN_NAMES = {
    "LEFT-OF",
    "RIGHT-OF",
    "FRONT-OF",
    "BACK-OF",
    "ALIGN-CENTER-LR",
    "ALIGN-CENTER-FB",
    "ALIGN-LEFT",
    "ALIGN-RIGHT",
    "ALIGN-FRONT",
    "ALIGN-BACK",
    "SYMMETRY-ALONG",
    "FACING-FRONT",
    "FACING-BACK",
    "FACING-LEFT",
    "FACING-RIGHT",
    "FACING-TO",
    "FACING-SAME-AS",
    "FACING-OPPOSITE-TO",
    "RANDOM-ROT",
    "ORIENT-BY-RELATIVE-SIDE",
    "PLACE-ON-BASE",
    "PLACE-ON",
    "PLACE-IN",
    "PLACE-ANYWHERE",
    "GROUP",
    "COPY-GROUP",
}


def test_registry_has_exactly_the_predicates_of_the_design() -> None:
    assert set(PREDICATES) == DESIGN_NAMES


def test_lookup_ignores_case_dashes_and_underscores() -> None:
    for raw in ("place_on", "Place-On", "PLACEON", " place on "):
        spec = lookup(raw)
        assert spec is not None and spec.name == "PLACE-ON"


def test_closest_name_suggests_a_fix() -> None:
    assert closest_name("LEFT_OFF") == "LEFT-OF"
    assert closest_name("facing-frnt") == "FACING-FRONT"


def test_every_spec_is_consistent() -> None:
    for spec in PREDICATES.values():
        assert spec.summary and spec.formula and spec.example, spec.name
        assert spec.example[1] == spec.name
        if spec.edge is not None:
            assert spec.determines == frozenset({Axis(spec.edge.axis)})
            assert (spec.param("distance") is not None) == (spec.edge.direction != 0)
        if spec.yaw is not None:
            assert spec.determines == frozenset({Axis.YAW})
        if spec.solver is Solver.GROUP:
            assert Role.NEW_GROUP in spec.subject
        if spec.placement is not None and spec.placement.decides_everything:
            assert spec.determines == ALL_AXES, spec.name
        for p in spec.params:
            if p.optimisable:
                assert p.low is not None and p.high is not None


def test_place_on_base_determines_x_and_y_only_when_given() -> None:
    spec = PREDICATES["PLACE-ON-BASE"]
    assert spec.axes_determined({}) == {Axis.HEIGHT}
    assert spec.axes_determined({"x": 0.1}) == {Axis.HEIGHT, Axis.X}
    assert spec.axes_determined({"x": 0.1, "y": 0.0}) == {Axis.HEIGHT, Axis.X, Axis.Y}


def test_each_placement_has_exactly_one_predicate_in_the_papers_order() -> None:
    placements = [spec.placement for spec in PREDICATES.values() if spec.placement is not None]
    assert sorted(placements) == sorted(PlacementKind)
    assert {p: placement_spec(p).name for p in PlacementKind} == {
        PlacementKind.BASE: "PLACE-ON-BASE",
        PlacementKind.ON: "PLACE-ON",
        PlacementKind.IN: "PLACE-IN",
        PlacementKind.ANYWHERE: "PLACE-ANYWHERE",
    }
    assert [p.rank for p in PlacementKind] == [0, 1, 1, 2]
    assert [p.decides_everything for p in PlacementKind] == [False, True, True, True]
    assert placement_names(rank=1) == ["PLACE-ON", "PLACE-IN"] and placement_names(rank=2) == ["PLACE-ANYWHERE"]


def test_solver_placement_and_position_follow_from_the_effect() -> None:
    by_effect = {spec.effect: spec for spec in PREDICATES.values()}
    assert set(by_effect) == set(Effect)  # every effect is used by some predicate
    assert {e for e, s in by_effect.items() if s.solver is Solver.PHYSICAL} == {Effect.ON, Effect.IN, Effect.ANYWHERE}
    assert {e for e, s in by_effect.items() if s.solver is Solver.GROUP} == {Effect.GROUP, Effect.COPY_GROUP}
    assert {e for e, s in by_effect.items() if s.sets_position} == {Effect.EDGE, Effect.SYMMETRY, Effect.BASE}
    assert PREDICATES["LEFT-OF"].solver is Solver.SPATIAL and PREDICATES["LEFT-OF"].placement is None


def test_every_yaw_mode_is_used_and_only_relative_side_refines() -> None:
    modes = {spec.yaw.mode for spec in PREDICATES.values() if spec.yaw is not None}
    assert modes == set(YawMode)
    assert [m for m in YawMode if m.refines] == [YawMode.RELATIVE_SIDE]
    assert PREDICATES["RANDOM-ROT"].param("yaw_offset") is None
    assert PREDICATES["FACING-TO"].param("yaw_offset") is not None


@pytest.mark.parametrize(
    ("effect", "edge", "yaw"),
    [
        (Effect.EDGE, None, None),
        (Effect.YAW, None, None),
        (Effect.SYMMETRY, EdgeRule("x", "min", "max", 1), None),
        (Effect.EDGE, EdgeRule("x", "min", "max", 1), YawRule(YawMode.SAME)),
    ],
)
def test_a_rule_that_disagrees_with_the_effect_is_refused(
    effect: Effect, edge: EdgeRule | None, yaw: YawRule | None
) -> None:
    with pytest.raises(PhyscensisError, match="predicate FAKE: a `(edge|yaw)` rule goes with effect"):
        PredicateSpec(
            name="FAKE",
            effect=effect,
            summary="s",
            formula="f",
            subject=frozenset({Role.OBJECT}),
            target=frozenset({Role.OBJECT}),
            edge=edge,
            yaw=yaw,
        )
