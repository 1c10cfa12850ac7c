"""Bathroom, bedroom and living room objects: toiletries, grooming tools, bins, cushions, blankets, accessories."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

import numpy as np
import trimesh
from shapely.affinity import scale as shapely_scale
from shapely.geometry import Point, Polygon
from shapely.geometry import box as shapely_box
from shapely.ops import unary_union

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.gen.boxes import open_tray
from physcensis.assets.gen.common import Vessel, fit_to_size, rectangle, resample
from physcensis.assets.gen.variant_data import builtin_categories
from physcensis.assets.model import RGBA, Cavity, CollisionPart
from physcensis.assets.spec import CategoryDef, Geometry, NoOptions, Variant, builder


def _superellipse(a: float, b: float, n: float = 2.0, count: int = 48) -> np.ndarray:
    """Points of |x/a|^n + |y/b|^n = 1 (n = 2: an ellipse; larger n: squarer)."""
    t = np.linspace(0.0, 2 * np.pi, count, endpoint=False)
    c, s = np.cos(t), np.sin(t)
    return np.stack([a * np.sign(c) * np.abs(c) ** (2 / n), b * np.sign(s) * np.abs(s) ** (2 / n)], axis=1)


def _hull(points: np.ndarray) -> trimesh.Trimesh:
    """The convex hull, with points closer than a micron merged first (near-duplicates leave the hull open)."""
    return shapes.hull(np.round(np.asarray(points, dtype=float), 6))


def _loft(sections: Sequence[tuple[float, float, float]], n: float = 2.0, count: int = 48) -> trimesh.Trimesh:
    """The convex hull of superellipse rings, each (width along x, depth along y, height z): bottles, bars, pouches."""
    rings = [np.column_stack([_superellipse(w / 2, d / 2, n, count), np.full(count, z)]) for w, d, z in sections]
    return _hull(np.vstack(rings))


def _open_box_mesh(x: float, y: float, z: float, wall: float, floor: float, radius: float = 0.0) -> trimesh.Trimesh:
    outer = shapes.slab(x, y, z, radius, (0, 0, z / 2))
    inner = shapes.slab(x - 2 * wall, y - 2 * wall, z, max(0.0, radius - wall), (0, 0, floor + z / 2))
    return trimesh.boolean.difference([outer, inner], engine="manifold")


_XYZ_TO_YZX = np.array([[0.0, 0, 1, 0], [1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 1]])  # x -> y, y -> z, z -> x


def _turned(mesh: trimesh.Trimesh, matrix: np.ndarray) -> trimesh.Trimesh:
    out = mesh.copy()
    out.apply_transform(matrix)
    return out


# --- toiletries -----------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class SoapBarShape:
    """An oval bar instead of a rectangular one; a paper wrapper band around the middle."""

    oval: bool = False
    wrapped: bool = False


@builder(SoapBarShape)
def soap_bar(v: Variant, p: SoapBarShape) -> Geometry:
    """A bar of soap with softly rounded edges and a raised logo; one convex hull."""
    x, y, z = v.size
    n = 2.0 if p.oval else 5.0
    body = _loft([(0.9 * x, 0.9 * y, 0.0), (x, y, 0.25 * z), (x, y, 0.6 * z), (0.86 * x, 0.86 * y, z - 0.0006)], n)
    logo = _loft([(0.45 * x, 0.3 * y, z - 0.001), (0.45 * x, 0.3 * y, z)], 2.0)
    color = v.color(0, P.WHITE)
    parts = [(body, color), (logo, v.color(1, color))]
    if p.wrapped:
        parts.append((shapes.box((0.45 * x, y, z), (0, 0, z / 2)), v.color(2, P.PAPER)))
        return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))
    return Geometry(tuple(parts), (col.hull_part(body),))


@dataclass(frozen=True)
class ShampooShape:
    """The closure: a "flip" cap, a "pump", or a wide "disc" cap the bottle stands upside down on; the body's
    squareness (2: oval, larger: squarer)."""

    closure: Literal["flip", "pump", "disc"] = "flip"
    squareness: float = 3.0


@builder(ShampooShape)
def shampoo_bottle(v: Variant, p: ShampooShape) -> Geometry:
    """A squeezable oval plastic bottle with a flip cap, a pump head, or standing upside down on its cap."""
    x, y, h = v.size
    body_color, cap_color = v.color(0, P.BLUE), v.color(1, P.WHITE)
    n = p.squareness
    if p.closure == "disc":
        cap_h = 0.12 * h
        cap = _loft([(0.7 * x, 0.75 * y, 0.0), (0.7 * x, 0.75 * y, cap_h + 0.002)], n)
        body = _loft([(0.72 * x, 0.78 * y, cap_h), (x, y, 0.35 * h), (x, y, 0.9 * h), (0.95 * x, 0.55 * y, h)], n)
        return Geometry(((body, body_color), (cap, cap_color)), (col.hull_part(body), col.hull_part(cap)))
    if p.closure == "pump":
        return _pump_bottle(v, p)
    body_h = 0.84 * h
    body = _loft([(0.92 * x, 0.92 * y, 0.0), (x, y, 0.06 * h), (x, y, 0.7 * h), (0.8 * x, 0.7 * y, body_h)], n)
    cap = _loft([(0.72 * x, 0.62 * y, body_h - 0.002), (0.66 * x, 0.58 * y, h)], n)
    return Geometry(((body, body_color), (cap, cap_color)), (col.hull_part(body), col.hull_part(cap)))


def _pump_bottle(v: Variant, p: ShampooShape) -> Geometry:
    x, y, h = v.size
    bx = 0.62 * x  # the body's depth; the nozzle reaches the rest of x towards +x
    body_h = 0.72 * h
    body = _loft([(0.92 * bx, 0.92 * y, 0.0), (bx, y, 0.05 * h), (bx, y, 0.6 * h), (0.7 * bx, 0.6 * y, body_h)], 3.0)
    collar = shapes.cylinder(0.16 * y, 0.03 * h, (0, 0, body_h + 0.01 * h))
    stem = shapes.cylinder(0.05 * y, h - body_h - 0.06 * h, (0, 0, (h + body_h) / 2 - 0.03 * h))
    head = shapes.rounded_box((0.2 * x, 0.3 * y, 0.08 * h), 0.004, (0, 0, h - 0.04 * h))
    reach = x - bx / 2
    nozzle = shapes.box((reach, 0.1 * y, 0.035 * h), (reach / 2, 0, h - 0.03 * h))
    pump = v.color(1, P.WHITE)
    parts = ((body, v.color(0, P.BLUE)), (collar, pump), (stem, pump), (head, pump), (nozzle, pump))
    top = col.hull_part(np.vstack([collar.vertices, head.vertices, nozzle.vertices]))
    return Geometry(parts, (col.hull_part(body), top))


@dataclass(frozen=True)
class ToothpasteShape:
    """Standing on its cap instead of lying flat; the cap's length as a fraction of the whole."""

    standing: bool = False
    cap: float = 0.12


@builder(ToothpasteShape)
def toothpaste_tube(v: Variant, p: ToothpasteShape) -> Geometry:
    """A squeeze tube, round at the cap and flattening to a crimped seal; lying on its belly or standing on its cap."""
    x, y, z = v.size
    length, depth = (z, x) if p.standing else (x, z)
    cap_len = p.cap * length
    x0 = -length / 2 + cap_len
    span = length - cap_len
    stations = [(0.0, 0.62 * y, depth, 2.0), (0.3, 0.72 * y, 0.9 * depth, 2.2), (0.75, 0.9 * y, 0.5 * depth, 3.0)]
    stations += [(0.93, y, 0.12 * depth, 6.0), (1.0, y, 0.1 * depth, 8.0)]
    rings = []
    for u, w, d, n in stations:  # rings in the yz plane, bottoms on z = 0
        ring = _superellipse(w / 2, d / 2, n, 40)
        rings.append(np.column_stack([np.full(len(ring), x0 + u * span), ring[:, 0], ring[:, 1] + d / 2]))
    body = _hull(np.vstack(rings))
    cap_r = (0.5 if p.standing else 0.42) * min(depth, 0.62 * y)
    cap = shapes.cylinder(cap_r, cap_len + 0.002, (-length / 2 + cap_len / 2 + 0.001, 0, depth / 2), axis="x")
    parts = [(body, v.color(0, P.WHITE)), (cap, v.color(1, P.RED))]
    collision: list[CollisionPart] = [col.hull_part(body), col.hull_part(cap)]
    if p.standing:  # cap end down: turn -90 degrees about y, so -x goes to the bottom
        turn = trimesh.transformations.rotation_matrix(-np.pi / 2, (0, 1, 0))
        parts = [(_turned(m, turn), c) for m, c in parts]
        collision = [col.hull_part(m) for m, _ in parts]
    return Geometry(tuple(parts), tuple(collision))


@dataclass(frozen=True)
class CombShape:
    """The tooth pitch (m), the handle's share of the length (0: teeth all along), a thin rat-tail handle."""

    pitch: float = 0.003
    handle: float = 0.0
    tail: bool = False


