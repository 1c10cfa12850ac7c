"""The offline planner: a deterministic agent that writes predicate programs from a prompt, no network.

It reads the prompt (agent/reading.py), lays out the larger objects on the support
with spatial predicates, builds place settings as a GROUP copied per diner, stacks
as PLACE-ON chains, contents as PLACE-IN and the rest as PLACE-ANYWHERE. Given
feedback it drops or frees what failed, and when asked to enrich it adds objects
that suit the scene.
"""

from __future__ import annotations

import contextlib
import json
import math
import re
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from physcensis.agent import choosing
from physcensis.agent.base import AgentContext
from physcensis.agent.choosing import Room
from physcensis.agent.reading import NUMERALS, Lexicon, Mention, SceneRequest, read_prompt
from physcensis.agent.repair import failure_reasons, repair_program, waited_only, within_objects
from physcensis.agent.variety import DEFAULT_VARIETY, NO_VARIETY, Draws, Variety, parse_variety
from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.assets.model import Asset
from physcensis.assets.supports import SHELF_SPACING
from physcensis.program import PREDICATES, parse_program
from physcensis.program.registry import PlacementKind, placement_spec, registered
from physcensis.viewpoint import frame_side

# The predicates the plans are written with, from the registry: the placements by their kind, the others checked to
# be registered (a predicate renamed there fails here, at import, not in a plan).
PLACE_ON_BASE, PLACE_ON, PLACE_IN, PLACE_ANYWHERE = (
    placement_spec(kind).name
    for kind in (PlacementKind.BASE, PlacementKind.ON, PlacementKind.IN, PlacementKind.ANYWHERE)
)
(
    ALIGN_BACK,
    ALIGN_CENTER_FB,
    ALIGN_CENTER_LR,
    ALIGN_LEFT,
    ALIGN_RIGHT,
    BACK_OF,
    COPY_GROUP,
    FACING_BACK,
    FACING_FRONT,
    FACING_LEFT,
    FACING_RIGHT,
    FACING_SAME_AS,
    FACING_TO,
    FRONT_OF,
    GROUP,
    LEFT_OF,
    ORIENT_BY_RELATIVE_SIDE,
    RANDOM_ROT,
    RIGHT_OF,
    SYMMETRY_ALONG,
) = registered(
    "ALIGN-BACK",
    "ALIGN-CENTER-FB",
    "ALIGN-CENTER-LR",
    "ALIGN-LEFT",
    "ALIGN-RIGHT",
    "BACK-OF",
    "COPY-GROUP",
    "FACING-BACK",
    "FACING-FRONT",
    "FACING-LEFT",
    "FACING-RIGHT",
    "FACING-SAME-AS",
    "FACING-TO",
    "FRONT-OF",
    "GROUP",
    "LEFT-OF",
    "ORIENT-BY-RELATIVE-SIDE",
    "RANDOM-ROT",
    "RIGHT-OF",
    "SYMMETRY-ALONG",
)


Entry = list[Any]
SETTING_ITEMS = ("plate", "fork", "knife", "spoon", "cup", "glass", "wine glass", "napkin")
FILLERS = {
    "desk": [
        "pen",
        "notebook",
        "mug",
        "phone",
        "book lying flat",
        "pencil",
        "pencil case",
        "potted plant",
        "glass",
        "apple",
    ],
    "dining": ["napkin", "candle", "glass", "bowl", "vase", "bread", "pitcher", "spoon"],
    "kitchen": ["jar", "bottle", "bowl", "spoon", "can", "cutting board", "mug", "apple", "orange", "plate"],
    "bathroom": ["bottle", "towel", "cup", "soap dispenser", "toothbrush", "jar"],
    "shelf": ["book standing upright", "jar", "can", "box", "bottle", "potted plant", "vase"],
    "floor": ["toy block", "ball", "stuffed animal", "toy truck", "book lying flat", "basket"],
    "everyday": [
        "mug",
        "book lying flat",
        "phone",
        "can",
        "apple",
        "jar",
        "bottle",
        "notebook",
        "pen",
        "glass",
        "plate",
        "bowl",
        "box",
        "candle",
        "orange",
        "banana",
        "tape measure",
        "toy block",
        "cup",
        "napkin",
        "spoon",
        "potted plant",
        "screwdriver",
        "pencil",
    ],
}
# Words that name a kind of scene or a support: a prompt with one of them and no object gets that kind's typical scene.
SCENE_KINDS = frozenset(
    """table desk counter countertop worktop workbench nightstand shelf bookshelf bookcase cabinet cupboard dresser
    sideboard windowsill vanity floor room kitchen bathroom bedroom office pantry garage playroom nursery
    tabletop island dinner dining breakfast lunch picnic meal party study student tea""".split()
)
DEFAULT_SCENES = {
    "desk": ["laptop", "notebook", "pen", "pencil", "mug", "phone", "book lying flat", "pencil case"],
    "everyday": ["mug", "book lying flat", "phone", "apple", "bottle", "notebook"],
}
ENRICH_PER_ROUND = 4
# Objects that belong to a kind of scene without being asked for; with variety a few may be added (`added`).
CONTEXT = {
    "dining": ["vase", "napkin", "salt shaker", "candle", "bread", "pitcher", "bowl"],
    "desk": ["potted plant", "mug", "pen", "notebook", "desk lamp", "glass"],
    "kitchen": ["jar", "olive oil bottle", "cutting board", "bowl", "apple", "mug"],
    "bathroom": ["towel", "soap dispenser", "cup", "bottle"],
}  # only scenes the prompt's words name: "a gizmo and two mugs" gets nothing it did not ask for
# How a loose count may be read ("a few": two to four), and what a place setting's pieces are looked up as.
LOOSE_RANGES = {"few": (2, 4), "several": (3, 6)}
BOOK_ROW_LEAST = 8  # books a drawn row of no said count keeps even on a crowded shelf
CANONICAL_POOL, VARIETY_POOL = 8, 24  # how many retrieval hits of a noun's category the variants are chosen from
# The choices of where things stand, which a redraw after a failure takes from the canonical scene.
LAYOUT_CHOICES = frozenset(
    {"gap", "row fill", "spots", "spot", "turn", "side", "beside", "stacks", "monitor", "keyboard"}
    | {"mouse", "ring", "book row", "pile x", "pile y", "seats", "first seat", "inset", "along", "slide"}
)
# Words that ask for things of several kinds ("assorted mugs", "boxes of different sizes").
ASSORTED = frozenset({"assorted", "different", "various", "mixed", "mismatched", "varied", "odd"})
# Things a stack of which is one kind whatever the seed: a stack of plates is a set.
MATCHED = frozenset({"plate", "saucer", "dish", "bowl", "cup", "mug", "glass", "tray", "coaster", "napkin"})
DRAWN_ROUNDS = 2  # a run's first program and, when it failed, one drawn afresh
ROOMY = 0.9  # a drawn container or carrier has at least this share of the canonical one's room
VARIETY_CLOSE = 0.6  # with variety, hits scoring at least this share of the best ("open shipping box": no toolbox)
SETTING_NAMES = {"plate": "dinner plate", "fork": "fork", "knife": "table knife", "spoon": "spoon"}
NOT_AT_TABLE = frozenset(
    {"paper", "plastic", "toothbrush", "chef", "paring", "bread", "measuring", "wooden", "baby", "serving", "toy"}
)


@dataclass
class _Plan:
    anchors: list[Entry] = field(default_factory=list)  # spatial entries
    physical: list[Entry] = field(default_factory=list)  # PLACE-ON / PLACE-IN
    free: list[Entry] = field(default_factory=list)  # PLACE-ANYWHERE
    used: set[str] = field(default_factory=set)

    def new_id(self, category: str) -> str:
        slug = re.sub(r"[^a-z0-9]+", "_", category.lower()).strip("_") or "object"
        k = 0
        while f"{slug}_{k}" in self.used:
            k += 1
        self.used.add(f"{slug}_{k}")
        return f"{slug}_{k}"

    def program(self) -> list[Entry]:
        return [*self.anchors, *self.physical, *self.free]


