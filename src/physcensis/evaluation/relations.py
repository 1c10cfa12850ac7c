"""Relation accuracy: every relation of a scene's program checked geometrically on the scene's final poses.

It reads a scene folder alone (scene.json with the program it keeps, and the folder's copies of library assets), so
it scores any method's output. Each predicate is checked by its effect (`CHECKS`) and, for yaw rules, by its yaw
mode (`YAW_CHECKS`), read from the registry like the solvers' own tables, so a new predicate of an existing effect is
checked with no change here. Coordinates follow docs/DESIGN.md: front = +x, left = +y, yaw 0 faces +x.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import shapely
import shapely.affinity

from physcensis.assets.catalogue import Catalogue
from physcensis.assets.model import Asset
from physcensis.errors import PhyscensisError
from physcensis.geometry.footprints import rotate
from physcensis.ids import ROOT_ID, copy_member_id, slug
from physcensis.program import ItemCount, Program, Relation, parse_program
from physcensis.program.registry import Effect, PredicateSpec, YawMode
from physcensis.scene import PlacedObject, Scene
from physcensis.solver.objects import compose_yaw, quaternion_yaw

POSITION_TOL_M = 0.01  # an alignment, a mirrored centre or a rest height may be off by this much
SIDE_TOL_M = 0.01  # LEFT-OF and friends: A may reach this far past B's edge
YAW_TOL_RAD = math.radians(15.0)  # the solver fine-tunes yaw offsets by up to 10 degrees; settling turns a little
Box = tuple[float, float, float, float]  # min_x, max_x, min_y, max_y


@dataclass(frozen=True)
class RelationCheck:
    """One relation of the program, judged on the scene: whether it holds, what was measured and the tolerance."""

    entry: int  # the program entry it comes from
    predicate: str
    subject: str
    target: str
    holds: bool
    measured: float | None  # in `unit`; None when an object it names is not in the scene
    tolerance: float
    unit: str
    detail: str

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


@dataclass
class SceneRelations:
    """Every relation check of one scene, and the share that holds."""

    scene: str
    checks: list[RelationCheck] = field(default_factory=list)
    skipped: list[str] = field(default_factory=list)  # entries with no meaning here (an unknown predicate)
    error: str | None = None  # why the scene could not be scored (an unreadable scene.json)

    @property
    def satisfied(self) -> int:
        return sum(c.holds for c in self.checks)

    @property
    def accuracy(self) -> float | None:
        """Share of relations that hold; None for a program without relations."""
        return self.satisfied / len(self.checks) if self.checks else None

    def to_dict(self) -> dict[str, Any]:
        return {
            "scene": self.scene,
            "relations": len(self.checks),
            "satisfied": self.satisfied,
            "accuracy": self.accuracy,
            "checks": [c.to_dict() for c in self.checks],
            "skipped": self.skipped,
            "error": self.error,
        }


@dataclass(frozen=True)
class Outcome:
    holds: bool
    measured: float
    tolerance: float
    unit: str
    detail: str


class World:
    """The scene as the checks see it: placed objects' footprints, boxes, heights and yaws, groups and the support."""

    def __init__(self, scene: Scene, catalogue: Catalogue, program: Program) -> None:
        self.scene, self.catalogue, self.program = scene, catalogue, program
        self.objects: dict[str, PlacedObject] = {o.id: o for o in scene.placed}
        self.groups: dict[str, list[str]] = {}
        self.anchors: dict[str, str] = {}
        self._prints: dict[str, shapely.Polygon] = {}
        self._assets: dict[str, Asset] = {}
        self._read_groups(program)

    def _read_groups(self, program: Program) -> None:
        for rel in program.relations:
            if rel.spec is None or not isinstance(rel.subject, str):
                continue
            if rel.spec.effect is Effect.GROUP and isinstance(rel.target, tuple):
                members = [str(m) for m in rel.target]
                self.groups[rel.subject] = members
                anchor = rel.params.get("anchor")
                self.anchors[rel.subject] = str(anchor) if anchor in members else (members[0] if members else "")
            elif rel.spec.effect is Effect.COPY_GROUP and isinstance(rel.target, str):
                members = self.groups.get(rel.target, [])
                self.groups[rel.subject] = [copy_member_id(m, rel.subject) for m in members]
                self.anchors[rel.subject] = copy_member_id(self.anchors.get(rel.target, ""), rel.subject)

    def members(self, ref: str) -> list[str]:
        return self.groups.get(ref, [ref])

    def turned(self, oids: set[str], *, about: str, by: float) -> World:
        """This scene with the objects `oids` turned rigidly by `by` radians about the vertical through `about`."""
        cx, cy = self.objects[about].position[:2]
        c, s = math.cos(by), math.sin(by)
        objects = []
        for o in self.scene.objects:
            if o.id in oids and o.status == "placed":
                x, y, z = o.position
                dx, dy = x - cx, y - cy
                position = (cx + c * dx - s * dy, cy + s * dx + c * dy, z)
                o = o.model_copy(update={"position": position, "quaternion": compose_yaw(o.quaternion, by)})
            objects.append(o)
        return World(self.scene.model_copy(update={"objects": objects}), self.catalogue, self.program)

    def missing(self, *refs: str) -> list[str]:
        """The objects (or group members) named by `refs` that are not placed in the scene."""
        return [m for ref in refs if ref != ROOT_ID for m in self.members(ref) if m not in self.objects]

    def asset(self, oid: str) -> Asset:
        if oid not in self._assets:
            obj = self.objects[oid]
            self._assets[oid] = self.catalogue.asset_for(obj.asset, obj.description)
        return self._assets[oid]

    def yaw_of_object(self, oid: str) -> float:
        return quaternion_yaw(self.objects[oid].quaternion)

    def footprint(self, oid: str) -> shapely.Polygon:
        if oid not in self._prints:
            obj = self.objects[oid]
            hull = rotate(self.asset(oid).footprint(), np.array([self.yaw_of_object(oid)]))[0]
            self._prints[oid] = shapely.Polygon(hull + np.asarray(obj.position[:2]))
        return self._prints[oid]

    def box(self, ref: str) -> Box:
        """(min_x, max_x, min_y, max_y) of an object's footprint, a group's members, or the support's top."""
        if ref == ROOT_ID:
            hx, hy = self.scene.support.half_extents
            return -hx, hx, -hy, hy
        min_x, min_y, max_x, max_y = shapely.union_all([self.footprint(m) for m in self.members(ref)]).bounds
        return min_x, max_x, min_y, max_y

    def yaw(self, ref: str) -> float:
        """An object's yaw; a group's is its anchor's; the support's is 0."""
        if ref == ROOT_ID:
            return 0.0
        return self.yaw_of_object(self.anchors.get(ref, ref))

    def base_z(self, ref: str) -> float:
        return min(self.objects[m].position[2] for m in self.members(ref))

    def top_z(self, oid: str) -> float:
        return self.objects[oid].position[2] + float(self.asset(oid).size[2])

    @property
    def support_top(self) -> float:
        return self.scene.support.top_height


