"""The generate loop: propose -> check -> solve -> feedback, with retries and enrichment rounds."""

from __future__ import annotations

import contextlib
import json
import logging
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field, replace
from typing import Any

from physcensis.agent.base import Agent, AgentContext, AgentError, Round
from physcensis.agent.critic import MAX_REVISIONS, REVISE_BELOW, Critic, Critique
from physcensis.agent.prompt import HISTORY_REPLY_CHARS, clip_text
from physcensis.agent.repair import repair_program
from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.errors import ProgramParseError
from physcensis.feedback.messages import (
    Feedback,
    grammar_feedback,
    repeat_feedback,
    solver_feedback,
    success_feedback,
)
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.program import DEFAULT_MAX_OBJECTS, check_program, parse_program
from physcensis.program.lenient_json import read_lenient
from physcensis.program.schema import is_object_form, list_form
from physcensis.scene import MAX_PROMPT_CHARS, Support
from physcensis.settings import DEFAULT_TIME_BUDGET_S
from physcensis.solver.pipeline import Solution, solve

log = logging.getLogger(__name__)
MAX_RETRIES = 3
MAX_REPLY_CHARS = 256_000  # a longer reply is refused unread: a program for hundreds of objects is far smaller


FINISHING_SHARE = 0.25  # of the budget, for the one solve after it that frees what failed
MIN_SOLVE_S = 5.0  # the least time a solve gets, however little of the budget is left


@dataclass
class GenerateResult:
    solution: Solution | None  # the best scene reached (None if no program ever solved)
    transcript: list[dict[str, Any]] = field(default_factory=list)
    rounds: int = 0
    seconds: float = 0.0
    stop_reason: str = "done"  # "done", "retries" (every attempt failed), "agent-error" or "time-budget"
    failure: str | None = None  # one line: why there is no scene, or why the rounds stopped early
    vqa: float | None = None  # the critic's score of `solution`, when a critic judged it

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
    time_budget_s: float | None = DEFAULT_TIME_BUDGET_S,
    critic: Critic | None = None,
) -> GenerateResult:
    """Run the agent loop. `rounds` counts successful rounds (1 = no enrichment); a round may be retried
    `retries` times with feedback; enrichment also continues until `min_objects` are placed. No round starts once
    `time_budget_s` is spent (None: no budget); the best scene so far is the result. A `critic` (a vision model)
    judges every solved scene: its words join the feedback, a low score earns one more round, and the scene kept is
    the one it scored highest among those without failures."""
    catalogue = catalogue or default_catalogue()
    settings = _Settings(
        prompt, support, seed, max(1, rounds), retries, min_objects, max_objects, time_budget_s, progress, critic
    )
    return _Run(agent, settings, catalogue, engine or MujocoEngine(catalogue)).go()


@dataclass(frozen=True)
class _Settings:
    prompt: str
    support: Support
    seed: int
    rounds: int
    retries: int
    min_objects: int
    max_objects: int
    time_budget_s: float | None
    progress: Progress | None
    critic: Critic | None = None


