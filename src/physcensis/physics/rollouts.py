"""Many short simulations of one model that differ in one body's pose, mass, centre of mass and friction.

Used by the stability measure: each copy starts from its own state and its own
parameters of the watched body, runs for a short horizon, and is labelled fell or
stood. `run_batched` runs the copies on MuJoCo's thread pool (`mujoco.batch`,
per-copy model fields, no recompiling); `run_serial` runs the same copies one
after another on a single MjData and gives bit-identical results.  Nothing here
knows about scenes or predicates.
"""

from __future__ import annotations

import copy
import math
import os
import time
from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np
from mujoco import batch as mjbatch

CHUNK_STEPS = 25  # steps between checks of each copy (0.05 s at the 2 ms timestep)
MAX_SPEED = 50.0  # m/s or rad/s: a copy this fast has blown up
SEAT_ITERATIONS = 4
SEAT_TOLERANCE_M = 1e-4
MAX_SEAT_LIFT_M = 0.05
# MuJoCo resets a copy whose state went bad (and counts a warning): such a copy has blown up
BAD_STATE_WARNINGS = [
    int(w)
    for w in (mujoco.mjtWarning.mjWARN_BADQACC, mujoco.mjtWarning.mjWARN_BADQPOS, mujoco.mjtWarning.mjWARN_BADQVEL)
]


@dataclass(frozen=True)
class FallRule:
    """When a copy's watched body counts as fallen, and when a copy may stop early because it is at rest."""

    translation_m: float = 0.01  # from the pose the body should rest at if it stands
    rotation_rad: float = math.radians(10.0)
    early_factor: float = 1.5  # before the end a copy is called fallen only this many times past the limits
    rest_speed: float = 0.002  # m/s and rad/s
    rest_after_s: float = 0.3  # a copy may stop at rest only after this much simulated time


@dataclass(frozen=True)
class BodyParams:
    """Per-copy physical parameters of the watched body: mass (n,), centre of mass in the body frame (n, 3),
    sliding friction of its geoms (n,)."""

    mass: np.ndarray
    com: np.ndarray
    friction: np.ndarray


@dataclass(frozen=True)
class Watched:
    """The body whose fall is judged, its geoms, and the free bodies that move with it (for the rest test)."""

    body: int
    geoms: np.ndarray
    group_bodies: tuple[int, ...] = ()


@dataclass
class RolloutOutcome:
    """What happened in each copy: fell (n,), blew up (n,), how far the watched body ended from its reference
    pose and how far it turned from it, the final state of every copy (n, nq), and how many steps each ran."""

    fell: np.ndarray
    blew_up: np.ndarray
    translation_m: np.ndarray
    rotation_rad: np.ndarray
    final_qpos: np.ndarray
    steps: np.ndarray
    wall_s: float
    threads: int


def default_threads() -> int:
    return max(1, os.cpu_count() or 1)


def free_qpos_address(model: mujoco.MjModel, body: int) -> int:
    return int(model.jnt_qposadr[model.body_jntadr[body]])


def free_dof_address(model: mujoco.MjModel, body: int) -> int:
    return int(model.jnt_dofadr[model.body_jntadr[body]])


# -- seating: perturbed copies start touching, not inside, what they rest on ---------------------------
def group_depth(model: mujoco.MjModel, data: mujoco.MjData, in_group: np.ndarray) -> float:
    """Deepest penetration between a geom of the group and a geom outside it, at data.qpos (no dynamics)."""
    mujoco.mj_kinematics(model, data)
    mujoco.mj_collision(model, data)
    worst = 0.0
    for i in range(data.ncon):
        contact = data.contact[i]
        if in_group[contact.geom[0]] != in_group[contact.geom[1]]:
            worst = max(worst, -float(contact.dist))
    return worst


