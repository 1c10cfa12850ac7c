"""Inverse kinematics for the Panda's TCP: mink's differential IK, iterated to convergence with random restarts.

The iterations run on an arm-only model mounted where the world mounts the arm (no scene geometry, so each step is
cheap); every answer is then checked against the world's own model: forward kinematics within tolerance, joints
within limits and, with a checker, free of collisions.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import mink
import mujoco
import numpy as np

from physcensis.errors import PhyscensisError
from physcensis.robot import panda
from physcensis.robot.collision import CollisionChecker
from physcensis.robot.world import PREFIX, RobotWorld

_DT = 0.1  # the IK's integration step; with gain 1 each iteration aims at the whole remaining error
_MAX_ITERATIONS = 150
_REFINE_ITERATIONS = 30
_POSTURE_COST = 1e-2
_REFINE_DAMPING = 1e-3  # minimum-norm steps: the last iterations do not drift along the self-motion
_STALL_WINDOW = 15
_REACH_LIMIT = 1.25  # m from the shoulder: no Panda pose reaches past this, so restarts are pointless
_SHOULDER_HEIGHT = 0.333
_LINE_TOLERANCES = (0.002, 0.0175)  # m, rad: each waypoint of a straight line
_MAX_PATH_STEP = 0.5  # rad: a larger joint jump between two close Cartesian waypoints is a branch flip


class IkTargetError(PhyscensisError, ValueError):
    """An IK target that is not a pose: a rotation that is not a rotation, or numbers that are not finite."""


@dataclass(frozen=True)
class IkResult:
    """A joint configuration reaching the target, or None and the reason; the errors are the best attempt's."""

    q: np.ndarray | None
    position_error: float
    rotation_error: float
    reason: str | None

    @property
    def ok(self) -> bool:
        return self.q is not None


class _ArmIk:
    """mink's configuration, tasks and limits on an arm-only model at one mount."""

    def __init__(self, base_position: tuple[float, ...], base_yaw: float) -> None:
        spec = mujoco.MjSpec()
        quat = [float(np.cos(base_yaw / 2.0)), 0.0, 0.0, float(np.sin(base_yaw / 2.0))]
        frame = spec.worldbody.add_frame(pos=list(base_position), quat=quat)
        spec.attach(panda.panda_spec(), prefix=PREFIX, frame=frame)
        self.model = spec.compile()
        self.arm_qpos = np.array([self.model.joint(PREFIX + name).qposadr[0] for name in panda.ARM_JOINTS])
        self.site = int(self.model.site(PREFIX + panda.TCP_SITE).id)
        self.rest = np.zeros(self.model.nq)
        self.rest[self.arm_qpos] = panda.HOME_Q
        for name in panda.FINGER_JOINTS:
            self.rest[self.model.joint(PREFIX + name).qposadr[0]] = panda.FINGER_OPEN
        self.configuration = mink.Configuration(self.model, self.rest.copy())
        self.frame = mink.FrameTask(PREFIX + panda.TCP_SITE, "site", position_cost=1.0, orientation_cost=1.0)
        self.posture = mink.PostureTask(self.model, cost=_POSTURE_COST)
        self.posture.set_target(self.rest)
        self.limits = [mink.ConfigurationLimit(self.model)]

    def errors(self, position: np.ndarray, rotation: np.ndarray) -> tuple[float, float]:
        data = self.configuration.data
        return _pose_errors(data.site_xpos[self.site], data.site_xmat[self.site].reshape(3, 3), position, rotation)

    def descend(
        self,
        q0: np.ndarray,
        position: np.ndarray,
        rotation: np.ndarray,
        tolerances: tuple[float, float],
        stay_near_start: bool = False,
    ) -> np.ndarray:
        """Iterate from q0 (7 joints) toward the target; stops when converged or stalled. The arm's joints at the end.

        The posture task pulls toward HOME_Q (a natural elbow) or, with stay_near_start, toward q0 itself: a small
        Cartesian step then gets a small joint step, with no drift along the arm's self-motion.
        """
        q = self.rest.copy()
        q[self.arm_qpos] = q0
        self.configuration.update(q)
        self.posture.set_target(q if stay_near_start else self.rest)
        self.frame.set_target(mink.SE3.from_rotation_and_translation(mink.SO3.from_matrix(rotation), position))
        history: list[float] = []
        for _ in range(_MAX_ITERATIONS):
            self._step([self.frame, self.posture])
            history.append(_score(self.errors(position, rotation), tolerances))
            if history[-1] < 0.2 or _stalled(history):
                break
        for _ in range(_REFINE_ITERATIONS):  # without the posture's pull, the residual it leaves goes to zero
            if _score(self.errors(position, rotation), tolerances) < 0.05:
                break
            self._step([self.frame], damping=_REFINE_DAMPING)
        return self.configuration.q[self.arm_qpos].copy()

    def _step(self, tasks: list[mink.Task], damping: float = 1e-6) -> None:
        velocity = mink.solve_ik(self.configuration, tasks, _DT, "daqp", damping=damping, limits=self.limits)
        self.configuration.integrate_inplace(velocity, _DT)


