"""Agents that write predicate programs: the offline planner and any OpenAI-compatible LLM."""
