"""Variety of the scenes made from one prompt (one prompt, seeds 0..N-1, is a distribution of scenes).

Pure functions over `Scene` objects, grouped by the prompt and support each scene records:

* distinct scenes: two scenes are the same when they use the same multiset of assets and, their objects matched per
  asset (optimal matching on centre distances), stand less than 5 cm apart on average; distinct scenes are the groups
  of that relation (union-find), so jitter is not variety;
* distinct asset choices: how many different per-category multisets of asset ids the scenes chose;
* asset-choice entropy: per category, the Shannon entropy (bits) of the sorted asset ids each scene chose for it;
* mean layout distance: per pair of scenes, the mean xy distance of their objects matched per category (optimal
  matching; unmatched objects are ignored), averaged over pairs;
* coverage: per cell of the support, the share of scenes whose footprints (or centres) cover it;
* expectations met (when a check is given for the prompt) and scenes resting (settle distance within 3 mm).
"""

from __future__ import annotations

import math
import re
from collections import Counter, defaultdict
from collections.abc import Callable, Hashable, Iterable, Mapping, Sequence
from dataclasses import asdict, dataclass, field
from itertools import combinations
from typing import Any

import numpy as np
import shapely
from numpy.typing import NDArray
from scipy.optimize import linear_sum_assignment

from physcensis.scene import PlacedObject, Scene, Support

SAME_SCENE_M = 0.05  # objects matched by asset closer than this on average: the same scene, jittered
RESTING_M = 0.003  # a scene's settle distance within this: it rests
HEATMAP_CELLS = 100  # cells along the support's longer side
CENTRE_MARK_M = 0.01  # radius a centre covers when an object has no footprint

ExpectCheck = Callable[[Scene], Sequence[str]]  # what a scene misses of its prompt's expect block
AssetChoice = tuple[tuple[str, tuple[str, ...]], ...]  # (category, sorted asset ids) per category


@dataclass(frozen=True, order=True)
class PromptKey:
    """What a group of scenes was made from: the prompt text (None: solved from a program) and the support."""

    prompt: str | None
    support: str

    @property
    def label(self) -> str:
        return f"{self.prompt or '(no prompt)'} [{self.support}]"


@dataclass
class PromptDiversity:
    """The variety of one prompt's scenes; distances in metres, entropies in bits."""

    prompt: str | None
    support: str
    scenes: int
    distinct_scenes: int
    distinct_asset_choices: int
    entropy_bits: dict[str, float] = field(default_factory=dict)
    mean_layout_distance_m: float | None = None
    layout_pairs: int = 0
    resting: int = 0
    expectations_checked: bool = False
    expectations_met: int = 0

    @property
    def mean_entropy_bits(self) -> float | None:
        return sum(self.entropy_bits.values()) / len(self.entropy_bits) if self.entropy_bits else None

    @property
    def expectations_share(self) -> float | None:
        return self.expectations_met / self.scenes if self.expectations_checked and self.scenes else None

    @property
    def resting_share(self) -> float | None:
        return self.resting / self.scenes if self.scenes else None

    def to_dict(self) -> dict[str, Any]:
        return asdict(self) | {
            "mean_entropy_bits": self.mean_entropy_bits,
            "expectations_share": self.expectations_share,
            "resting_share": self.resting_share,
        }


# ---- grouping -------------------------------------------------------------------------------------------------------


def normalise_prompt(prompt: str) -> str:
    """A prompt as the expect blocks are looked up: case and runs of white space do not matter."""
    return " ".join(prompt.split()).lower()


def support_text(support: Support) -> str:
    height = "" if support.height is None else f"@{support.height:g}"
    return f"{support.kind}:{support.size[0]:g}x{support.size[1]:g}{height}"


def prompt_key(scene: Scene) -> PromptKey:
    prompt = " ".join(scene.prompt.split()) if scene.prompt else None
    return PromptKey(prompt, support_text(scene.support))


def group_by_prompt(scenes: Sequence[Scene]) -> dict[PromptKey, list[int]]:
    """The indices of the scenes of each (prompt, support), in the order of `scenes`; keys sorted."""
    groups: dict[PromptKey, list[int]] = defaultdict(list)
    for index, scene in enumerate(scenes):
        groups[prompt_key(scene)].append(index)
    return {key: groups[key] for key in sorted(groups, key=lambda k: (k.prompt or "", k.support))}


# ---- distinct scenes ------------------------------------------------------------------------------------------------


