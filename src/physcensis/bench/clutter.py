"""The clutter-count protocol (the paper's comparison with ClutterGen).

Ten YCB dining assets on a 0.40 x 0.60 m table; shuffle them (seeded), place them
one after another with PLACE-ANYWHERE, cycling through the list; stop at the first
object that cannot be placed (`with-skip`: skip it and go on until no asset fits or
time runs out). Score: objects placed and still resting after the physics check.
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

import numpy as np

from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.machine import machine_info
from physcensis.physics.engine import DEFAULT_TOLERANCE
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.physics.profiles import MUJOCO_DEFAULT
from physcensis.program.registry import PlacementKind
from physcensis.scene import Scene, Support
from physcensis.solver.physical import PhysicalSolver, PlaceRequest
from physcensis.solver.pipeline import verify

Mode = Literal["no-stack", "with-stack", "with-skip"]
MODES: tuple[str, ...] = ("no-stack", "with-stack", "with-skip")
CLUTTER_TABLE = Support(kind="table", size=(0.40, 0.60))
YCB_DINING = (
    "ycb_005_tomato_soup_can",
    "ycb_006_mustard_bottle",
    "ycb_007_tuna_fish_can",
    "ycb_009_gelatin_box",
    "ycb_010_potted_meat_can",
    "ycb_019_pitcher_base",
    "ycb_024_bowl",
    "ycb_025_mug",
    "ycb_029_plate",
    "ycb_030_fork",
)
# Where PLACE-ANYWHERE puts each object: packed snug against what is there and the table's edges (our mode, which the
# paper does not describe), or the predicate's own random spot among those that fit (as the paper's ANYWHERE reads).
PLACEMENTS = {"packed": True, "random": False}
MAX_OBJECTS = 80  # a bound for with-skip, far above what the table holds
SKIP_TIME_LIMIT_S = 60.0


@dataclass
class ClutterScene:
    seed: int
    placed: int
    attempts: int
    seconds: float
    settle_distance_m: float
    scene: Scene
    stop_reason: str


def run_scene(
    mode: Mode,
    seed: int,
    *,
    catalogue: Catalogue | None = None,
    engine: MujocoEngine | None = None,
    time_limit_s: float = SKIP_TIME_LIMIT_S,
    overhang: bool = False,
    pitch: float | None = None,
    patience: int = 1,
    placement: str = "packed",
) -> ClutterScene:
    """One scene of the protocol. `patience`: stop after this many failures in a row, each failed object skipped
    (1, the paper's rule: stop at the first failure); `with-skip` goes on until no asset fits or time runs out."""
    if mode not in MODES:
        raise ValueError(f"mode must be one of {', '.join(MODES)}")
    if patience < 1:
        raise ValueError("patience must be at least 1")
    if placement not in PLACEMENTS:
        raise ValueError(f"placement must be one of {', '.join(PLACEMENTS)}")
    start = time.perf_counter()
    catalogue = catalogue or default_catalogue()
    engine = engine or MujocoEngine(catalogue)
    assets = [catalogue.get(a) for a in YCB_DINING]
    order = [int(k) for k in np.random.default_rng(seed).permutation(len(assets))]
    scene = Scene(seed=seed, prompt=f"clutter benchmark ({mode})", support=CLUTTER_TABLE)
    solver = PhysicalSolver(scene, engine, seed=seed, pitch=pitch)
    loop = AttemptLoop(order, patience if mode != "with-skip" else None)
    while (k := loop.next_asset()) is not None:
        asset = assets[k]
        request = PlaceRequest(
            object_id=f"{asset.kind.replace(' ', '_')}_{loop.attempts}",
            description=asset.description,
            asset=asset,
            kind=PlacementKind.ANYWHERE,
            stack=mode != "no-stack",
            pack=PLACEMENTS[placement],
            overhang=overhang,
        )
        loop.record(k, solver.place(request).ok)
        if mode == "with-skip" and loop.stop is None and time.perf_counter() - start > time_limit_s:
            loop.stop = f"time limit of {time_limit_s:.0f} s"
    # The final physics check of the whole scene, as for any solved program: what moves is failed and
    # removed, the rest take their settled poses; the score counts what still rests.
    verify(scene, engine, DEFAULT_TOLERANCE)
    distance = engine.settle_distance(scene).mean_m if scene.placed else 0.0
    seconds = time.perf_counter() - start
    return ClutterScene(seed, len(scene.placed), loop.attempts, seconds, distance, scene, loop.stop or "")


class AttemptLoop:
    """The protocol's order of attempts and its stopping rules: cycle through the shuffled assets; stop after
    `patience` failures in a row (None, with-skip: skip each asset that failed once, until none is left), or after
    MAX_OBJECTS attempts."""

    def __init__(self, order: list[int], patience: int | None) -> None:
        self.order = order
        self.patience = patience
        self.attempts = 0
        self.failures = 0  # in a row
        self.index = 0
        self.unplaceable: set[int] = set()
        self.stop: str | None = None

    def next_asset(self) -> int | None:
        """The next asset to try, or None once a stopping rule holds."""
        if self.stop is None and self.attempts >= MAX_OBJECTS:
            self.stop = f"{MAX_OBJECTS} attempts"
        if self.stop is not None:
            return None
        while self.order[self.index % len(self.order)] in self.unplaceable:
            self.index += 1
        self.index += 1
        return self.order[(self.index - 1) % len(self.order)]

    def record(self, asset: int, ok: bool) -> None:
        self.attempts += 1
        self.failures = 0 if ok else self.failures + 1
        if ok:
            return
        if self.patience is None:
            self.unplaceable.add(asset)
            if len(self.unplaceable) == len(self.order):
                self.stop = "no remaining asset fits"
        elif self.failures >= self.patience:
            self.stop = stop_reason(self.patience)


def stop_reason(patience: int) -> str:
    """Why a scene stopped under the failures-in-a-row rule."""
    return "the first object that could not be placed" if patience == 1 else f"{patience} failures in a row"


def scene_folder_name(mode: str, seed: int) -> str:
    return f"{mode}_{seed:04d}"


def count_statistics(counts: list[int], seconds: list[float]) -> dict[str, float]:
    """The summary's figures of a run: objects per scene and seconds per scene."""
    return {
        "mean_objects": round(statistics.mean(counts), 3),
        "std_objects": round(statistics.pstdev(counts), 3),
        "min_objects": min(counts),
        "max_objects": max(counts),
        "mean_seconds_per_scene": round(statistics.mean(seconds), 3),
        "median_seconds_per_scene": round(statistics.median(seconds), 3),
    }


def run(
    mode: Mode,
    scenes: int,
    seed: int = 0,
    *,
    out_dir: Path | None = None,
    overhang: bool = False,
    patience: int = 1,
    placement: str = "packed",
    progress: Callable[[int, ClutterScene], None] | None = None,
) -> dict[str, Any]:
    """Many scenes; mean and standard deviation of the count, time per scene, settle distance."""
    from physcensis.output import write_solution
    from physcensis.program import CheckReport
    from physcensis.solver.pipeline import Solution

    catalogue = default_catalogue()
    engine = MujocoEngine(catalogue)
    rows = []
    for i in range(scenes):
        result = run_scene(
            mode,
            seed + i,
            catalogue=catalogue,
            engine=engine,
            overhang=overhang,
            patience=patience,
            placement=placement,
        )
        rows.append(result)
        if out_dir is not None:
            result.scene.metrics = {"objects_placed": result.placed, "settle_distance_m": result.settle_distance_m}
            folder = out_dir / scene_folder_name(mode, seed + i)
            write_solution(Solution(result.scene, CheckReport(())), folder, engine=engine)
        if progress:
            progress(i, result)
    counts = [r.placed for r in rows]
    return {
        "mode": mode,
        "scenes": scenes,
        "seed": seed,
        "patience": patience,  # with-skip has its own rule (skip what failed until nothing fits)
        "overhang": overhang,
        "placement": placement,
        **count_statistics(counts, [r.seconds for r in rows]),
        "mean_settle_distance_m": round(statistics.mean(r.settle_distance_m for r in rows), 6),
        "paper": {"no-stack": 14.77, "with-stack": 22.30, "cluttergen": 3.57},
        "counts": counts,
        "mujoco_default": summarise_under_defaults([measure_under_mujoco_defaults(r.scene, catalogue) for r in rows]),
        "machine": machine_info(),
    }


def run_all(scenes: int = 20, seed: int = 0) -> dict[str, Any]:
    """What `make bench` runs: every mode on the same seeds (the README's 100-scene figures come from
    `physcensis bench clutter --scenes 100`)."""
    results = {mode: run(mode, scenes, seed) for mode in ("no-stack", "with-stack")}
    results["no-stack-overhang"] = run("no-stack", scenes, seed, overhang=True)
    results["no-stack-random"] = run("no-stack", scenes, seed, placement="random")
    results["with-skip"] = run("with-skip", max(3, scenes // 4), seed)
    return results


# --- every final scene measured under MuJoCo's default contact settings (ours and the peer's alike) ----------------


@dataclass(frozen=True)
class DefaultsMeasure:
    """A final scene loaded into MuJoCo with its default contact settings: how far it settles, and what still rests
    after the same final check as any solved program (whatever moves more than 1 cm or 10 degrees is removed)."""

    objects: int
    resting: int
    settle_distance_m: float


def measure_under_mujoco_defaults(scene: Scene, catalogue: Catalogue) -> DefaultsMeasure:
    """The scene as its method delivered it (left unchanged), measured under `MUJOCO_DEFAULT`."""
    if not scene.placed:
        return DefaultsMeasure(0, 0, 0.0)
    engine = MujocoEngine(catalogue, profile=MUJOCO_DEFAULT)
    distance = engine.settle_distance(scene).mean_m
    checked = scene.model_copy(deep=True)
    verify(checked, engine, DEFAULT_TOLERANCE)
    return DefaultsMeasure(len(scene.placed), len(checked.placed), distance)


def summarise_under_defaults(measures: list[DefaultsMeasure]) -> dict[str, Any]:
    """The `mujoco_default` block of a clutter summary."""
    resting = [m.resting for m in measures]
    return {
        "profile": MUJOCO_DEFAULT.name,
        "mean_resting": round(statistics.mean(resting), 3),
        "std_resting": round(statistics.pstdev(resting), 3),
        "min_resting": min(resting),
        "max_resting": max(resting),
        "all_rest": all(m.resting == m.objects for m in measures),
        "mean_settle_distance_m": round(statistics.mean(m.settle_distance_m for m in measures), 6),
        "max_settle_distance_m": round(max(m.settle_distance_m for m in measures), 6),
        "resting": resting,
    }
