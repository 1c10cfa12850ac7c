"""The scene file: a versioned JSON document of a solved scene (`physcensis.scene/1`).

A Scene is plain data. Solvers, engines and exporters read and write it; none of
their behaviour lives here.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Iterator
from pathlib import Path
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    ValidationError,
    ValidationInfo,
    field_validator,
    model_validator,
)

from physcensis.bounded_json import shape_problem
from physcensis.errors import SceneFormatError
from physcensis.fileio import BoundError, atomic_write_text, read_in_folder
from physcensis.ids import ID_RULE, RESERVED_IDS, is_reserved_id, is_valid_id

SCENE_FORMAT = "physcensis.scene/1"
SupportKind = Literal["table", "shelf", "floor", "box"]
SUPPORT_KINDS: tuple[str, ...] = ("table", "shelf", "floor", "box")

# Height of the support's top above the floor when a scene does not say.
DEFAULT_SUPPORT_HEIGHT: dict[str, float] = {"table": 0.75, "shelf": 0.80, "floor": 0.0, "box": 0.02}
QUATERNION_TOLERANCE = 1e-3

# Bounds on what a scene may hold: beyond them no engine gives a usable answer (or the search runs out of memory).
MIN_MASS_KG = 1e-9  # MuJoCo cannot compile a moving body this light
MAX_MASS_KG = 1e4
MAX_FRICTION = 10.0
MAX_COORDINATE_M = 1e3  # |x|, |y|, |z| of an object's position
MAX_COM_OFFSET_M = 10.0  # |x|, |y|, |z| of a centre of mass in its object's frame
MAX_SUPPORT_SIDE_M = 50.0
MAX_SUPPORT_HEIGHT_M = 10.0
MIN_SUPPORT_HEIGHT_M = {"table": 0.05, "box": 0.01}  # a 3 cm table top on legs, a 1 cm box floor
MAX_SEED = 2**63
MAX_SCENE_OBJECTS = 10_000
MAX_TEXT_CHARS = 10_000  # description, asset, category, reason
MAX_PROMPT_CHARS = 100_000
# Limits on the file itself, checked before it is parsed.
MAX_SCENE_BYTES = 32 * 1024 * 1024
MAX_NESTING = 64  # brackets deep; a scene needs about 8
MAX_INT_DIGITS = 40


def _plain_number(value: Any) -> Any:
    """Numbers only: pydantic would otherwise read "1.0" and true as numbers."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise ValueError(f"must be a number, not {_kind_of(value)}")
    try:
        number = float(value)
    except OverflowError:
        raise ValueError("is too large to be a number of a scene") from None
    if not math.isfinite(number):
        raise ValueError(f"{number} is not allowed: every number in a scene must be finite")
    return number


def _plain_integer(value: Any) -> Any:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise ValueError(f"must be an integer, not {_kind_of(value)}")
    return int(value)


def _kind_of(value: Any) -> str:
    names = {str: "a string", bool: "a boolean", list: "a list", tuple: "a list", dict: "an object", type(None): "null"}
    return names.get(type(value), type(value).__name__)


Number = Annotated[float, BeforeValidator(_plain_number)]
Integer = Annotated[int, BeforeValidator(_plain_integer)]
Vec3 = tuple[Number, Number, Number]
Quaternion = tuple[Number, Number, Number, Number]


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", allow_inf_nan=False, frozen=False)


