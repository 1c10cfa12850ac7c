"""The paper's ranking of methods by a vision model: answers read as orders, shuffled showings, mean ranks."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from typer.testing import CliRunner

from physcensis.cli import app
from physcensis.evaluation.rank import GroupRanks, Ranker, mean_ranks, question, read_ranking
from tests.agent.fake_server import FakeOpenAI, use_loopback_only

PNG = b"\x89PNG\r\n\x1a\n" + b"\x00" * 32


@pytest.mark.parametrize(
    ("answer", "order"),
    [
        ("2, 1, 3", [1, 0, 2]),
        ("Best is 3, then 1, then 2.", [2, 0, 1]),
        ("3 1", [2, 0, 1]),  # all but one named: the last is the one left out
        ("1, 1, 2, 3", [0, 1, 2]),  # a repeat counts once
        ("7, 8", None),
        ("I cannot tell", None),
    ],
)
def test_an_answer_is_read_as_an_order_of_pictures(answer: str, order: list[int] | None) -> None:
    assert read_ranking(answer, 3) == order


def test_each_showing_is_shuffled_and_ranks_follow_the_pictures(monkeypatch: pytest.MonkeyPatch) -> None:
    """The model always prefers the picture it sees first: every method then ranks first as often as it is shown
    first, so a method's mean rank depends on the showings, not on its name; the question holds every render."""
    use_loopback_only(monkeypatch, "sk-test-rank")
    renders = {"ours": PNG + b"o", "random": PNG + b"r", "llm-only": PNG + b"l"}
    with FakeOpenAI(["1, 2, 3"] * 8) as server:
        group = Ranker("fake-vlm", server.base_url, draws=8, seed=3).rank_group("p", 0, "a desk", renders)
        requests = list(server.requests)
    assert len(requests) == 8 and group.unread == 0 and group.error is None
    firsts = []
    for request in requests:
        content = request["messages"][0]["content"]
        assert content[0]["text"] == question("a desk", 3) and len(content) == 4
        firsts.append(content[1]["image_url"]["url"])
    assert len(set(firsts)) > 1  # not always the same method shown first
    assert sorted(len(v) for v in group.ranks.values()) == [8, 8, 8]
    assert sum(group.mean(m) or 0 for m in renders) == pytest.approx(6.0)  # ranks 1, 2, 3 each showing


def test_mean_ranks_order_the_methods_best_first() -> None:
    groups = [GroupRanks("a", 0, {"x": [1, 1], "y": [2, 2]}), GroupRanks("b", 0, {"x": [2], "y": [1]})]
    means = mean_ranks(groups)
    assert list(means) == ["x", "y"] and means["x"]["mean"] == pytest.approx(1.5) and means["x"]["groups"] == 2


def test_eval_rank_on_a_comparison_folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    use_loopback_only(monkeypatch, "sk-test-rank")
    out = tmp_path / "cmp"
    rows = []
    for k, method in enumerate(("ours", "random")):
        folder = out / "scenes" / method
        folder.mkdir(parents=True)
        (folder / "render.png").write_bytes(PNG + bytes([k]))
        rows.append(
            {
                "prompt": "a desk",
                "prompt_id": "desk",
                "method": method,
                "seed": 0,
                "scene_dir": f"scenes/{method}",
                "made_by": {},
                "ok": True,
                "metrics": {},
                "failures": [],
            }
        )
    (out / "results.jsonl").write_text("".join(json.dumps(r) + "\n" for r in rows))
    with FakeOpenAI(["1, 2"] * 3) as server:
        args = ["eval", "rank", str(out), "--vlm", "fake-vlm", "--base-url", server.base_url, "--json"]
        result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    summary = json.loads(result.stdout)
    assert summary["groups"] == 1 and set(summary["methods"]) == {"ours", "random"}
    assert json.loads((out / "rank.json").read_text())["methods"] == summary["methods"]
    shutil.rmtree(out / "scenes" / "random")  # one render left: nothing to rank
    with FakeOpenAI([]) as server:
        args = ["eval", "rank", str(out), "--vlm", "fake-vlm", "--base-url", server.base_url]
        alone = CliRunner().invoke(app, args)
    assert alone.exit_code == 1 and "could be ranked" in alone.output
