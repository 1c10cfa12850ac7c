"""The physical solver: stacks, containers and free placement that physics confirms."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest
import shapely

from physcensis.assets import default_catalogue
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.program import load_program
from physcensis.program.registry import PlacementKind
from physcensis.scene import Scene, Support
from physcensis.solver.objects import quaternion_yaw
from physcensis.solver.physical import PhysicalSolver, PlaceRequest
from physcensis.solver.pipeline import Solution, solve

from ..conftest import EXAMPLES

pytestmark = pytest.mark.physics


class _SolvedOnRequest(dict[str, Solution]):
    """The examples, each solved when a test first asks for it: a test worker that runs one test of this module
    solves one example, not four."""

    def __init__(self, solved_example: Callable[[str], Solution]) -> None:
        super().__init__()
        self._solved_example = solved_example

    def __missing__(self, name: str) -> Solution:
        self[name] = self._solved_example(name)
        return self[name]


@pytest.fixture(scope="module")
def solved(solved_example: Callable[[str], Solution]) -> dict[str, Solution]:
    return _SolvedOnRequest(solved_example)


def placement(solution: Solution, object_id: str) -> dict[str, Any]:
    return next(p for p in solution.scene.metrics["placements"] if p["object"] == object_id)


def footprint(solution: Solution, object_id: str) -> shapely.Polygon:
    import numpy as np

    from physcensis.geometry.footprints import rotate

    o = solution.scene.object(object_id)
    hull = default_catalogue().asset_for(o.asset, o.description).footprint()
    return shapely.Polygon(rotate(hull, np.array([quaternion_yaw(o.quaternion)]))[0] + o.position[:2])


@pytest.mark.slow
@pytest.mark.parametrize(
    "name", ["books_stack", "fruit_bowl", "desk_basic", pytest.param("unstable_cup", marks=pytest.mark.long)]
)
def test_every_object_is_placed_and_the_scene_rests(solved: dict[str, Solution], name: str) -> None:
    solution = solved[name]
    assert all(o.status == "placed" for o in solution.scene.objects), solution.feedback()
    assert solution.scene.metrics["settle_distance_m"] < 0.003
    assert solution.scene.metrics["max_penetration_mm"] < 2.0


def test_five_books_form_one_stack(solved: dict[str, Solution]) -> None:
    solution = solved["books_stack"]
    books = [solution.scene.object(f"book_{i}") for i in range(5)]
    assert [b.position[2] for b in books] == sorted(b.position[2] for b in books)
    for lower, upper in zip(books, books[1:], strict=False):
        thickness = default_catalogue().get(lower.asset).size[2]
        assert upper.position[2] == pytest.approx(lower.position[2] + thickness, abs=0.004)
        assert footprint(solution, lower.id).intersects(footprint(solution, upper.id))
    assert placement(solution, "book_1")["support_ratio"] == pytest.approx(0.9, abs=0.15)


def test_every_fruit_ends_inside_the_bowl(solved: dict[str, Solution]) -> None:
    assert_fruit_in_the_bowl(solved["fruit_bowl"])


def assert_fruit_in_the_bowl(solution: Solution) -> None:
    bowl = solution.scene.object("bowl_0")
    cavity = default_catalogue().get(bowl.asset).cavity
    assert cavity is not None
    opening = shapely.Polygon(cavity.opening + bowl.position[:2])  # the bowl stands upright, yaw 0
    fruit = [o for o in solution.scene.objects if o.category in ("apple", "orange")]
    assert sorted(o.category for o in fruit) == ["apple"] * 3 + ["orange"] * 2
    for o in fruit:
        assert o.status == "placed", (o.id, o.reason)
        assert opening.contains(shapely.Point(o.position[:2])), o.id
        assert o.position[2] < bowl.position[2] + cavity.rim_height
    banana = solution.scene.object("banana_0")
    assert banana.status == "placed"


def test_cup_rests_on_the_notebook_with_the_requested_overlap(solved: dict[str, Solution]) -> None:
    solution = solved["desk_basic"]
    cup, notebook = solution.scene.object("cup_0"), solution.scene.object("notebook_0")
    record = placement(solution, "cup_0")
    assert record["ok"] and record["support_ratio"] == pytest.approx(1.0, abs=0.15)
    top = notebook.position[2] + default_catalogue().get(notebook.asset).size[2]
    assert cup.position[2] == pytest.approx(top, abs=0.004)
    assert footprint(solution, "notebook_0").contains(shapely.Point(cup.position[:2]))


@pytest.mark.long  # the fragility search solves it: half a minute
def test_unstable_cup_overhangs_the_book_edge(solved: dict[str, Solution]) -> None:
    record = placement(solved["unstable_cup"], "cup_0")
    assert record["ok"] and record["support_ratio"] == pytest.approx(0.55, abs=0.15)


def test_place_on_an_object_too_small_fails_with_no_supported_spot() -> None:
    solution = solve(
        {
            "support": {"kind": "table", "size": [0.8, 0.6]},
            "program": [
                ["pen_0", "a ballpoint pen"],
                ["pen_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
                ["pen_0", "FACING-FRONT", "root", {}],
                ["book_0", "a large atlas lying flat"],
                ["book_0", "PLACE-ON", "pen_0", {}],
            ],
        }
    )
    book = solution.scene.object("book_0")
    assert book.status == "failed"
    assert "no supported spot on pen_0" in (book.reason or "")
    assert "overhang" in solution.feedback()


def test_over_filled_container_reports_the_items_left_out() -> None:
    solution = solve(
        {
            "support": {"kind": "table", "size": [0.6, 0.6]},
            "program": [
                ["bowl_0", "a small glass bowl"],
                ["bowl_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
                ["bowl_0", "FACING-FRONT", "root", {}],
                [[["orange", 12]], "PLACE-IN", "bowl_0", {}],
            ],
        }
    )
    inside = [o for o in solution.scene.objects if o.category == "orange" and o.status == "placed"]
    out = [o for o in solution.scene.objects if o.category == "orange" and o.status == "failed"]
    assert inside and out
    assert all("bowl_0 is full" in (o.reason or "") or "did not end inside bowl_0" in (o.reason or "") for o in out)
    assert any("full" in (o.reason or "") for o in out)
    bowl = solution.scene.object("bowl_0")
    assert abs(bowl.position[0]) < 0.01 and abs(bowl.position[1]) < 0.01  # the drop did not knock it away


def test_place_anywhere_fills_free_space_without_overlap() -> None:
    scene = Scene(support=Support(kind="table", size=(0.6, 0.6)))
    solver = PhysicalSolver(scene, MujocoEngine(), seed=3)
    mug = default_catalogue().get("mug_white")
    for i in range(6):
        outcome = solver.place(
            PlaceRequest(
                object_id=f"mug_{i}", description=mug.description, asset=mug, kind=PlacementKind.ANYWHERE, stack=False
            )
        )
        assert outcome.ok, outcome.reason
    result = MujocoEngine().settle(scene)
    assert not result.failed and result.max_penetration_m < 0.002
    assert all(abs(o.position[2] - scene.support.top_height) < 0.003 for o in scene.objects)


@pytest.mark.long  # 6 s
def test_physical_solving_is_deterministic(solved: dict[str, Solution]) -> None:
    """Solved again after whatever else this process solved since: the same scene."""
    first = solved["fruit_bowl"].scene
    solved["desk_basic"]  # another example solved in between, if this process has not solved it yet
    assert solve(load_program(EXAMPLES / "fruit_bowl.json"), seed=0).scene == first


def test_an_object_asked_to_be_unstable_is_placed_where_it_rests_when_every_fragile_spot_falls() -> None:
    """A jar asked to be unstable on a side plate: the spots nearest the edge of standing are on the plate's sloping
    rim, where it slides off. It is then placed where it rests (the stability search moves it afterwards) instead
    of failing."""
    program = {
        "support": {"kind": "table", "size": [1.0, 0.8]},
        "program": [
            ["box_0", "a cardboard parcel box"],
            ["box_0", "PLACE-ON-BASE", "root", {"x": 0.2, "y": -0.2}],
            ["box_0", "FACING-FRONT", "root", {}],
            ["plate_0", "a small blue side plate"],
            ["plate_0", "PLACE-ON", "box_0", {}],
        ],
    }
    scene = solve(program, seed=0).scene
    engine = MujocoEngine(default_catalogue())
    jar = engine.catalogue.get("jar_mason")
    solver = PhysicalSolver(scene, engine, seed=0)
    outcome = solver.place(
        PlaceRequest("jar_0", "a mason jar", jar, PlacementKind.ON, target="plate_0", stability="unstable")
    )
    assert outcome.ok, outcome.reason
    assert scene.object("jar_0").status == "placed"
    assert scene.object("jar_0").position[2] > scene.object("plate_0").position[2]
    assert engine.settle_distance(scene).mean_m < 0.001
