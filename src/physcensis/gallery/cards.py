"""The cards of a report: one per scene, from `results.jsonl` (written by `eval compare`) or from the scene folders.

A card holds only plain data (strings, numbers, lists), ready to be embedded in the page as JSON. Everything in it
comes from files a user may have written by hand, so nothing here is trusted: the page shows it as text.

The folder itself may come from elsewhere, so every file of it is read with `read_in_folder` (a regular file inside
the folder, below a size limit) and no symbolic link is followed anywhere in it: physcensis writes none into scene,
batch or report folders, so a link there is someone else's, and the page would show (or, with `--embed`, carry) what
it leads to. A link, a special file or a file over its limit where the report reads (results.jsonl, scene.json,
report.json, batch.json, render.png, layout.png, scene.glb) is refused: one line naming the file, nothing written.
So is a results row whose `scene_dir` is not a relative path inside the folder. A scene file that is there but is not
JSON (cut short by a killed run) is still a card, which says so.
"""

from __future__ import annotations

import json
import math
import os
import stat
from collections.abc import Iterator, Mapping
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, TypedDict

from physcensis.bounded_json import check_values, load_json
from physcensis.errors import PhyscensisError
from physcensis.fileio import FOLDER_OUTPUTS, BoundError, read_in_folder
from physcensis.gallery.objects import scene_objects

RESULTS_NAME = "results.jsonl"
SCENE_FILE = "scene.json"
IMAGE_NAMES = {"render": "render.png", "layout": "layout.png"}
GLB_NAME = "scene.glb"  # the glb export of a scene folder (export/glb.py), shown by the page's 3-D viewer
DEFAULT_METHOD = "ours"  # a plain scene folder was made by physcensis itself
MAX_JSON_BYTES = 64 * 2**20
MAX_CARDS = 50_000  # scenes on one page; an eval compare of the whole suite has a few thousand
MAX_ENTRIES_SCANNED = 1_000_000  # files and folders looked at while searching for scene folders
# Folders a scene folder holds that are never scene folders themselves (exports, asset copies), and are not searched.
_NOT_SCENES = FOLDER_OUTPUTS


class GalleryError(PhyscensisError):
    """A report that cannot be made: no scenes under the folder, an unreadable results file."""


@dataclass
class Card:
    """One scene as the page shows it. `scene_dir`, `render`, `layout` and `glb` are paths relative to the report's
    folder (or None when the file is missing); `metrics` maps a metric's name to a number, or None when not finite;
    `objects` is what the 3-D viewer shows of each placed object (gallery/objects.py), listed only with a `glb`."""

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
    glb: str | None = None
    objects: list[dict[str, Any]] = field(default_factory=list)

    def to_json(self) -> dict[str, Any]:
        return asdict(self)


def collect_cards(folder: Path) -> list[Card]:
    """The cards of `folder`: the rows of its results.jsonl when it has one, else one per scene folder under it."""
    if not folder.is_dir():
        raise GalleryError(f"{folder}: {'is not a folder' if folder.exists() else 'no such folder'}")
    results = folder / RESULTS_NAME
    has_results = os.path.lexists(results)  # a link there is refused when read, not taken for a missing file
    cards = cards_from_results(folder, results) if has_results else cards_from_folders(folder)
    if not cards:
        where = f"{RESULTS_NAME} has no rows" if has_results else f"no scene folder (one holding {SCENE_FILE})"
        raise GalleryError(f"{folder}: nothing to show: {where}")
    return cards


# ---- results.jsonl --------------------------------------------------------------------------------------------------


def cards_from_results(folder: Path, results: Path) -> list[Card]:
    """One card per row of results.jsonl; method, metrics and failures are the row's own."""
    cards: list[Card] = []
    for number, row in results_rows(results):
        if len(cards) == MAX_CARDS:
            raise GalleryError(f"{results}: more than {MAX_CARDS:,} rows; make a report of a smaller folder")
        cards.append(_card_from_row(folder, row, f"{results}: line {number}"))
    return cards