def centre(box: Box) -> tuple[float, float]:
    return (box[0] + box[1]) / 2, (box[2] + box[3]) / 2


def turn_between(a: float, b: float) -> float:
    """The smallest angle between two yaws, in [0, pi]."""
    return abs((a - b + math.pi) % (2 * math.pi) - math.pi)


def _param(rel: Relation, name: str, default: float = 0.0) -> float:
    value = rel.params.get(name)
    return float(value) if isinstance(value, (int, float)) and not isinstance(value, bool) else default


# -- the checks, by effect -------------------------------------------------------------------------------------------

_EDGE_INDEX = {"x": (0, 1), "y": (2, 3)}


def _edge_value(box: Box, axis: str, which: str) -> float:
    lo, hi = (box[i] for i in _EDGE_INDEX[axis])
    return {"min": lo, "max": hi, "center": (lo + hi) / 2}[which]


def edge_holds(world: World, rel: Relation, spec: PredicateSpec) -> Outcome:
    """LEFT-OF and friends: A lies wholly on its side of B; ALIGN-*: the two edges (or centres) coincide."""
    rule = spec.edge_rule()
    a, b = world.box(str(rel.subject)), world.box(str(rel.target))
    gap = _edge_value(a, rule.axis, rule.a_edge) - _edge_value(b, rule.axis, rule.b_edge)
    if rule.direction:
        side = rule.direction * gap
        return Outcome(side >= -SIDE_TOL_M, side, SIDE_TOL_M, "m", f"gap {side * 100:.1f} cm along {rule.axis}")
    return Outcome(abs(gap) <= POSITION_TOL_M, gap, POSITION_TOL_M, "m", f"{rule.a_edge} {rule.axis} off by {gap:+.3f}")


