"""The one client for OpenAI-compatible chat servers (OpenAI, vLLM, Ollama, llama.cpp server, LM Studio): the LLM
agent, the vision critic, VQA and the robot's verifier all talk to their models through it.

It sends the plain chat-completions request every such server understands. Transient failures (no connection,
timeouts, rate limits, 5xx, an HTTP-200 body that is not a chat completion) are retried with exponential backoff;
anything else (bad key, bad request, unknown model) raises `LLMRequestError` at once.

Every request has a wall-clock deadline covering all its attempts and the waits between them. An attempt runs on a
daemon thread, so the caller leaves at the deadline whatever the server does (a server that drips one byte a second
resets every read timeout); the attempt's sockets are then shut down, which ends the thread too. Replies are read
up to `MAX_RESPONSE_BYTES`.

Replies are streamed (server-sent events) by default and assembled into the shape of a plain completion, so
`on_tokens` can show them arriving; a stream that breaks off is retried like a 5xx, a server answering plain JSON is
read as such, and one refusing `stream` or `stream_options` is asked without it.

The API key (read from the environment variable the settings name) and the credentials of the base URL never appear
in errors, logs or returned text (see `physcensis.redaction`).
"""

from __future__ import annotations

import functools
import json
import logging
import math
import os
import re
import socket
import threading
import time
import zlib
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from typing import Any
from urllib.parse import unquote, urlsplit

import openai

from physcensis.errors import AgentError
from physcensis.llm.provider import AttemptFailure, ChatProvider
from physcensis.redaction import REDACTED, Redactor, basic_credentials, strip_userinfo, url_secrets
from physcensis.settings import API_KEY_ENV, DEFAULT_LLM_TIMEOUT_S

log = logging.getLogger(__name__)

NO_KEY = "not-needed"  # local servers ignore the key, but the client wants one
MAX_ERROR_CHARS = 300
DEFAULT_TIMEOUT_S = DEFAULT_LLM_TIMEOUT_S
MAX_RESPONSE_BYTES = 64 * 1024 * 1024  # a chat completion is far smaller; more is a broken or hostile server
MAX_RECORDED_CHARS = 256_000  # of one reply, in `calls`
ATTEMPT_GRACE_S = 0.25  # lets the client's own per-attempt timeout speak before the wall clock does
TOKEN_REPORT_EVERY_S = 0.1  # streamed replies report their progress at most this often
CLOSE_HEADERS = {"Connection": "close"}  # every attempt on its own connection, so abandoning it cannot hit another

_RETRYABLE = (openai.APIConnectionError, openai.RateLimitError, openai.InternalServerError)  # timeouts included
_RETRYABLE_STATUS = {408}
# What a server says when it refuses `response_format` (OpenAI and vLLM answer 400/422, llama-cpp-python's server a
# 500 with its validation error): an error status whose message names structured output. One about anything else
# (temperature, the model) is not a refusal of it.
_REFUSAL_WORDS = ("response_format", "json_schema", "json schema", "structured output", "guided", "grammar")


class LLMRequestError(AgentError):
    """A chat request that failed for good; `status` is the HTTP status when the server answered."""

    def __init__(self, message: str, status: int | None = None) -> None:
        super().__init__(message)
        self.status = status


class ReplyError(Exception):
    """An HTTP-200 reply that is not a chat completion (or broke off, or is too large): retried like a 5xx."""


class OutOfTime(Exception):
    """The attempt did not finish within its wall-clock time."""


@dataclass(frozen=True)
class RetryPolicy:
    """How often and how patiently to retry transient failures."""

    max_retries: int = 4
    backoff_s: float = 1.0  # first wait; doubles each retry
    max_backoff_s: float = 30.0
    jitter: float = 0.25  # up to this fraction is added to each wait

    def delay_s(self, retry: int, key: str = "") -> float:
        """Wait before retry number `retry` (0-based): exponential, capped, plus a deterministic jitter."""
        base = min(self.max_backoff_s, self.backoff_s * 2.0**retry)
        fraction = (zlib.crc32(f"{key}:{retry}".encode()) % 1000) / 1000.0
        return min(self.max_backoff_s, base * (1.0 + self.jitter * fraction))


