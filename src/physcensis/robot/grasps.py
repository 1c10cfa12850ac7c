"""Parallel-jaw grasps of one asset: antipodal candidates on its collision parts, kept when a free-floating Panda hand
lifts and shakes the object without losing it; cached per asset; filtered per scene by the open hand's collisions.

A grasp is the TCP's pose in the object's body frame: the hand's +z is the approach, its y the jaw axis (the fingers
close along it), the TCP sits between the fingertip pads.
"""

from __future__ import annotations

import copy
import hashlib
import io
import logging
from collections.abc import Iterator
from dataclasses import dataclass

import mujoco
import numpy as np
from mujoco import rollout

from physcensis.assets.cache import cache_root
from physcensis.errors import PhyscensisError
from physcensis.fileio import atomic_write_bytes
from physcensis.robot import hand as free_hand
from physcensis.robot import panda
from physcensis.robot.convex import (
    ConvexPiece,
    body_pieces,
    collision_geoms,
    exit_through_union,
    last_exit_through_union,
    sample_surface,
)
from physcensis.robot.scratch import add_frozen_geoms, add_object_copy, copy_options, frozen_owner
from physcensis.robot.world import RobotWorld

log = logging.getLogger(__name__)
GRASP_VERSION = 6  # 2: stiffer fingers; 3: 3 mm clearance a side; 4: across hollows; 5-6: per asset
JAW_OPEN = 2.0 * panda.FINGER_OPEN  # 8 cm between the pads
WIDTH_MARGIN = 0.003  # each side: the object must fit between the open jaws with this much room
MIN_WIDTH = 0.0015
FRICTION_SAFETY = 0.8  # the friction cone is taken this much narrower than the contact's friction says
APPROACH_ANGLES = 12  # approach directions tried around each jaw axis
NOT_FROM_BELOW = -0.3  # approaches pointing up more than this (z of the approach axis) would come through the floor
CONTACT_DEPTHS = (0.0075, 0.003, -0.003, -0.009)  # where the pads touch, along the approach, from the TCP (metres)
FINGER_BOXES = (  # the open hand's parts as boxes in the hand frame (min, max): palm, left finger, right finger
    ((-0.032, -0.104, -0.026), (0.032, 0.101, 0.066)),
    ((-0.011, 0.040, 0.0585), (0.011, 0.067, 0.1125)),
    ((-0.011, -0.067, 0.0585), (0.011, -0.040, 0.1125)),
)
OPEN_PENETRATION = 2e-4  # metres: deeper than this and the open hand collides
CLOSED_INSET_M = 0.001  # the closed-hand check puts each finger this far inside the grasp's width
LIFT_TESTS = 48  # candidates lift-tested per asset
LIFT_HEIGHT = 0.15
SIDEWAYS = 0.08
SHAKE = 0.01
HELD_SLIP = 0.01  # the object's point between the pads may move this much relative to the hand during the carry
HELD_SWING_DEG = 15.0  # and the object may turn this much in the hand
SPREAD_DISTANCE = 0.012  # lift-tested candidates closer than this with a similar approach count as the same grasp
SPREAD_COS = 0.9
FINGER_FRICTION = panda.FINGER_FRICTION[0]
FROM_ABOVE = 0.64  # an approach whose axis points down at least this much (cos 50 degrees) counts as from above
_CLOSE_S, _LIFT_S, _SIDE_S, _SHAKE_S, _HOLD_S = 0.35, 0.5, 0.4, 0.4, 0.15


class GraspError(PhyscensisError):
    """No grasp can be computed for an object (no collision part, nothing in the scene of that name)."""


@dataclass(frozen=True, eq=False)
class Grasp:
    """The TCP's pose in the object's body frame (4x4), the object's width between the two contacts (metres), and a
    score (higher is better)."""

    object_T_tcp: np.ndarray
    width: float
    score: float

    @property
    def approach(self) -> np.ndarray:
        """The approach axis (the hand's +z) in the object's frame."""
        return self.object_T_tcp[:3, 2].copy()


@dataclass
class _Pairs:
    """Antipodal contact pairs: centre, jaw axis, width and quality (cosine of the far normal to the axis)."""

    centre: np.ndarray
    axis: np.ndarray
    width: np.ndarray
    quality: np.ndarray


