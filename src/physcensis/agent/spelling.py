"""Misspelt nouns read as the catalogue word they miss by one letter ("a bannana", "three shampoo botles").

A word is corrected only when no catalogue name has it, it is no word the reading knows otherwise (a scene word, a
stop word), English does not know it (pyspellchecker's word list, MIT: "painting" is no misspelt "printing"), and
exactly one catalogue word of five letters or more that starts with the same letter is one edit away from it (a
letter added, dropped, changed, or two neighbours swapped). The reading and its account correct alike, so the account
says what the misspelt phrase became.
"""

from __future__ import annotations

import functools
from collections.abc import Iterable
from typing import Any

MIN_TARGET = 5  # letters of the catalogue word a misspelling may be read as
MIN_WORD = 4  # letters of a word that may be misspelt


def one_edit(a: str, b: str) -> bool:
    """Whether `a` and `b` differ by exactly one edit: a letter inserted, deleted or changed, or two adjacent letters
    swapped."""
    if a == b or abs(len(a) - len(b)) > 1:
        return False
    if len(a) == len(b):
        diff = [i for i, (x, y) in enumerate(zip(a, b, strict=True)) if x != y]
        if len(diff) == 1:
            return True
        i = diff[0]
        return len(diff) == 2 and diff[1] == i + 1 and a[i] == b[i + 1] and a[i + 1] == b[i]
    short, long = (a, b) if len(a) < len(b) else (b, a)
    i = next((i for i, (x, y) in enumerate(zip(short, long, strict=False)) if x != y), len(short))
    return short[i:] == long[i + 1 :]


def correction(word: str, by_initial: dict[str, list[str]], fits: Iterable[str] = ()) -> str | None:
    """The one catalogue word (`by_initial`) `word` misses by one edit, or None (none, several, or `word` is an
    English word: "painting" is no misspelt "printing"). Of several, the one of `fits` (the words that make a
    catalogue name with the word before: "a hole puch" is a hole punch, not a pouch). The caller has checked that no
    catalogue name has it."""
    if len(word) < MIN_WORD or not word.isalpha():
        return None
    found = {w for w in by_initial.get(word[0], ()) if one_edit(word, w)}
    if len(found) > 1:
        found &= set(fits)
    if len(found) != 1 or _english().known([word]):
        return None
    return found.pop()


@functools.cache
def _english() -> Any:
    """pyspellchecker's English word list, loaded (0.3 s) only when a word may be misspelt."""
    from spellchecker import SpellChecker

    return SpellChecker(language="en")


def by_initial(vocabulary: Iterable[str]) -> dict[str, list[str]]:
    """The catalogue words long enough to correct to, by their first letter."""
    index: dict[str, list[str]] = {}
    for w in vocabulary:
        if len(w) >= MIN_TARGET and w.isalpha():
            index.setdefault(w[0], []).append(w)
    return index
