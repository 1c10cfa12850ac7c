"""Headless pictures of a built scene: the camera frames the support and its objects automatically."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import mujoco
import numpy as np

from physcensis.assets.supports import BOX_WALL, SHELF_BOARD, TABLE_TOP, box_wall_height, shelf_board_heights
from physcensis.errors import PhyscensisError
from physcensis.physics.built import BuiltScene
from physcensis.physics.engine import View
from physcensis.physics.framing import Frame, covered, fit, fit_shaped
from physcensis.physics.mujoco_assets import VISUAL_GROUP
from physcensis.physics.offscreen import Offscreen, OffscreenError
from physcensis.scene import Scene, Support

# (azimuth, elevation) in degrees of each named view. MuJoCo's camera looks along its azimuth, so 180 looks from the
# front (+x): every view is named as the viewer (viewpoint.py) says it, who stands in front and sees world -y on the
# left of the picture; "left" looks from the viewer's left side (-y).
VIEWS: dict[str, tuple[float, float]] = {
    "iso": (150.0, -42.0),
    "iso-right": (210.0, -42.0),
    "front": (180.0, -30.0),
    "back": (0.0, -30.0),
    "left": (90.0, -25.0),
    "right": (270.0, -25.0),
    "top": (180.0, -89.9),
}
VIEW_ALIASES = {"side": "right"}
DEFAULT_VIEW: View = "iso"  # render.png's: words such as "the rightmost plate" are told apart as it shows them
# Steeper or flatter views by support: a shelf is seen nearly level so every board's objects show, an open box
# from high enough above to see into it.
ELEVATIONS: dict[str, dict[str, float]] = {
    "shelf": {"iso": -15.0, "iso-right": -15.0, "front": -10.0, "back": -15.0, "left": -15.0, "right": -15.0},
    "box": {"iso": -60.0, "iso-right": -60.0, "front": -60.0, "back": -60.0, "left": -60.0, "right": -60.0},
    "floor": {"iso": -50.0, "iso-right": -50.0, "front": -45.0},
}
# The default view's angles to try, most oblique first: the first whose support covers COVER_TARGET of the picture
# is taken, else the one that covers most. All look from the front and the viewer's left (azimuth below 180), as
# the robot's "leftmost" and "rightmost" assume (robot/tasks.py).
ISO_CHOICES: dict[str, tuple[tuple[float, float], ...]] = {
    "table": (
        (150.0, -45.0),
        (160.0, -50.0),
        (165.0, -55.0),
        (170.0, -60.0),
        (175.0, -65.0),
        (175.0, -70.0),
        (178.0, -80.0),
    ),
    "shelf": ((155.0, -15.0), (165.0, -12.0), (175.0, -10.0)),
    "box": ((150.0, -55.0), (160.0, -60.0), (170.0, -65.0), (175.0, -70.0)),
    "floor": ((150.0, -50.0), (160.0, -55.0), (170.0, -60.0)),
}
COVER_TARGET = 0.55
RENDER_SIDE = 960  # render.png's longer side; its shape suits the scene, within PICTURE_ASPECTS (width / height)
PICTURE_ASPECTS = (0.6, 3.0)
HEADLIGHT_DIFFUSE = 0.4  # looking level; less as the view looks down
FLOOR_MARGIN_M = 0.2  # around what stands on a floor, which is framed instead of the whole floor


@dataclass(frozen=True)
class Camera:
    """A named view, with any of its azimuth, elevation, distance (m) and vertical field of view (degrees) given
    instead of the view's own; what is not given is the view's, and the distance is fitted to the scene."""

    view: str = DEFAULT_VIEW
    azimuth: float | None = None
    elevation: float | None = None
    distance: float | None = None
    fovy: float | None = None

    def angles(self, support_kind: str) -> tuple[float, float]:
        """The azimuth and elevation (degrees) of this camera over a support of this kind."""
        name = view_name(self.view)
        azimuth, elevation = VIEWS[name]
        elevation = ELEVATIONS.get(support_kind, {}).get(name, elevation)
        return (
            azimuth if self.azimuth is None else self.azimuth,
            elevation if self.elevation is None else self.elevation,
        )


def view_name(view: str) -> str:
    """The view's name in VIEWS (an alias resolved), or RenderError naming the views there are."""
    name = VIEW_ALIASES.get(view, view)
    if name not in VIEWS:
        raise RenderError(f"unknown view {view!r}; choose one of {', '.join([*VIEWS, *VIEW_ALIASES])}")
    return name


class RenderError(PhyscensisError):
    """Rendering could not start (usually no OpenGL context)."""


