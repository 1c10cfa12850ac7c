"""The built-in catalogue: coverage, sizes, masses, conventions, collision construction."""

from __future__ import annotations

from collections import Counter

import numpy as np
import pytest

from physcensis.assets.build import build_asset
from physcensis.assets.builtin import CATEGORY_DEFS
from physcensis.assets.catalogue import Catalogue
from physcensis.assets.model import Asset

# Objects the benchmark prompts name, with the category a correct scene must show.
PROMPT_OBJECTS = [
    ("a plate", "plate"),
    ("a fork", "fork"),
    ("a knife", "knife"),
    ("a cup", "cup"),
    ("a wine glass", "wine glass"),
    ("a candle", "candle"),
    ("a book", "book"),
    ("a textbook", "book"),
    ("a notebook", "notebook"),
    ("a pencil", "pencil"),
    ("a pencil case", "pencil case"),
    ("a water bottle", "bottle"),
    ("a laptop", "laptop"),
    ("a monitor", "monitor"),
    ("a keyboard", "keyboard"),
    ("a mouse", "mouse"),
    ("a mug of coffee", "mug"),
    ("a pen", "pen"),
    ("a bowl", "bowl"),
    ("an apple", "apple"),
    ("an orange", "orange"),
    ("a cutting board", "cutting board"),
    ("a pot", "pot"),
    ("a jar of spices", "jar"),
    ("a bottle of oil", "bottle"),
    ("a cardboard box", "box"),
    ("a can", "can"),
    ("a small box", "box"),
    ("a pen holder", "pen holder"),
    ("paper cups", "cup"),
    ("a stack of plates", "plate"),
    ("a rice bowl", "bowl"),
    ("a pair of chopsticks", "chopsticks"),
    ("a soup spoon", "spoon"),
    ("a small dish", "plate"),
    ("a plate of toast", "plate"),
    ("a bowl of cereal", "bowl"),
    ("a glass of orange juice", "glass"),
    ("a coffee mug", "mug"),
    ("a jar of jam", "jar"),
    ("a small plant", "potted plant"),
    ("cereal boxes", "box"),
    ("an open toolbox", "box"),
    ("a hammer", "hammer"),
    ("screwdrivers", "screwdriver"),
    ("a tape measure", "tape measure"),
    ("a soap dispenser", "soap dispenser"),
    ("a toothbrush", "toothbrush"),
    ("a folded towel", "towel"),
    ("a teapot", "teapot"),
    ("a tray", "tray"),
    ("saucers", "saucer"),
    ("dishes", "plate"),
    ("blocks", "toy block"),
    ("balls", "ball"),
    ("a toy truck", "toy truck"),
    ("a basket", "basket"),
    ("stuffed animals", "stuffed animal"),
    ("sandwiches", "sandwich"),
    ("cans of soda", "can"),
    ("a bowl of grapes", "bowl"),
    ("napkins", "napkin"),
    ("gift boxes", "box"),
    ("a book lying flat", "book"),
    ("a book standing upright", "book"),
    ("a phone", "phone"),
    ("a vase", "vase"),
    ("a potted plant", "potted plant"),
    ("bananas", "banana"),
    ("grapes", "grapes"),
    ("bread", "bread"),
    ("a pan", "pan"),
    ("a glass", "glass"),
    ("a spoon", "spoon"),
]

YCB = {  # id: (sorted size in metres, mass in kg, category)
    "ycb_005_tomato_soup_can": ((0.066, 0.066, 0.101), 0.349, "can"),
    "ycb_006_mustard_bottle": ((0.05, 0.085, 0.175), 0.603, "bottle"),
    "ycb_007_tuna_fish_can": ((0.033, 0.085, 0.085), 0.171, "can"),
    "ycb_009_gelatin_box": ((0.028, 0.073, 0.085), 0.097, "box"),
    "ycb_010_potted_meat_can": ((0.05, 0.082, 0.097), 0.370, "can"),
    "ycb_019_pitcher_base": ((0.108, 0.155, 0.235), 0.178, "pitcher"),
    "ycb_024_bowl": ((0.053, 0.159, 0.159), 0.147, "bowl"),
    "ycb_025_mug": ((0.08, 0.082, 0.116), 0.118, "mug"),
    "ycb_029_plate": ((0.024, 0.258, 0.258), 0.279, "plate"),
    "ycb_030_fork": ((0.014, 0.02, 0.198), 0.034, "fork"),
}
FLAT_KINDS = {
    "plate",
    "saucer",
    "tray",
    "cutting board",
    "book lying flat",
    "notebook",
    "napkin",
    "phone",
    "knife",
    "spoon",
}


