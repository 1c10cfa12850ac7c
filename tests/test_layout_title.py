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
