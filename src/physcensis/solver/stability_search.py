"""Search for a fragile or a robust placement: move the object until its p_fail reaches a target.

Each round moves the best state found so far and measures the new state. The first
kind of move is the paper's: among the samples of a state that stood, re-centre on
the one whose p_fail is closest to the target (highest for "unstable", lowest for
"stable"). A move slides the object, turns it about the vertical and shifts its
centre of mass (within the asset's feasible range); it is kept only if the new state
stands in a plain simulation. Three additions make the search converge on a few
hundred samples:

* Every state is first measured on the same perturbation draws (common random
  numbers), so comparing two states does not compare two sampling noises; a state
  that looks reached is measured again on fresh draws, and counts as reached only
  when enough samples back it.
* Scouts: with every state's first samples, extra copies that are only slid and
  given another centre of mass, three times farther, map where the object would
  still stand. Candidates are ranked by a surrogate of their p_fail: the failure
  rate of the scouts whose centre of mass started near the candidate's.
* Edge moves: near the limit of stability every sample that stood lies on the safe
  side, so re-centring stops helping a fragile target. The search then slides the
  object toward where the scouts fell nearby (away from the middle of its support
  when none fell: it lies deep inside) and bisects, with plain simulations,
  for the last position that still stands comfortably: the most fragile standing
  state on that line (at a corner of the support, it heads into the corner).
* Corner walks, tried first for a fragile target: the most fragile state that still
  stands lies in a corner of the region where it stands (a perturbation of any
  direction but one quadrant then topples it; on a straight edge only half do). From
  the nearest edge (found as above) the walk slides along it either way, to where
  the next edge stops it, and back onto the first; each lap learns the edge's
  direction from the points found on it and keeps half as far inside the edges as
  the last, each slide a bisection in plain simulation, so the walk ends a fraction
  of a millimetre inside the corner.

* Between, for a numeric target: once states were measured on both sides of the
  band, the next is the one on the line between the closest two where p_fail,
  interpolated linearly, meets the target.

Every state is kept as it settles (so the p_fail measured is the p_fail the final
verification delivers), and a search that ends without reaching its target chooses
among its closest few states on fresh draws alone.

A value the program also asked for (a PLACE-ON's overlap) is kept: a move that would
take it outside its tolerance is treated as a move that does not stand (so a slide
stops at the tolerance's edge), a state outside it ranks after every state within it,
and the target counts as reached only within it. When the placement started outside
the tolerance, moves toward it are taken.
"""

from __future__ import annotations

import logging
import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
from scipy.spatial.transform import Rotation

from physcensis.physics.engine import DEFAULT_TOLERANCE, at_rest
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.scene import PlacedObject, Scene
from physcensis.solver.perturb import (
    COM,
    POSITION,
    ROTATION,
    PerturbationScales,
    com_projection,
    feasible_com,
    rate_near,
    rigid_motion,
)
from physcensis.solver.stability import (
    StabilityEstimate,
    StabilitySettings,
    estimate_from_samples,
    estimate_stability,
    wilson_interval,
)
from physcensis.solver.stability_sim import StandCheck, StandRule, asset_of, check_stands

log = logging.getLogger(__name__)

UNSTABLE_P = 0.9
STABLE_P = 0.05
SURROGATE_BANDWIDTH = 1.0  # of the position sigma: the COM neighbourhood whose failure rate predicts p_fail
EDGE_REACH = 2.0  # of the scout spread: how far away failures still pull an edge move
EDGE_INSET = 0.5  # of the position sigma: a slide along an edge keeps this far inside it
SAME_STATE_M = 2e-4  # a move that ends this close to a visited state (pose and COM) is no move
SCOUT_STREAM = 10**6  # the random stream of the scouts (states share it, like their first samples)
FLAT = [2, 3, 4]  # Δz and the tilt of Δr: a move keeps the object resting, so it only slides and turns about z
# What a state tries next: CORNER (a fragile target's walks into both corners of the nearest edge), RECENTRE, then
# EDGE + 0, 1, 2 (three slide directions).
CORNER, RECENTRE, EDGE, EXHAUSTED = 0, 1, 2, 5
CORNER_LAPS = 4  # slides along an edge and back onto it, each lap keeping half as far inside the edges
CORNER_AIM = 0.5  # an edge offers up to about this p_fail; only a target beyond it needs a corner
SLIDE_TOLERANCE_M = 1e-4  # a slide to the limit of standing ends this close to it
BETWEEN_MIN = 0.1  # a state between two others lies at least this fraction of the way from either


