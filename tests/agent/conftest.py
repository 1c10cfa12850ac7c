"""Fixtures for agent tests: a scrubbed environment, a secret key and the local fake OpenAI server."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

import pytest

from physcensis.agent.base import AgentContext
from physcensis.scene import Support

from .fake_server import FakeOpenAI

SECRET_KEY = "sk-test-9f8e7d6c5b4a-never-print-me"
_PROXY_VARS = ("HTTP_PROXY", "HTTPS_PROXY", "ALL_PROXY", "http_proxy", "https_proxy", "all_proxy")


@pytest.fixture(autouse=True)
def _llm_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    """Only loopback, only our key: no proxies, no base URL from the developer's shell."""
    for name in _PROXY_VARS:
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("NO_PROXY", "127.0.0.1,localhost")
    monkeypatch.delenv("OPENAI_BASE_URL", raising=False)
    monkeypatch.setenv("OPENAI_API_KEY", SECRET_KEY)


@pytest.fixture
def fake_openai() -> Iterator[Callable[..., FakeOpenAI]]:
    """A factory of started fake servers (same arguments as FakeOpenAI), all closed after the test."""
    servers: list[FakeOpenAI] = []

    def start(*replies: Any, **options: Any) -> FakeOpenAI:
        server = FakeOpenAI(list(replies), **options).start()
        servers.append(server)
        return server

    yield start
    for server in servers:
        server.close()


@pytest.fixture
def desk_context() -> AgentContext:
    return AgentContext(
        prompt="a small desk with a laptop and a mug",
        support=Support(kind="table", size=(0.7, 1.4)),
        vocabulary=("laptop", "mug", "notebook", "pen"),
    )