class Support(_Strict):
    """The surface objects stand on ("root"): its top is centred on x = y = 0."""

    kind: SupportKind = "table"
    size: tuple[Number, Number] = Field(description="[x extent, y extent] of the top, metres")
    height: Number | None = Field(default=None, description="height of the top above the floor")

    @field_validator("size")
    @classmethod
    def _sane_size(cls, value: tuple[float, float]) -> tuple[float, float]:
        for extent in value:
            if not 0.0 < extent <= MAX_SUPPORT_SIDE_M:
                raise ValueError(
                    f"{extent:g} m is not a usable extent: both extents must be in (0, {MAX_SUPPORT_SIDE_M:g}] metres"
                )
        return value

    @field_validator("height")
    @classmethod
    def _height_range(cls, value: float | None) -> float | None:
        if value is not None and not 0.0 <= value <= MAX_SUPPORT_HEIGHT_M:
            raise ValueError(f"{value:g} m is not a usable height: it must be in [0, {MAX_SUPPORT_HEIGHT_M:g}] metres")
        return value

    @model_validator(mode="after")
    def _tall_enough_to_build(self) -> Support:
        lowest = MIN_SUPPORT_HEIGHT_M.get(self.kind, 0.0)
        if self.height is not None and self.height < lowest:
            raise ValueError(
                f"a {self.kind} top {self.height:g} m high cannot be built (its top or floor slab is "
                f"thicker): give a height of at least {lowest:g} m"
            )
        return self

    @classmethod
    def parse(cls, text: str) -> Support:
        """Read the command-line form `table:0.7x1.4` (kind:x_extent x y_extent[@height])."""
        kind, sep, rest = text.strip().partition(":")
        if not sep or kind not in SUPPORT_KINDS:
            raise ValueError(f"support {text!r} must look like table:1.2x0.8 (kinds: {', '.join(SUPPORT_KINDS)})")
        dims, _, height = rest.partition("@")
        parts = dims.lower().split("x")
        try:
            size = tuple(float(p) for p in parts)
            top = float(height) if height else None
        except ValueError:
            raise ValueError(f"support {text!r}: sizes must be numbers in metres, e.g. {kind}:1.2x0.8") from None
        if not all(math.isfinite(v) for v in (*size, 0.0 if top is None else top)):
            raise ValueError(f"support {text!r}: sizes must be finite numbers in metres, e.g. {kind}:1.2x0.8")
        if len(size) != 2:
            raise ValueError(f"support {text!r}: give two extents, x by y, e.g. {kind}:1.2x0.8")
        try:
            return cls(kind=kind, size=size, height=top)  # type: ignore[arg-type]
        except ValidationError as exc:
            raise ValueError(f"support {text!r}: {exc.errors()[0]['msg'].removeprefix('Value error, ')}") from None

    @property
    def top_height(self) -> float:
        return DEFAULT_SUPPORT_HEIGHT[self.kind] if self.height is None else self.height

    @property
    def half_extents(self) -> tuple[float, float]:
        return self.size[0] / 2.0, self.size[1] / 2.0


Text = Annotated[str, Field(max_length=MAX_TEXT_CHARS)]


class Placement(_Strict):
    """Which predicate put the object where it is, and on what."""

    predicate: Text
    target: Text | None = None


def _each_within(value: Vec3, limit: float, complaint: str) -> Vec3:
    for axis, coordinate in zip("xyz", value, strict=True):
        if abs(coordinate) > limit:
            raise ValueError(f"{axis} = {coordinate:g} {complaint} ±{limit:g} m)")
    return value


