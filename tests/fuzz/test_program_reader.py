"""Fuzz the program reader: `load_program` / `parse_program`, then `check_program`, as `physcensis check` runs them.

Inputs: the bundled example programs with bytes and JSON structure damaged; any JSON value; and data shaped like a
program (list form, object form, with an envelope) with registry predicates, odd ids and odd parameter values.
"""

from __future__ import annotations

import json
import tempfile
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from physcensis.program import PREDICATES
from tests.fuzz.harness import FUZZ, TIMEOUT, Blob, read_safely
from tests.fuzz.mutations import ODD_VALUES, json_values, mutated_bytes, mutated_json, odd_text
from tests.fuzz.readers import load_and_check, read_and_check

pytestmark = [pytest.mark.fuzz, TIMEOUT]

PREDICATE_NAMES = sorted(PREDICATES)
PARAM_NAMES = sorted({p.name for spec in PREDICATES.values() for p in spec.params})


def _source_size(source: Any) -> int:
    return len(source) if isinstance(source, str) else len(repr(source))


# ---- mutated example files ------------------------------------------------------------------------------------------


def _mutated_example(name: str, seed: bytes) -> st.SearchStrategy[bytes]:
    if name.endswith(".json"):
        return mutated_json(json.loads(seed)) | mutated_bytes(seed)
    return mutated_bytes(seed)


@FUZZ
@given(data=st.data())
def test_mutated_example_programs_are_read_or_refused(example_programs: dict[str, bytes], data: st.DataObject) -> None:
    name = data.draw(st.sampled_from(sorted(example_programs)), label="example")
    raw = data.draw(_mutated_example(name, example_programs[name]).map(Blob), label="file")
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / name
        path.write_bytes(raw)
        read_safely(lambda: load_and_check(path), len(raw), keep=path)


# ---- any JSON -------------------------------------------------------------------------------------------------------


@FUZZ
@given(value=json_values(60), as_text=st.booleans())
def test_any_json_value_is_read_or_refused(value: Any, as_text: bool) -> None:
    source = json.dumps(value) if as_text else value
    read_safely(lambda: read_and_check(source), _source_size(source))


# ---- data shaped like a program -------------------------------------------------------------------------------------

ids = st.sampled_from(["cup_0", "plate_0", "table", "root", "group:g", "", "cup_0 ", "ROOT"]) | odd_text()
predicates = (
    st.sampled_from(PREDICATE_NAMES)
    | st.sampled_from(PREDICATE_NAMES).map(str.lower)
    | st.sampled_from(PREDICATE_NAMES).map(lambda n: n.replace("-", "_"))
    | odd_text()
)
descriptions = st.sampled_from(["a mug", "asset:lib_block", "asset:", "PLACE-ON", "3 mugs", "a" * 10_001]) | odd_text()
param_values = (
    st.sampled_from(ODD_VALUES)
    | st.floats()
    | st.integers()
    | st.sampled_from(["stable", "unstable", "cup_0", "root"])
    | json_values(5)
)
params = st.dictionaries(st.sampled_from(PARAM_NAMES) | odd_text(), param_values, max_size=4)
items = st.lists(st.tuples(odd_text() | st.just("mug"), param_values).map(list), max_size=4)
subjects = ids | items | json_values(3)
declaration = st.tuples(ids, descriptions).map(list)
relation = st.tuples(subjects, predicates, ids | json_values(3)).map(list) | st.tuples(
    subjects, predicates, ids, params | json_values(3)
).map(list)
entries = st.lists(declaration | relation | json_values(5), max_size=40)
supports = st.fixed_dictionaries(
    {"kind": st.sampled_from(["table", "floor", "shelf", "tray"]) | odd_text()},
    optional={"size": st.lists(param_values, max_size=3), "height": param_values},
) | json_values(4)
envelope = st.fixed_dictionaries(
    {"program": entries | json_values(5)},
    optional={
        "support": supports,
        "prompt": odd_text() | st.just("p" * 100_001),
        "seed": param_values,
        "format": odd_text(),
        "extra": json_values(3),
    },
)
relation_objects = st.fixed_dictionaries(
    {"predicate": predicates}, optional={"subject": subjects, "target": ids, "params": params | json_values(3)}
)
guided_objects = st.fixed_dictionaries(
    {"id": ids | json_values(2)},
    optional={
        "description": descriptions | json_values(2),
        "place": relation_objects | json_values(2),
        "facing": relation_objects | json_values(2),
        "relations": st.lists(relation_objects | json_values(2), max_size=4) | json_values(2),
    },
)
object_form = st.fixed_dictionaries(
    {},
    optional={
        "objects": st.lists(guided_objects | json_values(2), max_size=12) | json_values(2),
        "relations": st.lists(relation_objects | json_values(2), max_size=12) | json_values(2),
        "support": supports,
        "prompt": odd_text(),
    },
)
programs = entries | envelope | object_form | envelope.map(lambda e: {**e, "program": {"objects": []}})


@st.composite
def program_sources(draw: st.DrawFn) -> str | list[Any] | dict[str, Any]:
    """The program as data (as an LLM client hands it over), as strict JSON text, or as text damaged a little."""
    program = draw(programs)
    form = draw(st.sampled_from(["data", "text", "llm-text"]))
    if form == "data":
        return program
    text = json.dumps(program, ensure_ascii=draw(st.booleans()))
    if form == "llm-text":
        reply = f"Here is the program:\n```json\n{text}\n```\n".encode("utf-8", "surrogatepass")
        text = draw(mutated_bytes(reply)).decode("utf-8", "replace")
    return text


@FUZZ
@given(source=program_sources())
def test_program_shaped_data_is_read_or_refused(source: str | list[Any] | dict[str, Any]) -> None:
    read_safely(lambda: read_and_check(source), _source_size(source))
