"""`physcensis eval settle|relations|vqa|compare|diversity` and `physcensis stability`: measure saved scenes."""

from __future__ import annotations

import json
from enum import StrEnum
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from rich.markup import escape
from rich.table import Table

from physcensis.cli.errors import ExitCode, err_console, fail, finish, print_error, reports_errors
from physcensis.cli.options import (
    LibraryOption,
    VqaOption,
    console,
    no_scene_file,
    scene_file,
    with_libraries,
)
from physcensis.crosscheck.engines import SETTLE_ENGINES, settle_engine
from physcensis.errors import PhyscensisError
from physcensis.physics.engine import SETTLE_S, SETTLE_STEP_S

if TYPE_CHECKING:  # the commands import the physics only when they run, so the CLI starts fast
    from physcensis.assets.catalogue import Catalogue
    from physcensis.evaluation.diversity import ExpectCheck
    from physcensis.evaluation.diversity_files import DiversityRun
    from physcensis.evaluation.relations import SceneRelations
    from physcensis.physics.engine import SettleEngine
    from physcensis.solver.stability import SceneStability

MAX_SETTLE_S = 600.0  # `eval settle --seconds`: ten minutes of simulated time per scene at most

eval_app = typer.Typer(
    help="Measure scenes: settle distance, relation accuracy, VQA score; compare methods.", no_args_is_help=True
)


# The choices of `eval settle --engine`: every registered settle engine.
Engine = StrEnum("Engine", {name.replace("-", "_"): name for name in SETTLE_ENGINES})  # type: ignore[misc]
DEFAULT_ENGINE = Engine("mujoco")


def _scene_paths(path: Path) -> list[Path]:
    if path.is_dir() and not (path / "scene.json").is_file():
        found = sorted(path.rglob("scene.json"))
        if not found:
            raise no_scene_file(path, below=True)
        return found
    return [path]


@eval_app.command("settle")
@reports_errors
def eval_settle(
    path: Annotated[Path, typer.Argument(help="scene.json, a scene folder, or a folder of scene folders")],
    as_json: Annotated[bool, typer.Option("--json", help="print JSON")] = False,
    engine_name: Annotated[
        Engine,
        typer.Option(
            "--engine",
            help="; ".join(f"{r.name}: {r.help}" for r in SETTLE_ENGINES.values()),
        ),
    ] = DEFAULT_ENGINE,
    seconds: Annotated[
        float,
        typer.Option(
            "--seconds",
            min=SETTLE_STEP_S,
            max=MAX_SETTLE_S,
            help="how long the scene falls (the paper's 4 s; longer shows what creeps, e.g. under MuJoCo's defaults)",
        ),
    ] = SETTLE_S,
    library: LibraryOption = None,
) -> None:
    """Settle distance (the paper's: 4 s of free fall, displacement clamped at 1 m, mean over objects)."""
    with_libraries(library)
    _settle_engine(engine_name, None)  # a missing simulator is one error line before any scene is read
    rows = [_settle_row(engine_name, scene_path, seconds) for scene_path in _scene_paths(path)]
    measured = [r["settle_distance_m"] for r in rows if r["settle_distance_m"] is not None]
    overall = sum(measured) / len(measured) if measured else None
    diverged = [r for r in rows if r.get("diverged")]
    if as_json:
        summary = {"scenes": rows, "mean_m": overall, "diverged": len(diverged), "seconds": seconds}
        typer.echo(json.dumps(summary, indent=2))
    else:
        _print_settle_table(rows, engine_name, overall, seconds)
    for row in diverged:
        print_error(f"{row['scene']}: {row['diverged']}; no settle distance can be measured")
    raise finish(not diverged)


