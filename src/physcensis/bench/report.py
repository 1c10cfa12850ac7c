"""Regenerate the benchmark tables of `docs/BENCHMARKS.md` from `bench/results/*.json`.

The document marks each generated block with a pair of HTML comments, `bench:NAME` and `/bench:NAME`
(see `MARKER`); only the text between a pair is replaced, everything else stays byte-identical.
Run with `python -m physcensis.bench.report` (`make bench` does it after the benchmarks).

Result files tagged with a commit (`clutter_<setting>_<scenes>_<commit>.json`) measure an earlier source tree: they
stay in `bench/results/` but are left out of the tables, which describe the code as it is.
"""

from __future__ import annotations

import argparse
import json
import logging
import os
import re
import sys
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from physcensis.fileio import atomic_write_text

log = logging.getLogger(__name__)

BENCHMARKS_DOC = Path("docs/BENCHMARKS.md")  # the document holding the generated tables, from the repository root

MARKER = re.compile(r"<!--\s*(/?)bench:([\w-]+)\s*-->")
NOT_MEASURED = "not measured yet"
CLUTTER_FILE = re.compile(r"^clutter_(?P<setting>.+?)_(?P<scenes>\d+)(?:_(?P<tag>.+))?$")
COMMIT = re.compile(r"^[0-9a-f]{7,40}$")
CLUTTER_MODES = ("no-stack", "with-stack", "with-skip")

Row = tuple[str, ...]


@dataclass(frozen=True)
class Result:
    """One JSON file of `bench/results/`."""

    name: str  # file name without `.json`
    data: dict[str, Any]

    @property
    def machine(self) -> str | None:
        machine = self.data.get("machine")
        return format_machine(machine) if isinstance(machine, dict) else None

    @property
    def result(self) -> Any:
        """The benchmark's own figures (`physcensis bench clutter --json` files are the figures themselves)."""
        return self.data.get("result", self.data)


# --- loading and small formatters -----------------------------------------------------------------------------


def load_results(results_dir: Path) -> dict[str, Result]:
    """Every readable `*.json` of the folder by name; unreadable files are logged and left out."""
    results: dict[str, Result] = {}
    for path in sorted(results_dir.glob("*.json")) if results_dir.is_dir() else []:
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError) as exc:
            log.warning("skip %s: %s", path, exc)
            continue
        if isinstance(data, dict):
            results[path.stem] = Result(path.stem, data)
    return results


def format_machine(machine: dict[str, Any]) -> str:
    """`<cpu>, <cores> cores, <system>, Python x` from a `machine_info()` dict."""
    return (
        f"{machine.get('cpu', 'unknown CPU')}, {machine.get('cores', '?')} cores, "
        f"{machine.get('system', 'unknown system')}, Python {machine.get('python', '?')}"
    )


def sig(value: float, digits: int = 2) -> str:
    """`value` to `digits` significant figures, keeping trailing zeros (0.60, 6.0) and never going exponential."""
    if value == 0:
        return "0"
    if abs(value) >= 10 ** (digits - 1):
        return f"{value:.0f}"
    return f"{value:#.{digits}g}".rstrip(".")


def millimetres(metres: float | None) -> str:
    """A settle distance in mm, with enough decimals to show small ones."""
    if metres is None:
        return "–"
    mm = metres * 1000
    if mm == 0:
        return "0"
    return f"{mm:.1f}" if mm >= 1 else f"{mm:.2f}" if mm >= 0.01 else f"{mm:.3f}"


def millimetres_2dp(metres: float | None) -> str:
    """A settle distance in mm with two decimals, as the prompt table shows it."""
    return "–" if metres is None else f"{metres * 1000:.2f}"


def cell(value: Any) -> str:
    """Text safe inside a markdown table cell."""
    return str(value).replace("|", "\\|").replace("\n", " ")


def table(header: Row, rows: Iterable[Row]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(cell(v) for v in row) + " |" for row in rows]
    return "\n".join(lines)


def missing(name: str) -> str:
    return f"{NOT_MEASURED} (`bench/results/{name}.json` is missing)"


# --- machines -----------------------------------------------------------------------------------------------------


def machine_line(results: dict[str, Result]) -> str:
    """The `machine` block: where the figures were measured."""
    machines = sorted({r.machine for r in results.values() if r.machine})
    if not machines:
        return "Measured on: not recorded in `bench/results/`."
    if len(machines) == 1:
        return f"Measured on: {machines[0]}."
    return "Measured on different machines (" + "; ".join(machines) + "); each table names its own."


