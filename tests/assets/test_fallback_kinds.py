"""Nouns the catalogue does not know get a plausible stand-in from a prior per kind of thing (shape, size range,
density), the same one every time; it stands after a nudge, and the solution's report and the agent's feedback say
which nouns fell back and to what."""

from __future__ import annotations

import json
from pathlib import Path

import mujoco
import numpy as np
import pytest
from typer.testing import CliRunner

from physcensis.assets.catalogue import Catalogue
from physcensis.assets.fallback import stand_in, stand_in_info, stand_in_note
from physcensis.assets.kinds import GENERIC_KIND, KINDS, head_noun, kind_of
from physcensis.assets.model import Asset
from physcensis.cli import app
from physcensis.feedback.messages import success_feedback
from physcensis.physics.mujoco_assets import add_asset_geoms
from physcensis.scene import Support
from physcensis.solver.pipeline import solve

BY_NAME = {kind.name: kind for kind in KINDS}
# (description, noun, kind, shape) for the priors themselves (the catalogue may learn some of these nouns later)
UNKNOWN = [
    ("a tall brass hookah with a long hose", "hookah", "container", "cylinder"),
    ("an old samovar", "samovar", "container", "cylinder"),
    ("a dehumidifier", "dehumidifier", "appliance", "box"),
    ("a waffle maker", "waffle maker", "appliance", "box"),
    ("a glass cruet of vinegar", "cruet", "bottle-like", "cylinder"),
    ("a rusty crowbar", "crowbar", "tool", "box"),
    ("a walkie talkie", "walkie talkie", "electronics", "box"),
    ("a wooden marionette", "marionette", "toy", "rounded"),
    ("a ripe papaya", "papaya", "food", "rounded"),
    ("a folded poncho", "poncho", "soft item", "slab"),
    ("a footstool", "footstool", "furniture-like", "box"),
    ("a glossy brochure", "brochure", "flat item", "slab"),
    ("a stone obelisk", "obelisk", "ornament", "cylinder"),
    ("a thingamajig", "thingamajig", "object", "box"),
]


@pytest.mark.parametrize(
    ("description", "noun"),
    [
        ("a pair of red clogs", "clog"),
        ("two tall brass hookahs along the wall", "hookah"),
        ("a carving knife", "carving knife"),
        ("a sewing machine under the window", "sewing machine"),
        ("a glowing orb", "orb"),
        ("", "object"),
    ],
)
def test_the_head_noun_is_the_name_a_reader_would_use(description: str, noun: str) -> None:
    assert head_noun(description) == noun


@pytest.mark.parametrize(("description", "noun", "kind", "shape"), UNKNOWN, ids=[u[1] for u in UNKNOWN])
def test_an_unknown_noun_gets_its_kinds_shape_size_and_density(
    description: str, noun: str, kind: str, shape: str
) -> None:
    assert head_noun(description) == noun
    prior = BY_NAME.get(kind, GENERIC_KIND)
    assert kind_of(description) is prior
    asset = stand_in(description)
    lo, hi = np.asarray(prior.smallest), np.asarray(prior.largest)
    assert np.all(np.asarray(asset.size) >= lo - 1e-9) and np.all(np.asarray(asset.size) <= hi + 1e-9), asset.size
    info = stand_in_info(asset)
    assert info is not None and info["noun"] == noun and info["kind"] == kind and info["shape"] == shape
    assert asset.category == noun and asset.generated and asset.visual.is_watertight
    box_volume = float(np.prod(asset.size))
    assert 0.4 * prior.density * box_volume <= asset.mass <= prior.density * box_volume * 1.01  # the kind's density


def test_kinds_differ_in_size_as_real_things_do() -> None:
    """A furniture-like stand-in is larger than an appliance, which is larger than a piece of food or a toy; flat
    items and soft items are thin."""
    size = {kind: max(stand_in(d).size) for d, _, kind, _ in UNKNOWN}
    assert size["furniture-like"] > size["appliance"] > max(size["food"], size["toy"])
    for description, _, kind, _ in UNKNOWN:
        if kind in ("flat item", "soft item"):
            x, y, z = stand_in(description).size
            assert z < 0.35 * min(x, y), description


def test_the_same_noun_always_gets_the_same_stand_in_and_size_words_still_apply() -> None:
    first, again = stand_in("a samovar"), stand_in("a samovar")
    assert first.size == again.size and first.mass == again.mass
    assert stand_in("a huge samovar").size[2] > first.size[2] > stand_in("a tiny samovar").size[2]
    assert stand_in("a 40 cm tall samovar").size[2] == pytest.approx(0.4, rel=0.01)


def test_the_catalogue_falls_back_to_the_stand_in_and_names_it() -> None:
    asset = Catalogue(cache=False).resolve("a tall brass hookah with a long hose")
    note = stand_in_note(asset)
    assert note is not None
    assert note.startswith("'hookah' not in the catalogue: a 0.") and note.endswith(
        "m cylinder stand-in (kind: container)"
    )
    assert stand_in_note(Catalogue(cache=False).resolve("a white ceramic mug")) is None


