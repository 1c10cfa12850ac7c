"""The program's object form and its JSON Schema, generated from the predicate registry.

The list form (`[["cup_0", "a mug"], ["cup_0", "PLACE-ON", "plate_0", {...}]]`) needs tuples, which the strict
schema dialects of structured output cannot express (OpenAI strict mode wants objects whose properties are all
required, and no `prefixItems`). The object form says the same with objects only:

    {"objects": [{"id": "cup_0", "description": "a mug"}],
     "relations": [{"subject": "cup_0", "predicate": "PLACE-ON", "target": "plate_0", "params": {...}}]}

`program_schema()` describes it in the subset of JSON Schema that OpenAI strict mode, vLLM guided decoding,
llama.cpp's `json_schema` and Ollama's `format` all accept: inline (no `$ref`), every property required, optional
parameters nullable (`null` means "not given"), `additionalProperties: false` everywhere, one `anyOf` branch per
predicate whose `predicate` is a one-name `enum` and whose `params` hold exactly that predicate's parameters.
`list_form` turns the object form back into the list form the parser reads; `object_form` goes the other way.
"""

from __future__ import annotations

import math
from typing import Any

from physcensis.errors import ProgramParseError
from physcensis.ids import GROUP_PREFIX, MAX_ID_CHARS, ROOT_ID
from physcensis.program.checker import MAX_ITEM_COUNT
from physcensis.program.registry import (
    PREDICATES,
    STABILITY_WORDS,
    Axis,
    ParamSpec,
    ParamType,
    PredicateSpec,
    Role,
)
from physcensis.scene import Support

SCHEMA_NAME = "program"
STRUCTURED_MODES = ("auto", "on", "off")  # send the schema: try and fall back to plain text when refused, always, never
OBJECT_FORM_KEYS = ("objects", "relations")
_ID_CHARS = "[A-Za-z0-9_-]"
ID_SCHEMA: dict[str, Any] = {"type": "string", "pattern": f"^{_ID_CHARS}{{1,{MAX_ID_CHARS}}}$"}
_NEW_GROUP_SCHEMA: dict[str, Any] = {
    "type": "string",
    "pattern": f"^{GROUP_PREFIX}{_ID_CHARS}{{1,{MAX_ID_CHARS - len(GROUP_PREFIX)}}}$",
}
_ROOT_SCHEMA: dict[str, Any] = {"type": "string", "enum": [ROOT_ID]}


def closed_object(properties: dict[str, Any]) -> dict[str, Any]:
    """An object with exactly these properties, all required (what strict mode asks for)."""
    return {"type": "object", "properties": properties, "required": list(properties), "additionalProperties": False}


_ITEM_COUNT_SCHEMA = closed_object(
    {"category": {"type": "string"}, "count": {"type": "integer", "minimum": 1, "maximum": MAX_ITEM_COUNT}}
)


def _role_schema(roles: frozenset[Role]) -> dict[str, Any]:
    """What may stand in a subject or target slot with these roles."""
    if Role.ITEMS in roles:
        listed = {"type": "array", "items": {"anyOf": [ID_SCHEMA, _ITEM_COUNT_SCHEMA]}}
        return {"anyOf": [ID_SCHEMA, listed]}
    if Role.MEMBERS in roles:
        return {"type": "array", "items": ID_SCHEMA}
    if roles == {Role.ROOT}:
        return _ROOT_SCHEMA
    if roles == {Role.NEW_GROUP}:
        return _NEW_GROUP_SCHEMA
    return ID_SCHEMA


def _value_schema(param: ParamSpec) -> dict[str, Any]:
    if param.type is ParamType.NUMBER:
        schema: dict[str, Any] = {"type": "number"}
        if param.low is not None:
            schema["minimum"] = param.low
        if param.high is not None:
            schema["maximum"] = param.high
        return schema
    if param.type is ParamType.BOOL:
        return {"type": "boolean"}
    if param.type is ParamType.STABILITY:
        words = {"type": "string", "enum": list(STABILITY_WORDS)}
        return {"anyOf": [words, {"type": "number", "minimum": 0.0, "maximum": 1.0}]}
    return dict(ID_SCHEMA)  # REFERENCE and OBJECT: an id


def param_schema(param: ParamSpec) -> dict[str, Any]:
    """A parameter's value; `null` (not given) allowed unless it is required."""
    schema = _value_schema(param)
    if param.required:
        return schema
    if "anyOf" in schema:
        return {"anyOf": [*schema["anyOf"], {"type": "null"}]}
    return {**schema, "type": [schema["type"], "null"]}


def relation_schema(spec: PredicateSpec) -> dict[str, Any]:
    """One relation of predicate `spec`: its subject, name, target and exactly its parameters."""
    return closed_object(
        {
            "subject": _role_schema(spec.subject),
            "predicate": {"type": "string", "enum": [spec.name]},
            "target": _role_schema(spec.target),
            "params": closed_object({p.name: param_schema(p) for p in spec.params}),
        }
    )


