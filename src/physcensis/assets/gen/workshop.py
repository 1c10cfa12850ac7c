"""Kids' room and workshop: toys and games, hand and power tools, paint, tape and protective gear.

Most builders draw in convenient units and let `_fitted` centre, ground and scale the result to the variant's
size; their collision is one convex hull per rigid piece (point sets transformed with the visual).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

import numpy as np
import trimesh
from shapely import affinity
from shapely.geometry import LineString, Point, Polygon
from shapely.geometry import box as shapely_box

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.gen.common import Vessel, loop_handle, rectangle, resample, spout
from physcensis.assets.gen.variant_data import builtin_categories
from physcensis.assets.model import RGBA, Cavity
from physcensis.assets.spec import CategoryDef, Geometry, NoOptions, Variant, builder

RAINBOW = (P.RED, P.ORANGE, P.YELLOW, P.GREEN, P.TEAL, P.BLUE, P.PURPLE, P.PINK)


def _points(*meshes: trimesh.Trimesh) -> np.ndarray:
    return np.vstack([m.vertices for m in meshes])


def _fitted(
    parts: Sequence[tuple[trimesh.Trimesh, RGBA]], hulls: Sequence[np.ndarray], size: tuple[float, float, float]
) -> Geometry:
    """Scale the drawing to `size` with its footprint centred and its base at z = 0; one convex hull per point set."""
    lo = np.min([m.bounds[0] for m, _ in parts], axis=0)
    hi = np.max([m.bounds[1] for m, _ in parts], axis=0)
    scale = np.asarray(size, dtype=float) / (hi - lo)
    target = np.array([-size[0] / 2, -size[1] / 2, 0.0])

    def place(points: np.ndarray) -> np.ndarray:
        return (np.asarray(points, dtype=float) - lo) * scale + target

    placed = []
    for mesh, color in parts:
        moved = mesh.copy()
        moved.vertices = place(moved.vertices)
        placed.append((moved, color))
    return Geometry(tuple(placed), tuple(col.hull_part(place(h)) for h in hulls))


def _clip_below(mesh: trimesh.Trimesh, z: float) -> trimesh.Trimesh:
    """The part of a closed mesh above height `z` (a flat base where a round body meets the floor)."""
    lo, hi = mesh.bounds
    keep = shapes.box(hi - lo + 0.2, ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, z + (hi[2] - lo[2] + 0.2) / 2))
    return trimesh.boolean.intersection([mesh, keep], engine="manifold")


def _slab(polygon: Polygon, height: float, z0: float = 0.0) -> trimesh.Trimesh:
    return shapes.extrude(polygon, height, z0)


def _strip(points: Sequence[tuple[float, float]], width: float) -> Polygon:
    """A flat strip of `width` along a 2-D polyline, with round ends."""
    return LineString(points).buffer(width / 2, quad_segs=6)


# --------------------------------------------------------------------------------------------- kids' room


@dataclass(frozen=True)
class DuckShape:
    """The head's radius as a fraction of the body length."""

    head: float = 0.24


@builder(DuckShape)
def rubber_duck(v: Variant, p: DuckShape) -> Geometry:
    """A bath duck facing +x: flat-bottomed body, upturned tail, head with a beak and eyes."""
    body = _clip_below(shapes.ellipsoid((0.5, 0.37, 0.3), (0, 0, 0.26), 3), 0.03)
    tail = shapes.hull([[-0.52, 0, 0.5], [-0.3, 0.12, 0.3], [-0.3, -0.12, 0.3], [-0.25, 0, 0.45], [-0.3, 0, 0.2]])
    r = p.head
    head_c = np.array([0.2, 0.0, 0.52 + r * 0.7])
    head = shapes.sphere(r, head_c, 3)
    beak = shapes.ellipsoid((0.14, 0.1, 0.045), head_c + (r * 0.95, 0, -0.2 * r), 2)
    eyes = shapes.concatenate([shapes.sphere(0.035, head_c + (0.7 * r, s * 0.5 * r, 0.35 * r), 1) for s in (1, -1)])
    yellow = v.color(0, P.YELLOW)
    parts = [(body, yellow), (tail, yellow), (head, yellow), (beak, v.color(1, P.ORANGE)), (eyes, P.BLACK)]
    return _fitted(parts, [_points(body, tail), _points(head, beak)], v.size)


@dataclass(frozen=True)
class DieShape:
    """How round the edges are (fraction of the side) and whether the pips are drawn."""

    rounding: float = 0.15
    pips: bool = True


PIPS = {  # face value: pip positions in units of the pip spacing
    2: ((-1, -1), (1, 1)),
    3: ((-1, -1), (0, 0), (1, 1)),
    5: ((-1, -1), (1, 1), (-1, 1), (1, -1), (0, 0)),
}


def _pip_centres(value: int) -> list[tuple[float, float]]:
    return [(0.27 * a, 0.27 * b) for a, b in PIPS[value]]


@builder(DieShape)
def dice(v: Variant, p: DieShape) -> Geometry:
    """A cube with rounded edges and pips sunk into the top (5), front (3) and side (2) faces."""
    cube = shapes.rounded_box((1.0, 1.0, 1.0), p.rounding, (0, 0, 0.5))
    parts = [(cube, v.color(0, P.WHITE))]
    if p.pips:
        pip_r, sink = 0.075, 0.5 - 0.06
        spots = [shapes.sphere(pip_r, (a, b, 0.5 + sink), 1) for a, b in _pip_centres(5)]
        spots += [shapes.sphere(pip_r, (sink, a, 0.5 + b), 1) for a, b in _pip_centres(3)]
        spots += [shapes.sphere(pip_r, (a, -sink, 0.5 + b), 1) for a, b in _pip_centres(2)]
        parts.append((shapes.concatenate(spots), v.color(1, P.BLACK)))
    return _fitted(parts, [cube.vertices], v.size)


@dataclass(frozen=True)
class TopShape:
    """The flat base's radius and the handle stem's length, as fractions of the body radius / height."""

    base: float = 0.35
    stem: float = 0.3


@builder(TopShape)
def spinning_top(v: Variant, p: TopShape) -> Geometry:
    """A spinning top resting upright on a small flat foot: cone, wide shoulder, dome, stem knob."""
    h = 1.0
    stem_z = (1 - p.stem) * h
    body = shapes.lathe([(0, 0), (p.base, 0), (1.0, 0.38), (0.96, 0.48), (0.55, 0.6), (0.18, stem_z), (0, stem_z)], 48)
    stem = shapes.lathe([(0, stem_z - 0.02), (0.1, stem_z - 0.02), (0.1, h - 0.05), (0.07, h), (0, h)], 24)
    band = shapes.cylinder(1.005, 0.05, (0, 0, 0.41), sections=48)
    parts = [(body, v.color(0, P.RED)), (band, v.color(1, P.YELLOW)), (stem, v.color(2, P.WOOD))]
    return _fitted(parts, [_points(body, band, stem)], v.size)


@dataclass(frozen=True)
class BrickShape:
    """The number of studs on top along x and along y."""

    studs_x: int = 4
    studs_y: int = 2


@builder(BrickShape)
def building_brick(v: Variant, p: BrickShape) -> Geometry:
    """An interlocking plastic brick: rectangular body with a grid of round studs on top."""
    x, y, z = v.size
    pitch_x, pitch_y = x / p.studs_x, y / p.studs_y
    stud_h = min(0.35 * z, 0.0017 * pitch_x / 0.008)  # 1.7 mm on the standard 8 mm pitch
    body = shapes.box((x, y, z - stud_h), (0, 0, (z - stud_h) / 2))
    studs = [
        shapes.cylinder(0.3 * min(pitch_x, pitch_y), stud_h + 0.0005, (cx, cy, z - (stud_h + 0.0005) / 2), sections=20)
        for cx in (np.arange(p.studs_x) - (p.studs_x - 1) / 2) * pitch_x
        for cy in (np.arange(p.studs_y) - (p.studs_y - 1) / 2) * pitch_y
    ]
    color = v.color(0, P.RED)
    parts = ((body, color), (shapes.concatenate(studs), color))
    return Geometry(parts, (col.box_part((x, y, z - stud_h), (0, 0, (z - stud_h) / 2)), col.hull_part(_points(*studs))))


@dataclass(frozen=True)
class DollShape:
    """Standing in a long dress, or sitting with the legs stretched out in front; the hair style."""

    pose: Literal["standing", "sitting"] = "standing"
    hair: Literal["long", "short"] = "long"


def _doll_head(centre: np.ndarray, r: float, hair: str) -> tuple[trimesh.Trimesh, trimesh.Trimesh]:
    head = shapes.sphere(r, centre, 3)
    if hair == "long":
        locks = shapes.ellipsoid((0.95 * r, 1.08 * r, 1.5 * r), centre + (-0.25 * r, 0, -0.35 * r), 3)
    else:
        locks = shapes.ellipsoid((0.95 * r, 1.06 * r, 0.85 * r), centre + (-0.2 * r, 0, 0.28 * r), 3)
    return head, locks


