"""`--llm-writes graph`: a chat model reads the prompt into a scene graph (agent/graph.py); the offline planner writes,
repairs and varies the programs from that graph.

A graph is a few hundred tokens where a program with its placements is over a thousand: a small local model writes
it in a fraction of the time, and the solver's feedback is answered by the planner's own repairs. The model is asked
once per prompt; a graph that does not check is sent back with what is wrong (up to GRAPH_ATTEMPTS replies), and
when none checks the offline reading's graph stands in, said in the transcript and the report.
"""

from __future__ import annotations

import json
import logging
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from physcensis.agent.graph import (
    GraphError,
    GraphReading,
    SceneGraph,
    graph_of,
    graph_schema,
    parse_graph,
    request_of,
)
from physcensis.agent.hint import HINT_MODES
from physcensis.agent.planner import OfflinePlanner
from physcensis.agent.prompt import clip_text
from physcensis.agent.reading import SceneRequest, read_prompt
from physcensis.agent.variety import DEFAULT_VARIETY, Variety
from physcensis.errors import AgentError
from physcensis.llm.server import is_local_server

if TYPE_CHECKING:
    from physcensis.agent.llm import LLMAgent
    from physcensis.assets.catalogue import Catalogue
    from physcensis.redaction import Redactor

log = logging.getLogger(__name__)

GRAPH_ATTEMPTS = 3
GRAPH_TOKENS_BASE = 120
GRAPH_TOKENS_PER_OBJECT = 90
GRAPH_OBJECTS_EXPECTED = 12  # the reply's token budget covers at least this many objects
MAX_GRAPH_TOKENS = 3000

SYSTEM = """You read a request for a 3-D scene and write its scene graph: one JSON object, nothing else.

{"objects": [...], "diners": 0, "style": "tidy"}

Each object is {"id", "name", "count", "words", "arrangement", "groups", "where", "relation", "of"}:
- id: a short unique name for it; name: the noun, singular ("mug", "wine glass", "teddy bear");
- count: how many the request asks for; 0 when it leaves the number open ("some apples", "a few books");
- words: the request's adjectives for it (colour, material, size), else [];
- arrangement: "stack", "pile", "row", "column", "scatter" or "none"; groups: how many stacks or rows (0: not said);
- where: its place on the support as the viewer sees it: "left", "right", "back", "front", "centre", "back left", \
"front right corner", "corner", "end", "edge" and the like, or "" for anywhere (never the support's name);
- relation and of: how it stands to other objects, by their ids: "in", "on" (resting in or on it), "in each", \
"on each" (count is per target), "in its own", "on its own" (each on one of the target's copies), "left of", \
"right of", "in front of", "behind", "beside", "on either side of", "at either end of", "between" (two ids, or one \
id of two or more objects), "around", or "none" with of [].
Left, right, in front of and behind are as seen by the viewer facing the support.
List every kind of thing the request names once, with its count. Never list the support the scene stands on (the \
table, desk, shelf, counter, box or floor). A table set for people is "diners": their number, with no plates or \
cutlery listed. style: "messy" for a messy or cluttered scene, "dense" for as many things as fit, "precarious" \
for things balanced on an edge, "stable" when they must stand securely, else "tidy".

Example. Request: a blue bowl of three apples on the left, two mugs in front of it and some pens
{"objects": [{"id": "bowl", "name": "bowl", "count": 1, "words": ["blue"], "arrangement": "none", "groups": 0, \
"where": "left", "relation": "none", "of": []}, {"id": "apple", "name": "apple", "count": 3, "words": [], \
"arrangement": "none", "groups": 0, "where": "", "relation": "in", "of": ["bowl"]}, {"id": "mug", "name": "mug", \
"count": 2, "words": [], "arrangement": "none", "groups": 0, "where": "", "relation": "in front of", "of": \
["bowl"]}, {"id": "pen", "name": "pen", "count": 0, "words": [], "arrangement": "none", "groups": 0, "where": "", \
"relation": "none", "of": []}], "diners": 0, "style": "tidy"}"""


