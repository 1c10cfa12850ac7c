"""Fuzz the batch resume reader: `read_record` on every scene folder, then the resume itself (`run_batch` over the
same folder, its scenes made by the stub scene maker), on a finished batch folder with one file damaged: a scene's
record (`scenes/<key>/batch.json`) or scene.json, manifest.jsonl or failures.jsonl."""

from __future__ import annotations

import json
import tempfile
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from physcensis.batch import FAILURES, MANIFEST, RECORD, SCENES_DIR
from tests.fuzz.harness import FUZZ, TIMEOUT, Blob, copy_folder, read_safely, size_on_disk
from tests.fuzz.mutations import mutated_json, mutated_jsonl
from tests.fuzz.readers import read_records, resume

pytestmark = [pytest.mark.fuzz, TIMEOUT]


def _targets(seed: Path) -> list[str]:
    scenes = sorted(p.name for p in (seed / SCENES_DIR).iterdir())
    records = [f"{SCENES_DIR}/{name}/{RECORD}" for name in scenes]
    return [*records, *records, MANIFEST, FAILURES, f"{SCENES_DIR}/{scenes[0]}/scene.json"]


def _rows(path: Path) -> list[Any]:
    return [json.loads(line) for line in path.read_text().splitlines() if line.strip()]


@st.composite
def damaged_files(draw: st.DrawFn, seed: Path) -> tuple[str, bytes]:
    target = draw(st.sampled_from(_targets(seed)))
    if target.endswith(".jsonl"):
        return target, Blob(draw(mutated_jsonl(_rows(seed / target))))
    return target, Blob(draw(mutated_json(json.loads((seed / target).read_text()))))


@FUZZ
@given(data=st.data())
def test_a_damaged_batch_folder_is_resumed_or_refused(batch_seed: Path, data: st.DataObject) -> None:
    target, content = data.draw(damaged_files(batch_seed), label="damage")
    with tempfile.TemporaryDirectory() as tmp:
        out = copy_folder(batch_seed, Path(tmp) / "out")
        (out / target).write_bytes(content)
        size = size_on_disk([out])
        read_safely(lambda: read_records(out), size, keep=out)
        read_safely(lambda: resume(out, batch_seed.parent / "prompts.txt"), size, keep=out)
