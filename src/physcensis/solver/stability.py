"""Stability: the probability that an object falls under small perturbations.

`estimate_stability` perturbs one object's pose, centre of mass, friction and mass
(model in `solver/perturb.py`), runs every perturbed copy of its neighbourhood for a
short horizon in one batch (`solver/stability_sim.py`, `physics/rollouts.py`),
labels each copy fell or stood, and reports p_fail(0), the kernel-weighted failure
rate around the state the scene holds, with the number of samples behind it.

A scene is as fragile as its most fragile object: `SceneStability.p_fail` is the
largest per-object p_fail (the mean is reported too).

Every p_fail comes with a 95 % interval: Wilson's score interval on the estimate's effective sample size (Kish's,
of the kernel weights), as the weighted rate behaves like a rate over that many samples. `min_effective` keeps
drawing rounds of samples (fresh streams, pooled) until the estimate rests on that many effective samples: 128 draws
give about 26 in 11 dimensions, which leaves an interval of about ±0.15 around 0.3.

Searching for a fragile or robust state is in `solver/stability_search.py`
(`search_stability`, `refine_stability`), which builds on this module.
"""

from __future__ import annotations

import math
import time
import zlib
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.physics.rollouts import FallRule
from physcensis.scene import Scene
from physcensis.solver.perturb import PerturbationScales, effective_samples, p_fail, sample
from physcensis.solver.stability_sim import StandCheck, StandRule, asset_of, check_stands, neighbourhood, simulate

__all__ = [
    "FallRule",
    "PerturbationScales",
    "SceneStability",
    "StabilityEstimate",
    "StabilitySettings",
    "StandCheck",
    "StandRule",
    "check_stands",
    "estimate_from_samples",
    "estimate_scene_stability",
    "estimate_stability",
]


Z_95 = 1.959964
MIN_EFFECTIVE = 80.0  # what `physcensis stability` draws until (an interval of about ±0.1 around 0.3)
MAX_SAMPLES = 1024  # ... but never more than this many draws per object
STREAM_STEP = 7919  # the extra rounds' streams: far from the rounds a search numbers 0, 1, 2, ...


def wilson_interval(p: float, n: float, z: float = Z_95) -> tuple[float, float]:
    """Wilson's score interval of a rate `p` over `n` (effective) samples; (0, 1) when there are none."""
    if n <= 0:
        return 0.0, 1.0
    denominator = 1.0 + z * z / n
    centre = (p + z * z / (2 * n)) / denominator
    half = z / denominator * math.sqrt(max(0.0, p * (1 - p) / n + z * z / (4 * n * n)))
    return max(0.0, centre - half), min(1.0, centre + half)


@dataclass(frozen=True)
class StabilitySettings:
    """How one stability estimate is made."""

    samples: int = 128
    horizon_s: float = 0.8
    scales: PerturbationScales = PerturbationScales()
    fall: FallRule = FallRule()
    # Simulated free: the object, what rests on it, what touches them, and what lies within this distance (None:
    # the whole scene). The rest is held fixed: it matters only if something falls onto it.
    neighbourhood_m: float | None = 0.0
    threads: int | None = None  # None: every CPU
    batched: bool = True


@dataclass
class StabilityEstimate:
    """p_fail(0) of one object and the labelled samples behind it."""

    object_id: str
    p_fail: float
    samples: int
    fell: int
    blew_up: int
    effective_samples: float  # Kish's effective size of the kernel weights at 0
    simulated_objects: int
    horizon_s: float
    wall_s: float
    perturbations: np.ndarray = field(repr=False)  # (n, 11)
    labels: np.ndarray = field(repr=False)  # (n,) 1 = fell
    sigma: np.ndarray = field(repr=False)  # (11,)
    group: list[str] = field(default_factory=list)  # the object and what rests on it (moved with it)

    @property
    def interval(self) -> tuple[float, float]:
        """The 95 % interval of p_fail (Wilson's, on the effective samples)."""
        return wilson_interval(self.p_fail, self.effective_samples)

    def to_dict(self) -> dict[str, Any]:
        return {
            "object": self.object_id,
            "p_fail": round(self.p_fail, 4),
            "p_fail_95": [round(v, 4) for v in self.interval],
            "samples": self.samples,
            "fell": self.fell,
            "blew_up": self.blew_up,
            "effective_samples": round(self.effective_samples, 1),
            "simulated_objects": self.simulated_objects,
            "horizon_s": self.horizon_s,
            "wall_s": round(self.wall_s, 3),
        }