def symmetry_holds(world: World, rel: Relation, spec: PredicateSpec) -> Outcome:
    """A's centre is B's mirrored through C's."""
    a, b = centre(world.box(str(rel.subject))), centre(world.box(str(rel.target)))
    c = centre(world.box(str(rel.params.get("C", ROOT_ID))))
    off = math.dist(a, (2 * c[0] - b[0], 2 * c[1] - b[1]))
    return Outcome(off <= POSITION_TOL_M, off, POSITION_TOL_M, "m", f"mirrored centre off by {off * 100:.1f} cm")


def stands_on_the_support(world: World, rel: Relation, spec: PredicateSpec) -> Outcome:
    """A's base is on the support's top and its centre over the support."""
    subject = str(rel.subject)
    height = world.base_z(subject) - world.support_top
    cx, cy = centre(world.box(subject))
    hx, hy = world.scene.support.half_extents
    over = abs(cx) <= hx and abs(cy) <= hy
    holds = abs(height) <= POSITION_TOL_M and over
    where = "over the support" if over else "centre off the support"
    return Outcome(holds, height, POSITION_TOL_M, "m", f"base {height * 1000:+.1f} mm from the top, {where}")


def yaw_holds(world: World, rel: Relation, spec: PredicateSpec) -> Outcome:
    return YAW_CHECKS[spec.yaw_rule().mode](world, rel, spec)


def _facing(world: World, rel: Relation, wanted: float) -> Outcome:
    yaw = world.yaw(str(rel.subject))
    off = turn_between(yaw, wanted + _param(rel, "yaw_offset"))
    return Outcome(off <= YAW_TOL_RAD, off, YAW_TOL_RAD, "rad", f"yaw {math.degrees(off):.1f} deg from the rule's")


def _yaw_absolute(world: World, rel: Relation, spec: PredicateSpec) -> Outcome:
    return _facing(world, rel, spec.yaw_rule().angle)


def _yaw_toward(world: World, rel: Relation, spec: PredicateSpec) -> Outcome:
    ax, ay = centre(world.box(str(rel.subject)))
    bx, by = centre(world.box(str(rel.target)))
    return _facing(world, rel, math.atan2(by - ay, bx - ax))


def _yaw_same(world: World, rel: Relation, spec: PredicateSpec) -> Outcome:
    return _facing(world, rel, world.yaw(str(rel.target)))


def _yaw_opposite(world: World, rel: Relation, spec: PredicateSpec) -> Outcome:
    return _facing(world, rel, world.yaw(str(rel.target)) + math.pi)


def _yaw_random(world: World, rel: Relation, spec: PredicateSpec) -> Outcome:
    """Any yaw is a random yaw: the relation holds once A is placed."""
    return Outcome(True, world.yaw(str(rel.subject)), math.pi, "rad", "any yaw")


def _yaw_relative_side(world: World, rel: Relation, spec: PredicateSpec) -> Outcome:
    """Of A's yaw and a quarter turn more, A has the one that lines its box up better with B's."""
    subject, b = str(rel.subject), world.box(str(rel.target))
    shape = shapely.union_all([world.footprint(m) for m in world.members(subject)])

    def lined_up(turn: float) -> float:
        min_x, min_y, max_x, max_y = shapely.affinity.rotate(shape, turn, use_radians=True).bounds
        return max(0.0, min(max_x, b[1]) - max(min_x, b[0])) + max(0.0, min(max_y, b[3]) - max(min_y, b[2]))

    margin = lined_up(0.0) - lined_up(math.pi / 2)
    return Outcome(margin >= -POSITION_TOL_M, margin, POSITION_TOL_M, "m", f"lined up {margin * 100:+.1f} cm better")


def rests_on_the_target(world: World, rel: Relation, spec: PredicateSpec) -> Outcome:
    """A's base centre is over B's footprint and A's base at B's top (or, when B has a cavity, between its floor
    and its rim): neither floating above B nor sunk into it."""
    subject, target = str(rel.subject), str(rel.target)
    obj = world.objects[subject]
    over = world.footprint(target).buffer(POSITION_TOL_M).contains(shapely.Point(obj.position[:2]))
    above_top = obj.position[2] - world.top_z(target)
    holds = over and base_rests_on(world, obj.position[2], target)
    where = "over it" if over else "not over it"
    return Outcome(
        holds, above_top, POSITION_TOL_M, "m", f"base {above_top * 1000:+.1f} mm from {target}'s top, {where}"
    )


