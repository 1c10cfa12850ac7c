"""Closed revolved solids and small containers: bottles, jars, cans, candles, soap dispensers, pen holders."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
import trimesh

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.gen.common import Vessel, rectangle, resample
from physcensis.assets.model import Cavity
from physcensis.assets.spec import CategoryDef, Geometry, NoOptions, Parts, Variant, builder, define
from physcensis.assets.spec import Variant as V


@dataclass(frozen=True)
class BottleShape:
    """Bottle proportions: the neck radius as a fraction of the body's, heights as fractions of the whole."""

    neck: float = 0.3
    shoulder: float = 0.62
    neck_start: float = 0.78
    cap: float = 0.06


@builder(BottleShape)
def bottle(v: Variant, p: BottleShape) -> Geometry:
    """Body, shoulder, neck and cap; two convex hulls (body, neck)."""
    d, _, h = v.size
    r = d / 2
    rn = p.neck * r
    shoulder = p.shoulder * h
    neck_start = p.neck_start * h
    cap_h = p.cap * h
    top = h - cap_h
    body = shapes.lathe(
        [
            (0, 0),
            (0.93 * r, 0),
            (r, 0.02 * h),
            (r, shoulder),
            (rn + 0.7 * (r - rn), 0.5 * (shoulder + neck_start)),
            (rn, neck_start),
            (rn, top),
            (0, top),
        ]
    )
    cap = shapes.cylinder(rn * 1.12, cap_h, (0, 0, top + cap_h / 2))
    parts = ((body, v.color(0, P.GREEN_GLASS)), (cap, v.color(1, P.GOLD)))
    split = body.vertices[:, 2] <= shoulder + 1e-9
    collision = (col.hull_part(body.vertices[split]), col.hull_part(np.vstack([body.vertices[~split], cap.vertices])))
    return Geometry(parts, collision)


@dataclass(frozen=True)
class FlatBottleShape:
    """The cap's height as a fraction of the whole."""

    cap: float = 0.14


@builder(FlatBottleShape)
def flat_bottle(v: Variant, p: FlatBottleShape) -> Geometry:
    """A bottle with an oval/rectangular body (shampoo, mustard): rounded box body, neck, cap."""
    x, y, h = v.size
    cap_h = p.cap * h
    body_h = h - cap_h
    body = shapes.rounded_box((x, y, body_h), 0.2 * min(x, y), (0, 0, body_h / 2))  # a flat bottom to stand on
    cap = shapes.cone(0.28 * min(x, y), 0.12 * min(x, y), cap_h + 0.004, (0, 0, body_h + cap_h / 2 - 0.002))
    parts = ((body, v.color(0, P.YELLOW)), (cap, v.color(1, P.RED)))
    return Geometry(parts, (col.hull_part(body), col.hull_part(cap)))


@dataclass(frozen=True)
class JarShape:
    """The lid's height (fraction of the whole) and the mouth's radius (fraction of the body's); `open`: an empty jar
    without its lid, a container things are dropped into."""

    lid: float = 0.16
    mouth: float = 0.85
    open: bool = False


@builder(JarShape)
def jar(v: Variant, p: JarShape) -> Geometry:
    """A closed jar: glass or ceramic body with a short neck and a lid; or an open empty one."""
    d, _, h = v.size
    r = d / 2
    if p.open:
        return _open_jar(v, p.mouth)
    lid_h = p.lid * h
    body_h = h - lid_h
    rn = p.mouth * r
    body = shapes.lathe(
        [
            (0, 0),
            (0.95 * r, 0),
            (r, 0.04 * h),
            (r, 0.82 * body_h),
            (rn, 0.95 * body_h),
            (rn, body_h + 0.002),
            (0, body_h + 0.002),
        ]
    )
    lid = shapes.lathe([(0, body_h), (rn * 1.04, body_h), (rn * 1.04, h - 0.003), (rn * 1.0, h), (0, h)])
    parts = ((body, v.color(0, P.rgb(170, 40, 50))), (lid, v.color(1, P.GOLD)))
    return Geometry(parts, (col.hull_part(np.vstack([body.vertices, lid.vertices])),))


