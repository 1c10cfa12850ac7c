"""Physics speed: build and settle a 40-object scene, real-time factor, render time per frame."""

from __future__ import annotations

import statistics
import time
from typing import Any

import mujoco

from physcensis.bench.spatial_speed import crowded_program
from physcensis.physics.mujoco_engine import TIMESTEP, MujocoEngine
from physcensis.physics.render import make_renderer, render_built
from physcensis.solver.pipeline import solve


def run(objects: int = 40, repeats: int = 3) -> dict[str, Any]:
    program, support = crowded_program(objects, cell=0.25)
    scene = solve(program, support=support, seed=0, physics=False).scene
    engine = MujocoEngine()
    engine.build(scene, visual=False)  # warm the asset cache
    build_s = statistics.median(_time(lambda: engine.build(scene, visual=False)) for _ in range(repeats))
    # A new engine each time: an engine keeps the compiled model of what it settled (build_posed).
    settle_s = statistics.median(
        _time(lambda: MujocoEngine(engine.catalogue).settle(scene, duration_s=2.0)) for _ in range(repeats)
    )
    built = engine.build(scene, visual=False)
    steps = int(2.0 / TIMESTEP)
    start = time.perf_counter()
    mujoco.mj_step(built.model, built.data, nstep=steps)
    step_s = time.perf_counter() - start
    visual = engine.build(scene)
    first = _time(lambda: render_built(visual, scene, size=(640, 480)))  # includes the GL context
    renderer = make_renderer(visual, (640, 480))
    frames = [_time(lambda: render_built(visual, scene, size=(640, 480), renderer=renderer)) for _ in range(5)]
    renderer.close()
    return {
        "objects": len(scene.objects),
        "build_median_s": round(build_s, 4),
        "build_and_settle_2s_median_s": round(settle_s, 4),
        "real_time_factor": round(2.0 / step_s, 2),
        "render_640x480_first_frame_s": round(first, 4),
        "render_640x480_median_s": round(statistics.median(frames), 4),
        "timestep_s": TIMESTEP,
    }


def _time(fn: Any) -> float:
    start = time.perf_counter()
    fn()
    return time.perf_counter() - start
