"""A pick-and-place task in words, resolved against one scene: which object to pick, on or in which target.

Two forms are understood. The explicit one names ids: "pick cup_0 place-on plate_2", "pick cup_0 place-in bowl_0".
The relative one is ordinary English, as in the paper: "pick up the leftmost cup and place it on the rightmost plate",
"put the frontmost glass on the plate farthest from the robot". An object phrase is a category (or an id's noun, or a
catalogue synonym) with at most one superlative: leftmost / rightmost / frontmost / backmost as the person looking at
the default render sees them (viewpoint.py: the picture, the prompt and the task agree, wherever the robot stands),
nearest / farthest (horizontal distance from the robot's base), topmost / bottommost (the height of its base: "the top
book" of a stack); with no superlative the category must name exactly one object. Nothing in the text is ever
evaluated.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Literal

import numpy as np

from physcensis.assets.builtin import CATEGORY_DEFS
from physcensis.assets.text import plural
from physcensis.errors import PhyscensisError
from physcensis.physics.render import DEFAULT_VIEW, VIEWS
from physcensis.scene import PlacedObject, Scene
from physcensis.viewpoint import DIRECTION

Relation = Literal["on", "in"]
MAX_TASK_CHARS = 500
TIE_M = 0.005  # two objects closer than this along a superlative's direction are equally "leftmost"
MOUNT_CLEARANCE_M = 0.08  # the default mount: the base's axis this far beyond the support's edge

RELATION_WORDS: dict[str, Relation] = {
    "place-on": "on",
    "place-onto": "on",
    "on": "on",
    "onto": "on",
    "atop": "on",
    "upon": "on",
    "place-in": "in",
    "place-into": "in",
    "in": "in",
    "into": "in",
    "inside": "in",
    "within": "in",
}
SUPERLATIVES: dict[str, str] = {
    **dict.fromkeys(("leftmost", "left", "left-most", "left-hand"), "leftmost"),
    **dict.fromkeys(("rightmost", "right", "right-most", "right-hand"), "rightmost"),
    **dict.fromkeys(("frontmost", "front", "front-most", "foremost"), "frontmost"),
    **dict.fromkeys(("backmost", "back", "back-most", "rearmost", "rear", "hindmost"), "backmost"),
    **dict.fromkeys(("nearest", "closest"), "nearest"),
    **dict.fromkeys(("farthest", "furthest", "farthermost", "furthermost"), "farthest"),
    **dict.fromkeys(("topmost", "top", "uppermost", "upper", "highest"), "topmost"),
    **dict.fromkeys(("bottommost", "bottom", "lowermost", "lower", "lowest"), "bottommost"),
}
SUPERLATIVE_NAMES = ("leftmost", "rightmost", "frontmost", "backmost", "nearest", "farthest", "topmost", "bottommost")
# Words that carry no meaning for the resolution: verbs of the task, articles, and the robot as a reference point.
FILLER = frozenset(
    "pick picks up grab take put place set move lift get drop stack carry transfer and then it them please the a an "
    "one only single object item thing robot robot's base arm you me from to of away side hand most there".split()
)
# Everyday words for the same drinking vessels, beyond what the catalogue's synonyms already say.
EXTRA_SYNONYMS: dict[str, tuple[str, ...]] = {
    "mug": ("cup", "coffee cup", "tea cup", "teacup"),
    "cup": ("mug", "teacup", "tea cup", "coffee cup"),
    "glass": ("tumbler", "drinking glass"),
    "wine glass": ("glass",),
}
_SIDE_PHRASE = re.compile(
    r"\b(?:on|to|at|in|towards?)\s+(?:the\s+)?(?:(?:robot's|your|its)\s+)?(left|right|front|back|rear)"
    r"(?:[\s-]+hand)?(?:\s+side)?(?:\s+of\s+the\s+(?:table|robot|support))?"
    r"(?=\s*(?:$|[,;.]|\b(?:and|then|place|put|set|drop|on|onto|in|into|inside|atop)\b))",
    re.IGNORECASE,
)
_MULTIWORD = (
    (re.compile(r"\bon\s+top\s+of\b", re.IGNORECASE), " onto "),
    (re.compile(r"\binside\s+of\b", re.IGNORECASE), " inside "),
    (re.compile(r"\bin\s+to\b", re.IGNORECASE), " into "),
    (re.compile(r"\bplace[-_\s]+(on|onto|in|into)\b", re.IGNORECASE), r" place-\1 "),
)
_TOKEN = re.compile(r"[a-z0-9][a-z0-9_'\-]*", re.IGNORECASE)
_ID_LIKE = re.compile(r"^[a-z0-9]+(?:[_-][a-z0-9]+)*_\d")


class TaskError(PhyscensisError):
    """A task's words cannot be resolved to one object, one relation and one target in the scene."""


