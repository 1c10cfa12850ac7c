"""`eval diversity` on folders: finds and reads the scene folders, draws the coverage heat maps, writes diversity.json.

The measures themselves are `diversity.py`'s; this module only reads and writes files.
"""

from __future__ import annotations

import io
import json
import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import shapely

from physcensis.errors import PhyscensisError
from physcensis.evaluation.diversity import (
    CoverageGrid,
    ExpectCheck,
    PromptDiversity,
    PromptKey,
    centre_marks,
    coverage_grid,
    diversity_by_prompt,
    file_stem,
    prompt_key,
)
from physcensis.fileio import atomic_write_bytes, atomic_write_text, check_output_dir, check_output_file
from physcensis.scene import Scene, load_scene

REPORT_NAME = "diversity.json"
HEATMAPS_DIR = "diversity"
REPORT_FORMAT = "physcensis.diversity/1"
# How diversity.json starts as written here: such a file is replaced without --overwrite.
REPORT_MAGIC = ('{\n "format": "' + REPORT_FORMAT).encode()
MAX_DEPTH = 6  # folders below DIR searched for scene folders (a batch's scenes are 2 down)
MAX_SCENES = 10_000
_NOT_SCENES = frozenset({"mjcf", "urdf", "assets", HEATMAPS_DIR})


class DiversityError(PhyscensisError):
    """A folder that cannot be measured: none or too many scene folders, no readable scene."""


@dataclass(frozen=True)
class FoundScene:
    folder: Path
    scene: Scene


@dataclass
class DiversityRun:
    """What `measure_folder` found: the scenes read, the ones that could not be, and the measures per prompt."""

    root: Path
    scenes: list[FoundScene]
    unreadable: list[tuple[Path, str]]
    results: list[tuple[PromptDiversity, list[int]]]

    def scene_dirs(self, members: Sequence[int]) -> list[str]:
        return [_relative(self.scenes[i].folder, self.root) for i in members]


def find_scene_folders(root: Path, max_depth: int = MAX_DEPTH, max_scenes: int = MAX_SCENES) -> list[Path]:
    """`root` itself when it holds a scene.json, else every folder at most `max_depth` below it that does (hidden
    folders, exports and links are not searched). More than `max_scenes` is refused."""
    if (root / "scene.json").is_file():
        return [root]
    found: list[Path] = []
    for here, dirs, files in os.walk(root):
        depth = len(Path(here).relative_to(root).parts)
        if "scene.json" in files:
            found.append(Path(here))
            if len(found) > max_scenes:
                raise DiversityError(f"{root}: more than {max_scenes:,} scene folders; measure a smaller folder")
        dirs[:] = (
            [] if depth >= max_depth else sorted(d for d in dirs if not d.startswith(".") and d not in _NOT_SCENES)
        )
    return sorted(found, key=lambda p: p.relative_to(root).parts)


def read_scenes(folders: Sequence[Path]) -> tuple[list[FoundScene], list[tuple[Path, str]]]:
    """The scenes of the folders, and the folders whose scene.json could not be read (with why)."""
    scenes, unreadable = [], []
    for folder in folders:
        try:
            scenes.append(FoundScene(folder, load_scene(folder / "scene.json")))
        except (PhyscensisError, OSError) as exc:
            unreadable.append((folder, str(exc)))
    return scenes, unreadable


def measure_folder(root: Path, checks: Mapping[str, ExpectCheck] | None = None) -> DiversityRun:
    """Read every scene under `root` and measure the variety of each prompt's scenes."""
    if not root.is_dir():
        raise DiversityError(f"{root}: {'is not a folder' if root.exists() else 'no such folder'}")
    folders = find_scene_folders(root)
    if not folders:
        raise DiversityError(f"{root}: no scene folder (one holding scene.json) in this folder or below it")
    scenes, unreadable = read_scenes(folders)
    if not scenes:
        raise DiversityError(f"{root}: no scene could be read ({unreadable[0][0]}: {unreadable[0][1]})")
    results = diversity_by_prompt([s.scene for s in scenes], checks)
    return DiversityRun(root, scenes, unreadable, results)


# ---- writing --------------------------------------------------------------------------------------------------------


def check_outputs(out: Path, *, overwrite: bool = False, heatmaps: bool = True) -> None:
    """Refuse, before any work, outputs that cannot or may not be written: a diversity.json not ours, a user's
    diversity/ folder."""
    check_output_file(out / REPORT_NAME, overwrite=overwrite, suffixes=(REPORT_MAGIC,))
    if heatmaps:
        check_output_dir(out / HEATMAPS_DIR, overwrite=overwrite)


