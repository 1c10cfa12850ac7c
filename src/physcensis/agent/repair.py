"""Repairing a program after some of its objects failed to place: each is freed or dropped, with what depends on it.

Which entries refer to what is read from the predicate registry (each spec's subject and target roles and its
reference parameters), never from predicate names, so the repaired program passes the checker whatever predicates
the program uses:

* an entry depends on the ids it refers to: its target and its reference parameters (`C` of SYMMETRY-ALONG, ...);
* dropping an object drops every object or group with an entry that refers to it (what rests on it or is inside
  it, what is placed or turned relative to it), transitively;
* a group of listed members (GROUP) only loses a dropped member; it goes, with its copies, once none is left;
* a copy of a group (COPY-GROUP) goes with its group, and a copied member with its original.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable
from typing import Any

from physcensis.ids import ROOT_ID, copy_member_id
from physcensis.program.model import Declaration, Program, Relation
from physcensis.program.parser import parse_program
from physcensis.program.registry import ParamType, PlacementKind, Role, placement_spec

Entry = list[Any]
_REFERENCE_PARAMS = (ParamType.REFERENCE, ParamType.OBJECT)
FREE_PARAMS: dict[str, Any] = {"stack": False}  # a freed object stands on the support, not on others


def repair_program(program: list[Entry], failed: set[str], tried_free: set[str]) -> list[Entry]:
    """`program` without what failed. A failed object tried for the first time, that nothing refers to and that
    does not depend on a dropped one, is freed: placed anywhere there is room, at the end of the program. Any other
    failed object is dropped with everything that depends on it (when that is everything, nothing is left). Ids the
    program does not declare (copies of group members, objects a PLACE-IN count makes) cannot be moved alone:
    dropping them drops only what refers to them."""
    parsed = parse_program(program)
    declared = {d.object_id for d in parsed.declarations}
    referenced: set[str] = set().union(*(references(rel) for rel in parsed.relations))
    freeable = {f for f in failed - tried_free if f in declared and f not in referenced}
    dropped = dependents(parsed, failed - freeable)
    freed = freeable - dropped  # one that rests on a dropped object goes with it
    kept = [entry for e in parsed.entries if (entry := _kept(e, dropped | freed)) is not None]
    anywhere = placement_spec(PlacementKind.ANYWHERE).name
    moved = [
        entry
        for d in parsed.declarations
        if d.object_id in freed
        for entry in (d.to_json(), [d.object_id, anywhere, ROOT_ID, dict(FREE_PARAMS)])
    ]
    return kept + moved


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


def dependents(program: Program, dropped: Iterable[str]) -> set[str]:
    """`dropped` and every object and group of `program` that depends on one of them, transitively."""
    result = set(dropped)
    members = _group_members(program)
    copies = [(rel.subject, rel.target) for rel in program.relations if _copies_group(rel)]
    size = -1
    while size != len(result):
        size = len(result)
        for rel in program.relations:
            if _lists_members(rel):  # loses dropped members; goes when none is left
                if set(rel.target) <= result:
                    result.add(rel.subject)
            elif references(rel) & result:
                result.update(subjects(rel))
        for copy, source in copies:  # a copied member goes with its original, and with its copy group
            result.update(
                copy_member_id(member, copy) for member in members.get(source, ()) if member in result or copy in result
            )
    return result


def _kept(entry: Declaration | Relation, gone: set[str]) -> Entry | None:
    """The entry as it stays once the ids in `gone` are dropped or moved; None when it goes with them."""
    if isinstance(entry, Declaration):
        return None if entry.object_id in gone else entry.to_json()
    if _lists_members(entry):
        return _kept_group(entry, gone)
    if references(entry) & gone:
        return None
    if isinstance(entry.subject, tuple):  # items: those that stay
        items = tuple(item for item in entry.subject if not isinstance(item, str) or item not in gone)
        return dataclasses.replace(entry, subject=items).to_json() if items else None
    return None if entry.subject in gone else entry.to_json()


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
