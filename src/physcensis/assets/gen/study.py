"""Office, desk and study objects: lamps, staplers, scissors, glue, tape, paper, notes, calculators, rulers, erasers,
remotes, binders, folders, envelopes, organisers, letter trays, clocks, frames, speakers, tablets and more."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
import trimesh
from shapely import affinity
from shapely.geometry import Point, Polygon
from shapely.ops import unary_union

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.gen.common import fit_to_size, rectangle
from physcensis.assets.gen.office import monitor  # noqa: F401 (a builder data/study.json names)
from physcensis.assets.gen.variant_data import builtin_categories
from physcensis.assets.model import RGBA, Cavity, CollisionPart
from physcensis.assets.spec import CategoryDef, Geometry, NoOptions, Variant, builder

SCREEN = P.rgb(20, 28, 45)


def _points(*meshes: trimesh.Trimesh) -> np.ndarray:
    return np.vstack([m.vertices for m in meshes])


def _solid_box(x: float, y: float, z: float) -> CollisionPart:
    """One box filling the whole size, base at z = 0."""
    return col.box_part((x, y, z), (0, 0, z / 2))


def _whole_hull(parts: list[tuple[trimesh.Trimesh, RGBA]]) -> Geometry:
    """A simple solid: the visual parts with one convex hull around them all."""
    return Geometry(tuple(parts), (col.hull_part(_points(*(m for m, _ in parts))),))


def _rod(start: tuple[float, float, float], end: tuple[float, float, float], radius: float) -> trimesh.Trimesh:
    """A straight round rod between two points."""
    return shapes.tube(np.array([start, end], dtype=float), radius, sides=12)


# --- desk lamp ---------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class DeskLampShape:
    """An angled arm reaching forward (else a straight stem under the shade), the shade's form, width (a share of
    the lamp's width) and height (a share of the lamp's; 0: the style's own), and the weighted base's thickness (m)."""

    arm: bool = True
    shade: Literal["cone", "dome", "drum"] = "cone"
    shade_width: float = 0.8
    shade_height: float = 0.0
    base_height: float = 0.022


def _shade_profile(style: str, radius: float, height: float, wall: float) -> np.ndarray:
    """(r, z) profile of a thin shade shell, closed at the top and open at the rim (z = 0)."""
    if style == "dome":
        t = np.linspace(0.0, np.pi / 2, 10)
        outer = np.stack([radius * np.sin(t), height * np.cos(t)], axis=1)
        inner = np.stack([(radius - wall) * np.sin(t), (height - wall) * np.cos(t)], axis=1)
        return np.vstack([outer, inner[::-1]])
    top = 0.45 * radius if style == "cone" else radius
    return np.array(
        [(0, height), (top, height), (radius, 0), (radius - wall, 0), (top - wall, height - wall), (0, height - wall)]
    )


def _shade_collision(profile: np.ndarray, centre: tuple[float, float, float], segments: int = 8) -> list[CollisionPart]:
    """Thin convex wall pieces of a shade shell, so the shade weighs what its thin wall weighs."""
    half = len(profile) // 2
    outer, inner = profile[:half], profile[half:][::-1]
    keep = np.unique(np.linspace(0, half - 1, min(half, 4)).round().astype(int))
    edges = np.linspace(0.0, 2 * np.pi, segments + 1)
    parts = []
    for j0, j1 in zip(keep[:-1], keep[1:], strict=True):
        for k in range(segments):
            ang = edges[k : k + 2]
            pts = [
                (centre[0] + r * np.cos(a), centre[1] + r * np.sin(a), centre[2] + h)
                for r, h in (outer[j0], outer[j1], inner[j0], inner[j1])
                for a in ang
            ]
            parts.append(col.hull_part(pts))
    return parts


@builder(DeskLampShape)
def desk_lamp(v: Variant, p: DeskLampShape) -> Geometry:
    """A desk lamp: a heavy round base, an arm or stem and a thin shade opening downwards; the light shines to +x."""
    x, y, z = v.size
    metal = v.color(0, P.BLACK)
    shade_color = v.color(1, metal)
    base_h = p.base_height
    if p.arm:
        base_r, shade_r = y / 2, p.shade_width * y / 2
        bx, sx = -x / 2 + base_r, x / 2 - shade_r
        shade_h = 0.32 * z
    else:
        base_r, shade_r = 0.36 * y, y / 2
        bx = sx = 0.0
        shade_h = 0.42 * z
    shade_h = p.shade_height * z or shade_h
    base = shapes.cylinder(base_r, base_h, (bx, 0, base_h / 2), sections=40)
    profile = _shade_profile(p.shade, shade_r, shade_h, 0.0025)
    shade = shapes.lathe(profile)
    shade.apply_translation((sx, 0, z - shade_h))
    rod_r = max(0.005, 0.012 * z)
    if p.arm:
        elbow = (bx - 0.3 * base_r, 0.0, 0.68 * z)
        rods = [_rod((bx, 0.0, base_h - 0.002), elbow, rod_r), _rod(elbow, (sx, 0.0, z - 0.25 * shade_h), rod_r)]
        rods.append(shapes.sphere(1.6 * rod_r, elbow, 2))
    else:
        rods = [shapes.cylinder(rod_r, z - shade_h - base_h + 0.004, (0, 0, (z - shade_h + base_h) / 2), sections=16)]
    switch = shapes.box((0.018, 0.012, 0.008), (bx + 0.55 * base_r, 0, base_h + 0.003))
    bulb = shapes.sphere(0.3 * shade_r, (sx, 0, z - 0.55 * shade_h), 2)
    parts = [(base, metal), (shade, shade_color), (switch, P.GREY), (bulb, P.rgb(250, 245, 215))]
    parts += [(rod, metal) for rod in rods]
    collision = [
        col.cylinder_part(base_r, base_h, (bx, 0, base_h / 2)),
        *_shade_collision(profile, (sx, 0, z - shade_h)),
    ]
    collision += [col.hull_part(rod) for rod in rods]
    return Geometry(tuple(parts), tuple(collision))


# --- stapler, hole punch, tape dispenser ---------------------------------------------------------------------------


@dataclass(frozen=True)
class StaplerShape:
    """The base plate's height as a share of the whole."""

    plate: float = 0.18


@builder(StaplerShape)
def stapler(v: Variant, p: StaplerShape) -> Geometry:
    """A desk stapler lying along x, its head at +x: base plate with anvil, hinge block at the back, top arm."""
    x, y, z = v.size
    body = v.color(0, P.BLACK)
    trim = v.color(1, P.SILVER)
    plate_h = p.plate * z
    plate = shapes.slab(x, 0.82 * y, plate_h, 0.3 * y, (0, 0, plate_h / 2))
    hinge = shapes.box((0.2 * x, 0.7 * y, 0.55 * z), (-0.38 * x, 0, 0.3 * z))
    arm_low = 0.42 * z
    back = shapes.rounded_box((0.3 * x, y, z - arm_low), 0.25 * y, (-0.33 * x, 0, (z + arm_low) / 2))
    front = shapes.rounded_box(
        (0.16 * x, 0.9 * y, 0.7 * (z - arm_low)), 0.2 * y, (0.41 * x, 0, arm_low + 0.35 * (z - arm_low))
    )
    arm = shapes.hull(_points(back, front))
    anvil = shapes.box((0.12 * x, 0.4 * y, 0.002), (0.38 * x, 0, plate_h))
    parts = [(plate, body), (hinge, trim), (arm, body), (anvil, trim)]
    return _whole_hull(parts)


@dataclass(frozen=True)
class HolePunchShape:
    """How many holes it punches (2 or 4 side by side)."""

    holes: int = 2


@builder(HolePunchShape)
def hole_punch(v: Variant, p: HolePunchShape) -> Geometry:
    """A desk hole punch: a flat base with a paper slot at the front (+x), the punch body and a lever on top."""
    x, y, z = v.size
    body = v.color(0, P.CHARCOAL)
    lever_c = v.color(1, P.SILVER)
    base = shapes.slab(x, y, 0.2 * z, 0.01, (0, 0, 0.1 * z))
    block = shapes.slab(0.45 * x, 0.92 * y, 0.55 * z, 0.01, (0.05 * x, 0, 0.2 * z + 0.275 * z - 0.001))
    lever = shapes.hull(
        _points(
            shapes.box((0.7 * x, 0.9 * y, 0.06 * z), (-0.05 * x, 0, 0.75 * z)),
            shapes.box((0.35 * x, 0.9 * y, 0.06 * z), (0.05 * x, 0, 0.97 * z)),
        )
    )
    pins = [
        shapes.cylinder(0.006, 0.5 * z, (0.05 * x, (k - (p.holes - 1) / 2) * 0.8 * y / p.holes, 0.45 * z), sections=12)
        for k in range(p.holes)
    ]
    parts = [(base, body), (block, body), (lever, lever_c), *((pin, P.STEEL) for pin in pins)]
    return _whole_hull(parts)


@builder(NoOptions)
def tape_dispenser(v: Variant, _: NoOptions) -> Geometry:
    """A weighted desk tape dispenser: two side cheeks around a tape roll, the cutting edge at the front (+x)."""
    x, y, z = v.size
    body = v.color(0, P.BLACK)
    roll_r = 0.42 * z
    roll_c = (-0.12 * x, z - roll_r)
    cheek_w = 0.2 * y
    angles = np.linspace(0, 2 * np.pi, 24, endpoint=False)
    ring = [(roll_c[0] + 1.04 * roll_r * np.cos(a), roll_c[1] + 1.04 * roll_r * np.sin(a)) for a in angles]
    profile = [*ring, (-x / 2, 0.0), (x / 2, 0.0), (x / 2, 0.3 * z), (-x / 2, 0.25 * z)]
    clipped = [(min(max(px, -x / 2), x / 2), min(max(pz, 0.0), z)) for px, pz in profile]
    cheeks = []
    for s in (1, -1):
        cy = s * (y / 2 - cheek_w / 2)
        cheeks.append(shapes.hull([(px, cy + dy, pz) for px, pz in clipped for dy in (-cheek_w / 2, cheek_w / 2)]))
    cradle = shapes.box((x, y - 2 * cheek_w + 0.002, 0.3 * z), (0, 0, 0.15 * z))
    roll = shapes.cylinder(roll_r, y - 2 * cheek_w, (roll_c[0], 0, roll_c[1]), axis="y", sections=32)
    hub = shapes.cylinder(0.55 * roll_r, y - 2 * cheek_w + 0.002, (roll_c[0], 0, roll_c[1]), axis="y", sections=24)
    blade = shapes.box((0.02, y - 2 * cheek_w, 0.012), (x / 2 - 0.012, 0, 0.3 * z))
    parts = [
        (cheeks[0], body),
        (cheeks[1], body),
        (cradle, body),
        (roll, v.color(1, P.rgb(225, 220, 200, 0.8))),
        (hub, v.color(2, P.GREY)),
        (blade, P.STEEL),
    ]
    return _whole_hull(parts)


# --- scissors, glue, rulers, erasers -------------------------------------------------------------------------------


@dataclass(frozen=True)
class ScissorsShape:
    """The blades' share of the length and the finger loops' share of the width each."""

    blade: float = 0.55
    loop: float = 0.56


def _finger_loops(x: float, y: float, p: ScissorsShape) -> Polygon:
    """The two handle loops side by side at the back (-x) with the shanks that join them to the pivot."""
    handle_len = (1 - p.blade) * x
    r = p.loop * y / 2
    stretch = min(1.4, 0.55 * handle_len / r)
    loops = []
    for s in (1, -1):
        cx, cy = -x / 2 + stretch * r, s * (y / 2 - r)
        outer = affinity.scale(Point(cx, cy).buffer(r, quad_segs=8), stretch, 1.0)
        inner = affinity.scale(Point(cx, cy).buffer(0.7 * r, quad_segs=8), stretch, 1.0)
        shank = Polygon(
            [
                (cx, cy - 0.2 * r),
                (cx, cy + 0.2 * r),
                (x / 2 - p.blade * x + 0.01, 0.04 * y),
                (x / 2 - p.blade * x + 0.01, -0.04 * y),
            ]
        )
        loops.append(unary_union([outer.difference(inner), shank.difference(inner)]))
    return unary_union(loops)


@builder(ScissorsShape)
def scissors(v: Variant, p: ScissorsShape) -> Geometry:
    """A pair of closed scissors lying flat: coloured finger loops at -x, steel blades pointing to +x."""
    x, y, z = v.size
    pivot = x / 2 - p.blade * x
    handles = _finger_loops(x, y, p)
    blade_w = 0.11 * y + 0.006
    blade = Polygon(
        [
            (pivot - 0.02, -blade_w / 2),
            (pivot + 0.01, -blade_w / 2),
            (x / 2, -0.001),
            (x / 2, 0.001),
            (pivot, blade_w / 2),
            (pivot - 0.02, blade_w / 2),
        ]
    )
    handle_mesh = shapes.extrude(handles, z)
    blade_mesh = shapes.extrude(blade, 0.45 * z)
    screw = shapes.cylinder(0.004, z, (pivot, 0, z / 2), sections=16)
    parts = [(handle_mesh, v.color(0, P.RED)), (blade_mesh, v.color(1, P.STEEL)), (screw, P.GREY)]
    return _whole_hull(parts)


