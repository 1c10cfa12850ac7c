"""PyBullet cross-check: load the URDF export and measure the settle distance in a second engine.

A scene that rests in MuJoCo but not in Bullet leans on one engine's quirks.  Needs
the optional extra `physcensis[bullet]`.  It sits above export/ (it loads what the URDF
exporter writes); `BulletEngine` is a `SettleEngine` like `MujocoEngine`.
"""

from __future__ import annotations

import json
import tempfile
from pathlib import Path
from types import ModuleType

import numpy as np

from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.crosscheck.quiet import quiet_output
from physcensis.errors import ExportError
from physcensis.export.bodies import export_scene_bodies
from physcensis.export.urdf import export_urdf
from physcensis.physics.engine import SETTLE_S, SettleDistance
from physcensis.scene import Scene

BULLET_TIMESTEP = 1.0 / 240.0  # Bullet's default step; 960 of them make the paper's 4 s


def require_pybullet() -> None:
    """Raise ExportError (with the install hint) unless PyBullet can be imported."""
    _pybullet()


def _pybullet() -> ModuleType:
    try:
        with quiet_output():
            import pybullet
    except ImportError:
        raise ExportError("the Bullet cross-check needs the optional extra: pip install 'physcensis[bullet]'") from None
    return pybullet


class BulletEngine:
    """Settle distance in PyBullet of a scene, through its URDF export."""

    def __init__(self, catalogue: Catalogue | None = None) -> None:
        self.catalogue = catalogue or default_catalogue()

    def settle_distance(self, scene: Scene, duration_s: float = SETTLE_S) -> SettleDistance:
        with tempfile.TemporaryDirectory(prefix="physcensis-bullet-") as tmp:
            index = export_urdf(export_scene_bodies(scene, self.catalogue), Path(tmp) / "urdf")
            return urdf_settle_distance(index, duration_s=duration_s)


def _origin(p: ModuleType, handle: int, client: int) -> np.ndarray:
    """World position of the body's URDF link frame (the asset origin, as MuJoCo measures it); Bullet reports the
    centre of mass."""
    com_position, com_orientation = p.getBasePositionAndOrientation(handle, physicsClientId=client)
    local_position, local_orientation = p.getDynamicsInfo(handle, -1, physicsClientId=client)[3:5]
    inverse = p.invertTransform(local_position, local_orientation)
    position, _ = p.multiplyTransforms(com_position, com_orientation, *inverse)
    return np.asarray(position)


def load_bodies(p: ModuleType, index: Path, client: int, *, free_only: bool = False) -> dict[str, int]:
    """Load every body of a URDF export (`bodies.json`) into a connected PyBullet client as written (poses, fixed
    bases, the files' inertia): body id -> PyBullet handle (`free_only`: the bodies that may move)."""
    handles: dict[str, int] = {}
    for entry in json.loads(index.read_text())["bodies"]:
        with quiet_output():
            handle = p.loadURDF(
                str(index.parent / entry["urdf"]),
                entry["position"],
                entry["quaternion_xyzw"],
                useFixedBase=entry["fixed"],
                flags=p.URDF_USE_INERTIA_FROM_FILE,
                physicsClientId=client,
            )
        if not (free_only and entry["fixed"]):
            handles[entry["id"]] = handle
    return handles


def urdf_settle_distance(
    index: str | Path, *, duration_s: float = SETTLE_S, timestep: float = BULLET_TIMESTEP
) -> SettleDistance:
    """Load a URDF export (`bodies.json` of `export_urdf`), let it fall for `duration_s` and measure how far each
    free body moved (clamped at 1 m, like the MuJoCo measure)."""
    p = _pybullet()
    index = Path(index)
    with quiet_output():
        client = p.connect(p.DIRECT)
    try:
        p.setGravity(0.0, 0.0, -9.81, physicsClientId=client)
        p.setTimeStep(timestep, physicsClientId=client)
        handles = load_bodies(p, index, client, free_only=True)
        start = {oid: _origin(p, h, client) for oid, h in handles.items()}
        for _ in range(int(round(duration_s / timestep))):
            p.stepSimulation(physicsClientId=client)
        moved = {oid: float(np.linalg.norm(_origin(p, h, client) - start[oid])) for oid, h in handles.items()}
        return SettleDistance.of_moves(moved, "PyBullet")
    finally:
        p.disconnect(physicsClientId=client)
