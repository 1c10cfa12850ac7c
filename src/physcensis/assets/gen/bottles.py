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
from physcensis.assets.gen.variant_data import builtin_categories
from physcensis.assets.model import Cavity
from physcensis.assets.spec import CategoryDef, Geometry, NoOptions, Parts, Variant, builder


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


CATEGORIES: tuple[CategoryDef, ...] = builtin_categories(__name__, globals())  # variants: data/bottles.json
