"""The learner's heavy dependencies, loaded on demand: torch and robomimic 0.3.0 (BC), behind the `policy` extra.

robomimic imports torchvision when its models load, but uses it only for image encoders; PyPI's torchvision does not
load beside the CPU torch this extra pins. The policies here see low-dimensional observations only, so when
torchvision cannot be imported a stand-in module takes its place whose every attribute raises a clear error if used.
"""

from __future__ import annotations

import importlib
import sys
import types
from typing import Any

from physcensis.errors import PhyscensisError

INSTALL = "pip install 'physcensis[policy]' && pip install --no-deps robomimic==0.3.0"
_TORCHVISION = ("torchvision", "torchvision.transforms", "torchvision.transforms.functional", "torchvision.models")


class PolicyError(PhyscensisError):
    """A policy cannot be trained or evaluated: missing learner, a dataset or checkpoint that is not one."""


class MissingLearnerError(PolicyError):
    """torch or robomimic is not installed."""


def load_learner() -> None:
    """Make `import robomimic...` work for low-dimensional BC, or raise MissingLearnerError naming the install."""
    for name in ("torch", "robomimic"):
        try:
            importlib.import_module(name)
        except ImportError:
            raise MissingLearnerError(f"policy training and evaluation need {name}: {INSTALL}") from None
    _quiet_robomimic_macros()
    _stand_in_for_torchvision()


def _quiet_robomimic_macros() -> None:
    """robomimic warns at every import that it has no private macro file; an empty one says there is nothing to add."""
    sys.modules.setdefault("robomimic.macros_private", types.ModuleType("robomimic.macros_private"))


def _stand_in_for_torchvision() -> None:
    if "torchvision" in sys.modules:
        return
    try:
        importlib.import_module("torchvision")
        return
    except Exception:  # missing, or built for another torch (it then fails with all kinds of errors)
        sys.modules.pop("torchvision", None)
    modules = {name: _unusable_module(name) for name in _TORCHVISION}
    for name, module in modules.items():
        parent, _, child = name.rpartition(".")
        if parent:
            setattr(modules[parent], child, module)
        sys.modules[name] = module


def _unusable_module(name: str) -> types.ModuleType:
    module = types.ModuleType(name)
    module.__path__ = []  # a package, so that `import torchvision.models` finds its stand-in too

    def __getattr__(attribute: str) -> Any:
        if attribute.startswith("__"):
            raise AttributeError(attribute)

        def unusable(*args: Any, **kwargs: Any) -> Any:
            raise PolicyError(
                f"{name}.{attribute} is not available: torchvision is not installed, and physcensis policies "
                "use low-dimensional observations only"
            )

        return unusable

    module.__getattr__ = __getattr__  # type: ignore[method-assign]
    return module
