"""Reading a prompt file and planning a batch's scenes (each with its own seed)."""

from __future__ import annotations

import json
import re
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from pydantic import ValidationError

from physcensis.errors import PhyscensisError
from physcensis.fileio import BoundError, read_bounded
from physcensis.scene import Support

DEFAULT_SUPPORT = "table:1.2x0.8"
TEXT_SUFFIXES = (".txt",)
JSONL_SUFFIXES = (".jsonl", ".ndjson")
MAX_PROMPT_FILE_BYTES = 16 * 2**20  # thousands of prompts; a longer file is refused unread


class BatchError(PhyscensisError):
    """A prompt file or batch folder that cannot be used, named with the line or folder at fault."""


@dataclass(frozen=True)
class PromptSpec:
    id: str
    prompt: str
    support: str = DEFAULT_SUPPORT
    count: int | None = None  # scenes for this prompt (default: --per-prompt)


@dataclass(frozen=True)
class Task:
    key: str  # the scene's folder name
    prompt_id: str
    prompt: str
    support: str
    seed: int


def read_prompts(path: str | Path) -> list[PromptSpec]:
    """A .txt file (one prompt per line, # comments) or .jsonl (objects with "prompt" and optionally "id",
    "support" as "table:1.2x0.8" or {"kind", "size", "height"}, and "count"); the prompt suite reads as is."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in TEXT_SUFFIXES + JSONL_SUFFIXES:
        raise BatchError(f"{path}: prompt files are .txt (one prompt per line) or .jsonl (one JSON object per line)")
    specs: list[PromptSpec] = []
    for number, line in enumerate(_lines(path), start=1):
        text = line.strip()
        if not text or text.startswith("#"):
            continue
        where = f"{path}:{number}"
        if suffix in JSONL_SUFFIXES:
            spec = _json_prompt(text, where, len(specs))
        elif text[0] in "{[":
            raise BatchError(f"{where}: this line looks like JSON; name the file .jsonl to read JSON lines")
        else:
            spec = PromptSpec(_slug(text, len(specs)), text)
        _check_support(spec.support, where)
        specs.append(spec)
    if not specs:
        raise BatchError(f"{path}: no prompts in the file")
    _refuse_repeated_ids(path, specs)
    return specs


def _lines(path: Path) -> list[str]:
    """The prompt file's lines; a folder, device, FIFO or file over MAX_PROMPT_FILE_BYTES is refused unread."""
    try:
        return read_bounded(path, MAX_PROMPT_FILE_BYTES, "prompt file").decode("utf-8").splitlines()
    except BoundError as exc:
        raise BatchError(f"{path}: cannot read: {exc}") from None
    except UnicodeDecodeError as exc:
        raise BatchError(f"{path}: cannot read the prompt file ({exc.__class__.__name__}: {exc})") from None


def _refuse_repeated_ids(path: Path, specs: list[PromptSpec]) -> None:
    seen: set[str] = set()
    for spec in specs:
        if spec.id in seen:
            raise BatchError(f"{path}: prompt id {spec.id!r} is used twice; ids name the scene folders")
        seen.add(spec.id)


def _json_prompt(text: str, where: str, index: int) -> PromptSpec:
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise BatchError(f"{where}: not valid JSON ({exc.msg})") from None
    if not isinstance(data, dict) or not isinstance(data.get("prompt"), str) or not data["prompt"].strip():
        raise BatchError(f'{where}: each line must be an object with a "prompt" string')
    prompt = data["prompt"].strip()
    support = data.get("support", DEFAULT_SUPPORT)
    if isinstance(support, dict):
        try:
            support = _support_text(Support.model_validate(support))
        except ValidationError as exc:
            raise BatchError(f"{where}: support: {exc.errors()[0]['msg']}") from None
    elif not isinstance(support, str):
        raise BatchError(f'{where}: "support" must be a string like "table:1.2x0.8" or an object')
    count = data.get("count")
    if count is not None and (not isinstance(count, int) or isinstance(count, bool) or count < 0):
        raise BatchError(f'{where}: "count" must be a whole number >= 0')
    raw_id = data.get("id")
    if raw_id is not None and (not isinstance(raw_id, str) or not re.fullmatch(r"[A-Za-z0-9][A-Za-z0-9_.-]*", raw_id)):
        raise BatchError(f'{where}: "id" must be letters, digits, "-", "_" or "." (it names folders)')
    return PromptSpec(raw_id or _slug(prompt, index), prompt, support, count)


def _check_support(text: str, where: str) -> None:
    try:
        Support.parse(text)
    except ValueError as exc:
        raise BatchError(f"{where}: {exc}") from None


def _support_text(support: Support) -> str:
    height = "" if support.height is None else f"@{support.height:g}"
    return f"{support.kind}:{support.size[0]:g}x{support.size[1]:g}{height}"


def _slug(prompt: str, index: int) -> str:
    words = re.findall(r"[a-z0-9]+", prompt.lower())[:6]
    return f"{index:03d}-" + "-".join(words or ["prompt"])


def plan_tasks(specs: Sequence[PromptSpec], per_prompt: int, seed: int = 0) -> list[Task]:
    """Every scene of the run, in a fixed order, each with its own seed drawn from (seed, prompt, k)."""
    tasks = []
    for index, spec in enumerate(specs):
        for k in range(per_prompt if spec.count is None else spec.count):
            scene_seed = int(np.random.SeedSequence([seed, index, k]).generate_state(1)[0] % 2**31)
            tasks.append(Task(f"{spec.id}_{k:03d}", spec.id, spec.prompt, spec.support, scene_seed))
    return tasks
