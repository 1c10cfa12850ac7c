"""Fitting the conversation to the model: which system prompt to send, and how long a reply may be.

`--prompt auto` sends the compact prompt to local servers (small models run there) and to servers that report a
small context window (`physcensis.llm.server` asks), the full one otherwise. `max_tokens` is sized from the program
the request should produce, so a small model cannot ramble to the end of its context.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from physcensis.agent.base import AgentContext
from physcensis.agent.prompt import PROMPT_STYLES, estimate_tokens
from physcensis.agent.reading import NUMERALS
from physcensis.llm.server import is_local_server

PROMPT_CHOICES = ("auto", *PROMPT_STYLES)
SMALL_CONTEXT_TOKENS = 16_384  # below this the full prompt (~5,400 tokens) leaves too little room for the rounds

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