def machine_note(sources: list[Result], results: dict[str, Result]) -> str:
    """A line under a table naming its machine(s), or '' when it is the one machine of all results."""
    everywhere = {r.machine for r in results.values() if r.machine}
    groups: dict[str | None, list[str]] = {}
    for source in sources:
        groups.setdefault(source.machine, []).append(f"{source.name}.json")
    if not groups or (len(everywhere) == 1 and set(groups) == everywhere):
        return ""
    if len(groups) == 1:
        (machine,) = groups
        return f"Measured on: {machine}." if machine else "Machine: not recorded in these JSON files."
    parts = [f"{machine or 'not recorded'} ({', '.join(names)})" for machine, names in groups.items()]
    return "Measured on: " + "; ".join(parts) + "."


def with_note(body: str, sources: list[Result], results: dict[str, Result]) -> str:
    note = machine_note(sources, results)
    return f"{body}\n\n{note}" if note else body


# --- prompts ------------------------------------------------------------------------------------------------------


def prompts_block(results: dict[str, Result], name: str = "prompts", label: str = "Prompt suite") -> str:
    """Per-prompt table of a prompt suite (`prompts` is the public one, `prompts_home` our own)."""
    source = results.get(name)
    if source is None:
        return f"{label}: {missing(name)}."
    data = source.result
    if "skipped" in data:
        return f"{label}: skipped ({data['skipped']})."
    rows = [
        (
            r["id"],
            str(r["objects"]),
            millimetres_2dp(r.get("settle_distance_m")),
            f"{r['seconds']:.2f}",
            "yes" if r["ok"] else "no: " + "; ".join(r.get("problems", [])),
        )
        for r in data["results"]
    ]
    body = table(("prompt", "objects", "settle distance (mm)", "time (s)", "expect block met"), rows)
    settled = [r["settle_distance_m"] for r in data["results"] if r.get("settle_distance_m") is not None]
    summary = f"{data['passed']} of {data['prompts']} prompts meet their `expect` block"
    if settled:
        summary += f"; the largest settle distance is {millimetres_2dp(max(settled))} mm"
    summary += "."
    said = _not_delivered(data["results"])
    if said:  # what each report says was not delivered (the run exits 1 for it), even where the block is met
        summary += f"\n\nSaid not delivered in the report (missing, or not where asked): {said}."
    return with_note(f"{body}\n\n{summary}", [source], results)


def _not_delivered(rows: list[dict[str, Any]]) -> str:
    """The suite's prompts whose report says something asked for is missing or not where it was asked."""
    said = []
    for r in rows:
        parts = [f"'{m.get('phrase', m['category'])}' missing" for m in r.get("missing", [])]
        parts += [f"'{m['phrase']}' {m['why']}" for m in r.get("elsewhere", [])]
        if parts:
            said.append(f"{r['id']} ({'; '.join(parts)})")
    return "; ".join(said)


# --- clutter ------------------------------------------------------------------------------------------------------


def clutter_label(summary: dict[str, Any], tag: str | None) -> str:
    """The setting column: mode, overhang, and which run (`make bench`, or another tag of the file name)."""
    label = str(summary["mode"])
    if summary.get("overhang"):
        label += ", overhang allowed (may stick out past the edge if it rests stably)"
    elif label == "no-stack":
        label += " (objects stay within the table's edges)"
    if tag:
        label += f", {tag}"
    return label


def clutter_stop(summary: dict[str, Any]) -> str:
    """The stopping rule: the paper's (stop at the first failure), N failures in a row, or with-skip's."""
    if summary["mode"] == "with-skip":
        return "skip what fails until nothing fits"
    patience = int(summary.get("patience", 1))
    return "first failure" if patience == 1 else f"{patience} failures in a row"


def clutter_method(summary: dict[str, Any]) -> str:
    return str(summary.get("peer") or "physcensis")


def clutter_resting(summary: dict[str, Any]) -> str:
    """Objects still resting once the final scenes are loaded with MuJoCo's default contact settings."""
    defaults = summary.get("mujoco_default")
    if not isinstance(defaults, dict):
        return "–"
    every = ", all rest" if defaults.get("all_rest") else ""
    return f"{defaults['mean_resting']:.2f} ± {defaults['std_resting']:.2f}{every}"


def clutter_row(summary: dict[str, Any], tag: str | None) -> Row:
    paper = summary.get("paper", {}).get(summary["mode"])
    count = (
        f"{summary['mean_objects']:.2f} ± {summary['std_objects']:.2f} (min {summary['min_objects']}, "
        f"max {summary['max_objects']}), {summary['scenes']} scenes"
    )
    defaults = summary.get("mujoco_default")
    ours = None if summary.get("peer") else summary["mean_settle_distance_m"]
    return (
        clutter_label(summary, tag),
        clutter_placement(summary),
        clutter_stop(summary),
        clutter_method(summary),
        count,
        clutter_resting(summary),
        "–" if paper is None else f"{paper:.2f}",
        f"{summary['median_seconds_per_scene']:.1f} s",
        "–" if ours is None else f"{millimetres(ours)} mm",
        f"{millimetres(defaults['mean_settle_distance_m'])} mm" if isinstance(defaults, dict) else "–",
    )


