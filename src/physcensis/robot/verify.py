"""Did the demonstration do what the task said? Two verifiers, each returning a verdict with its reasons.

The primitive verifier reads the settled MuJoCo state: the picked object on (touching, over the footprint, above the
top) or in (within the opening, between bottom and rim) the target, at rest and out of the hand, and every other
object where it was and still on the support. The VLM verifier shows a vision model the before and after views and
asks a yes/no question; its answer is read as a word, never evaluated.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np
import shapely

from physcensis.agent.vqa import image_message, read_yes_no
from physcensis.llm.client import LLMRequestError, RetryPolicy, chat_completion, reply_text
from physcensis.llm.provider import ChatProvider
from physcensis.robot.convex import collision_geoms
from physcensis.robot.tasks import Task
from physcensis.robot.world import RobotWorld

AT_REST_M_S = 0.01  # the picked object's speed below which it is at rest
FELL_M = 0.01  # an object whose centre of mass is this far below the support's top has fallen off
TIPPED_RAD = np.deg2rad(15.0)  # another object tilted this much has been knocked over


@dataclass
class Verdict:
    """Whether the task was done; every failing check's reason when it was not."""

    ok: bool
    reasons: list[str] = field(default_factory=list)


# -- the primitive verifier -----------------------------------------------------------------------------------------


def verify_primitive(
    world: RobotWorld, task: Task, before: dict[str, np.ndarray], *, moved_tolerance: float = 0.02
) -> Verdict:
    """The task's outcome judged from the world's current (settled) state and the object poses `before` it began."""
    for oid in (task.pick, task.target):
        if oid not in world.object_bodies:
            return Verdict(False, [f"{oid} is not an object of this world"])
    mujoco.mj_forward(world.model, world.data)  # contacts of the state as it is now
    reasons = _relation_reasons(world, task)
    reasons += _release_reasons(world, task.pick)
    reasons += _moved_reasons(world, task.pick, before, moved_tolerance)
    reasons += _fallen_reasons(world)
    return Verdict(not reasons, reasons)


def _relation_reasons(world: RobotWorld, task: Task) -> list[str]:
    if task.relation == "on":
        return _on_reasons(world, task.pick, task.target)
    return _in_reasons(world, task.pick, task.target)


def _on_reasons(world: RobotWorld, pick: str, target: str) -> list[str]:
    com = world.data.xipos[world.object_bodies[pick]]
    points = body_points(world, target)
    reasons: list[str] = []
    beside = _distance_outside(points, com)
    if beside > 0.0:
        reasons.append(f"{pick} is not on {target}: {beside * 100:.1f} cm beside its rim")
    else:
        top = surface_below(world, target, com[:2], float(points[:, 2].max()) + 0.05)
        if top is not None and com[2] <= top:
            reasons.append(
                f"{pick} is not on {target}: its centre of mass is {(top - com[2]) * 100:.1f} cm below its top"
            )
    if not _touching(world, world.object_bodies[pick], {world.object_bodies[target]}):
        reasons.append(f"{pick} does not touch {target}")
    return reasons


def _in_reasons(world: RobotWorld, pick: str, target: str) -> list[str]:
    com = world.data.xipos[world.object_bodies[pick]]
    points = body_points(world, target)
    rim = float(points[:, 2].max())
    reasons: list[str] = []
    beside = _distance_outside(points, com)
    if beside > 0.0:
        reasons.append(f"{pick} is not in {target}: {beside * 100:.1f} cm beside its rim")
    if com[2] >= rim:
        reasons.append(f"{pick} is not in {target}: its centre of mass is {(com[2] - rim) * 100:.1f} cm above the rim")
    elif beside == 0.0 and surface_below(world, target, com[:2], float(com[2])) is None:
        # Within the outline and below the rim, yet no floor of the target under it: beside a handle, or under it.
        reasons.append(f"{pick} is not in {target}: no part of {target} is under its centre of mass")
    return reasons