def _open_jar(v: Variant, mouth: float) -> Geometry:
    """An empty jar, lid off: a revolved thin glass wall with shoulders up to a threaded mouth."""
    d, _, h = v.size
    r = d / 2
    outer = np.array([(0.95 * r, 0.0), (r, 0.04 * h), (r, 0.8 * h), (mouth * r, 0.92 * h), (mouth * r, h)])
    vessel = Vessel(outer, 0.003, 0.005, stations=4)
    return Geometry(((vessel.mesh(), v.color(0, P.GLASS)),), tuple(vessel.collision(16)), vessel.cavity())


@dataclass(frozen=True)
class CanShape:
    """Fractions of the height: the tapered neck (0: straight sides) and the paper label (0: none)."""

    neck: float = 0.0
    label: float = 0.0


@builder(CanShape)
def can(v: Variant, p: CanShape) -> Geometry:
    """A drinks or food can: cylinder with rolled rims; collision is an exact cylinder primitive."""
    d, _, h = v.size
    r = d / 2
    neck = p.neck
    prof = [
        (0, 0),
        (0.9 * r, 0),
        (r, 0.03 * h),
        (r, h * (1 - neck) - 0.004),
        ((1 - 0.6 * neck - 0.04) * r if neck else 0.97 * r, h - 0.003),
        ((1 - 0.6 * neck - 0.04) * r if neck else 0.97 * r, h),
        (0, h),
    ]
    body = shapes.lathe(prof)
    label_h = p.label
    parts = [(body, v.color(0, P.RED))]
    if label_h:
        band = shapes.lathe(
            [(0, 0.12 * h), (r + 0.0005, 0.12 * h), (r + 0.0005, (0.12 + label_h) * h), (0, (0.12 + label_h) * h)]
        )
        parts.append((band, v.color(1, P.WHITE)))
    return Geometry(tuple(parts), (col.cylinder_part(r, h, (0, 0, h / 2)),))


@builder(NoOptions)
def box_can(v: Variant, _: NoOptions) -> Geometry:
    """A rectangular tin with rounded corners (potted meat, sardines)."""
    x, y, h = v.size
    body = shapes.slab(x, y, h * 0.93, 0.3 * min(x, y), (0, 0, h * 0.465))
    lid = shapes.slab(x * 0.97, y * 0.97, h * 0.07, 0.3 * min(x, y), (0, 0, h * 0.965))
    parts = ((body, v.color(0, P.BLUE)), (lid, v.color(1, P.SILVER)))
    return Geometry(parts, (col.box_part((x, y, h), (0, 0, h / 2)),))


@dataclass(frozen=True)
class CandleShape:
    """A pillar, a taper in a holder, a tea light or a candle in a jar."""

    style: Literal["pillar", "taper", "tealight", "jar"] = "pillar"


@builder(CandleShape)
def candle(v: Variant, p: CandleShape) -> Geometry:
    """Pillar, taper-in-holder, tea light and jar candles with a wick."""
    if p.style == "taper":
        return _taper_candle(v)
    d, _, h = v.size
    r = d / 2
    wax = v.color(0, P.WAX)
    wick_h = 0.012 if p.style != "tealight" else 0.006
    body_h = h - wick_h
    parts: Parts
    if p.style == "tealight":
        cup = shapes.lathe(
            [(0, 0), (r, 0), (r, body_h), (0.94 * r, body_h), (0.94 * r, 0.7 * body_h), (0, 0.7 * body_h)]
        )
        wax_top = shapes.cylinder(0.94 * r - 0.0002, 0.7 * body_h, (0, 0, 0.35 * body_h + 0.0004))
        parts = ((cup, v.color(1, P.SILVER)), (wax_top, wax))
    elif p.style == "jar":
        glass = shapes.lathe(
            [(0, 0), (r, 0), (r, body_h), (0.92 * r, body_h), (0.92 * r, 0.6 * body_h), (0, 0.6 * body_h)]
        )
        wax_fill = shapes.cylinder(0.92 * r - 0.0005, 0.6 * body_h, (0, 0, 0.3 * body_h + 0.0004))
        parts = ((glass, v.color(1, P.GLASS)), (wax_fill, wax))
    else:
        pillar = shapes.lathe([(0, 0), (r, 0), (r, body_h), (0.9 * r, body_h - 0.003), (0, body_h - 0.006)])
        parts = ((pillar, wax),)
    wick = shapes.cylinder(0.0012, wick_h + 0.006, (0, 0, h - (wick_h + 0.006) / 2))
    return Geometry((*parts, (wick, P.BLACK)), (col.cylinder_part(r, body_h, (0, 0, body_h / 2)),))


