"""`eval compare`: every method on the same prompts and seeds, scored the same way, resumable.

Each (prompt, method, seed) is one scene folder, DIR/scenes/<method>/<prompt id>/seed<seed>, and one line of
DIR/results.jsonl, appended once the folder is in place; a run started again skips the lines already there, unless
what made them differs (the prompt's text or support, the LLM or the VLM): those rows are dropped and made again. The
metrics are measured on the scene as written (settle distance, penetration, relation accuracy), so they match
what `eval settle` and `eval relations` say of the folder; evaluation.json in the folder holds the same row. A row
is `ok` when every object was placed, nothing moved over MOVED_M in the settle check and every relation holds.
"""

from __future__ import annotations

import io
import json
import math
import multiprocessing
import statistics
import time
from collections.abc import Callable, Iterator, Sequence
from concurrent import futures
from dataclasses import astuple, dataclass
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.batch.prompts import PromptSpec, read_prompts
from physcensis.errors import PhyscensisError
from physcensis.evaluation.methods import METHODS, NEEDS_VLM, MethodOutput, MethodTask, method_named, object_list
from physcensis.evaluation.relations import check_scene
from physcensis.fileio import atomic_write_bytes, atomic_write_text
from physcensis.gallery import write_report
from physcensis.gallery.cards import results_rows
from physcensis.physics.engine import SETTLE_CLAMP_M, at_rest
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.program import check_program, parse_program
from physcensis.scene import Scene, Support
from physcensis.settings import ModelSettings

RESULTS = "results.jsonl"
TABLE = "table.md"
MOVED_M = 0.01  # an object that moves more than this in the settle check is a failure (as in batches)
MAX_FAILURES = 20  # failure lines kept per row
SETTLED_S = 2.0  # free fall before the relations are judged again ("relation_accuracy_settled")

# (metric key, column title, better when lower, scale to the shown unit, decimals)
COLUMNS: tuple[tuple[str, str, bool, float, int], ...] = (
    ("settle_distance_m", "Settle distance (mm) ↓", True, 1000.0, 2),
    ("settle_distance_requested_m", "Settle over requested (mm) ↓", True, 1000.0, 2),
    ("placed_ratio", "Placed / requested ↑", False, 1.0, 3),
    ("relation_accuracy", "Relation accuracy ↑", False, 1.0, 3),
    ("relation_accuracy_settled", "Relation accuracy, settled ↑", False, 1.0, 3),
    ("penetration_mm", "Penetration (mm) ↓", True, 1.0, 2),
    ("vqa_score", "VQA score ↑", False, 1.0, 3),
    ("vlm_rank", "VLM rank ↓", True, 1.0, 2),
    ("attempts", "Attempts ↓", True, 1.0, 2),
    ("rounds", "Rounds", True, 1.0, 2),
    ("time_s", "Time (s) ↓", True, 1.0, 1),
)


@dataclass(frozen=True)
class Job:
    """One row to make: where the comparison lives, which prompt, method and seed, and the LLM if any."""

    out: str
    prompt_id: str
    prompt: str
    support: str
    method: str
    seed: int
    llm: str | None = None
    base_url: str | None = None
    vlm: str | None = None
    vlm_base_url: str | None = None

    @property
    def key(self) -> tuple[str, str, int]:
        return self.prompt_id, self.method, self.seed

    @property
    def made_by(self) -> dict[str, str | None]:
        """What decides the row besides its key: a row made otherwise is stale."""
        support = Support.parse(self.support).model_dump_json()  # "table:1.2x0.8" and "table: 1.2 x 0.8" agree
        return {"prompt": self.prompt, "support": support, "llm": self.llm, "vlm": self.vlm}

    def current(self, row: dict[str, Any]) -> bool:
        """Whether `row` (of this job's key) is what this job would make: made the same way (rows written before
        rows recorded it count as current), and scored by the VLM when one is given and there is a scene."""
        made = row.get("made_by")
        if made is not None and made != self.made_by:
            return False
        metrics = row["metrics"]
        return not self.vlm or "vqa_score" in metrics or not metrics.get("objects_placed")

    @property
    def scene_dir(self) -> str:
        return f"scenes/{self.method}/{self.prompt_id}/seed{self.seed}"


