"""A predicate program as typed entries, and the problems found in it."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Literal

from physcensis.errors import one_line
from physcensis.program.registry import PredicateSpec
from physcensis.scene import Support

Severity = Literal["error", "warning"]
MAX_PROBLEMS = 1000  # errors, and warnings, kept for one program; the rest are counted


def printable(text: str) -> str:
    """`text` as one line that prints: control characters and anything UTF-8 cannot encode (a lone surrogate)
    written as backslash escapes."""
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        text = text.encode("utf-8", "backslashreplace").decode("utf-8")
    return one_line(text)


def describe(value: Any, limit: int = 60) -> str:
    """A value for a message: its repr, cut to `limit` characters (never an error, whatever the value)."""
    try:
        text = repr(value)
    except (ValueError, RecursionError):  # an integer past Python's digit limit, data nested too deep
        text = f"<a {type(value).__name__} too large to show>"
    return text if len(text) <= limit else text[: limit - 3] + "..."


@dataclass(frozen=True)
class Problem:
    """One thing wrong with a program, worded for the agent that wrote it."""

    index: int | None  # 1-based entry index; None for the file as a whole
    object: str | None
    severity: Severity
    message: str
    rule: str  # a stable code, e.g. "unknown-predicate"

    def __post_init__(self) -> None:
        # Lone surrogates (JSON "\ud800") cannot be printed or written as UTF-8: show them as escapes.
        object.__setattr__(self, "message", printable(self.message))
        if self.object is not None:
            object.__setattr__(self, "object", printable(self.object))

    def to_dict(self) -> dict[str, Any]:
        return {
            "index": self.index,
            "object": self.object,
            "severity": self.severity,
            "message": self.message,
            "rule": self.rule,
        }

    def __str__(self) -> str:
        where = f"#{self.index}" if self.index is not None else "program"
        who = f" {self.object}" if self.object else ""
        return f"{self.severity} at {where}{who}: {self.message}"


class ProblemLog:
    """Problems in the order they are found: the first MAX_PROBLEMS errors and the first MAX_PROBLEMS warnings are
    kept (warnings never crowd out an error), the rest only counted (a program of a million broken entries would
    otherwise hold a million messages), and `listed` ends with one problem saying how many more there were."""

    def __init__(self, first: tuple[Problem, ...] | list[Problem] = ()) -> None:
        self.kept: list[Problem] = []
        self.kept_errors = self.kept_warnings = self.more_errors = self.more_warnings = 0
        for problem in first:
            self.append(problem)

    def append(self, problem: Problem) -> None:
        error = problem.severity == "error"
        if problem.rule == MORE_PROBLEMS or (self.kept_errors if error else self.kept_warnings) < MAX_PROBLEMS:
            self.kept.append(problem)  # (an earlier log's count stays listed)
            self.kept_errors += error
            self.kept_warnings += not error
        elif error:
            self.more_errors += 1
        else:
            self.more_warnings += 1

    def listed(self, order: Callable[[Problem], Any] | None = None) -> tuple[Problem, ...]:
        """The kept problems (sorted by `order` when given), then the count of the others if there were any."""
        kept = sorted(self.kept, key=order) if order is not None else list(self.kept)
        if not self.more_errors and not self.more_warnings:
            return tuple(kept)
        severity: Severity = "error" if self.more_errors else "warning"
        message = (
            f"and {self.more_errors} more errors and {self.more_warnings} more warnings, not listed "
            f"(the first {MAX_PROBLEMS} of each are)"
        )
        return (*kept, Problem(None, None, severity, message, MORE_PROBLEMS))


MORE_PROBLEMS = "more-problems"  # the rule of the problem that counts those not listed


@dataclass(frozen=True)
class ItemCount:
    """`["apple", 3]` inside PLACE-IN: make three apples from the catalogue."""

    category: str
    count: int


@dataclass(frozen=True)
class Declaration:
    index: int
    object_id: str
    description: str

    def to_json(self) -> list[Any]:
        return [self.object_id, self.description]


@dataclass(frozen=True)
class Relation:
    index: int
    subject: Any  # str, or for PLACE-IN a tuple of ids / ItemCounts, kept as written otherwise
    predicate: str  # canonical name when known, else as written
    target: Any  # str, or for GROUP a tuple of member ids
    params: dict[str, Any]
    spec: PredicateSpec | None

    def to_json(self) -> list[Any]:
        subject: Any = self.subject
        if isinstance(subject, tuple):
            subject = [[s.category, s.count] if isinstance(s, ItemCount) else s for s in subject]
        target = list(self.target) if isinstance(self.target, tuple) else self.target
        return [subject, self.predicate, target, dict(self.params)]


Entry = Declaration | Relation


@dataclass(frozen=True)
class Program:
    entries: tuple[Entry, ...]
    support: Support | None = None
    prompt: str | None = None
    read_problems: tuple[Problem, ...] = field(default=())  # shape problems found while reading

    def to_json(self) -> list[Any]:
        """The canonical program: a plain JSON list with canonical predicate names."""
        return [entry.to_json() for entry in self.entries]

    @property
    def declarations(self) -> list[Declaration]:
        return [e for e in self.entries if isinstance(e, Declaration)]

    @property
    def relations(self) -> list[Relation]:
        return [e for e in self.entries if isinstance(e, Relation)]
