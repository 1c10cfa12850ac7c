"""User asset libraries: a folder with `library.yaml` (or `.json`) listing mesh files and annotations.

Ingest normalises each mesh to the asset conventions (metres, +z up, front +x,
base at z = 0, footprint centred), checks watertightness, builds collision
(one hull for nearly convex meshes, CoACD parts otherwise) and fills missing
annotations from the category's defaults, recording them in `Asset.guessed`.
A broken entry - an unreadable, empty, flat or NaN mesh, a path leaving the
folder, a field of the wrong type or out of range, a nested or aliased value
over the bounds of `bounded.py`, a failing decomposition - is reported as an
`EntryError` naming its file, position and reason, and the rest still loads.
Only a library file that cannot be read as a whole raises `LibraryError`.

Bounds: library file 1 MB, 5,000 entries, 64 nesting levels and 10,000 values
(aliases expanded) per entry; mesh files 100 MB and 2,000,000 triangles (see
`meshfile.py`); sides 0.1 mm to 20 m, masses 1 mg to 100 t, friction (0, 10].

    unit: cm            # optional library defaults: unit, up, front
    up: +y
    assets:
      - file: meshes/mug.glb
        id: red_mug
        category: mug
        description: a red enamel mug
        size: [0.12, 0.09, 0.1]   # or height: 0.1, or scale: 0.01
        mass: [0.25, 0.35]
"""

from __future__ import annotations

import logging
import re
import reprlib
import sys
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Annotated, Any, Literal, TypeGuard

import numpy as np
import trimesh
from pydantic import AfterValidator, BaseModel, ConfigDict, Field, ValidationError, field_validator
from scipy.spatial import ConvexHull, QhullError

from physcensis.assets import collision as col
from physcensis.assets.bounded import Refused, load_yaml, value_problem
from physcensis.assets.build import MASS_SPREAD
from physcensis.assets.builtin import category_defaults
from physcensis.assets.cache import AssetCache
from physcensis.assets.colours import coloured_parts, face_colours
from physcensis.assets.decompose import convex_decomposition
from physcensis.assets.errors import AssetError
from physcensis.assets.hulls import near_convex
from physcensis.assets.import_cache import asset_key
from physcensis.assets.meshfile import confined_path, first_line, load_mesh_file
from physcensis.assets.model import Asset, Cavity, CollisionPart
from physcensis.assets.rest_pose import AXIS_UPS, FILE_UP, GLTF_UPS, Pose, choose_pose, flattened_base, pose_of
from physcensis.bounded_json import load_json
from physcensis.fileio import BoundError, read_bounded
from physcensis.ids import is_valid_id

log = logging.getLogger(__name__)
LIBRARY_FILES = ("library.yaml", "library.yml", "library.json")
MAX_LIBRARY_BYTES = 1_000_000  # pure-Python YAML reads about 100 kB a second
MAX_ENTRIES = 5_000  # each entry loads a mesh: bounds the work one library can ask for
UNITS = {"m": 1.0, "cm": 0.01, "mm": 0.001, "in": 0.0254}
AXES = {"+x": (1, 0, 0), "-x": (-1, 0, 0), "+y": (0, 1, 0), "-y": (0, -1, 0), "+z": (0, 0, 1), "-z": (0, 0, -1)}
CONVEX_ENOUGH = 0.92  # volume / hull volume above which one hull is the collision
GENERIC_DENSITY = 500.0
MIN_PART_VOLUME = 1e-10  # m^3; flatter convex pieces are dropped (MuJoCo cannot give them inertia)
MIN_MASS, MAX_MASS = 1e-6, 1e5  # kg; MuJoCo cannot compile much lighter bodies, heavier ones are unit mistakes
MIN_EXTENT, MAX_EXTENT = 1e-4, 20.0  # m, each side of an imported asset
MIN_FILL = 1e-6  # hull volume / bounding-box volume below which a mesh is flat or knife-edge
MIN_ENCLOSED = 1e-4  # a closed mesh enclosing less than this fraction of its hull is inside-out or doubled
MAX_FRICTION = 10.0
Axis = Literal["+x", "-x", "+y", "-y", "+z", "-z"]
Unit = Literal["m", "cm", "mm", "in"]
Progress = Callable[[str, "Asset | EntryError"], None]  # called as each entry finishes


