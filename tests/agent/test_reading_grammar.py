"""The reading is compositional: quantities x nouns x holders x relations x arrangements, for any catalogue noun."""

from __future__ import annotations

import pytest

from physcensis.agent.base import AgentContext
from physcensis.agent.planner import OfflinePlanner
from physcensis.agent.reading import Lexicon, Mention, read_prompt
from physcensis.assets import default_catalogue
from physcensis.program import check_program, parse_program
from physcensis.scene import Support


@pytest.fixture(scope="module")
def lexicon() -> Lexicon:
    return Lexicon(default_catalogue())


def _roles(lexicon: Lexicon, role: str) -> list[str]:
    """Catalogue categories with this role whose name is read back as that category (any category added later
    takes part)."""
    found = []
    for category in default_catalogue().categories():
        if lexicon.role(category) != role:  # cheap, and most categories have none: read only the rest
            continue
        if [m.category for m in read_prompt(f"a {category}", lexicon).mentions] == [category]:
            found.append(category)
    return found


def _by_category(text: str, lexicon: Lexicon) -> dict[str, Mention]:
    return {m.category: m for m in read_prompt(text, lexicon).mentions}


def test_roles_come_from_the_assets(lexicon: Lexicon) -> None:
    containers, carriers = _roles(lexicon, "container"), _roles(lexicon, "carrier")
    assert {"bowl", "basket", "box"} <= set(containers) and {"tray", "cutting board", "plate"} <= set(carriers)
    assert {"jar", "pencil case", "makeup bag"} <= set(containers)  # their open variants hold things
    catalogue = default_catalogue()
    for category in containers:
        variants = [e.id for e in catalogue.entries() if e.category == category]
        assert any(catalogue.get(v).cavity is not None for v in variants), category
    assert not set(containers) & set(carriers)


@pytest.mark.parametrize(
    "phrasing",
    [
        "a {h} full of {n} {i}s",
        "a {h} filled with {n} {i}s",
        "a {h} holding {n} {i}s",
        "a {h} carrying {n} {i}s",
        "a {h} loaded with {n} {i}s",
        "a {h} containing {n} {i}s",
        "a {h} with {n} {i}s",
        "a {h} of {n} {i}s",
        "{n} {i}s in a {h}",
        "{n} {i}s inside the {h}",
        "a {h} with {n} {i}s on it",
    ],
)
def test_every_holder_phrasing_puts_the_items_in_or_on_any_holder(lexicon: Lexicon, phrasing: str) -> None:
    holders = _roles(lexicon, "container")[:4] + _roles(lexicon, "carrier")[:4]
    for holder in holders:
        for item, n in (("apple", "three"), ("toy block", "5")):
            by = _by_category(phrasing.format(h=holder, i=item, n=n), lexicon)
            mentions = list(by.values())
            h = mentions.index(by[holder])
            assert by[item].count == (3 if n == "three" else 5), (phrasing, holder)
            if lexicon.role(holder) == "container":  # "with apples on it" ends in the basket too
                assert mentions.index(by[item]) in by[holder].contents, (phrasing, holder)
            else:
                assert by[item].on == h, (phrasing, holder)


@pytest.mark.parametrize(
    ("words", "count"),
    [
        ("two", 2),
        ("7", 7),
        ("a pair of", 2),
        ("a couple of", 2),
        ("a few", 3),
        ("several", 4),
        ("a dozen", 12),
        ("two pairs of", 4),
    ],
)
def test_quantities_compose_with_any_noun(lexicon: Lexicon, words: str, count: int) -> None:
    for noun in ("mugs", "spoons", "toy blocks", "bottles", "widgets"):
        (m,) = read_prompt(f"{words} {noun}", lexicon).mentions
        assert (m.count, m.explicit_count, m.plural) == (count, True, True), noun


