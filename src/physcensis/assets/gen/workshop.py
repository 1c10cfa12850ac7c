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
from physcensis.assets.model import RGBA, Cavity
from physcensis.assets.spec import CategoryDef, Geometry, NoOptions, Variant, builder, define
from physcensis.assets.spec import Variant as V

RAINBOW = (P.RED, P.ORANGE, P.YELLOW, P.GREEN, P.TEAL, P.BLUE, P.PURPLE, P.PINK)
KIDS = ("toy", "kids", "children", "play", "playroom")
TOOLS = ("tool", "tools", "workshop", "garage", "diy")


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


KIDS_CATEGORIES: tuple[CategoryDef, ...] = (
    define(
        "rubber duck",
        "rubber duck",
        rubber_duck,
        [
            V("yellow", "a classic yellow rubber duck with an orange beak", (0.09, 0.07, 0.085)),
            V("small_yellow", "a small yellow squeaky bath duck", (0.06, 0.047, 0.057)),
            V("large_yellow", "a large yellow vinyl rubber duck", (0.16, 0.12, 0.15), mass=0.09),
            V("pink", "a pink rubber bath duck", (0.09, 0.07, 0.085), (P.PINK, P.ORANGE)),
            V("blue", "a blue rubber duckie", (0.09, 0.07, 0.085), (P.SKY, P.YELLOW)),
            V("black", "a black rubber duck with a yellow beak", (0.1, 0.077, 0.095), (P.BLACK, P.YELLOW)),
            V("white", "a white rubber duck with a red beak", (0.08, 0.062, 0.076), (P.WHITE, P.RED), {"head": 0.27}),
            V("green", "a green vinyl bath toy duck", (0.09, 0.07, 0.085), (P.LIME, P.ORANGE)),
        ],
        density=120.0,
        mass_limits=(0.005, 0.15),
        friction=(0.6, 1.0),
        support_probability=0.05,
        has_front=True,
        synonyms=("rubber ducky", "rubber duckie", "bath duck", "duck", "squeaky duck", "bath toy", "duckie"),
        tags=(*KIDS, "bath", "rubber", "squeaky"),
    ),
    define(
        "dice",
        "dice",
        dice,
        [
            V("white", "a white plastic six-sided die with black pips", (0.016, 0.016, 0.016)),
            V(
                "red",
                "a red translucent casino die",
                (0.019, 0.019, 0.019),
                (P.rgb(200, 30, 30, 0.9), P.WHITE),
                {"rounding": 0.05},
                synonyms=("casino die",),
            ),
            V("black", "a black die with white dots", (0.016, 0.016, 0.016), (P.BLACK, P.WHITE)),
            V("small_ivory", "a small ivory-coloured game die", (0.012, 0.012, 0.012), (P.CREAM, P.BLACK)),
            V("blue", "a blue plastic dice cube with white spots", (0.016, 0.016, 0.016), (P.BLUE, P.WHITE)),
            V(
                "wood",
                "a wooden die with burnt black dots",
                (0.02, 0.02, 0.02),
                (P.LIGHT_WOOD, P.DARK_BROWN),
                {"rounding": 0.1},
                density=650.0,
            ),
            V(
                "foam_big",
                "a big green foam play die",
                (0.1, 0.1, 0.1),
                (P.GREEN, P.WHITE),
                {"rounding": 0.2},
                density=40.0,
                synonyms=("foam dice",),
            ),
            V("blank", "a plain yellow blank die without pips", (0.016, 0.016, 0.016), (P.YELLOW,), {"pips": False}),
        ],
        density=1200.0,
        mass_limits=(0.001, 0.1),
        friction=(0.4, 0.7),
        support_probability=0.3,
        has_front=False,
        synonyms=("die", "dice cube", "game die", "six-sided die", "d6"),
        tags=("game", "board game", "cube", "gambling", "kids", "play"),
    ),
    define(
        "spinning top",
        "spinning top",
        spinning_top,
        [
            V("red_wood", "a red wooden spinning top with a yellow band", (0.06, 0.06, 0.07)),
            V("blue_wood", "a blue painted wooden whirligig top", (0.055, 0.055, 0.065), (P.BLUE, P.WHITE, P.WOOD)),
            V("natural", "an unpainted beech wood spinning top", (0.05, 0.05, 0.06), (P.LIGHT_WOOD, P.WOOD, P.WOOD)),
            V(
                "tin_large",
                "a large striped tin humming top",
                (0.16, 0.16, 0.2),
                (P.RED, P.YELLOW, P.SILVER),
                {"stem": 0.22},
                density=250.0,
                synonyms=("humming top", "tin top"),
            ),
            V(
                "green_small",
                "a small green plastic spin top",
                (0.035, 0.035, 0.04),
                (P.GREEN, P.ORANGE, P.GREEN),
                density=500.0,
            ),
            V(
                "rainbow",
                "a purple and pink peg top",
                (0.07, 0.07, 0.075),
                (P.PURPLE, P.PINK, P.WOOD),
                {"base": 0.4},
                synonyms=("peg top",),
            ),
            V(
                "gold_metal",
                "a gold metal precision spinning top",
                (0.04, 0.04, 0.045),
                (P.GOLD, P.BRASS, P.GOLD),
                {"stem": 0.4},
                density=2500.0,
            ),
        ],
        density=700.0,
        mass_limits=(0.005, 0.6),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("top", "toy top", "spin top", "whirligig", "peg top", "dreidel"),
        tags=(*KIDS, "spinning", "wooden"),
    ),
    define(
        "building brick",
        "building brick",
        building_brick,
        [
            V("red_2x4", "a red 2x4 interlocking plastic brick with studs", (0.032, 0.016, 0.0114)),
            V("blue_2x2", "a blue 2 by 2 stud brick", (0.016, 0.016, 0.0114), (P.BLUE,), {"studs_x": 2}),
            V(
                "yellow_2x6",
                "a long yellow 2x6 construction brick",
                (0.048, 0.016, 0.0114),
                (P.YELLOW,),
                {"studs_x": 6},
            ),
            V(
                "green_plate",
                "a flat green 2x4 brick plate",
                (0.032, 0.016, 0.005),
                (P.GREEN,),
                synonyms=("brick plate",),
            ),
            V("white_1x4", "a white 1x4 slim building brick", (0.032, 0.008, 0.0114), (P.WHITE,), {"studs_y": 1}),
            V(
                "duplo_red",
                "a big red toddler brick, 2x4 studs",
                (0.064, 0.032, 0.024),
                (P.RED,),
                synonyms=("duplo", "duplo brick", "large brick"),
                density=300.0,
            ),
            V(
                "duplo_orange",
                "a big orange toddler brick with 2x2 studs",
                (0.032, 0.032, 0.024),
                (P.ORANGE,),
                {"studs_x": 2},
                synonyms=("duplo",),
                density=300.0,
            ),
            V("black_1x2", "a small black 1x2 brick", (0.016, 0.008, 0.0114), (P.BLACK,), {"studs_x": 2, "studs_y": 1}),
        ],
        density=420.0,
        mass_limits=(0.0003, 0.05),
        friction=(0.5, 0.8),
        support_probability=0.6,
        has_front=False,
        synonyms=(
            "lego",
            "lego brick",
            "interlocking brick",
            "construction brick",
            "toy brick",
            "brick",
            "building bricks",
            "lego piece",
            "stud brick",
        ),
        tags=(*KIDS, "plastic", "construction", "stackable"),
    ),
    define(
        "doll",
        "doll",
        doll,
        [
            V("pink_dress", "a standing doll in a long pink dress with brown hair", (0.12, 0.12, 0.3)),
            V(
                "blue_dress",
                "a blonde doll in a blue gown",
                (0.12, 0.12, 0.3),
                (P.rgb(240, 200, 170), P.SKY, P.rgb(230, 200, 110)),
            ),
            V(
                "princess",
                "a princess doll in a purple ball gown",
                (0.16, 0.16, 0.35),
                (P.rgb(240, 200, 170), P.PURPLE, P.rgb(230, 200, 110)),
                synonyms=("princess doll",),
            ),
            V(
                "baby_sitting",
                "a sitting baby doll in a white romper",
                (0.2, 0.2, 0.28),
                (P.rgb(245, 210, 185), P.WHITE, P.rgb(120, 80, 40)),
                {"pose": "sitting", "hair": "short"},
                synonyms=("baby doll",),
            ),
            V(
                "rag_doll",
                "a soft rag doll in a red dress, sitting",
                (0.16, 0.16, 0.22),
                (P.rgb(250, 220, 195), P.RED, P.ORANGE),
                {"pose": "sitting"},
                density=150.0,
                synonyms=("rag doll", "cloth doll"),
            ),
            V(
                "small_green",
                "a small doll in a green dress with short hair",
                (0.07, 0.07, 0.16),
                (P.rgb(200, 150, 110), P.GREEN, P.BLACK),
                {"hair": "short"},
            ),
            V(
                "sitting_boy",
                "a sitting boy doll in blue overalls",
                (0.17, 0.18, 0.25),
                (P.rgb(230, 190, 160), P.NAVY, P.DARK_BROWN),
                {"pose": "sitting", "hair": "short"},
            ),
        ],
        density=300.0,
        mass_limits=(0.03, 1.2),
        friction=(0.6, 0.9),
        support_probability=0.0,
        has_front=True,
        synonyms=("dolly", "toy doll", "dolls", "baby doll", "puppet"),
        tags=(*KIDS, "girl", "dress"),
    ),
    define(
        "xylophone",
        "toy xylophone",
        xylophone,
        [
            V("rainbow_wood", "a wooden toy xylophone with eight rainbow bars", (0.3, 0.13, 0.04)),
            V("small", "a small baby xylophone with five bars", (0.2, 0.1, 0.035), options={"bars": 5}),
            V(
                "white_frame",
                "a white framed kids' glockenspiel with metal bars",
                (0.32, 0.14, 0.04),
                (P.WHITE,),
                synonyms=("glockenspiel", "metallophone"),
            ),
            V("large", "a large twelve-bar toy xylophone", (0.42, 0.16, 0.045), options={"bars": 12}),
            V("red_frame", "a red plastic toy xylophone", (0.26, 0.12, 0.035), (P.RED,), density=300.0),
            V("natural", "a natural beech xylophone with six bars", (0.24, 0.11, 0.035), (P.LIGHT_WOOD,), {"bars": 6}),
            V("blue_frame", "a blue baby xylophone", (0.22, 0.1, 0.035), (P.BLUE,), {"bars": 7}, density=300.0),
        ],
        density=550.0,
        mass_limits=(0.08, 1.5),
        friction=(0.5, 0.8),
        support_probability=0.1,
        has_front=False,
        synonyms=(
            "toy xylophone",
            "glockenspiel",
            "kids xylophone",
            "children's xylophone",
            "children's glockenspiel",
            "musical toy",
            "toy piano bars",
        ),
        tags=(*KIDS, "music", "instrument", "musical", "rainbow"),
    ),
    define(
        "stacking rings",
        "stacking rings toy",
        stacking_rings,
        [
            V("rainbow", "a rainbow ring stacker with five rings on a red base", (0.12, 0.12, 0.2)),
            V("large", "a tall stacking rings toy with seven rings", (0.15, 0.15, 0.26), options={"rings": 7}),
            V("small", "a small baby ring stacker with four rings", (0.09, 0.09, 0.15), options={"rings": 4}),
            V(
                "wood_pastel",
                "a wooden ring stacker in pastel colours",
                (0.11, 0.11, 0.19),
                (P.LIGHT_WOOD, P.PINK, P.SKY, P.CREAM, P.LIME, P.YELLOW),
                density=600.0,
            ),
            V(
                "blue_base",
                "a blue-based stacking cone with rainbow rings",
                (0.13, 0.13, 0.22),
                (P.BLUE,),
                options={"rings": 6},
            ),
            V(
                "green_plastic",
                "a green and white plastic stacking rings toy",
                (0.12, 0.12, 0.19),
                (P.GREEN, P.WHITE, P.LIME),
            ),
            V(
                "grey_modern",
                "a grey and white modern ring stacker",
                (0.1, 0.1, 0.17),
                (P.GREY, P.WHITE, P.SILVER, P.CHARCOAL),
                {"rings": 5},
            ),
        ],
        density=250.0,
        mass_limits=(0.05, 0.9),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=False,
        synonyms=(
            "ring stacker",
            "stacking toy",
            "rock a stack",
            "stacking cone",
            "stacking rings toy",
            "ring stack",
            "stacker",
        ),
        tags=(*KIDS, "baby", "toddler", "rings", "rainbow"),
    ),
    define(
        "crayons",
        "crayon box",
        crayon_box,
        [
            V("yellow_8", "a yellow box of eight wax crayons", (0.025, 0.09, 0.11)),
            V(
                "green_16",
                "a green box of sixteen crayons in two rows",
                (0.03, 0.09, 0.11),
                (P.GREEN, P.YELLOW),
                {"count": 16},
            ),
            V(
                "small_4",
                "a small four-crayon pack from a restaurant",
                (0.012, 0.05, 0.1),
                (P.WHITE, P.RED),
                {"count": 4},
            ),
            V("big_24", "a big box of twenty-four crayons", (0.045, 0.14, 0.12), (P.ORANGE, P.GREEN), {"count": 24}),
            V(
                "blue_12",
                "a blue cardboard pack of twelve coloured crayons",
                (0.022, 0.12, 0.11),
                (P.BLUE, P.WHITE),
                {"count": 12},
            ),
            V("red_10", "a red carton of ten chunky crayons", (0.03, 0.13, 0.12), (P.RED, P.YELLOW), {"count": 10}),
            V("purple_6", "a purple pack of six jumbo crayons", (0.025, 0.1, 0.1), (P.PURPLE, P.PINK), {"count": 6}),
        ],
        density=700.0,
        mass_limits=(0.02, 0.6),
        friction=(0.5, 0.8),
        support_probability=0.1,
        has_front=True,
        synonyms=(
            "crayon",
            "crayon box",
            "box of crayons",
            "wax crayons",
            "crayon pack",
            "colouring crayons",
            "coloring crayons",
            "crayola",
        ),
        tags=(*KIDS, "drawing", "colouring", "coloring", "art", "craft", "wax"),
    ),
    define(
        "board game",
        "board game box",
        game_box,
        [
            V("blue", "a blue boxed family board game", (0.4, 0.27, 0.055)),
            V("red_square", "a square red board game box", (0.27, 0.27, 0.055), (P.RED, P.WHITE, P.YELLOW)),
            V(
                "green_small",
                "a small green card game box",
                (0.16, 0.12, 0.04),
                (P.GREEN, P.WHITE, P.YELLOW),
                synonyms=("card game",),
            ),
            V("black_strategy", "a black strategy game box", (0.3, 0.3, 0.08), (P.BLACK, P.GOLD, P.RED)),
            V(
                "chess",
                "a wooden chess set box",
                (0.3, 0.15, 0.06),
                (P.DARK_BROWN, P.LIGHT_WOOD, P.CREAM),
                density=500.0,
                synonyms=("chess set", "chess", "checkers"),
            ),
            V("yellow_kids", "a yellow kids' board game box", (0.27, 0.27, 0.055), (P.YELLOW, P.BLUE, P.RED)),
            V("orange_long", "a long orange boxed party game", (0.4, 0.2, 0.07), (P.ORANGE, P.PURPLE, P.WHITE)),
        ],
        density=170.0,
        mass_limits=(0.1, 2.5),
        friction=(0.4, 0.7),
        support_probability=0.85,
        has_front=False,
        synonyms=("board game", "game box", "boardgame", "family game", "tabletop game", "game"),
        tags=(*KIDS, "games", "family", "cardboard", "flat"),
    ),
    define(
        "jigsaw puzzle",
        "jigsaw puzzle box",
        game_box,
        [
            V(
                "landscape",
                "a boxed 1000-piece jigsaw puzzle with a landscape picture",
                (0.36, 0.26, 0.06),
                options={"picture": "puzzle"},
            ),
            V(
                "small",
                "a small 100-piece kids' jigsaw in a box",
                (0.2, 0.2, 0.04),
                (P.YELLOW, P.PINK, P.GREEN),
                {"picture": "puzzle"},
            ),
            V(
                "sunset",
                "a red boxed puzzle with a sunset picture",
                (0.33, 0.23, 0.05),
                (P.RED, P.ORANGE, P.PURPLE),
                {"picture": "puzzle"},
            ),
            V(
                "square",
                "a square 500-piece jigsaw box",
                (0.25, 0.25, 0.055),
                (P.WHITE, P.SKY, P.BLUE),
                {"picture": "puzzle"},
            ),
            V(
                "large",
                "a large 2000-piece jigsaw puzzle box",
                (0.45, 0.32, 0.07),
                (P.NAVY, P.TEAL, P.DARK_GREEN),
                {"picture": "puzzle"},
            ),
            V(
                "forest",
                "a green boxed forest jigsaw",
                (0.3, 0.22, 0.05),
                (P.DARK_GREEN, P.LIME, P.GREEN),
                {"picture": "puzzle"},
            ),
            V(
                "floor",
                "a tall box of a giant floor puzzle for toddlers",
                (0.3, 0.25, 0.1),
                (P.ORANGE, P.SKY, P.YELLOW),
                {"picture": "puzzle"},
                synonyms=("floor puzzle",),
            ),
        ],
        density=170.0,
        mass_limits=(0.1, 2.5),
        friction=(0.4, 0.7),
        support_probability=0.85,
        has_front=False,
        synonyms=("puzzle", "jigsaw", "puzzle box", "jigsaw box", "box of puzzle pieces", "pieces"),
        tags=("puzzle", "pieces", "games", "family", "cardboard", "flat", "kids"),
    ),
    define(
        "toy bin",
        "toy bin",
        toy_bin,
        [
            V("blue", "an open blue plastic toy bin with hand holes", (0.4, 0.3, 0.22)),
            V("red_large", "a large red toy storage tub", (0.5, 0.38, 0.28), (P.RED, P.DARK_RED)),
            V("green_small", "a small green plastic toy tub", (0.3, 0.22, 0.14), (P.GREEN, P.DARK_GREEN)),
            V("yellow", "a yellow toy storage bin", (0.4, 0.3, 0.2), (P.YELLOW, P.CHARCOAL)),
            V(
                "white",
                "a white plastic storage tub for toys",
                (0.45, 0.32, 0.24),
                (P.WHITE, P.GREY),
                synonyms=("toy storage tub",),
            ),
            V(
                "pink_fabric",
                "a pink fabric toy storage cube",
                (0.3, 0.3, 0.28),
                (P.PINK, P.PURPLE),
                {"radius": 0.01, "wall": 0.008},
                density=120.0,
                synonyms=("fabric toy bin", "toy storage cube"),
            ),
            V(
                "grey_fabric",
                "a grey felt toy box without a lid",
                (0.38, 0.26, 0.24),
                (P.GREY, P.CHARCOAL),
                {"radius": 0.01, "wall": 0.008},
                density=120.0,
                synonyms=("felt bin", "toy box"),
            ),
            V(
                "clear",
                "a clear plastic toy tub",
                (0.36, 0.26, 0.16),
                (P.rgb(210, 225, 235, 0.6), P.GREY),
                {"handles": False},
            ),
        ],
        density=450.0,
        mass_limits=(0.15, 3.5),
        friction=(0.5, 0.8),
        support_probability=0.3,
        has_front=False,
        synonyms=("toy box", "toy chest", "storage tub", "toybox"),
        tags=("kids", "children", "playroom", "storage", "container", "open", "bin", "tidy"),
    ),
)