def write_outputs(run: DiversityRun, out: Path, *, heatmaps: bool = True) -> dict[str, Any]:
    """diversity.json in `out` and, with `heatmaps`, one coverage PNG per prompt in `out/diversity/`; each written
    atomically. Returns what diversity.json holds."""
    from physcensis.fileio import output_directory

    pictures: dict[int, str] = {}
    if heatmaps:
        with output_directory(out / HEATMAPS_DIR, overwrite=True) as staging:  # refused earlier if not ours
            for index, (result, members) in enumerate(run.results):
                key = prompt_key(run.scenes[members[0]].scene)
                name = f"{file_stem(key, index)}.png"
                write_heatmap(staging / name, key, [run.scenes[i] for i in members], result)
                pictures[index] = f"{HEATMAPS_DIR}/{name}"
    report = report_document(run, pictures)
    atomic_write_text(out / REPORT_NAME, json.dumps(report, indent=1) + "\n")
    return report


def report_document(run: DiversityRun, pictures: Mapping[int, str] | None = None) -> dict[str, Any]:
    pictures = pictures or {}
    prompts = [
        result.to_dict() | {"scene_dirs": run.scene_dirs(members), "heatmap": pictures.get(index)}
        for index, (result, members) in enumerate(run.results)
    ]
    return {
        "format": REPORT_FORMAT,
        "folder": str(run.root),
        "scenes": len(run.scenes),
        "prompts": prompts,
        "unreadable": [{"scene": _relative(folder, run.root), "error": why} for folder, why in run.unreadable],
    }


def summary_line(result: PromptDiversity) -> str:
    """One line per prompt for the batch summary."""
    layout = "-" if result.mean_layout_distance_m is None else f"{result.mean_layout_distance_m * 100:.1f} cm"
    return (
        f"{result.distinct_scenes} distinct scene(s) of {result.scenes}, "
        f"{result.distinct_asset_choices} distinct asset/count choice(s), mean layout distance {layout}"
    )


def _relative(folder: Path, root: Path) -> str:
    return Path(os.path.relpath(folder, root)).as_posix()


# ---- heat maps ------------------------------------------------------------------------------------------------------


def scene_prints(found: FoundScene) -> list[shapely.Geometry]:
    """The footprints of a scene's objects as its own catalogue knows them; discs at the centres when the assets
    cannot be read."""
    from physcensis.feedback.regions import footprints
    from physcensis.output import scene_catalogue

    try:
        return list(footprints(found.scene, scene_catalogue(found.scene, found.folder)).values())
    except (PhyscensisError, OSError, ValueError):
        return centre_marks(found.scene)


def write_heatmap(path: Path, key: PromptKey, scenes: Sequence[FoundScene], result: PromptDiversity) -> Path:
    """A PNG of the share of scenes covering each cell of the support, the objects' centres as dots."""
    support = scenes[0].scene.support
    grid = coverage_grid(support, [scene_prints(s) for s in scenes])
    centres = np.array([o.position[:2] for s in scenes for o in s.scene.placed], dtype=float).reshape(-1, 2)
    title = f"{key.prompt or '(no prompt)'}"
    caption = f"{result.scenes} scene(s), {result.distinct_scenes} distinct; {key.support}"
    atomic_write_bytes(path, _heatmap_png(grid, support.half_extents, centres, title, caption))
    return path


def _heatmap_png(grid: CoverageGrid, half: tuple[float, float], centres: np.ndarray, title: str, caption: str) -> bytes:
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib import pyplot as plt

    hx, hy = half
    # As layout.png: the support from above as the viewer sees it (viewpoint.py): world +x (front, towards the
    # viewer) down the page, world +y (the viewer's right) to the right.
    fig, ax = plt.subplots(figsize=(6.4, 6.4 * min(2.0, max(0.5, hx / hy))), dpi=110)
    image = ax.imshow(grid.share[::-1, :], extent=(-hy, hy, -hx, hx), origin="lower", cmap="YlOrRd", vmin=0.0, vmax=1.0)
    ax.add_patch(plt.Rectangle((-hy, -hx), 2 * hy, 2 * hx, fill=False, edgecolor="#7a5c3a", linewidth=2))
    if len(centres):
        ax.scatter(centres[:, 1], -centres[:, 0], s=4, c="#1f3a93", linewidths=0)
    margin = 0.05 * max(hx, hy)
    ax.set_xlim(-hy - margin, hy + margin)
    ax.set_ylim(-hx - margin, hx + margin)
    ax.set_yticks(ax.get_yticks(), [f"{-t:g}" for t in ax.get_yticks()])
    ax.set_xlim(-hy - margin, hy + margin)
    ax.set_ylim(-hx - margin, hx + margin)
    ax.set_xlabel("the viewer's left (-y)  <-   y   ->  the viewer's right (+y)   [m]")
    ax.set_ylabel("x, front (towards the viewer) at the bottom   [m]")
    line = " ".join(title.split())  # a prompt: shown as typed ('$' is not maths) and cut to a line
    line = line if len(line) <= 90 else line[:89] + "…"
    ax.set_title(f"{line}\n{caption}", fontsize=9, parse_math=False)
    fig.colorbar(image, ax=ax, fraction=0.046, pad=0.04, label="share of scenes covering the cell")
    buffer = io.BytesIO()
    fig.tight_layout()
    fig.savefig(buffer, format="png")
    plt.close(fig)
    return buffer.getvalue()