@dataclass(frozen=True)
class Task:
    """Pick `pick`, and put it `relation` (on top of / inside) `target`; `text` is what the task said."""

    pick: str
    relation: Relation
    target: str
    text: str

    @property
    def explicit(self) -> str:
        """The task in its explicit form: 'pick cup_0 place-on plate_2'."""
        return f"pick {self.pick} place-{self.relation} {self.target}"


@dataclass(frozen=True)
class _Frame:
    """The robot's horizontal frame: its base's xy and the direction it faces."""

    origin: np.ndarray
    forward: np.ndarray


def parse_task(text: str, scene: Scene, base_yaw: float, *, base_position: Sequence[float] | None = None) -> Task:
    """The task `text` resolved in `scene` for a robot facing `base_yaw` (its base at `base_position`; by default the
    middle of the support's edge behind it, where `Mount()` puts it). Raises TaskError naming what is wrong."""
    if not isinstance(text, str) or not text.strip():
        raise TaskError("the task is empty: say what to pick and where to put it, e.g. 'pick cup_0 place-on plate_0'")
    if len(text) > MAX_TASK_CHARS:
        raise TaskError(f"the task is {len(text)} characters long; at most {MAX_TASK_CHARS} are read")
    if not np.isfinite(base_yaw) or (base_position is not None and not np.all(np.isfinite(base_position))):
        raise TaskError(f"the robot's base pose is not finite (yaw {base_yaw!r}, position {base_position!r})")
    frame = _robot_frame(scene, base_yaw, base_position)
    pick_words, relation, target_words = _split(_tokens(text, {o.id for o in scene.objects}))
    pick = _resolve(pick_words, scene, frame, "to pick")
    target = _resolve(target_words, scene, frame, "to place it " + relation)
    if pick.id == target.id:
        raise TaskError(f"the object to pick and the target are the same ({pick.id}): name two different objects")
    return Task(pick=pick.id, relation=relation, target=target.id, text=" ".join(text.split()))


# -- words ----------------------------------------------------------------------------------------------------------


def _tokens(text: str, ids: set[str]) -> list[str]:
    """The words of the task, lower-cased except a scene's ids spelled exactly (ids may hold capitals)."""
    text = text.replace("\u2019", "'")
    for pattern, replacement in _MULTIWORD:
        text = pattern.sub(replacement, text)
    text = _SIDE_PHRASE.sub(lambda m: " " + m.group(1) + " ", text)
    words = [t.strip("'-") for t in _TOKEN.findall(text)]
    return [w if w in ids else w.lower() for w in words if w]


def _split(tokens: list[str]) -> tuple[list[str], Relation, list[str]]:
    """(words naming the object to pick, the relation, words naming the target)."""
    for i, token in enumerate(tokens):
        if token in RELATION_WORDS:
            pick, target = tokens[:i], tokens[i + 1 :]
            if not any(_meaningful(t) for t in pick):
                raise TaskError(f"no object named to pick before '{token}': say what to pick, e.g. 'pick cup_0 ...'")
            if not any(_meaningful(t) for t in target):
                raise TaskError(f"the task says '{token}' but names no target after it")
            return pick, RELATION_WORDS[token], target
    if not any(_meaningful(t) for t in tokens):
        raise TaskError("the task names no object: say what to pick, e.g. 'pick the leftmost cup, place on the plate'")
    raise TaskError(
        "no relation given: say where the object goes with 'on' or 'in' (e.g. '... place it on the plate', "
        "'pick cup_0 place-in bowl_0')"
    )


def _meaningful(token: str) -> bool:
    return token not in FILLER and token not in RELATION_WORDS


# -- objects --------------------------------------------------------------------------------------------------------


