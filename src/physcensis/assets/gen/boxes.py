"""Boxes (open, closed, gift, cereal, tissue, shoe, toolbox), baskets and toy blocks."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
import trimesh

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.gen.common import Vessel, rectangle, resample
from physcensis.assets.gen.variant_data import builtin_categories
from physcensis.assets.model import RGBA, Cavity
from physcensis.assets.spec import CategoryDef, Geometry, Variant, builder


def _open_box_mesh(x: float, y: float, z: float, wall: float, floor: float, radius: float = 0.0) -> trimesh.Trimesh:
    outer = shapes.slab(x, y, z, radius, (0, 0, z / 2))
    inner = shapes.slab(x - 2 * wall, y - 2 * wall, z, max(0.0, radius - wall), (0, 0, floor + z / 2))
    return trimesh.boolean.difference([outer, inner], engine="manifold")


def open_tray(
    size: tuple[float, float, float], wall: float, floor: float, color: RGBA, radius: float = 0.0
) -> Geometry:
    """An open-topped rectangular container (walls, floor, no lid) with its cavity: open shoe boxes, egg cartons,
    pencil cases and tins share it."""
    x, y, z = size
    mesh = _open_box_mesh(x, y, z, wall, floor, radius)
    cavity = Cavity(rectangle(x - 2 * wall, y - 2 * wall), floor, z - floor)
    return Geometry(((mesh, color),), tuple(col.open_box_parts(x, y, z, wall, floor)), cavity)


@dataclass(frozen=True)
class OpenBoxShape:
    """Wall and floor thickness and the width of the folded-out flaps (m; 0: no flaps)."""

    wall: float = 0.004
    floor: float = 0.004
    flap: float = 0.0


@builder(OpenBoxShape)
def open_box(v: Variant, p: OpenBoxShape) -> Geometry:
    """An open-topped cardboard box: five slabs, flaps folded outwards at the top."""
    x, y, z = v.size
    wall, floor = p.wall, p.floor
    flap = p.flap
    body_z = z
    mesh = _open_box_mesh(x - 2 * flap, y - 2 * flap, body_z, wall, floor)
    parts = [(mesh, v.color(0, P.CARDBOARD))]
    if flap:
        bx, by = x - 2 * flap, y - 2 * flap
        t = 0.003
        for sx, sy, ex, ey in ((1, 0, flap, by), (-1, 0, flap, by), (0, 1, bx, flap), (0, -1, bx, flap)):
            cx, cy = sx * (bx / 2 + flap / 2), sy * (by / 2 + flap / 2)
            parts.append((shapes.box((ex, ey, t), (cx, cy, body_z - t / 2)), v.color(0, P.CARDBOARD)))
    ix, iy = x - 2 * flap - 2 * wall, y - 2 * flap - 2 * wall
    collision = col.open_box_parts(x - 2 * flap, y - 2 * flap, body_z, wall, floor)
    return Geometry(tuple(parts), tuple(collision), Cavity(rectangle(ix, iy), floor, body_z - floor))


@dataclass(frozen=True)
class ClosedBoxShape:
    """The decoration, and for gifts the height of the bow (m; 0: none)."""

    style: Literal["plain", "tape", "gift", "cereal", "tissue", "lid"] = "plain"
    bow: float = 0.0


@builder(ClosedBoxShape)
def closed_box(v: Variant, p: ClosedBoxShape) -> Geometry:
    """A closed box with optional tape strip, ribbon and bow, front panel or lid."""
    x, y, z = v.size
    style = p.style
    main = v.color(0, P.CARDBOARD)
    accent = v.color(1, P.WHITE)
    bow_h = p.bow
    body_z = z - bow_h
    parts = [(shapes.box((x, y, body_z), (0, 0, body_z / 2)), main)]
    collision = [col.box_part((x, y, body_z), (0, 0, body_z / 2))]
    if style == "tape":
        parts.append((shapes.box((x * 0.999, 0.05, 0.002), (0, 0, body_z - 0.0009)), P.rgb(215, 190, 140)))
    elif style == "gift":
        w = min(0.025, 0.15 * min(x, y))
        parts.append((shapes.box((x + 0.002, w, body_z + 0.002), (0, 0, body_z / 2)), accent))
        parts.append((shapes.box((w, y + 0.002, body_z + 0.002), (0, 0, body_z / 2)), accent))
        if bow_h:
            for yaw in (0.6, -0.6, 2.5, -2.5):
                c = 0.45 * bow_h
                centre = (c * np.cos(yaw) * 1.6, c * np.sin(yaw) * 1.6, body_z + bow_h * 0.45)
                loop = shapes.ellipsoid((1.1 * bow_h, 0.45 * bow_h, 0.45 * bow_h), (0, 0, 0), 2)
                loop.apply_transform(trimesh.transformations.rotation_matrix(yaw, (0, 0, 1)))
                loop.apply_translation(centre)
                parts.append((loop, accent))
            knot = shapes.sphere(0.35 * bow_h, (0, 0, body_z + 0.3 * bow_h), 2)
            parts.append((knot, accent))
            bow_pts = np.vstack([m.vertices for m, _ in parts[3:]])
            collision.append(col.hull_part(bow_pts))
    elif style == "cereal":
        parts.append((shapes.box((0.002, 0.86 * y, 0.55 * body_z), (x / 2, 0, 0.52 * body_z)), accent))
        parts.append((shapes.box((0.002, 0.7 * y, 0.12 * body_z), (x / 2, 0, 0.88 * body_z)), v.color(2, P.YELLOW)))
    elif style == "tissue":
        body_z = z - 0.022
        parts = [(shapes.box((x, y, body_z), (0, 0, body_z / 2)), main)]
        collision = [col.box_part((x, y, body_z), (0, 0, body_z / 2))]
        slot = shapes.slab(0.45 * x, 0.14 * y, 0.002, 0.01, (0, 0, body_z - 0.0008))
        puff = shapes.ellipsoid((0.12 * x, 0.06 * y, 0.03), (0, 0, body_z - 0.008), 2)
        parts += [(slot, P.CHARCOAL), (puff, P.WHITE)]
    elif style == "lid":
        lid_h = 0.3 * body_z
        parts.append((shapes.box((x, y, lid_h), (0, 0, body_z - lid_h / 2)), accent))
        parts[0] = (shapes.box((x - 0.006, y - 0.006, body_z - 0.002), (0, 0, body_z / 2 - 0.001)), main)
    return Geometry(tuple(parts), tuple(collision))


@dataclass(frozen=True)
class ToolboxShape:
    """The open body's height as a fraction of the whole (the lid stands above it)."""

    body: float = 0.55