def positive_seconds(value: float, what: str) -> float:
    """`value` if it is a usable timeout, else an `AgentError` naming `what`."""
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value) or value <= 0:
        raise AgentError(f"{what} must be a positive number of seconds, not {value!r}")
    return float(value)


def _one_line(text: str) -> str:
    line = " ".join(text.split())
    return line if len(line) <= MAX_ERROR_CHARS else line[: MAX_ERROR_CHARS - 3] + "..."


# -- the server and its secrets ---------------------------------------------------------------------------------


def _password(url: str | None) -> list[str]:
    try:
        password = urlsplit(url or "").password
    except ValueError:
        return []
    return [password, unquote(password)] if password else []


class ChatServer:
    """One OpenAI-compatible server: a client that never retries by itself, and the secrets it must not leak.

    `redactor` cleans everything recorded or printed; `scrub` removes only the literal secrets from a model's
    reply, which goes on to the parser (pattern rules could change an object's description).
    """

    def __init__(self, base_url: str | None, api_key_env: str = API_KEY_ENV) -> None:
        key = os.environ.get(api_key_env) or NO_KEY
        self.api_key_env = api_key_env
        secret_key = None if key == NO_KEY else key
        given = url_secrets(base_url)
        http_client = openai.DefaultHttpxClient(event_hooks={"request": [_trace_current_attempt]})
        try:
            self.client = openai.OpenAI(base_url=base_url, api_key=key, max_retries=0, http_client=http_client)
        except Exception as exc:  # the URL parser's own errors (httpx): one clear line, never the credentials
            http_client.close()
            redactor = Redactor([secret_key, *given])
            raise LLMRequestError(
                redactor.text(f"base URL {strip_userinfo(base_url)!r} is not usable: {_one_line(str(exc))}")
            ) from None
        raw = str(self.client.base_url)  # OPENAI_BASE_URL applies when base_url is None
        self.url = strip_userinfo(raw) or raw
        self.redactor = Redactor([secret_key, *given, *url_secrets(raw)])
        literal = [
            secret_key,
            *_password(base_url),
            *_password(raw),
            *basic_credentials(base_url),
            *basic_credentials(raw),
        ]
        self._literal = sorted({s for s in literal if s and len(s) >= 4}, key=len, reverse=True)

    @property
    def api_key(self) -> str | None:
        key = self.client.api_key
        return None if key == NO_KEY else key

    def scrub(self, text: str) -> str:
        for secret in self._literal:
            text = text.replace(secret, REDACTED)
        return text

    def attempt(
        self, request: dict[str, Any], seconds: float, on_chunks: Callable[[int], None] | None = None
    ) -> dict[str, Any]:
        return _post_chat(self, request, seconds, on_chunks)

    def failure(self, exc: Exception) -> AttemptFailure | None:
        if not isinstance(exc, openai.OpenAIError):
            return None
        return AttemptFailure(
            text=describe_error(exc, self.redactor),
            status=status_of(exc),
            retryable=_retryable(exc),
            retry_after_s=_retry_after_s(exc),
            timed_out=isinstance(exc, openai.APITimeoutError),
            hint=key_hint(exc, self.api_key_env),
        )

    def served_models(self, timeout_s: float) -> list[str]:
        label = f"LLM server at {self.url}"
        try:
            page = call_within(
                lambda: self.client.models.list(timeout=timeout_s, extra_headers=CLOSE_HEADERS),
                timeout_s + ATTEMPT_GRACE_S,
            )
            return [str(model.id) for model in page.data]
        except OutOfTime:
            raise LLMRequestError(f"{label}: no complete answer within {timeout_s:g} s") from None
        except (openai.APIConnectionError, openai.AuthenticationError, openai.PermissionDeniedError) as exc:
            text = describe_error(exc, self.redactor)
            raise LLMRequestError(f"{label}: {text}{key_hint(exc, self.api_key_env)}", status_of(exc)) from None
        except Exception as exc:  # any other answer (404, not a list, ...): the endpoint is optional
            log.info("%s does not list its models: %s", label, describe_error(exc, self.redactor))
            return []

    def close(self) -> None:
        self.client.close()


