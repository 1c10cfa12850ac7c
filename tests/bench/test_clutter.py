"""The clutter protocol's stopping rules: the paper's (stop at the first failure), `--patience N` (stop after N
failures in a row, each failed object skipped) and with-skip (skip each asset that failed until none is left)."""

from __future__ import annotations

import json
from typing import Any

import pytest
from typer.testing import CliRunner

from physcensis.assets.catalogue import default_catalogue
from physcensis.bench import clutter
from physcensis.bench.clutter import MAX_OBJECTS, AttemptLoop
from physcensis.cli import app
from physcensis.solver.objects import physical_properties


def _run(loop: AttemptLoop, fits: dict[int, list[bool]]) -> list[int]:
    """Drive the loop: each asset's attempts succeed or fail in the order given (then fail); the assets tried."""
    tried: list[int] = []
    while (k := loop.next_asset()) is not None:
        tried.append(k)
        outcomes = fits.get(k, [])
        loop.record(k, outcomes.pop(0) if outcomes else False)
    return tried


def test_patience_one_stops_at_the_first_failure() -> None:
    loop = AttemptLoop([2, 0, 1], patience=1)
    tried = _run(loop, {2: [True], 0: [False], 1: [True]})
    assert tried == [2, 0]
    assert loop.stop == "the first object that could not be placed"


def test_patience_skips_failed_objects_and_stops_after_that_many_failures_in_a_row() -> None:
    loop = AttemptLoop([0, 1, 2], patience=3)
    # 0 fits twice, 1 never, 2 once: 0 1 2 | 0 1 2 | 0 ... the first three failures in a row end it
    tried = _run(loop, {0: [True, True], 2: [True]})
    assert tried == [0, 1, 2, 0, 1, 2, 0]
    assert loop.failures == 3 and loop.stop == "3 failures in a row"


def test_a_success_resets_the_count_of_failures_in_a_row() -> None:
    loop = AttemptLoop([0, 1, 2, 3], patience=2)
    tried = _run(loop, {1: [True], 3: [True]})  # fail, fit, fail, fit, fail, fail
    assert tried == [0, 1, 2, 3, 0, 1]


def test_with_skip_never_tries_a_failed_asset_again() -> None:
    loop = AttemptLoop([0, 1, 2], patience=None)
    tried = _run(loop, {0: [True] * 3, 1: [False], 2: [True] * 2})
    assert tried == [0, 1, 2, 0, 2, 0, 2, 0]
    assert loop.stop == "no remaining asset fits"


def test_attempts_are_bounded() -> None:
    loop = AttemptLoop([0], patience=1)
    tried = _run(loop, {0: [True] * (2 * MAX_OBJECTS)})
    assert len(tried) == MAX_OBJECTS and loop.stop == f"{MAX_OBJECTS} attempts"


def test_cli_passes_patience_and_the_summary_records_it(monkeypatch: pytest.MonkeyPatch) -> None:
    seen: dict[str, Any] = {}

    def fake_run(mode: str, scenes: int, seed: int, **options: Any) -> dict[str, Any]:
        seen.update(options, mode=mode)
        return {"mode": mode, "patience": options["patience"], "mean_objects": 1.0}

    monkeypatch.setattr(clutter, "run", fake_run)
    result = CliRunner().invoke(app, ["bench", "clutter", "--mode", "no-stack", "--patience", "10", "--json"])
    assert result.exit_code == 0, result.output
    assert seen["patience"] == 10 and json.loads(result.stdout)["patience"] == 10
    refused = CliRunner().invoke(app, ["bench", "clutter", "--patience", "0"])
    assert refused.exit_code != 0
    spots = CliRunner().invoke(app, ["bench", "clutter", "--mode", "no-stack", "--spot", "random", "--json"])
    assert spots.exit_code == 0 and seen["placement"] == "random"
    unknown = CliRunner().invoke(app, ["bench", "clutter", "--spot", "tight"])
    assert unknown.exit_code != 0 and "unknown --spot 'tight'" in unknown.output


def test_every_clutter_row_states_its_placement() -> None:
    from physcensis.bench.report import clutter_row

    base = {"mode": "no-stack", "scenes": 3, "mean_objects": 8.0, "std_objects": 1.0, "min_objects": 7}
    base |= {"max_objects": 9, "median_seconds_per_scene": 1.0, "mean_settle_distance_m": 0.0}
    rows = {
        name: clutter_row(summary, None)
        for name, summary in {
            "before the key": base,
            "random": {**base, "placement": "random"},
            "peer": {**base, "peer": "scene-synthesizer 1.15.0"},
        }.items()
    }
    assert "packed" in rows["before the key"][1] and "random spot that fits" in rows["random"][1]
    assert "the peer's own" in rows["peer"][1]


@pytest.mark.long
def test_a_random_spot_scene_places_objects_that_rest() -> None:
    scene = clutter.run_scene("no-stack", 0, placement="random")
    assert scene.placed >= 3 and all(o.status == "placed" for o in scene.scene.placed)
    assert scene.settle_distance_m < 0.003


# The protocol's published masses (g), ../shared/bench/clutter_protocol.md
PROTOCOL_MASSES_G = {
    "ycb_005_tomato_soup_can": 349,
    "ycb_006_mustard_bottle": 603,
    "ycb_007_tuna_fish_can": 171,
    "ycb_009_gelatin_box": 97,
    "ycb_010_potted_meat_can": 370,
    "ycb_019_pitcher_base": 178,
    "ycb_024_bowl": 147,
    "ycb_025_mug": 118,
    "ycb_029_plate": 279,
    "ycb_030_fork": 34,
}


def test_placed_ycb_objects_weigh_the_protocols_published_masses() -> None:
    catalogue = default_catalogue()
    assert set(PROTOCOL_MASSES_G) == set(clutter.YCB_DINING)
    for asset_id, grams in PROTOCOL_MASSES_G.items():
        asset = catalogue.get(asset_id)
        for seed in range(3):
            mass, _, _ = physical_properties(asset, f"{asset.kind}_{seed}", seed)
            assert mass == pytest.approx(grams / 1000, abs=1e-9), asset_id
    spread = catalogue.get("ball_tennis").mass_range  # an object not from a weighed set still varies
    assert spread[1] > spread[0]