TOOL_CATEGORIES: tuple[CategoryDef, ...] = (
    define(
        "wrench",
        "wrench",
        wrench,
        [
            V("combination_13", "a 13 mm chrome steel combination spanner", (0.17, 0.032, 0.007)),
            V("combination_19", "a large 19 mm combination wrench", (0.24, 0.045, 0.009)),
            V("combination_8", "a small 8 mm steel spanner", (0.12, 0.022, 0.005)),
            V(
                "open_ended",
                "a double open-ended steel spanner",
                (0.18, 0.034, 0.007),
                options={"style": "open"},
                synonyms=("open end wrench", "open ended spanner"),
            ),
            V(
                "adjustable_200",
                "an adjustable steel wrench, 200 mm",
                (0.2, 0.056, 0.014),
                options={"style": "adjustable"},
                synonyms=("adjustable wrench", "adjustable spanner", "crescent wrench", "monkey wrench"),
            ),
            V(
                "adjustable_small",
                "a small adjustable crescent wrench with a red handle",
                (0.15, 0.042, 0.011),
                (P.rgb(190, 60, 50),),
                {"style": "adjustable"},
                synonyms=("adjustable wrench", "crescent wrench"),
            ),
            V(
                "black_oxide",
                "a black oxide 17 mm ring spanner",
                (0.21, 0.04, 0.008),
                (P.CHARCOAL,),
                synonyms=("ring spanner",),
            ),
        ],
        density=7800.0,
        mass_limits=(0.01, 0.8),
        friction=(0.3, 0.6),
        support_probability=0.0,
        has_front=False,
        synonyms=("spanner", "wrench", "combination wrench", "box wrench", "ring spanner"),
        tags=(*TOOLS, "steel", "bolts", "nuts", "mechanic", "hand tool"),
    ),
    define(
        "pliers",
        "pliers",
        pliers,
        [
            V("red_combination", "a pair of combination pliers with red grips", (0.2, 0.055, 0.016)),
            V(
                "blue_combination",
                "blue-handled lineman's pliers",
                (0.22, 0.06, 0.018),
                (P.BLUE,),
                synonyms=("lineman pliers",),
            ),
            V(
                "needle_nose",
                "needle-nose pliers with yellow grips",
                (0.16, 0.045, 0.012),
                (P.YELLOW,),
                {"nose": "needle"},
                synonyms=("needle nose pliers", "long nose pliers"),
            ),
            V(
                "needle_small",
                "small jewellery pliers with pink handles",
                (0.12, 0.04, 0.01),
                (P.PINK,),
                {"nose": "needle"},
            ),
            V("black_large", "large black-handled pliers", (0.25, 0.07, 0.02), (P.BLACK,)),
            V(
                "orange",
                "orange-gripped slip joint pliers",
                (0.2, 0.055, 0.016),
                (P.ORANGE,),
                synonyms=("slip joint pliers",),
            ),
            V("green_needle", "green needle nose pliers", (0.18, 0.05, 0.013), (P.GREEN,), {"nose": "needle"}),
        ],
        density=5500.0,
        mass_limits=(0.03, 0.8),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("plier", "pair of pliers", "pincers", "grips"),
        tags=(*TOOLS, "steel", "grip", "wire", "hand tool"),
    ),
    define(
        "power drill",
        "power drill",
        power_drill,
        [
            V("yellow", "a yellow and black cordless power drill", (0.22, 0.08, 0.24), mass=1.6),
            V("green", "a green cordless drill driver", (0.21, 0.075, 0.23), (P.GREEN, P.CHARCOAL), mass=1.4),
            V(
                "red",
                "a red cordless hammer drill",
                (0.23, 0.085, 0.25),
                (P.RED, P.BLACK),
                mass=1.9,
                synonyms=("hammer drill",),
            ),
            V("teal", "a teal compact drill driver", (0.18, 0.075, 0.21), (P.TEAL, P.BLACK), {"body": 0.6}, mass=1.2),
            V("blue", "a blue battery drill", (0.21, 0.08, 0.23), (P.BLUE, P.CHARCOAL), mass=1.5),
            V(
                "orange",
                "an orange cordless screwdriver drill",
                (0.2, 0.07, 0.22),
                (P.ORANGE, P.BLACK),
                mass=1.3,
                synonyms=("drill driver", "electric screwdriver"),
            ),
            V(
                "black_small",
                "a small black and grey power drill",
                (0.17, 0.065, 0.19),
                (P.GREY, P.BLACK),
                {"body": 0.6},
                mass=0.9,
            ),
        ],
        density=1100.0,
        mass_limits=(0.5, 3.0),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        synonyms=("drill", "cordless drill", "electric drill", "battery drill", "drill driver", "power tool"),
        tags=(*TOOLS, "power tool", "electric", "cordless", "battery"),
    ),
    define(
        "hand saw",
        "hand saw",
        hand_saw,
        [
            V("wood_handle", "a hand saw with a wooden handle", (0.55, 0.13, 0.025)),
            V(
                "red_handle",
                "a red-handled panel saw",
                (0.6, 0.14, 0.028),
                (P.RED,),
                {"teeth": 50},
                synonyms=("panel saw",),
            ),
            V(
                "small",
                "a small tenon saw with a beech grip",
                (0.35, 0.1, 0.022),
                (P.LIGHT_WOOD,),
                {"teeth": 30},
                synonyms=("tenon saw",),
            ),
            V("black", "a black plastic-handled wood saw", (0.5, 0.12, 0.025), (P.BLACK,), {"teeth": 45}),
            V("yellow", "a yellow-handled carpenter's saw", (0.55, 0.13, 0.025), (P.YELLOW,)),
            V(
                "large",
                "a large rip saw with a dark wooden handle",
                (0.7, 0.16, 0.03),
                (P.DARK_BROWN,),
                {"teeth": 60},
                synonyms=("rip saw",),
            ),
            V("green", "a green toolbox saw", (0.4, 0.11, 0.023), (P.GREEN,), {"teeth": 35}),
        ],
        density=1000.0,
        mass_limits=(0.15, 1.2),
        friction=(0.3, 0.6),
        support_probability=0.0,
        has_front=False,
        synonyms=("saw", "handsaw", "wood saw", "carpenter's saw", "crosscut saw"),
        tags=(*TOOLS, "woodworking", "cutting", "carpentry", "teeth"),
    ),
    define(
        "paint can",
        "paint can",
        paint_can,
        [
            V("gallon_white", "a one-gallon metal can of white paint", (0.17, 0.17, 0.22), mass=4.5),
            V("gallon_blue", "a gallon paint tin with a blue label", (0.17, 0.17, 0.22), (P.BLUE,), mass=4.5),
            V("quart_red", "a quart tin of red paint", (0.11, 0.11, 0.14), (P.RED,), mass=1.3),
            V("quart_green", "a small green paint can", (0.11, 0.11, 0.14), (P.GREEN,), mass=1.3),
            V(
                "litre_yellow",
                "a one-litre tin of yellow gloss paint",
                (0.115, 0.115, 0.125),
                (P.YELLOW,),
                {"handle": False},
                mass=1.4,
            ),
            V(
                "sample",
                "a little paint sample pot",
                (0.065, 0.065, 0.08),
                (P.PINK, P.WHITE),
                {"handle": False},
                mass=0.3,
                synonyms=("sample pot", "tester pot"),
            ),
            V("large_grey", "a large 5-litre tin of grey paint", (0.2, 0.2, 0.25), (P.GREY, P.CHARCOAL), mass=6.5),
        ],
        density=1300.0,
        mass_limits=(0.1, 8.0),
        friction=(0.4, 0.7),
        support_probability=0.4,
        has_front=False,
        synonyms=(
            "paint tin",
            "can of paint",
            "tin of paint",
            "paint pot",
            "paint",
            "paint bucket",
            "wall paint",
            "house paint",
        ),
        tags=(*TOOLS, "paint", "decorating", "metal", "tin", "wall", "wire handle"),
    ),
    define(
        "paintbrush",
        "paintbrush",
        paintbrush,
        [
            V("wood_50", "a 50 mm decorating paintbrush with a wooden handle", (0.24, 0.05, 0.02)),
            V("wood_25", "a narrow 25 mm paint brush", (0.2, 0.025, 0.016), options={"handle": 0.6}),
            V(
                "wide_100",
                "a wide 100 mm wall brush",
                (0.28, 0.1, 0.028),
                options={"handle": 0.3},
                synonyms=("wall brush",),
            ),
            V("red_handle", "a red-handled 40 mm paintbrush", (0.22, 0.04, 0.018), (P.RED, P.SILVER, P.CREAM)),
            V("black_75", "a black 75 mm emulsion brush", (0.25, 0.075, 0.024), (P.BLACK, P.GOLD, P.BLACK)),
            V(
                "blue_small",
                "a small blue-handled trim brush",
                (0.18, 0.03, 0.015),
                (P.BLUE, P.SILVER, P.WHITE),
                {"handle": 0.5},
                synonyms=("trim brush",),
            ),
            V(
                "bamboo",
                "a bamboo-handled chip brush",
                (0.21, 0.04, 0.016),
                (P.BAMBOO, P.SILVER, P.rgb(200, 170, 120)),
                synonyms=("chip brush",),
            ),
        ],
        density=450.0,
        mass_limits=(0.01, 0.3),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("paint brush", "brush", "decorating brush", "paintbrushes"),
        tags=(*TOOLS, "paint", "painting", "decorating", "bristles", "art"),
    ),
    define(
        "spirit level",
        "spirit level",
        spirit_level,
        [
            V("600", "a 600 mm aluminium spirit level with red end caps", (0.6, 0.025, 0.06)),
            V(
                "torpedo",
                "a short torpedo level",
                (0.23, 0.025, 0.045),
                (P.YELLOW, P.BLACK),
                {"vials": 2},
                synonyms=("torpedo level",),
            ),
            V("long_1200", "a long 1.2 metre box level", (1.2, 0.03, 0.07), (P.SILVER, P.BLUE)),
            V("yellow", "a yellow 400 mm bubble level", (0.4, 0.025, 0.055), (P.YELLOW, P.BLACK)),
            V("blue", "a blue aluminium level", (0.8, 0.028, 0.065), (P.BLUE, P.BLACK)),
            V("wood", "a wooden carpenter's level", (0.6, 0.03, 0.07), (P.WOOD, P.BRASS), density=700.0),
            V("mini", "a mini pocket level with one vial", (0.12, 0.022, 0.035), (P.RED, P.BLACK), {"vials": 1}),
        ],
        density=650.0,
        mass_limits=(0.05, 3.0),
        friction=(0.4, 0.7),
        support_probability=0.1,
        has_front=False,
        synonyms=("level", "bubble level", "spirit-level", "builder's level", "carpenter's level"),
        tags=(*TOOLS, "measure", "measuring", "straight", "bubble"),
    ),
    define(
        "utility knife",
        "utility knife",
        utility_knife,
        [
            V("yellow", "a yellow retractable utility knife", (0.16, 0.035, 0.018)),
            V(
                "orange",
                "an orange snap-off box cutter",
                (0.15, 0.03, 0.016),
                (P.ORANGE, P.BLACK),
                synonyms=("snap off knife",),
            ),
            V("silver", "a heavy silver metal utility knife", (0.17, 0.038, 0.02), (P.SILVER, P.BLACK), density=3500.0),
            V(
                "blue_closed",
                "a blue box cutter with the blade retracted",
                (0.14, 0.03, 0.016),
                (P.BLUE, P.CHARCOAL),
                {"blade_out": False},
            ),
            V("black", "a black trimming knife", (0.16, 0.035, 0.018), (P.BLACK, P.RED)),
            V(
                "small_green",
                "a small green craft cutter",
                (0.13, 0.025, 0.014),
                (P.GREEN, P.WHITE),
                synonyms=("craft knife",),
            ),
            V(
                "red_closed",
                "a red retractable cutter, closed",
                (0.15, 0.033, 0.017),
                (P.RED, P.BLACK),
                {"blade_out": False},
            ),
        ],
        density=1400.0,
        mass_limits=(0.02, 0.4),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("box cutter", "stanley knife", "carpet knife", "cutter", "boxcutter", "retractable knife"),
        tags=(*TOOLS, "blade", "cutting", "sharp"),
    ),
    define(
        "flashlight",
        "flashlight",
        flashlight,
        [
            V("black", "a black aluminium LED flashlight lying on its side", (0.15, 0.038, 0.036)),
            V(
                "yellow_large",
                "a big yellow rubber torch",
                (0.25, 0.09, 0.08),
                (P.YELLOW, P.BLACK),
                {"head": 1.6},
                density=500.0,
            ),
            V("red_small", "a small red pocket flashlight", (0.1, 0.025, 0.024), (P.RED, P.SILVER), {"head": 1.2}),
            V("silver", "a silver metal torch", (0.2, 0.05, 0.048), (P.SILVER, P.CHARCOAL), {"head": 1.4}),
            V("blue", "a blue plastic torch", (0.16, 0.045, 0.043), (P.BLUE, P.GREY)),
            V(
                "pen_light",
                "a slim black penlight",
                (0.13, 0.016, 0.016),
                (P.BLACK, P.SILVER),
                {"head": 1.05},
                synonyms=("penlight", "pen light"),
            ),
            V(
                "heavy_long",
                "a long heavy-duty black flashlight",
                (0.32, 0.06, 0.058),
                (P.CHARCOAL, P.BLACK),
                {"head": 1.3},
            ),
        ],
        density=900.0,
        mass_limits=(0.01, 1.5),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=(
            "torch",
            "flash light",
            "electric torch",
            "led torch",
            "hand torch",
            "battery light",
            "handheld light",
        ),
        tags=(*TOOLS, "light", "lamp", "handheld", "dark", "beam", "camping", "emergency"),
    ),
    define(
        "work gloves",
        "work gloves",
        work_gloves,
        [
            V("leather_pair", "a pair of tan leather work gloves", (0.26, 0.3, 0.025), (P.rgb(200, 160, 110), P.BLUE)),
            V(
                "garden_green",
                "a pair of green gardening gloves",
                (0.24, 0.28, 0.02),
                (P.LIME, P.GREEN),
                synonyms=("gardening gloves", "garden gloves"),
            ),
            V(
                "rubber_yellow",
                "a pair of yellow rubber gloves",
                (0.3, 0.3, 0.015),
                (P.YELLOW, P.YELLOW),
                synonyms=("rubber gloves", "washing-up gloves"),
            ),
            V("grey_knit", "grey knitted work gloves with black cuffs", (0.25, 0.29, 0.02), (P.GREY, P.BLACK)),
            V(
                "single_orange",
                "a single orange safety glove",
                (0.25, 0.14, 0.025),
                (P.ORANGE, P.BLACK),
                {"pair": False},
                synonyms=("glove",),
            ),
            V("kids_pink", "a pair of small pink children's gloves", (0.16, 0.2, 0.016), (P.PINK, P.PURPLE)),
            V(
                "black_mechanic",
                "black mechanic's gloves",
                (0.26, 0.3, 0.022),
                (P.BLACK, P.RED),
                synonyms=("mechanic gloves",),
            ),
        ],
        density=250.0,
        mass_limits=(0.02, 0.5),
        friction=(0.7, 1.0),
        support_probability=0.0,
        has_front=False,
        synonyms=("gloves", "glove", "work glove", "safety gloves", "pair of gloves", "protective gloves"),
        tags=(*TOOLS, "soft", "protective", "hands", "clothing", "flat"),
    ),
    define(
        "safety glasses",
        "safety glasses",
        safety_glasses,
        [
            V("clear", "clear safety glasses with a black frame", (0.16, 0.15, 0.055)),
            V("yellow", "yellow-tinted shooting glasses", (0.16, 0.15, 0.05), (P.rgb(250, 220, 80, 0.6), P.BLACK)),
            V("smoke", "dark smoke-tinted protective eyewear", (0.16, 0.15, 0.05), (P.rgb(60, 60, 70, 0.7), P.GREY)),
            V(
                "blue_frame",
                "clear safety specs with a blue frame",
                (0.15, 0.145, 0.05),
                (P.rgb(220, 235, 240, 0.5), P.BLUE),
            ),
            V(
                "wide_goggles",
                "wide wraparound safety goggles",
                (0.17, 0.17, 0.065),
                (P.rgb(220, 235, 240, 0.5), P.GREY),
                {"wrap": 65.0},
                synonyms=("safety goggles", "goggles"),
            ),
            V(
                "orange_frame",
                "orange-framed protective glasses",
                (0.16, 0.15, 0.05),
                (P.rgb(230, 240, 240, 0.5), P.ORANGE),
            ),
            V("kids", "small red kids' safety glasses", (0.13, 0.12, 0.04), (P.rgb(230, 240, 240, 0.5), P.RED)),
        ],
        density=500.0,
        mass_limits=(0.01, 0.15),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=True,
        synonyms=("safety goggles", "goggles", "protective glasses", "eye protection", "safety specs", "eyewear"),
        tags=(*TOOLS, "protective", "safety", "eyes", "lab"),
    ),
    define(
        "clamp",
        "clamp",
        clamp,
        [
            V(
                "c_blue",
                "a blue cast-iron C-clamp",
                (0.11, 0.18, 0.025),
                mass=0.9,
                synonyms=("c-clamp", "c clamp", "g clamp"),
            ),
            V(
                "c_small",
                "a small red G-clamp",
                (0.07, 0.11, 0.018),
                (P.RED,),
                mass=0.3,
                synonyms=("g-clamp", "g clamp"),
            ),
            V("c_large", "a large grey C-clamp", (0.16, 0.26, 0.035), (P.GREY,), mass=2.2),
            V(
                "bar_red",
                "a red F-style bar clamp",
                (0.35, 0.14, 0.03),
                (P.RED, P.BLACK),
                {"style": "bar"},
                mass=0.7,
                synonyms=("bar clamp", "f clamp"),
            ),
            V(
                "bar_long",
                "a long orange bar clamp",
                (0.6, 0.15, 0.032),
                (P.ORANGE, P.BLACK),
                {"style": "bar"},
                mass=1.1,
            ),
            V(
                "bar_small",
                "a small yellow quick-grip clamp",
                (0.25, 0.12, 0.025),
                (P.YELLOW, P.BLACK),
                {"style": "bar"},
                mass=0.4,
                synonyms=("quick clamp", "quick grip"),
            ),
            V("c_black", "a black steel C clamp", (0.09, 0.14, 0.022), (P.BLACK,), mass=0.6),
        ],
        density=3000.0,
        mass_limits=(0.1, 3.5),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("clamp", "c-clamp", "g-clamp", "bar clamp", "woodworking clamp", "vice grip"),
        tags=(*TOOLS, "woodworking", "hold", "steel", "carpentry"),
    ),
    define(
        "sandpaper",
        "sandpaper",
        sandpaper,
        [
            V("sheet_medium", "a sheet of medium-grit sandpaper", (0.28, 0.23, 0.0008)),
            V(
                "sheet_fine",
                "a sheet of fine grey wet-and-dry paper",
                (0.28, 0.23, 0.0006),
                (P.CHARCOAL, P.PAPER),
                synonyms=("wet and dry paper",),
            ),
            V("sheet_coarse", "a coarse red sandpaper sheet", (0.28, 0.23, 0.001), (P.rgb(170, 60, 40), P.PAPER)),
            V("quarter", "a quarter sheet of sandpaper", (0.14, 0.115, 0.0008)),
            V(
                "block_foam",
                "a foam sanding block",
                (0.12, 0.1, 0.025),
                (P.rgb(200, 150, 90), P.rgb(230, 220, 90)),
                {"block": True},
                density=120.0,
                synonyms=("sanding block", "sanding sponge"),
            ),
            V(
                "block_blue",
                "a blue sanding sponge",
                (0.1, 0.07, 0.025),
                (P.BLUE, P.SKY),
                {"block": True},
                density=120.0,
                synonyms=("sanding sponge",),
            ),
            V("strip_green", "a green strip of abrasive paper", (0.23, 0.09, 0.0008), (P.GREEN, P.PAPER)),
        ],
        density=600.0,
        mass_limits=(0.002, 0.2),
        friction=(0.8, 1.2),
        support_probability=0.0,
        has_front=False,
        synonyms=("sand paper", "glasspaper", "abrasive paper", "emery paper", "sanding paper", "sanding sheet"),
        tags=(*TOOLS, "sanding", "abrasive", "flat", "woodworking", "paper"),
    ),
    define(
        "tape roll",
        "tape roll",
        tape_roll,
        [
            V("duct_silver", "a roll of silver duct tape", (0.12, 0.12, 0.048), synonyms=("duct tape", "gaffer tape")),
            V("duct_black", "a roll of black gaffer tape", (0.11, 0.11, 0.05), (P.BLACK,), synonyms=("gaffer tape",)),
            V(
                "masking",
                "a roll of beige masking tape",
                (0.09, 0.09, 0.024),
                (P.rgb(230, 215, 170),),
                {"hole": 0.75},
                synonyms=("masking tape", "painter's tape"),
            ),
            V(
                "painters_blue",
                "a roll of blue painter's tape",
                (0.09, 0.09, 0.036),
                (P.SKY,),
                {"hole": 0.75},
                synonyms=("painter's tape", "painters tape"),
            ),
            V(
                "electrical_black",
                "a small roll of black electrical tape",
                (0.05, 0.05, 0.019),
                (P.BLACK,),
                {"hole": 0.7, "core": 0.04},
                synonyms=("electrical tape", "insulating tape"),
            ),
            V(
                "electrical_red",
                "a red roll of insulation tape",
                (0.05, 0.05, 0.019),
                (P.RED,),
                {"hole": 0.7, "core": 0.04},
                synonyms=("electrical tape", "insulating tape"),
            ),
            V(
                "packing_brown",
                "a roll of brown packing tape",
                (0.1, 0.1, 0.05),
                (P.rgb(170, 110, 50, 0.9),),
                {"hole": 0.76},
                synonyms=("packing tape", "parcel tape"),
            ),
            V("duct_red", "a roll of red duct tape", (0.12, 0.12, 0.048), (P.RED,), synonyms=("duct tape",)),
        ],
        density=900.0,
        mass_limits=(0.01, 0.6),
        friction=(0.6, 0.9),
        support_probability=0.2,
        has_front=False,
        synonyms=("duct tape", "roll of tape", "tape", "masking tape", "electrical tape", "duck tape", "adhesive tape"),
        tags=(*TOOLS, "sticky", "roll", "adhesive"),
    ),
    define(
        "hard hat",
        "hard hat",
        hard_hat,
        [
            V("yellow", "a yellow construction hard hat", (0.3, 0.22, 0.16)),
            V("white", "a white site manager's safety helmet", (0.3, 0.22, 0.16), (P.WHITE,)),
            V("orange", "an orange hard hat", (0.3, 0.22, 0.16), (P.ORANGE,)),
            V("blue", "a blue safety helmet", (0.29, 0.21, 0.155), (P.BLUE,)),
            V("red_full_brim", "a red full-brim hard hat", (0.34, 0.29, 0.16), (P.RED,), {"brim": "full"}),
            V("green", "a green builder's helmet", (0.3, 0.22, 0.16), (P.GREEN,)),
            V(
                "kids_toy",
                "a small yellow toy hard hat for kids",
                (0.22, 0.17, 0.12),
                (P.YELLOW,),
                density=80.0,
                synonyms=("toy hard hat", "construction hat"),
            ),
        ],
        density=90.0,
        mass_limits=(0.05, 0.8),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=True,
        synonyms=("hardhat", "safety helmet", "construction helmet", "helmet", "builder's hat", "hard helmet"),
        tags=(*TOOLS, "safety", "construction", "protective", "head"),
    ),
)