def base_rests_on(world: World, base: float, oid: str) -> bool:
    """Whether a base at height `base` rests on object `oid`: at its top, or within its cavity (floor to rim)."""
    if abs(base - world.top_z(oid)) <= POSITION_TOL_M:
        return True
    cavity = world.asset(oid).cavity
    if cavity is None:
        return False
    bottom = world.objects[oid].position[2]
    return bottom + cavity.floor_height - POSITION_TOL_M <= base <= bottom + cavity.rim_height + POSITION_TOL_M


def rests_somewhere(world: World, rel: Relation, spec: PredicateSpec) -> Outcome:
    """A's centre is over the support and its base on the support's top or on a placed object it overlaps (at its
    top, or in its cavity): not floating, not sunk."""
    subject = str(rel.subject)
    obj = world.objects[subject]
    hx, hy = world.scene.support.half_extents
    height = obj.position[2] - world.support_top
    over = abs(obj.position[0]) <= hx and abs(obj.position[1]) <= hy
    if abs(height) <= POSITION_TOL_M:
        return Outcome(over, height, POSITION_TOL_M, "m", f"base {height * 1000:+.1f} mm above the support's top")
    carrier = _carrier(world, subject)
    where = f"resting on {carrier}" if carrier else "on nothing"
    detail = f"base {height * 1000:+.1f} mm above the support's top, {where}"
    return Outcome(over and carrier is not None, height, POSITION_TOL_M, "m", detail)


def _carrier(world: World, subject: str) -> str | None:
    """A placed object whose footprint overlaps the subject's and on which the subject's base rests, if any."""
    base, footprint = world.objects[subject].position[2], world.footprint(subject)
    for oid in sorted(world.objects):
        if oid != subject and world.footprint(oid).intersects(footprint) and base_rests_on(world, base, oid):
            return oid
    return None


def members_placed(world: World, rel: Relation, spec: PredicateSpec) -> Outcome:
    """A group stands for its members: it holds when every member is in the scene (checked before this runs)."""
    members = world.members(str(rel.subject))
    return Outcome(True, float(len(members)), 0.0, "objects", f"{len(members)} member(s) placed")


def copies_keep_their_poses(world: World, rel: Relation, spec: PredicateSpec) -> Outcome:
    """Each copy stands to the copy of the anchor as its original stands to the anchor."""
    copy, original = str(rel.subject), str(rel.target)
    worst = 0.0
    for member, twin in zip(world.members(original), world.members(copy), strict=True):
        a = _relative_pose(world, member, world.anchors[original])
        b = _relative_pose(world, twin, world.anchors[copy])
        worst = max(worst, math.dist(a[:2], b[:2]), turn_between(a[2], b[2]) * 0.1)  # 10 cm per radian
    return Outcome(worst <= POSITION_TOL_M, worst, POSITION_TOL_M, "m", f"copies off by up to {worst * 100:.1f} cm")


def _relative_pose(world: World, oid: str, anchor: str) -> tuple[float, float, float]:
    yaw = world.yaw_of_object(anchor)
    dx, dy = np.subtract(world.objects[oid].position[:2], world.objects[anchor].position[:2])
    c, s = math.cos(-yaw), math.sin(-yaw)
    return float(c * dx - s * dy), float(s * dx + c * dy), world.yaw_of_object(oid) - yaw


Check = Callable[[World, Relation, PredicateSpec], Outcome]
Checks = Callable[[World, Relation, PredicateSpec], list[RelationCheck]]


def single(check: Check) -> Checks:
    """A check of one relation between the entry's subject and target, as the list every entry gives."""

    def run(world: World, rel: Relation, spec: PredicateSpec) -> list[RelationCheck]:
        target = str(rel.target) if isinstance(rel.target, str) else ",".join(map(str, rel.target))
        missing = world.missing(*_refs(rel, spec))
        if missing:
            return [_not_placed(rel, str(rel.subject), target, missing)]
        o = check(world, rel, spec)
        subject = str(rel.subject)
        return [
            RelationCheck(rel.index, spec.name, subject, target, o.holds, o.measured, o.tolerance, o.unit, o.detail)
        ]

    return run


