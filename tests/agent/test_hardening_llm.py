"""Issue 14, the LLM path: wall-clock deadlines, malformed replies, bounded history, no secret written or printed.

Every test talks to the real `openai` client through a real loopback server (tests/agent/fake_server.py), or runs
the `physcensis` command: in this process through Typer's CliRunner, or the real executable where what a process
prints or how it ends is the point.
"""

from __future__ import annotations

import base64
import json
import os
import subprocess
import sys
import threading
import time
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner, Result

from physcensis.agent.base import AgentContext, AgentError, Round
from physcensis.agent.llm import LLMAgent
from physcensis.agent.loop import MAX_REPLY_CHARS, generate_scene
from physcensis.agent.prompt import (
    HISTORY_FEEDBACK_CHARS,
    HISTORY_REPLY_CHARS,
    HISTORY_ROUNDS_CHARS,
    clip_text,
    first_user_message,
    messages,
    system_prompt,
)
from physcensis.agent.vqa import vqa_score
from physcensis.api import generate, write_generated
from physcensis.cli import app
from physcensis.llm.client import LLMRequestError, ReplyError, completion_from_body, reply_text
from physcensis.redaction import Redactor
from physcensis.scene import Support
from physcensis.settings import SettingsError

from .conftest import SECRET_KEY
from .fake_server import MUG_AND_BOOK, FakeOpenAI, Reply

pytestmark = pytest.mark.timeout(120)
Fake = Callable[..., FakeOpenAI]
PROGRAM = '[["mug_0", "a white mug"], ["mug_0", "PLACE-ANYWHERE", "root", {}]]'
PNG = b"\x89PNG\r\n\x1a\n" + b"\x00" * 32
SMALL_TABLE = Support(kind="table", size=(0.6, 0.6))
PASSWORD = "pa55word"
BASIC_TOKEN = base64.b64encode(f"user:{PASSWORD}".encode()).decode()
# What a deadline may overrun on a busy machine (xdist, CI): thread wake-ups and the local server's replies come late.
# A deadline that is not kept overruns by far more: the dripping replies take tens of seconds.
SLACK_S = 3.0


def _agent(server: FakeOpenAI, **options: object) -> LLMAgent:
    # no draft: these tests time requests, and a draft's time counts against the reply's limit
    settings_: dict[str, object] = {"max_retries": 3, "backoff_s": 0.01, "hint": "off"}
    settings_.update(options)
    return LLMAgent("fake-model", base_url=server.base_url, **settings_)  # type: ignore[arg-type]


def _request_threads() -> list[threading.Thread]:
    return [t for t in threading.enumerate() if t.name == "physcensis-llm-request"]


def _wait_for_no_request_threads(limit_s: float = 3.0) -> list[threading.Thread]:
    end = time.monotonic() + limit_s
    while _request_threads() and time.monotonic() < end:
        time.sleep(0.05)
    return _request_threads()


# -- 1. wall-clock deadline --------------------------------------------------------------------------------------


@pytest.mark.parametrize("drip_headers", [False, True], ids=["body", "headers"])
def test_a_dripping_server_cannot_outlast_the_deadline(
    fake_openai: Fake, desk_context: AgentContext, drip_headers: bool
) -> None:
    # One byte every 0.2 s: each read succeeds, so a per-read timeout never fires.
    server = fake_openai(Reply(content=PROGRAM, drip_s=0.2, drip_headers=drip_headers), repeat_last=True)
    agent = _agent(server, timeout_s=1.5)
    start = time.monotonic()
    with pytest.raises(LLMRequestError) as info:
        agent.propose(desk_context)
    elapsed = time.monotonic() - start
    assert 1.4 <= elapsed < 1.5 + SLACK_S  # the whole reply would take a minute
    message = str(info.value)
    assert "no complete answer within 1.5 s (1 attempt, waited 0.0 s between them)" in message
    assert "\n" not in message and agent.calls[0]["error"] == message
    assert _wait_for_no_request_threads() == []  # the abandoned attempt's socket was shut: its thread ended


