"""Contact profiles: what MuJoCo's defaults mean here, and that solved scenes rest under them and in exports that drop
our tuning."""

from __future__ import annotations

import json
import re
from pathlib import Path

import mujoco
import numpy as np
import pytest
from typer.testing import CliRunner

from physcensis.assets import default_catalogue
from physcensis.bench.clutter import YCB_DINING
from physcensis.cli.app import app
from physcensis.export import export_scene
from physcensis.output import write_solution
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.physics.profiles import MUJOCO_DEFAULT, OURS
from physcensis.program import CheckReport
from physcensis.scene import Scene, Support
from physcensis.solver.pipeline import Solution, solve
from tests.conftest import EXAMPLES
from tests.scenes import placed_object


@pytest.fixture(scope="module")
def stacked_scene() -> Scene:
    """`books_stack.json` solved: books piled on each other, the case where soft, pyramidal friction shows first."""
    solution = solve(EXAMPLES / "books_stack.json", seed=0)
    assert solution.ok
    return solution.scene


def test_the_default_profile_compiles_mujocos_own_defaults() -> None:
    scene = Scene(seed=0, prompt="one can", support=Support(kind="table", size=(0.4, 0.4)))
    scene.objects = [placed_object("can_0", "can_soda_red", 0.0, 0.0, 0.8)]
    default = mujoco.MjModel.from_xml_string("<mujoco><worldbody><geom size='1 1 1' type='box'/></worldbody></mujoco>")
    model = MujocoEngine(profile=MUJOCO_DEFAULT).build(scene, visual=False).model
    assert model.opt.cone == mujoco.mjtCone.mjCONE_PYRAMIDAL
    assert model.opt.impratio == default.opt.impratio == 1.0
    assert model.opt.timestep == pytest.approx(0.01)
    collision = model.geom_contype > 0
    assert np.allclose(model.geom_solref[collision], default.geom_solref[0])
    ours = MujocoEngine(profile=OURS).build(scene, visual=False).model
    assert ours.opt.cone == mujoco.mjtCone.mjCONE_ELLIPTIC and ours.opt.timestep == pytest.approx(0.002)


def test_a_solved_stack_rests_under_mujoco_defaults(stacked_scene: Scene) -> None:
    distance = MujocoEngine(profile=MUJOCO_DEFAULT).settle_distance(stacked_scene)
    assert distance.diverged is None
    assert max(distance.per_object.values()) < 0.002, distance.per_object
    assert distance.mean_m < 0.001


def test_the_mjcf_export_rests_without_its_option_block(stacked_scene: Scene, tmp_path: Path) -> None:
    xml_path = export_scene(stacked_scene, tmp_path / "mjcf", formats=["mjcf"])["mjcf"]
    xml = xml_path.read_text()
    stripped = re.sub(r"<option\b[^>]*/>|<option\b.*?</option>", "", xml, flags=re.S)
    assert "<option" in xml and "<option" not in stripped
    xml_path.write_text(stripped)
    model = mujoco.MjModel.from_xml_path(str(xml_path))
    assert model.opt.cone == mujoco.mjtCone.mjCONE_PYRAMIDAL  # MuJoCo's default, not ours
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    bodies = [model.body(o.id).id for o in stacked_scene.placed]
    start = data.xpos[bodies].copy()
    mujoco.mj_step(model, data, nstep=int(round(4.0 / model.opt.timestep)))
    moved = np.linalg.norm(data.xpos[bodies] - start, axis=1)
    assert moved.max() < 0.002, dict(zip([o.id for o in stacked_scene.placed], moved, strict=True))


def test_eval_settle_measures_under_each_mujoco_profile(stacked_scene: Scene, tmp_path: Path) -> None:
    folder = tmp_path / "scene"
    write_solution(
        Solution(stacked_scene, CheckReport(())), folder, layout_png=False, physics_outputs=False, exports=()
    )
    raised = stacked_scene.model_copy(deep=True)
    top = max(raised.placed, key=lambda o: o.position[2])
    top.position = (top.position[0], top.position[1], top.position[2] + 0.05)
    write_solution(
        Solution(raised, CheckReport(())), tmp_path / "raised", layout_png=False, physics_outputs=False, exports=()
    )
    for engine in ("mujoco", "mujoco-default"):
        for scene_dir, expected in ((folder, 0.0), (tmp_path / "raised", 0.05 / len(raised.placed))):
            result = CliRunner().invoke(app, ["eval", "settle", str(scene_dir), "--engine", engine, "--json"])
            assert result.exit_code == 0, result.output
            row = json.loads(result.stdout)["scenes"][0]
            assert row["engine"] == engine
            assert row["settle_distance_m"] == pytest.approx(expected, abs=0.001)
        # --seconds: 50 ms into the 5 cm drop the top object has fallen ½ g t² (1.2 cm; + the steps' Euler error)
        args = ["eval", "settle", str(tmp_path / "raised"), "--engine", engine, "--json", "--seconds", "0.05"]
        result = CliRunner().invoke(app, args)
        assert result.exit_code == 0, result.output
        summary = json.loads(result.stdout)
        assert summary["seconds"] == 0.05
        assert summary["scenes"][0]["per_object_m"][top.id] == pytest.approx(0.0135, abs=0.002)


def _alone_on_a_table(asset_id: str) -> Scene:
    scene = Scene(seed=0, prompt=asset_id, support=Support(kind="table", size=(0.4, 0.6)))
    top = scene.support.top_height
    scene.objects = [placed_object("o", asset_id, 0.0, 0.0, top + 0.05, yaw=0.3)]
    built = MujocoEngine().build(scene, visual=False)
    z = built.lower_onto_support("o", top + 0.05, top - 0.05)
    assert z is not None
    scene.objects = [placed_object("o", asset_id, 0.0, 0.0, z, yaw=0.3)]
    return scene


FORKS = [e.id for e in default_catalogue().entries() if e.category == "fork"]


@pytest.mark.parametrize("asset_id", [*YCB_DINING, *FORKS])
def test_every_clutter_asset_and_fork_rests_alone_under_mujoco_defaults(asset_id: str) -> None:
    # A fork as one hull touched the table on its narrow neck and crept away under MuJoCo's soft default contacts
    # (the YCB fork: 44 mm in 4 s); under ours it lay still.
    distance = MujocoEngine(profile=MUJOCO_DEFAULT).settle_distance(_alone_on_a_table(asset_id))
    assert distance.per_object["o"] < 0.001, asset_id