@dataclass(frozen=True)
class SearchSettings:
    """Bounds and targets of the stability search."""

    iterations: int = 16  # rounds; each measures a new state, or takes a second look at a promising one
    # When no state reached the target, this many of the closest are measured on fresh draws before one is chosen:
    # the closest on the shared first draws alone was often a lucky look (0.90 there, 0.82 on 2,048 fresh draws).
    final_candidates: int = 3
    confirm_rounds: int = 3  # ... and the one chosen is measured again at least this many times while it is in the band
    candidates: int = 4  # re-centring candidates tried (in plain simulation) per move
    unstable_p: float = UNSTABLE_P
    stable_p: float = STABLE_P
    band: float = 0.05  # a numeric target is reached within this distance
    # A state counts as reached only on this many effective fresh samples (about 5 draws per effective one): the
    # best of a few states on fewer draws was often a few points lower on draws nobody had seen.
    min_effective_samples: float = 80.0
    max_confirm_effective: float = 120.0  # fresh draws stop being added to a state once they weigh this much
    max_shift_m: float = 0.15  # how far the object may move from where the search found it (to a corner of a book)
    scouts: int = 64  # extra copies per state that only map where it would stand
    scout_scale: float = 3.0  # their spread, in sample spreads
    stand: StandRule = StandRule()
    edge_stand: StandRule = StandRule(max_move_m=0.001)  # an edge move keeps a comfortable margin


@dataclass
class StabilityResult:
    """What a stability search reached, and why it stopped."""

    object_id: str
    target: str | float
    band: tuple[float, float]
    reached: bool
    p_fail: float
    estimate: StabilityEstimate  # every sample drawn around the final state
    stands: StandCheck
    rounds: int
    stop_reason: str
    history: list[float]  # p_fail of each state visited, as first measured
    moved_m: float
    com: tuple[float, float, float]
    wall_s: float

    def to_dict(self) -> dict[str, Any]:
        return {
            "object": self.object_id,
            "target": self.target,
            "band": [round(b, 3) for b in self.band],
            "reached": self.reached,
            "p_fail": round(self.p_fail, 4),
            "p_fail_95": [round(v, 4) for v in wilson_interval(self.p_fail, self.estimate.effective_samples)],
            "samples": self.estimate.samples,
            "effective_samples": round(self.estimate.effective_samples, 1),
            "stands": self.stands.ok,
            "stand_moved_mm": round(self.stands.moved_m * 1000, 3),
            "rounds": self.rounds,
            "stop_reason": self.stop_reason,
            "history": [round(p, 4) for p in self.history],
            "moved_m": round(self.moved_m, 4),
            "com": [round(c, 5) for c in self.com],
            "wall_s": round(self.wall_s, 3),
        }


def target_band(target: str | float, search: SearchSettings = SearchSettings()) -> tuple[float, float, float]:
    """(aim, low, high): the p_fail the search heads for and the band that counts as reached."""
    if isinstance(target, str):
        target = target.strip().lower()
    if target == "unstable":
        return 1.0, search.unstable_p, 1.0
    if target == "stable":
        return 0.0, 0.0, search.stable_p
    try:
        value = float(target)
    except ValueError:
        raise ValueError(f"stability must be 'stable', 'unstable' or a number in [0, 1], not {target!r}") from None
    if not 0.0 <= value <= 1.0:
        raise ValueError(f"a stability target must be a probability in [0, 1], not {value}")
    return value, max(0.0, value - search.band), min(1.0, value + search.band)


@dataclass
class _State:
    """A state of the scene the search visited."""

    objects: list[PlacedObject]
    stands: StandCheck
    estimate: StabilityEstimate | None = None  # every sample drawn around it
    fresh: StabilityEstimate | None = None  # only the draws made after it was chosen: an unbiased p_fail
    stage: int = CORNER

    @property
    def unbiased(self) -> StabilityEstimate | None:
        """The fresh draws once there are any: the first ones are shared by every state, and the search picked
        this state partly because of how they fell."""
        return self.fresh or self.estimate


