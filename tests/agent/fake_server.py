"""A real, local OpenAI-compatible HTTP server for tests: scripted replies, injectable failures.

    with FakeOpenAI(replies=["[...program...]", Reply(status=500), "..."], fail_first=2) as server:
        agent = LLMAgent("fake-model", base_url=server.base_url)
        ...
        server.requests  # every request body received, parsed, in order

It listens on 127.0.0.1 on a free port and serves POST /v1/chat/completions
(and GET /v1/models). Requests are answered in this order: the first
`hang_first` ones hang for `hang_s` and get no answer (past the client's
timeout), the next `fail_first` ones get HTTP `fail_status`, and the rest take
the scripted replies one by one. With `api_key` set, a request whose bearer
token differs gets a 401 whose message echoes the token it received, as some
servers do (tests check that the client never repeats it).

A `Reply` can also be hostile: `drip_s` sends it one byte at a time (the body
only, or with `drip_headers` the whole response), `raw` sends any bytes as the
body (HTML, truncated JSON, nothing), and `echo` quotes the request's
Authorization header and URL (with the credentials it decodes) in the reply
and in an error's message. `request_sizes` holds the byte size of each
request body received. With `refuse_json_schema`, a request whose `response_format` is OpenAI's `json_schema` gets
the HTTP 500 llama-cpp-python's server answers (its validation error), while `json_object` with a schema is taken.
With `refuse_response_format`, every request carrying a
`response_format` gets HTTP 400 naming it (a server without structured output).

A request with `"stream": true` is answered with server-sent events (`data: {chunk}` lines, the content a few
characters per chunk, more for a huge one, then `data: [DONE]`), the usage in a last chunk when
`stream_options.include_usage` asks for it, unless the server is made with `no_stream` (then plain JSON, as servers
without streaming answer). A `Reply` can
space its chunks (`chunk_s`), break off after `break_after` chunks (no finish, no [DONE]) or stream for ever
(`endless`). `refuse_stream_options` / `refuse_stream` answer HTTP 400 naming the field, as servers without them do.
"""

from __future__ import annotations

import base64
import binascii
import itertools
import json
import threading
import time
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field, replace
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from types import TracebackType
from typing import Any

import pytest

CHAT_PATH = "/v1/chat/completions"
PROXY_VARS = ("HTTP_PROXY", "HTTPS_PROXY", "ALL_PROXY", "http_proxy", "https_proxy", "all_proxy")

