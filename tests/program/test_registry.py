from __future__ import annotations

import inspect
import sys
import types

import pytest

from physcensis.errors import PhyscensisError
from physcensis.program import registry
from physcensis.program.registry import (
    ALIGNING_SECTION,
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
    effect_spec,
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


def test_registry_has_every_predicate_of_the_design() -> None:
    """The paper's predicates are all registered (a new one is an entry in the registry alone)."""
    assert DESIGN_NAMES <= set(PREDICATES), f"not registered: {sorted(DESIGN_NAMES - set(PREDICATES))}"


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


def test_each_placement_kind_has_exactly_one_predicate() -> None:
    placements = [spec.placement for spec in PREDICATES.values() if spec.placement is not None]
    assert sorted(placements) == sorted(PlacementKind)
    for kind in PlacementKind:
        assert placement_spec(kind).placement is kind
        assert placement_spec(kind).effect.info.placement is kind


def test_placement_ranks_follow_the_papers_order() -> None:
    """Spatial placements first, then PLACE-ON and PLACE-IN together, and PLACE-ANYWHERE last."""
    ranks = sorted({kind.rank for kind in PlacementKind})
    assert ranks == list(range(len(ranks)))  # 0, 1, 2, ...: no gaps
    assert PlacementKind.BASE.rank == 0
    assert PlacementKind.BASE.rank < PlacementKind.ON.rank == PlacementKind.IN.rank < PlacementKind.ANYWHERE.rank
    assert PlacementKind.ANYWHERE.rank == ranks[-1]
    for rank in ranks:  # the names of one rank, in registry order
        kinds = [spec.placement for spec in PREDICATES.values() if spec.placement is not None]
        assert placement_names(rank=rank) == [placement_spec(kind).name for kind in kinds if kind.rank == rank]
    on, in_ = placement_spec(PlacementKind.ON).name, placement_spec(PlacementKind.IN).name
    middle = placement_names(rank=PlacementKind.ON.rank)
    assert on in middle and in_ in middle and middle.index(on) < middle.index(in_)
    assert placement_spec(PlacementKind.ANYWHERE).name in placement_names(rank=PlacementKind.ANYWHERE.rank)


def test_a_placement_decides_everything_exactly_when_the_physical_solver_realises_it() -> None:
    for kind in PlacementKind:
        spec = placement_spec(kind)
        assert kind.decides_everything == (spec.solver is Solver.PHYSICAL), kind
        assert kind.decides_everything == (kind.rank > 0), kind  # only the spatial placement comes first


def test_solver_placement_and_position_follow_from_the_effect() -> None:
    by_effect: dict[Effect, list[PredicateSpec]] = {}
    for spec in PREDICATES.values():
        by_effect.setdefault(spec.effect, []).append(spec)
        assert (spec.solver, spec.placement, spec.sets_position) == (
            spec.effect.info.solver,
            spec.effect.info.placement,
            spec.effect.info.sets_position,
        )
    assert set(by_effect) == set(Effect), f"effects no predicate has: {set(Effect) - set(by_effect)}"
    for effect, specs in by_effect.items():
        if effect.info.placement is not None:  # a placing effect is the one predicate of its placement kind
            assert [s.name for s in specs] == [placement_spec(effect.info.placement).name], effect
    assert PREDICATES["LEFT-OF"].solver is Solver.SPATIAL and PREDICATES["LEFT-OF"].placement is None


def test_an_effect_sets_a_position_exactly_when_its_predicates_move_x_or_y_in_the_layout() -> None:
    for spec in PREDICATES.values():
        may_move = spec.determines | {axis for _, axis in spec.determines_when_given}
        moves_x_or_y = spec.solver is Solver.SPATIAL and bool(may_move & {Axis.X, Axis.Y})
        assert spec.sets_position == moves_x_or_y, spec.name


def test_the_physical_solver_realises_exactly_the_placements_that_decide_everything_and_groups_make_groups() -> None:
    for spec in PREDICATES.values():
        decides = spec.placement is not None and spec.placement.decides_everything
        assert (spec.solver is Solver.PHYSICAL) == decides, spec.name
        assert (spec.solver is Solver.GROUP) == (Role.NEW_GROUP in spec.subject), spec.name


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


def test_only_an_edge_rule_with_no_gap_has_its_own_prompt_section() -> None:
    for spec in PREDICATES.values():
        aligns = spec.edge is not None and spec.edge.direction == 0
        assert spec.section == (ALIGNING_SECTION if aligns else spec.effect.info.section), spec.name


def test_effect_spec_is_the_one_predicate_of_an_effect() -> None:
    assert effect_spec(Effect.GROUP).name == "GROUP" and effect_spec(Effect.COPY_GROUP).name == "COPY-GROUP"
    with pytest.raises(PhyscensisError, match=r"^effect edge has \d+ predicates, not exactly one$"):
        effect_spec(Effect.EDGE)


# -- what is refused when the registry module is imported ----------------------------------------------------------


def _import_edited_registry(monkeypatch: pytest.MonkeyPatch, old: str, new: str) -> types.ModuleType:
    """Import a copy of the registry module whose source has `old` replaced by `new`."""
    source = inspect.getsource(registry)
    assert old in source
    module = types.ModuleType("edited_registry")
    monkeypatch.setitem(sys.modules, module.__name__, module)  # dataclasses look their module up there
    exec(compile(source.replace(old, new, 1), str(registry.__file__), "exec"), module.__dict__)
    return module


_EDGE_ROW = '    EDGE = "edge", EffectInfo('
_BASE_KIND = '    BASE = "base", 0, False'


def test_an_unedited_copy_of_the_registry_imports(monkeypatch: pytest.MonkeyPatch) -> None:
    copy = _import_edited_registry(monkeypatch, _EDGE_ROW, _EDGE_ROW)
    assert set(copy.PREDICATES) == set(PREDICATES)


def test_an_effect_without_its_row_is_refused_at_import(monkeypatch: pytest.MonkeyPatch) -> None:
    with pytest.raises(PhyscensisError, match=r"^effect 'new' has no row: write it as NAME = 'new', EffectInfo\("):
        _import_edited_registry(monkeypatch, _EDGE_ROW, f'    NEW = "new"\n{_EDGE_ROW}')


def test_a_placement_kind_without_its_rank_is_refused_at_import(monkeypatch: pytest.MonkeyPatch) -> None:
    with pytest.raises(
        PhyscensisError, match=r"^placement kind 'new' needs its rank and whether it decides everything"
    ):
        _import_edited_registry(monkeypatch, _BASE_KIND, f'    NEW = "new"\n{_BASE_KIND}')


def test_a_placement_kind_without_its_predicate_is_refused_at_import(monkeypatch: pytest.MonkeyPatch) -> None:
    with pytest.raises(
        PhyscensisError, match=r"^every placement kind needs exactly one predicate; these do not: \{'new': \[\]\}$"
    ):
        _import_edited_registry(monkeypatch, _BASE_KIND, f'    NEW = "new", 3, True\n{_BASE_KIND}')


def test_a_placement_kind_with_two_predicates_is_refused_at_import(monkeypatch: pytest.MonkeyPatch) -> None:
    anywhere = '    ANYWHERE = "anywhere", EffectInfo(Solver.PHYSICAL, PHYSICAL_SECTION, PlacementKind.ANYWHERE)'
    twice = anywhere.replace("PlacementKind.ANYWHERE)", "PlacementKind.ON)")  # PLACE-ANYWHERE now places ON
    with pytest.raises(
        PhyscensisError, match=r"these do not: \{'on': \['PLACE-ON', 'PLACE-ANYWHERE'\], 'anywhere': \[\]\}$"
    ):
        _import_edited_registry(monkeypatch, anywhere, twice)
