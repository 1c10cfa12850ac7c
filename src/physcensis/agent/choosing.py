"""Which catalogue variant the offline planner uses for a mention: the one the words ask for, that fits where it goes.

Pure functions over `Asset`s and sizes. The planner lists a mention's variants (`Catalogue.variants`) and narrows
them here: to those its words name (colours, materials, "standing", "single", "small" ...), to those whose footprint
fits the support (a quarter turn allowed, under the clearance), to one flat-topped, stable variant for every level of
a stack, to a container whose cavity holds what is asked into it, and to contents that fit that container.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import shapely

from physcensis.agent.reading import singular
from physcensis.assets.model import Asset
from physcensis.solver.filling import cavity_capacity, item_volume

EDGE_MARGIN = 0.01  # metres a footprint keeps from each side of the support (the solver's grid rounds)
STANDING_PACKING = 0.5  # share of an opening long things standing side by side can fill
LONG_RATIO = 2.5  # longest side over the next one: a pen, a toothbrush, a straw
FLAT_TOP = 0.5  # share of the footprint a flat top covers (a cube, not a roof)
STABLE_RATIO = 2.0  # height over the narrower side of the footprint that still stacks
NEST_BASE = 0.1  # the base: the lowest tenth of the height
NEST_RATIO = 0.75  # a base this much narrower than the opening nests in another of its kind

SMALL_WORDS = frozenset({"small", "tiny", "little", "mini", "miniature", "compact", "short", "slim", "thin", "narrow"})
LARGE_WORDS = frozenset({"large", "big", "huge", "giant", "tall", "long", "wide", "thick", "oversized", "jumbo"})
MULTIPLE_WORDS = frozenset({"pack", "pair", "set", "bundle", "multipack", "double", "twin", "stack", "pile"})
NUMBER_WORDS = frozenset(
    {"two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve", "dozen", "several"}
)
# Words that say how things are arranged or related, not which variant they are.
NEUTRAL_WORDS = frozenset(
    {
        *"a an the of and or with on in to by at for its it is are some few many each one another other".split(),
        *"side row column line lined up evenly spaced neatly arranged placed sitting resting set next top".split(),
        *"stack stacked pile piled heap tower nested inside near beside behind front around under".split(),
        *"parked left right middle centre center couple bunch number lot".split(),
    }
)
BOUNDARIES = frozenset(
    {",", "and", "a", "an", "the", "with", "on", "in", "next", "beside", "behind", "near", "inside", "around", "under"}
)
WORDS_AFTER_NOUN = 4


@dataclass(frozen=True)
class Room:
    """Where objects stand: the support's depth (x, front to back) and width (y), and the clearance above it."""

    depth: float
    width: float
    height: float | None = None


# -- the words --------------------------------------------------------------------------------------------------------


def words_of(tokens: Sequence[str], start: int, end: int, phrase: str, adjectives: Sequence[str]) -> set[str]:
    """The words that describe a mention: its span (quantity, adjectives, noun), its phrase and adjectives, and the few
    words after the noun up to the next phrase ("standing side by side", "lying flat"), singular, without numbers and
    arrangement words."""
    words = [*adjectives, *phrase.split()]
    if end > start:
        words += tokens[start:end]
        for token in tokens[end : end + WORDS_AFTER_NOUN]:
            if token in BOUNDARIES or token.isdigit() or token in NUMBER_WORDS:
                break
            words.append(token)
    return {base_word(w) for w in words if w not in NEUTRAL_WORDS and w not in NUMBER_WORDS and not w.isdigit()} - {""}


def base_word(word: str) -> str:
    """A word as `words_of` gives it: lower case, singular."""
    return singular(word.lower().strip("'"))


def asset_words(asset: Asset) -> list[str]:
    """The singular words of an asset's description and kind."""
    return [base_word(w) for w in re.findall(r"[a-z]+", f"{asset.description} {asset.kind}".lower())]


def is_multiple(asset: Asset) -> bool:
    """A variant that is several things in one ("a pack of six rolls", "two rolls side by side")."""
    raw = re.findall(r"[a-z]+", asset.description.lower())
    if MULTIPLE_WORDS & set(raw):
        return True
    return any(w in NUMBER_WORDS and any(_plural(n) for n in raw[i + 1 : i + 4]) for i, w in enumerate(raw))


def _plural(word: str) -> bool:
    return len(word) > 3 and word.endswith("s") and not word.endswith("ss") and singular(word) != word


