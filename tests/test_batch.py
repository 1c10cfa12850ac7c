"""Batch generation: prompt files, seeds, failures on record, and resuming after the whole run was killed."""

from __future__ import annotations

import functools
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from click.testing import Result
from typer.testing import CliRunner

import physcensis.batch
from physcensis.batch import (
    FAILURES,
    MANIFEST,
    RECORD,
    SCENES_DIR,
    BatchError,
    Options,
    Task,
    make_scene,
    plan_tasks,
    read_prompts,
    run_batch,
)
from physcensis.batch.prompts import PromptSpec
from physcensis.batch.runners import MAX_ATTEMPTS
from physcensis.bench.prompt_suite import SUITE
from physcensis.cli import app
from physcensis.scene import load_scene
from tests.agent.fake_server import MUG_AND_BOOK, FakeOpenAI, use_loopback_only
from tests.batch.stub_scenes import SECONDS_ENV, stub_scene
from tests.conftest import REPO

DINING = "a dining table set up for four people"
NO_EXPORTS = Options(exports=("none",))
STUB_SECONDS = 0.3  # per scene, in the command-line runs that are killed or stopped on the way


def test_text_prompt_file_skips_blanks_and_comments(tmp_path: Path) -> None:
    path = tmp_path / "prompts.txt"
    path.write_text(f"# dining\n{DINING}\n\n  a stack of 3 books  \n")
    specs = read_prompts(path)
    assert [s.prompt for s in specs] == [DINING, "a stack of 3 books"]
    assert specs[0].id == "000-a-dining-table-set-up-for" and specs[1].id.startswith("001-")
    assert all(s.support == "table:1.2x0.8" for s in specs)


def test_jsonl_prompt_file_takes_ids_supports_and_counts(tmp_path: Path) -> None:
    path = tmp_path / "prompts.jsonl"
    path.write_text(
        '{"id": "shelf", "prompt": "books on a shelf", "support": "shelf:0.3x0.9", "count": 2}\n'
        '{"prompt": "a bowl of fruit", "support": {"kind": "table", "size": [0.6, 0.6]}}\n'
    )
    shelf, fruit = read_prompts(path)
    assert (shelf.id, shelf.support, shelf.count) == ("shelf", "shelf:0.3x0.9", 2)
    assert fruit.support == "table:0.6x0.6" and fruit.count is None
    assert [t.key for t in plan_tasks([shelf, fruit], per_prompt=3)] == [
        "shelf_000",
        "shelf_001",
        f"{fruit.id}_000",
        f"{fruit.id}_001",
        f"{fruit.id}_002",
    ]


def test_the_public_prompt_suite_reads_as_a_batch_file() -> None:
    specs = read_prompts(SUITE)
    assert len(specs) == 24 and specs[0].id == "dining-4" and specs[0].support == "table:1.2x0.8"


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ('{"prompt": "a cup"}\n{"prompt": "a cup", ', ":2: not valid JSON"),
        ('{"support": "table:1x1"}', ':1: each line must be an object with a "prompt"'),
        ('{"prompt": "a cup", "support": "table:1x"}', ":1: support 'table:1x'"),
        ('{"prompt": "a cup", "support": {"kind": "table", "size": [1, -1]}}', ":1: support:"),
        ('{"prompt": "a cup", "count": -1}', ':1: "count"'),
        ('{"prompt": "a cup", "id": "../x"}', ':1: "id"'),
        ('{"id": "a", "prompt": "a cup"}\n{"id": "a", "prompt": "a mug"}', "'a' is used twice"),
        ("# nothing here\n", "no prompts"),
    ],
)
def test_bad_prompt_files_name_the_line(tmp_path: Path, text: str, words: str) -> None:
    path = tmp_path / "p.jsonl"
    path.write_text(text)
    with pytest.raises(BatchError) as error:
        read_prompts(path)
    assert words in str(error.value)


def test_prompt_files_must_say_their_format(tmp_path: Path) -> None:
    array = tmp_path / "prompts.json"
    array.write_text('["a cup", "a mug"]')
    with pytest.raises(BatchError, match=r"\.txt .* or \.jsonl"):
        read_prompts(array)
    jsonish = tmp_path / "prompts.txt"
    jsonish.write_text('{"prompt": "a cup"}\n')
    with pytest.raises(BatchError, match=r"prompts.txt:1: this line looks like JSON"):
        read_prompts(jsonish)