def _taper_candle(v: Variant) -> Geometry:
    """A taper candle standing in a holder."""
    d, _, h = v.size
    r = d / 2
    wax = v.color(0, P.WAX)
    holder_h = 0.035
    holder = shapes.lathe(
        [
            (0, 0),
            (r, 0),
            (r, 0.006),
            (0.3 * r, 0.012),
            (0.25 * r, holder_h - 0.008),
            (0.45 * r, holder_h),
            (0, holder_h),
        ]
    )
    stick_r = min(0.011, 0.3 * r)
    stick = shapes.lathe(
        [
            (0, holder_h - 0.01),
            (stick_r, holder_h - 0.01),
            (stick_r, h - 0.02),
            (0.5 * stick_r, h - 0.01),
            (0, h - 0.01),
        ]
    )
    wick = shapes.cylinder(0.0012, 0.012, (0, 0, h - 0.006))
    parts = ((holder, v.color(1, P.BRASS)), (stick, wax), (wick, P.BLACK))
    collision = (
        col.cylinder_part(r, 0.012, (0, 0, 0.006)),
        col.cylinder_part(0.45 * r, holder_h - 0.012, (0, 0, (holder_h + 0.012) / 2)),
        col.cylinder_part(stick_r, h - holder_h - 0.01, (0, 0, (h + holder_h - 0.01) / 2)),
    )
    return Geometry(parts, collision)


@dataclass(frozen=True)
class SoapDispenserShape:
    """A square body instead of a round one."""

    square: bool = False


@builder(SoapDispenserShape)
def soap_dispenser(v: Variant, p: SoapDispenserShape) -> Geometry:
    """A pump bottle: body, collar, pump head and a nozzle pointing to +x."""
    x, y, h = v.size
    d = y
    body_h = 0.68 * h
    if p.square:
        body = shapes.rounded_box((0.75 * x, d, body_h), 0.012, (0, 0, body_h / 2))
    else:
        r = d / 2
        body = shapes.lathe([(0, 0), (0.95 * r, 0), (r, 0.05 * h), (r, 0.85 * body_h), (0.55 * r, body_h), (0, body_h)])
    collar = shapes.cylinder(0.014, 0.02, (0, 0, body_h + 0.008))
    stem = shapes.cylinder(0.0045, h - body_h - 0.035, (0, 0, body_h + 0.018 + (h - body_h - 0.035) / 2))
    head_z = h - 0.012
    nozzle_len = x - 0.75 * x / 2 if p.square else x - d / 2
    head = shapes.rounded_box((0.03, 0.022, 0.024), 0.006, (0.004, 0, head_z))
    nozzle = shapes.box((nozzle_len, 0.008, 0.008), (nozzle_len / 2, 0, head_z + 0.004))
    body_color = v.color(0, P.rgb(230, 170, 200, 0.9))
    pump = v.color(1, P.WHITE)
    parts = ((body, body_color), (collar, pump), (stem, pump), (head, pump), (nozzle, pump))
    collision = (col.hull_part(body), col.hull_part(np.vstack([collar.vertices, head.vertices, nozzle.vertices])))
    return Geometry(parts, collision)


@dataclass(frozen=True)
class PenHolderShape:
    """A square box, or a round cup with this wall thickness (m)."""

    square: bool = False
    wall: float = 0.003


@builder(PenHolderShape)
def pen_holder(v: Variant, p: PenHolderShape) -> Geometry:
    """An open cup for pens: round (revolved) or square (five slabs)."""
    x, y, h = v.size
    if p.square:
        wall, floor = 0.004, 0.006
        outer = shapes.box((x, y, h), (0, 0, h / 2))
        inner = shapes.box((x - 2 * wall, y - 2 * wall, h), (0, 0, floor + h / 2))
        mesh = trimesh.boolean.difference([outer, inner], engine="manifold")
        cavity = Cavity(rectangle(x - 2 * wall, y - 2 * wall), floor, h - floor)
        return Geometry(((mesh, v.color(0, P.WOOD)),), tuple(col.open_box_parts(x, y, h, wall, floor)), cavity)
    vessel = Vessel(resample([(x / 2, 0.0), (x / 2, h)], 4), p.wall, 0.006, stations=1)
    return Geometry(((vessel.mesh(), v.color(0, P.CHARCOAL)),), tuple(vessel.collision(14)), vessel.cavity())