@dataclass(frozen=True)
class KeptValue:
    """A value of the object's pose the search must keep near what was asked (a PLACE-ON's overlap): `measure`
    reads it from a state's objects."""

    name: str
    requested: float
    tolerance: float
    measure: Callable[[list[PlacedObject]], float]

    def excess(self, value: float) -> float:
        """How far `value` lies outside the tolerance (0 within it)."""
        return max(0.0, abs(value - self.requested) - self.tolerance)

    def allows(self, value: float, start: float) -> bool:
        """Within the tolerance, or outside it only on the start's side and no farther than the start."""
        off, start_off = value - self.requested, start - self.requested
        return self.excess(value) == 0.0 or (off * start_off > 0.0 and abs(off) <= abs(start_off))

    def describe(self) -> str:
        return f"the {self.name} asked ({self.requested:g} ± {self.tolerance:g})"


@dataclass
class _Samples:
    """Every labelled copy so far: its perturbation (relative to its state), label, state, whether it was a
    scout, and where its centre of mass started over the ground plane."""

    x: np.ndarray = field(default_factory=lambda: np.zeros((0, 11)))
    fell: np.ndarray = field(default_factory=lambda: np.zeros(0))
    state: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    scout: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=bool))
    com_xy: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))

    def add(self, estimate: StabilityEstimate, state: int, obj: PlacedObject, *, scout: bool = False) -> None:
        x = estimate.perturbations
        self.x = np.concatenate([self.x, x])
        self.fell = np.concatenate([self.fell, estimate.labels])
        self.state = np.concatenate([self.state, np.full(len(x), state)])
        self.scout = np.concatenate([self.scout, np.full(len(x), scout)])
        self.com_xy = np.concatenate([self.com_xy, _com_xy(obj, x)])


def _scout_scales(scales: PerturbationScales, factor: float) -> PerturbationScales:
    """Scouts are only slid and given another centre of mass, farther than samples: they map where a state
    would stand, not how it reacts to being disturbed."""
    return PerturbationScales(
        position_m=factor * scales.position_m,
        height_m=0.0,
        rotation_rad=0.0,
        com_fraction=factor * scales.com_fraction,
        friction=0.0,
        mass_fraction=0.0,
    )


def _com_xy(obj: PlacedObject, x: np.ndarray) -> np.ndarray:
    return com_projection(np.asarray(obj.position), np.asarray(obj.quaternion), np.asarray(obj.com), x)


def _flat(x: np.ndarray) -> np.ndarray:
    """A perturbation made into a move that keeps the object resting: no lift and no tilt."""
    moved = np.array(x, dtype=float)
    moved[FLAT] = 0.0
    return moved


