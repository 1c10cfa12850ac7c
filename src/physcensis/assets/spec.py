"""Declarative description of built-in asset categories and their variants.

A category names what the benchmark matches (`category`), what the object is
(`kind`), its words (synonyms, tags), a builder, and its physical defaults.
Each variant gives the overall real-world size (x, y, z extents, metres),
colours and options; the builder fits its shape into exactly that size.

A builder is a function registered with the frozen dataclass of its parameters
(`@builder(BottleShape) def bottle(v, p): ...`).  A variant gives parameters as
a compact mapping (`{"neck": 0.3}`); a category checks every variant's options
against its builder's parameters when it is defined, so a misspelt key or a value
of the wrong type fails at import, naming the category, the variant and the key.
The built-in categories and variants are data, one JSON file per generator module
(`gen/data/<module>.json`, read by `gen/variant_data.py`); the modules keep the builders.
"""

from __future__ import annotations

import dataclasses
import difflib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType, UnionType
from typing import Any, Generic, Literal, TypeVar, Union, get_args, get_origin, get_type_hints

import trimesh

from physcensis.assets.errors import AssetError
from physcensis.assets.model import RGBA, Cavity, CollisionPart, Vec3

ParamsT = TypeVar("ParamsT")


class OptionError(AssetError):
    """A variant's options do not fit its builder's parameters (an unknown key, a value of the wrong type)."""


class VariantDataError(AssetError):
    """A variant data file (`gen/data/*.json`) that does not describe categories and variants: a missing or unknown
    field, a bad colour or size, a builder its module does not have."""


Parts = tuple[tuple[trimesh.Trimesh, RGBA], ...]  # visual meshes with their colours


@dataclass(frozen=True)
class Geometry:
    """What a builder returns: coloured visual parts, convex collision parts, an optional cavity."""

    parts: Parts
    collision: tuple[CollisionPart, ...]
    cavity: Cavity | None = None


@dataclass(frozen=True)
class Variant:
    name: str  # id suffix: the asset id is f"{category_def.prefix}_{name}" unless `asset_id` is set
    description: str
    size: Vec3
    colors: tuple[RGBA, ...] = ()
    options: Mapping[str, Any] = field(default_factory=lambda: MappingProxyType({}))  # the builder's parameters
    tags: tuple[str, ...] = ()
    synonyms: tuple[str, ...] = ()
    density: float | None = None  # kg/m^3 of the visual solid, overrides the category's
    mass: float | None = None  # kg, a published mass that overrides density x volume
    asset_id: str | None = None

    def color(self, index: int, default: RGBA) -> RGBA:
        return self.colors[index] if index < len(self.colors) else default


@dataclass(frozen=True)
class NoOptions:
    """The parameters of a builder that takes none."""


@dataclass(frozen=True)
class Builder(Generic[ParamsT]):
    """A builder function and the frozen dataclass of its parameters.

    Calling it with a variant reads the variant's options into `params` and draws;
    `where` names the variant in errors.
    """

    draw: Callable[[Variant, ParamsT], Geometry]
    params: type[ParamsT]

    @property
    def name(self) -> str:
        return self.draw.__name__

    def parse(self, options: Mapping[str, Any], where: str) -> ParamsT:
        """The typed parameters for these options; raises OptionError naming `where` and the bad key."""
        return parse_params(self.params, options, where)

    def __call__(self, variant: Variant, where: str | None = None) -> Geometry:
        return self.draw(variant, self.parse(variant.options, where or f"variant {variant.name!r}"))


def builder(params: type[ParamsT]) -> Callable[[Callable[[Variant, ParamsT], Geometry]], Builder[ParamsT]]:
    """Register a builder with its parameter class: `@builder(BottleShape)` above `def bottle(v, p)`."""
    _check_params_class(params)

    def register(draw: Callable[[Variant, ParamsT], Geometry]) -> Builder[ParamsT]:
        return Builder(draw, params)

    return register


def _check_params_class(params: type) -> None:
    settings = getattr(params, "__dataclass_params__", None)
    if not dataclasses.is_dataclass(params) or settings is None or not settings.frozen:
        raise TypeError(f"{params.__name__}: builder parameters must be a frozen dataclass")
    hints = get_type_hints(params)
    for f in dataclasses.fields(params):
        hint = hints[f.name]
        if f.default is dataclasses.MISSING:
            raise TypeError(f"{params.__name__}.{f.name}: every builder parameter needs a default")
        if not _fits(f.default, hint):
            raise TypeError(f"{params.__name__}.{f.name}: default {f.default!r} is not {_describe(hint)}")


