"""Pictures drawn on the kept GL context: one model's picture does not depend on what was drawn before it."""

from __future__ import annotations

import threading

import mujoco
import numpy as np
import pytest

from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.physics.offscreen import Offscreen, OffscreenError
from physcensis.physics.render import image_centres, render_built
from physcensis.scene import Scene, Support

from ..scenes import placed_object

pytestmark = pytest.mark.physics
TABLE = Support(kind="table", size=(0.8, 0.6))
SIZE = (160, 120)


def _scene(*objects: tuple[str, str, float]) -> Scene:
    return Scene(
        support=TABLE,
        objects=[placed_object(oid, asset, 0.0, y, TABLE.top_height + 0.001) for oid, asset, y in objects],
    )


@pytest.fixture(scope="module")
def engine() -> MujocoEngine:
    return MujocoEngine()


def test_a_picture_is_the_same_whatever_was_drawn_before(engine: MujocoEngine) -> None:
    mug, plates = _scene(("mug", "mug_white", 0.0)), _scene(("a", "plate_dinner_white", -0.2))
    first = render_built(engine.build(mug), mug, size=SIZE)
    other = render_built(engine.build(plates), plates, size=(200, 150))
    again = render_built(engine.build(mug), mug, size=SIZE)
    assert first.shape == (120, 160, 3) and other.shape == (150, 200, 3)
    assert np.array_equal(first, again)
    assert first.std() > 1.0  # a picture, not a blank


def test_the_objects_are_where_the_picture_shows_them(engine: MujocoEngine) -> None:
    scene = _scene(("left_mug", "mug_white", -0.25), ("right_mug", "mug_white", 0.25))
    centres = image_centres(engine.build(scene), scene, view="front", size=SIZE)
    assert set(centres) == {"left_mug", "right_mug"}
    assert centres["left_mug"][0] < SIZE[0] / 2 < centres["right_mug"][0]  # world -y is the viewer's left


def test_another_thread_draws_on_its_own_context(engine: MujocoEngine) -> None:
    scene = _scene(("mug", "mug_white", 0.0))
    here = render_built(engine.build(scene), scene, size=SIZE)
    there: list[np.ndarray] = []
    thread = threading.Thread(target=lambda: there.append(render_built(engine.build(scene), scene, size=SIZE)))
    thread.start()
    thread.join()
    assert len(there) == 1 and np.array_equal(here, there[0])


def test_a_closed_renderer_says_so(engine: MujocoEngine) -> None:
    scene = _scene(("mug", "mug_white", 0.0))
    built = engine.build(scene)
    with Offscreen(built.model, SIZE) as renderer:
        pass
    with pytest.raises(OffscreenError, match="closed"):
        renderer.rgb(built.data, mujoco.MjvCamera(), mujoco.MjvOption())