class _Search:
    """One bounded search; `run` returns the result and leaves the scene at the best standing state."""

    def __init__(
        self,
        scene: Scene,
        object_id: str,
        target: str | float,
        engine: MujocoEngine,
        seed: int,
        settings: StabilitySettings,
        search: SearchSettings,
        kept: KeptValue | None = None,
    ) -> None:
        self.scene, self.object_id, self.target = scene, object_id, target
        self.engine, self.seed, self.settings, self.search = engine, seed, settings, search
        self.kept = kept
        self.kept_start = kept.measure(list(scene.objects)) if kept else 0.0
        self.refused = 0  # moves not taken because they would break the kept value
        self.aim, self.low, self.high = target_band(target, search)
        self.start = scene.object(object_id)
        self.asset = asset_of(engine, self.start)
        self.scout_settings = replace(settings, scales=_scout_scales(settings.scales, search.scout_scale))
        self.states: list[_State] = []
        self.samples = _Samples()
        self.draws = 0
        self.history: list[float] = []

    # -- measuring -----------------------------------------------------------------------------------------
    def measure(self, index: int) -> None:
        """Simulate samples around a state: the first set on the draws every state shares (with its scouts),
        later ones afresh."""
        state = self.states[index]
        self.scene.objects = state.objects
        first = state.estimate is None
        estimate = estimate_stability(
            self.scene,
            self.object_id,
            self.settings.samples,
            self.seed,
            engine=self.engine,
            settings=self.settings,
            round_=0 if first else self.draws,
        )
        self.draws += 1
        obj = self.scene.object(self.object_id)
        self.samples.add(estimate, index, obj)
        state.estimate = estimate if state.estimate is None else pool(state.estimate, estimate)
        if not first:
            state.fresh = estimate if state.fresh is None else pool(state.fresh, estimate)
        if first and self.search.scouts:
            scouts = estimate_stability(
                self.scene,
                self.object_id,
                self.search.scouts,
                self.seed,
                engine=self.engine,
                settings=self.scout_settings,
                round_=SCOUT_STREAM,
            )
            self.samples.add(scouts, index, obj, scout=True)

    def gap(self, state: _State) -> float:
        """How far the state's p_fail (the unbiased one once measured afresh) lies outside the band, infinite when
        it does not stand. Once fresh draws have had their fill, a one-sided target counts their uncertainty."""
        estimate = state.unbiased
        if not state.stands.ok or estimate is None:
            return math.inf
        outside = self.kept_excess(state)
        if outside > 0.0:  # after every state that keeps the value asked, however far from the band
            return 2.0 + outside
        full = state.fresh is not None and estimate.effective_samples >= self.search.max_confirm_effective
        return self.band_gap(estimate, confident=full)

    def kept_excess(self, state: _State) -> float:
        return self.kept.excess(self.kept.measure(state.objects)) if self.kept else 0.0

    def band_gap(self, estimate: StabilityEstimate, *, confident: bool) -> float:
        """Distance of p_fail outside the band; with `confident`, "unstable" and "stable" need p_fail one standard
        error inside it (a numeric target's band is its own tolerance)."""
        p = estimate.p_fail
        margin = standard_error(estimate) if confident else 0.0
        low = self.low + (margin if self.high >= 1.0 and self.low > 0.0 else 0.0)
        high = self.high - (margin if self.low <= 0.0 and self.high < 1.0 else 0.0)
        return max(low - p, p - high, 0.0)

    def best(self, *, open_only: bool = False) -> int:
        """The standing state closest to the band (the start when none stands); with `open_only`, among the
        states that still have a move to try (-1 when none has)."""
        gaps = [math.inf if open_only and s.stage == EXHAUSTED else self.gap(s) for s in self.states]
        if math.isfinite(min(gaps)):
            return int(np.argmin(gaps))
        return -1 if open_only and self.states[0].stage == EXHAUSTED else 0

    def reached(self, index: int) -> bool:
        """In the band on fresh draws alone, with enough of them (and, for "unstable" or "stable", confidently)."""
        s = self.states[index]
        return (
            s.stands.ok
            and self.kept_excess(s) == 0.0
            and s.fresh is not None
            and s.fresh.effective_samples >= self.search.min_effective_samples
            and self.band_gap(s.fresh, confident=True) == 0.0
        )

    # -- moving --------------------------------------------------------------------------------------------
    def obj(self, index: int) -> PlacedObject:
        return next(o for o in self.states[index].objects if o.id == self.object_id)

    def moved(self, index: int, x: np.ndarray) -> list[PlacedObject]:
        """State `index` moved by a flat perturbation x: slid and turned about z (with whatever rests on the
        object), and its centre of mass shifted within the asset's feasible range."""
        state = self.states[index]
        obj = self.obj(index)
        assert state.estimate is not None
        carried = set(state.estimate.group or [self.object_id])
        updated = []
        for o in state.objects:
            if o.id not in carried:
                updated.append(o)
                continue
            position, quat = rigid_motion(
                np.asarray(obj.position),
                x[None, POSITION],
                x[None, ROTATION],
                np.asarray([o.position]),
                np.asarray([o.quaternion]),
            )
            change: dict[str, Any] = {
                "position": tuple(float(v) for v in position[0, 0]),
                "quaternion": tuple(float(v) for v in quat[0, 0]),
            }
            if o.id == self.object_id:
                change["com"] = tuple(float(c) for c in feasible_com(self.asset, np.asarray(o.com) + x[COM]))
            updated.append(o.model_copy(update=change))
        return updated

    def within_reach(self, objects: list[PlacedObject]) -> bool:
        obj = next(o for o in objects if o.id == self.object_id)
        return bool(np.linalg.norm(np.subtract(obj.position[:2], self.start.position[:2])) <= self.search.max_shift_m)

    def stands(self, objects: list[PlacedObject], rule: StandRule) -> StandCheck:
        """Whether a moved state stands; one that would break the kept value counts as one that does not (judged
        before it is simulated, on the pose the move gives it)."""
        if self.kept is not None and not self.kept.allows(self.kept.measure(objects), self.kept_start):
            self.refused += 1
            return StandCheck(ok=False, moved_m=0.0, duration_s=0.0)
        return check_stands(self.scene.model_copy(update={"objects": objects}), [self.object_id], self.engine, rule)

    def recentre(self, index: int) -> bool:
        """The paper's move: toward the standing copy of this state (sample or scout) whose predicted p_fail is
        closest to the aim, trying the best few in plain simulation. True when a new state was added."""
        s = self.samples
        pick = np.flatnonzero((s.state == index) & (s.fell == 0))
        moves = np.array([_flat(x) for x in s.x[pick]]).reshape(-1, 11)
        predicted = self.surrogate(_com_xy(self.obj(index), moves))
        tried = 0
        for k in np.argsort(np.abs(predicted - self.aim), kind="stable"):
            objects = self.moved(index, moves[k])
            if not self.within_reach(objects):
                continue
            tried += 1
            stands = self.stands(objects, self.search.stand)
            if stands.ok and self.add_state(objects, stands):
                return True
            if tried >= self.search.candidates:
                break
        return False

    def surrogate(self, com_xy: np.ndarray) -> np.ndarray:
        """Predicted p_fail of states whose centre of mass lies at each point: the scouts' failure rate there."""
        s = self.samples
        mapped = s.scout if s.scout.any() else np.ones(len(s.fell), dtype=bool)
        bandwidth = SURROGATE_BANDWIDTH * self.settings.scales.position_m
        return rate_near(s.com_xy[mapped], com_xy, s.fell[mapped], bandwidth)

    def edge_direction(self, index: int) -> np.ndarray | None:
        """The unit direction over the ground from where the scouts near this state stood toward where they fell:
        the outward normal of the nearest edge of stability (None without scouts on both sides)."""
        s = self.samples
        offsets = s.com_xy[s.scout] - _com_xy(self.obj(index), np.zeros((1, 11)))[0]
        fell = s.fell[s.scout] == 1
        if fell.all() or not fell.any():
            return None
        reach = EDGE_REACH * self.search.scout_scale * self.settings.scales.position_m
        w = np.exp(-0.5 * np.sum(offsets**2, axis=1) / reach**2)[:, None]
        pull = (w * offsets)[fell].sum(axis=0) / w[fell].sum() - (w * offsets)[~fell].sum(axis=0) / w[~fell].sum()
        norm = float(np.linalg.norm(pull))
        return pull / norm if norm > 0.0 else None

    def edge(self, index: int, turn: int) -> bool:
        """Slide toward where nearby scouts fell (turn 0), or along that edge either way (turns 1 and 2, kept a
        little inside it), as far as the object still stands comfortably. Along an edge the slide stops where the
        edge turns, in a corner of the support. True when a state was added."""
        normal = self.edge_direction(index)
        if normal is None and turn == 0 and not self.samples.fell[self.samples.scout].any():
            normal = self.away_from_support(index)  # no scout fell: deep inside a wide support, head for its side
        if normal is None:
            return False
        tangent = np.array([-normal[1], normal[0]]) * (1 if turn == 1 else -1)
        base = np.zeros(2) if turn == 0 else -EDGE_INSET * self.settings.scales.position_m * normal
        found = self.slide(index, base, normal if turn == 0 else tangent)
        return found is not None and self.add_state(*found[1])

    def slide(
        self, index: int, start: np.ndarray, direction: np.ndarray
    ) -> tuple[np.ndarray, tuple[list[PlacedObject], StandCheck]] | None:
        """The farthest offset over the ground from state `index`, on the ray from `start` along the unit
        `direction`, at which the object still stands comfortably (within the search's reach): steps that double
        until one falls, then bisection in plain simulation. None when nothing on the ray stands."""

        def stands_at(distance: float) -> tuple[list[PlacedObject], StandCheck] | None:
            x = np.zeros(11)
            x[:2] = start + distance * direction
            objects = self.moved(index, x)
            check = self.stands(objects, self.search.edge_stand) if self.within_reach(objects) else None
            return (objects, check) if check is not None and check.ok else None

        lo, hi, found = 0.0, self.search.max_shift_m, None
        step = EDGE_INSET * self.settings.scales.position_m
        while step < hi:
            ahead = stands_at(step)
            if ahead is None:
                hi = step
                break
            lo, found, step = step, ahead, 2.0 * step
        while hi - lo > SLIDE_TOLERANCE_M:
            mid = (lo + hi) / 2
            ahead = stands_at(mid)
            lo, hi, found = (mid, hi, ahead) if ahead is not None else (lo, mid, found)
        found = found or stands_at(0.0)  # nothing ahead stood: the start itself may
        return None if found is None else (start + lo * direction, found)

    def corner(self, index: int) -> bool:
        """Walk into both corners of the nearest edge of standing (`walk_to_corner`); True when a state was added."""
        normal = self.edge_direction(index)
        if normal is None:
            normal = self.away_from_support(index)
        added = [self.walk_to_corner(index, normal, side) for side in (1.0, -1.0)]
        return any(added)

    def away_from_support(self, index: int) -> np.ndarray:
        """The unit direction over the ground from the centre of what the object rests on to its centre of mass: the
        way to an edge when no scout near the state fell (it lies deep inside a wide support)."""
        obj = self.obj(index)
        target = obj.placement.target if obj.placement else None
        below = next((o for o in self.states[index].objects if o.id == target), None)
        centre = np.zeros(2) if below is None else np.asarray(below.position[:2])
        away = _com_xy(obj, np.zeros((1, 11)))[0] - centre
        norm = float(np.linalg.norm(away))
        return away / norm if norm > 1e-6 else np.array([1.0, 0.0])

    def walk_to_corner(self, index: int, normal: np.ndarray, side: float) -> bool:
        """Onto the edge of standing whose outward normal is about `normal`, then laps: along the edge (toward
        `side`, a little inside it) to where the next edge stops the slide, a little back, and onto the first
        edge again. Each lap learns the edge's direction from the first and the last point found on it, and
        halves how far inside the edges the next lap keeps, so the walk ends a fraction of a millimetre inside
        the corner of the region where the object stands, where a perturbation of almost any direction topples
        it. True when a state was added."""
        inset = EDGE_INSET * self.settings.scales.position_m
        # A state placed at the very edge may stand, but not comfortably: then the walk starts from farther inside.
        on_edge = self.slide(index, np.zeros(2), normal) or self.slide(index, -4.0 * inset * normal, normal)
        if on_edge is None:
            return False
        first, found = on_edge
        point, tangent = first, side * np.array([-normal[1], normal[0]])
        min_chord = 4.0 * inset  # shorter, the bisections' tolerance would turn the edge too much
        for _ in range(CORNER_LAPS):
            along = self.slide(index, point - inset * normal, tangent)
            if along is not None:
                point, found = along
            back = self.slide(index, point - inset * tangent, normal)
            if back is not None:
                point, found = back
                tangent, normal = edge_frame(point - first, tangent, normal, min_chord=min_chord)
            inset /= 2.0
        closer = self.slide(index, point - inset * normal, tangent)  # the last lap's first half, closer still
        # Re-centring on its samples would only wander out of the corner after their noise: edge moves may refine it.
        return self.add_state(*(closer or (point, found))[1], stage=EDGE)

    def between(self) -> bool:
        """A numeric target between two standing states, the closest measured below the band and the closest above
        it: a state on the line between them, where p_fail interpolated linearly meets the target (p_fail grows
        steadily on the way from the middle of a support to its edge). True when a state was added."""
        if not 0.0 < self.aim < 1.0:
            return False
        measured = [(k, s.unbiased.p_fail) for k, s in enumerate(self.states) if s.stands.ok and s.unbiased]
        below = [(p, k) for k, p in measured if p < self.low]
        above = [(p, k) for k, p in measured if p > self.high]
        if not below or not above:
            return False
        (p_low, low), (p_high, high) = max(below), min(above)
        t = float(np.clip((self.aim - p_low) / (p_high - p_low), BETWEEN_MIN, 1.0 - BETWEEN_MIN))
        a, b = self.obj(low), self.obj(high)
        x = np.zeros(11)  # a flat move: a slide and a turn about the vertical, and the centre of mass shifted
        x[POSITION] = t * np.array([b.position[0] - a.position[0], b.position[1] - a.position[1], 0.0])
        x[ROTATION] = t * np.array([0.0, 0.0, turn_about_vertical(a.quaternion, b.quaternion)])
        x[COM] = t * np.subtract(b.com, a.com)
        objects = self.moved(low, x)
        if not self.within_reach(objects):
            return False
        stands = self.stands(objects, self.search.stand)
        return stands.ok and self.add_state(objects, stands, stage=RECENTRE)

    def add_state(self, objects: list[PlacedObject], stands: StandCheck, stage: int = CORNER) -> bool:
        """Keep a new state, to try moves from `stage` on, unless the search has already been there (False). The
        state is kept as it settles, as the final verification will settle it: near the edge of standing, the
        hundredths of a millimetre it sinks into its contacts change p_fail by about 0.01."""
        objects = self.settled(objects)
        new = next(o for o in objects if o.id == self.object_id)
        for state in self.states:
            old = next(o for o in state.objects if o.id == self.object_id)
            if (
                np.linalg.norm(np.subtract(new.position, old.position)) < SAME_STATE_M
                and np.linalg.norm(np.subtract(new.com, old.com)) < SAME_STATE_M
                and abs(np.dot(new.quaternion, old.quaternion)) > 1.0 - 1e-6
            ):
                return False
        self.states.append(_State(objects, stands, stage=stage))
        return True

    def settled(self, objects: list[PlacedObject]) -> list[PlacedObject]:
        """The objects at the poses they settle in under the engine's contact settings (as they were if anything
        moves too far: the stand check has the last word on whether the state stands)."""
        result = self.engine.settle(self.scene.model_copy(update={"objects": objects}), tolerance=DEFAULT_TOLERANCE)
        return objects if result.failed or result.unstable else at_rest(objects, result.objects)

    def move(self, index: int) -> bool:
        """Try the state's next kind of move; advance its stage when there is none left of that kind."""
        state = self.states[index]
        while state.stage != EXHAUSTED:
            if self.try_stage(index, state.stage):
                return True
            state.stage += 1
        return False

    def try_stage(self, index: int, stage: int) -> bool:
        """One kind of move from a state; corner and edge moves only serve a target more fragile than the state."""
        estimate = self.states[index].estimate
        fragile = estimate is not None and self.aim > estimate.p_fail
        if stage == CORNER:
            return fragile and self.aim > CORNER_AIM and self.corner(index)
        if stage == RECENTRE:
            return self.recentre(index)
        return fragile and self.edge(index, stage - EDGE)

    # -- the loop ------------------------------------------------------------------------------------------
    def run(self) -> StabilityResult:
        begin = time.perf_counter()
        self.states.append(
            _State(list(self.scene.objects), check_stands(self.scene, [self.object_id], self.engine, self.search.stand))
        )
        self.measure(0)
        self.history.append(self._p(0))
        reason = f"used its {self.search.iterations} rounds"
        rounds = 0  # used; a search that stops early leaves the rest to confirm_closest
        for _ in range(self.search.iterations):
            rounds += 1
            stop = self.step()
            if stop:
                reason = stop
                break
        else:
            if self.reached(self.best()):
                reason = "reached the target"
        best = self.best()
        if not self.reached(best):
            best = self.confirm_closest(max(self.search.iterations - rounds, self.search.confirm_rounds))
            if self.reached(best):
                reason = "reached the target on a second look at the closest states"
        if self.kept is not None and self.refused and not self.reached(best):
            reason += f"; it kept {self.kept.describe()}: {self.refused} move(s) that would leave it were not taken"
        return self.result(best, reason, time.perf_counter() - begin)

    def confirm_closest(self, rounds: int) -> int:
        """The target was not reached: the few standing states closest to it are measured on fresh draws (those
        without any), and the one closest on fresh draws alone is chosen, so the p_fail reported is unbiased. While
        the chosen one lies in the band on too few fresh samples to count as reached, it is measured again, up to
        `rounds` times."""
        gaps = [self.gap(s) for s in self.states]
        closest = [int(k) for k in np.argsort(gaps, kind="stable")[: self.search.final_candidates]]
        closest = [k for k in closest if math.isfinite(gaps[k])]
        if not closest:
            return self.best()
        for k in closest:
            if self.states[k].fresh is None:
                self.measure(k)
        chosen = min(closest, key=lambda k: self.gap(self.states[k]))
        for _ in range(max(0, rounds)):
            state = self.states[chosen]
            assert state.fresh is not None
            if self.reached(chosen) or self.gap(state) > 0.0:
                break
            if state.fresh.effective_samples >= self.search.max_confirm_effective:
                break
            self.measure(chosen)
            chosen = min(closest, key=lambda k: self.gap(self.states[k]))
        return chosen

    def step(self) -> str | None:
        """One round: a second look at a state in the band on too few samples, else a move and a look at the states
        it added; why the search stops, or None."""
        best = self.best()
        if self.reached(best):
            return "reached the target"
        if self.gap(self.states[best]) == 0.0:  # in the band on too few samples: measure it again
            self.measure(best)
            return None
        before, source = len(self.states), -1
        if not self.between():
            source = self.best(open_only=True)
            if source < 0 or not self.move(source):
                return "no move from any state it found stands or helps"
        for new in range(before, len(self.states)):
            self.measure(new)
            self.history.append(self._p(new))
            log.debug("stability search %s: state %d p_fail %.3f", self.object_id, new, self.history[-1])
        # The move did not help (or it was the corner walks, done once): try the next kind from there.
        if source >= 0 and (self.best(open_only=True) == source or self.states[source].stage == CORNER):
            self.states[source].stage += 1
        return None

    def _p(self, index: int) -> float:
        estimate = self.states[index].estimate
        return math.nan if estimate is None else estimate.p_fail

    def result(self, index: int, reason: str, wall_s: float) -> StabilityResult:
        state = self.states[index]
        estimate = state.unbiased
        assert estimate is not None
        self.scene.objects = state.objects
        final = self.scene.object(self.object_id)
        return StabilityResult(
            object_id=self.object_id,
            target=self.target,
            band=(self.low, self.high),
            reached=self.reached(index),
            p_fail=estimate.p_fail,
            estimate=estimate,
            stands=state.stands,
            rounds=self.draws,
            stop_reason=reason,
            history=self.history,
            moved_m=float(np.linalg.norm(np.subtract(final.position, self.start.position))),
            com=final.com,
            wall_s=wall_s,
        )