def program_schema() -> dict[str, Any]:
    """The JSON Schema of a program in the object form (see the module docstring for the dialect)."""
    declaration = closed_object({"id": ID_SCHEMA, "description": {"type": "string"}})
    relation = {"anyOf": [relation_schema(spec) for spec in PREDICATES.values()]}
    return closed_object(
        {"objects": {"type": "array", "items": declaration}, "relations": {"type": "array", "items": relation}}
    )


# -- the guided form: one entry per object, its placement inside it ---------------------------------------------
#
# Small models given the flat form leave objects unplaced or place them twice. In the guided form every object
# carries exactly one placement, so a reply its schema (agent/guided.py) accepts is complete by construction:
#
#     {"objects": [{"id": "laptop_0", "description": "...",
#                   "place": {"predicate": "PLACE-ON-BASE", "target": "root", "params": {"x": 0.0, "y": 0.1}},
#                   "facing": {"predicate": "FACING-FRONT", "target": "root", "params": {"yaw_offset": null}},
#                   "relations": [{"predicate": "LEFT-OF", "target": "mug_0", "params": {"distance": 0.05}}]},
#                  {"id": "cup_0", "description": "...",
#                   "place": {"predicate": "PLACE-ON", "target": "laptop_0", "params": {...}}}]}
#
# An object standing on the support gives x and y (within the support) and a yaw; its 2-D relations override x or y.
# An object placed by the physical solver (on, in, anywhere) carries nothing else. Groups are not part of it.

GUIDED_KEYS = ("place", "facing", "relations")


def bare_relation_schema(
    spec: PredicateSpec, target: dict[str, Any] | None = None, params: dict[str, Any] | None = None
) -> dict[str, Any]:
    """A relation of the guided form (its subject is the object it belongs to); `target` and `params` narrow the
    predicate's own target roles and parameter schemas."""
    if params is None:
        params = {p.name: param_schema(p) for p in spec.params}
    if target is None:
        target = ID_SCHEMA if Role.ITEMS in spec.subject else _role_schema(spec.target)
    return closed_object(
        {"predicate": {"type": "string", "enum": [spec.name]}, "target": target, "params": closed_object(params)}
    )


def support_position(param: ParamSpec, support: Support) -> dict[str, Any]:
    """A required position on the support (PLACE-ON-BASE's x or y): inside its top, as the checker asks."""
    half = math.floor(support.size[0 if param.bounded_by_support == "x" else 1] / 2 * 1e4) / 1e4  # rounded inward
    return {"type": "number", "minimum": -half, "maximum": half}


# How servers take a JSON Schema: OpenAI's `json_schema` (OpenAI, vLLM, llama.cpp's own server, LM Studio, Ollama's
# /v1), and `json_object` with a `schema` beside it (llama-cpp-python's server, which refuses `json_schema`).
SCHEMA_DIALECTS = ("json_schema", "json_object")


def response_format(dialect: str = "json_schema", schema: dict[str, Any] | None = None) -> dict[str, Any]:
    """The chat request's `response_format` asking for JSON under `schema` (a program in the object form when not
    given), in a server's dialect."""
    schema = program_schema() if schema is None else schema
    if dialect == "json_object":
        return {"type": "json_object", "schema": schema}
    return {"type": "json_schema", "json_schema": {"name": SCHEMA_NAME, "schema": schema, "strict": True}}


# -- the object form and the list form ---------------------------------------------------------------------------


def is_object_form(data: dict[str, Any]) -> bool:
    return "program" not in data and any(key in data for key in OBJECT_FORM_KEYS)


def _listed(data: dict[str, Any], key: str) -> list[Any]:
    value = data.get(key, [])
    if not isinstance(value, list):
        raise ProgramParseError(f'"{key}" of an object-form program must be a list, got {type(value).__name__}')
    return value


def _items_from_objects(value: Any) -> Any:
    """PLACE-IN's items with {"category", "count"} objects turned into [category, count] pairs."""
    if not isinstance(value, list):
        return value
    return [
        [item.get("category"), item.get("count")]
        if isinstance(item, dict) and set(item) == {"category", "count"}
        else item
        for item in value
    ]


def _entry_from_relation(raw: Any) -> Any:
    if not isinstance(raw, dict):
        return raw  # the parser reports it as an entry of the wrong shape
    params = raw.get("params")
    if isinstance(params, dict):
        params = {name: value for name, value in params.items() if value is not None}
    entry = [_items_from_objects(raw.get("subject")), raw.get("predicate"), raw.get("target")]
    return entry if params is None else [*entry, params]


def _entry_from_object(raw: Any) -> Any:
    return [raw.get("id"), raw.get("description")] if isinstance(raw, dict) else raw


def list_form(data: dict[str, Any]) -> list[Any]:
    """The list-form entries of an object-form program: declarations first, then relations, in their order (the
    guided objects' own relations first, ordered so that what an object refers to is placed before it)."""
    objects = _listed(data, "objects")
    guided = [raw for raw in objects if isinstance(raw, dict) and any(key in raw for key in GUIDED_KEYS)]
    declarations = [_entry_from_object(raw) for raw in objects if not any(raw is g for g in guided)]
    return declarations + _guided_entries(guided) + [_entry_from_relation(raw) for raw in _listed(data, "relations")]


