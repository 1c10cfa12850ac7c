"""Headless pictures of a built scene: the camera frames the support and its objects automatically."""

from __future__ import annotations

import math

import mujoco
import numpy as np

from physcensis.errors import PhyscensisError
from physcensis.physics.built import BuiltScene
from physcensis.physics.engine import View
from physcensis.physics.mujoco_assets import VISUAL_GROUP
from physcensis.physics.offscreen import Offscreen, OffscreenError
from physcensis.scene import Scene

# (azimuth, elevation) in degrees; MuJoCo's camera looks along azimuth, so 180 looks from the front (+x): every view
# is the viewer's (viewpoint.py), who stands in front and sees world -y on the left of the picture.
VIEWS: dict[str, tuple[float, float]] = {"front": (180.0, -28.0), "top": (180.0, -89.9), "iso": (145.0, -38.0)}
DEFAULT_VIEW: View = "iso"  # render.png's: words such as "the rightmost plate" are told apart as it shows them


class RenderError(PhyscensisError):
    """Rendering could not start (usually no OpenGL context)."""


def _scene_bounds(built: BuiltScene, scene: Scene) -> tuple[np.ndarray, np.ndarray]:
    hx, hy = scene.support.half_extents
    top = scene.support.top_height
    lo = np.array([-hx, -hy, top])
    hi = np.array([hx, hy, top + 0.05])
    if scene.support.kind == "floor" and scene.placed:  # a floor is large: frame what is on it
        xy = np.array([o.position[:2] for o in scene.placed])
        lo = np.array([*(xy.min(0) - 0.2), top])
        hi = np.array([*(xy.max(0) + 0.2), top + 0.05])
    model, data = built.model, built.data
    object_bodies = set(built.body.values())
    for g in range(model.ngeom):
        if model.geom_group[g] != VISUAL_GROUP or int(model.geom_bodyid[g]) not in object_bodies:
            continue
        centre, radius = data.geom_xpos[g], model.geom_rbound[g]
        if radius > 0 and np.isfinite(centre).all():
            lo = np.minimum(lo, centre - radius * 0.7)
            hi = np.maximum(hi, centre + radius * 0.7)
    return lo, hi


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
    view: View = "iso",
    size: tuple[int, int] = (960, 720),
    renderer: Offscreen | None = None,
) -> np.ndarray:
    """RGB image (height, width, 3) of a built scene from one of the standard views."""
    own = renderer is None
    renderer = renderer or make_renderer(built, size)
    try:
        return renderer.rgb(built.data, _camera(built, scene, view, size), _visual_options())
    finally:
        if own:
            renderer.close()


def image_centres(
    built: BuiltScene, scene: Scene, *, view: View = "iso", size: tuple[int, int] = (480, 360)
) -> dict[str, tuple[float, float]]:
    """Where each object appears in the picture of `view`: the mean (column, row) in pixels of what of it is seen,
    column 0 at the picture's left and row 0 at its top; an object hidden entirely is left out."""
    with make_renderer(built, size) as renderer:
        segments = renderer.segments(built.data, _camera(built, scene, view, size), _visual_options())
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


def _camera(built: BuiltScene, scene: Scene, view: View, size: tuple[int, int]) -> mujoco.MjvCamera:
    """The free camera of a standard view, framing the support and its objects."""
    if view not in VIEWS:
        raise RenderError(f"unknown view {view!r}; choose one of {', '.join(VIEWS)}")
    width, height = size
    lo, hi = _scene_bounds(built, scene)
    camera = mujoco.MjvCamera()
    camera.type = mujoco.mjtCamera.mjCAMERA_FREE
    camera.azimuth, camera.elevation = VIEWS[view]
    camera.lookat[:] = (lo + hi) / 2
    half = (hi - lo) / 2
    fovy = math.radians(built.model.vis.global_.fovy)
    aspect = width / height
    # Distance at which a sphere around the box fits the narrower field of view.
    radius = float(np.linalg.norm(half))
    half_fov = min(fovy / 2, math.atan(math.tan(fovy / 2) * aspect))
    camera.distance = 0.9 * radius / math.sin(half_fov)
    return camera


def _visual_options() -> mujoco.MjvOption:
    """The support, the floor and the objects' visual meshes; no collision geometry."""
    options = mujoco.MjvOption()
    options.geomgroup[:] = 0
    options.geomgroup[0] = 1  # support and floor
    options.geomgroup[VISUAL_GROUP] = 1
    return options
