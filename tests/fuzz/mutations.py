"""Hypothesis strategies that turn a seed file into a damaged or hostile one.

* `mutated_bytes`: byte flips, overwrites, truncation, deletions, insertions of interesting tokens, splices;
* `mutated_json`: structural edits of a JSON document (field deletions, type swaps, huge arrays and strings,
  NaN and infinities, huge numbers, deep nesting, unicode with lone surrogates, unknown keys), then maybe bytes;
* `mutated_jsonl`: the same on one line of a JSON-lines file, or whole lines deleted, duplicated, torn;
* `mutated_xml`: attribute values and names, tags, lines and hostile snippets of an XML file, then maybe bytes;
* `json_values`: any JSON value, as `hypothesis.strategies.recursive` makes them.

Huge and deep things are written as markers in the document and expanded in its text, so that making them never
builds a deep Python structure (json.dumps would recurse) and stays cheap. Repetitions are capped so that an input
never grows past MAX_GROWN_BYTES however the edits compound (a huge list of a huge list would not fit in memory).
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Callable
from typing import Any

from hypothesis import strategies as st

Draw = Callable[[st.SearchStrategy[Any]], Any]
Path_ = tuple[str | int, ...]

INTERESTING_BYTES = [
    b"NaN",
    b"Infinity",
    b"-Infinity",
    b"1e999",
    b"-1",
    b"0",
    b"9" * 400,
    b"9" * 5000,
    b"\x00",
    b"\xff\xfe",
    b"\xed\xa0\x80",  # a UTF-16 surrogate encoded as UTF-8: not valid UTF-8
    "é\u202e\u2028".encode(),
    b"[" * 2000,
    b'{"a":' * 500,
    b'"',
    b"\\",
    b"\\ud800",
    b"\n",
    b"\r\n",
    b"<",
    b"PK\x03\x04",
    b"PK\x05\x06",
]
ODD_VALUES: list[Any] = [None, True, False, 0, -1, 1, 1.5, -0.0, "", "x", [], {}, 2**70, -(2**63), 1e308, -1e308]
ODD_VALUES += [math.nan, math.inf, -math.inf, "NaN", "../../etc/passwd", "/etc/passwd", "a\nb", "\udcff", "\x00"]
# Marker text -> what it becomes in the document's text.
EXPANSIONS = {
    **{f"@@deep{n}@@": "[" * n + "]" * n for n in (65, 1_000, 100_000)},
    **{f"@@dict{n}@@": '{"a":' * n + "0" + "}" * n for n in (65, 1_000)},
    **{f"@@digits{n}@@": "9" * n for n in (41, 301, 4_301, 100_000)},
    "@@containers@@": "[" + ",".join(["[]"] * 2_700_000) + "]",  # 8 MB of text, 2.7 million objects once read
    "@@exp@@": "1e999",
    "@@-exp@@": "-1e999",
    "@@nan@@": "NaN",
    "@@inf@@": "Infinity",
}
_MARKER = re.compile(r'"(@@[a-z0-9-]+@@)"')
MAX_GROWN_BYTES = 8 * 2**20


def expand(text: str) -> str:
    """The document's text with its markers replaced by what they stand for."""
    return _MARKER.sub(lambda m: EXPANSIONS.get(m.group(1), m.group()), text)


def _text_size(node: Any) -> int:
    """The size of a node's JSON text once its markers are expanded."""
    text = json.dumps(node)
    return len(expand(text))


def _unshared(value: Any) -> Any:
    """`value` with no node shared between two places (json.dumps escapes lone surrogates, so they come back)."""
    return json.loads(json.dumps(value))


