"""Kitchen and dining: small appliances, cookware and utensils, condiments, cartons, crates, racks and mats.

Closed objects are drawn in proportion to their size and fitted to it exactly (`fit_to_size`), with convex hulls for
collision; containers (colander, dish rack, crate, measuring cup, egg cup) are built to their size with open walls
and a `Cavity`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.gen.common import Vessel, fit_to_size, loop_handle, rectangle, resample, spout
from physcensis.assets.model import RGBA, Cavity, CollisionPart
from physcensis.assets.spec import CategoryDef, Geometry, Parts, Variant, builder, define
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
    """Eggs per row (two rows), and the lid open (eggs showing, lid removed) instead of closed."""

    per_row: int = 6
    open: bool = False


@builder(EggCartonShape)
def egg_carton(v: Variant, p: EggCartonShape) -> Geometry:
    """An egg carton of two rows along y: a moulded pulp tray with a closed ridged lid, or open with eggs showing."""
    x, y, z = v.size
    color = v.color(0, P.rgb(200, 190, 170))
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
                synonyms=("pepper shaker",),
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
        synonyms=("salt cellar", "pepper shaker", "salt and pepper shaker", "shaker", "cruet", "salt", "salt pot"),
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
        synonyms=("pop-up toaster", "bread toaster", "two-slice toaster", "toaster oven"),
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
        mass_limits=(0.1, 1.4),
        friction=(0.5, 0.8),
        support_probability=0.3,
        has_front=False,
        synonyms=("egg box", "eggs", "carton of eggs", "box of eggs", "dozen eggs", "egg"),
        tags=("kitchen", "fridge", "breakfast", "eggs", "pulp", "cardboard"),
    ),
)
