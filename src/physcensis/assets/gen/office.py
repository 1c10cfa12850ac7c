"""Desk and home objects: books, notebooks, pens, pencils, pencil cases, laptops, monitors, keyboards, mice, phones."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
import trimesh

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.gen.boxes import open_tray
from physcensis.assets.gen.variant_data import builtin_categories
from physcensis.assets.model import RGBA
from physcensis.assets.spec import CategoryDef, Geometry, NoOptions, Parts, Variant, builder


@dataclass(frozen=True)
class BookShape:
    """Standing on its bottom edge instead of lying flat."""

    upright: bool = False


@builder(BookShape)
def book(v: Variant, p: BookShape) -> Geometry:
    """Hard covers, spine and an inset page block; one box collision.

    Lying flat (default): x = book height (text reads from +x), y = width (spine at +y),
    z = thickness.  Upright (`p.upright`): x = width, y = thickness, z = height,
    standing on its bottom edge with the spine facing +x.
    """
    upright = p.upright
    if upright:
        w, t, h = v.size
    else:
        h, w, t = v.size
    board = min(0.003, 0.12 * t)
    inset = min(0.004, 0.2 * t + 0.001)
    cover = v.color(0, P.RED)
    # Built lying flat: x = height, y = width (spine at +y), z = thickness.
    covers = [
        shapes.box((h, w, board), (0, 0, board / 2)),
        shapes.box((h, w, board), (0, 0, t - board / 2)),
        shapes.box((h, board * 1.2, t), (0, w / 2 - board * 0.6, t / 2)),
    ]
    pages = shapes.box(
        (h - 2 * inset, w - inset - board, t - 2 * board + 0.0004), (0, -inset / 2 + board / 2 - 0.0001, t / 2)
    )
    meshes = [*covers, pages]
    if upright:
        # stand on the bottom edge (+x side of the flat book goes down), spine to +x
        rot = trimesh.transformations.rotation_matrix(np.pi / 2, (0, 1, 0)) @ trimesh.transformations.rotation_matrix(
            np.pi / 2, (1, 0, 0)
        )
        for m in meshes:
            m.apply_transform(rot)
    ext = np.ptp(np.vstack([m.vertices for m in meshes]), axis=0)
    centre = np.vstack([m.vertices for m in meshes]).min(axis=0) + ext / 2
    parts = tuple((m, cover) for m in meshes[:3]) + ((pages, v.color(1, P.PAPER)),)
    return Geometry(parts, (col.box_part(ext, centre),))


@dataclass(frozen=True)
class NotebookShape:
    """A spiral binding (else a glued spine)."""

    spiral: bool = True


@builder(NotebookShape)
def notebook(v: Variant, p: NotebookShape) -> Geometry:
    """A lying notebook: covers, pages and (optionally) a spiral binding along +y."""
    x, y, z = v.size
    spiral = p.spiral
    ring_r = z / 2 if spiral else 0.0
    body_w = y - (ring_r if spiral else 0)
    board = 0.0008
    cover = v.color(0, P.BLUE)
    cy = -(y - body_w) / 2
    parts = [
        (shapes.box((x, body_w, board), (0, cy, board / 2)), cover),
        (shapes.box((x, body_w, board), (0, cy, z - board / 2)), cover),
        (shapes.box((x - 0.002, body_w - 0.002, z - 2 * board + 0.0002), (0, cy - 0.001, z / 2)), v.color(1, P.PAPER)),
    ]
    if spiral:
        edge = cy + body_w / 2
        count = int(x / 0.012)
        for k in range(count):
            px = -x / 2 + (k + 0.5) * x / count
            loop = trimesh.creation.torus(
                major_radius=ring_r - 0.0008, minor_radius=0.0008, major_sections=12, minor_sections=6
            )
            loop.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, (0, 1, 0)))
            loop.apply_translation((px, edge, z / 2))
            parts.append((loop, P.SILVER))
    else:
        parts.append((shapes.box((x, 0.012, z), (0, y / 2 - 0.006, z / 2)), v.color(2, P.BLACK)))
    return Geometry(tuple(parts), (col.box_part((x, y, z), (0, 0, z / 2)),))


@dataclass(frozen=True)
class PenShape:
    """The clip's height above the barrel (m)."""

    clip: float = 0.0025


