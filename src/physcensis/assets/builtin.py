"""The built-in procedural catalogue: every category definition, in one table."""

from __future__ import annotations

from functools import lru_cache

from physcensis.assets.gen import (
    bathroom,
    bottles,
    boxes,
    household,
    kitchen,
    office,
    organic,
    study,
    tableware,
    toys,
    utensils,
    workshop,
)
from physcensis.assets.spec import CategoryDef

CATEGORY_DEFS: tuple[CategoryDef, ...] = (
    *tableware.CATEGORIES,
    *bottles.CATEGORIES,
    *boxes.CATEGORIES,
    *household.CATEGORIES,
    *office.CATEGORIES,
    *utensils.CATEGORIES,
    *organic.CATEGORIES,
    *toys.CATEGORIES,
    *kitchen.CATEGORIES,
    *study.CATEGORIES,
    *bathroom.CATEGORIES,
    *workshop.CATEGORIES,
)


@lru_cache(maxsize=1)
def category_defaults() -> dict[str, CategoryDef]:
    """The first definition of each category (and each kind): defaults for imported assets."""
    table: dict[str, CategoryDef] = {}
    for cat in CATEGORY_DEFS:
        table.setdefault(cat.kind, cat)
        table.setdefault(cat.category, cat)
    return table