class OfflinePlanner:
    """The default agent: reads the prompt, writes a program, reacts to feedback. Every choice the prompt leaves
    open (which variant, how many of a vague plural, where a group stands, which end a place setting takes, context
    objects) is drawn from `seed` at the `variety` level (agent/variety.py): the same prompt, seed and variety give
    the same program; `variety="none"` gives the canonical one. `context` (default: on when variety is) lets it add
    a few objects that belong to the kind of scene; they are listed in `added`."""

    name = "offline-planner"

    def __init__(
        self,
        catalogue: Catalogue | None = None,
        seed: int = 0,
        variety: str | Variety = DEFAULT_VARIETY,
        context: bool | None = None,
    ) -> None:
        self.catalogue = catalogue or default_catalogue()
        self.lexicon = Lexicon(self.catalogue)
        self.seed = seed
        self.draws = Draws(parse_variety(variety), seed)
        self.context = self.draws.on if context is None else context
        self.added: list[dict[str, str]] = []  # objects the prompt did not name: id, category, why
        self._height_limit: float | None = None
        self._room: Room | None = None  # the support of the plan being written, for choosing variants that fit
        self._tokens: list[str] = []  # its prompt's words
        self._lone = False  # whether the prompt's things make one group on the support
        self._owners: dict[str, list[tuple[object, ...]]] = {}  # object id -> keys of its mention and those around it
        self._mentions: list[Mention] = []  # and its mentions
        self.transcript_notes: list[str] = []  # said to the user in the run's transcript (contents not held)

    # -- the agent interface -------------------------------------------------------------------
    def propose(self, context: AgentContext) -> str:
        self.seed = context.seed  # the run's seed draws the open choices (one planner may serve many runs)
        self.draws = Draws(self.draws.level, context.seed)
        if context.request == "create" or not context.history:
            program = self.plan(context)
        elif context.request == "repair" and self._redraw_due(context):
            program = self._redraw(context)
        else:
            previous = _entries(context.history[-1].program_text)
            if context.request == "repair":
                program = self.repair(previous, context)
            else:  # "enrich", and "revise": the planner cannot see the picture; a richer scene is its one move
                program = self.enrich(previous, context)
        return json.dumps(program)

    @property
    def open_choices(self) -> int:
        """How many choices of assets and counts the last program drew from (where it stands left out): 1 when the
        words and the catalogue left none open ("a dozen tennis balls" with one tennis ball)."""
        return self.draws.open_choices(LAYOUT_CHOICES | {"spots", "enrich"})

    @property
    def redraws(self) -> int:
        """How many more programs a run of this planner may try before its repairs: a drawn first program that fails
        is drawn afresh once, then drawn with the failed things canonical (the loop adds them to its retries)."""
        return 1 if self.draws.on else 0

    def _failed_only_as_drawn(self, context: AgentContext) -> set[str]:
        """What failed only in the drawn programs of a run that was drawn again (the first and the fresh draw): the
        canonical redraw put it back as the canonical scene has it, so the repair starts afresh with it (frees it
        before it shrinks or drops it)."""
        history = context.history
        if not self.draws.on or len(history) < 2 or history[0].ok:
            return set()
        drawn = history[: min(DRAWN_ROUNDS, len(history) - 1)]
        later = {oid for r in history[len(drawn) : -1] for oid in failure_reasons(r.feedback)}
        return {oid for r in drawn for oid in failure_reasons(r.feedback)} - later

    def _redraw_due(self, context: AgentContext) -> bool:
        """Whether every program so far was drawn and failed: then it is drawn again rather than anything dropped
        (even when both drawn programs failed on the same kinds of thing: repairing the fresh draw then left a
        ladle beside the pot it was asked in, where the canonical choices hold it)."""
        history = context.history
        return self.draws.on and len(history) <= DRAWN_ROUNDS and not any(r.ok for r in history)

    def _redraw(self, context: AgentContext) -> list[Entry]:
        """After the first program failed, every choice drawn afresh (another scene of the same prompt). After that
        failed too, the program drawn again with the failed objects' mentions as the canonical scene has them
        (variant, count) and the canonical layout (spots, sides, gaps: what failed may have been crowded by its
        neighbours, and the canonical scene is the one known to hold: keeping the drawn layout when only contents
        failed left fruit-bowl's fruit out of its bowl in 2 of 20 seeds); a failure that belongs to no mention (a
        place setting's piece) redraws the whole scene canonically, and a context object that failed is left out. The
        usual repair when that changes nothing."""
        failed = set(filter(None, context.notes.get("failed", "").split(",")))
        added = {row["id"] for row in self.added}
        fresh = len(context.history) == 1
        keys = {key for oid in failed if oid in self._owners for key in self._owners[oid]}
        whole = any(oid not in self._owners and oid not in added for oid in failed) or not failed
        level = Variety.NONE if whole and not fresh else self.draws.level
        if fresh:
            self.draws = Draws(level, context.seed, attempt=1)
        else:
            self.draws = Draws(level, context.seed, frozenset(keys), LAYOUT_CHOICES, attempt=1)
        wanted = self.context
        self.context = self.context and not failed & added
        try:
            program = self.plan(context)
        finally:
            self.context = wanted
        previous = _entries(context.history[-1].program_text)
        if program == previous:
            return self.repair(previous, context)
        if fresh:
            self.transcript_notes.append("variety: the first draw failed; every choice drawn afresh")
        else:
            which = "the whole scene" if whole else ", ".join(sorted(failed))
            self.transcript_notes.append(f"variety: drawn again with the canonical choices for {which}")
        return program

    # -- first program -----------------------------------------------------------------------------
    def plan(self, context: AgentContext) -> list[Entry]:
        request = read_prompt(context.prompt, self.lexicon)
        kind = context.support.kind
        self._height_limit = SHELF_SPACING - 0.05 if kind == "shelf" else None
        plan = _Plan()
        mentions = _first_mentions(self._mentions_or_default_scene(request, kind), context.max_objects)
        self._room = Room(float(context.support.size[0]), float(context.support.size[1]), self._height_limit)
        self._tokens, self._mentions = request.tokens, mentions
        self.added = []
        self._vary_counts(mentions)
        self._resolve_counts(mentions, context)
        consumed: set[int] = set()
        if request.diners:
            consumed = self._place_settings(plan, request, mentions, context)
        ids: dict[int, list[str]] = {}
        anchors = [
            k for k, m in enumerate(mentions) if k not in consumed and self._is_anchor(k, m, mentions, request, kind)
        ]
        self._layout_anchors(plan, anchors, mentions, ids, request, context)
        self._place_the_rest(plan, mentions, consumed, ids, request)
        self._owners = {oid: self._related(k) for k, oids in ids.items() for oid in oids}
        if not request.mentions and not request.diners:  # the whole scene is the planner's, said as such
            why = f"the prompt names no object: a typical {_scene_type(request, kind)} scene"
            self.added += [{"id": oid, "category": mentions[k].category, "why": why} for k in ids for oid in ids[k]]
        if request.dense and request.mentions:
            for name in FILLERS["everyday"][:12]:
                self._add_free(plan, name, request)
        if self.context and (request.mentions or request.diners) and not request.dense:
            self._add_context(plan, request, mentions, _scene_type(request, kind))
        return self._within_limit(plan.program(), context)

    def _within_limit(self, program: list[Entry], context: AgentContext) -> list[Entry]:
        """The program cut to the run's object limit (its last objects dropped), said in a note to the user."""
        kept, dropped = within_objects(program, context.support, context.max_objects)
        if dropped:
            self.added = [row for row in self.added if row["id"] not in dropped]
            note = (
                f"max-objects: the prompt asks for more than {context.max_objects} objects; the last {len(dropped)} "
                f"were left out ({_listed(dropped)}); raise --max-objects to keep them"
            )
            if note not in self.transcript_notes:
                self.transcript_notes.append(note)
        return kept

    def _add_context(self, plan: _Plan, request: SceneRequest, mentions: list[Mention], scene_type: str) -> None:
        """A few objects that belong to this kind of scene and that the prompt did not name (a vase or a salt shaker
        on a dining table), drawn from the seed; each is recorded in `added`."""
        named = {m.category for m in mentions}
        choices = [n for n in CONTEXT.get(scene_type, ()) if self._category(n) not in named]
        most = 3 if self.draws.wide else 2
        count = self.draws.count(0, 0, most, "context", "count") if self.draws.chance(0.7, "context") else 0
        for name in self.draws.order(choices, "context", "names")[:count]:
            oid = self._add_free(plan, name, request)
            self.added.append({"id": oid, "category": self._category(name), "why": f"context of a {scene_type} scene"})

    def _related(self, k: int) -> list[tuple[object, ...]]:
        """The keys of mention k, of what holds or carries it and of everything else in or on that (a spoon dropped
        into a bowl that chopsticks lie across): a redraw after k failed takes all of them canonical."""
        m = self._mentions[k]
        holder = m.on if m.on is not None else next((j for j, o in enumerate(self._mentions) if k in o.contents), None)
        group = {k} if holder is None else {holder, *self._mentions[holder].contents}
        if holder is not None:
            group |= {j for j, o in enumerate(self._mentions) if o.on == holder}
        return [self._key(self._mentions[j]) for j in sorted(group) if j < len(self._mentions)]

    @contextmanager
    def _canonically(self) -> Iterator[None]:
        """Within the block, every choice is the canonical one."""
        draws, self.draws = self.draws, NO_VARIETY
        try:
            yield
        finally:
            self.draws = draws

    def _canonical_first(self, m: Mention) -> Asset:
        """m's first variant in the catalogue's order, for choices of structure (a row of upright books or a pile,
        not which book), which a drawn variant must not decide."""
        with self._canonically():
            return self._assets(m)[0]

    def _key(self, m: Mention) -> tuple[object, ...]:
        """What names mention m's choices: the same mention draws the same, whichever call asks."""
        return (m.category, m.phrase, m.start, m.end)

    def _vary_counts(self, mentions: list[Mention]) -> None:
        """Counts said loosely ("a few", "several") and stacks of no said height are drawn from a typical range;
        numbers said stay exact."""
        for m in mentions:
            if m.loose is not None and m.explicit_count and not m.sizes:
                low, high = LOOSE_RANGES[m.loose]
                m.count = self.draws.count(m.count, low, high + (2 if self.draws.wide else 0), "loose", *self._key(m))
            elif m.stacked and not m.sizes and not m.explicit_count and m.per is None:
                high = 6 if self.draws.wide else 5
                m.count = self.draws.count(m.count, 2 if self.draws.wide else 3, high, "stack", *self._key(m))

    def _fewest(self, canonical: int) -> int:
        """The fewest of a bare plural a draw may give: one less than the room suggests, but never below three when the
        room suggests three or more ("a pantry shelf with cans" is not two cans); any plural, 2, when wide."""
        return 2 if self.draws.wide else min(canonical, max(3, canonical - 1))

    def _gap(self, m: Mention) -> float:
        """The gap between neighbours of a row or side-by-side stacks: wider when evenly spaced."""
        if m.spaced:
            return self.draws.uniform(0.06, 0.05, 0.05 + self.draws.spread(0.03), "gap", *self._key(m))
        return self.draws.uniform(0.03, 0.02, 0.02 + self.draws.spread(0.025), "gap", *self._key(m))

    def reads(self, prompt: str) -> bool:
        """Whether the prompt names anything the reading knows: a thing to place, diners, or a kind of scene or
        support ("a tidy desk"). "asdf qwerty", an empty prompt or only symbols name nothing."""
        request = read_prompt(prompt, self.lexicon)
        return bool(request.mentions or request.diners or set(request.tokens) & SCENE_KINDS)

    def requested(self, prompt: str) -> dict[str, int]:
        """What the prompt asks for, per category: a said count ("three mugs": 3), the fewest of a loose one ("a few":
        2), two of a plural or a stack of no said height ("some pens"), else one; the most one mention of a category
        asks for (a second mention may be the same thing: "the monitors"). What a place setting's words ("set for
        four") imply is not counted."""
        asked: dict[str, int] = {}
        request = read_prompt(prompt, self.lexicon)
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
            category = self._category(" ".join([*m.adjectives, m.phrase])) if m.known else m.category
            asked[category] = max(asked.get(category, 0), least)  # as filed ("a toothbrush cup": glass)
        return asked

    def _mentions_or_default_scene(self, request: SceneRequest, kind: str) -> list[Mention]:
        """What the prompt names; for a prompt naming nothing (and no diners) a typical scene of its kind."""
        if request.mentions or request.diners:
            return list(request.mentions)
        names = DEFAULT_SCENES.get(_scene_type(request, kind), DEFAULT_SCENES["everyday"])
        if request.dense:
            names = FILLERS["everyday"][:22]
        return [Mention(self._category(n), 1, n, (), 0, 0, False, False) for n in names]

    def _resolve_counts(self, mentions: list[Mention], context: AgentContext) -> None:
        """Plurals the prompt gives no number for fill the room they have: a row fills the support's width, things
        on a carrier cover part of it, loose things share the support (a container's contents are sized by `_fill`,
        stacks by the reading)."""
        held = {j for m in mentions for j in m.contents}
        paired = {m.per for m in mentions if m.per is not None}
        loose = max(1, sum(1 for k, m in enumerate(mentions) if m.on is None and k not in held))
        for k, m in enumerate(mentions):
            if not m.plural or m.explicit_count or k in held or k in paired or m.per is not None or m.stacked:
                continue
            asset = self._assets(m)[0]
            key = ("plural", *self._key(m))
            if m.on is not None:
                carrier = self._assets(mentions[m.on])[0]
                share = carrier.size[0] * carrier.size[1] / _area(asset)
                m.count = _clamp(0.5 * share, 2, 6)
                most = 8 if self.draws.wide else 6
                high = max(m.count, min(most, int(self.draws.spread(0.6) * share)))
                m.count = self.draws.count(m.count, self._fewest(m.count), high, *key)
                if m.least:  # "a tray with lots of cups": as many as most of the carrier holds
                    room = int(0.8 * carrier.size[0] * carrier.size[1] / _area(asset))
                    m.count = max(1, min(max(m.count, m.least), room))
            elif m.arrangement in ("row", "column"):
                self._fill_rows(m, asset, context, self._width_of_others(mentions, k, held))
            elif m.least and self._stands_in_rows(m, self._canonical_first(m), context, loose):
                self._fill_rows(m, self._assets(m)[0], context, self._width_of_others(mentions, k, held))
            else:
                hx, hy = context.support.half_extents
                share = hx * hy / loose / _area(asset)
                m.count = _clamp(share, 2, 4)  # a quarter of the support, shared
                most = 8 if self.draws.wide else 5
                high = max(m.count, min(most, int(self.draws.spread(1.0) * share)))
                m.count = self.draws.count(m.count, self._fewest(m.count), high, *key)
                if m.least:  # "lots of", "everywhere", "packed tightly": more, as far as half the support holds
                    top = int(2 * hx * hy / loose / _area(asset))
                    m.count = max(1, min(max(m.count, m.least), top))
                    m.count = self.draws.count(m.count, m.count, min(top, m.count + 3), "least", *key)

    def _stands_in_rows(self, m: Mention, asset: Asset, context: AgentContext, loose: int) -> bool:
        """ "a shelf full of books": when many are asked for and lying they would not fit, things that also stand
        upright (books, binders, records) stand in a row instead; m then names the upright variants."""
        hx, hy = context.support.half_extents
        if 2 * hx * hy / loose / _area(asset) >= m.least or "upright" in m.adjectives:
            return False
        variants = self.catalogue.variants(" ".join([*m.adjectives, m.phrase]))
        upright = [a for a in variants if a.category == m.category and "upright" in f"{a.kind} {a.description}"]
        if not upright:
            return False
        m.adjectives = (*m.adjectives, "upright")
        m.arrangement = "row"
        return True

    def _width_of_others(self, mentions: list[Mention], k: int, held: set[int]) -> float:
        """How much of the support's width the other free-standing things take (side by side with a row)."""
        others = [o for j, o in enumerate(mentions) if j != k and j not in held and o.on is None and o.per is None]
        # held: the contents of containers, and any other mention the caller leaves out
        return sum(self._assets(o)[0].size[1] * (1 if o.stacked else o.count) + 0.03 for o in others)

    def _fill_rows(self, m: Mention, asset: Asset, context: AgentContext, taken: float = 0.0) -> None:
        """As many per row as the support's width holds (capped), less what the other things take, in the rows
        asked for."""
        hx, hy = context.support.half_extents
        gap = self._gap(m)
        across = 2 * hx if m.arrangement == "column" else max(hy, 2 * hy - taken)
        along = asset.size[0] if m.arrangement == "column" else asset.size[1]
        low = 0.9 if m.least else 0.9 - self.draws.spread(0.25)  # "full of": full, whatever the seed
        filled = self.draws.uniform(0.9, low, 0.9, "row fill", *self._key(m))
        per_row = _clamp((filled * across + gap) / (along + gap), 2, 12)
        groups = max(1, m.groups)
        if m.arrangement == "column":  # the width decides how many columns; each column as long as asked
            m.sizes = (max(2, min(per_row, 4)),) * per_row if not m.groups else (per_row,) * groups
        else:
            m.sizes = (per_row,) * groups
        m.count = sum(m.sizes)

    def _place_the_rest(
        self, plan: _Plan, mentions: list[Mention], consumed: set[int], ids: dict[int, list[str]], request: SceneRequest
    ) -> None:
        """What the layout left: free-standing mentions anywhere, then what rests on others, then the contents
        of containers."""
        held = {j for m in mentions for j in m.contents}
        for k, m in enumerate(mentions):
            if k not in consumed and k not in ids and m.on is None and k not in held and not _rings_on(m, mentions):
                self._free(plan, k, m, ids, request)
        for k, m in enumerate(mentions):
            if k not in consumed and m.on is not None and k not in ids:
                self._on(plan, k, m, mentions, ids, request)
        for k, m in enumerate(mentions):
            if k not in consumed and k not in ids and _rings_on(m, mentions):
                self._ring_on(plan, k, m, mentions, ids, request)
        for k, m in enumerate(mentions):
            if k not in consumed and m.contents and k in ids:
                self._fill(plan, k, m, mentions, ids, request)

    def _category(self, name: str) -> str:
        hits = self.catalogue.hits(name, 1)
        return self.catalogue.entry(hits[0].asset_id).category if hits else name

    def _assets(self, m: Mention) -> list[Asset]:
        """The variants of m's category that its words name and that fit the support (agent/choosing.py); for a
        container those that hold what goes in it first, for what goes in a container those that fit it."""
        variants = self._fitting_variants(m)
        if m.contents and any(a.cavity is not None for a in variants):
            return self._as_roomy(m, choosing.containers_for(variants, self._contents_of(m)), choosing.capacity)
        if any(o.on is not None and self._mentions[o.on] is m for o in self._mentions):  # a carrier: as large a top
            variants = self._as_roomy(m, variants, lambda a: a.size[0] * a.size[1])
        holder = self._container_of(m)
        container = self._assets(holder)[0] if holder is not None else None
        if holder is None or container is None or container.cavity is None:
            return variants
        share = 1 / max(1, len(holder.contents))
        count = m.count if m.explicit_count else 1
        contents = choosing.contents_for(variants, container, count, share)
        fit = [a for a in contents if choosing.room_for(container, a, share) >= count]
        return [*self.draws.order(fit, "contents", *self._key(m)), *contents[len(fit) :]]

    def _as_roomy(self, m: Mention, drawn: list[Asset], room: Callable[[Asset], float]) -> list[Asset]:
        """The drawn containers (or carriers) with at least nine tenths of the room of the canonical one first: what
        goes in or on them must still fit as the words ask ("a bucket of five tennis balls" in a small sand bucket held
        two)."""
        if self.draws.canonical("variants", *self._key(m)) or not drawn:
            return drawn
        least = ROOMY * room(self._canonical_first(m))
        return [a for a in drawn if room(a) >= least] + [a for a in drawn if room(a) < least]

    def _fitting_variants(self, m: Mention) -> list[Asset]:
        """The catalogue's variants for m, narrowed to those its words name, those that fit the support first (a row
        or stacks side by side share its width; all under the next shelf board)."""
        description = " ".join([*m.adjectives, m.phrase])
        # a noun no catalogue name covers ("a label maker") takes retrieval's confident match or its fallback, never
        # a category that shares a word with it (a waffle maker)
        # with variety, any variant of the noun that retrieval finds nearly as good as the best may stand for it
        canonical = self.draws.canonical("variants", *self._key(m))
        pool, close = (CANONICAL_POOL, 0.0) if canonical else (VARIETY_POOL, VARIETY_CLOSE)
        variants = (self.catalogue.variants(description, pool, close=close) if m.known else []) or [
            self.catalogue.resolve(description)
        ]
        read = any(o is m for o in self._mentions)  # a mention of this prompt: the words around it count too
        words = choosing.words_of(self._tokens if read else [], m.start, m.end, m.phrase, m.adjectives)
        variants = choosing.rank_by_words(variants, words)
        if self._room is None:
            return variants
        along = len(m.sizes) if m.stacked else max(_row_lengths(m), default=1) if m.arrangement == "row" else 1
        gap = self._gap(m)
        fit = choosing.fitting(variants, self._room, max(1, along), gap)
        return self._drawn_variants(fit, m, max(1, along), gap)

    def _drawn_variants(self, fit: list[Asset], m: Mention, along: int = 1, gap: float = 0.0) -> list[Asset]:
        """The variants in a seeded order: any of them may stand for the mention, those that fit the support as they
        stand more often than those that must turn, a user library's before the built-in ones (a user who brings a
        bin means that bin); the canonical order without variety, or when none fits."""
        own = [a for a in fit if a.source != "builtin"]  # the user's own objects, when they fit, before ours
        if own and len(own) < len(fit) and not self.draws.canonical("variants", *self._key(m)):
            rest = [a for a in fit if a.source == "builtin"]
            return self._drawn_variants(own, m, along, gap) + self._drawn_variants(rest, m, along, gap)
        if self._room is None:
            return self.draws.order(fit, "variants", *self._key(m))
        tiers = [choosing.fit_tier(a, self._room, along, gap) % 3 for a in fit]
        if any(t == 2 for t in tiers):  # nothing fits: smallest first, as fitting() ordered them
            return fit
        return self.draws.order(fit, "variants", *self._key(m), weights=[1.0 if t == 0 else 0.5 for t in tiers])

    def _contents_of(self, m: Mention) -> list[tuple[Asset, int]]:
        """What goes into container m: for each of its contents a typical variant, and how many."""
        items = [self._mentions[j] for j in m.contents if j < len(self._mentions)]
        return [(choosing.typical(self._fitting_variants(i)), i.count if i.explicit_count else 1) for i in items]

    def _container_of(self, m: Mention) -> Mention | None:
        """The container m is dropped into (None for what rests on something, or is in nothing)."""
        k = next((n for n, o in enumerate(self._mentions) if o is m), None)
        if k is None or m.on is not None:
            return None
        return next((o for o in self._mentions if k in o.contents), None)

    def _describe(self, m: Mention, k: int) -> tuple[str, Asset]:
        """A description that retrieval maps back to one of the matching assets (variety by k; one variant for all of
        a stack of things that stack, wherever they are placed)."""
        variants = self._assets(m)
        levels = max(m.sizes) if m.sizes else m.count
        if m.stacked and choosing.stacks_well(stacked := choosing.stack_choice(variants, levels, self._room)):
            variants = [stacked]
        else:
            variants = self._kinds(m, variants)
        asset = variants[(k // 2 if self._in_pairs(m) else k) % len(variants)]
        if self.catalogue.resolve(asset.description).category == asset.category:
            return asset.description, asset
        plain = " ".join([*m.adjectives, m.phrase])
        return f"a {plain}", self.catalogue.resolve(f"a {plain}")

    def _kinds(self, m: Mention, variants: list[Asset]) -> list[Asset]:
        """The variants m's things take in turn: every one canonically, and when the words ask for assorted things
        ("boxes of different sizes"); with variety, a drawn number of the first ones (five matching wine glasses, or
        mugs of two kinds)."""
        if len(variants) < 2 or self._assorted(m) or self.draws.canonical("kinds", *self._key(m)):
            return variants
        things = m.count // 2 if self._in_pairs(m) else m.count
        return variants[
            : self.draws.count(len(variants), 1, min(len(variants), max(1, things)), "kinds", *self._key(m))
        ]

    def _assorted(self, m: Mention) -> bool:
        """Whether the words around m ask for things that differ ("assorted mugs", "gift boxes of different sizes")."""
        return bool(ASSORTED & {*m.adjectives, *self._tokens[m.start : m.end + 4]})

    def _in_pairs(self, m: Mention) -> bool:
        """ "a pair of chopsticks": two things that match, where one asset is one of the pair (a pair of slippers is
        one asset, and counts as one)."""
        return "pair" in " ".join(self._tokens[m.start : m.end]) and "pair" not in self._canonical_first(m).description

    def _is_anchor(self, k: int, m: Mention, mentions: list[Mention], request: SceneRequest, kind: str) -> bool:
        if m.on is not None or any(k in o.contents for o in mentions) or _rings_on(m, mentions):
            return False
        if self._pile_is_free(m):
            return False
        if m.stacked or m.contents or m.centre or m.around is not None or m.beside is not None:
            return True
        if m.arrangement in ("row", "column"):
            return True
        if any(k in (o.on, o.beside, o.around) for o in mentions):
            return True
        if kind == "shelf" and "upright" in m.phrase:
            return True
        if request.messy or request.dense or kind in ("floor", "box"):
            return False
        asset = self._assets(m)[0]
        return bool(asset.size[0] * asset.size[1] > 0.03 or request.rows)  # large things get a spot of their own

    # -- layout ------------------------------------------------------------------------------------
    def _layout_anchors(
        self,
        plan: _Plan,
        anchors: list[int],
        mentions: list[Mention],
        ids: dict[int, list[str]],
        request: SceneRequest,
        context: AgentContext,
    ) -> None:
        hx, hy = context.support.half_extents
        upright = [k for k in anchors if "upright" in mentions[k].phrase]
        if upright:
            self._book_row(plan, upright, mentions, ids, context)
        rest = _targets_first([k for k in anchors if k not in upright], mentions)
        office = self._office(plan, rest, mentions, ids)
        spots = iter(self._spots(len(rest), hx, hy))
        self._lone = len(rest) == 1
        centred = any(mentions[k].centre for k in rest)
        ring_centres = {mentions[k].around for k in rest} - {None}
        for k in rest:
            m = mentions[k]
            if k in ids or k in office or (m.around is not None and m.around in ids):
                continue
            spot = _first_spot(m, ids, spots)
            if k in ring_centres and not centred and m.beside is None:
                spot = (0.0, 0.0)  # what others stand around takes the middle
            self._anchor(plan, k, m, spot, ids, request, (hx, hy))
        for k in rest:  # things arranged around a centre piece
            m = mentions[k]
            if m.around is not None and m.around in ids and k not in ids:
                self._ring(plan, k, m, mentions[m.around], ids[m.around][0], ids, (hx, hy))

    def _spots(self, n: int, hx: float, hy: float) -> list[tuple[float, float]]:
        """Where the anchors stand: the grid's spots, with variety in a drawn order, each moved within its cell (a
        lone anchor anywhere in the middle half of the support, not only at its centre)."""
        spots = _grid_spots(n, hx, hy)
        if not self.draws.on or not spots:
            return spots
        rows, cols = _grid_shape(n, hx, hy)
        reach = self.draws.spread(0.35 if n == 1 else 0.25)  # a lone anchor: anywhere in the middle of the support
        cell_x, cell_y = 2 * hx * 0.8 / rows, 2 * hy * 0.8 / cols
        moved = []
        for i, (x, y) in enumerate(self.draws.order(spots, "spots")):
            u, v = self.draws.spread_point("spot", i) or (0.5, 0.5)
            dx, dy = (2 * u - 1) * reach * cell_x, (2 * v - 1) * reach * cell_y
            moved.append((float(np.clip(x + dx, -0.8 * hx, 0.8 * hx)), float(np.clip(y + dy, -0.8 * hy, 0.8 * hy))))
        return moved

    def _facing_entry(self, oid: str, facing: str, asset: Asset) -> Entry:
        """`oid` turned by the yaw rule `facing`; with variety, a thing that has no front (a round tin, a plate) turned
        a little more, as a person sets it down (never what a front faces the way the words say, nor a random turn)."""
        takes_offset = any(p.name == "yaw_offset" for p in PREDICATES[facing].params)
        if self.draws.canonical("turn", oid) or asset.has_front or not takes_offset:
            return [oid, facing, "root", {}]
        reach = math.radians(self.draws.spread(10.0))
        return [oid, facing, "root", {"yaw_offset": round(self.draws.uniform(0.0, -reach, reach, "turn", oid), 3)}]

    def _offset_along(self, canonical: float, *key: object) -> float:
        """A position along the support's width for something the prompt does not place (the monitor of a desk):
        within the middle third with variety."""
        half = (self._room.width / 2 if self._room is not None else 0.3) * self.draws.spread(0.3)
        return round(self.draws.uniform(canonical, canonical - half, canonical + half, *key), 3)

    def _ring_turn(self, m: Mention) -> float:
        """Where a ring of m's objects starts: the canonical angle 0, or any turn up to one step with variety."""
        return self.draws.uniform(0.0, 0.0, 2 * math.pi / max(1, m.count), "ring", *self._key(m))

    def _side(self, m: Mention) -> str:
        """The frame's side for mention m's side word, said as the viewer sees it ("left of" is the frame's right:
        viewpoint.py); "beside" / "next to": right canonically, either with variety."""
        if m.side != "beside":
            return frame_side(m.side)
        return self.draws.pick("right", ["right", "left"], "side", *self._key(m))

    def _distance(self, canonical: float, *key: object) -> float:
        """A gap between two things said to stand near each other: a few centimetres either way with variety."""
        return round(self.draws.uniform(canonical, 0.7 * canonical, canonical + self.draws.spread(0.04), *key), 3)

    def _anchor(
        self,
        plan: _Plan,
        k: int,
        m: Mention,
        spot: tuple[float, float] | None,
        ids: dict[int, list[str]],
        request: SceneRequest,
        half: tuple[float, float],
    ) -> None:
        """Mention k's objects: stacks side by side, or rows (front to back) of objects left to right; the first
        at `spot` (None: where its relation to an earlier object puts it)."""
        ids[k] = []
        if m.stacked:
            self._stacks(plan, k, m, spot, ids, request, half)
            return
        if m.beside is not None and ids.get(m.beside) and (m.side in ("sides", "ends") or m.per == m.beside):
            self._beside_each(plan, k, m, ids, request)
            return
        if m.beside is not None and m.side == "between" and len(ids.get(m.beside, [])) >= 2:
            self._between(plan, k, m, ids, request)
            return
        shape = _row_lengths(m)
        gap = self._gap(m)
        extent = self._row_extent(m, shape, gap)
        first_row: list[str] = []
        for length in shape:
            row: list[str] = []
            for _ in range(length):
                description, asset = self._describe(m, len(ids[k]))
                oid = plan.new_id(m.category)
                plan.anchors.append([oid, description])
                if row:  # along the row, left to right (room for what stands between the first two)
                    plan.anchors += _beside_entries(oid, row[-1], "right", gap + self._room_between(k, len(row), gap))
                elif first_row:  # the next row, in front of the previous one and lined up with it on the left
                    plan.anchors += [
                        [oid, PLACE_ON_BASE, "root", {}],
                        [oid, FRONT_OF, first_row[-1], {"distance": gap}],
                        [oid, ALIGN_LEFT, first_row[-1], {}],
                    ]
                else:
                    plan.anchors += self._first_of(plan, oid, m, spot, ids, self._row_start(m, spot, extent, half))
                plan.anchors.append(self._facing_entry(oid, self._facing(asset, request, alone=shape == [1]), asset))
                row.append(oid)
                ids[k].append(oid)
            first_row.append(row[0])

    def _row_start(
        self,
        m: Mention,
        spot: tuple[float, float] | None,
        extent: tuple[float, float, float, float],
        half: tuple[float, float],
    ) -> tuple[float, float] | None:
        """Where the first of m's rows stands; the rows of the support's one group, wider than half the support, may
        start anywhere their length leaves room for (a line of jars along a shelf is not always at its left end)."""
        start = _row_start(spot, extent, half)
        width, hy = extent[0], half[1]
        if start is None or not self._lone or not hy < width < 2 * hy:
            return start
        point = self.draws.spread_point("slide", *self._key(m))
        if point is None:
            return start
        low, high = -hy + width - extent[2] / 2, hy - extent[2] / 2
        return start[0], round(low + point[0] * (high - low), 3)

    def _facing(self, asset: Asset, request: SceneRequest, alone: bool) -> str:
        """Which way an anchor faces: a lone one turns a quarter when only then does its footprint fit the support
        (a letter tray deeper than the shelf)."""
        if request.messy:
            return RANDOM_ROT
        if alone and self._room is not None and choosing.fit_tier(asset, self._room) % 3 == 1:
            return FACING_LEFT
        return FACING_FRONT

    def _beside_each(self, plan: _Plan, k: int, m: Mention, ids: dict[int, list[str]], request: SceneRequest) -> None:
        """ "a speaker on each side of the monitor": one left and one right of it (its two ends: the long way);
        "plates, each with a fork beside it": object n beside the target's object n."""
        assert m.beside is not None
        targets = ids[m.beside]
        whole = _standing(plan, targets)
        sides = [self._side(m)]
        if m.side in ("sides", "ends"):
            lengthwise = m.side == "ends" and self._deeper_than_wide(plan, whole)
            sides = ["behind", "front"] if lengthwise else ["left", "right"]
        for n in range(m.count):
            description, asset = self._describe(m, n)
            oid = plan.new_id(m.category)
            target = targets[n % len(targets)] if m.per == m.beside else whole
            plan.anchors.append([oid, description])
            distance = self._distance(0.05, "beside", n, *self._key(m))
            plan.anchors += _beside_entries(oid, target, sides[n % len(sides)], distance)
            facing = RANDOM_ROT if request.messy else FACING_FRONT
            plan.anchors.append(self._facing_entry(oid, facing, asset))
            ids[k].append(oid)

    def _between(self, plan: _Plan, k: int, m: Mention, ids: dict[int, list[str]], request: SceneRequest) -> None:
        """ "a vase between two candles", "a lamp between them": right of the first, left of the second, lined up."""
        assert m.beside is not None
        left, right = ids[m.beside][0], ids[m.beside][1]
        for n in range(m.count):
            description, asset = self._describe(m, n)
            oid = plan.new_id(m.category)
            plan.anchors += [
                [oid, description],
                [oid, PLACE_ON_BASE, "root", {}],
                [oid, RIGHT_OF, left, {"distance": 0.03}],
                [oid, LEFT_OF, right, {"distance": 0.03}],
                [oid, ALIGN_CENTER_FB, left, {}],
                self._facing_entry(oid, self._facing(asset, request, alone=True), asset),
            ]
            ids[k].append(oid)

    def _room_between(self, k: int, n: int, gap: float) -> float:
        """The width to leave before the second object of mention k's row for the things said to stand between."""
        inside = [o for o in self._mentions if o.beside == k and o.side == "between"] if n == 1 else []
        return sum(self._assets(o)[0].size[1] * o.count + gap for o in inside)

    def _deeper_than_wide(self, plan: _Plan, oid: str) -> bool:
        """Whether the object `oid` names is longer front to back than left to right (its ends are front and back)."""
        description = next((str(e[1]) for e in plan.anchors if e[0] == oid and len(e) == 2), None)
        if description is None:
            return False
        x, y, _ = self.catalogue.resolve(description).size
        return bool(x > y)

    def _first_of(
        self,
        plan: _Plan,
        oid: str,
        m: Mention,
        spot: tuple[float, float] | None,
        ids: dict[int, list[str]],
        start: tuple[float, float] | None,
    ) -> list[Entry]:
        """Where the first object of a mention stands: its spot, or beside (left of, in front of ...) its target."""
        if spot is None and m.beside is not None and ids.get(m.beside):
            distance = self._distance(0.05, "beside", *self._key(m))
            return _beside_entries(oid, _standing(plan, ids[m.beside]), self._side(m), distance)
        x, y = start if start is not None else (0.0, 0.0)
        return [[oid, PLACE_ON_BASE, "root", {"x": round(x, 3), "y": round(y, 3)}]]

    def _row_extent(self, m: Mention, shape: list[int], gap: float) -> tuple[float, float, float, float]:
        """The width (left to right) of the longest row, the depth (front to back) of all rows, and one object's
        width and depth."""
        x, y, _ = self._assets(m)[0].size
        return max(shape) * y + (max(shape) - 1) * gap, len(shape) * x + (len(shape) - 1) * gap, y, x

    def _stacks(
        self,
        plan: _Plan,
        k: int,
        m: Mention,
        spot: tuple[float, float] | None,
        ids: dict[int, list[str]],
        request: SceneRequest,
        half: tuple[float, float],
    ) -> None:
        """Each stack's bottom object stands beside the previous stack's; the others rest each on the one below."""
        heights = list(m.sizes) or [m.count]
        spacing = self._distance(0.05, "stacks", *self._key(m))
        stacks = [self._stack_levels(m, request, height, which) for which, height in enumerate(heights)]
        width = sum(levels[0].size[1] for levels in stacks) + (len(stacks) - 1) * spacing
        depth = max(levels[0].size[0] for levels in stacks)
        start = _row_start(spot, (width, depth, stacks[0][0].size[1], stacks[0][0].size[0]), half)
        bases: list[str] = []
        for levels in stacks:
            oid = plan.new_id(m.category)
            plan.anchors.append([oid, levels[0].description])
            if bases:
                plan.anchors += _beside_entries(oid, bases[-1], "right", spacing)
            else:
                plan.anchors += self._first_of(plan, oid, m, spot, ids, start)
            plan.anchors.append([oid, RANDOM_ROT if request.messy else FACING_FRONT, "root", {}])
            bases.append(oid)
            ids[k].append(oid)
            ids[k] += self._stack_on(plan, oid, m, levels, request)

    def _ring(
        self,
        plan: _Plan,
        k: int,
        m: Mention,
        centre: Mention,
        centre_id: str,
        ids: dict[int, list[str]],
        half: tuple[float, float],
    ) -> None:
        """Mention k's objects evenly around the centre piece, each facing it (kept on the support)."""
        hx, hy = half
        ids[k] = []
        radius = 0.5 * max(self._assets(centre)[0].size[:2]) + 0.5 * max(self._assets(m)[0].size[:2]) + 0.04
        cx, cy = _spot_of(plan, centre_id)
        turn = self._ring_turn(m)
        for n in range(m.count):
            angle = 2 * math.pi * n / m.count + turn
            description, _ = self._describe(m, n)
            oid = plan.new_id(m.category)
            ids[k].append(oid)
            plan.anchors += [
                [oid, description],
                [
                    oid,
                    PLACE_ON_BASE,
                    "root",
                    {
                        "x": round(float(np.clip(cx + radius * math.cos(angle), -hx, hx)), 3),
                        "y": round(float(np.clip(cy + radius * math.sin(angle), -hy, hy)), 3),
                    },
                ],
                [oid, FACING_TO, centre_id, {}],
            ]

    def _ring_on(
        self, plan: _Plan, k: int, m: Mention, mentions: list[Mention], ids: dict[int, list[str]], request: SceneRequest
    ) -> None:
        """Mention k's objects around a centre piece that stands on a carrier ("toy cars around a tower of blocks on
        the rug", "cups around the teapot on the tray"): on the same carrier, evenly around the middle, where the
        piece stands."""
        assert m.around is not None
        centre = mentions[m.around]
        carriers = ids.get(centre.on) if centre.on is not None else None
        if not carriers:
            self._free(plan, k, m, ids, request)
            return
        radius = 0.5 * max(self._assets(centre)[0].size[:2]) + 0.5 * max(self._assets(m)[0].size[:2]) + 0.03
        ids[k] = []
        turn = self._ring_turn(m)
        for n in range(m.count):
            angle = 2 * math.pi * n / m.count + turn
            description, _ = self._describe(m, n)
            oid = plan.new_id(m.category)
            ids[k].append(oid)
            offsets = {"x_offset": round(radius * math.cos(angle), 3), "y_offset": round(radius * math.sin(angle), 3)}
            plan.physical += [[oid, description], [oid, PLACE_ON, carriers[-1], offsets]]

    def _office(self, plan: _Plan, anchors: list[int], mentions: list[Mention], ids: dict[int, list[str]]) -> set[int]:
        """Monitor at the back, keyboard in front of it, mouse to its right as the person at the desk (the viewer)
        sees it."""
        by_cat = {mentions[k].category: k for k in anchors}
        if "monitor" not in by_cat or "keyboard" not in by_cat:
            return set()
        pair = [mentions[by_cat["monitor"]], mentions[by_cat["keyboard"]]]
        if any(m.count > 1 or m.beside is not None for m in pair):
            return set()  # several monitors, or a placement the prompt gives: the general layout
        done = set()
        monitor, keyboard = by_cat["monitor"], by_cat["keyboard"]
        mid = plan.new_id("monitor")
        plan.anchors += [
            [mid, self._describe(mentions[monitor], 0)[0]],
            [mid, PLACE_ON_BASE, "root", {"y": self._offset_along(0.0, "monitor")}],
            [mid, ALIGN_BACK, "root", {}],
            [mid, FACING_FRONT, "root", {}],
        ]
        kid = plan.new_id("keyboard")
        plan.anchors += [
            [kid, self._describe(mentions[keyboard], 0)[0]],
            [kid, PLACE_ON_BASE, "root", {}],
            [kid, FRONT_OF, mid, {"distance": self._distance(0.08, "keyboard")}],
            [kid, ALIGN_CENTER_LR, mid, {}],
            [kid, FACING_SAME_AS, mid, {}],
        ]
        ids[monitor], ids[keyboard] = [mid], [kid]
        done |= {monitor, keyboard}
        if "mouse" in by_cat:
            mouse = by_cat["mouse"]
            oid = plan.new_id("mouse")
            plan.anchors += [
                [oid, self._describe(mentions[mouse], 0)[0]],
                [oid, PLACE_ON_BASE, "root", {}],
                [oid, f"{frame_side('right').upper()}-OF", kid, {"distance": self._distance(0.05, "mouse")}],
                [oid, ALIGN_CENTER_FB, kid, {}],
                [oid, FACING_SAME_AS, kid, {}],
            ]
            ids[mouse] = [oid]
            done.add(mouse)
        return done

    def _book_row(
        self, plan: _Plan, upright: list[int], mentions: list[Mention], ids: dict[int, list[str]], context: AgentContext
    ) -> None:
        """Books standing upright in a row along the back of a shelf."""
        hx, hy = context.support.half_extents
        for k in upright:
            m = mentions[k]
            count = m.count if m.explicit_count else max(m.count, 10)
            if not m.explicit_count:  # "rows of books": how many the seed says, ten or a few more
                high = count + 2
                if self.draws.on:  # a drawn row leaves room on the shelf for what else is asked
                    room = self._books_in_room(k, m, mentions, context, upright)
                    count, high = max(BOOK_ROW_LEAST, min(count, room)), max(BOOK_ROW_LEAST, min(high, room))
                count = self.draws.count(count, count, high, "book row count", *self._key(m))
            start = self.draws.pick("left", ["left", "right"], "book row", *self._key(m))  # the end it starts from
            ids[k] = []
            for n in range(count):
                description, _ = self._describe(m, n)
                oid = plan.new_id("book")
                plan.anchors.append([oid, description])
                if not ids[k]:
                    plan.anchors += [
                        [oid, PLACE_ON_BASE, "root", {}],
                        [oid, ALIGN_LEFT if start == "left" else ALIGN_RIGHT, "root", {}],
                        [oid, ALIGN_BACK, "root", {}],
                    ]
                else:
                    plan.anchors += [
                        [oid, PLACE_ON_BASE, "root", {}],
                        [oid, RIGHT_OF if start == "left" else LEFT_OF, ids[k][-1], {"distance": 0.003}],
                        [oid, ALIGN_BACK, "root", {}],
                    ]
                plan.anchors.append([oid, FACING_FRONT, "root", {}])
                ids[k].append(oid)
        tokens = " ".join(read_prompt(context.prompt, self.lexicon).tokens)
        if "lying flat" in tokens and not any("flat" in m.phrase for m in mentions):
            match = re.search(r"(\w+) lying flat", tokens)
            word = match.group(1) if match else ""
            count = {"few": 3, "couple": 2, "two": 2, "three": 3, "some": 3}.get(word, 3)
            if word not in ("couple", "two", "three"):  # "a few lying flat": two to four
                count = self.draws.count(count, *LOOSE_RANGES["few"], "loose", "book lying flat")
            flat = Mention("book", count, "book lying flat", (), 0, 0, True, True, stacked=True)
            self._add_stack_free(plan, flat)

    def _books_in_room(
        self, k: int, m: Mention, mentions: list[Mention], context: AgentContext, upright: list[int]
    ) -> int:
        """How many of m's upright books fit along the shelf beside the other free-standing things and a stack of
        books lying flat (the widest flat book, when the prompt asks for some)."""
        held = {j for o in mentions for j in o.contents}
        others = self._width_of_others(mentions, k, held | set(upright))
        if "lying flat" in " ".join(self._tokens):
            flat = [a for a in self.catalogue.variants("book lying flat", 16) if "flat" in a.kind]
            others += max((min(a.size[:2]) for a in flat), default=0.0) + 0.03
        thickness = max(self._describe(m, n)[1].size[1] for n in range(12)) + 0.003
        return int((2 * context.support.half_extents[1] - others) / thickness)

    def _add_stack_free(self, plan: _Plan, m: Mention) -> None:
        previous = None
        for n in range(m.count):
            description, _ = self._describe(m, n)
            oid = plan.new_id(m.category)
            plan.free.append([oid, description])
            if previous is None:
                plan.free.append([oid, PLACE_ANYWHERE, "root", {"stack": False}])
            else:
                plan.free.append([oid, PLACE_ON, previous, {"overlap": 0.9}])
            previous = oid

    def _stack_levels(self, m: Mention, request: SceneRequest, height: int, which: int = 0) -> list[Asset]:
        """The asset at each level of one of m's stacks, bottom first. One variant throughout canonically: flat on top,
        steady, the stack under the next shelf board (agent/choosing.py), lying flat; dishes, what nests and what
        things go in stack with their own kind. Other things that lie flat (books, gift boxes, towels) may mix, with
        variety or when the words ask for assorted ones, the largest at the bottom."""
        assorted = self._assorted(m)
        with self._canonically() if assorted else contextlib.nullcontext():  # the words choose: every kind there is
            variants = [a for a in self._assets(m) if "upright" not in a.kind] or self._assets(m)  # stacks lie flat
        levels = max(m.sizes) if m.sizes else m.count
        first = choosing.stack_choice(variants, levels, self._room)
        key = ("kinds", *self._key(m), which)
        nested = "inside" in request.tokens[m.end : m.end + 6] or "nested" in request.tokens
        if nested or first.cavity is not None or m.category in MATCHED or not choosing.stacks_well(first):
            return [first] * height
        if not assorted and self.draws.canonical(*key):
            return [first] * height
        well = [a for a in variants if a is not first and choosing.stacks_well(a)]
        kinds = height if assorted else self.draws.count(1, 1, min(height, 1 + len(well)), *key)
        candidates = [first, *(well if assorted else self.draws.order(well, *key))]
        chosen = _nesting_footprints(candidates[:kinds])
        chains = _footprint_chains([first, *well], height) if assorted else []
        if chains and not self.draws.canonical(*key):  # different ones: the seed picks which
            chosen = self.draws.pick(chains[0], chains, *key)
        elif assorted and len(chosen) < height:  # different ones, those that stack best first
            chosen = _nesting_footprints(candidates)
            chosen += [a for a in candidates if a not in chosen][: height - len(chosen)]
        stack = sorted((chosen[n % len(chosen)] for n in range(height)), key=_area, reverse=True)
        if (
            self._room is not None
            and self._room.height is not None
            and sum(a.size[2] for a in stack) >= self._room.height
        ):
            return [first] * height
        return stack

    def _stacks_same(self, m: Mention, request: SceneRequest) -> bool:
        """Identical dishes nest and stack; anything with a cavity stacks best with its own kind."""
        nested = "inside" in request.tokens[m.end : m.end + 6] or "nested" in request.tokens
        return nested or self._role(m) in ("container", "carrier")

    def _stack_on(self, plan: _Plan, base: str, m: Mention, levels: list[Asset], request: SceneRequest) -> list[str]:
        """The levels above `base`, the first of one of mention m's stacks, each resting on (or, nested, dropped into)
        the one below: bowls, colanders and paper cups nest in a stack of their own kind whatever the words."""
        same = self._stacks_same(m, request)
        nested = "inside" in request.tokens[m.end : m.end + 6] or "nested" in request.tokens
        nested = nested or (same and choosing.nests(levels[0]))
        previous, placed = base, []
        for asset in levels[1:]:
            oid = plan.new_id(m.category)
            placed.append(oid)
            messy = request.messy or m.arrangement == "pile"
            params: dict[str, Any] = {"messy": True} if messy else {"overlap": 0.9}
            if messy and self.draws.on:  # a messy pile: each a little off the one below, the seed says where
                x, y, _ = asset.size
                reach = self.draws.spread(0.1)
                params["x_offset"] = round(self.draws.uniform(0.0, -reach * x, reach * x, "pile x", oid), 3)
                params["y_offset"] = round(self.draws.uniform(0.0, -reach * y, reach * y, "pile y", oid), 3)
            if nested:  # "cups stacked inside one another": each dropped into the one below
                plan.physical += [[oid, asset.description], [[oid], PLACE_IN, previous, {}]]
            else:
                plan.physical += [[oid, asset.description], [oid, PLACE_ON, previous, params]]
            previous = oid
        return placed

    def _role(self, m: Mention) -> str:
        return self.lexicon.role(m.category) if m.known else ""

    def _pile_is_free(self, m: Mention) -> bool:
        """A pile of things that do not stack (balls, apples) is scattered, allowed to rest on each other."""
        return m.arrangement == "pile" and self._canonical_first(m).support_probability < 0.5

    def _on(
        self, plan: _Plan, k: int, m: Mention, mentions: list[Mention], ids: dict[int, list[str]], request: SceneRequest
    ) -> None:
        target = m.on
        assert target is not None
        carriers = ids.get(target)
        if not carriers:
            self._free(plan, k, m, ids, request)
            return
        ids[k] = []
        if m.stacked and m.per is None and not self._pile_is_free(m):
            self._stacks_on(plan, k, m, carriers[-1], ids, request)
            return
        for n in range(m.count):
            description, _ = self._describe(m, n)
            oid = plan.new_id(m.category)
            ids[k].append(oid)
            carrier = carriers[n % len(carriers)] if m.per is not None else carriers[-1]
            params: dict[str, Any] = {}
            if request.fragile:
                params = {"overlap": 0.5, "stability": "unstable"}
            elif request.stable:
                params = {"stability": "stable"}
            elif request.messy:
                params = {"messy": True}
            plan.physical += [[oid, description], [oid, PLACE_ON, carrier, params]]
            if m.category in ("cup", "mug", "teapot", "pitcher"):
                plan.physical.append([oid, FACING_FRONT, "root", {}])

    def _stacks_on(
        self, plan: _Plan, k: int, m: Mention, carrier: str, ids: dict[int, list[str]], request: SceneRequest
    ) -> None:
        """ "a stack of plates on a tray": each stack's bottom on the carrier, the others each on the one below."""
        for which, height in enumerate(list(m.sizes) or [m.count]):
            levels = self._stack_levels(m, request, height, which)
            base = plan.new_id(m.category)
            plan.physical += [[base, levels[0].description], [base, PLACE_ON, carrier, {}]]
            ids[k] += [base, *self._stack_on(plan, base, m, levels, request)]

    def _fill(
        self, plan: _Plan, k: int, m: Mention, mentions: list[Mention], ids: dict[int, list[str]], request: SceneRequest
    ) -> None:
        """Drop mention k's contents into its (first) container; "each holding" spreads them over all of them. What
        does not fit through the opening is placed anywhere instead. A container none of whose variants is open
        (no cavity) gets its contents beside it on the support, and the user is told so."""
        container = self._assets(m)[0]  # the variant that holds them, an open one when there is (agent/choosing.py)
        into: dict[str, list[str]] = {}
        for j in m.contents:
            item = mentions[j]
            if item.on is not None:
                continue
            variants = self._assets(item)
            if container.cavity is None:
                self._note_not_held(m, item)
            if not choosing.passes_opening(variants[0], container):
                self._free(plan, j, item, ids, request)
                continue
            room = max(1, _capacity(container, variants, len(m.contents)))
            if item.plural and not item.explicit_count and not self.draws.canonical("contents", *self._key(item)):
                smallest_first = sorted(variants, key=lambda a: float(np.prod(a.size)))
                if room < _capacity(container, smallest_first, len(m.contents)):  # the drawn ones fill it sooner
                    self.draws = replace(self.draws, fixed=self.draws.fixed | {self._key(item)})
                    variants = self._assets(item)
                    room = max(1, _capacity(container, variants, len(m.contents)))
            count = item.count if item.explicit_count else min(room, 8 if item.plural else 1)
            if item.plural and not item.explicit_count and self.draws.wide and not item.least:  # how full is open
                count = self.draws.count(count, min(max(2, math.ceil(0.5 * count)), count), count, *self._key(item))
            ids[j] = []
            for n in range(count):
                description, _ = self._describe(item, n)
                oid = plan.new_id(item.category)
                ids[j].append(oid)
                plan.physical.append([oid, description])
                target = ids[k][n % len(ids[k])] if item.per == k else ids[k][0]
                into.setdefault(target, []).append(oid)
        for target, items in into.items():
            plan.physical.append([items, PLACE_IN, target, {}])

    def _note_not_held(self, container: Mention, item: Mention) -> None:
        """Tell the user that the item could not go in the container: the catalogue has no open one."""
        note = (
            f"no {container.category} in the asset catalogue is open (none has a cavity to put things in): "
            f"the {item.category} (x{item.count}) placed beside it on the support, not in it"
        )
        if note not in self.transcript_notes:
            self.transcript_notes.append(note)

    def _free(self, plan: _Plan, k: int, m: Mention, ids: dict[int, list[str]], request: SceneRequest) -> None:
        ids[k] = []
        for n in range(m.count):
            description, _ = self._describe(m, n)
            oid = plan.new_id(m.category)
            ids[k].append(oid)
            messy = request.messy or request.dense or m.arrangement in ("pile", "scatter")
            params: dict[str, Any] = {"messy": True, "stack": True} if messy else {"stack": False}
            plan.free += [[oid, description], [oid, PLACE_ANYWHERE, "root", params]]

    def _add_free(self, plan: _Plan, name: str, request: SceneRequest) -> str:
        m = Mention(self._category(name), 1, name, (), 0, 0, False, False)
        ids: dict[int, list[str]] = {}
        self._free(plan, 0, m, ids, request)
        return ids[0][0]

    def _place_settings(
        self, plan: _Plan, request: SceneRequest, mentions: list[Mention], context: AgentContext
    ) -> set[int]:
        """One place setting as a GROUP, copied for every other diner and turned to face the table's middle."""
        consumed = {k for k, m in enumerate(mentions) if m.category in SETTING_ITEMS and not m.centre}
        named = {mentions[k].category for k in consumed}
        drink = "wine glass" if "wine glass" in named else "glass" if "glass" in named else "cup"
        items = ["plate", "fork", "knife"] + (["spoon"] if "spoon" in named else []) + [drink]
        hx, hy = context.support.half_extents
        ids: dict[str, str] = {}
        descriptions = {
            "plate": "a round white dinner plate",
            "fork": "a stainless steel dinner fork",
            "knife": "a stainless steel table knife",
            "spoon": "a stainless steel soup spoon",
            "cup": "a white coffee cup",
            "glass": "a clear drinking glass",
            "wine glass": "a clear wine glass",
        }
        for item in items:
            ids[item] = plan.new_id(item)
            plan.anchors.append([ids[item], self._setting_piece(item, descriptions[item])])
            plate = ids["plate"]
            if item == "plate":
                plan.anchors += [
                    [plate, PLACE_ON_BASE, "root", {"x": round(hx - 0.17, 3), "y": 0.0}],
                    [plate, FACING_BACK, "root", {}],
                ]
            elif item == "fork":
                plan.anchors += [
                    [ids[item], PLACE_ON_BASE, "root", {}],
                    [ids[item], RIGHT_OF, plate, {"distance": 0.02}],
                    [ids[item], ALIGN_CENTER_FB, plate, {}],
                    [ids[item], ORIENT_BY_RELATIVE_SIDE, plate, {}],
                ]
            elif item == "knife":
                plan.anchors += [
                    [ids[item], PLACE_ON_BASE, "root", {}],
                    [ids[item], SYMMETRY_ALONG, ids["fork"], {"C": plate}],
                    [ids[item], ORIENT_BY_RELATIVE_SIDE, plate, {}],
                ]
            elif item == "spoon":
                plan.anchors += [
                    [ids[item], PLACE_ON_BASE, "root", {}],
                    [ids[item], LEFT_OF, ids["knife"], {"distance": 0.015}],
                    [ids[item], ALIGN_CENTER_FB, plate, {}],
                    [ids[item], ORIENT_BY_RELATIVE_SIDE, plate, {}],
                ]
            else:
                side = ids.get("spoon", ids["knife"])
                plan.anchors += [
                    [ids[item], PLACE_ON_BASE, "root", {}],
                    [ids[item], BACK_OF, plate, {"distance": 0.03}],
                    [ids[item], ALIGN_LEFT, side, {}],
                    [ids[item], FACING_SAME_AS, plate, {}],
                ]
        group = "group_setting_0"
        plan.anchors.append([group, GROUP, [ids[i] for i in items], {"anchor": ids["plate"]}])
        seats = self._seats(request.diners, hx, hy)
        if seats is not None:  # the first diner sits elsewhere too: the setting built at the near end moves there
            facing, x, y = seats[0]
            plan.anchors += [
                [group, PLACE_ON_BASE, "root", {"x": round(x, 3), "y": round(y, 3)}],
                [group, facing, "root", {}],
            ]
        for n in range(1, request.diners):
            facing, x, y = _seat(n, request.diners, hx, hy) if seats is None else seats[n]
            copy = f"group_setting_{n}"
            plan.anchors += [
                [copy, COPY_GROUP, group, {}],
                [copy, PLACE_ON_BASE, "root", {"x": round(x, 3), "y": round(y, 3)}],
                [copy, facing, "root", {}],
            ]
        return consumed

    def _setting_piece(self, item: str, canonical: str) -> str:
        """The description of one piece of a place setting: the canonical one, or with variety any variant of the
        piece that suits a dining table (a cream or a white dinner plate, a tumbler or a highball)."""
        if not self.draws.on:
            return canonical
        words = choosing.words_of([], 0, 0, canonical, ())
        variants = [
            a
            for a in self.catalogue.variants(SETTING_NAMES.get(item, item))
            if a.category == item and not choosing.is_multiple(a) and not NOT_AT_TABLE & set(choosing.asset_words(a))
        ]
        if not variants:
            return canonical
        weights = [1.0 + choosing.word_score(a, words) for a in variants]
        chosen = self.draws.order(variants, "setting", item, weights=weights)[0]
        return chosen.description if self.catalogue.resolve(chosen.description).id == chosen.id else canonical

    def _seats(self, diners: int, hx: float, hy: float) -> list[tuple[str, float, float]] | None:
        """Where each diner's setting goes (facing, x, y), or None for the canonical seats (`_seat`). With variety
        the diners sit at the ends first or along the sides first, spread along each edge, and the first of them
        anywhere; every edge holds only as many settings as its length gives room for."""
        if not self.draws.on or diners < 2:
            return None
        length = {"front": 2 * hy, "back": 2 * hy, "left": 2 * hx, "right": 2 * hx}
        room = {edge: int(length[edge] // _SETTING_WIDTH) for edge in length}
        ends, sides = ("front", "back"), ("left", "right")
        if length["front"] > length["left"]:
            ends, sides = sides, ends
        plan = self.draws.pick("round", ["round", "long sides"], "seats")
        tiers = [(*ends, *sides)] if plan == "round" else [sides, ends]
        per_edge = dict.fromkeys(length, 0)
        left = diners
        for tier in tiers:  # deal the diners round the edges of each tier, as far as each has room
            while left and any(per_edge[e] < room[e] for e in tier):
                for edge in tier:
                    if left and per_edge[edge] < room[edge]:
                        per_edge[edge] += 1
                        left -= 1
        if left:
            return None  # more diners than the edges hold: the canonical seats
        seats = [self._seat_on(edge, i, n, hx, hy) for edge, n in per_edge.items() for i in range(n)]
        first = self.draws.pick(seats[0], seats, "first seat")
        return [first, *(s for s in seats if s is not first)]

    def _seat_on(self, edge: str, i: int, of: int, hx: float, hy: float) -> tuple[str, float, float]:
        """Setting i of `of` along one edge of the table (spread evenly, shifted a little when there is room)."""
        facing, sign = _EDGE_FACING[edge]
        inset = self.draws.uniform(_SETTING_DEPTH / 2, 0.17, 0.21, "inset", edge, i)
        along = hy if edge in ("front", "back") else hx
        spot = -along + 2 * along * (i + 0.5) / of
        slack = max(0.0, (2 * along / of - _SETTING_WIDTH) / 2)
        spot += self.draws.uniform(0.0, -slack, slack, "along", edge, i)
        if edge in ("front", "back"):
            return facing, sign * (hx - inset), spot
        return facing, spot, sign * (hy - inset)

    # -- reacting to feedback -------------------------------------------------------------------------
    def repair(self, program: list[Entry], context: AgentContext) -> list[Entry]:
        """What failed is pulled in from the edge it stuck out past, takes a smaller variant, or is placed anywhere
        with what rests on it; it is dropped only when it failed before and has no smaller variant (agent/repair.py).
        When nothing is left, each mention's smallest variant is placed anywhere."""
        failed = set(filter(None, context.notes.get("failed", "").split(",")))
        tried_free = set(filter(None, context.notes.get("freed", "").split(",")))
        tried_free -= waited_only(r.feedback for r in context.history[:-1])
        tried_free -= self._failed_only_as_drawn(context)
        if not failed:
            return program or self._smallest_scene(context)
        reasons = failure_reasons(context.history[-1].feedback) if context.history else {}
        repaired = repair_program(
            program, failed, tried_free, reasons=reasons, catalogue=self.catalogue, support=context.support
        )
        return repaired if any(len(e) == 2 for e in repaired) else self._smallest_scene(context)

    def _smallest_scene(self, context: AgentContext) -> list[Entry]:
        """Each mention's first object as its smallest variant, placed anywhere there is room."""
        request = read_prompt(context.prompt, self.lexicon)
        plan = _Plan()
        for m in self._mentions_or_default_scene(request, context.support.kind):
            asset = min(self._assets(m), key=_area)
            if self.catalogue.resolve(asset.description).id != asset.id:
                asset = self.catalogue.resolve(f"a {' '.join([*m.adjectives, m.phrase])}")
            oid = plan.new_id(m.category)
            plan.free += [[oid, asset.description], [oid, PLACE_ANYWHERE, "root", {"stack": False, "pack": True}]]
        return plan.free

    def enrich(self, program: list[Entry], context: AgentContext) -> list[Entry]:
        """Add a few more objects that suit the scene, placed wherever there is room."""
        request = read_prompt(context.prompt, self.lexicon)
        scene_type = _scene_type(request, context.support.kind)
        names = self.draws.order(FILLERS.get(scene_type, FILLERS["everyday"]), "enrich")
        plan = _Plan(used={e[0] for e in program if isinstance(e[0], str)})
        start = len(context.history) * ENRICH_PER_ROUND
        for n in range(ENRICH_PER_ROUND):
            self._add_free(plan, names[(start + n) % len(names)], request)
        return program + plan.free


def _rings_on(m: Mention, mentions: list[Mention]) -> bool:
    """Whether m goes around a centre piece that itself stands on a carrier (so m goes on that carrier too)."""
    return m.around is not None and m.on is None and mentions[m.around].on is not None


def _nesting_footprints(assets: list[Asset]) -> list[Asset]:
    """The largest of the assets and those of the others each of which lies about within the footprint of the one
    before (length and width both at most a tenth larger): in a stack of them, largest at the bottom, no level
    reaches far past the one under it (an atlas on a pocket book)."""
    chain: list[Asset] = []
    for asset in sorted(assets, key=_area, reverse=True):
        if not chain or _within(asset, chain[-1]):
            chain.append(asset)
    return chain


def _footprint_chains(assets: list[Asset], length: int, most: int = 200) -> list[list[Asset]]:
    """Up to `most` sets of `length` different assets that stack as `_nesting_footprints` keeps them (largest at the
    bottom, each within a tenth of the one below), largest first."""
    ordered = sorted(dict.fromkeys(assets), key=_area, reverse=True)
    chains: list[list[Asset]] = []

    def extend(chain: list[Asset], start: int) -> None:
        if len(chains) >= most:
            return
        if len(chain) == length:
            chains.append(list(chain))
            return
        for i in range(start, len(ordered)):
            if _within(ordered[i], chain[-1]):
                extend([*chain, ordered[i]], i + 1)

    for i in range(len(ordered)):
        extend([ordered[i]], i + 1)
    return chains


def _within(upper: Asset, lower: Asset) -> bool:
    return all(a <= 1.1 * b for a, b in zip(sorted(upper.size[:2]), sorted(lower.size[:2]), strict=True))


def _area(asset: Asset) -> float:
    return max(1e-4, asset.size[0] * asset.size[1])


def _clamp(value: float, low: int, high: int) -> int:
    return max(low, min(high, int(value)))


def _capacity(container: Asset, variants: list[Asset], kinds: int) -> int:
    """How many things, the variants in turn, fit in the container when `kinds` kinds of things share it (at most 8):
    long things standing by the opening's area, the rest by the cavity's volume."""
    return choosing.room_for_mixed(container, variants, 1 / max(1, kinds))


def _grid_shape(n: int, hx: float, hy: float) -> tuple[int, int]:
    """The rows (front to back) and columns of the grid that spreads n anchors over the support."""
    cols = max(1, math.ceil(math.sqrt(n * hy / hx)))
    return math.ceil(n / cols), cols


def _grid_spots(n: int, hx: float, hy: float) -> list[tuple[float, float]]:
    """n spots spread over the support, back row first."""
    if n == 0:
        return []
    rows, cols = _grid_shape(n, hx, hy)
    spots = []
    for r in range(rows):
        for c in range(cols):
            x = -hx + (2 * hx) * (r + 0.5) / rows
            y = hy - (2 * hy) * (c + 0.5) / cols
            spots.append((x * 0.8, y * 0.8))
    return spots[:n]


def _standing(plan: _Plan, oids: list[str]) -> str:
    """What to stand beside: the one object of a mention standing on the support, or a GROUP of its several (a row,
    stacks side by side), so "a keyboard in front of them" is in front of the whole row."""
    standing = [oid for oid in oids if any(e[0] == oid and e[1] == PLACE_ON_BASE for e in plan.anchors)]
    if len(standing) <= 1:
        return (standing or oids)[0]
    for entry in plan.anchors:
        if entry[1] == GROUP and entry[2] == standing:
            return str(entry[0])
    group = plan.new_id(f"group {standing[0]}")
    plan.anchors.append([group, GROUP, standing, {}])
    return group


def _spot_of(plan: _Plan, oid: str) -> tuple[float, float]:
    """Where the program puts `oid` on the support (the middle when no entry gives x and y)."""
    for entry in plan.anchors:
        if entry[0] == oid and entry[1] == PLACE_ON_BASE and "x" in entry[3] and "y" in entry[3]:
            return float(entry[3]["x"]), float(entry[3]["y"])
    return 0.0, 0.0


def _first_spot(
    m: Mention, ids: dict[int, list[str]], spots: Iterator[tuple[float, float]]
) -> tuple[float, float] | None:
    """Where the first of mention m stands: the middle when centred, None when it goes beside something already
    placed, else the next grid spot (the grid has a spot for every anchor)."""
    if m.centre:
        return 0.0, 0.0
    if m.beside is not None and m.beside in ids:
        return None
    return next(spots)


_SIDES = {  # where one object stands relative to another: the edge rule and the alignment that goes with it
    "beside": (RIGHT_OF, ALIGN_CENTER_FB),
    "right": (RIGHT_OF, ALIGN_CENTER_FB),
    "left": (LEFT_OF, ALIGN_CENTER_FB),
    "front": (FRONT_OF, ALIGN_CENTER_LR),
    "behind": (BACK_OF, ALIGN_CENTER_LR),
}


def _beside_entries(oid: str, other: str, side: str, distance: float) -> list[Entry]:
    """`oid` on the support, `distance` to the `side` of `other` and lined up with it."""
    edge, align = _SIDES.get(side, _SIDES["beside"])
    return [
        [oid, PLACE_ON_BASE, "root", {}],
        [oid, edge, other, {"distance": distance}],
        [oid, align, other, {}],
    ]


def _targets_first(anchors: list[int], mentions: list[Mention]) -> list[int]:
    """The anchors ordered so that what one stands beside (in front of, around ...) is laid out before it."""
    ordered: list[int] = []

    def visit(k: int, depth: int) -> None:
        for target in (mentions[k].beside, mentions[k].around):
            if target is not None and target in anchors and target not in ordered and depth < len(anchors):
                visit(target, depth + 1)
        if k not in ordered:
            ordered.append(k)

    for k in anchors:
        visit(k, 0)
    return ordered


def _row_lengths(m: Mention) -> list[int]:
    """How many objects each row holds, back row first: rows of the given sizes, columns turned into rows."""
    sizes = list(m.sizes) or ([m.count] if m.groups <= 1 else _even(m.count, m.groups))
    if m.arrangement == "column":  # columns run front to back: row r holds one object of each column long enough
        return [sum(1 for size in sizes if size > r) for r in range(max(sizes))]
    return sizes


def _even(count: int, groups: int) -> list[int]:
    base, extra = divmod(count, groups)
    return [base + (1 if g < extra else 0) for g in range(groups) if base + (1 if g < extra else 0) > 0]


def _row_start(
    spot: tuple[float, float] | None, extent: tuple[float, float, float, float], half: tuple[float, float]
) -> tuple[float, float] | None:
    """The centre of the first (leftmost, back) object of rows centred on `spot`, kept on the support."""
    if spot is None:
        return None
    width, depth, item_width, item_depth = extent
    hx, hy = half
    x, y = spot
    left = min(y + width / 2, hy) if width < 2 * hy else hy
    back = max(x - depth / 2, -hx) if depth < 2 * hx else -hx
    return back + item_depth / 2, left - item_width / 2


_SETTING_DEPTH = 0.38  # how far a place setting reaches in from the table's edge
_SETTING_WIDTH = 0.55  # how much of an edge one place setting takes, with elbow room
# Which way a setting at each edge of the table faces (towards the middle), and the sign of its coordinate.
_EDGE_FACING = {
    "front": (FACING_BACK, 1.0),
    "back": (FACING_FRONT, -1.0),
    "left": (FACING_RIGHT, 1.0),
    "right": (FACING_LEFT, -1.0),
}
_EDGES_ENDS_FIRST = ("front", "back", "left", "right")
_EDGES_SIDES_FIRST = ("left", "right", "front", "back")


def _seat(n: int, diners: int, hx: float, hy: float) -> tuple[str, float, float]:
    """The facing and centre of diner n's copied setting (n >= 1; diner 0's setting is at the near end)."""
    inset = _SETTING_DEPTH / 2
    head_seats = [
        (FACING_FRONT, -hx + inset, 0.0),
        (FACING_RIGHT, 0.0, hy - inset),
        (FACING_LEFT, 0.0, -hy + inset),
    ]
    if n <= len(head_seats):  # the far end, then the middle of each side
        return head_seats[n - 1]
    side = 1 if n % 2 else -1  # more diners: along the long sides
    return (
        FACING_RIGHT if side > 0 else FACING_LEFT,
        (-0.5 + (n // 2) / max(1, diners // 2)) * hx,
        side * (hy - inset),
    )


def _scene_type(request: SceneRequest, kind: str) -> str:
    words = set(request.tokens)
    if kind == "floor":
        return "floor"
    if kind == "shelf":
        return "shelf"
    if words & {"desk", "office", "student", "study"}:
        return "desk"
    if words & {"dinner", "dining", "breakfast", "lunch", "picnic", "tea"} or request.diners:
        return "dining"
    if words & {"kitchen", "counter", "cooking", "pantry"}:
        return "kitchen"
    if words & {"bathroom", "sink"}:
        return "bathroom"
    return "everyday"


def _entries(text: str) -> list[Entry]:
    return [list(e) for e in parse_program(text).to_json()]


def _first_mentions(mentions: list[Mention], max_objects: int) -> list[Mention]:
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


def _listed(ids: list[str], most: int = 6) -> str:
    shown = ", ".join(ids[:most])
    return shown + (f" and {len(ids) - most} more" if len(ids) > most else "")
