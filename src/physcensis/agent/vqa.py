"""VQA score: how sure a vision model is that a render shows the prompt.

The score is P("Yes") to "Does this image show {prompt}? Answer Yes or No.",
read from the first answer token's log-probabilities where the server returns
them (yes-variants summed and normalised against no-variants), otherwise 1.0 or
0.0 from the answer text. Failures return None and are logged: a missing score
must never stop a scene from being written.
"""

from __future__ import annotations

import base64
import logging
import math
import time
from collections.abc import Callable, Iterable
from typing import Any

from physcensis.agent.llm import LLMRequestError, RetryPolicy, chat_completion, make_client, reply_text

log = logging.getLogger(__name__)

YES_WORDS = frozenset({"yes"})
NO_WORDS = frozenset({"no"})
TOP_LOGPROBS = 5
_STRIP = " \t\n\r.,;:!?\"'`*()[]"


def question(prompt: str) -> str:
    return f"Does this image show {prompt.strip().rstrip('.!?') or 'anything'}? Answer Yes or No."


def _word(token: str) -> str:
    return token.strip(_STRIP).lower()


def yes_probability(candidates: Iterable[tuple[str, float]]) -> float | None:
    """P(yes) / (P(yes) + P(no)) over (token, logprob) pairs; None when neither appears.

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
    return yes / (yes + no)


def _first_token_candidates(response: Any) -> list[tuple[str, float]]:
    """(token, logprob) of the first generated token and its alternatives, if the server sent them."""
    choices = getattr(response, "choices", None) or []
    logprobs = getattr(choices[0], "logprobs", None) if choices else None
    content = getattr(logprobs, "content", None) or []
    if not content:
        return []
    first = content[0]
    pairs = [(getattr(first, "token", None), getattr(first, "logprob", None))]
    alternatives = getattr(first, "top_logprobs", None) or []
    pairs += [(getattr(t, "token", None), getattr(t, "logprob", None)) for t in alternatives]
    return [(t, lp) for t, lp in pairs if isinstance(t, str) and isinstance(lp, int | float)]


def _answer_score(text: str) -> float | None:
    words = text.strip().split()
    word = _word(words[0]) if words else ""
    if word in YES_WORDS:
        return 1.0
    if word in NO_WORDS:
        return 0.0
    return None


def vqa_score(
    image_png: bytes,
    prompt: str,
    model: str,
    base_url: str | None = None,
    *,
    api_key_env: str = "OPENAI_API_KEY",
    timeout_s: float = 60.0,
    max_retries: int = 2,
    backoff_s: float = 1.0,
    calls: list[dict[str, Any]] | None = None,
    sleep: Callable[[float], None] = time.sleep,
) -> float | None:
    """P(yes) that `image_png` shows `prompt`, from a vision chat model; None when it cannot be had.

    When the server refuses log-probabilities (HTTP 400), the question is asked once more
    without them and the answer text decides. `calls`, if given, receives a record of each
    request (the image replaced by its size) and reply.
    """
    client, secret = make_client(base_url, api_key_env, timeout_s)
    url = "data:image/png;base64," + base64.b64encode(image_png).decode("ascii")
    ask = question(prompt)
    content = [{"type": "text", "text": ask}, {"type": "image_url", "image_url": {"url": url}}]
    body: dict[str, Any] = {
        "model": model, "messages": [{"role": "user", "content": content}],
        "temperature": 0.0, "max_tokens": 1, "logprobs": True, "top_logprobs": TOP_LOGPROBS,
    }
    policy = RetryPolicy(max_retries=max_retries, backoff_s=backoff_s)
    label = f"VQA {model} at {client.base_url}"
    for with_logprobs in (True, False):
        if not with_logprobs:
            body = {k: v for k, v in body.items() if k not in ("logprobs", "top_logprobs", "max_tokens")}
        record: dict[str, Any] = {"question": ask, "image_bytes": len(image_png), "model": model,
                                  "logprobs": with_logprobs, "attempts": [], "answer": None, "score": None}
        if calls is not None:
            calls.append(record)
        try:
            response = chat_completion(client, body, policy=policy, secret=secret, label=label,
                                       attempts=record["attempts"], sleep=sleep, key_env=api_key_env)
        except LLMRequestError as exc:
            record["error"] = str(exc)
            if with_logprobs and exc.status == 400:
                log.info("%s refused log-probabilities; asking for the answer text instead", label)
                continue
            log.warning("VQA score unavailable: %s", exc)
            return None
        text, _ = reply_text(response)
        score = yes_probability(_first_token_candidates(response))
        if score is None:
            score = _answer_score(text)
        record.update(answer=text, score=score)
        if score is None:
            log.warning("%s: could not read yes or no from the answer %r", label, text[:40])
        return score
    return None
