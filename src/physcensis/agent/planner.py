"""The offline planner: a deterministic agent that writes predicate programs from a prompt, no network.

It reads the prompt (agent/reading.py), sets the counts the words leave open (planning/counts.py), chooses each
mention's variants (planning/variants.py), lays out the larger objects on the support with spatial predicates
(planning/layout.py), builds place settings as a GROUP copied per diner (planning/dining.py), stacks as PLACE-ON
chains (planning/stacks.py), contents as PLACE-IN and the rest as PLACE-ANYWHERE (planning/placing.py). Given
feedback it drops or frees what failed, and when asked to enrich it adds objects that suit the scene
(planning/scenes.py). This module keeps the agent's interface and the run's choices across rounds.
"""

from __future__ import annotations

import json
from typing import Any

from physcensis.agent.base import AgentContext
from physcensis.agent.choosing import Room
from physcensis.agent.graph import GraphReading, graph_of
from physcensis.agent.planning import dining
from physcensis.agent.planning.counts import Counts, asked_counts, first_mentions
from physcensis.agent.planning.entries import PLACE_ANYWHERE, Entry, Plan
from physcensis.agent.planning.layout import Layout
from physcensis.agent.planning.placing import Placing
from physcensis.agent.planning.scenes import CONTEXT, FILLERS, SCENE_KINDS, mentions_or_default_scene, scene_type
from physcensis.agent.planning.stacks import Stacks
from physcensis.agent.planning.state import Ids, PlanState, choice_key
from physcensis.agent.planning.variants import Variants, area
from physcensis.agent.reading import Mention, SceneRequest, lexicon_for, read_prompt, without_the_support
from physcensis.agent.repair import failure_reasons, repair_program, waited_only, within_objects
from physcensis.agent.variety import DEFAULT_VARIETY, Draws, Variety, parse_variety
from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.assets.supports import SHELF_SPACING
from physcensis.program import parse_program

ENRICH_PER_ROUND = 4
DRAWN_ROUNDS = 2  # a run's first program and, when it failed, one drawn afresh
# The choices of where things stand, which a redraw after a failure takes from the canonical scene.
LAYOUT_CHOICES = frozenset(
    {"gap", "row fill", "spots", "spot", "turn", "side", "beside", "stacks", "monitor", "keyboard"}
    | {"mouse", "ring", "book row", "pile x", "pile y", "seats", "first seat", "inset", "along", "slide"}
)


