"""The viewer's first camera: at render.png's angles (the default view, physics/render.py), as far back as a browser
window of any shape needs to show the support and everything on it."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from physcensis.assets.catalogue import Catalogue
from physcensis.physics.framing import camera_axes
from physcensis.physics.render import DEFAULT_VIEW, Camera, frame_of
from physcensis.scene import Scene

FRAMING = 1.0  # of the distance at which the sphere around the support and its objects just fits the view
FLOOR_MARGIN_M = 0.2  # around what stands on a floor, which is framed instead of the whole floor


@dataclass(frozen=True)
class CameraPose:
    position: tuple[float, float, float]
    look_at: tuple[float, float, float]
    fov_deg: float  # vertical
    up: tuple[float, float, float] = (0.0, 0.0, 1.0)


def render_camera(scene: Scene, catalogue: Catalogue, points: np.ndarray) -> CameraPose:
    """A camera at render.png's angles (in front at +x, above the top, looking back towards -x) that frames the
    support's top and `points` (n, 3): the objects' mesh vertices in the world."""
    from physcensis.physics.mujoco_engine import MujocoEngine

    frame = frame_of(MujocoEngine(catalogue).build(scene), scene, Camera(view=DEFAULT_VIEW))
    forward, _, _ = camera_axes(frame.azimuth, frame.elevation)
    lo, hi = _bounds(scene, points)
    centre, radius = (lo + hi) / 2, float(np.linalg.norm(hi - lo) / 2)
    eye = centre - FRAMING * radius / math.sin(math.radians(frame.fovy) / 2) * forward  # it looks along `forward`
    return CameraPose(position=_triple(eye), look_at=_triple(centre), fov_deg=float(frame.fovy))


def _bounds(scene: Scene, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The box around the support's top (on a floor, around what stands on it) and `points`."""
    hx, hy = scene.support.half_extents
    top = scene.support.top_height
    lo, hi = np.array([-hx, -hy, top]), np.array([hx, hy, top + 0.05])
    if scene.support.kind == "floor" and len(points):
        lo = np.array([*(points[:, :2].min(0) - FLOOR_MARGIN_M), top])
        hi = np.array([*(points[:, :2].max(0) + FLOOR_MARGIN_M), top + 0.05])
    if len(points):
        lo, hi = np.minimum(lo, points.min(0)), np.maximum(hi, points.max(0))
    return lo, hi


def _triple(v: np.ndarray) -> tuple[float, float, float]:
    return float(v[0]), float(v[1]), float(v[2])
