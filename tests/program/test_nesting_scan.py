"""The nesting scan of a program's text: the same tokens as the plain string pattern, in bounded memory."""

from __future__ import annotations

import re
import tracemalloc

from hypothesis import given, settings
from hypothesis import strategies as st

from physcensis.program.lenient_json import _BRACKET_OR_STRING, _refuse_deep_nesting

PLAIN = re.compile(r'"(?:[^"\\\n]|\\.)*"|[\[\]{}]')  # one regex step per character: what it replaced


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet='"\\[]{}a\n', max_size=60))
def test_the_scan_finds_the_tokens_the_plain_pattern_finds(text: str) -> None:
    assert [m.span() for m in _BRACKET_OR_STRING.finditer(text)] == [m.span() for m in PLAIN.finditer(text)]


def test_a_megabyte_string_is_scanned_in_little_memory() -> None:
    text = '[["mug_0", "' + "x" * 1_000_000 + '"]]'
    tracemalloc.start()
    try:
        _refuse_deep_nesting(text)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 1_000_000  # the plain pattern kept about 120 MB for this string