def _settle_row(engine_name: Engine, scene_path: Path, seconds: float) -> dict[str, Any]:
    """One scene's settle distance; a diverged simulation has none, rather than the 0 or 1 m of a stopped run."""
    from physcensis.output import open_scene

    scene, catalogue = open_scene(scene_path)  # with the scene folder's own copies of library assets
    try:
        result = _settle_engine(engine_name, catalogue).settle_distance(scene, duration_s=seconds)
    except PhyscensisError as exc:
        raise fail(f"{scene_path}: {exc}") from None
    if result.diverged:
        return {
            "scene": str(scene_path),
            "engine": engine_name.value,
            "settle_distance_m": None,
            "per_object_m": {},
            "diverged": result.diverged,
        }
    return {
        "scene": str(scene_path),
        "engine": engine_name.value,
        "settle_distance_m": result.mean_m,
        "per_object_m": result.per_object,
    }


def _print_settle_table(rows: list[dict[str, Any]], engine_name: Engine, overall: float | None, seconds: float) -> None:
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
        console.print(f"settle distance ({engine_name.value}, {seconds:g} s): every scene diverged")
    else:
        console.print(
            f"settle distance ({engine_name.value}, {seconds:g} s) over {measured} scene(s): {overall * 1000:.3f} mm"
        )


def _settle_engine(name: Engine, catalogue: Catalogue | None) -> SettleEngine:
    return settle_engine(name.value, catalogue)


@reports_errors
def stability(
    scene_path: Annotated[Path, typer.Argument(help="scene.json or a scene folder")],
    object_id: Annotated[str | None, typer.Option("--object", help="only this object")] = None,
    samples: Annotated[
        int, typer.Option("--samples", min=8, help="perturbed simulations per object, per round of draws")
    ] = 128,
    min_effective: Annotated[
        float,
        typer.Option(
            "--min-effective",
            min=0.0,
            help="draw rounds until each estimate rests on this many effective samples (at most 1024 draws)",
        ),
    ] = 80.0,
    as_json: Annotated[bool, typer.Option("--json", help="print JSON")] = False,
    seed: Annotated[int, typer.Option(help="random seed of the perturbations")] = 0,
    library: LibraryOption = None,
) -> None:
    """p_fail of each placed object (or one): the kernel-weighted share of perturbed simulations in which it fell
    (moved more than 1 cm or turned more than 10 degrees within 0.8 s), with its 95 % interval. The scene's p_fail is
    its most fragile object's."""
    from physcensis.output import open_scene
    from physcensis.physics.mujoco_engine import MujocoEngine
    from physcensis.solver.stability import estimate_scene_stability

    scene, catalogue = open_scene(scene_file(scene_path), with_libraries(library))
    placed = [o.id for o in scene.placed]
    if object_id is not None and object_id not in placed:
        known = ", ".join(placed) or "none"
        raise fail(f"{scene_path}: no placed object {object_id!r} (placed: {known})", ExitCode.USAGE)
    result = estimate_scene_stability(
        scene,
        [object_id] if object_id else placed,
        samples,
        seed,
        engine=MujocoEngine(catalogue),
        min_effective=min_effective or None,
    )
    if as_json:
        typer.echo(json.dumps({"scene": str(scene_path), "seed": seed} | result.to_dict(), indent=2))
        return
    _print_stability_table(result)


def _print_stability_table(result: SceneStability) -> None:
    table = Table(show_header=True, header_style="bold")
    for column in ("object", "p_fail", "95 % interval", "fell / samples", "effective samples", "time (s)"):
        table.add_column(column, justify="left" if column == "object" else "right")
    for e in result.objects.values():
        low, high = e.interval
        table.add_row(
            escape(e.object_id),
            f"{e.p_fail:.3f}",
            f"{low:.3f} – {high:.3f}",
            f"{e.fell} / {e.samples}",
            f"{e.effective_samples:.0f}",
            f"{e.wall_s:.2f}",
        )
    console.print(table)
    console.print(f"scene p_fail (most fragile object): {result.p_fail:.3f}; mean {result.mean_p_fail:.3f}")


