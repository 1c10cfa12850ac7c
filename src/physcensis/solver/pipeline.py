"""Program -> scene: check, resolve assets, solve the spatial part, and assemble the scene and its report."""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.assets.fallback import stand_in_info
from physcensis.assets.model import Asset
from physcensis.errors import PhyscensisError
from physcensis.ids import ROOT_ID, slug, unique_id
from physcensis.physics.engine import (
    AT_REST,
    DEFAULT_TOLERANCE,
    SETTLE_S,
    ObjectMotion,
    Tolerance,
    at_rest,
)
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.physics.profiles import MUJOCO_DEFAULT_TOLERANCE, UNDER_DEFAULTS
from physcensis.program import (
    DEFAULT_MAX_OBJECTS,
    CheckReport,
    ItemCount,
    Program,
    Relation,
    check_program,
    load_program,
    parse_program,
)
from physcensis.program.model import describe
from physcensis.program.registry import Effect, PlacementKind, YawMode, YawRule, handler_for, placement_spec
from physcensis.scene import (
    MAX_COORDINATE_M,
    MAX_PROMPT_CHARS,
    MAX_SEED,
    PlacedObject,
    Placement,
    Scene,
    Support,
    first_unusable_value,
)
from physcensis.solver.filling import ContainerFilling
from physcensis.solver.layout import PhysicalRequest, Pose2D
from physcensis.solver.objects import (
    copy_assets,
    object_rng,
    physical_properties,
    quaternion_yaw,
    resolve_assets,
    yaw_quaternion,
)
from physcensis.solver.physical import PhysicalSolver, PlaceOutcome, PlaceRequest
from physcensis.solver.spatial import SpatialResult, optimise_layout
from physcensis.solver.stability_search import KeptValue, refine_stability
from physcensis.solver.unmet import (
    OVERLAP_TOLERANCE,
    final_on_geometry,
    footprint_overlap,
    placement_changes,
    spatial_changes,
)

DEFAULT_SUPPORT = Support(kind="table", size=(1.2, 0.8))
NO_PHYSICS_REASON = "physics is off (physics=False, --no-physics), and the physical solver needs it"
VERIFY_ROUNDS = 8  # settle, fail what moved, settle again: a pile that lost objects needs a few rounds to rest
AT_REST_M = 0.001  # a verification settle that moved nothing more than this ends the verification
PLACE_IN = placement_spec(PlacementKind.IN).name
FINAL_CHECKS = 2  # how many times the final check under MuJoCo's defaults may fail objects (each time, settle again)
LONG_CREEP_S = 12.0  # how long what keeps creeping under MuJoCo's defaults is watched: a pile that slides apart falls
COUNTED_VARIANTS_CLOSE = 0.9  # a counted item's variants score this share of the best match or more (see variants)
CREPT_M = 0.0015  # under MuJoCo's defaults all sinks ~0.5 mm into its softer contacts; beyond this, it crept
# When a layout is not accepted, objects in these (or worse) overlaps or overhangs are the failed ones.
FAIL_OVERLAP_M2 = 0.5e-4
FAIL_OUTSIDE_M = 0.003  # settle, drop what failed, settle the rest again
MAX_REASONS = 6  # reasons named per failed object