def unique_methods(methods: Sequence[str]) -> list[str]:
    """The method names in order, each once; at least one, every one known (before any work)."""
    names = list(dict.fromkeys(m.strip() for m in methods if m.strip()))
    if not names:
        raise PhyscensisError("no method given (known: " + ", ".join(METHODS) + ")")
    for name in names:
        method_named(name)
    return names


@dataclass(frozen=True)
class Models:
    """The models a comparison uses: the LLM that writes programs (None: the offline planner) and the VLM that
    scores renders (None: no VQA)."""

    llm: str | None = None
    base_url: str | None = None
    vlm: str | None = None
    vlm_base_url: str | None = None


def plan_jobs(out: Path, specs: Sequence[PromptSpec], methods: Sequence[str], seeds: int, models: Models) -> list[Job]:
    names = unique_methods(methods)
    needing = sorted(NEEDS_VLM & set(names))
    if needing and not models.vlm:
        raise PhyscensisError(f"the method(s) {', '.join(needing)} need a vision model: give --vlm MODEL")
    return [
        Job(str(out), spec.id, spec.prompt, spec.support, method, seed, *astuple(models))
        for spec in specs
        for seed in range(seeds)
        for method in names
    ]


def _row_key(row: dict[str, Any]) -> tuple[str, str, int]:
    return row["prompt_id"], row["method"], row["seed"]


def done_keys(out: Path, jobs: Sequence[Job]) -> set[tuple[str, str, int]]:
    """The jobs whose rows results.jsonl already holds, made as the job would make them (a torn last line, from a
    kill, is left out and made again)."""
    by_key = {job.key: job for job in jobs}
    return {_row_key(r) for r in read_rows(out) if _row_key(r) in by_key and by_key[_row_key(r)].current(r)}


def drop_stale_rows(out: Path, jobs: Sequence[Job]) -> int:
    """Remove from results.jsonl the rows of these jobs that are not current (made with another prompt text, support,
    LLM or VLM under the same prompt id, or left unscored by the VLM); how many. The file is rewritten whole or not at
    all."""
    by_key = {job.key: job for job in jobs}
    rows = read_rows(out)
    kept = [r for r in rows if _row_key(r) not in by_key or by_key[_row_key(r)].current(r)]
    if len(kept) < len(rows):
        atomic_write_text(out / RESULTS, "".join(json.dumps(row) + "\n" for row in kept))
    return len(rows) - len(kept)


# The fields every row must have, and their types: anything else is not a row `eval compare` wrote.
ROW_FIELDS: tuple[tuple[str, type | tuple[type, ...]], ...] = (
    ("prompt_id", str),
    ("method", str),
    ("seed", int),
    ("ok", bool),
    ("metrics", dict),
    ("failures", list),
)


def read_rows(out: Path) -> list[dict[str, Any]]:
    """The rows of DIR/results.jsonl, each checked; a line that is not a row is an error naming it."""
    path = out / RESULTS
    if not path.is_file():
        return []
    rows = []
    for number, row in results_rows(path):
        problem = row_problem(row)
        if problem is not None:
            raise PhyscensisError(f"{path}: line {number} is not a comparison row: {problem}")
        rows.append(row)
    return rows


def row_problem(row: dict[str, Any]) -> str | None:
    """What makes `row` unusable, or None."""
    for key, kind in ROW_FIELDS:
        value = row.get(key)
        if not isinstance(value, kind) or (kind is int and isinstance(value, bool)):
            return f"{key!r} is missing or not a {getattr(kind, '__name__', kind)}"
    for key, value in row["metrics"].items():
        if isinstance(value, bool) or not isinstance(value, int | float):
            return f"metric {key!r} is not a number"
    return None


