"""One pick-and-place demonstration: grasp, goal, plan, execute, verify, record.

The stages, in order (each failure names its stage and why, which is what a dataset's report lists):
  task     the words resolved to a pick object, a relation and a target in this scene
  grasp    the asset's tested grasps at the object's pose, reachable by IK without collisions (pre-grasp and grasp)
  goal     object poses on / in the target where the held object, the hand and the arm fit, reachable by IK
  plan     collision-free joint paths: home -> pre-grasp, (approach, close, lift) -> pre-place, (lower, open, retreat)
  execute  the plan run in MuJoCo by the arm's position servos at 20 Hz, recorded step by step
  verify   after release and settling: the primitive verifier (and the VLM verifier when enabled)
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from physcensis.robot import control, goals, grasps, ik, planning, tasks, verify
from physcensis.robot.collision import CollisionChecker, Held, pose_matrix
from physcensis.robot.hand import qpos_to_pose
from physcensis.robot.panda import FINGER_CLOSED, FINGER_OPEN, HOME_Q
from physcensis.robot.record import Episode, EpisodeRecorder
from physcensis.robot.world import RobotWorld
from physcensis.solver.objects import quaternion_yaw

APPROACH_M = 0.10  # pre-grasp stand-off along the approach axis, and the lift / pre-place height
GRASP_TRIES = 12  # scene grasps tried for IK, best first
GOAL_TRIES = 12
CLOSE_S = 0.6
RELEASE_S = 0.5
FINAL_SETTLE_S = 1.0
ARRIVE_S = 0.3
HELD_SLIP_M = 0.02  # the object moved this far from the hand during the carry: dropped
HELD_SWING_DEG = 20.0  # or turned this much in it: it will not stand where it is put
PLACE_DROP_M = 0.005  # released this far above its goal pose, so the fingers never press it into the target
LINEAR_STEPS = 20
APPROACH_MARGIN_M = 0.001
CARRY_VELOCITY = 0.3  # fractions of the Panda's joint limits while an object is in the hand
CARRY_ACCELERATION = 0.1


@dataclass
class EpisodeOptions:
    seed: int = 0
    grasp_candidates: int = 2000
    goal_samples: int = 16
    plan_timeout_s: float = 5.0
    images: tuple[int, int] | None = (128, 128)  # (height, width) of the recorded camera frames; None: no images
    vlm: Callable[[bytes, bytes, tasks.Task], verify.Verdict] | None = None


@dataclass
class Outcome:
    """What one attempt produced: success, the failing stage and why, timings, and the recorded episode."""

    success: bool
    stage: str  # the last stage reached ("done" on success)
    reason: str | None
    task: str
    seconds: dict[str, float] = field(default_factory=dict)
    episode: Episode | None = None

    def summary(self) -> dict[str, Any]:
        return {
            "success": self.success,
            "stage": self.stage,
            "reason": self.reason,
            "task": self.task,
            "seconds": {k: round(v, 3) for k, v in self.seconds.items()},
            "steps": 0 if self.episode is None else len(self.episode.actions),
        }


class StageFailed(Exception):
    def __init__(self, stage: str, reason: str) -> None:
        super().__init__(f"{stage}: {reason}")
        self.stage = stage
        self.reason = reason


@dataclass
class _Grip:
    """A reachable grasp: the joint configurations at pre-grasp and grasp, and the TCP in the object's frame."""

    object_T_tcp: np.ndarray
    q_pre: np.ndarray
    q_grasp: np.ndarray  # the straight approach from pre-grasp to grasp, (steps + 1, 7)
    free: CollisionChecker  # the arm alone, as it reached the pre-grasp (the path there reuses it)


@dataclass
class _Place:
    q_pre: np.ndarray
    q_place: np.ndarray  # the straight descent from pre-place to release, (steps + 1, 7)
    carrying: CollisionChecker  # the arm holding the object, as it reached the pre-place (the carry reuses it)


def _ik(world: RobotWorld, tcp: np.ndarray, seed_q: np.ndarray, checker: CollisionChecker, rng: np.random.Generator):
    return ik.solve_ik(world, tcp[:3, 3], tcp[:3, :3], seed_q=seed_q, rng=rng, checker=checker)