class PlacedObject(_Strict):
    id: str
    description: Text
    asset: Text
    category: Text
    position: Vec3 = Field(description="asset origin (base centre) in world, metres")
    quaternion: Quaternion = Field(default=(1.0, 0.0, 0.0, 0.0), description="[w, x, y, z]")
    mass: Number = Field(description="kg")
    friction: Number
    com: Vec3 = Field(default=(0.0, 0.0, 0.0), description="centre of mass in the object frame")
    placement: Placement | None = None
    status: Literal["placed", "failed"] = "placed"
    reason: Text | None = None

    @field_validator("mass")
    @classmethod
    def _usable_mass(cls, value: float) -> float:
        if not MIN_MASS_KG < value <= MAX_MASS_KG:
            raise ValueError(
                f"{value:g} kg is not a usable mass (must be > {MIN_MASS_KG:g} kg and at most {MAX_MASS_KG:g} kg)"
            )
        return value

    @field_validator("friction")
    @classmethod
    def _usable_friction(cls, value: float) -> float:
        if not 0.0 <= value <= MAX_FRICTION:
            raise ValueError(f"{value:g} is not a usable friction coefficient (must be in [0, {MAX_FRICTION:g}])")
        return value

    @field_validator("position")
    @classmethod
    def _inside_any_scene(cls, value: Vec3) -> Vec3:
        return _each_within(value, MAX_COORDINATE_M, "m is far outside any scene (each coordinate must be within")

    @field_validator("com")
    @classmethod
    def _com_near_object(cls, value: Vec3) -> Vec3:
        return _each_within(
            value, MAX_COM_OFFSET_M, "m puts the centre of mass far outside the object (each coordinate must be within"
        )

    @field_validator("id")
    @classmethod
    def _valid_id(cls, value: str) -> str:
        if not is_valid_id(value):
            raise ValueError(f"{value!r} is not a valid id ({ID_RULE})")
        if is_reserved_id(value):
            raise ValueError(f"{value!r} is reserved for the scene's own parts ({', '.join(RESERVED_IDS)})")
        return value

    @field_validator("quaternion")
    @classmethod
    def _unit_quaternion(cls, value: Quaternion) -> Quaternion:
        norm = math.sqrt(sum(c * c for c in value))
        if abs(norm - 1.0) > QUATERNION_TOLERANCE:
            raise ValueError(f"must be a unit quaternion [w, x, y, z], its norm is {norm:.6g}")
        return value

    @model_validator(mode="after")
    def _failed_has_reason(self) -> PlacedObject:
        if self.status == "failed" and not self.reason:
            raise ValueError("a failed object must carry a reason")
        return self


class AssetCopy(_Strict):
    """Where a library asset the scene uses came from, and its copy in the scene folder (`assets/<id>.npz`), so the
    scene renders, exports and simulates on a machine without the library."""

    file: Text = Field(description="the copy, relative to the scene folder: assets/<id>.npz")
    sha256: Annotated[str, Field(pattern=r"^[0-9a-f]{64}$")] = Field(description="hash of the copy")
    source: Text | None = Field(default=None, description="the mesh file the library imported")
    source_sha256: Annotated[str, Field(pattern=r"^[0-9a-f]{64}$")] | None = None


class Scene(_Strict):
    format: Literal["physcensis.scene/1"] = "physcensis.scene/1"
    seed: Integer = Field(default=0, gt=-MAX_SEED, lt=MAX_SEED)
    prompt: Annotated[str, Field(max_length=MAX_PROMPT_CHARS)] | None = None
    support: Support
    objects: list[PlacedObject] = Field(default_factory=list, max_length=MAX_SCENE_OBJECTS)
    program: list[Any] = Field(default_factory=list)
    metrics: dict[str, Any] = Field(default_factory=dict)
    assets: dict[str, AssetCopy] = Field(default_factory=dict, max_length=MAX_SCENE_OBJECTS)

    @field_validator("assets")
    @classmethod
    def _copies_in_assets_folder(cls, value: dict[str, AssetCopy]) -> dict[str, AssetCopy]:
        for asset_id, copy in value.items():
            if not is_valid_id(asset_id) or copy.file != f"assets/{asset_id}.npz":
                raise ValueError(f"assets: {asset_id!r} must be an asset id whose copy is assets/<id>.npz")
        return value

    @model_validator(mode="after")
    def _unique_ids(self) -> Scene:
        seen: set[str] = set()
        for index, obj in enumerate(self.objects):
            if obj.id in seen:
                raise ValueError(f"objects[{index}].id: duplicate object id {obj.id!r}")
            seen.add(obj.id)
        return self

    @field_validator("program", "metrics")
    @classmethod
    def _plain_json(cls, value: Any, info: ValidationInfo) -> Any:
        if info.context and info.context.get("checked"):  # scene_from_data looked at the whole document already
            return value
        problem = first_unusable_value(value, (str(info.field_name),))
        if problem:
            raise ValueError(problem)
        return value

    def object(self, object_id: str) -> PlacedObject:
        for obj in self.objects:
            if obj.id == object_id:
                return obj
        raise KeyError(object_id)

    @property
    def placed(self) -> list[PlacedObject]:
        return [o for o in self.objects if o.status == "placed"]

    def to_json(self) -> str:
        return json.dumps(self.model_dump(mode="json"), indent=2, allow_nan=False) + "\n"


