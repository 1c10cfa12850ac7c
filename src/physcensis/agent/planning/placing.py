"""What the layout leaves: things placed by the physical solver, on a carrier (PLACE-ON), in a container (PLACE-IN)
or anywhere there is room (PLACE-ANYWHERE)."""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import numpy as np

from physcensis.agent import choosing
from physcensis.agent.planning.entries import FACING_FRONT, PLACE_ANYWHERE, PLACE_IN, PLACE_ON, Plan
from physcensis.agent.planning.stacks import Stacks
from physcensis.agent.planning.state import Ids, PlanState, choice_key, rings_on
from physcensis.agent.planning.variants import Variants
from physcensis.agent.reading import Mention, SceneRequest
from physcensis.assets.model import Asset
from physcensis.viewpoint import DIRECTION

# Drawn contents of a container must fill it with at least this share of what the smallest variants would make.
FULL_SHARE = 0.75
SIDE_GAP_M = 0.02  # between two things said to stand side by side on one carrier


class Placing:
    """Writes the physical placements of a plan's mentions that stand nowhere in particular."""

    def __init__(self, state: PlanState, variants: Variants, stacks: Stacks) -> None:
        self.state = state
        self.variants = variants
        self.stacks = stacks

    def place_the_rest(
        self, plan: Plan, mentions: list[Mention], consumed: set[int], ids: Ids, request: SceneRequest
    ) -> None:
        """What the layout left: free-standing mentions anywhere, then what rests on others, then the contents
        of containers."""
        held = {j for m in mentions for j in m.contents}
        for k, m in enumerate(mentions):
            if k not in consumed and k not in ids and m.on is None and k not in held and not rings_on(m, mentions):
                self.free(plan, k, m, ids, request)
        resting = [k for k, m in enumerate(mentions) if k not in consumed and m.on is not None]
        for k in _carriers_first(resting, mentions):
            if k not in ids:
                self._on(plan, k, mentions[k], ids, request)
        self._sides_on_carriers(plan, mentions, ids)
        for k, m in enumerate(mentions):
            if k not in consumed and k not in ids and rings_on(m, mentions):
                self._ring_on(plan, k, m, mentions, ids, request)
        for k, m in enumerate(mentions):
            if k not in consumed and m.contents and k in ids:
                self._fill(plan, k, m, mentions, ids, request)

    def free(self, plan: Plan, k: int, m: Mention, ids: Ids, request: SceneRequest) -> None:
        """Mention k's objects anywhere there is room (scattered, resting on each other, when messy)."""
        ids[k] = []
        for n in range(m.count):
            description, asset = self.variants.describe(m, n)
            oid = plan.new_id(m.category)
            ids[k].append(oid)
            messy = request.messy or request.dense or m.arrangement in ("pile", "scatter")
            params: dict[str, Any] = {"messy": True, "stack": True} if messy else {"stack": False}
            plan.free += [[oid, description], [oid, PLACE_ANYWHERE, "root", params]]
            if asset.has_front and not messy:  # a photo frame, a clock, a radio: its face to the viewer, not the wall
                plan.free.append([oid, FACING_FRONT, "root", {}])

    def add_free(self, plan: Plan, name: str, request: SceneRequest) -> str:
        """One thing the prompt did not name, placed anywhere; its id."""
        m = Mention(self.state.category(name), 1, name, (), 0, 0, False, False)
        ids: Ids = {}
        self.free(plan, 0, m, ids, request)
        return ids[0][0]

    def _on(self, plan: Plan, k: int, m: Mention, ids: Ids, request: SceneRequest) -> None:
        target = m.on
        assert target is not None
        carriers = ids.get(target)
        if not carriers:
            self.free(plan, k, m, ids, request)
            return
        ids[k] = []
        before = _taken_before(self.state.mentions, k)
        carriers = [c for c in carriers if c in plan.tops] or carriers  # on a stack: on its top
        if m.stacked and m.per is None and not self.stacks.pile_is_free(m):
            self._stacks_on(plan, k, m, carriers[-1], ids, request)
            return
        for n in range(m.count):
            description, _ = self.variants.describe(m, n)
            oid = plan.new_id(m.category)
            ids[k].append(oid)
            carrier = carriers[(before + n) % len(carriers)] if m.per is not None else carriers[-1]
            params: dict[str, Any] = {}
            if request.fragile:
                params = {"overlap": 0.5, "stability": "unstable"}
            elif request.stable:
                params = {"stability": "stable"}
            elif request.messy:
                params = {"messy": True}
            params |= self._on_a_side(m, target)
            plan.physical += [[oid, description], [oid, PLACE_ON, carrier, params]]
            if m.category in ("cup", "mug", "teapot", "pitcher"):
                plan.physical.append([oid, FACING_FRONT, "root", {}])

    def _on_a_side(self, m: Mention, carrier: int) -> dict[str, float]:
        """ "a tray with two glasses on the left and a bottle on the right": the offset, from the carrier's middle, of
        a quarter of its extent towards that side as the viewer sees it (none when no side was said)."""
        if m.on_side not in DIRECTION:
            return {}
        direction = np.asarray(DIRECTION[m.on_side])
        reach = self.variants.assets(self.state.mentions[carrier])[0].size[0 if direction[0] else 1] / 4
        return _offsets(direction * reach)

    def _sides_on_carriers(self, plan: Plan, mentions: list[Mention], ids: Ids) -> None:
        for k, m in enumerate(mentions):
            if m.on is not None and m.beside is not None and mentions[m.beside].on == m.on:
                self._side_by_side_on(plan, k, m, ids)

    def _side_by_side_on(self, plan: Plan, k: int, m: Mention, ids: Ids) -> None:
        """Mention m and the thing it is said to stand beside (left of, in front of ...), both on one carrier ("a
        tray with a bowl and a spoon to the right of the bowl"): each asks for an offset from the carrier's middle
        along that side, as the viewer sees it, the pair centred with a gap between; when the pair does not fit
        along the carrier, both go where there is room on it."""
        assert m.beside is not None and m.on is not None
        target = self.state.mentions[m.beside]
        if not ids.get(m.beside) or not ids.get(m.on) or not ids.get(k):
            return
        side = m.side
        if side == "beside":
            side = self.state.draws.pick("right", ["right", "left"], "side", *choice_key(m))
        direction = np.asarray(DIRECTION[side])
        axis = 0 if direction[0] else 1
        assets = self.variants.assets
        mine, theirs = min(assets(m)[0].size[:2]), assets(target)[0].size[axis]  # it may turn to lie along the side
        carrier = assets(self.state.mentions[m.on])[0].size[axis]
        if mine + theirs + SIDE_GAP_M > carrier:
            return
        own = direction * (theirs + SIDE_GAP_M) / 2
        other = -direction * (mine + SIDE_GAP_M) / 2
        for oids, offset in ((ids[k], own), (ids[m.beside], other)):
            for entry in plan.physical:
                if len(entry) == 4 and entry[0] in oids and entry[1] == PLACE_ON and entry[2] in ids[m.on]:
                    entry[3] = {**entry[3], **_offsets(offset)}

    def _stacks_on(self, plan: Plan, k: int, m: Mention, carrier: str, ids: Ids, request: SceneRequest) -> None:
        """ "a stack of plates on a tray": each stack's bottom on the carrier, the others each on the one below."""
        for which, height in enumerate(list(m.sizes) or [m.count]):
            levels = self.stacks.levels(m, request, height, which)
            base = plan.new_id(m.category)
            plan.physical += [[base, levels[0].description], [base, PLACE_ON, carrier, {}]]
            ids[k] += [base, *self.stacks.stack_on(plan, base, m, levels, request)]

    def _ring_on(
        self, plan: Plan, k: int, m: Mention, mentions: list[Mention], ids: Ids, request: SceneRequest
    ) -> None:
        """Mention k's objects around a centre piece that stands on a carrier ("toy cars around a tower of blocks on
        the rug", "cups around the teapot on the tray"): on the same carrier, evenly around the middle, where the
        piece stands."""
        assert m.around is not None
        centre = mentions[m.around]
        carriers = ids.get(centre.on) if centre.on is not None else None
        if not carriers:
            self.free(plan, k, m, ids, request)
            return
        assets = self.variants.assets
        radius = 0.5 * max(assets(centre)[0].size[:2]) + 0.5 * max(assets(m)[0].size[:2]) + 0.03
        ids[k] = []
        turn = self.state.ring_turn(m)
        for n in range(m.count):
            angle = 2 * math.pi * n / m.count + turn
            description, _ = self.variants.describe(m, n)
            oid = plan.new_id(m.category)
            ids[k].append(oid)
            offsets = {"x_offset": round(radius * math.cos(angle), 3), "y_offset": round(radius * math.sin(angle), 3)}
            plan.physical += [[oid, description], [oid, PLACE_ON, carriers[-1], offsets]]

    def _fill(self, plan: Plan, k: int, m: Mention, mentions: list[Mention], ids: Ids, request: SceneRequest) -> None:
        """Drop mention k's contents into its (first) container; "each holding" spreads them over all of them. What
        does not fit through the opening is placed anywhere instead. A container none of whose variants is open
        (no cavity) gets its contents beside it on the support, and the user is told so."""
        container = self.variants.assets(m)[0]  # the variant that holds them, an open one when there is
        into: dict[str, list[str]] = {}
        for j in m.contents:
            item = mentions[j]
            if item.on is not None:
                continue
            variants = self.variants.assets(item)
            if container.cavity is None:
                self._note_not_held(m, item)
            if not choosing.passes_opening(variants[0], container):
                self.free(plan, j, item, ids, request)
                continue
            one_set_each = item.per == k and not item.plural  # "two bowls, each holding a lemon": one in each
            count = item.count if one_set_each else self._contents_count(item, container, variants, len(m.contents))
            before = _taken_before(self.state.mentions, j)
            ids[j] = []
            for n in range(count):
                description, _ = self.variants.describe(item, n)
                oid = plan.new_id(item.category)
                ids[j].append(oid)
                plan.physical.append([oid, description])
                target = ids[k][(before + n) % len(ids[k])] if item.per == k else ids[k][0]
                into.setdefault(target, []).append(oid)
        for target, items in into.items():
            plan.physical.append([items, PLACE_IN, target, {}])

    def _contents_count(self, item: Mention, container: Asset, variants: list[Asset], kinds: int) -> int:
        """How many of `item` go into the container: as said, else as many as fit (at most 8, one of a singular). When
        the drawn variants would fill it with much fewer than the smallest would, the item's variants are fixed
        canonical (a bowl full of apples is not three large apples)."""
        state = self.state
        room = max(1, _capacity(container, variants, kinds))
        if item.plural and not item.explicit_count and not state.draws.canonical("contents", *choice_key(item)):
            smallest_first = sorted(variants, key=lambda a: float(np.prod(a.size)))
            if room < FULL_SHARE * _capacity(container, smallest_first, kinds):  # the drawn ones fill it far sooner
                state.draws = replace(state.draws, fixed=state.draws.fixed | {choice_key(item)})
                variants = self.variants.assets(item)
                room = max(1, _capacity(container, variants, kinds))
        count = item.count if item.explicit_count else min(room, 8 if item.plural else 1)
        if item.plural and not item.explicit_count and state.draws.wide and not item.least:  # how full is open
            count = state.draws.count(count, min(max(2, math.ceil(0.5 * count)), count), count, *choice_key(item))
        return count

    def _note_not_held(self, container: Mention, item: Mention) -> None:
        """Tell the user that the item could not go in the container: the catalogue has no open one."""
        self.state.note(
            f"no {container.category} in the asset catalogue is open (none has a cavity to put things in): "
            f"the {item.category} (x{item.count}) placed beside it on the support, not in it"
        )


