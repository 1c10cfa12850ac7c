"""Issue 21: streamed LLM replies (server-sent events) with progress, within the same deadline, cap and secrets.

The fake server (tests/agent/fake_server.py) answers `"stream": true` with SSE chunks of about a token each; with
`no_stream` it answers plain JSON as servers without streaming do.
"""

from __future__ import annotations

import json
import math
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

from physcensis.agent.llm import LLMAgent
from physcensis.cli import app
from physcensis.llm import client as llm
from physcensis.llm.client import LLMRequestError, ReplyError, completion_from_events

from .conftest import SECRET_KEY
from .fake_server import MUG_AND_BOOK, STREAM_CHUNK_CHARS, FakeOpenAI, Reply

pytestmark = pytest.mark.timeout(120)
Fake = Callable[..., FakeOpenAI]
CHAT = [{"role": "user", "content": "a mug and a book"}]
SLACK_S = 3.0  # what a deadline may overrun on a busy machine (see test_hardening_llm.py)
CHUNKS = math.ceil(len(MUG_AND_BOOK) / STREAM_CHUNK_CHARS)


def _agent(server: FakeOpenAI, **options: Any) -> LLMAgent:
    # no draft (test_hint.py tests it): these tests are about streams, and a draft would only slow them
    settings: dict[str, Any] = {"max_retries": 2, "backoff_s": 0.01, "timeout_s": 20.0, "hint": "off"}
    settings.update(options)
    return LLMAgent("fake-model", base_url=server.base_url, **settings)


def _request_threads() -> list[threading.Thread]:
    end = time.monotonic() + 3.0
    while time.monotonic() < end:
        alive = [t for t in threading.enumerate() if t.name == "physcensis-llm-request"]
        if not alive:
            return []
        time.sleep(0.05)
    return alive


# -- the same reply, streamed or not -----------------------------------------------------------------------------


def test_a_streamed_reply_is_the_same_as_a_plain_one(fake_openai: Fake) -> None:
    streaming, plain = fake_openai(MUG_AND_BOOK), fake_openai(MUG_AND_BOOK, no_stream=True)
    streamed_agent, plain_agent = _agent(streaming), _agent(plain)
    assert streamed_agent.complete(CHAT) == plain_agent.complete(CHAT) == MUG_AND_BOOK
    [body] = streaming.requests
    assert body["stream"] is True and body["stream_options"] == {"include_usage": True}
    [streamed], [answered] = streamed_agent.calls, plain_agent.calls
    assert streamed["usage"] == answered["usage"] and streamed["usage"]["completion_tokens"] == len(MUG_AND_BOOK) // 4
    assert streamed["finish_reason"] == answered["finish_reason"] == "stop"
    assert streamed["response_chars"] == len(MUG_AND_BOOK)
    assert "stream" not in streamed["request"]  # the record is the chat asked for, as before streaming
    assert streamed_agent.transcript_notes == plain_agent.transcript_notes == []


def test_stream_false_sends_a_plain_request(fake_openai: Fake) -> None:
    server = fake_openai(MUG_AND_BOOK)
    agent = _agent(server, stream=False)
    assert agent.complete(CHAT) == MUG_AND_BOOK
    assert "stream" not in server.requests[0] and "stream_options" not in server.requests[0]
    assert agent.calls[0]["usage"] is not None


def test_a_whole_program_round_streams(fake_openai: Fake, desk_context: Any) -> None:
    server = fake_openai(MUG_AND_BOOK)
    agent = _agent(server, structured="off")
    assert agent.propose(desk_context) == MUG_AND_BOOK
    assert server.requests[0]["stream"] is True


# -- progress ----------------------------------------------------------------------------------------------------


def test_on_tokens_hears_growing_counts_at_most_ten_times_a_second(fake_openai: Fake) -> None:
    server = fake_openai(Reply(content=MUG_AND_BOOK, chunk_s=0.01))
    agent = _agent(server)
    heard: list[int] = []
    agent.on_tokens = heard.append
    start = time.monotonic()
    assert agent.complete(CHAT) == MUG_AND_BOOK
    seconds = time.monotonic() - start
    assert heard[0] == 1 and heard[-1] == CHUNKS
    assert heard == sorted(set(heard))  # growing
    assert 3 <= len(heard) <= seconds / llm.TOKEN_REPORT_EVERY_S + 2  # throttled, the last count always said


