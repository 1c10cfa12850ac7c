"""Revolved tableware and cookware: plates, bowls, cups, mugs, glasses, pitchers, teapots, pots, pans, vases."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.gen.common import Vessel, loop_handle, resample, spout
from physcensis.assets.spec import CategoryDef, Geometry, NoOptions, Variant, builder, define
from physcensis.assets.spec import Variant as V

CERAMIC = 2300.0


@dataclass(frozen=True)
class PlateShape:
    """The well's radius as a fraction of the plate's."""

    well: float = 0.62


@builder(PlateShape)
def plate(v: Variant, p: PlateShape) -> Geometry:
    """A solid plate with a recessed well; one convex hull so stacks rest rim on rim."""
    d, _, h = v.size
    r = d / 2
    well = p.well * r
    t = min(0.006, 0.3 * h)
    prof = [
        (0, t * 0.5),
        (0.55 * r - 0.004, t * 0.5),
        (0.55 * r, 0.0),
        (0.6 * r, 0.0),
        (r, h - 0.003),
        (r - 0.002, h),
        (r - 0.007, h),
        (well, t + 0.25 * (h - t)),
        (0.9 * well, t),
        (0, t),
    ]
    mesh = shapes.lathe(prof, 48)
    # the hull of a coarser lathe: exactly symmetric, so a plate rests flat and stacks without tilting
    return Geometry(((mesh, v.color(0, P.WHITE)),), (col.hull_part(shapes.lathe(prof, 32)),))


def _bowl_outer(r: float, h: float, foot: float, curve: float) -> np.ndarray:
    """Outer wall from the foot ring up to the rim; curve 1 = round, 0 = straight flared."""
    t = np.linspace(0.0, np.pi / 2, 14)
    round_r = foot + (r - foot) * np.sin(t)
    round_z = h * (1 - np.cos(t))
    s = np.linspace(0, 1, 14)
    straight_r, straight_z = foot + (r - foot) * s, h * s
    return np.stack([curve * round_r + (1 - curve) * straight_r, curve * round_z + (1 - curve) * straight_z], axis=1)


@dataclass(frozen=True)
class BowlShape:
    """The foot's radius (fraction of the rim's), the wall (m), the curve (1 round, 0 straight flared)."""

    foot: float = 0.45
    wall: float = 0.005
    curve: float = 0.85


@builder(BowlShape)
def bowl(v: Variant, p: BowlShape) -> Geometry:
    d, _, h = v.size
    r = d / 2
    foot = p.foot * r
    wall = p.wall
    vessel = Vessel(_bowl_outer(r, h, foot, p.curve), wall, wall, stations=3)
    return Geometry(((vessel.mesh(), v.color(0, P.WHITE)),), tuple(vessel.collision(16)), vessel.cavity())


@dataclass(frozen=True)
class CupShape:
    """A handle; the bottom's radius (fraction of the rim's); wall and floor (m); the curve (0: straight)."""

    handle: bool = False
    bottom: float = 0.7
    wall: float = 0.002
    curve: float = 0.0
    floor: float | None = None  # None: the wall's thickness, at least 3 mm


@builder(CupShape)
def cup(v: Variant, p: CupShape) -> Geometry:
    """Tapered cup (paper, plastic) or a teacup with a handle (`p.handle`)."""
    x, y, h = v.size
    handle = p.handle
    r_top = x / 2
    r_bot = p.bottom * r_top
    wall = p.wall
    curve = p.curve
    outer = _bowl_outer(r_top, h, r_bot, curve) if curve else resample([(r_bot, 0.0), (r_top, h)], 8)
    vessel = Vessel(outer, wall, p.floor if p.floor is not None else max(wall, 0.003), stations=2 if not curve else 3)
    parts = [(vessel.mesh(), v.color(0, P.WHITE))]
    collision = vessel.collision(16)
    if handle:
        attach = float(np.interp(0.55 * h, vessel.outer[:, 1], vessel.outer[:, 0]))
        reach = r_top + (y - x) - attach
        mesh, hparts = loop_handle(attach, 0.8 * h, 0.3 * h, reach, 0.0045)
        parts.append((mesh, v.color(1, v.color(0, P.WHITE))))
        collision += hparts
    return Geometry(tuple(parts), tuple(collision), vessel.cavity())


@dataclass(frozen=True)
class MugShape:
    """Wall (m), the bottom's radius (fraction of the rim's) and the handle's thickness (m)."""

    wall: float = 0.0045
    bottom: float = 0.97
    handle_thickness: float = 0.006


