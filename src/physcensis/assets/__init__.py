"""Assets: the data model, the built-in procedural catalogue, user libraries and retrieval.

from physcensis.assets import default_catalogue
mug = default_catalogue().resolve("a white ceramic mug")
"""

from __future__ import annotations

from physcensis.assets.catalogue import Catalogue, Entry, default_catalogue
from physcensis.assets.errors import AssetError
from physcensis.assets.library import LibraryResult, load_library
from physcensis.assets.model import Asset, Cavity, CollisionPart
from physcensis.assets.supports import support_asset

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