def _antipodal_pairs(pieces: list[ConvexPiece], n: int, friction: float, rng: np.random.Generator) -> _Pairs:
    """Pairs across the wall the ray first crosses (a pinch of a rim), and, where the ray goes on across a hollow,
    pairs with the far side's outside (the whole cup or bowl held between the jaws)."""
    points, normals = sample_surface(pieces, n, rng)
    inward = -normals
    origins = points + inward * 1e-5
    near, near_normal = exit_through_union(pieces, origins, inward)
    far, far_normal = last_exit_through_union(pieces, origins, inward)
    hollow = np.isfinite(near) & (far > near + 1e-3)
    return _pairs_to(
        np.concatenate([points, points[hollow]]),
        np.concatenate([inward, inward[hollow]]),
        np.concatenate([near, far[hollow]]),
        np.concatenate([near_normal, far_normal[hollow]]),
        friction,
    )


def _pairs_to(
    points: np.ndarray, inward: np.ndarray, reach: np.ndarray, far_normal: np.ndarray, friction: float
) -> _Pairs:
    cone = np.cos(np.arctan(friction * FRICTION_SAFETY))
    with np.errstate(invalid="ignore"):
        quality = np.einsum("ij,ij->i", far_normal, inward)
    fits = np.isfinite(reach) & (reach >= MIN_WIDTH) & (reach <= JAW_OPEN - 2.0 * WIDTH_MARGIN)
    keep = fits & (quality >= cone)
    return _Pairs(
        centre=points[keep] + inward[keep] * reach[keep, None] / 2.0,
        axis=inward[keep],
        width=reach[keep],
        quality=quality[keep],
    )