def seat(model: mujoco.MjModel, qpos: np.ndarray, group_bodies: Sequence[int]) -> np.ndarray:
    """Lift each row's group of free bodies straight up until it penetrates the rest of the scene no deeper than
    it does at the model's own qpos0 (where it rests). Returns the seated rows."""
    data = mujoco.MjData(model)
    in_group = np.isin(model.geom_bodyid, np.asarray(group_bodies))
    z_addresses = [free_qpos_address(model, b) + 2 for b in group_bodies]
    data.qpos[:] = model.qpos0
    baseline = group_depth(model, data, in_group)
    seated = np.array(qpos, dtype=float, copy=True)
    for row in seated:
        lifted = 0.0
        for _ in range(SEAT_ITERATIONS):
            data.qpos[:] = row
            lift = group_depth(model, data, in_group) - baseline
            if lift < SEAT_TOLERANCE_M or lifted >= MAX_SEAT_LIFT_M:
                break
            row[z_addresses] += lift
            lifted += lift
    return seated


# -- per-copy parameters ---------------------------------------------------------------------------------
def _write_params(
    mass: np.ndarray,
    inertia: np.ndarray,
    ipos: np.ndarray,
    friction: np.ndarray,
    model: mujoco.MjModel,
    watched: Watched,
    params: BodyParams,
    rows: slice | int,
) -> None:
    """Write the watched body's parameters for `rows` into mass, inertia, ipos and friction field views."""
    b = watched.body
    scale = np.asarray(params.mass[rows]) / model.body_mass[b]
    mass[..., b] = params.mass[rows]
    inertia[..., b, :] = np.multiply.outer(scale, model.body_inertia[b])
    ipos[..., b, :] = params.com[rows]
    friction[..., watched.geoms, 0] = np.asarray(params.friction[rows])[..., None]


# -- judging copies ------------------------------------------------------------------------------------
@dataclass
class _Monitor:
    """The per-copy bookkeeping shared by the batched and the serial runners."""

    model: mujoco.MjModel
    watched: Watched
    reference: np.ndarray  # (n, 7) where the watched body should rest if it stands
    rule: FallRule

    def __post_init__(self) -> None:
        n = len(self.reference)
        self.adr = free_qpos_address(self.model, self.watched.body)
        bodies = (self.watched.body, *self.watched.group_bodies)
        self.dofs = np.concatenate(
            [np.arange(free_dof_address(self.model, b), free_dof_address(self.model, b) + 6) for b in bodies]
        )
        self.fell = np.zeros(n, dtype=bool)
        self.blew_up = np.zeros(n, dtype=bool)
        self.translation = np.zeros(n)
        self.rotation = np.zeros(n)
        self.steps = np.zeros(n, dtype=int)

    def judge(
        self, ids: np.ndarray, qpos: np.ndarray, qvel: np.ndarray, warned: np.ndarray, steps: int, last: bool
    ) -> np.ndarray:
        """Update copies `ids` from their state after `steps` (`warned`: MuJoCo reset them after a bad state);
        returns which of them are finished."""
        pose = qpos[:, self.adr : self.adr + 7]
        quat = pose[:, 3:] / np.linalg.norm(pose[:, 3:], axis=1, keepdims=True)
        translation = np.linalg.norm(pose[:, :3] - self.reference[ids, :3], axis=1)
        dot = np.clip(np.abs(np.einsum("ij,ij->i", quat, self.reference[ids, 3:])), 0.0, 1.0)
        rotation = 2.0 * np.arccos(dot)
        speed = np.abs(qvel[:, self.dofs]).max(axis=1)
        broken = warned | ~np.isfinite(qpos).all(axis=1) | ~np.isfinite(speed) | (speed > MAX_SPEED)
        resting = (steps * self.model.opt.timestep >= self.rule.rest_after_s) & (speed < self.rule.rest_speed)
        final = resting | last
        factor = np.where(final, 1.0, self.rule.early_factor)
        fell = broken | (translation > factor * self.rule.translation_m) | (rotation > factor * self.rule.rotation_rad)
        done = fell | final
        self.fell[ids] = fell
        self.blew_up[ids] = broken
        self.translation[ids] = np.where(broken, np.inf, translation)
        self.rotation[ids] = np.where(broken, np.pi, rotation)
        self.steps[ids] = steps
        return done

    def mark_errors(self, ids: np.ndarray, steps: int) -> None:
        self.fell[ids] = self.blew_up[ids] = True
        self.translation[ids], self.rotation[ids], self.steps[ids] = np.inf, np.pi, steps

    def outcome(self, final_qpos: np.ndarray, wall_s: float, threads: int) -> RolloutOutcome:
        return RolloutOutcome(
            self.fell, self.blew_up, self.translation, self.rotation, final_qpos, self.steps, wall_s, threads
        )