def support_outline(support: Support, placed: np.ndarray | None = None) -> np.ndarray:
    """Corners (n, 3) of what of the support the picture frames: a table's top slab (not its legs), a shelf unit
    and an open box whole, and of a floor the part that `placed` (object positions) stand on."""
    x, y = support.size
    top = support.top_height
    if support.kind == "table":
        return _corners((-x / 2, -y / 2, top - TABLE_TOP), (x / 2, y / 2, top))
    if support.kind == "shelf":
        return _corners(
            (-x / 2 - SHELF_BOARD, -y / 2 - SHELF_BOARD, 0.0),
            (x / 2, y / 2 + SHELF_BOARD, shelf_board_heights(top)[-1]),
        )
    if support.kind == "box":
        return _corners(
            (-x / 2 - BOX_WALL, -y / 2 - BOX_WALL, 0.0),
            (x / 2 + BOX_WALL, y / 2 + BOX_WALL, top + box_wall_height(support)),
        )
    if placed is not None and len(placed):  # a floor is large: its part around the objects
        lo = np.maximum(placed[:, :2].min(axis=0) - FLOOR_MARGIN_M, [-x / 2, -y / 2])
        hi = np.minimum(placed[:, :2].max(axis=0) + FLOOR_MARGIN_M, [x / 2, y / 2])
        return _corners((*lo, top), (*hi, top))
    return _corners((-x / 2, -y / 2, top), (x / 2, y / 2, top))


def _corners(lo: tuple[float, ...], hi: tuple[float, ...]) -> np.ndarray:
    return np.array([[(lo, hi)[i][0], (lo, hi)[j][1], (lo, hi)[k][2]] for i in (0, 1) for j in (0, 1) for k in (0, 1)])


def framed_points(built: BuiltScene, scene: Scene) -> np.ndarray:
    """The points the camera must show: the support's outline and the corners of every object's visual geoms."""
    positions = np.array([o.position for o in scene.placed]) if scene.placed else None
    points = [support_outline(scene.support, positions)]
    model, data = built.model, built.data
    object_bodies = set(built.body.values())
    signs = _corners((-1.0, -1.0, -1.0), (1.0, 1.0, 1.0))
    for g in range(model.ngeom):
        if model.geom_group[g] != VISUAL_GROUP or int(model.geom_bodyid[g]) not in object_bodies:
            continue
        centre, half = model.geom_aabb[g, :3], model.geom_aabb[g, 3:]
        corners = data.geom_xpos[g] + (centre + signs * half) @ data.geom_xmat[g].reshape(3, 3).T
        if np.isfinite(corners).all():
            points.append(corners)
    return np.concatenate(points)


def frame_of(built: BuiltScene, scene: Scene, camera: Camera, size: tuple[int, int] | None = None) -> Frame:
    """Where `camera` stands for this scene, fitted to it, in a picture of `size`, or (None) of the shape that suits
    the scene; then the default view with no angle given takes the first of ISO_CHOICES that frames it well."""
    fovy = float(built.model.vis.global_.fovy) if camera.fovy is None else camera.fovy
    points = framed_points(built, scene)
    choices = [camera.angles(scene.support.kind)]
    if view_name(camera.view) == DEFAULT_VIEW and camera.azimuth is None and camera.elevation is None:
        iso = ISO_CHOICES.get(scene.support.kind, ISO_CHOICES["table"])
        choices = list(iso) if size is None else [iso[0]]  # a picture of a given shape is not searched for
    outline = framed_outline(scene)
    best: tuple[float, Frame] | None = None
    for azimuth, elevation in choices:
        if size is None:
            frame = fit_shaped(points, azimuth, elevation, fovy, PICTURE_ASPECTS)
        else:
            frame = fit(points, azimuth, elevation, fovy, size[0] / size[1])
        share = covered(frame, outline)
        if best is None or share > best[0]:
            best = (share, frame)
        if share >= COVER_TARGET:
            break
    assert best is not None
    frame = best[1]
    return frame if camera.distance is None else replace(frame, distance=camera.distance)


def framed_outline(scene: Scene) -> np.ndarray:
    """The support's outline whose share of the picture the framing is judged by: a table's top, the rest whole."""
    positions = np.array([o.position for o in scene.placed]) if scene.placed else None
    corners = support_outline(scene.support, positions)
    return corners[1::2] if scene.support.kind == "table" else corners  # the slab's upper corners


def picture_size(frame: Frame) -> tuple[int, int]:
    """The size of a picture of the frame's aspect whose longer side is RENDER_SIDE."""
    if frame.aspect >= 1.0:
        return RENDER_SIDE, max(16, round(RENDER_SIDE / frame.aspect))
    return max(16, round(RENDER_SIDE * frame.aspect)), RENDER_SIDE


