"""A finished scene's record (`scenes/<key>/batch.json`) read back when a batch resumes.

A batch folder may come from elsewhere (copied from a cluster, sent by a colleague), so what a resume finds under
`scenes/` is untrusted input. Each record is read with `read_in_folder` (a regular file inside the batch folder, no
symbolic link anywhere on the way: the driver writes none, so one is someone else's), at most MAX_RECORD_BYTES,
parsed with the bounded JSON reader and validated against `SceneRecord`: the fields every version of the writer
(`worker.make_scene`) has produced, of their types, and nothing else. Its key and scene path must be its folder's.

A scene folder without a record is not finished (a folder the driver never wrote: it is made again). A record that is
there but refused is not guessed at: the driver publishes scene folders whole (written in a hidden staging folder and
renamed), so it never leaves a record half-written, and a bad one is someone else's doing. The resume stops with one
line naming the file, before anything is written.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, ValidationError

from physcensis.batch.prompts import BatchError
from physcensis.batch.worker import RECORD, SCENES_DIR
from physcensis.bounded_json import load_json
from physcensis.fileio import BoundError, read_in_folder

MAX_RECORD_BYTES = 64 * 1024  # a record is about a kilobyte


class SceneRecord(BaseModel):
    """The fields of a record. The ones after `scene` came with later versions and may be missing from older records;
    `ok` is always true (a failed scene has no folder)."""

    model_config = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False)

    key: str
    prompt_id: str
    prompt: str
    support: str
    seed: int
    scene: str
    agent: str | None = None
    worker: str | None = None
    ok: Literal[True] = True
    seconds: float | None = None
    rounds: int | None = None
    exports: list[str] | None = None
    variety: str | None = None
    added: list[str] | None = None
    objects: int | None = None
    objects_failed: int | None = None
    settle_distance_m: float | None = None
    stage_seconds: dict[str, float] | None = None


@dataclass(frozen=True)
class Record:
    """A record as read: its validated fields, and the JSON object as written (the manifest line is made from it)."""

    fields: SceneRecord
    data: dict[str, Any]


def read_record(out: Path, name: str) -> Record | None:
    """The record of the scene folder `out/scenes/<name>`, None when it has none; `BatchError` naming the file when
    it is refused (a link, a special file, too large, not JSON, not of a record's shape)."""
    relative = f"{SCENES_DIR}/{name}/{RECORD}"
    path = out / relative
    if not os.path.lexists(path):
        return None
    try:
        raw = read_in_folder(out, relative, MAX_RECORD_BYTES, str(path))
    except BoundError as exc:  # its message names the file
        raise _refused(str(exc), name) from None
    try:
        data = _parsed(raw)
        fields = SceneRecord.model_validate(data)
    except ValueError as exc:  # not UTF-8, not JSON, nested too deeply (BoundError), not a record (ValidationError)
        raise _refused(f"{path}: not a scene record: {_problem(exc)}", name) from None
    if (fields.key, fields.scene) != (name, f"{SCENES_DIR}/{name}"):
        raise _refused(f"{path}: is the record of {fields.key!r}, not of its folder {name!r}", name)
    return Record(fields, data)


def _parsed(raw: bytes) -> dict[str, Any]:
    data = load_json(raw.decode("utf-8"))
    if not isinstance(data, dict):
        raise ValueError(f"a JSON {type(data).__name__}, not an object")
    return data


def _problem(exc: Exception) -> str:
    """The first thing wrong, on one line: "seed: Input should be a valid integer"."""
    if isinstance(exc, ValidationError):
        error = exc.errors()[0]
        where = ".".join(str(part) for part in error["loc"]) or "the record"
        more = f" (and {exc.error_count() - 1} more)" if exc.error_count() > 1 else ""
        return f"{where}: {error['msg']}{more}"
    return " ".join(str(exc).split())


def _refused(message: str, name: str) -> BatchError:
    return BatchError(
        f"{message}; a resume reads only records the batch wrote: remove {SCENES_DIR}/{name} to have it made again, "
        "or use another --out"
    )
