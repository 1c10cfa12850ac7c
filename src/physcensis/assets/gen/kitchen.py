"""Kitchen and dining: small appliances, cookware and utensils, condiments, cartons, crates, racks and mats.

Closed objects are drawn in proportion to their size and fitted to it exactly (`fit_to_size`), with convex hulls for
collision; containers (colander, dish rack, crate, measuring cup, egg cup) are built to their size with open walls
and a `Cavity`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
import trimesh
from shapely import affinity
from shapely.geometry import Point, Polygon, box
from shapely.ops import unary_union

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.gen.boxes import open_tray
from physcensis.assets.gen.common import Vessel, fit_to_size, loop_handle, rectangle, resample, spout
from physcensis.assets.gen.variant_data import builtin_categories
from physcensis.assets.model import RGBA, Cavity, CollisionPart
from physcensis.assets.spec import CategoryDef, Geometry, NoOptions, Parts, Variant, builder


def _hulls(parts: Parts, size: tuple[float, float, float]) -> Geometry:
    """One convex hull per visual part, the whole fitted to `size` (for closed objects drawn in proportion)."""
    return fit_to_size(Geometry(parts, tuple(col.hull_part(m) for m, _ in parts)), size)


def _one_hull(parts: Parts, size: tuple[float, float, float]) -> Geometry:
    """A single convex hull around every visual part, fitted to `size` (compact closed objects)."""
    points = np.vstack([m.vertices for m, _ in parts])
    return fit_to_size(Geometry(parts, (col.hull_part(points),)), size)


def _open_box_mesh(x: float, y: float, z: float, wall: float, floor: float, radius: float = 0.0) -> trimesh.Trimesh:
    outer = shapes.slab(x, y, z, radius, (0, 0, z / 2))
    inner = shapes.slab(x - 2 * wall, y - 2 * wall, z, max(0.0, radius - wall), (0, 0, floor + z / 2))
    return trimesh.boolean.difference([outer, inner], engine="manifold")


# --- condiments -------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class SpiceJarShape:
    """The lid's height (fraction of the whole); a square body instead of a round one; a sifter cap with holes."""

    lid: float = 0.22
    square: bool = False
    sifter: bool = True


@builder(SpiceJarShape)
def spice_jar(v: Variant, p: SpiceJarShape) -> Geometry:
    """A small closed spice jar: glass body with the spice showing, a coloured screw lid on top."""
    x, y, z = v.size
    lid_h = p.lid * z
    body_h = z - lid_h
    r = x / 2
    if p.square:
        body = shapes.rounded_box((x, y, body_h), 0.15 * x, (0, 0, body_h / 2))
        fill = shapes.box((0.9 * x, 0.9 * y, 0.6 * body_h), (0, 0, 0.35 * body_h))
    else:
        body = shapes.lathe([(0, 0), (0.96 * r, 0), (r, 0.05 * z), (r, 0.95 * body_h), (0.9 * r, body_h), (0, body_h)])
        fill = shapes.cylinder(0.93 * r, 0.6 * body_h, (0, 0, 0.35 * body_h))
    lid_r = 0.92 * r
    lid = shapes.cylinder(lid_r, lid_h + 0.002, (0, 0, body_h + lid_h / 2 - 0.001), sections=36)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [
        (body, v.color(0, P.GLASS)),
        (fill, v.color(2, P.TERRACOTTA)),
        (lid, v.color(1, P.RED)),
    ]
    if p.sifter:
        for k in range(5):
            a = 2 * np.pi * k / 5
            hole = shapes.cylinder(
                0.08 * r, 0.002, (0.45 * r * np.cos(a), 0.45 * r * np.sin(a), z - 0.0008), sections=8
            )
            parts.append((hole, P.CHARCOAL))
    return _one_hull(tuple(parts), v.size)


@dataclass(frozen=True)
class ShakerShape:
    """The body's waist (fraction of the widest radius) and the cap's height (fraction of the whole)."""

    waist: float = 0.8
    cap: float = 0.2


@builder(ShakerShape)
def salt_shaker(v: Variant, p: ShakerShape) -> Geometry:
    """A salt or pepper shaker: a waisted glass or ceramic body and a domed cap pierced with holes."""
    d, _, z = v.size
    r = d / 2
    cap_h = p.cap * z
    body_h = z - cap_h
    body = shapes.lathe(
        [(0, 0), (0.95 * r, 0), (r, 0.06 * z), (p.waist * r, 0.5 * body_h), (0.92 * r, body_h), (0, body_h)]
    )
    cap = shapes.lathe(
        [(0, body_h - 0.002), (0.93 * r, body_h - 0.002), (0.93 * r, body_h + 0.5 * cap_h), (0.6 * r, z), (0, z)]
    )
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(body, v.color(0, P.GLASS)), (cap, v.color(1, P.SILVER))]
    for k in range(4):
        a = 2 * np.pi * k / 4
        hole = shapes.cylinder(0.07 * r, 0.003, (0.28 * r * np.cos(a), 0.28 * r * np.sin(a), z - 0.0012), sections=8)
        parts.append((hole, P.CHARCOAL))
    return _one_hull(tuple(parts), v.size)


@dataclass(frozen=True)
class PepperMillShape:
    """The crown knob's height (fraction of the whole) and the body's waist (fraction of the widest radius)."""

    knob: float = 0.08
    waist: float = 0.75


@builder(PepperMillShape)
def pepper_mill(v: Variant, p: PepperMillShape) -> Geometry:
    """A pepper or salt mill: a tall turned body, a grinding head and a knob on top."""
    d, _, z = v.size
    r = d / 2
    knob_h = p.knob * z
    top = z - knob_h
    body = shapes.lathe(
        [
            (0, 0),
            (0.96 * r, 0),
            (r, 0.04 * z),
            (r, 0.12 * z),
            (p.waist * r, 0.45 * top),
            (0.9 * r, 0.72 * top),
            (0.9 * r, 0.74 * top),
            (0.8 * r, top),
            (0, top),
        ]
    )
    band = shapes.cylinder(0.91 * r, 0.03 * z, (0, 0, 0.73 * top))
    knob = shapes.lathe(
        [(0, top - 0.002), (0.3 * r, top - 0.002), (0.35 * r, top + 0.5 * knob_h), (0.2 * r, z), (0, z)]
    )
    parts = ((body, v.color(0, P.WOOD)), (band, v.color(1, P.STEEL)), (knob, v.color(1, P.STEEL)))
    return _one_hull(parts, v.size)


# --- small appliances -----------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class KettleShape:
    """An electric jug kettle on its power base, or a stovetop kettle with a long spout and an arched handle."""

    electric: bool = True


@builder(KettleShape)
def kettle(v: Variant, p: KettleShape) -> Geometry:
    """A kettle: spout towards +x, handle at the back (-x) or arched over the lid."""
    x, y, z = v.size
    return _electric_kettle(v, x, y, z) if p.electric else _stovetop_kettle(v, x, y, z)


def _electric_kettle(v: Variant, x: float, y: float, z: float) -> Geometry:
    r = y / 2
    base_h = 0.08 * z
    body_h = 0.86 * z
    body = shapes.lathe(
        [(0, base_h - 0.002), (r, base_h - 0.002), (0.97 * r, base_h + 0.3 * body_h), (0.8 * r, body_h), (0, body_h)]
    )
    base = shapes.cylinder(1.0 * r, base_h, (0, 0, base_h / 2), sections=40)
    lid = shapes.lathe([(0, body_h - 0.002), (0.8 * r, body_h - 0.002), (0.55 * r, z - 0.01), (0.2 * r, z), (0, z)])
    reach = x - y - 0.08 * y
    handle, hparts = loop_handle(0.9 * r, 0.93 * body_h, 0.3 * body_h, reach, 0.012, yaw=np.pi, squareness=0.3)
    s_mesh, s_parts = spout(
        np.array([0.6 * r, 0, 0.82 * body_h]), np.array([r + 0.08 * y, 0, 0.97 * body_h]), 0.0, 0.12 * r, 0.06 * r
    )
    body_color = v.color(0, P.STEEL)
    parts = (
        (body, body_color),
        (base, v.color(1, P.BLACK)),
        (lid, v.color(1, P.BLACK)),
        (handle, v.color(1, P.BLACK)),
        (s_mesh, body_color),
    )
    collision = (col.hull_part(np.vstack([body.vertices, base.vertices, lid.vertices])), *hparts, *s_parts)
    return fit_to_size(Geometry(parts, collision), v.size)


def _stovetop_kettle(v: Variant, x: float, y: float, z: float) -> Geometry:
    r = y / 2
    body_h = 0.62 * z
    body = shapes.lathe(
        [(0, 0), (0.9 * r, 0), (r, 0.12 * body_h), (0.95 * r, 0.6 * body_h), (0.55 * r, body_h), (0, body_h)]
    )
    lid = shapes.lathe(
        [(0, body_h - 0.002), (0.56 * r, body_h - 0.002), (0.2 * r, body_h + 0.06 * z), (0, body_h + 0.08 * z)]
    )
    t = np.linspace(0.0, np.pi, 17)
    arch = np.stack([0.5 * r * np.cos(t), np.zeros_like(t), body_h - 0.01 + (z - body_h - 0.02) * np.sin(t)], axis=1)
    grip = shapes.tube(arch, 0.012, sides=12)
    reach = x - y
    s_mesh, s_parts = spout(
        np.array([0.5 * r, 0, 0.3 * body_h]), np.array([r + reach, 0, 0.95 * body_h]), 0.05 * z, 0.14 * r, 0.05 * r
    )
    color = v.color(0, P.RED)
    parts = ((body, color), (lid, color), (grip, v.color(1, P.BLACK)), (s_mesh, color))
    collision = (col.hull_part(np.vstack([body.vertices, lid.vertices])), *col.tube_parts(arch, 0.012, 3), *s_parts)
    return fit_to_size(Geometry(parts, collision), v.size)


@dataclass(frozen=True)
class ToasterShape:
    """The number of bread slots, and the corner rounding (m)."""

    slots: int = 2
    radius: float = 0.03


@builder(ToasterShape)
def toaster(v: Variant, p: ToasterShape) -> Geometry:
    """A pop-up toaster: a rounded body with slots along y on top, a lever and a dial on the +x front."""
    x, y, z = v.size
    lever_reach = 0.06 * x
    bx = x - lever_reach
    body = shapes.rounded_box((bx, y, z), min(p.radius, 0.2 * bx), (-lever_reach / 2, 0, z / 2))
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(body, v.color(0, P.SILVER))]
    slot_w = 0.14 * bx
    spacing = bx / (p.slots + 1)
    for k in range(p.slots):
        cx = -lever_reach / 2 - bx / 2 + spacing * (k + 1)
        parts.append((shapes.box((slot_w, 0.8 * y, 0.012), (cx, 0, z - 0.005)), P.CHARCOAL))
    lever = shapes.box(
        (lever_reach + 0.01, 0.05 * y + 0.01, 0.025), (x / 2 - (lever_reach + 0.01) / 2, 0.3 * y, 0.6 * z)
    )
    dial = shapes.cylinder(0.06 * z, lever_reach + 0.01, (x / 2 - (lever_reach + 0.01) / 2, -0.3 * y, 0.35 * z), "x")
    parts += [(lever, v.color(1, P.BLACK)), (dial, v.color(1, P.BLACK))]
    feet = shapes.box((0.9 * bx, 0.9 * y, 0.006), (-lever_reach / 2, 0, 0.003))
    parts.append((feet, P.BLACK))
    collision = (col.hull_part(body), col.hull_part(lever), col.hull_part(dial))
    return fit_to_size(Geometry(tuple(parts), collision), v.size)


# --- cookware and utensils ------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ColanderShape:
    """The foot ring's height (m), the wall (m), and side grips (or none)."""

    foot: float = 0.012
    wall: float = 0.003
    grips: bool = True


@builder(ColanderShape)
def colander(v: Variant, p: ColanderShape) -> Geometry:
    """A colander: a perforated bowl on a ring foot, with grips on +-y; an open container."""
    x, y, z = v.size
    grip = 0.035 if p.grips else 0.0
    r = x / 2
    if not p.grips:
        r = min(x, y) / 2
    fh = p.foot
    outer = resample([(0.55 * r, fh), (0.8 * r, fh + 0.45 * (z - fh)), (r, z)], 8)
    vessel = Vessel(outer, p.wall, 0.004, stations=3, base=[(0.0, 0.0), (0.6 * r, 0.0), (0.6 * r, fh + 0.001)])
    color = v.color(0, P.STEEL)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(vessel.mesh(), color)]
    dark = v.color(1, P.CHARCOAL)
    for ring_z, ring_r in ((0.45, 0.8), (0.7, 0.9)):
        zc = fh + ring_z * (z - fh)
        for k in range(18):
            a = 2 * np.pi * (k + 0.5 * (ring_z > 0.5)) / 18
            rr = ring_r * r + 0.0005
            hole = shapes.cylinder(0.0035, 0.002, (rr * np.cos(a), rr * np.sin(a), zc), sections=8)
            hole.apply_transform(_facing(a, (rr * np.cos(a), rr * np.sin(a), zc)))
            parts.append((hole, dark))
    collision: list[CollisionPart] = [
        *vessel.collision(16),
        col.hull_part(shapes.cylinder(0.6 * r, fh, (0, 0, fh / 2))),
    ]
    if p.grips:
        for s in (1, -1):
            handle = shapes.box((0.06 * x, grip + 0.01, 0.006), (0, s * (r + grip / 2 - 0.005), z - 0.004))
            parts.append((handle, color))
            collision.append(col.hull_part(handle))
    return Geometry(tuple(parts), tuple(collision), vessel.cavity())


