"""`physcensis solve`, `generate`, `export` and `render`: commands that make or write a scene."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated, NoReturn

import typer
from rich.markup import escape
from rich.table import Table

from physcensis.cli.errors import ExitCode, err_console, fail, finish, reports_errors
from physcensis.cli.options import (
    EXPORT_TO_CHOICES,
    ExportOption,
    ExportToOption,
    LibraryOption,
    MaxObjectsOption,
    OverwriteOption,
    console,
    export_formats,
    output_dir,
    scene_file,
    support_option,
    takes_run_settings,
    with_libraries,
    write_or_fail,
)
from physcensis.cli.programs import print_problems
from physcensis.program import DEFAULT_MAX_OBJECTS, load_program
from physcensis.settings import RunSettings

if TYPE_CHECKING:
    from physcensis.agent.account import Reading
    from physcensis.api import Generated
    from physcensis.solver.pipeline import Solution

MAX_RENDER_PX = 8192  # MuJoCo's offscreen buffer and the PNG must fit in memory


@reports_errors
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
    library: LibraryOption = None,
) -> None:
    """Solve a predicate program into a scene folder (scene.json, report.json, layout.png, render and exports)."""
    from physcensis.output import write_solution
    from physcensis.solver.pipeline import solve as solve_program

    support_override = support_option(support)
    formats = export_formats(export)
    output_dir(out, overwrite)
    program = load_program(file)
    catalogue = with_libraries(library)
    with console.status("solving…"):  # a PhyscensisError here is an argument no scene can hold (a negative seed)
        solution = solve_program(
            program, support=support_override, seed=seed, physics=physics, max_objects=max_objects, catalogue=catalogue
        )
    if not solution.check.ok:
        print_problems(solution.check.problems)
        raise fail(f"{file}: the program has {solution.check.summary()}; nothing was solved", ExitCode.PROBLEMS)
    with console.status("writing scene, render and exports…"):
        write_or_fail(
            lambda: write_solution(solution, out, physics_outputs=physics, exports=formats, overwrite=overwrite), out
        )
    if not physics and formats:
        console.print("no render or exports without physics (the poses are not verified); scene.json is written")
    _print_solution_summary(solution, out)
    for w in solution.warnings:  # a value the program asked for that the scene does not hold (an overlap, a stability)
        console.print(f"[yellow]not as asked:[/] {escape(w['text'])}")
    raise finish(solution.ok)


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
    console.print(
        f"placed {m.get('objects_placed', 0)}, failed {m.get('objects_failed', 0)}, "
        f"pending {m.get('objects_pending', 0)}{settle} in {solution.timings.get('total', 0):.2f} s"
    )
    if solution.spatial is not None and not solution.spatial.ok:
        console.print(solution.spatial.feedback())
    for row in solution.fallbacks():  # nouns the catalogue does not know: the user sees what stands in for them
        console.print(escape(f"{row['note']}: {', '.join(row['objects'])}"))


def _print_reading(reading: Reading) -> None:
    """One line: what each noun phrase of the prompt became (a thing placed, the support, the contents, nothing)."""
    parts = []
    for a in reading.phrases:
        said = escape(f"'{a.phrase}'")
        kinds = escape(", ".join(sorted({b.split(" (")[0] for b in a.became})))
        if a.status == "placed":
            short = f" ({a.placed} of {a.asked})" if a.asked is not None and a.placed < a.asked else ""
            parts.append(f"{said} -> {kinds}{short}")
        elif a.status == "missing":
            parts.append(f"{said} -> [red]nothing[/] ({escape(a.why)})")
        elif a.status == "elsewhere":
            parts.append(f"{said} -> {kinds}, [red]not where asked[/]")
        elif a.status in ("support", "contents", "landmark"):
            parts.append(f"{said} -> {a.status}")
    if parts:
        console.print("read: " + "; ".join(parts))


@reports_errors
@takes_run_settings
def generate(
    prompt: Annotated[str, typer.Argument(help="what the scene should show")],
    support: Annotated[
        str, typer.Option(help="support, e.g. table:1.2x0.8, shelf:0.3x0.9, floor:3x3, box:0.4x0.3")
    ] = "table:1.2x0.8",
    seed: Annotated[int, typer.Option(help="random seed")] = 0,
    out: Annotated[Path, typer.Option("--out", "-o", help="output folder (new, empty, or an earlier output)")] = Path(
        "out/scene"
    ),
    export: ExportOption = "all",
    overwrite: OverwriteOption = False,
    library: LibraryOption = None,
    *,
    settings: RunSettings,  # from the run's flags (cli/options.py's RUN_FLAGS), the same as `batch`'s
) -> None:
    """Generate a scene from a sentence: the agent writes a program, the solvers realise it, feedback refines it."""
    from physcensis.api import generate as generate_api
    from physcensis.api import write_generated

    support_value = support_option(support)
    formats = export_formats(export)
    output_dir(out, overwrite)
    catalogue = with_libraries(library)
    status = console.status("starting…")

    current_round: list[object] = [1]  # "receiving" (a streamed LLM reply's tokens) does not name its round

    def progress(stage: str, data: dict[str, object]) -> None:
        if stage == "receiving":
            status.update(f"round {current_round[0]}: receiving reply, {data.get('tokens')} tokens")
            return
        current_round[0] = data.get("round", current_round[0])
        words = {"propose": "agent is writing a program", "solve": "solving", "solved": "solved"}
        detail = ", ".join(f"{k} {v}" for k, v in data.items())
        status.update(f"{words.get(stage, stage)} ({detail})")

    with status:
        generated = generate_api(
            prompt, settings=settings, support=support_value, seed=seed, progress=progress, catalogue=catalogue
        )
    if generated.solution is None:
        _fail_with_record(generated, out, overwrite)
    with console.status("writing scene, render and exports…"):
        write_or_fail(lambda: write_generated(generated, out, exports=formats, overwrite=overwrite), out)
    _print_solution_summary(generated.solution, out)
    if generated.reading is not None:
        _print_reading(generated.reading)
    for row in generated.added:  # placed without being asked for: said here and in report.json, not only logged
        console.print(escape(f"added (not in the prompt): {row['id']} ({row['category']}), {row['why']}"))
    for row in generated.transcript:  # what the agent could not do as asked (a container none of whose kind is open)
        if "note" in row and "round" not in row:
            console.print(escape(f"note: {row['note']}"))
    vqa = f", VQA {generated.vqa:.2f}" if generated.vqa is not None else ""
    console.print(f"{generated.result.rounds} round(s), {generated.result.seconds:.1f} s{vqa}")
    if generated.result.stop_reason == "time-budget":
        console.print(f"stopped early: {generated.result.failure}; the best scene so far was written")
    undelivered = _print_undelivered(generated)
    # the scene is written either way; 1 says some objects failed in it or something asked for is missing or not
    # where it was asked
    raise finish(generated.solution.ok and not undelivered)


def _print_undelivered(generated: Generated) -> bool:
    """Say what was asked for and is not in the scene, or not where it was asked; whether there was any (never a
    clean success)."""
    missing, elsewhere = generated.missing, generated.elsewhere  # each computed from the scene and the reading
    for row in missing:
        console.print(
            escape(f"asked for and not in the scene: {row['category']} ({row['placed']} of {row['asked']} placed)")
        )
    for row in elsewhere:  # placed, but not in or on what the prompt put it in
        console.print(escape(f"not where asked: '{row['phrase']}' ({row['why']})"))
    return bool(missing or elsewhere)


def _fail_with_record(generated: Generated, out: Path, overwrite: bool) -> NoReturn:
    """Print the last feedback, write the failed run's record (transcript.jsonl, report.json) and exit 1."""
    from physcensis.api import write_generated

    for row in generated.transcript[-3:]:
        err_console.print(row.get("feedback") or row.get("error") or "", markup=False, highlight=False, soft_wrap=True)
    write_or_fail(lambda: write_generated(generated, out, overwrite=overwrite), out)
    why = " ".join(generated.redactor.text(generated.result.failure or "every round failed").split())
    raise fail(f"no scene could be generated ({why}); the record is in {out}", ExitCode.PROBLEMS)


