"""Talking to models: one client for OpenAI-compatible chat servers (`client.py`), used by the LLM agent, the vision
critic, VQA and the robot's verifier. It sits below `agent/` and `robot/`: neither reaches into the other for it."""

from __future__ import annotations

from physcensis.llm.client import (
    ChatServer,
    LLMRequestError,
    RetryPolicy,
    chat_completion,
    positive_seconds,
    reply_text,
)

__all__ = ["ChatServer", "LLMRequestError", "RetryPolicy", "chat_completion", "positive_seconds", "reply_text"]