class LibraryError(AssetError):
    """The library as a whole is unreadable: no folder or file, bad syntax, over a bound, not a mapping."""


class EntryError(AssetError):
    """One library entry that failed: `entry` names it (file and position), `reason` says why."""

    def __init__(self, entry: str, reason: str) -> None:
        super().__init__(f"{entry}: {reason}")
        self.entry = entry
        self.reason = reason

    def __reduce__(self) -> tuple[type[EntryError], tuple[str, str]]:
        return (EntryError, (self.entry, self.reason))


def _one_line_of_text(value: str) -> str:
    if any(ord(c) < 32 or ord(c) == 127 for c in value):
        raise ValueError("must be one line of text without control characters")
    return value


Length = Annotated[float, Field(strict=True, gt=0, le=MAX_EXTENT)]
Scale = Annotated[float, Field(strict=True, ge=1e-6, le=1e6)]
Shift = Annotated[float, Field(strict=True, ge=0, le=MAX_EXTENT)]
Fraction = Annotated[float, Field(strict=True, ge=0, le=1)]
FrictionCoefficient = Annotated[float, Field(strict=True, gt=0, le=MAX_FRICTION)]
Name = Annotated[str, Field(min_length=1, max_length=200), AfterValidator(_one_line_of_text)]
Text = Annotated[str, Field(max_length=2000), AfterValidator(_one_line_of_text)]


def _is_number(value: object) -> TypeGuard[int | float]:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _within_mass_bounds(value: float) -> bool:
    try:
        return MIN_MASS <= float(value) <= MAX_MASS  # False for NaN; float() of a huge int overflows
    except OverflowError:
        return False


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)


class EntrySpec(_Model):
    file: Annotated[str, Field(min_length=1, max_length=4096)]
    id: Annotated[str, Field(max_length=200)] | None = None
    category: Name | None = None
    kind: Name | None = None
    description: Text | None = None
    tags: list[Name] = Field(default_factory=list, max_length=200)
    synonyms: list[Name] = Field(default_factory=list, max_length=200)
    unit: Unit | None = None
    scale: Scale | None = None
    size: tuple[Length, Length, Length] | None = None
    height: Length | None = None
    up: Axis | None = None
    front: Axis | None = None
    mass: float | tuple[float, float] | None = None
    friction: tuple[FrictionCoefficient, FrictionCoefficient] | None = None
    com_shift: tuple[Shift, Shift, Shift] | None = None
    support_probability: Fraction | None = None
    container: bool | None = None
    rgba: tuple[Fraction, Fraction, Fraction, Fraction] | None = None

    @field_validator("mass", mode="before")
    @classmethod
    def _mass_in_kilograms(cls, value: object) -> object:
        if value is None:
            return None
        pair = isinstance(value, list | tuple)
        values = list(value) if isinstance(value, list | tuple) else [value]
        numbers = [v for v in values if _is_number(v)]
        if (pair and len(values) != 2) or len(numbers) != len(values):
            raise ValueError("must be a number of kilograms or a [min, max] pair")
        if not all(_within_mass_bounds(v) for v in numbers):
            raise ValueError(f"must be between {MIN_MASS:g} and {MAX_MASS:g} kg (got {_short(value)})")
        return tuple(float(v) for v in numbers) if pair else float(numbers[0])


class LibrarySpec(_Model):
    name: Name | None = None
    unit: Unit = "m"
    up: Axis | None = None  # None: the resting pose is found (see rest_pose.py)
    front: Axis = "+x"
    assets: list[Any] = Field(default_factory=list, max_length=MAX_ENTRIES)  # each entry is validated on its own


@dataclass
class LibraryResult:
    """What loading a library produced: the good assets and one `EntryError` per broken entry."""

    folder: Path
    assets: list[Asset] = field(default_factory=list)
    errors: list[AssetError] = field(default_factory=list)


