"""Fitting the conversation to the model: which system prompt to send, and how long a reply may be.

`--prompt auto` sends the compact prompt to local servers (small models run there) and to servers that report a
small context window, the full one otherwise. The context is probed once per run, cheaply: llama.cpp server's
`/props` (`n_ctx`), vLLM's `/v1/models` (`max_model_len`) and Ollama's `/api/show` (`num_ctx`), each with a short
timeout; whatever fails is ignored. `max_tokens` is sized from the program the request should produce, so a small
model cannot ramble to the end of its context.
"""

from __future__ import annotations

import ipaddress
import json
import re
import threading
import time
import urllib.error
import urllib.request
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any
from urllib.parse import urlsplit

from physcensis.agent.base import AgentContext
from physcensis.agent.prompt import PROMPT_STYLES, estimate_tokens
from physcensis.agent.reading import NUMERALS

PROMPT_CHOICES = ("auto", *PROMPT_STYLES)
SMALL_CONTEXT_TOKENS = 16_384  # below this the full prompt (~5,400 tokens) leaves too little room for the rounds
PROBE_TIMEOUT_S = 1.5  # per probe request
PROBE_BUDGET_S = 4.0  # all probes together
MAX_PROBE_BYTES = 1024 * 1024

# One object costs about 48 estimated tokens in the prompts' examples (a declaration and three predicates); twice
# that leaves room for longer descriptions and pretty-printed JSON.
TOKENS_PER_OBJECT = 100
REPLY_BASE_TOKENS = 256
DEFAULT_OBJECTS = 12  # when the request names no larger number
ENRICH_EXTRA_OBJECTS = 8
MIN_REPLY_TOKENS = 512
MAX_REPLY_TOKENS = 8_192
CONTEXT_MARGIN_TOKENS = 64  # chat template overhead the estimate does not see
_NUMBER_WORDS = {**NUMERALS, "twenty": 20}  # only exact counts: "a" or "some" name no number to budget for
_DECLARATION = re.compile(r'\[\s*"[^"\[\]]*"\s*,\s*"[^"\[\]]*"\s*\]')  # ["id", "description"]
_GUIDED_OBJECT = re.compile(r'"description"\s*:')  # an object of the object forms


def prompt_choice(value: str) -> str:
    """`value` if it names a prompt choice, else a `ValueError` listing them."""
    if value not in PROMPT_CHOICES:
        raise ValueError(f"prompt must be one of {', '.join(PROMPT_CHOICES)}, not {value!r}")
    return value


# -- which prompt ------------------------------------------------------------------------------------------------


def is_local_server(base_url: str | None) -> bool:
    """Whether the server runs on this machine or the local network: localhost, loopback, private or link-local
    addresses, and *.local names."""
    try:
        host = (urlsplit(base_url or "").hostname or "").rstrip(".").lower()
    except ValueError:
        return False
    if not host:
        return False
    if host == "localhost" or host.endswith((".localhost", ".local")):
        return True
    try:
        address = ipaddress.ip_address(host)
    except ValueError:
        return False
    return address.is_loopback or address.is_private or address.is_link_local


@dataclass(frozen=True)
class PromptDecision:
    style: str  # "full" or "compact"
    reason: str  # in words, for the transcript
    context_tokens: int | None  # the context window the server reported, if any

    def record(self) -> dict[str, Any]:
        return {"style": self.style, "reason": self.reason, "context_tokens": self.context_tokens}


def decide_prompt(setting: str, base_url: str | None, context_tokens: int | None) -> PromptDecision:
    """The prompt style for `setting` ("auto", "full" or "compact") at this server."""
    if setting in PROMPT_STYLES:
        return PromptDecision(setting, f"--prompt {setting}", context_tokens)
    if context_tokens is not None and context_tokens < SMALL_CONTEXT_TOKENS:
        return PromptDecision("compact", f"the server's context is {context_tokens} tokens", context_tokens)
    if is_local_server(base_url):
        return PromptDecision("compact", "a local server", context_tokens)
    why = f"the server's context is {context_tokens} tokens" if context_tokens else "a remote server"
    return PromptDecision("full", why, context_tokens)


# -- the server's context window ----------------------------------------------------------------------------------


def _positive_int(value: Any) -> int | None:
    if isinstance(value, bool):
        return None
    if isinstance(value, int | float) and 0 < value < 1e9:
        return int(value)
    return None


def _from_props(data: Any) -> int | None:
    """llama.cpp server's /props: `default_generation_settings.n_ctx` (or `n_ctx` at the top in older builds)."""
    if not isinstance(data, dict):
        return None
    settings = data.get("default_generation_settings")
    nested = settings.get("n_ctx") if isinstance(settings, dict) else None
    return _positive_int(nested) or _positive_int(data.get("n_ctx"))


def _from_models(data: Any, model: str) -> int | None:
    """vLLM's /v1/models: the served model's `max_model_len`."""
    rows = data.get("data") if isinstance(data, dict) else None
    if not isinstance(rows, list):
        return None
    lengths = {str(r.get("id")): _positive_int(r.get("max_model_len")) for r in rows if isinstance(r, dict)}
    return lengths.get(model) or next((n for n in lengths.values() if n), None)


