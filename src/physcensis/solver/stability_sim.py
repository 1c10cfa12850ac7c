"""From a scene and perturbations of one object to labelled simulations, and the plain-simulation stand test.

The object's neighbourhood is compiled once: the object, what rests on it and what
touches them move freely, the rest of the scene is held fixed. Every perturbed copy
moves the object, and whatever rests on it, rigidly; the copies start touching what
they rest on (`physics.rollouts.seat`) and run in one batch.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

from physcensis.assets.model import Asset
from physcensis.geometry.voxels import quat_to_matrix
from physcensis.physics.mujoco_engine import TIMESTEP, BuiltScene, MujocoEngine
from physcensis.physics.rollouts import (
    BodyParams,
    FallRule,
    RolloutOutcome,
    Watched,
    free_qpos_address,
    run_batched,
    run_serial,
    seat,
)
from physcensis.scene import PlacedObject, Scene
from physcensis.solver.perturb import POSITION, ROTATION, perturbed_params, rigid_motion

RESTING_NORMAL_Z = 0.5  # a contact normal this close to vertical means one body rests on the other
STAND_CHECK_STEPS = 50


@dataclass(frozen=True)
class StandRule:
    """A plain simulation of the whole scene for `duration_s`: an object stands when no corner of its bounding
    box moves more than `max_move_m`."""

    duration_s: float = 4.0
    max_move_m: float = 0.003


@dataclass(frozen=True)
class StandCheck:
    ok: bool
    moved_m: float
    duration_s: float


@dataclass
class Neighbourhood:
    """A compiled neighbourhood of one object: the object first in `group`, then everything resting on it."""

    built: BuiltScene
    object_id: str
    group: list[str]

    @property
    def body(self) -> int:
        return self.built.body[self.object_id]

    def nominal_poses(self) -> tuple[np.ndarray, np.ndarray]:
        """Positions (m, 3) and quaternions (m, 4) of the group at the scene's state."""
        poses = np.array([self.built.data.qpos[self.built.qpos[g] : self.built.qpos[g] + 7] for g in self.group])
        return poses[:, :3], poses[:, 3:]


def asset_of(engine: MujocoEngine, obj: PlacedObject) -> Asset:
    return engine.catalogue.asset_for(obj.asset, obj.description)


def carried_by_placement(scene: Scene, object_id: str) -> set[str]:
    """Objects placed on (or in) the object, directly or through others."""
    carried: set[str] = set()
    frontier = {object_id}
    while frontier:
        frontier = {o.id for o in scene.placed if o.placement and o.placement.target in frontier} - carried
        carried |= frontier
    return carried


def object_contacts(built: BuiltScene) -> list[tuple[str, str, float]]:
    """(first, second, z of the normal from first to second) for every contact between two objects, at the built
    state (no dynamics)."""
    model, data = built.model, built.data
    mujoco.mj_forward(model, data)
    owner = {b: oid for oid, b in built.body.items()}
    pairs = []
    for i in range(data.ncon):
        contact = data.contact[i]
        a, b = (owner.get(int(model.geom_bodyid[g])) for g in contact.geom)
        if a is not None and b is not None and a != b:
            pairs.append((a, b, float(contact.frame[2])))  # frame[:3] is the normal, from geom 0 to geom 1
    return pairs


def carried_by_contact(built: BuiltScene, object_id: str) -> set[str]:
    """Objects resting on the object at the built state, directly or through others (by contact normals)."""
    above: dict[str, set[str]] = {}
    for a, b, nz in object_contacts(built):
        if nz > RESTING_NORMAL_Z:
            above.setdefault(a, set()).add(b)
        elif nz < -RESTING_NORMAL_Z:
            above.setdefault(b, set()).add(a)
    carried: set[str] = set()
    frontier = {object_id}
    while frontier:
        frontier = set().union(*(above.get(f, set()) for f in frontier)) - carried - {object_id}
        carried |= frontier
    return carried


def touching(built: BuiltScene, ids: set[str]) -> set[str]:
    """Objects in contact with any of `ids` at the built state (not counting `ids` themselves)."""
    pairs = object_contacts(built)
    return ({b for a, b, _ in pairs if a in ids} | {a for a, b, _ in pairs if b in ids}) - ids


def within(scene: Scene, obj: PlacedObject, engine: MujocoEngine, reach_m: float) -> set[str]:
    """Placed objects whose footprint circle comes within `reach_m` of the object's."""
    radius = 0.5 * float(np.linalg.norm(asset_of(engine, obj).size[:2]))
    close = set()
    for other in scene.placed:
        gap = np.linalg.norm(np.subtract(other.position[:2], obj.position[:2])) - radius
        if gap - 0.5 * float(np.linalg.norm(asset_of(engine, other).size[:2])) < reach_m:
            close.add(other.id)
    return close - {obj.id}


