"""No settle distance for a simulation that diverged, MuJoCo's warnings off stdout, and large supports searched in
bounded memory."""

from __future__ import annotations

import json
import math
import subprocess
import sys
import tracemalloc
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from physcensis.cli import app
from physcensis.physics.engine import SETTLE_CLAMP_M
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.scene import Scene, Support, save_scene
from physcensis.solver.physical import MAX_GRID_CELLS_XY, PhysicalSolver

from ..scenes import placed_object

pytestmark = pytest.mark.physics
TABLE = Support(kind="table", size=(0.8, 0.6))
TOP = TABLE.top_height
EXE = Path(sys.executable).with_name("physcensis")


@pytest.fixture(scope="module")
def engine() -> MujocoEngine:
    return MujocoEngine()


def mujoco_reset_scene() -> Scene:
    """Two near-weightless objects (2 mg, allowed by the loader) tangled into each other: MuJoCo meets a huge
    acceleration after 0.026 s, resets the state to the start and says "the simulation is unstable". The old
    measure then saw the basket back where it started: a settle distance of 0."""
    screwdriver = placed_object("screwdriver_0", "screwdriver_small_blue", 0.0, 0.0, 0.0).model_copy(
        update={
            "position": (-0.005719952132988627, 0.03704937076301694, 0.7116860888872711),
            "quaternion": (-0.9471432804212743, 0.09682274127339807, 0.262968120293636, -0.1561817237526973),
            "mass": 1.9073029778509471e-06,
            "friction": 0.55,
            "com": (0.033967479812184335, 7.026824868236889e-13, 0.009000000062764269),
        }
    )
    basket = placed_object("basket_0", "basket_laundry", 0.0, 0.0, 0.0).model_copy(
        update={
            "position": (-0.01958306928447854, 0.014630827269257407, 0.8091681961896611),
            "quaternion": (-0.6291108721512868, 0.500991970640545, 0.49582216771715815, 0.3276994566596181),
            "mass": 2.0031167455346307e-06,
            "friction": 0.7,
            "com": (9.883550189512876e-17, -2.6253180190893584e-17, 0.10194709830247557),
        }
    )
    return Scene(support=TABLE, objects=[screwdriver, basket])


def runaway_scene() -> Scene:
    """A 4 mg can inside a ketchup bottle: the can is flung out at over 100 m/s; the old measure stopped the run and
    reported the bottle's distance at that moment, 0."""
    can = placed_object("can_0", "can_beans_large", 0.0, 0.0, TOP).model_copy(update={"mass": 3.631152491003765e-06})
    ketchup = placed_object("ketchup_0", "bottle_ketchup", 0.0, 0.0, TOP).model_copy(
        update={"mass": 0.0018980646801001085}
    )
    return Scene(support=TABLE, objects=[can, ketchup])


def resting_scene() -> Scene:
    return Scene(support=TABLE, objects=[placed_object("mug_0", "mug_white", 0.1, 0.0, TOP + 1e-4)])


# -- the settle distance of a diverged simulation ------------------------------------------------------------------
def test_a_state_mujoco_resets_is_a_divergence_not_a_distance(engine: MujocoEngine) -> None:
    result = engine.settle_distance(mujoco_reset_scene())
    assert result.diverged is not None
    assert "MuJoCo: Nan, Inf or huge value in QACC" in result.diverged and "screwdriver_0" in result.diverged
    assert result.diverged.startswith("the simulation diverged within")
    assert all(value == SETTLE_CLAMP_M for value in result.per_object.values())  # never 0


def test_runaway_speeds_are_a_divergence_not_a_distance(engine: MujocoEngine) -> None:
    result = engine.settle_distance(runaway_scene())
    assert result.diverged is not None and "can_0 reached" in result.diverged and "m/s" in result.diverged
    assert result.mean_m == SETTLE_CLAMP_M


def test_a_resting_scene_is_measured_as_before(engine: MujocoEngine) -> None:
    result = engine.settle_distance(resting_scene())
    assert result.diverged is None
    assert 0.0 <= result.mean_m < 0.002


def test_settle_fails_the_object_mujoco_names_and_says_why(engine: MujocoEngine) -> None:
    result = engine.settle(mujoco_reset_scene(), duration_s=0.5)
    assert result.unstable and "diverged" in result.messages[0]
    motion = result.objects["screwdriver_0"]
    assert not motion.ok and motion.reason is not None and "MuJoCo" in motion.reason
    assert all(math.isfinite(v) for m in result.objects.values() for v in m.position)


def run_cli(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [str(EXE), *args],
        capture_output=True,
        text=True,
        timeout=300,
        cwd=cwd,
        env={"MUJOCO_GL": "egl", "PATH": "/usr/bin:/bin"},
    )


