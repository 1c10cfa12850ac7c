"""Bowls, colanders and paper cups dropped into one of their own kind nest in it: each sits centred inside the one
below, a little higher, and the whole nest rests."""

from __future__ import annotations

import numpy as np
import pytest

from physcensis.assets.catalogue import default_catalogue
from physcensis.scene import Support
from physcensis.solver.pipeline import solve


@pytest.mark.slow
@pytest.mark.parametrize(
    ("description", "seed"),
    [
        ("a white ceramic cereal bowl", 1),
        ("a white ceramic cereal bowl", 2),
        ("a steel mixing bowl", 0),
        ("a metal colander", 0),
    ],
)
@pytest.mark.long
def test_a_nest_of_four(description: str, seed: int) -> None:
    program: list[list[object]] = [
        ["nest_0", description],
        ["nest_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
        ["nest_0", "FACING-FRONT", "root", {}],
    ]
    for k in range(1, 4):
        program += [[f"nest_{k}", description], [[f"nest_{k}"], "PLACE-IN", f"nest_{k - 1}", {}]]
    solution = solve(program, support=Support(kind="shelf", size=(0.35, 1.0)), seed=seed)
    scene = solution.scene
    assert all(o.status == "placed" for o in scene.objects), solution.feedback()
    levels = [scene.object(f"nest_{k}") for k in range(4)]
    size = default_catalogue().asset_for(levels[0].asset, levels[0].description).size
    for below, above in zip(levels, levels[1:], strict=False):
        rise = above.position[2] - below.position[2]
        assert 0.0 < rise < 0.6 * size[2]  # inside the one below: higher, but by less than its height
        assert np.linalg.norm(np.subtract(above.position[:2], below.position[:2])) < 0.15 * size[0]  # centred
    assert scene.metrics["settle_distance_m"] < 0.003
