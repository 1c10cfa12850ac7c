"""The predicate registry: the single list of predicates and what each one means.

The parser, the checker, the solvers' dispatch and the agent's prompt all read
this table; no other module lists predicate names. Adding a predicate is one
entry here plus its behaviour in the solver that owns its `stage`.
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Mapping
from dataclasses import dataclass
from enum import StrEnum
from types import MappingProxyType
from typing import Any, Literal


class Kind(StrEnum):
    SPATIAL = "spatial"  # 2-D position or yaw on the support
    PHYSICAL = "physical"  # 3-D contact placement confirmed by physics
    GROUP = "group"  # virtual objects made of other objects
    SPECIAL = "special"  # decides everything about its objects by itself


class Stage(StrEnum):
    """Which solver realises the predicate."""

    SPATIAL = "spatial"
    PHYSICAL = "physical"
    GROUP = "group"


class Axis(StrEnum):
    X = "x"
    Y = "y"
    HEIGHT = "height"
    YAW = "yaw"


ALL_AXES: frozenset[Axis] = frozenset(Axis)
AXIS_WORDS: dict[Axis, str] = {
    Axis.X: "x (front/back position)",
    Axis.Y: "y (left/right position)",
    Axis.HEIGHT: "height (what it stands on)",
    Axis.YAW: "yaw (which way it faces)",
}


class Role(StrEnum):
    """What may stand in a predicate's subject or target slot."""

    OBJECT = "object"  # a declared object
    GROUP = "group"  # a group made by GROUP or COPY-GROUP
    ROOT = "root"  # the support
    NEW_GROUP = "new group"  # a fresh `group_` id this entry creates
    MEMBERS = "members"  # a list of declared object ids
    ITEMS = "items"  # an id, a list of ids, or a list of [category, count]


class ParamType(StrEnum):
    NUMBER = "number"
    REFERENCE = "reference"  # an object, group or root id
    OBJECT = "object"  # a declared object id
    STABILITY = "stability"  # "stable", "unstable" or a probability in [0, 1]
    BOOL = "bool"


STABILITY_WORDS = ("stable", "unstable")


@dataclass(frozen=True)
class ParamSpec:
    name: str
    type: ParamType
    description: str
    default: Any = None
    required: bool = False
    low: float | None = None
    high: float | None = None
    optimisable: bool = False
    bounded_by_support: Literal["x", "y"] | None = None  # must lie on the support along this axis
    unit: str = ""


@dataclass(frozen=True)
class EdgeRule:
    """`A.<a_edge> = B.<b_edge> + direction * distance` along one axis of the boxes."""

    axis: Literal["x", "y"]
    a_edge: Literal["min", "center", "max"]
    b_edge: Literal["min", "center", "max"]
    direction: Literal[-1, 0, 1] = 0


@dataclass(frozen=True)
class YawRule:
    mode: Literal["absolute", "toward", "same", "opposite", "random", "relative_side"]
    angle: float = 0.0


@dataclass(frozen=True)
class PredicateSpec:
    name: str
    kind: Kind
    stage: Stage
    summary: str
    effect: str  # the update in symbols, as the prompt shows it
    subject: frozenset[Role]
    target: frozenset[Role]
    params: tuple[ParamSpec, ...] = ()
    determines: frozenset[Axis] = frozenset()
    determines_when_given: tuple[tuple[str, Axis], ...] = ()  # (param, axis) pairs
    edge: EdgeRule | None = None
    yaw: YawRule | None = None
    sets_position: bool = False  # a 2-D position rule (conflicts with PLACE-ON and friends)
    placement: Literal["base", "on", "in", "anywhere"] | None = None
    example: tuple[Any, ...] = ()

    def param(self, name: str) -> ParamSpec | None:
        for p in self.params:
            if p.name == name:
                return p
        return None

    def axes_determined(self, params: Mapping[str, Any]) -> frozenset[Axis]:
        extra = {axis for name, axis in self.determines_when_given if params.get(name) is not None}
        return self.determines | extra


_OBJ_OR_GROUP = frozenset({Role.OBJECT, Role.GROUP})
_ANY_REF = frozenset({Role.OBJECT, Role.GROUP, Role.ROOT})

