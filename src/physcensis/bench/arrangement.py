"""The arrangement keys of a prompt's `expect` block, checked on the solved scene.

* `"inside": [[item, container, n]]` — at least n items rest in a container of that category: placed IN it (directly
  or on something placed in it), or with their base inside its cavity (within its opening and depth, in its frame).
* `"on": [[item, carrier, n]]` — at least n items rest on a carrier of that category: placed on or in it (a tray's
  rim makes it a cavity), or on a stack standing on it, or with their base over its footprint and above its base.
* `"stacks": {category: [h1, h2, ...]}` — separate stacks of that category at least h1, h2, ... high.
* `"rows": {category: [n1, n2, ...]}` — separate straight lines of at least n1, n2, ... objects of that category.
* `"evenly_spaced": [category, ...]` — the longest row of that category has equal gaps (centre to centre, within a
  quarter of their mean or 2 cm).
* `"around": [[item, centre, n]]` — at least n items near a centre object and on more than one side of it (no gap
  between their bearings as seen from it of half a turn or more).
* `"sides": [[subject, "left" | "right" | "front" | "behind", target]]` — some subject stands on that side of some
  target as the person looking at the default render sees it (viewpoint.py): its centre at least 1 cm that way, and
  more that way than across it.
* `"between": [[subject, a, b]]` — some subject stands between some a and some b: its centre projects onto the
  middle 80 % of the line joining their centres, less than half their distance away from that line.
* `"regions": [[subject, "corner" | "left" | "right" | "front" | "back" | "end" | "edge" ...]]` — some subject
  stands in that place on the support as the viewer sees it: for each side word its centre is on that side of the
  middle and its footprint reaches into that side's outer third of the support; "corner": a front or back side and a
  left or right one, each reaching into its outer half (side words say which); "end": a side of the longer axis;
  "edge": any side.
"""

from __future__ import annotations

import itertools
import math
from collections import defaultdict
from collections.abc import Callable
from typing import Any

import numpy as np
from shapely.geometry import Point, Polygon

from physcensis.assets.model import Asset
from physcensis.program.registry import PlacementKind, placement_spec
from physcensis.scene import PlacedObject, Scene
from physcensis.viewpoint import DIRECTION, stands_towards

EVEN_GAP_SPREAD = 0.25  # gaps of an evenly spaced row differ from their mean by at most this fraction of it ...
EVEN_GAP_SLACK_M = 0.02  # ... or by this much
ROW_TOLERANCE_M = 0.03  # an object's centre this close to the line (or a third of its width) is in the row
BETWEEN_SPAN = (0.1, 0.9)  # a thing is between two others when it projects onto this part of the line joining them
REGION_SIDE = 0.05  # a thing in a place on the support has its centre this far (in halves of it) to that side ...
REGION_OUTER_THIRD, REGION_OUTER_HALF = 1 / 3, 0.5  # ... and its footprint reaching into this outer part of it
AROUND_REACH = 4.0  # items count as around a centre within this many of its half-diagonals (at least 0.25 m)
AssetOf = Callable[[PlacedObject], Asset]


def check_arrangements(scene: Scene, expect: dict[str, Any], asset_of: AssetOf) -> list[str]:
    """What the scene misses of the arrangement keys of `expect` (empty when it meets them)."""
    placed = scene.placed
    links = _links(placed)
    return [
        *_missing_inside(placed, links, expect.get("inside", []), asset_of),
        *_missing_on(placed, links, expect.get("on", []), asset_of),
        *_short_stacks(placed, links, expect.get("stacks", {})),
        *_missing_rows(placed, expect.get("rows", {}), asset_of),
        *_uneven_rows(placed, expect.get("evenly_spaced", []), asset_of),
        *_missing_around(placed, expect.get("around", []), asset_of),
        *_missing_sides(placed, expect.get("sides", [])),
        *_missing_between(placed, expect.get("between", [])),
        *_missing_regions(scene, expect.get("regions", []), asset_of),
    ]


