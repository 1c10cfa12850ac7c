"""Goal poses for the picked object: on the target's top surface or inside its cavity, upright as it stands now at any
yaw, lowered until it touches, free of penetration and at rest after a short simulation.

The checks run in a scratch model: the scene's collision geoms frozen where they are (the arm and the picked object's
old place left out) and a free copy of the picked object with its mass, inertia and friction.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from typing import Literal

import mujoco
import numpy as np
from scipy.spatial import ConvexHull

from physcensis.errors import PhyscensisError
from physcensis.geometry.voxels import yaw_matrix
from physcensis.robot.convex import ConvexPiece, body_pieces
from physcensis.robot.hand import pose_to_qpos, qpos_to_pose
from physcensis.robot.scratch import add_frozen_geoms, add_object_copy, copy_options, frozen_owner
from physcensis.robot.world import RobotWorld

Relation = Literal["on", "in"]
TOUCH_PENETRATION = 5e-4  # metres the lowered object may sink into what it lands on
SUPPORT_PROBE = 1e-3  # lowered this much further, the object's contacts name what carries it
GOAL_SETTLE_S = 0.4
REST_MOVE = 0.005  # metres: further than this during the settle and the pose is not at rest
REST_TILT_DEG = 5.0
TRIES_PER_GOAL = 6  # candidate poses tried per pose asked for
ON_SPREAD = 0.8  # "on": sampled within this fraction of the target's half extents
IN_SPREAD = 0.5  # "in": nearer the middle, where a cavity is deepest
LIFT_CLEARANCE = 0.05
IN_DEPTH = 0.01  # "in": the object's bottom ends at least this far below the target's rim
BASE_HEIGHT = 0.01  # "on": the object's points this close to its lowest one make its base
FOOTPRINT_INSET = 0.005  # and must stay this far inside the target's outline (a rim is no place to stand)
_COPY = "goal_object"


class GoalError(PhyscensisError):
    """A goal cannot be asked for (unknown object, target is the object itself, unknown relation)."""


class GoalPoses(list):
    """World poses (7 numbers: position, wxyz quaternion), best first; when empty, `reason` says why."""

    def __init__(self, poses: list[np.ndarray], reason: str | None = None) -> None:
        super().__init__(poses)
        self.reason = reason


@dataclass
class _Footprint:
    """The target's extent in the world: centre and half extents in x and y, its top (rim) height and bottom."""

    centre: np.ndarray
    half: np.ndarray
    top: float
    bottom: float
    outline: np.ndarray  # (k, 3): the 2D hull's edges as n . xy + d <= 0 inside


class _Scratch:
    """The scene frozen around a free copy of the picked object."""

    def __init__(self, world: RobotWorld, object_id: str) -> None:
        spec = mujoco.MjSpec()
        copy_options(spec, world.model)
        picked = world.object_bodies[object_id]
        frozen = [b for b in range(world.model.nbody) if b not in world.robot_bodies and b != picked]
        add_frozen_geoms(spec, world.model, world.data, frozen)
        add_object_copy(spec, world.model, picked, _COPY)
        self.model = spec.compile()
        self.data = mujoco.MjData(self.model)
        body = int(self.model.body(_COPY).id)
        self.qpos = int(self.model.jnt_qposadr[self.model.body_jntadr[body]])
        self.dof = int(self.model.jnt_dofadr[self.model.body_jntadr[body]])
        self.geoms = frozenset(g for g in range(self.model.ngeom) if int(self.model.geom_bodyid[g]) == body)

    def put(self, pose: np.ndarray) -> None:
        self.data.qpos[self.qpos : self.qpos + 7] = pose
        self.data.qvel[self.dof : self.dof + 6] = 0.0
        mujoco.mj_forward(self.model, self.data)

    def touching(self) -> dict[str, float]:
        """Whose parts the copy penetrates now, and how deep."""
        depth: dict[str, float] = {}
        for contact in self.data.contact[: self.data.ncon]:
            mine = contact.geom[0] in self.geoms, contact.geom[1] in self.geoms
            if mine[0] == mine[1]:
                continue
            other = frozen_owner(self.model, int(contact.geom[1] if mine[0] else contact.geom[0]))
            depth[other] = max(depth.get(other, 0.0), -float(contact.dist))
        return depth

    def deepest(self, pose: np.ndarray) -> tuple[float, str]:
        self.put(pose)
        depth = self.touching()
        if not depth:
            return 0.0, ""
        other = max(depth, key=lambda name: depth[name])
        return depth[other], other


