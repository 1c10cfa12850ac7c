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
from physcensis.program.checker import MAX_ITEM_COUNT
from physcensis.program.lenient_json import MAX_DEPTH, OversizedNumber, read_lenient, usable_number
from physcensis.program.model import Declaration, Entry, ItemCount, Problem, Program, Relation, describe
from physcensis.program.registry import Role, lookup
from physcensis.scene import MAX_PROMPT_CHARS, Support

_TOP_LEVEL_KEYS = {"program", "support", "prompt", "seed", "format"}
ENTRY_SHAPES = '[id, "description"] or [A, "PREDICATE", B, {params}]'


def parse_program(source: str | list[Any] | dict[str, Any]) -> Program:
    """Read a program from text (strict or LLM-style) or already-parsed JSON data."""
    data = read_lenient(source) if isinstance(source, str) else source
    problems: list[Problem] = []
    support: Support | None = None
    prompt: str | None = None
    if isinstance(data, dict):
        if "program" not in data:
            raise ProgramParseError('an object program needs a "program" key holding the list of entries')
        for key in sorted(set(data) - _TOP_LEVEL_KEYS, key=str):
            problems.append(Problem(None, None, "warning", f"unknown top-level key {key!r} is ignored", "unknown-key"))
        support, support_problem = _read_support(data.get("support"))
        if support_problem:
            problems.append(support_problem)
        if isinstance(data.get("prompt"), str):
            prompt = data["prompt"]
            if len(prompt) > MAX_PROMPT_CHARS or not _encodable(prompt):
                problems.append(Problem(None, None, "error", f"the prompt is {len(prompt)} characters of text a scene "
                                        f"cannot hold (at most {MAX_PROMPT_CHARS}, valid unicode)", "bad-prompt"))
                prompt = None
        data = data["program"]
    if not isinstance(data, list):
        raise ProgramParseError(f"a program is a list of entries, got {type(data).__name__}")
    entries: list[Entry] = []
    for index, raw in enumerate(data, start=1):
        entry = _read_entry(index, raw, problems)
        if entry is not None:
            entries.append(entry)
    if not data:
        problems.append(Problem(None, None, "error", "the program is empty: declare objects and place them", "empty"))
    return Program(tuple(entries), support, prompt, tuple(problems))


def load_program(path: str | Path) -> Program:
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
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


def _read_entry(index: int, raw: Any, problems: list[Problem]) -> Entry | None:
    def bad(message: str, obj: str | None = None, rule: str = "bad-entry") -> None:
        problems.append(Problem(index, obj, "error", message, rule))

    try:
        raw = _usable_numbers(raw)
    except _TooDeep:
        bad(f"the entry is nested deeper than {MAX_DEPTH} levels; write it as {ENTRY_SHAPES}")
        return None
    if not isinstance(raw, list) or not 2 <= len(raw) <= 4:
        bad(f"entry {describe(raw)} is not of the form {ENTRY_SHAPES}")
        return None
    first = raw[0]
    subject_name = first if isinstance(first, str) else None
    if len(raw) == 2:
        if not isinstance(first, str):
            bad(f"a declaration is [id, \"description\"]; the id {describe(first)} is not a string")
            return None
        if isinstance(raw[1], str) and lookup(raw[1]) is not None:
            bad(f"{raw[1]} needs a target: write [{first!r}, {raw[1]!r}, \"root\" or an object id, {{}}]",
                first, "missing-target")
            return None
        if not isinstance(raw[1], str):
            bad(f"the description of {first} must be a string, got {describe(raw[1])}", first, "no-description")
            return None
        return Declaration(index, first, raw[1])

    predicate = raw[1]
    if not isinstance(predicate, str):
        bad(f"the predicate name must be a string, got {describe(predicate)}", subject_name)
        return None
    spec = lookup(predicate)
    name = spec.name if spec else predicate
    params = raw[3] if len(raw) == 4 else {}
    if params is None:
        params = {}
    if not isinstance(params, dict):
        bad(f"{name}'s parameters must be an object like {{\"distance\": 0.1}}, got {describe(params)}",
            subject_name, "bad-params")
        return None

    subject: Any = first
    if spec is not None and Role.ITEMS in spec.subject:
        subject = _read_items(first)
        if isinstance(subject, str):
            bad(subject, None, "param-range")
            return None
        if subject is None:
            bad(f"{name} takes an id, a list of ids, or a list of [category, count] pairs "
                f"such as [[\"apple\", 3]]; got {describe(first)}", None, "bad-items")
            return None
    elif not isinstance(first, str):
        bad(f"the subject of {name} must be an object id, got {describe(first)}", None)
        return None

    target: Any = raw[2]
    if spec is not None and Role.MEMBERS in spec.target:
        if not isinstance(target, list) or not all(isinstance(t, str) for t in target):
            bad(f"{name} takes a list of member ids as its third element, got {describe(target)}",
                subject_name, "bad-members")
            return None
        target = tuple(target)
    elif not isinstance(target, str):
        bad(f"the target of {name} must be \"root\" or an object id, got {describe(target)}", subject_name)
        return None
    return Relation(index, subject, name, target, dict(params), spec)


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
            isinstance(item, list) and len(item) == 2 and isinstance(item[0], str)
            and isinstance(item[1], int) and not isinstance(item[1], bool)
        ):
            items.append(ItemCount(item[0], item[1]))
        elif isinstance(item, list) and len(item) == 2 and isinstance(item[1], OversizedNumber):
            return (f"PLACE-IN count for {describe(item[0])} is {item[1]!r}; it must be a whole number "
                    f"between 1 and {MAX_ITEM_COUNT}")
        else:
            return None
    return tuple(items)
