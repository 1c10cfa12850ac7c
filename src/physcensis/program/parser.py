"""Turn program text or JSON data into typed entries.

Shape problems (an entry that is not a list, a predicate that is not a string)
become `Problem`s so the checker can report every problem at once; only text
holding no program at all raises `ProgramParseError`.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from pydantic import ValidationError

from physcensis.errors import ProgramParseError
from physcensis.fileio import BoundError, read_bounded
from physcensis.program.checker import MAX_ITEM_COUNT
from physcensis.program.lenient_json import MAX_DEPTH, MAX_TEXT_CHARS, OversizedNumber, read_lenient, usable_number
from physcensis.program.model import Declaration, Entry, ItemCount, Problem, ProblemLog, Program, Relation, describe
from physcensis.program.registry import PredicateSpec, Role, lookup
from physcensis.program.schema import OBJECT_FORM_KEYS, is_object_form, list_form
from physcensis.scene import MAX_PROMPT_CHARS, Support

_TOP_LEVEL_KEYS = {"program", "support", "prompt", "seed", "format"}
ENTRY_SHAPES = '[id, "description"] or [A, "PREDICATE", B, {params}]'
MAX_PROGRAM_BYTES = MAX_TEXT_CHARS  # a program file is read no further: its text could not be longer
MAX_ENTRIES = 100_000  # entries one program may hold: ten for each object of the largest scene


def parse_program(source: str | list[Any] | dict[str, Any]) -> Program:
    """Read a program from text (strict or LLM-style) or already-parsed JSON data, in the list form or the object
    form ({"objects": [...], "relations": [...]}, see program/schema.py)."""
    data = read_lenient(source) if isinstance(source, str) else source
    problems = ProblemLog()
    support: Support | None = None
    prompt: str | None = None
    if isinstance(data, dict):
        if is_object_form(data):
            envelope = {key: value for key, value in data.items() if key not in OBJECT_FORM_KEYS}
            data = {**envelope, "program": list_form(data)}
        support, prompt = _read_envelope(data, problems)
        data = data["program"]
        if isinstance(data, dict) and is_object_form(data):
            data = list_form(data)
    if not isinstance(data, list):
        raise ProgramParseError(f"a program is a list of entries, got {type(data).__name__}")
    if len(data) > MAX_ENTRIES:
        raise ProgramParseError(f"the program holds {len(data):,} entries; a program may hold at most {MAX_ENTRIES:,}")
    entries: list[Entry] = []
    for index, raw in enumerate(data, start=1):
        entry = _read_entry(index, raw, problems)
        if entry is not None:
            entries.append(entry)
    if not data:
        problems.append(Problem(None, None, "error", "the program is empty: declare objects and place them", "empty"))
    return Program(tuple(entries), support, prompt, problems.listed())


def _read_envelope(data: dict[str, Any], problems: ProblemLog) -> tuple[Support | None, str | None]:
    """The support and prompt of an object program ({"program": [...], "support": ..., "prompt": ...})."""
    if "program" not in data:
        raise ProgramParseError('an object program needs a "program" key holding the list of entries')
    for key in sorted(set(data) - _TOP_LEVEL_KEYS, key=str):
        problems.append(Problem(None, None, "warning", f"unknown top-level key {key!r} is ignored", "unknown-key"))
    support, support_problem = _read_support(data.get("support"))
    if support_problem:
        problems.append(support_problem)
    prompt = data.get("prompt")
    if not isinstance(prompt, str):
        return support, None
    if len(prompt) > MAX_PROMPT_CHARS or not _encodable(prompt):
        problems.append(
            Problem(
                None,
                None,
                "error",
                f"the prompt is {len(prompt)} characters of text a scene "
                f"cannot hold (at most {MAX_PROMPT_CHARS}, valid unicode)",
                "bad-prompt",
            )
        )
        return support, None
    return support, prompt


def load_program(path: str | Path) -> Program:
    """The program in a file; a folder, device, FIFO or file over MAX_PROGRAM_BYTES is refused unread."""
    path = Path(path)
    try:
        text = read_bounded(path, MAX_PROGRAM_BYTES, "program file").decode("utf-8")
    except BoundError as exc:
        raise ProgramParseError(f"{path}: cannot read: {exc}") from None
    except UnicodeDecodeError as exc:
        raise ProgramParseError(f"{path}: cannot read ({exc.__class__.__name__}: {exc})") from None
    try:
        return parse_program(text)
    except ProgramParseError as exc:
        raise ProgramParseError(f"{path}: {exc}") from None


def _read_support(raw: Any) -> tuple[Support | None, Problem | None]:
    if raw is None:
        return None, None
    try:
        return Support.model_validate(raw), None
    except ValidationError as exc:
        err = exc.errors()[0]
        where = ".".join(str(p) for p in ("support", *err["loc"]))
        message = err["msg"].removeprefix("Value error, ")
        return None, Problem(None, None, "error", f"{where}: {message}", "bad-support")


def _encodable(text: str) -> bool:
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        return False
    return True


class _TooDeep(Exception):
    pass


def _usable_numbers(value: Any, depth: int = 0) -> Any:
    """`value` with integers too large to use replaced by OversizedNumber (data from Python or strict JSON can
    hold any integer; converting or printing one of thousands of digits raises)."""
    if depth > MAX_DEPTH:
        raise _TooDeep
    if isinstance(value, bool):
        return value
    if isinstance(value, int):
        return usable_number(value)
    if isinstance(value, list):
        return [_usable_numbers(v, depth + 1) for v in value]
    if isinstance(value, dict):
        return {_usable_numbers(k, depth + 1): _usable_numbers(v, depth + 1) for k, v in value.items()}
    return value


class _BadEntry(Exception):
    """An entry of the wrong shape: it is left out and reported as a Problem of rule `rule` about `obj`."""

    def __init__(self, message: str, obj: str | None = None, rule: str = "bad-entry") -> None:
        super().__init__(message)
        self.obj = obj
        self.rule = rule


def _read_entry(index: int, raw: Any, problems: ProblemLog) -> Entry | None:
    try:
        return _entry(index, raw)
    except _BadEntry as exc:
        problems.append(Problem(index, exc.obj, "error", str(exc), exc.rule))
        return None


def _entry(index: int, raw: Any) -> Entry:
    try:
        raw = _usable_numbers(raw)
    except _TooDeep:
        raise _BadEntry(f"the entry is nested deeper than {MAX_DEPTH} levels; write it as {ENTRY_SHAPES}") from None
    if not isinstance(raw, list) or not 2 <= len(raw) <= 4:
        raise _BadEntry(f"entry {describe(raw)} is not of the form {ENTRY_SHAPES}")
    if len(raw) == 2:
        return _declaration(index, raw[0], raw[1])
    return _relation(index, raw)


def _declaration(index: int, first: Any, second: Any) -> Declaration:
    if not isinstance(first, str):
        raise _BadEntry(f'a declaration is [id, "description"]; the id {describe(first)} is not a string')
    if isinstance(second, str) and lookup(second) is not None:
        raise _BadEntry(
            f'{second} needs a target: write [{first!r}, {second!r}, "root" or an object id, {{}}]',
            first,
            "missing-target",
        )
    if not isinstance(second, str):
        raise _BadEntry(f"the description of {first} must be a string, got {describe(second)}", first, "no-description")
    return Declaration(index, first, second)


def _relation(index: int, raw: list[Any]) -> Relation:
    """[subject, "PREDICATE", target] or [subject, "PREDICATE", target, {params}]."""
    first, predicate = raw[0], raw[1]
    subject_name = first if isinstance(first, str) else None
    if not isinstance(predicate, str):
        raise _BadEntry(f"the predicate name must be a string, got {describe(predicate)}", subject_name)
    spec = lookup(predicate)
    name = spec.name if spec else predicate
    params = _params(name, raw[3] if len(raw) == 4 else None, subject_name)
    subject = _subject(name, spec, first)
    target = _target(name, spec, raw[2], subject_name)
    return Relation(index, subject, name, target, params, spec)


def _params(name: str, raw: Any, subject_name: str | None) -> dict[str, Any]:
    if raw is None:
        return {}
    if not isinstance(raw, dict):
        raise _BadEntry(
            f'{name}\'s parameters must be an object like {{"distance": 0.1}}, got {describe(raw)}',
            subject_name,
            "bad-params",
        )
    return dict(raw)


def _subject(name: str, spec: PredicateSpec | None, raw: Any) -> str | tuple[ItemCount | str, ...]:
    """An object id, or for predicates that take items (PLACE-IN) the items as a tuple."""
    if spec is None or Role.ITEMS not in spec.subject:
        if not isinstance(raw, str):
            raise _BadEntry(f"the subject of {name} must be an object id, got {describe(raw)}")
        return raw
    items = _read_items(raw)
    if isinstance(items, str):
        raise _BadEntry(items, None, "param-range")
    if items is None:
        raise _BadEntry(
            f"{name} takes an id, a list of ids, or a list of [category, count] pairs "
            f'such as [["apple", 3]]; got {describe(raw)}',
            None,
            "bad-items",
        )
    return items


def _target(name: str, spec: PredicateSpec | None, raw: Any, subject_name: str | None) -> str | tuple[str, ...]:
    """\"root\" or an object id, or for predicates that take members (GROUP) the member ids as a tuple."""
    if spec is None or Role.MEMBERS not in spec.target:
        if not isinstance(raw, str):
            raise _BadEntry(f'the target of {name} must be "root" or an object id, got {describe(raw)}', subject_name)
        return raw
    if not isinstance(raw, list) or not all(isinstance(t, str) for t in raw):
        raise _BadEntry(
            f"{name} takes a list of member ids as its third element, got {describe(raw)}", subject_name, "bad-members"
        )
    return tuple(raw)


def _read_items(raw: Any) -> tuple[ItemCount | str, ...] | str | None:
    """The items of PLACE-IN; None for a wrong shape, or a message for a count too large to use."""
    if isinstance(raw, str):
        return (raw,)
    if not isinstance(raw, list) or not raw:
        return None
    items: list[ItemCount | str] = []
    for item in raw:
        if isinstance(item, str):
            items.append(item)
        elif (
            isinstance(item, list)
            and len(item) == 2
            and isinstance(item[0], str)
            and isinstance(item[1], int)
            and not isinstance(item[1], bool)
        ):
            items.append(ItemCount(item[0], item[1]))
        elif isinstance(item, list) and len(item) == 2 and isinstance(item[1], OversizedNumber):
            return (
                f"PLACE-IN count for {describe(item[0])} is {item[1]!r}; it must be a whole number "
                f"between 1 and {MAX_ITEM_COUNT}"
            )
        else:
            return None
    return tuple(items)
