"""The benchmark tables of docs/BENCHMARKS.md are generated from the results JSON, between marker comments."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import pytest

from physcensis.bench import __main__ as bench_main
from physcensis.bench.report import BENCHMARKS_DOC, marker_spans, render_tables, update_tables

REPO = Path(__file__).resolve().parents[2]
MACHINE = {"cpu": "Test CPU 9000", "cores": 3, "python": "3.11.9", "system": "Linux testarch"}
OTHER_MACHINE = {"cpu": "Other CPU", "cores": 64, "python": "3.12.1", "system": "Darwin arm64"}
SPEED = {
    "check": {"objects": 10000, "entries": 49999, "parse_median_s": 0.1852, "check_median_s": 0.1517, "target_s": 1.0},
    "spatial": {
        "dining_4": {"objects": 16, "median_s": 0.0135, "repeats": 10, "target_s": 0.5},
        "scaling": [{"objects": 8, "median_s": 0.0181}, {"objects": 64, "median_s": 7.3289}],
    },
    "place": {"objects_on_table": 20, "search_median_s": 0.1989, "target_s": 0.2},
    "physics": {
        "objects": 40,
        "build_median_s": 0.0217,
        "build_and_settle_2s_median_s": 0.3664,
        "real_time_factor": 6.03,
        "render_640x480_first_frame_s": 0.6025,
        "render_640x480_median_s": 0.0691,
        "timestep_s": 0.002,
    },
    "stability": {
        "objects": 20,
        "samples": 128,
        "threads": 2,
        "serial_median_s": 1.017,
        "batched_median_s": 0.817,
        "target_s": 2.0,
    },
    "assets": {"assets": 361, "generate_cold_s": 4.754, "cache_load_median_s": 0.326},
}
PROMPTS = {
    "prompts": 2,
    "passed": 1,
    "results": [
        {
            "id": "dining-4",
            "ok": True,
            "problems": [],
            "seconds": 0.87,
            "objects": 16,
            "rounds": 1,
            "settle_distance_m": 0.000352,
            "elsewhere": [{"category": "flower", "placed": 2, "phrase": "flowers", "why": "asked in or on a vase"}],
        },
        {
            "id": "picnic",
            "ok": False,
            "problems": ["no cup on a plate"],
            "seconds": 4.1,
            "objects": 11,
            "rounds": 2,
            "settle_distance_m": 0.002403,
        },
    ],
}
CLUTTER = {
    "mode": "no-stack",
    "scenes": 100,
    "seed": 0,
    "overhang": False,
    "mean_objects": 13.55,
    "std_objects": 1.997,
    "min_objects": 10,
    "max_objects": 17,
    "median_seconds_per_scene": 2.981,
    "mean_settle_distance_m": 1e-06,
    "paper": {"no-stack": 14.77, "with-stack": 22.3},
}
BATCH = {
    "prompt": "a dining table for four",
    "scenes": 12,
    "runs": [
        {"workers": 1, "scenes_per_min": 6.26, "seconds": 115.2, "failures": 0},
        {"workers": 2, "scenes_per_min": 11.8, "seconds": 61.0, "failures": 1},
        {
            "workers": 2,
            "exports": "none",
            "scenes_per_min": 14.5,
            "seconds": 49.7,
            "failures": 0,
            "stage_seconds": {"plan": 0.2, "verify": 0.31, "render": 0.4},
        },
        {
            "workers": 2,
            "exports": "none",
            "scenes": 48,
            "scenes_per_min": 50.2,
            "seconds": 57.4,
            "start_up_s": 6.52,
            "scenes_per_min_after_start_up": 54.2,
            "failures": 0,
            "stage_seconds": {"plan": 0.1, "verify": 0.3, "render": 0.3},
        },
    ],
}
DOC = """# Benchmarks

Intro text, with a trailing space \nand a table:

| a | b |
|---|---|

## Benchmarks

<!-- bench:machine -->
old machine
<!-- /bench:machine -->

Hand-written prose stays.

