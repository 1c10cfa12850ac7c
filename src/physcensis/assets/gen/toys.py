"""Toys: balls, toy trucks, stuffed animals."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.gen.common import fit_to_size
from physcensis.assets.gen.variant_data import builtin_categories
from physcensis.assets.spec import CategoryDef, Geometry, NoOptions, Variant, builder


@dataclass(frozen=True)
class BallShape:
    """The seam drawn on the ball, and for great circles whether there are three."""

    seam: Literal["none", "tennis", "lines"] = "none"
    three: bool = False


@builder(BallShape)
def ball(v: Variant, p: BallShape) -> Geometry:
    """A sphere with seam lines (tennis-ball curve or great circles); collision is an exact sphere."""
    d = v.size[0]
    r = d / 2
    body = shapes.sphere(r, (0, 0, r), 3)
    parts = [(body, v.color(0, P.RED))]
    seam = p.seam
    w = max(0.0012, 0.02 * r)
    if seam == "tennis":
        t = np.linspace(0, 2 * np.pi, 80)
        a, b = 0.75, 0.25
        pts = np.stack(
            [a * np.cos(t) + b * np.cos(3 * t), a * np.sin(t) - b * np.sin(3 * t), 2 * np.sqrt(a * b) * np.sin(2 * t)],
            axis=1,
        )
        pts = pts / np.linalg.norm(pts, axis=1, keepdims=True) * (r + 0.2 * w)
        parts.append((shapes.tube(np.vstack([pts, pts[:1]]) + (0, 0, r), w, sides=6), v.color(1, P.WHITE)))
    elif seam == "lines":
        t = np.linspace(0, 2 * np.pi, 64)
        for axis in range(3 if p.three else 2):
            circ = np.zeros((64, 3))
            circ[:, axis] = (r + 0.2 * w) * np.cos(t)
            circ[:, (axis + 1) % 3] = (r + 0.2 * w) * np.sin(t)
            parts.append((shapes.tube(circ + (0, 0, r), w, sides=6), v.color(1, P.BLACK)))
    return Geometry(tuple(parts), (col.sphere_part(r, (0, 0, r)),))


@builder(NoOptions)
def toy_truck(v: Variant, _: NoOptions) -> Geometry:
    """A toy truck: chassis, cab at the front (+x) with windows, cargo bed, four wheels."""
    x, y, z = v.size
    wheel_r = 0.22 * z
    wheel_w = 0.16 * y
    body_y = y - 2 * 0.002
    chassis_z0 = 0.6 * wheel_r
    cab_len = 0.32 * x
    body = v.color(0, P.RED)
    chassis = shapes.box((x, body_y - 2 * wheel_w, 0.12 * z), (0, 0, chassis_z0 + 0.06 * z))
    cab = shapes.rounded_box(
        (cab_len, body_y, z - chassis_z0 - 0.1 * z),
        0.01,
        (x / 2 - cab_len / 2, 0, chassis_z0 + 0.1 * z + (z - chassis_z0 - 0.1 * z) / 2),
    )
    window = shapes.box((0.004, 0.8 * body_y, 0.25 * z), (x / 2 + 0.0005 - 0.002, 0, 0.72 * z))
    side_windows = shapes.box((0.5 * cab_len, body_y + 0.002, 0.22 * z), (x / 2 - cab_len / 2, 0, 0.72 * z))
    bed_len = x - cab_len - 0.01
    bed = shapes.box((bed_len, body_y, 0.45 * z), (-x / 2 + bed_len / 2, 0, chassis_z0 + 0.1 * z + 0.225 * z))
    wheels = []
    for wx in (x / 2 - 0.5 * cab_len, -x / 2 + 0.25 * bed_len + wheel_r * 0.5):
        for sy in (1, -1):
            wheels.append(
                shapes.cylinder(wheel_r, wheel_w, (wx, sy * (y / 2 - wheel_w / 2), wheel_r), axis="y", sections=24)
            )
    hubs = [
        shapes.cylinder(0.45 * wheel_r, wheel_w + 0.002, w.bounds.mean(axis=0), axis="y", sections=16) for w in wheels
    ]
    parts = (
        (chassis, P.CHARCOAL),
        (cab, body),
        (bed, v.color(1, P.YELLOW)),
        (window, P.rgb(150, 200, 230)),
        (side_windows, P.rgb(150, 200, 230)),
        (shapes.concatenate(wheels), P.BLACK),
        (shapes.concatenate(hubs), P.SILVER),
    )
    collision = [col.hull_part(np.vstack([cab.vertices, chassis.vertices])), col.hull_part(bed)]
    for w in wheels:
        c = w.bounds.mean(axis=0)
        collision.append(col.cylinder_part(wheel_r, wheel_w, c, (0, 1, 0)))
    return Geometry(parts, tuple(collision))


@dataclass(frozen=True)
class StuffedAnimalShape:
    """The ears."""

    ears: Literal["round", "long", "pointed"] = "round"


@builder(StuffedAnimalShape)
def stuffed_animal(v: Variant, p: StuffedAnimalShape) -> Geometry:
    """A sitting plush animal facing +x: body, head, muzzle, ears (round, long or pointed), arms, legs."""
    x, y, z = v.size
    ears = p.ears
    ear_h = {"round": 0.1, "long": 0.2, "pointed": 0.12}[ears] * z
    head_r = 0.22 * (z - ear_h) * 1.05
    body_h = z - ear_h - 1.7 * head_r
    fur = v.color(0, P.BROWN)
    light = v.color(1, P.rgb(230, 200, 160))
    bx, by = 0.5 * x * 0.75, 0.5 * y * 0.7
    body = shapes.ellipsoid((bx * 0.8, by, body_h * 0.55), (-0.1 * x, 0, body_h * 0.55), 2)
    head_c = (-0.05 * x, 0, body_h + head_r * 0.85)
    head = shapes.sphere(head_r, head_c, 2)
    muzzle = shapes.ellipsoid(
        (0.45 * head_r, 0.5 * head_r, 0.38 * head_r), (head_c[0] + 0.85 * head_r, 0, head_c[2] - 0.25 * head_r), 2
    )
    eyes = [
        shapes.sphere(0.11 * head_r, (head_c[0] + 0.82 * head_r, s * 0.35 * head_r, head_c[2] + 0.22 * head_r), 1)
        for s in (1, -1)
    ]
    ear_parts = []
    for s in (1, -1):
        base = np.array([head_c[0], s * 0.55 * head_r, head_c[2] + 0.7 * head_r])
        if ears == "round":
            ear_parts.append(
                shapes.ellipsoid(
                    (0.18 * head_r, 0.3 * head_r, 0.3 * head_r), base + (0, s * 0.1 * head_r, 0.15 * head_r), 2
                )
            )
        else:
            tip = base + np.array([0, s * 0.15 * head_r, ear_h + 0.25 * head_r])
            ear_parts.append(
                shapes.tube(
                    np.linspace(base, tip, 6), np.linspace(0.25 * head_r, 0.06 * head_r, 6), sides=10, squash=0.5
                )
            )
    legs = [
        shapes.ellipsoid(
            (0.55 * x * 0.5, 0.2 * y, 0.16 * body_h + 0.01), (0.2 * x, s * 0.28 * y, 0.16 * body_h + 0.01), 2
        )
        for s in (1, -1)
    ]
    arms = [
        shapes.ellipsoid((0.15 * x, 0.13 * y, 0.3 * body_h), (0.02 * x, s * (by + 0.02 * y), 0.6 * body_h), 2)
        for s in (1, -1)
    ]
    parts = (
        (body, fur),
        (head, fur),
        (muzzle, light),
        (shapes.concatenate(eyes), P.BLACK),
        (shapes.concatenate(ear_parts), fur),
        (shapes.concatenate(legs), fur),
        (shapes.concatenate(arms), fur),
    )
    collision = (
        col.hull_part(np.vstack([body.vertices, *[m.vertices for m in legs + arms]])),
        col.hull_part(np.vstack([head.vertices, muzzle.vertices, *[m.vertices for m in ear_parts]])),
    )
    return fit_to_size(Geometry(parts, collision), v.size)


CATEGORIES: tuple[CategoryDef, ...] = builtin_categories(__name__, globals())  # variants: data/toys.json
