"""Physical solver: PLACE-ON and PLACE-ANYWHERE by voxel search confirmed in physics (PLACE-IN: filling.py).

For one object: voxelise the scene and the object at a few yaws, find every free
translation by FFT cross-correlation, drop each column to its resting height, keep
spots whose centre of mass projects inside the contact patch, rank them by the
predicate's wishes, then try the best few in MuJoCo: lower the object until it
touches, let the scene settle, and keep the first spot where nothing moved too far.
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import NamedTuple

import numpy as np
from scipy.ndimage import binary_dilation, distance_transform_edt

from physcensis.assets.model import Asset
from physcensis.assets.supports import SHELF_SPACING, support_asset
from physcensis.errors import PhyscensisError
from physcensis.geometry.footprints import min_distance, outline, placed_hull
from physcensis.geometry.voxels import (
    Candidates,
    Grid,
    ObjectGrid,
    PartCells,
    candidate_origin,
    object_grid,
    part_cells,
    quat_to_matrix,
    rasterise,
    stamp,
    supported_candidates,
    yaw_matrix,
)
from physcensis.ids import ROOT_ID
from physcensis.physics.engine import DEFAULT_TOLERANCE, Tolerance, at_rest
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.physics.profiles import MUJOCO_DEFAULT_TOLERANCE, UNDER_DEFAULTS
from physcensis.program.registry import PlacementKind, placement_spec
from physcensis.scene import PlacedObject, Placement, Scene
from physcensis.solver.objects import object_rng, physical_properties, yaw_quaternion

PITCH_M = 0.01
FLOOR_PITCH_M = 0.03
PACKING_CELLS = 10_000  # PLACE-ANYWHERE packing on a table or shelf: cells over its top, at most
MIN_PACKING_PITCH_M = 0.005
KEPT_LATTICES = 4  # per placed object, its cells on this many grid lattices are kept (see _cells_of)
PAD_FRACTION = 0.25
MIN_MARGIN_FRACTION = 0.5  # the COM must project at least half a cell inside the contact patch
MAX_MARGIN_M = 0.01  # ... or a centimetre, whichever is less
MAX_TRIES = 6
# PLACE-ON with an overlap: score per cell off the target's centre. It only breaks ties (a cup asked for 0.55
# ended at 0.76 under a pull of 0.2), so a stability search starts at the overlap asked, which it then keeps.
OFF_CENTRE_PULL = 0.05
NEAR_STABLE = 0.05  # a numeric stability target at most this is as robust as "stable" (see _fragile)
CENTRED_OVERLAP = 0.85  # PLACE-ON asking at least this much overlap is first tried centred on its target
TRY_SPACING_CELLS = 3
PLACE_SETTLE_S = 1.0
# Under MuJoCo's defaults a placement must hold more tightly than "moved under a centimetre": whatever still creeps a
# few millimetres in a second is far from resting after the paper's four (turning in place is no fall, see profiles).
STRICT_TOLERANCE = Tolerance(translation_m=0.003, rotation_rad=MUJOCO_DEFAULT_TOLERANCE.rotation_rad)
REST_CHECK_S = 0.8  # a confirmation may stop once this much time has passed and nothing moves
SUPPORT_LABEL = -2
SNUG_OVERLAP_M = 0.003
OUT_OF_TIME = "not tried: the run's time budget ran out before its turn (raise --time-budget, or ask for fewer objects)"
EDGE_CLEARANCE_M = 0.0  # the physics check already rejects anything that teeters at the edge
DEFAULT_YAWS = 4
NEIGHBOUR_MARGIN_M = 0.15  # objects this close to a new one are simulated with it; the rest are held fixed
# A PLACE-ANYWHERE spot on a bare table top this far from everything placed and from the edges touches nothing as it
# rests: it is set down in its rest pose without a settle of its own, and the scene's final verification, under both
# contact settings, confirms it with the rest (a context vase on a dining table took 0.56 s of settles alone).
APART_M = 0.01
ROOM_CHECKS = 40  # PLACE-ANYWHERE: how many of the best spots are checked for the room they leave
ROOM_WEIGHT = 5.0  # score per ROOM_RADIUS_M of radius of the largest open patch left
ROOM_AREA_WEIGHT = 5.0  # score for open room that is all far from everything (see _room_score)
ROOM_RADIUS_M = 0.13  # ... "far": this far (the radius of a large plate)
KEEP_WEIGHT = 3.0  # score for a spot that keeps room for the largest thing on the support to go down again
KEEP_AREA_WEIGHT = 3.0  # ... plus this times the share of the places for it that stay open
PACKING_YAWS = 8  # PLACE-ANYWHERE yaws: along the support's edges and between (over 2 pi with a front, else pi)
# Cells per layer of the search grid: a larger support is searched in a window of it around what matters (the
# target, or what is already placed), so memory stays bounded (a whole 50 x 50 m floor would take gigabytes).
MAX_GRID_CELLS_XY = 300 * 300


SEARCHED_PLACEMENTS = (PlacementKind.ON, PlacementKind.ANYWHERE)  # what the voxel search places


def support_margin(asset: Asset, pitch: float) -> float:
    """How far inside its contact patch an object's COM must project to count as supported: half a cell but at most
    a centimetre (the floor's cells are 3 cm), less for objects so small that this is a large part of them."""
    return min(MIN_MARGIN_FRACTION * pitch, MAX_MARGIN_M, 0.3 * 0.5 * min(asset.size[:2]))


@dataclass
class PlaceRequest:
    """One object to place on another object (kind ON, PLACE-ON) or anywhere (kind ANYWHERE, PLACE-ANYWHERE)."""

    object_id: str
    description: str
    asset: Asset
    kind: PlacementKind
    target: str = "root"
    x_offset: float | None = None
    y_offset: float | None = None
    overlap: float | None = None
    stability: str | float | None = None
    messy: bool = False
    stack: bool = True
    yaws: tuple[float, ...] | None = None
    predicate: str = ""  # recorded in the scene as what placed the object; by default the kind's own predicate
    # PLACE-ANYWHERE: pack snugly against what is already there and the support's edges, keeping room for more
    # (filling a support densely); otherwise a seeded random free spot, as the paper defines the predicate
    pack: bool = False
    overhang: bool = False  # may stick out past the support's edge when it still rests stably

    def __post_init__(self) -> None:
        if self.kind not in SEARCHED_PLACEMENTS:
            searched = " or ".join(str(k) for k in SEARCHED_PLACEMENTS)
            raise PhyscensisError(
                f"PlaceRequest for {self.object_id}: kind must be {searched}, not {self.kind!r} "
                "(PLACE-IN drops its items with PhysicalSolver.place_in)"
            )
        self.kind = PlacementKind(self.kind)
        self.predicate = self.predicate or placement_spec(self.kind).name


# One yaw's share of a search: (yaw, object grid, supported candidates, their scores).
Ranked = tuple[float, ObjectGrid, Candidates, np.ndarray]


class Spots(NamedTuple):
    """What the voxel search found: ranked supported spots at each yaw."""

    grid: Grid
    pool: list[Ranked]
    crowding: float  # share of the target's top (or of the support) that is covered
    total: int  # supported spots over all yaws


@dataclass
class PlaceOutcome:
    object_id: str
    ok: bool
    reason: str | None = None
    tries: int = 0
    candidates: int = 0
    crowding: float = 0.0  # share of the target's top area that is covered
    support_ratio: float | None = None
    margin_m: float | None = None
    extra: dict[str, float] = field(default_factory=dict)


class PhysicalSolver:
    """Places objects into a scene one at a time; `scene.objects` grows with every success."""

    def __init__(
        self,
        scene: Scene,
        engine: MujocoEngine,
        *,
        seed: int = 0,
        tolerance: Tolerance = DEFAULT_TOLERANCE,
        settle_s: float = PLACE_SETTLE_S,
        pitch: float | None = None,
        deadline: float | None = None,
    ) -> None:
        self.scene = scene
        self.deadline = deadline  # time.perf_counter() after which no placement is tried (each fails, said why)
        self.engine = engine
        self.seed = seed
        self.tolerance = tolerance
        self.settle_s = settle_s
        self.pitch = pitch or (FLOOR_PITCH_M if scene.support.kind == "floor" else PITCH_M)
        self.fixed_pitch = pitch is not None  # a caller's pitch is used for every search
        self.pad = PAD_FRACTION * self.pitch
        self.rng = np.random.default_rng([seed, 7919])
        self._support = support_asset(scene.support)
        self._object_grids: dict[tuple[str, float, int, float], ObjectGrid] = {}
        self._cells: dict[str, dict[tuple[object, ...], list[PartCells]]] = {}
        self._hulls: dict[str, tuple[tuple[object, ...], np.ndarray]] = {}
        # Placements are confirmed under MuJoCo's defaults too, unless that is what the engine already runs.
        self.strict = engine.defaults_check()

    # -- the scene as a grid ----------------------------------------------------------
    def scene_grid(
        self, z_top: float, margin: float = 0.0, focus: tuple[float, float] = (0.0, 0.0)
    ) -> tuple[Grid, list[PlacedObject]]:
        """The support and the placed objects as cells, `margin` metres past the support's edges; a support of
        more than MAX_GRID_CELLS_XY cells is covered only in a window of that many cells centred near `focus`."""
        support = self.scene.support
        hx, hy = support.half_extents
        hx, hy = hx + margin, hy + margin
        top = support.top_height
        p = self.pitch
        if support.kind == "shelf":
            z_top = min(z_top, top + SHELF_SPACING - 0.02)
        nz = max(3, int(math.ceil((z_top - (top - 2 * p)) / p)))
        nx, ny = int(math.floor(2 * hx / p)), int(math.floor(2 * hy / p))
        (i0, wx), (j0, wy) = _window(nx, ny, ((focus[0] + nx * p / 2) / p, (focus[1] + ny * p / 2) / p))
        origin = np.array([-nx * p / 2 + i0 * p, -ny * p / 2 + j0 * p, top - 2 * p])
        open_sides = (i0 > 0, i0 + wx < nx, j0 > 0, j0 + wy < ny)
        grid = Grid(
            np.zeros((wx, wy, nz), dtype=bool), np.full((wx, wy, nz), -1, dtype=np.int32), origin, p, open_sides
        )
        rasterise(grid, self._support.collision, np.eye(3), np.zeros(3), SUPPORT_LABEL, self.pad)
        placed = self.scene.placed
        for k, obj in enumerate(placed):
            stamp(grid, self._cells_of(obj, grid), k)
        return grid, placed

    def _cells_of(self, obj: PlacedObject, grid: Grid) -> list[PartCells]:
        """A placed object's cells on the grid's lattice, kept while it stays where it is (every search
        rasterises every placed object again, mostly unmoved): the last few lattices per object, none for old poses."""
        key = (obj.asset, obj.position, obj.quaternion, tuple(grid.origin), grid.shape[:2], self.pitch, self.pad)
        kept = self._cells.setdefault(obj.id, {})
        if key not in kept:
            if len(kept) >= KEPT_LATTICES or any(k[:3] != key[:3] for k in kept):
                kept.clear()
            asset = self.engine.catalogue.asset_for(obj.asset, obj.description)
            rotation, position = quat_to_matrix(obj.quaternion), np.asarray(obj.position)
            kept[key] = part_cells(grid, asset.collision, rotation, position, self.pad)
        return kept[key]

    def _object_grid(self, asset: Asset, yaw: float, k_bottom: int) -> ObjectGrid:
        key = (asset.id, round(yaw, 6), k_bottom, self.pitch)
        if key not in self._object_grids:
            self._object_grids[key] = object_grid(asset, yaw, self.pitch, pad=self.pad, k_bottom=k_bottom)
        return self._object_grids[key]

    def _top_of(self, obj: PlacedObject) -> float:
        asset = self.engine.catalogue.asset_for(obj.asset, obj.description)
        return float(obj.position[2] + np.linalg.norm(asset.size) / 2 + asset.size[2] / 2)

    # -- PLACE-ON / PLACE-ANYWHERE ------------------------------------------------------------
    def place(self, request: PlaceRequest) -> PlaceOutcome:
        """Find supported spots, then confirm the best few in physics; the scene gains the object, placed
        or (with its reason) failed."""
        if self.out_of_time():
            where = self.meant_for(request.target)
            args = (request.object_id, request.description, request.asset, OUT_OF_TIME, request.predicate)
            return self.fail(*args, request.target, where)
        search = self.search(request)
        outcome = search if isinstance(search, PlaceOutcome) else self._confirm(request, search)
        if not outcome.ok and not isinstance(search, PlaceOutcome) and _fragile(request.stability):
            # The most fragile spots all fell (a jar at a plate's sloping rim): any spot that rests will do, the
            # stability search then moves the object toward the fragility asked for.
            robust = replace(request, stability=None)
            retry = self.search(robust)
            outcome = retry if isinstance(retry, PlaceOutcome) else self._confirm(robust, retry)
        if not outcome.ok:
            self.fail(
                request.object_id,
                request.description,
                request.asset,
                outcome.reason or "not placed",
                request.predicate,
                request.target,
                self.meant_for(request.target),
            )
        return outcome

    def out_of_time(self) -> bool:
        return self.deadline is not None and time.perf_counter() >= self.deadline

    def meant_for(self, target: str) -> tuple[float, float, float]:
        """Where an object that failed was meant to go: its target, or the middle of the support."""
        found = next((o for o in self.scene.objects if o.id == target), None)
        return found.position if found else (0.0, 0.0, self.scene.support.top_height)

    def search(self, request: PlaceRequest) -> PlaceOutcome | Spots:
        """The voxel search alone: ranked supported spots at each yaw, or a failure with its reason."""
        pitch = self._search_pitch(request)
        if pitch == self.pitch:
            return self._search(request)
        own = self.pitch, self.pad
        self.pitch, self.pad = pitch, PAD_FRACTION * pitch
        try:
            return self._search(request)
        finally:
            self.pitch, self.pad = own

    def _search_pitch(self, request: PlaceRequest) -> float:
        """The cell size of one search. On another object the table's fine grid even on a floor: a floor cell is
        coarser than a toy block, and the grid is windowed around the target anyway. Packing a table or shelf
        (PLACE-ANYWHERE, snug, on the support only), cells as fine as PACKING_CELLS over its top allow, down to
        MIN_PACKING_PITCH_M: a centimetre cell leaves up to a centimetre between neighbours, which on a small table
        is room for more. Searches that may stack keep their cells: the centre of mass's margin inside a patch on
        another object is half a cell, and piles searched on 5 mm cells lost objects under MuJoCo's defaults."""
        if request.kind is PlacementKind.ON:
            return min(self.pitch, PITCH_M)
        if self.fixed_pitch:
            return self.pitch
        support = self.scene.support
        packing = request.kind is PlacementKind.ANYWHERE and request.pack and not request.stack
        if packing and support.kind != "floor":
            sx, sy = support.size[:2]
            return float(np.clip(math.sqrt(sx * sy / PACKING_CELLS), MIN_PACKING_PITCH_M, self.pitch))
        return self.pitch

    def _search(self, request: PlaceRequest) -> PlaceOutcome | Spots:
        placed_now = self.scene.placed
        ids = [o.id for o in placed_now]
        on_target = request.kind is PlacementKind.ON
        if on_target and request.target not in ids:
            return PlaceOutcome(
                request.object_id,
                False,
                f"{request.target} is not in the scene (it failed or was never placed), so nothing can rest on it",
            )
        height = request.asset.size[2]
        if on_target:
            z_top = self._top_of(self.scene.object(request.target)) + height + 3 * self.pitch
        elif request.stack and placed_now:
            z_top = max(self._top_of(o) for o in placed_now) + height + 3 * self.pitch
        else:
            z_top = self.scene.support.top_height + height + 3 * self.pitch
        # Overhang: the grid reaches past the edges. Otherwise keep a cell clear of the edge, so nothing teeters.
        margin = 0.5 * max(request.asset.size[:2]) if request.overhang else -EDGE_CLEARANCE_M
        grid, placed = self.scene_grid(z_top, margin, self._focus(request, placed_now))
        target_label = ids.index(request.target) if on_target else None
        stack = self._stack_under(request.target, ids) if on_target else []
        k = 5 if request.messy else 1
        yaws = request.yaws or self._default_yaws(request)
        pool: list[Ranked] = []
        free_any = supported_any = False
        for yaw in yaws:
            og = self._object_grid(request.asset, yaw, k)
            min_margin = support_margin(request.asset, self.pitch)
            cands = supported_candidates(
                grid,
                og,
                k_search=k,
                min_margin=min_margin,
                target_label=stack or None,
                rng=self.rng,
                support_label=SUPPORT_LABEL,
            )
            free_any = free_any or cands.free_spots > 0
            supported_any = supported_any or len(cands.tx) > 0
            keep = self._filter(cands, request, target_label)
            cands = cands.subset(keep & self._over_target(grid, og, cands, request, stack))
            if len(cands.tx) == 0:
                continue
            scores = self._score(grid, og, cands, request, placed, target_label)
            pool.append((yaw, og, cands, scores))
        crowding = self._crowding(grid, target_label)
        total = sum(len(c.tx) for _, _, c, _ in pool)
        if total:
            if request.kind is PlacementKind.ANYWHERE and request.pack:
                self._room_left(grid, pool)
            return Spots(grid, pool, crowding, total)
        where = f"on {request.target}" if on_target else "on the support"
        if not free_any:
            reason = f"no free spot {where}: nothing there is large enough for it ({crowding:.0%} covered)"
        elif not supported_any or on_target:
            reason = (
                f"no supported spot {where}: wherever it fits, its centre of mass would overhang "
                f"what is under it ({crowding:.0%} covered)"
            )
        else:
            reason = (
                f"no free spot {where}: the only supported spots are on top of other objects, and this "
                f"placement may not stack ({crowding:.0%} covered)"
            )
        return PlaceOutcome(request.object_id, False, reason, 0, 0, crowding)

    def _over_target(
        self, grid: Grid, og: ObjectGrid, cands: Candidates, request: PlaceRequest, stack: list[int]
    ) -> np.ndarray:
        """Which spots put the object's centre of mass over the target's footprint: on a stack it may also touch
        what the target rests on (thin things share cells), but it rests on the target, not beside it."""
        if len(stack) < 2:
            return np.ones(len(cands.tx), dtype=bool)
        below = self.scene.object(request.target)
        size = self.engine.catalogue.asset_for(below.asset, below.description).size
        origins = grid.origin[:2] + np.stack([cands.tx, cands.ty], axis=1) * grid.pitch + og.origin_offset[:2]
        com = origins + yaw_matrix(og.yaw)[:2, :2] @ np.asarray(request.asset.com[:2])
        turn = quat_to_matrix(below.quaternion)[:2, :2]
        local = (com - np.asarray(below.position[:2])) @ turn  # into the target's frame
        return np.all(np.abs(local) <= 0.5 * np.asarray(size[:2]), axis=1)

    def _stack_under(self, target: str, ids: list[str]) -> list[int]:
        """The labels of the target and of the stack it rests on: a thin thing on a stack of thin things (envelopes,
        napkins) shares cells with the ones below its target, and resting on them is resting on the stack."""
        labels: list[int] = []
        on = placement_spec(PlacementKind.ON).name
        below: str | None = target
        while below in ids and ids.index(below) not in labels:
            labels.append(ids.index(below))
            placement = self.scene.object(below).placement
            below = placement.target if placement is not None and placement.predicate == on else None
        return labels

    def _focus(self, request: PlaceRequest, placed: list[PlacedObject]) -> tuple[float, float]:
        """Where a windowed search grid is centred: on the target, else amid what is already placed."""
        if request.kind is PlacementKind.ON:
            x, y, _ = self.scene.object(request.target).position
            return x, y
        if not placed:
            return 0.0, 0.0
        xy = np.array([o.position[:2] for o in placed])
        low, high = xy.min(axis=0), xy.max(axis=0)
        return float(low[0] + high[0]) / 2, float(low[1] + high[1]) / 2

    def _default_yaws(self, request: PlaceRequest) -> tuple[float, ...]:
        round_one = not request.asset.has_front and _round_footprint(request.asset)
        if request.kind is PlacementKind.ANYWHERE and request.pack:
            return _packing_yaws(request.asset, round_one)
        start = float(object_rng(self.seed, request.object_id).uniform(0, math.pi / 2))
        n = 1 if round_one else DEFAULT_YAWS
        return tuple(start + i * math.pi / n for i in range(n))

    def _filter(self, cands: Candidates, request: PlaceRequest, target: int | None) -> np.ndarray:
        if target is not None:
            only_target = cands.n_target == cands.n_contact
            return (cands.n_target > 0) & (only_target | request.messy)
        if not request.stack:
            return cands.n_support == cands.n_contact
        return np.ones(len(cands.tx), dtype=bool)

    def _score(
        self,
        grid: Grid,
        og: ObjectGrid,
        cands: Candidates,
        request: PlaceRequest,
        placed: list[PlacedObject],
        target: int | None,
    ) -> np.ndarray:
        p = self.pitch
        m = len(cands.tx)
        jitter = self.rng.uniform(0.0, 1.0, m)
        margin_cells = np.clip(cands.margin / p, 0.0, 10.0)
        if request.kind is PlacementKind.ON and target is not None:
            b = placed[target]
            centre = np.array(
                [candidate_origin(grid, og, *t)[:2] for t in zip(cands.tx, cands.ty, cands.tz, strict=True)]
            )
            ratio_b = cands.target_ratio
            score = 0.05 * jitter
            if request.overlap is not None:
                score -= 6.0 * np.abs(ratio_b - request.overlap)
            if request.x_offset is not None or request.y_offset is not None:
                wish = np.asarray(b.position[:2]) + [request.x_offset or 0.0, request.y_offset or 0.0]
                score -= 20.0 * np.linalg.norm(centre - wish, axis=1)
            else:  # centred by default, and among spots of equal overlap the most centred (a tower stays straight)
                off = np.linalg.norm(centre - np.asarray(b.position[:2]), axis=1)
                if request.overlap is None:
                    score -= 5.0 * off
                else:  # a tie-break, so the overlap asked for is kept (a stability search keeps it too)
                    score -= OFF_CENTRE_PULL * off / p
            score += _stability_term(request.stability, margin_cells)
            return score
        # PLACE-ANYWHERE: a random spot, low ones first when it may stack; packed, snug against its neighbours
        score = 0.3 * jitter - 0.02 * (cands.tz - cands.tz.min())
        if request.pack:
            # The edges of the support count as neighbours too, so things pack into corners and along edges.
            body = np.pad(og.occupied, ((1, 1), (1, 1), (0, 0)))
            ring = binary_dilation(body, structure=np.ones((3, 3, 1), dtype=bool)) & ~body
            walled = grid.spectrum("occupied, edges walled", lambda: _pad_xy(grid.occupied, grid, blocked=True))
            near = walled.correlate_valid(ring)
            score += near[cands.tx, cands.ty, cands.tz] / max(1, ring.sum())
            score += _keeps_room(grid, og, cands, self._room_to_keep(request) / self.pitch)
        return score

    def _room_left(self, grid: Grid, pool: list[Ranked]) -> None:
        """Among the best spots of all yaws, favour those that leave the most usable open room for what comes
        next (scores are raised in place)."""
        free = _uncovered(grid)
        cap = max(1.0, ROOM_RADIUS_M / self.pitch)
        for yi, idx in _best(pool, ROOM_CHECKS):
            _, og, cands, scores = pool[yi]
            if cands.tz[idx] > 2:  # resting on something: it does not use floor space
                continue
            footprint = og.occupied.any(axis=2)
            fx, fy = footprint.shape
            after = free.copy()
            after[cands.tx[idx] : cands.tx[idx] + fx, cands.ty[idx] : cands.ty[idx] + fy] &= ~footprint
            room = distance_transform_edt(_pad_xy(after, grid, blocked=False))  # the support's edges are walls
            scores[idx] += _room_score(room, cap, after.size)

    def _room_to_keep(self, request: PlaceRequest) -> float:
        """The radius of open room that the largest thing already on the support (or this one) needs to go down
        again: half its footprint's shorter side, grown by the cells' pad."""
        sizes = [request.asset.size[:2]]
        for obj in self.scene.placed:
            sizes.append(self.engine.catalogue.asset_for(obj.asset, obj.description).size[:2])
        return max(0.5 * min(s) for s in sizes) + self.pad

    def _crowding(self, grid: Grid, target: int | None) -> float:
        top_layer = 2  # the first layer above the support
        if target is None:
            free_top = ~grid.occupied[:, :, top_layer]
            return float(1.0 - free_top.mean())
        mask = (grid.label == target).any(axis=2)
        if not mask.any():
            return 0.0
        covered = (grid.occupied & (grid.label != target) & (grid.label >= 0)).any(axis=2)
        return float((covered & mask).sum() / mask.sum())

    def _confirm(self, request: PlaceRequest, spots: Spots) -> PlaceOutcome:
        grid, pool, crowding, total = spots
        chosen: list[tuple[int, int]] = []
        seen_xy: list[np.ndarray] = []
        for yi, idx in _best(pool, 2000):
            cands = pool[yi][2]
            xy = np.array([cands.tx[idx], cands.ty[idx]])
            if any(np.abs(xy - other).max() < TRY_SPACING_CELLS for other in seen_xy):
                continue
            chosen.append((yi, idx))
            seen_xy.append(xy)
            if len(chosen) >= MAX_TRIES:
                break
        last_reason = "it never came to rest"
        for attempt, (yi, idx) in enumerate(chosen, start=1):
            yaw, og, cands, _ = pool[yi]
            origin = candidate_origin(grid, og, cands.tx[idx], cands.ty[idx], cands.tz[idx])
            ok, reason = self._set_down_apart(request, origin, yaw), None
            centred = None if ok else self._centred_on_target(request, origin, yaw, grid.pitch)
            if centred is not None:  # the cell-free centre first: a tower of cells' offsets leans
                ok, reason = self._try(request, centred, yaw, grid.pitch)
            if not ok:
                ok, reason = self._try(request, origin, yaw, grid.pitch)
            if ok:
                ratio = float(cands.target_ratio[idx] if request.kind is PlacementKind.ON else cands.ratio[idx])
                return PlaceOutcome(
                    request.object_id, True, None, attempt, total, crowding, ratio, float(cands.margin[idx])
                )
            last_reason = reason or last_reason
        return PlaceOutcome(
            request.object_id,
            False,
            f"fell during settling at each of the {len(chosen)} best "
            f"supported spots (last: {last_reason}); the target is {crowding:.0%} covered",
            len(chosen),
            total,
            crowding,
        )

    def _centred_on_target(
        self, request: PlaceRequest, origin: np.ndarray, yaw: float, pitch: float
    ) -> np.ndarray | None:
        """For a PLACE-ON that asks for no offsets, no stability and no partial overlap, the spot (within a cell and
        a half of `origin`) whose centre of mass is right over the target's, or None."""
        partial = request.overlap is not None and request.overlap < CENTRED_OVERLAP
        asked = request.x_offset is not None or request.y_offset is not None or request.stability is not None
        if request.kind is not PlacementKind.ON or partial or asked:
            return None
        target = self.scene.object(request.target)
        below = self.engine.catalogue.asset_for(target.asset, target.description)
        wish = np.asarray(target.position[:2]) + quat_to_matrix(target.quaternion)[:2, :2] @ np.asarray(below.com[:2])
        centred = origin.copy()
        centred[:2] = wish - yaw_matrix(yaw)[:2, :2] @ np.asarray(request.asset.com[:2])
        return centred if float(np.linalg.norm(centred[:2] - origin[:2])) <= 1.5 * pitch else None

    def _set_down_apart(self, request: PlaceRequest, origin: np.ndarray, yaw: float) -> bool:
        """Set the object down in its rest pose at `origin` when the spot is on a bare table top, APART_M from
        everything placed and inside the edges, and it is a plain PLACE-ANYWHERE (no stacking, packing, overhang or
        stability asked); whether it was."""
        plain = not (request.stack or request.messy or request.pack or request.overhang or request.stability)
        support = self.scene.support
        if request.kind is not PlacementKind.ANYWHERE or request.target != ROOT_ID or not plain:
            return False
        if support.kind != "table" or not request.asset.rests:
            return False
        hull = placed_hull(request.asset.footprint(), float(origin[0]), float(origin[1]), yaw)
        if (np.abs(hull) > np.array(support.half_extents) - APART_M).any():
            return False
        if min_distance(hull, [self._hull_of(obj) for obj in self.scene.placed]) < APART_M:
            return False
        new = self._new_object(request, (float(origin[0]), float(origin[1]), support.top_height), yaw)
        self.scene.objects = [*self.scene.objects, new]
        return True

    def _hull_of(self, obj: PlacedObject) -> np.ndarray:
        """The xy outline (convex hull) of a placed object as it stands, tilted or not; kept while it stays put."""
        key = (obj.asset, obj.position, obj.quaternion)
        kept = self._hulls.get(obj.id)
        if kept is None or kept[0] != key:
            asset = self.engine.catalogue.asset_for(obj.asset, obj.description)
            points = np.asarray(asset.visual.vertices) @ quat_to_matrix(obj.quaternion).T + np.asarray(obj.position)
            kept = self._hulls[obj.id] = (key, outline(points[:, :2]))
        return kept[1]

    def _new_object(self, request: PlaceRequest, position: tuple[float, float, float], yaw: float) -> PlacedObject:
        mass, friction, com = physical_properties(request.asset, request.object_id, self.seed)
        return PlacedObject(
            id=request.object_id,
            description=request.description,
            asset=request.asset.id,
            category=request.asset.category,
            position=position,
            quaternion=yaw_quaternion(yaw),
            mass=mass,
            friction=friction,
            com=com,
            placement=Placement(predicate=request.predicate, target=request.target),
        )

    def _try(self, request: PlaceRequest, origin: np.ndarray, yaw: float, pitch: float) -> tuple[bool, str | None]:
        new = self._new_object(request, (float(origin[0]), float(origin[1]), float(origin[2])), yaw)
        near, far = self._neighbours(new, request.asset)
        built = self.engine.build(self.scene, objects=[*near, new], visual=False, fixed=far)
        # Voxels are a cell coarse: a few millimetres of overlap with a snug neighbour is left to the settle.
        z = built.lower_onto_support(
            new.id, origin[2] + 0.5 * pitch, origin[2] - 1.5 * pitch, allowed_side=SNUG_OVERLAP_M
        )
        if z is None:
            return False, "it would overlap a neighbour there"
        result = self.engine.settle_built(
            built,
            self.scene.support.top_height,
            duration_s=self.settle_s,
            tolerance=self.tolerance,
            stop_at_rest_s=REST_CHECK_S,
        )
        motion = result.objects[new.id]
        if not motion.ok:
            return False, motion.reason
        disturbed = [m for m in result.objects.values() if m.id != new.id and not m.ok]
        if disturbed:
            return False, f"it knocked {disturbed[0].id} over ({disturbed[0].reason})"
        reason = self._moves_under_defaults(at_rest([*near, new], result.objects), far, new.id)
        if reason:
            return False, reason
        self.scene.objects = at_rest([*self.scene.objects, new], result.objects)
        return True, None

    def _moves_under_defaults(self, objects: list[PlacedObject], fixed: list[PlacedObject], new_id: str) -> str | None:
        """Why the settled neighbourhood would not rest under MuJoCo's default contact settings (a softer, pyramidal
        friction cone and a 0.01 s step, what a user's simulator most likely runs), or None when it does."""
        if self.strict is None:
            return None
        built = self.strict.build(self.scene, objects=objects, visual=False, fixed=fixed)
        result = self.strict.settle_built(
            built,
            self.scene.support.top_height,
            duration_s=self.settle_s,
            tolerance=STRICT_TOLERANCE,
            stop_at_rest_s=REST_CHECK_S,
        )
        failed = sorted(result.failed, key=lambda m: m.id != new_id)
        if not failed:
            return None
        who = "it" if failed[0].id == new_id else f"{failed[0].id}"
        return f"{UNDER_DEFAULTS} {who} would not rest ({failed[0].reason})"

    def _neighbours(self, new: PlacedObject, asset: Asset) -> tuple[list[PlacedObject], list[PlacedObject]]:
        """Placed objects that the new one could touch or push (simulated), and the rest (held fixed)."""
        reach = 0.5 * float(np.linalg.norm(asset.size[:2])) + NEIGHBOUR_MARGIN_M
        near: list[PlacedObject] = []
        far: list[PlacedObject] = []
        for obj in self.scene.placed:
            other = self.engine.catalogue.asset_for(obj.asset, obj.description)
            radius = 0.5 * float(np.linalg.norm(other.size))
            close = np.linalg.norm(np.subtract(obj.position[:2], new.position[:2])) < reach + radius
            (near if close else far).append(obj)
        return near, far

    def fail(
        self,
        object_id: str,
        description: str,
        asset: Asset,
        reason: str,
        predicate: str,
        target: str,
        position: Sequence[float],
    ) -> PlaceOutcome:
        """Record a failed placement in the scene: status failed, its reason, and where it was meant to go."""
        if not any(o.id == object_id for o in self.scene.objects):
            mass, friction, com = physical_properties(asset, object_id, self.seed)
            self.scene.objects = [
                *self.scene.objects,
                PlacedObject(
                    id=object_id,
                    description=description,
                    asset=asset.id,
                    category=asset.category,
                    position=(float(position[0]), float(position[1]), float(position[2])),
                    mass=mass,
                    friction=friction,
                    com=com,
                    placement=Placement(predicate=predicate, target=target),
                    status="failed",
                    reason=reason,
                ),
            ]
        return PlaceOutcome(object_id, False, reason)


def _window(nx: int, ny: int, centre: tuple[float, float]) -> tuple[tuple[int, int], tuple[int, int]]:
    """(start, size) along x and y of at most MAX_GRID_CELLS_XY cells of an nx x ny grid, centred as near `centre`
    (in cells) as the grid allows: the whole grid when it is small enough."""
    if nx * ny <= MAX_GRID_CELLS_XY:
        return (0, nx), (0, ny)
    side = math.isqrt(MAX_GRID_CELLS_XY)
    wx = min(nx, max(side, MAX_GRID_CELLS_XY // max(1, ny)))
    wy = min(ny, MAX_GRID_CELLS_XY // wx)
    i0 = int(np.clip(round(centre[0] - wx / 2), 0, nx - wx))
    j0 = int(np.clip(round(centre[1] - wy / 2), 0, ny - wy))
    return (i0, wx), (j0, wy)


def _pad_xy(cells: np.ndarray, grid: Grid, *, blocked: bool) -> np.ndarray:
    """`cells` with one more cell on each side in x and y: `blocked` along the support's edges, free (`not
    blocked`) along the open sides of a windowed grid."""
    padded = np.pad(cells, [(1, 1), (1, 1)] + [(0, 0)] * (cells.ndim - 2), constant_values=blocked)
    low_x, high_x, low_y, high_y = grid.open_sides
    for is_open, side in ((low_x, np.s_[0]), (high_x, np.s_[-1]), (low_y, np.s_[:, 0]), (high_y, np.s_[:, -1])):
        if is_open:
            padded[side] = not blocked
    return padded


def _best(pool: list[Ranked], n: int) -> list[tuple[int, int]]:
    """(yaw index, candidate index) of the n best-scored spots over all yaws, best first."""
    scores = np.concatenate([p[3] for p in pool])
    which = np.concatenate([np.full(len(p[3]), yi) for yi, p in enumerate(pool)])
    index = np.concatenate([np.arange(len(p[3])) for p in pool])
    order = np.argsort(-scores, kind="stable")[:n]
    return [(int(which[k]), int(index[k])) for k in order]


def _fragile(stability: str | float | None) -> bool:
    """Whether a stability wish makes the search prefer spots near the edge of standing (a target of a few per cent
    is scored like "stable")."""
    if stability is None or stability == "stable":
        return False
    return stability == "unstable" or float(stability) > NEAR_STABLE


def _stability_term(stability: str | float | None, margin_cells: np.ndarray) -> np.ndarray:
    if stability is None or stability == "stable":
        return 0.3 * np.minimum(margin_cells, 4.0)
    if stability == "unstable":
        return -0.6 * margin_cells
    target = float(stability)
    return -0.6 * margin_cells * target + 0.3 * np.minimum(margin_cells, 4.0) * (1 - target)


def _uncovered(grid: Grid) -> np.ndarray:
    """The cells of the support's top that nothing covers (layer 2 is the first above the support), as (x, y)."""
    return np.asarray(~grid.occupied[:, :, 2:].any(axis=2))


def _keeps_room(grid: Grid, og: ObjectGrid, cands: Candidates, radius: float) -> np.ndarray:
    """Score of each spot for the room it keeps for the largest thing on the support: a disc of `radius` cells fits
    where no occupied cell is that near; a spot keeps room when some such place stays clear of the object and its
    surroundings (the object's footprint grown by the radius), more so the more such places stay clear."""
    free = _uncovered(grid)
    room = distance_transform_edt(_pad_xy(free, grid, blocked=False))[1:-1, 1:-1]
    centres = room > radius
    total = int(centres.sum())
    if total == 0:
        return np.zeros(len(cands.tx))
    r = int(math.ceil(radius))
    footprint = og.occupied.any(axis=2)
    near = distance_transform_edt(~np.pad(footprint, r)) <= radius
    padded = grid.spectrum(f"room centres {radius:.4f}", lambda: np.pad(centres, r))
    covered = padded.correlate_valid(near)[cands.tx, cands.ty]
    left = np.clip(total - np.rint(covered), 0, None)
    return KEEP_WEIGHT * (left > 0) + KEEP_AREA_WEIGHT * left / total


def _room_score(room: np.ndarray, cap: float, cells: int) -> float:
    """How usable the open room left is: the radius of the largest open patch (can the largest thing still go
    down?), and how much of the open area lies far enough from everything for a large thing (no slivers)."""
    largest = ROOM_WEIGHT * float(room.max()) / cap
    usable = ROOM_AREA_WEIGHT * float(np.minimum(room, cap).sum()) / (cap * cells)
    return largest + usable


def _packing_yaws(asset: Asset, round_one: bool) -> tuple[float, ...]:
    """Yaws for packing: along the support's edges (what packs a rectangle best) and between; one for round things."""
    if round_one:
        return (0.0,)
    turn = 2 * math.pi if asset.has_front else math.pi  # a handle or a front makes the half turn another footprint
    return tuple(i * turn / PACKING_YAWS for i in range(PACKING_YAWS))


def _round_footprint(asset: Asset) -> bool:
    sx, sy, _ = asset.size
    return abs(sx - sy) < 0.05 * max(sx, sy)
