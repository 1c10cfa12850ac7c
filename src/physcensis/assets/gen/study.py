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
from physcensis.assets.gen.office import monitor
from physcensis.assets.model import RGBA, Cavity, CollisionPart
from physcensis.assets.spec import CategoryDef, Geometry, NoOptions, Variant, builder, define
from physcensis.assets.spec import Variant as V

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


OFFICE = ("office", "desk", "study", "stationery")

CATEGORIES: tuple[CategoryDef, ...] = (
    define(
        "desk lamp",
        "desk lamp",
        desk_lamp,
        [
            V("arm_black", "a black metal desk lamp with an angled arm and a cone shade", (0.3, 0.16, 0.42)),
            V(
                "arm_white",
                "a white adjustable desk lamp with a jointed arm",
                (0.28, 0.15, 0.4),
                (P.WHITE, P.WHITE),
                synonyms=("adjustable lamp",),
            ),
            V(
                "arm_red_dome",
                "a red metal task lamp with a dome shade on a bent arm",
                (0.32, 0.17, 0.45),
                (P.RED, P.RED),
                {"shade": "dome"},
                synonyms=("task lamp", "anglepoise"),
            ),
            V(
                "arm_silver_small",
                "a small silver reading lamp with an arm",
                (0.24, 0.13, 0.34),
                (P.SILVER, P.SILVER),
                synonyms=("reading lamp",),
            ),
            V(
                "stem_drum_cream",
                "a table lamp with a cream fabric drum shade on a brass stem",
                (0.24, 0.24, 0.42),
                (P.BRASS, P.CREAM),
                {"arm": False, "shade": "drum", "base_height": 0.02},
                density=1800.0,
                synonyms=("table lamp", "bedside lamp"),
            ),
            V(
                "stem_cone_white",
                "a small white bedside lamp with a cone shade on a straight stem",
                (0.2, 0.2, 0.34),
                (P.WHITE, P.WHITE),
                {"arm": False, "shade": "cone"},
                density=1800.0,
                synonyms=("bedside lamp", "night lamp"),
            ),
            V(
                "stem_dome_green",
                "a green banker's lamp style dome desk light on a brass stem",
                (0.22, 0.22, 0.38),
                (P.BRASS, P.DARK_GREEN),
                {"arm": False, "shade": "dome"},
                density=1800.0,
                synonyms=("bankers lamp",),
            ),
        ],
        density=2600.0,
        mass_limits=(0.4, 4.0),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=True,
        synonyms=("lamp", "desk light", "reading light", "table lamp", "reading lamp", "study lamp", "light"),
        tags=("light", "lighting", "bulb", "shade", "arm", "adjustable", "desk", "office", "study", "bedside"),
    ),
    define(
        "stapler",
        "stapler",
        stapler,
        [
            V("black", "a black metal desk stapler", (0.16, 0.04, 0.06)),
            V("red", "a red office stapler", (0.16, 0.04, 0.06), (P.RED,)),
            V("blue_mini", "a small blue plastic mini stapler", (0.09, 0.03, 0.04), (P.BLUE, P.WHITE), density=900.0),
            V(
                "silver_heavy",
                "a heavy duty silver stapler",
                (0.26, 0.06, 0.1),
                (P.SILVER, P.CHARCOAL),
                {"plate": 0.14},
            ),
            V("grey_long", "a long grey desk stapler", (0.2, 0.045, 0.065), (P.GREY, P.BLACK)),
            V("white", "a white plastic stapler", (0.15, 0.04, 0.055), (P.WHITE, P.GREY), density=900.0),
            V("green", "a green half strip stapler", (0.14, 0.038, 0.055), (P.GREEN, P.SILVER)),
        ],
        density=1500.0,
        mass_limits=(0.03, 2.0),
        friction=(0.4, 0.7),
        support_probability=0.1,
        has_front=True,
        synonyms=("staple gun", "desk stapler", "staples"),
        tags=("staple", "stapling", "paper", *OFFICE),
    ),
    define(
        "hole punch",
        "hole punch",
        hole_punch,
        [
            V("grey_two", "a grey metal two hole paper punch", (0.12, 0.14, 0.075)),
            V("black_two", "a black two hole punch", (0.12, 0.14, 0.075), (P.BLACK, P.SILVER)),
            V("blue_small", "a small blue plastic hole punch", (0.1, 0.11, 0.06), (P.BLUE, P.WHITE), density=900.0),
            V("silver_four", "a silver four hole punch", (0.13, 0.3, 0.08), (P.SILVER, P.BLACK), {"holes": 4}),
            V("red", "a red two hole punch", (0.12, 0.14, 0.07), (P.RED, P.SILVER)),
            V("heavy_black", "a heavy duty black hole puncher", (0.17, 0.2, 0.11), (P.BLACK, P.STEEL)),
            V("white_single", "a white one hole punch", (0.09, 0.07, 0.055), (P.WHITE, P.GREY), {"holes": 1}),
        ],
        density=1300.0,
        mass_limits=(0.05, 3.0),
        friction=(0.4, 0.7),
        support_probability=0.05,
        has_front=True,
        synonyms=("hole puncher", "paper punch", "punch"),
        tags=("holes", "paper", "binder", *OFFICE),
    ),
    define(
        "tape dispenser",
        "tape dispenser",
        tape_dispenser,
        [
            V("black", "a black weighted desk tape dispenser with a roll of clear tape", (0.15, 0.06, 0.08)),
            V("grey", "a grey sticky tape dispenser", (0.14, 0.055, 0.075), (P.GREY,)),
            V("red", "a red desktop tape dispenser", (0.15, 0.06, 0.08), (P.RED,)),
            V("clear_small", "a small clear plastic tape dispenser", (0.1, 0.04, 0.06), (P.GLASS,), density=900.0),
            V("white", "a white desk tape holder", (0.14, 0.055, 0.075), (P.WHITE,)),
            V("wood", "a wooden tape dispenser", (0.16, 0.065, 0.085), (P.WOOD,), density=1000.0),
            V(
                "blue_masking",
                "a blue tape dispenser with a roll of beige paper tape",
                (0.15, 0.07, 0.085),
                (P.BLUE, P.rgb(225, 205, 160)),
            ),
        ],
        density=1800.0,
        mass_limits=(0.05, 1.5),
        friction=(0.5, 0.8),
        support_probability=0.05,
        has_front=True,
        synonyms=("tape", "sticky tape", "scotch tape", "tape holder", "sellotape", "clear tape", "adhesive tape"),
        tags=("tape", "roll", "dispenser", *OFFICE),
    ),
    define(
        "scissors",
        "scissors",
        scissors,
        [
            V("red", "a pair of red handled office scissors", (0.21, 0.08, 0.01)),
            V("black", "a pair of black handled scissors", (0.2, 0.075, 0.01), (P.BLACK,)),
            V(
                "kids_blue",
                "a pair of small blue children's safety scissors",
                (0.13, 0.06, 0.009),
                (P.BLUE,),
                {"blade": 0.45},
                synonyms=("safety scissors", "kids scissors"),
            ),
            V("orange_large", "a pair of large orange shears", (0.25, 0.09, 0.012), (P.ORANGE,), synonyms=("shears",)),
            V("green", "a pair of green craft scissors", (0.17, 0.07, 0.009), (P.GREEN,)),
            V("purple", "a pair of purple paper scissors", (0.18, 0.07, 0.009), (P.PURPLE,)),
            V(
                "steel_small",
                "a pair of small all steel scissors",
                (0.14, 0.055, 0.007),
                (P.STEEL, P.STEEL),
                {"loop": 0.52},
                density=3500.0,
            ),
        ],
        density=2000.0,
        mass_limits=(0.01, 0.3),
        friction=(0.3, 0.6),
        support_probability=0.0,
        has_front=True,
        synonyms=("scissor", "shears", "pair of scissors", "paper scissors"),
        tags=("cutting", "blade", "craft", "school", *OFFICE, "flat"),
    ),
    define(
        "glue",
        "glue stick",
        glue,
        [
            V("stick_purple", "a white glue stick with a purple cap", (0.025, 0.025, 0.1)),
            V("stick_red", "a glue stick with a red cap", (0.022, 0.022, 0.09), (P.WHITE, P.RED)),
            V("stick_large_green", "a large glue stick with a green cap", (0.03, 0.03, 0.11), (P.WHITE, P.GREEN)),
            V("stick_small_blue", "a small glue stick with a blue cap", (0.018, 0.018, 0.075), (P.WHITE, P.BLUE)),
            V(
                "bottle_white",
                "a white bottle of school glue with an orange nozzle",
                (0.045, 0.045, 0.14),
                (P.WHITE, P.ORANGE),
                {"style": "bottle"},
                density=700.0,
                synonyms=("glue bottle", "white glue", "pva glue"),
            ),
            V(
                "bottle_small",
                "a small bottle of craft glue with a blue nozzle",
                (0.035, 0.035, 0.1),
                (P.WHITE, P.BLUE),
                {"style": "bottle"},
                density=700.0,
                synonyms=("glue bottle", "craft glue"),
            ),
            V(
                "bottle_clear",
                "a clear bottle of liquid glue with a red cap",
                (0.04, 0.04, 0.12),
                (P.rgb(215, 230, 235), P.RED),
                {"style": "bottle"},
                density=700.0,
                synonyms=("liquid glue", "glue bottle"),
            ),
            V(
                "tube_super",
                "a small tube of super glue with a red cap",
                (0.085, 0.03, 0.016),
                (P.WHITE, P.RED, P.rgb(230, 60, 60)),
                {"style": "tube"},
                density=900.0,
                synonyms=("tube of glue", "glue tube", "super glue", "superglue"),
            ),
        ],
        density=800.0,
        mass_limits=(0.01, 0.3),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        prefix="glue",
        synonyms=(
            "glue stick",
            "gluestick",
            "glue",
            "adhesive",
            "adhesive stick",
            "paper glue",
            "paste",
            "pritt stick",
        ),
        tags=("glue", "sticky", "stick", "craft", "school", *OFFICE),
    ),
    define(
        "ruler",
        "ruler",
        ruler,
        [
            V("wood_30", "a 30 cm wooden ruler", (0.305, 0.03, 0.004), density=650.0),
            V(
                "clear_15",
                "a short clear plastic ruler of 15 cm",
                (0.16, 0.035, 0.003),
                (P.rgb(215, 230, 240, 0.6),),
                density=1200.0,
            ),
            V(
                "steel_30",
                "a stainless steel ruler",
                (0.32, 0.025, 0.003),
                (P.STEEL,),
                density=3500.0,
                synonyms=("steel rule", "metal ruler"),
            ),
            V(
                "yardstick",
                "a long wooden metre stick",
                (1.0, 0.03, 0.006),
                density=650.0,
                synonyms=("yardstick", "meter stick", "metre stick"),
            ),
            V("blue_30", "a blue plastic school ruler", (0.31, 0.035, 0.003), (P.BLUE, P.WHITE), density=1200.0),
            V(
                "set_square",
                "a clear plastic triangle set square",
                (0.2, 0.2, 0.003),
                (P.rgb(215, 230, 240, 0.6),),
                {"style": "triangle"},
                density=1200.0,
                synonyms=("set square", "triangle ruler", "drafting triangle"),
            ),
            V(
                "protractor",
                "a clear half round protractor",
                (0.08, 0.15, 0.003),
                (P.rgb(215, 230, 240, 0.6),),
                {"style": "protractor"},
                density=1200.0,
                synonyms=("protractor", "angle measure"),
            ),
        ],
        density=1000.0,
        mass_limits=(0.002, 0.3),
        friction=(0.3, 0.6),
        support_probability=0.1,
        has_front=False,
        synonyms=("rule", "straightedge", "measuring ruler", "scale ruler"),
        tags=("measuring", "measure", "length", "straight", "school", "geometry", *OFFICE, "flat"),
    ),
    define(
        "eraser",
        "eraser",
        eraser,
        [
            V("white", "a white vinyl pencil eraser", (0.06, 0.022, 0.012), (P.WHITE, P.BLUE), {"sleeve": True}),
            V("pink", "a pink rubber eraser", (0.05, 0.02, 0.01)),
            V("pink_large", "a large pink wedge of rubber eraser", (0.065, 0.025, 0.013)),
            V("blue_small", "a small blue eraser block", (0.035, 0.02, 0.01), (P.SKY,)),
            V(
                "green_sleeve",
                "a green eraser in a paper sleeve",
                (0.055, 0.022, 0.012),
                (P.LIME, P.WHITE),
                {"sleeve": True},
            ),
            V(
                "whiteboard",
                "a whiteboard eraser with a grey felt pad and a blue plastic handle",
                (0.15, 0.055, 0.04),
                (P.BLUE, P.GREY),
                {"style": "board"},
                density=450.0,
                synonyms=("whiteboard eraser", "board eraser", "blackboard duster", "chalkboard eraser"),
            ),
            V(
                "board_black",
                "a black board duster with a felt pad",
                (0.13, 0.05, 0.035),
                (P.BLACK, P.GREY),
                {"style": "board"},
                density=450.0,
                synonyms=("board duster", "chalk eraser"),
            ),
        ],
        density=1300.0,
        mass_limits=(0.003, 0.3),
        friction=(0.7, 1.0),
        support_probability=0.1,
        has_front=False,
        synonyms=("rubber", "pencil eraser", "rubber eraser", "eraser block"),
        tags=("erase", "rubber", "school", "pencil", *OFFICE),
    ),
    define(
        "paper",
        "sheet of paper",
        paper,
        [
            V(
                "a4_sheet",
                "a single white A4 sheet of paper lying flat",
                (0.297, 0.21, 0.003),
                density=30.0,
                synonyms=("sheet", "a4 sheet", "page", "white paper"),
            ),
            V(
                "letter_sheet",
                "a single white letter size sheet of paper with printed text",
                (0.279, 0.216, 0.003),
                density=30.0,
                synonyms=("sheet", "letter paper", "printout", "document"),
            ),
            V(
                "lined_sheet",
                "a sheet of lined writing paper",
                (0.28, 0.215, 0.003),
                options={"lined": True},
                density=30.0,
                synonyms=("lined paper", "ruled paper", "writing paper", "loose leaf"),
            ),
            V(
                "yellow_sheet",
                "a sheet of yellow coloured paper",
                (0.297, 0.21, 0.003),
                (P.rgb(250, 230, 120),),
                density=30.0,
                synonyms=("colored paper", "coloured paper", "construction paper"),
            ),
            V(
                "stack_small",
                "a small stack of white printer paper sheets",
                (0.297, 0.21, 0.006),
                synonyms=("stack of paper", "pile of paper", "papers", "paper stack", "printer paper", "white paper"),
            ),
            V(
                "stack_letter",
                "a neat pile of letter size printed pages",
                (0.279, 0.216, 0.012),
                synonyms=("pile of paper", "papers", "documents", "paperwork"),
            ),
            V(
                "ream_wrapped",
                "a wrapped ream of 500 sheets of copy paper",
                (0.297, 0.21, 0.05),
                (P.PAPER, P.rgb(200, 60, 50)),
                {"wrapped": True},
                synonyms=("ream", "ream of paper", "copy paper", "printer paper", "white paper"),
            ),
            V(
                "crumpled_ball",
                "a crumpled paper ball, a sheet scrunched up",
                (0.075, 0.07, 0.062),
                mass=0.005,
                options={"crumpled": True},
                synonyms=("crumpled paper", "paper ball", "ball of paper", "scrunched up paper", "wad of paper"),
                tags=("crumpled", "scrunched", "waste", "rubbish", "ball"),
            ),
            V(
                "crumpled_lined",
                "a crumpled ball of lined paper",
                (0.065, 0.06, 0.055),
                (P.rgb(235, 238, 245),),
                mass=0.004,
                options={"crumpled": True},
                synonyms=("crumpled paper", "paper ball", "scrunched paper", "balled up paper"),
                tags=("crumpled", "scrunched", "waste", "rubbish", "ball"),
            ),
        ],
        density=800.0,
        mass_limits=(0.003, 3.0),
        friction=(0.4, 0.7),
        support_probability=0.9,
        has_front=False,
        prefix="paper",
        synonyms=("paper", "sheet of paper", "paper sheet", "sheets", "sheets of paper", "printer paper", "a4 paper"),
        tags=("paper", "sheet", "page", "writing", "printing", *OFFICE, "flat"),
    ),
    define(
        "sticky notes",
        "sticky notes pad",
        sticky_notes,
        [
            V("yellow", "a square pad of yellow sticky notes", (0.076, 0.076, 0.01)),
            V("pink", "a pink pad of sticky notes", (0.076, 0.076, 0.01), (P.PINK,)),
            V("green", "a lime green sticky note pad", (0.076, 0.076, 0.012), (P.LIME,)),
            V("blue_small", "a small blue pad of memo notes", (0.05, 0.04, 0.008), (P.SKY,)),
            V("orange_large", "a large orange lined sticky note pad", (0.1, 0.1, 0.012), (P.ORANGE,)),
            V(
                "cube_mixed",
                "a cube of rainbow coloured sticky notes",
                (0.08, 0.08, 0.05),
                (P.YELLOW, P.PINK, P.LIME, P.SKY, P.ORANGE),
                {"bands": 5},
                synonyms=("note cube", "memo cube"),
            ),
            V(
                "cube_white",
                "a cube of white memo paper notes",
                (0.09, 0.09, 0.045),
                (P.PAPER,),
                synonyms=("memo cube", "note block", "scratch paper"),
            ),
        ],
        density=650.0,
        mass_limits=(0.005, 0.5),
        friction=(0.5, 0.8),
        support_probability=0.8,
        has_front=False,
        prefix="sticky_notes",
        synonyms=("sticky note", "post-it", "post-its", "post it notes", "memo pad", "sticky pad", "note pad"),
        tags=("notes", "memo", "reminder", "paper", *OFFICE, "flat"),
    ),
    define(
        "calculator",
        "calculator",
        calculator,
        [
            V("black_desk", "a black desktop calculator", (0.15, 0.1, 0.02)),
            V("grey_pocket", "a small grey pocket calculator", (0.1, 0.065, 0.01), (P.GREY, P.CHARCOAL), {"rows": 5}),
            V(
                "scientific_blue",
                "a dark blue scientific calculator",
                (0.165, 0.08, 0.017),
                (P.NAVY, P.GREY),
                {"rows": 8, "cols": 5},
                synonyms=("scientific calculator",),
            ),
            V(
                "graphing_black",
                "a black graphing calculator with a large screen",
                (0.19, 0.086, 0.024),
                (P.BLACK, P.GREY),
                {"rows": 9, "cols": 5, "display": 0.38},
                synonyms=("graphing calculator", "graphic calculator"),
            ),
            V("white", "a white desk calculator with big keys", (0.16, 0.12, 0.025), (P.WHITE, P.GREY), {"cols": 5}),
            V("silver_solar", "a silver solar calculator", (0.13, 0.09, 0.015), (P.SILVER, P.CHARCOAL)),
            V("pink_kids", "a pink children's calculator", (0.12, 0.08, 0.018), (P.PINK, P.WHITE)),
        ],
        density=700.0,
        mass_limits=(0.03, 0.5),
        friction=(0.5, 0.8),
        support_probability=0.2,
        has_front=True,
        synonyms=("adding machine", "pocket calculator", "desk calculator"),
        tags=("math", "maths", "numbers", "keys", "electronics", *OFFICE, "school"),
    ),
    define(
        "remote control",
        "remote control",
        remote_control,
        [
            V("tv_black", "a black TV remote control", (0.2, 0.05, 0.022), synonyms=("tv remote",)),
            V(
                "tv_silver",
                "a long silver television remote",
                (0.21, 0.048, 0.02),
                (P.SILVER, P.CHARCOAL),
                synonyms=("tv remote",),
            ),
            V("small_white", "a small white streaming remote", (0.13, 0.038, 0.015), (P.WHITE, P.GREY), {"rows": 3}),
            V("grey_ac", "a grey air conditioner remote", (0.16, 0.055, 0.02), (P.GREY, P.WHITE), {"rows": 5}),
            V("universal", "a large black universal remote", (0.24, 0.06, 0.025), (P.BLACK, P.CHARCOAL), {"rows": 8}),
            V("slim_dark", "a slim dark grey remote", (0.17, 0.04, 0.015), (P.CHARCOAL, P.BLACK), {"rows": 4}),
            V("blue_kids", "a chunky blue remote control", (0.15, 0.06, 0.025), (P.BLUE, P.YELLOW), {"rows": 3}),
        ],
        density=650.0,
        mass_limits=(0.03, 0.4),
        friction=(0.4, 0.7),
        support_probability=0.05,
        has_front=True,
        synonyms=("remote", "tv remote", "clicker", "controller", "television remote", "remote controller"),
        tags=("buttons", "handheld", "electronics", "living room", "sofa"),
    ),
    define(
        "binder",
        "ring binder",
        ring_binder,
        [
            V("blue_flat", "a blue ring binder lying flat", (0.32, 0.29, 0.055)),
            V(
                "black_flat",
                "a black lever arch file lying flat",
                (0.32, 0.29, 0.08),
                (P.BLACK,),
                synonyms=("lever arch file",),
            ),
            V("red_flat", "a slim red binder lying flat", (0.31, 0.27, 0.035), (P.RED,)),
            V(
                "white_upright",
                "a white presentation binder standing upright on a shelf",
                (0.29, 0.055, 0.32),
                (P.WHITE,),
                {"upright": True},
            ),
            V(
                "black_upright",
                "a black lever arch file standing on its edge",
                (0.29, 0.08, 0.32),
                (P.BLACK,),
                {"upright": True},
                synonyms=("lever arch file", "archive file"),
            ),
            V(
                "green_upright",
                "a green school binder standing upright",
                (0.28, 0.045, 0.31),
                (P.GREEN,),
                {"upright": True},
            ),
            V(
                "yellow_upright",
                "a yellow office file standing upright",
                (0.29, 0.055, 0.32),
                (P.YELLOW,),
                {"upright": True},
            ),
        ],
        density=350.0,
        mass_limits=(0.15, 2.5),
        friction=(0.4, 0.7),
        support_probability=0.6,
        has_front=True,
        synonyms=("ring binder", "binder", "lever arch file", "ring file", "folder binder", "three ring binder"),
        tags=("file", "filing", "documents", "paper", "archive", "shelf", *OFFICE),
    ),
    define(
        "folder",
        "file folder",
        file_folder,
        [
            V("manila", "a manila file folder with papers inside", (0.31, 0.24, 0.006)),
            V("blue_card", "a blue card folder holding a few sheets", (0.31, 0.24, 0.005), (P.SKY,)),
            V("red_card", "a red document folder lying flat", (0.31, 0.24, 0.005), (P.RED,)),
            V(
                "clear_wallet",
                "a clear plastic document wallet with a snap button",
                (0.33, 0.24, 0.006),
                (P.rgb(210, 225, 235, 0.7), P.PAPER, P.rgb(190, 210, 225, 0.8)),
                {"style": "wallet"},
                synonyms=("document wallet", "plastic sleeve", "clear folder"),
            ),
            V(
                "green_wallet",
                "a green plastic envelope folder",
                (0.33, 0.24, 0.008),
                (P.GREEN, P.PAPER, P.DARK_GREEN),
                {"style": "wallet"},
                synonyms=("envelope folder", "document wallet"),
            ),
            V(
                "expanding_black",
                "a black expanding file with pockets",
                (0.33, 0.25, 0.04),
                (P.BLACK, P.PAPER, P.CHARCOAL),
                {"style": "expanding"},
                density=250.0,
                synonyms=("expanding file", "accordion folder", "accordion file"),
            ),
            V(
                "expanding_brown",
                "a brown cardboard accordion file",
                (0.3, 0.24, 0.05),
                (P.CARDBOARD, P.PAPER, P.DARK_BROWN),
                {"style": "expanding"},
                density=250.0,
                synonyms=("expanding file", "accordion folder"),
            ),
        ],
        density=500.0,
        mass_limits=(0.02, 1.0),
        friction=(0.4, 0.7),
        support_probability=0.9,
        has_front=True,
        synonyms=("file folder", "document folder", "file", "manila folder", "paper folder", "portfolio"),
        tags=("documents", "papers", "filing", "paperwork", *OFFICE, "flat"),
    ),
    define(
        "envelope",
        "envelope",
        envelope,
        [
            V("white_dl", "a white letter envelope", (0.22, 0.11, 0.003), density=120.0),
            V("kraft_c5", "a brown kraft paper envelope", (0.229, 0.162, 0.003), (P.CARDBOARD,), density=400.0),
            V(
                "manila_large",
                "a large manila envelope for documents",
                (0.324, 0.229, 0.004),
                (P.rgb(220, 190, 130),),
                density=400.0,
                synonyms=("manila envelope",),
            ),
            V(
                "airmail",
                "a white airmail envelope with red and blue stripes",
                (0.22, 0.11, 0.003),
                options={"airmail": True},
                density=120.0,
                synonyms=("airmail", "letter"),
            ),
            V(
                "padded_yellow",
                "a yellow padded bubble mailer",
                (0.26, 0.18, 0.012),
                (P.rgb(235, 205, 110),),
                {"padded": True},
                density=150.0,
                synonyms=("padded envelope", "bubble mailer", "mailer"),
            ),
            V(
                "pink_card",
                "a pink greeting card envelope",
                (0.16, 0.12, 0.004),
                (P.PINK,),
                density=400.0,
                synonyms=("card envelope",),
            ),
            V("blue_square", "a square blue envelope", (0.15, 0.15, 0.003), (P.SKY,), density=400.0),
        ],
        density=400.0,
        mass_limits=(0.002, 0.3),
        friction=(0.4, 0.7),
        support_probability=0.8,
        has_front=False,
        synonyms=("letter", "mail", "post", "envelopes"),
        tags=("mail", "letter", "post", "paper", "stationery", "office", "flat"),
    ),
    define(
        "desk organiser",
        "desk organiser",
        desk_organiser,
        [
            V("black_mesh", "a black metal desk organiser with compartments", (0.16, 0.25, 0.1)),
            V(
                "bamboo_drawer",
                "a bamboo drawer organiser tray with small compartments",
                (0.23, 0.38, 0.05),
                (P.BAMBOO, P.LIGHT_WOOD),
                {"cells": 4, "main": 0.5, "wall": 0.006},
                density=600.0,
                synonyms=("drawer organiser", "drawer organizer", "drawer tray", "cutlery tray"),
            ),
            V(
                "white_plastic",
                "a white plastic desk tidy with four cells",
                (0.14, 0.22, 0.09),
                (P.WHITE,),
                {"cells": 4},
                density=950.0,
                synonyms=("desk tidy",),
            ),
            V(
                "wood_caddy",
                "a wooden desk caddy for pens and notes",
                (0.15, 0.3, 0.11),
                (P.WOOD, P.LIGHT_WOOD),
                {"cells": 2, "main": 0.5, "wall": 0.006},
                density=600.0,
                synonyms=("desk caddy", "stationery caddy"),
            ),
            V(
                "grey_drawer",
                "a grey plastic drawer organizer",
                (0.3, 0.23, 0.05),
                (P.GREY,),
                {"cells": 2, "main": 0.6},
                density=950.0,
                synonyms=("drawer organizer", "drawer divider"),
            ),
            V("pink_small", "a small pink desk organizer", (0.1, 0.18, 0.08), (P.PINK,), {"cells": 2}, density=950.0),
            V(
                "clear_acrylic",
                "a clear acrylic stationery organiser",
                (0.15, 0.24, 0.1),
                (P.rgb(210, 230, 240, 0.6),),
                {"cells": 3, "main": 0.45},
                density=1180.0,
                synonyms=("stationery organiser", "acrylic organizer"),
            ),
        ],
        density=2000.0,
        mass_limits=(0.05, 2.0),
        friction=(0.4, 0.7),
        support_probability=0.3,
        has_front=True,
        prefix="desk_organiser",
        synonyms=(
            "desk organizer",
            "organiser",
            "organizer",
            "desk tidy",
            "drawer organiser",
            "drawer organizer",
            "stationery holder",
            "supply caddy",
        ),
        tags=("container", "compartments", "storage", "tidy", "holder", *OFFICE),
    ),
    define(
        "letter tray",
        "letter tray",
        letter_tray,
        [
            V("black", "a black plastic letter tray for paper", (0.34, 0.26, 0.065)),
            V("grey", "a grey A4 document tray", (0.35, 0.26, 0.065), (P.GREY,)),
            V("blue", "a blue paper tray", (0.34, 0.26, 0.065), (P.BLUE,)),
            V(
                "black_double",
                "a two tier black letter tray on posts",
                (0.34, 0.26, 0.15),
                (P.BLACK, P.SILVER),
                {"tiers": 2},
            ),
            V(
                "silver_triple",
                "a three tier silver mesh paper tray",
                (0.35, 0.27, 0.24),
                (P.SILVER, P.GREY),
                {"tiers": 3},
                density=1500.0,
                synonyms=("paper organizer",),
            ),
            V(
                "wood",
                "a wooden in tray for letters",
                (0.34, 0.27, 0.07),
                (P.WOOD,),
                density=600.0,
            ),
            V("clear", "a clear acrylic letter tray", (0.33, 0.25, 0.06), (P.rgb(210, 230, 240, 0.6),), {"front": 0.3}),
        ],
        density=1000.0,
        mass_limits=(0.1, 3.0),
        friction=(0.4, 0.7),
        support_probability=0.7,
        has_front=True,
        synonyms=("file tray", "paper tray", "letter holder", "document holder", "inbox"),
        tags=("container", "papers", "documents", "letters", "filing", *OFFICE),
    ),
    define(
        "clock",
        "alarm clock",
        alarm_clock,
        [
            V("bell_red", "a red twin bell alarm clock", (0.06, 0.12, 0.14)),
            V(
                "bell_black",
                "a black retro alarm clock with two bells",
                (0.06, 0.12, 0.14),
                (P.BLACK, P.WHITE, P.SILVER),
            ),
            V("bell_blue_small", "a small blue wind-up alarm clock", (0.05, 0.1, 0.115), (P.BLUE, P.WHITE, P.SILVER)),
            V(
                "round_wood",
                "a round desk clock on a wooden base",
                (0.07, 0.13, 0.14),
                (P.SILVER, P.WHITE, P.WOOD),
                {"style": "round"},
                synonyms=("desk clock", "table clock", "mantel clock"),
            ),
            V(
                "round_white",
                "a white round bedside clock",
                (0.06, 0.11, 0.12),
                (P.WHITE, P.CREAM, P.GREY),
                {"style": "round"},
                synonyms=("bedside clock",),
            ),
            V(
                "digital_black",
                "a black digital alarm clock with green numbers",
                (0.07, 0.15, 0.07),
                (P.BLACK,),
                {"style": "digital"},
                density=600.0,
                synonyms=("digital clock", "clock radio"),
            ),
            V(
                "digital_white",
                "a white cube shaped digital clock with red digits",
                (0.07, 0.08, 0.07),
                (P.WHITE, P.RED),
                {"style": "digital"},
                density=600.0,
                synonyms=("digital clock", "cube clock"),
            ),
        ],
        density=900.0,
        mass_limits=(0.08, 1.0),
        friction=(0.5, 0.8),
        support_probability=0.05,
        has_front=True,
        prefix="clock",
        synonyms=("alarm clock", "clock", "desk clock", "bedside clock", "table clock", "alarm"),
        tags=("time", "alarm", "bedside", "nightstand", "desk", "bedroom", "wake"),
    ),
    define(
        "picture frame",
        "picture frame",
        picture_frame,
        [
            V("black_4x6", "a small black photo frame standing on a desk", (0.07, 0.13, 0.18)),
            V(
                "wood_landscape",
                "a wooden landscape picture frame with a family photo",
                (0.09, 0.25, 0.2),
                (P.WOOD, P.WHITE, P.rgb(110, 160, 90)),
                density=700.0,
            ),
            V(
                "white_portrait",
                "a white portrait picture frame",
                (0.08, 0.18, 0.23),
                (P.WHITE, P.CREAM, P.rgb(230, 170, 120)),
                density=700.0,
            ),
            V(
                "silver_small",
                "a small silver metal photo frame",
                (0.06, 0.11, 0.14),
                (P.SILVER, P.WHITE, P.rgb(200, 120, 140)),
                {"border": 0.09},
            ),
            V(
                "gold_ornate",
                "a gold framed photograph with a wide border",
                (0.09, 0.22, 0.27),
                (P.GOLD, P.CREAM, P.rgb(90, 120, 170)),
                {"border": 0.16},
            ),
            V(
                "digital_black",
                "a black digital photo frame with a screen",
                (0.1, 0.26, 0.18),
                (P.BLACK,),
                {"digital": True, "border": 0.08},
                density=1000.0,
                synonyms=("digital photo frame", "digital frame"),
            ),
            V(
                "red_square",
                "a square red picture frame holding a print",
                (0.07, 0.15, 0.15),
                (P.RED, P.WHITE, P.rgb(240, 200, 90)),
                density=700.0,
            ),
        ],
        density=1000.0,
        mass_limits=(0.05, 1.5),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        synonyms=("photo frame", "frame", "photograph", "photo", "picture", "framed photo", "framed picture"),
        tags=("photo", "picture", "family", "memory", "decoration", "decor", "desk", "shelf", "mantel"),
    ),
    define(
        "calendar",
        "desk calendar",
        desk_calendar,
        [
            V("white_red", "a white tent desk calendar with a red date grid", (0.08, 0.2, 0.14)),
            V("blue", "a blue standing desk calendar", (0.08, 0.2, 0.14), (P.SKY, P.NAVY)),
            V("small_green", "a small green table calendar", (0.06, 0.14, 0.1), (P.rgb(210, 235, 200), P.GREEN)),
            V("large_black", "a large black desk planner calendar", (0.11, 0.28, 0.18), (P.CHARCOAL, P.WHITE)),
            V("kraft", "a kraft paper flip calendar", (0.07, 0.18, 0.12), (P.CARDBOARD, P.DARK_BROWN)),
            V("pink", "a pink standing calendar", (0.08, 0.18, 0.13), (P.PINK, P.PURPLE)),
            V("yellow_wide", "a wide yellow monthly calendar", (0.09, 0.26, 0.15), (P.rgb(250, 230, 130), P.ORANGE)),
        ],
        density=150.0,
        mass_limits=(0.03, 0.8),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        synonyms=("desk calendar", "table calendar", "standing calendar", "planner", "flip calendar", "date calendar"),
        tags=("date", "dates", "month", "schedule", "paper", *OFFICE),
    ),
    define(
        "speaker",
        "speaker",
        speaker,
        [
            V(
                "bookshelf_black",
                "a black bookshelf loudspeaker",
                (0.2, 0.15, 0.25),
                synonyms=("bookshelf speaker", "loudspeaker"),
            ),
            V(
                "bookshelf_wood",
                "a wooden hifi speaker with a black woofer",
                (0.22, 0.16, 0.28),
                (P.WOOD, P.BLACK),
                synonyms=("hifi speaker", "stereo speaker"),
            ),
            V(
                "desktop_white",
                "a small white computer speaker",
                (0.09, 0.08, 0.15),
                (P.WHITE, P.GREY),
                density=450.0,
                synonyms=("computer speaker",),
            ),
            V(
                "smart_grey",
                "a round grey fabric smart speaker",
                (0.1, 0.1, 0.15),
                (P.CHARCOAL, P.GREY),
                {"style": "round"},
                density=650.0,
                synonyms=("smart speaker", "voice assistant"),
            ),
            V(
                "smart_white_small",
                "a small white smart speaker with a light ring",
                (0.1, 0.1, 0.09),
                (P.WHITE, P.rgb(225, 225, 225)),
                {"style": "round"},
                density=650.0,
                synonyms=("smart speaker",),
            ),
            V(
                "portable_blue",
                "a blue portable bluetooth speaker",
                (0.07, 0.18, 0.07),
                (P.BLUE, P.NAVY),
                {"style": "pill"},
                density=800.0,
                synonyms=("bluetooth speaker", "portable speaker", "wireless speaker"),
            ),
            V(
                "portable_red",
                "a red wireless speaker",
                (0.06, 0.15, 0.06),
                (P.RED, P.DARK_RED),
                {"style": "pill"},
                density=800.0,
                synonyms=("bluetooth speaker", "portable speaker"),
            ),
        ],
        density=550.0,
        mass_limits=(0.2, 8.0),
        friction=(0.5, 0.8),
        support_probability=0.3,
        has_front=True,
        synonyms=("loudspeaker", "speakers", "sound system", "audio speaker", "stereo speaker"),
        tags=("audio", "music", "sound", "electronics", "desk", "shelf", "living room"),
    ),
    define(
        "tablet",
        "tablet",
        tablet,
        [
            V("black_10", "a black ten inch tablet computer", (0.245, 0.17, 0.008)),
            V("silver_11", "a silver tablet with a thin bezel", (0.25, 0.18, 0.007), (P.SILVER,), {"bezel": 0.008}),
            V("mini_gold", "a small gold mini tablet", (0.2, 0.135, 0.007), (P.GOLD,), synonyms=("mini tablet",)),
            V("large_grey", "a large grey pro tablet", (0.28, 0.215, 0.0065), (P.GREY,), {"bezel": 0.008}),
            V(
                "case_navy",
                "a tablet in a navy blue folio case",
                (0.255, 0.18, 0.015),
                (P.CHARCOAL, P.NAVY),
                {"case": True},
                density=1200.0,
                synonyms=("tablet case", "ipad case"),
            ),
            V(
                "ereader",
                "a black e-reader with a wide bezel",
                (0.16, 0.115, 0.008),
                (P.BLACK, P.BLACK, P.rgb(200, 200, 190)),
                {"bezel": 0.012},
                synonyms=("e-reader", "ebook reader", "kindle"),
            ),
            V(
                "kids_red",
                "a children's tablet in a red rubber case",
                (0.22, 0.16, 0.022),
                (P.CHARCOAL, P.RED),
                {"case": True, "bezel": 0.02},
                density=800.0,
                synonyms=("kids tablet",),
            ),
        ],
        density=1900.0,
        mass_limits=(0.15, 1.0),
        friction=(0.3, 0.6),
        support_probability=0.5,
        has_front=True,
        synonyms=("tablet computer", "ipad", "touchscreen tablet", "e-reader", "slate"),
        tags=("electronics", "device", "screen", "touchscreen", "computer", "reading"),
    ),
    define(
        "headphones",
        "headphones",
        headphones,
        [
            V("black_over_ear", "a pair of black over-ear headphones lying flat", (0.17, 0.19, 0.07)),
            V("white_over_ear", "white wireless headphones", (0.17, 0.19, 0.07), (P.WHITE, P.GREY)),
            V("red_on_ear", "red on-ear headphones", (0.15, 0.17, 0.05), (P.RED, P.BLACK), {"cup": 0.38}),
            V("silver_studio", "a pair of silver studio headphones", (0.19, 0.21, 0.08), (P.SILVER, P.BLACK)),
            V(
                "gaming_headset",
                "a black gaming headset with a microphone boom",
                (0.2, 0.21, 0.08),
                (P.BLACK, P.RED),
                {"mic": True},
                synonyms=("headset", "gaming headset"),
            ),
            V(
                "office_headset",
                "a grey office headset with a mic",
                (0.17, 0.18, 0.06),
                (P.GREY, P.CHARCOAL),
                {"mic": True, "cup": 0.35},
                synonyms=("headset", "call headset"),
            ),
            V("kids_blue", "small blue kids headphones", (0.14, 0.16, 0.05), (P.SKY, P.BLUE), {"cup": 0.4}),
        ],
        density=450.0,
        mass_limits=(0.08, 0.6),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        synonyms=("headphone", "headset", "earphones", "cans", "over-ear headphones", "wireless headphones"),
        tags=("audio", "music", "listening", "sound", "electronics", "desk"),
    ),
    define(
        "webcam",
        "webcam",
        webcam,
        [
            V("black_bar", "a black webcam on a small stand", (0.035, 0.095, 0.06)),
            V("grey_bar", "a grey HD web camera", (0.035, 0.1, 0.06), (P.GREY,)),
            V("wide_black", "a wide black conference camera", (0.045, 0.16, 0.07), synonyms=("conference camera",)),
            V("ball_white", "a round white webcam", (0.05, 0.05, 0.08), (P.WHITE,), {"ball": True}),
            V("ball_black", "a black ball shaped web cam", (0.045, 0.045, 0.075), (P.BLACK,), {"ball": True}),
            V("silver_small", "a small silver webcam", (0.03, 0.08, 0.05), (P.SILVER,)),
            V("white_bar", "a white usb webcam", (0.035, 0.09, 0.055), (P.WHITE,)),
        ],
        density=700.0,
        mass_limits=(0.02, 0.4),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        synonyms=("web camera", "web cam", "camera", "usb camera", "video camera"),
        tags=("video", "camera", "computer", "electronics", "call", "meeting", *OFFICE),
    ),
    define(
        "mouse pad",
        "mouse pad",
        mouse_pad,
        [
            V("black", "a black rectangular mouse pad", (0.22, 0.26, 0.003)),
            V("blue", "a blue mouse mat", (0.2, 0.24, 0.003), (P.BLUE,), synonyms=("mouse mat",)),
            V("round_grey", "a round grey mousepad", (0.22, 0.22, 0.003), (P.GREY,), {"round": True}),
            V("gaming_xl", "a large black gaming desk mat", (0.4, 0.9, 0.004), synonyms=("desk mat", "gaming mat")),
            V(
                "leather_desk_pad",
                "a brown leather desk pad",
                (0.45, 0.8, 0.003),
                (P.BROWN,),
                density=900.0,
                synonyms=("desk pad", "desk blotter", "desk mat"),
            ),
            V(
                "wrist_rest",
                "a purple mouse pad with a gel wrist rest",
                (0.23, 0.2, 0.022),
                (P.PURPLE, P.rgb(90, 50, 130)),
                {"wrist_rest": True},
                synonyms=("wrist rest",),
            ),
            V("pink", "a pink cloth mouse pad", (0.2, 0.24, 0.003), (P.PINK,)),
        ],
        density=350.0,
        mass_limits=(0.01, 2.0),
        friction=(0.7, 1.0),
        support_probability=0.95,
        has_front=False,
        synonyms=("mousepad", "mouse mat", "desk mat", "desk pad", "mouse pad"),
        tags=("computer", "mat", "pad", *OFFICE, "flat"),
    ),
    define(
        "bookend",
        "bookend",
        bookend,
        [
            V("black_metal", "a black metal bookend", (0.12, 0.13, 0.16)),
            V("silver_metal", "a silver steel bookend", (0.12, 0.13, 0.16), (P.SILVER,)),
            V("white_small", "a small white metal book end", (0.1, 0.1, 0.12), (P.WHITE,)),
            V("tall_black", "a tall black heavy duty bookend", (0.14, 0.16, 0.22), (P.BLACK,)),
            V(
                "wood_block",
                "a solid wooden block bookend",
                (0.1, 0.06, 0.15),
                (P.WOOD, P.LIGHT_WOOD),
                {"style": "block"},
                density=650.0,
            ),
            V(
                "marble_block",
                "a white marble bookend",
                (0.1, 0.06, 0.13),
                (P.rgb(230, 228, 222), P.GREY),
                {"style": "block"},
                density=2600.0,
            ),
            V(
                "walnut_block",
                "a dark walnut book end",
                (0.11, 0.07, 0.16),
                (P.DARK_BROWN, P.BROWN),
                {"style": "block"},
                density=650.0,
            ),
        ],
        density=7800.0,
        mass_limits=(0.1, 3.5),
        friction=(0.5, 0.8),
        support_probability=0.1,
        has_front=True,
        synonyms=("book end", "book holder", "book support", "book stopper"),
        tags=("books", "shelf", "row", "library", "study"),
    ),
    define(
        "globe",
        "desk globe",
        desk_globe,
        [
            V("blue_brass", "a blue world globe on a brass stand", (0.25, 0.25, 0.37)),
            V("small_blue", "a small desk globe", (0.16, 0.16, 0.24), (P.SKY, P.SILVER, P.BLACK)),
            V("antique", "an antique cream globe on a wooden base", (0.3, 0.3, 0.43), (P.CREAM, P.BRASS, P.DARK_BROWN)),
            V("black_political", "a black political globe of the world", (0.22, 0.22, 0.33), (P.NAVY, P.GOLD, P.BLACK)),
            V("green_kids", "a green children's globe", (0.2, 0.2, 0.3), (P.rgb(120, 190, 120), P.SILVER, P.BLUE)),
            V("large_floor", "a large world globe", (0.35, 0.35, 0.5), (P.SKY, P.BRASS, P.DARK_BROWN)),
            V("mini_teal", "a mini teal globe on a silver stand", (0.12, 0.12, 0.18), (P.TEAL, P.SILVER, P.GREY)),
        ],
        density=120.0,
        mass_limits=(0.05, 3.0),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=False,
        synonyms=("world globe", "desk globe", "earth globe", "globe of the world", "terrestrial globe"),
        tags=("geography", "world", "earth", "map", "study", "school", "classroom", "decor"),
    ),
    define(
        "pencil sharpener",
        "pencil sharpener",
        pencil_sharpener,
        [
            V("pocket_red", "a small red plastic pencil sharpener", (0.03, 0.018, 0.02)),
            V("pocket_blue", "a blue pocket sharpener", (0.03, 0.018, 0.02), (P.BLUE,)),
            V("metal_silver", "a silver metal pencil sharpener", (0.025, 0.015, 0.013), (P.SILVER,), density=2700.0),
            V("pocket_green", "a green pencil sharpener with a blade", (0.032, 0.02, 0.022), (P.GREEN,)),
            V(
                "crank_grey",
                "a grey hand crank desk pencil sharpener",
                (0.13, 0.07, 0.09),
                (P.GREY,),
                {"style": "crank"},
                density=500.0,
                synonyms=("crank sharpener", "desk sharpener"),
            ),
            V(
                "electric_black",
                "a black electric pencil sharpener",
                (0.13, 0.09, 0.1),
                (P.BLACK,),
                {"style": "electric"},
                density=450.0,
                synonyms=("electric sharpener",),
            ),
            V(
                "electric_white",
                "a white battery powered pencil sharpener",
                (0.11, 0.08, 0.09),
                (P.WHITE,),
                {"style": "electric"},
                density=450.0,
                synonyms=("electric sharpener",),
            ),
        ],
        density=1100.0,
        mass_limits=(0.003, 1.0),
        friction=(0.5, 0.8),
        support_probability=0.05,
        has_front=True,
        synonyms=("sharpener", "pencil sharpner", "crayon sharpener"),
        tags=("pencil", "sharpen", "school", *OFFICE),
    ),
    define(
        "paper clip",
        "paper clip",
        paper_clip,
        [
            V("silver", "a silver metal paper clip", (0.033, 0.009, 0.003), density=4000.0),
            V("large_silver", "a large steel paperclip", (0.05, 0.013, 0.003), density=4000.0),
            V("red_coated", "a red plastic coated paper clip", (0.033, 0.009, 0.003), (P.RED,), density=3000.0),
            V("blue_coated", "a blue vinyl paperclip", (0.033, 0.009, 0.003), (P.BLUE,), density=3000.0),
            V(
                "binder_black",
                "a black binder clip with silver handles",
                (0.025, 0.032, 0.03),
                density=1500.0,
                options={"binder": True},
                synonyms=("binder clip", "bulldog clip", "foldback clip"),
            ),
            V(
                "binder_large",
                "a large black bulldog clip",
                (0.04, 0.05, 0.045),
                density=1500.0,
                options={"binder": True},
                synonyms=("binder clip", "bulldog clip"),
            ),
            V(
                "binder_pink_small",
                "a small pink binder clip",
                (0.015, 0.019, 0.018),
                (P.PINK,),
                {"binder": True},
                density=1500.0,
                synonyms=("binder clip",),
            ),
        ],
        density=7800.0,
        mass_limits=(0.0003, 0.05),
        friction=(0.3, 0.6),
        support_probability=0.0,
        has_front=False,
        synonyms=("paperclip", "clip", "binder clip", "bulldog clip", "paper fastener"),
        tags=("clip", "paper", "wire", "fastener", *OFFICE),
    ),
    define(
        "magnifying glass",
        "magnifying glass",
        magnifying_glass,
        [
            V("brown", "a magnifying glass with a brown wooden handle", (0.24, 0.09, 0.022)),
            V("black", "a black handled magnifier", (0.22, 0.08, 0.02), (P.BLACK, P.BLACK)),
            V("large_silver", "a large reading magnifier with a silver rim", (0.28, 0.11, 0.024), (P.BLACK, P.SILVER)),
            V("small_red", "a small red kids magnifying glass", (0.15, 0.06, 0.018), (P.RED, P.RED)),
            V("brass", "an antique brass magnifying glass", (0.23, 0.08, 0.02), (P.DARK_BROWN, P.BRASS)),
            V("blue", "a blue plastic magnifier lens", (0.18, 0.07, 0.02), (P.BLUE, P.BLUE)),
            V("gold", "a gold rimmed loupe with a black handle", (0.16, 0.06, 0.016), (P.BLACK, P.GOLD)),
        ],
        density=900.0,
        mass_limits=(0.02, 0.5),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=True,
        synonyms=("magnifier", "magnifying lens", "hand lens", "loupe", "reading glass", "magnifying glasses"),
        tags=("lens", "reading", "zoom", "detective", "study", "desk"),
    ),
    define(
        "hourglass",
        "hourglass",
        hourglass,
        [
            V("wood", "a wooden hourglass with golden sand", (0.08, 0.08, 0.16)),
            V("dark_wood", "a dark wood sand timer", (0.07, 0.07, 0.14), (P.DARK_BROWN, P.rgb(235, 225, 200))),
            V("small_white", "a small white sand timer", (0.05, 0.05, 0.1), (P.WHITE, P.PINK)),
            V(
                "large_brass",
                "a large brass hourglass",
                (0.1, 0.1, 0.22),
                (P.BRASS, P.rgb(230, 200, 140)),
                density=1500.0,
            ),
            V("black_blue", "a black hourglass with blue sand", (0.07, 0.07, 0.15), (P.BLACK, P.SKY)),
            V("bamboo", "a bamboo egg timer hourglass", (0.05, 0.05, 0.09), (P.BAMBOO, P.rgb(240, 220, 170))),
            V("red_green", "a red sand timer with green sand", (0.06, 0.06, 0.12), (P.RED, P.LIME)),
        ],
        density=900.0,
        mass_limits=(0.03, 1.5),
        friction=(0.5, 0.8),
        support_probability=0.1,
        has_front=False,
        synonyms=("sand timer", "sand clock", "egg timer", "sandglass", "timer"),
        tags=("time", "sand", "glass", "decor", "desk", "study"),
    ),
    define(
        "desk bell",
        "desk bell",
        desk_bell,
        [
            V("silver", "a silver service bell on a black base", (0.085, 0.085, 0.065)),
            V("gold", "a gold reception bell", (0.085, 0.085, 0.065), (P.GOLD, P.BLACK)),
            V("small_silver", "a small chrome call bell", (0.065, 0.065, 0.05), (P.SILVER, P.CHARCOAL)),
            V("red_base", "a service bell on a red base", (0.085, 0.085, 0.065), (P.SILVER, P.RED)),
            V("wood_base", "a brass bell on a wooden base", (0.09, 0.09, 0.07), (P.BRASS, P.WOOD)),
            V("large", "a large hotel counter bell", (0.1, 0.1, 0.08), (P.SILVER, P.BLACK)),
            V("blue", "a blue school desk bell", (0.08, 0.08, 0.06), (P.SKY, P.BLUE)),
        ],
        density=1400.0,
        mass_limits=(0.05, 1.0),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=False,
        synonyms=("service bell", "call bell", "reception bell", "counter bell", "bell", "hotel bell"),
        tags=("bell", "ring", "reception", "counter", "desk", "office"),
    ),
    define(
        "fan",
        "desk fan",
        desk_fan,
        [
            V("white", "a small white desk fan", (0.14, 0.22, 0.3)),
            V("black", "a black personal fan", (0.13, 0.2, 0.28), (P.BLACK, P.CHARCOAL)),
            V(
                "mini_blue",
                "a mini blue usb fan",
                (0.08, 0.12, 0.17),
                (P.BLUE, P.WHITE),
                synonyms=("usb fan", "mini fan"),
            ),
            V("large_grey", "a large grey table fan", (0.2, 0.32, 0.42), (P.GREY, P.CHARCOAL), synonyms=("table fan",)),
            V("retro_green", "a retro mint green desk fan", (0.16, 0.25, 0.34), (P.rgb(160, 215, 190), P.SILVER)),
            V("silver", "a chrome silver desk fan", (0.15, 0.25, 0.33), (P.SILVER, P.STEEL), density=500.0),
            V("pink", "a small pink fan", (0.1, 0.15, 0.2), (P.PINK, P.WHITE)),
        ],
        density=300.0,
        mass_limits=(0.1, 4.0),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        prefix="desk_fan",
        synonyms=("desk fan", "table fan", "electric fan", "personal fan", "cooling fan"),
        tags=("fan", "air", "cooling", "electric", "desk", "office", "summer"),
    ),
    define(
        "printer",
        "printer",
        printer,
        [
            V("inkjet_black", "a black inkjet printer", (0.3, 0.44, 0.2)),
            V("inkjet_white", "a white home printer", (0.3, 0.42, 0.19), (P.WHITE, P.GREY)),
            V(
                "all_in_one",
                "a grey all-in-one printer with a scanner",
                (0.36, 0.45, 0.24),
                (P.GREY, P.CHARCOAL),
                {"scanner": True},
                synonyms=("all-in-one printer", "scanner", "copier"),
            ),
            V(
                "laser_white",
                "a white laser printer",
                (0.38, 0.4, 0.25),
                (P.WHITE, P.CHARCOAL),
                {"feed": False},
                density=250.0,
                synonyms=("laser printer",),
            ),
            V(
                "laser_black",
                "a black office laser printer",
                (0.4, 0.42, 0.3),
                (P.BLACK, P.GREY),
                {"feed": False},
                density=250.0,
                synonyms=("laser printer", "office printer"),
            ),
            V(
                "compact_blue",
                "a compact blue photo printer",
                (0.2, 0.3, 0.14),
                (P.NAVY, P.GREY),
                synonyms=("photo printer",),
            ),
            V(
                "scanner_flat",
                "a flat black document scanner",
                (0.3, 0.45, 0.08),
                (P.BLACK, P.GREY),
                {"feed": False, "scanner": True},
                synonyms=("scanner", "flatbed scanner"),
            ),
        ],
        density=300.0,
        mass_limits=(1.0, 15.0),
        friction=(0.5, 0.8),
        support_probability=0.6,
        has_front=True,
        synonyms=("inkjet printer", "laser printer", "home printer", "office printer", "printing machine"),
        tags=("print", "printing", "paper", "computer", "electronics", *OFFICE),
    ),
    define(
        "laptop stand",
        "laptop stand",
        laptop_stand,
        [
            V("aluminium", "a silver aluminium laptop stand", (0.24, 0.26, 0.15)),
            V("black", "a black laptop riser", (0.22, 0.25, 0.12), (P.BLACK,)),
            V("wood", "a wooden laptop stand", (0.24, 0.28, 0.14), (P.WOOD,), {"board": 0.012}, density=700.0),
            V(
                "riser_wood",
                "a wooden monitor riser shelf",
                (0.22, 0.55, 0.1),
                (P.LIGHT_WOOD,),
                {"splayed": False, "board": 0.015},
                density=700.0,
                synonyms=("monitor riser", "monitor stand", "desk shelf"),
            ),
            V(
                "riser_black",
                "a black metal monitor stand",
                (0.23, 0.5, 0.1),
                (P.BLACK,),
                {"splayed": False},
                synonyms=("monitor stand", "screen riser"),
            ),
            V(
                "riser_bamboo",
                "a bamboo desk riser for a screen",
                (0.2, 0.45, 0.09),
                (P.BAMBOO,),
                {"splayed": False, "board": 0.012},
                density=700.0,
                synonyms=("monitor riser",),
            ),
            V("white", "a white laptop holder", (0.22, 0.25, 0.13), (P.WHITE,), density=1200.0),
        ],
        density=2700.0,
        mass_limits=(0.2, 4.0),
        friction=(0.6, 0.9),
        support_probability=0.95,
        has_front=True,
        synonyms=("laptop riser", "laptop holder", "monitor stand", "monitor riser", "notebook stand"),
        tags=("stand", "riser", "computer", "ergonomic", *OFFICE),
    ),
    define(
        "magazine file",
        "magazine file",
        magazine_file,
        [
            V("white", "a white magazine file box", (0.25, 0.08, 0.3)),
            V("black", "a black magazine holder", (0.25, 0.08, 0.3), (P.BLACK, P.WHITE)),
            V(
                "cardboard",
                "a brown cardboard magazine file",
                (0.24, 0.08, 0.31),
                (P.CARDBOARD, P.WHITE),
                density=500.0,
            ),
            V("blue", "a blue plastic file holder", (0.24, 0.075, 0.3), (P.BLUE, P.WHITE), synonyms=("file holder",)),
            V("wood", "a wooden magazine rack for the desk", (0.25, 0.1, 0.3), (P.WOOD, P.LIGHT_WOOD), density=650.0),
            V(
                "grey_wide",
                "a wide grey document holder",
                (0.26, 0.11, 0.29),
                (P.GREY, P.WHITE),
                synonyms=("document holder",),
            ),
            V("pink_small", "a small pink folder holder", (0.2, 0.07, 0.24), (P.PINK, P.WHITE)),
        ],
        density=1000.0,
        mass_limits=(0.05, 1.5),
        friction=(0.4, 0.7),
        support_probability=0.2,
        has_front=True,
        synonyms=("magazine holder", "magazine box", "file holder", "file box", "magazine rack", "document holder"),
        tags=("container", "files", "documents", "magazines", "filing", "storage", *OFFICE),
    ),
    define(
        "backpack",
        "backpack",
        backpack,
        [
            V("navy", "a navy school backpack", (0.2, 0.3, 0.42)),
            V("black", "a black laptop backpack", (0.2, 0.31, 0.45), (P.BLACK, P.CHARCOAL), synonyms=("laptop bag",)),
            V("red", "a red rucksack", (0.2, 0.3, 0.42), (P.RED, P.DARK_RED), synonyms=("rucksack",)),
            V("pink_kids", "a small pink kids backpack", (0.14, 0.24, 0.3), (P.PINK, P.PURPLE)),
            V(
                "green_hiking",
                "a green hiking daypack",
                (0.22, 0.3, 0.48),
                (P.DARK_GREEN, P.GREEN),
                synonyms=("daypack",),
            ),
            V("grey", "a grey canvas backpack", (0.18, 0.29, 0.4), (P.GREY, P.CHARCOAL)),
            V(
                "yellow",
                "a yellow school bag",
                (0.18, 0.28, 0.38),
                (P.YELLOW, P.ORANGE),
                synonyms=("school bag", "satchel"),
            ),
        ],
        density=60.0,
        mass_limits=(0.2, 3.0),
        friction=(0.6, 0.9),
        support_probability=0.1,
        has_front=True,
        synonyms=("rucksack", "school bag", "schoolbag", "book bag", "knapsack", "bag", "daypack"),
        tags=("school", "student", "travel", "bag", "carry", "study"),
    ),
    define(
        "game controller",
        "game controller",
        game_controller,
        [
            V("black", "a black wireless game controller", (0.105, 0.155, 0.06)),
            V("white", "a white video game controller", (0.105, 0.155, 0.06), (P.WHITE, P.BLACK)),
            V("red", "a red gamepad", (0.1, 0.15, 0.055), (P.RED, P.BLACK)),
            V("blue", "a blue console controller", (0.1, 0.15, 0.055), (P.BLUE, P.BLACK)),
            V("grey_small", "a small grey retro joypad", (0.07, 0.14, 0.035), (P.GREY, P.CHARCOAL)),
            V("green", "a green xbox style controller", (0.11, 0.155, 0.06), (P.DARK_GREEN, P.BLACK)),
            V("purple", "a purple wireless gamepad", (0.1, 0.15, 0.055), (P.PURPLE, P.BLACK)),
        ],
        density=450.0,
        mass_limits=(0.05, 0.45),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        synonyms=(
            "gamepad",
            "joypad",
            "joystick",
            "video game controller",
            "console controller",
            "xbox controller",
            "ps5 controller",
        ),
        tags=("game", "gaming", "video game", "console", "play", "electronics", "living room"),
    ),
    define(
        "power bank",
        "power bank",
        power_bank,
        [
            V("black", "a black portable power bank", (0.14, 0.07, 0.015)),
            V("white", "a white battery pack", (0.13, 0.065, 0.014), (P.WHITE, P.SKY)),
            V(
                "silver_slim",
                "a slim silver portable charger",
                (0.14, 0.07, 0.01),
                (P.SILVER, P.BLUE),
                synonyms=("portable charger",),
            ),
            V("blue_large", "a large blue power bank", (0.16, 0.08, 0.022), (P.BLUE, P.WHITE)),
            V("pink_mini", "a small pink power bank", (0.09, 0.045, 0.02), (P.PINK, P.WHITE)),
            V(
                "charger_white",
                "a white usb wall charger plug",
                (0.03, 0.035, 0.035),
                (P.WHITE, P.GREEN),
                {"cube": True},
                density=1200.0,
                synonyms=("phone charger", "wall charger", "charging plug", "usb plug"),
            ),
            V(
                "charger_black",
                "a black laptop charger brick",
                (0.11, 0.055, 0.03),
                (P.BLACK, P.GREEN),
                {"cube": True},
                density=1200.0,
                synonyms=("laptop charger", "power adapter", "power brick"),
            ),
        ],
        density=1700.0,
        mass_limits=(0.03, 0.6),
        friction=(0.4, 0.7),
        support_probability=0.3,
        has_front=True,
        synonyms=(
            "portable charger",
            "battery pack",
            "phone charger",
            "portable battery",
            "powerbank",
            "power adapter",
        ),
        tags=("battery", "charging", "phone", "usb", "electronics", "travel"),
    ),
    define(
        "usb drive",
        "usb flash drive",
        usb_drive,
        [
            V("black", "a black usb flash drive", (0.055, 0.02, 0.009)),
            V("red", "a red usb stick", (0.055, 0.02, 0.009), (P.RED,)),
            V("blue", "a blue thumb drive", (0.05, 0.018, 0.008), (P.BLUE,)),
            V("silver_metal", "a small silver metal flash drive", (0.04, 0.014, 0.006), (P.SILVER,), density=3000.0),
            V("white", "a white memory stick", (0.06, 0.02, 0.01), (P.WHITE,)),
            V("green", "a green usb key", (0.055, 0.02, 0.009), (P.GREEN,)),
            V(
                "large_grey",
                "a chunky grey external ssd drive",
                (0.1, 0.055, 0.011),
                (P.GREY,),
                synonyms=("external drive", "ssd", "hard drive"),
            ),
        ],
        density=1400.0,
        mass_limits=(0.003, 0.2),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=True,
        prefix="usb_drive",
        synonyms=("flash drive", "usb stick", "thumb drive", "memory stick", "pen drive", "usb key", "usb flash drive"),
        tags=("usb", "storage", "data", "computer", "electronics", *OFFICE),
    ),
    define(
        "phone stand",
        "phone stand",
        phone_stand,
        [
            V("silver", "a silver aluminium phone stand", (0.08, 0.07, 0.1)),
            V("black", "a black desk phone holder", (0.08, 0.07, 0.1), (P.BLACK,)),
            V("wood", "a wooden phone stand", (0.09, 0.08, 0.11), (P.WOOD,), density=700.0),
            V("white", "a white plastic phone dock", (0.075, 0.065, 0.09), (P.WHITE,), density=1200.0),
            V(
                "tablet_grey",
                "a grey tablet stand",
                (0.12, 0.14, 0.15),
                (P.GREY,),
                synonyms=("tablet stand", "tablet holder"),
            ),
            V("pink", "a pink phone holder for the desk", (0.07, 0.06, 0.09), (P.PINK,), density=1200.0),
            V("bamboo", "a bamboo stand for a phone", (0.09, 0.08, 0.11), (P.BAMBOO,), density=700.0),
        ],
        density=2700.0,
        mass_limits=(0.02, 1.0),
        friction=(0.6, 0.9),
        support_probability=0.0,
        has_front=True,
        synonyms=("phone holder", "phone dock", "cell phone stand", "smartphone stand", "tablet stand", "mobile stand"),
        tags=("phone", "holder", "stand", "desk", "office"),
    ),
    define(
        "stamp",
        "rubber stamp",
        rubber_stamp,
        [
            V("wood", "a wooden rubber stamp", (0.05, 0.03, 0.065)),
            V("large_wood", "a large wooden office stamp", (0.07, 0.045, 0.075)),
            V("red_knob", "a rubber stamp with a red handle", (0.05, 0.03, 0.065), (P.CHARCOAL, P.BLACK, P.RED)),
            V(
                "black",
                "a black date stamp",
                (0.06, 0.035, 0.07),
                (P.BLACK, P.BLACK, P.CHARCOAL),
                synonyms=("date stamp",),
            ),
            V("small", "a small craft stamp", (0.03, 0.03, 0.05), (P.LIGHT_WOOD, P.BLUE)),
            V("blue", "a blue ink stamp", (0.05, 0.03, 0.065), (P.BLUE, P.BLUE, P.SKY)),
            V(
                "round_top",
                "a dark wood seal stamp",
                (0.04, 0.04, 0.07),
                (P.DARK_BROWN, P.RED),
                synonyms=("seal", "wax seal"),
            ),
        ],
        density=650.0,
        mass_limits=(0.01, 0.3),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=False,
        prefix="stamp",
        synonyms=("rubber stamp", "ink stamp", "office stamp", "hand stamp"),
        tags=("ink", "stamping", "office", "desk", "craft"),
    ),
    define(
        "index cards",
        "index cards",
        paper,
        [
            V("white_3x5", "a stack of white lined index cards", (0.127, 0.076, 0.01), options={"lined": True}),
            V("white_4x6", "a pile of large white note cards", (0.152, 0.102, 0.012), options={"lined": True}),
            V(
                "yellow",
                "a stack of yellow index cards",
                (0.127, 0.076, 0.008),
                (P.rgb(250, 230, 130), P.rgb(200, 150, 60)),
                {"lined": True},
            ),
            V("pink", "a few pink revision cards", (0.127, 0.076, 0.004), (P.PINK, P.RED), {"lined": True}),
            V(
                "blue",
                "a stack of blue flash cards",
                (0.127, 0.076, 0.012),
                (P.SKY, P.NAVY),
                synonyms=("flash cards", "flashcards"),
            ),
            V(
                "mixed_green",
                "a deck of green study cards",
                (0.1, 0.07, 0.015),
                (P.LIME, P.DARK_GREEN),
                synonyms=("study cards",),
            ),
            V(
                "recipe",
                "a stack of recipe cards",
                (0.152, 0.102, 0.01),
                (P.CREAM, P.BROWN),
                {"lined": True},
                synonyms=("recipe cards",),
            ),
        ],
        density=700.0,
        mass_limits=(0.005, 0.4),
        friction=(0.4, 0.7),
        support_probability=0.8,
        has_front=False,
        prefix="index_cards",
        synonyms=(
            "index card",
            "note cards",
            "flash cards",
            "flashcards",
            "cue cards",
            "revision cards",
            "record cards",
        ),
        tags=("cards", "notes", "study", "revision", "school", "paper", "flat"),
    ),
    define(
        "whiteboard",
        "desk whiteboard",
        picture_frame,
        [
            V("white_small", "a small desktop whiteboard on a stand", (0.1, 0.35, 0.25), (P.SILVER, P.WHITE, P.WHITE)),
            V(
                "white_large",
                "a large whiteboard with an aluminium frame",
                (0.14, 0.6, 0.4),
                (P.SILVER, P.WHITE, P.WHITE),
            ),
            V(
                "white_black_frame",
                "a white dry erase board with a black frame",
                (0.1, 0.4, 0.28),
                (P.BLACK, P.WHITE, P.WHITE),
                synonyms=("dry erase board",),
            ),
            V(
                "chalkboard",
                "a small chalkboard with a wooden frame",
                (0.1, 0.35, 0.25),
                (P.WOOD, P.rgb(40, 50, 45), P.rgb(40, 50, 45)),
                density=700.0,
                synonyms=("chalkboard", "blackboard", "chalk board"),
            ),
            V(
                "chalk_easel",
                "a standing black chalk sign",
                (0.12, 0.3, 0.35),
                (P.DARK_BROWN, P.BLACK, P.BLACK),
                density=700.0,
                synonyms=("chalkboard", "blackboard", "chalk sign"),
            ),
            V(
                "corkboard",
                "a cork pin board on a stand",
                (0.1, 0.4, 0.3),
                (P.WOOD, P.rgb(190, 150, 100), P.rgb(190, 150, 100)),
                density=500.0,
                synonyms=("cork board", "corkboard", "pin board", "bulletin board", "notice board"),
            ),
            V(
                "glass_board",
                "a frosted glass dry erase board",
                (0.1, 0.35, 0.22),
                (P.rgb(220, 235, 240), P.rgb(230, 240, 245), P.rgb(230, 240, 245)),
                {"border": 0.03},
                density=2500.0,
                synonyms=("glass board",),
            ),
        ],
        density=900.0,
        mass_limits=(0.1, 5.0),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        prefix="whiteboard",
        synonyms=(
            "white board",
            "dry erase board",
            "marker board",
            "chalkboard",
            "blackboard",
            "memo board",
            "message board",
        ),
        tags=("board", "writing", "notes", "marker", "classroom", "office", "school", "study"),
    ),
    define(
        "name plate",
        "desk name plate",
        desk_calendar,
        [
            V(
                "black_gold",
                "a black desk name plate with gold letters",
                (0.04, 0.2, 0.05),
                (P.BLACK, P.GOLD),
                {"binding": False},
            ),
            V(
                "wood",
                "a wooden nameplate for the desk",
                (0.045, 0.22, 0.055),
                (P.WOOD, P.DARK_BROWN),
                {"binding": False},
            ),
            V("silver", "a silver name sign", (0.04, 0.2, 0.05), (P.SILVER, P.BLACK), {"binding": False}),
            V(
                "white_card",
                "a folded white place card",
                (0.05, 0.1, 0.04),
                (P.WHITE, P.BLACK),
                {"binding": False},
                synonyms=("place card", "table card", "tent card"),
            ),
            V(
                "clear",
                "a clear acrylic name holder",
                (0.05, 0.2, 0.06),
                (P.rgb(215, 230, 240, 0.6), P.WHITE),
                {"binding": False},
            ),
            V(
                "brass",
                "a brass executive name plate",
                (0.045, 0.25, 0.055),
                (P.DARK_BROWN, P.BRASS),
                {"binding": False},
            ),
            V(
                "table_number",
                "a white table number card",
                (0.05, 0.1, 0.07),
                (P.WHITE, P.NAVY),
                {"binding": False},
                synonyms=("table number", "tent card"),
            ),
        ],
        density=600.0,
        mass_limits=(0.005, 1.0),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        prefix="name_plate",
        synonyms=("nameplate", "name sign", "name tag", "desk sign", "name card", "place card", "tent card"),
        tags=("name", "sign", "label", "office", "desk", "reception"),
    ),
    define(
        "cable",
        "charging cable",
        cable,
        [
            V("white_usb", "a coiled white usb charging cable", (0.16, 0.12, 0.008)),
            V("black_usb", "a black usb cable rolled up", (0.15, 0.12, 0.008), (P.BLACK,)),
            V(
                "long_white",
                "a long white phone charging cord in loose loops",
                (0.22, 0.16, 0.008),
                options={"turns": 4.0},
            ),
            V("red_braided", "a red braided charging cable", (0.14, 0.11, 0.008), (P.RED, P.BLACK)),
            V(
                "laptop_brick",
                "a black laptop power cord with its charger brick",
                (0.22, 0.16, 0.03),
                (P.BLACK,),
                {"brick": True, "turns": 2.5},
                density=1200.0,
                synonyms=("power cord", "laptop charger"),
            ),
            V(
                "grey_hdmi",
                "a grey hdmi cable coiled up",
                (0.18, 0.14, 0.009),
                (P.GREY, P.BLACK),
                synonyms=("hdmi cable",),
            ),
            V(
                "blue_ethernet",
                "a blue ethernet network cable",
                (0.2, 0.15, 0.008),
                (P.BLUE,),
                {"turns": 3.5},
                synonyms=("ethernet cable", "network cable"),
            ),
        ],
        density=1400.0,
        mass_limits=(0.01, 0.6),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=False,
        prefix="cable",
        synonyms=("charging cable", "charger cable", "usb cable", "cord", "wire", "charging cord", "lead", "cables"),
        tags=("charging", "wire", "usb", "electronics", "desk", "messy", "flat"),
    ),
    define(
        "earbuds",
        "earbuds case",
        earbuds,
        [
            V("white", "a white wireless earbuds charging case", (0.022, 0.046, 0.054)),
            V("black", "a black earbuds case", (0.03, 0.06, 0.03), (P.BLACK, P.CHARCOAL), {"upright": False}),
            V(
                "white_flat",
                "a white earphone case lying flat",
                (0.05, 0.062, 0.025),
                (P.WHITE, P.GREY),
                {"upright": False},
            ),
            V("grey", "a grey case for wireless earphones", (0.025, 0.05, 0.05), (P.GREY, P.CHARCOAL)),
            V("blue", "a blue earbud case", (0.04, 0.055, 0.028), (P.BLUE, P.NAVY), {"upright": False}),
            V("pink", "a pink case of bluetooth earbuds", (0.025, 0.048, 0.052), (P.PINK, P.WHITE)),
            V(
                "green",
                "a green charging case for in-ear headphones",
                (0.035, 0.06, 0.03),
                (P.GREEN, P.DARK_GREEN),
                {"upright": False},
            ),
        ],
        density=900.0,
        mass_limits=(0.02, 0.15),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=True,
        synonyms=(
            "earbuds",
            "earphones",
            "earbud case",
            "airpods",
            "wireless earbuds",
            "in-ear headphones",
            "earphone case",
        ),
        tags=("audio", "music", "wireless", "bluetooth", "electronics", "charging"),
    ),
    define(
        "drawer unit",
        "desk drawer unit",
        drawer_unit,
        [
            V(
                "white_three",
                "a white three drawer desktop storage unit",
                (0.3, 0.25, 0.25),
                (P.WHITE, P.WHITE, P.GREY),
            ),
            V(
                "black_mesh",
                "a black metal mini drawer set",
                (0.28, 0.2, 0.22),
                (P.BLACK, P.CHARCOAL, P.SILVER),
                {"drawers": 2},
                density=500.0,
            ),
            V(
                "wood_knobs",
                "a small wooden chest of drawers with knobs",
                (0.25, 0.3, 0.3),
                (P.WOOD, P.LIGHT_WOOD, P.DARK_BROWN),
                {"drawers": 4, "handle": "knob"},
                density=350.0,
            ),
            V(
                "clear_plastic",
                "a clear plastic drawer organiser tower",
                (0.35, 0.26, 0.3),
                (P.rgb(215, 230, 240), P.rgb(200, 220, 235), P.WHITE),
                {"drawers": 3, "handle": "slot"},
            ),
            V(
                "pastel",
                "a pink desk drawer cabinet",
                (0.25, 0.2, 0.2),
                (P.PINK, P.WHITE, P.WHITE),
                {"drawers": 3, "handle": "slot"},
            ),
            V(
                "bamboo",
                "a bamboo desktop drawer box",
                (0.2, 0.28, 0.15),
                (P.BAMBOO, P.LIGHT_WOOD, P.DARK_BROWN),
                {"drawers": 2, "handle": "knob"},
                density=350.0,
            ),
            V(
                "grey_five",
                "a grey five drawer paper storage unit",
                (0.34, 0.27, 0.32),
                (P.GREY, P.rgb(180, 180, 185), P.CHARCOAL),
                {"drawers": 5},
            ),
        ],
        density=250.0,
        mass_limits=(0.5, 8.0),
        friction=(0.5, 0.8),
        support_probability=0.6,
        has_front=True,
        synonyms=(
            "drawer set",
            "mini drawers",
            "storage drawers",
            "desk drawers",
            "chest of drawers",
            "drawer cabinet",
            "drawers",
        ),
        tags=("storage", "drawers", "organising", "office", "desk", "bedroom"),
    ),
    define(
        "filing cabinet",
        "filing cabinet",
        drawer_unit,
        [
            V(
                "grey_two",
                "a grey metal two drawer filing cabinet",
                (0.6, 0.47, 0.72),
                (P.GREY, P.rgb(170, 172, 176), P.SILVER),
                {"drawers": 2},
            ),
            V(
                "grey_four",
                "a tall grey four drawer file cabinet",
                (0.62, 0.47, 1.32),
                (P.GREY, P.rgb(170, 172, 176), P.SILVER),
                {"drawers": 4},
            ),
            V(
                "black_three",
                "a black three drawer filing cabinet",
                (0.6, 0.4, 1.0),
                (P.BLACK, P.CHARCOAL, P.SILVER),
                {"drawers": 3},
            ),
            V(
                "white_mobile",
                "a small white mobile pedestal with three drawers",
                (0.5, 0.4, 0.6),
                (P.WHITE, P.WHITE, P.GREY),
                {"drawers": 3},
                synonyms=("pedestal", "under desk drawers"),
            ),
            V(
                "wood_two",
                "a wooden two drawer file cabinet",
                (0.55, 0.45, 0.75),
                (P.WOOD, P.LIGHT_WOOD, P.BRASS),
                {"drawers": 2, "handle": "knob"},
                density=300.0,
            ),
            V(
                "blue_lateral",
                "a blue lateral filing cabinet",
                (0.45, 0.8, 0.72),
                (P.NAVY, P.BLUE, P.SILVER),
                {"drawers": 2},
            ),
            V(
                "beige_three",
                "a beige office file cabinet",
                (0.6, 0.45, 1.0),
                (P.rgb(225, 215, 190), P.rgb(215, 205, 180), P.SILVER),
                {"drawers": 3},
            ),
        ],
        density=150.0,
        mass_limits=(10.0, 60.0),
        friction=(0.5, 0.8),
        support_probability=0.8,
        has_front=True,
        synonyms=("file cabinet", "filing drawers", "file drawer", "office cabinet", "pedestal", "document cabinet"),
        tags=("storage", "files", "documents", "filing", "office", "furniture", "floor"),
    ),
    define(
        "trophy",
        "trophy",
        trophy,
        [
            V("gold_cup", "a gold trophy cup with two handles", (0.09, 0.16, 0.25)),
            V("silver_cup", "a silver trophy on a black base", (0.08, 0.14, 0.22), (P.SILVER, P.BLACK)),
            V("small_bronze", "a small bronze award cup", (0.06, 0.1, 0.15), (P.rgb(180, 110, 60), P.DARK_BROWN)),
            V("large_gold", "a large gold championship trophy", (0.12, 0.22, 0.38), (P.GOLD, P.DARK_BROWN)),
            V(
                "star_gold",
                "a gold star award on a column",
                (0.08, 0.08, 0.22),
                (P.GOLD, P.BLACK, P.BLUE),
                {"style": "star"},
            ),
            V(
                "star_silver",
                "a silver star trophy",
                (0.07, 0.07, 0.2),
                (P.SILVER, P.CHARCOAL, P.RED),
                {"style": "star"},
            ),
            V(
                "star_crystal",
                "a clear glass star award",
                (0.07, 0.07, 0.18),
                (P.GLASS, P.BLACK, P.GLASS),
                {"style": "star"},
                density=2500.0,
            ),
        ],
        density=1200.0,
        mass_limits=(0.1, 5.0),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        synonyms=("award", "cup trophy", "prize", "trophy cup", "medal trophy"),
        tags=("award", "prize", "winner", "sport", "shelf", "decor", "achievement"),
    ),
    define(
        "book stand",
        "book stand",
        phone_stand,
        [
            V("wood", "a wooden book stand for reading", (0.22, 0.3, 0.26), (P.WOOD,), density=650.0),
            V("bamboo", "a bamboo reading stand", (0.22, 0.32, 0.27), (P.BAMBOO,), density=650.0),
            V("black_metal", "a black metal book holder", (0.2, 0.28, 0.24), (P.BLACK,), density=1500.0),
            V(
                "cookbook",
                "a white cookbook stand",
                (0.2, 0.3, 0.25),
                (P.WHITE,),
                density=900.0,
                synonyms=("cookbook stand", "recipe book holder"),
            ),
            V(
                "acrylic",
                "a clear acrylic book display stand",
                (0.15, 0.2, 0.2),
                (P.rgb(215, 230, 240, 0.6),),
                density=1180.0,
                synonyms=("display stand",),
            ),
            V(
                "small_wood",
                "a small wooden plate stand",
                (0.12, 0.15, 0.15),
                (P.LIGHT_WOOD,),
                density=650.0,
                synonyms=("plate stand", "display easel"),
            ),
            V(
                "large_dark",
                "a large dark wood lectern stand",
                (0.3, 0.4, 0.32),
                (P.DARK_BROWN,),
                density=650.0,
                synonyms=("lectern",),
            ),
        ],
        density=900.0,
        mass_limits=(0.05, 4.0),
        friction=(0.6, 0.9),
        support_probability=0.0,
        has_front=True,
        synonyms=("reading stand", "book holder", "book rest", "bookstand", "document stand", "easel stand"),
        tags=("reading", "books", "stand", "study", "kitchen", "display"),
    ),
    define(
        "microscope",
        "microscope",
        microscope,
        [
            V("white", "a white student microscope", (0.16, 0.12, 0.32)),
            V("black", "a black lab microscope", (0.18, 0.13, 0.36), (P.BLACK, P.CHARCOAL)),
            V("grey", "a grey compound microscope", (0.17, 0.12, 0.34), (P.GREY, P.BLACK)),
            V("kids_blue", "a small blue toy microscope for kids", (0.1, 0.08, 0.2), (P.BLUE, P.WHITE), density=500.0),
            V("cream", "a cream coloured vintage microscope", (0.16, 0.11, 0.3), (P.CREAM, P.BRASS)),
            V("red_kids", "a red children's science microscope", (0.1, 0.08, 0.2), (P.RED, P.BLACK), density=500.0),
            V("large_white", "a large white laboratory microscope", (0.22, 0.16, 0.42), (P.WHITE, P.CHARCOAL)),
        ],
        density=1000.0,
        mass_limits=(0.2, 8.0),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        synonyms=("lab microscope", "science microscope", "compound microscope", "magnifier scope"),
        tags=("science", "lab", "laboratory", "biology", "study", "school", "lens"),
    ),
    define(
        "abacus",
        "abacus",
        abacus,
        [
            V("wood_rainbow", "a wooden abacus with rainbow beads", (0.08, 0.3, 0.25)),
            V("small", "a small counting frame", (0.06, 0.2, 0.18), options={"rods": 6}),
            V("large", "a large classroom abacus", (0.1, 0.4, 0.32), options={"rods": 10, "beads": 10}),
            V("red_beads", "a wooden abacus with red beads", (0.07, 0.26, 0.22), (P.WOOD, P.RED), {"rods": 7}),
            V("dark_wood", "a dark wooden bead counter", (0.08, 0.3, 0.25), (P.DARK_BROWN, P.GOLD)),
            V("white_frame", "a white frame abacus for kids", (0.08, 0.28, 0.24), (P.WHITE,), {"rods": 8}),
            V(
                "mini_blue",
                "a mini abacus with blue beads",
                (0.05, 0.15, 0.12),
                (P.LIGHT_WOOD, P.BLUE),
                {"rods": 5, "beads": 8},
            ),
        ],
        density=500.0,
        mass_limits=(0.03, 2.0),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        synonyms=("counting frame", "bead counter", "counting beads", "soroban"),
        tags=("math", "counting", "beads", "school", "kids", "study", "toy"),
    ),
    define(
        "floor lamp",
        "floor lamp",
        desk_lamp,
        [
            V(
                "drum_cream",
                "a tall floor lamp with a cream fabric drum shade",
                (0.45, 0.45, 1.6),
                (P.BLACK, P.CREAM),
                {"arm": False, "shade": "drum", "shade_height": 0.18, "base_height": 0.03},
            ),
            V(
                "cone_white",
                "a white standing lamp with a cone shade",
                (0.4, 0.4, 1.5),
                (P.WHITE, P.WHITE),
                {"arm": False, "shade": "cone", "shade_height": 0.16, "base_height": 0.03},
            ),
            V(
                "brass_drum",
                "a brass floor lamp with a white shade",
                (0.45, 0.45, 1.65),
                (P.BRASS, P.WHITE),
                {"arm": False, "shade": "drum", "shade_height": 0.17, "base_height": 0.03},
            ),
            V(
                "black_dome",
                "a black metal floor lamp with a dome shade",
                (0.35, 0.35, 1.5),
                (P.BLACK, P.BLACK),
                {"arm": False, "shade": "dome", "shade_height": 0.14, "base_height": 0.03},
            ),
            V(
                "silver_dome",
                "a silver reading floor lamp with a dome shade",
                (0.38, 0.38, 1.45),
                (P.SILVER, P.SILVER),
                {"arm": False, "shade": "dome", "shade_height": 0.13, "base_height": 0.03},
                synonyms=("reading floor lamp",),
            ),
            V(
                "wood_linen",
                "a wooden standing lamp with a linen shade",
                (0.42, 0.42, 1.55),
                (P.WOOD, P.rgb(225, 215, 195)),
                {"arm": False, "shade": "drum", "shade_height": 0.18, "base_height": 0.03},
            ),
            V(
                "grey_small",
                "a short grey floor lamp",
                (0.35, 0.35, 1.2),
                (P.GREY, P.WHITE),
                {"arm": False, "shade": "cone", "shade_height": 0.18, "base_height": 0.03},
            ),
        ],
        density=2200.0,
        mass_limits=(2.0, 20.0),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        synonyms=("standing lamp", "standard lamp", "floor light", "torchiere", "tall lamp"),
        tags=("light", "lighting", "shade", "living room", "bedroom", "floor", "corner"),
    ),
    define(
        "clipboard",
        "clipboard",
        clipboard,
        [
            V("wood", "a wooden clipboard holding a sheet of paper", (0.32, 0.23, 0.02)),
            V("black", "a black plastic clipboard", (0.32, 0.23, 0.02), (P.BLACK, P.SILVER), density=900.0),
            V("blue", "a blue clipboard with a form on it", (0.32, 0.23, 0.02), (P.BLUE, P.SILVER), density=900.0),
            V(
                "clear",
                "a clear acrylic clip board",
                (0.31, 0.22, 0.02),
                (P.rgb(215, 230, 240, 0.6), P.SILVER),
                density=1180.0,
            ),
            V("small_wood", "a small wooden memo clipboard", (0.23, 0.16, 0.018), (P.LIGHT_WOOD, P.SILVER)),
            V("silver_metal", "an aluminium clipboard", (0.32, 0.23, 0.02), (P.SILVER, P.STEEL), density=2700.0),
            V("pink", "a pink clipboard", (0.32, 0.23, 0.02), (P.PINK, P.SILVER), density=900.0),
        ],
        density=700.0,
        mass_limits=(0.05, 1.0),
        friction=(0.4, 0.7),
        support_probability=0.7,
        has_front=True,
        synonyms=("clip board", "writing board", "clipboard with paper"),
        tags=("paper", "forms", "writing", "clip", *OFFICE, "flat"),
    ),
    define(
        "paperweight",
        "paperweight",
        paperweight,
        [
            V("glass_blue", "a round glass paperweight with a blue swirl", (0.07, 0.07, 0.05)),
            V("glass_red", "a glass dome paperweight with a red flower", (0.075, 0.075, 0.055), (P.GLASS, P.RED)),
            V(
                "glass_green",
                "a small green glass paperweight",
                (0.06, 0.06, 0.045),
                (P.rgb(150, 210, 170, 0.6), P.GREEN),
            ),
            V("crystal_block", "a square crystal paperweight", (0.06, 0.06, 0.04), (P.GLASS, P.GOLD), {"dome": False}),
            V(
                "crystal_tall",
                "a faceted glass block paperweight",
                (0.05, 0.05, 0.06),
                (P.GLASS, P.SKY),
                {"dome": False},
            ),
            V("large_clear", "a large clear dome paperweight", (0.09, 0.09, 0.06), (P.GLASS, P.PURPLE)),
            V("amber", "an amber glass paperweight", (0.07, 0.07, 0.05), (P.AMBER_GLASS, P.GOLD)),
        ],
        density=2500.0,
        mass_limits=(0.05, 1.0),
        friction=(0.5, 0.8),
        support_probability=0.2,
        has_front=False,
        synonyms=("paper weight", "glass weight", "desk weight"),
        tags=("glass", "desk", "decor", "paper", "office", "study"),
    ),
    define(
        "microphone",
        "desk microphone",
        microphone,
        [
            V("black", "a black usb desk microphone on a round stand", (0.11, 0.11, 0.25)),
            V("silver", "a silver podcast microphone", (0.12, 0.12, 0.27), (P.SILVER, P.GREY, P.STEEL), density=1500.0),
            V("white", "a white streaming mic", (0.1, 0.1, 0.22), (P.WHITE, P.SILVER, P.GREY)),
            V("small_black", "a small black conference microphone", (0.08, 0.08, 0.15), (P.BLACK, P.CHARCOAL, P.GREY)),
            V("red", "a red gaming microphone", (0.11, 0.11, 0.24), (P.RED, P.BLACK, P.BLACK)),
            V(
                "vintage",
                "a vintage chrome desk microphone",
                (0.12, 0.12, 0.26),
                (P.STEEL, P.SILVER, P.CHARCOAL),
                density=1500.0,
            ),
            V("blue", "a blue usb condenser mic", (0.11, 0.11, 0.26), (P.NAVY, P.SILVER, P.CHARCOAL)),
        ],
        density=1100.0,
        mass_limits=(0.1, 2.0),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        prefix="microphone",
        synonyms=("mic", "desk mic", "usb microphone", "podcast microphone", "condenser microphone", "recording mic"),
        tags=("audio", "recording", "podcast", "streaming", "voice", "electronics", "desk"),
    ),
    define(
        "briefcase",
        "briefcase",
        briefcase,
        [
            V("black_leather", "a black leather briefcase", (0.1, 0.44, 0.36)),
            V(
                "brown_leather",
                "a brown leather attache case",
                (0.1, 0.43, 0.35),
                (P.BROWN, P.GOLD, P.DARK_BROWN),
                synonyms=("attache case",),
            ),
            V(
                "aluminium",
                "a silver aluminium briefcase",
                (0.11, 0.46, 0.36),
                (P.SILVER, P.STEEL, P.GREY),
                density=250.0,
            ),
            V(
                "tan",
                "a tan leather work bag",
                (0.12, 0.4, 0.33),
                (P.rgb(190, 140, 90), P.GOLD, P.BROWN),
                synonyms=("work bag",),
            ),
            V(
                "navy_laptop",
                "a navy laptop briefcase",
                (0.09, 0.42, 0.34),
                (P.NAVY, P.SILVER, P.NAVY),
                synonyms=("laptop case",),
            ),
            V(
                "black_slim",
                "a slim black document case",
                (0.07, 0.42, 0.32),
                (P.BLACK, P.SILVER, P.CHARCOAL),
                synonyms=("document case", "portfolio case"),
            ),
            V("burgundy", "a burgundy leather briefcase", (0.1, 0.42, 0.34), (P.DARK_RED, P.GOLD, P.DARK_RED)),
        ],
        density=150.0,
        mass_limits=(0.5, 5.0),
        friction=(0.5, 0.8),
        support_probability=0.1,
        has_front=True,
        synonyms=("attache case", "attache", "business case", "work bag", "document case", "laptop case"),
        tags=("office", "work", "business", "documents", "leather", "carry", "travel"),
    ),
    define(
        "ink pad",
        "ink pad",
        ink_pad,
        [
            V("black", "a black ink stamp pad", (0.11, 0.07, 0.02), (P.CHARCOAL, P.BLACK)),
            V("blue", "a blue ink pad in a metal tin", (0.11, 0.07, 0.02), (P.GREY, P.BLUE)),
            V("red", "a red stamp pad", (0.11, 0.07, 0.02), (P.CHARCOAL, P.RED)),
            V("small_purple", "a small purple ink pad", (0.07, 0.05, 0.018), (P.PURPLE, P.PURPLE)),
            V("large_black", "a large office stamp pad", (0.16, 0.09, 0.022), (P.BLACK, P.BLACK)),
            V("green_craft", "a green craft ink pad", (0.08, 0.08, 0.02), (P.GREEN, P.DARK_GREEN)),
            V("rainbow", "a rainbow coloured ink pad", (0.1, 0.06, 0.02), (P.WHITE, P.ORANGE)),
        ],
        density=900.0,
        mass_limits=(0.02, 0.4),
        friction=(0.5, 0.8),
        support_probability=0.3,
        has_front=False,
        synonyms=("stamp pad", "inkpad", "ink stamp pad", "stamping pad"),
        tags=("ink", "stamp", "stamping", "craft", "office", "desk"),
    ),
    define(
        "router",
        "wifi router",
        router,
        [
            V("black_two", "a black wifi router with two antennas", (0.13, 0.2, 0.17)),
            V("white_flat", "a white internet router", (0.14, 0.2, 0.035), (P.WHITE,), {"antennas": 0}, density=350.0),
            V(
                "black_four",
                "a black gaming router with four antennas",
                (0.16, 0.25, 0.19),
                (P.BLACK,),
                {"antennas": 4},
            ),
            V(
                "grey_modem",
                "a grey cable modem",
                (0.16, 0.17, 0.04),
                (P.GREY,),
                {"antennas": 0},
                density=350.0,
                synonyms=("modem",),
            ),
            V(
                "white_three",
                "a white wireless router with three aerials",
                (0.13, 0.22, 0.17),
                (P.WHITE,),
                {"antennas": 3},
            ),
            V(
                "small_black",
                "a small travel router",
                (0.07, 0.1, 0.025),
                (P.CHARCOAL,),
                {"antennas": 0},
                density=350.0,
            ),
            V("blue_two", "a blue dual band router", (0.12, 0.19, 0.16), (P.NAVY,)),
        ],
        density=350.0,
        mass_limits=(0.05, 2.0),
        friction=(0.5, 0.8),
        support_probability=0.1,
        has_front=True,
        prefix="router",
        synonyms=("wifi router", "wireless router", "modem", "internet router", "wi-fi router", "network router"),
        tags=("internet", "network", "wifi", "electronics", "home office"),
    ),
    define(
        "television",
        "television",
        monitor,
        [
            V(
                "black_43",
                "a black 43 inch flat screen television on its stand",
                (0.25, 0.97, 0.62),
                options={"screen_h": 0.88},
            ),
            V(
                "black_55",
                "a large black 55 inch smart tv",
                (0.27, 1.23, 0.77),
                options={"screen_h": 0.9},
                synonyms=("smart tv",),
            ),
            V("silver_32", "a silver 32 inch tv", (0.2, 0.73, 0.48), (P.SILVER,), {"screen_h": 0.88}),
            V("small_24", "a small 24 inch kitchen television", (0.16, 0.56, 0.37), options={"screen_h": 0.86}),
            V("white_40", "a white 40 inch television", (0.24, 0.91, 0.58), (P.WHITE,), {"screen_h": 0.88}),
            V("grey_50", "a dark grey 50 inch led tv", (0.26, 1.12, 0.7), (P.CHARCOAL,), {"screen_h": 0.9}),
            V("black_65", "a very large 65 inch black television", (0.3, 1.45, 0.9), options={"screen_h": 0.9}),
        ],
        density=700.0,
        mass_limits=(3.0, 30.0),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=True,
        prefix="television",
        synonyms=("tv", "telly", "flat screen tv", "flatscreen", "tv set", "television set", "smart tv", "led tv"),
        tags=("screen", "display", "entertainment", "living room", "electronics", "watching"),
    ),
)
