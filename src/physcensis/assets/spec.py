"""Declarative description of built-in asset categories and their variants.

A category names what the benchmark matches (`category`), what the object is
(`kind`), its words (synonyms, tags), a generator, and its physical defaults.
Each variant gives the overall real-world size (x, y, z extents, metres) and
colours; the generator fits its shape into exactly that size.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import trimesh

from physcensis.assets.model import RGBA, Cavity, CollisionPart, Vec3


@dataclass(frozen=True)
class Geometry:
    """What a generator returns: coloured visual parts, convex collision parts, an optional cavity."""

    parts: tuple[tuple[trimesh.Trimesh, RGBA], ...]
    collision: tuple[CollisionPart, ...]
    cavity: Cavity | None = None


@dataclass(frozen=True)
class Variant:
    name: str  # id suffix: the asset id is f"{category_def.prefix}_{name}" unless `asset_id` is set
    description: str
    size: Vec3
    colors: tuple[RGBA, ...] = ()
    options: Mapping[str, Any] = field(default_factory=lambda: MappingProxyType({}))
    tags: tuple[str, ...] = ()
    synonyms: tuple[str, ...] = ()
    density: float | None = None  # kg/m^3 of the visual solid, overrides the category's
    mass: float | None = None  # kg, a published mass that overrides density x volume
    asset_id: str | None = None

    def opt(self, key: str, default: Any) -> Any:
        return self.options.get(key, default)

    def color(self, index: int, default: RGBA) -> RGBA:
        return self.colors[index] if index < len(self.colors) else default


Builder = Callable[[Variant], Geometry]


@dataclass(frozen=True)
class CategoryDef:
    category: str  # what scene benchmarks match
    kind: str  # the specific object type
    build: Builder
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

    @property
    def id_prefix(self) -> str:
        return self.prefix or self.kind.replace(" ", "_")


def define(category: str, kind: str, build: Builder, variants: list[Variant], **kw: Any) -> CategoryDef:
    """A CategoryDef from a variant list (keeps the generator modules' tables short)."""
    return CategoryDef(category=category, kind=kind, build=build, variants=tuple(variants), **kw)