def _perpendicular_basis(axis: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit vectors perpendicular to each axis; the first points down as much as the axis allows."""
    down = np.array([0.0, 0.0, -1.0])
    first = down - (axis @ down)[:, None] * axis
    norm = np.linalg.norm(first, axis=1)
    vertical = norm < 1e-6
    first[vertical] = np.array([1.0, 0.0, 0.0])
    first /= np.linalg.norm(first, axis=1)[:, None]
    return first, np.cross(axis, first)


def _candidate_poses(pairs: _Pairs) -> tuple[np.ndarray, np.ndarray]:
    """TCP poses (k, 4, 4) for every pair x approach angle x contact depth, and the index of each one's pair."""
    first, second = _perpendicular_basis(pairs.axis)
    angles = np.arange(APPROACH_ANGLES) * (2.0 * np.pi / APPROACH_ANGLES)
    approach = np.cos(angles)[None, :, None] * first[:, None] + np.sin(angles)[None, :, None] * second[:, None]
    jaw = np.broadcast_to(pairs.axis[:, None], approach.shape)
    side = np.cross(jaw, approach)
    depth = np.asarray(CONTACT_DEPTHS)
    origin = pairs.centre[:, None, None] - depth[None, None, :, None] * approach[:, :, None]
    count = len(pairs.centre) * APPROACH_ANGLES * len(depth)
    poses = np.tile(np.eye(4), (count, 1, 1))
    rotation = np.stack([side, jaw, approach], axis=-1)  # (pairs, angles, 3, 3), columns x y z
    poses[:, :3, :3] = np.repeat(rotation, len(depth), axis=1).reshape(-1, 3, 3)
    poses[:, :3, 3] = origin.reshape(-1, 3)
    owner = np.repeat(np.arange(len(pairs.centre)), APPROACH_ANGLES * len(depth))
    upward = poses[:, 2, 2] >= -NOT_FROM_BELOW
    return poses[~upward], owner[~upward]


def _boxes_hit(points: np.ndarray, pose: np.ndarray) -> bool:
    """Whether any object point lies inside the open hand's boxes at this TCP pose (the cheap check)."""
    frame = pose @ free_hand.tcp_T_hand()
    local = (points - frame[:3, 3]) @ frame[:3, :3]
    for low, high in FINGER_BOXES:
        if np.any(np.all((local > np.asarray(low) + 1e-3) & (local < np.asarray(high) - 1e-3), axis=1)):
            return True
    return False


def _scores(pairs: _Pairs, owner: np.ndarray, poses: np.ndarray, com: np.ndarray, size: float, cone: float):
    alignment = (pairs.quality[owner] - cone) / max(1.0 - cone, 1e-9)
    off_centre = np.linalg.norm(pairs.centre[owner] - com, axis=1) / size
    downward = -poses[:, 2, 2]
    # how far the contact is from the pads' middle (at the TCP): the very tip slips off rounded rims
    off_pad = np.abs(
        np.einsum("kij,kj->ki", poses[:, :3, :3].transpose(0, 2, 1), pairs.centre[owner] - poses[:, :3, 3])
    )
    off_pad_score = 1.0 - np.clip(off_pad[:, 2] / 0.01, 0.0, 1.0)
    return 0.35 * alignment + 0.25 * (1.0 - np.clip(off_centre, 0.0, 1.0)) + 0.25 * downward + 0.15 * off_pad_score


class _LiftRig:
    """The object (free, resting on a floor at z = 0) and the free hand in one model."""

    OBJECT = "object"

    def __init__(self, model: mujoco.MjModel, body: int, pieces: list[ConvexPiece]) -> None:
        spec = mujoco.MjSpec()
        copy_options(spec, model)
        spec.option.timestep = 0.002
        spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
        spec.worldbody.add_geom(name="floor", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[1.0, 1.0, 0.05])
        add_object_copy(spec, model, body, self.OBJECT)
        free_hand.add_free_hand(spec)
        self.model = spec.compile()
        self.data = mujoco.MjData(self.model)
        self.hand = free_hand.HandIndex.of(self.model)
        obj = int(self.model.body(self.OBJECT).id)
        self.object_qpos = int(self.model.jnt_qposadr[self.model.body_jntadr[obj]])
        self.object_geoms = frozenset(collision_geoms(self.model, obj))
        lowest = min(float(piece.vertices[:, 2].min()) for piece in pieces)
        self.rest = np.eye(4)
        self.rest[2, 3] = -lowest  # the object's body frame as it stands on the floor

    def pose_open(self, object_T_tcp: np.ndarray) -> None:
        data = self.data
        mujoco.mj_resetData(self.model, data)
        data.qpos[self.object_qpos : self.object_qpos + 7] = free_hand.pose_to_qpos(self.rest)
        free_hand.place_hand(self.model, data, self.hand, self.rest @ object_T_tcp, panda.FINGER_OPEN)
        mujoco.mj_forward(self.model, data)

    def open_hand_collides(self, object_T_tcp: np.ndarray) -> bool:
        self.pose_open(object_T_tcp)
        for contact in self.data.contact[: self.data.ncon]:
            if contact.dist < -OPEN_PENETRATION and (
                contact.geom[0] in self.hand.geoms or contact.geom[1] in self.hand.geoms
            ):
                return True
        return False


def sample_antipodal(
    model: mujoco.MjModel,
    body: int,
    *,
    n: int = 5000,
    rng: np.random.Generator,
    limit: int | None = None,
    rig: _LiftRig | None = None,
) -> list[Grasp]:
    """Antipodal grasp candidates on the body's collision parts (in its frame), best first: pairs of surface points
    whose normals lie in each other's friction cone and that fit the open hand, each with several approaches and
    contact depths, kept when the open hand misses the object and a floor under it (boxes first, then MuJoCo).
    `limit` stops after that many, spread over the object rather than crowded around the best."""
    pieces = body_pieces(model, body)
    friction = min(float(min(model.geom_friction[g, 0] for g in collision_geoms(model, body))), FINGER_FRICTION)
    pairs = _antipodal_pairs(pieces, n, friction, rng)
    if len(pairs.centre) == 0:
        return []
    poses, owner = _candidate_poses(pairs)
    surface, _ = sample_surface(pieces, 800, rng)
    points = np.concatenate([surface, *(piece.vertices for piece in pieces)])
    lowest = min(float(piece.vertices[:, 2].min()) for piece in pieces)
    clear = _fingertips_above(poses, lowest)
    poses, owner = poses[clear], owner[clear]
    cone = float(np.cos(np.arctan(friction * FRICTION_SAFETY)))
    extent = float(np.ptp(np.concatenate([piece.vertices for piece in pieces]), axis=0).max())
    scores = _scores(pairs, owner, poses, model.body_ipos[body], extent, cone)
    rig = rig or _LiftRig(model, body, pieces)
    kept: list[Grasp] = []
    for i in _spread_order(poses, scores, rng):
        if not _boxes_hit(points, poses[i]) and not rig.open_hand_collides(poses[i]):
            kept.append(Grasp(poses[i], float(pairs.width[owner[i]]), float(scores[i])))
            if limit is not None and len(kept) >= limit:
                break
    return kept


def _spread_order(poses: np.ndarray, scores: np.ndarray, rng: np.random.Generator) -> Iterator[int]:
    """Candidates best first, but each next one is taken only if no earlier one has nearly the same TCP position
    and approach; the crowded ones follow at the end, best first."""
    jitter = rng.random(len(scores)) * 1e-6  # a seeded tie-break between equal scores
    order = np.argsort(-(scores + jitter), kind="stable")
    taken: list[int] = []
    crowded: list[int] = []
    for i in order:
        if taken and _near_any(poses[i], poses[taken]):
            crowded.append(int(i))
        else:
            taken.append(int(i))
            yield int(i)
    yield from crowded


def _near_any(pose: np.ndarray, others: np.ndarray) -> bool:
    close = np.linalg.norm(others[:, :3, 3] - pose[:3, 3], axis=1) < SPREAD_DISTANCE
    similar = others[:, :3, 2] @ pose[:3, 2] > SPREAD_COS
    return bool(np.any(close & similar))


def _fingertips_above(poses: np.ndarray, floor: float) -> np.ndarray:
    """Whether the open fingertips stay above the floor the object stands on (its lowest point)."""
    tips = np.array([[0.0, y, FINGER_BOXES[1][1][2]] for y in (0.054, -0.054)]) - [0, 0, panda.TCP_OFFSET]
    world = np.einsum("kij,nj->kni", poses[:, :3, :3], tips) + poses[:, None, :3, 3]
    return world[:, :, 2].min(axis=1) > floor + 1e-3


def _carry_offsets(timestep: float) -> np.ndarray:
    """The hand's displacement from its grasp pose at every step after closing: lift, move sideways, shake, hold."""

    def ease(seconds: float) -> np.ndarray:
        t = np.linspace(0.0, 1.0, max(int(round(seconds / timestep)), 1))
        return 0.5 - 0.5 * np.cos(np.pi * t)

    lift = np.outer(ease(_LIFT_S), [0.0, 0.0, LIFT_HEIGHT])
    side = np.outer(ease(_SIDE_S), [SIDEWAYS, 0.0, 0.0]) + [0.0, 0.0, LIFT_HEIGHT]
    wave = np.sin(np.linspace(0.0, 2.0 * np.pi, max(int(round(_SHAKE_S / timestep)), 1)))
    shake = np.outer(wave, [0.0, SHAKE, SHAKE / 2.0]) + [SIDEWAYS, 0.0, LIFT_HEIGHT]
    hold = np.tile([SIDEWAYS, 0.0, LIFT_HEIGHT], (max(int(round(_HOLD_S / timestep)), 1), 1))
    return np.concatenate([lift, side, shake, hold])


@dataclass
class LiftResult:
    """Per candidate: held or not, and how far the object slipped in the hand during the carry (metres)."""

    held: np.ndarray
    slip: np.ndarray
    rise: np.ndarray
    swing: np.ndarray  # degrees


def lift_test(rig: _LiftRig, candidates: list[Grasp], *, threads: int = 1) -> LiftResult:
    """Close the hand on the resting object at each grasp, lift it 15 cm, move it sideways and shake it; held when
    the object rose with the hand and moved less than 1 cm relative to it after closing."""
    if not candidates:
        return LiftResult(np.zeros(0, dtype=bool), np.zeros(0), np.zeros(0), np.zeros(0))
    model = rig.model
    datas = [mujoco.MjData(model) for _ in range(max(threads, 1))]
    full = mujoco.mjtState.mjSTATE_FULLPHYSICS
    spec = mujoco.mjtState.mjSTATE_CTRL | mujoco.mjtState.mjSTATE_MOCAP_POS | mujoco.mjtState.mjSTATE_MOCAP_QUAT
    starts = np.array([_open_state(rig, grasp.object_T_tcp, full) for grasp in candidates])
    hand_pose = [free_hand.pose_to_qpos(rig.rest @ grasp.object_T_tcp @ free_hand.tcp_T_hand()) for grasp in candidates]
    grasp_pos = np.array([pose[:3] for pose in hand_pose])
    grasp_quat = np.array([pose[3:] for pose in hand_pose])
    close_steps = int(round(_CLOSE_S / model.opt.timestep))
    closing = _controls(grasp_pos[:, None, :].repeat(close_steps, axis=1), grasp_quat)
    closed = rollout.rollout(model, datas, starts, closing, control_spec=spec)[0][:, -1]
    offsets = _carry_offsets(model.opt.timestep)
    carrying = _controls(grasp_pos[:, None, :] + offsets[None], grasp_quat)
    carried = rollout.rollout(model, datas, closed, carrying, control_spec=spec)[0][:, -1]
    return _judge(rig, closed, carried, full)


def _controls(positions: np.ndarray, quats: np.ndarray) -> np.ndarray:
    """Rollout inputs: the gripper closed, the mocap at `positions` (batch, steps, 3) with a fixed orientation."""
    batch, steps, _ = positions.shape
    ctrl = np.full((batch, steps, 1), panda.FINGER_CLOSED)
    return np.concatenate([ctrl, positions, np.broadcast_to(quats[:, None, :], (batch, steps, 4))], axis=2)


def _open_state(rig: _LiftRig, object_T_tcp: np.ndarray, kind: int) -> np.ndarray:
    rig.pose_open(object_T_tcp)
    state = np.empty(mujoco.mj_stateSize(rig.model, kind))
    mujoco.mj_getState(rig.model, rig.data, state, kind)
    return state


def _hand_T_object(rig: _LiftRig, state: np.ndarray, kind: int) -> np.ndarray:
    mujoco.mj_setState(rig.model, rig.data, state, kind)
    qpos = rig.data.qpos
    hand = free_hand.qpos_to_pose(qpos[rig.hand.hand_qpos : rig.hand.hand_qpos + 7])
    obj = free_hand.qpos_to_pose(qpos[rig.object_qpos : rig.object_qpos + 7])
    return np.linalg.inv(hand) @ obj


def _judge(rig: _LiftRig, closed: np.ndarray, carried: np.ndarray, kind: int) -> LiftResult:
    held, slip, rise, turn = [], [], [], []
    grasp_point = np.array([0.0, 0.0, panda.TCP_OFFSET])  # in the hand's frame: what the pads hold
    for after_close, end in zip(closed, carried, strict=True):
        before = _hand_T_object(rig, after_close, kind)
        closed_z = rig.data.qpos[rig.object_qpos + 2]
        after = _hand_T_object(rig, end, kind)
        change = after @ np.linalg.inv(before)  # how the object moved in the hand's frame
        moved = float(np.linalg.norm(change[:3, :3] @ grasp_point + change[:3, 3] - grasp_point))
        swing = float(np.degrees(np.arccos(np.clip((np.trace(change[:3, :3]) - 1.0) / 2.0, -1.0, 1.0))))
        risen = float(rig.data.qpos[rig.object_qpos + 2] - closed_z)
        slip.append(moved)
        rise.append(risen)
        turn.append(swing)
        held.append(moved < HELD_SLIP and swing < HELD_SWING_DEG and risen > LIFT_HEIGHT / 2.0)
    return LiftResult(np.array(held), np.array(slip), np.array(rise), np.array(turn))


def _geometry_key(model: mujoco.MjModel, body: int, asset: str, counts: tuple[int, int, int]) -> str:
    """Asset name plus a hash of everything the tested grasps depend on: collision geometry, contact parameters,
    mass and inertia, the sampling count and seed, and GRASP_VERSION."""
    digest = hashlib.sha256(f"v{GRASP_VERSION}:{counts}".encode())
    for values in (model.body_mass[body : body + 1], model.body_ipos[body], model.body_inertia[body]):
        digest.update(np.round(np.asarray(values, dtype=float), 7).tobytes())
    for geom in collision_geoms(model, body):
        for values in (model.geom_type[geom : geom + 1], model.geom_size[geom], model.geom_pos[geom]):
            digest.update(np.round(np.asarray(values, dtype=float), 7).tobytes())
        digest.update(np.round(model.geom_quat[geom], 7).tobytes() + np.round(model.geom_friction[geom], 5).tobytes())
        if model.geom_type[geom] == mujoco.mjtGeom.mjGEOM_MESH:
            mesh = int(model.geom_dataid[geom])
            start = int(model.mesh_vertadr[mesh])
            digest.update(np.round(model.mesh_vert[start : start + int(model.mesh_vertnum[mesh])], 6).tobytes())
    safe = "".join(ch if ch.isalnum() or ch in "-_" else "_" for ch in asset)[:80]
    return f"{safe}-{digest.hexdigest()[:16]}"


def cache_path(world: RobotWorld, object_id: str, n_candidates: int, seed: int, lift_tests: int = LIFT_TESTS) -> str:
    """Where the asset's tested grasps are kept."""
    return _cache_path(_trial_model(world, object_id), world, object_id, (n_candidates, seed, lift_tests))


def _cache_path(trial: mujoco.MjModel, world: RobotWorld, object_id: str, counts: tuple[int, int, int]) -> str:
    asset = world.scene.object(object_id).asset
    return str(cache_root() / "grasps" / f"{_geometry_key(trial, world.object_bodies[object_id], asset, counts)}.npz")


def _trial_model(world: RobotWorld, object_id: str) -> mujoco.MjModel:
    """The world's model with the object as its asset, not this instance: the heaviest mass of the asset's range
    (the hardest to hold), the middle of its friction range (which only shapes the sampler's friction cone: the
    pads' own friction rules their contacts) and the nominal centre of mass. Every instance of the asset (scenes
    draw masses and frictions from those ranges) is then held by the same grasps, tested and cached once per asset.
    An asset the built-in catalogue does not know (a user's library) is tried as it is in this scene."""
    from physcensis.assets.catalogue import default_catalogue

    try:
        asset = default_catalogue().get(world.scene.object(object_id).asset)
    except KeyError:
        return world.model
    model = copy.deepcopy(world.model)
    body = world.object_bodies[object_id]
    heaviest = float(asset.mass_range[1])
    model.body_inertia[body] *= heaviest / float(model.body_mass[body])
    model.body_mass[body] = heaviest
    model.body_ipos[body] = asset.com
    for geom in collision_geoms(model, body):
        model.geom_friction[geom, 0] = float(np.mean(asset.friction_range))
    return model


def _save(path: str, grasps: list[Grasp]) -> None:
    buffer = io.BytesIO()
    np.savez(
        buffer,
        poses=np.array([g.object_T_tcp for g in grasps]).reshape(-1, 4, 4),
        widths=np.array([g.width for g in grasps], dtype=float),
        scores=np.array([g.score for g in grasps], dtype=float),
    )
    try:
        atomic_write_bytes(path, buffer.getvalue())
    except OSError as err:  # a read-only cache costs time, not results
        log.warning("grasp cache: cannot write %s (%s)", path, err)


def _load(path: str) -> list[Grasp] | None:
    try:
        with np.load(path) as stored:
            poses, widths, scores = stored["poses"], stored["widths"], stored["scores"]
    except FileNotFoundError:
        return None
    except (OSError, ValueError, KeyError) as err:
        log.warning("grasp cache: %s is unreadable (%s); sampling again", path, err)
        return None
    return [Grasp(p, float(w), float(s)) for p, w, s in zip(poses, widths, scores, strict=True)]


def tested_grasps(
    model: mujoco.MjModel, body: int, *, n_candidates: int, seed: int, lift_tests: int = LIFT_TESTS
) -> list[Grasp]:
    """Sample candidates on the body and keep those that hold in the lift test, best first."""
    rig = _LiftRig(model, body, body_pieces(model, body))
    rng = np.random.default_rng(seed)
    candidates = sample_antipodal(model, body, n=n_candidates, rng=rng, limit=lift_tests, rig=rig)
    result = lift_test(rig, candidates)
    kept = [
        Grasp(grasp.object_T_tcp, grasp.width, grasp.score - float(slip) / HELD_SLIP * 0.1)
        for grasp, held, slip in zip(candidates, result.held, result.slip, strict=True)
        if held
    ]
    return sorted(kept, key=lambda grasp: -grasp.score)


def grasps_for(
    world: RobotWorld, object_id: str, *, n_candidates: int = 2000, seed: int = 0, lift_tests: int = LIFT_TESTS
) -> list[Grasp]:
    """The object's asset's grasps that held in the lift test at the asset's hardest mass and friction, from the
    cache when this asset (same collision geometry) was done before. The seed is part of the key: pass the same one
    to share the cache across scenes."""
    if object_id not in world.object_bodies:
        raise GraspError(f"no placed object {object_id!r} in the scene (objects: {', '.join(world.object_bodies)})")
    trial = _trial_model(world, object_id)
    path = _cache_path(trial, world, object_id, (n_candidates, seed, lift_tests))
    cached = _load(path)
    if cached is not None:
        return cached
    body = world.object_bodies[object_id]
    grasps = tested_grasps(trial, body, n_candidates=n_candidates, seed=seed, lift_tests=lift_tests)
    _save(path, grasps)
    return grasps


class SceneHand:
    """The open hand alone among the scene's frozen collision geoms (support, objects; not the arm)."""

    def __init__(self, world: RobotWorld) -> None:
        spec = mujoco.MjSpec()
        copy_options(spec, world.model)
        bodies = [b for b in range(world.model.nbody) if b not in world.robot_bodies]
        add_frozen_geoms(spec, world.model, world.data, bodies)
        free_hand.add_free_hand(spec)
        self.model = spec.compile()
        self.data = mujoco.MjData(self.model)
        self.hand = free_hand.HandIndex.of(self.model)

    def collides(self, world_T_tcp: np.ndarray, opening: float = panda.FINGER_OPEN, spare: str | None = None) -> bool:
        """Whether the hand at `world_T_tcp`, each finger `opening` out, cuts into anything (but `spare`, a body's
        name, when given)."""
        free_hand.place_hand(self.model, self.data, self.hand, world_T_tcp, opening)
        mujoco.mj_forward(self.model, self.data)
        for contact in self.data.contact[: self.data.ncon]:
            first, second = contact.geom
            touches_hand = first in self.hand.geoms or second in self.hand.geoms
            if not touches_hand or contact.dist >= -OPEN_PENETRATION:
                continue
            other = second if first in self.hand.geoms else first
            if spare is None or frozen_owner(self.model, int(other)) != spare:
                return True
        return False

    def pinches_another(self, world_T_tcp: np.ndarray, width: float, object_body: str) -> bool:
        """Whether the fingers, closed to the grasp's width, would squeeze something besides the object (a finger
        that went down inside a neighbouring cup pulls its wall along)."""
        return self.collides(world_T_tcp, max(0.0, width / 2 - CLOSED_INSET_M), spare=object_body)


def grasps_in_scene(world: RobotWorld, object_id: str, grasps: list[Grasp]) -> list[tuple[Grasp, np.ndarray]]:
    """Each grasp with its world TCP pose at the object's current pose, approaches from above first, then by score;
    grasps whose open hand would collide with the support or other objects there, or whose closing fingers would
    squeeze another object too, are dropped."""
    if object_id not in world.object_bodies:
        raise GraspError(f"no placed object {object_id!r} in the scene (objects: {', '.join(world.object_bodies)})")
    world_T_object = free_hand.qpos_to_pose(world.object_poses()[object_id])
    posed = [(grasp, world_T_object @ grasp.object_T_tcp) for grasp in grasps]
    posed.sort(key=lambda item: (-float(-item[1][2, 2] >= FROM_ABOVE), -item[0].score))
    if not posed:
        return []
    scene_hand = SceneHand(world)
    body = world.model.body(world.object_bodies[object_id]).name
    return [
        (grasp, tcp)
        for grasp, tcp in posed
        if not scene_hand.collides(tcp) and not scene_hand.pinches_another(tcp, grasp.width, body)
    ]