class _Run:
    """The state of one generate loop: history, transcript, the best scene, and the failed programs seen."""

    def __init__(self, agent: Agent, settings: _Settings, catalogue: Catalogue, engine: MujocoEngine) -> None:
        self.agent, self.s, self.catalogue, self.engine = agent, settings, catalogue, engine
        self.start = time.perf_counter()
        self.vocabulary = tuple(catalogue.categories())
        self.own_assets = tuple((e.id, e.description) for e in catalogue.entries() if not e.builtin)
        self.history: list[Round] = []
        self.transcript: list[dict[str, Any]] = []
        self.best: Solution | None = None
        self.request, self.notes = "create", dict[str, str]()
        self.successes, self.attempts, self.step, self.repeats = 0, 0, 0, 0
        self.revisions = 0  # rounds added because the critic found the scene unlike the prompt
        self.critique: Critique | None = None  # of the last round that solved
        self.best_score: float | None = None  # the critic's score of `best`
        self.freed: set[str] = set()
        self.failed_programs: dict[str, int] = {}  # canonical program -> the round it first failed in
        self.stop_reason: str = "done"
        self.failure: str | None = None
        self._best_round: tuple[str, Feedback] | None = None  # the program and feedback of `best`
        self._finishing = False  # the run's last, budget-free step (the critic still scores what it makes)
        self._cost: dict[str, Any] = {}

    def go(self) -> GenerateResult:
        while self._wants_more():
            self.step += 1
            if self.attempts > self.s.retries or self.step > 3 * (self.s.rounds + self.s.retries) + 6:
                self.stop_reason = "retries"
                break
            if self._budget_spent():
                self.stop_reason = "time-budget"
                break
            text = self._propose()
            if text is None or not self._round(text):
                break
        if self.stop_reason == "time-budget":
            self._free_the_failing_of_best()
        seconds = time.perf_counter() - self.start
        failure = self.failure or self._why_stopped()
        result = GenerateResult(self.best, self.transcript, self.step, seconds, self.stop_reason, failure)
        result.vqa = self.best_score
        return result

    def _wants_more(self) -> bool:
        few = self.best is not None and len(self.best.scene.placed) < self.s.min_objects
        return self.successes < self.s.rounds + self.revisions or few

    def _budget_spent(self) -> bool:
        budget = self.s.time_budget_s
        return budget is not None and time.perf_counter() - self.start >= budget

    def _why_stopped(self) -> str | None:
        if self.stop_reason == "time-budget":
            done = sum("program" in row and row.get("agent") != "loop-repair" for row in self.transcript)
            return f"the time budget of {self.s.time_budget_s:g} s ran out after {done} round(s)"
        if self.best is None:
            kinds = ", ".join(str(row.get("feedback_kind", "error")) for row in self.transcript) or "none"
            return f"no program solved in {len(self.transcript)} round(s) (feedback: {kinds})"
        return None

    def _propose(self) -> str | None:
        """The agent's reply, or None (recorded, and the run ends) when the agent fails."""
        context = AgentContext(
            self.s.prompt,
            self.s.support,
            self.vocabulary,
            tuple(self.history),
            self.request,
            dict(self.notes),
            self.s.seed,
            self.own_assets,
            self.s.max_objects,
        )
        _report(self.s.progress, "propose", {"round": self.step, "request": self.request})
        calls_before, begun = len(getattr(self.agent, "calls", [])), time.perf_counter()
        try:
            with self._request_within_budget():
                return self.agent.propose(context)
        except AgentError as exc:
            if self._budget_spent():  # the request was cut short by the budget
                self.stop_reason = "time-budget"
            else:
                self.stop_reason = "agent-error"
                self.failure = _redacted(self.agent, " ".join(f"the agent failed: {exc}".split()))
            row = {"round": self.step, "request": self.request, "error": str(exc)}
            self.transcript.append(_redacted(self.agent, row | self._request_cost(calls_before, begun)))
            return None
        finally:
            self._cost = self._request_cost(calls_before, begun)

    @contextlib.contextmanager
    def _request_within_budget(self) -> Iterator[None]:
        """An agent with a per-request wall-clock limit (`timeout_s`, as LLMAgent has) gets at most what is left
        of the time budget for this request, so one slow request cannot outlast the budget."""
        limit = getattr(self.agent, "timeout_s", None)
        budget = self.s.time_budget_s
        if budget is None or not isinstance(limit, (int, float)) or isinstance(limit, bool):
            yield
            return
        left = max(budget - (time.perf_counter() - self.start), 0.001)
        self.agent.timeout_s = min(float(limit), left)  # type: ignore[attr-defined]  # checked by getattr above
        try:
            yield
        finally:
            self.agent.timeout_s = limit  # type: ignore[attr-defined]  # restored for the next run

    def _request_cost(self, calls_before: int, begun: float) -> dict[str, Any]:
        """Seconds of the request, and the tokens the server reported (LLM agents record their calls)."""
        calls = getattr(self.agent, "calls", [])
        made = [c for c in (calls[calls_before:] if isinstance(calls, list) else []) if isinstance(c, dict)]
        cost: dict[str, Any] = {"seconds": round(time.perf_counter() - begun, 3), "usage": _summed_usage(made)}
        if made:  # each request of the reply (a guided one makes two), also the one that failed
            cost["requests"] = [_request_record(c) for c in made]
        return cost

    def _round(self, text: str) -> bool:
        """Evaluate one reply; False when the run should stop."""
        feedback, solution = self._evaluate(text)
        key = program_key(text)
        repeated = feedback.kind != "success" and key in self.failed_programs
        repaired: str | None = None
        if repeated:
            self.repeats += 1
            entries = _entries(text)
            repaired = self._without_failing(entries, feedback)
            first = self.failed_programs[key]
            feedback = repeat_feedback(feedback, first, self.repeats, entries, dropped=repaired is not None)
        elif feedback.kind != "success":
            self.failed_programs[key] = self.step
        self._record(text, feedback, solution, getattr(self.agent, "name", "agent"), self._cost)
        if not self._advance(feedback, solution):
            return False
        if repaired is not None:  # the model is stuck: its program without what fails, as for solver failures
            feedback, solution = self._evaluate(repaired)
            self._record(repaired, feedback, solution, "loop-repair", {"seconds": 0.0, "usage": None})
            return self._advance(feedback, solution)
        return True

    def _without_failing(self, entries: list[Any] | None, feedback: Feedback) -> str | None:
        """The program (its `entries`) with its failing objects dropped or freed (placed anywhere), or None when that
        leaves nothing or cannot be done."""
        failing = _failing(feedback)
        if not failing or entries is None:
            return None
        try:
            repaired = json.dumps(repair_program(entries, failing, self.freed))
        except (ProgramParseError, ValueError, TypeError):
            return None
        self.freed |= failing
        return None if repaired == "[]" else repaired

    def _free_the_failing_of_best(self) -> None:
        """The time budget ended the run on a scene with failing objects, leaving the agent no round to fix them: the
        loop drops or frees them itself, once (one solve, no request), as it does for a repeated program."""
        if self.best is None or self.best.ok or self._best_round is None:
            return
        text, feedback = self._best_round
        repaired = self._without_failing(_entries(text), feedback)
        if repaired is None:
            return
        self._finishing = True
        feedback, solution = self._evaluate(repaired)
        self._record(repaired, feedback, solution, "loop-repair", {"seconds": 0.0, "usage": None})

    def _evaluate(self, text: str) -> tuple[Feedback, Solution | None]:
        s = self.s
        where = s.support, s.seed, self.catalogue, self.engine, s.progress, self.step
        feedback, solution = _evaluate(text, *where, s.max_objects, self._time_left())
        if solution is not None and _storable(s.prompt):
            solution.scene.prompt = s.prompt  # scene.json says what it was made for (eval vqa reads it)
        return feedback, solution

    def _time_left(self) -> float | None:
        """How long a solve may search and place: what is left of the time budget, or after it ran out a last grace
        of FINISHING_SHARE of it for the one solve that frees what failed; never less than MIN_SOLVE_S, so that a
        reply which arrives as the budget ends is still judged."""
        budget = self.s.time_budget_s
        if budget is None:
            return None
        left = budget * FINISHING_SHARE if self._finishing else budget - (time.perf_counter() - self.start)
        return max(left, MIN_SOLVE_S)

    def _record(
        self, text: str, feedback: Feedback, solution: Solution | None, author: str, cost: dict[str, Any]
    ) -> None:
        program_text = text
        critique = self._criticise(solution) if feedback.kind == "success" else None
        if critique is not None:
            feedback = replace(feedback, text=_with_critique(feedback.text, critique, self.s.prompt))
        row = {
            "round": self.step,
            "request": self.request,
            "agent": author,
            "program": text,
            "feedback_kind": feedback.kind,
            "feedback": feedback.text,
            "metrics": feedback.data if feedback.kind != "grammar" else {},
            **cost,
        }
        if critique is not None:
            row["critic"] = {"vqa_score": critique.vqa, "remarks": critique.remarks, "requests": critique.calls}
        if "repeat_of_round" in feedback.data:
            row["repeat_of_round"] = feedback.data["repeat_of_round"]
        if len(text) > MAX_REPLY_CHARS:  # kept only as a short head, in the history and the transcript
            text = row["program"] = clip_text(text, HISTORY_REPLY_CHARS, "reply")
            row["reply_chars"] = feedback.data["reply_chars"]
        self.transcript.append(_redacted(self.agent, row))
        self.history.append(Round(text, feedback.text, feedback.kind == "success"))
        score = critique.vqa if critique is not None else None
        if solution is not None and (self.best is None or self._better(solution, score)):
            self.best, self.best_score = solution, score
            self._best_round = (program_text, feedback)

    def _criticise(self, solution: Solution | None) -> Critique | None:
        if self.s.critic is None or solution is None or not solution.scene.placed:
            return None
        if self._budget_spent() and not self._finishing:
            return None
        _report(self.s.progress, "critic", {"round": self.step})
        budget = self.s.time_budget_s
        left = None if budget is None or self._finishing else max(1.0, budget - (time.perf_counter() - self.start))
        self.critique = self.s.critic(solution.scene, left)
        return self.critique

    def _better(self, new: Solution, score: float | None) -> bool:
        """Whether `new` (scored `score` by the critic) beats the best so far."""
        assert self.best is not None
        return self._rank(new, score) >= self._rank(self.best, self.best_score)

    def _rank(self, solution: Solution, score: float | None) -> tuple[Any, ...]:
        """A scene without failures beats one with; then, with a critic, one with the `min_objects` asked for, then
        the higher score (an unscored scene ranks below scored ones); then more placed objects."""
        placed = len(solution.scene.placed)
        if self.s.critic is None:
            return solution.ok, placed
        return solution.ok, placed >= self.s.min_objects, -1.0 if score is None else score, placed

    def _advance(self, feedback: Feedback, solution: Solution | None) -> bool:
        """The next request after the round just recorded; False when the run should stop."""
        if feedback.kind == "success":
            self.successes += 1
            self.attempts, self.repeats = 0, 0
            self.request, self.notes = "enrich", {}
            critique, self.critique = self.critique, None
            low = critique is not None and critique.vqa is not None and critique.vqa < REVISE_BELOW
            if low and not self._wants_more() and self.revisions < MAX_REVISIONS:
                self.revisions += 1
                self.request = "revise"  # change the scene to look like the prompt, not only add to it
            if self._wants_more() and solution is not None:  # the enrichment request carries the empty regions
                text = success_feedback(solution, self.catalogue, enrich=self.request == "enrich").text
                if critique is not None:
                    text = _with_critique(text, critique, self.s.prompt)
                self.history[-1] = Round(self.history[-1].program_text, text, True)
                self.transcript[-1]["feedback"] = _redacted(self.agent, text)
            return True
        self.attempts += 1
        self.request = "repair"
        self.freed |= set(self.notes.get("failed", "").split(",")) - {""}
        self.notes = {"failed": ",".join(feedback.failed), "freed": ",".join(sorted(self.freed))}
        if self.successes and self.attempts > self.s.retries:  # enrichment keeps failing: stop at the last good scene
            self.stop_reason = "retries"
            return False
        return True


