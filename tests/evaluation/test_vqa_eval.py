"""VQA in the evaluation, against a scripted OpenAI-compatible vision server: `eval compare --vlm` scores every
method's scene from the same view (reusing the loop's own score for `visual`), shows a VQA column and keeps the visual
method's remarks in its transcript; `eval vqa` scores saved folders and names the ones it cannot."""

from __future__ import annotations

import json
import math
import shutil
from pathlib import Path

import pytest
from typer.testing import CliRunner

from physcensis.cli import app
from physcensis.evaluation.compare import TABLE, Models, run_compare
from tests.agent.fake_server import FakeOpenAI, Reply, use_loopback_only

pytestmark = pytest.mark.physics


def _vqa(p_yes: float) -> Reply:
    return Reply(
        content="Yes" if p_yes >= 0.5 else "No", top_logprobs=(("Yes", math.log(p_yes)), ("No", math.log(1 - p_yes)))
    )


@pytest.fixture(autouse=True)
def _loopback(monkeypatch: pytest.MonkeyPatch) -> None:
    use_loopback_only(monkeypatch, "sk-test-vqa")


@pytest.fixture(scope="module")
def compared(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, list[dict], list[dict]]:
    root = tmp_path_factory.mktemp("vqa-compare")
    prompts = root / "prompts.jsonl"
    prompts.write_text('{"id": "mug", "prompt": "a mug on a small table", "support": "table:0.6x0.6"}\n')
    with pytest.MonkeyPatch.context() as patch:
        use_loopback_only(patch, "sk-test-vqa")
        with FakeOpenAI([_vqa(0.4), _vqa(0.9), "Nothing.", "1, 2", "2, 1", "Picture 2 is best, then 1."]) as server:
            models = Models(vlm="fake-vlm", vlm_base_url=server.base_url)
            rows = run_compare(prompts, root / "cmp", ["random", "visual"], 1, models=models)
            requests = list(server.requests)
    return root / "cmp", rows, requests


@pytest.mark.slow
@pytest.mark.long
def test_compare_scores_every_method_once_from_the_same_view(compared: tuple[Path, list[dict], list[dict]]) -> None:
    out, rows, requests = compared
    by_method = {row["method"]: row for row in rows}
    assert by_method["random"]["metrics"]["vqa_score"] == pytest.approx(0.4)
    assert by_method["visual"]["metrics"]["vqa_score"] == pytest.approx(0.9)  # the loop's score, not asked again
    assert len(requests) == 6  # two VQA questions, the visual method's remarks, three showings to rank
    questions = [r["messages"][0]["content"][0]["text"] for r in requests]
    assert questions[0] == questions[1] == "Does this image show a mug on a small table? Answer Yes or No."
    assert "does not match" in questions[2]
    images = [r["messages"][0]["content"][1]["image_url"]["url"] for r in requests]
    assert all(url.startswith("data:image/png;base64,iVBORw0KGgo") for url in images)
    assert "VQA score ↑" in (out / TABLE).read_text() and "VLM rank ↓" in (out / TABLE).read_text()
    for request in requests[3:]:  # the paper's ranking: both renders in one question, best first
        content = request["messages"][0]["content"]
        assert "Rank them from best to worst" in content[0]["text"] and len(content) == 3
    ranks = [row["metrics"]["vlm_rank"] for row in rows]
    assert all(1.0 <= r <= 2.0 for r in ranks) and sum(ranks) == pytest.approx(3.0)
    assert json.loads((out / rows[0]["scene_dir"] / "evaluation.json").read_text()) == rows[0]
    assert all(row["made_by"]["vlm"] == "fake-vlm" for row in rows)


