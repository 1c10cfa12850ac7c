"""Spatial solver: optimise a program's parameters so footprints neither overlap nor leave the support.

Penalty = total pairwise footprint overlap (in units of 1 cm^2) + total distance
of footprints beyond the support's edges (in units of 5 mm). Coordinate descent as
the paper fixes it: 10 rounds; in each, every parameter gets 40 uniform samples
around its value and keeps the best; stop early at zero penalty. Only the pairs
whose objects a parameter actually moves are re-evaluated.
"""

from __future__ import annotations

import time
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from physcensis.geometry.footprints import Array, overlap_areas, placed_polygons
from physcensis.program.model import Program, Relation
from physcensis.scene import Support
from physcensis.solve.layout import CompiledLayout, PhysicalRequest, Pose2D

ROUNDS = 10
SAMPLES_PER_PARAM = 40
OVERLAP_TOLERANCE_M2 = 1e-4  # accept at most 1 cm^2 of overlap in total
OUTSIDE_TOLERANCE_M = 0.005  # and 5 mm beyond the support's edges in total
REPORT_OVERLAP_M2 = 1e-6  # pairs below this are not worth naming
# Among equally good samples prefer the agent's own values: a tiny cost per sampling radius moved.
STAY_WEIGHT = 0.01
_SIDES = ("back", "front", "right", "left")  # -x, +x, -y, +y


@dataclass(frozen=True)
class Overlap:
    a: str
    b: str
    area_m2: float
    entries_a: tuple[int, ...]
    entries_b: tuple[int, ...]


@dataclass(frozen=True)
class Outside:
    object: str
    side: str  # front, back, left or right
    distance_m: float
    entries: tuple[int, ...]


@dataclass
class SpatialResult:
    ok: bool
    poses: dict[str, Pose2D]
    params: dict[int, dict[str, float]]  # entry index -> parameter -> optimised value
    overlaps: list[Overlap]
    outside: list[Outside]
    overlap_m2: float
    outside_m: float
    rounds: int
    evaluations: int
    stop_reason: str
    seconds: float
    copies: dict[str, str] = field(default_factory=dict)  # copy id -> original id
    pending: list[PhysicalRequest] = field(default_factory=list)
    yaw_rules: dict[str, list[Relation]] = field(default_factory=dict)

    def feedback(self) -> str:
        """The diagnosis in words an agent can act on."""
        lines: list[str] = []
        for o in self.overlaps:
            lines.append(
                f"{o.a} and {o.b} overlap by {o.area_m2 * 1e4:.1f} cm^2 ({o.a} is placed by "
                f"{_entries_text(o.entries_a)}; {o.b} by {_entries_text(o.entries_b)}): the support may be too "
                "crowded there; increase a distance, move one of them, or stack one with PLACE-ON"
            )
        for s in self.outside:
            lines.append(
                f"{s.object} sticks out {s.distance_m * 100:.1f} cm past the {s.side} edge of the support "
                f"(placed by {_entries_text(s.entries)}); move it inwards or choose smaller distances"
            )
        if not lines:
            lines.append(f"all {len(self.poses)} objects on the support are placed without overlap")
        return "\n".join(lines)


def _entries_text(entries: tuple[int, ...]) -> str:
    return ", ".join(f"#{i}" for i in entries) if entries else "no predicate"


