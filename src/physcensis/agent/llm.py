"""An agent backed by any OpenAI-compatible chat model (OpenAI, vLLM, Ollama, llama.cpp server, LM Studio).

It sends the plain chat-completions request every such server understands and
returns the model's text as is: the loop parses it, so invalid output becomes
grammar feedback rather than an exception. Transient failures (no connection,
timeouts, rate limits, 5xx) are retried here with exponential backoff; anything
else (bad key, bad request, unknown model) raises `AgentError` at once. The API
key is read from the environment and never appears in errors, logs or `calls`.
"""

from __future__ import annotations

import logging
import math
import os
import time
import zlib
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import openai

from physcensis.agent.base import AgentContext, AgentError
from physcensis.agent.prompt import messages as build_messages

log = logging.getLogger(__name__)

NO_KEY = "not-needed"  # local servers ignore the key, but the client wants one
MAX_ERROR_CHARS = 300
REDACTED = "[redacted]"

_RETRYABLE = (openai.APIConnectionError, openai.RateLimitError, openai.InternalServerError)  # timeouts included
_RETRYABLE_STATUS = {408}


class LLMRequestError(AgentError):
    """A chat request that failed for good; `status` is the HTTP status when the server answered."""

    def __init__(self, message: str, status: int | None = None) -> None:
        super().__init__(message)
        self.status = status


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


def redact(text: str, secret: str | None) -> str:
    """`text` on one line, shortened, with the secret removed."""
    if secret and secret != NO_KEY:
        text = text.replace(secret, REDACTED)
    line = " ".join(text.split())
    return line if len(line) <= MAX_ERROR_CHARS else line[: MAX_ERROR_CHARS - 3] + "..."


def describe_error(exc: Exception, secret: str | None) -> str:
    """A short, key-free description of an `openai` exception."""
    if isinstance(exc, openai.APITimeoutError):
        return "no answer before the timeout"
    if isinstance(exc, openai.APIConnectionError):
        cause = exc.__cause__
        detail = f" ({cause.__class__.__name__}: {cause})" if cause else ""
        return redact(f"could not connect{detail}", secret)
    if isinstance(exc, openai.APIStatusError):
        body = exc.body
        message = body.get("message") if isinstance(body, dict) else None
        if not isinstance(message, str) or not message:
            message = str(body) if body else exc.response.reason_phrase
        return redact(f"HTTP {exc.status_code} {exc.__class__.__name__}: {message}", secret)
    return redact(f"{exc.__class__.__name__}: {exc}", secret)


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


def _key_hint(exc: Exception, key_env: str) -> str:
    if isinstance(exc, openai.AuthenticationError | openai.PermissionDeniedError):
        return f" (check the API key in {key_env or 'the environment'})"
    return ""


def _retryable(exc: Exception) -> bool:
    return isinstance(exc, _RETRYABLE) or (
        isinstance(exc, openai.APIStatusError) and exc.status_code in _RETRYABLE_STATUS
    )


def make_client(base_url: str | None, api_key_env: str, timeout_s: float) -> tuple[openai.OpenAI, str]:
    """An `openai` client that does not retry by itself, and the key it uses (for redaction only)."""
    secret = os.environ.get(api_key_env) or NO_KEY
    client = openai.OpenAI(base_url=base_url, api_key=secret, timeout=timeout_s, max_retries=0)
    return client, secret


def chat_completion(
    client: openai.OpenAI,
    request: dict[str, Any],
    *,
    policy: RetryPolicy,
    secret: str | None,
    label: str,
    attempts: list[dict[str, Any]] | None = None,
    sleep: Callable[[float], None] = time.sleep,
    key_env: str = "",
) -> Any:
    """`client.chat.completions.create(**request)`, retrying transient failures as `policy` says.

    Each failed attempt is appended to `attempts` (error text and the wait that followed).
    `key_env` names the key's environment variable in authentication errors. Raises
    `LLMRequestError` with a one-line, key-free message when it gives up.
    """
    for attempt in range(policy.max_retries + 1):
        try:
            return client.chat.completions.create(**request)
        except openai.OpenAIError as exc:
            text = describe_error(exc, secret)
            status = exc.status_code if isinstance(exc, openai.APIStatusError) else None
            last = attempt == policy.max_retries
            if not _retryable(exc):
                if attempts is not None:
                    attempts.append({"error": text, "status": status, "retry": False})
                raise LLMRequestError(f"{label}: {text}{_key_hint(exc, key_env)}", status) from None
            if last:
                if attempts is not None:
                    attempts.append({"error": text, "status": status, "retry": False})
                raise LLMRequestError(
                    f"{label}: gave up after {attempt + 1} attempt{'s' if attempt else ''}; last error: {text}", status
                ) from None
            wait = policy.delay_s(attempt, label)
            wished = _retry_after_s(exc)
            if wished is not None:
                wait = min(policy.max_backoff_s, max(wait, wished))
            if attempts is not None:
                attempts.append({"error": text, "status": status, "retry": True, "wait_s": round(wait, 3)})
            log.warning("%s: %s; retry %d of %d in %.1f s", label, text, attempt + 1, policy.max_retries, wait)
            sleep(wait)
    raise AssertionError("unreachable")  # the loop returns or raises


