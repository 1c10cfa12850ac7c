"""Is an arm configuration free of collisions? Checked on a scratch copy of the world, never its live state.

The copy's collision filters are rewritten so only pairs that matter are tested at all: the robot (and a held object)
against the scene, and robot links against each other. Scene-against-scene pairs (the objects resting on the table)
are never generated. A safety margin on the robot's geoms reports near misses closer than `margin` as contacts.
"""

from __future__ import annotations

import copy
from collections.abc import Iterable
from dataclasses import dataclass

import mujoco
import numpy as np

from physcensis.errors import PhyscensisError
from physcensis.robot import panda
from physcensis.robot.world import PREFIX, RobotWorld

DEFAULT_MARGIN = 0.005  # m
_MOVING = 1  # contype of robot (and held) geoms
_SCENE = 2  # contype of scene geoms: they hit moving geoms only


class UnknownObjectError(PhyscensisError, KeyError):
    """A held or ignored object id that is not a placed object of the scene."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""


@dataclass(frozen=True)
class Held:
    """An object carried rigidly by the hand: its pose in the TCP frame (4x4)."""

    object_id: str
    tcp_T_object: np.ndarray


def pose_matrix(position: np.ndarray, rotation: np.ndarray) -> np.ndarray:
    """A 4x4 transform from a position and a 3x3 rotation."""
    transform = np.eye(4)
    transform[:3, :3] = rotation
    transform[:3, 3] = position
    return transform


class CollisionChecker:
    """Collision queries for arm configurations in a world, with an optional held object and ignored objects."""

    def __init__(
        self,
        world: RobotWorld,
        held: Held | None = None,
        ignore: Iterable[str] = (),
        margin: float = DEFAULT_MARGIN,
    ) -> None:
        ignore = tuple(ignore)
        _check_known(world, ([held.object_id] if held is not None else []) + list(ignore))
        self.world = world
        self.held = held
        self.margin = float(margin)
        self.ignored_bodies = frozenset(world.object_bodies[name] for name in ignore)
        self.model = copy.deepcopy(world.model)
        self.data = mujoco.MjData(self.model)
        self._held_body = world.object_bodies[held.object_id] if held is not None else -1
        self._finger_bodies = frozenset(int(self.model.body(PREFIX + name).id) for name in panda.FINGER_BODIES)
        self._base_body = int(self.model.body(PREFIX + "link0").id)
        self._adjacent = _adjacent_robot_pairs(self.model, world.robot_bodies)
        self._filter_pairs()
        self._counted = self._counted_pairs()
        self.sync()

    def sync(self) -> None:
        """Take the objects' poses and the finger opening from the world's live state."""
        self.data.qpos[:] = self.world.data.qpos

    def _moving_bodies(self) -> frozenset[int]:
        held = {self._held_body} if self._held_body >= 0 else set()
        return self.world.robot_bodies | held

    def _filter_pairs(self) -> None:
        model = self.model
        moving = self._moving_bodies()
        for geom in range(model.ngeom):
            if model.geom_contype[geom] == 0 and model.geom_conaffinity[geom] == 0:
                continue  # a visual geom
            if int(model.geom_bodyid[geom]) in moving:
                model.geom_contype[geom] = _MOVING
                model.geom_conaffinity[geom] = _MOVING | _SCENE
                model.geom_margin[geom] = self.margin
            else:
                model.geom_contype[geom] = _SCENE
                model.geom_conaffinity[geom] = 0

    def _pose(self, q: np.ndarray) -> None:
        world, data = self.world, self.data
        data.qpos[world.arm_qpos] = q
        mujoco.mj_kinematics(self.model, data)
        if self.held is None:
            return
        tcp = pose_matrix(data.site_xpos[world.tcp_site], data.site_xmat[world.tcp_site].reshape(3, 3))
        pose = tcp @ self.held.tcp_T_object
        address = world.object_qpos[self.held.object_id]
        quat = np.zeros(4)
        mujoco.mju_mat2Quat(quat, pose[:3, :3].ravel())
        data.qpos[address : address + 3] = pose[:3, 3]
        data.qpos[address + 3 : address + 7] = quat
        mujoco.mj_kinematics(self.model, data)

    def _counted_pairs(self) -> np.ndarray:
        """(nbody, nbody) booleans: does a contact between these two bodies count?"""
        nbody = self.model.nbody
        counted = np.zeros((nbody, nbody), dtype=bool)
        moving = sorted(self._moving_bodies())
        counted[moving, :] = True
        counted[:, moving] = True
        for pair in self._adjacent:
            a, b = tuple(pair)
            counted[a, b] = counted[b, a] = False
        for finger in self._finger_bodies:
            if self._held_body >= 0:  # the fingers hold it
                counted[self._held_body, finger] = counted[finger, self._held_body] = False
        counted[self._base_body, 0] = counted[0, self._base_body] = False  # the base stands on its pedestal
        ignored = sorted(self.ignored_bodies)
        counted[ignored, :] = False
        counted[:, ignored] = False
        return counted

    def _colliding_pairs(self, q: np.ndarray, first_only: bool) -> list[tuple[int, int]]:
        self._pose(np.asarray(q, dtype=float))
        mujoco.mj_collision(self.model, self.data)
        count = self.data.ncon
        if count == 0:
            return []
        contacts = self.data.contact
        geoms = contacts.geom[:count]
        bodies = self.model.geom_bodyid[geoms]
        hits = np.flatnonzero(self._counted[bodies[:, 0], bodies[:, 1]] & (contacts.dist[:count] < self.margin))
        if first_only:
            hits = hits[:1]
        return [(int(geoms[k, 0]), int(geoms[k, 1])) for k in hits]

    def valid(self, q: np.ndarray) -> bool:
        """True when the arm at `q` (and what it holds) touches nothing within the margin."""
        return not self._colliding_pairs(q, first_only=True)

    def contacts(self, q: np.ndarray) -> list[str]:
        """The colliding pairs at `q`, e.g. "panda/link7 with cup_0", each named once."""
        names: list[str] = []
        for geom1, geom2 in self._colliding_pairs(q, first_only=False):
            first, second = sorted((self._name(geom1), self._name(geom2)), key=_robot_first)
            text = f"{first} with {second}"
            if text not in names:
                names.append(text)
        return names

    def _name(self, geom: int) -> str:
        body = int(self.model.geom_bodyid[geom])
        if body == 0:
            return self.model.geom(geom).name or f"world geom {geom}"
        return self.model.body(body).name


def _check_known(world: RobotWorld, object_ids: list[str]) -> None:
    unknown = [name for name in object_ids if name not in world.object_bodies]
    if unknown:
        known = ", ".join(sorted(world.object_bodies))
        raise UnknownObjectError(f"{', '.join(map(repr, unknown))} not among the scene's placed objects ({known})")


def _robot_first(name: str) -> tuple[int, str]:
    return (0 if name.startswith(PREFIX) else 1, name)


def _moving_link(model: mujoco.MjModel, body: int) -> int:
    """The body itself if a joint moves it, else its nearest ancestor that has one (or the world)."""
    while body > 0 and model.body_jntnum[body] == 0:
        parent = int(model.body_parentid[body])
        if parent == 0:
            return body  # a fixed base: its own link
        body = parent
    return body


def _adjacent_robot_pairs(model: mujoco.MjModel, robot_bodies: frozenset[int]) -> frozenset[frozenset[int]]:
    """Robot body pairs never counted: the same rigid link, a joint's two sides, or siblings on one link (fingers)."""
    link = {body: _moving_link(model, body) for body in robot_bodies}
    parent_link = {body: _moving_link(model, int(model.body_parentid[link[body]])) for body in robot_bodies}
    pairs = set()
    for a in robot_bodies:
        for b in robot_bodies:
            if a >= b:
                continue
            same = link[a] == link[b]
            joined = parent_link[a] == link[b] or parent_link[b] == link[a]
            siblings = parent_link[a] == parent_link[b] and model.body_parentid[link[a]] != 0
            if same or joined or siblings:
                pairs.add(frozenset((a, b)))
    return frozenset(pairs)
