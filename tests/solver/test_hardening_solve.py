"""Everything `check` accepts, `solve` handles: in bounded time and memory, with valid ids, never a traceback."""

from __future__ import annotations

import json
import math
import time
import tracemalloc
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from physcensis.api import generate
from physcensis.assets import default_catalogue
from physcensis.cli import app
from physcensis.errors import PhyscensisError
from physcensis.ids import is_reserved_id, is_valid_id
from physcensis.program import PREDICATES, ItemCount, Relation, check_program, lookup, parse_program
from physcensis.program.registry import ParamType
from physcensis.scene import MAX_COORDINATE_M, Scene, Support
from physcensis.solver.layout import CompiledLayout, PhysicalRequest, Pose2D
from physcensis.solver.pipeline import Solution, _place_in_items, _spatial_failures, _within_scene, solve
from physcensis.solver.spatial import Overlap, SpatialResult, _Penalty, envelopes, near_pairs, optimise_layout

runner = CliRunner()
FLOOR = Support(kind="floor", size=(10.0, 10.0))
_QUIET = [HealthCheck.too_slow, HealthCheck.data_too_large]
_settings = settings(deadline=None, suppress_health_check=_QUIET)


def disc(r: float = 0.1, k: int = 24) -> np.ndarray:
    a = np.linspace(0, 2 * np.pi, k, endpoint=False)
    return np.c_[r * np.cos(a), r * np.sin(a)]


