"""How many of each mention: the counts the words say, and the ones they leave open (plurals, "a few", stacks)."""

from __future__ import annotations

from physcensis.agent.base import AgentContext
from physcensis.agent.planning.state import PlanState, choice_key
from physcensis.agent.planning.variants import Variants, area, named_by
from physcensis.agent.reading import NUMERALS, Mention, SceneRequest
from physcensis.assets.model import Asset

# How a loose count may be read ("a few": two to four).
LOOSE_RANGES = {"few": (2, 4), "several": (3, 6)}


class Counts:
    """Sets the counts (and row sizes) of a plan's mentions that the words leave open, from the room they have."""

    def __init__(self, state: PlanState, variants: Variants) -> None:
        self.state = state
        self.variants = variants

    def vary(self, mentions: list[Mention]) -> None:
        """Counts said loosely ("a few", "several") and stacks of no said height are drawn from a typical range;
        numbers said stay exact."""
        draws = self.state.draws
        for m in mentions:
            if m.loose is not None and m.explicit_count and not m.sizes:
                low, high = LOOSE_RANGES[m.loose]
                m.count = draws.count(m.count, low, high + (2 if draws.wide else 0), "loose", *choice_key(m))
            elif m.stacked and not m.sizes and not m.explicit_count and m.per is None:
                high = 6 if draws.wide else 5
                m.count = draws.count(m.count, 2 if draws.wide else 3, high, "stack", *choice_key(m))

    def resolve(self, mentions: list[Mention], context: AgentContext) -> None:
        """Plurals the prompt gives no number for fill the room they have: a row fills the support's width, things
        on a carrier cover part of it, loose things share the support (a container's contents are sized when they are
        placed, stacks by the reading)."""
        for m in mentions:  # "five books between a pair of bookends": a row of them standing
            if m.side == "between" and m.count > 1 and m.beside is not None and not m.stacked:
                self.stand_upright(m)
        held = {j for m in mentions for j in m.contents}
        paired = {m.per for m in mentions if m.per is not None}
        loose = max(1, sum(1 for k, m in enumerate(mentions) if m.on is None and k not in held))
        for k, m in enumerate(mentions):
            if not m.plural or m.explicit_count or k in held or k in paired or m.per is not None or m.stacked:
                continue
            asset = self.variants.assets(m)[0]
            if m.on is not None:
                self._cover_carrier(m, asset, self.variants.assets(mentions[m.on])[0])
            elif m.arrangement in ("row", "column"):
                self.fill_rows(m, asset, context, self.width_of_others(mentions, k, held))
            elif m.least and self._stands_in_rows(m, self.variants.canonical_first(m), context, loose):
                self.fill_rows(m, self.variants.assets(m)[0], context, self.width_of_others(mentions, k, held))
            else:
                self._share_support(m, asset, context, loose)

    def _cover_carrier(self, m: Mention, asset: Asset, carrier: Asset) -> None:
        """Things on a carrier cover part of it ("a tray with lots of cups": as many as most of it holds)."""
        draws = self.state.draws
        share = carrier.size[0] * carrier.size[1] / area(asset)
        m.count = _clamp(0.5 * share, 2, 6)
        most = 8 if draws.wide else 6
        high = max(m.count, min(most, int(draws.spread(0.6) * share)))
        m.count = draws.count(m.count, self._fewest(m.count), high, "plural", *choice_key(m))
        if m.least:
            room = int(0.8 * carrier.size[0] * carrier.size[1] / area(asset))
            m.count = max(1, min(max(m.count, m.least), room))

    def _share_support(self, m: Mention, asset: Asset, context: AgentContext, loose: int) -> None:
        """Loose things share the support: a quarter of it canonically; "lots of", "everywhere", "packed tightly":
        more, as far as half the support holds."""
        draws = self.state.draws
        key = ("plural", *choice_key(m))
        hx, hy = context.support.half_extents
        share = hx * hy / loose / area(asset)
        m.count = _clamp(share, 2, 4)
        most = 8 if draws.wide else 5
        high = max(m.count, min(most, int(draws.spread(1.0) * share)))
        m.count = draws.count(m.count, self._fewest(m.count), high, *key)
        if m.least:
            top = int(2 * hx * hy / loose / area(asset))
            m.count = max(1, min(max(m.count, m.least), top))
            m.count = draws.count(m.count, m.count, min(top, m.count + 3), "least", *key)

    def _fewest(self, canonical: int) -> int:
        """The fewest of a bare plural a draw may give: one less than the room suggests, but never below three when the
        room suggests three or more ("a pantry shelf with cans" is not two cans); any plural, 2, when wide."""
        return 2 if self.state.draws.wide else min(canonical, max(3, canonical - 1))

    def _stands_in_rows(self, m: Mention, asset: Asset, context: AgentContext, loose: int) -> bool:
        """ "a shelf full of books": when many are asked for and lying they would not fit, things that also stand
        upright (books, binders, records) stand in a row instead; m then names the upright variants."""
        hx, hy = context.support.half_extents
        if 2 * hx * hy / loose / area(asset) >= m.least or not self.stand_upright(m):
            return False
        m.arrangement = "row"
        return True

    def stand_upright(self, m: Mention) -> bool:
        """Name the upright variants of m's things when the catalogue has some (books, binders, records): whether
        they now stand."""
        if "upright" in m.adjectives:
            return False
        variants = self.state.catalogue.variants(" ".join([*m.adjectives, m.phrase]))
        if not any(a.category == m.category and "upright" in f"{a.kind} {a.description}" for a in variants):
            return False
        m.adjectives = (*m.adjectives, "upright")
        return True

    def width_of_others(self, mentions: list[Mention], k: int, held: set[int]) -> float:
        """How much of the support's width the other free-standing things take (side by side with a row)."""
        others = [o for j, o in enumerate(mentions) if j != k and j not in held and o.on is None and o.per is None]
        # held: the contents of containers, and any other mention the caller leaves out
        return sum(self.variants.assets(o)[0].size[1] * (1 if o.stacked else o.count) + 0.03 for o in others)

    def fill_rows(self, m: Mention, asset: Asset, context: AgentContext, taken: float = 0.0) -> None:
        """As many per row as the support's width holds (capped), less what the other things take, in the rows
        asked for."""
        draws = self.state.draws
        hx, hy = context.support.half_extents
        gap = self.state.gap(m)
        across = 2 * hx if m.arrangement == "column" else max(hy, 2 * hy - taken)
        along = asset.size[0] if m.arrangement == "column" else asset.size[1]
        low = 0.9 if m.least else 0.9 - draws.spread(0.25)  # "full of": full, whatever the seed
        filled = draws.uniform(0.9, low, 0.9, "row fill", *choice_key(m))
        per_row = _clamp((filled * across + gap) / (along + gap), 2, 12)
        groups = max(1, m.groups)
        if m.arrangement == "column":  # the width decides how many columns; each column as long as asked
            m.sizes = (max(2, min(per_row, 4)),) * per_row if not m.groups else (per_row,) * groups
        else:
            m.sizes = (per_row,) * groups
        m.count = sum(m.sizes)