# -- one attempt on a thread the caller can walk away from -------------------------------------------------------

_LOCAL = threading.local()


def _trace_current_attempt(request: Any) -> None:
    """httpx request hook (runs on the attempt's thread): let the attempt see the sockets it opens."""
    attempt = getattr(_LOCAL, "attempt", None)
    if attempt is not None:
        request.extensions["trace"] = attempt.trace


def _shut(sock: Any) -> None:
    try:  # the plain socket's method even for TLS: it wakes a blocked read at once
        socket.socket.shutdown(sock, socket.SHUT_RDWR)
    except (OSError, TypeError):
        pass


class _Attempt:
    """Runs `call` on a daemon thread; past its time, the caller leaves and the attempt's sockets are shut."""

    def __init__(self, call: Callable[[], Any]) -> None:
        self._call = call
        self._lock = threading.Lock()
        self._sockets: list[Any] = []
        self._abandoned = False
        self._done = threading.Event()
        self._result: Any = None
        self._error: BaseException | None = None

    def run(self, seconds: float) -> Any:
        threading.Thread(target=self._work, name="physcensis-llm-request", daemon=True).start()
        try:
            finished = self._done.wait(max(0.0, seconds))
        except BaseException:  # Ctrl-C while waiting: the attempt must not live on
            self._abandon()
            raise
        if not finished:
            self._abandon()
            raise OutOfTime
        if self._error is not None:
            raise self._error
        return self._result

    def _work(self) -> None:
        _LOCAL.attempt = self
        try:
            self._result = self._call()
        except BaseException as exc:  # handed to the caller (or dropped, once it has left)
            self._error = exc
        finally:
            _LOCAL.attempt = None
            self._done.set()

    def trace(self, event: str, info: dict[str, Any]) -> None:
        """httpcore trace callback: note every socket connected or wrapped in TLS."""
        if not event.endswith(("connect_tcp.complete", "start_tls.complete")):
            return
        stream = info.get("return_value")
        sock = stream.get_extra_info("socket") if stream is not None else None
        if sock is None:
            return
        with self._lock:
            self._sockets.append(sock)
            abandoned = self._abandoned
        if abandoned:  # connected just after the caller left
            _shut(sock)

    def _abandon(self) -> None:
        with self._lock:
            self._abandoned = True
            sockets = list(self._sockets)
        for sock in sockets:
            _shut(sock)


# -- reading and checking a reply --------------------------------------------------------------------------------


def _read_capped(chunks: Iterable[bytes], limit: int) -> bytes:
    body = bytearray()
    for chunk in chunks:
        body += chunk
        if len(body) > limit:
            raise ReplyError(f"the server's reply is larger than {limit // (1024 * 1024)} MB; stopped reading")
    return bytes(body)


def _lines_capped(chunks: Iterable[bytes], limit: int) -> Iterator[bytes]:
    """The lines of a streamed body (without their ends), up to `limit` bytes read in all."""
    total = 0
    pending = bytearray()
    for chunk in chunks:
        total += len(chunk)
        if total > limit:
            raise ReplyError(f"the server's reply is larger than {limit // (1024 * 1024)} MB; stopped reading")
        pending += chunk
        if b"\n" in chunk:  # split only then: a long line arriving in small pieces is not copied again and again
            *lines, rest = bytes(pending).split(b"\n")
            pending = bytearray(rest)
            yield from lines
    if pending:
        yield bytes(pending)


def _post_chat(
    server: ChatServer, request: dict[str, Any], seconds: float, on_chunks: Callable[[int], None] | None = None
) -> dict[str, Any]:
    """One chat request; the reply's JSON once it is known to be a chat completion. A streamed reply (server-sent
    events) is assembled into the same shape; a server may answer a streamed request with plain JSON."""
    endpoint = server.client.chat.completions.with_streaming_response
    with endpoint.create(**request, timeout=seconds, extra_headers=CLOSE_HEADERS) as response:
        try:
            if request.get("stream") and _is_event_stream(response.headers.get("content-type")):
                lines = _lines_capped(response.iter_bytes(), MAX_RESPONSE_BYTES)
                return completion_from_events(lines, server.redactor, on_chunks)
            body = _read_capped(response.iter_bytes(), MAX_RESPONSE_BYTES)
        except ReplyError:
            raise
        except Exception as exc:  # the transport's own errors (httpx), raised while the body streams in
            raise ReplyError(f"the reply broke off ({exc.__class__.__name__}: {exc})") from None
    return completion_from_body(body, server.redactor)


