"""The predicates the offline planner writes with, and the program it is writing (`Plan`)."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from physcensis.program.registry import PlacementKind, placement_spec, registered

# The predicates the plans are written with, from the registry: the placements by their kind, the others checked to
# be registered (a predicate renamed there fails here, at import, not in a plan).
PLACE_ON_BASE, PLACE_ON, PLACE_IN, PLACE_ANYWHERE = (
    placement_spec(kind).name
    for kind in (PlacementKind.BASE, PlacementKind.ON, PlacementKind.IN, PlacementKind.ANYWHERE)
)
(
    ALIGN_BACK,
    ALIGN_CENTER_FB,
    ALIGN_CENTER_LR,
    ALIGN_LEFT,
    ALIGN_RIGHT,
    BACK_OF,
    COPY_GROUP,
    FACING_BACK,
    FACING_FRONT,
    FACING_LEFT,
    FACING_RIGHT,
    FACING_SAME_AS,
    FACING_TO,
    FRONT_OF,
    GROUP,
    LEFT_OF,
    ORIENT_BY_RELATIVE_SIDE,
    RANDOM_ROT,
    RIGHT_OF,
    SYMMETRY_ALONG,
) = registered(
    "ALIGN-BACK",
    "ALIGN-CENTER-FB",
    "ALIGN-CENTER-LR",
    "ALIGN-LEFT",
    "ALIGN-RIGHT",
    "BACK-OF",
    "COPY-GROUP",
    "FACING-BACK",
    "FACING-FRONT",
    "FACING-LEFT",
    "FACING-RIGHT",
    "FACING-SAME-AS",
    "FACING-TO",
    "FRONT-OF",
    "GROUP",
    "LEFT-OF",
    "ORIENT-BY-RELATIVE-SIDE",
    "RANDOM-ROT",
    "RIGHT-OF",
    "SYMMETRY-ALONG",
)


Entry = list[Any]


@dataclass
class Plan:
    """A program being written, in the order the paper asks for: spatial entries, then physical, then free."""

    anchors: list[Entry] = field(default_factory=list)  # spatial entries
    physical: list[Entry] = field(default_factory=list)  # PLACE-ON / PLACE-IN
    free: list[Entry] = field(default_factory=list)  # PLACE-ANYWHERE
    used: set[str] = field(default_factory=set)
    tops: set[str] = field(default_factory=set)  # the top object of each stack written

    def new_id(self, category: str) -> str:
        slug = re.sub(r"[^a-z0-9]+", "_", category.lower()).strip("_") or "object"
        k = 0
        while f"{slug}_{k}" in self.used:
            k += 1
        self.used.add(f"{slug}_{k}")
        return f"{slug}_{k}"

    def program(self) -> list[Entry]:
        """The entries in order; a thing placed anywhere that others are put in or on comes before them (a bowl of
        grapes the words gave no place of its own): a program names only what it introduced earlier."""
        targets = {e[2] for e in self.physical if len(e) > 2 and isinstance(e[2], str)}
        holders = [e for e in self.free if isinstance(e[0], str) and e[0] in targets]
        rest = [e for e in self.free if not (isinstance(e[0], str) and e[0] in targets)]
        return [*self.anchors, *holders, *self.physical, *rest]