@dataclass
class Solution:
    """Everything one solve produced: the scene, what went wrong, and the numbers."""

    scene: Scene
    check: CheckReport
    spatial: SpatialResult | None = None
    assets: dict[str, Asset] = field(default_factory=dict)
    pending: list[dict[str, Any]] = field(default_factory=list)
    timings: dict[str, float] = field(default_factory=dict)
    exports: dict[str, str] = field(default_factory=dict)  # format -> main file, relative to the output folder
    warnings: list[dict[str, Any]] = field(default_factory=list)  # requested values the scene does not hold

    @property
    def ok(self) -> bool:
        return self.check.ok and all(o.status == "placed" for o in self.scene.objects)

    def report(self) -> dict[str, Any]:
        objects = [
            {
                "id": o.id,
                "asset": o.asset,
                "category": o.category,
                "status": o.status,
                "reason": o.reason,
                "placement": o.placement.model_dump() if o.placement else None,
            }
            for o in self.scene.objects
        ]
        spatial = None
        if self.spatial is not None:
            s = self.spatial
            spatial = {
                "ok": s.ok,
                "overlap_cm2": round(s.overlap_m2 * 1e4, 4),
                "outside_cm": round(s.outside_m * 100, 3),
                "rounds": s.rounds,
                "evaluations": s.evaluations,
                "stop_reason": s.stop_reason,
                "params": {str(k): v for k, v in s.params.items()},
                "feedback": s.feedback(),
            }
        return {
            "ok": self.ok,
            "problems": [p.to_dict() for p in self.check.problems],
            "objects": objects,
            "pending": self.pending,
            "spatial": spatial,
            "metrics": self.scene.metrics,
            "timings_s": {k: round(v, 4) for k, v in self.timings.items()},
            "exports": self.exports,
            "fallbacks": self.fallbacks(),
            "warnings": self.warnings,
        }

    def fallbacks(self) -> list[dict[str, Any]]:
        """One row per noun the catalogue does not know: the stand-in it became and the objects that use it."""
        rows: dict[str, dict[str, Any]] = {}
        for o in self.scene.objects:
            asset = self.assets.get(o.id)
            info = stand_in_info(asset) if asset is not None else None
            if info is not None:
                rows.setdefault(info["note"], {**info, "objects": []})["objects"].append(o.id)
        return list(rows.values())

    def feedback(self) -> str:
        """What an agent needs to hear: grammar problems, then solver failures."""
        if not self.check.ok:
            return self.check.feedback()
        lines = [f"{o.id} failed: {o.reason}" for o in self.scene.objects if o.status == "failed"]
        if self.spatial is not None and not self.spatial.ok:
            lines.append(self.spatial.feedback())
        lines += [f"warning: {w['text']}" for w in self.warnings]
        return "\n".join(lines) or "every object was placed"


def as_program(source: Program | str | Path | list[Any] | dict[str, Any]) -> Program:
    if isinstance(source, Program):
        return source
    if isinstance(source, Path):
        return load_program(source)
    return parse_program(source)


def solve(
    source: Program | str | Path | list[Any] | dict[str, Any],
    *,
    support: Support | None = None,
    catalogue: Catalogue | None = None,
    seed: int = 0,
    prompt: str | None = None,
    physics: bool = True,
    tolerance: Tolerance = DEFAULT_TOLERANCE,
    engine: MujocoEngine | None = None,
    max_objects: int = DEFAULT_MAX_OBJECTS,
    time_limit_s: float | None = None,
) -> Solution:
    """Solve a program into a scene: check, spatial solve, then (with `physics`) let everything settle, realise
    the physical placements (PLACE-ON, PLACE-IN, PLACE-ANYWHERE) and fail what moves. Without `physics` the
    physical placements are reported as pending, unsolved. A program that makes more than `max_objects` objects is
    refused by the check (nothing is built). Once `time_limit_s` has passed (None: no limit) no further physical
    placement is tried: each left fails with the reason, and the scene is verified as it stands."""
    timings: dict[str, float] = {}
    start = time.perf_counter()
    deadline = None if time_limit_s is None else start + max(0.0, time_limit_s)
    _check_arguments(seed, prompt)
    program = as_program(source)
    support = support or program.support or DEFAULT_SUPPORT
    catalogue = catalogue or default_catalogue()
    report = check_program(program, support, max_objects=max_objects, assets=catalogue.id_set())
    timings["check"] = time.perf_counter() - start
    written = program.to_json()  # a program with errors may hold what no scene can (NaN, huge numbers): left out
    scene = Scene(
        seed=seed,
        prompt=prompt or program.prompt,
        support=support,
        program=written if report.ok or first_unusable_value(written) is None else [],
    )
    if not report.ok:
        return Solution(scene, report, timings=timings)

    t = time.perf_counter()
    assets = resolve_assets(program, catalogue)
    timings["assets"] = time.perf_counter() - t

    t = time.perf_counter()
    footprints = {oid: a.footprint() for oid, a in assets.items()}
    spatial = optimise_layout(program, support, footprints, seed=seed, deadline=deadline)
    timings["spatial"] = time.perf_counter() - t
    assets = copy_assets(assets, spatial.copies)

    failed = _spatial_failures(spatial)
    descriptions = {d.object_id: d.description for d in program.declarations}
    for copy, original in spatial.copies.items():
        descriptions[copy] = descriptions.get(original, copy)
    objects = []
    for oid, pose in spatial.poses.items():
        asset = assets[oid]
        mass, friction, com = physical_properties(asset, oid, seed)
        x, y = _within_scene(pose, oid, failed)
        objects.append(
            PlacedObject(
                id=oid,
                description=descriptions[oid],
                asset=asset.id,
                category=asset.category,
                position=(x, y, support.top_height),
                quaternion=yaw_quaternion(pose.yaw),
                mass=mass,
                friction=friction,
                com=com,
                placement=Placement(predicate=placement_spec(PlacementKind.BASE).name, target=ROOT_ID),
                status="failed" if oid in failed else "placed",
                reason=failed.get(oid),
            )
        )
    scene.objects = objects
    pending: list[dict[str, Any]] = []
    if physics:
        run = _PhysicalRun(
            PhysicalSolver(scene, engine or MujocoEngine(catalogue), seed=seed, tolerance=tolerance, deadline=deadline),
            spatial,
            assets,
            descriptions,
            catalogue,
            seed,
        )
        _physics(run, tolerance, timings)
    else:
        pending = [
            {
                "entry": r.relation.index,
                "predicate": r.relation.predicate,
                "objects": list(r.subject_ids) or [str(s) for s in r.relation.to_json()[0]],
                "target": r.target,
                "reason": NO_PHYSICS_REASON,
            }
            for r in spatial.pending
        ]
    timings["total"] = time.perf_counter() - start
    warnings = _warnings(program, spatial, scene.metrics.get("placements", []))
    scene.metrics |= {
        "objects_placed": sum(o.status == "placed" for o in scene.objects),
        "objects_failed": sum(o.status == "failed" for o in scene.objects),
        "objects_pending": len(pending),
        "overlap_cm2": round(spatial.overlap_m2 * 1e4, 4),
        "outside_cm": round(spatial.outside_m * 100, 3),
    }
    return Solution(scene, report, spatial, assets, pending, timings, warnings=warnings)


