"""Spatial solver speed: dining_4 (target: median <= 0.5 s) and how time grows with object count."""

from __future__ import annotations

import statistics
import time
from functools import partial
from typing import Any

from physcensis.assets import default_catalogue
from physcensis.examples import example_path
from physcensis.program import Program, load_program, parse_program
from physcensis.scene import Support
from physcensis.solver.objects import resolve_assets
from physcensis.solver.spatial import optimise_layout

KINDS = [
    "a white ceramic mug",
    "a hardcover book lying flat",
    "a glass jar of honey",
    "a red apple",
    "a small potted succulent",
    "a can of tomato soup",
    "a smartphone",
    "a wooden toy block",
]


def crowded_program(n_objects: int, cell: float = 0.18) -> tuple[Program, Support]:
    """n objects in rows on a table of about `cell` x `cell` per object: each row starts at a given spot,
    the rest of the row lines up to the right of its neighbour; yaws are random."""
    per_row = max(2, round(n_objects**0.5))
    rows = -(-n_objects // per_row)
    support = Support(kind="table", size=(cell * rows, cell * per_row))
    hx, hy = support.half_extents
    entries: list[list[Any]] = []
    for i in range(n_objects):
        oid = f"obj_{i}"
        row, col = divmod(i, per_row)
        entries.append([oid, KINDS[i % len(KINDS)]])
        if col == 0:
            entries.append(
                [oid, "PLACE-ON-BASE", "root", {"x": round(-hx + cell * (row + 0.5), 3), "y": round(hy - cell / 2, 3)}]
            )
        else:
            entries.append([oid, "PLACE-ON-BASE", "root", {}])
            entries.append([oid, "RIGHT-OF", f"obj_{i - 1}", {"distance": 0.02}])
            entries.append([oid, "ALIGN-CENTER-FB", f"obj_{i - 1}", {}])
        entries.append([oid, "RANDOM-ROT", "root", {}])
    return parse_program(entries), support


def _median_time(fn: Any, repeats: int) -> tuple[float, Any]:
    times, result = [], None
    for _ in range(repeats):
        start = time.perf_counter()
        result = fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times), result


def run(repeats: int = 10) -> dict[str, Any]:
    catalogue = default_catalogue()
    program = load_program(example_path("dining_4.json"))
    assert program.support is not None
    prints = {oid: a.footprint() for oid, a in resolve_assets(program, catalogue).items()}
    dining_s, dining = _median_time(lambda: optimise_layout(program, program.support, prints, seed=0), repeats)
    scaling = []
    for n in (8, 16, 32, 64):
        crowded, support = crowded_program(n)
        fp = {oid: a.footprint() for oid, a in resolve_assets(crowded, catalogue).items()}
        seconds, result = _median_time(partial(optimise_layout, crowded, support, fp, seed=0), 3)
        scaling.append(
            {
                "objects": n,
                "median_s": round(seconds, 4),
                "ok": result.ok,
                "rounds": result.rounds,
                "evaluations": result.evaluations,
                "overlap_cm2": round(result.overlap_m2 * 1e4, 3),
            }
        )
    return {
        "dining_4": {
            "objects": len(dining.poses),
            "median_s": round(dining_s, 4),
            "repeats": repeats,
            "ok": dining.ok,
            "rounds": dining.rounds,
            "target_s": 0.5,
        },
        "scaling": scaling,
    }