@builder(DollShape)
def doll(v: Variant, p: DollShape) -> Geometry:
    """A child's doll facing +x, standing on the hem of its dress or sitting with legs forward."""
    skin, dress, hair = v.color(0, P.rgb(240, 200, 170)), v.color(1, P.PINK), v.color(2, P.rgb(150, 90, 40))
    if p.pose == "standing":
        skirt = shapes.lathe([(0, 0), (0.2, 0), (0.09, 0.45), (0.08, 0.72), (0, 0.72)], 32)
        head, locks = _doll_head(np.array([0.0, 0, 0.84]), 0.12, p.hair)
        arms = [shapes.tube([(0, s * 0.09, 0.68), (0.02, s * 0.15, 0.45)], 0.03, 10) for s in (1, -1)]
        parts = [(skirt, dress), (head, skin), (locks, hair), (shapes.concatenate(arms), skin)]
        return _fitted(parts, [_points(skirt, *arms), _points(head, locks)], v.size)
    torso = shapes.rounded_box((0.16, 0.22, 0.3), 0.03, (0, 0, 0.15))
    legs = [shapes.tube([(0.0, s * 0.06, 0.045), (0.36, s * 0.06, 0.045)], 0.045, 12) for s in (1, -1)]
    head, locks = _doll_head(np.array([0.02, 0, 0.41]), 0.12, p.hair)
    arms = [shapes.tube([(0, s * 0.13, 0.28), (0.08, s * 0.15, 0.1)], 0.03, 10) for s in (1, -1)]
    parts = [(torso, dress), (shapes.concatenate(legs), skin), (head, skin), (locks, hair)]
    parts.append((shapes.concatenate(arms), skin))
    return _fitted(parts, [_points(torso, *arms, *legs), _points(head, locks)], v.size)


@dataclass(frozen=True)
class XylophoneShape:
    """The number of bars."""

    bars: int = 8


@builder(XylophoneShape)
def xylophone(v: Variant, p: XylophoneShape) -> Geometry:
    """A toy xylophone: two rails converging towards +x carrying rainbow bars that shorten from -x to +x."""
    x, y, z = v.size
    rail_h = 0.55 * z
    gap = x / p.bars
    rails = []
    for s in (1, -1):
        ya, yb = s * 0.3 * y, s * 0.18 * y
        rails.append(
            shapes.hull(
                [
                    [ex, ey + d, hz]
                    for ex, ey in ((-x / 2, ya), (x / 2, yb))
                    for d in (-0.006, 0.006)
                    for hz in (0.0, rail_h)
                ]
            )
        )
    bars = []
    for k in range(p.bars):
        cx = -x / 2 + gap * (k + 0.5)
        length = y * (1.0 - 0.45 * k / max(1, p.bars - 1))
        bars.append((shapes.box((0.8 * gap, length, z - rail_h), (cx, 0, rail_h + (z - rail_h) / 2)), RAINBOW[k % 8]))
    frame = v.color(0, P.WOOD)
    parts = [(rails[0], frame), (rails[1], frame), *bars]
    return _fitted(parts, [_points(*rails, *(b for b, _ in bars))], v.size)


@dataclass(frozen=True)
class StackerShape:
    """The number of rings on the peg."""

    rings: int = 5


@builder(StackerShape)
def stacking_rings(v: Variant, p: StackerShape) -> Geometry:
    """A ring stacker: round base, centre peg, rings shrinking upwards, a ball on top."""
    base_h, ring_h = 0.12, 0.7 / p.rings
    base = shapes.cylinder(1.0, base_h, (0, 0, base_h / 2), sections=48)
    peg = shapes.cylinder(0.16, 0.85, (0, 0, base_h + 0.42), sections=24)
    rings = []
    for k in range(p.rings):
        outer = 0.95 - 0.5 * k / max(1, p.rings - 1)
        ring = trimesh.creation.annulus(r_min=0.17, r_max=outer, height=ring_h * 0.96, sections=40)
        ring.apply_translation((0, 0, base_h + ring_h * (k + 0.5)))
        rings.append((ring, v.colors[(k + 1) % len(v.colors)] if len(v.colors) > 1 else RAINBOW[k % 8]))
    knob = shapes.sphere(0.22, (0, 0, base_h + 0.72 + 0.2), 3)
    parts = [(base, v.color(0, P.RED)), (peg, v.color(0, P.RED)), *rings, (knob, v.color(0, P.RED))]
    return _fitted(parts, [_points(base, peg, knob, *(r for r, _ in rings))], v.size)


@dataclass(frozen=True)
class CrayonBoxShape:
    """How many crayons show above the open box."""

    count: int = 8


@builder(CrayonBoxShape)
def crayon_box(v: Variant, p: CrayonBoxShape) -> Geometry:
    """A cardboard crayon box standing upright, open at the top with a row (or two) of crayon tips."""
    x, y, z = v.size
    tip = 0.18 * z
    box_z = z - tip
    box = shapes.box((x, y, box_z), (0, 0, box_z / 2))
    band = shapes.box((x + 0.0004, y * 0.6, 0.25 * box_z), (0, 0, 0.55 * box_z))
    rows = 2 if p.count > 12 else 1
    per_row = int(np.ceil(p.count / rows))
    r = min(0.45 * y / (per_row * 0.9), 0.45 * x / rows)
    crayons = []
    for k in range(p.count):
        row, col_k = divmod(k, per_row)
        cy = (col_k - (per_row - 1) / 2) * (y * 0.9 / per_row)
        cx = (row - (rows - 1) / 2) * (x / rows) * 0.9
        stick = shapes.cylinder(r, tip * 0.6 + 0.005, (cx, cy, box_z + tip * 0.3 - 0.0025), sections=10)
        point = shapes.cone(r, 0.25 * r, tip * 0.4, (cx, cy, box_z + tip * 0.8), sections=10)
        crayons.append((shapes.concatenate([stick, point]), RAINBOW[k % 8]))
    parts = [(box, v.color(0, P.YELLOW)), (band, v.color(1, P.GREEN)), *crayons]
    collision = (col.box_part((x, y, box_z), (0, 0, box_z / 2)), col.hull_part(_points(*(c for c, _ in crayons))))
    return Geometry(tuple(parts), collision)


@dataclass(frozen=True)
class GameBoxShape:
    """The picture on the lid: a board game's title band or a jigsaw puzzle's picture."""

    picture: Literal["game", "puzzle"] = "game"


@builder(GameBoxShape)
def game_box(v: Variant, p: GameBoxShape) -> Geometry:
    """A flat cardboard box lying on its base: lid overlapping the base, printed picture on the lid."""
    x, y, z = v.size
    base = shapes.box((x - 0.004, y - 0.004, z - 0.002), (0, 0, (z - 0.002) / 2))
    lid_h = 0.6 * z
    lid = shapes.box((x, y, lid_h), (0, 0, z - lid_h / 2))
    parts = [(base, P.CARDBOARD), (lid, v.color(0, P.BLUE))]
    if p.picture == "game":
        parts.append((shapes.box((0.8 * x, 0.25 * y, 0.0012), (0, 0.2 * y, z - 0.0005)), v.color(1, P.YELLOW)))
        parts.append((shapes.box((0.5 * x, 0.35 * y, 0.0012), (0, -0.15 * y, z - 0.0005)), v.color(2, P.WHITE)))
    else:
        parts.append((shapes.box((0.86 * x, 0.8 * y, 0.0012), (0, 0, z - 0.0005)), v.color(1, P.SKY)))
        parts.append((shapes.box((0.86 * x, 0.3 * y, 0.0014), (0, -0.25 * y, z - 0.0004)), v.color(2, P.GREEN)))
    return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


@dataclass(frozen=True)
class BinShape:
    """Wall thickness (m) and corner radius (m); hand holes in the short ends."""

    wall: float = 0.006
    radius: float = 0.03
    handles: bool = True


@builder(BinShape)
def toy_bin(v: Variant, p: BinShape) -> Geometry:
    """An open-topped toy storage bin: rounded rectangular tub (five collision slabs) with hand holes."""
    x, y, z = v.size
    wall, floor = p.wall, p.wall
    outer = shapes.slab(x, y, z, p.radius, (0, 0, z / 2))
    inner = shapes.slab(x - 2 * wall, y - 2 * wall, z, max(0.001, p.radius - wall), (0, 0, floor + z / 2))
    tub = trimesh.boolean.difference([outer, inner], engine="manifold")
    parts = [(tub, v.color(0, P.BLUE))]
    if p.handles:
        for s in (1, -1):
            hole = shapes.slab(0.0015, 0.3 * y, 0.05 * z + 0.012, 0.0, (s * (x / 2 + 0.0002), 0, 0.82 * z))
            parts.append((hole, v.color(1, P.CHARCOAL)))
    collision = col.open_box_parts(x, y, z, wall, floor)
    cavity = Cavity(rectangle(x - 2 * wall, y - 2 * wall), floor, z - floor)
    return Geometry(tuple(parts), tuple(collision), cavity)


# --------------------------------------------------------------------------------------------- workshop


def _hexagon(centre: tuple[float, float], radius: float) -> Polygon:
    t = np.linspace(0, 2 * np.pi, 6, endpoint=False)
    return Polygon(np.stack([centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t)], axis=1))


def _open_jaw(centre: tuple[float, float], radius: float, facing: float) -> Polygon:
    """A round spanner head with a jaw slot opening towards `facing` (radians, 0 = +x)."""
    slot = shapely_box(0.0, -0.42 * radius, 2 * radius, 0.42 * radius)
    slot = affinity.translate(affinity.rotate(slot, facing, origin=(0, 0), use_radians=True), *centre)
    return Point(centre).buffer(radius, quad_segs=12).difference(slot)


@dataclass(frozen=True)
class WrenchShape:
    """Ends: open jaw and ring (combination), open jaws at both ends, or an adjustable jaw."""

    style: Literal["combination", "open", "adjustable"] = "combination"