def _release_reasons(world: RobotWorld, pick: str) -> list[str]:
    body = world.object_bodies[pick]
    reasons: list[str] = []
    velocity = np.zeros(6)
    mujoco.mj_objectVelocity(world.model, world.data, mujoco.mjtObj.mjOBJ_BODY, body, velocity, 0)
    speed = float(np.linalg.norm(velocity[3:]))
    if speed >= AT_REST_M_S:
        reasons.append(f"{pick} is not at rest: it moves at {speed * 100:.1f} cm/s")
    if _touching(world, body, set(world.robot_bodies)):
        reasons.append(f"{pick} is still touching the gripper")
    return reasons


def _moved_reasons(world: RobotWorld, pick: str, before: dict[str, np.ndarray], tolerance: float) -> list[str]:
    now = world.object_poses()
    reasons: list[str] = []
    for oid, pose in before.items():
        if oid == pick or oid not in now:
            continue
        then = np.asarray(pose, dtype=float)
        moved = float(np.linalg.norm(now[oid][:3] - then[:3]))
        if moved > tolerance:
            reasons.append(f"{oid} moved {moved * 100:.1f} cm")
        tilt = _tilt_change(then[3:7], now[oid][3:7])
        if tilt > TIPPED_RAD:
            reasons.append(f"{oid} tipped over ({np.rad2deg(tilt):.0f} degrees)")
    return reasons


def _fallen_reasons(world: RobotWorld) -> list[str]:
    """Objects whose centre of mass is below the support's top: on the floor, or on their way there (anything resting
    on the support, even overhanging its edge, has its centre of mass above the top)."""
    support = world.scene.support
    return [
        f"{oid} fell off the {support.kind}"
        for oid, body in world.object_bodies.items()
        if world.data.xipos[body][2] < support.top_height - FELL_M
    ]


def _tilt_change(before_wxyz: np.ndarray, after_wxyz: np.ndarray) -> float:
    """The angle between the object's up axis before and after."""
    ups = []
    for quat in (before_wxyz, after_wxyz):
        matrix = np.zeros(9)
        mujoco.mju_quat2Mat(matrix, np.asarray(quat, dtype=float) / np.linalg.norm(quat))
        ups.append(matrix.reshape(3, 3)[:, 2])
    return float(np.arccos(np.clip(ups[0] @ ups[1], -1.0, 1.0)))


# -- geometry of a body's collision geoms ---------------------------------------------------------------------------


def body_points(world: RobotWorld, object_id: str) -> np.ndarray:
    """(K, 3) world points on the hull of an object's collision geoms: mesh vertices, primitives' corners."""
    geoms = collision_geoms(world.model, world.object_bodies[object_id])
    return np.vstack([_geom_points(world.model, world.data, g) for g in geoms])


def _unit_directions() -> np.ndarray:
    angles = np.linspace(0.0, 2.0 * np.pi, 16, endpoint=False)
    ring = np.column_stack([np.cos(angles), np.sin(angles), np.zeros_like(angles)])
    return np.vstack([ring, [[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]]])


def _local_points(model: mujoco.MjModel, geom: int) -> np.ndarray:
    kind, size = int(model.geom_type[geom]), model.geom_size[geom]
    if kind == mujoco.mjtGeom.mjGEOM_MESH:
        mesh = int(model.geom_dataid[geom])
        start, count = int(model.mesh_vertadr[mesh]), int(model.mesh_vertnum[mesh])
        return model.mesh_vert[start : start + count].astype(float)
    if kind == mujoco.mjtGeom.mjGEOM_BOX:
        corners = np.array(np.meshgrid([-1, 1], [-1, 1], [-1, 1])).reshape(3, -1).T
        return corners * size
    ring = _unit_directions()[:16] * size[0]
    if kind in (mujoco.mjtGeom.mjGEOM_CYLINDER, mujoco.mjtGeom.mjGEOM_CAPSULE):
        cap = size[0] if kind == mujoco.mjtGeom.mjGEOM_CAPSULE else 0.0
        ends = [ring + [0.0, 0.0, size[1]], ring - [0.0, 0.0, size[1]]]
        return np.vstack([*ends, [[0.0, 0.0, size[1] + cap], [0.0, 0.0, -size[1] - cap]]])
    return _unit_directions() * size[0]  # sphere, ellipsoid (roughly)


