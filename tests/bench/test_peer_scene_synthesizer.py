"""The clutter protocol's peer (scene_synthesizer): same hulls and table, converted to our scene, measured like ours."""

from __future__ import annotations

import sys
from typing import Any

import numpy as np
import pytest
import trimesh
from typer.testing import CliRunner

from physcensis.assets import default_catalogue
from physcensis.bench.clutter import CLUTTER_TABLE, measure_under_mujoco_defaults
from physcensis.bench.peer_scene_synthesizer import INSTALL_HINT
from physcensis.cli import app
from physcensis.cli.errors import ExitCode
from physcensis.export.bodies import part_mesh
from physcensis.scene import PlacedObject, Scene

from ..scenes import placed_object

runner = CliRunner()


def world_hull_points(obj: PlacedObject) -> np.ndarray:
    """Our asset's collision hull vertices at the object's pose."""
    from scipy.spatial.transform import Rotation

    asset = default_catalogue().get(obj.asset)
    points = np.vstack([part_mesh(part).vertices for part in asset.collision])
    w, x, y, z = obj.quaternion
    return Rotation.from_quat([x, y, z, w]).apply(points) + np.asarray(obj.position)


def peer_world_points(peer: Any, oid: str) -> np.ndarray:
    """Every vertex of the peer's geometry of this object, in the world, as the peer's scene graph places it."""
    graph, geometry = peer.scene.graph, peer.scene.geometry
    points = []
    for node in graph.nodes_geometry:
        if node.startswith(f"{oid}/"):
            matrix, name = graph[node]
            points.append(trimesh.transform_points(geometry[name].vertices, matrix))
    return np.vstack(points)


def test_without_the_extra_the_peer_is_a_one_line_error_naming_it(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "scene_synthesizer", None)  # `import scene_synthesizer` raises ImportError
    result = runner.invoke(app, ["bench", "clutter", "--peer", "scene-synthesizer", "--mode", "no-stack"])
    assert result.exit_code == ExitCode.USAGE
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert len(lines) == 1 and INSTALL_HINT in lines[0]


def test_an_unknown_peer_or_mode_is_refused() -> None:
    unknown = runner.invoke(app, ["bench", "clutter", "--peer", "cluttergen", "--mode", "no-stack"])
    assert unknown.exit_code == ExitCode.USAGE and "unknown peer" in unknown.output
    skip = runner.invoke(app, ["bench", "clutter", "--peer", "scene-synthesizer", "--mode", "with-skip"])
    assert skip.exit_code == ExitCode.USAGE and "no-stack or with-stack" in skip.output


@pytest.mark.physics
def test_the_defaults_measure_removes_what_falls_and_keeps_what_rests() -> None:
    edge = CLUTTER_TABLE.half_extents[0]
    top = CLUTTER_TABLE.top_height
    scene = Scene(
        support=CLUTTER_TABLE,
        objects=[
            placed_object("can_0", "ycb_005_tomato_soup_can", 0.0, 0.0, top),
            placed_object("can_1", "ycb_005_tomato_soup_can", edge + 0.02, 0.2, top),  # its centre past the edge
        ],
    )
    measure = measure_under_mujoco_defaults(scene, default_catalogue())
    assert (measure.objects, measure.resting) == (2, 1)
    assert measure.settle_distance_m > 0.01  # the falling can dominates the mean
    assert len(scene.placed) == 2  # the measured scene itself is left as it was delivered


@pytest.mark.physics
def test_peer_objects_sit_on_our_hulls_inside_the_table_and_rest() -> None:
    pytest.importorskip("scene_synthesizer")
    from physcensis.bench import peer_scene_synthesizer as peers

    synth = peers.load_scene_synthesizer()
    catalogue = default_catalogue()
    peer = peers.peer_table(synth, seed=3)
    scene = Scene(support=CLUTTER_TABLE)
    for k, asset_id in enumerate(("ycb_024_bowl", "ycb_010_potted_meat_can", "ycb_007_tuna_fish_can")):
        asset = catalogue.get(asset_id)
        rule = peers.PlacementRule(stack=False, valid=peers.within_table_edges(peers.hull_points(asset)))
        assert peers.place_one(peer, f"o{k}", peers.peer_asset(synth, asset), rule)
        obj = peers.placed_object(peer, f"o{k}", asset, seed=3)
        scene.objects.append(obj)
        # the converted pose puts our hulls exactly where the peer checked them for collisions
        ours = world_hull_points(obj)
        theirs = peer_world_points(peer, f"o{k}")
        assert ours.shape == theirs.shape and np.allclose(ours, theirs, atol=1e-9)
        assert (np.abs(ours[:, :2]) <= np.asarray(CLUTTER_TABLE.half_extents) + 1e-3).all()
        assert ours[:, 2].min() == pytest.approx(CLUTTER_TABLE.top_height + 0.001, abs=1e-6)  # its 1 mm gap
    measure = peers.measure_under_mujoco_defaults(scene, catalogue)
    assert measure.resting == 3 and measure.settle_distance_m < 0.002
