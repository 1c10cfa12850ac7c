"""Check a program before solving: every problem at once, each worded for the agent.

Errors stop the solver; warnings point at style the paper's agent is asked to
follow (contiguous entries per object, spatial -> PLACE-ON -> PLACE-ANYWHERE order).
"""

from __future__ import annotations

import itertools
import math
from collections import Counter
from collections.abc import Collection
from dataclasses import dataclass, field
from typing import Any

from physcensis.errors import PhyscensisError
from physcensis.ids import (
    GROUP_PREFIX,
    ID_RULE,
    PIN_PREFIX,
    RESERVED_IDS,
    ROOT_ID,
    close_match,
    copy_member_id,
    is_reserved_id,
    is_valid_id,
    pinned_id,
)
from physcensis.program.model import Declaration, ItemCount, Problem, ProblemLog, Program, Relation, describe
from physcensis.program.registry import (
    ALL_AXES,
    AXIS_WORDS,
    STABILITY_WORDS,
    Axis,
    Effect,
    ParamSpec,
    ParamType,
    PlacementKind,
    PredicateSpec,
    Role,
    axis_rules,
    closest_name,
    complete_placements,
    effect_spec,
    placement_names,
    placement_spec,
)
from physcensis.scene import MAX_SCENE_OBJECTS, Support

MAX_ITEM_COUNT = 200
TOO_MANY_OBJECTS = "too-many-objects"  # the rule of the problem a program over its object limit gets
DEFAULT_MAX_OBJECTS = 500  # objects a program may make: declared, copied by COPY-GROUP and made by PLACE-IN counts
MAX_OBJECTS = MAX_SCENE_OBJECTS  # the highest limit that can be asked for: what one scene may hold
MAX_TEXT_CHARS = 2000  # a description or PLACE-IN category: one sentence, far below what a scene may store
MAX_SUGGESTIONS = 20  # "did you mean" close matches are searched for the first this many unknown names of a kind


@dataclass
class _ObjectState:
    index: int  # where it was introduced
    axes: dict[Axis, int] = field(default_factory=dict)  # axis -> entry that determined it
    placement: PlacementKind | None = None
    placement_index: int | None = None
    position_rules: list[tuple[int, str]] = field(default_factory=list)
    entries: list[int] = field(default_factory=list)  # entries where it is the subject

    @property
    def decided(self) -> bool:
        """Whether a placement decides everything about it (its axes are then not tracked)."""
        return self.placement is not None and self.placement.decides_everything

    @property
    def rank(self) -> int:
        return self.placement.rank if self.placement is not None else 0


@dataclass(frozen=True)
class CheckReport:
    problems: tuple[Problem, ...]

    @property
    def errors(self) -> list[Problem]:
        return [p for p in self.problems if p.severity == "error"]

    @property
    def warnings(self) -> list[Problem]:
        return [p for p in self.problems if p.severity == "warning"]

    @property
    def ok(self) -> bool:
        return not self.errors

    def summary(self) -> str:
        return f"{len(self.errors)} errors, {len(self.warnings)} warnings"

    def feedback(self) -> str:
        """All problems as lines of text for an agent."""
        return "\n".join(str(p) for p in self.problems)