@eval_app.command("relations")
@reports_errors
def eval_relations(
    path: Annotated[Path, typer.Argument(help="a scene folder, or a folder of scene folders")],
    as_json: Annotated[bool, typer.Option("--json", help="print JSON (every check with its measured value)")] = False,
    library: LibraryOption = None,
) -> None:
    """Relation accuracy: every relation of each scene's program checked on its final poses."""
    from physcensis.evaluation.relations import check_scene_folder_or_error, scene_folders

    with_libraries(library)
    folders = scene_folders(path)
    if not folders:
        raise no_scene_file(path, below=True)
    results = [check_scene_folder_or_error(folder) for folder in folders]
    total = sum(len(r.checks) for r in results)
    overall = sum(r.satisfied for r in results) / total if total else None
    if as_json:
        typer.echo(json.dumps({"scenes": [r.to_dict() for r in results], "accuracy": overall}, indent=2))
    else:
        _print_relations_table(results)
        console.print(f"relation accuracy over {total} relation(s): {'-' if overall is None else f'{overall:.3f}'}")
    broken = [r for r in results if r.error is not None]
    for r in broken:
        print_error(f"{r.scene}: not scored: {r.error}")
    raise finish(not broken)


def _print_relations_table(results: list[SceneRelations]) -> None:
    table = Table(show_header=True, header_style="bold")
    for column in ("scene", "relations", "hold", "accuracy", "failing"):
        table.add_column(column)
    for r in results:
        if r.error is not None:
            table.add_row(escape(r.scene), "-", "-", "[bold red]error[/]", escape(r.error[:300]))
            continue
        failing = "; ".join(f"{c.predicate} {c.subject}->{c.target}: {c.detail}" for c in r.checks if not c.holds)
        accuracy = "-" if r.accuracy is None else f"{r.accuracy:.3f}"
        table.add_row(escape(r.scene), str(len(r.checks)), str(r.satisfied), accuracy, escape(failing[:300]))
    console.print(table)


@eval_app.command("rank")
@reports_errors
def eval_rank(
    path: Annotated[Path, typer.Argument(help="a comparison folder (eval compare --out): its results.jsonl")],
    vlm: Annotated[str, typer.Option("--vlm", help="an OpenAI-compatible vision model")],
    base_url: Annotated[str | None, typer.Option("--base-url", help="its server, e.g. http://localhost:8000/v1")] = (
        None
    ),
    draws: Annotated[int, typer.Option(min=1, max=20, help="showings per prompt and seed, each in a new order")] = 3,
    seed: Annotated[int, typer.Option(help="seed of the showing orders")] = 0,
    timeout: Annotated[float, typer.Option("--timeout", min=1.0, help="seconds per question, retries included")] = (
        120.0
    ),
    as_json: Annotated[bool, typer.Option("--json", help="print JSON")] = False,
) -> None:
    """The paper's ranking: a vision model ranks the methods' renders of each prompt and seed, best first, over
    several showings in shuffled orders; the mean rank of each method (1 is best). Writes PATH/rank.json."""
    from physcensis.evaluation.compare import read_rows
    from physcensis.evaluation.rank import Ranker, mean_ranks, rank_rows
    from physcensis.fileio import atomic_write_text

    if not vlm.strip():
        raise fail("--vlm is empty: name the vision model", ExitCode.USAGE)
    rows = read_rows(path)
    if not rows:
        raise fail(f"{path}: no results.jsonl rows to rank (run eval compare --out {path} first)", ExitCode.USAGE)
    with console.status(f"asking {escape(vlm)} to rank the methods…"):
        groups = rank_rows(rows, path, Ranker(vlm, base_url, draws, seed, timeout))
    means = mean_ranks(groups)
    errors = sorted({g.error for g in groups if g.error})
    summary = {
        "vlm": vlm,
        "draws": draws,
        "groups": len(groups),
        "unread_draws": sum(g.unread for g in groups),
        "methods": means,
        "per_group": [{"prompt_id": g.prompt_id, "seed": g.seed, "ranks": g.ranks} for g in groups],
        "errors": errors,
    }
    atomic_write_text(path / "rank.json", json.dumps(summary, indent=2) + "\n")
    if as_json:
        typer.echo(json.dumps(summary, indent=2))
    else:
        table = Table(show_header=True, header_style="bold")
        for column in ("method", "mean rank (1 is best)", "groups"):
            table.add_column(column)
        for method, stats in means.items():
            table.add_row(escape(method), f"{stats['mean']:.2f} ± {stats['std']:.2f}", f"{stats['groups']:.0f}")
        console.print(table)
        if summary["unread_draws"]:
            console.print(f"{summary['unread_draws']} answer(s) named no full order and were not counted")
    for error in errors:
        err_console.print(f"error: {escape(error)}")
    if not means:
        raise fail("no group of two or more methods' renders could be ranked", ExitCode.PROBLEMS)


