"""Assets: the data model, the built-in procedural catalogue, user libraries and retrieval.

from physcensis.assets import default_catalogue
mug = default_catalogue().resolve("a white ceramic mug")

The names below are loaded on first use: importing a light module of this package (`physcensis.assets.errors`,
say) does not build the catalogue's machinery, which takes seconds (trimesh, SciPy).
"""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from physcensis.assets.catalogue import Catalogue, Entry, default_catalogue
    from physcensis.assets.errors import AssetError
    from physcensis.assets.library import LibraryResult, load_library
    from physcensis.assets.model import Asset, Cavity, CollisionPart
    from physcensis.assets.supports import support_asset

_LAZY = {
    "Asset": "physcensis.assets.model",
    "AssetError": "physcensis.assets.errors",
    "Catalogue": "physcensis.assets.catalogue",
    "Cavity": "physcensis.assets.model",
    "CollisionPart": "physcensis.assets.model",
    "Entry": "physcensis.assets.catalogue",
    "LibraryResult": "physcensis.assets.library",
    "default_catalogue": "physcensis.assets.catalogue",
    "load_library": "physcensis.assets.library",
    "support_asset": "physcensis.assets.supports",
}
__all__ = [
    "Asset",
    "AssetError",
    "Catalogue",
    "Cavity",
    "CollisionPart",
    "Entry",
    "LibraryResult",
    "default_catalogue",
    "load_library",
    "support_asset",
]

if not TYPE_CHECKING:

    def __getattr__(name: str) -> Any:
        if name not in _LAZY:
            raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
        value = getattr(import_module(_LAZY[name]), name)
        globals()[name] = value
        return value

    def __dir__() -> list[str]:
        return sorted({*globals(), *_LAZY})