def _pose_errors(
    position: np.ndarray, rotation: np.ndarray, target_position: np.ndarray, target_rotation: np.ndarray
) -> tuple[float, float]:
    cosine = (np.trace(target_rotation.T @ rotation) - 1.0) / 2.0
    return float(np.linalg.norm(position - target_position)), float(np.arccos(np.clip(cosine, -1.0, 1.0)))


def _score(errors: tuple[float, float], tolerances: tuple[float, float]) -> float:
    return max(errors[0] / tolerances[0], errors[1] / tolerances[1])


def _stalled(history: list[float]) -> bool:
    return len(history) > _STALL_WINDOW and history[-1] > 0.98 * history[-1 - _STALL_WINDOW]


@functools.lru_cache(maxsize=8)
def _arm_ik(base_position: tuple[float, ...], base_yaw: float) -> _ArmIk:
    return _ArmIk(base_position, base_yaw)


def arm_ik_for(world: RobotWorld) -> _ArmIk:
    """The cached arm-only IK model mounted like the world's arm."""
    return _arm_ik(tuple(float(x) for x in world.base_position), float(world.base_yaw))


class _WorldFk:
    """Forward kinematics on a scratch copy of the world's model state (the live data is never touched)."""

    _cache: dict[int, tuple[mujoco.MjModel, mujoco.MjData]] = {}

    @classmethod
    def tcp(cls, world: RobotWorld, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        cached = cls._cache.get(id(world.model))
        if cached is None or cached[0] is not world.model:
            if len(cls._cache) > 8:
                cls._cache.clear()
            cached = (world.model, mujoco.MjData(world.model))
            cls._cache[id(world.model)] = cached
        data = cached[1]
        data.qpos[:] = world.data.qpos
        data.qpos[world.arm_qpos] = q
        mujoco.mj_kinematics(world.model, data)
        return data.site_xpos[world.tcp_site].copy(), data.site_xmat[world.tcp_site].reshape(3, 3).copy()


def tcp_at(world: RobotWorld, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(position, rotation) of the TCP with the arm at q, by the world model's forward kinematics."""
    return _WorldFk.tcp(world, np.asarray(q, dtype=float))


@dataclass
class _Attempts:
    """What the restarts found so far: the closest pose reached and the contacts of valid-but-colliding ones."""

    best_errors: tuple[float, float] = (np.inf, np.inf)
    best_score: float = np.inf
    collisions: list[str] | None = None

    def note(self, errors: tuple[float, float], score: float) -> None:
        if score < self.best_score:
            self.best_errors, self.best_score = errors, score

    def failure(self) -> IkResult:
        position_error, rotation_error = self.best_errors
        if self.collisions is not None:
            reason = "every solution collides: " + ", ".join(self.collisions)
        else:
            reason = (
                f"out of reach: best {100 * position_error:.1f} cm and {np.degrees(rotation_error):.1f} deg "
                "from the target"
            )
        return IkResult(None, position_error, rotation_error, reason)


def _check_rotation(rotation: np.ndarray) -> np.ndarray:
    rotation = np.asarray(rotation, dtype=float).reshape(3, 3)
    if (
        not np.all(np.isfinite(rotation))
        or not np.allclose(rotation.T @ rotation, np.eye(3), atol=1e-6)
        or np.linalg.det(rotation) < 0.0
    ):
        raise IkTargetError("the IK target's rotation is not a proper 3x3 rotation matrix")
    return rotation


def _seeds(world: RobotWorld, seed_q: np.ndarray | None, rng: np.random.Generator, restarts: int) -> list[np.ndarray]:
    limits = world.arm_limits
    first = panda.HOME_Q.copy() if seed_q is None else np.clip(np.asarray(seed_q, dtype=float), *limits.T)
    return [first] + [rng.uniform(limits[:, 0], limits[:, 1]) for _ in range(restarts)]


def _within_limits(world: RobotWorld, q: np.ndarray) -> bool:
    limits = world.arm_limits
    return bool(np.all(q >= limits[:, 0] - 1e-6) and np.all(q <= limits[:, 1] + 1e-6))


def _beyond_reach(world: RobotWorld, position: np.ndarray) -> bool:
    shoulder = world.base_position + np.array([0.0, 0.0, _SHOULDER_HEIGHT])
    return bool(np.linalg.norm(position - shoulder) > _REACH_LIMIT)


def solve_ik(
    world: RobotWorld,
    position: np.ndarray,
    rotation: np.ndarray,
    *,
    seed_q: np.ndarray | None = None,
    rng: np.random.Generator | None = None,
    checker: CollisionChecker | None = None,
    tolerance_m: float = 0.005,
    tolerance_rad: float = 0.035,
    restarts: int = 8,
) -> IkResult:
    """Arm joints putting the TCP at (position, rotation) in world coordinates, or why there are none."""
    position = np.asarray(position, dtype=float).reshape(3)
    if not np.all(np.isfinite(position)):
        raise IkTargetError(f"the IK target's position is not finite: {position.tolist()}")
    rotation = _check_rotation(rotation)
    tolerances = (tolerance_m, tolerance_rad)
    rng = rng if rng is not None else np.random.default_rng(0)
    seeds = _seeds(world, seed_q, rng, 0 if _beyond_reach(world, position) else restarts)
    return _first_solution(world, position, rotation, seeds, tolerances, checker)


def _first_solution(
    world: RobotWorld,
    position: np.ndarray,
    rotation: np.ndarray,
    seeds: list[np.ndarray],
    tolerances: tuple[float, float],
    checker: CollisionChecker | None,
    stay_near_start: bool = False,
) -> IkResult:
    arm = arm_ik_for(world)
    attempts = _Attempts()
    for start in seeds:
        q = arm.descend(start, position, rotation, tolerances, stay_near_start)
        errors = _pose_errors(*tcp_at(world, q), position, rotation)
        score = _score(errors, tolerances)
        attempts.note(errors, score)
        if score > 1.0 or not _within_limits(world, q):
            continue
        if checker is not None and not checker.valid(q):
            attempts.collisions = checker.contacts(q)
            continue
        return IkResult(q, errors[0], errors[1], None)
    return attempts.failure()


def linear_path(
    world: RobotWorld,
    q_start: np.ndarray,
    displacement: np.ndarray,
    steps: int,
    checker: CollisionChecker | None = None,
) -> np.ndarray | str:
    """Joint waypoints moving the TCP along a straight line by `displacement` at a fixed orientation, or why not."""
    q = np.asarray(q_start, dtype=float).copy()
    start_position, rotation = tcp_at(world, q)
    displacement = np.asarray(displacement, dtype=float).reshape(3)
    length = float(np.linalg.norm(displacement))
    path = [q]
    for step in range(1, max(1, steps) + 1):
        target = start_position + displacement * step / max(1, steps)
        result = _first_solution(world, target, rotation, [path[-1]], _LINE_TOLERANCES, None, stay_near_start=True)
        where = f"at {100 * step / max(1, steps) * length:.1f} cm of a {100 * length:.1f} cm line"
        if result.q is None:
            return f"straight line breaks {where}: {result.reason}"
        if np.abs(result.q - path[-1]).max() > _MAX_PATH_STEP:
            return f"straight line breaks {where}: the arm would have to flip its joints"
        if checker is not None and not checker.valid(result.q):
            return f"straight line collides {where}: " + ", ".join(checker.contacts(result.q))
        path.append(result.q)
    return np.array(path)