def test_a_failing_progress_callback_does_not_fail_the_request(fake_openai: Fake) -> None:
    server = fake_openai(MUG_AND_BOOK)
    agent = _agent(server)
    calls: list[int] = []

    def broken(tokens: int) -> None:
        calls.append(tokens)
        raise RuntimeError("the display is gone")

    agent.on_tokens = broken
    assert agent.complete(CHAT) == MUG_AND_BOOK
    assert calls == [1] and len(server.requests) == 1  # called once, then left alone; not retried


def test_the_cli_progress_shows_the_tokens_received(
    fake_openai: Fake, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    server = fake_openai(Reply(content=MUG_AND_BOOK, chunk_s=0.005))
    shown: list[str] = []
    from rich.status import Status

    original = Status.update

    def update(self: Status, status: Any = None, **kwargs: Any) -> None:
        if status is not None:
            shown.append(str(status))
        original(self, status, **kwargs)

    monkeypatch.setattr(Status, "update", update)
    args = ["generate", "a mug and a book", "--llm", "fake-model", "--base-url", server.base_url]
    args += ["--support", "table:0.6x0.6", "--structured", "off", "--out", str(tmp_path / "s"), "--export", "none"]
    args += ["--hint", "off"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    receiving = [line for line in shown if "receiving reply" in line]
    assert receiving and receiving[-1] == f"round 1: receiving reply, {CHUNKS} tokens"


# -- broken, endless and oversize streams --------------------------------------------------------------------------


def test_a_stream_that_breaks_off_is_retried(fake_openai: Fake) -> None:
    server = fake_openai(Reply(content=MUG_AND_BOOK, break_after=5), MUG_AND_BOOK)
    agent = _agent(server)
    assert agent.complete(CHAT) == MUG_AND_BOOK
    [first] = agent.calls[0]["attempts"]
    assert first["retry"] and "stream broke off before its end (5 content chunks received)" in first["error"]


def test_a_stream_that_always_breaks_off_is_one_clear_error(fake_openai: Fake) -> None:
    server = fake_openai(Reply(content=MUG_AND_BOOK, break_after=3), repeat_last=True)
    agent = _agent(server, max_retries=2)
    with pytest.raises(LLMRequestError) as info:
        agent.complete(CHAT)
    message = str(info.value)
    assert "\n" not in message and len(server.requests) == 3
    assert message.endswith(
        "gave up after 3 attempts; last error: the server's stream broke off before its end (3 content chunks received)"
    )


def test_a_stream_that_never_ends_is_cut_at_the_deadline(fake_openai: Fake) -> None:
    server = fake_openai(Reply(content="[", endless=True, chunk_s=0.05), repeat_last=True)
    agent = _agent(server, timeout_s=1.5)
    heard: list[int] = []
    agent.on_tokens = heard.append
    start = time.monotonic()
    with pytest.raises(LLMRequestError) as info:
        agent.complete(CHAT)
    assert 1.4 <= time.monotonic() - start < 1.5 + SLACK_S
    assert "no complete answer within 1.5 s (1 attempt, waited 0.0 s between them)" in str(info.value)
    assert heard and heard[-1] > 5  # it was streaming all along
    assert _request_threads() == []  # the abandoned attempt's socket was shut: its thread ended


def test_an_oversize_stream_is_capped(fake_openai: Fake, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(llm, "MAX_RESPONSE_BYTES", 2 * 1024 * 1024)
    server = fake_openai(Reply(content="x" * 4096, endless=True))
    agent = _agent(server, max_retries=0)
    start = time.monotonic()
    with pytest.raises(LLMRequestError, match="reply is larger than 2 MB; stopped reading"):
        agent.complete(CHAT)
    assert time.monotonic() - start < 10.0


def test_an_error_event_is_retried_and_never_shows_the_key(fake_openai: Fake) -> None:
    event = f'data: {{"error": {{"message": "overloaded, key {SECRET_KEY}"}}}}\n\n'.encode()
    garbage = f"data: <html>{SECRET_KEY}</html>\n\n".encode()
    sse = "text/event-stream"
    server = fake_openai(Reply(raw=event, content_type=sse), Reply(raw=garbage, content_type=sse))
    agent = _agent(server, max_retries=1)
    with pytest.raises(LLMRequestError) as info:
        agent.complete(CHAT)
    errors = [attempt["error"] for attempt in agent.calls[0]["attempts"]]
    assert "the server's stream reported an error: overloaded, key" in errors[0]
    assert "an event is not JSON; it starts with '<html>" in errors[1]
    assert SECRET_KEY not in str(info.value) and SECRET_KEY not in json.dumps(agent.calls)


# -- servers that do not stream ----------------------------------------------------------------------------------


def test_a_plain_json_answer_to_a_streamed_request_is_taken(fake_openai: Fake) -> None:
    server = fake_openai(MUG_AND_BOOK, no_stream=True)
    agent = _agent(server)
    assert agent.complete(CHAT) == MUG_AND_BOOK
    assert server.requests[0]["stream"] is True and agent.transcript_notes == []


def test_a_server_refusing_stream_options_is_asked_without_them_for_the_rest_of_the_run(fake_openai: Fake) -> None:
    server = fake_openai(MUG_AND_BOOK, MUG_AND_BOOK, refuse_stream_options=True)
    agent = _agent(server)
    assert agent.complete(CHAT) == agent.complete(CHAT) == MUG_AND_BOOK
    assert [("stream_options" in b, b.get("stream")) for b in server.requests] == [
        (True, True),
        (False, True),
        (False, True),
    ]
    [note] = agent.transcript_notes
    assert note.startswith("stream_options refused by the server, sending requests without stream_options: ")
    assert [call["usage"] for call in agent.calls] == [None, None]  # the server was not asked for it


def test_a_server_refusing_stream_is_asked_plainly_for_the_rest_of_the_run(fake_openai: Fake) -> None:
    server = fake_openai(MUG_AND_BOOK, MUG_AND_BOOK, refuse_stream=True)
    agent = _agent(server)
    assert agent.complete(CHAT) == agent.complete(CHAT) == MUG_AND_BOOK
    assert [sorted({"stream", "stream_options"} & set(b)) for b in server.requests] == [
        ["stream", "stream_options"],
        [],
        [],
    ]
    [note] = agent.transcript_notes
    assert note.startswith("stream refused by the server, sending requests without stream and stream_options: ")
    assert agent.calls[0]["usage"] is not None


def test_other_client_errors_are_not_taken_for_a_refusal(fake_openai: Fake) -> None:
    server = fake_openai(Reply(status=400, error="model 'fake-model' is not loaded"))
    agent = LLMAgent("upstream-model", base_url=server.base_url, max_retries=0)  # "stream" only in the label
    with pytest.raises(LLMRequestError, match="HTTP 400"):
        agent.complete(CHAT)
    assert len(server.requests) == 1 and agent.transcript_notes == []


# -- reading events ----------------------------------------------------------------------------------------------


def _event(delta: dict[str, Any], finish: str | None = None) -> bytes:
    return b"data: " + json.dumps({"choices": [{"index": 0, "delta": delta, "finish_reason": finish}]}).encode()


def test_keep_alives_carriage_returns_and_a_missing_done_are_read() -> None:
    lines = [b": keep-alive", b"", _event({"content": "he"}) + b"\r", b"event: message", _event({"content": "llo"})]
    lines.append(_event({}, "length"))
    completion = completion_from_events(lines)
    assert completion["choices"][0]["message"]["content"] == "hello"
    assert completion["choices"][0]["finish_reason"] == "length" and completion["usage"] is None


def test_a_stream_without_an_end_is_a_reply_error() -> None:
    with pytest.raises(ReplyError, match=r"broke off before its end \(1 content chunk received\)"):
        completion_from_events([_event({"content": "he"})])


def test_lines_are_split_however_the_bytes_arrive() -> None:
    body = b"".join(line + b"\n" for line in [_event({"content": "a"}), _event({"content": "b"}, "stop")])
    pieces = [body[i : i + 3] for i in range(0, len(body), 3)]
    lines = llm._lines_capped(pieces, 1024)
    assert completion_from_events(lines)["choices"][0]["message"]["content"] == "ab"
    with pytest.raises(ReplyError, match="larger than"):
        list(llm._lines_capped(pieces, 10))


def test_generate_no_stream_asks_for_plain_replies(fake_openai: Any, tmp_path: Path) -> None:
    server = fake_openai(MUG_AND_BOOK)
    args = ["generate", "a mug and a book", "--llm", "fake-model", "--base-url", server.base_url]
    args += ["--hint", "off", "--no-stream", "--support", "table:0.6x0.6", "--out", str(tmp_path / "s")]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    assert server.requests and not any(body.get("stream") for body in server.requests)
    assert all(isinstance(row.get("usage"), dict) for row in _rows(tmp_path / "s") if "program" in row)


def _rows(folder: Path) -> list[dict[str, Any]]:
    return [json.loads(line) for line in (folder / "transcript.jsonl").read_text().splitlines()]