def test_seeds_are_fixed_by_the_base_seed_and_distinct() -> None:
    specs = read_prompts_from([DINING, "a stack of 3 books"])
    first, again, other = plan_tasks(specs, 5, seed=0), plan_tasks(specs, 5, seed=0), plan_tasks(specs, 5, seed=1)
    assert first == again
    assert len({t.seed for t in first}) == 10
    assert [t.seed for t in first] != [t.seed for t in other]


def read_prompts_from(prompts: list[str]) -> list:
    from physcensis.batch import PromptSpec

    return [PromptSpec(f"p{i}", p) for i, p in enumerate(prompts)]


@pytest.mark.slow
def test_same_task_same_scene() -> None:
    task = Task("desk_000", "desk", "a laptop and a mug on a desk", "table:1.0x0.6", seed=7)
    first, second = make_scene(task, NO_EXPORTS), make_scene(task, NO_EXPORTS)
    assert first.ok and second.ok
    assert first.files["scene.json"] == second.files["scene.json"]


def test_a_failing_scene_is_recorded_with_its_reason_and_the_run_goes_on(tmp_path: Path) -> None:
    prompts = tmp_path / "p.jsonl"
    prompts.write_text(
        json.dumps({"id": "tiny", "prompt": DINING, "support": "table:0.05x0.05"})
        + "\n"
        + json.dumps({"id": "books", "prompt": "a stack of 3 books", "support": "table:0.6x0.5"})
        + "\n"
    )
    summary = run_batch(prompts, tmp_path / "out", per_prompt=1, options=NO_EXPORTS)
    assert (summary.made, summary.failed) == (1, 1)
    failure = json.loads((tmp_path / "out" / FAILURES).read_text())
    assert failure["key"] == "tiny_000" and failure["ok"] is False
    assert "no scene could be generated" in failure["reason"] and "plate" in failure["reason"]
    assert [p.name for p in (tmp_path / "out" / SCENES_DIR).iterdir()] == ["books_000"]
    # --skip-failed leaves the recorded failure alone; nothing else is left to do.
    again = run_batch(prompts, tmp_path / "out", per_prompt=1, options=NO_EXPORTS, retry_failed=False)
    assert (again.made, again.failed, again.already_done) == (0, 0, 1)


def test_nothing_to_make_or_nowhere_to_write_is_refused_before_touching_the_disk(tmp_path: Path) -> None:
    prompts = tmp_path / "p.txt"
    prompts.write_text("a stack of 3 books\n")
    with pytest.raises(BatchError, match="nothing to make"):
        run_batch(prompts, tmp_path / "out", per_prompt=0)
    assert not (tmp_path / "out").exists()
    afile = tmp_path / "afile"
    afile.write_text("")
    with pytest.raises(BatchError, match="is not a folder"):
        run_batch(prompts, afile, per_prompt=1)


def test_a_second_driver_on_the_same_folder_is_refused(tmp_path: Path) -> None:
    import fcntl

    prompts = tmp_path / "p.txt"
    prompts.write_text("a stack of 3 books\n")
    (tmp_path / "out").mkdir()
    with open(tmp_path / "out" / ".batch.lock", "w") as held:
        fcntl.flock(held, fcntl.LOCK_EX | fcntl.LOCK_NB)  # as a running driver holds it
        with pytest.raises(BatchError, match="another batch is writing"):
            run_batch(prompts, tmp_path / "out", per_prompt=1, options=NO_EXPORTS)


def test_failures_file_keeps_one_line_per_scene_still_missing(tmp_path: Path) -> None:
    prompts = tmp_path / "p.txt"
    prompts.write_text("a stack of 3 books\n")
    out = tmp_path / "out"
    out.mkdir()
    key = "000-a-stack-of-3-books_000"
    (out / FAILURES).write_text(
        json.dumps({"key": key, "reason": "the LLM server was down"})
        + "\n"
        + json.dumps({"key": "gone_000", "reason": "old"})
        + "\n"
        + '{"key": "cut sh'
    )
    summary = run_batch(prompts, out, per_prompt=1, options=NO_EXPORTS, scene_maker=stub_scene)  # works this time
    assert summary.made == 1
    assert [json.loads(line)["key"] for line in (out / FAILURES).read_text().splitlines()] == ["gone_000"]


