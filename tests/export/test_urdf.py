"""URDF export: loadable by PyBullet with the scene's masses and friction, and it rests there too."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
import trimesh
from scipy.spatial.transform import Rotation

from physcensis.assets.catalogue import default_catalogue
from physcensis.assets.model import Asset
from physcensis.crosscheck.bullet_engine import load_bodies, urdf_settle_distance
from physcensis.export import export_scene
from physcensis.export.bodies import part_mesh
from physcensis.export.urdf import BULLET_URDF_MARGIN_M, inset_hull
from physcensis.scene import PlacedObject, Scene, Support
from physcensis.solver.pipeline import solve
from tests.conftest import EXAMPLES


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
        assert entry["friction"] == pytest.approx(obj.friction)
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
        # PyBullet multiplies two links' values: each carries the root, so a pair meets with its geometric mean
        assert float(link.find("contact/lateral_friction").get("value")) == pytest.approx(obj.friction**0.5)
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
            assert info[1] ** 2 == pytest.approx(obj.friction, rel=1e-6)
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


def _lone_object(asset_id: str, quaternion: tuple[float, float, float, float] = (1.0, 0.0, 0.0, 0.0)) -> Scene:
    """One catalogue object standing exactly on an empty table (its lowest point on the top), nothing else."""
    asset = default_catalogue().get(asset_id)
    support = Support.parse("table:0.8x0.6")
    rotated = part_mesh_points(asset) @ Rotation.from_quat([*quaternion[1:], quaternion[0]]).as_matrix().T
    obj = PlacedObject(
        id=f"{asset.category}_0",
        description=asset.category,
        asset=asset.id,
        category=asset.category,
        position=(0.0, 0.0, support.top_height - float(rotated[:, 2].min())),
        quaternion=quaternion,
        mass=asset.mass,
        friction=float(np.mean(asset.friction_range)),
        com=asset.com,
    )
    return Scene(support=support, objects=[obj])


def part_mesh_points(asset: Asset) -> np.ndarray:
    return np.vstack([part_mesh(part).vertices for part in asset.collision])


@pytest.mark.parametrize("quaternion", [(1.0, 0.0, 0.0, 0.0), (0.5**0.5, 0.5**0.5, 0.0, 0.0)], ids=["upright", "lying"])
def test_a_cylinder_stands_at_its_own_height_in_pybullet(
    quaternion: tuple[float, float, float, float], tmp_path: Path
) -> None:
    """PyBullet turns a URDF <cylinder> into a hull padded by its 1 mm margin (the can rose 1.0 mm and grew 1 mm
    wider); the export writes cylinders as inset meshes, so the can stays where MuJoCo put it."""
    pytest.importorskip("pybullet")
    scene = _lone_object("can_soup", quaternion)
    index = export_scene(scene, tmp_path, ["urdf"])["urdf"]
    link = ET.parse(index.parent / "can_0.urdf").getroot().find("link")
    assert link is not None and link.find("collision/geometry/cylinder") is None
    assert urdf_settle_distance(index).per_object["can_0"] < 0.0002


def test_a_thin_part_is_inset_to_a_thin_core_and_a_thick_one_by_the_margin() -> None:
    """What PyBullet collides is the written hull grown by its 1 mm margin: a 10 mm cube is written 8 mm wide, so it
    collides 10 mm wide; a 1.8 mm wall (a paper cup's) cannot lose 1 mm a side, so it keeps a 0.02 mm core and
    collides 2.02 mm thick, not 3.1 mm as when thin parts were inset by 40 % of their half-thickness (its sides move
    in as far as its faces, 0.89 mm)."""
    cube = inset_hull(trimesh.creation.box(extents=(0.01, 0.01, 0.01)), BULLET_URDF_MARGIN_M)
    assert np.ptp(cube.vertices, axis=0) == pytest.approx([0.008] * 3, abs=1e-9)
    wall = inset_hull(trimesh.creation.box(extents=(0.04, 0.03, 0.0018)), BULLET_URDF_MARGIN_M)
    assert np.ptp(wall.vertices, axis=0) == pytest.approx([0.03822, 0.02822, 0.00002], abs=1e-9)
    assert wall.vertices[:, 2].mean() == pytest.approx(0.0, abs=1e-9)  # the core stays in the middle of the wall


def test_a_book_sliding_on_the_table_in_pybullet_meets_it_with_no_more_friction_than_in_mujoco(tmp_path: Path) -> None:
    """MuJoCo gives a pair the larger coefficient, PyBullet the product of what the two links say. A book pushed
    along the table at 0.5 m/s stops after v^2 / (2 mu g): the friction PyBullet applied lies between the book's and
    the table's coefficients, near their geometric mean (written as they are, it was their product, below both)."""
    pybullet = pytest.importorskip("pybullet")
    scene = _lone_object("book_flat_hardcover_red")
    index = export_scene(scene, tmp_path, ["urdf"])["urdf"]
    client = pybullet.connect(pybullet.DIRECT)
    try:
        pybullet.setGravity(0, 0, -9.81, physicsClientId=client)
        handles = load_bodies(pybullet, index, client)
        book = handles["book_0"]
        for _ in range(24):  # let the contact form before the push
            pybullet.stepSimulation(physicsClientId=client)
        start = np.asarray(pybullet.getBasePositionAndOrientation(book, physicsClientId=client)[0])
        pybullet.resetBaseVelocity(book, [0.5, 0.0, 0.0], [0.0, 0.0, 0.0], physicsClientId=client)
        for _ in range(240):
            pybullet.stepSimulation(physicsClientId=client)
        slid = float(
            np.linalg.norm(np.asarray(pybullet.getBasePositionAndOrientation(book, physicsClientId=client)[0]) - start)
        )
    finally:
        pybullet.disconnect(physicsClientId=client)
    applied = 0.5**2 / (2 * 9.81 * slid)
    entries = json.loads(index.read_text())["bodies"]
    book_mu, table_mu = (next(e["friction"] for e in entries if e["id"] == k) for k in ("book_0", "support"))
    assert min(book_mu, table_mu) <= applied <= max(book_mu, table_mu)
    assert applied == pytest.approx((book_mu * table_mu) ** 0.5, rel=0.1)


@pytest.mark.slow
def test_a_stack_of_five_books_stands_still_in_pybullet(tmp_path: Path) -> None:
    """Bullet recomputed the books' friction points every step and `books_stack.json`'s pile crept (1.1 mm on average,
    2.1 mm at most over the 4 s settle); the books' links now anchor their contacts' friction, and it stays put."""
    pytest.importorskip("pybullet")
    solution = solve(EXAMPLES / "books_stack.json", seed=0)
    index = export_scene(solution.scene, tmp_path, ["urdf"])["urdf"]
    distance = urdf_settle_distance(index)
    assert len(distance.per_object) == 5
    assert distance.mean_m < 0.0006, distance.per_object
    assert max(distance.per_object.values()) < 0.001


def _anchored(index: Path, name: str) -> bool:
    link = ET.parse(index.parent / f"{name}.urdf").getroot().find("link")
    assert link is not None
    return link.find("contact/friction_anchor") is not None


@pytest.mark.parametrize(
    ("asset_id", "anchored"),
    [
        ("book_flat_hardcover_red", True),  # 25 mm thick
        ("flashlight_pen_light", True),  # 16 mm
        ("pen_fountain", False),  # 12.5 mm
        ("pen_ballpoint_blue", False),  # 9.5 mm
    ],
)
def test_objects_at_least_15_mm_thick_anchor_their_friction(asset_id: str, anchored: bool, tmp_path: Path) -> None:
    """Anchored contacts throw thin round things off what they lie on (a pen or chopsticks flew off in PyBullet)."""
    scene = _lone_object(asset_id)
    index = export_scene(scene, tmp_path, ["urdf"])["urdf"]
    assert _anchored(index, scene.objects[0].id) is anchored
    assert not _anchored(index, "support")


def test_a_pen_lying_on_a_book_stays_put_in_pybullet(tmp_path: Path) -> None:
    """Bullet anchors a contact when either body asks: a pen on an anchored book slid 3.7 mm (chopsticks 14 mm), so a
    thick object that a thin one touches is not anchored."""
    pytest.importorskip("pybullet")
    scene = _lone_object("book_flat_hardcover_red")
    book = scene.objects[0]
    pen_asset = default_catalogue().get("pen_ballpoint_blue")
    top = book.position[2] + float(part_mesh_points(default_catalogue().get(book.asset))[:, 2].max())
    pen = PlacedObject(
        id="pen_0",
        description="pen",
        asset=pen_asset.id,
        category=pen_asset.category,
        position=(0.0, 0.0, top - float(part_mesh_points(pen_asset)[:, 2].min())),
        mass=pen_asset.mass,
        friction=float(np.mean(pen_asset.friction_range)),
        com=pen_asset.com,
    )
    scene.objects.append(pen)
    index = export_scene(scene, tmp_path, ["urdf"])["urdf"]
    assert not _anchored(index, "book_0") and not _anchored(index, "pen_0")
    assert urdf_settle_distance(index).per_object["pen_0"] < 0.001
