"""Fast import of real meshes: one hull when it fits, budgeted CoACD with a voxel fallback, a whole-asset cache."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pytest
import trimesh

from physcensis.assets import decompose, library
from physcensis.assets.cache import AssetCache
from physcensis.assets.decompose import cavity_probe_points, voxel_boxes
from physcensis.assets.hulls import inside_any, near_convex, surface_deviation, surface_distance
from physcensis.assets.library import load_library


def _library(folder: Path, meshes: dict[str, trimesh.Trimesh], **fields: object) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    entries = []
    for name, mesh in meshes.items():
        (folder / f"{name}.stl").write_bytes(mesh.export(file_type="stl"))
        entries.append({"file": f"{name}.stl", "id": name, "category": "mug", "up": "+z", **fields})
    (folder / "library.json").write_text(json.dumps({"assets": entries}))
    return folder


def _can_with_holes() -> trimesh.Trimesh:
    """A 5 x 8 cm cylinder missing a few faces (scanned and CAD meshes often have such holes)."""
    can = trimesh.creation.cylinder(radius=0.025, height=0.08, sections=48)
    keep = np.ones(len(can.faces), dtype=bool)
    keep[[3, 40, 77]] = False
    can.update_faces(keep)
    return can


def _cup() -> trimesh.Trimesh:
    """An open cup: a 4 mm annulus wall 9 cm high on a 6 mm bottom, 8 cm across (two overlapping open parts)."""
    wall = trimesh.creation.annulus(r_min=0.036, r_max=0.04, height=0.09, sections=32)
    wall.apply_translation((0, 0, 0.045))
    bottom = trimesh.creation.cylinder(radius=0.04, height=0.006, sections=32)
    bottom.apply_translation((0, 0, 0.003))
    return trimesh.util.concatenate([wall, bottom])


def _cavity_points() -> np.ndarray:
    """Points inside the cup's cavity, in its local frame (base at z = 0), from just above the floor to the rim."""
    angles = np.linspace(0, 2 * np.pi, 12, endpoint=False)
    rings = [np.zeros((1, 2))] + [r * np.c_[np.cos(angles), np.sin(angles)] for r in (0.015, 0.028)]
    return np.array([[x, y, z] for z in np.linspace(0.015, 0.088, 8) for ring in rings for x, y in ring])


def _vertices(asset: object) -> list[np.ndarray]:
    return [np.asarray(p.vertices) for p in asset.collision]  # type: ignore[attr-defined]


def test_surface_distance_is_exact_for_a_box() -> None:
    box = trimesh.creation.box((0.1, 0.2, 0.3))
    points = np.random.default_rng(0).normal(scale=0.2, size=(400, 3))
    q = np.abs(points) - np.array([0.05, 0.1, 0.15])
    signed = np.linalg.norm(np.maximum(q, 0), axis=1) + np.minimum(q.max(axis=1), 0)
    assert np.allclose(surface_distance(box, points), np.abs(signed), atol=1e-12)


def test_a_can_with_holes_gets_one_hull(tmp_path: Path) -> None:
    can = _can_with_holes()
    assert not can.is_watertight and near_convex(can)
    assert not near_convex(_cup())
    result = load_library(_library(tmp_path / "lib", {"can": can}, container=False), cache=AssetCache(tmp_path / "c"))
    assert result.errors == []
    assert len(result.assets[0].collision) == 1