def test_resuming_with_other_settings_is_refused(tmp_path: Path) -> None:
    prompts = tmp_path / "p.txt"
    prompts.write_text("a stack of 3 books\n")
    run_batch(prompts, tmp_path / "out", per_prompt=1, seed=0, options=NO_EXPORTS, scene_maker=stub_scene)
    with pytest.raises(BatchError, match="another prompt, seed or support"):
        run_batch(prompts, tmp_path / "out", per_prompt=1, seed=1, options=NO_EXPORTS, scene_maker=stub_scene)
    canonical = Options.of(exports=("none",), variety="none")  # the same seeds would give other scenes
    with pytest.raises(BatchError, match="--variety normal, this run asks for --variety none"):
        run_batch(prompts, tmp_path / "out", per_prompt=1, seed=0, options=canonical, scene_maker=stub_scene)


SECRET = "sk-batch-test-never-print-me"


@pytest.fixture
def loopback_llm_env(monkeypatch: pytest.MonkeyPatch) -> None:
    use_loopback_only(monkeypatch, SECRET)


def _llm_options(base_url: str) -> Options:
    return Options.of(exports=("none",), llm="fake-model", base_url=base_url, hint="off")  # test_hint.py: the draft


@pytest.mark.physics
def test_an_llm_batch_asks_the_server_and_records_the_agent(tmp_path: Path, loopback_llm_env: None) -> None:
    spec = PromptSpec(id="desk", prompt="a mug and a book", support="table:0.6x0.6")
    with FakeOpenAI([MUG_AND_BOOK], repeat_last=True) as server:
        summary = run_batch([spec], tmp_path / "out", per_prompt=2, options=_llm_options(server.base_url))
        assert len(server.requests) == 2  # one program per scene
    assert (summary.made, summary.failed) == (2, 0)
    records = [json.loads(line) for line in (tmp_path / "out" / MANIFEST).read_text().splitlines()]
    assert [r["agent"] for r in records] == ["llm:fake-model"] * 2
    for record in records:
        scene = load_scene(tmp_path / "out" / record["scene"] / "scene.json")
        assert {o.id for o in scene.placed} == {"mug_0", "book_0"}
    with pytest.raises(BatchError, match="made by llm:fake-model, this run uses offline-planner"):
        run_batch([spec], tmp_path / "out", per_prompt=3, options=NO_EXPORTS)


@pytest.mark.slow
@pytest.mark.physics
def test_batch_prompt_chooses_the_system_prompt_the_llm_is_sent(tmp_path: Path, loopback_llm_env: None) -> None:
    prompts = tmp_path / "prompts.jsonl"
    prompts.write_text('{"id": "desk", "prompt": "a mug and a book", "support": "table:0.6x0.6"}\n')
    system: dict[str, str] = {}
    for style in ("full", "compact"):  # auto would send the compact prompt to this local server either way
        with FakeOpenAI([MUG_AND_BOOK], repeat_last=True) as server:
            args = ["batch", str(prompts), "--out", str(tmp_path / style), "--llm", "fake-model"]
            args += ["--base-url", server.base_url, "--export", "none", "--structured", "off", "--prompt", style]
            args += ["--hint", "off"]  # test_hint.py tests the draft
            result = CliRunner().invoke(app, args)
            assert result.exit_code == 0, result.output
            system[style] = server.messages[0][0]["content"]
    assert len(system["compact"]) < len(system["full"]) / 2


def test_an_llm_server_that_does_not_answer_stops_the_batch_before_it_starts(
    tmp_path: Path, loopback_llm_env: None
) -> None:
    with FakeOpenAI() as server:
        dead_url = server.base_url  # the port is free again once the server is closed
    # Imported before the clock starts (seconds on a loaded machine): the bound is for the check itself, which
    # takes milliseconds against a closed port, and catches retries with backoff (15 s) or waiting for an answer.
    import physcensis.agent.llm
    import physcensis.export  # noqa: F401

    start = time.monotonic()
    with pytest.raises(BatchError, match=r"--llm fake-model: LLM server at .*could not connect"):
        run_batch([PromptSpec(id="desk", prompt="a mug")], tmp_path / "out", options=_llm_options(dead_url))
    assert time.monotonic() - start < 10
    assert not (tmp_path / "out").exists()