@dataclass(frozen=True)
class GlueShape:
    """A twist-up glue stick, a squeeze bottle of white glue, or a small tube lying flat."""

    style: Literal["stick", "bottle", "tube"] = "stick"


def _glue_tube(v: Variant) -> Geometry:
    """A squeeze tube lying along x: round at the cap (-x), crimped flat at +x, flattened where it lies."""
    x, y, z = v.size
    cap_len = 0.15 * x
    ring = [
        (-x / 2 + cap_len, 0.55 * z * np.cos(a), z / 2 + 0.55 * z * np.sin(a)) for a in np.linspace(0, 2 * np.pi, 24)
    ]
    crimp = [
        (x / 2 - dx, sy * y / 2, z / 2 + dz) for dx in (0.0, 0.06 * x) for sy in (1, -1) for dz in (-0.0008, 0.0008)
    ]
    body = _flat_bottomed(np.array(ring + crimp), z)
    cap = shapes.cylinder(0.35 * z, cap_len + 0.002, (-x / 2 + cap_len / 2, 0, z / 2), axis="x", sections=16)
    label = _flat_bottomed(_points(body) * np.array([0.5, 1.01, 1.01]) + np.array([0.0, 0.0, -0.005 * z]), z)
    parts = [(body, v.color(0, P.WHITE)), (cap, v.color(1, P.RED)), (label, v.color(2, P.YELLOW))]
    return fit_to_size(_whole_hull(parts), v.size)


@builder(GlueShape)
def glue(v: Variant, p: GlueShape) -> Geometry:
    """A glue stick standing on its base (cap up), a glue bottle with a nozzle, or a tube lying flat."""
    if p.style == "tube":
        return _glue_tube(v)
    x, z = v.size[0], v.size[2]
    r = x / 2
    body_c = v.color(0, P.WHITE)
    cap_c = v.color(1, P.PURPLE)
    if p.style == "stick":
        body = shapes.cylinder(0.97 * r, 0.68 * z, (0, 0, 0.34 * z), sections=32)
        cap = shapes.cylinder(r, 0.34 * z, (0, 0, 0.83 * z), sections=32)
        knob = shapes.cylinder(0.9 * r, 0.06 * z, (0, 0, 0.03 * z), sections=32)
        label = shapes.cylinder(0.98 * r, 0.3 * z, (0, 0, 0.35 * z), sections=32)
        parts = [(body, body_c), (cap, cap_c), (knob, cap_c), (label, v.color(2, P.YELLOW))]
        return Geometry(tuple(parts), (col.cylinder_part(r, z, (0, 0, z / 2)),))
    body_h = 0.62 * z
    body = shapes.cylinder(r, body_h, (0, 0, body_h / 2), sections=32)
    shoulder = shapes.cone(r, 0.35 * r, 0.14 * z, (0, 0, body_h + 0.07 * z - 0.001), sections=32)
    nozzle = shapes.cone(0.35 * r, 0.08 * r, z - body_h - 0.14 * z + 0.002, (0, 0, (z + body_h + 0.14 * z) / 2 - 0.001))
    label = shapes.cylinder(1.0 * r, 0.35 * z, (0, 0, 0.3 * z), sections=32)
    parts = [(body, body_c), (shoulder, cap_c), (nozzle, cap_c), (label, v.color(2, P.YELLOW))]
    return Geometry(
        tuple(parts), (col.cylinder_part(r, body_h, (0, 0, body_h / 2)), col.hull_part(_points(shoulder, nozzle)))
    )


@dataclass(frozen=True)
class RulerShape:
    """A straight rule, a triangular set square or a half-round protractor."""

    style: Literal["straight", "triangle", "protractor"] = "straight"


def _ruler_outline(x: float, y: float, style: str) -> Polygon:
    if style == "triangle":
        outer = Polygon([(-x / 2, -y / 2), (x / 2, -y / 2), (-x / 2, y / 2)])
        hole = affinity.scale(outer, 0.45, 0.45, origin=outer.centroid)
        return outer.difference(hole)
    if style == "protractor":
        disc = affinity.scale(Point(0, 0).buffer(1.0, quad_segs=16), x, y / 2)
        half = disc.intersection(Polygon([(0, -y), (x, -y), (x, y), (0, y)]))
        inner = affinity.scale(Point(0, 0).buffer(1.0, quad_segs=16), 0.35 * x, 0.35 * y / 2)
        return affinity.translate(half.difference(inner), -x / 2, 0)
    return Polygon([(-x / 2, -y / 2), (x / 2, -y / 2), (x / 2, y / 2), (-x / 2, y / 2)])


def _ruler_ticks(x: float, y: float, z: float, tick_h: float, style: str) -> list[trimesh.Trimesh]:
    """Engraved marks: every centimetre along a rule's edge, a dozen along a set square's or a protractor's."""
    top = z - tick_h / 2 - 0.00005
    if style == "protractor":  # across the straight edge at -x
        return [
            shapes.box((0.12 * x, 0.0006, tick_h + 0.0001), (-x / 2 + 0.06 * x + 0.001, (k - 5) * 0.08 * y, top))
            for k in range(11)
        ]
    count = max(10, int(x / 0.01)) if style == "straight" else 12
    start, step = (-x / 2 + 0.5 * x / count, x / count) if style == "straight" else (-x / 2 + 0.08 * x, 0.06 * x)
    ticks = []
    for k in range(count):
        length = (0.3 if k % 5 == 0 else 0.15) * (y if style == "straight" else 0.4 * y)
        ticks.append(
            shapes.box((0.0006, length, tick_h + 0.0001), (start + k * step, -y / 2 + length / 2 + 0.0005, top))
        )
    return ticks


@builder(RulerShape)
def ruler(v: Variant, p: RulerShape) -> Geometry:
    """A flat measuring tool lying down with engraved ticks along one edge."""
    x, y, z = v.size
    tick_h = min(0.0003, 0.15 * z)
    plate = shapes.extrude(_ruler_outline(x, y, p.style), z - tick_h)
    ticks = _ruler_ticks(x, y, z, tick_h, p.style)
    parts = [(plate, v.color(0, P.LIGHT_WOOD)), (shapes.concatenate(ticks), v.color(1, P.BLACK))]
    return _whole_hull(parts)


@dataclass(frozen=True)
class EraserShape:
    """A rubber block (with or without a paper sleeve) or a whiteboard eraser with a felt pad and a handle."""

    style: Literal["block", "board"] = "block"
    sleeve: bool = False


@builder(EraserShape)
def eraser(v: Variant, p: EraserShape) -> Geometry:
    """An eraser lying on its widest face."""
    x, y, z = v.size
    color = v.color(0, P.PINK)
    if p.style == "board":
        felt = shapes.box((x, y, 0.3 * z), (0, 0, 0.15 * z))
        handle = shapes.rounded_box((x, 0.9 * y, 0.72 * z), 0.3 * z, (0, 0, 0.64 * z))
        parts = [(felt, v.color(1, P.GREY)), (handle, color)]
        return Geometry(tuple(parts), (_solid_box(x, y, z),))
    if p.sleeve:
        block = shapes.rounded_box((x, 0.96 * y, 0.94 * z), 0.15 * z, (0, 0, 0.47 * z))
        sleeve = shapes.box((0.55 * x, y, z), (-0.1 * x, 0, z / 2))
        parts = [(block, color), (sleeve, v.color(1, P.BLUE))]
    else:
        parts = [(shapes.rounded_box((x, y, z), 0.15 * z, (0, 0, z / 2)), color)]
    return Geometry(tuple(parts), (_solid_box(x, y, z),))


# --- paper, sticky notes, envelopes, folders ----------------------------------------------------------------------


@dataclass(frozen=True)
class PaperShape:
    """Printed rule lines on the top sheet, a paper wrapper band around a ream, or one sheet crumpled into a ball."""

    lined: bool = False
    wrapped: bool = False
    crumpled: bool = False


@builder(PaperShape)
def paper(v: Variant, p: PaperShape) -> Geometry:
    """A sheet or a stack of sheets lying flat; x is the sheet's long side (it reads from +x)."""
    x, y, z = v.size
    sheet = v.color(0, P.PAPER)
    line_h = min(0.0001, 0.1 * z)
    if p.crumpled:
        return _crumpled_ball(v, sheet)
    if p.wrapped:
        stack = shapes.box((x, y - 0.002, z - 0.002), (0, 0, z / 2))
        band = shapes.box((0.62 * x, y, z), (0, 0, z / 2))
        return Geometry(((stack, sheet), (band, v.color(1, P.rgb(200, 60, 50)))), (_solid_box(x, y, z),))
    stack = shapes.box((x, y, z - line_h), (0, 0, (z - line_h) / 2))
    count = int((x - 0.04) / 0.008) if p.lined else 3
    spacing = (x - 0.04) / count
    lines = [
        shapes.box(
            (0.0005, (0.86 if p.lined else 0.6) * y, line_h + 0.00002),
            (0.02 - x / 2 + (k + 0.5) * spacing, 0.02 * y, z - line_h / 2 - 0.00001),
        )
        for k in range(count)
    ]
    ink = v.color(1, P.rgb(120, 150, 210) if p.lined else P.rgb(150, 150, 150))
    return Geometry(((stack, sheet), (shapes.concatenate(lines), ink)), (_solid_box(x, y, z),))


def _crumpled_ball(v: Variant, color: RGBA) -> Geometry:
    """A sheet scrunched into a lumpy ball: a sphere with creased (randomly pushed in, fixed seed) facets, squashed a
    little where it rests so it does not roll."""
    x, y, z = v.size
    ball = trimesh.creation.icosphere(subdivisions=2, radius=0.5)
    dents = np.random.default_rng(len(v.name)).uniform(0.78, 1.0, len(ball.vertices))
    ball.vertices = ball.vertices * dents[:, None]
    ball.vertices[:, 2] = np.maximum(ball.vertices[:, 2], -0.36)  # the flattened underside it rests on
    lo, hi = ball.bounds
    ball.vertices = (ball.vertices - (lo + hi) / 2) / (hi - lo) * (x, y, z) + (0.0, 0.0, z / 2)
    return Geometry(((ball, color),), (col.hull_part(ball.vertices),))


@dataclass(frozen=True)
class StickyNotesShape:
    """How many colour bands the side of the pad shows (a cube of mixed colours); the top sheet is the first."""

    bands: int = 1


@builder(StickyNotesShape)
def sticky_notes(v: Variant, p: StickyNotesShape) -> Geometry:
    """A square pad of sticky notes lying flat; a band of colours on the side for a mixed cube."""
    x, y, z = v.size
    parts = []
    band_h = z / p.bands
    for k in range(p.bands):
        color = v.color(k % max(1, len(v.colors)), P.YELLOW)
        parts.append(
            (shapes.box((x, y, band_h + 0.0002), (0, 0, min(z - band_h / 2 - 0.0001, (k + 0.5) * band_h))), color)
        )
    glue = shapes.box((0.1 * x, 0.98 * y, 0.0003), (-0.42 * x, 0, z - 0.00015))
    parts.append((glue, v.color(0, P.YELLOW)))
    return Geometry(tuple(parts), (_solid_box(x, y, z),))


# --- calculators, remotes, tablets ---------------------------------------------------------------------------------


@dataclass(frozen=True)
class CalculatorShape:
    """Rows and columns of keys, and the display's share of the depth (at the back, -x)."""

    rows: int = 5
    cols: int = 4
    display: float = 0.28


def _key_grid(x0: float, x1: float, y: float, z0: float, height: float, rows: int, cols: int) -> trimesh.Trimesh:
    """A grid of square key caps between x0 and x1, across a width y, standing on z0."""
    pitch_x, pitch_y = (x1 - x0) / rows, y / cols
    keys = [
        shapes.box(
            (0.72 * pitch_x, 0.72 * pitch_y, height),
            (x0 + (r + 0.5) * pitch_x, -y / 2 + (c + 0.5) * pitch_y, z0 + height / 2),
        )
        for r in range(rows)
        for c in range(cols)
    ]
    return shapes.concatenate(keys)


@builder(CalculatorShape)
def calculator(v: Variant, p: CalculatorShape) -> Geometry:
    """A calculator lying face up: the display at the back (-x), keys towards the user (+x)."""
    x, y, z = v.size
    key_h = min(0.003, 0.3 * z)
    body_h = z - key_h
    body = shapes.slab(x, y, body_h, 0.1 * y, (0, 0, body_h / 2))
    disp_x = p.display * x
    display = shapes.box((0.7 * disp_x, 0.8 * y, 0.0008), (-x / 2 + 0.6 * disp_x, 0, body_h))
    keys = _key_grid(-x / 2 + disp_x + 0.004, x / 2 - 0.006, 0.86 * y, body_h - 0.0005, key_h + 0.0005, p.rows, p.cols)
    parts = ((body, v.color(0, P.CHARCOAL)), (display, v.color(2, P.rgb(150, 165, 140))), (keys, v.color(1, P.GREY)))
    return Geometry(parts, (_solid_box(x, y, z),))


