"""Long thin objects lying along x (handle towards +x, the user): cutlery, chopsticks, toothbrushes, hand tools."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh
from shapely.geometry import Polygon, box
from shapely.ops import unary_union

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.gen.common import fit_to_size
from physcensis.assets.gen.variant_data import builtin_categories
from physcensis.assets.spec import CategoryDef, Geometry, NoOptions, Variant, builder


def _bend(
    mesh: trimesh.Trimesh,
    length: float,
    lift_handle: float,
    lift_head: float,
    dip: tuple[float, float, float] | None = None,
) -> trimesh.Trimesh:
    """Curve a flat utensil: the handle end (+x) and head end (-x) rise; optional spoon-bowl dip (cx, rx, depth)."""
    v = mesh.vertices.copy()
    u = v[:, 0] / (length / 2)  # -1 at the head tip, +1 at the handle end
    v[:, 2] += (
        lift_handle * np.clip(u - 0.2, 0, None) ** 2 / 0.64 + lift_head * np.clip(-u - 0.55, 0, None) ** 2 / 0.2025
    )
    if dip is not None:
        cx, rx, depth = dip
        w = np.clip(1 - ((v[:, 0] - cx) / rx) ** 2 - (v[:, 1] / (0.7 * rx)) ** 2, 0, None)
        v[:, 2] -= depth * w
    return trimesh.Trimesh(v, mesh.faces, process=False)


def _flat_utensil(
    outline: Polygon,
    thickness: float,
    length: float,
    lift_handle: float,
    lift_head: float,
    dip: tuple[float, float, float] | None = None,
) -> trimesh.Trimesh:
    extruded = shapes.extrude(outline.segmentize(length / 60), thickness)
    merged = trimesh.Trimesh(extruded.vertices, extruded.faces)  # processed: duplicate vertices merged
    vertices, faces = trimesh.remesh.subdivide_to_size(merged.vertices, merged.faces, length / 40)
    return _bend(trimesh.Trimesh(vertices, faces, process=False), length, lift_handle, lift_head, dip)


@dataclass(frozen=True)
class ForkShape:
    """The number of tines."""

    tines: int = 4


@builder(ForkShape)
def fork(v: Variant, p: ForkShape) -> Geometry:
    length, width, height = v.size
    t = 0.0025
    tines = p.tines
    head_len = 0.3 * length
    x_head = -length / 2
    handle = Polygon(
        [
            (x_head + head_len + 0.02, -0.003),
            (length / 2 - 0.012, -0.6 * width / 2),
            (length / 2, -0.5 * width / 2 + 0.002),
            (length / 2, 0.5 * width / 2 - 0.002),
            (length / 2 - 0.012, 0.6 * width / 2),
            (x_head + head_len + 0.02, 0.003),
        ]
    )
    head = Polygon(
        [
            (x_head, -width / 2),
            (x_head + head_len, -width / 2),
            (x_head + head_len + 0.025, -0.003),
            (x_head + head_len + 0.025, 0.003),
            (x_head + head_len, width / 2),
            (x_head, width / 2),
        ]
    )
    slot_w = width / (2 * tines - 1) * 0.8
    pitch = (width - slot_w * (tines - 1)) / tines + slot_w
    slots = [
        box(
            x_head - 0.001,
            -width / 2 + (k + 1) * pitch - slot_w,
            x_head + 0.55 * head_len,
            -width / 2 + (k + 1) * pitch,
        )
        for k in range(tines - 1)
    ]
    outline = unary_union([handle, head]).difference(unary_union(slots))
    mesh = _flat_utensil(outline, t, length, height - t - 0.002, 0.4 * (height - t))
    return fit_to_size(Geometry(((mesh, v.color(0, P.STEEL)),), col.segment_hulls(mesh)), v.size)


@dataclass(frozen=True)
class KnifeShape:
    """The blade's length as a fraction of the whole."""

    blade: float = 0.5


