"""Read the JSON-like text an LLM really writes.

Accepts prose around the data, code fences, missing commas between adjacent
values, trailing commas, single quotes, Python's True/False/None, bare words
as strings, and `//`, `#` and `/* */` comments. It never evaluates anything:
it is a small tokenizer and recursive-descent reader with a depth limit.
"""

from __future__ import annotations

import itertools
import json
import re
from typing import Any

from physcensis.bounded_json import VALUE_ALLOWANCE, value_limit
from physcensis.errors import ProgramParseError
from physcensis.program.schema import OBJECT_FORM_KEYS

MAX_TEXT_CHARS = 20_000_000
MAX_DEPTH = 64
MAX_CANDIDATES = 200
# Integers longer than this are never a usable quantity, and past ~4300 digits int() refuses them outright.
MAX_NUMBER_DIGITS = 300
MAX_NUMBER_BITS = 996  # the same bound for integers given as data: 2**996 < 10**300

_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
_WORD = re.compile(r"[A-Za-z_+\-][A-Za-z0-9_.+\-]*")
_FENCE = re.compile(r"```[^\n`]*\n?(.*?)(?:```|\Z)", re.DOTALL)
_CONSTANTS: dict[str, Any] = {
    "true": True,
    "false": False,
    "null": None,
    "True": True,
    "False": False,
    "None": None,
    "NaN": float("nan"),
    "nan": float("nan"),
    "Infinity": float("inf"),
    "+Infinity": float("inf"),
    "-Infinity": float("-inf"),
    "inf": float("inf"),
    "-inf": float("-inf"),
}
_NOT_SPACE = re.compile(r"\S")
_STRING_STOP = {'"': re.compile(r'["\\]'), "'": re.compile(r"['\\]")}
_ESCAPES = {"n": "\n", "t": "\t", "r": "\r", "b": "\b", "f": "\f", "/": "/", "\\": "\\", '"': '"', "'": "'"}


class OversizedNumber(float):
    """A number too large to use (`1e999`, an integer of thousands of digits). It is infinite, so every range
    check refuses it, and it describes itself by its size instead of its digits."""

    description: str

    def __new__(cls, text: str) -> OversizedNumber:
        self = super().__new__(cls, float("-inf") if text.lstrip().startswith("-") else float("inf"))
        if any(c in text for c in ".eE"):
            self.description = f"{text if len(text) <= 24 else text[:20] + '...'} (too large a number)"
        else:
            sign = "a negative " if text.lstrip().startswith("-") else "an "
            self.description = f"{sign}integer of {sum(c.isdigit() for c in text)} digits (too large a number)"
        return self

    @classmethod
    def of_int(cls, value: int) -> OversizedNumber:
        """An integer too large to use, described without converting it to text (which Python refuses)."""
        digits = int(value.bit_length() * 0.30103) + 1
        number = cls("-1" if value < 0 else "1")
        sign = "a negative" if value < 0 else "an"
        number.description = f"{sign} integer of about {digits} digits (too large a number)"
        return number

    def __reduce__(self) -> tuple[Any, ...]:  # pickling and copying: rebuilt from its sign, then its description
        return (OversizedNumber, ("-1e999" if self < 0 else "1e999",), self.__dict__)

    def __repr__(self) -> str:
        return self.description

    __str__ = __repr__

    def __format__(self, spec: str) -> str:
        return repr(self)


def usable_number(value: int) -> int | float:
    """`value`, or an OversizedNumber when it is an integer too large to use (digit-limit- and overflow-safe)."""
    return OversizedNumber.of_int(value) if value.bit_length() > MAX_NUMBER_BITS else value


def read_number(literal: str) -> int | float:
    """The value of a JSON number literal; OversizedNumber when it is too large to use (never an exception)."""
    if any(c in literal for c in ".eE"):
        value = float(literal)
        return value if value not in (float("inf"), float("-inf")) else OversizedNumber(literal)
    if len(literal.lstrip("+-")) > MAX_NUMBER_DIGITS:
        return OversizedNumber(literal)
    return int(literal)


class _Fail(Exception):
    """A candidate that does not read as data; the caller tries the next one."""

    def __init__(self, message: str, position: int) -> None:
        super().__init__(message)
        self.position = position