@dataclass(frozen=True)
class RemoteShape:
    """Rows of buttons down the remote (besides the power button and the round pad)."""

    rows: int = 6


@builder(RemoteShape)
def remote_control(v: Variant, p: RemoteShape) -> Geometry:
    """A remote control lying face up along x, the end that points at the TV at -x: power button, pad, buttons."""
    x, y, z = v.size
    btn_h = min(0.002, 0.2 * z)
    body_h = z - btn_h
    body = shapes.slab(x, y, body_h, 0.35 * y, (0, 0, body_h / 2))
    power = shapes.cylinder(
        0.18 * y, btn_h + 0.0005, (-x / 2 + 0.06 * x, 0.22 * y, body_h + btn_h / 2 - 0.00025), sections=16
    )
    pad = shapes.cylinder(0.32 * y, btn_h + 0.0005, (-x / 2 + 0.3 * x, 0, body_h + btn_h / 2 - 0.00025), sections=24)
    grid = _key_grid(-x / 2 + 0.42 * x, x / 2 - 0.06 * x, 0.6 * y, body_h - 0.0005, btn_h + 0.0005, p.rows, 3)
    parts = (
        (body, v.color(0, P.BLACK)),
        (power, P.RED),
        (pad, v.color(1, P.GREY)),
        (grid, v.color(1, P.GREY)),
    )
    return Geometry(parts, (_solid_box(x, y, z),))


def _stand_up(meshes: list[trimesh.Trimesh]) -> None:
    """Turn a lying object (x = height, spine at +y) onto its bottom edge with the spine facing +x, like a book."""
    rot = trimesh.transformations.rotation_matrix(np.pi / 2, (0, 1, 0)) @ trimesh.transformations.rotation_matrix(
        np.pi / 2, (1, 0, 0)
    )
    for mesh in meshes:
        mesh.apply_transform(rot)


def _bounds(meshes: list[trimesh.Trimesh]) -> tuple[np.ndarray, np.ndarray]:
    """Extents and centre of the box around some meshes."""
    pts = _points(*meshes)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    return hi - lo, (lo + hi) / 2


@dataclass(frozen=True)
class BinderShape:
    """Standing on its bottom edge, spine out (else lying flat)."""

    upright: bool = False


@builder(BinderShape)
def ring_binder(v: Variant, p: BinderShape) -> Geometry:
    """A ring binder: two stiff covers, a wide spine with a label and a finger hole, a block of filed sheets.

    Lying (default): x = height, y = width (spine at +y), z = spine width; upright: x = width, y = spine width,
    z = height, spine facing +x.
    """
    if p.upright:
        w, t, h = v.size
    else:
        h, w, t = v.size
    board = 0.002
    cover = v.color(0, P.BLUE)
    covers = [shapes.box((h, w, board), (0, 0, board / 2)), shapes.box((h, w, board), (0, 0, t - board / 2))]
    spine = shapes.box((h, board, t), (0, w / 2 - board / 2, t / 2))
    sheets = shapes.box((0.94 * h, 0.85 * w, 0.6 * t), (0, -0.05 * w, board + 0.3 * t))
    label = shapes.box((0.35 * h, 0.001, 0.7 * t), (-0.15 * h, w / 2 + 0.0004, t / 2))
    hole = shapes.cylinder(0.3 * t, 0.001, (0.3 * h, w / 2 + 0.0004, t / 2), axis="y", sections=20)
    meshes = [*covers, spine, sheets, label, hole]
    if p.upright:
        _stand_up(meshes)
    ext, centre = _bounds(meshes)
    colors = [cover, cover, cover, v.color(1, P.PAPER), P.WHITE, P.CHARCOAL]
    return Geometry(tuple(zip(meshes, colors, strict=True)), (col.box_part(ext, centre),))


@dataclass(frozen=True)
class FolderShape:
    """A card folder with a tab, a plastic document wallet with a snap button, or a thick expanding file."""

    style: Literal["card", "wallet", "expanding"] = "card"


@builder(FolderShape)
def file_folder(v: Variant, p: FolderShape) -> Geometry:
    """A document folder lying flat, its opening towards +x and papers peeking out."""
    x, y, z = v.size
    color = v.color(0, P.rgb(225, 195, 130))
    papers = v.color(1, P.PAPER)
    if p.style == "card":
        tab = 0.012
        body_x = x - tab
        back = shapes.box((body_x, y, 0.0008), (tab / 2, 0, 0.0004))
        front = shapes.box((body_x - 0.015, y, 0.0008), (tab / 2 + 0.0075, 0, z - 0.0004))
        inside = shapes.box((body_x - 0.01, 0.96 * y, z - 0.0016), (tab / 2 + 0.004, 0, z / 2))
        tab_mesh = shapes.box((tab + 0.001, 0.35 * y, 0.0008), (-x / 2 + tab / 2, 0.25 * y, 0.0004))
        parts = [(back, color), (front, color), (inside, papers), (tab_mesh, color)]
    elif p.style == "wallet":
        shell = shapes.slab(x, y, z, 0.008, (0, 0, z / 2))
        flap = shapes.slab(0.25 * x, y, 0.0006, 0.008, (-0.375 * x, 0, z - 0.0003))
        snap = shapes.cylinder(0.006, 0.001, (-0.26 * x, 0, z - 0.0005), sections=16)
        parts = [(shell, color), (flap, v.color(2, color)), (snap, P.WHITE)]
    else:
        body = shapes.box((x, y, 0.85 * z), (0, 0, 0.425 * z))
        flap = shapes.box((0.3 * x, 0.98 * y, 0.15 * z + 0.001), (-0.35 * x, 0, 0.925 * z - 0.0005))
        band = shapes.box((0.02, y, z), (0.1 * x, 0, z / 2))
        pleats = [shapes.box((0.9 * x, 0.004, 0.8 * z), (0, s * (y / 2 - 0.002), 0.42 * z)) for s in (1, -1)]
        parts = [(body, color), (flap, color), (band, P.BLACK), *((pl, v.color(2, P.CHARCOAL)) for pl in pleats)]
    return Geometry(tuple(parts), (_solid_box(x, y, z),))


@dataclass(frozen=True)
class EnvelopeShape:
    """Red and blue airmail stripes along the edges, and a padded (bubble) lining."""

    airmail: bool = False
    padded: bool = False


@builder(EnvelopeShape)
def envelope(v: Variant, p: EnvelopeShape) -> Geometry:
    """A sealed envelope lying flat, back up: the body and the triangular flap on top."""
    x, y, z = v.size
    color = v.color(0, P.WHITE)
    flap_h = min(0.0004, 0.3 * z)
    body_z = z - flap_h
    body = shapes.slab(x, y, body_z, 0.004 if p.padded else 0.0, (0, 0, body_z / 2))
    tip = Polygon([(-x / 2 + 0.002, -y / 2 + 0.002), (-x / 2 + 0.002, y / 2 - 0.002), (0.15 * x, 0)])
    flap = shapes.extrude(tip, flap_h + 0.0001, body_z - 0.0001)
    parts = [(body, color), (flap, v.color(1, color))]
    if p.airmail:
        stripes = []
        for k in range(int(y / 0.012)):
            cy = -y / 2 + (k + 0.5) * 0.012
            for sx in (1, -1):
                stripes.append(
                    shapes.box(
                        (0.006, 0.006, flap_h + 0.0001), (sx * (x / 2 - 0.004), cy, body_z + flap_h / 2 - 0.00005)
                    )
                )
        parts.append((shapes.concatenate(stripes[0::4] + stripes[1::4]), P.RED))
        parts.append((shapes.concatenate(stripes[2::4] + stripes[3::4]), P.BLUE))
    return Geometry(tuple(parts), (_solid_box(x, y, z),))


# --- containers: desk organiser, letter tray -------------------------------------------------------------------


def _open_box(x: float, y: float, z: float, wall: float, floor: float, z0: float = 0.0) -> trimesh.Trimesh:
    outer = shapes.box((x, y, z), (0, 0, z0 + z / 2))
    inner = shapes.box((x - 2 * wall, y - 2 * wall, z), (0, 0, z0 + floor + z / 2))
    return trimesh.boolean.difference([outer, inner], engine="manifold")


@dataclass(frozen=True)
class OrganiserShape:
    """The cells behind the main compartment (side by side along y), the main compartment's share of the depth
    (at the front, +x), the dividers' height as a share of the walls', and the wall thickness (m)."""

    cells: int = 3
    main: float = 0.55
    divider: float = 0.85
    wall: float = 0.004


@builder(OrganiserShape)
def desk_organiser(v: Variant, p: OrganiserShape) -> Geometry:
    """An open desk or drawer organiser: a main compartment at the front (the cavity) and small cells behind it."""
    x, y, z = v.size
    wall, floor = p.wall, max(0.004, p.wall)
    color = v.color(0, P.BLACK)
    div_h = p.divider * (z - floor)
    split = x / 2 - wall - p.main * (x - 2 * wall)  # the divider between the main compartment and the cells
    dividers = [shapes.box((wall, y - 2 * wall, div_h), (split, 0, floor + div_h / 2))]
    back = split - (-x / 2 + wall)
    for k in range(1, p.cells):
        cy = -y / 2 + wall + k * (y - 2 * wall) / p.cells
        dividers.append(shapes.box((back, wall, div_h), (split - back / 2, cy, floor + div_h / 2)))
    parts = [(_open_box(x, y, z, wall, floor), color), *((d, v.color(1, color)) for d in dividers)]
    collision = col.open_box_parts(x, y, z, wall, floor)
    collision += [col.box_part(d.extents, d.bounds.mean(axis=0)) for d in dividers]
    main_x = x / 2 - wall - (split + wall / 2)
    cavity = Cavity(rectangle(main_x, y - 2 * wall, (split + wall / 2 + main_x / 2, 0.0)), floor, z - floor)
    return Geometry(tuple(parts), tuple(collision), cavity)


@dataclass(frozen=True)
class LetterTrayShape:
    """How many trays are stacked on posts, and the front wall's height as a share of the tray's."""

    tiers: int = 1
    front: float = 0.45


def _tray_tier(x: float, y: float, h: float, z0: float, front: float) -> tuple[trimesh.Trimesh, list[CollisionPart]]:
    """One letter tray standing on z0: floor, back and side walls, a low front wall to reach in from +x."""
    wall, floor = 0.004, 0.004
    body = _open_box(x, y, h, wall, floor, z0)
    notch = shapes.box((3 * wall, y - 2 * wall, h), (x / 2, 0, z0 + floor + front * h + h / 2))
    body = trimesh.boolean.difference([body, notch], engine="manifold")
    low = front * h + floor
    zc = z0 + floor + (h - floor) / 2
    parts = [
        col.box_part((x, y, floor), (0, 0, z0 + floor / 2)),
        col.box_part((wall, y, h - floor), (-x / 2 + wall / 2, 0, zc)),
        col.box_part((wall, y, low - floor), (x / 2 - wall / 2, 0, z0 + (floor + low) / 2)),
        col.box_part((x - 2 * wall, wall, h - floor), (0, y / 2 - wall / 2, zc)),
        col.box_part((x - 2 * wall, wall, h - floor), (0, -y / 2 + wall / 2, zc)),
    ]
    return body, parts


@builder(LetterTrayShape)
def letter_tray(v: Variant, p: LetterTrayShape) -> Geometry:
    """A desk letter tray (or a stack of them on four posts) for paper, open at the front (+x); the top tray holds."""
    x, y, z = v.size
    color = v.color(0, P.BLACK)
    tier_h = 0.06 if p.tiers > 1 else z
    gap = (z - p.tiers * tier_h) / max(1, p.tiers - 1)
    parts: list[tuple[trimesh.Trimesh, RGBA]] = []
    collision: list[CollisionPart] = []
    for k in range(p.tiers):
        z0 = k * (tier_h + gap)
        body, walls = _tray_tier(x, y, tier_h, z0, p.front)
        parts.append((body, color))
        collision += walls
        if k:
            for sx in (1, -1):
                for sy in (1, -1):
                    post = shapes.cylinder(
                        0.004, gap + 0.004, (sx * (x / 2 - 0.01), sy * (y / 2 - 0.01), z0 - gap / 2), sections=12
                    )
                    parts.append((post, v.color(1, P.SILVER)))
                    collision.append(col.hull_part(post))
    top = (p.tiers - 1) * (tier_h + gap)
    cavity = Cavity(rectangle(x - 0.008, y - 0.008), top + 0.004, tier_h - 0.004)
    return Geometry(tuple(parts), tuple(collision), cavity)


# --- clocks, frames, calendars -------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ClockShape:
    """A twin-bell wind-up clock on four feet, a round clock on a flat plinth, or a digital box clock."""

    style: Literal["bell", "round", "digital"] = "bell"