def word_score(asset: Asset, words: set[str]) -> int:
    """How many of the mention's words (sizes aside: `rank_by_words` compares sizes) the variant's description and
    kind name; a pack or a pair counts against a variant unless the words ask for one."""
    score = len((words - SMALL_WORDS - LARGE_WORDS) & set(asset_words(asset)))
    if is_multiple(asset) and not words & MULTIPLE_WORDS:
        score -= 2
    return score


def rank_by_words(variants: Sequence[Asset], words: set[str]) -> list[Asset]:
    """The variants that name most of the words (in catalogue order); "small" or "large" keeps the smaller or larger
    half of them by volume, that end first (so "a large blue bowl" is the largest blue bowl)."""
    if not variants:
        return []
    scores = [word_score(a, words) for a in variants]
    best = [a for a, s in zip(variants, scores, strict=True) if s == max(scores)]
    small, large = bool(words & SMALL_WORDS), bool(words & LARGE_WORDS)
    if small == large or len(best) == 1:
        return best
    ordered = sorted(best, key=lambda a: float(np.prod(a.size)) * (1 if small else -1))
    return ordered[: math.ceil(len(ordered) / 2)]


# -- the support ------------------------------------------------------------------------------------------------------


def fit_tier(asset: Asset, room: Room, along: int = 1, gap: float = 0.0) -> int:
    """0: the footprint fits the support as the asset stands (x in the depth), 1: it fits turned a quarter, 2: it does
    not fit. `along` objects side by side, `gap` apart, share the width. 3 more when it is taller than the clearance
    (the planner's clearance keeps a margin below the next shelf board)."""
    x, y = asset.size[0], asset.size[1]
    depth, width = room.depth - 2 * EDGE_MARGIN + 1e-9, room.width - 2 * EDGE_MARGIN + 1e-9
    gaps = gap * (along - 1)
    tier = 2
    if x <= depth and y * along + gaps <= width:
        tier = 0
    elif y <= depth and x * along + gaps <= width:
        tier = 1
    too_tall = room.height is not None and asset.size[2] >= room.height
    return tier + 3 if too_tall else tier


def fitting(variants: Sequence[Asset], room: Room, along: int = 1, gap: float = 0.0) -> list[Asset]:
    """The variants that fit the support, those that fit as they stand first (in their order); when none does, those
    whose footprint fits though they are taller than the clearance; else all of them, smallest footprint first."""
    tiers = [fit_tier(a, room, along, gap) for a in variants]
    for usable in ((0, 1), (3, 4)):
        fit = [a for tier in usable for a, t in zip(variants, tiers, strict=True) if t == tier]
        if fit:
            return fit
    return sorted(variants, key=lambda a: a.size[0] * a.size[1])


# -- stacks -----------------------------------------------------------------------------------------------------------

_TOP_SHARE: dict[str, float] = {}


def top_share(asset: Asset) -> float:
    """The share of the footprint that the asset's flat top covers (1 for a cube or a book, 0 for a roof, a ball or a
    cylinder on its side)."""
    if asset.id not in _TOP_SHARE:
        mesh = asset.visual
        z = np.asarray(mesh.vertices)[:, 2]
        tolerance = max(0.002, 0.02 * float(z.max() - z.min()))
        up = (mesh.face_normals[:, 2] > 0.95) & (mesh.triangles_center[:, 2] > z.max() - tolerance)
        hull = shapely.MultiPoint(np.asarray(mesh.vertices)[:, :2]).convex_hull.area
        _TOP_SHARE[asset.id] = min(1.0, float(mesh.area_faces[up].sum()) / max(hull, 1e-9))
    return _TOP_SHARE[asset.id]


def stacks_well(asset: Asset) -> bool:
    """Flat on top and not tall for its footprint, so the same asset rests steadily on it."""
    return top_share(asset) >= FLAT_TOP and asset.size[2] <= STABLE_RATIO * min(asset.size[0], asset.size[1])


def stack_choice(variants: Sequence[Asset], levels: int, room: Room | None = None) -> Asset:
    """The one variant every level of a stack uses: the first that stacks well and whose stack stays under the
    clearance; else the first that stacks well; else (dishes that nest, not flat on top) the first."""
    return stack_choices(variants, levels, room)[0]


def stack_choices(variants: Sequence[Asset], levels: int, room: Room | None = None) -> list[Asset]:
    """The variants a stack of `levels` may use throughout, best first (see `stack_choice`)."""
    well = [a for a in variants if stacks_well(a)]
    if room is not None and room.height is not None:
        under = [a for a in well if a.size[2] * levels < room.height]
        well = under or well
    return well or list(variants)


# -- containers and contents ------------------------------------------------------------------------------------------