def test_catalogue_size_and_variety(catalogue: Catalogue) -> None:
    per_category = Counter(e.category for e in catalogue.entries())
    assert len(catalogue) >= 250
    assert len(per_category) >= 45
    assert min(per_category.values()) >= 5, {c: n for c, n in per_category.items() if n < 5}


def test_every_asset_generates(all_assets: list[Asset], catalogue: Catalogue) -> None:
    assert len(all_assets) == len(catalogue)
    assert len({a.id for a in all_assets}) == len(all_assets)


def test_visual_meshes_are_watertight(all_assets: list[Asset]) -> None:
    leaky = [a.id for a in all_assets if not a.visual.is_watertight]
    assert leaky == []


def test_sizes_match_annotations(all_assets: list[Asset]) -> None:
    for a in all_assets:
        ext = np.asarray(a.visual.extents)
        assert np.all(np.abs(ext / np.asarray(a.size) - 1.0) <= 0.05), (a.id, ext, a.size)


def test_base_at_zero_and_footprint_centred(all_assets: list[Asset]) -> None:
    for a in all_assets:
        lo, hi = a.visual.bounds
        assert abs(lo[2]) < 1e-7, a.id
        assert np.allclose((lo[:2] + hi[:2]) / 2, 0.0, atol=1e-7), a.id
        for part in a.collision:
            if part.vertices is not None:
                assert part.vertices[:, 2].min() > -2e-3, a.id  # collision never reaches below the base


def test_masses_in_ranges_and_plausible(all_assets: list[Asset]) -> None:
    limits = {(c.category, c.kind): c.mass_limits for c in CATEGORY_DEFS}
    for a in all_assets:
        lo, hi = a.mass_range
        assert lo <= a.mass <= hi, a.id
        mlo, mhi = limits[(a.category, a.kind)]
        assert mlo <= a.mass <= mhi, (a.id, a.mass, (mlo, mhi))
        density = a.mass / a.visual.volume
        assert 20 <= density <= 9000, (a.id, density)


def test_prompt_objects_are_covered(catalogue: Catalogue) -> None:
    for text, category in PROMPT_OBJECTS:
        asset = catalogue.resolve(text)
        assert not asset.generated, text
        assert asset.category == category, (text, asset.id)


def test_ycb_dining_objects(by_id: dict[str, Asset]) -> None:
    for ident, (size, mass, category) in YCB.items():
        asset = by_id[ident]
        assert asset.category == category
        assert np.allclose(sorted(asset.size), size, rtol=0.01), ident
        assert asset.mass == pytest.approx(mass)


def test_collision_is_built_to_purpose(all_assets: list[Asset]) -> None:
    for a in all_assets:
        if a.kind in FLAT_KINDS:
            assert len(a.collision) == 1, (a.id, len(a.collision))
        if a.kind == "fork":  # a hull per third of its length: one hull lay on the neck and crept (DESIGN)
            assert len(a.collision) == 3, (a.id, len(a.collision))
        if a.cavity is not None:
            assert len(a.collision) >= 5, a.id  # a floor plus walls: the opening stays open
            assert 0 < a.cavity.depth <= a.size[2]
        for part in a.collision:
            if part.kind == "mesh":
                assert part.volume >= 0


def test_containers_and_handles(by_id: dict[str, Asset]) -> None:
    containers = {a.category for a in by_id.values() if a.cavity is not None}
    assert {
        "bowl",
        "cup",
        "mug",
        "glass",
        "wine glass",
        "pot",
        "pan",
        "vase",
        "pen holder",
        "basket",
        "box",
        "pitcher",
    } <= containers
    mug = by_id["mug_white"]
    assert mug.size[1] > mug.size[0]  # the handle sticks out on -y
    assert mug.visual.bounds[0][1] < -mug.size[0] / 2 - 0.01


def test_generation_is_deterministic() -> None:
    cat = next(c for c in CATEGORY_DEFS if c.kind == "grapes")
    a, b = build_asset(cat, cat.variants[0]), build_asset(cat, cat.variants[0])
    assert np.array_equal(a.visual.vertices, b.visual.vertices)
    assert a.mass == b.mass


def test_footprint_is_ccw_hull(by_id: dict[str, Asset]) -> None:
    fp = by_id["plate_dinner_white"].footprint()
    x, y = fp[:, 0], fp[:, 1]
    area = 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)
    assert area == pytest.approx(np.pi * 0.135**2, rel=0.02)
    assert by_id["plate_dinner_white"].footprint() is fp  # cached
