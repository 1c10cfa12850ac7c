"""Write RGB images as PNG files (atomically): the pixels as they are with Pillow, or with small text labels drawn by
matplotlib (imported only then: it is a second of a batch worker's start-up)."""

from __future__ import annotations

import io
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from physcensis.fileio import atomic_write_bytes

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
PNG_LEVEL = 3  # zlib level of the PNGs written: a sixth larger than the default 6, in half the time
Label = tuple[int, int, str]  # (column, row) of the text's top-left pixel, text


def save_png(path: str | Path, rgb: np.ndarray, labels: Sequence[Label] = (), font_px: int = 10) -> Path:
    """Save an (H, W, 3) uint8 image at its exact pixel size; labels are drawn in dark grey."""
    buffer = io.BytesIO()
    if not labels:  # the pixels as they are, without drawing a figure
        from PIL import Image

        Image.fromarray(np.ascontiguousarray(rgb, dtype=np.uint8)).save(buffer, format="png", compress_level=PNG_LEVEL)
        atomic_write_bytes(Path(path), buffer.getvalue())
        return Path(path)
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib import pyplot as plt

    height, width = rgb.shape[:2]
    dpi = 100
    fig = plt.figure(figsize=(width / dpi, height / dpi), dpi=dpi)
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0))
    ax.imshow(rgb, interpolation="nearest")
    ax.set_axis_off()
    for col, row, text in labels:
        ax.text(
            col, row, text, fontsize=font_px * 72 / dpi, color="#333333", va="top", ha="left", family="DejaVu Sans Mono"
        )
    fig.savefig(buffer, format="png", dpi=dpi, pil_kwargs={"compress_level": PNG_LEVEL})
    plt.close(fig)
    path = Path(path)
    atomic_write_bytes(path, buffer.getvalue())
    return path