def _facing(angle: float, at: tuple[float, float, float]) -> np.ndarray:
    """The transform that turns a z-axis disc centred at `at` to face outwards at `angle` about z."""
    to_origin = trimesh.transformations.translation_matrix([-c for c in at])
    turn = trimesh.transformations.rotation_matrix(angle, (0, 0, 1)) @ trimesh.transformations.rotation_matrix(
        np.pi / 2, (0, 1, 0)
    )
    back = trimesh.transformations.translation_matrix(at)
    return back @ turn @ to_origin


@dataclass(frozen=True)
class RollingPinShape:
    """Handles at both ends (their length, fraction of the whole; 0: a plain French pin) and tapered ends."""

    handles: float = 0.18
    tapered: bool = False


@builder(RollingPinShape)
def rolling_pin(v: Variant, p: RollingPinShape) -> Geometry:
    """A rolling pin lying along y: a faceted barrel (so it rests) with handles or tapered ends."""
    _, length, d = v.size
    r = d / 2
    barrel_len = length * (1 - 2 * p.handles)
    sections = 20
    if p.tapered:
        barrel = shapes.lathe(
            [
                (0, -barrel_len / 2),
                (0.55 * r, -barrel_len / 2),
                (r, 0),
                (0.55 * r, barrel_len / 2),
                (0, barrel_len / 2),
            ],
            sections,
        )
        barrel.apply_transform(trimesh.transformations.rotation_matrix(-np.pi / 2, (1, 0, 0)))
        barrel.apply_translation((0, 0, r))
    else:
        barrel = shapes.cylinder(r, barrel_len, (0, 0, r), "y", sections)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(barrel, v.color(0, P.LIGHT_WOOD))]
    collision = [col.hull_part(barrel)]
    if p.handles > 0:
        hl = length * p.handles + 0.004
        for s in (1, -1):
            handle = shapes.cylinder(0.45 * r, hl, (0, s * (length / 2 - hl / 2), r), "y", 16)
            parts.append((handle, v.color(1, P.WOOD)))
            collision.append(col.hull_part(handle))
    return fit_to_size(Geometry(tuple(parts), tuple(collision)), v.size)


# --- containers ------------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class DishRackShape:
    """Wire thickness (m), the number of upright plate tines along the back, a drip tray under it."""

    wire: float = 0.005
    tines: int = 8
    tray: bool = True


@builder(DishRackShape)
def dish_rack(v: Variant, p: DishRackShape) -> Geometry:
    """A dish drying rack: a wire basket (open walls) standing on a drip tray, plate tines along the back wall."""
    x, y, z = v.size
    w = p.wire
    floor = 0.012 if p.tray else w
    color = v.color(0, P.SILVER)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = []
    if p.tray:
        parts.append((_open_box_mesh(x, y, floor + 0.006, 0.004, 0.004, 0.01), v.color(1, P.WHITE)))
    for zb in np.linspace(floor + 0.01, z - w / 2, 4):
        parts.append((_open_box_mesh(x - 0.002, y - 0.002, w, w, 0.0).apply_translation((0, 0, zb - w / 2)), color))
    grid = shapes.box((x - 0.003, y - 0.003, w), (0, 0, floor - w / 2 + 0.003))
    parts.append((grid, color))
    for sx in (1, -1):
        for sy in (1, -1):
            post = shapes.box(
                (w, w, z - floor), (sx * (x / 2 - w / 2 - 0.001), sy * (y / 2 - w / 2 - 0.001), (z + floor) / 2)
            )
            parts.append((post, color))
    for sx, length, across in ((1, y, "y"), (-1, y, "y"), (1, x, "x"), (-1, x, "x")):
        for u in np.linspace(-length / 2 + 0.03, length / 2 - 0.03, max(2, int(length / 0.04))):
            at = (sx * (x / 2 - w / 2 - 0.001), u) if across == "y" else (u, sx * (y / 2 - w / 2 - 0.001))
            parts.append((shapes.box((0.003, 0.003, z - floor - 0.004), (*at, (z + floor) / 2 - 0.002)), color))
    for k in range(p.tines):
        ty = -y / 2 + (k + 1) * y / (p.tines + 1)
        tine = shapes.box((0.005, 0.005, 0.5 * z), (-x / 2 + w + 0.006, ty, floor + 0.25 * z))
        parts.append((tine, color))
    wall = w + 0.002
    cavity = Cavity(rectangle(x - 2 * wall - 0.01, y - 2 * wall), floor, z - floor)
    return Geometry(tuple(parts), tuple(col.open_box_parts(x, y, z, wall, floor)), cavity)


@dataclass(frozen=True)
class CrateShape:
    """Slat count per side, gap between slats (fraction of the height), plastic (solid walls with hand holes)."""

    slats: int = 3
    gap: float = 0.12
    plastic: bool = False


@builder(CrateShape)
def crate(v: Variant, p: CrateShape) -> Geometry:
    """An open crate: slatted wooden sides on corner posts, or a moulded plastic crate with hand holes."""
    x, y, z = v.size
    wall = 0.012 if not p.plastic else 0.006
    floor = 0.012 if not p.plastic else 0.008
    color = v.color(0, P.LIGHT_WOOD)
    if p.plastic:
        body = _open_box_mesh(x, y, z, wall, floor, 0.015)
        parts: list[tuple[trimesh.Trimesh, RGBA]] = [(body, color)]
        for s in (1, -1):
            hole = shapes.slab(0.3 * x, 0.004, 0.05 * z + 0.02, 0.008, (0, s * (y / 2 - 0.0015), 0.82 * z))
            parts.append((hole, v.color(1, P.CHARCOAL)))
    else:
        parts = [(shapes.box((x - 0.004, y - 0.004, floor), (0, 0, floor / 2)), color)]
        slat_h = (z - floor) * (1 - p.gap * (p.slats - 1)) / p.slats
        step = (z - floor - slat_h) / max(1, p.slats - 1)
        for k in range(p.slats):
            zc = floor + slat_h / 2 + k * step
            parts.append((shapes.box((x, wall, slat_h), (0, y / 2 - wall / 2, zc)), color))
            parts.append((shapes.box((x, wall, slat_h), (0, -y / 2 + wall / 2, zc)), color))
            parts.append((shapes.box((wall, y - 2 * wall + 0.002, slat_h), (x / 2 - wall / 2, 0, zc)), color))
            parts.append((shapes.box((wall, y - 2 * wall + 0.002, slat_h), (-x / 2 + wall / 2, 0, zc)), color))
        post = v.color(1, P.WOOD)
        for sx in (1, -1):
            for sy in (1, -1):
                c = (sx * (x / 2 - wall - 0.011), sy * (y / 2 - wall - 0.011), z / 2 + 0.0005)
                parts.append((shapes.box((0.022, 0.022, z - 0.001), c), post))
        wall += 0.022
    cavity = Cavity(rectangle(x - 2 * wall, y - 2 * wall), floor, z - floor)
    return Geometry(tuple(parts), tuple(col.open_box_parts(x, y, z, wall, floor)), cavity)


@dataclass(frozen=True)
class MeasuringCupShape:
    """A glass jug with a loop handle and spout, or a metal cup with a long flat handle; the wall (m)."""

    jug: bool = True
    wall: float = 0.003


@builder(MeasuringCupShape)
def measuring_cup(v: Variant, p: MeasuringCupShape) -> Geometry:
    """A measuring cup (open): straight walls with printed graduations, a handle on -y."""
    x, y, z = v.size
    d = x
    r = d / 2
    reach = y - d
    outer = resample([(0.92 * r, 0.0), (r, z)], 6)
    vessel = Vessel(outer, p.wall, 0.005, stations=1)
    color = v.color(0, P.GLASS if p.jug else P.STEEL)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(vessel.mesh(), color)]
    for k in range(1, 5):
        zk = z * k / 5
        rk = 0.92 * r + 0.08 * r * zk / z + 0.0004
        mark = shapes.box((0.002, 0.2 * d, 0.002), (rk - 0.0008, 0, zk))
        mark.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 4, (0, 0, 1)))
        parts.append((mark, v.color(1, P.RED)))
    collision: list[CollisionPart] = list(vessel.collision(16))
    if p.jug:
        handle, hparts = loop_handle(r - 0.002, 0.85 * z, 0.25 * z, reach, 0.007, squareness=0.5)
        parts.append((handle, color))
        collision += hparts
    else:
        stick = shapes.box((0.02, reach + 0.004, 0.004), (0, -(r + reach / 2 - 0.002), z - 0.002))
        parts.append((stick, color))
        collision.append(col.hull_part(stick))
    return Geometry(tuple(parts), tuple(collision), vessel.cavity())


@dataclass(frozen=True)
class EggCupShape:
    """The stem's height (fraction of the whole) and the foot's radius (fraction of the cup's)."""

    stem: float = 0.3
    foot: float = 0.9


@builder(EggCupShape)
def egg_cup(v: Variant, p: EggCupShape) -> Geometry:
    """An egg cup: a small round cup on a short stem and a wide flat foot; holds one egg upright."""
    d, _, z = v.size
    r = d / 2
    stem_h = p.stem * z
    rf = p.foot * r
    t = np.linspace(-0.5 * np.pi, 0.0, 8)
    outer = np.stack([0.4 * r + 0.6 * r * np.cos(t) * 1.0, stem_h + (z - stem_h) * (1 + np.sin(t))], axis=1)
    outer[0, 0] = 0.4 * r
    base = [(0.0, 0.0), (rf, 0.0), (rf, 0.06 * z), (0.35 * r, 0.5 * stem_h), (0.3 * r, stem_h)]
    vessel = Vessel(outer, 0.003, 0.006, stations=3, base=base)
    foot = shapes.hull(shapes.cylinder(rf, 0.06 * z, (0, 0, 0.03 * z)).vertices)
    stem = shapes.cylinder(0.33 * r, stem_h, (0, 0, stem_h / 2))
    collision = [*vessel.collision(12), col.hull_part(foot), col.hull_part(stem)]
    return Geometry(((vessel.mesh(), v.color(0, P.WHITE)),), tuple(collision), vessel.cavity())


# --- cartons ---------------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class MilkCartonShape:
    """A gable top with a screw cap (or a flat-topped brick carton) and the label band's height (fraction)."""

    gable: bool = True
    label: float = 0.45


@builder(MilkCartonShape)
def milk_carton(v: Variant, p: MilkCartonShape) -> Geometry:
    """A milk or juice carton: a square paperboard column with a gable roof and cap, or a flat brick."""
    x, y, z = v.size
    roof = 0.18 * z if p.gable else 0.0
    body_h = z - roof
    main = v.color(0, P.WHITE)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(shapes.box((x, y, body_h), (0, 0, body_h / 2)), main)]
    label = shapes.box((x + 0.002, 0.8 * y, p.label * body_h), (0, 0, 0.45 * body_h))
    parts.append((label, v.color(1, P.BLUE)))
    if p.gable:
        ridge_t = 0.004
        pts = [(sx * x / 2, sy * y / 2, body_h - 0.001) for sx in (1, -1) for sy in (1, -1)]
        pts += [(sx * ridge_t / 2, sy * y / 2, z - 0.012) for sx in (1, -1) for sy in (1, -1)]
        parts.append((shapes.hull(pts), main))
        fin = shapes.box((ridge_t, y, 0.013), (0, 0, z - 0.0065))
        parts.append((fin, main))
        cap = shapes.cylinder(0.12 * x, 0.014, (0.22 * x, 0, body_h + 0.5 * roof), sections=20)
        cap.apply_transform(_tilt_about_y(0.6, (0.22 * x, 0, body_h + 0.5 * roof)))
        parts.append((cap, v.color(2, P.BLUE)))
    return _one_hull(tuple(parts), v.size)


def _tilt_about_y(angle: float, at: tuple[float, float, float]) -> np.ndarray:
    return trimesh.transformations.rotation_matrix(angle, (0, 1, 0), at)


@dataclass(frozen=True)
class EggCartonShape:
    """Eggs per row (two rows), and the lid open (eggs showing, lid removed) instead of closed; `empty`: an open
    tray with nothing in it, a container the eggs are dropped into."""

    per_row: int = 6
    open: bool = False
    empty: bool = False