def reply_text(response: Any) -> tuple[str, str | None]:
    """The first choice's text ("" when the server sent none) and its finish reason."""
    choices = getattr(response, "choices", None)
    if not choices:
        return "", None
    choice = choices[0]
    message = getattr(choice, "message", None)
    content = getattr(message, "content", None)
    return (content if isinstance(content, str) else ""), getattr(choice, "finish_reason", None)


def _usage(response: Any) -> dict[str, Any] | None:
    usage = getattr(response, "usage", None)
    if usage is None:
        return None
    keys = ("prompt_tokens", "completion_tokens", "total_tokens")
    return {k: getattr(usage, k, None) for k in keys}


class LLMAgent:
    """Writes programs with a chat model; `calls` keeps every request and reply (never the key)."""

    def __init__(
        self,
        model: str,
        base_url: str | None = None,
        api_key_env: str = "OPENAI_API_KEY",
        temperature: float | None = 0.7,
        timeout_s: float = 120.0,
        max_retries: int = 4,
        max_tokens: int | None = None,
        *,
        backoff_s: float = 1.0,
        max_backoff_s: float = 30.0,
        sleep: Callable[[float], None] = time.sleep,
    ) -> None:
        self.model = model
        self.name = f"llm:{model}"
        self.temperature = temperature
        self.max_tokens = max_tokens
        self.timeout_s = timeout_s
        self.api_key_env = api_key_env
        self.policy = RetryPolicy(max_retries=max_retries, backoff_s=backoff_s, max_backoff_s=max_backoff_s)
        self._client, self._secret = make_client(base_url, api_key_env, timeout_s)
        self.base_url = str(self._client.base_url)
        self._sleep = sleep
        self.calls: list[dict[str, Any]] = []

    def propose(self, context: AgentContext) -> str:
        """The model's reply to the conversation built from `context` (unparsed)."""
        return self.complete(build_messages(context), request=context.request)

    def complete(self, chat: list[dict[str, Any]], request: str = "") -> str:
        """Send one chat and return the reply text; record the exchange in `calls`."""
        body: dict[str, Any] = {"model": self.model, "messages": chat}
        if self.temperature is not None:
            body["temperature"] = self.temperature
        if self.max_tokens is not None:
            body["max_tokens"] = self.max_tokens
        record: dict[str, Any] = {
            "base_url": self.base_url, "request_kind": request, "request": body,
            "attempts": [], "response": None, "finish_reason": None, "usage": None, "error": None,
        }
        self.calls.append(record)
        label = f"LLM {self.model} at {self.base_url}"
        start = time.perf_counter()
        try:
            response = chat_completion(
                self._client, body, policy=self.policy, secret=self._secret, label=label,
                attempts=record["attempts"], sleep=self._sleep, key_env=self.api_key_env,
            )
        except LLMRequestError as exc:
            record["error"] = str(exc)
            raise
        finally:
            record["duration_s"] = round(time.perf_counter() - start, 3)
        text, finish = reply_text(response)
        record.update(response=text, finish_reason=finish, usage=_usage(response))
        if not text:
            log.warning("%s: the reply holds no text (finish reason %s)", label, finish)
        return text

    def served_models(self, timeout_s: float = 10.0) -> list[str]:
        """The model ids the server lists (GET /models), to find a dead server or a refused key up front.

        Raises `LLMRequestError` when nobody answers or the key is refused; returns [] when the server
        answers but does not list its models (the endpoint is optional for some servers).
        """
        label = f"LLM server at {self.base_url}"
        try:
            page = self._client.with_options(timeout=timeout_s).models.list()
        except (openai.APIConnectionError, openai.AuthenticationError, openai.PermissionDeniedError) as exc:
            status = exc.status_code if isinstance(exc, openai.APIStatusError) else None
            text = describe_error(exc, self._secret)
            raise LLMRequestError(f"{label}: {text}{_key_hint(exc, self.api_key_env)}", status) from None
        except openai.OpenAIError as exc:
            log.info("%s does not list its models: %s", label, describe_error(exc, self._secret))
            return []
        return [str(model.id) for model in page.data]
