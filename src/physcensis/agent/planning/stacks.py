"""Stacks: the asset at each level, and the PLACE-ON (or, nested, PLACE-IN) chain that writes one."""

from __future__ import annotations

import contextlib
from typing import Any

from physcensis.agent import choosing
from physcensis.agent.planning.entries import PLACE_ANYWHERE, PLACE_IN, PLACE_ON, Plan
from physcensis.agent.planning.state import PlanState, choice_key
from physcensis.agent.planning.variants import Variants, area
from physcensis.agent.reading import Mention, SceneRequest
from physcensis.assets.model import Asset

# Things a stack of which is one kind whatever the seed: a stack of plates is a set.
MATCHED = frozenset({"plate", "saucer", "dish", "bowl", "cup", "mug", "glass", "tray", "coaster", "napkin"})


class Stacks:
    """Chooses what each level of a stack is and writes the levels above its bottom object."""

    def __init__(self, state: PlanState, variants: Variants) -> None:
        self.state = state
        self.variants = variants

    def levels(self, m: Mention, request: SceneRequest, height: int, which: int = 0) -> list[Asset]:
        """The asset at each level of one of m's stacks, bottom first. One variant throughout canonically: flat on top,
        steady, the stack under the next shelf board (agent/choosing.py), lying flat; dishes, what nests and what
        things go in stack with their own kind. Other things that lie flat (books, gift boxes, towels) may mix, with
        variety or when the words ask for assorted ones, the largest at the bottom."""
        state, draws = self.state, self.state.draws
        assorted = self.variants.assorted(m)
        with state.canonically() if assorted else contextlib.nullcontext():  # the words choose: every kind there is
            flat = [a for a in self.variants.assets(m) if "upright" not in a.kind]
            variants = flat or self.variants.assets(m)  # stacks lie flat
        levels = max(m.sizes) if m.sizes else m.count
        choices = choosing.stack_choices(variants, levels, state.room)
        first = choices[0]
        if which:  # with variety, each further stack of one kind may be another set ("two stacks of saucers")
            first = draws.pick(first, choices, "stack kind", *choice_key(m), which)
        key = ("kinds", *choice_key(m), which)
        if _nested(m, request) or first.cavity is not None or m.category in MATCHED or not choosing.stacks_well(first):
            return [first] * height
        if not assorted and draws.canonical(*key):
            return [first] * height
        well = [a for a in variants if a is not first and choosing.stacks_well(a)]
        kinds = height if assorted else draws.count(1, 1, min(height, 1 + len(well)), *key)
        candidates = [first, *(well if assorted else draws.order(well, *key))]
        chosen = _nesting_footprints(candidates[:kinds])
        chains = _footprint_chains([first, *well], height) if assorted else []
        if chains and not draws.canonical(*key):  # different ones: the seed picks which
            chosen = draws.pick(chains[0], chains, *key)
        elif assorted and len(chosen) < height:  # different ones, those that stack best first
            chosen = _nesting_footprints(candidates)
            chosen += [a for a in candidates if a not in chosen][: height - len(chosen)]
        stack = sorted((chosen[n % len(chosen)] for n in range(height)), key=area, reverse=True)
        room = state.room
        if room is not None and room.height is not None and sum(a.size[2] for a in stack) >= room.height:
            return [first] * height
        return stack

    def stack_on(self, plan: Plan, base: str, m: Mention, levels: list[Asset], request: SceneRequest) -> list[str]:
        """The levels above `base`, the first of one of mention m's stacks, each resting on (or, nested, dropped into)
        the one below: bowls, colanders and paper cups nest in a stack of their own kind whatever the words."""
        draws = self.state.draws
        same = _nested(m, request) or self.state.role(m) in ("container", "carrier")  # stacks with its own kind
        nested = _nested(m, request) or (same and choosing.nests(levels[0]))
        previous, placed = base, []
        for below, asset in zip(levels, levels[1:], strict=False):
            oid = plan.new_id(m.category)
            placed.append(oid)
            messy = request.messy or m.arrangement == "pile"
            params: dict[str, Any] = {"messy": True} if messy else {"overlap": neat_overlap(asset, below)}
            if messy and draws.on:  # a messy pile: each a little off the one below, the seed says where
                x, y, _ = asset.size
                reach = draws.spread(0.1)
                params["x_offset"] = round(draws.uniform(0.0, -reach * x, reach * x, "pile x", oid), 3)
                params["y_offset"] = round(draws.uniform(0.0, -reach * y, reach * y, "pile y", oid), 3)
            if nested:  # "cups stacked inside one another": each dropped into the one below
                plan.physical += [[oid, asset.description], [[oid], PLACE_IN, previous, {}]]
            else:
                plan.physical += [[oid, asset.description], [oid, PLACE_ON, previous, params]]
            previous = oid
        plan.tops.add(previous)
        return placed

    def free_stack(self, plan: Plan, m: Mention) -> None:
        """m's objects as one stack placed anywhere: the first wherever there is room, each other on the one below."""
        previous, below = None, None
        for n in range(m.count):
            description, asset = self.variants.describe(m, n)
            oid = plan.new_id(m.category)
            plan.free.append([oid, description])
            if previous is None:
                plan.free.append([oid, PLACE_ANYWHERE, "root", {"stack": False}])
            else:
                plan.free.append([oid, PLACE_ON, previous, {"overlap": neat_overlap(asset, below or asset)}])
            previous, below = oid, asset
        if previous is not None:
            plan.tops.add(previous)

    def pile_is_free(self, m: Mention) -> bool:
        """A pile of things that do not stack (balls, apples) is scattered, allowed to rest on each other."""
        return m.arrangement == "pile" and self.variants.canonical_first(m).support_probability < 0.5