@builder(EggCartonShape)
def egg_carton(v: Variant, p: EggCartonShape) -> Geometry:
    """An egg carton of two rows along y: a moulded pulp tray with a closed ridged lid, or open with eggs showing."""
    x, y, z = v.size
    color = v.color(0, P.rgb(200, 190, 170))
    if p.empty:
        return _empty_egg_tray(v, p.per_row, color)
    tray_h = 0.55 * z if p.open else 0.5 * z
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(shapes.rounded_box((x, y, tray_h), 0.006, (0, 0, tray_h / 2)), color)]
    pitch = y / p.per_row
    centres = [(sx * x / 4, -y / 2 + pitch * (k + 0.5)) for sx in (1, -1) for k in range(p.per_row)]
    if p.open:
        er = min(0.42 * pitch, 0.21 * x)
        for cx, cy in centres:
            egg = shapes.ellipsoid((er, er, 1.3 * er), (cx, cy, z - 1.3 * er), 2)
            egg.vertices[:, 2] = np.maximum(egg.vertices[:, 2], 0.3 * tray_h)
            parts.append((egg, v.color(1, P.rgb(235, 215, 185))))
        return _hulls(tuple(parts), v.size)
    lid = shapes.rounded_box((x, y, z - tray_h + 0.004), 0.008, (0, 0, tray_h + (z - tray_h) / 2 - 0.002))
    parts.append((lid, color))
    parts.append((shapes.box((0.6 * x, 0.5 * y, 0.003), (0, 0, z - 0.001)), v.color(1, P.rgb(235, 215, 185))))
    return _one_hull(tuple(parts), v.size)


def _empty_egg_tray(v: Variant, per_row: int, color: RGBA) -> Geometry:
    """An open pulp tray, lid off, with low cone posts between the cups drawn on its floor; the eggs settle on the
    floor (the cavity is the whole tray)."""
    x, y, z = v.size
    tray = open_tray(v.size, 0.003, 0.003, color, radius=0.006)
    pitch = y / per_row
    post_h = 0.45 * z
    posts = [
        shapes.cone(0.009, 0.004, post_h, (0.0, -y / 2 + pitch * k, 0.003 + post_h / 2)) for k in range(1, per_row)
    ]
    return Geometry((*tray.parts, (shapes.concatenate(posts), color)), tray.collision, tray.cavity)


# --- table linen and flat things -----------------------------------------------------------------------------------


@dataclass(frozen=True)
class PlaceMatShape:
    """Round (or oval) instead of rectangular; woven stripes across it; the corner radius (m)."""

    round: bool = False
    woven: bool = False
    radius: float = 0.01


@builder(PlaceMatShape)
def place_mat(v: Variant, p: PlaceMatShape) -> Geometry:
    """A flat table mat under a place setting: a thin slab or disc, optionally with woven stripes."""
    x, y, z = v.size
    color = v.color(0, P.BAMBOO)
    if p.round:
        mat = shapes.cylinder(0.5, z, (0, 0, z / 2), sections=64)
        mat.apply_scale((x, y, 1.0))
    else:
        mat = shapes.slab(x, y, z, p.radius, (0, 0, z / 2))
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(mat, color)]
    if p.woven:
        stripe = v.color(1, P.WOOD)
        for k in range(1, 6):
            band = shapes.box((0.012, 0.9 * y if not p.round else 0.55 * y, 1.02 * z), (x * (k / 6 - 0.5), 0, z / 2))
            parts.append((band, stripe))
    part = col.hull_part(mat) if p.round else col.box_part((x, y, z), (0, 0, z / 2))
    return Geometry(tuple(parts), (part,))


@dataclass(frozen=True)
class CoasterShape:
    """Round instead of square; an inset top of a second colour (cork in wood, felt in slate)."""

    round: bool = True
    inset: bool = False


@builder(CoasterShape)
def coaster(v: Variant, p: CoasterShape) -> Geometry:
    """A drink coaster: a thin disc or square tile, optionally with an inset top."""
    x, y, z = v.size
    color = v.color(0, P.rgb(195, 160, 115))
    if p.round:
        body = shapes.cylinder(x / 2, z, (0, 0, z / 2), sections=48)
        part = col.cylinder_part(x / 2, z, (0, 0, z / 2))
    else:
        body = shapes.slab(x, y, z, 0.006, (0, 0, z / 2))
        part = col.box_part((x, y, z), (0, 0, z / 2))
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(body, color)]
    if p.inset:
        top = (
            shapes.cylinder(0.4 * x, 0.3 * z, (0, 0, z - 0.13 * z), sections=48)
            if p.round
            else shapes.slab(0.8 * x, 0.8 * y, 0.3 * z, 0.004, (0, 0, z - 0.13 * z))
        )
        parts.append((top, v.color(1, P.rgb(150, 110, 70))))
    return Geometry(tuple(parts), (part,))


@dataclass(frozen=True)
class OvenMittShape:
    """A mitten with a thumb, or a square pot holder pad with a hanging loop."""

    style: Literal["mitt", "pad"] = "mitt"


@builder(OvenMittShape)
def oven_mitt(v: Variant, p: OvenMittShape) -> Geometry:
    """A quilted oven mitt (or pot holder) lying flat, fingers towards -x, with a contrasting cuff."""
    x, y, z = v.size
    color = v.color(0, P.RED)
    trim = v.color(1, P.WHITE)
    if p.style == "pad":
        pad = shapes.rounded_box((x, y, z), 0.4 * z, (0, 0, z / 2))
        edge = _ring_band(x, y, z)
        return Geometry(((pad, color), (edge, trim)), (col.box_part((x, y, z), (0, 0, z / 2)),))
    hand = Point(0, 0).buffer(1.0, quad_segs=16)
    hand = affinity.scale(hand, 0.3 * x, 0.36 * y)
    hand = affinity.translate(hand, -0.15 * x, -0.1 * y)
    thumb = affinity.rotate(affinity.scale(Point(0, 0).buffer(1.0, quad_segs=12), 0.2 * x, 0.1 * y), 35)
    thumb = affinity.translate(thumb, -0.02 * x, 0.36 * y)
    palm = box(-0.15 * x, -0.46 * y, 0.3 * x, 0.26 * y)
    outline = unary_union([hand, thumb, palm]).buffer(0.005, quad_segs=4)
    body = shapes.extrude(outline, 0.92 * z)
    cuff = shapes.rounded_box((0.24 * x, 0.74 * y, z), 0.4 * z, (0.37 * x, -0.1 * y, z / 2))
    parts = ((body, color), (cuff, trim))
    return _one_hull(parts, v.size)


def _ring_band(x: float, y: float, z: float) -> trimesh.Trimesh:
    """A binding strip around a flat pad's edge."""
    outer = shapes.slab(x + 0.002, y + 0.002, 0.6 * z, 0.4 * z, (0, 0, z / 2))
    inner = shapes.slab(x - 0.01, y - 0.01, z, 0.3 * z, (0, 0, z / 2))
    return trimesh.boolean.difference([outer, inner], engine="manifold")


@dataclass(frozen=True)
class SpongeShape:
    """The scouring layer's thickness (fraction of the whole; 0: a plain sponge) and the corner rounding (m)."""

    scourer: float = 0.25
    radius: float = 0.004


@builder(SpongeShape)
def sponge(v: Variant, p: SpongeShape) -> Geometry:
    """A kitchen sponge: a soft rounded block, usually with a green scouring pad on top."""
    x, y, z = v.size
    pad_h = p.scourer * z
    soft_h = z - pad_h
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [
        (shapes.rounded_box((x, y, soft_h + 0.001), p.radius, (0, 0, (soft_h + 0.001) / 2)), v.color(0, P.YELLOW))
    ]
    if pad_h > 0:
        parts.append(
            (shapes.rounded_box((x, y, pad_h), min(p.radius, 0.4 * pad_h), (0, 0, z - pad_h / 2)), v.color(1, P.GREEN))
        )
    return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


# --- lidded dishes and boxes ----------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ButterDishShape:
    """The cover's height (fraction of the whole above the plate) and a knob on the cover."""

    knob: bool = True


@builder(ButterDishShape)
def butter_dish(v: Variant, p: ButterDishShape) -> Geometry:
    """A covered butter dish: a flat oblong plate with a rounded cover on it."""
    x, y, z = v.size
    plate_h = 0.14 * z
    knob_h = 0.15 * z if p.knob else 0.0
    cover_h = z - plate_h - knob_h
    plate = shapes.slab(x, y, plate_h, 0.015, (0, 0, plate_h / 2))
    cover = shapes.rounded_box(
        (0.82 * x, 0.74 * y, cover_h + 0.01), 0.018, (0, 0, plate_h + cover_h / 2 - 0.005 + 0.001)
    )
    cover.vertices[:, 2] = np.maximum(cover.vertices[:, 2], plate_h - 0.002)
    color = v.color(0, P.WHITE)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(plate, color), (cover, v.color(1, color))]
    if p.knob:
        parts.append((shapes.sphere(knob_h * 0.6, (0, 0, z - knob_h * 0.6), 2), v.color(2, v.color(1, color))))
    return _one_hull(tuple(parts), v.size)


@dataclass(frozen=True)
class SugarBowlShape:
    """Two ear handles on +-y (or none) and the lid's knob height (fraction of the whole)."""

    handles: bool = True
    knob: float = 0.12


@builder(SugarBowlShape)
def sugar_bowl(v: Variant, p: SugarBowlShape) -> Geometry:
    """A lidded sugar bowl: a round body on a foot, a lid with a knob, two small handles."""
    x, y, z = v.size
    r = x / 2
    knob_h = p.knob * z
    body_h = 0.72 * z
    t = np.linspace(-0.5 * np.pi, 0.35 * np.pi, 12)
    prof = [(0.0, 0.0), (0.55 * r, 0.0), (0.55 * r, 0.06 * z)]
    prof += [
        (r * (0.62 + 0.38 * np.cos(a)), 0.06 * z + (body_h - 0.06 * z) * (1 + np.sin(a)) / (1 + np.sin(t[-1])))
        for a in t[1:]
    ]
    prof += [(0.0, body_h)]
    body = shapes.lathe(prof)
    lid_top = z - knob_h
    lid = shapes.lathe(
        [
            (0, body_h - 0.003),
            (0.86 * r, body_h - 0.003),
            (0.8 * r, body_h + 0.3 * (lid_top - body_h)),
            (0.3 * r, lid_top),
            (0, lid_top),
        ]
    )
    knob = shapes.sphere(0.55 * knob_h, (0, 0, z - 0.55 * knob_h), 2)
    color = v.color(0, P.WHITE)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(body, color), (lid, v.color(1, color)), (knob, v.color(1, color))]
    collision: list[CollisionPart] = [col.hull_part(np.vstack([body.vertices, lid.vertices, knob.vertices]))]
    if p.handles:
        reach = (y - x) / 2
        for yaw in (-np.pi / 2, np.pi / 2):
            mesh, hparts = loop_handle(0.95 * r, 0.75 * body_h, 0.35 * body_h, reach, 0.006, yaw=yaw, pieces=2)
            parts.append((mesh, color))
            collision += hparts
    return fit_to_size(Geometry(tuple(parts), tuple(collision)), v.size)


@dataclass(frozen=True)
class FoodContainerShape:
    """Round instead of rectangular; a glass body with four clip tabs on the lid; the taper of the walls."""

    round: bool = False
    clips: bool = False
    taper: float = 0.92
    open: bool = False  # the lid off: an empty rectangular tub things are put into


@builder(FoodContainerShape)
def food_container(v: Variant, p: FoodContainerShape) -> Geometry:
    """A closed food storage container: a tapered tub with a snap-on lid (or open, the lid off)."""
    x, y, z = v.size
    if p.open:
        return open_tray(v.size, 0.0025, 0.003, v.color(0, P.rgb(235, 240, 245, 0.6)), radius=0.15 * min(x, y))
    lid_h = 0.16 * z
    tub_h = z - lid_h + 0.002
    tabs = 0.012 if p.clips else 0.0
    bx, by = x - 2 * tabs, y - 2 * tabs
    if p.round:
        tub = shapes.cone(p.taper * bx / 2, bx / 2, tub_h, (0, 0, tub_h / 2), sections=48)
        tub.apply_scale((1.0, by / bx, 1.0))
        lid = shapes.cylinder(bx / 2 + 0.002, lid_h, (0, 0, z - lid_h / 2), sections=48)
        lid.apply_scale((1.0, by / bx, 1.0))
    else:
        radius = 0.15 * min(bx, by)
        low = shapes.slab(p.taper * bx, p.taper * by, 0.001, p.taper * radius, (0, 0, 0.0005))
        high = shapes.slab(bx, by, 0.001, radius, (0, 0, tub_h - 0.0005))
        tub = shapes.hull(np.vstack([low.vertices, high.vertices]))
        lid = shapes.slab(bx + 0.003, by + 0.003, lid_h, radius + 0.0015, (0, 0, z - lid_h / 2))
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [
        (tub, v.color(0, P.rgb(235, 240, 245, 0.6))),
        (lid, v.color(1, P.BLUE)),
    ]
    if p.clips:
        for sx, sy, ex, ey in (
            (1, 0, tabs + 0.002, 0.3 * by),
            (-1, 0, tabs + 0.002, 0.3 * by),
            (0, 1, 0.3 * bx, tabs + 0.002),
            (0, -1, 0.3 * bx, tabs + 0.002),
        ):
            centre = (sx * (x / 2 - ex / 2), sy * (y / 2 - ey / 2), z - 0.6 * lid_h)
            parts.append((shapes.box((ex, ey, 1.2 * lid_h), centre), v.color(1, P.BLUE)))
    return _one_hull(tuple(parts), v.size)