class _Checker:
    def __init__(
        self, program: Program, support: Support | None, max_objects: int, assets: Collection[str] | None = None
    ) -> None:
        self.program = program
        self.assets = assets  # asset ids a pinned description may name (None: not checked)
        self.support = support or program.support
        self.max_objects = max_objects
        self.object_count = 0  # objects the program makes so far, copies and PLACE-IN counts included
        self.over_limit = False
        self.overridden: set[tuple[str, Axis]] = set()
        self.suggestions: dict[str, int] = {}  # kind -> close-match searches done (each costs O(known names))
        # PLACE-IN entries that make objects by count: (ids they also drop, objects made); a COPY-GROUP of
        # all those ids repeats the count (the solver copies such a request with the group).
        self.counted_drops: list[tuple[tuple[str, ...], int]] = []
        self.problems = ProblemLog(program.read_problems)
        self.objects: dict[str, _ObjectState] = {}
        self.groups: dict[str, tuple[str, ...]] = {}
        self.group_entries: dict[str, list[int]] = {}
        self.first_seen: dict[str, int] = {}  # every id anywhere in the program, for "not yet" vs "never"
        for entry in program.entries:
            if isinstance(entry, Declaration):
                self.first_seen.setdefault(entry.object_id, entry.index)
            elif entry.spec is not None and Role.NEW_GROUP in entry.spec.subject and isinstance(entry.subject, str):
                self.first_seen.setdefault(entry.subject, entry.index)

    # -- reporting -----------------------------------------------------------
    def error(self, index: int | None, obj: str | None, message: str, rule: str) -> None:
        self.problems.append(Problem(index, obj, "error", message, rule))

    def warning(self, index: int | None, obj: str | None, message: str, rule: str) -> None:
        self.problems.append(Problem(index, obj, "warning", message, rule))

    def may_suggest(self, kind: str) -> bool:
        """Whether to search close matches for one more unknown name of `kind`: only for the first few, so that
        thousands of unknown names cost linear time, not thousands of searches over every known name."""
        done = self.suggestions.get(kind, 0)
        self.suggestions[kind] = done + 1
        return done < MAX_SUGGESTIONS

    # -- size ------------------------------------------------------------------
    def count_objects(self, index: int, obj: str | None, made: int, how: str) -> bool:
        """Count `made` new objects; past the limit, report it once and return False (make nothing more)."""
        if self.over_limit:
            return False
        self.object_count += made
        if self.object_count <= self.max_objects:
            return True
        self.over_limit = True
        self.error(
            index,
            obj,
            f"this entry brings the program to more than {self.max_objects} objects "
            f"({self.object_count} so far; {how}): declared objects, {effect_spec(Effect.COPY_GROUP).name} copies "
            f"and {placement_spec(PlacementKind.IN).name} counts "
            f"together may be at most {self.max_objects} (raise the limit with --max-objects, or max_objects= "
            "in Python)",
            TOO_MANY_OBJECTS,
        )
        return False

    # -- references ------------------------------------------------------------
    def _unknown_reference(self, index: int, obj: str | None, ref: str, role_text: str) -> None:
        later = self.first_seen.get(ref)
        if later is not None and later > index:
            self.error(
                index,
                obj,
                f"{role_text} {ref!r} is introduced only later, at #{later}; "
                "refer only to root or to objects introduced earlier",
                "not-yet-introduced",
            )
            return
        close = close_match(ref, [*self.objects, *self.groups, ROOT_ID]) if self.may_suggest("reference") else None
        hint = f" (did you mean {close!r}?)" if close else ""
        self.error(
            index,
            obj,
            f'{role_text} {ref!r} is never introduced{hint}; declare it first with [{ref!r}, "description"]',
            "never-introduced",
        )

    def reference(
        self, index: int, obj: str | None, ref: Any, roles: frozenset[Role], role_text: str, spec: PredicateSpec
    ) -> bool:
        """Check that `ref` is a known id of an allowed role; report and return False if not."""
        if not isinstance(ref, str):
            self.error(index, obj, f"{role_text} must be an id, got {describe(ref)}", "bad-reference")
            return False
        if ref == obj and ref != ROOT_ID:
            self.error(index, obj, f"{spec.name} relates {obj} to itself; pick another object", "self-reference")
            return False
        found = self.role_of(ref)
        if found is None:
            self.unknown(index, obj, ref, role_text, spec)
            return False
        if found in roles:
            return True
        self.refuse_role(index, obj, ref, found, roles, role_text, spec)
        return False

    def role_of(self, ref: str) -> Role | None:
        """What a known id is (root, a group or an object), or None for an id nothing introduced."""
        if ref == ROOT_ID:
            return Role.ROOT
        if ref in self.groups:
            return Role.GROUP
        return Role.OBJECT if ref in self.objects else None

    def unknown(self, index: int, obj: str | None, ref: str, role_text: str, spec: PredicateSpec) -> None:
        if spec.effect is Effect.COPY_GROUP:
            self.error(
                index,
                obj,
                f"{spec.name} of unknown group {ref!r}; define it first with "
                f'[{ref!r}, "{effect_spec(Effect.GROUP).name}", [members], {{"anchor": member}}]',
                "copy-unknown-group",
            )
        else:
            self._unknown_reference(index, obj, ref, role_text)

    def refuse_role(
        self,
        index: int,
        obj: str | None,
        ref: str,
        found: Role,
        roles: frozenset[Role],
        role_text: str,
        spec: PredicateSpec,
    ) -> None:
        """Report a known id of a role that this slot does not take, in the words most useful for `spec`."""
        allowed = _roles_text(roles)
        if found is Role.ROOT and spec.effect is Effect.ON:
            base = placement_spec(PlacementKind.BASE).name
            self.error(
                index,
                obj,
                f"{spec.name} cannot target root: use {base} to stand on the support, "
                f"{spec.name} only to rest on another object",
                "place-on-root",
            )
        elif found is Role.ROOT:
            self.error(index, obj, f"{spec.name}'s {role_text} cannot be root; it must be {allowed}", "bad-reference")
        elif found is Role.GROUP:
            self.error(
                index, obj, f"{spec.name}'s {role_text} {ref!r} is a group; it must be {allowed}", "group-not-allowed"
            )
        elif Role.GROUP in roles and spec.effect is Effect.COPY_GROUP:
            self.error(
                index,
                obj,
                f"{spec.name} of unknown group {ref!r}: {ref} is an object, not a group; make a group first with "
                f"{effect_spec(Effect.GROUP).name}",
                "copy-unknown-group",
            )
        elif Role.ROOT in roles and spec.effect is Effect.ANYWHERE:
            self.error(index, obj, f'{spec.name} takes "root" as its target, not {ref!r}', "bad-reference")
        else:
            self.error(
                index, obj, f"{spec.name}'s {role_text} must be {allowed}, not the object {ref!r}", "bad-reference"
            )

    # -- parameters --------------------------------------------------------------
    def params(self, rel: Relation, spec: PredicateSpec, obj: str | None) -> None:
        for name, value in rel.params.items():
            if not isinstance(name, str):
                self.error(
                    rel.index, obj, f"{spec.name}'s parameter names must be text, got {describe(name)}", "unknown-param"
                )
                continue
            param = spec.param(name)
            if param is None:
                options = [p.name for p in spec.params]
                close = close_match(name, options, cutoff=0.5) if self.may_suggest("param") else None
                hint = f"; did you mean {close!r}?" if close else ""
                allowed = ", ".join(options) if options else "none"
                self.error(
                    rel.index,
                    obj,
                    f"{spec.name} has no parameter {name!r}{hint} (its parameters: {allowed})",
                    "unknown-param",
                )
                continue
            self.param_value(rel, spec, obj, param, value)
        for param in spec.params:
            if param.required and param.name not in rel.params:
                self.error(
                    rel.index,
                    obj,
                    f"{spec.name} needs the parameter {param.name!r}: {param.description}",
                    "missing-param",
                )

    def param_value(self, rel: Relation, spec: PredicateSpec, obj: str | None, param: ParamSpec, value: Any) -> None:
        name = f"{rel.predicate}'s {param.name}"
        if param.type is ParamType.NUMBER:
            self.number_param(rel.index, obj, name, param, value)
        elif param.type is ParamType.STABILITY:
            self.stability_param(rel.index, obj, name, value)
        elif param.type is ParamType.BOOL:
            if not isinstance(value, bool):
                self.error(rel.index, obj, f"{name} must be true or false, got {describe(value)}", "param-type")
        elif param.type in (ParamType.REFERENCE, ParamType.OBJECT):
            roles = (
                frozenset({Role.OBJECT})
                if param.type is ParamType.OBJECT
                else frozenset({Role.OBJECT, Role.GROUP, Role.ROOT})
            )
            self.reference(rel.index, obj, value, roles, f"parameter {param.name}", spec)

    def number_param(self, index: int, obj: str | None, name: str, param: ParamSpec, value: Any) -> None:
        if value is None:
            return
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            self.error(index, obj, f"{name} must be a number, got {describe(value)}", "param-type")
            return
        self.number_range(index, obj, name, param, value)

    def stability_param(self, index: int, obj: str | None, name: str, value: Any) -> None:
        if isinstance(value, str) and value.strip().lower() in STABILITY_WORDS:
            return
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            if not (math.isfinite(value) and 0.0 <= value <= 1.0):
                self.error(
                    index,
                    obj,
                    f"{name} as a number is a probability of falling in [0, 1], got {_number_text(value)}",
                    "param-range",
                )
            return
        self.error(
            index,
            obj,
            f'{name} must be "stable", "unstable" or a probability in [0, 1], got {describe(value)}',
            "param-type",
        )

    def number_range(self, index: int, obj: str | None, name: str, param: ParamSpec, raw: float) -> None:
        unit = f" {param.unit}" if param.unit else ""
        value = float(raw)  # ints of at most 300 digits (the parser replaces larger ones), so never overflows
        if not math.isfinite(value):
            self.error(index, obj, f"{name} must be a finite number, got {raw!r}", "param-range")
            return
        if param.low is not None and param.high is not None and not param.low <= value <= param.high:
            self.error(
                index,
                obj,
                f"{name} = {value:g}{unit} is outside its range [{param.low:g}, {param.high:g}]{unit}",
                "param-range",
            )
            return
        if param.bounded_by_support and self.support is not None:
            half = self.support.half_extents[0 if param.bounded_by_support == "x" else 1]
            if abs(value) > half:
                self.error(
                    index,
                    obj,
                    f"{name} = {value:g} m lies off the support, whose {param.bounded_by_support} "
                    f"runs from {-half:g} to {half:g} m",
                    "param-range",
                )

    # -- entries -------------------------------------------------------------------
    def declaration(self, decl: Declaration) -> None:
        oid = decl.object_id
        if oid == ROOT_ID:
            self.error(decl.index, oid, '"root" is the support\'s name; give the object another id', "reserved-id")
            return
        if is_reserved_id(oid):
            self.error(
                decl.index,
                oid,
                f"{oid!r} is reserved ({', '.join(RESERVED_IDS)} name parts of every "
                "exported scene); give the object another id",
                "reserved-id",
            )
            return
        if not is_valid_id(oid):
            self.error(decl.index, oid, f"id {describe(oid)} is not valid: use {ID_RULE}", "bad-id")
        if oid in self.objects or oid in self.groups:
            first = self.objects[oid].index if oid in self.objects else self.first_seen.get(oid)
            self.error(
                decl.index,
                oid,
                f"{oid} is declared twice (first at #{first}); give the new object its own id",
                "duplicate-object",
            )
            return
        if oid.startswith(GROUP_PREFIX):
            self.warning(decl.index, oid, f"ids starting with {GROUP_PREFIX!r} are meant for groups", "group-prefix")
        if not decl.description.strip():
            self.error(
                decl.index,
                oid,
                f"{oid} has no description; write one sentence describing the object so an asset can be found",
                "no-description",
            )
        elif problem := text_problem(decl.description):
            self.error(decl.index, oid, f"the description of {oid} {problem}", "bad-description")
        else:
            self.pinned_asset(decl)
        self.count_objects(decl.index, oid, 1, f"{oid} is declared")
        state = _ObjectState(decl.index)
        state.entries.append(decl.index)
        self.objects[oid] = state

    def pinned_asset(self, decl: Declaration) -> None:
        """A description "asset:ID" must name an asset id (one the catalogue has, when the checker knows them)."""
        asset_id = pinned_id(decl.description)
        if asset_id is None:
            return
        oid = decl.object_id
        if not is_valid_id(asset_id):
            self.error(
                decl.index,
                oid,
                f"{oid}'s description {describe(decl.description)} pins no valid asset id: write {PIN_PREFIX}ID "
                "with an id from `physcensis assets list`, or describe the object in words",
                "bad-asset-pin",
            )
        elif self.assets is not None and asset_id not in self.assets:
            close = close_match(asset_id, self.assets) if self.may_suggest("asset") else None
            hint = f"; did you mean {close!r}?" if close else " (is its library loaded? see --library)"
            self.error(
                decl.index,
                oid,
                f"{oid} pins asset {asset_id!r}, which the catalogue does not have{hint}",
                "unknown-asset",
            )

    def relation(self, rel: Relation) -> None:
        spec = rel.spec
        subject = rel.subject if isinstance(rel.subject, str) else None
        if spec is None:
            close = closest_name(rel.predicate) if self.may_suggest("predicate") else None
            hint = f"; did you mean {close}?" if close else ""
            self.error(rel.index, subject, f"unknown predicate {rel.predicate!r}{hint}", "unknown-predicate")
            return
        if Role.NEW_GROUP in spec.subject:
            self.group_entry(rel, spec)
            return
        if Role.ITEMS in spec.subject:
            self.place_in(rel, spec)
            return
        assert subject is not None
        is_group = subject in self.groups
        if is_group:
            self.group_entries.setdefault(subject, []).append(rel.index)
            if Role.GROUP not in spec.subject:
                self.error(
                    rel.index,
                    subject,
                    f"{spec.name} cannot be used on a group ({subject}); use it on single objects",
                    "group-subject",
                )
                return
        known = is_group or subject in self.objects
        if not known:
            self.subject_missing(rel, subject)  # and still check the rest of the entry
        if Role.MEMBERS not in spec.target:
            self.reference(rel.index, subject, rel.target, spec.target, "target", spec)
        self.params(rel, spec, subject)
        if known and not is_group:
            self.apply(rel, spec, subject)

    def subject_missing(self, rel: Relation, subject: str) -> None:
        later = self.first_seen.get(subject)
        if later is not None and later > rel.index:
            self.error(
                rel.index,
                subject,
                f"{subject} is used before it is declared at #{later}; declare each object before its predicates",
                "not-yet-introduced",
            )
        else:
            self.error(
                rel.index,
                subject,
                f'{subject} has no description: declare it first with [{subject!r}, "one sentence describing it"]',
                "no-description",
            )

    def apply(self, rel: Relation, spec: PredicateSpec, subject: str) -> None:
        state = self.objects[subject]
        state.entries.append(rel.index)
        if spec.placement is not None:
            if state.placement is not None and state.placement != spec.placement:
                self.error(
                    rel.index,
                    subject,
                    f"{subject} is already placed by "
                    f"{placement_spec(state.placement).name} at #{state.placement_index}; an object takes "
                    f"one of {_either(placement_names())}",
                    "conflicting-placement",
                )
            state.placement = spec.placement
            state.placement_index = rel.index
        if spec.sets_position and spec.axes_determined(rel.params) & {Axis.X, Axis.Y}:
            state.position_rules.append((rel.index, spec.name))
        if spec.placement is not None and spec.placement.decides_everything:
            return  # decides everything itself; completeness is judged from `placement`
        refines = spec.yaw is not None and spec.yaw.mode.refines
        determined = spec.axes_determined(rel.params)
        for axis in (a for a in Axis if a in determined):  # in a fixed order: the set's order varies between runs
            earlier = state.axes.get(axis)
            if earlier is not None and not refines and (subject, axis) not in self.overridden:
                self.overridden.add((subject, axis))  # once per object and axis: thousands of lines help no one
                self.warning(
                    rel.index,
                    subject,
                    f"{AXIS_WORDS[axis]} of {subject} was already set at #{earlier}; {spec.name} here overrides it",
                    "override",
                )
            state.axes[axis] = rel.index

    def place_in(self, rel: Relation, spec: PredicateSpec) -> None:
        container = rel.target if isinstance(rel.target, str) else None
        self.reference(rel.index, None, rel.target, spec.target, "container", spec)
        self.params(rel, spec, container)
        items = rel.subject if isinstance(rel.subject, tuple) else (rel.subject,)
        made = 0
        for item in items:
            if isinstance(item, ItemCount):
                made += self.item_count(rel, spec, container, item)
                continue
            if item == container:
                self.error(rel.index, item, f"{item} cannot be placed in itself", "self-reference")
                continue
            if item not in self.objects:
                if item in self.groups:
                    self.error(rel.index, item, f"{spec.name} takes objects, not the group {item}", "group-subject")
                else:
                    self.subject_missing(rel, item)
                continue
            self.apply(rel, spec, item)
        if made:
            self.count_objects(rel.index, container, made, f"{spec.name} makes {made}")
            self.counted_drops.append((tuple(i for i in items if isinstance(i, str)), made))

    def item_count(self, rel: Relation, spec: PredicateSpec, container: str | None, item: ItemCount) -> int:
        """How many objects a [category, count] item makes (0 if it is wrong, reported)."""
        if not item.category.strip():
            self.error(rel.index, container, f"{spec.name} item category is empty", "bad-items")
        elif problem := text_problem(item.category):
            self.error(
                rel.index, container, f"{spec.name} item category {describe(item.category)} {problem}", "bad-items"
            )
        if not 1 <= item.count <= MAX_ITEM_COUNT:
            self.error(
                rel.index,
                container,
                f"{spec.name} count for {describe(item.category)} is "
                f"{_number_text(item.count)}; it must be between 1 and {MAX_ITEM_COUNT}",
                "param-range",
            )
            return 0
        return item.count

    def group_entry(self, rel: Relation, spec: PredicateSpec) -> None:
        name = rel.subject
        if not isinstance(name, str):
            self.error(rel.index, None, f"{spec.name}'s first element must be a new group name", "bad-group-name")
            return
        ok = self.new_group_name(rel, name)
        self.params(rel, spec, name)
        if spec.effect is Effect.COPY_GROUP:
            self.copy_group(rel, spec, name, ok)
        else:
            self.make_group(rel, name, ok)

    def new_group_name(self, rel: Relation, name: str) -> bool:
        """Whether `name` can name a new group; report why not."""
        ok = True
        if not name.startswith(GROUP_PREFIX):
            self.error(
                rel.index,
                name,
                f"group name {describe(name)} must start with {GROUP_PREFIX!r}, e.g. {GROUP_PREFIX}{name}",
                "group-name",
            )
            ok = False
        if not is_valid_id(name):
            self.error(rel.index, name, f"group name {describe(name)} is not valid: use {ID_RULE}", "bad-id")
            ok = False
        if name in self.groups or name in self.objects:
            self.error(rel.index, name, f"{name} already exists; a new group needs a fresh name", "duplicate-object")
            ok = False
        return ok

    def make_group(self, rel: Relation, name: str, ok: bool) -> None:
        members = rel.target if isinstance(rel.target, tuple) else ()
        if not members:
            self.error(rel.index, name, f"{rel.predicate} needs at least one member", "bad-members")
            ok = False
        for member in members:
            if member in self.groups:
                self.error(
                    rel.index,
                    name,
                    f"{member} is a group; groups of groups are not supported, list its objects instead",
                    "group-not-allowed",
                )
                ok = False
            elif member not in self.objects:
                self._unknown_reference(rel.index, name, member, "member")
                ok = False
        if len(set(members)) != len(members):
            self.error(rel.index, name, f"{rel.predicate} lists a member twice", "bad-members")
        anchor = rel.params.get("anchor")
        if isinstance(anchor, str) and anchor in self.objects and anchor not in members:
            self.error(rel.index, name, f"the anchor {anchor} is not one of the group's members", "bad-anchor")
        if ok:
            self.groups[name] = tuple(members)
            self.group_entries[name] = [rel.index]

    def copy_group(self, rel: Relation, spec: PredicateSpec, name: str, ok: bool) -> None:
        source = rel.target
        if not self.reference(rel.index, name, source, spec.target, "group to copy", spec) or not ok:
            return
        if self.over_limit or not self.count_objects(
            rel.index, name, self.copied_count(self.groups[source]), f"copying {source}"
        ):
            self.groups[name] = ()  # known, so later entries are not reported as unknown; but makes nothing
            return
        copies = self.copy_ids(rel, name, self.groups[source])
        if copies is None:
            return
        for member, new_id in zip(self.groups[source], copies, strict=True):
            original = self.objects[member]
            copy = _ObjectState(rel.index, placement=original.placement, placement_index=rel.index)
            copy.axes = {axis: rel.index for axis in original.axes}
            self.objects[new_id] = copy
        self.groups[name] = tuple(copies)
        self.group_entries[name] = [rel.index]
        self.copy_drops(self.groups[source], name)

    def copy_ids(self, rel: Relation, name: str, members: tuple[str, ...]) -> list[str] | None:
        """The ids of the copies of `members` in the new group `name`, or None (reported) if one cannot be used."""
        copies: list[str] = []
        for member in members:
            new_id = copy_member_id(member, name)
            if not is_valid_id(new_id):
                self.error(
                    rel.index,
                    name,
                    f"the copy of {member} would be named {new_id!r}, which is not a valid "
                    f"id ({ID_RULE}); use shorter names",
                    "bad-id",
                )
                return None
            if new_id in self.objects:
                self.error(
                    rel.index,
                    name,
                    f"the copy of {member} would be named {new_id}, which already exists",
                    "duplicate-object",
                )
                return None
            copies.append(new_id)
        return copies

    def copied_count(self, members: tuple[str, ...]) -> int:
        """Objects a COPY-GROUP of `members` makes: one per member, plus the PLACE-IN counts it repeats."""
        inside = set(members)
        return len(members) + sum(n for ids, n in self.counted_drops if ids and inside.issuperset(ids))

    def copy_drops(self, members: tuple[str, ...], new_group: str) -> None:
        inside = set(members)
        copied = [
            (tuple(copy_member_id(i, new_group) for i in ids), n)
            for ids, n in self.counted_drops
            if ids and inside.issuperset(ids)
        ]
        self.counted_drops.extend(copied)

    # -- whole-program rules -------------------------------------------------------
    def finish(self) -> None:
        for oid, state in self.objects.items():
            if state.decided and state.position_rules:
                index, rule = state.position_rules[0]
                placement = placement_spec(state.placement).name if state.placement else "a placement"
                self.error(
                    index,
                    oid,
                    f"{oid} is placed by {placement} (#{state.placement_index}), which decides "
                    f"its position; remove {rule} (2-D position predicates cannot be mixed with it)",
                    "position-with-physical",
                )
            elif not state.decided:
                self.completeness(oid, state)
        self.contiguity()
        self.ordering()

    def completeness(self, oid: str, state: _ObjectState) -> None:
        """Report the axes of `oid` that none of its predicates determine, with the predicates that would."""
        missing = [axis for axis in Axis if axis not in state.axes]
        if not missing:
            return
        words = " and ".join(AXIS_WORDS[a] for a in missing)
        rules = axis_rules()
        hints = "; ".join(f"{a.value}: {_either(rules[a])}" for a in missing)
        lead = f"{oid} has no predicates" if len(missing) == len(ALL_AXES) else f"{oid} is not fully solved"
        self.error(
            state.index,
            oid,
            f"{lead}: its {words} {'is' if len(missing) == 1 else 'are'} "
            f"undetermined. Add {hints}; or let {'/'.join(complete_placements())} decide everything",
            "not-fully-solved",
        )

    def contiguity(self) -> None:
        spans = {oid: s.entries for oid, s in self.objects.items()} | self.group_entries
        # An entry of several objects (PLACE-IN of a list of ids) cannot sit next to each one's own entries: it
        # splits none of them.
        uses = Counter(index for entries in spans.values() for index in entries)
        spans = {oid: [i for i in entries if uses[i] == 1] for oid, entries in spans.items()}
        owner_of: dict[int, str] = {}
        for oid, entries in spans.items():
            for index in entries:
                owner_of.setdefault(index, oid)
        # owned_before[i]: how many entries before #i belong to someone; an object's own entries are never strictly
        # between two of its consecutive ones, so any owned entry there is another object's.
        last = max(owner_of, default=0)
        owned_before = list(itertools.accumulate((i in owner_of for i in range(last + 1)), initial=0))
        for oid, entries in spans.items():
            for before, after in zip(entries, entries[1:], strict=False):
                if after > before + 1 and owned_before[after] - owned_before[before + 1] > 0:
                    self.warning(
                        after,
                        oid,
                        f"{oid}'s entries are split (#{before} and #{after} have other "
                        "objects' entries between them); keep each object's entries together",
                        "contiguity",
                    )
                    break

    def ordering(self) -> None:
        highest_rank, highest_at, highest_obj = 0, 0, ""
        warned: set[str] = set()
        for entry in self.program.entries:
            if not isinstance(entry, Relation) or entry.spec is None:
                continue
            rank, owner = self.rank_of(entry, entry.spec)
            if rank < highest_rank and owner not in warned:
                warned.add(owner)
                kind = "/".join(placement_names(rank=highest_rank))
                self.warning(
                    entry.index,
                    owner,
                    f"{owner}'s predicate comes after the {kind} placement of "
                    f"{highest_obj} (#{highest_at}); order a program as spatial predicates first, "
                    f"then {' and '.join(placement_names(rank=1))}, "
                    f"then {' and '.join(placement_names(rank=2))}",
                    "ordering",
                )
            if rank > highest_rank:
                highest_rank, highest_at, highest_obj = rank, entry.index, owner

    def rank_of(self, rel: Relation, spec: PredicateSpec) -> tuple[int, str]:
        """Where an entry belongs in the paper's order (its object's placement rank), and whose entry it is."""
        if Role.ITEMS in spec.subject:  # PLACE-IN: the container's entry
            return (spec.placement.rank if spec.placement else 0), str(rel.target)
        if isinstance(rel.subject, str) and rel.subject in self.objects:
            return self.objects[rel.subject].rank, rel.subject
        return 0, str(rel.subject)

    def run(self) -> CheckReport:
        for entry in self.program.entries:
            if isinstance(entry, Declaration):
                self.declaration(entry)
            else:
                self.relation(entry)
            if self.over_limit:
                break  # one clear error at the entry that crosses the limit; the rest is not worth analysing
        if not self.over_limit:
            self.finish()
        order = self.problems.listed(lambda p: (p.index is not None, p.index or 0, p.severity != "error"))
        return CheckReport(order)


