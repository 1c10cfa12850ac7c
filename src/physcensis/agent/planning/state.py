"""What the offline planner's parts share while they write a program, and what they all read of a mention.

One `PlanState` per planner, kept between its programs: a repair or an enrichment reads the support and the words
of the last plan. `draws` is replaced, not mutated, when a choice is fixed or made canonical for a while, so every
part reads it from here at the moment it draws.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field

from physcensis.agent.choosing import Room
from physcensis.agent.reading import Lexicon, Mention
from physcensis.agent.variety import NO_VARIETY, Draws
from physcensis.assets.catalogue import Catalogue

Ids = dict[int, list[str]]  # mention index -> the ids of its objects in the program


@dataclass
class PlanState:
    """The catalogue, the run's draws, the notes for the user, and the support and prompt of the plan last written."""

    catalogue: Catalogue
    lexicon: Lexicon
    draws: Draws  # the seeded choices of the run
    notes: list[str] = field(default_factory=list)  # said to the user in the run's transcript
    room: Room | None = None  # the support of the plan being written, for choosing variants that fit
    tokens: list[str] = field(default_factory=list)  # its prompt's words
    mentions: list[Mention] = field(default_factory=list)  # and its mentions

    @contextmanager
    def canonically(self) -> Iterator[None]:
        """Within the block, every choice is the canonical one."""
        draws, self.draws = self.draws, NO_VARIETY
        try:
            yield
        finally:
            self.draws = draws

    def note(self, text: str) -> None:
        """Say `text` to the user, once."""
        if text not in self.notes:
            self.notes.append(text)

    def category(self, name: str) -> str:
        hits = self.catalogue.hits(name, 1)
        return self.catalogue.entry(hits[0].asset_id).category if hits else name

    def role(self, m: Mention) -> str:
        return self.lexicon.role(m.category) if m.known else ""

    def gap(self, m: Mention) -> float:
        """The gap between neighbours of a row or side-by-side stacks: wider when evenly spaced."""
        if m.spaced:
            return self.draws.uniform(0.06, 0.05, 0.05 + self.draws.spread(0.03), "gap", *choice_key(m))
        return self.draws.uniform(0.03, 0.02, 0.02 + self.draws.spread(0.025), "gap", *choice_key(m))

    def ring_turn(self, m: Mention) -> float:
        """Where a ring of m's objects starts: the canonical angle 0, or any turn up to one step with variety."""
        return self.draws.uniform(0.0, 0.0, 2 * math.pi / max(1, m.count), "ring", *choice_key(m))


def choice_key(m: Mention) -> tuple[object, ...]:
    """What names mention m's choices: the same mention draws the same, whichever part asks."""
    return (m.category, m.phrase, m.start, m.end)


def row_lengths(m: Mention) -> list[int]:
    """How many objects each row holds, back row first: rows of the given sizes, columns turned into rows."""
    sizes = list(m.sizes) or ([m.count] if m.groups <= 1 else _even(m.count, m.groups))
    if m.arrangement == "column":  # columns run front to back: row r holds one object of each column long enough
        return [sum(1 for size in sizes if size > r) for r in range(max(sizes))]
    return sizes


def _even(count: int, groups: int) -> list[int]:
    base, extra = divmod(count, groups)
    return [base + (1 if g < extra else 0) for g in range(groups) if base + (1 if g < extra else 0) > 0]


def rings_on(m: Mention, mentions: list[Mention]) -> bool:
    """Whether m goes around a centre piece that itself stands on a carrier (so m goes on that carrier too)."""
    return m.around is not None and m.on is None and mentions[m.around].on is not None