@eval_app.command("vqa")
@reports_errors
def eval_vqa(
    path: Annotated[Path, typer.Argument(help="a scene folder, or a folder of scene folders")],
    vlm: Annotated[str, typer.Option("--vlm", help="an OpenAI-compatible vision model")],
    base_url: Annotated[str | None, typer.Option("--base-url", help="its server, e.g. http://localhost:8000/v1")] = (
        None
    ),
    prompt: Annotated[
        str | None, typer.Option("--prompt", help="score every scene against this text (default: each scene's own)")
    ] = None,
    timeout: Annotated[float, typer.Option("--timeout", min=1.0, help="seconds per question, retries included")] = (
        120.0
    ),
    vqa: VqaOption = "p-yes",
    as_json: Annotated[bool, typer.Option("--json", help="print JSON")] = False,
    library: LibraryOption = None,
) -> None:
    """VQA score: the vision model's probability that each scene's render (the standard view) shows its prompt: the
    paper's P("Yes") of the first answer token, or with --vqa normalised P(yes) / (P(yes) + P(no))."""
    from physcensis.evaluation.relations import scene_folders
    from physcensis.evaluation.vqa_folders import score_folders, score_stats

    if not vlm.strip():
        raise fail("--vlm is empty: name the vision model", ExitCode.USAGE)
    if prompt is not None and not prompt.strip():
        raise fail("--prompt is empty: give the text to score against, or leave it out", ExitCode.USAGE)
    with_libraries(library)
    folders = scene_folders(path)
    if not folders:
        raise no_scene_file(path, below=True)
    with console.status(f"asking {escape(vlm)} about {len(folders)} scene(s)…") as status:

        def asking(k: int) -> None:
            status.update(f"asking {escape(vlm)} about scene {k + 1} of {len(folders)}…")

        results = score_folders(
            folders, vlm, base_url, prompt, timeout, on_folder=asking, normalised=vqa == "normalised"
        )
    stats = score_stats(results)
    if as_json:
        overall = None if stats is None else {"mean": stats[0], "std": stats[1]}
        typer.echo(json.dumps({"scenes": [r.to_dict() for r in results], "vqa_score": overall, "vqa": vqa}, indent=2))
    else:
        table = Table(show_header=True, header_style="bold")
        for column in ("scene", "prompt", "VQA score"):
            table.add_column(column)
        for r in results:
            score = "[bold red]-[/]" if r.score is None else f"{r.score:.3f}"
            table.add_row(escape(r.scene), escape((r.prompt or "-")[:80]), score)
        console.print(table)
        scored = sum(r.score is not None for r in results)
        summary = "-" if stats is None else f"{stats[0]:.3f} ± {stats[1]:.3f}"
        console.print(f"VQA score over {scored} of {len(results)} scene(s): {summary}")
    for r in results:
        if r.error is not None:
            print_error(f"{r.scene}: not scored: {r.error}")
    raise finish(all(r.error is None for r in results))


