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
from physcensis.assets.model import RGBA, CollisionPart
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
    """An angled arm reaching forward (else a straight stem under the shade), the shade's form and width
    (a share of the lamp's width), and the weighted base's thickness (m)."""

    arm: bool = True
    shade: Literal["cone", "dome", "drum"] = "cone"
    shade_width: float = 0.8
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
    """A twist-up glue stick or a squeeze bottle of white glue."""

    style: Literal["stick", "bottle"] = "stick"


@builder(GlueShape)
def glue(v: Variant, p: GlueShape) -> Geometry:
    """A glue stick standing on its base (cap up) or a glue bottle with a nozzle; round, so it stands."""
    x, _, z = v.size
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
    """Printed rule lines on the top sheet, and a paper wrapper band around a ream."""

    lined: bool = False
    wrapped: bool = False


@builder(PaperShape)
def paper(v: Variant, p: PaperShape) -> Geometry:
    """A sheet or a stack of sheets lying flat; x is the sheet's long side (it reads from +x)."""
    x, y, z = v.size
    sheet = v.color(0, P.PAPER)
    line_h = min(0.0001, 0.1 * z)
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
                "a blue tape dispenser with a roll of beige masking tape",
                (0.15, 0.07, 0.085),
                (P.BLUE, P.rgb(225, 205, 160)),
                synonyms=("masking tape",),
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
        ],
        density=800.0,
        mass_limits=(0.01, 0.3),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        prefix="glue",
        synonyms=("glue stick", "gluestick", "glue", "adhesive", "paste", "pritt stick"),
        tags=("glue", "sticky", "craft", "school", *OFFICE),
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
                (0.32, 0.025, 0.0012),
                (P.STEEL,),
                density=7800.0,
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
                (0.08, 0.15, 0.002),
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
                (0.297, 0.21, 0.0005),
                density=160.0,
                synonyms=("sheet", "a4 sheet", "page"),
            ),
            V(
                "letter_sheet",
                "a single white letter size sheet of paper with printed text",
                (0.279, 0.216, 0.0005),
                density=160.0,
                synonyms=("sheet", "letter paper", "printout", "document"),
            ),
            V(
                "lined_sheet",
                "a sheet of lined writing paper",
                (0.28, 0.215, 0.0005),
                options={"lined": True},
                density=160.0,
                synonyms=("lined paper", "ruled paper", "writing paper", "loose leaf"),
            ),
            V(
                "yellow_sheet",
                "a sheet of yellow coloured paper",
                (0.297, 0.21, 0.0005),
                (P.rgb(250, 230, 120),),
                density=160.0,
                synonyms=("colored paper", "coloured paper", "construction paper"),
            ),
            V(
                "stack_small",
                "a small stack of white printer paper sheets",
                (0.297, 0.21, 0.006),
                synonyms=("stack of paper", "pile of paper", "papers", "paper stack", "printer paper"),
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
                synonyms=("ream", "ream of paper", "copy paper", "printer paper"),
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
        tags=("tv", "television", "buttons", "electronics", "living room", "sofa"),
    ),
)
