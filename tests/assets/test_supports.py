"""Support assets: geometry in world coordinates with the usable top centred at the support's height."""

from __future__ import annotations

import numpy as np
import pytest

from physcensis.assets.supports import shelf_board_heights, support_asset
from physcensis.scene import Support


@pytest.mark.parametrize("size", [(1.2, 0.8), (0.6, 1.5), (2.0, 2.0)])
def test_table_of_any_size(size: tuple[float, float]) -> None:
    support = Support(kind="table", size=size)
    table = support_asset(support)
    lo, hi = table.visual.bounds
    assert np.allclose(hi[:2], np.array(size) / 2) and np.allclose(lo[:2], -np.array(size) / 2)
    assert hi[2] == pytest.approx(support.top_height) and lo[2] == pytest.approx(0.0)
    assert len(table.collision) == 5  # top and four legs


def test_shelf_has_boards_sides_and_back() -> None:
    support = Support(kind="shelf", size=(0.3, 0.9))
    shelf = support_asset(support)
    heights = shelf_board_heights(support.top_height)
    assert support.top_height in heights and max(heights) > support.top_height
    tops = [p.pos[2] + p.size[2] for p in shelf.collision if p.kind == "box"]
    assert any(t == pytest.approx(support.top_height) for t in tops)
    assert shelf.visual.bounds[0][0] < -0.15  # back panel behind the usable top (-x)
    assert shelf.has_front


def test_open_box_and_floor() -> None:
    box = support_asset(Support(kind="box", size=(0.5, 0.4)))
    assert box.cavity is not None and box.cavity.floor_height == pytest.approx(0.02)
    assert len(box.collision) == 5
    floor = support_asset(Support(kind="floor", size=(3.0, 3.0)))
    assert floor.collision[0].kind == "plane"
