"""The offline reading of a request, as a starting point for a language model.

Small models lose count ("a dining table for four" becomes a table and a plate) and misname things the catalogue
has (a "teacup" that retrieval turns into a vase). The offline planner reads counts, place settings, stacks and
contents reliably, so its first program, flattened to one line per object (group copies spelled out, "on" and "in"
kept), is shown to the model as a draft it may correct. The model still writes the whole program: what it keeps,
adds or drops is its own.
"""

from __future__ import annotations

import logging
import re
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from physcensis.agent.base import AgentContext
from physcensis.agent.guided import MAX_GUIDED_OBJECTS
from physcensis.ids import ROOT_ID, copy_member_id
from physcensis.program import parse_program
from physcensis.program.model import ItemCount, Program, Relation
from physcensis.program.registry import Effect
from physcensis.settings import HINT_MODES

if TYPE_CHECKING:
    from physcensis.agent.planner import OfflinePlanner
    from physcensis.assets.catalogue import Catalogue

log = logging.getLogger(__name__)

MAX_HINT_OBJECTS = MAX_GUIDED_OBJECTS  # what one guided reply can place


@dataclass(frozen=True)
class DraftObject:
    object_id: str
    description: str
    rests: str = ""  # "on ID" / "in ID" / "" (stands on the support)
    solved_id: str = ""  # its id in the solved draft (a group copy's member is named after its original)
    xy: tuple[float, float] | None = None  # where it stands in the solved draft

    def line(self) -> str:
        where = self.rests or "anywhere with room"
        if self.xy is not None and not self.rests:
            where = f"stands at x {self.xy[0]:.2f}, y {self.xy[1]:.2f}"
        return f"- {self.object_id}: {self.description} ({where})"


def draft_objects(program: Program, limit: int = MAX_HINT_OBJECTS) -> list[DraftObject]:
    """One entry per object `program` makes, in its order: declarations, PLACE-IN counts as numbered objects, and
    the members of every COPY-GROUP copy under fresh ids of their category; what each rests on or in."""
    described = {d.object_id: d.description for d in program.declarations}
    solved = {oid: oid for oid in described}
    rests: dict[str, str] = {}
    groups: dict[str, list[str]] = {}
    order = [d.object_id for d in program.declarations]
    used = set(order) | {ROOT_ID}
    for rel in program.relations:
        effect = rel.spec.effect if rel.spec else None
        if effect is Effect.GROUP and isinstance(rel.target, tuple):
            groups[str(rel.subject)] = [str(m) for m in rel.target]
        elif effect is Effect.COPY_GROUP and isinstance(rel.target, str):
            copied = _copy(groups.get(rel.target, []), described, rests, order, used)
            for old, new in copied.items():
                solved[new] = copy_member_id(solved.get(old, old), str(rel.subject))
            groups[str(rel.subject)] = list(copied.values())
        else:
            _rest(rel, described, rests, order, used)
    drafted = [DraftObject(o, described[o], rests.get(o, ""), solved.get(o, "")) for o in order if o in described]
    return drafted[:limit]


def _rest(rel: Relation, described: dict[str, str], rests: dict[str, str], order: list[str], used: set[str]) -> None:
    effect = rel.spec.effect if rel.spec else None
    if effect is Effect.ON and isinstance(rel.subject, str) and isinstance(rel.target, str) and rel.target != ROOT_ID:
        rests[rel.subject] = f"on {rel.target}"
    elif effect is Effect.IN and isinstance(rel.target, str):
        items = rel.subject if isinstance(rel.subject, tuple) else (rel.subject,)
        for item in items:
            if isinstance(item, ItemCount):
                for _ in range(max(0, item.count)):
                    oid = _fresh(item.category, used)
                    described[oid] = item.category
                    order.append(oid)
                    rests[oid] = f"in {rel.target}"
            elif isinstance(item, str):
                rests[item] = f"in {rel.target}"


def _copy(
    members: list[str], described: dict[str, str], rests: dict[str, str], order: list[str], used: set[str]
) -> dict[str, str]:
    """Fresh ids for a copy of `members`, old -> new (a copy's "on"/"in" points at the copy of its target when it
    is one)."""
    renamed = {m: _fresh(_SUFFIX.sub("", m), used) for m in members if m in described}
    for old, new in renamed.items():
        described[new] = described[old]
        order.append(new)
        where = rests.get(old, "")
        if where:
            kind, target = where.split(" ", 1)
            rests[new] = f"{kind} {renamed.get(target, target)}"
    return renamed


