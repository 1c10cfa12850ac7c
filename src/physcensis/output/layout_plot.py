"""Top-down plot of a layout (layout.png): the support outline, every footprint with its id and facing arrow."""

from __future__ import annotations

import io
import math
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from physcensis.fileio import atomic_write_bytes
from physcensis.geometry.footprints import Array, rotate
from physcensis.scene import Support


def plot_layout(
    path: str | Path,
    support: Support,
    footprints: Mapping[str, tuple[Array, float, float, float]],
    highlight: Sequence[str] = (),
    title: str = "",
) -> Path:
    """Write a PNG of footprints given as id -> (hull, x, y, yaw); `highlight` ids are drawn red."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib import pyplot as plt

    hx, hy = support.half_extents
    # The support from above as the viewer sees it (viewpoint.py): world +x (front, towards the viewer) down the
    # page, world +y (the viewer's right) to the right.
    fig, ax = plt.subplots(figsize=(6.4, 6.4 * min(2.0, max(0.5, hx / hy))), dpi=120)
    ax.add_patch(
        plt.Rectangle((-hy, -hx), 2 * hy, 2 * hx, fill=True, facecolor="#f3ead8", edgecolor="#7a5c3a", linewidth=2)
    )
    cmap = plt.get_cmap("tab20")
    for k, (oid, (hull, x, y, yaw)) in enumerate(sorted(footprints.items())):
        pts = rotate(np.asarray(hull, dtype=float), np.array([yaw]))[0] + [x, y]
        colour = "#d62728" if oid in highlight else cmap(k % 20)
        ax.fill(pts[:, 1], -pts[:, 0], facecolor=colour, alpha=0.55, edgecolor="black", linewidth=0.8)
        reach = 0.5 * float(np.ptp(pts[:, 0]) + np.ptp(pts[:, 1])) / 2
        ax.annotate(
            "",
            xy=(y + reach * math.sin(yaw), -(x + reach * math.cos(yaw))),
            xytext=(y, -x),
            arrowprops={"arrowstyle": "->", "color": "black", "lw": 0.8},
        )
        ax.text(y, -x, oid, fontsize=6, ha="center", va="center")
    margin = 0.05 * max(hx, hy)
    ax.set_xlim(-hy - margin, hy + margin)
    ax.set_ylim(-hx - margin, hx + margin)
    ax.set_aspect("equal")
    ax.set_xlabel("the viewer's left (-y)  <-   y   ->  the viewer's right (+y)   [m]")
    ax.set_ylabel("x, front (towards the viewer) at the bottom   [m]")
    ax.set_yticks(ax.get_yticks(), [f"{-t:g}" for t in ax.get_yticks()])
    ax.set_xlim(-hy - margin, hy + margin)
    ax.set_ylim(-hx - margin, hx + margin)
    if title:  # a prompt: shown as typed ('$' is not maths) and cut to a line
        line = " ".join(title.split())
        ax.set_title(line if len(line) <= 100 else line[:99] + "…", fontsize=9, parse_math=False)
    buffer = io.BytesIO()
    fig.tight_layout()
    fig.savefig(buffer, format="png")
    plt.close(fig)
    path = Path(path)
    atomic_write_bytes(path, buffer.getvalue())
    return path
