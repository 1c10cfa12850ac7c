"""Arbitrary text and JSON never crash the parser or checker with anything but our error."""

from __future__ import annotations

import json
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from physcensis.errors import ProgramParseError
from physcensis.program import check_program, parse_program
from physcensis.program.registry import PREDICATES

_words = st.sampled_from([*PREDICATES, "root", "group_a", "cup_0", "plate_0", "apple", "x", "C", "anchor"])
_scalars = st.one_of(st.none(), st.booleans(), st.integers(-10**6, 10**6),
                     st.floats(allow_nan=True, allow_infinity=True), st.text(max_size=12), _words)
_json = st.recursive(_scalars, lambda inner: st.one_of(
    st.lists(inner, max_size=6), st.dictionaries(st.one_of(st.text(max_size=6), _words), inner, max_size=4)),
    max_leaves=40)
_entry = st.lists(st.one_of(_words, _json), min_size=1, max_size=5)
_program_like = st.one_of(_json, st.lists(_entry, max_size=12),
                          st.fixed_dictionaries({"program": st.lists(_entry, max_size=8)}, optional={"support": _json}))
_settings = settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _parse_and_check(source: Any) -> None:
    try:
        program = parse_program(source)
    except ProgramParseError:
        return
    report = check_program(program)
    assert all(p.severity in ("error", "warning") for p in report.problems)
    program.to_json()


@_settings
@given(st.text(max_size=400))
def test_arbitrary_text(text: str) -> None:
    _parse_and_check(text)


@_settings
@given(st.text(alphabet="[]{},:\"'#/*\n abc-_0123.eE+TrueFalsNn", max_size=300))
def test_bracket_soup(text: str) -> None:
    _parse_and_check(text)


@_settings
@given(_program_like)
def test_arbitrary_json_data(data: Any) -> None:
    _parse_and_check(data)


@_settings
@given(_program_like)
def test_arbitrary_json_text(data: Any) -> None:
    _parse_and_check(json.dumps(data))


@pytest.mark.timeout(60)
@pytest.mark.parametrize(
    "text",
    [
        "[" * 200_000,
        "{" * 200_000,
        "[a" * 100_000,
        "[" * 150 + '"' + "x" * 1_000_000,
        "[\"" + "\\\\" * 300_000,
        "/*" + " " * 1_000_000,
        "# " * 200_000,
        "[[\"a\",\"b\"]" + ",[\"a\",\"b\"]" * 50_000 + "]",
    ],
    ids=["open-lists", "open-objects", "nested-words", "unterminated-strings", "escapes", "open-comment",
         "comments", "many-entries"],
)
def test_pathological_text_does_not_hang(text: str) -> None:
    _parse_and_check(text)