def _clock_face(r: float, depth: float, z: float, face: RGBA) -> list[tuple[trimesh.Trimesh, RGBA]]:
    """The dial on the front (+x) of a round body of radius r centred at height z, with two hands."""
    dial = shapes.cylinder(0.86 * r, 0.002, (depth / 2, 0, z), axis="x", sections=40)
    hour = shapes.box((0.002, 0.05 * r, 0.45 * r), (depth / 2 + 0.001, 0, z + 0.2 * r))
    minute = shapes.box((0.002, 0.65 * r, 0.04 * r), (depth / 2 + 0.0015, 0.3 * r, z))
    return [(dial, face), (hour, P.BLACK), (minute, P.BLACK)]


def _bell_clock(v: Variant, style: str) -> Geometry:
    depth, r = 0.5, 0.5  # drawn in proportion (units of the body's diameter), then fitted to the size
    body_c = v.color(0, P.RED)
    feet_h = 0.12 if style == "bell" else 0.1
    cz = feet_h + r
    body = shapes.cylinder(r, depth, (0, 0, cz), axis="x", sections=40)
    parts = [(body, body_c), *_clock_face(r, depth, cz, v.color(1, P.WHITE))]
    collision = [col.hull_part(body)]
    if style == "bell":
        feet = [
            shapes.cylinder(0.07, feet_h + 0.05, (sx * 0.15, sy * 0.3, (feet_h + 0.05) / 2), sections=12)
            for sx in (1, -1)
            for sy in (1, -1)
        ]
        bells = [shapes.sphere(0.26, (0, sy * 0.36, cz + 0.5), 2) for sy in (1, -1)]
        knob = shapes.cylinder(0.05, 0.2, (0, 0, cz + r + 0.08), sections=12)
        parts += [*((f, P.SILVER) for f in feet), *((b, v.color(2, P.SILVER)) for b in bells), (knob, P.SILVER)]
        collision += [col.hull_part(_points(*feet)), col.hull_part(_points(*bells, knob))]
    else:
        plinth = shapes.box((depth + 0.1, 1.1, feet_h + 0.05), (0, 0, (feet_h + 0.05) / 2))
        parts.append((plinth, v.color(2, P.WOOD)))
        collision.append(col.hull_part(plinth))
    return fit_to_size(Geometry(tuple(parts), tuple(collision)), v.size)


@builder(ClockShape)
def alarm_clock(v: Variant, p: ClockShape) -> Geometry:
    """A bedside or desk alarm clock; its face looks to +x."""
    if p.style != "digital":
        return _bell_clock(v, p.style)
    x, y, z = v.size
    body = shapes.rounded_box((x, y, z), 0.2 * min(x, z), (0, 0, z / 2))
    screen = shapes.box((0.002, 0.8 * y, 0.55 * z), (x / 2 - 0.0005, 0, 0.5 * z))
    digits = [shapes.box((0.002, 0.12 * y, 0.3 * z), (x / 2, (k - 1.5) * 0.18 * y, 0.5 * z)) for k in range(4)]
    parts = [
        (body, v.color(0, P.BLACK)),
        (screen, SCREEN),
        (shapes.concatenate(digits), v.color(1, P.rgb(90, 230, 120))),
    ]
    return Geometry(tuple(parts), (_solid_box(x, y, z),))


@dataclass(frozen=True)
class FrameShape:
    """How far the frame leans back (degrees), the border's width as a share of the frame's, a digital screen."""

    tilt: float = 14.0
    border: float = 0.12
    digital: bool = False


@builder(FrameShape)
def picture_frame(v: Variant, p: FrameShape) -> Geometry:
    """A picture frame standing on its bottom edge, leaning back on a strut; the picture faces +x."""
    x, y, z = v.size
    t = 0.1 * x if p.digital else 0.06 * x
    height = z
    border = p.border * min(y, height)
    frame = shapes.box((t, y, height), (-t / 2, 0, height / 2))
    if p.digital:
        picture = [(shapes.box((0.002, y - 2 * border, height - 2 * border), (0.0005, 0, height / 2)), SCREEN)]
    else:
        mat = shapes.box((0.002, y - 2 * border, height - 2 * border), (0.0003, 0, height / 2))
        photo = shapes.box((0.003, 0.6 * y - border, 0.6 * height - border), (0.0005, 0, height / 2))
        picture = [(mat, v.color(1, P.WHITE)), (photo, v.color(2, P.SKY))]
    meshes = [frame, *(m for m, _ in picture)]
    turn = trimesh.transformations.rotation_matrix(-np.radians(p.tilt), (0, 1, 0))
    for m in meshes:
        m.apply_transform(turn)
    lowest = min(m.bounds[0][2] for m in meshes)
    top = trimesh.transform_points([(-t, 0.0, 0.55 * height)], turn)[0]
    rod_r = 0.005
    strut = _rod((top[0], 0.0, top[2]), (top[0] - 0.35 * height, 0.0, lowest + rod_r), rod_r)
    parts = [(frame, v.color(0, P.BLACK)), *picture, (strut, v.color(0, P.BLACK))]
    collision = (col.hull_part(_points(*meshes)), col.hull_part(strut))
    return fit_to_size(Geometry(tuple(parts), collision), v.size)


@dataclass(frozen=True)
class TentShape:
    """A spiral binding along the top edge (a flip calendar; a name plate has none)."""

    binding: bool = True


@builder(TentShape)
def desk_calendar(v: Variant, p: TentShape) -> Geometry:
    """A tent-shaped standing card: two leaning faces, a spiral binding on top, a printed panel facing +x."""
    x, y, z = v.size
    ring_r = min(0.006, 0.1 * z) if p.binding else 0.0
    apex = z - ring_r
    tent = shapes.hull(
        [(sx * x / 2, sy * y / 2, 0.0) for sx in (1, -1) for sy in (1, -1)]
        + [(0.0, sy * y / 2, apex) for sy in (1, -1)]
    )
    normal = np.array([apex, 0.0, x / 2]) / np.hypot(apex, x / 2)
    page = []
    for s in (0.12, 0.8):
        base = np.array([x / 2 * (1 - s), 0.0, apex * s])
        for sy in (1, -1):
            for lift in (0.0, 0.0008):
                page.append(base + lift * normal + (0, sy * 0.42 * y, 0))
    grid = shapes.hull(page)
    parts = [(tent, v.color(0, P.WHITE)), (grid, v.color(1, P.RED))]
    if p.binding:
        parts.append((shapes.cylinder(ring_r, 0.9 * y, (0, 0, apex), axis="y", sections=16), P.SILVER))
    return _whole_hull(parts)


# --- electronics: speakers, tablets, headphones, webcams -------------------------------------------------------


@dataclass(frozen=True)
class SpeakerShape:
    """A bookshelf box with drivers on its front, a round smart speaker, or a pill-shaped portable speaker."""

    style: Literal["box", "round", "pill"] = "box"


@builder(SpeakerShape)
def speaker(v: Variant, p: SpeakerShape) -> Geometry:
    """A loudspeaker; the drivers or the grille face +x."""
    x, y, z = v.size
    body_c = v.color(0, P.BLACK)
    grille_c = v.color(1, P.CHARCOAL)
    if p.style == "round":
        r = x / 2
        body = shapes.cylinder(r, 0.97 * z, (0, 0, 0.485 * z), sections=40)
        top = shapes.cylinder(0.92 * r, 0.03 * z + 0.001, (0, 0, 0.985 * z - 0.0005), sections=40)
        ring = shapes.cylinder(0.5 * r, 0.03 * z + 0.0012, (0, 0, 0.985 * z - 0.0004), sections=40)
        parts = [(body, grille_c), (top, body_c), (ring, v.color(2, P.rgb(90, 160, 230)))]
        return Geometry(tuple(parts), (col.cylinder_part(r, z, (0, 0, z / 2)),))
    if p.style == "pill":
        body = shapes.rounded_box((x, y, z), 0.45 * min(x, z), (0, 0, z / 2))
        grille = shapes.rounded_box((x * 0.5, y * 0.8, z * 0.7), 0.3 * min(x, z), (0.25 * x, 0, z / 2))
        foot = shapes.box((0.5 * x, 0.6 * y, 0.003), (0, 0, 0.0015))
        parts = [(body, body_c), (grille, grille_c), (foot, P.BLACK)]
        return _whole_hull(parts)
    cabinet = shapes.box((x, y, z), (0, 0, z / 2))
    woofer_r = 0.36 * min(y, 0.6 * z)
    woofer = shapes.cylinder(woofer_r, 0.004, (x / 2, 0, 0.36 * z), axis="x", sections=32)
    cone = shapes.cone(0.8 * woofer_r, 0.2 * woofer_r, 0.003, (x / 2 + 0.0015, 0, 0.36 * z), axis="x", sections=32)
    tweeter = shapes.cylinder(0.35 * woofer_r, 0.004, (x / 2, 0, 0.78 * z), axis="x", sections=24)
    parts = [(cabinet, body_c), (woofer, grille_c), (cone, P.GREY), (tweeter, grille_c)]
    return Geometry(tuple(parts), (_solid_box(x - 0.004, y, z),))


@dataclass(frozen=True)
class TabletShape:
    """The bezel around the screen (m) and a folio case around the back and sides."""

    bezel: float = 0.01
    case: bool = False


@builder(TabletShape)
def tablet(v: Variant, p: TabletShape) -> Geometry:
    """A tablet computer lying screen up; its top edge (camera) at -x."""
    x, y, z = v.size
    body_c = v.color(0, P.CHARCOAL)
    if p.case:
        shell = shapes.slab(x, y, z, 0.012, (0, 0, z / 2))
        device = shapes.slab(x - 0.006, y - 0.006, 0.5 * z, 0.01, (0, 0, 0.75 * z))
        parts = [(shell, v.color(1, P.NAVY)), (device, body_c)]
    else:
        parts = [(shapes.slab(x, y, z, 0.012, (0, 0, z / 2)), body_c)]
    screen = shapes.slab(x - 2 * p.bezel, y - 2 * p.bezel, 0.0006, 0.008, (0, 0, z - 0.0002))
    camera = shapes.cylinder(0.002, 0.0006, (-x / 2 + p.bezel / 2 + 0.001, 0, z - 0.0001), sections=12)
    parts += [(screen, v.color(2, SCREEN)), (camera, P.BLACK)]
    return Geometry(tuple(parts), (_solid_box(x, y, z),))


@dataclass(frozen=True)
class HeadphonesShape:
    """The ear cups' radius as a share of the headband's, and a boom microphone (a headset)."""

    cup: float = 0.45
    mic: bool = False


@builder(HeadphonesShape)
def headphones(v: Variant, p: HeadphonesShape) -> Geometry:
    """Over-ear headphones lying flat: two ear cups side by side (at +-y), the headband arching towards +x."""
    band_r, cup_r = 1.0, p.cup  # in proportion, then fitted to the size
    cup_h = 0.5
    band_t = 0.12  # the band lies flat: thin up the z axis, wide across
    angles = np.linspace(-np.pi / 2, np.pi / 2, 25)
    path = np.stack([band_r * np.cos(angles), band_r * np.sin(angles), np.full_like(angles, band_t / 2)], axis=1)
    band = shapes.tube(path, band_t / 2, sides=16, squash=2.5)
    cups, pads = [], []
    for sy in (1, -1):
        cups.append(shapes.cylinder(cup_r, 0.7 * cup_h, (0, sy * band_r, 0.35 * cup_h), sections=32))
        pads.append(
            shapes.cylinder(0.85 * cup_r, 0.3 * cup_h + 0.01, (0, sy * band_r, 0.85 * cup_h - 0.005), sections=32)
        )
    body_c, pad_c = v.color(0, P.BLACK), v.color(1, P.CHARCOAL)
    parts = [(band, body_c), *((c, body_c) for c in cups), *((pad, pad_c) for pad in pads)]
    collision = [col.hull_part(_points(c, pad)) for c, pad in zip(cups, pads, strict=True)]
    collision += col.tube_parts(path, band_t / 2, 4)
    if p.mic:
        boom_path = np.array([(0.2, -band_r - 0.3, 0.15), (0.9, -band_r - 0.35, 0.15), (1.4, -band_r - 0.1, 0.15)])
        boom = shapes.tube(boom_path, 0.08, sides=10)
        parts.append((boom, P.BLACK))
        collision += col.tube_parts(boom_path, 0.08, 2)
    return fit_to_size(Geometry(tuple(parts), tuple(collision)), v.size)


@dataclass(frozen=True)
class WebcamShape:
    """A round ball camera (else a wide bar camera) on its small stand."""

    ball: bool = False


