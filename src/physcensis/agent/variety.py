"""Seeded variety: how the offline planner makes the choices a prompt leaves open.

A prompt is a distribution of scenes. "a mug" may be any mug, "some pens" two to five pens, a lone vase stands
anywhere sensible on the table, and a place setting may sit at either end. Every such choice is drawn here from a
generator keyed by the run's seed, the variety level and the choice's own name (the mention it is for, what is
chosen), so the same prompt, seed and level always give the same program, whatever order the planner asks in, and
another seed gives another scene. `none` draws nothing: every choice is the canonical one (the planner's scene before
variety existed). What the words fix (a count, a colour, a side) is never drawn.
"""

from __future__ import annotations

import hashlib
from collections.abc import Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from typing import TypeVar

import numpy as np

from physcensis.errors import PhyscensisError

T = TypeVar("T")
R2 = (0.7548776662466927, 0.5698402909980532)  # 1/p and 1/p^2, p the plastic number: the best-spread 2-D sequence
R2_PERIOD = 1 << 32


class Variety(StrEnum):
    NONE = "none"  # the canonical scene: nothing drawn
    NORMAL = "normal"  # choices within what the words and a typical scene allow
    WIDE = "wide"  # wider ranges: counts, spacing, context objects, turns


VARIETIES = tuple(v.value for v in Variety)
DEFAULT_VARIETY = Variety.NORMAL


def parse_variety(value: str | Variety) -> Variety:
    """`value` as a Variety, or a one-line error naming the levels."""
    try:
        return Variety(str(value).strip().lower())
    except ValueError:
        raise PhyscensisError(f"variety {value!r}: give one of {', '.join(VARIETIES)}") from None


@dataclass(frozen=True)
class Draws:
    """The seeded choices of one run. Each method takes a `key` naming the choice; with `Variety.NONE` each returns
    its canonical value and draws nothing."""

    level: Variety = Variety.NONE
    seed: int = 0
    fixed: frozenset[tuple[object, ...]] = frozenset()  # choices whose keys hold one of these stay canonical
    fixed_kinds: frozenset[str] = frozenset()  # and choices whose key starts with one of these (a redraw)
    attempt: int = 0  # a second draw of the same run (after the first failed) draws every choice afresh
    # every choice drawn: its key and how many options it had (how open the prompt left it; evaluation reads it)
    options: dict[tuple[object, ...], int] = field(default_factory=dict, compare=False, repr=False)

    @property
    def on(self) -> bool:
        return self.level is not Variety.NONE

    def canonical(self, *key: object) -> bool:
        """Whether the choice `key` is canonical: no variety, or it names a fixed key (as a contiguous part)."""
        if not self.on:
            return True
        return bool(key and key[0] in self.fixed_kinds) or any(_contains(key, part) for part in self.fixed)

    @property
    def wide(self) -> bool:
        return self.level is Variety.WIDE

    def rng(self, *key: object) -> np.random.Generator:
        """A generator of its own for the choice `key` (stable across runs and Python processes)."""
        attempt = (f"attempt {self.attempt}",) if self.attempt else ()
        text = "\x1f".join(map(str, (self.seed, self.level.value, *attempt, *key)))
        digest = hashlib.blake2b(text.encode(), digest_size=8).digest()
        return np.random.default_rng(int.from_bytes(digest, "little"))

    def order(self, items: Sequence[T], *key: object, weights: Sequence[float] | None = None) -> list[T]:
        """The items in a drawn order (a weighted shuffle: heavier items tend to come first); as given when off."""
        items = list(items)
        if self.canonical(*key) or len(items) < 2:
            return items
        self.options[key] = len(items)
        w = np.ones(len(items)) if weights is None else np.maximum(np.asarray(weights, dtype=float), 1e-6)
        keys = self.rng("order", *key).random(len(items)) ** (1.0 / w)  # Efraimidis-Spirakis
        return [items[i] for i in np.argsort(-keys, kind="stable")]

    def count(self, canonical: int, low: int, high: int, *key: object) -> int:
        """A count in [low, high] (canonical kept inside), uniform; the canonical count when off."""
        low, high = min(low, canonical), max(high, canonical)
        if self.canonical(*key) or low >= high:
            return canonical
        self.options[key] = high - low + 1
        return int(self.rng("count", *key).integers(low, high + 1))

    def uniform(self, canonical: float, low: float, high: float, *key: object) -> float:
        """A value in [low, high], uniform; the canonical value when off."""
        if self.canonical(*key) or low >= high:
            return canonical
        return float(self.rng("uniform", *key).uniform(low, high))

    def spread_point(self, *key: object) -> tuple[float, float] | None:
        """A point (u, v) of the unit square for the choice `key`, None when it is canonical. Over consecutive seeds
        the points of one key follow an R2 low-discrepancy sequence from a start drawn from the key (and attempt)
        alone: twenty seeds put a lone group in twenty places spread over its room, not in the clumps that
        independent draws make (two of twenty within 5 cm of each other is then likely)."""
        if self.canonical(*key):
            return None
        attempt = (f"attempt {self.attempt}",) if self.attempt else ()
        text = "\x1f".join(map(str, ("spread", self.level.value, *attempt, *key)))
        start = np.random.default_rng(int.from_bytes(hashlib.blake2b(text.encode(), digest_size=8).digest(), "little"))
        u, v = start.random(2)
        step = self.seed % R2_PERIOD  # the same point for the same seed, without float trouble on huge seeds
        return float((u + step * R2[0]) % 1.0), float((v + step * R2[1]) % 1.0)

    def chance(self, probability: float, *key: object) -> bool:
        """True with `probability` (never when off)."""
        return not self.canonical(*key) and bool(self.rng("chance", *key).random() < probability)

    def pick(self, canonical: T, options: Sequence[T], *key: object) -> T:
        """One of the options, uniform; the canonical one when off."""
        if self.canonical(*key) or not options:
            return canonical
        self.options[key] = len(options)
        return options[int(self.rng("pick", *key).integers(len(options)))]

    def open_choices(self, leave_out: frozenset[str] = frozenset()) -> int:
        """How many different programs the choices drawn so far could give (their options multiplied, at most a
        million), leaving out the choices whose key starts with one of `leave_out`: 1 when nothing was open."""
        total = 1
        for key, n in self.options.items():
            if not (key and key[0] in leave_out):
                total = min(1_000_000, total * n)
        return total

    def spread(self, half_range: float) -> float:
        """How far a range drawn around a canonical value reaches: wide variety twice as far."""
        return half_range * (2.0 if self.wide else 1.0)


def _contains(key: tuple[object, ...], part: tuple[object, ...]) -> bool:
    n = len(part)
    return any(key[i : i + n] == part for i in range(len(key) - n + 1))


NO_VARIETY = Draws()