@dataclass(frozen=True)
class BreadBoxShape:
    """The rounded roll-top's radius (fraction of the height) and a window in the front."""

    roll: float = 0.55
    window: bool = False


@builder(BreadBoxShape)
def bread_box(v: Variant, p: BreadBoxShape) -> Geometry:
    """A closed bread bin: a box with a rounded roll-top front (+x) and a handle on the front."""
    x, y, z = v.size
    rr = min(p.roll * z, 0.9 * x)
    t = np.linspace(0.0, 0.5 * np.pi, 10)
    arc = [(x / 2 - rr + rr * np.cos(a), z - rr + rr * np.sin(a)) for a in t]
    outline = Polygon([(-x / 2, 0.0), (x / 2, 0.0), *arc, (-x / 2, z)])
    body = _extrude_xz(outline, y)
    color = v.color(0, P.WOOD)
    handle = shapes.box((0.014, 0.3 * y, 0.016), (x / 2 + 0.005, 0, 0.4 * z))
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(body, color), (handle, v.color(1, P.DARK_BROWN))]
    if p.window:
        window = shapes.box((0.012, 0.6 * y, 0.25 * z), (x / 2 - 0.004, 0, 0.6 * z - 0.12 * rr))
        window.apply_transform(trimesh.transformations.rotation_matrix(-0.35, (0, 1, 0), (x / 2 - 0.004, 0, 0.6 * z)))
        parts.append((window, P.GLASS))
    return _one_hull(tuple(parts), v.size)


def _extrude_xz(outline: Polygon, depth: float) -> trimesh.Trimesh:
    """A polygon drawn in the xz plane, extruded `depth` along y and centred on y = 0."""
    mesh = shapes.extrude(outline, depth)
    mesh.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, (1, 0, 0)))
    mesh.apply_translation((0, depth / 2, 0))
    return mesh


@dataclass(frozen=True)
class CakeStandShape:
    """The pedestal's height (fraction of the whole) and the foot's radius (fraction of the plate's)."""

    stem: float = 0.75
    foot: float = 0.5


@builder(CakeStandShape)
def cake_stand(v: Variant, p: CakeStandShape) -> Geometry:
    """A cake stand: a flat round plate with a low lip on a pedestal and a wide foot."""
    d, _, z = v.size
    r = d / 2
    plate_h = (1 - p.stem) * z
    rf = p.foot * r
    foot_h = 0.12 * z
    foot = shapes.cone(rf, 0.3 * rf, foot_h, (0, 0, foot_h / 2), sections=40)
    stem = shapes.cylinder(0.12 * r, p.stem * z - foot_h + 0.004, (0, 0, (foot_h + p.stem * z) / 2), sections=24)
    plate = shapes.lathe(
        [
            (0, p.stem * z),
            (0.9 * r, p.stem * z),
            (r, z),
            (0.97 * r, z),
            (0.9 * r, z - 0.4 * plate_h),
            (0, z - 0.4 * plate_h),
        ]
    )
    color = v.color(0, P.WHITE)
    parts = ((foot, color), (stem, color), (plate, v.color(1, color)))
    return _hulls(parts, v.size)


# --- coffee -------------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class FrenchPressShape:
    """The coffee level inside (fraction of the glass; 0: empty) and the frame's colour is the second colour."""

    coffee: float = 0.55


@builder(FrenchPressShape)
def french_press(v: Variant, p: FrenchPressShape) -> Geometry:
    """A French press: a glass beaker in a metal frame with a lid, plunger knob and a handle on -y."""
    x, y, z = v.size
    r = x / 2
    rod_h = 0.1 * z
    lid_top = z - rod_h
    glass_h = 0.85 * lid_top
    frame = v.color(1, P.STEEL)
    glass = shapes.cylinder(0.95 * r, glass_h, (0, 0, glass_h / 2 + 0.006), sections=40)
    base = shapes.cylinder(r, 0.012, (0, 0, 0.006), sections=40)
    lid = shapes.lathe([(0, glass_h), (r, glass_h), (r, glass_h + 0.04 * z), (0.5 * r, lid_top), (0, lid_top)])
    rod = shapes.cylinder(0.05 * r, rod_h, (0, 0, lid_top + rod_h / 2 - 0.002), sections=12)
    knob = shapes.sphere(0.16 * r, (0, 0, z - 0.16 * r), 2)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [
        (glass, v.color(0, P.GLASS)),
        (base, frame),
        (lid, frame),
        (rod, frame),
        (knob, v.color(2, P.BLACK)),
    ]
    if p.coffee > 0:
        parts.append(
            (
                shapes.cylinder(0.9 * r, p.coffee * glass_h, (0, 0, 0.012 + p.coffee * glass_h / 2), sections=32),
                P.DARK_BROWN,
            )
        )
    handle, hparts = loop_handle(0.95 * r, 0.8 * glass_h, 0.2 * glass_h, y - x, 0.01, squareness=0.3)
    parts.append((handle, v.color(2, P.BLACK)))
    body = col.hull_part(np.vstack([glass.vertices, base.vertices, lid.vertices, rod.vertices, knob.vertices]))
    return fit_to_size(Geometry(tuple(parts), (body, *hparts)), v.size)


@dataclass(frozen=True)
class CoffeeMakerShape:
    """A drip machine with a glass carafe, a single-serve pod machine with a mug, or an espresso machine."""

    style: Literal["drip", "pod", "espresso"] = "drip"


@builder(CoffeeMakerShape)
def coffee_maker(v: Variant, p: CoffeeMakerShape) -> Geometry:
    """A coffee machine, front +x: a back tower with the water tank, a head above and a base plate below the vessel."""
    x, y, z = v.size
    body = v.color(0, P.BLACK)
    trim = v.color(1, P.SILVER)
    tower_x = {"drip": 0.4, "pod": 0.55, "espresso": 0.65}[p.style] * x
    head_h = {"drip": 0.22, "pod": 0.25, "espresso": 0.2}[p.style] * z
    base_h = 0.07 * z
    tower = shapes.rounded_box((tower_x, y, z), 0.01, (-x / 2 + tower_x / 2, 0, z / 2))
    head = shapes.rounded_box(
        (x - tower_x + 0.01, y, head_h), 0.01, (x / 2 - (x - tower_x + 0.01) / 2, 0, z - head_h / 2)
    )
    base = shapes.rounded_box(
        (x - tower_x + 0.01, 0.9 * y, base_h), 0.006, (x / 2 - (x - tower_x + 0.01) / 2, 0, base_h / 2)
    )
    gap = z - head_h - base_h
    cx = -x / 2 + tower_x + (x - tower_x) / 2
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(tower, body), (head, body), (base, trim)]
    room = min(x - tower_x, y)
    if p.style == "drip":
        vessel = shapes.cone(0.42 * room, 0.3 * room, 0.8 * gap, (cx, 0, base_h + 0.4 * gap), sections=32)
        parts.append((vessel, P.GLASS))
        parts.append(
            (shapes.cylinder(0.38 * room, 0.35 * gap, (cx, 0, base_h + 0.18 * gap), sections=32), P.DARK_BROWN)
        )
    else:
        vessel = shapes.cylinder(0.3 * room, 0.45 * gap, (cx, 0, base_h + 0.225 * gap), sections=32)
        parts.append((vessel, v.color(2, P.WHITE)))
    if p.style == "espresso":
        group = shapes.cylinder(0.2 * room, 0.1 * gap, (cx, 0, z - head_h - 0.05 * gap + 0.002), sections=24)
        parts.append((group, trim))
    panel = shapes.box((0.004, 0.5 * y, 0.4 * head_h), (x / 2 - 0.0015, 0, z - head_h / 2))
    parts.append((panel, P.CHARCOAL))
    return _hulls(tuple(parts), v.size)


# --- utensils -------------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class LadleShape:
    """The bowl's diameter as a fraction of the whole length."""

    bowl: float = 0.28


@builder(LadleShape)
def ladle(v: Variant, p: LadleShape) -> Geometry:
    """A ladle lying on the table: a deep flat-bottomed bowl at -x and a straight handle sloping down to +x."""
    length, width, z = v.size
    r = p.bowl * length / 2
    x0 = -length / 2 + r
    bowl_h = 0.55 * z
    outer = resample([(0.55 * r, 0.0), (0.92 * r, 0.45 * bowl_h), (r, bowl_h)], 6)
    vessel = Vessel(outer, 0.002, 0.002, stations=2)
    bowl = vessel.mesh()
    bowl.apply_translation((x0, 0, 0))
    t = 0.006
    path = np.array([[x0 + 0.6 * r, 0, z - t], [x0 + r + 0.01, 0, z - t], [length / 2, 0, t]])
    path = shapes.resample_polyline(path, 12)
    handle = shapes.tube(path, t, sides=8, squash=0.5)
    color = v.color(0, P.STEEL)
    parts = ((bowl, color), (handle, v.color(1, color)))
    collision = (col.hull_part(bowl), *col.tube_parts(path, t, 3, sides=8))
    return fit_to_size(Geometry(parts, collision), v.size)


@dataclass(frozen=True)
class SpatulaShape:
    """A flat turner (optionally slotted) or a soft rubber scraper; the blade's length (fraction of the whole)."""

    style: Literal["turner", "scraper"] = "turner"
    slotted: bool = False
    blade: float = 0.35


@builder(SpatulaShape)
def spatula(v: Variant, p: SpatulaShape) -> Geometry:
    """A spatula lying flat: a thin blade at -x and a handle towards +x, both resting on the table."""
    length, width, z = v.size
    blade_len = p.blade * length
    bx = -length / 2 + blade_len / 2
    blade_t = 0.003 if p.style == "turner" else 0.006
    radius = 0.008 if p.style == "turner" else 0.35 * width
    blade = shapes.slab(blade_len, width, blade_t, radius, (bx, 0, blade_t / 2))
    handle_len = length - blade_len + 0.01
    neck = shapes.box((0.03, 0.22 * width, blade_t), (-length / 2 + blade_len + 0.01, 0, blade_t / 2))
    handle = shapes.rounded_box(
        (handle_len - 0.03, 0.3 * width, z), 0.4 * min(z, 0.3 * width), (length / 2 - (handle_len - 0.03) / 2, 0, z / 2)
    )
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [
        (blade, v.color(0, P.BLACK)),
        (neck, v.color(0, P.BLACK)),
        (handle, v.color(1, P.BLACK)),
    ]
    if p.slotted:
        for k in (-1, 0, 1):
            slot = shapes.box((0.6 * blade_len, 0.08 * width, blade_t + 0.0004), (bx, k * 0.22 * width, blade_t / 2))
            parts.append((slot, P.CHARCOAL))
    collision = (col.hull_part(np.vstack([blade.vertices, neck.vertices])), col.hull_part(handle))
    return fit_to_size(Geometry(tuple(parts), collision), v.size)


@dataclass(frozen=True)
class GraterShape:
    """Four-sided box grater or a flat paddle grater with a handle."""

    flat: bool = False


@builder(GraterShape)
def grater(v: Variant, p: GraterShape) -> Geometry:
    """A box grater: a tapered four-sided steel tower with a handle on top (or a flat paddle grater lying down)."""
    x, y, z = v.size
    color = v.color(0, P.STEEL)
    if p.flat:
        blade = shapes.slab(0.65 * x, y, 0.4 * z, 0.006, (-0.175 * x, 0, 0.2 * z))
        handle = shapes.rounded_box((0.37 * x, 0.45 * y, z), 0.3 * z, (0.315 * x, 0, z / 2))
        parts = ((blade, color), (handle, v.color(1, P.BLACK)))
        return _hulls(parts, v.size)
    body_h = 0.8 * z
    low = shapes.box((x, y, 0.002), (0, 0, 0.001))
    high = shapes.box((0.75 * x, 0.75 * y, 0.002), (0, 0, body_h - 0.001))
    body = shapes.hull(np.vstack([low.vertices, high.vertices]))
    t = np.linspace(0.0, np.pi, 13)
    arch = np.stack([0.3 * x * np.cos(t), np.zeros_like(t), body_h - 0.01 + (z - body_h - 0.002) * np.sin(t)], axis=1)
    grip = shapes.tube(arch, 0.011, sides=10)
    dots = []
    for k in range(4):
        for j in range(3):
            zc = 0.15 * body_h + 0.22 * body_h * k
            half = x / 2 - (0.125 * x) * zc / body_h
            dots.append((shapes.box((0.004, 0.12 * y, 0.012), (half - 0.001, (j - 1) * 0.25 * y, zc)), P.CHARCOAL))
    parts2: list[tuple[trimesh.Trimesh, RGBA]] = [(body, color), (grip, v.color(1, P.BLACK)), *dots]
    collision = (col.hull_part(body), *col.tube_parts(arch, 0.011, 3))
    return fit_to_size(Geometry(tuple(parts2), collision), v.size)


