"""Fuzz the report reader: `collect_cards` (results.jsonl, or the scene folders' scene.json, report.json and
batch.json) and `write_report` (the page, with or without the images embedded), as `physcensis report` runs them, on
a report's folder with one file damaged. Half the examples drop results.jsonl, so the cards come from the folders."""

from __future__ import annotations

import json
import tempfile
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.fuzz.harness import FUZZ, TIMEOUT, Blob, copy_folder, read_safely, size_on_disk
from tests.fuzz.mutations import mutated_bytes, mutated_json, mutated_jsonl
from tests.fuzz.readers import report

pytestmark = [pytest.mark.fuzz, TIMEOUT]
RESULTS = "results.jsonl"
TARGETS = [
    RESULTS,
    RESULTS,
    "ours/s0/scene.json",
    "ours/s0/report.json",
    "ours/s0/batch.json",
    "ours/real/scene.json",
    "ours/real/report.json",
    "peer/s0/report.json",
    "ours/s0/render.png",
]


def _rows(path: Path) -> list[Any]:
    return [json.loads(line) for line in path.read_text().splitlines() if line.strip()]


@st.composite
def damaged_files(draw: st.DrawFn, seed: Path) -> tuple[str, bytes, bool]:
    """(the file damaged, its new content, whether results.jsonl is dropped)."""
    target = draw(st.sampled_from(TARGETS))
    if target == RESULTS:
        content = draw(mutated_jsonl(_rows(seed / target)))
    elif target.endswith(".json"):
        content = draw(mutated_json(json.loads((seed / target).read_text())))
    else:
        content = draw(mutated_bytes((seed / target).read_bytes()))
    return target, Blob(content), target != RESULTS and draw(st.booleans())


@FUZZ
@given(data=st.data(), embed=st.booleans())
def test_a_damaged_report_folder_is_shown_or_refused(report_seed: Path, data: st.DataObject, embed: bool) -> None:
    target, content, drop_results = data.draw(damaged_files(report_seed), label="damage")
    with tempfile.TemporaryDirectory() as tmp:
        folder = copy_folder(report_seed, Path(tmp) / "report", skip=(RESULTS,) if drop_results else ())
        (folder / target).write_bytes(content)
        read_safely(lambda: report(folder, embed), size_on_disk([folder]), keep=folder)
