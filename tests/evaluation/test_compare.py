"""`eval compare` and its methods: llm-only runs no solver, the table's numbers are the scene folders' numbers."""

from __future__ import annotations

import json
import statistics
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from physcensis.assets.catalogue import default_catalogue
from physcensis.evaluation import methods
from physcensis.evaluation.compare import RESULTS, TABLE, Job, run_compare, run_job
from physcensis.evaluation.methods import OFFLINE_STAND_IN, MethodTask, run_llm_only, run_program_frozen, without_report
from physcensis.evaluation.relations import check_scene_folder
from physcensis.scene import Support, load_scene

SUPPORT = Support(kind="table", size=(0.8, 0.6))


def _refuse(*args: Any, **kwargs: Any) -> Any:
    raise AssertionError("a baseline without search must not run a solver")


def test_program_frozen_keeps_the_programs_positions_without_any_solver(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(methods, "solve", _refuse)
    monkeypatch.setattr("physcensis.solver.spatial._Search.round", _refuse)  # no step of the layout search
    monkeypatch.setattr("physcensis.solver.pipeline.PhysicalSolver", _refuse)
    task = MethodTask("a laptop with a mug to the right of it and a book on the laptop", SUPPORT, seed=0)
    output = run_program_frozen(task, default_catalogue())
    assert output.solution is not None
    scene = output.solution.scene
    by_id = {o.id: o for o in scene.objects}
    laptop = next(o for o in scene.objects if o.category == "laptop")
    book = next(o for o in scene.objects if o.category == "book")
    assert book.placement is not None and book.placement.target == laptop.id
    # on the laptop's centre at its top, as the program asks, not where a solver would have let it rest
    assert book.position[:2] == pytest.approx(laptop.position[:2], abs=1e-9)
    assert book.position[2] > laptop.position[2]
    assert set(by_id) == {o.id for o in scene.objects}
    assert output.judged_program == scene.program and output.attempts == 1


def test_no_report_drops_only_the_empty_region_lines() -> None:
    text = "\n".join(
        [
            "The scene was solved but 1 object(s) could not be placed:",
            "- mug_0 (PLACE-ON-BASE): sticks out 2.0 cm past the left edge",
            "The table is crowded (71% of its top is covered).",
            "There is an empty region of 20 x 30 cm at the front left (x 0.30, y 0.20).",
            "Revise the program: move or shrink what failed.",
        ]
    )
    kept = without_report(text).splitlines()
    assert kept == [text.splitlines()[k] for k in (0, 1, 4)]


def _mean(rows: list[dict[str, Any]], method: str, key: str) -> float:
    return statistics.fmean(r["metrics"][key] for r in rows if r["method"] == method)


def test_compare_writes_rows_table_and_plots_that_match_the_scene_folders(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    tiny = np.zeros((8, 8, 3), dtype=np.uint8)  # the render itself is tested elsewhere; here it only costs time
    monkeypatch.setattr("physcensis.output.scene_folder.render_built", lambda *args, **kwargs: tiny)
    monkeypatch.setattr("physcensis.output.scene_folder.plot_layout", lambda *args, **kwargs: None)
    prompts = tmp_path / "prompts.jsonl"
    lines = [
        {
            "id": "mug-laptop",
            "prompt": "a laptop with a mug to the right of it",
            "support": {"kind": "table", "size": [0.8, 0.6]},
        },
        {"id": "laptop", "prompt": "a laptop", "support": {"kind": "table", "size": [0.8, 0.6]}},
    ]
    prompts.write_text("".join(json.dumps(line) + "\n" for line in lines))
    out = tmp_path / "cmp"
    rows = run_compare(prompts, out, ["random", "llm-only"], 1)
    assert len(rows) == 4 and len((out / RESULTS).read_text().splitlines()) == 4
    keys = {"prompt", "prompt_id", "method", "seed", "scene_dir", "made_by", "ok", "metrics", "failures"}
    for row in rows:
        assert set(row) == keys
        folder = out / row["scene_dir"]
        assert {"render.png", "scene.json", "report.json"} <= {p.name for p in folder.iterdir()}
        assert json.loads((folder / "evaluation.json").read_text()) == row
        relations = check_scene_folder(folder)
        assert row["metrics"]["relation_accuracy"] == pytest.approx(relations.accuracy)
        assert row["metrics"]["objects_placed"] == len(load_scene(folder / "scene.json").placed)
        metrics = row["metrics"]  # over every requested object, a missing one counting as fallen (1 m)
        missing = max(metrics["objects_requested"], metrics["objects_placed"]) - metrics["objects_placed"]
        measured = metrics["settle_distance_m"] * metrics["objects_placed"]
        expected = (measured + missing) / (metrics["objects_placed"] + missing)
        assert metrics["settle_distance_requested_m"] == pytest.approx(expected)
    table = (out / TABLE).read_text()
    for method in ("random", "llm-only"):
        line = next(x for x in table.splitlines() if x.startswith(f"| {method} |"))
        assert f"{_mean(rows, method, 'relation_accuracy'):.3f} ±" in line
        assert f"{_mean(rows, method, 'settle_distance_m') * 1000:.2f} ±" in line
        assert f"{_mean(rows, method, 'settle_distance_requested_m') * 1000:.2f} ±" in line
    assert (out / "metrics.png").stat().st_size > 0 and (out / "settle_distance.png").stat().st_size > 0
    page = (out / "index.html").read_text()  # the gallery of the rows: one card each, from results.jsonl
    assert all(json.dumps(row["scene_dir"])[1:-1] in page for row in rows)
    # run again: every row is there, nothing is made twice
    assert run_compare(prompts, out, ["random", "llm-only"], 1) == rows
    assert len((out / RESULTS).read_text().splitlines()) == 4


def test_a_method_that_breaks_is_a_failed_row_with_its_folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    def broken(task: MethodTask, catalogue: Any) -> Any:
        raise RuntimeError("the simulator is gone")

    monkeypatch.setitem(methods.METHODS, "random", broken)
    row = run_job(Job(str(tmp_path), "p", "a mug", "table:0.8x0.6", "random", 3))
    assert row["ok"] is False and row["failures"] == ["the method failed: RuntimeError: the simulator is gone"]
    folder = tmp_path / row["scene_dir"]
    assert json.loads((folder / "report.json").read_text())["ok"] is False
    assert json.loads((folder / "evaluation.json").read_text()) == row


def test_the_readme_block_shows_each_methods_mean_and_std(tmp_path: Path) -> None:
    from physcensis.bench.report import render_tables
    from physcensis.evaluation.compare import summary_record

    def row(method: str, seed: int, settle_m: float, accuracy: float) -> dict[str, Any]:
        metrics = {"settle_distance_m": settle_m, "relation_accuracy": accuracy, "attempts": 1.0 + seed}
        return {"prompt_id": "p", "method": method, "seed": seed, "ok": accuracy == 1.0, "metrics": metrics}

    rows = [row("ours", 0, 0.001, 1.0), row("ours", 1, 0.003, 1.0), row("random", 0, 0.010, 0.5)]
    (tmp_path / "compare.json").write_text(json.dumps({"result": summary_record(rows, ["ours", "random"])}))
    block = render_tables(tmp_path)["compare"]
    ours = next(line for line in block.splitlines() if line.startswith("| ours |"))
    assert "2.00 ± 1.00" in ours and "1.000 ± 0.000" in ours and "1.50 ± 0.50" in ours and "2 / 2" in ours
    random = next(line for line in block.splitlines() if line.startswith("| random |"))
    assert "10.00 ± 0.00" in random and "0.500 ± 0.000" in random and "0 / 1" in random
    assert "VQA" not in block  # no VLM, no column
    rows[0]["metrics"]["vqa_score"] = 0.8
    (tmp_path / "compare.json").write_text(json.dumps({"result": summary_record(rows, ["ours", "random"])}))
    block = render_tables(tmp_path)["compare"]
    header = block.splitlines()[0].split(" | ")
    ours = next(line for line in block.splitlines() if line.startswith("| ours |")).split(" | ")
    random = next(line for line in block.splitlines() if line.startswith("| random |")).split(" | ")
    column = header.index("VQA score")
    assert ours[column] == "0.800 ± 0.000" and random[column] == "–"


PROMPTS = {"a": "a mug", "b": "a cup"}  # what _two_prompts writes


def _row(prompt_id: str, method: str = "random") -> dict[str, Any]:
    from physcensis.batch.prompts import DEFAULT_SUPPORT

    prompt = PROMPTS[prompt_id]
    return {
        "prompt": prompt,
        "prompt_id": prompt_id,
        "method": method,
        "seed": 0,
        "scene_dir": f"scenes/{method}/{prompt_id}/seed0",
        "made_by": {
            "prompt": prompt,
            "support": Support.parse(DEFAULT_SUPPORT).model_dump_json(),
            "llm": None,
            "vlm": None,
        },
        "ok": True,
        "metrics": {"attempts": 1.0},
        "failures": [],
    }


def _two_prompts(tmp_path: Path) -> Path:
    prompts = tmp_path / "prompts.jsonl"
    prompts.write_text('{"id": "a", "prompt": "a mug"}\n{"id": "b", "prompt": "a cup"}\n')
    return prompts


def test_a_run_killed_mid_row_resumes_on_a_line_of_its_own(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from physcensis.evaluation import compare
    from physcensis.gallery.cards import collect_cards

    out = tmp_path / "cmp"
    out.mkdir()
    (out / RESULTS).write_text(json.dumps(_row("a")) + "\n" + json.dumps(_row("b"))[:40])  # b torn by a kill
    made: list[str] = []
    monkeypatch.setattr(
        compare, "_rows", lambda todo, workers: (made.append(j.prompt_id) or _row(j.prompt_id) for j in todo)
    )
    monkeypatch.setattr(compare, "write_plots", lambda *args: [])
    rows = run_compare(_two_prompts(tmp_path), out, ["random"], 1)
    assert made == ["b"] and [r["prompt_id"] for r in rows] == ["a", "b"]
    lines = (out / RESULTS).read_text().splitlines()
    assert [json.loads(line)["prompt_id"] for line in lines] == ["a", "b"]
    assert [c.prompt_id for c in collect_cards(out)] == ["a", "b"]  # the report reads the same file


@pytest.mark.parametrize("garbage", ['{"a": 1}', json.dumps({k: v for k, v in _row("a").items() if k != "metrics"})])
def test_a_results_file_with_a_line_that_is_no_row_is_one_clear_error(tmp_path: Path, garbage: str) -> None:
    from typer.testing import CliRunner

    from physcensis.cli import app

    out = tmp_path / "cmp"
    out.mkdir()
    (out / RESULTS).write_text(json.dumps(_row("a")) + "\n" + garbage + "\n")
    args = ["eval", "compare", "--prompts", str(_two_prompts(tmp_path)), "--out", str(out), "--methods", "random"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2, result.output
    assert "line 2" in result.output and "Traceback" not in result.output
    assert not (out / "scenes").exists()  # nothing was made


@pytest.mark.parametrize(("methods_option", "message"), [(",", "no method"), ("ours,nonesuch", "unknown method")])
def test_compare_needs_known_methods(tmp_path: Path, methods_option: str, message: str) -> None:
    from typer.testing import CliRunner

    from physcensis.cli import app

    out = tmp_path / "cmp"
    args = ["eval", "compare", "--prompts", str(_two_prompts(tmp_path)), "--out", str(out), "--methods", methods_option]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2 and message in result.output, result.output
    assert not out.exists()


def test_a_method_named_twice_runs_once(tmp_path: Path) -> None:
    from physcensis.batch.prompts import read_prompts
    from physcensis.evaluation.compare import Models, plan_jobs

    names = ["ours", " ours", "random", "ours"]
    jobs = plan_jobs(tmp_path, read_prompts(_two_prompts(tmp_path)), names, 1, Models())
    assert [(j.prompt_id, j.method) for j in jobs] == [("a", "ours"), ("a", "random"), ("b", "ours"), ("b", "random")]


def test_a_plot_cut_short_leaves_the_old_one(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from matplotlib.figure import Figure

    from physcensis.evaluation.compare import write_plots

    (tmp_path / "metrics.png").write_bytes(b"the old plot")

    def killed(self: Any, target: Any, *args: Any, **kwargs: Any) -> None:
        (target.write if hasattr(target, "write") else Path(target).write_bytes)(b"\x89PNG half")
        raise KeyboardInterrupt

    monkeypatch.setattr(Figure, "savefig", killed)
    with pytest.raises(KeyboardInterrupt):
        write_plots([_row("a")], ["random"], tmp_path)
    assert (tmp_path / "metrics.png").read_bytes() == b"the old plot"


@pytest.mark.parametrize("kind", ["file", "link"])
def test_compare_out_must_be_a_folder(tmp_path: Path, kind: str) -> None:
    from typer.testing import CliRunner

    from physcensis.cli import app

    out = tmp_path / "cmp"
    if kind == "file":
        out.write_text("a user's notes")
    else:
        (tmp_path / "elsewhere").mkdir()
        out.symlink_to(tmp_path / "elsewhere")
    args = ["eval", "compare", "--prompts", str(_two_prompts(tmp_path)), "--out", str(out), "--methods", "random"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2 and "give --out a folder" in result.output, result.output
    assert "Errno" not in result.output and "Traceback" not in result.output
    assert out.is_symlink() or out.read_text() == "a user's notes"
    assert not (tmp_path / "elsewhere" / RESULTS).exists()


def test_rows_made_from_another_prompt_text_or_model_are_made_again(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from physcensis.evaluation import compare

    out = tmp_path / "cmp"
    out.mkdir()
    edited = _row("a") | {"prompt": "a blue mug", "made_by": _row("a")["made_by"] | {"prompt": "a blue mug"}}
    other_llm = _row("b") | {"made_by": _row("b")["made_by"] | {"llm": "some-model"}}
    (out / RESULTS).write_text(json.dumps(edited) + "\n" + json.dumps(other_llm) + "\n")
    made: list[str] = []
    monkeypatch.setattr(
        compare, "_rows", lambda todo, workers: (made.append(j.prompt_id) or _row(j.prompt_id) for j in todo)
    )
    monkeypatch.setattr(compare, "write_plots", lambda *args: [])
    rows = run_compare(_two_prompts(tmp_path), out, ["random"], 1)
    assert made == ["a", "b"]
    lines = [json.loads(line) for line in (out / RESULTS).read_text().splitlines()]
    assert [(r["prompt_id"], r["prompt"]) for r in lines] == [("a", "a mug"), ("b", "a cup")]  # stale rows gone
    assert rows == lines
    assert run_compare(_two_prompts(tmp_path), out, ["random"], 1) == rows and made == ["a", "b"]  # now resumed


def test_the_visual_method_without_a_vlm_is_refused_before_any_work(tmp_path: Path) -> None:
    from typer.testing import CliRunner

    from physcensis.cli import app

    out = tmp_path / "cmp"
    args = ["eval", "compare", "--prompts", str(_two_prompts(tmp_path)), "--out", str(out), "--methods", "ours,visual"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2 and "--vlm" in result.output and "visual" in result.output, result.output
    assert not out.exists()


def test_rows_from_before_rows_recorded_their_making_are_kept_and_unscored_vlm_rows_remade(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from physcensis.evaluation import compare
    from physcensis.evaluation.compare import Models

    out = tmp_path / "cmp"
    out.mkdir()
    legacy = {k: v for k, v in _row("a").items() if k != "made_by"}
    (out / RESULTS).write_text(json.dumps(legacy) + "\n")
    made: list[str] = []
    monkeypatch.setattr(
        compare, "_rows", lambda todo, workers: (made.append(j.prompt_id) or _row(j.prompt_id) for j in todo)
    )
    monkeypatch.setattr(compare, "write_plots", lambda *args: [])
    run_compare(_two_prompts(tmp_path), out, ["random"], 1)
    assert made == ["b"]  # the old row of "a" stands
    with_vlm = Models(vlm="some-vlm", vlm_base_url="http://127.0.0.1:9/v1")
    placed = {"objects_placed": 1.0}

    def scored(prompt_id: str, score: bool) -> dict[str, Any]:
        row = _row(prompt_id)
        row["made_by"] = row["made_by"] | {"vlm": "some-vlm"}
        row["metrics"] = placed | ({"vqa_score": 0.5} if score else {})
        return row

    (out / RESULTS).write_text(json.dumps(scored("a", True)) + "\n" + json.dumps(scored("b", False)) + "\n")
    made.clear()
    dropped: list[int] = []
    run_compare(_two_prompts(tmp_path), out, ["random"], 1, models=with_vlm, on_dropped=dropped.append)
    assert made == ["b"] and dropped == [1]  # the VLM never scored b's scene: made again


LAYOUT_PROGRAM = """[["mug_0", "a white mug"], ["mug_0", "PLACE-ON-BASE", "root", {"x": 0.1, "y": 0.1}],
 ["book_0", "a hardcover book lying flat"], ["book_0", "PLACE-ON-BASE", "root", {"x": -0.1, "y": -0.1}]]"""


def test_llm_only_has_the_model_write_every_pose_and_hears_what_is_wrong(monkeypatch: pytest.MonkeyPatch) -> None:
    """The paper's LLM-only: the model's coordinates are the scene (no solver); a reply that misses an object goes
    back to it with what is missing; the scene is judged against the first program."""
    from physcensis.program import parse_program
    from tests.agent.fake_server import FakeOpenAI, use_loopback_only

    use_loopback_only(monkeypatch, "sk-test-layout")
    monkeypatch.setattr(methods, "first_program", lambda task, catalogue: parse_program(LAYOUT_PROGRAM))
    monkeypatch.setattr(methods, "solve", _refuse)
    monkeypatch.setattr("physcensis.solver.pipeline.PhysicalSolver", _refuse)
    partial = json.dumps({"poses": [{"id": "mug_0", "x": 0.2, "y": -0.1, "z": 0.0, "yaw": 90}]})
    whole = json.dumps(
        {
            "poses": [
                {"id": "mug_0", "x": 0.2, "y": -0.1, "z": 0.0, "yaw": 90},
                {"id": "book_0", "x": -0.15, "y": 0.12, "z": 0.0, "yaw": 0},
            ]
        }
    )
    with FakeOpenAI([partial, whole]) as server:
        from physcensis.settings import ModelSettings

        models = ModelSettings(llm="fake-llm", base_url=server.base_url, stream=False)
        output = run_llm_only(MethodTask("a mug and a book", SUPPORT, seed=0, models=models), default_catalogue())
        asked = server.requests
    assert len(asked) == 2 and "book_0: no pose given" in asked[1]["messages"][-1]["content"]
    assert "mug_0: a white mug" in asked[0]["messages"][1]["content"]  # each object listed with its size
    assert '"enum": ["mug_0", "book_0"]' in json.dumps(asked[0]["response_format"])  # under the layout's schema
    assert output.solution is not None
    poses = {o.id: o for o in output.solution.scene.objects}
    assert poses["mug_0"].position[:2] == pytest.approx((0.2, -0.1))
    assert poses["book_0"].position[:2] == pytest.approx((-0.15, 0.12))
    assert poses["mug_0"].position[2] == pytest.approx(SUPPORT.top_height)
    assert output.extra["layout_problems"] == [] and output.judged_program == output.solution.scene.program


def test_llm_only_offline_says_what_stands_in() -> None:
    output = run_llm_only(MethodTask("a mug on a book", SUPPORT, seed=0), default_catalogue())
    assert output.extra["stand_in"] == OFFLINE_STAND_IN and output.solution is not None
