"""What a process imports to read a prompt offline: nothing slow that the offline path never uses. Every batch worker
pays these imports once, so each second here is a second of every batch's start."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

pytestmark = pytest.mark.long  # a fresh interpreter that loads the parser: 4-6 s here

PROBE = """
import json, sys
import physcensis.api
from physcensis.agent.parse import parse
relations = parse("a pen to the right of the notebook").relations
print(json.dumps({"loaded": sorted(m for m in ("openai", "torch", "scipy.signal") if m in sys.modules),
                  "relations": [r.word for r in relations]}))
import torch  # imports as usual afterwards
print(json.dumps({"torch": torch.zeros(2).tolist()}))
"""


def test_the_offline_reading_imports_no_model_client_no_torch_and_torch_still_imports_after() -> None:
    pytest.importorskip("torch")
    done = subprocess.run([sys.executable, "-c", PROBE], capture_output=True, text=True, timeout=300, check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    first, second = (json.loads(line) for line in done.stdout.strip().splitlines()[-2:])
    assert first == {"loaded": [], "relations": ["to the right of"]}
    assert second == {"torch": [0.0, 0.0]}


SCENE_PROBE = """
import json, sys
from physcensis.batch.prompts import Task
from physcensis.batch.worker import Options, make_scene
task = Task(key="desk", prompt_id="desk", prompt="a mug next to a book", support="table:0.6x0.5", seed=0)
outcome = make_scene(task, Options(exports=("none",)))
print(json.dumps({"ok": outcome.ok, "files": sorted(outcome.files), "matplotlib": "matplotlib" in sys.modules}))
"""


def test_a_batch_worker_writes_a_whole_scene_folder_without_importing_matplotlib() -> None:
    """render.png and layout.png are drawn with Pillow: matplotlib's import is a second of every worker's start."""
    done = subprocess.run([sys.executable, "-c", SCENE_PROBE], capture_output=True, text=True, timeout=300, check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    result = json.loads(done.stdout.strip().splitlines()[-1])
    assert result["ok"] and {"render.png", "layout.png", "scene.json", "report.json"} <= set(result["files"])
    assert result["matplotlib"] is False
