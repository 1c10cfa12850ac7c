"""The `physcensis` command: thin wrappers over the public API."""

from __future__ import annotations

import json
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.console import Console
from rich.table import Table

from physcensis.assets.cli import assets_app
from physcensis.errors import PhyscensisError
from physcensis.program import Problem, check_program, load_program, parse_program
from physcensis.program.registry import PREDICATES
from physcensis.scene import Support

if TYPE_CHECKING:
    from physcensis.solve.pipeline import Solution

app = typer.Typer(
    name="physcensis",
    help="Dense, physically valid 3D scenes from a sentence or a predicate program.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)
app.add_typer(assets_app, name="assets", help="The asset catalogue: list, show, search, import, gallery.")
console = Console()
err_console = Console(stderr=True)

EXIT_OK, EXIT_PROBLEMS, EXIT_UNREADABLE = 0, 1, 2


def _fail(message: str, code: int = EXIT_UNREADABLE) -> typer.Exit:
    err_console.print(f"[bold red]error:[/] {message}", highlight=False, soft_wrap=True)
    return typer.Exit(code)


def _support_option(value: str | None) -> Support | None:
    if value is None:
        return None
    try:
        return Support.parse(value)
    except ValueError as exc:
        raise typer.BadParameter(str(exc)) from None


@app.command()
def check(
    file: Annotated[Path, typer.Argument(help="program file (.json, or LLM text); '-' reads stdin")],
    as_json: Annotated[bool, typer.Option("--json", help="print problems as JSON")] = False,
    support: Annotated[
        str | None, typer.Option(help="support to check x/y against, e.g. table:1.2x0.8")
    ] = None,
) -> None:
    """Parse and check a predicate program; exit 0 if it has no errors, 1 if it has, 2 if unreadable."""
    support_override = _support_option(support)
    try:
        if str(file) == "-":
            program = parse_program(sys.stdin.read())
        else:
            program = load_program(file)
    except PhyscensisError as exc:
        raise _fail(str(exc)) from None
    report = check_program(program, support_override)
    if as_json:
        typer.echo(json.dumps([p.to_dict() for p in report.problems], indent=2))
    else:
        if report.problems:
            _print_problems(report.problems)
        objects = len(program.declarations)
        verdict = "[green]ok[/]" if report.ok else "[red]has errors[/]"
        counts = f"{len(program.entries)} entries, {objects} declared objects, {report.summary()}"
        console.print(f"{file}: {counts} — {verdict}")
    raise typer.Exit(EXIT_OK if report.ok else EXIT_PROBLEMS)


@app.command()
def solve(
    file: Annotated[Path, typer.Argument(help="program file (.json, or LLM text)")],
    out: Annotated[Path, typer.Option("--out", "-o", help="output folder (replaced atomically)")],
    seed: Annotated[int, typer.Option(help="random seed: same program and seed, same scene")] = 0,
    support: Annotated[
        str | None, typer.Option(help="support, e.g. table:1.2x0.8 (default: the program's, else table:1.2x0.8)")
    ] = None,
    physics: Annotated[bool, typer.Option("--physics/--no-physics", help="run the physical solver")] = True,
) -> None:
    """Solve a predicate program into a scene folder (scene.json, report.json, layout.png)."""
    from physcensis.solve.pipeline import solve as solve_program
    from physcensis.solve.pipeline import write_solution

    support_override = _support_option(support)
    try:
        program = load_program(file)
    except PhyscensisError as exc:
        raise _fail(str(exc)) from None
    if physics:
        err_console.print("[yellow]note:[/] the physical solver is not available yet; solving the spatial part "
                          "(as with --no-physics)")
    solution = solve_program(program, support=support_override, seed=seed)
    if not solution.check.ok:
        _print_problems(solution.check.problems)
        raise _fail(f"{file}: the program has {solution.check.summary()}; nothing was solved", EXIT_PROBLEMS)
    write_solution(solution, out)
    _print_solution_summary(solution, out)
    raise typer.Exit(EXIT_OK if solution.ok else EXIT_PROBLEMS)


def _print_problems(problems: Sequence[Problem]) -> None:
    table = Table(show_header=True, header_style="bold")
    for column in ("#", "object", "severity", "message"):
        table.add_column(column, overflow="fold")
    for p in problems:
        style = "red" if p.severity == "error" else "yellow"
        table.add_row("" if p.index is None else str(p.index), p.object or "", f"[{style}]{p.severity}[/]", p.message)
    console.print(table)


def _print_solution_summary(solution: Solution, out: Path) -> None:
    table = Table(show_header=True, header_style="bold", title=f"scene written to {out}")
    for column in ("object", "asset", "status", "reason"):
        table.add_column(column, overflow="fold")
    for o in solution.scene.objects:
        style = "green" if o.status == "placed" else "red"
        table.add_row(o.id, o.asset, f"[{style}]{o.status}[/]", o.reason or "")
    for p in solution.pending:
        table.add_row(", ".join(p["objects"]), "", "[yellow]pending[/]", f"{p['predicate']} (#{p['entry']})")
    console.print(table)
    m = solution.scene.metrics
    console.print(f"placed {m.get('objects_placed', 0)}, failed {m.get('objects_failed', 0)}, "
                  f"pending {m.get('objects_pending', 0)} in {solution.timings.get('total', 0):.2f} s")
    if solution.spatial is not None and not solution.spatial.ok:
        console.print(solution.spatial.feedback())


@app.command()
def predicates(
    as_json: Annotated[bool, typer.Option("--json", help="print the registry as JSON")] = False,
) -> None:
    """List the predicates the language knows, with their parameters."""
    if as_json:
        rows = [
            {
                "name": s.name, "kind": s.kind.value, "summary": s.summary, "effect": s.effect,
                "determines": sorted(a.value for a in s.determines),
                "params": [
                    {"name": p.name, "type": p.type.value, "default": p.default, "required": p.required,
                     "range": [p.low, p.high] if p.low is not None else None, "optimisable": p.optimisable}
                    for p in s.params
                ],
            }
            for s in PREDICATES.values()
        ]
        typer.echo(json.dumps(rows, indent=2))
        return
    table = Table(show_header=True, header_style="bold")
    for column in ("predicate", "kind", "effect", "parameters"):
        table.add_column(column, overflow="fold")
    for s in PREDICATES.values():
        params = ", ".join(p.name + ("*" if p.required else "") for p in s.params)
        table.add_row(s.name, s.kind.value, s.effect, params)
    console.print(table)


def main() -> None:
    """Console entry point: user errors print one line, never a traceback."""
    try:
        app()
    except PhyscensisError as exc:
        err_console.print(f"[bold red]error:[/] {exc}", highlight=False, soft_wrap=True)
        sys.exit(EXIT_UNREADABLE)
    except KeyboardInterrupt:
        err_console.print("interrupted")
        sys.exit(130)
