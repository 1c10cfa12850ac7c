"""What a chat provider is to the rest of the package: the seam a server that does not speak OpenAI's API plugs into.

`chat_completion` (client.py) owns the deadline, the retries and the waits; a provider makes one attempt and says
how a failed attempt reads. Replies come back in the shape of an OpenAI chat completion (`choices[0].message`,
`usage`), whatever the provider's own wire format, so the agent, the critic, VQA and the verifier read them alike.
The OpenAI-compatible server (`ChatServer`) is the built-in provider; `llm/providers.py` names them.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Protocol

from physcensis.redaction import Redactor


@dataclass(frozen=True)
class AttemptFailure:
    """How one failed attempt reads: a secret-free line, the HTTP status if any, and whether to try again."""

    text: str
    status: int | None = None
    retryable: bool = False
    retry_after_s: float | None = None  # the server's own wish, when it said
    timed_out: bool = False  # the provider's own per-attempt timer fired
    hint: str = ""  # appended to a final error (" (check the API key in OPENAI_API_KEY)")


class ChatProvider(Protocol):
    """One model server."""

    url: str  # for messages: without credentials
    api_key_env: str  # where its key was read from
    redactor: Redactor  # cleans everything recorded or printed of its secrets

    @property
    def api_key(self) -> str | None:
        """The key it sends (None: none)."""

    def scrub(self, text: str) -> str:
        """`text` without the literal secrets (a model's reply, before it is parsed)."""

    def attempt(
        self, request: dict[str, Any], seconds: float, on_chunks: Callable[[int], None] | None
    ) -> dict[str, Any]:
        """One try at the chat `request` (OpenAI's request JSON) within `seconds`: a chat completion's JSON, or an
        exception that `failure` reads."""

    def failure(self, exc: Exception) -> AttemptFailure | None:
        """How `exc`, raised by `attempt`, reads; None when it is not the provider's (it then propagates)."""

    def served_models(self, timeout_s: float) -> list[str]:
        """The model ids the server lists ([] when it does not list them); `LLMRequestError` when nobody answers
        or the key is refused."""

    def close(self) -> None: ...
