"""Feedback for each kind the paper's ablation studies: grammar, solver failure, empty regions."""

from __future__ import annotations

import math

import pytest

from physcensis.assets import default_catalogue
from physcensis.feedback.messages import grammar_feedback, solver_feedback, success_feedback
from physcensis.feedback.regions import coverage, describe_region, empty_regions
from physcensis.program import check_program, parse_program
from physcensis.scene import PlacedObject, Scene, Support
from physcensis.solver.pipeline import solve


def laptop_scene() -> Scene:
    asset = default_catalogue().get("laptop_silver_closed")
    laptop = PlacedObject(
        id="laptop_0",
        description=asset.description,
        asset=asset.id,
        category=asset.category,
        position=(0.25, -0.35, 0.75),
        quaternion=(1.0, 0.0, 0.0, 0.0),
        mass=asset.mass,
        friction=0.5,
    )
    return Scene(support=Support(kind="table", size=(1.2, 1.6)), objects=[laptop])


def test_grammar_feedback_lists_every_problem_with_its_entry() -> None:
    report = check_program(parse_program('[["a","a cup"],["a","PLACE-ONN","root",{}],["b","PLACE-ON","root",{}]]'))
    feedback = grammar_feedback(report)
    assert feedback.kind == "grammar"
    assert "#2" in feedback.text and "did you mean PLACE-ON" in feedback.text
    assert "#3" in feedback.text and "PLACE-ON cannot target root" in feedback.text
    unreadable = grammar_feedback(None, "no program found")
    assert "could not be read" in unreadable.text


@pytest.mark.physics
def test_solver_feedback_names_the_failed_objects_and_why() -> None:
    entries = []
    for i in range(6):
        entries += [
            [f"pot_{i}", "a large stainless steel cooking pot"],
            [f"pot_{i}", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
            [f"pot_{i}", "FACING-FRONT", "root", {}],
        ]
    solution = solve({"support": {"kind": "table", "size": [0.5, 0.5]}, "program": entries})
    feedback = solver_feedback(solution)
    assert feedback.kind == "solver" and feedback.failed
    for oid in feedback.failed:
        assert f"- {oid} (PLACE-ON-BASE): " in feedback.text
    assert "overlaps pot_" in feedback.text
    assert "covered" in feedback.text


def test_empty_region_is_reported_in_words_and_numbers() -> None:
    scene = laptop_scene()
    regions = empty_regions(scene)
    assert regions, "an almost empty table has room"
    biggest = regions[0]
    assert biggest.size_x * biggest.size_y > 0.5
    text = describe_region(biggest, scene)
    assert text.startswith("an empty region of about") and "cm" in text and "of the table" in text
    # the laptop sits at the front right: the largest free box must not contain it
    assert not (abs(biggest.x - 0.25) < biggest.size_x / 2 and abs(biggest.y + 0.35) < biggest.size_y / 2)
    assert 0.0 < coverage(scene) < 0.1


def test_region_words_follow_the_axes() -> None:
    scene = laptop_scene()
    scene.objects = []
    from physcensis.feedback.regions import where_words

    assert where_words(0.5, 0.1, 0.6, 0.8) == "the front"
    assert where_words(-0.5, 0.5, 0.6, 0.6) == "the back left"
    assert where_words(0.0, -0.5, 0.6, 0.6) == "the right"
    assert where_words(0.0, 0.0, 0.6, 0.6) == "the middle"
    assert math.isclose(coverage(scene), 0.0)


@pytest.mark.physics
def test_success_feedback_carries_metrics_and_asks_for_more_when_enriching() -> None:
    solution = solve(
        {
            "support": {"kind": "table", "size": [0.8, 0.6]},
            "program": [
                ["mug_0", "a white coffee mug"],
                ["mug_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
                ["mug_0", "FACING-FRONT", "root", {}],
            ],
        }
    )
    plain = success_feedback(solution)
    assert "All 1 objects were placed" in plain.text and plain.data["coverage"] > 0
    enriched = success_feedback(solution, enrich=True)
    assert "empty region" in enriched.text and "Add more objects" in enriched.text