# --- larger appliances ----------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class BlenderShape:
    """A countertop blender with a handled jug, or a personal blender with a narrow bottle on a small base."""

    personal: bool = False


@builder(BlenderShape)
def blender(v: Variant, p: BlenderShape) -> Geometry:
    """A blender: a motor base, a tapered glass or plastic jar on it, a lid, a handle on -y (countertop)."""
    x, y, z = v.size
    base_h = 0.28 * z if not p.personal else 0.3 * z
    d = x
    base = shapes.cone(0.5 * d, 0.42 * d, base_h, (0, 0, base_h / 2), sections=4 if not p.personal else 32)
    if not p.personal:
        base.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 4, (0, 0, 1)))
    jar_h = z - base_h - 0.06 * z
    jar = shapes.cone(0.3 * d, 0.42 * d, jar_h, (0, 0, base_h + jar_h / 2 - 0.002), sections=32)
    lid = shapes.cylinder(0.43 * d, 0.06 * z + 0.002, (0, 0, z - 0.03 * z - 0.001), sections=32)
    dial = shapes.cylinder(0.1 * d, 0.02, (0.36 * d, 0, 0.5 * base_h), "x", 20)
    fill = shapes.cone(0.27 * d, 0.33 * d, 0.35 * jar_h, (0, 0, base_h + 0.175 * jar_h), sections=32)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [
        (base, v.color(0, P.BLACK)),
        (jar, v.color(1, P.GLASS)),
        (lid, v.color(0, P.BLACK)),
        (dial, P.SILVER),
        (fill, v.color(2, P.rgb(200, 60, 90))),
    ]
    collision = [
        col.hull_part(np.vstack([base.vertices, dial.vertices])),
        col.hull_part(np.vstack([jar.vertices, lid.vertices])),
    ]
    if not p.personal:
        handle, hparts = loop_handle(
            0.36 * d, base_h + 0.85 * jar_h, base_h + 0.2 * jar_h, y - 0.78 * d, 0.012, squareness=0.3
        )
        parts.append((handle, v.color(0, P.BLACK)))
        collision += hparts
    return fit_to_size(Geometry(tuple(parts), tuple(collision)), v.size)


@dataclass(frozen=True)
class MicrowaveShape:
    """The control panel's width (fraction of the front) and a handle bar on the door."""

    panel: float = 0.25
    handle: bool = False


@builder(MicrowaveShape)
def microwave(v: Variant, p: MicrowaveShape) -> Geometry:
    """A microwave oven, front +x: a box with a dark glass door on the left and a control panel on the right."""
    x, y, z = v.size
    body = shapes.rounded_box((x - 0.004, y, z - 0.006), 0.008, (-0.002, 0, z / 2 + 0.003))
    panel_w = p.panel * y
    door_w = y - panel_w - 0.03
    door = shapes.box((0.006, door_w, 0.78 * z), (x / 2 - 0.003, panel_w / 2, z / 2))
    window = shapes.box((0.006, 0.7 * door_w, 0.55 * z), (x / 2 - 0.0025, panel_w / 2 - 0.05 * door_w, z / 2))
    panel = shapes.box((0.004, panel_w - 0.02, 0.78 * z), (x / 2 - 0.002, -y / 2 + panel_w / 2 + 0.005, z / 2))
    feet = shapes.box((0.9 * x, 0.9 * y, 0.006), (0, 0, 0.003))
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [
        (body, v.color(0, P.WHITE)),
        (door, v.color(1, P.CHARCOAL)),
        (window, P.BLACK),
        (panel, v.color(2, P.CHARCOAL)),
        (feet, P.BLACK),
    ]
    if p.handle:
        parts.append((shapes.box((0.01, 0.02, 0.6 * z), (x / 2 - 0.001, -y / 2 + panel_w + 0.03, z / 2)), P.SILVER))
    return _one_hull(tuple(parts), v.size)


@builder(NoOptions)
def stand_mixer(v: Variant, _: NoOptions) -> Geometry:
    """A stand mixer, front +x: a base plate, a column at the back, a head over a steel bowl with a beater."""
    x, y, z = v.size
    color = v.color(0, P.RED)
    base_h = 0.08 * z
    base = shapes.rounded_box((x, 0.6 * y, base_h), 0.02, (0, 0, base_h / 2))
    column = shapes.rounded_box((0.3 * x, 0.5 * y, 0.75 * z), 0.05, (-0.35 * x, 0, 0.375 * z + 0.02))
    head = shapes.rounded_box((0.95 * x, 0.5 * y, 0.27 * z), 0.06, (-0.025 * x, 0, z - 0.135 * z))
    bowl_h = 0.45 * z
    bowl = shapes.lathe(
        [(0, base_h - 0.002), (0.25 * y, base_h - 0.002), (0.5 * y, base_h + bowl_h), (0, base_h + bowl_h)]
    )
    bowl.apply_translation((0.15 * x, 0, 0))
    beater = shapes.cylinder(
        0.02 * y, z - 0.27 * z - base_h - bowl_h + 0.01, (0.15 * x, 0, (base_h + bowl_h + z - 0.27 * z) / 2)
    )
    parts = ((base, color), (column, color), (head, color), (bowl, v.color(1, P.STEEL)), (beater, v.color(1, P.STEEL)))
    return _hulls(parts, v.size)


# --- holders -------------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class KnifeBlockShape:
    """The number of knife handles showing and the block's slant (fraction of the depth)."""

    knives: int = 5
    slant: float = 0.45


@builder(KnifeBlockShape)
def knife_block(v: Variant, p: KnifeBlockShape) -> Geometry:
    """A slanted wooden knife block with knife handles sticking out of its top, front +x."""
    x, y, z = v.size
    handle_h = 0.22 * z
    top = z - handle_h
    pts = [(sx, sy, 0.0) for sx in (-x / 2, x / 2) for sy in (-y / 2, y / 2)]
    pts += [(sx, sy, top) for sx in (-x / 2, -x / 2 + (1 - p.slant) * x) for sy in (-y / 2, y / 2)]
    block = shapes.hull(pts)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(block, v.color(0, P.WOOD))]
    top_x = -x / 2 + (1 - p.slant) * x / 2
    for k in range(p.knives):
        hy = -0.35 * y + 0.7 * y * k / max(1, p.knives - 1)
        handle = shapes.rounded_box(
            (0.045 if k % 2 else 0.035, 0.018, handle_h + 0.02), 0.006, (top_x, hy, top + handle_h / 2 - 0.01)
        )
        parts.append((handle, v.color(1, P.BLACK)))
    return _one_hull(tuple(parts), v.size)


@dataclass(frozen=True)
class UtensilHolderShape:
    """Square instead of round; the wall (m)."""

    square: bool = False
    wall: float = 0.006


@builder(UtensilHolderShape)
def utensil_holder(v: Variant, p: UtensilHolderShape) -> Geometry:
    """An open utensil crock for spoons and spatulas: a round or square pot, open at the top."""
    x, y, z = v.size
    color = v.color(0, P.WHITE)
    if p.square:
        mesh = _open_box_mesh(x, y, z, p.wall, 0.01, 0.01)
        cavity = Cavity(rectangle(x - 2 * p.wall, y - 2 * p.wall), 0.01, z - 0.01)
        return Geometry(((mesh, color),), tuple(col.open_box_parts(x, y, z, p.wall, 0.01)), cavity)
    r = x / 2
    vessel = Vessel(resample([(0.95 * r, 0.0), (r, z)], 4), p.wall, 0.01, stations=1)
    band = trimesh.creation.annulus(r_min=0.9 * r, r_max=0.975 * r + 0.002, height=0.1 * z).apply_translation(
        (0, 0, 0.3 * z)
    )
    return Geometry(((vessel.mesh(), color), (band, v.color(1, color))), tuple(vessel.collision(16)), vessel.cavity())


@dataclass(frozen=True)
class PaperTowelHolderShape:
    """With a roll of paper towel on it (or bare), the base's radius (fraction of the whole width)."""

    roll: bool = True


@builder(PaperTowelHolderShape)
def paper_towel_holder(v: Variant, p: PaperTowelHolderShape) -> Geometry:
    """A standing paper towel holder: a weighted round base, an upright rod with a knob, a roll of kitchen paper."""
    d, _, z = v.size
    r = d / 2
    base = shapes.cylinder(r, 0.02, (0, 0, 0.01), sections=40)
    rod = shapes.cylinder(0.08 * r, z - 0.03, (0, 0, 0.02 + (z - 0.03) / 2), sections=16)
    knob = shapes.sphere(0.14 * r, (0, 0, z - 0.14 * r), 2)
    metal = v.color(0, P.STEEL)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(base, metal), (rod, metal), (knob, metal)]
    if p.roll:
        roll = shapes.cylinder(0.8 * r, 0.82 * z, (0, 0, 0.025 + 0.41 * z), sections=40)
        parts.append((roll, v.color(1, P.PAPER)))
    return _hulls(tuple(parts), v.size)


@builder(NoOptions)
def napkin_holder(v: Variant, _: NoOptions) -> Geometry:
    """A napkin holder: a base with two upright sides along y and a stack of paper napkins standing between them."""
    x, y, z = v.size
    color = v.color(0, P.STEEL)
    base = shapes.slab(x, y, 0.012, 0.005, (0, 0, 0.006))
    sides = [shapes.slab(0.006, 0.85 * y, z - 0.01, 0.002, (s * (x / 2 - 0.004), 0, z / 2 + 0.004)) for s in (1, -1)]
    napkins = shapes.box((x - 0.03, 0.8 * y, 0.75 * z), (0, 0, 0.375 * z + 0.008))
    parts = ((base, color), (sides[0], color), (sides[1], color), (napkins, v.color(1, P.WHITE)))
    return _hulls(parts, v.size)


@dataclass(frozen=True)
class ScaleShape:
    """A flat digital platform scale, or a mechanical scale with a dial and a weighing bowl on top."""

    bowl: bool = False


@builder(ScaleShape)
def kitchen_scale(v: Variant, p: ScaleShape) -> Geometry:
    """A kitchen scale: a flat platform with a display at the front (+x), or a dial body with a bowl on top."""
    x, y, z = v.size
    color = v.color(0, P.WHITE)
    if not p.bowl:
        body = shapes.rounded_box((x, y, z), min(0.4 * z, 0.01), (0, 0, z / 2))
        display = shapes.box((0.04, 0.4 * y, 0.2 * z), (0.38 * x, 0, z - 0.08 * z))
        flat = ((body, color), (display, v.color(1, P.CHARCOAL)))
        return Geometry(flat, (col.box_part((x, y, z), (0, 0, z / 2)),))
    body_h = 0.6 * z
    body = shapes.rounded_box((0.8 * x, 0.8 * y, body_h), 0.02, (0, 0, body_h / 2))
    dial = shapes.cylinder(0.3 * body_h, 0.01, (0.4 * x, 0, 0.5 * body_h), "x", 32)
    bowl = shapes.lathe([(0, body_h - 0.002), (0.2 * y, body_h - 0.002), (0.5 * y, z), (0, z)])
    parts = ((body, color), (dial, v.color(1, P.WHITE)), (bowl, v.color(2, P.STEEL)))
    return _hulls(parts, v.size)


# --- bakeware ------------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class BakingTrayShape:
    """The rim's width (m), and the number of muffin cups (rows x columns; 0: a flat sheet pan)."""

    rim: float = 0.012
    cups: int = 0
    square: bool = False


@builder(BakingTrayShape)
def baking_tray(v: Variant, p: BakingTrayShape) -> Geometry:
    """A rimmed metal baking sheet (a flat carrier), a muffin tin with round cups or an ice cube tray; one hull."""
    x, y, z = v.size
    color = v.color(0, P.SILVER)
    outer = shapes.slab(x, y, z, 0.01, (0, 0, z / 2))
    if p.cups:
        mesh = trimesh.boolean.difference([outer, *_pockets(x, y, z, p.cups, p.square)], engine="manifold")
    else:
        inner = shapes.slab(x - 2 * p.rim, y - 2 * p.rim, z, 0.006, (0, 0, 0.0015 + z / 2))
        mesh = trimesh.boolean.difference([outer, inner], engine="manifold")
    return Geometry(((mesh, color),), (col.hull_part(mesh),))


