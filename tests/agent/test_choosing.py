"""The offline planner chooses variants that fit: the words, the support, a stack, a container and its contents."""

from __future__ import annotations

import json
from typing import Any

import numpy as np
import pytest

from physcensis.agent import choosing
from physcensis.agent.base import AgentContext
from physcensis.agent.choosing import Room
from physcensis.agent.planner import OfflinePlanner
from physcensis.agent.reading import Lexicon, read_prompt
from physcensis.assets import default_catalogue
from physcensis.assets.catalogue import Catalogue
from physcensis.assets.model import Asset
from physcensis.scene import Support


@pytest.fixture(scope="module")
def catalogue() -> Catalogue:
    return default_catalogue()


@pytest.fixture(scope="module")
def lexicon(catalogue: Catalogue) -> Lexicon:
    return Lexicon(catalogue)


def _variants(catalogue: Catalogue, name: str) -> list[Asset]:
    return catalogue.variants(name)


def _ranked(prompt: str, lexicon: Lexicon, catalogue: Catalogue, k: int = 0) -> tuple[list[Asset], list[Asset]]:
    """The variants of the prompt's k-th mention before and after ranking them by its words."""
    request = read_prompt(prompt, lexicon)
    m = request.mentions[k]
    variants = catalogue.variants(" ".join([*m.adjectives, m.phrase]))
    words = choosing.words_of(request.tokens, m.start, m.end, m.phrase, m.adjectives)
    return variants, choosing.rank_by_words(variants, words)


# -- the words --------------------------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("prompt", "word"),
    [
        ("a red mug", "red"),
        ("a wooden spoon", "wooden"),
        ("a blue towel", "blue"),
        ("a green toy car", "green"),
        ("a black stapler", "black"),
        ("a galvanised metal bucket", "metal"),
        ("a white candle", "white"),
        ("a pink toothbrush", "pink"),
        ("two tennis balls", "tennis"),
        ("three soccer balls", "soccer"),
        ("books lying flat on the desk", "flat"),
        ("books standing upright", "upright"),
        ("ring binders lying flat", "flat"),
    ],
)
def test_the_words_named_pick_the_variants(prompt: str, word: str, lexicon: Lexicon, catalogue: Catalogue) -> None:
    variants, ranked = _ranked(prompt, lexicon, catalogue)
    assert any(word not in a.description for a in variants)  # the words narrow something
    assert ranked and all(word in f"{a.description} {a.kind}" for a in ranked)


def test_binders_standing_side_by_side_are_upright(lexicon: Lexicon, catalogue: Catalogue) -> None:
    variants, ranked = _ranked("ring binders standing side by side on the shelf", lexicon, catalogue)
    assert any("flat" in a.description for a in variants)
    assert ranked and all("flat" not in a.description and a.size[2] > a.size[1] for a in ranked)


@pytest.mark.parametrize(
    "prompt", ["three rolls of toilet paper stacked", "a roll of toilet paper", "two rolls of toilet paper"]
)
def test_rolls_are_single_rolls_not_packs(prompt: str, lexicon: Lexicon, catalogue: Catalogue) -> None:
    variants, ranked = _ranked(prompt, lexicon, catalogue)
    assert any(choosing.is_multiple(a) for a in variants)
    assert ranked and not any(choosing.is_multiple(a) for a in ranked)


def test_a_pack_asked_for_is_a_pack(lexicon: Lexicon, catalogue: Catalogue) -> None:
    _, ranked = _ranked("a pack of toilet paper", lexicon, catalogue)
    assert ranked and all("pack" in a.description for a in ranked)


@pytest.mark.parametrize("noun", ["rubber duck", "bowl", "toy car", "bucket", "plate"])
def test_small_and_large_pick_the_smaller_and_larger_variants(
    noun: str, lexicon: Lexicon, catalogue: Catalogue
) -> None:
    _, small = _ranked(f"a small {noun}", lexicon, catalogue)
    _, large = _ranked(f"a large {noun}", lexicon, catalogue)
    _, plain = _ranked(f"a {noun}", lexicon, catalogue)
    volume = [float(np.prod(a.size)) for a in plain]
    assert float(np.prod(small[0].size)) < float(np.median(volume)) < float(np.prod(large[0].size))