@builder(PenShape)
def pen(v: Variant, p: PenShape) -> Geometry:
    """A pen lying along x, tip to +x, with a clip on the cap end (the clip also stops it rolling)."""
    length, width, height = v.size
    clip_h = p.clip
    r = min(width / 2, (height - clip_h) / 2)
    body_r = 0.92 * r
    body_len = 0.82 * length
    cap_len = 0.3 * length
    x0 = -length / 2
    body = shapes.cylinder(body_r, body_len, (x0 + body_len / 2, 0, r), axis="x", sections=16)
    cone = shapes.cone(
        body_r * 0.95,
        body_r * 0.25,
        length - body_len,
        (x0 + body_len + (length - body_len) / 2, 0, r),
        axis="x",
        sections=16,
    )
    cap = shapes.cylinder(r, cap_len, (x0 + cap_len / 2, 0, r), axis="x", sections=16)
    clip = shapes.box(
        (0.55 * cap_len, min(0.003, width), clip_h + 0.001), (x0 + 0.45 * cap_len, 0, 2 * r + clip_h / 2 - 0.0005)
    )
    body_color = v.color(0, P.BLUE)
    parts = (
        (body, v.color(2, body_color)),
        (cone, v.color(2, body_color)),
        (cap, body_color),
        (clip, v.color(1, P.SILVER)),
    )
    return Geometry(parts, (col.hull_part(np.vstack([m.vertices for m, _ in parts])),))


@dataclass(frozen=True)
class PencilShape:
    """The sharpened tip's length relative to a new pencil's."""

    sharp: float = 1.0


@builder(PencilShape)
def pencil(v: Variant, p: PencilShape) -> Geometry:
    """A hexagonal pencil lying along x: eraser, ferrule, painted body, sharpened wood cone, graphite tip."""
    length, _, d = v.size
    r = d / 2 / np.cos(np.pi / 6)
    tip = 0.07 * length * p.sharp
    eraser = 0.035 * length
    ferrule = 0.04 * length
    body_len = length - tip - eraser - ferrule
    x = -length / 2
    rot = trimesh.transformations.rotation_matrix(np.pi / 6, (1, 0, 0))
    body = trimesh.creation.cylinder(radius=r, height=body_len, sections=6)
    body.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, (0, 1, 0)))
    body.apply_transform(rot)
    body.apply_translation((x + eraser + ferrule + body_len / 2, 0, d / 2))
    round_r = d / 2 * 0.95
    eras = shapes.cylinder(round_r * 0.95, eraser + 0.001, (x + eraser / 2, 0, d / 2), axis="x", sections=16)
    ferr = shapes.cylinder(round_r, ferrule + 0.001, (x + eraser + ferrule / 2, 0, d / 2), axis="x", sections=16)
    wood = shapes.cone(
        round_r,
        0.3 * round_r,
        0.75 * tip + 0.0005,
        (length / 2 - tip + 0.375 * tip - 0.0002, 0, d / 2),
        axis="x",
        sections=16,
    )
    lead = shapes.cone(
        0.3 * round_r, 0.02 * round_r, 0.25 * tip, (length / 2 - 0.125 * tip, 0, d / 2), axis="x", sections=12
    )
    parts = ((body, v.color(0, P.YELLOW)), (eras, P.PINK), (ferr, P.SILVER), (wood, P.LIGHT_WOOD), (lead, P.CHARCOAL))
    return Geometry(parts, (col.hull_part(np.vstack([m.vertices for m, _ in parts])),))


@dataclass(frozen=True)
class PencilCaseShape:
    """A zipped pouch, a tin or a tube, closed; or open (`open_pouch` unzipped, `open_tin` lid off): a tray that
    pens and erasers are dropped into."""

    style: Literal["pouch", "tin", "tube", "open_pouch", "open_tin"] = "pouch"


@builder(PencilCaseShape)
def pencil_case(v: Variant, p: PencilCaseShape) -> Geometry:
    x, y, z = v.size
    style = p.style
    color = v.color(0, P.NAVY)
    if style in ("open_pouch", "open_tin"):
        return _open_pencil_case(v, style == "open_pouch", color)
    parts: Parts
    if style == "tin":
        body = shapes.slab(x, y, z, 0.006, (0, 0, z / 2))
        seam = shapes.slab(x + 0.001, y + 0.001, 0.002, 0.0065, (0, 0, 0.7 * z))
        parts = ((body, color), (seam, v.color(1, P.SILVER)))
    elif style == "tube":
        body = shapes.hull(
            np.vstack([shapes.sphere(z / 2, (sx * (x / 2 - z / 2), 0, z / 2), 2).vertices for sx in (-1, 1)])
        )
        zip_line = shapes.box((x - z, 0.004, 0.003), (0, 0, z - 0.001))
        parts = ((body, color), (zip_line, v.color(1, P.SILVER)))
    else:
        body = shapes.rounded_box((x, y, z), 0.45 * z, (0, 0, z / 2))
        zip_line = shapes.box((x - 0.02, 0.005, 0.003), (0, 0, z - 0.0012))
        pull = shapes.box((0.012, 0.008, 0.003), (x / 2 - 0.02, 0.004, z - 0.0002))
        parts = ((body, color), (zip_line, v.color(1, P.SILVER)), (pull, v.color(1, P.SILVER)))
    return Geometry(parts, (col.hull_part(np.vstack([m.vertices for m, _ in parts])),))