def test_stacks_rows_and_columns_read_their_sizes(lexicon: Lexicon) -> None:
    cases = {
        "two stacks of plates, one of three and one of four": ("stack", (3, 4)),
        "a stack of 5 books": ("stack", (5,)),
        "three stacks of two bowls": ("stack", (2, 2, 2)),
        "six saucers in two stacks": ("stack", (3, 3)),
        "two rows of three cans": ("row", (3, 3)),
        "cans in rows of four": ("row", (4, 4)),
        "two columns of four books": ("column", (4, 4)),
        "a row of 5 jars": ("row", (5,)),
    }
    for text, (arrangement, sizes) in cases.items():
        (m,) = read_prompt(text, lexicon).mentions
        assert (m.arrangement, m.sizes, m.count) == (arrangement, sizes, sum(sizes)), text
    for text in ("two monitors side by side", "mugs lined up", "four cups in a row", "bottles evenly spaced"):
        (m,) = read_prompt(text, lexicon).mentions
        assert m.arrangement == "row", text
    (pairs,) = read_prompt("six mugs in pairs", lexicon).mentions
    assert (pairs.arrangement, pairs.sizes) == ("row", (2, 2, 2))
    assert read_prompt("a pile of books", lexicon).mentions[0].arrangement == "pile"
    assert read_prompt("balls scattered", lexicon).mentions[0].arrangement == "scatter"


def test_relations_attach_to_the_nearest_noun_phrase(lexicon: Lexicon) -> None:
    by = _by_category("a lamp beside the monitor and a mug", lexicon)
    names = list(by)
    lamp = next(m for m in by.values() if "lamp" in m.phrase)
    assert names[lamp.beside or 0] == "monitor" and by["mug"].beside is None
    sides = {
        "a mug in front of the laptop": "front",
        "a vase behind a bowl": "behind",
        "a phone to the left of the keyboard": "left",
        "a mouse right of the keyboard": "right",
        "a candle next to a vase": "beside",
        "a mug on the left side of the laptop": "left",  # a side of it: not a laptop held "of" a mug
        "a notebook on the right-hand side of the keyboard": "right",
        "a plant on the far side of the monitor": "behind",
    }
    for text, side in sides.items():
        first, second = read_prompt(text, lexicon).mentions
        assert (first.beside, first.side, second.beside) == (1, side, None), text
        assert not first.contents and second.held_by is None, text
    keyboard, mouse, mug = read_prompt("a keyboard with a mouse to its right and a mug on its left", lexicon).mentions
    assert (mouse.beside, mouse.side, mug.beside, mug.side, keyboard.beside) == (0, "right", 0, "left", None)
    # a holder's list ends where a new object (with its own article) begins; its position is the holder's
    basket = read_prompt("a basket of apples and oranges next to a mug", lexicon).mentions
    assert basket[0].contents == [1, 2] and basket[0].beside == 3 and basket[2].beside is None
    assert read_prompt("a bowl of apples and a mug", lexicon).mentions[0].contents == [1]
    trays, mugs = read_prompt("two trays with mugs", lexicon).mentions
    assert (trays.category, trays.count, mugs.on, mugs.per) == ("tray", 2, 0, 0)  # on both trays
    around = read_prompt("four cups around the bowl", lexicon).mentions
    assert around[0].around == 1 and around[0].count == 4


def test_unknown_and_missing_nouns_are_kept(lexicon: Lexicon) -> None:
    mentions = read_prompt("a gizmo next to a mug and three frobnicators on a tray", lexicon).mentions
    assert [(m.category, m.count, m.known) for m in mentions] == [
        ("gizmo", 1, False),
        ("mug", 1, True),
        ("frobnicator", 3, False),
        ("tray", 1, True),
    ]
    assert mentions[0].beside == 1 and mentions[2].on == 3
    scene_words = read_prompt("a messy desk in a kids room with a mug", lexicon).mentions
    assert [m.category for m in scene_words] == ["mug"]
    listed = read_prompt("a very tidy desk with widgets, gadgets and a bowl of cherries", lexicon).mentions
    assert [(m.category, m.known) for m in listed] == [
        ("widget", False),
        ("gadget", False),
        ("bowl", True),
        ("cherry", False),
    ]
    assert listed[2].contents == [3]


