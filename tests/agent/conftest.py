"""Fixtures for agent tests: a scrubbed environment, a secret key and the local fake OpenAI server."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

import pytest

from physcensis.agent.base import AgentContext
from physcensis.scene import Support

from .fake_server import FakeOpenAI, use_loopback_only

SECRET_KEY = "sk-test-9f8e7d6c5b4a-never-print-me"


@pytest.fixture(autouse=True)
def _llm_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    use_loopback_only(monkeypatch, SECRET_KEY)


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
