"""Renders framed on the scene: the camera model agrees with MuJoCo's pictures, the support fills the default render,
every shelf board and a box's floor show, and no view is washed out."""

from __future__ import annotations

import math

import mujoco
import numpy as np
import pytest

from physcensis.api import generate
from physcensis.bench.prompt_suite import load_suite
from physcensis.physics.built import BuiltScene
from physcensis.physics.framing import MARGIN, Frame, covered, fit
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.physics.render import (
    VIEWS,
    Camera,
    RenderError,
    frame_of,
    framed_outline,
    image_centres,
    make_renderer,
    picture_size,
    render_built,
    support_outline,
)
from physcensis.scene import Scene, Support

pytestmark = pytest.mark.physics


@pytest.fixture(scope="module")
def dining() -> Scene:
    generated = generate("two mugs, a bowl and a book", support=Support(kind="table", size=(1.2, 0.8)), seed=0)
    assert generated.solution is not None
    return generated.solution.scene


def _support_pixels(built: BuiltScene, frame: Frame, size: tuple[int, int]) -> np.ndarray:
    """A mask of the pixels that show the support (its geoms, not the floor) in a picture of `size` by `frame`."""
    from physcensis.physics.render import mjv_camera, visual_options

    with make_renderer(built, size) as renderer:
        segments = renderer.segments(built.data, mjv_camera(built, frame), visual_options())
    ids, kinds = segments[..., 0], segments[..., 1]
    is_geom = (kinds == int(mujoco.mjtObj.mjOBJ_GEOM)) & (ids >= 0)
    support = built.model.body("support").id
    return is_geom & np.isin(ids, np.flatnonzero(built.model.geom_bodyid == support))


@pytest.mark.parametrize("seed", range(5))
def test_a_fitted_camera_shows_every_point_centred_and_close(seed: int) -> None:
    rng = np.random.default_rng(seed)
    points = rng.normal(size=(40, 3)) * rng.uniform(0.1, 2.0, size=3) + rng.uniform(-3, 3, size=3)
    azimuth, elevation = float(rng.uniform(0, 360)), float(rng.uniform(-85, -5))
    frame = fit(points, azimuth, elevation, 45.0, float(rng.uniform(0.7, 2.5)))
    uv = frame.project(points)
    assert np.isfinite(uv).all() and np.abs(uv).max() <= 1.0 + 1e-6  # nothing cut off
    reach = np.abs(uv).max(axis=0)
    assert reach.max() == pytest.approx(MARGIN, abs=0.01)  # as close as the margin lets it come
    centre = (uv.max(axis=0) + uv.min(axis=0)) / 2
    assert np.abs(centre).max() < 0.02


def test_the_camera_model_is_mujocos(dining: Scene) -> None:
    """Each object's pixels are where the fitted frame projects it, in every view: the framing and the coverage
    figures describe the pictures MuJoCo draws."""
    engine = MujocoEngine()
    built = engine.build(dining)
    size = (480, 360)
    for view in ("iso", "front", "top", "left"):
        frame = frame_of(built, dining, Camera(view), size)
        centres = image_centres(built, dining, view=view, size=size)
        for obj in dining.placed:
            if obj.id not in centres:
                continue
            body = built.body[obj.id]
            centre = built.data.xipos[body]  # the centre of mass: inside the object
            column, row = frame.pixels(centre[None, :], size)[0]
            assert math.dist((column, row), centres[obj.id]) < 0.08 * size[0], (view, obj.id)


SUITE_SUPPORTS = sorted({(c["support"]["kind"], tuple(c["support"]["size"])) for c in load_suite()})


