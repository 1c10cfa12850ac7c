"""PhyScensis: dense, physically valid 3D scenes from a sentence or a predicate program."""

from __future__ import annotations

import os
import types
from typing import TYPE_CHECKING, Any

# Headless rendering: MuJoCo picks its GL backend when first imported, so choose EGL before that.
if not os.environ.get("DISPLAY") and not os.environ.get("MUJOCO_GL"):
    os.environ["MUJOCO_GL"] = "egl"
    os.environ.setdefault("PYOPENGL_PLATFORM", "egl")

import physcensis.solve as _solve_subpackage
from physcensis.errors import PhyscensisError, ProgramParseError, SceneFormatError
from physcensis.scene import Scene, load_scene, save_scene

if TYPE_CHECKING:
    from physcensis.api import Generated
    from physcensis.api import solve as solve  # what type checkers see: the function the solve subpackage acts as
    from physcensis.solve.pipeline import Solution

__version__ = "0.1.0"


def generate(prompt: str, **kwargs: Any) -> Generated:
    """A scene from a sentence; see `physcensis.api.generate`."""
    from physcensis.api import generate as generate_scene

    return generate_scene(prompt, **kwargs)


class _SolvePackage(types.ModuleType):
    """`physcensis.solve` names both the public function and the subpackage of the solvers, and the import system
    binds a subpackage to its parent's attribute when it is first imported (importing `physcensis.api` replaced a
    function of that name with the module). So the two are one object: the subpackage, callable as the function.
    `physcensis.solve(...)`, `physcensis.solve.pipeline` and `import physcensis.solve.pipeline as p` all work,
    whatever was imported first."""

    def __call__(self, program: Any, **kwargs: Any) -> Solution:
        """A scene from a predicate program (text, JSON data, a Path or a Program); see `physcensis.api.solve`."""
        from physcensis.api import solve as solve_program

        return solve_program(program, **kwargs)


_solve_subpackage.__class__ = _SolvePackage

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
