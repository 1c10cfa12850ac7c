"""A vision model's VQA score (and, for the visual method, its remarks) reaches the agent as feedback in the loop:
the question and the render are sent, the answer's log-probabilities are read, a low score earns one more round,
and the scene kept is the one the model scored highest. Two real local servers: the agent's and the VLM's."""

from __future__ import annotations

import json
import math
from collections.abc import Callable

import pytest

from physcensis.agent.critic import MAX_REVISIONS, REVISE_BELOW, Critique
from physcensis.agent.loop import generate_scene
from physcensis.api import Generated, generate
from physcensis.scene import Scene, Support

from .fake_server import MUG_AND_BOOK, FakeOpenAI, Reply

pytestmark = pytest.mark.physics
SUPPORT = Support(kind="table", size=(0.6, 0.6))
PROMPT = "a mug and a book on a small table"
MUG_ONLY = json.dumps(
    [
        ["mug_0", "a white coffee mug"],
        ["mug_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
        ["mug_0", "FACING-FRONT", "root", {}],
    ]
)
Fake = Callable[..., FakeOpenAI]


def _vqa_reply(p_yes: float) -> Reply:
    top = (("Yes", math.log(p_yes)), ("No", math.log(1 - p_yes)))
    return Reply(content="Yes" if p_yes >= 0.5 else "No", top_logprobs=top)


def _generate(llm: FakeOpenAI, vlm: FakeOpenAI, **options: object) -> Generated:
    """The loop with the scripted agent `llm` and the scripted vision model `vlm`."""
    return generate(
        PROMPT,
        support=SUPPORT,
        llm="test-model",
        base_url=llm.base_url,
        vlm="fake-vlm",
        vlm_base_url=vlm.base_url,
        stream=False,
        hint="off",  # test_hint.py tests the draft
        **options,  # type: ignore[arg-type]
    )


@pytest.mark.slow
def test_a_low_score_is_fed_back_and_earns_one_more_round_whose_better_scene_is_kept(fake_openai: Fake) -> None:
    llm = fake_openai(MUG_ONLY, MUG_AND_BOOK)
    vlm = fake_openai(_vqa_reply(0.2), _vqa_reply(0.9))
    generated = _generate(llm, vlm)
    result = generated.result
    assert [row["feedback_kind"] for row in result.transcript if "program" in row] == ["success", "success"]
    # the VLM got the paper's question with the render, twice (once per solved round)
    assert len(vlm.requests) == 2
    text, image = vlm.requests[0]["messages"][0]["content"]
    assert text["text"].startswith("Does this image show a mug and a book") and image["image_url"]["url"].startswith(
        "data:image/png;base64,"
    )
    # what the agent was told in its second request: the score and that the scene should change
    second = llm.messages[1][-1]["content"]
    assert "VQA score 0.20" in second and "unlikely" in second
    assert "doubts that it shows the request" in second and "Keep every existing entry" not in second  # revise
    scores = [row["critic"]["vqa_score"] for row in result.transcript if "critic" in row]
    assert scores == [pytest.approx(0.2), pytest.approx(0.9)]
    assert generated.solution is not None
    assert {o.id for o in generated.solution.scene.placed} == {"mug_0", "book_0"}
    assert generated.vqa == pytest.approx(0.9)  # the kept scene's score, not asked a third time


def test_a_good_score_adds_no_round_and_the_higher_scored_scene_wins_over_a_later_one() -> None:
    calls: list[int] = []

    def critic(scene: Scene, seconds_left: float | None) -> Critique:
        calls.append(len(scene.placed))
        return Critique(0.9 if len(scene.placed) == 1 else 0.6)

    class Scripted:
        name = "scripted"

        def __init__(self) -> None:
            self.replies = [MUG_ONLY, MUG_AND_BOOK, MUG_AND_BOOK]

        def propose(self, context: object) -> str:
            return self.replies.pop(0)

    result = generate_scene(PROMPT, Scripted(), support=SUPPORT, rounds=2, critic=critic)  # type: ignore[arg-type]
    assert calls == [1, 2]  # two rounds asked for, both scored above REVISE_BELOW: no revision round
    assert result.solution is not None and len(result.solution.scene.placed) == 1  # 0.9 beats 0.6
    assert result.vqa == pytest.approx(0.9)


def test_revisions_are_bounded_however_low_the_scores_stay() -> None:
    scored: list[float] = []

    def critic(scene: Scene, seconds_left: float | None) -> Critique:
        scored.append(0.1)
        return Critique(0.1)

    class Scripted:
        name = "scripted"

        def propose(self, context: object) -> str:
            return MUG_AND_BOOK

    result = generate_scene(PROMPT, Scripted(), support=SUPPORT, critic=critic)  # type: ignore[arg-type]
    assert 0.1 < REVISE_BELOW and len(scored) == 1 + MAX_REVISIONS
    assert result.ok and result.vqa == pytest.approx(0.1)


@pytest.mark.slow
def test_the_visual_method_sends_the_models_remarks_and_an_unreachable_vlm_stops_nothing(fake_openai: Fake) -> None:
    llm = fake_openai(MUG_AND_BOOK, MUG_AND_BOOK)
    remark = "The book is missing; only a mug is visible."
    vlm = fake_openai(_vqa_reply(0.3), remark, _vqa_reply(0.8), "Nothing.")
    generated = _generate(llm, vlm, vlm_feedback="remarks")
    assert "does not match" in vlm.requests[1]["messages"][0]["content"][0]["text"]
    second = llm.messages[1][-1]["content"]
    assert remark in second
    rows = [row for row in generated.result.transcript if "critic" in row]
    assert rows[0]["critic"]["remarks"] == remark and "base64" not in json.dumps(rows)

    down = fake_openai(fail_first=100)
    llm2 = fake_openai(MUG_AND_BOOK)
    kept = _generate(llm2, down, llm_timeout_s=2.0)
    assert kept.solution is not None and kept.vqa is None  # no score, no extra round, the scene still made
    assert len(llm2.requests) == 1


def test_with_min_objects_a_scene_that_has_them_beats_a_better_scored_one_that_does_not() -> None:
    def critic(scene: Scene, seconds_left: float | None) -> Critique:
        return Critique(0.9 if len(scene.placed) == 1 else 0.6)

    class Scripted:
        name = "scripted"

        def __init__(self) -> None:
            self.replies = [MUG_ONLY, MUG_AND_BOOK]

        def propose(self, context: object) -> str:
            return self.replies.pop(0) if self.replies else MUG_AND_BOOK

    agent = Scripted()
    result = generate_scene(PROMPT, agent, support=SUPPORT, min_objects=2, critic=critic)  # type: ignore[arg-type]
    assert result.solution is not None and len(result.solution.scene.placed) == 2
    assert result.vqa == pytest.approx(0.6) and result.rounds == 2 and result.stop_reason == "done"
