"""What several commands share: the stdout console, common options and the checks of their values."""

from __future__ import annotations

import inspect
import math
from collections.abc import Callable
from functools import wraps
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any, ParamSpec, TypeVar

import typer
from rich.console import Console

from physcensis.cli.errors import fail, print_warning
from physcensis.errors import PhyscensisError
from physcensis.export import EXPORT_FORMATS, format_choices
from physcensis.program.checker import MAX_OBJECTS
from physcensis.program.schema import STRUCTURED_MODES
from physcensis.scene import Support
from physcensis.settings import (
    HINT_MODES,
    LLM_WRITES,
    PROMPT_CHOICES,
    VARIETIES,
    VLM_FEEDBACK,
    VQA_SCORES,
    RunSettings,
    SettingsError,
)

if TYPE_CHECKING:
    from physcensis.assets.catalogue import Catalogue

console = Console()
P = ParamSpec("P")
R = TypeVar("R")

# The export formats the options take are the registry's (physcensis.export.EXPORT_FORMATS), and so is their help.
ExportOption = Annotated[
    str, typer.Option("--export", help=f"formats to write: comma list of {format_choices(',')}, or all / none")
]
EXPORT_TO_CHOICES = f"{format_choices()} or all"  # what `export --to` takes, for its error when given none
ExportToOption = Annotated[
    list[str],
    typer.Option(
        "--to",
        help="formats to write (repeat or comma-separate), or all; "
        + "; ".join(f.help_line() for f in EXPORT_FORMATS.values()),
    ),
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
        PROMPT_CHOICES,
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
LlmWritesOption = Annotated[
    str,
    _choice(
        "--llm-writes",
        LLM_WRITES,
        "what the LLM writes: the whole program, or only the scene graph (objects, counts, relations: a few hundred "
        "tokens) that the offline planner turns into programs, repairs and varies by seed",
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
LlmOption = Annotated[str | None, typer.Option(help="an OpenAI-compatible chat model plays the agent")]
BaseUrlOption = Annotated[str | None, typer.Option(help="its server, e.g. http://localhost:8000/v1")]
ProviderOption = Annotated[
    str,
    typer.Option(
        "--llm-provider",
        metavar="NAME",
        help="how the LLM and VLM servers are spoken to: openai (any OpenAI-compatible server), or a provider a "
        "plug-in registered (physcensis.llm.providers.register_provider)",
    ),
]
ApiKeyEnvOption = Annotated[
    str, typer.Option("--api-key-env", metavar="NAME", help="the environment variable that holds the server's key")
]
TemperatureOption = Annotated[float, typer.Option(min=0.0, max=2.0, help="the LLM's sampling temperature")]
LlmTimeoutOption = Annotated[
    float,
    typer.Option(
        "--llm-timeout",
        metavar="SECONDS",
        callback=lambda v: positive_seconds(v, "--llm-timeout"),
        help="wall-clock limit of one LLM or VLM request, retries and their waits included",
    ),
]
VlmOption = Annotated[str | None, typer.Option(help="a vision model scores the render (VQA)")]
VlmBaseUrlOption = Annotated[str | None, typer.Option(help="the vision model's server (default: --base-url)")]
VqaOption = Annotated[
    str,
    _choice(
        "--vqa",
        VQA_SCORES,
        'the VQA score: p-yes, the paper\'s P("Yes") from the first answer token, or normalised, P(yes) / (P(yes) + '
        "P(no)), which reads higher",
    ),
]
VlmFeedbackOption = Annotated[
    str,
    _choice(
        "--vlm-feedback",
        VLM_FEEDBACK,
        "what the agent hears of the vision model: score (one more round when it is low), remarks (also its words "
        "on what does not match), off (only the final scene is scored)",
    ),
]
RoundsOption = Annotated[int, typer.Option(min=1, help="successful rounds; more than 1 enriches the scene")]
MinObjectsOption = Annotated[
    int, typer.Option(min=0, max=MAX_OBJECTS, help="keep enriching until this many objects are placed")
]
TimeBudgetOption = Annotated[
    float,
    typer.Option(
        "--time-budget",
        metavar="SECONDS",
        callback=lambda v: positive_seconds(v, "--time-budget"),
        help=(
            "no new round starts, and the solve under way places nothing more, after this long (a solve gets at "
            "least 5 s; one last solve that frees what failed gets a quarter of it more); the best scene so far "
            "is kept"
        ),
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


# The run's settings as command-line flags: parameter -> its option, in --help's order. `takes_run_settings` gives a
# command all of them, with `RunSettings()`'s defaults: a new run option is its field in physcensis/settings.py and
# its line here (a flag whose parameter is named otherwise than its option is in _SETTING_OF_PARAMETER).
RUN_FLAGS: dict[str, Any] = {
    "llm": LlmOption,
    "provider": ProviderOption,
    "base_url": BaseUrlOption,
    "api_key_env": ApiKeyEnvOption,
    "temperature": TemperatureOption,
    "llm_timeout": LlmTimeoutOption,
    "structured": StructuredOption,
    "prompt_style": PromptOption,
    "stream": StreamOption,
    "hint": HintOption,
    "llm_writes": LlmWritesOption,
    "vlm": VlmOption,
    "vlm_base_url": VlmBaseUrlOption,
    "vlm_feedback": VlmFeedbackOption,
    "vqa": VqaOption,
    "rounds": RoundsOption,
    "min_objects": MinObjectsOption,
    "max_objects": MaxObjectsOption,
    "time_budget": TimeBudgetOption,
    "variety": VarietyOption,
    "context": ContextOption,
    "default_scene": DefaultSceneOption,
}
_SETTING_OF_PARAMETER = {"llm_timeout": "llm_timeout_s", "time_budget": "time_budget_s"}
KEYWORD = inspect.Parameter.KEYWORD_ONLY


def takes_run_settings(command: Callable[P, R]) -> Callable[..., R]:
    """`command` with every run-settings flag (RUN_FLAGS) added to its parameters; it is called with `settings=`, the
    `RunSettings` the flags give (a value out of range is one error line), in their place."""
    defaults = RunSettings().options()
    own = inspect.signature(command, eval_str=True)
    flags = [
        inspect.Parameter(
            name,
            inspect.Parameter.KEYWORD_ONLY,
            default=defaults[_SETTING_OF_PARAMETER.get(name, name)],
            annotation=flag,
        )
        for name, flag in RUN_FLAGS.items()
    ]

    @wraps(command)
    def run(*args: Any, **kwargs: Any) -> R:
        given = {_SETTING_OF_PARAMETER.get(name, name): kwargs.pop(name) for name in RUN_FLAGS if name in kwargs}
        try:
            settings = RunSettings.from_options(**given)
        except SettingsError as exc:
            raise fail(str(exc)) from None
        return command(*args, settings=settings, **kwargs)  # type: ignore[arg-type]

    kept = [p for p in own.parameters.values() if p.name != "settings"]
    run.__signature__ = own.replace(parameters=[*kept, *flags])  # type: ignore[attr-defined]
    return run