MORE_CATEGORIES: tuple[CategoryDef, ...] = (
    define(
        "bucket",
        "bucket",
        bucket,
        [
            V("red_10l", "an open red plastic 10-litre bucket with a wire handle", (0.292, 0.2856, 0.27)),
            V("grey_15l", "a large grey builder's bucket", (0.332, 0.3256, 0.3), (P.GREY, P.STEEL)),
            V("white", "a white plastic pail", (0.272, 0.2656, 0.25), (P.WHITE, P.STEEL), synonyms=("pail",)),
            V(
                "orange_tall",
                "a tall orange hardware-store bucket",
                (0.312, 0.3056, 0.36),
                (P.ORANGE, P.STEEL),
                {"taper": 0.88},
            ),
            V(
                "metal",
                "a galvanised metal pail",
                (0.292, 0.2856, 0.26),
                (P.SILVER, P.STEEL),
                density=2500.0,
                synonyms=("metal bucket", "galvanised bucket", "tin pail"),
            ),
            V(
                "sand_blue",
                "a small blue sand bucket for the beach",
                (0.16, 0.16, 0.14),
                (P.SKY,),
                {"handle": False, "taper": 0.75},
                synonyms=("sand bucket", "sand pail", "beach bucket"),
            ),
            V(
                "sand_yellow",
                "a little yellow kids' pail",
                (0.14, 0.14, 0.12),
                (P.YELLOW,),
                {"handle": False, "taper": 0.75},
                synonyms=("sand pail",),
            ),
            V(
                "green_mop",
                "a green cleaning bucket",
                (0.312, 0.3056, 0.28),
                (P.GREEN, P.STEEL),
                synonyms=("cleaning bucket", "mop bucket"),
            ),
        ],
        density=500.0,
        mass_limits=(0.05, 3.0),
        friction=(0.4, 0.7),
        support_probability=0.1,
        has_front=False,
        synonyms=("pail", "bucket", "plastic bucket", "buckets"),
        tags=("container", "open", "garage", "cleaning", "garden", "water", "carry"),
    ),
    define(
        "tool bag",
        "tool bag",
        tool_bag,
        [
            V("canvas", "an open khaki canvas tool bag with two handles", (0.4, 0.22, 0.3)),
            V(
                "black_large",
                "a large black open-top tool tote",
                (0.5, 0.26, 0.34),
                (P.BLACK, P.RED),
                synonyms=("tool tote",),
            ),
            V("orange", "an orange wide-mouth tool bag", (0.42, 0.24, 0.3), (P.ORANGE, P.BLACK)),
            V("small_grey", "a small grey electrician's tool pouch bag", (0.3, 0.16, 0.24), (P.GREY, P.BLACK)),
            V("blue", "a blue open tool carrier bag", (0.4, 0.22, 0.3), (P.BLUE, P.CHARCOAL)),
            V("brown_leather", "a brown leather tool bag", (0.38, 0.2, 0.28), (P.BROWN, P.DARK_BROWN), density=450.0),
            V("yellow", "a yellow and black tool tote", (0.45, 0.25, 0.32), (P.YELLOW, P.BLACK)),
        ],
        density=280.0,
        mass_limits=(0.3, 3.0),
        friction=(0.6, 0.9),
        support_probability=0.1,
        has_front=False,
        synonyms=("toolbag", "tool tote", "holdall", "carryall"),
        tags=("workshop", "garage", "diy", "bag", "container", "open", "canvas", "carry"),
    ),
    define(
        "piggy bank",
        "piggy bank",
        piggy_bank,
        [
            V("pink", "a pink ceramic piggy bank", (0.15, 0.1, 0.11)),
            V("large_pink", "a large pink pig money box", (0.24, 0.16, 0.18)),
            V("white", "a white porcelain piggy bank", (0.15, 0.1, 0.11), (P.WHITE, P.PINK)),
            V("gold", "a gold-painted piggy bank", (0.14, 0.095, 0.1), (P.GOLD, P.BRASS)),
            V("blue_plastic", "a blue plastic piggy bank", (0.16, 0.11, 0.12), (P.SKY, P.BLUE), density=150.0),
            V("small_red", "a small red coin bank shaped like a pig", (0.1, 0.07, 0.075), (P.RED, P.DARK_RED)),
            V("spotted_black", "a black piggy bank", (0.15, 0.1, 0.11), (P.BLACK, P.GREY)),
        ],
        density=400.0,
        mass_limits=(0.05, 1.5),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        synonyms=("piggybank", "money box", "coin bank", "savings bank", "pig bank", "money pig"),
        tags=(*KIDS, "money", "coins", "savings", "ceramic", "pig"),
    ),
    define(
        "yo-yo",
        "yo-yo",
        yo_yo,
        [
            V("red", "a red plastic yo-yo", (0.056, 0.056, 0.036)),
            V("blue", "a blue yo-yo with a white string", (0.056, 0.056, 0.036), (P.BLUE, P.WHITE)),
            V("wood", "a wooden yo-yo", (0.06, 0.06, 0.04), (P.LIGHT_WOOD, P.RED)),
            V("metal", "a silver metal butterfly yo-yo", (0.055, 0.055, 0.042), (P.SILVER, P.BLACK), density=2000.0),
            V("green", "a glow-in-the-dark green yoyo", (0.058, 0.058, 0.036), (P.LIME, P.WHITE)),
            V("small_yellow", "a small yellow yo-yo", (0.045, 0.045, 0.03), (P.YELLOW, P.RED)),
            V("purple", "a purple and pink yo-yo", (0.056, 0.056, 0.036), (P.PURPLE, P.PINK)),
        ],
        density=650.0,
        mass_limits=(0.01, 0.2),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("yoyo", "yo yo", "yo-yo toy"),
        tags=(*KIDS, "string", "spinning", "round"),
    ),
    define(
        "toy drum",
        "toy drum",
        toy_drum,
        [
            V("blue", "a blue children's drum with red rims and two sticks", (0.22, 0.22, 0.16)),
            V("red", "a red toy drum", (0.2, 0.2, 0.14), (P.RED, P.WHITE)),
            V("small", "a small toddler drum", (0.15, 0.15, 0.1), (P.YELLOW, P.BLUE)),
            V(
                "marching",
                "a tall toy marching drum",
                (0.26, 0.26, 0.24),
                (P.WHITE, P.RED),
                synonyms=("marching drum",),
            ),
            V("green", "a green kids' snare drum", (0.24, 0.24, 0.14), (P.GREEN, P.YELLOW), synonyms=("snare drum",)),
            V(
                "wood",
                "a wooden tom-tom drum for kids",
                (0.2, 0.2, 0.18),
                (P.WOOD, P.DARK_BROWN),
                synonyms=("tom-tom",),
            ),
            V("pink", "a pink toy drum", (0.2, 0.2, 0.14), (P.PINK, P.PURPLE)),
        ],
        density=90.0,
        mass_limits=(0.1, 1.5),
        friction=(0.5, 0.8),
        support_probability=0.1,
        has_front=False,
        synonyms=("drum", "kids drum", "children's drum", "drum set", "drumsticks"),
        tags=(*KIDS, "music", "musical", "instrument", "noise"),
    ),
    define(
        "toy robot",
        "toy robot",
        toy_robot,
        [
            V("silver", "a silver tin toy robot with red feet", (0.1, 0.14, 0.2)),
            V("red", "a red plastic toy robot", (0.1, 0.14, 0.2), (P.RED, P.YELLOW)),
            V("blue_large", "a large blue robot toy", (0.15, 0.21, 0.3), (P.BLUE, P.ORANGE)),
            V("small_green", "a small green wind-up robot", (0.06, 0.085, 0.12), (P.GREEN, P.RED), density=500.0),
            V("white", "a white toy robot with blue accents", (0.1, 0.14, 0.2), (P.WHITE, P.BLUE)),
            V("gold", "a gold retro robot figure", (0.1, 0.14, 0.2), (P.GOLD, P.BLACK)),
            V("black", "a black and yellow toy robot", (0.12, 0.17, 0.24), (P.CHARCOAL, P.YELLOW)),
        ],
        density=250.0,
        mass_limits=(0.03, 1.5),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        synonyms=("robot", "robot toy", "tin robot", "wind-up robot", "android toy"),
        tags=(*KIDS, "robot", "retro", "sci-fi"),
    ),
    define(
        "toy train",
        "toy train",
        toy_train,
        [
            V("red", "a red wooden toy steam engine", (0.2, 0.085, 0.15)),
            V("green", "a green toy locomotive", (0.2, 0.085, 0.15), (P.GREEN, P.RED, P.BLACK)),
            V("blue_small", "a small blue toy train engine", (0.12, 0.05, 0.09), (P.BLUE, P.YELLOW, P.RED)),
            V("large", "a large red and black toy train", (0.32, 0.13, 0.24), (P.RED, P.BLACK, P.GOLD)),
            V("yellow", "a yellow wooden train", (0.18, 0.075, 0.13), (P.YELLOW, P.GREEN, P.RED)),
            V("black_tin", "a black tin toy locomotive", (0.22, 0.09, 0.16), (P.BLACK, P.RED, P.GOLD), density=400.0),
            V("natural", "an unpainted wooden toy train engine", (0.18, 0.075, 0.13), (P.LIGHT_WOOD, P.WOOD, P.WOOD)),
        ],
        density=250.0,
        mass_limits=(0.03, 2.0),
        friction=(0.5, 0.8),
        support_probability=0.1,
        has_front=True,
        synonyms=("train", "toy locomotive", "toy engine", "train set", "steam engine", "wooden train"),
        tags=(*KIDS, "vehicle", "railway", "wheels", "wooden"),
    ),
    define(
        "chisel",
        "chisel",
        chisel,
        [
            V("wood_20", "a 20 mm wood chisel with a beech handle", (0.25, 0.028, 0.028)),
            V("wood_12", "a narrow 12 mm bevel-edge chisel", (0.24, 0.024, 0.026), synonyms=("bevel edge chisel",)),
            V("wide_32", "a wide 32 mm firmer chisel", (0.28, 0.034, 0.03), synonyms=("firmer chisel",)),
            V("yellow", "a chisel with a yellow plastic handle", (0.24, 0.028, 0.028), (P.YELLOW,)),
            V("blue", "a blue-handled wood chisel", (0.25, 0.028, 0.028), (P.BLUE,)),
            V("red", "a red-handled carpenter's chisel", (0.26, 0.03, 0.028), (P.RED,)),
            V(
                "dark",
                "a dark wooden mortise chisel",
                (0.3, 0.03, 0.032),
                (P.DARK_BROWN,),
                synonyms=("mortise chisel",),
            ),
        ],
        density=2000.0,
        mass_limits=(0.05, 0.8),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("wood chisel", "carving chisel", "gouge"),
        tags=(*TOOLS, "woodworking", "carpentry", "blade", "carving"),
    ),
    define(
        "hacksaw",
        "hacksaw",
        hacksaw,
        [
            V("blue", "a blue-framed hacksaw with a black grip", (0.42, 0.13, 0.03)),
            V("red", "a red hacksaw for cutting metal", (0.42, 0.13, 0.03), (P.RED, P.BLACK)),
            V("junior", "a small junior hacksaw", (0.26, 0.09, 0.02), (P.SILVER, P.BLUE), synonyms=("junior hacksaw",)),
            V("orange", "an orange hacksaw", (0.4, 0.125, 0.028), (P.ORANGE, P.BLACK)),
            V("black", "a black metal hacksaw", (0.44, 0.14, 0.03), (P.BLACK, P.RED)),
            V("yellow", "a yellow pipe-cutting hacksaw", (0.42, 0.13, 0.03), (P.YELLOW, P.BLACK)),
            V("silver", "a chrome hacksaw frame with a wooden grip", (0.42, 0.13, 0.03), (P.SILVER, P.WOOD)),
        ],
        density=1400.0,
        mass_limits=(0.1, 1.2),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("hack saw", "metal saw", "bow saw frame", "junior hacksaw"),
        tags=(*TOOLS, "metal", "cutting", "pipe", "blade"),
    ),
    define(
        "hatchet",
        "hatchet",
        hatchet,
        [
            V("wood", "a hatchet with a wooden handle and a black steel head", (0.36, 0.16, 0.035)),
            V("red_head", "a camping hatchet with a red head", (0.35, 0.15, 0.034), (P.WOOD, P.RED)),
            V("orange", "an orange fibreglass-handled hatchet", (0.38, 0.16, 0.035), (P.ORANGE, P.BLACK)),
            V("small", "a small hand axe", (0.28, 0.13, 0.03), (P.LIGHT_WOOD, P.STEEL), synonyms=("hand axe",)),
            V(
                "large",
                "a large splitting axe",
                (0.5, 0.2, 0.045),
                (P.WOOD, P.CHARCOAL),
                synonyms=("axe", "splitting axe"),
            ),
            V("black", "an all-black tactical hatchet", (0.34, 0.15, 0.034), (P.BLACK, P.CHARCOAL)),
            V(
                "green",
                "a green-handled camp axe",
                (0.36, 0.16, 0.035),
                (P.DARK_GREEN, P.STEEL),
                synonyms=("camp axe",),
            ),
        ],
        density=1800.0,
        mass_limits=(0.3, 3.0),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("axe", "ax", "hand axe", "camping axe", "hatchets"),
        tags=(*TOOLS, "wood", "chopping", "camping", "blade", "firewood"),
    ),
)

