"""Guided decoding in two steps, for small models behind a server that enforces a JSON Schema.

A schema cannot say "a target must be one of the ids declared above", and small models break exactly that rule
(an object related to itself, a target nobody declared), or forget to place an object. So one round is two
requests, each with a schema built for it:

1. the objects: `{"objects": [{"id", "description"}, ...]}`;
2. their placements: `{"<id>": {"place", "facing", "relations"}, ...}` with one required property per listed id,
   each a choice of the guided form's placements (program/schema.py) whose targets are enums of the *other*
   listed ids (and "root" where the predicate takes it), positions within the support.

A reply that both schemas accept is a complete program whose references all resolve. The two replies are joined
into one program in the guided form, which is what the loop sees and what the history shows the model next round.
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable
from typing import Any

from physcensis.agent.base import AgentContext
from physcensis.ids import MAX_ID_CHARS, ROOT_ID, is_reserved_id
from physcensis.program.registry import (
    PREDICATES,
    Effect,
    ParamSpec,
    ParamType,
    PlacementKind,
    PredicateSpec,
    Role,
    placement_spec,
)
from physcensis.program.schema import ID_SCHEMA, bare_relation_schema, closed_object, param_schema, support_position
from physcensis.scene import Support

# Send(chat, schema, max_tokens) -> the reply text. The agent wraps the schema in its server's dialect.
Send = Callable[[list[dict[str, Any]], dict[str, Any], int], str]

OBJECTS_STEP = (
    'Step 1 of 2: list the objects only, as {"objects": [{"id", "description"}, ...]}: one entry for every object '
    "the scene needs (five books are five entries: book_0 to book_4), each after the objects it rests on, stands "
    "in or is placed by (the bowl before the apples in it, a stack from the bottom up)."
)
PLACEMENTS_STEP = (
    'Step 2 of 2: place each object you listed, as {"<id>": {"place", "facing", "relations"}, ...}; an object on '
    'the support needs all three, one on, in or anywhere only "place". A target is an object listed before it '
    f'or "{ROOT_ID}".'
)
OBJECTS_REPLY_BASE_TOKENS = 64
OBJECT_LIST_TOKENS = 40  # an id and a one-sentence description
PLACEMENT_TOKENS = 160  # one object's place, facing and a relation, every parameter written out
_SUFFIX = re.compile(r"_\d+$")


DESCRIPTION_MAX_CHARS = 160  # one sentence; small models otherwise ramble on in a description


def objects_schema(local: bool = False, least: int = 1) -> dict[str, Any]:
    """The objects step: ids and descriptions, at least `least` of them (no maxItems: grammar-based servers unroll
    it; the checker limits). For a `local` server (llama.cpp and friends, which enforce it) a description is at most
    one sentence long."""
    description: dict[str, Any] = {"type": "string", "minLength": 3}
    if local:
        description["maxLength"] = DESCRIPTION_MAX_CHARS
    declaration = closed_object({"id": ID_SCHEMA, "description": description})
    listed = {"type": "array", "minItems": max(1, min(least, MAX_GUIDED_OBJECTS)), "items": declaration}
    return closed_object({"objects": listed})


OPENAI_MAX_ENUM_VALUES = 1000  # OpenAI strict mode: enum values in one schema (all enums together)
MAX_RELATIONS = 3  # 2-D relations of one standing object: x and y need two; more is a small model repeating itself
MAX_GUIDED_OBJECTS = 48  # what one placements reply of MAX_REPLY_TOKENS holds at PLACEMENT_TOKENS each


def placements_schema(ids: list[str], support: Support, max_enum_values: int | None = None) -> dict[str, Any]:
    """One required property per id, in order: its placement, with targets among the ids listed before it (so
    references cannot loop, and what an object rests on is placed before it). When that many enum values exceed
    `max_enum_values` (a server's limit), targets are any id instead, and the checker judges them."""
    exact = closed_object({oid: _placement_choices(ids[:k], support) for k, oid in enumerate(ids)})
    if max_enum_values is None or enum_values(exact) <= max_enum_values:
        return exact
    return closed_object({oid: _placement_choices(None, support) for oid in ids})


def enum_values(schema: Any) -> int:
    """How many enum values a schema holds (servers such as OpenAI limit the total)."""
    if isinstance(schema, dict):
        return len(schema.get("enum", ())) + sum(enum_values(value) for value in schema.values())
    if isinstance(schema, list):
        return sum(enum_values(value) for value in schema)
    return 0


def _placement_choices(others: list[str] | None, support: Support) -> dict[str, Any]:
    """The ways to place one object: standing (position, facing, relations to `others`), or on, in or anywhere.
    `others` None: any id may be a target."""
    base = placement_spec(PlacementKind.BASE)
    position = {p.name: support_position(p, support) for p in base.params}
    facing = [s for s in _specs(Effect.YAW) if _targets(s, others) != []]
    relations = [s for s in _specs(Effect.EDGE, Effect.SYMMETRY) if _targets(s, others) != [] and _refs_ok(s, others)]
    standing = closed_object(
        {
            "place": bare_relation_schema(base, target=_enum([ROOT_ID]), params=position),
            "facing": {"anyOf": _merged(facing, others)},
            "relations": {"type": "array", "maxItems": MAX_RELATIONS, "items": {"anyOf": _merged(relations, others)}}
            if relations
            else {"type": "array", "maxItems": 0, "items": {"type": "null"}},
        }
    )
    resting = [closed_object({"place": branch}) for branch in _merged(_resting_specs(others), others)]
    return {"anyOf": [standing, *resting]}


def _resting_specs(others: list[str] | None) -> list[PredicateSpec]:
    placements = (placement_spec(kind) for kind in PlacementKind if kind.decides_everything)
    return [spec for spec in placements if _targets(spec, others) != []]


def _specs(*effects: Effect) -> list[PredicateSpec]:
    return [spec for spec in PREDICATES.values() if spec.effect in effects]


def _targets(spec: PredicateSpec, others: list[str] | None) -> list[str] | None:
    """The ids a relation of `spec` may name as its target: root where it takes root (but never beside root, which
    is off the support), else another object; None when any object id may stand there."""
    roles = spec.target
    beside = spec.edge is not None and spec.edge.direction != 0
    named = [ROOT_ID] if Role.ROOT in roles and not beside else []
    if roles & {Role.OBJECT, Role.GROUP} or Role.ITEMS in spec.subject:
        if others is None:
            return None
        named += others
    return named


def _is_reference(param: ParamSpec) -> bool:
    return param.type in (ParamType.REFERENCE, ParamType.OBJECT)


def _refs_ok(spec: PredicateSpec, others: list[str] | None) -> bool:
    """Whether every required reference parameter can name an object other than the target (SYMMETRY-ALONG's C)."""
    enough = others is None or len(others) >= 2
    return all(not (p.required and _is_reference(p)) or enough for p in spec.params)


def _merged(specs: list[PredicateSpec], others: list[str] | None) -> list[dict[str, Any]]:
    """One branch per shape (same targets and parameters) with the predicates' names in one enum: a schema a
    fraction of the size of one branch per predicate."""
    shapes: dict[str, tuple[list[str], dict[str, Any], dict[str, Any]]] = {}
    for spec in specs:
        targets = _targets(spec, others)
        target = ID_SCHEMA if targets is None else _enum(targets)
        params = {p.name: _reference_schema(p, others) if _is_reference(p) else param_schema(p) for p in spec.params}
        key = json.dumps([target, params], sort_keys=True)
        shapes.setdefault(key, ([], target, params))[0].append(spec.name)
    return [
        closed_object({"predicate": _enum(names), "target": target, "params": closed_object(params)})
        for names, target, params in shapes.values()
    ]


def _reference_schema(param: ParamSpec, others: list[str] | None) -> dict[str, Any]:
    ids = ID_SCHEMA if others is None else _enum(others)
    return ids if param.required else {"anyOf": [ids, {"type": "null"}]}


def _enum(values: list[str]) -> dict[str, Any]:
    return {"type": "string", "enum": list(dict.fromkeys(values))}


# -- the two requests --------------------------------------------------------------------------------------------


# Supports a small model lists as an object of their own ("table_0": "a dining table, 1.2 m wide ..."), after which it
# puts everything on it. A box is left out: boxes are also things that stand on shelves and tables.
_SUPPORT_WORDS = {
    "table": ("table", "desk", "counter", "countertop", "tabletop"),
    "shelf": ("shelf",),
    "floor": ("floor",),
}
# What a model copies from the draft's lines into a description: where the draft put the object (at its end).
DRAFT_PLACE_CHARS = 64
_DRAFT_PLACE = re.compile(
    r"[\s,;(]*\b(stands at x -?\d+(\.\d+)?, y -?\d+(\.\d+)?|(on|in) [a-z][a-z0-9_]*_\d+|anywhere with room)\)?\s*$"
)


def without_the_support(objects: list[tuple[str, str]], support: Support) -> list[tuple[str, str]]:
    """The listed objects without one that names the support itself (its id is the support's word: "table_0",
    "dining_table_0"), and with what a model copied of the draft's places cut from the descriptions."""
    words = _SUPPORT_WORDS.get(support.kind, ())
    kept = []
    for oid, description in objects:
        stem = _SUFFIX.sub("", oid)
        if any(stem == w or stem.endswith(f"_{w}") for w in words):
            continue
        text = " ".join(description.split()).rstrip(". ")
        head, tail = text[:-DRAFT_PLACE_CHARS], text[-DRAFT_PLACE_CHARS:]  # a copied place ends the description
        tidy = (head + _DRAFT_PLACE.sub("", tail)).strip()
        kept.append((oid, tidy if len(tidy) >= 3 else description))
    return kept


def unique_objects(reply: str) -> list[tuple[str, str]]:
    """(id, description) pairs of the objects step; an id used twice (or a reserved one such as "root") gets the next
    free suffix and a blank description one made from the id, so every object the model listed stays and checks. A
    reply that is not the expected JSON gives []."""
    try:
        data = json.loads(reply)
    except ValueError:
        return []
    raw = data.get("objects") if isinstance(data, dict) else None
    pairs = [
        (o["id"], o["description"])
        for o in (raw if isinstance(raw, list) else [])
        if isinstance(o, dict) and isinstance(o.get("id"), str) and isinstance(o.get("description"), str)
    ]
    seen: set[str] = set()
    result = []
    for oid, description in pairs:
        if oid in seen or is_reserved_id(oid):
            stem, n = _SUFFIX.sub("", oid)[: MAX_ID_CHARS - 4], 0
            while f"{stem}_{n}" in seen:
                n += 1
            oid = f"{stem}_{n}"
        seen.add(oid)
        words = _SUFFIX.sub("", oid).replace("_", " ").replace("-", " ").strip() or "object"
        result.append((oid, description if description.strip() else f"a {words}"))
    return result


def two_step_reply(
    chat: list[dict[str, Any]],
    context: AgentContext,
    send: Send,
    expected_objects: int,
    max_enum_values: int | None = None,
    least_objects: int = 1,
) -> str:
    """The program in the guided form, from the objects step and then the placements step (`expected_objects`
    sizes the first reply's token budget; `max_enum_values` is the server's schema limit, if it has one; the objects
    step lists at least `least_objects`, the count of the draft the model was shown). When the
    objects step gives nothing usable, its reply is returned as it is: the loop reports what is wrong. At most
    MAX_GUIDED_OBJECTS objects (what one reply can place) go on to the placements step; an enrichment round can add
    more."""
    first = _with_step(chat, OBJECTS_STEP)
    tokens = OBJECTS_REPLY_BASE_TOKENS + OBJECT_LIST_TOKENS * 2 * expected_objects
    listed = send(first, objects_schema(local=max_enum_values is None, least=least_objects), tokens)
    objects = without_the_support(unique_objects(listed), context.support)[:MAX_GUIDED_OBJECTS]
    if not objects:
        return listed
    ids = [oid for oid, _ in objects]
    declared = json.dumps({"objects": [{"id": i, "description": d} for i, d in objects]}, separators=(",", ":"))
    second = [*first, {"role": "assistant", "content": declared}, {"role": "user", "content": PLACEMENTS_STEP}]
    schema = placements_schema(ids, context.support, max_enum_values)
    placed = send(second, schema, 64 + PLACEMENT_TOKENS * len(ids))
    return joined(objects, placed, context.support)


def joined(objects: list[tuple[str, str]], placements_reply: str, support: Support | None = None) -> str:
    """The guided-form program of the listed objects and the placements reply (an object the reply misses is
    declared without a placement, which the checker reports). Numbers are brought within the schema's ranges (the
    predicates' own, the support's for a standing position): some servers (llama-cpp-python) enforce a schema's
    structure but not its numeric bounds."""
    placements = _read_placements(placements_reply)
    program = []
    for oid, description in objects:
        entry: dict[str, Any] = {"id": oid, "description": description}
        own = placements.get(oid)
        if isinstance(own, dict):
            entry |= {key: _within_ranges(own[key], support) for key in ("place", "facing", "relations") if key in own}
        else:
            entry["place"] = None
        program.append(entry)
    return json.dumps({"objects": program}, separators=(",", ":"))


def _read_placements(reply: str) -> dict[str, Any]:
    """The placements by id; of a reply cut short (its token budget ran out), the objects received whole."""
    try:
        data = json.loads(reply)
    except ValueError:
        data = _complete_prefix(reply)
    return data if isinstance(data, dict) else {}


def _complete_prefix(reply: str) -> dict[str, Any]:
    """The members of a cut-off top-level JSON object that arrived whole."""
    decoder = json.JSONDecoder()
    found: dict[str, Any] = {}
    text = reply.strip()
    index = 1 if text.startswith("{") else len(text)
    while index < len(text):
        try:
            key, index = decoder.raw_decode(text, _skip(text, index, ","))
            value, index = decoder.raw_decode(text, _skip(text, _skip(text, index, ":"), ""))
        except (ValueError, IndexError):
            break
        if isinstance(key, str):
            found[key] = value
    return found


def _skip(text: str, index: int, separator: str) -> int:
    """The index after whitespace and one optional `separator` at `index`."""
    while index < len(text) and text[index].isspace():
        index += 1
    if separator and text.startswith(separator, index):
        index += 1
    while index < len(text) and text[index].isspace():
        index += 1
    return index


def _within_ranges(value: Any, support: Support | None) -> Any:
    """A relation (or a list of them) with each number parameter clipped to its range."""
    if isinstance(value, list):
        return [_within_ranges(item, support) for item in value]
    spec = PREDICATES.get(value.get("predicate", "")) if isinstance(value, dict) else None
    params = value.get("params") if isinstance(value, dict) else None
    if spec is None or not isinstance(params, dict):
        return value
    clipped = dict(params)
    for param in spec.params:
        number = params.get(param.name)
        if isinstance(number, bool) or not isinstance(number, int | float) or param.type is not ParamType.NUMBER:
            continue
        low, high = param.low, param.high
        if param.bounded_by_support and support is not None:
            bounds = support_position(param, support)
            low, high = bounds["minimum"], bounds["maximum"]
        clipped[param.name] = min(max(number, low if low is not None else number), high if high is not None else number)
    return {**value, "params": clipped}


def _with_step(chat: list[dict[str, Any]], step: str) -> list[dict[str, Any]]:
    """The chat with the step's instruction added to its last user turn."""
    last = chat[-1]
    return [*chat[:-1], {**last, "content": f"{last['content']}\n\n{step}"}]