def test_the_deadline_covers_retries_and_their_waits(fake_openai: Fake, desk_context: AgentContext) -> None:
    server = fake_openai(PROGRAM, fail_first=100)
    agent = _agent(server, timeout_s=2.0, max_retries=20, backoff_s=0.3, max_backoff_s=0.6)
    start = time.monotonic()
    with pytest.raises(LLMRequestError) as info:
        agent.propose(desk_context)
    assert time.monotonic() - start < 2.0 + SLACK_S  # without the deadline: 20 attempts, waits of 0.3-0.6 s
    message = str(info.value)
    attempts = len(server.requests)
    assert 2 <= attempts < 20
    assert f"no complete answer within 2 s ({attempts} attempts, waited " in message
    waited = float(message.split("waited ")[1].split(" s")[0])
    assert 0.8 <= waited <= 2.0
    assert message.endswith("last error: HTTP 500 InternalServerError: injected failure " + str(attempts))


def test_a_slow_attempt_is_retried_within_the_same_budget(fake_openai: Fake, desk_context: AgentContext) -> None:
    server = fake_openai(Reply(content=PROGRAM, drip_s=0.3), PROGRAM)
    agent = _agent(server, timeout_s=10.0, attempt_timeout_s=0.8)
    start = time.monotonic()
    assert agent.propose(desk_context) == PROGRAM
    assert time.monotonic() - start < 0.8 + SLACK_S  # the slow reply, byte by byte, takes over a minute
    assert "no complete answer within 0.8 s" in agent.calls[0]["attempts"][0]["error"]


@pytest.mark.parametrize("bad", [0, -1.0, float("nan"), float("inf")])
def test_timeouts_must_be_positive_and_finite(fake_openai: Fake, bad: float) -> None:
    with pytest.raises(AgentError, match="positive number of seconds"):
        _agent(fake_openai(), timeout_s=bad)
    with pytest.raises(SettingsError, match="llm_timeout_s must be a positive number of seconds"):
        generate("a mug", llm="fake-model", base_url=fake_openai().base_url, llm_timeout_s=bad)


def test_vqa_has_the_same_deadline(fake_openai: Fake) -> None:
    server = fake_openai(Reply(content="Yes", drip_s=0.2), repeat_last=True)
    start = time.monotonic()
    assert vqa_score(PNG, "a desk", "fake-vlm", server.base_url, timeout_s=1.0) is None
    assert time.monotonic() - start < 1.0 + SLACK_S  # the dripped reply would take a minute


def test_served_models_has_a_wall_clock_limit(fake_openai: Fake) -> None:
    assert _agent(fake_openai()).served_models(timeout_s=2.0) == ["fake-model"]
    agent = _agent(fake_openai(models_reply=Reply(drip_s=0.2)))
    start = time.monotonic()
    with pytest.raises(LLMRequestError, match="no complete answer within 1 s"):
        agent.served_models(timeout_s=1.0)
    assert time.monotonic() - start < 1.0 + SLACK_S  # the dripped list would take 20 s


def _run_cli(
    *args: str, env_extra: dict[str, str] | None = None, timeout: float = 120
) -> tuple[subprocess.CompletedProcess[str], float]:
    env = {
        **os.environ,
        "MUJOCO_GL": "egl",
        "OPENAI_API_KEY": SECRET_KEY,
        "NO_PROXY": "127.0.0.1,localhost",
        **(env_extra or {}),
    }
    for name in ("HTTP_PROXY", "HTTPS_PROXY", "ALL_PROXY", "http_proxy", "https_proxy", "all_proxy", "OPENAI_BASE_URL"):
        env.pop(name, None)
    start = time.monotonic()
    exe = Path(sys.executable).with_name("physcensis")
    done = subprocess.run([str(exe), *args], capture_output=True, text=True, timeout=timeout, env=env, check=False)
    return done, time.monotonic() - start