@pytest.mark.parametrize(
    "prompt",
    [
        "",
        "a stack of",
        "0 mugs",
        "1000 mugs",
        "99 stacks of 99 cups",
        "rows of rows of cans",
        "a cup on a saucer on a plate on a tray",
        "a gizmo in a widget on a thingamajig beside a doohickey",
        "the mug next to the mug",
    ],
)
def test_any_prompt_gives_the_same_checked_program_twice(prompt: str) -> None:
    support = Support.parse("table:0.8x1.2")
    first = OfflinePlanner(seed=3).plan(AgentContext(prompt, support, ()))
    assert first == OfflinePlanner(seed=3).plan(AgentContext(prompt, support, ()))
    report = check_program(parse_program(first), support)
    assert report.ok, report.feedback()
    assert 0 < sum(len(e) == 2 and isinstance(e[0], str) for e in first) <= 100


@pytest.mark.parametrize(
    ("holder", "resting", "after"),
    [
        ("rice bowl", "a pair of chopsticks", ["a soup spoon", "a small dish"]),
        ("pot", "a wooden spoon", ["a lid", "a cutting board"]),
        ("mug", "a teaspoon", ["a saucer", "a napkin", "a plate"]),
    ],
)
def test_a_rim_closes_the_with_list(lexicon: Lexicon, holder: str, resting: str, after: list[str]) -> None:
    """ "A with B resting across its rim, C and D": B rests on A's rim, and C and D stand beside it, not inside A
    (a soup spoon dropped into a rice bowl that chopsticks lie across never stayed in)."""
    listed = ", ".join(after[:-1]) + f" and {after[-1]}"
    mentions = read_prompt(f"a {holder} with {resting} resting across its rim, {listed}", lexicon).mentions
    assert [m.held_by for m in mentions[1:2]] == [0] and mentions[1].on == 0
    assert len(mentions) == 2 + len(after)
    assert all(m.held_by is None and m.on is None for m in mentions[2:]), [(m.category, m.held_by) for m in mentions]
    # without the rim the list stays the holder's
    plain = read_prompt(f"a tray with {resting}, {listed}", lexicon).mentions
    assert plain[0].category == "tray" and all(m.held_by == 0 for m in plain[1:])


@pytest.mark.parametrize(
    ("prompt", "beside"),
    [
        ("a plate with a fork on the left and a knife on the right", {"fork": "left", "knife": "right"}),
        ("a bowl with a spoon on the left", {"spoon": "left"}),
        ("a laptop with a mug on the left and a notebook on the right", {"mug": "left", "notebook": "right"}),
    ],
)
def test_a_side_said_of_a_with_list_item_is_beside_what_the_list_is_with(
    lexicon: Lexicon, prompt: str, beside: dict[str, str]
) -> None:
    """Not in the bowl, not on the plate, not on the support's side: beside the first thing, on that side of it."""
    mentions = read_prompt(prompt, lexicon).mentions
    first = mentions[0]
    assert not first.contents and not first.region, prompt
    for m in mentions[1:]:
        assert (m.beside, m.side, m.on, m.held_by, m.region) == (0, beside[m.category], None, None, ()), prompt


def test_what_fits_on_a_side_of_a_tray_stays_on_the_tray(lexicon: Lexicon) -> None:
    tray, teapot, cups = read_prompt("a tray with a teapot on the left and two cups on the right", lexicon).mentions
    assert (teapot.on, cups.on, teapot.beside, cups.beside) == (0, 0, None, None)
    assert not (tray.region or teapot.region or cups.region)


def test_a_side_of_it_after_the_support_is_the_thing_before(lexicon: Lexicon) -> None:
    """ "it" of "on it" after "a desk with ..." is the desk; of "in front of it", the thing just named."""
    text = "a desk with a monitor in the back, a keyboard in front of it and a mouse to the right of the keyboard"
    monitor, keyboard, mouse = read_prompt(text, lexicon).mentions
    assert monitor.region == ("back",)
    assert (keyboard.beside, keyboard.side, mouse.beside, mouse.side) == (0, "front", 1, "right")
    lamp, mug = read_prompt("a desk with a lamp and a mug on it", lexicon).mentions
    assert lamp.on is None and mug.on is None and mug.beside is None  # on the desk: the support