# A reply that solves on a 0.6 x 0.6 m table: a mug and a book beside it.
MUG_AND_BOOK = json.dumps(
    [
        ["mug_0", "a white coffee mug"],
        ["mug_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
        ["mug_0", "FACING-FRONT", "root", {}],
        ["book_0", "a red hardcover book lying flat"],
        ["book_0", "PLACE-ON-BASE", "root", {}],
        ["book_0", "LEFT-OF", "mug_0", {"distance": 0.05}],
        ["book_0", "ALIGN-CENTER-FB", "mug_0", {}],
        ["book_0", "FACING-FRONT", "root", {}],
    ]
)


def use_loopback_only(monkeypatch: pytest.MonkeyPatch, api_key: str) -> None:
    """Only loopback, only `api_key`: no proxies, no base URL from the developer's shell."""
    for name in PROXY_VARS:
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("NO_PROXY", "127.0.0.1,localhost")
    monkeypatch.delenv("OPENAI_BASE_URL", raising=False)
    monkeypatch.setenv("OPENAI_API_KEY", api_key)


@dataclass(frozen=True)
class Reply:
    """One scripted answer."""

    content: str | None = ""
    status: int = 200
    delay_s: float = 0.0  # wait before answering
    top_logprobs: tuple[tuple[str, float], ...] | None = None  # alternatives for the first token
    error: str = "scripted failure"  # message of a non-200 reply
    headers: Mapping[str, str] = field(default_factory=dict)
    body: dict[str, Any] | None = None  # sent verbatim instead of a built completion
    raw: bytes | None = None  # sent as the body as is (with `content_type`), whatever the status
    content_type: str = "application/json"
    drip_s: float = 0.0  # seconds between bytes: the response trickles in, resetting every read timeout
    drip_headers: bool = False  # drip the status line and headers too, not only the body
    echo: bool = False  # quote the Authorization header and the URL (credentials decoded) in content and error
    chunk_s: float = 0.0  # a streamed reply: seconds between its chunks
    break_after: int | None = None  # a streamed reply: hang up after this many content chunks
    endless: bool = False  # a streamed reply: content chunks for ever (until the client or the server stops)


class _Server(ThreadingHTTPServer):
    daemon_threads = True
    block_on_close = False
    fake: FakeOpenAI

    def handle_error(self, request: Any, client_address: Any) -> None:
        """Clients that gave up (timeouts) break pipes; that is expected here."""


class _Handler(BaseHTTPRequestHandler):
    protocol_version = "HTTP/1.1"
    server: _Server

    def log_message(self, format: str, *args: Any) -> None:  # `format`: the base class's parameter name
        """Silence the default per-request stderr line."""

    def _send(
        self, status: int, payload: dict[str, Any], headers: Mapping[str, str] | None = None, reply: Reply | None = None
    ) -> None:
        reply = reply or Reply()
        data = reply.raw if reply.raw is not None else json.dumps(payload).encode()
        self.send_response(status)
        self.send_header("Content-Type", reply.content_type if reply.raw is not None else "application/json")
        self.send_header("Content-Length", str(len(data)))
        for name, value in (headers or {}).items():
            self.send_header(name, value)
        if reply.drip_s <= 0:
            self.end_headers()
            self.wfile.write(data)
            return
        if reply.drip_headers:
            self._headers_buffer.append(b"\r\n")
            data = b"".join(self._headers_buffer) + data
            self._headers_buffer = []
        else:
            self.end_headers()
            self.wfile.flush()
        self._drip(data, reply.drip_s)

    def _drip(self, data: bytes, every_s: float) -> None:
        """One byte, then a pause, until done, the client hangs up or the server stops."""
        stopping = self.server.fake._stopping
        for i in range(len(data)):
            try:
                self.wfile.write(data[i : i + 1])
                self.wfile.flush()
            except OSError:
                break
            if stopping.wait(every_s):
                break
        self.close_connection = True

    def _echo(self) -> str:
        """The request's Authorization header and the URL it was sent to, credentials decoded as a proxy would."""
        auth = self.headers.get("Authorization") or ""
        userinfo = ""
        if auth.startswith("Basic "):
            try:
                userinfo = base64.b64decode(auth.removeprefix("Basic ")).decode() + "@"
            except (binascii.Error, UnicodeDecodeError):
                userinfo = ""
        return f"you sent Authorization: {auth} to http://{userinfo}{self.headers.get('Host')}{self.path}"

    def _key_refused(self) -> bool:
        token = (self.headers.get("Authorization") or "").removeprefix("Bearer ").strip()
        if self.server.fake.api_key is None or token == self.server.fake.api_key:
            return False
        self._send(
            401,
            {
                "error": {
                    "message": f"Incorrect API key provided: {token}",
                    "type": "invalid_request_error",
                    "code": "invalid_api_key",
                }
            },
        )
        return True

    def do_GET(self) -> None:  # http.server's naming
        self.server.fake.get_paths.append(self.path)
        if self._key_refused():
            return
        n_ctx = self.server.fake.n_ctx
        if self.path.rstrip("/") == "/props" and n_ctx is not None:  # llama.cpp server's context size
            self._send(200, {"default_generation_settings": {"n_ctx": n_ctx}, "total_slots": 1})
        elif self.path.rstrip("/") == "/v1/models":
            self._send(
                200,
                {
                    "object": "list",
                    "data": [{"id": self.server.fake.model, "object": "model", "created": 0, "owned_by": "fake"}],
                },
                reply=self.server.fake.models_reply,
            )
        else:
            self._send(404, {"error": {"message": f"no route {self.path}", "type": "not_found"}})

    def do_POST(self) -> None:  # http.server's naming
        length = int(self.headers.get("Content-Length") or 0)
        raw = self.rfile.read(length)
        self.server.fake.request_sizes.append(len(raw))
        try:
            body = json.loads(raw or b"null")
        except json.JSONDecodeError:
            body = None
        fake = self.server.fake
        if self.path.rstrip("/") != CHAT_PATH:
            self._send(404, {"error": {"message": f"no route {self.path}", "type": "not_found"}})
            return
        action = fake._record(body, {k.lower(): v for k, v in self.headers.items()})
        if action is _HANG:
            fake._stopping.wait(fake.hang_s)
            self.close_connection = True
            return
        if not isinstance(body, dict):
            self._send(400, {"error": {"message": "the body is not a JSON object", "type": "invalid_request_error"}})
            return
        if self._key_refused():
            return
        reply = action if isinstance(action, Reply) else fake._next_reply()
        if reply.echo:
            echo = self._echo()
            reply = replace(reply, content=f"{reply.content or ''} {echo}".strip(), error=f"{reply.error}: {echo}")
        if reply.delay_s > 0:
            fake._stopping.wait(reply.delay_s)
        if reply.status != 200:
            self._send(reply.status, {"error": {"message": reply.error, "type": "fake_error"}}, reply.headers, reply)
            return
        if body.get("stream") and not fake.no_stream and reply.body is None and reply.raw is None:
            self._send_events(_events(body, reply, fake), reply)
            return
        self._send(200, reply.body if reply.body is not None else _completion(body, reply, fake), reply.headers, reply)

    def _send_events(self, events: Iterator[bytes], reply: Reply) -> None:
        """A server-sent event stream: no Content-Length, so the connection's end is the body's end."""
        self.send_response(200)
        self.send_header("Content-Type", "text/event-stream")
        self.send_header("Connection", "close")
        self.end_headers()
        self.close_connection = True
        stopping = self.server.fake._stopping
        for event in events:
            if reply.drip_s > 0:
                self._drip(event, reply.drip_s)
                if stopping.is_set():
                    return
                continue
            try:
                self.wfile.write(event)
                self.wfile.flush()
            except OSError:
                return
            if reply.chunk_s > 0 and stopping.wait(reply.chunk_s):
                return


_HANG = object()
STREAM_CHUNK_CHARS = 4  # about a token
MAX_STREAM_CHUNKS = 10_000  # a huge reply comes in longer chunks: as tokens, it would pass the client's byte cap


def _events(request: dict[str, Any], reply: Reply, fake: FakeOpenAI) -> Iterator[bytes]:
    """The SSE lines of `reply` streamed: role, content pieces, finish, usage (when asked), [DONE]."""
    completion = _completion(request, reply, fake)
    base = {k: completion[k] for k in ("id", "created", "model")} | {"object": "chat.completion.chunk"}

    def chunk(delta: dict[str, Any], finish: str | None = None) -> bytes:
        choice = {"index": 0, "delta": delta, "finish_reason": finish}
        return f"data: {json.dumps(base | {'choices': [choice]})}\n\n".encode()

    yield chunk({"role": "assistant", "content": ""})
    content = reply.content or ""
    size = max(STREAM_CHUNK_CHARS, -(-len(content) // MAX_STREAM_CHUNKS))
    pieces = [content[i : i + size] for i in range(0, len(content), size)]
    for n, piece in enumerate(itertools.cycle(pieces or [" "]) if reply.endless else pieces):
        if reply.break_after is not None and n >= reply.break_after:
            return
        yield chunk({"content": piece})
    yield chunk({}, "stop")
    if (request.get("stream_options") or {}).get("include_usage"):
        yield f"data: {json.dumps(base | {'choices': [], 'usage': completion['usage']})}\n\n".encode()
    yield b"data: [DONE]\n\n"


def _completion(request: dict[str, Any], reply: Reply, fake: FakeOpenAI) -> dict[str, Any]:
    content = reply.content
    logprobs = None
    if request.get("logprobs") and reply.top_logprobs:
        top = [{"token": t, "logprob": lp, "bytes": list(t.encode())} for t, lp in reply.top_logprobs]
        first = max(top, key=lambda t: t["logprob"])
        logprobs = {"content": [{**first, "top_logprobs": top}], "refusal": None}
    prompt_chars = len(json.dumps(request.get("messages", "")))
    completion_chars = len(content or "")
    return {
        "id": f"chatcmpl-fake-{len(fake.requests)}",
        "object": "chat.completion",
        "created": int(time.time()),
        "model": str(request.get("model", fake.model)),
        "choices": [
            {
                "index": 0,
                "message": {"role": "assistant", "content": content},
                "finish_reason": "stop",
                "logprobs": logprobs,
            }
        ],
        "usage": {
            "prompt_tokens": prompt_chars // 4,
            "completion_tokens": completion_chars // 4,
            "total_tokens": (prompt_chars + completion_chars) // 4,
        },
    }


class FakeOpenAI:
    """A context manager running the server in a background thread; see the module docstring."""

    n_ctx: int | None = None  # set it to serve GET /props with this context size, as llama.cpp server does

    def __init__(
        self,
        replies: Sequence[str | Reply] = (),
        *,
        fail_first: int = 0,
        fail_status: int = 500,
        hang_first: int = 0,
        hang_s: float = 5.0,
        api_key: str | None = None,
        repeat_last: bool = False,
        model: str = "fake-model",
        models_reply: Reply | None = None,
        refuse_response_format: bool = False,
        refuse_json_schema: bool = False,
        no_stream: bool = False,
        refuse_stream_options: bool = False,
        refuse_stream: bool = False,
    ) -> None:
        self.replies = [r if isinstance(r, Reply) else Reply(content=r) for r in replies]
        self.fail_first = fail_first
        self.fail_status = fail_status
        self.hang_first = hang_first
        self.hang_s = hang_s
        self.api_key = api_key
        self.repeat_last = repeat_last
        self.model = model
        self.models_reply = models_reply  # how GET /models answers (its drip, a raw body); the list by default
        # answer HTTP 400 naming the field to every request with a `response_format`, as servers without
        # structured output do
        self.refuse_response_format = refuse_response_format
        self.refuse_json_schema = refuse_json_schema
        self.no_stream = no_stream  # answer `stream: true` with plain JSON, as servers without streaming do
        self.refuse_stream_options = refuse_stream_options
        self.refuse_stream = refuse_stream
        self.requests: list[Any] = []  # parsed bodies, in arrival order
        self.headers: list[dict[str, str]] = []  # their headers, names in lower case
        self.request_sizes: list[int] = []  # bytes of each request body, in arrival order
        self._served = 0
        self._lock = threading.Lock()
        self._stopping = threading.Event()
        self._server: _Server | None = None
        self._thread: threading.Thread | None = None

    # -- lifecycle -------------------------------------------------------------
    def start(self) -> FakeOpenAI:
        self.get_paths: list[str] = []  # the path of every GET received, in order
        server = _Server(("127.0.0.1", 0), _Handler)
        server.fake = self
        self._server = server
        self._thread = threading.Thread(
            target=server.serve_forever, kwargs={"poll_interval": 0.05}, name="fake-openai", daemon=True
        )
        self._thread.start()
        return self

    def close(self) -> None:
        self._stopping.set()
        if self._server is not None:
            self._server.shutdown()
            self._server.server_close()
        if self._thread is not None:
            self._thread.join(timeout=5)
        self._server = self._thread = None

    def __enter__(self) -> FakeOpenAI:
        return self.start()

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        self.close()

    @property
    def port(self) -> int:
        if self._server is None:
            raise RuntimeError("the fake server is not running")
        return int(self._server.server_address[1])

    @property
    def base_url(self) -> str:
        return f"http://127.0.0.1:{self.port}/v1"

    # -- scripting -------------------------------------------------------------
    def add_replies(self, *replies: str | Reply) -> None:
        with self._lock:
            self.replies.extend(r if isinstance(r, Reply) else Reply(content=r) for r in replies)

    def _record(self, body: Any, headers: dict[str, str]) -> object:
        """Store the request; return _HANG, an injected failure `Reply`, or None (use the script)."""
        with self._lock:
            self.requests.append(body)
            self.headers.append(headers)
            n = len(self.requests)
        if self.refuse_stream_options and isinstance(body, dict) and "stream_options" in body:
            return Reply(status=400, error="Unsupported parameter: 'stream_options' is not supported with this model")
        if self.refuse_stream and isinstance(body, dict) and body.get("stream"):
            return Reply(status=400, error="Unsupported value: 'stream' does not support true with this model")
        if self.refuse_response_format and isinstance(body, dict) and "response_format" in body:
            return Reply(status=400, error="Unsupported parameter: 'response_format' (json_schema) is not supported")
        if (
            self.refuse_json_schema
            and isinstance(body, dict)
            and body.get("response_format", {}).get("type") == ("json_schema")
        ):
            return Reply(
                status=500,
                error="1 validation error: {'type': 'literal_error', 'loc': ('body', 'response_format', 'type'), "
                "'msg': \"Input should be 'text' or 'json_object'\", 'input': 'json_schema'}",
            )
        if n <= self.hang_first:
            return _HANG
        if n <= self.hang_first + self.fail_first:
            headers_out = {"retry-after": "0"} if self.fail_status == 429 else {}
            return Reply(status=self.fail_status, error=f"injected failure {n}", headers=headers_out)
        return None

    def _next_reply(self) -> Reply:
        with self._lock:
            if self._served < len(self.replies):
                reply = self.replies[self._served]
                self._served += 1
                return reply
            if self.repeat_last and self.replies:
                return self.replies[-1]
        return Reply(status=500, error="fake server: no scripted reply left")

    @property
    def messages(self) -> list[list[dict[str, Any]]]:
        """The `messages` of every chat request received, in order."""
        return [b.get("messages", []) if isinstance(b, dict) else [] for b in self.requests]
