from __future__ import annotations

from physcensis.program.registry import PREDICATES, Axis, Kind, Role, closest_name, lookup

DESIGN_NAMES = {
    "LEFT-OF", "RIGHT-OF", "FRONT-OF", "BACK-OF",
    "ALIGN-CENTER-LR", "ALIGN-CENTER-FB", "ALIGN-LEFT", "ALIGN-RIGHT", "ALIGN-FRONT", "ALIGN-BACK",
    "SYMMETRY-ALONG", "FACING-FRONT", "FACING-BACK", "FACING-LEFT", "FACING-RIGHT", "FACING-TO",
    "FACING-SAME-AS", "FACING-OPPOSITE-TO", "RANDOM-ROT", "ORIENT-BY-RELATIVE-SIDE",
    "PLACE-ON-BASE", "PLACE-ON", "PLACE-IN", "PLACE-ANYWHERE", "GROUP", "COPY-GROUP",
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
        assert spec.summary and spec.effect and spec.example, spec.name
        assert spec.example[1] == spec.name
        if spec.edge is not None:
            assert spec.determines == frozenset({Axis(spec.edge.axis)})
            assert (spec.param("distance") is not None) == (spec.edge.direction != 0)
        if spec.yaw is not None:
            assert spec.determines == frozenset({Axis.YAW})
        if spec.kind is Kind.GROUP:
            assert Role.NEW_GROUP in spec.subject
        for p in spec.params:
            if p.optimisable:
                assert p.low is not None and p.high is not None


def test_place_on_base_determines_x_and_y_only_when_given() -> None:
    spec = PREDICATES["PLACE-ON-BASE"]
    assert spec.axes_determined({}) == {Axis.HEIGHT}
    assert spec.axes_determined({"x": 0.1}) == {Axis.HEIGHT, Axis.X}
    assert spec.axes_determined({"x": 0.1, "y": 0.0}) == {Axis.HEIGHT, Axis.X, Axis.Y}
