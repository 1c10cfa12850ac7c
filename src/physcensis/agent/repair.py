"""Repairing a program after some of its objects failed to place: each is moved, shrunk, freed or dropped, and
what rests on it stays on it.

Which entries refer to what is read from the predicate registry (each spec's subject and target roles, its placement
kind and its reference parameters), never from predicate names, so the repaired program passes the checker whatever
predicates the program uses. An object that failed only because of another failed one (it rests on it, is placed
beside it, or only overlaps one that also sticks out) stays as it is and follows it. Each other failed object:

* sticks out past one edge, standing at a given x/y (PLACE-ON-BASE): it is pulled inwards by as much, unless that
  would put its centre off the support;
* is too large for its place (sticks out past opposite edges or cannot be pulled in far enough, "nothing there is
  large enough", "no supported spot" on its holder), fails again, or was already placed anywhere: it takes a
  smaller variant of its category from the catalogue, keeping its placement;
* otherwise is freed: placed anywhere there is room (PLACE-ANYWHERE), and what rests on it or is inside it keeps its
  placement on it, after it; what is placed beside it or turned towards it is freed too;
* is dropped only when it failed again, already placed anywhere, with no smaller variant; what rested on it is
  then freed.

Groups: a GROUP only loses dropped and freed members, and goes with its copies once none is left; a group with an
entry referring to a dropped or freed object goes with its copies (a group cannot be placed anywhere), and a copied
member goes with its original. If every object would go, the smallest version of the scene stays: the first object
of each kind, its smallest variant, placed anywhere.
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from typing import Any

from physcensis.assets.catalogue import Catalogue
from physcensis.assets.model import Asset
from physcensis.ids import ROOT_ID, copy_member_id
from physcensis.program.checker import TOO_MANY_OBJECTS, check_program
from physcensis.program.model import Declaration, Program, Relation
from physcensis.program.parser import parse_program
from physcensis.program.registry import ParamType, PlacementKind, Role, placement_spec
from physcensis.scene import Support

Entry = list[Any]
_REFERENCE_PARAMS = (ParamType.REFERENCE, ParamType.OBJECT)
# A freed object stands on the support, not on others, packed snugly: room was often what it lacked, and a random
# spot leaves less of it for the next one (six pots freed on a small table: 2 placed, not 4).
FREE_PARAMS: dict[str, Any] = {"stack": False, "pack": True}
EDGE_MARGIN_M = 0.01  # pulled this much further in than it stuck out, so it clears the edge
VARIANTS_SEARCHED = 16
_OVERHANG = re.compile(r"sticks out ([0-9.]+) cm past the (front|back|left|right) edge")
_SIDE_SHIFT = {"front": ("x", -1.0), "back": ("x", 1.0), "left": ("y", -1.0), "right": ("y", 1.0)}  # +x front, +y left
_OVERLAP = re.compile(r"overlaps (\S+) by ")
_FAILURE_LINE = re.compile(r"^- (\S+) \([^)]*\): (.*)$")
_RESTING = (PlacementKind.ON, PlacementKind.IN)


def failure_reasons(feedback: str) -> dict[str, str]:
    """Object id -> why it could not be placed, read from a solver feedback's "- id (PREDICATE): reason" lines."""
    found = {}
    for line in feedback.splitlines():
        match = _FAILURE_LINE.match(line.strip())
        if match:
            found[match.group(1)] = match.group(2)
    return found


def waited_only(feedbacks: Iterable[str]) -> set[str]:
    """The objects that, in these feedbacks, failed only because what they rest on or are placed by was missing:
    they have not been tried on their own yet."""
    waited: set[str] = set()
    own: set[str] = set()
    for text in feedbacks:
        for oid, reason in failure_reasons(text).items():
            (waited if Failure(reason).missing_holder() else own).add(oid)
    return waited - own


