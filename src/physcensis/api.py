"""The public entry points: `generate` a scene from a sentence, `solve` a predicate program."""

from __future__ import annotations

import functools
import json
import os
from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from physcensis.agent.account import (
    Reading,
    displaced_phrases,
    graph_displaced,
    graph_sides_missed,
    missing_phrases,
    read_account,
    stood_in_for,
)
from physcensis.agent.base import Agent
from physcensis.agent.factory import make_agent
from physcensis.agent.loop import MAX_RETRIES, GenerateResult, Progress, generate_scene
from physcensis.agent.planner import OfflinePlanner
from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.errors import UnreadablePromptError
from physcensis.fileio import output_directory
from physcensis.output import DEFAULT_EXPORTS, write_solution
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.redaction import Redactor, url_secrets
from physcensis.scene import Support
from physcensis.settings import ModelSettings, RunSettings
from physcensis.solver.pipeline import (
    DEFAULT_SUPPORT,
    Solution,
    solve,  # the public solve is the pipeline's, with its signature
)

__all__ = ["Generated", "generate", "solve", "write_generated"]


@dataclass
class Generated:
    """A generated scene with its report and the whole conversation that produced it."""

    result: GenerateResult
    prompt: str
    support: Support
    vqa: float | None = None
    vqa_kind: str | None = None  # how `vqa` was scored: "p-yes" (the paper's) or "normalised"; None: not scored
    added: list[dict[str, str]] = field(default_factory=list)  # objects placed that the prompt did not name, and why
    requested: dict[str, int] = field(default_factory=dict)  # per category, the fewest the prompt asks for
    reading: Reading | None = None  # the prompt's parse and what each of its noun phrases became (agent/account.py)
    scene_graph: dict[str, Any] | None = None  # the graph the planner planned from, and whose it is (agent/graph.py)
    variety: str = "none"
    redactor: Redactor = field(default_factory=Redactor, repr=False)  # keeps the run's secrets out of both

    @property
    def solution(self) -> Solution | None:
        return self.result.solution

    @property
    def transcript(self) -> list[dict[str, Any]]:
        return self.redactor.data(self.result.transcript)

    @property
    def missing(self) -> list[dict[str, Any]]:
        """What the prompt asked for and the scene does not hold: category, how many asked, how many placed."""
        placed = Counter(o.category for o in self.solution.scene.placed) if self.solution else Counter()
        rows = [{"category": c, "asked": n, "placed": placed[c]} for c, n in self.requested.items() if placed[c] < n]
        return rows + (missing_phrases(self.reading.phrases) if self.reading is not None else [])

    @property
    def elsewhere(self) -> list[dict[str, Any]]:
        """What the prompt put in or on a holder, or on a side of another thing, and the scene placed elsewhere:
        phrase, how many, why."""
        said = displaced_phrases(self.reading.phrases) if self.reading is not None else []
        scene = self.solution.scene if self.solution else None
        graph = (self.scene_graph or {}).get("graph")
        counted = [row for row in graph_displaced(graph, scene) if row["category"] not in {r["category"] for r in said}]
        return said + counted + graph_sides_missed(graph, scene)

    def report(self) -> dict[str, Any]:
        """The scene's report with the run's; without a scene, `ok` false, why, and every round's exchange."""
        base: dict[str, Any] = self.solution.report() if self.solution else {"ok": False}
        base["generate"] = {
            "prompt": self.prompt,
            "rounds": self.result.rounds,
            "seconds": round(self.result.seconds, 3),
            "vqa_score": self.vqa,
            "vqa": self.vqa_kind,
            "stop_reason": self.result.stop_reason,
            "variety": self.variety,
            "added": self.added,
            "requested": self.requested,
            "missing": self.missing,
            "elsewhere": self.elsewhere,
            "reading": self.reading.to_json() if self.reading is not None else None,
            "scene_graph": self.scene_graph,
            "failure": self.result.failure,
            "requests": [_request_summary(row) for row in self.result.transcript if "round" in row],
        }
        if self.solution is None:
            base["generate"]["exchanges"] = self.result.transcript
        return self.redactor.data(base)


