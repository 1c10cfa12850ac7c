"""The layout plot's title is the user's prompt: shown as typed (no maths parsing of '$') and cut to one line."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from physcensis.imageio import PNG_MAGIC
from physcensis.output.layout_plot import plot_layout
from physcensis.scene import Support

SQUARE = np.array([[-0.05, -0.05], [0.05, -0.05], [0.05, 0.05], [-0.05, 0.05]])


def test_a_prompt_with_dollar_signs_or_of_any_length_is_drawn(tmp_path: Path) -> None:
    support = Support(kind="table", size=(0.6, 0.6))
    for k, title in enumerate([r"a mug priced $\frac{1}$ and $x^$", "a tea set " * 5000]):
        path = plot_layout(tmp_path / f"layout{k}.png", support, {"mug_0": (SQUARE, 0.0, 0.0, 0.0)}, title=title)
        assert path.read_bytes().startswith(PNG_MAGIC)


def test_many_objects_are_numbered_with_a_legend_in_columns(tmp_path: Path) -> None:
    """Every footprint is numbered and its id listed beside the plot, in as many columns as the list needs."""
    from PIL import Image

    support = Support(kind="table", size=(1.0, 1.0))
    widths = []
    for count in (10, 100):
        prints = {
            f"block_{k}": (SQUARE * 0.3, -0.45 + 0.09 * (k % 10), -0.45 + 0.09 * (k // 10), 0.0) for k in range(count)
        }
        path = plot_layout(tmp_path / f"layout{count}.png", support, prints, highlight=["block_3"])
        with Image.open(path) as image:
            widths.append(image.size[0])
    assert widths[1] > widths[0] * 1.3  # 100 ids need three columns where 10 need one


def test_footprints_are_drawn_where_the_viewer_sees_them_and_failed_ones_red(tmp_path: Path) -> None:
    """World +x (the front) is down the page and +y (the viewer's right) to the right; a failed footprint is red."""
    from PIL import Image

    support = Support(kind="table", size=(1.0, 1.0))
    big = SQUARE * 2  # 20 cm
    prints = {"a_failed": (big, 0.3, 0.15, 0.0), "b_placed": (big, -0.3, -0.15, 0.0)}  # x, y in a half extent 0.5
    path = plot_layout(tmp_path / "layout.png", support, prints, highlight=["a_failed"])
    with Image.open(path) as image:
        rgb = np.asarray(image.convert("RGB")).astype(int)
    r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    face = (abs(r - 243) < 6) & (abs(g - 234) < 6) & (abs(b - 216) < 6)  # the support's fill, #f3ead8
    rows, cols = np.nonzero(face)
    top, bottom, left, right = rows.min(), rows.max(), cols.min(), cols.max()
    mid_y, mid_x = (top + bottom) / 2, (left + right) / 2
    half = (right - left) / 2
    red = (r > 200) & (g < 170) & (b < 170)
    blue = (b > r + 10) & (b > 180)  # tab20's second colour over the support
    red_y, red_x = (c.mean() for c in np.nonzero(red))
    blue_y, blue_x = (c.mean() for c in np.nonzero(blue))
    assert red.sum() > 0.5 * (0.4 * half) ** 2 and blue.sum() > 0.5 * (0.4 * half) ** 2
    assert (
        abs(red_x - (mid_x + 0.3 * half)) < 0.1 * half and abs(red_y - (mid_y + 0.6 * half)) < 0.1 * half
    )  # front right
    assert (
        abs(blue_x - (mid_x - 0.3 * half)) < 0.1 * half and abs(blue_y - (mid_y - 0.6 * half)) < 0.1 * half
    )  # back left
    assert not red[: int(mid_y), : int(mid_x)].any()  # the footprint that did not fail is not red
