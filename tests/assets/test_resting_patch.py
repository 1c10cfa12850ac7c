"""Every built-in asset, turned any way, rests supported on an empty flat surface as the solver's voxel search sees it
(the COM projects far enough inside the contact patch) on the table's fine grid and the floor's coarse one. Small
things (a die, a lipstick) are smaller than a floor cell; some lean on a thin point (a whisk's handle end)."""

from __future__ import annotations

import pytest

from physcensis.assets.catalogue import default_catalogue
from physcensis.geometry.voxels import object_grid
from physcensis.solver.physical import FLOOR_PITCH_M, PAD_FRACTION, PITCH_M, support_margin

SHARES = 4  # the catalogue in interleaved quarters, so that the check's minute spreads over the test workers


@pytest.mark.slow
@pytest.mark.parametrize("share", range(SHARES))
@pytest.mark.parametrize("pitch", [PITCH_M, FLOOR_PITCH_M])
@pytest.mark.long
def test_every_asset_is_supported_on_an_empty_surface(pitch: float, share: int) -> None:
    unsupported = []
    catalogue = default_catalogue()
    for asset in [catalogue.get(asset_id) for asset_id in catalogue.ids()[share::SHARES]]:
        for yaw in (0.0, 0.7):
            grid = object_grid(asset, yaw, pitch, pad=PAD_FRACTION * pitch)
            patches = grid.flat_projections
            margin = float(patches.max(axis=0).min()) if len(patches) else float("-inf")
            if margin < support_margin(asset, pitch):
                unsupported.append(f"{asset.id} at yaw {yaw}: {margin:.4f} m")
    assert not unsupported, unsupported