@dataclass
class SceneStability:
    """Per-object estimates; the scene's p_fail is the largest of them."""

    objects: dict[str, StabilityEstimate]

    @property
    def p_fail(self) -> float:
        return max((e.p_fail for e in self.objects.values()), default=0.0)

    @property
    def mean_p_fail(self) -> float:
        return float(np.mean([e.p_fail for e in self.objects.values()])) if self.objects else 0.0

    def to_dict(self) -> dict[str, Any]:
        return {
            "p_fail": round(self.p_fail, 4),
            "mean_p_fail": round(self.mean_p_fail, 4),
            "samples_per_object": max((e.samples for e in self.objects.values()), default=0),
            "objects": [e.to_dict() for e in self.objects.values()],
        }


def sample_rng(seed: int, object_id: str, round_: int = 0) -> np.random.Generator:
    """The generator of one object's perturbations: independent of the other objects, one stream per round."""
    return np.random.default_rng([seed, zlib.crc32(object_id.encode("utf-8")), 104729, round_])


def estimate_from_samples(
    object_id: str,
    x: np.ndarray,
    labels: np.ndarray,
    sigma: np.ndarray,
    *,
    blew_up: int = 0,
    simulated_objects: int = 0,
    horizon_s: float = math.nan,
    wall_s: float = 0.0,
    group: Sequence[str] = (),
    query: np.ndarray | None = None,
) -> StabilityEstimate:
    """The estimate at `query` (default 0) from labelled samples; the perturbations are stored relative to it."""
    query = np.zeros_like(sigma) if query is None else query
    zero = np.zeros_like(sigma)
    relative = x - query
    return StabilityEstimate(
        object_id=object_id,
        p_fail=p_fail(relative, labels, zero, sigma),
        samples=len(x),
        fell=int(labels.sum()),
        blew_up=blew_up,
        effective_samples=effective_samples(relative, zero, sigma),
        simulated_objects=simulated_objects,
        horizon_s=horizon_s,
        wall_s=wall_s,
        perturbations=relative,
        labels=labels,
        sigma=sigma,
        group=list(group),
    )


def estimate_stability(
    scene: Scene,
    object_id: str,
    samples: int = 128,
    seed: int = 0,
    *,
    engine: MujocoEngine | None = None,
    settings: StabilitySettings | None = None,
    round_: int = 0,
    min_effective: float | None = None,
    max_samples: int = MAX_SAMPLES,
) -> StabilityEstimate:
    """p_fail(0) of one placed object from `samples` perturbed, simulated copies of its neighbourhood; with
    `min_effective`, more rounds of `samples` (fresh streams) until the estimate rests on that many effective samples
    or `max_samples` are drawn. Deterministic for a given seed (and `round_`, the stream a search uses for its
    repeated estimates)."""
    start = time.perf_counter()
    engine = engine or MujocoEngine()
    settings = settings or StabilitySettings()
    hood = neighbourhood(scene, object_id, engine, settings.neighbourhood_m)
    sigma = settings.scales.sigma(asset_of(engine, scene.object(object_id)))
    draws, fell, blew_up = [], [], 0
    stream = round_
    while True:
        x = sample(sample_rng(seed, object_id, stream), sigma, samples)
        outcome = simulate(
            hood, x, settings.horizon_s, settings.fall, batched=settings.batched, threads=settings.threads
        )
        draws.append(x)
        fell.append(outcome.fell.astype(float))
        blew_up += int(outcome.blew_up.sum())
        pooled = np.concatenate(draws)
        if (
            min_effective is None
            or len(pooled) + samples > max_samples
            or effective_samples(pooled, np.zeros_like(sigma), sigma) >= min_effective
        ):
            break
        stream += STREAM_STEP
    return estimate_from_samples(
        object_id,
        pooled,
        np.concatenate(fell),
        sigma,
        blew_up=blew_up,
        simulated_objects=len(hood.built.objects),
        horizon_s=settings.horizon_s,
        wall_s=time.perf_counter() - start,
        group=hood.group,
    )


def estimate_scene_stability(
    scene: Scene,
    object_ids: Sequence[str] | None = None,
    samples: int = 128,
    seed: int = 0,
    *,
    engine: MujocoEngine | None = None,
    settings: StabilitySettings | None = None,
    min_effective: float | None = None,
) -> SceneStability:
    """Estimate every placed object (or the given ones), each with its own perturbed copies."""
    engine = engine or MujocoEngine()
    ids = list(object_ids) if object_ids is not None else [o.id for o in scene.placed]
    return SceneStability(
        {
            oid: estimate_stability(
                scene, oid, samples, seed, engine=engine, settings=settings, min_effective=min_effective
            )
            for oid in ids
        }
    )
