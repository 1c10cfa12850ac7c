"""Food and plants: fruit, bread, sandwiches, potted plants."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
import trimesh
from shapely.geometry import Polygon, box

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.gen.common import fit_to_size
from physcensis.assets.gen.variant_data import builtin_categories
from physcensis.assets.model import RGBA
from physcensis.assets.spec import CategoryDef, Geometry, NoOptions, Variant, builder


def _round_fruit(v: Variant, profile: str) -> Geometry:
    """Apples, oranges, lemons, pears: a revolved body plus a stem (and a leaf for apples)."""
    t = np.linspace(0, np.pi, 25)
    zz = 0.5 - 0.5 * np.cos(t)
    if profile == "apple":
        r = np.sin(t) * (0.5 + 0.06 * np.cos(t))
        prof = np.stack([r, zz], axis=1)
        prof[0] = (0, 0.06)  # dimples at the bottom and around the stem
        prof[-1] = (0, 0.9)
    elif profile == "pear":
        r = np.sin(t) ** 0.9 * (0.5 - 0.3 * np.clip(zz - 0.35, 0, None) / 0.65)
        prof = np.stack([r, zz], axis=1)
    else:
        prof = np.stack([0.5 * np.sin(t), zz], axis=1)
    prof[0, 0] = prof[-1, 0] = 0.0
    body = shapes.lathe(prof, 32)
    if profile == "lemon":
        body.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, (0, 1, 0)))
        tips = [shapes.cone(0.12, 0.03, 0.12, (sx * 0.53, 0, 0.0), axis="x", sections=16) for sx in (-1, 1)]
        tips[0].apply_transform(trimesh.transformations.rotation_matrix(np.pi, (0, 0, 1)))
        body = trimesh.boolean.union([body, *tips], engine="manifold")
    lo, hi = body.bounds
    body.apply_scale(np.asarray(v.size) / (hi - lo) * (np.array([0.9, 1.0, 1.0]) if profile == "lemon" else 1.0))
    body.apply_translation(-body.bounds[0] * [0, 0, 1])
    parts = [(body, v.color(0, P.RED))]
    if profile in ("apple", "pear", "orange"):
        top = body.bounds[1][2]
        stem_h = 0.012 if profile != "orange" else 0.003
        stem = shapes.cylinder(
            0.0018 if profile != "orange" else 0.004,
            stem_h + 0.01,
            (0, 0, top + stem_h / 2 - 0.005 - (0.01 if profile == "apple" else 0.0)),
        )
        parts.append((stem, v.color(1, P.DARK_BROWN if profile != "orange" else P.DARK_GREEN)))
    geometry = Geometry(tuple(parts), (col.hull_part(np.vstack([m.vertices for m, _ in parts])),))
    return fit_to_size(geometry, v.size)


@builder(NoOptions)
def apple(v: Variant, _: NoOptions) -> Geometry:
    return _round_fruit(v, "apple")


@builder(NoOptions)
def orange(v: Variant, _: NoOptions) -> Geometry:
    return _round_fruit(v, "orange")


@builder(NoOptions)
def lemon(v: Variant, _: NoOptions) -> Geometry:
    return _round_fruit(v, "lemon")


@builder(NoOptions)
def pear(v: Variant, _: NoOptions) -> Geometry:
    return _round_fruit(v, "pear")


@dataclass(frozen=True)
class BananaShape:
    """The angle the banana's arc sweeps (radians)."""

    curve: float = 1.1


@builder(BananaShape)
def banana(v: Variant, p: BananaShape) -> Geometry:
    """A curved banana lying on its side (the curve in the xy plane)."""
    x, _, z = v.size
    r = z / 2
    n = 24
    sweep = p.curve
    radius_arc = x / (2 * np.sin(sweep / 2))
    a = np.linspace(-sweep / 2, sweep / 2, n)
    path = np.stack([radius_arc * np.sin(a), radius_arc * np.cos(a), np.full(n, r)], axis=1)
    s = np.linspace(0, 1, n)
    radii = r * np.clip(np.sin(np.pi * s) ** 0.25, 0.2, 1.0)
    body = shapes.tube(path, radii, sides=10, squash=1.0)
    stem_dir = path[-1] - path[-3]
    stem_dir /= np.linalg.norm(stem_dir)
    stem = shapes.tube(np.stack([path[-2], path[-1] + 0.012 * stem_dir]), 0.0035, sides=8)
    tip = shapes.sphere(0.2 * r + 0.001, path[0], 1)
    parts = ((body, v.color(0, P.YELLOW)), (stem, P.rgb(110, 90, 40)), (tip, P.DARK_BROWN))
    collision = tuple(col.tube_parts(path, radii, 6, sides=8))
    return fit_to_size(Geometry(parts, collision), v.size)


@dataclass(frozen=True)
class GrapesShape:
    """One berry's radius (m)."""

    berry: float = 0.0095


