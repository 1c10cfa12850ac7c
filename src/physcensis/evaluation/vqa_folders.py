"""`eval vqa`: the VQA score of saved scene folders, each re-rendered from the same standard view (as the paper
re-renders every method's scenes before scoring), asked of a vision model for the scene's own prompt."""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from physcensis.errors import PhyscensisError


@dataclass(frozen=True)
class SceneVQA:
    scene: str
    prompt: str | None
    score: float | None
    error: str | None = None
    unreachable: bool = False  # the VLM's server did not answer (later folders would only wait again)

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


def scene_prompt(folder: Path, given: str | None = None) -> str:
    """The prompt a folder's scene was made for: `given`, else scene.json's, else report.json's."""
    if given is not None:
        if not given.strip():
            raise PhyscensisError("the prompt to score against is empty")
        return given.strip()
    from physcensis.scene import load_scene

    scene = load_scene(folder / "scene.json" if folder.is_dir() else folder)
    if scene.prompt:
        return scene.prompt
    report = (folder if folder.is_dir() else folder.parent) / "report.json"
    try:
        prompt = json.loads(report.read_text()).get("prompt") if report.is_file() else None
    except (OSError, ValueError, AttributeError):
        prompt = None
    if isinstance(prompt, str) and prompt.strip():
        return prompt.strip()
    raise PhyscensisError("the scene records no prompt: give one with --prompt")


def score_folder(
    folder: Path,
    vlm: str,
    base_url: str | None,
    prompt: str | None = None,
    timeout_s: float = 120.0,
    normalised: bool = False,
) -> SceneVQA:
    """One folder's score; a folder that cannot be scored is a result holding why (the others still are)."""
    from physcensis.agent.critic import render_png
    from physcensis.agent.vqa import vqa_score
    from physcensis.output import open_scene
    from physcensis.physics.mujoco_engine import MujocoEngine

    asked: str | None = None
    try:
        asked = scene_prompt(folder, prompt)
        scene, catalogue = open_scene(folder)
        if not scene.placed:
            return SceneVQA(str(folder), asked, None, "no placed object to render")
        image = render_png(scene, MujocoEngine(catalogue))
    except (PhyscensisError, OSError, ValueError) as exc:
        return SceneVQA(str(folder), asked, None, str(exc) or type(exc).__name__)
    calls: list[dict[str, Any]] = []
    score = vqa_score(image, asked, vlm, base_url, timeout_s=timeout_s, calls=calls, normalised=normalised)
    if score is not None:
        return SceneVQA(str(folder), asked, score)
    failed = next((call["error"] for call in reversed(calls) if call.get("error")), None)
    if failed is not None and not any(call.get("answer") is not None for call in calls):
        return SceneVQA(str(folder), asked, None, f"the VLM did not answer: {failed}", unreachable=True)
    return SceneVQA(str(folder), asked, None, f"the VLM {vlm} gave no answer that reads as yes or no")


def score_folders(
    folders: list[Path],
    vlm: str,
    base_url: str | None,
    prompt: str | None = None,
    timeout_s: float = 120.0,
    on_folder: Callable[[int], None] | None = None,
    normalised: bool = False,
) -> list[SceneVQA]:
    """Every folder's score, in order; once the server does not answer, the rest are not asked (each would wait its
    whole timeout again) and say so."""
    results: list[SceneVQA] = []
    for k, folder in enumerate(folders):
        if on_folder is not None:
            on_folder(k)
        if results and results[-1].unreachable:
            results.append(SceneVQA(str(folder), None, None, "not asked: the VLM did not answer for an earlier scene"))
            continue
        results.append(score_folder(folder, vlm, base_url, prompt, timeout_s, normalised))
    return results


def score_stats(results: list[SceneVQA]) -> tuple[float, float] | None:
    """Mean and standard deviation of the scores had (None when none was)."""
    from physcensis.evaluation.compare import mean_std

    return mean_std([r.score for r in results if r.score is not None])