def _no_grasp_reason(world: RobotWorld, pick: str) -> str:
    extents = np.ptp(verify.body_points(world, pick), axis=0)
    widest = grasps.JAW_OPEN - 2.0 * grasps.WIDTH_MARGIN
    if extents.min() > widest:
        return (
            f"{pick} is {extents.min() * 100:.1f} cm across at its narrowest; the hand opens "
            f"{grasps.JAW_OPEN * 100:.0f} cm and needs {grasps.WIDTH_MARGIN * 1000:.0f} mm clearance a side"
        )
    return f"no grasp of {pick} held in the lift test (the hand lifting and shaking it alone)"


def _steady_first(
    world: RobotWorld, pick: str, in_scene: list[tuple[grasps.Grasp, np.ndarray]]
) -> list[tuple[grasps.Grasp, np.ndarray]]:
    """Grasps whose approach is nearest vertical first (in 10-degree bands: a tilted hand needs the arm to twist to
    carry it, and the twist swings what it holds), then those with the centre of mass nearest straight below the TCP
    (in 1 cm bands of the horizontal distance: gravity's lever, which swings a cup pinched by its rim and twists it
    about the jaw axis, where only the pads' torsional friction holds it), then by the grasp's own score."""
    com = world.data.xipos[world.object_bodies[pick]]

    def key(item: tuple[grasps.Grasp, np.ndarray]) -> tuple[int, int, float]:
        tcp = item[1]
        down = float(np.clip(-tcp[2, 2], -1.0, 1.0))
        lever = float(np.linalg.norm((com - tcp[:3, 3])[:2]))  # gravity's arm: straight below, it hangs still
        return int(np.degrees(np.arccos(down)) // 10), int(lever // 0.01), -item[0].score

    return sorted(in_scene, key=key)


def _least_turn_first(poses: list[np.ndarray], now: np.ndarray) -> list[np.ndarray]:
    """Goal poses needing the least turn about the vertical from the object's pose now first (the hand then keeps
    its orientation over the carry); the goal sampler's order (nearest the target's centre) breaks ties."""
    yaw_now = quaternion_yaw(now[3:7].tolist())

    def turn(pose: np.ndarray) -> int:
        delta = abs((quaternion_yaw(pose[3:7].tolist()) - yaw_now + np.pi) % (2 * np.pi) - np.pi)
        return int(np.degrees(delta) // 15)

    return sorted(poses, key=turn)


def _reachable_grips(
    world: RobotWorld, task: tasks.Task, options: EpisodeOptions, rng: np.random.Generator
) -> Iterator[_Grip | str]:
    """Reachable grasps, best first; a string says why one grasp is not."""
    tested = grasps.grasps_for(world, task.pick, n_candidates=options.grasp_candidates)
    if not tested:
        raise StageFailed("grasp", _no_grasp_reason(world, task.pick))
    in_scene = grasps.grasps_in_scene(world, task.pick, tested)
    if not in_scene:
        raise StageFailed(
            "grasp", f"no grasp of {task.pick} is free of collisions ({len(tested)} held in the lift test)"
        )
    free = CollisionChecker(world)
    # The open hand goes all the way in without touching the object (a finger that brushes it on the way down shoves
    # a light cup out of the grasp); the margin is small because the pads end a few millimetres from its sides.
    touching = CollisionChecker(world, margin=APPROACH_MARGIN_M)
    object_T_world = np.linalg.inv(qpos_to_pose(world.object_poses()[task.pick]))
    for _grasp, tcp in _steady_first(world, task.pick, in_scene)[:GRASP_TRIES]:
        pre = tcp.copy()
        pre[:3, 3] -= tcp[:3, 2] * APPROACH_M  # back off along the approach axis (the hand's z)
        at_pre = _ik(world, pre, HOME_Q, free, rng)
        if at_pre.q is None:
            yield f"pre-grasp: {at_pre.reason}"
            continue
        approach = ik.linear_path(world, at_pre.q, tcp[:3, 3] - pre[:3, 3], LINEAR_STEPS, checker=touching)
        yield (
            f"approach: {approach}"
            if isinstance(approach, str)
            else _Grip(object_T_world @ tcp, at_pre.q, approach, free)
        )


def _place_for(world: RobotWorld, task: tasks.Task, grip: _Grip, poses: list[np.ndarray], rng) -> _Place | str:
    """The first goal pose reachable holding the object with this grasp, or why none is."""
    held = Held(task.pick, np.linalg.inv(grip.object_T_tcp))
    carrying = CollisionChecker(world, held=held)
    placing = CollisionChecker(world, held=held, ignore=(task.target,))
    last = "no IK"
    for pose in poses[:GOAL_TRIES]:
        tcp = qpos_to_pose(pose) @ grip.object_T_tcp
        tcp[2, 3] += PLACE_DROP_M
        pre = tcp.copy()
        pre[2, 3] += APPROACH_M
        at_pre = _ik(world, pre, grip.q_grasp[-1], carrying, rng)
        if at_pre.q is None:
            last = f"pre-place: {at_pre.reason}"
            continue
        lower = ik.linear_path(world, at_pre.q, tcp[:3, 3] - pre[:3, 3], LINEAR_STEPS, checker=placing)
        if isinstance(lower, str):
            last = f"lowering: {lower}"
            continue
        return _Place(at_pre.q, lower, carrying)
    return last


@dataclass
class _Plan:
    """Joint waypoints of every segment, each already retimed at the control rate, with the gripper's state."""

    segments: list[tuple[str, np.ndarray | float]]
    object_T_tcp: np.ndarray  # the grasp: the TCP in the picked object's frame


def _plan_pick_and_place(world: RobotWorld, task: tasks.Task, options: EpisodeOptions) -> _Plan:
    rng = np.random.default_rng(options.seed)
    poses = goals.goal_poses(world, task.pick, task.relation, task.target, n=options.goal_samples, rng=rng)
    if not poses:
        why = getattr(poses, "reason", None) or f"no free pose {task.relation} {task.target} for {task.pick}"
        raise StageFailed("goal", why)
    ordered = _least_turn_first(list(poses), world.object_poses()[task.pick])
    last, reachable = "", 0
    for grip in _reachable_grips(world, task, options, rng):
        if isinstance(grip, str):
            last = last or f"grasp: {grip}"
            continue
        reachable += 1
        place = _place_for(world, task, grip, ordered, rng)
        if isinstance(place, str):
            last = f"goal: {place}"
            continue
        plan = _paths(world, task, grip, place, options)
        if isinstance(plan, str):
            last = f"plan: {plan}"
            continue
        return plan
    if reachable == 0:
        raise StageFailed("grasp", f"no grasp of {task.pick} is reachable without collisions ({last})")
    stage, _, why = last.partition(": ")
    raise StageFailed(stage, f"{reachable} reachable grasps of {task.pick} tried; the last: {why}")


def _paths(world: RobotWorld, task: tasks.Task, grip: _Grip, place: _Place, options: EpisodeOptions) -> _Plan | str:
    held = Held(task.pick, np.linalg.inv(grip.object_T_tcp))
    free, carrying = grip.free, place.carrying
    lifting = CollisionChecker(world, held=held, ignore=(task.pick,))
    near_object = CollisionChecker(world, ignore=(task.pick,))
    to_object = planning.plan(world, HOME_Q, grip.q_pre, free, seed=options.seed, timeout_s=options.plan_timeout_s)
    if isinstance(to_object, str):
        return f"to the pre-grasp: {to_object}"
    lift = ik.linear_path(world, grip.q_grasp[-1], np.array([0.0, 0.0, APPROACH_M]), LINEAR_STEPS, checker=lifting)
    if isinstance(lift, str):
        return f"lift: {lift}"
    carry = planning.plan(world, lift[-1], place.q_pre, carrying, seed=options.seed, timeout_s=options.plan_timeout_s)
    if isinstance(carry, str):
        return f"carry: {carry}"
    world_T_tcp = pose_matrix(*ik.tcp_at(world, place.q_place[-1]))
    retreat = ik.linear_path(
        world, place.q_place[-1], -world_T_tcp[:3, 2] * APPROACH_M, LINEAR_STEPS, checker=near_object
    )
    if isinstance(retreat, str):
        return f"retreat: {retreat}"
    return _Plan(
        [
            ("reach", planning.retime(to_object)),
            ("approach", planning.retime(grip.q_grasp)),
            ("close", FINGER_CLOSED),
            ("lift", _gently(lift)),
            ("carry", _gently(carry)),
            ("lower", _gently(place.q_place)),
            ("open", FINGER_OPEN),
            ("retreat", planning.retime(retreat)),
        ],
        grip.object_T_tcp,
    )


def _gently(path: np.ndarray) -> np.ndarray:
    """Retimed slower while holding: the hand's accelerations swing an object pinched off its centre of mass."""
    return planning.retime(
        path,
        max_velocity=planning.PANDA_MAX_VELOCITY * CARRY_VELOCITY,
        max_acceleration=planning.PANDA_MAX_ACCELERATION * CARRY_ACCELERATION,
    )


def _execute(world: RobotWorld, task: tasks.Task, plan: _Plan, recorder: EpisodeRecorder) -> str | None:
    """Run the plan; None, or why the object was lost on the way."""
    gripper = FINGER_OPEN
    hand_T_object: np.ndarray | None = None
    for name, segment in plan.segments:
        if isinstance(segment, float):
            gripper = segment
            control.move_gripper(world, gripper, CLOSE_S if gripper == FINGER_CLOSED else RELEASE_S, recorder.observe)
            if gripper == FINGER_CLOSED:
                hand_T_object = _relative(world, task.pick)
            continue
        control.follow(world, segment, gripper, recorder.observe)
        if name in ("approach", "lower"):
            control.settle(world, ARRIVE_S, recorder.observe)  # the servos lag a fast move: be there before gripping
        if name in ("lift", "carry") and hand_T_object is not None:
            lost = _lost_grip(world, task.pick, hand_T_object, name)
            if lost:
                return lost
    control.settle(world, FINAL_SETTLE_S, recorder.observe)
    return None


def _lost_grip(world: RobotWorld, pick: str, hand_T_object: np.ndarray, segment: str) -> str | None:
    now = _relative(world, pick)
    slip = float(np.linalg.norm(now[:3, 3] - hand_T_object[:3, 3]))
    turn = np.degrees(np.arccos(np.clip((np.trace(now[:3, :3] @ hand_T_object[:3, :3].T) - 1.0) / 2.0, -1.0, 1.0)))
    if slip > HELD_SLIP_M:
        return f"dropped {pick} during the {segment} (it slid {slip * 100:.1f} cm in the hand)"
    if turn > HELD_SWING_DEG:
        return f"{pick} swung {turn:.0f} degrees in the hand during the {segment}"
    return None


def _relative(world: RobotWorld, object_id: str) -> np.ndarray:
    """The object's pose in the TCP's frame now."""
    return np.linalg.inv(pose_matrix(*world.tcp_pose())) @ qpos_to_pose(world.object_poses()[object_id])


def run_episode(world: RobotWorld, task_text: str, options: EpisodeOptions | None = None) -> Outcome:
    """One attempt of the task on the world from its initial state; the world is left where the attempt ended."""
    import time

    options = options or EpisodeOptions()
    world.reset()
    seconds: dict[str, float] = {}
    start = time.perf_counter()
    try:
        task = tasks.parse_task(task_text, world.scene, world.base_yaw, base_position=world.base_position.tolist())
    except tasks.TaskError as err:
        return Outcome(False, "task", str(err), task_text)
    before = world.object_poses()
    try:
        plan = _plan_pick_and_place(world, task, options)
    except StageFailed as failed:
        seconds["planning"] = time.perf_counter() - start
        return Outcome(False, failed.stage, failed.reason, task_text, seconds)
    seconds["planning"] = time.perf_counter() - start
    world.reset()
    recorder = EpisodeRecorder(world, image_size=options.images)
    start = time.perf_counter()
    lost = _execute(world, task, plan, recorder)
    seconds["execution"] = time.perf_counter() - start - recorder.render_seconds
    seconds["rendering"] = recorder.render_seconds
    verdict = verify.Verdict(False, [lost]) if lost else verify.verify_primitive(world, task, before)
    stage = "execute" if lost else "verify"
    if verdict.ok and options.vlm is not None:
        verdict = options.vlm(recorder.first_frame_png(), recorder.last_frame_png(), task)
    reason = None if verdict.ok else "; ".join(verdict.reasons)
    episode = recorder.episode(task=task.explicit, success=verdict.ok, reason=reason, seed=options.seed)
    episode.attrs["instruction"] = task.text
    return Outcome(verdict.ok, "done" if verdict.ok else stage, reason, task_text, seconds, episode)