def _footprint(world: RobotWorld, target_id: str) -> _Footprint:
    model, body = world.model, world.object_bodies[target_id]
    rotation = world.data.xmat[body].reshape(3, 3)
    points = np.concatenate([p.vertices for p in body_pieces(model, body)]) @ rotation.T + world.data.xpos[body]
    low, high = points.min(axis=0), points.max(axis=0)
    outline = ConvexHull(points[:, :2]).equations
    return _Footprint((low[:2] + high[:2]) / 2.0, (high[:2] - low[:2]) / 2.0, float(high[2]), float(low[2]), outline)


def _lowest(pieces: list[ConvexPiece], rotation: np.ndarray) -> float:
    return float(min((piece.vertices @ rotation.T)[:, 2].min() for piece in pieces))


def _lower(scratch: _Scratch, pose: np.ndarray, z_low: float, iterations: int = 14) -> tuple[np.ndarray | None, str]:
    """The pose lowered until it touches (bisection on the height), or None and whose part it already hits above."""
    depth, other = scratch.deepest(pose)
    if depth > TOUCH_PENETRATION:
        return None, f"collide with {other}"
    low, high = z_low, float(pose[2])
    trial = pose.copy()
    for _ in range(iterations):
        trial[2] = (low + high) / 2.0
        if scratch.deepest(trial)[0] > TOUCH_PENETRATION:
            low = float(trial[2])
        else:
            high = float(trial[2])
    trial[2] = high
    return trial, ""


def _supporters(scratch: _Scratch, pose: np.ndarray) -> set[str]:
    probe = pose.copy()
    probe[2] -= SUPPORT_PROBE
    scratch.put(probe)
    return set(scratch.touching())


def _settles(scratch: _Scratch, pose: np.ndarray) -> str:
    """'' when the object stays put through a short simulation, else how it moved."""
    scratch.put(pose)
    for _ in range(int(round(GOAL_SETTLE_S / scratch.model.opt.timestep))):
        mujoco.mj_step(scratch.model, scratch.data)
    end = scratch.data.qpos[scratch.qpos : scratch.qpos + 7]
    moved = float(np.linalg.norm(end[:3] - pose[:3]))
    turn = np.degrees(2.0 * np.arccos(min(1.0, abs(float(np.dot(end[3:], pose[3:]))))))
    if moved > REST_MOVE or turn > REST_TILT_DEG:
        return "slide or tip over"
    return ""


@dataclass
class _Request:
    world: RobotWorld
    object_id: str
    relation: Relation
    target_id: str
    scratch: _Scratch
    pieces: list[ConvexPiece]
    rotation: np.ndarray  # the object's rotation now
    area: _Footprint


