"""VQA score: how sure a vision model is that a render shows the prompt.

The score is the paper's: P("Yes") to "Does this image show {prompt}? Answer Yes
or No.", the probability of the first answer token being yes (its variants, " Yes",
"yes", summed), read from the log-probabilities where the server returns them;
otherwise 1.0 or 0.0 from the answer text. `normalised` scores P(yes) / (P(yes) +
P(no)) instead, which leaves out what the model puts on other first tokens (so it
reads higher than the paper's). Failures return None and are logged: a missing score
must never stop a scene from being written. Each question has a wall-clock
deadline (`timeout_s`, retries and their waits included), like the agent's requests.
"""

from __future__ import annotations

import base64
import logging
import math
import time
from collections.abc import Callable, Iterable
from typing import Any

from physcensis.agent.base import AgentError
from physcensis.llm.client import (
    LLMRequestError,
    RetryPolicy,
    chat_completion,
    positive_seconds,
    reply_text,
)
from physcensis.llm.provider import ChatProvider
from physcensis.llm.providers import connect
from physcensis.settings import API_KEY_ENV, DEFAULT_PROVIDER

log = logging.getLogger(__name__)

YES_WORDS = frozenset({"yes"})
NO_WORDS = frozenset({"no"})
TOP_LOGPROBS = 5
_STRIP = " \t\n\r.,;:!?\"'`*()[]"


def question(prompt: str) -> str:
    return f"Does this image show {prompt.strip().rstrip('.!?') or 'anything'}? Answer Yes or No."


def image_message(text: str, *images_png: bytes) -> dict[str, Any]:
    """A user chat message asking `text` about PNG images (sent inline as data URLs, in order)."""
    content: list[dict[str, Any]] = [{"type": "text", "text": text}]
    for png in images_png:
        url = "data:image/png;base64," + base64.b64encode(png).decode("ascii")
        content.append({"type": "image_url", "image_url": {"url": url}})
    return {"role": "user", "content": content}


def _word(token: str) -> str:
    return token.strip(_STRIP).lower()


def yes_probability(candidates: Iterable[tuple[str, float]], *, normalised: bool = False) -> float | None:
    """P(yes) over (token, logprob) pairs of the first token, or with `normalised` P(yes) / (P(yes) + P(no)); None
    when neither appears. A yes that is not among the returned tokens counts as 0: it is less likely than all of them.

    Pairs are deduplicated by token text, so the sampled token may be passed along with the top list.
    """
    seen: dict[str, float] = {}
    for token, logprob in candidates:
        if isinstance(token, str) and isinstance(logprob, int | float) and math.isfinite(logprob):
            seen.setdefault(token, float(logprob))
    yes = sum(math.exp(lp) for tok, lp in seen.items() if _word(tok) in YES_WORDS)
    no = sum(math.exp(lp) for tok, lp in seen.items() if _word(tok) in NO_WORDS)
    if yes + no <= 0.0:
        return None
    return yes / (yes + no) if normalised else min(1.0, yes)


def _first_token_candidates(response: dict[str, Any]) -> list[tuple[str, float]]:
    """(token, logprob) of the first generated token and its alternatives, if the server sent them."""
    logprobs = _field(response["choices"][0], "logprobs")
    content = _field(logprobs, "content")
    if not isinstance(content, list) or not content:
        return []
    first = content[0]
    pairs = [(_field(first, "token"), _field(first, "logprob"))]
    alternatives = _field(first, "top_logprobs")
    if isinstance(alternatives, list):
        pairs += [(_field(t, "token"), _field(t, "logprob")) for t in alternatives]
    return [(t, lp) for t, lp in pairs if isinstance(t, str) and isinstance(lp, int | float)]


def _field(value: Any, name: str) -> Any:
    return value.get(name) if isinstance(value, dict) else None


def read_yes_no(text: str) -> bool | None:
    """True for an answer that starts with 'yes', False for 'no', None for anything else."""
    words = text.strip().split()
    word = _word(words[0]) if words else ""
    return True if word in YES_WORDS else False if word in NO_WORDS else None


def _answer_score(text: str) -> float | None:
    answer = read_yes_no(text)
    return None if answer is None else float(answer)


def vqa_score(
    image_png: bytes,
    prompt: str,
    model: str,
    base_url: str | None = None,
    *,
    api_key_env: str = API_KEY_ENV,
    provider: str = DEFAULT_PROVIDER,
    timeout_s: float = 120.0,
    max_retries: int = 2,
    backoff_s: float = 1.0,
    calls: list[dict[str, Any]] | None = None,
    sleep: Callable[[float], None] = time.sleep,
    normalised: bool = False,
) -> float | None:
    """P(yes) that `image_png` shows `prompt`, from a vision chat model (`normalised`: against P(no)); None when it
    cannot be had.

    When the server refuses log-probabilities (HTTP 400), the question is asked once more
    without them and the answer text decides. Each question gets `timeout_s` of wall-clock time.
    `calls`, if given, receives a record of each request (the image replaced by its size) and reply.
    """
    try:
        timeout_s = positive_seconds(timeout_s, "the VQA timeout")
        server = connect(base_url, api_key_env, provider)
    except AgentError as exc:
        log.warning("VQA score unavailable: %s", exc)
        return None
    try:
        return _ask(
            server,
            image_png,
            prompt,
            model,
            RetryPolicy(max_retries=max_retries, backoff_s=backoff_s),
            timeout_s,
            calls,
            sleep,
            normalised,
        )
    finally:
        server.close()


def _ask(
    server: ChatProvider,
    image_png: bytes,
    prompt: str,
    model: str,
    policy: RetryPolicy,
    timeout_s: float,
    calls: list[dict[str, Any]] | None,
    sleep: Callable[[float], None],
    normalised: bool,
) -> float | None:
    ask = question(prompt)
    body: dict[str, Any] = {
        "model": model,
        "messages": [image_message(ask, image_png)],
        "temperature": 0.0,
        "max_tokens": 1,
        "logprobs": True,
        "top_logprobs": TOP_LOGPROBS,
    }
    label = f"VQA {model} at {server.url}"
    for with_logprobs in (True, False):
        if not with_logprobs:
            body = {k: v for k, v in body.items() if k not in ("logprobs", "top_logprobs", "max_tokens")}
        record: dict[str, Any] = {
            "question": ask,
            "image_bytes": len(image_png),
            "model": model,
            "logprobs": with_logprobs,
            "attempts": [],
            "scored": "normalised" if normalised else "p-yes",
            "answer": None,
            "score": None,
        }
        if calls is not None:
            calls.append(record)
        try:
            response = chat_completion(
                server, body, policy=policy, timeout_s=timeout_s, label=label, attempts=record["attempts"], sleep=sleep
            )
        except LLMRequestError as exc:
            record["error"] = str(exc)
            if with_logprobs and exc.status == 400:
                log.info("%s refused log-probabilities; asking for the answer text instead", label)
                continue
            log.warning("VQA score unavailable: %s", exc)
            return None
        text, _ = reply_text(response)
        text = server.redactor.text(server.scrub(text))
        score = yes_probability(_first_token_candidates(response), normalised=normalised)
        if score is None:
            score = _answer_score(text)
        record.update(answer=text, score=score)
        if score is None:
            log.warning("%s: could not read yes or no from the answer %r", label, text[:40])
        return score
    return None