def asset_multiset(scene: Scene) -> tuple[tuple[str, int], ...]:
    return tuple(sorted(Counter(o.asset for o in scene.placed).items()))


def asset_choice(scene: Scene) -> AssetChoice:
    """Per category, the sorted asset ids of its placed objects (so a different count is a different choice)."""
    by_category: dict[str, list[str]] = defaultdict(list)
    for obj in scene.placed:
        by_category[obj.category].append(obj.asset)
    return tuple(sorted((category, tuple(sorted(assets))) for category, assets in by_category.items()))


def matched_distance(a: Scene, b: Scene) -> float | None:
    """Mean centre distance of the objects of two scenes with the same assets, matched per asset id (optimal
    matching); None when their assets differ. Scenes without objects are 0 apart."""
    if asset_multiset(a) != asset_multiset(b):
        return None
    firsts, seconds = _centres_by(a.placed, _asset_of, 3), _centres_by(b.placed, _asset_of, 3)
    distances = [_matched(firsts[asset], seconds[asset]) for asset in firsts]
    flat = np.concatenate(distances) if distances else np.zeros(0)
    return float(flat.mean()) if flat.size else 0.0


def same_scene(a: Scene, b: Scene, threshold_m: float = SAME_SCENE_M) -> bool:
    distance = matched_distance(a, b)
    return distance is not None and distance < threshold_m