@builder(CombShape)
def comb(v: Variant, p: CombShape) -> Geometry:
    """A comb lying flat: a spine along +y with a row of teeth towards -y; one box collision."""
    x, y, z = v.size
    spine_w = 0.3 * y
    handle_len = p.handle * x
    spine_len = x - handle_len if p.tail else x
    spine_x = x / 2 - spine_len / 2
    spine = shapes.slab(spine_len, spine_w, z, 0.002, (spine_x, y / 2 - spine_w / 2, z / 2))
    teeth_x0 = -x / 2 + handle_len + p.pitch
    count = max(2, int((x / 2 - teeth_x0) / p.pitch))
    tooth_len = y - spine_w + 0.001
    teeth = [
        shapes.box((0.45 * p.pitch, tooth_len, 0.85 * z), (teeth_x0 + k * p.pitch, -y / 2 + tooth_len / 2, 0.425 * z))
        for k in range(count)
    ]
    parts = [shapes.concatenate([spine, *teeth])]
    if p.handle and p.tail:
        parts.append(
            shapes.box((handle_len + 0.002, 0.08 * y, 0.7 * z), (-x / 2 + handle_len / 2, y / 2 - 0.15 * y, 0.35 * z))
        )
    elif p.handle:
        parts.append(shapes.slab(handle_len, y, z, 0.004, (-x / 2 + handle_len / 2, 0, z / 2)))
    color = v.color(0, P.BLACK)
    return Geometry(tuple((m, color) for m in parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


@dataclass(frozen=True)
class HairbrushShape:
    """The head: "oval" or "paddle" (wide and square); the head's share of the length."""

    head: Literal["oval", "paddle"] = "oval"
    head_share: float = 0.45


@builder(HairbrushShape)
def hairbrush(v: Variant, p: HairbrushShape) -> Geometry:
    """A hairbrush lying on its back: a flat head at +x with a cushion pad and rows of bristles, a handle at -x."""
    x, y, z = v.size
    head_len = p.head_share * x
    head_w = y
    n = 5.0 if p.head == "paddle" else 2.0
    back_h, pad_h = 0.3 * z, 0.12 * z
    hx = x / 2 - head_len / 2
    head = _loft([(head_len, head_w, 0.0), (head_len, head_w, back_h)], n)
    head.apply_translation((hx, 0, 0))
    pad = _loft([(0.88 * head_len, 0.85 * head_w, back_h - 0.001), (0.85 * head_len, 0.8 * head_w, back_h + pad_h)], n)
    pad.apply_translation((hx, 0, 0))
    grid = _superellipse(0.38 * head_len, 0.34 * head_w, n, 24)
    inner = _superellipse(0.2 * head_len, 0.17 * head_w, n, 12)
    tips = np.vstack([grid, inner, [[0.0, 0.0]]])
    bristle_h = z - back_h - pad_h + 0.001
    bristles = shapes.concatenate(
        [shapes.cylinder(0.0011, bristle_h, (hx + u, w, z - bristle_h / 2), sections=6) for u, w in tips]
    )
    handle_len = x - head_len + 0.01
    handle = _loft([(handle_len, 0.3 * y, 0.0), (handle_len, 0.26 * y, 0.75 * back_h + 0.004)], 3.0)
    handle.apply_translation((-x / 2 + handle_len / 2, 0, 0))
    body = v.color(0, P.BLACK)
    parts = ((head, body), (handle, body), (pad, v.color(1, P.CHARCOAL)), (bristles, v.color(2, P.BLACK)))
    collision = (col.hull_part(np.vstack([head.vertices, pad.vertices, bristles.vertices])), col.hull_part(handle))
    return Geometry(parts, collision)


@dataclass(frozen=True)
class RazorShape:
    """A metal safety razor (an octagonal handle and a T head) instead of a cartridge razor."""

    safety: bool = False


@builder(RazorShape)
def razor(v: Variant, p: RazorShape) -> Geometry:
    """A razor lying on the side: a handle along x and the blade head across it at +x."""
    x, y, z = v.size
    body, accent = v.color(0, P.BLUE), v.color(1, P.SILVER)
    head_d = 0.13 * x if p.safety else 0.1 * x
    head = shapes.rounded_box((head_d, y, z), 0.002, (x / 2 - head_d / 2, 0, z / 2))
    blade = shapes.box((0.35 * head_d, 0.92 * y, 0.002), (x / 2 - 0.5 * head_d, 0, z - 0.0009))
    handle_len = x - head_d + 0.004
    hx = -x / 2 + handle_len / 2
    if p.safety:
        r = 0.3 * z
        handle = shapes.cylinder(r, handle_len, (hx, 0, r), axis="x", sections=8)
        knurl = shapes.cylinder(r * 1.04, 0.45 * handle_len, (hx - 0.1 * handle_len, 0, r), axis="x", sections=8)
        parts = ((handle, body), (knurl, v.color(2, body)), (head, accent), (blade, P.STEEL))
        return Geometry(parts, (col.hull_part(handle), col.hull_part(head)))
    rings = []
    for u, w, d in ((0.0, 0.26 * y, 0.55 * z), (0.55, 0.32 * y, 0.7 * z), (1.0, 0.2 * y, 0.45 * z)):
        ring = _superellipse(w / 2, d / 2, 2.5, 24)
        rings.append(np.column_stack([np.full(24, -x / 2 + u * handle_len), ring[:, 0], ring[:, 1] + d / 2]))
    handle = _hull(np.vstack(rings))
    strip = shapes.box((0.25 * head_d, 0.9 * y, 0.002), (x / 2 - 0.85 * head_d, 0, z - 0.0009))
    parts = ((handle, body), (head, v.color(2, P.CHARCOAL)), (blade, accent), (strip, P.rgb(120, 200, 170)))
    return Geometry(parts, (col.hull_part(handle), col.box_part((head_d, y, z), (x / 2 - head_d / 2, 0, z / 2))))


@dataclass(frozen=True)
class ToiletPaperShape:
    """Rolls along x and y and layers high (1, 1, 1: one roll); a clear plastic wrap around a pack."""

    nx: int = 1
    ny: int = 1
    layers: int = 1
    wrapped: bool = False


@builder(ToiletPaperShape)
def toilet_paper(v: Variant, p: ToiletPaperShape) -> Geometry:
    """Rolls of toilet paper standing on end: white paper around a cardboard core; packs are a grid of rolls."""
    x, y, z = v.size
    inset = 0.002 if p.wrapped else 0.0
    d = min((x - 2 * inset) / p.nx, (y - 2 * inset) / p.ny)
    h = (z - 2 * inset) / p.layers
    paper, core = v.color(0, P.WHITE), v.color(1, P.CARDBOARD)
    rolls, cores = [], []
    for i in range(p.nx):
        for j in range(p.ny):
            for k in range(p.layers):
                centre = ((i - (p.nx - 1) / 2) * d, (j - (p.ny - 1) / 2) * d, inset + k * h + h / 2)
                rolls.append(
                    trimesh.creation.annulus(0.21 * d, d / 2, h * 0.995, sections=40).apply_translation(centre)
                )
                cores.append(
                    trimesh.creation.annulus(0.2 * d, 0.215 * d, h * 0.999, sections=40).apply_translation(centre)
                )
    parts = [(shapes.concatenate(rolls), paper), (shapes.concatenate(cores), core)]
    if p.wrapped:
        parts.append((shapes.box((x, y, z), (0, 0, z / 2)), v.color(2, P.rgb(220, 235, 250, 0.3))))
    if p.nx * p.ny * p.layers == 1:
        return Geometry(tuple(parts), (col.cylinder_part(d / 2, h, (0, 0, h / 2)),))
    return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


@dataclass(frozen=True)
class CreamJarShape:
    """The lid's height as a fraction of the whole, the base's radius relative to the top's, a domed lid."""

    lid: float = 0.35
    taper: float = 1.0
    domed: bool = False


@builder(CreamJarShape)
def cream_jar(v: Variant, p: CreamJarShape) -> Geometry:
    """A squat cosmetic jar or tin with a screw lid as wide as the body; one convex hull."""
    d, _, h = v.size
    r = d / 2
    lid_h = p.lid * h
    body_h = h - lid_h
    rb = p.taper * 0.97 * r
    body = shapes.lathe(
        [(0, 0), (0.96 * rb, 0), (rb, 0.04 * h), (0.97 * r, body_h * 0.95), (0.92 * r, body_h), (0, body_h)]
    )
    if p.domed:
        top = [(r, body_h - 0.001), (r, h - 0.5 * lid_h), (0.75 * r, h - 0.1 * lid_h), (0.4 * r, h), (0, h)]
    else:
        top = [(r, body_h - 0.001), (r, h - 0.003), (0.97 * r, h), (0, h)]
    lid = shapes.lathe([(0, body_h - 0.001), *top])
    parts = ((body, v.color(0, P.WHITE)), (lid, v.color(1, P.GOLD)))
    return Geometry(parts, (col.hull_part(np.vstack([body.vertices, lid.vertices])),))


@dataclass(frozen=True)
class SmallBottleShape:
    """The body ("square", "round" or "flat" oval), the cap ("cylinder", "cube" or "ball"), and the body's and
    neck's heights as fractions of the whole."""

    body: Literal["square", "round", "flat"] = "square"
    cap: Literal["cylinder", "cube", "ball"] = "cylinder"
    body_share: float = 0.6
    neck_share: float = 0.08


@builder(SmallBottleShape)
def small_bottle(v: Variant, p: SmallBottleShape) -> Geometry:
    """A small glass bottle (perfume, nail polish): thick body, short neck, a decorative cap; two convex hulls."""
    x, y, h = v.size
    body_h = p.body_share * h
    neck_h = p.neck_share * h
    m = min(x, y)
    if p.body == "round":
        r = x / 2
        body = shapes.lathe(
            [(0, 0), (0.95 * r, 0), (r, 0.05 * body_h), (r, 0.8 * body_h), (0.5 * r, body_h), (0, body_h)]
        )
    elif p.body == "flat":
        body = _loft([(0.9 * x, 0.9 * y, 0.0), (x, y, 0.2 * body_h), (x, y, 0.8 * body_h), (0.7 * x, 0.6 * y, body_h)])
    else:
        body = shapes.rounded_box((x, y, body_h), 0.12 * m, (0, 0, body_h / 2))
    neck = shapes.cylinder(0.16 * m, neck_h + 0.002, (0, 0, body_h + neck_h / 2))
    cap_h = h - body_h - neck_h
    cap_z = body_h + neck_h
    if p.cap == "cube":
        cap = shapes.rounded_box((0.55 * m, 0.55 * m, cap_h + 0.001), 0.002, (0, 0, cap_z + cap_h / 2 - 0.0005))
    elif p.cap == "ball":
        cap = shapes.ellipsoid((0.3 * m, 0.3 * m, cap_h / 2 + 0.0005), (0, 0, cap_z + cap_h / 2 - 0.0005), 2)
    else:
        cap = shapes.cylinder(0.24 * m, cap_h + 0.001, (0, 0, cap_z + cap_h / 2 - 0.0005))
    parts = ((body, v.color(0, P.GLASS)), (neck, v.color(2, P.SILVER)), (cap, v.color(1, P.GOLD)))
    return Geometry(parts, (col.hull_part(body), col.hull_part(np.vstack([neck.vertices, cap.vertices]))))


# --- bins -----------------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class StorageBinShape:
    """Wall thickness and corner radius (m), hand holes in the two ends, a lip around the rim (m; 0: none)."""

    wall: float = 0.004
    radius: float = 0.02
    hand_holes: bool = True
    lip: float = 0.0


@builder(StorageBinShape)
def storage_bin(v: Variant, p: StorageBinShape) -> Geometry:
    """An open storage bin: rounded walls (five slabs of collision), hand holes in the ends, an optional rim lip."""
    x, y, z = v.size
    bx, by = x - 2 * p.lip, y - 2 * p.lip
    wall, floor = p.wall, max(p.wall, 0.004)
    mesh = _open_box_mesh(bx, by, z, wall, floor, p.radius)
    if p.hand_holes:
        hole_w, hole_h = min(0.1, 0.35 * by), min(0.03, 0.15 * z)
        mesh = trimesh.boolean.difference([mesh, _slot_ends(bx, hole_w, hole_h, z)], engine="manifold")
    color = v.color(0, P.GREY)
    parts = [(mesh, color)]
    if p.lip:
        outer = shapes.slab(x, y, 0.008, p.radius + p.lip, (0, 0, z - 0.004))
        inner = shapes.slab(bx - 0.002, by - 0.002, 0.01, p.radius, (0, 0, z - 0.004))
        parts.append((trimesh.boolean.difference([outer, inner], engine="manifold"), v.color(1, color)))
    cavity = Cavity(rectangle(bx - 2 * wall, by - 2 * wall), floor, z - floor)
    return Geometry(tuple(parts), tuple(col.open_box_parts(bx, by, z, wall, floor)), cavity)


def _slot_ends(length: float, width: float, height: float, z: float) -> trimesh.Trimesh:
    """Two rounded slots through the end walls (+-x), below the rim: the hand holes of a bin."""
    slot = shapes.slab(width, height, 0.06, 0.499 * height)  # a stadium in the xy plane ...
    slot = _turned(slot, _XYZ_TO_YZX)  # ... stood up in the yz plane, through the end walls
    ends = []
    for s in (1, -1):
        piece = slot.copy()
        piece.apply_translation((s * length / 2, 0, z - 1.6 * height))
        ends.append(piece)
    return shapes.concatenate(ends)


@dataclass(frozen=True)
class TrashCanShape:
    """Round (revolved) or square; the base's width relative to the top (tapered sides); a rolled rim band."""

    round: bool = True
    bottom: float = 0.85
    rim: bool = True


@builder(TrashCanShape)
def trash_can(v: Variant, p: TrashCanShape) -> Geometry:
    """An open-topped waste bin: a tapered revolved shell or a square box, with a rim band; collision walls."""
    x, y, z = v.size
    color, band = v.color(0, P.CHARCOAL), v.color(1, v.color(0, P.CHARCOAL))
    rim_t = 0.004 if p.rim else 0.0
    if p.round:
        r = x / 2 - rim_t
        vessel = Vessel(resample([(p.bottom * r, 0.0), (r, z)], 6), 0.003, 0.006, stations=2)
        parts = [(vessel.mesh(), color)]
        if p.rim:
            ring = trimesh.creation.annulus(r - 0.004, r + rim_t, 0.015, sections=48).apply_translation(
                (0, 0, z - 0.0075)
            )
            parts.append((ring, band))
        return Geometry(tuple(parts), tuple(vessel.collision(16)), vessel.cavity())
    bx, by = x - 2 * rim_t, y - 2 * rim_t
    wall, floor = 0.004, 0.006
    parts = [(_open_box_mesh(bx, by, z, wall, floor, 0.015), color)]
    if p.rim:
        outer = shapes.slab(x, y, 0.015, 0.015 + rim_t, (0, 0, z - 0.0075))
        inner = shapes.slab(bx - 0.004, by - 0.004, 0.02, 0.012, (0, 0, z - 0.0075))
        parts.append((trimesh.boolean.difference([outer, inner], engine="manifold"), band))
    cavity = Cavity(rectangle(bx - 2 * wall, by - 2 * wall), floor, z - floor)
    return Geometry(tuple(parts), tuple(col.open_box_parts(bx, by, z, wall, floor)), cavity)


# --- bedroom and living room ----------------------------------------------------------------------------------------


@dataclass(frozen=True)
class MakeupBagShape:
    """The top's width across as a fraction of the base's (a pouch narrows to its zip; 1: a box-shaped case) and a
    carry handle on top."""

    ridge: float = 0.3
    handle: bool = False
    open: bool = False  # unzipped wide open: an empty tray-like bag things are put into


@builder(MakeupBagShape)
def makeup_bag(v: Variant, p: MakeupBagShape) -> Geometry:
    """A zipped cosmetic pouch (a flat base narrowing to a zip along the top) or a boxy case with a handle; or open."""
    x, y, z = v.size
    if p.open:
        return open_tray(v.size, 0.004, 0.004, v.color(0, P.PINK), radius=0.25 * min(x, y))
    handle_h = 0.25 * z if p.handle else 0.0
    body_h = z - handle_h
    body = _loft(
        [(0.96 * x, 0.94 * y, 0.0), (x, y, 0.12 * body_h), (0.97 * x, max(0.6, p.ridge) * y, 0.75 * body_h)], 4.0
    )
    top = _loft([(0.92 * x, p.ridge * y, body_h - 0.002), (0.9 * x, p.ridge * y * 0.9, body_h)], 4.0)
    body = _hull(np.vstack([body.vertices, top.vertices]))
    zip_line = shapes.box((0.86 * x, 0.008, 0.003), (0, 0, body_h - 0.0012))
    pull = shapes.box((0.012, 0.006, 0.02), (0.43 * x, 0, body_h - 0.006))
    color = v.color(0, P.PINK)
    parts = [(body, color), (zip_line, v.color(1, P.GOLD)), (pull, v.color(1, P.GOLD))]
    collision = [col.hull_part(body)]
    if p.handle:
        t = np.linspace(0.0, np.pi, 13)
        path = np.stack([0.25 * x * np.cos(t), np.zeros_like(t), body_h - 0.006 + (handle_h - 0.002) * np.sin(t)], 1)
        handle = shapes.tube(path, 0.004, sides=10)
        parts.append((handle, v.color(2, color)))
        collision.append(col.hull_part(handle))
    return Geometry(tuple(parts), tuple(collision))


@dataclass(frozen=True)
class CushionShape:
    """Round instead of square; the thickness at the edges as a fraction of the middle; a tufted button on top."""

    round: bool = False
    edge: float = 0.35
    button: bool = False


def _puff(u: np.ndarray, edge: float) -> np.ndarray:
    """A cushion's relative thickness over u in [-1, 1]: full in the middle, `edge` at the seams."""
    return edge + (1 - edge) * np.sqrt(np.clip(1 - u**4, 0.0, 1.0))


@builder(CushionShape)
def cushion(v: Variant, p: CushionShape) -> Geometry:
    """A plump cushion or pillow resting on its flat underside: a dome falling to thin seams; one convex hull."""
    x, y, z = v.size
    if p.round:
        radii = np.linspace(1.0, 0.05, 14)
        rim = [(x / 2 * float(r), z * float(_puff(np.asarray(r), p.edge))) for r in radii]
        body = shapes.lathe([(0.0, 0.0), (0.97 * x / 2, 0.0), *rim, (0.0, z)], 48)
    else:
        u, w = (g.ravel() for g in np.meshgrid(np.linspace(-1, 1, 17), np.linspace(-1, 1, 17)))
        height = z * (p.edge + (1 - p.edge) * np.sqrt(np.clip((1 - u**4) * (1 - w**4), 0.0, 1.0)))
        top = np.column_stack([u * x / 2, w * y / 2, height])
        bottom = np.column_stack([0.97 * u * x / 2, 0.97 * w * y / 2, np.zeros(u.size)])
        body = _hull(np.vstack([top, bottom]))
    color = v.color(0, P.GREY)
    parts = [(body, color)]
    if p.button:
        parts.append((shapes.ellipsoid((0.015, 0.015, 0.006), (0, 0, z - 0.005), 2), v.color(1, color)))
    return Geometry(tuple(parts), (col.hull_part(body),))


@dataclass(frozen=True)
class BlanketShape:
    """Layers when folded; rolled up along y instead; stripes across the top in the second colour."""

    folds: int = 4
    rolled: bool = False
    stripes: int = 0


@builder(BlanketShape)
def blanket(v: Variant, p: BlanketShape) -> Geometry:
    """A folded blanket (a stack of soft rounded layers) or a blanket rolled up and tied, lying along y."""
    x, y, z = v.size
    color, accent = v.color(0, P.rgb(170, 60, 60)), v.color(1, P.CREAM)
    if p.rolled:
        r = z / 2
        roll = shapes.cylinder(r, y, (0, 0, r), axis="y", sections=16)
        ties = [shapes.cylinder(r * 1.03, 0.025, (0, s * 0.3 * y, r), axis="y", sections=16) for s in (1, -1)]
        return Geometry(((roll, color), (shapes.concatenate(ties), accent)), (col.hull_part(roll),))
    t = z / p.folds
    layers = [
        shapes.rounded_box((x - 0.008 * (k % 2), y - 0.006 * k, t + 0.002), 0.45 * t, (0, 0, t * k + t / 2))
        for k in range(p.folds)
    ]
    layers[-1] = shapes.rounded_box((x, y - 0.006 * (p.folds - 1), t), 0.45 * t, (0, 0, z - t / 2))
    parts = [(shapes.concatenate(layers), color)]
    top_y = y - 0.006 * (p.folds - 1) - 0.9 * t
    for k in range(p.stripes):
        sx = (k + 0.5) / p.stripes * x - x / 2
        parts.append((shapes.box((0.025, top_y, 0.0012), (sx, 0, z - 0.0004)), accent))
    return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


@dataclass(frozen=True)
class SlipperShape:
    """A pair side by side (or one slipper); an open-toe slide (a strap across the foot) instead of a closed toe."""

    pair: bool = True
    open_toe: bool = False


def _foot_outline(length: float, width: float) -> Polygon:
    """An egg-shaped sole outline along x, toe at +x, centred on the origin."""
    heel = Point(-length / 2 + 0.36 * width, 0.0).buffer(0.36 * width, quad_segs=10)
    toe = Point(length / 2 - 0.5 * width, 0.0).buffer(0.5 * width, quad_segs=10)
    outline = heel.union(toe).convex_hull
    assert isinstance(outline, Polygon)
    return outline


@builder(SlipperShape)
def slippers(v: Variant, p: SlipperShape) -> Geometry:
    """House slippers toes to +x: a flat sole and a soft upper over the front (or a strap); one hull each."""
    x, y, z = v.size
    gap = 0.025 if p.pair else 0.0
    width = (y - gap) / 2 if p.pair else y
    sole_h = 0.28 * z
    outline = _foot_outline(x, width)
    dome = shapes.ellipsoid((0.34 * x, 0.58 * width, z - sole_h), (0.18 * x, 0, sole_h), 3)
    prism = shapes.extrude(outline.buffer(-0.002), z, sole_h - 0.001)
    keep = [dome, prism]
    if p.open_toe:
        keep.append(shapes.box((0.22 * x, y, z), (0.05 * x, 0, z / 2)))
    upper = trimesh.boolean.intersection(keep, engine="manifold")
    sole = shapes.extrude(outline, sole_h)
    parts, collision = [], []
    for cy in (-(width + gap) / 2, (width + gap) / 2) if p.pair else (0.0,):
        pieces = [m.copy().apply_translation((0, cy, 0)) for m in (sole, upper)]
        parts += [(pieces[0], v.color(1, P.rgb(90, 80, 75))), (pieces[1], v.color(0, P.GREY))]
        collision.append(col.hull_part(np.vstack([m.vertices for m in pieces])))
    return Geometry(tuple(parts), tuple(collision))


@dataclass(frozen=True)
class SunglassesShape:
    """The lens outline: "round", "wayfarer" (a rounded trapezoid) or "aviator" (a teardrop); the rim's width (m)."""

    lens: Literal["round", "wayfarer", "aviator"] = "wayfarer"
    rim: float = 0.004


def _lens_outline(kind: str, w: float, h: float) -> np.ndarray:
    """The right lens's outline (u outwards, v up), centred on the origin."""
    if kind == "round":
        return _superellipse(w / 2, h / 2, 2.0, 40)
    pts = _superellipse(w / 2, h / 2, 4.0 if kind == "wayfarer" else 2.2, 40)
    u, vv = pts[:, 0], pts[:, 1]
    if kind == "wayfarer":
        u = u * (0.86 + 0.14 * (vv + h / 2) / h)
    else:  # the lower inner corner recedes towards the outside: a teardrop
        u = np.where((u < 0) & (vv < 0), u * (1 - 0.45 * np.clip(-vv / (h / 2), 0, 1)), u)
    return np.column_stack([u, vv])


@builder(SunglassesShape)
def sunglasses(v: Variant, p: SunglassesShape) -> Geometry:
    """Sunglasses standing open on a table: the front frame facing +x, the temples running back and down to the
    surface; a hull for the frame and one per temple."""
    x, y, z = v.size
    rim, bridge, depth = p.rim, 0.018, 0.005
    w, h = (y - bridge - 4 * rim) / 2, z - 2 * rim
    cu = bridge / 2 + rim + w / 2
    right = Polygon(_lens_outline(p.lens, w, h) + (cu, 0.0))
    left = Polygon(_lens_outline(p.lens, w, h) * (-1.0, 1.0) + (-cu, 0.0))
    bar = shapely_box(-cu, 0.15 * h, cu, 0.3 * h)
    frame_outline = unary_union([right.buffer(rim), left.buffer(rim), bar])
    assert isinstance(frame_outline, Polygon)
    front = [shapes.extrude(frame_outline, depth)]
    front += [shapes.extrude(lens, depth + 0.001, -0.0005) for lens in (right, left)]
    lo_v, hi_u = frame_outline.bounds[1], frame_outline.bounds[2]
    front = [_turned(m, _XYZ_TO_YZX).apply_translation((x / 2 - depth, 0, -lo_v)) for m in front]
    hinge_z = 0.75 * (frame_outline.bounds[3] - lo_v)
    temples = []
    for s in (1, -1):
        ends = [(x / 2 - depth, hinge_z), (-x / 2, 0.003)]
        pts = [
            (px, s * (hi_u - 0.0015) + dy, pz + dz)
            for px, pz in ends
            for dy in (-0.0015, 0.0015)
            for dz in (-0.003, 0.003)
        ]
        temples.append(_hull(np.asarray(pts)))
    frame_color = v.color(0, P.BLACK)
    lens_color = v.color(1, P.rgb(40, 40, 45, 0.8))
    parts = [(front[0], frame_color), (front[1], lens_color), (front[2], lens_color)]
    parts += [(t, frame_color) for t in temples]
    collision = (col.hull_part(np.vstack([m.vertices for m in front])), *(col.hull_part(t) for t in temples))
    return fit_to_size(Geometry(tuple(parts), collision), v.size)


@dataclass(frozen=True)
class WalletShape:
    """The style: a "bifold" wallet, a "long" wallet with a snap tab, or a "card" holder with a card peeking out."""

    style: Literal["bifold", "long", "card"] = "bifold"


@builder(WalletShape)
def wallet(v: Variant, p: WalletShape) -> Geometry:
    """A wallet lying flat: a soft rounded leather slab with a stitched border; one box collision."""
    x, y, z = v.size
    color = v.color(0, P.BROWN)
    body_h = z - 0.0006
    body = shapes.rounded_box((x, y, body_h), 0.4 * body_h, (0, 0, body_h / 2))
    outer = shapes.slab(x - 0.006, y - 0.006, 0.001, 0.004, (0, 0, body_h - 0.0001))
    inner = shapes.slab(x - 0.008, y - 0.008, 0.002, 0.003, (0, 0, body_h - 0.0001))
    stitch = trimesh.boolean.difference([outer, inner], engine="manifold")
    parts = [(body, color), (stitch, v.color(1, P.rgb(200, 170, 120)))]
    if p.style == "long":
        tab = shapes.slab(0.035, 0.3 * y, 0.002, 0.008, (x / 2 - 0.017, 0, body_h - 0.0004))
        parts.append((tab, v.color(2, color)))
        parts.append((shapes.cylinder(0.005, 0.0012, (x / 2 - 0.012, 0, body_h + 0.0001)), P.SILVER))
    elif p.style == "card":
        card = shapes.slab(0.8 * x, 0.7 * y, 0.0008, 0.003, (0.1 * x, 0, body_h + 0.0002))
        parts.append((card, v.color(2, P.rgb(60, 110, 190))))
    return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


@dataclass(frozen=True)
class WatchShape:
    """A square case instead of a round one; a metal link bracelet instead of a leather strap."""

    square: bool = False
    bracelet: bool = False


@builder(WatchShape)
def watch(v: Variant, p: WatchShape) -> Geometry:
    """A wristwatch lying flat with its strap laid open along x: case, dial, hands, crown at +y, buckle."""
    x, y, z = v.size
    crown = 0.08 * y
    dia = y - crown
    case_h = 0.85 * z
    strap_w, strap_t = 0.5 * dia, 0.0035
    cy = -crown / 2  # the case sits off centre so the crown fits inside y
    metal, strap_color = v.color(1, P.SILVER), v.color(0, P.BROWN)
    if p.square:
        case = shapes.rounded_box((dia, dia, case_h), 0.004, (0, cy, case_h / 2))
        dial = shapes.box((0.8 * dia, 0.8 * dia, z - case_h + 0.001), (0, cy, (z + case_h) / 2 - 0.0005))
    else:
        case = shapes.cylinder(dia / 2, case_h, (0, cy, case_h / 2), sections=40)
        dial = shapes.cylinder(0.4 * dia, z - case_h + 0.001, (0, cy, (z + case_h) / 2 - 0.0005), sections=40)
    hands = [
        shapes.box((0.32 * dia, 0.0018, 0.0005), (0.14 * dia, cy, z - 0.0002)),
        shapes.box((0.0022, 0.26 * dia, 0.0005), (0, cy + 0.12 * dia, z - 0.0002)),
    ]
    stem = shapes.cylinder(0.0025, crown + 0.002, (0, cy + dia / 2 + crown / 2 - 0.001, 0.5 * case_h), axis="y")
    strap = shapes.box((x, strap_w, strap_t), (0, cy, strap_t / 2))
    buckle_outer = shapes.box((0.02, strap_w + 0.004, 0.004), (-x / 2 + 0.03, cy, 0.002))
    buckle_inner = shapes.box((0.014, strap_w - 0.002, 0.006), (-x / 2 + 0.03, cy, 0.002))
    buckle = trimesh.boolean.difference([buckle_outer, buckle_inner], engine="manifold")
    parts = [(case, metal), (dial, v.color(2, P.WHITE)), (shapes.concatenate(hands), P.BLACK), (stem, metal)]
    parts += [(strap, metal if p.bracelet else strap_color), (buckle, metal)]
    if p.bracelet:
        links = [
            shapes.box((0.0012, strap_w + 0.0004, strap_t + 0.0004), (lx, cy, strap_t / 2))
            for lx in np.arange(-x / 2 + 0.01, x / 2, 0.008)
            if abs(lx) > dia / 2
        ]
        parts.append((shapes.concatenate(links), P.GREY))
    collision = (
        col.hull_part(np.vstack([case.vertices, dial.vertices, stem.vertices])),
        col.box_part((x, strap_w + 0.004, 0.004), (0, cy, 0.002)),
    )
    return Geometry(tuple(parts), collision)


@dataclass(frozen=True)
class MagazineShape:
    """A border around the cover in the third colour (m; 0: none); the cover photo block."""

    border: float = 0.0
    photo: bool = True


@builder(MagazineShape)
def magazine(v: Variant, p: MagazineShape) -> Geometry:
    """A magazine lying flat: pages between glossy covers, a spine at -x, a title band and a cover picture."""
    x, y, z = v.size
    cover = v.color(0, P.RED)
    pages = shapes.box((x - 0.002, y - 0.002, z - 0.0008), (0.001, 0, z / 2))
    back = shapes.box((x, y, 0.0005), (0, 0, 0.00025))
    front = shapes.box((x, y, 0.0005), (0, 0, z - 0.00025))
    spine = shapes.box((0.0008, y, z), (-x / 2 + 0.0004, 0, z / 2))
    parts = [(pages, P.PAPER), (shapes.concatenate([back, front, spine]), v.color(2, cover) if p.border else cover)]
    inner_x, inner_y = x - 2 * p.border, y - 2 * p.border
    if p.border:
        parts.append((shapes.box((inner_x, inner_y, 0.0004), (0, 0, z - 0.00015)), cover))
    title = shapes.box((0.85 * inner_x, 0.16 * inner_y, 0.0004), (0, inner_y / 2 - 0.12 * inner_y, z - 0.0001))
    parts.append((title, v.color(1, P.WHITE)))
    if p.photo:
        picture = shapes.box((0.7 * inner_x, 0.5 * inner_y, 0.0004), (0.05 * inner_x, -0.12 * inner_y, z - 0.0001))
        parts.append((picture, v.color(3, P.SKY)))
    return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


@dataclass(frozen=True)
class CandleHolderShape:
    """The style: a "stick" (a candlestick with a socket for a taper), a "votive" glass cup for a tea light, or a
    "lantern" (a tall glass chimney on a base plate)."""

    style: Literal["stick", "votive", "lantern"] = "stick"


@builder(CandleHolderShape)
def candle_holder(v: Variant, p: CandleHolderShape) -> Geometry:
    """A candle holder: a revolved cup (socket, votive or chimney) on a foot; the cup is a container for a candle."""
    d, _, h = v.size
    r = d / 2
    color = v.color(0, P.BRASS)
    if p.style == "stick":
        socket_r, cup_h = max(0.014, 0.28 * r), 0.025
        z0 = h - cup_h
        base = [(0.0, 0.0), (r, 0.0), (r, 0.012), (0.55 * r, 0.022), (0.16 * r, 0.05), (0.12 * r, z0 - 0.02)]
        base += [(0.2 * r, z0 - 0.01), (0.75 * socket_r, z0)]
        vessel = Vessel(resample([(socket_r, z0), (socket_r, h)], 3), 0.0025, 0.003, stations=1, base=base)
        foot = [pt for pt in base if pt[0] > 0 and pt[1] <= 0.022]
        stem = [pt for pt in base if pt[0] > 0 and pt[1] >= 0.022]
        collision = [col.hull_part(_ring_points(foot)), col.hull_part(_ring_points(stem)), *vessel.collision(12)]
        return Geometry(((vessel.mesh(), color),), tuple(collision), vessel.cavity())
    if p.style == "votive":
        vessel = Vessel(resample([(0.9 * r, 0.0), (r, h)], 4), 0.003, 0.012, stations=2)
        return Geometry(((vessel.mesh(), v.color(0, P.GLASS)),), tuple(vessel.collision(14)), vessel.cavity())
    plate_h = 0.025
    glass_r = 0.8 * r
    vessel = Vessel(resample([(glass_r, plate_h), (glass_r, h)], 3), 0.003, 0.002, stations=1)
    plate = shapes.cylinder(r, plate_h, (0, 0, plate_h / 2), sections=40)
    glass = vessel.mesh()
    collision = [col.cylinder_part(r, plate_h, (0, 0, plate_h / 2)), *vessel.collision(14)]
    return Geometry(((plate, color), (glass, v.color(1, P.GLASS))), tuple(collision), vessel.cavity())


def _ring_points(profile: list[tuple[float, float]], count: int = 24) -> np.ndarray:
    """Points of a revolved (r, z) profile, for its convex hull."""
    t = np.linspace(0.0, 2 * np.pi, count, endpoint=False)
    return np.vstack([np.column_stack([r * np.cos(t), r * np.sin(t), np.full(count, zz)]) for r, zz in profile])


@dataclass(frozen=True)
class JewelryBoxShape:
    """Compartments across the tray (odd, so the middle one is open) and the open lid's height (m; 0: no lid)."""

    compartments: int = 3
    lid: float = 0.0


@builder(JewelryBoxShape)
def jewelry_box(v: Variant, p: JewelryBoxShape) -> Geometry:
    """An open jewellery box: walls, a velvet lined floor, low dividers, and a lid standing open at the back (-x)."""
    x, y, z = v.size
    body_h = z - p.lid
    wall, floor, lining = 0.006, 0.006, 0.003
    color, velvet = v.color(0, P.WOOD), v.color(1, P.rgb(150, 30, 50))
    body = _open_box_mesh(x, y, body_h, wall, floor, 0.004)
    ix, iy = x - 2 * wall, y - 2 * wall
    pad = shapes.box((ix + 0.001, iy + 0.001, lining), (0, 0, floor + lining / 2 - 0.0005))
    parts = [(body, color), (pad, velvet)]
    collision = list(col.open_box_parts(x, y, body_h, wall, floor))
    divider_h = 0.6 * (body_h - floor - lining)
    for k in range(1, p.compartments):
        dy = -iy / 2 + k * iy / p.compartments
        divider = shapes.box((ix + 0.001, 0.003, divider_h), (0, dy, floor + lining + divider_h / 2))
        parts.append((divider, color))
        collision.append(col.box_part((ix, 0.003, divider_h), (0, dy, floor + lining + divider_h / 2)))
    if p.lid:
        lid_c = (-x / 2 + wall / 2, 0, body_h + p.lid / 2 - 0.002)
        lid = shapes.box((wall, y, p.lid + 0.004), lid_c)
        mirror = shapes.box((0.001, 0.7 * y, 0.6 * p.lid), (-x / 2 + wall + 0.0004, 0, body_h + 0.5 * p.lid))
        parts += [(lid, color), (mirror, v.color(2, P.rgb(210, 225, 235)))]
        collision.append(col.box_part((wall, y, p.lid + 0.004), lid_c))
    floor_top = floor + lining - 0.0005
    cavity = Cavity(rectangle(ix, iy), floor_top, body_h - floor_top)
    return Geometry(tuple(parts), tuple(collision), cavity)


@dataclass(frozen=True)
class HandMirrorShape:
    """The handle's share of the length (0: a round compact with no handle); an oval instead of a round glass."""

    handle: float = 0.4
    oval: bool = False


@builder(HandMirrorShape)
def hand_mirror(v: Variant, p: HandMirrorShape) -> Geometry:
    """A hand mirror lying face up: a framed round or oval glass at +x and a flat handle at -x; one convex hull."""
    x, y, z = v.size
    head_len = x - p.handle * x if p.oval else min(y, x - p.handle * x)  # a round glass is as long as it is wide
    handle_len = x - head_len
    hx = x / 2 - head_len / 2
    rim = [(0.95 * head_len, 0.95 * y, 0.0), (head_len, y, 0.3 * z), (head_len, y, 0.75 * z)]
    frame = _loft([*rim, (0.92 * head_len, 0.92 * y, z - 0.0005)], 2.0, 64)
    frame.apply_translation((hx, 0, 0))
    glass = _loft([(head_len - 0.012, y - 0.012, z - 0.0012), (head_len - 0.012, y - 0.012, z)], 2.0, 64)
    glass.apply_translation((hx, 0, 0))
    color = v.color(0, P.GOLD)
    parts = [(frame, color), (glass, v.color(1, P.rgb(215, 228, 236)))]
    if handle_len:
        handle = _loft([(handle_len + 0.02, 0.22 * y, 0.0), (handle_len + 0.02, 0.18 * y, 0.6 * z)], 3.0)
        handle.apply_translation((-x / 2 + handle_len / 2 + 0.01, 0, 0))
        parts.append((handle, color))
    return Geometry(tuple(parts), (col.hull_part(np.vstack([m.vertices for m, _ in parts])),))


# --- more bathroom and bedroom things -------------------------------------------------------------------------------


@dataclass(frozen=True)
class HairDryerShape:
    """The attachment on the nozzle: a slim "concentrator", a wide "diffuser", or "none"."""

    nozzle: Literal["concentrator", "diffuser", "none"] = "concentrator"


@builder(HairDryerShape)
def hair_dryer(v: Variant, p: HairDryerShape) -> Geometry:
    """A hair dryer lying on its side: the barrel along x (nozzle at +x), the handle lying flat towards -y."""
    x, y, z = v.size
    r = z / 2
    body, dark = v.color(0, P.BLACK), v.color(1, P.CHARCOAL)
    nozzle_len = {"concentrator": 0.22, "diffuser": 0.2, "none": 0.0}[p.nozzle] * x
    barrel_len = x - nozzle_len
    bx = -x / 2 + barrel_len / 2
    barrel = shapes.cylinder(r, barrel_len - 0.012, (bx + 0.006, 0, r), axis="x")
    vent = shapes.cylinder(0.94 * r, 0.014, (-x / 2 + 0.007, 0, r), axis="x")
    parts = [(barrel, body), (vent, dark)]
    front = [barrel]
    if p.nozzle == "concentrator":
        nozzle = shapes.cone(0.8 * r, 0.55 * r, nozzle_len + 0.004, (x / 2 - nozzle_len / 2 - 0.002, 0, r), axis="x")
        parts.append((nozzle, dark))
        front.append(nozzle)
    elif p.nozzle == "diffuser":
        neck = shapes.cylinder(0.75 * r, 0.5 * nozzle_len + 0.004, (x / 2 - 0.75 * nozzle_len, 0, r), axis="x")
        bowl = shapes.cylinder(r, 0.5 * nozzle_len, (x / 2 - 0.25 * nozzle_len, 0, r), axis="x")
        parts += [(neck, dark), (bowl, dark)]
        front += [neck, bowl]
    t, reach = 0.62 * z, y - r  # the handle runs from the barrel's axis to -y
    hx = bx + 0.1 * barrel_len
    handle = shapes.rounded_box((0.3 * barrel_len, reach, t), 0.3 * t, (hx, -reach / 2, t / 2))
    switch = shapes.box((0.02, 0.03, 0.004), (hx, -0.45 * reach, t - 0.0015))
    parts += [(handle, body), (switch, v.color(2, P.SILVER))]
    collision = (col.hull_part(np.vstack([m.vertices for m in front])), col.hull_part(handle))
    return Geometry(tuple(parts), collision)


@dataclass(frozen=True)
class RugShape:
    """Round instead of rectangular; a border in the second colour (m; 0: none); fringes at the two ends."""

    round: bool = False
    border: float = 0.0
    fringe: bool = False


@builder(RugShape)
def rug(v: Variant, p: RugShape) -> Geometry:
    """A rug or mat lying flat: a thin pile slab with an optional border, a centre motif and fringed ends."""
    x, y, z = v.size
    fringe = 0.04 if p.fringe and not p.round else 0.0
    color, accent = v.color(0, P.rgb(150, 40, 40)), v.color(1, P.CREAM)
    lx = x - 2 * fringe
    top_z = z - 0.0006
    if p.round:
        base = shapes.cylinder(x / 2, top_z, (0, 0, top_z / 2), sections=64)
        collision = col.cylinder_part(x / 2, z, (0, 0, z / 2))
    else:
        base = shapes.slab(lx, y, top_z, 0.01, (0, 0, top_z / 2))
        collision = col.box_part((x, y, z), (0, 0, z / 2))
    parts = [(base, color)]
    if p.border:
        ring = _flat_ring(lx, y, p.border, p.round)
        parts.append((shapes.extrude(ring, 0.0012, top_z - 0.0006), accent))
    motif = _loft(
        [(0.3 * lx, 0.3 * y, top_z - 0.0006), (0.3 * lx, 0.3 * y, z)], 2.0 if p.round else 1.2, 4 if not p.round else 48
    )
    parts.append((motif, v.color(2, accent)))
    if fringe:
        tassels = [
            shapes.box((fringe + 0.002, 0.004, 0.002), (s * (x / 2 - fringe / 2), fy, 0.001))
            for s in (1, -1)
            for fy in np.arange(-y / 2 + 0.01, y / 2 - 0.005, 0.02)
        ]
        parts.append((shapes.concatenate(tassels), v.color(3, P.CREAM)))
    return Geometry(tuple(parts), (collision,))


def _flat_ring(x: float, y: float, width: float, round_: bool) -> Polygon:
    """A border band just inside the outline of a rectangle (or circle) x by y."""
    if round_:
        outer = Point(0, 0).buffer(x / 2 - 0.01, quad_segs=16)
    else:
        outer = shapely_box(-x / 2 + 0.01, -y / 2 + 0.01, x / 2 - 0.01, y / 2 - 0.01)
    ring = outer.difference(outer.buffer(-width))
    assert isinstance(ring, Polygon)
    return ring


@dataclass(frozen=True)
class BathroomScaleShape:
    """Round instead of square; a glass top with a visible display window."""

    round: bool = False
    glass: bool = True


@builder(BathroomScaleShape)
def bathroom_scale(v: Variant, p: BathroomScaleShape) -> Geometry:
    """A flat bathroom scale: a low body with a top plate and a digital display at +x."""
    x, y, z = v.size
    body_color, top_color = v.color(0, P.WHITE), v.color(1, P.rgb(230, 235, 240, 0.9) if p.glass else P.WHITE)
    base_h = 0.6 * z
    if p.round:
        base = shapes.cylinder(0.49 * x, base_h, (0, 0, base_h / 2), sections=64)
        top_r = x / 2 if p.glass else 0.45 * x
        top = shapes.lathe([(0, base_h - 0.001), (top_r, base_h - 0.001), (top_r - 0.004, z), (0, z)], 64)
        collision = col.cylinder_part(x / 2, z, (0, 0, z / 2))
    else:
        base = shapes.slab(0.97 * x, 0.97 * y, base_h, 0.03, (0, 0, base_h / 2))
        inset = 1.0 if p.glass else 0.9  # a glass plate covers the whole top; a plastic one is a raised pad
        top = shapes.slab(inset * x, inset * y, z - base_h + 0.001, 0.03, (0, 0, (z + base_h) / 2 - 0.0005))
        collision = col.box_part((x, y, z), (0, 0, z / 2))
    display = shapes.box((0.1 * x, 0.25 * y, 0.0008), (0.3 * x, 0, z - 0.0003))
    parts = ((base, body_color), (top, top_color), (display, v.color(2, P.rgb(40, 50, 60))))
    return Geometry(parts, (collision,))


@dataclass(frozen=True)
class DeodorantShape:
    """An aerosol spray can instead of a stick; the stick's body oval (2) or squarer (larger)."""

    spray: bool = False
    squareness: float = 2.5


@builder(DeodorantShape)
def deodorant(v: Variant, p: DeodorantShape) -> Geometry:
    """A deodorant: an oval twist-up stick with a cap, or an aerosol can with a domed shoulder and a cap."""
    x, y, h = v.size
    body_color, cap_color = v.color(0, P.WHITE), v.color(1, P.BLUE)
    if p.spray:
        r = x / 2
        body_h = 0.8 * h
        body = shapes.lathe([(0, 0), (0.95 * r, 0), (r, 0.02 * h), (r, 0.9 * body_h), (0.8 * r, body_h), (0, body_h)])
        cap = shapes.lathe(
            [(0, body_h - 0.002), (0.82 * r, body_h - 0.002), (0.8 * r, h - 0.004), (0.7 * r, h), (0, h)]
        )
    else:
        body_h = 0.72 * h
        n = p.squareness
        body = _loft([(0.94 * x, 0.92 * y, 0.0), (x, y, 0.03 * h), (x, y, body_h)], n)
        cap = _loft([(x, y, body_h - 0.001), (x, y, h - 0.01), (0.9 * x, 0.85 * y, h)], n)
    return Geometry(((body, body_color), (cap, cap_color)), (col.hull_part(body), col.hull_part(cap)))


@dataclass(frozen=True)
class LipstickShape:
    """With the cap off (the bullet twisted up beside it), and a square case instead of a round one."""

    open: bool = False
    square: bool = False


@builder(LipstickShape)
def lipstick(v: Variant, p: LipstickShape) -> Geometry:
    """A lipstick standing upright: a metal case with its cap on, or open with the coloured bullet showing."""
    x, y, h = v.size
    case_color, tint = v.color(0, P.GOLD), v.color(1, P.RED)
    d = min(x, y)

    def column(width: float, height: float, z0: float) -> trimesh.Trimesh:
        if p.square:
            return shapes.box((width, width, height), (0, 0, z0 + height / 2))
        return shapes.cylinder(width / 2, height, (0, 0, z0 + height / 2))

    base_h = 0.45 * h
    base = column(d, base_h, 0.0)
    if not p.open:
        cap = column(d, h - base_h + 0.002, base_h - 0.002)
        return Geometry(
            ((base, case_color), (cap, v.color(2, case_color))),
            (col.hull_part(np.vstack([base.vertices, cap.vertices])),),
        )
    sleeve = column(0.85 * d, 0.15 * h, base_h - 0.001)
    bullet_r = 0.33 * d
    z0 = base_h + 0.15 * h - 0.002
    ring = _superellipse(bullet_r, bullet_r, 2.0, 24)
    slant = 0.15 * h
    tip = h - slant + slant * (ring[:, 0] / bullet_r + 1) / 2  # the tip is cut at a slant
    bullet = _hull(np.vstack([np.column_stack([ring, z]) for z in (np.full(24, z0), np.full(24, h - slant), tip)]))
    parts = ((base, case_color), (sleeve, v.color(2, case_color)), (bullet, tint))
    return Geometry(parts, (col.hull_part(np.vstack([base.vertices, sleeve.vertices])), col.hull_part(bullet)))


@dataclass(frozen=True)
class ClothesShape:
    """The garment folded: a "shirt" (collar and buttons), a "sweater" (ribbed hem), "jeans" (pocket and seam), or a
    pair of rolled "socks"."""

    garment: Literal["shirt", "sweater", "jeans", "socks"] = "shirt"


@builder(ClothesShape)
def clothes(v: Variant, p: ClothesShape) -> Geometry:
    """A folded garment lying flat: a soft stack of two or three layers with the garment's details on top."""
    x, y, z = v.size
    color, detail = v.color(0, P.WHITE), v.color(1, P.rgb(200, 200, 200))
    if p.garment == "socks":
        return _rolled_socks(x, y, z, color, detail)
    layers = 2 if p.garment == "shirt" else 3
    t = z / layers
    stack = [
        shapes.rounded_box((x - 0.006 * (k % 2), y - 0.004 * k, t + 0.001), 0.45 * t, (0, 0, t * k + t / 2))
        for k in range(layers - 1)
    ]
    stack.append(shapes.rounded_box((x, y - 0.004 * (layers - 1), t), 0.45 * t, (0, 0, z - t / 2)))
    parts = [(shapes.concatenate(stack), color)]
    if p.garment == "shirt":
        collar = shapes.slab(0.12 * x, 0.45 * y, 0.004, 0.015, (x / 2 - 0.08 * x, 0, z - 0.0015))
        placket = shapes.box((0.7 * x, 0.012, 0.001), (-0.05 * x, 0, z - 0.0003))
        parts += [(collar, detail), (placket, detail)]
    elif p.garment == "sweater":
        hem = shapes.box((0.08 * x, y - 0.004 * (layers - 1) - 0.6 * t, 0.0012), (-x / 2 + 0.06 * x, 0, z - 0.0004))
        neck = shapes.slab(0.06 * x, 0.3 * y, 0.0012, 0.01, (x / 2 - 0.06 * x, 0, z - 0.0004))
        parts += [(hem, detail), (neck, detail)]
    else:
        band = shapes.box((0.06 * x, y - 0.004 * (layers - 1) - 0.6 * t, 0.0012), (x / 2 - 0.06 * x, 0, z - 0.0004))
        pocket = shapes.slab(0.25 * x, 0.3 * y, 0.0012, 0.01, (0.15 * x, 0.2 * y, z - 0.0004))
        parts += [(band, detail), (pocket, detail)]
    return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


def _rolled_socks(x: float, y: float, z: float, color: RGBA, cuff: RGBA) -> Geometry:
    """A pair of socks rolled into two soft bundles lying side by side along y, each with its cuff turned over."""
    w = y / 2 - 0.002
    parts = []
    for s in (1, -1):
        centre = (0.0, s * (y / 2 - w / 2), z / 2)
        parts.append((shapes.rounded_box((x, w, z), 0.45 * min(w, z), centre), color))
        band = shapes.rounded_box((0.3 * x, w + 0.001, z + 0.001), 0.45 * min(w, z), (0.25 * x, centre[1], z / 2))
        parts.append((band, cuff))
    return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


@dataclass(frozen=True)
class ShoeShape:
    """The style: a "sneaker" (thick white sole), a "dress" shoe (thin sole, low) or a "boot" (high at the ankle);
    a pair side by side or one shoe."""

    style: Literal["sneaker", "dress", "boot"] = "sneaker"
    pair: bool = True


def _shoe(
    length: float, width: float, height: float, style: str
) -> tuple[trimesh.Trimesh, trimesh.Trimesh, trimesh.Trimesh]:
    """One shoe toe to +x: sole, upper (low at the toe, full height from the heel to mid-foot), the opening on top."""
    sole_h = {"sneaker": 0.22, "dress": 0.1, "boot": 0.1}[style] * height
    outline = _foot_outline(length, width)
    sole = shapes.extrude(outline, sole_h)
    ring = np.asarray(outline.buffer(-0.002).exterior.coords)[:-1]
    rise = np.clip((length / 2 - ring[:, 0]) / (0.55 * length), 0.0, 1.0)  # 0 at the toe, 1 from mid-foot back
    top_z = sole_h + (height - sole_h) * (0.35 + 0.65 * rise)
    shrink = 0.75 + 0.15 * (1 - rise)
    top = np.column_stack([ring[:, 0] * shrink + 0.02 * length, ring[:, 1] * shrink, top_z])
    upper = _hull(np.vstack([np.column_stack([ring, np.full(len(ring), sole_h - 0.001)]), top]))
    open_len = (0.3 if style == "boot" else 0.38) * length
    opening = _loft([(open_len, 0.55 * width, height - 0.0015), (open_len, 0.55 * width, height + 0.0002)], 2.0, 32)
    opening.apply_translation((-length / 2 + 0.08 * length + open_len / 2, 0, 0))
    return sole, upper, opening


@builder(ShoeShape)
def shoes(v: Variant, p: ShoeShape) -> Geometry:
    """Shoes toes to +x: a sole, an upper rising from the toe to the heel and a dark opening on top; a hull each."""
    x, y, z = v.size
    gap = 0.02 if p.pair else 0.0
    width = (y - gap) / 2 if p.pair else y
    sole, upper, opening = _shoe(x, width, z, p.style)
    sole_color = v.color(1, P.WHITE if p.style == "sneaker" else P.BLACK)
    parts, collision = [], []
    for cy in (-(width + gap) / 2, (width + gap) / 2) if p.pair else (0.0,):
        pieces = [m.copy().apply_translation((0, cy, 0)) for m in (sole, upper, opening)]
        parts += [(pieces[0], sole_color), (pieces[1], v.color(0, P.BROWN)), (pieces[2], v.color(2, P.CHARCOAL))]
        collision.append(col.hull_part(np.vstack([pieces[0].vertices, pieces[1].vertices])))
    return Geometry(tuple(parts), tuple(collision))


@dataclass(frozen=True)
class HatShape:
    """The style: a baseball "cap" (a crown and a visor towards +x), a "brim" hat (a crown on a wide round brim) or
    a "beanie" (a knitted dome with a turned-up cuff and a pom-pom)."""

    style: Literal["cap", "brim", "beanie"] = "cap"


def _dome(radius: float, height: float, squareness: float = 2.0) -> trimesh.Trimesh:
    """A solid revolved dome: a quarter superellipse from (radius, 0) to the top of the axis."""
    t = np.linspace(0.0, np.pi / 2, 12)
    c, s = np.cos(t), np.sin(t)
    arc = [
        (radius * float(ci) ** (2 / squareness), height * float(si) ** (2 / squareness))
        for ci, si in zip(c, s, strict=True)
    ]
    return shapes.lathe([(0.0, 0.0), *arc[:-1], (0.0, height)], 40)


@builder(HatShape)
def hat(v: Variant, p: HatShape) -> Geometry:
    """A hat resting on its rim or brim: a baseball cap, a brimmed sun hat or fedora, or a beanie."""
    x, y, z = v.size
    color, accent = v.color(0, P.NAVY), v.color(1, P.WHITE)
    if p.style == "brim":
        brim_t = 0.006
        brim = shapes.cylinder(x / 2, brim_t, (0, 0, brim_t / 2), sections=48)
        crown = _dome(0.3 * x, z - brim_t + 0.001, 4.0).apply_translation((0, 0, brim_t - 0.001))
        band = trimesh.creation.annulus(0.28 * x, 0.305 * x, 0.02, sections=40).apply_translation(
            (0, 0, brim_t + 0.011)
        )
        parts = ((brim, color), (crown, color), (band, accent))
        return Geometry(parts, (col.cylinder_part(x / 2, brim_t, (0, 0, brim_t / 2)), col.hull_part(crown)))
    if p.style == "beanie":
        cuff_h, pom = 0.3 * z, 0.22 * z
        body = _dome(0.48 * x, z - pom * 0.6, 3.0)
        cuff = shapes.cylinder(x / 2, cuff_h, (0, 0, cuff_h / 2), sections=40)
        ball = shapes.sphere(pom / 2, (0, 0, z - pom / 2), 2)
        parts = ((body, color), (cuff, v.color(2, color)), (ball, accent))
        return Geometry(parts, (col.hull_part(np.vstack([body.vertices, cuff.vertices, ball.vertices])),))
    rc = y / 2
    xc = -x / 2 + rc
    crown = _dome(rc, z - 0.004, 2.6).apply_translation((xc, 0, 0))
    button = shapes.cylinder(0.007, 0.006, (xc, 0, z - 0.003))
    visor_outline = Point(0, 0).buffer(1.0, quad_segs=16)
    visor_outline = shapely_scale(visor_outline, x - rc, 0.85 * rc, origin=(0, 0))
    visor_outline = visor_outline.intersection(shapely_box(0, -rc, x, rc))
    visor = shapes.extrude(visor_outline, 0.004).apply_translation((xc, 0, 0))
    parts = ((crown, color), (button, color), (visor, v.color(1, color)))
    return Geometry(parts, (col.hull_part(np.vstack([crown.vertices, button.vertices])), col.hull_part(visor)))


@dataclass(frozen=True)
class PoufShape:
    """A square pouf instead of a round one; piping bands round the top and bottom edges."""

    square: bool = False
    piping: bool = True


@builder(PoufShape)
def pouf(v: Variant, p: PoufShape) -> Geometry:
    """A soft pouf or footstool: a squat drum (or cube) with rounded edges and piped seams; one convex hull."""
    x, y, h = v.size
    color, trim = v.color(0, P.rgb(190, 170, 140)), v.color(1, P.rgb(150, 130, 100))
    inset = 0.004 if p.piping else 0.0
    if p.square:
        body = shapes.rounded_box((x - 2 * inset, y - 2 * inset, h), 0.04, (0, 0, h / 2))
    else:
        r = x / 2 - inset
        body = shapes.lathe([(0, 0), (0.93 * r, 0), (r, 0.08 * h), (r, 0.9 * h), (0.93 * r, h), (0, h)], 48)
    parts = [(body, color)]
    if p.piping:
        for zz in (0.08 * h, 0.9 * h):
            if p.square:
                band = shapes.slab(x, y, 0.01, 0.04, (0, 0, zz))
                hole = shapes.slab(x - 0.012, y - 0.012, 0.02, 0.035, (0, 0, zz))
                parts.append((trimesh.boolean.difference([band, hole], engine="manifold"), trim))
            else:
                parts.append(
                    (
                        trimesh.creation.annulus(x / 2 - 0.008, x / 2, 0.01, sections=48).apply_translation((0, 0, zz)),
                        trim,
                    )
                )
    return Geometry(tuple(parts), (col.hull_part(body),))


@dataclass(frozen=True)
class KeysShape:
    """How many keys hang on the ring; a car key fob among them."""

    count: int = 3
    fob: bool = False


def _key(angle: float, reach: float) -> list[trimesh.Trimesh]:
    """One flat key on the ring, its bow near the ring and its blade pointing out at `angle` from +x."""
    bow = shapes.cylinder(0.012, 0.002, (reach + 0.012, 0, 0.001), sections=20)
    blade = shapes.box((0.035, 0.008, 0.0018), (reach + 0.024 + 0.0175, 0, 0.0009))
    teeth = [shapes.box((0.003, 0.003, 0.0018), (reach + 0.03 + 0.005 * k, -0.005, 0.0009)) for k in range(5)]
    turn = trimesh.transformations.rotation_matrix(angle, (0, 0, 1))
    return [_turned(m, turn) for m in (bow, blade, *teeth)]


@builder(KeysShape)
def keys(v: Variant, p: KeysShape) -> Geometry:
    """A bunch of keys lying flat: a split ring at -x and flat keys fanning out towards +x; one flat hull."""
    ring = trimesh.creation.annulus(0.011, 0.0135, 0.0025, sections=32).apply_translation((0, 0, 0.00125))
    metal = v.color(0, P.BRASS)
    angles = np.linspace(-0.45, 0.45, p.count) if p.count > 1 else np.zeros(1)
    keys_meshes: list[trimesh.Trimesh] = []
    for a in angles:
        keys_meshes += _key(float(a), 0.008)
    parts = [(ring, P.SILVER), (shapes.concatenate(keys_meshes), metal)]
    if p.fob:
        fob = shapes.rounded_box((0.055, 0.03, 0.013), 0.005, (0.012, 0.0, 0.0065))
        fob.apply_transform(trimesh.transformations.rotation_matrix(-0.9, (0, 0, 1)))
        fob.apply_translation((0.02, -0.03, 0))
        buttons = [shapes.cylinder(0.004, 0.0014, (0.0, 0.0, 0.0)) for _ in range(2)]
        for k, b in enumerate(buttons):
            b.apply_translation(fob.bounds.mean(axis=0) * (1, 1, 0) + (0.006 * (k - 0.5), 0.004 * (k - 0.5), 0.0128))
        parts += [(fob, v.color(1, P.BLACK)), (shapes.concatenate(buttons), P.GREY)]
    geometry = Geometry(tuple(parts), (col.hull_part(np.vstack([m.vertices for m, _ in parts])),))
    return fit_to_size(geometry, v.size)


@dataclass(frozen=True)
class ReedDiffuserShape:
    """How many reeds; a square bottle instead of a round one."""

    reeds: int = 8
    square: bool = False


@builder(ReedDiffuserShape)
def reed_diffuser(v: Variant, p: ReedDiffuserShape) -> Geometry:
    """A reed diffuser: a glass bottle of scented oil with thin rattan reeds fanning out of its neck."""
    x, y, h = v.size
    body_h = 0.35 * h
    r = x / 2
    if p.square:
        body = shapes.rounded_box((x, y, body_h), 0.006, (0, 0, body_h / 2))
    else:
        body = shapes.lathe(
            [(0, 0), (0.95 * r, 0), (r, 0.05 * body_h), (r, 0.8 * body_h), (0.35 * r, body_h), (0, body_h)]
        )
    neck = shapes.cylinder(0.25 * min(x, y), 0.1 * h, (0, 0, body_h + 0.05 * h - 0.001))
    base = np.array([0.0, 0.0, body_h + 0.02 * h])
    reeds = []
    for k in range(p.reeds):
        a = 2 * np.pi * k / p.reeds
        spread = 0.85 * min(x, y) / 2
        tip = np.array([spread * np.cos(a), spread * np.sin(a), h - 0.002])
        reeds.append(shapes.tube(np.linspace(base, tip, 3), 0.0018, sides=6))
    parts = (
        (body, v.color(0, P.GLASS)),
        (neck, v.color(1, P.BLACK)),
        (shapes.concatenate(reeds), v.color(2, P.rgb(110, 80, 50))),
    )
    stalks = np.vstack([m.vertices for m in reeds])
    return Geometry(parts, (col.hull_part(body), col.hull_part(np.vstack([neck.vertices, stalks]))))


@dataclass(frozen=True)
class HangerShape:
    """Wooden (flat wide shoulders) instead of a round wire or plastic rod; a bar across the bottom."""

    wooden: bool = False
    bar: bool = True


@builder(HangerShape)
def hanger(v: Variant, p: HangerShape) -> Geometry:
    """A clothes hanger lying flat: shoulders rising to a neck at the middle, a hook at +y and a bottom bar."""
    x, y, z = v.size
    r = z / 2
    hook_h = 0.32 * y
    y0, neck_y = -y / 2 + r, y / 2 - hook_h
    color, metal = v.color(0, P.rgb(240, 240, 240)), v.color(1, P.SILVER)
    shoulders = np.array([[-x / 2 + r, y0, r], [0, neck_y, r], [x / 2 - r, y0, r]])
    frame: list[trimesh.Trimesh] = []
    for a, b in ((shoulders[0], shoulders[1]), (shoulders[1], shoulders[2])):
        if p.wooden:
            frame.append(
                _hull(
                    np.vstack(
                        [a + (0, dy, dz) for dy in (-0.012, 0.012) for dz in (-r, r)]
                        + [b + (0, dy, dz) for dy in (-0.012, 0.012) for dz in (-r, r)]
                    )
                )
            )
        else:
            frame.append(shapes.tube(np.linspace(a, b, 3), r, sides=8))
    if p.bar:
        bar_r = 0.35 * r if p.wooden else r
        frame.append(shapes.tube(np.array([shoulders[0], shoulders[2]]) + (0, 0, bar_r - r), bar_r, sides=8))
    hr, y_s = 0.3 * hook_h, neck_y + 0.4 * hook_h  # the hook: straight up from the neck, then curling over to -x
    t = np.linspace(0.0, 1.15 * np.pi, 14)
    arc = np.column_stack([-hr + hr * np.cos(t), y_s + hr * np.sin(t), np.full(14, r)])
    hook_path = np.vstack([[0.0, neck_y - 0.01, r], arc])
    hook_r = 0.55 * r if p.wooden else r
    hook = shapes.tube(hook_path + (0, 0, hook_r - r), hook_r, sides=8)
    parts = ((shapes.concatenate(frame), color), (hook, metal if p.wooden else color))
    geometry = Geometry(parts, (col.hull_part(np.vstack([m.vertices for m, _ in parts])),))
    return fit_to_size(geometry, v.size)


@dataclass(frozen=True)
class SoapDishShape:
    """Round instead of rectangular; raised ribs across the floor that let the soap drain."""

    round: bool = False
    ribs: bool = True


@builder(SoapDishShape)
def soap_dish(v: Variant, p: SoapDishShape) -> Geometry:
    """A shallow soap dish with a low wall (a container for a bar of soap) and drainage ribs on its floor."""
    x, y, z = v.size
    color = v.color(0, P.WHITE)
    wall, floor = 0.004, 0.004
    if p.round:
        vessel = Vessel(resample([(0.8 * x / 2, 0.0), (x / 2, z)], 4), wall, floor, stations=2)
        parts = [(vessel.mesh(), color)]
        collision = list(vessel.collision(14))
        cavity = vessel.cavity()
        rib_len = 0.55 * x
    else:
        parts = [(_open_box_mesh(x, y, z, wall, floor, 0.015), color)]
        collision = list(col.open_box_parts(x, y, z, wall, floor))
        cavity = Cavity(rectangle(x - 2 * wall, y - 2 * wall), floor, z - floor)
        rib_len = x - 2 * wall - 0.004
    if p.ribs:
        rib_h = min(0.003, 0.25 * (z - floor))
        for k in range(-2, 3):
            centre = (0.0, k * 0.18 * (y - 2 * wall) / 1.0 * 0.5, floor + rib_h / 2 - 0.0005)
            parts.append((shapes.box((rib_len, 0.004, rib_h + 0.001), centre), v.color(1, color)))
            collision.append(col.box_part((rib_len, 0.004, rib_h + 0.001), centre))
    return Geometry(tuple(parts), tuple(collision), cavity)


@dataclass(frozen=True)
class ToiletBrushShape:
    """A square holder instead of a round one."""

    square: bool = False


@builder(ToiletBrushShape)
def toilet_brush(v: Variant, p: ToiletBrushShape) -> Geometry:
    """A toilet brush standing in its holder: a cup-shaped holder, the handle rising out of it and a knob on top."""
    x, y, h = v.size
    holder_h = 0.38 * h
    color = v.color(0, P.WHITE)
    if p.square:
        holder = shapes.rounded_box((x, y, holder_h), 0.008, (0, 0, holder_h / 2))
    else:
        r = x / 2
        holder = shapes.lathe(
            [(0, 0), (0.92 * r, 0), (r, 0.06 * holder_h), (r, holder_h), (0.8 * r, holder_h), (0, holder_h)]
        )
    rim = trimesh.creation.annulus(0.3 * min(x, y), 0.36 * min(x, y), 0.006, sections=32).apply_translation(
        (0, 0, holder_h + 0.002)
    )
    handle = shapes.cylinder(0.0065, h - holder_h - 0.015, (0, 0, holder_h + (h - holder_h - 0.015) / 2))
    knob = shapes.ellipsoid((0.016, 0.016, 0.01), (0, 0, h - 0.01), 2)
    parts = ((holder, color), (rim, v.color(1, P.SILVER)), (handle, v.color(1, P.SILVER)), (knob, v.color(2, color)))
    return Geometry(parts, (col.hull_part(holder), col.hull_part(np.vstack([handle.vertices, knob.vertices]))))


@dataclass(frozen=True)
class MakeupBrushShape:
    """The bristle tuft: a round "powder" dome, a flat "foundation" paddle or an angled "blush" tuft."""

    tuft: Literal["powder", "foundation", "blush"] = "powder"


@builder(MakeupBrushShape)
def makeup_brush(v: Variant, p: MakeupBrushShape) -> Geometry:
    """A makeup brush lying on the table: a tapered octagonal handle, a metal ferrule and a bristle tuft at +x."""
    x, y, z = v.size
    tuft_len = 0.3 * x
    ferrule_len = 0.15 * x
    handle_len = x - tuft_len - ferrule_len
    r_end, r_ferrule = 0.22 * z, 0.36 * z

    def ring(px: float, radius: float) -> np.ndarray:  # an octagon in the yz plane, its bottom flat on z = 0
        t = np.linspace(0.0, 2 * np.pi, 8, endpoint=False) + np.pi / 8
        return np.column_stack([np.full(8, px), radius * np.cos(t), radius * np.sin(t) + radius * np.cos(np.pi / 8)])

    x0 = -x / 2
    handle = _hull(np.vstack([ring(x0, r_end), ring(x0 + handle_len + 0.002, 0.8 * r_ferrule)]))
    ferrule = _hull(
        np.vstack([ring(x0 + handle_len, 0.85 * r_ferrule), ring(x0 + handle_len + ferrule_len + 0.002, r_ferrule)])
    )
    tx0 = x0 + handle_len + ferrule_len
    if p.tuft == "foundation":
        pts = [(tx0, 0.7 * y, 0.8 * z), (tx0 + 0.8 * tuft_len, y, 0.45 * z), (x / 2, 0.8 * y, 0.35 * z)]
    else:
        pts = [(tx0, 0.8 * y, 0.8 * z), (tx0 + 0.55 * tuft_len, y, z), (x / 2, 0.35 * y, 0.4 * z)]
    rings = [
        np.column_stack(
            [
                np.full(24, px),
                _superellipse(w / 2, d / 2, 2.0, 24)[:, 0],
                _superellipse(w / 2, d / 2, 2.0, 24)[:, 1] + d / 2,
            ]
        )
        for px, w, d in pts
    ]
    if p.tuft == "blush":
        rings[-1][:, 0] += 0.15 * tuft_len * rings[-1][:, 1] / (0.2 * y)  # an angled tip
    tuft = _hull(np.vstack(rings))
    parts = ((handle, v.color(0, P.BLACK)), (ferrule, v.color(1, P.SILVER)), (tuft, v.color(2, P.rgb(220, 190, 160))))
    geometry = Geometry(parts, (col.hull_part(np.vstack([m.vertices for m, _ in parts])),))
    return fit_to_size(geometry, v.size)


@dataclass(frozen=True)
class ClothesIronShape:
    """A transparent water tank in the second colour under the handle."""

    tank: bool = True


@builder(ClothesIronShape)
def clothes_iron(v: Variant, p: ClothesIronShape) -> Geometry:
    """A steam iron standing on its soleplate: a pointed plate (tip at +x), a body rising to a handle loop."""
    x, y, z = v.size
    plate_h = 0.1 * z
    tip = Point(x / 2 - 0.12 * y, 0).buffer(0.12 * y, quad_segs=8)
    outline = unary_union([tip, shapely_box(-x / 2, -y / 2, -0.25 * x, y / 2)]).convex_hull
    assert isinstance(outline, Polygon)
    plate = shapes.extrude(outline, plate_h)
    ring = np.asarray(outline.exterior.coords)[:-1]
    body_top = 0.5 * z
    body = _hull(
        np.vstack(
            [
                np.column_stack([ring, np.full(len(ring), plate_h - 0.001)]),
                np.column_stack([ring * (0.8, 0.7) + (-0.05 * x, 0), np.full(len(ring), body_top)]),
            ]
        )
    )
    path = np.array(
        [
            [0.3 * x, 0, body_top - 0.01],
            [0.25 * x, 0, z - 0.015],
            [-0.15 * x, 0, z - 0.015],
            [-0.3 * x, 0, body_top - 0.01],
        ]
    )
    handle = shapes.tube(shapes.resample_polyline(path, 12), 0.015, sides=12)
    color, sole = v.color(0, P.rgb(60, 120, 200)), v.color(2, P.SILVER)
    parts = [(plate, sole), (body, color), (handle, color)]
    if p.tank:
        tank = _loft([(0.35 * x, 0.5 * y, body_top - 0.002), (0.3 * x, 0.35 * y, body_top + 0.03)], 2.0)
        tank.apply_translation((0.05 * x, 0, 0))
        parts.append((tank, v.color(1, P.rgb(200, 225, 245, 0.6))))
    collision = (col.hull_part(np.vstack([plate.vertices, body.vertices])), col.hull_part(handle))
    return fit_to_size(Geometry(tuple(parts), collision), v.size)


@dataclass(frozen=True)
class PhotoAlbumShape:
    """A window in the cover showing a photo; a ribbon tie around the album."""

    window: bool = True
    ribbon: bool = False


@builder(PhotoAlbumShape)
def photo_album(v: Variant, p: PhotoAlbumShape) -> Geometry:
    """A photo album lying flat: padded covers round a block of thick pages, a spine at -x, a photo window."""
    x, y, z = v.size
    cover = v.color(0, P.rgb(120, 40, 40))
    board = 0.15 * z
    covers = [shapes.rounded_box((x, y, board), 0.4 * board, (0, 0, zz)) for zz in (board / 2, z - board / 2)]
    spine = shapes.rounded_box((0.04 * x, y, z), 0.3 * board, (-x / 2 + 0.02 * x, 0, z / 2))
    pages = shapes.box((x - 0.012, y - 0.012, z - 2 * board + 0.002), (0.004, 0, z / 2))
    parts = [(shapes.concatenate([*covers, spine]), cover), (pages, P.PAPER)]
    if p.window:
        frame = shapes.box((0.45 * x, 0.4 * y, 0.0008), (0.05 * x, 0.05 * y, z - 0.0003))
        photo = shapes.box((0.38 * x, 0.33 * y, 0.001), (0.05 * x, 0.05 * y, z - 0.0003))
        parts += [(frame, v.color(1, P.GOLD)), (photo, v.color(2, P.SKY))]
    if p.ribbon:
        parts.append((shapes.box((0.03, y + 0.001, z + 0.0006), (0.25 * x, 0, z / 2)), v.color(1, P.GOLD)))
    return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


@dataclass(frozen=True)
class HotWaterBottleShape:
    """A knitted cover over the rubber bottle (the neck and stopper stay visible)."""

    cover: bool = False


@builder(HotWaterBottleShape)
def hot_water_bottle(v: Variant, p: HotWaterBottleShape) -> Geometry:
    """A hot water bottle lying flat: a soft rounded body, a neck at +x and a stopper; one convex hull."""
    x, y, z = v.size
    neck_len, stopper_len = 0.1 * x, 0.07 * x
    body_len = x - neck_len - stopper_len
    bx = -x / 2 + body_len / 2
    body = _loft([(0.96 * body_len, 0.96 * y, 0.0), (body_len, y, 0.35 * z), (0.96 * body_len, 0.94 * y, z)], 5.0)
    body.apply_translation((bx, 0, 0))
    neck = shapes.box((neck_len + 0.01, 0.3 * y, 0.4 * z), (bx + body_len / 2 + neck_len / 2 - 0.005, 0, 0.2 * z))
    stopper = shapes.cylinder(
        0.45 * z, stopper_len + 0.002, (x / 2 - stopper_len / 2, 0, 0.45 * z), axis="x", sections=12
    )
    color = v.color(0, P.rgb(200, 60, 60))
    if p.cover:  # knitted cables running along the bottle
        ribs = [shapes.box((0.7 * body_len, 0.006, 0.0012), (bx, k * 0.15 * y, z - 0.0003)) for k in range(-2, 3)]
    else:  # moulded rubber ribs across it
        ribs = [shapes.box((0.004, 0.7 * y, 0.0012), (bx + k * 0.12 * body_len, 0, z - 0.0003)) for k in range(-3, 4)]
    body_color = v.color(2, color) if p.cover else color
    parts = (
        (body, body_color),
        (neck, color),
        (stopper, v.color(1, P.CHARCOAL)),
        (shapes.concatenate(ribs), v.color(2, color)),
    )
    return Geometry(parts, (col.hull_part(np.vstack([m.vertices for m, _ in parts])),))


@dataclass(frozen=True)
class GlassesCaseShape:
    """A hard shell (a clamshell with a hinge) instead of a soft pouch."""

    hard: bool = True


@builder(GlassesCaseShape)
def glasses_case(v: Variant, p: GlassesCaseShape) -> Geometry:
    """A glasses case lying flat: a rounded oblong clamshell with a seam around it, or a soft flat pouch."""
    x, y, z = v.size
    n = 3.0 if p.hard else 6.0
    body = _loft([(0.94 * x, 0.85 * y, 0.0), (x, y, 0.45 * z), (0.94 * x, 0.85 * y, z)], n, 48)
    seam = _loft([(x + 0.0004, y + 0.0004, 0.44 * z), (x + 0.0004, y + 0.0004, 0.5 * z)], n, 48)
    parts = [(body, v.color(0, P.BLACK)), (seam, v.color(1, P.CHARCOAL))]
    if p.hard:
        hinge = shapes.cylinder(0.003, 0.35 * x, (0, -y / 2 + 0.002, 0.47 * z), axis="x", sections=10)
        parts.append((hinge, v.color(2, P.SILVER)))
    return Geometry(tuple(parts), (col.hull_part(body),))


@dataclass(frozen=True)
class SuitcaseShape:
    """A hard shell (ribbed) instead of soft fabric (a zip and a front pocket); wheels under it."""

    hard: bool = True
    wheels: bool = True


@builder(SuitcaseShape)
def suitcase(v: Variant, p: SuitcaseShape) -> Geometry:
    """A suitcase standing upright: a rounded case (front +x), a retracted trolley handle on top, a side handle and
    four wheels."""
    x, y, z = v.size
    color, trim = v.color(0, P.NAVY), v.color(1, P.CHARCOAL)
    wheel_h = 0.06 if p.wheels else 0.015
    top_h = 0.03
    body_h = z - wheel_h - top_h
    body = shapes.rounded_box((x, y, body_h), 0.03, (0, 0, wheel_h + body_h / 2))
    parts = [(body, color)]
    if p.hard:
        ribs = [
            shapes.box((x + 0.002, 0.02, 0.8 * body_h), (0, dy, wheel_h + body_h / 2))
            for dy in (-0.25 * y, 0.0, 0.25 * y)
        ]
        parts.append((shapes.concatenate(ribs), v.color(2, color)))
    else:
        zip_band = shapes.box((0.012, y - 0.04, body_h - 0.04), (0, 0, wheel_h + body_h / 2))
        pocket = shapes.rounded_box((0.03, 0.7 * y, 0.5 * body_h), 0.01, (x / 2 - 0.012, 0, wheel_h + 0.45 * body_h))
        parts += [(zip_band, trim), (pocket, v.color(2, color))]
    feet = []
    for sx in (-1, 1):
        for sy in (-1, 1):
            centre = (sx * (x / 2 - 0.03), sy * (y / 2 - 0.035), wheel_h / 2)
            if p.wheels:
                feet.append(shapes.cylinder(wheel_h / 2, 0.02, centre, axis="y", sections=16))
            else:
                feet.append(shapes.box((0.03, 0.03, wheel_h + 0.002), (centre[0], centre[1], wheel_h / 2 + 0.001)))
    posts = [
        shapes.box((0.015, 0.015, top_h + 0.005), (-x / 4, dy, z - top_h / 2 - 0.0025)) for dy in (-0.3 * y, 0.3 * y)
    ]
    grip = shapes.box((0.025, 0.62 * y, 0.015), (-x / 4, 0, z - 0.0075))
    parts += [(shapes.concatenate(feet), P.BLACK), (shapes.concatenate([*posts, grip]), trim)]
    collision = (
        col.hull_part(body),
        col.hull_part(np.vstack([m.vertices for m in feet])),
        col.hull_part(np.vstack([m.vertices for m in (*posts, grip)])),
    )
    return Geometry(tuple(parts), collision)


@dataclass(frozen=True)
class UmbrellaShape:
    """A J hook handle (lying flat) instead of a straight grip."""

    hook: bool = True


@builder(UmbrellaShape)
def umbrella(v: Variant, p: UmbrellaShape) -> Geometry:
    """A closed umbrella lying on its side: the furled canopy along x (tip at +x), a handle at -x."""
    x, y, z = v.size
    rc = z / 2
    grip_r = 0.012
    hook_w = y - rc - grip_r if p.hook else 0.0
    handle_len = 0.15 * x if p.hook else 0.12 * x
    canopy_len = 0.72 * x
    c0 = -x / 2 + handle_len + 0.04 * x
    canopy_pts = []
    t = np.linspace(0.0, 2 * np.pi, 8, endpoint=False) + np.pi / 8  # an octagon with a flat facet down: no rolling
    for px, r in ((c0, 0.45 * rc), (c0 + 0.2 * canopy_len, rc), (c0 + canopy_len, 0.25 * rc)):
        lift = r * np.cos(np.pi / 8)
        canopy_pts.append(np.column_stack([np.full(8, px), r * np.cos(t), r * np.sin(t) + lift]))
    canopy = _hull(np.vstack(canopy_pts))
    shaft = shapes.cylinder(
        0.004, x / 2 - c0 + 0.04 * x, ((x / 2 + c0 - 0.04 * x) / 2 + 0.0, 0, 0.3 * rc + 0.004), axis="x", sections=8
    )
    color, dark = v.color(0, P.NAVY), v.color(1, P.BLACK)
    parts = [(canopy, color), (shaft, P.SILVER)]
    hx1 = c0 + 0.01
    if p.hook:
        straight = np.array([[hx1, 0.0, grip_r], [-x / 2 + hook_w / 2 + grip_r, 0.0, grip_r]])
        t = np.linspace(0.0, np.pi, 12)
        centre = np.array([-x / 2 + hook_w / 2 + grip_r, hook_w / 2, grip_r])
        arc = centre + np.column_stack([-(hook_w / 2) * np.sin(t), -(hook_w / 2) * np.cos(t), np.zeros(12)])
        path = np.vstack([straight, arc[1:]])
        grip = shapes.tube(path, grip_r, sides=8)
    else:
        grip = shapes.cylinder(0.014, hx1 - (-x / 2), ((hx1 - x / 2) / 2, 0, 0.014), axis="x", sections=8)
    parts.append((grip, dark))
    collision = (col.hull_part(np.vstack([canopy.vertices, shaft.vertices])), col.hull_part(grip))
    return fit_to_size(Geometry(tuple(parts), collision), v.size)


@dataclass(frozen=True)
class HandbagShape:
    """How much narrower the top is than the base (0: straight sides); a flap with a clasp over the front (+x)."""

    taper: float = 0.15
    flap: bool = True
    open: bool = False  # an open tote: straight walls, no top, things are put into it


@builder(HandbagShape)
def handbag(v: Variant, p: HandbagShape) -> Geometry:
    """A handbag standing on its base: a tapered body, two arched handles on top and a flap with a clasp."""
    x, y, z = v.size
    if p.open:
        return _open_tote(v)
    body_h = 0.68 * z
    top_w = y * (1 - p.taper)
    body = _loft([(0.96 * x, 0.97 * y, 0.0), (x, y, 0.05 * body_h), (0.8 * x, top_w, body_h)], 6.0)
    color = v.color(0, P.BROWN)
    parts = [(body, color)]
    handles = []
    t = np.linspace(0.0, np.pi, 13)
    for hx in (-0.18 * x, 0.18 * x):
        path = np.column_stack(
            [np.full(13, hx), 0.3 * top_w * np.cos(t), body_h - 0.01 + (z - body_h + 0.002) * np.sin(t)]
        )
        path[:, 2] = np.minimum(path[:, 2], z - 0.006)
        handles.append(shapes.tube(path, 0.006, sides=10))
    parts.append((shapes.concatenate(handles), v.color(1, color)))
    if p.flap:
        flap = shapes.box((0.006, 0.85 * top_w, 0.45 * body_h), (0.4 * x - 0.002, 0, 0.75 * body_h))
        clasp = shapes.box((0.006, 0.03, 0.02), (0.4 * x + 0.002, 0, 0.55 * body_h))
        parts += [(flap, v.color(1, color)), (clasp, v.color(2, P.GOLD))]
    collision = (col.hull_part(body), *(col.hull_part(h) for h in handles))
    return fit_to_size(Geometry(tuple(parts), collision), v.size)


def _open_tote(v: Variant) -> Geometry:
    """An open tote bag: an open box of canvas and two handles rising from its long sides (clear of the opening)."""
    x, y, z = v.size
    body_h = 0.72 * z
    color = v.color(0, P.rgb(225, 210, 180))
    tote = open_tray((x, y, body_h), 0.003, 0.004, color, radius=0.01)
    t = np.linspace(0.0, np.pi, 13)
    handles = []
    for hx in (-(x / 2 - 0.004), x / 2 - 0.004):
        path = np.column_stack(
            [np.full(13, hx), 0.28 * y * np.cos(t), body_h - 0.01 + (z - body_h + 0.006) * np.sin(t)]
        )
        path[:, 2] = np.minimum(path[:, 2], z - 0.004)
        handles.append(shapes.tube(path, 0.004, sides=10))
    parts = (*tote.parts, (shapes.concatenate(handles), v.color(1, color)))
    return Geometry(parts, (*tote.collision, *(col.hull_part(h) for h in handles)), tote.cavity)


@dataclass(frozen=True)
class PlungerShape:
    """A flanged toilet cup (a lip below the dome) instead of a flat sink cup."""

    flange: bool = False


@builder(PlungerShape)
def plunger(v: Variant, p: PlungerShape) -> Geometry:
    """A plunger standing on its rubber cup: a squat dome and a long wooden or plastic handle with a rounded end."""
    d, _, h = v.size
    r = d / 2
    cup_h = 0.16 * h if p.flange else 0.12 * h
    profile = [(0.0, 0.0), (r, 0.0), (0.98 * r, 0.3 * cup_h), (0.75 * r, 0.8 * cup_h), (0.25 * r, cup_h), (0.0, cup_h)]
    if p.flange:
        profile = [
            (0.0, 0.0),
            (0.55 * r, 0.0),
            (0.55 * r, 0.2 * cup_h),
            (r, 0.35 * cup_h),
            (0.8 * r, 0.85 * cup_h),
            (0.25 * r, cup_h),
            (0.0, cup_h),
        ]
    cup = shapes.lathe(profile, 40)
    handle_r = 0.012
    handle = shapes.cylinder(
        handle_r, h - cup_h - handle_r + 0.005, (0, 0, cup_h - 0.005 + (h - cup_h - handle_r + 0.005) / 2)
    )
    end = shapes.sphere(handle_r, (0, 0, h - handle_r), 2)
    parts = ((cup, v.color(0, P.RED)), (handle, v.color(1, P.WOOD)), (end, v.color(1, P.WOOD)))
    collision = (col.hull_part(cup), col.hull_part(np.vstack([handle.vertices, end.vertices])))
    return Geometry(parts, collision)


@dataclass(frozen=True)
class JewelryShape:
    """The piece: a "necklace" (a chain with a pendant), a "bracelet" or bangle, a "ring", or a pair of "earrings"."""

    piece: Literal["necklace", "bracelet", "ring", "earrings"] = "necklace"


def _torus(radius: float, thickness: float, centre: tuple[float, float]) -> trimesh.Trimesh:
    """A flat-lying torus of outer radius `radius` and wire thickness `thickness`, resting on z = 0."""
    tor = trimesh.creation.torus(radius - thickness / 2, thickness / 2, major_sections=40, minor_sections=10)
    return tor.apply_translation((centre[0], centre[1], thickness / 2))


@builder(JewelryShape)
def jewelry(v: Variant, p: JewelryShape) -> Geometry:
    """A piece of jewellery lying flat: a chain loop with a pendant, a bangle, a ring with a stone, or two hoops."""
    x, y, z = v.size
    metal, stone = v.color(0, P.GOLD), v.color(1, P.rgb(200, 30, 60))
    if p.piece == "necklace":
        t = np.linspace(0.05 * np.pi, 1.95 * np.pi, 48)  # open at the clasp
        path = np.column_stack(
            [0.45 * x * np.cos(t), 0.42 * y * np.sin(t) * (1 + 0.25 * np.cos(t)), np.full(48, 0.0015)]
        )
        chain = shapes.tube(path, 0.0015, sides=6)
        pendant = shapes.cylinder(0.008, 0.004, (-0.45 * x - 0.006, 0, 0.002), sections=16)
        parts = [(chain, metal), (pendant, stone)]
    elif p.piece == "earrings":
        r = min(y / 4, x / 2)
        parts = [(_torus(r, 0.002, (0.0, s * (y / 2 - r))), metal) for s in (1, -1)]
        parts += [(shapes.sphere(0.003, (r - 0.003, s * (y / 2 - r), 0.003), 1), stone) for s in (1, -1)]
    else:
        band = min(x, y) / 2
        thickness = 0.0025 if p.piece == "ring" else 0.006
        parts = [(_torus(band, thickness, (0.0, 0.0)), metal)]
        if p.piece == "ring":
            gem = shapes.cone(
                0.003,
                0.0015,
                z - thickness + 0.001,
                (band - thickness / 2, 0, thickness + (z - thickness) / 2 - 0.0005),
                sections=8,
            )
            parts.append((gem, stone))
    geometry = Geometry(tuple(parts), (col.hull_part(np.vstack([m.vertices for m, _ in parts])),))
    return fit_to_size(geometry, v.size)


@dataclass(frozen=True)
class VinylRecordShape:
    """The record lying bare instead of in its printed sleeve."""

    bare: bool = False


@builder(VinylRecordShape)
def vinyl_record(v: Variant, p: VinylRecordShape) -> Geometry:
    """A vinyl record lying flat: a square printed sleeve with the disc's edge showing, or a bare black disc."""
    x, y, z = v.size
    label = v.color(1, P.RED)
    if p.bare:
        disc = shapes.cylinder(x / 2, z - 0.0004, (0, 0, (z - 0.0004) / 2), sections=64)
        sticker = shapes.cylinder(0.05, 0.0008, (0, 0, z - 0.0004), sections=32)
        return Geometry(((disc, P.BLACK), (sticker, label)), (col.cylinder_part(x / 2, z, (0, 0, z / 2)),))
    sleeve = shapes.box((x, y, z - 0.0004), (0, 0, (z - 0.0004) / 2))
    art = shapes.box((0.7 * x, 0.7 * y, 0.0008), (0, 0, z - 0.0004))
    parts = ((sleeve, v.color(0, P.WHITE)), (art, label))
    return Geometry(parts, (col.box_part((x, y, z), (0, 0, z / 2)),))


@dataclass(frozen=True)
class LoofahShape:
    """A mesh bath pouf (a ruffled ball with a cord loop) instead of a flat natural loofah sponge."""

    pouf: bool = True


@builder(LoofahShape)
def loofah(v: Variant, p: LoofahShape) -> Geometry:
    """A bath pouf resting squashed on its flat underside, with a cord loop; or an oblong natural loofah."""
    x, y, z = v.size
    color = v.color(0, P.rgb(120, 190, 220))
    if p.pouf:
        ball = shapes.ellipsoid((x / 2, y / 2, 0.56 * z), (0, 0, 0.46 * z), 3)
        ball = trimesh.boolean.intersection([ball, shapes.box((x, y, z), (0, 0, z / 2))], engine="manifold")
        ruffles = [
            trimesh.creation.annulus(0.3 * x, 0.49 * x, 0.006, sections=40).apply_translation((0, 0, zz))
            for zz in (0.3 * z, 0.62 * z)
        ]
        parts = [(ball, color), *((r, v.color(1, color)) for r in ruffles)]
        return Geometry(tuple(parts), (col.hull_part(ball),))
    body = _loft([(0.9 * x, 0.8 * y, 0.0), (x, y, 0.4 * z), (0.85 * x, 0.75 * y, z)], 2.0, 40)
    return Geometry(((body, v.color(0, P.rgb(220, 200, 150))),), (col.hull_part(body),))


@dataclass(frozen=True)
class CottonPadsShape:
    """Loose pads in a short stack, or a full sleeve of pads lying on its side."""

    sleeve: bool = False


@builder(CottonPadsShape)
def cotton_pads(v: Variant, p: CottonPadsShape) -> Geometry:
    """Round cotton pads: a small stack standing flat, or a plastic sleeve of pads lying along x."""
    x, y, z = v.size
    white = v.color(0, P.WHITE)
    if p.sleeve:
        r = z / 2
        pads = shapes.cylinder(r * 0.98, x - 0.01, (0, 0, r), axis="x", sections=24)
        wrap = shapes.cylinder(r, 0.8 * x, (0, 0, r), axis="x", sections=24)
        caps = shapes.concatenate([shapes.box((0.004, 0.7 * y, 0.7 * z), (s * (x / 2 - 0.002), 0, r)) for s in (1, -1)])
        parts = (
            (pads, white),
            (wrap, v.color(1, P.rgb(200, 225, 245, 0.5))),
            (caps, v.color(1, P.rgb(200, 225, 245, 0.5))),
        )
        return Geometry(parts, (col.hull_part(np.vstack([pads.vertices, wrap.vertices])),))
    count = max(1, int(round(z / 0.004)))
    t = z / count
    stack = [
        shapes.cylinder(x / 2 - 0.001 * (k % 2), t, (0.001 * (k % 3 - 1), 0, t * k + t / 2), sections=24)
        for k in range(count)
    ]
    return Geometry(((shapes.concatenate(stack), white),), (col.cylinder_part(x / 2, z, (0, 0, z / 2)),))


@dataclass(frozen=True)
class TweezersShape:
    """Slanted tips instead of pointed ones."""

    slanted: bool = True


@builder(TweezersShape)
def tweezers(v: Variant, p: TweezersShape) -> Geometry:
    """Tweezers lying flat: two thin arms joined at -x, spreading apart towards their tips at +x; one flat hull."""
    x, y, z = v.size
    arms = []
    for s in (1, -1):
        root, tip = np.array([-x / 2, s * 0.15 * y]), np.array([x / 2, s * 0.5 * y - s * 0.0015])
        d = tip - root
        n = np.array([-d[1], d[0]]) / np.linalg.norm(d) * 0.0025
        outline = [root - n, root + n, tip + n * (0.3 if not p.slanted else 1.0), tip - n]
        arms.append(shapes.extrude(Polygon(outline).convex_hull, z))
    joint = shapes.box((0.012, 0.4 * y, z), (-x / 2 + 0.006, 0, z / 2))
    metal = v.color(0, P.STEEL)
    parts = ((shapes.concatenate(arms), metal), (joint, metal))
    return fit_to_size(Geometry(parts, (col.hull_part(np.vstack([m.vertices for m, _ in parts])),)), v.size)


@builder(NoOptions)
def nail_clippers(v: Variant, _: NoOptions) -> Geometry:
    """Nail clippers lying flat: two stacked jaws with a cutting edge at +x and a lever on top; one flat hull."""
    x, y, z = v.size
    jaw_h = 0.3 * z
    lower = shapes.slab(x, y, jaw_h, 0.4 * y, (0, 0, jaw_h / 2))
    upper = shapes.slab(0.9 * x, y, jaw_h, 0.4 * y, (0.05 * x, 0, 1.5 * jaw_h))
    lever = shapes.slab(0.85 * x, 0.8 * y, 0.25 * z, 0.35 * y, (-0.05 * x, 0, z - 0.125 * z))
    pin = shapes.cylinder(0.0025, z - jaw_h, (0.25 * x, 0, jaw_h + (z - jaw_h) / 2), sections=12)
    metal = v.color(0, P.SILVER)
    parts = ((lower, metal), (upper, metal), (lever, v.color(1, metal)), (pin, P.STEEL))
    return Geometry(parts, (col.hull_part(np.vstack([m.vertices for m, _ in parts])),))


@dataclass(frozen=True)
class HairStraightenerShape:
    """A curling iron (a round barrel) instead of a straightener's two flat plates."""

    curling: bool = False


@builder(HairStraightenerShape)
def hair_straightener(v: Variant, p: HairStraightenerShape) -> Geometry:
    """A hair straightener (or curling iron) lying flat: the handle at -x, heated plates or a barrel at +x."""
    x, y, z = v.size
    color, plate = v.color(0, P.BLACK), v.color(1, P.rgb(120, 120, 125))
    handle_len = 0.45 * x
    handle = _loft([(handle_len, 0.85 * y, 0.0), (handle_len, y, 0.5 * z), (handle_len, 0.85 * y, z)], 4.0, 32)
    handle.apply_translation((-x / 2 + handle_len / 2, 0, 0))
    front_len = x - handle_len + 0.01
    fx = x / 2 - front_len / 2
    if p.curling:
        r = 0.4 * z
        barrel = shapes.cylinder(r, front_len, (fx, 0, r), axis="x", sections=16)
        clamp = shapes.box((0.8 * front_len, 0.3 * y, 0.2 * z), (fx, 0, z - 0.1 * z))
        parts = ((handle, color), (barrel, plate), (clamp, color))
    else:
        arms = shapes.slab(front_len, 0.9 * y, z, 0.3 * y, (fx, 0, z / 2))
        plates = shapes.box((0.8 * front_len, y, 0.12 * z), (fx + 0.05 * front_len, 0, z / 2))
        parts = ((handle, color), (arms, color), (plates, plate))
    return Geometry(parts, (col.hull_part(np.vstack([m.vertices for m, _ in parts])),))


@dataclass(frozen=True)
class ToothbrushHolderShape:
    """A square caddy with two dividers (three slots) instead of a round cup."""

    square: bool = False


@builder(ToothbrushHolderShape)
def toothbrush_holder(v: Variant, p: ToothbrushHolderShape) -> Geometry:
    """An open holder for toothbrushes (a container): a round ceramic cup, or a square caddy with three slots."""
    x, y, h = v.size
    color = v.color(0, P.WHITE)
    if not p.square:
        vessel = Vessel(resample([(0.46 * x, 0.0), (x / 2, h)], 4), 0.004, 0.008, stations=2)
        band = trimesh.creation.annulus(0.47 * x, 0.495 * x, 0.012, sections=40).apply_translation((0, 0, 0.35 * h))
        parts = ((vessel.mesh(), color), (band, v.color(1, color)))
        return Geometry(parts, tuple(vessel.collision(14)), vessel.cavity())
    wall, floor = 0.004, 0.008
    parts_list = [(_open_box_mesh(x, y, h, wall, floor, 0.008), color)]
    collision = list(col.open_box_parts(x, y, h, wall, floor))
    for dy in (-(y - 2 * wall) / 6, (y - 2 * wall) / 6):
        divider = (x - 2 * wall + 0.001, 0.003, 0.6 * (h - floor))
        centre = (0.0, dy, floor + 0.3 * (h - floor))
        parts_list.append((shapes.box(divider, centre), v.color(1, color)))
        collision.append(col.box_part(divider, centre))
    cavity = Cavity(rectangle(x - 2 * wall, y - 2 * wall), floor, h - floor)
    return Geometry(tuple(parts_list), tuple(collision), cavity)


@dataclass(frozen=True)
class SmallTubShape:
    """A lid in the second colour on a clear tub showing what is inside ("swabs" standing, or a "floss" spool box)."""

    contents: Literal["swabs", "floss"] = "swabs"


@builder(SmallTubShape)
def small_tub(v: Variant, p: SmallTubShape) -> Geometry:
    """A small closed toiletry container: a clear round tub of cotton swabs, or a rounded dental floss box."""
    x, y, h = v.size
    lid_color = v.color(1, P.WHITE)
    if p.contents == "floss":
        lid_h = 0.35 * h
        body = _loft([(0.96 * x, 0.96 * y, 0.0), (x, y, 0.1 * h), (x, y, h - lid_h)], 4.0, 32)
        lid = _loft([(x, y, h - lid_h - 0.0005), (x, y, h - 0.002), (0.94 * x, 0.92 * y, h)], 4.0, 32)
        cutter = shapes.box((0.004, 0.4 * y, 0.0012), (0.35 * x, 0, h - 0.0003))
        parts = ((body, v.color(0, P.rgb(120, 200, 210))), (lid, lid_color), (cutter, P.SILVER))
        return Geometry(parts, (col.hull_part(np.vstack([body.vertices, lid.vertices])),))
    r = x / 2
    lid_h = 0.2 * h
    body_h = h - lid_h
    tub = shapes.lathe([(0, 0), (0.97 * r, 0), (r, 0.05 * h), (r, body_h), (0, body_h)])
    swabs = shapes.cylinder(0.9 * r, body_h - 0.004, (0, 0, (body_h - 0.004) / 2 + 0.002), sections=32)
    lid = shapes.lathe([(0, body_h - 0.001), (1.0 * r, body_h - 0.001), (r, h - 0.003), (0.96 * r, h), (0, h)])
    parts = ((swabs, P.WHITE), (tub, v.color(0, P.rgb(220, 235, 245, 0.35))), (lid, lid_color))
    return Geometry(parts, (col.hull_part(np.vstack([tub.vertices, lid.vertices])),))


CATEGORIES: tuple[CategoryDef, ...] = builtin_categories(__name__, globals())  # variants: data/bathroom.json