EXTRA_CATEGORIES: tuple[CategoryDef, ...] = (
    define(
        "toy car",
        "toy car",
        toy_car,
        [
            V("red", "a red toy car", (0.12, 0.055, 0.05)),
            V(
                "blue",
                "a blue die-cast model car",
                (0.08, 0.036, 0.032),
                (P.BLUE,),
                density=1500.0,
                synonyms=("model car", "die-cast car", "matchbox car"),
            ),
            V("yellow_taxi", "a yellow toy taxi", (0.12, 0.055, 0.05), (P.YELLOW,), synonyms=("toy taxi",)),
            V(
                "green_racer",
                "a green toy racing car with a rear wing",
                (0.14, 0.06, 0.04),
                (P.GREEN, P.BLACK),
                {"style": "racer"},
                synonyms=("race car", "racing car"),
            ),
            V(
                "red_racer",
                "a red toy race car",
                (0.16, 0.07, 0.045),
                (P.RED, P.WHITE),
                {"style": "racer"},
                synonyms=("race car", "racing car", "formula car"),
            ),
            V("big_white", "a big white plastic push car", (0.25, 0.11, 0.1), (P.WHITE,), density=150.0),
            V(
                "silver",
                "a silver die-cast sports car",
                (0.08, 0.036, 0.03),
                (P.SILVER,),
                density=1500.0,
                synonyms=("sports car", "die-cast car"),
            ),
            V("orange_small", "a small orange toy car", (0.07, 0.032, 0.03), (P.ORANGE,)),
        ],
        density=400.0,
        mass_limits=(0.01, 1.0),
        friction=(0.5, 0.8),
        support_probability=0.1,
        has_front=True,
        synonyms=("toy car", "car", "model car", "race car", "toy automobile", "hot wheels", "matchbox car"),
        tags=(*KIDS, "vehicle", "wheels", "car"),
    ),
    define(
        "puzzle cube",
        "puzzle cube",
        puzzle_cube,
        [
            V("classic", "a classic 3x3 twisty puzzle cube, solved", (0.057, 0.057, 0.057)),
            V("pocket", "a 2x2 pocket cube", (0.05, 0.05, 0.05), options={"n": 2}, synonyms=("pocket cube",)),
            V("revenge", "a 4x4 revenge cube", (0.062, 0.062, 0.062), options={"n": 4}),
            V(
                "white_core",
                "a white-bodied 3x3 speed cube",
                (0.056, 0.056, 0.056),
                (P.WHITE,),
                synonyms=("speed cube", "speedcube"),
            ),
            V("mini", "a mini keyring puzzle cube", (0.03, 0.03, 0.03), synonyms=("keychain cube",)),
            V("big", "a big 5x5 professor's cube", (0.07, 0.07, 0.07), options={"n": 5}),
            V("grey_core", "a stickerless-look grey 3x3 cube", (0.055, 0.055, 0.055), (P.GREY,)),
        ],
        density=450.0,
        mass_limits=(0.01, 0.3),
        friction=(0.4, 0.7),
        support_probability=0.3,
        has_front=False,
        synonyms=(
            "rubik's cube",
            "rubiks cube",
            "rubik cube",
            "magic cube",
            "speed cube",
            "twisty puzzle",
            "cube puzzle",
        ),
        tags=(*KIDS, "puzzle", "brain teaser", "colourful", "colorful", "cube"),
    ),
    define(
        "skateboard",
        "skateboard",
        skateboard,
        [
            V("wood", "a wooden skateboard with white wheels", (0.8, 0.2, 0.1)),
            V("red", "a red skateboard", (0.8, 0.2, 0.1), (P.RED, P.YELLOW)),
            V("blue_kids", "a small blue kids' skateboard", (0.6, 0.16, 0.09), (P.BLUE, P.WHITE)),
            V(
                "cruiser",
                "a green plastic penny board cruiser",
                (0.56, 0.15, 0.09),
                (P.LIME, P.PINK),
                synonyms=("penny board", "cruiser board"),
            ),
            V("black", "a black skateboard deck on orange wheels", (0.81, 0.21, 0.1), (P.BLACK, P.ORANGE)),
            V("longboard", "a long bamboo longboard", (1.0, 0.24, 0.11), (P.BAMBOO, P.BLACK), synonyms=("longboard",)),
            V("pink", "a pink skateboard", (0.78, 0.2, 0.1), (P.PINK, P.WHITE)),
        ],
        density=650.0,
        mass_limits=(0.5, 4.5),
        friction=(0.5, 0.9),
        support_probability=0.3,
        has_front=False,
        synonyms=("skate board", "skate", "deck", "board with wheels"),
        tags=(*KIDS, "sport", "wheels", "outdoor", "ride"),
    ),
)