@dataclass(frozen=True)
class Failure:
    """Why one object failed, as the solver worded it ("" when not known)."""

    reason: str = ""

    def overhangs(self) -> dict[str, float]:
        """Edge -> metres it sticks out past that edge of the support."""
        found: dict[str, float] = {}
        for cm, side in _OVERHANG.findall(self.reason):
            found[side] = max(found.get(side, 0.0), float(cm) / 100)
        return found

    def no_room(self) -> bool:
        return "large enough" in self.reason

    def overhangs_below(self) -> bool:
        """It found no spot where its centre of mass rests over what is under it (too large for its holder)."""
        return "no supported spot" in self.reason

    def parts(self) -> list[str]:
        return [part.strip() for part in self.reason.split(";") if part.strip()]

    def overlapped(self) -> set[str]:
        """The objects it overlaps."""
        return {m.group(1) for part in self.parts() if (m := _OVERLAP.match(part))}

    def only_overlaps(self) -> bool:
        return bool(self.parts()) and all(_OVERLAP.match(part) for part in self.parts())

    def missing_holder(self) -> bool:
        """It failed only because what it rests on or is placed by is not in the scene."""
        return "is not in the scene" in self.reason

    def too_large(self) -> bool:
        """Its footprint cannot fit: nothing is large enough, or it sticks out past opposite edges at once."""
        sides = self.overhangs()
        opposite = ("front" in sides and "back" in sides) or ("left" in sides and "right" in sides)
        return self.no_room() or self.overhangs_below() or opposite

    def excess(self) -> float:
        """How much longer than the room its footprint is along the worst axis (0 when unknown)."""
        sides = self.overhangs()
        return max(sides.get("front", 0.0) + sides.get("back", 0.0), sides.get("left", 0.0) + sides.get("right", 0.0))

    def shift(self) -> dict[str, float]:
        """Axis ("x"/"y") -> how far to move it inwards, for the edges it sticks out past on one side only."""
        moves: dict[str, float] = {}
        for side, metres in self.overhangs().items():
            axis, sign = _SIDE_SHIFT[side]
            moves[axis] = moves.get(axis, 0.0) + sign * (metres + EDGE_MARGIN_M)
        return {axis: move for axis, move in moves.items() if abs(move) > EDGE_MARGIN_M}


@dataclass
class RepairPlan:
    """What happens to each object: new placement parameters, a new description, freed, or dropped."""

    shifted: dict[str, dict[str, float]] = field(default_factory=dict)  # id -> PLACE-ON-BASE params to update
    described: dict[str, str] = field(default_factory=dict)  # id -> a smaller variant's description
    freed: set[str] = field(default_factory=set)
    gone: set[str] = field(default_factory=set)  # dropped objects and groups, and ids that cannot exist any more
    first: set[str] = field(default_factory=set)  # freed objects that found no room: placed before the others


def repair_program(
    program: list[Entry],
    failed: set[str],
    tried_free: set[str],
    *,
    reasons: dict[str, str] | None = None,
    catalogue: Catalogue | None = None,
    support: Support | None = None,
) -> list[Entry]:
    """`program` repaired after the objects in `failed` could not be placed (see the module's rules). `tried_free`
    holds the objects that failed in an earlier round, `reasons` the solver's reason for each failure, `catalogue`
    the smaller variants (without it none is tried) and `support` how far an object may be pulled in. The result
    keeps at least one object whenever `program` declares one."""
    parsed = parse_program(program)
    half = (float(support.size[0]) / 2, float(support.size[1]) / 2) if support is not None else None
    inputs = _Inputs(parsed, frozenset(tried_free), reasons or {}, catalogue, half)
    plan = decide(inputs, failed)
    repaired = rewrite(parsed, plan)
    if parsed.declarations and not any(len(entry) == 2 for entry in repaired):
        return smallest_scene(parsed, catalogue)
    return repaired


@dataclass(frozen=True)
class _Inputs:
    program: Program
    tried: frozenset[str]  # failed in an earlier round
    reasons: dict[str, str]
    catalogue: Catalogue | None
    half: tuple[float, float] | None  # the support's half extents along x and y