@builder(MugShape)
def mug(v: Variant, p: MugShape) -> Geometry:
    x, y, h = v.size
    r = x / 2
    wall = p.wall
    outer = resample([(r * p.bottom, 0.0), (r, h)], 6)
    vessel = Vessel(outer, wall, 0.007, stations=1)
    reach = y - x
    handle, hparts = loop_handle(r, 0.82 * h, 0.22 * h, reach, p.handle_thickness, squareness=0.45)
    body = vessel.mesh()
    parts = [(body, v.color(0, P.WHITE)), (handle, v.color(1, v.color(0, P.WHITE)))]
    return Geometry(tuple(parts), (*vessel.collision(16), *hparts), vessel.cavity())


@dataclass(frozen=True)
class GlassShape:
    """The bottom's radius (fraction of the rim's), wall and floor (m)."""

    bottom: float = 0.85
    wall: float = 0.0025
    floor: float = 0.01


@builder(GlassShape)
def glass(v: Variant, p: GlassShape) -> Geometry:
    d, _, h = v.size
    r = d / 2
    outer = resample([(r * p.bottom, 0.0), (r, h)], 6)
    vessel = Vessel(outer, p.wall, p.floor, stations=1)
    return Geometry(((vessel.mesh(), v.color(0, P.GLASS)),), tuple(vessel.collision(16)), vessel.cavity())


@dataclass(frozen=True)
class WineGlassShape:
    """The foot's radius (fraction of the bowl's), the bowl's height (fraction of the whole), how far the bowl
    closes (fraction of a half turn).
    """

    foot: float = 0.8
    bowl: float = 0.5
    closing: float = 0.6


@builder(WineGlassShape)
def wine_glass(v: Variant, p: WineGlassShape) -> Geometry:
    """Foot, stem and a tulip bowl (the bowl is the open container)."""
    d, _, h = v.size
    r_bowl = d / 2
    r_foot = p.foot * r_bowl
    bowl_h = p.bowl * h
    stem_r = 0.0035
    z0 = h - bowl_h
    theta = np.linspace(0.12, p.closing * np.pi, 14)
    rr = r_bowl * np.sin(theta) / np.sin(theta).max()
    zz = z0 + bowl_h * (1 - np.cos(theta)) / (1 - np.cos(theta[-1]))
    outer = np.stack([rr, zz], axis=1)
    foot_t = 0.004
    base = [
        (0.0, 0.0),
        (r_foot, 0.0),
        (r_foot, 0.0025),
        (stem_r * 2.2, foot_t + 0.004),
        (stem_r, foot_t + 0.012),
        (stem_r, z0 - 0.006),
        (rr[0], z0 - 0.001),
    ]
    vessel = Vessel(outer, 0.002, 0.006, stations=4, base=base)
    collision = [
        col.cylinder_part(r_foot, foot_t, (0, 0, foot_t / 2)),
        col.cylinder_part(stem_r, z0 - foot_t, (0, 0, (z0 + foot_t) / 2)),
        *vessel.collision(14),
    ]
    return Geometry(((vessel.mesh(48), v.color(0, P.GLASS)),), tuple(collision), vessel.cavity())


@builder(NoOptions)
def saucer(v: Variant, _: NoOptions) -> Geometry:
    return plate.draw(v, PlateShape(well=0.42))


@dataclass(frozen=True)
class PitcherShape:
    """How far the body bellies out (fraction of the radius)."""

    belly: float = 0.06


