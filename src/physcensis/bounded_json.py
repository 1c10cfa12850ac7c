"""Reading JSON that came from a folder within bounds decided before parsing.

`json.loads` recurses once per nesting level and builds a Python object of 30 to 170 bytes for each value, so a few
megabytes of `[],[],...` or `{"k1":0,...}` cost hundreds of megabytes. `json_shape` measures a text first (how deep
its brackets nest, how many values it holds) in one vectorised pass that copies no string, and `check_json_shape`
refuses a text nested too deep or holding more values than `value_limit` allows for its size: with at most about 80
bytes per counted value, parsing then stays within 4 x the text's size + 40 MB.
"""

from __future__ import annotations

import json
from typing import Any, NamedTuple

import numpy as np

from physcensis.fileio import BoundError

# Values any file may hold, plus one per BYTES_PER_VALUE bytes of text. A scene of 10,000 objects holds about
# 300,000; a value costs json.loads at most about 80 bytes (a list 64, a key and its value 58 each as counted).
VALUE_ALLOWANCE = 500_000
BYTES_PER_VALUE = 40
_CHUNK = 1 << 18  # bytes scanned at once: the scan's arrays stay a few megabytes for any file

_QUOTE, _BACKSLASH = ord('"'), ord("\\")
_OPENS = (ord("["), ord("{"))
_CLOSES = (ord("]"), ord("}"))
_SEPARATORS = (ord(","), ord(":"))


class JsonShape(NamedTuple):
    depth: int  # the deepest nesting of brackets outside strings
    values: int  # containers, commas and colons outside strings: about one per value and one per key
    too_deep_at: int  # byte offset of the first bracket deeper than the depth asked about, or -1


def value_limit(size: int) -> int:
    """The most values a JSON text of `size` bytes may hold."""
    return VALUE_ALLOWANCE + size // BYTES_PER_VALUE


def json_shape(text: str | bytes, max_depth: int = 2**31 - 1, chunk: int = _CHUNK) -> JsonShape:
    """How deep `text` nests and how many values it holds, counting only brackets, commas and colons outside
    strings (a quote after an odd run of backslashes does not end a string). On text that is not JSON the figures
    are those of its longest valid beginning, which is all a parser would read. `chunk`: bytes scanned at once."""
    data = text.encode("utf-8", "surrogatepass") if isinstance(text, str) else text
    deepest = level = values = 0
    too_deep_at = -1
    in_string = 0
    backslashes = 0  # the run of backslashes that ends the previous chunk
    for start in range(0, len(data), chunk):
        codes = np.frombuffer(data, np.uint8, count=min(chunk, len(data) - start), offset=start)
        quotes = codes == _QUOTE
        if backslashes or (codes == _BACKSLASH).any():
            quotes &= _escaped_parity(codes, backslashes) == 0
            backslashes = _trailing_backslashes(codes, backslashes)
        toggles = np.cumsum(quotes, dtype=np.int32)
        outside = ((toggles + in_string) & 1) == 0
        in_string = int(toggles[-1] + in_string) & 1
        opens = np.isin(codes, _OPENS) & outside
        steps = opens.astype(np.int32) - (np.isin(codes, _CLOSES) & outside)
        levels = np.cumsum(steps, dtype=np.int32) + level
        top = int(levels.max())
        if top > max_depth and too_deep_at < 0:
            too_deep_at = start + int(np.argmax(levels > max_depth))
        deepest, level = max(deepest, top), int(levels[-1])
        values += int(np.count_nonzero(opens)) + int(np.count_nonzero(np.isin(codes, _SEPARATORS) & outside))
    return JsonShape(deepest, values + (1 if data.strip() else 0), too_deep_at)


def _escaped_parity(codes: np.ndarray, carried: int) -> np.ndarray:
    """For each byte, whether an odd run of backslashes comes right before it (1) or not (0)."""
    index = np.arange(len(codes), dtype=np.int32)
    last_other = np.maximum.accumulate(np.where(codes == _BACKSLASH, -1, index))  # last non-backslash up to here
    before = np.empty_like(last_other)
    before[0], before[1:] = -1, last_other[:-1]
    run = index - 1 - before + np.where(before < 0, carried, 0)
    return run & 1


def _trailing_backslashes(codes: np.ndarray, carried: int) -> int:
    others = np.flatnonzero(codes != _BACKSLASH)
    if not len(others):
        return carried + len(codes)
    return len(codes) - 1 - int(others[-1])


def shape_problem(text: str | bytes, max_depth: int) -> str | None:
    """Why `text` may not be parsed - nested deeper than `max_depth` (and where) or more values than its size
    allows - or None."""
    shape = json_shape(text, max_depth)
    if shape.too_deep_at >= 0:
        data = text.encode("utf-8", "surrogatepass") if isinstance(text, str) else text
        line = data.count(b"\n", 0, shape.too_deep_at) + 1
        return f"nested {shape.depth} levels deep (from line {line}); at most {max_depth} levels are allowed"
    limit = value_limit(len(text))
    if shape.values > limit:
        return f"holds about {shape.values:,} values; a JSON file of this size may hold at most {limit:,}"
    return None


def check_values(text: str | bytes) -> None:
    """Refuse (BoundError) a JSON text, or a JSON-lines file as a whole, holding more values than its size allows.
    A text no longer than VALUE_ALLOWANCE cannot hold more (every value takes a byte), so it is not scanned."""
    if len(text) <= VALUE_ALLOWANCE:
        return
    values, limit = json_shape(text).values, value_limit(len(text))
    if values > limit:
        raise BoundError(f"holds about {values:,} JSON values; a file of this size may hold at most {limit:,}")


def load_json(text: str | bytes) -> Any:
    """One JSON document, within the value bound (`check_values`); BoundError if it holds too many values or nests
    too deeply to parse, ValueError on bad syntax."""
    check_values(text)
    try:
        return json.loads(text)
    except RecursionError:
        raise BoundError("nested too deeply to read (more than a thousand levels)") from None
