"""Stability: calibrated p_fail on scenes built by hand, and fragile or robust placements that physics confirms."""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from typing import Any

import mujoco
import numpy as np
import pytest
from typer.testing import CliRunner

from physcensis.assets import default_catalogue
from physcensis.cli.evaluate import stability
from physcensis.geometry.voxels import quat_to_matrix
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.physics.profiles import MUJOCO_DEFAULT
from physcensis.scene import Scene, Support, save_scene
from physcensis.solver.objects import yaw_quaternion
from physcensis.solver.perturb import PerturbationScales, kernel_weights, p_fail
from physcensis.solver.pipeline import Solution, solve
from physcensis.solver.stability import StabilitySettings, estimate_stability
from physcensis.solver.stability_search import KeptValue, edge_frame, target_band, turn_about_vertical
from physcensis.solver.unmet import footprint_overlap

from ..conftest import EXAMPLES
from ..scenes import placed_object

TABLE = Support(kind="table", size=(0.8, 0.6))
TOP = TABLE.top_height
BOOK = "book_flat_hardcover_red"
physics = pytest.mark.physics


@pytest.fixture(scope="module")
def engine() -> MujocoEngine:
    return MujocoEngine()


placed = placed_object


def on_book_edge(asset_id: str, margin_m: float, yaw: float = 0.0) -> Scene:
    """A book flat on the table and an object on it whose centre of mass lies `margin_m` inside the book's +x
    edge."""
    catalogue = default_catalogue()
    book, item = catalogue.get(BOOK), catalogue.get(asset_id)
    com_x = (quat_to_matrix((math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2))) @ np.asarray(item.com))[0]
    x = book.size[0] / 2 - margin_m - com_x
    return Scene(
        support=TABLE,
        objects=[placed("book_0", BOOK, 0.0, 0.0, TOP), placed("item_0", asset_id, x, 0.0, TOP + book.size[2], yaw)],
    )


# -- the estimator without physics --------------------------------------------------------------------------
def test_p_fail_is_the_mahalanobis_kernel_weighted_failure_rate() -> None:
    sigma = np.array([0.005, 0.005, 0.005, 0.05, 0.05, 0.05, 0.001, 0.001, 0.001, 0.1, 0.1])
    x = np.zeros((2, 11))
    x[1, 0] = 0.005  # one standard deviation away along one axis
    fell = np.array([0.0, 1.0])
    w = kernel_weights(x, np.zeros(11), sigma)
    assert w == pytest.approx([1.0, math.exp(-0.5)])
    assert p_fail(x, fell, np.zeros(11), sigma) == pytest.approx(math.exp(-0.5) / (1 + math.exp(-0.5)))
    assert p_fail(x, fell, x[1], sigma) == pytest.approx(1 / (1 + math.exp(-0.5)))


def test_the_interval_is_wilsons_on_the_effective_samples() -> None:
    from physcensis.solver.stability import wilson_interval

    low, high = wilson_interval(0.3, 80)
    assert low == pytest.approx(0.2106, abs=1e-3) and high == pytest.approx(0.4077, abs=1e-3)
    assert wilson_interval(0.0, 86)[0] == 0.0 and wilson_interval(0.0, 86)[1] == pytest.approx(0.0428, abs=1e-3)
    assert wilson_interval(0.5, 0) == (0.0, 1.0)  # nothing behind it: nothing is known
    narrow, wide = wilson_interval(0.3, 320), wilson_interval(0.3, 20)
    assert narrow[1] - narrow[0] < (high - low) < wide[1] - wide[0]


def test_a_dimension_without_spread_is_not_perturbed() -> None:
    asset = default_catalogue().get("mug_white")
    sigma = PerturbationScales(friction=0.0).sigma(asset)
    assert sigma[9] == 0.0 and sigma[:3] == pytest.approx([0.005] * 3)
    assert sigma[6:9] == pytest.approx(np.asarray(asset.com_shift_range) / 4)
    x = np.zeros((1, 11))
    x[0, 9] = 5.0  # a friction change is ignored when friction is not perturbed
    assert kernel_weights(x, np.zeros(11), sigma) == pytest.approx([1.0])


@pytest.mark.parametrize("bad", ["sideways", 1.5, -0.1])
def test_a_stability_target_must_be_a_level_or_a_probability(bad: Any) -> None:
    with pytest.raises(ValueError, match="stability"):
        target_band(bad)


