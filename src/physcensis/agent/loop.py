"""The generate loop: propose -> check -> solve -> feedback, with retries and enrichment rounds."""

from __future__ import annotations

import json
import logging
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from physcensis.agent.base import Agent, AgentContext, AgentError, Round
from physcensis.agent.prompt import HISTORY_REPLY_CHARS, clip_text
from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.errors import ProgramParseError
from physcensis.feedback.messages import Feedback, grammar_feedback, solver_feedback, success_feedback
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.program import DEFAULT_MAX_OBJECTS, check_program, parse_program
from physcensis.scene import Support
from physcensis.solver.pipeline import Solution, solve

log = logging.getLogger(__name__)
MAX_RETRIES = 3
MAX_REPLY_CHARS = 256_000  # a longer reply is refused unread: a program for hundreds of objects is far smaller


@dataclass
class GenerateResult:
    solution: Solution | None  # the best scene reached (None if no program ever solved)
    transcript: list[dict[str, Any]] = field(default_factory=list)
    rounds: int = 0
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        return self.solution is not None


Progress = Callable[[str, dict[str, Any]], None]


def generate_scene(
    prompt: str,
    agent: Agent,
    *,
    support: Support,
    seed: int = 0,
    rounds: int = 1,
    retries: int = MAX_RETRIES,
    min_objects: int = 0,
    catalogue: Catalogue | None = None,
    engine: MujocoEngine | None = None,
    progress: Progress | None = None,
    max_objects: int = DEFAULT_MAX_OBJECTS,
) -> GenerateResult:
    """Run the agent loop. `rounds` counts successful rounds (1 = no enrichment); a round may be retried
    `retries` times with feedback; enrichment also continues until `min_objects` are placed."""
    start = time.perf_counter()
    catalogue = catalogue or default_catalogue()
    engine = engine or MujocoEngine(catalogue)
    vocabulary = tuple(catalogue.categories())
    history: list[Round] = []
    transcript: list[dict[str, Any]] = []
    best: Solution | None = None
    request, notes = "create", dict[str, str]()
    successes, attempts, freed = 0, 0, set[str]()
    step = 0
    while successes < max(1, rounds) or (best is not None and len(best.scene.placed) < min_objects):
        step += 1
        if attempts > retries or step > 3 * (max(1, rounds) + retries) + 6:
            break
        context = AgentContext(prompt, support, vocabulary, tuple(history), request, dict(notes))
        _report(progress, "propose", {"round": step, "request": request})
        try:
            text = agent.propose(context)
        except AgentError as exc:
            transcript.append(_redacted(agent, {"round": step, "request": request, "error": str(exc)}))
            break
        feedback, solution = _evaluate(text, support, seed, catalogue, engine, progress, step, max_objects)
        row = {
            "round": step,
            "request": request,
            "agent": getattr(agent, "name", "agent"),
            "program": text,
            "feedback_kind": feedback.kind,
            "feedback": feedback.text,
            "metrics": feedback.data if feedback.kind != "grammar" else {},
        }
        if len(text) > MAX_REPLY_CHARS:  # kept only as a short head, in the history and the transcript
            text = row["program"] = clip_text(text, HISTORY_REPLY_CHARS, "reply")
            row["reply_chars"] = feedback.data["reply_chars"]
        transcript.append(_redacted(agent, row))
        ok = feedback.kind == "success"
        history.append(Round(text, feedback.text, ok))
        if solution is not None and (best is None or _better(solution, best)):
            best = solution
        if ok:
            successes += 1
            attempts = 0
            request, notes = "enrich", {}
            enrich = successes < rounds or (best is not None and len(best.scene.placed) < min_objects)
            if enrich:  # the enrichment request carries the success feedback with empty regions
                feedback = success_feedback(solution, catalogue, enrich=True) if solution else feedback
                history[-1] = Round(text, feedback.text, True)
                transcript[-1]["feedback"] = _redacted(agent, feedback.text)
        else:
            attempts += 1
            request = "repair"
            freed |= set(notes.get("failed", "").split(",")) - {""}
            notes = {"failed": ",".join(feedback.failed), "freed": ",".join(sorted(freed))}
            if successes and attempts > retries:  # enrichment keeps failing: stop at the last good scene
                break
    return GenerateResult(best, transcript, step, time.perf_counter() - start)


def _redacted(agent: Agent, value: Any) -> Any:
    """`value` without the agent's secrets (API key, base-URL credentials), for the transcript."""
    redactor = getattr(agent, "redactor", None)
    return redactor.data(value) if redactor is not None else value


def oversize_feedback(chars: int, limit: int = MAX_REPLY_CHARS) -> Feedback:
    """A reply too long to read is a grammar problem: the agent is told to send only the program."""
    text = (
        f"Your reply was {chars} characters, over the limit of {limit}; it was not read. Send only the "
        "program: one JSON list of entries, with no explanation and nothing repeated."
    )
    return Feedback("grammar", text, data={"reply_chars": chars, "limit": limit})


def _evaluate(
    text: str,
    support: Support,
    seed: int,
    catalogue: Catalogue,
    engine: MujocoEngine,
    progress: Progress | None,
    step: int,
    max_objects: int = DEFAULT_MAX_OBJECTS,
) -> tuple[Feedback, Solution | None]:
    if len(text) > MAX_REPLY_CHARS:
        return oversize_feedback(len(text)), None
    try:
        program = parse_program(text)
    except ProgramParseError as exc:
        return grammar_feedback(None, str(exc)), None
    report = check_program(program, support, max_objects=max_objects)
    if not report.ok:
        return grammar_feedback(report), None
    _report(progress, "solve", {"round": step, "objects": len(program.declarations)})
    solution = solve(program, support=support, seed=seed, catalogue=catalogue, engine=engine, max_objects=max_objects)
    _report(progress, "solved", {"round": step, "placed": len(solution.scene.placed)})
    if not solution.ok:
        return solver_feedback(solution, catalogue), solution
    return success_feedback(solution, catalogue), solution


def _better(new: Solution, old: Solution) -> bool:
    """A scene without failures beats one with; then more placed objects win."""
    return (new.ok, len(new.scene.placed)) >= (old.ok, len(old.scene.placed))


def _report(progress: Progress | None, stage: str, data: dict[str, Any]) -> None:
    if progress is not None:
        progress(stage, data)
    log.debug("%s %s", stage, json.dumps(data))
