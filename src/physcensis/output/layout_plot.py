"""Top-down plot of a layout (layout.png): the support outline, every footprint with its id and facing arrow."""

from __future__ import annotations

import io
import math
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from physcensis.fileio import atomic_write_bytes
from physcensis.geometry.footprints import Array, rotate
from physcensis.imageio import PNG_LEVEL
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
    from matplotlib.collections import PolyCollection

    hx, hy = support.half_extents
    # The support from above as the viewer sees it (viewpoint.py): world +x (front, towards the viewer) down the
    # page, world +y (the viewer's right) to the right.
    width = 6.4
    height = width * min(2.0, max(0.5, hx / hy))
    fig, ax = plt.subplots(figsize=(width, height), dpi=120)
    # Margins in inches for the labels and the title, set once: matplotlib's tight layout draws the figure twice.
    fig.subplots_adjust(left=0.8 / width, right=1 - 0.15 / width, bottom=0.6 / height, top=1 - 0.35 / height)
    ax.add_patch(
        plt.Rectangle((-hy, -hx), 2 * hy, 2 * hx, fill=True, facecolor="#f3ead8", edgecolor="#7a5c3a", linewidth=2)
    )
    cmap = plt.get_cmap("tab20")
    outlines, colours, arrows = [], [], []
    for k, (oid, (hull, x, y, yaw)) in enumerate(sorted(footprints.items())):
        pts = rotate(np.asarray(hull, dtype=float), np.array([yaw]))[0] + [x, y]
        outlines.append(np.column_stack([pts[:, 1], -pts[:, 0]]))
        colours.append("#d62728" if oid in highlight else cmap(k % 20))
        reach = 0.5 * float(np.ptp(pts[:, 0]) + np.ptp(pts[:, 1])) / 2
        arrows.append((y, -x, reach * math.sin(yaw), -reach * math.cos(yaw)))
        ax.text(y, -x, oid, fontsize=6, ha="center", va="center")
    ax.add_collection(PolyCollection(outlines, facecolors=colours, alpha=0.55, edgecolors="black", linewidths=0.8))
    if arrows:  # each object's facing, one artist for all
        u, v, du, dv = np.array(arrows).T
        ax.quiver(u, v, du, dv, angles="xy", scale_units="xy", scale=1, width=0.0025, headwidth=5, headlength=6)
    margin = 0.05 * max(hx, hy)
    ax.set_xlim(-hy - margin, hy + margin)
    ax.set_ylim(-hx - margin, hx + margin)
    ax.set_aspect("equal")
    ax.set_xlabel("the viewer's left (-y)  <-   y   ->  the viewer's right (+y)   [m]")
    ax.set_ylabel("x, front (towards the viewer) at the bottom   [m]")
    ax.set_yticks(ax.get_yticks(), [f"{-t + 0.0:g}" for t in ax.get_yticks()])
    ax.set_xlim(-hy - margin, hy + margin)
    ax.set_ylim(-hx - margin, hx + margin)
    if title:  # a prompt: shown as typed ('$' is not maths) and cut to a line
        line = " ".join(title.split())
        ax.set_title(line if len(line) <= 100 else line[:99] + "…", fontsize=9, parse_math=False)
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", pil_kwargs={"compress_level": PNG_LEVEL})
    plt.close(fig)
    path = Path(path)
    atomic_write_bytes(path, buffer.getvalue())
    return path
