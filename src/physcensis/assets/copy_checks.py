"""An asset read back from a file that came from elsewhere (a scene folder's copy) checked as an import checks one.

A payload that decodes (`serialize.asset_from_bytes`: bounded, types and shapes right) is not yet an asset an import
could have made. `check_copied_asset` applies the importer's own checks and ranges again: the visual mesh passes
`meshfile.check_mesh_arrays` (triangles, indices in range, finite coordinates) within the triangle limit, measures
0.1 mm to 20 m a side (`library.py`) and lies within 20 m of the asset's origin; it has at most MAX_COLOURS coloured
parts, each with an area (MuJoCo refuses a mesh without one); mass, friction, colours and centre of mass are in the
importer's ranges; collision parts are solid convex pieces of at most MAX_HULL_VERTICES vertices, at most MAX_PARTS of
them; a cavity lies within the asset; names and descriptions are one line of text of an entry's lengths.
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from physcensis.assets.build import MASS_SPREAD
from physcensis.assets.collision import MAX_HULL_VERTICES
from physcensis.assets.colours import MAX_COLOURS
from physcensis.assets.decompose import MAX_PARTS
from physcensis.assets.errors import AssetError
from physcensis.assets.library import MAX_EXTENT, MAX_FRICTION, MAX_MASS, MIN_EXTENT, MIN_MASS, MIN_PART_VOLUME
from physcensis.assets.meshfile import check_mesh_arrays
from physcensis.assets.model import Asset, Cavity, CollisionPart
from physcensis.assets.serialize import MAX_PAYLOAD_FACES

MIN_PART_AREA = 1e-12  # m^2; MuJoCo refuses a visual mesh of (almost) no area
MAX_NAME_CHARS, MAX_TEXT_CHARS, MAX_PATH_CHARS = 200, 2000, 8192  # an entry's names, descriptions; a mesh's path
MAX_NAMES = 200  # tags, synonyms, guessed fields


def check_copied_asset(asset: Asset) -> None:
    """Raise AssetError with the first reason an import would not have made `asset`."""
    _check_visual(asset)
    _check_physics(asset)
    _check_collision(asset.collision)
    if asset.cavity is not None:
        _check_cavity(asset.cavity)
    _check_text(asset)


def _within(what: str, values: np.ndarray | Iterable[float], bound: float = MAX_EXTENT) -> None:
    """Finite and no farther than `bound` metres from the asset's origin."""
    array = np.asarray(values, dtype=float)
    if not np.isfinite(array).all():
        raise AssetError(f"{what} has NaN or infinite coordinates")
    largest = float(np.abs(array).max(initial=0.0))
    if largest > bound:
        raise AssetError(f"{what} reaches {largest:.3g} m from the asset's origin; an asset lies within {bound:g} m")


def _check_visual(asset: Asset) -> None:
    check_mesh_arrays(asset.visual)
    vertices, faces = np.asarray(asset.visual.vertices, dtype=float), np.asarray(asset.visual.faces)
    if len(faces) > MAX_PAYLOAD_FACES:
        raise AssetError(f"the mesh has {len(faces):,} triangles, over the limit of {MAX_PAYLOAD_FACES:,}")
    _within("a vertex", vertices)
    used = np.zeros(len(vertices), dtype=bool)
    used[faces.ravel()] = True
    extents = np.ptp(vertices[used], axis=0)  # the importer's extents: of the vertices the faces use
    for what, sides in (("the mesh", extents), ("its recorded size", asset.size)):
        if not all(MIN_EXTENT <= float(side) <= MAX_EXTENT for side in sides):
            shown = " x ".join(f"{float(side):.3g}" for side in sides)
            raise AssetError(f"{what} measures {shown} m; each side must be between 0.1 mm and {MAX_EXTENT:g} m")
    _check_coloured_parts(vertices, faces, asset.part_faces)


def _check_coloured_parts(vertices: np.ndarray, faces: np.ndarray, part_faces: tuple[int, ...]) -> None:
    if len(part_faces) > MAX_COLOURS or min(part_faces) < 1:
        raise AssetError(f"its {len(part_faces):,} coloured parts are not 1 to {MAX_COLOURS} runs of faces")
    start = 0
    for index, count in enumerate(part_faces):
        if not _has_area(vertices, faces[start : start + count]):
            raise AssetError(f"coloured part {index} of the mesh has no area (degenerate triangles)")
        start += count