def cut_torn_tail(path: Path) -> None:
    """Drop a last line without its newline (a run killed mid-write), so the next row starts on a line of its own."""
    if not path.is_file():
        return
    with path.open("rb+") as handle:
        data = handle.read()
        if data and not data.endswith(b"\n"):
            handle.truncate(data.rfind(b"\n") + 1)


def run_compare(
    prompts: Path,
    out: Path,
    methods: Sequence[str],
    seeds: int,
    *,
    models: Models = Models(),
    workers: int = 1,
    on_row: Callable[[dict[str, Any], int, int], None] | None = None,
    on_dropped: Callable[[int], None] | None = None,
) -> list[dict[str, Any]]:
    """Run what results.jsonl lacks, then write table.md, the plots and index.html (the gallery of every row's scene);
    every row (old and new) is returned. `on_dropped` hears how many rows were dropped to be made again."""
    names = unique_methods(methods)
    jobs = plan_jobs(out, read_prompts(prompts), names, seeds, models)
    out.mkdir(parents=True, exist_ok=True)
    cut_torn_tail(out / RESULTS)
    dropped = drop_stale_rows(out, jobs)
    if dropped and on_dropped is not None:
        on_dropped(dropped)
    done = done_keys(out, jobs)
    todo = [job for job in jobs if job.key not in done]
    with (out / RESULTS).open("a") as handle:
        for k, row in enumerate(_rows(todo, workers), start=1):
            handle.write(json.dumps(row) + "\n")
            handle.flush()
            if on_row is not None:
                on_row(row, len(jobs) - len(todo) + k, len(jobs))
    wanted = {job.key for job in jobs}
    rows = [r for r in read_rows(out) if _row_key(r) in wanted]
    if models.vlm and len(names) > 1:
        _rank_unranked(rows, out, models)
    write_table(rows, names, out / TABLE)
    write_plots(rows, names, out)
    if rows:
        write_report(out)
    return rows


def _rank_unranked(rows: list[dict[str, Any]], out: Path, models: Models) -> None:
    """The VLM's ranking of the methods' renders (the paper's), for every group of one prompt and seed whose rows
    lack it; results.jsonl and the ranked rows' evaluation.json are rewritten with the ranks (atomically)."""
    from physcensis.evaluation.rank import RANK_KEY, Ranker, rank_rows

    pending = {(r["prompt_id"], r["seed"]) for r in rows if RANK_KEY not in r["metrics"]}
    groups = [r for r in rows if (r["prompt_id"], r["seed"]) in pending]
    if not groups:
        return
    assert models.vlm is not None
    rank_rows(groups, out, Ranker(models.vlm, models.vlm_base_url))
    for row in groups:
        evaluation = out / row["scene_dir"] / "evaluation.json" if row.get("scene_dir") else None
        if RANK_KEY in row["metrics"] and evaluation is not None and evaluation.is_file():
            atomic_write_text(evaluation, json.dumps(row, indent=2) + "\n")
    ranked = {_row_key(r): r for r in rows}
    kept = [ranked.get(_row_key(r), r) for r in read_rows(out)]
    atomic_write_text(out / RESULTS, "".join(json.dumps(r) + "\n" for r in kept))


def _rows(jobs: list[Job], workers: int) -> Iterator[dict[str, Any]]:
    if workers <= 1:
        for job in jobs:
            yield run_job(job)
        return
    context = multiprocessing.get_context("spawn")
    with futures.ProcessPoolExecutor(max_workers=workers, mp_context=context) as pool:
        pending = [pool.submit(run_job, job) for job in jobs]
        for future in futures.as_completed(pending):
            yield future.result()