def results_rows(results: Path) -> Iterator[tuple[int, dict[str, Any]]]:
    """The rows of a results.jsonl with their line numbers; a torn last line (a killed run) is left out, any other
    line that is not a JSON object is an error. The one reader of the file: `eval compare` resumes with it too."""
    try:
        text = read_folder_file(results.parent, results.name, MAX_JSON_BYTES).decode("utf-8")
    except UnicodeDecodeError as exc:
        raise GalleryError(f"{results}: {exc}") from None
    try:
        check_values(text)  # all the rows together: they are all kept
    except BoundError as exc:
        raise GalleryError(f"{results}: {exc}") from None
    lines = text.splitlines()
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        try:
            row = load_json(line)
        except BoundError as exc:
            raise GalleryError(f"{results}: line {number}: {exc}") from None
        except ValueError:
            if number == len(lines) and not text.endswith("\n"):
                return  # torn by a killed run, as `eval compare` reads it too: that row is made again on resume
            raise GalleryError(f"{results}: line {number} is not JSON") from None
        if not isinstance(row, dict):
            raise GalleryError(f"{results}: line {number} is not a JSON object")
        yield number, row


def _card_from_row(folder: Path, row: Mapping[str, Any], where: str) -> Card:
    scene_dir = row_scene_dir(row.get("scene_dir"), where)
    prompt = _text(row.get("prompt"))
    card = Card(
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
        **_images(folder, scene_dir or None),
    )
    card.glb, card.objects = _viewer(folder, scene_dir or None)
    return card


def row_scene_dir(value: Any, where: str) -> str:
    """A row's `scene_dir` ("" when it has none): a relative path inside the report's folder, else refused."""
    if value is None or value == "":
        return ""
    if not isinstance(value, str):
        raise GalleryError(f"{where}: scene_dir is not a text but {_text(value)[:80]}")
    path = Path(value)
    if "\0" in value or path.is_absolute() or ".." in path.parts:
        raise GalleryError(f"{where}: scene_dir {value[:200]!r} is not a relative path inside the report's folder")
    return path.as_posix()


# ---- scene folders --------------------------------------------------------------------------------------------------


def cards_from_folders(folder: Path) -> list[Card]:
    """One card per scene folder under `folder` (itself included), in path order; method "ours"."""
    scenes = scene_folders(folder)
    if len(scenes) > MAX_CARDS:
        raise GalleryError(f"{folder}: more than {MAX_CARDS:,} scene folders; make a report of a smaller folder")
    return [_card_from_scene(folder, scene) for scene in scenes]


def scene_folders(folder: Path) -> list[Path]:
    """Every folder under `folder` (itself included) that holds a scene.json; hidden folders (staging, leftovers)
    and the exports inside a scene folder are not searched, and links are not followed. At most
    MAX_ENTRIES_SCANNED entries are looked at; a folder unreadable below `folder` is passed over."""
    found: list[Path] = []
    pending, scanned = [folder], 0
    while pending:
        current = pending.pop()
        try:
            with os.scandir(current) as entries:
                names = []
                for entry in entries:
                    scanned += 1
                    if scanned > MAX_ENTRIES_SCANNED:
                        raise GalleryError(f"{folder}: more than {MAX_ENTRIES_SCANNED:,} files and folders to search")
                    names.append((entry.name, entry.is_dir(follow_symlinks=False)))
        except OSError:
            continue
        if any(name == SCENE_FILE and not is_dir for name, is_dir in names):
            found.append(current)
        pending += [current / n for n, is_dir in names if is_dir and not n.startswith(".") and n not in _NOT_SCENES]
    return sorted(found, key=lambda p: p.relative_to(folder).parts)


def _card_from_scene(folder: Path, scene: Path) -> Card:
    relative = scene.relative_to(folder).as_posix()
    scene_json = _json_object(folder, f"{relative}/{SCENE_FILE}")
    unreadable = [] if scene_json else [f"{SCENE_FILE} could not be read as a scene (damaged or not an object)"]
    report = _json_object(folder, f"{relative}/report.json")
    batch = _json_object(folder, f"{relative}/batch.json")
    generate = _mapping(report.get("generate"))
    prompt = _text(scene_json.get("prompt") or generate.get("prompt") or batch.get("prompt"))
    card = Card(
        prompt=prompt,
        prompt_id=_text(batch.get("prompt_id")) or (scene.name if relative != "." else prompt),
        method=DEFAULT_METHOD,
        seed=_integer(batch.get("seed", scene_json.get("seed"))),
        ok=report["ok"] if isinstance(report.get("ok"), bool) else None,
        scene_dir=relative,
        metrics=scene_metrics(scene_json, report),
        failures=unreadable + scene_failures(report),
        **_images(folder, relative),
    )
    card.glb, card.objects = _viewer(folder, relative, scene_json, report)
    return card


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


