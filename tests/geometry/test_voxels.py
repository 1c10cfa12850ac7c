"""Voxel grids: occupancy, free translations, resting heights and the centre-of-mass support test."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from scipy.signal import correlate
from scipy.spatial.transform import Rotation

from physcensis.assets.model import Asset, CollisionPart
from physcensis.geometry.voxels import (
    Grid,
    Spectrum,
    collision_counts,
    inside_part,
    object_grid,
    part_cells,
    rasterise,
    resting_heights,
    supported_candidates,
)


def test_collision_counts_match_a_direct_count() -> None:
    rng = np.random.default_rng(0)
    scene = rng.random((9, 8, 7)) < 0.3
    obj = rng.random((3, 2, 2)) < 0.6
    counts = collision_counts(scene, obj)
    assert counts.shape == (7, 7, 6)
    for t in [(0, 0, 0), (3, 4, 2), (6, 6, 5)]:
        direct = (scene[t[0] : t[0] + 3, t[1] : t[1] + 2, t[2] : t[2] + 2] & obj).sum()
        assert counts[t] == pytest.approx(direct, abs=1e-3)


def test_resting_height_is_where_a_dropped_object_stops() -> None:
    counts = np.zeros((2, 1, 6))
    counts[0, 0, :3] = 1  # column 0: blocked up to layer 2 -> rests at 3
    counts[1, 0, 4] = 1  # column 1: blocked only at layer 4 -> rests at 5 (cannot pass through)
    rest, reachable = resting_heights(counts)
    assert rest[0, 0] == 3 and rest[1, 0] == 5 and reachable.all()


def test_parts_cover_their_volume() -> None:
    box = CollisionPart("box", (0.1, 0.05, 0.02))
    points = np.array([[0.09, 0.0, 0.0], [0.11, 0.0, 0.0], [0.0, 0.0, 0.021]])
    assert inside_part(box, points, 0.0).tolist() == [True, False, False]
    assert inside_part(box, points, 0.015).tolist() == [True, True, True]
    cube = CollisionPart(
        "mesh", vertices=np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    )
    assert inside_part(cube, np.array([[0.5, 0.5, 0.5], [1.5, 0.5, 0.5]]), 0.0).tolist() == [True, False]


@pytest.mark.parametrize("seed", range(3))
def test_a_mesh_part_has_the_cells_whose_centres_are_inside_its_grown_hull(seed: int) -> None:
    """Mesh parts are rasterised a column at a time: exactly the cells of testing each centre against the hull, for a
    turned and tilted blob and for a cube whose grown faces pass through rows of cell centres."""
    rng = np.random.default_rng(seed)
    grid = Grid(np.zeros((40, 40, 40), dtype=bool), np.full((40, 40, 40), -1, dtype=np.int32), np.full(3, -0.2), 0.01)
    blob = rng.normal(size=(40, 3)) * np.array([0.08, 0.05, 0.03])
    cube = np.array([[x, y, z] for x in (0.0, 0.1) for y in (0.0, 0.1) for z in (0.0, 0.1)])
    tilted = Rotation.random(random_state=seed).as_matrix()
    for vertices, rotation, translation, pad in (
        (blob, tilted, rng.uniform(-0.02, 0.02, 3), 0.0025),
        (cube, np.eye(3), np.zeros(3), 0.005),
    ):
        part = CollisionPart("mesh", vertices=vertices)
        (cells,) = part_cells(grid, [part], rotation, translation, pad)
        axes = [
            grid.origin[a] + (cells.lo[a] + np.arange(n) + 0.5) * grid.pitch for a, n in enumerate(cells.inside.shape)
        ]
        gx, gy, gz = np.meshgrid(*axes, indexing="ij")
        points = np.stack([gx.ravel(), gy.ravel(), gz.ravel()], axis=1)
        expected = inside_part(part, (points - translation) @ rotation, pad).reshape(gx.shape)
        assert expected.any() and np.array_equal(cells.inside, expected)


def _slab_scene(nx: int = 20, ny: int = 20, nz: int = 10) -> Grid:
    grid = Grid(
        np.zeros((nx, ny, nz), dtype=bool), np.full((nx, ny, nz), -1, dtype=np.int32), np.array([0.0, 0.0, 0.0]), 0.01
    )
    rasterise(grid, [CollisionPart("box", (0.1, 0.1, 0.01), (0.1, 0.1, 0.01))], np.eye(3), np.zeros(3), -2, 0.0)
    return grid


def test_centre_of_mass_must_project_inside_the_contact_patch() -> None:
    from physcensis.geometry.voxels import _DIRECTIONS, ObjectGrid

    scene = _slab_scene()
    # a small raised block in one corner of the slab
    rasterise(scene, [CollisionPart("box", (0.02, 0.02, 0.02), (0.03, 0.03, 0.04))], np.eye(3), np.zeros(3), 0, 0.0)
    occ = np.ones((6, 6, 1), dtype=bool)
    inner = Grid(occ, np.zeros_like(occ, dtype=np.int32), np.array([-0.03, -0.03, 0.0]), 0.01)
    i, j = np.nonzero(occ[:, :, 0])
    k = np.zeros_like(i)
    cx = -0.03 + (i + 0.5) * 0.01
    cy = -0.03 + (j + 0.5) * 0.01
    obj = ObjectGrid(inner, 0.0, np.array([0.03, 0.03, 0.0]), i, j, k, np.stack([cx, cy], 1) @ _DIRECTIONS.T)
    cands = supported_candidates(scene, obj, min_margin=0.005)
    assert len(cands.tx) > 0
    on_block = cands.tz > 2
    # on the raised block only spots with the whole plate above the block are kept (COM over the block)
    assert not on_block.any() or (cands.ratio[on_block] > 0.4).all()
    flat = ~on_block
    assert (cands.ratio[flat] == 1.0).all()


def _asset(
    parts: tuple[CollisionPart, ...], size: tuple[float, float, float], com: tuple[float, float, float]
) -> Asset:
    return Asset(
        id="probe",
        category="probe",
        kind="box",
        description="a probe",
        size=size,
        visual=trimesh.creation.box(size),
        collision=parts,
        mass=0.1,
        mass_range=(0.1, 0.1),
        friction_range=(0.5, 0.5),
        com=com,
    )


def test_an_object_smaller_than_a_cell_rests_squarely_on_its_one_column() -> None:
    # A 16 mm die on the floor's 3 cm grid has one bottom column whose centre lies beside its COM; the die still rests
    # on that cell, so the support test must see the COM well inside the patch.
    die = _asset(
        (CollisionPart("box", (0.008, 0.008, 0.008), (0.0, 0.0, 0.008)),), (0.016, 0.016, 0.016), (0, 0, 0.008)
    )
    for yaw in (0.0, 0.4):
        og = object_grid(die, yaw, 0.03, pad=0.0075)
        assert len(og.bottom_i) >= 1
        assert og.flat_projections.max(axis=0).min() >= 0.3 * 0.008  # the solver's margin for an object this small


def test_a_patch_reaches_no_further_than_the_object_itself() -> None:
    die = _asset(
        (CollisionPart("box", (0.008, 0.008, 0.008), (0.0, 0.0, 0.008)),), (0.016, 0.016, 0.016), (0, 0, 0.008)
    )
    og = object_grid(die, 0.0, 0.03, pad=0.0)
    assert og.flat_projections.max() <= 0.008 * np.sqrt(2) + 1e-9


def test_a_thin_contact_point_counts_in_the_contact_patch() -> None:
    # A heavy block held up at one end by a thin tilted rod: it rests on the block's edge and the rod's tip, which
    # is thinner than a cell, so no cell centre is inside it; the tip's cell must still be part of the patch.
    block = CollisionPart("box", (0.03, 0.03, 0.03), (-0.07, 0.0, 0.03))
    tip = np.array([[0.1, -0.002, 0.0], [0.1, 0.002, 0.0], [0.1, 0.0, 0.004], [-0.04, 0.0, 0.004]])
    rod = CollisionPart("mesh", vertices=tip)
    lop_sided = _asset((block, rod), (0.2, 0.06, 0.06), (0.0, 0.0, 0.02))  # COM between block and tip
    og = object_grid(lop_sided, 0.0, 0.01, pad=0.0025)
    assert og.flat_projections.max(axis=0).min() > 0.0
    without_rod = object_grid(_asset((block,), (0.06, 0.06, 0.06), (0.0, 0.0, 0.02)), 0.0, 0.01, pad=0.0025)
    assert without_rod.flat_projections.max(axis=0).min() < 0.0


@pytest.mark.parametrize(
    ("shape", "kernel"), [((37, 61, 9), (5, 3, 2)), ((12, 12, 4), (12, 12, 4)), ((40, 60), (7, 30))]
)
def test_a_kept_scene_spectrum_correlates_like_scipy(shape: tuple[int, ...], kernel: tuple[int, ...]) -> None:
    rng = np.random.default_rng(3)
    cells = rng.random(shape) < 0.3
    spectrum = Spectrum(cells)
    for _ in range(3):  # one transform of the scene, several kernels (the yaws of a search)
        k = rng.random(kernel) < 0.5
        expected = correlate(cells.astype(np.float32), k.astype(np.float32), mode="valid", method="direct")
        np.testing.assert_allclose(spectrum.correlate_valid(k), expected, atol=1e-3)
    assert spectrum.correlate_valid(np.ones(tuple(n + 1 for n in shape), dtype=bool)).size == 0


def test_a_grid_forgets_its_spectra_when_cells_are_added() -> None:
    grid = Grid(np.zeros((6, 6, 4), dtype=bool), np.full((6, 6, 4), -1, dtype=np.int32), np.zeros(3), 0.01)
    before = grid.spectrum("occupied", lambda: grid.occupied).correlate_valid(np.ones((2, 2, 2), dtype=bool))
    assert before.max() == 0
    box = CollisionPart(kind="box", size=(0.01, 0.01, 0.01), pos=(0.03, 0.03, 0.02))
    rasterise(grid, [box], np.eye(3), np.zeros(3), 0, 0.0)
    after = grid.spectrum("occupied", lambda: grid.occupied).correlate_valid(np.ones((2, 2, 2), dtype=bool))
    assert after.max() > 0.5
