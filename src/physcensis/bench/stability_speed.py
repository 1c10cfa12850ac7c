"""Stability speed: one 128-sample p_fail estimate in a 20-object scene, serial against batched (target: under
2 s batched on 2 cores). The probe is a mug on a book in the middle of the table; by default only what touches
it is simulated (the rest held fixed), and once for comparison the whole scene."""

from __future__ import annotations

import math
import statistics
import time
from dataclasses import replace
from typing import Any

import numpy as np

from physcensis.assets import default_catalogue
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.physics.rollouts import default_threads
from physcensis.scene import PlacedObject, Scene, Support
from physcensis.solver.stability import StabilitySettings, estimate_stability

FILL = (
    "can_soup",
    "bowl_cereal_white",
    "apple_red",
    "jar_honey",
    "plate_dinner_white",
    "glass_tumbler",
    "phone_black",
    "bottle_water_plastic",
    "mug_white",
    "can_soda_red",
)
PROBE = "mug_0"
TARGET_S = 2.0


def twenty_objects() -> Scene:
    """A 1.0 x 0.8 m table with 18 objects in a grid, a book in the middle and a mug on it, settled."""
    catalogue = default_catalogue()
    support = Support(kind="table", size=(0.8, 1.0))
    top = support.top_height
    objects = []
    cells = [(x, y) for x in (-0.3, -0.1, 0.1, 0.3) for y in (-0.4, -0.2, 0.0, 0.2, 0.4) if (x, y) != (0.1, 0.0)]
    for i, (x, y) in enumerate(cells[:18]):
        objects.append(_object(f"item_{i}", FILL[i % len(FILL)], x, y, top, yaw=0.7 * i))
    book = catalogue.get("book_flat_hardcover_red")
    objects.append(_object("book_0", book.id, 0.1, 0.0, top))
    objects.append(_object(PROBE, "mug_white", 0.1, 0.0, top + book.size[2]))
    scene = Scene(seed=0, support=support, objects=objects)
    settled = MujocoEngine(catalogue).settle(scene, duration_s=1.0)
    scene.objects = [
        o.model_copy(
            update={"position": settled.objects[o.id].position, "quaternion": settled.objects[o.id].quaternion}
        )
        for o in scene.objects
    ]
    return scene


def _object(oid: str, asset_id: str, x: float, y: float, z: float, yaw: float = 0.0) -> PlacedObject:
    asset = default_catalogue().get(asset_id)
    return PlacedObject(
        id=oid,
        description=asset.description,
        asset=asset_id,
        category=asset.category,
        position=(x, y, z),
        quaternion=(math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)),
        mass=asset.mass,
        friction=float(np.mean(asset.friction_range)),
        com=asset.com,
    )


def run(samples: int = 128, repeats: int = 3) -> dict[str, Any]:
    scene = twenty_objects()
    engine = MujocoEngine()
    threads = default_threads()
    batched = StabilitySettings(samples=samples, threads=threads)
    serial = replace(batched, batched=False)
    estimate_stability(scene, PROBE, samples, engine=engine, settings=batched)  # warm the asset cache
    times: dict[str, list[float]] = {"serial": [], "batched": []}
    results = {}
    for _ in range(repeats):
        for name, settings in (("serial", serial), ("batched", batched)):
            start = time.perf_counter()
            results[name] = estimate_stability(scene, PROBE, samples, engine=engine, settings=settings)
            times[name].append(time.perf_counter() - start)
    start = time.perf_counter()  # every object simulated, none held fixed: the worst case, once
    whole = estimate_stability(scene, PROBE, samples, engine=engine, settings=replace(batched, neighbourhood_m=None))
    whole_s = time.perf_counter() - start
    median = {name: statistics.median(values) for name, values in times.items()}
    return {
        "objects": len(scene.objects),
        "samples": samples,
        "threads": threads,
        "simulated_objects": results["batched"].simulated_objects,
        "serial_median_s": round(median["serial"], 3),
        "batched_median_s": round(median["batched"], 3),
        "speedup": round(median["serial"] / median["batched"], 2),
        "p_fail": round(results["batched"].p_fail, 4),
        "serial_equals_batched": bool(np.array_equal(results["serial"].labels, results["batched"].labels)),
        "whole_scene_batched_s": round(whole_s, 3),
        "whole_scene_p_fail": round(whole.p_fail, 4),
        "target_s": TARGET_S,
    }