def _open_pencil_case(v: Variant, pouch: bool, color: RGBA) -> Geometry:
    """An open pencil case: fabric walls with a zip along the rim (pouch) or a thin metal tray (tin)."""
    x, y, z = v.size
    wall = 0.004 if pouch else 0.0015
    tray = open_tray(v.size, wall, 0.003 if pouch else 0.0015, color, radius=0.012 if pouch else 0.005)
    trim = v.color(1, P.SILVER)
    if pouch:  # the open zip's two rails along the long sides
        rails = [shapes.box((x - 0.03, 0.003, 0.003), (0, s * (y / 2 - wall / 2), z - 0.0015)) for s in (1, -1)]
    else:  # the rolled rim
        rails = [shapes.box((x - 0.01, 0.002, 0.002), (0, s * (y / 2 - 0.001), z - 0.001)) for s in (1, -1)]
    return Geometry((*tray.parts, (shapes.concatenate(rails), trim)), tray.collision, tray.cavity)


@dataclass(frozen=True)
class LaptopShape:
    """Open (screen up), the base's thickness (m) and the screen's angle from the base (degrees)."""

    open: bool = False
    base: float = 0.016
    angle: float = 105.0


@builder(LaptopShape)
def laptop(v: Variant, p: LaptopShape) -> Geometry:
    """A laptop, front edge at +x: closed (thin slab with a hinge line) or open (screen raised at the back)."""
    return _open_laptop(v, p) if p.open else _closed_laptop(v)


def _closed_laptop(v: Variant) -> Geometry:
    x, y, z = v.size
    body = v.color(0, P.SILVER)
    half = z / 2
    base = shapes.slab(x, y, half, 0.01, (0, 0, half / 2))
    lid = shapes.slab(x, y, half - 0.0006, 0.01, (0, 0, half + (half - 0.0006) / 2 + 0.0006))
    hinge = shapes.cylinder(0.3 * z, 0.8 * y, (-x / 2 + 0.3 * z, 0, half), axis="y")
    logo = shapes.slab(0.03, 0.025, 0.0004, 0.004, (0, 0, z - 0.0001))
    parts = ((base, body), (lid, body), (hinge, v.color(1, P.CHARCOAL)), (logo, P.WHITE))
    return Geometry(parts, (col.box_part((x, y, z), (0, 0, z / 2)),))


def _open_laptop(v: Variant, p: LaptopShape) -> Geometry:
    x, y, z = v.size
    body = v.color(0, P.SILVER)
    dark = v.color(1, P.CHARCOAL)
    base_t = p.base
    tilt = np.radians(p.angle - 90.0)  # how far the screen leans back from vertical
    screen_t = 0.007
    d = np.array([-np.sin(tilt), 0.0, np.cos(tilt)])  # up the screen
    n = np.array([np.cos(tilt), 0.0, np.sin(tilt)])  # out of the display, towards the user
    length = (z - base_t - screen_t * np.sin(tilt)) / np.cos(tilt)
    depth = x - length * np.sin(tilt) - screen_t * np.cos(tilt)
    hinge = np.array([x / 2 - depth, 0.0, base_t])
    base = shapes.slab(depth, y, base_t, 0.008, (x / 2 - depth / 2, 0, base_t / 2))
    keys = shapes.box((0.45 * depth, 0.8 * y, 0.0015), (x / 2 - 0.6 * depth, 0, base_t))
    pad = shapes.box((0.2 * depth, 0.3 * y, 0.001), (x / 2 - 0.2 * depth, 0, base_t))

    def plate(a0: float, a1: float, b0: float, b1: float, half_y: float) -> trimesh.Trimesh:
        pts = [
            hinge + a * d + b * n + np.array([0.0, c, 0.0])
            for a in (a0, a1)
            for b in (b0, b1)
            for c in (-half_y, half_y)
        ]
        return shapes.hull(pts)

    lid = plate(0.0, length, -screen_t, 0.0, y / 2)
    panel = plate(0.05 * length, 0.95 * length, -0.0005, 0.0006, 0.46 * y)
    parts = ((base, body), (keys, dark), (pad, P.GREY), (lid, body), (panel, P.rgb(20, 30, 50)))
    return Geometry(parts, (col.box_part((depth, y, base_t), (x / 2 - depth / 2, 0, base_t / 2)), col.hull_part(lid)))


@dataclass(frozen=True)
class MonitorShape:
    """The screen's height as a fraction of the whole."""

    screen_h: float = 0.6