def clutter_placement(summary: dict[str, Any]) -> str:
    """Where each object went: packed (ours, the default of every run before the key was recorded), the
    predicate's own random spot, or the peer's uniform random tries."""
    if summary.get("peer"):
        return "uniform random spot, 100 tries (the peer's own)"
    if summary.get("placement", "packed") == "random":
        return "random spot that fits (PLACE-ANYWHERE as the paper reads)"
    return "packed against the others and the edges (ours)"


def clutter_summaries(results: dict[str, Result]) -> list[tuple[Result, dict[str, Any], str | None]]:
    """(file, summary, tag) for every clutter_*.json and each setting of `make bench`'s clutter.json."""
    found = []
    for name, source in results.items():
        match = CLUTTER_FILE.match(name)
        if match:
            found.append((source, source.result, match["tag"]))
        elif name == "clutter" and isinstance(source.result, dict):
            found += [(source, s, "`make bench`") for s in source.result.values() if isinstance(s, dict)]

    def order(item: tuple[Result, dict[str, Any], str | None]) -> tuple[Any, ...]:
        _, summary, tag = item
        mode = summary.get("mode")
        rank = CLUTTER_MODES.index(mode) if mode in CLUTTER_MODES else len(CLUTTER_MODES)
        return (
            rank,
            bool(summary.get("overhang")),
            summary.get("placement", "packed") == "random",
            tag is not None,
            tag or "",
            int(summary.get("patience", 1)),
            bool(summary.get("peer")),
            -int(summary.get("scenes", 0)),
        )

    return sorted(found, key=order)


def clutter_block(results: dict[str, Result]) -> str:
    """One row per clutter result file."""
    rows, sources = [], []
    for source, summary, tag in clutter_summaries(results):
        try:
            rows.append(clutter_row(summary, tag))
        except (KeyError, TypeError, ValueError) as exc:
            log.warning("skip a clutter summary of %s.json: missing or bad %s", source.name, exc)
            continue
        if source not in sources:
            sources.append(source)
    if not rows:
        return f"Clutter count: {NOT_MEASURED} (no `bench/results/clutter_*.json`)."
    header = (
        "setting",
        "placement",
        "stop at",
        "method",
        "objects placed (mean ± std)",
        "still resting under MuJoCo defaults",
        "paper",
        "time per scene (median)",
        "settle distance, our settings",
        "settle distance, MuJoCo defaults",
    )
    return with_note(table(header, rows), sources, results)


# --- speed --------------------------------------------------------------------------------------------------------


def target(result: dict[str, Any], relation: str) -> str:
    return f"{relation} {result['target_s']:g} s" if "target_s" in result else ""


def speed_check(r: dict[str, Any]) -> list[Row]:
    return [
        (
            f"parse + check a {r['objects']:,}-object program ({r['entries']:,} entries)",
            f"{sig(r['parse_median_s'])} s + {sig(r['check_median_s'])} s",
            target(r, "<"),
        )
    ]


def speed_spatial(r: dict[str, Any]) -> list[Row]:
    dining, scaling = r["dining_4"], r["scaling"]
    sizes = " / ".join(str(s["objects"]) for s in scaling)
    times = " / ".join(sig(s["median_s"]) for s in scaling)
    return [
        (
            f"spatial solve of `dining_4.json` ({dining['objects']} objects), median of {dining['repeats']}",
            f"{sig(dining['median_s'])} s",
            target(dining, "≤"),
        ),
        (f"spatial solve, tight rows of {sizes} objects", f"{times} s", ""),
    ]


def speed_place(r: dict[str, Any]) -> list[Row]:
    return [
        (
            f"PLACE-ANYWHERE search, 1.2 × 0.8 m table with {r['objects_on_table']} objects",
            f"{sig(r['search_median_s'], 3)} s",
            target(r, "<"),
        )
    ]


def speed_physics(r: dict[str, Any]) -> list[Row]:
    return [
        (
            f"build a {r['objects']}-object scene in MuJoCo / build and settle 2 s",
            f"{sig(r['build_median_s'])} s / {sig(r['build_and_settle_2s_median_s'])} s",
            "",
        ),
        (f"real-time factor of that scene ({r['timestep_s'] * 1000:g} ms steps)", f"{sig(r['real_time_factor'])}×", ""),
        (
            "render 640×480 per frame (reused renderer) / first frame",
            f"{sig(r['render_640x480_median_s'])} s / {sig(r['render_640x480_first_frame_s'])} s",
            "",
        ),
    ]


