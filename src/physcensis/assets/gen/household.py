"""Flat household objects: trays, cutting boards, napkins, towels (one convex collision each)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.gen.variant_data import builtin_categories
from physcensis.assets.spec import CategoryDef, Geometry, Variant, builder


@dataclass(frozen=True)
class TrayShape:
    """Rim width and corner radius (m); round instead of rectangular."""

    rim: float = 0.008
    radius: float = 0.03
    round: bool = False


@builder(TrayShape)
def tray(v: Variant, p: TrayShape) -> Geometry:
    """A serving tray with a low rim; one convex hull (flat objects stack rim on rim)."""
    x, y, z = v.size
    rim = p.rim
    radius = p.radius
    if p.round:
        r = x / 2
        mesh = shapes.lathe([(0, 0), (r - 0.01, 0), (r, z), (r - rim, z), (r - rim - 0.005, 0.006), (0, 0.006)])
    else:
        outer = shapes.slab(x, y, z, radius, (0, 0, z / 2))
        inner = shapes.slab(x - 2 * rim, y - 2 * rim, z, max(0.001, radius - rim), (0, 0, 0.006 + z / 2))
        mesh = trimesh.boolean.difference([outer, inner], engine="manifold")
    return Geometry(((mesh, v.color(0, P.WOOD)),), (col.hull_part(mesh),))


@dataclass(frozen=True)
class CuttingBoardShape:
    """Round instead of rectangular, the corner radius (m), a juice groove."""

    round: bool = False
    radius: float = 0.015
    groove: bool = False


@builder(CuttingBoardShape)
def cutting_board(v: Variant, p: CuttingBoardShape) -> Geometry:
    x, y, z = v.size
    if p.round:
        mesh = shapes.cylinder(x / 2, z, (0, 0, z / 2), sections=48)
        return Geometry(((mesh, v.color(0, P.WOOD)),), (col.cylinder_part(x / 2, z, (0, 0, z / 2)),))
    board = shapes.slab(x, y, z, p.radius, (0, 0, z / 2))
    parts = [(board, v.color(0, P.WOOD))]
    if p.groove:
        groove = shapes.slab(x - 0.03, y - 0.03, 0.0012, 0.01, (0, 0, z - 0.0003))
        inner = shapes.slab(x - 0.036, y - 0.036, 0.0014, 0.008, (0, 0, z - 0.0003))
        parts.append((trimesh.boolean.difference([groove, inner], engine="manifold"), v.color(1, P.rgb(150, 100, 60))))
    return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


@dataclass(frozen=True)
class NapkinShape:
    """Folded into a triangle instead of a rectangle."""

    triangle: bool = False


@builder(NapkinShape)
def napkin(v: Variant, p: NapkinShape) -> Geometry:
    """A folded cloth or paper napkin lying flat (square, rectangle or triangle)."""
    x, y, z = v.size
    color = v.color(0, P.WHITE)
    if p.triangle:
        pts = np.array(
            [[sx, sy, sz] for sx, sy in ((-x / 2, -y / 2), (x / 2, -y / 2), (-x / 2, y / 2)) for sz in (0.0, z)]
        )
        mesh = shapes.hull(pts)
        return Geometry(((mesh, color),), (col.hull_part(pts),))
    body = shapes.rounded_box((x, y, z), 0.45 * z, (0, 0, z / 2))
    fold = shapes.box((x * 0.96, 0.002, 0.0006), (0, 0, z - 0.0002))
    return Geometry(
        ((body, color), (fold, v.color(1, P.rgb(225, 225, 220)))), (col.box_part((x, y, z), (0, 0, z / 2)),)
    )


@dataclass(frozen=True)
class TowelShape:
    """Rolled instead of folded; the number of folds."""

    rolled: bool = False
    folds: int = 3


@builder(TowelShape)
def towel(v: Variant, p: TowelShape) -> Geometry:
    """A folded towel (stack of rounded folds with a stripe) or a rolled towel lying along y."""
    x, y, z = v.size
    color = v.color(0, P.WHITE)
    stripe = v.color(1, color)
    if p.rolled:
        r = z / 2
        body = shapes.cylinder(r, y, (0, 0, r), axis="y", sections=32)
        band = shapes.cylinder(r + 0.0008, 0.02, (0, 0.3 * y, r), axis="y", sections=32)
        return Geometry(((body, color), (band, stripe)), (col.cylinder_part(r, y, (0, 0, r), (0, 1, 0)),))
    folds = p.folds
    t = z / folds
    parts = [
        (shapes.rounded_box((x, y - 0.004 * k, t + 0.001), 0.45 * t, (0, 0, t * k + t / 2)), color)
        for k in range(folds)
    ]
    band = shapes.rounded_box(
        (0.03, y - 0.004 * (folds - 1) + 0.002, z + 0.0005 - 0.001), 0.45 * t, (0.3 * x, 0, z / 2 + 0.0002)
    )
    parts.append((band, stripe))
    return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


CATEGORIES: tuple[CategoryDef, ...] = builtin_categories(__name__, globals())  # variants: data/household.json
