"""The Asset data model's own checks and derived geometry."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from physcensis.assets.collision import box_part
from physcensis.assets.model import Asset, CollisionPart


def _asset(**kw: object) -> Asset:
    mesh = trimesh.creation.box((0.1, 0.2, 0.3))
    mesh.apply_translation((0, 0, 0.15))
    base = dict(
        id="box_a",
        category="box",
        kind="box",
        description="a box",
        size=(0.1, 0.2, 0.3),
        visual=mesh,
        collision=(box_part((0.1, 0.2, 0.3), (0, 0, 0.15)),),
        mass=1.0,
        mass_range=(0.9, 1.1),
        friction_range=(0.4, 0.6),
    )
    base.update(kw)
    return Asset(**base)  # type: ignore[arg-type]


def test_valid_asset_and_parts() -> None:
    a = _asset()
    assert a.part_faces == (12,)
    ((mesh, color),) = a.visual_parts()
    assert len(mesh.faces) == 12 and color == a.rgba[0]
    assert a.names == ("box",)
    assert a.collision[0].volume == pytest.approx(0.006)


@pytest.mark.parametrize(
    "kw, message",
    [
        ({"id": "bad id!"}, "not valid"),
        ({"mass": 2.0}, "outside its range"),
        ({"collision": ()}, "collision part"),
        ({"support_probability": 1.5}, "support_probability"),
        ({"rgba": ((1, 0, 0, 1), (0, 1, 0, 1))}, "part_faces"),
    ],
)
def test_invalid_assets_are_refused(kw: dict, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        _asset(**kw)


def test_mesh_part_needs_vertices() -> None:
    with pytest.raises(ValueError):
        CollisionPart("mesh")
    with pytest.raises(ValueError):
        CollisionPart("torus")  # type: ignore[arg-type]
    part = CollisionPart("mesh", vertices=np.eye(4, 3))
    moved = part.translated(np.array([1.0, 0, 0]))
    assert moved.vertices is not None and moved.vertices[0, 0] == 2.0