def _has_area(vertices: np.ndarray, faces: np.ndarray) -> bool:
    """Whether the triangles' area exceeds MIN_PART_AREA; the first few triangles almost always show it."""
    area = 0.0
    for triangles in (faces[:64], faces[64:]):
        corner = vertices[triangles[:, 0]]
        sides = np.cross(vertices[triangles[:, 1]] - corner, vertices[triangles[:, 2]] - corner)
        area += 0.5 * float(np.linalg.norm(sides, axis=1).sum())
        if area > MIN_PART_AREA:
            return True
    return False


def _check_physics(asset: Asset) -> None:
    if not MIN_MASS <= asset.mass <= MAX_MASS:
        raise AssetError(f"its mass {asset.mass:.3g} kg is not between {MIN_MASS:g} and {MAX_MASS:g} kg")
    lowest, highest = MIN_MASS * (1 - MASS_SPREAD), MAX_MASS * (1 + MASS_SPREAD)  # a mass +/- the import's spread
    lo, hi = asset.mass_range
    if not lowest <= lo <= asset.mass <= hi <= highest:
        raise AssetError(
            f"its mass range [{lo:.3g}, {hi:.3g}] kg does not hold its mass within [{lowest:g}, {highest:g}]"
        )
    lo, hi = asset.friction_range
    if not 0.0 < lo <= hi <= MAX_FRICTION:
        raise AssetError(f"its friction range [{lo:.3g}, {hi:.3g}] is not an ordered range in (0, {MAX_FRICTION:g}]")
    _within("its centre of mass", asset.com)
    if not all(0.0 <= shift <= MAX_EXTENT for shift in asset.com_shift_range):
        raise AssetError(f"its centre-of-mass shift {asset.com_shift_range} is not between 0 and {MAX_EXTENT:g} m")
    if not all(0.0 <= channel <= 1.0 for colour in asset.rgba for channel in colour):
        raise AssetError("a colour has a channel outside [0, 1]")


def _check_collision(parts: tuple[CollisionPart, ...]) -> None:
    if len(parts) > MAX_PARTS:
        raise AssetError(f"it has {len(parts)} collision parts, over the limit of {MAX_PARTS}")
    for index, part in enumerate(parts):
        what = f"collision part {index}"
        _within(what, part.pos)
        if part.vertices is not None:
            if len(part.vertices) > MAX_HULL_VERTICES:
                raise AssetError(f"{what} has {len(part.vertices):,} vertices, over the limit of {MAX_HULL_VERTICES}")
            _within(what, part.vertices)
            if not part.volume > MIN_PART_VOLUME:
                raise AssetError(f"{what} is flat or degenerate: it has no volume")
        elif not all(0.0 <= side <= MAX_EXTENT for side in part.size):
            raise AssetError(f"{what} has the size {part.size}, not sides between 0 and {MAX_EXTENT:g} m")
        if not 0.5 <= float(np.linalg.norm(part.quat)) <= 2.0:
            raise AssetError(f"{what} has the rotation {part.quat}, far from a unit quaternion")


def _check_cavity(cavity: Cavity) -> None:
    if len(cavity.opening) < 3:
        raise AssetError("its cavity opening has fewer than 3 corners")
    _within("its cavity opening", cavity.opening)
    _within("its cavity floor", (cavity.floor_height,))
    if not 0.0 <= cavity.depth <= MAX_EXTENT:
        raise AssetError(f"its cavity depth {cavity.depth:.3g} m is not between 0 and {MAX_EXTENT:g} m")


def _one_line(what: str, text: str, limit: int) -> None:
    if len(text) > limit or any(ord(c) < 32 or ord(c) == 127 for c in text):
        raise AssetError(f"its {what} is not one line of at most {limit:,} characters without control characters")


def _check_text(asset: Asset) -> None:
    for what, text, limit in (
        ("category", asset.category, MAX_NAME_CHARS),
        ("kind", asset.kind, MAX_NAME_CHARS),
        ("description", asset.description, MAX_TEXT_CHARS),
        ("pose", asset.pose, MAX_TEXT_CHARS),
        ("source", asset.source, MAX_PATH_CHARS),
    ):
        _one_line(what, text, limit)
    for what, names in (("tags", asset.tags), ("synonyms", asset.synonyms), ("guessed fields", asset.guessed)):
        if len(names) > MAX_NAMES:
            raise AssetError(f"it has {len(names):,} {what}, over the limit of {MAX_NAMES}")
        for name in names:
            _one_line(what, name, MAX_NAME_CHARS)