class _Penalty:
    """Overlap and out-of-support terms over batches of layouts, with per-pair caching."""

    def __init__(self, layout: CompiledLayout) -> None:
        self.layout = layout
        self.hulls = layout.hulls  # (n, K, 2)
        self.limits = np.array([-layout.hx, layout.hx, -layout.hy, layout.hy])

    def boxes(self, x: Array, y: Array, yaw: Array) -> Array:
        """(n, B, 4) boxes of every footprint."""
        c, s = np.cos(yaw)[..., None], np.sin(yaw)[..., None]
        hx, hy = self.hulls[:, None, :, 0], self.hulls[:, None, :, 1]
        px = c * hx - s * hy + x[..., None]
        py = s * hx + c * hy + y[..., None]
        return np.stack([px.min(-1), px.max(-1), py.min(-1), py.max(-1)], axis=-1)

    def outside(self, boxes: Array) -> Array:
        """(n, B, 4) distance beyond the back, front, right and left edges."""
        lo = np.maximum(0.0, self.limits[[0, 2]] - boxes[..., [0, 2]])
        hi = np.maximum(0.0, boxes[..., [1, 3]] - self.limits[[1, 3]])
        return np.stack([lo[..., 0], hi[..., 0], lo[..., 1], hi[..., 1]], axis=-1)

    def pair_overlaps(self, pairs: Array, x: Array, y: Array, yaw: Array, boxes: Array) -> Array:
        """(P, B) footprint overlap areas of object pairs, exact where their boxes meet."""
        areas = np.zeros((len(pairs), x.shape[1]))
        if len(pairs) == 0:
            return areas
        a, b = pairs[:, 0], pairs[:, 1]
        ba, bb = boxes[a], boxes[b]
        meet = (
            (np.minimum(ba[..., 1], bb[..., 1]) - np.maximum(ba[..., 0], bb[..., 0]) > 1e-9)
            & (np.minimum(ba[..., 3], bb[..., 3]) - np.maximum(ba[..., 2], bb[..., 2]) > 1e-9)
        )
        p_idx, s_idx = np.nonzero(meet)
        if len(p_idx) == 0:
            return areas
        ia, ib = a[p_idx], b[p_idx]
        polys_a = placed_polygons(self.hulls[ia], x[ia, s_idx], y[ia, s_idx], yaw[ia, s_idx])
        polys_b = placed_polygons(self.hulls[ib], x[ib, s_idx], y[ib, s_idx], yaw[ib, s_idx])
        areas[p_idx, s_idx] = overlap_areas(polys_a, polys_b)
        return areas


def _score(overlap_m2: Array | float, outside_m: Array | float) -> Array | float:
    return overlap_m2 / OVERLAP_TOLERANCE_M2 + outside_m / OUTSIDE_TOLERANCE_M


