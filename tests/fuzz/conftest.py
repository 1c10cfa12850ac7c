"""The fuzz profiles, and the seed corpora of the fuzz targets (made once per module).

Two Hypothesis profiles: "fuzz-ci" (the default: few examples, derandomized so that CI is reproducible, no shrinking so
that it fails fast) and "fuzz-long" (FUZZ_PROFILE=long, as `make fuzz` runs it: FUZZ_EXAMPLES examples per target,
random, failures shrunk and kept in Hypothesis's database). Neither is loaded globally: each fuzz test is decorated
with the chosen one (`harness.FUZZ`), so the rest of the suite keeps its own profile.
"""

from __future__ import annotations

import json
import os
import shutil
from datetime import timedelta
from pathlib import Path

import pytest
import trimesh
import yaml
from hypothesis import HealthCheck, Phase, settings
from typer.testing import CliRunner

from physcensis.batch import FAILURES, read_prompts, run_batch
from physcensis.cli import app
from tests.batch.stub_scenes import stub_scene
from tests.conftest import EXAMPLES
from tests.fuzz.readers import BATCH_OPTIONS, reader_for
from tests.gallery.folders import results_file, row, scene_folder

ASSET_ID = "lib_block"
COPY = f"assets/{ASSET_ID}.npz"
BATCH_PROMPT = "a cup"
_SLOW_INPUTS = [HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.large_base_example]

settings.register_profile(
    "fuzz-ci",
    max_examples=30,
    deadline=timedelta(seconds=20),  # a backstop: each reader call has a size-scaled time bound (harness)
    phases=[Phase.explicit, Phase.generate],  # CI fails fast: `make fuzz` shrinks what it finds
    derandomize=True,
    database=None,
    print_blob=True,
    suppress_health_check=_SLOW_INPUTS,
)
settings.register_profile(
    "fuzz-long",
    max_examples=int(os.environ.get("FUZZ_EXAMPLES", "3000")),
    deadline=timedelta(seconds=60),
    derandomize=False,
    print_blob=True,
    suppress_health_check=_SLOW_INPUTS,
)


def _library(root: Path) -> Path:
    """A user library of one asset (a 12 x 9 x 4 cm block): a scene using it carries a copy in assets/."""
    library = root / "library"
    (library / "meshes").mkdir(parents=True)
    block = trimesh.creation.box((0.12, 0.09, 0.04))
    (library / "meshes" / "block.stl").write_bytes(block.export(file_type="stl"))
    entry = {"file": "meshes/block.stl", "id": ASSET_ID, "category": "wooden block", "up": "+z"}
    (library / "library.yaml").write_text(yaml.safe_dump({"assets": [entry]}))
    return library


def _warm(seed: Path, target: str) -> None:
    """Run a reader once on a copy of its seed: what it imports and caches on first use (the catalogue, MuJoCo, the
    robot) is not counted against the first example's time and memory."""
    copy = seed.parent / f".warm-{target}"
    shutil.copytree(seed, copy, symlinks=True)
    try:
        reader_for(target, copy, seed)()
    finally:
        shutil.rmtree(copy)


def _run(args: list[str]) -> None:
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output


@pytest.fixture(scope="module")
def scene_seed(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A real scene folder: a library block and a built-in mug on a table, solved without physics (fast), then
    exported to MJCF into the same folder; it holds scene.json, report.json, layout.png, assets/lib_block.npz,
    mjcf/ and exports.json."""
    root = tmp_path_factory.mktemp("scene-seed")
    library = _library(root)
    program = {
        "support": {"kind": "table", "size": [0.6, 0.4]},
        "program": [
            ["block", f"asset:{ASSET_ID}"],
            ["block", "PLACE-ON-BASE", "root", {"x": 0.1, "y": 0.05}],
            ["block", "FACING-FRONT", "root", {}],
            ["mug", "a mug"],
            ["mug", "PLACE-ON-BASE", "root", {"x": -0.1, "y": -0.05}],
            ["mug", "FACING-FRONT", "root", {}],
        ],
    }
    (root / "program.json").write_text(json.dumps(program))
    out = root / "scene"
    _run(["solve", str(root / "program.json"), "--out", str(out), "--library", str(library), "--no-physics"])
    _run(["export", str(out), "--to", "mjcf", "--out", str(out), "--library", str(library)])
    assert (out / COPY).is_file() and (out / "mjcf" / "scene.xml").is_file() and (out / "exports.json").is_file()
    _warm(out, "scene")
    _warm(out, "mjcf")
    return out


@pytest.fixture(scope="module")
def batch_seed(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A finished batch of two scenes of "a cup" made by the stub scene maker, with an old failure on record."""
    root = tmp_path_factory.mktemp("batch-seed")
    (root / "prompts.txt").write_text(f"{BATCH_PROMPT}\n")
    out = root / "out"
    run_batch(read_prompts(root / "prompts.txt"), out, per_prompt=2, options=BATCH_OPTIONS, scene_maker=stub_scene)
    (out / FAILURES).write_text(json.dumps({"key": "000-a-cup_009", "ok": False, "reason": "an old failure"}) + "\n")
    _warm(out, "batch")
    return out


@pytest.fixture(scope="module")
def report_seed(tmp_path_factory: pytest.TempPathFactory, scene_seed: Path) -> Path:
    """A report's folder: two hand-made scene folders (renders, layouts, batch records), a copy of the real scene
    folder's files, and eval compare's results.jsonl over them."""
    root = tmp_path_factory.mktemp("report-seed") / "report"
    batch = {"key": "000-a-mug_000", "prompt_id": "000-a-mug", "seed": 3}
    scene_folder(root / "ours" / "s0", batch=batch, failed=[("cup_0", "fell off")])
    scene_folder(root / "peer" / "s0", prompt="a plate", problems=[{"message": "no room", "severity": "error"}])
    real = root / "ours" / "real"
    real.mkdir(parents=True)
    for name in ("scene.json", "report.json", "layout.png"):
        (real / name).write_bytes((scene_seed / name).read_bytes())
    metrics = {"settle_distance_m": 0.002, "objects_placed": 2}
    results_file(
        root,
        [
            row("a mug on a coaster", "ours", 3, "ours/s0", metrics, ["cup_0 fell off"]),
            row("a plate", "peer", 3, "peer/s0", {"settle_distance_m": None}),
            row("a mug", "ours", 0, "ours/real", metrics),
        ],
    )
    _warm(root, "report")
    return root


@pytest.fixture(scope="module")
def example_programs() -> dict[str, bytes]:
    """The bundled example programs (JSON, and the LLM-style text one), by file name."""
    return {path.name: path.read_bytes() for path in sorted(EXAMPLES.iterdir()) if path.suffix in (".json", ".txt")}


@pytest.fixture(scope="module")
def example_program_folder(tmp_path_factory: pytest.TempPathFactory, example_programs: dict[str, bytes]) -> Path:
    folder = tmp_path_factory.mktemp("programs")
    for name, data in example_programs.items():
        (folder / name).write_bytes(data)
    _warm(folder, "program")
    return folder
