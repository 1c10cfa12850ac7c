"""`physcensis demo` and `physcensis demo-batch`: verified pick-and-place demonstrations recorded as datasets."""

from __future__ import annotations

import re
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from rich.markup import escape

from physcensis.cli.errors import ExitCode, err_console, fail, finish, reports_errors
from physcensis.cli.options import ApiKeyEnvOption, ProviderOption, console, output_dir
from physcensis.errors import PhyscensisError
from physcensis.settings import API_KEY_ENV, DEFAULT_PROVIDER

if TYPE_CHECKING:
    from physcensis.robot.demos import DemoSettings

TaskOption = Annotated[
    str,
    typer.Option(
        "--task",
        help='what to do: "pick cup_0 place-on plate_2", or "pick up the leftmost cup and place it on the '
        'rightmost plate" (left/right/front/back as seen in the default render; near/far from the robot)',
    ),
]
EpisodesOption = Annotated[int, typer.Option("--episodes", min=1, help="attempts per scene (seeds seed, seed+1, ...)")]
SeedOption = Annotated[int, typer.Option(min=0, help="seed of the first attempt")]
MountOption = Annotated[
    str,
    typer.Option(
        "--mount",
        help="where the arm stands: auto (a longer edge of the support), or its front (+x), back (-x), left (+y) or "
        "right (-y) edge",
    ),
]
OffsetOption = Annotated[
    float, typer.Option("--mount-offset", help="metres along the edge from its middle (+ towards +x or +y)")
]
VlmOption = Annotated[
    str | None,
    typer.Option("--vlm", help="a vision model (OpenAI-compatible) that must also judge each episode a success"),
]
BaseUrlOption = Annotated[str | None, typer.Option(help="the VLM's server, e.g. http://localhost:8000/v1")]
ImagesOption = Annotated[
    str, typer.Option("--images", help="camera frames recorded per step, HxW (e.g. 128x128), or none")
]


def _image_size(text: str, flag: str = "--images", largest: int = 1024) -> tuple[int, int] | None:
    if text.strip().lower() == "none":
        return None
    match = re.fullmatch(r"\s*(\d{1,4})\s*[xX]\s*(\d{1,4})\s*", text)
    if not match or not all(16 <= int(v) <= largest for v in match.groups()):
        raise fail(f"{flag} {text!r}: give HxW with each side in 16..{largest} (e.g. 128x128), or none")
    return int(match[1]), int(match[2])


def _settings(
    task: str,
    episodes: int,
    seed: int,
    mount: str,
    images: str,
    videos: list[int],
    *,
    video_size: str = "none",
    mount_offset: float,
    vlm: str | None,
    base_url: str | None,
    provider: str,
    api_key_env: str,
) -> DemoSettings:
    from physcensis.robot.demos import DemoSettings
    from physcensis.robot.panda import MOUNT_EDGES, Mount

    if mount not in MOUNT_EDGES:
        raise fail(f"--mount {mount!r}: give one of {', '.join(MOUNT_EDGES)}")
    if not task.strip():
        raise fail("--task is empty: say what to pick and where to place it")
    bad = [v for v in videos if not 0 <= v < episodes]
    if bad:
        raise fail(f"--video {bad[0]}: there are episodes 0..{episodes - 1}")
    return DemoSettings(
        task=task,
        episodes=episodes,
        seed=seed,
        mount=Mount(edge=mount, offset=mount_offset),
        images=_image_size(images),
        videos=tuple(videos),
        video_size=_image_size(video_size, "--video-size", 2048),
        vlm=vlm,
        vlm_base_url=base_url,
        provider=provider,
        api_key_env=api_key_env,
    )


@reports_errors
def demo(
    scene: Annotated[Path, typer.Argument(help="a scene folder (scene.json and its mjcf/ export)")],
    task: TaskOption,
    out: Annotated[Path, typer.Option("--out", "-o", help="folder for demos.hdf5, report.json and videos")],
    episodes: EpisodesOption = 1,
    seed: SeedOption = 0,
    mount: MountOption = "auto",
    images: ImagesOption = "128x128",
    video: Annotated[list[int] | None, typer.Option("--video", help="write episode K as an MP4 (repeatable)")] = None,
    video_size: Annotated[
        str,
        typer.Option(
            "--video-size",
            help="the MP4s' size, HxW (e.g. 480x640), filmed again by exact replay; none: the recorded frames",
        ),
    ] = "none",
    overwrite: Annotated[bool, typer.Option("--overwrite", help="replace an earlier run's outputs")] = False,
    mount_offset: OffsetOption = 0.0,
    vlm: VlmOption = None,
    base_url: BaseUrlOption = None,
    provider: ProviderOption = DEFAULT_PROVIDER,
    api_key_env: ApiKeyEnvOption = API_KEY_ENV,
) -> None:
    """Record pick-and-place demonstrations of a Panda arm on one scene, each checked by the verifier."""
    from physcensis.robot.demos import refuse_scene_as_out, run_scene, scene_folders
    from physcensis.robot.world import read_scene_folder

    settings = _settings(
        task,
        episodes,
        seed,
        mount,
        images,
        video or [],
        video_size=video_size,
        mount_offset=mount_offset,
        vlm=vlm,
        base_url=base_url,
        provider=provider,
        api_key_env=api_key_env,
    )
    folders = scene_folders(scene)
    if len(folders) != 1 or folders[0] != scene:
        raise fail(f"{scene}: not a scene folder (use demo-batch for a folder of scenes)")
    read_scene_folder(scene)  # its mjcf/ must belong to its scene.json, before anything is written
    refuse_scene_as_out(out)
    output_dir(out, overwrite)
    try:
        with console.status(f"{episodes} episode(s) on {scene.name}…"):
            report = run_scene(scene, out, settings, overwrite=overwrite)
    except KeyboardInterrupt:
        raise fail("stopped; nothing was written", ExitCode.INTERRUPTED) from None
    _print_report(report)
    raise finish(report["succeeded"] > 0)