# Lengths on the cards are in millimetres, whatever unit a file records them in (the name's suffix says which).
TO_MILLIMETRES = {"_m": 1000.0, "_cm": 10.0, "_mm": 1.0}


def numeric_metrics(metrics: Any) -> dict[str, float | None]:
    """The entries of a metrics mapping that are numbers (booleans and nested values are not metrics), lengths in
    millimetres (`settle_distance_m` 0.002 becomes `settle_distance_mm` 2.0); a value that is not finite (NaN,
    infinity) is kept as None, so the page shows it as missing."""
    if not isinstance(metrics, Mapping):
        return {}
    numbers: dict[str, float | None] = {}
    for name, value in metrics.items():
        if isinstance(value, int | float) and not isinstance(value, bool):
            key, scale = _in_millimetres(str(name))
            numbers[key] = float(value) * scale if math.isfinite(value) else None
    return numbers


def _in_millimetres(name: str) -> tuple[str, float]:
    """The metric's name and scale with its length in millimetres."""
    for suffix, scale in TO_MILLIMETRES.items():
        if name.endswith(suffix):
            return name.removesuffix(suffix) + "_mm", scale
    return name, 1.0


def read_folder_file(folder: Path, relative: str, limit: int) -> bytes:
    """The bytes of `folder/relative` as `read_in_folder` reads them (no link, a regular file, at most `limit`
    bytes); a refusal is a `GalleryError` naming the file."""
    try:
        return read_in_folder(folder, relative, limit, str(folder / relative))
    except BoundError as exc:
        raise GalleryError(str(exc)) from None


class _Images(TypedDict):
    render: str | None
    layout: str | None


def _images(folder: Path, scene: str | None) -> _Images:
    """The render and layout plot of a scene, as paths relative to the report's folder, None when missing."""
    found = {key: _present(folder, f"{scene}/{name}") if scene else None for key, name in IMAGE_NAMES.items()}
    return _Images(render=found["render"], layout=found["layout"])


def _viewer(
    folder: Path,
    scene: str | None,
    scene_json: Mapping[str, Any] | None = None,
    report: Mapping[str, Any] | None = None,
) -> tuple[str | None, list[dict[str, Any]]]:
    """A scene's glb export and its placed objects, for the 3-D viewer; nothing when the scene has no glb."""
    glb = _present(folder, f"{scene}/{GLB_NAME}") if scene else None
    if glb is None:
        return None, []
    if scene_json is None or report is None:  # a results row: its scene folder's files, read only now
        scene_json, report = _json_object(folder, f"{scene}/{SCENE_FILE}"), _json_object(folder, f"{scene}/report.json")
    return glb, scene_objects(scene_json, report)


def _present(folder: Path, relative: str) -> str | None:
    """`relative` (normalised) when a regular file is there, None when nothing is; a symbolic link on the way or
    anything other than a regular file is refused (the page would show what it leads to)."""
    path = folder
    for part in Path(relative).parts:
        path = path / part
        try:
            info = path.lstat()
        except (FileNotFoundError, NotADirectoryError):
            return None
        except OSError as exc:
            raise GalleryError(f"{path}: cannot be read ({exc.strerror or exc})") from None
        if stat.S_ISLNK(info.st_mode):
            raise GalleryError(f"{path}: is a symbolic link; a report follows no link (copy the file there instead)")
    if not stat.S_ISREG(info.st_mode):
        raise GalleryError(f"{path}: is not a regular file; refused")
    return Path(relative).as_posix()


def _json_object(folder: Path, relative: str) -> dict[str, Any]:
    """A JSON file's top-level object; {} when it is missing or not a JSON object (the card shows less). A file the
    reader refuses (a link, a special file, too large) is a `GalleryError`."""
    if not os.path.lexists(folder / relative):
        return {}
    data = read_folder_file(folder, relative, MAX_JSON_BYTES)
    try:
        value = load_json(data)
    except ValueError:  # not JSON, or too deeply nested to read: damaged, shown so on the card
        return {}
    return value if isinstance(value, dict) else {}


def _mapping(value: Any) -> Mapping[str, Any]:
    return value if isinstance(value, Mapping) else {}


def _dicts(value: Any) -> list[Mapping[str, Any]]:
    return [v for v in value if isinstance(v, Mapping)] if isinstance(value, list) else []


def _text(value: Any) -> str:
    return "" if value is None else value if isinstance(value, str) else json.dumps(value, default=str)


def _integer(value: Any) -> int | None:
    return value if isinstance(value, int) and not isinstance(value, bool) else None
