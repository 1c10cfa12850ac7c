"""Collision checking, planning around an obstacle and retiming: every commanded state was checked and is free."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from physcensis.robot import panda
from physcensis.robot.collision import CollisionChecker, Held, UnknownObjectError
from physcensis.robot.control import CONTROL_DT
from physcensis.robot.ik import solve_ik
from physcensis.robot.planning import DEFAULT_VELOCITY, densify, first_collision, plan, retime
from physcensis.robot.world import RobotWorld, build_world

DOWN = np.diag([1.0, -1.0, -1.0])


@pytest.fixture(scope="module")
def world(small_scene_dir: Path) -> RobotWorld:
    return build_world(small_scene_dir)


@pytest.fixture(scope="module")
def either_side_of_the_mug(world: RobotWorld) -> tuple[np.ndarray, np.ndarray]:
    """Two low hand poses, 10 cm left and right of the mug: the straight joint line between them hits it."""
    checker = CollisionChecker(world)
    cup, _ = world.object_pose("cup_0")
    ends = [solve_ik(world, cup + np.array([dx, 0.0, 0.04]), DOWN, checker=checker) for dx in (-0.1, 0.1)]
    assert ends[0].q is not None and ends[1].q is not None
    return ends[0].q, ends[1].q


def test_checker_sees_the_table_and_not_the_home_pose(world: RobotWorld) -> None:
    live = world.data.qpos.copy()
    checker = CollisionChecker(world)
    assert checker.valid(panda.HOME_Q) and checker.contacts(panda.HOME_Q) == []
    plate, _ = world.object_pose("plate_0")
    sunk = solve_ik(world, plate + np.array([0.0, 0.0, -0.04]), DOWN)  # the fingertips 4 cm into the table
    assert sunk.q is not None
    assert not checker.valid(sunk.q)
    assert any("support" in pair and pair.startswith("panda/") for pair in checker.contacts(sunk.q))
    assert np.array_equal(world.data.qpos, live)  # a scratch copy did the work


def test_a_held_object_moves_with_the_hand_and_ignored_objects_do_not_count(world: RobotWorld) -> None:
    plate, _ = world.object_pose("plate_0")
    low = solve_ik(world, plate + np.array([0.0, 0.0, 0.09]), DOWN, checker=CollisionChecker(world))
    assert low.q is not None
    hanging = np.eye(4)
    hanging[2, 3] = 0.08  # the mug's origin 8 cm further along the approach axis: below the table top
    held = CollisionChecker(world, held=Held("cup_0", hanging))
    assert any(pair.startswith("cup_0 with") or "with cup_0" in pair for pair in held.contacts(low.q))
    hanging[2, 3] = 0.0
    assert CollisionChecker(world, held=Held("cup_0", hanging)).valid(panda.HOME_Q)
    cup, _ = world.object_pose("cup_0")
    at_mug = solve_ik(world, cup + np.array([0.0, 0.0, 0.06]), DOWN)
    assert at_mug.q is not None
    assert not CollisionChecker(world).valid(at_mug.q)
    assert CollisionChecker(world, ignore=["cup_0"]).valid(at_mug.q)


def test_plan_goes_around_the_mug_and_every_dense_state_is_free(
    world: RobotWorld, either_side_of_the_mug: tuple[np.ndarray, np.ndarray]
) -> None:
    start, goal = either_side_of_the_mug
    checker = CollisionChecker(world)
    assert first_collision(np.array([start, goal]), checker) is not None  # the direct joint line is blocked
    path = plan(world, start, goal, checker, seed=3)
    assert isinstance(path, np.ndarray), path
    assert np.array_equal(path[0], start) and np.array_equal(path[-1], goal)
    assert first_collision(path, checker, step=0.003) is None
    again = plan(world, start, goal, checker, seed=3)
    assert isinstance(again, np.ndarray) and np.array_equal(again, path)  # seeded
    waypoints = retime(path)
    assert np.array_equal(waypoints[0], start) and np.array_equal(waypoints[-1], goal)
    speeds = np.abs(np.diff(waypoints, axis=0)) / CONTROL_DT
    assert np.all(speeds <= DEFAULT_VELOCITY + 1e-9)
    assert first_collision(waypoints, checker, step=0.003) is None  # retiming stays on the checked polyline


def test_plan_names_a_blocked_end(world: RobotWorld, either_side_of_the_mug: tuple[np.ndarray, np.ndarray]) -> None:
    cup, _ = world.object_pose("cup_0")
    inside = solve_ik(world, cup + np.array([0.0, 0.0, 0.05]), DOWN)
    assert inside.q is not None
    checker = CollisionChecker(world)
    blocked_goal = plan(world, panda.HOME_Q, inside.q, checker, seed=0)
    assert isinstance(blocked_goal, str) and blocked_goal.startswith("goal in collision") and "cup_0" in blocked_goal
    blocked_start = plan(world, inside.q, either_side_of_the_mug[0], checker, seed=0)
    assert isinstance(blocked_start, str) and blocked_start.startswith("start in collision")
    short = plan(world, panda.HOME_Q[:6], inside.q, checker, seed=0)
    assert isinstance(short, str) and "6 joint values" in short
    with pytest.raises(UnknownObjectError, match="teapot_9"):
        CollisionChecker(world, ignore=["cup_0", "teapot_9"])


def test_retime_limits_velocity_and_acceleration() -> None:
    path = np.array([panda.HOME_Q, panda.HOME_Q + 0.8, panda.HOME_Q + np.array([0.8, 0.0, 0.8, 0.0, 0.8, 0.0, 0.0])])
    limit = np.full(7, 0.5)
    waypoints = retime(densify(path, 0.05), max_velocity=limit, max_acceleration=np.full(7, 2.0))
    velocity = np.diff(waypoints, axis=0) / CONTROL_DT
    assert np.all(np.abs(velocity) <= limit + 1e-9)
    assert np.all(np.abs(np.diff(velocity, axis=0)) / CONTROL_DT <= 2.0 + 1e-6)
    assert waypoints.shape[0] * CONTROL_DT >= 2 * 0.8 / 0.5  # it cannot be faster than cruising all the way
    assert max(_off_polyline(q, path) for q in waypoints) < 1e-9  # it turns at the corner, never cuts it


def _off_polyline(q: np.ndarray, path: np.ndarray) -> float:
    distances = []
    for a, b in zip(path[:-1], path[1:], strict=True):
        s = np.clip((q - a) @ (b - a) / ((b - a) @ (b - a)), 0.0, 1.0)
        distances.append(float(np.linalg.norm(a + s * (b - a) - q)))
    return min(distances)


def test_densify_keeps_every_corner_exactly() -> None:
    rng = np.random.default_rng(5)
    corners = rng.uniform(-2.9, 2.9, size=(6, 7))
    dense = densify(corners, 0.01)
    assert np.all(np.linalg.norm(np.diff(dense, axis=0), axis=1) <= 0.01 + 1e-12)
    for corner in corners:  # each corner is a row of the dense path bit for bit, not a rounding of it
        assert any(np.array_equal(row, corner) for row in dense)
    assert np.array_equal(dense[-1], corners[-1])
