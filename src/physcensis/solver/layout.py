"""A program's spatial part compiled into array operations (the spatial solver's model).

The program is compiled once into a list of operations over arrays, so a whole
batch of parameter vectors (the 40 samples of coordinate descent) is evaluated
in one pass. Semantics (docs/DESIGN.md): predicates apply in program order to
the axis-aligned box of the rotated convex-hull footprint; a yaw rule turns an
object (or group) about its box centre; after an object's last entry, its
position rules are applied once more so they hold for its final yaw.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from physcensis.geometry.footprints import Array, hull_area, pad_hull
from physcensis.ids import ROOT_ID, copy_member_id
from physcensis.program.model import Program, Relation
from physcensis.program.registry import (
    EdgeRule,
    Effect,
    ParamSpec,
    PlacementKind,
    PredicateSpec,
    Solver,
    YawMode,
    handler_for,
)
from physcensis.scene import Support

YAW_RADIUS = math.radians(10.0)  # sampling half-width of yaw offsets
FAR_M = 1e4  # a mirrored centre is kept within this many metres of the support's centre


@dataclass(frozen=True)
class Pose2D:
    x: float
    y: float
    yaw: float


@dataclass(frozen=True)
class ParamSlot:
    """One optimisable value: a parameter of one program entry."""

    entry: int
    name: str
    initial: float
    low: float
    high: float
    radius: float


@dataclass(frozen=True)
class PhysicalRequest:
    """A placement the physical solver must realise (PLACE-ON, PLACE-IN, PLACE-ANYWHERE)."""

    relation: Relation
    subject_ids: tuple[str, ...]  # ids it places (for PLACE-IN with ids) or the subject
    target: str
    copied_from: str | None = None  # for members of a copied group


# -- compiled program ---------------------------------------------------------------

Node = tuple[str, Any]  # ("obj", index) | ("group", name) | ("root", None)


@dataclass
class _Op:
    """One program entry (or a finalisation) over (object, sample) arrays."""

    step: Callable[[_State, _Op, Array], None]  # the `_State` method that applies it
    subject: Node
    target: Node | None = None
    relation: Relation | None = None
    slots: dict[str, int] = field(default_factory=dict)  # param name -> slot index
    extra: dict[str, Any] = field(default_factory=dict)
    position: bool = False  # a 2-D position rule: applied once more after its subject's last entry


SpatialHandler = Callable[["CompiledLayout", Relation, PredicateSpec, Node], "_Op"]
GroupHandler = Callable[["CompiledLayout", Relation, PredicateSpec], "_Op"]


class CompiledLayout:
    """A program's spatial part as operations over (object, sample) arrays.

    Entries are compiled by the solver that owns them (SOLVER_ENTRIES): SPATIAL and GROUP effects by their
    handlers (SPATIAL_HANDLERS, GROUP_HANDLERS); PHYSICAL ones are collected as requests for the physical solver.
    """

    def __init__(self, program: Program, support: Support, hulls: Mapping[str, Array], seed: int) -> None:
        self.support = support
        self.hx, self.hy = support.half_extents
        self.ids: list[str] = []
        self.hull_list: list[Array] = []
        self.index: dict[str, int] = {}
        self.ops: list[_Op] = []
        self.slots: list[ParamSlot] = []
        self.entries_of: dict[str, list[int]] = {}
        self.copies: dict[str, str] = {}
        self.pending: list[PhysicalRequest] = []
        self.yaw_rules: dict[str, list[Relation]] = {}
        self.group_members: dict[str, list[int]] = {}
        self._rng = np.random.default_rng(seed)
        self._hulls = hulls
        self._placement = _placements(program)
        self._group_physical: dict[str, list[str]] = {}  # group -> its members placed physically
        self._compile(program)
        size = max(len(h) for h in self.hull_list) if self.hull_list else 3
        self.hulls = np.stack([pad_hull(h, size) for h in self.hull_list]) if self.hull_list else np.zeros((0, 3, 2))
        self.areas = np.array([hull_area(h) for h in self.hull_list])

    # -- compilation -----------------------------------------------------------------
    def _compile(self, program: Program) -> None:
        for oid in (d.object_id for d in program.declarations):
            if self._placement.get(oid) is PlacementKind.BASE and oid not in self._hulls:
                raise KeyError(f"no footprint for {oid}")
        ops: list[_Op] = []
        last_entry: dict[Node, int] = {}
        for rel in program.relations:
            spec = rel.spec
            if spec is None:
                continue
            op = handler_for(SOLVER_ENTRIES, spec, spec.solver)(self, rel, spec)
            if op is None:
                continue
            ops.append(op)
            if spec.solver is Solver.SPATIAL:
                last_entry[op.subject] = len(ops) - 1
        finals = {pos: node for node, pos in last_entry.items()}
        for pos, op in enumerate(ops):
            self.ops.append(op)
            if pos in finals:
                self.ops.append(_Op(_State.finalize, finals[pos]))

    def _spatial_entry(self, rel: Relation, spec: PredicateSpec) -> _Op | None:
        handler = handler_for(SPATIAL_HANDLERS, spec)
        node = self._spatial_node(rel.subject)
        if node is None:  # placed physically: its yaw rules are hints for the physical solver
            if spec.yaw is not None:
                self.yaw_rules.setdefault(rel.subject, []).append(rel)
            return None
        self.entries_of.setdefault(rel.subject, []).append(rel.index)
        if node[0] == "group":
            for member in self.group_members[rel.subject]:
                self.entries_of.setdefault(self.ids[member], []).append(rel.index)
        return handler(self, rel, spec, node)

    def _spatial_node(self, subject: str) -> Node | None:
        """The node a spatial entry moves (an object standing on the support joins the layout at its first
        entry), or None for an object placed physically."""
        if subject in self.group_members:
            return ("group", subject)
        if self._placement.get(subject) is not PlacementKind.BASE:
            return None
        if subject not in self.index:
            self._add(subject, np.asarray(self._hulls[subject], dtype=float))
            self.entries_of[subject] = []
        return ("obj", self.index[subject])

    def _group_entry(self, rel: Relation, spec: PredicateSpec) -> _Op:
        return handler_for(GROUP_HANDLERS, spec)(self, rel, spec)

    def _physical(self, rel: Relation, spec: PredicateSpec) -> None:
        """A placement the physical solver realises later (its handler is looked up there)."""
        if isinstance(rel.subject, tuple):
            ids = tuple(s for s in rel.subject if isinstance(s, str))
        else:
            ids = (rel.subject,)
        self.pending.append(PhysicalRequest(rel, ids, str(rel.target)))

    def _add(self, oid: str, hull: Array) -> int:
        self.index[oid] = len(self.ids)
        self.ids.append(oid)
        self.hull_list.append(hull)
        return self.index[oid]

    def _node(self, ref: str) -> Node:
        if ref == ROOT_ID:
            return ("root", None)
        if ref in self.group_members:
            return ("group", ref)
        if ref in self.index:
            return ("obj", self.index[ref])
        return ("root", None)  # a physically placed object has no spatial pose yet; use the support

    def _slot(self, rel: Relation, param: ParamSpec, initial: float, low: float, high: float, radius: float) -> int:
        self.slots.append(ParamSlot(rel.index, param.name, float(np.clip(initial, low, high)), low, high, radius))
        return len(self.slots) - 1

    @property
    def _step_radius(self) -> float:
        """Sampling half-width of distances and positions: a tenth of the support's shorter side."""
        return min(self.support.size) / 10.0

    # -- spatial handlers: one per spatial effect ------------------------------------------------
    def _edge_op(self, rel: Relation, spec: PredicateSpec, node: Node) -> _Op:
        op = _Op(_State.align_edge, node, self._node(rel.target), rel, extra={"rule": spec.edge_rule()}, position=True)
        dist = spec.param("distance")
        if dist is not None:
            value = rel.params.get("distance", dist.default)
            op.slots["distance"] = self._slot(
                rel, dist, float(value), dist.low or 0.0, dist.high or 10.0, self._step_radius
            )
        return op

    def _symmetry_op(self, rel: Relation, spec: PredicateSpec, node: Node) -> _Op:
        return _Op(
            _State.mirror,
            node,
            self._node(rel.target),
            rel,
            extra={"C": self._node(str(rel.params["C"]))},
            position=True,
        )

    def _base_op(self, rel: Relation, spec: PredicateSpec, node: Node) -> _Op:
        op = _Op(_State.stand, node, None, rel, position=True)
        for name, half in (("x", self.hx), ("y", self.hy)):
            param = spec.param(name)
            if param is not None and rel.params.get(name) is not None:
                op.slots[name] = self._slot(rel, param, float(rel.params[name]), -half, half, self._step_radius)
        return op

    def _yaw_op(self, rel: Relation, spec: PredicateSpec, node: Node) -> _Op:
        rule = spec.yaw_rule()
        value = handler_for(YAW_RULES, spec, rule.mode)
        op = _Op(_State.turn_by_rule, node, self._node(rel.target), rel, extra={"rule": rule, "value": value})
        if rule.mode is YawMode.RANDOM:
            op.extra["angle"] = float(self._rng.uniform(0.0, 2.0 * math.pi))
        offset = spec.param("yaw_offset")
        if offset is not None:
            op.slots["yaw_offset"] = self._slot(
                rel, offset, float(rel.params.get("yaw_offset", 0.0)), -math.pi, math.pi, YAW_RADIUS
            )
        return op

    # -- group handlers ----------------------------------------------------------------------------
    def _group_op(self, rel: Relation, spec: PredicateSpec) -> _Op:
        members = [m for m in rel.target if m in self.index]
        self._group_physical[rel.subject] = [m for m in rel.target if m not in self.index]
        anchor = rel.params.get("anchor") or (rel.target[0] if rel.target else None)
        self.group_members[rel.subject] = [self.index[m] for m in members]
        return _Op(
            _State.make_group,
            ("group", rel.subject),
            relation=rel,
            extra={"anchor": self.index.get(anchor) if anchor else None},
        )

    def _copy_group_op(self, rel: Relation, spec: PredicateSpec) -> _Op:
        source = rel.target
        pairs = []
        for member in self.group_members.get(source, []):
            new_id = copy_member_id(self.ids[member], rel.subject)
            pairs.append((member, self._add(new_id, self.hull_list[member])))
            self.copies[new_id] = self.copies.get(self.ids[member], self.ids[member])
            self.entries_of[new_id] = [rel.index]
        self.group_members[rel.subject] = [new for _, new in pairs]
        physical = self._group_physical.get(source, [])
        self._group_physical[rel.subject] = [copy_member_id(m, rel.subject) for m in physical]
        spatial = [self.ids[i] for i in self.group_members.get(source, [])]
        self._copy_physical({*spatial, *physical}, rel.subject)
        return _Op(
            _State.copy_group, ("group", rel.subject), ("group", source), rel, extra={"pairs": pairs, "source": source}
        )

    def _copy_physical(self, members: set[str], new_group: str) -> None:
        """Members placed physically (a cup on a plate) are copied as new requests on the copies."""
        for request in list(self.pending):
            if request.subject_ids and all(s in members for s in request.subject_ids):
                target = request.target
                new_target = copy_member_id(target, new_group) if target in members else target
                self.pending.append(
                    PhysicalRequest(
                        request.relation,
                        tuple(copy_member_id(s, new_group) for s in request.subject_ids),
                        new_target,
                        copied_from=request.subject_ids[0],
                    )
                )

    # -- evaluation ----------------------------------------------------------------------
    def initial_theta(self) -> Array:
        return np.array([s.initial for s in self.slots], dtype=float)

    def evaluate(self, theta: Array) -> tuple[Array, Array, Array]:
        """Poses (x, y, yaw), each (objects, samples), for parameter vectors theta (samples, slots)."""
        batch = theta.shape[0]
        n = len(self.ids)
        x = np.zeros((n, batch))
        y = np.zeros((n, batch))
        yaw = np.zeros((n, batch))
        state = _State(self, x, y, yaw, batch)
        for op in self.ops:
            state.apply(op, theta)
        return x, y, yaw