def _links(placed: list[PlacedObject]) -> dict[str, tuple[str, str]]:
    """Object id -> ("on" | "in", the id of the placed object it was put on or in)."""
    ids = {o.id for o in placed}
    names = {placement_spec(PlacementKind.ON).name: "on", placement_spec(PlacementKind.IN).name: "in"}
    return {
        o.id: (names[o.placement.predicate], o.placement.target)
        for o in placed
        if o.placement and o.placement.predicate in names and o.placement.target in ids
    }


def _below(object_id: str, links: dict[str, tuple[str, str]]) -> list[tuple[str, str]]:
    """The chain under an object: (relation, id) from the nearest down to the one standing on the support."""
    chain, seen = [], {object_id}
    while object_id in links and links[object_id][1] not in seen:
        relation, object_id = links[object_id]
        seen.add(object_id)
        chain.append((relation, object_id))
    return chain


def _missing_inside(
    placed: list[PlacedObject], links: dict[str, tuple[str, str]], wanted: list[list[Any]], asset_of: AssetOf
) -> list[str]:
    problems = []
    for item, container, need in wanted:
        holders = [o for o in placed if o.category == container]
        inside = [
            o
            for o in placed
            if o.category == item
            and any(_placed_in(o, h, links) or _base_in_cavity(o, h, asset_of(h)) for h in holders if h.id != o.id)
        ]
        if len(inside) < need:
            problems.append(f"{len(inside)} x {item} in a {container}, expected at least {need}")
    return problems


def _placed_in(item: PlacedObject, holder: PlacedObject, links: dict[str, tuple[str, str]]) -> bool:
    chain = _below(item.id, links)
    return any(relation == "in" and target == holder.id for relation, target in chain)


def _base_in_cavity(item: PlacedObject, holder: PlacedObject, asset: Asset) -> bool:
    """The item's base lies within the holder's footprint and below its rim, in the holder's frame."""
    if asset.cavity is None:
        return False
    local = _to_frame(holder, np.asarray(item.position))
    within = Polygon(asset.cavity.opening).contains(Point(local[0], local[1]))
    return bool(within and asset.cavity.floor_height - 0.01 <= local[2] <= asset.cavity.rim_height)


def _to_frame(holder: PlacedObject, point: np.ndarray) -> np.ndarray:
    w, x, y, z = holder.quaternion
    rotation = np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )
    return rotation.T @ (point - np.asarray(holder.position))


def _missing_on(
    placed: list[PlacedObject], links: dict[str, tuple[str, str]], wanted: list[list[Any]], asset_of: AssetOf
) -> list[str]:
    problems = []
    for item, carrier, need in wanted:
        carriers = [o for o in placed if o.category == carrier]
        count = sum(
            o.category == item and any(_carried(o, c, links, asset_of(c)) for c in carriers if c.id != o.id)
            for o in placed
        )
        if count < need:
            problems.append(f"{count} x {item} on a {carrier}, expected at least {need}")
    return problems


def _carried(item: PlacedObject, carrier: PlacedObject, links: dict[str, tuple[str, str]], asset: Asset) -> bool:
    """Placed on (or into: a tray's rim makes it a cavity) the carrier or a stack on it, or resting on its top."""
    if any(target == carrier.id for _, target in _below(item.id, links)):
        return True
    local = _to_frame(carrier, np.asarray(item.position))
    height = asset.size[2]
    above_its_base = min(0.5 * height, 0.003) <= local[2] <= height + 0.01  # not beside it on the support
    return bool(above_its_base and Polygon(asset.footprint()).contains(Point(local[0], local[1])))


def _short_stacks(
    placed: list[PlacedObject], links: dict[str, tuple[str, str]], wanted: dict[str, list[int]]
) -> list[str]:
    problems = []
    for category, heights in wanted.items():
        found = sorted(_stack_heights(placed, links, category), reverse=True)
        need = sorted(heights, reverse=True)
        if len(found) < len(need) or any(h < n for h, n in zip(found, need, strict=False)):
            problems.append(f"stacks of {category} {found or [0]} high, expected {need}")
    return problems