def _try(request: _Request, rng: np.random.Generator) -> tuple[np.ndarray | None, str]:
    """One sampled pose, or None and why it failed."""
    spread = ON_SPREAD if request.relation == "on" else IN_SPREAD
    xy = request.area.centre + (rng.random(2) * 2.0 - 1.0) * request.area.half * spread
    rotation = yaw_matrix(float(rng.uniform(0.0, 2.0 * np.pi))) @ request.rotation
    lowest = _lowest(request.pieces, rotation)
    frame = np.eye(4)
    frame[:3, :3] = rotation
    frame[:3, 3] = [*xy, request.area.top + LIFT_CLEARANCE - lowest]
    start = pose_to_qpos(frame)
    pose, why = _lower(request.scratch, start, request.area.bottom - 0.05 - lowest)
    if pose is None:
        return None, why
    if request.relation == "on" and not _footprint_fits(request, rotation, pose[:3]):
        return None, f"overhang {request.target_id}'s outline"
    if request.relation == "in" and not _centre_of_mass_inside(request, rotation, pose[:3]):
        return None, f"keep the centre of mass within {request.target_id}'s opening and below its rim"
    under = _supporters(request.scratch, pose)
    if under != {request.target_id}:
        named = ", ".join(sorted(name or "?" for name in under)) or "nothing"
        return None, f"rest on {named}"
    if request.relation == "in" and pose[2] + lowest > request.area.top - IN_DEPTH:
        return None, f"stay above {request.target_id}'s rim"
    moved = _settles(request.scratch, pose)
    return (None, moved) if moved else (pose, "")


def _footprint_fits(request: _Request, rotation: np.ndarray, position: np.ndarray) -> bool:
    """Whether the object's base (its parts' points within BASE_HEIGHT of its lowest) lies within the target's
    outline seen from above."""
    points = np.concatenate([piece.vertices for piece in request.pieces]) @ rotation.T + position
    base = points[points[:, 2] <= points[:, 2].min() + BASE_HEIGHT, :2]
    outline = request.area.outline
    return bool(np.all(base @ outline[:, :2].T + outline[:, 2] <= -FOOTPRINT_INSET))


def _centre_of_mass_inside(request: _Request, rotation: np.ndarray, position: np.ndarray) -> bool:
    """ "In" asks what the verifier asks: the centre of mass within the opening and below the rim (a long fruit may
    lie across a bowl with its ends over the rim, as it would in a kitchen)."""
    body = request.world.object_bodies[request.object_id]
    com = position + rotation @ request.world.model.body_ipos[body]
    outline = request.area.outline
    inside = bool(np.all(com[:2] @ outline[:, :2].T + outline[:, 2] <= -FOOTPRINT_INSET))
    return inside and com[2] < request.area.top


def _check_request(world: RobotWorld, object_id: str, relation: str, target_id: str) -> None:
    for name in (object_id, target_id):
        if name not in world.object_bodies:
            raise GoalError(f"no placed object {name!r} in the scene (objects: {', '.join(world.object_bodies)})")
    if object_id == target_id:
        raise GoalError(f"{object_id} cannot be placed {relation} itself")
    if relation not in ("on", "in"):
        raise GoalError(f"relation {relation!r} is not one of: on, in")


def goal_poses(
    world: RobotWorld, object_id: str, relation: Relation, target_id: str, *, n: int = 16, rng: np.random.Generator
) -> GoalPoses:
    """Up to n resting, penetration-free world poses (position + wxyz quaternion) of the object on / in the target,
    nearest the target's centre first; an empty result carries the reason."""
    _check_request(world, object_id, relation, target_id)
    body = world.object_bodies[object_id]
    request = _Request(
        world,
        object_id,
        relation,
        target_id,
        _Scratch(world, object_id),
        body_pieces(world.model, body),
        qpos_to_pose(world.object_poses()[object_id])[:3, :3],
        _footprint(world, target_id),
    )
    found: list[np.ndarray] = []
    failures: Counter[str] = Counter()
    tries = 0
    while len(found) < n and tries < n * TRIES_PER_GOAL:
        tries += 1
        pose, why = _try(request, rng)
        if pose is None:
            failures[why] += 1
        else:
            found.append(pose)
    com = world.model.body_ipos[body]
    found.sort(
        key=lambda pose: float(np.linalg.norm((qpos_to_pose(pose)[:3, :3] @ com + pose[:3])[:2] - request.area.centre))
    )
    if found:
        return GoalPoses(found)
    summary = "; ".join(f"{count} {why}" for why, count in failures.most_common(3))
    word = "room on" if relation == "on" else "room in"
    return GoalPoses([], f"no {word} {target_id} for {object_id}: {tries} tried, {summary}")