@reports_errors
def export_command(
    path: Annotated[Path, typer.Argument(help="scene.json or a scene folder")],
    to: ExportToOption,
    out: Annotated[
        Path,
        typer.Option(
            "--out",
            "-o",
            help="folder to write into (new, empty, or a physcensis output such as the scene's own folder)",
        ),
    ],
    overwrite: OverwriteOption = False,
    library: LibraryOption = None,
) -> None:
    """Export a scene for another simulator or viewer: MJCF, URDF (+ bodies.json of poses), GLB, USD. A folder that
    holds another scene is refused; exports.json records which scene the exports come from."""
    from physcensis.export import export_scene, parse_formats
    from physcensis.export.manifest import refuse_other_scene
    from physcensis.fileio import output_directory
    from physcensis.output import open_scene

    formats = parse_formats(",".join(to))
    if not formats:
        raise fail(f"nothing to export: give --to {EXPORT_TO_CHOICES}")
    scene, catalogue = open_scene(scene_file(path), with_libraries(library))
    if not scene.placed:
        raise fail(f"{path}: the scene has no placed objects; nothing to export")
    refuse_other_scene(out, scene)
    output_dir(out, overwrite)
    written: dict[str, Path] = {}

    def write() -> None:
        with (
            console.status(f"exporting {', '.join(formats)}…"),
            output_directory(out, overwrite=overwrite, replace_owned=False) as staging,
        ):
            written.update(
                {
                    name: out / file.relative_to(staging)
                    for name, file in export_scene(scene, staging, formats, catalogue=catalogue, target=out).items()
                }
            )

    write_or_fail(write, out)
    for name, file in written.items():
        console.print(f"{name}: {escape(str(file))}")


