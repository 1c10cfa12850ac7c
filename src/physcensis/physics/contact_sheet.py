"""A contact sheet of assets rendered headless with MuJoCo (EGL when there is no display: see physcensis/__init__)."""

from __future__ import annotations

import logging
import math
from collections.abc import Sequence
from pathlib import Path

import mujoco
import numpy as np

from physcensis.assets.errors import AssetError
from physcensis.assets.model import Asset
from physcensis.imageio import Label, save_png
from physcensis.physics.mujoco_assets import add_asset_geoms
from physcensis.physics.offscreen import Offscreen

log = logging.getLogger(__name__)
SPACING = 4.0  # metres between assets in the gallery world, so neighbours stay out of view
LABEL_HEIGHT = 16
FOVY_DEG = 30.0


def _build_model(assets: Sequence[Asset], cols: int, tile: int) -> mujoco.MjModel:
    spec = mujoco.MjSpec()
    spec.visual.global_.offwidth = max(tile, 640)
    spec.visual.global_.offheight = max(tile, 480)
    spec.visual.global_.fovy = FOVY_DEG
    spec.visual.headlight.ambient = [0.35, 0.35, 0.35]
    spec.visual.headlight.diffuse = [0.45, 0.45, 0.45]
    spec.visual.headlight.specular = [0.05, 0.05, 0.05]
    spec.visual.quality.offsamples = 8
    spec.stat.extent = 1.0  # clipping planes scale with the extent: keep them tight around one tile
    # nothing moves: without contacts, thousands of assets resting on the floor need no memory for them
    spec.option.disableflags |= mujoco.mjtDisableBit.mjDSBL_CONTACT | mujoco.mjtDisableBit.mjDSBL_CONSTRAINT
    spec.visual.map.znear = 0.002
    spec.visual.map.zfar = 60.0
    tex = spec.add_texture(
        name="grid",
        type=mujoco.mjtTexture.mjTEXTURE_2D,
        builtin=mujoco.mjtBuiltin.mjBUILTIN_CHECKER,
        width=64,
        height=64,
        rgb1=[0.93, 0.93, 0.92],
        rgb2=[0.86, 0.86, 0.85],
    )
    del tex
    mat = spec.add_material(name="floor")
    mat.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = "grid"
    mat.texrepeat = [40, 40]
    mat.reflectance = 0.0
    rows = math.ceil(len(assets) / cols)
    floor = spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, material="floor")
    floor.size = [cols * SPACING, rows * SPACING, 0.1]
    floor.pos = [(cols - 1) * SPACING / 2, -(rows - 1) * SPACING / 2, -0.0005]
    for direction in ([-0.4, 0.5, -1.0], [0.6, -0.3, -0.8]):
        light = spec.worldbody.add_light(type=mujoco.mjtLightType.mjLIGHT_DIRECTIONAL, dir=direction, castshadow=False)
        light.diffuse = [0.45, 0.45, 0.45]
        light.specular = [0.15, 0.15, 0.15]
    for i, asset in enumerate(assets):
        r, c = divmod(i, cols)
        body = spec.worldbody.add_body(name=f"tile{i}", pos=[c * SPACING, -r * SPACING, 0.0])
        add_asset_geoms(spec, body, asset, f"tile{i}", static=True)
    return spec.compile()


def render_contact_sheet(
    assets: Sequence[Asset],
    out: str | Path,
    *,
    cols: int = 12,
    tile: int = 200,
    labels: bool = True,
    azimuth: float = 145.0,
    elevation: float = -28.0,
) -> Path:
    """Render each asset in its own framed tile and write one PNG; returns its path."""
    if not assets:
        raise AssetError("gallery: no assets to render")
    cols = max(1, min(cols, len(assets)))
    try:
        model = _build_model(assets, cols, tile)
        data = mujoco.MjData(model)
        mujoco.mj_forward(model, data)
        renderer = Offscreen(model, (tile, tile))
    except Exception as exc:  # report rendering set-up failures as one line
        raise AssetError(
            f"gallery: cannot set up MuJoCo rendering ({exc.__class__.__name__}: {exc})"
            + ("; on a machine without a display set MUJOCO_GL=egl or osmesa" if "GL" in str(exc) else "")
        ) from exc
    rows = math.ceil(len(assets) / cols)
    cell_h = tile + (LABEL_HEIGHT if labels else 0)
    sheet = np.full((rows * cell_h, cols * tile, 3), 255, dtype=np.uint8)
    text: list[Label] = []
    options = mujoco.MjvOption()
    camera = mujoco.MjvCamera()
    camera.type = mujoco.mjtCamera.mjCAMERA_FREE
    camera.azimuth, camera.elevation = azimuth, elevation
    half_fov = math.radians(FOVY_DEG) / 2
    for i, asset in enumerate(assets):
        r, c = divmod(i, cols)
        ext = np.asarray(asset.visual.extents)
        centre = asset.visual.bounds.mean(axis=0)
        radius = 0.5 * float(np.linalg.norm(ext))
        camera.lookat[:] = [c * SPACING + centre[0], -r * SPACING + centre[1], centre[2]]
        camera.distance = 1.05 * radius / math.sin(half_fov)
        sheet[r * cell_h : r * cell_h + tile, c * tile : (c + 1) * tile] = renderer.rgb(data, camera, options)
        if labels:
            text.append((c * tile + 3, r * cell_h + tile + 2, asset.id[: tile // 7]))
    renderer.close()
    path = Path(out)
    save_png(path, sheet, text)
    log.info("wrote a gallery of %d assets to %s", len(assets), path)
    return path