def run_job(job: Job) -> dict[str, Any]:
    """Make one scene with one method, measure it, write its folder; its results.jsonl row."""
    catalogue = default_catalogue()
    support = Support.parse(job.support)
    models = ModelSettings(llm=job.llm, base_url=job.base_url, vlm=job.vlm, vlm_base_url=job.vlm_base_url)
    task = MethodTask(job.prompt, support, job.seed, models)
    started = time.perf_counter()
    try:
        output = method_named(job.method)(task, catalogue)
    except Exception as exc:  # one scene that cannot be made is a failed row, not the end of a long comparison
        reason = str(exc) if isinstance(exc, PhyscensisError) else f"{type(exc).__name__}: {exc}"
        row = _row(job, False, {"time_s": time.perf_counter() - started}, [f"the method failed: {reason}"])
        _write_failure(Path(job.out) / job.scene_dir, row)
        return row
    metrics, failures = measure(output, catalogue, job.vlm, job.vlm_base_url)
    ok = output.solution is not None and not failures
    row = _row(job, ok, metrics, failures)
    from physcensis.evaluation.methods import write_output

    write_output(output, Path(job.out) / job.scene_dir, row)
    return row


def _write_failure(folder: Path, row: dict[str, Any]) -> None:
    """The folder of a scene that could not be made: report.json (`"ok": false` and why) and evaluation.json."""
    from physcensis.fileio import output_directory

    with output_directory(folder, overwrite=True) as staging:
        report = {"ok": False, "failure": row["failures"][0], "method": row["method"]}
        (staging / "report.json").write_text(json.dumps(report, indent=2) + "\n")
        (staging / "evaluation.json").write_text(json.dumps(row, indent=2) + "\n")


def _row(job: Job, ok: bool, metrics: dict[str, float], failures: list[str]) -> dict[str, Any]:
    return {
        "prompt": job.prompt,
        "prompt_id": job.prompt_id,
        "method": job.method,
        "seed": job.seed,
        "scene_dir": job.scene_dir,
        "made_by": job.made_by,
        "ok": ok,
        "metrics": {k: v for k, v in metrics.items() if v is not None and math.isfinite(v)},
        "failures": failures[:MAX_FAILURES],
    }


def measure(
    output: MethodOutput, catalogue: Catalogue, vlm: str | None = None, vlm_base_url: str | None = None
) -> tuple[dict[str, float], list[str]]:
    """The row's metrics and failures, measured on the scene the method made (as it will be written); with a `vlm`,
    its VQA score of the scene's render (the same view for every method)."""
    metrics: dict[str, float] = {
        "attempts": float(output.attempts),
        "rounds": float(output.rounds),
        "time_s": round(output.seconds, 3),
        "objects_requested": float(requested_objects(output, catalogue)),
    }
    if output.solution is None:
        if metrics["objects_requested"]:  # nothing stood: every requested object counts as fallen
            metrics["settle_distance_requested_m"] = SETTLE_CLAMP_M
        return metrics, ["no scene: " + str(output.generated.result.failure or "every attempt failed")]
    scene = output.solution.scene
    failures = [f"{o.id} failed: {o.reason}" for o in scene.objects if o.status == "failed"]
    metrics["objects_placed"] = float(len(scene.placed))
    if metrics["objects_requested"]:
        metrics["placed_ratio"] = min(1.0, metrics["objects_placed"] / metrics["objects_requested"])
    failures += _physics(scene, catalogue, metrics, int(metrics["objects_requested"]))
    failures += _relations(scene, catalogue, metrics)
    if scene.placed:
        settled = check_scene(settled_scene(scene, catalogue), catalogue)
        if settled.accuracy is not None:
            metrics["relation_accuracy_settled"] = settled.accuracy
    if vlm and scene.placed:
        score = output.generated.vqa  # the loop's critic already scored this scene from the same view
        if score is None:
            score = scene_vqa(scene, output.generated.prompt, catalogue, vlm, vlm_base_url)
        if score is not None:  # a VLM that could not answer is not the scene's failure (logged by vqa_score)
            metrics["vqa_score"] = score
    return metrics, failures