def _is_event_stream(content_type: str | None) -> bool:
    return (content_type or "").split(";")[0].strip().lower() == "text/event-stream"


# -- a streamed reply ----------------------------------------------------------------------------------------------


class _ChunkCounter:
    """Counts the content chunks of a streamed reply and reports the count, at most every `every_s` seconds.
    Reporting is only a display: a callback that fails is logged and not called again."""

    def __init__(self, report: Callable[[int], None] | None, every_s: float = TOKEN_REPORT_EVERY_S) -> None:
        self.count = 0
        self._report = report
        self._every_s = every_s
        self._reported = 0
        self._last = -math.inf

    def add(self) -> None:
        self.count += 1
        now = time.monotonic()
        if now - self._last >= self._every_s:
            self._last = now
            self._call()

    def flush(self) -> None:
        if self._reported != self.count:
            self._call()

    def _call(self) -> None:
        if self._report is None:
            return
        self._reported = self.count
        try:
            self._report(self.count)
        except Exception as exc:  # the progress display's own bug must not fail (or retry) the request
            log.warning("the token progress callback failed (%s: %s); not calling it again", type(exc).__name__, exc)
            self._report = None


class _StreamedReply:
    """A chat completion assembled from its stream's chunks."""

    def __init__(self, counter: _ChunkCounter, redactor: Redactor) -> None:
        self.counter = counter
        self.redactor = redactor
        self.parts: list[str] = []
        self.refusal: list[str] = []
        self.finish: str | None = None
        self.usage: dict[str, Any] | None = None
        self.model: Any = None

    def add(self, data: str) -> None:
        chunk = self._parse(data)
        self.model = chunk.get("model", self.model)
        if isinstance(chunk.get("usage"), dict):
            self.usage = chunk["usage"]
        choices = chunk.get("choices") or []
        if not isinstance(choices, list):
            raise ReplyError("the server's stream was not a chat completion: 'choices' is not a list")
        for choice in choices[:1]:
            delta = choice.get("delta") if isinstance(choice, dict) else None
            content = delta.get("content") if isinstance(delta, dict) else None
            if isinstance(content, str) and content:
                self.parts.append(content)
                self.counter.add()
            refusal = delta.get("refusal") if isinstance(delta, dict) else None
            if isinstance(refusal, str):
                self.refusal.append(refusal)
            finish = choice.get("finish_reason") if isinstance(choice, dict) else None
            if isinstance(finish, str):
                self.finish = finish

    def _parse(self, data: str) -> dict[str, Any]:
        try:
            chunk = json.loads(data)
        except (ValueError, RecursionError):
            raise ReplyError(
                f"the server's stream was not a chat completion: an event is not JSON; it starts with "
                f"{_snippet(data, self.redactor)}"
            ) from None
        if not isinstance(chunk, dict):
            raise ReplyError(f"the server's stream was not a chat completion: an event is JSON {type(chunk).__name__}")
        error = chunk.get("error")
        if error:
            message = error.get("message") if isinstance(error, dict) else error
            raise ReplyError(self.redactor.text(f"the server's stream reported an error: {_one_line(str(message))}"))
        return chunk

    def completion(self) -> dict[str, Any]:
        return {
            "object": "chat.completion",
            "model": self.model,
            "choices": [
                {
                    "index": 0,
                    "message": {
                        "role": "assistant",
                        "content": "".join(self.parts),
                        "refusal": "".join(self.refusal) or None,
                    },
                    "finish_reason": self.finish,
                }
            ],
            "usage": self.usage,
        }


