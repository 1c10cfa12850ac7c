"""`physcensis batch`: many scenes from a prompt file, resumable."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.markup import escape

from physcensis.cli.errors import ExitCode, err_console, fail, finish, reports_errors
from physcensis.cli.options import (
    ExportOption,
    LibraryOption,
    console,
    export_formats,
    takes_run_settings,
    with_libraries,
)
from physcensis.errors import PhyscensisError
from physcensis.settings import RunSettings

if TYPE_CHECKING:
    from rich.progress import Progress, TaskID

    from physcensis.batch import BatchSummary, Options, Outcome

StartHook = Callable[[int, int], None]
OutcomeHook = Callable[["Outcome", "BatchSummary"], None]


@reports_errors
@takes_run_settings
def batch(
    prompts: Annotated[Path, typer.Argument(help='prompts: .txt (one per line) or .jsonl ({"prompt", "support"})')],
    out: Annotated[Path, typer.Option("--out", "-o", help="batch folder: scenes/, manifest.jsonl, failures.jsonl")],
    per_prompt: Annotated[int, typer.Option("--per-prompt", min=0, help="scenes per prompt")] = 1,
    workers: Annotated[int, typer.Option(min=1, help="parallel worker processes (or Ray CPUs for a local Ray)")] = 1,
    ray: Annotated[bool, typer.Option("--ray", help="run the tasks on Ray (needs the ray extra)")] = False,
    ray_address: Annotated[
        str | None,
        typer.Option(
            "--ray-address", help="an existing Ray cluster, e.g. auto or ray://head:10001; --ray=ADDRESS says the same"
        ),
    ] = None,
    seed: Annotated[int, typer.Option(help="base seed; every scene gets its own seed from it")] = 0,
    export: ExportOption = "all",
    retry_failed: Annotated[
        bool, typer.Option("--retry-failed/--skip-failed", help="on a re-run, try recorded failures again")
    ] = True,
    scene_timeout: Annotated[
        float | None,
        typer.Option(
            "--scene-timeout",
            metavar="SECONDS",
            help="a scene still running after this is stopped and recorded in failures.jsonl; the run goes on",
        ),
    ] = None,
    library: LibraryOption = None,
    overwrite: Annotated[
        bool,
        typer.Option(
            "--overwrite",
            help="use a non-empty folder that is not a batch folder "
            "(the batch's own entries are added; nothing else is touched)",
        ),
    ] = False,
    *,
    settings: RunSettings,  # from the run's flags (cli/options.py's RUN_FLAGS), the same as `generate`'s
) -> None:
    """Generate many scenes. Re-running the same command resumes where a stopped or killed run left off."""
    from physcensis.assets.libraries import configured_libraries
    from physcensis.batch import Options, read_prompts, run_batch

    if library or configured_libraries():  # the built-ins need no check, nor the catalogue's 2 s import here
        with_libraries(library)  # a broken library is reported here, once, not by every worker
    options = Options(
        settings=settings,
        libraries=tuple(str(folder.resolve()) for folder in configured_libraries()),
        exports=export_formats(export),
        scene_timeout_s=scene_timeout,
    )
    specs = read_prompts(prompts)  # before the progress bar: a bad file is one line, not a bar and a line
    progress, started, finished = _progress_bar()
    try:
        summary = run_batch(
            specs,
            out,
            per_prompt=per_prompt,
            seed=seed,
            workers=workers,
            use_ray=ray or bool(ray_address),
            ray_address=ray_address,
            options=options,
            retry_failed=retry_failed,
            on_start=started,
            on_outcome=finished,
            overwrite=overwrite,
        )
    except (PhyscensisError, KeyboardInterrupt) as exc:
        progress.stop()  # before the error line, so the line is not drawn over by the bar
        raise _stopped(exc, options) from None
    progress.stop()
    console.print(
        f"{summary.made} scene(s) made, {summary.already_done} already there, {summary.failed} failed "
        f"in {summary.seconds:.1f} s ({summary.rate_line()}); manifest: "
        f"{out / 'manifest.jsonl'}"
    )
    if summary.stage_seconds:  # where a scene's time goes, so that a slower stage shows
        console.print(f"median per scene: {summary.stages_line()}", soft_wrap=True)
    _print_diversity(out)
    raise finish(not summary.failed)


def _print_diversity(out: Path) -> None:
    """The variety of each prompt's scenes in the batch folder, a line each (`eval diversity` tells more)."""
    from physcensis.batch import SCENES_DIR
    from physcensis.evaluation.diversity_files import measure_folder, summary_line

    try:
        run = measure_folder(out / SCENES_DIR)
    except PhyscensisError as exc:
        console.print(f"diversity: not measured ({escape(str(exc))})", soft_wrap=True)
        return
    console.print("diversity per prompt (physcensis eval diversity for more):")
    for result, _ in run.results:
        console.print(f"  {escape(result.prompt or '(no prompt)')}: {summary_line(result)}", soft_wrap=True)


def _stopped(exc: PhyscensisError | KeyboardInterrupt, options: Options) -> typer.Exit:
    if isinstance(exc, KeyboardInterrupt):
        return fail("stopped; run the same command again to resume", ExitCode.INTERRUPTED)
    return fail(options.redactor().text(str(exc)))  # an error may quote the LLM server's URL and its credentials


def _progress_bar() -> tuple[Progress, StartHook, OutcomeHook]:
    """The progress bar on stderr, started once the batch knows its size, and the two hooks that drive it."""
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    columns = (
        TextColumn("{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TextColumn("{task.fields[rate]:.1f} scenes/min, [red]{task.fields[failed]} failed[/]"),
        TimeElapsedColumn(),
    )
    progress = Progress(*columns, console=err_console, transient=False)
    handle: TaskID = progress.add_task("scenes", total=None, rate=0.0, failed=0)

    def started(total: int, done: int) -> None:
        progress.update(handle, total=total, completed=done)
        progress.start()

    def finished(outcome: Outcome, summary: BatchSummary) -> None:
        progress.update(handle, advance=1, rate=summary.scenes_per_minute, failed=summary.failed)
        if not outcome.ok:
            reason = escape(str(outcome.record.get("reason")))  # shown as written: "[redacted]" is not markup
            progress.console.print(f"[red]failed[/] {escape(outcome.task.key)}: {reason}", highlight=False)

    return progress, started, finished
