"""The diversity measures on hand-built scenes (no solving, no simulation), and `eval diversity` on a folder."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from physcensis.cli import app
from physcensis.evaluation.diversity import (
    asset_choice,
    choice_entropy_bits,
    coverage_grid,
    distinct_asset_choices,
    distinct_scenes,
    diversity_by_prompt,
    entropy_bits,
    is_resting,
    layout_distance,
    matched_distance,
    mean_layout_distance,
    prompt_diversity,
)
from physcensis.evaluation.diversity_files import find_scene_folders
from physcensis.scene import PlacedObject, Scene, Support, save_scene

SUPPORT = Support(kind="table", size=(1.2, 0.8))
PROMPT = "a plate and a mug"
Item = tuple[str, str, float, float]  # asset, category, x, y

runner = CliRunner()


def scene_of(items: list[Item], prompt: str = PROMPT, settle_m: float | None = 0.0) -> Scene:
    objects = [
        PlacedObject(
            id=f"{category.replace(' ', '_')}_{k}",
            description=f"a {category}",
            asset=asset,
            category=category,
            position=(x, y, SUPPORT.top_height),
            mass=0.3,
            friction=0.5,
        )
        for k, (asset, category, x, y) in enumerate(items)
    ]
    metrics = {} if settle_m is None else {"settle_distance_m": settle_m}
    return Scene(support=SUPPORT, prompt=prompt, objects=objects, metrics=metrics)


BASE: list[Item] = [("plate_a", "plate", 0.0, 0.0), ("mug_a", "mug", 0.2, 0.1), ("mug_a", "mug", -0.2, -0.1)]


def moved(items: list[Item], dx: float, dy: float = 0.0) -> list[Item]:
    return [(asset, category, x + dx, y + dy) for asset, category, x, y in items]


def test_jitter_of_one_centimetre_is_the_same_scene() -> None:
    scenes = [scene_of(BASE), scene_of(moved(BASE, 0.01))]
    assert matched_distance(*scenes) == pytest.approx(0.01)
    assert distinct_scenes(scenes) == 1


def test_moving_ten_centimetres_makes_another_scene() -> None:
    scenes = [scene_of(BASE), scene_of(moved(BASE, 0.10))]
    assert distinct_scenes(scenes) == 2
    assert layout_distance(*scenes) == pytest.approx(0.10)


def test_objects_are_matched_whatever_their_order() -> None:
    swapped = [BASE[0], BASE[2], BASE[1]]  # the two mugs listed the other way round: the same scene
    assert matched_distance(scene_of(BASE), scene_of(swapped)) == pytest.approx(0.0)


def test_another_asset_makes_another_scene() -> None:
    other = [("plate_b", "plate", 0.0, 0.0), *BASE[1:]]
    scenes = [scene_of(BASE), scene_of(other)]
    assert matched_distance(*scenes) is None
    assert distinct_scenes(scenes) == 2
    assert distinct_asset_choices(scenes) == 2
    assert layout_distance(*scenes) == pytest.approx(0.0)  # the same layout, matched per category


def test_the_same_scene_relation_is_closed_transitively() -> None:
    # 0-1 and 1-2 are 4 cm apart, 0-2 are 8 cm: one chain, one distinct scene
    scenes = [scene_of(BASE), scene_of(moved(BASE, 0.04)), scene_of(moved(BASE, 0.08))]
    assert distinct_scenes(scenes) == 1


def test_entropy_of_a_fifty_fifty_choice_is_one_bit() -> None:
    assert entropy_bits(["a", "b", "a", "b"]) == pytest.approx(1.0)
    assert entropy_bits(["a", "a", "a"]) == 0.0
    assert entropy_bits(["a", "b", "c", "d"]) == pytest.approx(2.0)
    other = [("plate_b", "plate", 0.0, 0.0), *BASE[1:]]
    bits = choice_entropy_bits([scene_of(BASE), scene_of(other)])
    assert bits == {"mug": 0.0, "plate": pytest.approx(1.0)}


def test_counts_are_part_of_a_choice() -> None:
    one_mug = scene_of(BASE[:2])
    assert asset_choice(one_mug) != asset_choice(scene_of(BASE))
    assert choice_entropy_bits([one_mug, scene_of(BASE)])["mug"] == pytest.approx(1.0)


def test_layout_distance_ignores_unmatched_objects_and_averages_pairs() -> None:
    extra = scene_of([*BASE, ("cup_a", "cup", 0.5, 0.3)])
    assert layout_distance(scene_of(BASE), extra) == pytest.approx(0.0)
    assert layout_distance(scene_of(BASE[:1]), scene_of(BASE[1:])) is None  # nothing in common
    mean, pairs = mean_layout_distance([scene_of(BASE), scene_of(moved(BASE, 0.1)), scene_of(moved(BASE, 0.2))])
    assert pairs == 3
    assert mean == pytest.approx((0.1 + 0.1 + 0.2) / 3)


def test_resting_and_expectations() -> None:
    scenes = [scene_of(BASE, settle_m=0.001), scene_of(BASE, settle_m=0.01), scene_of(BASE[:2], settle_m=None)]
    assert [is_resting(s) for s in scenes] == [True, False, False]
    result = prompt_diversity(scenes, check=lambda s: [] if len(s.placed) == 3 else ["too few"])
    assert (result.resting, result.expectations_met, result.expectations_checked) == (1, 2, True)
    assert result.expectations_share == pytest.approx(2 / 3)
    assert prompt_diversity(scenes).expectations_share is None


def test_scenes_are_grouped_by_prompt_and_support() -> None:
    other_prompt = scene_of(BASE, prompt="two  mugs")
    scenes = [scene_of(BASE), other_prompt, scene_of(moved(BASE, 0.2))]
    results = diversity_by_prompt(scenes, {"two mugs": lambda s: []})
    assert [(r.prompt, members) for r, members in results] == [(PROMPT, [0, 2]), ("two mugs", [1])]
    assert [r.distinct_scenes for r, _ in results] == [2, 1]
    assert results[1][0].expectations_met == 1  # the prompt found its check, white space aside


def test_coverage_grid_counts_the_share_of_scenes() -> None:
    import shapely

    left, right = shapely.box(-0.6, -0.4, 0.0, 0.4), shapely.box(-0.6, -0.4, 0.6, 0.4)
    grid = coverage_grid(SUPPORT, [[left], [right]], cells=12)
    assert grid.share.shape == (12, 8)
    assert np.all(grid.share[grid.xs < 0] == 1.0) and np.all(grid.share[grid.xs > 0] == 0.5)


def _write_folder(root: Path, scenes: list[Scene]) -> None:
    for k, scene in enumerate(scenes):
        save_scene(scene, root / "scenes" / f"s_{k:03d}" / "scene.json")


def test_eval_diversity_writes_its_report(tmp_path: Path) -> None:
    _write_folder(tmp_path, [scene_of(BASE), scene_of(moved(BASE, 0.01)), scene_of(moved(BASE, 0.10))])
    result = runner.invoke(app, ["eval", "diversity", str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert "2 of 3" in result.output
    report = json.loads((tmp_path / "diversity.json").read_text())
    (prompt,) = report["prompts"]
    assert (prompt["scenes"], prompt["distinct_scenes"], prompt["distinct_asset_choices"]) == (3, 2, 1)
    assert prompt["scene_dirs"] == ["scenes/s_000", "scenes/s_001", "scenes/s_002"]
    assert math.isclose(prompt["mean_layout_distance_m"], (0.01 + 0.10 + 0.09) / 3)
    assert (tmp_path / prompt["heatmap"]).read_bytes().startswith(b"\x89PNG")
    again = runner.invoke(app, ["eval", "diversity", str(tmp_path), "--no-heatmaps", "--json"])
    assert again.exit_code == 0, again.output  # its own diversity.json is replaced without --overwrite
    assert json.loads(again.output)["prompts"][0]["heatmap"] is None


def test_eval_diversity_checks_expect_blocks(tmp_path: Path) -> None:
    _write_folder(tmp_path / "in", [scene_of(BASE), scene_of(BASE[:1])])
    expect = tmp_path / "expect.jsonl"
    expect.write_text(json.dumps({"prompt": PROMPT, "expect": {"categories": {"plate": 1, "mug": 1}}}) + "\n")
    out = tmp_path / "out"
    result = runner.invoke(
        app, ["eval", "diversity", str(tmp_path / "in"), "--out", str(out), "--expect", str(expect), "--no-heatmaps"]
    )
    assert result.exit_code == 0, result.output
    (prompt,) = json.loads((out / "diversity.json").read_text())["prompts"]
    assert (prompt["expectations_checked"], prompt["expectations_met"]) == (True, 1)
    assert not (tmp_path / "in" / "diversity.json").exists()


def test_eval_diversity_refuses_an_empty_or_missing_folder(tmp_path: Path) -> None:
    result = runner.invoke(app, ["eval", "diversity", str(tmp_path)])
    assert result.exit_code == 2
    assert "no scene folder" in result.output and len(result.output.strip().splitlines()) == 1
    assert runner.invoke(app, ["eval", "diversity", str(tmp_path / "nope")]).exit_code == 2
    assert not (tmp_path / "diversity.json").exists()


def test_eval_diversity_reports_an_unreadable_scene(tmp_path: Path) -> None:
    _write_folder(tmp_path, [scene_of(BASE)])
    (tmp_path / "scenes" / "broken").mkdir()
    (tmp_path / "scenes" / "broken" / "scene.json").write_text("{not json")
    result = runner.invoke(app, ["eval", "diversity", str(tmp_path), "--no-heatmaps"])
    assert result.exit_code == 1
    assert json.loads((tmp_path / "diversity.json").read_text())["unreadable"][0]["scene"] == "scenes/broken"


def test_scene_folders_are_searched_to_a_bounded_depth(tmp_path: Path) -> None:
    save_scene(scene_of(BASE), tmp_path / "a" / "scene.json")
    save_scene(scene_of(BASE), tmp_path / "b" / "c" / "d" / "scene.json")
    save_scene(scene_of(BASE), tmp_path / ".hidden" / "scene.json")
    assert find_scene_folders(tmp_path, max_depth=2) == [tmp_path / "a"]
    assert find_scene_folders(tmp_path) == [tmp_path / "a", tmp_path / "b" / "c" / "d"]
    assert find_scene_folders(tmp_path / "a") == [tmp_path / "a"]
