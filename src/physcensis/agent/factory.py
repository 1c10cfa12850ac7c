"""The one place a run's settings become an agent: the offline planner, or an LLM agent on an OpenAI-compatible
server. The API, the batch workers, the batch's server check and the evaluation's methods all build theirs here."""

from __future__ import annotations

from typing import TYPE_CHECKING

from physcensis.agent.base import Agent
from physcensis.agent.planner import OfflinePlanner
from physcensis.agent.variety import parse_variety
from physcensis.settings import ModelSettings, RunSettings

if TYPE_CHECKING:
    from physcensis.agent.llm import LLMAgent
    from physcensis.assets.catalogue import Catalogue


def make_agent(settings: RunSettings, catalogue: Catalogue, seed: int = 0) -> Agent:
    """The agent `settings` ask for: an LLM agent when they name an LLM (writing programs, or with `llm_writes="graph"`
    the scene graph the seeded offline planner plans from), else the seeded offline planner."""
    models, draws = settings.models, settings.draws
    variety = parse_variety(draws.variety)
    if models.llm and models.llm_writes == "graph":
        from physcensis.agent.graph_planner import GraphPlanner

        llm = llm_agent(models, catalogue)
        return GraphPlanner(llm, catalogue, seed=seed, variety=variety, context=draws.context, hint=models.hint)
    if models.llm:
        return llm_agent(models, catalogue)
    return OfflinePlanner(catalogue, seed=seed, variety=variety, context=draws.context)


def llm_agent(models: ModelSettings, catalogue: Catalogue | None = None) -> LLMAgent:
    """An LLM agent on `models.llm` driven as `models` say (the `openai` client is imported only here)."""
    from physcensis.agent.llm import LLMAgent

    if not models.llm:
        raise ValueError("llm_agent needs settings that name an LLM")
    return LLMAgent(
        models.llm,
        base_url=models.base_url,
        api_key_env=models.api_key_env,
        provider=models.provider,
        temperature=models.temperature,
        timeout_s=models.llm_timeout_s,
        structured=models.structured,
        prompt=models.prompt_style,
        stream=models.stream,
        hint=models.hint,
        catalogue=catalogue,
    )