def speed_stability(r: dict[str, Any]) -> list[Row]:
    return [
        (
            f"{r['samples']}-sample stability estimate, {r['objects']}-object scene: "
            f"batched ({r['threads']} threads) / serial",
            f"{r['batched_median_s']:.2f} s / {r['serial_median_s']:.2f} s",
            target(r, "<"),
        )
    ]


def speed_assets(r: dict[str, Any]) -> list[Row]:
    return [
        (
            f"generate the whole catalogue cold ({r['assets']} assets) / load from cache",
            f"{sig(r['generate_cold_s'])} s / {sig(r['cache_load_median_s'])} s",
            "",
        )
    ]


SPEED_ROWS: tuple[tuple[str, Callable[[dict[str, Any]], list[Row]]], ...] = (
    ("check", speed_check),
    ("spatial", speed_spatial),
    ("place", speed_place),
    ("physics", speed_physics),
    ("stability", speed_stability),
    ("assets", speed_assets),
)


def speed_rows(name: str, rows: Callable[[dict[str, Any]], list[Row]], results: dict[str, Result]) -> list[Row]:
    source = results.get(name)
    if source is None:
        return [(f"`{name}` benchmark", missing(name), "")]
    try:
        return rows(source.result)
    except (KeyError, TypeError, ValueError) as exc:
        log.warning("cannot read %s.json: missing or bad %s", name, exc)
        return [(f"`{name}` benchmark", f"unreadable `bench/results/{name}.json` ({exc!r})", "")]


def speed_block(results: dict[str, Result]) -> str:
    """The speed table: one or more rows per speed benchmark."""
    rows = [row for name, make in SPEED_ROWS for row in speed_rows(name, make, results)]
    sources = [results[name] for name, _ in SPEED_ROWS if name in results]
    return with_note(table(("benchmark", "figure", "target"), rows), sources, results)


# --- throughput ---------------------------------------------------------------------------------------------------


def throughput_block(results: dict[str, Result]) -> str:
    """Batch generation with 1, 2, ... workers, from `batch.json`."""
    source = results.get("batch")
    if source is None:
        return f"Throughput: {missing('batch')}."
    data = source.result
    try:
        rows = [
            (
                str(run["workers"]),
                str(run.get("exports", "all")),  # older files measured the default exports only
                str(run.get("scenes", data["scenes"])),
                f"{run['seconds']:.1f} s",
                f"{run['scenes_per_min']:.1f}",
                _seconds_or_dash(run.get("start_up_s")),  # older files did not time the start-up
                _rate_or_dash(run.get("scenes_per_min_after_start_up")),
                str(run["failures"]),
            )
            for run in data["runs"]
        ]
        stages = [_stage_line(run) for run in data["runs"] if run.get("stage_seconds")]
    except (KeyError, TypeError, ValueError, AttributeError) as exc:
        log.warning("cannot read batch.json: missing or bad %s", exc)
        return f"Throughput: unreadable `bench/results/batch.json` ({exc!r})."
    rate = ("scenes per minute", "start-up", "after start-up")
    body = table(("workers", "exports", "scenes", "wall time", *rate, "failures"), rows)
    if stages:
        body += "\n\nMedian seconds per scene and stage:\n\n" + "\n".join(stages)
    prompt = f"Prompt: “{data['prompt']}”.\n\n" if data.get("prompt") else ""
    return with_note(prompt + body, [source], results)


def _seconds_or_dash(value: Any) -> str:
    return "–" if value is None else f"{float(value):.1f} s"


def _rate_or_dash(value: Any) -> str:
    return "–" if value is None else f"{float(value):.1f}"


def _stage_line(run: dict[str, Any]) -> str:
    stages = ", ".join(f"{name} {float(seconds):.2f}" for name, seconds in run["stage_seconds"].items())
    scenes = f", {run['scenes']} scenes" if "scenes" in run else ""
    return f"* {run['workers']} worker(s), exports {run.get('exports', 'all')}{scenes}: {stages}"