def _pockets(x: float, y: float, z: float, cols: int, square: bool) -> list[trimesh.Trimesh]:
    """The solids cut out of a tray for its cups: `cols` along x and as many rows as fit along y."""
    rows = max(1, round(cols * y / x))
    pitch = min(x / cols, y / rows)
    centres = [(-x / 2 + (i + 0.5) * x / cols, -y / 2 + (j + 0.5) * y / rows) for i in range(cols) for j in range(rows)]
    if square:
        return [shapes.box((0.8 * x / cols, 0.8 * y / rows, z), (cx, cy, 0.002 + z / 2)) for cx, cy in centres]
    return [shapes.cylinder(0.38 * pitch, z, (cx, cy, 0.0015 + z / 2), sections=24) for cx, cy in centres]


@dataclass(frozen=True)
class MortarShape:
    """The pestle lying beside the mortar (on +y), and the mortar's wall (m)."""

    pestle: bool = True
    wall: float = 0.012


@builder(MortarShape)
def mortar_and_pestle(v: Variant, p: MortarShape) -> Geometry:
    """A heavy stone mortar (an open bowl with thick walls) with its pestle lying beside it on +y."""
    x, y, z = v.size
    r = x / 2
    shift = (y - x) / 2 if p.pestle else 0.0
    outer = resample([(0.75 * r, 0.0), (0.97 * r, 0.5 * z), (r, z)], 6)
    vessel = Vessel(outer, p.wall, 0.02, stations=2)
    bowl = vessel.mesh().apply_translation((0, -shift, 0))
    color = v.color(0, P.GREY)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(bowl, color)]
    collision = [c.translated(np.array([0, -shift, 0])) for c in vessel.collision(12)]
    if p.pestle:
        pr = min(0.45 * (y - x), 0.025)
        length = 0.9 * x
        path = np.array([[-length / 2, 0, 0], [length / 2, 0, 0]])
        path = shapes.resample_polyline(path, 8)
        radii = np.linspace(0.6 * pr, pr, 8)
        path[:, 1] = y / 2 - pr
        path[:, 2] = radii
        pestle = shapes.tube(path, radii, sides=12)
        parts.append((pestle, v.color(1, color)))
        collision += col.tube_parts(path, radii, 2, sides=12)
    cavity = vessel.cavity()
    cavity = Cavity(cavity.opening + np.array([0, -shift]), cavity.floor_height, cavity.depth)
    return Geometry(tuple(parts), tuple(collision), cavity)


# --- small utensils ------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class TongsShape:
    """How far the tips open (fraction of the width) and silicone tips of the second colour."""

    tips: bool = True


@builder(TongsShape)
def tongs(v: Variant, p: TongsShape) -> Geometry:
    """Kitchen tongs lying flat: two arms joined at the hinge (+x) and spreading to the tips (-x)."""
    length, width, z = v.size
    color = v.color(0, P.STEEL)
    arm_w = 0.2 * width
    parts: list[tuple[trimesh.Trimesh, RGBA]] = []
    collision = []
    for s in (1, -1):
        pts = [(length / 2, s * 0.05 * width, zz) for zz in (0.0, z)] + [
            (length / 2, s * (0.05 * width + arm_w), zz) for zz in (0.0, z)
        ]
        pts += [(-length / 2, s * (width / 2 - arm_w), zz) for zz in (0.0, z)] + [
            (-length / 2, s * width / 2, zz) for zz in (0.0, z)
        ]
        arm = shapes.hull(pts)
        parts.append((arm, color))
        collision.append(col.hull_part(arm))
        if p.tips:
            tip = shapes.box(
                (0.22 * length, arm_w * 1.1, z * 1.02), (-0.39 * length, s * (width / 2 - 0.6 * arm_w), z / 2)
            )
            parts.append((tip, v.color(1, P.BLACK)))
    hinge = shapes.box((0.04 * length, 0.3 * width, z), (0.48 * length, 0, z / 2))
    parts.append((hinge, color))
    collision.append(col.hull_part(hinge))
    return fit_to_size(Geometry(tuple(parts), tuple(collision)), v.size)


@dataclass(frozen=True)
class PeelerShape:
    """A Y-shaped peeler (blade across the fork) or a straight swivel peeler."""

    y_shaped: bool = True


@builder(PeelerShape)
def peeler(v: Variant, p: PeelerShape) -> Geometry:
    """A vegetable peeler lying flat: a handle towards +x and a blade in a frame at -x."""
    length, width, z = v.size
    handle_len = 0.6 * length if p.y_shaped else 0.55 * length
    handle = shapes.rounded_box(
        (handle_len, 0.3 * width if p.y_shaped else 0.45 * width, z), 0.4 * z, (length / 2 - handle_len / 2, 0, z / 2)
    )
    head_len = length - handle_len + 0.005
    hx = -length / 2 + head_len / 2
    if p.y_shaped:
        frame = [shapes.box((head_len, 0.08 * width, 0.5 * z), (hx, s * 0.46 * width, 0.25 * z)) for s in (1, -1)]
        blade = shapes.box((0.12 * head_len, 0.95 * width, 0.3 * z), (-length / 2 + 0.1 * head_len, 0, 0.15 * z))
        metal = [*frame, blade]
    else:
        metal = [shapes.box((head_len, 0.35 * width, 0.4 * z), (hx, 0, 0.2 * z))]
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(handle, v.color(0, P.BLACK))] + [
        (m, v.color(1, P.STEEL)) for m in metal
    ]
    collision = (col.hull_part(handle), col.hull_part(np.vstack([m.vertices for m in metal])))
    return fit_to_size(Geometry(tuple(parts), collision), v.size)


@dataclass(frozen=True)
class WhiskShape:
    """The number of wire loops and the balloon's length (fraction of the whole)."""

    loops: int = 4
    head: float = 0.6


@builder(WhiskShape)
def whisk(v: Variant, p: WhiskShape) -> Geometry:
    """A balloon whisk lying on its side: wire loops at -x, a handle towards +x whose end rests on the table."""
    length, width, height = v.size
    rb = width / 2
    head_len = p.head * length
    rh = 0.22 * rb
    x_join = -length / 2 + head_len
    t = np.linspace(0.0, 1.0, 24)
    bulge = np.sin(np.pi * np.clip(t, 0, 1) ** 0.7)
    radial = rh * 0.6 + (rb - rh * 0.6) * bulge
    xs = x_join - head_len * t
    parts: list[tuple[trimesh.Trimesh, RGBA]] = []
    wire_pts = []
    offset = (1.5 * np.pi - np.pi / (2 * p.loops)) % (np.pi / p.loops)  # two wires straddle the bottom: a flat facet
    for k in range(p.loops):
        phi = np.pi * k / p.loops + offset
        half = np.stack([xs, radial * np.cos(phi), radial * np.sin(phi)], axis=1)
        other = np.stack([xs[::-1], -radial[::-1] * np.cos(phi), -radial[::-1] * np.sin(phi)], axis=1)
        loop = np.vstack([half, other[1:]])
        parts.append((shapes.tube(loop, 0.0012, sides=6), v.color(0, P.STEEL)))
        wire_pts.append(loop)
    handle = shapes.cylinder(rh, length - head_len, (x_join + (length - head_len) / 2, 0, 0), "x", 12)
    parts.append((handle, v.color(1, v.color(0, P.STEEL))))
    tilt = np.arctan2(rb - rh, length - 0.45 * head_len)
    turn = trimesh.transformations.rotation_matrix(tilt, (0, 1, 0), (x_join - 0.45 * head_len, 0, 0))
    head_hull = shapes.hull(np.vstack(wire_pts)).apply_transform(turn)
    handle_turned = parts[-1][0].copy().apply_transform(turn)
    # Settle the tilt exactly: the handle's end and the balloon's lowest wire touch the table together.
    b = head_hull.vertices[np.argmin(head_hull.vertices[:, 2])]
    h = handle_turned.vertices[np.argmin(handle_turned.vertices[:, 2])]
    turn = trimesh.transformations.rotation_matrix(np.arctan2(h[2] - b[2], h[0] - b[0]), (0, 1, 0), b) @ turn
    meshes = [(m.copy().apply_transform(turn), c) for m, c in parts]
    head_hull = shapes.hull(np.vstack(wire_pts)).apply_transform(turn)
    collision = (col.hull_part(head_hull), col.hull_part(meshes[-1][0]))
    return fit_to_size(Geometry(tuple(meshes), collision), v.size)


# --- canisters and jars ----------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class CanisterShape:
    """Square instead of round, the lid's height (fraction of the whole) and a printed label band."""

    square: bool = False
    lid: float = 0.18
    label: bool = True
    open: bool = False  # the lid off, empty: a round tin things are dropped into


@builder(CanisterShape)
def canister(v: Variant, p: CanisterShape) -> Geometry:
    """A closed kitchen storage canister (flour, sugar, coffee, tea): a round or square body with a lid."""
    x, y, z = v.size
    if p.open:
        vessel = Vessel(np.array([(x / 2, 0.0), (x / 2, z)]), 0.0025, 0.004, stations=1)
        return Geometry(((vessel.mesh(), v.color(0, P.WHITE)),), tuple(vessel.collision(16)), vessel.cavity())
    lid_h = p.lid * z
    body_h = z - lid_h
    if p.square:
        body = shapes.rounded_box((x, y, body_h + 0.002), 0.01, (0, 0, body_h / 2 + 0.001))
        lid = shapes.rounded_box((x, y, lid_h), 0.01, (0, 0, z - lid_h / 2))
        label = shapes.box((0.004, 0.6 * y, 0.3 * body_h), (x / 2 - 0.0015, 0, 0.5 * body_h))
    else:
        body = shapes.cylinder(0.97 * x / 2, body_h + 0.002, (0, 0, body_h / 2 + 0.001), sections=48)
        lid = shapes.cylinder(x / 2, lid_h, (0, 0, z - lid_h / 2), sections=48)
        label = shapes.cylinder(0.97 * x / 2 + 0.001, 0.3 * body_h, (0, 0, 0.5 * body_h), sections=48)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(body, v.color(0, P.WHITE)), (lid, v.color(1, P.WOOD))]
    if p.label:
        parts.append((label, v.color(2, P.CHARCOAL)))
    return _one_hull(tuple(parts), v.size)


@dataclass(frozen=True)
class CookieJarShape:
    """Open: the lid off, an empty jar that cookies are dropped into."""

    open: bool = False


@builder(CookieJarShape)
def cookie_jar(v: Variant, p: CookieJarShape) -> Geometry:
    """A bulbous ceramic cookie jar with a domed lid and a round knob (or open: the lid off, empty)."""
    d, z = v.size[0], v.size[2]
    r = d / 2
    if p.open:
        outer = resample([(0.7 * r, 0.0), (r, 0.45 * z), (0.86 * r, z)], 8)
        vessel = Vessel(outer, 0.006, 0.008, stations=4)
        return Geometry(((vessel.mesh(), v.color(0, P.CREAM)),), tuple(vessel.collision(16)), vessel.cavity())
    body_h = 0.75 * z
    t = np.linspace(-0.5 * np.pi, 0.5 * np.pi, 14)
    prof = [(0.0, 0.0), (0.7 * r, 0.0)]
    prof += [
        (0.7 * r + 0.3 * r * np.cos(a) if a < 0 else r - 0.2 * r * np.sin(a), body_h * (0.5 + 0.5 * np.sin(a)))
        for a in t[1:-1]
    ]
    prof += [(0.8 * r, body_h), (0.0, body_h)]
    body = shapes.lathe(prof)
    lid = shapes.lathe(
        [
            (0, body_h - 0.003),
            (0.82 * r, body_h - 0.003),
            (0.7 * r, body_h + 0.08 * z),
            (0.2 * r, z - 0.08 * z),
            (0, z - 0.08 * z),
        ]
    )
    knob = shapes.sphere(0.06 * z, (0, 0, z - 0.06 * z), 2)
    color = v.color(0, P.CREAM)
    parts = ((body, color), (lid, v.color(1, color)), (knob, v.color(2, P.BROWN)))
    return _one_hull(parts, v.size)


@dataclass(frozen=True)
class TrivetShape:
    """Round instead of square, and an open cast-iron grid instead of a solid cork or wood pad."""

    round: bool = False
    grid: bool = False


@builder(TrivetShape)
def trivet(v: Variant, p: TrivetShape) -> Geometry:
    """A trivet for hot pots: a flat cork or wooden pad, or a cast-iron grid on small feet."""
    x, y, z = v.size
    color = v.color(0, P.rgb(195, 160, 115))
    if not p.grid:
        pad = (
            shapes.cylinder(x / 2, z, (0, 0, z / 2), sections=48)
            if p.round
            else shapes.slab(x, y, z, 0.01, (0, 0, z / 2))
        )
        part = col.hull_part(pad)
        return Geometry(((pad, color),), (part,))
    frame = _open_box_mesh(x, y, 0.6 * z, 0.008, 0.0, 0.01).apply_translation((0, 0, 0.4 * z))
    bars = [
        shapes.box((0.006, y - 0.004, 0.5 * z), (u, 0, 0.75 * z - 0.001)) for u in np.linspace(-0.3 * x, 0.3 * x, 5)
    ]
    feet = [
        shapes.box((0.015, 0.015, 0.42 * z), (sx * (x / 2 - 0.01), sy * (y / 2 - 0.01), 0.21 * z))
        for sx in (1, -1)
        for sy in (1, -1)
    ]
    parts = tuple((m, color) for m in (frame, *bars, *feet))
    return Geometry(parts, (col.box_part((x, y, z), (0, 0, z / 2)),))


