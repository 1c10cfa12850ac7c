"""A model compiled once and posed again simulates exactly as a model compiled for the new poses."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from physcensis.physics.mujoco_engine import MujocoEngine, build_scene
from physcensis.physics.profiles import MUJOCO_DEFAULT
from physcensis.scene import PlacedObject, Scene, Support

from ..scenes import placed_object

pytestmark = pytest.mark.physics
TABLE = Support(kind="table", size=(0.6, 0.5))
TOP = TABLE.top_height
STEPS = 1500


def _tilted(o: PlacedObject, rng: np.random.Generator, scale: float) -> PlacedObject:
    """The object moved a little and turned about a random axis; its quaternion is left a little off unit length
    on purpose (the compiler normalises it, and so must a posed build)."""
    q = np.asarray(o.quaternion) + rng.normal(0.0, scale, 4)
    q = q / np.linalg.norm(q) * (1.0 + rng.uniform(-1e-9, 1e-9))
    position = np.asarray(o.position) + rng.normal(0.0, 0.01, 3) * (1.0, 1.0, 0.0) + (0.0, 0.0, 0.003)
    return o.model_copy(
        update={"position": tuple(float(v) for v in position), "quaternion": tuple(float(v) for v in q)}
    )


def _scene() -> Scene:
    book = placed_object("book_0", "book_flat_hardcover_red", 0.0, 0.0, TOP)
    mug = placed_object("mug_0", "mug_white", 0.02, 0.01, TOP + 0.03)
    can = placed_object("can_0", "ycb_005_tomato_soup_can", -0.15, 0.1, TOP)
    # A centre of mass moved by hand (the stability search does it) gives the body an explicit inertial.
    can = can.model_copy(update={"com": (0.01, 0.0, 0.04)})
    return Scene(support=TABLE, objects=[book, mug, can])


def _final_qpos(model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
    mujoco.mj_step(model, data, STEPS)
    return data.qpos.copy()


@pytest.mark.parametrize("profile", ["ours", "defaults"])
def test_a_posed_build_falls_to_the_last_bit_as_a_fresh_one(profile: str) -> None:
    engine = MujocoEngine()
    engine = engine if profile == "ours" else engine.with_profile(MUJOCO_DEFAULT)
    scene = _scene()
    engine.build_posed(scene)  # compiles and keeps the model
    rng = np.random.default_rng(7)
    for scale in (0.0, 0.02, 0.2):  # unturned, tilted, tumbling into the table
        moved = scene.model_copy(update={"objects": [_tilted(o, rng, scale) for o in scene.objects]})
        posed = engine.build_posed(moved)
        fresh = build_scene(moved, engine.catalogue, visual=False, profile=engine.profile)
        assert posed.model is engine.build_posed(moved).model  # one compiled model, posed again
        assert np.array_equal(posed.data.qpos, fresh.data.qpos)
        assert np.array_equal(_final_qpos(posed.model, posed.data), _final_qpos(fresh.model, fresh.data))


CHANGES = {
    "mass": lambda o: o.model_copy(update={"mass": o.mass * 2.0}),
    "friction": lambda o: o.model_copy(update={"friction": 0.2}),
    "centre of mass": lambda o: o.model_copy(update={"com": (0.01, 0.005, 0.03)}),
    "asset": lambda o: o.model_copy(update={"asset": "mug_red"}),
}


@pytest.mark.parametrize("change", list(CHANGES))
def test_a_posed_build_recompiles_when_anything_but_the_poses_changes(change: str) -> None:
    engine = MujocoEngine()
    scene = _scene()
    first = engine.build_posed(scene).model
    changed = scene.model_copy(
        update={"objects": [CHANGES[change](o) if o.id == "mug_0" else o for o in scene.objects]}
    )
    posed = engine.build_posed(changed)
    fresh = build_scene(changed, engine.catalogue, visual=False)
    assert posed.model is not first
    assert np.array_equal(_final_qpos(posed.model, posed.data), _final_qpos(fresh.model, fresh.data))
    assert engine.build_posed(scene).model is first  # still kept


def test_a_posed_build_recompiles_for_another_support_or_fewer_objects() -> None:
    engine = MujocoEngine()
    scene = _scene()
    first = engine.build_posed(scene).model
    wider = scene.model_copy(update={"support": Support(kind="table", size=(0.9, 0.5))})
    assert engine.build_posed(wider).model is not first
    fewer = engine.build_posed(scene, scene.objects[:2])
    assert fewer.model is not first and [o.id for o in fewer.objects] == ["book_0", "mug_0"]
    assert engine.build_posed(scene).model is first


def test_settling_from_a_kept_model_is_what_settling_from_a_fresh_one_was() -> None:
    scene = _scene()
    kept = MujocoEngine()
    kept.settle(scene)  # leaves the compiled model behind
    rng = np.random.default_rng(3)
    moved = scene.model_copy(update={"objects": [_tilted(o, rng, 0.02) for o in scene.objects]})
    again, fresh = kept.settle(moved), MujocoEngine().settle(moved)
    for oid, motion in fresh.objects.items():
        assert again.objects[oid].position == motion.position
        assert again.objects[oid].quaternion == motion.quaternion


def test_a_posed_build_normalises_quaternions_as_the_compiler_does() -> None:
    engine = MujocoEngine()
    can = placed_object("can_0", "ycb_005_tomato_soup_can", 0.0, 0.0, TOP + 0.05)
    scene = Scene(support=TABLE, objects=[can])
    engine.build_posed(scene)
    rng = np.random.default_rng(11)
    for k in range(60):
        q = rng.normal(size=4)
        off = (0.0, 1e-16, 1e-14, 1e-12, 1e-9, 0.3)[k % 6]  # within 1e-14 of unit length the compiler keeps it
        q = q / np.linalg.norm(q) * (1.0 + off)
        moved = Scene(support=TABLE, objects=[can.model_copy(update={"quaternion": tuple(float(v) for v in q)})])
        posed, fresh = engine.build_posed(moved), build_scene(moved, engine.catalogue, visual=False)
        assert np.array_equal(posed.model.body_quat, fresh.model.body_quat), q
        assert np.array_equal(posed.model.qpos0, fresh.model.qpos0), q


def _two_pass_reference(scene: Scene) -> mujoco.MjModel:
    """The model compiled the plain way: once to learn the inertia MuJoCo derives from each object's parts, then again
    with the scene's centres of mass where they differ from it."""
    plain = scene.model_copy(update={"objects": [o.model_copy(update={"com": (0.0, 0.0, 0.0)}) for o in scene.objects]})
    built = build_scene(plain, visual=False)  # a zero centre of mass means: the parts' own
    spec, model = built.spec.copy(), built.model
    for o in scene.placed:
        body, b = spec.body(o.id), model.body(o.id).id
        body.explicitinertial = True
        body.mass = o.mass
        body.ipos = list(o.com) if np.linalg.norm(np.subtract(o.com, model.body_ipos[b])) > 1e-4 else model.body_ipos[b]
        body.iquat = list(model.body_iquat[b])
        body.inertia = list(model.body_inertia[b])
    return spec.compile()


def test_one_compile_gives_each_body_the_inertia_of_its_parts_about_the_scenes_centre_of_mass() -> None:
    scene = _scene()
    built = build_scene(scene, visual=False)
    reference = _two_pass_reference(scene)
    for o in scene.placed:
        b = built.body[o.id]
        assert np.allclose(built.model.body_ipos[b], reference.body_ipos[b], atol=1e-12)
        assert np.allclose(built.model.body_inertia[b], reference.body_inertia[b], rtol=1e-12)
        assert np.allclose(built.model.body_iquat[b], reference.body_iquat[b], atol=1e-12)
        assert built.model.body_mass[b] == pytest.approx(o.mass)
    can = built.body["can_0"]  # its centre of mass was moved by hand: the scene's, not the parts'
    assert np.array_equal(built.model.body_ipos[can], (0.01, 0.0, 0.04))