def first_mentions(mentions: list[Mention], max_objects: int) -> list[Mention]:
    """The mentions a plan needs at most: once their counts pass twice the object limit the rest are left (the plan
    is cut exactly at the limit later), so a huge prompt is not planned in full. A kept mention's links to a left
    one are dropped."""
    total, keep = 0, len(mentions)
    for k, m in enumerate(mentions):
        total += max(1, m.count, m.least)
        if total > 2 * max_objects:
            keep = k + 1
            break
    if keep == len(mentions):
        return mentions
    kept = mentions[:keep]
    for m in kept:
        m.contents = [j for j in m.contents if j < keep]
        for name in ("on", "beside", "around", "per", "held_by", "alias"):
            index = getattr(m, name)
            if index is not None and index >= keep:
                setattr(m, name, None)
    return kept


def asked_counts(request: SceneRequest, state: PlanState) -> dict[str, int]:
    """The fewest of each category the request asks for (`OfflinePlanner.requested` says how they are read)."""
    asked: dict[str, int] = {}
    for m in request.mentions:
        if m.alias is not None:
            continue
        said = any(t.isdigit() or t in NUMERALS for t in request.tokens[m.start : m.end + 4])
        if m.loose is not None:
            least = LOOSE_RANGES[m.loose][0]
        elif m.explicit_count and (said or not m.stacked):  # "a stack of plates" said no height
            least = m.count
        else:  # "some pens", "a stack of plates", "toys everywhere": two
            least = 2 if m.plural or m.stacked or m.least else 1
        category = _filed_under(m, state)
        asked[category] = max(asked.get(category, 0), least)
    return asked


def _filed_under(m: Mention, state: PlanState) -> str:
    """The category the catalogue files the mention's words under ("a toothbrush cup": cup) when its noun names
    that asset, as the planner draws its variants; else the reading's ("two empty glasses": the best hit, an empty
    french press, is not a glass)."""
    if not m.known:
        return m.category
    hits = state.catalogue.hits(" ".join([*m.adjectives, m.phrase]), 1)
    if not hits:
        return m.category
    asset = state.catalogue.get(hits[0].asset_id)
    return asset.category if named_by(asset, m.phrase) else m.category


def _clamp(value: float, low: int, high: int) -> int:
    return max(low, min(high, int(value)))
