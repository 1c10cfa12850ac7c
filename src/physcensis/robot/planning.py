"""Collision-free joint paths (OMPL's RRT-Connect, shortcut and interpolated) and their time parameterisation.

A returned path is a polyline in joint space whose every densely interpolated state passed the collision checker;
`retime` keeps to that polyline exactly (a trapezoidal velocity profile on each straight piece, stopping at each
corner), so what the arm is commanded is what was checked.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from physcensis.robot.collision import CollisionChecker
from physcensis.robot.control import CONTROL_DT
from physcensis.robot.world import RobotWorld

# The Panda's joint velocity and acceleration limits (rad/s, rad/s^2), from Franka's datasheet.
PANDA_MAX_VELOCITY = np.array([2.175, 2.175, 2.175, 2.175, 2.61, 2.61, 2.61])
PANDA_MAX_ACCELERATION = np.array([15.0, 7.5, 10.0, 12.5, 15.0, 20.0, 20.0])
DEFAULT_VELOCITY = 0.6 * PANDA_MAX_VELOCITY
DEFAULT_ACCELERATION = 0.4 * PANDA_MAX_ACCELERATION
# Joint-space step between checked states (rad, Euclidean): with the arm's levers (|J| below ~1.7 m/rad) no
# checked step moves the hand more than about a centimetre.
CHECK_STEP = 0.006
OUTPUT_STEP = 0.05  # rad between the returned waypoints
_CORNER_COSINE = 1.0 - 1e-9
_SHORTCUT_ROUNDS = 5


def _ompl() -> tuple[Any, Any, Any]:
    try:
        from ompl import base, geometric, util
    except ImportError as err:  # pragma: no cover - the robot extra installs it
        raise ImportError("planning needs OMPL: pip install 'physcensis[robot]'") from err
    return base, geometric, util


def _outside_limits(world: RobotWorld, q: np.ndarray) -> str | None:
    limits = world.arm_limits
    bad = [i for i in range(len(q)) if not limits[i, 0] - 1e-6 <= q[i] <= limits[i, 1] + 1e-6]
    if not bad:
        return None
    return ", ".join(f"joint{i + 1} = {q[i]:.3f} outside [{limits[i, 0]:.3f}, {limits[i, 1]:.3f}]" for i in bad)


def _endpoint_problem(world: RobotWorld, checker: CollisionChecker, q: np.ndarray, which: str) -> str | None:
    if q.shape != (len(world.arm_qpos),):
        return f"{which} has {q.size} joint values; the arm has {len(world.arm_qpos)}"
    outside = _outside_limits(world, q)
    if outside:
        return f"{which} outside the joint limits: {outside}"
    if not checker.valid(q):
        return f"{which} in collision: " + ", ".join(checker.contacts(q))
    return None


def densify(path: np.ndarray, step: float = CHECK_STEP) -> np.ndarray:
    """The polyline's states with at most `step` (rad, Euclidean) between neighbours, corners kept."""
    path = np.atleast_2d(np.asarray(path, dtype=float))
    pieces = [path[:1]]
    for a, b in zip(path[:-1], path[1:], strict=True):
        count = max(1, int(np.ceil(np.linalg.norm(b - a) / step)))
        fractions = np.arange(1, count + 1)[:, None] / count
        piece = a + fractions * (b - a)
        piece[-1] = b  # a + (b - a) need not be b in floating point: corners and ends stay exactly as given
        pieces.append(piece)
    return np.concatenate(pieces)


def first_collision(path: np.ndarray, checker: CollisionChecker, step: float = CHECK_STEP) -> np.ndarray | None:
    """The first densely interpolated state of the polyline that collides, or None if all are free."""
    for q in densify(path, step):
        if not checker.valid(q):
            return q
    return None


def _search(
    world: RobotWorld, q_start: np.ndarray, q_goal: np.ndarray, checker: CollisionChecker, seed: int, timeout_s: float
) -> np.ndarray | None:
    base, geometric, util = _ompl()
    util.setLogLevel(util.LOG_NONE)
    util.RNG.setSeed(int(seed) % 2_147_483_646 + 1)  # OMPL reserves 0 for "random"; this OMPL restarts its sequence
    limits = world.arm_limits
    space = base.RealVectorStateSpace(len(q_start))
    bounds = base.RealVectorBounds(len(q_start))
    for i, (low, high) in enumerate(limits):
        bounds.setLow(i, float(low))
        bounds.setHigh(i, float(high))
    space.setBounds(bounds)
    setup = geometric.SimpleSetup(space)
    dimension = len(q_start)
    setup.setStateValidityChecker(lambda state: checker.valid(np.array([state[i] for i in range(dimension)])))
    info = setup.getSpaceInformation()
    info.setStateValidityCheckingResolution(CHECK_STEP / space.getMaximumExtent())
    start, goal = space.allocState(), space.allocState()
    for i in range(dimension):
        start[i], goal[i] = float(q_start[i]), float(q_goal[i])
    setup.setStartAndGoalStates(start, goal)
    setup.setPlanner(geometric.RRTConnect(info))
    if not setup.solve(float(timeout_s)) or not setup.haveExactSolutionPath():
        return None
    solution = setup.getSolutionPath()
    _shortcut(setup.getPathSimplifier(), solution)
    states = np.array([[solution.getState(k)[i] for i in range(dimension)] for k in range(solution.getStateCount())])
    states[0], states[-1] = q_start, q_goal  # exactly the requested ends (OMPL copies them, in doubles)
    return states


