"""PhyScensis: dense, physically valid 3D scenes from a sentence or a predicate program."""

from __future__ import annotations

import os

# Headless rendering: MuJoCo picks its GL backend when first imported, so choose EGL before that.
if not os.environ.get("DISPLAY") and not os.environ.get("MUJOCO_GL"):
    os.environ["MUJOCO_GL"] = "egl"
    os.environ.setdefault("PYOPENGL_PLATFORM", "egl")

from physcensis.errors import PhyscensisError, ProgramParseError, SceneFormatError
from physcensis.scene import Scene, load_scene, save_scene

__version__ = "0.1.0"


def generate(prompt: str, **kwargs):  # type: ignore[no-untyped-def]
    """A scene from a sentence; see `physcensis.api.generate`."""
    from physcensis.api import generate as _generate

    return _generate(prompt, **kwargs)


def solve(program, **kwargs):  # type: ignore[no-untyped-def]
    """A scene from a predicate program; see `physcensis.api.solve`."""
    from physcensis.api import solve as _solve

    return _solve(program, **kwargs)

__all__ = [
    "PhyscensisError",
    "ProgramParseError",
    "Scene",
    "SceneFormatError",
    "generate",
    "load_scene",
    "save_scene",
    "solve",
]