# --- oven dishes and cookers ----------------------------------------------------------------------------------------


@dataclass(frozen=True)
class OvenDishShape:
    """The dish's outline, its wall and floor (m), and ear handles on +-x (their reach, m; 0: none)."""

    outline: Literal["rect", "oval", "round"] = "rect"
    wall: float = 0.008
    handles: float = 0.0


@builder(OvenDishShape)
def oven_dish(v: Variant, p: OvenDishShape) -> Geometry:
    """An open ovenproof dish (baking, lasagne or pie dish): rectangular walls or a revolved round/oval bowl."""
    x, y, z = v.size
    color = v.color(0, P.WHITE)
    bx = x - 2 * p.handles
    if p.outline == "rect":
        mesh = _open_box_mesh(bx, y, z, p.wall, p.wall, 0.025)
        collision: list[CollisionPart] = list(col.open_box_parts(bx, y, z, p.wall, p.wall))
        cavity = Cavity(rectangle(bx - 2 * p.wall, y - 2 * p.wall), p.wall, z - p.wall)
    else:
        r = bx / 2
        vessel = Vessel(resample([(0.85 * r, 0.0), (r, z)], 4), p.wall, p.wall, stations=1)
        squash = np.array([1.0, y / bx, 1.0])
        mesh = vessel.mesh().apply_scale(squash)
        collision = [
            col.hull_part(part.vertices * squash) for part in vessel.collision(16) if part.vertices is not None
        ]
        base = vessel.cavity()
        cavity = Cavity(base.opening * squash[:2], base.floor_height, base.depth)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(mesh, color)]
    if p.handles:
        for s in (1, -1):
            ear = shapes.slab(
                p.handles + 0.01, 0.4 * y, 0.012, 0.008, (s * (x / 2 - (p.handles + 0.01) / 2), 0, z - 0.008)
            )
            parts.append((ear, v.color(1, color)))
            collision.append(col.hull_part(ear))
    return Geometry(tuple(parts), tuple(collision), cavity)


@dataclass(frozen=True)
class CookerShape:
    """A round rice cooker with a domed lid and a carry handle, or an oval slow cooker with side grips."""

    slow: bool = False


@builder(CookerShape)
def cooker(v: Variant, p: CookerShape) -> Geometry:
    """An electric cooker: a rounded body, a lid with a knob or handle, a control panel at the front (+x)."""
    x, y, z = v.size
    body_color = v.color(0, P.WHITE)
    body_h = 0.72 * z
    r = min(x, y) / 2
    body = shapes.lathe(
        [(0, 0), (0.88 * r, 0), (r, 0.15 * body_h), (r, 0.85 * body_h), (0.92 * r, body_h), (0, body_h)]
    )
    lid = shapes.lathe(
        [(0, body_h - 0.003), (0.93 * r, body_h - 0.003), (0.75 * r, body_h + 0.12 * z), (0, body_h + 0.14 * z)]
    )
    panel = shapes.box((0.02, 0.5 * r, 0.25 * body_h), (0.96 * r, 0, 0.45 * body_h))
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(body, body_color), (lid, v.color(1, P.SILVER)), (panel, P.CHARCOAL)]
    if p.slow:
        for s in (1, -1):
            parts.append((shapes.box((0.3 * r, 0.1 * r + 0.02, 0.03), (0, s * (r + 0.005), 0.8 * body_h)), P.BLACK))
        parts.append((shapes.sphere(0.03 * z + 0.006, (0, 0, z - 0.03 * z - 0.006), 2), P.BLACK))
    else:
        grip = shapes.box((0.12 * r, 0.9 * r, 0.06 * z), (0, 0, z - 0.03 * z))
        parts.append((grip, v.color(1, P.SILVER)))
    return _one_hull(tuple(parts), v.size)


@builder(NoOptions)
def salad_spinner(v: Variant, _: NoOptions) -> Geometry:
    """A salad spinner: a wide round bowl with a lid and a pump knob on top."""
    d, z = v.size[0], v.size[2]
    r = d / 2
    bowl_h = 0.8 * z
    bowl = shapes.lathe([(0, 0), (0.7 * r, 0), (0.95 * r, 0.5 * bowl_h), (r, bowl_h), (0, bowl_h)])
    lid = shapes.lathe(
        [(0, bowl_h - 0.002), (r, bowl_h - 0.002), (0.95 * r, bowl_h + 0.06 * z), (0, bowl_h + 0.06 * z)]
    )
    knob = shapes.cylinder(0.18 * r, z - bowl_h - 0.05 * z, (0, 0, (z + bowl_h + 0.05 * z) / 2), sections=24)
    parts = ((bowl, v.color(0, P.GLASS)), (lid, v.color(1, P.WHITE)), (knob, v.color(2, P.GREEN)))
    return _one_hull(parts, v.size)


@builder(NoOptions)
def gravy_boat(v: Variant, _: NoOptions) -> Geometry:
    """A gravy boat: a long low bowl on a foot with a pouring lip at +x and a handle at -x."""
    x, y, z = v.size
    r = y / 2
    body_h = 0.7 * z
    body = shapes.lathe(
        [(0, 0), (0.45 * r, 0), (0.45 * r, 0.12 * z), (0.9 * r, 0.35 * body_h), (r, body_h), (0, body_h)]
    )
    body.apply_scale((1.5, 1.0, 1.0))
    lip = shapes.hull(
        [(0.9 * 1.5 * r, sy * 0.45 * r, zz) for sy in (-1, 1) for zz in (0.4 * body_h, body_h)]
        + [(x / 2 - 0.002, 0, z - 0.005), (x / 2 - 0.002, 0, 0.85 * z)]
    )
    handle, hparts = loop_handle(1.35 * r, z - 0.01, 0.45 * body_h, x / 2 - 1.5 * r, 0.006, yaw=np.pi, squareness=0.5)
    color = v.color(0, P.WHITE)
    parts = ((body, color), (lip, color), (handle, color))
    return fit_to_size(Geometry(parts, (col.hull_part(np.vstack([body.vertices, lip.vertices])), *hparts)), v.size)


@builder(NoOptions)
def thermos(v: Variant, _: NoOptions) -> Geometry:
    """A vacuum flask standing: a tall insulated cylinder with a shoulder and a cup-lid on top."""
    d, z = v.size[0], v.size[2]
    r = d / 2
    cup_h = 0.18 * z
    body_h = z - cup_h
    body = shapes.lathe([(0, 0), (0.96 * r, 0), (r, 0.03 * z), (r, 0.9 * body_h), (0.85 * r, body_h), (0, body_h)])
    cup = shapes.cylinder(0.93 * r, cup_h + 0.002, (0, 0, body_h + cup_h / 2 - 0.001), sections=40)
    band = shapes.cylinder(r + 0.0008, 0.05 * z, (0, 0, 0.15 * z), sections=40)
    parts = ((body, v.color(0, P.STEEL)), (cup, v.color(1, P.BLACK)), (band, v.color(1, P.BLACK)))
    return _one_hull(parts, v.size)


@builder(NoOptions)
def cocktail_shaker(v: Variant, _: NoOptions) -> Geometry:
    """A three-piece cocktail shaker: a tapered tin, a strainer top and a small cap."""
    d, z = v.size[0], v.size[2]
    r = d / 2
    tin_h = 0.62 * z
    tin = shapes.lathe([(0, 0), (0.8 * r, 0), (r, tin_h), (0, tin_h)])
    top = shapes.lathe(
        [(0, tin_h - 0.003), (r, tin_h - 0.003), (0.95 * r, tin_h + 0.05 * z), (0.45 * r, 0.9 * z), (0, 0.9 * z)]
    )
    cap = shapes.cylinder(0.47 * r, 0.1 * z + 0.002, (0, 0, 0.95 * z - 0.001), sections=32)
    color = v.color(0, P.STEEL)
    return _one_hull(((tin, color), (top, v.color(1, color)), (cap, v.color(1, color))), v.size)


# --- more hand tools -----------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class FlatToolShape:
    """The tool: a can opener (two long handles and a cutting head), a pizza wheel or a dish brush."""

    tool: Literal["can_opener", "pizza_cutter", "dish_brush"] = "can_opener"


@builder(FlatToolShape)
def flat_tool(v: Variant, p: FlatToolShape) -> Geometry:
    """A small kitchen hand tool lying flat with its handle towards +x."""
    length, width, z = v.size
    grip = v.color(0, P.BLACK)
    metal = v.color(1, P.STEEL)
    parts: Parts
    if p.tool == "can_opener":
        head = shapes.slab(0.3 * length, width, 0.7 * z, 0.01, (-0.35 * length, 0, 0.35 * z))
        key = shapes.cylinder(0.3 * width, z, (-0.35 * length, 0, z / 2), sections=24)
        arms = [
            shapes.rounded_box(
                (0.72 * length, 0.25 * width, 0.6 * z), 0.2 * z, (0.14 * length, s * 0.2 * width, 0.3 * z)
            )
            for s in (1, -1)
        ]
        parts = ((head, metal), (key, grip), (arms[0], grip), (arms[1], grip))
    elif p.tool == "pizza_cutter":
        wheel = shapes.cylinder(width / 2, 0.25 * z, (-length / 2 + width / 2, 0, 0.125 * z), sections=48)
        guard = shapes.box((0.3 * width, 0.25 * width, 0.5 * z), (-length / 2 + width / 2, 0, 0.25 * z))
        handle = shapes.rounded_box((length - width, 0.35 * width, z), 0.35 * z, (width / 2, 0, z / 2))
        parts = ((wheel, metal), (guard, metal), (handle, grip))
    else:
        head = shapes.rounded_box((0.3 * length, width, 0.7 * z), 0.2 * z, (-0.35 * length, 0, 0.35 * z))
        bristles = shapes.box((0.28 * length, 0.85 * width, 0.35 * z), (-0.36 * length, 0, 0.7 * z))
        handle = shapes.rounded_box((0.72 * length, 0.35 * width, 0.5 * z), 0.2 * z, (0.14 * length, 0, 0.25 * z))
        parts = ((head, grip), (bristles, metal), (handle, grip))
    return _hulls(parts, v.size)


# --- more small appliances and gadgets ------------------------------------------------------------------------------


@builder(NoOptions)
def air_fryer(v: Variant, _: NoOptions) -> Geometry:
    """An air fryer, front +x: a rounded upright body, a pull-out basket drawer with a handle, a dark top panel."""
    x, y, z = v.size
    handle_reach = 0.08 * x
    bx = x - handle_reach
    body = shapes.rounded_box((bx, y, z), 0.25 * min(bx, y), (-handle_reach / 2, 0, z / 2))
    drawer = shapes.rounded_box((0.1 * bx, 0.8 * y, 0.45 * z), 0.02, (bx / 2 - handle_reach / 2 - 0.035, 0, 0.27 * z))
    handle = shapes.rounded_box(
        (handle_reach + 0.02, 0.12 * y, 0.16 * z), 0.008, (x / 2 - (handle_reach + 0.02) / 2, 0, 0.3 * z)
    )
    panel = shapes.box((0.35 * bx, 0.5 * y, 0.01), (0.05 * bx, 0, z - 0.004))
    color = v.color(0, P.BLACK)
    parts = ((body, color), (drawer, v.color(1, P.CHARCOAL)), (handle, v.color(1, P.CHARCOAL)), (panel, P.CHARCOAL))
    return _hulls(parts, v.size)


@dataclass(frozen=True)
class GrinderShape:
    """A burr grinder (a box with a bean hopper on top) or a small round blade grinder with a clear cap."""

    burr: bool = True


@builder(GrinderShape)
def coffee_grinder(v: Variant, p: GrinderShape) -> Geometry:
    """A coffee grinder: a body with a bean hopper or a clear cap on top."""
    x, y, z = v.size
    color = v.color(0, P.BLACK)
    if p.burr:
        body_h = 0.6 * z
        body = shapes.rounded_box((x, y, body_h), 0.015, (0, 0, body_h / 2))
        hopper = shapes.cone(
            0.22 * min(x, y), 0.45 * min(x, y), z - body_h + 0.004, (0, 0, body_h + (z - body_h) / 2 - 0.002)
        )
        beans = shapes.cone(0.2 * min(x, y), 0.38 * min(x, y), 0.5 * (z - body_h), (0, 0, body_h + 0.25 * (z - body_h)))
        cup = shapes.box((0.01, 0.5 * y, 0.3 * body_h), (x / 2 - 0.004, 0, 0.25 * body_h))
        parts = ((body, color), (hopper, P.GLASS), (beans, P.DARK_BROWN), (cup, v.color(1, P.SILVER)))
        return _hulls(parts, v.size)
    r = x / 2
    body_h = 0.65 * z
    body = shapes.cylinder(r, body_h, (0, 0, body_h / 2), sections=40)
    cap = shapes.lathe([(0, body_h - 0.002), (0.92 * r, body_h - 0.002), (0.85 * r, z - 0.02), (0.5 * r, z), (0, z)])
    return _one_hull(((body, color), (cap, v.color(1, P.GLASS))), v.size)


