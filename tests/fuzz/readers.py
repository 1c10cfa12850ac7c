"""The fuzz targets: each the entry point a user's command reaches, called in-process, from the reading of the files
to the first use of what was read."""

from __future__ import annotations

import importlib.util
from collections.abc import Callable
from pathlib import Path
from typing import Any

from physcensis.batch import SCENES_DIR, Options, read_prompts, run_batch
from physcensis.batch.records import read_record
from physcensis.gallery import collect_cards, write_report
from physcensis.output import open_scene
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.program import check_program, load_program, parse_program
from physcensis.robot.world import build_world, read_scene_folder
from tests.batch.stub_scenes import stub_scene

BATCH_OPTIONS = Options(exports=("none",))  # the stub scene maker writes no exports
NPZ_READER = importlib.util.find_spec("physcensis.assets.npz") is not None  # the bounded reader of asset copies


def read_and_check(source: str | list[Any] | dict[str, Any]) -> None:
    """`physcensis check -` (a program as text), or a program handed over as data (an LLM client's reply)."""
    check_program(parse_program(source))


def load_and_check(path: Path) -> None:
    """`physcensis check FILE` (and what solve, generate --program and batch read first)."""
    check_program(load_program(path))


def open_and_build(folder: Path) -> None:
    """`render`, `export`, `stability`, `eval settle`: the scene folder with its asset copies, built into MuJoCo."""
    scene, catalogue = open_scene(folder)
    if scene.placed:
        MujocoEngine(catalogue).build(scene)


def read_and_build(folder: Path) -> None:
    """`demo`: the scene and its MJCF export read and checked together, then compiled with the robot."""
    read_scene_folder(folder)
    build_world(folder)


def read_records(out: Path) -> None:
    """Each scene folder's record, as a resume reads it."""
    for folder in sorted((out / SCENES_DIR).iterdir()):
        read_record(out, folder.name)


def resume(out: Path, prompts: Path) -> None:
    """`physcensis batch PROMPTS --out OUT` again over a finished batch (its scenes made by the stub)."""
    run_batch(read_prompts(prompts), out, per_prompt=2, options=BATCH_OPTIONS, scene_maker=stub_scene)


def report(folder: Path, embed: bool) -> None:
    """`physcensis report FOLDER [--embed]`."""
    collect_cards(folder)
    write_report(folder, embed=embed, overwrite=True)


def reader_for(target: str, folder: Path, seed: Path) -> Callable[[], object]:
    """The reader of a folder copied from `seed`: "program" (its desk_basic.json), "scene", "mjcf", "batch" (the
    records, then the resume) or "report"."""
    if target == "program":
        return lambda: load_and_check(folder / "desk_basic.json")
    if target == "scene":
        return lambda: open_and_build(folder)
    if target == "mjcf":
        return lambda: read_and_build(folder)
    if target == "batch":
        return lambda: (read_records(folder), resume(folder, seed.parent / "prompts.txt"))
    return lambda: report(folder, embed=True)