@pytest.mark.slow
@pytest.mark.long  # 5 s: every support of the suite rendered
def test_the_support_fills_half_the_default_render_of_every_suite_support() -> None:
    """An empty support of each size the public suite uses: its outline covers at least half of render.png, as
    counted on the picture itself (the support's pixels) and as projected."""
    engine = MujocoEngine()
    for kind, size in SUITE_SUPPORTS:
        scene = Scene(support=Support(kind=kind, size=size), objects=[])  # type: ignore[arg-type]
        built = engine.build(scene)
        frame = frame_of(built, scene, Camera())
        assert covered(frame, framed_outline(scene)) >= 0.5, (kind, size)
        width, height = picture_size(frame)
        small = (width // 2, height // 2)  # the same picture at half the size: the same shares
        if kind != "floor":  # the floor's outline is what stands on it; an empty one shows only floor
            share = _support_pixels(built, frame, small).mean()
            assert share >= 0.5, (kind, size, share)


def test_every_shelf_board_shows() -> None:
    scene = Scene(support=Support(kind="shelf", size=(0.35, 1.0)), objects=[])
    built = MujocoEngine().build(scene)
    frame = frame_of(built, scene, Camera())
    outline = support_outline(scene.support)
    top = outline[:, 2].max()
    from physcensis.assets.supports import shelf_board_heights

    for z in shelf_board_heights(scene.support.top_height):
        front = np.array([[0.175, 0.0, min(z, top)]])
        u, v = frame.project(front)[0]
        assert abs(u) <= 1.0 and abs(v) <= 1.0, z


def test_an_open_box_is_seen_into() -> None:
    """Most of a box's floor is seen through its opening in the default render."""
    from shapely.geometry import MultiPoint

    from physcensis.assets.supports import box_wall_height

    support = Support(kind="box", size=(0.5, 0.4))
    scene = Scene(support=support, objects=[])
    built = MujocoEngine().build(scene)
    frame = frame_of(built, scene, Camera())
    x, y = support.size
    floor, rim = support.top_height, support.top_height + box_wall_height(support)

    def hull(z: float) -> object:
        corners = np.array([[sx * x / 2, sy * y / 2, z] for sx in (-1, 1) for sy in (-1, 1)])
        return MultiPoint([tuple(p) for p in frame.project(corners)]).convex_hull

    bottom, opening = hull(floor), hull(rim)
    assert bottom.intersection(opening).area >= 0.6 * bottom.area  # type: ignore[attr-defined]


@pytest.mark.parametrize("view", list(VIEWS))
def test_no_view_is_washed_out(dining: Scene, view: str) -> None:
    built = MujocoEngine().build(dining)
    image = render_built(built, dining, view=view, size=(320, 240))
    saturated = (image >= 250).all(axis=2).mean()
    assert saturated < 0.01, saturated
    support = _support_pixels(built, frame_of(built, dining, Camera(view), (320, 240)), (320, 240))
    brightness = image[support].mean()
    assert 60 < brightness < 235, brightness  # the support's wood is neither burnt out nor black


def test_a_named_view_and_given_angles() -> None:
    scene = Scene(support=Support(kind="table", size=(1.0, 0.7)), objects=[])
    built = MujocoEngine().build(scene)
    assert frame_of(built, scene, Camera("left"), (400, 300)).azimuth == VIEWS["left"][0]
    assert frame_of(built, scene, Camera("side"), (400, 300)).azimuth == VIEWS["right"][0]
    given = frame_of(built, scene, Camera("iso", azimuth=30.0, elevation=-20.0, distance=4.0, fovy=30.0), (400, 300))
    assert (given.azimuth, given.elevation, given.distance, given.fovy) == (30.0, -20.0, 4.0, 30.0)
    with pytest.raises(RenderError, match="unknown view 'sideways'"):
        frame_of(built, scene, Camera("sideways"), (400, 300))


def test_the_default_render_is_shaped_to_the_scene() -> None:
    """A long counter gets a wide picture, a deep table a squarer one; the longer side is 960 pixels."""
    engine = MujocoEngine()
    shapes = {}
    for size in ((0.6, 1.5), (1.2, 0.8)):
        scene = Scene(support=Support(kind="table", size=size), objects=[])
        image = engine.render(scene)
        assert max(image.shape[:2]) == 960
        shapes[size] = image.shape[1] / image.shape[0]
    assert shapes[(0.6, 1.5)] > 1.8 > shapes[(1.2, 0.8)]


def test_frame_projection_puts_what_is_behind_the_camera_nowhere() -> None:
    frame = Frame(np.zeros(3), 2.0, 180.0, -30.0, 45.0, 4 / 3)
    forward, _, _ = frame.axes
    behind = frame.lookat - 3.0 * forward
    assert np.isnan(frame.project(behind[None, :])).all()
