"""The batch command on hostile ground: planted links, changed settings on resume, stuck scenes, secrets, leftovers.

Most tests use `stub_scene` (tests/batch/stub_scenes.py) instead of real scenes: it runs in the spawned worker
processes, makes a tiny scene folder at once, and for a prompt containing "stuck" hangs inside a C call that holds the
GIL, as a scene stuck in MuJoCo would: only killing the process stops it.
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import time
from dataclasses import asdict
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from physcensis.batch import FAILURES, MANIFEST, RECORD, SCENES_DIR, BatchError, Options, Outcome, Task, run_batch
from physcensis.batch.prompts import PromptSpec
from physcensis.batch.worker import make_scene
from physcensis.settings import SettingsError
from tests.agent.fake_server import MUG_AND_BOOK, FakeOpenAI, Reply, use_loopback_only
from tests.batch.stub_scenes import STUCK_PID_FILE, named_formats, stub_scene

NO_EXPORTS = Options(exports=("none",))


def _specs(*prompts: str) -> list[PromptSpec]:
    return [PromptSpec(f"p{i}", prompt) for i, prompt in enumerate(prompts)]


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except (OSError, IndexError):
        return False
    return state != "Z"


# -- the lock, the manifest and the failures file are never followed through a link --------------------------------


def test_a_planted_lock_link_is_refused_and_its_target_untouched(tmp_path: Path) -> None:
    victim = tmp_path / "precious.txt"
    victim.write_text("years of work\n")
    out = tmp_path / "out"
    out.mkdir()
    (out / ".batch.lock").symlink_to(victim)
    with pytest.raises(BatchError, match=r"\.batch\.lock: is a symbolic link"):
        run_batch(_specs("a cup"), out, options=NO_EXPORTS, scene_maker=stub_scene)
    assert victim.read_text() == "years of work\n"
    assert not (out / SCENES_DIR).exists() and not (out / MANIFEST).exists()


def test_a_dangling_lock_link_does_not_create_its_target(tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    (out / ".batch.lock").symlink_to(tmp_path / "created-through-the-link")
    with pytest.raises(BatchError, match="symbolic link"):
        run_batch(_specs("a cup"), out, options=NO_EXPORTS, scene_maker=stub_scene)
    assert not (tmp_path / "created-through-the-link").exists()


def test_a_lock_that_is_not_a_file_is_refused_without_hanging(tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    os.mkfifo(out / ".batch.lock")  # opening a FIFO for writing would wait for a reader forever
    with pytest.raises(BatchError, match="not a regular file"):
        run_batch(_specs("a cup"), out, options=NO_EXPORTS, scene_maker=stub_scene)


def test_an_existing_lock_file_is_reused_not_truncated(tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    (out / ".batch.lock").write_text("left by an earlier run\n")
    run_batch(_specs("a cup"), out, options=NO_EXPORTS, scene_maker=stub_scene)
    assert (out / ".batch.lock").read_text() == "left by an earlier run\n"


@pytest.mark.parametrize("name", [MANIFEST, FAILURES])
def test_a_manifest_or_failures_link_is_refused_and_its_target_untouched(tmp_path: Path, name: str) -> None:
    victim = tmp_path / "precious.jsonl"
    victim.write_text('{"key": "mine"}\n')
    out = tmp_path / "out"
    out.mkdir()
    (out / name).symlink_to(victim)
    with pytest.raises(BatchError, match=rf"{name}: is a symbolic link"):
        run_batch(_specs("a cup"), out, options=NO_EXPORTS, scene_maker=stub_scene)
    assert victim.read_text() == '{"key": "mine"}\n'
    assert (out / name).is_symlink()


# -- a resume with other export formats is refused ------------------------------------------------------------------


def test_resuming_with_another_export_is_refused_naming_the_folder(tmp_path: Path) -> None:
    out = tmp_path / "out"
    run_batch(_specs("a cup"), out, options=Options(exports=("mjcf", "urdf")), scene_maker=stub_scene)
    record = json.loads((out / MANIFEST).read_text())
    assert record["exports"] == ["mjcf", "urdf"]
    with pytest.raises(
        BatchError,
        match=r"p0_000: was made with --export mjcf,urdf, this run asks for "
        r"--export none",
    ):
        run_batch(_specs("a cup"), out, options=NO_EXPORTS, scene_maker=stub_scene)
    with pytest.raises(BatchError, match=r"was made with --export mjcf,urdf, this run asks for --export glb"):
        run_batch(_specs("a cup"), out, options=Options(exports=("glb",)), scene_maker=stub_scene)
    # the same formats in another order are the same run
    again = run_batch(_specs("a cup"), out, options=Options(exports=("urdf", "mjcf")), scene_maker=stub_scene)
    assert (again.already_done, again.made) == (1, 0)


def test_old_records_without_formats_count_as_the_default_all(tmp_path: Path) -> None:
    out = tmp_path / "out"
    run_batch(_specs("a cup"), out, options=NO_EXPORTS, scene_maker=stub_scene)
    record_path = out / SCENES_DIR / "p0_000" / RECORD
    old = json.loads(record_path.read_text())
    del old["exports"]
    record_path.write_text(json.dumps(old))
    with pytest.raises(BatchError, match=r"p0_000: was made with --export .*mjcf.*, this run asks for --export none"):
        run_batch(_specs("a cup"), out, options=NO_EXPORTS, scene_maker=stub_scene)
    again = run_batch(_specs("a cup"), out, options=Options(exports=("all",)), scene_maker=stub_scene)
    assert (again.already_done, again.made) == (1, 0)


def test_a_real_scene_records_its_formats(tmp_path: Path) -> None:
    task = Task("books_000", "books", "a stack of 3 books", "table:0.6x0.5", seed=3)
    outcome = make_scene(task, Options(exports=("urdf", "mjcf")))
    assert outcome.ok and outcome.record["exports"] == ["mjcf", "urdf"]
    assert json.loads(outcome.files[RECORD])["exports"] == ["mjcf", "urdf"]
    assert any(name.startswith("urdf/") for name in outcome.files) and not any(
        name.endswith(".glb") for name in outcome.files
    )


# -- the scene timeout ---------------------------------------------------------------------------------------------


@pytest.mark.long  # real worker processes
@pytest.mark.timeout(90)
@pytest.mark.parametrize("workers", [1, 2])
def test_a_stuck_scene_is_killed_recorded_and_the_others_are_made(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, workers: int
) -> None:
    pid_file = tmp_path / "stuck.pids"
    monkeypatch.setenv(STUCK_PID_FILE, str(pid_file))  # spawned workers take the environment along
    specs = _specs("a cup", "a stuck cup", "a mug", "a plate", "a bowl")
    out = tmp_path / "out"
    start = time.monotonic()
    summary = run_batch(
        specs, out, per_prompt=1, workers=workers, options=NO_EXPORTS, scene_timeout_s=2.5, scene_maker=stub_scene
    )
    assert time.monotonic() - start < 45  # not STUCK_FOR_S
    failures = [json.loads(line) for line in (out / FAILURES).read_text().splitlines()]
    assert (summary.made, summary.failed) == (4, 1), failures
    assert [(f["key"], f["reason"]) for f in failures] == [("p1_000", "took longer than the scene timeout of 2.5 s")]
    assert sorted(p.name for p in (out / SCENES_DIR).iterdir()) == ["p0_000", "p2_000", "p3_000", "p4_000"]
    assert len((out / MANIFEST).read_text().splitlines()) == 4
    stuck = [int(pid) for pid in pid_file.read_text().split()]
    assert len(stuck) == 1  # tried once: a timeout is a failure, not a retry
    deadline = time.monotonic() + 10
    while _alive(stuck[0]):
        assert time.monotonic() < deadline, "the stuck worker still runs"
        time.sleep(0.1)


@pytest.mark.timeout(60)
@pytest.mark.parametrize("scene_timeout_s", [None, 100.0])
def test_an_interrupted_run_does_not_wait_for_a_stuck_scene(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, scene_timeout_s: float | None
) -> None:
    pid_file = tmp_path / "stuck.pids"
    monkeypatch.setenv(STUCK_PID_FILE, str(pid_file))

    def interrupt(outcome: Outcome, summary: object) -> None:
        started = time.monotonic()
        while not pid_file.is_file():  # interrupt only once the stuck scene is really running
            assert time.monotonic() - started < 20, "the stuck scene never started"
            time.sleep(0.05)
        raise KeyboardInterrupt  # as Ctrl-C or SIGTERM in the driver

    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        run_batch(
            _specs("a stuck cup", "a cup", "a mug"),
            tmp_path / "out",
            workers=2,
            options=NO_EXPORTS,
            scene_timeout_s=scene_timeout_s,
            scene_maker=stub_scene,
            on_outcome=interrupt,
        )
    assert time.monotonic() - start < 30  # not STUCK_FOR_S
    stuck = int(pid_file.read_text().split()[0])
    deadline = time.monotonic() + 10
    while _alive(stuck):
        assert time.monotonic() < deadline, "the stuck worker still runs"
        time.sleep(0.1)


@pytest.mark.slow
@pytest.mark.timeout(120)
@pytest.mark.long
def test_scene_timeout_stops_real_scenes_from_the_command_line(tmp_path: Path) -> None:
    """Real scenes, each in a worker process that is killed at the timeout; the command runs in this process."""
    from typer.testing import CliRunner

    from physcensis.cli import app

    prompts = tmp_path / "p.txt"
    prompts.write_text("a stack of 3 books\n")
    out = tmp_path / "out"
    args = ["batch", str(prompts), "--per-prompt", "2", "--export", "none", "--scene-timeout", "0.3", "--out", str(out)]
    run = CliRunner().invoke(app, args)
    assert run.exit_code == 1, run.output
    assert "0 scene(s) made, 0 already there, 2 failed" in run.stdout.replace("\n", " ")
    assert "took longer than the scene timeout of 0.3 s" in run.stderr
    reasons = [json.loads(line)["reason"] for line in (out / FAILURES).read_text().splitlines()]
    assert reasons == ["took longer than the scene timeout of 0.3 s"] * 2
    assert list((out / SCENES_DIR).iterdir()) == []


@pytest.mark.slow
@pytest.mark.timeout(180)
@pytest.mark.long
def test_a_stuck_ray_task_is_cancelled_and_recorded(tmp_path: Path) -> None:
    ray = pytest.importorskip("ray")
    assert not ray.is_initialized()
    out = tmp_path / "out"
    summary = run_batch(
        _specs("a cup", "a stuck cup", "a mug"),
        out,
        use_ray=True,
        workers=2,
        options=NO_EXPORTS,
        scene_timeout_s=2.0,
        scene_maker=stub_scene,
    )
    assert (summary.made, summary.failed) == (2, 1)
    failure = json.loads((out / FAILURES).read_text())
    assert (failure["key"], failure["reason"]) == ("p1_000", "took longer than the scene timeout of 2 s")
    assert not ray.is_initialized()  # the run started its own Ray, and shut it down


@given(
    value=st.one_of(st.floats(max_value=0.0), st.just(math.inf), st.just(math.nan), st.booleans(), st.text(max_size=3))
)
@settings(max_examples=40, deadline=None)
def test_timeouts_that_are_not_positive_seconds_are_refused_up_front(
    tmp_path_factory: pytest.TempPathFactory, value: object
) -> None:
    out = tmp_path_factory.mktemp("t") / "out"
    with pytest.raises(BatchError, match="--scene-timeout must be a positive number of seconds"):
        run_batch(_specs("a cup"), out, options=NO_EXPORTS, scene_timeout_s=value, scene_maker=stub_scene)  # type: ignore[arg-type]
    with pytest.raises(SettingsError, match="llm_timeout_s must be a positive number of seconds"):
        Options.of(exports=("none",), llm_timeout_s=value)  # the run's settings refuse it before any batch
    assert not out.exists()


def test_unknown_export_formats_are_refused_before_any_scene(tmp_path: Path) -> None:
    with pytest.raises(BatchError, match="--export: unknown export format 'stl'"):
        run_batch(_specs("a cup"), tmp_path / "out", options=Options(exports=("stl",)), scene_maker=stub_scene)
    assert not (tmp_path / "out").exists()


# -- the LLM timeout reaches every worker's agent ------------------------------------------------------------------


def test_the_cli_carries_both_timeouts_to_the_run(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from typer.testing import CliRunner

    import physcensis.batch
    from physcensis.cli import app

    seen: dict[str, object] = {}

    def fake_run_batch(specs: object, out: object, **kwargs: object) -> object:
        seen.update(kwargs)
        raise BatchError("stop here")

    monkeypatch.setattr(physcensis.batch, "run_batch", fake_run_batch)
    prompts = tmp_path / "p.txt"
    prompts.write_text("a cup\n")
    args = ["batch", str(prompts), "--out", str(tmp_path / "out"), "--export", "none"]
    CliRunner().invoke(app, [*args, "--llm-timeout", "12.5", "--scene-timeout", "40"])
    options = seen["options"]
    assert isinstance(options, Options) and (options.settings.models.llm_timeout_s, options.scene_timeout_s) == (
        12.5,
        40.0,
    )
    CliRunner().invoke(app, args)
    options = seen["options"]
    assert isinstance(options, Options) and (options.settings.models.llm_timeout_s, options.scene_timeout_s) == (
        300.0,
        None,
    )


def test_the_worker_gives_the_llm_timeout_to_generate(monkeypatch: pytest.MonkeyPatch) -> None:
    import physcensis.api

    seen: dict[str, object] = {}

    def fake_generate(prompt: str, **kwargs: object) -> object:
        seen.update(kwargs)
        raise BatchError("no server here")

    monkeypatch.setattr(physcensis.api, "generate", fake_generate)
    task = Task("desk_000", "desk", "a mug", "table:0.6x0.6", seed=1)
    outcome = make_scene(task, Options.of(exports=("none",), llm="some-model", llm_timeout_s=7.0))
    assert not outcome.ok and outcome.record["reason"] == "no server here"
    models = seen["settings"].models  # type: ignore[attr-defined]
    assert models.llm == "some-model" and models.llm_timeout_s == 7.0


# -- secrets ---------------------------------------------------------------------------------------------------------

KEY = "sk-hardening-batch-key-0123456789"
PASSWORD = "pw-in-the-base-url-s3cr3t"


def _with_password(base_url: str) -> str:
    return base_url.replace("http://", f"http://alice:{PASSWORD}@")


def _batch_cli(prompts: Path, out: Path, base_url: str, *extra: str) -> subprocess.CompletedProcess[str]:
    exe = Path(sys.executable).with_name("physcensis")
    env = {**os.environ, "OPENAI_API_KEY": KEY, "NO_PROXY": "127.0.0.1,localhost"}
    for name in ("HTTP_PROXY", "HTTPS_PROXY", "ALL_PROXY", "http_proxy", "https_proxy", "all_proxy", "OPENAI_BASE_URL"):
        env.pop(name, None)
    return subprocess.run(
        [
            str(exe),
            "batch",
            str(prompts),
            "--out",
            str(out),
            "--export",
            "none",
            "--llm",
            "fake-model",
            "--base-url",
            base_url,
            "--llm-timeout",
            "20",
            "--hint",
            "off",  # test_hint.py tests the draft
            *extra,
        ],
        capture_output=True,
        text=True,
        timeout=240,
        env=env,
    )


def _assert_no_secret_in(folder: Path, *texts: str) -> None:
    for text in texts:
        assert PASSWORD not in text and KEY not in text
    for path in folder.rglob("*") if folder.exists() else []:
        if path.is_file():
            data = path.read_bytes()
            assert PASSWORD.encode() not in data and KEY.encode() not in data, path


@pytest.mark.slow
@pytest.mark.long
def test_a_dead_server_with_credentials_in_the_url_is_reported_without_them(tmp_path: Path) -> None:
    with FakeOpenAI() as server:
        dead = _with_password(server.base_url)  # the port is closed once the server is
    prompts = tmp_path / "p.txt"
    prompts.write_text("a mug\n")
    run = _batch_cli(prompts, tmp_path / "out", dead)
    assert run.returncode == 2 and "could not connect" in run.stderr
    assert "127.0.0.1" in run.stderr  # the server is still named, without its credentials
    _assert_no_secret_in(tmp_path / "out", run.stdout, run.stderr)
    assert not (tmp_path / "out").exists()


def test_the_api_refuses_a_dead_server_without_showing_credentials(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    use_loopback_only(monkeypatch, KEY)
    with FakeOpenAI() as server:
        dead = _with_password(server.base_url)
    with pytest.raises(BatchError) as refused:
        run_batch(_specs("a mug"), tmp_path / "out", options=Options.of(exports=("none",), llm="m", base_url=dead))
    assert "could not connect" in str(refused.value)
    assert PASSWORD not in str(refused.value) and KEY not in str(refused.value)


@pytest.mark.slow
@pytest.mark.physics
@pytest.mark.timeout(240)
@pytest.mark.long
def test_secrets_appear_nowhere_in_the_folder_or_output(tmp_path: Path) -> None:
    """One scene is made, one fails on a reply that quotes the key and the URL with its password. Nothing written
    (scene folders and transcripts included) or printed holds either."""
    prompts = tmp_path / "p.jsonl"
    prompts.write_text(json.dumps({"id": "desk", "prompt": "a mug and a book", "support": "table:0.6x0.6"}) + "\n")
    with FakeOpenAI([MUG_AND_BOOK]) as server:
        url = _with_password(server.base_url)
        server.add_replies(Reply(status=400, error=f"rejected {url} with Authorization: Bearer {KEY}"))
        run = _batch_cli(prompts, tmp_path / "out", url, "--per-prompt", "2")
    assert run.returncode == 1, run.stderr
    out = tmp_path / "out"
    assert [json.loads(line)["key"] for line in (out / MANIFEST).read_text().splitlines()] == ["desk_000"]
    failure = json.loads((out / FAILURES).read_text())
    assert failure["key"] == "desk_001" and "HTTP 400" in failure["reason"]
    assert "rejected http://[redacted]@127.0.0.1" in failure["reason"] and "Bearer [redacted]" in failure["reason"]
    assert "rejected http://[redacted]@127.0.0.1" in " ".join(run.stderr.split())  # shown as written, not as markup
    _assert_no_secret_in(out, run.stdout, run.stderr)


def test_records_are_redacted_before_they_are_written_or_shown(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("OPENAI_API_KEY", KEY)
    shown: list[str] = []
    url = f"http://alice:{PASSWORD}@127.0.0.1:9/v1"
    options = Options.of(exports=("none",), llm="m", base_url=url)
    monkeypatch.setattr("physcensis.batch.driver.check_llm", lambda options, on_ray: None)  # no server here
    run_batch(
        _specs("a cup", "a mug"),
        tmp_path / "out",
        options=options,
        scene_maker=leaky,
        on_outcome=lambda outcome, summary: shown.append(json.dumps(outcome.record)),
    )
    _assert_no_secret_in(tmp_path / "out", *shown)
    assert len(shown) == 2


def leaky(task: Task, options: Options) -> Outcome:
    """A scene maker whose records quote the secrets (as an exception message from a server might)."""
    quote = f"server {options.settings.models.base_url} said: key {os.environ['OPENAI_API_KEY']} is wrong"
    record = {
        **asdict(task),
        "scene": f"{SCENES_DIR}/{task.key}",
        "agent": options.agent,
        "exports": named_formats(options),
    }
    if task.prompt == "a cup":
        return Outcome(task, {**record, "ok": False, "reason": quote})
    record = {**record, "ok": True, "note": quote}
    return Outcome(task, record, {"scene.json": b"{}\n", RECORD: json.dumps(record).encode()})


# -- leftovers of a killed run in the batch folder itself ------------------------------------------------------------


def test_temporary_manifest_files_left_by_a_kill_are_removed_on_resume(tmp_path: Path) -> None:
    out = tmp_path / "out"
    run_batch(_specs("a cup"), out, options=NO_EXPORTS, scene_maker=stub_scene)
    leftovers = [
        out / ".manifest.jsonl.k3j_x9a2.tmp",
        out / ".failures.jsonl.4242.ab12cd34.tmp",
        out / ".manifest.jsonl.99999.zz_top00.tmp",
    ]
    for path in leftovers:
        path.write_text('{"key": "half')
    (out / SCENES_DIR / ".p0_001.4242.ab12cd.partial").mkdir()
    (out / SCENES_DIR / ".p0_000.4242.old").mkdir()
    keep = [out / "notes.tmp", out / ".manifest.jsonl.notes", out / ".other.jsonl.abc.tmp"]
    for path in keep:
        path.write_text("mine")
    summary = run_batch(_specs("a cup"), out, per_prompt=2, options=NO_EXPORTS, scene_maker=stub_scene)
    assert (summary.already_done, summary.made) == (1, 1)
    assert not [p for p in leftovers if p.exists()]
    assert sorted(p.name for p in (out / SCENES_DIR).iterdir()) == ["p0_000", "p0_001"]
    assert all(p.read_text() == "mine" for p in keep)


def test_a_users_folder_is_not_taken_for_a_batch_folder(tmp_path: Path) -> None:
    out = tmp_path / "mine"
    out.mkdir()
    (out / "manifest.txt").write_text("my own")
    with pytest.raises(BatchError, match="not a batch folder"):
        run_batch([PromptSpec("a", "a mug")], out, per_prompt=1)
    assert [p.name for p in out.iterdir()] == ["manifest.txt"]
    link = tmp_path / "link"
    link.symlink_to(out)
    with pytest.raises(BatchError, match="symbolic link"):
        run_batch([PromptSpec("a", "a mug")], link, per_prompt=1)