_SUFFIX = re.compile(r"_\d+$")


def _fresh(category: str, used: set[str]) -> str:
    slug = re.sub(r"[^a-z0-9]+", "_", category.lower()).strip("_") or "object"
    k = 0
    while f"{slug}_{k}" in used:
        k += 1
    used.add(f"{slug}_{k}")
    return f"{slug}_{k}"


@dataclass(frozen=True)
class Hint:
    """The draft shown to the model: its paragraph of the first user message, and how many objects it lists (a
    guided objects step asks for at least that many)."""

    text: str = ""
    objects: int = 0


# The planner per catalogue (reading a catalogue's vocabulary takes a second) and the drafts it made, per request:
# catalogue -> (planner, {(prompt, support, seed): hint}); the catalogue is held so its id is not reused.
_MADE: dict[int, tuple[Catalogue, OfflinePlanner, dict[tuple[str, str, int], Hint]]] = {}
MAX_DRAFTS_KEPT = 256


def reading_hint(context: AgentContext, catalogue: Catalogue | None = None) -> Hint:
    """The offline planner's objects for `context`'s request (an empty hint when it reads nothing it can list);
    made once per catalogue and request."""
    from physcensis.agent.planner import OfflinePlanner  # the planner imports the agents' shared modules
    from physcensis.assets.catalogue import default_catalogue

    catalogue = catalogue or default_catalogue()
    kept = _MADE.get(id(catalogue))
    if kept is None or kept[0] is not catalogue:
        kept = _MADE[id(catalogue)] = (catalogue, OfflinePlanner(catalogue, variety="none"), {})
    drafts = kept[2]
    key = (context.prompt, context.support.model_dump_json(), context.seed)
    if key not in drafts:
        if len(drafts) >= MAX_DRAFTS_KEPT:
            drafts.clear()
        drafts[key] = _reading_hint(context, catalogue, kept[1])
    return drafts[key]


def _reading_hint(context: AgentContext, catalogue: Catalogue, planner: OfflinePlanner) -> Hint:
    from physcensis.agent.reading import read_prompt

    first = AgentContext(prompt=context.prompt, support=context.support, vocabulary=context.vocabulary)
    try:
        planner.transcript_notes = []
        request = read_prompt(context.prompt, planner.lexicon)
        if not request.mentions and not request.diners:  # the planner would write its default scene: no reading
            return Hint()
        program = parse_program(planner.propose(first))
        drafted = _with_spots(draft_objects(program), program, context, catalogue)
    except Exception as exc:  # the draft is a courtesy: a planner failure must not end the model's run
        log.warning("no draft of the offline reading (%s)", exc)
        return Hint()
    if not drafted:
        return Hint()
    text = (
        "A rule-based reading of the description gives these objects (id: what it is (where: standing on the "
        "support at x, y; on or in another object; or anywhere with room)). Start from them: keep their ids, count "
        "and places, correct what does not fit the description, add what it asks for and they miss:\n"
        + "\n".join(d.line() for d in drafted)
    )
    return Hint(text, len(drafted))


def _with_spots(
    drafted: list[DraftObject], program: Program, context: AgentContext, catalogue: Catalogue | None
) -> list[DraftObject]:
    """The draft with where each standing object stands once the draft's layout is solved (no physics: only the
    positions, which the model may copy or change)."""
    from physcensis.solver.pipeline import solve  # the solver is heavy to import; only hints need it here

    try:
        scene = solve(program, support=context.support, catalogue=catalogue, seed=context.seed, physics=False).scene
    except Exception as exc:  # the draft is a courtesy: without spots it still gives the objects
        log.warning("the draft's layout could not be solved (%s); the draft gives no spots", exc)
        return drafted
    xy = {o.id: (float(o.position[0]), float(o.position[1])) for o in scene.objects if o.status == "placed"}
    return [replace(d, xy=xy.get(d.solved_id)) for d in drafted]


def wants_hint(mode: str, prompt_style: str) -> bool:
    """`auto` gives the draft to the compact prompt's (small) models; large models read the request themselves."""
    if mode not in HINT_MODES:
        raise ValueError(f"hint must be one of {', '.join(HINT_MODES)}, not {mode!r}")
    return mode == "on" or (mode == "auto" and prompt_style == "compact")
