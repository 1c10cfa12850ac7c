"""Spatial solver: optimise a program's parameters so footprints neither overlap nor leave the support.

Penalty = total pairwise footprint overlap (in units of 1 cm^2) + total distance
of footprints beyond the support's edges (in units of 5 mm). Coordinate descent as
the paper fixes it: 10 rounds; in each, every parameter gets 40 uniform samples
around its value and keeps the best; stop early at zero penalty. Only the pairs
whose objects a parameter actually moves, and whose boxes can meet in some sample,
are re-evaluated; the overlapping pairs are kept as a sparse list, so memory grows
with the contacts, not with n(n-1)/2. The search stops at a fixed amount of work
(predicate evaluations), so a huge program ends in bounded time, deterministically.
"""

from __future__ import annotations

import time
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from physcensis.geometry.footprints import Array, overlap_areas, placed_polygons
from physcensis.program.model import Program, Relation
from physcensis.scene import Support
from physcensis.solver.layout import CompiledLayout, PhysicalRequest, Pose2D

ROUNDS = 10
SAMPLES_PER_PARAM = 40
OVERLAP_TOLERANCE_M2 = 1e-4  # accept at most 1 cm^2 of overlap in total
OUTSIDE_TOLERANCE_M = 0.005  # and 5 mm beyond the support's edges in total
REPORT_OVERLAP_M2 = 1e-6  # pairs below this are not worth naming
# Among equally good samples prefer the agent's own values: a tiny cost per sampling radius moved.
STAY_WEIGHT = 0.01
# Work the search may spend: predicate applications (one program entry over one batch of samples) plus exact
# footprint intersections; a program of a few dozen objects needs far less, 500 chained objects about one round's
# worth (a couple of minutes).
WORK_LIMIT = 2_000_000
PAIR_CHUNK = 1 << 20  # (pair, sample) boxes compared at once; bounds the temporary arrays to tens of MB
POLYGON_CHUNK = 20_000  # exact intersections computed at once
POLYGONS_PER_WORK = 8  # exact footprint intersections that cost about one predicate application
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
        self.intersections = 0  # exact polygon intersections computed so far (they count as work)

    def boxes(self, x: Array, y: Array, yaw: Array, idx: NDArray[np.intp] | None = None) -> Array:
        """(n, B, 4) boxes of every footprint (or of the objects `idx`, whose poses x, y, yaw are)."""
        hulls = self.hulls if idx is None else self.hulls[idx]
        c, s = np.cos(yaw)[..., None], np.sin(yaw)[..., None]
        hx, hy = hulls[:, None, :, 0], hulls[:, None, :, 1]
        px = c * hx - s * hy + x[..., None]
        py = s * hx + c * hy + y[..., None]
        return np.stack([px.min(-1), px.max(-1), py.min(-1), py.max(-1)], axis=-1)

    def outside(self, boxes: Array) -> Array:
        """(n, B, 4) distance beyond the back, front, right and left edges."""
        lo = np.maximum(0.0, self.limits[[0, 2]] - boxes[..., [0, 2]])
        hi = np.maximum(0.0, boxes[..., [1, 3]] - self.limits[[1, 3]])
        return np.stack([lo[..., 0], hi[..., 0], lo[..., 1], hi[..., 1]], axis=-1)

    def pair_overlaps(self, pairs: NDArray[np.intp], x: Array, y: Array, yaw: Array, boxes: Array) -> Array:
        """(P, B) footprint overlap areas of object pairs, exact where their boxes meet."""
        batch = x.shape[1]
        areas = np.zeros((len(pairs), batch))
        step = max(1, PAIR_CHUNK // max(1, batch))
        for first in range(0, len(pairs), step):
            chunk = pairs[first : first + step]
            a, b = chunk[:, 0], chunk[:, 1]
            ba, bb = boxes[a], boxes[b]
            meet = (np.minimum(ba[..., 1], bb[..., 1]) - np.maximum(ba[..., 0], bb[..., 0]) > 1e-9) & (
                np.minimum(ba[..., 3], bb[..., 3]) - np.maximum(ba[..., 2], bb[..., 2]) > 1e-9
            )
            p_idx, s_idx = np.nonzero(meet)
            self.intersections += len(p_idx)
            for k in range(0, len(p_idx), POLYGON_CHUNK):
                p, smp = p_idx[k : k + POLYGON_CHUNK], s_idx[k : k + POLYGON_CHUNK]
                ia, ib = a[p], b[p]
                polys_a = placed_polygons(self.hulls[ia], x[ia, smp], y[ia, smp], yaw[ia, smp])
                polys_b = placed_polygons(self.hulls[ib], x[ib, smp], y[ib, smp], yaw[ib, smp])
                areas[first + p, smp] = overlap_areas(polys_a, polys_b)
        return areas


def near_pairs(movers: NDArray[np.intp], envelopes: Array, moved: NDArray[np.bool_]) -> NDArray[np.intp]:
    """(P, 2) pairs (i < j) with at least one of `movers` whose envelopes (n, 4: min_x, max_x, min_y, max_y over
    all samples) overlap, so whose boxes may meet in some sample; each pair once. Compared in chunks of rows."""
    n = len(envelopes)
    found: list[NDArray[np.intp]] = []
    rows_per_chunk = max(1, PAIR_CHUNK // max(1, n))
    for first in range(0, len(movers), rows_per_chunk):
        rows = movers[first : first + rows_per_chunk]
        e, others = envelopes[rows][:, None, :], envelopes[None, :, :]
        meet = (np.minimum(e[..., 1], others[..., 1]) - np.maximum(e[..., 0], others[..., 0]) > 1e-9) & (
            np.minimum(e[..., 3], others[..., 3]) - np.maximum(e[..., 2], others[..., 2]) > 1e-9
        )
        r, j = np.nonzero(meet)
        i = rows[r]
        keep = (i != j) & (~moved[j] | (i < j))  # a pair of two movers is found from both sides: keep one
        i, j = i[keep], j[keep]
        found.append(np.stack([np.minimum(i, j), np.maximum(i, j)], axis=1))
    return np.concatenate(found) if found else np.zeros((0, 2), dtype=np.intp)


def envelopes(boxes: Array) -> Array:
    """(n, 4) box around each object's boxes (n, B, 4) over all samples."""
    return np.stack([boxes[..., 0].min(1), boxes[..., 1].max(1), boxes[..., 2].min(1), boxes[..., 3].max(1)], axis=1)


@dataclass
class _Contacts:
    """The pairs whose footprints overlap now, with their areas: a sparse stand-in for all n(n-1)/2 pairs."""

    pairs: NDArray[np.intp]  # (k, 2), i < j
    areas: Array  # (k,) > 0

    @classmethod
    def of(cls, pairs: NDArray[np.intp], areas: Array) -> _Contacts:
        positive = areas > 0
        return cls(pairs[positive], areas[positive])

    def total(self) -> float:
        return float(self.areas.sum())

    def touching(self, moved: NDArray[np.bool_]) -> NDArray[np.bool_]:
        if not len(self.pairs):
            return np.zeros(0, dtype=bool)
        return np.any(moved[self.pairs], axis=1)

    def replace(self, moved: NDArray[np.bool_], pairs: NDArray[np.intp], areas: Array) -> _Contacts:
        """Contacts after the `moved` objects took new poses, with these new areas of their near pairs."""
        keep = ~self.touching(moved)
        fresh = _Contacts.of(pairs, areas)
        return _Contacts(
            np.concatenate([self.pairs[keep], fresh.pairs]), np.concatenate([self.areas[keep], fresh.areas])
        )

    def sorted(self) -> _Contacts:
        order = np.lexsort((self.pairs[:, 1], self.pairs[:, 0])) if len(self.pairs) else np.zeros(0, dtype=np.intp)
        return _Contacts(self.pairs[order], self.areas[order])


def _score(overlap_m2: float, outside_m: float) -> float:
    return overlap_m2 / OVERLAP_TOLERANCE_M2 + outside_m / OUTSIDE_TOLERANCE_M


def _scores(overlap_m2: Array, outside_m: Array) -> Array:
    """`_score` of each sample."""
    return overlap_m2 / OVERLAP_TOLERANCE_M2 + outside_m / OUTSIDE_TOLERANCE_M


def optimise_layout(
    program: Program,
    support: Support,
    footprints: Mapping[str, Array],
    seed: int = 0,
    rounds: int = ROUNDS,
    samples: int = SAMPLES_PER_PARAM,
    work_limit: int = WORK_LIMIT,
    deadline: float | None = None,
) -> SpatialResult:
    """Solve the spatial part of a checked program; `footprints` maps declared ids to (K, 2) hulls. The search
    stops after `work_limit` units of work, one per predicate application or POLYGONS_PER_WORK exact footprint
    intersections, or at `deadline` (a time.perf_counter() value; None: none), and the result then says so and is
    judged as it stands."""
    start = time.perf_counter()
    layout = CompiledLayout(program, support, footprints, seed)
    search = _Search.begin(layout, np.random.default_rng(seed), samples, work_limit)
    search.deadline = deadline
    rounds_done, stop = search.descend(rounds)
    return _result(layout, search, rounds_done, stop, time.perf_counter() - start)


@dataclass
class _Search:
    """Coordinate descent over a compiled layout's parameters: the layout it stands at and what that costs."""

    layout: CompiledLayout
    penalty: _Penalty
    rng: np.random.Generator
    samples: int
    work_limit: int
    order: list[int]  # slots in the order they are visited each round
    theta: Array
    theta0: Array  # the agent's own values
    radius: Array
    x: Array  # (n, 1) poses at theta
    y: Array
    yaw: Array
    boxes: Array  # (n, 1, 4)
    contacts: _Contacts
    outside: Array  # (n,) distance beyond the support's edges
    deviation: Array  # how far each parameter is from the agent's value, in sampling radii
    stay_total: float
    objective: float  # score + the cost of moving away from the agent's values
    current: float  # score
    evaluations: int = 1  # layouts evaluated
    evaluations_work: int = 0  # predicate applications so far
    deadline: float | None = None  # time.perf_counter() at which the search stops where it stands

    @classmethod
    def begin(cls, layout: CompiledLayout, rng: np.random.Generator, samples: int, work_limit: int) -> _Search:
        """The search at the agent's own values."""
        penalty = _Penalty(layout)
        n = len(layout.ids)
        theta = layout.initial_theta()
        radius = np.array([slot.radius for slot in layout.slots])
        x, y, yaw = layout.evaluate(theta[None, :])
        boxes = penalty.boxes(x, y, yaw)
        pairs = near_pairs(np.arange(n, dtype=np.intp), boxes[:, 0, :], np.ones(n, dtype=bool))
        contacts = _Contacts.of(pairs, penalty.pair_overlaps(pairs, x, y, yaw, boxes)[:, 0])
        outside = penalty.outside(boxes)[:, 0, :].sum(-1)
        current = _score(contacts.total(), float(outside.sum()))
        deviation = np.abs(theta - theta) / radius  # how far each parameter is from the agent's value
        # Latest entries first (they move the fewest other objects), yaw offsets last (a turned object
        # is the most visible change to the agent's plan).
        order = sorted(range(len(layout.slots)), key=lambda k: (layout.slots[k].name == "yaw_offset", -k))
        return cls(
            layout,
            penalty,
            rng,
            samples,
            work_limit,
            order,
            theta,
            theta.copy(),
            radius,
            x,
            y,
            yaw,
            boxes,
            contacts,
            outside,
            deviation,
            float(deviation.sum()),
            current,
            current,
            evaluations_work=max(1, len(layout.ops)),
        )

    @property
    def cost(self) -> int:
        """Work of one evaluation: one predicate application per operation."""
        return max(1, len(self.layout.ops))

    def work(self) -> int:
        return self.evaluations_work + self.penalty.intersections // POLYGONS_PER_WORK

    def over_budget(self) -> bool:
        """Whether one more evaluation would pass the work limit, or the deadline has passed."""
        return self.work() + self.cost > self.work_limit or self.out_of_time()

    def out_of_time(self) -> bool:
        return self.deadline is not None and time.perf_counter() >= self.deadline

    def descend(self, rounds: int) -> tuple[int, str]:
        """Up to `rounds` rounds; the rounds done and why the search stopped."""
        if self.current <= 0:
            return 0, "zero penalty"
        for done in range(1, rounds + 1):
            improved = self.round()
            if self.current <= 0.0:
                return done, "zero penalty"
            if self.out_of_time():
                return done, f"stopped at the run's time budget in round {done}"
            if self.over_budget():
                return done, (
                    f"stopped at the work limit ({self.work_limit} predicate evaluations) in round {done}: "
                    "the program is too large to optimise fully"
                )
            if not improved:
                return done, "no parameter change lowered the penalty"
        return rounds, f"stopped after {rounds} rounds"

    def round(self) -> bool:
        """Sample every parameter once, in order, keeping improvements; whether anything improved."""
        improved = False
        for j in self.order:
            if self.over_budget():
                break
            if self.sample(j):
                improved = True
                if self.current <= 0.0:
                    break
        return improved

    def sample(self, j: int) -> bool:
        """Try `samples` values of parameter j around its own; keep the best if it lowers the objective."""
        slot = self.layout.slots[j]
        theta, x, y, yaw = self.theta, self.x, self.y, self.yaw
        values = np.clip(
            self.rng.uniform(theta[j] - slot.radius, theta[j] + slot.radius, self.samples), slot.low, slot.high
        )
        batch = np.repeat(theta[None, :], self.samples + 1, axis=0)
        batch[1:, j] = values  # sample 0 keeps the current value
        bx, by, byaw = self.layout.evaluate(batch)
        self.evaluations += self.samples + 1
        self.evaluations_work += self.cost
        moved = np.nonzero(
            (np.abs(bx - x[:, :1]) + np.abs(by - y[:, :1]) + np.abs(byaw - yaw[:, :1])).max(axis=1) > 1e-12
        )[0]
        if len(moved) == 0:
            return False
        is_moved = np.zeros(len(self.layout.ids), dtype=bool)
        is_moved[moved] = True
        bboxes = np.repeat(self.boxes, self.samples + 1, axis=1)  # (n, B, 4): those that did not move keep theirs
        bboxes[moved] = self.penalty.boxes(bx[moved], by[moved], byaw[moved], moved)
        near = near_pairs(moved, envelopes(bboxes), is_moved)
        new_area = self.penalty.pair_overlaps(near, bx, by, byaw, bboxes)  # (P, B)
        new_outside = self.penalty.outside(bboxes[moved]).sum(-1)  # (m, B)
        touching = float(self.contacts.areas[self.contacts.touching(is_moved)].sum())
        totals_area = self.contacts.total() - touching + new_area.sum(0)
        totals_out = self.outside.sum() - self.outside[moved].sum() + new_outside.sum(0)
        scores = _scores(totals_area, totals_out)
        radius, theta0 = self.radius, self.theta0
        stay = STAY_WEIGHT * (self.stay_total - self.deviation[j] + np.abs(batch[:, j] - theta0[j]) / radius[j])
        best = int(np.argmin(scores + stay))
        if best == 0 or scores[best] + stay[best] >= self.objective:
            return False
        self.objective = float(scores[best] + stay[best])
        theta[j] = batch[best, j]
        self.stay_total += float(np.abs(theta[j] - theta0[j]) / radius[j]) - self.deviation[j]
        self.deviation[j] = np.abs(theta[j] - theta0[j]) / radius[j]
        self.x, self.y, self.yaw = bx[:, best : best + 1], by[:, best : best + 1], byaw[:, best : best + 1]
        self.boxes = bboxes[:, best : best + 1]
        self.contacts = self.contacts.replace(is_moved, near, new_area[:, best])
        self.outside[moved] = new_outside[:, best]
        self.current = float(scores[best])
        return True


def _result(layout: CompiledLayout, search: _Search, rounds_done: int, stop: str, seconds: float) -> SpatialResult:
    """The search's final layout, judged: what overlaps, what sticks out, and the parameters it chose."""
    contacts = search.contacts.sorted()
    overlap_m2, outside_m = contacts.total(), float(search.outside.sum())
    ok = overlap_m2 <= OVERLAP_TOLERANCE_M2 and outside_m <= OUTSIDE_TOLERANCE_M
    ids = layout.ids
    entries = {oid: tuple(sorted(set(layout.entries_of.get(oid, [])))) for oid in ids}
    overlaps = [
        Overlap(ids[i], ids[j], float(area), entries[ids[i]], entries[ids[j]])
        for (i, j), area in zip(contacts.pairs.tolist(), contacts.areas.tolist(), strict=True)
        if area > REPORT_OVERLAP_M2
    ]
    overlaps.sort(key=lambda o: -o.area_m2)
    x, y, yaw = search.x, search.y, search.yaw
    per_side = search.penalty.outside(search.penalty.boxes(x, y, yaw))[:, 0, :]
    beyond = [
        Outside(ids[i], _SIDES[k], float(per_side[i, k]), entries[ids[i]])
        for i, k in zip(*np.nonzero(per_side > 1e-4), strict=True)
    ]
    params: dict[int, dict[str, float]] = {}
    for slot, value in zip(layout.slots, search.theta, strict=True):
        params.setdefault(slot.entry, {})[slot.name] = float(value)
    poses = {oid: Pose2D(float(x[i, 0]), float(y[i, 0]), _wrap(float(yaw[i, 0]))) for i, oid in enumerate(ids)}
    return SpatialResult(
        ok=ok,
        poses=poses,
        params=params,
        overlaps=overlaps,
        outside=beyond,
        overlap_m2=overlap_m2,
        outside_m=outside_m,
        rounds=rounds_done,
        evaluations=search.evaluations,
        stop_reason=stop,
        seconds=seconds,
        copies=dict(layout.copies),
        pending=list(layout.pending),
        yaw_rules=dict(layout.yaw_rules),
    )


def _wrap(angle: float) -> float:
    """Angle in (-pi, pi]."""
    wrapped = (angle + np.pi) % (2 * np.pi) - np.pi
    return float(np.pi if wrapped <= -np.pi + 1e-12 else wrapped)
