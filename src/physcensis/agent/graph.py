"""The scene graph: what a prompt asks for, as data. The offline reading (agent/reading.py) and, with `--llm-writes
graph`, a chat model both produce one; the offline planner writes its programs from it.

A graph is a small JSON object a small model can write in a few hundred tokens:

    {"diners": 0, "style": "tidy",
     "objects": [{"id": "bowl", "name": "bowl", "count": 1, "words": ["blue"], "arrangement": "none",
                  "where": "left", "relation": "none", "of": []},
                 {"id": "apple", "name": "apple", "count": 3, "words": [], "arrangement": "none",
                  "where": "", "relation": "in", "of": ["bowl"]}]}

* `count` is how many the prompt asks for; 0 when it leaves the number open ("some apples"); with "in each" or "on
  each" it is the number per target ("a teacup on each saucer": 1).
* `relation` ties an object to others by id: in, on, in each, on each, in its own, on its own (each of these on a
  target of its own: "a mug and a glass, each on its own coaster"), left of, right of, in front of, behind, beside,
  on either side of, at either end of, between (two ids in `of`, or one naming two or more), around, or none.
  Left, right, in front of and behind are as seen by the viewer of the default render, the words' own frame
  (docs/DESIGN.md, "One viewpoint").
* `where` is a place on the support in the viewer's words: left, right, back, front, centre, corner and their
  combinations ("back left corner"), end, edge; "" for anywhere.
* `arrangement` is stack, pile, row, column, scatter or none (`groups`: how many stacks or rows, 0 when not
  said); `style` is tidy, messy, dense (as many as fit), precarious (balanced on edges) or stable; `diners` is
  how many people a table is set for.

`request_of` turns a graph into the planner's `SceneRequest`; `graph_of` the other way (the offline reading's graph,
saved in the report and shown to a model as a draft). `parse_graph` checks a model's reply and names what is wrong
and where, for the model to correct.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from typing import Any

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from physcensis.agent.reading import (
    ARRANGE_NOUNS,
    MOST,
    NOT_OBJECTS,
    TRAILING_UNITS,
    Lexicon,
    Mention,
    SceneRequest,
    singular,
    tokenize,
)
from physcensis.assets.text import MODIFIERS, STOPWORDS
from physcensis.errors import PhyscensisError

ARRANGEMENTS = ("none", "stack", "pile", "row", "column", "scatter")
STYLES = ("tidy", "messy", "dense", "precarious", "stable")
# relation -> the side a `beside` relation takes (agent/reading.py's Mention.side)
SIDES = {
    "left of": "left",
    "right of": "right",
    "in front of": "front",
    "behind": "behind",
    "beside": "beside",
    "on either side of": "sides",
    "at either end of": "ends",
}
RESTING = ("in", "on", "in each", "on each", "in its own", "on its own")
RELATIONS = ("none", *RESTING, *SIDES, "between", "around")
# in the order a place says them; "ends": both ends of the support ("a lamp at each end of the shelf")
REGION_WORDS = ("back", "front", "left", "right", "centre", "corner", "end", "ends", "edge")
# the places a graph's `where` may name (the schema's enum; the check also takes the words in another order)
PLACES = (
    *("", "centre", "left", "right", "back", "front", "back left", "back right", "front left", "front right"),
    *("corner", "back left corner", "back right corner", "front left corner", "front right corner", "back corner"),
    *("front corner", "left corner", "right corner", "end", "ends", "edge"),
    *("back centre", "front centre", "left centre", "right centre"),  # "in the middle at the back"
)
MAX_GRAPH_OBJECTS = 60
_MEASURES = {*ARRANGE_NOUNS, *TRAILING_UNITS, "pair", "couple", "set", "bunch", "handful", "dozen", "loaf", "deck"}
_NAME = re.compile(r"^[a-z][a-z '-]{0,39}$")
_SIDE_WORDS = {v: k for k, v in SIDES.items()}


class GraphError(PhyscensisError):
    """A scene graph that cannot be used: what is wrong and where (said to the model that wrote it)."""


class GraphObject(BaseModel):
    model_config = ConfigDict(extra="forbid")

    id: str = Field(min_length=1, max_length=40)
    name: str = Field(min_length=1, max_length=40)
    count: int = Field(ge=0, le=MOST)
    words: list[str] = Field(default_factory=list, max_length=6)
    arrangement: str = "none"
    groups: int = Field(default=0, ge=0, le=12)
    where: str = ""
    relation: str = "none"
    of: list[str] = Field(default_factory=list, max_length=2)


class SceneGraph(BaseModel):
    model_config = ConfigDict(extra="forbid")

    objects: list[GraphObject] = Field(max_length=MAX_GRAPH_OBJECTS)
    diners: int = Field(default=0, ge=0, le=12)
    style: str = "tidy"

    def to_json(self) -> dict[str, Any]:
        return self.model_dump()


@dataclass(frozen=True)
class GraphReading:
    """The graph a run planned from: the offline reading's, or a model's (or the offline reading's standing in for a
    model's that did not check, and why)."""

    graph: SceneGraph
    source: str  # "offline reading", "model"
    why: str = ""

    def to_json(self) -> dict[str, Any]:
        return {"source": self.source, "why": self.why, "graph": self.graph.to_json()}


def graph_schema() -> dict[str, Any]:
    """The graph's JSON Schema in the strict dialect servers accept for structured output: every property required,
    no `$ref`, no extra properties (agent/llm.py sends it as `response_format`)."""
    text = {"type": "string"}
    obj = {
        "type": "object",
        "properties": {
            "id": text,
            "name": text,
            "count": {"type": "integer", "minimum": 0, "maximum": MOST},
            "words": {"type": "array", "items": text},
            "arrangement": {"type": "string", "enum": list(ARRANGEMENTS)},
            "groups": {"type": "integer", "minimum": 0, "maximum": 12},
            "where": {"type": "string", "enum": list(PLACES)},
            "relation": {"type": "string", "enum": list(RELATIONS)},
            "of": {"type": "array", "items": text},
        },
        "required": ["id", "name", "count", "words", "arrangement", "groups", "where", "relation", "of"],
        "additionalProperties": False,
    }
    return {
        "type": "object",
        "properties": {
            "objects": {"type": "array", "items": obj},
            "diners": {"type": "integer", "minimum": 0, "maximum": 12},
            "style": {"type": "string", "enum": list(STYLES)},
        },
        "required": ["objects", "diners", "style"],
        "additionalProperties": False,
    }


def parse_graph(text: str) -> SceneGraph:
    """The graph in a model's reply (a JSON object, possibly inside a code fence or after some words), checked: every
    problem named with the object it is about."""
    data = _json_object(text)
    try:
        graph = SceneGraph.model_validate(data)
    except ValidationError as exc:
        first = exc.errors()[0]
        where = ".".join(str(p) for p in first["loc"])
        raise GraphError(f"the scene graph's {where or 'top level'}: {first['msg']}") from None
    problems = _problems(graph)
    if problems:
        raise GraphError("; ".join(problems[:4]))
    return graph


def _json_object(text: str) -> Any:
    start, end = text.find("{"), text.rfind("}")
    if start < 0:
        raise GraphError("the reply holds no JSON object: send the scene graph as one JSON object")
    if end <= start:
        raise GraphError("the scene graph is not valid JSON: the reply ends before its object closes (cut off?)")
    try:
        return json.loads(text[start : end + 1])
    except json.JSONDecodeError as exc:
        raise GraphError(f"the scene graph is not valid JSON: {exc.msg} at character {exc.pos}") from None


def _problems(graph: SceneGraph) -> list[str]:
    ids = [o.id for o in graph.objects]
    problems = [f"style {graph.style!r}: give one of {', '.join(STYLES)}"] if graph.style not in STYLES else []
    for o in graph.objects:
        problems += [f"object {o.id!r}: {p}" for p in _object_problems(graph, o, ids)]
    cycle = _resting_cycle(graph)
    if cycle:
        problems.append(f"objects {', '.join(cycle)} rest in or on each other in a circle")
    return problems


def _object_problems(graph: SceneGraph, o: GraphObject, ids: list[str]) -> list[str]:
    problems = []
    if ids.count(o.id) > 1:
        problems.append("two objects share this id; give each its own")
    if not _NAME.match(o.name.strip().lower()):
        problems.append(f"name {o.name!r} should be a short noun in letters ('mug', 'wine glass')")
    if o.arrangement not in ARRANGEMENTS:
        problems.append(f"arrangement {o.arrangement!r}: give one of {', '.join(ARRANGEMENTS)}")
    unknown = [w for w in re.split(r"[ -]+", o.where.lower().strip()) if w and w not in (*REGION_WORDS, "center")]
    if unknown:
        problems.append(f"where {o.where!r}: use {', '.join(REGION_WORDS)} or ''")
    if o.relation not in RELATIONS:
        return [*problems, f"relation {o.relation!r}: give one of {', '.join(RELATIONS)}"]
    wanted = 0 if o.relation == "none" else 2 if o.relation == "between" else 1
    if len(o.of) != wanted and not _between_many(graph, o):
        problems.append(f"relation {o.relation!r} takes {wanted} id(s) in 'of', not {len(o.of)}")
    for target in o.of:
        if target == o.id:
            problems.append(f"it cannot be {o.relation} itself")
        elif target not in ids:
            problems.append(f"'of' names {target!r}, which is no object's id")
    return problems


def _between_many(graph: SceneGraph, o: GraphObject) -> bool:
    """ "between two candles": one id naming two or more objects."""
    counts = {x.id: x.count for x in graph.objects}
    return o.relation == "between" and len(o.of) == 1 and counts.get(o.of[0]) != 1  # 0: a number not said


def _resting_cycle(graph: SceneGraph) -> list[str]:
    rests = {o.id: o.of[0] for o in graph.objects if o.relation in RESTING and o.of}
    for start in rests:
        seen, node = [start], rests[start]
        while node in rests and node not in seen:
            seen.append(node)
            node = rests[node]
        if node == start:
            return seen
    return []


# -- graph -> the planner's request -------------------------------------------------------------------------------


def request_of(graph: SceneGraph, lexicon: Lexicon, prompt: str = "") -> SceneRequest:
    """The planner's request for `graph`. Each object becomes a mention whose words are a token span of its own
    (count, words, name), so the planner's word-sensitive choices (a red mug's variant) read the graph's words; the
    prompt's tokens come first, for the kind of scene ("dining", "desk")."""
    tokens = [t for t in tokenize(prompt) if t != ","] + [","]
    mentions: list[Mention] = []
    objects = _without_the_setting(graph.objects, lexicon)
    index = {o.id: k for k, o in enumerate(objects)}
    for o in objects:
        start = len(tokens)
        tokens += _count_words(o.count) + [w for word in o.words for w in tokenize(word) if w != ","]
        name_start = len(tokens)
        tokens += [w for w in tokenize(o.name) if w != ","]
        mentions.append(_mention(o, tokens, start, name_start, lexicon))
        tokens.append(",")
    for k, o in enumerate(objects):
        _relate(mentions, k, o, [index[t] for t in o.of], lexicon)
    request = SceneRequest(mentions, diners=graph.diners, tokens=tokens)
    request.messy = graph.style == "messy"
    request.dense = graph.style == "dense"
    request.fragile = graph.style == "precarious"
    request.stable = graph.style == "stable"
    return request


def _without_the_setting(objects: list[GraphObject], lexicon: Lexicon) -> list[GraphObject]:
    """The objects without those naming the setting rather than a thing on it ("desk", "kitchen", "floor": the
    support a small model lists as an object); what stood in, on or beside them stands on the support."""
    setting = set()
    for o in objects:
        name = [singular(w) for w in tokenize(o.name) if w != ","]
        if name and (name[-1],) in NOT_OBJECTS and _head(name, lexicon) is None:
            setting.add(o.id)
    if not setting:
        return objects
    kept = []
    for o in (o for o in objects if o.id not in setting):
        if set(o.of) & setting:
            o = o.model_copy(update={"relation": "none", "of": []})
        kept.append(o)
    return kept


def _count_words(count: int) -> list[str]:
    return ["some"] if count == 0 else ["a"] if count == 1 else [str(count)]


def _mention(o: GraphObject, tokens: list[str], start: int, name_start: int, lexicon: Lexicon) -> Mention:
    name = tokens[name_start:]
    found = _head(name, lexicon)
    adjectives = [w for w in tokens[start:name_start] if w not in ("a", "some") and not w.isdigit()]
    if found is not None:
        at, category, phrase = found
        adjectives += name[:at]
        known = True
    else:
        own = _own_words(name)
        head = next((w for w in reversed(own) if w not in MODIFIERS and w not in STOPWORDS), own[-1])
        category = phrase = singular(head)
        adjectives += [w for w in name if w != head]
        known = False
    plural = o.count != 1
    count = o.count if o.count else 3
    m = Mention(category, count, phrase, tuple(adjectives), start, len(tokens), plural, o.count > 1, known=known)
    arrangement = "" if o.arrangement == "none" else o.arrangement
    m.arrangement, m.stacked = arrangement, arrangement in ("stack", "pile")
    m.groups = o.groups if arrangement else 0
    if m.groups and o.count and arrangement != "scatter":  # "two stacks of eight plates": four and four
        m.sizes = tuple(o.count // m.groups + (i < o.count % m.groups) for i in range(m.groups))
    where = [("centre" if w == "center" else w) for w in re.split(r"[ -]+", o.where.lower().strip()) if w]
    m.centre = "centre" in where
    m.region = tuple(dict.fromkeys(w for w in where if w != "centre"))
    return m


def _own_words(name: list[str]) -> list[str]:
    """The words naming the object itself: "bowl of fruit" is a bowl, "tube of toothpaste" and "pair of socks" the
    things after "of"."""
    if "of" not in name[1:]:
        return name
    at = name.index("of", 1)
    return name[at + 1 :] or name if singular(name[at - 1]) in _MEASURES else name[:at]


def _head(name: list[str], lexicon: Lexicon) -> tuple[int, str, str] | None:
    """(where it starts, category, phrase) of the catalogue noun that ends the name, the head noun ("coffee mug":
    a mug; "bowl of fruit": a bowl; "bar of soap": soap); None when the head is no catalogue noun ("mug holder" is
    no mug)."""
    whole = lexicon.match(name, 0)
    if whole is not None and whole[1] == len(name):  # a catalogue name with "of" in it: "box of crayons"
        return 0, whole[0], whole[2]
    name = _own_words(name)
    for i in range(len(name)):
        found = lexicon.match(name, i)
        if found is not None and i + found[1] == len(name):
            return i, found[0], found[2]
    return None


def _relate(mentions: list[Mention], k: int, o: GraphObject, targets: list[int], lexicon: Lexicon) -> None:
    m = mentions[k]
    if o.relation in RESTING:
        _rest(mentions, k, o, targets[0], lexicon)
    elif o.relation in SIDES:
        m.beside, m.side = targets[0], SIDES[o.relation]
    elif o.relation == "between" and len(targets) == 1:
        m.beside, m.side = targets[0], "between"  # between two of that object's copies
    elif o.relation == "between":
        first, second = targets
        m.beside, m.second, m.side = first, second, "between"
        b = mentions[second]
        if b.beside is None and b.on is None and not any(second in x.contents for x in mentions):
            b.beside, b.side = first, "right"  # the second stands to the viewer's right of the first
    elif o.relation == "around":
        m.around = targets[0]


def _rest(mentions: list[Mention], k: int, o: GraphObject, target: int, lexicon: Lexicon) -> None:
    """In or on `target`: in its cavity when it has one and the graph says "in", else resting on it."""
    m, t = mentions[k], mentions[target]
    if o.relation.endswith("each"):
        m.per, m.count, m.explicit_count, m.plural = target, max(1, o.count or 1) * t.count, True, True
    elif o.relation.endswith("own"):
        m.per = target
        if not t.explicit_count:  # "four cups on saucers": as many saucers as cups
            t.count, t.plural = max(t.count, m.count), True
    role = lexicon.role(t.category) if t.known else ""
    if o.relation.startswith("in") and role == "container":
        t.contents.append(k)
    else:
        m.on = target
        if o.relation == "on" and m.plural and t.plural:
            m.per = target  # "sandwiches on plates": one on each


# -- the planner's request -> graph ----------------------------------------------------------------------------------


def graph_of(request: SceneRequest) -> SceneGraph:
    """The graph of a reading: what the report saves, and the draft a model is shown."""
    mentions = request.mentions
    ids = _ids(mentions)
    objects = []
    for k, m in enumerate(mentions):
        relation, of = _relation_of(mentions, k, ids)
        count = m.count if m.explicit_count or not m.plural else 0
        if m.per is not None and relation in ("in each", "on each"):
            count = m.count // mentions[m.per].count
        where = sorted({*m.region, *(["centre"] if m.centre else [])}, key=REGION_WORDS.index)
        if "centre" in where and not {"back", "front", "left", "right"} & set(where):
            where = ["centre"]  # "in the middle", not "in the middle of one end"
        objects.append(
            GraphObject(
                id=ids[k],
                name=m.phrase[:40] or m.category[:40],
                count=min(count, MOST),
                words=[w[:40] for w in _words(request, m)],
                arrangement=m.arrangement or "none",
                groups=min(m.groups, 12),
                where=" ".join(where),
                relation=relation,
                of=of,
            )
        )
    flags = (
        ("dense", request.dense),
        ("precarious", request.fragile),
        ("stable", request.stable),
        ("messy", request.messy),
    )
    style = next((name for name, on in flags if on), "tidy")
    return SceneGraph(objects=objects[:MAX_GRAPH_OBJECTS], diners=min(request.diners, 12), style=style)


def _words(request: SceneRequest, m: Mention) -> list[str]:
    """The mention's adjectives, and "pair" when the words asked for a pair (two alike)."""
    pair = "pair" in request.tokens[m.start : m.end] and "pair" not in m.adjectives
    return [*m.adjectives[: 5 if pair else 6], *(["pair"] if pair else [])]


def _ids(mentions: list[Mention]) -> list[str]:
    ids: list[str] = []
    for m in mentions:
        base = re.sub(r"[^a-z0-9]+", "_", (m.phrase or m.category).lower()).strip("_")[:36] or "thing"
        name, n = base, 2
        while name in ids:
            name, n = f"{base}_{n}", n + 1
        ids.append(name)
    return ids


def _each(mentions: list[Mention], k: int, target: int) -> bool:
    """Whether mention k is so many of its kind for every one of `target` ("a teacup on each saucer")."""
    m, t = mentions[k], mentions[target]
    said = t.explicit_count or not t.plural  # "four cups on saucers": four cups, as many saucers as it takes
    return m.per == target and m.explicit_count and said and t.count > 1 and m.count % t.count == 0


def _relation_of(mentions: list[Mention], k: int, ids: list[str]) -> tuple[str, list[str]]:
    m = mentions[k]
    holder = next((j for j, o in enumerate(mentions) if k in o.contents), None)
    for where, target in (("on", m.on), ("in", holder)):  # on a container: across its rim
        if target is not None:
            own = " its own" if m.per == target and not _each(mentions, k, target) else ""
            return f"{where}{' each' if _each(mentions, k, target) else own}", [ids[target]]
    if m.beside is not None:
        if m.side == "between":
            return "between", [ids[m.beside]] + ([ids[m.second]] if m.second is not None else [])
        return _SIDE_WORDS.get(m.side, "beside"), [ids[m.beside]]
    if m.around is not None:
        return "around", [ids[m.around]]
    return "none", []