class GraphPlanner(OfflinePlanner):
    """The offline planner reading prompts through a chat model's scene graph (see the module's doc)."""

    def __init__(
        self,
        llm: LLMAgent,
        catalogue: Catalogue | None = None,
        seed: int = 0,
        variety: str | Variety = DEFAULT_VARIETY,
        context: bool | None = None,
        hint: str = "auto",
    ) -> None:
        super().__init__(catalogue, seed, variety, context)
        if hint not in HINT_MODES:
            raise AgentError(f"the reading hint must be one of {', '.join(HINT_MODES)}, not {hint!r}")
        self.llm = llm
        self.name = f"llm-graph:{llm.model}"
        self.hint = hint
        self._graphs: dict[str, GraphReading] = {}

    # what the loop and the API read of an LLM agent
    @property
    def calls(self) -> list[dict[str, Any]]:
        return self.llm.calls

    @property
    def redactor(self) -> Redactor:
        return self.llm.redactor

    @property
    def on_tokens(self) -> Callable[[int], None] | None:
        return self.llm.on_tokens

    @on_tokens.setter
    def on_tokens(self, hear: Callable[[int], None] | None) -> None:
        self.llm.on_tokens = hear

    @property
    def transcript_notes(self) -> list[str]:
        return [*self.llm.transcript_notes, *self.state.notes]

    @transcript_notes.setter
    def transcript_notes(self, notes: list[str]) -> None:
        self.state.notes = notes

    def read(self, prompt: str) -> SceneRequest:
        return request_of(self.graph_reading(prompt).graph, self.lexicon, prompt)

    def graph_reading(self, prompt: str) -> GraphReading:
        """The graph of `prompt` (the model is asked once per prompt)."""
        if prompt not in self._graphs:
            self._graphs[prompt] = self._ask(prompt)
        return self._graphs[prompt]

    def _ask(self, prompt: str) -> GraphReading:
        offline = graph_of(read_prompt(prompt, self.lexicon))  # the draft, and what stands in when no graph checks
        draft = offline if self._shows_draft() else None
        chat = graph_messages(prompt, draft)
        expected = max(GRAPH_OBJECTS_EXPECTED, len(draft.objects) if draft else 0)
        budget = GRAPH_TOKENS_BASE + GRAPH_TOKENS_PER_OBJECT * expected
        problem = ""
        for attempt in range(GRAPH_ATTEMPTS):
            text = self._send(chat, min(budget, MAX_GRAPH_TOKENS), attempt)
            try:
                graph = parse_graph(text)
            except GraphError as exc:
                problem = str(exc)
                chat = [
                    *chat,
                    {"role": "assistant", "content": clip_text(text, 4000, "reply")},
                    {"role": "user", "content": f"That graph cannot be used: {problem}. Send the whole graph again."},
                ]
                continue
            self.state.note(f"scene graph from the model: {_listed(graph)}")
            return GraphReading(graph, "model")
        why = f"the model sent no usable scene graph in {GRAPH_ATTEMPTS} replies (last: {problem})"
        self.state.note(f"{why}; the offline reading's graph stands in")
        log.warning("%s; the offline reading's graph stands in", why)
        return GraphReading(offline, "offline reading", why)

    def graph_requests(self) -> list[dict[str, Any]]:
        """The transcript's rows for the graph requests: seconds, tokens and the reply of each."""
        rows = []
        for call in (c for c in self.llm.calls if c.get("request_kind") == "graph"):
            row = {"graph_request": call.get("response"), "seconds": call.get("duration_s"), "usage": call.get("usage")}
            rows.append(row | ({"error": call["error"]} if call.get("error") else {}))
        return rows

    def _shows_draft(self) -> bool:
        """The offline reading's graph as a draft: `auto` for local servers (small models), `on` always."""
        return self.hint == "on" or (self.hint == "auto" and is_local_server(self.llm.base_url))

    def _send(self, chat: list[dict[str, Any]], tokens: int, attempt: int) -> str:
        """The model's reply under the graph's JSON Schema, within `tokens` unless the run set `max_tokens`."""
        wanted = self.llm.max_tokens
        self.llm.max_tokens = wanted if wanted is not None else tokens
        try:
            return self.llm.reply_with_schema(chat, graph_schema(), "graph", (self.seed * 1009 + attempt) % 2**31)
        finally:
            self.llm.max_tokens = wanted


def graph_messages(prompt: str, draft: SceneGraph | None = None) -> list[dict[str, Any]]:
    """The chat asking for the graph of `prompt`, with the offline reading's graph as a draft when given."""
    user = f"Request: {prompt}"
    if draft is not None:
        user += (
            "\nA rule-based reader's draft of the graph (it can be wrong: keep what is right, correct what is not, "
            f"add what it missed):\n{_compact(draft)}"
        )
    return [{"role": "system", "content": SYSTEM}, {"role": "user", "content": user}]


def _listed(graph: SceneGraph) -> str:
    """ "bowl, apple ×3 in bowl, mug ×2 right of bowl" """
    parts = []
    for o in graph.objects:
        count = "" if o.count == 1 else " ×some" if o.count == 0 else f" ×{o.count}"
        relation = "" if o.relation == "none" else f" {o.relation} {' and '.join(o.of)}"
        parts.append(f"{o.name}{count}{relation}")
    diners = f"; set for {graph.diners}" if graph.diners else ""
    return (", ".join(parts) or "no objects") + diners


def _compact(graph: SceneGraph) -> str:
    return json.dumps(graph.to_json(), separators=(", ", ": "))