def _geom_points(model: mujoco.MjModel, data: mujoco.MjData, geom: int) -> np.ndarray:
    rotation = data.geom_xmat[geom].reshape(3, 3)
    return _local_points(model, geom) @ rotation.T + data.geom_xpos[geom]


def surface_below(world: RobotWorld, object_id: str, xy: np.ndarray, from_z: float) -> float | None:
    """The height of an object's uppermost collision surface straight below (x, y, from_z); None if there is none
    (a plate's well, not its rim, under a fork lying in it)."""
    model, data = world.model, world.data
    start = np.array([xy[0], xy[1], from_z], dtype=float)
    down = np.array([0.0, 0.0, -1.0])
    hits = []
    for geom in collision_geoms(world.model, world.object_bodies[object_id]):
        if model.geom_type[geom] == mujoco.mjtGeom.mjGEOM_MESH:
            distance = mujoco.mj_rayMesh(model, data, geom, start, down)
        else:
            distance = mujoco.mju_rayGeom(
                data.geom_xpos[geom], data.geom_xmat[geom], model.geom_size[geom], start, down, model.geom_type[geom]
            )
        if distance >= 0.0:
            hits.append(distance)
    return from_z - min(hits) if hits else None


def _distance_outside(points: np.ndarray, com: np.ndarray) -> float:
    """How far (m) the point's xy lies outside the convex hull of the points' xy (0 inside)."""
    hull = shapely.MultiPoint(points[:, :2]).convex_hull
    return float(hull.distance(shapely.Point(com[0], com[1])))


def _touching(world: RobotWorld, body: int, others: set[int]) -> bool:
    data, model = world.data, world.model
    for contact in data.contact[: data.ncon]:
        pair = {int(model.geom_bodyid[contact.geom1]), int(model.geom_bodyid[contact.geom2])}
        if body in pair and (pair - {body}) & others and contact.dist <= 1e-3:
            return True
    return False


# -- the VLM verifier -----------------------------------------------------------------------------------------------


def vlm_question(task: Task) -> str:
    """The yes/no question the vision model is asked about the two images."""
    place = "on top of" if task.relation == "on" else "inside"
    return (
        f'A robot arm was given the task: "{task.text}". The first image shows the scene before, the second after the '
        f"robot acted. Is the object it had to pick ({task.pick}) now resting {place} {task.target}, with nothing else "
        "knocked over or off the table? Answer Yes or No."
    )


def _request(model: str, before_png: bytes, after_png: bytes, task: Task) -> dict[str, Any]:
    message = image_message(vlm_question(task), before_png, after_png)
    return {"model": model, "messages": [message], "temperature": 0.0, "max_tokens": 8}


def verify_vlm(
    client: ChatProvider,
    model: str,
    before_png: bytes,
    after_png: bytes,
    task: Task,
    *,
    timeout_s: float = 120.0,
    max_retries: int = 2,
    sleep: Callable[[float], None] = time.sleep,
) -> Verdict:
    """A vision model's yes/no on whether `task` was done, from before and after views; a failed request is a no."""
    label = f"VLM verifier {model} at {client.url}"
    try:
        response = chat_completion(
            client,
            _request(model, before_png, after_png, task),
            policy=RetryPolicy(max_retries=max_retries),
            timeout_s=timeout_s,
            label=label,
            sleep=sleep,
        )
    except LLMRequestError as err:
        return Verdict(False, [f"the VLM verifier could not answer: {err}"])
    text, _ = reply_text(response)
    text = client.redactor.text(client.scrub(text)).strip()
    answer = read_yes_no(text)
    if answer is None:
        return Verdict(False, [f"the VLM verifier's answer is neither yes nor no: {text[:80]!r}"])
    if not answer:
        return Verdict(False, [f"the VLM verifier ({model}) said no: {text[:120]}"])
    return Verdict(True, [])