def test_a_corner_walk_learns_the_edge_direction_from_two_points_on_it() -> None:
    tangent, normal = np.array([1.0, 0.0]), np.array([0.0, -1.0])  # a first guess, off by about 6 degrees
    chord = np.array([-0.1, -0.01])  # from the first point found on the edge to the last, against the guess
    along, out = edge_frame(chord, tangent, normal, min_chord=0.01)
    assert along == pytest.approx(-chord / np.linalg.norm(chord))  # oriented like the guess
    assert out @ along == pytest.approx(0.0) and out @ normal > 0.99  # still outward
    kept = edge_frame(np.array([0.001, 0.0005]), tangent, normal, min_chord=0.01)  # too short to tell
    assert np.array_equal(kept[0], tangent) and np.array_equal(kept[1], normal)


def test_a_kept_overlap_allows_its_band_and_from_outside_it_only_moves_toward_it() -> None:
    kept = KeptValue("overlap", 0.55, 0.1, lambda objects: 0.0)
    assert kept.excess(0.62) == 0.0 and kept.excess(0.4) == pytest.approx(0.05)
    inside = 0.55
    assert kept.allows(0.46, inside) and kept.allows(0.64, inside)
    assert not kept.allows(0.44, inside) and not kept.allows(0.66, inside)
    above = 0.75  # a placement that started outside the band may move toward it, never farther or across it
    assert kept.allows(0.7, above) and kept.allows(0.75, above) and kept.allows(0.5, above)
    assert not kept.allows(0.8, above) and not kept.allows(0.4, above)
    assert "overlap asked (0.55 ± 0.1)" in kept.describe()


def test_the_turn_between_two_states_is_about_the_vertical_and_the_short_way_round() -> None:
    assert turn_about_vertical(yaw_quaternion(0.3), yaw_quaternion(1.0)) == pytest.approx(0.7)
    assert turn_about_vertical(yaw_quaternion(3.0), yaw_quaternion(-3.0)) == pytest.approx(2 * math.pi - 6.0)
    tilt = (math.cos(0.4), math.sin(0.4), 0.0, 0.0)  # lying tilted about x; then turned 0.5 rad about the vertical
    turned = (math.cos(0.25) * tilt[0], math.cos(0.25) * tilt[1], math.sin(0.25) * tilt[1], math.sin(0.25) * tilt[0])
    assert turn_about_vertical(tilt, turned) == pytest.approx(0.5)


# -- calibration ---------------------------------------------------------------------------------------------
@physics
def test_a_mug_in_the_middle_of_a_book_stands_firm(engine: MujocoEngine) -> None:
    book = default_catalogue().get(BOOK)
    scene = Scene(
        support=TABLE,
        objects=[placed("book_0", BOOK, 0.0, 0.0, TOP), placed("mug_0", "mug_white", 0.0, 0.0, TOP + book.size[2])],
    )
    estimate = estimate_stability(scene, "mug_0", 128, seed=0, engine=engine)
    assert estimate.p_fail < 0.05
    assert estimate.samples == 128 and estimate.effective_samples > 10


@physics
def test_a_mug_with_its_centre_of_mass_just_inside_the_book_edge_is_fragile(engine: MujocoEngine) -> None:
    # Handle toward the book: most of the mug's body hangs past the edge, its centre of mass 1 mm inside.
    scene = on_book_edge("mug_white", 0.001, yaw=math.pi / 2)
    mug = scene.object("item_0")
    assert mug.position[0] > default_catalogue().get(BOOK).size[0] / 2  # the mug's axis is past the edge
    assert plain_motion(scene, "item_0", engine) < 0.003  # left alone, it stands
    assert estimate_stability(scene, "item_0", 128, seed=0, engine=engine).p_fail > 0.5


@physics
def test_a_tall_thin_bottle_is_more_fragile_than_a_squat_can(engine: MujocoEngine) -> None:
    bottle = estimate_stability(on_book_edge("bottle_olive_oil", 0.004), "item_0", 128, seed=0, engine=engine)
    can = estimate_stability(on_book_edge("can_soup", 0.004), "item_0", 128, seed=0, engine=engine)
    assert bottle.p_fail > can.p_fail + 0.1


@physics
def test_batched_and_serial_simulations_give_the_same_labels_and_repeat_exactly(engine: MujocoEngine) -> None:
    scene = on_book_edge("mug_white", 0.002)
    batched = estimate_stability(scene, "item_0", 24, seed=3, engine=engine, settings=StabilitySettings(threads=2))
    serial = estimate_stability(scene, "item_0", 24, seed=3, engine=engine, settings=StabilitySettings(batched=False))
    again = estimate_stability(scene, "item_0", 24, seed=3, engine=engine, settings=StabilitySettings(threads=1))
    assert np.array_equal(batched.labels, serial.labels) and np.array_equal(batched.labels, again.labels)
    assert 0 < batched.fell < 24  # a real mix of falls and stands
    other = estimate_stability(scene, "item_0", 24, seed=4, engine=engine)
    assert not np.array_equal(batched.perturbations, other.perturbations)