def _resolve(words: list[str], scene: Scene, frame: _Frame, role: str) -> PlacedObject:
    named = [w for w in words if _meaningful(w)]
    by_id = {o.id: o for o in scene.objects}
    superlatives = sorted({SUPERLATIVES[w] for w in named if w in SUPERLATIVES})
    ids = [w for w in named if _names_an_id(w, by_id, bool(superlatives))]
    if ids:
        return _by_id(ids, by_id, scene, role)
    nouns = [w for w in named if w not in SUPERLATIVES]
    if not nouns:
        raise TaskError(f"no object named {role}: give a category or an id ({_inventory(scene)})")
    if len(superlatives) > 1:
        raise TaskError(f"'{' '.join(nouns)}' {role}: use one of {', '.join(superlatives)}, not several")
    phrase, matches, others = _match_category(nouns, scene)
    placed = [o for o in matches if o.status == "placed"]
    if not placed:
        _unplaced_or_unknown(phrase, matches, scene)
    placed = _narrow_by_description(others, placed)
    if superlatives:
        return _extreme(placed, superlatives[0], frame, phrase)
    if len(placed) > 1:
        raise TaskError(
            f"{len(placed)} {plural(phrase)}: say which ({', '.join(SUPERLATIVE_NAMES)}) or give an id "
            f"({', '.join(o.id for o in placed)})"
        )
    return placed[0]


def _names_an_id(word: str, by_id: dict[str, PlacedObject], superlative: bool) -> bool:
    """An id-like word ('cup_0', 'Mug-A'), or a plain word that is an id ('mug') when no superlative asks to choose
    among a category ('the leftmost plate' with an object named 'plate')."""
    if _ID_LIKE.match(word):
        return True
    if word not in by_id:
        return False
    return not superlative or word != word.lower() or any(c in "_-0123456789" for c in word)


def _by_id(ids: list[str], by_id: dict[str, PlacedObject], scene: Scene, role: str) -> PlacedObject:
    if len(set(ids)) > 1:
        raise TaskError(f"several ids given {role} ({', '.join(ids)}): name one object")
    oid = ids[0]
    if oid not in by_id:
        raise TaskError(f"no '{oid}' in this scene; it has: {_inventory(scene)}")
    obj = by_id[oid]
    if obj.status != "placed":
        raise TaskError(f"{oid} was not placed in this scene ({obj.reason or 'it failed'}): pick another object")
    return obj


def _unplaced_or_unknown(phrase: str, matches: list[PlacedObject], scene: Scene) -> None:
    if matches:
        failed = ", ".join(f"{o.id} ({o.reason or 'failed'})" for o in matches)
        raise TaskError(f"no {phrase} was placed in this scene: {failed}")
    raise TaskError(f"no '{phrase}' in this scene; it has: {_inventory(scene)}")


def _inventory(scene: Scene) -> str:
    groups: dict[str, list[str]] = {}
    for obj in scene.placed:
        groups.setdefault(obj.category, []).append(obj.id)
    if not groups:
        return "no placed objects"
    parts = [f"{cat} ({', '.join(ids[:4])}{', ...' if len(ids) > 4 else ''})" for cat, ids in sorted(groups.items())]
    return "; ".join(parts)


def _singulars(word: str) -> set[str]:
    forms = {word}
    if word.endswith("ves"):
        forms |= {word[:-3] + "f", word[:-3] + "fe"}
    if word.endswith("ies"):
        forms.add(word[:-3] + "y")
    if word.endswith("es"):
        forms.add(word[:-2])
    if word.endswith("s") and not word.endswith("ss"):
        forms.add(word[:-1])
    return forms


def _phrase_forms(words: list[str]) -> set[str]:
    head = " ".join(words[:-1])
    return {(head + " " + last).strip() for last in _singulars(words[-1])}


def _id_noun(object_id: str) -> str:
    match = re.match(r"(.+?)_\d", object_id)
    return (match.group(1) if match else object_id).replace("_", " ")


@functools.cache
def _catalogue_names() -> dict[str, frozenset[str]]:
    """Every category's kinds and synonyms in the built-in catalogue."""
    names: dict[str, set[str]] = {}
    for definition in CATEGORY_DEFS:
        names.setdefault(definition.category, set()).update(n.lower() for n in (definition.kind, *definition.synonyms))
    return {category: frozenset(found) for category, found in names.items()}


def _exact_names(obj: PlacedObject) -> set[str]:
    return {obj.category.lower(), _id_noun(obj.id)}


def _loose_names(obj: PlacedObject) -> set[str]:
    names: set[str] = set()
    for name in _exact_names(obj):
        names.update(_catalogue_names().get(name, ()))
        names.update(EXTRA_SYNONYMS.get(name, ()))
        if " " in name:
            names.add(name.rsplit(" ", 1)[1])  # "glass" for a wine glass
    return names


def _windows(count: int) -> list[tuple[int, int]]:
    """(start, end) of every run of words, longest first; among equally long runs the last first (English puts the
    noun last: 'white coffee mug'), so 'cup' wins in 'cup table' only when 'cup table' and 'table' name nothing."""
    return [(start, start + length) for length in range(count, 0, -1) for start in range(count - length, -1, -1)]


