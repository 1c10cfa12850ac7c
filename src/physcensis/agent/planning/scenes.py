"""Kinds of scene (dining, desk, kitchen ...) and the objects typical of each: the scene a prompt naming no object
gets, the fillers of a dense scene or an enrichment, and the context objects variety may add."""

from __future__ import annotations

from collections.abc import Callable

from physcensis.agent.reading import Mention, SceneRequest

FILLERS = {
    "desk": [
        "pen",
        "notebook",
        "mug",
        "phone",
        "book lying flat",
        "pencil",
        "pencil case",
        "potted plant",
        "glass",
        "apple",
    ],
    "dining": ["napkin", "candle", "glass", "bowl", "vase", "bread", "pitcher", "spoon"],
    "kitchen": ["jar", "bottle", "bowl", "spoon", "can", "cutting board", "mug", "apple", "orange", "plate"],
    "bathroom": ["bottle", "towel", "cup", "soap dispenser", "toothbrush", "jar"],
    "shelf": ["book standing upright", "jar", "can", "box", "bottle", "potted plant", "vase"],
    "floor": ["toy block", "ball", "stuffed animal", "toy truck", "book lying flat", "basket"],
    "everyday": [
        "mug",
        "book lying flat",
        "phone",
        "can",
        "apple",
        "jar",
        "bottle",
        "notebook",
        "pen",
        "glass",
        "plate",
        "bowl",
        "box",
        "candle",
        "orange",
        "banana",
        "tape measure",
        "toy block",
        "cup",
        "napkin",
        "spoon",
        "potted plant",
        "screwdriver",
        "pencil",
    ],
}
# Words that name a kind of scene or a support: a prompt with one of them and no object gets that kind's typical scene.
SCENE_KINDS = frozenset(
    """table desk counter countertop worktop workbench nightstand shelf bookshelf bookcase cabinet cupboard dresser
    sideboard windowsill vanity floor room kitchen bathroom bedroom office pantry garage playroom nursery
    tabletop island dinner dining breakfast lunch picnic meal party study student tea""".split()
)
DEFAULT_SCENES = {
    "desk": ["laptop", "notebook", "pen", "pencil", "mug", "phone", "book lying flat", "pencil case"],
    "everyday": ["mug", "book lying flat", "phone", "apple", "bottle", "notebook"],
}
# Objects that belong to a kind of scene without being asked for; with variety a few may be added.
CONTEXT = {
    "dining": ["vase", "napkin", "salt shaker", "candle", "bread", "pitcher", "bowl"],
    "desk": ["potted plant", "mug", "pen", "notebook", "desk lamp", "glass"],
    "kitchen": ["jar", "olive oil bottle", "cutting board", "bowl", "apple", "mug"],
    "bathroom": ["towel", "soap dispenser", "cup", "bottle"],
}  # only scenes the prompt's words name: "a gizmo and two mugs" gets nothing it did not ask for


def scene_type(request: SceneRequest, kind: str) -> str:
    """The kind of scene the request and the support's kind make (a key of FILLERS)."""
    words = set(request.tokens)
    if kind == "floor":
        return "floor"
    if kind == "shelf":
        return "shelf"
    if words & {"desk", "office", "student", "study"}:
        return "desk"
    if words & {"dinner", "dining", "breakfast", "lunch", "picnic", "tea"} or request.diners:
        return "dining"
    if "bathroom" in words:  # the room named, before what its support is called ("a bathroom counter")
        return "bathroom"
    if words & {"kitchen", "counter", "cooking", "pantry"}:
        return "kitchen"
    if "sink" in words:
        return "bathroom"
    return "everyday"


def mentions_or_default_scene(request: SceneRequest, kind: str, category: Callable[[str], str]) -> list[Mention]:
    """What the prompt names; for a prompt naming nothing (and no diners) a typical scene of its kind."""
    if request.mentions or request.diners:
        return list(request.mentions)
    names = DEFAULT_SCENES.get(scene_type(request, kind), DEFAULT_SCENES["everyday"])
    if request.dense:
        names = FILLERS["everyday"][:22]
    return [Mention(category(n), 1, n, (), 0, 0, False, False) for n in names]