def _stack_heights(placed: list[PlacedObject], links: dict[str, tuple[str, str]], category: str) -> list[int]:
    """The height of each separate stack of `category` (objects of it placed ON one another, or nested IN one
    another: a stack of bowls), by its bottom."""
    category_of = {o.id: o.category for o in placed}
    tallest: dict[str, int] = defaultdict(int)
    for o in placed:
        if o.category != category:
            continue
        height, bottom = 1, o.id
        for _relation, target in _below(o.id, links):
            if category_of[target] != category:
                break
            height, bottom = height + 1, target
        tallest[bottom] = max(tallest[bottom], height)
    return list(tallest.values())


def _missing_rows(placed: list[PlacedObject], wanted: dict[str, list[int]], asset_of: AssetOf) -> list[str]:
    problems = []
    for category, lengths in wanted.items():
        members = [o for o in placed if o.category == category]
        found = _rows(members, asset_of)
        need = sorted(lengths, reverse=True)
        if len(found) < len(need) or any(f < n for f, n in zip(found, need, strict=False)):
            problems.append(f"rows of {category} {found or [0]} long, expected {need}")
    return problems


def _rows(members: list[PlacedObject], asset_of: AssetOf) -> list[int]:
    """Lengths of separate straight lines among the objects (largest first, greedily), lines of two or more."""
    left = list(members)
    lengths = []
    while len(left) >= 2:
        row = _longest_row(left, asset_of)
        if len(row) < 2:
            break
        lengths.append(len(row))
        left = [o for o in left if o.id not in row]
    return lengths


def _uneven_rows(placed: list[PlacedObject], categories: list[str], asset_of: AssetOf) -> list[str]:
    problems = []
    for category in categories:
        members = [o for o in placed if o.category == category]
        row = [o for o in members if o.id in _longest_row(members, asset_of)]
        gaps = _gaps(row)
        if len(row) < 3:
            problems.append(f"no row of three or more {category} to space evenly")
        elif max(abs(g - float(np.mean(gaps))) for g in gaps) > max(
            EVEN_GAP_SPREAD * float(np.mean(gaps)), EVEN_GAP_SLACK_M
        ):
            problems.append(f"{category} not evenly spaced (gaps {[round(g, 3) for g in gaps]} m)")
    return problems


def _gaps(row: list[PlacedObject]) -> list[float]:
    """Centre-to-centre distances between neighbours along the row's main direction."""
    if len(row) < 2:
        return []
    points = np.asarray([o.position[:2] for o in row])
    centred = points - points.mean(axis=0)
    direction = np.linalg.svd(centred, full_matrices=False)[2][0]
    along = np.sort(centred @ direction)
    return [float(g) for g in np.diff(along)]


def _longest_row(members: list[PlacedObject], asset_of: AssetOf) -> set[str]:
    points = {o.id: np.asarray(o.position[:2]) for o in members}
    tolerance = {o.id: max(ROW_TOLERANCE_M, min(asset_of(o).size[:2]) / 3) for o in members}
    best: set[str] = set()
    for a, b in itertools.combinations(members, 2):
        direction = points[b.id] - points[a.id]
        length = float(np.linalg.norm(direction))
        if length < 1e-6:
            continue
        normal = np.array([-direction[1], direction[0]]) / length
        row = {o.id for o in members if abs(float(normal @ (points[o.id] - points[a.id]))) <= tolerance[o.id]}
        if len(row) > len(best):
            best = row
    return best


def _missing_around(placed: list[PlacedObject], wanted: list[list[Any]], asset_of: AssetOf) -> list[str]:
    problems = []
    for item, centre, need in wanted:
        items = [o for o in placed if o.category == item]
        best = max((_around_count(c, items, asset_of) for c in placed if c.category == centre), default=0)
        if best < need:
            problems.append(f"{best} x {item} around a {centre}, expected at least {need}")
    return problems


