"""Genesis cross-check: load the MJCF export in the paper's own engine and measure its settle distance there.

The paper runs its physical solver in Genesis; we run MuJoCo. This engine lets a scene made here be measured as the
paper measures it: Genesis (its CPU backend), the exported MJCF as Genesis reads it, Genesis's own contact settings
(the MJCF's `<option>` block is left to Genesis, which ignores its friction cone and raises its too-stiff time
constant to twice the step), the paper's 0.01 s step, 4 s of free fall. Needs the optional extra
`physcensis[genesis]` (genesis-world and a CPU build of PyTorch). Genesis compiles its kernels the first time it
builds a scene on a machine (minutes; cached after that), and importing it takes about ten seconds.
"""

from __future__ import annotations

import math
import tempfile
from pathlib import Path
from types import ModuleType
from typing import Any

from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.crosscheck.quiet import quiet_output
from physcensis.errors import ExportError
from physcensis.physics.engine import SETTLE_S, SETTLE_STEP_S, SettleDistance
from physcensis.scene import Scene

GENESIS_TIMESTEP = SETTLE_STEP_S  # the paper's step: 400 of them make its 4 s
_INSTALL_HINT = "the Genesis cross-check needs the optional extra: pip install 'physcensis[genesis]'"


def require_genesis() -> None:
    """Raise ExportError (with the install hint) unless Genesis can be imported and started on the CPU."""
    _genesis()


def _genesis() -> ModuleType:
    """Genesis, imported and initialised once per process on its CPU backend."""
    try:
        with quiet_output():
            import genesis as gs
    except ImportError as exc:
        raise ExportError(f"{_INSTALL_HINT} ({exc})") from None
    if not gs._initialized:
        with quiet_output():
            gs.init(backend=gs.cpu, logging_level="error", seed=0)
    return gs


class GenesisEngine:
    """Settle distance in Genesis of a scene, through its MJCF export."""

    def __init__(self, catalogue: Catalogue | None = None) -> None:
        self.catalogue = catalogue or default_catalogue()

    def settle_distance(self, scene: Scene, duration_s: float = SETTLE_S) -> SettleDistance:
        from physcensis.export.mjcf import export_mjcf
        from physcensis.physics.mujoco_engine import build_scene

        with tempfile.TemporaryDirectory(prefix="physcensis-genesis-") as tmp:
            xml = export_mjcf(build_scene(scene, self.catalogue), Path(tmp) / "mjcf")
            return mjcf_settle_distance(xml, [o.id for o in scene.placed], duration_s=duration_s)


def mjcf_settle_distance(
    xml: str | Path, object_ids: list[str], *, duration_s: float = SETTLE_S, timestep: float = GENESIS_TIMESTEP
) -> SettleDistance:
    """Load an MJCF export in Genesis, let it fall for `duration_s` and measure how far the body of each of
    `object_ids` moved (its frame's origin, as the MuJoCo measure takes it; clamped at 1 m)."""
    gs = _genesis()
    with quiet_output():
        world = gs.Scene(sim_options=gs.options.SimOptions(dt=timestep), show_viewer=False)
        entity = world.add_entity(gs.morphs.MJCF(file=str(xml)))
        world.build()
    try:
        links = {link.name: link for link in entity.links}
        missing = [oid for oid in object_ids if oid not in links]
        if missing:
            raise ExportError(f"{xml}: Genesis read no body named {', '.join(missing)}")
        start = {oid: _position(links[oid]) for oid in object_ids}
        with quiet_output():
            for _ in range(int(round(duration_s / timestep))):
                world.step()
        return SettleDistance.of_moves(
            {oid: math.dist(_position(links[oid]), start[oid]) for oid in object_ids}, "Genesis"
        )
    finally:
        world.destroy()


def _position(link: Any) -> tuple[float, float, float]:
    x, y, z = (float(v) for v in link.get_pos().reshape(-1)[:3])
    return (x, y, z)