@builder(WrenchShape)
def wrench(v: Variant, p: WrenchShape) -> Geometry:
    """A spanner lying flat along x: steel handle with a jaw at -x and a ring, jaw or hang hole at +x."""
    handle = _slab(shapely_box(-0.4, -0.035, 0.4, 0.035), 0.05)
    if p.style == "adjustable":
        head = _slab(_open_jaw((-0.4, 0.0), 0.13, np.pi + 0.3), 0.06)
        worm = shapes.cylinder(0.03, 0.1, (-0.33, 0.0, 0.065), axis="y", sections=16)
        tail = _slab(Point(0.42, 0).buffer(0.06).difference(Point(0.42, 0).buffer(0.025)), 0.05)
        parts = [(handle, v.color(0, P.STEEL)), (head, P.STEEL), (worm, P.CHARCOAL), (tail, v.color(0, P.STEEL))]
        return _fitted(parts, [_points(handle, tail), _points(head, worm)], v.size)
    head = _slab(_open_jaw((-0.42, 0.0), 0.1, np.pi + 0.26), 0.05)
    if p.style == "open":
        other = _slab(_open_jaw((0.42, 0.0), 0.085, 0.26), 0.05)
    else:
        ring = Point(0.42, 0).buffer(0.085, quad_segs=12).difference(_hexagon((0.42, 0.0), 0.045))
        other = _slab(ring, 0.055)
    color = v.color(0, P.STEEL)
    return _fitted(
        [(handle, color), (head, color), (other, color)], [handle.vertices, head.vertices, other.vertices], v.size
    )


@dataclass(frozen=True)
class PliersShape:
    """The nose: short combination jaws or long needle-nose jaws."""

    nose: Literal["combination", "needle"] = "combination"


@builder(PliersShape)
def pliers(v: Variant, p: PliersShape) -> Geometry:
    """Pliers lying flat, closed: jaws towards -x, pivot, two handles spreading to +x with coloured grips."""
    tip, half = (-0.55, 0.008) if p.nose == "needle" else (-0.35, 0.025)
    jaws = Polygon([(tip, -half), (tip, half), (-0.08, 0.06), (0.03, 0.05), (0.03, -0.05), (-0.08, -0.06)])
    metal = jaws.union(Point(0, 0).buffer(0.065))
    handles = [_strip([(0.0, s * 0.03), (0.5, s * 0.13)], 0.045) for s in (1, -1)]
    grips = [_strip([(0.16, s * 0.063), (0.5, s * 0.13)], 0.075) for s in (1, -1)]
    steel = _slab(metal.union(handles[0]).union(handles[1]), 0.055)
    grip_meshes = [_slab(g, 0.075) for g in grips]
    jaw_mesh = _slab(metal, 0.055)
    parts = [(steel, P.STEEL), (grip_meshes[0], v.color(0, P.RED)), (grip_meshes[1], v.color(0, P.RED))]
    hulls = [jaw_mesh.vertices, *(_points(_slab(h, 0.055), g) for h, g in zip(handles, grip_meshes, strict=True))]
    return _fitted(parts, hulls, v.size)


@dataclass(frozen=True)
class DrillShape:
    """The motor body's length as a fraction of the drill's, and a side handle's absence (compact drills)."""

    body: float = 0.7


@builder(DrillShape)
def power_drill(v: Variant, p: DrillShape) -> Geometry:
    """A cordless drill standing on its battery: battery pack, slanted grip with trigger, motor body, chuck at +x."""
    battery = shapes.rounded_box((0.5, 0.34, 0.2), 0.03, (-0.07, 0, 0.1))
    handle = shapes.hull(
        [[x, y, z] for x, z in ((-0.2, 0.18), (0.0, 0.18), (-0.14, 0.74), (0.08, 0.74)) for y in (-0.1, 0.1)]
    )
    trigger = shapes.box((0.06, 0.06, 0.1), (0.06, 0, 0.64))
    back = -0.45
    front = back + p.body
    body = shapes.cylinder(0.16, front - back, ((back + front) / 2, 0, 0.82), axis="x", sections=32)
    chuck = shapes.cone(0.12, 0.07, 0.16, (front + 0.08, 0, 0.82), axis="x", sections=24)
    bit = shapes.cylinder(0.02, 0.1, (front + 0.21, 0, 0.82), axis="x", sections=12)
    main, dark = v.color(0, P.YELLOW), v.color(1, P.CHARCOAL)
    parts = [(battery, dark), (handle, dark), (trigger, P.BLACK), (body, main), (chuck, P.BLACK), (bit, P.STEEL)]
    hulls = [battery.vertices, _points(handle, trigger), _points(body, chuck, bit)]
    return _fitted(parts, hulls, v.size)


@dataclass(frozen=True)
class SawShape:
    """How many teeth the blade has."""

    teeth: int = 40


@builder(SawShape)
def hand_saw(v: Variant, p: SawShape) -> Geometry:
    """A hand saw lying flat: tapering steel blade with teeth along -y, closed grip handle at +x."""
    n = p.teeth
    xs = np.linspace(-0.5, 0.22, 2 * n + 1)
    teeth = [(x, -0.07 - 0.008 * (k % 2)) for k, x in enumerate(xs)]
    blade = Polygon([*teeth, (0.22, 0.1), (-0.5, 0.0)])
    grip = shapes.rounded_rect(0.3, 0.24, 0.05, (0.34, 0.01))
    hole = shapes.rounded_rect(0.14, 0.07, 0.03, (0.37, 0.03))
    blade_mesh = _slab(blade, 0.004)
    handle = _slab(grip.difference(hole), 0.05)
    parts = [(blade_mesh, P.STEEL), (handle, v.color(0, P.WOOD))]
    return _fitted(parts, [blade_mesh.vertices, handle.vertices], v.size)


@dataclass(frozen=True)
class PaintCanShape:
    """A wire bail handle standing up over the lid."""

    handle: bool = True


@builder(PaintCanShape)
def paint_can(v: Variant, p: PaintCanShape) -> Geometry:
    """A round metal paint tin: steel body with rolled rims, a label in the paint's colour, lid, optional bail."""
    x, _, z = v.size
    r = x / 2
    bail_h = 0.16 * z if p.handle else 0.0
    h = z - bail_h
    body = shapes.lathe(
        [
            (0, 0),
            (r - 0.003, 0),
            (r, 0.004),
            (r - 0.002, 0.01),
            (r - 0.002, h - 0.01),
            (r, h - 0.004),
            (r - 0.003, h),
            (0, h),
        ],
        48,
    )
    label = shapes.cylinder(r - 0.0015, 0.62 * h, (0, 0, 0.48 * h), sections=48)
    lid = shapes.cylinder(r - 0.012, 0.002, (0, 0, h - 0.0005), sections=48)
    parts = [(body, P.SILVER), (label, v.color(0, P.WHITE)), (lid, v.color(1, P.GREY))]
    hulls = [body.vertices]
    if p.handle:
        t = np.linspace(0, np.pi, 17)
        arc = np.stack([np.zeros_like(t), (r - 0.004) * np.cos(t), h - 0.03 + (bail_h + 0.03 - 0.002) * np.sin(t)], 1)
        bail = shapes.tube(arc, 0.0018, sides=8)
        ears = [shapes.box((0.012, 0.004, 0.016), (0, s * (r - 0.001), h - 0.03)) for s in (1, -1)]
        parts += [(bail, P.STEEL), (shapes.concatenate(ears), P.STEEL)]
        hulls.append(bail.vertices)
    return Geometry(tuple(parts), tuple(col.hull_part(hp) for hp in hulls))


@dataclass(frozen=True)
class BrushShape:
    """The bristle head's width as a fraction of the brush's width (the handle is narrower)."""

    handle: float = 0.35


@builder(BrushShape)
def paintbrush(v: Variant, p: BrushShape) -> Geometry:
    """A decorating paintbrush lying flat: flat handle at +x, metal ferrule, bristles tapering to -x."""
    hw = p.handle
    handle = shapes.rounded_box((0.5, hw, 0.1), 0.04, (0.24, 0, 0.05))
    ferrule = shapes.box((0.16, 1.0, 0.14), (-0.07, 0, 0.07))
    bristles = shapes.hull(
        [
            [x, s * w / 2, 0.07 + sz * t / 2]
            for x, w, t in ((-0.14, 0.98, 0.12), (-0.5, 0.94, 0.03))
            for s in (1, -1)
            for sz in (1, -1)
        ]
    )
    parts = [(handle, v.color(0, P.WOOD)), (ferrule, v.color(1, P.SILVER)), (bristles, v.color(2, P.rgb(60, 45, 35)))]
    return _fitted(parts, [handle.vertices, _points(ferrule, bristles)], v.size)


@dataclass(frozen=True)
class LevelShape:
    """The number of bubble vials showing in the face."""

    vials: int = 3


@builder(LevelShape)
def spirit_level(v: Variant, p: LevelShape) -> Geometry:
    """A spirit level standing on its long edge: aluminium bar, end caps, green bubble vials in windows."""
    x, y, z = v.size
    bar = shapes.box((x - 0.01, y, z), (0, 0, z / 2))
    caps = shapes.concatenate([shapes.box((0.006, y, z), (s * (x / 2 - 0.003), 0, z / 2)) for s in (1, -1)])
    spots = [0.0] if p.vials == 1 else list(np.linspace(-0.35 * x, 0.35 * x, p.vials))
    windows = [shapes.box((min(0.05, 0.12 * x), y + 0.0004, 0.45 * z), (sx, 0, z / 2)) for sx in spots]
    bubbles = [shapes.cylinder(0.12 * z, y + 0.0008, (sx, 0, z / 2), axis="y", sections=16) for sx in spots]
    parts = [(bar, v.color(0, P.SILVER)), (caps, v.color(1, P.RED)), (shapes.concatenate(windows), P.BLACK)]
    parts.append((shapes.concatenate(bubbles), P.LIME))
    return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


@dataclass(frozen=True)
class CutterShape:
    """Whether the blade is extended out of the nose."""

    blade_out: bool = True


