"""PhyScensis: dense, physically valid 3D scenes from a sentence or a predicate program."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any

# Headless rendering: MuJoCo picks its GL backend when first imported, so choose EGL before that.
if not os.environ.get("DISPLAY") and not os.environ.get("MUJOCO_GL"):
    os.environ["MUJOCO_GL"] = "egl"
    os.environ.setdefault("PYOPENGL_PLATFORM", "egl")

from physcensis.errors import PhyscensisError, ProgramParseError, SceneFormatError
from physcensis.scene import Scene, load_scene, save_scene

if TYPE_CHECKING:
    from physcensis.api import Generated
    from physcensis.solver.pipeline import Solution

__version__ = "0.1.0"


# The solvers live in `physcensis.solver`, so no subpackage shadows these names once it is imported.
def generate(prompt: str, **kwargs: Any) -> Generated:
    """A scene from a sentence; see `physcensis.api.generate`."""
    from physcensis.api import generate as generate_scene

    return generate_scene(prompt, **kwargs)


def solve(program: Any, **kwargs: Any) -> Solution:
    """A scene from a predicate program (text, JSON data, a Path or a Program); see `physcensis.api.solve`."""
    from physcensis.api import solve as solve_program

    return solve_program(program, **kwargs)


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