def _capacity(container: Asset, variants: list[Asset], kinds: int) -> int:
    """How many things, the variants in turn, fit in the container when `kinds` kinds of things share it (at most 8):
    long things standing by the opening's area, the rest by the cavity's volume."""
    return choosing.room_for_mixed(container, variants, 1 / max(1, kinds))


def _carriers_first(resting: list[int], mentions: list[Mention]) -> list[int]:
    """The mentions that rest on others, each after the one it rests on when that rests on another too ("a cup on
    a saucer on a tray": the saucer, then the cup); otherwise in the order said."""
    order: list[int] = []
    pending = list(resting)
    while pending:
        ready = [k for k in pending if mentions[k].on not in pending or mentions[k].on == k]
        if not ready:  # a cycle the words made: as said
            ready = pending[:1]
        order += ready
        pending = [k for k in pending if k not in ready]
    return order


def _taken_before(mentions: list[Mention], k: int) -> int:
    """How many of the targets mention k has one each of ("a mug, a glass and a cup, each on its own coaster") the
    mentions before it already took: k's things take the next ones."""
    m = mentions[k]
    if m.per is None or k > m.per:  # things named after their targets ("plates, each with a fork"): one on each
        return 0
    return sum(o.count for o in mentions[:k] if o.per == m.per)


def _offsets(offset: np.ndarray) -> dict[str, float]:
    """PLACE-ON's x and y offsets from the carrier's middle, to the millimetre."""
    return {"x_offset": round(float(offset[0]), 3), "y_offset": round(float(offset[1]), 3)}