def _request_summary(row: dict[str, Any]) -> dict[str, Any]:
    """Round, author, outcome, seconds and tokens of one transcript row."""
    keys = ("round", "agent", "feedback_kind", "error", "seconds", "usage")
    return {key: row[key] for key in keys if key in row}


def generate(
    prompt: str,
    *,
    settings: RunSettings | None = None,
    support: Support | None = None,
    seed: int = 0,
    agent: Agent | None = None,
    catalogue: Catalogue | None = None,
    progress: Progress | None = None,
    **options: Any,
) -> Generated:
    """A scene for `prompt`: the offline planner by default, or any OpenAI-compatible LLM.

    `settings` (physcensis.settings.RunSettings) says which models, how much work and how much variety; any of its
    options can also be given by name and change those settings: `generate("two mugs", seed=3, rounds=2)`,
    `generate(prompt, llm="qwen2.5-7b", base_url="http://localhost:8000/v1", hint="on")`. The options:

    * models: `llm` (None: the offline planner), `base_url`, `api_key_env`, `temperature`, `llm_timeout_s` (the
      wall-clock budget of each LLM and VLM request, retries and waits included), `structured` (send the program's
      JSON Schema: "auto" falls back to plain text when refused, "on" fails instead, "off"), `prompt_style` ("auto",
      "full", "compact": auto sends the compact prompt to local and small-context servers), `stream`, `hint` (show
      the LLM the offline reading as a draft: "auto" with the compact prompt), `llm_writes` ("program", or "graph":
      the LLM writes only the scene graph and the seeded offline planner plans from it), `vlm`, `vlm_base_url`,
      `vlm_feedback` (with a VLM every solved round's render is scored: "score" tells the agent the score and asks
      one more round when it is low, "remarks" also the model's words, "off" scores only the final scene), `vqa`
      ("p-yes", the paper's P("Yes"), or "normalised", P(yes) / (P(yes) + P(no)));
    * budget: `rounds`, `min_objects`, `max_objects`, `time_budget_s` (no new round starts once it is spent; None:
      none);
    * draws: `variety` ("none", "normal", "wide": how far the seed reaches in what the prompt leaves open; the same
      prompt, seed and variety give the same scene), `context` (objects that belong to the kind of scene, listed in
      the report's `added`; default on unless the variety is none), `default_scene` (a prompt the offline planner
      cannot read gets a typical scene, listed as added, instead of `UnreadablePromptError`).

    An unknown option or a value out of range is a `SettingsError` naming it.
    """
    settings = (settings or RunSettings()).replace(**options)
    models, budget = settings.models, settings.budget
    support = support or DEFAULT_SUPPORT
    catalogue = catalogue or default_catalogue()
    if agent is None:
        agent = make_agent(settings, catalogue, seed)
        if progress is not None and models.llm:  # the reply's tokens as they stream in
            agent.on_tokens = functools.partial(_tokens_received, progress)  # type: ignore[attr-defined]
    if not settings.draws.default_scene:
        _refuse_unreadable(agent, prompt)
    engine = MujocoEngine(catalogue)
    critic = None
    if models.vlm and models.vlm_feedback != "off":
        from physcensis.agent.critic import VisionCritic

        critic = VisionCritic(
            prompt,
            models.vlm,
            models.vlm_url,
            engine,
            remarks=models.vlm_feedback == "remarks",
            timeout_s=models.llm_timeout_s,
            api_key_env=models.api_key_env,
            provider=models.provider,
            normalised=models.vqa == "normalised",
        )
    result = generate_scene(
        prompt,
        agent,
        support=support,
        seed=seed,
        rounds=budget.rounds,
        retries=MAX_RETRIES + getattr(agent, "redraws", 0),
        min_objects=budget.min_objects,
        catalogue=catalogue,
        engine=engine,
        progress=progress,
        max_objects=budget.max_objects,
        time_budget_s=budget.time_budget_s,
        critic=critic,
    )
    notes = [{"note": note} for note in getattr(agent, "transcript_notes", [])]  # e.g. structured output refused
    result.transcript[:0] = notes + (agent.graph_requests() if isinstance(agent, OfflinePlanner) else [])
    generated = Generated(result, prompt, support, redactor=_run_redactor(agent, models))
    generated.variety = settings.draws.variety if isinstance(agent, OfflinePlanner) else "llm"
    generated.added = _added(agent, result.solution)
    # what the prompt asks for, as the planner reads it (offline, or through a model's graph); a program an LLM wrote
    # is not counted
    generated.requested = agent.requested(prompt, support.kind) if isinstance(agent, OfflinePlanner) else {}
    generated.reading = read_account(prompt, result.solution.scene if result.solution else None, catalogue)
    if isinstance(agent, OfflinePlanner):  # the offline reading's graph, or a model's (--llm-writes graph)
        generated.scene_graph = agent.graph_reading(prompt).to_json()
    if isinstance(agent, OfflinePlanner) and settings.draws.default_scene and not agent.reads(prompt):
        generated.reading = stood_in_for(generated.reading)
    if models.vlm and result.solution is not None and result.solution.scene.placed:
        generated.vqa_kind = models.vqa
        generated.vqa = result.vqa  # the critic's score of the kept scene (None: the VLM did not answer)
        if critic is None:
            generated.vqa = _vqa(result.solution, prompt, models, engine)
    return generated


