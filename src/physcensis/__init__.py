"""PhyScensis: dense, physically valid 3D scenes from a sentence or a predicate program."""

from __future__ import annotations

import os
from importlib import import_module
from typing import TYPE_CHECKING, Any

# Headless rendering: MuJoCo picks its GL backend when first imported, so choose EGL before that.
if not os.environ.get("DISPLAY") and not os.environ.get("MUJOCO_GL"):
    os.environ["MUJOCO_GL"] = "egl"
    os.environ.setdefault("PYOPENGL_PLATFORM", "egl")

from physcensis.errors import PhyscensisError, ProgramParseError, SceneFormatError
from physcensis.scene import Scene, load_scene, save_scene

if TYPE_CHECKING:
    from physcensis.api import generate
    from physcensis.solver.pipeline import solve

__version__ = "0.1.0"

# `generate` and `solve` are the real functions, loaded on first use: `import physcensis` stays light (no MuJoCo),
# and help(), inspect.signature and type checkers see their own signatures and docstrings, not a forwarding wrapper.
# The solvers live in `physcensis.solver`, so no subpackage shadows these names once it is imported.
_LAZY_FUNCTIONS = {"generate": "physcensis.api", "solve": "physcensis.solver.pipeline"}


if not TYPE_CHECKING:  # hidden from type checkers, which see the imports above and still flag a misspelt name

    def __getattr__(name: str) -> Any:
        if name not in _LAZY_FUNCTIONS:
            raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
        function = getattr(import_module(_LAZY_FUNCTIONS[name]), name)
        globals()[name] = function  # later look-ups find it directly
        return function

    def __dir__() -> list[str]:
        return sorted({*globals(), *_LAZY_FUNCTIONS})


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