def _placements(program: Program) -> dict[str, PlacementKind]:
    """How each object is placed: by the first placement predicate about it."""
    placement: dict[str, PlacementKind] = {}
    for rel in program.relations:
        if rel.spec is not None and rel.spec.placement is not None and isinstance(rel.subject, str):
            placement.setdefault(rel.subject, rel.spec.placement)
    return placement


class _State:
    def __init__(self, layout: CompiledLayout, x: Array, y: Array, yaw: Array, batch: int) -> None:
        self.layout = layout
        self.x, self.y, self.yaw = x, y, yaw
        self.batch = batch
        self.group_yaw: dict[str, Array] = {}
        self.position_ops: dict[Node, list[_Op]] = {}
        # Box of each turned hull about its origin (min_x, max_x, min_y, max_y per sample), valid while `fresh`.
        self.ext = np.zeros((len(layout.ids), 4, batch))
        self.fresh = np.zeros(len(layout.ids), dtype=bool)
        self.members: dict[str, NDArray[np.intp]] = {
            g: np.array(m, dtype=np.intp) for g, m in layout.group_members.items()
        }
        hx, hy = layout.hx, layout.hy
        self.root_box = np.array([[-hx], [hx], [-hy], [hy]]) * np.ones((1, batch))

    # boxes
    def refresh(self, idx: NDArray[np.intp]) -> None:
        """Recompute the extents of the objects `idx` that turned since they were last computed."""
        stale = idx[~self.fresh[idx]]
        if len(stale) == 0:
            return
        hulls = self.layout.hulls[stale]  # (m, K, 2), padded by repeating a vertex: same extents
        c, s = np.cos(self.yaw[stale])[..., None], np.sin(self.yaw[stale])[..., None]  # (m, B, 1)
        hx, hy = hulls[:, None, :, 0], hulls[:, None, :, 1]  # (m, 1, K)
        px, py = c * hx - s * hy, s * hx + c * hy
        self.ext[stale] = np.stack([px.min(-1), px.max(-1), py.min(-1), py.max(-1)], axis=1)
        self.fresh[stale] = True

    def refresh_one(self, i: int) -> None:
        hull = self.layout.hull_list[i]
        c, s = np.cos(self.yaw[i])[:, None], np.sin(self.yaw[i])[:, None]  # (B, 1)
        px, py = c * hull[:, 0] - s * hull[:, 1], s * hull[:, 0] + c * hull[:, 1]
        e = self.ext[i]
        px.min(-1, out=e[0])
        px.max(-1, out=e[1])
        py.min(-1, out=e[2])
        py.max(-1, out=e[3])
        self.fresh[i] = True

    def set_yaw(self, members: int | NDArray[np.intp], yaw: Array) -> None:
        self.yaw[members] = yaw
        self.fresh[members] = False

    def box(self, node: Node) -> Array:
        """(4, batch): min_x, max_x, min_y, max_y."""
        kind, ref = node
        if kind == "obj":
            if not self.fresh[ref]:
                self.refresh_one(ref)
            b = self.ext[ref].copy()
            b[:2] += self.x[ref]
            b[2:] += self.y[ref]
            return b
        if kind == "group":
            members = self.members[ref]
            if len(members) == 0:
                return np.zeros((4, self.batch))
            self.refresh(members)
            e, x, y = self.ext[members], self.x[members], self.y[members]
            return np.stack([(e[:, 0] + x).min(0), (e[:, 1] + x).max(0), (e[:, 2] + y).min(0), (e[:, 3] + y).max(0)])
        return self.root_box.copy()

    def node_yaw(self, node: Node) -> Array:
        kind, ref = node
        if kind == "obj":
            return self.yaw[ref]
        if kind == "group":
            return self.group_yaw.get(ref, np.zeros(self.batch))
        return np.zeros(self.batch)

    def move(self, node: Node, dx: Array | float, dy: Array | float) -> None:
        kind, ref = node
        if kind == "obj":
            self.x[ref] += dx
            self.y[ref] += dy
        elif kind == "group":
            members = self.members[ref]
            self.x[members] += dx
            self.y[members] += dy

    def turn(self, node: Node, new_yaw: Array) -> None:
        """Set the yaw, turning about the box centre."""
        b0 = self.box(node)
        cx0, cy0 = (b0[0] + b0[1]) / 2, (b0[2] + b0[3]) / 2
        kind, ref = node
        if kind == "obj":
            self.set_yaw(ref, new_yaw)
        elif kind == "group":
            delta = new_yaw - self.node_yaw(node)
            members = self.members[ref]
            c, s = np.cos(delta), np.sin(delta)
            px, py = self.x[members] - cx0, self.y[members] - cy0
            self.x[members] = cx0 + c * px - s * py
            self.y[members] = cy0 + s * px + c * py
            self.set_yaw(members, self.yaw[members] + delta)
            self.group_yaw[ref] = new_yaw
        else:
            return
        b1 = self.box(node)
        self.move(node, cx0 - (b1[0] + b1[1]) / 2, cy0 - (b1[2] + b1[3]) / 2)

    # operations: each `_Op.step` is one of these
    def apply(self, op: _Op, theta: Array) -> None:
        if op.position:
            self.position_ops.setdefault(op.subject, []).append(op)
        op.step(self, op, theta)

    def make_group(self, op: _Op, theta: Array) -> None:
        anchor = op.extra["anchor"]
        self.group_yaw[op.subject[1]] = self.yaw[anchor].copy() if anchor is not None else np.zeros(self.batch)

    def copy_group(self, op: _Op, theta: Array) -> None:
        for old, new in op.extra["pairs"]:
            self.x[new], self.y[new] = self.x[old], self.y[old]
            self.set_yaw(new, self.yaw[old])
        self.group_yaw[op.subject[1]] = self.group_yaw.get(op.extra["source"], np.zeros(self.batch)).copy()

    def finalize(self, op: _Op, theta: Array) -> None:
        """After the subject's last entry: its position rules once more, for its final yaw."""
        for position_op in self.position_ops.get(op.subject, []):
            position_op.step(self, position_op, theta)

    def align_edge(self, op: _Op, theta: Array) -> None:
        rule: EdgeRule = op.extra["rule"]
        box = self.box(op.subject)
        lo, hi = _AXIS_ROWS[rule.axis]
        target = self.box(op.target) if op.target else box
        value = _edge(target, lo, hi, rule.b_edge)
        if rule.direction:
            value = value + rule.direction * theta[:, op.slots["distance"]]
        delta = value - _edge(box, lo, hi, rule.a_edge)
        if rule.axis == "x":
            self.move(op.subject, delta, 0.0)
        else:
            self.move(op.subject, 0.0, delta)

    def mirror(self, op: _Op, theta: Array) -> None:
        box = self.box(op.subject)
        b = self.box(op.target) if op.target else box
        c = self.box(op.extra["C"])
        # Mirroring doubles distances, so chains of it could overflow: centres stay within FAR_M (such an
        # object is far off any support and fails as such).
        tx = np.clip((c[0] + c[1]) - (b[0] + b[1]) / 2, -FAR_M, FAR_M)
        ty = np.clip((c[2] + c[3]) - (b[2] + b[3]) / 2, -FAR_M, FAR_M)
        self.move(op.subject, tx - (box[0] + box[1]) / 2, ty - (box[2] + box[3]) / 2)

    def stand(self, op: _Op, theta: Array) -> None:
        box = self.box(op.subject)
        dx = theta[:, op.slots["x"]] - (box[0] + box[1]) / 2 if "x" in op.slots else 0.0
        dy = theta[:, op.slots["y"]] - (box[2] + box[3]) / 2 if "y" in op.slots else 0.0
        self.move(op.subject, dx, dy)

    def turn_by_rule(self, op: _Op, theta: Array) -> None:
        offset = theta[:, op.slots["yaw_offset"]] if "yaw_offset" in op.slots else np.zeros(self.batch)
        self.turn(op.subject, op.extra["value"](self, op, offset))

    # yaw rules: one per YawMode, each the new yaw (batch,) before the turn
    def _yaw_absolute(self, op: _Op, offset: Array) -> Array:
        return op.extra["rule"].angle + offset

    def _yaw_random(self, op: _Op, offset: Array) -> Array:
        return np.full(self.batch, op.extra["angle"])

    def _yaw_same(self, op: _Op, offset: Array) -> Array:
        return self.node_yaw(op.target or ("root", None)) + offset

    def _yaw_opposite(self, op: _Op, offset: Array) -> Array:
        return self.node_yaw(op.target or ("root", None)) + math.pi + offset

    def _yaw_toward(self, op: _Op, offset: Array) -> Array:
        a, b = self.box(op.subject), self.box(op.target or ("root", None))
        return np.arctan2((b[2] + b[3] - a[2] - a[3]) / 2, (b[0] + b[1] - a[0] - a[1]) / 2) + offset

    def _yaw_relative_side(self, op: _Op, offset: Array) -> Array:
        """Keep the yaw or add a quarter turn, whichever lines A's box up better with B's."""
        current = self.node_yaw(op.subject).copy()
        b = self.box(op.target or ("root", None))
        scores = []
        for candidate in (current + offset, current + offset + math.pi / 2):
            self.turn(op.subject, candidate)
            a = self.box(op.subject)
            scores.append(_overlap_1d(a[0], a[1], b[0], b[1]) + _overlap_1d(a[2], a[3], b[2], b[3]))
        self.turn(op.subject, current)
        return np.where(scores[0] >= scores[1], current + offset, current + offset + math.pi / 2)


