"""Golden geometry of every built-in asset: a generator refactor must not move one vertex.

`builtin_geometry.json` holds, per asset id, a summary of its built geometry (vertex
moments per visual part, face checksums, colours, collision parts, cavity, mass and
centre of mass), recorded from the generators as they were.  The comparison allows
only floating-point noise, so any change of shape, default or option shows up.
Re-record after an intended change of shape with
`python tests/assets/test_builtin_geometry.py --write`.
"""

from __future__ import annotations

import hashlib
import json
import sys
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from physcensis.assets.model import Asset, CollisionPart

GOLDEN = Path(__file__).with_name("builtin_geometry.json")
RTOL, ATOL = 1e-8, 1e-12  # the file keeps 10 significant digits


def _moments(points: np.ndarray) -> list[float]:
    """Count, per-axis sums and sums of squares: any moved vertex changes them."""
    pts = np.asarray(points, dtype=float).reshape(-1, 3)
    return [float(len(pts)), *pts.sum(axis=0).tolist(), *(pts**2).sum(axis=0).tolist()]


def _checksum(array: np.ndarray) -> str:
    return hashlib.sha1(np.ascontiguousarray(array).tobytes()).hexdigest()[:16]


def _collision(parts: tuple[CollisionPart, ...]) -> dict[str, Any]:
    meshes = [p.vertices for p in parts if p.vertices is not None]
    primitives = [[*p.size, *p.pos, *p.quat] for p in parts if p.vertices is None]
    return {
        "kinds": ",".join(p.kind for p in parts),
        "mesh_vertices": _moments(np.vstack(meshes)) if meshes else [],
        "primitives": [float(x) for row in primitives for x in row],
    }


def summary(asset: Asset) -> dict[str, Any]:
    """The golden record of one asset: visual and collision geometry, colours, cavity, mass and centre of mass."""
    cavity: list[float] = []
    if asset.cavity is not None:
        opening = np.column_stack([asset.cavity.opening, np.zeros(len(asset.cavity.opening))])
        cavity = [*_moments(opening), asset.cavity.floor_height, asset.cavity.depth]
    record = {
        "size": list(asset.size),
        "faces": _checksum(np.asarray(asset.visual.faces, dtype=np.int64)),
        "part_faces": [float(n) for n in asset.part_faces],
        "colors": _checksum(np.round(np.asarray(asset.rgba, dtype=float), 6)),
        "visual": _moments(asset.visual.vertices),
        **{f"collision_{k}": v for k, v in _collision(asset.collision).items()},
        "cavity": cavity,
        "mass_com": [asset.mass, *asset.com],
    }
    return {k: [float(f"{x:.10g}") for x in v] if isinstance(v, list) else v for k, v in record.items()}


def _assert_close(actual: dict[str, Any], expected: dict[str, Any], where: str) -> None:
    assert actual.keys() == expected.keys(), where
    for key, want in expected.items():
        if isinstance(want, list):
            assert len(actual[key]) == len(want), f"{where}.{key}: {len(actual[key])} numbers, expected {len(want)}"
            np.testing.assert_allclose(actual[key], want, rtol=RTOL, atol=ATOL, err_msg=f"{where}.{key}")
        else:
            assert actual[key] == want, f"{where}.{key}: {actual[key]!r} != {want!r}"


@pytest.fixture(scope="module")
def golden() -> dict[str, Any]:
    return json.loads(GOLDEN.read_text())


@pytest.mark.slow
def test_every_builtin_asset_is_in_the_golden_file(golden: dict[str, Any], by_id: dict[str, Asset]) -> None:
    builtin = sorted(i for i, a in by_id.items() if a.source == "builtin")
    assert builtin == sorted(golden)


def test_builtin_geometry_matches_the_golden_file(golden: dict[str, Any], by_id: dict[str, Asset]) -> None:
    for asset_id, expected in golden.items():
        _assert_close(summary(by_id[asset_id]), expected, asset_id)


def test_the_comparison_sees_a_small_change(golden: dict[str, Any], by_id: dict[str, Asset]) -> None:
    """A vertex moved by 10 micrometres fails the comparison (the test can fail)."""
    asset = by_id["bottle_wine_red"]
    moved = asset.visual.copy()
    moved.vertices[0] += 1e-5
    with pytest.raises(AssertionError):
        _assert_close(summary(replace(asset, visual=moved)), golden[asset.id], asset.id)


def write_golden() -> None:
    from physcensis.assets.catalogue import Catalogue

    catalogue = Catalogue(cache=False)
    table = {a.id: summary(a) for a in catalogue.all() if a.source == "builtin"}
    rows = (f"{json.dumps(asset_id)}: {json.dumps(record)}" for asset_id, record in sorted(table.items()))
    GOLDEN.write_text("{\n" + ",\n".join(rows) + "\n}\n")  # one asset a line: readable diffs


if __name__ == "__main__":
    if sys.argv[1:] != ["--write"]:
        sys.exit("usage: python tests/assets/test_builtin_geometry.py --write")
    write_golden()