def parse_params(params: type[ParamsT], options: Mapping[str, Any], where: str) -> ParamsT:
    """`params(**options)` with every key and value checked against the dataclass's fields and types."""
    hints = _field_types(params)
    for key, value in options.items():
        if key not in hints:
            raise OptionError(
                f"{where}: unknown option {key!r}{_suggestion(key, hints)}; valid options: {', '.join(hints) or 'none'}"
            )
        if not _fits(value, hints[key]):
            raise OptionError(f"{where}: option {key!r} is {value!r}, expected {_describe(hints[key])}")
    return params(**{key: _as_declared(value, hints[key]) for key, value in options.items()})


_FIELD_TYPES: dict[type, Mapping[str, Any]] = {}


def _field_types(params: type) -> Mapping[str, Any]:
    """The resolved field types of a parameter class, worked out once per class rather than once per variant."""
    hints = _FIELD_TYPES.get(params)
    if hints is None:
        hints = _FIELD_TYPES[params] = MappingProxyType(get_type_hints(params))
    return hints


def _suggestion(key: str, valid: Mapping[str, Any]) -> str:
    close = difflib.get_close_matches(key, list(valid), n=1, cutoff=0.6)
    return f" (did you mean {close[0]!r}?)" if close else ""


def _members(hint: Any) -> tuple[Any, ...]:
    """The alternatives of a union hint (`float | None`), or the hint itself."""
    return get_args(hint) if get_origin(hint) in (Union, UnionType) else (hint,)


def _fits(value: object, hint: Any) -> bool:
    return any(_fits_one(value, member) for member in _members(hint))


def _fits_one(value: object, hint: Any) -> bool:
    if get_origin(hint) is Literal:
        return any(type(value) is type(choice) and value == choice for choice in get_args(hint))
    if hint is float:  # an integer is a number too, a bool is not
        return isinstance(value, int | float) and not isinstance(value, bool)
    if hint is int:
        return isinstance(value, int) and not isinstance(value, bool)
    if hint in (bool, str, type(None)):
        return isinstance(value, hint)
    raise TypeError(f"builder parameter type {hint!r} is not supported (use bool, int, float, str, Literal or | None)")


def _as_declared(value: object, hint: Any) -> object:
    """An integer given for a number field becomes a float, so the dataclass holds what it declares."""
    members = _members(hint)
    if isinstance(value, int) and not isinstance(value, bool) and float in members and int not in members:
        return float(value)
    return value


def _describe(hint: Any) -> str:
    names = {float: "a number", int: "an integer", bool: "True or False", str: "a string", type(None): "None"}
    words = []
    for member in _members(hint):
        if get_origin(member) is Literal:
            words.append("one of " + ", ".join(repr(choice) for choice in get_args(member)))
        else:
            words.append(names.get(member, repr(member)))
    return " or ".join(words)


@dataclass(frozen=True)
class CategoryDef:
    category: str  # what scene benchmarks match
    kind: str  # the specific object type
    build: Builder[Any]
    variants: tuple[Variant, ...]
    density: float  # kg/m^3 of the visual solid (effective: includes contents and hollows)
    mass_limits: tuple[float, float]  # plausible real-world mass of one such object, kg
    friction: tuple[float, float] = (0.4, 0.8)
    support_probability: float = 0.5
    has_front: bool = True
    com_shift: float = 0.05  # max |centre-of-mass shift| as a fraction of the size, per axis
    synonyms: tuple[str, ...] = ()
    tags: tuple[str, ...] = ()
    prefix: str = ""

    def __post_init__(self) -> None:
        if not isinstance(self.build, Builder):
            raise TypeError(f"category {self.category!r} ({self.kind}): build must be a @builder(...) function")
        for variant in self.variants:
            self.build.parse(variant.options, self.where(variant))

    def geometry(self, variant: Variant) -> Geometry:
        """The builder's geometry for one variant (of this category or derived from one)."""
        return self.build(variant, self.where(variant))

    def where(self, variant: Variant) -> str:
        """How errors name one variant of this category."""
        return f"category {self.category!r} ({self.kind}), variant {variant.name!r}"

    @property
    def id_prefix(self) -> str:
        return self.prefix or self.kind.replace(" ", "_")


def define(category: str, kind: str, build: Builder[Any], variants: list[Variant], **kw: Any) -> CategoryDef:
    """A CategoryDef from a variant list (what `variant_data` calls for each category of a data file)."""
    return CategoryDef(category=category, kind=kind, build=build, variants=tuple(variants), **kw)