@builder(PitcherShape)
def pitcher(v: Variant, p: PitcherShape) -> Geometry:
    """A jug: slightly bellied body, pinched lip (spout) at +x, handle at -x."""
    x, y, h = v.size
    r = y / 2
    wall = 0.003
    zs = np.linspace(0, h, 12)
    belly = p.belly
    rr = r * (0.88 + belly * np.sin(np.pi * zs / h) - 0.02 * (zs / h))
    rr = rr / rr.max() * r
    vessel = Vessel(np.stack([rr, zs], axis=1), wall, 0.005, stations=3)
    lip = x - y
    handle_reach = 0.55 * lip
    spout_reach = lip - handle_reach
    rim = rr[-1]
    lip_mesh = shapes.hull(
        [
            (rim - 0.012, -0.022, h - 0.03),
            (rim - 0.012, 0.022, h - 0.03),
            (rim - 0.012, -0.024, h),
            (rim - 0.012, 0.024, h),
            (rim + spout_reach, 0, h),
            (rim + spout_reach - 0.004, 0, h - 0.012),
        ]
    )
    handle, hparts = loop_handle(
        r * 0.97, 0.85 * h, 0.3 * h, handle_reach + (r - r * 0.97), 0.008, yaw=np.pi, squareness=0.5
    )
    color = v.color(0, P.WHITE)
    parts = ((vessel.mesh(), color), (lip_mesh, color), (handle, v.color(1, color)))
    return Geometry(parts, (*vessel.collision(16), col.hull_part(lip_mesh), *hparts), vessel.cavity())


@builder(NoOptions)
def teapot(v: Variant, _: NoOptions) -> Geometry:
    """A closed teapot: round body, lid with knob, spout at +x, handle at -x."""
    x, y, h = v.size
    r = y / 2
    body_h = 0.78 * h
    t = np.linspace(-0.5 * np.pi, 0.5 * np.pi, 20)
    prof = [(0.0, 0.0)] + [
        (max(0.6 * r, r * np.cos(a)) if a < 0 else r * np.cos(a) ** 0.8, body_h / 2 * (1 + np.sin(a))) for a in t[1:-1]
    ]
    prof = (
        [(0.0, 0.0), (0.62 * r, 0.0)]
        + [(rr, zz) for rr, zz in prof[1:] if zz > 0.005]
        + [(0.45 * r, body_h), (0.0, body_h)]
    )
    body = shapes.lathe(prof)
    lid = shapes.lathe(
        [
            (0, body_h - 0.002),
            (0.47 * r, body_h - 0.002),
            (0.4 * r, body_h + 0.1 * (h - body_h)),
            (0.1 * r, body_h + 0.45 * (h - body_h)),
            (0.1 * r, h - 0.04 * h),
            (0.16 * r, h - 0.03 * h),
            (0.1 * r, h),
            (0, h),
        ]
    )
    reach_spout = 0.55 * (x - y)
    reach_handle = (x - y) - reach_spout
    s_mesh, s_parts = spout(
        np.array([0.7 * r, 0, 0.3 * body_h]),
        np.array([r + reach_spout - 0.008, 0, 0.92 * body_h]),
        0.0,
        0.016 * r / 0.08,
        0.008,
    )
    h_mesh, h_parts = loop_handle(
        0.93 * r, 0.85 * body_h, 0.25 * body_h, reach_handle + 0.07 * r, 0.008, yaw=np.pi, squareness=0.7
    )
    color = v.color(0, P.WHITE)
    parts = ((body, color), (lid, v.color(1, color)), (s_mesh, color), (h_mesh, color))
    return Geometry(parts, (col.hull_part(np.vstack([body.vertices, lid.vertices])), *s_parts, *h_parts))


@dataclass(frozen=True)
class CookingPotShape:
    """Wall and floor thickness (m)."""

    wall: float = 0.0015
    floor: float = 0.004


@builder(CookingPotShape)
def cooking_pot(v: Variant, p: CookingPotShape) -> Geometry:
    """A stock pot: straight walls, thick base, two side handles on +y and -y."""
    x, y, h = v.size
    r = x / 2
    outer = resample([(r, 0.0), (r, h)], 6)
    vessel = Vessel(outer, p.wall, p.floor, stations=1)
    reach = (y - x) / 2
    grip_w = min(0.1, 0.6 * r)
    handles = []
    hparts = []
    for side in (1, -1):
        center = (0, side * (r + reach / 2 - 0.002), 0.85 * h)
        handles.append(shapes.rounded_box((grip_w, reach + 0.004, 0.014), 0.004, center))
        hparts.append(col.box_part((grip_w, reach + 0.004, 0.014), center))
    color = v.color(0, P.STEEL)
    parts = ((vessel.mesh(), color), (handles[0], v.color(1, P.CHARCOAL)), (handles[1], v.color(1, P.CHARCOAL)))
    return Geometry(parts, (*vessel.collision(16), *hparts), vessel.cavity())


