"""A run's settings, one frozen object per concern, built once at the edge (the command line, the API, a batch, an
evaluation) and passed whole to what makes the scene.

* `ModelSettings`: the LLM and VLM, how to reach them and how to drive them;
* `BudgetSettings`: how much a run may do (rounds, objects, time);
* `VarietySettings`: how far the seed reaches in what the prompt leaves open.

`RunSettings` holds one of each. Every field has a name no other concern uses, so a run's settings also read and
write as one flat mapping (`RunSettings.from_options(rounds=2, llm="qwen")`, `options()`): the API's keyword
arguments, a batch's recorded options and the CLI's flags are those names. Adding an option is one field here and its
CLI flag; tests/test_settings.py checks that the API, `generate` and `batch` all take every field.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field, fields
from typing import Any, ClassVar

from physcensis.errors import PhyscensisError
from physcensis.program.checker import DEFAULT_MAX_OBJECTS, MAX_OBJECTS
from physcensis.program.schema import STRUCTURED_MODES

DEFAULT_PROVIDER = "openai"  # every OpenAI-compatible server (llm/providers.py names the others)
API_KEY_ENV = "OPENAI_API_KEY"  # where the key of an OpenAI-compatible server is read from, unless told otherwise
DEFAULT_LLM_TIMEOUT_S = 300.0  # wall-clock budget of one request, all attempts and waits included
DEFAULT_TIME_BUDGET_S = 600.0  # no new round starts, and no solve places more, once a run has taken this long
PROMPT_CHOICES = ("auto", "full", "compact")
HINT_MODES = ("auto", "on", "off")
LLM_WRITES = ("program", "graph")
VLM_FEEDBACK = ("score", "remarks", "off")
VQA_SCORES = ("p-yes", "normalised")  # the paper's P("Yes"), or P(yes) / (P(yes) + P(no)) (agent/vqa.py)
VARIETIES = ("none", "normal", "wide")


class SettingsError(PhyscensisError):
    """A setting out of its range or choices, or an option no settings object has."""


def _one_of(name: str, value: Any, choices: tuple[str, ...]) -> None:
    if value not in choices:
        raise SettingsError(f"{name} {value!r}: give one of {', '.join(choices)}")


def _positive_seconds(name: str, value: Any) -> None:
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value) or value <= 0:
        raise SettingsError(f"{name} must be a positive number of seconds, not {value!r}")


@dataclass(frozen=True)
class ModelSettings:
    """The models a run talks to: `llm` writes the programs (None: the offline planner), `vlm` scores renders."""

    llm: str | None = None
    provider: str = DEFAULT_PROVIDER  # how the servers are spoken to (llm/providers.py)
    base_url: str | None = None  # the server (None: OPENAI_BASE_URL, else OpenAI's)
    api_key_env: str = API_KEY_ENV
    temperature: float | None = 0.7  # None: the server's default
    llm_timeout_s: float = DEFAULT_LLM_TIMEOUT_S  # one LLM or VLM request, its retries and their waits included
    structured: str = "auto"  # send the program's JSON Schema: auto (fall back when refused), on or off
    prompt_style: str = "auto"  # the system prompt: auto, full or compact (agent/sizing.py)
    stream: bool = True  # stream replies (progress shows the tokens received)
    hint: str = "auto"  # show the LLM the offline reading as a draft: auto, on or off (agent/hint.py)
    llm_writes: str = "program"  # the LLM writes the program, or only the scene graph (agent/graph_planner.py)
    vlm: str | None = None
    vlm_base_url: str | None = None  # None: base_url
    vlm_feedback: str = "score"  # what the agent hears of the VLM: score, remarks or off
    vqa: str = "p-yes"  # the VQA score: the paper's P("Yes"), or normalised against P("No")

    def __post_init__(self) -> None:
        _one_of("structured", self.structured, STRUCTURED_MODES)
        _one_of("prompt_style", self.prompt_style, PROMPT_CHOICES)
        _one_of("hint", self.hint, HINT_MODES)
        _one_of("llm_writes", self.llm_writes, LLM_WRITES)
        _one_of("vlm_feedback", self.vlm_feedback, VLM_FEEDBACK)
        _one_of("vqa", self.vqa, VQA_SCORES)
        _positive_seconds("llm_timeout_s", self.llm_timeout_s)
        temperature = self.temperature
        if temperature is not None and (not isinstance(temperature, int | float) or not 0 <= temperature <= 2):
            raise SettingsError(f"temperature {self.temperature!r}: give a number from 0 to 2, or none")
        if not isinstance(self.provider, str) or not self.provider.strip():
            raise SettingsError(f"provider {self.provider!r}: give a provider's name")
        for name in ("llm", "vlm", "base_url", "vlm_base_url"):
            value = getattr(self, name)
            if value is not None and (not isinstance(value, str) or not value.strip()):
                raise SettingsError(f"{name} {value!r}: give a non-empty name, or none")

    @property
    def agent(self) -> str:
        """Who writes the programs, as recorded with every scene."""
        return f"llm:{self.llm}" if self.llm else "offline-planner"

    @property
    def vlm_url(self) -> str | None:
        """The VLM's server: its own, else the LLM's."""
        return self.vlm_base_url or self.base_url


@dataclass(frozen=True)
class BudgetSettings:
    """How much one run may do."""

    rounds: int = 1  # successful rounds; more than one enriches the scene
    min_objects: int = 0  # keep enriching until this many objects are placed
    max_objects: int = DEFAULT_MAX_OBJECTS  # objects a program may make
    time_budget_s: float | None = DEFAULT_TIME_BUDGET_S  # None: no budget

    def __post_init__(self) -> None:
        if not _is_int(self.rounds) or self.rounds < 1:
            raise SettingsError(f"rounds {self.rounds!r}: give 1 or more")
        if not _is_int(self.min_objects) or not 0 <= self.min_objects <= MAX_OBJECTS:
            raise SettingsError(f"min_objects {self.min_objects!r}: give 0 to {MAX_OBJECTS}")
        if not _is_int(self.max_objects) or not 1 <= self.max_objects <= MAX_OBJECTS:
            raise SettingsError(f"max_objects {self.max_objects!r}: give 1 to {MAX_OBJECTS}")
        if self.time_budget_s is not None:
            _positive_seconds("time_budget_s", self.time_budget_s)


@dataclass(frozen=True)
class VarietySettings:
    """How far the offline planner's seeded choices reach (agent/variety.py)."""

    variety: str = "normal"  # none (the canonical scene), normal or wide
    context: bool | None = None  # add objects that belong to the scene (None: on unless the variety is none)
    default_scene: bool = False  # a prompt the planner cannot read gets a typical scene instead of an error

    def __post_init__(self) -> None:
        object.__setattr__(self, "variety", str(self.variety).strip().lower())  # a Variety member is its value
        _one_of("variety", self.variety, VARIETIES)