GARAGE_CATEGORIES: tuple[CategoryDef, ...] = (
    define(
        "multimeter",
        "multimeter",
        multimeter,
        [
            V("yellow", "a yellow digital multimeter lying on its back", (0.09, 0.18, 0.045)),
            V("orange", "an orange electrician's multimeter", (0.09, 0.19, 0.05), (P.ORANGE, P.CHARCOAL)),
            V("red_pocket", "a small red pocket multimeter", (0.07, 0.13, 0.03), (P.RED, P.CHARCOAL)),
            V("grey", "a grey and black digital meter", (0.1, 0.2, 0.05), (P.GREY, P.BLACK)),
            V("green", "a green voltmeter", (0.09, 0.18, 0.045), (P.GREEN, P.CHARCOAL), synonyms=("voltmeter",)),
            V("blue", "a blue test meter", (0.085, 0.17, 0.042), (P.BLUE, P.CHARCOAL)),
            V("black", "a black professional multimeter", (0.1, 0.21, 0.055), (P.BLACK, P.CHARCOAL)),
        ],
        density=700.0,
        mass_limits=(0.1, 1.0),
        friction=(0.5, 0.8),
        support_probability=0.2,
        has_front=False,
        synonyms=("multi meter", "voltmeter", "test meter", "digital meter", "multitester", "ammeter"),
        tags=(*TOOLS, "electrical", "electronics", "measure", "volts"),
    ),
    define(
        "oil can",
        "oil can",
        oil_can,
        [
            V("red", "a red metal oil can with a brass spout", (0.16, 0.08, 0.14)),
            V("green", "a green pump oiler", (0.16, 0.08, 0.14), (P.GREEN, P.BRASS)),
            V("silver", "a silver steel oil can", (0.15, 0.075, 0.13), (P.SILVER, P.BRASS)),
            V("small_brass", "a small brass oiler", (0.11, 0.055, 0.1), (P.BRASS, P.BRASS), density=900.0),
            V("black", "a black oil can with a long spout", (0.18, 0.085, 0.16), (P.BLACK, P.STEEL)),
            V("blue", "a blue machine oil can", (0.16, 0.08, 0.14), (P.BLUE, P.BRASS)),
            V("yellow", "a yellow lubricant oiler", (0.15, 0.075, 0.13), (P.YELLOW, P.BLACK)),
        ],
        density=600.0,
        mass_limits=(0.05, 1.5),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=True,
        synonyms=("oiler", "oil can", "pump oiler", "lubricant can", "machine oil"),
        tags=(*TOOLS, "oil", "lubricant", "metal", "mechanic", "spout"),
    ),
    define(
        "spray paint",
        "spray paint can",
        spray_paint,
        [
            V("red", "a red can of spray paint", (0.066, 0.066, 0.2)),
            V("black", "a black aerosol paint can", (0.066, 0.066, 0.2), (P.BLACK, P.WHITE)),
            V("white", "a white spray paint can", (0.066, 0.066, 0.2), (P.WHITE, P.RED)),
            V("blue", "a blue spray can", (0.066, 0.066, 0.2), (P.BLUE, P.WHITE)),
            V("gold", "a metallic gold spray paint", (0.066, 0.066, 0.2), (P.GOLD, P.BLACK)),
            V("small_green", "a small green spray paint tin", (0.052, 0.052, 0.15), (P.GREEN, P.BLACK)),
            V(
                "wd_blue",
                "a blue and yellow lubricant spray can",
                (0.06, 0.06, 0.22),
                (P.BLUE, P.YELLOW),
                synonyms=("lubricant spray", "penetrating oil", "wd-40"),
            ),
        ],
        density=700.0,
        mass_limits=(0.1, 0.8),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("spray can", "aerosol paint", "spray paint can", "paint spray", "aerosol can of paint", "spraypaint"),
        tags=(*TOOLS, "paint", "aerosol", "graffiti", "decorating"),
    ),
    define(
        "camping lantern",
        "camping lantern",
        camping_lantern,
        [
            V("green", "a green battery camping lantern with a handle", (0.12, 0.12, 0.2)),
            V("orange", "an orange LED camp lantern", (0.12, 0.12, 0.2), (P.ORANGE,)),
            V("black", "a black rechargeable lantern", (0.14, 0.14, 0.24), (P.BLACK,)),
            V("red_small", "a small red camp light", (0.08, 0.08, 0.13), (P.RED,)),
            V("blue", "a blue tent lantern", (0.1, 0.1, 0.17), (P.BLUE,)),
            V(
                "silver",
                "a silver metal work lantern",
                (0.13, 0.13, 0.22),
                (P.SILVER,),
                density=400.0,
                synonyms=("work light",),
            ),
            V("yellow", "a yellow camping light", (0.12, 0.12, 0.2), (P.YELLOW,)),
        ],
        density=250.0,
        mass_limits=(0.05, 1.5),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=False,
        synonyms=("camping lantern", "camp lantern", "battery lantern", "led lantern", "camp light", "lantern"),
        tags=("camping", "outdoor", "light", "lamp", "battery", "garage", "emergency"),
    ),
    define(
        "extension cord",
        "extension cord",
        extension_cord,
        [
            V("orange", "a coiled orange outdoor extension cord", (0.3, 0.28, 0.045)),
            V(
                "white",
                "a coiled white extension lead with a socket",
                (0.25, 0.23, 0.04),
                (P.WHITE, P.WHITE),
                synonyms=("extension lead",),
            ),
            V("black", "a black heavy-duty extension cable", (0.34, 0.31, 0.05), (P.BLACK, P.CHARCOAL)),
            V("green", "a green garden extension cord", (0.3, 0.28, 0.045), (P.GREEN, P.BLACK)),
            V("yellow", "a yellow site extension lead", (0.32, 0.3, 0.05), (P.YELLOW, P.BLACK)),
            V("blue", "a blue extension cable coil", (0.28, 0.26, 0.042), (P.BLUE, P.WHITE)),
            V("small_white", "a short white power extension", (0.2, 0.18, 0.035), (P.WHITE, P.GREY)),
        ],
        density=700.0,
        mass_limits=(0.1, 3.0),
        friction=(0.6, 0.9),
        support_probability=0.0,
        has_front=False,
        synonyms=("extension lead", "extension cable", "power cord", "power lead", "electrical cord", "extension"),
        tags=(*TOOLS, "electrical", "power", "coil", "socket", "plug"),
    ),
    define(
        "nails",
        "box of nails",
        fastener_box,
        [
            V("nails", "a small open cardboard box full of steel nails", (0.1, 0.07, 0.05), mass=0.5),
            V(
                "screws",
                "an open box of wood screws",
                (0.1, 0.07, 0.05),
                (P.CARDBOARD, P.BRASS),
                {"screws": True},
                mass=0.45,
                synonyms=("box of screws", "screws", "wood screws"),
            ),
            V("large_nails", "a large box of framing nails", (0.16, 0.1, 0.07), mass=1.6),
            V(
                "tacks",
                "a tiny box of brass tacks",
                (0.06, 0.04, 0.025),
                (P.RED, P.BRASS),
                mass=0.08,
                synonyms=("tacks", "thumbtacks", "drawing pins"),
            ),
            V(
                "plastic_screws",
                "a clear plastic tub of screws",
                (0.09, 0.06, 0.045),
                (P.rgb(220, 230, 235, 0.6), P.STEEL),
                {"screws": True},
                mass=0.35,
                synonyms=("screws",),
            ),
            V(
                "blue_screws",
                "a blue box of machine screws",
                (0.1, 0.07, 0.05),
                (P.BLUE, P.SILVER),
                {"screws": True},
                mass=0.45,
                synonyms=("machine screws", "bolts"),
            ),
            V("finishing", "a yellow box of finishing nails", (0.09, 0.06, 0.04), (P.YELLOW, P.STEEL), mass=0.3),
        ],
        density=1500.0,
        mass_limits=(0.03, 2.5),
        friction=(0.5, 0.8),
        support_probability=0.3,
        has_front=False,
        synonyms=("box of nails", "nails", "box of screws", "screws", "nail box", "fasteners", "pack of nails"),
        tags=(*TOOLS, "hardware", "nails", "screws", "fasteners", "metal"),
    ),
    define(
        "kite",
        "kite",
        kite,
        [
            V("red", "a red diamond kite with a yellow tail", (0.9, 0.6, 0.015)),
            V("blue", "a blue diamond kite", (0.9, 0.6, 0.015), (P.BLUE, P.RED, P.YELLOW)),
            V("rainbow", "a rainbow-coloured kids' kite", (0.8, 0.55, 0.014), (P.PURPLE, P.ORANGE, P.GREEN)),
            V("small_green", "a small green pocket kite", (0.5, 0.35, 0.01), (P.GREEN, P.PINK, P.BLUE)),
            V("yellow", "a yellow kite with a long blue tail", (1.0, 0.62, 0.016), (P.YELLOW, P.BLUE, P.RED)),
            V("black", "a black stunt kite", (0.9, 0.6, 0.015), (P.BLACK, P.RED, P.WHITE)),
            V("pink", "a pink kite", (0.8, 0.55, 0.014), (P.PINK, P.WHITE, P.PURPLE)),
        ],
        density=60.0,
        mass_limits=(0.02, 0.5),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=False,
        synonyms=("diamond kite", "flying kite", "kites"),
        tags=(*KIDS, "outdoor", "wind", "flat", "flying"),
    ),
)

