"""An enabled VLM verifier must agree too: the primitive verifier's success becomes a failure when the model says
no, and the model is shown the scene before and after."""

from __future__ import annotations

import json
from pathlib import Path

import h5py
import pytest

from physcensis.robot.demos import DATASET, REPORT, DemoSettings, run_scene
from tests.agent.fake_server import FakeOpenAI


@pytest.mark.slow
@pytest.mark.long
def test_a_vlm_that_says_no_turns_the_primitive_success_into_a_failure(small_scene_dir: Path, tmp_path: Path) -> None:
    settings = DemoSettings(task="pick cup_0 place-on plate_0", images=None, vlm="fake-vlm")
    with FakeOpenAI(["No. The mug is lying beside the plate."]) as server:
        settings.vlm_base_url = server.base_url
        report = run_scene(small_scene_dir, tmp_path / "out", settings)
        requests = list(server.requests)
    episode = report["episodes"][0]
    assert episode["stage"] == "verify"  # the arm did its part: only the VLM's no stands in the way
    assert not episode["success"] and "said no" in episode["reason"]
    assert len(requests) == 1 and requests[0]["model"] == "fake-vlm"
    images = [part for m in requests[0]["messages"] for part in m["content"] if isinstance(m["content"], list)]
    assert sum(part.get("type") == "image_url" for part in images) == 2  # before and after
    assert json.loads((tmp_path / "out" / REPORT).read_text())["settings"]["vlm"] == "fake-vlm"
    with h5py.File(tmp_path / "out" / DATASET) as dataset:
        assert not dataset["data/demo_0"].attrs["success"]


def test_the_vlm_verifier_speaks_through_the_chosen_provider(monkeypatch: pytest.MonkeyPatch) -> None:
    """`--llm-provider` and `--api-key-env` reach the demonstrations' VLM verifier (it once built an OpenAI client
    with OPENAI_API_KEY whatever the run said)."""
    from physcensis.errors import AgentError
    from physcensis.llm.providers import PROVIDERS
    from physcensis.robot.demos import _vlm_verifier

    made: list[tuple[str | None, str]] = []
    server = object()

    def toy(base_url: str | None, api_key_env: str) -> object:
        made.append((base_url, api_key_env))
        return server

    monkeypatch.setitem(PROVIDERS, "toy", toy)
    settings = DemoSettings(task="pick a place-on b", vlm="v", vlm_base_url="toy://v", provider="toy", api_key_env="K")
    verifier = _vlm_verifier(settings)
    assert made == [("toy://v", "K")] and verifier is not None and verifier.args == (server, "v")  # type: ignore[attr-defined]
    with pytest.raises(AgentError, match="no chat provider named 'nope'"):
        _vlm_verifier(DemoSettings(task="pick a place-on b", vlm="v", provider="nope"))