def _library_file(folder: Path) -> Path:
    for name in LIBRARY_FILES:
        if (folder / name).exists() or (folder / name).is_symlink():
            return folder / name
    raise LibraryError(f"{folder}: no library file ({' or '.join(LIBRARY_FILES)}) in this folder")


def _printable(text: str, limit: int) -> str:
    text = "".join(c if c.isprintable() else "?" for c in text)
    return text if len(text) <= limit else text[: limit - 1] + "…"


_REPR = reprlib.Repr()  # keyword arguments need Python 3.12
_REPR.maxlevel, _REPR.maxstring, _REPR.maxother = 3, 60, 60


def _short(value: object, limit: int = 60) -> str:
    """A bounded repr: a huge, deep or self-containing value is never expanded in full."""
    return _printable(_REPR.repr(value), limit)


def validation_reason(exc: ValidationError) -> str:
    """The first problem of a pydantic error as `field: what is wrong (got value)`, on one line."""
    problems = exc.errors()
    first = problems[0]
    where = ".".join(str(p) for p in first["loc"]) or "entry"
    if first["type"] == "extra_forbidden":
        reason = f"{where}: unknown field"
    elif first["type"] == "missing":
        reason = f"{where}: required field missing"
    else:
        message = first["msg"].removeprefix("Value error, ")
        reason = f"{where}: {message}" + ("" if "(got" in message else f" (got {_short(first.get('input'))})")
    more = len(problems) - 1
    return reason + (f" (and {more} more problem{'s' * (more > 1)})" if more else "")


def _parse_error(exc: Exception) -> str:
    problem, mark = getattr(exc, "problem", None), getattr(exc, "problem_mark", None)
    if problem and mark is not None:  # a MarkedYAMLError: say what and where, on one line
        return f"{problem} at line {mark.line + 1}, column {mark.column + 1}"
    if isinstance(exc, ValueError) and "integer string conversion" in str(exc):
        return f"a number has more than {sys.get_int_max_str_digits()} digits"
    return first_line(exc)


def _read_library_data(path: Path) -> Any:
    try:
        text = read_bounded(path, MAX_LIBRARY_BYTES, "library file").decode("utf-8")
        return load_json(text) if path.suffix == ".json" else load_yaml(text)
    except BoundError as exc:
        raise LibraryError(f"{path}: {exc}") from None
    except Exception as exc:  # syntax, encoding, digit limits, ...: all are the file's fault
        raise LibraryError(f"{path}: cannot read the library file ({_parse_error(exc)})") from None


def _top_level_problem(data: dict) -> str | None:
    """A problem of the file outside its entries (each entry is checked on its own when it is ingested)."""
    entries = data.get("assets")
    if isinstance(entries, Refused):
        return entries.reason
    return value_problem({key: value for key, value in data.items() if key != "assets"})


def read_library_spec(folder: str | Path) -> LibrarySpec:
    """The library file's top level (entries unchecked); LibraryError if the library as a whole is unusable."""
    folder = Path(folder)
    if not folder.is_dir():
        raise LibraryError(f"{folder}: asset library folder not found")
    path = _library_file(folder)
    data = _read_library_data(path)
    if not isinstance(data, dict):
        found = "nothing" if data is None else f"a {type(data).__name__}"
        raise LibraryError(f"{path}: the library file must be a mapping with an 'assets' list (found {found})")
    problem = _top_level_problem(data)
    if problem:
        raise LibraryError(f"{path}: {problem}")
    try:
        spec = LibrarySpec.model_validate(data)
    except ValidationError as exc:
        raise LibraryError(f"{path}: {validation_reason(exc)}") from None
    try:
        _rotation(spec.up or FILE_UP, spec.front)
    except AssetError as exc:
        raise LibraryError(f"{path}: {exc}") from None
    return spec


def _entry_label(folder: Path, index: int, raw: object) -> str:
    """How a summary names an entry: its file (when it has one) and its place in the list."""
    where = f"assets[{index}]"
    if isinstance(raw, dict) and isinstance(raw.get("file"), str):
        return f"{folder / _printable(raw['file'], 200)} ({where})"
    return f"{folder} ({where})"