@pytest.mark.slow
@pytest.mark.parametrize("make", [mujoco_reset_scene, runaway_scene])
@pytest.mark.long
def test_eval_settle_reports_a_diverged_scene_as_a_failure_never_as_0(
    tmp_path: Path, make: Callable[[], Scene]
) -> None:
    path = save_scene(make(), tmp_path / "diverges" / "scene.json")
    done = run_cli("eval", "settle", str(path), cwd=tmp_path)
    assert done.returncode == 1, done.stderr
    assert "0.000" not in done.stdout and "diverged" in done.stdout
    assert "error:" in done.stderr and "the simulation diverged" in done.stderr and "Traceback" not in done.stderr
    assert "WARNING" not in done.stdout  # MuJoCo's own warning text stays off stdout ...
    assert not (tmp_path / "MUJOCO_LOG.TXT").exists()  # ... and out of the user's folder
    as_json = run_cli("eval", "settle", str(path), "--json", cwd=tmp_path)
    assert as_json.returncode == 1
    report = json.loads(as_json.stdout)  # stdout is pure JSON
    assert report["mean_m"] is None and report["diverged"] == 1
    row = report["scenes"][0]
    assert row["settle_distance_m"] is None and row["diverged"].startswith("the simulation diverged")


def test_eval_settle_measures_the_other_scenes_of_a_folder(tmp_path: Path) -> None:
    """In process: what stays off stdout in a real process is the test above's."""
    save_scene(mujoco_reset_scene(), tmp_path / "scenes" / "a" / "scene.json")
    save_scene(resting_scene(), tmp_path / "scenes" / "b" / "scene.json")
    done = CliRunner().invoke(app, ["eval", "settle", str(tmp_path / "scenes"), "--json"])
    assert done.exit_code == 1, done.output
    report = json.loads(done.stdout)
    by_scene = {Path(r["scene"]).parent.name: r for r in report["scenes"]}
    assert by_scene["a"]["diverged"] and by_scene["b"]["settle_distance_m"] < 0.002
    assert report["mean_m"] == by_scene["b"]["settle_distance_m"]


# -- the voxel search on large supports ----------------------------------------------------------------------------
def solver_on(support: Support, *objects_at: tuple[float, float]) -> PhysicalSolver:
    objects = [
        placed_object(f"crate_{k}", "box_parcel_small", x, y, support.top_height) for k, (x, y) in enumerate(objects_at)
    ]
    return PhysicalSolver(Scene(support=support, objects=objects), MujocoEngine())


def test_the_grid_of_a_large_support_is_a_bounded_window_around_the_focus() -> None:
    solver = solver_on(Support(kind="floor", size=(50.0, 50.0)), (20.0, -15.0))
    grid, _ = solver.scene_grid(0.5, focus=(20.0, -15.0))
    assert grid.shape[0] * grid.shape[1] <= MAX_GRID_CELLS_XY
    low = grid.origin[:2]
    high = low + np.array(grid.shape[:2]) * grid.pitch
    assert np.all(low < [20.0, -15.0]) and np.all(high > [20.0, -15.0])
    assert grid.open_sides == (True, True, True, True)
    assert grid.occupied.any()  # the crate is in it


def test_a_window_at_the_corner_keeps_the_support_edges_as_edges() -> None:
    solver = solver_on(Support(kind="floor", size=(50.0, 50.0)))
    grid, _ = solver.scene_grid(0.5, focus=(30.0, 30.0))
    high = grid.origin[:2] + np.array(grid.shape[:2]) * grid.pitch
    assert np.allclose(high, [25.0, 25.0], atol=grid.pitch)
    assert grid.open_sides == (True, False, True, False)


def test_an_ordinary_support_is_searched_whole() -> None:
    solver = solver_on(Support(kind="table", size=(1.2, 0.8)))
    grid, _ = solver.scene_grid(0.9, focus=(0.5, 0.3))
    assert grid.shape[:2] == (120, 80) and grid.open_sides == (False, False, False, False)


def test_three_objects_on_the_largest_floor_solve_in_bounded_memory() -> None:
    from physcensis.solver.pipeline import solve

    program = {
        "support": {"kind": "floor", "size": [50, 50]},
        "program": [
            ["crate_0", "a large parcel box"],
            ["crate_0", "PLACE-ON-BASE", "root", {"x": 12.0, "y": -8.0}],
            ["crate_0", "FACING-FRONT", "root", {}],
            ["book_0", "a red hardcover book"],
            ["book_0", "PLACE-ON", "crate_0", {}],
            ["ball_0", "a basketball"],
            ["ball_0", "PLACE-ANYWHERE", "root", {}],
        ],
    }
    tracemalloc.start()
    try:
        solution = solve(program, seed=0)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    scene = solution.scene
    assert [o.status for o in scene.objects] == ["placed"] * 3, [o.reason for o in scene.objects]
    assert peak < 250e6, f"{peak / 1e6:.0f} MB"  # about 85 MB; the whole-floor grid took about 3 GB
    crate, ball = scene.object("crate_0"), scene.object("ball_0")
    # searched in the 9 m window (300 cells of 3 cm) around what is there, not over the 50 m floor
    assert np.abs(np.subtract(ball.position[:2], crate.position[:2])).max() < 4.6