def completion_from_events(
    lines: Iterable[bytes], redactor: Redactor | None = None, on_chunks: Callable[[int], None] | None = None
) -> dict[str, Any]:
    """The chat completion a stream of server-sent events carries (`data: {chunk}` lines up to `data: [DONE]`), in
    the shape of a non-streamed one; `on_chunks` hears the number of content chunks received so far. `ReplyError`
    when the stream breaks off before its end or is not a chat completion's."""
    reply = _StreamedReply(_ChunkCounter(on_chunks), redactor or Redactor())
    done = False
    for line in lines:
        text = line.decode("utf-8", errors="replace").rstrip("\r")
        if not text.startswith("data:"):  # comments (keep-alives), event names, blank separators
            continue
        data = text.removeprefix("data:").strip()
        if data == "[DONE]":
            done = True
            break
        reply.add(data)
    reply.counter.flush()
    if not done and reply.finish is None:  # a finished choice without [DONE] is whole: some servers end so
        raise ReplyError(
            f"the server's stream broke off before its end ({_plural(reply.counter.count, 'content chunk')} received)"
        )
    return reply.completion()


def _snippet(text: str, redactor: Redactor) -> str:
    line = " ".join(redactor.text(text[:400]).split())
    return repr(line if len(line) <= 60 else line[:57] + "...")


def completion_from_body(body: bytes, redactor: Redactor | None = None) -> dict[str, Any]:
    """The parsed body of an HTTP-200 chat reply, or `ReplyError` saying why it is not a chat completion."""
    redactor = redactor or Redactor()
    text = body.decode("utf-8", errors="replace")
    if not text.strip():
        raise ReplyError("the server's reply was not a chat completion: the body is empty")
    try:
        data = json.loads(text)
    except ValueError as exc:  # JSONDecodeError, and the int() digit limit
        where = f" ({exc.msg} at character {exc.pos})" if isinstance(exc, json.JSONDecodeError) else ""
        raise ReplyError(
            f"the server's reply was not a chat completion: not JSON{where}; it starts with {_snippet(text, redactor)}"
        ) from None
    except RecursionError:
        raise ReplyError("the server's reply was not a chat completion: JSON nested too deeply") from None
    problem = _completion_problem(data)
    if problem:
        raise ReplyError(redactor.text(f"the server's reply was not a chat completion: {problem}"))
    return data


def _completion_problem(data: Any) -> str | None:
    if not isinstance(data, dict):
        return f"JSON {type(data).__name__} instead of an object"
    choices = data.get("choices")
    if choices is None:
        error = data.get("error")
        if error:
            message = error.get("message") if isinstance(error, dict) else error
            return f"an error object ({_one_line(str(message))[:200]})"
        if "choices" in data:
            return "'choices' is null"
        return f"JSON without 'choices' (keys: {', '.join(sorted(map(str, data))[:8]) or 'none'})"
    if not isinstance(choices, list) or not choices:
        return "'choices' is empty" if isinstance(choices, list) else "'choices' is not a list"
    first = choices[0]
    message = first.get("message") if isinstance(first, dict) else None
    if not isinstance(message, dict):
        return "the first choice has no 'message'"
    content = message.get("content")
    if content is not None and not isinstance(content, str | list):
        return f"the message content is JSON {type(content).__name__}, not text"
    return None


def reply_text(response: dict[str, Any]) -> tuple[str, str | None]:
    """The first choice's text ("" when the server sent none; the model's refusal, marked, when it refused) and its
    finish reason."""
    choice = response["choices"][0]
    content = choice["message"].get("content")
    if isinstance(content, list):  # content parts: keep the text ones
        content = "".join(p.get("text", "") for p in content if isinstance(p, dict) and isinstance(p.get("text"), str))
    refusal = choice["message"].get("refusal")
    if not content and isinstance(refusal, str) and refusal:
        content = f"(the model refused: {refusal})"
    finish = choice.get("finish_reason")
    return (content if isinstance(content, str) else ""), (finish if isinstance(finish, str) else None)