def _ingest_raw(folder: Path, raw: object, spec: LibrarySpec, cache: AssetCache | None) -> Asset:
    problem = value_problem(raw)
    if problem:
        raise AssetError(problem)
    if not isinstance(raw, dict):
        raise AssetError(f"an entry must be a mapping with at least a 'file' key (found {_short(raw)})")
    try:
        entry = EntrySpec.model_validate(raw)
    except ValidationError as exc:
        raise AssetError(validation_reason(exc)) from None
    if cache is None:
        return ingest(folder, entry, spec, cache)
    return _cached_ingest(folder, entry, spec, cache)


def _cached_ingest(folder: Path, entry: EntrySpec, spec: LibrarySpec, cache: AssetCache) -> Asset:
    """The cached asset when the entry, its files and the import code are unchanged; else ingest and store it."""
    path = confined_path(folder.resolve(), entry.file)
    defaults = spec.model_dump(mode="json", exclude={"assets", "name"})
    key = asset_key(entry.model_dump(mode="json"), defaults, path)
    asset = cache.load(key)
    if asset is None:
        asset = ingest(folder, entry, spec, cache)
        cache.store(key, asset)
    return asset


def _load_entry(
    folder: Path, index: int, raw: object, spec: LibrarySpec, cache: AssetCache | None
) -> Asset | EntryError:
    """One entry's asset, or the EntryError naming it and why (never raises: the other entries still load)."""
    label = _entry_label(folder, index, raw)
    try:
        with np.errstate(all="ignore"):  # results are checked explicitly; no numpy noise on stderr
            return _ingest_raw(folder, raw, spec, cache)
    except AssetError as exc:
        return EntryError(label, _printable(str(exc), 500))
    except Exception as exc:  # whatever one entry does, the others still load
        log.debug("asset library: %s failed", label, exc_info=True)
        return EntryError(label, f"unexpected failure ({first_line(exc)})")


def _load_entries(
    folder: Path, spec: LibrarySpec, cache: AssetCache | None, workers: int, progress: Progress | None
) -> list[Asset | EntryError]:
    """Every entry's outcome in library order; `workers` threads (CoACD itself runs in child processes)."""

    def load(index: int) -> Asset | EntryError:
        outcome = _load_entry(folder, index, spec.assets[index], spec, cache)
        if progress is not None:
            progress(_entry_label(folder, index, spec.assets[index]), outcome)
        return outcome

    if workers <= 1 or len(spec.assets) <= 1:
        return [load(i) for i in range(len(spec.assets))]
    with ThreadPoolExecutor(max_workers=workers, thread_name_prefix="asset-import") as pool:
        return list(pool.map(load, range(len(spec.assets))))


def load_library(
    folder: str | Path, cache: AssetCache | None = None, workers: int = 2, progress: Progress | None = None
) -> LibraryResult:
    """Ingest every entry of a library; a broken entry becomes an EntryError naming it and why, the rest loads.

    Entries are ingested by `workers` threads; `progress(label, asset or error)` is called as each one finishes.
    Raises LibraryError when the library itself cannot be read (see `read_library_spec`).
    """
    folder = Path(folder)
    spec = read_library_spec(folder)
    result = LibraryResult(folder)
    seen: set[str] = set()
    for index, outcome in enumerate(_load_entries(folder, spec, cache, workers, progress)):
        if isinstance(outcome, Asset) and outcome.id in seen:
            outcome = EntryError(_entry_label(folder, index, spec.assets[index]), f"duplicate asset id {outcome.id!r}")
        if isinstance(outcome, Asset):
            seen.add(outcome.id)
            result.assets.append(outcome)
        else:
            result.errors.append(outcome)
    for err in result.errors:  # the caller reports them (result.errors); log for the record only
        log.info("asset library: %s", err)
    return result


def _rotation(up: str, front: str) -> np.ndarray:
    u, f = np.asarray(AXES[up], dtype=float), np.asarray(AXES[front], dtype=float)
    if abs(u.dot(f)) > 1e-9:
        raise AssetError(f"up {up} and front {front} must be perpendicular axes")
    return np.stack([f, np.cross(u, f), u])  # rows: new x (front), new y, new z (up)


def _slug(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9_-]+", "_", text).strip("_")[:64] or "asset"