def decide(inputs: _Inputs, failed: set[str]) -> RepairPlan:
    """What to do with each failed object, and what follows from it for the others."""
    program = inputs.program
    plan = RepairPlan(gone=set(failed) - _declared(program))  # copies and counted items cannot be moved alone
    for oid in sorted(_failed_on_their_own(program, failed) - _pushed_aside(inputs.reasons, failed)):
        _decide_one(inputs, plan, oid)
    _follow(program, plan)
    return plan


def _pushed_aside(reasons: dict[str, str], failed: set[str]) -> set[str]:
    """The failed objects that only overlap failed objects that also fail for another reason (stick out, ...):
    those move, and these stay where they are."""
    failures = {oid: Failure(reasons.get(oid, "")) for oid in failed}
    return {
        oid
        for oid, failure in failures.items()
        if failure.only_overlaps()
        and all(other in failures and not failures[other].only_overlaps() for other in failure.overlapped())
    }


def _failed_on_their_own(program: Program, failed: set[str]) -> set[str]:
    """The declared failed objects that do not refer to another declared failed one (one that rests on a failed
    holder, or is placed beside a failed anchor, fails because of it, and follows it once it is moved)."""
    declared = _declared(program)
    own = set(failed) & declared
    for rel in program.relations:
        if references(rel) & failed & declared:
            own -= set(subjects(rel))
    return own


def _decide_one(inputs: _Inputs, plan: RepairPlan, oid: str) -> None:
    program, tried = inputs.program, oid in inputs.tried
    failure = Failure(inputs.reasons.get(oid, ""))
    base, shift = _base_position(program, oid), failure.shift()
    inwards = _moved_inwards(base, shift, inputs.half)
    if not tried and inwards and not failure.too_large():
        plan.shifted[oid] = inwards
        return
    catalogue = inputs.catalogue
    smaller = _smaller_description(catalogue, _description(program, oid), failure) if catalogue else None
    anywhere = _placed_anywhere(program, oid)  # freeing it again would change nothing
    if smaller is not None and (tried or anywhere or failure.too_large() or (shift and not inwards)):
        plan.described[oid] = smaller
        if clamped := _moved_inwards(base, shift, inputs.half, clamp=True):
            plan.shifted[oid] = clamped
    elif not tried or not anywhere:  # anywhere, it may turn to fit
        plan.freed.add(oid)
        if failure.no_room():
            plan.first.add(oid)
    else:
        plan.gone.add(oid)


def _moved_inwards(
    base: Relation | None, shift: dict[str, float], half: tuple[float, float] | None, *, clamp: bool = False
) -> dict[str, float] | None:
    """The PLACE-ON-BASE coordinates moved by `shift`; None when it gives no such coordinate or, unless `clamp`ed
    (then centred on that axis), when the move would put the object's centre off the support: it is too large."""
    if base is None or not shift or not all(_is_number(base.params.get(axis)) for axis in shift):
        return None
    moved = {axis: float(base.params[axis]) + move for axis, move in shift.items()}
    if half is not None:
        limits = {"x": half[0], "y": half[1]}
        off = {axis for axis, value in moved.items() if abs(value) > limits[axis]}
        if off and not clamp:
            return None
        moved |= dict.fromkeys(off, 0.0)  # a shrunk object that still cannot be pulled in far enough: centred
    return {axis: round(value, 3) for axis, value in moved.items()}


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _follow(program: Program, plan: RepairPlan) -> None:
    """Spread the decisions: what rests on a dropped object is freed, what is placed or turned relative to a dropped
    or freed one is freed too (a group with such an entry goes), and copies go with their originals and groups."""
    declared = _declared(program)
    members = _group_members(program)
    copies = [(rel.subject, rel.target) for rel in program.relations if _copies_group(rel)]
    size = -1
    while size != len(plan.gone) + len(plan.freed):
        size = len(plan.gone) + len(plan.freed)
        for rel in program.relations:
            if _lists_members(rel):
                if set(rel.target) <= plan.gone | plan.freed:
                    plan.gone.add(rel.subject)
            elif _loses_its_place(rel, plan):
                for subject in subjects(rel):
                    (plan.freed if subject in declared else plan.gone).add(subject)
        for copy, source in copies:
            moved = plan.gone | plan.freed
            plan.gone.update(
                copy_member_id(m, copy) for m in members.get(source, ()) if m in moved or copy in plan.gone
            )
    plan.freed -= plan.gone


