"""The settle-engine registry: every registered engine measures the same settle distance of a scene, the command
line offers exactly the registered engines, and a name is never silently replaced."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest
from typer.testing import CliRunner

from physcensis.cli import app
from physcensis.cli.evaluate import Engine
from physcensis.crosscheck.engines import (
    SETTLE_ENGINES,
    SettleEngineRecord,
    register_settle_engine,
    settle_engine,
)
from physcensis.errors import PhyscensisError
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.scene import Scene, Support
from tests.scenes import placed_object

HAS_BULLET = importlib.util.find_spec("pybullet") is not None
HAS_GENESIS = importlib.util.find_spec("genesis") is not None


def _dropped_can(height_m: float) -> Scene:
    """A can resting on a table (lowered onto it), or held `height_m` above that."""
    scene = Scene(seed=0, prompt="a can", support=Support(kind="table", size=(0.4, 0.4)))
    top = scene.support.top_height
    scene.objects = [placed_object("can_0", "can_soda_red", 0.0, 0.0, top + 0.1)]
    z = MujocoEngine().build(scene, visual=False).lower_onto_support("can_0", top + 0.1, top - 0.1)
    assert z is not None
    scene.objects = [placed_object("can_0", "can_soda_red", 0.0, 0.0, z + height_m)]
    return scene


def test_the_command_line_offers_every_registered_engine() -> None:
    assert sorted(e.value for e in Engine) == sorted(SETTLE_ENGINES)
    assert {"mujoco", "mujoco-default", "bullet"} <= set(SETTLE_ENGINES)


def _engine_params() -> list[object]:
    """Every engine; Genesis (the paper's engine, an extra) is slow to start, so it runs with `make test-long`."""
    slow = pytest.mark.long
    return [pytest.param(name, marks=slow) if name == "genesis" else name for name in sorted(SETTLE_ENGINES)]


@pytest.mark.physics
@pytest.mark.parametrize("name", _engine_params())
def test_every_engine_measures_a_drop_and_a_rest(name: str) -> None:
    if name == "bullet" and not HAS_BULLET:
        pytest.skip("the bullet extra is not installed")
    if name == "genesis" and not HAS_GENESIS:
        pytest.skip("the genesis extra is not installed")
    engine = settle_engine(name)
    resting = engine.settle_distance(_dropped_can(0.0))
    assert resting.diverged is None and resting.mean_m < 0.002
    dropped = engine.settle_distance(_dropped_can(0.04))
    assert dropped.mean_m == pytest.approx(0.04, abs=0.006)  # it falls the 4 cm onto the table and stays


@pytest.mark.skipif(HAS_GENESIS, reason="the genesis extra is installed")
def test_a_missing_extra_is_one_line_naming_it_before_any_scene_is_read(tmp_path: Path) -> None:
    result = CliRunner().invoke(app, ["eval", "settle", str(tmp_path / "no-such-scene"), "--engine", "genesis"])
    assert result.exit_code != 0
    assert "pip install 'physcensis[genesis]'" in result.output
    assert "no-such-scene" not in result.output  # the engine is checked before the path is looked at
    assert "Traceback" not in result.output


def test_an_unknown_engine_is_named_with_the_known_ones() -> None:
    with pytest.raises(PhyscensisError, match=r"no settle engine named 'ode'.*mujoco-default"):
        settle_engine("ode")


def test_a_taken_name_is_not_replaced() -> None:
    record = SETTLE_ENGINES["mujoco"]
    with pytest.raises(ValueError, match="already registered"):
        register_settle_engine(SettleEngineRecord("mujoco", "another", record.make))
    assert SETTLE_ENGINES["mujoco"] is record