def top_surface_height(mesh: trimesh.Trimesh, x: float = 0.0, y: float = 0.0) -> float | None:
    """Height where a vertical ray from above at (x, y) first meets the mesh (None if it misses)."""
    return _top_height(np.asarray(mesh.triangles), x, y)


def _top_height(tri: np.ndarray, x: float, y: float) -> float | None:
    """Height where a vertical ray from above at (x, y) first meets the triangles (None if it misses)."""
    a, b, c = tri[:, 0], tri[:, 1], tri[:, 2]
    v0, v1 = b[:, :2] - a[:, :2], c[:, :2] - a[:, :2]
    p = np.array([x, y]) - a[:, :2]
    det = v0[:, 0] * v1[:, 1] - v0[:, 1] * v1[:, 0]
    ok = np.abs(det) > 1e-15
    safe = np.where(ok, det, 1.0)
    u = (p[:, 0] * v1[:, 1] - p[:, 1] * v1[:, 0]) / safe
    v = (v0[:, 0] * p[:, 1] - v0[:, 1] * p[:, 0]) / safe
    inside = ok & (u >= -1e-9) & (v >= -1e-9) & (u + v <= 1 + 1e-9)
    if not inside.any():
        return None
    z = a[:, 2] + u * (b[:, 2] - a[:, 2]) + v * (c[:, 2] - a[:, 2])
    return float(z[inside].max())


def _detect_cavity(mesh: trimesh.Trimesh) -> Cavity | None:
    """An open top: looking straight down at the footprint centre, the first surface is well below the top, and
    walls rise around it in every direction (a figure lying on its back is low in the middle but open sideways)."""
    height = float(mesh.bounds[1][2])
    floor = top_surface_height(mesh)
    if floor is None:
        return None
    if floor > 0.6 * height or not _walled_all_around(mesh, floor, height):
        return None
    top = mesh.vertices[mesh.vertices[:, 2] > height - 0.03 * height][:, :2]
    try:
        rim = top[ConvexHull(top).vertices]
    except (QhullError, ValueError):  # a knife-edge (collinear) top has no opening
        return None
    opening = rim * 0.85  # inside the outer rim, by a wall's worth
    return Cavity(opening, floor, height - floor)


WALL_DIRECTIONS = 8
WALL_STEPS = 200  # along each walk: a 1 mm wall of a 20 cm bin is not stepped over


def _walled_all_around(mesh: trimesh.Trimesh, floor: float, height: float) -> bool:
    """Whether, walking out from the footprint centre in each of 8 directions, the top surface rises at least halfway
    from the cavity's floor to the top before the walk leaves the mesh."""
    reach = 0.5 * float(np.linalg.norm(mesh.extents[:2]))
    wall = floor + 0.5 * (height - floor)
    triangles = np.asarray(mesh.triangles)
    for angle in np.linspace(0.0, 2 * np.pi, WALL_DIRECTIONS, endpoint=False):
        direction = np.array([np.cos(angle), np.sin(angle)])
        if not _meets_wall(_near_line(triangles, direction, reach), direction, reach, wall):
            return False
    return True


def _near_line(triangles: np.ndarray, direction: np.ndarray, reach: float) -> np.ndarray:
    """The triangles whose xy bounding circle touches the walk from the centre along `direction` (bounded work on
    dense meshes: each ray of the walk then tests only these)."""
    xy = triangles[:, :, :2]
    centre = xy.mean(axis=1)
    radius = np.linalg.norm(xy - centre[:, None, :], axis=2).max(axis=1)
    along = centre @ direction
    across = np.abs(centre @ np.array([-direction[1], direction[0]]))
    return triangles[(across <= radius) & (along >= -radius) & (along <= reach + radius)]


def _meets_wall(triangles: np.ndarray, direction: np.ndarray, reach: float, wall: float) -> bool:
    for step in np.linspace(reach / WALL_STEPS, reach, WALL_STEPS):
        z = _top_height(triangles, *(step * direction))
        if z is None:
            return False  # out past the mesh without meeting a wall: open on that side
        if z >= wall:
            return True
    return False