def _loses_its_place(rel: Relation, plan: RepairPlan) -> bool:
    """Whether the entry's subjects can no longer keep their place: it refers to a dropped object, or to a freed
    one other than as what they rest on or in."""
    refs = references(rel)
    if refs & plan.gone:
        return True
    return bool(refs & plan.freed) and not _rests(rel)


def rewrite(program: Program, plan: RepairPlan) -> list[Entry]:
    """The program with the plan applied: kept entries in their order, then each freed object placed anywhere (one
    that found no room before the first physical placement, so it is placed before the loose things fill the room),
    then the entries of what rests on or in a freed object (transitively), so each comes after its holder."""
    out = plan.gone | plan.freed
    riding = _resting_on(program, plan.freed) - out
    kept: list[Entry] = []
    moved: list[Entry] = []
    starts: dict[str, int] = {}  # where each kept object's entries start
    physical_from: int | None = None  # where the first object placed physically starts (they go in program order)
    for entry in program.entries:
        json_entry = _kept(entry, plan)
        if json_entry is None:
            continue
        if _owners(entry) & riding:
            moved.append(json_entry)
            continue
        owner_starts = [starts.setdefault(owner, len(kept)) for owner in sorted(_owners(entry))]
        if physical_from is None and _places_physically(entry):
            physical_from = min(owner_starts, default=len(kept))
        kept.append(json_entry)
    first, later = ([*_freed_entries(program, plan, ids)] for ids in (plan.first, plan.freed - plan.first))
    at = len(kept) if physical_from is None else physical_from
    return kept[:at] + first + kept[at:] + later + moved


def _freed_entries(program: Program, plan: RepairPlan, ids: set[str]) -> Iterator[Entry]:
    """Each of `ids` declared (with its new description) and placed anywhere, in declaration order."""
    for d in program.declarations:
        if d.object_id in ids:
            yield _declared_entry(d, plan)
            yield _anywhere_entry(program, d.object_id)


def _places_physically(entry: Declaration | Relation) -> bool:
    """Whether the entry is a physical placement (PLACE-ON, PLACE-IN, PLACE-ANYWHERE): these run in program order."""
    if isinstance(entry, Declaration) or entry.spec is None or entry.spec.placement is None:
        return False
    return entry.spec.placement is not PlacementKind.BASE


def _anywhere_entry(program: Program, oid: str) -> Entry:
    """The object's PLACE-ANYWHERE entry: its own when it had one (messy, stacking), else a plain one."""
    for rel in program.relations:
        if rel.subject == oid and rel.spec is not None and rel.spec.placement is PlacementKind.ANYWHERE:
            return rel.to_json()
    return [oid, placement_spec(PlacementKind.ANYWHERE).name, ROOT_ID, dict(FREE_PARAMS)]


def _resting_on(program: Program, holders: set[str]) -> set[str]:
    """The objects resting on or in one of `holders`, transitively."""
    found: set[str] = set()
    size = -1
    while size != len(found):
        size = len(found)
        for rel in program.relations:
            if _rests(rel) and isinstance(rel.target, str) and rel.target in holders | found:
                found.update(subjects(rel))
    return found


def _owners(entry: Declaration | Relation) -> set[str]:
    return {entry.object_id} if isinstance(entry, Declaration) else set(subjects(entry))


def _declared_entry(declaration: Declaration, plan: RepairPlan) -> Entry:
    return [declaration.object_id, plan.described.get(declaration.object_id, declaration.description)]


