"""Revolved tableware and cookware: plates, bowls, cups, mugs, glasses, pitchers, teapots, pots, pans, vases."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.gen.common import Vessel, loop_handle, resample, spout
from physcensis.assets.gen.variant_data import builtin_categories
from physcensis.assets.spec import CategoryDef, Geometry, NoOptions, Variant, builder


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


CATEGORIES: tuple[CategoryDef, ...] = builtin_categories(__name__, globals())  # variants: data/tableware.json