@reports_errors
def render(
    path: Annotated[Path, typer.Argument(help="scene.json or a scene folder")],
    out: Annotated[Path, typer.Option("--out", "-o", help="PNG file to write (an existing PNG is replaced)")],
    view: Annotated[
        str, typer.Option(help="iso, iso-right, front, back, left, right (or side), top; or all: a sheet of them all")
    ] = "iso",
    azimuth: Annotated[
        float | None, typer.Option(help="degrees around the scene, instead of the view's: 180 looks from the front")
    ] = None,
    elevation: Annotated[
        float | None, typer.Option(help="degrees, instead of the view's: -90 looks straight down, 0 level")
    ] = None,
    distance: Annotated[
        float | None, typer.Option(help="metres from the camera to the point it aims at (default: fitted)")
    ] = None,
    fov: Annotated[float | None, typer.Option(help="vertical field of view in degrees (default 45)")] = None,
    size: Annotated[
        str, typer.Option(help="image size WxH in pixels; auto: 960 on the longer side, shaped to the scene")
    ] = "auto",
    overwrite: Annotated[bool, typer.Option("--overwrite", help="replace an existing file that is not a PNG")] = False,
    library: LibraryOption = None,
) -> None:
    """Render a scene headless with MuJoCo, the camera framed on the support and everything on it."""
    from physcensis.fileio import check_output_file
    from physcensis.imageio import PNG_MAGIC, save_png
    from physcensis.output import open_scene
    from physcensis.physics.mujoco_engine import MujocoEngine
    from physcensis.physics.render import VIEWS, Camera, RenderError, render_views, view_name

    _check_camera(azimuth, elevation, distance, fov)
    every = view == "all"
    try:
        name = "iso" if every else view_name(view)
    except RenderError as exc:
        raise fail(f"{exc} (or all)") from None
    chosen = None if size == "auto" else _render_size(size)
    check_output_file(out, overwrite=overwrite, suffixes=[PNG_MAGIC])
    scene, catalogue = open_scene(scene_file(path), with_libraries(library))
    engine = MujocoEngine(catalogue)
    labels: list[tuple[int, int, str]] = []
    if every:
        if any(v is not None for v in (azimuth, elevation, distance)):
            raise fail("--view all shows each view at its own angles: leave out --azimuth, --elevation, --distance")
        image, labels = render_views(engine.build(scene), scene, list(VIEWS), tile=chosen or (480, 360))
    else:
        camera = Camera(name, azimuth, elevation, distance, fov)
        image = engine.render(scene, view=camera, size=chosen)
    write_or_fail(lambda: save_png(out, image, labels), out)
    height, width = image.shape[:2]
    shown = "all views" if every else f"{view} view"
    console.print(f"wrote {escape(str(out))} ({width}x{height}, {shown}, {len(scene.placed)} objects)")


def _check_camera(azimuth: float | None, elevation: float | None, distance: float | None, fov: float | None) -> None:
    """Every camera number given is finite and within what a camera can be."""
    import math

    for flag, value in (("--azimuth", azimuth), ("--elevation", elevation), ("--distance", distance), ("--fov", fov)):
        if value is not None and not math.isfinite(value):
            raise fail(f"{flag} {value} must be a finite number")
    if elevation is not None and not -90.0 <= elevation <= 90.0:
        raise fail(f"--elevation {elevation:g} must be between -90 and 90 degrees")
    if distance is not None and not 0.0 < distance <= 1000.0:
        raise fail(f"--distance {distance:g} must be more than 0 and at most 1000 m")
    if fov is not None and not 1.0 <= fov <= 170.0:
        raise fail(f"--fov {fov:g} must be between 1 and 170 degrees")


def _render_size(size: str) -> tuple[int, int]:
    """`WxH` in pixels, each side within what MuJoCo's offscreen buffer can hold."""
    try:
        width, height = (int(v) for v in size.lower().split("x"))
    except ValueError:
        raise fail(f"size {size!r} must look like 960x720") from None
    if not (1 <= width <= MAX_RENDER_PX and 1 <= height <= MAX_RENDER_PX):
        raise fail(f"size {size!r}: width and height must be between 1 and {MAX_RENDER_PX} pixels")
    return width, height
