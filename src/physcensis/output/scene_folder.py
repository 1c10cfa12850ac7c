"""The folder of one solved scene: scene.json, report.json, render.png, layout.png and the simulator exports."""

from __future__ import annotations

import json
import time
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path

from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.export import export_scene, parse_formats
from physcensis.fileio import output_directory
from physcensis.imageio import save_png
from physcensis.output.layout_plot import plot_layout
from physcensis.output.scene_assets import write_scene_assets
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.physics.render import DEFAULT_VIEW, render_built
from physcensis.scene import save_scene
from physcensis.solver.objects import quaternion_yaw
from physcensis.solver.pipeline import Solution

DEFAULT_EXPORTS = ("all",)  # every format this installation can write


def write_solution(
    solution: Solution,
    out_dir: str | Path,
    *,
    layout_png: bool = True,
    physics_outputs: bool = True,
    engine: MujocoEngine | None = None,
    exports: Iterable[str] = DEFAULT_EXPORTS,
    extra_files: Mapping[str, str | Callable[[], str]] | None = None,
    overwrite: bool = False,
) -> Path:
    """Write scene.json, report.json, layout.png and (with physics) render.png and the `exports` (mjcf/, urdf/,
    scene.glb, scene.usd, and exports.json recording which scene they come from), copies of the library assets the
    scene uses (assets/, see `scene_assets.py`), plus `extra_files` (name -> text, or a function giving it once the
    rest is written; it may replace report.json), all or nothing.

    `out_dir` may be new, empty or an earlier physcensis output (its files are replaced); a folder holding other
    files is refused with `OutputError` unless `overwrite`, and even then only physcensis's files are replaced."""
    formats = parse_formats(list(exports))  # an unknown or unavailable format fails before any work
    out_dir = Path(out_dir)
    with output_directory(out_dir, overwrite=overwrite) as staging:
        catalogue = engine.catalogue if engine else default_catalogue()
        solution.scene = write_scene_assets(solution.scene, catalogue, staging)
        save_scene(solution.scene, staging / "scene.json")
        if physics_outputs and solution.scene.placed:
            engine = engine or MujocoEngine(catalogue)
            _write_render_and_exports(solution, staging, engine, formats)
        (staging / "report.json").write_text(json.dumps(solution.report(), indent=2) + "\n")
        for name, text in (extra_files or {}).items():
            (staging / name).write_text(text if isinstance(text, str) else text())
        if layout_png and solution.spatial is not None:
            _write_layout(solution, staging / "layout.png", catalogue)
    return out_dir


def _write_render_and_exports(
    solution: Solution, staging: Path, engine: MujocoEngine, formats: tuple[str, ...]
) -> None:
    """render.png and the exports from one built model; their timings and files go into the solution's report."""
    built = engine.build(solution.scene)
    t = time.perf_counter()
    save_png(staging / "render.png", render_built(built, solution.scene, view=DEFAULT_VIEW))
    solution.timings["render"] = time.perf_counter() - t
    t = time.perf_counter()
    written = export_scene(solution.scene, staging, formats, catalogue=engine.catalogue, built=built)
    solution.timings["export"] = time.perf_counter() - t
    solution.exports = {name: str(path.relative_to(staging)) for name, path in written.items()}


def _write_layout(solution: Solution, path: Path, catalogue: Catalogue) -> None:
    """The top-down plot of every object's footprint, failed ones highlighted, titled with the prompt."""
    prints = {
        o.id: (
            catalogue.asset_for(o.asset, o.description).footprint(),
            o.position[0],
            o.position[1],
            quaternion_yaw(o.quaternion),
        )
        for o in solution.scene.objects
    }
    failed = [o.id for o in solution.scene.objects if o.status == "failed"]
    plot_layout(path, solution.scene.support, prints, highlight=failed, title=solution.scene.prompt or "")
