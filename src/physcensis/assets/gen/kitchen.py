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
from physcensis.assets.model import RGBA, Cavity, CollisionPart
from physcensis.assets.spec import CategoryDef, Geometry, NoOptions, Parts, Variant, builder, define
from physcensis.assets.spec import Variant as V


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


SPICE_GLASS = P.rgb(215, 235, 240, 0.55)

CATEGORIES: tuple[CategoryDef, ...] = (
    define(
        "spice jar",
        "spice jar",
        spice_jar,
        [
            V(
                "paprika",
                "a small glass spice jar of red paprika with a red screw lid",
                (0.045, 0.045, 0.1),
                (SPICE_GLASS, P.RED, P.rgb(190, 60, 30)),
                synonyms=("paprika",),
            ),
            V(
                "oregano",
                "a glass spice jar of dried oregano with a green lid",
                (0.045, 0.045, 0.1),
                (SPICE_GLASS, P.DARK_GREEN, P.rgb(110, 120, 50)),
                synonyms=("herb jar", "dried herbs"),
            ),
            V(
                "cinnamon",
                "a tall glass jar of ground cinnamon with a brown lid",
                (0.05, 0.05, 0.115),
                (SPICE_GLASS, P.DARK_BROWN, P.rgb(150, 90, 45)),
                synonyms=("cinnamon",),
            ),
            V(
                "black_pepper",
                "a glass jar of ground black pepper with a black sifter lid",
                (0.045, 0.045, 0.095),
                (SPICE_GLASS, P.BLACK, P.rgb(60, 55, 50)),
                synonyms=("ground pepper",),
            ),
            V(
                "turmeric_square",
                "a square glass spice bottle of yellow turmeric with a white lid",
                (0.045, 0.045, 0.1),
                (SPICE_GLASS, P.WHITE, P.rgb(220, 160, 30)),
                {"square": True},
                synonyms=("spice bottle",),
            ),
            V(
                "chili_square",
                "a square glass spice bottle of chili flakes with a red lid",
                (0.042, 0.042, 0.095),
                (SPICE_GLASS, P.RED, P.rgb(170, 40, 25)),
                {"square": True},
                synonyms=("chili flakes",),
            ),
            V(
                "cumin_short",
                "a short round glass jar of cumin seeds with a silver metal lid",
                (0.055, 0.055, 0.075),
                (SPICE_GLASS, P.SILVER, P.rgb(150, 115, 60)),
                {"lid": 0.25, "sifter": False},
            ),
            V(
                "nutmeg_small",
                "a small glass spice jar of nutmeg with a wooden lid",
                (0.038, 0.038, 0.085),
                (SPICE_GLASS, P.WOOD, P.rgb(160, 110, 70)),
                {"sifter": False},
            ),
        ],
        density=650.0,
        mass_limits=(0.03, 0.4),
        friction=(0.4, 0.7),
        support_probability=0.1,
        has_front=False,
        synonyms=("spice bottle", "spice container", "seasoning jar", "herb jar", "spice shaker", "spices", "spice"),
        tags=("kitchen", "pantry", "seasoning", "condiment", "cooking", "spice rack", "herbs", "glass"),
    ),
    define(
        "salt shaker",
        "salt shaker",
        salt_shaker,
        [
            V("glass_salt", "a clear glass salt shaker with a silver cap", (0.04, 0.04, 0.09), (P.GLASS, P.SILVER)),
            V(
                "glass_pepper",
                "a glass pepper shaker filled with black pepper and a steel cap",
                (0.04, 0.04, 0.09),
                (P.rgb(70, 65, 60, 0.9), P.STEEL),
                synonyms=("pepper shaker", "pepper pot"),
            ),
            V(
                "white_ceramic",
                "a white ceramic salt shaker with a white cap",
                (0.045, 0.045, 0.08),
                (P.WHITE, P.WHITE),
                {"waist": 0.7},
                density=1500.0,
            ),
            V(
                "black_ceramic",
                "a black ceramic pepper shaker",
                (0.045, 0.045, 0.08),
                (P.BLACK, P.CHARCOAL),
                {"waist": 0.7},
                density=1500.0,
                synonyms=("pepper shaker",),
            ),
            V(
                "mini_glass",
                "a small glass salt cellar shaker with a chrome top",
                (0.032, 0.032, 0.065),
                (P.GLASS, P.SILVER),
                synonyms=("salt cellar",),
            ),
            V(
                "tall_diner",
                "a tall glass diner-style salt shaker with a steel top",
                (0.05, 0.05, 0.12),
                (P.GLASS, P.STEEL),
                {"waist": 0.9, "cap": 0.25},
            ),
            V("red_ceramic", "a red ceramic salt shaker", (0.042, 0.042, 0.085), (P.RED, P.WHITE), density=1500.0),
            V(
                "wooden",
                "a wooden salt shaker with a wooden cap",
                (0.045, 0.045, 0.095),
                (P.WOOD, P.DARK_BROWN),
                {"waist": 0.85},
                density=700.0,
            ),
        ],
        density=1100.0,
        mass_limits=(0.02, 0.3),
        friction=(0.4, 0.7),
        support_probability=0.1,
        has_front=False,
        synonyms=(
            "salt cellar",
            "pepper shaker",
            "salt and pepper shaker",
            "shaker",
            "cruet",
            "salt",
            "salt pot",
            "saltshaker",
        ),
        tags=("kitchen", "dining", "table", "condiment", "seasoning", "salt", "pepper"),
    ),
    define(
        "pepper mill",
        "pepper mill",
        pepper_mill,
        [
            V("wood", "a turned wooden pepper mill with a steel knob", (0.055, 0.055, 0.2)),
            V("tall_wood", "a tall dark wooden pepper grinder", (0.06, 0.06, 0.3), (P.DARK_BROWN, P.SILVER)),
            V("black", "a black acrylic pepper grinder", (0.055, 0.055, 0.18), (P.BLACK, P.SILVER), density=900.0),
            V(
                "steel",
                "a brushed stainless steel pepper mill",
                (0.05, 0.05, 0.19),
                (P.STEEL, P.CHARCOAL),
                density=1200.0,
            ),
            V(
                "salt_white",
                "a white salt mill with a chrome top",
                (0.055, 0.055, 0.18),
                (P.WHITE, P.SILVER),
                density=900.0,
                synonyms=("salt mill", "salt grinder"),
            ),
            V(
                "small_wood",
                "a small light wooden spice grinder",
                (0.05, 0.05, 0.13),
                (P.LIGHT_WOOD, P.SILVER),
                synonyms=("spice grinder",),
            ),
            V(
                "clear_acrylic",
                "a clear acrylic pepper mill full of peppercorns",
                (0.058, 0.058, 0.21),
                (P.rgb(90, 70, 55, 0.8), P.SILVER),
                {"waist": 0.85},
                density=900.0,
            ),
        ],
        density=650.0,
        mass_limits=(0.08, 0.8),
        friction=(0.4, 0.7),
        support_probability=0.05,
        has_front=False,
        synonyms=("pepper grinder", "salt mill", "spice grinder", "grinder", "peppermill", "pepper"),
        tags=("kitchen", "dining", "table", "condiment", "seasoning", "peppercorns", "grind"),
    ),
    define(
        "kettle",
        "kettle",
        kettle,
        [
            V(
                "electric_steel",
                "a stainless steel electric kettle on its black power base",
                (0.24, 0.16, 0.25),
                synonyms=("electric kettle",),
            ),
            V(
                "electric_white",
                "a white plastic electric kettle",
                (0.23, 0.15, 0.24),
                (P.WHITE, P.GREY),
                synonyms=("electric kettle",),
            ),
            V(
                "electric_black",
                "a black electric water kettle",
                (0.24, 0.16, 0.25),
                (P.BLACK, P.CHARCOAL),
                synonyms=("electric kettle",),
            ),
            V(
                "electric_red",
                "a red retro electric kettle",
                (0.23, 0.16, 0.24),
                (P.RED, P.SILVER),
                synonyms=("electric kettle",),
            ),
            V(
                "electric_small",
                "a small cream travel kettle",
                (0.18, 0.12, 0.18),
                (P.CREAM, P.CHARCOAL),
                synonyms=("travel kettle",),
            ),
            V(
                "stovetop_red",
                "a red enamel stovetop kettle with a curved spout and a black handle",
                (0.28, 0.2, 0.24),
                options={"electric": False},
                synonyms=("stovetop kettle", "whistling kettle"),
            ),
            V(
                "stovetop_steel",
                "a stainless steel whistling kettle for the stove",
                (0.27, 0.19, 0.23),
                (P.STEEL, P.BLACK),
                {"electric": False},
                synonyms=("stovetop kettle", "whistling kettle"),
            ),
            V(
                "stovetop_blue",
                "a blue enamel kettle for the hob",
                (0.26, 0.18, 0.22),
                (P.BLUE, P.BLACK),
                {"electric": False},
                synonyms=("stovetop kettle", "tea kettle"),
            ),
        ],
        density=280.0,
        mass_limits=(0.4, 2.5),
        friction=(0.4, 0.7),
        support_probability=0.05,
        synonyms=("tea kettle", "water kettle", "electric kettle", "boiler", "water boiler"),
        tags=("kitchen", "appliance", "boil", "water", "tea", "hot"),
    ),
    define(
        "toaster",
        "toaster",
        toaster,
        [
            V("steel_2slot", "a brushed steel two-slot pop-up toaster", (0.17, 0.28, 0.19)),
            V("white_2slot", "a white plastic two-slice toaster", (0.16, 0.26, 0.18), (P.WHITE, P.GREY)),
            V("black_2slot", "a black two-slice toaster", (0.17, 0.27, 0.19), (P.BLACK, P.SILVER)),
            V(
                "red_retro",
                "a red retro toaster with rounded corners",
                (0.18, 0.3, 0.2),
                (P.RED, P.SILVER),
                {"radius": 0.05},
            ),
            V(
                "steel_4slot",
                "a wide stainless steel four-slot toaster",
                (0.3, 0.3, 0.2),
                (P.STEEL, P.BLACK),
                {"slots": 4},
                mass=2.4,
                synonyms=("four-slice toaster", "four slice toaster", "4-slice toaster"),
            ),
            V(
                "cream_retro",
                "a cream retro two-slot toaster",
                (0.18, 0.29, 0.2),
                (P.CREAM, P.SILVER),
                {"radius": 0.05},
            ),
            V(
                "copper_long",
                "a copper long-slot toaster",
                (0.2, 0.42, 0.2),
                (P.rgb(190, 110, 60), P.BLACK),
                {"radius": 0.03},
                mass=2.2,
            ),
        ],
        density=190.0,
        mass_limits=(0.8, 3.5),
        friction=(0.5, 0.8),
        support_probability=0.1,
        synonyms=("pop-up toaster", "bread toaster", "two-slice toaster", "slice toaster"),
        tags=("kitchen", "appliance", "breakfast", "toast", "bread", "counter"),
    ),
    define(
        "colander",
        "colander",
        colander,
        [
            V("steel", "a stainless steel colander with two grips", (0.24, 0.31, 0.11)),
            V("steel_large", "a large perforated steel colander", (0.3, 0.37, 0.13), (P.STEEL, P.CHARCOAL)),
            V(
                "red_plastic",
                "a red plastic colander with grips",
                (0.24, 0.31, 0.11),
                (P.RED, P.DARK_RED),
                density=450.0,
            ),
            V(
                "white_plastic",
                "a white plastic pasta strainer",
                (0.22, 0.29, 0.1),
                (P.WHITE, P.GREY),
                density=450.0,
                synonyms=("pasta strainer",),
            ),
            V(
                "green_small",
                "a small green plastic colander for berries",
                (0.16, 0.16, 0.08),
                (P.LIME, P.DARK_GREEN),
                {"grips": False},
                density=450.0,
                synonyms=("berry colander",),
            ),
            V(
                "enamel_blue",
                "a blue enamel colander on a ring foot",
                (0.26, 0.33, 0.12),
                (P.BLUE, P.NAVY),
                {"foot": 0.018},
            ),
            V(
                "steel_round",
                "a round steel strainer bowl without handles",
                (0.22, 0.22, 0.1),
                (P.SILVER, P.CHARCOAL),
                {"grips": False},
            ),
        ],
        density=900.0,
        mass_limits=(0.08, 1.2),
        friction=(0.4, 0.7),
        support_probability=0.3,
        has_front=False,
        synonyms=("strainer", "pasta strainer", "sieve", "drainer", "colander bowl"),
        tags=("kitchen", "cooking", "draining", "pasta", "washing", "vegetables", "container", "perforated"),
    ),
    define(
        "rolling pin",
        "rolling pin",
        rolling_pin,
        [
            V("wood_handles", "a wooden rolling pin with two handles", (0.06, 0.45, 0.06)),
            V(
                "french",
                "a tapered French rolling pin of beech wood",
                (0.05, 0.5, 0.05),
                (P.LIGHT_WOOD,),
                {"handles": 0.0, "tapered": True},
                synonyms=("french rolling pin",),
            ),
            V("straight", "a straight wooden dowel rolling pin", (0.045, 0.45, 0.045), (P.BAMBOO,), {"handles": 0.0}),
            V(
                "marble",
                "a white marble rolling pin with wooden handles",
                (0.065, 0.44, 0.065),
                (P.WHITE, P.WOOD),
                density=2000.0,
                synonyms=("marble rolling pin",),
            ),
            V("dark_wood", "a dark walnut rolling pin with handles", (0.06, 0.42, 0.06), (P.DARK_BROWN, P.DARK_BROWN)),
            V(
                "silicone_red",
                "a red silicone rolling pin with black handles",
                (0.055, 0.43, 0.055),
                (P.RED, P.BLACK),
                density=900.0,
            ),
            V(
                "small_kids",
                "a small wooden rolling pin for pastry",
                (0.035, 0.25, 0.035),
                (P.LIGHT_WOOD, P.WOOD),
                {"handles": 0.22},
            ),
        ],
        density=650.0,
        mass_limits=(0.05, 3.0),
        friction=(0.4, 0.7),
        support_probability=0.05,
        has_front=False,
        synonyms=("pastry roller", "dough roller", "rolling-pin", "roller"),
        tags=("kitchen", "baking", "dough", "pastry", "wood", "cylinder"),
    ),
    define(
        "dish rack",
        "dish rack",
        dish_rack,
        [
            V("chrome", "a chrome wire dish drying rack on a white drip tray", (0.45, 0.35, 0.15)),
            V("black", "a black wire dish rack with a drip tray", (0.42, 0.32, 0.14), (P.BLACK, P.CHARCOAL)),
            V(
                "white",
                "a white coated wire dish drainer",
                (0.44, 0.34, 0.14),
                (P.WHITE, P.GREY),
                synonyms=("dish drainer",),
            ),
            V(
                "small",
                "a small steel dish rack without a tray",
                (0.32, 0.25, 0.12),
                (P.STEEL,),
                {"tray": False, "tines": 6},
            ),
            V(
                "large",
                "a large stainless steel drying rack for dishes and pots",
                (0.55, 0.4, 0.17),
                (P.STEEL, P.CHARCOAL),
                {"tines": 10},
            ),
            V("bamboo", "a bamboo dish rack", (0.45, 0.3, 0.13), (P.BAMBOO, P.BAMBOO), {"wire": 0.008}),
            V("grey", "a grey plastic-coated dish drying rack", (0.4, 0.3, 0.14), (P.GREY, P.WHITE)),
        ],
        density=800.0,
        mass_limits=(0.3, 3.5),
        friction=(0.4, 0.7),
        support_probability=0.2,
        has_front=False,
        synonyms=("dish drainer", "drying rack", "dish drying rack", "plate rack", "drainer", "dish rack"),
        tags=("kitchen", "sink", "washing up", "drying", "dishes", "plates", "container", "wire"),
    ),
    define(
        "crate",
        "crate",
        crate,
        [
            V("wooden_fruit", "a slatted wooden fruit crate", (0.5, 0.3, 0.25), synonyms=("fruit crate",)),
            V("wooden_small", "a small wooden crate of light pine slats", (0.35, 0.25, 0.18), synonyms=("wooden box",)),
            V(
                "wooden_dark",
                "a dark stained wooden storage crate",
                (0.45, 0.32, 0.24),
                (P.WOOD, P.DARK_BROWN),
                {"slats": 4, "gap": 0.08},
            ),
            V(
                "plastic_green",
                "a green plastic vegetable crate",
                (0.4, 0.3, 0.22),
                (P.GREEN, P.DARK_GREEN),
                {"plastic": True},
                density=500.0,
                synonyms=("vegetable crate", "produce crate"),
            ),
            V(
                "plastic_blue",
                "a blue plastic stacking crate",
                (0.4, 0.3, 0.25),
                (P.BLUE, P.NAVY),
                {"plastic": True},
                density=500.0,
                synonyms=("stacking crate",),
            ),
            V(
                "milk_crate",
                "a red plastic milk crate",
                (0.33, 0.33, 0.28),
                (P.RED, P.DARK_RED),
                {"plastic": True},
                density=500.0,
                synonyms=("milk crate",),
            ),
            V(
                "apple_crate",
                "a wooden apple crate with two wide slats per side",
                (0.5, 0.32, 0.3),
                (P.rgb(200, 160, 110), P.WOOD),
                {"slats": 2, "gap": 0.2},
                synonyms=("apple crate",),
            ),
        ],
        density=450.0,
        mass_limits=(0.4, 6.0),
        friction=(0.5, 0.8),
        support_probability=0.7,
        has_front=False,
        synonyms=("fruit crate", "wooden crate", "produce crate", "vegetable crate", "plastic crate", "crates"),
        tags=("kitchen", "storage", "fruit", "vegetables", "market", "container", "slats", "open"),
    ),
    define(
        "measuring cup",
        "measuring cup",
        measuring_cup,
        [
            V(
                "glass_500",
                "a clear glass measuring jug with red markings and a handle",
                (0.09, 0.13, 0.11),
                synonyms=("measuring jug",),
            ),
            V(
                "glass_1l",
                "a large glass measuring jug for one litre",
                (0.115, 0.165, 0.15),
                synonyms=("measuring jug",),
            ),
            V(
                "plastic_clear",
                "a clear plastic measuring cup with blue markings",
                (0.09, 0.13, 0.1),
                (P.rgb(220, 235, 245, 0.5), P.BLUE),
                density=700.0,
            ),
            V(
                "steel_cup",
                "a stainless steel measuring cup with a flat handle",
                (0.08, 0.2, 0.05),
                options={"jug": False},
                density=1500.0,
            ),
            V(
                "steel_half",
                "a small steel half-cup measure with a long handle",
                (0.07, 0.17, 0.04),
                options={"jug": False},
                density=1500.0,
            ),
            V(
                "red_plastic",
                "a red plastic measuring cup with a handle",
                (0.08, 0.18, 0.05),
                (P.RED, P.WHITE),
                {"jug": False},
                density=700.0,
            ),
            V(
                "copper",
                "a copper measuring cup with a handle",
                (0.085, 0.2, 0.055),
                (P.rgb(190, 110, 60), P.BLACK),
                {"jug": False},
                density=1500.0,
            ),
        ],
        density=1300.0,
        mass_limits=(0.02, 0.9),
        friction=(0.4, 0.7),
        support_probability=0.05,
        synonyms=("measuring jug", "measuring cups", "measure", "cup measure", "jug with markings"),
        tags=("kitchen", "baking", "cooking", "measuring", "graduated", "container"),
    ),
    define(
        "egg cup",
        "egg cup",
        egg_cup,
        [
            V("white", "a white porcelain egg cup on a short stem", (0.05, 0.05, 0.06)),
            V("yellow", "a yellow ceramic egg cup", (0.05, 0.05, 0.06), (P.YELLOW,)),
            V("blue", "a blue ceramic egg cup", (0.05, 0.05, 0.058), (P.SKY,)),
            V("wooden", "a wooden egg cup", (0.048, 0.048, 0.055), (P.LIGHT_WOOD,), density=700.0),
            V("steel", "a stainless steel egg cup", (0.048, 0.048, 0.06), (P.STEEL,), density=2500.0),
            V(
                "red",
                "a red ceramic egg cup on a wide foot",
                (0.05, 0.05, 0.055),
                (P.RED,),
                {"foot": 1.0, "stem": 0.25},
            ),
            V("tall_white", "a tall white egg cup on a slender stem", (0.048, 0.048, 0.07), options={"stem": 0.4}),
        ],
        density=2000.0,
        mass_limits=(0.01, 0.15),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("egg holder", "eggcup", "boiled egg cup", "egg stand"),
        tags=("breakfast", "dining", "table", "egg", "boiled egg", "ceramic", "container"),
    ),
    define(
        "milk carton",
        "milk carton",
        milk_carton,
        [
            V("litre_white", "a one-litre white milk carton with a blue label and a gable top", (0.07, 0.07, 0.24)),
            V(
                "half_gallon",
                "a half-gallon milk carton with a red label",
                (0.095, 0.095, 0.26),
                (P.WHITE, P.RED, P.RED),
            ),
            V("pint", "a small pint carton of milk", (0.058, 0.058, 0.15), (P.WHITE, P.SKY, P.WHITE)),
            V(
                "orange_juice",
                "a one-litre carton of orange juice",
                (0.07, 0.07, 0.24),
                (P.ORANGE, P.YELLOW, P.GREEN),
                synonyms=("juice carton", "orange juice"),
            ),
            V(
                "juice_brick",
                "a flat-topped one-litre juice carton",
                (0.06, 0.095, 0.195),
                (P.YELLOW, P.ORANGE),
                {"gable": False},
                synonyms=("juice carton", "tetra pak"),
            ),
            V(
                "juice_box",
                "a small juice box for a child's lunch",
                (0.04, 0.063, 0.105),
                (P.LIME, P.PURPLE),
                {"gable": False},
                synonyms=("juice box", "drink box"),
            ),
            V(
                "oat_milk",
                "a brick carton of oat milk",
                (0.065, 0.095, 0.2),
                (P.CREAM, P.BROWN),
                {"gable": False},
                synonyms=("oat milk", "plant milk"),
            ),
            V(
                "cream",
                "a small carton of cream with a gable top",
                (0.055, 0.055, 0.12),
                (P.WHITE, P.YELLOW, P.WHITE),
                synonyms=("cream carton",),
            ),
        ],
        density=1000.0,
        mass_limits=(0.1, 2.4),
        friction=(0.4, 0.7),
        support_probability=0.05,
        synonyms=("carton of milk", "milk", "juice carton", "carton of juice", "milk box", "drink carton"),
        tags=("kitchen", "fridge", "breakfast", "dairy", "drink", "paperboard"),
    ),
    define(
        "egg carton",
        "egg carton",
        egg_carton,
        [
            V("dozen_closed", "a closed grey pulp egg carton for a dozen eggs", (0.105, 0.3, 0.07)),
            V("half_dozen", "a closed carton of six eggs", (0.105, 0.155, 0.07), options={"per_row": 3}),
            V(
                "dozen_open",
                "an open egg carton showing twelve brown eggs",
                (0.105, 0.3, 0.07),
                (P.rgb(200, 190, 170), P.rgb(200, 150, 100)),
                {"open": True},
            ),
            V(
                "six_open",
                "an open tray of six white eggs",
                (0.105, 0.155, 0.07),
                (P.rgb(200, 190, 170), P.WHITE),
                {"per_row": 3, "open": True},
                synonyms=("egg tray",),
            ),
            V(
                "dozen_open_empty",
                "an open empty pulp egg carton with its lid off",
                (0.105, 0.3, 0.04),
                options={"empty": True},
                synonyms=("open egg carton", "empty egg carton", "egg tray", "egg box"),
            ),
            V(
                "six_open_empty",
                "a small open empty egg carton with its lid off",
                (0.105, 0.155, 0.045),
                options={"per_row": 3, "empty": True},
                synonyms=("open egg carton", "empty egg carton", "egg tray"),
            ),
            V("blue_dozen", "a blue plastic egg box for twelve eggs", (0.11, 0.31, 0.075), (P.SKY, P.WHITE)),
            V("yellow_six", "a yellow egg box for six eggs", (0.105, 0.155, 0.07), (P.YELLOW, P.WHITE), {"per_row": 3}),
            V(
                "eighteen",
                "a large closed carton of eighteen eggs",
                (0.16, 0.3, 0.07),
                (P.rgb(200, 190, 170), P.WHITE),
                mass=1.1,
            ),
        ],
        density=330.0,
        mass_limits=(0.03, 1.4),  # an empty open tray weighs a few tens of grams
        friction=(0.5, 0.8),
        support_probability=0.3,
        has_front=False,
        synonyms=("egg box", "carton of eggs", "box of eggs", "dozen eggs", "egg tray"),
        tags=("kitchen", "fridge", "breakfast", "eggs", "pulp", "cardboard"),
    ),
    define(
        "place mat",
        "place mat",
        place_mat,
        [
            V("bamboo", "a woven bamboo place mat", (0.45, 0.3, 0.004), (P.BAMBOO, P.WOOD), {"woven": True}),
            V("grey_felt", "a grey felt placemat", (0.44, 0.32, 0.004), (P.GREY,), density=250.0),
            V("white_linen", "a white linen place mat", (0.45, 0.33, 0.003), (P.WHITE,)),
            V("red_plastic", "a red wipe-clean plastic placemat", (0.43, 0.29, 0.003), (P.RED,), density=1000.0),
            V(
                "round_rattan",
                "a round woven rattan place mat",
                (0.38, 0.38, 0.005),
                (P.LIGHT_WOOD, P.WOOD),
                {"round": True, "woven": True},
            ),
            V("oval_navy", "an oval navy blue table mat", (0.45, 0.32, 0.003), (P.NAVY,), {"round": True}),
            V(
                "brown_leather",
                "a brown faux leather place mat with rounded corners",
                (0.4, 0.3, 0.004),
                (P.rgb(120, 80, 50),),
                {"radius": 0.03},
            ),
            V(
                "green_striped",
                "a green striped cotton placemat",
                (0.45, 0.3, 0.003),
                (P.GREEN, P.WHITE),
                {"woven": True},
            ),
        ],
        density=350.0,
        mass_limits=(0.01, 0.6),
        friction=(0.6, 0.9),
        support_probability=0.95,
        has_front=False,
        synonyms=("placemat", "table mat", "dining mat", "place setting mat", "mat"),
        tags=("dining", "table", "flat", "place setting", "fabric", "woven"),
    ),
    define(
        "coaster",
        "coaster",
        coaster,
        [
            V("cork_round", "a round cork drink coaster", (0.1, 0.1, 0.005)),
            V(
                "wood_round",
                "a round wooden coaster with a cork inset",
                (0.1, 0.1, 0.008),
                (P.WOOD, P.rgb(195, 160, 115)),
                {"inset": True},
                density=650.0,
            ),
            V(
                "slate_square",
                "a square black slate coaster",
                (0.1, 0.1, 0.006),
                (P.CHARCOAL, P.BLACK),
                {"round": False},
                density=2700.0,
            ),
            V(
                "ceramic_white",
                "a square white ceramic coaster",
                (0.1, 0.1, 0.007),
                (P.WHITE, P.rgb(195, 160, 115)),
                {"round": False, "inset": False},
                density=2000.0,
            ),
            V("felt_grey", "a round grey felt coaster", (0.095, 0.095, 0.004), (P.GREY,), density=300.0),
            V(
                "bamboo_square",
                "a square bamboo coaster",
                (0.1, 0.1, 0.008),
                (P.BAMBOO,),
                {"round": False},
                density=650.0,
            ),
            V(
                "marble_round",
                "a round white marble coaster",
                (0.1, 0.1, 0.008),
                (P.rgb(230, 230, 228),),
                density=2600.0,
            ),
            V(
                "silicone_blue",
                "a blue silicone cup coaster",
                (0.09, 0.09, 0.005),
                (P.SKY, P.BLUE),
                {"inset": True},
                density=1100.0,
            ),
        ],
        density=250.0,
        mass_limits=(0.003, 0.25),
        friction=(0.5, 0.9),
        support_probability=0.9,
        has_front=False,
        synonyms=(
            "drink coaster",
            "cup coaster",
            "beer mat",
            "coasters",
            "mug mat",
            "glass mat",
            "drink mat",
            "cork mat",
        ),
        tags=("dining", "table", "drinks", "flat", "cork", "living room"),
    ),
    define(
        "oven mitt",
        "oven mitt",
        oven_mitt,
        [
            V("red", "a red quilted oven mitt with a white cuff", (0.32, 0.18, 0.03)),
            V(
                "grey",
                "a grey silicone oven glove",
                (0.3, 0.17, 0.03),
                (P.GREY, P.CHARCOAL),
                density=250.0,
                synonyms=("oven glove",),
            ),
            V("blue_check", "a blue oven mitt with a navy cuff", (0.32, 0.18, 0.03), (P.SKY, P.NAVY)),
            V(
                "black",
                "a black heat-resistant oven glove",
                (0.34, 0.19, 0.032),
                (P.BLACK, P.CHARCOAL),
                synonyms=("oven glove",),
            ),
            V(
                "pot_holder_red",
                "a square red quilted pot holder",
                (0.2, 0.2, 0.015),
                (P.RED, P.WHITE),
                {"style": "pad"},
                synonyms=("pot holder", "potholder"),
            ),
            V(
                "pot_holder_green",
                "a square green pot holder pad",
                (0.19, 0.19, 0.015),
                (P.GREEN, P.CREAM),
                {"style": "pad"},
                synonyms=("pot holder", "potholder"),
            ),
            V("cream", "a cream cotton oven mitt with a red cuff", (0.3, 0.17, 0.028), (P.CREAM, P.RED)),
        ],
        density=130.0,
        mass_limits=(0.03, 0.4),
        friction=(0.7, 1.0),
        support_probability=0.3,
        has_front=False,
        synonyms=("oven glove", "oven mitten", "pot holder", "potholder", "kitchen glove", "mitt"),
        tags=("kitchen", "cooking", "baking", "hot", "fabric", "quilted", "soft"),
    ),
    define(
        "sponge",
        "sponge",
        sponge,
        [
            V("yellow_green", "a yellow kitchen sponge with a green scouring pad", (0.11, 0.07, 0.035)),
            V("pink_grey", "a pink sponge with a grey scourer", (0.11, 0.07, 0.035), (P.PINK, P.GREY)),
            V("blue", "a blue non-scratch dish sponge", (0.1, 0.065, 0.03), (P.SKY, P.BLUE)),
            V("plain_yellow", "a plain yellow cellulose sponge", (0.12, 0.08, 0.04), (P.YELLOW,), {"scourer": 0.0}),
            V(
                "large_car",
                "a large yellow cleaning sponge",
                (0.16, 0.1, 0.05),
                (P.YELLOW,),
                {"scourer": 0.0, "radius": 0.012},
            ),
            V(
                "green_scrub",
                "a thin green scrub pad",
                (0.1, 0.07, 0.012),
                (P.GREEN, P.DARK_GREEN),
                {"scourer": 0.5},
                density=120.0,
                synonyms=("scouring pad", "scrubber"),
            ),
            V(
                "orange_round",
                "an orange sponge with rounded edges",
                (0.1, 0.07, 0.035),
                (P.ORANGE, P.DARK_GREEN),
                {"radius": 0.012},
            ),
        ],
        density=50.0,
        mass_limits=(0.003, 0.06),
        friction=(0.7, 1.0),
        support_probability=0.2,
        has_front=False,
        synonyms=("dish sponge", "kitchen sponge", "scourer", "scrubber", "scouring pad", "cleaning sponge"),
        tags=("kitchen", "sink", "cleaning", "washing up", "soft", "foam", "bathroom"),
    ),
    define(
        "butter dish",
        "butter dish",
        butter_dish,
        [
            V("white", "a white porcelain butter dish with a cover", (0.2, 0.12, 0.08)),
            V("glass", "a glass butter dish with a clear cover", (0.19, 0.11, 0.075), (P.GLASS, P.GLASS)),
            V("cream", "a cream stoneware covered butter dish", (0.2, 0.13, 0.085), (P.CREAM, P.CREAM, P.BROWN)),
            V(
                "steel",
                "a stainless steel butter dish with a knob",
                (0.2, 0.12, 0.085),
                (P.STEEL, P.SILVER),
                density=700.0,
            ),
            V(
                "wood_glass",
                "a wooden butter tray with a glass dome lid",
                (0.21, 0.12, 0.08),
                (P.WOOD, P.GLASS),
                {"knob": False},
            ),
            V("blue", "a blue enamel butter dish", (0.18, 0.11, 0.07), (P.BLUE, P.BLUE, P.WHITE)),
            V(
                "small_white",
                "a small white ceramic butter keeper",
                (0.15, 0.1, 0.07),
                (P.WHITE,),
                {"knob": False},
                synonyms=("butter keeper",),
            ),
        ],
        density=400.0,
        mass_limits=(0.1, 1.2),
        friction=(0.4, 0.7),
        support_probability=0.1,
        synonyms=("butter tray", "butter keeper", "covered butter dish", "butter"),
        tags=("dining", "table", "breakfast", "dairy", "ceramic", "lidded"),
    ),
    define(
        "sugar bowl",
        "sugar bowl",
        sugar_bowl,
        [
            V("white", "a white porcelain sugar bowl with a lid and two handles", (0.09, 0.13, 0.1)),
            V("blue", "a blue ceramic sugar bowl with a lid", (0.09, 0.13, 0.1), (P.SKY,)),
            V("steel", "a stainless steel sugar bowl with lid", (0.085, 0.12, 0.095), (P.STEEL,), density=900.0),
            V(
                "glass",
                "a glass sugar pot with a lid",
                (0.09, 0.09, 0.1),
                (P.GLASS, P.SILVER),
                {"handles": False},
                synonyms=("sugar pot",),
            ),
            V("green", "a green stoneware sugar bowl", (0.1, 0.14, 0.1), (P.rgb(120, 160, 110),)),
            V("cream_small", "a small cream sugar bowl for the tea set", (0.08, 0.11, 0.085), (P.CREAM, P.CREAM)),
            V(
                "black",
                "a black ceramic sugar canister with a lid",
                (0.09, 0.09, 0.11),
                (P.BLACK,),
                {"handles": False},
                synonyms=("sugar canister",),
            ),
        ],
        density=750.0,
        mass_limits=(0.08, 0.6),
        friction=(0.4, 0.7),
        support_probability=0.05,
        has_front=False,
        synonyms=("sugar pot", "sugar dish", "sugar basin", "sugar canister", "sugar", "lidded sugar bowl"),
        tags=("dining", "table", "tea", "coffee", "tea set", "ceramic", "lidded"),
    ),
    define(
        "food container",
        "food container",
        food_container,
        [
            V("clear_blue", "a clear plastic food container with a blue snap lid", (0.18, 0.13, 0.07)),
            V(
                "open_clear",
                "an open empty plastic food container with its lid off",
                (0.18, 0.13, 0.07),
                options={"open": True},
                mass=0.08,
                synonyms=("open food container", "open tub", "open container", "empty container", "tupperware"),
            ),
            V(
                "open_lunch_box",
                "an open blue lunch box with its lid off",
                (0.2, 0.14, 0.065),
                (P.rgb(90, 140, 210),),
                {"open": True},
                mass=0.08,
                synonyms=("open lunch box", "lunch box", "lunchbox", "open lunchbox"),
            ),
            V(
                "clear_green",
                "a small plastic storage container with a green lid",
                (0.13, 0.1, 0.06),
                (P.rgb(235, 240, 245, 0.6), P.GREEN),
            ),
            V(
                "glass_clips",
                "a glass food storage box with a clip-lock lid",
                (0.22, 0.16, 0.08),
                (P.GLASS, P.GREY),
                {"clips": True},
                density=450.0,
                synonyms=("glass container",),
            ),
            V(
                "round_red",
                "a round plastic container with a red lid",
                (0.13, 0.13, 0.07),
                (P.rgb(235, 240, 245, 0.6), P.RED),
                {"round": True},
                synonyms=("deli container",),
            ),
            V(
                "lunch_box",
                "a blue plastic lunch box",
                (0.2, 0.14, 0.065),
                (P.SKY, P.BLUE),
                {"taper": 0.97},
                synonyms=("lunch box", "lunchbox"),
            ),
            V(
                "bento",
                "a black bento box with a red lid",
                (0.19, 0.12, 0.06),
                (P.BLACK, P.RED),
                {"taper": 0.98},
                synonyms=("bento box",),
            ),
            V(
                "tall_white",
                "a tall white plastic food tub with a lid",
                (0.12, 0.12, 0.12),
                (P.WHITE, P.WHITE),
                {"round": True, "taper": 0.88},
                synonyms=("tub",),
            ),
            V(
                "meal_prep",
                "a black meal prep container with a clear lid",
                (0.2, 0.15, 0.05),
                (P.BLACK, P.rgb(235, 240, 245, 0.6)),
                synonyms=("meal prep container",),
            ),
        ],
        density=160.0,
        mass_limits=(0.03, 1.5),
        friction=(0.4, 0.7),
        support_probability=0.5,
        synonyms=(
            "tupperware",
            "storage container",
            "plastic container",
            "lunch box",
            "leftovers container",
            "food storage box",
            "lidded box",
            "container",
            "food box",
        ),
        tags=("kitchen", "fridge", "leftovers", "lunch", "storage", "plastic", "lidded"),
    ),
    define(
        "bread box",
        "bread box",
        bread_box,
        [
            V("wood", "a wooden bread box with a roll-top front", (0.25, 0.4, 0.2)),
            V("white_metal", "a white metal bread bin", (0.24, 0.38, 0.2), (P.WHITE, P.SILVER), density=160.0),
            V(
                "steel",
                "a stainless steel bread box with a window",
                (0.25, 0.4, 0.22),
                (P.STEEL, P.BLACK),
                {"window": True},
                density=160.0,
            ),
            V("cream_retro", "a cream retro bread bin", (0.24, 0.36, 0.21), (P.CREAM, P.SILVER), density=160.0),
            V("bamboo", "a bamboo bread box", (0.26, 0.4, 0.2), (P.BAMBOO, P.WOOD), {"roll": 0.45}),
            V("red_enamel", "a red enamel bread bin", (0.24, 0.36, 0.2), (P.RED, P.SILVER), density=160.0),
            V(
                "small_black",
                "a small black bread keeper",
                (0.2, 0.32, 0.16),
                (P.BLACK, P.SILVER),
                density=160.0,
                synonyms=("bread keeper",),
            ),
        ],
        density=120.0,
        mass_limits=(0.5, 4.0),
        friction=(0.4, 0.7),
        support_probability=0.6,
        synonyms=("bread bin", "bread keeper", "breadbox", "bread container", "bread storage", "loaf bin", "breadbin"),
        tags=("kitchen", "counter", "bread", "loaf", "keep fresh", "storage", "roll-top", "bin", "metal"),
    ),
    define(
        "cake stand",
        "cake stand",
        cake_stand,
        [
            V("white", "a white porcelain cake stand on a pedestal", (0.28, 0.28, 0.12)),
            V("glass", "a clear glass cake stand", (0.3, 0.3, 0.13), (P.GLASS, P.GLASS)),
            V("tall_white", "a tall white ceramic cake stand", (0.26, 0.26, 0.17), options={"stem": 0.82}),
            V("wood", "a wooden cake stand", (0.3, 0.3, 0.11), (P.WOOD,), density=650.0),
            V("pink", "a pink ceramic cupcake stand", (0.22, 0.22, 0.1), (P.PINK,), synonyms=("cupcake stand",)),
            V("silver", "a silver metal cake stand", (0.28, 0.28, 0.12), (P.SILVER,), {"foot": 0.45}),
            V("low_cream", "a low cream pedestal plate for cakes", (0.3, 0.3, 0.08), (P.CREAM,), {"stem": 0.7}),
        ],
        density=1400.0,
        mass_limits=(0.3, 3.0),
        friction=(0.4, 0.7),
        support_probability=0.95,
        has_front=False,
        synonyms=("cake plate", "pedestal plate", "cupcake stand", "dessert stand", "cake stand"),
        tags=("dining", "baking", "dessert", "cake", "party", "flat top"),
    ),
    define(
        "french press",
        "french press",
        french_press,
        [
            V("steel", "a glass French press coffee maker in a steel frame", (0.1, 0.15, 0.21)),
            V("black", "a glass French press with a black frame", (0.1, 0.15, 0.2), (P.GLASS, P.BLACK, P.BLACK)),
            V(
                "small",
                "a small two-cup French press",
                (0.08, 0.12, 0.16),
                (P.GLASS, P.STEEL, P.BLACK),
                {"coffee": 0.4},
            ),
            V(
                "large_copper",
                "a large French press with a copper frame",
                (0.12, 0.18, 0.24),
                (P.GLASS, P.rgb(190, 110, 60), P.BLACK),
            ),
            V("empty", "an empty glass coffee press", (0.1, 0.15, 0.21), options={"coffee": 0.0}),
            V(
                "red",
                "a red French press for tea",
                (0.1, 0.15, 0.2),
                (P.GLASS, P.RED, P.RED),
                {"coffee": 0.5},
                synonyms=("tea press",),
            ),
            V("white", "a white French press cafetiere", (0.1, 0.15, 0.21), (P.GLASS, P.WHITE, P.WHITE)),
        ],
        density=380.0,
        mass_limits=(0.2, 1.5),
        friction=(0.4, 0.7),
        support_probability=0.05,
        synonyms=("cafetiere", "coffee press", "press pot", "plunger pot", "french press coffee maker"),
        tags=("kitchen", "coffee", "breakfast", "glass", "brew"),
    ),
    define(
        "coffee maker",
        "coffee maker",
        coffee_maker,
        [
            V(
                "drip_black",
                "a black drip coffee maker with a glass carafe",
                (0.25, 0.2, 0.35),
                synonyms=("drip coffee maker", "filter coffee machine"),
            ),
            V(
                "drip_white",
                "a white filter coffee machine with a carafe",
                (0.24, 0.2, 0.34),
                (P.WHITE, P.GREY),
                synonyms=("drip coffee maker", "filter coffee machine"),
            ),
            V(
                "drip_steel",
                "a stainless steel drip coffee maker",
                (0.26, 0.22, 0.36),
                (P.STEEL, P.BLACK),
                synonyms=("drip coffee maker",),
            ),
            V(
                "pod_black",
                "a black single-serve pod coffee machine with a mug",
                (0.3, 0.15, 0.3),
                (P.BLACK, P.SILVER, P.WHITE),
                {"style": "pod"},
                mass=2.6,
                synonyms=("pod machine", "capsule machine"),
            ),
            V(
                "pod_red",
                "a red capsule coffee machine",
                (0.28, 0.13, 0.26),
                (P.RED, P.SILVER, P.WHITE),
                {"style": "pod"},
                mass=2.2,
                synonyms=("capsule machine", "nespresso"),
            ),
            V(
                "espresso_steel",
                "a stainless steel espresso machine with a cup",
                (0.3, 0.25, 0.32),
                (P.STEEL, P.BLACK, P.WHITE),
                {"style": "espresso"},
                mass=6.5,
                synonyms=("espresso machine",),
            ),
            V(
                "espresso_black",
                "a black home espresso maker",
                (0.28, 0.22, 0.3),
                (P.BLACK, P.SILVER, P.WHITE),
                {"style": "espresso"},
                mass=5.0,
                synonyms=("espresso machine",),
            ),
        ],
        density=200.0,
        mass_limits=(1.0, 9.0),
        friction=(0.5, 0.8),
        support_probability=0.1,
        synonyms=("coffee machine", "coffeemaker", "coffee brewer", "espresso machine", "coffee pot"),
        tags=("kitchen", "appliance", "coffee", "breakfast", "counter", "brew"),
    ),
    define(
        "ladle",
        "ladle",
        ladle,
        [
            V("steel", "a stainless steel soup ladle", (0.32, 0.09, 0.08)),
            V("black_nylon", "a black nylon ladle", (0.31, 0.09, 0.08), (P.BLACK,), density=1300.0),
            V("wood", "a wooden ladle", (0.3, 0.08, 0.07), (P.WOOD,), density=700.0),
            V("small_sauce", "a small steel sauce ladle", (0.22, 0.06, 0.05)),
            V("large_punch", "a large punch ladle of steel", (0.38, 0.11, 0.1), synonyms=("punch ladle",)),
            V(
                "red_silicone",
                "a red silicone ladle with a steel handle",
                (0.32, 0.09, 0.08),
                (P.RED, P.STEEL),
                density=1800.0,
            ),
            V("enamel_white", "a white enamel ladle with a black handle", (0.3, 0.09, 0.08), (P.WHITE, P.BLACK)),
        ],
        density=2600.0,
        mass_limits=(0.02, 0.4),
        friction=(0.3, 0.6),
        support_probability=0.0,
        has_front=False,
        synonyms=("soup ladle", "dipper", "serving ladle", "big spoon", "soup serving spoon", "deep spoon"),
        tags=("kitchen", "cooking", "utensil", "soup", "serving", "scoop"),
    ),
    define(
        "spatula",
        "spatula",
        spatula,
        [
            V("black_turner", "a black nylon spatula for turning food", (0.33, 0.08, 0.02), synonyms=("turner",)),
            V(
                "slotted_steel",
                "a slotted stainless steel fish slice",
                (0.32, 0.08, 0.02),
                (P.STEEL, P.BLACK),
                {"slotted": True},
                density=1500.0,
                synonyms=("fish slice", "slotted turner"),
            ),
            V("wood", "a wooden spatula", (0.3, 0.07, 0.015), (P.WOOD, P.WOOD), density=700.0),
            V(
                "red_scraper",
                "a red silicone rubber scraper spatula",
                (0.27, 0.05, 0.015),
                (P.RED, P.WHITE),
                {"style": "scraper", "blade": 0.3},
                synonyms=("rubber spatula", "scraper"),
            ),
            V(
                "blue_scraper",
                "a blue silicone spatula for baking",
                (0.25, 0.05, 0.015),
                (P.SKY, P.BLUE),
                {"style": "scraper", "blade": 0.3},
                synonyms=("rubber spatula", "scraper"),
            ),
            V(
                "pancake",
                "a wide steel pancake turner with a black handle",
                (0.34, 0.1, 0.022),
                (P.STEEL, P.BLACK),
                {"blade": 0.38},
                density=1500.0,
                synonyms=("pancake turner", "flipper"),
            ),
            V(
                "grey_slotted",
                "a grey slotted plastic spatula",
                (0.32, 0.08, 0.02),
                (P.GREY, P.CHARCOAL),
                {"slotted": True},
            ),
        ],
        density=1300.0,
        mass_limits=(0.02, 0.3),
        friction=(0.3, 0.6),
        support_probability=0.0,
        has_front=False,
        synonyms=("turner", "flipper", "fish slice", "egg flipper", "scraper", "spatulas"),
        tags=("kitchen", "cooking", "utensil", "frying", "baking", "flat"),
    ),
    define(
        "grater",
        "grater",
        grater,
        [
            V("box_steel", "a four-sided stainless steel box grater with a black handle", (0.11, 0.09, 0.24)),
            V("box_small", "a small steel cheese grater", (0.09, 0.07, 0.18), synonyms=("cheese grater",)),
            V("box_red", "a box grater with a red handle", (0.11, 0.09, 0.24), (P.STEEL, P.RED)),
            V("box_tall", "a tall steel box grater", (0.12, 0.1, 0.27), (P.SILVER, P.BLACK)),
            V(
                "flat_black",
                "a flat steel grater with a black handle",
                (0.3, 0.07, 0.02),
                (P.STEEL, P.BLACK),
                {"flat": True},
                density=900.0,
                synonyms=("paddle grater", "rasp"),
            ),
            V(
                "flat_zester",
                "a narrow zester grater with a grey handle",
                (0.3, 0.04, 0.02),
                (P.STEEL, P.GREY),
                {"flat": True},
                density=900.0,
                synonyms=("zester", "microplane"),
            ),
            V("box_green", "a box grater with a green handle", (0.1, 0.08, 0.22), (P.STEEL, P.GREEN)),
        ],
        density=220.0,
        mass_limits=(0.05, 0.6),
        friction=(0.4, 0.7),
        support_probability=0.0,
        synonyms=("cheese grater", "box grater", "zester", "shredder", "grater"),
        tags=("kitchen", "cooking", "cheese", "steel", "utensil"),
    ),
    define(
        "blender",
        "blender",
        blender,
        [
            V("black_jug", "a black countertop blender with a glass jug", (0.18, 0.22, 0.4)),
            V(
                "silver_jug",
                "a silver blender with a clear jar and a smoothie inside",
                (0.18, 0.22, 0.42),
                (P.SILVER, P.GLASS, P.rgb(230, 120, 150)),
            ),
            V("red_jug", "a red kitchen blender", (0.17, 0.21, 0.38), (P.RED, P.GLASS, P.rgb(240, 200, 80))),
            V("white_jug", "a white food blender with a plastic jug", (0.17, 0.21, 0.38), (P.WHITE, P.GLASS, P.LIME)),
            V(
                "personal_black",
                "a black personal smoothie blender with a bottle",
                (0.11, 0.11, 0.35),
                options={"personal": True},
                mass=1.6,
                synonyms=("smoothie maker", "bullet blender"),
            ),
            V(
                "personal_teal",
                "a teal single-serve blender",
                (0.11, 0.11, 0.33),
                (P.TEAL, P.GLASS, P.PINK),
                {"personal": True},
                mass=1.5,
                synonyms=("smoothie maker",),
            ),
            V(
                "steel_pro",
                "a large stainless steel high-power blender",
                (0.2, 0.25, 0.45),
                (P.STEEL, P.GLASS, P.WHITE),
                mass=4.5,
            ),
        ],
        density=500.0,
        mass_limits=(0.8, 6.0),
        friction=(0.5, 0.8),
        support_probability=0.05,
        synonyms=("liquidiser", "liquidizer", "smoothie maker", "food blender", "mixer jug"),
        tags=("kitchen", "appliance", "smoothie", "counter", "blend", "jug"),
    ),
    define(
        "microwave",
        "microwave",
        microwave,
        [
            V("white", "a white microwave oven with a dark glass door", (0.38, 0.5, 0.29)),
            V("black", "a black microwave oven", (0.38, 0.5, 0.29), (P.BLACK, P.CHARCOAL, P.BLACK)),
            V(
                "steel",
                "a stainless steel microwave with a door handle",
                (0.4, 0.52, 0.3),
                (P.STEEL, P.CHARCOAL, P.BLACK),
                {"handle": True},
            ),
            V("compact_white", "a compact white microwave", (0.34, 0.44, 0.26), (P.WHITE, P.GREY, P.GREY)),
            V("red_retro", "a red retro microwave oven", (0.36, 0.48, 0.28), (P.RED, P.CHARCOAL, P.CREAM)),
            V(
                "large_silver",
                "a large silver combination microwave",
                (0.45, 0.55, 0.33),
                (P.SILVER, P.BLACK, P.BLACK),
                {"handle": True, "panel": 0.22},
                mass=17.0,
            ),
            V("cream", "a cream countertop microwave", (0.37, 0.48, 0.28), (P.CREAM, P.GREY, P.BROWN)),
        ],
        density=220.0,
        mass_limits=(6.0, 25.0),
        friction=(0.5, 0.8),
        support_probability=0.6,
        synonyms=("microwave oven", "micro-wave", "microwave", "oven"),
        tags=("kitchen", "appliance", "heating", "counter", "reheat"),
    ),
    define(
        "stand mixer",
        "stand mixer",
        stand_mixer,
        [
            V("red", "a red stand mixer with a steel bowl", (0.35, 0.22, 0.35), mass=10.0),
            V("white", "a white stand mixer", (0.35, 0.22, 0.35), (P.WHITE, P.STEEL), mass=10.0),
            V("black", "a black kitchen stand mixer", (0.36, 0.23, 0.36), (P.BLACK, P.STEEL), mass=10.5),
            V("silver", "a silver food mixer with a bowl", (0.36, 0.23, 0.36), (P.SILVER, P.STEEL), mass=11.0),
            V("mint", "a mint green stand mixer", (0.35, 0.22, 0.35), (P.rgb(160, 220, 200), P.STEEL), mass=10.0),
            V("cream", "a cream tilt-head mixer", (0.34, 0.22, 0.34), (P.CREAM, P.STEEL), mass=9.5),
            V("compact_blue", "a compact blue stand mixer", (0.3, 0.19, 0.3), (P.SKY, P.STEEL), mass=6.0),
        ],
        density=800.0,
        mass_limits=(3.0, 14.0),
        friction=(0.5, 0.8),
        support_probability=0.05,
        synonyms=("food mixer", "kitchen mixer", "kitchenaid", "mixer", "dough mixer"),
        tags=("kitchen", "appliance", "baking", "dough", "counter", "bowl"),
    ),
    define(
        "knife block",
        "knife block",
        knife_block,
        [
            V("wood", "a slanted wooden knife block with black handles showing", (0.12, 0.1, 0.3)),
            V("bamboo", "a bamboo knife block holding five blades", (0.12, 0.1, 0.28), (P.BAMBOO, P.BLACK)),
            V("black", "a black knife block with steel handles", (0.13, 0.1, 0.3), (P.BLACK, P.STEEL)),
            V(
                "dark_wood",
                "a dark walnut knife block with six black handles",
                (0.14, 0.12, 0.32),
                (P.DARK_BROWN, P.BLACK),
                {"knives": 6},
            ),
            V("white", "a white knife block", (0.12, 0.1, 0.28), (P.WHITE, P.CHARCOAL)),
            V(
                "small",
                "a small wooden knife block with three handles",
                (0.1, 0.07, 0.24),
                (P.LIGHT_WOOD, P.BLACK),
                {"knives": 3},
            ),
            V("red", "a red knife block with black handles", (0.12, 0.1, 0.3), (P.RED, P.BLACK)),
        ],
        density=850.0,
        mass_limits=(0.6, 4.0),
        friction=(0.5, 0.8),
        support_probability=0.05,
        synonyms=("knife holder", "knife stand", "cutlery block", "blade block"),
        tags=("kitchen", "counter", "cutlery", "wood", "cooking", "holding", "chef"),
    ),
    define(
        "utensil holder",
        "utensil holder",
        utensil_holder,
        [
            V("white", "a white ceramic utensil crock", (0.12, 0.12, 0.17)),
            V(
                "steel",
                "a stainless steel kitchen utensil holder",
                (0.11, 0.11, 0.16),
                (P.STEEL, P.SILVER),
                density=3500.0,
            ),
            V("blue", "a blue stoneware utensil pot", (0.13, 0.13, 0.18), (P.BLUE, P.NAVY)),
            V("terracotta", "a terracotta crock for cooking spoons", (0.13, 0.13, 0.17), (P.TERRACOTTA,)),
            V(
                "bamboo_square",
                "a square bamboo utensil holder",
                (0.11, 0.11, 0.16),
                (P.BAMBOO,),
                {"square": True},
                density=700.0,
            ),
            V(
                "black_square",
                "a black square utensil caddy",
                (0.1, 0.1, 0.15),
                (P.BLACK,),
                {"square": True, "wall": 0.004},
                density=1200.0,
            ),
            V("cream_large", "a large cream ceramic utensil jar", (0.15, 0.15, 0.19), (P.CREAM, P.BROWN)),
        ],
        density=2000.0,
        mass_limits=(0.1, 2.0),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=(
            "utensil crock",
            "utensil jar",
            "utensil pot",
            "spoon holder",
            "kitchen tool holder",
            "cooking utensil holder",
            "utensil caddy",
        ),
        tags=("kitchen", "counter", "utensils", "spoons", "spatulas", "container", "open"),
    ),
    define(
        "paper towel holder",
        "paper towel holder",
        paper_towel_holder,
        [
            V("steel", "a steel paper towel holder with a roll of kitchen paper", (0.15, 0.15, 0.33)),
            V("black", "a black standing kitchen roll holder", (0.15, 0.15, 0.33), (P.BLACK, P.PAPER)),
            V("wood", "a wooden paper towel stand with a roll", (0.16, 0.16, 0.32), (P.WOOD, P.PAPER)),
            V(
                "empty_steel",
                "an empty chrome paper towel holder",
                (0.14, 0.14, 0.33),
                (P.SILVER,),
                {"roll": False},
                density=2500.0,
            ),
            V("white", "a white paper towel holder with a patterned roll", (0.15, 0.15, 0.32), (P.WHITE, P.CREAM)),
            V("brass", "a brass kitchen roll stand", (0.15, 0.15, 0.34), (P.BRASS, P.PAPER)),
            V("short", "a short paper towel holder with a half-used roll", (0.13, 0.13, 0.28), (P.STEEL, P.PAPER)),
        ],
        density=180.0,
        mass_limits=(0.2, 2.0),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=(
            "kitchen roll holder",
            "paper towel stand",
            "paper towels",
            "kitchen roll",
            "paper towel roll",
            "roll of paper towels",
        ),
        tags=("kitchen", "counter", "paper", "cleaning", "roll"),
    ),
    define(
        "napkin holder",
        "napkin holder",
        napkin_holder,
        [
            V("steel", "a steel napkin holder full of white paper napkins", (0.06, 0.18, 0.12)),
            V("wood", "a wooden napkin holder with paper napkins", (0.07, 0.18, 0.12), (P.WOOD, P.WHITE)),
            V("black", "a black metal napkin holder", (0.06, 0.17, 0.11), (P.BLACK, P.WHITE)),
            V(
                "diner",
                "a chrome diner napkin dispenser",
                (0.08, 0.15, 0.13),
                (P.SILVER, P.WHITE),
                synonyms=("napkin dispenser",),
            ),
            V("bamboo", "a bamboo napkin holder with yellow napkins", (0.07, 0.19, 0.12), (P.BAMBOO, P.YELLOW)),
            V("white", "a white ceramic napkin holder", (0.06, 0.17, 0.1), (P.WHITE, P.rgb(245, 225, 120))),
            V("acrylic", "a clear acrylic napkin holder with red napkins", (0.06, 0.18, 0.12), (P.GLASS, P.RED)),
        ],
        density=650.0,
        mass_limits=(0.08, 1.2),
        friction=(0.4, 0.7),
        support_probability=0.0,
        synonyms=("serviette holder", "napkin dispenser", "napkin stand", "napkin rack"),
        tags=("dining", "table", "napkins", "paper", "restaurant"),
    ),
    define(
        "kitchen scale",
        "kitchen scale",
        kitchen_scale,
        [
            V("white_digital", "a flat white digital kitchen scale", (0.2, 0.15, 0.02)),
            V("black_glass", "a black glass digital scale", (0.2, 0.16, 0.018), (P.BLACK, P.SKY)),
            V("steel", "a stainless steel kitchen scale", (0.22, 0.17, 0.025), (P.STEEL, P.CHARCOAL)),
            V(
                "bamboo",
                "a bamboo food scale with a display",
                (0.2, 0.15, 0.022),
                (P.BAMBOO, P.CHARCOAL),
                density=800.0,
            ),
            V(
                "dial_red",
                "a red mechanical kitchen scale with a weighing bowl",
                (0.2, 0.2, 0.19),
                (P.RED, P.WHITE),
                {"bowl": True},
                density=250.0,
            ),
            V(
                "dial_cream",
                "a cream retro dial scale with a steel bowl",
                (0.2, 0.2, 0.19),
                (P.CREAM, P.WHITE),
                {"bowl": True},
                density=250.0,
            ),
            V("small_grey", "a small grey pocket scale", (0.13, 0.1, 0.02), (P.GREY, P.CHARCOAL)),
        ],
        density=1100.0,
        mass_limits=(0.15, 2.5),
        friction=(0.5, 0.8),
        support_probability=0.7,
        synonyms=("food scale", "weighing scale", "digital scale", "kitchen scales", "baking scale", "scale"),
        tags=("kitchen", "baking", "weighing", "cooking", "counter", "flat"),
    ),
    define(
        "baking tray",
        "baking tray",
        baking_tray,
        [
            V("sheet_pan", "a rimmed aluminium sheet pan", (0.45, 0.3, 0.02), synonyms=("sheet pan",)),
            V(
                "dark_nonstick",
                "a dark nonstick baking sheet",
                (0.4, 0.28, 0.018),
                (P.CHARCOAL,),
                synonyms=("baking sheet",),
            ),
            V("small_steel", "a small steel oven tray", (0.3, 0.22, 0.02), (P.STEEL,), synonyms=("oven tray",)),
            V(
                "cookie_sheet",
                "a flat cookie sheet with a low rim",
                (0.42, 0.3, 0.012),
                (P.SILVER,),
                {"rim": 0.01},
                synonyms=("cookie sheet",),
            ),
            V(
                "large_roasting",
                "a large deep roasting tray",
                (0.45, 0.32, 0.035),
                (P.CHARCOAL,),
                {"rim": 0.015},
                density=1600.0,
                synonyms=("roasting tray", "roasting pan"),
            ),
            V("blue_enamel", "a blue enamel baking tray", (0.38, 0.26, 0.025), (P.NAVY,), density=2200.0),
            V(
                "copper",
                "a copper-coloured baking pan",
                (0.35, 0.25, 0.02),
                (P.rgb(190, 110, 60),),
                synonyms=("baking pan",),
            ),
        ],
        density=2700.0,
        mass_limits=(0.15, 2.0),
        friction=(0.3, 0.6),
        support_probability=0.95,
        has_front=False,
        synonyms=("baking sheet", "sheet pan", "oven tray", "cookie sheet", "baking pan", "roasting tray"),
        tags=("kitchen", "baking", "oven", "cookies", "flat", "metal"),
    ),
    define(
        "muffin tin",
        "muffin tin",
        baking_tray,
        [
            V("twelve", "a steel muffin tin with twelve cups", (0.35, 0.27, 0.03), (P.SILVER,), {"cups": 4}),
            V("six", "a small muffin tin with six cups", (0.27, 0.18, 0.03), (P.SILVER,), {"cups": 3}),
            V(
                "dark_twelve",
                "a dark nonstick cupcake pan for twelve",
                (0.35, 0.27, 0.03),
                (P.CHARCOAL,),
                {"cups": 4},
                synonyms=("cupcake pan", "cupcake tin"),
            ),
            V(
                "mini_24",
                "a mini muffin tray with twenty-four cups",
                (0.38, 0.26, 0.022),
                (P.SILVER,),
                {"cups": 6},
                synonyms=("mini muffin tin",),
            ),
            V(
                "red_silicone",
                "a red silicone muffin mould",
                (0.32, 0.24, 0.03),
                (P.RED,),
                {"cups": 4},
                density=600.0,
                synonyms=("muffin mould", "muffin mold"),
            ),
            V(
                "blue_silicone",
                "a blue silicone cupcake mould for six",
                (0.26, 0.18, 0.03),
                (P.SKY,),
                {"cups": 3},
                density=600.0,
                synonyms=("cupcake mould",),
            ),
            V("gold", "a gold-coloured muffin pan", (0.35, 0.27, 0.03), (P.GOLD,), {"cups": 4}),
        ],
        density=450.0,
        mass_limits=(0.1, 1.5),
        friction=(0.3, 0.6),
        support_probability=0.3,
        has_front=False,
        synonyms=(
            "muffin pan",
            "muffin tray",
            "cupcake tin",
            "cupcake pan",
            "bun tin",
            "muffin mould",
            "tray for muffins",
        ),
        tags=("kitchen", "baking", "oven", "muffins", "cupcakes", "metal"),
    ),
    define(
        "mortar and pestle",
        "mortar and pestle",
        mortar_and_pestle,
        [
            V("granite", "a grey granite mortar with its pestle beside it", (0.13, 0.18, 0.09), synonyms=("mortar",)),
            V("marble", "a white marble mortar and pestle", (0.12, 0.17, 0.08), (P.rgb(230, 230, 228),)),
            V("black_granite", "a black granite pestle and mortar", (0.15, 0.21, 0.1), (P.CHARCOAL,)),
            V("wood", "a wooden mortar and pestle", (0.12, 0.17, 0.09), (P.WOOD,), density=700.0),
            V(
                "ceramic_white",
                "a white ceramic mortar with a wooden-handled pestle",
                (0.11, 0.16, 0.07),
                (P.WHITE, P.WOOD),
                {"wall": 0.008},
                density=2000.0,
            ),
            V(
                "molcajete",
                "a large dark stone molcajete with its pestle",
                (0.18, 0.25, 0.11),
                (P.CHARCOAL,),
                {"wall": 0.018},
                synonyms=("molcajete",),
            ),
            V(
                "mortar_only",
                "a green stone mortar bowl without its pestle",
                (0.12, 0.12, 0.08),
                (P.DARK_GREEN,),
                {"pestle": False},
                synonyms=("mortar",),
            ),
        ],
        density=2500.0,
        mass_limits=(0.15, 8.0),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=False,
        synonyms=("pestle and mortar", "mortar", "pestle", "spice grinder bowl", "grinding bowl"),
        tags=("kitchen", "cooking", "spices", "grinding", "stone", "container"),
    ),
    define(
        "tongs",
        "tongs",
        tongs,
        [
            V("steel", "a pair of steel kitchen tongs with black silicone tips", (0.3, 0.05, 0.02)),
            V(
                "long_bbq",
                "long steel barbecue tongs",
                (0.42, 0.06, 0.022),
                (P.STEEL,),
                {"tips": False},
                synonyms=("bbq tongs", "grill tongs"),
            ),
            V("red_tips", "steel tongs with red silicone tips", (0.3, 0.05, 0.02), (P.STEEL, P.RED)),
            V(
                "small_serving",
                "small serving tongs for salad",
                (0.22, 0.04, 0.016),
                (P.SILVER,),
                {"tips": False},
                synonyms=("salad tongs", "serving tongs"),
            ),
            V("black_nylon", "black nylon cooking tongs", (0.3, 0.05, 0.02), (P.BLACK, P.BLACK)),
            V(
                "wood",
                "wooden toast tongs",
                (0.2, 0.04, 0.015),
                (P.BAMBOO,),
                {"tips": False},
                density=600.0,
                synonyms=("toast tongs",),
            ),
            V("green_tips", "kitchen tongs with green silicone tips", (0.28, 0.05, 0.02), (P.STEEL, P.GREEN)),
        ],
        density=1000.0,
        mass_limits=(0.01, 0.4),
        friction=(0.3, 0.6),
        support_probability=0.0,
        has_front=False,
        synonyms=("kitchen tongs", "cooking tongs", "pair of tongs", "serving tongs", "grill tongs", "tong"),
        tags=("kitchen", "cooking", "utensil", "grilling", "serving", "metal"),
    ),
    define(
        "peeler",
        "peeler",
        peeler,
        [
            V("y_black", "a Y-shaped vegetable peeler with a black handle", (0.15, 0.07, 0.015)),
            V("y_red", "a red Y peeler for potatoes", (0.15, 0.07, 0.015), (P.RED, P.STEEL)),
            V(
                "swivel_steel",
                "a straight swivel peeler with a steel handle",
                (0.18, 0.03, 0.014),
                (P.STEEL, P.SILVER),
                {"y_shaped": False},
                density=1800.0,
                synonyms=("swivel peeler",),
            ),
            V(
                "swivel_black",
                "a straight peeler with a black grip",
                (0.18, 0.03, 0.015),
                (P.BLACK, P.STEEL),
                {"y_shaped": False},
            ),
            V("y_green", "a green speed peeler", (0.14, 0.065, 0.014), (P.GREEN, P.STEEL)),
            V(
                "wood",
                "a peeler with a wooden handle",
                (0.17, 0.03, 0.015),
                (P.WOOD, P.STEEL),
                {"y_shaped": False},
                density=800.0,
            ),
            V("y_white", "a white Y peeler", (0.15, 0.07, 0.015), (P.WHITE, P.STEEL)),
        ],
        density=1000.0,
        mass_limits=(0.01, 0.15),
        friction=(0.3, 0.6),
        support_probability=0.0,
        has_front=False,
        synonyms=("vegetable peeler", "potato peeler", "speed peeler", "y peeler", "fruit peeler", "peeling tool"),
        tags=("kitchen", "cooking", "utensil", "vegetables", "potatoes", "peel"),
    ),
    define(
        "whisk",
        "whisk",
        whisk,
        [
            V("steel", "a stainless steel balloon whisk", (0.28, 0.07, 0.07)),
            V("black_handle", "a balloon whisk with a black handle", (0.28, 0.07, 0.07), (P.STEEL, P.BLACK)),
            V("small", "a small steel whisk for sauces", (0.2, 0.05, 0.05), (P.STEEL,), {"loops": 3}),
            V("large", "a large whisk with a wooden handle", (0.35, 0.09, 0.09), (P.STEEL, P.WOOD), {"loops": 5}),
            V("red_silicone", "a red silicone-coated whisk", (0.27, 0.07, 0.07), (P.RED,)),
            V("french", "a narrow French whisk", (0.3, 0.05, 0.05), (P.SILVER, P.SILVER), {"head": 0.65}),
            V("white_handle", "a whisk with a white plastic handle", (0.26, 0.065, 0.065), (P.STEEL, P.WHITE)),
        ],
        density=2200.0,
        mass_limits=(0.015, 0.3),
        friction=(0.3, 0.6),
        support_probability=0.0,
        has_front=False,
        synonyms=("balloon whisk", "egg beater", "egg whisk", "wire whisk", "beater"),
        tags=("kitchen", "baking", "utensil", "eggs", "cream", "whipping"),
    ),
    define(
        "canister",
        "canister",
        canister,
        [
            V(
                "flour",
                "a white ceramic flour canister with a wooden lid",
                (0.12, 0.12, 0.2),
                (P.WHITE, P.WOOD, P.CHARCOAL),
                synonyms=("flour canister", "flour jar"),
            ),
            V(
                "sugar",
                "a white sugar canister with a bamboo lid",
                (0.11, 0.11, 0.17),
                (P.WHITE, P.BAMBOO, P.CHARCOAL),
                synonyms=("sugar canister",),
            ),
            V(
                "coffee_black",
                "a black coffee canister",
                (0.11, 0.11, 0.16),
                (P.BLACK, P.BLACK, P.WHITE),
                synonyms=("coffee canister", "coffee tin"),
            ),
            V(
                "tea_steel",
                "a stainless steel tea canister",
                (0.1, 0.1, 0.15),
                (P.STEEL, P.STEEL, P.BLACK),
                density=400.0,
                synonyms=("tea canister",),
            ),
            V(
                "pasta_glass",
                "a tall glass storage jar of pasta with a wooden lid",
                (0.11, 0.11, 0.25),
                (P.rgb(235, 215, 150, 0.8), P.WOOD),
                {"label": False},
                synonyms=("pasta jar", "storage jar"),
            ),
            V(
                "red_square",
                "a red square storage canister",
                (0.11, 0.11, 0.18),
                (P.RED, P.RED, P.WHITE),
                {"square": True},
            ),
            V(
                "cream_square",
                "a cream enamel bread-and-biscuit canister",
                (0.13, 0.13, 0.2),
                (P.CREAM, P.SILVER, P.BROWN),
                {"square": True},
            ),
            V(
                "rice_tall",
                "a tall white canister for rice",
                (0.13, 0.13, 0.24),
                (P.WHITE, P.GREY, P.GREY),
                synonyms=("rice container",),
            ),
            V(
                "open_tin",
                "an open empty tin canister with its lid off",
                (0.11, 0.11, 0.15),
                (P.SILVER,),
                {"open": True},
                mass=0.2,
                synonyms=("open canister", "empty canister", "open tin", "storage tin"),
            ),
        ],
        density=600.0,
        mass_limits=(0.2, 3.5),
        friction=(0.4, 0.7),
        support_probability=0.1,
        has_front=False,
        synonyms=(
            "kitchen canister",
            "storage canister",
            "storage jar",
            "flour canister",
            "coffee canister",
            "tea canister",
            "sugar canister",
            "dry goods container",
        ),
        tags=("kitchen", "pantry", "counter", "flour", "sugar", "coffee", "tea", "storage", "lidded"),
    ),
    define(
        "cookie jar",
        "cookie jar",
        cookie_jar,
        [
            V("cream", "a cream ceramic cookie jar with a brown knob", (0.18, 0.18, 0.25)),
            V(
                "open_cream",
                "an open cream cookie jar with its lid off",
                (0.18, 0.18, 0.2),
                options={"open": True},
                synonyms=("open cookie jar", "open biscuit jar", "empty cookie jar"),
            ),
            V(
                "blue",
                "a blue ceramic biscuit jar",
                (0.17, 0.17, 0.24),
                (P.SKY, P.SKY, P.WHITE),
                synonyms=("biscuit jar",),
            ),
            V("red", "a red cookie jar", (0.18, 0.18, 0.25), (P.RED, P.RED, P.WHITE)),
            V(
                "glass",
                "a glass cookie jar with a lid",
                (0.16, 0.16, 0.24),
                (P.GLASS, P.GLASS, P.SILVER),
                density=300.0,
            ),
            V(
                "white",
                "a white porcelain biscuit barrel",
                (0.16, 0.16, 0.22),
                (P.WHITE, P.WHITE, P.GOLD),
                synonyms=("biscuit barrel",),
            ),
            V("brown", "a brown stoneware cookie jar", (0.19, 0.19, 0.26), (P.BROWN, P.BROWN, P.CREAM)),
            V(
                "small_pink",
                "a small pink candy jar",
                (0.13, 0.13, 0.18),
                (P.PINK, P.PINK, P.WHITE),
                synonyms=("candy jar", "sweet jar"),
            ),
        ],
        density=380.0,
        mass_limits=(0.2, 3.0),
        friction=(0.4, 0.7),
        support_probability=0.05,
        has_front=False,
        synonyms=("biscuit jar", "biscuit barrel", "cookie pot", "candy jar", "treat jar", "cookie container"),
        tags=("kitchen", "counter", "cookies", "biscuits", "snacks", "ceramic", "lidded"),
    ),
    define(
        "trivet",
        "trivet",
        trivet,
        [
            V("cork_round", "a round cork trivet for hot pots", (0.2, 0.2, 0.01), options={"round": True}),
            V("cork_square", "a square cork hot pad", (0.2, 0.2, 0.01)),
            V("wood", "a wooden trivet", (0.2, 0.2, 0.015), (P.WOOD,), density=650.0),
            V(
                "iron_grid",
                "a black cast-iron trivet grid on feet",
                (0.2, 0.2, 0.02),
                (P.BLACK,),
                {"grid": True},
                density=7000.0,
                synonyms=("iron trivet",),
            ),
            V("brass_grid", "a brass trivet", (0.18, 0.18, 0.02), (P.BRASS,), {"grid": True}, density=7000.0),
            V(
                "silicone_red",
                "a red silicone pot stand",
                (0.18, 0.18, 0.008),
                (P.RED,),
                {"round": True},
                density=1100.0,
            ),
            V("slate", "a square slate trivet", (0.2, 0.2, 0.01), (P.CHARCOAL,), density=2700.0),
        ],
        density=200.0,
        mass_limits=(0.03, 2.0),
        friction=(0.5, 0.8),
        support_probability=0.95,
        has_front=False,
        synonyms=("pot stand", "hot pad", "pot rest", "trivet mat", "hot plate stand", "pan stand"),
        tags=("kitchen", "dining", "table", "hot pot", "flat", "cork"),
    ),
    define(
        "baking dish",
        "baking dish",
        oven_dish,
        [
            V(
                "white_rect",
                "a white ceramic rectangular baking dish with handles",
                (0.34, 0.22, 0.065),
                options={"handles": 0.02},
            ),
            V(
                "glass_rect",
                "a clear glass oven dish with handles",
                (0.36, 0.22, 0.06),
                (P.GLASS,),
                {"handles": 0.025, "wall": 0.006},
                synonyms=("pyrex dish", "glass baking dish"),
            ),
            V(
                "red_lasagne",
                "a red stoneware lasagne dish",
                (0.33, 0.23, 0.07),
                (P.RED,),
                {"handles": 0.02},
                synonyms=("lasagne dish", "lasagna pan"),
            ),
            V(
                "oval_white",
                "a white oval gratin dish",
                (0.3, 0.2, 0.055),
                options={"outline": "oval"},
                synonyms=("gratin dish", "oval dish"),
            ),
            V(
                "oval_blue",
                "a blue oval casserole dish",
                (0.32, 0.22, 0.07),
                (P.BLUE,),
                {"outline": "oval"},
                synonyms=("casserole dish",),
            ),
            V("small_cream", "a small cream baking dish", (0.22, 0.15, 0.05), (P.CREAM,), {"wall": 0.006}),
            V(
                "steel_roaster",
                "a deep steel roasting pan with handles",
                (0.4, 0.26, 0.08),
                (P.STEEL,),
                {"handles": 0.025, "wall": 0.004},
                density=3500.0,
                synonyms=("roasting pan", "roaster"),
            ),
        ],
        density=2200.0,
        mass_limits=(0.3, 4.0),
        friction=(0.4, 0.7),
        support_probability=0.3,
        has_front=False,
        synonyms=(
            "oven dish",
            "casserole dish",
            "lasagne dish",
            "lasagna pan",
            "bakeware dish",
            "gratin dish",
            "ovenproof dish",
            "roasting dish",
        ),
        tags=("kitchen", "baking", "oven", "casserole", "ceramic", "container", "open"),
    ),
    define(
        "pie dish",
        "pie dish",
        oven_dish,
        [
            V("white", "a white ceramic pie dish", (0.26, 0.26, 0.045), options={"outline": "round"}),
            V(
                "glass",
                "a round glass pie plate",
                (0.25, 0.25, 0.045),
                (P.GLASS,),
                {"outline": "round", "wall": 0.006},
                synonyms=("pie plate",),
            ),
            V(
                "tin",
                "a metal pie tin",
                (0.23, 0.23, 0.03),
                (P.SILVER,),
                {"outline": "round", "wall": 0.003},
                density=3500.0,
                synonyms=("pie tin", "pie pan"),
            ),
            V("red", "a red stoneware pie dish", (0.27, 0.27, 0.05), (P.RED,), {"outline": "round"}),
            V(
                "blue_handles",
                "a blue pie dish with two handles",
                (0.3, 0.26, 0.05),
                (P.SKY,),
                {"outline": "round", "handles": 0.02},
            ),
            V(
                "tart_tin",
                "a shallow fluted tart tin",
                (0.24, 0.24, 0.025),
                (P.GOLD,),
                {"outline": "round", "wall": 0.003},
                density=3500.0,
                synonyms=("tart tin", "quiche dish", "flan tin"),
            ),
            V(
                "small_cream",
                "a small cream pie dish for one",
                (0.15, 0.15, 0.04),
                (P.CREAM,),
                {"outline": "round", "wall": 0.006},
                synonyms=("ramekin",),
            ),
        ],
        density=2200.0,
        mass_limits=(0.08, 2.5),
        friction=(0.4, 0.7),
        support_probability=0.4,
        has_front=False,
        synonyms=("pie plate", "pie tin", "pie pan", "tart tin", "quiche dish", "flan dish", "tart pan"),
        tags=("kitchen", "baking", "oven", "pie", "tart", "round", "container", "open"),
    ),
    define(
        "rice cooker",
        "rice cooker",
        cooker,
        [
            V("white", "a white electric rice cooker with a carry handle", (0.27, 0.26, 0.24)),
            V("steel", "a stainless steel rice cooker", (0.27, 0.26, 0.24), (P.STEEL, P.BLACK)),
            V("black", "a black rice cooker", (0.28, 0.27, 0.25), (P.BLACK, P.SILVER)),
            V("small_pink", "a small pink rice cooker", (0.21, 0.2, 0.2), (P.PINK, P.WHITE)),
            V("cream", "a cream multi cooker", (0.3, 0.29, 0.27), (P.CREAM, P.SILVER), synonyms=("multi cooker",)),
            V(
                "red",
                "a red electric pressure cooker",
                (0.3, 0.29, 0.3),
                (P.RED, P.BLACK),
                synonyms=("pressure cooker", "instant pot"),
            ),
            V("grey", "a grey rice steamer", (0.26, 0.25, 0.23), (P.GREY, P.WHITE), synonyms=("rice steamer",)),
        ],
        density=260.0,
        mass_limits=(1.0, 7.0),
        friction=(0.5, 0.8),
        support_probability=0.1,
        synonyms=("rice steamer", "electric cooker", "multi cooker", "pressure cooker", "instant pot", "rice maker"),
        tags=("kitchen", "appliance", "rice", "cooking", "counter"),
    ),
    define(
        "slow cooker",
        "slow cooker",
        cooker,
        [
            V("black", "a black slow cooker with a glass lid", (0.3, 0.36, 0.25), (P.BLACK, P.GLASS), {"slow": True}),
            V("steel", "a stainless steel slow cooker", (0.3, 0.36, 0.25), (P.STEEL, P.GLASS), {"slow": True}),
            V(
                "red",
                "a red crock pot",
                (0.28, 0.34, 0.24),
                (P.RED, P.GLASS),
                {"slow": True},
                synonyms=("crock pot", "crockpot"),
            ),
            V("cream", "a cream ceramic slow cooker", (0.3, 0.36, 0.26), (P.CREAM, P.GLASS), {"slow": True}),
            V("small_white", "a small white slow cooker", (0.24, 0.29, 0.2), (P.WHITE, P.GLASS), {"slow": True}),
            V("large_grey", "a large grey slow cooker", (0.34, 0.41, 0.28), (P.GREY, P.GLASS), {"slow": True}),
            V(
                "brown",
                "a brown stoneware crockpot",
                (0.3, 0.36, 0.25),
                (P.BROWN, P.GLASS),
                {"slow": True},
                synonyms=("crock pot", "crockpot"),
            ),
        ],
        density=320.0,
        mass_limits=(2.0, 9.0),
        friction=(0.5, 0.8),
        support_probability=0.1,
        synonyms=("crock pot", "crockpot", "slow-cooker", "electric casserole"),
        tags=("kitchen", "appliance", "stew", "cooking", "counter"),
    ),
    define(
        "salad spinner",
        "salad spinner",
        salad_spinner,
        [
            V("green", "a clear salad spinner with a green pump", (0.26, 0.26, 0.16)),
            V("white", "a white salad spinner", (0.25, 0.25, 0.15), (P.WHITE, P.WHITE, P.GREY)),
            V("red", "a red salad spinner with a clear bowl", (0.26, 0.26, 0.16), (P.GLASS, P.RED, P.RED)),
            V("large", "a large salad spinner", (0.3, 0.3, 0.18), (P.GLASS, P.WHITE, P.BLACK)),
            V(
                "small",
                "a small herb spinner",
                (0.2, 0.2, 0.13),
                (P.GLASS, P.LIME, P.GREEN),
                synonyms=("herb spinner",),
            ),
            V("steel", "a steel salad spinner", (0.27, 0.27, 0.17), (P.STEEL, P.BLACK, P.BLACK), density=220.0),
            V("blue", "a blue salad spinner", (0.26, 0.26, 0.16), (P.SKY, P.BLUE, P.BLUE)),
        ],
        density=120.0,
        mass_limits=(0.2, 2.0),
        friction=(0.4, 0.7),
        support_probability=0.2,
        has_front=False,
        synonyms=("salad dryer", "lettuce spinner", "herb spinner", "salad drier"),
        tags=("kitchen", "salad", "lettuce", "washing", "vegetables", "plastic"),
    ),
    define(
        "gravy boat",
        "gravy boat",
        gravy_boat,
        [
            V("white", "a white porcelain gravy boat", (0.2, 0.09, 0.09)),
            V("cream", "a cream sauce boat", (0.19, 0.085, 0.085), (P.CREAM,), synonyms=("sauce boat",)),
            V("steel", "a stainless steel gravy boat", (0.2, 0.09, 0.09), (P.STEEL,), density=1200.0),
            V("blue", "a blue ceramic gravy boat", (0.2, 0.09, 0.09), (P.SKY,)),
            V("small", "a small white creamer boat", (0.15, 0.07, 0.07), synonyms=("sauce boat",)),
            V("large", "a large white gravy jug", (0.24, 0.11, 0.11), synonyms=("gravy jug",)),
            V(
                "silver",
                "a silver sauce boat",
                (0.2, 0.09, 0.085),
                (P.SILVER,),
                density=1200.0,
                synonyms=("sauce boat",),
            ),
        ],
        density=800.0,
        mass_limits=(0.08, 1.0),
        friction=(0.4, 0.7),
        support_probability=0.0,
        synonyms=("sauce boat", "gravy jug", "sauceboat", "gravy pitcher", "gravy"),
        tags=("dining", "table", "sauce", "gravy", "porcelain", "serving", "dinner"),
    ),
    define(
        "thermos",
        "thermos",
        thermos,
        [
            V("steel", "a stainless steel vacuum flask with a black cup lid", (0.075, 0.075, 0.3)),
            V("green", "a green insulated thermos", (0.09, 0.09, 0.32), (P.DARK_GREEN, P.STEEL)),
            V("red", "a red vacuum flask", (0.075, 0.075, 0.28), (P.RED, P.CHARCOAL)),
            V("black", "a black insulated flask", (0.08, 0.08, 0.3), (P.BLACK, P.STEEL)),
            V(
                "small_blue",
                "a small blue thermos for soup",
                (0.1, 0.1, 0.17),
                (P.BLUE, P.WHITE),
                synonyms=("food flask", "food jar"),
            ),
            V("large_steel", "a large steel flask for coffee", (0.1, 0.1, 0.36), (P.STEEL, P.BLACK)),
            V("cream", "a cream thermos with a wooden lid", (0.075, 0.075, 0.26), (P.CREAM, P.WOOD)),
        ],
        density=450.0,
        mass_limits=(0.2, 1.5),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("vacuum flask", "thermos flask", "insulated flask", "thermal flask", "hot drink flask"),
        tags=("kitchen", "coffee", "tea", "picnic", "hot", "insulated", "camping"),
    ),
    define(
        "cocktail shaker",
        "cocktail shaker",
        cocktail_shaker,
        [
            V("steel", "a stainless steel cocktail shaker", (0.09, 0.09, 0.24)),
            V("copper", "a copper cocktail shaker", (0.09, 0.09, 0.24), (P.rgb(190, 110, 60),)),
            V("gold", "a gold cocktail shaker", (0.085, 0.085, 0.22), (P.GOLD,)),
            V("black", "a matte black cocktail shaker", (0.09, 0.09, 0.24), (P.BLACK,)),
            V("small", "a small steel drinks shaker", (0.075, 0.075, 0.19), (P.SILVER,)),
            V("glass_steel", "a glass cocktail shaker with a steel top", (0.09, 0.09, 0.25), (P.GLASS, P.STEEL)),
            V("large", "a large bar shaker", (0.1, 0.1, 0.27), (P.STEEL,)),
        ],
        density=330.0,
        mass_limits=(0.1, 0.8),
        friction=(0.3, 0.6),
        support_probability=0.0,
        has_front=False,
        synonyms=("drinks shaker", "bar shaker", "martini shaker", "boston shaker", "steel shaker"),
        tags=("kitchen", "bar", "drinks", "cocktails", "martini", "mixing", "steel"),
    ),
    define(
        "can opener",
        "can opener",
        flat_tool,
        [
            V("black", "a steel can opener with black handles", (0.2, 0.06, 0.03)),
            V("red", "a can opener with red grips", (0.2, 0.06, 0.03), (P.RED, P.STEEL)),
            V(
                "steel",
                "an all-steel tin opener",
                (0.18, 0.055, 0.025),
                (P.STEEL, P.SILVER),
                density=2500.0,
                synonyms=("tin opener",),
            ),
            V("green", "a green-handled tin opener", (0.2, 0.06, 0.03), (P.GREEN, P.STEEL), synonyms=("tin opener",)),
            V("white", "a white can opener", (0.19, 0.06, 0.03), (P.WHITE, P.STEEL)),
            V("large", "a large heavy-duty can opener", (0.23, 0.07, 0.035), (P.BLACK, P.STEEL)),
            V("blue", "a blue can opener", (0.2, 0.06, 0.03), (P.BLUE, P.STEEL)),
        ],
        density=1300.0,
        mass_limits=(0.05, 0.5),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("tin opener", "can-opener", "canopener", "opening tool", "can opening tool"),
        tags=("kitchen", "utensil", "cans", "tins", "opening"),
    ),
    define(
        "pizza cutter",
        "pizza cutter",
        flat_tool,
        [
            V(
                "black",
                "a pizza cutter wheel with a black handle",
                (0.22, 0.1, 0.025),
                options={"tool": "pizza_cutter"},
            ),
            V("red", "a pizza wheel with a red handle", (0.22, 0.1, 0.025), (P.RED, P.STEEL), {"tool": "pizza_cutter"}),
            V(
                "steel",
                "an all-steel pizza cutter",
                (0.21, 0.09, 0.022),
                (P.STEEL, P.SILVER),
                {"tool": "pizza_cutter"},
                density=2500.0,
            ),
            V(
                "wood",
                "a pizza cutter with a wooden handle",
                (0.23, 0.1, 0.025),
                (P.WOOD, P.STEEL),
                {"tool": "pizza_cutter"},
                density=800.0,
            ),
            V("large", "a large pizza wheel", (0.26, 0.12, 0.03), (P.BLACK, P.STEEL), {"tool": "pizza_cutter"}),
            V(
                "green",
                "a green pizza slicer",
                (0.21, 0.09, 0.024),
                (P.GREEN, P.STEEL),
                {"tool": "pizza_cutter"},
                synonyms=("pizza slicer",),
            ),
            V("white", "a white pizza cutter", (0.22, 0.1, 0.025), (P.WHITE, P.STEEL), {"tool": "pizza_cutter"}),
        ],
        density=1100.0,
        mass_limits=(0.04, 0.5),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("pizza wheel", "pizza slicer", "rolling cutter", "pizza knife"),
        tags=("kitchen", "utensil", "pizza", "cutting", "wheel"),
    ),
    define(
        "dish brush",
        "dish brush",
        flat_tool,
        [
            V(
                "blue",
                "a blue dish brush with a long handle",
                (0.26, 0.06, 0.04),
                (P.BLUE, P.WHITE),
                {"tool": "dish_brush"},
            ),
            V(
                "wood",
                "a wooden dish brush with natural bristles",
                (0.25, 0.06, 0.04),
                (P.WOOD, P.BAMBOO),
                {"tool": "dish_brush"},
                density=500.0,
            ),
            V(
                "green",
                "a green washing-up brush",
                (0.26, 0.06, 0.04),
                (P.GREEN, P.WHITE),
                {"tool": "dish_brush"},
                synonyms=("washing up brush",),
            ),
            V("white", "a white dish scrub brush", (0.24, 0.055, 0.038), (P.WHITE, P.GREY), {"tool": "dish_brush"}),
            V(
                "red",
                "a red kitchen scrubbing brush",
                (0.25, 0.06, 0.04),
                (P.RED, P.WHITE),
                {"tool": "dish_brush"},
                synonyms=("scrubbing brush",),
            ),
            V(
                "bottle",
                "a narrow bottle brush",
                (0.3, 0.04, 0.035),
                (P.GREY, P.WHITE),
                {"tool": "dish_brush"},
                synonyms=("bottle brush",),
            ),
            V("black", "a black dish brush", (0.26, 0.06, 0.04), (P.BLACK, P.GREY), {"tool": "dish_brush"}),
        ],
        density=350.0,
        mass_limits=(0.02, 0.2),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=False,
        synonyms=("washing up brush", "scrubbing brush", "dishwashing brush", "scrub brush", "pot brush"),
        tags=("kitchen", "sink", "cleaning", "washing up", "bristles"),
    ),
    define(
        "ice cube tray",
        "ice cube tray",
        baking_tray,
        [
            V("white", "a white plastic ice cube tray", (0.28, 0.1, 0.035), (P.WHITE,), {"cups": 7, "square": True}),
            V("blue", "a blue silicone ice cube tray", (0.28, 0.1, 0.035), (P.SKY,), {"cups": 7, "square": True}),
            V("clear", "a clear ice cube tray", (0.26, 0.1, 0.03), (P.GLASS,), {"cups": 7, "square": True}),
            V(
                "large_cubes",
                "a grey tray for large ice cubes",
                (0.2, 0.1, 0.05),
                (P.GREY,),
                {"cups": 4, "square": True},
                synonyms=("ice mould",),
            ),
            V("green", "a green ice tray", (0.28, 0.1, 0.035), (P.LIME,), {"cups": 7, "square": True}),
            V("pink", "a pink silicone ice tray", (0.24, 0.11, 0.03), (P.PINK,), {"cups": 6, "square": True}),
            V(
                "round_balls",
                "a black ice tray with round pockets",
                (0.2, 0.1, 0.04),
                (P.BLACK,),
                {"cups": 4},
                synonyms=("ice sphere tray",),
            ),
        ],
        density=320.0,
        mass_limits=(0.03, 0.4),
        friction=(0.4, 0.7),
        support_probability=0.2,
        has_front=False,
        synonyms=("ice tray", "ice cube mould", "ice mold", "ice cube mold", "ice maker tray"),
        tags=("kitchen", "freezer", "ice", "drinks", "plastic", "silicone"),
    ),
    define(
        "air fryer",
        "air fryer",
        air_fryer,
        [
            V("black", "a black air fryer with a pull-out basket", (0.3, 0.27, 0.32)),
            V("white", "a white air fryer", (0.3, 0.27, 0.32), (P.WHITE, P.GREY)),
            V("steel", "a stainless steel air fryer", (0.32, 0.28, 0.33), (P.STEEL, P.BLACK)),
            V("compact_grey", "a compact grey air fryer", (0.26, 0.23, 0.28), (P.GREY, P.CHARCOAL)),
            V("large_black", "a large black family air fryer", (0.38, 0.33, 0.36), (P.BLACK, P.CHARCOAL)),
            V("red", "a red air fryer", (0.3, 0.27, 0.31), (P.RED, P.BLACK)),
            V("cream", "a cream retro air fryer", (0.3, 0.27, 0.31), (P.CREAM, P.BROWN)),
        ],
        density=180.0,
        mass_limits=(2.0, 9.0),
        friction=(0.5, 0.8),
        support_probability=0.3,
        synonyms=("airfryer", "air-fryer", "hot air fryer", "fryer"),
        tags=("kitchen", "appliance", "frying", "cooking", "counter"),
    ),
    define(
        "toaster oven",
        "toaster oven",
        microwave,
        [
            V(
                "steel",
                "a stainless steel toaster oven with a glass door",
                (0.33, 0.45, 0.24),
                (P.STEEL, P.rgb(60, 45, 35), P.BLACK),
                {"handle": True, "panel": 0.3},
            ),
            V(
                "black",
                "a black countertop toaster oven",
                (0.33, 0.45, 0.24),
                (P.BLACK, P.rgb(60, 45, 35), P.CHARCOAL),
                {"handle": True, "panel": 0.3},
            ),
            V(
                "small_white",
                "a small white mini oven",
                (0.3, 0.4, 0.22),
                (P.WHITE, P.rgb(60, 45, 35), P.GREY),
                {"handle": True, "panel": 0.3},
                synonyms=("mini oven",),
            ),
            V(
                "red",
                "a red toaster oven",
                (0.33, 0.45, 0.24),
                (P.RED, P.rgb(60, 45, 35), P.BLACK),
                {"handle": True, "panel": 0.3},
            ),
            V(
                "large",
                "a large convection countertop oven",
                (0.4, 0.52, 0.28),
                (P.SILVER, P.rgb(60, 45, 35), P.BLACK),
                {"handle": True, "panel": 0.28},
                synonyms=("convection oven",),
            ),
            V(
                "cream",
                "a cream retro toaster oven",
                (0.33, 0.44, 0.24),
                (P.CREAM, P.rgb(60, 45, 35), P.BROWN),
                {"handle": True, "panel": 0.3},
            ),
            V(
                "grey",
                "a grey pizza oven for the counter",
                (0.35, 0.45, 0.2),
                (P.GREY, P.rgb(60, 45, 35), P.BLACK),
                {"handle": True, "panel": 0.3},
                synonyms=("pizza oven",),
            ),
        ],
        density=230.0,
        mass_limits=(3.0, 15.0),
        friction=(0.5, 0.8),
        support_probability=0.5,
        synonyms=("mini oven", "countertop oven", "convection oven", "toaster-oven", "benchtop oven"),
        tags=("kitchen", "appliance", "baking", "toasting", "counter"),
    ),
    define(
        "coffee grinder",
        "coffee grinder",
        coffee_grinder,
        [
            V("burr_black", "a black burr coffee grinder with a bean hopper", (0.16, 0.13, 0.34)),
            V("burr_steel", "a stainless steel burr grinder", (0.16, 0.13, 0.35), (P.STEEL, P.BLACK)),
            V("burr_red", "a red coffee bean grinder", (0.15, 0.12, 0.32), (P.RED, P.SILVER)),
            V(
                "blade_black",
                "a small black blade coffee grinder",
                (0.09, 0.09, 0.17),
                options={"burr": False},
                density=600.0,
            ),
            V(
                "blade_white",
                "a white electric spice and coffee mill",
                (0.09, 0.09, 0.17),
                (P.WHITE, P.GLASS),
                {"burr": False},
                density=600.0,
            ),
            V(
                "blade_steel",
                "a steel blade grinder with a clear cap",
                (0.1, 0.1, 0.18),
                (P.STEEL, P.GLASS),
                {"burr": False},
                density=600.0,
            ),
            V("burr_white", "a white burr coffee mill", (0.15, 0.12, 0.32), (P.WHITE, P.SILVER)),
        ],
        density=350.0,
        mass_limits=(0.4, 4.0),
        friction=(0.5, 0.8),
        support_probability=0.05,
        synonyms=("coffee mill", "bean grinder", "burr grinder", "coffee bean grinder"),
        tags=("kitchen", "appliance", "coffee", "beans", "grinding", "counter"),
    ),
    define(
        "citrus juicer",
        "citrus juicer",
        citrus_juicer,
        [
            V("glass", "a glass hand juicer with a ribbed cone", (0.15, 0.15, 0.08)),
            V(
                "white_plastic",
                "a white plastic lemon squeezer",
                (0.14, 0.14, 0.08),
                (P.WHITE,),
                density=500.0,
                synonyms=("lemon squeezer",),
            ),
            V(
                "yellow",
                "a yellow lemon juicer",
                (0.13, 0.13, 0.07),
                (P.YELLOW,),
                density=500.0,
                synonyms=("lemon squeezer",),
            ),
            V(
                "electric_white",
                "a white electric citrus press",
                (0.18, 0.18, 0.2),
                (P.GLASS, P.WHITE),
                {"electric": True},
                density=400.0,
                synonyms=("citrus press",),
            ),
            V(
                "electric_steel",
                "a steel electric orange juicer",
                (0.19, 0.19, 0.22),
                (P.GLASS, P.STEEL),
                {"electric": True},
                density=400.0,
                synonyms=("orange juicer",),
            ),
            V(
                "ceramic_blue",
                "a blue ceramic citrus reamer dish",
                (0.14, 0.14, 0.08),
                (P.SKY,),
                density=900.0,
                synonyms=("reamer",),
            ),
            V("green", "a green plastic lime squeezer", (0.12, 0.12, 0.065), (P.LIME,), density=500.0),
        ],
        density=700.0,
        mass_limits=(0.05, 2.0),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("juicer", "lemon squeezer", "orange juicer", "citrus press", "reamer", "juice squeezer"),
        tags=("kitchen", "juice", "lemon", "orange", "citrus", "squeezing"),
    ),
    define(
        "waffle maker",
        "waffle maker",
        waffle_maker,
        [
            V("black", "a black waffle maker with a silver lid", (0.3, 0.24, 0.11)),
            V(
                "steel",
                "a stainless steel waffle iron",
                (0.32, 0.25, 0.12),
                (P.STEEL, P.STEEL),
                synonyms=("waffle iron",),
            ),
            V("red", "a red round waffle maker", (0.28, 0.22, 0.1), (P.RED, P.RED)),
            V(
                "white",
                "a white sandwich toaster",
                (0.28, 0.22, 0.1),
                (P.WHITE, P.WHITE),
                synonyms=("sandwich maker", "toastie maker"),
            ),
            V(
                "panini",
                "a black panini press grill",
                (0.36, 0.3, 0.13),
                (P.BLACK, P.STEEL),
                synonyms=("panini press", "contact grill"),
            ),
            V("mini_blue", "a small blue waffle maker", (0.2, 0.16, 0.09), (P.SKY, P.WHITE)),
            V("cream", "a cream waffle iron", (0.3, 0.24, 0.11), (P.CREAM, P.SILVER), synonyms=("waffle iron",)),
        ],
        density=220.0,
        mass_limits=(0.4, 5.0),
        friction=(0.5, 0.8),
        support_probability=0.5,
        synonyms=("waffle iron", "sandwich maker", "panini press", "toastie maker", "waffle machine"),
        tags=("kitchen", "appliance", "breakfast", "waffles", "counter"),
    ),
    define(
        "kitchen timer",
        "kitchen timer",
        kitchen_timer,
        [
            V("white_dial", "a white wind-up kitchen timer with a red top", (0.07, 0.07, 0.06)),
            V("red_dial", "a red dial egg timer", (0.065, 0.065, 0.055), (P.RED, P.WHITE), synonyms=("egg timer",)),
            V("steel_dial", "a steel kitchen timer", (0.07, 0.07, 0.06), (P.STEEL, P.BLACK), density=900.0),
            V(
                "digital_white",
                "a white digital kitchen timer",
                (0.025, 0.07, 0.07),
                (P.WHITE, P.CHARCOAL),
                {"digital": True},
                synonyms=("digital timer",),
            ),
            V(
                "digital_black",
                "a black digital cooking timer",
                (0.025, 0.07, 0.07),
                (P.BLACK, P.SKY),
                {"digital": True},
                synonyms=("digital timer",),
            ),
            V("yellow_dial", "a yellow egg timer", (0.06, 0.06, 0.05), (P.YELLOW, P.WHITE), synonyms=("egg timer",)),
            V("mint_dial", "a mint green minute timer", (0.07, 0.07, 0.06), (P.rgb(160, 220, 200), P.WHITE)),
        ],
        density=450.0,
        mass_limits=(0.02, 0.3),
        friction=(0.5, 0.8),
        support_probability=0.0,
        synonyms=("egg timer", "cooking timer", "minute timer", "timer"),
        tags=("kitchen", "cooking", "baking", "time", "counter"),
    ),
    define(
        "funnel",
        "funnel",
        funnel,
        [
            V("steel", "a stainless steel kitchen funnel", (0.12, 0.12, 0.12)),
            V("white", "a white plastic funnel", (0.12, 0.12, 0.12), (P.WHITE,), density=400.0),
            V("red", "a red plastic funnel", (0.1, 0.1, 0.1), (P.RED,), density=400.0),
            V("large", "a large steel jam funnel", (0.15, 0.15, 0.1), (P.STEEL,), synonyms=("jam funnel",)),
            V("small", "a small funnel for spices and oil", (0.07, 0.07, 0.08), (P.SILVER,)),
            V("blue", "a blue silicone funnel", (0.11, 0.11, 0.1), (P.SKY,), density=500.0),
            V("copper", "a copper funnel", (0.12, 0.12, 0.12), (P.rgb(190, 110, 60),)),
        ],
        density=700.0,
        mass_limits=(0.01, 0.4),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("kitchen funnel", "jam funnel", "filler funnel", "pouring funnel"),
        tags=("kitchen", "pouring", "cooking", "cone"),
    ),
    define(
        "water filter jug",
        "water filter jug",
        filter_jug,
        [
            V("blue", "a clear water filter jug with a blue lid", (0.26, 0.11, 0.26)),
            V("white", "a water filter pitcher with a white lid", (0.26, 0.11, 0.26), (P.GLASS, P.WHITE)),
            V("grey", "a filter jug with a grey lid", (0.25, 0.1, 0.25), (P.GLASS, P.GREY)),
            V("large", "a large water filter jug", (0.28, 0.12, 0.28), (P.GLASS, P.NAVY)),
            V("green", "a filter jug with a green lid", (0.25, 0.1, 0.25), (P.GLASS, P.GREEN)),
            V("small", "a small filter jug for the fridge door", (0.22, 0.09, 0.23), (P.GLASS, P.SKY)),
            V("black", "a water filtering carafe with a black lid", (0.26, 0.11, 0.26), (P.GLASS, P.BLACK)),
        ],
        density=450.0,
        mass_limits=(0.3, 3.5),
        friction=(0.4, 0.7),
        support_probability=0.0,
        synonyms=("filter jug", "water filter pitcher", "filter pitcher", "brita", "water filter"),
        tags=("kitchen", "fridge", "water", "filtered", "drinking"),
    ),
    define(
        "egg",
        "egg",
        egg,
        [
            V("white", "a white hen's egg lying on its side", (0.058, 0.044, 0.044)),
            V("brown", "a brown egg", (0.058, 0.044, 0.044), (P.rgb(200, 150, 100),)),
            V("large_brown", "a large brown free-range egg", (0.062, 0.047, 0.047), (P.rgb(190, 135, 90),)),
            V("standing", "a white egg standing upright", (0.044, 0.044, 0.058), options={"lying": False}),
            V(
                "boiled",
                "a peeled hard-boiled egg",
                (0.055, 0.042, 0.042),
                (P.rgb(250, 248, 240),),
                synonyms=("boiled egg", "hard-boiled egg"),
            ),
            V("duck", "a pale blue duck egg", (0.065, 0.048, 0.048), (P.rgb(200, 225, 220),), synonyms=("duck egg",)),
            V(
                "quail",
                "a small speckled quail egg",
                (0.033, 0.026, 0.026),
                (P.rgb(210, 195, 170),),
                synonyms=("quail egg",),
            ),
            V(
                "chocolate",
                "a chocolate easter egg",
                (0.07, 0.05, 0.05),
                (P.DARK_BROWN,),
                density=1000.0,
                synonyms=("easter egg", "chocolate egg"),
            ),
        ],
        density=1030.0,
        mass_limits=(0.005, 0.12),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("eggs", "hen's egg", "chicken egg", "fresh egg", "raw egg"),
        tags=("food", "breakfast", "kitchen", "baking", "fridge", "protein"),
    ),
    define(
        "cookie",
        "cookie",
        cookie,
        [
            V("chocolate_chip", "a round chocolate chip cookie", (0.075, 0.075, 0.012), options={"chips": 7}),
            V(
                "oatmeal",
                "an oatmeal raisin cookie",
                (0.08, 0.08, 0.013),
                (P.rgb(190, 150, 100), P.rgb(90, 40, 50)),
                {"chips": 6},
                synonyms=("oatmeal cookie",),
            ),
            V("sugar", "a pale sugar cookie", (0.07, 0.07, 0.01), (P.rgb(240, 215, 160),), synonyms=("sugar cookie",)),
            V(
                "sandwich",
                "a chocolate sandwich cookie with a cream filling",
                (0.045, 0.045, 0.014),
                (P.rgb(50, 35, 30), P.WHITE),
                {"sandwich": True},
                synonyms=("oreo", "cream biscuit"),
            ),
            V(
                "digestive",
                "a round digestive biscuit",
                (0.068, 0.068, 0.009),
                (P.rgb(200, 160, 100),),
                synonyms=("biscuit", "digestive"),
            ),
            V(
                "cracker",
                "a square cream cracker",
                (0.065, 0.065, 0.006),
                (P.rgb(230, 200, 140),),
                {"square": True},
                synonyms=("cracker", "crackers"),
            ),
            V(
                "double_chocolate",
                "a double chocolate cookie with white chips",
                (0.08, 0.08, 0.013),
                (P.rgb(80, 50, 35), P.WHITE),
                {"chips": 7},
            ),
            V(
                "macaron_pink",
                "a pink macaron",
                (0.045, 0.045, 0.022),
                (P.PINK, P.WHITE),
                {"sandwich": True},
                density=500.0,
                synonyms=("macaron", "macaroon"),
            ),
        ],
        density=650.0,
        mass_limits=(0.004, 0.06),
        friction=(0.5, 0.8),
        support_probability=0.6,
        has_front=False,
        synonyms=("cookies", "biscuit", "biscuits", "cracker", "baked treat"),
        tags=("food", "snack", "dessert", "baking", "sweet", "flat"),
    ),
    define(
        "wok",
        "wok",
        wok,
        [
            V("carbon_steel", "a black carbon steel wok with a wooden handle", (0.55, 0.33, 0.1)),
            V("nonstick", "a nonstick wok with a black handle", (0.52, 0.3, 0.09), (P.BLACK, P.BLACK)),
            V("steel", "a stainless steel wok", (0.55, 0.32, 0.1), (P.STEEL, P.BLACK)),
            V("large", "a large cast iron wok", (0.6, 0.36, 0.11), (P.CHARCOAL, P.DARK_BROWN), density=5000.0),
            V("small", "a small wok for one", (0.42, 0.24, 0.07), (P.CHARCOAL, P.WOOD), {"helper": False}),
            V(
                "red",
                "a red enamel stir-fry pan",
                (0.5, 0.28, 0.085),
                (P.RED, P.BLACK),
                {"helper": False},
                synonyms=("stir fry pan", "stir-fry pan"),
            ),
            V("copper", "a copper wok with a wooden handle", (0.52, 0.3, 0.09), (P.rgb(190, 110, 60), P.WOOD)),
        ],
        density=3000.0,
        mass_limits=(0.5, 5.0),
        friction=(0.4, 0.7),
        support_probability=0.1,
        synonyms=("stir fry pan", "stir-fry pan", "wok pan", "chinese wok"),
        tags=("kitchen", "cooking", "stir fry", "stove", "asian", "container"),
    ),
    define(
        "steamer",
        "steamer",
        steamer,
        [
            V("two_tier", "a two-tier bamboo steamer with a lid", (0.25, 0.25, 0.15)),
            V("three_tier", "a three-tier bamboo steamer", (0.25, 0.25, 0.2), options={"tiers": 3}),
            V(
                "small",
                "a small bamboo dim sum steamer",
                (0.15, 0.15, 0.1),
                options={"tiers": 1},
                synonyms=("dim sum basket",),
            ),
            V("large", "a large bamboo steamer basket", (0.3, 0.3, 0.18)),
            V("dark", "a dark bamboo steamer", (0.25, 0.25, 0.15), (P.rgb(170, 130, 80), P.DARK_BROWN)),
            V(
                "steel",
                "a stainless steel two-tier steamer pot",
                (0.24, 0.24, 0.2),
                (P.STEEL, P.SILVER, P.GLASS),
                density=300.0,
                synonyms=("steamer pot",),
            ),
            V("single", "a single bamboo steamer basket with lid", (0.2, 0.2, 0.11), options={"tiers": 1}),
        ],
        density=160.0,
        mass_limits=(0.1, 3.0),
        friction=(0.5, 0.8),
        support_probability=0.5,
        has_front=False,
        synonyms=("bamboo steamer", "steamer basket", "dim sum steamer", "food steamer", "dumpling steamer"),
        tags=("kitchen", "cooking", "dumplings", "dim sum", "bamboo", "asian", "lidded"),
    ),
    define(
        "cake tin",
        "cake tin",
        oven_dish,
        [
            V("round", "a round metal cake tin", (0.23, 0.23, 0.07), (P.SILVER,), {"outline": "round", "wall": 0.003}),
            V(
                "springform",
                "a springform cake pan",
                (0.26, 0.26, 0.075),
                (P.CHARCOAL,),
                {"outline": "round", "wall": 0.004},
                synonyms=("springform pan",),
            ),
            V(
                "small_round",
                "a small round sandwich tin",
                (0.2, 0.2, 0.04),
                (P.SILVER,),
                {"outline": "round", "wall": 0.003},
                synonyms=("sandwich tin",),
            ),
            V(
                "square",
                "a square cake tin",
                (0.23, 0.23, 0.06),
                (P.SILVER,),
                {"wall": 0.003},
                synonyms=("square cake pan", "brownie tin"),
            ),
            V(
                "loaf",
                "a metal loaf tin",
                (0.26, 0.12, 0.075),
                (P.CHARCOAL,),
                {"wall": 0.003},
                synonyms=("loaf tin", "loaf pan", "bread tin"),
            ),
            V(
                "loaf_silicone",
                "a red silicone loaf pan",
                (0.26, 0.12, 0.07),
                (P.RED,),
                {"wall": 0.004},
                density=1400.0,
                synonyms=("loaf pan", "loaf tin"),
            ),
            V(
                "gold_round",
                "a gold nonstick cake pan",
                (0.23, 0.23, 0.06),
                (P.GOLD,),
                {"outline": "round", "wall": 0.003},
                synonyms=("cake pan",),
            ),
        ],
        density=3000.0,
        mass_limits=(0.1, 1.5),
        friction=(0.3, 0.6),
        support_probability=0.4,
        has_front=False,
        synonyms=("cake pan", "baking tin", "cake mould", "baking pan for cakes"),
        tags=("kitchen", "baking", "oven", "cake", "bread", "metal", "container", "open"),
    ),
    define(
        "apron",
        "apron",
        apron,
        [
            V("navy", "a folded navy cotton apron with a pocket", (0.3, 0.25, 0.02)),
            V("red_check", "a folded red kitchen apron", (0.3, 0.25, 0.02), (P.RED, P.WHITE)),
            V(
                "white",
                "a folded white chef's apron",
                (0.32, 0.26, 0.02),
                (P.WHITE, P.GREY),
                synonyms=("chef's apron",),
            ),
            V("denim", "a folded blue denim apron", (0.3, 0.25, 0.025), (P.BLUE, P.NAVY)),
            V("striped", "a folded green striped apron", (0.3, 0.24, 0.02), (P.GREEN, P.CREAM)),
            V("leather", "a folded brown leather apron", (0.32, 0.26, 0.025), (P.BROWN, P.DARK_BROWN), density=400.0),
            V(
                "kids",
                "a small yellow children's apron",
                (0.22, 0.18, 0.015),
                (P.YELLOW, P.ORANGE),
                {"pocket": False},
                synonyms=("kids apron",),
            ),
        ],
        density=150.0,
        mass_limits=(0.03, 0.8),
        friction=(0.6, 0.9),
        support_probability=0.6,
        has_front=False,
        synonyms=("kitchen apron", "cooking apron", "pinafore", "chef's apron", "pinny"),
        tags=("kitchen", "cooking", "baking", "fabric", "cotton", "folded", "soft", "flat"),
    ),
)