_DISTANCE = ParamSpec(
    "distance", ParamType.NUMBER, "gap between the two boxes", default=0.02,
    low=0.0, high=10.0, optimisable=True, unit="m",
)
_MESSY = ParamSpec(
    "messy", ParamType.BOOL, "a natural, untidy rest (may lean on neighbours) instead of a tidy, flat one",
    default=False,
)
_YAW_OFFSET = ParamSpec(
    "yaw_offset", ParamType.NUMBER, "small turn added to the rule's yaw", default=0.0,
    low=-math.pi, high=math.pi, optimisable=True, unit="rad",
)


def _relative(name: str, edge: EdgeRule, summary: str, effect: str, example: tuple[Any, ...]) -> PredicateSpec:
    has_distance = edge.direction != 0
    return PredicateSpec(
        name=name, kind=Kind.SPATIAL, stage=Stage.SPATIAL, summary=summary, effect=effect,
        subject=_OBJ_OR_GROUP, target=_ANY_REF,
        params=(_DISTANCE,) if has_distance else (),
        determines=frozenset({Axis(edge.axis)}), edge=edge, sets_position=True, example=example,
    )


def _facing(name: str, rule: YawRule, summary: str, effect: str, example: tuple[Any, ...],
            target: frozenset[Role] = _ANY_REF) -> PredicateSpec:
    params = () if rule.mode == "random" else (_YAW_OFFSET,)
    return PredicateSpec(
        name=name, kind=Kind.SPATIAL, stage=Stage.SPATIAL, summary=summary, effect=effect,
        subject=_OBJ_OR_GROUP, target=target, params=params,
        determines=frozenset({Axis.YAW}), yaw=rule, example=example,
    )


