"""`eval vqa`: the VQA score of saved scene folders, each re-rendered from the same standard view (as the paper
re-renders every method's scenes before scoring), asked of a vision model for the scene's own prompt."""

from __future__ import annotations

import json
import statistics
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

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


def scene_prompt(folder: Path, given: str | None = None) -> str:
    """The prompt a folder's scene was made for: `given`, else scene.json's, else report.json's."""
    if given and given.strip():
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
    folder: Path, vlm: str, base_url: str | None, prompt: str | None = None, timeout_s: float = 120.0
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
    score = vqa_score(image, asked, vlm, base_url, timeout_s=timeout_s)
    error = None if score is not None else f"the VLM {vlm} gave no answer that reads as yes or no (see the log)"
    return SceneVQA(str(folder), asked, score, error)


def mean_std(results: list[SceneVQA]) -> tuple[float, float] | None:
    scores = [r.score for r in results if r.score is not None]
    if not scores:
        return None
    return statistics.fmean(scores), statistics.pstdev(scores) if len(scores) > 1 else 0.0