@builder(MonitorShape)
def monitor(v: Variant, p: MonitorShape) -> Geometry:
    """A flat-screen monitor on a stand; the screen faces +x."""
    x, y, z = v.size
    frame = v.color(0, P.CHARCOAL)
    base_x = x
    base = shapes.slab(base_x, min(0.25, 0.45 * y), 0.012, 0.02, (0, 0, 0.006))
    screen_t = 0.022
    screen_h = p.screen_h * z
    screen = shapes.box((screen_t, y, screen_h), (0.0, 0, z - screen_h / 2))
    display = shapes.box((0.002, y - 0.02, screen_h - 0.025), (screen_t / 2 + 0.0005, 0, z - screen_h / 2 + 0.004))
    neck = shapes.box(
        (0.03, 0.06, z - screen_h / 2 - 0.012), (-screen_t / 2 - 0.015, 0, 0.012 + (z - screen_h / 2 - 0.012) / 2)
    )
    parts = ((base, frame), (neck, frame), (screen, frame), (display, P.rgb(25, 40, 70)))
    collision = (
        col.hull_part(base),
        col.hull_part(neck),
        col.hull_part(np.vstack([screen.vertices, display.vertices])),
    )
    return Geometry(parts, collision)


@builder(NoOptions)
def keyboard(v: Variant, _: NoOptions) -> Geometry:
    """A keyboard: base slab plus rows of key caps; the space bar row is nearest +x (the typist)."""
    x, y, z = v.size
    base_h = 0.55 * z
    base = shapes.slab(x, y, base_h, 0.006, (0, 0, base_h / 2))
    cap_h = z - base_h
    rows = 5 if x < 0.17 else 6
    pitch_x = (x - 0.02) / rows
    cols = max(10, int((y - 0.02) / 0.019))
    pitch_y = (y - 0.02) / cols
    keys = []
    for row in range(rows):
        px = x / 2 - 0.01 - (row + 0.5) * pitch_x
        if row == 0:
            keys.append(shapes.box((0.8 * pitch_x, 6 * pitch_y, cap_h), (px, 0, base_h + cap_h / 2)))
            for c in list(range(0, 3)) + list(range(cols - 3, cols)):
                py = -y / 2 + 0.01 + (c + 0.5) * pitch_y
                keys.append(shapes.box((0.8 * pitch_x, 0.8 * pitch_y, cap_h), (px, py, base_h + cap_h / 2)))
            continue
        for c in range(cols):
            py = -y / 2 + 0.01 + (c + 0.5) * pitch_y
            keys.append(shapes.box((0.8 * pitch_x, 0.8 * pitch_y, cap_h), (px, py, base_h + cap_h / 2)))
    caps = shapes.concatenate(keys)
    parts = ((base, v.color(0, P.CHARCOAL)), (caps, v.color(1, P.rgb(70, 72, 78))))
    return Geometry(parts, (col.box_part((x, y, base_h + 0.6 * cap_h), (0, 0, (base_h + 0.6 * cap_h) / 2)),))


@builder(NoOptions)
def mouse(v: Variant, _: NoOptions) -> Geometry:
    """A computer mouse: a domed shell; buttons at -x (away from the user), button split line and wheel."""
    x, y, z = v.size
    dome = shapes.ellipsoid((x / 2, y / 2, z), (0, 0, 0), 3)
    keep = dome.vertices[:, 2] >= -1e-9
    pts = dome.vertices.copy()
    pts[:, 2] = np.maximum(pts[:, 2], 0.0)
    shell = shapes.hull(pts[keep | True])
    wheel = shapes.cylinder(0.004, 0.003, (-0.22 * x, 0, 0.96 * z - 0.003), axis="y", sections=16)
    split = shapes.box((0.4 * x, 0.0012, 0.004), (-0.3 * x, 0, 0.88 * z))
    parts = ((shell, v.color(0, P.CHARCOAL)), (split, P.BLACK), (wheel, v.color(1, P.GREY)))
    return Geometry(parts, (col.hull_part(shell),))


@builder(NoOptions)
def phone(v: Variant, _: NoOptions) -> Geometry:
    """A smartphone lying screen up; top edge at -x."""
    x, y, z = v.size
    body = shapes.slab(x, y, z, 0.2 * y, (0, 0, z / 2))
    screen = shapes.slab(x - 0.008, y - 0.006, 0.0006, 0.18 * y, (0, 0, z - 0.0002))
    camera = shapes.cylinder(0.0025, 0.0006, (-x / 2 + 0.01, 0, z - 0.0001))
    parts = ((body, v.color(0, P.CHARCOAL)), (screen, v.color(1, P.rgb(15, 20, 35))), (camera, P.GREY))
    return Geometry(parts, (col.box_part((x, y, z), (0, 0, z / 2)),))


CATEGORIES: tuple[CategoryDef, ...] = builtin_categories(__name__, globals())  # variants: data/office.json