def _check(qpos0: np.ndarray, reference: np.ndarray, params: BodyParams) -> int:
    n = len(qpos0)
    if not (len(reference) == len(params.mass) == len(params.com) == len(params.friction) == n):
        raise ValueError("initial states, reference poses and parameters must have one row per copy")
    return n


def run_batched(
    model: mujoco.MjModel,
    watched: Watched,
    qpos0: np.ndarray,
    reference: np.ndarray,
    params: BodyParams,
    horizon_steps: int,
    *,
    rule: FallRule = FallRule(),
    threads: int | None = None,
) -> RolloutOutcome:
    """Run every copy on MuJoCo's batch thread pool from its qpos0 row; copies stop early once fallen or at rest.
    `reference` (n, 7) is where each copy's watched body should rest if it stands."""
    start_time = time.perf_counter()
    n = _check(qpos0, reference, params)
    threads = threads or default_threads()
    batch = mjbatch.Batch(model, nsim=n, nthread=threads)
    _write_params(
        batch.expand("body_mass"),
        batch.expand("body_inertia"),
        batch.expand("body_ipos"),
        batch.expand("geom_friction"),
        model,
        watched,
        params,
        slice(None),
    )
    batch.set_const()
    qpos, qvel = batch.bind("qpos"), batch.bind("qvel")
    qpos[:] = qpos0
    qvel[:] = 0.0
    monitor = _Monitor(model, watched, np.asarray(reference, dtype=float), rule)
    active = np.arange(n)
    done_steps = 0
    while len(active) and done_steps < horizon_steps:
        chunk = min(CHUNK_STEPS, horizon_steps - done_steps)
        try:
            batch.step(ids=active, nstep=chunk)
        except mjbatch.SimulationError as error:
            monitor.mark_errors(error.ids, done_steps + chunk)
            active = np.setdiff1d(active, error.ids)
        done_steps += chunk
        warned = batch.warning[active][:, BAD_STATE_WARNINGS, 1].any(axis=1)
        done = monitor.judge(active, qpos[active], qvel[active], warned, done_steps, done_steps >= horizon_steps)
        active = active[~done]
    return monitor.outcome(np.array(qpos), time.perf_counter() - start_time, threads)


def run_serial(
    model: mujoco.MjModel,
    watched: Watched,
    qpos0: np.ndarray,
    reference: np.ndarray,
    params: BodyParams,
    horizon_steps: int,
    *,
    rule: FallRule = FallRule(),
) -> RolloutOutcome:
    """The same copies one after another on one MjData (a reference for `run_batched`, and its baseline)."""
    start_time = time.perf_counter()
    n = _check(qpos0, reference, params)
    work = copy.deepcopy(model)  # its per-copy fields are overwritten; the caller's model is left alone
    data = mujoco.MjData(work)
    monitor = _Monitor(model, watched, np.asarray(reference, dtype=float), rule)
    final = np.array(qpos0, dtype=float, copy=True)
    for k in range(n):
        _write_params(work.body_mass, work.body_inertia, work.body_ipos, work.geom_friction, model, watched, params, k)
        mujoco.mj_resetData(work, data)
        mujoco.mj_setConst(work, data)
        mujoco.mj_resetData(work, data)
        data.qpos[:] = qpos0[k]
        ids = np.array([k])
        done_steps = 0
        while done_steps < horizon_steps:
            chunk = min(CHUNK_STEPS, horizon_steps - done_steps)
            mujoco.mj_step(work, data, nstep=chunk)
            done_steps += chunk
            warned = np.array([any(data.warning[w].number for w in BAD_STATE_WARNINGS)])
            if monitor.judge(ids, data.qpos[None], data.qvel[None], warned, done_steps, done_steps >= horizon_steps)[0]:
                break
        final[k] = data.qpos
    return monitor.outcome(final, time.perf_counter() - start_time, 1)
