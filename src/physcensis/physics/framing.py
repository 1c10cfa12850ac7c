"""Where the camera stands: a view's angles, and the distance and aim that fit a scene into the picture.

MuJoCo's free camera looks along (cos el cos az, cos el sin az, sin el) from `distance` before its `lookat`. The
camera is fitted to points, not to a bounding sphere: every point projects inside the picture (within a margin) and
the points' extent is centred in it, so the support fills the picture as far as its shape allows.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from shapely.geometry import MultiPoint, Polygon, box

MARGIN = 0.98  # the fitted points stay within this share of the half-picture from its centre
FIT_ROUNDS = 12


@dataclass(frozen=True)
class Frame:
    """A perspective camera: where it aims, from how far and at what angles, with its field of view and aspect."""

    lookat: np.ndarray
    distance: float
    azimuth: float  # degrees
    elevation: float  # degrees, negative looking down
    fovy: float  # degrees, vertical
    aspect: float  # width / height

    @property
    def axes(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        return camera_axes(self.azimuth, self.elevation)

    def project(self, points: np.ndarray) -> np.ndarray:
        """(n, 2) picture coordinates in [-1, 1] across the picture's width and height (x to the right, y up),
        of (n, 3) world points in front of the camera; NaN for points behind it."""
        forward, right, up = self.axes
        eye = self.lookat - self.distance * forward
        rel = np.asarray(points, dtype=float) - eye
        depth = rel @ forward
        tan_y = math.tan(math.radians(self.fovy) / 2)
        with np.errstate(divide="ignore", invalid="ignore"):
            u = (rel @ right) / (depth * tan_y * self.aspect)
            v = (rel @ up) / (depth * tan_y)
        out = np.column_stack([u, v])
        out[depth <= 1e-6] = np.nan
        return out

    def pixels(self, points: np.ndarray, size: tuple[int, int]) -> np.ndarray:
        """(n, 2) (column, row) pixel positions, row 0 at the picture's top."""
        width, height = size
        uv = self.project(points)
        return np.column_stack([(uv[:, 0] + 1) / 2 * width, (1 - uv[:, 1]) / 2 * height])


def camera_axes(azimuth: float, elevation: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The camera's forward, right and up unit vectors (MuJoCo's free camera; world z up)."""
    az, el = math.radians(azimuth), math.radians(elevation)
    forward = np.array([math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)])
    right = np.cross(forward, [0.0, 0.0, 1.0])
    if np.linalg.norm(right) < 1e-9:  # straight down: the picture's right is the azimuth's right
        right = np.array([math.sin(az), -math.cos(az), 0.0])
    right /= np.linalg.norm(right)
    return forward, right, np.cross(right, forward)


def fit(points: np.ndarray, azimuth: float, elevation: float, fovy: float, aspect: float) -> Frame:
    """The closest camera at these angles that shows every point, the points' extent centred in the picture."""
    points = np.asarray(points, dtype=float).reshape(-1, 3)
    forward, right, up = camera_axes(azimuth, elevation)
    tan_y = math.tan(math.radians(fovy) / 2) * MARGIN
    tan_x = tan_y * aspect
    lookat = (points.min(axis=0) + points.max(axis=0)) / 2
    distance = 1.0
    for _ in range(FIT_ROUNDS):
        rel = points - lookat
        x, y, z = rel @ right, rel @ up, rel @ forward
        # A point at depth (distance + z) fits when |x| <= tan_x (distance + z), and likewise for y.
        distance = max(float(np.max(np.abs(x) / tan_x - z)), float(np.max(np.abs(y) / tan_y - z)), 1e-3)
        depth = distance + z
        u, v = x / (depth * tan_x), y / (depth * tan_y)
        du, dv = (u.max() + u.min()) / 2, (v.max() + v.min()) / 2
        if abs(du) < 1e-3 and abs(dv) < 1e-3:
            break
        lookat = lookat + right * du * distance * tan_x + up * dv * distance * tan_y
    return Frame(lookat, distance, azimuth, elevation, fovy, aspect)


def covered(frame: Frame, outline: np.ndarray) -> float:
    """The share of the picture's area inside the projected convex outline of these world points (0 to 1)."""
    uv = frame.project(outline)
    uv = uv[np.isfinite(uv).all(axis=1)]
    if len(uv) < 3:
        return 0.0
    hull = MultiPoint([tuple(p) for p in uv]).convex_hull
    if not isinstance(hull, Polygon):
        return 0.0
    return float(hull.intersection(box(-1.0, -1.0, 1.0, 1.0)).area / 4.0)


def extent_aspect(frame: Frame, points: np.ndarray) -> float:
    """Width over height of what `points` cover in the picture of `frame`."""
    uv = frame.project(points)
    uv = uv[np.isfinite(uv).all(axis=1)]
    width = float(np.ptp(uv[:, 0])) * frame.aspect
    height = float(np.ptp(uv[:, 1]))
    return width / max(height, 1e-9)


def fit_shaped(
    points: np.ndarray, azimuth: float, elevation: float, fovy: float, aspects: tuple[float, float]
) -> Frame:
    """`fit`, with the picture's aspect (width / height) chosen within `aspects` to match the points' own shape in
    it: a long counter gets a wide picture, a deep table a squarer one."""
    low, high = aspects
    frame = fit(points, azimuth, elevation, fovy, (low + high) / 2)
    for _ in range(3):  # the shape changes a little with the aspect under perspective
        aspect = float(np.clip(extent_aspect(frame, points), low, high))
        frame = fit(points, azimuth, elevation, fovy, aspect)
    return frame