def text_problem(text: str) -> str | None:
    """Why a description-like text cannot be used (too long, not writable as UTF-8), or None."""
    if len(text) > MAX_TEXT_CHARS:
        return f"is {len(text)} characters long; keep it to one sentence of at most {MAX_TEXT_CHARS}"
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        return "is not valid unicode text (it holds a lone surrogate such as \\ud800)"
    return None


def _number_text(value: float) -> str:
    """A number for a message: huge integers in short scientific form, not hundreds of digits."""
    if isinstance(value, int) and abs(value) >= 10**15:
        return f"{float(value):.3g}"
    return repr(value) if isinstance(value, float) else str(value)


def _either(names: list[str]) -> str:
    """`a, b or c`."""
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} or {names[-1]}"


def _roles_text(roles: frozenset[Role]) -> str:
    words = {Role.OBJECT: "an object", Role.GROUP: "a group", Role.ROOT: "root"}
    return " or ".join(words[r] for r in (Role.OBJECT, Role.GROUP, Role.ROOT) if r in roles) or "something else"


def check_program(
    program: Program,
    support: Support | None = None,
    *,
    max_objects: int = DEFAULT_MAX_OBJECTS,
    assets: Collection[str] | None = None,
) -> CheckReport:
    """Every problem of `program`, sorted by entry; `support` overrides the program's own. A program that makes
    more than `max_objects` objects (declared, copied and counted in PLACE-IN together) is an error. With `assets`
    (the catalogue's ids), a description that pins an asset ("asset:ID") must name one of them."""
    if isinstance(max_objects, bool) or not isinstance(max_objects, int) or not 1 <= max_objects <= MAX_OBJECTS:
        raise PhyscensisError(
            f"max_objects must be a whole number from 1 to {MAX_OBJECTS}, got {describe(max_objects)}"
        )
    return _Checker(program, support, max_objects, assets).run()
