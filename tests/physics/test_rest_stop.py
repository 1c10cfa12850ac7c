"""A settle stops once everything is at rest, and only then: a resting stack stops early with the motion the whole
settle measures, what creeps or slides is watched to the end, and a settle already simulated is not simulated again."""

from __future__ import annotations

import math
from typing import Any

import mujoco
import numpy as np
import pytest

from physcensis.assets import default_catalogue
from physcensis.physics.engine import AT_REST, SETTLE_S, RestRule
from physcensis.physics.mujoco_engine import MujocoEngine, _RestWatch
from physcensis.physics.profiles import MUJOCO_DEFAULT, OURS, ContactProfile
from physcensis.scene import Scene, Support

from ..scenes import placed_object

pytestmark = pytest.mark.physics
TABLE = Support(kind="table", size=(0.8, 0.6))
BOOK = "book_flat_cookbook_orange"
SAME_M = 5e-5  # what stopping early may leave out: the rest speed for the rest of the settle, at most


def books(count: int) -> Scene:
    objects, z = [], TABLE.top_height
    for k in range(count):
        objects.append(placed_object(f"book_{k}", BOOK, 0.01 * k, 0.0, z + 1e-4, yaw=0.1 * k))
        z += default_catalogue().get(BOOK).size[2]
    return Scene(support=TABLE, objects=objects)


def tilted(engine: MujocoEngine, scene: Scene, radians: float) -> Any:
    """The scene built with gravity tilted along x: a book on it is pushed sideways, below what friction holds."""
    built = engine.build_posed(scene)
    built.model.opt.gravity[:] = [9.81 * math.sin(radians), 0.0, -9.81 * math.cos(radians)]
    return built


@pytest.mark.parametrize("profile", [OURS, MUJOCO_DEFAULT], ids=lambda p: p.name)
def test_a_resting_stack_stops_early_and_reports_the_motion_of_the_whole_settle(profile: ContactProfile) -> None:
    scene = books(4)
    engine = MujocoEngine(profile=profile)
    whole = engine.settle(scene, duration_s=SETTLE_S, rest=None)
    early = MujocoEngine(profile=profile).settle(scene, duration_s=SETTLE_S)  # at rest by AT_REST, the default
    assert whole.simulated_s == pytest.approx(SETTLE_S)
    assert early.simulated_s <= 1.0
    for oid, motion in whole.objects.items():
        assert motion.ok and early.objects[oid].ok
        assert abs(early.objects[oid].translation_m - motion.translation_m) < SAME_M
        assert np.allclose(early.objects[oid].position, motion.position, atol=SAME_M)


def test_the_settle_distance_of_a_resting_scene_stops_early_with_the_same_distance() -> None:
    scene = books(3)
    whole = MujocoEngine().settle_distance(scene)
    steps = []

    def counted(model: Any, data: Any, nstep: int = 1) -> None:
        steps.append(nstep)
        real_step(model, data, nstep=nstep)

    real_step = mujoco.mj_step
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(mujoco, "mj_step", counted)
        early = MujocoEngine().settle_distance(scene, rest=AT_REST)
    assert sum(steps) * OURS.timestep <= 1.0  # not the 4 s
    assert early.diverged is None and abs(early.mean_m - whole.mean_m) < SAME_M
    assert whole.mean_m < 0.003


def test_what_creeps_under_the_defaults_is_watched_to_the_end() -> None:
    """Tilted 0.05 rad, a book creeps 0.18 mm/s under MuJoCo's soft default contacts: slow, and still moving."""
    engine = MujocoEngine(profile=MUJOCO_DEFAULT)
    scene = books(1)
    whole = engine.settle_built(tilted(engine, scene, 0.05), TABLE.top_height, duration_s=SETTLE_S)
    watched = engine.settle_built(tilted(engine, scene, 0.05), TABLE.top_height, duration_s=SETTLE_S, rest=AT_REST)
    assert watched.simulated_s == pytest.approx(SETTLE_S)
    assert watched.objects["book_0"].translation_m == pytest.approx(whole.objects["book_0"].translation_m)
    assert watched.objects["book_0"].translation_m > 0.0005


def test_what_slides_is_not_stopped_before_it_stops() -> None:
    engine = MujocoEngine()
    scene = books(1)
    motions = []
    for rest in (None, AT_REST):
        built = engine.build_posed(scene)
        built.data.qvel[built.dof["book_0"]] = 0.6  # pushed along x
        motions.append(engine.settle_built(built, TABLE.top_height, duration_s=2.0, rest=rest).objects["book_0"])
    whole, early = motions
    assert whole.translation_m > 0.01 and not whole.ok  # it slid
    assert abs(early.translation_m - whole.translation_m) < SAME_M and not early.ok


def test_the_watch_needs_a_whole_window_where_nothing_goes_anywhere_nor_speeds_up() -> None:
    rule = RestRule()
    poses = np.array([[0.0, 0.0, 0.8, 1.0, 0.0, 0.0, 0.0]])
    checks = int(round(2.0 / rule.check_s))

    def watched(speeds: list[float], spins: list[float] | None = None, drift: float = 0.0) -> float | None:
        """When a watch fed these speeds and spins (one each per check) says at rest; the body drifts `drift` m/s."""
        watch = _RestWatch(rule)
        for k, speed in enumerate(speeds):
            t = (k + 1) * rule.check_s
            spin = 0.0 if spins is None else spins[k]
            if watch.at_rest(t, poses + [[drift * t, 0, 0, 0, 0, 0, 0]], np.array([speed]), np.array([spin])):
                return t
        return None

    assert watched([1e-5] * checks) == pytest.approx(rule.window_s + rule.check_s)  # a window after the first check
    assert watched([2 * rule.speed_m_s] * checks, drift=2 * rule.speed_m_s) is None  # creeping faster than allowed
    assert watched([1e-5] * checks, drift=2 * rule.speed_m_s) is None  # slow at each check, yet it went somewhere
    chatter = [1.4e-2, 3.1e-2, 1.9e-2, 2.1e-2] * (checks // 4)  # a salad fork rocking in place
    assert watched([1.9e-5] * checks, chatter) == pytest.approx(rule.window_s + rule.check_s)
    assert watched([2 * rule.jitter_m_s] * checks) is None  # fast at every check: moving, wherever it ends up
    growing = [1e-6 * math.exp(k * rule.check_s / 0.15) for k in range(checks)]  # tipping over, from nearly still
    assert watched([s for s in growing if s < rule.jitter_m_s]) is None
    assert watched([1e-2, 1e-2] + [1e-5] * checks) == pytest.approx(3 * rule.check_s + rule.window_s)


def test_a_settle_from_a_start_already_settled_is_not_simulated_again() -> None:
    engine = MujocoEngine()
    scene = books(2)
    first = engine.settle(scene, duration_s=SETTLE_S)  # stops at rest well within 1.5 s
    steps = []
    real_step = mujoco.mj_step
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(mujoco, "mj_step", lambda m, d, nstep=1: (steps.append(nstep), real_step(m, d, nstep=nstep)))
        again = engine.settle(scene, duration_s=1.5)
        assert steps == []  # the same settle: it ended at rest before 1.5 s
        assert again.objects == first.objects and again.simulated_s == first.simulated_s
        engine.settle(scene, duration_s=SETTLE_S, rest=None)
        assert sum(steps) == round(SETTLE_S / OURS.timestep)  # another rule is another settle
        moved = scene.model_copy(update={"objects": [scene.objects[0]]})
        engine.settle(moved, duration_s=1.5)
        assert sum(steps) > round(SETTLE_S / OURS.timestep)  # other objects, another settle
