"""A scene compiled into MuJoCo: the model and its state, and where each object lives in them.

Its own module so that the engine (which builds and settles it) and the renderer (which draws it) both import it
without importing each other.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import mujoco
import numpy as np

from physcensis.assets.model import Asset
from physcensis.scene import PlacedObject


@dataclass
class BuiltScene:
    """A compiled model of a scene plus the maps from object ids to MuJoCo indices."""

    model: mujoco.MjModel
    data: mujoco.MjData
    spec: mujoco.MjSpec
    objects: list[PlacedObject]
    assets: dict[str, Asset]
    body: dict[str, int] = field(default_factory=dict)
    qpos: dict[str, int] = field(default_factory=dict)
    dof: dict[str, int] = field(default_factory=dict)
    # geom index -> index (in `objects`) of the object it belongs to, or -1 for the support and the floor
    geom_owner: np.ndarray = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        for obj in self.objects:
            body_id = self.model.body(obj.id).id
            joint = self.model.body_jntadr[body_id]
            self.body[obj.id] = body_id
            self.qpos[obj.id] = int(self.model.jnt_qposadr[joint])
            self.dof[obj.id] = int(self.model.jnt_dofadr[joint])
        owner = np.full(self.model.ngeom, -1, dtype=int)
        index = {bid: k for k, bid in enumerate(self.body.values())}
        for g in range(self.model.ngeom):
            owner[g] = index.get(int(self.model.geom_bodyid[g]), -1)
        self.geom_owner = owner

    def penetration_of(self, object_id: str) -> tuple[float, float]:
        """Deepest penetration of one object at the current positions (collision only, no dynamics), split into
        contacts that carry it (normal mostly vertical) and side contacts."""
        mujoco.mj_kinematics(self.model, self.data)
        mujoco.mj_collision(self.model, self.data)
        me = list(self.body).index(object_id)
        below, side = 0.0, 0.0
        for i in range(self.data.ncon):
            contact = self.data.contact[i]
            if me in (self.geom_owner[contact.geom[0]], self.geom_owner[contact.geom[1]]):
                depth = -float(contact.dist)
                if abs(contact.frame[2]) > 0.7:
                    below = max(below, depth)
                else:
                    side = max(side, depth)
        return below, side

    def lower_onto_support(
        self,
        object_id: str,
        z_high: float,
        z_low: float,
        *,
        allowed: float = 5e-4,
        allowed_side: float = 5e-4,
        iterations: int = 12,
    ) -> float | None:
        """The lowest height in [z_low, z_high] at which the object does not sink into what carries it (more
        than `allowed`) nor into its neighbours (more than `allowed_side`); None if even z_high does. The
        object is left there."""
        a = self.qpos[object_id]

        def clear(z: float) -> bool:
            self.data.qpos[a + 2] = z
            below, side = self.penetration_of(object_id)
            return below <= allowed and side <= allowed_side

        if not clear(z_high):
            return None
        lo, hi = z_low, z_high
        for _ in range(iterations):
            mid = (lo + hi) / 2
            if clear(mid):
                hi = mid
            else:
                lo = mid
        self.data.qpos[a + 2] = hi
        return hi

    def poses(self) -> np.ndarray:
        """(n, 7) position and quaternion of every object."""
        return np.array([self.data.qpos[a : a + 7] for a in self.qpos.values()]).reshape(-1, 7)

    def com(self, object_id: str) -> tuple[float, float, float]:
        x, y, z = (float(v) for v in self.model.body_ipos[self.body[object_id]])
        return x, y, z

    def penetrations(self) -> tuple[np.ndarray, list[dict[int, float]]]:
        """Deepest penetration of each object, and with whom (object index, or -1 for the support)."""
        deepest = np.zeros(len(self.objects))
        partners: list[dict[int, float]] = [{} for _ in self.objects]
        for i in range(self.data.ncon):
            contact = self.data.contact[i]
            depth = -float(contact.dist)
            if depth <= 0:
                continue
            a, b = self.geom_owner[contact.geom[0]], self.geom_owner[contact.geom[1]]
            for me, other in ((a, b), (b, a)):
                if me >= 0:
                    deepest[me] = max(deepest[me], depth)
                    partners[me][other] = max(partners[me].get(other, 0.0), depth)
        return deepest, partners