def neighbourhood(scene: Scene, object_id: str, engine: MujocoEngine, reach_m: float | None) -> Neighbourhood:
    """Compile the object with what rests on it and what it touches as free bodies (plus, with `reach_m`, what
    lies that close; with None, everything); the rest of the scene is held fixed."""
    obj = scene.object(object_id)
    if obj.status != "placed":
        raise ValueError(f"{object_id} is not placed ({obj.reason}); only placed objects have a stability")
    whole = engine.build(scene, visual=False)
    group = {object_id} | carried_by_placement(scene, object_id) | carried_by_contact(whole, object_id)
    free = (
        {o.id for o in scene.placed}
        if reach_m is None
        else (group | touching(whole, group) | within(scene, obj, engine, reach_m))
    )
    far = [o for o in scene.placed if o.id not in free]
    built = whole
    if far:
        near = [obj, *[o for o in scene.placed if o.id in free and o.id != object_id]]
        built = engine.build(scene, objects=near, visual=False, fixed=far)
    carried = [o.id for o in scene.placed if o.id in group and o.id != object_id]
    return Neighbourhood(built, object_id, [object_id, *carried])


def initial_states(hood: Neighbourhood, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per-copy initial qpos (n, nq): the group moved rigidly by Δp, Δr about the object's origin, seated on what
    it rests on, then lifted by Δz where Δz > 0 (nothing can be pushed into its support, so Δz < 0 rests
    touching). Also the pose (n, 7) the object should rest at if it stands: shifted by Δx, Δy and turned by the
    yaw of Δr, but flat again."""
    built = hood.built
    positions, quats = hood.nominal_poses()
    shift = x[:, POSITION].copy()
    lift = np.maximum(shift[:, 2], 0.0)
    shift[:, 2] = 0.0
    moved, turned = rigid_motion(positions[0], shift, x[:, ROTATION], positions, quats)
    rows = np.tile(built.data.qpos, (len(x), 1))
    for k, gid in enumerate(hood.group):
        a = built.qpos[gid]
        rows[:, a : a + 3] = moved[:, k]
        rows[:, a + 3 : a + 7] = turned[:, k]
    bodies = [built.body[g] for g in hood.group]
    seated = seat(built.model, rows, bodies)
    for b in bodies:
        seated[:, free_qpos_address(built.model, b) + 2] += lift
    yaw = np.zeros_like(shift)
    yaw[:, 2] = x[:, ROTATION][:, 2]
    rest_position, rest_quat = rigid_motion(positions[0], shift, yaw, positions[:1], quats[:1])
    return seated, np.concatenate([rest_position[:, 0], rest_quat[:, 0]], axis=1)


def simulate(
    hood: Neighbourhood,
    x: np.ndarray,
    horizon_s: float,
    rule: FallRule,
    *,
    batched: bool = True,
    threads: int | None = None,
) -> RolloutOutcome:
    """Run one copy per row of x and label each: did the object fall?"""
    model = hood.built.model
    body = hood.body
    geoms = np.flatnonzero((model.geom_bodyid == body) & (model.geom_contype > 0))
    mass, com, friction = perturbed_params(
        float(model.body_mass[body]), model.body_ipos[body], float(model.geom_friction[geoms[0], 0]), x
    )
    qpos0, reference = initial_states(hood, x)
    watched = Watched(body, geoms, tuple(hood.built.body[g] for g in hood.group[1:]))
    params = BodyParams(mass, com, friction)
    steps = int(round(horizon_s / TIMESTEP))
    if batched:
        return run_batched(model, watched, qpos0, reference, params, steps, rule=rule, threads=threads)
    return run_serial(model, watched, qpos0, reference, params, steps, rule=rule)


def _corners(asset: Asset) -> np.ndarray:
    sx, sy, sz = asset.size
    return np.array([[x, y, z] for x in (-sx / 2, sx / 2) for y in (-sy / 2, sy / 2) for z in (0.0, sz)])


def check_stands(
    scene: Scene, object_ids: Sequence[str], engine: MujocoEngine, rule: StandRule = StandRule()
) -> StandCheck:
    """Simulate the whole scene as it is, under the engine's contact settings and under MuJoCo's defaults; the
    objects stand when none of their box corners moves more than `rule.max_move_m` in `rule.duration_s` under
    either (stops as soon as one does)."""
    engines = [e for e in (engine, engine.defaults_check()) if e is not None]
    worst = 0.0
    for each in engines:
        worst = max(worst, _worst_corner_move(scene, object_ids, each, rule))
        if worst > rule.max_move_m:
            break
    return StandCheck(worst <= rule.max_move_m, worst, rule.duration_s)


def _worst_corner_move(scene: Scene, object_ids: Sequence[str], engine: MujocoEngine, rule: StandRule) -> float:
    built = engine.build_posed(scene)
    corners = {oid: _corners(asset_of(engine, scene.object(oid))) for oid in object_ids}

    def world() -> dict[str, np.ndarray]:
        out = {}
        for oid, local in corners.items():
            pose = built.data.qpos[built.qpos[oid] : built.qpos[oid] + 7]
            out[oid] = local @ quat_to_matrix(pose[3:] / np.linalg.norm(pose[3:])).T + pose[:3]
        return out

    start = world()
    worst = 0.0
    steps = int(round(rule.duration_s / float(built.model.opt.timestep)))
    chunk = max(1, int(round(STAND_CHECK_STEPS * TIMESTEP / float(built.model.opt.timestep))))
    for done in range(0, steps, chunk):
        mujoco.mj_step(built.model, built.data, nstep=min(chunk, steps - done))
        now = world()
        moved = max(float(np.linalg.norm(now[o] - start[o], axis=1).max()) for o in object_ids)
        worst = max(worst, moved if math.isfinite(moved) else math.inf)
        if worst > rule.max_move_m:
            break
    return worst