def _around_count(centre: PlacedObject, items: list[PlacedObject], asset_of: AssetOf) -> int:
    """How many items are near the centre object, when they surround it (0 when they are all to one side)."""
    reach = max(0.25, AROUND_REACH * float(np.hypot(*asset_of(centre).size[:2])) / 2)
    origin = np.asarray(centre.position[:2])
    offsets = [np.asarray(o.position[:2]) - origin for o in items if o.id != centre.id]
    near = [v for v in offsets if 1e-6 < float(np.linalg.norm(v)) <= reach]
    if len(near) < 2:
        return len(near)
    bearings = sorted(math.atan2(v[1], v[0]) for v in near)
    gaps = [b - a for a, b in itertools.pairwise(bearings)] + [bearings[0] + 2 * math.pi - bearings[-1]]
    return len(near) if max(gaps) < math.pi else 0


def _missing_sides(placed: list[PlacedObject], wanted: list[list[str]]) -> list[str]:
    problems = []
    for subject, word, target in wanted:
        pairs = ((s, t) for s in _of(placed, subject) for t in _of(placed, target) if s.id != t.id)
        if not any(stands_towards(s.position, t.position, word) for s, t in pairs):
            problems.append(f"no {subject} {_side_phrase(word)} a {target} (as the viewer sees it)")
    return problems


def _side_phrase(word: str) -> str:
    return {"front": "in front of", "behind": "behind"}.get(word, f"to the {word} of")


def _missing_between(placed: list[PlacedObject], wanted: list[list[str]]) -> list[str]:
    problems = []
    for subject, first, second in wanted:
        pairs = [(a, b) for a in _of(placed, first) for b in _of(placed, second) if a.id != b.id]
        if not any(
            _stands_between(s, a, b) for s in _of(placed, subject) for a, b in pairs if s.id not in (a.id, b.id)
        ):
            problems.append(f"no {subject} between a {first} and a {second}")
    return problems


def _stands_between(subject: PlacedObject, a: PlacedObject, b: PlacedObject) -> bool:
    start, end, point = (np.asarray(o.position[:2]) for o in (a, b, subject))
    line = end - start
    length = float(np.linalg.norm(line))
    if length < 1e-6:
        return False
    share = float((point - start) @ line) / length**2
    off = abs(float(line[0] * (point - start)[1] - line[1] * (point - start)[0])) / length
    return BETWEEN_SPAN[0] <= share <= BETWEEN_SPAN[1] and off < length / 2


def _of(placed: list[PlacedObject], category: str) -> list[PlacedObject]:
    return [o for o in placed if o.category == category]


def _missing_regions(scene: Scene, wanted: list[list[str]], asset_of: AssetOf) -> list[str]:
    half = (scene.support.size[0] / 2, scene.support.size[1] / 2)
    return [
        f"no {subject} {' '.join(words)} on the support (as the viewer sees it)"
        for subject, *words in wanted
        if not any(_in_region(o, asset_of(o), half, set(words)) for o in _of(scene.placed, subject))
    ]


def _in_region(o: PlacedObject, asset: Asset, half: tuple[float, float], words: set[str]) -> bool:
    """Whether an object stands in the place on the support that the words name, as the viewer sees it: on that side
    of the middle, its footprint reaching into the outer part of the support on that side."""
    yaw = 2 * math.atan2(o.quaternion[3], o.quaternion[0])  # about the vertical: what a resting object turns by
    c, s = abs(math.cos(yaw)), abs(math.sin(yaw))
    extent = (c * asset.size[0] / 2 + s * asset.size[1] / 2, s * asset.size[0] / 2 + c * asset.size[1] / 2)
    outer = REGION_OUTER_HALF if "corner" in words else REGION_OUTER_THIRD

    def reaches(word: str) -> bool:
        axis = 0 if word in ("front", "behind") else 1
        along = float(np.dot(o.position[:2], DIRECTION[word])) / half[axis]
        return along >= REGION_SIDE and along + extent[axis] / half[axis] >= 1 - outer

    said = ["behind" if w == "back" else w for w in words if w in ("front", "back", "left", "right")]
    if not all(reaches(w) for w in said):
        return False
    depth, across = ["front", "behind"], ["left", "right"]
    if "corner" in words:
        return any(map(reaches, depth)) and any(map(reaches, across))
    if "end" in words:
        return any(map(reaches, across if half[1] >= half[0] else depth))
    if "edge" in words:
        return any(map(reaches, depth + across))
    return True
