"""One test per checker rule, each with a program that breaks exactly that rule."""

from __future__ import annotations

from typing import Any

import pytest

from physcensis.program import check_program, load_program, parse_program
from physcensis.program.model import Problem
from physcensis.scene import Support

from ..conftest import EXAMPLES

# A small valid program the rule tests extend.
PLATE: list[Any] = [
    ["plate_0", "a round white dinner plate"],
    ["plate_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
    ["plate_0", "FACING-FRONT", "root", {}],
]


def fork(*predicates: list[Any]) -> list[list[Any]]:
    return [["fork_0", "a steel fork"], *predicates]


FORK_OK = fork(
    ["fork_0", "PLACE-ON-BASE", "root", {}],
    ["fork_0", "RIGHT-OF", "plate_0", {"distance": 0.02}],
    ["fork_0", "ALIGN-CENTER-FB", "plate_0", {}],
    ["fork_0", "ORIENT-BY-RELATIVE-SIDE", "plate_0", {}],
)


def problems(program: list[Any], support: Support | None = None) -> list[Problem]:
    return list(check_program(parse_program(program), support).problems)


def only(program: list[Any], rule: str, severity: str = "error", support: Support | None = None) -> Problem:
    """The program has problems of exactly one rule; return the first."""
    found = problems(program, support)
    assert found, "expected a problem"
    assert {p.rule for p in found} == {rule}, [str(p) for p in found]
    assert all(p.severity == severity for p in found)
    return found[0]


def test_valid_base_program_is_clean() -> None:
    assert problems(PLATE + FORK_OK) == []


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.json")) + sorted(EXAMPLES.glob("*.txt")), ids=lambda p: p.name)
def test_every_bundled_program_checks_clean(path: Any) -> None:
    report = check_program(load_program(path))
    assert report.ok, report.feedback()
    assert report.problems == ()


def test_every_shared_bench_program_checks_without_errors() -> None:
    """The shared bench's programs, as bundled (tests/program/test_parser.py checks the copies against it)."""
    paths = [p for p in EXAMPLES.iterdir() if p.suffix in {".json", ".txt"}]
    assert len(paths) >= 6
    for path in paths:
        report = check_program(load_program(path))
        assert report.ok, (path.name, report.feedback())


def test_unknown_predicate_suggests_the_closest_name() -> None:
    p = only(
        PLATE
        + fork(
            ["fork_0", "PLACE-ON-BASE", "root", {}],
            ["fork_0", "RIGTH-OF", "plate_0", {}],
            ["fork_0", "ALIGN-CENTER-FB", "plate_0", {}],
            ["fork_0", "ALIGN-CENTER-LR", "plate_0", {}],
            ["fork_0", "FACING-FRONT", "root", {}],
        ),
        "unknown-predicate",
    )
    assert p.index == 6 and "RIGHT-OF" in p.message


def test_unknown_parameter_names_the_valid_ones() -> None:
    p = only(
        PLATE
        + fork(
            ["fork_0", "PLACE-ON-BASE", "root", {}],
            ["fork_0", "RIGHT-OF", "plate_0", {"distanse": 0.02}],
            ["fork_0", "ALIGN-CENTER-FB", "plate_0", {}],
            ["fork_0", "FACING-FRONT", "root", {}],
        ),
        "unknown-param",
    )
    assert "'distance'" in p.message and p.object == "fork_0"


def test_missing_required_parameter() -> None:
    p = only(
        PLATE
        + FORK_OK
        + [
            ["knife_0", "a table knife"],
            ["knife_0", "PLACE-ON-BASE", "root", {}],
            ["knife_0", "SYMMETRY-ALONG", "fork_0", {}],
            ["knife_0", "FACING-FRONT", "root", {}],
        ],
        "missing-param",
    )
    assert "'C'" in p.message and p.index == 11


def test_wrong_parameter_type() -> None:
    p = only(
        PLATE
        + fork(
            ["fork_0", "PLACE-ON-BASE", "root", {}],
            ["fork_0", "RIGHT-OF", "plate_0", {"distance": "close"}],
            ["fork_0", "ALIGN-CENTER-FB", "plate_0", {}],
            ["fork_0", "FACING-FRONT", "root", {}],
        ),
        "param-type",
    )
    assert "must be a number" in p.message


@pytest.mark.parametrize("params", [{"overlap": 1.5}, {"stability": 2}, {"x_offset": float("nan")}])
def test_value_out_of_range(params: dict[str, Any]) -> None:
    only(PLATE + [["cup_0", "a cup"], ["cup_0", "PLACE-ON", "plate_0", params]], "param-range")


def test_place_on_base_outside_the_support() -> None:
    program = [
        ["cup_0", "a cup"],
        ["cup_0", "PLACE-ON-BASE", "root", {"x": 0.9, "y": 0.0}],
        ["cup_0", "FACING-FRONT", "root", {}],
    ]
    assert problems(program) == []  # no support known: nothing to compare with
    p = only(program, "param-range", support=Support(kind="table", size=(1.2, 0.8)))
    assert "-0.6 to 0.6" in p.message


def test_reference_to_an_object_not_yet_introduced() -> None:
    p = only(
        [
            ["cup_0", "a cup"],
            ["cup_0", "PLACE-ON-BASE", "root", {}],
            ["cup_0", "LEFT-OF", "plate_0", {}],
            ["cup_0", "ALIGN-CENTER-FB", "plate_0", {}],
            ["cup_0", "FACING-FRONT", "root", {}],
        ]
        + PLATE,
        "not-yet-introduced",
    )
    assert "#6" in p.message


def test_reference_to_an_object_never_introduced() -> None:
    p = only(
        PLATE
        + fork(
            ["fork_0", "PLACE-ON-BASE", "root", {}],
            ["fork_0", "RIGHT-OF", "plate_1", {}],
            ["fork_0", "ALIGN-CENTER-FB", "plate_0", {}],
            ["fork_0", "FACING-FRONT", "root", {}],
        ),
        "never-introduced",
    )
    assert "plate_0" in p.message  # did-you-mean


def test_place_on_onto_root() -> None:
    p = only([["cup_0", "a cup"], ["cup_0", "PLACE-ON", "root", {}]], "place-on-root")
    assert "PLACE-ON-BASE" in p.message


def test_place_on_mixed_with_2d_position_predicates() -> None:
    p = only(
        PLATE
        + [
            ["cup_0", "a cup"],
            ["cup_0", "PLACE-ON", "plate_0", {}],
            ["cup_0", "LEFT-OF", "plate_0", {"distance": 0.1}],
        ],
        "position-with-physical",
    )
    assert "LEFT-OF" in p.message and p.object == "cup_0"


def test_group_name_must_start_with_group() -> None:
    p = only(PLATE + FORK_OK + [["setting_0", "GROUP", ["plate_0", "fork_0"], {"anchor": "plate_0"}]], "group-name")
    assert "group_setting_0" in p.message


def test_copy_group_of_an_unknown_group() -> None:
    only(PLATE + FORK_OK + [["group_b", "COPY-GROUP", "group_a", {}]], "copy-unknown-group")


def test_place_anywhere_on_a_group() -> None:
    p = only(
        PLATE
        + FORK_OK
        + [
            ["group_a", "GROUP", ["plate_0", "fork_0"], {"anchor": "plate_0"}],
            ["group_a", "PLACE-ANYWHERE", "root", {}],
        ],
        "group-subject",
    )
    assert "PLACE-ANYWHERE" in p.message


def test_object_declared_twice() -> None:
    p = only(PLATE + [["plate_0", "another plate"]], "duplicate-object")
    assert "#1" in p.message


def test_object_with_no_description() -> None:
    only([["cup_0", "  "], ["cup_0", "PLACE-ANYWHERE", "root", {}]], "no-description")
    only([["cup_0", "PLACE-ANYWHERE", "root", {}]], "no-description")


@pytest.mark.parametrize("bad_id", ["cup 0", "cup/0", "x" * 65, "tasse_é"])
def test_invalid_ids(bad_id: str) -> None:
    only([[bad_id, "a cup"], [bad_id, "PLACE-ANYWHERE", "root", {}]], "bad-id")


def test_not_fully_solved_names_the_missing_axes() -> None:
    p = only([["cup_0", "a cup"], ["cup_0", "PLACE-ON-BASE", "root", {"x": 0.1}]], "not-fully-solved")
    assert "y (left/right position)" in p.message and "yaw" in p.message
    assert "x (front" not in p.message and "height" not in p.message


def test_copies_of_a_solved_group_are_solved() -> None:
    program = (
        PLATE
        + FORK_OK
        + [
            ["group_a", "GROUP", ["plate_0", "fork_0"], {"anchor": "plate_0"}],
            ["group_b", "COPY-GROUP", "group_a", {}],
            ["group_b", "BACK-OF", "group_a", {"distance": 0.1}],
            ["group_b", "FACING-OPPOSITE-TO", "group_a", {}],
            ["plate_0-group_b", "FACING-FRONT", "root", {}],  # copies are real objects afterwards
        ]
    )
    assert [p.rule for p in problems(program)] == ["override"]


def test_warning_for_split_entries() -> None:
    program = [
        ["a", "a cup"],
        ["b", "a plate"],
        ["a", "PLACE-ANYWHERE", "root", {}],
        ["b", "PLACE-ANYWHERE", "root", {}],
    ]
    found = problems(program)
    assert {p.rule for p in found} == {"contiguity"} and all(p.severity == "warning" for p in found)


def test_a_place_in_of_several_declared_ids_splits_none_of_them() -> None:
    """The planner's own form: the items declared, then one PLACE-IN of their ids (it warned for every item)."""
    program = [
        ["mug_0", "a mug"],
        ["mug_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
        ["mug_0", "FACING-FRONT", "root", {}],
        ["pencil_0", "a pencil"],
        ["pencil_1", "a pencil"],
        [["pencil_0", "pencil_1"], "PLACE-IN", "mug_0", {}],
    ]
    assert problems(program) == []
    split = [program[0], program[3], *program[1:3], *program[4:]]  # the mug's own entries are still split
    assert [(p.rule, p.object) for p in problems(split)] == [("contiguity", "mug_0")]


def test_warning_for_spatial_after_place_anywhere() -> None:
    p = only([["mug_0", "a mug"], ["mug_0", "PLACE-ANYWHERE", "root", {}]] + PLATE, "ordering", "warning")
    assert p.object == "plate_0" and "PLACE-ANYWHERE" in p.message


def test_conflicting_placements() -> None:
    only(
        PLATE + [["cup_0", "a cup"], ["cup_0", "PLACE-ON", "plate_0", {}], ["cup_0", "PLACE-ANYWHERE", "root", {}]],
        "conflicting-placement",
    )


def test_all_problems_are_reported_at_once() -> None:
    found = problems(
        [["a b", "x"], ["a b", "PLACE-ON", "root", {}], ["c", "FLY", "root", {}], ["d", "PLACE-ANYWHERE", "root", {}]]
    )
    assert {"bad-id", "place-on-root", "unknown-predicate", "no-description"} <= {p.rule for p in found}


@pytest.mark.parametrize("reserved", ["support", "Ground", "world", "SCENE"])
def test_ids_the_exports_use_for_the_scene_itself_are_reserved(reserved: str) -> None:
    found = problems([[reserved, "a cup"], [reserved, "PLACE-ANYWHERE", "root", {}]])
    first = found[0]
    assert first.rule == "reserved-id" and first.index == 1 and "another id" in first.message