@pytest.mark.parametrize(
    ("text", "category", "count"),
    [("a roll of tape in a drawer organizer", "desk organiser", 1), ("two desk organizers", "desk organiser", 2)],
)
def test_another_spelling_is_not_a_plural(lexicon: Lexicon, text: str, category: str, count: int) -> None:
    found = [m for m in read_prompt(text, lexicon).mentions if m.category == category]
    assert [m.count for m in found] == [count]


@pytest.mark.parametrize(
    ("text", "on_it", "inside"),
    [
        ("a breakfast tray with a plate of toast, a cup of coffee and a small vase", ["plate", "cup", "vase"], set()),
        ("a tray with a bowl of apples and pears, a mug and a spoon", ["bowl", "mug", "spoon"], {"apple", "pear"}),
    ],
)
def test_a_with_list_goes_on_after_an_item_holding_its_own(
    lexicon: Lexicon, text: str, on_it: list[str], inside: set[str]
) -> None:
    """ "a plate of toast" inside a tray's list: the toast is the plate's, and what follows is the tray's again."""
    tray, *rest = read_prompt(text, lexicon).mentions
    assert [m.category for m in rest if m.on == 0] == on_it, text
    held = {m.category for m in rest if m.held_by not in (None, 0)}
    assert inside <= held, text


@pytest.mark.parametrize(
    ("text", "ring", "where"),
    [
        ("a vase surrounded by four candles", ["candle"], "around"),
        ("a cake encircled by six cupcakes", ["cupcake"], "around"),  # an unknown noun before the participle too
        ("a plate surrounded by a fork, a knife and a spoon", ["fork", "knife", "spoon"], "around"),
        ("a candle ringed by pebbles", ["pebble"], "around"),  # a bare plural after "by"
        ("a laptop flanked by two speakers", ["speaker"], "sides"),
    ],
)
def test_a_passive_ring_stands_around_what_it_names_first(
    lexicon: Lexicon, text: str, ring: list[str], where: str
) -> None:
    """ "A surrounded by B": B stands around A (the words name B after A, the other way round from "B around A")."""
    first, *rest = read_prompt(text, lexicon).mentions
    assert [m.category for m in rest] == ring
    for m in rest:
        assert (m.around if where == "around" else m.beside) == 0, text
        assert where == "around" or m.side == "sides"
    assert first.around is None and first.beside is None


def test_a_passive_ring_rings_the_holder_and_stops_at_a_thing_placed_by_its_own_words(lexicon: Lexicon) -> None:
    vase, flowers, candles = read_prompt(
        "a table with a vase of flowers in the middle, surrounded by four candles", lexicon
    ).mentions
    assert vase.contents == [1] and flowers.held_by == 0  # the flowers stay in the vase
    assert candles.around == 0 and candles.count == 4  # the candles ring the vase, not the flowers
    candle, pebbles, bowl = read_prompt("a candle surrounded by pebbles and a bowl on the left", lexicon).mentions
    assert pebbles.around == 0 and bowl.around is None and bowl.region == ("left",)


def test_a_dish_counted_as_one_is_a_small_dish_and_dishes_are_plates(lexicon: Lexicon) -> None:
    soap, dish = read_prompt("a bar of soap on a dish", lexicon).mentions
    assert (dish.category, dish.count, soap.on) == ("plate", 1, 1)
    (plates,) = read_prompt("a sink full of dishes", lexicon).mentions
    assert plates.category == "plate" and plates.count > 1


@pytest.mark.parametrize(
    "text",
    [
        "a cooking pot with a ladle in it on the counter, and a kettle",
        "a bowl with a spoon in it, a milk carton and a coffee mug",
    ],
)
def test_in_it_after_a_listed_thing_ends_the_holders_list(lexicon: Lexicon, text: str) -> None:
    """ "A bowl with a spoon in it, a milk carton and a mug": the spoon is in the bowl, the carton and mug are not."""
    holder, inside, *rest = read_prompt(text, lexicon).mentions
    assert holder.contents == [1] and inside.held_by == 0
    assert rest and all(m.held_by is None and m.on is None for m in rest)
    # said after the whole list, "in it" still puts every item in
    bowl, *fruit = read_prompt("a bowl with apples, pears and plums in it", lexicon).mentions
    assert bowl.contents == [1, 2, 3]