def usage_of(response: dict[str, Any]) -> dict[str, Any] | None:
    usage = response.get("usage")
    if not isinstance(usage, dict):
        return None
    return {k: usage.get(k) for k in ("prompt_tokens", "completion_tokens", "total_tokens")}


# -- errors, retries and the deadline ----------------------------------------------------------------------------


def describe_error(exc: Exception, redactor: Redactor) -> str:
    """A short, secret-free description of a failed attempt."""
    if isinstance(exc, openai.APITimeoutError):
        return "no answer before the timeout"
    if isinstance(exc, openai.APIConnectionError):
        cause = exc.__cause__
        detail = f" ({cause.__class__.__name__}: {cause})" if cause else ""
        return _one_line(redactor.text(f"could not connect{detail}"))
    if isinstance(exc, openai.APIStatusError):
        body = exc.body
        message = body.get("message") if isinstance(body, dict) else None
        if not isinstance(message, str) or not message:
            message = str(body) if body else exc.response.reason_phrase
        return _one_line(redactor.text(f"HTTP {exc.status_code} {exc.__class__.__name__}: {message}"))
    return _one_line(redactor.text(f"{exc}" if isinstance(exc, ReplyError) else f"{exc.__class__.__name__}: {exc}"))


def _retry_after_s(exc: Exception) -> float | None:
    """The server's own `retry-after` wish, in seconds, when it gave one."""
    if not isinstance(exc, openai.APIStatusError):
        return None
    headers = exc.response.headers
    for name, divisor in (("retry-after-ms", 1000.0), ("retry-after", 1.0)):
        value = headers.get(name)
        if value is None:
            continue
        try:
            seconds = float(value) / divisor
        except ValueError:
            continue
        if math.isfinite(seconds) and seconds >= 0:
            return seconds
    return None


def key_hint(exc: Exception, key_env: str) -> str:
    if isinstance(exc, openai.AuthenticationError | openai.PermissionDeniedError):
        return f" (check the API key in {key_env or 'the environment'})"
    return ""


def _retryable(exc: Exception) -> bool:
    if isinstance(exc, openai.APIStatusError) and _names_structured_output(str(exc)):
        return False  # the server rejects the request's response_format: asking again cannot help
    return isinstance(exc, _RETRYABLE) or (  # our own ReplyError and OutOfTime are read by _failure_of
        isinstance(exc, openai.APIStatusError) and exc.status_code in _RETRYABLE_STATUS
    )


def _names_structured_output(text: str) -> bool:
    text = text.lower()
    return any(word in text for word in _REFUSAL_WORDS)


def status_of(exc: Exception) -> int | None:
    return exc.status_code if isinstance(exc, openai.APIStatusError) else None


def _plural(n: int, word: str) -> str:
    return f"{n} {word}{'' if n == 1 else 's'}"


class _Deadline:
    """The wall-clock budget of one request, with what it was spent on."""

    def __init__(self, seconds: float) -> None:
        self.seconds = seconds
        self.ends = time.monotonic() + seconds
        self.attempts = 0
        self.waited_s = 0.0

    def remaining(self) -> float:
        return self.ends - time.monotonic()

    def missed(self, label: str, last_error: str | None) -> str:
        message = (
            f"{label}: no complete answer within {self.seconds:g} s ({_plural(self.attempts, 'attempt')}, "
            f"waited {self.waited_s:.1f} s between them)"
        )
        return f"{message}; last error: {last_error}" if last_error else message


