"""`physcensis view`: a scene folder in a live 3-D viewer in the browser (viser), or checked without one."""

from __future__ import annotations

import time
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from physcensis.cli.errors import ExitCode, finish, print_warning, reports_errors
from physcensis.cli.options import LibraryOption, console, scene_file, with_libraries
from physcensis.errors import PhyscensisError

if TYPE_CHECKING:  # the viewer's modules load MuJoCo and the catalogue: imported when the command runs
    from physcensis.viewer.episode import EpisodeTrack
    from physcensis.viewer.playback import SettlePlayback
    from physcensis.viewer.robot_view import RobotView
    from physcensis.viewer.scene_view import SceneView

MAX_CHECK_STEPS = 100_000


@reports_errors
def view(
    scene_path: Annotated[Path, typer.Argument(metavar="SCENE", help="scene.json or a scene folder")],
    episode: Annotated[
        str | None,
        typer.Option(
            "--episode",
            metavar="DATASET[:INDEX]",
            help="a recorded robot demonstration of this scene (an HDF5 dataset of `physcensis demo`, episode INDEX, "
            "default 0): a button plays its recorded object and arm poses",
        ),
    ] = None,
    host: Annotated[
        str, typer.Option(help="address to serve on: 127.0.0.1 is this machine only, 0.0.0.0 every network")
    ] = "127.0.0.1",
    port: Annotated[int, typer.Option(min=0, max=65535, help="port to serve on (0: any free port)")] = 0,
    check: Annotated[
        bool,
        typer.Option(
            "--check",
            help="no server: build the view, the simulation (and the episode), play --steps frames of the settle, "
            "print what would be shown and exit (for tests and headless machines)",
        ),
    ] = False,
    steps: Annotated[
        int, typer.Option("--steps", min=1, max=MAX_CHECK_STEPS, help="frames of 1/30 s that --check plays")
    ] = 30,
    library: LibraryOption = None,
) -> None:
    """Show a scene in a live 3-D viewer in the browser: click an object for its facts; play its settle (and a
    recorded episode) in real time. Ctrl-C stops the server."""
    from physcensis.viewer.playback import SettlePlayback
    from physcensis.viewer.scene_view import open_scene_view, scene_folder
    from physcensis.viewer.server import check_address, import_viser

    if not check:  # a missing viser, or an address that cannot be served on, is one line before any work
        import_viser()
        check_address(host, port)
    shown, catalogue = open_scene_view(scene_file(scene_path), with_libraries(library))
    for note in shown.notes:
        print_warning(note)
    settle = SettlePlayback(shown.scene, catalogue)
    track, robot = _episode(episode, shown, scene_folder(scene_path)) if episode else (None, None)
    if check:
        raise finish(_check(shown, settle, track, robot, steps))
    _serve(shown, settle, track, robot, host, port)


def _episode(text: str, shown: SceneView, folder: Path) -> tuple[EpisodeTrack, RobotView | None]:
    """The episode's track and, when its world can be built here, the arm along it."""
    from physcensis.viewer.episode import EpisodeRef, check_objects, read_episode_track, recorded_scene
    from physcensis.viewer.robot_view import robot_view

    track = read_episode_track(EpisodeRef.parse(text))
    recorded = recorded_scene(track)
    if recorded is not None and recorded.resolve() != folder.resolve():
        print_warning(f"--episode {track.ref} was recorded in {recorded}, not in {folder}")
    placed = [node.id for node in shown.objects]
    shared = check_objects(track, placed)
    if len(shared) < len(track.object_ids):
        missing = sorted(set(track.object_ids) - set(shared))
        print_warning(f"--episode {track.ref}: objects not in this scene are left out: {', '.join(missing)}")
    try:
        return track, robot_view(folder, track)
    except PhyscensisError as exc:
        print_warning(f"the arm is not shown, only the hand's recorded pose ({exc})")
        return track, None


def _check(
    shown: SceneView, settle: SettlePlayback, track: EpisodeTrack | None, robot: RobotView | None, steps: int
) -> bool:
    """Print what the viewer would show and play `steps` frames; False if the settle blew up."""
    from physcensis.viewer.playback import FRAME_S, moved_m

    support = shown.scene.support
    _say(f"scene: {shown.source}" + (f" ({shown.scene.prompt})" if shown.scene.prompt else ""))
    _say(f"support: {support.kind} {support.size[0]:g} x {support.size[1]:g} m, top at {support.top_height:g} m")
    _say(f"objects: {len(shown.objects)} placed, {len(shown.failed)} failed")
    for node in shown.objects:
        assert node.info is not None
        x, y, z = node.pose[:3]
        placed_by = "; ".join(p.text() for p in node.info.placements) or "-"
        p_fail = "-" if node.info.p_fail is None else f"{node.info.p_fail:.3f}"
        _say(
            f"  {node.id}: {node.info.asset} at ({x:.3f}, {y:.3f}, {z:.3f}), {len(node.parts)} mesh parts, "
            f"{node.info.mass_kg:.3f} kg, placed by {placed_by}, p_fail {p_fail}"
        )
    camera = shown.camera
    _say(f"camera: at {_xyz(camera.position)} looking at {_xyz(camera.look_at)}")
    start = settle.reset()
    for _ in range(steps):
        settle.step(FRAME_S)
    moved = moved_m(start, settle.poses())
    most = max(moved, key=lambda oid: moved[oid], default=None)
    largest = f", largest move {moved[most] * 1000:.1f} mm ({most})" if most else ""
    _say(f"settle: {steps} frames ({settle.time:.2f} s simulated){largest}")
    if settle.diverged:
        _say(f"settle: {settle.diverged}")
    if track is not None:
        arm = f"the arm's {len(robot.links)} links" if robot is not None else "the hand's recorded pose"
        _say(
            f"episode: {track.ref}, {track.frames - 1} steps ({track.duration_s:.2f} s), "
            f"{len(track.object_ids)} objects, {arm}"
        )
    return settle.diverged is None


def _say(text: str) -> None:
    """One line of plain text on stdout, never wrapped nor read as markup."""
    console.print(text, markup=False, highlight=False, soft_wrap=True)


def _xyz(v: tuple[float, float, float]) -> str:
    return "(" + ", ".join(f"{c:.2f}" for c in v) + ")"


def _serve(
    shown: SceneView, settle: SettlePlayback, track: EpisodeTrack | None, robot: RobotView | None, host: str, port: int
) -> None:
    from physcensis.viewer.server import ViewerServer

    server = ViewerServer(shown, settle, track=track, robot=robot, host=host, port=port)
    _say(f"viewing {shown.source} ({len(shown.objects)} objects) at {server.url} - Ctrl-C stops")
    try:
        while True:
            time.sleep(1.0)
    except KeyboardInterrupt:
        _say("stopped")
    finally:
        server.close()
    raise typer.Exit(ExitCode.OK)
