"""Misspelt nouns are read as the catalogue word they miss by one letter, and real English words never are."""

from __future__ import annotations

import pytest

from physcensis.agent.reading import Lexicon, read_prompt
from physcensis.agent.spelling import one_edit
from physcensis.assets import default_catalogue


@pytest.fixture(scope="module")
def lexicon() -> Lexicon:
    return Lexicon(default_catalogue())


@pytest.mark.parametrize(
    ("a", "b", "one"),
    [
        ("bannana", "banana", True),  # a letter added
        ("botle", "bottle", True),  # dropped
        ("glaas", "glass", True),  # changed
        ("galss", "glass", True),  # two neighbours swapped
        ("glass", "glass", False),
        ("gsals", "glass", False),  # two letters apart
        ("banan", "bananas", False),  # two added
    ],
)
def test_one_edit(a: str, b: str, one: bool) -> None:
    assert one_edit(a, b) is one and one_edit(b, a) is one


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("a bannana, two apples and an orange in a bowl", [("banana", 1), ("apple", 2), ("orange", 1), ("bowl", 1)]),
        ("three shampoo botles and a soap dispenser", [("shampoo bottle", 3), ("soap dispenser", 1)]),
        ("four wine glases in a row", [("wine glass", 4)]),
    ],
)
def test_a_noun_misspelt_by_one_letter_is_the_catalogues(
    text: str, read: list[tuple[str, int]], lexicon: Lexicon
) -> None:
    assert [(m.category, m.count) for m in read_prompt(text, lexicon).mentions] == read


@pytest.mark.parametrize(
    "text",
    [
        "a painting leaning against the wall",  # not a misspelt "printing"
        "a laptop plus a mouse",  # not a "plush"
        "a clean plate",  # not "clear"
    ],
)
def test_an_english_word_is_never_respelt(text: str, lexicon: Lexicon) -> None:
    words = [w for m in read_prompt(text, lexicon).mentions for w in (*m.adjectives, *m.phrase.split())]
    assert not {"printing", "plush", "clear"} & set(words)