YARD_CATEGORIES: tuple[CategoryDef, ...] = (
    define(
        "watering can",
        "watering can",
        watering_can,
        [
            V("green", "a green plastic watering can with a long spout", (0.42, 0.17, 0.3)),
            V("metal", "a galvanised metal watering can", (0.45, 0.18, 0.32), (P.SILVER, P.STEEL), density=200.0),
            V("red", "a red watering can", (0.42, 0.17, 0.3), (P.RED, P.GREY)),
            V("blue_small", "a small blue indoor watering can", (0.28, 0.11, 0.2), (P.BLUE, P.SKY)),
            V(
                "kids_yellow",
                "a little yellow kids' watering can",
                (0.22, 0.09, 0.16),
                (P.YELLOW, P.ORANGE),
                synonyms=("toy watering can",),
            ),
            V(
                "copper",
                "a copper-coloured decorative watering can",
                (0.4, 0.16, 0.28),
                (P.BRASS, P.BRASS),
                density=200.0,
            ),
            V("grey_large", "a large grey garden watering can", (0.5, 0.2, 0.36), (P.GREY, P.CHARCOAL)),
        ],
        density=80.0,
        mass_limits=(0.04, 2.0),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=True,
        synonyms=("watering pot", "sprinkling can", "water can", "plant waterer"),
        tags=("garden", "gardening", "plants", "water", "garage", "outdoor"),
    ),
    define(
        "trowel",
        "trowel",
        trowel,
        [
            V("green", "a garden trowel with a green handle", (0.3, 0.08, 0.03)),
            V("wood", "a wooden-handled hand trowel", (0.3, 0.08, 0.03), (P.WOOD,)),
            V("red", "a red-handled planting trowel", (0.29, 0.075, 0.03), (P.RED,)),
            V("narrow", "a narrow transplanting trowel", (0.3, 0.055, 0.028), (P.ORANGE,)),
            V("kids", "a small blue kids' garden trowel", (0.22, 0.06, 0.024), (P.BLUE,), density=600.0),
            V("black", "a black-handled stainless trowel", (0.32, 0.085, 0.032), (P.BLACK,)),
            V("yellow", "a yellow garden spade trowel", (0.3, 0.08, 0.03), (P.YELLOW,)),
        ],
        density=1300.0,
        mass_limits=(0.03, 0.6),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("hand trowel", "garden trowel", "hand spade", "trowel", "garden spade", "planting trowel"),
        tags=("garden", "gardening", "tool", "tools", "digging", "soil", "garage"),
    ),
    define(
        "toy boat",
        "toy boat",
        toy_boat,
        [
            V("red_sail", "a red toy sailing boat with a white sail", (0.25, 0.09, 0.26)),
            V("blue_sail", "a blue wooden sailboat toy", (0.22, 0.08, 0.24), (P.BLUE, P.WHITE)),
            V("wood_sail", "a natural wood toy yacht", (0.3, 0.1, 0.32), (P.WOOD, P.CREAM), synonyms=("toy yacht",)),
            V(
                "tug_yellow",
                "a yellow toy tugboat with a cabin",
                (0.2, 0.08, 0.12),
                (P.YELLOW, P.WHITE, P.RED),
                {"sail": False},
                synonyms=("tugboat", "tug boat"),
            ),
            V(
                "bath_green",
                "a green bath boat toy",
                (0.16, 0.07, 0.1),
                (P.GREEN, P.WHITE, P.BLUE),
                {"sail": False},
                synonyms=("bath boat",),
            ),
            V("small_sail", "a small white toy sailboat with a red sail", (0.14, 0.05, 0.15), (P.WHITE, P.RED)),
            V(
                "steamer",
                "a blue toy steamer with a black funnel",
                (0.26, 0.09, 0.14),
                (P.NAVY, P.WHITE, P.BLACK),
                {"sail": False},
                synonyms=("toy steamboat", "steamboat"),
            ),
        ],
        density=200.0,
        mass_limits=(0.02, 1.5),
        friction=(0.5, 0.8),
        support_probability=0.0,
        has_front=True,
        synonyms=("boat", "sailboat", "sailing boat", "toy ship", "ship", "toy sailboat"),
        tags=(*KIDS, "bath", "water", "sail", "vehicle"),
    ),
    define(
        "play dough",
        "play dough tub",
        play_dough,
        [
            V("red", "a tub of red modelling dough", (0.065, 0.065, 0.07)),
            V("blue", "a tub of blue play dough", (0.065, 0.065, 0.07), (P.BLUE, P.YELLOW)),
            V("yellow", "a yellow tub of dough", (0.065, 0.065, 0.07), (P.YELLOW, P.RED)),
            V("green", "a green play dough pot", (0.065, 0.065, 0.07), (P.GREEN, P.YELLOW)),
            V("purple_small", "a small purple dough tub", (0.05, 0.05, 0.05), (P.PURPLE, P.YELLOW)),
            V("pink_large", "a large pink tub of modelling clay", (0.1, 0.1, 0.1), (P.PINK, P.YELLOW)),
            V("orange", "an orange play-doh tub", (0.065, 0.065, 0.07), (P.ORANGE, P.YELLOW)),
        ],
        density=650.0,
        mass_limits=(0.03, 0.8),
        friction=(0.5, 0.8),
        support_probability=0.2,
        has_front=False,
        synonyms=("playdough", "play-doh", "play doh", "modelling clay", "modeling clay", "plasticine", "dough tub"),
        tags=(*KIDS, "craft", "clay", "modelling", "tub", "art"),
    ),
)