@dataclass(frozen=True)
class JuicerShape:
    """A glass hand juicer (a dish with a ribbed cone) or an electric juicer on a round motor base."""

    electric: bool = False


@builder(JuicerShape)
def citrus_juicer(v: Variant, p: JuicerShape) -> Geometry:
    """A citrus juicer: a shallow dish with a ribbed reamer cone in the middle, on a motor base if electric."""
    d, z = v.size[0], v.size[2]
    r = d / 2
    base_h = 0.45 * z if p.electric else 0.0
    dish_h = 0.3 * (z - base_h)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = []
    if p.electric:
        parts.append(
            (shapes.cylinder(0.85 * r, base_h + 0.002, (0, 0, base_h / 2 + 0.001), sections=40), v.color(1, P.WHITE))
        )
    dish = shapes.lathe([(0, base_h), (0.85 * r, base_h), (r, base_h + dish_h), (0, base_h + dish_h)])
    cone = shapes.lathe(
        [(0, base_h + dish_h - 0.002), (0.4 * r, base_h + dish_h - 0.002), (0.05 * r, z - 0.003), (0, z)], 12
    )
    parts += [(dish, v.color(0, P.GLASS)), (cone, v.color(0, P.GLASS))]
    return _one_hull(tuple(parts), v.size)


@builder(NoOptions)
def waffle_maker(v: Variant, _: NoOptions) -> Geometry:
    """A closed waffle maker, front +x: a low rounded clamshell on a base, with a handle at the front."""
    x, y, z = v.size
    reach = 0.1 * x
    bx = x - reach
    base = shapes.rounded_box((bx, y, 0.45 * z), 0.02, (-reach / 2, 0, 0.225 * z))
    lid = shapes.rounded_box((0.95 * bx, 0.95 * y, 0.6 * z), 0.04, (-reach / 2, 0, 0.7 * z))
    handle = shapes.rounded_box((reach + 0.02, 0.3 * y, 0.12 * z), 0.01, (x / 2 - (reach + 0.02) / 2, 0, 0.55 * z))
    color = v.color(0, P.BLACK)
    return _one_hull(((base, color), (lid, v.color(1, P.SILVER)), (handle, color)), v.size)


@dataclass(frozen=True)
class TimerShape:
    """A wind-up dial timer (a low drum with a knob) or a digital square one."""

    digital: bool = False


@builder(TimerShape)
def kitchen_timer(v: Variant, p: TimerShape) -> Geometry:
    """A kitchen timer standing on the counter: a dial drum with a turning top, or a small digital box."""
    x, y, z = v.size
    color = v.color(0, P.WHITE)
    if p.digital:
        body = shapes.rounded_box((x, y, z), 0.006, (0, 0, z / 2))
        screen = shapes.box((0.004, 0.7 * y, 0.35 * z), (x / 2 - 0.0015, 0, 0.65 * z))
        return _one_hull(((body, color), (screen, v.color(1, P.CHARCOAL))), v.size)
    r = x / 2
    drum = shapes.lathe([(0, 0), (0.95 * r, 0), (r, 0.5 * z), (0.9 * r, 0.7 * z), (0, 0.7 * z)])
    top = shapes.lathe([(0, 0.7 * z - 0.002), (0.88 * r, 0.7 * z - 0.002), (0.5 * r, z), (0, z)])
    return _one_hull(((drum, color), (top, v.color(1, P.RED))), v.size)


@builder(NoOptions)
def funnel(v: Variant, _: NoOptions) -> Geometry:
    """A kitchen funnel resting on its wide mouth: a cone narrowing to a short spout at the top."""
    d, z = v.size[0], v.size[2]
    r = d / 2
    cone_h = 0.6 * z
    mesh = shapes.lathe([(0, 0), (r, 0), (r, 0.05 * z), (0.15 * r, cone_h), (0.12 * r, z), (0, z)])
    return _one_hull(((mesh, v.color(0, P.STEEL)),), v.size)


@builder(NoOptions)
def filter_jug(v: Variant, _: NoOptions) -> Geometry:
    """A water filter jug, front +x: a tall oval jug with a filter cartridge under the lid and a handle at -x."""
    x, y, z = v.size
    reach = 0.25 * x
    bx = x - reach
    body = shapes.rounded_box((bx, y, 0.9 * z), 0.3 * min(bx, y), (reach / 2, 0, 0.45 * z))
    lid = shapes.rounded_box((bx, y, 0.12 * z), 0.3 * min(bx, y), (reach / 2, 0, z - 0.06 * z))
    water = shapes.rounded_box((0.96 * bx, 0.94 * y, 0.45 * z), 0.28 * min(bx, y), (reach / 2, 0, 0.24 * z))
    handle, hparts = loop_handle(bx / 2 - 0.01, 0.95 * z, 0.2 * z, reach + 0.01, 0.012, yaw=np.pi, squareness=0.3)
    handle.apply_translation((reach / 2, 0, 0))
    parts = (
        (body, v.color(0, P.GLASS)),
        (lid, v.color(1, P.BLUE)),
        (water, P.rgb(170, 210, 240, 0.5)),
        (handle, v.color(1, P.BLUE)),
    )
    collision = (
        col.hull_part(np.vstack([body.vertices, lid.vertices])),
        *(c.translated(np.array([reach / 2, 0, 0])) for c in hparts),
    )
    return fit_to_size(Geometry(parts, collision), v.size)


# --- small foods ---------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class EggShape:
    """Lying on its side (long axis along x) or standing on its broad end; the bottom flattened by this much (m)."""

    lying: bool = True
    flat: float = 0.0015


@builder(EggShape)
def egg(v: Variant, p: EggShape) -> Geometry:
    """A hen's egg: an ellipsoid fuller at one end, its resting side pressed flat a little so it does not roll away."""
    x, y, z = v.size
    radii = (x / 2, y / 2, z / 2)
    mesh = shapes.ellipsoid(radii, (0.0, 0.0, 0.0), 3)
    along = 0 if p.lying else 2
    u = mesh.vertices[:, along] / radii[along]
    taper = 1.0 - 0.12 * u  # the narrow end (+) is slimmer than the broad end (-)
    for k in range(3):
        if k != along:
            mesh.vertices[:, k] *= taper
    mesh.vertices[:, 2] = np.maximum(mesh.vertices[:, 2], mesh.vertices[:, 2].min() + p.flat)
    mesh = trimesh.convex.convex_hull(mesh.vertices)
    return fit_to_size(Geometry(((mesh, v.color(0, P.rgb(240, 230, 215))),), (col.hull_part(mesh),)), v.size)


@dataclass(frozen=True)
class CookieShape:
    """Chocolate chips on top, a sandwich with a cream filling (two discs), or a square cracker with docking holes."""

    chips: int = 0
    sandwich: bool = False
    square: bool = False


@builder(CookieShape)
def cookie(v: Variant, p: CookieShape) -> Geometry:
    """A cookie or biscuit lying flat: a round disc (or square cracker), with chips, or two discs with a filling."""
    x, y, z = v.size
    dough = v.color(0, P.rgb(200, 150, 90))
    if p.square:
        body = shapes.slab(x, y, z, 0.004, (0, 0, z / 2))
        part = col.box_part((x, y, z), (0, 0, z / 2))
    else:
        body = shapes.cylinder(x / 2, z, (0, 0, z / 2), sections=32)
        part = col.cylinder_part(x / 2, z, (0, 0, z / 2))
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(body, dough)]
    if p.sandwich:
        disc_h = 0.38 * z
        top = shapes.cylinder(x / 2, disc_h, (0, 0, z - disc_h / 2), sections=32)
        bottom = shapes.cylinder(x / 2, disc_h, (0, 0, disc_h / 2), sections=32)
        filling = shapes.cylinder(0.45 * x, z - 2 * disc_h + 0.002, (0, 0, z / 2), sections=32)
        parts = [(bottom, dough), (filling, v.color(1, P.WHITE)), (top, dough)]
    rng = np.random.default_rng(len(v.name))
    for _ in range(p.chips):
        a, rr = rng.uniform(0, 2 * np.pi), 0.32 * x * np.sqrt(rng.uniform(0.05, 1.0))
        parts.append(
            (
                shapes.box((0.1 * x, 0.1 * x, 0.4 * z), (rr * np.cos(a), rr * np.sin(a), z - 0.18 * z)),
                v.color(1, P.DARK_BROWN),
            )
        )
    return Geometry(tuple(parts), (part,))


# --- woks, steamers, aprons -----------------------------------------------------------------------------------------


@dataclass(frozen=True)
class WokShape:
    """A small helper handle opposite the long one (the long handle fills the rest of the length)."""

    helper: bool = True


@builder(WokShape)
def wok(v: Variant, p: WokShape) -> Geometry:
    """A wok: a wide flaring bowl on a small flat base (so it stands), a long handle towards +x; an open container."""
    x, y, z = v.size
    r = y / 2
    helper = 0.04 if p.helper else 0.0
    bowl_h = 0.7 * z
    t = np.linspace(0.0, 0.5 * np.pi, 7)
    outer = np.stack([0.5 * r + 0.5 * r * np.sin(t), bowl_h * (1 - np.cos(t))], axis=1)
    vessel = Vessel(outer, 0.003, 0.004, stations=3)
    cx = -x / 2 + helper + r
    bowl = vessel.mesh().apply_translation((cx, 0, 0))
    collision: list[CollisionPart] = [c.translated(np.array([cx, 0, 0])) for c in vessel.collision(16)]
    path = np.array([[cx + 0.95 * r, 0, 0.85 * bowl_h], [x / 2 - 0.011, 0, z - 0.011]])
    path = shapes.resample_polyline(path, 6)
    grip = shapes.tube(path, 0.011, sides=10)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(bowl, v.color(0, P.CHARCOAL)), (grip, v.color(1, P.WOOD))]
    collision += col.tube_parts(path, 0.011, 2)
    if p.helper:
        ear, hparts = loop_handle(
            r - 0.003, bowl_h - 0.004, bowl_h - 0.03, helper + 0.004, 0.006, yaw=np.pi, squareness=0.8
        )
        parts.append((ear.apply_translation((cx, 0, 0)), v.color(1, P.WOOD)))
        collision += [c.translated(np.array([cx, 0, 0])) for c in hparts]
    cavity = vessel.cavity()
    return Geometry(
        tuple(parts), tuple(collision), Cavity(cavity.opening + np.array([cx, 0.0]), cavity.floor_height, cavity.depth)
    )


@dataclass(frozen=True)
class SteamerShape:
    """The number of stacked baskets under the lid."""

    tiers: int = 2


@builder(SteamerShape)
def steamer(v: Variant, p: SteamerShape) -> Geometry:
    """A bamboo steamer: stacked round baskets with woven bands and a domed lid; closed."""
    d, z = v.size[0], v.size[2]
    r = d / 2
    lid_h = 0.3 * z
    tier_h = (z - lid_h) / p.tiers
    color = v.color(0, P.BAMBOO)
    band = v.color(1, P.WOOD)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = []
    for k in range(p.tiers):
        parts.append((shapes.cylinder(r, tier_h + 0.001, (0, 0, k * tier_h + tier_h / 2), sections=48), color))
        parts.append((shapes.cylinder(r + 0.001, 0.2 * tier_h, (0, 0, k * tier_h + 0.5 * tier_h), sections=48), band))
    base = z - lid_h
    lid = shapes.lathe([(0, base - 0.002), (r, base - 0.002), (r, base + 0.4 * lid_h), (0.7 * r, z), (0, z)], 48)
    parts.append((lid, v.color(2, color)))
    return _one_hull(tuple(parts), v.size)


@dataclass(frozen=True)
class ApronShape:
    """A front pocket of the second colour and the neck strap folded on top."""

    pocket: bool = True


@builder(ApronShape)
def apron(v: Variant, p: ApronShape) -> Geometry:
    """A kitchen apron folded flat into a rectangle, with a pocket and the neck strap lying on top."""
    x, y, z = v.size
    body = shapes.rounded_box((x, y, 0.8 * z), 0.3 * z, (0, 0, 0.4 * z))
    color = v.color(0, P.NAVY)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = [(body, color)]
    if p.pocket:
        parts.append(
            (shapes.box((0.4 * x, 0.5 * y, 0.2 * z + 0.001), (0.1 * x, 0, 0.9 * z - 0.0005)), v.color(1, color))
        )
    strap = shapes.box((0.06 * x, 0.9 * y, 0.2 * z), (-0.3 * x, 0, 0.9 * z))
    parts.append((strap, v.color(1, color)))
    return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


CATEGORIES: tuple[CategoryDef, ...] = builtin_categories(__name__, globals())  # variants: data/kitchen.json