# -- fragile and robust placements from a program ------------------------------------------------------------
def plain_motion(scene: Scene, object_id: str, engine: MujocoEngine, seconds: float = 4.0) -> float:
    """How far the farthest corner of the object's box moves when the whole scene is simulated, untouched."""
    built = engine.build(scene, visual=False)
    size = default_catalogue().get(scene.object(object_id).asset).size
    corners = np.array(
        [[sx * size[0] / 2, sy * size[1] / 2, z] for sx in (-1, 1) for sy in (-1, 1) for z in (0.0, size[2])]
    )

    def world() -> np.ndarray:
        pose = built.data.qpos[built.qpos[object_id] : built.qpos[object_id] + 7]
        return corners @ quat_to_matrix(pose[3:] / np.linalg.norm(pose[3:])).T + pose[:3]

    start = world()
    mujoco.mj_step(built.model, built.data, nstep=int(round(seconds / built.model.opt.timestep)))
    return float(np.linalg.norm(world() - start, axis=1).max())


def cup_program(stability_level: str) -> dict[str, Any]:
    program = json.loads((EXAMPLES / "unstable_cup.json").read_text())
    program["program"][-1][3]["stability"] = stability_level
    return program


@pytest.fixture(scope="module")
def fragile(solved_example: Callable[[str], Solution]) -> Solution:
    """The bundled unstable_cup example is this program: its solution is shared with the other solver tests."""
    assert cup_program("unstable") == json.loads((EXAMPLES / "unstable_cup.json").read_text())
    return solved_example("unstable_cup")


@pytest.fixture(scope="module")
def robust() -> Solution:
    return solve(cup_program("stable"), seed=0)


def record(solution: Solution) -> dict[str, Any]:
    return next(p for p in solution.scene.metrics["placements"] if p["object"] == "cup_0")


@physics
@pytest.mark.long
def test_the_unstable_cup_stands_yet_almost_any_disturbance_topples_it(fragile: Solution, engine: MujocoEngine) -> None:
    cup = fragile.scene.object("cup_0")
    assert cup.status == "placed", cup.reason
    assert plain_motion(fragile.scene, "cup_0", engine) < 0.003
    assert plain_motion(fragile.scene, "cup_0", engine.with_profile(MUJOCO_DEFAULT)) < 0.003
    # The most fragile state that stands (under MuJoCo's defaults too) while keeping the overlap asked (0.55 ± 0.1)
    # is at an edge of the book: its centre of mass within a millimetre or two of it.
    book, catalogue = fragile.scene.object("book_0"), default_catalogue()
    com = np.asarray(cup.position) + quat_to_matrix(cup.quaternion) @ np.asarray(cup.com)
    local = quat_to_matrix(book.quaternion).T @ (com - np.asarray(book.position))
    inside = np.asarray(catalogue.get(book.asset).size[:2]) / 2 - np.abs(local[:2])
    assert np.all(inside > 0.0) and np.min(inside) < 0.002, inside
    assert record(fragile)["overlap"] == pytest.approx(0.55, abs=0.1)
    # The target (0.9) counts as reached only on fresh draws, confidently; otherwise the report says what it reached.
    placed = record(fragile)
    assert placed["stability_target"] == "unstable" and placed["p_fail"] >= 0.8
    # reached only with p_fail at least 0.9 (plus a standard error); otherwise a warning says what it reached
    assert (
        placed["p_fail"] >= 0.9
        if placed["reached"]
        else any(w["parameter"] == "stability" for w in fragile.report()["warnings"])
    )
    # Measured again on draws the search never saw: still fragile, and the two figures agree within their 95 %
    # intervals (a single figure on some 80 effective samples is good to about ±0.1).
    again = estimate_stability(fragile.scene, "cup_0", 128, seed=11, engine=engine, min_effective=80.0)
    low, high = placed["p_fail_95"]
    assert again.p_fail >= 0.6 and again.interval[0] <= high and low <= again.interval[1], (again.interval, low, high)