@builder(CutterShape)
def utility_knife(v: Variant, p: CutterShape) -> Geometry:
    """A box cutter lying flat: tapered body towards -x, rubber grip, slider button, trapezoid blade."""
    outline = Polygon([(-0.32, -0.07), (-0.32, 0.07), (0.45, 0.12), (0.5, 0.0), (0.45, -0.12)]).buffer(0.02)
    body = _slab(outline, 0.12)
    grip = _slab(Polygon([(0.0, -0.09), (0.0, 0.09), (0.42, 0.12), (0.42, -0.12)]), 0.125)
    slider = shapes.rounded_box((0.08, 0.05, 0.03), 0.01, (-0.1, 0.0, 0.13))
    parts = [(body, v.color(0, P.YELLOW)), (grip, v.color(1, P.CHARCOAL)), (slider, v.color(1, P.CHARCOAL))]
    hulls = [_points(body, grip, slider)]
    if p.blade_out:
        blade = _slab(Polygon([(-0.33, -0.05), (-0.33, 0.04), (-0.5, 0.04), (-0.42, -0.05)]), 0.01, 0.055)
        parts.append((blade, P.STEEL))
        hulls.append(blade.vertices)
    return _fitted(parts, hulls, v.size)


@dataclass(frozen=True)
class FlashlightShape:
    """The head's radius relative to the barrel's."""

    head: float = 1.5


@builder(FlashlightShape)
def flashlight(v: Variant, p: FlashlightShape) -> Geometry:
    """A torch lying on its side along x, head at +x, tilted so the barrel's tail and the head both touch."""
    rb, rh = 0.08, 0.08 * p.head
    barrel = shapes.cylinder(rb, 0.62, (-0.17, 0, 0), axis="x", sections=16)
    head = shapes.cone(rb, rh, 0.3, (0.29, 0, 0), axis="x", sections=16)
    lens = shapes.cylinder(0.88 * rh, 0.02, (0.445, 0, 0), axis="x", sections=16)
    tail = shapes.cylinder(rb * 1.05, 0.06, (-0.47, 0, 0), axis="x", sections=16)
    button = shapes.cylinder(0.03, 0.03, (0.0, 0, rb), sections=12)
    tilt = trimesh.transformations.rotation_matrix(-np.arctan2(rh - rb * 1.05, 0.95), (0, 1, 0))
    meshes = [barrel, head, lens, tail, button]
    for m in meshes:
        m.apply_transform(tilt)
    main = v.color(0, P.BLACK)
    parts = [
        (barrel, main),
        (head, main),
        (lens, P.rgb(235, 240, 200)),
        (tail, v.color(1, P.CHARCOAL)),
        (button, P.RED),
    ]
    return _fitted(parts, [_points(*meshes)], v.size)


def _glove_outline() -> Polygon:
    """One flat glove, fingers towards +x and thumb towards +y."""
    palm = shapes.rounded_rect(0.42, 0.4, 0.08, (0.23, 0.0))
    fingers = [
        _strip([(0.4, y), (0.4 + reach, y)], 0.095)
        for y, reach in ((0.15, 0.3), (0.05, 0.38), (-0.05, 0.36), (-0.15, 0.28))
    ]
    thumb = _strip([(0.15, 0.15), (0.38, 0.34)], 0.11)
    cuff = shapes.rounded_rect(0.3, 0.44, 0.03, (-0.12, 0.0))
    shape = palm.union(thumb).union(cuff)
    for f in fingers:
        shape = shape.union(f)
    return shape


def _mirrored(shape: Polygon, side: int, offset: float) -> Polygon:
    """`shape` mirrored across the x axis when `side` is -1, then moved `offset` towards its side."""
    return affinity.translate(affinity.scale(shape, 1, side, origin=(0, 0)), 0, side * offset)


@dataclass(frozen=True)
class GloveShape:
    """A pair lying side by side (thumbs outwards) or a single glove."""

    pair: bool = True


@builder(GloveShape)
def work_gloves(v: Variant, p: GloveShape) -> Geometry:
    """Work gloves lying flat (a soft object drawn rigid): padded hand and a cuff band in a second colour."""
    outline = _glove_outline()
    cuff = shapes.rounded_rect(0.3, 0.44, 0.03, (-0.12, 0.0))
    hands = [(outline, cuff)]
    if p.pair:
        hands = [(_mirrored(outline, s, 0.32), _mirrored(cuff, s, 0.32)) for s in (1, -1)]
    parts, hulls = [], []
    for hand, band in hands:
        hand_mesh = _slab(hand, 0.06)
        band_mesh = _slab(band, 0.07)
        parts += [(hand_mesh, v.color(0, P.CREAM)), (band_mesh, v.color(1, P.BLUE))]
        hulls.append(_points(hand_mesh, band_mesh))
    return _fitted(parts, hulls, v.size)


@dataclass(frozen=True)
class GlassesShape:
    """How far the lens wraps around (degrees either side of straight ahead)."""

    wrap: float = 55.0


@builder(GlassesShape)
def safety_glasses(v: Variant, p: GlassesShape) -> Geometry:
    """Safety glasses standing open: a wraparound lens facing +x with a frame brow, temples reaching back to -x."""
    a = np.radians(p.wrap)
    t = np.linspace(-a, a, 24)
    r0, r1 = 0.55, 0.575
    arc = Polygon(
        np.vstack([np.stack([r1 * np.cos(t), r1 * np.sin(t)], 1), np.stack([r0 * np.cos(t), r0 * np.sin(t)], 1)[::-1]])
    )
    arc = affinity.translate(arc, -0.5, 0)
    lens = _slab(arc, 0.3)
    brow = _slab(arc.buffer(0.006), 0.06, 0.27)
    end_x, end_y = -0.5 + r0 * np.cos(a), r0 * np.sin(a)
    temples = [
        shapes.hull(
            [
                [x, s * end_y + dy, z]
                for x, z in ((end_x, 0.27), (end_x, 0.33), (end_x - 0.75, 0.0), (end_x - 0.75, 0.05))
                for dy in (-0.012, 0.012)
            ]
        )
        for s in (1, -1)
    ]
    frame = v.color(1, P.BLACK)
    parts = [(lens, v.color(0, P.rgb(220, 235, 240, 0.5))), (brow, frame), (temples[0], frame), (temples[1], frame)]
    return _fitted(parts, [_points(lens, brow), temples[0].vertices, temples[1].vertices], v.size)


@dataclass(frozen=True)
class ClampShape:
    """A C-clamp (G-clamp) or an F-style bar clamp."""

    style: Literal["c", "bar"] = "c"


@builder(ClampShape)
def clamp(v: Variant, p: ClampShape) -> Geometry:
    """A clamp lying flat: C frame with screw, pad and T-bar, or a steel bar with a fixed and a sliding jaw."""
    if p.style == "bar":
        bar = _slab(shapely_box(-0.5, -0.02, 0.5, 0.02), 0.05)
        fixed = _slab(shapely_box(0.44, -0.02, 0.5, 0.3), 0.07)
        sliding = _slab(shapely_box(0.02, -0.02, 0.09, 0.26), 0.07)
        grip = _slab(shapes.rounded_rect(0.1, 0.26, 0.04, (0.055, -0.16)), 0.09)
        color = v.color(0, P.RED)
        parts = [(bar, P.STEEL), (fixed, color), (sliding, color), (grip, v.color(1, P.BLACK))]
        return _fitted(parts, [bar.vertices, fixed.vertices, _points(sliding, grip)], v.size)
    frame = shapely_box(-0.35, -0.35, -0.24, 0.35).union(shapely_box(-0.35, 0.24, 0.2, 0.35))
    frame = frame.union(shapely_box(-0.35, -0.35, 0.2, -0.24)).buffer(0.02)
    frame_mesh = _slab(frame, 0.1)
    screw = _slab(shapely_box(0.13, -0.62, 0.17, 0.12), 0.05, 0.025)
    pad = _slab(shapely_box(0.08, 0.1, 0.22, 0.15), 0.08, 0.01)
    tbar = _slab(shapes.rounded_rect(0.32, 0.04, 0.015, (0.15, -0.6)), 0.05, 0.025)
    parts = [(frame_mesh, v.color(0, P.BLUE)), (screw, P.STEEL), (pad, P.STEEL), (tbar, P.STEEL)]
    hulls = [
        _points(_slab(shapely_box(-0.37, -0.37, -0.22, 0.37), 0.1)),
        _points(_slab(shapely_box(-0.37, 0.22, 0.22, 0.37), 0.1)),
        _points(_slab(shapely_box(-0.37, -0.37, 0.22, -0.22), 0.1)),
        _points(screw, pad, tbar),
    ]
    return _fitted(parts, hulls, v.size)


@dataclass(frozen=True)
class SandpaperShape:
    """A foam sanding block instead of a loose sheet."""

    block: bool = False


@builder(SandpaperShape)
def sandpaper(v: Variant, p: SandpaperShape) -> Geometry:
    """Abrasive paper lying flat: a grit layer on a paper backing (or on a foam block); one box of collision."""
    x, y, z = v.size
    backing_t = 0.85 * z if p.block else 0.4 * z
    backing = shapes.box((x, y, backing_t), (0, 0, backing_t / 2))
    grit = shapes.box((x, y, z - backing_t), (0, 0, backing_t + (z - backing_t) / 2))
    parts = ((backing, v.color(1, P.PAPER)), (grit, v.color(0, P.rgb(200, 150, 90))))
    return Geometry(parts, (col.box_part((x, y, z), (0, 0, z / 2)),))


@dataclass(frozen=True)
class TapeRollShape:
    """The hole's radius as a fraction of the roll's, and the cardboard core's thickness as a fraction too."""

    hole: float = 0.62
    core: float = 0.06