# The handler tables. Each program entry is compiled by the method of its solver, and within the spatial and group
# solvers by the handler of its effect; a yaw rule's new yaw is computed by the rule of its mode.
# tests/program/test_conformance.py checks that they cover every Solver, spatial and group Effect and YawMode.
SOLVER_ENTRIES: Mapping[Solver, Callable[[CompiledLayout, Relation, PredicateSpec], _Op | None]] = {
    Solver.SPATIAL: CompiledLayout._spatial_entry,
    Solver.GROUP: CompiledLayout._group_entry,
    Solver.PHYSICAL: CompiledLayout._physical,
}
SPATIAL_HANDLERS: Mapping[Effect, SpatialHandler] = {
    Effect.EDGE: CompiledLayout._edge_op,
    Effect.SYMMETRY: CompiledLayout._symmetry_op,
    Effect.BASE: CompiledLayout._base_op,
    Effect.YAW: CompiledLayout._yaw_op,
}
GROUP_HANDLERS: Mapping[Effect, GroupHandler] = {
    Effect.GROUP: CompiledLayout._group_op,
    Effect.COPY_GROUP: CompiledLayout._copy_group_op,
}
YAW_RULES: Mapping[YawMode, Callable[[_State, _Op, Array], Array]] = {
    YawMode.ABSOLUTE: _State._yaw_absolute,
    YawMode.RANDOM: _State._yaw_random,
    YawMode.SAME: _State._yaw_same,
    YawMode.OPPOSITE: _State._yaw_opposite,
    YawMode.TOWARD: _State._yaw_toward,
    YawMode.RELATIVE_SIDE: _State._yaw_relative_side,
}
_AXIS_ROWS = {"x": (0, 1), "y": (2, 3)}  # rows of a box (min_x, max_x, min_y, max_y) along each axis


def _edge(box: Array, lo: int, hi: int, which: str) -> Array:
    if which == "min":
        return box[lo]
    if which == "max":
        return box[hi]
    return (box[lo] + box[hi]) / 2


def _overlap_1d(a0: Array, a1: Array, b0: Array, b1: Array) -> Array:
    return np.maximum(0.0, np.minimum(a1, b1) - np.maximum(a0, b0))
