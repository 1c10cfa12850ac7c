"""The settle, played: the scene's MuJoCo model (the engine's, with the scene's contact settings) stepped from the
written poses, a frame at a time, for the viewer to show as it goes."""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import mujoco
import numpy as np

from physcensis.assets.catalogue import Catalogue
from physcensis.physics.built import BuiltScene
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.scene import PlacedObject, Scene
from physcensis.viewer.scene_view import Pose, ViewerError

FRAME_S = 1.0 / 30.0  # one frame of the viewer's playback: 30 per second of simulated time, shown in real time
_DIVERGED = (mujoco.mjtWarning.mjWARN_BADQACC, mujoco.mjtWarning.mjWARN_BADQPOS, mujoco.mjtWarning.mjWARN_BADQVEL)


class SettlePlayback:
    """The scene's placed objects falling from their written poses (or `objects`, e.g. one lifted) under gravity."""

    def __init__(self, scene: Scene, catalogue: Catalogue, objects: Sequence[PlacedObject] | None = None) -> None:
        self._built: BuiltScene = MujocoEngine(catalogue).build(scene, objects=objects, visual=False)
        self.ids: tuple[str, ...] = tuple(self._built.qpos)
        self.timestep = float(self._built.model.opt.timestep)
        self._start = self._built.data.qpos.copy()
        self.time = 0.0
        self.diverged: str | None = None  # why the simulation was stopped, once it blew up

    def reset(self) -> dict[str, Pose]:
        """Back to the written poses, nothing moving."""
        model, data = self._built.model, self._built.data
        mujoco.mj_resetData(model, data)
        data.qpos[:] = self._start
        mujoco.mj_forward(model, data)
        self.time, self.diverged = 0.0, None
        return self.poses()

    def step(self, seconds: float = FRAME_S) -> dict[str, Pose]:
        """Simulate `seconds` more (whole time steps, at least one); the poses then. A simulation that blew up stays
        where it stopped (`diverged` says why)."""
        if self.diverged is None:
            model, data = self._built.model, self._built.data
            for _ in range(max(1, int(round(seconds / self.timestep)))):
                mujoco.mj_step(model, data)
                self.time += self.timestep
            self.diverged = _divergence(data)
        return self.poses()

    def poses(self) -> dict[str, Pose]:
        qpos = self._built.data.qpos
        return {oid: qpos[a : a + 7].copy() for oid, a in self._built.qpos.items()}

    def set_pose(self, object_id: str, pose: Pose) -> None:
        """Move one object to `pose` (7 numbers) now; `reset` puts it back at its written pose."""
        if object_id not in self._built.qpos:
            raise ViewerError(f"the simulation has no object {object_id!r}")
        address = self._built.qpos[object_id]
        self._built.data.qpos[address : address + 7] = np.asarray(pose, dtype=float)
        mujoco.mj_forward(self._built.model, self._built.data)


def _divergence(data: mujoco.MjData) -> str | None:
    for warning in _DIVERGED:
        if data.warning[warning].number > 0:
            return f"the simulation diverged at t = {data.time:.3f} s ({mujoco.mjtWarning(warning).name})"
    if not np.all(np.isfinite(data.qpos)):
        return f"the simulation diverged at t = {data.time:.3f} s (a position is not finite)"
    return None


def moved_m(start: Mapping[str, Pose], now: Mapping[str, Pose]) -> dict[str, float]:
    """How far each object's origin is from where it started, metres."""
    return {oid: float(np.linalg.norm(now[oid][:3] - start[oid][:3])) for oid in start if oid in now}