def distinct_scenes(scenes: Sequence[Scene], threshold_m: float = SAME_SCENE_M) -> int:
    """How many groups the "same scene" relation makes of the scenes (its transitive closure, by union-find)."""
    parent = list(range(len(scenes)))

    def root(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    by_assets: dict[tuple[tuple[str, int], ...], list[int]] = defaultdict(list)
    for index, scene in enumerate(scenes):
        by_assets[asset_multiset(scene)].append(index)
    for members in by_assets.values():  # only scenes with the same assets can be the same
        for i, j in combinations(members, 2):
            if root(i) != root(j) and same_scene(scenes[i], scenes[j], threshold_m):
                parent[root(i)] = root(j)
    return len({root(i) for i in range(len(scenes))})


def distinct_asset_choices(scenes: Iterable[Scene]) -> int:
    return len({asset_choice(scene) for scene in scenes})


# ---- entropy --------------------------------------------------------------------------------------------------------


def entropy_bits(choices: Iterable[Hashable]) -> float:
    """Shannon entropy (bits) of the observed choices: 0 when all agree, 1 for a 50/50 split of two."""
    counts = np.array(list(Counter(choices).values()), dtype=float)
    if counts.size < 2:
        return 0.0
    p = counts / counts.sum()
    return float(-(p * np.log2(p)).sum()) + 0.0  # + 0.0: no -0.0


def choice_entropy_bits(scenes: Sequence[Scene]) -> dict[str, float]:
    """Per category any of the scenes placed, the entropy of the sorted asset ids each scene chose for it (a scene
    without that category chose none, which counts as a choice)."""
    choices = [dict(asset_choice(scene)) for scene in scenes]
    categories = sorted({category for choice in choices for category in choice})
    return {category: entropy_bits(choice.get(category, ()) for choice in choices) for category in categories}


# ---- layout distance ------------------------------------------------------------------------------------------------


def layout_distance(a: Scene, b: Scene) -> float | None:
    """Mean xy distance of the objects of two scenes matched per category (optimal matching; what one scene has more
    of is ignored); None when no category has objects in both."""
    firsts, seconds = _centres_by(a.placed, _category_of, 2), _centres_by(b.placed, _category_of, 2)
    distances = [_matched(firsts[c], seconds[c]) for c in firsts.keys() & seconds.keys()]
    flat = np.concatenate(distances) if distances else np.zeros(0)
    return float(flat.mean()) if flat.size else None


def mean_layout_distance(scenes: Sequence[Scene]) -> tuple[float | None, int]:
    """The mean of `layout_distance` over the pairs of scenes that share a category, and how many pairs that is."""
    distances = [d for a, b in combinations(scenes, 2) if (d := layout_distance(a, b)) is not None]
    return (float(np.mean(distances)) if distances else None), len(distances)


def _asset_of(obj: PlacedObject) -> str:
    return obj.asset


def _category_of(obj: PlacedObject) -> str:
    return obj.category


def _centres_by(
    objects: Iterable[PlacedObject], key: Callable[[PlacedObject], str], dims: int
) -> dict[str, NDArray[np.float64]]:
    grouped: dict[str, list[tuple[float, ...]]] = defaultdict(list)
    for obj in objects:
        grouped[key(obj)].append(tuple(obj.position[:dims]))
    return {name: np.array(points, dtype=float) for name, points in grouped.items()}


def _matched(first: NDArray[np.float64], second: NDArray[np.float64]) -> NDArray[np.float64]:
    """Distances of the pairs of an optimal matching of two point sets (as many pairs as the smaller set holds)."""
    cost = np.linalg.norm(first[:, None, :] - second[None, :, :], axis=-1)
    rows, cols = linear_sum_assignment(cost)
    return np.asarray(cost[rows, cols], dtype=float)


# ---- resting, expectations, the whole summary -----------------------------------------------------------------------


def is_resting(scene: Scene, limit_m: float = RESTING_M) -> bool:
    """Whether the scene's recorded settle distance is within `limit_m` (a scene that records none does not rest)."""
    distance = scene.metrics.get("settle_distance_m")
    if not isinstance(distance, int | float) or isinstance(distance, bool):
        return False
    return math.isfinite(distance) and distance <= limit_m


def prompt_diversity(scenes: Sequence[Scene], check: ExpectCheck | None = None) -> PromptDiversity:
    """The variety of scenes made from one prompt (and support), with the share meeting `check` if given."""
    if not scenes:
        raise ValueError("prompt_diversity needs at least one scene")
    key = prompt_key(scenes[0])
    layout, pairs = mean_layout_distance(scenes)
    return PromptDiversity(
        prompt=key.prompt,
        support=key.support,
        scenes=len(scenes),
        distinct_scenes=distinct_scenes(scenes),
        distinct_asset_choices=distinct_asset_choices(scenes),
        entropy_bits=choice_entropy_bits(scenes),
        mean_layout_distance_m=layout,
        layout_pairs=pairs,
        resting=sum(is_resting(s) for s in scenes),
        expectations_checked=check is not None,
        expectations_met=0 if check is None else sum(not check(s) for s in scenes),
    )


def diversity_by_prompt(
    scenes: Sequence[Scene], checks: Mapping[str, ExpectCheck] | None = None
) -> list[tuple[PromptDiversity, list[int]]]:
    """`prompt_diversity` of every (prompt, support) group, with the indices of its scenes. `checks` maps a
    `normalise_prompt`d prompt to the check of its expect block."""
    checks = checks or {}
    results = []
    for key, members in group_by_prompt(scenes).items():
        check = checks.get(normalise_prompt(key.prompt)) if key.prompt else None
        results.append((prompt_diversity([scenes[i] for i in members], check), members))
    return results


# ---- coverage -------------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class CoverageGrid:
    """share[i, j]: the share of scenes covering the cell at x = xs[i], y = ys[j] (cell centres, metres)."""

    xs: NDArray[np.float64]
    ys: NDArray[np.float64]
    share: NDArray[np.float64]


def coverage_grid(
    support: Support, prints: Sequence[Sequence[shapely.Geometry]], cells: int = HEATMAP_CELLS
) -> CoverageGrid:
    """Per cell of the support's top, the share of scenes (one sequence of footprints each) that cover its centre."""
    hx, hy = support.half_extents
    cell = 2.0 * max(hx, hy) / cells
    xs = _cell_centres(hx, cell)
    ys = _cell_centres(hy, cell)
    gx, gy = np.meshgrid(xs, ys, indexing="ij")
    covered = np.zeros(gx.shape, dtype=float)
    for scene_prints in prints:
        if scene_prints:
            covered += shapely.contains_xy(shapely.union_all(list(scene_prints)), gx, gy)
    share = covered / len(prints) if prints else covered
    return CoverageGrid(xs, ys, share)


def centre_marks(scene: Scene, radius_m: float = CENTRE_MARK_M) -> list[shapely.Geometry]:
    """Small discs at the objects' centres: the coverage of a scene whose footprints are not known."""
    return [shapely.Point(o.position[0], o.position[1]).buffer(radius_m) for o in scene.placed]


def _cell_centres(half: float, cell: float) -> NDArray[np.float64]:
    count = max(1, round(2.0 * half / cell))
    return np.asarray(-half + (np.arange(count) + 0.5) * (2.0 * half / count), dtype=float)


def file_stem(key: PromptKey, index: int) -> str:
    """A file name for one prompt's outputs: its number and the first words of the prompt."""
    words = re.findall(r"[a-z0-9]+", (key.prompt or "no prompt").lower())[:6]
    return f"{index:03d}-" + "-".join(words or ["prompt"])
