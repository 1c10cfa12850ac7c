"""The bench programs solve with the real catalogue: relations hold, nothing overlaps, all on the support."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
import shapely

from physcensis.assets import default_catalogue
from physcensis.geometry.footprints import rotate
from physcensis.output import write_solution
from physcensis.program import load_program
from physcensis.scene import load_scene
from physcensis.solver.objects import quaternion_yaw
from physcensis.solver.pipeline import NO_PHYSICS_REASON, Solution, solve

from ..conftest import EXAMPLES


def polygons(solution: Solution) -> dict[str, shapely.Polygon]:
    out = {}
    for o in solution.scene.objects:
        hull = solution.assets[o.id].footprint()
        pts = rotate(hull, np.array([quaternion_yaw(o.quaternion)]))[0] + o.position[:2]
        out[o.id] = shapely.Polygon(pts)
    return out


def assert_valid_layout(solution: Solution) -> dict[str, shapely.Polygon]:
    polys = polygons(solution)
    ids = sorted(polys)
    for i, a in enumerate(ids):
        for b in ids[i + 1 :]:
            assert polys[a].intersection(polys[b]).area <= 1e-4, (a, b)
    hx, hy = solution.scene.support.half_extents
    table = shapely.box(-hx, -hy, hx, hy).buffer(1e-9)
    for oid, poly in polys.items():
        assert poly.difference(table).area <= 1e-6, oid
        assert solution.scene.object(oid).position[2] == pytest.approx(solution.scene.support.top_height)
    return polys


def bounds(polys: dict[str, shapely.Polygon], oid: str) -> tuple[float, float, float, float]:
    minx, miny, maxx, maxy = polys[oid].bounds
    return minx, maxx, miny, maxy


def test_desk_basic() -> None:
    solution = solve(load_program(EXAMPLES / "desk_basic.json"), seed=0, physics=False)
    assert solution.spatial is not None and solution.spatial.ok
    polys = assert_valid_layout(solution)
    laptop, notebook = bounds(polys, "laptop_0"), bounds(polys, "notebook_0")
    distance = solution.spatial.params[6]["distance"]
    assert notebook[0] - laptop[1] == pytest.approx(distance, abs=1e-6)  # FRONT-OF
    assert (notebook[2] + notebook[3]) / 2 == pytest.approx((laptop[2] + laptop[3]) / 2, abs=1e-6)
    assert [p["objects"] for p in solution.pending] == [["cup_0"]]  # PLACE-ON waits for the physical solver
    assert solution.pending[0]["reason"] == NO_PHYSICS_REASON  # which runs only with physics on


def test_dining_four() -> None:
    solution = solve(load_program(EXAMPLES / "dining_4.json"), seed=0, physics=False)
    assert solution.ok and len(solution.scene.objects) == 16
    polys = assert_valid_layout(solution)
    params = solution.spatial.params if solution.spatial else {}
    for suffix in ("", "-group_setting_1", "-group_setting_2", "-group_setting_3"):
        plate, fork = solution.scene.object(f"plate_0{suffix}"), solution.scene.object(f"fork_0{suffix}")
        knife, cup = solution.scene.object(f"knife_0{suffix}"), solution.scene.object(f"cup_0{suffix}")
        # the knife mirrors the fork across the plate
        centre = np.array(polys[plate.id].envelope.centroid.coords[0])
        fork_c = np.array(polys[fork.id].envelope.centroid.coords[0])
        knife_c = np.array(polys[knife.id].envelope.centroid.coords[0])
        assert np.allclose(fork_c + knife_c, 2 * centre, atol=1e-6)
        # each plate faces the middle of the table, i.e. away from its diner's edge
        yaw = quaternion_yaw(plate.quaternion)
        facing = np.array([math.cos(yaw), math.sin(yaw)])
        assert float(facing @ -np.array(plate.position[:2])) > 0.9 * np.linalg.norm(plate.position[:2])
        # the glass stands on the far side of the plate from the diner
        assert float((np.array(cup.position[:2]) - plate.position[:2]) @ facing) > 0.1
        # fork on the diner's left: diner looks along `facing`, so left is facing turned +90 deg
        left = np.array([-facing[1], facing[0]])
        assert float((np.array(fork.position[:2]) - plate.position[:2]) @ left) > 0.1
    plate0 = bounds(polys, "plate_0")
    fork0 = bounds(polys, "fork_0")
    assert plate0[2] - fork0[3] == pytest.approx(params[6]["distance"], abs=1e-6)  # RIGHT-OF


def test_same_program_and_seed_same_scene(tmp_path: Path) -> None:
    program = load_program(EXAMPLES / "dining_4.json")
    first, second = solve(program, seed=3), solve(program, seed=3)
    assert first.scene == second.scene
    # scene.json alone is compared: the render and exports, written after it from the same scene, are left out
    write_solution(first, tmp_path / "a", physics_outputs=False, layout_png=False)
    write_solution(second, tmp_path / "b", physics_outputs=False, layout_png=False)
    assert (tmp_path / "a" / "scene.json").read_bytes() == (tmp_path / "b" / "scene.json").read_bytes()


def test_written_folder_has_scene_report_and_layout(tmp_path: Path) -> None:
    out = write_solution(
        solve(load_program(EXAMPLES / "books_stack.json"), physics=False), tmp_path / "books", physics_outputs=False
    )
    assert sorted(p.name for p in out.iterdir()) == [".physcensis.json", "layout.png", "report.json", "scene.json"]
    scene = load_scene(out)
    assert [o.id for o in scene.objects] == ["book_0"]
    report = json.loads((out / "report.json").read_text())
    assert len(report["pending"]) == 4 and all(p["predicate"] == "PLACE-ON" for p in report["pending"])
    assert not list(tmp_path.glob(".*partial"))


@pytest.mark.long  # a full table solved and settled
def test_over_full_table_reports_the_overlapping_objects() -> None:
    entries = []
    for i in range(10):
        entries += [
            [f"pot_{i}", "a large stainless steel cooking pot"],
            [f"pot_{i}", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
            [f"pot_{i}", "FACING-FRONT", "root", {}],
        ]
    solution = solve({"support": {"kind": "table", "size": [0.5, 0.5]}, "program": entries})
    assert not solution.ok
    failed = [o for o in solution.scene.objects if o.status == "failed"]
    assert failed and all("overlaps pot_" in (o.reason or "") for o in failed)
    assert "overlap by" in solution.feedback()


def test_unsolved_object_stops_in_the_checker() -> None:
    solution = solve([["cup_0", "a mug"], ["cup_0", "PLACE-ON-BASE", "root", {"x": 0.1}]])
    assert not solution.check.ok and solution.spatial is None and solution.scene.objects == []
    assert "not fully solved" in solution.feedback()


def test_catalogue_is_shared() -> None:
    assert default_catalogue() is default_catalogue()
