"""Reading untrusted library files within fixed bounds: nesting depth and expanded size (file size:
`physcensis.fileio.read_bounded`).

`yaml.safe_load` recurses once per nesting level (10,000 levels raise RecursionError)
and still expands aliases: a "billion laughs" document of a few hundred bytes loads
quickly, as shared Python objects, but stands for 10^9 values once anything walks it.
`BoundedLoader` composes without deep recursion: a list or mapping nested deeper than
MAX_DEPTH is skipped and replaced by a `Refused` marker.  `value_problem` then tells,
per value (one library entry, say), whether it holds such a marker, nests too deeply,
refers to itself, or expands to more than a bound - without expanding anything, so one
hostile entry fails on its own and the rest of the library still loads.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import yaml
from yaml.scanner import ScannerError

from physcensis.fileio import BoundError

MAX_DEPTH = 64  # nesting levels; a real library uses about five
MAX_VALUE_NODES = 10_000  # values in one entry, counting each alias expansion
MAX_SCAN_DEPTH = 20_000  # deeper nesting is not even scanned (about 3 s): the whole file is refused
REFUSED_TAG = "tag:physcensis,2026:refused"


@dataclass(frozen=True)
class Refused:
    """Stands in for a part of a document that was not read; `reason` says why."""

    reason: str


class BoundedLoader(yaml.SafeLoader):
    """A SafeLoader that skips lists and mappings nested deeper than `max_depth`, leaving a `Refused` marker."""

    max_depth = MAX_DEPTH

    def __init__(self, stream: Any) -> None:
        super().__init__(stream)
        self._depth = 0

    def compose_node(self, parent: yaml.Node | None, index: Any) -> yaml.Node | None:
        if self._depth >= self.max_depth and self.check_event(yaml.SequenceStartEvent, yaml.MappingStartEvent):
            return self._skip_collection()
        self._depth += 1
        try:
            return super().compose_node(parent, index)
        finally:
            self._depth -= 1

    # PyYAML scans each token against every open flow level (quadratic in nesting: 10,000 levels take
    # a minute).  Its simple-key table is ordered by position, oldest first, so both scans can stop early.
    def next_possible_simple_key(self) -> int | None:
        for key in self.possible_simple_keys.values():
            return key.token_number
        return None

    def stale_possible_simple_keys(self) -> None:
        keys = self.possible_simple_keys
        while keys:
            level, key = next(iter(keys.items()))
            if key.line == self.line and self.index - key.index <= 1024:
                return  # every later key is newer, so not stale either
            if key.required:
                raise ScannerError(
                    "while scanning a simple key", key.mark, "could not find expected ':'", self.get_mark()
                )
            del keys[level]

    def fetch_flow_collection_start(self, token_class: type) -> None:
        if self.flow_level >= MAX_SCAN_DEPTH:
            raise BoundError(f"nested more than {MAX_SCAN_DEPTH:,} levels deep")
        super().fetch_flow_collection_start(token_class)

    def add_indent(self, column: int) -> bool:
        if len(self.indents) >= MAX_SCAN_DEPTH:
            raise BoundError(f"nested more than {MAX_SCAN_DEPTH:,} levels deep")
        return super().add_indent(column)

    def _skip_collection(self) -> yaml.Node:
        """Consume one list or mapping without recursion; its anchors (and it) become the marker."""
        start = self.get_event()
        marker = yaml.ScalarNode(REFUSED_TAG, f"nested more than {self.max_depth} levels deep", start.start_mark)
        level = 1
        if start.anchor is not None:
            self.anchors[start.anchor] = marker
        while level:
            event = self.get_event()
            if isinstance(event, yaml.SequenceStartEvent | yaml.MappingStartEvent):
                level += 1
            elif isinstance(event, yaml.SequenceEndEvent | yaml.MappingEndEvent):
                level -= 1
            anchor = getattr(event, "anchor", None)
            if anchor is not None and not isinstance(event, yaml.AliasEvent):
                self.anchors[anchor] = marker
        return marker


def _construct_refused(loader: yaml.SafeLoader, node: yaml.ScalarNode) -> Refused:
    return Refused(str(loader.construct_scalar(node)))


BoundedLoader.add_constructor(REFUSED_TAG, _construct_refused)


def load_yaml(text: str) -> Any:
    """One YAML document; parts nested deeper than MAX_DEPTH come back as `Refused` markers."""
    loader = BoundedLoader(text)
    try:
        return loader.get_single_data()
    finally:
        loader.dispose()


def _children(value: dict | list) -> list[Any]:
    return [item for pair in value.items() for item in pair] if isinstance(value, dict) else list(value)


def value_problem(value: Any, max_depth: int = MAX_DEPTH, max_nodes: int = MAX_VALUE_NODES) -> str | None:
    """Why `value` cannot be used - a `Refused` part, nesting deeper than `max_depth`, a list or mapping that
    contains itself, more than `max_nodes` values once shared (aliased) parts are counted at each use - or None.

    Iterative, and each shared list or mapping is measured once: the work is linear in the document's text.
    """
    sizes: dict[int, tuple[int, int]] = {}  # id -> (values when expanded, levels)
    on_path: set[int] = set()
    stack: list[tuple[Any, int, bool]] = [(value, 1, False)]
    while stack:
        item, depth, finished = stack.pop()
        if isinstance(item, Refused):
            return item.reason
        if not isinstance(item, dict | list):
            continue
        key = id(item)
        if finished:
            on_path.discard(key)
            parts = [sizes.get(id(child), (1, 0)) for child in _children(item)]
            count = 1 + sum(size for size, _ in parts)
            if count > max_nodes:
                return f"more than {max_nodes:,} values, counting each alias expansion (an alias bomb?)"
            sizes[key] = (count, 1 + max((levels for _, levels in parts), default=0))
            continue
        if key in on_path:
            return "a list or mapping contains itself (a recursive alias)"
        if key in sizes:
            if depth + sizes[key][1] - 1 > max_depth:
                return f"nested more than {max_depth} levels deep"
            continue
        if depth > max_depth:
            return f"nested more than {max_depth} levels deep"
        on_path.add(key)
        stack.append((item, depth, True))
        stack.extend((child, depth + 1, False) for child in _children(item))
    return None
