"""The provider seam: a server that does not speak OpenAI's API plugs in by name, and the agent, its retries and its
deadline work through it as through the built-in OpenAI-compatible client."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest
from typer.testing import CliRunner

from physcensis.api import generate
from physcensis.cli.app import app
from physcensis.errors import AgentError
from physcensis.llm.client import ChatServer, RetryPolicy, chat_completion
from physcensis.llm.provider import AttemptFailure
from physcensis.llm.providers import PROVIDERS, connect, register_provider
from physcensis.redaction import Redactor
from physcensis.scene import Support

PROGRAM = '[["mug_0", "a white mug"], ["mug_0", "PLACE-ANYWHERE", "root", {}]]'


class Busy(Exception):
    """The toy server's own "try later"."""


class Refused(Exception):
    """The toy server's own "no"."""


class ToyProvider:
    """A provider with its own API: it takes the prompt text alone and answers a string, or raises its own errors."""

    def __init__(self, base_url: str | None, api_key_env: str, script: list[object]) -> None:
        self.url = base_url or "toy://local"
        self.api_key_env = api_key_env
        self.redactor = Redactor()
        self.script = script  # what each attempt does: a reply, or an exception to raise
        self.asked: list[str] = []

    @property
    def api_key(self) -> str | None:
        return None

    def scrub(self, text: str) -> str:
        return text

    def attempt(self, request: dict[str, Any], seconds: float, on_chunks: Callable[[int], None] | None) -> dict:
        self.asked.append(request["messages"][-1]["content"])
        step = self.script.pop(0)
        if isinstance(step, Exception):
            raise step
        return {"choices": [{"index": 0, "message": {"role": "assistant", "content": step}, "finish_reason": "stop"}]}

    def failure(self, exc: Exception) -> AttemptFailure | None:
        if isinstance(exc, Busy):
            return AttemptFailure("the toy server is busy", retryable=True, retry_after_s=0.0)
        if isinstance(exc, Refused):
            return AttemptFailure("the toy server refused", status=403, hint=" (ask the toy's owner)")
        return None

    def served_models(self, timeout_s: float) -> list[str]:
        return ["toy-model"]

    def close(self) -> None:
        pass


@pytest.fixture
def toy(monkeypatch: pytest.MonkeyPatch) -> list[ToyProvider]:
    """Registers the toy provider as "toy" for one test; the list holds the instances made."""
    made: list[ToyProvider] = []
    script: list[object] = []

    def factory(base_url: str | None, api_key_env: str) -> ToyProvider:
        made.append(ToyProvider(base_url, api_key_env, script))
        return made[-1]

    monkeypatch.setitem(PROVIDERS, "toy", factory)
    made.append(ToyProvider(None, "", script))  # made[0] only carries the shared script
    return made


def test_a_registered_provider_writes_the_scene(toy: list[ToyProvider]) -> None:
    toy[0].script.extend([Busy(), PROGRAM])  # a busy server first: retried through the provider's own reading
    generated = generate(
        "a white mug on a small table",
        support=Support(kind="table", size=(0.6, 0.6)),
        llm="toy-model",
        provider="toy",
        hint="off",
        structured="off",
        stream=False,
    )
    assert generated.solution is not None and generated.solution.ok
    assert [o.asset for o in generated.solution.scene.placed] and generated.solution.scene.placed[0].id == "mug_0"
    server = toy[-1]
    assert len(server.asked) == 2 and "mug" in server.asked[0]


def test_a_final_failure_is_one_line_with_the_providers_hint(toy: list[ToyProvider]) -> None:
    toy[0].script.append(Refused())
    server = connect("toy://x", "TOY_KEY", "toy")
    with pytest.raises(AgentError, match=r"^ask toy: the toy server refused \(ask the toy's owner\)$"):
        chat_completion(
            server,
            {"messages": [{"role": "user", "content": "hi"}]},
            policy=RetryPolicy(),
            timeout_s=5,
            label="ask toy",
        )


def test_an_exception_the_provider_does_not_know_propagates(toy: list[ToyProvider]) -> None:
    toy[0].script.append(KeyError("a bug"))
    with pytest.raises(KeyError):
        chat_completion(
            connect(None, "", "toy"),
            {"messages": [{"role": "user", "content": "hi"}]},
            policy=RetryPolicy(),
            timeout_s=5,
            label="x",
        )


def test_openai_is_the_default_and_unknown_names_are_refused() -> None:
    assert isinstance(connect("http://127.0.0.1:9/v1"), ChatServer)
    with pytest.raises(AgentError, match=r"no chat provider named 'anthropicx' \(known: .*openai"):
        connect(None, provider="anthropicx")
    with pytest.raises(ValueError, match="already registered"):
        register_provider("openai", ChatServer)


def test_the_command_line_names_an_unknown_provider() -> None:
    args = ["generate", "a mug", "--llm", "m", "--llm-provider", "nope", "--export", "none", "--out", "/nonexistent/x"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code != 0
    assert "no chat provider named 'nope'" in result.output and "Traceback" not in result.output