def _copies(draw: Draw, unit_bytes: int, choices: list[int]) -> int:
    """How many copies of a unit of `unit_bytes` to make: one of `choices`, capped by MAX_GROWN_BYTES."""
    return max(1, min(draw(st.sampled_from(choices)), MAX_GROWN_BYTES // max(unit_bytes, 1)))


def _index(draw: Draw, length: int) -> int:
    """A position in 0..length (shrinks towards the start)."""
    return draw(st.integers(0, max(length, 0)))


def _insertion(draw: Draw) -> bytes:
    return draw(st.sampled_from(INTERESTING_BYTES) | st.binary(min_size=1, max_size=32))


def _one_byte_edit(draw: Draw, data: bytes) -> bytes:
    op = draw(st.sampled_from(["flip", "set", "truncate", "delete", "insert", "splice"]))
    at = _index(draw, len(data))
    if op == "flip" and data:
        at = min(at, len(data) - 1)
        return data[:at] + bytes([data[at] ^ draw(st.integers(1, 255))]) + data[at + 1 :]
    if op == "set" and data:
        at = min(at, len(data) - 1)
        return data[:at] + bytes([draw(st.integers(0, 255))]) + data[at + 1 :]
    if op == "truncate":
        return data[:at]
    if op == "delete":
        return data[:at] + data[at + draw(st.integers(1, 64)) :]
    if op == "splice" and data:
        start = _index(draw, len(data) - 1)
        piece = data[start : start + draw(st.integers(1, 256))]
        return data[:at] + piece * _copies(draw, len(piece) + len(data), [1, 2, 100]) + data[at:]
    return data[:at] + _insertion(draw) + data[at:]


@st.composite
def mutated_bytes(draw: Draw, data: bytes, max_edits: int = 4) -> bytes:
    for _ in range(draw(st.integers(1, max_edits))):
        data = _one_byte_edit(draw, data)
    return data


def json_values(max_leaves: int = 20) -> st.SearchStrategy[Any]:
    """Any JSON value (with NaN and infinities, as Python's json reads them)."""
    scalars = st.none() | st.booleans() | st.integers() | st.floats() | st.text(max_size=20)
    return st.recursive(
        scalars,
        lambda children: st.lists(children, max_size=5) | st.dictionaries(st.text(max_size=10), children, max_size=5),
        max_leaves=max_leaves,
    )


def odd_text() -> st.SearchStrategy[str]:
    """Text with lone surrogates, controls, bidirectional marks and non-BMP characters."""
    surrogates = st.characters(min_codepoint=0xD800, max_codepoint=0xDFFF)
    odd = st.sampled_from(["\x00", "\n", "\r", "\u202e", "\u2028", "\ufeff", "\U0001f600", "<", "&", '"', "\\"])
    return st.text(st.characters(codec=None) | surrogates | odd, max_size=30)


def node_paths(value: Any, limit: int = 5_000) -> list[Path_]:
    """The first `limit` nodes of a JSON document, depth first, as the keys and indices that lead to them (the root
    is ()); a document grown by earlier edits is not walked whole."""
    paths: list[Path_] = []
    pending: list[tuple[Path_, Any]] = [((), value)]
    while pending and len(paths) < limit:
        path, node = pending.pop()
        paths.append(path)
        children = node.items() if isinstance(node, dict) else enumerate(node) if isinstance(node, list) else ()
        pending += reversed([((*path, key), child) for key, child in children])
    return paths


def _get(value: Any, path: Path_) -> Any:
    for step in path:
        value = value[step]
    return value


def _replacement(draw: Draw, node: Any) -> Any:
    """What a node becomes (None for "delete it")."""
    op = draw(
        st.sampled_from(["delete", "odd", "random", "marker", "text", "huge-list", "huge-text", "wrap", "add-key"])
    )
    if op == "odd":
        return draw(st.sampled_from(ODD_VALUES))
    if op == "random":
        return draw(json_values())
    if op == "marker":
        return draw(st.sampled_from(sorted(EXPANSIONS)))
    if op == "text":
        return draw(odd_text())
    if op == "huge-list":  # copies, not references: a later edit of one must not grow them all
        return _unshared([node] * _copies(draw, _text_size(node), [1_000, 20_000]))
    if op == "huge-text":
        return "x" * draw(st.sampled_from([10_001, 100_001, 1_000_001]))
    if op == "wrap":
        return _unshared(draw(st.sampled_from([[node], {"value": node}, [node, node]])))
    if op == "add-key" and isinstance(node, dict):
        return {**node, draw(odd_text()): draw(json_values(5))}
    return _DELETE


_DELETE = object()


def _apply(document: Any, path: Path_, new: Any) -> Any:
    if not path:
        return None if new is _DELETE else new
    parent = _get(document, path[:-1])
    if new is _DELETE:
        del parent[path[-1]]
    else:
        parent[path[-1]] = new
    return document


def structural_edit(draw: Draw, document: Any) -> Any:
    """One edit of a JSON document (a deep copy is edited)."""
    document = _unshared(document)
    path = draw(st.sampled_from(node_paths(document)))
    return _apply(document, path, _replacement(draw, _get(document, path)))


def json_text(draw: Draw, document: Any) -> bytes:
    """The document as bytes: markers expanded, maybe not ASCII (lone surrogates then make invalid UTF-8)."""
    ascii_only = draw(st.booleans())
    text = json.dumps(document, ensure_ascii=ascii_only, indent=draw(st.sampled_from([None, 1])))
    return expand(text).encode("utf-8", "surrogatepass")


@st.composite
def mutated_json(draw: Draw, document: Any, max_edits: int = 3) -> bytes:
    for _ in range(draw(st.integers(1, max_edits))):
        document = structural_edit(draw, document)
    data = json_text(draw, document)
    return draw(mutated_bytes(data)) if draw(st.booleans()) else data


@st.composite
def mutated_jsonl(draw: Draw, rows: list[Any]) -> bytes:
    """A JSON-lines file from `rows`, one line edited (or lines deleted, duplicated, torn), then maybe bytes."""
    lines = [json.dumps(row).encode() for row in rows]
    op = draw(st.sampled_from(["edit", "edit", "delete", "duplicate", "torn", "blank", "bytes"]))
    at = draw(st.integers(0, max(len(lines) - 1, 0)))
    if op == "edit" and lines:
        lines[at] = draw(mutated_json(rows[at]))
    elif op == "delete" and lines:
        del lines[at]
    elif op == "duplicate" and lines:
        lines[at : at + 1] = [lines[at]] * _copies(draw, len(lines[at]), [2, 1_000, 20_000])
    elif op == "torn" and lines:
        lines[-1] = lines[-1][: draw(st.integers(0, len(lines[-1])))]
    elif op == "blank":
        lines.insert(at, draw(st.sampled_from([b"", b"   ", b"\x00", b"\xff"])))
    data = b"\n".join(lines) + draw(st.sampled_from([b"\n", b""]))
    return draw(mutated_bytes(data)) if op == "bytes" or draw(st.booleans()) else data


# ---- XML -------------------------------------------------------------------------------------------------------------

_ATTRIBUTE = re.compile(rb'([A-Za-z_:][\w:.-]*)="([^"]*)"')
_TAG = re.compile(rb"<(/?)([A-Za-z_][\w:.-]*)")
ODD_ATTRIBUTE_VALUES = [
    b"nan",
    b"inf",
    b"-inf",
    b"1e999",
    b"-1",
    b"0",
    b"",
    b"0 0",
    b"1 2 3 4 5",
    b"9" * 400,
    b"1e308 1e308 1e308",
    b"0 0 0 0",
    b"../x.stl",
    b"/etc/passwd",
    b"a.STL",
    b"x.obj",
    b"100000",
    b"&#0;",
    b"\xc3\xa9",
]
ATTRIBUTE_NAMES = [
    b"file",
    b"meshdir",
    b"assetdir",
    b"texturedir",
    b"builtin",
    b"pos",
    b"quat",
    b"euler",
    b"type",
    b"content_type",
    b"offwidth",
    b"width",
    b"height",
    b"name",
    b"fileup",
    b"params",
]
TAGS = [
    b"mujoco",
    b"body",
    b"geom",
    b"mesh",
    b"texture",
    b"freejoint",
    b"joint",
    b"include",
    b"model",
    b"plugin",
    b"replicate",
    b"composite",
    b"flex",
    b"frame",
    b"hfield",
    b"skin",
    b"worldbody",
]
SNIPPETS = [
    b'<!DOCTYPE x [<!ENTITY a "aaaaaaaaaa">]>',
    b'<include file="x.xml"/>',
    b'<body name="block" pos="0 0 0"><freejoint/></body>',
    b'<body name="intruder" pos="0 0 1"><freejoint/><geom size="0.1"/></body>',
    b"<body>" * 20 + b"</body>" * 20,
    b'<texture name="t" type="2d" builtin="checker" width="100000" height="100000"/>',
    b'<mesh name="m" file="../../../../etc/passwd"/>',
    b'<mesh name="n" vertex="0 0 0 1 0 0 0 1 0 0 0 1"/>',
    b"<![CDATA[x]]>",
    b"<?pi x?>",
    b"&a;",
    b"<mujoco/>",
    b"<!-- -->",
    b"\xff",
]


def _xml_edit(draw: Draw, data: bytes) -> bytes:
    op = draw(st.sampled_from(["value", "name", "tag", "line-delete", "line-copy", "line-swap", "snippet"]))
    if op in ("value", "name"):
        found = list(_ATTRIBUTE.finditer(data))
        if found:
            match = draw(st.sampled_from(found))
            group = 2 if op == "value" else 1
            pool = ODD_ATTRIBUTE_VALUES if op == "value" else ATTRIBUTE_NAMES
            new = draw(st.sampled_from(pool) | odd_text().map(lambda t: t.encode("utf-8", "surrogatepass")))
            return data[: match.start(group)] + new + data[match.end(group) :]
    if op == "tag":
        found = list(_TAG.finditer(data))
        if found:
            match = draw(st.sampled_from(found))
            return data[: match.start(2)] + draw(st.sampled_from(TAGS)) + data[match.end(2) :]
    lines = data.split(b"\n")
    at = draw(st.integers(0, len(lines) - 1))
    if op == "line-delete":
        del lines[at]
    elif op == "line-copy":
        lines[at : at + 1] = [lines[at]] * _copies(draw, len(lines[at]), [2, 100, 10_000])
    elif op == "line-swap":
        other = draw(st.integers(0, len(lines) - 1))
        lines[at], lines[other] = lines[other], lines[at]
    else:
        lines.insert(at, draw(st.sampled_from(SNIPPETS)))
    return b"\n".join(lines)


@st.composite
def mutated_xml(draw: Draw, data: bytes, max_edits: int = 3) -> bytes:
    for _ in range(draw(st.integers(1, max_edits))):
        data = _xml_edit(draw, data)
    return draw(mutated_bytes(data)) if draw(st.booleans()) else data
