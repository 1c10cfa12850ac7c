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
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from physcensis.geometry.footprints import Array, hull_area, pad_hull
from physcensis.ids import ROOT_ID, copy_member_id
from physcensis.program.model import Declaration, Program, Relation
from physcensis.program.registry import ParamSpec, Stage
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
    kind: str  # edge | sym | base | yaw | group | copy | finalize
    subject: Node
    target: Node | None = None
    relation: Relation | None = None
    slots: dict[str, int] = field(default_factory=dict)  # param name -> slot index
    extra: dict[str, Any] = field(default_factory=dict)


class CompiledLayout:
    """A program's spatial part as operations over (object, sample) arrays."""

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
        self._compile(program, hulls)
        size = max(len(h) for h in self.hull_list) if self.hull_list else 3
        self.hulls = np.stack([pad_hull(h, size) for h in self.hull_list]) if self.hull_list else np.zeros((0, 3, 2))
        self.areas = np.array([hull_area(h) for h in self.hull_list])

    # -- compilation -----------------------------------------------------------------
    def _compile(self, program: Program, hulls: Mapping[str, Array]) -> None:
        placement: dict[str, str] = {}
        for rel in program.relations:
            if rel.spec is not None and rel.spec.placement and isinstance(rel.subject, str):
                placement.setdefault(rel.subject, rel.spec.placement)
        descriptions = {d.object_id for d in program.entries if isinstance(d, Declaration)}
        for oid in descriptions:
            if placement.get(oid) == "base":
                if oid not in hulls:
                    raise KeyError(f"no footprint for {oid}")
        group_physical: dict[str, list[str]] = {}
        last_entry: dict[Node, int] = {}
        ops: list[_Op] = []
        for rel in program.relations:
            spec = rel.spec
            if spec is None:
                continue
            if spec.stage is Stage.PHYSICAL:
                self._physical(rel)
                continue
            if spec.name == "GROUP":
                members = [m for m in rel.target if m in self.index]
                group_physical[rel.subject] = [m for m in rel.target if m not in self.index]
                anchor = rel.params.get("anchor") or (rel.target[0] if rel.target else None)
                self.group_members[rel.subject] = [self.index[m] for m in members]
                ops.append(_Op("group", ("group", rel.subject), relation=rel,
                               extra={"anchor": self.index.get(anchor) if anchor else None}))
                continue
            if spec.name == "COPY-GROUP":
                source = rel.target
                pairs = []
                for member in self.group_members.get(source, []):
                    new_id = copy_member_id(self.ids[member], rel.subject)
                    pairs.append((member, self._add(new_id, self.hull_list[member])))
                    self.copies[new_id] = self.copies.get(self.ids[member], self.ids[member])
                    self.entries_of[new_id] = [rel.index]
                self.group_members[rel.subject] = [new for _, new in pairs]
                physical = group_physical.get(source, [])
                group_physical[rel.subject] = [copy_member_id(m, rel.subject) for m in physical]
                spatial = [self.ids[i] for i in self.group_members.get(source, [])]
                self._copy_physical({*spatial, *physical}, rel.subject)
                ops.append(_Op("copy", ("group", rel.subject), ("group", source), rel, extra={"pairs": pairs}))
                continue
            subject = rel.subject
            if subject in self.group_members:
                node: Node = ("group", subject)
            elif placement.get(subject) == "base":
                if subject not in self.index:
                    self._add(subject, np.asarray(hulls[subject], dtype=float))
                    self.entries_of[subject] = []
                node = ("obj", self.index[subject])
            else:
                if spec.yaw is not None:
                    self.yaw_rules.setdefault(subject, []).append(rel)
                continue
            self.entries_of.setdefault(subject, []).append(rel.index)
            if node[0] == "group":
                for member in self.group_members[subject]:
                    self.entries_of.setdefault(self.ids[member], []).append(rel.index)
            op = self._spatial_op(rel, node)
            ops.append(op)
            last_entry[node] = len(ops) - 1
        finals = {pos: node for node, pos in last_entry.items()}
        for pos, op in enumerate(ops):
            self.ops.append(op)
            if pos in finals:
                self.ops.append(_Op("finalize", finals[pos]))

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

    def _spatial_op(self, rel: Relation, node: Node) -> _Op:
        spec = rel.spec
        assert spec is not None
        short = min(self.support.size)
        if spec.edge is not None:
            op = _Op("edge", node, self._node(rel.target), rel, extra={"rule": spec.edge})
            dist = spec.param("distance")
            if dist is not None:
                value = rel.params.get("distance", dist.default)
                op.slots["distance"] = self._slot(rel, dist, float(value), dist.low or 0.0, dist.high or 10.0,
                                                  short / 10.0)
            return op
        if spec.name == "SYMMETRY-ALONG":
            return _Op("sym", node, self._node(rel.target), rel, extra={"C": self._node(str(rel.params["C"]))})
        if spec.name == "PLACE-ON-BASE":
            op = _Op("base", node, None, rel)
            for name, half in (("x", self.hx), ("y", self.hy)):
                param = spec.param(name)
                if param is not None and rel.params.get(name) is not None:
                    op.slots[name] = self._slot(rel, param, float(rel.params[name]), -half, half, short / 10.0)
            return op
        assert spec.yaw is not None, spec.name
        op = _Op("yaw", node, self._node(rel.target), rel, extra={"rule": spec.yaw})
        if spec.yaw.mode == "random":
            op.extra["angle"] = float(self._rng.uniform(0.0, 2.0 * math.pi))
        else:
            offset = spec.param("yaw_offset")
            assert offset is not None
            op.slots["yaw_offset"] = self._slot(rel, offset, float(rel.params.get("yaw_offset", 0.0)),
                                                -math.pi, math.pi, YAW_RADIUS)
        return op

    def _physical(self, rel: Relation) -> None:
        if isinstance(rel.subject, tuple):
            ids = tuple(s for s in rel.subject if isinstance(s, str))
        else:
            ids = (rel.subject,)
        self.pending.append(PhysicalRequest(rel, ids, str(rel.target)))

    def _copy_physical(self, members: set[str], new_group: str) -> None:
        """Members placed physically (a cup on a plate) are copied as new requests on the copies."""
        for request in list(self.pending):
            if request.subject_ids and all(s in members for s in request.subject_ids):
                target = request.target
                new_target = copy_member_id(target, new_group) if target in members else target
                self.pending.append(PhysicalRequest(
                    request.relation, tuple(copy_member_id(s, new_group) for s in request.subject_ids),
                    new_target, copied_from=request.subject_ids[0]))

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
            g: np.array(m, dtype=np.intp) for g, m in layout.group_members.items()}
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

    def apply(self, op: _Op, theta: Array) -> None:
        kind = op.kind
        if kind == "group":
            anchor = op.extra["anchor"]
            self.group_yaw[op.subject[1]] = self.yaw[anchor].copy() if anchor is not None else np.zeros(self.batch)
            return
        if kind == "copy":
            for old, new in op.extra["pairs"]:
                self.x[new], self.y[new] = self.x[old], self.y[old]
                self.set_yaw(new, self.yaw[old])
            source = op.target[1] if op.target else None
            self.group_yaw[op.subject[1]] = self.group_yaw.get(source, np.zeros(self.batch)).copy()
            return
        if kind == "finalize":
            for position_op in self.position_ops.get(op.subject, []):
                self.position(position_op, theta)
            return
        if kind == "yaw":
            self.turn(op.subject, self.yaw_value(op, theta))
            return
        self.position_ops.setdefault(op.subject, []).append(op)
        self.position(op, theta)

    def position(self, op: _Op, theta: Array) -> None:
        axis_index = {"x": (0, 1), "y": (2, 3)}
        box = self.box(op.subject)
        if op.kind == "edge":
            rule = op.extra["rule"]
            lo, hi = axis_index[rule.axis]
            target = self.box(op.target) if op.target else box
            value = _edge(target, lo, hi, rule.b_edge)
            if rule.direction:
                value = value + rule.direction * theta[:, op.slots["distance"]]
            delta = value - _edge(box, lo, hi, rule.a_edge)
            if rule.axis == "x":
                self.move(op.subject, delta, 0.0)
            else:
                self.move(op.subject, 0.0, delta)
        elif op.kind == "sym":
            b = self.box(op.target) if op.target else box
            c = self.box(op.extra["C"])
            # Mirroring doubles distances, so chains of it could overflow: centres stay within FAR_M (such an
            # object is far off any support and fails as such).
            tx = np.clip((c[0] + c[1]) - (b[0] + b[1]) / 2, -FAR_M, FAR_M)
            ty = np.clip((c[2] + c[3]) - (b[2] + b[3]) / 2, -FAR_M, FAR_M)
            self.move(op.subject, tx - (box[0] + box[1]) / 2, ty - (box[2] + box[3]) / 2)
        elif op.kind == "base":
            dx = theta[:, op.slots["x"]] - (box[0] + box[1]) / 2 if "x" in op.slots else 0.0
            dy = theta[:, op.slots["y"]] - (box[2] + box[3]) / 2 if "y" in op.slots else 0.0
            self.move(op.subject, dx, dy)

    def yaw_value(self, op: _Op, theta: Array) -> Array:
        rule = op.extra["rule"]
        offset = theta[:, op.slots["yaw_offset"]] if "yaw_offset" in op.slots else 0.0
        if rule.mode == "random":
            return np.full(self.batch, op.extra["angle"])
        if rule.mode == "absolute":
            return rule.angle + offset
        target = op.target or ("root", None)
        if rule.mode == "same":
            return self.node_yaw(target) + offset
        if rule.mode == "opposite":
            return self.node_yaw(target) + math.pi + offset
        if rule.mode == "toward":
            a, b = self.box(op.subject), self.box(target)
            return np.arctan2((b[2] + b[3] - a[2] - a[3]) / 2, (b[0] + b[1] - a[0] - a[1]) / 2) + offset
        # relative_side: keep the yaw or add a quarter turn, whichever lines A's box up better with B's
        current = self.node_yaw(op.subject).copy()
        b = self.box(target)
        scores = []
        for candidate in (current + offset, current + offset + math.pi / 2):
            self.turn(op.subject, candidate)
            a = self.box(op.subject)
            scores.append(_overlap_1d(a[0], a[1], b[0], b[1]) + _overlap_1d(a[2], a[3], b[2], b[3]))
        self.turn(op.subject, current)
        return np.where(scores[0] >= scores[1], current + offset, current + offset + math.pi / 2)


def _edge(box: Array, lo: int, hi: int, which: str) -> Array:
    if which == "min":
        return box[lo]
    if which == "max":
        return box[hi]
    return (box[lo] + box[hi]) / 2


def _overlap_1d(a0: Array, a1: Array, b0: Array, b1: Array) -> Array:
    return np.maximum(0.0, np.minimum(a1, b1) - np.maximum(a0, b0))