def scene_vqa(scene: Scene, prompt: str, catalogue: Catalogue, vlm: str, base_url: str | None) -> float | None:
    """The VQA score of `scene` for `prompt`, from the standard view every method is rendered from."""
    from physcensis.agent.critic import render_png
    from physcensis.agent.vqa import vqa_score

    return vqa_score(render_png(scene, MujocoEngine(catalogue)), prompt, vlm, base_url)


def settled_scene(scene: Scene, catalogue: Catalogue) -> Scene:
    """The scene after SETTLED_S of free fall: where its objects really end up (a frozen layout may fall apart)."""
    motions = MujocoEngine(catalogue).settle(scene, duration_s=SETTLED_S).objects
    return scene.model_copy(update={"objects": at_rest(scene.objects, motions)})


def requested_objects(output: MethodOutput, catalogue: Catalogue) -> int:
    """How many objects the method's first program asked for (the program judged, when that is all there is)."""
    texts = [row["program"] for row in output.generated.result.transcript if isinstance(row.get("program"), str)]
    for text in [*texts[:1], json.dumps(output.judged_program)]:
        try:
            program = parse_program(text)
        except PhyscensisError:
            continue
        if program.relations and check_program(program, assets=catalogue.id_set()).ok:
            return len(object_list(program, catalogue, 0))
    return 0


def _physics(scene: Scene, catalogue: Catalogue, metrics: dict[str, float], requested: int) -> list[str]:
    """Settle distance (the paper's protocol) and the deepest interpenetration of the scene as written; the settle
    distance over the placed objects, and over every requested one, one that is not there counting as fallen."""
    if not scene.placed:
        if requested or scene.objects:
            metrics["settle_distance_requested_m"] = SETTLE_CLAMP_M
        return []
    engine = MujocoEngine(catalogue)
    built = engine.build(scene, visual=False)
    mujoco.mj_forward(built.model, built.data)
    depth, _ = built.penetrations()
    metrics["penetration_mm"] = round(float(np.max(depth, initial=0.0)) * 1000, 3)
    settle = engine.settle_distance(scene)
    metrics["settle_distance_m"] = settle.mean_m
    metrics["settle_distance_requested_m"] = settle.over_requested(max(requested, len(scene.objects)))
    failures = [f"the settle check diverged: {settle.diverged}"] if settle.diverged else []
    moved = sorted(((d, oid) for oid, d in settle.per_object.items() if d > MOVED_M), reverse=True)
    return failures + [f"{oid} moved {d * 100:.1f} cm in the settle check" for d, oid in moved]


def _relations(scene: Scene, catalogue: Catalogue, metrics: dict[str, float]) -> list[str]:
    result = check_scene(scene, catalogue)
    metrics["relations"] = float(len(result.checks))
    if result.accuracy is not None:
        metrics["relation_accuracy"] = result.accuracy
    return [f"{c.predicate} {c.subject} -> {c.target} does not hold: {c.detail}" for c in result.checks if not c.holds]


# -- the table and the plots ---------------------------------------------------------------------------------------


def values(rows: list[dict[str, Any]], method: str, key: str) -> list[float]:
    return [float(r["metrics"][key]) for r in rows if r["method"] == method and key in r["metrics"]]


def mean_std(xs: list[float]) -> tuple[float, float] | None:
    if not xs:
        return None
    return statistics.fmean(xs), statistics.pstdev(xs) if len(xs) > 1 else 0.0


def summary(rows: list[dict[str, Any]], methods: list[str]) -> dict[str, dict[str, Any]]:
    """Per method: mean and std of every metric, the scenes made and the scenes ok."""
    out: dict[str, dict[str, Any]] = {}
    for method in methods:
        mine = [r for r in rows if r["method"] == method]
        entry: dict[str, Any] = {"scenes": len(mine), "ok": sum(bool(r["ok"]) for r in mine)}
        keys = sorted({k for r in mine for k in r["metrics"]})
        for key in keys:
            stats = mean_std(values(rows, method, key))
            if stats is not None:
                entry[key] = {"mean": stats[0], "std": stats[1], "n": len(values(rows, method, key))}
        out[method] = entry
    return out