def chat_completion(
    server: ChatProvider,
    request: dict[str, Any],
    *,
    policy: RetryPolicy,
    timeout_s: float,
    label: str,
    attempts: list[dict[str, Any]] | None = None,
    sleep: Callable[[float], None] = time.sleep,
    attempt_timeout_s: float | None = None,
    on_chunks: Callable[[int], None] | None = None,
) -> dict[str, Any]:
    """The server's chat completion for `request` (its JSON), retrying transient failures as `policy` says.

    All attempts and the waits between them share the wall-clock budget `timeout_s`; `attempt_timeout_s`
    can end a single attempt earlier so that it is retried. Each failed attempt is appended to `attempts`
    (error text and the wait that followed). Raises `LLMRequestError` with a one-line, secret-free message.
    A streamed request (`"stream": true`) tells `on_chunks` how many content chunks of the attempt have arrived.
    """
    attempts = attempts if attempts is not None else []
    deadline = _Deadline(timeout_s)
    last_error: str | None = None
    status: int | None = None
    for attempt in range(policy.max_retries + 1):
        remaining = deadline.remaining()
        if remaining <= 0:
            raise LLMRequestError(deadline.missed(label, last_error), status)
        seconds = remaining if attempt_timeout_s is None else min(remaining, attempt_timeout_s)
        wall = remaining if seconds >= remaining else min(remaining, seconds + ATTEMPT_GRACE_S)
        deadline.attempts += 1
        try:
            return _Attempt(functools.partial(server.attempt, request, seconds, on_chunks)).run(wall)
        except Exception as exc:
            failure = _failure_of(server, exc, seconds)
            if failure is None:
                raise
            # An attempt given all the time left ends at the deadline whichever timer fires first, ours or the client's.
            client_timer = failure.timed_out and seconds >= remaining
            if client_timer or (isinstance(exc, OutOfTime) and deadline.remaining() <= 0):
                attempts.append({"error": "no complete answer before the deadline", "status": None, "retry": False})
                raise LLMRequestError(deadline.missed(label, None), None) from None
            text = failure.text
            status, last_error = failure.status, text
            if not failure.retryable or attempt == policy.max_retries:
                attempts.append({"error": text, "status": status, "retry": False})
                if not failure.retryable:
                    raise LLMRequestError(f"{label}: {text}{failure.hint}", status) from None
                raise LLMRequestError(
                    f"{label}: gave up after {_plural(attempt + 1, 'attempt')}; last error: {text}", status
                ) from None
            wait = _wait_s(policy, attempt, label, failure)
            if wait >= deadline.remaining():
                attempts.append({"error": text, "status": status, "retry": False})
                raise LLMRequestError(deadline.missed(label, text), status) from None
            attempts.append({"error": text, "status": status, "retry": True, "wait_s": round(wait, 3)})
            log.warning("%s: %s; retry %d of %d in %.1f s", label, text, attempt + 1, policy.max_retries, wait)
            sleep(wait)
            deadline.waited_s += wait
    raise AssertionError("unreachable")  # the loop returns or raises


def _failure_of(server: ChatProvider, exc: Exception, seconds: float) -> AttemptFailure | None:
    """How a failed attempt reads: ours (out of time, a reply that is not a completion) or the provider's."""
    if isinstance(exc, OutOfTime):
        return AttemptFailure(f"no complete answer within {seconds:g} s", retryable=True)
    if isinstance(exc, ReplyError):
        return AttemptFailure(_one_line(server.redactor.text(str(exc))), retryable=True)
    return server.failure(exc)


def _wait_s(policy: RetryPolicy, attempt: int, label: str, failure: AttemptFailure) -> float:
    wait = policy.delay_s(attempt, label)
    wished = failure.retry_after_s
    return wait if wished is None else min(policy.max_backoff_s, max(wait, wished))


def call_within(call: Callable[[], Any], seconds: float) -> Any:
    """`call()` (a request on a `ChatServer`'s client) with a wall-clock limit; `OutOfTime` past it."""
    return _Attempt(call).run(seconds)


# -- structured output -------------------------------------------------------------------------------------------


def refuses_structured_output(exc: LLMRequestError) -> bool:
    """Whether a failed request is the server refusing `response_format` (not a bad key, model or message)."""
    return exc.status is not None and exc.status >= 400 and _names_structured_output(str(exc))


def refuses_streaming(exc: LLMRequestError, label: str) -> str | None:
    """The streaming field a failed request's server refused ("stream_options" or "stream"), or None: a 4xx whose
    message (past the label, which names the model and URL) names it."""
    if exc.status is None or not 400 <= exc.status < 500:
        return None
    text = str(exc).removeprefix(label).lower()
    if "stream_options" in text or "include_usage" in text:
        return "stream_options"
    return "stream" if re.search(r"\bstream(ing)?\b", text) else None