def crosscheck_block(results: dict[str, Result]) -> str:
    """The prompt suite's and clutter scenes settled under our settings, MuJoCo's defaults and PyBullet, from
    `crosscheck.json`."""
    source = results.get("crosscheck")
    if source is None:
        return f"Cross-check: {missing('crosscheck')}."
    data = source.result
    try:
        rows = [
            (
                r["id"],
                str(r["objects"]),
                millimetres_2dp(r["mujoco_settle_m"]),
                millimetres_2dp(r["mujoco_default_settle_m"]),
                millimetres_2dp(r["bullet_settle_m"]),
                f"{r['worst_object']} ({millimetres_2dp(r['worst_m'])}, {ENGINE_NAMES[r['worst_engine']]})",
            )
            for r in data["results"]
            if "skipped" not in r
        ]
        limit = millimetres(data["limit_m"])
        summary = "; ".join(
            f"{ENGINE_NAMES[key]}: {e['at_most_limit']} of {data['scenes']} at most {limit} mm, "
            f"largest {millimetres_2dp(e['max_settle_m'])} mm"
            for key, e in data["engines"].items()
        )
    except (KeyError, TypeError, ValueError) as exc:
        log.warning("cannot read crosscheck.json: missing or bad %s", exc)
        return f"Cross-check: unreadable `bench/results/crosscheck.json` ({exc!r})."
    header = ("scene", "objects", "ours (mm)", "MuJoCo defaults (mm)", "PyBullet (mm)", "moved most (mm, where)")
    return with_note(table(header, rows) + "\n\n" + summary + ".", [source], results)


def genesis_block(results: dict[str, Result]) -> str:
    """The same kinds of scenes made again with the `[genesis]` extra installed and settled in Genesis, beside our
    own settle of each, from `crosscheck_genesis.json`."""
    source = results.get("crosscheck_genesis")
    if source is None:
        return f"Genesis: {missing('crosscheck_genesis')}."
    data = source.result
    try:
        measured = [r for r in data["results"] if "skipped" not in r]
        rows = [
            (
                r["id"],
                str(r["objects"]),
                millimetres_2dp(r["mujoco_settle_m"]),
                millimetres_2dp(r["genesis_settle_m"]),
                f"{r['genesis_worst_object']} ({millimetres_2dp(r['genesis_worst_m'])})",
                f"{r['genesis_seconds']:.1f}",
            )
            for r in measured
        ]
        skipped = [r["id"] for r in data["results"] if "skipped" in r]
        summary = (
            f"Genesis: {data['at_most_limit']} of {data['scenes']} scenes at most {millimetres(data['limit_m'])} mm, "
            f"median {millimetres_2dp(data['median_settle_m'])} mm, largest {millimetres_2dp(data['max_settle_m'])} mm"
            f"; {data['genesis']}; median {data['median_seconds']:.1f} s per scene"
        )
        if skipped:
            summary += f"; no scene for {', '.join(skipped)}"
    except (KeyError, TypeError, ValueError) as exc:
        log.warning("cannot read crosscheck_genesis.json: missing or bad %s", exc)
        return f"Genesis: unreadable `bench/results/crosscheck_genesis.json` ({exc!r})."
    header = ("scene", "objects", "ours (mm)", "Genesis (mm)", "moved most in Genesis (mm)", "Genesis (s)")
    return with_note(table(header, rows) + "\n\n" + summary + ".", [source], results)


ENGINE_NAMES = {"mujoco": "ours", "mujoco_default": "MuJoCo defaults", "bullet": "PyBullet"}


def _seconds(value: float | None) -> str:
    return "–" if value is None else f"{sig(value)} s"


def _env_replay(r: dict[str, Any]) -> str:
    replay = r["env_replay"]
    return f"{replay['succeeded']} of {replay['replayed']}"


def demos_rows(r: dict[str, Any]) -> list[Row]:
    """Success, re-check, median times and dataset size of the robot demonstrations (`demos.json`)."""
    times, check, dataset = r["median_seconds_per_episode"], r["recheck"], r["dataset"]
    failures = ", ".join(f"{stage} {entry['count']}" for stage, entry in r["failures_by_stage"].items()) or "none"
    return [
        ("scenes / episodes attempted", f"{r['scenes']} / {r['attempted']}", ""),
        (
            "succeeded (primitive verifier)",
            f"{r['succeeded']} ({r['success_rate'] * 100:.0f} %); failed: {failures}",
            f"≥ {r['success_goal'] * 100:.0f} %",
        ),
        ("successes confirmed by replay in a fresh world", f"{check['confirmed']} of {check['checked']}", "all"),
        *(
            [("successes that succeed again stepped through the Gymnasium environment", _env_replay(r), "all")]
            if "env_replay" in r
            else []
        ),
        (
            "median per episode: planning / simulation / rendering",
            " / ".join(_seconds(times[k]) for k in ("planning", "execution", "rendering")),
            "",
        ),
        (
            "dataset (robomimic HDF5, 128×128 front and wrist frames)",
            f"{dataset['bytes'] / 1e6:.1f} MB, {dataset['episodes']} episodes",
            "",
        ),
    ]


