"""The command line's one error path: the exit codes, the stderr console and the one-line error.

Every command reports a failure the same way: `error: <message>` on stderr, on one line (the message is text, never
Rich markup), and one of the `ExitCode`s. A `PhyscensisError` (or an `OSError`) that escapes a command decorated with
`reports_errors` becomes that line and `ExitCode.USAGE`; so does a bad invocation (an unknown or missing option, a bad
value), in click's own words (`usage_error_message`).
"""

from __future__ import annotations

from collections.abc import Callable
from enum import IntEnum
from functools import wraps
from typing import ParamSpec, Protocol, TypeVar, runtime_checkable

import typer
from rich.console import Console
from rich.markup import escape

from physcensis.errors import PhyscensisError, one_line

P = ParamSpec("P")
R = TypeVar("R")

err_console = Console(stderr=True)


class ExitCode(IntEnum):
    """What a `physcensis` command's exit status means, the same for every command."""

    OK = 0
    PROBLEMS = 1  # the input was read, but the program or scene has problems, or some objects failed
    USAGE = 2  # bad arguments, unreadable or refused input, an output that cannot or may not be written
    INTERRUPTED = 130  # stopped by Ctrl-C (128 + SIGINT, as shells report it)


EXIT_CODE_MEANINGS = {
    ExitCode.OK: "done",
    ExitCode.PROBLEMS: "the input was read but the program or scene has problems, some objects failed, or something "
    "the prompt asked for is not in the scene",
    ExitCode.USAGE: "bad arguments, unreadable or refused input, or an output that cannot or may not be written",
    ExitCode.INTERRUPTED: "interrupted",
}


def exit_codes_help() -> str:
    """The exit codes as a line of help text (the `physcensis --help` epilog)."""
    return "Exit codes: " + "; ".join(f"{int(code)} {text}" for code, text in EXIT_CODE_MEANINGS.items()) + "."


def print_error(message: str) -> None:
    """`error: <message>` on stderr, on one line; the message is printed as written, never read as markup."""
    err_console.print(f"[bold red]error:[/] {escape(one_line(message))}", highlight=False, soft_wrap=True)


def print_warning(message: str) -> None:
    err_console.print(f"[yellow]warning:[/] {escape(one_line(message))}", highlight=False, soft_wrap=True)


@runtime_checkable
class ClickError(Protocol):
    """A click error as Typer raises it (Typer vendors click, privately, so its classes are not imported here): a bad
    invocation (unknown or missing option, bad value: exit code 2) or another click failure."""

    exit_code: int

    def format_message(self) -> str: ...


def usage_error_message(error: ClickError) -> str:
    """Click's message for a bad invocation (it names the option and what is wrong) as one line, with the help to
    read: "invalid value for '--rounds': ... (see physcensis generate --help)"."""
    message = " ".join(error.format_message().split()).removesuffix(".")
    if message[:1].isupper() and message[1:2].islower():  # "Invalid value ..." -> "error: invalid value ..."
        message = message[0].lower() + message[1:]
    command_path = getattr(getattr(error, "ctx", None), "command_path", None)  # the command that was misused
    return f"{message} (see {command_path} --help)" if command_path else message


def fail(message: str, code: ExitCode = ExitCode.USAGE) -> typer.Exit:
    """Print the one-line error and return the exit to raise: `raise fail(...) from None`."""
    print_error(message)
    return typer.Exit(code)


def finish(ok: bool) -> typer.Exit:
    """The exit of a command that ran to the end: OK, or PROBLEMS if something in its input or output failed."""
    return typer.Exit(ExitCode.OK if ok else ExitCode.PROBLEMS)


def reports_errors(command: Callable[P, R]) -> Callable[P, R]:
    """Decorate a command so that a `PhyscensisError` or `OSError` it raises is one error line and `USAGE`."""

    @wraps(command)
    def run(*args: P.args, **kwargs: P.kwargs) -> R:
        try:
            return command(*args, **kwargs)
        except (PhyscensisError, OSError) as exc:
            raise fail(str(exc)) from None

    return run
