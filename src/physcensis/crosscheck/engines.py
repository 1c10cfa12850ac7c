"""The engines that measure the paper's settle distance, one record each: `eval settle --engine`, the cross-check
benchmark and the Python API read them from here, so a new engine is one `register_settle_engine` call.

An engine is built only when asked for (PyBullet and Genesis are optional extras); `make` raises a `PhyscensisError`
naming the extra when the simulator is missing, before any scene is read.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from physcensis.errors import PhyscensisError

if TYPE_CHECKING:
    from physcensis.assets.catalogue import Catalogue
    from physcensis.physics.engine import SettleEngine


@dataclass(frozen=True)
class SettleEngineRecord:
    """One engine: its name on the command line, what it simulates, and how to build it for a catalogue."""

    name: str
    help: str
    make: Callable[[Catalogue | None], SettleEngine]


def _mujoco(profile_name: str) -> Callable[[Catalogue | None], SettleEngine]:
    def make(catalogue: Catalogue | None) -> SettleEngine:
        from physcensis.physics.mujoco_engine import MujocoEngine
        from physcensis.physics.profiles import PROFILES

        return MujocoEngine(catalogue, PROFILES[profile_name])

    return make


def _bullet(catalogue: Catalogue | None) -> SettleEngine:
    from physcensis.crosscheck.bullet_engine import BulletEngine, require_pybullet

    require_pybullet()
    return BulletEngine(catalogue)


def _genesis(catalogue: Catalogue | None) -> SettleEngine:
    from physcensis.crosscheck.genesis_engine import GenesisEngine, require_genesis

    require_genesis()
    return GenesisEngine(catalogue)


SETTLE_ENGINES: dict[str, SettleEngineRecord] = {}


def register_settle_engine(record: SettleEngineRecord) -> SettleEngineRecord:
    """Add an engine under `record.name` (a name already taken is an error: engines are not replaced silently)."""
    if record.name in SETTLE_ENGINES:
        raise ValueError(f"a settle engine named {record.name!r} is already registered")
    SETTLE_ENGINES[record.name] = record
    return record


for _record in (
    SettleEngineRecord(
        "mujoco", "our contact settings (elliptic cone, impratio 10, stiff contacts, 2 ms step)", _mujoco("mujoco")
    ),
    SettleEngineRecord(
        "mujoco-default",
        "MuJoCo's defaults: pyramidal cone, default solref, the paper's 0.01 s step",
        _mujoco("mujoco-default"),
    ),
    SettleEngineRecord("bullet", "PyBullet's defaults on the URDF export (needs the bullet extra)", _bullet),
    SettleEngineRecord(
        "genesis",
        "Genesis, the paper's engine, on the MJCF export: its CPU backend and defaults, 0.01 s step "
        "(needs the genesis extra)",
        _genesis,
    ),
):
    register_settle_engine(_record)


def settle_engine(name: str, catalogue: Catalogue | None = None) -> SettleEngine:
    """The engine registered as `name`, built for `catalogue` (the built-in one when None)."""
    record = SETTLE_ENGINES.get(name)
    if record is None:
        known = ", ".join(SETTLE_ENGINES)
        raise PhyscensisError(f"no settle engine named {name!r} (known: {known})")
    return record.make(catalogue)