def test_words_stop_at_the_next_phrase() -> None:
    tokens = "three rolls of toilet paper stacked and a folded towel".split()
    words = choosing.words_of(tokens, 0, 5, "roll of toilet paper", ())
    assert "folded" not in words and "towel" not in words
    assert {"roll", "toilet", "paper"} <= words and "three" not in words


# -- the support ------------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("noun", ["toilet paper", "towel", "ring binder", "letter tray", "box", "book", "basket"])
def test_variants_that_fit_a_shallow_shelf_come_first(noun: str, catalogue: Catalogue) -> None:
    room = Room(0.3, 0.6, 0.3)
    variants = _variants(catalogue, noun)
    chosen = choosing.fitting(variants, room)
    fits = [a for a in variants if choosing.fit_tier(a, room) < 2]  # and under the clearance
    if not fits:
        pytest.skip(f"no {noun} fits a 30 cm shelf")
    assert set(chosen) == set(fits)  # what does not fit is left out
    first = chosen[0]
    assert min(first.size[:2]) <= 0.3 - 2 * choosing.EDGE_MARGIN and first.size[2] < 0.3
    tiers = [choosing.fit_tier(a, room) for a in chosen]
    assert tiers == sorted(tiers)  # fitting as it stands before fitting turned


def test_a_rug_smaller_than_the_floor(catalogue: Catalogue) -> None:
    variants = _variants(catalogue, "rug")
    assert any(max(a.size[:2]) > 1.5 for a in variants)
    assert all(max(a.size[:2]) <= 1.48 for a in choosing.fitting(variants, Room(1.5, 1.5)))


def test_a_row_fits_the_width(catalogue: Catalogue) -> None:
    variants = [a for a in _variants(catalogue, "ring binder") if a.size[2] > a.size[1]]  # standing on an edge
    row = choosing.fitting(variants, Room(0.3, 1.0, 0.35), along=12, gap=0.03)
    assert all(12 * a.size[1] + 11 * 0.03 <= 1.0 for a in row)
    assert len(row) < len(variants)


def test_nothing_fits_gives_the_smallest_first(catalogue: Catalogue) -> None:
    variants = _variants(catalogue, "rug")
    chosen = choosing.fitting(variants, Room(0.2, 0.2))
    assert chosen[0].size[0] * chosen[0].size[1] == min(a.size[0] * a.size[1] for a in variants)


# -- stacks -----------------------------------------------------------------------------------------------------------


def test_flat_tops(catalogue: Catalogue) -> None:
    blocks = {a.id: a for a in _variants(catalogue, "toy block")}
    assert choosing.top_share(blocks["toy_block_roof_red"]) < choosing.FLAT_TOP
    assert choosing.top_share(blocks["toy_block_cube_red"]) >= choosing.FLAT_TOP
    assert all(choosing.top_share(a) < choosing.FLAT_TOP for a in _variants(catalogue, "ball"))
    assert all(choosing.stacks_well(a) for a in _variants(catalogue, "book lying flat") if "flat" in a.kind)


@pytest.mark.parametrize(
    ("noun", "levels"),
    [("toy block", 6), ("book", 4), ("envelope", 5), ("towel", 3), ("toilet paper", 3), ("box", 3), ("can", 3)],
)
def test_a_stack_uses_one_variant_that_stacks(noun: str, levels: int, catalogue: Catalogue) -> None:
    variants = _variants(catalogue, noun)
    chosen = choosing.stack_choice(variants, levels, Room(0.35, 0.9, 0.3))
    assert choosing.stacks_well(chosen)
    assert chosen.size[2] * levels < 0.3 or not any(
        choosing.stacks_well(a) and a.size[2] * levels < 0.3 for a in variants
    )


def test_a_stack_of_what_never_stacks_takes_the_first(catalogue: Catalogue) -> None:
    saucers = _variants(catalogue, "saucer")
    assert not any(choosing.stacks_well(a) for a in saucers)  # dishes: not flat on top
    assert choosing.stack_choice(saucers, 5) is saucers[0]


