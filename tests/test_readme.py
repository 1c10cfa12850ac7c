"""Every code block of README.md works: the Python blocks run as scripts, the shell blocks name commands and options
that exist.

Python blocks run one by one as `python snippet.py` in a fresh interpreter and an empty folder holding the files they
name (`desk.json`, from the bundled examples), as a reader who pastes one into a file would run it. A fresh interpreter
matters: what a block imports first is what a reader's script imports first.
"""

from __future__ import annotations

import re
import shlex
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
import typer
import yaml

from physcensis.assets.library import EntrySpec, LibrarySpec
from physcensis.cli import app
from tests.conftest import EXAMPLES, REPO

README = REPO / "README.md"
FENCE = re.compile(r"^```(\w*)\n(.*?)^```", re.MULTILINE | re.DOTALL)
LANGUAGES = {"python", "bash", "yaml"}  # a block in any other language fails test_every_block_is_one_these_tests_run
INPUTS = {"desk.json": EXAMPLES / "desk_basic.json"}  # files the blocks read, as a reader would have them
# What a block promises to write (a file that must exist afterwards), by the call in the block that writes it.
PROMISES = {
    'write_solution(solution, "out/desk")': ["out/desk/scene.json", "out/desk/report.json", "out/desk/mjcf/scene.xml"],
    'write_generated(generated, "out/books")': ["out/books/scene.json", "out/books/transcript.jsonl"],
    'export_scene(scene, "out/books_sim", ["urdf", "glb"])': [
        "out/books_sim/urdf/bodies.json",
        "out/books_sim/scene.glb",
    ],
    '"data/dining", per_prompt=2': [
        "data/dining/manifest.jsonl",
        "data/dining/scenes/dining_000/scene.json",
        "data/dining/scenes/dining_001/scene.json",
    ],
}


def code_blocks(language: str | None = None) -> list[tuple[str, str]]:
    """(language, code) of each fenced block of the README, in order; only `language`'s when given."""
    blocks = [(m.group(1), m.group(2)) for m in FENCE.finditer(README.read_text(encoding="utf-8"))]
    return [b for b in blocks if language is None or b[0] == language]


PYTHON = [code for _, code in code_blocks("python")]
SHELL = [code for _, code in code_blocks("bash")]


def test_every_block_is_one_these_tests_run() -> None:
    assert {language for language, _ in code_blocks()} <= LANGUAGES
    assert len(PYTHON) >= 2 and len(SHELL) >= 2


@pytest.mark.slow
@pytest.mark.long
@pytest.mark.physics
@pytest.mark.timeout(300)
@pytest.mark.parametrize("code", PYTHON, ids=[f"python-{i}" for i in range(len(PYTHON))])
def test_python_block_runs(tmp_path: Path, code: str) -> None:
    for name, source in INPUTS.items():
        (tmp_path / name).write_bytes(source.read_bytes())
    (tmp_path / "snippet.py").write_text(code)
    run = subprocess.run([sys.executable, "snippet.py"], cwd=tmp_path, capture_output=True, text=True, timeout=280)
    assert run.returncode == 0, run.stderr[-4000:]
    for call, paths in PROMISES.items():
        if call in code:
            assert [p for p in paths if not (tmp_path / p).is_file()] == [], call


def test_every_promise_is_checked_in_some_block() -> None:
    """A block that changed its output paths must change PROMISES too, or its outputs go unchecked."""
    assert [call for call in PROMISES if not any(call in code for code in PYTHON)] == []


@pytest.mark.slow
@pytest.mark.long
def test_physcensis_solve_is_the_function_whatever_was_imported_first() -> None:
    """Importing the solvers (here through physcensis.api and physcensis.solver.pipeline) must not replace the
    function `physcensis.solve` (a subpackage of that name once did)."""
    program = EXAMPLES / "books_stack.json"
    code = (
        "import pathlib\nimport physcensis.api\nimport physcensis.solver.pipeline as pipeline\nimport physcensis\n"
        "from physcensis.solver import spatial\n"
        f"solution = physcensis.solve(pathlib.Path({str(program)!r}), seed=0, physics=False)\n"
        "assert isinstance(solution, pipeline.Solution) and solution.scene.placed\n"
        "assert physcensis.solver.pipeline is pipeline and physcensis.solver.spatial is spatial\n"
        "assert callable(physcensis.solve) and not hasattr(physcensis.solve, 'pipeline')\n"
        "print(len(solution.scene.placed))\n"
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr[-4000:]
    assert int(run.stdout) >= 1


# -- shell blocks -------------------------------------------------------------------------------------------------


def _commands(block: str) -> list[list[str]]:
    """The `physcensis ...` lines of a shell block as words, comments dropped and `[--json]` read as `--json`."""
    commands = []
    for line in block.splitlines():
        words = shlex.split(line, comments=True)
        if words[:1] == ["physcensis"]:
            commands.append([w.strip("[]") for w in words[1:]])
    return commands


def _command(root: Any, words: list[str]) -> tuple[Any, list[str]]:
    """The (click) subcommand the words name (`eval settle`; `assets list|show`: each alternative is checked by
    test_shell_blocks_name_real_commands_and_options) and the words after it."""
    command = root
    while getattr(command, "commands", None) and words:  # a group (Typer bundles its own click: no isinstance)
        sub = command.commands.get(words[0])
        assert sub is not None, f"physcensis has no command {words[0]!r}"
        command, words = sub, words[1:]
    return command, words


def _option_names(command: Any) -> set[str]:
    return {name for param in command.params for name in (*param.opts, *param.secondary_opts)}


def _alternatives(words: list[str]) -> list[list[str]]:
    """`assets list|show|search` -> `assets list`, `assets show`, `assets search` (only the subcommand word)."""
    for i, word in enumerate(words):
        if "|" in word and not word.startswith("-") and i < 2:
            return [[*words[:i], alternative, *words[i + 1 :]] for alternative in word.split("|")]
    return [words]


def test_shell_blocks_name_real_commands_and_options() -> None:
    root = typer.main.get_command(app)
    commands = [a for block in SHELL for c in _commands(block) for a in _alternatives(c)]
    assert len(commands) >= 20
    for words in commands:
        command, rest = _command(root, words)
        options = _option_names(command)
        named = {w.split("=", 1)[0] for w in rest if w.startswith("--")}
        assert named <= options, (" ".join(words), sorted(named - options))


def test_yaml_blocks_are_valid_asset_libraries() -> None:
    """Each YAML block is a library.yaml as the importer reads it: its top level and every entry validate."""
    blocks = [code for _, code in code_blocks("yaml")]
    assert blocks
    for code in blocks:
        data = yaml.safe_load(code)
        spec = LibrarySpec.model_validate(data)
        assert spec.assets and all(EntrySpec.model_validate(entry) for entry in spec.assets)


def test_make_targets_of_the_readme_exist() -> None:
    targets = set(re.findall(r"^make (\w+)", "\n".join(SHELL), re.MULTILINE))
    assert targets >= {"demo", "test"}
    makefile = (REPO / "Makefile").read_text()
    assert all(re.search(rf"^{t}:", makefile, re.MULTILINE) for t in targets), targets