def _shortcut(simplifier: object, path: object) -> None:
    """Shortcut and drop vertices until nothing changes (no B-spline smoothing: retime stops at every corner)."""
    for _ in range(_SHORTCUT_ROUNDS):
        changed = simplifier.ropeShortcutPath(path)  # type: ignore[attr-defined]
        changed = simplifier.reduceVertices(path) or changed  # type: ignore[attr-defined]
        changed = simplifier.collapseCloseVertices(path) or changed  # type: ignore[attr-defined]
        if not changed:
            return


def plan(
    world: RobotWorld,
    q_start: np.ndarray,
    q_goal: np.ndarray,
    checker: CollisionChecker,
    *,
    seed: int,
    timeout_s: float = 5.0,
) -> np.ndarray | str:
    """A collision-free joint path from q_start to q_goal ((N, 7), ends included), or why there is none."""
    q_start = np.asarray(q_start, dtype=float).reshape(-1)
    q_goal = np.asarray(q_goal, dtype=float).reshape(-1)
    for q, which in ((q_start, "start"), (q_goal, "goal")):
        problem = _endpoint_problem(world, checker, q, which)
        if problem:
            return problem
    if first_collision(np.array([q_start, q_goal]), checker) is None:
        return densify(np.array([q_start, q_goal]), OUTPUT_STEP)  # the straight joint line is already free
    corners = _search(world, q_start, q_goal, checker, seed, timeout_s)
    if corners is None:
        return f"no path found in {timeout_s:g} s"
    blocked = first_collision(corners, checker)
    if blocked is not None:  # OMPL checked each motion at the same resolution; this is the contract, kept
        return "planned path collides at a checked state: " + ", ".join(checker.contacts(blocked))
    return densify(_merge_collinear(corners), OUTPUT_STEP)


def _merge_collinear(path: np.ndarray) -> np.ndarray:
    """The polyline's corners only: drops repeated states and states inside straight runs."""
    kept = [path[0]]
    for k in range(1, len(path)):
        if np.linalg.norm(path[k] - kept[-1]) < 1e-12:
            continue
        if k + 1 < len(path) and len(kept) >= 1:
            incoming = path[k] - kept[-1]
            outgoing = path[k + 1] - path[k]
            norms = np.linalg.norm(incoming) * np.linalg.norm(outgoing)
            if norms > 0.0 and incoming @ outgoing / norms > _CORNER_COSINE:
                continue
        kept.append(path[k])
    if len(kept) == 1:
        kept.append(path[-1])
    return np.array(kept)


def _trapezoid(rate: float, acceleration: float) -> tuple[float, float]:
    """(ramp time, total time) to go s = 0 -> 1 from rest to rest with |ds/dt| <= rate and |d2s/dt2| <= acceleration."""
    if rate * rate / acceleration >= 1.0:  # never reaches the cruise rate
        ramp = float(np.sqrt(1.0 / acceleration))
        return ramp, 2.0 * ramp
    ramp = rate / acceleration
    return ramp, 1.0 / rate + ramp


def _progress(t: float, ramp: float, total: float, acceleration: float) -> float:
    """s(t) along one trapezoid."""
    peak = acceleration * ramp
    if t <= ramp:
        return 0.5 * acceleration * t * t
    if t >= total - ramp:
        left = max(0.0, total - t)
        return 1.0 - 0.5 * acceleration * left * left
    return 0.5 * acceleration * ramp * ramp + peak * (t - ramp)


def retime(
    path: np.ndarray,
    *,
    max_velocity: np.ndarray | tuple[float, ...] = tuple(DEFAULT_VELOCITY),
    max_acceleration: np.ndarray | tuple[float, ...] = tuple(DEFAULT_ACCELERATION),
) -> np.ndarray:
    """Waypoints every CONTROL_DT along the path: rest to rest on each straight piece, within the given rates."""
    corners = _merge_collinear(np.atleast_2d(np.asarray(path, dtype=float)))
    velocity = np.asarray(max_velocity, dtype=float)
    acceleration = np.asarray(max_acceleration, dtype=float)
    pieces: list[tuple[np.ndarray, np.ndarray, float, float, float]] = []
    for a, b in zip(corners[:-1], corners[1:], strict=True):
        delta = np.abs(b - a)
        if delta.max() < 1e-12:
            continue
        moving = delta > 0.0
        rate = float(np.min(velocity[moving] / delta[moving]))
        s_acceleration = float(np.min(acceleration[moving] / delta[moving]))
        ramp, total = _trapezoid(rate, s_acceleration)
        pieces.append((a, b, ramp, total, s_acceleration))
    if not pieces:
        return corners[:1].copy()
    duration = sum(piece[3] for piece in pieces)
    times = np.arange(int(np.ceil(duration / CONTROL_DT - 1e-9)) + 1) * CONTROL_DT
    waypoints = np.array([_state_at(pieces, t) for t in times])
    waypoints[-1] = corners[-1]
    return waypoints


def _state_at(pieces: list[tuple[np.ndarray, np.ndarray, float, float, float]], t: float) -> np.ndarray:
    for a, b, ramp, total, acceleration in pieces:
        if t <= total:
            return a + _progress(t, ramp, total, acceleration) * (b - a)
        t -= total
    return pieces[-1][1].copy()