@builder(WebcamShape)
def webcam(v: Variant, p: WebcamShape) -> Geometry:
    """A webcam on a small desk stand, its lens looking to +x."""
    x, y, z = v.size
    body_c = v.color(0, P.BLACK)
    foot_h = 0.35 * z
    foot = shapes.slab(x, 0.6 * y if not p.ball else y, 0.12 * z, 0.005, (0, 0, 0.06 * z))
    neck = shapes.cylinder(0.12 * min(x, y), foot_h, (0, 0, foot_h / 2 + 0.05 * z), sections=16)
    head_h = z - foot_h
    if p.ball:
        r = min(x / 2, y / 2, head_h / 2)
        head = shapes.sphere(r, (0, 0, z - r), 3)
        lens_x = r
    else:
        head = shapes.rounded_box((0.8 * x, y, head_h), 0.4 * min(0.8 * x, head_h), (-0.1 * x, 0, z - head_h / 2))
        lens_x = 0.3 * x
    lens_r = 0.28 * min(y, head_h)
    lens = shapes.cylinder(lens_r, 0.004, (lens_x - 0.0015, 0, z - head_h / 2), axis="x", sections=24)
    parts = [(foot, body_c), (neck, P.GREY), (head, body_c), (lens, v.color(1, P.rgb(40, 60, 90)))]
    collision = (col.hull_part(foot), col.hull_part(neck), col.hull_part(_points(head, lens)))
    return Geometry(tuple(parts), collision)


# --- desk accessories: mouse pads, bookends, globes ----------------------------------------------------------


@dataclass(frozen=True)
class MousePadShape:
    """A round pad (else rectangular with rounded corners) and a raised wrist rest along the front (+x)."""

    round: bool = False
    wrist_rest: bool = False


@builder(MousePadShape)
def mouse_pad(v: Variant, p: MousePadShape) -> Geometry:
    """A flat mouse pad or desk mat lying on the desk."""
    x, y, z = v.size
    color = v.color(0, P.CHARCOAL)
    if p.round:
        pad = shapes.cylinder(x / 2, z, (0, 0, z / 2), sections=48)
        return Geometry(((pad, color),), (col.cylinder_part(x / 2, z, (0, 0, z / 2)),))
    if p.wrist_rest:
        pad = shapes.slab(x, y, 0.004, 0.015, (0, 0, 0.002))
        rest = shapes.rounded_box((0.3 * x, 0.7 * y, z), 0.45 * z, (x / 2 - 0.15 * x, 0, z / 2))
        parts = ((pad, color), (rest, v.color(1, color)))
        collision = (col.box_part((x, y, 0.004), (0, 0, 0.002)), col.hull_part(rest))
        return Geometry(parts, collision)
    pad = shapes.slab(x, y, z, min(0.02, 0.1 * min(x, y)), (0, 0, z / 2))
    return Geometry(((pad, color),), (_solid_box(x, y, z),))


@dataclass(frozen=True)
class BookendShape:
    """A bent metal L (a base plate that books stand on, an upright plate) or a solid decorative block."""

    style: Literal["metal", "block"] = "metal"


@builder(BookendShape)
def bookend(v: Variant, p: BookendShape) -> Geometry:
    """A bookend: what holds a row of books upright; the books lean on its +y face."""
    x, y, z = v.size
    color = v.color(0, P.BLACK)
    if p.style == "block":
        base = shapes.box((x, y, 0.3 * z), (0, 0, 0.15 * z))
        top = shapes.hull(
            _points(shapes.box((x, y, 0.01), (0, 0, 0.3 * z)), shapes.box((0.5 * x, 0.7 * y, 0.01), (0, 0, z - 0.005)))
        )
        return _whole_hull([(base, color), (top, v.color(1, color))])
    t = min(0.003, 0.1 * y)
    upright = shapes.box((x, t, z), (0, -y / 2 + t / 2, z / 2))
    plate = shapes.box((0.8 * x, y, t), (0, 0, t / 2))
    parts = ((upright, color), (plate, color))
    return Geometry(
        parts, (col.box_part((x, t, z), (0, -y / 2 + t / 2, z / 2)), col.box_part((0.8 * x, y, t), (0, 0, t / 2)))
    )


@builder(NoOptions)
def desk_globe(v: Variant, _: NoOptions) -> Geometry:
    """A desk globe: a round base, a stem and a half meridian ring, the globe tilted on its axis."""
    x, z = v.size[0], v.size[2]
    r = x / 2
    base_r = 0.6 * r
    base = shapes.cylinder(base_r, 0.05 * z, (0, 0, 0.025 * z), sections=40)
    stem_h = z - 2 * r - 0.04 * z
    stem = shapes.cylinder(0.06 * r, stem_h + 0.06 * z, (0, 0, 0.05 * z + stem_h / 2 - 0.01 * z), sections=16)
    centre = (0.0, 0.0, z - r)
    globe = shapes.sphere(0.97 * r, centre, 3)
    tilt = np.radians(23.5)
    arc_angles = np.linspace(-np.pi / 2 - 0.25, np.pi / 2 + 0.25, 25)
    ring = np.stack([0.985 * r * np.cos(arc_angles), np.zeros_like(arc_angles), 0.985 * r * np.sin(arc_angles)], axis=1)
    ring = ring @ trimesh.transformations.rotation_matrix(tilt, (1, 0, 0))[:3, :3].T + centre
    meridian = shapes.tube(ring, 0.015 * r, sides=10)
    parts = [
        (base, v.color(2, P.DARK_BROWN)),
        (stem, P.BRASS),
        (globe, v.color(0, P.SKY)),
        (meridian, v.color(1, P.BRASS)),
    ]
    collision = (
        col.cylinder_part(base_r, 0.05 * z, (0, 0, 0.025 * z)),
        col.hull_part(stem),
        col.sphere_part(0.95 * r, centre),
    )
    return Geometry(tuple(parts), collision)


# --- more desk tools: sharpeners, clips, magnifiers, bells, hourglasses ------------------------------------------


@dataclass(frozen=True)
class SharpenerShape:
    """A pocket sharpener, a crank desk sharpener, or an electric one."""

    style: Literal["pocket", "crank", "electric"] = "pocket"


@builder(SharpenerShape)
def pencil_sharpener(v: Variant, p: SharpenerShape) -> Geometry:
    """A pencil sharpener; the pencil hole faces +x."""
    x, y, z = v.size
    body_c = v.color(0, P.RED)
    hole_r = min(0.0045, 0.3 * min(y, z))
    if p.style == "pocket":
        body = shapes.rounded_box((x, y, z), 0.12 * min(y, z), (0, 0, z / 2))
        blade = shapes.box((0.6 * x, 0.5 * y, 0.0008), (0, 0, z - 0.0002))
        hole = shapes.cylinder(hole_r, 0.002, (x / 2 - 0.0008, 0, z / 2), axis="x", sections=16)
        parts = [(body, body_c), (blade, P.STEEL), (hole, P.BLACK)]
        return Geometry(tuple(parts), (_solid_box(x, y, z),))
    body_x = 0.8 * x if p.style == "crank" else x
    body = shapes.rounded_box((body_x, y, z), 0.15 * min(y, z), (x / 2 - body_x / 2, 0, z / 2))
    hole = shapes.cylinder(hole_r, 0.003, (x / 2 - 0.001, 0, 0.6 * z), axis="x", sections=16)
    parts = [(body, body_c), (hole, P.BLACK)]
    collision = [col.box_part((body_x, y, z), (x / 2 - body_x / 2, 0, z / 2))]
    if p.style == "crank":
        axle = shapes.cylinder(
            0.004, x - body_x + 0.004, (-x / 2 + (x - body_x) / 2, 0, 0.6 * z), axis="x", sections=12
        )
        arm = shapes.box((0.006, 0.012, 0.35 * z), (-x / 2 + 0.003, 0, 0.6 * z - 0.15 * z))
        knob = shapes.cylinder(0.007, 0.02, (-x / 2 + 0.012, 0, 0.3 * z), axis="x", sections=12)
        parts += [(axle, P.SILVER), (arm, P.SILVER), (knob, P.BLACK)]
        collision.append(col.hull_part(_points(axle, arm, knob)))
    else:
        vents = shapes.box((0.002, 0.6 * y, 0.08 * z), (-x / 2 + 0.0008, 0, 0.3 * z))
        parts.append((vents, P.CHARCOAL))
    return Geometry(tuple(parts), tuple(collision))


@dataclass(frozen=True)
class ClipShape:
    """A bent wire paper clip lying flat, or a binder clip resting on its back with its handles up."""

    binder: bool = False


def _wire_clip(v: Variant) -> Geometry:
    w = 1.0  # in proportion (the clip's width), then fitted to the size
    outer = [
        (-1.5, -0.5),
        (1.8, -0.5),
        (1.8, 0.5),
        (-1.8, 0.5),
        (-1.8, -0.3),
        (1.4, -0.3),
        (1.4, 0.3),
        (-1.2, 0.3),
        (-1.2, -0.1),
    ]
    pts = np.array([(px * w, py * w, 0.06) for px, py in outer])
    path = shapes.resample_polyline(pts, 60)
    wire = shapes.tube(path, 0.06, sides=8)
    geometry = Geometry(((wire, v.color(0, P.SILVER)),), (col.hull_part(wire),))
    return fit_to_size(geometry, v.size)


@builder(ClipShape)
def paper_clip(v: Variant, p: ClipShape) -> Geometry:
    """A paper clip or a binder clip (the jaws along y)."""
    if not p.binder:
        return _wire_clip(v)
    x, y, z = v.size
    body_h = 0.45 * z
    body = shapes.hull(
        [(sx * x / 2, sy * y / 2, 0.0) for sx in (1, -1) for sy in (1, -1)]
        + [(sx * 0.06 * x, sy * y / 2, body_h) for sx in (1, -1) for sy in (1, -1)]
    )
    handles = []
    for sx in (1, -1):
        top = (sx * 0.35 * x, 0.0, z - 0.02 * z)
        path = np.array(
            [
                (sx * 0.08 * x, -0.35 * y, body_h),
                (top[0], -0.35 * y, top[2]),
                (top[0], 0.35 * y, top[2]),
                (sx * 0.08 * x, 0.35 * y, body_h),
            ]
        )
        handles.append(shapes.tube(shapes.resample_polyline(path, 12), 0.02 * z, sides=8))
    parts = [(body, v.color(0, P.BLACK)), *((h, P.SILVER) for h in handles)]
    collision = (col.hull_part(body), col.hull_part(_points(*handles)))
    return fit_to_size(Geometry(tuple(parts), collision), v.size)


@builder(NoOptions)
def magnifying_glass(v: Variant, _: NoOptions) -> Geometry:
    """A magnifying glass lying flat: a round lens in a rim at +x, the handle towards -x."""
    x, y, z = v.size
    r = y / 2
    rim_t = min(z, 0.012)
    cx = x / 2 - r
    rim_poly = Point(cx, 0).buffer(r, quad_segs=16).difference(Point(cx, 0).buffer(0.86 * r, quad_segs=16))
    rim = shapes.extrude(rim_poly, rim_t)
    lens = shapes.cylinder(0.87 * r, 0.6 * rim_t, (cx, 0, 0.5 * rim_t), sections=40)
    handle_len = x - 2 * r + 0.01
    handle = shapes.cylinder(z / 2, handle_len, (-x / 2 + handle_len / 2, 0, z / 2), axis="x", sections=16)
    neck = shapes.box((0.02, 0.3 * z + 0.004, min(z, rim_t)), (cx - r - 0.005, 0, min(z, rim_t) / 2))
    parts = [(rim, v.color(1, P.BLACK)), (lens, P.GLASS), (handle, v.color(0, P.BROWN)), (neck, v.color(1, P.BLACK))]
    return _whole_hull(parts)


@builder(NoOptions)
def hourglass(v: Variant, _: NoOptions) -> Geometry:
    """An hourglass (sand timer): two glass bulbs between round end plates held by three posts."""
    x, z = v.size[0], v.size[2]
    r = x / 2
    plate_h = 0.07 * z
    plate_top = shapes.cylinder(r, plate_h, (0, 0, z - plate_h / 2), sections=40)
    plate_bottom = shapes.cylinder(r, plate_h, (0, 0, plate_h / 2), sections=40)
    inner_h = z - 2 * plate_h
    t = np.linspace(0, 1, 17)
    radius = 0.62 * r * (0.1 + 0.9 * np.abs(np.sin(2 * np.pi * t)) ** 0.7)  # two bulbs, a narrow waist
    radius[[0, -1]] = 0.3 * r
    profile = [(0.0, plate_h - 0.001)] + [
        (float(rr), plate_h + float(tt) * inner_h) for rr, tt in zip(radius, t, strict=True)
    ]
    profile[-1] = (0.3 * r, z - plate_h + 0.001)
    glass = shapes.lathe([*profile, (0.0, z - plate_h + 0.001)])
    sand = shapes.cone(0.42 * r, 0.05 * r, 0.22 * inner_h, (0, 0, plate_h + 0.15 * inner_h))
    posts = [
        shapes.cylinder(0.06 * r, inner_h + 0.002, (0.85 * r * np.cos(a), 0.85 * r * np.sin(a), z / 2), sections=12)
        for a in (0.0, 2 * np.pi / 3, 4 * np.pi / 3)
    ]
    wood = v.color(0, P.WOOD)
    parts = [
        (plate_top, wood),
        (plate_bottom, wood),
        (glass, P.GLASS),
        (sand, v.color(1, P.rgb(225, 195, 130))),
        *((q, wood) for q in posts),
    ]
    collision = (
        col.cylinder_part(r, plate_h, (0, 0, plate_h / 2)),
        col.cylinder_part(r, plate_h, (0, 0, z - plate_h / 2)),
        col.hull_part(_points(glass, *posts)),
    )
    return Geometry(tuple(parts), collision)