def make_renderer(built: BuiltScene, size: tuple[int, int]) -> Offscreen:
    """An offscreen renderer for a built scene; reuse it for several frames of the same scene."""
    width, height = size
    model = built.model
    if not (16 <= width <= model.vis.global_.offwidth and 16 <= height <= model.vis.global_.offheight):
        raise RenderError(
            f"image size {width}x{height} must be between 16x16 and "
            f"{model.vis.global_.offwidth}x{model.vis.global_.offheight}"
        )
    try:
        return Offscreen(model, size)
    except OffscreenError as exc:
        raise RenderError(str(exc)) from None


def render_built(
    built: BuiltScene,
    scene: Scene,
    *,
    view: str | Camera = DEFAULT_VIEW,
    size: tuple[int, int] | None = None,
    renderer: Offscreen | None = None,
) -> np.ndarray:
    """RGB image (height, width, 3) of a built scene from a named view (VIEWS) or a Camera, of `size` (width,
    height) or (None) RENDER_SIDE wide and as high as suits the scene. A `renderer` is drawn with at its size."""
    camera = view if isinstance(view, Camera) else Camera(view)
    frame = frame_of(built, scene, camera, size)
    size = size or picture_size(frame)
    own = renderer is None
    renderer = renderer or make_renderer(built, size)
    try:
        return renderer.rgb(built.data, mjv_camera(built, frame), visual_options())
    finally:
        if own:
            renderer.close()


def image_centres(
    built: BuiltScene, scene: Scene, *, view: str | Camera = DEFAULT_VIEW, size: tuple[int, int] = (480, 360)
) -> dict[str, tuple[float, float]]:
    """Where each object appears in the picture of `view`: the mean (column, row) in pixels of what of it is seen,
    column 0 at the picture's left and row 0 at its top; an object hidden entirely is left out."""
    frame = frame_of(built, scene, view if isinstance(view, Camera) else Camera(view), size)
    with make_renderer(built, size) as renderer:
        segments = renderer.segments(built.data, mjv_camera(built, frame), visual_options())
    ids, kinds = segments[..., 0], segments[..., 1]
    is_geom = (kinds == int(mujoco.mjtObj.mjOBJ_GEOM)) & (ids >= 0)
    body = np.full(ids.shape, -1)
    body[is_geom] = built.model.geom_bodyid[ids[is_geom]]
    centres = {}
    for oid, body_id in built.body.items():
        rows, columns = np.nonzero(body == body_id)
        if len(rows):
            centres[oid] = (float(columns.mean()), float(rows.mean()))
    return centres


def mjv_camera(built: BuiltScene, frame: Frame) -> mujoco.MjvCamera:
    """MuJoCo's free camera of a frame; the model's field of view is set to the frame's."""
    if not 1.0 <= frame.fovy <= 170.0:
        raise RenderError(f"field of view {frame.fovy:g} degrees must be between 1 and 170")
    if not (math.isfinite(frame.distance) and frame.distance > 0):
        raise RenderError(f"camera distance {frame.distance:g} m must be a positive number")
    built.model.vis.global_.fovy = frame.fovy
    # The headlight shines along the view: looking down, it would add to the lights above and wash out every top.
    built.model.vis.headlight.diffuse[:] = HEADLIGHT_DIFFUSE * math.cos(math.radians(frame.elevation))
    camera = mujoco.MjvCamera()
    camera.type = mujoco.mjtCamera.mjCAMERA_FREE
    camera.azimuth, camera.elevation = frame.azimuth, frame.elevation
    camera.lookat[:] = frame.lookat
    camera.distance = frame.distance
    return camera


def visual_options() -> mujoco.MjvOption:
    """The support, the floor and the objects' visual meshes; no collision geometry."""
    options = mujoco.MjvOption()
    options.geomgroup[:] = 0
    options.geomgroup[0] = 1  # support and floor
    options.geomgroup[VISUAL_GROUP] = 1
    return options


def render_views(
    built: BuiltScene, scene: Scene, views: list[str], tile: tuple[int, int] = (480, 360), columns: int = 4
) -> tuple[np.ndarray, list[tuple[int, int, str]]]:
    """A sheet of the scene from several named views, `columns` to a row, each tile framed on its own; with the
    (column, row, name) of each tile's label for `save_png`."""
    width, height = tile
    rows = -(-len(views) // columns)
    sheet = np.full((rows * height, min(columns, len(views)) * width, 3), 255, dtype=np.uint8)
    labels = []
    with make_renderer(built, tile) as renderer:
        for k, name in enumerate(views):
            r, c = divmod(k, columns)
            image = render_built(built, scene, view=name, size=tile, renderer=renderer)
            sheet[r * height : (r + 1) * height, c * width : (c + 1) * width] = image
            labels.append((c * width + 6, r * height + 4, name))
    return sheet, labels


def support_share(built: BuiltScene, scene: Scene) -> float:
    """The share of the default render (render.png) that the support's outline covers (0 to 1)."""
    return covered(frame_of(built, scene, Camera()), framed_outline(scene))
