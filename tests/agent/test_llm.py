"""The LLM agent and the VQA score against a real local HTTP server with the real `openai` client."""

from __future__ import annotations

import json
import math
import socket
import time
from collections.abc import Callable
from dataclasses import replace

import pytest

from physcensis.agent.base import AgentContext, AgentError, Round
from physcensis.agent.llm import LLMAgent
from physcensis.agent.prompt import REPAIR_INSTRUCTION, compact_system_prompt
from physcensis.agent.vqa import question, vqa_score, yes_probability
from physcensis.llm.client import RetryPolicy

from .conftest import SECRET_KEY
from .fake_server import FakeOpenAI, Reply

pytestmark = pytest.mark.timeout(30)

PROGRAM = '[["mug_0", "a white mug"], ["mug_0", "PLACE-ANYWHERE", "root", {}]]'
PNG = b"\x89PNG\r\n\x1a\n" + b"\x00" * 32
Fake = Callable[..., FakeOpenAI]


def _agent(server: FakeOpenAI | str, **options: object) -> LLMAgent:
    base_url = server if isinstance(server, str) else server.base_url
    # no draft (test_hint.py tests it): these tests are about requests, and a draft would only slow them
    settings: dict[str, object] = {"timeout_s": 5.0, "max_retries": 3, "backoff_s": 0.01, "hint": "off"}
    settings.update(options)
    return LLMAgent("fake-model", base_url=base_url, **settings)  # type: ignore[arg-type]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def test_propose_sends_the_chat_and_returns_the_text(fake_openai: Fake, desk_context: AgentContext) -> None:
    server = fake_openai(PROGRAM)
    agent = _agent(server, temperature=0.3, max_tokens=2000, structured="off")  # the plain request
    assert agent.propose(desk_context) == PROGRAM
    [body] = server.requests
    assert body["model"] == "fake-model" and body["temperature"] == 0.3 and body["max_tokens"] == 2000
    assert body["messages"][0] == {"role": "system", "content": compact_system_prompt()}  # a local server
    assert server.headers[0]["authorization"] == f"Bearer {SECRET_KEY}"
    [call] = agent.calls
    assert call["response"] == PROGRAM and call["error"] is None and call["attempts"] == []
    assert call["usage"]["total_tokens"] > 0


def test_history_goes_over_the_wire(fake_openai: Fake, desk_context: AgentContext) -> None:
    server = fake_openai(PROGRAM)
    context = replace(desk_context, request="repair", history=(Round("[oops", "error: not a list"),))
    _agent(server).propose(context)
    roles = [m["role"] for m in server.messages[0]]
    assert roles == ["system", "user", "assistant", "user"]
    assert REPAIR_INSTRUCTION in server.messages[0][3]["content"]  # then, with the compact prompt, the step's own


def test_invalid_output_is_returned_for_the_loop_to_judge(fake_openai: Fake, desk_context: AgentContext) -> None:
    server = fake_openai("Sure! Here is a nice scene.", Reply(content=None))
    agent = _agent(server)
    assert agent.propose(desk_context) == "Sure! Here is a nice scene."
    assert agent.propose(desk_context) == ""


@pytest.mark.parametrize("status", [500, 502, 429])
def test_transient_status_is_retried(fake_openai: Fake, desk_context: AgentContext, status: int) -> None:
    server = fake_openai(PROGRAM, fail_first=2, fail_status=status)
    agent = _agent(server)
    assert agent.propose(desk_context) == PROGRAM
    assert len(server.requests) == 3
    attempts = agent.calls[0]["attempts"]
    assert [a["status"] for a in attempts] == [status, status] and all(a["retry"] for a in attempts)


def test_retries_wait_exponentially_with_deterministic_jitter(fake_openai: Fake, desk_context: AgentContext) -> None:
    waits: list[float] = []
    server = fake_openai(PROGRAM, fail_first=3)
    agent = _agent(server, backoff_s=0.5, max_backoff_s=60.0, sleep=waits.append)
    assert agent.propose(desk_context) == PROGRAM
    assert len(waits) == 3
    for i, wait in enumerate(waits):
        assert 0.5 * 2**i <= wait <= 0.5 * 2**i * 1.25
    policy = RetryPolicy(backoff_s=0.5, max_backoff_s=60.0)
    assert [policy.delay_s(i, "k") for i in range(3)] == [policy.delay_s(i, "k") for i in range(3)]
    assert RetryPolicy(backoff_s=1.0, max_backoff_s=3.0).delay_s(10) == 3.0


def test_server_errors_exhaust_retries_then_raise(fake_openai: Fake, desk_context: AgentContext) -> None:
    server = fake_openai(PROGRAM, fail_first=10)
    agent = _agent(server, max_retries=2)
    with pytest.raises(AgentError, match="gave up after 3 attempts") as info:
        agent.propose(desk_context)
    assert len(server.requests) == 3
    assert "\n" not in str(info.value) and "500" in str(info.value)
    assert agent.calls[0]["error"] == str(info.value)


def test_timeout_is_retried_and_recovers(fake_openai: Fake, desk_context: AgentContext) -> None:
    server = fake_openai(PROGRAM, hang_first=1, hang_s=5.0)
    agent = _agent(server, attempt_timeout_s=1.0)  # generous: the second request must answer within it
    assert agent.propose(desk_context) == PROGRAM
    assert len(server.requests) == 2
    assert "timeout" in agent.calls[0]["attempts"][0]["error"]


