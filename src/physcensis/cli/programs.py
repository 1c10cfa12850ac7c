"""`physcensis check` and `physcensis predicates`: the predicate language."""

from __future__ import annotations

import json
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Annotated

import typer
from rich.markup import escape
from rich.table import Table

from physcensis.cli.errors import finish, reports_errors
from physcensis.cli.options import LibraryOption, MaxObjectsOption, console, support_option, with_libraries
from physcensis.program import DEFAULT_MAX_OBJECTS, Problem, check_program, load_program, parse_program
from physcensis.program.registry import PREDICATES


@reports_errors
def check(
    file: Annotated[Path, typer.Argument(help="program file (.json, or LLM text); '-' reads stdin")],
    as_json: Annotated[bool, typer.Option("--json", help="print problems as JSON")] = False,
    support: Annotated[str | None, typer.Option(help="support to check x/y against, e.g. table:1.2x0.8")] = None,
    max_objects: MaxObjectsOption = DEFAULT_MAX_OBJECTS,
    library: LibraryOption = None,
) -> None:
    """Parse and check a predicate program; exit 0 if it has no errors, 1 if it has, 2 if unreadable. Pinned assets
    ("asset:ID") must be in the catalogue: the built-ins and the user libraries in use."""
    support_override = support_option(support)
    program = parse_program(sys.stdin.read()) if str(file) == "-" else load_program(file)
    known = with_libraries(library).id_set()
    report = check_program(program, support_override, max_objects=max_objects, assets=known)
    if as_json:
        typer.echo(json.dumps([p.to_dict() for p in report.problems], indent=2))
    else:
        if report.problems:
            print_problems(report.problems)
        objects = len(program.declarations)
        verdict = "[green]ok[/]" if report.ok else "[red]has errors[/]"
        counts = f"{len(program.entries)} entries, {objects} declared objects, {report.summary()}"
        console.print(f"{escape(str(file))}: {counts} — {verdict}")
    raise finish(report.ok)


def print_problems(problems: Sequence[Problem]) -> None:
    table = Table(show_header=True, header_style="bold")
    for column in ("#", "object", "severity", "message"):
        table.add_column(column, overflow="fold")
    for p in problems:
        style = "red" if p.severity == "error" else "yellow"
        table.add_row(
            "" if p.index is None else str(p.index),
            escape(p.object or ""),
            f"[{style}]{p.severity}[/]",
            escape(p.message),
        )
    console.print(table)


@reports_errors
def predicates(
    as_json: Annotated[bool, typer.Option("--json", help="print the registry as JSON")] = False,
) -> None:
    """List the predicates the language knows, with their parameters."""
    if as_json:
        rows = [
            {
                "name": s.name,
                "solver": s.solver.value,
                "effect": s.effect.value,
                "summary": s.summary,
                "formula": s.formula,
                "determines": sorted(a.value for a in s.determines),
                "params": [
                    {
                        "name": p.name,
                        "type": p.type.value,
                        "default": p.default,
                        "required": p.required,
                        "range": [p.low, p.high] if p.low is not None else None,
                        "optimisable": p.optimisable,
                    }
                    for p in s.params
                ],
            }
            for s in PREDICATES.values()
        ]
        typer.echo(json.dumps(rows, indent=2))
        return
    table = Table(show_header=True, header_style="bold")
    for column in ("predicate", "solver", "formula", "parameters"):
        table.add_column(column, overflow="fold")
    for s in PREDICATES.values():
        params = ", ".join(p.name + ("*" if p.required else "") for p in s.params)
        table.add_row(s.name, s.solver.value, escape(s.formula), escape(params))
    console.print(table)