def program_key(text: str) -> str:
    """What makes two replies the same program: the parsed program (key order, whitespace and predicate spelling
    normalised), or the whitespace-normalised text when it does not parse."""
    try:
        return json.dumps(parse_program(text).to_json(), sort_keys=True)
    except (ProgramParseError, ValueError, TypeError, RecursionError):
        return " ".join(text.split())


def _failing(feedback: Feedback) -> set[str]:
    """The objects a failed round names: those the solver could not place and those the checker found wrong."""
    return set(feedback.failed) | {p["object"] for p in feedback.data.get("problems", []) if p.get("object")}


REQUEST_REPLY_CHARS = 4_000  # of each request's reply, in the transcript row


def _summed_usage(calls: list[dict[str, Any]]) -> dict[str, int | None] | None:
    """The tokens of the requests one reply took (a guided round makes two), None when no server reported any; a
    count some answered request did not report is None (unknown), not 0. A refused request used none."""
    usages = [c.get("usage") for c in calls if not c.get("error")]
    if not any(isinstance(u, dict) for u in usages):
        return None
    keys = ("prompt_tokens", "completion_tokens", "total_tokens")
    totals: dict[str, int | None] = {}
    for key in keys:
        counts = [u.get(key) if isinstance(u, dict) else None for u in usages]
        known = [n for n in counts if isinstance(n, int)]
        totals[key] = sum(known) if len(known) == len(counts) else None
    return totals