CATEGORIES: tuple[CategoryDef, ...] = (
    define(
        "bottle",
        "bottle",
        bottle,
        [
            V(
                "water_plastic",
                "a clear plastic water bottle with a blue cap",
                (0.065, 0.065, 0.21),
                (P.rgb(200, 230, 245, 0.6), P.BLUE),
                {"neck": 0.45, "shoulder": 0.7, "neck_start": 0.88, "cap": 0.06},
                synonyms=("water bottle",),
                tags=("water", "plastic", "drink"),
            ),
            V(
                "wine_red",
                "a dark green wine bottle",
                (0.075, 0.075, 0.3),
                (P.GREEN_GLASS, P.DARK_RED),
                {"neck": 0.3, "shoulder": 0.62, "neck_start": 0.78},
                synonyms=("wine bottle",),
                tags=("wine", "glass"),
            ),
            V(
                "olive_oil",
                "a tall bottle of olive oil",
                (0.06, 0.06, 0.28),
                (P.rgb(150, 160, 40, 0.85), P.BLACK),
                {"neck": 0.35, "shoulder": 0.7, "neck_start": 0.82},
                synonyms=("oil bottle", "cooking oil"),
                tags=("oil", "kitchen", "glass"),
            ),
            V(
                "beer_brown",
                "a brown glass beer bottle",
                (0.062, 0.062, 0.23),
                (P.AMBER_GLASS, P.GOLD),
                {"neck": 0.4, "shoulder": 0.55, "neck_start": 0.72},
                synonyms=("beer bottle",),
                tags=("beer", "glass"),
            ),
            V(
                "soda_large",
                "a large plastic soda bottle",
                (0.095, 0.095, 0.31),
                (P.rgb(120, 60, 40, 0.8), P.RED),
                {"neck": 0.3, "shoulder": 0.68, "neck_start": 0.85, "cap": 0.05},
                synonyms=("soda bottle", "pop bottle"),
                tags=("soda", "plastic", "drink"),
            ),
            V(
                "sports_steel",
                "a reusable stainless steel water bottle",
                (0.072, 0.072, 0.26),
                (P.STEEL, P.BLACK),
                {"neck": 0.6, "shoulder": 0.8, "neck_start": 0.86, "cap": 0.08},
                density=450.0,
                synonyms=("water bottle", "flask", "thermos"),
                tags=("water", "metal", "reusable"),
            ),
            V(
                "milk_glass",
                "a glass bottle of milk",
                (0.075, 0.075, 0.24),
                (P.rgb(248, 248, 240, 0.95), P.BLUE),
                {"neck": 0.5, "shoulder": 0.55, "neck_start": 0.8},
                synonyms=("milk bottle",),
                tags=("milk", "glass"),
            ),
            V(
                "ketchup",
                "a red bottle of ketchup",
                (0.065, 0.065, 0.2),
                (P.rgb(190, 30, 25), P.WHITE),
                {"neck": 0.5, "shoulder": 0.72, "neck_start": 0.8, "cap": 0.1},
                synonyms=("ketchup bottle", "sauce bottle"),
                tags=("ketchup", "sauce", "condiment"),
            ),
        ],
        density=950.0,
        mass_limits=(0.2, 2.2),
        friction=(0.3, 0.6),
        support_probability=0.0,
        has_front=False,
        synonyms=("flask",),
        tags=("drink", "liquid"),
    ),
    define(
        "bottle",
        "flat bottle",
        flat_bottle,
        [
            V(
                "shampoo",
                "a blue shampoo bottle",
                (0.045, 0.075, 0.2),
                (P.rgb(60, 120, 200), P.WHITE),
                synonyms=("shampoo bottle", "lotion bottle"),
                tags=("bathroom", "shampoo", "plastic"),
            ),
            V(
                "lotion",
                "a white bottle of body lotion",
                (0.04, 0.07, 0.18),
                (P.WHITE, P.SKY),
                synonyms=("lotion bottle",),
                tags=("bathroom", "lotion"),
            ),
            V(
                "dish_soap",
                "a green dish soap bottle",
                (0.045, 0.08, 0.22),
                (P.LIME, P.WHITE),
                synonyms=("dish soap", "detergent bottle"),
                tags=("kitchen", "soap", "cleaning"),
            ),
            V(
                "mouthwash",
                "a bottle of mouthwash",
                (0.05, 0.085, 0.2),
                (P.rgb(60, 170, 190, 0.8), P.WHITE),
                synonyms=("mouthwash bottle",),
                tags=("bathroom",),
            ),
            V(
                "sunscreen",
                "an orange sunscreen bottle",
                (0.035, 0.06, 0.16),
                (P.ORANGE, P.WHITE),
                tags=("bathroom", "sunscreen"),
            ),
            V(
                "ycb_006",
                "the YCB mustard bottle: a yellow squeeze bottle of mustard",
                (0.05, 0.085, 0.175),
                (P.YELLOW, P.rgb(230, 180, 20)),
                mass=0.603,
                asset_id="ycb_006_mustard_bottle",
                synonyms=("mustard bottle", "mustard"),
                tags=("ycb", "condiment"),
            ),
        ],
        density=900.0,
        mass_limits=(0.1, 1.2),
        friction=(0.3, 0.6),
        support_probability=0.0,
        has_front=True,
        prefix="bottle_flat",
        synonyms=("bottle", "plastic bottle"),
        tags=("liquid",),
    ),
    define(
        "jar",
        "jar",
        jar,
        [
            V(
                "jam",
                "a small glass jar of strawberry jam with a gold lid",
                (0.07, 0.07, 0.095),
                (P.rgb(160, 20, 40, 0.95), P.GOLD),
                synonyms=("jam jar",),
                tags=("jam", "breakfast"),
            ),
            V(
                "spice_small",
                "a small spice jar with a black lid",
                (0.045, 0.045, 0.1),
                (P.rgb(170, 70, 30, 0.95), P.BLACK),
                {"mouth": 0.9, "lid": 0.22},
                synonyms=("spice jar",),
                tags=("spices", "spice", "kitchen", "seasoning"),
            ),
            V(
                "spice_green",
                "a small jar of dried herbs",
                (0.045, 0.045, 0.1),
                (P.rgb(90, 120, 50, 0.95), P.RED),
                {"mouth": 0.9, "lid": 0.22},
                synonyms=("spice jar", "herb jar"),
                tags=("spices", "herbs", "kitchen"),
            ),
            V(
                "honey",
                "a jar of golden honey",
                (0.075, 0.075, 0.11),
                (P.rgb(220, 150, 30, 0.9), P.WOOD),
                synonyms=("honey jar",),
                tags=("honey", "breakfast"),
            ),
            V(
                "mason",
                "a large glass mason jar",
                (0.085, 0.085, 0.14),
                (P.GLASS, P.SILVER),
                {"mouth": 0.8},
                synonyms=("mason jar",),
                tags=("glass", "storage"),
            ),
            V(
                "pickles",
                "a jar of pickles",
                (0.1, 0.1, 0.16),
                (P.rgb(120, 150, 60, 0.9), P.GREEN),
                synonyms=("pickle jar",),
                tags=("pickles", "food"),
            ),
            V(
                "peanut_butter",
                "a plastic jar of peanut butter",
                (0.085, 0.085, 0.11),
                (P.rgb(190, 130, 70), P.RED),
                {"mouth": 0.9},
                synonyms=("peanut butter jar",),
                tags=("peanut butter", "breakfast"),
            ),
            V(
                "open_mason",
                "an empty open glass mason jar without its lid",
                (0.085, 0.085, 0.14),
                (P.GLASS,),
                {"mouth": 0.85, "open": True},
                density=2500.0,
                synonyms=("empty jar", "open jar", "glass jar", "mason jar"),
                tags=("glass", "storage", "empty", "open"),
            ),
            V(
                "open_wide",
                "a wide empty glass jar with no lid",
                (0.11, 0.11, 0.15),
                (P.GLASS,),
                {"mouth": 0.9, "open": True},
                density=2500.0,
                synonyms=("empty jar", "open jar", "glass jar"),
                tags=("glass", "storage", "empty", "open"),
            ),
        ],
        density=1100.0,
        mass_limits=(0.08, 2.0),
        friction=(0.3, 0.6),
        support_probability=0.5,
        has_front=False,
        synonyms=("pot", "container"),
        tags=("kitchen", "food", "lid"),
    ),
    define(
        "can",
        "can",
        can,
        [
            V(
                "soda_red",
                "a red aluminium soda can",
                (0.066, 0.066, 0.122),
                (P.RED, P.WHITE),
                {"neck": 0.08, "label": 0.3},
                synonyms=("soda can", "soft drink"),
                tags=("soda", "drink", "aluminium"),
            ),
            V(
                "soda_silver",
                "a silver can of sparkling water",
                (0.066, 0.066, 0.122),
                (P.SILVER, P.SKY),
                {"neck": 0.08, "label": 0.4},
                synonyms=("soda can", "drink can"),
                tags=("soda", "drink"),
            ),
            V(
                "energy_tall",
                "a tall slim energy drink can",
                (0.058, 0.058, 0.168),
                (P.rgb(30, 60, 140), P.SILVER),
                {"neck": 0.06, "label": 0.5},
                synonyms=("energy drink",),
                tags=("drink",),
            ),
            V(
                "beer_green",
                "a green can of beer",
                (0.066, 0.066, 0.122),
                (P.rgb(40, 120, 60), P.GOLD),
                {"neck": 0.08, "label": 0.3},
                synonyms=("beer can",),
                tags=("beer", "drink"),
            ),
            V(
                "soup",
                "a can of soup with a paper label",
                (0.067, 0.067, 0.1),
                (P.SILVER, P.rgb(200, 40, 40)),
                {"label": 0.76},
                synonyms=("soup can", "tin can", "tin"),
                tags=("soup", "food", "pantry"),
            ),
            V(
                "beans_large",
                "a large tin of beans",
                (0.075, 0.075, 0.11),
                (P.SILVER, P.rgb(40, 110, 170)),
                {"label": 0.76},
                synonyms=("tin", "food can"),
                tags=("food", "pantry"),
            ),
            V(
                "tomatoes",
                "a can of chopped tomatoes",
                (0.074, 0.074, 0.115),
                (P.SILVER, P.rgb(220, 60, 40)),
                {"label": 0.76},
                synonyms=("tin", "food can"),
                tags=("tomato", "food", "pantry"),
            ),
            V(
                "ycb_005",
                "the YCB tomato soup can",
                (0.066, 0.066, 0.101),
                (P.SILVER, P.rgb(200, 30, 30)),
                {"label": 0.76},
                mass=0.349,
                asset_id="ycb_005_tomato_soup_can",
                synonyms=("soup can",),
                tags=("ycb", "soup", "food"),
            ),
            V(
                "ycb_007",
                "the YCB tuna fish can: a short flat can",
                (0.085, 0.085, 0.033),
                (P.SILVER, P.rgb(40, 80, 160)),
                {"label": 0.6},
                mass=0.171,
                asset_id="ycb_007_tuna_fish_can",
                synonyms=("tuna can", "tin"),
                tags=("ycb", "tuna", "fish", "food"),
            ),
        ],
        density=1000.0,
        mass_limits=(0.1, 0.9),
        friction=(0.3, 0.6),
        support_probability=0.6,
        has_front=False,
        synonyms=("tin", "tin can"),
        tags=("food", "drink", "pantry", "metal", "cylinder"),
    ),
    define(
        "can",
        "rectangular can",
        box_can,
        [
            V(
                "sardines",
                "a flat rectangular tin of sardines",
                (0.105, 0.075, 0.025),
                (P.rgb(40, 90, 150), P.SILVER),
                synonyms=("sardine tin",),
                tags=("fish", "food"),
            ),
            V(
                "spam",
                "a rectangular can of luncheon meat",
                (0.1, 0.05, 0.085),
                (P.rgb(40, 70, 150), P.YELLOW),
                tags=("meat", "food"),
            ),
            V(
                "cookies",
                "a square cookie tin",
                (0.16, 0.16, 0.08),
                (P.rgb(30, 60, 130), P.GOLD),
                density=300.0,
                synonyms=("cookie tin", "biscuit tin"),
                tags=("cookies", "biscuits"),
            ),
            V(
                "tea_tin",
                "a small square tin of tea leaves",
                (0.08, 0.08, 0.12),
                (P.DARK_GREEN, P.GOLD),
                density=350.0,
                synonyms=("tea tin", "tea caddy"),
                tags=("tea",),
            ),
            V(
                "ycb_010",
                "the YCB potted meat can: a blue rectangular can",
                (0.05, 0.097, 0.082),
                (P.rgb(40, 70, 160), P.SILVER),
                mass=0.37,
                asset_id="ycb_010_potted_meat_can",
                synonyms=("potted meat can", "potted meat"),
                tags=("ycb", "meat", "food"),
            ),
        ],
        density=900.0,
        mass_limits=(0.08, 1.2),
        friction=(0.3, 0.6),
        support_probability=0.7,
        has_front=True,
        prefix="can_rect",
        synonyms=("tin", "tin can"),
        tags=("food", "pantry", "metal"),
    ),
    define(
        "candle",
        "candle",
        candle,
        [
            V("pillar_white", "a thick white pillar candle", (0.075, 0.075, 0.15)),
            V("pillar_red", "a short red pillar candle", (0.07, 0.07, 0.1), (P.rgb(180, 30, 40),)),
            V(
                "taper_brass",
                "a tall taper candle in a brass candlestick",
                (0.08, 0.08, 0.3),
                (P.CREAM, P.BRASS),
                {"style": "taper"},
                density=900.0,
                synonyms=("candlestick", "taper candle"),
                tags=("candlestick", "dinner"),
            ),
            V(
                "taper_silver",
                "a blue taper candle in a silver holder",
                (0.07, 0.07, 0.27),
                (P.rgb(60, 90, 170), P.SILVER),
                {"style": "taper"},
                density=900.0,
                synonyms=("candlestick", "taper candle"),
            ),
            V(
                "tealight",
                "a small tea light candle",
                (0.039, 0.039, 0.018),
                options={"style": "tealight"},
                synonyms=("tea light", "tealight"),
            ),
            V(
                "jar_scented",
                "a scented candle in a glass jar",
                (0.08, 0.08, 0.1),
                (P.rgb(240, 200, 210), P.GLASS),
                {"style": "jar"},
                density=1000.0,
                synonyms=("jar candle", "scented candle"),
            ),
        ],
        density=900.0,
        mass_limits=(0.005, 1.0),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("candle light",),
        tags=("wax", "light", "decor", "romantic", "dinner", "wick"),
    ),
    define(
        "soap dispenser",
        "soap dispenser",
        soap_dispenser,
        [
            V("pink", "a pink liquid soap dispenser with a white pump", (0.09, 0.07, 0.18)),
            V("glass_clear", "a clear glass soap dispenser with a steel pump", (0.1, 0.075, 0.19), (P.GLASS, P.STEEL)),
            V("white_ceramic", "a white ceramic soap pump bottle", (0.1, 0.08, 0.17), (P.WHITE, P.SILVER)),
            V("amber", "an amber glass hand soap dispenser", (0.09, 0.07, 0.2), (P.AMBER_GLASS, P.BLACK)),
            V(
                "square_green",
                "a square green soap dispenser",
                (0.1, 0.065, 0.17),
                (P.rgb(110, 170, 110), P.WHITE),
                {"square": True},
            ),
        ],
        density=900.0,
        mass_limits=(0.15, 0.9),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=True,
        synonyms=("soap pump", "hand soap", "liquid soap", "lotion pump"),
        tags=("bathroom", "soap", "pump", "hygiene"),
    ),
    define(
        "pen holder",
        "pen holder",
        pen_holder,
        [
            V(
                "black_mesh",
                "a round black metal mesh pen holder",
                (0.08, 0.08, 0.1),
                (P.CHARCOAL,),
                {"wall": 0.002},
                density=2500.0,
            ),
            V(
                "white_ceramic",
                "a white ceramic pen cup",
                (0.085, 0.085, 0.11),
                (P.WHITE,),
                density=2000.0,
                synonyms=("pen cup",),
            ),
            V(
                "wooden_square",
                "a square wooden pencil holder",
                (0.08, 0.08, 0.1),
                (P.WOOD,),
                {"square": True},
                density=700.0,
                synonyms=("pencil holder",),
            ),
            V(
                "blue_plastic",
                "a blue plastic pen pot",
                (0.075, 0.075, 0.1),
                (P.rgb(50, 110, 200),),
                density=1100.0,
                synonyms=("pen pot",),
            ),
            V(
                "bamboo_square",
                "a bamboo desk organiser cup",
                (0.09, 0.09, 0.115),
                (P.BAMBOO,),
                {"square": True},
                density=700.0,
                synonyms=("desk organiser",),
            ),
        ],
        density=1500.0,
        mass_limits=(0.03, 0.7),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("pencil holder", "pen cup", "pencil cup"),
        tags=("desk", "office", "pens", "pencils", "stationery", "container"),
    ),
)
