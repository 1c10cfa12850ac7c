"""Which asset variants stand for a mention: those its words name, that fit where it goes, in a seeded order.

The narrowing itself is in agent/choosing.py; here it is applied to the mentions of one plan (a container to what
goes in it, contents to their container, a carrier to what rests on it) and the seed's choices are drawn.
"""

from __future__ import annotations

from collections.abc import Callable

from physcensis.agent import choosing
from physcensis.agent.planning.state import PlanState, choice_key, row_lengths
from physcensis.agent.reading import Mention
from physcensis.assets.model import Asset
from physcensis.assets.text import lemma

CANONICAL_POOL, VARIETY_POOL = 8, 24  # how many retrieval hits of a noun's category the variants are chosen from
ROOMY = 0.9  # a drawn container or carrier has at least this share of the canonical one's room
VARIETY_CLOSE = 0.6  # with variety, hits scoring at least this share of the best ("open shipping box": no toolbox)
# Words that ask for things of several kinds ("assorted mugs", "boxes of different sizes").
ASSORTED = frozenset({"assorted", "different", "various", "mixed", "mismatched", "varied", "odd"})


class Variants:
    """The variants of the plan's mentions, and the description each of their objects is written with."""

    def __init__(self, state: PlanState) -> None:
        self.state = state

    def assets(self, m: Mention) -> list[Asset]:
        """The variants of m's category that its words name and that fit the support (agent/choosing.py); for a
        container those that hold what goes in it first, for what goes in a container those that fit it."""
        mentions = self.state.mentions
        variants = self._fitting_variants(m)
        if m.contents and any(a.cavity is not None for a in variants):
            return self._as_roomy(m, choosing.containers_for(variants, self._contents_of(m)), choosing.capacity)
        if any(o.on is not None and mentions[o.on] is m for o in mentions):  # a carrier: as large a top
            variants = self._as_roomy(m, variants, lambda a: a.size[0] * a.size[1])
        holder = self._container_of(m)
        container = self.assets(holder)[0] if holder is not None else None
        if holder is None or container is None or container.cavity is None:
            return variants
        share = 1 / max(1, len(holder.contents))
        count = m.count if m.explicit_count else 1
        contents = choosing.contents_for(variants, container, count, share)
        fit = [a for a in contents if choosing.room_for(container, a, share) >= count]
        return [*self.state.draws.order(fit, "contents", *choice_key(m)), *contents[len(fit) :]]

    def canonical_first(self, m: Mention) -> Asset:
        """m's first variant in the catalogue's order, for choices of structure (a row of upright books or a pile,
        not which book), which a drawn variant must not decide."""
        with self.state.canonically():
            return self.assets(m)[0]

    def describe(self, m: Mention, k: int) -> tuple[str, Asset]:
        """A description that retrieval maps back to one of the matching assets (variety by k; one variant for all of
        a stack of things that stack, wherever they are placed)."""
        catalogue = self.state.catalogue
        variants = self.assets(m)
        levels = max(m.sizes) if m.sizes else m.count
        if m.stacked and choosing.stacks_well(stacked := choosing.stack_choice(variants, levels, self.state.room)):
            variants = [stacked]
        else:
            variants = self._kinds(m, variants)
        asset = variants[self._kind_at(m, k // 2 if self._in_pairs(m) else k, len(variants))]
        if catalogue.resolve(asset.description).category == asset.category:
            return asset.description, asset
        plain = " ".join([*m.adjectives, m.phrase])
        return f"a {plain}", catalogue.resolve(f"a {plain}")

    def assorted(self, m: Mention) -> bool:
        """Whether the words around m ask for things that differ ("assorted mugs", "gift boxes of different sizes")."""
        return bool(ASSORTED & {*m.adjectives, *self.state.tokens[m.start : m.end + 4]})

    def _as_roomy(self, m: Mention, drawn: list[Asset], room: Callable[[Asset], float]) -> list[Asset]:
        """The drawn containers (or carriers) with at least nine tenths of the room of the canonical one first: what
        goes in or on them must still fit as the words ask ("a bucket of five tennis balls" in a small sand bucket held
        two)."""
        if self.state.draws.canonical("variants", *choice_key(m)) or not drawn:
            return drawn
        least = ROOMY * room(self.canonical_first(m))
        return [a for a in drawn if room(a) >= least] + [a for a in drawn if room(a) < least]

    def _fitting_variants(self, m: Mention) -> list[Asset]:
        """The catalogue's variants for m, narrowed to those its words name, those that fit the support first (a row
        or stacks side by side share its width; all under the next shelf board)."""
        state = self.state
        description = " ".join([*m.adjectives, m.phrase])
        # a noun no catalogue name covers ("a label maker") takes retrieval's confident match or its fallback, never
        # a category that shares a word with it (a waffle maker)
        # with variety, any variant of the noun that retrieval finds nearly as good as the best may stand for it
        canonical = state.draws.canonical("variants", *choice_key(m))
        pool, close = (CANONICAL_POOL, 0.0) if canonical else (VARIETY_POOL, VARIETY_CLOSE)
        variants = (state.catalogue.variants(description, pool, close=close) if m.known else []) or [
            state.catalogue.resolve(description)
        ]
        if m.known and not any(named_by(a, m.phrase) for a in variants):
            # the words found an asset that the noun does not name ("a soup pot": a soup ladle); the noun decides
            named = state.catalogue.variants(m.category, pool, close=close)
            variants = [a for a in named if a.category == m.category] or variants
        if m.known and m.contents and not any(a.cavity is not None for a in variants):
            # a holder of things: the open variants of its noun, however far down retrieval ranks them ("a small box
            # holding two wrenches" is no small cereal box)
            wide = state.catalogue.variants(description, pool, close=0.0)
            variants = [a for a in wide if a.cavity is not None and a.category == m.category] or variants
        read = any(o is m for o in state.mentions)  # a mention of this prompt: the words around it count too
        words = choosing.words_of(state.tokens if read else [], m.start, m.end, m.phrase, m.adjectives)
        if read:  # "a bowl of green apples": the words of what it holds are theirs, not the bowl's
            held = [o for o in state.mentions if o.held_by is not None and state.mentions[o.held_by] is m]
            words -= {choosing.base_word(w) for o in held for w in state.tokens[o.start : o.end]}
        variants = choosing.rank_by_words(variants, words)
        if state.room is None:
            return variants
        along = len(m.sizes) if m.stacked else max(row_lengths(m), default=1) if m.arrangement == "row" else 1
        gap = state.gap(m)
        fit = choosing.fitting(variants, state.room, max(1, along), gap)
        return self._drawn_variants(fit, m, max(1, along), gap)

    def _drawn_variants(self, fit: list[Asset], m: Mention, along: int = 1, gap: float = 0.0) -> list[Asset]:
        """The variants in a seeded order: any of them may stand for the mention, those that fit the support as they
        stand more often than those that must turn, a user library's before the built-in ones (a user who brings a
        bin means that bin); the canonical order without variety, or when none fits."""
        draws, room = self.state.draws, self.state.room
        own = [a for a in fit if a.source != "builtin"]  # the user's own objects, when they fit, before ours
        if own and len(own) < len(fit) and not draws.canonical("variants", *choice_key(m)):
            rest = [a for a in fit if a.source == "builtin"]
            return self._drawn_variants(own, m, along, gap) + self._drawn_variants(rest, m, along, gap)
        if room is None:
            return draws.order(fit, "variants", *choice_key(m))
        tiers = [choosing.fit_tier(a, room, along, gap) % 3 for a in fit]
        if any(t == 2 for t in tiers):  # nothing fits: smallest first, as fitting() ordered them
            return fit
        return draws.order(fit, "variants", *choice_key(m), weights=[1.0 if t == 0 else 0.5 for t in tiers])

    def _contents_of(self, m: Mention) -> list[tuple[Asset, int]]:
        """What goes into container m: for each of its contents a typical variant, and how many."""
        mentions = self.state.mentions
        items = [mentions[j] for j in m.contents if j < len(mentions)]
        return [(choosing.typical(self._fitting_variants(i)), i.count if i.explicit_count else 1) for i in items]

    def _container_of(self, m: Mention) -> Mention | None:
        """The container m is dropped into (None for what rests on something, or is in nothing)."""
        mentions = self.state.mentions
        k = next((n for n, o in enumerate(mentions) if o is m), None)
        if k is None or m.on is not None:
            return None
        return next((o for o in mentions if k in o.contents), None)

    def _kinds(self, m: Mention, variants: list[Asset]) -> list[Asset]:
        """The variants m's things take in turn: every one canonically, and when the words ask for assorted things
        ("boxes of different sizes"); with variety, a drawn number of the first ones (five matching wine glasses, or
        mugs of two kinds)."""
        draws = self.state.draws
        if len(variants) < 2 or self.assorted(m) or draws.canonical("kinds", *choice_key(m)):
            return variants
        things = m.count // 2 if self._in_pairs(m) else m.count
        return variants[: draws.count(len(variants), 1, min(len(variants), max(1, things)), "kinds", *choice_key(m))]

    def _kind_at(self, m: Mention, slot: int, kinds: int) -> int:
        """Which of m's kinds its slot-th thing takes: in turn canonically; with variety, each kind a drawn share (at
        least one) in a drawn order: a dozen tennis balls of two kinds may be nine and three, and a line of jars of
        three kinds is not always paprika, pepper, salt, paprika, ... Assorted things keep equal shares."""
        if kinds < 2:
            return 0
        things = max(1, m.count // 2 if self._in_pairs(m) else m.count)
        if slot >= things:
            return slot % kinds
        return self._turns(m, things, kinds)[slot]

    def _turns(self, m: Mention, things: int, kinds: int) -> list[int]:
        draws = self.state.draws
        key = choice_key(m)
        if kinds > things or self.assorted(m) or draws.canonical("shares", *key):
            shares = [i % kinds for i in range(things)]
        else:  # kinds - 1 cuts among the things' things - 1 gaps: every split into kinds parts equally likely
            cuts = sorted(draws.order(range(1, things), "shares", *key)[: kinds - 1])
            bounds = [0, *cuts, things]
            shares = [kind for kind in range(kinds) for _ in range(bounds[kind + 1] - bounds[kind])]
        return draws.order(shares, "sequence", *key)

    def _in_pairs(self, m: Mention) -> bool:
        """ "a pair of chopsticks": two things that match, where one asset is one of the pair (a pair of slippers is
        one asset, and counts as one)."""
        pair = "pair" in " ".join(self.state.tokens[m.start : m.end])
        return pair and "pair" not in self.canonical_first(m).description


def area(asset: Asset) -> float:
    return max(1e-4, asset.size[0] * asset.size[1])


def named_by(asset: Asset, phrase: str) -> bool:
    """Whether one of the asset's names (category, kind, synonyms) holds the phrase's noun ("tumbler" names a glass
    tumbler; "pot" no soup ladle)."""
    words = phrase.split()
    head = lemma(words[-1]) if words else ""
    return any(head in {lemma(w) for w in name.split()} for name in asset.names)