@reports_errors
def demo_batch(
    scenes: Annotated[Path, typer.Argument(help="a folder of scene folders (e.g. a batch's scenes/)")],
    task: TaskOption,
    out: Annotated[Path, typer.Option("--out", "-o", help="folder for scenes/, demos.hdf5 and report.json")],
    episodes: EpisodesOption = 1,
    workers: Annotated[int, typer.Option(min=1, help="parallel worker processes")] = 1,
    seed: SeedOption = 0,
    mount: MountOption = "auto",
    images: ImagesOption = "128x128",
    mount_offset: OffsetOption = 0.0,
    vlm: VlmOption = None,
    base_url: BaseUrlOption = None,
    provider: ProviderOption = DEFAULT_PROVIDER,
    api_key_env: ApiKeyEnvOption = API_KEY_ENV,
) -> None:
    """Demonstrations on every scene folder below SCENES. Re-running the same command resumes a stopped run."""
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    from physcensis.robot.demos import check_batch_out, run_batch, scene_folders
    from physcensis.robot.world import read_scene_folder

    settings = _settings(
        task,
        episodes,
        seed,
        mount,
        images,
        [],
        mount_offset=mount_offset,
        vlm=vlm,
        base_url=base_url,
        provider=provider,
        api_key_env=api_key_env,
    )
    folders = scene_folders(scenes)
    for folder in folders:  # every scene's mjcf/ must belong to its scene.json, before anything is written
        read_scene_folder(folder)
    check_batch_out(out, folders)
    total = len(folders)
    columns = (TextColumn("scenes"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn())
    progress = Progress(*columns, console=err_console, transient=False)
    handle = progress.add_task("scenes", total=total)

    def done(scene: str, result: dict[str, Any] | str) -> None:
        progress.update(handle, advance=1)
        if isinstance(result, str):
            progress.console.print(f"[red]failed[/] {escape(scene)}: {escape(result)}", highlight=False)

    progress.start()
    try:
        summary = run_batch(scenes, out, settings, workers=workers, on_scene=done)
    except (PhyscensisError, KeyboardInterrupt) as exc:
        progress.stop()
        if isinstance(exc, KeyboardInterrupt):
            raise fail("stopped; run the same command again to resume", ExitCode.INTERRUPTED) from None
        raise
    progress.stop()
    _print_report(summary)
    raise finish(summary["succeeded"] > 0)


def _print_report(report: dict[str, Any]) -> None:
    rate = report["success_rate"] * 100
    console.print(f"{report['succeeded']}/{report['attempted']} episodes succeeded ({rate:.0f} %)")
    for episode in report.get("episodes", []):
        if not episode["success"]:
            console.print(f"  [red]{escape(episode['stage'])}[/]: {escape(str(episode['reason']))}", highlight=False)
    for stage, count in report.get("failures_by_stage", {}).items():
        console.print(f"  [red]{escape(stage)}[/]: {count} failed")
    timing = ", ".join(f"{k} {v:.1f} s" for k, v in report["seconds"].items() if v is not None)
    if timing:
        console.print(f"median per episode: {timing}")


@reports_errors
def demo_export(
    dataset: Annotated[Path, typer.Argument(help="a demos.hdf5 written by demo or demo-batch")],
    out: Annotated[Path, typer.Option("--out", "-o", help="a new folder for the LeRobot dataset")],
    repo_id: Annotated[str, typer.Option("--repo-id", help="the dataset's name, owner/name")] = "physcensis/demos",
    include_failed: Annotated[
        bool, typer.Option("--include-failed", help="convert the episodes the verifier rejected too")
    ] = False,
) -> None:
    """Convert recorded demonstrations to a LeRobot dataset (needs the lerobot extra)."""
    from physcensis.robot.lerobot_export import export_lerobot

    if not dataset.is_file():
        raise fail(f"{dataset}: no such dataset file")
    try:
        with console.status(f"converting {dataset.name} to LeRobot…"):
            summary = export_lerobot(dataset, out, repo_id=repo_id, include_failed=include_failed)
    except KeyboardInterrupt:
        raise fail("stopped; nothing was written", ExitCode.INTERRUPTED) from None
    skipped = f" ({summary.skipped_failed} failed episodes left out)" if summary.skipped_failed else ""
    console.print(f"{summary.episodes} episodes, {summary.frames} frames → {escape(str(summary.out))}{skipped}")