@builder(ToolboxShape)
def toolbox(v: Variant, p: ToolboxShape) -> Geometry:
    """An open metal toolbox: open body (five slabs), lid standing open at the back (-x), end grips on +-y."""
    x, y, z = v.size
    lid_t, grip = 0.004, 0.01
    body_x, body_y = x - lid_t, y - 2 * grip
    body_z = p.body * z
    wall, floor = 0.003, 0.004
    shift = np.array([lid_t / 2, 0.0, 0.0])
    body = _open_box_mesh(body_x, body_y, body_z, wall, floor)
    body.apply_translation(shift)
    lid_z = z - body_z
    lid_centre = (-body_x / 2, 0.0, body_z + lid_z / 2 - 0.005)
    lid = shapes.box((lid_t, body_y, lid_z + 0.01), lid_centre)
    grips = [
        shapes.rounded_box(
            (0.07, grip + 0.004, 0.02), 0.004, (lid_t / 2, s * (body_y / 2 + grip / 2 - 0.002), 0.75 * body_z)
        )
        for s in (1, -1)
    ]
    color = v.color(0, P.RED)
    collision = [c.translated(shift) for c in col.open_box_parts(body_x, body_y, body_z, wall, floor)]
    collision.append(col.box_part((lid_t, body_y, lid_z + 0.01), lid_centre))
    cavity = Cavity(rectangle(body_x - 2 * wall, body_y - 2 * wall, (lid_t / 2, 0.0)), floor, body_z - floor)
    parts = ((body, color), (lid, color), (grips[0], P.CHARCOAL), (grips[1], P.CHARCOAL))
    return Geometry(parts, tuple(collision), cavity)


@dataclass(frozen=True)
class BasketShape:
    """Round (revolved) instead of rectangular."""

    round: bool = False


@builder(BasketShape)
def basket(v: Variant, p: BasketShape) -> Geometry:
    """A woven basket: round (revolved walls with woven bands) or rectangular (slabs)."""
    x, y, z = v.size
    color = v.color(0, P.rgb(190, 150, 95))
    dark = v.color(1, P.rgb(150, 110, 65))
    if p.round:
        r = x / 2
        vessel = Vessel(resample([(0.8 * r, 0.0), (r, z)], 6), 0.008, 0.008, stations=2)
        parts = [(vessel.mesh(), color)]
        for k in range(1, 4):
            zb = z * k / 4
            rb = 0.8 * r + 0.2 * r * zb / z
            parts.append(
                (
                    trimesh.creation.annulus(r_min=rb - 0.004, r_max=rb + 0.0025, height=0.012).apply_translation(
                        (0, 0, zb)
                    ),
                    dark,
                )
            )
        return Geometry(tuple(parts), tuple(vessel.collision(16)), vessel.cavity())
    wall = 0.008
    mesh = _open_box_mesh(x, y, z, wall, 0.008, radius=0.03)
    parts = [(mesh, color)]
    for k in range(1, 4):
        zb = z * k / 4
        ring = _open_box_mesh(x + 0.004, y + 0.004, 0.012, 0.008, 0.0, radius=0.032)
        ring.apply_translation((0, 0, zb - 0.006))
        parts.append((ring, dark))
    cavity = Cavity(rectangle(x - 2 * wall, y - 2 * wall), 0.008, z - 0.008)
    return Geometry(tuple(parts), tuple(col.open_box_parts(x, y, z, wall, 0.008)), cavity)


@dataclass(frozen=True)
class ToyBlockShape:
    """The block's shape."""

    shape: Literal["cube", "cylinder", "roof"] = "cube"


@builder(ToyBlockShape)
def toy_block(v: Variant, p: ToyBlockShape) -> Geometry:
    x, y, z = v.size
    shape = p.shape
    color = v.color(0, P.RED)
    if shape == "cylinder":
        mesh = shapes.cylinder(x / 2, z, (0, 0, z / 2))
        return Geometry(((mesh, color),), (col.cylinder_part(x / 2, z, (0, 0, z / 2)),))
    if shape == "roof":
        pts = np.array(
            [[sx * x / 2, sy * y / 2, 0.0] for sx in (-1, 1) for sy in (-1, 1)]
            + [[sx * x / 2, 0.0, z] for sx in (-1, 1)]
        )
        mesh = shapes.hull(pts)
        return Geometry(((mesh, color),), (col.hull_part(pts),))
    mesh = shapes.rounded_box((x, y, z), 0.003, (0, 0, z / 2))
    return Geometry(((mesh, color),), (col.box_part((x, y, z), (0, 0, z / 2)),))


CATEGORIES: tuple[CategoryDef, ...] = builtin_categories(__name__, globals())  # variants: data/boxes.json
