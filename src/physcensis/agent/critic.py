"""A vision model's view of a solved scene, as feedback for the loop: the VQA score of the render and, for the
`visual` method, the model's own words on what does not match the prompt.

The loop asks the critic after every round that solved; what it says is appended to that round's feedback, a low
score earns the agent one more round to change the scene (`REVISE_BELOW`), and the scene the loop keeps is the one
the model found likeliest to show the prompt (among those without failures).
"""

from __future__ import annotations

import io
import logging
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from physcensis.agent.base import AgentError
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.scene import Scene
from physcensis.settings import API_KEY_ENV, DEFAULT_PROVIDER

log = logging.getLogger(__name__)

REVISE_BELOW = 0.5  # a VQA score under this asks the agent for one more round
MAX_REVISIONS = 1  # extra rounds a low score may add to one run
MAX_REMARK_CHARS = 600


@dataclass(frozen=True)
class Critique:
    """What the vision model said of one render: P(yes) that it shows the prompt (None when it could not be had)
    and, when asked, its remarks."""

    vqa: float | None
    remarks: str | None = None
    calls: list[dict[str, Any]] = field(default_factory=list, compare=False)

    def feedback_lines(self, prompt: str) -> list[str]:
        if self.vqa is None and not self.remarks:
            return []
        lines = []
        if self.vqa is not None:
            verdict = "likely" if self.vqa >= REVISE_BELOW else "unlikely"
            lines.append(
                f"A vision model looked at a render of the scene: it is {verdict} to show {prompt.strip()!r} "
                f"(VQA score {self.vqa:.2f} of 1)."
            )
        if self.remarks:
            lines.append(f"The vision model says: {self.remarks}")
        if self.vqa is not None and self.vqa < REVISE_BELOW:
            lines.append(
                "Change the program so the scene shows the prompt more plainly: the objects it names, their number "
                "and their arrangement."
            )
        return lines


Critic = Callable[[Scene, float | None], Critique]  # (scene, seconds left of the run's budget or None)


def render_png(scene: Scene, engine: MujocoEngine, size: tuple[int, int] = (640, 480)) -> bytes:
    """The scene from the standard three-quarter view, as PNG bytes (the same view for every method)."""
    import matplotlib.image

    from physcensis.physics.render import render_built

    image = render_built(engine.build(scene), scene, view="iso", size=size)
    buffer = io.BytesIO()
    matplotlib.image.imsave(buffer, image, format="png")
    return buffer.getvalue()


@dataclass
class VisionCritic:
    """Asks `model` (an OpenAI-compatible vision chat model) about each scene's render."""

    prompt: str
    model: str
    base_url: str | None
    engine: MujocoEngine
    remarks: bool = False  # also ask what does not match (the `visual` method)
    timeout_s: float = 120.0
    api_key_env: str = API_KEY_ENV
    provider: str = DEFAULT_PROVIDER
    normalised: bool = False  # the VQA score against P(no), not the paper's P("Yes")

    def __call__(self, scene: Scene, seconds_left: float | None = None) -> Critique:
        """The model's view of `scene`; its questions share `seconds_left` (and each keeps within `timeout_s`)."""
        from physcensis.agent.vqa import vqa_score  # here: the offline path asks no model, and openai's import is slow

        started = time.perf_counter()
        png = render_png(scene, self.engine)
        calls: list[dict[str, Any]] = []

        def timeout() -> float:
            if seconds_left is None:
                return self.timeout_s
            return max(1.0, min(self.timeout_s, seconds_left - (time.perf_counter() - started)))

        score = vqa_score(
            png,
            self.prompt,
            self.model,
            self.base_url,
            timeout_s=timeout(),
            calls=calls,
            api_key_env=self.api_key_env,
            provider=self.provider,
            normalised=self.normalised,
        )
        said = None
        if self.remarks and not _unreachable(calls):
            said = ask_remarks(
                png, self.prompt, self.model, self.base_url, timeout(), calls, self.api_key_env, self.provider
            )
        return Critique(score, said, calls)


def _unreachable(calls: list[dict[str, Any]]) -> bool:
    """Whether the model's last question got no answer at all (so a second one would only wait again)."""
    return bool(calls) and calls[-1].get("answer") is None and "error" in calls[-1]


def remarks_question(prompt: str) -> str:
    return (
        f"This is a rendered 3D scene that should show: {prompt.strip()}. In at most two sentences, say what in the "
        "picture does not match that description (missing, extra, misplaced or fallen objects), or answer 'Nothing.'"
    )


def ask_remarks(
    image_png: bytes,
    prompt: str,
    model: str,
    base_url: str | None,
    timeout_s: float,
    calls: list[dict[str, Any]] | None = None,
    api_key_env: str = API_KEY_ENV,
    provider: str = DEFAULT_PROVIDER,
) -> str | None:
    """The model's short description of what does not match; None when it cannot be had (logged)."""
    from physcensis.agent.vqa import image_message
    from physcensis.llm.client import LLMRequestError, RetryPolicy, chat_completion, reply_text
    from physcensis.llm.providers import connect

    ask = remarks_question(prompt)
    body = {
        "model": model,
        "messages": [image_message(ask, image_png)],
        "temperature": 0.0,
        "max_tokens": 160,
    }
    record: dict[str, Any] = {"question": ask, "image_bytes": len(image_png), "model": model, "attempts": []}
    if calls is not None:
        calls.append(record)
    try:
        server = connect(base_url, api_key_env, provider)
    except AgentError as exc:
        log.warning("visual remarks unavailable: %s", exc)
        record["error"] = str(exc)
        return None
    try:
        response = chat_completion(
            server,
            body,
            policy=RetryPolicy(max_retries=2, backoff_s=1.0),
            timeout_s=timeout_s,
            label=f"visual remarks {model} at {server.url}",
            attempts=record["attempts"],
        )
        text, _ = reply_text(response)
        text = " ".join(server.redactor.text(server.scrub(text)).split())[:MAX_REMARK_CHARS]
    except LLMRequestError as exc:
        log.warning("visual remarks unavailable: %s", exc)
        record["error"] = str(exc)
        return None
    finally:
        server.close()
    record["answer"] = text
    return text or None
