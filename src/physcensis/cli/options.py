"""What several commands share: the stdout console, common options and the checks of their values."""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from rich.console import Console

from physcensis.agent.hint import HINT_MODES
from physcensis.agent.variety import VARIETIES
from physcensis.cli.errors import fail, print_warning
from physcensis.errors import PhyscensisError
from physcensis.program.checker import MAX_OBJECTS
from physcensis.program.schema import STRUCTURED_MODES
from physcensis.scene import Support

if TYPE_CHECKING:
    from physcensis.assets.catalogue import Catalogue

console = Console()

ExportOption = Annotated[
    str, typer.Option("--export", help="formats to write: comma list of mjcf,urdf,glb,usd, or all / none")
]
MaxObjectsOption = Annotated[
    int,
    typer.Option(
        "--max-objects",
        min=1,
        max=MAX_OBJECTS,
        help="refuse a program that makes more objects "
        "than this (declared, COPY-GROUP copies and PLACE-IN counts together)",
    ),
]


def _choice(flag: str, choices: tuple[str, ...], help: str) -> Any:
    """An option taking one of `choices`, shown as `a|b|c`; anything else is one line naming the option."""
    return typer.Option(
        flag, metavar="|".join(choices), callback=lambda value: _one_of(value, choices, flag), help=help
    )


StructuredOption = Annotated[
    str,
    _choice(
        "--structured",
        STRUCTURED_MODES,
        "send the program's JSON Schema as response_format (structured output): auto falls back to plain text "
        "when the server refuses it, on fails instead, off never sends it",
    ),
]
PromptOption = Annotated[
    str,
    _choice(
        "--prompt",
        ("auto", "full", "compact"),
        "the LLM's system prompt: compact (about 1,400 tokens) for small models, full (about 5,400) for large "
        "ones; auto picks compact for local servers and servers that report a small context",
    ),
]
VarietyOption = Annotated[
    str,
    _choice(
        "--variety",
        VARIETIES,
        "how far the seed reaches in what the prompt leaves open (which variant, how many of a vague plural, "
        "where groups and place settings stand, context objects): none gives the canonical scene, wide the most",
    ),
]
DefaultSceneOption = Annotated[
    bool,
    typer.Option(
        "--default-scene",
        help="a prompt the offline planner cannot read (no object, no scene named) gets a typical everyday scene, "
        "said as such, instead of an error",
    ),
]
ContextOption = Annotated[
    bool | None,
    typer.Option(
        "--context/--no-context",
        help="let the offline planner add a few objects that belong to the scene (listed as added in the report); "
        "default: on unless --variety none",
        show_default=False,
    ),
]
HintOption = Annotated[
    str,
    _choice(
        "--hint",
        HINT_MODES,
        "show the LLM the offline planner's reading of the prompt (its objects, what rests on or in what) as "
        "a draft to correct: auto does so with the compact prompt (small models), on always, off never",
    ),
]
StreamOption = Annotated[
    bool,
    typer.Option(
        "--stream/--no-stream",
        help="stream the LLM's replies (progress shows the tokens received); --no-stream when a server counts tokens "
        "only for plain replies (llama-cpp-python)",
    ),
]
LibraryOption = Annotated[
    list[Path] | None,
    typer.Option(
        "--library",
        "-l",
        metavar="FOLDER",
        help="a user asset library folder (repeatable); added to those of $PHYSCENSIS_LIBRARY and the config file",
    ),
]
OverwriteOption = Annotated[
    bool,
    typer.Option(
        "--overwrite",
        help="write into a non-empty folder that is not a physcensis output "
        "(only physcensis's own files are replaced; the rest stay)",
    ),
]


def with_libraries(folders: list[Path] | None) -> Catalogue:
    """The catalogue of this command: built-ins, its --library folders and the configured libraries. A --library
    folder that is not a library is a usage error; broken entries and unreadable configured libraries are warnings."""
    from physcensis.assets.catalogue import use_libraries
    from physcensis.assets.library import read_library_spec

    for folder in folders or ():
        read_library_spec(folder)  # LibraryError (one line, exit 2) before any work
    catalogue = use_libraries(folders or ())
    for err in catalogue.errors:
        print_warning(str(err))
    return catalogue


def _one_of(value: str, choices: tuple[str, ...], option: str) -> str:
    if value not in choices:
        raise typer.BadParameter(f"{value!r} is not one of {', '.join(choices)}", param_hint=option)
    return value


def support_option(value: str | None) -> Support | None:
    if value is None:
        return None
    try:
        return Support.parse(value)
    except ValueError as exc:
        raise typer.BadParameter(str(exc), param_hint=["--support"]) from None


def export_formats(value: str) -> tuple[str, ...]:
    from physcensis.export import parse_formats

    try:
        return parse_formats(value)
    except PhyscensisError as exc:
        raise typer.BadParameter(str(exc), param_hint=["--export"]) from None


def positive_seconds(value: float, flag: str) -> float:
    if not math.isfinite(value) or value <= 0:
        raise typer.BadParameter(f"must be a positive number of seconds, not {value}", param_hint=[flag])
    return value


def no_scene_file(folder: Path, *, below: bool = False) -> typer.Exit:
    """The error of a scene folder without a scene.json (`below`: nor any folder under it), the same for every
    command that reads scenes: `raise no_scene_file(path) from None`."""
    return fail(f"{folder}: no scene.json in this folder{' or below it' if below else ''}")


def scene_file(path: Path) -> Path:
    """A scene argument as given (scene.json or a scene folder); a folder without a scene.json is refused here."""
    if path.is_dir() and not (path / "scene.json").exists():
        raise no_scene_file(path)
    return path


def output_dir(out: Path, overwrite: bool) -> Path:
    """Refuse an output folder that cannot or may not be written, before any work is done."""
    from physcensis.fileio import check_output_dir

    return check_output_dir(out, overwrite=overwrite)


def write_or_fail(write: Callable[[], object], out: Path) -> None:
    """Run `write`; a file system error names the output it was writing."""
    try:
        write()
    except OSError as exc:
        raise fail(f"{out}: cannot write there ({exc.strerror or exc})") from None