@pytest.mark.slow
@pytest.mark.long
def test_a_cup_keeps_its_cavity_open_within_a_few_millimetres(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(decompose, "TIME_LIMIT", 5.0)  # CoACD or the fallback: either must keep the cup open
    result = load_library(_library(tmp_path / "lib", {"cup": _cup()}), cache=AssetCache(tmp_path / "c"))
    assert result.errors == []
    (cup,) = result.assets
    assert cup.cavity is not None
    parts = _vertices(cup)
    assert 1 < len(parts) <= decompose.MAX_PARTS
    assert not inside_any(_cavity_points(), parts).any()  # an item dropped in goes in
    deviation = surface_deviation(cup.visual, parts, samples=1500)
    assert deviation.mesh_max < 0.002  # the hulls cover the cup
    assert deviation.hull_p95 < 0.006 and deviation.hull_max < 0.012


@pytest.mark.slow
@pytest.mark.long
def test_voxel_fallback_keeps_the_cavity_open() -> None:
    cup = _cup()
    parts = voxel_boxes(cup)
    assert len(parts) <= decompose.MAX_PARTS
    assert not inside_any(_cavity_points(), parts).any()
    assert surface_deviation(cup, parts, samples=1500).mesh_max < 0.002


def test_a_decomposition_over_its_time_falls_back_and_the_entry_imports(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(decompose, "TIME_LIMIT", 0.5)
    monkeypatch.setattr(decompose, "_worker_command", lambda: [sys.executable, "-c", "import time; time.sleep(30)"])
    cache = AssetCache(tmp_path / "c")
    # The cup takes the container-sector path; the L-shaped block (concave, no cavity) is what reaches CoACD.
    arm_x = trimesh.creation.box((0.12, 0.03, 0.03), trimesh.transformations.translation_matrix((0.045, 0, 0)))
    arm_y = trimesh.creation.box((0.03, 0.12, 0.03), trimesh.transformations.translation_matrix((0, 0.045, 0)))
    ell = trimesh.boolean.union([arm_x, arm_y])
    result = load_library(_library(tmp_path / "lib", {"cup": _cup(), "ell": ell}), cache=cache)
    assert result.errors == []
    cup, block = result.assets
    assert 1 < len(block.collision) <= decompose.MAX_PARTS  # the voxel fallback, not one hull
    assert cup.cavity is not None
    parts = _vertices(cup)
    assert 1 < len(parts) <= decompose.MAX_PARTS
    assert not inside_any(cavity_probe_points(cup.cavity), parts).any()
    assert not (tmp_path / "c" / "coacd").exists()  # a fallback is not cached as if it were CoACD's answer


def test_a_failing_entry_stays_its_own_while_the_others_load_in_parallel(tmp_path: Path) -> None:
    lib = _library(tmp_path / "lib", {"can": _can_with_holes(), "box": trimesh.creation.box((0.05, 0.05, 0.05))})
    spec = json.loads((lib / "library.json").read_text())
    spec["assets"].insert(1, {"file": "missing.stl"})
    (lib / "library.json").write_text(json.dumps(spec))
    seen: list[str] = []
    result = load_library(lib, workers=2, progress=lambda label, outcome: seen.append(label))
    assert [a.id for a in result.assets] == ["can", "box"]
    assert len(result.errors) == 1 and "missing.stl" in str(result.errors[0])
    assert len(seen) == 3


def test_a_second_load_comes_from_the_asset_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(decompose, "TIME_LIMIT", 2.0)
    lib = _library(tmp_path / "lib", {"cup": _cup(), "can": _can_with_holes()})
    cache = AssetCache(tmp_path / "c")
    first = load_library(lib, cache=cache)
    assert first.errors == []

    def refuse(*args: object, **kwargs: object) -> None:
        raise AssertionError("ingested again although nothing changed")

    monkeypatch.setattr(decompose, "_run_coacd", refuse)
    monkeypatch.setattr(library, "ingest", refuse)
    second = load_library(lib, cache=cache)
    assert second.errors == []
    for old, new in zip(first.assets, second.assets, strict=True):
        assert new.id == old.id and len(new.collision) == len(old.collision)
        assert np.allclose(new.visual.vertices, old.visual.vertices)
        assert new.cavity is not None or old.cavity is None
    monkeypatch.undo()
    monkeypatch.setattr(decompose, "TIME_LIMIT", 2.0)
    for entry in (tmp_path / "c" / "assets").glob("lib-*.npz"):
        entry.write_bytes(b"damaged")
    (lib / "cup.stl").write_bytes((lib / "cup.stl").read_bytes())  # same bytes: same key, damaged entry rebuilt
    again = load_library(lib, cache=cache)
    assert again.errors == [] and [a.id for a in again.assets] == ["cup", "can"]


def test_changing_the_mesh_file_changes_the_cached_asset(tmp_path: Path) -> None:
    lib = _library(tmp_path / "lib", {"box": trimesh.creation.box((0.05, 0.05, 0.05))})
    cache = AssetCache(tmp_path / "c")
    assert load_library(lib, cache=cache).assets[0].size[0] == pytest.approx(0.05)
    (lib / "box.stl").write_bytes(trimesh.creation.box((0.08, 0.05, 0.05)).export(file_type="stl"))
    assert load_library(lib, cache=cache).assets[0].size[0] == pytest.approx(0.08)


def test_import_command_takes_workers_and_keeps_json_clean(tmp_path: Path, cache_dir: Path) -> None:
    from typer.testing import CliRunner

    from physcensis.cli.assets import assets_app

    lib = _library(tmp_path / "lib", {"can": _can_with_holes(), "box": trimesh.creation.box((0.05, 0.05, 0.05))})
    result = CliRunner().invoke(assets_app, ["import", str(lib), "--json", "--workers", "3"])
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout)
    assert [a["id"] for a in payload["imported"]] == ["can", "box"]
    assert [a["collision_parts"] for a in payload["imported"]] == [1, 1]


def test_the_import_benchmark_gives_a_readme_table(tmp_path: Path) -> None:
    from physcensis.bench.report import render_tables

    mesh = {"id": "pb_mug", "seconds": 2.7, "hulls": 16, "hull_from_mesh_max_mm": 6.4, "hull_from_mesh_p95_mm": 4.5}
    result = {
        "sources": ["pb", "rs"],
        "meshes": [{**mesh, "mesh_outside_hulls_mm": 0.0, "cavity": True}, {"id": "x.stl", "error": "unreadable"}],
        "library_assets": 10,
        "library_cold_s": 8.3,
        "library_warm_s": 0.03,
    }
    (tmp_path / "import.json").write_text(json.dumps({"benchmark": "import", "result": result}))
    block = render_tables(tmp_path)["import"]
    assert "| pb_mug | 2.7 | 16 | 6.4 / 4.5 | open |" in block
    assert "| x.stl |  | failed |" in block
    assert "| whole library cold (10 assets, 2 workers) | 8.3 |" in block and "Meshes from: pb, rs." in block
    assert "not measured yet" in render_tables(tmp_path / "none")["import"]