@physics
@pytest.mark.long
def test_the_report_holds_the_overlap_and_offsets_after_the_search_which_keeps_the_overlap_asked(
    fragile: Solution,
) -> None:
    catalogue = default_catalogue()
    cup, book = fragile.scene.object("cup_0"), fragile.scene.object("book_0")
    placed = record(fragile)
    final = footprint_overlap(cup, catalogue.get(cup.asset), book, catalogue.get(book.asset))
    assert placed["overlap"] == pytest.approx(final, abs=1e-3)
    assert placed["x_offset"] == pytest.approx(cup.position[0] - book.position[0], abs=1e-4)
    assert placed["y_offset"] == pytest.approx(cup.position[1] - book.position[1], abs=1e-4)
    assert placed["stability"]["moved_m"] > 0.001
    assert placed["stability"]["p_fail"] == placed["p_fail"]
    # The search kept the overlap asked for within the report's tolerance: no warning says it changed; what the
    # overlap kept it from reaching, the stability warning says.
    assert placed["requested"]["overlap"] == 0.55 and placed["overlap"] == pytest.approx(0.55, abs=0.1)
    warnings = fragile.report()["warnings"]
    assert not any(w["parameter"] == "overlap" for w in warnings)
    if not placed["reached"]:
        stability = next(w for w in warnings if w["parameter"] == "stability")
        assert "overlap" in stability["why"] and "the overlap asked (0.55 ± 0.1)" in stability["why"]


@physics
@pytest.mark.long
def test_the_search_shifts_the_centre_of_mass_only_within_the_asset_range(fragile: Solution) -> None:
    cup = fragile.scene.object("cup_0")
    asset = default_catalogue().get(cup.asset)
    reach = np.asarray(asset.com_shift_range) + 1e-9
    assert np.all(np.abs(np.subtract(cup.com, asset.com)) <= reach)


@pytest.mark.slow
@physics
@pytest.mark.long
def test_the_same_cup_asked_to_be_stable_is_robust(robust: Solution, engine: MujocoEngine) -> None:
    assert record(robust)["stability_target"] == "stable" and record(robust)["p_fail"] <= 0.05
    assert plain_motion(robust.scene, "cup_0", engine) < 0.003
    again = estimate_stability(robust.scene, "cup_0", 128, seed=11, engine=engine, min_effective=80.0)
    assert again.p_fail <= 0.05 and again.effective_samples >= 80.0
    # The solver's figure and a fresh one on the scene as written agree within their 95 % intervals.
    low, high = record(robust)["p_fail_95"]
    assert low <= record(robust)["p_fail"] <= high and again.interval[0] <= high and low <= again.interval[1]


# -- command line -------------------------------------------------------------------------------------------
@physics
def test_the_stability_command_prints_p_fail_per_object(tmp_path: Any) -> None:
    import typer

    app = typer.Typer()
    app.command()(stability)
    path = save_scene(on_book_edge("mug_white", 0.02), tmp_path / "scene.json")
    args = [str(path), "--object", "item_0", "--samples", "16", "--json"]
    result = CliRunner().invoke(app, [*args, "--min-effective", "0"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.output)
    assert [o["object"] for o in data["objects"]] == ["item_0"] and data["objects"][0]["samples"] == 16
    assert 0.0 <= data["p_fail"] <= 1.0
    low, high = data["objects"][0]["p_fail_95"]
    assert low <= data["objects"][0]["p_fail"] <= high
    enough = json.loads(CliRunner().invoke(app, [*args, "--min-effective", "12"]).output)["objects"][0]
    assert enough["effective_samples"] >= 12 and enough["samples"] % 16 == 0 and enough["samples"] > 16
    missing = CliRunner().invoke(app, [str(path), "--object", "nope"])
    assert missing.exit_code == 2  # an object the scene does not have is a bad argument
    assert "no placed object 'nope'" in missing.output


@pytest.mark.slow
@pytest.mark.long
@physics
def test_a_numeric_target_moves_an_object_from_the_middle_of_its_support_to_its_fragility(
    engine: MujocoEngine,
) -> None:
    """A can placed in the middle of a book, where no perturbed copy falls, is asked for p_fail 0.3: with nothing
    nearby to learn an edge from, the search heads for the book's side (it used to stay put at p_fail 0)."""
    program = {
        "support": {"kind": "table", "size": [0.8, 0.6]},
        "program": [
            ["book_0", "a hardcover book lying flat"],
            ["book_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
            ["book_0", "FACING-FRONT", "root", {}],
            ["can_0", "a red soda can"],
            ["can_0", "PLACE-ON", "book_0", {"stability": 0.3}],
        ],
    }
    solution = solve(program, seed=1)
    placed = next(p for p in solution.scene.metrics["placements"] if p["object"] == "can_0")
    assert placed["stability"]["moved_m"] > 0.02, placed
    assert 0.2 <= placed["p_fail"] <= 0.4, placed
    assert plain_motion(solution.scene, "can_0", engine) < 0.003
