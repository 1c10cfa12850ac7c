"""The chat providers a run can name (`--llm-provider`, `ModelSettings.provider`): one factory each, keyed by name.

`openai` is every OpenAI-compatible server (OpenAI, vLLM, Ollama, llama.cpp server, LM Studio). A server with another
API plugs in with `register_provider(name, factory)`: the factory takes the base URL and the environment variable
holding the key, and returns a `ChatProvider` (llm/provider.py).
"""

from __future__ import annotations

from collections.abc import Callable

from physcensis.errors import AgentError
from physcensis.llm.client import ChatServer
from physcensis.llm.provider import ChatProvider
from physcensis.settings import API_KEY_ENV, DEFAULT_PROVIDER

ProviderFactory = Callable[[str | None, str], ChatProvider]

PROVIDERS: dict[str, ProviderFactory] = {DEFAULT_PROVIDER: ChatServer}


def register_provider(name: str, factory: ProviderFactory) -> None:
    """Make `name` a provider a run can choose; a name already taken is an error (providers are not replaced)."""
    if not name or name != name.strip():
        raise ValueError(f"a provider's name must be a non-empty word, not {name!r}")
    if name in PROVIDERS:
        raise ValueError(f"a chat provider named {name!r} is already registered")
    PROVIDERS[name] = factory


def connect(base_url: str | None, api_key_env: str = API_KEY_ENV, provider: str = DEFAULT_PROVIDER) -> ChatProvider:
    """The server at `base_url`, spoken to as `provider` says; an unknown provider is an `AgentError` naming the
    known ones."""
    factory = PROVIDERS.get(provider)
    if factory is None:
        raise AgentError(f"no chat provider named {provider!r} (known: {', '.join(sorted(PROVIDERS))})")
    return factory(base_url, api_key_env)
