"""The scene file: a versioned JSON document of a solved scene (`physcensis.scene/1`).

A Scene is plain data. Solvers, engines and exporters read and write it; none of
their behaviour lives here.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

from physcensis.errors import SceneFormatError
from physcensis.fileio import atomic_write_text
from physcensis.ids import ID_RULE, RESERVED_IDS, is_reserved_id, is_valid_id

SCENE_FORMAT = "physcensis.scene/1"
SupportKind = Literal["table", "shelf", "floor", "box"]
SUPPORT_KINDS: tuple[str, ...] = ("table", "shelf", "floor", "box")

# Height of the support's top above the floor when a scene does not say.
DEFAULT_SUPPORT_HEIGHT: dict[str, float] = {"table": 0.75, "shelf": 0.80, "floor": 0.0, "box": 0.02}
QUATERNION_TOLERANCE = 1e-3

Vec3 = tuple[float, float, float]
Quaternion = tuple[float, float, float, float]


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", allow_inf_nan=False, frozen=False)


class Support(_Strict):
    """The surface objects stand on ("root"): its top is centred on x = y = 0."""

    kind: SupportKind = "table"
    size: tuple[float, float] = Field(description="[x extent, y extent] of the top, metres")
    height: float | None = Field(default=None, description="height of the top above the floor")

    @field_validator("size")
    @classmethod
    def _positive_size(cls, value: tuple[float, float]) -> tuple[float, float]:
        if not all(0.0 < v <= 100.0 for v in value):
            raise ValueError("both extents must be in (0, 100] metres")
        return value

    @field_validator("height")
    @classmethod
    def _height_range(cls, value: float | None) -> float | None:
        if value is not None and not 0.0 <= value <= 10.0:
            raise ValueError("must be in [0, 10] metres")
        return value

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


class Placement(_Strict):
    """Which predicate put the object where it is, and on what."""

    predicate: str
    target: str | None = None


class PlacedObject(_Strict):
    id: str
    description: str
    asset: str
    category: str
    position: Vec3 = Field(description="asset origin (base centre) in world, metres")
    quaternion: Quaternion = Field(default=(1.0, 0.0, 0.0, 0.0), description="[w, x, y, z]")
    mass: float = Field(gt=0.0, description="kg")
    friction: float = Field(ge=0.0, le=10.0)
    com: Vec3 = Field(default=(0.0, 0.0, 0.0), description="centre of mass in the object frame")
    placement: Placement | None = None
    status: Literal["placed", "failed"] = "placed"
    reason: str | None = None

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


class Scene(_Strict):
    format: Literal["physcensis.scene/1"] = "physcensis.scene/1"
    seed: int = 0
    prompt: str | None = None
    support: Support
    objects: list[PlacedObject] = Field(default_factory=list)
    program: list[Any] = Field(default_factory=list)
    metrics: dict[str, Any] = Field(default_factory=dict)

    @model_validator(mode="after")
    def _unique_ids(self) -> Scene:
        seen: set[str] = set()
        for index, obj in enumerate(self.objects):
            if obj.id in seen:
                raise ValueError(f"objects[{index}].id: duplicate object id {obj.id!r}")
            seen.add(obj.id)
        return self

    @field_validator("metrics")
    @classmethod
    def _finite_metrics(cls, value: dict[str, Any]) -> dict[str, Any]:
        bad = _first_non_finite(value, "metrics")
        if bad:
            raise ValueError(f"{bad} is not a finite number")
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


def _first_non_finite(value: Any, path: str) -> str | None:
    if isinstance(value, float) and not math.isfinite(value):
        return path
    if isinstance(value, dict):
        for key, item in value.items():
            found = _first_non_finite(item, f"{path}.{key}")
            if found:
                return found
    if isinstance(value, (list, tuple)):
        for i, item in enumerate(value):
            found = _first_non_finite(item, f"{path}[{i}]")
            if found:
                return found
    return None


def _reject_constant(name: str) -> float:
    raise SceneFormatError(f"{name} is not allowed: every number in a scene must be finite")


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
            text += f".{part}" if text else str(part)
            node = node.get(part) if isinstance(node, dict) else None
    return text or "scene"


def scene_from_data(data: Any, source: str = "scene") -> Scene:
    """Validate parsed JSON as a Scene, raising SceneFormatError naming the bad field."""
    if not isinstance(data, dict):
        raise SceneFormatError(f"{source}: a scene must be a JSON object, got {type(data).__name__}")
    version = data.get("format")
    if version != SCENE_FORMAT:
        raise SceneFormatError(
            f"{source}: unsupported scene format {version!r}; this version reads {SCENE_FORMAT!r}"
        )
    try:
        return Scene.model_validate(data)
    except ValidationError as exc:
        first = exc.errors()[0]
        where = _field_path(tuple(first["loc"]), data)
        message = first["msg"].removeprefix("Value error, ")
        more = f" (and {exc.error_count() - 1} more problems)" if exc.error_count() > 1 else ""
        raise SceneFormatError(f"{source}: {where}: {message}{more}") from None


def scene_from_json(text: str, source: str = "scene") -> Scene:
    try:
        data = json.loads(text, parse_constant=_reject_constant)
    except json.JSONDecodeError as exc:
        raise SceneFormatError(f"{source}: not valid JSON ({exc.msg} at line {exc.lineno})") from None
    except SceneFormatError as exc:
        raise SceneFormatError(f"{source}: {exc}") from None
    return scene_from_data(data, source)


def load_scene(path: str | Path) -> Scene:
    path = Path(path)
    if path.is_dir():
        path = path / "scene.json"
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise SceneFormatError(f"{path}: cannot read scene file ({exc.__class__.__name__}: {exc})") from None
    return scene_from_json(text, str(path))


def save_scene(scene: Scene, path: str | Path) -> Path:
    """Write the scene atomically: readers never see a half-written file."""
    path = Path(path)
    atomic_write_text(path, scene.to_json())
    return path