def test_a_colour_outweighs_a_size(lexicon: Lexicon, catalogue: Catalogue) -> None:
    _, ranked = _ranked("a large blue bowl", lexicon, catalogue)
    assert ranked and all("blue" in a.description for a in ranked)


# -- containers and contents ------------------------------------------------------------------------------------------


def test_long_things_stand_by_the_opening(catalogue: Catalogue) -> None:
    holder = catalogue.variants("pen holder")[0]
    pen = catalogue.variants("ballpoint pen")[0]
    ball = catalogue.variants("tennis ball")[0]
    assert holder.cavity is not None
    assert choosing.is_long(pen, holder.cavity.depth) and not choosing.is_long(ball, 0.05)
    by_volume = choosing.capacity(holder) / (float(np.prod(pen.size)) * 0.8)
    assert 3 <= choosing.room_for(holder, pen) < by_volume  # the opening, not the volume, decides


@pytest.mark.parametrize(
    ("container", "item", "count"),
    [
        ("bucket", "tennis ball", 5),
        ("tumbler", "toothbrush", 2),
        ("pen holder", "ballpoint pen", 3),
        ("tool bag", "hammer", 1),
        ("basket", "apple", 4),
        ("bowl", "orange", 3),
        ("mug", "pencil", 4),
    ],
)
def test_the_container_chosen_holds_the_count(container: str, item: str, count: int, catalogue: Catalogue) -> None:
    items = catalogue.variants(item)
    containers = choosing.containers_for(catalogue.variants(container), [(choosing.typical(items), count)])
    chosen = containers[0]
    assert choosing.holds(chosen, [(choosing.typical(items), count)])
    contents = choosing.contents_for(items, chosen, count)
    assert choosing.room_for(chosen, contents[0], 1.0) >= count
    assert all(choosing.passes_opening(a, chosen) for a in contents)


def test_a_container_too_small_is_not_chosen(catalogue: Catalogue) -> None:
    buckets = catalogue.variants("bucket")
    ball = catalogue.variants("soccer ball")[0]
    chosen = choosing.containers_for(buckets, [(ball, 2)])
    assert choosing.holds(chosen[0], [(ball, 2)])
    assert not choosing.holds(buckets[0], [(ball, 2)])  # the first is too small


def test_what_does_not_pass_the_opening_is_not_held(catalogue: Catalogue) -> None:
    holder = catalogue.variants("pen holder")[0]
    basketball = catalogue.variants("basketball")[0]
    assert not choosing.passes_opening(basketball, holder)
    assert not choosing.holds(holder, [(basketball, 1)]) and choosing.room_for(holder, basketball) == 0


def test_contents_that_fit_come_first(catalogue: Catalogue) -> None:
    tumbler = catalogue.variants("tumbler")[0]
    brushes = catalogue.variants("toothbrush")
    chosen = choosing.contents_for(brushes, tumbler, 2)
    assert "electric" not in " ".join(a.description for a in chosen)
    assert all(choosing.room_for(tumbler, a) >= 2 for a in chosen)


# -- the planner ------------------------------------------------------------------------------------------------------


def _program(prompt: str, support: Support, variety: str = "normal") -> list[list[Any]]:
    return list(json.loads(OfflinePlanner(variety=variety).propose(AgentContext(prompt, support, ()))))


def _descriptions(program: list[list[Any]], prefix: str) -> list[str]:
    return [e[1] for e in program if len(e) == 2 and isinstance(e[0], str) and e[0].startswith(prefix)]


def test_planner_toilet_rolls_and_towel_fit_the_shelf(catalogue: Catalogue) -> None:
    shelf = Support(kind="shelf", size=(0.3, 0.6))
    prompt = "a bathroom shelf with three rolls of toilet paper stacked and a folded towel"
    for variety in ("none", "normal"):
        program = _program(prompt, shelf, variety)
        rolls = _descriptions(program, "toilet_paper")
        assert len(rolls) == 3
        assert variety != "none" or len(set(rolls)) == 1  # one variant for the whole stack canonically
        for description in [*rolls, *_descriptions(program, "towel")]:
            asset = catalogue.resolve(description)
            assert not choosing.is_multiple(asset)
            assert choosing.fit_tier(asset, Room(0.3, 0.6, 0.3)) < 2
        assert all(choosing.stacks_well(catalogue.resolve(r)) for r in rolls)