def _match_category(nouns: list[str], scene: Scene) -> tuple[str, list[PlacedObject], list[str]]:
    """The longest run of the noun words that names some objects (exact names before synonyms), those objects, and the
    other words (adjectives to narrow them by)."""
    for start, end in _windows(len(nouns)):
        forms = _phrase_forms(nouns[start:end])
        for names in (_exact_names, _loose_names):
            found = [o for o in scene.objects if forms & names(o)]
            if found:
                return min(forms & names(found[0])), found, nouns[:start] + nouns[end:]
    return " ".join(nouns), [], []


def _narrow_by_description(words: list[str], objects: list[PlacedObject]) -> list[PlacedObject]:
    """The objects whose descriptions have the most of the other words given ('the red cup'), when any has one."""
    if not words:
        return objects

    def described(obj: PlacedObject) -> int:
        return sum(bool(re.search(rf"\b{re.escape(w)}\b", obj.description.lower())) for w in words)

    best = max(described(o) for o in objects)
    return [o for o in objects if described(o) == best] if best else objects


# -- the robot's point of view --------------------------------------------------------------------------------------


def _robot_frame(scene: Scene, base_yaw: float, base_position: Sequence[float] | None) -> _Frame:
    forward = np.array([np.cos(base_yaw), np.sin(base_yaw)])
    if base_position is None:
        half_x, half_y = scene.support.half_extents
        reach = abs(forward[0]) * half_x + abs(forward[1]) * half_y + MOUNT_CLEARANCE_M
        origin = -forward * reach
    else:
        origin = np.asarray(base_position, dtype=float)[:2]
    return _Frame(origin=origin, forward=forward)


def _score(frame: _Frame, superlative: str) -> Callable[[PlacedObject], float]:
    """A number that is largest for the object the superlative picks."""

    def offset(obj: PlacedObject) -> np.ndarray:
        return np.asarray(obj.position[:2], dtype=float) - frame.origin

    def seen(word: str) -> Callable[[PlacedObject], float]:  # how far towards the viewer's `word` side
        direction = np.asarray(DIRECTION[word])
        return lambda o: float(np.asarray(o.position[:2], dtype=float) @ direction)

    scores: dict[str, Callable[[PlacedObject], float]] = {
        "leftmost": seen("left"),
        "rightmost": seen("right"),
        "frontmost": seen("front"),
        "backmost": seen("behind"),
        "nearest": lambda o: -float(np.linalg.norm(offset(o))),
        "farthest": lambda o: float(np.linalg.norm(offset(o))),
        "topmost": lambda o: float(o.position[2]),
        "bottommost": lambda o: -float(o.position[2]),
    }
    return scores[superlative]


def _extreme(objects: list[PlacedObject], superlative: str, frame: _Frame, phrase: str) -> PlacedObject:
    score = _score(frame, superlative)
    ranked = sorted(objects, key=score, reverse=True)
    if len(ranked) > 1 and score(ranked[0]) - score(ranked[1]) < TIE_M:
        tied = [o for o in ranked if score(ranked[0]) - score(o) < TIE_M]
        pictured = _as_pictured(tied, superlative)
        if pictured is not None:
            return pictured
        raise TaskError(
            f"{len(tied)} {plural(phrase)} are equally {superlative} ({', '.join(o.id for o in tied)}, within "
            f"{TIE_M * 1000:g} mm): "
            "give an id"
        )
    return ranked[0]


def _as_pictured(tied: list[PlacedObject], superlative: str) -> PlacedObject | None:
    """Of objects equally far to the viewer's left (or right), the one the default render (`render.png`) shows
    farthest that way, or None when it cannot tell them apart either. That camera looks at the support from the front
    and a little from the side (`physics/render.py`'s iso view), so of two things the same distance to one side it
    draws the nearer one more to the right ("the rightmost plate" of two facing each other across a table is the one
    in front, "the leftmost" the one behind)."""
    if superlative not in ("leftmost", "rightmost"):
        return None
    azimuth = np.radians(VIEWS[DEFAULT_VIEW][0])
    right = np.array([np.sin(azimuth), -np.cos(azimuth)])  # the picture's rightward direction over the support

    def pictured(o: PlacedObject) -> float:
        across = float(np.asarray(o.position[:2], dtype=float) @ right)
        return across if superlative == "rightmost" else -across

    ranked = sorted(tied, key=pictured, reverse=True)
    return ranked[0] if pictured(ranked[0]) - pictured(ranked[1]) >= TIE_M else None