class _Reader:
    def __init__(self, text: str, start: int) -> None:
        self.text = text
        self.pos = start

    # -- lexical -----------------------------------------------------------
    def _skip_space_and_comments(self) -> None:
        text, n = self.text, len(self.text)
        while self.pos < n:
            visible = _NOT_SPACE.search(text, self.pos)
            self.pos = n if visible is None else visible.start()
            if text.startswith("#", self.pos) or text.startswith("//", self.pos):
                end = text.find("\n", self.pos)
                self.pos = n if end < 0 else end + 1
            elif text.startswith("/*", self.pos):
                end = text.find("*/", self.pos + 2)
                self.pos = n if end < 0 else end + 2
            else:
                return

    def peek(self) -> str:
        self._skip_space_and_comments()
        return self.text[self.pos] if self.pos < len(self.text) else ""

    def _string(self, quote: str) -> str:
        text = self.text
        stop = _STRING_STOP[quote]
        self.pos += 1
        out: list[str] = []
        while True:
            match = stop.search(text, self.pos)
            if match is None:
                raise _Fail("unterminated string", self.pos)
            out.append(text[self.pos : match.start()])
            self.pos = match.end()
            if match.group() == quote:
                return "".join(out)
            nxt = text[self.pos : self.pos + 1]  # after a backslash
            if nxt == "u" and re.fullmatch(r"[0-9a-fA-F]{4}", text[self.pos + 1 : self.pos + 5]):
                out.append(chr(int(text[self.pos + 1 : self.pos + 5], 16)))
                self.pos += 5
            elif nxt:
                out.append(_ESCAPES.get(nxt, nxt))
                self.pos += 1

    # -- grammar -----------------------------------------------------------
    def value(self, depth: int = 0) -> Any:
        if depth > MAX_DEPTH:
            raise _Fail(f"nested deeper than {MAX_DEPTH} levels", self.pos)
        ch = self.peek()
        if not ch:
            raise _Fail("unexpected end of text", self.pos)
        if ch == "[":
            return self._array(depth)
        if ch == "{":
            return self._object(depth)
        if ch in "\"'":
            return self._string(ch)
        number = _NUMBER.match(self.text, self.pos)
        word = _WORD.match(self.text, self.pos)
        if number and not (word and len(word.group()) > len(number.group())):
            self.pos = number.end()
            return read_number(number.group())
        if word:
            self.pos = word.end()
            token = word.group()
            return _CONSTANTS[token] if token in _CONSTANTS else token
        raise _Fail(f"unexpected character {ch!r}", self.pos)

    def _array(self, depth: int) -> list[Any]:
        self.pos += 1
        items: list[Any] = []
        while True:
            ch = self.peek()
            if not ch:
                raise _Fail("a list is never closed with ']'", self.pos)
            if ch == "]":
                self.pos += 1
                return items
            if ch == ",":
                self.pos += 1
                continue
            if ch in "}:":
                raise _Fail(f"unexpected {ch!r} in a list", self.pos)
            items.append(self.value(depth + 1))  # a missing comma between values is forgiven

    def _object(self, depth: int) -> dict[str, Any]:
        self.pos += 1
        result: dict[str, Any] = {}
        while True:
            ch = self.peek()
            if not ch:
                raise _Fail("an object is never closed with '}'", self.pos)
            if ch == "}":
                self.pos += 1
                return result
            if ch == ",":
                self.pos += 1
                continue
            if ch in "[{]:":
                raise _Fail(f"unexpected {ch!r} where a key was expected", self.pos)
            key = self.value(depth + 1)
            if self.peek() != ":":
                raise _Fail("expected ':' after a key", self.pos)
            self.pos += 1
            result[str(key)] = self.value(depth + 1)

    def sequence(self) -> list[Any]:
        """Successive values (a program written without its outer brackets)."""
        items: list[Any] = []
        while True:
            ch = self.peek()
            if ch == ",":
                self.pos += 1
                continue
            if not ch or ch not in "[{":
                return items
            saved = self.pos
            try:
                items.append(self.value(1))
            except _Fail:
                self.pos = saved
                return items


def _looks_like_program(value: Any) -> bool:
    if isinstance(value, dict):  # the envelope, or the object form (program/schema.py)
        return "program" in value or any(key in value for key in OBJECT_FORM_KEYS)
    return isinstance(value, list) and (not value or any(isinstance(v, list) for v in value))


def _looks_like_entry(value: Any) -> bool:
    """One program entry on its own, e.g. `["cup_0", "a white mug"]`."""
    return (
        isinstance(value, list)
        and 2 <= len(value) <= 4
        and isinstance(value[0], (str, list))
        and isinstance(value[1], str)
    )