@builder(TapeRollShape)
def tape_roll(v: Variant, p: TapeRollShape) -> Geometry:
    """A roll of tape lying flat on its side: wound tape around a cardboard core; eight convex ring segments."""
    x, _, z = v.size
    r = x / 2
    r_in = p.hole * r
    r_core = r_in + p.core * r
    tape = trimesh.creation.annulus(r_min=r_core - 0.0005, r_max=r, height=z, sections=48)
    core = trimesh.creation.annulus(r_min=r_in, r_max=r_core, height=z * 0.995, sections=48)
    for m in (tape, core):
        m.apply_translation((0, 0, z / 2))
    edges = np.linspace(0, 2 * np.pi, 9)
    segments = []
    for a0, a1 in zip(edges[:-1], edges[1:], strict=True):
        ang = np.linspace(a0, a1, 4)
        ring = [
            np.stack([rr * np.cos(ang), rr * np.sin(ang), np.full_like(ang, hz)], 1)
            for rr in (r_in, r)
            for hz in (0.0, z)
        ]
        segments.append(col.hull_part(np.vstack(ring)))
    return Geometry(((tape, v.color(0, P.SILVER)), (core, P.CARDBOARD)), tuple(segments))


@dataclass(frozen=True)
class HardHatShape:
    """The brim: a full brim all round, or a cap-style peak at the front only."""

    brim: Literal["full", "peak"] = "peak"


@builder(HardHatShape)
def hard_hat(v: Variant, p: HardHatShape) -> Geometry:
    """A safety helmet resting on its rim: domed shell with a ridge, peak towards +x (or a full brim)."""
    t = np.linspace(0, np.pi / 2, 12)
    dome = [(0.38 * np.cos(a), 0.08 + 0.52 * np.sin(a)) for a in t]
    shell = shapes.lathe([(0, 0), (0.4, 0), (0.4, 0.08), *dome[1:], (0, 0.6)], 48)
    shell.apply_scale((1.0, 0.85, 1.0))
    ridge = shapes.hull([[x, y, z] for x in (-0.3, 0.3) for y in (-0.03, 0.03) for z in (0.45, 0.62)])
    if p.brim == "full":
        brim = shapes.cylinder(0.5, 0.03, (0, 0, 0.015), sections=48)
        brim.apply_scale((1.0, 0.85, 1.0))
    else:
        brim = _slab(
            Point(0, 0).buffer(0.4).union(shapely_box(0.0, -0.3, 0.5, 0.3).intersection(Point(0.05, 0).buffer(0.47))),
            0.03,
        )
        brim.apply_scale((1.0, 0.85, 1.0))
    color = v.color(0, P.YELLOW)
    parts = [(shell, color), (ridge, color), (brim, color)]
    return _fitted(parts, [_points(shell, ridge, brim)], v.size)


# --------------------------------------------------------------------------------------------- more


@dataclass(frozen=True)
class BucketShape:
    """The base's radius as a fraction of the rim's, and a wire bail folded down against the side (-x)."""

    taper: float = 0.82
    handle: bool = True


@builder(BucketShape)
def bucket(v: Variant, p: BucketShape) -> Geometry:
    """An open pail: tapered revolved wall with a rolled rim (open collision ring and cavity), optional bail."""
    x, _, z = v.size
    out = 0.012 if p.handle else 0.0
    r = (x - out) / 2
    vessel = Vessel(resample([(p.taper * r - 0.002, 0.0), (r - 0.003, z - 0.006), (r, z)], 8), 0.004, 0.005, stations=3)
    color = v.color(0, P.RED)
    rim = trimesh.creation.annulus(r_min=r - 0.006, r_max=r, height=0.006).apply_translation((0, 0, z - 0.003))
    parts = [(vessel.mesh(), color), (rim, color)]
    if p.handle:
        t = np.linspace(np.pi / 2, 3 * np.pi / 2, 21)
        reach = r + out - 0.002
        sag = z - 0.02 - 0.35 * r * np.abs(np.cos(t))  # the folded bail hangs lowest at its middle
        bail = np.stack([reach * np.cos(t), (r + 0.001) * np.sin(t), sag], 1)
        parts.append((shapes.tube(bail, 0.0018, sides=8), v.color(1, P.STEEL)))
    shift = np.array([out / 2, 0.0, 0.0])
    for mesh, _ in parts:
        mesh.apply_translation(shift)
    cavity = vessel.cavity()
    return Geometry(
        tuple(parts),
        tuple(c.translated(shift) for c in vessel.collision(16)),
        Cavity(cavity.opening + shift[:2], cavity.floor_height, cavity.depth),
    )


@dataclass(frozen=True)
class ToolBagShape:
    """The wall thickness (m)."""

    wall: float = 0.008


@builder(ToolBagShape)
def tool_bag(v: Variant, p: ToolBagShape) -> Geometry:
    """An open-topped canvas tool bag: padded tub (five collision slabs) with two carry handles along the long sides."""
    x, y, z = v.size
    handle_h = 0.22 * z
    body_z = z - handle_h
    wall, floor = p.wall, p.wall
    outer = shapes.slab(x, y, body_z, 0.02, (0, 0, body_z / 2))
    inner = shapes.slab(x - 2 * wall, y - 2 * wall, body_z, 0.012, (0, 0, floor + body_z / 2))
    tub = trimesh.boolean.difference([outer, inner], engine="manifold")
    base = shapes.slab(x, y, 0.012, 0.02, (0, 0, 0.006))
    t = np.linspace(0, np.pi, 15)
    handles = [
        shapes.tube(
            np.stack(
                [
                    0.3 * x * np.cos(t),
                    np.full_like(t, s * (y / 2 - wall / 2)),
                    body_z - 0.01 + (handle_h + 0.005) * np.sin(t),
                ],
                1,
            ),
            0.005,
            sides=8,
        )
        for s in (1, -1)
    ]
    parts = [
        (tub, v.color(0, P.rgb(120, 110, 80))),
        (base, v.color(1, P.BLACK)),
        (shapes.concatenate(handles), v.color(1, P.BLACK)),
    ]
    cavity = Cavity(rectangle(x - 2 * wall, y - 2 * wall), floor, body_z - floor)
    return Geometry(tuple(parts), tuple(col.open_box_parts(x, y, body_z, wall, floor)), cavity)


@builder(NoOptions)
def piggy_bank(v: Variant, _: NoOptions) -> Geometry:
    """A piggy bank facing +x on four short legs: round body, snout, ears, coin slot on the back."""
    body = shapes.ellipsoid((0.5, 0.36, 0.36), (0, 0, 0.44), 3)
    snout = shapes.cylinder(0.13, 0.1, (0.5, 0, 0.46), axis="x", sections=24)
    ears = [shapes.cone(0.08, 0.01, 0.12, (0.28, s * 0.17, 0.8), sections=12) for s in (1, -1)]
    legs = [shapes.cylinder(0.08, 0.16, (lx, s * 0.18, 0.08), sections=16) for lx in (-0.25, 0.25) for s in (1, -1)]
    slot = shapes.box((0.16, 0.02, 0.01), (-0.05, 0, 0.799))
    nostrils = [shapes.cylinder(0.025, 0.01, (0.552, s * 0.045, 0.46), axis="x", sections=8) for s in (1, -1)]
    pink = v.color(0, P.PINK)
    parts = [(body, pink), (snout, pink), (shapes.concatenate(ears), pink), (shapes.concatenate(legs), pink)]
    parts += [(slot, P.BLACK), (shapes.concatenate(nostrils), v.color(1, P.rgb(200, 100, 130)))]
    return _fitted(parts, [_points(body, snout, *ears, *legs)], v.size)


@builder(NoOptions)
def yo_yo(v: Variant, _: NoOptions) -> Geometry:
    """A yo-yo lying on one face: two rounded discs joined by a short axle with the string wound on it."""
    x, z = v.size[0], v.size[2]
    r = x / 2
    half = 0.44 * z
    disc = [(0, 0), (0.85 * r, 0), (r, 0.25 * half), (r, 0.8 * half), (0.9 * r, half), (0, half)]
    lower = shapes.lathe(disc, 40)
    upper = shapes.lathe([(rr, z - zz) for rr, zz in disc], 40)
    string = shapes.cylinder(0.4 * r, z - 2 * half + 0.002, (0, 0, z / 2), sections=24)
    parts = [(lower, v.color(0, P.RED)), (upper, v.color(0, P.RED)), (string, v.color(1, P.WHITE))]
    return Geometry(tuple(parts), (col.hull_part(lower), col.hull_part(upper), col.hull_part(string)))


@builder(NoOptions)
def toy_drum(v: Variant, _: NoOptions) -> Geometry:
    """A children's drum standing on its base: shell, two rims, drumhead on top, two sticks lying crossed on it."""
    x, z = v.size[0], v.size[2]
    r = x / 2
    stick_r = 0.035 * r
    shell_h = z - 2 * stick_r
    shell = shapes.cylinder(0.96 * r, shell_h, (0, 0, shell_h / 2), sections=48)
    rims = [shapes.cylinder(r, 0.12 * shell_h, (0, 0, zc), sections=48) for zc in (0.06 * shell_h, 0.94 * shell_h)]
    head = shapes.cylinder(0.93 * r, 0.002, (0, 0, shell_h - 0.0009), sections=48)
    sticks = [
        shapes.tube(col_path, stick_r, sides=8)
        for col_path in (
            np.array([[-0.7 * r, -0.3 * r, shell_h + stick_r], [0.7 * r, 0.2 * r, shell_h + stick_r]]),
            np.array([[-0.6 * r, 0.35 * r, shell_h + stick_r], [0.7 * r, -0.25 * r, shell_h + stick_r]]),
        )
    ]
    parts = [(shell, v.color(0, P.BLUE)), (shapes.concatenate(rims), v.color(1, P.RED)), (head, P.WHITE)]
    parts.append((shapes.concatenate(sticks), P.LIGHT_WOOD))
    return Geometry(tuple(parts), (col.hull_part(_points(shell, *rims)), col.hull_part(_points(*sticks))))


