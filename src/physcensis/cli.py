"""The `physcensis` command: thin wrappers over the public API."""

from __future__ import annotations

import json
import math
import sys
from collections.abc import Callable, Sequence
from enum import StrEnum
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from physcensis.assets.cli import assets_app
from physcensis.errors import PhyscensisError
from physcensis.program import DEFAULT_MAX_OBJECTS, Problem, check_program, load_program, parse_program
from physcensis.program.checker import MAX_OBJECTS
from physcensis.program.registry import PREDICATES
from physcensis.scene import Support
from physcensis.stability_cli import stability


class Engine(StrEnum):
    mujoco = "mujoco"
    bullet = "bullet"


if TYPE_CHECKING:
    from physcensis.solve.pipeline import Solution

app = typer.Typer(
    name="physcensis",
    help="Dense, physically valid 3D scenes from a sentence or a predicate program.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)
app.add_typer(assets_app, name="assets", help="The asset catalogue: list, show, search, import, gallery.")
console = Console()
err_console = Console(stderr=True)

EXIT_OK, EXIT_PROBLEMS, EXIT_UNREADABLE = 0, 1, 2
MAX_RENDER_PX = 8192  # MuJoCo's offscreen buffer and the PNG must fit in memory


def _fail(message: str, code: int = EXIT_UNREADABLE) -> typer.Exit:
    err_console.print(f"[bold red]error:[/] {escape(message)}", highlight=False, soft_wrap=True)  # text, not markup
    return typer.Exit(code)


def _support_option(value: str | None) -> Support | None:
    if value is None:
        return None
    try:
        return Support.parse(value)
    except ValueError as exc:
        raise typer.BadParameter(str(exc)) from None


ExportOption = Annotated[
    str, typer.Option("--export", help="formats to write: comma list of mjcf,urdf,glb,usd, or all / none")
]
MaxObjectsOption = Annotated[
    int, typer.Option("--max-objects", min=1, max=MAX_OBJECTS, help="refuse a program that makes more objects "
                      "than this (declared, COPY-GROUP copies and PLACE-IN counts together)")
]


OverwriteOption = Annotated[
    bool, typer.Option("--overwrite", help="write into a non-empty folder that is not a physcensis output "
                       "(only physcensis's own files are replaced; the rest stay)")
]


def _output_dir(out: Path, overwrite: bool) -> Path:
    """Refuse an output folder that cannot or may not be written, before any work is done."""
    from physcensis.fileio import check_output_dir

    try:
        return check_output_dir(out, overwrite=overwrite)
    except PhyscensisError as exc:
        raise _fail(str(exc)) from None


def _export_formats(value: str) -> tuple[str, ...]:
    from physcensis.export import parse_formats

    try:
        return parse_formats(value)
    except PhyscensisError as exc:
        raise typer.BadParameter(str(exc), param_hint="--export") from None


@app.command()
def check(
    file: Annotated[Path, typer.Argument(help="program file (.json, or LLM text); '-' reads stdin")],
    as_json: Annotated[bool, typer.Option("--json", help="print problems as JSON")] = False,
    support: Annotated[
        str | None, typer.Option(help="support to check x/y against, e.g. table:1.2x0.8")
    ] = None,
    max_objects: MaxObjectsOption = DEFAULT_MAX_OBJECTS,
) -> None:
    """Parse and check a predicate program; exit 0 if it has no errors, 1 if it has, 2 if unreadable."""
    support_override = _support_option(support)
    try:
        if str(file) == "-":
            program = parse_program(sys.stdin.read())
        else:
            program = load_program(file)
    except PhyscensisError as exc:
        raise _fail(str(exc)) from None
    report = check_program(program, support_override, max_objects=max_objects)
    if as_json:
        typer.echo(json.dumps([p.to_dict() for p in report.problems], indent=2))
    else:
        if report.problems:
            _print_problems(report.problems)
        objects = len(program.declarations)
        verdict = "[green]ok[/]" if report.ok else "[red]has errors[/]"
        counts = f"{len(program.entries)} entries, {objects} declared objects, {report.summary()}"
        console.print(f"{escape(str(file))}: {counts} — {verdict}")
    raise typer.Exit(EXIT_OK if report.ok else EXIT_PROBLEMS)


@app.command()
def solve(
    file: Annotated[Path, typer.Argument(help="program file (.json, or LLM text)")],
    out: Annotated[Path, typer.Option("--out", "-o", help="output folder (new, empty, or an earlier output)")],
    seed: Annotated[int, typer.Option(help="random seed: same program and seed, same scene")] = 0,
    support: Annotated[
        str | None, typer.Option(help="support, e.g. table:1.2x0.8 (default: the program's, else table:1.2x0.8)")
    ] = None,
    physics: Annotated[bool, typer.Option("--physics/--no-physics", help="run the physical solver")] = True,
    export: ExportOption = "all",
    overwrite: OverwriteOption = False,
    max_objects: MaxObjectsOption = DEFAULT_MAX_OBJECTS,
) -> None:
    """Solve a predicate program into a scene folder (scene.json, report.json, layout.png, render and exports)."""
    from physcensis.solve.pipeline import solve as solve_program
    from physcensis.solve.pipeline import write_solution

    support_override = _support_option(support)
    formats = _export_formats(export)
    _output_dir(out, overwrite)
    try:
        program = load_program(file)
    except PhyscensisError as exc:
        raise _fail(str(exc)) from None
    with console.status("solving…"):
        try:
            solution = solve_program(program, support=support_override, seed=seed, physics=physics,
                                     max_objects=max_objects)
        except PhyscensisError as exc:  # an argument no scene can hold (a negative seed)
            raise _fail(str(exc)) from None
    if not solution.check.ok:
        _print_problems(solution.check.problems)
        raise _fail(f"{file}: the program has {solution.check.summary()}; nothing was solved", EXIT_PROBLEMS)
    with console.status("writing scene, render and exports…"):
        _write_or_fail(lambda: write_solution(solution, out, physics_outputs=physics, exports=formats,
                                              overwrite=overwrite), out)
    if not physics and formats:
        console.print("no render or exports without physics (the poses are not verified); scene.json is written")
    _print_solution_summary(solution, out)
    raise typer.Exit(EXIT_OK if solution.ok else EXIT_PROBLEMS)


def _write_or_fail(write: Callable[[], object], out: Path) -> None:
    try:
        write()
    except PhyscensisError as exc:
        raise _fail(str(exc)) from None
    except OSError as exc:
        raise _fail(f"{out}: cannot write there ({exc.strerror or exc})") from None


def _print_problems(problems: Sequence[Problem]) -> None:
    table = Table(show_header=True, header_style="bold")
    for column in ("#", "object", "severity", "message"):
        table.add_column(column, overflow="fold")
    for p in problems:
        style = "red" if p.severity == "error" else "yellow"
        table.add_row("" if p.index is None else str(p.index), escape(p.object or ""), f"[{style}]{p.severity}[/]",
                      escape(p.message))
    console.print(table)


def _print_solution_summary(solution: Solution, out: Path) -> None:
    table = Table(show_header=True, header_style="bold", title=f"scene written to {escape(str(out))}")
    for column in ("object", "asset", "status", "reason"):
        table.add_column(column, overflow="fold")
    for o in solution.scene.objects:
        style = "green" if o.status == "placed" else "red"
        table.add_row(o.id, escape(o.asset), f"[{style}]{o.status}[/]", escape(o.reason or ""))
    for p in solution.pending:
        where = f"{p['predicate']} (#{p['entry']})"
        table.add_row(escape(", ".join(p["objects"])), "", "[yellow]pending[/]", escape(where))
    console.print(table)
    m = solution.scene.metrics
    settle = f", settle distance {m['settle_distance_m'] * 1000:.2f} mm" if "settle_distance_m" in m else ""
    console.print(f"placed {m.get('objects_placed', 0)}, failed {m.get('objects_failed', 0)}, "
                  f"pending {m.get('objects_pending', 0)}{settle} in {solution.timings.get('total', 0):.2f} s")
    if solution.spatial is not None and not solution.spatial.ok:
        console.print(solution.spatial.feedback())


def _positive_seconds(value: float, flag: str) -> float:
    if not math.isfinite(value) or value <= 0:
        raise typer.BadParameter(f"must be a positive number of seconds, not {value}", param_hint=flag)
    return value


@app.command()
def generate(
    prompt: Annotated[str, typer.Argument(help="what the scene should show")],
    support: Annotated[str, typer.Option(help="support, e.g. table:1.2x0.8, shelf:0.3x0.9, floor:3x3, box:0.4x0.3")]
    = "table:1.2x0.8",
    llm: Annotated[str | None, typer.Option(help="an OpenAI-compatible chat model plays the agent")] = None,
    base_url: Annotated[str | None, typer.Option(help="its server, e.g. http://localhost:8000/v1")] = None,
    vlm: Annotated[str | None, typer.Option(help="a vision model scores the render (VQA)")] = None,
    seed: Annotated[int, typer.Option(help="random seed")] = 0,
    rounds: Annotated[int, typer.Option(min=1, help="successful rounds; more than 1 enriches the scene")] = 1,
    min_objects: Annotated[int, typer.Option(help="keep enriching until this many objects are placed")] = 0,
    out: Annotated[Path, typer.Option("--out", "-o", help="output folder (new, empty, or an earlier output)")]
    = Path("out/scene"),
    export: ExportOption = "all",
    overwrite: OverwriteOption = False,
    llm_timeout: Annotated[float, typer.Option(
        "--llm-timeout", metavar="SECONDS", callback=lambda v: _positive_seconds(v, "--llm-timeout"),
        help="wall-clock limit of one LLM or VLM request, retries and their waits included")] = 300.0,
    max_objects: MaxObjectsOption = DEFAULT_MAX_OBJECTS,
) -> None:
    """Generate a scene from a sentence: the agent writes a program, the solvers realise it, feedback refines it."""
    from physcensis.api import generate as generate_api
    from physcensis.api import write_generated

    support_value = _support_option(support)
    formats = _export_formats(export)
    _output_dir(out, overwrite)
    status = console.status("starting…")

    def progress(stage: str, data: dict[str, object]) -> None:
        words = {"propose": "agent is writing a program", "solve": "solving", "solved": "solved"}
        detail = ", ".join(f"{k} {v}" for k, v in data.items())
        status.update(f"{words.get(stage, stage)} ({detail})")

    with status:
        try:
            generated = generate_api(prompt, support=support_value, llm=llm, base_url=base_url, vlm=vlm, seed=seed,
                                     rounds=rounds, min_objects=min_objects, progress=progress,
                                     llm_timeout_s=llm_timeout, max_objects=max_objects)
        except PhyscensisError as exc:
            raise _fail(str(exc)) from None
    if generated.solution is None:
        for row in generated.transcript[-3:]:
            err_console.print(row.get("feedback") or row.get("error") or "", markup=False, highlight=False,
                              soft_wrap=True)
        raise _fail("no scene could be generated (see the feedback above)", EXIT_PROBLEMS)
    with console.status("writing scene, render and exports…"):
        _write_or_fail(lambda: write_generated(generated, out, exports=formats, overwrite=overwrite), out)
    _print_solution_summary(generated.solution, out)
    vqa = f", VQA {generated.vqa:.2f}" if generated.vqa is not None else ""
    console.print(f"{generated.result.rounds} round(s), {generated.result.seconds:.1f} s{vqa}")


eval_app = typer.Typer(help="Measure scenes: settle distance.", no_args_is_help=True)
app.add_typer(eval_app, name="eval")


def _scene_paths(path: Path) -> list[Path]:
    if path.is_dir() and not (path / "scene.json").is_file():
        found = sorted(path.rglob("scene.json"))
        if not found:
            raise _fail(f"{path}: no scene.json in this folder or below it")
        return found
    return [path]


@eval_app.command("settle")
def eval_settle(
    path: Annotated[Path, typer.Argument(help="scene.json, a scene folder, or a folder of scene folders")],
    as_json: Annotated[bool, typer.Option("--json", help="print JSON")] = False,
    engine_name: Annotated[
        Engine, typer.Option("--engine", help="mujoco, or bullet (PyBullet on the URDF export; needs the bullet extra)")
    ] = Engine.mujoco,
) -> None:
    """Settle distance (the paper's: 4 s of free fall, displacement clamped at 1 m, mean over objects)."""
    from physcensis.scene import load_scene

    engine = _settle_engine(engine_name)
    rows = []
    for scene_path in _scene_paths(path):
        try:
            scene = load_scene(scene_path)
        except PhyscensisError as exc:
            raise _fail(str(exc)) from None
        try:
            result = engine.settle_distance(scene)
        except PhyscensisError as exc:
            raise _fail(f"{scene_path}: {exc}") from None
        if result.diverged:  # no distance at all, rather than the 0 or 1 m of a run that was stopped
            rows.append({"scene": str(scene_path), "engine": engine_name.value, "settle_distance_m": None,
                         "per_object_m": {}, "diverged": result.diverged})
            continue
        rows.append({"scene": str(scene_path), "engine": engine_name.value, "settle_distance_m": result.mean_m,
                     "per_object_m": result.per_object})
    measured = [r["settle_distance_m"] for r in rows if r["settle_distance_m"] is not None]
    overall = sum(measured) / len(measured) if measured else None
    diverged = [r for r in rows if r.get("diverged")]
    if as_json:
        typer.echo(json.dumps({"scenes": rows, "mean_m": overall, "diverged": len(diverged)}, indent=2))
    else:
        _print_settle_table(rows, engine_name, overall)
    for row in diverged:
        err_console.print(f"[bold red]error:[/] {escape(row['scene'])}: {escape(row['diverged'])}; no settle "
                          "distance can be measured", highlight=False, soft_wrap=True)
    if diverged:
        raise typer.Exit(EXIT_PROBLEMS)


def _print_settle_table(rows: list[dict], engine_name: Engine, overall: float | None) -> None:
    table = Table(show_header=True, header_style="bold")
    for column in ("scene", "object", "settle distance (mm)"):
        table.add_column(column)
    for row in rows:
        if row.get("diverged"):
            table.add_row(escape(row["scene"]), "[bold]mean[/]", "[bold red]diverged[/]")
            continue
        for oid, value in row["per_object_m"].items():
            table.add_row(escape(row["scene"]), oid, f"{value * 1000:.3f}")
        table.add_row(escape(row["scene"]), "[bold]mean[/]", f"[bold]{row['settle_distance_m'] * 1000:.3f}[/]")
    console.print(table)
    measured = sum(1 for r in rows if not r.get("diverged"))
    if overall is None:
        console.print(f"settle distance ({engine_name.value}): every scene diverged")
    else:
        console.print(f"settle distance ({engine_name.value}) over {measured} scene(s): {overall * 1000:.3f} mm")


def _settle_engine(name: Engine):  # noqa: ANN202
    if name is Engine.bullet:
        from physcensis.physics.bullet_engine import BulletEngine, require_pybullet

        try:
            require_pybullet()
        except PhyscensisError as exc:
            raise _fail(str(exc)) from None
        return BulletEngine()
    from physcensis.physics.mujoco_engine import MujocoEngine

    return MujocoEngine()


@app.command()
def batch(
    prompts: Annotated[Path, typer.Argument(help="prompts: .txt (one per line) or .jsonl ({\"prompt\", \"support\"})")],
    out: Annotated[Path, typer.Option("--out", "-o", help="batch folder: scenes/, manifest.jsonl, failures.jsonl")],
    per_prompt: Annotated[int, typer.Option("--per-prompt", min=0, help="scenes per prompt")] = 1,
    workers: Annotated[int, typer.Option(min=1, help="parallel worker processes (or Ray CPUs for a local Ray)")] = 1,
    ray: Annotated[bool, typer.Option("--ray", help="run the tasks on Ray (needs the ray extra)")] = False,
    ray_address: Annotated[
        str | None, typer.Option("--ray-address", help="an existing Ray cluster, e.g. auto or ray://head:10001; "
                                 "--ray=ADDRESS says the same")
    ] = None,
    seed: Annotated[int, typer.Option(help="base seed; every scene gets its own seed from it")] = 0,
    export: ExportOption = "all",
    llm: Annotated[str | None, typer.Option(help="an OpenAI-compatible chat model plays the agent")] = None,
    base_url: Annotated[str | None, typer.Option(help="its server, e.g. http://localhost:8000/v1")] = None,
    retry_failed: Annotated[bool, typer.Option("--retry-failed/--skip-failed",
                                               help="on a re-run, try recorded failures again")] = True,
    scene_timeout: Annotated[float | None, typer.Option(
        "--scene-timeout", metavar="SECONDS",
        help="a scene still running after this is stopped and recorded in failures.jsonl; the run goes on")] = None,
    llm_timeout: Annotated[float, typer.Option(
        "--llm-timeout", metavar="SECONDS", help="wall-clock limit of one LLM request, retries included")] = 300.0,
    overwrite: Annotated[bool, typer.Option("--overwrite", help="use a non-empty folder that is not a batch folder "
                                            "(the batch's own entries are added; nothing else is touched)")] = False,
) -> None:
    """Generate many scenes. Re-running the same command resumes where a stopped or killed run left off."""
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    from physcensis.batch import Options, read_prompts, run_batch

    options = Options(exports=_export_formats(export), llm=llm, base_url=base_url, llm_timeout_s=llm_timeout,
                      scene_timeout_s=scene_timeout)
    try:
        specs = read_prompts(prompts)  # before the progress bar: a bad file is one line, not a bar and a line
    except PhyscensisError as exc:
        raise _fail(str(exc)) from None
    columns = (TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
               TextColumn("{task.fields[rate]:.1f} scenes/min, [red]{task.fields[failed]} failed[/]"),
               TimeElapsedColumn())
    progress = Progress(*columns, console=err_console, transient=False)
    handle = progress.add_task("scenes", total=None, rate=0.0, failed=0)

    def started(total: int, done: int) -> None:
        progress.update(handle, total=total, completed=done)
        progress.start()

    def finished(outcome, summary) -> None:  # noqa: ANN001
        progress.update(handle, advance=1, rate=summary.scenes_per_minute, failed=summary.failed)
        if not outcome.ok:
            reason = escape(str(outcome.record.get("reason")))  # shown as written: "[redacted]" is not markup
            progress.console.print(f"[red]failed[/] {escape(outcome.task.key)}: {reason}", highlight=False)

    try:
        summary = run_batch(specs, out, per_prompt=per_prompt, seed=seed, workers=workers,
                            use_ray=ray or bool(ray_address), ray_address=ray_address, options=options,
                            retry_failed=retry_failed, on_start=started, on_outcome=finished, overwrite=overwrite)
    except PhyscensisError as exc:
        progress.stop()
        raise _fail(options.redactor().text(str(exc))) from None
    except KeyboardInterrupt:
        progress.stop()
        raise _fail("stopped; run the same command again to resume", 130) from None
    progress.stop()
    console.print(f"{summary.made} scene(s) made, {summary.already_done} already there, {summary.failed} failed "
                  f"in {summary.seconds:.1f} s ({summary.scenes_per_minute:.1f} scenes/min); manifest: "
                  f"{out / 'manifest.jsonl'}")
    if summary.failed:
        raise typer.Exit(EXIT_PROBLEMS)


@app.command("export")
def export_command(
    path: Annotated[Path, typer.Argument(help="scene.json or a scene folder")],
    to: Annotated[list[str], typer.Option("--to", help="mjcf, urdf, glb, usd or all (repeat or comma-separate)")],
    out: Annotated[Path, typer.Option("--out", "-o", help="folder to write into (new, empty, or a physcensis "
                                      "output such as the scene's own folder)")],
    overwrite: OverwriteOption = False,
) -> None:
    """Export a scene for another simulator or viewer: MJCF, URDF (+ bodies.json of poses), GLB, USD."""
    from physcensis.export import export_scene, parse_formats
    from physcensis.fileio import output_directory
    from physcensis.scene import load_scene

    try:
        formats = parse_formats(",".join(to))
        if not formats:
            raise _fail("nothing to export: give --to mjcf, urdf, glb, usd or all")
        scene = load_scene(path)
        if not scene.placed:
            raise _fail(f"{path}: the scene has no placed objects; nothing to export")
        _output_dir(out, overwrite)
        with console.status(f"exporting {', '.join(formats)}…"), \
                output_directory(out, overwrite=overwrite, replace_owned=False) as staging:
            written = {name: out / file.relative_to(staging)
                       for name, file in export_scene(scene, staging, formats).items()}
    except PhyscensisError as exc:
        raise _fail(str(exc)) from None
    except OSError as exc:
        raise _fail(f"{out}: cannot write there ({exc.strerror or exc})") from None
    for name, file in written.items():
        console.print(f"{name}: {escape(str(file))}")


bench_app = typer.Typer(help="The paper's benchmarks.", no_args_is_help=True)
app.add_typer(bench_app, name="bench")


@bench_app.command("clutter")
def bench_clutter(
    mode: Annotated[str, typer.Option(help="no-stack, with-stack or with-skip")] = "with-stack",
    scenes: Annotated[int, typer.Option(min=1, help="number of seeded scenes")] = 10,
    seed: Annotated[int, typer.Option(help="seed of the first scene")] = 0,
    overhang: Annotated[bool, typer.Option(help="objects may stick out past the table edge if they rest stably")]
    = False,
    as_json: Annotated[bool, typer.Option("--json", help="print the summary as JSON")] = False,
    out: Annotated[Path | None, typer.Option(help="save every scene's folder here")] = None,
    overwrite: Annotated[bool, typer.Option("--overwrite", help="save into a non-empty folder that holds other "
                                            "things (they are left alone)")] = False,
) -> None:
    """The clutter-count protocol: YCB dining objects placed with PLACE-ANYWHERE until one does not fit."""
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    from physcensis.bench import clutter

    if mode not in clutter.MODES:
        raise _fail(f"unknown mode {mode!r}; choose one of {', '.join(clutter.MODES)}")
    if out is not None:
        _clutter_folder(out, overwrite)
        for i in range(scenes):
            _output_dir(out / clutter.scene_folder_name(mode, seed + i), overwrite=False)
    with Progress(TextColumn("[bold]clutter {task.fields[mode]}"), BarColumn(), MofNCompleteColumn(),
                  TextColumn("last: {task.fields[last]} objects"), TimeElapsedColumn(), console=err_console,
                  disable=as_json) as progress:
        task = progress.add_task("scenes", total=scenes, mode=mode, last="-")
        summary = clutter.run(mode, scenes, seed, out_dir=out, overhang=overhang,  # type: ignore[arg-type]
                              progress=lambda i, r: progress.update(task, advance=1, last=str(r.placed)))
    if as_json:
        typer.echo(json.dumps(summary, indent=2))
        return
    console.print(f"{mode}{' (overhang allowed)' if overhang else ''}: {summary['mean_objects']:.2f} ± "
                  f"{summary['std_objects']:.2f} objects over {scenes} scenes "
                  f"(paper: {summary['paper'].get(mode, '-')}); {summary['mean_seconds_per_scene']:.1f} s per "
                  f"scene; settle distance {summary['mean_settle_distance_m'] * 1000:.3f} mm")


def _clutter_folder(out: Path, overwrite: bool) -> None:
    """The folder of clutter scenes: new, empty or holding only clutter scenes, unless --overwrite."""
    import re

    from physcensis.fileio import owned_entries

    if out.is_symlink() or (out.exists() and not out.is_dir()):
        raise _fail(f"{out}: is {'a symbolic link' if out.is_symlink() else 'not a folder'}; give a folder")
    if not out.is_dir() or overwrite:
        return
    scene_name = re.compile(r"(no-stack|with-stack|with-skip)_\d{4,}")
    foreign = [e.name for e in out.iterdir()
               if not (scene_name.fullmatch(e.name) and e.is_dir() and not e.is_symlink() and owned_entries(e))]
    if foreign:
        raise _fail(f"{out}: holds other things than clutter scenes ({', '.join(sorted(foreign)[:3])}); give an "
                    "empty or new folder, or --overwrite to add the scenes beside them")


@app.command()
def render(
    path: Annotated[Path, typer.Argument(help="scene.json or a scene folder")],
    out: Annotated[Path, typer.Option("--out", "-o", help="PNG file to write (an existing PNG is replaced)")],
    view: Annotated[str, typer.Option(help="front, top or iso")] = "iso",
    size: Annotated[str, typer.Option(help="image size WxH in pixels")] = "960x720",
    overwrite: Annotated[bool, typer.Option("--overwrite", help="replace an existing file that is not a PNG")]
    = False,
) -> None:
    """Render a scene headless with MuJoCo."""
    from physcensis.fileio import check_output_file
    from physcensis.imageio import PNG_MAGIC, save_png
    from physcensis.physics.mujoco_engine import MujocoEngine
    from physcensis.physics.render import VIEWS
    from physcensis.scene import load_scene

    if view not in VIEWS:
        raise _fail(f"unknown view {view!r}; choose one of {', '.join(VIEWS)}")
    try:
        width, height = (int(v) for v in size.lower().split("x"))
    except ValueError:
        raise _fail(f"size {size!r} must look like 960x720") from None
    if not (1 <= width <= MAX_RENDER_PX and 1 <= height <= MAX_RENDER_PX):
        raise _fail(f"size {size!r}: width and height must be between 1 and {MAX_RENDER_PX} pixels")
    try:
        check_output_file(out, overwrite=overwrite, suffixes=[PNG_MAGIC])
        scene = load_scene(path)
        image = MujocoEngine().render(scene, view=view, size=(width, height))  # type: ignore[arg-type]
    except PhyscensisError as exc:
        raise _fail(str(exc)) from None
    _write_or_fail(lambda: save_png(out, image), out)
    console.print(f"wrote {escape(str(out))} ({width}x{height}, {view} view, {len(scene.placed)} objects)")


@app.command()
def predicates(
    as_json: Annotated[bool, typer.Option("--json", help="print the registry as JSON")] = False,
) -> None:
    """List the predicates the language knows, with their parameters."""
    if as_json:
        rows = [
            {
                "name": s.name, "kind": s.kind.value, "summary": s.summary, "effect": s.effect,
                "determines": sorted(a.value for a in s.determines),
                "params": [
                    {"name": p.name, "type": p.type.value, "default": p.default, "required": p.required,
                     "range": [p.low, p.high] if p.low is not None else None, "optimisable": p.optimisable}
                    for p in s.params
                ],
            }
            for s in PREDICATES.values()
        ]
        typer.echo(json.dumps(rows, indent=2))
        return
    table = Table(show_header=True, header_style="bold")
    for column in ("predicate", "kind", "effect", "parameters"):
        table.add_column(column, overflow="fold")
    for s in PREDICATES.values():
        params = ", ".join(p.name + ("*" if p.required else "") for p in s.params)
        table.add_row(s.name, s.kind.value, escape(s.effect), escape(params))
    console.print(table)


app.command("stability")(stability)


def _ray_address_form(args: list[str]) -> list[str]:
    """`batch --ray=ADDRESS` is `--ray --ray-address ADDRESS` (Typer has no options with an optional value)."""
    out: list[str] = []
    for arg in args:
        if arg.startswith("--ray=") and out[:1] == ["batch"]:
            out += ["--ray", "--ray-address", arg.removeprefix("--ray=")]
        else:
            out.append(arg)
    return out


def main() -> None:
    """Console entry point: user errors print one line, never a traceback."""
    try:
        app(args=_ray_address_form(sys.argv[1:]))
    except PhyscensisError as exc:
        err_console.print(f"[bold red]error:[/] {escape(str(exc))}", highlight=False, soft_wrap=True)
        sys.exit(EXIT_UNREADABLE)
    except KeyboardInterrupt:
        err_console.print("interrupted")
        sys.exit(130)