def _require_thickness(mesh: trimesh.Trimesh) -> None:
    extents = np.asarray(mesh.extents, dtype=float)
    flat = [axis for axis, extent in zip("xyz", extents, strict=True) if not extent > 1e-9 * extents.max()]
    if flat:
        raise AssetError(f"the mesh is flat: it has no thickness along its {' or '.join(flat)} axis, so no volume")


def _check_extents(mesh: trimesh.Trimesh) -> None:
    extents = np.asarray(mesh.extents, dtype=float)
    if not np.isfinite(extents).all():
        raise AssetError("scaling the mesh gives non-finite sizes (check 'unit', 'scale', 'size' or 'height')")
    if not (np.all(extents >= MIN_EXTENT) and np.all(extents <= MAX_EXTENT)):
        shown = " x ".join(f"{v:.3g}" for v in extents)
        raise AssetError(
            f"the asset would measure {shown} m; each side must be between {MIN_EXTENT * 1000:g} mm and "
            f"{MAX_EXTENT:g} m (check 'unit', 'scale', 'size' or 'height')"
        )


def _front_for(up: str, front: str) -> str:
    """The library's front when it is perpendicular to the chosen up, else the first axis that is."""
    if abs(np.dot(AXES[up], AXES[front])) < 0.5:
        return front
    return next(f for f in ("+x", "-y", "+z", "-z") if abs(np.dot(AXES[up], AXES[f])) < 0.5)


def _orient(mesh: trimesh.Trimesh, e: EntrySpec, lib: LibrarySpec, path: Path) -> Pose:
    """In place: the entry's or library's up and front, or (neither giving an up) the pose the mesh rests in,
    trying the file format's own up first (+y for glTF, +z otherwise)."""
    up = e.up or lib.up
    front = e.front or lib.front
    order = GLTF_UPS if path.suffix.lower() in (".glb", ".gltf") else AXIS_UPS
    pose = choose_pose(mesh, order) if up is None else None
    if pose is not None and pose.also:
        log.warning(
            "%s: rests with %s up (chosen) and with %s up; give 'up' in library.yaml if it should stand otherwise",
            path,
            pose.up,
            " or ".join(pose.also),
        )
    if pose is not None and pose.up == "stable pose":
        rotation = pose.rotation
    else:
        chosen = pose.up if pose is not None else up
        assert chosen is not None
        rotation = _rotation(chosen, _front_for(chosen, front) if up is None else front)
    transform = np.eye(4)
    transform[:3, :3] = rotation
    mesh.apply_transform(transform)
    return pose if pose is not None else pose_of(mesh, str(up))


def _normalise(mesh: trimesh.Trimesh, e: EntrySpec, lib: LibrarySpec, path: Path) -> Pose:
    """In place: metres, +z up (the resting pose when no up is given), front +x, scaled to `size` / `height`,
    footprint centred, base at z = 0. Returns the pose and whether the mesh rests in it."""
    _require_thickness(mesh)
    mesh.apply_scale(UNITS[e.unit or lib.unit] * (e.scale or 1.0))
    pose = _orient(mesh, e, lib, path)
    if e.size is not None or e.height is not None:
        ext = mesh.extents
        target = np.asarray(e.size) if e.size is not None else None
        factor = float(np.median(target / ext)) if target is not None else float(e.height / ext[2])
        if target is not None and np.max(np.abs(ext * factor / target - 1)) > 0.1:
            log.warning(
                "%s: size %s differs from the mesh proportions by more than 10%%; scaled uniformly", path, e.size
            )
        mesh.apply_scale(factor)
    _check_extents(mesh)
    lo, hi = mesh.bounds
    mesh.apply_translation((-(lo[0] + hi[0]) / 2, -(lo[1] + hi[1]) / 2, -lo[2]))
    return pose


def _close_small_holes(mesh: trimesh.Trimesh, path: Path) -> bool:
    """Fill triangle and quad holes; whether the mesh is watertight afterwards."""
    if not mesh.is_watertight:
        try:
            trimesh.repair.fill_holes(mesh)
        except Exception as exc:  # junk topology: keep the open mesh, it is handled as such
            log.warning("%s: cannot fill the mesh's holes (%s)", path, first_line(exc))
    watertight = bool(mesh.is_watertight)
    if not watertight:
        log.warning("%s: mesh is not watertight; mass and collision are approximate", path)
    _face_outwards(mesh, path)
    return watertight