def _guided_entries(objects: list[dict[str, Any]]) -> list[Any]:
    """Each guided object's declaration and relations together, objects in the order they must be solved."""
    owned = [(raw.get("id"), [_entry_from_object(raw), *_own_relations(raw)]) for raw in objects]
    return [entry for index in _solving_order(owned) for entry in owned[index][1]]


def _own_relations(raw: dict[str, Any]) -> list[Any]:
    """An object's placement, then its 2-D relations, then its facing, as list-form entries with it as subject.
    Its own x or y are left out where a relation sets that axis (the relation would override them anyway)."""
    oid = raw.get("id")
    relations = raw.get("relations")
    relations = relations if isinstance(relations, list) else ([] if relations is None else [relations])
    entries = [_entry_from_relation({"subject": oid, **r}) if isinstance(r, dict) else r for r in relations]
    place = raw.get("place")
    if isinstance(place, dict):
        place_entry = _entry_from_relation({"subject": oid, **place})
        entries.insert(0, _without_overridden(place_entry, entries))
    elif place is not None:
        entries.insert(0, place)  # the parser reports its shape
    facing = raw.get("facing")
    if isinstance(facing, dict):
        entries.append(_entry_from_relation({"subject": oid, **facing}))
    return entries


def _without_overridden(place: list[Any], relations: list[Any]) -> list[Any]:
    spec = _spec_of(place)
    if spec is None or len(place) < 4 or not isinstance(place[3], dict):
        return place
    overridden: set[Axis] = set()
    for entry in relations:
        other = _spec_of(entry)
        if other is not None:
            overridden |= other.axes_determined(_params_of(entry))
    given = dict(spec.determines_when_given)
    params = {name: value for name, value in place[3].items() if given.get(name) not in overridden}
    return [*place[:3], params]


def _solving_order(owned: list[tuple[Any, list[Any]]]) -> list[int]:
    """Indices of `owned` so that an object comes after those its entries refer to, and otherwise standing objects
    first, then those resting on or in others, then those placed anywhere (the paper's order); declared order
    breaks ties and a cycle is left in declared order for the checker to report."""
    index_of = {oid: i for i, (oid, _) in enumerate(owned) if isinstance(oid, str)}
    needs = [{index_of[r] for r in _referenced(entries) if r in index_of} - {i} for i, (_, entries) in enumerate(owned)]
    ranks = [_rank(entries) for _, entries in owned]
    order: list[int] = []
    waiting = set(range(len(owned)))
    while waiting:
        ready = [i for i in waiting if not needs[i] & waiting] or list(waiting)
        chosen = min(ready, key=lambda i: (ranks[i], i))
        order.append(chosen)
        waiting.discard(chosen)
    return order


def _referenced(entries: list[Any]) -> set[str]:
    refs: set[str] = set()
    for entry in entries:
        spec = _spec_of(entry)
        if spec is None:
            continue
        if isinstance(entry[2], str):
            refs.add(entry[2])
        for name, value in _params_of(entry).items():
            param = spec.param(name) if isinstance(name, str) else None
            if param is not None and param.type in (ParamType.REFERENCE, ParamType.OBJECT) and isinstance(value, str):
                refs.add(value)
    return refs


def _rank(entries: list[Any]) -> int:
    spec = next((spec for spec in map(_spec_of, entries) if spec is not None), None)
    return spec.placement.rank if spec is not None and spec.placement is not None else 0


def _spec_of(entry: Any) -> PredicateSpec | None:
    """The predicate of a list-form relation, None for anything else."""
    if not isinstance(entry, list) or len(entry) < 3 or not isinstance(entry[1], str):
        return None
    return PREDICATES.get(entry[1])


def _params_of(entry: list[Any]) -> dict[str, Any]:
    return entry[3] if len(entry) == 4 and isinstance(entry[3], dict) else {}


def _items_as_objects(value: Any) -> Any:
    if not isinstance(value, list | tuple):
        return value
    return [
        {"category": item[0], "count": item[1]} if isinstance(item, list | tuple) and len(item) == 2 else item
        for item in value
    ]


def _relation_object(entry: list[Any] | tuple[Any, ...]) -> dict[str, Any]:
    subject, name, target = entry[0], entry[1], entry[2]
    given = dict(entry[3]) if len(entry) == 4 and isinstance(entry[3], dict) else {}
    spec = PREDICATES.get(name) if isinstance(name, str) else None
    params = {p.name: given.get(p.name) for p in spec.params} if spec else given
    if spec is not None and Role.ITEMS in spec.subject:
        subject = _items_as_objects(subject)
    return {"subject": subject, "predicate": name, "target": target, "params": params}


def object_form(entries: list[Any]) -> dict[str, Any]:
    """The object form of list-form entries, every parameter of each predicate present (`null` when not given)."""
    objects = [{"id": e[0], "description": e[1]} for e in entries if len(e) == 2]
    relations = [_relation_object(e) for e in entries if len(e) in (3, 4)]
    return {"objects": objects, "relations": relations}
