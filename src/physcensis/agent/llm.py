"""An agent backed by any OpenAI-compatible chat model (OpenAI, vLLM, Ollama, llama.cpp server, LM Studio).

It sends its conversation through the one chat client (`physcensis.llm`: deadlines, retries, streaming, redaction)
and returns the model's text as is: the loop parses it, so invalid output becomes grammar feedback rather than an
exception. What is the agent's own: the system prompt that fits the server, the JSON Schema as `response_format` (and
the fallback when a server refuses it), guided two-step rounds for small models, the offline reading as a draft, and
`calls`, every request and reply (never a secret).
"""

from __future__ import annotations

import logging
import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from physcensis.agent import sizing
from physcensis.agent.base import AgentContext, AgentError
from physcensis.agent.guided import (
    OBJECT_LIST_TOKENS,
    OBJECTS_REPLY_BASE_TOKENS,
    OPENAI_MAX_ENUM_VALUES,
    Send,
    two_step_reply,
)
from physcensis.agent.hint import HINT_MODES, Hint, reading_hint, wants_hint
from physcensis.agent.prompt import clip_text
from physcensis.agent.prompt import messages as build_messages
from physcensis.llm.client import (
    DEFAULT_TIMEOUT_S,
    MAX_RECORDED_CHARS,
    LLMRequestError,
    RetryPolicy,
    chat_completion,
    positive_seconds,
    refuses_streaming,
    refuses_structured_output,
    reply_text,
    usage_of,
)
from physcensis.llm.providers import connect
from physcensis.llm.server import is_local_server, probe_context_tokens
from physcensis.program.schema import SCHEMA_DIALECTS, STRUCTURED_MODES, response_format
from physcensis.settings import API_KEY_ENV, DEFAULT_PROVIDER

if TYPE_CHECKING:
    from physcensis.assets.catalogue import Catalogue

log = logging.getLogger(__name__)


def _prompt_setting(value: str) -> str:
    try:
        return sizing.prompt_choice(value)
    except ValueError as exc:
        raise AgentError(str(exc)) from None


def prompt_note(decision: sizing.PromptDecision) -> str:
    """The transcript's line about the system prompt chosen."""
    size = decision.context_tokens
    context = f"; the server's context is {size} tokens" if size and "context" not in decision.reason else ""
    return f"system prompt: {decision.style} ({decision.reason}{context})"


def _request_seed(context: AgentContext) -> int:
    """The sampling seed of a request: the run's seed, moved on every round, so a run repeats exactly while a
    repaired program is not sampled the way the failed one was."""
    return (context.seed * 1009 + len(context.history)) % 2**31


# -- the agent ---------------------------------------------------------------------------------------------------


