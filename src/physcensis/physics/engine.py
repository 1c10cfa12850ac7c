"""What the physics engines share: settle results, tolerances, the settle-distance metric and its interface.

They know scenes and meshes, not predicates. `MujocoEngine` (physics/mujoco_engine.py) builds, settles and
renders scenes; any engine that measures the paper's settle distance (`SettleEngine`: MujocoEngine, and
BulletEngine in crosscheck/ on the URDF export) can stand in for another where only that metric is wanted.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Literal, Protocol, runtime_checkable

import numpy as np

from physcensis.scene import PlacedObject, Scene

View = Literal["iso", "iso-right", "front", "back", "left", "right", "top", "side"]
SETTLE_STEPS = 400  # the paper's settle distance: 400 steps of 0.01 s
SETTLE_STEP_S = 0.01
SETTLE_S = SETTLE_STEPS * SETTLE_STEP_S  # the paper's settle: 4 s of free fall
SETTLE_CLAMP_M = 1.0


@dataclass(frozen=True)
class Tolerance:
    """How far an object may move while settling and still count as resting where it was put."""

    translation_m: float = 0.01
    rotation_rad: float = math.radians(10.0)


DEFAULT_TOLERANCE = Tolerance()


@dataclass(frozen=True)
class RestRule:
    """When a settle may stop before its time is up: over the last `window_s` (checked each `check_s`) no free body
    went further from where the window began than `speed_m_s` or turned further than `spin_rad_s` per second of it, none
    was ever faster than the jitter speeds (what chatters in place on its contacts is still: a salad fork rocks at
    0.02 rad/s under MuJoCo's defaults and stays within 0.03 deg of where it lay), and none sped up (its fastest in the
    window's later half is at most twice its fastest in the earlier half). What the rest of the settle could still show
    is then below those speeds times the time left (0.6 mm in 12 s). A pen spinning about its own axis, fruit rolling
    into a hollow, a pile sliding apart slowly, all move faster than this and are watched to the end."""

    speed_m_s: float = 5e-5
    spin_rad_s: float = 5e-4
    window_s: float = 0.5
    check_s: float = 0.05

    @property
    def jitter_m_s(self) -> float:
        """Faster than this at any check a body is moving, wherever it ends up."""
        return 100.0 * self.speed_m_s

    @property
    def jitter_rad_s(self) -> float:
        return 100.0 * self.spin_rad_s

    @property
    def speed_floor_m_s(self) -> float:
        """Below this a body counts as still whatever its speed did: the noise of a resting contact."""
        return self.speed_m_s / 100.0

    @property
    def spin_floor_rad_s(self) -> float:
        return self.spin_rad_s / 100.0


AT_REST = RestRule()


@dataclass(frozen=True)
class ObjectMotion:
    """What settling did to one object."""

    id: str
    translation_m: float
    rotation_rad: float
    left_support: bool
    penetration_m: float  # deepest interpenetration with anything, after settling (0 when none)
    initial_penetration_m: float  # the same before settling: how badly it was placed
    position: tuple[float, float, float]
    quaternion: tuple[float, float, float, float]
    ok: bool
    reason: str | None = None


def at_rest(objects: Sequence[PlacedObject], motions: Mapping[str, ObjectMotion]) -> list[PlacedObject]:
    """`objects`, each that has a motion taken to the pose it settled in."""
    return [
        o.model_copy(update={"position": motions[o.id].position, "quaternion": motions[o.id].quaternion})
        if o.id in motions
        else o
        for o in objects
    ]


@dataclass
class SettleResult:
    objects: dict[str, ObjectMotion]
    simulated_s: float
    wall_s: float
    unstable: bool = False  # the simulation blew up (NaN or runaway speeds) and was stopped
    messages: list[str] = field(default_factory=list)

    @property
    def failed(self) -> list[ObjectMotion]:
        return [m for m in self.objects.values() if not m.ok]

    @property
    def max_penetration_m(self) -> float:
        return max((m.penetration_m for m in self.objects.values()), default=0.0)


@dataclass(frozen=True)
class SettleDistance:
    """The paper's metric: mean displacement over 4 s of free fall, each clamped at 1 m.

    When the simulation diverged (NaN, MuJoCo's "simulation is unstable" warnings, runaway speeds) no distance can
    be measured: `diverged` says why, and every object counts as having moved the full clamp, never 0."""

    per_object: dict[str, float]
    diverged: str | None = None

    @classmethod
    def of_moves(cls, moved: Mapping[str, float], engine: str) -> SettleDistance:
        """Each object's displacement clamped at 1 m; the first one that is not a number (the simulation of
        `engine` diverged) makes every object count as fallen, with why."""
        for oid, distance in moved.items():
            if not math.isfinite(distance):
                why = f"the simulation diverged ({engine}: the position of {oid} became NaN)"
                return cls(dict.fromkeys(moved, SETTLE_CLAMP_M), diverged=why)
        return cls({oid: min(SETTLE_CLAMP_M, float(distance)) for oid, distance in moved.items()})

    @property
    def mean_m(self) -> float:
        return float(np.mean(list(self.per_object.values()))) if self.per_object else 0.0

    def over_requested(self, requested: int) -> float:
        """The mean over `requested` objects, those measured here and the rest (asked for, but removed or never
        placed) counted as fallen: the full clamp. Placed objects alone read about 0 when verification removed
        whatever moved."""
        missing = max(0, requested - len(self.per_object))
        total = sum(self.per_object.values()) + SETTLE_CLAMP_M * missing
        count = len(self.per_object) + missing
        return float(total / count) if count else 0.0


@runtime_checkable
class SettleEngine(Protocol):
    """An engine that measures the paper's settle distance (`physcensis eval settle --engine` picks one)."""

    def settle_distance(self, scene: Scene, duration_s: float = SETTLE_S) -> SettleDistance:
        """The settle distance of the scene's placed objects after `duration_s` of free fall (the paper's 4 s)."""
        ...


def quaternion_angle(q0: np.ndarray, q1: np.ndarray) -> float:
    """Rotation angle between two unit quaternions [w, x, y, z]."""
    dot = abs(float(np.dot(q0, q1)))
    return 2.0 * math.acos(min(1.0, dot))


ROD_ASPECT = 3.0  # a rod's longest side is at least this many times its middle one ...
ROUND_SECTION = 1.3  # ... and its cross-section about as wide as it is thick (a pen, a pencil, a chopstick)
STANDING_COS = 0.5  # a rod stands (on end, or leaning in a holder) when its long axis is within 60° of vertical


def spin_axis(size: Sequence[float]) -> np.ndarray | None:
    """The long axis (in the asset's frame) of a rod with a round cross-section, about which a turn changes nothing
    that matters (a pen spinning in its holder); None for any other shape."""
    order = np.argsort(np.asarray(size, dtype=float))
    small, middle, long = (float(size[k]) for k in order)
    if long < ROD_ASPECT * middle or middle > ROUND_SECTION * small:
        return None
    axis = np.zeros(3)
    axis[order[2]] = 1.0
    return axis


def _rotate(q: np.ndarray, v: np.ndarray) -> np.ndarray:
    """v turned by the unit quaternion q = [w, x, y, z]."""
    w, u = float(q[0]), np.asarray(q[1:], dtype=float)
    return np.asarray(v + 2.0 * np.cross(u, np.cross(u, v) + w * v))


def turn_angle(q0: np.ndarray, q1: np.ndarray, spin: np.ndarray | None = None) -> float:
    """How far an object turned between two orientations; for a round rod standing on end (`spin`, its long axis),
    how far that axis turned: spinning about it leaves a pen in its holder where it was. A rod lying down that turns
    about its axis is rolling, and that turn counts."""
    if spin is None:
        return quaternion_angle(q0, q1)
    a0 = _rotate(q0, spin)
    if abs(float(a0[2])) < STANDING_COS:
        return quaternion_angle(q0, q1)
    return math.acos(max(-1.0, min(1.0, float(np.dot(a0, _rotate(q1, spin))))))
