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

from physcensis.agent.base import Agent
from physcensis.agent.loop import DEFAULT_TIME_BUDGET_S, MAX_RETRIES, GenerateResult, Progress, generate_scene
from physcensis.agent.planner import OfflinePlanner
from physcensis.agent.variety import DEFAULT_VARIETY, Variety, parse_variety
from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.errors import PhyscensisError, UnreadablePromptError
from physcensis.fileio import output_directory
from physcensis.output import DEFAULT_EXPORTS, write_solution
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.program import DEFAULT_MAX_OBJECTS
from physcensis.redaction import Redactor, url_secrets
from physcensis.scene import Support
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
    added: list[dict[str, str]] = field(default_factory=list)  # objects placed that the prompt did not name, and why
    requested: dict[str, int] = field(default_factory=dict)  # per category, the fewest the prompt asks for
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
        return [{"category": c, "asked": n, "placed": placed[c]} for c, n in self.requested.items() if placed[c] < n]

    def report(self) -> dict[str, Any]:
        """The scene's report with the run's; without a scene, `ok` false, why, and every round's exchange."""
        base: dict[str, Any] = self.solution.report() if self.solution else {"ok": False}
        base["generate"] = {
            "prompt": self.prompt,
            "rounds": self.result.rounds,
            "seconds": round(self.result.seconds, 3),
            "vqa_score": self.vqa,
            "stop_reason": self.result.stop_reason,
            "variety": self.variety,
            "added": self.added,
            "requested": self.requested,
            "missing": self.missing,
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
    support: Support | None = None,
    llm: str | None = None,
    base_url: str | None = None,
    agent: Agent | None = None,
    seed: int = 0,
    rounds: int = 1,
    min_objects: int = 0,
    vlm: str | None = None,
    vlm_base_url: str | None = None,
    catalogue: Catalogue | None = None,
    progress: Progress | None = None,
    temperature: float | None = 0.7,
    llm_timeout_s: float = 300.0,
    max_objects: int = DEFAULT_MAX_OBJECTS,
    structured: str = "auto",
    prompt_style: str = "auto",
    time_budget_s: float | None = DEFAULT_TIME_BUDGET_S,
    stream: bool = True,
    vlm_feedback: str = "score",
    hint: str = "auto",
    variety: str | Variety = DEFAULT_VARIETY,
    context: bool | None = None,
    default_scene: bool = False,
) -> Generated:
    """A scene for `prompt`: offline planner by default, or any OpenAI-compatible `llm` (model name).

    `llm_timeout_s` is the wall-clock budget of each LLM (and VLM) request, its retries and their waits included.
    No new round starts once `time_budget_s` is spent (None: no budget); the best scene so far is the result.
    `structured` ("auto", "on" or "off") says whether the LLM is sent the program's JSON Schema as `response_format`;
    "auto" falls back to plain text when the server refuses it (noted in the transcript), "on" fails instead.
    `prompt_style` ("auto", "full" or "compact") is the LLM's system prompt: "auto" sends the compact one to local
    servers and to servers that report a small context (the choice is noted in the transcript). `stream` asks for
    streamed replies (progress shows the tokens received; some servers then report no token counts).
    `hint` ("auto", "on" or "off") shows the LLM the offline planner's reading of the prompt (its objects, what rests
    on or in what) as a draft to correct; "auto" does so with the compact prompt (small models).
    `variety` ("none", "normal" or "wide") is how far the offline planner's seeded choices reach (which variant,
    how many of a vague plural, where groups stand, context objects; agent/variety.py): the same prompt, seed and
    variety give the same scene, "none" the canonical one. `context` (default: on unless the variety is "none") lets
    it add a few objects that belong to the kind of scene; they are listed in the report's `added`.
    A prompt the offline planner cannot read (it names no object, no diners and no kind of scene: "asdf", empty,
    only symbols) is refused with `UnreadablePromptError`; with `default_scene` it gets a typical everyday scene
    instead, every object of it listed in `added` as the planner's.
    With a `vlm`, every solved round's render is scored (VQA) and `vlm_feedback` says what the agent hears of it:
    "score" (the score, and one more round when it is low), "remarks" (also the model's words on what does not match:
    the `visual` method) or "off" (only the final scene is scored).
    """
    if vlm_feedback not in ("score", "remarks", "off"):
        raise PhyscensisError(f"vlm_feedback {vlm_feedback!r}: give score, remarks or off")
    support = support or DEFAULT_SUPPORT
    catalogue = catalogue or default_catalogue()
    variety = parse_variety(variety)
    if llm or vlm:
        from physcensis.agent.llm import positive_seconds

        llm_timeout_s = positive_seconds(llm_timeout_s, "llm_timeout_s")
    if agent is None:
        if llm:
            from physcensis.agent.llm import LLMAgent

            agent = LLMAgent(
                llm,
                base_url=base_url,
                temperature=temperature,
                timeout_s=llm_timeout_s,
                structured=structured,
                prompt=prompt_style,
                stream=stream,
                hint=hint,
                catalogue=catalogue,
            )
            if progress is not None:  # the reply's tokens as they stream in
                agent.on_tokens = functools.partial(_tokens_received, progress)
        else:
            agent = OfflinePlanner(catalogue, seed=seed, variety=variety, context=context)
    if not default_scene:
        _refuse_unreadable(agent, prompt)
    engine = MujocoEngine(catalogue)
    critic = None
    if vlm and vlm_feedback != "off":
        from physcensis.agent.critic import VisionCritic

        critic = VisionCritic(
            prompt, vlm, vlm_base_url or base_url, engine, remarks=vlm_feedback == "remarks", timeout_s=llm_timeout_s
        )
    result = generate_scene(
        prompt,
        agent,
        support=support,
        seed=seed,
        rounds=rounds,
        retries=MAX_RETRIES + getattr(agent, "redraws", 0),
        min_objects=min_objects,
        catalogue=catalogue,
        engine=engine,
        progress=progress,
        max_objects=max_objects,
        time_budget_s=time_budget_s,
        critic=critic,
    )
    notes = [{"note": note} for note in getattr(agent, "transcript_notes", [])]  # e.g. structured output refused
    result.transcript[:0] = notes
    generated = Generated(result, prompt, support, redactor=_run_redactor(agent, base_url, vlm_base_url))
    generated.variety = variety.value if isinstance(agent, OfflinePlanner) else "llm"
    generated.added = _added(agent, result.solution)
    # what the prompt asks for, as the offline planner reads it (an LLM's reading may differ: not counted)
    generated.requested = agent.requested(prompt) if isinstance(agent, OfflinePlanner) else {}
    if vlm and result.solution is not None and result.solution.scene.placed:
        generated.vqa = result.vqa  # the critic's score of the kept scene (None: the VLM did not answer)
        if critic is None:
            generated.vqa = _vqa(result.solution, prompt, vlm, vlm_base_url or base_url, engine, llm_timeout_s)
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