@builder(KnifeShape)
def knife(v: Variant, p: KnifeShape) -> Geometry:
    length, width, height = v.size
    t = 0.0025
    blade_len = p.blade * length
    x0 = -length / 2
    blade = Polygon(
        [
            (x0, width / 2 - 0.004),
            (x0 + 0.02, width / 2),
            (x0 + blade_len, width / 2),
            (x0 + blade_len, -width / 2 + 0.004),
            (x0 + 0.35 * blade_len, -width / 2),
            (x0 + 0.08 * blade_len, -width / 2 + 0.25 * width),
        ]
    )
    handle = Polygon(
        [
            (x0 + blade_len - 0.002, width / 2 - 0.001),
            (length / 2, 0.35 * width),
            (length / 2, -0.35 * width),
            (x0 + blade_len - 0.002, -width / 2 + 0.004),
        ]
    )
    outline = unary_union([blade, handle]).buffer(0.0008).buffer(-0.0008)
    mesh = _flat_utensil(outline, t, length, height - t, 0.0)
    colors = v.colors
    if len(colors) > 1:
        handle_mesh = _flat_utensil(handle.buffer(0.0003), t + 0.003, length, height - t - 0.003, 0.0)
        blade_mesh = _flat_utensil(blade.buffer(0.0004), t * 0.6, length, height - t, 0.0)
        parts = ((blade_mesh, colors[0]), (handle_mesh, colors[1]))
        return fit_to_size(
            Geometry(parts, (col.hull_part(np.vstack([blade_mesh.vertices, handle_mesh.vertices])),)), v.size
        )
    return fit_to_size(Geometry(((mesh, v.color(0, P.STEEL)),), (col.hull_part(mesh),)), v.size)


@dataclass(frozen=True)
class SpoonShape:
    """The bowl's length as a fraction of the whole."""

    bowl: float = 0.33


@builder(SpoonShape)
def spoon(v: Variant, p: SpoonShape) -> Geometry:
    length, width, height = v.size
    t = 0.0022
    bowl_len = p.bowl * length
    x0 = -length / 2
    bowl = Polygon(
        [
            (x0 + bowl_len / 2 + bowl_len / 2 * np.cos(a), width / 2 * np.sin(a))
            for a in np.linspace(0, 2 * np.pi, 48, endpoint=False)
        ]
    )
    handle = Polygon(
        [
            (x0 + bowl_len * 0.9, -0.003),
            (length / 2 - 0.012, -0.5 * width * 0.45),
            (length / 2, -0.3 * width * 0.45),
            (length / 2, 0.3 * width * 0.45),
            (length / 2 - 0.012, 0.5 * width * 0.45),
            (x0 + bowl_len * 0.9, 0.003),
        ]
    )
    outline = unary_union([bowl, handle])
    dip = 0.45 * (height - t)
    mesh = _flat_utensil(outline, t, length, height - t - dip * 0.2, 0.0, (x0 + bowl_len / 2, bowl_len / 2, dip))
    return fit_to_size(Geometry(((mesh, v.color(0, P.STEEL)),), (col.hull_part(mesh),)), v.size)


@dataclass(frozen=True)
class ChopstickShape:
    """Square instead of round."""

    square: bool = False


@builder(ChopstickShape)
def chopstick(v: Variant, p: ChopstickShape) -> Geometry:
    """One chopstick (a pair is two objects), tapering to the tip at -x."""
    length, _, d = v.size
    if p.square:
        mesh = shapes.hull(
            [
                [x, sy * s / 2, d / 2 + sz * s / 2]
                for x, s in ((length / 2, d), (-length / 2, 0.55 * d))
                for sy in (-1, 1)
                for sz in (-1, 1)
            ]
        )
    else:
        mesh = shapes.cone(0.55 * d / 2, d / 2, length, (0, 0, d / 2), axis="x", sections=12)
    # tilt the taper so the underside lies flat on the table instead of rolling on an edge
    mesh.apply_transform(trimesh.transformations.rotation_matrix(-np.arctan(0.225 * d / length), (0, 1, 0)))
    return Geometry(((mesh, v.color(0, P.BAMBOO)),), (col.hull_part(mesh),))


@builder(NoOptions)
def toothbrush(v: Variant, _: NoOptions) -> Geometry:
    """Handle along x, bristle head at -x, bristles up."""
    length, width, height = v.size
    handle_t = 0.007
    path = np.array(
        [
            [length / 2 - 0.005, 0, handle_t / 2 + 0.001],
            [0.0, 0, handle_t / 2 + 0.0005],
            [-length / 2 + 0.03, 0, handle_t / 2],
        ]
    )
    handle = shapes.tube(
        shapes.resample_polyline(path, 12), np.linspace(0.55 * width, 0.35 * width, 12), sides=14, squash=0.6
    )
    head = shapes.slab(0.028, 0.75 * width, 0.005, 0.004, (-length / 2 + 0.016, 0, 0.0025))
    tufts = shapes.slab(
        0.024, 0.7 * width, height - 0.005, 0.003, (-length / 2 + 0.016, 0, 0.005 + (height - 0.005) / 2)
    )
    parts = ((handle, v.color(0, P.BLUE)), (head, v.color(0, P.BLUE)), (tufts, v.color(1, P.WHITE)))
    return fit_to_size(Geometry(parts, (col.hull_part(np.vstack([m.vertices for m, _ in parts])),)), v.size)


@dataclass(frozen=True)
class HammerShape:
    """The head's width along the handle (m)."""

    head: float = 0.028