@eval_app.command("compare")
@reports_errors
def eval_compare(
    prompts: Annotated[Path, typer.Option("--prompts", help="prompt file (text lines or JSON lines, as `batch`)")],
    out: Annotated[Path, typer.Option("--out", help="the comparison folder (run again to resume)")],
    methods: Annotated[
        str,
        typer.Option(
            "--methods",
            help="comma-separated: ours, random, llm-only (the model writes poses), program-frozen, no-feedback, "
            "no-report, visual",
        ),
    ] = "ours,random,llm-only",
    seeds: Annotated[int, typer.Option("--seeds", min=1, help="seeds per prompt (0 .. N-1)")] = 1,
    llm: Annotated[str | None, typer.Option("--llm", help="OpenAI-compatible model that writes the programs")] = None,
    base_url: Annotated[str | None, typer.Option("--base-url", help="the LLM server's URL")] = None,
    vlm: Annotated[
        str | None,
        typer.Option("--vlm", help="a vision model: VQA of every scene, and feedback in the loop (visual needs it)"),
    ] = None,
    vlm_base_url: Annotated[
        str | None, typer.Option("--vlm-base-url", help="the VLM's server (default: the LLM's)")
    ] = None,
    workers: Annotated[int, typer.Option("--workers", min=1, help="scenes made in parallel")] = 1,
    summary_json: Annotated[
        Path | None, typer.Option("--summary-json", help="also write each method's summary here (bench/results/)")
    ] = None,
) -> None:
    """Every method on the same prompts and seeds: DIR/results.jsonl, DIR/table.md and plots (metrics.png,
    settle_distance.png). Rows already in results.jsonl are kept, so an interrupted run resumes."""
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    from physcensis.evaluation.compare import TABLE, Models, done_keys, plan_jobs, run_compare, unique_methods

    if out.is_symlink() or (out.exists() and not out.is_dir()):
        raise fail(f"{out}: is not a folder (a file or a link); give --out a folder", ExitCode.USAGE)
    try:
        names = unique_methods(methods.split(","))
        import matplotlib  # noqa: F401  # the plots need it: say so before hours of work
    except PhyscensisError as exc:
        raise fail(str(exc), ExitCode.USAGE) from None
    except ImportError:
        raise fail("eval compare draws its plots with matplotlib: pip install matplotlib", ExitCode.USAGE) from None
    from physcensis.batch.prompts import read_prompts

    models = Models(llm, base_url, vlm, vlm_base_url or (base_url if vlm else None))
    try:
        jobs = plan_jobs(out, read_prompts(prompts), names, seeds, models)
    except PhyscensisError as exc:
        raise fail(str(exc), ExitCode.USAGE) from None
    columns = (TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn())
    with Progress(*columns, console=console) as progress:
        done = len(done_keys(out, jobs)) if out.is_dir() else 0
        bar = progress.add_task("scenes", total=len(jobs), completed=done)

        def advance(row: dict[str, Any], done: int, _total: int) -> None:
            state = "ok" if row["ok"] else "failed"
            progress.update(
                bar, completed=done, description=f"{row['method']} {row['prompt_id']} s{row['seed']} {state}"
            )

        def dropped(count: int) -> None:
            progress.console.print(
                f"{count} earlier row(s) were made with another prompt text, support, LLM or VLM (or lack a VQA "
                "score): making them again"
            )

        rows = run_compare(
            prompts, out, names, seeds, models=models, workers=workers, on_row=advance, on_dropped=dropped
        )
    typer.echo((out / TABLE).read_text())
    if summary_json is not None:
        from physcensis.evaluation.compare import summary_record
        from physcensis.machine import machine_info

        record = {"machine": machine_info(), "result": summary_record(rows, names)}
        from physcensis.fileio import atomic_write_text

        atomic_write_text(summary_json, json.dumps(record, indent=1) + "\n")
    console.print(
        f"{len(rows)} row(s) in {escape(str(out / 'results.jsonl'))}; plots: metrics.png, settle_distance.png"
    )
    unscored = [r for r in rows if vlm and r["metrics"].get("objects_placed") and "vqa_score" not in r["metrics"]]
    if unscored:
        print_error(
            f"the VLM {vlm} gave no VQA score for {len(unscored)} scene(s) (see the log); run the same command again "
            "to score them"
        )