def _run_redactor(agent: Agent, *base_urls: str | None) -> Redactor:
    """Everything secret in this run: the agent's own secrets, the servers' credentials and the API key."""
    agent_redactor = getattr(agent, "redactor", None)
    known = agent_redactor.secrets if isinstance(agent_redactor, Redactor) else []
    return Redactor([*known, *(s for url in base_urls for s in url_secrets(url)), os.environ.get("OPENAI_API_KEY")])


def _vqa(
    solution: Solution, prompt: str, model: str, base_url: str | None, engine: MujocoEngine, timeout_s: float
) -> float | None:
    from physcensis.agent.critic import render_png
    from physcensis.agent.vqa import vqa_score

    return vqa_score(render_png(solution.scene, engine), prompt, model, base_url, timeout_s=timeout_s)


def write_generated(
    generated: Generated, out_dir: str | Path, *, exports: Iterable[str] = DEFAULT_EXPORTS, overwrite: bool = False
) -> Path:
    """scene.json, report.json, render.png, layout.png, the exports and transcript.jsonl in `out_dir`, atomically.

    A failed run (no scene) leaves its record: transcript.jsonl and report.json (`"ok": false`) only."""
    out_dir = Path(out_dir)
    transcript = "\n".join(json.dumps(row) for row in generated.transcript) + "\n"
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