def neat_overlap(upper: Asset, lower: Asset) -> float:
    """The share of a neat stack's level that rests on the one below: all of it, or as much as the lower one's
    footprint allows. Asking less than all of a saucer for a saucer the same size pushes it off centre, and a stack
    of such offsets leans and creeps."""
    return round(min(1.0, area(lower) / max(area(upper), 1e-9)), 2)


def _nested(m: Mention, request: SceneRequest) -> bool:
    """Whether the words ask for m's stack nested ("cups stacked inside one another")."""
    return "inside" in request.tokens[m.end : m.end + 6] or "nested" in request.tokens


def _nesting_footprints(assets: list[Asset]) -> list[Asset]:
    """The largest of the assets and those of the others each of which lies about within the footprint of the one
    before (length and width both at most a tenth larger): in a stack of them, largest at the bottom, no level
    reaches far past the one under it (an atlas on a pocket book)."""
    chain: list[Asset] = []
    for asset in sorted(assets, key=area, reverse=True):
        if not chain or _within(asset, chain[-1]):
            chain.append(asset)
    return chain


def _footprint_chains(assets: list[Asset], length: int, most: int = 200) -> list[list[Asset]]:
    """Up to `most` sets of `length` different assets that stack as `_nesting_footprints` keeps them (largest at the
    bottom, each within a tenth of the one below), largest first."""
    ordered = sorted(dict.fromkeys(assets), key=area, reverse=True)
    chains: list[list[Asset]] = []

    def extend(chain: list[Asset], start: int) -> None:
        if len(chains) >= most:
            return
        if len(chain) == length:
            chains.append(list(chain))
            return
        for i in range(start, len(ordered)):
            if _within(ordered[i], chain[-1]):
                extend([*chain, ordered[i]], i + 1)

    for i in range(len(ordered)):
        extend([ordered[i]], i + 1)
    return chains


def _within(upper: Asset, lower: Asset) -> bool:
    return all(a <= 1.1 * b for a, b in zip(sorted(upper.size[:2]), sorted(lower.size[:2]), strict=True))