def _from_ollama_show(data: Any) -> int | None:
    """Ollama's /api/show: `num_ctx` in the model's parameters (a text of "name value" lines)."""
    parameters = data.get("parameters") if isinstance(data, dict) else None
    if not isinstance(parameters, str):
        return None
    match = re.search(r"^\s*num_ctx\s+(\d+)\s*$", parameters, re.MULTILINE)
    return _positive_int(int(match.group(1))) if match else None


class _Prober:
    """GETs and POSTs to one server with short timeouts; `None` for anything but a small JSON answer."""

    def __init__(self, base_url: str, api_key: str | None, deadline: float) -> None:
        self.api = base_url.rstrip("/")
        self.root = self.api.removesuffix("/v1")
        self.deadline = deadline
        self.unreachable = False
        self.headers = {"Authorization": f"Bearer {api_key}"} if api_key else {}

    def json(self, method: str, url: str, body: dict[str, Any] | None = None) -> Any:
        if self.unreachable or time.monotonic() > self.deadline or not url.startswith(("http://", "https://")):
            return None
        data = None if body is None else json.dumps(body).encode()
        headers = {**self.headers, **({"Content-Type": "application/json"} if data else {})}
        request = urllib.request.Request(url, data=data, headers=headers, method=method)
        try:
            with _OPENER.open(request, timeout=PROBE_TIMEOUT_S) as response:
                return json.loads(self._read(response))
        except urllib.error.HTTPError:
            return None  # the server answered: this endpoint is not there
        except (ValueError, RecursionError):  # not JSON, too large, too slow
            return None
        except OSError:  # no connection or no answer in time: the other probes would fare the same
            self.unreachable = True
            return None

    def _read(self, response: Any) -> bytes:
        data = bytearray()
        while chunk := response.read(64 * 1024):
            data += chunk
            if len(data) > MAX_PROBE_BYTES or time.monotonic() > self.deadline:
                raise ValueError("too large or too slow")
        return bytes(data)


class _NoRedirects(urllib.request.HTTPRedirectHandler):
    def redirect_request(self, *args: Any, **kwargs: Any) -> None:
        return None


_OPENER = urllib.request.build_opener(_NoRedirects)


def _probe(base_url: str, model: str, api_key: str | None) -> int | None:
    prober = _Prober(base_url, api_key, time.monotonic() + PROBE_BUDGET_S)
    found = _from_models(prober.json("GET", f"{prober.api}/models"), model) or _from_props(
        prober.json("GET", f"{prober.root}/props")
    )
    if found is None and isinstance(prober.json("GET", f"{prober.root}/api/version"), dict):  # an Ollama
        found = _from_ollama_show(prober.json("POST", f"{prober.root}/api/show", {"model": model}))
    return found


def probe_context_tokens(base_url: str, model: str, api_key: str | None = None) -> int | None:
    """The context window the server reports for `model`, or None (no such endpoint, no answer in time, ...).

    Runs on a daemon thread so that a server dripping its answer cannot hold the caller past `PROBE_BUDGET_S`.
    """
    result: list[int | None] = [None]

    def work() -> None:
        result[0] = _probe(base_url, model, api_key)

    thread = threading.Thread(target=work, name="physcensis-context-probe", daemon=True)
    thread.start()
    thread.join(PROBE_BUDGET_S + PROBE_TIMEOUT_S)
    return None if thread.is_alive() else result[0]


# -- how long a reply may be --------------------------------------------------------------------------------------


def objects_asked_for(text: str) -> int:
    """The numbers a scene request names, added up ("two plates and 6 cups" -> 8); 0 when it names none."""
    words = re.findall(r"[a-z]+|\d+", text.lower())
    return sum(_NUMBER_WORDS.get(w, 0) if w.isalpha() else int(w) for w in words if len(w) <= 3 or w.isalpha())


def expected_objects(context: AgentContext) -> int:
    """How many objects the program of this request should hold."""
    asked = objects_asked_for(context.prompt) + 4  # what is counted, and a few things around it
    last = context.history[-1].program_text if context.history else ""
    written = max(len(_DECLARATION.findall(last)), len(_GUIDED_OBJECT.findall(last)))
    if context.request == "enrich":
        written += ENRICH_EXTRA_OBJECTS
    return max(DEFAULT_OBJECTS, asked, written)


def reply_token_budget(
    context: AgentContext, chat: Sequence[dict[str, Any]], context_tokens: int | None = None, drafted: int = 0
) -> int:
    """`max_tokens` for this request: a budget per expected object (at least the `drafted` objects of the draft the
    model was shown), within [MIN, MAX]_REPLY_TOKENS, and within what the server's context leaves after the chat
    (when it reported its context)."""
    budget = REPLY_BASE_TOKENS + TOKENS_PER_OBJECT * max(expected_objects(context), drafted)
    return fit_reply_tokens(min(MAX_REPLY_TOKENS, max(MIN_REPLY_TOKENS, budget)), chat, context_tokens)


def fit_reply_tokens(budget: int, chat: Sequence[dict[str, Any]], context_tokens: int | None = None) -> int:
    """`budget`, at most MAX_REPLY_TOKENS and at most what the server's context leaves after `chat` (when known)."""
    budget = min(MAX_REPLY_TOKENS, budget)
    if context_tokens is None:
        return budget
    used = sum(estimate_tokens(str(m.get("content") or "")) for m in chat) + CONTEXT_MARGIN_TOKENS
    return max(1, min(budget, context_tokens - used))