def summary_record(rows: list[dict[str, Any]], methods: list[str]) -> dict[str, Any]:
    """What a benchmark file keeps of a comparison: its prompts and seeds and each method's summary."""
    return {
        "prompts": sorted({r["prompt_id"] for r in rows}),
        "seeds": sorted({r["seed"] for r in rows}),
        "methods": summary(rows, methods),
    }


def shown_columns(rows: list[dict[str, Any]]) -> tuple[tuple[str, str, bool, float, int], ...]:
    """The columns to show: VQA only when some row has a score (a VLM was given)."""
    scored = any("vqa_score" in r["metrics"] for r in rows)
    return tuple(c for c in COLUMNS if c[0] != "vqa_score" or scored)


def table_markdown(rows: list[dict[str, Any]], methods: list[str]) -> str:
    """Methods as rows, the paper's metrics as columns, mean ± std over the scenes of each method."""
    stats = summary(rows, methods)
    columns = shown_columns(rows)
    header = ["Method", *[title for _, title, *_ in columns], "Scenes ok"]
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for method in methods:
        cells = [method]
        for key, _, _, scale, decimals in columns:
            entry = stats[method].get(key)
            cells.append(
                "–" if entry is None else f"{entry['mean'] * scale:.{decimals}f} ± {entry['std'] * scale:.{decimals}f}"
            )
        cells.append(f"{stats[method]['ok']} / {stats[method]['scenes']}")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def write_table(rows: list[dict[str, Any]], methods: list[str], path: Path) -> None:
    prompts = len({r["prompt_id"] for r in rows})
    seeds = len({r["seed"] for r in rows})
    intro = f"{prompts} prompt(s) × {seeds} seed(s); mean ± std over each method's scenes.\n\n"
    atomic_write_text(path, intro + table_markdown(rows, methods))


def write_plots(rows: list[dict[str, Any]], methods: list[str], out: Path) -> list[Path]:
    """metrics.png (a bar per method for each metric, with std error bars) and settle_distance.png (the
    distribution of each method's settle distances)."""
    try:
        from matplotlib.figure import Figure  # without pyplot: no GUI backend, and seconds less to import
    except ImportError as exc:
        raise PhyscensisError("the plots need matplotlib: pip install matplotlib") from exc
    paths = [out / "metrics.png", out / "settle_distance.png"]
    columns = shown_columns(rows)
    fig = Figure(figsize=(3.2 * len(columns), 3.4))
    for k, (key, title, _, scale, _) in enumerate(columns):
        ax = fig.add_subplot(1, len(columns), k + 1)
        stats = [mean_std(values(rows, m, key)) or (0.0, 0.0) for m in methods]
        ax.bar(methods, [s[0] * scale for s in stats], yerr=[s[1] * scale for s in stats], capsize=4, color="#4c72b0")
        ax.set_title(title, fontsize=9)
        ax.tick_params(axis="x", labelrotation=45, labelsize=8)
    fig.tight_layout()
    _save_png(fig, paths[0])
    fig = Figure(figsize=(1.6 * len(methods) + 2, 3.6))
    ax = fig.add_subplot()
    data = [[v * 1000 for v in values(rows, m, "settle_distance_m")] or [0.0] for m in methods]
    ax.boxplot(data, showfliers=True)
    ax.set_xticks(range(1, len(methods) + 1), methods)
    ax.set_yscale("symlog", linthresh=0.1)
    ax.set_ylabel("settle distance per scene (mm)")
    fig.tight_layout()
    _save_png(fig, paths[1])
    return paths


def _save_png(fig: Any, path: Path) -> None:
    """The figure as a PNG at `path`, written whole or not at all (a killed run leaves no half image)."""
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=100)
    atomic_write_bytes(path, buffer.getvalue())