def _face_outwards(mesh: trimesh.Trimesh, path: Path) -> None:
    """Consistent winding with the normals outwards: a mesh exported inside out would render as its back faces
    (an open box where a book should be). An open mesh's signed volume still tells which way most faces look."""
    try:
        trimesh.repair.fix_winding(mesh)
        if float(mesh.volume) < 0:
            mesh.invert()
            log.info("%s: the mesh was inside out; its faces are turned", path)
    except Exception as exc:  # junk topology: keep the faces as they are
        log.debug("%s: cannot orient the faces (%s)", path, first_line(exc))


def _solid_hull(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    """The mesh's convex hull; AssetError for flat, collinear, knife-edge or vanishingly small meshes."""
    try:
        hull = mesh.convex_hull
        hull_volume = float(hull.volume)
    except Exception:  # Qhull refuses coplanar / collinear input in several ways
        raise AssetError("the mesh is flat or degenerate: its points are coplanar or collinear, so no volume") from None
    fill = hull_volume / float(np.prod(mesh.extents))
    if not fill > MIN_FILL:
        raise AssetError(f"the mesh is flat or knife-edge: its convex hull fills {fill:.1e} of its bounding box")
    if not hull_volume > MIN_PART_VOLUME:
        raise AssetError(f"the mesh's volume, {hull_volume:.2g} m^3, is too small to simulate (check 'unit', 'scale')")
    return hull


def _enclosed_volume(mesh: trimesh.Trimesh, hull: trimesh.Trimesh, watertight: bool) -> float:
    if not watertight:
        return 0.5 * float(hull.volume)  # an open mesh encloses nothing: guess half its hull
    volume = abs(float(mesh.volume))
    if not volume >= MIN_ENCLOSED * float(hull.volume):
        raise AssetError("the closed mesh encloses almost no volume (inside-out parts or doubled surfaces)")
    return volume


def _mass(e: EntrySpec, density: float, volume: float, guessed: set[str]) -> tuple[float, tuple[float, float]]:
    if isinstance(e.mass, tuple):
        lo, hi = sorted(e.mass)
        return (lo + hi) / 2, (lo, hi)
    if e.mass is not None:
        return e.mass, (e.mass * (1 - MASS_SPREAD), e.mass * (1 + MASS_SPREAD))
    mass = density * volume
    if not _within_mass_bounds(mass):
        raise AssetError(
            f"the mass estimated from the mesh volume, {mass:.2g} kg, is not between {MIN_MASS:g} and "
            f"{MAX_MASS:g} kg: give 'mass' or check 'unit' / 'scale'"
        )
    guessed.add("mass")
    return mass, (mass * (1 - MASS_SPREAD), mass * (1 + MASS_SPREAD))


def _cavity(mesh: trimesh.Trimesh, e: EntrySpec, guessed: set[str]) -> Cavity | None:
    if e.container is False:
        return None
    cavity = _detect_cavity(mesh)
    if e.container is None:
        guessed.add("container")
    elif cavity is None:
        raise AssetError("marked as a container but no open cavity was found from above")
    return cavity


def _hull_part(points: np.ndarray) -> CollisionPart | None:
    """The convex collision part around `points`, or None for a flat or degenerate piece."""
    pts = np.asarray(points, dtype=float)
    if pts.ndim != 2 or pts.shape[1] != 3 or len(pts) < 4 or not np.isfinite(pts).all():
        return None
    try:
        part = col.hull_part(pts)
    except (QhullError, ValueError):
        return None
    return part if part.volume > MIN_PART_VOLUME else None


def _one_hull_fits(mesh: trimesh.Trimesh, convexity: float, cavity: Cavity | None) -> bool:
    """A solid that fills its hull, or an open mesh whose hull stays near its surface (a can with holes); no cup."""
    if cavity is not None:
        return False
    return convexity >= CONVEX_ENOUGH if mesh.is_watertight else near_convex(mesh)


def _collision(
    mesh: trimesh.Trimesh, hull: trimesh.Trimesh, convexity: float, cavity: Cavity | None, cache: AssetCache | None
) -> tuple[CollisionPart, ...]:
    """One hull for a nearly convex mesh, at most 16 convex parts otherwise (flat pieces dropped)."""
    if _one_hull_fits(mesh, convexity, cavity):
        part = _hull_part(hull.vertices)
        if part is None:
            raise AssetError("the mesh's convex hull is degenerate (a knife-edge mesh)")
        return (part,)
    parts = (_hull_part(v) for v in convex_decomposition(mesh, cache=cache, cavity=cavity))
    collision = tuple(p for p in parts if p is not None)
    if not collision:
        raise AssetError("convex decomposition gave no solid parts")
    return collision


def ingest(folder: Path, e: EntrySpec, lib: LibrarySpec, cache: AssetCache | None) -> Asset:
    """One library entry -> Asset (raises AssetError with a plain reason)."""
    ident = e.id or _slug(Path(e.file).stem)
    if not is_valid_id(ident):
        raise AssetError(f"invalid asset id {ident!r}")
    root = folder.resolve()
    path = confined_path(root, e.file)
    mesh = load_mesh_file(path, root)
    pose = _normalise(mesh, e, lib, path)
    colours = face_colours(mesh) if e.rgba is None else None  # before filling holes adds faces
    hull = _solid_hull(mesh)  # filling holes below adds faces, never vertices: the hull stays valid
    watertight = _close_small_holes(mesh, path)
    volume = _enclosed_volume(mesh, hull, watertight)
    guessed: set[str] = set() if watertight else {"watertight"}
    category = e.category or "object"
    defaults = category_defaults().get(category)
    mass, mass_range = _mass(e, defaults.density if defaults else GENERIC_DENSITY, volume, guessed)
    cavity = _cavity(mesh, e, guessed)
    convexity = volume / float(hull.volume) if watertight else 0.0
    collision = _collision(mesh, hull, convexity, cavity, cache)
    if e.up is None and lib.up is None:
        guessed.add("pose")
    for name, value in (
        ("category", e.category),
        ("friction", e.friction),
        ("support_probability", e.support_probability),
        ("com_shift", e.com_shift),
        ("description", e.description),
    ):
        if value is None:
            guessed.add(name)
    size = tuple(float(v) for v in mesh.extents)
    friction = sorted(e.friction or (defaults.friction if defaults else (0.4, 0.8)))
    com_fraction = defaults.com_shift if defaults else 0.05
    com = np.asarray(mesh.center_mass if watertight else mesh.centroid, dtype=float)
    if not np.isfinite(com).all():
        com = np.asarray(mesh.centroid, dtype=float)
    if not pose.rests:
        collision, depth = flattened_base(collision, com, size[2])
        log.warning(
            "%s: rests in no pose (it rolls or tips); collision pressed %.1f mm flat where it lies", path, depth * 1e3
        )
    visual, part_faces, rgba = coloured_parts(mesh, colours, e.rgba)
    try:
        return Asset(
            id=ident,
            category=category,
            kind=e.kind or category,
            description=e.description or f"a {category}",
            size=size,  # type: ignore[arg-type]
            visual=visual,
            collision=collision,
            mass=mass,
            mass_range=mass_range,
            friction_range=(float(friction[0]), float(friction[1])),
            com=tuple(float(v) for v in com),  # type: ignore[arg-type]
            com_shift_range=e.com_shift or tuple(com_fraction * s for s in size),  # type: ignore[arg-type]
            support_probability=e.support_probability
            if e.support_probability is not None
            else (defaults.support_probability if defaults else 0.5),
            has_front=defaults.has_front if defaults else True,
            cavity=cavity,
            rgba=rgba,
            part_faces=part_faces,
            tags=tuple(e.tags),
            synonyms=tuple(e.synonyms),
            guessed=frozenset(guessed),
            source=str(path),
            pose=pose.up + (f" (also rests {' or '.join(pose.also)} up: give 'up' to choose)" if pose.also else ""),
            rests=pose.rests,
        )
    except ValueError as exc:
        raise AssetError(str(exc)) from None
