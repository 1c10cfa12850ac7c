"""Where the larger things stand on the support: a grid of spots for the anchors, rows and columns, stacks side by
side, things beside, between or around others, a desk's monitor, keyboard and mouse, a shelf's row of books. All
written as spatial predicates (PLACE-ON-BASE and the edge, alignment and facing rules)."""

from __future__ import annotations

import math
import re
from collections.abc import Iterator
from dataclasses import replace

import numpy as np

from physcensis.agent import choosing
from physcensis.agent.base import AgentContext
from physcensis.agent.planning.counts import LOOSE_RANGES, Counts
from physcensis.agent.planning.entries import (
    ALIGN_BACK,
    ALIGN_CENTER_FB,
    ALIGN_CENTER_LR,
    ALIGN_LEFT,
    ALIGN_RIGHT,
    BACK_OF,
    FACING_FRONT,
    FACING_LEFT,
    FACING_SAME_AS,
    FACING_TO,
    FRONT_OF,
    GROUP,
    LEFT_OF,
    PLACE_ON_BASE,
    RANDOM_ROT,
    RIGHT_OF,
    Entry,
    Plan,
)
from physcensis.agent.planning.stacks import Stacks
from physcensis.agent.planning.state import Ids, PlanState, choice_key, rings_on, row_lengths
from physcensis.agent.planning.variants import Variants, area
from physcensis.agent.reading import Mention, SceneRequest
from physcensis.assets.model import Asset
from physcensis.program import PREDICATES
from physcensis.viewpoint import DIRECTION, frame_side

BOOK_ROW_LEAST = 8  # books a drawn row of no said count keeps even on a crowded shelf
BETWEEN_ROW_GAP = 0.01  # between the things of a row said to stand between two others, and at its ends
TURN_ROOM = 0.02  # a messy anchor turns any way only where its diagonal and this much fit the support
Spot = tuple[float, float]
Half = tuple[float, float]  # the support's half extents (x, y)


GATHER_ROOM = 8  # a group of things gathers when the table has this many times their footprint