@pytest.mark.long
def test_the_visual_methods_transcript_holds_the_score_and_the_remarks(
    compared: tuple[Path, list[dict], list[dict]],
) -> None:
    out, rows, _ = compared
    visual = next(row for row in rows if row["method"] == "visual")
    lines = [json.loads(line) for line in (out / visual["scene_dir"] / "transcript.jsonl").read_text().splitlines()]
    critic = next(line["critic"] for line in lines if "critic" in line)
    assert critic["vqa_score"] == pytest.approx(0.9) and critic["remarks"] == "Nothing."
    assert "base64" not in json.dumps(lines)  # the requests are recorded without the image


@pytest.mark.long
def test_eval_vqa_scores_saved_folders_and_names_one_it_cannot(
    compared: tuple[Path, list[dict], list[dict]], tmp_path: Path
) -> None:
    out, rows, _ = compared
    scenes = tmp_path / "scenes"
    for k, row in enumerate(rows):
        shutil.copytree(out / row["scene_dir"], scenes / f"s{k}")
    orphan = scenes / "s9"
    shutil.copytree(scenes / "s0", orphan)
    for name in ("scene.json", "report.json"):
        data = json.loads((orphan / name).read_text())
        data.pop("prompt", None)
        (orphan / name).write_text(json.dumps(data))
    with FakeOpenAI([_vqa(0.7), _vqa(0.2)]) as server:
        args = ["eval", "vqa", str(scenes), "--vlm", "fake-vlm", "--base-url", server.base_url, "--json"]
        result = CliRunner().invoke(app, args)
    assert result.exit_code == 1, result.output
    printed = json.loads(result.stdout)
    scores = {Path(r["scene"]).name: r["score"] for r in printed["scenes"]}
    assert scores["s0"] == pytest.approx(0.7) and scores["s1"] == pytest.approx(0.2), printed
    assert scores["s9"] is None
    assert printed["vqa_score"]["mean"] == pytest.approx(0.45)
    assert "s9: not scored: the scene records no prompt" in result.output
    with FakeOpenAI(["Yes"]) as server:
        args = ["eval", "vqa", str(orphan), "--vlm", "fake-vlm", "--base-url", server.base_url, "--prompt", "a mug"]
        given = CliRunner().invoke(app, args)
        asked = server.requests[0]["messages"][0]["content"][0]["text"]
    assert given.exit_code == 0 and "1.000" in given.stdout and "a mug?" in asked
    unsure = Reply(content="Yes", top_logprobs=(("Yes", math.log(0.6)), ("No", math.log(0.2)), ("Hmm", math.log(0.2))))
    for kind, expected in (("p-yes", 0.6), ("normalised", 0.75)):  # the paper's P("Yes"), or against P("No") alone
        with FakeOpenAI([unsure]) as server:
            args = ["eval", "vqa", str(scenes / "s0"), "--vlm", "fake-vlm", "--base-url", server.base_url]
            scored = CliRunner().invoke(app, [*args, "--vqa", kind, "--json"])
        assert json.loads(scored.stdout)["scenes"][0]["score"] == pytest.approx(expected), kind


@pytest.mark.long
def test_eval_vqa_stops_asking_once_the_server_does_not_answer_and_refuses_empty_values(
    compared: tuple[Path, list[dict], list[dict]],
) -> None:
    out, rows, _ = compared
    scenes = str(out / "scenes")
    args = [
        "eval",
        "vqa",
        scenes,
        "--vlm",
        "fake-vlm",
        "--base-url",
        "http://127.0.0.1:9/v1",
        "--timeout",
        "2",
        "--json",
    ]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 1 and "Traceback" not in result.output
    errors = [r["error"] for r in json.loads(result.stdout)["scenes"]]
    assert len(errors) == len(rows) == 2
    assert errors[0].startswith("the VLM did not answer:") and errors[1].startswith("not asked")
    for option, value in (("--vlm", " "), ("--prompt", "")):
        given = ["eval", "vqa", scenes, "--vlm", "fake-vlm", option, value]
        refused = CliRunner().invoke(app, given)
        assert refused.exit_code == 2 and f"{option} is empty" in refused.output