@builder(GrapesShape)
def grapes(v: Variant, p: GrapesShape) -> Geometry:
    """A bunch of grapes lying down: berries packed in a tapering cone along x, a woody stem at +x."""
    x, y, z = v.size
    berry = p.berry
    rng = np.random.default_rng(7)  # fixed seed: deterministic bunches
    centres = []
    length = x - 0.02
    for k in range(int(length / (1.3 * berry))):
        u = k / max(1, int(length / (1.3 * berry)) - 1)
        cx = -length / 2 + u * length
        width = (0.25 + 0.75 * u) * (y / 2 - berry)
        count = max(1, int(2 + 4 * u))
        for j in range(count):
            ang = 2 * np.pi * j / count + rng.uniform(0, 0.5)
            centres.append((cx, width * np.cos(ang), berry + (z / 2 - berry) * (0.5 + 0.5 * np.sin(ang))))
    berries = [shapes.sphere(berry * rng.uniform(0.92, 1.0), c, 1) for c in centres]
    stem = shapes.tube(np.array([[length / 2 - 0.01, 0, z / 2], [x / 2, 0, z / 2 + 0.004]]), 0.0025, sides=8)
    parts = ((shapes.concatenate(berries), v.color(0, P.rgb(90, 40, 110))), (stem, P.rgb(110, 90, 50)))
    return fit_to_size(Geometry(parts, (col.hull_part(np.vstack([m.vertices for m, _ in parts])),)), v.size)


@dataclass(frozen=True)
class BreadShape:
    """A loaf, a toast slice, a baguette or a roll."""

    style: Literal["loaf", "slice", "baguette", "roll"] = "loaf"


@builder(BreadShape)
def bread(v: Variant, p: BreadShape) -> Geometry:
    crust = v.color(0, P.rgb(190, 125, 60))
    draw = {"slice": _toast_slice, "baguette": _baguette, "roll": _bread_roll, "loaf": _loaf}[p.style]
    return fit_to_size(draw(v, crust), v.size)


def _toast_slice(v: Variant, crust: RGBA) -> Geometry:
    """A toast slice lying flat: square with a domed top edge (at -x)."""
    x, y, z = v.size
    pts = [(x / 2, -y / 2), (x / 2, y / 2), (-x / 2 + 0.25 * x, y / 2)]
    pts += [(-x / 2 + 0.25 * x - 0.25 * x * np.sin(a), (y / 2) * np.cos(a)) for a in np.linspace(0, np.pi, 12)[1:-1]]
    pts += [(-x / 2 + 0.25 * x, -y / 2)]
    mesh = shapes.extrude(Polygon(pts).buffer(0.003).buffer(-0.003), z)
    crumb = shapes.extrude(Polygon(pts).buffer(-0.006), 0.0006, z - 0.0003)
    return Geometry(((mesh, crust), (crumb, v.color(1, P.rgb(235, 205, 150)))), (col.hull_part(mesh),))


def _baguette(v: Variant, crust: RGBA) -> Geometry:
    x, y, z = v.size
    path = np.stack([np.linspace(-x / 2 + z / 2, x / 2 - z / 2, 10), np.zeros(10), np.full(10, z / 2)], axis=1)
    mesh = shapes.tube(
        path, np.clip(np.sin(np.linspace(0.15, np.pi - 0.15, 10)) ** 0.25, 0.5, 1) * z / 2, sides=16, squash=y / z
    )
    scores = [shapes.box((0.04, 0.006, 0.003), (cx, 0, z - 0.0015)) for cx in np.linspace(-x / 3, x / 3, 4)]
    parts = ((mesh, crust), (shapes.concatenate(scores), v.color(1, P.rgb(225, 190, 120))))
    return Geometry(parts, (col.hull_part(mesh),))


def _bread_roll(v: Variant, crust: RGBA) -> Geometry:
    x, y, z = v.size
    pts = shapes.ellipsoid((x / 2, y / 2, z), (0, 0, 0), 3).vertices.copy()
    pts[:, 2] = np.maximum(pts[:, 2], 0.0)
    mesh = shapes.hull(pts)
    return Geometry(((mesh, crust),), (col.hull_part(mesh),))


def _loaf(v: Variant, crust: RGBA) -> Geometry:
    x, y, z = v.size
    body_h = 0.6 * z
    base = shapes.rounded_box((x, y, body_h), 0.012, (0, 0, body_h / 2))
    dome = shapes.ellipsoid((x / 2 - 0.004, y / 2 - 0.002, z - body_h + 0.01), (0, 0, body_h - 0.01), 3)
    loaf = shapes.hull(np.vstack([base.vertices, dome.vertices[dome.vertices[:, 2] >= body_h - 0.01]]))
    return Geometry(((loaf, crust),), (col.hull_part(loaf),))


@dataclass(frozen=True)
class SandwichShape:
    """Cut into a triangle instead of square."""

    triangle: bool = False