def is_long(item: Asset, depth: float) -> bool:
    """A pen, a toothbrush, a straw: much longer than thick, and longer than the cavity is deep, so it stands in it."""
    short, middle, longest = sorted(item.size)
    return longest > LONG_RATIO * middle and longest > depth


def _opening(container: Asset) -> shapely.Polygon | None:
    return shapely.Polygon(container.cavity.opening) if container.cavity is not None else None


def passes_opening(item: Asset, container: Asset) -> bool:
    """The item's middle side goes through the widest circle in the opening."""
    opening = _opening(container)
    if opening is None:
        return False
    return sorted(item.size)[1] < 2 * opening.exterior.distance(opening.centroid)


def nests(asset: Asset) -> bool:
    """Whether one of this asset sits inside another like it (bowls, colanders, paper cups): its base is much narrower
    than its opening. Mugs, boxes and jars, as wide at the base as at the top, stack on one another instead."""
    opening = _opening(asset)
    if opening is None:
        return False
    vertices = np.asarray(asset.visual.vertices)
    base = vertices[vertices[:, 2] <= vertices[:, 2].min() + NEST_BASE * asset.size[2]]
    width = float((base[:, :2].max(axis=0) - base[:, :2].min(axis=0)).max())
    return width < NEST_RATIO * 2 * opening.exterior.distance(opening.centroid)


def capacity(container: Asset) -> float:
    """The volume dropped things can fill, m^3 (0 without a cavity), as the solver counts it."""
    return 0.0 if container.cavity is None else cavity_capacity(container.cavity)


def _needs(item: Asset, container: Asset) -> tuple[float, float]:
    """The volume one item takes in the cavity and the opening area it takes when it stands (0 for what lies)."""
    assert container.cavity is not None
    depth = container.cavity.depth
    if is_long(item, depth):  # it stands: its cross-section in the opening, the part below the rim in the cavity
        short, middle, _ = sorted(item.size)
        return item_volume(item, depth), short * middle / STANDING_PACKING
    return item_volume(item), 0.0


def room_for(container: Asset, item: Asset, share: float = 1.0) -> int:
    """How many of the item fit in `share` of the container: by the opening area for long things standing, by the
    volume for the rest; 0 when it does not pass the opening."""
    opening = _opening(container)
    if opening is None or not passes_opening(item, container):
        return 0
    volume, area = _needs(item, container)
    by_volume = share * capacity(container) / max(volume, 1e-9)
    by_area = share * opening.area / area if area > 0 else by_volume
    return int(min(by_volume, by_area))


def room_for_mixed(container: Asset, variants: Sequence[Asset], share: float = 1.0, most: int = 8) -> int:
    """How many things fit in `share` of the container when they are the variants in turn (the planner's variety:
    thing n is variant n mod len), at most `most`."""
    opening = _opening(container)
    if opening is None or not variants:
        return 0
    volume = area = 0.0
    for n in range(most):
        item = variants[n % len(variants)]
        item_volume, item_area = _needs(item, container)
        volume, area = volume + item_volume, area + item_area
        if not passes_opening(item, container) or volume > share * capacity(container) or area > share * opening.area:
            return n
    return most


def holds(container: Asset, items: Sequence[tuple[Asset, int]]) -> bool:
    """Whether the container's cavity takes all the items (item, count) at once."""
    opening = _opening(container)
    if opening is None or not all(passes_opening(item, container) for item, _ in items):
        return False
    needs = [(_needs(item, container), count) for item, count in items]
    volume = sum(v * count for (v, _), count in needs)
    area = sum(a * count for (_, a), count in needs)
    return volume <= capacity(container) and area <= opening.area


def containers_for(variants: Sequence[Asset], items: Sequence[tuple[Asset, int]]) -> list[Asset]:
    """The container variants that hold the items (in their order), then the others, roomiest first."""
    holding = [a for a in variants if holds(a, items)]
    rest = sorted((a for a in variants if a not in holding), key=lambda a: -capacity(a))
    return holding + rest


def typical(variants: Sequence[Asset]) -> Asset:
    """The variant of median volume: what a container is sized for, so that contents of several variants fit it."""
    ordered = sorted(variants, key=lambda a: float(np.prod(a.size)))
    return ordered[(len(ordered) - 1) // 2]


def contents_for(variants: Sequence[Asset], container: Asset, count: int, share: float = 1.0) -> list[Asset]:
    """The item variants `count` of which fit in `share` of the container, smallest first (so the first ones also fit
    when they are mixed); all of them, smallest first, when none does."""
    ordered = sorted(variants, key=lambda a: float(np.prod(a.size)))
    fit = [a for a in ordered if room_for(container, a, share) >= count]
    return fit or ordered
