"""The methods a comparison runs, behind one interface and selected by name.

* `ours`: the full loop (offline planner, or `--llm`).
* `no-feedback`: the loop's agent hears only whether a round succeeded; with nothing to act on, a deterministic agent
  resamples (each attempt is solved with a fresh seed).
* `no-report`: the loop's agent hears everything but the empty-region report (crowding and empty regions).
* `visual`: the full loop, and a vision model (`--vlm`) looks at every solved round's render: its VQA score and its
  own words on what does not match the prompt join the feedback. (`ours` and `no-report` hear the score alone when
  a VLM is given; `no-feedback` hears nothing of it.)
* `random`: the objects of the agent's first program, each stood on the support at a random spot and yaw; the spatial
  solver only pulls them apart (no predicates).
* `llm-only` (the paper's): the model writes every object's pose as coordinates (`evaluation/llm_layout.py`), for
  the objects of the agent's first program; no predicates, no solver; then physics-checked like any scene. Without
  an LLM no model can write poses, and `program-frozen`'s scene stands in (said in method.json).
* `program-frozen`: the positions the agent's first program asks for, frozen: its entries evaluated once with the
  values written (no solver search), things put on, in or anywhere at the spot the program names or a seeded one;
  then physics-checked like any scene.

Every method's scene keeps, as its program, the program it is judged against (for the baselines, the agent's first
program), so `eval relations` scores any of them; the program a baseline was really solved from is in method.json.
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from physcensis.agent.base import Agent, AgentContext, Round
from physcensis.agent.factory import llm_agent
from physcensis.agent.loop import GenerateResult
from physcensis.api import Generated, generate
from physcensis.assets.catalogue import Catalogue
from physcensis.assets.model import Asset
from physcensis.errors import PhyscensisError
from physcensis.ids import ROOT_ID, slug, unique_id
from physcensis.program import ItemCount, Program, check_program, parse_program
from physcensis.program.registry import PlacementKind, placement_spec
from physcensis.scene import PlacedObject, Placement, Scene, Support
from physcensis.settings import DEFAULT_TIME_BUDGET_S, BudgetSettings, ModelSettings, RunSettings
from physcensis.solver.layout import PhysicalRequest
from physcensis.solver.objects import copy_assets, physical_properties, resolve_assets, yaw_quaternion
from physcensis.solver.pipeline import Solution, solve
from physcensis.solver.spatial import optimise_layout

BINARY_FAILURE = "The program failed."
BINARY_SUCCESS = "The program succeeded."
MAX_ATTEMPTS = 4  # the loop's first try and its three retries
RESAMPLE_SEED_STEP = 7919  # the seed of attempt k is seed + k * this


@dataclass(frozen=True)
class MethodTask:
    """One scene to make: the prompt, its support and seed, and the LLM when one writes the programs."""

    prompt: str
    support: Support
    seed: int
    models: ModelSettings = field(default_factory=ModelSettings)  # the LLM (None: the offline planner) and the VLM
    time_budget_s: float | None = DEFAULT_TIME_BUDGET_S


@dataclass
class MethodOutput:
    """What a method made: the generate record (its solution may be None), the program it is judged against, what
    it was really solved from, and its effort (programs solved, agent rounds, seconds)."""

    generated: Generated
    judged_program: list[Any]
    solved_program: list[Any] | None
    attempts: int
    rounds: int
    seconds: float
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def solution(self) -> Solution | None:
        return self.generated.solution


Method = Callable[[MethodTask, Catalogue], MethodOutput]


_PLANNERS: dict[int, tuple[Catalogue, Agent]] = {}  # reading the catalogue's vocabulary takes a second or more


def _agent(task: MethodTask, catalogue: Catalogue, hint: str = "auto") -> Agent:
    """The LLM agent (shown the offline reading's draft as `hint` says), or the offline planner of this catalogue
    (one per process: it draws its open choices from each run's seed, and keeps nothing between plans but what it
    says in the transcript, cleared here)."""
    if task.models.llm:
        return llm_agent(replace(task.models, hint=hint), catalogue)
    from physcensis.agent.planner import OfflinePlanner

    kept = _PLANNERS.get(id(catalogue))
    if kept is None or kept[0] is not catalogue:
        kept = _PLANNERS[id(catalogue)] = (catalogue, OfflinePlanner(catalogue, seed=task.seed))
    planner = kept[1]
    planner.transcript_notes = []  # type: ignore[attr-defined]  # the planner's, said once per run
    return planner


def _loop_output(generated: Generated, started: float) -> MethodOutput:
    result = generated.result
    attempts = sum("program" in row for row in result.transcript)
    program = generated.solution.scene.program if generated.solution else []
    return MethodOutput(generated, program, program, attempts, result.rounds, time.perf_counter() - started)


def run_ours(task: MethodTask, catalogue: Catalogue) -> MethodOutput:
    return _run_loop(task, catalogue, _agent(task, catalogue), "score")


def run_visual(task: MethodTask, catalogue: Catalogue) -> MethodOutput:
    if not task.models.vlm:
        raise PhyscensisError("the visual method needs a vision model: give --vlm MODEL (and --vlm-base-url)")
    return _run_loop(task, catalogue, _agent(task, catalogue), "remarks")


def _run_loop(task: MethodTask, catalogue: Catalogue, agent: Agent, vlm_feedback: str) -> MethodOutput:
    """The generate loop with `agent`; with a VLM, its judgement of each solved round is fed back as said."""
    started = time.perf_counter()
    generated = generate(
        task.prompt,
        support=task.support,
        agent=agent,
        seed=task.seed,
        catalogue=catalogue,
        settings=RunSettings(
            models=replace(task.models, vlm_feedback=vlm_feedback),
            budget=BudgetSettings(time_budget_s=task.time_budget_s),
        ),
    )
    return _loop_output(generated, started)


class WithoutReport:
    """An agent that hears the loop's feedback without the empty-region report (crowding and empty regions)."""

    def __init__(self, inner: Agent) -> None:
        self.inner = inner
        self.name = f"{getattr(inner, 'name', 'agent')} (no report)"

    def propose(self, context: AgentContext) -> str:
        history = tuple(replace(r, feedback=without_report(r.feedback)) for r in context.history)
        return self.inner.propose(replace(context, history=history))


def without_report(feedback: str) -> str:
    """The feedback text without its lines on crowding and empty regions."""
    return "\n".join(line for line in feedback.splitlines() if not _region_line(line))


def _region_line(line: str) -> bool:
    text = line.strip()
    return text.startswith("There is ") or (text.startswith("The ") and "% of its top is covered" in text)


def run_no_report(task: MethodTask, catalogue: Catalogue) -> MethodOutput:
    return _run_loop(task, catalogue, WithoutReport(_agent(task, catalogue)), "score")


def run_no_feedback(task: MethodTask, catalogue: Catalogue) -> MethodOutput:
    """Attempts until one succeeds (at most MAX_ATTEMPTS); the agent hears only 'succeeded' or 'failed', and each
    attempt is solved with its own seed (the only thing a deterministic agent can change without feedback)."""
    started = time.perf_counter()
    agent = _agent(task, catalogue)
    history: list[Round] = []
    transcript: list[dict[str, Any]] = []
    best: Solution | None = None
    for attempt in range(MAX_ATTEMPTS):
        context = AgentContext(
            task.prompt,
            task.support,
            tuple(catalogue.categories()),
            tuple(history),
            "repair" if history else "create",
            seed=task.seed,
        )
        text = agent.propose(context)
        solution = _solve_text(text, task, catalogue, task.seed + attempt * RESAMPLE_SEED_STEP)
        ok = solution is not None and solution.ok
        history.append(Round(text, BINARY_SUCCESS if ok else BINARY_FAILURE, ok))
        transcript.append({"round": attempt + 1, "agent": agent.name, "program": text, "feedback_kind": str(ok)})
        if solution is not None and (best is None or (solution.ok, len(solution.scene.placed)) > _rank(best)):
            best = solution
        if ok:
            break
    seconds = time.perf_counter() - started
    result = GenerateResult(best, transcript, len(transcript), seconds, "done" if best and best.ok else "retries")
    generated = Generated(result, task.prompt, task.support)
    program = best.scene.program if best else []
    return MethodOutput(generated, program, program, len(transcript), len(transcript), seconds)


def _rank(solution: Solution) -> tuple[bool, int]:
    return solution.ok, len(solution.scene.placed)


def _solve_text(text: str, task: MethodTask, catalogue: Catalogue, seed: int) -> Solution | None:
    try:
        program = parse_program(text)
    except PhyscensisError:
        return None
    if not check_program(program, task.support, assets=catalogue.id_set()).ok:
        return None
    return solve(program, support=task.support, seed=seed, catalogue=catalogue, prompt=task.prompt)


def first_program(task: MethodTask, catalogue: Catalogue) -> Program:
    """The agent's first program for the prompt, checked (a baseline has nothing to run without one). An LLM gets no
    draft: the draft's positions come from our solver, which the baselines do without."""
    agent = _agent(task, catalogue, hint="off")
    context = AgentContext(task.prompt, task.support, tuple(catalogue.categories()), seed=task.seed)
    program = parse_program(agent.propose(context))
    report = check_program(program, task.support, assets=catalogue.id_set())
    if not report.ok:
        raise PhyscensisError(f"the agent's first program does not check: {report.summary()}")
    return program


# -- random --------------------------------------------------------------------------------------------------------


def object_list(program: Program, catalogue: Catalogue, seed: int) -> list[tuple[str, str, Asset]]:
    """(id, description, asset) of every object the program makes: declarations, the copies of copied groups and
    the items PLACE-IN makes by category (named as the solver names them)."""
    assets = resolve_assets(program, catalogue)
    descriptions = {d.object_id: d.description for d in program.declarations}
    layout = optimise_layout(program, Support(kind="table", size=(50.0, 50.0)), _prints(assets), seed, rounds=0)
    assets = copy_assets(assets, layout.copies)
    ids = list(layout.poses) + [oid for r in layout.pending for oid in r.subject_ids if oid not in layout.poses]
    objects = [(oid, descriptions.get(oid) or descriptions[layout.copies[oid]], assets[oid]) for oid in ids]
    taken = set(ids)
    for request in layout.pending:
        for category, count in _counted(request):
            for _ in range(count):
                oid = unique_id([slug(category), request.target], taken)
                taken.add(oid)
                objects.append((oid, category, catalogue.resolve(category)))
    return objects


def _prints(assets: dict[str, Asset]) -> dict[str, np.ndarray]:
    return {oid: a.footprint() for oid, a in assets.items()}


def _counted(request: PhysicalRequest) -> list[tuple[str, int]]:
    subject = request.relation.subject
    subjects = subject if isinstance(subject, tuple) else (subject,)
    return [(s.category, s.count) for s in subjects if isinstance(s, ItemCount)]


def random_program(objects: list[tuple[str, str, Asset]], support: Support, seed: int) -> list[list[Any]]:
    """Each object stood on the support at a uniform random spot (its footprint inside) and a random yaw."""
    rng = np.random.default_rng([seed, 17])
    hx, hy = support.half_extents
    base, turn = placement_spec(PlacementKind.BASE).name, "RANDOM-ROT"
    entries: list[list[Any]] = []
    for oid, description, asset in objects:
        reach = float(np.max(np.linalg.norm(asset.footprint(), axis=1)))
        x = float(rng.uniform(-1, 1) * max(hx - reach, 0.0))
        y = float(rng.uniform(-1, 1) * max(hy - reach, 0.0))
        entries += [[oid, description], [oid, base, ROOT_ID, {"x": round(x, 4), "y": round(y, 4)}]]
        entries.append([oid, turn, ROOT_ID, {}])
    return entries


def run_random(task: MethodTask, catalogue: Catalogue) -> MethodOutput:
    started = time.perf_counter()
    program = first_program(task, catalogue)
    entries = random_program(object_list(program, catalogue, task.seed), task.support, task.seed)
    solution = solve(entries, support=task.support, seed=task.seed, catalogue=catalogue, prompt=task.prompt)
    return _baseline_output(task, program, entries, solution, started)


def _baseline_output(
    task: MethodTask, judged: Program, solved: list[Any], solution: Solution, started: float
) -> MethodOutput:
    solution.scene.program = judged.to_json()
    seconds = time.perf_counter() - started
    row = {"round": 1, "agent": "baseline", "program": json.dumps(solved), "feedback_kind": str(solution.ok)}
    result = GenerateResult(solution, [row], 1, seconds)
    return MethodOutput(Generated(result, task.prompt, task.support), judged.to_json(), solved, 1, 1, seconds)


# -- llm-only ------------------------------------------------------------------------------------------------------


@dataclass
class _Frozen:
    """The poses the program asks for, built up entry by entry: (x, y, z, yaw) and asset per object."""

    support: Support
    rng: np.random.Generator
    poses: dict[str, tuple[float, float, float, float]] = field(default_factory=dict)
    assets: dict[str, Asset] = field(default_factory=dict)
    descriptions: dict[str, str] = field(default_factory=dict)
    placements: dict[str, Placement] = field(default_factory=dict)

    def top(self, oid: str) -> float:
        return self.poses[oid][2] + float(self.assets[oid].size[2])


def frozen_scene(program: Program, task: MethodTask, catalogue: Catalogue) -> tuple[Scene, dict[str, Asset]]:
    """The scene at the positions the program asks for, with no solver search: the spatial entries evaluated once
    with the values written; PLACE-ON at the target's centre plus the offsets written, on its top; PLACE-IN items
    in a ring inside the container's opening, on its floor; PLACE-ANYWHERE at a seeded spot on the support."""
    frozen = _Frozen(task.support, np.random.default_rng([task.seed, 23]))
    assets = resolve_assets(program, catalogue)
    layout = optimise_layout(program, task.support, _prints(assets), task.seed, rounds=0)
    frozen.assets = copy_assets(assets, layout.copies)
    frozen.descriptions = {d.object_id: d.description for d in program.declarations}
    pending = {oid for r in layout.pending for oid in r.subject_ids}
    for oid, pose in layout.poses.items():
        frozen.descriptions.setdefault(oid, frozen.descriptions.get(layout.copies.get(oid, ""), oid))
        if oid not in pending:
            frozen.poses[oid] = (pose.x, pose.y, task.support.top_height, pose.yaw)
            frozen.placements[oid] = Placement(predicate=placement_spec(PlacementKind.BASE).name, target=ROOT_ID)
    for request in layout.pending:
        yaws = {oid: layout.poses[oid].yaw for oid in request.subject_ids if oid in layout.poses}
        FROZEN_PLACEMENTS[request.relation.spec.placement if request.relation.spec else None](
            frozen, request, yaws, catalogue
        )
    return _scene_of(frozen, task), frozen.assets


def _freeze_on(frozen: _Frozen, request: PhysicalRequest, yaws: dict[str, float], catalogue: Catalogue) -> None:
    target = request.target
    if target not in frozen.poses:
        return
    tx, ty, _, tyaw = frozen.poses[target]
    dx, dy = (float(request.relation.params.get(k) or 0.0) for k in ("x_offset", "y_offset"))
    for oid in request.subject_ids:
        frozen.poses[oid] = (tx + dx, ty + dy, frozen.top(target), yaws.get(oid, tyaw))
        frozen.placements[oid] = Placement(predicate=request.relation.predicate, target=target)


def _freeze_in(frozen: _Frozen, request: PhysicalRequest, yaws: dict[str, float], catalogue: Catalogue) -> None:
    target = request.target
    if target not in frozen.poses:
        return
    items = [(oid, frozen.assets[oid]) for oid in request.subject_ids if oid in frozen.assets]
    for category, count in _counted(request):
        for _ in range(count):
            oid = unique_id([slug(category), target], set(frozen.assets))
            frozen.assets[oid], frozen.descriptions[oid] = catalogue.resolve(category), category
            items.append((oid, frozen.assets[oid]))
    tx, ty, tz, _ = frozen.poses[target]
    cavity = frozen.assets[target].cavity
    floor = tz + (cavity.floor_height if cavity is not None else float(frozen.assets[target].size[2]))
    radius = 0.3 * float(min(frozen.assets[target].size[:2])) / 2
    for k, (oid, _asset) in enumerate(items):
        angle = 2 * math.pi * k / max(1, len(items))
        frozen.poses[oid] = (tx + radius * math.cos(angle), ty + radius * math.sin(angle), floor, 0.0)
        frozen.placements[oid] = Placement(predicate=request.relation.predicate, target=target)


def _freeze_anywhere(frozen: _Frozen, request: PhysicalRequest, yaws: dict[str, float], catalogue: Catalogue) -> None:
    hx, hy = frozen.support.half_extents
    for oid in request.subject_ids:
        x, y = (float(v) for v in frozen.rng.uniform(-1, 1, 2) * np.array([hx, hy]) * 0.8)
        yaw = float(frozen.rng.uniform(-math.pi, math.pi))
        frozen.poses[oid] = (x, y, frozen.support.top_height, yaw)
        frozen.placements[oid] = Placement(predicate=request.relation.predicate, target=ROOT_ID)


FrozenPlacement = Callable[[_Frozen, PhysicalRequest, dict[str, float], Catalogue], None]
FROZEN_PLACEMENTS: dict[PlacementKind | None, FrozenPlacement] = {
    PlacementKind.ON: _freeze_on,
    PlacementKind.IN: _freeze_in,
    PlacementKind.ANYWHERE: _freeze_anywhere,
    PlacementKind.BASE: _freeze_anywhere,
    None: _freeze_anywhere,
}


def _scene_of(frozen: _Frozen, task: MethodTask) -> Scene:
    objects = []
    for oid, (x, y, z, yaw) in frozen.poses.items():
        asset = frozen.assets[oid]
        mass, friction, com = physical_properties(asset, oid, task.seed)
        objects.append(
            PlacedObject(
                id=oid,
                description=frozen.descriptions.get(oid, oid),
                asset=asset.id,
                category=asset.category,
                position=(x, y, z),
                quaternion=yaw_quaternion(yaw),
                mass=mass,
                friction=friction,
                com=com,
                placement=frozen.placements.get(oid),
            )
        )
    return Scene(seed=task.seed, prompt=task.prompt, support=task.support, objects=objects)


def run_program_frozen(task: MethodTask, catalogue: Catalogue) -> MethodOutput:
    started = time.perf_counter()
    program = first_program(task, catalogue)
    scene, assets = frozen_scene(program, task, catalogue)
    solved = [[o.id, o.description] for o in scene.objects] + [
        [o.id, "AT", ROOT_ID, {"position": list(o.position), "quaternion": list(o.quaternion)}] for o in scene.objects
    ]
    report = check_program(program, task.support, assets=catalogue.id_set())
    solution = Solution(scene, report, assets={o.id: assets[o.id] for o in scene.objects})
    return _baseline_output(task, program, solved, solution, started)


# -- llm-only: the model writes the poses --------------------------------------------------------------------------

OFFLINE_STAND_IN = "no LLM: no model writes poses, so the offline planner's first program, frozen, stands in"


def run_llm_only(task: MethodTask, catalogue: Catalogue) -> MethodOutput:
    """The paper's LLM-only: the model writes each object's pose; the scene is checked, never solved."""
    if not task.models.llm:
        output = run_program_frozen(task, catalogue)
        output.extra["stand_in"] = OFFLINE_STAND_IN
        return output
    from physcensis.evaluation import llm_layout

    started = time.perf_counter()
    program = first_program(task, catalogue)
    objects = object_list(program, catalogue, task.seed)
    ids = [oid for oid, _, _ in objects]
    agent = llm_agent(replace(task.models, hint="off"), catalogue)
    chat = llm_layout.layout_messages(task.prompt, task.support, objects)
    poses: dict[str, llm_layout.Pose] = {}
    problems: list[str] = []
    for attempt in range(llm_layout.ATTEMPTS):
        reply = agent.reply_with_schema(chat, llm_layout.layout_schema(ids), "layout", task.seed * 1009 + attempt)
        try:
            poses, problems = llm_layout.read_layout(reply, ids)
        except llm_layout.LayoutReplyError as exc:
            poses, problems = {}, [str(exc)]
        if not problems:
            break
        chat += [
            {"role": "assistant", "content": reply},
            {"role": "user", "content": "Fix these and send the whole layout again:\n" + "\n".join(problems)},
        ]
    top = task.support.top_height
    posed = [(oid, description, asset) for oid, description, asset in objects if oid in poses]
    scene = Scene(
        seed=task.seed,
        prompt=task.prompt,
        support=task.support,
        objects=[
            _posed_object(oid, description, asset, poses[oid], top, task.seed) for oid, description, asset in posed
        ],
    )
    report = check_program(program, task.support, assets=catalogue.id_set())
    solution = Solution(scene, report, assets={oid: asset for oid, _, asset in posed})
    solved = [[o.id, "AT", ROOT_ID, {"position": list(o.position), "yaw": poses[o.id].yaw}] for o in scene.objects]
    output = _baseline_output(task, program, solved, solution, started)
    output.extra |= {"layout_problems": problems, "layout_requests": len(agent.calls)}
    return output


def _posed_object(oid: str, description: str, asset: Asset, pose: Any, top: float, seed: int) -> PlacedObject:
    mass, friction, com = physical_properties(asset, oid, seed)
    return PlacedObject(
        id=oid,
        description=description,
        asset=asset.id,
        category=asset.category,
        position=(pose.x, pose.y, top + pose.z),
        quaternion=yaw_quaternion(pose.yaw),
        mass=mass,
        friction=friction,
        com=com,
    )


METHODS: dict[str, Method] = {
    "ours": run_ours,
    "random": run_random,
    "llm-only": run_llm_only,
    "program-frozen": run_program_frozen,
    "no-feedback": run_no_feedback,
    "no-report": run_no_report,
    "visual": run_visual,
}
NEEDS_VLM = frozenset({"visual"})


def method_named(name: str) -> Method:
    if name not in METHODS:
        raise PhyscensisError(f"unknown method {name!r} (known: {', '.join(METHODS)})")
    return METHODS[name]


def write_output(output: MethodOutput, out_dir: Path, evaluation: dict[str, Any]) -> None:
    """The scene folder: scene.json, report.json, render.png, ... (as `generate` writes it), transcript.jsonl,
    method.json (the program solved) and evaluation.json (this comparison's metrics of the scene)."""
    from physcensis.fileio import output_directory
    from physcensis.output import write_solution

    generated = output.generated
    transcript = "\n".join(json.dumps(row) for row in generated.transcript) + "\n"
    extra = {
        "transcript.jsonl": transcript,
        "method.json": json.dumps({"solved_program": output.solved_program} | output.extra, indent=1) + "\n",
        "evaluation.json": json.dumps(evaluation, indent=2) + "\n",
    }
    if output.solution is None:
        with output_directory(out_dir, overwrite=True) as staging:
            for name, text in extra.items():
                (staging / name).write_text(text)
            (staging / "report.json").write_text(json.dumps(generated.report(), indent=2) + "\n")
        return
    report = {"report.json": lambda: json.dumps(generated.report(), indent=2) + "\n"}
    write_solution(output.solution, out_dir, exports=(), overwrite=True, extra_files={**extra, **report})