def _kept(entry: Declaration | Relation, plan: RepairPlan) -> Entry | None:
    """The entry as it stays under the plan; None when it goes (a freed object's own entries are written anew)."""
    out = plan.gone | plan.freed
    if isinstance(entry, Declaration):
        return None if entry.object_id in out else _declared_entry(entry, plan)
    if _lists_members(entry):
        return _kept_group(entry, out)
    if _loses_its_place(entry, plan):
        return None
    if isinstance(entry.subject, tuple):  # items: those that stay
        items = tuple(item for item in entry.subject if not isinstance(item, str) or item not in out)
        return dataclasses.replace(entry, subject=items).to_json() if items else None
    if entry.subject in out:
        return None
    shift = plan.shifted.get(entry.subject)
    if shift and entry.spec is not None and entry.spec.placement is PlacementKind.BASE:
        return dataclasses.replace(entry, params={**entry.params, **shift}).to_json()
    return entry.to_json()


def smallest_scene(program: Program, catalogue: Catalogue | None) -> list[Entry]:
    """The first declared object of each kind, as its smallest variant, placed anywhere: what is left of a scene
    whose every object failed."""
    anywhere = placement_spec(PlacementKind.ANYWHERE).name
    seen: set[str] = set()
    entries: list[Entry] = []
    for d in program.declarations:
        kind = catalogue.resolve(d.description).category if catalogue else d.description
        if kind in seen:
            continue
        seen.add(kind)
        smallest = _smallest_description(catalogue, d.description) if catalogue else None
        entries += [[d.object_id, smallest or d.description], [d.object_id, anywhere, ROOT_ID, dict(FREE_PARAMS)]]
    return entries


# ---- smaller variants ------------------------------------------------------------------------------------------------


def _footprint(asset: Asset) -> float:
    return float(asset.size[0] * asset.size[1])


def _smaller_variants(catalogue: Catalogue, description: str) -> list[Asset]:
    """The catalogue's variants of the description's category with a smaller footprint than the asset it names,
    largest first; only those whose own description names them again (the program refers to them by it)."""
    current = catalogue.resolve(description)
    variants = [
        a
        for a in catalogue.variants(description, VARIANTS_SEARCHED)
        if a.category == current.category and _footprint(a) < _footprint(current) * 0.98
    ]
    named = [a for a in variants if catalogue.resolve(a.description).id == a.id]
    return sorted(named, key=_footprint, reverse=True)


def _smaller_description(catalogue: Catalogue, description: str, failure: Failure) -> str | None:
    """A smaller variant: the smallest when nothing was large enough, else the largest that is short enough by
    the length it stuck out (the next smaller one when that is not known)."""
    smaller = _smaller_variants(catalogue, description)
    if not smaller:
        return None
    if failure.no_room():
        return smaller[-1].description
    longest = max(catalogue.resolve(description).size[:2])
    short_enough = [a for a in smaller if max(a.size[:2]) <= longest - failure.excess()]
    return (short_enough or smaller[-1:])[0].description


def _smallest_description(catalogue: Catalogue, description: str) -> str | None:
    smaller = _smaller_variants(catalogue, description)
    return smaller[-1].description if smaller else None


# ---- reading the program ---------------------------------------------------------------------------------------------


def _declared(program: Program) -> set[str]:
    return {d.object_id for d in program.declarations}


def _description(program: Program, oid: str) -> str:
    return next(d.description for d in program.declarations if d.object_id == oid)


def _base_position(program: Program, oid: str) -> Relation | None:
    """The object's PLACE-ON-BASE entry, when it gives it an x or a y."""
    for rel in program.relations:
        placement = rel.spec.placement if rel.spec is not None else None
        numbers = {k for k, v in rel.params.items() if _is_number(v)}
        if rel.subject == oid and placement is PlacementKind.BASE and {"x", "y"} & numbers:
            return rel
    return None


def _placed_anywhere(program: Program, oid: str) -> bool:
    return any(
        rel.subject == oid and rel.spec is not None and rel.spec.placement is PlacementKind.ANYWHERE
        for rel in program.relations
    )


def _rests(rel: Relation) -> bool:
    """Whether the entry puts its subjects on or in its target (PLACE-ON, PLACE-IN)."""
    return rel.spec is not None and rel.spec.placement in _RESTING


