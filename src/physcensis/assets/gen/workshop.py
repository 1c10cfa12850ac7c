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
from shapely.geometry import LineString, Polygon

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.gen.common import rectangle
from physcensis.assets.model import RGBA, Cavity
from physcensis.assets.spec import CategoryDef, Geometry, Variant, builder, define
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
        synonyms=("toy xylophone", "glockenspiel", "kids xylophone", "musical toy", "toy piano bars"),
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
                synonyms=("storage tub",),
            ),
            V(
                "pink_fabric",
                "a pink fabric toy storage cube",
                (0.3, 0.3, 0.28),
                (P.PINK, P.PURPLE),
                {"radius": 0.01, "wall": 0.008},
                density=120.0,
                synonyms=("storage cube", "fabric bin"),
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
        synonyms=("toy box", "toy tub", "toy storage", "storage bin", "toy chest", "toy storage bin", "tub"),
        tags=(*KIDS, "storage", "container", "open", "bin", "tidy"),
    ),
)

CATEGORIES: tuple[CategoryDef, ...] = KIDS_CATEGORIES
