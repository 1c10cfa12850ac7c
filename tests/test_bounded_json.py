"""JSON from a folder is measured before it is parsed: the scan agrees with a plain character-by-character reading
of the text, and texts holding more values than their size allows are refused, cheaply."""

from __future__ import annotations

import json
import tracemalloc
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from physcensis import bounded_json
from physcensis.bounded_json import JsonShape, check_values, json_shape, load_json, shape_problem, value_limit
from physcensis.errors import SceneFormatError, one_line
from physcensis.fileio import BoundError


def reference_shape(text: str, max_depth: int) -> JsonShape:
    """The same figures read one character at a time, the way a JSON parser tracks strings and escapes."""
    deepest = level = values = 0
    string = _String()
    too_deep_at = -1
    data = text.encode("utf-8", "surrogatepass")
    for offset, code in enumerate(data):
        char = chr(code)
        if string.step(char):
            continue
        if char in "[{":
            level += 1
            values += 1
            deepest = max(deepest, level)
            if level > max_depth and too_deep_at < 0:
                too_deep_at = offset
        elif char in "]}":
            level -= 1
        elif char in ",:":
            values += 1
    return JsonShape(deepest, values + (1 if data.strip() else 0), too_deep_at)


class _String:
    """Whether a character is part of a string (its quotes included), tracking escapes."""

    def __init__(self) -> None:
        self.inside = self.escaped = False

    def step(self, char: str) -> bool:
        if not self.inside:
            self.inside = char == '"'
            return self.inside
        if self.escaped:
            self.escaped = False
        elif char == "\\":
            self.escaped = True
        elif char == '"':
            self.inside = False
        return True


# Texts full of what trips a scan: escaped quotes, runs of backslashes, brackets inside strings, non-ASCII.
TRICKY_TEXT = st.text(alphabet=st.sampled_from(['"', "\\", "[", "]", "{", "}", ",", ":", "a", "é", "\n"]), max_size=12)
JSON_VALUES = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False) | TRICKY_TEXT,
    lambda children: st.lists(children, max_size=4) | st.dictionaries(TRICKY_TEXT, children, max_size=4),
    max_leaves=40,
)


@settings(max_examples=300, deadline=None)
@given(JSON_VALUES, st.booleans(), st.sampled_from([None, 1]), st.sampled_from([1, 3, 7, 64, 1 << 18]))
@pytest.mark.long
def test_the_scan_agrees_with_a_character_by_character_reading(
    value: Any, ascii_only: bool, indent: int | None, chunk: int
) -> None:
    text = json.dumps(value, ensure_ascii=ascii_only, indent=indent)
    for max_depth in (1, 3):  # small chunks: strings and backslash runs cross their ends
        assert json_shape(text, max_depth, chunk) == reference_shape(text, max_depth)


def test_brackets_and_escaped_quotes_inside_strings_do_not_count() -> None:
    text = json.dumps({"a": 'x\\"[[[{{{,,,:::\\\\', "b": [1, 2]})
    assert json_shape(text) == JsonShape(depth=2, values=7, too_deep_at=-1)


def test_nesting_deeper_than_allowed_is_named_with_its_line() -> None:
    text = "[\n" * 3 + "[" * 70 + "]" * 73
    assert shape_problem(text, 64) == "nested 73 levels deep (from line 4); at most 64 levels are allowed"


def test_millions_of_empty_lists_are_refused_before_parsing_with_a_small_peak() -> None:
    text = "[" + ",".join(["[]"] * 2_700_000) + "]"  # 8 MB: json.loads would build 170 MB of lists
    tracemalloc.start()
    try:
        with pytest.raises(BoundError, match=r"holds about 5,400,001 JSON values; a file of this size may hold"):
            load_json(text)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 2 * len(text)  # the scan's copy of the text as bytes and a few small arrays


def test_a_text_within_its_allowance_parses_as_json_does() -> None:
    rows = [{"id": f"cup_{i}", "position": [i, 0.5, 0.25]} for i in range(30_000)]
    text = json.dumps(rows)
    assert len(text) > bounded_json.VALUE_ALLOWANCE  # scanned, not waved through by its size
    assert json_shape(text).values < value_limit(len(text))
    assert load_json(text) == rows


def test_a_short_text_is_not_scanned_as_it_cannot_hold_too_many_values(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(bounded_json, "json_shape", lambda *_: pytest.fail("scanned"))
    check_values("[" + ",".join(["[]"] * 1000) + "]")


def test_nesting_past_the_parser_is_a_bound_error_not_a_recursion_error() -> None:
    with pytest.raises(BoundError, match="nested too deeply to read"):
        load_json("[" * 100_000 + "]" * 100_000)


def test_every_error_message_is_one_line_whatever_a_file_put_in_it() -> None:
    message = str(SceneFormatError("scene.json: objects[0] (x\n\x1b[31mred\u2028\x85).id: bad"))
    assert message == "scene.json: objects[0] (x\\n\\x1b[31mred\\u2028\\x85).id: bad"
    assert one_line("a mug, é, ü, 日本") == "a mug, é, ü, 日本"  # printable text is left as it is