def _warnings(program: Program, spatial: SpatialResult, records: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Every explicit value the scene does not hold: requested, final, why (`solver/unmet.py` has the tolerances)."""
    changes = spatial_changes(program, spatial.params)
    for record in records:
        changes += placement_changes(record, record.get("requested", {}))
    return [c.to_dict() | {"text": c.text()} for c in changes]


@dataclass
class _PhysicalRun:
    """What realising a solve's physical placements needs."""

    solver: PhysicalSolver
    spatial: SpatialResult
    assets: dict[str, Asset]
    descriptions: dict[str, str]
    catalogue: Catalogue
    seed: int

    @property
    def scene(self) -> Scene:
        return self.solver.scene

    @property
    def engine(self) -> MujocoEngine:
        return self.solver.engine


def _physics(run: _PhysicalRun, tolerance: Tolerance, timings: dict[str, float]) -> None:
    """Settle the spatial layout, realise the physical placements, settle again and measure the settle distance."""
    scene, engine = run.scene, run.engine
    t = time.perf_counter()
    # A scene that came to rest and was not changed since is not verified twice; one whose only physical
    # placements are set down apart on the table top, beside a layout already standing apart, is verified once, after.
    deferred = _only_set_down(run)
    rested = deferred or verify(scene, engine, tolerance)
    timings["physics"] = time.perf_counter() - t
    t = time.perf_counter()
    outcomes = _solve_physical(run)
    timings["physical"] = time.perf_counter() - t
    t = time.perf_counter()
    if outcomes or not rested or deferred:
        verify(scene, engine, tolerance)
    timings["physics"] += time.perf_counter() - t
    failed = {o.id: o.reason for o in scene.objects if o.status == "failed"}
    for record in outcomes:
        if record["ok"] and record["object"] in failed:  # placed, then failed by the final verification
            record |= {"ok": False, "reason": failed[record["object"]]}
        if "requested" in record:  # a PLACE-ON record
            record |= _on_geometry(run, record)
    scene.metrics["placements"] = outcomes
    if scene.placed:
        t = time.perf_counter()
        distance = engine.settle_distance(scene, rest=AT_REST)  # a scene at rest is not watched for all 4 s
        timings["settle_distance"] = time.perf_counter() - t
        scene.metrics["settle_distance_m"] = round(distance.mean_m, 6)
        scene.metrics["settle_distance_requested_m"] = round(distance.over_requested(len(scene.objects)), 6)
        scene.metrics["settle_distance_per_object_m"] = {k: round(v, 6) for k, v in distance.per_object.items()}


# A physical handler places a request's objects; it returns their outcomes and extra fields for their records.
PhysicalHandler = Callable[["_PhysicalRun", PhysicalRequest], tuple[list[PlaceOutcome], dict[str, Any]]]


SPATIAL_APART_M2 = 1e-6  # a spatial layout overlapping less than this (0.01 cm^2 in all) stands apart


def _only_set_down(run: _PhysicalRun) -> bool:
    """Whether every physical placement is a plain PLACE-ANYWHERE on a table top (no stacking, packing, mess, overhang
    or stability asked: what the physical solver sets down apart from everything, `PhysicalSolver._set_down_apart`,
    or else confirms in a settle with its neighbours) and the spatial layout stands apart within the table. Such a
    scene's layout need not be settled before they are placed: the spatial solver stood each thing in its rest
    pose, and the one verification after them settles everything together."""
    spatial = run.spatial
    if run.scene.support.kind != "table" or not spatial.pending:
        return False
    if not spatial.ok or spatial.overlap_m2 > SPATIAL_APART_M2 or spatial.outside_m > 0.0:
        return False
    return all(
        _physical_handler(r) is _place_anywhere
        and r.target == ROOT_ID
        and r.relation.params.get("stack", True) is False
        and not (r.relation.params.get("pack") or r.relation.params.get("messy"))
        for r in spatial.pending
    )


def _solve_physical(run: _PhysicalRun) -> list[dict[str, Any]]:
    """The physical placements in program order, each by the handler of its effect; one record per object."""
    handlers = [(request, _physical_handler(request)) for request in run.spatial.pending]  # all known before work
    records: list[dict[str, Any]] = []
    for request, handler in handlers:
        outcomes, extra = handler(run, request)
        records += [_placement_record(request, outcome) | extra for outcome in outcomes]
    return records


def _physical_handler(request: PhysicalRequest) -> PhysicalHandler:
    spec = request.relation.spec
    if spec is None:
        raise PhyscensisError(f"entry #{request.relation.index}: unknown predicate {request.relation.predicate!r}")
    return handler_for(PHYSICAL_HANDLERS, spec)


def _placement_record(request: PhysicalRequest, outcome: PlaceOutcome) -> dict[str, Any]:
    return {
        "entry": request.relation.index,
        "predicate": request.relation.predicate,
        "object": outcome.object_id,
        "target": request.target,
        "ok": outcome.ok,
        "reason": outcome.reason,
        "tries": outcome.tries,
        "crowding": round(outcome.crowding, 3),
        "support_ratio": None if outcome.support_ratio is None else round(outcome.support_ratio, 3),
    }


ON_REQUESTS = ("overlap", "x_offset", "y_offset", "stability")


def _place_on(run: _PhysicalRun, request: PhysicalRequest) -> tuple[list[PlaceOutcome], dict[str, Any]]:
    """PLACE-ON: rest on the target; a wished stability is then searched for. The record keeps the requested
    values, and the overlap and offsets where the object was placed (the final ones are added after verifying)."""
    outcome = _place_one(run, request, PlacementKind.ON)
    params = request.relation.params
    extra: dict[str, Any] = {"requested": {k: params[k] for k in ON_REQUESTS if params.get(k) is not None}}
    stability = params.get("stability")
    if not outcome.ok:
        return [outcome], extra
    extra |= {
        f"{k}_placed": v for k, v in _on_geometry(run, {"object": outcome.object_id, "target": request.target}).items()
    }
    if stability is None:
        return [outcome], extra
    kept = _kept_overlap(run, outcome.object_id, request.target, params.get("overlap"))
    reached = refine_stability(run.scene, outcome.object_id, stability, run.engine, seed=run.seed, kept=kept)
    searched = reached.to_dict()
    searched = {
        k: searched[k]
        for k in ("target", "band", "reached", "p_fail", "p_fail_95", "effective_samples", "moved_m", "stop_reason")
    }
    return [outcome], extra | {
        "stability_target": stability,
        "p_fail": round(reached.p_fail, 4),
        "p_fail_95": searched["p_fail_95"],
        "reached": reached.reached,
        "stability": searched,
    }


def _kept_overlap(run: _PhysicalRun, object_id: str, target_id: str | None, requested: Any) -> KeptValue | None:
    """A PLACE-ON that asked for an overlap and a stability: the search keeps that overlap within the report's own
    tolerance (None when no overlap was asked)."""
    if requested is None or target_id is None:
        return None
    catalogue = run.engine.catalogue
    obj, target = run.scene.object(object_id), run.scene.object(target_id)
    asset = catalogue.asset_for(obj.asset, obj.description)
    target_asset = catalogue.asset_for(target.asset, target.description)

    def measure(objects: list[PlacedObject]) -> float:
        by_id = {o.id: o for o in objects}
        return footprint_overlap(by_id[object_id], asset, by_id[target_id], target_asset)

    return KeptValue("overlap", float(requested), OVERLAP_TOLERANCE, measure)


def _on_geometry(run: _PhysicalRun, record: dict[str, Any]) -> dict[str, float]:
    """The overlap and x/y offsets of a PLACE-ON object on its target as the scene holds them (nothing when either
    is not placed)."""
    placed = {o.id: o for o in run.scene.placed}
    obj, target = placed.get(record.get("object", "")), placed.get(record.get("target") or "")
    if obj is None or target is None:
        return {}
    catalogue = run.engine.catalogue
    return final_on_geometry(
        obj,
        catalogue.asset_for(obj.asset, obj.description),
        target,
        catalogue.asset_for(target.asset, target.description),
    )


def _place_anywhere(run: _PhysicalRun, request: PhysicalRequest) -> tuple[list[PlaceOutcome], dict[str, Any]]:
    return [_place_one(run, request, PlacementKind.ANYWHERE)], {}


def _place_in(run: _PhysicalRun, request: PhysicalRequest) -> tuple[list[PlaceOutcome], dict[str, Any]]:
    items = _place_in_items(request, request.relation, run.assets, run.descriptions, run.catalogue, run.seed, run.scene)
    return ContainerFilling(run.solver).place_in(items, request.target, predicate=request.relation.predicate), {}


# The physical solver's handler table: how each physical effect is realised (tests/program/test_conformance.py
# checks that every physical effect has one).
PHYSICAL_HANDLERS: Mapping[Effect, PhysicalHandler] = {
    Effect.ON: _place_on,
    Effect.IN: _place_in,
    Effect.ANYWHERE: _place_anywhere,
}


def _place_one(run: _PhysicalRun, request: PhysicalRequest, kind: PlacementKind) -> PlaceOutcome:
    """Place the request's one object by the voxel search, confirmed in physics."""
    rel = request.relation
    oid = request.subject_ids[0]
    original = spatial_original(oid, request)
    params = rel.params
    stability = params.get("stability")
    return run.solver.place(
        PlaceRequest(
            object_id=oid,
            description=run.descriptions.get(oid, run.descriptions.get(original, oid)),
            asset=run.assets.get(oid) or run.assets[original],
            kind=kind,
            target=request.target,
            x_offset=params.get("x_offset"),
            y_offset=params.get("y_offset"),
            overlap=params.get("overlap"),
            stability=stability.lower() if isinstance(stability, str) else stability,
            messy=bool(params.get("messy", False)),
            stack=bool(params.get("stack", True)),
            pack=bool(params.get("pack", False)) and not params.get("messy", False),  # messy: scattered
            yaws=_yaw_hint(run.spatial.yaw_rules.get(oid, []), run.scene),
            predicate=rel.predicate,
        )
    )


def spatial_original(object_id: str, request: PhysicalRequest) -> str:
    return request.copied_from or object_id.split("-group_")[0]


def _yaw_hint(rules: list[Relation], scene: Scene) -> tuple[float, ...] | None:
    """The yaw a physically placed object's own yaw rules ask for, when it can be known in advance (the last rule
    that knows wins)."""
    yaw = None
    placed = {o.id: o for o in scene.placed}
    for rel in rules:
        spec = rel.spec
        if spec is None or spec.yaw is None:
            continue
        hint = handler_for(YAW_HINTS, spec, spec.yaw.mode)(spec.yaw, rel, placed)
        if hint is not None:
            yaw = hint
    return None if yaw is None else (yaw,)


def _target_yaw(rel: Relation, placed: Mapping[str, PlacedObject]) -> float | None:
    """The yaw of the rule's target: 0 for the support, None for an object not (yet) placed."""
    if rel.target == ROOT_ID:
        return 0.0
    return quaternion_yaw(placed[rel.target].quaternion) if rel.target in placed else None


def _offset(rel: Relation) -> float:
    return float(rel.params.get("yaw_offset", 0.0))


def _absolute_hint(rule: YawRule, rel: Relation, placed: Mapping[str, PlacedObject]) -> float | None:
    return rule.angle + _offset(rel)


def _same_hint(rule: YawRule, rel: Relation, placed: Mapping[str, PlacedObject]) -> float | None:
    base = _target_yaw(rel, placed)
    return None if base is None else base + _offset(rel)


def _opposite_hint(rule: YawRule, rel: Relation, placed: Mapping[str, PlacedObject]) -> float | None:
    base = _target_yaw(rel, placed)
    return None if base is None else base + _offset(rel) + math.pi


def _no_hint(rule: YawRule, rel: Relation, placed: Mapping[str, PlacedObject]) -> float | None:
    """A yaw that depends on where the object ends up, or a random one: the search tries yaws of its own."""
    return None


# The yaw each mode asks of a physically placed object, as far as it is known before the object is placed.
# Every YawMode has an entry (tests/program/test_conformance.py checks it): `_no_hint` when it cannot be known.
YAW_HINTS: Mapping[YawMode, Callable[[YawRule, Relation, Mapping[str, PlacedObject]], float | None]] = {
    YawMode.ABSOLUTE: _absolute_hint,
    YawMode.SAME: _same_hint,
    YawMode.OPPOSITE: _opposite_hint,
    YawMode.TOWARD: _no_hint,
    YawMode.RANDOM: _no_hint,
    YawMode.RELATIVE_SIDE: _no_hint,
}


def _place_in_items(
    request: PhysicalRequest,
    rel: Relation,
    assets: dict[str, Asset],
    descriptions: dict[str, str],
    catalogue: Catalogue,
    seed: int,
    scene: Scene,
) -> list[tuple[str, str, Asset]]:
    """(id, description, asset) of every item a PLACE-IN drops: declared ids, or new objects by category."""
    items: list[tuple[str, str, Asset]] = []
    taken = {o.id for o in scene.objects} | set(assets)
    subjects = rel.subject if isinstance(rel.subject, tuple) else (rel.subject,)
    suffix = request.target
    for subject in subjects:
        if isinstance(subject, ItemCount):
            variants = catalogue.variants(subject.category, close=COUNTED_VARIANTS_CLOSE)
            name = slug(subject.category)
            for _ in range(subject.count):
                oid = unique_id([name, suffix], taken)  # any category text gives a valid id
                taken.add(oid)
                asset = variants[int(object_rng(seed, oid).integers(len(variants)))]
                items.append((oid, f"{subject.category} ({asset.description})", asset))
        else:
            oid = str(subject)
            items.append((oid, descriptions.get(oid, oid), assets[oid]))
    return items


def verify(scene: Scene, engine: MujocoEngine, tolerance: Tolerance) -> bool:
    """Let the placed objects fall, under our contact settings and under MuJoCo's defaults; those that move too far
    under either fail, the rest take their settled poses (settling again while anything still creeps, so the
    written scene is at rest under both). Last, the scene as it would be written settles under the defaults alone,
    round after round as a user's simulator would run it: what moves or turns too far there fails too (a
    container's contents excepted), and the rest is verified again. True when it ended with the scene at rest (not
    when it ran out of rounds)."""
    strict = engine.defaults_check()
    rested = False
    for check in range(FINAL_CHECKS + 1):
        max_depth, rested = _settle_rounds(scene, engine, strict, tolerance)
        if strict is None or check == FINAL_CHECKS:
            break
        if not _fail_moved(scene, _lost_under_defaults(scene, strict, tolerance)):
            break
        rested = False
    scene.metrics["max_penetration_mm"] = round(max_depth * 1000, 3)
    return rested


def _settle_rounds(
    scene: Scene, engine: MujocoEngine, strict: MujocoEngine | None, tolerance: Tolerance
) -> tuple[float, bool]:
    """Verification's settle rounds under ours (and the defaults' check of each); the deepest penetration of the
    last settle, and whether the rounds ended at rest (not by running out)."""
    max_depth = 0.0
    before: dict[str, PlacedObject] = {}  # objects moved to where they crept under the defaults, as they were
    tried: set[str] = set()  # ... and every object that was (it is not moved there twice)
    for _ in range(VERIFY_ROUNDS):
        if not scene.placed:
            return max_depth, True
        result = engine.settle(scene, tolerance=tolerance)
        max_depth = result.max_penetration_m
        if _undo_creep(scene, result.failed, before):
            continue
        if _fail_moved(scene, result.failed):
            continue
        crept: dict[str, ObjectMotion] = {}
        if strict is not None:
            loose = strict.settle(scene, tolerance=MUJOCO_DEFAULT_TOLERANCE, duration_s=SETTLE_S)
            if _fail_moved(scene, loose.failed, f"{UNDER_DEFAULTS}: "):
                continue
            # What creeps again after it was given the pose it crept to may be on its way down (a pile sliding apart
            # over several seconds) or settling slowly (fruit rolling into a bowl's hollow): a longer settle tells.
            # A container's contents are not watched: pencils leaning in a mug slide a centimetre deeper under the
            # defaults and are still in it.
            contents = _contents(scene)
            watched = [m for m in loose.objects.values() if m.id not in contents]
            if any(m.translation_m > CREPT_M and m.id in tried for m in watched):
                longer = strict.settle(scene, tolerance=MUJOCO_DEFAULT_TOLERANCE, duration_s=LONG_CREEP_S)
                fell = [replace(m, reason=_kept_creeping(m)) for m in longer.failed if m.id not in contents]
                if _fail_moved(scene, fell):
                    continue
            # What still crept under the defaults (a fruit rolling into its bowl's hollow) takes the pose it found,
            # once; if that pose does not rest under ours (a pen leaning in a holder), it goes back.
            crept = {
                m.id: m
                for m in loose.objects.values()
                if m.translation_m > CREPT_M and m.id not in tried and m.rotation_rad <= tolerance.rotation_rad
            }
            before.update({o.id: o for o in scene.objects if o.id in crept})
            tried.update(crept)
        if not crept and max(m.translation_m for m in result.objects.values()) < AT_REST_M:
            # This settle confirmed the poses it started from: they are what is written, and the settle distance
            # and the final check under the defaults start from them too (the settles already simulated).
            return max(m.initial_penetration_m for m in result.objects.values()), True
        scene.objects = at_rest(scene.objects, {**result.objects, **crept})
    return max_depth, False


def _lost_under_defaults(scene: Scene, strict: MujocoEngine, tolerance: Tolerance) -> list[ObjectMotion]:
    """The objects that a copy of the scene first loses when it is verified under MuJoCo's defaults alone, each
    round taking the poses the last one settled to, with the rounds `bench clutter` measures a delivered scene by:
    what moves or turns too far in a round (a tall bottle on a can tilted over a fork turns a few degrees every round
    and falls in the third). A container's contents are not failed (pencils lean a little deeper into their mug)."""
    trial = scene.model_copy(deep=True)
    contents = _contents(trial)
    seconds = 0.0
    for _ in range(VERIFY_ROUNDS):
        if not trial.placed:
            break
        result = strict.settle(trial, tolerance=tolerance)
        seconds += result.simulated_s
        if lost := [m for m in result.failed if m.id not in contents]:
            return [replace(m, reason=f"{UNDER_DEFAULTS}, within {seconds:g} s: {m.reason}") for m in lost]
        trial.objects = at_rest(trial.objects, result.objects)
        if max(m.translation_m for m in result.objects.values()) < AT_REST_M:
            break
    return []


def _contents(scene: Scene) -> set[str]:
    """The objects placed in a container (PLACE-IN)."""
    return {o.id for o in scene.objects if o.placement is not None and o.placement.predicate == PLACE_IN}


def _kept_creeping(motion: ObjectMotion) -> str:
    return (
        f"{UNDER_DEFAULTS} it kept creeping and moved {motion.translation_m * 100:.1f} cm "
        f"in {LONG_CREEP_S:g} s: it would not stay where it was put"
    )


def _undo_creep(scene: Scene, moved: list[ObjectMotion], before: dict[str, PlacedObject]) -> bool:
    """When an object that was moved to where it crept under the defaults then moves under ours, put back every
    object moved so, as it was (they crept together, into each other: pencils leaning in a mug), and return True;
    each is put back once. What else moved is not failed yet: it may have been pushed by them."""
    if not any(m.id in before for m in moved):
        return False
    scene.objects = [before.pop(o.id) if o.id in before else o for o in scene.objects]
    return True


def _fail_moved(scene: Scene, moved: list[ObjectMotion], prefix: str = "") -> bool:
    """Mark the objects that moved as failed, with why; True if there were any."""
    failed = {m.id: m for m in moved}
    scene.objects = [
        o.model_copy(update={"status": "failed", "reason": prefix + str(failed[o.id].reason)}) if o.id in failed else o
        for o in scene.objects
    ]
    return bool(failed)


def _spatial_failures(spatial: SpatialResult) -> dict[str, str]:
    """A reason for every object the spatial diagnosis names, when the layout was not accepted."""
    if spatial.ok:
        return {}
    reasons: dict[str, list[str]] = {}
    for o in spatial.overlaps:
        if o.area_m2 < FAIL_OVERLAP_M2:
            continue
        reasons.setdefault(o.a, []).append(f"overlaps {o.b} by {o.area_m2 * 1e4:.1f} cm^2")
        reasons.setdefault(o.b, []).append(f"overlaps {o.a} by {o.area_m2 * 1e4:.1f} cm^2")
    for s in spatial.outside:
        if s.distance_m < FAIL_OUTSIDE_M:
            continue
        reasons.setdefault(s.object, []).append(f"sticks out {s.distance_m * 100:.1f} cm past the {s.side} edge")
    return {oid: _joined(words) for oid, words in reasons.items()}


def _joined(reasons: list[str]) -> str:
    """Reasons as one line; an object in a pile of hundreds names the worst few and counts the rest."""
    if len(reasons) <= MAX_REASONS:
        return "; ".join(reasons)
    return "; ".join(reasons[:MAX_REASONS]) + f"; and {len(reasons) - MAX_REASONS} more"


def _within_scene(pose: Pose2D, oid: str, failed: dict[str, str]) -> tuple[float, float]:
    """The pose's x, y; one beyond what a scene may hold (a chain of mirrors far off the support) fails the object
    and is clipped to the scene's bounds, so the scene can still be written."""
    x, y = pose.x, pose.y
    if abs(x) <= MAX_COORDINATE_M and abs(y) <= MAX_COORDINATE_M:
        return x, y
    note = f"ends up far outside any scene (x = {x:.4g} m, y = {y:.4g} m; recorded clipped to ±{MAX_COORDINATE_M:g} m)"
    failed[oid] = f"{failed[oid]}; {note}" if oid in failed else note
    return _clip_coordinate(x), _clip_coordinate(y)


def _clip_coordinate(value: float) -> float:
    return 0.0 if math.isnan(value) else max(-MAX_COORDINATE_M, min(MAX_COORDINATE_M, value))


def _check_arguments(seed: int, prompt: str | None) -> None:
    if isinstance(seed, bool) or not isinstance(seed, int) or not 0 <= seed < MAX_SEED:
        raise PhyscensisError(f"seed must be a whole number from 0 to {MAX_SEED - 1}, got {describe(seed)}")
    if prompt is not None and len(prompt) > MAX_PROMPT_CHARS:
        raise PhyscensisError(f"the prompt is {len(prompt)} characters long; the limit is {MAX_PROMPT_CHARS}")