def _sources(text: str) -> list[str]:
    fenced = [m.group(1) for m in _FENCE.finditer(text) if "[" in m.group(1) or "{" in m.group(1)]
    return [*fenced, text]


# The string alternative is the unrolled loop ("[^"\\]*(\\.[^"\\]*)*"): a run of plain characters is one step of
# the regex engine, where (?:[^"\\]|\\.)* takes one per character and kept ~120 bytes each (a 1 MB string: 120 MB).
_BRACKET_OR_STRING = re.compile(r'"[^"\\\n]*(?:\\.[^"\\\n]*)*"|[\[\]{}]')


def _refuse_too_many_values(text: str) -> None:
    """Refuse text with more brackets, commas and colons than a text of its size may hold values
    (`bounded_json.value_limit`): parsing it would cost tens of bytes for each. Counted inside strings too, as the
    lenient reader does not trust where a model's strings end."""
    if len(text) <= VALUE_ALLOWANCE:
        return
    marks = sum(text.count(mark) for mark in "[{,:")
    if marks > value_limit(len(text)):
        raise ProgramParseError(
            f"the text holds {marks:,} brackets, commas and colons; a program of {len(text):,} characters may "
            f"hold at most {value_limit(len(text)):,} values"
        )


def _refuse_deep_nesting(text: str) -> None:
    """Refuse text nested deeper than MAX_DEPTH anywhere (brackets inside double-quoted strings do not count),
    naming where: a reader would otherwise skip that part and read the rest as if it were whole."""
    level = 0
    for match in _BRACKET_OR_STRING.finditer(text):
        token = text[match.start()]  # a bracket, or the quote a string starts with (not the string: no copy)
        if token in "[{":
            level += 1
            if level > MAX_DEPTH:
                line = text.count("\n", 0, match.start()) + 1
                column = match.start() - (text.rfind("\n", 0, match.start()) + 1) + 1
                raise ProgramParseError(
                    f"nested deeper than {MAX_DEPTH} levels at line {line}, column {column}; an "
                    'entry is [id, "description"] or [A, "PREDICATE", B, {params}]'
                )
        elif token in "]}":
            level = max(0, level - 1)


def read_lenient(text: str) -> Any:
    """The first program-shaped value in `text` (a list of entries, or an object with `program`, `objects` or
    `relations`)."""
    if not isinstance(text, str):
        raise ProgramParseError(f"expected text, got {type(text).__name__}")
    if len(text) > MAX_TEXT_CHARS:
        raise ProgramParseError(f"text is {len(text)} characters long; the limit is {MAX_TEXT_CHARS}")
    text = text.lstrip("\ufeff")
    _refuse_too_many_values(text)
    _refuse_deep_nesting(text)
    strict = _strict_program(text)
    return strict if strict is not None else _lenient_program(text)


def _strict_program(text: str) -> Any:
    """The program when `text` is strict JSON holding one (the fast path), else None."""
    try:
        value = json.loads(text, parse_int=read_number, parse_float=read_number)
    except (ValueError, RecursionError):
        return None
    return value if _looks_like_program(value) else None


def _lenient_program(text: str) -> Any:
    """The first program read leniently from a fenced block or the whole text, trying each '[' or '{' in turn;
    failing that, the first list or object read at all."""
    last_error: _Fail | None = None
    fallback: Any = None
    for source in _sources(text):
        for match in itertools.islice(re.finditer(r"[\[{]", source), MAX_CANDIDATES):
            try:
                value = _Reader(source, match.start()).value()
            except _Fail as exc:
                last_error = exc
                continue
            program = _program_from(source, match.start(), value)
            if program is not None:
                return program
            if fallback is None and isinstance(value, (list, dict)):
                fallback = value
    if fallback is not None:
        return fallback
    if last_error is not None:
        line = text.count("\n", 0, min(last_error.position, len(text))) + 1
        raise ProgramParseError(f"no program found: {last_error} (near line {line})")
    raise ProgramParseError("no program found: the text contains no '[' list of predicates")


def _program_from(source: str, start: int, value: Any) -> Any:
    """The program `value` (read at `start`) is or begins, else None: one entry starts the sequence of entries
    written without outer brackets."""
    if _looks_like_entry(value):
        entries = _Reader(source, start).sequence()
        if entries:
            return entries
    return value if _looks_like_program(value) else None