@builder(NoOptions)
def toy_robot(v: Variant, _: NoOptions) -> Geometry:
    """A boxy toy robot facing +x standing on two big feet: legs, body with a panel, arms, head, eyes, antenna."""
    feet = [shapes.box((0.3, 0.16, 0.08), (0.03, s * 0.11, 0.04)) for s in (1, -1)]
    legs = [shapes.box((0.12, 0.1, 0.22), (0, s * 0.11, 0.19)) for s in (1, -1)]
    body = shapes.rounded_box((0.26, 0.4, 0.34), 0.03, (0, 0, 0.47))
    panel = shapes.box((0.01, 0.22, 0.14), (0.13, 0, 0.48))
    arms = [shapes.rounded_box((0.1, 0.08, 0.3), 0.03, (0.02, s * 0.24, 0.46)) for s in (1, -1)]
    head = shapes.rounded_box((0.22, 0.26, 0.2), 0.03, (0, 0, 0.75))
    eyes = [shapes.cylinder(0.035, 0.012, (0.11, s * 0.06, 0.77), axis="x", sections=16) for s in (1, -1)]
    antenna = shapes.cylinder(0.012, 0.1, (0, 0, 0.9), sections=8)
    bulb = shapes.sphere(0.03, (0, 0, 0.96), 2)
    main, accent = v.color(0, P.SILVER), v.color(1, P.RED)
    parts = [(shapes.concatenate(feet), accent), (shapes.concatenate(legs), main), (body, main), (panel, accent)]
    parts += [(shapes.concatenate(arms), main), (head, main), (shapes.concatenate(eyes), P.YELLOW)]
    parts += [(antenna, P.CHARCOAL), (bulb, accent)]
    hulls = [_points(*feet, *legs), _points(body, panel, *arms), _points(head, *eyes, antenna, bulb)]
    return _fitted(parts, hulls, v.size)


@builder(NoOptions)
def toy_train(v: Variant, _: NoOptions) -> Geometry:
    """A toy steam engine facing +x: chassis, boiler with chimney, cab at the back, six wheels, buffer beam."""
    chassis = shapes.box((1.0, 0.36, 0.1), (0, 0, 0.16))
    boiler = shapes.cylinder(0.15, 0.6, (0.18, 0, 0.36), axis="x", sections=24)
    chimney = shapes.cone(0.06, 0.09, 0.2, (0.36, 0, 0.58), sections=16)
    cab = shapes.box((0.34, 0.36, 0.5), (-0.3, 0, 0.46))
    roof = shapes.box((0.4, 0.42, 0.04), (-0.3, 0, 0.73))
    wheels = [
        shapes.cylinder(0.11, 0.05, (wx, s * 0.19, 0.11), axis="y", sections=16)
        for wx in (-0.3, 0.02, 0.32)
        for s in (1, -1)
    ]
    main, accent = v.color(0, P.RED), v.color(1, P.BLUE)
    parts = [(chassis, P.CHARCOAL), (boiler, main), (chimney, P.BLACK), (cab, accent), (roof, main)]
    parts.append((shapes.concatenate(wheels), v.color(2, P.YELLOW)))
    hulls = [_points(chassis, *wheels), _points(boiler, chimney), _points(cab, roof)]
    return _fitted(parts, hulls, v.size)


@builder(NoOptions)
def chisel(v: Variant, _: NoOptions) -> Geometry:
    """A wood chisel lying flat: faceted handle at +x, steel ferrule and a flat blade bevelled at -x."""
    handle = shapes.cone(0.07, 0.08, 0.45, (0.27, 0, 0.08), axis="x", sections=8)
    handle.apply_translation((0, 0, -handle.bounds[0][2]))
    ferrule = shapes.cylinder(0.06, 0.06, (0.02, 0, 0.06), axis="x", sections=8)
    ferrule.apply_translation((0, 0, -ferrule.bounds[0][2]))
    blade = shapes.hull(
        [
            [bx, s * 0.05, bz]
            for s in (1, -1)
            for bx, bz in ((0.0, 0.0), (0.0, 0.035), (-0.45, 0.0), (-0.5, 0.0), (-0.45, 0.035))
        ]
    )
    parts = [(handle, v.color(0, P.WOOD)), (ferrule, P.STEEL), (blade, P.STEEL)]
    return _fitted(parts, [_points(handle, ferrule), blade.vertices], v.size)


@builder(NoOptions)
def hacksaw(v: Variant, _: NoOptions) -> Geometry:
    """A hacksaw lying flat: C-shaped tubular frame, thin blade along the bottom, pistol grip at +x."""
    frame = _strip([(-0.5, -0.06), (-0.5, 0.15), (0.28, 0.15), (0.28, -0.06)], 0.04)
    blade = shapely_box(-0.5, -0.075, 0.28, -0.045)
    grip = _strip([(0.28, 0.08), (0.45, -0.08)], 0.11)
    frame_mesh, grip_mesh = _slab(frame, 0.03), _slab(grip, 0.05)
    blade_mesh = _slab(blade, 0.006)
    parts = [(frame_mesh, v.color(0, P.BLUE)), (blade_mesh, P.STEEL), (grip_mesh, v.color(1, P.BLACK))]
    pieces = [
        _slab(_strip(seg, 0.04), 0.03)
        for seg in (((-0.5, -0.06), (-0.5, 0.15)), ((-0.5, 0.15), (0.28, 0.15)), ((0.28, 0.15), (0.28, -0.06)))
    ]
    return _fitted(parts, [*(m.vertices for m in pieces), blade_mesh.vertices, grip_mesh.vertices], v.size)


@builder(NoOptions)
def hatchet(v: Variant, _: NoOptions) -> Geometry:
    """A hatchet lying flat: handle along x (knob at +x), steel head at -x with its cutting edge towards -y."""
    handle = _strip([(-0.42, 0.0), (0.0, -0.01), (0.42, 0.02), (0.47, 0.0)], 0.08)
    head = Polygon([(-0.5, 0.1), (-0.36, 0.1), (-0.36, -0.02), (-0.3, -0.3), (-0.44, -0.34), (-0.5, -0.02)])
    handle_mesh, head_mesh = _slab(handle, 0.06), _slab(head.buffer(0.01), 0.05)
    parts = [(handle_mesh, v.color(0, P.WOOD)), (head_mesh, v.color(1, P.CHARCOAL))]
    return _fitted(parts, [handle_mesh.vertices, head_mesh.vertices], v.size)


@dataclass(frozen=True)
class ToyCarShape:
    """A saloon car with a cabin, or a low racing car with a cockpit and rear wing."""

    style: Literal["saloon", "racer"] = "saloon"


@builder(ToyCarShape)
def toy_car(v: Variant, p: ToyCarShape) -> Geometry:
    """A toy car facing +x on four wheels: body, cabin with dark windows (or cockpit and wing), headlights."""
    main = v.color(0, P.RED)
    wheels = [
        shapes.cylinder(0.1, 0.09, (wx, s * 0.2, 0.1), axis="y", sections=16) for wx in (-0.32, 0.32) for s in (1, -1)
    ]
    lights = shapes.concatenate([shapes.box((0.01, 0.06, 0.04), (0.5, s * 0.14, 0.22)) for s in (1, -1)])
    if p.style == "racer":
        body = shapes.hull(
            [
                [bx, s * by, bz]
                for bx, by, bz in ((-0.5, 0.22, 0.06), (-0.5, 0.22, 0.24), (0.5, 0.14, 0.06), (0.5, 0.12, 0.14))
                for s in (1, -1)
            ]
        )
        cockpit = shapes.ellipsoid((0.14, 0.09, 0.07), (-0.05, 0, 0.24), 2)
        wing = shapes.box((0.1, 0.46, 0.03), (-0.46, 0, 0.33))
        struts = shapes.box((0.04, 0.2, 0.1), (-0.46, 0, 0.27))
        parts = [(body, main), (cockpit, P.BLACK), (wing, v.color(1, P.BLACK)), (struts, v.color(1, P.BLACK))]
        parts += [(shapes.concatenate(wheels), P.BLACK), (lights, P.YELLOW)]
        return _fitted(parts, [_points(body, cockpit, *wheels), _points(wing, struts)], v.size)
    body = shapes.rounded_box((1.0, 0.46, 0.2), 0.05, (0, 0, 0.18))
    cabin = shapes.hull(
        [
            [cx, s * cy, cz]
            for cx, cy, cz in ((-0.3, 0.21, 0.27), (0.22, 0.21, 0.27), (-0.22, 0.17, 0.44), (0.08, 0.17, 0.44))
            for s in (1, -1)
        ]
    )
    windows = shapes.hull(
        [
            [cx, s * cy, cz]
            for cx, cy, cz in ((-0.26, 0.215, 0.3), (0.19, 0.215, 0.3), (-0.2, 0.175, 0.41), (0.07, 0.175, 0.41))
            for s in (1, -1)
        ]
    )
    parts = [(body, main), (cabin, main), (windows, P.rgb(60, 80, 100)), (shapes.concatenate(wheels), P.BLACK)]
    parts.append((lights, P.YELLOW))
    return _fitted(parts, [_points(body, cabin, *wheels)], v.size)


CUBE_FACES = (P.WHITE, P.YELLOW, P.RED, P.ORANGE, P.BLUE, P.GREEN)  # top, bottom, +x, -x, +y, -y


@dataclass(frozen=True)
class PuzzleCubeShape:
    """Stickers per edge (2 for a pocket cube, 3 standard, 4 for a revenge cube)."""

    n: int = 3