def _invoke_cli(*args: str) -> Result:
    """The command in this process (the agent tests' environment: the test key, loopback only)."""
    result = CliRunner().invoke(app, list(args))
    assert result.exception is None or isinstance(result.exception, SystemExit), result.exception
    return result


@pytest.mark.slow
@pytest.mark.long
def test_cli_generate_with_llm_timeout_ends_with_a_clear_error(fake_openai: Fake, tmp_path: Path) -> None:
    # Without a wall-clock deadline this reply would take 250 s per attempt, and each attempt is retried.
    server = fake_openai(Reply(content=MUG_AND_BOOK, drip_s=0.5), repeat_last=True)
    done, seconds = _run_cli(
        "generate",
        "a mug and a book",
        "--llm",
        "fake-model",
        "--base-url",
        server.base_url,
        "--llm-timeout",
        "1",
        "--hint",
        "off",
        "--out",
        str(tmp_path / "scene"),
        "--export",
        "none",
    )
    assert done.returncode == 1, done.stderr
    assert "no complete answer within 1 s (1 attempt, waited 0.0 s between them)" in done.stderr
    assert "Traceback" not in done.stderr + done.stdout
    assert seconds < 30.0  # start-up included; nothing waits for the dripping socket
    record = json.loads((tmp_path / "scene" / "report.json").read_text())  # the failed run's record, no scene
    assert record["ok"] is False and record["generate"]["stop_reason"] == "agent-error"
    assert not (tmp_path / "scene" / "scene.json").exists()


def test_cli_rejects_a_bad_llm_timeout() -> None:
    for bad in ("0", "-3", "nan"):
        result = CliRunner().invoke(app, ["generate", "a mug", "--llm-timeout", bad])
        assert result.exit_code == 2 and "--llm-timeout" in result.output, result.output


# -- 2. malformed HTTP-200 bodies ------------------------------------------------------------------------------

MALFORMED = {
    "truncated JSON": (b'{"id": "x", "object": "chat.completion", "choices": [{"message": {"cont', "application/json"),
    "HTML": (b"<html><body><h1>502 Bad Gateway</h1></body></html>", "text/html"),
    "empty body": (b"", "application/json"),
    "no choices": (b'{"id": "x", "object": "chat.completion", "model": "m"}', "application/json"),
    "empty choices": (b'{"choices": []}', "application/json"),
    "message not an object": (b'{"choices": [{"message": "hi"}]}', "application/json"),
    "a list": (b"[1, 2, 3]", "application/json"),
    "an error object": (b'{"error": {"message": "model overloaded"}}', "application/json"),
    "deep nesting": (b"[" * 100_000, "application/json"),
    "huge integer": (b'{"choices": ' + b"7" * 5000 + b"}", "application/json"),
    "not UTF-8": (b"\xff\xfe\x00\x81garbage", "application/octet-stream"),
}


@pytest.mark.parametrize("name", list(MALFORMED))
def test_a_malformed_200_is_retried_then_succeeds(fake_openai: Fake, desk_context: AgentContext, name: str) -> None:
    raw, content_type = MALFORMED[name]
    server = fake_openai(Reply(raw=raw, content_type=content_type), PROGRAM)
    agent = _agent(server)
    assert agent.propose(desk_context) == PROGRAM
    assert len(server.requests) == 2
    [failure] = agent.calls[0]["attempts"]
    assert failure["retry"] is True and "the server's reply was not a chat completion" in failure["error"]


@pytest.mark.parametrize("name", ["truncated JSON", "HTML", "no choices"])
def test_malformed_200s_end_in_one_clear_error(fake_openai: Fake, desk_context: AgentContext, name: str) -> None:
    raw, content_type = MALFORMED[name]
    server = fake_openai(Reply(raw=raw, content_type=content_type), repeat_last=True)
    with pytest.raises(LLMRequestError) as info:
        _agent(server, max_retries=2).propose(desk_context)
    message = str(info.value)
    assert "gave up after 3 attempts; last error: the server's reply was not a chat completion" in message
    assert "\n" not in message and len(server.requests) == 3