@builder(SandwichShape)
def sandwich(v: Variant, p: SandwichShape) -> Geometry:
    """Two slices of bread with fillings; square or cut into a triangle."""
    x, y, z = v.size
    tri = p.triangle
    shape = Polygon([(-x / 2, -y / 2), (x / 2, -y / 2), (-x / 2, y / 2)]) if tri else box(-x / 2, -y / 2, x / 2, y / 2)
    shape = shape.buffer(-0.004).buffer(0.004)
    slice_t = 0.28 * z
    fill = z - 2 * slice_t
    layers = [(0.0, slice_t, shape, P.rgb(230, 195, 140))]
    colors = v.colors or (P.rgb(110, 180, 60), P.rgb(230, 150, 160))
    step = fill / len(colors)
    for k, c in enumerate(colors):
        grown = shape.buffer(0.003 if k % 2 == 0 else 0.001)
        layers.append((slice_t + k * step, step, grown, c))
    layers.append((z - slice_t, slice_t, shape, P.rgb(230, 195, 140)))
    parts = tuple((shapes.extrude(poly, h, z0), c) for z0, h, poly, c in layers)
    return fit_to_size(Geometry(parts, (col.hull_part(np.vstack([m.vertices for m, _ in parts])),)), v.size)


@dataclass(frozen=True)
class PottedPlantShape:
    """The pot's diameter (fraction of the footprint) and height (fraction of the whole); the foliage."""

    pot: float = 0.6
    pot_h: float = 0.35
    style: Literal["bush", "succulent", "cactus", "leaves"] = "bush"


@builder(PottedPlantShape)
def potted_plant(v: Variant, p: PottedPlantShape) -> Geometry:
    """A pot with soil and foliage (bush, succulent, cactus, snake plant or tall leafy plant)."""
    x, y, z = v.size
    pot_d = p.pot * min(x, y)
    pot_h = p.pot_h * z
    r = pot_d / 2
    pot = shapes.lathe(
        [
            (0, 0),
            (0.78 * r, 0),
            (0.92 * r, 0.85 * pot_h),
            (r, 0.86 * pot_h),
            (r, pot_h),
            (0.9 * r, pot_h),
            (0.9 * r, pot_h - 0.01),
            (0, pot_h - 0.01),
        ]
    )
    soil = shapes.cylinder(0.88 * r, 0.006, (0, 0, pot_h - 0.012))
    style = p.style
    leaf = v.color(1, P.LEAF)
    rng = np.random.default_rng(3)
    top = z - pot_h
    pieces: list[trimesh.Trimesh] = []
    if style == "bush":
        for k in range(9):
            ang = 2 * np.pi * k / 9
            rad = 0.25 * x if k else 0.0
            c = (
                rad * np.cos(ang),
                rad * np.sin(ang),
                pot_h + 0.45 * top + (0.15 * top if k == 0 else rng.uniform(-0.1, 0.05) * top),
            )
            pieces.append(shapes.ellipsoid((0.22 * x, 0.22 * y, 0.3 * top), c, 2))
    elif style == "succulent":
        for k in range(10):
            ang = 2 * np.pi * k / 10
            tilt = 0.7 if k % 2 else 0.35
            length = 0.45 * min(x, y)
            tip = np.array(
                [
                    length * np.cos(ang) * np.sin(tilt),
                    length * np.sin(ang) * np.sin(tilt),
                    pot_h + 0.2 * top + 0.8 * top * np.cos(tilt),
                ]
            )
            pieces.append(shapes.tube(np.stack([(0, 0, pot_h - 0.005), tip]), np.array([0.012, 0.003]), sides=8))
    elif style == "cactus":
        cr = 0.15 * min(x, y)
        pieces.append(shapes.tube(np.array([[0, 0, pot_h - 0.01], [0, 0, z - cr]]), cr, sides=12))
        pieces.append(shapes.sphere(cr, (0, 0, z - cr), 2))
        for side in (1, -1):
            arm = np.array(
                [
                    [0, 0, pot_h + 0.4 * top],
                    [side * 0.3 * x, 0, pot_h + 0.45 * top],
                    [side * 0.3 * x, 0, pot_h + 0.75 * top],
                ]
            )
            pieces.append(shapes.tube(shapes.resample_polyline(arm, 8), 0.6 * cr, sides=10))
    else:  # snake plant / tall leaves: upright blades
        count = 7
        for k in range(count):
            ang = 2 * np.pi * k / count
            lean = 0.12 * x
            base = np.array([0.4 * r * np.cos(ang), 0.4 * r * np.sin(ang), pot_h - 0.005])
            tip = np.array([lean * np.cos(ang), lean * np.sin(ang), pot_h + top * rng.uniform(0.75, 1.0)])
            blade = shapes.tube(np.linspace(base, tip, 6), np.linspace(0.018, 0.004, 6), sides=8, squash=0.25)
            pieces.append(blade)
    foliage = shapes.concatenate(pieces)
    parts = ((pot, v.color(0, P.TERRACOTTA)), (soil, P.SOIL), (foliage, leaf))
    collision = (col.hull_part(pot), col.hull_part(foliage))
    return fit_to_size(Geometry(parts, collision), v.size)


CATEGORIES: tuple[CategoryDef, ...] = builtin_categories(__name__, globals())  # variants: data/organic.json