class _HugeInteger:
    """What the JSON reader makes of an integer too long to be a number of a scene (reported with its field)."""

    def __init__(self, digits: int) -> None:
        self.digits = digits


def _parse_int(text: str) -> int | _HugeInteger:
    digits = len(text.lstrip("-"))
    return int(text) if digits <= MAX_INT_DIGITS else _HugeInteger(digits)


def _reject_constant(name: str) -> float:
    raise SceneFormatError(f"{name} is not allowed: every number in a scene must be finite")


def first_unusable_value(value: Any, where: tuple[int | str, ...] = ()) -> str | None:
    """The first thing in JSON-like data that no scene may hold, as `path: problem`: a non-finite number, an
    integer of absurd length, a string that cannot be written as UTF-8, nesting deeper than MAX_NESTING."""
    found = _find_unusable(value, where)
    return f"{_path_text(found[0])}: {found[1]}" if found else None


def _find_unusable(value: Any, where: tuple[int | str, ...] = ()) -> tuple[tuple[int | str, ...], str] | None:
    """Where the first unusable thing is, and what is wrong with it. Iterative, keeping one iterator per open level
    (not a path per node), so any depth or breadth of input is safe."""
    if not isinstance(value, (dict, list, tuple)):
        problem = _unusable_scalar(value)
        return (where, problem) if problem else None
    path: list[int | str] = list(where)
    levels: list[Iterator[tuple[Any, Any]]] = [_children(value)]
    while levels:
        step = next(levels[-1], None)
        if step is None:
            levels.pop()
            if len(path) > len(where):
                path.pop()
            continue
        key, child = step
        if isinstance(key, str) and not _encodable(key):
            return tuple(path), "a key is not valid unicode text (it holds a lone surrogate)"
        if isinstance(child, (dict, list, tuple)):
            if len(path) + 1 >= MAX_NESTING:
                return (*path, key), f"nested more than {MAX_NESTING} levels deep"
            path.append(key)
            levels.append(_children(child))
            continue
        problem = _unusable_scalar(child)
        if problem:
            return (*path, key), problem
    return None


def _children(node: dict | list | tuple) -> Iterator[tuple[Any, Any]]:
    return iter(node.items()) if isinstance(node, dict) else enumerate(node)


def _unusable_scalar(item: Any) -> str | None:
    if isinstance(item, str):
        return None if _encodable(item) else "not valid unicode text (it holds a lone surrogate)"
    if isinstance(item, float) and not math.isfinite(item):
        return f"{item} is not a finite number"
    if isinstance(item, _HugeInteger):
        return f"an integer of {item.digits} digits is not a usable number"
    return None


def _encodable(text: str) -> bool:
    if text.isascii():
        return True
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        return False
    return True


def _path_text(path: tuple[int | str, ...]) -> str:
    text = ""
    for part in path:
        text += f"[{part}]" if isinstance(part, int) else _key_text(part, first=not text)
    return text or "scene"


_PLAIN_KEY = re.compile(r"[A-Za-z0-9_\-]{1,40}")


def _key_text(key: str, *, first: bool) -> str:
    """A key as part of a one-line path: plain names as `.name`, anything else quoted and shortened."""
    if _PLAIN_KEY.fullmatch(key):
        return key if first else f".{key}"
    return f"[{_short(key)}]"


