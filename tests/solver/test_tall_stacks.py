"""Stacks hold at any height the solver is asked for: toy blocks on floors of any size (the floor's search grid has
3 cm cells and its alignment with a 4 cm block depends on the floor's size) and thin things (envelopes, napkins) whose
cells overlap those of the one below their target."""

from __future__ import annotations

import numpy as np
import pytest

from physcensis.assets.catalogue import default_catalogue
from physcensis.scene import Support
from physcensis.solver.pipeline import solve


def _stack(description: str, height: int, support: Support) -> list[list[object]]:
    program: list[list[object]] = [
        ["level_0", description],
        ["level_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
        ["level_0", "FACING-FRONT", "root", {}],
    ]
    for k in range(1, height):
        program += [[f"level_{k}", description], [f"level_{k}", "PLACE-ON", f"level_{k - 1}", {"overlap": 0.9}]]
    return program


@pytest.mark.parametrize(
    ("description", "height", "support"),
    [
        ("a red wooden toy cube", 6, Support(kind="floor", size=(1.2, 1.6))),
        ("a red wooden toy cube", 6, Support(kind="floor", size=(1.5, 1.5))),
        ("a yellow wooden toy cube", 5, Support(kind="floor", size=(3.1, 2.3))),
        ("a white letter envelope", 6, Support(kind="table", size=(0.8, 0.6))),
        ("a folded paper napkin", 6, Support(kind="table", size=(0.8, 0.6))),
    ],
)
def test_every_level_rests_on_the_one_below(description: str, height: int, support: Support) -> None:
    solution = solve(_stack(description, height, support), support=support, seed=0)
    scene = solution.scene
    assert all(o.status == "placed" for o in scene.objects), solution.feedback()
    levels = [scene.object(f"level_{k}") for k in range(height)]
    item = default_catalogue().asset_for(levels[0].asset, levels[0].description)
    for below, above in zip(levels, levels[1:], strict=False):
        rise = above.position[2] - below.position[2]
        assert 0.5 * item.size[2] < rise < 1.5 * item.size[2] + 0.002  # on top of it, not beside or inside it
        assert np.linalg.norm(np.subtract(above.position[:2], below.position[:2])) < 0.5 * min(item.size[:2])
    assert scene.metrics["settle_distance_m"] < 0.003