class Layout:
    """Writes the spatial part of a plan: which mentions are anchors, and where each anchor's objects stand."""

    def __init__(self, state: PlanState, variants: Variants, counts: Counts, stacks: Stacks) -> None:
        self.state = state
        self.variants = variants
        self.counts = counts
        self.stacks = stacks
        self._lone = False  # whether the prompt's things make one group on the support
        self._gathered = False  # whether they were gathered beside the largest of them (`gather`)

    def is_anchor(self, k: int, m: Mention, mentions: list[Mention], request: SceneRequest, kind: str) -> bool:
        """Whether mention k stands on the support where the layout puts it (else the physical solver places it)."""
        if m.on is not None or any(k in o.contents for o in mentions) or rings_on(m, mentions):
            return False
        if self.stacks.pile_is_free(m):
            return False
        if m.stacked or m.contents or m.centre or m.region or m.around is not None or m.beside is not None:
            return True
        if m.arrangement in ("row", "column"):
            return True
        if any(k in (o.on, o.beside, o.around) for o in mentions):
            return True
        if kind == "shelf" and "upright" in m.phrase:
            return True
        if request.messy or request.dense or kind in ("floor", "box"):
            return False
        asset = self.variants.assets(m)[0]
        return bool(asset.size[0] * asset.size[1] > 0.03 or request.rows)  # large things get a spot of their own

    def gather(self, mentions: list[Mention], request: SceneRequest, kind: str, table_area: float) -> None:
        """A few things the words relate to nothing ("a teapot and two cups") on a table much larger than they are:
        a person sets them down together, not over the whole top. The largest takes the middle spot (a lone
        anchor's) and the others stand beside it, on sides the seed picks."""
        self._gathered = False
        if kind != "table" or request.messy or request.dense or request.diners or request.rows:
            return
        if not 2 <= len(mentions) <= 3 or sum(m.count for m in mentions) > 4 or any(_related(m) for m in mentions):
            return
        footprints = [area(self.variants.assets(m)[0]) for m in mentions]
        if sum(f * m.count for f, m in zip(footprints, mentions, strict=True)) * GATHER_ROOM > table_area:
            return
        largest = max(range(len(mentions)), key=lambda k: (footprints[k], -k))
        for k, m in enumerate(mentions):
            if k != largest:
                m.beside, m.side = largest, "beside"
        self._gathered = True

    def _gathered_spot(self, hx: float, hy: float) -> Spot:
        """Where a gathered group stands: the middle canonically; with variety anywhere in the middle of the table
        and towards its front, in reach of the person it was set down for."""
        point = self.state.draws.spread_point("gathered spot")
        if point is None:
            return 0.0, 0.0
        u, v = point
        return (-0.1 + 0.5 * u) * hx, (-0.3 + 0.6 * v) * hy

    def lay_out(
        self,
        plan: Plan,
        anchors: list[int],
        mentions: list[Mention],
        ids: Ids,
        request: SceneRequest,
        context: AgentContext,
    ) -> None:
        """The anchors' objects: a shelf's upright books first, a desk's monitor set, then each anchor at its grid
        spot or beside what it is said to stand by, and last what stands around a centre piece."""
        hx, hy = context.support.half_extents
        upright = [k for k in anchors if "upright" in mentions[k].phrase]
        if upright:
            self._book_row(plan, upright, mentions, ids, context)
        rest = _targets_first([k for k in anchors if k not in upright], mentions)
        office = self._office(plan, rest, mentions, ids)
        taking = len(_taking_spots(rest, mentions, ids, office))
        spots = iter(self._spots(taking, hx, hy) + _grid_spots(len(rest), hx, hy))  # the full grid: never short
        if self._gathered:
            spots = iter([self._gathered_spot(hx, hy), *spots])
        self._lone = len(rest) == 1
        centred = any(mentions[k].centre for k in rest)
        ring_centres = {mentions[k].around for k in rest} - {None}
        for k in rest:
            m = mentions[k]
            if k in ids or k in office or (m.around is not None and m.around in ids):
                continue
            spot = self._region_spot(m, (hx, hy)) if m.region and m.beside is None else _first_spot(m, ids, spots)
            if k in ring_centres and not centred and m.beside is None:
                spot = (0.0, 0.0)  # what others stand around takes the middle
            self._anchor(plan, k, m, spot, ids, request, (hx, hy))
        for k in rest:  # things arranged around a centre piece
            m = mentions[k]
            if m.around is not None and m.around in ids and k not in ids:
                self._ring(plan, k, m, mentions[m.around], ids[m.around][0], ids, (hx, hy))

    def _spots(self, n: int, hx: float, hy: float) -> list[Spot]:
        """Where the anchors stand: the grid's spots, with variety in a drawn order, each moved within its cell (a
        lone anchor near the middle of the support, not only at its centre)."""
        draws = self.state.draws
        spots = _grid_spots(n, hx, hy)
        if not draws.on or not spots:
            return spots
        rows, cols = _grid_shape(n, hx, hy)
        # Each spot moves within a quarter of its cell either way: a lone anchor (with what stands beside it) keeps to
        # the middle of the support, as a person sets one group down on a large table, not near its edges or corners.
        reach = draws.spread(0.25)
        cell_x, cell_y = 2 * hx * 0.8 / rows, 2 * hy * 0.8 / cols
        moved = []
        for i, (x, y) in enumerate(draws.order(spots, "spots")):
            u, v = draws.spread_point("spot", i) or (0.5, 0.5)
            dx, dy = (2 * u - 1) * reach * cell_x, (2 * v - 1) * reach * cell_y
            moved.append((float(np.clip(x + dx, -0.8 * hx, 0.8 * hx)), float(np.clip(y + dy, -0.8 * hy, 0.8 * hy))))
        return moved

    def _region_spot(self, m: Mention, half: Half) -> Spot:
        """A point towards the place the words give m on the support, beyond it where it is an edge or a corner
        (_row_start keeps the group on the support, a margin from its edges). What the words leave open is drawn: which
        corner ("in the corner"), which end or edge, where along the edge."""
        hx, hy = half
        draws, key = self.state.draws, choice_key(m)
        words = {"end" if w == "ends" else w for w in m.region}  # both ends, of more than two things: an end
        if "end" in words:  # an end of the support's longer side
            ends = ["left", "right"] if hy >= hx else ["back", "front"]
            words.add(draws.pick(ends[0], ends, "end", *key))
        if "edge" in words:
            words.add(draws.pick("back", ["back", "left", "right", "front"], "edge", *key))
        if "corner" in words:
            if not words & {"back", "front"}:
                words.add(draws.pick("back", ["back", "front"], "corner depth", *key))
            if not words & {"left", "right"}:
                words.add(draws.pick("left", ["left", "right"], "corner side", *key))
        x = -hx if "back" in words else hx if "front" in words else None
        y = DIRECTION["left"][1] * hy if "left" in words else DIRECTION["right"][1] * hy if "right" in words else None
        along = draws.spread_point("along", *key) or (0.5, 0.5)
        # an open coordinate: the middle canonically, anywhere near it with variety; the middle when the words say so
        free = 0.0 if m.centre else 0.6 * (2 * along[0] - 1)
        sharing = [o for o in self.state.mentions if o.region == m.region and o.beside is None and o.on is None]
        if len(sharing) > 1 and not words & {"corner", "end"} and not m.centre and (x is None) != (y is None):
            offset = self._side_by_side(m, sharing, hy if x is not None else hx, along[0])
            if x is not None:
                return x, DIRECTION["left"][1] * offset
            return -offset, y if y is not None else 0.0
        return (x if x is not None else free * hx, y if y is not None else free * hy)

    def _side_by_side(self, m: Mention, sharing: list[Mention], half: float, drawn: float) -> float:
        """Where along a band of the support ("along the back") m stands among the things that share it ("a
        microwave, a blender and a rice cooker along the back"): side by side in the order said, from the viewer's
        left (or from the back), with the room left over as gaps; with variety, each a little way within its gaps.
        The distance from the band's middle towards its start (the viewer's left, or the back)."""
        widths = [max(self.variants.assets(o)[0].size[:2]) * (o.count if o.count > 1 else 1) for o in sharing]
        slot = next(i for i, o in enumerate(sharing) if o is m)
        spare = max(0.0, 1.8 * half - sum(widths))
        gap = spare / (len(sharing) + 1)
        start = -0.9 * half + gap * (slot + 1) + sum(widths[:slot])
        centre = start + widths[slot] / 2 + 0.4 * gap * (2 * drawn - 1)
        return round(-centre, 3)

    def _margin(self, m: Mention) -> float:
        """How far from the support's edges a group with a place of its own keeps (none without one)."""
        if not m.region:
            return 0.0
        draws, room = self.state.draws, self.state.room
        most = 0.15 * min(room.depth, room.width) / 2 if room is not None else 0.03  # a narrow shelf: close to its edge
        margin = draws.uniform(0.03, 0.01, 0.03 + draws.spread(0.05), "margin", *choice_key(m))
        return round(min(margin, max(0.005, most)), 3)

    def _facing_entry(self, oid: str, facing: str, asset: Asset) -> Entry:
        """`oid` turned by the yaw rule `facing`; with variety, a thing that has no front (a round tin, a plate) turned
        a little more, as a person sets it down (never what a front faces the way the words say, nor a random turn)."""
        draws = self.state.draws
        takes_offset = any(p.name == "yaw_offset" for p in PREDICATES[facing].params)
        if draws.canonical("turn", oid) or asset.has_front or not takes_offset:
            return [oid, facing, "root", {}]
        reach = math.radians(draws.spread(10.0))
        return [oid, facing, "root", {"yaw_offset": round(draws.uniform(0.0, -reach, reach, "turn", oid), 3)}]

    def _offset_along(self, canonical: float, *key: object) -> float:
        """A position along the support's width for something the prompt does not place (the monitor of a desk):
        within the middle third with variety."""
        draws, room = self.state.draws, self.state.room
        half = (room.width / 2 if room is not None else 0.3) * draws.spread(0.3)
        return round(draws.uniform(canonical, canonical - half, canonical + half, *key), 3)

    def _side(self, m: Mention) -> str:
        """The frame's side for mention m's side word, said as the viewer sees it ("left of" is the frame's right:
        viewpoint.py); "beside" / "next to": the side away from the support's edge its anchor is said to stand at,
        else right canonically, either with variety."""
        if m.side != "beside":
            return frame_side(m.side)
        region = self.state.mentions[m.beside].region if m.beside is not None else ()
        if "left" in region or "right" in region:  # "a holder at the far left, a tube next to it": on its right
            return frame_side("right" if "left" in region else "left")
        return self.state.draws.pick("right", ["right", "left"], "side", *choice_key(m))

    def _distance(self, canonical: float, *key: object) -> float:
        """A gap between two things said to stand near each other: a few centimetres either way with variety."""
        draws = self.state.draws
        return round(draws.uniform(canonical, 0.7 * canonical, canonical + draws.spread(0.04), *key), 3)

    def _anchor(
        self, plan: Plan, k: int, m: Mention, spot: Spot | None, ids: Ids, request: SceneRequest, half: Half
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
        laid = m.beside is not None and bool(ids.get(m.beside))
        pair = m.second is not None and bool(ids.get(m.second)) and laid  # both laid out, neither held
        if m.beside is not None and m.side == "between" and (len(ids.get(m.beside, [])) >= 2 or pair):
            self._between(plan, k, m, ids, request)
            return
        if "ends" in m.region and m.count == 2:
            self._at_both_ends(plan, k, m, ids, request, half)
            return
        shape = row_lengths(m)
        gap = self.state.gap(m)
        extent = self._row_extent(m, shape, gap)
        first_row: list[str] = []
        for length in shape:
            row: list[str] = []
            for _ in range(length):
                description, asset = self.variants.describe(m, len(ids[k]))
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

    def _at_both_ends(self, plan: Plan, k: int, m: Mention, ids: Ids, request: SceneRequest, half: Half) -> None:
        """ "a lamp at each end of the shelf": one of m's two objects at either end of the support's longer side."""
        hx, hy = half
        extent = self._row_extent(m, [1], self.state.gap(m))
        for end in ("left", "right") if hy >= hx else ("back", "front"):
            description, asset = self.variants.describe(m, len(ids[k]))
            oid = plan.new_id(m.category)
            at_end = replace(m, region=(end,))
            spot = self._region_spot(at_end, half)
            plan.anchors.append([oid, description])
            plan.anchors += self._first_of(plan, oid, at_end, spot, ids, self._row_start(at_end, spot, extent, half))
            plan.anchors.append(self._facing_entry(oid, self._facing(asset, request, alone=False), asset))
            ids[k].append(oid)

    def _row_start(
        self, m: Mention, spot: Spot | None, extent: tuple[float, float, float, float], half: Half
    ) -> Spot | None:
        """Where the first of m's rows stands; the rows of the support's one group, wider than half the support, may
        start anywhere their length leaves room for (a line of jars along a shelf is not always at its left end)."""
        start = _row_start(spot, extent, half, self._margin(m))
        width, hy = extent[0], half[1]
        if start is None or not self._lone or m.region or not hy < width < 2 * hy:
            return start
        point = self.state.draws.spread_point("slide", *choice_key(m))
        if point is None:
            return start
        low, high = -hy + width - extent[2] / 2, hy - extent[2] / 2
        return start[0], round(low + point[0] * (high - low), 3)

    def _facing(self, asset: Asset, request: SceneRequest, alone: bool) -> str:
        """Which way an anchor faces: any way in a messy scene where it fits the support turned any way; a lone one
        turns a quarter when only then does its footprint fit the support (a letter tray deeper than the shelf)."""
        room = self.state.room
        if request.messy and (room is None or math.hypot(*asset.size[:2]) <= min(room.depth, room.width) - TURN_ROOM):
            return RANDOM_ROT
        if alone and room is not None and choosing.fit_tier(asset, room) % 3 == 1:
            return FACING_LEFT
        return FACING_FRONT

    def _beside_each(self, plan: Plan, k: int, m: Mention, ids: Ids, request: SceneRequest) -> None:
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
            description, asset = self.variants.describe(m, n)
            oid = plan.new_id(m.category)
            target = targets[n % len(targets)] if m.per == m.beside else whole
            plan.anchors.append([oid, description])
            distance = self._distance(0.05, "beside", n, *choice_key(m))
            plan.anchors += _beside_entries(oid, target, sides[n % len(sides)], distance)
            facing = RANDOM_ROT if request.messy else FACING_FRONT
            plan.anchors.append(self._facing_entry(oid, facing, asset))
            ids[k].append(oid)

    def _between(self, plan: Plan, k: int, m: Mention, ids: Ids, request: SceneRequest) -> None:
        """ "a vase between two candles", "a lamp between them": right of the first, left of the second, lined up."""
        assert m.beside is not None
        left, right = (ids[m.beside] + ids[m.beside])[:2]
        after, before = RIGHT_OF, LEFT_OF  # in the frame, the second of a pair stands right of the first
        if m.second is not None and ids.get(m.second):  # "between A and B": B stands to the viewer's right of A
            right = ids[m.second][0]
            after, before = (LEFT_OF, RIGHT_OF) if frame_side("right") == "left" else (RIGHT_OF, LEFT_OF)
        gap = BETWEEN_ROW_GAP if m.count > 1 else 0.03
        for n in range(m.count):  # several stand side by side: "five books between a pair of bookends"
            description, asset = self.variants.describe(m, n)
            oid = plan.new_id(m.category)
            first = ids[k][-1] if ids[k] else left
            # one rule per axis (a later one replaces an earlier): a row is a chain from the first of the pair, which
            # stands as far from the second as the row needs
            along = [[oid, after, first, {"distance": gap}]]
            if m.count == 1:
                along.append([oid, before, right, {"distance": gap}])
            plan.anchors += [
                [oid, description],
                [oid, PLACE_ON_BASE, "root", {}],
                *along,
                [oid, ALIGN_CENTER_FB, left, {}],
                self._facing_entry(oid, self._facing(asset, request, alone=True), asset),
            ]
            ids[k].append(oid)

    def _room_for_between(self, m: Mention) -> float:
        """The room to leave between the two things something is said to stand between ("a clock between a lamp and
        a pile of books": the books stand right of the lamp, the clock's width and two gaps away)."""
        mentions = self.state.mentions
        k = next((j for j, o in enumerate(mentions) if o is m), None)
        inside = [o for o in mentions if k is not None and o.second == k and o.side == "between"]
        return sum(_row_width(self.variants.assets(o)[0], o.count, 0.03) + 0.03 for o in inside)

    def _room_between(self, k: int, n: int, gap: float) -> float:
        """The width to leave before the second object of mention k's row for the things said to stand between."""
        inside = [o for o in self.state.mentions if o.beside == k and o.side == "between"] if n == 1 else []
        return sum(_row_width(self.variants.assets(o)[0], o.count, gap) for o in inside)

    def _deeper_than_wide(self, plan: Plan, oid: str) -> bool:
        """Whether the object `oid` names is longer front to back than left to right (its ends are front and back)."""
        description = next((str(e[1]) for e in plan.anchors if e[0] == oid and len(e) == 2), None)
        if description is None:
            return False
        x, y, _ = self.state.catalogue.resolve(description).size
        return bool(x > y)

    def _first_of(
        self, plan: Plan, oid: str, m: Mention, spot: Spot | None, ids: Ids, start: Spot | None
    ) -> list[Entry]:
        """Where the first object of a mention stands: its spot, or beside (left of, in front of ...) its target."""
        if spot is None and m.beside is not None and ids.get(m.beside):
            distance = self._distance(0.05, "beside", *choice_key(m)) + self._room_for_between(m)
            return _beside_entries(oid, _standing(plan, ids[m.beside]), self._side(m), distance)
        x, y = start if start is not None else (0.0, 0.0)
        return [[oid, PLACE_ON_BASE, "root", {"x": round(x, 3), "y": round(y, 3)}]]

    def _row_extent(self, m: Mention, shape: list[int], gap: float) -> tuple[float, float, float, float]:
        """The width (left to right) of the longest row, the depth (front to back) of all rows, and one object's
        width and depth."""
        x, y, _ = self.variants.assets(m)[0].size
        return max(shape) * y + (max(shape) - 1) * gap, len(shape) * x + (len(shape) - 1) * gap, y, x

    def _stacks(
        self, plan: Plan, k: int, m: Mention, spot: Spot | None, ids: Ids, request: SceneRequest, half: Half
    ) -> None:
        """Each stack's bottom object stands beside the previous stack's; the others rest each on the one below."""
        heights = list(m.sizes) or [m.count]
        spacing = self._distance(0.05, "stacks", *choice_key(m))
        stacks = [self.stacks.levels(m, request, height, which) for which, height in enumerate(heights)]
        width = sum(levels[0].size[1] for levels in stacks) + (len(stacks) - 1) * spacing
        depth = max(levels[0].size[0] for levels in stacks)
        start = _row_start(spot, (width, depth, stacks[0][0].size[1], stacks[0][0].size[0]), half, self._margin(m))
        bases: list[str] = []
        for levels in stacks:
            oid = plan.new_id(m.category)
            plan.anchors.append([oid, levels[0].description])
            if bases:
                plan.anchors += _beside_entries(oid, bases[-1], "right", spacing)
            else:
                plan.anchors += self._first_of(plan, oid, m, spot, ids, start)
            plan.anchors.append([oid, self._facing(levels[0], request, alone=len(stacks) == 1), "root", {}])
            bases.append(oid)
            ids[k].append(oid)
            ids[k] += self.stacks.stack_on(plan, oid, m, levels, request)

    def _ring(self, plan: Plan, k: int, m: Mention, centre: Mention, centre_id: str, ids: Ids, half: Half) -> None:
        """Mention k's objects evenly around the centre piece, each facing it (kept on the support)."""
        hx, hy = half
        ids[k] = []
        assets = self.variants.assets
        radius = 0.5 * max(assets(centre)[0].size[:2]) + 0.5 * max(assets(m)[0].size[:2]) + 0.04
        cx, cy = _spot_of(plan, centre_id)
        turn = self.state.ring_turn(m)
        for n in range(m.count):
            angle = 2 * math.pi * n / m.count + turn
            description, _ = self.variants.describe(m, n)
            oid = plan.new_id(m.category)
            ids[k].append(oid)
            x = round(float(np.clip(cx + radius * math.cos(angle), -hx, hx)), 3)
            y = round(float(np.clip(cy + radius * math.sin(angle), -hy, hy)), 3)
            plan.anchors += [
                [oid, description],
                [oid, PLACE_ON_BASE, "root", {"x": x, "y": y}],
                [oid, FACING_TO, centre_id, {}],
            ]

    def _office(self, plan: Plan, anchors: list[int], mentions: list[Mention], ids: Ids) -> set[int]:
        """Monitor at the back, keyboard in front of it, mouse to its right as the person at the desk (the viewer)
        sees it."""
        by_cat = {mentions[k].category: k for k in anchors}
        if "monitor" not in by_cat or "keyboard" not in by_cat:
            return set()
        pair = [mentions[by_cat["monitor"]], mentions[by_cat["keyboard"]]]
        if any(m.count > 1 or m.beside is not None for m in pair):
            return set()  # several monitors, or a placement the prompt gives: the general layout
        describe = self.variants.describe
        monitor, keyboard = by_cat["monitor"], by_cat["keyboard"]
        mid = plan.new_id("monitor")
        plan.anchors += [
            [mid, describe(mentions[monitor], 0)[0]],
            [mid, PLACE_ON_BASE, "root", {"y": self._offset_along(0.0, "monitor")}],
            [mid, ALIGN_BACK, "root", {}],
            [mid, FACING_FRONT, "root", {}],
        ]
        kid = plan.new_id("keyboard")
        plan.anchors += [
            [kid, describe(mentions[keyboard], 0)[0]],
            [kid, PLACE_ON_BASE, "root", {}],
            [kid, FRONT_OF, mid, {"distance": self._distance(0.08, "keyboard")}],
            [kid, ALIGN_CENTER_LR, mid, {}],
            [kid, FACING_SAME_AS, mid, {}],
        ]
        ids[monitor], ids[keyboard] = [mid], [kid]
        done = {monitor, keyboard}
        placed_by_words = "mouse" in by_cat and _related(mentions[by_cat["mouse"]])  # a mouse said to stand somewhere
        if "mouse" in by_cat and not placed_by_words:  # stands there
            mouse = by_cat["mouse"]
            oid = plan.new_id("mouse")
            plan.anchors += [
                [oid, describe(mentions[mouse], 0)[0]],
                [oid, PLACE_ON_BASE, "root", {}],
                [oid, f"{frame_side('right').upper()}-OF", kid, {"distance": self._distance(0.05, "mouse")}],
                [oid, ALIGN_CENTER_FB, kid, {}],
                [oid, FACING_SAME_AS, kid, {}],
            ]
            ids[mouse] = [oid]
            done.add(mouse)
        return done

    def _book_row(
        self, plan: Plan, upright: list[int], mentions: list[Mention], ids: Ids, context: AgentContext
    ) -> None:
        """Books standing upright in a row along the back of a shelf; books the words ask to lie flat, one stack of
        them placed anywhere."""
        for k in upright:
            m = mentions[k]
            count = self._book_count(k, m, mentions, context, upright)
            start = self.state.draws.pick("left", ["left", "right"], "book row", *choice_key(m))  # the end it starts
            ids[k] = []
            for n in range(count):
                description, _ = self.variants.describe(m, n)
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
        tokens = " ".join(self.state.tokens)
        if "lying flat" in tokens and not any("flat" in m.phrase for m in mentions):
            match = re.search(r"(\w+) lying flat", tokens)
            word = match.group(1) if match else ""
            count = {"few": 3, "couple": 2, "two": 2, "three": 3, "some": 3}.get(word, 3)
            if word not in ("couple", "two", "three"):  # "a few lying flat": two to four
                count = self.state.draws.count(count, *LOOSE_RANGES["few"], "loose", "book lying flat")
            self.stacks.free_stack(plan, Mention("book", count, "book lying flat", (), 0, 0, True, True, stacked=True))

    def _book_count(
        self, k: int, m: Mention, mentions: list[Mention], context: AgentContext, upright: list[int]
    ) -> int:
        """How many books m's row holds: as said, else how many the seed says, ten or a few more; a drawn row leaves
        room on the shelf for what else is asked."""
        draws = self.state.draws
        count = m.count if m.explicit_count else max(m.count, 10)
        if m.explicit_count:
            return count
        high = count + 2
        if draws.on:
            room = self._books_in_room(k, m, mentions, context, upright)
            count, high = max(BOOK_ROW_LEAST, min(count, room)), max(BOOK_ROW_LEAST, min(high, room))
        return draws.count(count, count, high, "book row count", *choice_key(m))

    def _books_in_room(
        self, k: int, m: Mention, mentions: list[Mention], context: AgentContext, upright: list[int]
    ) -> int:
        """How many of m's upright books fit along the shelf beside the other free-standing things and a stack of
        books lying flat (the widest flat book, when the prompt asks for some)."""
        held = {j for o in mentions for j in o.contents}
        others = self.counts.width_of_others(mentions, k, held | set(upright))
        if "lying flat" in " ".join(self.state.tokens):
            flat = [a for a in self.state.catalogue.variants("book lying flat", 16) if "flat" in a.kind]
            others += max((min(a.size[:2]) for a in flat), default=0.0) + 0.03
        thickness = max(self.variants.describe(m, n)[1].size[1] for n in range(12)) + 0.003
        return int((2 * context.support.half_extents[1] - others) / thickness)


_SIDES = {  # where one object stands relative to another: the edge rule and the alignment that goes with it
    "beside": (RIGHT_OF, ALIGN_CENTER_FB),
    "right": (RIGHT_OF, ALIGN_CENTER_FB),
    "left": (LEFT_OF, ALIGN_CENTER_FB),
    "front": (FRONT_OF, ALIGN_CENTER_LR),
    "behind": (BACK_OF, ALIGN_CENTER_LR),
}


def _related(m: Mention) -> bool:
    """Whether the words place mention m anywhere or arrange it (on, in, beside, around, a region, a stack, a row)."""
    placed = (m.on, m.beside, m.around, m.held_by, m.per, m.alias)
    return any(x is not None for x in placed) or bool(m.contents or m.region or m.centre or m.arrangement or m.stacked)


def _row_width(asset: Asset, count: int, gap: float) -> float:
    """The room things said to stand between two others take beyond one gap: one with a gap, several side by side
    with the small gaps of such a row (the last gap is the caller's)."""
    if count == 1:
        return asset.size[1] + gap
    return count * asset.size[1] + count * BETWEEN_ROW_GAP + max(0.0, BETWEEN_ROW_GAP - gap)


def _beside_entries(oid: str, other: str, side: str, distance: float) -> list[Entry]:
    """`oid` on the support, `distance` to the `side` of `other` and lined up with it."""
    edge, align = _SIDES.get(side, _SIDES["beside"])
    return [
        [oid, PLACE_ON_BASE, "root", {}],
        [oid, edge, other, {"distance": distance}],
        [oid, align, other, {}],
    ]


def _grid_shape(n: int, hx: float, hy: float) -> tuple[int, int]:
    """The rows (front to back) and columns of the grid that spreads n anchors over the support."""
    cols = max(1, math.ceil(math.sqrt(n * hy / hx)))
    return math.ceil(n / cols), cols


def _grid_spots(n: int, hx: float, hy: float) -> list[Spot]:
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


def _standing(plan: Plan, oids: list[str]) -> str:
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


def _spot_of(plan: Plan, oid: str) -> Spot:
    """Where the program puts `oid` on the support (the middle when no entry gives x and y)."""
    for entry in plan.anchors:
        if entry[0] == oid and entry[1] == PLACE_ON_BASE and "x" in entry[3] and "y" in entry[3]:
            return float(entry[3]["x"]), float(entry[3]["y"])
    return 0.0, 0.0


def _taking_spots(rest: list[int], mentions: list[Mention], ids: Ids, office: set[int]) -> list[int]:
    """The anchors that take a grid spot of their own: not those already laid out, in the middle, at a place the
    words give, or beside another anchor (a stack of books with a mug next to it is one group, which stands where a
    lone group would, not in one cell of a grid of two)."""
    laid = set(ids) | set(rest)
    taking = []
    for k in rest:
        m = mentions[k]
        if k in ids or k in office or m.centre or (m.region and m.beside is None):
            continue
        if (m.beside is not None and m.beside in laid) or (m.around is not None and m.around in laid):
            continue
        taking.append(k)
    return taking


def _first_spot(m: Mention, ids: Ids, spots: Iterator[Spot]) -> Spot | None:
    """Where the first of mention m stands: the middle when centred, None when it goes beside something already
    placed, else the next grid spot (the grid has a spot for every anchor)."""
    if m.centre:
        return 0.0, 0.0
    if m.beside is not None and m.beside in ids:
        return None
    return next(spots)


def _targets_first(anchors: list[int], mentions: list[Mention]) -> list[int]:
    """The anchors ordered so that what one stands beside (in front of, around ...) is laid out before it."""
    ordered: list[int] = []

    def visit(k: int, depth: int) -> None:
        for target in (mentions[k].beside, mentions[k].around, mentions[k].second):
            if target is not None and target in anchors and target not in ordered and depth < len(anchors):
                visit(target, depth + 1)
        if k not in ordered:
            ordered.append(k)

    for k in anchors:
        visit(k, 0)
    return ordered


def _row_start(
    spot: Spot | None, extent: tuple[float, float, float, float], half: Half, margin: float = 0.0
) -> Spot | None:
    """The centre of the first (leftmost, back) object of rows centred on `spot`, kept on the support (and `margin`
    from its edges, where it has room)."""
    if spot is None:
        return None
    width, depth, item_width, item_depth = extent
    hx, hy = half
    x, y = spot
    left = min(y + width / 2, hy - margin) if width < 2 * hy else hy
    back = max(x - depth / 2, -hx + margin) if depth < 2 * hx else -hx
    if margin and width < 2 * hy:  # a group with a place of its own stays whole on the support, a margin in if it can
        left = max(left, -hy + width + (margin if width + 2 * margin < 2 * hy else 0.0))
    if margin and depth < 2 * hx:
        back = min(back, hx - depth - (margin if depth + 2 * margin < 2 * hx else 0.0))
    return back + item_depth / 2, left - item_width / 2