def _refuse_unreadable(agent: Agent, prompt: str) -> None:
    """Raise UnreadablePromptError when the offline planner's reading finds nothing it knows in the prompt."""
    if isinstance(agent, OfflinePlanner) and not agent.reads(prompt):
        shown = " ".join(prompt.split())[:80]
        raise UnreadablePromptError(
            f"the prompt {shown!r} names no object, no diners and no kind of scene the offline planner knows: name "
            "what to place ('two mugs and a plate') or a scene ('a tidy desk'), or ask for the default scene "
            "(--default-scene)"
        )


def _added(agent: Agent, solution: Solution | None) -> list[dict[str, str]]:
    """The objects the agent added without being asked (context objects) that the final scene holds."""
    placed = {o.id for o in solution.scene.placed} if solution is not None else set()
    return [row for row in getattr(agent, "added", []) if row.get("id") in placed]


def _tokens_received(progress: Progress, tokens: int) -> None:
    progress("receiving", {"tokens": tokens})


def _run_redactor(agent: Agent, models: ModelSettings) -> Redactor:
    """Everything secret in this run: the agent's own secrets, the servers' credentials and the API key."""
    agent_redactor = getattr(agent, "redactor", None)
    known = agent_redactor.secrets if isinstance(agent_redactor, Redactor) else []
    urls = (models.base_url, models.vlm_base_url)
    return Redactor([*known, *(s for url in urls for s in url_secrets(url)), os.environ.get(models.api_key_env)])


def _vqa(solution: Solution, prompt: str, models: ModelSettings, engine: MujocoEngine) -> float | None:
    from physcensis.agent.critic import render_png
    from physcensis.agent.vqa import vqa_score

    assert models.vlm is not None
    png = render_png(solution.scene, engine)
    return vqa_score(
        png,
        prompt,
        models.vlm,
        models.vlm_url,
        timeout_s=models.llm_timeout_s,
        api_key_env=models.api_key_env,
        provider=models.provider,
        normalised=models.vqa == "normalised",
    )


def write_generated(
    generated: Generated, out_dir: str | Path, *, exports: Iterable[str] = DEFAULT_EXPORTS, overwrite: bool = False
) -> Path:
    """scene.json, report.json, render.png, layout.png, the exports and transcript.jsonl in `out_dir`, atomically.

    A failed run (no scene) leaves its record: transcript.jsonl and report.json (`"ok": false`) only."""
    out_dir = Path(out_dir)
    rows = generated.transcript
    if generated.reading is not None:  # what the words became, the record's last row
        rows = [*rows, {"reading": generated.reading.to_json()}]
    transcript = "\n".join(json.dumps(row) for row in rows) + "\n"
    if generated.solution is None:
        with output_directory(out_dir, overwrite=overwrite) as staging:
            (staging / "transcript.jsonl").write_text(transcript)
            (staging / "report.json").write_text(json.dumps(generated.report(), indent=2) + "\n")
        return out_dir
    write_solution(
        generated.solution,
        out_dir,
        exports=exports,
        overwrite=overwrite,
        extra_files={
            "transcript.jsonl": transcript,
            "report.json": lambda: json.dumps(generated.report(), indent=2) + "\n",  # with the exports just written
        },
    )
    return out_dir