def turn_about_vertical(a: tuple[float, ...], b: tuple[float, ...]) -> float:
    """The turn about the vertical (rad, in (-pi, pi]) that takes orientation `a` to `b` (quaternions w, x, y, z)."""
    qa, qb = (Rotation.from_quat(np.roll(np.asarray(q, dtype=float), -1)) for q in (a, b))
    return float((qb * qa.inv()).as_rotvec()[2])


def edge_frame(
    chord: np.ndarray, tangent: np.ndarray, normal: np.ndarray, *, min_chord: float
) -> tuple[np.ndarray, np.ndarray]:
    """The direction along an edge (oriented like `tangent`) and its outward normal (like `normal`) from a chord
    between two points found on it; the old frame when the chord is shorter than `min_chord` (too short to tell)."""
    length = float(np.linalg.norm(chord))
    if length < min_chord:
        return tangent, normal
    along = chord / length * np.sign(chord @ tangent)
    out = np.array([-along[1], along[0]])
    return along, out * np.sign(out @ normal)


def standard_error(estimate: StabilityEstimate) -> float:
    """The standard error of a kernel p_fail on its effective samples (p kept off 0 and 1, where the plain formula
    claims certainty from a few samples)."""
    p = min(max(estimate.p_fail, 0.02), 0.98)
    return math.sqrt(p * (1.0 - p) / max(estimate.effective_samples, 1.0))


