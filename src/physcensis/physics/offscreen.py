"""Offscreen drawing of a MuJoCo model, on one GL context per thread kept for the life of the process.

Starting a GL context is the larger part of a picture with software GL (Mesa's llvmpipe compiles its shaders anew
for every context): a 960 x 720 render.png of a dining scene takes 0.74 s with a fresh context and 0.36 s on a kept
one. Only what belongs to one model (its meshes and textures on the GL side, its offscreen buffer) is made per
`Offscreen`.
"""

from __future__ import annotations

import atexit
import os
import threading
from types import TracebackType
from typing import Any

import mujoco
import numpy as np

from physcensis.errors import PhyscensisError

MAX_GEOMS = 10_000  # visual geoms one frame may draw


class OffscreenError(PhyscensisError):
    """Drawing could not start (usually no OpenGL context on a machine without a display)."""


class _Kept(threading.local):
    context: Any = None  # the GL context of this thread
    pid: int = 0  # the process that made it: a forked child must not use its parent's


_kept = _Kept()


def _gl_context() -> Any:
    """This thread's GL context, made current; made on first use (MUJOCO_GL chooses EGL, OSMesa or a window)."""
    if _kept.context is None or _kept.pid != os.getpid():
        from mujoco.rendering.classic import gl_context

        if gl_context.__dict__.get("GLContext") is None:  # MUJOCO_GL=disable: MuJoCo offers no context
            raise OffscreenError("MUJOCO_GL disables rendering here; set MUJOCO_GL=egl (or osmesa)")
        _kept.context, _kept.pid = gl_context.GLContext(1, 1), os.getpid()  # EGL ignores the size; MuJoCo draws
        if threading.current_thread() is threading.main_thread():  # into its own buffer of the model's size
            atexit.register(_free_main_context, _kept.context)  # before EGL's own exit hook (registered earlier)
    _kept.context.make_current()
    return _kept.context


def _free_main_context(context: Any) -> None:
    if _kept.context is context and _kept.pid == os.getpid():
        context.free()
        _kept.context = None


class Offscreen:
    """Pictures of one model at one size: `rgb` and `segments` of its data from a camera. Close it (or use it in a
    `with` block) to free what the model put on the GL side; the context itself stays for the next model."""

    def __init__(self, model: mujoco.MjModel, size: tuple[int, int], *, font_scale: int = 150) -> None:
        width, height = size
        self.model, self.width, self.height = model, width, height
        largest = (model.vis.global_.offwidth, model.vis.global_.offheight)
        try:
            _gl_context()
            # The offscreen buffer is made as large as the frames drawn, not the model's largest: the pixels of a
            # frame are the same, and a smaller buffer is faster to make.
            model.vis.global_.offwidth, model.vis.global_.offheight = width, height
            self._context: mujoco.MjrContext | None = mujoco.MjrContext(model, font_scale)
            mujoco.mjr_setBuffer(mujoco.mjtFramebuffer.mjFB_OFFSCREEN, self._context)
        except OffscreenError:
            raise
        except Exception as exc:  # any GL failure becomes one clear line
            raise OffscreenError(
                f"cannot start headless rendering ({exc.__class__.__name__}: {exc}); "
                "install libegl1 and set MUJOCO_GL=egl (or osmesa)"
            ) from None
        finally:
            model.vis.global_.offwidth, model.vis.global_.offheight = largest
        self.scene = mujoco.MjvScene(model, MAX_GEOMS)
        self._rect = mujoco.MjrRect(0, 0, width, height)

    def rgb(self, data: mujoco.MjData, camera: mujoco.MjvCamera, option: mujoco.MjvOption) -> np.ndarray:
        """An (height, width, 3) uint8 picture, row 0 at the top."""
        return self._draw(data, camera, option, segmented=False)

    def segments(self, data: mujoco.MjData, camera: mujoco.MjvCamera, option: mujoco.MjvOption) -> np.ndarray:
        """An (height, width, 2) int32 image of (object id, object type) per pixel; (-1, -1) where nothing is."""
        colours = self._draw(data, camera, option, segmented=True).astype(np.int64)
        segment = colours[..., 0] | (colours[..., 1] << 8) | (colours[..., 2] << 16)  # segment id + 1; 0: nothing
        drawn = self.scene.geoms[: self.scene.ngeom]
        table = np.full((len(drawn) + 2, 2), -1, dtype=np.int32)
        for geom in drawn:
            if geom.segid >= 0:
                table[geom.segid + 1] = (geom.objid, geom.objtype)
        return table[np.clip(segment, 0, len(table) - 1)]

    def _draw(
        self, data: mujoco.MjData, camera: mujoco.MjvCamera, option: mujoco.MjvOption, *, segmented: bool
    ) -> np.ndarray:
        if self._context is None:
            raise OffscreenError("this offscreen renderer was closed")
        mujoco.mjv_updateScene(self.model, data, option, None, camera, mujoco.mjtCatBit.mjCAT_ALL, self.scene)
        self.scene.flags[mujoco.mjtRndFlag.mjRND_SEGMENT] = segmented
        self.scene.flags[mujoco.mjtRndFlag.mjRND_IDCOLOR] = segmented
        _gl_context()
        mujoco.mjr_setBuffer(mujoco.mjtFramebuffer.mjFB_OFFSCREEN, self._context)
        mujoco.mjr_render(self._rect, self.scene, self._context)
        pixels = np.empty((self.height, self.width, 3), dtype=np.uint8)
        mujoco.mjr_readPixels(pixels, None, self._rect, self._context)
        return np.ascontiguousarray(pixels[::-1])  # GL's rows start at the bottom

    def close(self) -> None:
        if self._context is not None:
            _gl_context()  # the model's GL objects are freed in the context that holds them
            self._context.free()
            self._context = None

    def __enter__(self) -> Offscreen:
        return self

    def __exit__(
        self, kind: type[BaseException] | None, error: BaseException | None, trace: TracebackType | None
    ) -> None:
        self.close()