def test_a_refused_api_key_stops_the_batch_without_showing_the_key(tmp_path: Path, loopback_llm_env: None) -> None:
    with FakeOpenAI(api_key="sk-the-right-one") as server, pytest.raises(BatchError) as refused:
        run_batch([PromptSpec(id="desk", prompt="a mug")], tmp_path / "out", options=_llm_options(server.base_url))
    assert "HTTP 401" in str(refused.value) and "OPENAI_API_KEY" in str(refused.value)
    assert SECRET not in str(refused.value)
    assert not (tmp_path / "out").exists()


def _batch_args(prompts: Path, out: Path, *extra: str, scenes: int) -> list[str]:
    return ["batch", str(prompts), "--per-prompt", str(scenes), "--workers", "2", "--out", str(out), *extra]


def _batch_command(prompts: Path, out: Path, *extra: str, scenes: int) -> list[str]:
    """The batch command of the real `physcensis` executable."""
    return [str(Path(sys.executable).with_name("physcensis")), *_batch_args(prompts, out, *extra, scenes=scenes)]


def _stub_batch_command(prompts: Path, out: Path, *extra: str, scenes: int) -> list[str]:
    """The same command line, its scenes made by `stub_scene` (run with cwd=REPO and `_stub_env`)."""
    return [sys.executable, "-m", "tests.batch.stub_cli", *_batch_args(prompts, out, *extra, scenes=scenes)]


def _invoke_stub_batch(monkeypatch: pytest.MonkeyPatch, args: list[str]) -> Result:
    """`args` (from `_batch_args`) run in this process by the command line's own app, its scenes made by `stub_scene`
    at once, as `tests.batch.stub_cli` makes them. For a run nobody kills or signals: the real executable's start-up
    (seconds of imports) would be all its own process adds."""
    monkeypatch.setattr(physcensis.batch, "run_batch", functools.partial(run_batch, scene_maker=stub_scene))
    monkeypatch.delenv(SECONDS_ENV, raising=False)
    return CliRunner().invoke(app, args)


def _stub_env(seconds_per_scene: float = STUB_SECONDS) -> dict[str, str]:
    return {**os.environ, SECONDS_ENV: str(seconds_per_scene)}


def _books(tmp_path: Path) -> Path:
    prompts = tmp_path / "prompts.txt"
    prompts.write_text("a stack of 3 books\n")
    return prompts


def _workers_of(pid: int) -> list[int]:
    """Spawned pool workers among the children of `pid` (Linux /proc)."""
    children = []
    for task in Path(f"/proc/{pid}/task").iterdir():
        children += [int(c) for c in (task / "children").read_text().split()]
    return [c for c in children if b"spawn_main" in Path(f"/proc/{c}/cmdline").read_bytes()]


def _wait_for_lines(path: Path, lines: int, run: subprocess.Popen, limit_s: float = 120) -> None:
    deadline = time.monotonic() + limit_s
    while not (path.is_file() and len(path.read_text().splitlines()) >= lines):
        assert run.poll() is None, "the batch ended too early"
        assert time.monotonic() < deadline, "no progress"
        time.sleep(0.05)