def optimise_layout(
    program: Program, support: Support, footprints: Mapping[str, Array], seed: int = 0,
    rounds: int = ROUNDS, samples: int = SAMPLES_PER_PARAM,
) -> SpatialResult:
    """Solve the spatial part of a checked program; `footprints` maps declared ids to (K, 2) hulls."""
    start = time.perf_counter()
    layout = CompiledLayout(program, support, footprints, seed)
    rng = np.random.default_rng(seed)
    penalty = _Penalty(layout)
    n = len(layout.ids)
    all_pairs = np.array([(i, j) for i in range(n) for j in range(i + 1, n)], dtype=int).reshape(-1, 2)

    theta = layout.initial_theta()
    theta0 = theta.copy()
    radius = np.array([slot.radius for slot in layout.slots])
    x, y, yaw = layout.evaluate(theta[None, :])
    boxes = penalty.boxes(x, y, yaw)
    pair_area = penalty.pair_overlaps(all_pairs, x, y, yaw, boxes)[:, 0]
    outside = penalty.outside(boxes)[:, 0, :].sum(-1)
    evaluations, rounds_done, stop = 1, 0, "zero penalty"
    current = float(_score(pair_area.sum(), outside.sum()))
    objective = current
    # Latest entries first (they move the fewest other objects), yaw offsets last (a turned object
    # is the most visible change to the agent's plan).
    order = sorted(range(len(layout.slots)), key=lambda k: (layout.slots[k].name == "yaw_offset", -k))

    for round_index in range(rounds if current > 0 else 0):
        rounds_done = round_index + 1
        improved = False
        for j in order:
            slot = layout.slots[j]
            values = np.clip(rng.uniform(theta[j] - slot.radius, theta[j] + slot.radius, samples),
                             slot.low, slot.high)
            batch = np.repeat(theta[None, :], samples + 1, axis=0)
            batch[1:, j] = values  # sample 0 keeps the current value
            bx, by, byaw = layout.evaluate(batch)
            evaluations += samples + 1
            moved = np.nonzero((np.abs(bx - x[:, :1]) + np.abs(by - y[:, :1]) + np.abs(byaw - yaw[:, :1]))
                               .max(axis=1) > 1e-12)[0]
            if len(moved) == 0:
                continue
            touched = np.isin(all_pairs, moved).any(axis=1)
            pairs = all_pairs[touched]
            bboxes = penalty.boxes(bx, by, byaw)
            new_area = penalty.pair_overlaps(pairs, bx, by, byaw, bboxes)  # (P, B)
            new_outside = penalty.outside(bboxes[moved]).sum(-1)  # (m, B)
            totals_area = pair_area.sum() - pair_area[touched].sum() + new_area.sum(0)
            totals_out = outside.sum() - outside[moved].sum() + new_outside.sum(0)
            scores = _score(totals_area, totals_out)
            others = np.abs(theta - theta0) / radius
            stay = STAY_WEIGHT * (others.sum() - others[j] + np.abs(batch[:, j] - theta0[j]) / radius[j])
            best = int(np.argmin(scores + stay))
            if best == 0 or scores[best] + stay[best] >= objective:
                continue
            objective = float(scores[best] + stay[best])
            theta[j] = batch[best, j]
            x, y, yaw = bx[:, best : best + 1], by[:, best : best + 1], byaw[:, best : best + 1]
            pair_area[touched] = new_area[:, best]
            outside[moved] = new_outside[:, best]
            current = float(scores[best])
            improved = True
            if current <= 0.0:
                break
        if current <= 0.0:
            stop = "zero penalty"
            break
        if not improved:
            stop = "no parameter change lowered the penalty"
            break
    else:
        if current > 0:
            stop = f"stopped after {rounds} rounds"

    overlap_m2, outside_m = float(pair_area.sum()), float(outside.sum())
    ok = overlap_m2 <= OVERLAP_TOLERANCE_M2 and outside_m <= OUTSIDE_TOLERANCE_M
    ids = layout.ids
    entries = {oid: tuple(sorted(set(layout.entries_of.get(oid, [])))) for oid in ids}
    overlaps = [
        Overlap(ids[i], ids[j], float(area), entries[ids[i]], entries[ids[j]])
        for (i, j), area in zip(all_pairs, pair_area, strict=True)
        if area > REPORT_OVERLAP_M2
    ]
    overlaps.sort(key=lambda o: -o.area_m2)
    final_boxes = penalty.boxes(x, y, yaw)
    per_side = penalty.outside(final_boxes)[:, 0, :]
    beyond = [
        Outside(ids[i], _SIDES[k], float(per_side[i, k]), entries[ids[i]])
        for i in range(n) for k in range(4) if per_side[i, k] > 1e-4
    ]
    params: dict[int, dict[str, float]] = {}
    for slot, value in zip(layout.slots, theta, strict=True):
        params.setdefault(slot.entry, {})[slot.name] = float(value)
    poses = {oid: Pose2D(float(x[i, 0]), float(y[i, 0]), _wrap(float(yaw[i, 0]))) for i, oid in enumerate(ids)}
    return SpatialResult(
        ok=ok, poses=poses, params=params, overlaps=overlaps, outside=beyond,
        overlap_m2=overlap_m2, outside_m=outside_m, rounds=rounds_done, evaluations=evaluations,
        stop_reason=stop, seconds=time.perf_counter() - start, copies=dict(layout.copies),
        pending=list(layout.pending), yaw_rules=dict(layout.yaw_rules),
    )


def _wrap(angle: float) -> float:
    """Angle in (-pi, pi]."""
    wrapped = (angle + np.pi) % (2 * np.pi) - np.pi
    return float(np.pi if wrapped <= -np.pi + 1e-12 else wrapped)