SMALL_CATEGORIES: tuple[CategoryDef, ...] = (
    define(
        "ratchet",
        "socket ratchet",
        ratchet,
        [
            V("red", "a 3/8-inch socket ratchet with a red grip", (0.2, 0.04, 0.02)),
            V("black", "a black-handled socket wrench", (0.25, 0.045, 0.022), (P.BLACK,)),
            V("small_blue", "a small 1/4-inch ratchet with a blue grip", (0.15, 0.03, 0.016), (P.BLUE,)),
            V("chrome", "an all-chrome ratchet handle", (0.22, 0.04, 0.02), (P.SILVER,)),
            V("large_yellow", "a large 1/2-inch drive ratchet", (0.3, 0.055, 0.026), (P.YELLOW,)),
            V("green", "a green-gripped ratchet spanner", (0.2, 0.04, 0.02), (P.GREEN,)),
            V("orange", "an orange socket ratchet", (0.2, 0.04, 0.02), (P.ORANGE,)),
        ],
        density=4500.0,
        mass_limits=(0.05, 1.2),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("socket wrench", "ratchet wrench", "socket ratchet", "ratchet handle", "ratchet spanner"),
        tags=(*TOOLS, "sockets", "bolts", "mechanic", "steel", "hand tool"),
    ),
    define(
        "jump rope",
        "jump rope",
        jump_rope,
        [
            V("red", "a skipping rope with red handles, lying in a loop", (0.4, 0.44, 0.04)),
            V("blue", "a blue-handled jump rope", (0.4, 0.44, 0.04), (P.BLUE, P.WHITE)),
            V("wood", "a skipping rope with wooden handles", (0.42, 0.46, 0.045), (P.WOOD, P.CREAM)),
            V("pink", "a pink kids' jump rope", (0.34, 0.38, 0.035), (P.PINK, P.PURPLE)),
            V(
                "black",
                "a black fitness speed rope",
                (0.44, 0.46, 0.035),
                (P.BLACK, P.CHARCOAL),
                synonyms=("speed rope",),
            ),
            V("green", "a green skipping rope", (0.4, 0.44, 0.04), (P.GREEN, P.YELLOW)),
            V("yellow", "a yellow jump rope with a white cord", (0.4, 0.44, 0.04), (P.YELLOW, P.WHITE)),
        ],
        density=300.0,
        mass_limits=(0.05, 0.8),
        friction=(0.6, 0.9),
        support_probability=0.0,
        has_front=False,
        synonyms=("skipping rope", "jumprope", "skip rope", "jump-rope", "rope"),
        tags=(*KIDS, "sport", "fitness", "exercise", "playground", "flat"),
    ),
)

CATEGORIES: tuple[CategoryDef, ...] = (
    *KIDS_CATEGORIES,
    *TOOL_CATEGORIES,
    *MORE_CATEGORIES,
    *EXTRA_CATEGORIES,
    *GARAGE_CATEGORIES,
    *YARD_CATEGORIES,
    *SMALL_CATEGORIES,
)
