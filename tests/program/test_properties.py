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
_scalars = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-(10**6), 10**6),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=12),
    _words,
)
_json = st.recursive(
    _scalars,
    lambda inner: st.one_of(
        st.lists(inner, max_size=6), st.dictionaries(st.one_of(st.text(max_size=6), _words), inner, max_size=4)
    ),
    max_leaves=40,
)
_entry = st.lists(st.one_of(_words, _json), min_size=1, max_size=5)
_program_like = st.one_of(
    _json,
    st.lists(_entry, max_size=12),
    st.fixed_dictionaries({"program": st.lists(_entry, max_size=8)}, optional={"support": _json}),
)
_settings = settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
# Drawing a nested structure costs Hypothesis 20-50 ms, far more than parsing and checking it: these take the
# profile's number of examples (tests/conftest.py).
_structure_settings = settings(deadline=None, suppress_health_check=[HealthCheck.too_slow])


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


@_structure_settings
@given(_program_like)
def test_arbitrary_json_data(data: Any) -> None:
    _parse_and_check(data)


@_structure_settings
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
        '["' + "\\\\" * 300_000,
        "/*" + " " * 1_000_000,
        "# " * 200_000,
        '[["a","b"]' + ',["a","b"]' * 50_000 + "]",
    ],
    ids=[
        "open-lists",
        "open-objects",
        "nested-words",
        "unterminated-strings",
        "escapes",
        "open-comment",
        "comments",
        "many-entries",
    ],
)
def test_pathological_text_does_not_hang(text: str) -> None:
    _parse_and_check(text)


# -- numbers of any size, keys of any type, programs of any length ---------------------------------------------------

_any_number = st.one_of(
    st.integers(),
    st.integers(-(10**6), 10**6).map(lambda e: 10 ** min(abs(e), 5000) * (e or 1)),
    st.floats(allow_nan=True, allow_infinity=True),
)
_wild = st.recursive(
    st.one_of(_scalars, _any_number),
    lambda inner: st.one_of(
        st.lists(inner, max_size=5),
        st.dictionaries(st.one_of(st.text(max_size=6), _words, _any_number, st.booleans()), inner, max_size=4),
    ),
    max_leaves=30,
)
_wild_entry = st.lists(st.one_of(_words, _wild), min_size=1, max_size=5)


@_structure_settings
@given(st.lists(_wild_entry, max_size=10), st.integers(1, 50))
def test_numbers_of_any_size_and_keys_of_any_type(entries: list[Any], max_objects: int) -> None:
    """Integers far past Python's 4300-digit str() limit, NaN, inf and non-text keys anywhere: our error or a report
    whose messages can be printed and written."""
    try:
        program = parse_program(entries)
    except ProgramParseError:
        return
    report = check_program(program, max_objects=max_objects)
    json.dumps([p.to_dict() for p in report.problems])
    assert all(len(p.message) < 2000 for p in report.problems if p.index is not None)


@_settings
@given(
    st.lists(
        st.one_of(
            st.text(alphabet="0123456789", min_size=1, max_size=6000),
            st.sampled_from(["1e999", "-1e999", "NaN", "Infinity", "-Infinity", "1" + "0" * 400 + ".5"]),
        ),
        min_size=1,
        max_size=4,
    ),
    st.sampled_from(["{}", "```json\n{}\n```", "the program: {} thanks"]),
)
def test_number_literals_of_any_length_in_text(literals: list[str], wrap: str) -> None:
    values = ", ".join(literals)
    text = wrap.format(
        f'[["cup_0", "a mug"], ["cup_0", "PLACE-ON-BASE", "root", {{"x": {literals[0]}}}], '
        f'[[["apple", {literals[-1]}]], "PLACE-IN", "cup_0", {{}}], [{values}]]'
    )
    _parse_and_check(text)