@builder(PuzzleCubeShape)
def puzzle_cube(v: Variant, p: PuzzleCubeShape) -> Geometry:
    """A twisty puzzle cube: black core with an n-by-n grid of coloured stickers on every face (solved)."""
    s = v.size[0]
    skin = 0.0004
    core = shapes.rounded_box((s - 2 * skin, s - 2 * skin, s - 2 * skin), 0.06 * s, (0, 0, s / 2))
    pitch = (s - 2 * skin) / p.n
    offsets = (np.arange(p.n) - (p.n - 1) / 2) * pitch
    tile = 0.86 * pitch
    half = s / 2 - skin / 2
    parts = [(core, v.color(0, P.BLACK))]
    faces = [
        (lambda a, b: (a, b, s / 2 + half), (tile, tile, skin)),
        (lambda a, b: (a, b, s / 2 - half), (tile, tile, skin)),
        (lambda a, b: (half, a, s / 2 + b), (skin, tile, tile)),
        (lambda a, b: (-half, a, s / 2 + b), (skin, tile, tile)),
        (lambda a, b: (a, half, s / 2 + b), (tile, skin, tile)),
        (lambda a, b: (a, -half, s / 2 + b), (tile, skin, tile)),
    ]
    for k, (where, ext) in enumerate(faces):
        stickers = [shapes.box(ext, where(a, b)) for a in offsets for b in offsets]
        parts.append((shapes.concatenate(stickers), CUBE_FACES[k]))
    return Geometry(tuple(parts), (col.box_part((s, s, s), (0, 0, s / 2)),))


@builder(NoOptions)
def skateboard(v: Variant, _: NoOptions) -> Geometry:
    """A skateboard on its wheels: rounded deck with grip tape, two trucks, four wheels."""
    x, y, z = v.size
    wheel_r, wheel_w = 0.27 * z, 0.16 * y
    deck_t = 0.12 * z
    deck = shapes.slab(x, y, deck_t, y / 2 - 0.001, (0, 0, z - deck_t / 2))
    grip = shapes.slab(x - 0.02, y - 0.02, 0.001, y / 2 - 0.012, (0, 0, z - 0.0004))
    axle_x = 0.33 * x
    trucks = [
        shapes.box((0.05 * x, 0.75 * y, z - deck_t - wheel_r + 0.004), (sx * axle_x, 0, (z - deck_t + wheel_r) / 2))
        for sx in (1, -1)
    ]
    wheels = [
        shapes.cylinder(wheel_r, wheel_w, (sx * axle_x, sy * (y / 2 - wheel_w / 2), wheel_r), axis="y", sections=16)
        for sx in (1, -1)
        for sy in (1, -1)
    ]
    parts = [(deck, v.color(0, P.WOOD)), (grip, P.BLACK), (shapes.concatenate(trucks), P.SILVER)]
    parts.append((shapes.concatenate(wheels), v.color(1, P.WHITE)))
    collision = (col.hull_part(deck), col.hull_part(_points(*trucks, *wheels)))
    return Geometry(tuple(parts), collision)


@builder(NoOptions)
def multimeter(v: Variant, _: NoOptions) -> Geometry:
    """A digital multimeter lying on its back: rubber holster, display at +x, rotary dial, probe jacks at -x."""
    x, y, z = v.size
    holster = shapes.rounded_box((x, y, z), 0.12 * min(x, y), (0, 0, z / 2))
    face = shapes.box((0.86 * x, 0.8 * y, 0.002), (0, 0, z - 0.0009))
    screen = shapes.box((0.6 * x, 0.28 * y, 0.002), (0.24 * x, 0, z - 0.0004))
    dial = shapes.cylinder(0.26 * min(x, y), 0.004, (-0.1 * x, 0, z - 0.0015), sections=32)
    jacks = [
        shapes.cylinder(0.05 * min(x, y), 0.002, (-0.38 * x, jy * y, z - 0.0005), sections=12)
        for jy in (-0.25, 0, 0.25)
    ]
    parts = [(holster, v.color(0, P.YELLOW)), (face, v.color(1, P.CHARCOAL)), (screen, P.rgb(170, 190, 160))]
    parts += [(dial, P.BLACK), (shapes.concatenate(jacks), P.RED)]
    return Geometry(tuple(parts), (col.hull_part(holster),))


@builder(NoOptions)
def oil_can(v: Variant, _: NoOptions) -> Geometry:
    """A pump oil can standing on its flat base: squat body, domed top, long spout to +x, loop handle at -x."""
    body = shapes.lathe([(0, 0), (0.3, 0), (0.3, 0.3), (0.22, 0.42), (0.08, 0.46), (0, 0.46)], 40)
    spout_mesh, spout_parts = spout(np.array([0.0, 0.0, 0.42]), np.array([0.62, 0.0, 1.0]), 0.04, 0.05, 0.015)
    handle_mesh, handle_parts = loop_handle(0.28, 0.38, 0.12, 0.16, 0.03, yaw=np.pi)
    color = v.color(0, P.RED)
    parts = [(body, color), (spout_mesh, v.color(1, P.BRASS)), (handle_mesh, color)]
    hulls = [body.vertices, *(c.vertices for c in spout_parts + handle_parts if c.vertices is not None)]
    return _fitted(parts, hulls, v.size)


@builder(NoOptions)
def spray_paint(v: Variant, _: NoOptions) -> Geometry:
    """An aerosol can of spray paint standing upright: steel can with a domed shoulder, coloured cap."""
    x, _y, z = v.size
    r = x / 2
    cap_h = 0.2 * z
    can_h = z - cap_h
    can = shapes.lathe([(0, 0), (r - 0.002, 0), (r, 0.004), (r, can_h - 0.2 * r), (0.55 * r, can_h), (0, can_h)], 40)
    label = shapes.cylinder(r + 0.0003, 0.55 * can_h, (0, 0, 0.45 * can_h), sections=40)
    cap = shapes.lathe(
        [(0, can_h - 0.02 * z), (0.94 * r, can_h - 0.02 * z), (0.94 * r, z - 0.003), (0.9 * r, z), (0, z)], 40
    )
    parts = [(can, P.SILVER), (label, v.color(1, P.BLACK)), (cap, v.color(0, P.RED))]
    return Geometry(tuple(parts), (col.hull_part(_points(can, cap)),))


@builder(NoOptions)
def camping_lantern(v: Variant, _: NoOptions) -> Geometry:
    """A battery camping lantern: round base, glowing globe between posts, top cap, bail handle standing up."""
    base = shapes.lathe([(0, 0), (0.42, 0), (0.45, 0.05), (0.4, 0.2), (0, 0.2)], 40)
    globe = shapes.cylinder(0.3, 0.42, (0, 0, 0.41), sections=40)
    posts = shapes.concatenate(
        [shapes.cylinder(0.03, 0.44, (0.33 * np.cos(a), 0.33 * np.sin(a), 0.41), sections=8) for a in (0.5, 2.6, 4.7)]
    )
    cap = shapes.lathe([(0, 0.62), (0.4, 0.62), (0.3, 0.74), (0.1, 0.78), (0, 0.78)], 40)
    t = np.linspace(0, np.pi, 17)
    bail = shapes.tube(np.stack([np.zeros_like(t), 0.3 * np.cos(t), 0.74 + 0.24 * np.sin(t)], 1), 0.02, sides=8)
    main = v.color(0, P.GREEN)
    parts = [(base, main), (globe, v.color(1, P.rgb(255, 240, 190, 0.85))), (posts, main), (cap, main), (bail, P.BLACK)]
    return _fitted(parts, [_points(base, globe, posts, cap), bail.vertices], v.size)


@builder(NoOptions)
def extension_cord(v: Variant, _: NoOptions) -> Geometry:
    """A coiled extension cord lying flat: three loops of cable, a plug and a socket block beside the coil."""
    loops = []
    for k, (dx, dy) in enumerate(((0.0, 0.0), (0.03, -0.02), (-0.02, 0.03))):
        loop = trimesh.creation.torus(0.34, 0.035, major_sections=40, minor_sections=10)
        loop.apply_translation((dx, dy, 0.035 + 0.05 * k))
        loops.append(loop)
    socket = shapes.rounded_box((0.3, 0.16, 0.12), 0.02, (0.5, -0.25, 0.06))
    plug = shapes.rounded_box((0.14, 0.1, 0.08), 0.02, (0.42, 0.25, 0.04))
    prongs = shapes.concatenate([shapes.box((0.08, 0.012, 0.03), (0.52, 0.25 + s * 0.025, 0.04)) for s in (1, -1)])
    main = v.color(0, P.ORANGE)
    parts = [(shapes.concatenate(loops), main), (socket, v.color(1, P.WHITE)), (plug, main), (prongs, P.BRASS)]
    edges = np.linspace(0, 2 * np.pi, 9)
    hulls = []
    for a0, a1 in zip(edges[:-1], edges[1:], strict=True):
        ang = np.linspace(a0, a1, 4)
        hulls.append(
            np.vstack(
                [
                    np.stack([rr * np.cos(ang), rr * np.sin(ang), np.full_like(ang, hz)], 1)
                    for rr in (0.29, 0.4)
                    for hz in (0.0, 0.17)
                ]
            )
        )
    hulls += [socket.vertices, _points(plug, prongs)]
    return _fitted(parts, hulls, v.size)


@dataclass(frozen=True)
class FastenerBoxShape:
    """Nail heads (plain discs) or screw heads (discs with a cross) showing in the open box."""

    screws: bool = False