def _is_int(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


@dataclass(frozen=True)
class RunSettings:
    """Everything a run of `generate` (one scene, or each scene of a batch) is told."""

    models: ModelSettings = field(default_factory=ModelSettings)
    budget: BudgetSettings = field(default_factory=BudgetSettings)
    draws: VarietySettings = field(default_factory=VarietySettings)

    CONCERNS: ClassVar[dict[str, type]] = {
        "models": ModelSettings,
        "budget": BudgetSettings,
        "draws": VarietySettings,
    }

    @classmethod
    def option_names(cls) -> list[str]:
        """Every option's flat name, in the order of the concerns and their fields."""
        return [f.name for concern in cls.CONCERNS.values() for f in fields(concern)]

    @classmethod
    def from_options(cls, **options: Any) -> RunSettings:
        """Settings from flat options (`rounds=2, llm="qwen"`); an unknown name is a SettingsError naming it."""
        return cls().replace(**options)

    def replace(self, **options: Any) -> RunSettings:
        """These settings with some flat options changed."""
        unknown = sorted(set(options) - set(self.option_names()))
        if unknown:
            raise SettingsError(f"unknown option {unknown[0]!r}; the options are {', '.join(self.option_names())}")
        changed = {}
        for name, concern in self.CONCERNS.items():
            mine = {f.name for f in fields(concern)}
            wanted = {key: value for key, value in options.items() if key in mine}
            if wanted:
                changed[name] = dataclasses.replace(getattr(self, name), **wanted)
        return dataclasses.replace(self, **changed)

    def options(self) -> dict[str, Any]:
        """The flat options these settings hold (plain data: JSON-ready)."""
        return {key: value for name in self.CONCERNS for key, value in dataclasses.asdict(getattr(self, name)).items()}