def test_a_malformed_vqa_reply_gives_no_score_not_a_crash(fake_openai: Fake) -> None:
    server = fake_openai(Reply(raw=b"<html>oops</html>", content_type="text/html"), repeat_last=True)
    assert vqa_score(PNG, "a desk", "fake-vlm", server.base_url, max_retries=1, backoff_s=0.01) is None


@settings(max_examples=300, deadline=None)
@given(
    st.one_of(
        st.binary(max_size=200),
        st.recursive(
            st.none() | st.booleans() | st.integers() | st.floats() | st.text(max_size=8),
            lambda inner: (
                st.lists(inner, max_size=3)
                | st.dictionaries(
                    st.sampled_from(["choices", "message", "content", "error", "finish_reason", "x"]), inner, max_size=3
                )
            ),
            max_leaves=12,
        ).map(lambda v: json.dumps(v).encode()),
    )
)
def test_any_body_is_a_chat_completion_or_a_reply_error(body: bytes) -> None:
    try:
        data = completion_from_body(body)
    except ReplyError as exc:
        assert str(exc).startswith("the server's reply was not a chat completion")
        return
    text, finish = reply_text(data)
    assert isinstance(text, str) and (finish is None or isinstance(finish, str))


# -- 3. bounded history ------------------------------------------------------------------------------------------


@pytest.mark.physics
def test_a_huge_reply_is_refused_as_feedback_and_the_next_request_stays_small(fake_openai: Fake) -> None:
    huge = "Here is my thinking. " * 250_000  # 5.25 MB
    server = fake_openai(huge, MUG_AND_BOOK)
    agent = LLMAgent("fake-model", base_url=server.base_url, backoff_s=0.01, hint="off")
    result = generate_scene("a mug and a book", agent, support=SMALL_TABLE, retries=2)
    assert result.ok
    first, second = result.transcript[:2]
    assert first["feedback_kind"] == "grammar" and first["reply_chars"] == len(huge)
    assert f"Your reply was {len(huge)} characters, over the limit of {MAX_REPLY_CHARS}" in first["feedback"]
    assert len(first["program"]) <= HISTORY_REPLY_CHARS and "cut here" in first["program"]
    assert second["feedback_kind"] == "success"
    assert server.request_sizes[0] < 60_000  # the first request: system prompt and scene request
    assert server.request_sizes[1] < server.request_sizes[0] + 2 * HISTORY_REPLY_CHARS + 4_000
    assert "over the limit" in server.messages[1][-1]["content"]
    assert len(agent.calls[0]["response"]) <= MAX_REPLY_CHARS and agent.calls[0]["response_chars"] == len(huge)


