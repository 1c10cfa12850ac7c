"""A scene that came to rest in the first verification and was not changed since is not verified again; one that
the physical solver added to is, and both rest when written."""

from __future__ import annotations

from typing import Any

import pytest

import physcensis.solver.pipeline as pipeline
from physcensis.solver.pipeline import solve

pytestmark = pytest.mark.physics
SETTING = [
    ["plate_0", "a dinner plate"],
    ["plate_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
    ["plate_0", "FACING-FRONT", "root", {}],
    ["mug_0", "a mug"],
    ["mug_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.2}],
    ["mug_0", "FACING-FRONT", "root", {}],
]
STACKED = [*SETTING, ["book_0", "a paperback novel lying flat"], ["book_0", "PLACE-ANYWHERE", "root", {}]]
SET_DOWN = [*SETTING, ["vase_0", "a flower vase"], ["vase_0", "PLACE-ANYWHERE", "root", {"stack": False}]]


def verifications(program: list[list[Any]], monkeypatch: pytest.MonkeyPatch) -> tuple[int, pipeline.Solution]:
    calls = []
    real = pipeline.verify

    def counted(*args: Any) -> bool:
        calls.append(1)
        return real(*args)

    monkeypatch.setattr(pipeline, "verify", counted)
    solution = solve({"support": {"kind": "table", "size": [0.8, 0.6]}, "program": program})
    return len(calls), solution


def test_a_scene_without_physical_placements_is_verified_once_and_rests(monkeypatch: pytest.MonkeyPatch) -> None:
    count, solution = verifications(SETTING, monkeypatch)
    assert count == 1 and solution.ok
    assert solution.scene.metrics["settle_distance_m"] <= 0.003


def test_a_scene_the_physical_solver_added_to_is_verified_again(monkeypatch: pytest.MonkeyPatch) -> None:
    count, solution = verifications(STACKED, monkeypatch)
    assert count == 2 and solution.ok and len(solution.scene.placed) == 3
    assert solution.scene.metrics["settle_distance_m"] <= 0.003


def test_a_layout_that_only_gets_things_set_down_on_the_table_is_verified_once_after_them(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Plain PLACE-ANYWHERE beside a spatial layout that stands apart: the layout is not settled before they are
    placed; the one verification after them settles everything together, and the scene rests."""
    count, solution = verifications(SET_DOWN, monkeypatch)
    assert count == 1 and solution.ok and len(solution.scene.placed) == 3
    assert solution.scene.metrics["settle_distance_m"] <= 0.003


@pytest.mark.parametrize(
    "program", [SETTING, STACKED, SET_DOWN], ids=["spatial only", "with a physical placement", "set down"]
)
def test_the_written_scene_is_the_one_verified_at_rest_and_its_settle_distance_is_measured_from_it(
    program: list[list[Any]], monkeypatch: pytest.MonkeyPatch
) -> None:
    """Verification writes the poses its last settle started from, so the settle distance it reports (and a fresh
    engine measures again from the written scene) is that settle's motion: the scene as written rests."""
    from physcensis.assets.catalogue import default_catalogue
    from physcensis.physics.engine import AT_REST
    from physcensis.physics.mujoco_engine import MujocoEngine

    _, solution = verifications(program, monkeypatch)
    scene = solution.scene
    fresh = MujocoEngine(default_catalogue()).settle_distance(scene, rest=AT_REST)
    assert set(fresh.per_object) == {o.id for o in scene.placed}
    for oid, moved in fresh.per_object.items():
        assert moved < pipeline.AT_REST_M
        assert moved == pytest.approx(scene.metrics["settle_distance_per_object_m"][oid], abs=2e-6)
    full = MujocoEngine(default_catalogue()).settle_distance(scene)  # the paper's whole 4 s, not stopped at rest
    assert full.mean_m < pipeline.AT_REST_M