def pool(a: StabilityEstimate, b: StabilityEstimate) -> StabilityEstimate:
    """One estimate from two sample sets drawn around the same state."""
    return estimate_from_samples(
        a.object_id,
        np.concatenate([a.perturbations, b.perturbations]),
        np.concatenate([a.labels, b.labels]),
        a.sigma,
        blew_up=a.blew_up + b.blew_up,
        simulated_objects=a.simulated_objects,
        horizon_s=a.horizon_s,
        wall_s=a.wall_s + b.wall_s,
        group=a.group,
    )


def search_stability(
    scene: Scene,
    object_id: str,
    target: str | float,
    *,
    engine: MujocoEngine | None = None,
    seed: int = 0,
    settings: StabilitySettings | None = None,
    search: SearchSettings | None = None,
    kept: KeptValue | None = None,
) -> StabilityResult:
    """Move the object (pose and centre of mass) toward a target p_fail: "unstable" (at least 0.9 while it
    stands), "stable" (at most 0.05) or a number, keeping `kept` within its tolerance. The scene is left at the
    best standing state found."""
    return _Search(
        scene,
        object_id,
        target,
        engine or MujocoEngine(),
        seed,
        settings or StabilitySettings(),
        search or SearchSettings(),
        kept,
    ).run()


def refine_stability(
    scene: Scene,
    object_id: str,
    target: str | float,
    engine: MujocoEngine,
    seed: int = 0,
    samples: int = 128,
    kept: KeptValue | None = None,
) -> StabilityResult:
    """The solver's hook after a PLACE-ON with `stability`: search toward the target and leave the scene at the
    best standing state found (the object's pose and centre of mass change in place), keeping `kept`."""
    return search_stability(
        scene, object_id, target, engine=engine, seed=seed, settings=StabilitySettings(samples=samples), kept=kept
    )
