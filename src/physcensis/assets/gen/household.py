"""Flat household objects: trays, cutting boards, napkins, towels (one convex collision each)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.spec import CategoryDef, Geometry, Variant, builder, define
from physcensis.assets.spec import Variant as V


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


CATEGORIES: tuple[CategoryDef, ...] = (
    define(
        "tray",
        "tray",
        tray,
        [
            V("wooden_rect", "a rectangular wooden serving tray", (0.45, 0.32, 0.03)),
            V(
                "black_plastic",
                "a black plastic cafeteria tray",
                (0.46, 0.36, 0.02),
                (P.CHARCOAL,),
                {"radius": 0.02},
                density=1100.0,
            ),
            V(
                "round_silver",
                "a round silver serving tray",
                (0.35, 0.35, 0.02),
                (P.SILVER,),
                {"round": True, "rim": 0.012},
                density=2700.0,
            ),
            V(
                "small_white",
                "a small white tea tray",
                (0.35, 0.25, 0.025),
                (P.WHITE,),
                density=1200.0,
                synonyms=("tea tray",),
            ),
            V("bamboo_large", "a large bamboo tray", (0.5, 0.35, 0.035), (P.BAMBOO,), {"rim": 0.01}),
            V("round_wood", "a round wooden tray", (0.4, 0.4, 0.03), (P.LIGHT_WOOD,), {"round": True, "rim": 0.012}),
        ],
        density=650.0,
        mass_limits=(0.2, 2.5),
        friction=(0.4, 0.7),
        support_probability=0.95,
        has_front=False,
        synonyms=("serving tray", "platter"),
        tags=("serving", "tea", "breakfast", "flat"),
    ),
    define(
        "cutting board",
        "cutting board",
        cutting_board,
        [
            V("wood_rect", "a rectangular wooden cutting board", (0.36, 0.24, 0.02)),
            V("bamboo", "a bamboo chopping board", (0.33, 0.23, 0.015), (P.BAMBOO,), synonyms=("chopping board",)),
            V(
                "white_plastic",
                "a white plastic chopping board",
                (0.4, 0.28, 0.01),
                (P.WHITE,),
                {"radius": 0.01},
                density=950.0,
                synonyms=("chopping board",),
            ),
            V(
                "round_wood",
                "a round wooden board for bread",
                (0.3, 0.3, 0.02),
                (P.LIGHT_WOOD,),
                {"round": True},
                synonyms=("bread board", "round board"),
            ),
            V(
                "butcher_block",
                "a thick butcher block board with a juice groove",
                (0.45, 0.3, 0.04),
                (P.WOOD, P.DARK_BROWN),
                {"groove": True},
                synonyms=("butcher block",),
            ),
            V(
                "green_small",
                "a small green plastic cutting board",
                (0.25, 0.16, 0.009),
                (P.rgb(100, 170, 90),),
                {"radius": 0.012},
                density=950.0,
            ),
        ],
        density=700.0,
        mass_limits=(0.1, 4.0),
        friction=(0.4, 0.7),
        support_probability=0.95,
        has_front=False,
        synonyms=("chopping board", "board", "cutting board"),
        tags=("kitchen", "cooking", "flat", "wood"),
    ),
    define(
        "napkin",
        "napkin",
        napkin,
        [
            V("white_folded", "a folded white cloth napkin", (0.2, 0.2, 0.008)),
            V("red_rect", "a folded red napkin", (0.2, 0.1, 0.012), (P.RED,)),
            V(
                "paper_yellow",
                "a folded yellow paper napkin",
                (0.16, 0.16, 0.004),
                (P.rgb(245, 225, 120),),
                density=300.0,
                synonyms=("serviette", "paper napkin"),
            ),
            V(
                "blue_triangle",
                "a blue napkin folded into a triangle",
                (0.2, 0.2, 0.008),
                (P.rgb(80, 120, 190),),
                {"triangle": True},
            ),
            V("linen_grey", "a grey linen napkin folded in a rectangle", (0.22, 0.11, 0.012), (P.rgb(180, 180, 175),)),
        ],
        density=250.0,
        mass_limits=(0.002, 0.12),
        friction=(0.6, 0.9),
        support_probability=0.9,
        has_front=False,
        synonyms=("serviette", "cloth"),
        tags=("cloth", "dining", "table", "picnic", "flat", "fabric"),
    ),
    define(
        "towel",
        "towel",
        towel,
        [
            V("white_folded", "a folded white bath towel", (0.32, 0.25, 0.06)),
            V(
                "blue_stripe",
                "a folded blue hand towel with a white stripe",
                (0.25, 0.16, 0.045),
                (P.rgb(70, 120, 190), P.WHITE),
            ),
            V("grey_stack", "a thick grey towel folded in four", (0.3, 0.2, 0.08), (P.GREY, P.CHARCOAL), {"folds": 4}),
            V(
                "rolled_white",
                "a rolled white towel",
                (0.1, 0.3, 0.1),
                options={"rolled": True},
                synonyms=("rolled towel",),
            ),
            V(
                "kitchen_check",
                "a red kitchen tea towel folded flat",
                (0.22, 0.15, 0.02),
                (P.RED, P.WHITE),
                {"folds": 2},
                synonyms=("tea towel", "dish towel"),
            ),
        ],
        density=150.0,
        mass_limits=(0.03, 1.0),
        friction=(0.6, 0.9),
        support_probability=0.8,
        has_front=False,
        synonyms=("bath towel", "hand towel", "cloth"),
        tags=("bathroom", "fabric", "cotton", "folded", "soft"),
    ),
)