YAW_CHECKS: dict[YawMode, Check] = {
    YawMode.ABSOLUTE: _yaw_absolute,
    YawMode.TOWARD: _yaw_toward,
    YawMode.SAME: _yaw_same,
    YawMode.OPPOSITE: _yaw_opposite,
    YawMode.RANDOM: _yaw_random,
    YawMode.RELATIVE_SIDE: _yaw_relative_side,
}


# -- PLACE-IN: one check per item --------------------------------------------------------------------------------


def _inside(world: World, item: str, container: str) -> tuple[bool, float]:
    """Whether the item's base centre is within the container's opening (its footprint when it has no cavity) and
    between its base and its rim; and the item's base height above the container's base."""
    obj, box = world.objects[item], world.objects[container]
    asset = world.asset(container)
    cavity = asset.cavity
    rim = cavity.rim_height if cavity is not None else float(asset.size[2])
    if cavity is not None:
        yaw = world.yaw_of_object(container)
        opening = shapely.Polygon(rotate(cavity.opening, np.array([yaw]))[0] + np.asarray(box.position[:2]))
    else:
        opening = world.footprint(container)
    height = obj.position[2] - box.position[2]
    within = opening.buffer(POSITION_TOL_M).contains(shapely.Point(obj.position[:2]))
    return within and -POSITION_TOL_M <= height <= rim + POSITION_TOL_M, height


def _inside_checks(world: World, rel: Relation, spec: PredicateSpec) -> list[RelationCheck]:
    subjects = rel.subject if isinstance(rel.subject, tuple) else (rel.subject,)
    declared = {d.object_id for d in world.program.declarations}
    used: set[str] = set()
    checks: list[RelationCheck] = []
    for subject in subjects:
        if isinstance(subject, ItemCount):
            checks += _counted_items(world, rel, subject, declared | used, used)
        else:
            checks.append(_item_check(world, rel, str(subject)))
    return checks


def _item_check(world: World, rel: Relation, item: str) -> RelationCheck:
    container = str(rel.target)
    missing = world.missing(item, container)
    if missing:
        return _not_placed(rel, item, container, missing)
    holds, height = _inside(world, item, container)
    where = "inside" if holds else "not inside"
    detail = f"{where} {container} (base {height * 1000:+.1f} mm above its base)"
    return RelationCheck(rel.index, rel.predicate, item, container, holds, height, POSITION_TOL_M, "m", detail)


def _counted_items(
    world: World, rel: Relation, items: ItemCount, excluded: set[str], used: set[str]
) -> list[RelationCheck]:
    """`[category, n]` in a container: the objects the solver made for it (ids after the category, not declared in
    the program) that ended inside it, one check per requested item."""
    container = str(rel.target)
    if world.missing(container):
        return [_not_placed(rel, f"{items.category} #{k + 1}", container, [container]) for k in range(items.count)]
    prefix = slug(items.category) + "_"
    candidates = [oid for oid in world.objects if oid.startswith(prefix) and oid not in excluded]
    inside = [oid for oid in candidates if _inside(world, oid, container)[0]][: items.count]
    used.update(inside)
    checks = []
    for k in range(items.count):
        holds = k < len(inside)
        name = inside[k] if holds else f"{items.category} #{k + 1}"
        detail = f"{len(inside)} of {items.count} {items.category} inside {container}"
        checks.append(
            RelationCheck(rel.index, rel.predicate, name, container, holds, float(len(inside)), 0.0, "items", detail)
        )
    return checks


# Every effect's check: PLACE-IN relates many items to one container, so it gives one check per item.
CHECKS: dict[Effect, Checks] = {
    Effect.EDGE: single(edge_holds),
    Effect.SYMMETRY: single(symmetry_holds),
    Effect.BASE: single(stands_on_the_support),
    Effect.YAW: single(yaw_holds),
    Effect.ON: single(rests_on_the_target),
    Effect.IN: _inside_checks,
    Effect.ANYWHERE: single(rests_somewhere),
    Effect.GROUP: single(members_placed),
    Effect.COPY_GROUP: single(copies_keep_their_poses),
}


# -- a scene ------------------------------------------------------------------------------------------------------


def _not_placed(rel: Relation, subject: str, target: str, missing: Iterable[str]) -> RelationCheck:
    names = ", ".join(missing)
    return RelationCheck(rel.index, rel.predicate, subject, target, False, None, 0.0, "", f"not placed: {names}")