@builder(NoOptions)
def desk_bell(v: Variant, _: NoOptions) -> Geometry:
    """A service bell: a round base, a shiny dome and the plunger on top."""
    x, z = v.size[0], v.size[2]
    r = x / 2
    base_h = 0.22 * z
    base = shapes.cylinder(r, base_h, (0, 0, base_h / 2), sections=40)
    dome_r = 0.85 * r
    dome_h = 0.55 * z
    t = np.linspace(0, np.pi / 2, 10)
    arc = [(dome_r * np.cos(a), base_h + dome_h * np.sin(a)) for a in t[:-1]]
    dome = shapes.lathe([(0.0, base_h - 0.001), *arc, (0.0, base_h + dome_h)])
    plunger = shapes.cylinder(
        0.08 * r, z - base_h - dome_h + 0.002, (0, 0, (z + base_h + dome_h) / 2 - 0.001), sections=12
    )
    parts = [(base, v.color(1, P.BLACK)), (dome, v.color(0, P.SILVER)), (plunger, v.color(0, P.SILVER))]
    collision = (col.cylinder_part(r, base_h, (0, 0, base_h / 2)), col.hull_part(_points(dome, plunger)))
    return Geometry(tuple(parts), collision)


# --- larger office things: fans, printers, stands, magazine files, backpacks ------------------------------------


@builder(NoOptions)
def desk_fan(v: Variant, _: NoOptions) -> Geometry:
    """A small desk fan blowing towards +x: a round base, a stem, the motor and a caged rotor."""
    x, y, z = v.size
    cage_r = y / 2
    head_z = z - cage_r
    base_r = min(0.4 * y, 0.45 * x)
    base = shapes.cylinder(base_r, 0.05 * z, (0, 0, 0.025 * z), sections=40)
    stem = shapes.cylinder(0.05 * y, head_z - 0.04 * z, (0, 0, 0.04 * z + (head_z - 0.04 * z) / 2), sections=16)
    cage_depth = 0.45 * x
    cage_x = x / 2 - cage_depth / 2
    cage = shapes.cylinder(cage_r, cage_depth, (cage_x, 0, head_z), axis="x", sections=40)
    motor_len = x - cage_depth
    motor = shapes.cylinder(0.3 * cage_r, motor_len + 0.002, (-x / 2 + motor_len / 2, 0, head_z), axis="x", sections=24)
    hub = shapes.cylinder(0.15 * cage_r, cage_depth + 0.002, (cage_x, 0, head_z), axis="x", sections=24)
    blades = []
    for k in range(3):
        a = 2 * np.pi * k / 3
        blade = shapes.ellipsoid((0.01, 0.2 * cage_r, 0.45 * cage_r), (0, 0, 0), 2)
        blade.apply_transform(trimesh.transformations.rotation_matrix(a, (1, 0, 0)))
        blade.apply_translation((cage_x, 0.45 * cage_r * -np.sin(a), head_z + 0.45 * cage_r * np.cos(a)))
        blades.append(blade)
    body_c = v.color(0, P.WHITE)
    parts = [
        (base, body_c),
        (stem, body_c),
        (motor, body_c),
        (cage, v.color(2, P.rgb(200, 200, 205, 0.35))),
        (hub, v.color(1, P.GREY)),
        (shapes.concatenate(blades), v.color(1, P.GREY)),
    ]
    collision = (
        col.cylinder_part(base_r, 0.05 * z, (0, 0, 0.025 * z)),
        col.hull_part(stem),
        col.hull_part(_points(cage, motor)),
    )
    return Geometry(tuple(parts), collision)


@dataclass(frozen=True)
class PrinterShape:
    """A paper feed rising at the back (an inkjet) and a scanner lid on top (all-in-one)."""

    feed: bool = True
    scanner: bool = False


@builder(PrinterShape)
def printer(v: Variant, p: PrinterShape) -> Geometry:
    """A desktop printer: the body, the output tray at the front (+x), a paper feed at the back, a control panel."""
    x, y, z = v.size
    body_c = v.color(0, P.CHARCOAL)
    feed_h = 0.3 * z if p.feed else 0.0
    body_z = z - feed_h
    body_x = x - (0.08 * x if p.feed else 0.0)
    bx = x / 2 - body_x / 2
    body = shapes.rounded_box((body_x, y, body_z), 0.02, (bx, 0, body_z / 2))
    slot = shapes.box((0.004, 0.7 * y, 0.03 * z), (x / 2 - 0.0015, 0, 0.3 * body_z))
    tray = shapes.box((0.003, 0.6 * y, 0.12 * body_z), (x / 2 - 0.0012, 0, 0.15 * body_z))
    panel = shapes.box((0.1 * body_x, 0.3 * y, 0.004), (x / 2 - 0.08 * body_x, 0.25 * y, body_z - 0.0015))
    parts = [(body, body_c), (slot, P.BLACK), (tray, v.color(1, P.GREY)), (panel, P.rgb(40, 60, 80))]
    collision = [col.box_part((body_x, y, body_z), (bx, 0, body_z / 2))]
    if p.scanner:
        lid = shapes.box((0.96 * body_x, 0.96 * y, 0.004), (bx, 0, body_z - 0.0015))
        parts.append((lid, v.color(1, P.GREY)))
    if p.feed:
        feed = shapes.hull(
            [(-x / 2 + 0.08 * x + 0.02, sy * 0.35 * y, body_z - 0.02) for sy in (1, -1)]
            + [(-x / 2 + 0.08 * x + 0.026, sy * 0.35 * y, body_z - 0.02) for sy in (1, -1)]
            + [(-x / 2, sy * 0.35 * y, z) for sy in (1, -1)]
            + [(-x / 2 + 0.006, sy * 0.35 * y, z) for sy in (1, -1)]
        )
        sheet = shapes.hull(_points(feed) * np.array([1.0, 0.9, 1.0]) + np.array([0.004, 0.0, -0.002]))
        parts += [(feed, v.color(1, P.GREY)), (sheet, P.PAPER)]
        collision.append(col.hull_part(_points(feed, sheet)))
    return Geometry(tuple(parts), tuple(collision))


@dataclass(frozen=True)
class StandShape:
    """Side panels that splay out towards the desk (a laptop stand; else straight legs, a monitor riser) and the
    top board's thickness (m)."""

    splayed: bool = True
    board: float = 0.008


@builder(StandShape)
def laptop_stand(v: Variant, p: StandShape) -> Geometry:
    """A desk stand: a flat top board carried by two side panels, to raise a laptop or a screen."""
    x, y, z = v.size
    color = v.color(0, P.SILVER)
    t = p.board
    top = shapes.box((x, y, t), (0, 0, z - t / 2))
    leg_t = 0.012
    legs = []
    for sy in (1, -1):
        cy = sy * (y / 2 - 0.04 - leg_t / 2)
        foot = 0.5 * x if p.splayed else 0.45 * x
        head = 0.3 * x if p.splayed else 0.45 * x
        corners = [(sx * foot, 0.0) for sx in (1, -1)] + [(sx * head, z - t + 0.001) for sx in (1, -1)]
        legs.append(shapes.hull([(px, cy + dy, pz) for px, pz in corners for dy in (-leg_t / 2, leg_t / 2)]))
    parts = [(top, color), *((leg, v.color(1, color)) for leg in legs)]
    collision = [col.box_part((x, y, t), (0, 0, z - t / 2)), *(col.hull_part(leg) for leg in legs)]
    return Geometry(tuple(parts), tuple(collision))


@builder(NoOptions)
def magazine_file(v: Variant, _: NoOptions) -> Geometry:
    """A magazine file: a tall open box, its sides cut on a slant down to a low front (+x); it holds papers upright."""
    x, y, z = v.size
    wall, floor = 0.003, 0.004
    low = 0.4 * z
    color = v.color(0, P.WHITE)
    box = _open_box(x, y, z, wall, floor)
    slope = (z - low) / (0.7 * x)
    cut = shapes.hull(
        [
            (px, sy * y, pz)
            for sy in (1, -1)
            for px, pz in (
                (x / 2 + 0.01, low),
                (-0.2 * x, low + slope * 0.7 * x),
                (x / 2 + 0.01, z + 1.0),
                (-0.2 * x, z + 1.0),
            )
        ]
    )
    body = trimesh.boolean.difference([box, cut], engine="manifold")
    zc = floor + (z - floor) / 2
    collision = [
        col.box_part((x, y, floor), (0, 0, floor / 2)),
        col.box_part((wall, y, z - floor), (-x / 2 + wall / 2, 0, zc)),
        col.box_part((wall, y, low - floor), (x / 2 - wall / 2, 0, floor + (low - floor) / 2)),
    ]
    for sy in (1, -1):
        cy = sy * (y / 2 - wall / 2)
        side = [
            (px, cy + dy, pz)
            for dy in (-wall / 2, wall / 2)
            for px, pz in (
                (-x / 2 + wall, floor),
                (x / 2 - wall, floor),
                (x / 2 - wall, low),
                (-0.2 * x, z),
                (-x / 2 + wall, z),
            )
        ]
        collision.append(col.hull_part(side))
    label = shapes.box((0.001, 0.6 * y, 0.08 * z), (-x / 2 - 0.0003, 0, 0.75 * z))
    parts = ((body, color), (label, v.color(1, P.WHITE)))
    cavity = Cavity(rectangle(x - 2 * wall, y - 2 * wall), floor, z - floor)
    return Geometry(parts, tuple(collision), cavity)


@builder(NoOptions)
def backpack(v: Variant, _: NoOptions) -> Geometry:
    """A school backpack standing upright: a padded body, a front pocket (+x), a carry loop and straps at the back."""
    x, y, z = v.size
    body_c = v.color(0, P.NAVY)
    body_x = 0.7 * x
    body = shapes.rounded_box((body_x, y, 0.92 * z), 0.3 * body_x, (-x / 2 + body_x / 2 + 0.08 * x, 0, 0.46 * z))
    pocket = shapes.rounded_box((0.4 * x, 0.75 * y, 0.45 * z), 0.15 * x, (x / 2 - 0.2 * x, 0, 0.24 * z))
    loop_path = np.array(
        [
            (-0.1 * x, -0.12 * y, 0.9 * z),
            (-0.1 * x, -0.08 * y, z - 0.01),
            (-0.1 * x, 0.08 * y, z - 0.01),
            (-0.1 * x, 0.12 * y, 0.9 * z),
        ]
    )
    loop = shapes.tube(shapes.resample_polyline(loop_path, 10), 0.01, sides=8)
    straps = []
    for sy in (1, -1):
        path = np.array(
            [
                (-x / 2 + 0.08 * x + 0.01, sy * 0.25 * y, 0.85 * z),
                (-x / 2 + 0.02, sy * 0.28 * y, 0.5 * z),
                (-x / 2 + 0.05 * x + 0.01, sy * 0.3 * y, 0.1 * z),
            ]
        )
        straps.append(shapes.tube(shapes.resample_polyline(path, 12), 0.015, sides=8, squash=0.4))
    parts = [(body, body_c), (pocket, v.color(1, body_c)), (loop, P.BLACK), *((s, P.BLACK) for s in straps)]
    collision = (col.hull_part(_points(body, pocket)), col.hull_part(_points(*straps, loop)))
    return Geometry(tuple(parts), collision)


# --- small gadgets: game controllers, power banks, flash drives, phone stands, stamps ----------------------------


def _flat_bottomed(points: np.ndarray, height: float) -> trimesh.Trimesh:
    """The hull of some points squeezed into 0 <= z <= height, so it rests on a flat bottom."""
    pts = np.array(points, dtype=float)
    pts[:, 2] = np.clip(pts[:, 2], 0.0, height)
    return shapes.hull(pts)


@builder(NoOptions)
def game_controller(v: Variant, _: NoOptions) -> Geometry:
    """A gamepad lying face up: a body with two grips towards the player (+x), sticks, a d-pad and four buttons."""
    x, y, z = v.size
    shell_h = 0.7 * z
    centre = shapes.ellipsoid((0.32 * x, 0.3 * y, 0.6 * shell_h), (-0.15 * x, 0, 0.45 * shell_h), 2)
    grips = [
        shapes.ellipsoid((0.28 * x, 0.2 * y, 0.55 * shell_h), (0.2 * x, sy * 0.3 * y, 0.45 * shell_h), 2)
        for sy in (1, -1)
    ]
    body = _flat_bottomed(_points(centre, *grips), shell_h)
    top = shell_h - 0.001
    stick_h = z - top
    sticks = [
        shapes.cylinder(0.07 * y, stick_h, (0.05 * x, sy * 0.14 * y, top + stick_h / 2), sections=16) for sy in (1, -1)
    ]
    dpad = shapes.concatenate(
        [
            shapes.box((0.16 * x, 0.05 * y, 0.004), (-0.2 * x, 0.3 * y, top + 0.001)),
            shapes.box((0.05 * x, 0.09 * y, 0.004), (-0.2 * x, 0.3 * y, top + 0.001)),
        ]
    )
    buttons = [
        (shapes.cylinder(0.025 * y, 0.004, (-0.2 * x + dx, -0.3 * y + dy, top + 0.001), sections=12), color)
        for (dx, dy), color in zip(
            ((0.06 * x, 0.0), (-0.06 * x, 0.0), (0.0, 0.05 * y), (0.0, -0.05 * y)),
            (P.GREEN, P.YELLOW, P.RED, P.BLUE),
            strict=True,
        )
    ]
    body_c = v.color(0, P.CHARCOAL)
    parts = [(body, body_c), *((st, v.color(1, P.BLACK)) for st in sticks), (dpad, P.BLACK), *buttons]
    return fit_to_size(_whole_hull(parts), v.size)