@dataclass(frozen=True)
class FryingPanShape:
    """The pan's depth (m); the handle rises to the full height."""

    depth: float = 0.05


@builder(FryingPanShape)
def frying_pan(v: Variant, p: FryingPanShape) -> Geometry:
    """A shallow flared pan with a long rising handle towards -y."""
    x, y, h_total = v.size
    r = x / 2
    h = p.depth
    outer = resample([(0.8 * r, 0.0), (r, h)], 6)
    vessel = Vessel(outer, 0.003, 0.005, stations=1)
    length = y - x
    start = np.array([0, -(r - 0.006), h - 0.008])
    end = np.array([0, -(r + length - 0.012), h_total - 0.012])
    path = np.linspace(start, end, 8)
    handle = shapes.tube(path, 0.012, sides=12, squash=0.7)
    parts = ((vessel.mesh(), v.color(0, P.CHARCOAL)), (handle, v.color(1, P.BLACK)))
    return Geometry(parts, (*vessel.collision(16), *col.tube_parts(path, 0.012, 1)), vessel.cavity())


@dataclass(frozen=True)
class VaseShape:
    """The profile, and the number of collision bands up the wall."""

    shape: Literal["bulb", "flared", "cylinder", "amphora"] = "bulb"
    bands: int = 5


@builder(VaseShape)
def vase(v: Variant, p: VaseShape) -> Geometry:
    d, _, h = v.size
    r = d / 2
    shape = p.shape
    u = np.linspace(0, 1, 18)
    if shape == "bulb":
        rr = np.where(
            u >= 0.75,
            r * (0.42 + 1.6 * np.clip(u - 0.75, 0.0, None) ** 1.3),
            r * (0.62 + 0.38 * np.sin(np.pi * u / 0.75)),
        )
    elif shape == "flared":
        rr = r * (0.45 + 0.55 * u**2.2)
    elif shape == "cylinder":
        rr = r * np.ones_like(u)
    else:  # amphora: wide shoulder, narrowing neck
        rr = r * (0.55 + 0.45 * np.sin(np.pi * np.clip(u * 1.25, 0, 1)) ** 0.7)
        rr = np.maximum(rr, 0.5 * r)
    rr = rr / rr.max() * r
    vessel = Vessel(np.stack([rr, u * h], axis=1), 0.004, 0.008, stations=p.bands)
    return Geometry(((vessel.mesh(), v.color(0, P.SKY)),), tuple(vessel.collision(14)), vessel.cavity())


