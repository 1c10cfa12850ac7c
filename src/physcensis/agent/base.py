"""What every agent sees and returns: the scene request, the history of rounds, and a program as text."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

from physcensis.errors import AgentError as AgentError  # defined below the agent: the chat client raises it
from physcensis.program.checker import DEFAULT_MAX_OBJECTS
from physcensis.scene import Support


@dataclass(frozen=True)
class Round:
    """One exchange: the program text an agent wrote and the feedback it got for it."""

    program_text: str
    feedback: str
    ok: bool = False  # the program solved without failures


@dataclass(frozen=True)
class AgentContext:
    prompt: str
    support: Support
    vocabulary: tuple[str, ...]  # asset categories the catalogue knows
    history: tuple[Round, ...] = ()
    # "create", "repair" (fix the last program), "enrich" (add objects around it) or "revise" (a vision model doubts
    # that the scene shows the request: change it)
    request: str = "create"
    notes: dict[str, str] = field(default_factory=dict)  # e.g. {"density": "as many as possible"}
    seed: int = 0  # the run's seed (an LLM agent derives each request's sampling seed from it)
    own_assets: tuple[tuple[str, str], ...] = ()  # (id, description) of the user library assets, for pinning
    max_objects: int = DEFAULT_MAX_OBJECTS  # the most objects a program may make (the run's --max-objects)


class Agent(Protocol):
    """Writes a predicate program for a scene; the loop parses, checks and solves it."""

    name: str

    def propose(self, context: AgentContext) -> str:
        """The program as text (JSON, or whatever an LLM writes: the parser is lenient)."""
        ...