def _refs(rel: Relation, spec: PredicateSpec) -> list[str]:
    """The objects and groups a relation needs in the scene (a new group's members stand in for it)."""
    refs = [str(rel.subject)]
    if spec.effect not in (Effect.GROUP, Effect.COPY_GROUP) and isinstance(rel.target, str):
        refs.append(rel.target)
    elif spec.effect is Effect.COPY_GROUP:
        refs.append(str(rel.target))
    reference = rel.params.get("C")
    if isinstance(reference, str):
        refs.append(reference)
    return refs


def check_relation(world: World, rel: Relation, spec: PredicateSpec) -> list[RelationCheck]:
    """The checks of one program entry (one, or one per item for PLACE-IN)."""
    check = CHECKS.get(spec.effect)
    if check is None:
        raise PhyscensisError(f"no relation check for predicate {spec.name} (effect {spec.effect.value})")
    return check(world, rel, spec)


def check_scene(scene: Scene, catalogue: Catalogue, name: str = "", program: Program | None = None) -> SceneRelations:
    """Every relation of `program` (default: the program the scene keeps) judged on the scene's poses; what the
    members of a group say of each other is judged in the group's own frame once the group was turned."""
    program = program if program is not None else parse_program(scene.program)
    world = World(scene, catalogue, program)
    framed = _group_frames(world, program)
    result = SceneRelations(name)
    for rel in program.relations:
        if rel.spec is None:
            result.skipped.append(f"entry {rel.index}: unknown predicate {rel.predicate}")
            continue
        seen_from = world
        if rel.spec.effect in GROUP_FRAME_EFFECTS:  # resting on something is judged where the object is
            seen_from = next((w for made, members, w in framed if rel.index < made and rel.subject in members), world)
        result.checks += check_relation(seen_from, rel, rel.spec)
    return result


# What a group's members say of each other's places and turns is judged in the group's frame; whether one rests on
# the support or on another is a fact of the scene as it stands.
GROUP_FRAME_EFFECTS = (Effect.EDGE, Effect.SYMMETRY, Effect.YAW)


def _group_frames(world: World, program: Program) -> list[tuple[int, set[str], World]]:
    """For each group that later rules turned: the entry that made it, its members, and the scene with those members
    turned back about the anchor by as much as the anchor turned from the yaw its own absolute facing rule gave it
    (the member rules were solved before the group was turned, and the group moves them rigidly, so they hold in its
    frame, not in the support's: a place setting at the table's end has its fork on the plate's right, not on +y)."""
    frames = []
    made = {
        str(rel.subject): rel.index
        for rel in program.relations
        if rel.spec is not None and rel.spec.effect is Effect.GROUP and isinstance(rel.target, tuple)
    }
    for group, index in made.items():
        anchor = world.anchors.get(group, "")
        members = set(world.groups.get(group, []))
        if anchor not in world.objects or not members <= set(world.objects):
            continue
        wanted = [
            rel.spec.yaw_rule().angle + _param(rel, "yaw_offset")
            for rel in program.relations
            if rel.index < index
            and rel.subject == anchor
            and rel.spec is not None
            and rel.spec.effect is Effect.YAW
            and rel.spec.yaw_rule().mode is YawMode.ABSOLUTE
        ]
        if not wanted:
            continue
        turn = math.remainder(world.yaw_of_object(anchor) - wanted[-1], 2 * math.pi)
        if abs(turn) > YAW_TOL_RAD:
            frames.append((index, members, world.turned(members, about=anchor, by=-turn)))
    return frames


def check_scene_folder(path: str | Path) -> SceneRelations:
    """The relations of one scene folder (or scene.json), with the folder's own copies of library assets."""
    from physcensis.output import open_scene

    scene, catalogue = open_scene(path)
    return check_scene(scene, catalogue, str(path))


def scene_folders(path: str | Path) -> list[Path]:
    """A scene folder itself, or every scene folder below `path` as the gallery finds them (hidden staging folders
    and a scene's exports are not searched)."""
    from physcensis.gallery.cards import scene_folders as folders_below

    path = Path(path)
    if (path / "scene.json").is_file() or path.is_file():
        return [path]
    return folders_below(path) if path.is_dir() else []


def check_scene_folder_or_error(path: Path) -> SceneRelations:
    """check_scene_folder, or a result that holds why the folder could not be scored (the other folders still are)."""
    try:
        return check_scene_folder(path)
    except (PhyscensisError, OSError, ValueError) as exc:
        return SceneRelations(str(path), error=str(exc) or type(exc).__name__)
