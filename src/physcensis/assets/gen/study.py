"""Built-in categories: see the module's CATEGORIES table."""

from __future__ import annotations

from physcensis.assets.spec import CategoryDef

CATEGORIES: tuple[CategoryDef, ...] = ()