CATEGORIES: tuple[CategoryDef, ...] = (
    define(
        "plate",
        "plate",
        plate,
        [
            V("dinner_white", "a round white ceramic dinner plate", (0.27, 0.27, 0.025)),
            V("dinner_cream", "a cream stoneware dinner plate", (0.28, 0.28, 0.028), (P.CREAM,)),
            V(
                "side_blue",
                "a small blue side plate",
                (0.2, 0.2, 0.02),
                (P.rgb(70, 110, 180),),
                synonyms=("side plate", "bread plate"),
            ),
            V(
                "dessert_green",
                "a small sage green dessert plate",
                (0.19, 0.19, 0.019),
                (P.rgb(150, 180, 140),),
                synonyms=("dessert plate",),
            ),
            V("charger_black", "a large black charger plate", (0.31, 0.31, 0.024), (P.CHARCOAL,)),
            V("dish_small", "a small white dish for sauces or snacks", (0.15, 0.15, 0.022), synonyms=("small dish",)),
            V(
                "paper_white",
                "a white disposable paper plate",
                (0.23, 0.23, 0.018),
                density=450.0,
                tags=("paper", "disposable"),
            ),
            V(
                "ycb_029",
                "the YCB plate: a red plastic dinner plate",
                (0.258, 0.258, 0.024),
                (P.rgb(190, 40, 40),),
                mass=0.279,
                asset_id="ycb_029_plate",
                tags=("ycb", "plastic"),
            ),
        ],
        density=CERAMIC,
        mass_limits=(0.03, 1.2),
        friction=(0.3, 0.6),
        support_probability=0.9,
        has_front=False,
        synonyms=("dinner plate", "dish", "platter"),
        tags=("tableware", "dining", "crockery", "dishes"),
    ),
    define(
        "saucer",
        "saucer",
        saucer,
        [
            V("white", "a white porcelain saucer", (0.145, 0.145, 0.018)),
            V("blue_rim", "a pale blue saucer for a teacup", (0.15, 0.15, 0.02), (P.rgb(170, 200, 230),)),
            V("floral_pink", "a pink china saucer", (0.14, 0.14, 0.018), (P.rgb(240, 190, 200),)),
            V("espresso", "a tiny espresso saucer", (0.12, 0.12, 0.015), (P.CREAM,)),
            V("large_cream", "a large cream coffee saucer", (0.165, 0.165, 0.021), (P.CREAM,)),
        ],
        density=CERAMIC,
        mass_limits=(0.05, 0.4),
        friction=(0.3, 0.6),
        support_probability=0.8,
        has_front=False,
        synonyms=("cup plate",),
        tags=("tableware", "tea", "coffee", "crockery"),
    ),
    define(
        "bowl",
        "bowl",
        bowl,
        [
            V("cereal_white", "a white ceramic cereal bowl", (0.16, 0.16, 0.07), synonyms=("cereal bowl",)),
            V(
                "rice_blue",
                "a small blue rice bowl",
                (0.12, 0.12, 0.06),
                (P.rgb(60, 90, 170),),
                {"foot": 0.4},
                synonyms=("rice bowl",),
            ),
            V("soup_cream", "a deep cream soup bowl", (0.17, 0.17, 0.075), (P.CREAM,), synonyms=("soup bowl",)),
            V(
                "fruit_wide",
                "a wide shallow wooden fruit bowl",
                (0.28, 0.28, 0.09),
                (P.WOOD,),
                {"wall": 0.008, "curve": 0.6},
                density=700.0,
                synonyms=("fruit bowl", "salad bowl"),
            ),
            V(
                "mixing_steel",
                "a large stainless steel mixing bowl",
                (0.26, 0.26, 0.11),
                (P.STEEL,),
                {"wall": 0.0015, "foot": 0.5},
                density=7800.0,
                synonyms=("mixing bowl",),
            ),
            V("glass_small", "a small clear glass dessert bowl", (0.11, 0.11, 0.055), (P.GLASS,), density=2500.0),
            V("ramen_red", "a big red ramen bowl", (0.21, 0.21, 0.09), (P.rgb(170, 30, 30),), {"foot": 0.38}),
            V(
                "ycb_024",
                "the YCB bowl: a red plastic bowl",
                (0.159, 0.159, 0.053),
                (P.rgb(200, 45, 45),),
                {"curve": 0.7},
                mass=0.147,
                asset_id="ycb_024_bowl",
                tags=("ycb", "plastic"),
            ),
        ],
        density=CERAMIC,
        mass_limits=(0.05, 1.5),
        friction=(0.3, 0.7),
        support_probability=0.3,
        has_front=False,
        synonyms=("dish",),
        tags=("tableware", "container", "dishes", "crockery"),
    ),
    define(
        "cup",
        "cup",
        cup,
        [
            V(
                "paper_white",
                "a white disposable paper coffee cup",
                (0.08, 0.08, 0.095),
                options={"bottom": 0.68, "wall": 0.0015},
                density=600.0,
                synonyms=("paper cup",),
                tags=("paper", "disposable"),
            ),
            V(
                "paper_red",
                "a red paper party cup",
                (0.09, 0.09, 0.11),
                (P.RED,),
                {"bottom": 0.66, "wall": 0.0015},
                density=600.0,
                synonyms=("paper cup", "plastic cup", "party cup"),
            ),
            V(
                "teacup_white",
                "a white porcelain teacup with a handle",
                (0.09, 0.12, 0.065),
                options={"handle": True, "bottom": 0.5, "curve": 0.7, "wall": 0.003},
                synonyms=("teacup", "tea cup"),
            ),
            V(
                "teacup_floral",
                "a pink china teacup with a handle",
                (0.095, 0.125, 0.068),
                (P.rgb(240, 195, 205),),
                {"handle": True, "bottom": 0.5, "curve": 0.7, "wall": 0.003},
                synonyms=("teacup", "tea cup"),
            ),
            V(
                "espresso",
                "a small white espresso cup with a handle",
                (0.065, 0.09, 0.06),
                options={"handle": True, "bottom": 0.75, "wall": 0.004},
                synonyms=("espresso cup", "coffee cup"),
            ),
            V(
                "coffee_blue",
                "a blue ceramic coffee cup with a handle",
                (0.085, 0.115, 0.08),
                (P.rgb(60, 100, 170),),
                {"handle": True, "bottom": 0.8, "wall": 0.004},
                synonyms=("coffee cup",),
            ),
            V(
                "plastic_green",
                "a green plastic tumbler cup for kids",
                (0.075, 0.075, 0.1),
                (P.GREEN,),
                {"bottom": 0.8, "wall": 0.002},
                density=1000.0,
                synonyms=("plastic cup", "tumbler"),
            ),
            V(
                "toothbrush_cup",
                "a white bathroom cup for toothbrushes",
                (0.075, 0.075, 0.1),
                options={"bottom": 0.9, "wall": 0.003},
                synonyms=("bathroom cup", "rinse cup"),
                tags=("bathroom",),
            ),
        ],
        density=CERAMIC,
        mass_limits=(0.005, 0.5),
        friction=(0.3, 0.7),
        support_probability=0.2,
        has_front=True,
        synonyms=("drinking cup",),
        tags=("drink", "tableware", "coffee", "tea", "container"),
    ),
    define(
        "mug",
        "mug",
        mug,
        [
            V(
                "white",
                "a classic white ceramic coffee mug",
                (0.082, 0.117, 0.095),
                synonyms=("coffee mug",),
                tags=("white", "ceramic"),
            ),
            V("red", "a red ceramic mug", (0.085, 0.12, 0.1), (P.RED,)),
            V("blue_tall", "a tall blue latte mug", (0.08, 0.115, 0.115), (P.rgb(50, 90, 170),)),
            V("black_wide", "a wide black cappuccino mug", (0.095, 0.13, 0.085), (P.CHARCOAL,)),
            V("yellow_small", "a small yellow espresso mug", (0.065, 0.095, 0.07), (P.YELLOW,)),
            V(
                "enamel_camping",
                "a white enamel camping mug with a navy handle",
                (0.09, 0.125, 0.08),
                (P.WHITE, P.NAVY),
                {"wall": 0.0015},
                density=7800.0,
                synonyms=("camping mug", "tin mug"),
            ),
            V(
                "travel_steel",
                "a stainless steel travel mug with a handle",
                (0.085, 0.12, 0.15),
                (P.STEEL, P.BLACK),
                {"wall": 0.004},
                density=1400.0,
                synonyms=("travel mug",),
            ),
            V(
                "ycb_025",
                "the YCB mug: a red plastic mug",
                (0.08, 0.116, 0.082),
                (P.rgb(200, 40, 40),),
                {"wall": 0.003},
                mass=0.118,
                asset_id="ycb_025_mug",
                tags=("ycb", "plastic"),
            ),
        ],
        density=CERAMIC,
        mass_limits=(0.08, 0.7),
        friction=(0.4, 0.7),
        support_probability=0.15,
        has_front=True,
        synonyms=("coffee mug", "tea mug"),
        tags=("drink", "coffee", "tea", "handle", "container"),
    ),
    define(
        "glass",
        "drinking glass",
        glass,
        [
            V("tumbler", "a clear glass water tumbler", (0.075, 0.075, 0.1), synonyms=("tumbler", "water glass")),
            V(
                "highball",
                "a tall clear highball glass",
                (0.065, 0.065, 0.15),
                options={"bottom": 0.95},
                synonyms=("highball", "tall glass"),
            ),
            V(
                "juice_small",
                "a small juice glass",
                (0.065, 0.065, 0.085),
                options={"bottom": 0.9},
                synonyms=("juice glass",),
            ),
            V(
                "rocks",
                "a short heavy whisky rocks glass",
                (0.085, 0.085, 0.085),
                options={"bottom": 0.95, "floor": 0.018},
                synonyms=("rocks glass", "whisky glass", "old fashioned glass"),
            ),
            V(
                "pint",
                "a pint beer glass",
                (0.088, 0.088, 0.15),
                options={"bottom": 0.7},
                synonyms=("pint glass", "beer glass"),
            ),
            V("tinted_blue", "a blue tinted drinking glass", (0.075, 0.075, 0.11), (P.rgb(90, 140, 210, 0.5),)),
        ],
        density=2500.0,
        mass_limits=(0.1, 0.6),
        friction=(0.3, 0.6),
        support_probability=0.15,
        has_front=False,
        prefix="glass",
        synonyms=("glass", "drinking glass", "cup"),
        tags=("drink", "water", "juice", "clear", "container"),
    ),
    define(
        "wine glass",
        "wine glass",
        wine_glass,
        [
            V("red_wine", "a large red wine glass with a long stem", (0.09, 0.09, 0.22), options={"bowl": 0.5}),
            V("white_wine", "a slender white wine glass", (0.075, 0.075, 0.2), options={"bowl": 0.47}),
            V(
                "champagne_flute",
                "a tall champagne flute",
                (0.06, 0.06, 0.23),
                options={"bowl": 0.55, "closing": 0.52, "foot": 1.0},
                synonyms=("champagne flute", "flute"),
            ),
            V(
                "goblet",
                "a short wide water goblet on a stem",
                (0.09, 0.09, 0.17),
                options={"bowl": 0.55},
                synonyms=("goblet",),
            ),
            V(
                "burgundy",
                "a wide balloon burgundy glass",
                (0.105, 0.105, 0.21),
                options={"bowl": 0.5, "closing": 0.62, "foot": 0.75},
            ),
        ],
        density=2500.0,
        mass_limits=(0.08, 0.35),
        friction=(0.3, 0.6),
        support_probability=0.0,
        has_front=False,
        synonyms=("stemware", "wineglass"),
        tags=("drink", "wine", "stem", "dinner", "container"),
    ),
    define(
        "pitcher",
        "pitcher",
        pitcher,
        [
            V(
                "water_glass",
                "a clear glass water pitcher",
                (0.16, 0.115, 0.22),
                (P.GLASS,),
                density=2500.0,
                synonyms=("water jug",),
            ),
            V("milk_white", "a small white ceramic milk jug", (0.13, 0.09, 0.12), synonyms=("milk jug", "creamer")),
            V("plastic_blue", "a blue plastic jug", (0.17, 0.12, 0.23), (P.rgb(60, 110, 200),), density=950.0),
            V("ceramic_green", "a green ceramic pitcher for flowers", (0.18, 0.13, 0.21), (P.rgb(80, 140, 100),)),
            V("steel_milk", "a stainless steel milk frothing pitcher", (0.12, 0.085, 0.11), (P.STEEL,), density=7800.0),
            V(
                "ycb_019",
                "the YCB pitcher base: a blue plastic pitcher",
                (0.155, 0.108, 0.235),
                (P.rgb(40, 90, 190),),
                mass=0.178,
                asset_id="ycb_019_pitcher_base",
                tags=("ycb", "plastic"),
            ),
        ],
        density=CERAMIC,
        mass_limits=(0.1, 1.6),
        friction=(0.3, 0.7),
        support_probability=0.05,
        has_front=True,
        synonyms=("jug", "carafe"),
        tags=("drink", "water", "milk", "container", "handle", "spout"),
    ),
    define(
        "teapot",
        "teapot",
        teapot,
        [
            V("white", "a round white porcelain teapot", (0.24, 0.15, 0.15)),
            V("brown_betty", "a brown glazed teapot", (0.25, 0.16, 0.16), (P.BROWN,)),
            V("blue", "a blue ceramic teapot for four", (0.27, 0.17, 0.17), (P.rgb(60, 100, 170),)),
            V("small_green", "a small green Japanese teapot", (0.19, 0.11, 0.11), (P.rgb(90, 130, 90),)),
            V("red", "a red enamel teapot", (0.26, 0.16, 0.17), (P.rgb(190, 40, 40),)),
        ],
        density=600.0,
        mass_limits=(0.25, 1.6),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=True,
        synonyms=("tea pot", "kettle"),
        tags=("tea", "spout", "handle", "lid"),
    ),
    define(
        "pot",
        "cooking pot",
        cooking_pot,
        [
            V("stock_steel", "a stainless steel stock pot", (0.24, 0.32, 0.2)),
            V("saucepan_small", "a small steel pot with two handles", (0.16, 0.22, 0.1)),
            V(
                "red_dutch",
                "a red enamel cast iron dutch oven without its lid",
                (0.26, 0.33, 0.12),
                (P.rgb(180, 35, 30), P.rgb(180, 35, 30)),
                {"wall": 0.004, "floor": 0.006},
                density=7200.0,
                synonyms=("dutch oven", "casserole"),
            ),
            V("black_pot", "a black nonstick cooking pot", (0.2, 0.27, 0.12), (P.CHARCOAL,)),
            V("copper", "a copper pot", (0.18, 0.25, 0.12), (P.rgb(190, 110, 60), P.BRASS)),
        ],
        density=7800.0,
        mass_limits=(0.4, 6.0),
        friction=(0.4, 0.7),
        support_probability=0.2,
        has_front=False,
        prefix="pot",
        synonyms=("stockpot", "saucepan", "casserole"),
        tags=("kitchen", "cooking", "cookware", "container"),
    ),
    define(
        "pan",
        "frying pan",
        frying_pan,
        [
            V("nonstick", "a black nonstick frying pan", (0.26, 0.46, 0.07)),
            V(
                "cast_iron",
                "a heavy cast iron skillet",
                (0.27, 0.42, 0.06),
                (P.CHARCOAL, P.CHARCOAL),
                {"depth": 0.05},
                density=7200.0,
                synonyms=("skillet",),
            ),
            V("small_egg", "a small egg frying pan", (0.18, 0.33, 0.055), options={"depth": 0.04}),
            V("steel_saute", "a stainless steel saute pan", (0.28, 0.5, 0.08), (P.STEEL, P.STEEL), {"depth": 0.06}),
            V("red_ceramic", "a red ceramic coated frying pan", (0.24, 0.43, 0.065), (P.rgb(190, 50, 40), P.BLACK)),
        ],
        density=3000.0,
        mass_limits=(0.3, 4.0),
        friction=(0.4, 0.7),
        support_probability=0.2,
        has_front=True,
        prefix="pan",
        synonyms=("skillet", "frypan"),
        tags=("kitchen", "cooking", "cookware", "handle"),
    ),
    define(
        "vase",
        "vase",
        vase,
        [
            V("bulb_blue", "a round blue ceramic vase with a narrow neck", (0.14, 0.14, 0.22), (P.rgb(70, 110, 180),)),
            V(
                "tall_white",
                "a tall white cylinder vase",
                (0.1, 0.1, 0.3),
                (P.WHITE,),
                {"shape": "cylinder", "bands": 4},
            ),
            V(
                "flared_glass",
                "a flared clear glass flower vase",
                (0.14, 0.14, 0.25),
                (P.GLASS,),
                {"shape": "flared"},
                density=2500.0,
            ),
            V(
                "amphora_terracotta",
                "a terracotta amphora vase",
                (0.16, 0.16, 0.28),
                (P.TERRACOTTA,),
                {"shape": "amphora"},
            ),
            V("small_green", "a small green bud vase", (0.08, 0.08, 0.14), (P.rgb(80, 150, 110),)),
        ],
        density=CERAMIC,
        mass_limits=(0.2, 3.0),
        friction=(0.4, 0.7),
        support_probability=0.0,
        has_front=False,
        synonyms=("flower vase",),
        tags=("decor", "flowers", "container"),
    ),
)