@eval_app.command("diversity")
@reports_errors
def eval_diversity(
    path: Annotated[Path, typer.Argument(help="a batch folder, or any folder of scene folders (searched below)")],
    out: Annotated[
        Path | None, typer.Option("--out", help="write diversity.json and diversity/*.png here (default: PATH)")
    ] = None,
    expect: Annotated[
        Path | None,
        typer.Option(
            "--expect",
            help='JSON lines of {"prompt", "expect"} besides the bundled suites\' (a suite file reads as is)',
        ),
    ] = None,
    heatmaps: Annotated[
        bool, typer.Option("--heatmaps/--no-heatmaps", help="draw each prompt's support coverage heat map")
    ] = True,
    as_json: Annotated[bool, typer.Option("--json", help="print diversity.json's content instead of the tables")] = (
        False
    ),
    overwrite: Annotated[
        bool, typer.Option("--overwrite", help="replace a diversity.json or diversity/ folder physcensis did not write")
    ] = False,
) -> None:
    """Variety of each prompt's scenes (one prompt, many seeds): distinct scenes (same assets within 5 cm on average
    are one), distinct asset choices, asset-choice entropy per category, mean pairwise layout distance, expect blocks
    met (bundled suites, --expect), scenes resting; a coverage heat map per prompt. Writes diversity.json."""
    from physcensis.evaluation.diversity_files import REPORT_NAME, check_outputs, measure_folder, write_outputs

    if not path.is_dir():
        raise fail(f"{path}: {'is not a folder' if path.exists() else 'no such folder'}")
    target = out or path
    check_outputs(target, overwrite=overwrite, heatmaps=heatmaps)
    with console.status("measuring the scenes…"):
        run = measure_folder(path, _expect_checks(expect))
        document = write_outputs(run, target, heatmaps=heatmaps)
    if as_json:
        typer.echo(json.dumps(document, indent=2))
    else:
        _print_diversity(run)
        console.print(f"wrote {escape(str(target / REPORT_NAME))}", soft_wrap=True)
    for folder, why in run.unreadable:
        print_error(f"{folder}: not measured: {why}")
    raise finish(not run.unreadable)


def _expect_checks(path: Path | None) -> dict[str, ExpectCheck]:
    from physcensis.bench.prompt_suite import read_expectations, suite_expectations

    checks = suite_expectations()
    if path is not None:
        checks |= read_expectations(path)
    return checks


def _print_diversity(run: DiversityRun) -> None:
    for result, members in run.results:
        table = Table(title=escape(f"{result.prompt or '(no prompt)'} [{result.support}]"), show_header=False)
        table.add_column("measure")
        table.add_column("value", justify="right")
        layout = result.mean_layout_distance_m
        rows = [
            ("scenes", str(result.scenes)),
            ("distinct scenes", f"{result.distinct_scenes} of {result.scenes}"),
            ("distinct asset/count choices", str(result.distinct_asset_choices)),
            ("mean asset-choice entropy (bits)", _number(result.mean_entropy_bits, "{:.2f}")),
            ("mean layout distance (cm)", _number(None if layout is None else layout * 100, "{:.1f}")),
            (
                "expectations met",
                _share(result.expectations_met, result.scenes) if result.expectations_checked else "-",
            ),
            ("resting (settle <= 3 mm)", _share(result.resting, result.scenes)),
        ]
        rows += [(f"entropy: {category}", f"{bits:.2f}") for category, bits in result.entropy_bits.items()]
        for name, value in rows:
            table.add_row(escape(name), value)
        console.print(table)
        console.print(f"scenes: {escape(', '.join(run.scene_dirs(members)))}", soft_wrap=True)


def _number(value: float | None, form: str) -> str:
    return "-" if value is None else form.format(value)


def _share(count: int, total: int) -> str:
    return f"{count} of {total} ({count / total:.0%})" if total else "-"