@dataclass(frozen=True)
class PowerBankShape:
    """A slim battery pack lying flat (else a cube-shaped wall charger with its prongs folded)."""

    cube: bool = False


@builder(PowerBankShape)
def power_bank(v: Variant, p: PowerBankShape) -> Geometry:
    """A portable battery or a charger: a rounded block with a USB port on its front (+x) and status lights."""
    x, y, z = v.size
    body = shapes.rounded_box((x, y, z), 0.25 * min(y, z) if p.cube else 0.4 * z, (0, 0, z / 2))
    port = shapes.box((0.002, 0.12 * y + 0.006, 0.25 * z), (x / 2 - 0.0008, 0, 0.5 * z))
    lights = [
        shapes.cylinder(0.001, 0.0006, (0.2 * x + (k - 1.5) * min(0.006, 0.12 * x), -0.3 * y, z - 0.0002), sections=8)
        for k in range(4)
    ]
    parts = [
        (body, v.color(0, P.BLACK)),
        (port, P.CHARCOAL),
        (shapes.concatenate(lights), v.color(1, P.rgb(80, 200, 255))),
    ]
    return Geometry(tuple(parts), (_solid_box(x, y, z),))


@builder(NoOptions)
def usb_drive(v: Variant, _: NoOptions) -> Geometry:
    """A USB flash drive lying flat, the metal plug towards +x and a key-ring loop at -x."""
    x, y, z = v.size
    plug_x = min(0.3 * x, 0.013)
    body = shapes.slab(x - plug_x, y, z, 0.3 * min(y, z) + 0.001, (-plug_x / 2, 0, z / 2))
    plug = shapes.box((plug_x + 0.001, min(0.75 * y, 0.012), 0.5 * z), (x / 2 - plug_x / 2, 0, 0.5 * z))
    hole = shapes.cylinder(0.12 * y, 0.0006, (-x / 2 + 0.15 * y + 0.002, 0, z - 0.0002), sections=12)
    parts = [(body, v.color(0, P.BLACK)), (plug, P.SILVER), (hole, P.CHARCOAL)]
    return _whole_hull(parts)


@builder(NoOptions)
def phone_stand(v: Variant, _: NoOptions) -> Geometry:
    """A desk phone stand: a base plate, a back rest leaning back and a lip at the front (+x) that holds the phone."""
    x, y, z = v.size
    color = v.color(0, P.SILVER)
    t = max(0.004, 0.05 * x)
    base = shapes.box((x, y, t), (0, 0, t / 2))
    lip = shapes.box((t, y, 0.15 * z), (0.3 * x, 0, 0.075 * z))
    rest = shapes.hull(
        [
            (px, sy * y / 2, pz)
            for sy in (1, -1)
            for px, pz in ((0.2 * x, t), (0.2 * x - t, t), (-x / 2 + t, z), (-x / 2, z))
        ]
    )
    strut = shapes.hull(
        [
            (px, sy * 0.4 * y, pz)
            for sy in (1, -1)
            for px, pz in ((-x / 2, t), (-x / 2 + t, t), (-x / 2 + t, z - 0.01), (-x / 2, z - 0.01))
        ]
    )
    parts = [(base, color), (lip, color), (rest, v.color(1, color)), (strut, color)]
    collision = (col.box_part((x, y, t), (0, 0, t / 2)), col.hull_part(lip), col.hull_part(_points(rest, strut)))
    return Geometry(tuple(parts), collision)


@builder(NoOptions)
def rubber_stamp(v: Variant, _: NoOptions) -> Geometry:
    """A rubber stamp standing on its rubber face: a block mount and a turned wooden knob."""
    x, y, z = v.size
    rubber_h = 0.08 * z
    block_h = 0.3 * z
    rubber = shapes.box((0.96 * x, 0.96 * y, rubber_h), (0, 0, rubber_h / 2))
    block = shapes.box((x, y, block_h), (0, 0, rubber_h + block_h / 2 - 0.0005))
    knob_r = 0.45 * min(x, y)
    h0 = rubber_h + block_h - 0.001
    knob_h = z - h0
    knob = shapes.lathe(
        [
            (0.0, h0),
            (0.5 * knob_r, h0),
            (0.3 * knob_r, h0 + 0.5 * knob_h),
            (knob_r, h0 + 0.8 * knob_h),
            (0.8 * knob_r, z),
            (0.0, z),
        ]
    )
    wood = v.color(0, P.WOOD)
    parts = [(rubber, v.color(1, P.RED)), (block, wood), (knob, v.color(2, wood))]
    collision = (col.box_part((x, y, rubber_h + block_h), (0, 0, (rubber_h + block_h) / 2)), col.hull_part(knob))
    return Geometry(tuple(parts), collision)


# --- cables, earbuds, drawer units --------------------------------------------------------------------------------


@dataclass(frozen=True)
class CableShape:
    """How many turns the coiled cable makes, and a charger brick on its end (else a small plug)."""

    turns: float = 3.0
    brick: bool = False


@builder(CableShape)
def cable(v: Variant, p: CableShape) -> Geometry:
    """A cable coiled loosely flat on the desk, a plug at its end towards +x."""
    x, y, z = v.size
    wire_r = 0.0022
    angle = np.linspace(0.0, 2 * np.pi * p.turns, int(40 * p.turns))
    radius = 0.5 - 0.12 * angle / angle[-1]  # in proportion, then fitted to the size
    path = np.stack([radius * np.cos(angle), radius * np.sin(angle), np.full_like(angle, wire_r)], axis=1)
    path[:, :2] *= (x - 0.03, y)
    path[:, 2] += 0.5 * wire_r * np.sin(angle * 1.5)  # the loops cross each other a little
    path[:, 2] = np.maximum(path[:, 2], wire_r)
    wire = shapes.tube(path, wire_r, sides=8)
    end = path[0]
    plug_size = (0.04, 0.03, z) if p.brick else (0.025, 0.012, min(z, 0.008))
    plug = shapes.box(plug_size, (end[0] + plug_size[0] / 2 - 0.004, end[1], plug_size[2] / 2))
    parts = [(wire, v.color(0, P.WHITE)), (plug, v.color(1, v.color(0, P.WHITE)))]
    geometry = Geometry(tuple(parts), (col.hull_part(_points(wire, plug)),))
    return fit_to_size(geometry, v.size)


@dataclass(frozen=True)
class EarbudsShape:
    """The charging case stands on its end (else lies flat on its back)."""

    upright: bool = True


@builder(EarbudsShape)
def earbuds(v: Variant, p: EarbudsShape) -> Geometry:
    """A wireless earbuds charging case: a rounded pebble with a lid seam and a status light on the front (+x)."""
    x, y, z = v.size
    radius = 0.3 * min(x, y, z)
    body = shapes.rounded_box((x, y, z), radius, (0, 0, z / 2))
    seam_z = 0.7 * z if p.upright else 0.55 * z
    seam = shapes.extrude(shapes.rounded_rect(x + 0.0004, y + 0.0004, radius), 0.0008, seam_z - 0.0004)
    light = shapes.cylinder(0.0012, 0.001, (x / 2 - 0.0003, 0, 0.45 * z), axis="x", sections=8)
    parts = [(body, v.color(0, P.WHITE)), (seam, v.color(1, P.GREY)), (light, P.GREEN)]
    return _whole_hull(parts)


@dataclass(frozen=True)
class DrawerUnitShape:
    """How many drawers are stacked on the front (+x), and their handles."""

    drawers: int = 3
    handle: Literal["bar", "knob", "slot"] = "bar"


@builder(DrawerUnitShape)
def drawer_unit(v: Variant, p: DrawerUnitShape) -> Geometry:
    """A closed chest of drawers: a carcass with drawer fronts and handles on its front (+x); things go on top."""
    x, y, z = v.size
    handle_d = 0.0 if p.handle == "slot" else min(0.025, 0.08 * x)
    body_x = x - handle_d
    bx = -handle_d / 2
    carcass = shapes.box((body_x, y, z), (bx, 0, z / 2))
    gap = min(0.004, 0.02 * z)
    front_h = (z - gap * (p.drawers + 1)) / p.drawers
    fronts, handles = [], []
    for k in range(p.drawers):
        cz = gap + front_h / 2 + k * (front_h + gap)
        fronts.append(shapes.box((0.003, y - 2 * gap, front_h), (bx + body_x / 2, 0, cz)))
        if p.handle == "bar":
            handles.append(shapes.box((handle_d, 0.35 * y, min(0.012, 0.2 * front_h)), (x / 2 - handle_d / 2, 0, cz)))
        elif p.handle == "knob":
            handles.append(
                shapes.cylinder(
                    min(0.01, 0.15 * front_h), handle_d, (x / 2 - handle_d / 2, 0, cz), axis="x", sections=16
                )
            )
        else:
            handles.append(
                shapes.box(
                    (0.004, 0.3 * y, min(0.012, 0.2 * front_h)), (bx + body_x / 2 + 0.0005, 0, cz + 0.3 * front_h)
                )
            )
    body_c = v.color(0, P.GREY)
    parts = [
        (carcass, body_c),
        (shapes.concatenate(fronts), v.color(1, body_c)),
        (shapes.concatenate(handles), v.color(2, P.SILVER)),
    ]
    return Geometry(tuple(parts), (col.box_part((body_x, y, z), (bx, 0, z / 2)),))


# --- study room: trophies, microscopes, abacuses ------------------------------------------------------------------


@dataclass(frozen=True)
class TrophyShape:
    """A loving cup with two handles, or a column topped with a star."""

    style: Literal["cup", "star"] = "cup"


@builder(TrophyShape)
def trophy(v: Variant, p: TrophyShape) -> Geometry:
    """A trophy on a square plinth with a name plate on its front (+x)."""
    x, y, z = v.size
    metal = v.color(0, P.GOLD)
    plinth_h = 0.22 * z
    w = min(x, y)
    plinth = shapes.box((x, w if p.style == "star" else min(y, 0.75 * w + 0.35 * x), plinth_h), (0, 0, plinth_h / 2))
    plate = shapes.box((0.002, 0.5 * w, 0.4 * plinth_h), (x / 2, 0, plinth_h / 2))
    parts = [(plinth, v.color(1, P.BLACK)), (plate, metal)]
    collision = [col.box_part(plinth.extents, (0, 0, plinth_h / 2))]
    top_z = z - plinth_h
    if p.style == "cup":
        r = 0.42 * x
        profile = [
            (0.0, 0.0),
            (0.35 * r, 0.0),
            (0.12 * r, 0.12 * top_z),
            (0.1 * r, 0.35 * top_z),
            (0.6 * r, 0.45 * top_z),
            (r, 0.75 * top_z),
            (r, top_z),
            (0.0, top_z),
        ]
        cup = shapes.lathe(profile)
        cup.apply_translation((0, 0, plinth_h - 0.001))
        handles = []
        for sy in (1, -1):
            t = np.linspace(-np.pi / 2, np.pi / 2, 9)
            path = np.stack(
                [
                    np.zeros_like(t),
                    sy * (0.8 * r + (y / 2 - 0.8 * r - 0.006) * np.cos(t)),
                    plinth_h + top_z * (0.75 + 0.18 * np.sin(t)),
                ],
                axis=1,
            )
            handles.append(shapes.tube(path, 0.005, sides=8))
        parts += [(cup, metal), *((h, metal) for h in handles)]
        collision.append(col.hull_part(_points(cup, *handles)))
    else:
        column = shapes.box((0.4 * x, 0.4 * w, 0.6 * top_z), (0, 0, plinth_h + 0.3 * top_z - 0.001))
        star_r = 0.5 * min(w, 0.4 * top_z / 0.5)
        angles = np.linspace(0, 2 * np.pi, 11)[:-1] + np.pi / 2
        ring = [
            (star_r * (1.0 if k % 2 == 0 else 0.45) * np.cos(a), star_r * (1.0 if k % 2 == 0 else 0.45) * np.sin(a))
            for k, a in enumerate(angles)
        ]
        star = shapes.extrude(Polygon(ring), min(0.02, 0.4 * x))
        star.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, (0, 1, 0)))
        star.apply_translation((min(0.01, 0.2 * x), 0, z - star_r * 1.0))
        parts += [(column, v.color(2, metal)), (star, metal)]
        collision.append(col.hull_part(_points(column, star)))
    return Geometry(tuple(parts), tuple(collision))