@builder(HammerShape)
def hammer(v: Variant, p: HammerShape) -> Geometry:
    """A claw hammer lying on its side: handle along x (grip at +x), head across y at -x."""
    length, width, height = v.size
    head_w = p.head
    handle_r = 0.5 * height
    handle_path = np.array([[-length / 2 + head_w / 2, 0, height / 2], [length / 2 - 0.01, 0, height / 2]])
    handle = shapes.tube(
        shapes.resample_polyline(handle_path, 8), np.linspace(0.8 * handle_r, handle_r, 8), sides=16, squash=0.75
    )
    face_len = 0.45 * width
    head = shapes.cylinder(
        0.45 * height, face_len, (-length / 2 + head_w / 2, -face_len / 2 + 0.006, 0.5 * height), axis="y", sections=20
    )
    claw = shapes.hull(
        [
            [-length / 2 + head_w * f, y, z]
            for f in (0.15, 0.85)
            for y, z in (
                (0.0, 0.15 * height),
                (0.0, 0.85 * height),
                (width / 2, 0.4 * height),
                (width / 2, 0.6 * height),
                (0.45 * width, 0.1 * height),
            )
        ]
    )
    grip = shapes.tube(
        shapes.resample_polyline(np.array([[0.05 * length, 0, height / 2], [length / 2, 0, height / 2]]), 6),
        handle_r * 1.04,
        sides=16,
        squash=0.8,
    )
    parts = ((handle, v.color(0, P.WOOD)), (head, P.STEEL), (claw, P.STEEL), (grip, v.color(1, v.color(0, P.WOOD))))
    collision = (
        col.hull_part(np.vstack([handle.vertices, grip.vertices])),
        col.hull_part(np.vstack([head.vertices, claw.vertices])),
    )
    return fit_to_size(Geometry(parts, collision), v.size)


@dataclass(frozen=True)
class ScrewdriverShape:
    """The handle's length (fraction of the whole) and the shaft's radius (m)."""

    handle: float = 0.42
    shaft: float = 0.003


@builder(ScrewdriverShape)
def screwdriver(v: Variant, p: ScrewdriverShape) -> Geometry:
    """Handle at +x, steel shaft towards -x."""
    length, _, d = v.size
    handle_len = p.handle * length
    r = d / 2
    x_h = length / 2 - handle_len
    handle = shapes.lathe(
        np.array(
            [
                (0, 0),
                (0.75 * r, 0),
                (r, 0.1 * handle_len),
                (r, 0.85 * handle_len),
                (0.8 * r, handle_len),
                (0, handle_len),
            ]
        ),
        16,
    )
    handle.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, (0, 1, 0)))
    handle.apply_translation((x_h, 0, r))
    shaft_r = p.shaft
    shaft_len = length - handle_len + 0.01
    shaft = shapes.cylinder(shaft_r, shaft_len, (x_h - shaft_len / 2 + 0.01, 0, r), axis="x", sections=12)
    tip = shapes.hull(
        [[-length / 2, sy * shaft_r * 1.1, r + sz * 0.0006] for sy in (-1, 1) for sz in (-1, 1)]
        + [[-length / 2 + 0.012, sy * shaft_r, r + sz * shaft_r] for sy in (-1, 1) for sz in (-1, 1)]
    )
    parts = ((handle, v.color(0, P.RED)), (shaft, P.STEEL), (tip, P.STEEL))
    collision = (col.hull_part(handle), col.capsule_part(shaft_r, (-length / 2 + shaft_r, 0, r), (x_h, 0, r)))
    return Geometry(parts, collision)


@builder(NoOptions)
def tape_measure(v: Variant, _: NoOptions) -> Geometry:
    """A tape measure standing on its base: rounded case, tape mouth and hook at +x."""
    x, y, z = v.size
    case = shapes.rounded_box((x - 0.006, y, z), 0.25 * min(x, y, z), (-0.003, 0, z / 2))  # flat enough to stand
    hub = shapes.cylinder(0.28 * z, y + 0.002, (-0.003, 0, 0.55 * z), axis="y")
    hook = shapes.box((0.006, 0.022, 0.012), (x / 2 - 0.003, 0, 0.008))
    tape = shapes.box((0.012, 0.019, 0.002), (x / 2 - 0.009, 0, 0.004))
    parts = ((case, v.color(0, P.YELLOW)), (hub, v.color(1, P.CHARCOAL)), (hook, P.BRASS), (tape, P.YELLOW))
    return fit_to_size(Geometry(parts, (col.hull_part(np.vstack([m.vertices for m, _ in parts])),)), v.size)


CATEGORIES: tuple[CategoryDef, ...] = builtin_categories(__name__, globals())  # variants: data/utensils.json
