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

from typing import Any

from physcensis.errors import ProgramParseError
from physcensis.ids import GROUP_PREFIX, MAX_ID_CHARS, ROOT_ID
from physcensis.program.checker import MAX_ITEM_COUNT
from physcensis.program.registry import PREDICATES, STABILITY_WORDS, ParamSpec, ParamType, PredicateSpec, Role

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


def _closed_object(properties: dict[str, Any]) -> dict[str, Any]:
    """An object with exactly these properties, all required (what strict mode asks for)."""
    return {"type": "object", "properties": properties, "required": list(properties), "additionalProperties": False}


_ITEM_COUNT_SCHEMA = _closed_object(
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


def _param_schema(param: ParamSpec) -> dict[str, Any]:
    """A parameter's value; `null` (not given) allowed unless it is required."""
    schema = _value_schema(param)
    if param.required:
        return schema
    if "anyOf" in schema:
        return {"anyOf": [*schema["anyOf"], {"type": "null"}]}
    return {**schema, "type": [schema["type"], "null"]}


def relation_schema(spec: PredicateSpec) -> dict[str, Any]:
    """One relation of predicate `spec`: its subject, name, target and exactly its parameters."""
    return _closed_object(
        {
            "subject": _role_schema(spec.subject),
            "predicate": {"type": "string", "enum": [spec.name]},
            "target": _role_schema(spec.target),
            "params": _closed_object({p.name: _param_schema(p) for p in spec.params}),
        }
    )


def program_schema() -> dict[str, Any]:
    """The JSON Schema of a program in the object form (see the module docstring for the dialect)."""
    declaration = _closed_object({"id": ID_SCHEMA, "description": {"type": "string"}})
    relation = {"anyOf": [relation_schema(spec) for spec in PREDICATES.values()]}
    return _closed_object(
        {"objects": {"type": "array", "items": declaration}, "relations": {"type": "array", "items": relation}}
    )


# How servers take a JSON Schema: OpenAI's `json_schema` (OpenAI, vLLM, llama.cpp's own server, LM Studio, Ollama's
# /v1), and `json_object` with a `schema` beside it (llama-cpp-python's server, which refuses `json_schema`).
SCHEMA_DIALECTS = ("json_schema", "json_object")


def response_format(dialect: str = "json_schema") -> dict[str, Any]:
    """The chat request's `response_format` asking for a program in the object form, in a server's dialect."""
    if dialect == "json_object":
        return {"type": "json_object", "schema": program_schema()}
    return {"type": "json_schema", "json_schema": {"name": SCHEMA_NAME, "schema": program_schema(), "strict": True}}


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
    """The list-form entries of an object-form program: declarations first, then relations, in their order."""
    declarations = [_entry_from_object(raw) for raw in _listed(data, "objects")]
    return declarations + [_entry_from_relation(raw) for raw in _listed(data, "relations")]


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