def subjects(rel: Relation) -> tuple[str, ...]:
    """The objects or groups an entry places or makes: its subject, or each listed object of an items subject."""
    if isinstance(rel.subject, str):
        return (rel.subject,)
    if isinstance(rel.subject, tuple):
        return tuple(item for item in rel.subject if isinstance(item, str))
    return ()


def references(rel: Relation) -> set[str]:
    """The ids an entry refers to besides its subjects (root left out): its target, or its members, and the
    values of its reference parameters."""
    refs: set[str] = set()
    if isinstance(rel.target, str):
        refs.add(rel.target)
    elif isinstance(rel.target, tuple):
        refs.update(rel.target)
    refs.update(_reference_params(rel).values())
    refs.discard(ROOT_ID)
    return refs


def _kept_group(rel: Relation, gone: set[str]) -> Entry | None:
    """A GROUP without its members that are gone (and without a reference parameter, its anchor, naming one)."""
    if rel.subject in gone:
        return None
    members = tuple(m for m in rel.target if m not in gone)
    params = {k: v for k, v in rel.params.items() if k not in _reference_params(rel) or v not in gone}
    return dataclasses.replace(rel, target=members, params=params).to_json()


def _reference_params(rel: Relation) -> dict[str, str]:
    """Name -> id of the entry's parameters that refer to an object, group or root."""
    if rel.spec is None:
        return {}
    found = {}
    for name, value in rel.params.items():
        param = rel.spec.param(name) if isinstance(name, str) else None
        if param is not None and param.type in _REFERENCE_PARAMS and isinstance(value, str):
            found[name] = value
    return found


def _lists_members(rel: Relation) -> bool:
    """Whether the entry makes a group of the objects it lists (GROUP)."""
    return rel.spec is not None and Role.MEMBERS in rel.spec.target and isinstance(rel.target, tuple)


def _copies_group(rel: Relation) -> bool:
    """Whether the entry makes a new group as a copy of another (COPY-GROUP)."""
    spec = rel.spec
    return (
        spec is not None
        and Role.NEW_GROUP in spec.subject
        and Role.GROUP in spec.target
        and isinstance(rel.subject, str)
        and isinstance(rel.target, str)
    )


def _group_members(program: Program) -> dict[str, tuple[str, ...]]:
    """Group id -> its members as the program makes them (a copy's members named after the originals)."""
    members: dict[str, tuple[str, ...]] = {}
    for rel in program.relations:
        if _lists_members(rel) and isinstance(rel.subject, str):
            members[rel.subject] = rel.target
        elif _copies_group(rel):
            members[rel.subject] = tuple(copy_member_id(m, rel.subject) for m in members.get(rel.target, ()))
    return members


# ---- the object limit ------------------------------------------------------------------------------------------------


def within_objects(program: list[Entry], support: Support, max_objects: int) -> tuple[list[Entry], list[str]]:
    """`program` with its last objects dropped until it makes at most `max_objects` objects (declared, copied and
    counted in PLACE-IN, as the checker counts them); what rests on or is placed beside a dropped object is dropped or
    freed as in a repair. Also the ids dropped, in program order."""
    dropped: list[str] = []
    for _ in range(max(1, len(program))):  # each pass drops at least one object or group
        parsed = parse_program(program)
        report = check_program(parsed, support, max_objects=max_objects)
        over = next((p.index for p in report.problems if p.rule == TOO_MANY_OBJECTS), None)
        if over is None:
            break
        plan = RepairPlan(gone=_made_from(parsed, over))
        _follow(parsed, plan)
        dropped += [d.object_id for d in parsed.declarations if d.object_id in plan.gone]
        program = rewrite(parsed, plan)
    return program, dropped


def _made_from(program: Program, index: int | None) -> set[str]:
    """The objects declared at or after entry `index` (where the program passes the limit), and what that entry
    itself makes (a PLACE-IN count or a group's copy)."""
    start = index if index is not None else 0
    gone = {d.object_id for d in program.declarations if d.index >= start}
    gone |= {s for rel in program.relations if rel.index == start for s in subjects(rel)}
    return gone or {program.declarations[-1].object_id}