def grid_with_a_group(n: int, shift: float) -> list[list[Any]]:
    """n discs on a grid, grouped; the group's PLACE-ON-BASE x moves all n at once (off the floor if `shift`)."""
    side = math.ceil(n**0.5)
    entries: list[list[Any]] = []
    for i in range(n):
        oid = f"o_{i}"
        x, y = round(-4 + 8 * (i // side) / side, 3), round(-4 + 8 * (i % side) / side, 3)
        entries += [[oid, "a mug"], [oid, "PLACE-ON-BASE", "root", {"x": x, "y": y}], [oid, "FACING-FRONT", "root", {}]]
    return entries + [
        ["group_all", "GROUP", [f"o_{i}" for i in range(n)], {}],
        ["group_all", "PLACE-ON-BASE", "root", {"x": shift}],
    ]


# -- no quadratic memory, bounded work -------------------------------------------------------------------------------


def test_moving_hundreds_of_objects_at_once_needs_megabytes_not_hundreds() -> None:
    """One parameter moves 400 objects: the pairs it touches were (pairs, samples, 4) arrays over all n(n-1)/2
    pairs (about 300 MB here); only pairs whose boxes can meet are compared now."""
    n = 400
    program = parse_program(grid_with_a_group(n, 1.5))
    prints = {f"o_{i}": disc() for i in range(n)}
    tracemalloc.start()
    try:
        result = optimise_layout(program, FLOOR, prints, seed=0, rounds=1)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert result.ok and result.evaluations > 1
    assert peak < 60e6, peak / 1e6


def test_the_search_stops_at_the_work_limit_deterministically() -> None:
    entries: list[list[Any]] = [
        ["o_0", "a mug"],
        ["o_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
        ["o_0", "FACING-FRONT", "root", {}],
    ]
    for i in range(1, 60):  # a row far longer than the table: the search can never succeed
        entries += [
            [f"o_{i}", "a mug"],
            [f"o_{i}", "PLACE-ON-BASE", "root", {}],
            [f"o_{i}", "LEFT-OF", f"o_{i - 1}", {"distance": 0.05}],
            [f"o_{i}", "ALIGN-CENTER-FB", f"o_{i - 1}", {}],
            [f"o_{i}", "FACING-FRONT", "root", {}],
        ]
    program = parse_program(entries)
    prints = {f"o_{i}": disc() for i in range(60)}
    layout_ops = len(CompiledLayout(program, FLOOR, prints, 0).ops)
    table = Support(kind="table", size=(1.0, 1.0))
    first = optimise_layout(program, table, prints, seed=0, work_limit=30 * layout_ops)
    second = optimise_layout(program, table, prints, seed=0, work_limit=30 * layout_ops)
    assert not first.ok and "work limit" in first.stop_reason
    assert first.evaluations <= 30 * 41 and first.poses == second.poses


def test_exact_intersections_count_as_work() -> None:
    """A pile where every sample of every move intersects dozens of footprints: the polygons are paid for too."""
    entries: list[list[Any]] = []
    for i in range(60):
        entries += [
            [f"o_{i}", "a mug"],
            [f"o_{i}", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
            [f"o_{i}", "FACING-FRONT", "root", {}],
        ]
    program = parse_program(entries)
    prints = {f"o_{i}": disc() for i in range(60)}
    cost = len(CompiledLayout(program, FLOOR, prints, 0).ops)
    result = optimise_layout(program, Support(kind="table", size=(0.5, 0.5)), prints, seed=0, work_limit=30 * cost)
    assert "work limit" in result.stop_reason
    assert result.evaluations < 15 * 41  # predicate applications alone would have allowed 29 evaluations


@_settings
@given(
    st.lists(
        st.tuples(st.floats(-5, 5), st.floats(-5, 5), st.floats(0.01, 2), st.floats(0.01, 2)), min_size=1, max_size=40
    ),
    st.data(),
)
def test_near_pairs_are_exactly_the_pairs_whose_envelopes_meet(boxes: list[tuple[float, ...]], data: Any) -> None:
    n = len(boxes)
    env = np.array([[x, x + w, y, y + h] for x, y, w, h in boxes])
    movers = np.array(sorted(data.draw(st.sets(st.integers(0, n - 1), min_size=1))), dtype=np.intp)
    moved = np.zeros(n, dtype=bool)
    moved[movers] = True
    found = {tuple(p) for p in near_pairs(movers, env, moved).tolist()}
    expected = {
        (i, j)
        for i in range(n)
        for j in range(i + 1, n)
        if (moved[i] or moved[j])
        and min(env[i, 1], env[j, 1]) - max(env[i, 0], env[j, 0]) > 1e-9
        and min(env[i, 3], env[j, 3]) - max(env[i, 2], env[j, 2]) > 1e-9
    }
    assert found == expected and len(near_pairs(movers, env, moved)) == len(found)


@pytest.mark.long  # 25 solves of up to ten objects
@settings(max_examples=25, deadline=None)
@given(
    st.lists(
        st.tuples(st.floats(-0.4, 0.4), st.floats(-0.4, 0.4), st.sampled_from(["FACING-FRONT", "RANDOM-ROT"])),
        min_size=2,
        max_size=10,
    ),
    st.integers(0, 3),
)
def test_the_reported_overlap_is_the_overlap_of_the_final_poses(
    spots: list[tuple[float, float, str]], seed: int
) -> None:
    """The sparse contact list stays equal to intersecting every pair of the final footprints."""
    import shapely

    entries: list[list[Any]] = []
    for i, (x, y, yaw) in enumerate(spots):
        entries += [
            [f"o_{i}", "a box"],
            [f"o_{i}", "PLACE-ON-BASE", "root", {"x": x, "y": y}],
            [f"o_{i}", yaw, "root", {}],
        ]
    hull = np.array([[-0.1, -0.06], [0.1, -0.06], [0.1, 0.06], [-0.1, 0.06]])
    result = optimise_layout(
        parse_program(entries),
        Support(kind="table", size=(1.0, 1.0)),
        {f"o_{i}": hull for i in range(len(spots))},
        seed=seed,
        rounds=2,
    )
    polys = []
    for pose in result.poses.values():
        c, s = math.cos(pose.yaw), math.sin(pose.yaw)
        polys.append(shapely.Polygon([(pose.x + c * a - s * b, pose.y + s * a + c * b) for a, b in hull]))
    total = sum(polys[i].intersection(polys[j]).area for i in range(len(polys)) for j in range(i + 1, len(polys)))
    assert result.overlap_m2 == pytest.approx(total, abs=1e-9)


def test_penalty_envelopes_bound_every_sample() -> None:
    boxes = np.random.default_rng(0).uniform(-1, 1, (5, 7, 4))
    env = envelopes(boxes)
    assert (env[:, 0] <= boxes[..., 0].min(1)).all() and (env[:, 1] >= boxes[..., 1].max(1)).all()
    assert _Penalty is not None  # the penalty class stays importable for the benches


# -- objects far outside any scene -----------------------------------------------------------------------------------


@pytest.mark.parametrize("mirrors", [30, 1100])
def test_chains_of_mirrors_end_as_failed_objects_not_a_traceback(mirrors: int) -> None:
    """Each SYMMETRY-ALONG through the other object doubles the distance: 2^1100 m overflowed to NaN."""
    entries: list[list[Any]] = [
        ["b", "a mug"],
        ["b", "PLACE-ON-BASE", "root", {}],
        ["b", "RANDOM-ROT", "root", {}],
        ["b", "LEFT-OF", "root", {"distance": 0.1}],
        ["b", "ALIGN-CENTER-FB", "root", {}],
        ["a", "a mug"],
        ["a", "PLACE-ON-BASE", "root", {}],
        ["a", "RANDOM-ROT", "root", {}],
    ]
    for i in range(mirrors):
        entries.append(
            ["a", "SYMMETRY-ALONG", "root", {"C": "b"}] if i % 2 == 0 else ["b", "SYMMETRY-ALONG", "root", {"C": "a"}]
        )
    solution = solve(entries, physics=False)
    assert solution.check.ok
    for o in solution.scene.objects:
        assert o.status == "failed" and all(abs(c) <= MAX_COORDINATE_M for c in o.position)
        assert "sticks out" in (o.reason or "")
    json.loads(solution.scene.to_json())


@pytest.mark.parametrize(("x", "y"), [(1e5, 0.0), (0.0, -2e3), (float("nan"), 0.0), (float("inf"), float("-inf"))])
def test_poses_beyond_any_scene_fail_their_object_and_are_clipped(x: float, y: float) -> None:
    failed = {"a": "sticks out 1 m past the front edge"}
    cx, cy = _within_scene(Pose2D(x, y, 0.0), "a", failed)
    assert abs(cx) <= MAX_COORDINATE_M and abs(cy) <= MAX_COORDINATE_M
    assert failed["a"].startswith("sticks out") and "far outside any scene" in failed["a"]
    assert _within_scene(Pose2D(3.0, -4.0, 0.0), "b", failed) == (3.0, -4.0) and "b" not in failed


def test_reasons_of_an_object_in_a_pile_stay_one_short_line() -> None:
    overlaps = [Overlap("o_0", f"o_{i}", 0.01, (1,), (i,)) for i in range(1, 200)]
    result = SpatialResult(
        ok=False,
        poses={},
        params={},
        overlaps=overlaps,
        outside=[],
        overlap_m2=2.0,
        outside_m=0.0,
        rounds=1,
        evaluations=1,
        stop_reason="",
        seconds=0.0,
    )
    reasons = _spatial_failures(result)
    assert reasons["o_0"].endswith("and 193 more") and len(reasons["o_0"]) < 400
    assert reasons["o_7"] == "overlaps o_0 by 100.0 cm^2"


# -- 10,000 objects and other limits ---------------------------------------------------------------------------------


def test_ten_thousand_objects_are_refused_quickly_without_building_anything() -> None:
    entries: list[list[Any]] = []
    for i in range(10_000):
        entries += [
            [f"o_{i}", "a mug"],
            [f"o_{i}", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
            [f"o_{i}", "FACING-FRONT", "root", {}],
        ]
    start = time.process_time()  # CPU time: other processes on a busy machine do not count
    solution = solve(json.dumps(entries))
    assert time.process_time() - start < 3
    assert [p.rule for p in solution.check.errors] == ["too-many-objects"]
    assert "assets" not in solution.timings and not solution.scene.objects


@pytest.mark.parametrize("seed", [-1, 2**64, 10**5000], ids=["negative", "2^64", "huge"])
def test_seeds_no_scene_can_hold_are_our_error(seed: int) -> None:
    with pytest.raises(PhyscensisError, match="seed"):
        solve([["a", "a mug"]], seed=seed, physics=False)


def test_a_program_with_errors_keeps_only_what_a_scene_can_hold() -> None:
    solution = solve([["a", "a mug"], ["a", "LEFT-OF", "root", {"distance": float("nan")}]], physics=False)
    assert not solution.check.ok and solution.scene.program == []
    json.loads(solution.scene.to_json())


# -- safe ids for PLACE-IN items -------------------------------------------------------------------------------------

_category_text = st.one_of(
    st.text(max_size=250),
    st.sampled_from(
        [
            "children's toy",
            "crème brûlée",
            "🍎🍐",
            "x" * 200,
            "a b c d e f g h i j k",
            "Äpfel",
            "___",
            "日本語のテキスト",
            "root",
            "support",
        ]
    ),
)


@settings(max_examples=80, deadline=None)
@given(
    st.lists(st.tuples(_category_text, st.integers(1, 5)), min_size=1, max_size=4),
    st.sampled_from(["bowl_0", "b" * 64, "box-1"]),
)
def test_place_in_items_get_valid_unique_ids_from_any_category_text(
    items: list[tuple[str, int]], container: str
) -> None:
    catalogue = default_catalogue()
    counts = tuple(ItemCount(category, count) for category, count in items)
    relation = Relation(9, counts, "PLACE-IN", container, {}, lookup("PLACE-IN"))
    scene = Scene(support=Support(kind="table", size=(1.2, 0.8)))
    made = _place_in_items(PhysicalRequest(relation, (), container), relation, {}, {}, catalogue, 0, scene)
    ids = [oid for oid, _, _ in made]
    assert len(ids) == sum(n for _, n in items) == len(set(ids))
    assert all(is_valid_id(oid) and not is_reserved_id(oid) for oid in ids), ids
    again = [
        oid
        for oid, _, _ in _place_in_items(
            PhysicalRequest(relation, (), container), relation, {}, {}, catalogue, 0, scene
        )
    ]
    assert again == ids  # deterministic


@pytest.mark.physics
@settings(max_examples=6, deadline=None)
@given(_category_text.filter(lambda t: t.strip() != ""))
def test_solve_places_items_of_any_category_text(category: str) -> None:
    program = [
        ["bowl_0", "a wide ceramic bowl"],
        ["bowl_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
        ["bowl_0", "FACING-FRONT", "root", {}],
        [[[category, 2]], "PLACE-IN", "bowl_0", {}],
    ]
    report = check_program(parse_program(program))
    solution = solve(program, seed=0)
    assert isinstance(solution, Solution) and solution.check.ok == report.ok
    if report.ok:
        ids = [o.id for o in solution.scene.objects]
        assert len(ids) == 3 == len(set(ids)) and all(is_valid_id(i) for i in ids)


# -- property: check then solve never raises anything but our error --------------------------------------------------

DESCRIPTIONS = [
    "a white ceramic mug",
    "a hardcover book lying flat",
    "a wide ceramic bowl",
    "a red apple",
    "a dinner plate",
    "a stainless steel fork",
    "a laptop",
    "a glass jar of honey",
]
_weird_numbers = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(-(10**6), 10**6),
    st.just(10**400),
    st.just(float("nan")),
)


def _param_value(param: Any) -> st.SearchStrategy[Any]:
    if param.type is ParamType.NUMBER:
        low, high = param.low if param.low is not None else -10, param.high if param.high is not None else 10
        return st.one_of(st.floats(low, high), st.floats(low, high).map(lambda v: v * 3 + 1), _weird_numbers)
    if param.type is ParamType.STABILITY:
        return st.one_of(st.sampled_from(["stable", "unstable", "wobbly"]), st.floats(-1, 2), _weird_numbers)
    if param.type is ParamType.BOOL:
        return st.one_of(st.booleans(), st.just("yes"))
    return st.one_of(st.sampled_from(["o_0", "o_1", "o_2", "root", "group_g"]), st.integers())


@st.composite
def programs(draw: Any) -> list[list[Any]]:
    n = draw(st.integers(1, 4))
    entries: list[list[Any]] = []
    for i in range(n):
        oid = f"o_{i}"
        entries.append([oid, draw(st.sampled_from(DESCRIPTIONS))])
        placement = draw(st.sampled_from(["base", "base", "on", "anywhere", "in"] if i else ["base"]))
        if placement == "base":
            entries.append(
                [oid, "PLACE-ON-BASE", "root", {"x": draw(st.floats(-0.5, 0.5)), "y": draw(st.floats(-0.35, 0.35))}]
            )
            entries.append([oid, draw(st.sampled_from(["FACING-FRONT", "RANDOM-ROT", "FACING-LEFT"])), "root", {}])
        elif placement == "on":
            entries.append([oid, "PLACE-ON", f"o_{draw(st.integers(0, i - 1))}", {}])
        elif placement == "anywhere":
            entries.append([oid, "PLACE-ANYWHERE", "root", {}])
        else:
            entries.append(
                [
                    [draw(st.sampled_from(["apple", "pen", "crème brûlée", "🍎"])), draw(st.integers(1, 3))],
                    "PLACE-IN",
                    f"o_{draw(st.integers(0, i - 1))}",
                    {},
                ]
            )
            entries[-1][0] = [entries[-1][0]]
        for _ in range(draw(st.integers(0, 2))):  # random predicates from the registry, params in and out of range
            spec = PREDICATES[draw(st.sampled_from(sorted(PREDICATES)))]
            params = {p.name: draw(_param_value(p)) for p in spec.params if draw(st.booleans())}
            target = draw(st.sampled_from(["root", *[f"o_{k}" for k in range(i)]]))
            if spec.name == "GROUP":
                entries.append(["group_g", "GROUP", [f"o_{k}" for k in range(i + 1)], {}])
            elif spec.name == "COPY-GROUP":
                entries.append([f"group_c{i}", "COPY-GROUP", "group_g", {}])
            elif spec.name == "PLACE-IN":
                entries.append([[["apple", draw(st.integers(0, 3))]], "PLACE-IN", target, params])
            else:
                entries.append([oid, spec.name, target, params])
    return entries


def _check_then_solve(entries: list[list[Any]], physics: bool) -> None:
    try:
        program = parse_program(json.loads(json.dumps(entries, allow_nan=True)))
        report = check_program(program, Support(kind="table", size=(1.2, 0.8)))
        solution = solve(program, physics=physics, seed=0)
    except PhyscensisError:
        return
    assert isinstance(solution, Solution)
    assert solution.check.ok == report.ok
    if report.ok:
        json.loads(solution.scene.to_json())  # the scene can be written


@settings(max_examples=100, deadline=None, suppress_health_check=_QUIET)
@given(programs())
def test_check_then_solve_never_raises_anything_but_our_error(entries: list[list[Any]]) -> None:
    _check_then_solve(entries, physics=False)


@pytest.mark.physics
@settings(max_examples=10, deadline=None, suppress_health_check=_QUIET)
@given(programs())
def test_check_then_solve_with_physics_never_raises_anything_but_our_error(entries: list[list[Any]]) -> None:
    _check_then_solve(entries, physics=True)


# -- the limit on the command line and in generate -------------------------------------------------------------------


def test_max_objects_on_the_command_line(tmp_path: Path) -> None:
    path = tmp_path / "four.json"
    entries: list[list[Any]] = []
    for i in range(4):
        entries += [
            [f"o_{i}", "a mug"],
            [f"o_{i}", "PLACE-ON-BASE", "root", {"x": 0.3 * i - 0.45, "y": 0.0}],
            [f"o_{i}", "FACING-FRONT", "root", {}],
        ]
    path.write_text(json.dumps(entries))
    assert runner.invoke(app, ["check", str(path)]).exit_code == 0
    refused = runner.invoke(app, ["check", str(path), "--max-objects", "3", "--json"])
    rows = json.loads(refused.stdout)
    assert refused.exit_code == 1 and [(r["index"], r["rule"]) for r in rows] == [(10, "too-many-objects")]
    assert "more than 3 objects" in rows[0]["message"]
    solved = runner.invoke(
        app, ["solve", str(path), "--out", str(tmp_path / "out"), "--no-physics", "--max-objects", "3"]
    )
    assert solved.exit_code == 1 and "nothing was solved" in solved.output and "Traceback" not in solved.output
    assert not (tmp_path / "out").exists()
    for bad in ("0", "20000", "many"):
        assert runner.invoke(app, ["check", str(path), "--max-objects", bad]).exit_code == 2
    assert runner.invoke(app, ["solve", str(path), "--out", str(tmp_path / "o2"), "--seed", "-1"]).exit_code == 2
    assert "--max-objects" in runner.invoke(app, ["generate", "--help"]).output


def test_generate_passes_the_limit_to_every_round() -> None:
    """The offline planner keeps the limit itself (its plan cut, said in a note); a program over it is refused."""
    generated = generate("a dining table set up for four people", max_objects=2)
    assert generated.solution is not None and len(generated.solution.scene.objects) <= 2
    assert any("max-objects" in row.get("note", "") for row in generated.transcript)
    over = generate("a dining table", agent=_Fixed(json.dumps(_objects(3))), max_objects=2)
    assert "more than 2 objects" in over.transcript[0]["feedback"]  # refused, and the agent told why
    assert over.solution is None or len(over.solution.scene.objects) <= 2


class _Fixed:
    """An agent that always writes the same program."""

    name = "fixed"

    def __init__(self, text: str) -> None:
        self.text = text

    def propose(self, context: object) -> str:
        return self.text


def _objects(n: int) -> list[list[object]]:
    return [e for i in range(n) for e in ([f"mug_{i}", "a white mug"], [f"mug_{i}", "PLACE-ANYWHERE", "root", {}])]
