"""PhyScensis: dense, physically valid 3D scenes from a sentence or a predicate program."""

from __future__ import annotations

from physcensis.errors import PhyscensisError, ProgramParseError, SceneFormatError
from physcensis.scene import Scene, load_scene, save_scene

__version__ = "0.1.0"

__all__ = [
    "PhyscensisError",
    "ProgramParseError",
    "Scene",
    "SceneFormatError",
    "load_scene",
    "save_scene",
]
