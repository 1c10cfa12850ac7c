"""The cards of a report: one per scene, from `results.jsonl` (written by `eval compare`) or from the scene folders.

A card holds only plain data (strings, numbers, lists), ready to be embedded in the page as JSON. Everything in it
comes from files a user may have written by hand, so nothing here is trusted: the page shows it as text.
"""

from __future__ import annotations

import json
import math
import os
from collections.abc import Iterator, Mapping
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from physcensis.errors import PhyscensisError
from physcensis.fileio import BoundError, read_bounded

RESULTS_NAME = "results.jsonl"
SCENE_FILE = "scene.json"
IMAGE_NAMES = {"render": "render.png", "layout": "layout.png"}
DEFAULT_METHOD = "ours"  # a plain scene folder was made by physcensis itself
MAX_JSON_BYTES = 64 * 2**20
# Folders a scene folder holds that are never scene folders themselves (exports, asset copies), and are not searched.
_NOT_SCENES = frozenset({"mjcf", "urdf", "assets"})


class GalleryError(PhyscensisError):
    """A report that cannot be made: no scenes under the folder, an unreadable results file."""


@dataclass
class Card:
    """One scene as the page shows it. `scene_dir`, `render` and `layout` are paths relative to the report's folder
    (or None when the file is missing); `metrics` maps a metric's name to a number, or None when not finite."""

    prompt: str
    prompt_id: str
    method: str
    seed: int | None
    ok: bool | None
    scene_dir: str
    metrics: dict[str, float | None] = field(default_factory=dict)
    failures: list[str] = field(default_factory=list)
    render: str | None = None
    layout: str | None = None

    def to_json(self) -> dict[str, Any]:
        return asdict(self)


def collect_cards(folder: Path) -> list[Card]:
    """The cards of `folder`: the rows of its results.jsonl when it has one, else one per scene folder under it."""
    if not folder.is_dir():
        raise GalleryError(f"{folder}: {'is not a folder' if folder.exists() else 'no such folder'}")
    results = folder / RESULTS_NAME
    cards = cards_from_results(folder, results) if results.exists() else cards_from_folders(folder)
    if not cards:
        where = f"{RESULTS_NAME} has no rows" if results.exists() else f"no scene folder (one holding {SCENE_FILE})"
        raise GalleryError(f"{folder}: nothing to show: {where}")
    return cards


# ---- results.jsonl --------------------------------------------------------------------------------------------------


def cards_from_results(folder: Path, results: Path) -> list[Card]:
    """One card per row of results.jsonl; method, metrics and failures are the row's own."""
    return [_card_from_row(folder, row, number) for number, row in results_rows(results)]


def results_rows(results: Path) -> Iterator[tuple[int, dict[str, Any]]]:
    """The rows of a results.jsonl with their line numbers; a torn last line (a killed run) is left out, any other
    line that is not a JSON object is an error. The one reader of the file: `eval compare` resumes with it too."""
    try:
        text = read_bounded(results, MAX_JSON_BYTES, RESULTS_NAME).decode("utf-8")
    except (BoundError, UnicodeDecodeError) as exc:
        raise GalleryError(f"{results}: {exc}") from None
    lines = text.splitlines()
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        try:
            row = json.loads(line)
        except ValueError:
            if number == len(lines) and not text.endswith("\n"):
                return  # torn by a killed run, as `eval compare` reads it too: that row is made again on resume
            raise GalleryError(f"{results}: line {number} is not JSON") from None
        if not isinstance(row, dict):
            raise GalleryError(f"{results}: line {number} is not a JSON object")
        yield number, row


def _card_from_row(folder: Path, row: Mapping[str, Any], number: int) -> Card:
    scene_dir = _text(row.get("scene_dir"))
    prompt = _text(row.get("prompt"))
    return Card(
        prompt=prompt,
        prompt_id=_text(row.get("prompt_id")) or prompt,
        method=_text(row.get("method")) or DEFAULT_METHOD,
        seed=_integer(row.get("seed")),
        ok=row["ok"] if isinstance(row.get("ok"), bool) else None,
        scene_dir=scene_dir,
        metrics=numeric_metrics(row.get("metrics")),
        failures=[_text(f) for f in row.get("failures") or [] if f is not None]
        if isinstance(row.get("failures"), list)
        else [],
        **_images(folder, folder / scene_dir if scene_dir else None),
    )


# ---- scene folders --------------------------------------------------------------------------------------------------


def cards_from_folders(folder: Path) -> list[Card]:
    """One card per scene folder under `folder` (itself included), in path order; method "ours"."""
    return [_card_from_scene(folder, scene) for scene in scene_folders(folder)]


def scene_folders(folder: Path) -> list[Path]:
    """Every folder under `folder` (itself included) that holds a scene.json; hidden folders (staging, leftovers)
    and the exports inside a scene folder are not searched, and links are not followed."""
    found = []
    for root, dirs, files in os.walk(folder):
        if SCENE_FILE in files:
            found.append(Path(root))
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d not in _NOT_SCENES)
    return sorted(found, key=lambda p: p.relative_to(folder).parts)


