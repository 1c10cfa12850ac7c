"""The `physcensis` command: the Typer app, which command lives where, and the console entry point."""

from __future__ import annotations

import sys
from collections.abc import Sequence
from typing import Any

import typer
from typer.core import TyperGroup

from physcensis.cli.assets import assets_app
from physcensis.cli.batch import batch
from physcensis.cli.bench import bench_app
from physcensis.cli.demos import demo, demo_batch, demo_export
from physcensis.cli.errors import (
    ClickError,
    ExitCode,
    err_console,
    exit_codes_help,
    print_error,
    usage_error_message,
)
from physcensis.cli.evaluate import eval_app, stability
from physcensis.cli.policy import policy_app
from physcensis.cli.programs import check, predicates
from physcensis.cli.report import report
from physcensis.cli.scenes import export_command, generate, render, solve
from physcensis.cli.view import view
from physcensis.errors import PhyscensisError


class OneLineErrorsGroup(TyperGroup):
    """The root command: a bad invocation (unknown or missing option, bad value) is one `error:` line and exit 2, like
    every other error, not Typer's boxed usage panel."""

    def main(
        self,
        args: Sequence[str] | None = None,
        prog_name: str | None = None,
        complete_var: str | None = None,
        standalone_mode: bool = True,
        windows_expand_args: bool = True,
        **extra: Any,
    ) -> Any:
        if not standalone_mode:  # the caller handles click's exceptions and exit codes itself
            return super().main(args, prog_name, complete_var, False, windows_expand_args, **extra)
        try:
            # Not standalone: click raises its errors instead of printing them, and returns an Exit's code.
            code = super().main(args, prog_name, complete_var, False, windows_expand_args, **extra)
        except typer.Abort:  # Ctrl-C or end of input at a prompt
            err_console.print("interrupted")
            code = ExitCode.INTERRUPTED
        except Exception as exc:
            if not isinstance(exc, ClickError):
                raise
            code = _report_click_error(exc)
        sys.exit(code if isinstance(code, int) else ExitCode.OK)


def _report_click_error(error: ClickError) -> int:
    """One error line for a bad invocation; the help alone when no arguments were given (Typer prints it as it
    makes that error, and checks its class by name too)."""
    if type(error).__name__ != "NoArgsIsHelpError":
        print_error(usage_error_message(error))
    return error.exit_code


app = typer.Typer(
    name="physcensis",
    cls=OneLineErrorsGroup,
    help="Dense, physically valid 3D scenes from a sentence or a predicate program.",
    epilog=exit_codes_help(),
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)
app.add_typer(assets_app, name="assets", help="The asset catalogue: list, show, search, import, gallery.")
app.command()(check)
app.command()(solve)
app.command()(generate)
app.add_typer(eval_app, name="eval")
app.command()(batch)
app.command("export")(export_command)
app.add_typer(bench_app, name="bench")
app.command()(render)
app.command()(predicates)
app.command("stability")(stability)
app.command()(report)
app.command()(view)
app.command()(demo)
app.command("demo-batch")(demo_batch)
app.command("demo-export")(demo_export)
app.add_typer(policy_app, name="policy")


def _ray_address_form(args: list[str]) -> list[str]:
    """`batch --ray=ADDRESS` is `--ray --ray-address ADDRESS` (Typer has no options with an optional value)."""
    out: list[str] = []
    for arg in args:
        if arg.startswith("--ray=") and out[:1] == ["batch"]:
            out += ["--ray", "--ray-address", arg.removeprefix("--ray=")]
        else:
            out.append(arg)
    return out


def main() -> None:
    """Console entry point: user errors print one line, never a traceback."""
    try:
        app(args=_ray_address_form(sys.argv[1:]), prog_name="physcensis")  # also under python -m and test runners
    except PhyscensisError as exc:  # one that escaped a command's own error path
        print_error(str(exc))
        sys.exit(ExitCode.USAGE)
    except KeyboardInterrupt:
        err_console.print("interrupted")
        sys.exit(ExitCode.INTERRUPTED)