<!-- bench:prompts -->
<!-- /bench:prompts -->
<!-- bench:clutter -->
stale rows
<!-- /bench:clutter -->
<!-- bench:speed --><!-- /bench:speed -->
<!-- bench:throughput -->
<!-- /bench:throughput -->

## Known limitations

The end.
"""


def write(results: Path, name: str, result: dict[str, Any], machine: dict[str, Any] | None = MACHINE) -> None:
    record = result if machine is None else {"benchmark": name, "machine": machine, "wall_s": 1.0, "result": result}
    (results / f"{name}.json").write_text(json.dumps(record))


@pytest.fixture
def results(tmp_path: Path) -> Path:
    folder = tmp_path / "results"
    folder.mkdir()
    for name, result in SPEED.items():
        write(folder, name, result)
    write(folder, "prompts", PROMPTS)
    write(folder, "clutter_no-stack_100", CLUTTER, machine=MACHINE)
    write(folder, "clutter_with-stack_30", {**CLUTTER, "mode": "with-stack", "scenes": 30, "paper": {}})
    return folder


@pytest.fixture
def doc(tmp_path: Path) -> Path:
    path = tmp_path / "BENCHMARKS.md"
    path.write_bytes(DOC.encode("utf-8"))
    return path


def outside_markers(text: str) -> list[str]:
    spans = sorted(marker_spans(text).values())
    starts = [0] + [end for _, end in spans]
    ends = [start for start, _ in spans] + [len(text)]
    return [text[a:b] for a, b in zip(starts, ends, strict=True)]


def test_tables_contain_the_figures_and_the_machine(results: Path) -> None:
    tables = render_tables(results)
    assert tables["machine"] == "Measured on: Test CPU 9000, 3 cores, Linux testarch, Python 3.11.9."
    assert "| dining-4 | 16 | 0.35 | 0.87 | yes |" in tables["prompts"]
    assert "| picnic | 11 | 2.40 | 4.10 | no: no cup on a plate |" in tables["prompts"]
    assert "1 of 2 prompts meet their `expect` block" in tables["prompts"]
    # what a report says was not delivered is listed, though its block is met
    assert "not where asked): dining-4 ('flowers' asked in or on a vase)." in tables["prompts"]
    assert (
        "| no-stack (objects stay within the table's edges) | packed against the others and the edges (ours) | "
        "first failure | physcensis | 13.55 ± 2.00 (min 10, "
        "max 17), 100 scenes | – | 14.77 | 3.0 s | 0.001 mm | – |"
    ) in tables["clutter"]
    with_stack = (
        "| with-stack | packed against the others and the edges (ours) | first failure | physcensis | 13.55 ± 2.00 "
        "(min 10, max 17), 30 scenes | – | – |"
    )
    assert with_stack in tables["clutter"]
    assert tables["clutter"].index("no-stack (") < tables["clutter"].index("with-stack")
    speed = tables["speed"]
    assert "| parse + check a 10,000-object program (49,999 entries) | 0.19 s + 0.15 s | < 1 s |" in speed
    assert "| spatial solve of `dining_4.json` (16 objects), median of 10 | 0.013 s | ≤ 0.5 s |" in speed
    assert "tight rows of 8 / 64 objects | 0.018 / 7.3 s |" in speed
    assert "| 0.199 s | < 0.2 s |" in speed and "| 6.0× |" in speed and "| 0.069 s / 0.60 s |" in speed
    assert "batched (2 threads) / serial | 0.82 s / 1.02 s | < 2 s |" in speed
    assert "(361 assets) / load from cache | 4.8 s / 0.33 s |" in speed
    assert "Measured on" not in speed  # one machine for everything: named once, in the machine line


def test_missing_batch_json_is_not_measured_yet(results: Path) -> None:
    assert "not measured yet" in render_tables(results)["throughput"]


def test_batch_json_gives_the_throughput_table(results: Path) -> None:
    write(results, "batch", BATCH)
    throughput = render_tables(results)["throughput"]
    header = "| workers | exports | scenes | wall time | scenes per minute | start-up | after start-up | failures |"
    assert header in throughput
    assert "| 1 | all | 12 | 115.2 s | 6.3 | – | – | 0 |" in throughput  # an older file: no start-up timed
    assert "| 2 | all | 12 | 61.0 s | 11.8 | – | – | 1 |" in throughput
    assert "| 2 | none | 12 | 49.7 s | 14.5 | – | – | 0 |" in throughput
    assert "| 2 | none | 48 | 57.4 s | 50.2 | 6.5 s | 54.2 | 0 |" in throughput
    assert "* 2 worker(s), exports none: plan 0.20, verify 0.31, render 0.40" in throughput
    assert "* 2 worker(s), exports none, 48 scenes: plan 0.10, verify 0.30, render 0.30" in throughput
    assert "a dining table for four" in throughput


def test_crosscheck_json_gives_the_three_engine_table(results: Path) -> None:
    assert "not measured yet" in render_tables(results)["crosscheck"]
    engines = {
        "mujoco": {"at_most_limit": 2, "median_settle_m": 0.0, "max_settle_m": 0.0002},
        "mujoco_default": {"at_most_limit": 1, "median_settle_m": 0.0003, "max_settle_m": 0.0031},
        "bullet": {"at_most_limit": 1, "median_settle_m": 0.0236, "max_settle_m": 0.04667},
    }
    write(
        results,
        "crosscheck",
        {
            "scenes": 2,
            "limit_m": 0.001,
            "engines": engines,
            "results": [
                {
                    "id": "dining-4",
                    "objects": 16,
                    "mujoco_settle_m": 0.0,
                    "mujoco_default_settle_m": 0.0003,
                    "bullet_settle_m": 0.0004,
                    "worst_object": "knife_0",
                    "worst_engine": "bullet",
                    "worst_m": 0.001001,
                },
                {
                    "id": "clutter with-stack 3",
                    "objects": 30,
                    "mujoco_settle_m": 0.0002,
                    "mujoco_default_settle_m": 0.0031,
                    "bullet_settle_m": 0.04667,
                    "worst_object": "cup_0",
                    "worst_engine": "mujoco_default",
                    "worst_m": 0.09334,
                },
                {"id": "broken", "objects": 0, "skipped": "no scene"},
            ],
        },
    )
    block = render_tables(results)["crosscheck"]
    assert "| dining-4 | 16 | 0.00 | 0.30 | 0.40 | knife_0 (1.00, PyBullet) |" in block
    assert "| clutter with-stack 3 | 30 | 0.20 | 3.10 | 46.67 | cup_0 (93.34, MuJoCo defaults) |" in block
    assert "broken" not in block
    assert "ours: 2 of 2 at most 1.0 mm, largest 0.20 mm; MuJoCo defaults: 1 of 2 at most 1.0 mm" in block
    assert "PyBullet: 1 of 2 at most 1.0 mm, largest 46.67 mm." in block


def test_crosscheck_genesis_json_gives_genesis_beside_ours(results: Path) -> None:
    assert "not measured yet" in render_tables(results)["crosscheck_genesis"]
    rows = [
        {
            "id": "dining-4",
            "objects": 16,
            "mujoco_settle_m": 0.00001,
            "genesis_settle_m": 0.00042,
            "genesis_worst_object": "knife_0",
            "genesis_worst_m": 0.0012,
            "genesis_seconds": 11.04,
        },
        {"id": "broken", "objects": 0, "skipped": "no scene"},
    ]
    summary = {"scenes": 1, "limit_m": 0.003, "at_most_limit": 1, "median_settle_m": 0.00042}
    summary |= {"max_settle_m": 0.00042, "median_seconds": 11.04, "genesis": "genesis-world 1.4.5, torch 2.13.0"}
    write(results, "crosscheck_genesis", summary | {"results": rows})
    block = render_tables(results)["crosscheck_genesis"]
    assert "| dining-4 | 16 | 0.01 | 0.42 | knife_0 (1.20) | 11.0 |" in block
    assert "Genesis: 1 of 1 scenes at most 3.0 mm, median 0.42 mm, largest 0.42 mm" in block
    assert "no scene for broken" in block and "genesis-world 1.4.5" in block


def test_compare_json_gives_the_papers_columns_that_were_measured(results: Path) -> None:
    def stat(mean: float, std: float = 0.0) -> dict[str, float]:
        return {"mean": mean, "std": std}

    ours = {"settle_distance_m": stat(0.00001), "settle_distance_requested_m": stat(0.0004, 0.002)}
    ours |= {"relation_accuracy": stat(0.997, 0.014), "vlm_rank": stat(1.5, 0.5), "ok": 23, "scenes": 24}
    frozen = {"settle_distance_m": stat(0.39), "relation_accuracy": stat(0.99), "ok": 7, "scenes": 24}
    write(results, "compare", {"prompts": ["a"] * 24, "seeds": [0], "methods": {"ours": ours, "llm-only": frozen}})
    block = render_tables(results)["compare"]
    header = "| method | settle distance (mm) | settle over requested (mm) | relation accuracy | VLM rank | scenes ok |"
    assert header in block
    assert "| ours | 0.01 ± 0.00 | 0.40 ± 2.00 | 0.997 ± 0.014 | 1.50 ± 0.50 | 23 / 24 |" in block
    assert "| llm-only | 390.00 ± 0.00 | – | 0.990 ± 0.000 | – | 7 / 24 |" in block
    assert "VQA" not in block  # no method was scored by a vision model


def test_stability_controls_json_gives_a_row_per_target(results: Path) -> None:
    assert "not measured yet" in render_tables(results)["stability_controls"]

    def level(p: list[float], meets: int, reached: int) -> dict[str, Any]:
        rows = [{"seed": k, "fresh_p_fail": v, "stands": True} for k, v in enumerate(p)]
        summary = {"seeds": len(p), "standing": len(p), "meets_target": meets, "reported_reached": reached}
        stats = {"fresh_p_fail_min": min(p), "fresh_p_fail_mean": round(sum(p) / len(p), 3), "fresh_p_fail_max": max(p)}
        return summary | stats | {"solve_s_mean": 20.5, "rows": rows}

    kept = {"overlap_requested": 0.55, "overlap_min": 0.45, "overlap_max": 0.58}
    free = {"overlap_requested": None, "overlap_min": 0.22, "overlap_max": 0.33}
    variants = {"unstable": level([0.95, 0.88], 1, 2) | kept, "stable": level([0.01, 0.0], 2, 2) | kept}
    variants["unstable, no overlap asked"] = level([0.93, 0.94], 2, 2) | free
    write(results, "stability_controls", variants)
    block = render_tables(results)["stability_controls"]
    assert '| "unstable" (≥ 0.9) | 0.55 | 0.45–0.58 | 2 of 2 | 1 of 2 | 0.88 / 0.915 / 0.95 | 2 of 2 | 20.5 |' in block
    assert '| "stable" (≤ 0.05) | 0.55 | 0.45–0.58 | 2 of 2 | 2 of 2 | 0.0 / 0.005 / 0.01 | 2 of 2 | 20.5 |' in block
    assert '| "unstable" (≥ 0.9), no overlap asked | not asked | 0.22–0.33 | 2 of 2 | 2 of 2 |' in block
    assert 'fresh p_fail "unstable": 0.95, 0.88; "stable": 0.01, 0.0; "unstable, no overlap asked": 0.93' in block
    lost = level([0.95, 0.88], 1, 1)
    lost["rows"].append({"seed": 2, "placed": False, "reason": "it fell"})  # a cup the final check removed
    write(results, "stability_controls", {"unstable": lost | kept, "stable": level([0.01, 0.0], 2, 2) | kept})
    assert '"unstable": 0.95, 0.88, not placed;' in render_tables(results)["stability_controls"]


def test_other_machines_are_named_per_table(results: Path) -> None:
    write(results, "batch", BATCH, machine=OTHER_MACHINE)
    write(results, "clutter_no-stack_100", CLUTTER, machine=None)
    tables = render_tables(results)
    assert "different machines" in tables["machine"]
    assert "Measured on: Other CPU, 64 cores, Darwin arm64, Python 3.12.1." in tables["throughput"]
    assert "Measured on: Test CPU 9000, 3 cores, Linux testarch, Python 3.11.9." in tables["speed"]
    assert "not recorded (clutter_no-stack_100.json)" in tables["clutter"]


def test_make_bench_clutter_json_gives_a_row_per_setting(results: Path) -> None:
    overhang = {**CLUTTER, "overhang": True, "scenes": 20}
    skip = {**CLUTTER, "mode": "with-skip", "scenes": 5}
    write(results, "clutter", {"no-stack-overhang": overhang, "with-skip": skip})
    clutter = render_tables(results)["clutter"]
    assert "| no-stack, overhang allowed (may stick out past the edge if it rests stably), `make bench` |" in clutter
    assert (
        "| with-skip, `make bench` | packed against the others and the edges (ours) | skip what fails until nothing "
        "fits | physcensis | 13.55 ± 2.00 (min 10, max 17), "
        "5 scenes | – | – |"
    ) in clutter
    assert clutter.index("overhang") < clutter.index("with-stack") < clutter.index("with-skip")


def test_missing_results_are_not_measured_yet(tmp_path: Path) -> None:
    tables = render_tables(tmp_path / "nothing")
    measured = ("prompts", "prompts_home", "prompts_reading", "clutter", "speed", "throughput", "crosscheck", "import")
    measured += ("crosscheck_genesis",)
    measured += ("compare", "compare_crowded", "demos", "stability_controls", "variety")
    assert set(tables) == {"machine", *measured}
    assert all("not measured yet" in tables[name] for name in measured)


def test_update_replaces_only_between_markers_and_is_idempotent(doc: Path, results: Path) -> None:
    before = doc.read_bytes().decode("utf-8")
    assert update_tables(doc, results) is True
    after = doc.read_bytes().decode("utf-8")
    assert outside_markers(after) == outside_markers(before)
    assert "old machine" not in after and "stale rows" not in after
    assert "Measured on: Test CPU 9000" in after and "| dining-4 | 16 |" in after
    assert update_tables(doc, results) is False
    assert doc.read_bytes().decode("utf-8") == after


def test_missing_marker_pair_is_skipped(doc: Path, results: Path, caplog: pytest.LogCaptureFixture) -> None:
    text = DOC.replace("<!-- bench:throughput -->\n<!-- /bench:throughput -->\n", "")
    doc.write_text(text)
    assert update_tables(doc, results) is True
    assert "bench:throughput" in caplog.text
    assert doc.read_text().endswith("## Known limitations\n\nThe end.\n")


@pytest.mark.parametrize(
    ("broken", "named"),
    [
        (DOC.replace("<!-- /bench:clutter -->\n", ""), "bench:clutter"),
        (DOC.replace("<!-- bench:speed -->", ""), "bench:speed"),
        (DOC + "<!-- bench:prompts -->\n<!-- /bench:prompts -->\n", "bench:prompts"),
    ],
)
def test_unbalanced_markers_raise(doc: Path, results: Path, broken: str, named: str) -> None:
    doc.write_text(broken)
    with pytest.raises(ValueError, match=named):
        update_tables(doc, results)
    assert doc.read_text() == broken


def test_crlf_doc_keeps_its_line_endings(doc: Path, results: Path) -> None:
    doc.write_bytes(DOC.replace("\n", "\r\n").encode("utf-8"))
    update_tables(doc, results)
    data = doc.read_bytes()
    assert data.count(b"\n") == data.count(b"\r\n")


def test_benchmarks_doc_markers_are_balanced_and_the_readme_has_none() -> None:
    spans = marker_spans((REPO / BENCHMARKS_DOC).read_bytes().decode("utf-8"))
    assert set(render_tables(REPO / "no-results")) <= set(spans)  # every generated table has its place
    assert marker_spans((REPO / "README.md").read_text(encoding="utf-8")) == {}  # measurements live in one place


def test_a_clutter_file_tagged_with_a_commit_is_left_out(results: Path) -> None:
    """The tables describe the code as it is: a file measured on an earlier tree (its name ends in a commit) stays in
    bench/results/ but is neither a row nor named under the table (test_robot_demos_bench: nor is demos.json's)."""
    write(results, "clutter_with-stack_100_06f7899", {**CLUTTER, "mode": "with-stack"}, machine=OTHER_MACHINE)
    write(results, "clutter_with-stack_20_rerun", {**CLUTTER, "mode": "with-stack", "scenes": 20})
    tables = render_tables(results)
    assert "06f7899" not in tables["clutter"] and "| with-stack, rerun | packed against" in tables["clutter"]
    assert not any(re.search(r"\bcommit\b", block) for block in tables.values())
    assert "Other CPU" not in tables["machine"]  # nor its machine


def boom() -> dict[str, Any]:
    raise RuntimeError("benchmark exploded")


def fine() -> dict[str, Any]:
    return {"objects": 1}


def test_bench_main_goes_on_after_a_failure_and_exits_non_zero(
    tmp_path: Path, doc: Path, monkeypatch: pytest.MonkeyPatch, caplog: pytest.LogCaptureFixture
) -> None:
    monkeypatch.setattr(bench_main, "BENCHMARKS", {"boom": f"{__name__}:boom", "fine": f"{__name__}:fine"})
    out = tmp_path / "out"
    assert bench_main.main(["--out", str(out), "--doc", str(doc)]) == 1
    assert "benchmark exploded" in caplog.text
    assert json.loads((out / "fine.json").read_text())["result"] == {"objects": 1}
    assert not (out / "boom.json").exists()
    assert "not measured yet" in doc.read_text()  # the tables were regenerated all the same


def test_bench_main_lists_and_can_leave_the_doc(
    tmp_path: Path, doc: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    assert bench_main.main(["--list"]) == 0
    assert "clutter" in capsys.readouterr().out
    monkeypatch.setattr(bench_main, "BENCHMARKS", {"fine": f"{__name__}:fine"})
    before = doc.read_bytes()
    assert bench_main.main(["--out", str(tmp_path / "out"), "--doc", str(doc), "--no-doc"]) == 0
    assert doc.read_bytes() == before


def test_peer_and_patience_rows_sit_beside_ours_with_the_mujoco_default_measure(results: Path) -> None:
    defaults = {"mean_resting": 13.1, "std_resting": 2.0, "all_rest": False, "mean_settle_distance_m": 0.0021}
    ours_p10 = {**CLUTTER, "patience": 10, "mean_objects": 21.5, "mujoco_default": defaults}
    peer = {
        **CLUTTER,
        "peer": "scene-synthesizer 1.15.0",
        "mean_objects": 7.4,
        "mean_settle_distance_m": 0.0011,
        "mujoco_default": {**defaults, "mean_resting": 7.4, "all_rest": True, "mean_settle_distance_m": 0.0011},
    }
    write(results, "clutter_no-stack_p10_100", ours_p10, machine=MACHINE)
    write(results, "clutter_peer_no-stack_100", peer, machine=MACHINE)
    write(results, "clutter_peer_no-stack_p10_100", {**peer, "patience": 10, "mean_objects": 18.9}, machine=MACHINE)
    clutter = render_tables(results)["clutter"]
    rows = [line for line in clutter.splitlines() if line.startswith("| no-stack (")]
    assert [row.split(" | ")[2:4] for row in rows] == [
        ["first failure", "physcensis"],
        ["first failure", "scene-synthesizer 1.15.0"],
        ["10 failures in a row", "physcensis"],
        ["10 failures in a row", "scene-synthesizer 1.15.0"],
    ]
    assert (
        "| 7.40 ± 2.00 (min 10, max 17), 100 scenes | 7.40 ± 2.00, all rest | 14.77 | 3.0 s | – | 1.1 mm |" in rows[1]
    )
    assert "| 21.50 ± 2.00 (min 10, max 17), 100 scenes | 13.10 ± 2.00 | 14.77 | 3.0 s | 0.001 mm | 2.1 mm |" in rows[2]
    assert "| still resting under MuJoCo defaults |" in clutter