@pytest.mark.slow
@pytest.mark.long
@pytest.mark.skipif(not Path("/proc/self/task").is_dir(), reason="reads /proc")
def test_a_dead_worker_costs_no_scene_and_a_killed_driver_takes_its_workers(tmp_path: Path) -> None:
    prompts = _books(tmp_path)
    command = _stub_batch_command(prompts, tmp_path / "out", "--export", "none", scenes=8)
    run = subprocess.Popen(
        command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, cwd=REPO, env=_stub_env()
    )
    _wait_for_lines(tmp_path / "out" / MANIFEST, 2, run)
    os.kill(_workers_of(run.pid)[0], signal.SIGKILL)  # as the kernel's OOM killer would
    stdout, _ = run.communicate(timeout=120)
    assert run.returncode == 0, stdout
    assert len(list((tmp_path / "out" / SCENES_DIR).iterdir())) == 8  # the tasks it held were made again
    assert (tmp_path / "out" / FAILURES).read_text() == ""

    command = _stub_batch_command(prompts, tmp_path / "again", "--export", "none", scenes=8)
    run = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=REPO, env=_stub_env())
    _wait_for_lines(tmp_path / "again" / MANIFEST, 1, run)
    workers = _workers_of(run.pid)
    assert workers
    run.kill()  # the driver alone
    run.wait(timeout=30)
    _assert_gone(workers)


@pytest.mark.timeout(120)
def test_a_scene_that_kills_its_worker_every_time_is_given_up(tmp_path: Path) -> None:
    """One worker under a scene timeout: the scene runs in a pool even alone, and no other task shares its fate."""
    summary = run_batch(
        [PromptSpec("poison", "a cup that dies")],
        tmp_path / "out",
        workers=1,
        options=NO_EXPORTS,
        scene_timeout_s=60.0,
        scene_maker=stub_scene,
    )
    assert (summary.made, summary.failed) == (0, 1)
    failure = json.loads((tmp_path / "out" / FAILURES).read_text())
    assert (failure["key"], failure["reason"]) == (
        "poison_000",
        f"a worker process died while making it ({MAX_ATTEMPTS} times)",
    )
    assert list((tmp_path / "out" / SCENES_DIR).iterdir()) == []


def _assert_gone(workers: list[int], within_s: float = 10.0) -> None:
    def alive(pid: int) -> bool:
        try:
            return b"spawn_main" in Path(f"/proc/{pid}/cmdline").read_bytes()
        except OSError:
            return False

    deadline = time.monotonic() + within_s
    while any(alive(w) for w in workers):
        assert time.monotonic() < deadline, "workers outlived their driver"
        time.sleep(0.1)


@pytest.mark.skipif(not Path("/proc/self/task").is_dir(), reason="reads /proc")
def test_sigterm_stops_the_run_cleanly_and_it_resumes(tmp_path: Path) -> None:
    prompts = _books(tmp_path)
    out = tmp_path / "out"
    command = _stub_batch_command(prompts, out, "--export", "none", scenes=8)
    run = subprocess.Popen(
        command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=REPO, env=_stub_env()
    )
    _wait_for_lines(out / MANIFEST, 1, run)
    workers = _workers_of(run.pid)
    run.terminate()
    _, stderr = run.communicate(timeout=60)
    assert run.returncode == 130 and "run the same command again to resume" in stderr
    _assert_gone(workers)
    assert not [p for p in (out / SCENES_DIR).iterdir() if p.name.startswith(".")]
    made = len(list((out / SCENES_DIR).iterdir()))
    assert made == len((out / MANIFEST).read_text().splitlines()) < 8
    resumed = run_batch(prompts, out, per_prompt=8, options=NO_EXPORTS, scene_maker=stub_scene)
    assert (resumed.already_done, resumed.made) == (made, 8 - made)