def _demos_context(r: dict[str, Any]) -> str:
    """Whether the grasps were sampled afresh and how busy the machine was: the times depend on both (the commit
    the JSON records is left out: the tables describe the code as it is)."""
    parts = ["grasps sampled from an empty cache"] if r.get("grasp_cache") == "fresh" else []
    load = r.get("load_average")
    if isinstance(load, list) and len(load) == 2:
        parts.append(f"load average {load[0]:g} at the start, {load[1]:g} at the end")
    return f" ({'; '.join(parts)})" if parts else ""


def demos_block(results: dict[str, Result]) -> str:
    """Robot demonstrations on generated dining scenes, from `demos.json`."""
    source = results.get("demos")
    if source is None:
        return f"Robot demonstrations: {missing('demos')}."
    try:
        rows = demos_rows(source.result)
        task = source.result["task"]
    except (KeyError, TypeError, ValueError) as exc:
        log.warning("cannot read demos.json: missing or bad %s", exc)
        return f"Robot demonstrations: unreadable `bench/results/demos.json` ({exc!r})."
    body = f"Task: “{task}”, one episode per scene, one worker{_demos_context(source.result)}.\n\n"
    body += table(("figure", "value", "goal"), rows)
    if source.machine:  # the times mean little without it, even when every table shares the machine
        return f"{body}\n\nMeasured on: {source.machine}."
    return with_note(body, [source], results)


# --- the other tables ---------------------------------------------------------------------------------------------


def _import_row(mesh: dict[str, Any]) -> Row:
    if "error" in mesh:
        return (cell(mesh["id"]), "", "failed", "", "")
    cavity = "" if mesh["cavity"] is None else ("open" if mesh["cavity"] else "FILLED")
    deviation = f"{mesh['hull_from_mesh_max_mm']} / {mesh['hull_from_mesh_p95_mm']}"
    return (mesh["id"], cell(mesh["seconds"]), cell(mesh["hulls"]), deviation, cavity)


def import_block(results: dict[str, Result]) -> str:
    """Importing real meshes cold (`import.json`): per mesh, then the whole library cold and warm."""
    source = results.get("import")
    if source is None:
        return missing("import")
    r = source.result
    rows = [_import_row(mesh) for mesh in r["meshes"]]
    whole = f"whole library cold ({r['library_assets']} assets, 2 workers)"
    rows.append((whole, cell(r["library_cold_s"]), "", "", ""))
    rows.append(("whole library again (asset cache)", cell(r["library_warm_s"]), "", "", ""))
    header = ("mesh", "seconds (cold)", "convex parts", "hull off the surface, max / p95 (mm)", "cavity")
    body = table(header, rows) + f"\n\nMeshes from: {', '.join(r['sources'])}."
    return with_note(body, [source], results)


_COMPARE_COLUMNS = (  # (metric, title, scale to the shown unit, decimals), as `eval compare`'s table.md
    ("settle_distance_m", "settle distance (mm)", 1000.0, 2),
    ("settle_distance_requested_m", "settle over requested (mm)", 1000.0, 2),
    ("placed_ratio", "placed / requested", 1.0, 3),
    ("relation_accuracy", "relation accuracy", 1.0, 3),
    ("relation_accuracy_settled", "relation accuracy after 2 s of settling", 1.0, 3),
    ("penetration_mm", "penetration (mm)", 1.0, 2),
    ("vqa_score", "VQA score", 1.0, 3),
    ("vlm_rank", "VLM rank", 1.0, 2),
    ("attempts", "attempts", 1.0, 2),
    ("time_s", "time (s)", 1.0, 1),
)


def compare_block(results: dict[str, Result], name: str = "compare") -> str:
    """Methods compared on a prompt suite (`compare.json`, `compare_crowded.json`: `physcensis eval compare
    --summary-json`): mean ± std per method."""
    source = results.get(name)
    if source is None:
        return missing(name)
    r = source.result
    # a column only where some method has it (VQA and rank only when a VLM was given)
    columns = [c for c in _COMPARE_COLUMNS if any(c[0] in stats for stats in r["methods"].values())]
    rows = []
    for method, stats in r["methods"].items():
        cells = [
            f"{stats[key]['mean'] * scale:.{digits}f} ± {stats[key]['std'] * scale:.{digits}f}" if key in stats else "–"
            for key, _, scale, digits in columns
        ]
        rows.append((method, *cells, f"{stats['ok']} / {stats['scenes']}"))
    header = ("method", *[title for _, title, _, _ in columns], "scenes ok")
    body = table(header, rows) + f"\n\n{len(r['prompts'])} prompts, seeds {', '.join(map(str, r['seeds']))}."
    return with_note(body, [source], results)


