"""Open containers get a base and wall sectors as collision: no CoACD run, the cavity open, the walls hugged."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from physcensis.assets import decompose
from physcensis.assets.container_parts import sector_bounds
from physcensis.assets.decompose import blocks_cavity, convex_decomposition
from physcensis.assets.hulls import surface_deviation
from physcensis.assets.library import _detect_cavity
from physcensis.assets.model import Cavity


def _standing(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    lo, hi = mesh.bounds
    mesh.apply_translation((-(lo[0] + hi[0]) / 2, -(lo[1] + hi[1]) / 2, -lo[2]))
    return mesh


def _cup(radius: float = 0.04, wall: float = 0.002, height: float = 0.09) -> trimesh.Trimesh:
    outer = trimesh.creation.cylinder(radius, height, sections=48)
    inner = trimesh.creation.cylinder(radius - wall, height, sections=48)
    inner.apply_translation((0, 0, 0.004))
    return _standing(trimesh.boolean.difference([outer, inner], engine="manifold"))


def _bin(size: tuple[float, float, float] = (0.3, 0.2, 0.12), wall: float = 0.003) -> trimesh.Trimesh:
    outer = trimesh.creation.box(size)
    inner = trimesh.creation.box((size[0] - 2 * wall, size[1] - 2 * wall, size[2]))
    inner.apply_translation((0, 0, 0.005))
    return _standing(trimesh.boolean.difference([outer, inner], engine="manifold"))


@pytest.fixture
def no_coacd(monkeypatch: pytest.MonkeyPatch) -> None:
    def refuse(*args: object, **kwargs: object) -> list[np.ndarray]:
        raise AssertionError("CoACD should not be needed for an open container")

    monkeypatch.setattr(decompose, "_run_coacd", refuse)


@pytest.mark.slow
@pytest.mark.parametrize("make", [_cup, _bin], ids=["thin cup", "thin bin"])
@pytest.mark.long
def test_thin_walled_containers_need_no_coacd_and_stay_open(make: object, no_coacd: None) -> None:
    mesh = make()  # type: ignore[operator]
    cavity = _detect_cavity(mesh)
    assert cavity is not None  # walls of 2-3 mm are found all around
    parts = convex_decomposition(mesh, cavity=cavity)
    assert 2 <= len(parts) <= 16
    assert not blocks_cavity(parts, cavity)
    deviation = surface_deviation(mesh, parts)
    assert deviation.mesh_max < 0.003  # the mesh is covered (to a few samples between sectors)
    assert deviation.hull_max < 0.006  # and the hulls hug it: no corner of the bin is cut off


def test_a_box_opening_puts_sector_borders_at_its_corners() -> None:
    opening = np.array([[0.1, 0.05], [-0.1, 0.05], [-0.1, -0.05], [0.1, -0.05]])
    bounds = np.degrees(sector_bounds(opening, np.zeros(2), 15))
    corners = np.degrees(np.mod(np.arctan2(opening[:, 1], opening[:, 0]), 2 * np.pi))
    assert len(bounds) == 15 and all(np.isclose(bounds, c).any() for c in corners)
    turns = np.linspace(0, 2 * np.pi, 48, endpoint=False)
    round_opening = 0.05 * np.column_stack([np.cos(turns), np.sin(turns)])
    assert np.allclose(np.diff(sector_bounds(round_opening, np.zeros(2), 15)), 2 * np.pi / 15)


def test_a_round_bottomed_bowl_falls_back_when_sectors_would_bridge_it(monkeypatch: pytest.MonkeyPatch) -> None:
    arc = np.linspace(0, np.pi / 2, 12)
    outer = np.column_stack([0.06 * np.sin(arc), 0.06 - 0.06 * np.cos(arc)])  # a hemisphere's profile, rim on top
    inner = np.column_stack([0.056 * np.sin(arc), 0.06 - 0.056 * np.cos(arc)])[::-1]
    shell = _standing(trimesh.creation.revolve(np.vstack([outer, inner]), sections=32))
    cavity = Cavity(np.array([[0.05, 0.0], [0.0, 0.05], [-0.05, 0.0], [0.0, -0.05]]), 0.004, 0.056)
    calls: list[int] = []

    def coacd_stand_in(mesh: trimesh.Trimesh, threshold: float, time_limit: float) -> list[np.ndarray]:
        calls.append(1)
        return decompose.voxel_boxes(mesh)

    monkeypatch.setattr(decompose, "_run_coacd", coacd_stand_in)
    parts = convex_decomposition(shell, cavity=cavity)
    assert calls and parts  # the sectors' hulls would bridge the round bottom: CoACD's turn