def test_timeouts_retry_then_raise(fake_openai: Fake, desk_context: AgentContext) -> None:
    server = fake_openai(PROGRAM, hang_first=10, hang_s=5.0)
    agent = _agent(server, attempt_timeout_s=0.5, max_retries=2)
    start = time.perf_counter()
    with pytest.raises(AgentError, match="gave up after 3 attempts; last error: no answer before the timeout"):
        agent.propose(desk_context)
    assert len(server.requests) == 3
    assert time.perf_counter() - start < 8.0  # 1.5 s of attempts; had they not timed out, 15 s


def test_unreachable_server_is_retried_then_raises(desk_context: AgentContext) -> None:
    agent = _agent(f"http://127.0.0.1:{_free_port()}/v1", max_retries=1)
    with pytest.raises(AgentError, match="could not connect"):
        agent.propose(desk_context)
    assert len(agent.calls[0]["attempts"]) == 2


def test_auth_error_raises_at_once_without_the_key(fake_openai: Fake, desk_context: AgentContext) -> None:
    server = fake_openai(PROGRAM, api_key="sk-the-right-one")
    agent = _agent(server)
    with pytest.raises(AgentError) as info:
        agent.propose(desk_context)
    message = str(info.value)
    assert len(server.requests) == 1  # no retry
    assert "401" in message and "\n" not in message and "API key in OPENAI_API_KEY" in message
    assert server.headers[0]["authorization"] == f"Bearer {SECRET_KEY}"  # the server did see it ...
    assert SECRET_KEY not in message  # ... but we never repeat it
    assert SECRET_KEY not in json.dumps(agent.calls)
    assert SECRET_KEY not in repr(agent.__dict__.get("calls"))


def test_bad_request_raises_at_once(fake_openai: Fake, desk_context: AgentContext) -> None:
    server = fake_openai(Reply(status=400, error="temperature is not supported by this model"))
    with pytest.raises(AgentError, match="HTTP 400 .*temperature is not supported"):
        _agent(server).propose(desk_context)
    assert len(server.requests) == 1


def test_missing_key_is_sent_as_a_placeholder(
    fake_openai: Fake, desk_context: AgentContext, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv("OPENAI_API_KEY")
    server = fake_openai(PROGRAM)
    assert _agent(server).propose(desk_context) == PROGRAM
    assert server.headers[0]["authorization"] == "Bearer not-needed"


# -- VQA -----------------------------------------------------------------------------


def test_vqa_reads_yes_probability_from_logprobs(fake_openai: Fake) -> None:
    top = (("Yes", math.log(0.80)), ("No", math.log(0.15)), (" yes", math.log(0.03)), ("Maybe", math.log(0.01)))
    server = fake_openai(Reply(content="Yes", top_logprobs=top), Reply(content="Yes", top_logprobs=top))
    calls: list[dict[str, object]] = []
    score = vqa_score(PNG, "a desk with a mug.", "fake-vlm", server.base_url, calls=calls)
    assert score == pytest.approx(0.83)  # the paper's P("Yes"): what the model puts on yes, not against no alone
    normalised = vqa_score(PNG, "a desk with a mug.", "fake-vlm", server.base_url, normalised=True)
    assert normalised == pytest.approx(0.83 / 0.98)
    body = server.requests[0]
    assert body["logprobs"] is True and body["top_logprobs"] == 5 and body["max_tokens"] == 1
    text, image = body["messages"][0]["content"]
    assert text["text"] == "Does this image show a desk with a mug? Answer Yes or No."
    assert image["image_url"]["url"].startswith("data:image/png;base64,iVBORw0KGgo")
    assert calls[0]["score"] == score and calls[0]["scored"] == "p-yes" and "iVBOR" not in json.dumps(calls)


@pytest.mark.parametrize(("answer", "expected"), [("Yes.", 1.0), ("no", 0.0), ("I cannot tell", None)])
def test_vqa_falls_back_to_the_answer_text(fake_openai: Fake, answer: str, expected: float | None) -> None:
    server = fake_openai(answer)
    assert vqa_score(PNG, "a desk", "fake-vlm", server.base_url) == expected


def test_vqa_asks_again_without_logprobs_when_refused(fake_openai: Fake) -> None:
    server = fake_openai(Reply(status=400, error="logprobs are not supported"), "Yes")
    assert vqa_score(PNG, "a desk", "fake-vlm", server.base_url) == 1.0
    assert "logprobs" in server.requests[0] and "logprobs" not in server.requests[1]


def test_vqa_failure_returns_none(fake_openai: Fake, caplog: pytest.LogCaptureFixture) -> None:
    server = fake_openai(fail_first=10)
    assert vqa_score(PNG, "a desk", "fake-vlm", server.base_url, max_retries=1, backoff_s=0.01) is None
    assert len(server.requests) == 2
    assert "VQA score unavailable" in caplog.text and SECRET_KEY not in caplog.text


def test_yes_probability_rules() -> None:
    assert yes_probability([("YES", 0.0), ("no", -50.0)]) == pytest.approx(1.0)
    pairs = [("Yes", math.log(0.4)), ("Yes", math.log(0.1)), ("No", math.log(0.4)), ("Sure", math.log(0.2))]
    assert yes_probability(pairs) == pytest.approx(0.4)  # the first of a repeated token counts
    assert yes_probability(pairs, normalised=True) == pytest.approx(0.5)
    assert yes_probability([("No", math.log(0.9)), ("Maybe", math.log(0.1))]) == 0.0  # yes not among the likely
    assert yes_probability([("The", 0.0)]) is None
    assert question("a desk!") == "Does this image show a desk? Answer Yes or No."