def stability_controls_block(results: dict[str, Result]) -> str:
    """PLACE-ON `stability` on the bundled unstable_cup program (`stability_controls.json`): per target (as bundled,
    with its overlap of 0.55 kept, and with no overlap asked), how many seeds stand and meet it on the bench's own
    fresh draws, what the solver reported, and the overlap the cups kept."""
    source = results.get("stability_controls")
    if source is None:
        return missing("stability_controls")
    rows, seeds = [], []
    for key, r in source.result.items():
        level = "unstable" if key.startswith("unstable") else "stable"
        aim = "≥ 0.9" if level == "unstable" else "≤ 0.05"
        fresh = f"{r['fresh_p_fail_min']} / {r['fresh_p_fail_mean']} / {r['fresh_p_fail_max']}"
        asked = r.get("overlap_requested")
        kept = "–" if r.get("overlap_min") is None else f"{r['overlap_min']}–{r['overlap_max']}"
        rows.append(
            (
                f'"{level}" ({aim}){key[len(level) :]}',
                "not asked" if asked is None else cell(asked),
                kept,
                f"{r['standing']} of {r['seeds']}",
                f"{r['meets_target']} of {r['seeds']}",
                fresh,
                f"{r['reported_reached']} of {r['seeds']}",
                cell(r["solve_s_mean"]),
            )
        )
        seeds.append(f'"{key}": ' + ", ".join(str(row.get("fresh_p_fail", "not placed")) for row in r["rows"]))
    header = (
        "target",
        "overlap asked",
        "overlap delivered",
        "cup stands untouched",
        "meets the target",
        "p_fail on fresh draws, min / mean / max",
        "report says reached",
        "solve (s, mean)",
    )
    body = table(header, rows) + "\n\nPer seed (0–9), fresh p_fail " + "; ".join(seeds) + "."
    return with_note(body, [source], results)


def variety_block(results: dict[str, Result]) -> str:
    """Seeded variety over the suites (`variety.json`, `variety_home.json`): per suite, how many (prompt, seed) pairs
    meet their expect block, how many prompts reach 95 % distinct scenes and 50 % distinct choices, and the prompts and
    pairs that fall short."""
    sources = [results[name] for name in ("variety", "variety_home") if name in results]
    if not sources:
        return missing("variety")
    rows, short, missed = [], [], []
    try:
        for source in sources:
            r = source.result
            rows.append(
                (
                    {"variety": "public", "variety_home": "home"}.get(source.name, source.name),
                    r["variety"],
                    str(r["prompts"]),
                    str(r["seeds"]),
                    f"{r['expectations_met']} of {r['pairs']} ({100 * r['expectations_met_share']:.1f} %)",
                    f"{r['prompts_with_distinct_scenes']} of {r['prompts']}",
                    f"{r['prompts_with_distinct_choices']} of {r['prompts']}",
                    _choices_target(r),
                    f"{r['scenes_resting']} of {r['pairs']}",
                )
            )
            for row in r["results"]:
                target = row.get("choices_target", 0.5 * r["seeds"])
                if row.get("distinct_scenes", 0) < 0.95 * r["seeds"] or row.get("distinct_choices", 0) < target:
                    short.append(
                        f"{row['id']} ({row.get('distinct_scenes')} scenes, {row.get('distinct_choices')} choices"
                        + (f" of {row['open_choices']} open)" if "open_choices" in row else ")")
                    )
            missed += [f"{m['id']} seed {m['seed']}: {'; '.join(m['problems'])}" for m in r["misses"]]
    except (KeyError, TypeError, ValueError, ZeroDivisionError) as exc:
        log.warning("cannot read a variety result: missing or bad %s", exc)
        return f"Variety: unreadable `bench/results/variety*.json` ({exc!r})."
    header = (
        "suite",
        "variety",
        "prompts",
        "seeds",
        "expectations met",
        "prompts with ≥ 95 % distinct scenes",
        "prompts with ≥ 50 % distinct choices",
        "prompts reaching min(50 %, open) choices",
        "scenes resting (≤ 3 mm)",
    )
    body = table(header, rows)
    if short:
        below = ", ".join(cell(s) for s in short)
        body += f"\n\nBelow 95 % distinct scenes or min(50 %, open) distinct choices: {below}."
    if missed:
        body += "\n\nMissed their expect block: " + "; ".join(cell(m) for m in missed) + "."
    return with_note(body, sources, results)


def _choices_target(r: dict[str, Any]) -> str:
    """How many prompts reach their distinct-choices target, and how many of them leave fewer choices open than 50 %
    of the seeds (a result from before the targets were recorded: not measured)."""
    if "prompts_reaching_choices_target" not in r:
        return "not measured"
    fewer = r["prompts_with_fewer_open_choices"]
    return f"{r['prompts_reaching_choices_target']} of {r['prompts']} ({fewer} with fewer open)"