def _request_record(call: dict[str, Any]) -> dict[str, Any]:
    """One request of a reply as the transcript keeps it: seconds, tokens, how it ended, the reply's start."""
    reply = call.get("response")
    return {
        "seconds": call.get("duration_s"),
        "usage": call.get("usage"),
        "finish_reason": call.get("finish_reason"),
        "error": call.get("error"),
        "reply": clip_text(reply, REQUEST_REPLY_CHARS, "reply") if isinstance(reply, str) else None,
    }


def _entries(text: str) -> list[Any] | None:
    """The reply as a JSON list of entries (an object-form reply turned into one), or None when it is not one."""
    try:
        data = read_lenient(text)
        if isinstance(data, dict) and is_object_form(data):
            data = list_form(data)
    except (ProgramParseError, ValueError, TypeError, RecursionError):
        return None
    return data if isinstance(data, list) else None


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
    time_limit_s: float | None = None,
) -> tuple[Feedback, Solution | None]:
    if len(text) > MAX_REPLY_CHARS:
        return oversize_feedback(len(text)), None
    try:
        program = parse_program(text)
    except ProgramParseError as exc:
        return grammar_feedback(None, str(exc)), None
    report = check_program(program, support, max_objects=max_objects, assets=catalogue.id_set())
    if not report.ok:
        return grammar_feedback(report), None
    _report(progress, "solve", {"round": step, "objects": len(program.declarations)})
    solution = solve(
        program,
        support=support,
        seed=seed,
        catalogue=catalogue,
        engine=engine,
        max_objects=max_objects,
        time_limit_s=time_limit_s,
    )
    _report(progress, "solved", {"round": step, "placed": len(solution.scene.placed)})
    if not solution.ok:
        return solver_feedback(solution, catalogue), solution
    return success_feedback(solution, catalogue), solution


def _storable(prompt: str) -> bool:
    """Whether scene.json can hold `prompt` (within the length limit, valid unicode)."""
    try:
        prompt.encode("utf-8")
    except UnicodeEncodeError:
        return False
    return len(prompt) <= MAX_PROMPT_CHARS


def _with_critique(text: str, critique: Critique, prompt: str) -> str:
    return "\n".join([text, *critique.feedback_lines(prompt)])


def _report(progress: Progress | None, stage: str, data: dict[str, Any]) -> None:
    if progress is not None:
        progress(stage, data)
    log.debug("%s %s", stage, json.dumps(data))