def _card_from_scene(folder: Path, scene: Path) -> Card:
    scene_json = _json_object(scene / SCENE_FILE)
    unreadable = [] if scene_json else [f"{SCENE_FILE} could not be read as a scene (damaged or not an object)"]
    report = _json_object(scene / "report.json")
    batch = _json_object(scene / "batch.json")
    generate = _mapping(report.get("generate"))
    prompt = _text(scene_json.get("prompt") or generate.get("prompt") or batch.get("prompt"))
    relative = scene.relative_to(folder).as_posix()
    return Card(
        prompt=prompt,
        prompt_id=_text(batch.get("prompt_id")) or (scene.name if relative != "." else prompt),
        method=DEFAULT_METHOD,
        seed=_integer(batch.get("seed", scene_json.get("seed"))),
        ok=report["ok"] if isinstance(report.get("ok"), bool) else None,
        scene_dir=relative,
        metrics=scene_metrics(scene_json, report),
        failures=unreadable + scene_failures(report),
        **_images(folder, scene),
    )


def scene_metrics(scene_json: Mapping[str, Any], report: Mapping[str, Any]) -> dict[str, float | None]:
    """The numbers a scene folder records: every numeric entry of its metrics, plus the agent's rounds, seconds and
    VQA score when the scene was generated from a prompt."""
    metrics = numeric_metrics(report.get("metrics") or scene_json.get("metrics"))
    generate = _mapping(report.get("generate"))
    extras = {
        "rounds": generate.get("rounds"),
        "seconds": generate.get("seconds", _mapping(report.get("timings_s")).get("total")),
        "vqa_score": generate.get("vqa_score"),
    }
    metrics.update({k: v for k, v in numeric_metrics(extras).items() if v is not None and k not in metrics})
    return metrics


def scene_failures(report: Mapping[str, Any]) -> list[str]:
    """What went wrong, one line each: the program's errors, the objects that failed (with why), those left pending,
    and the agent's own failure."""
    failures = [
        _text(p.get("message")) for p in _dicts(report.get("problems")) if p.get("severity", "error") == "error"
    ]
    for obj in _dicts(report.get("objects")):
        if obj.get("status") == "failed":
            reason = _text(obj.get("reason"))
            failures.append(f"{_text(obj.get('id'))}: {reason}" if reason else f"{_text(obj.get('id'))} failed")
    failures += [_pending_line(p) for p in _dicts(report.get("pending"))]
    agent_failure = _mapping(report.get("generate")).get("failure")
    if agent_failure:
        failures.append(_text(agent_failure))
    return failures


def _pending_line(pending: Mapping[str, Any]) -> str:
    """A placement left unsolved (physics was off): its objects, its predicate and why."""
    objects = pending.get("objects")
    who = ", ".join(_text(o) for o in objects) if isinstance(objects, list) and objects else "?"
    why = _text(pending.get("reason")) or "not solved"
    return f"{who}: {_text(pending.get('predicate')) or 'placement'} pending ({why})"


# ---- shared helpers ------------------------------------------------------------------------------------------------


def numeric_metrics(metrics: Any) -> dict[str, float | None]:
    """The entries of a metrics mapping that are numbers (booleans and nested values are not metrics); a value that is
    not finite (NaN, infinity) is kept as None, so the page shows it as missing."""
    if not isinstance(metrics, Mapping):
        return {}
    numbers: dict[str, float | None] = {}
    for name, value in metrics.items():
        if isinstance(value, int | float) and not isinstance(value, bool):
            numbers[str(name)] = float(value) if math.isfinite(value) else None
    return numbers


def _images(folder: Path, scene: Path | None) -> dict[str, str | None]:
    """The render and layout plot of a scene, as paths relative to the report's folder, None when missing."""
    images: dict[str, str | None] = {}
    for key, name in IMAGE_NAMES.items():
        path = scene / name if scene is not None else None
        images[key] = Path(os.path.relpath(path, folder)).as_posix() if path is not None and path.is_file() else None
    return images


def _json_object(path: Path) -> dict[str, Any]:
    """A JSON file's top-level object; {} when it is missing or not a readable JSON object (the card shows less)."""
    try:
        data = json.loads(read_bounded(path, MAX_JSON_BYTES, path.name))
    except (BoundError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


def _mapping(value: Any) -> Mapping[str, Any]:
    return value if isinstance(value, Mapping) else {}


def _dicts(value: Any) -> list[Mapping[str, Any]]:
    return [v for v in value if isinstance(v, Mapping)] if isinstance(value, list) else []


def _text(value: Any) -> str:
    return "" if value is None else value if isinstance(value, str) else json.dumps(value, default=str)


def _integer(value: Any) -> int | None:
    return value if isinstance(value, int) and not isinstance(value, bool) else None