BLOCKS: dict[str, Callable[[dict[str, Result]], str]] = {
    "variety": variety_block,
    "compare": compare_block,
    "compare_crowded": lambda results: compare_block(results, "compare_crowded"),
    "machine": machine_line,
    "prompts": prompts_block,
    "prompts_home": lambda results: prompts_block(results, "prompts_home", "Home prompt suite"),
    "prompts_reading": lambda results: prompts_block(results, "prompts_reading", "Reading prompt suite"),
    "clutter": clutter_block,
    "speed": speed_block,
    "throughput": throughput_block,
    "crosscheck": crosscheck_block,
    "crosscheck_genesis": genesis_block,
    "stability_controls": stability_controls_block,
    "import": import_block,
    "demos": demos_block,
}


def earlier_tree(name: str) -> bool:
    """Whether a result file is tagged with a commit (`clutter_<setting>_<scenes>_<commit>`): an earlier source tree."""
    match = CLUTTER_FILE.match(name)
    return bool(match and match["tag"] and COMMIT.match(match["tag"]))


def render_tables(results_dir: Path) -> dict[str, str]:
    """Markdown for each generated block (`BLOCKS`) from the JSON files of `results_dir`, leaving out the files that
    measure an earlier source tree (their machines too)."""
    results = {}
    for name, result in load_results(results_dir).items():
        if earlier_tree(name):
            log.info("%s.json measures an earlier source tree: left out of the tables", name)
        else:
            results[name] = result
    return {name: build(results) for name, build in BLOCKS.items()}


def marker_spans(text: str) -> dict[str, tuple[int, int]]:
    """name -> (start, end) of the text between its opening and closing marker; ValueError if unbalanced."""
    spans: dict[str, tuple[int, int]] = {}
    open_name, open_end = None, 0
    for match in MARKER.finditer(text):
        closing, name = match.group(1) == "/", match.group(2)
        if not closing:
            if open_name is not None:
                raise ValueError(
                    f"marker <!-- bench:{name} --> opens inside bench:{open_name}, which is not closed before it"
                )
            if name in spans:
                raise ValueError(f"marker <!-- bench:{name} --> appears twice")
            open_name, open_end = name, match.end()
        elif name != open_name:
            raise ValueError(f"marker <!-- /bench:{name} --> has no matching <!-- bench:{name} --> before it")
        else:
            spans[name] = (open_end, match.start())
            open_name = None
    if open_name is not None:
        raise ValueError(f"marker <!-- bench:{open_name} --> is never closed by <!-- /bench:{open_name} -->")
    return spans


def replace_blocks(text: str, blocks: dict[str, str]) -> str:
    """`text` with each marker pair's content replaced by its block (a blank line either side)."""
    spans = marker_spans(text)
    for name in blocks.keys() - spans.keys():
        log.warning("no <!-- bench:%s --> ... <!-- /bench:%s --> markers; that table is not updated", name, name)
    for name in spans.keys() - blocks.keys():
        log.warning("marker bench:%s names no generated table; left as it is", name)
    newline = "\r\n" if "\r\n" in text else "\n"
    for name, (start, end) in sorted(spans.items(), key=lambda item: item[1][0], reverse=True):
        if name in blocks:
            block = blocks[name].strip("\n").replace("\n", newline)
            text = text[:start] + newline * 2 + block + newline * 2 + text[end:]
    return text


def update_tables(doc: Path, results_dir: Path) -> bool:
    """Regenerate the marked blocks of `doc` (docs/BENCHMARKS.md); True when the file changed."""
    text = doc.read_bytes().decode("utf-8")
    updated = replace_blocks(text, render_tables(results_dir))
    if updated == text:
        return False
    mode = doc.stat().st_mode & 0o7777
    atomic_write_text(doc, updated)
    os.chmod(doc, mode)  # keep the document's own permissions
    return True


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Regenerate the benchmark tables from the results JSON.")
    parser.add_argument("--doc", type=Path, default=BENCHMARKS_DOC, help="the document whose tables to regenerate")
    parser.add_argument("--results", type=Path, default=Path("bench/results"))
    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(message)s")
    try:
        changed = update_tables(args.doc, args.results)
    except (OSError, ValueError) as exc:
        log.error("cannot update %s: %s", args.doc, exc)
        return 1
    log.info("%s: %s", args.doc, "benchmark tables updated" if changed else "benchmark tables already up to date")
    return 0


if __name__ == "__main__":
    sys.exit(main())