def _short(value: Any, limit: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _field_path(loc: tuple[int | str, ...], data: Any) -> str:
    """Render a pydantic location as `objects[2] (cup_0).quaternion`."""
    text = ""
    node = data
    for part in loc:
        if isinstance(part, int):
            text += f"[{part}]"
            node = node[part] if isinstance(node, list) and 0 <= part < len(node) else None
            if isinstance(node, dict) and isinstance(node.get("id"), str):
                text += f" ({node['id']})"
        else:
            text += _key_text(str(part), first=not text)
            node = node.get(part) if isinstance(node, dict) else None
    return text or "scene"


def scene_from_data(data: Any, source: str = "scene") -> Scene:
    """Validate parsed JSON as a Scene, raising SceneFormatError naming the bad field."""
    if not isinstance(data, dict):
        raise SceneFormatError(f"{source}: a scene must be a JSON object, got {type(data).__name__}")
    found = _find_unusable(data)
    if found:
        raise SceneFormatError(f"{source}: {_field_path(found[0], data)}: {found[1]}")
    version = data.get("format")
    if version != SCENE_FORMAT:
        raise SceneFormatError(
            f"{source}: unsupported scene format {_short(version)}; this version reads {SCENE_FORMAT!r}"
        )
    try:
        return Scene.model_validate(data, context={"checked": True})
    except ValidationError as exc:
        first = exc.errors()[0]
        where = _field_path(tuple(first["loc"]), data)
        message = first["msg"].removeprefix("Value error, ")
        more = f" (and {exc.error_count() - 1} more problems)" if exc.error_count() > 1 else ""
        raise SceneFormatError(f"{source}: {where}: {message}{more}") from None


def scene_from_json(text: str, source: str = "scene") -> Scene:
    if len(text) > MAX_SCENE_BYTES:
        raise SceneFormatError(
            f"{source}: a scene file may hold at most {MAX_SCENE_BYTES // 2**20} MB, "
            f"this one holds {len(text) / 2**20:.1f} MB"
        )
    problem = shape_problem(text, MAX_NESTING)
    if problem:
        raise SceneFormatError(f"{source}: {problem}")
    try:
        data = json.loads(text, parse_constant=_reject_constant, parse_int=_parse_int)
    except json.JSONDecodeError as exc:
        raise SceneFormatError(f"{source}: not valid JSON ({exc.msg} at line {exc.lineno})") from None
    except SceneFormatError as exc:
        raise SceneFormatError(f"{source}: {exc}") from None
    except (ValueError, RecursionError) as exc:  # what the depth and digit checks should already have caught
        raise SceneFormatError(f"{source}: not a readable JSON document ({exc.__class__.__name__})") from None
    return scene_from_data(data, source)


def load_scene(path: str | Path) -> Scene:
    """A scene file, or a scene folder's scene.json: a file that comes with a folder is read as `read_in_folder`
    reads it (no link, a regular file), as the folder may come from anyone."""
    path = Path(path)
    if path.is_dir():
        return _load_folder_scene(path)
    if path.exists() and not path.is_file():
        raise SceneFormatError(f"{path}: cannot read scene file (not a regular file)")
    try:
        with path.open("rb") as handle:
            raw = handle.read(MAX_SCENE_BYTES + 1)
        if len(raw) > MAX_SCENE_BYTES:
            raise SceneFormatError(
                f"{path}: a scene file may hold at most {MAX_SCENE_BYTES // 2**20} MB, this one is larger"
            )
        text = raw.decode("utf-8-sig")  # editors on Windows start UTF-8 files with a byte-order mark
    except (OSError, UnicodeDecodeError) as exc:
        raise SceneFormatError(f"{path}: cannot read scene file ({exc.__class__.__name__}: {exc})") from None
    return scene_from_json(text, str(path))


def _load_folder_scene(folder: Path) -> Scene:
    path = folder / "scene.json"
    try:
        text = read_in_folder(folder, "scene.json", MAX_SCENE_BYTES, str(path)).decode("utf-8-sig")
    except BoundError as exc:
        raise SceneFormatError(f"cannot read scene file: {exc}") from None
    except UnicodeDecodeError as exc:
        raise SceneFormatError(f"{path}: cannot read scene file ({exc.__class__.__name__}: {exc})") from None
    return scene_from_json(text, str(path))


def save_scene(scene: Scene, path: str | Path) -> Path:
    """Write the scene atomically: readers never see a half-written file."""
    path = Path(path)
    atomic_write_text(path, scene.to_json())
    return path