def _kill_halfway_then_resume(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, *extra: str, scenes: int = 12) -> None:
    """Kill a run from the command line, driver and workers at once, then run the same command again (in this
    process: the resumed run is not killed)."""
    prompts = _books(tmp_path)
    out = tmp_path / "batch"
    args = _batch_args(prompts, out, "--export", "mjcf,urdf", *extra, scenes=scenes)
    run = subprocess.Popen(
        _stub_batch_command(prompts, out, "--export", "mjcf,urdf", *extra, scenes=scenes),
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        start_new_session=True,
        cwd=REPO,
        env=_stub_env(),
    )
    manifest = out / MANIFEST
    _wait_for_lines(manifest, 4, run)
    os.killpg(run.pid, signal.SIGKILL)  # the driver and every worker at once
    run.wait(timeout=30)
    done_when_killed = len(manifest.read_text().splitlines())
    assert 4 <= done_when_killed < scenes
    # What a worker would leave if killed while writing: a staging folder (and a cut-off manifest line).
    prefix = sorted(p.name for p in (out / SCENES_DIR).iterdir() if not p.name.startswith("."))[0].rsplit("_", 1)[0]
    (out / SCENES_DIR / f".{prefix}_{scenes - 1:03d}.x1y2.partial").mkdir()
    with manifest.open("a") as handle:
        handle.write('{"key": "000-a-stack')

    resumed = _invoke_stub_batch(monkeypatch, args)
    assert resumed.exit_code == 0, resumed.output
    said = resumed.stdout.replace("\n", " ")
    assert f"{scenes - done_when_killed} scene(s) made, {done_when_killed} already there" in said

    folders = sorted((out / SCENES_DIR).iterdir())
    assert len(folders) == scenes and not [f for f in folders if f.name.startswith(".")]
    records = [json.loads(line) for line in manifest.read_text().splitlines()]
    assert sorted(r["key"] for r in records) == [f.name for f in folders]  # each scene once, no duplicates
    for folder in folders:
        scene = json.loads((folder / "scene.json").read_text())
        assert json.loads((folder / RECORD).read_text())["seed"] == scene["seed"]
    # the same manifest as a run that was never interrupted
    uninterrupted = run_batch(
        prompts,
        tmp_path / "uninterrupted",
        per_prompt=scenes,
        options=Options(exports=("mjcf", "urdf")),
        scene_maker=stub_scene,
    )
    assert uninterrupted.made == scenes
    assert sorted(manifest.read_text().splitlines()) == sorted(
        (tmp_path / "uninterrupted" / MANIFEST).read_text().splitlines()
    )


@pytest.mark.long
def test_killed_local_batch_resumes_to_exactly_the_planned_scenes(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    _kill_halfway_then_resume(tmp_path, monkeypatch)


@pytest.mark.slow
@pytest.mark.long
@pytest.mark.timeout(180)
def test_killed_ray_batch_resumes_to_exactly_the_planned_scenes(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    pytest.importorskip("ray")
    _kill_halfway_then_resume(tmp_path, monkeypatch, "--ray")


@pytest.mark.slow
@pytest.mark.long
@pytest.mark.physics
@pytest.mark.timeout(240)
def test_a_real_batch_from_the_command_line_makes_resting_scenes_with_their_exports(tmp_path: Path) -> None:
    """The one end-to-end run with real scenes, by the real executable: a scene for each of two worker processes,
    then the same command again (in this process: it has nothing to make)."""
    prompts = _books(tmp_path)
    out = tmp_path / "batch"
    args = _batch_args(prompts, out, "--export", "mjcf,urdf", scenes=2)
    made = subprocess.run(
        _batch_command(prompts, out, "--export", "mjcf,urdf", scenes=2), capture_output=True, text=True, timeout=220
    )
    assert made.returncode == 0, made.stderr
    assert "2 scene(s) made, 0 already there, 0 failed" in made.stdout.replace("\n", " ")
    folders = sorted((out / SCENES_DIR).iterdir())
    assert len(folders) == 2 and not [f for f in folders if f.name.startswith(".")]
    records = [json.loads(line) for line in (out / MANIFEST).read_text().splitlines()]
    assert sorted(r["key"] for r in records) == [f.name for f in folders]
    for folder in folders:
        scene = load_scene(folder)
        assert len(scene.placed) == 3
        assert scene.metrics["settle_distance_m"] < 0.005
        assert json.loads((folder / RECORD).read_text())["seed"] == scene.seed
        assert (folder / "mjcf" / "scene.xml").is_file() and (folder / "urdf" / "bodies.json").is_file()
    again = CliRunner().invoke(app, args)
    assert again.exit_code == 0, again.output
    assert "0 scene(s) made, 2 already there, 0 failed" in again.stdout.replace("\n", " ")


def test_ray_address_form_is_read_as_two_options() -> None:
    from physcensis.cli.app import _ray_address_form

    assert _ray_address_form(["batch", "p.txt", "--ray=auto", "--workers", "2"]) == [
        "batch",
        "p.txt",
        "--ray",
        "--ray-address",
        "auto",
        "--workers",
        "2",
    ]
    assert _ray_address_form(["generate", "--ray=auto"]) == ["generate", "--ray=auto"]  # only batch has it
