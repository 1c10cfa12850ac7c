"""Supports as assets: a table, a shelf unit, an open box used as root, the floor.

A support asset is built in world coordinates: z = 0 is the floor and the
usable top (the surface objects stand on, `Support.top_height` high) is centred
on x = y = 0.  The front of a shelf (its open side) faces +x.
"""

from __future__ import annotations

from functools import lru_cache
from typing import cast

import numpy as np
import trimesh

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.build import MASS_SPREAD
from physcensis.assets.gen.common import rectangle
from physcensis.assets.model import RGBA, Asset, Cavity, CollisionPart
from physcensis.scene import Support

TABLE_TOP = 0.03
TABLE_LEG = 0.05
SHELF_BOARD = 0.018
SHELF_SPACING = 0.35
BOX_WALL = 0.01
WOOD_DENSITY = 650.0


def _boxes(
    specs: list[tuple[tuple[float, float, float], tuple[float, float, float]]], color: RGBA
) -> tuple[list[tuple[trimesh.Trimesh, RGBA]], list[CollisionPart]]:
    parts = [(shapes.box(ext, c), color) for ext, c in specs]
    return parts, [col.box_part(ext, c) for ext, c in specs]


def _table(s: Support) -> tuple[list, list, Cavity | None]:
    x, y = s.size
    h = s.top_height
    inset = min(0.06, 0.15 * min(x, y))
    leg_h = h - TABLE_TOP
    specs = [((x, y, TABLE_TOP), (0.0, 0.0, h - TABLE_TOP / 2))]
    for sx in (-1, 1):
        for sy in (-1, 1):
            specs.append(((TABLE_LEG, TABLE_LEG, leg_h), (sx * (x / 2 - inset), sy * (y / 2 - inset), leg_h / 2)))
    parts, collision = _boxes(specs, P.LIGHT_WOOD)
    return parts, collision, None


def shelf_board_heights(top: float) -> list[float]:
    """Heights of the tops of the shelf boards: one at `top`, more below every SHELF_SPACING, one above."""
    heights = [top + SHELF_SPACING]
    z = top
    while z >= SHELF_BOARD:
        heights.append(z)
        z -= SHELF_SPACING
    return sorted(heights)


def _shelf(s: Support) -> tuple[list, list, Cavity | None]:
    x, y = s.size
    boards = shelf_board_heights(s.top_height)
    height = boards[-1]
    t = SHELF_BOARD
    specs = [((x, y, t), (0.0, 0.0, z - t / 2)) for z in boards]
    specs += [((x + t, t, height), (-t / 2, sy * (y / 2 + t / 2), height / 2)) for sy in (-1, 1)]
    specs.append(((t, y + 2 * t, height), (-x / 2 - t / 2, 0.0, height / 2)))
    parts, collision = _boxes(specs, P.WOOD)
    return parts, collision, None


def box_wall_height(s: Support) -> float:
    return float(np.clip(0.35 * min(s.size), 0.08, 0.4))


def _open_box(s: Support) -> tuple[list, list, Cavity | None]:
    x, y = s.size
    floor = s.top_height
    wall_h = box_wall_height(s)
    w = BOX_WALL
    ox, oy, oz = x + 2 * w, y + 2 * w, floor + wall_h
    collision = col.open_box_parts(ox, oy, oz, w, floor)
    outer = shapes.box((ox, oy, oz), (0, 0, oz / 2))
    inner = shapes.box((x, y, wall_h + 0.01), (0, 0, floor + (wall_h + 0.01) / 2))
    mesh = trimesh.boolean.difference([outer, inner], engine="manifold")
    return [(mesh, P.CARDBOARD)], collision, Cavity(rectangle(x, y), floor, wall_h)


def _floor(s: Support) -> tuple[list, list, Cavity | None]:
    x, y = s.size
    mesh = shapes.box((x, y, 0.01), (0, 0, -0.005))
    return [(mesh, P.rgb(170, 160, 150))], [CollisionPart("plane", (x / 2, y / 2, 0.05))], None


_BUILDERS = {"table": _table, "shelf": _shelf, "box": _open_box, "floor": _floor}


def support_asset(support: Support) -> Asset:
    """The static support as an Asset (collision parts, visual, cavity for an open box): built once per kind, size
    and height, and shared like every catalogue asset (read it, never change it)."""
    return _support_asset(support.kind, (float(support.size[0]), float(support.size[1])), support.height)


@lru_cache(maxsize=64)
def _support_asset(kind: str, size: tuple[float, float], height: float | None) -> Asset:
    support = Support(kind=kind, size=size, height=height)  # type: ignore[arg-type]
    parts, collision, cavity = _BUILDERS[support.kind](support)
    meshes = [m for m, _ in parts]
    visual = cast(trimesh.Trimesh, trimesh.util.concatenate(meshes))
    volume = float(sum(abs(m.volume) for m in meshes))
    mass = max(WOOD_DENSITY * volume, 1.0)
    ext = visual.extents
    slug = f"{support.size[0]:.2f}x{support.size[1]:.2f}".replace(".", "p")
    return Asset(
        id=f"support_{support.kind}_{slug}",
        category=support.kind,
        kind=support.kind,
        description=f"a {support.kind} support with a {support.size[0]:.2f} by {support.size[1]:.2f} m top",
        size=(float(ext[0]), float(ext[1]), float(ext[2])),
        visual=visual,
        collision=tuple(collision),
        mass=mass,
        mass_range=(mass * (1 - MASS_SPREAD), mass * (1 + MASS_SPREAD)),
        friction_range=(0.5, 0.8),
        support_probability=1.0,
        has_front=support.kind == "shelf",
        cavity=cavity,
        rgba=tuple(c for _, c in parts),
        part_faces=tuple(len(m.faces) for m in meshes),
        source="support",
    )