@builder(NoOptions)
def microscope(v: Variant, _: NoOptions) -> Geometry:
    """A student microscope: a heavy base, a curved arm at the back (-x), a stage, a turret and an eyepiece tube."""
    x, y, z = v.size
    body_c = v.color(0, P.WHITE)
    dark = v.color(1, P.BLACK)
    base_h = 0.1 * z
    base = shapes.slab(x, y, base_h, 0.2 * y, (0, 0, base_h / 2))
    arm = shapes.hull(
        _points(
            shapes.box((0.25 * x, 0.4 * y, 0.6 * z), (-0.3 * x, 0, base_h + 0.3 * z - 0.002)),
            shapes.box((0.3 * x, 0.35 * y, 0.15 * z), (-0.15 * x, 0, 0.75 * z)),
        )
    )
    stage = shapes.box((0.5 * x, 0.8 * y, 0.03 * z), (0.12 * x, 0, 0.4 * z))
    turret = shapes.cylinder(0.18 * y, 0.08 * z, (0.12 * x, 0, 0.58 * z), sections=24)
    lenses = shapes.cylinder(0.06 * y, 0.1 * z, (0.12 * x, 0, 0.5 * z), sections=16)
    tube_path = np.array([(0.12 * x, 0.0, 0.62 * z), (0.05 * x, 0.0, 0.85 * z), (-0.05 * x, 0.0, z - 0.06 * y)])
    tube = shapes.tube(tube_path, 0.06 * y, sides=16)
    head = shapes.box((0.3 * x, 0.3 * y, 0.12 * z), (0.02 * x, 0, 0.72 * z))
    knob = shapes.cylinder(0.12 * z, 0.9 * y, (-0.3 * x, 0, 0.35 * z), axis="y", sections=24)
    parts = [
        (base, body_c),
        (arm, body_c),
        (stage, dark),
        (turret, P.SILVER),
        (lenses, P.SILVER),
        (tube, dark),
        (head, body_c),
        (knob, dark),
    ]
    collision = (
        col.hull_part(base),
        col.hull_part(_points(arm, knob)),
        col.hull_part(_points(stage, turret, lenses, head, tube)),
    )
    return fit_to_size(Geometry(tuple(parts), collision), v.size)


@dataclass(frozen=True)
class AbacusShape:
    """How many rods of beads across the frame, and beads per rod."""

    rods: int = 8
    beads: int = 10


@builder(AbacusShape)
def abacus(v: Variant, p: AbacusShape) -> Geometry:
    """A counting frame standing on two feet: posts at +-y, rods along y carrying coloured beads, facing +x."""
    x, y, z = v.size
    wood = v.color(0, P.WOOD)
    post_w = 0.06 * y
    feet = [shapes.box((x, post_w, 0.06 * z), (0, sy * (y / 2 - post_w / 2), 0.03 * z)) for sy in (1, -1)]
    posts = [
        shapes.box(
            (0.5 * x, post_w, z - 0.06 * z), (0, sy * (y / 2 - post_w / 2), 0.06 * z + (z - 0.06 * z) / 2 - 0.001)
        )
        for sy in (1, -1)
    ]
    span = y - 2 * post_w + 0.004
    top_bar = shapes.box((0.4 * x, span, 0.04 * z), (0, 0, z - 0.02 * z))
    rods, beads = [], []
    bead_r = min(0.45 * (z - 0.12 * z) / (p.rods + 1), 0.5 * span / (p.beads + 4), 0.35 * x)
    colors = [P.RED, P.YELLOW, P.GREEN, P.BLUE, P.ORANGE, P.PURPLE, P.PINK, P.SKY, P.LIME, P.TEAL]
    for k in range(p.rods):
        rz = 0.1 * z + (k + 0.5) * (z - 0.14 * z) / p.rods
        rods.append(shapes.cylinder(0.15 * bead_r, span, (0, 0, rz), axis="y", sections=8))
        row = [
            shapes.ellipsoid(
                (0.9 * bead_r, 0.7 * bead_r, 0.9 * bead_r), (0, -span / 2 + (j + 1) * 1.45 * bead_r, rz), 1
            )
            for j in range(p.beads)
        ]
        beads.append((shapes.concatenate(row), v.color(1, colors[k % len(colors)])))
    parts = [
        *((f, wood) for f in feet),
        *((q, wood) for q in posts),
        (top_bar, wood),
        (shapes.concatenate(rods), P.SILVER),
        *beads,
    ]
    collision = (
        *(col.box_part((x, post_w, 0.06 * z), (0, sy * (y / 2 - post_w / 2), 0.03 * z)) for sy in (1, -1)),
        col.hull_part(_points(*posts, top_bar, *(m for m, _ in beads))),
    )
    return Geometry(tuple(parts), collision)


@builder(NoOptions)
def clipboard(v: Variant, _: NoOptions) -> Geometry:
    """A clipboard lying flat with a sheet of paper held by the metal clip at its top edge (-x)."""
    x, y, z = v.size
    board_t = min(0.003, 0.3 * z)
    board = shapes.slab(x, y, board_t, 0.01, (0, 0, board_t / 2))
    sheet = shapes.box((0.85 * x, 0.9 * y, 0.0004), (0.06 * x, 0, board_t + 0.0001))
    clip_x = 0.1 * x
    clip = shapes.hull(
        [
            (-x / 2 + 0.01 + dx, sy * 0.3 * y, h)
            for dx in (0.0, clip_x)
            for sy in (1, -1)
            for h in (board_t - 0.0005, board_t + 0.003)
        ]
        + [(-x / 2 + 0.01 + 0.3 * clip_x, sy * 0.22 * y, z) for sy in (1, -1)]
    )
    parts = [(board, v.color(0, P.WOOD)), (sheet, P.PAPER), (clip, v.color(1, P.SILVER))]
    collision = (col.box_part((x, y, board_t + 0.0005), (0, 0, (board_t + 0.0005) / 2)), col.hull_part(clip))
    return Geometry(tuple(parts), collision)


@dataclass(frozen=True)
class PaperweightShape:
    """A glass dome (else a faceted block)."""

    dome: bool = True


@builder(PaperweightShape)
def paperweight(v: Variant, p: PaperweightShape) -> Geometry:
    """A heavy paperweight with a flat base: a glass dome with a coloured swirl inside, or a faceted crystal block."""
    x, _, z = v.size
    if p.dome:
        t = np.linspace(0.0, np.pi / 2, 12)
        dome = shapes.lathe([(0.0, 0.0), *((x / 2 * np.cos(a), z * np.sin(a)) for a in t[:-1]), (0.0, z)])
        swirl = shapes.ellipsoid((0.25 * x, 0.25 * x, 0.3 * z), (0, 0, 0.4 * z), 2)
        parts = [(dome, v.color(0, P.GLASS)), (swirl, v.color(1, P.BLUE))]
        return Geometry(tuple(parts), (col.hull_part(dome),))
    y = v.size[1]
    block = shapes.hull(
        [(sx * x / 2, sy * y / 2, 0.0) for sx in (1, -1) for sy in (1, -1)]
        + [(sx * 0.35 * x, sy * 0.35 * y, z) for sx in (1, -1) for sy in (1, -1)]
    )
    core = shapes.box((0.3 * x, 0.3 * y, 0.4 * z), (0, 0, 0.35 * z))
    parts = [(block, v.color(0, P.GLASS)), (core, v.color(1, P.GOLD))]
    return Geometry(tuple(parts), (col.hull_part(block),))


# --- home office electronics and carry cases ----------------------------------------------------------------------


@builder(NoOptions)
def microphone(v: Variant, _: NoOptions) -> Geometry:
    """A desktop microphone: a weighted round base, a short stem and an upright capsule with a mesh grille."""
    x, z = v.size[0], v.size[2]
    base_r = x / 2
    base_h = 0.06 * z
    body_r = 0.42 * base_r
    body_h = 0.55 * z
    body_z0 = z - body_h
    base = shapes.cylinder(base_r, base_h, (0, 0, base_h / 2), sections=40)
    stem = shapes.cylinder(0.12 * base_r, body_z0 - base_h + 0.004, (0, 0, (body_z0 + base_h) / 2), sections=16)
    t = np.linspace(0, np.pi / 2, 8)
    dome = [(body_r * np.cos(a), body_z0 + body_h - body_r + body_r * np.sin(a)) for a in t[:-1]]
    body = shapes.lathe([(0.0, body_z0), (body_r, body_z0), *dome, (0.0, z)])
    grille = shapes.cylinder(1.02 * body_r, 0.35 * body_h, (0, 0, z - 0.3 * body_h), sections=32)
    light = shapes.cylinder(0.15 * body_r, 0.002, (body_r, 0, body_z0 + 0.2 * body_h), axis="x", sections=12)
    dark = v.color(0, P.BLACK)
    parts = [
        (base, dark),
        (stem, v.color(1, P.SILVER)),
        (body, dark),
        (grille, v.color(2, P.CHARCOAL)),
        (light, P.GREEN),
    ]
    collision = (col.cylinder_part(base_r, base_h, (0, 0, base_h / 2)), col.hull_part(_points(stem, body, grille)))
    return Geometry(tuple(parts), collision)


@builder(NoOptions)
def briefcase(v: Variant, _: NoOptions) -> Geometry:
    """A briefcase standing on its bottom edge: a rounded case, a carry handle on top and two latches at +x."""
    x, y, z = v.size
    handle_h = 0.12 * z
    body_z = z - handle_h
    body = shapes.rounded_box((x, y, body_z), 0.2 * x, (0, 0, body_z / 2))
    seam = shapes.box((x + 0.001, y - 0.02, 0.004), (0, 0, 0.85 * body_z))
    t = np.linspace(0, np.pi, 11)
    path = np.stack(
        [np.zeros_like(t), 0.14 * y * np.cos(t), body_z - 0.004 + (handle_h - 0.006) * np.sin(t) ** 0.5], axis=1
    )
    handle = shapes.tube(path, 0.006, sides=10)
    latches = [shapes.box((0.004, 0.03, 0.02), (x / 2 - 0.0005, sy * 0.3 * y, 0.85 * body_z)) for sy in (1, -1)]
    case_c = v.color(0, P.BLACK)
    trim = v.color(1, P.GOLD)
    parts = [(body, case_c), (seam, v.color(2, case_c)), (handle, case_c), *((lt, trim) for lt in latches)]
    collision = (col.box_part((x, y, body_z), (0, 0, body_z / 2)), col.hull_part(handle))
    return Geometry(tuple(parts), collision)


@builder(NoOptions)
def ink_pad(v: Variant, _: NoOptions) -> Geometry:
    """A stamp pad: a flat tin with its lid closed, the inked felt showing as a coloured band at the seam."""
    x, y, z = v.size
    base = shapes.slab(x, y, 0.55 * z, 0.004, (0, 0, 0.275 * z))
    band = shapes.slab(x - 0.002, y - 0.002, 0.1 * z, 0.004, (0, 0, 0.58 * z))
    lid = shapes.slab(x, y, 0.4 * z, 0.004, (0, 0, 0.8 * z))
    parts = ((base, v.color(0, P.BLACK)), (band, v.color(1, P.BLUE)), (lid, v.color(0, P.BLACK)))
    return Geometry(parts, (_solid_box(x, y, z),))


@dataclass(frozen=True)
class RouterShape:
    """How many antennas stand at the back (-x)."""

    antennas: int = 2


@builder(RouterShape)
def router(v: Variant, p: RouterShape) -> Geometry:
    """A wifi router: a low box with status lights on its front (+x) and antennas standing at the back."""
    x, y, z = v.size
    body_h = 0.22 * z if p.antennas else z
    body = shapes.rounded_box((x, y, body_h), 0.3 * min(x, body_h), (0, 0, body_h / 2))
    lights = [
        shapes.cylinder(0.0015, 0.002, (x / 2 - 0.0005, (k - 2) * 0.1 * y, 0.5 * body_h), axis="x", sections=8)
        for k in range(5)
    ]
    parts = [(body, v.color(0, P.BLACK)), (shapes.concatenate(lights), P.rgb(80, 220, 120))]
    collision = [col.box_part((x, y, body_h), (0, 0, body_h / 2))]
    for k in range(p.antennas):
        ay = (k - (p.antennas - 1) / 2) * 0.8 * y / max(1, p.antennas - 1) if p.antennas > 1 else 0.0
        antenna = shapes.cylinder(0.005, z - body_h + 0.004, (-x / 2 + 0.01, ay, (z + body_h) / 2 - 0.002), sections=12)
        parts.append((antenna, v.color(0, P.BLACK)))
        collision.append(col.hull_part(antenna))
    return Geometry(tuple(parts), tuple(collision))


CATEGORIES: tuple[CategoryDef, ...] = builtin_categories(__name__, globals())  # variants: data/study.json