def test_planner_tower_of_toy_blocks_is_flat_topped_and_one_variant_canonically(catalogue: Catalogue) -> None:
    floor = Support(kind="floor", size=(1.5, 1.5))
    for variety in ("none", "normal"):
        blocks = _descriptions(_program("a tower of six toy blocks on the nursery floor", floor, variety), "toy_block")
        assert len(blocks) == 6 and all(choosing.stacks_well(catalogue.resolve(b)) for b in blocks)
        assert variety != "none" or len(set(blocks)) == 1


def test_planner_stacks_of_books_lie_flat_and_match_canonically(catalogue: Catalogue) -> None:
    table = Support(kind="table", size=(1.2, 0.8))
    for variety in ("none", "normal"):
        books = _descriptions(_program("three stacks of books on the table, four books each", table, variety), "book")
        assert len(books) == 12 and all(choosing.stacks_well(catalogue.resolve(b)) for b in books)
        assert variety != "none" or len(set(books)) == 1


def test_planner_fills_the_container_with_the_count_asked(catalogue: Catalogue) -> None:
    floor = Support(kind="floor", size=(1.5, 1.5))
    program = _program("a bucket filled with five tennis balls on the garage floor", floor)
    into = [e for e in program if len(e) == 4 and e[1] == "PLACE-IN"]
    assert len(into) == 1 and len(into[0][0]) == 5
    assert all("tennis" in d for d in _descriptions(program, "ball"))
    bucket = catalogue.resolve(_descriptions(program, "bucket")[0])
    assert choosing.holds(bucket, [(catalogue.resolve(_descriptions(program, "ball")[0]), 5)])


def test_planner_toothbrushes_fit_the_tumbler(catalogue: Catalogue) -> None:
    shelf = Support(kind="shelf", size=(0.25, 0.8))
    program = _program("a bathroom shelf with two toothbrushes in a tumbler and a bar of soap", shelf)
    into = [e for e in program if len(e) == 4 and e[1] == "PLACE-IN"]
    assert len(into) == 1 and len(into[0][0]) == 2
    tumbler = catalogue.resolve(_descriptions(program, "cup")[0])
    brushes = [catalogue.resolve(d) for d in _descriptions(program, "toothbrush")]
    assert choosing.holds(tumbler, [(b, 1) for b in brushes])


def test_planner_binders_standing_in_a_row_are_upright_and_fit(catalogue: Catalogue) -> None:
    shelf = Support(kind="shelf", size=(0.3, 1.0))
    program = _program("an office shelf with ring binders standing side by side and a letter tray", shelf)
    binders = [catalogue.resolve(d) for d in _descriptions(program, "ring_binder") + _descriptions(program, "binder")]
    assert len(binders) >= 3
    assert all(a.size[2] > a.size[1] and a.size[0] <= 0.3 for a in binders)
    assert sum(a.size[1] for a in binders) + 0.03 * (len(binders) - 1) <= 1.0


def test_mixed_contents_are_counted_variant_by_variant(catalogue: Catalogue) -> None:
    holder = catalogue.variants("pen holder")[0]
    pens = catalogue.variants("pen")
    mixed = choosing.room_for_mixed(holder, pens, 1.0, most=40)
    smallest = min(choosing.room_for(holder, a) for a in pens)
    largest = max(choosing.room_for(holder, a) for a in pens)
    assert smallest <= mixed <= largest and mixed >= 3
    basket = catalogue.variants("toy bin")[0]
    toys = catalogue.variants("toy robot")
    assert (
        2 <= choosing.room_for_mixed(basket, toys, 0.5, most=40) <= max(choosing.room_for(basket, a, 0.5) for a in toys)
    )