@builder(FastenerBoxShape)
def fastener_box(v: Variant, p: FastenerBoxShape) -> Geometry:
    """A small open box filled to the brim with nails or screws; one solid block of collision (it is full)."""
    x, y, z = v.size
    wall = 0.0025
    box = trimesh.boolean.difference(
        [shapes.box((x, y, z), (0, 0, z / 2)), shapes.box((x - 2 * wall, y - 2 * wall, z), (0, 0, z / 2 + 0.003))],
        engine="manifold",
    )
    fill_top = 0.9 * z
    fill = shapes.box((x - 2 * wall, y - 2 * wall, fill_top - 0.003), (0, 0, 0.003 + (fill_top - 0.003) / 2))
    rng = np.random.default_rng(7)
    head_r = min(0.004, 0.08 * min(x, y))
    heads = []
    for _k in range(18):
        hx, hy = (
            rng.uniform(-x / 2 + wall + head_r, x / 2 - wall - head_r),
            rng.uniform(-y / 2 + wall + head_r, y / 2 - wall - head_r),
        )
        heads.append(
            shapes.cylinder(
                head_r, 0.0015, (hx, hy, fill_top + 0.0007 + rng.uniform(0, 0.3) * (z - fill_top - 0.0015)), sections=10
            )
        )
        if p.screws:
            heads.append(shapes.box((1.6 * head_r, 0.25 * head_r, 0.0004), (hx, hy, heads[-1].bounds[1][2])))
    metal = v.color(1, P.STEEL)
    parts = [(box, v.color(0, P.CARDBOARD)), (fill, P.rgb(120, 120, 125)), (shapes.concatenate(heads), metal)]
    return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


@builder(NoOptions)
def kite(v: Variant, _: NoOptions) -> Geometry:
    """A diamond kite lying flat: sail with two crossed spars, a wavy ribbon tail at -x."""
    sail = Polygon([(0.5, 0.0), (0.2, 0.3), (-0.2, 0.0), (0.2, -0.3)])
    spars = [_strip([(0.5, 0.0), (-0.2, 0.0)], 0.015), _strip([(0.2, 0.3), (0.2, -0.3)], 0.015)]
    tail_pts = [(-0.2 - 0.06 * k, 0.05 * np.sin(1.4 * k)) for k in range(6)]
    tail = _strip(tail_pts, 0.02)
    sail_mesh = _slab(sail, 0.008)
    spar_mesh = shapes.concatenate([_slab(s, 0.015) for s in spars])
    tail_mesh = _slab(tail, 0.006)
    bows = shapes.concatenate([_slab(Point(pt).buffer(0.03, quad_segs=4), 0.01) for pt in tail_pts[1::2]])
    parts = [(sail_mesh, v.color(0, P.RED)), (spar_mesh, P.WOOD), (tail_mesh, v.color(1, P.YELLOW))]
    parts.append((bows, v.color(2, P.BLUE)))
    return _fitted(parts, [_points(sail_mesh, spar_mesh), _points(tail_mesh, bows)], v.size)


@builder(NoOptions)
def watering_can(v: Variant, _: NoOptions) -> Geometry:
    """A watering can facing +x: oval tank, long spout rising to a rose at +x, carry handle arching over the top."""
    tank = shapes.lathe([(0, 0), (0.28, 0), (0.3, 0.03), (0.3, 0.5), (0.24, 0.6), (0, 0.6)], 40)
    tank.apply_scale((1.0, 0.7, 1.0))
    spout_mesh, spout_parts = spout(np.array([0.2, 0.0, 0.12]), np.array([0.7, 0.0, 0.72]), 0.0, 0.05, 0.03)
    rose = shapes.cone(0.035, 0.08, 0.07, (0.72, 0, 0.74), axis="x", sections=16)
    t = np.linspace(0.15 * np.pi, 0.95 * np.pi, 15)
    handle = shapes.tube(np.stack([-0.05 + 0.3 * np.cos(t), np.zeros_like(t), 0.55 + 0.3 * np.sin(t)], 1), 0.035, 10)
    color = v.color(0, P.GREEN)
    parts = [(tank, color), (spout_mesh, color), (rose, v.color(1, color)), (handle, color)]
    hulls = [tank.vertices, *(c.vertices for c in spout_parts if c.vertices is not None), rose.vertices]
    hulls.append(handle.vertices)
    return _fitted(parts, hulls, v.size)


@builder(NoOptions)
def trowel(v: Variant, _: NoOptions) -> Geometry:
    """A garden trowel lying flat: pointed steel blade towards -x, a neck and a round handle at +x."""
    blade = Polygon([(-0.5, 0.0), (-0.3, 0.16), (0.02, 0.14), (0.04, -0.14), (-0.3, -0.16)]).buffer(0.01)
    neck = _strip([(0.0, 0.0), (0.12, 0.0)], 0.05)
    grip = shapes.rounded_rect(0.36, 0.12, 0.055, (0.3, 0.0))
    blade_mesh, neck_mesh, grip_mesh = _slab(blade, 0.02), _slab(neck, 0.04), _slab(grip, 0.1)
    parts = [(blade_mesh, P.STEEL), (neck_mesh, P.STEEL), (grip_mesh, v.color(0, P.GREEN))]
    return _fitted(parts, [blade_mesh.vertices, _points(neck_mesh, grip_mesh)], v.size)


@dataclass(frozen=True)
class BoatShape:
    """A sailing boat (mast and sail) instead of a tug with a cabin and funnel."""

    sail: bool = True


@builder(BoatShape)
def toy_boat(v: Variant, p: BoatShape) -> Geometry:
    """A toy boat on its flat keel, bow towards +x: hull with a deck stripe, then a mast and sail or a cabin."""
    outline = Polygon([(-0.5, -0.16), (0.2, -0.16), (0.5, 0.0), (0.2, 0.16), (-0.5, 0.16)]).buffer(0.02)
    hull = _slab(outline, 0.2)
    deck = _slab(outline.buffer(-0.03), 0.01, 0.2)
    main, accent = v.color(0, P.RED), v.color(1, P.WHITE)
    parts = [(hull, main), (deck, P.LIGHT_WOOD)]
    if p.sail:
        mast = shapes.cylinder(0.02, 0.8, (0.0, 0, 0.6), sections=12)
        sail = shapes.hull(
            [[sx, sy, sz] for sx, sz in ((0.0, 0.25), (0.0, 0.95), (-0.42, 0.25)) for sy in (-0.006, 0.006)]
        )
        parts += [(mast, P.WOOD), (sail, accent)]
        return _fitted(parts, [_points(hull, deck), _points(mast, sail)], v.size)
    cabin = shapes.box((0.36, 0.24, 0.18), (-0.15, 0, 0.3))
    funnel = shapes.cylinder(0.06, 0.18, (-0.2, 0, 0.48), sections=16)
    parts += [(cabin, accent), (funnel, v.color(2, P.BLACK))]
    return _fitted(parts, [_points(hull, deck), _points(cabin, funnel)], v.size)


@builder(NoOptions)
def play_dough(v: Variant, _: NoOptions) -> Geometry:
    """A tub of modelling dough standing on its base: translucent-looking tub, coloured snap lid, label band."""
    x, z = v.size[0], v.size[2]
    r = x / 2
    lid_h = 0.18 * z
    tub = shapes.lathe([(0, 0), (0.9 * r, 0), (0.95 * r, z - lid_h), (0, z - lid_h)], 40)
    lid = shapes.lathe([(0, z - lid_h - 0.004), (r, z - lid_h - 0.004), (r, z - 0.002), (0.97 * r, z), (0, z)], 40)
    label = shapes.lathe(
        [(0, 0.2 * z), (0.913 * r + 0.0006, 0.2 * z), (0.935 * r + 0.0006, 0.65 * z), (0, 0.65 * z)], 40
    )
    parts = [(tub, P.WHITE), (label, v.color(1, P.YELLOW)), (lid, v.color(0, P.RED))]
    return Geometry(tuple(parts), (col.hull_part(_points(tub, lid)),))


@builder(NoOptions)
def ratchet(v: Variant, _: NoOptions) -> Geometry:
    """A socket ratchet lying flat: round head with a reversing lever at -x, a handle with a rubber grip to +x."""
    head = _slab(Point(-0.38, 0).buffer(0.11, quad_segs=12).union(shapely_box(-0.38, -0.06, -0.2, 0.06)), 0.12)
    lever = _slab(_strip([(-0.4, 0.0), (-0.33, 0.05)], 0.03), 0.02, 0.12)
    shank = _slab(shapely_box(-0.22, -0.045, 0.1, 0.045), 0.08)
    grip = _slab(shapes.rounded_rect(0.42, 0.11, 0.05, (0.29, 0.0)), 0.1)
    parts = [(head, P.STEEL), (lever, P.CHARCOAL), (shank, P.STEEL), (grip, v.color(0, P.RED))]
    return _fitted(parts, [_points(head, lever), _points(shank, grip)], v.size)


@builder(NoOptions)
def jump_rope(v: Variant, _: NoOptions) -> Geometry:
    """A skipping rope lying flat in a loose loop, its two handles side by side at +x."""
    t = np.linspace(0.15 * np.pi, 1.85 * np.pi, 40)
    loop = np.stack([-0.1 + 0.35 * np.cos(t), 0.42 * np.sin(t), np.full_like(t, 0.02)], 1)
    ends = [np.array([[0.3, s * 0.09, 0.04], [0.5, s * 0.09, 0.04]]) for s in (1, -1)]
    rope_path = np.vstack([[0.3, 0.09, 0.02], loop[::-1], [0.3, -0.09, 0.02]])
    rope = shapes.tube(rope_path, 0.02, sides=8)
    handles = [shapes.tube(e, 0.04, sides=10) for e in ends]
    parts = [(rope, v.color(1, P.WHITE)), (handles[0], v.color(0, P.RED)), (handles[1], v.color(0, P.RED))]
    pieces = [c.vertices for c in col.tube_parts(rope_path, 0.02, 8) if c.vertices is not None]
    return _fitted(parts, [*pieces, handles[0].vertices, handles[1].vertices], v.size)


CATEGORIES: tuple[CategoryDef, ...] = builtin_categories(__name__, globals())  # variants: data/workshop.json
