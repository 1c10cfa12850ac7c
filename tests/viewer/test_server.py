"""The viser server: it serves its own client page on 127.0.0.1, holds a node per object at its pose, fills the panel
on a pick, and its buttons play and reset the settle."""

from __future__ import annotations

import time
import urllib.request
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

import physcensis.viewer.server as server_module
from physcensis.viewer.playback import SettlePlayback
from physcensis.viewer.scene_view import open_scene_view
from physcensis.viewer.server import ViewerServer

pytest.importorskip("viser")


@pytest.fixture
def viewer(scene_dir: Path) -> Iterator[ViewerServer]:
    view, catalogue = open_scene_view(scene_dir)
    server = ViewerServer(view, SettlePlayback(view.scene, catalogue), host="127.0.0.1", port=0)
    try:
        yield server
    finally:
        server.close()


def _wait_for(condition, seconds: float = 10.0) -> bool:  # type: ignore[no-untyped-def]
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if condition():
            return True
        time.sleep(0.05)
    return False


def test_the_server_serves_its_client_page_on_a_free_local_port(viewer: ViewerServer) -> None:
    assert viewer.port > 0 and viewer.url == f"http://127.0.0.1:{viewer.port}"
    with urllib.request.urlopen(viewer.url + "/", timeout=10) as response:
        assert response.status == 200
        page = response.read().decode("utf-8", "replace")
    assert "<html" in page.lower() and "<script" in page.lower()  # viser's bundled client, no CDN


def test_every_object_support_and_ground_is_a_node_of_the_servers_scene_at_its_pose(viewer: ViewerServer) -> None:
    scene = viewer.server.scene
    for node in viewer.view.objects:
        handle = scene.get_handle_by_name(node.name)
        assert handle is not None, node.name
        np.testing.assert_allclose(handle.position, node.pose[:3], atol=1e-6)
        np.testing.assert_allclose(handle.wxyz, node.pose[3:], atol=1e-6)
        for k in range(len(node.parts)):  # its meshes, each picking the object
            assert scene.get_handle_by_name(f"{node.name}/part{k}") is not None
            assert viewer.picks[f"{node.name}/part{k}"] == node.id
    assert scene.get_handle_by_name("/support") is not None and scene.get_handle_by_name("/ground") is not None
    assert viewer.picks["/support/part0"] is None


def test_a_pick_shows_the_objects_facts_and_the_support_its_own(viewer: ViewerServer) -> None:
    text = viewer.select("mug_0")
    assert viewer.info.content == text and "mug_0" in text and "PLACE-ON book_0" in text and "kg" in text
    assert "table" in viewer.select(None)


def test_play_moves_the_simulation_in_real_time_and_reset_returns_to_the_written_poses(viewer: ViewerServer) -> None:
    mug = viewer.server.scene.get_handle_by_name("/objects/mug_0")
    assert mug is not None
    started = time.monotonic()
    viewer.play_settle()
    assert _wait_for(lambda: viewer.settle.time > 0.3)
    viewer.pause()
    assert time.monotonic() - started > 0.25  # real time, not as fast as it can
    played = viewer.settle.time
    time.sleep(0.3)
    assert viewer.settle.time == played  # paused
    assert "t = " in viewer.status.content
    viewer.reset()
    assert viewer.settle.time == 0.0
    np.testing.assert_allclose(mug.position, viewer.view.node("mug_0").pose[:3], atol=1e-9)


def test_a_press_of_play_simulates_a_bounded_time_then_stops_by_itself(
    viewer: ViewerServer, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(server_module, "PLAY_S", 0.3)
    viewer.play_settle()
    assert _wait_for(lambda: viewer.playing == "idle")
    assert viewer.settle.time == pytest.approx(0.3, abs=0.05)
    viewer.play_settle()  # on from there
    assert _wait_for(lambda: viewer.playing == "idle")
    assert viewer.settle.time == pytest.approx(0.6, abs=0.08)
