"""The viewer's server: a viser server (it serves its own bundled web client, no network needed) holding the scene's
nodes, the panel a click fills, and the buttons that play the settle and a recorded episode in real time."""

from __future__ import annotations

import contextlib
import io
import socket
import threading
import time
from collections.abc import Mapping
from typing import Any

import numpy as np

from physcensis.viewer.episode import EpisodeTrack
from physcensis.viewer.playback import FRAME_S, SettlePlayback
from physcensis.viewer.robot_view import RobotView
from physcensis.viewer.scene_view import MeshPart, Pose, SceneView, ViewerError, ViewNode, object_node_name

INSTALL_HINT = "the viewer needs viser: pip install 'physcensis[view]'"
ROBOT = "/robot"
TCP = f"{ROBOT}/tcp"
HELP = "Click an object to see what it is and what placed it."
PLAY_S = 10.0  # simulated seconds one press of "Play settle" plays (a viewer left open does not simulate for ever)


def import_viser() -> Any:
    """The viser module, or one ViewerError saying how to install it."""
    try:
        import viser
    except ImportError:
        raise ViewerError(INSTALL_HINT) from None
    return viser


def check_address(host: str, port: int) -> None:
    """Refuse (ViewerError) an address this machine cannot serve on: viser would wait for it for ever, or take the
    next port up without a word when the one asked for is taken."""
    try:
        family, kind, proto, _, address = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM)[0]
    except (socket.gaierror, UnicodeError) as exc:
        raise ViewerError(f"--host {host!r} is not an address to serve on ({exc})") from None
    with socket.socket(family, kind, proto) as probe:
        probe.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            probe.bind(address)
        except OSError as exc:
            raise ViewerError(f"cannot serve the viewer on {host}:{port} ({exc.strerror or exc})") from None