_SPECS: tuple[PredicateSpec, ...] = (
    _relative("LEFT-OF", EdgeRule("y", "min", "max", 1), "A stands to the left (+y) of B",
              "A.min_y = B.max_y + distance", ("phone_0", "LEFT-OF", "laptop_0", {"distance": 0.1})),
    _relative("RIGHT-OF", EdgeRule("y", "max", "min", -1), "A stands to the right (-y) of B",
              "A.max_y = B.min_y - distance", ("mouse_0", "RIGHT-OF", "keyboard_0", {"distance": 0.05})),
    _relative("FRONT-OF", EdgeRule("x", "min", "max", 1), "A stands in front (+x) of B",
              "A.min_x = B.max_x + distance", ("keyboard_0", "FRONT-OF", "monitor_0", {"distance": 0.08})),
    _relative("BACK-OF", EdgeRule("x", "max", "min", -1), "A stands behind (-x) B",
              "A.max_x = B.min_x - distance", ("glass_0", "BACK-OF", "plate_0", {"distance": 0.03})),
    _relative("ALIGN-CENTER-LR", EdgeRule("y", "center", "center"), "A and B share their left/right centre",
              "A.center_y = B.center_y", ("keyboard_0", "ALIGN-CENTER-LR", "monitor_0", {})),
    _relative("ALIGN-CENTER-FB", EdgeRule("x", "center", "center"), "A and B share their front/back centre",
              "A.center_x = B.center_x", ("fork_0", "ALIGN-CENTER-FB", "plate_0", {})),
    _relative("ALIGN-LEFT", EdgeRule("y", "max", "max"), "A's left edge lines up with B's",
              "A.max_y = B.max_y", ("book_1", "ALIGN-LEFT", "book_0", {})),
    _relative("ALIGN-RIGHT", EdgeRule("y", "min", "min"), "A's right edge lines up with B's",
              "A.min_y = B.min_y", ("glass_0", "ALIGN-RIGHT", "knife_0", {})),
    _relative("ALIGN-FRONT", EdgeRule("x", "max", "max"), "A's front edge lines up with B's",
              "A.max_x = B.max_x", ("jar_1", "ALIGN-FRONT", "jar_0", {})),
    _relative("ALIGN-BACK", EdgeRule("x", "min", "min"), "A's back edge lines up with B's",
              "A.min_x = B.min_x", ("jar_1", "ALIGN-BACK", "jar_0", {})),
    PredicateSpec(
        name="SYMMETRY-ALONG", kind=Kind.SPATIAL, stage=Stage.SPATIAL,
        summary="A is B mirrored through the centre of C",
        effect="A.center = 2 * C.center - B.center",
        subject=_OBJ_OR_GROUP, target=_ANY_REF,
        params=(ParamSpec("C", ParamType.REFERENCE, "the object, group or root to mirror through", required=True),),
        determines=frozenset({Axis.X, Axis.Y}), sets_position=True,
        example=("knife_0", "SYMMETRY-ALONG", "fork_0", {"C": "plate_0"}),
    ),
    _facing("FACING-FRONT", YawRule("absolute", 0.0), "A faces the front (+x)", "A.yaw = 0",
            ("monitor_0", "FACING-FRONT", "root", {})),
    _facing("FACING-BACK", YawRule("absolute", math.pi), "A faces the back (-x)", "A.yaw = pi",
            ("chair_0", "FACING-BACK", "root", {})),
    _facing("FACING-LEFT", YawRule("absolute", math.pi / 2), "A faces left (+y)", "A.yaw = pi / 2",
            ("lamp_0", "FACING-LEFT", "root", {})),
    _facing("FACING-RIGHT", YawRule("absolute", -math.pi / 2), "A faces right (-y)", "A.yaw = -pi / 2",
            ("lamp_0", "FACING-RIGHT", "root", {})),
    _facing("FACING-TO", YawRule("toward"), "A turns to face B's centre",
            "A.yaw = atan2(B.center_y - A.center_y, B.center_x - A.center_x)",
            ("monitor_0", "FACING-TO", "keyboard_0", {}), target=_OBJ_OR_GROUP),
    _facing("FACING-SAME-AS", YawRule("same"), "A faces the same way as B", "A.yaw = B.yaw",
            ("mouse_0", "FACING-SAME-AS", "keyboard_0", {})),
    _facing("FACING-OPPOSITE-TO", YawRule("opposite"), "A faces the opposite way to B", "A.yaw = B.yaw + pi",
            ("group_setting_1", "FACING-OPPOSITE-TO", "group_setting_0", {}), target=_OBJ_OR_GROUP),
    _facing("RANDOM-ROT", YawRule("random"), "A gets a random yaw (seeded)", "A.yaw = uniform(0, 2 pi)",
            ("pen_0", "RANDOM-ROT", "root", {})),
    _facing("ORIENT-BY-RELATIVE-SIDE", YawRule("relative_side"),
            "A keeps its yaw or turns a quarter, whichever lines its box up better with B's "
            "(cutlery beside a plate, a mouse beside a keyboard)",
            "A.yaw = the one of {yaw, yaw + pi/2} maximising overlap_x(A, B) + overlap_y(A, B)",
            ("fork_0", "ORIENT-BY-RELATIVE-SIDE", "plate_0", {}), target=_OBJ_OR_GROUP),
    PredicateSpec(
        name="PLACE-ON-BASE", kind=Kind.SPATIAL, stage=Stage.SPATIAL,
        summary="A stands on the support; x and y fix its centre, or leave them out and let other predicates do it",
        effect="A.center_x = x; A.center_y = y; A.min_z = root.max_z",
        subject=_OBJ_OR_GROUP, target=frozenset({Role.ROOT}),
        params=(
            ParamSpec("x", ParamType.NUMBER, "centre x on the support", low=-50.0, high=50.0,
                      optimisable=True, bounded_by_support="x", unit="m"),
            ParamSpec("y", ParamType.NUMBER, "centre y on the support", low=-50.0, high=50.0,
                      optimisable=True, bounded_by_support="y", unit="m"),
        ),
        determines=frozenset({Axis.HEIGHT}),
        determines_when_given=(("x", Axis.X), ("y", Axis.Y)),
        sets_position=True, placement="base",
        example=("laptop_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}),
    ),
    PredicateSpec(
        name="PLACE-ON", kind=Kind.PHYSICAL, stage=Stage.PHYSICAL,
        summary="A rests on top of object B (never root); the solver finds a supported, collision-free spot",
        effect="A.center = B.center + (x_offset, y_offset); overlap = area(A.bottom & B.top) / area(A.bottom)",
        subject=frozenset({Role.OBJECT}), target=frozenset({Role.OBJECT}),
        params=(
            ParamSpec("x_offset", ParamType.NUMBER, "wished x of A's centre relative to B's",
                      low=-5.0, high=5.0, unit="m"),
            ParamSpec("y_offset", ParamType.NUMBER, "wished y of A's centre relative to B's",
                      low=-5.0, high=5.0, unit="m"),
            ParamSpec("overlap", ParamType.NUMBER, "wished share of A's bottom that rests on B", low=0.0, high=1.0),
            ParamSpec("stability", ParamType.STABILITY,
                      'how fragile the placement should be: "stable", "unstable" or a probability of falling'),
            _MESSY,
        ),
        determines=ALL_AXES, placement="on",
        example=("cup_0", "PLACE-ON", "notebook_0", {"overlap": 1.0}),
    ),
    PredicateSpec(
        name="PLACE-IN", kind=Kind.SPECIAL, stage=Stage.PHYSICAL,
        summary="the listed objects are dropped into container B and settle inside it; use it once per container",
        effect="A = an id, a list of ids, or a list of [category, count]; each ends inside B's cavity",
        subject=frozenset({Role.ITEMS}), target=frozenset({Role.OBJECT}),
        determines=ALL_AXES, placement="in",
        example=([["pen", 6], ["pencil", 3]], "PLACE-IN", "pen_holder_0", {}),
    ),
    PredicateSpec(
        name="PLACE-ANYWHERE", kind=Kind.SPECIAL, stage=Stage.PHYSICAL,
        summary="A goes to any supported, collision-free spot in the scene (good for filling crowded scenes)",
        effect="A = a free spot found by the solver",
        subject=frozenset({Role.OBJECT}), target=frozenset({Role.ROOT}),
        params=(
            ParamSpec("stack", ParamType.BOOL, "whether it may rest on other objects, not only on the support",
                      default=True),
            _MESSY,
        ),
        determines=ALL_AXES, placement="anywhere",
        example=("vase_0", "PLACE-ANYWHERE", "root", {}),
    ),
    PredicateSpec(
        name="GROUP", kind=Kind.GROUP, stage=Stage.GROUP,
        summary="a virtual object made of existing objects; its box bounds them and its yaw is its anchor's",
        effect="group.box = bounds(members); group.yaw = anchor.yaw",
        subject=frozenset({Role.NEW_GROUP}), target=frozenset({Role.MEMBERS}),
        params=(ParamSpec("anchor", ParamType.OBJECT, "the member whose yaw is the group's (default: the first)"),),
        example=("group_setting_0", "GROUP", ["plate_0", "fork_0", "knife_0", "glass_0"], {"anchor": "plate_0"}),
    ),
    PredicateSpec(
        name="COPY-GROUP", kind=Kind.GROUP, stage=Stage.GROUP,
        summary="copies every member of an existing group with the same relative poses; "
                "the copy of member M in group_N is named M-group_N, and later predicates move the copy as a whole",
        effect="group_new = rigid copy of group_old",
        subject=frozenset({Role.NEW_GROUP}), target=frozenset({Role.GROUP}),
        example=("group_setting_1", "COPY-GROUP", "group_setting_0", {}),
    ),
)

PREDICATES: Mapping[str, PredicateSpec] = MappingProxyType({spec.name: spec for spec in _SPECS})


def _key(name: str) -> str:
    return "".join(ch for ch in name.upper() if ch.isalnum())


_BY_KEY: dict[str, PredicateSpec] = {_key(spec.name): spec for spec in _SPECS}


def canonical_name(name: str) -> str:
    """Upper case with dashes: `place_on` and `Place-On` both become `PLACE-ON`."""
    return "-".join(part for part in name.strip().upper().replace("_", "-").replace(" ", "-").split("-") if part)


def lookup(name: str) -> PredicateSpec | None:
    """The predicate a name means, ignoring case, dashes, underscores and spaces."""
    return _BY_KEY.get(_key(name))


def closest_name(name: str) -> str | None:
    """The registered predicate name nearest to a misspelt one, if any is close."""
    matches = difflib.get_close_matches(_key(name), list(_BY_KEY), n=1, cutoff=0.5)
    return _BY_KEY[matches[0]].name if matches else None


def names(kind: Kind | None = None) -> list[str]:
    return [spec.name for spec in _SPECS if kind is None or spec.kind == kind]