class LLMAgent:
    """Writes programs with a chat model; `calls` keeps every request and reply (never a secret)."""

    def __init__(
        self,
        model: str,
        base_url: str | None = None,
        api_key_env: str = API_KEY_ENV,
        temperature: float | None = 0.7,
        timeout_s: float = DEFAULT_TIMEOUT_S,
        max_retries: int = 4,
        max_tokens: int | None = None,
        *,
        prompt: str = "auto",
        backoff_s: float = 1.0,
        max_backoff_s: float = 30.0,
        attempt_timeout_s: float | None = None,
        sleep: Callable[[float], None] = time.sleep,
        structured: str = "auto",
        stream: bool = True,
        hint: str = "auto",
        catalogue: Catalogue | None = None,
        provider: str = DEFAULT_PROVIDER,
    ) -> None:
        if structured not in STRUCTURED_MODES:
            raise AgentError(f"structured output must be one of {', '.join(STRUCTURED_MODES)}, not {structured!r}")
        self.structured = structured
        self._send_schema = structured != "off"  # `auto` turns it off for the rest of the run once refused
        self._dialects = list(SCHEMA_DIALECTS)  # the ways of sending the schema not yet refused, tried in order
        self.transcript_notes: list[str] = []  # said once in the run's transcript (the fallback to plain text)
        self.model = model
        self.name = f"llm:{model}"
        self.temperature = temperature
        self.max_tokens = max_tokens
        self.timeout_s = positive_seconds(timeout_s, "the LLM timeout")
        self.attempt_timeout_s = (
            None if attempt_timeout_s is None else positive_seconds(attempt_timeout_s, "the LLM attempt timeout")
        )
        self.api_key_env = api_key_env
        self.policy = RetryPolicy(max_retries=max_retries, backoff_s=backoff_s, max_backoff_s=max_backoff_s)
        self._server = connect(base_url, api_key_env, provider)
        self.base_url = self._server.url  # without user:password@
        self.redactor = self._server.redactor
        self._sleep = sleep
        self.calls: list[dict[str, Any]] = []
        self.prompt = _prompt_setting(prompt)
        if hint not in HINT_MODES:
            raise AgentError(f"the reading hint must be one of {', '.join(HINT_MODES)}, not {hint!r}")
        self.hint = hint
        self._catalogue = catalogue  # the offline reading's (None: the default catalogue)
        self._hints: dict[tuple[str, str], Hint] = {}  # (prompt, support) -> the offline reading's draft
        self.prompt_decision: sizing.PromptDecision | None = None  # made at the first request of the run
        self._reply_tokens: int | None = None  # max_tokens sized for the chat `propose` is sending
        self._in_reply = False  # within `propose`
        self._round_ends: float | None = None  # monotonic deadline of the reply `propose` is making
        # sent with every request until the server refuses a field (then without it for the rest of the run)
        self._stream_fields: dict[str, Any] = (
            {"stream": True, "stream_options": {"include_usage": True}} if stream else {}
        )
        # hears the number of content chunks (about tokens) of the reply arriving, at most ~10 times a second
        self.on_tokens: Callable[[int], None] | None = None

    def propose(self, context: AgentContext) -> str:
        """The model's reply to the conversation built from `context` (unparsed): with structured output, a program
        in the object form the server's JSON Schema enforces; in plain text once a server refused it (`auto`)."""
        self._in_reply = True  # every request of this reply shares `timeout_s` (`_time_left`)
        try:
            reply = self._in_a_dialect(lambda: self._structured_reply(context))
            if reply is not None:
                return reply
            return self.complete(self._chat(context), request=context.request, seed=_request_seed(context))
        finally:
            self._in_reply, self._round_ends = False, None

    def reply_with_schema(self, chat: list[dict[str, Any]], schema: dict[str, Any], request: str, seed: int) -> str:
        """One reply to `chat` under a JSON Schema of the caller's (a scene graph's), in the first dialect the server
        takes, in plain text once it refused them all (`auto`)."""
        reply = self._in_a_dialect(
            lambda: self.complete(chat, request=request, schema=response_format(self._dialects[0], schema), seed=seed)
        )
        return reply if reply is not None else self.complete(chat, request=request, seed=seed)

    def _in_a_dialect(self, send: Callable[[], str]) -> str | None:
        """`send()`'s reply, tried in each schema dialect not yet refused (`send` reads `_dialects[0]`); None when
        structured output is off or the server refused every dialect (`auto`: noted once, plain text from then on)."""
        while self._send_schema:
            try:
                return send()
            except LLMRequestError as exc:
                if not refuses_structured_output(exc):
                    raise
                self._dialects.pop(0)
                if not self._dialects:
                    self._structured_refused(exc)
        return None

    def _structured_reply(self, context: AgentContext) -> str:
        chat = self._chat(context, structured=True)
        if self._guided():
            limit = None if is_local_server(self.base_url) else OPENAI_MAX_ENUM_VALUES
            expected = sizing.expected_objects(context)
            least = self._least_objects(context, chat)
            return two_step_reply(chat, context, self._step_sender(context), max(expected, least), limit, least)
        schema = response_format(self._dialects[0])
        return self.complete(chat, request=context.request, schema=schema, seed=_request_seed(context))

    def _least_objects(self, context: AgentContext, chat: list[dict[str, Any]]) -> int:
        """How many objects a guided first round must list: as many as the draft the model was shown (small models
        otherwise stop early), no more than the objects step's reply can hold in what the server's context leaves."""
        if context.request != "create":
            return 0
        least = self._hint_for(context, "compact").objects
        context_tokens = self.prompt_decision.context_tokens if self.prompt_decision else None
        room = sizing.fit_reply_tokens(sizing.MAX_REPLY_TOKENS, chat, context_tokens)
        return max(0, min(least, (room - OBJECTS_REPLY_BASE_TOKENS) // (2 * OBJECT_LIST_TOKENS)))

    def _structured_refused(self, exc: LLMRequestError) -> None:
        """`on`: a clear error; `auto`: plain text for the rest of the run, noted once."""
        if self.structured == "on":
            raise LLMRequestError(
                f"{exc} (the server refused structured output, response_format json_schema; "
                "run with --structured auto or off)",
                exc.status,
            ) from None
        self._send_schema = False
        note = f"structured output refused by the server, falling back to plain text: {exc}"
        self.transcript_notes.append(note)
        log.warning("%s", note)

    def _guided(self) -> bool:
        """Whether rounds go in two guided steps (agent/guided.py): with the compact prompt, for small models."""
        return self.prompt_decision is not None and self.prompt_decision.style == "compact"

    def _step_sender(self, context: AgentContext) -> Send:
        """Sends one step of a guided round: its schema in the server's dialect, its own token budget (within what
        the server's context leaves), each step with its own seed."""

        def send(chat: list[dict[str, Any]], schema: dict[str, Any], tokens: int) -> str:
            context_tokens = self.prompt_decision.context_tokens if self.prompt_decision else None
            self._reply_tokens = sizing.fit_reply_tokens(tokens, chat, context_tokens)
            seed = _request_seed(context) + len(self.calls)
            return self.complete(
                chat, request=context.request, schema=response_format(self._dialects[0], schema), seed=seed
            )

        return send

    def complete(
        self,
        chat: list[dict[str, Any]],
        request: str = "",
        *,
        schema: dict[str, Any] | None = None,
        seed: int | None = None,
    ) -> str:
        """Send one chat and return the reply text (secrets removed); record the exchange in `calls`. `schema` is
        the request's `response_format` (a program's JSON Schema); `seed` makes sampling repeatable where the
        server honours it."""
        body: dict[str, Any] = {"model": self.model, "messages": chat}
        if schema is not None:
            body["response_format"] = schema
        if seed is not None:
            body["seed"] = seed
        if self.temperature is not None:
            body["temperature"] = self.temperature
        max_tokens = self.max_tokens if self.max_tokens is not None else self._reply_tokens
        if max_tokens is not None:
            body["max_tokens"] = max_tokens
        record: dict[str, Any] = {
            "base_url": self.base_url,
            "request_kind": request,
            "request": self.redactor.data(body),
            "attempts": [],
            "response": None,
            "response_chars": None,
            "finish_reason": None,
            "usage": None,
            "error": None,
        }
        self.calls.append(record)
        label = f"LLM {self.model} at {self.base_url}"
        start = time.perf_counter()
        try:
            response = self._send(body, label, record["attempts"])
        except LLMRequestError as exc:
            record["error"] = str(exc)
            raise
        finally:
            record["duration_s"] = round(time.perf_counter() - start, 3)
        text, finish = reply_text(response)
        text = self._server.scrub(text)
        record.update(
            response=self.redactor.text(clip_text(text, MAX_RECORDED_CHARS, "reply")),
            response_chars=len(text),
            finish_reason=finish,
            usage=usage_of(response),
        )
        if not text:
            log.warning("%s: the reply holds no text (finish reason %s)", label, finish)
        return text

    def _send(self, body: dict[str, Any], label: str, attempts: list[dict[str, Any]]) -> dict[str, Any]:
        """The chat completion for `body`, streamed unless the server refused it (asked again without the field it
        named, and never with it again in this run)."""
        while True:
            try:
                return chat_completion(
                    self._server,
                    {**body, **self._stream_fields},
                    policy=self.policy,
                    timeout_s=self._time_left(label),
                    label=label,
                    attempts=attempts,
                    sleep=self._sleep,
                    attempt_timeout_s=self.attempt_timeout_s,
                    on_chunks=self.on_tokens,
                )
            except LLMRequestError as exc:
                field = refuses_streaming(exc, label) if self._stream_fields else None
                if field is None:
                    raise
                self._streaming_refused(field, exc)

    def _time_left(self, label: str) -> float:
        """This request's wall-clock limit: `timeout_s`, and no more than what is left of the reply's (a guided reply
        makes two requests)."""
        if not self._in_reply:
            return self.timeout_s
        if self._round_ends is None:  # the reply's first request: its time starts now
            self._round_ends = time.monotonic() + self.timeout_s
            return self.timeout_s
        left = min(self.timeout_s, self._round_ends - time.monotonic())
        if left <= 0:
            raise LLMRequestError(f"{label}: no time left for this request within {self.timeout_s:g} s")
        return left

    def _streaming_refused(self, field: str, exc: LLMRequestError) -> None:
        only_options = field == "stream_options" and "stream_options" in self._stream_fields
        dropped = ["stream_options"] if only_options else list(self._stream_fields)  # so this loop ends
        for name in dropped:
            self._stream_fields.pop(name, None)
        note = f"{field} refused by the server, sending requests without {' and '.join(dropped)}: {exc}"
        self.transcript_notes.append(note)
        log.warning("%s", note)

    def _chat(self, context: AgentContext, structured: bool = False) -> list[dict[str, Any]]:
        """The conversation for `context` with the system prompt that fits this server, and the `max_tokens` its
        program needs. The prompt is chosen (and the server's context probed) once per run, at the first request."""
        if self.prompt_decision is None:
            self.prompt_decision = self._decide_prompt()
        decision = self.prompt_decision
        hint = self._hint_for(context, decision.style)
        chat = build_messages(context, decision.style, structured, hint.text)
        self._reply_tokens = sizing.reply_token_budget(context, chat, decision.context_tokens, hint.objects)
        return chat

    def _hint_for(self, context: AgentContext, style: str) -> Hint:
        """The offline reading's draft objects for this request, when this run gives one (made once per request)."""
        if not wants_hint(self.hint, style):
            return Hint()
        key = (context.prompt, context.support.model_dump_json())
        if key not in self._hints:
            if self._in_reply and self._round_ends is None:  # making the draft counts against the reply's limit
                self._round_ends = time.monotonic() + self.timeout_s
            hint = self._hints[key] = reading_hint(context, self._catalogue)
            if hint.objects:
                self.transcript_notes.append(f"the offline reading's {hint.objects} objects were shown to the model")
        return self._hints[key]

    def _decide_prompt(self) -> sizing.PromptDecision:
        probed = (
            probe_context_tokens(self.base_url, self.model, self._server.api_key)
            if self.max_tokens is None or self.prompt == "auto"
            else None
        )
        decision = sizing.decide_prompt(self.prompt, self.base_url, probed)
        log.info("system prompt: %s (%s)", decision.style, decision.reason)
        self.transcript_notes.append(prompt_note(decision))
        return decision

    def served_models(self, timeout_s: float = 10.0) -> list[str]:
        """The model ids the server lists (GET /models), to find a dead server or a refused key up front.

        Raises `LLMRequestError` when nobody answers in `timeout_s` or the key is refused; returns [] when the
        server answers but does not list its models (the endpoint is optional for some servers).
        """
        return self._server.served_models(timeout_s)