def test_a_long_reply_is_read_but_kept_short_in_the_history(desk_context: AgentContext) -> None:
    reply = "x" * (HISTORY_REPLY_CHARS * 3)
    chat = messages(replace(desk_context, request="repair", history=(Round(reply, "f" * 50_000),)))
    assistant, feedback = chat[2]["content"], chat[3]["content"]
    assert len(assistant) <= HISTORY_REPLY_CHARS and f"was {len(reply)} characters long" in assistant
    assert len(feedback) <= HISTORY_FEEDBACK_CHARS + 1000 and "the feedback was 50000 characters long" in feedback


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 300_000), st.integers(0, 100_000), st.booleans()), min_size=1, max_size=12))
def test_the_history_sent_stays_within_its_budget(sizes: list[tuple[int, int, bool]]) -> None:
    context = AgentContext(
        "a desk",
        SMALL_TABLE,
        ("mug",),
        request="repair",
        history=tuple(Round("p" * a, "f" * b, ok) for a, b, ok in sizes),
    )
    chat = messages(context)
    fixed = len(system_prompt()) + len(first_user_message(context)) + 200
    rounds_chars = sum(len(m["content"]) for m in chat[2:])
    last_round = HISTORY_REPLY_CHARS + HISTORY_FEEDBACK_CHARS + 1_000
    assert rounds_chars <= max(HISTORY_ROUNDS_CHARS, last_round)
    assert sum(len(m["content"]) for m in chat) <= fixed + max(HISTORY_ROUNDS_CHARS, last_round)
    assert [m["role"] for m in chat[2:]] == ["assistant", "user"] * ((len(chat) - 2) // 2)
    assert chat[-1]["content"].startswith("Feedback on your program:\n" + "f" * min(sizes[-1][1], 100))
    left_out = len(sizes) - (len(chat) - 2) // 2
    assert (f"The first {left_out} of {len(sizes)} earlier attempts are left out" in chat[1]["content"]) == (
        left_out > 0
    )


def test_clip_text_is_idempotent_and_bounded() -> None:
    for n in (0, 10, 999, 1000, 1001, 50_000):
        once = clip_text("y" * n, 1000)
        assert len(once) <= 1000 and clip_text(once, 1000) == once
        assert (once == "y" * n) == (n <= 1000)


# -- 4. secrets ------------------------------------------------------------------------------------------------


def _all_output(folder: Path, *texts: str) -> str:
    files = [p.read_bytes().decode("utf-8", errors="replace") for p in folder.rglob("*") if p.is_file()]
    return "\n".join([*files, *texts])


def _assert_no_secret(text: str) -> None:
    for secret in (SECRET_KEY, PASSWORD, BASIC_TOKEN):
        assert secret not in text


@pytest.mark.slow
@pytest.mark.physics
@pytest.mark.long
def test_cli_writes_and_prints_no_key_and_no_url_credentials(fake_openai: Fake, tmp_path: Path) -> None:
    # The server quotes the Authorization header and the URL (credentials decoded) in a reply and an error body.
    server = fake_openai(Reply(content="Here is the program:", echo=True), Reply(status=500, echo=True), MUG_AND_BOOK)
    base_url = f"http://user:{PASSWORD}@127.0.0.1:{server.port}/v1"
    out = tmp_path / "scene"
    done, _ = _run_cli(
        "generate",
        "a mug and a book",
        "--llm",
        "fake-model",
        "--base-url",
        base_url,
        "--support",
        "table:0.6x0.6",
        "--out",
        str(out),
        "--export",
        "none",
        "--llm-timeout",
        "60",
        "--hint",
        "off",
    )
    assert done.returncode == 0, done.stderr
    assert server.headers[0]["authorization"] == f"Basic {BASIC_TOKEN}"  # the credentials did go to the server
    assert len(server.requests) == 3
    transcript = (out / "transcript.jsonl").read_text()
    assert "[redacted]" in transcript and "you sent Authorization" in transcript
    assert "retry 1 of 4" in done.stderr and "[redacted]" in done.stderr  # the error body, logged, redacted
    _assert_no_secret(_all_output(out, done.stdout, done.stderr))


def test_cli_errors_print_no_url_credentials(
    fake_openai: Fake, tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    """In process: what the command prints (CliRunner's stderr) and logs (caplog) on a refused request and on a base
    URL it cannot read. test_cli_writes_and_prints_no_key_and_no_url_credentials runs the real executable."""
    server = fake_openai(Reply(status=400, echo=True, error="bad [/x] request [bold]"))
    base_url = f"http://user:{PASSWORD}@127.0.0.1:{server.port}/v1"
    out = ["--out", str(tmp_path / "scene"), "--export", "none"]
    done = _invoke_cli("generate", "a mug", "--llm", "fake-model", "--base-url", base_url, "--hint", "off", *out)
    assert done.exit_code == 1 and "HTTP 400" in done.stderr and "Traceback" not in done.output
    assert "bad [/x] request [bold]" in done.stderr  # the server's text is printed as is, not as markup
    assert "Basic [redacted] to http://[redacted]@127.0.0.1" in done.stderr
    _assert_no_secret(done.output + caplog.text)
    broken = _invoke_cli(
        "generate",
        "a mug",
        "--llm",
        "fake-model",
        "--base-url",
        f"http://user:{PASSWORD}@[::1",
        "--out",
        str(tmp_path / "scene2"),
    )
    assert broken.exit_code == 2 and "base URL" in broken.stderr and "Traceback" not in broken.output
    _assert_no_secret(broken.output + caplog.text)


@pytest.mark.physics
def test_api_records_hold_no_key(fake_openai: Fake, tmp_path: Path, caplog: pytest.LogCaptureFixture) -> None:
    server = fake_openai(Reply(content="I got", echo=True), Reply(status=503, echo=True), MUG_AND_BOOK)
    agent = LLMAgent("fake-model", base_url=server.base_url, backoff_s=0.01, hint="off")
    generated = generate("a mug and a book", agent=agent, support=SMALL_TABLE, base_url=server.base_url)
    assert server.headers[0]["authorization"] == f"Bearer {SECRET_KEY}"
    assert generated.solution is not None
    out = write_generated(generated, tmp_path / "scene", exports=())
    records = json.dumps([agent.calls, generated.transcript, generated.report()])
    assert "you sent Authorization" in records
    _assert_no_secret(_all_output(out, records, caplog.text))


def test_agent_reply_and_records_lose_the_base_url_credentials(
    fake_openai: Fake, desk_context: AgentContext, caplog: pytest.LogCaptureFixture
) -> None:
    server = fake_openai(Reply(status=500, echo=True), Reply(content="[]", echo=True))
    base_url = f"http://user:{PASSWORD}@127.0.0.1:{server.port}/v1"
    agent = LLMAgent("fake-model", base_url=base_url, backoff_s=0.01, hint="off")
    text = agent.propose(desk_context)
    assert text.startswith("[] you sent Authorization: Basic [redacted]")  # the parser never sees a secret
    assert agent.base_url == f"http://127.0.0.1:{server.port}/v1/"
    _assert_no_secret(json.dumps(agent.calls) + caplog.text + text)
    assert all(call["base_url"] == agent.base_url for call in agent.calls)


def test_redactor_of_the_agent_knows_the_basic_token(fake_openai: Fake) -> None:
    server = fake_openai()
    agent = LLMAgent("fake-model", base_url=f"http://user:{PASSWORD}@127.0.0.1:{server.port}/v1")
    assert isinstance(agent.redactor, Redactor)
    assert PASSWORD not in agent.redactor.text(f"token {BASIC_TOKEN} and {PASSWORD}")
    assert BASIC_TOKEN not in agent.redactor.text(f"token {BASIC_TOKEN}")


@pytest.mark.parametrize(
    "text",
    [
        "x" * 2_000_000,
        "ab." * 700_000,
        "http://" * 200_000,
        "Bearer " * 200_000,
        "authorization: " * 100_000,
        "a@" * 1_000_000,
    ],
)
def test_redaction_is_linear_in_the_length_of_the_text(text: str) -> None:
    from physcensis.redaction import Redactor

    redactor = Redactor.for_server("sk-TESTKEY123", "http://u:SECRETPW@127.0.0.1:9/v1")
    start = time.process_time()  # CPU time: other processes on a busy machine do not count
    redactor.text(text)
    assert time.process_time() - start < 5.0  # quadratic patterns took hours on such text


def test_a_large_reply_is_returned_promptly(fake_openai: Fake) -> None:
    reply = '["a","a mug"]\n' + "x" * 300_000
    agent = _agent(fake_openai(Reply(content=reply)), timeout_s=20.0)
    start = time.perf_counter()
    text = agent.complete([{"role": "user", "content": "hi"}])
    assert len(text) >= 300_000 and time.perf_counter() - start < 10
