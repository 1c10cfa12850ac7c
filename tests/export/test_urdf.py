"""URDF export: loadable by PyBullet with the scene's masses and friction, and it rests there too."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from physcensis.crosscheck.bullet_engine import urdf_settle_distance
from physcensis.export import export_scene
from physcensis.scene import Scene


@pytest.fixture(scope="module")
def urdf_index(desk_scene: Scene, tmp_path_factory: pytest.TempPathFactory) -> Path:
    return export_scene(desk_scene, tmp_path_factory.mktemp("urdf"), ["urdf"])["urdf"]


def test_index_lists_every_object_with_its_pose_and_the_static_support(urdf_index: Path, desk_scene: Scene) -> None:
    index = json.loads(urdf_index.read_text())
    bodies = {b["id"]: b for b in index["bodies"]}
    assert set(bodies) == {o.id for o in desk_scene.placed} | {"support", "ground"}
    assert bodies["support"]["fixed"] and bodies["ground"]["fixed"]
    for obj in desk_scene.placed:
        entry = bodies[obj.id]
        assert not entry["fixed"]
        assert entry["position"] == pytest.approx(obj.position)
        w, x, y, z = obj.quaternion
        assert entry["quaternion_xyzw"] == pytest.approx([x, y, z, w])
        assert (urdf_index.parent / entry["urdf"]).is_file()


def test_each_link_carries_mass_com_inertia_friction_and_existing_meshes(urdf_index: Path, desk_scene: Scene) -> None:
    for obj in desk_scene.placed:
        link = ET.parse(urdf_index.parent / f"{obj.id}.urdf").getroot().find("link")
        assert link is not None
        assert float(link.find("inertial/mass").get("value")) == pytest.approx(obj.mass, rel=1e-6)
        com = [float(v) for v in link.find("inertial/origin").get("xyz").split()]
        assert com == pytest.approx(obj.com, abs=1e-4)
        inertia = link.find("inertial/inertia")
        assert all(float(inertia.get(k)) > 0 for k in ("ixx", "iyy", "izz"))
        assert float(link.find("contact/lateral_friction").get("value")) == pytest.approx(obj.friction)
        assert link.findall("collision") and link.findall("visual")
        for mesh in link.iter("mesh"):
            assert (urdf_index.parent / mesh.get("filename")).is_file()


def test_pybullet_loads_the_export_with_the_scene_masses(urdf_index: Path, desk_scene: Scene) -> None:
    pybullet = pytest.importorskip("pybullet")
    client = pybullet.connect(pybullet.DIRECT)
    try:
        for obj in desk_scene.placed:
            handle = pybullet.loadURDF(
                str(urdf_index.parent / f"{obj.id}.urdf"),
                obj.position,
                physicsClientId=client,
                flags=pybullet.URDF_USE_INERTIA_FROM_FILE,
            )
            info = pybullet.getDynamicsInfo(handle, -1, physicsClientId=client)
            assert info[0] == pytest.approx(obj.mass, rel=1e-6)
            assert info[1] == pytest.approx(obj.friction, rel=1e-6)
            assert np.linalg.norm(np.asarray(info[3]) - np.asarray(obj.com)) < 1e-4  # local inertial position
    finally:
        pybullet.disconnect(physicsClientId=client)


def test_desk_scene_rests_in_pybullet_too(urdf_index: Path, desk_scene: Scene) -> None:
    pytest.importorskip("pybullet")
    distance = urdf_settle_distance(urdf_index)
    assert set(distance.per_object) == {o.id for o in desk_scene.placed}
    assert distance.mean_m < 0.005, distance.per_object
    assert max(distance.per_object.values()) < 0.005


def test_a_floating_object_falls_in_pybullet(desk_scene: Scene, tmp_path: Path) -> None:
    """The cross-check is not blind: a cup put 20 cm above the table drops about 20 cm."""
    pytest.importorskip("pybullet")
    raised = desk_scene.model_copy(deep=True)
    cup = next(o for o in raised.objects if o.category == "cup")
    cup.position = (cup.position[0], cup.position[1], cup.position[2] + 0.2)
    distance = urdf_settle_distance(export_scene(raised, tmp_path, ["urdf"])["urdf"])
    assert distance.per_object[cup.id] == pytest.approx(0.2, abs=0.01)
