"""Top-down plot of a layout (layout.png): the support outline, every footprint numbered with its facing arrow, a
legend of the numbers' ids beside it and a scale bar; lengths in centimetres."""

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

PLOT_IN = 6.4  # the support's plot, inches on its longer side
ROWS_PER_COLUMN = 40  # legend lines in one column
LEGEND_COLUMN_IN = 2.3
SCALE_STEPS_CM = (1, 2, 5, 10, 20, 50, 100)


def plot_layout(
    path: str | Path,
    support: Support,
    footprints: Mapping[str, tuple[Array, float, float, float]],
    highlight: Sequence[str] = (),
    title: str = "",
) -> Path:
    """Write a PNG of footprints given as id -> (hull, x, y, yaw); `highlight` ids (failed ones) are drawn red."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib import pyplot as plt
    from matplotlib.collections import PolyCollection

    hx, hy = support.half_extents
    ids = sorted(footprints)
    columns = math.ceil(len(ids) / ROWS_PER_COLUMN)
    # The support from above as the viewer sees it (viewpoint.py): world +x (front, towards the viewer) down the
    # page, world +y (the viewer's right) to the right; the plot's units are centimetres.
    plot_w = PLOT_IN * min(1.0, hy / hx)
    plot_h = PLOT_IN * min(1.0, hx / hy)
    left, right, bottom, top = 0.75, 0.2 + columns * LEGEND_COLUMN_IN, 0.65, 0.45
    width, height = plot_w + left + right, max(plot_h, 2.5) + bottom + top
    fig = plt.figure(figsize=(width, height), dpi=110)
    ax = fig.add_axes((left / width, bottom / height, plot_w / width, max(plot_h, 2.5) / height))
    cm = 100.0
    ax.add_patch(
        plt.Rectangle(
            (-hy * cm, -hx * cm), 2 * hy * cm, 2 * hx * cm, facecolor="#f3ead8", edgecolor="#7a5c3a", linewidth=2
        )
    )
    cmap = plt.get_cmap("tab20")
    outlines, colours, arrows, legend = [], [], [], []
    for k, oid in enumerate(ids):
        hull, x, y, yaw = footprints[oid]
        pts = (rotate(np.asarray(hull, dtype=float), np.array([yaw]))[0] + [x, y]) * cm
        outlines.append(np.column_stack([pts[:, 1], -pts[:, 0]]))
        failed = oid in highlight
        colours.append("#d62728" if failed else cmap(k % 20))
        reach = 0.25 * float(np.ptp(pts[:, 0]) + np.ptp(pts[:, 1])) / 2
        arrows.append((y * cm, -x * cm, reach * math.sin(yaw), -reach * math.cos(yaw)))
        ax.text(y * cm, -x * cm, str(k + 1), fontsize=6.5, ha="center", va="center", fontweight="bold")
        legend.append(f"{k + 1:>3}  {oid}{'  (failed)' if failed else ''}")
    ax.add_collection(PolyCollection(outlines, facecolors=colours, alpha=0.55, edgecolors="black", linewidths=0.8))
    if arrows:  # each object's facing, from its centre, one artist for all
        u, v, du, dv = np.array(arrows).T
        ax.quiver(u, v, du, dv, angles="xy", scale_units="xy", scale=1, width=0.002, headwidth=4, headlength=5)
    margin = 0.08 * max(hx, hy) * cm
    ax.set_xlim(-hy * cm - margin, hy * cm + margin)
    ax.set_ylim(-hx * cm - margin, hx * cm + margin)
    ax.set_aspect("equal")
    ax.set_xlabel("across, cm: the viewer's left  <  0  >  the viewer's right", fontsize=8)
    ax.set_ylabel("depth, cm: back at the top, front (the viewer) at the bottom", fontsize=8)
    ax.set_yticks(ax.get_yticks(), [f"{-t + 0.0:g}" for t in ax.get_yticks()])  # world x, which grows to the front
    ax.set_xlim(-hy * cm - margin, hy * cm + margin)
    ax.set_ylim(-hx * cm - margin, hx * cm + margin)
    ax.tick_params(labelsize=7)
    _scale_bar(ax, hx * cm, hy * cm, margin)
    for c in range(columns):
        lines = legend[c * ROWS_PER_COLUMN : (c + 1) * ROWS_PER_COLUMN]
        fig.text(
            (left + plot_w + 0.2 + c * LEGEND_COLUMN_IN) / width,
            1 - top / height,
            "\n".join(lines),
            fontsize=6.5,
            family="DejaVu Sans Mono",
            va="top",
            ha="left",
        )
    if title:  # a prompt: shown as typed ('$' is not maths) and cut to a line
        line = " ".join(title.split())
        fig.suptitle(
            line if len(line) <= 110 else line[:109] + "…", fontsize=9, y=1 - 0.12 / height, va="top", parse_math=False
        )
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", pil_kwargs={"compress_level": PNG_LEVEL})
    plt.close(fig)
    path = Path(path)
    atomic_write_bytes(path, buffer.getvalue())
    return path


def _scale_bar(ax: object, hx_cm: float, hy_cm: float, margin: float) -> None:
    """A bar of a round length, at most two fifths of the support's width, under its front left corner."""
    from matplotlib.axes import Axes

    assert isinstance(ax, Axes)
    length = max([s for s in SCALE_STEPS_CM if s <= 0.4 * hy_cm] or [SCALE_STEPS_CM[0]])
    x0, y0 = -hy_cm, -hx_cm - 0.55 * margin  # below the support, in the plot's margin
    ax.plot([x0, x0 + length], [y0, y0], color="black", linewidth=2.5, solid_capstyle="butt")
    ax.text(x0 + length + 0.1 * margin, y0, f"{length} cm", fontsize=7, ha="left", va="center")