class ViewerServer:
    """A running viewer of one scene on `host`:`port` (0: a free port). `close()` stops it."""

    def __init__(
        self,
        view: SceneView,
        settle: SettlePlayback,
        *,
        track: EpisodeTrack | None = None,
        robot: RobotView | None = None,
        host: str = "127.0.0.1",
        port: int = 0,
    ) -> None:
        viser = import_viser()
        check_address(host, port)
        self.view, self.settle, self.track, self.robot = view, settle, track, robot
        try:
            with contextlib.redirect_stdout(io.StringIO()):  # viser's own banner: the command prints the address
                self.server = viser.ViserServer(host=host, port=port, label=_label(view), verbose=False)
        except OSError as exc:
            raise ViewerError(f"cannot serve the viewer on {host}:{port} ({exc.strerror or exc})") from None
        # Nothing leaves this machine: no share button (it would open a tunnel through viser's public relay).
        self.server.gui.configure_theme(show_share_button=False)
        self.frames: dict[str, Any] = {}  # node name -> its viser frame (objects, support, ground, robot links)
        self.picks: dict[str, str | None] = {}  # mesh node name -> the object a click on it selects (None: support)
        self.selected: str | None = None
        self._mode = "idle"  # idle, settle or episode
        self._showing = "settle"  # what the objects' poses are: the settle's or the episode's
        self._episode_t = 0.0
        self._settle_until = PLAY_S
        self._lock = threading.Lock()
        self._wake = threading.Event()
        self._stopped = threading.Event()
        self._populate()
        self._panel()
        self._thread = threading.Thread(target=self._run, name="physcensis-viewer", daemon=True)
        self._thread.start()

    @property
    def port(self) -> int:
        return int(self.server.get_port())

    @property
    def url(self) -> str:
        host = self.server.get_host()
        return f"http://{'127.0.0.1' if host in ('0.0.0.0', '') else host}:{self.port}"

    @property
    def playing(self) -> str:
        """What is playing: idle, settle or episode."""
        return self._mode

    # -- the scene ------------------------------------------------------------------------------------------------

    def _populate(self) -> None:
        scene = self.server.scene
        scene.set_up_direction("+z")
        camera = self.server.initial_camera
        camera.position, camera.look_at, camera.up = self.view.camera.position, self.view.camera.look_at, (0, 0, 1)
        camera.fov = float(np.radians(self.view.camera.fov_deg))
        for node in (self.view.support, *([self.view.ground] if self.view.ground else []), *self.view.objects):
            self._add_node(node)
        if self.robot is not None:
            for k, part in enumerate(self.robot.fixed):
                self._add_mesh(f"{ROBOT}/fixed_{k}", part, None)
            for link in self.robot.links:
                pose = self.robot.link_poses(0)[link.name]
                name = f"{ROBOT}/{link.name}"
                self.frames[name] = scene.add_frame(name, show_axes=False, position=pose[:3], wxyz=pose[3:])
                for k, (part, local) in enumerate(link.parts):
                    self._add_mesh(f"{name}/part{k}", part, None, local)
        elif self.track is not None:  # no arm to show: the hand's recorded pose as axes
            self.frames[TCP] = scene.add_frame(
                TCP, axes_length=0.06, axes_radius=0.004, position=self.track.eef_pos[0], wxyz=self.track.eef_quat[0]
            )

    def _add_node(self, node: ViewNode) -> None:
        self.frames[node.name] = self.server.scene.add_frame(
            node.name, show_axes=False, position=node.pose[:3], wxyz=node.pose[3:]
        )
        for k, part in enumerate(node.parts):
            self._add_mesh(f"{node.name}/part{k}", part, node)

    def _add_mesh(self, name: str, part: MeshPart, node: ViewNode | None, local: Pose | None = None) -> None:
        extra = {} if local is None else {"position": local[:3], "wxyz": local[3:]}
        handle = self.server.scene.add_mesh_simple(
            name, part.vertices, part.faces, color=part.rgb, opacity=part.opacity, **extra
        )
        if node is not None:
            chosen = self.picks[name] = node.id if node.pickable else None
            handle.on_click(lambda _event: self.select(chosen))

    # -- the panel ------------------------------------------------------------------------------------------------

    def _panel(self) -> None:
        gui = self.server.gui
        gui.add_markdown(_title(self.view))
        self.status = gui.add_markdown(self._status_text())
        play = gui.add_button("Play settle", hint=f"simulate the scene on from where it is, {PLAY_S:g} s in real time")
        pause = gui.add_button("Pause")
        reset = gui.add_button("Reset to written poses")
        play.on_click(lambda _event: self.play_settle())
        pause.on_click(lambda _event: self.pause())
        reset.on_click(lambda _event: self.reset())
        if self.track is not None:
            episode = gui.add_button("Play episode", hint=f"the recorded demonstration {self.track.ref}")
            episode.on_click(lambda _event: self.play_episode())
        self.info = gui.add_markdown(HELP)

    def select(self, object_id: str | None) -> str:
        """Show `object_id`'s facts in the panel (None: the support's); the markdown shown."""
        self.selected = object_id
        node = self.view.node(object_id) if object_id else None
        text = node.info.markdown() if node is not None and node.info is not None else self.view.support_markdown()
        self.info.content = text
        return str(text)

    # -- playing --------------------------------------------------------------------------------------------------

    def play_settle(self) -> None:
        with self._lock:
            self._mode = self._showing = "settle"
            self._settle_until = self.settle.time + PLAY_S
        self._wake.set()

    def play_episode(self) -> None:
        if self.track is None:
            raise ViewerError("no episode was given (--episode DATASET[:INDEX])")
        with self._lock:
            self.show(self.view.written_poses())  # what the episode did not record stands where the scene has it
            self._mode = self._showing = "episode"
            self._episode_t = 0.0
        self._wake.set()

    def pause(self) -> None:
        with self._lock:
            self._mode = "idle"
        self._update_status()

    def reset(self) -> None:
        """The written poses, nothing playing (the arm back at the episode's start)."""
        with self._lock:
            self._mode, self._showing, self._episode_t = "idle", "settle", 0.0
            poses = self.settle.reset()
        self.show(poses)
        if self.track is not None:
            self._show_episode_frame(0, objects=False)
        self._update_status()

    def show(self, poses: Mapping[str, Pose]) -> None:
        """Put the objects named in `poses` there."""
        with self.server.atomic():
            for oid, pose in poses.items():
                frame = self.frames.get(object_node_name(oid))
                if frame is not None:
                    frame.position, frame.wxyz = pose[:3], pose[3:]

    def _show_episode_frame(self, frame: int, *, objects: bool = True) -> None:
        assert self.track is not None
        if objects:
            self.show(self.track.poses(frame))
        with self.server.atomic():
            if self.robot is not None:
                for name, pose in self.robot.link_poses(frame).items():
                    handle = self.frames[f"{ROBOT}/{name}"]
                    handle.position, handle.wxyz = pose[:3], pose[3:]
            elif TCP in self.frames:
                k = min(frame, self.track.frames - 1)
                self.frames[TCP].position, self.frames[TCP].wxyz = self.track.eef_pos[k], self.track.eef_quat[k]

    def _tick(self) -> None:
        """One frame of whatever is playing; at the episode's end (or when the settle blew up) playing stops."""
        with self._lock:
            mode = self._mode
            if mode == "settle":
                self.show(self.settle.step(FRAME_S))
                done = self.settle.diverged is not None or self.settle.time >= self._settle_until - 1e-9
            elif mode == "episode" and self.track is not None:
                self._episode_t += FRAME_S
                frame = self.track.frame_at(self._episode_t)
                self._show_episode_frame(frame)
                done = frame >= self.track.frames - 1
            else:
                done = False
            if done and self._mode == mode:
                self._mode = "idle"
        self._update_status()

    def _run(self) -> None:
        due = time.perf_counter()
        while not self._stopped.is_set():
            if self._mode == "idle":
                self._wake.wait(0.5)
                self._wake.clear()
                due = time.perf_counter()
                continue
            self._tick()
            due += FRAME_S
            late = due - time.perf_counter()
            if late > 0:
                time.sleep(late)
            else:  # slower than real time: carry on from now
                due = time.perf_counter()

    def _status_text(self) -> str:
        with self._lock:
            mode, showing, t, episode_t = self._mode, self._showing, self.settle.time, self._episode_t
        playing = " (playing)" if mode != "idle" else ""
        if showing == "episode" and self.track is not None:
            frame = self.track.frame_at(episode_t)
            return f"**episode**: step {frame} / {self.track.frames - 1} ({episode_t:.2f} s){playing}"
        if self.settle.diverged:
            return f"**settle**: stopped - {self.settle.diverged}"
        return f"**settle**: t = {t:.2f} s{playing}"

    def _update_status(self) -> None:
        self.status.content = self._status_text()

    def close(self) -> None:
        self._stopped.set()
        self._wake.set()
        self._thread.join(timeout=2.0)
        with contextlib.redirect_stdout(io.StringIO()):  # viser's "server stopped"
            self.server.stop()


def _label(view: SceneView) -> str:
    return f"physcensis: {view.source}"


def _title(view: SceneView) -> str:
    prompt = view.scene.prompt
    return f"**{view.source}**" + (f"\n\n*{prompt}*" if prompt else "") + f"\n\n{len(view.objects)} objects"