class OfflinePlanner:
    """The default agent: reads the prompt, writes a program, reacts to feedback. Every choice the prompt leaves
    open (which variant, how many of a vague plural, where a group stands, which end a place setting takes, context
    objects) is drawn from `seed` at the `variety` level (agent/variety.py): the same prompt, seed and variety give
    the same program; `variety="none"` gives the canonical one. `context` (default: on when variety is) lets it add
    a few objects that belong to the kind of scene; they are listed in `added`.

    The work is done by parts that share one `PlanState` (the draws, the support's room, the prompt's words and
    mentions, kept between rounds): `variants`, `counts`, `stacks`, `placing` and `layout`."""

    name = "offline-planner"

    def __init__(
        self,
        catalogue: Catalogue | None = None,
        seed: int = 0,
        variety: str | Variety = DEFAULT_VARIETY,
        context: bool | None = None,
    ) -> None:
        self.catalogue = catalogue or default_catalogue()
        self.lexicon = lexicon_for(self.catalogue)
        self.seed = seed
        self.state = PlanState(self.catalogue, self.lexicon, Draws(parse_variety(variety), seed))
        self.context = self.draws.on if context is None else context
        self.added: list[dict[str, str]] = []  # objects the prompt did not name: id, category, why
        self.variants = Variants(self.state)
        self.counts = Counts(self.state, self.variants)
        self.stacks = Stacks(self.state, self.variants)
        self.placing = Placing(self.state, self.variants, self.stacks)
        self.layout = Layout(self.state, self.variants, self.counts, self.stacks)
        self._owners: dict[str, list[tuple[object, ...]]] = {}  # object id -> keys of its mention and those around it
        self._open_contents: dict[int, list[str]] = {}  # a container's contents of no said count: mention -> ids
        self._open_least: dict[int, int] = {}  # ... and the fewest of each its words allow
        self._open_for: tuple[str, int] | None = None  # the prompt and seed they were planned for
        self._trimmed = 0  # the run's rounds that only left out what overflowed (they are not another draw)

    @property
    def draws(self) -> Draws:
        """The run's seeded choices (the parts read them from the shared state)."""
        return self.state.draws

    @draws.setter
    def draws(self, draws: Draws) -> None:
        self.state.draws = draws

    @property
    def transcript_notes(self) -> list[str]:
        """Said to the user in the run's transcript (contents not held, objects left out)."""
        return self.state.notes

    @transcript_notes.setter
    def transcript_notes(self, notes: list[str]) -> None:
        self.state.notes = notes

    def read(self, prompt: str) -> SceneRequest:
        """The prompt as the planner takes it: the offline reading (a subclass may read it otherwise: a model's scene
        graph, agent/graph_planner.py). A fresh request each time: planning changes its mentions."""
        return read_prompt(prompt, self.lexicon)

    def graph_reading(self, prompt: str) -> GraphReading:
        """The scene graph the planner plans `prompt` from (saved in the report)."""
        return GraphReading(graph_of(self.read(prompt)), "offline reading")

    def graph_requests(self) -> list[dict[str, Any]]:
        """The transcript's rows for the requests that read the prompt into a graph: none, offline."""
        return []

    # -- the agent interface -------------------------------------------------------------------
    def propose(self, context: AgentContext) -> str:
        self.seed = context.seed  # the run's seed draws the open choices (one planner may serve many runs)
        self.draws = Draws(self.draws.level, context.seed)
        if context.request == "create" or not context.history:
            self._trimmed = 0
            program = self.plan(context)
        elif context.request == "repair" and (fewer := self._without_overflow(context)) is not None:
            self._trimmed += 1
            program = fewer
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

    def reads(self, prompt: str) -> bool:
        """Whether the prompt names anything the reading knows: a thing to place, diners, or a kind of scene or
        support ("a tidy desk"). "asdf qwerty", an empty prompt or only symbols name nothing."""
        request = self.read(prompt)
        return bool(request.mentions or request.diners or set(request.tokens) & SCENE_KINDS)

    def requested(self, prompt: str, support_kind: str | None = None) -> dict[str, int]:
        """What the prompt asks for, per category: a said count ("three mugs": 3), the fewest of a loose one ("a few":
        2), two of a plural or a stack of no said height ("some pens"), else one; the most one mention of a category
        asks for (a second mention may be the same thing: "the monitors"). What a place setting's words ("set for
        four") imply is not counted."""
        request = self.read(prompt)
        if support_kind is not None:  # a word naming the support asks for no second one
            request.mentions = without_the_support(request.mentions, support_kind)
        return asked_counts(request, self.state)

    # -- first program -----------------------------------------------------------------------------
    def plan(self, context: AgentContext) -> list[Entry]:
        request = self.read(context.prompt)
        kind = context.support.kind
        height_limit = SHELF_SPACING - 0.05 if kind == "shelf" else None
        plan = Plan()
        request.mentions = without_the_support(request.mentions, kind)
        mentions = first_mentions(self._mentions_or_default_scene(request, kind), context.max_objects)
        state = self.state
        state.room = Room(float(context.support.size[0]), float(context.support.size[1]), height_limit)
        state.tokens, state.mentions = request.tokens, mentions
        self.added = []
        self.counts.vary(mentions)
        self.counts.resolve(mentions, context)
        consumed: set[int] = set()
        if request.diners:
            half = context.support.half_extents
            consumed = dining.place_settings(plan, request, mentions, half, self.draws, self.catalogue)
        ids: Ids = {}
        if request.mentions:
            self.layout.gather(mentions, request, kind, float(context.support.size[0] * context.support.size[1]))
        anchors = [
            k
            for k, m in enumerate(mentions)
            if k not in consumed and self.layout.is_anchor(k, m, mentions, request, kind)
        ]
        self.layout.lay_out(plan, anchors, mentions, ids, request, context)
        self.placing.place_the_rest(plan, mentions, consumed, ids, request)
        self._owners = {oid: self._related(k) for k, oids in ids.items() for oid in oids}
        held = {j for m in mentions for j in m.contents}
        self._open_contents = {  # what a container holds as many of as fit: the planner's count, not the words'
            k: list(oids)
            for k, oids in ids.items()
            if k in held and mentions[k].plural and not mentions[k].explicit_count
        }
        self._open_least = {k: max(2, mentions[k].least) for k in self._open_contents}  # "lots of": at least five
        self._open_for = (context.prompt, context.seed)
        if not request.mentions and not request.diners:  # the whole scene is the planner's, said as such
            why = f"the prompt names no object: a typical {scene_type(request, kind)} scene"
            self.added += [{"id": oid, "category": mentions[k].category, "why": why} for k in ids for oid in ids[k]]
        if request.dense and request.mentions:
            for name in FILLERS["everyday"][:12]:
                self.placing.add_free(plan, name, request)
        if self.context and (request.mentions or request.diners) and not request.dense:
            self._add_context(plan, request, mentions, scene_type(request, kind))
        return self._within_limit(plan.program(), context)

    def _mentions_or_default_scene(self, request: SceneRequest, kind: str) -> list[Mention]:
        return mentions_or_default_scene(request, kind, self.state.category)

    def _within_limit(self, program: list[Entry], context: AgentContext) -> list[Entry]:
        """The program cut to the run's object limit (its last objects dropped), said in a note to the user."""
        kept, dropped = within_objects(program, context.support, context.max_objects)
        if dropped:
            self.added = [row for row in self.added if row["id"] not in dropped]
            self.state.note(
                f"max-objects: the prompt asks for more than {context.max_objects} objects; the last {len(dropped)} "
                f"were left out ({_listed(dropped)}); raise --max-objects to keep them"
            )
        return kept

    def _add_context(self, plan: Plan, request: SceneRequest, mentions: list[Mention], kind_of_scene: str) -> None:
        """A few objects that belong to this kind of scene and that the prompt did not name (a vase or a salt shaker
        on a dining table), drawn from the seed; each is recorded in `added`."""
        category = self.state.category
        named = {m.category for m in mentions}
        choices = [n for n in CONTEXT.get(kind_of_scene, ()) if category(n) not in named]
        most = 3 if self.draws.wide else 2
        count = self.draws.count(0, 0, most, "context", "count") if self.draws.chance(0.7, "context") else 0
        for name in self.draws.order(choices, "context", "names")[:count]:
            oid = self.placing.add_free(plan, name, request)
            self.added.append({"id": oid, "category": category(name), "why": f"context of a {kind_of_scene} scene"})

    def _related(self, k: int) -> list[tuple[object, ...]]:
        """The keys of mention k, of what holds or carries it and of everything else in or on that (a spoon dropped
        into a bowl that chopsticks lie across): a redraw after k failed takes all of them canonical."""
        mentions = self.state.mentions
        m = mentions[k]
        holder = m.on if m.on is not None else next((j for j, o in enumerate(mentions) if k in o.contents), None)
        group = {k} if holder is None else {holder, *mentions[holder].contents}
        if holder is not None:
            group |= {j for j, o in enumerate(mentions) if o.on == holder}
        return [choice_key(mentions[j]) for j in sorted(group) if j < len(mentions)]

    # -- reacting to feedback -------------------------------------------------------------------------
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

    def _without_overflow(self, context: AgentContext) -> list[Entry] | None:
        """When all that failed are things a container was filled with as many as fit ("a bowl of apples": eight, and
        one bounced out), the same program without them, so long as two of each such plural stay: the count was the
        planner's, and the drawn scene is kept. None otherwise."""
        failed = set(filter(None, context.notes.get("failed", "").split(",")))
        owner = {oid: k for k, oids in self._open_contents.items() for oid in oids}
        if not failed or not failed <= owner.keys() or not context.history:
            return None
        if self._open_for != (context.prompt, context.seed):  # planned for another run
            return None
        if any(len(oids) - len(failed & set(oids)) < self._open_least[k] for k, oids in self._open_contents.items()):
            return None
        for oids in self._open_contents.values():
            oids[:] = [oid for oid in oids if oid not in failed]
        kept: list[Entry] = []
        for entry in _entries(context.history[-1].program_text):
            if isinstance(entry[0], list):
                entry = [[oid for oid in entry[0] if oid not in failed], *entry[1:]]
            if entry[0] and (isinstance(entry[0], list) or entry[0] not in failed):
                kept.append(entry)
        self.transcript_notes.append(
            f"{_listed(sorted(failed))} left out: the container holds fewer (no count was said)"
        )
        return kept

    def _redraw_due(self, context: AgentContext) -> bool:
        """Whether every program so far was drawn and failed: then it is drawn again rather than anything dropped
        (even when both drawn programs failed on the same kinds of thing: repairing the fresh draw then left a
        ladle beside the pot it was asked in, where the canonical choices hold it)."""
        history = context.history
        return self.draws.on and len(history) - self._trimmed <= DRAWN_ROUNDS and not any(r.ok for r in history)

    def _redraw(self, context: AgentContext) -> list[Entry]:
        """After the first program failed, every choice drawn afresh (another scene of the same prompt). After that
        failed too, the program drawn again with the failed objects' mentions as the canonical scene has them
        (variant, count) and the canonical layout (spots, sides, gaps: what failed may have been crowded by its
        neighbours, and the canonical scene is the one known to hold: keeping the drawn layout when only contents
        failed left fruit-bowl's fruit out of its bowl in 2 of 20 seeds); a failure that belongs to no mention (a
        place setting's piece) redraws the whole scene canonically, and context objects are left out once anything
        failed (they may have taken the room of what was asked). The usual repair when that changes nothing."""
        failed = set(filter(None, context.notes.get("failed", "").split(",")))
        added = {row["id"] for row in self.added}
        fresh = len(context.history) - self._trimmed == 1
        keys = {key for oid in failed if oid in self._owners for key in self._owners[oid]}
        whole = any(oid not in self._owners and oid not in added for oid in failed) or not failed
        level = Variety.NONE if whole and not fresh else self.draws.level
        if fresh:
            self.draws = Draws(level, context.seed, attempt=1)
        else:
            self.draws = Draws(level, context.seed, frozenset(keys), LAYOUT_CHOICES, attempt=1)
        wanted = self.context
        self.context = self.context and not failed  # context is optional: never kept at the cost of what was asked
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
        request = self.read(context.prompt)
        plan = Plan()
        for m in self._mentions_or_default_scene(request, context.support.kind):
            asset = min(self.variants.assets(m), key=area)
            if self.catalogue.resolve(asset.description).id != asset.id:
                asset = self.catalogue.resolve(f"a {' '.join([*m.adjectives, m.phrase])}")
            oid = plan.new_id(m.category)
            plan.free += [[oid, asset.description], [oid, PLACE_ANYWHERE, "root", {"stack": False, "pack": True}]]
        return plan.free

    def enrich(self, program: list[Entry], context: AgentContext) -> list[Entry]:
        """Add a few more objects that suit the scene, placed wherever there is room."""
        request = self.read(context.prompt)
        kind_of_scene = scene_type(request, context.support.kind)
        names = self.draws.order(FILLERS.get(kind_of_scene, FILLERS["everyday"]), "enrich")
        plan = Plan(used={e[0] for e in program if isinstance(e[0], str)})
        start = len(context.history) * ENRICH_PER_ROUND
        for n in range(ENRICH_PER_ROUND):
            self.placing.add_free(plan, names[(start + n) % len(names)], request)
        return program + plan.free


def _entries(text: str) -> list[Entry]:
    return [list(e) for e in parse_program(text).to_json()]


def _listed(ids: list[str], most: int = 6) -> str:
    shown = ", ".join(ids[:most])
    return shown + (f" and {len(ids) - most} more" if len(ids) > most else "")