@pytest.mark.physics
@pytest.mark.parametrize(("description", "noun", "kind", "shape"), UNKNOWN, ids=[u[1] for u in UNKNOWN])
def test_a_stand_in_stands_after_a_nudge(description: str, noun: str, kind: str, shape: str) -> None:
    """Tilted 2 degrees on the floor, it settles back (the catalogue's stand-after-a-nudge test)."""
    shift, turn = _nudged(stand_in(description))
    assert shift <= 0.01 and turn <= 10.0, (shift, turn)


def _nudged(asset: Asset) -> tuple[float, float]:
    spec = mujoco.MjSpec()
    spec.option.timestep = 0.002
    floor = spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[2, 2, 0.1])
    floor.friction = [0.8, 0.005, 0.0001]
    body = spec.worldbody.add_body(name="obj", pos=[0.0, 0.0, 0.003])
    body.add_freejoint()
    add_asset_geoms(spec, body, asset, "obj")
    half = np.radians(1.0)
    body.quat = [float(np.cos(half)), float(np.sin(half) / np.sqrt(2)), float(np.sin(half) / np.sqrt(2)), 0.0]
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_step(model, data, nstep=int(1.5 / 0.002))
    shift = float(np.linalg.norm(data.body("obj").xpos))
    turn = float(np.degrees(2 * np.arccos(min(1.0, abs(data.body("obj").xquat[0])))))
    return shift, turn


@pytest.mark.physics
def test_the_report_and_the_feedback_list_the_nouns_that_fell_back() -> None:
    program = [
        ["mug_0", "a white ceramic mug"],
        ["mug_0", "PLACE-ON-BASE", "root", {"x": -0.25, "y": 0.0}],
        ["mug_0", "RANDOM-ROT", "root", {}],
        ["hookah_0", "a tall brass hookah"],
        ["hookah_0", "PLACE-ON-BASE", "root", {"x": 0.15, "y": 0.15}],
        ["hookah_0", "RANDOM-ROT", "root", {}],
        ["hookah_1", "a tall brass hookah"],
        ["hookah_1", "PLACE-ON-BASE", "root", {"x": 0.15, "y": -0.15}],
        ["hookah_1", "RANDOM-ROT", "root", {}],
        ["serape_0", "a striped serape"],
        ["serape_0", "PLACE-ON-BASE", "root", {"x": -0.2, "y": 0.25}],
        ["serape_0", "RANDOM-ROT", "root", {}],
    ]
    catalogue = Catalogue(cache=False)
    solution = solve(program, support=Support(kind="table", size=(1.0, 0.8)), catalogue=catalogue, seed=0)
    assert solution.ok
    rows = {row["noun"]: row for row in solution.report()["fallbacks"]}
    assert set(rows) == {"hookah", "serape"}
    assert rows["hookah"]["objects"] == ["hookah_0", "hookah_1"] and rows["hookah"]["kind"] == "container"
    assert rows["serape"]["shape"] == "slab" and rows["serape"]["kind"] == "soft item"
    feedback = success_feedback(solution, catalogue)
    assert "'hookah' not in the catalogue: a 0." in feedback.text and "hookah_0, hookah_1" in feedback.text
    assert "'serape' not in the catalogue" in feedback.text and "mug" not in feedback.text.split("stand-in shapes")[1]
    assert [row["noun"] for row in feedback.data["fallbacks"]] == ["hookah", "serape"]


def test_solve_prints_the_stand_ins_and_writes_them_to_report_json(tmp_path: Path) -> None:
    program = {
        "support": {"kind": "table", "size": [0.8, 0.6]},
        "program": [
            ["samovar_0", "an old samovar"],
            ["samovar_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
            ["samovar_0", "RANDOM-ROT", "root", {}],
        ],
    }
    source = tmp_path / "program.json"
    source.write_text(json.dumps(program))
    out = tmp_path / "scene"
    result = CliRunner().invoke(app, ["solve", str(source), "--out", str(out), "--no-physics", "--export", "none"])
    assert result.exit_code == 0, result.output
    assert "'samovar' not in the catalogue: a 0." in " ".join(result.output.split())
    report = json.loads((out / "report.json").read_text())
    assert [(row["noun"], row["kind"], row["objects"]) for row in report["fallbacks"]] == [
        ("samovar", "container", ["samovar_0"])
    ]


@pytest.mark.parametrize(
    ("noun", "not_this"),
    [("a label maker", "waffle maker"), ("a coffee grinder", "pepper grinder"), ("a shoe horn", "shoes")],
)
def test_a_noun_that_only_shares_a_word_with_a_category_falls_back(noun: str, not_this: str) -> None:
    catalogue = Catalogue(cache=False)
    asset = catalogue.resolve(noun)
    assert asset.category != not_this
    if asset.generated:  # a stand-in carries (the head of) the noun it stands in for, so the report names it
        assert asset.category in noun


def test_a_confident_match_with_dimensions_is_the_match_resized() -> None:
    asset = Catalogue(cache=False).resolve("a white ceramic mug 12 cm tall")
    assert asset.category == "mug" and abs(asset.size[2] - 0.12) < 0.005
