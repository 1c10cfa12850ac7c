"""The verifiers: physical facts of a settled MuJoCo state, and a vision model's yes/no read strictly."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import mujoco
import pytest

from physcensis.llm.client import completion_from_body
from physcensis.llm.provider import AttemptFailure
from physcensis.redaction import Redactor
from physcensis.robot.tasks import Task
from physcensis.robot.verify import Verdict, body_points, verify_primitive, verify_vlm
from physcensis.robot.world import RobotWorld, build_world

ON_PLATE = Task("cup_0", "on", "plate_0", "pick cup_0 place-on plate_0")
IN_BOWL = Task("cup_0", "in", "bowl_0", "pick cup_0 place-in bowl_0")


@pytest.fixture(scope="module")
def world(small_scene_dir: Path) -> RobotWorld:
    return build_world(small_scene_dir)


def _drop(world: RobotWorld, oid: str, xy: tuple[float, float], onto: str | None = None) -> None:
    """Put `oid` with its lowest point 5 mm above `onto`'s top (or the table's) at `xy`."""
    address = world.object_qpos[oid]
    top = float(body_points(world, onto)[:, 2].max()) if onto else world.scene.support.top_height
    lowest = float(body_points(world, oid)[:, 2].min()) - world.data.qpos[address + 2]
    world.data.qpos[address : address + 3] = [xy[0], xy[1], top - lowest + 0.005]
    mujoco.mj_forward(world.model, world.data)


def _settle(world: RobotWorld, seconds: float = 1.0) -> None:
    for _ in range(round(seconds / world.model.opt.timestep)):
        mujoco.mj_step(world.model, world.data)


def _centre(world: RobotWorld, oid: str) -> tuple[float, float]:
    x, y = world.object_pose(oid)[0][:2]
    return float(x), float(y)


def _run(world: RobotWorld, task: Task, moves: list[tuple[str, tuple[float, float], str | None]]) -> Verdict:
    world.reset()
    before = world.object_poses()
    for oid, xy, onto in moves:
        _drop(world, oid, xy, onto)
    _settle(world)
    return verify_primitive(world, task, before)


def test_a_mug_resting_on_the_plate_is_on_it(world: RobotWorld) -> None:
    world.reset()
    verdict = _run(world, ON_PLATE, [("cup_0", _centre(world, "plate_0"), "plate_0")])
    assert verdict == Verdict(True, [])
    assert world.object_pose("cup_0")[0][2] > world.scene.support.top_height + 0.005  # really up on the plate


def test_a_mug_beside_the_plate_is_not(world: RobotWorld) -> None:
    world.reset()
    x, y = _centre(world, "plate_0")
    verdict = _run(world, ON_PLATE, [("cup_0", (x, y - 0.2), None)])
    assert not verdict.ok
    assert any(r.startswith("cup_0 is not on plate_0: ") and r.endswith(" cm beside its rim") for r in verdict.reasons)
    assert "cup_0 does not touch plate_0" in verdict.reasons


def test_a_moved_neighbour_fails_the_demo(world: RobotWorld) -> None:
    world.reset()
    x, y = _centre(world, "bowl_0")
    verdict = _run(world, ON_PLATE, [("cup_0", _centre(world, "plate_0"), "plate_0"), ("bowl_0", (x, y + 0.05), None)])
    assert verdict.reasons == ["bowl_0 moved 5.0 cm"]
    # Within the tolerance it is fine.
    world.reset()
    verdict = _run(world, ON_PLATE, [("cup_0", _centre(world, "plate_0"), "plate_0"), ("bowl_0", (x, y + 0.01), None)])
    assert verdict.ok, verdict.reasons


def test_an_object_that_fell_off_the_table(world: RobotWorld) -> None:
    world.reset()
    half_x = world.scene.support.half_extents[0]
    verdict = _run(world, ON_PLATE, [("cup_0", (half_x + 0.1, 0.0), None)])
    assert not verdict.ok
    assert "cup_0 fell off the table" in verdict.reasons
    assert world.object_pose("cup_0")[0][2] < world.scene.support.top_height


def test_in_the_bowl(world: RobotWorld) -> None:
    world.reset()
    assert _run(world, IN_BOWL, [("cup_0", _centre(world, "bowl_0"), "bowl_0")]).ok
    world.reset()
    on_plate = _run(world, IN_BOWL, [("cup_0", _centre(world, "plate_0"), "plate_0")])
    assert not on_plate.ok
    assert any(r.startswith("cup_0 is not in bowl_0: ") and "beside its rim" in r for r in on_plate.reasons)


def test_under_a_raised_bowl_is_not_in_it(world: RobotWorld) -> None:
    world.reset()
    before = world.object_poses()
    bowl, cup = world.object_qpos["bowl_0"], world.object_qpos["cup_0"]
    world.data.qpos[cup : cup + 2] = world.data.qpos[bowl : bowl + 2]
    world.data.qpos[bowl + 2] += 0.15  # held up in the air for this look: the mug stands beneath it
    verdict = verify_primitive(world, IN_BOWL, before)
    assert "cup_0 is not in bowl_0: no part of bowl_0 is under its centre of mass" in verdict.reasons


def test_a_moving_object_is_not_done(world: RobotWorld) -> None:
    world.reset()
    before = world.object_poses()
    _drop(world, "cup_0", _centre(world, "plate_0"), "plate_0")
    _settle(world)
    dof = world.model.jnt_dofadr[world.model.body_jntadr[world.object_bodies["cup_0"]]]
    world.data.qvel[dof : dof + 3] = [0.05, 0.0, 0.0]
    verdict = verify_primitive(world, ON_PLATE, before)
    assert "cup_0 is not at rest: it moves at 5.0 cm/s" in verdict.reasons


def test_an_object_still_in_the_hand_is_not_released(world: RobotWorld) -> None:
    world.reset()
    before = world.object_poses()
    address = world.object_qpos["cup_0"]
    world.data.qpos[address : address + 3] = world.tcp_pose()[0] - [0.0, 0.0, 0.03]  # between the open fingers
    verdict = verify_primitive(world, ON_PLATE, before)
    assert "cup_0 is still touching the gripper" in verdict.reasons
    assert "cup_0 fell off the table" not in verdict.reasons


# -- the VLM verifier, against a fake OpenAI-compatible server ------------------------------------------------------


class _FakeServer:
    """A chat provider (llm/provider.py) that records each request and answers `answer` (None: a body that is not a
    chat completion, as a broken gateway sends)."""

    url = "http://fake/v1"
    api_key_env = "FAKE_KEY"
    api_key = None

    def __init__(self, answer: str | None) -> None:
        self.requests: list[dict[str, Any]] = []
        self.answer = answer
        self.redactor = Redactor()

    def scrub(self, text: str) -> str:
        return text

    def attempt(self, request: dict[str, Any], seconds: float, on_chunks: Any = None) -> dict[str, Any]:
        self.requests.append(request)
        if self.answer is None:
            return completion_from_body(b"<html>gateway error</html>", self.redactor)
        message = {"role": "assistant", "content": self.answer}
        return {"choices": [{"index": 0, "message": message, "finish_reason": "stop"}]}

    def failure(self, exc: Exception) -> AttemptFailure | None:
        return None

    def served_models(self, timeout_s: float) -> list[str]:
        return []

    def close(self) -> None:
        pass


def _ask(answer: str | None) -> tuple[Verdict, _FakeServer]:
    server = _FakeServer(answer)
    verdict = verify_vlm(server, "vlm-1", b"\x89PNG-before", b"\x89PNG-after", ON_PLATE, max_retries=0)  # type: ignore[arg-type]
    return verdict, server


def test_vlm_yes_is_a_pass_and_it_saw_both_images() -> None:
    verdict, server = _ask("Yes.")
    assert verdict == Verdict(True, [])
    (request,) = server.requests
    text, before, after = request["messages"][0]["content"]
    assert "pick cup_0 place-on plate_0" in text["text"] and text["text"].endswith("Answer Yes or No.")
    assert before["image_url"]["url"].startswith("data:image/png;base64,")
    assert before["image_url"]["url"] != after["image_url"]["url"]
    assert request["model"] == "vlm-1" and request["temperature"] == 0.0


@pytest.mark.parametrize(
    ("answer", "reason"),
    [
        ("No, the mug is beside the plate.", "the VLM verifier (vlm-1) said no: No, the mug is beside the plate."),
        ("Maybe yes", "the VLM verifier's answer is neither yes nor no: 'Maybe yes'"),
        ("__import__('os').system('true')", "neither yes nor no"),
        ("", "neither yes nor no"),
        (None, "the VLM verifier could not answer: "),
    ],
)
def test_vlm_anything_but_yes_fails_with_its_reason(answer: str | None, reason: str) -> None:
    verdict, _ = _ask(answer)
    assert not verdict.ok
    assert len(verdict.reasons) == 1 and reason in verdict.reasons[0]
