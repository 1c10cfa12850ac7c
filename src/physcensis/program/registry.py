"""The predicate registry: the single list of predicates and what each one means.

The parser, the checker, the solvers' dispatch and the agent's prompt all read
this table; no other module lists predicate names. Each predicate has one
`Effect`, the key every solver dispatches on; which solver realises it, how it
places its object, whether it sets a 2-D position and where the prompt lists it
all follow from the effect's own row, which every `Effect` member carries.
Adding a predicate is one entry here; a new effect also needs one handler in the
table of the solver that owns it (tests/program/test_conformance.py checks both).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from enum import StrEnum
from types import MappingProxyType
from typing import Any, Literal, TypeVar

from physcensis.errors import PhyscensisError
from physcensis.ids import close_match


class Solver(StrEnum):
    """Which solver realises a predicate."""

    SPATIAL = "spatial"  # 2-D position or yaw on the support, optimised together (solver/layout.py)
    PHYSICAL = "physical"  # a 3-D resting place found by search and confirmed in physics (solver/pipeline.py)
    GROUP = "group"  # virtual objects made of other objects, compiled with the spatial layout (solver/layout.py)


class PlacementKind(StrEnum):
    """How an object gets its height. Every object takes exactly one; the predicate of each is `placement_spec`.

    Each kind carries its `rank`, its part in the order the paper asks for (spatial 0, then PLACE-ON and PLACE-IN 1,
    then PLACE-ANYWHERE 2), and whether it `decides_everything`: determines position, height and yaw by itself.
    """

    rank: int
    decides_everything: bool

    def __new__(cls, value: str, rank: int | None = None, decides_everything: bool | None = None) -> PlacementKind:
        if rank is None or decides_everything is None:
            raise PhyscensisError(
                f"placement kind {value!r} needs its rank and whether it decides everything: "
                f"write it as NAME = {value!r}, rank, decides_everything"
            )
        kind = str.__new__(cls, value)
        kind._value_ = value
        kind.rank = rank
        kind.decides_everything = decides_everything
        return kind

    BASE = "base", 0, False  # stands on the support (its x and y come from 2-D predicates)
    ON = "on", 1, True  # rests on another object
    IN = "in", 1, True  # dropped into a container
    ANYWHERE = "anywhere", 2, True  # any supported, collision-free spot


# The headings the agent's prompt lists predicates under (each predicate's is its effect's; the prompt shows them in
# the order their first predicates come in the registry).
BESIDE_SECTION = "Beside another object (2-D position)"
ALIGNING_SECTION = "Lining up with another object (2-D alignment)"  # an edge rule with no gap
MIRRORING_SECTION = "Mirroring (2-D symmetry)"
TURNING_SECTION = "Turning (yaw only)"
STANDING_SECTION = "Standing on the support (height)"
PHYSICAL_SECTION = "Placed by the physical solver (position, height and yaw at once)"
GROUPS_SECTION = "Groups"


@dataclass(frozen=True)
class EffectInfo:
    """What follows from an effect for every predicate that has it."""

    solver: Solver  # which solver realises it
    section: str  # the heading the agent's prompt lists its predicates under
    placement: PlacementKind | None = None  # how it gives its object a height, if it does
    sets_position: bool = False  # a 2-D position rule (which cannot be mixed with a physical placement)


class Effect(StrEnum):
    """What a predicate does: the single key every solver's handler table is keyed by. Each member carries its row,
    `info`; one declared without it is refused when this module is imported."""

    info: EffectInfo

    def __new__(cls, value: str, info: EffectInfo | None = None) -> Effect:
        if not isinstance(info, EffectInfo):
            raise PhyscensisError(
                f"effect {value!r} has no row: write it as NAME = {value!r}, EffectInfo(solver, prompt section, "
                "placement=..., sets_position=...)"
            )
        effect = str.__new__(cls, value)
        effect._value_ = value
        effect.info = info
        return effect

    # an edge or the centre of A's box from B's along one axis (the spec's `edge` rule)
    EDGE = "edge", EffectInfo(Solver.SPATIAL, BESIDE_SECTION, sets_position=True)
    # A mirrored through C
    SYMMETRY = "symmetry", EffectInfo(Solver.SPATIAL, MIRRORING_SECTION, sets_position=True)
    # stands on the support, at x and y if given
    BASE = "base", EffectInfo(Solver.SPATIAL, STANDING_SECTION, PlacementKind.BASE, sets_position=True)
    # A's yaw (the spec's `yaw` rule)
    YAW = "yaw", EffectInfo(Solver.SPATIAL, TURNING_SECTION)
    # rests on object B
    ON = "on", EffectInfo(Solver.PHYSICAL, PHYSICAL_SECTION, PlacementKind.ON)
    # items dropped into container B
    IN = "in", EffectInfo(Solver.PHYSICAL, PHYSICAL_SECTION, PlacementKind.IN)
    # any free, supported spot
    ANYWHERE = "anywhere", EffectInfo(Solver.PHYSICAL, PHYSICAL_SECTION, PlacementKind.ANYWHERE)
    # a virtual object bounding its members
    GROUP = "group", EffectInfo(Solver.GROUP, GROUPS_SECTION)
    # a rigid copy of a group
    COPY_GROUP = "copy-group", EffectInfo(Solver.GROUP, GROUPS_SECTION)


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


class YawMode(StrEnum):
    """How a yaw rule turns A."""

    ABSOLUTE = "absolute"  # to a fixed angle
    TOWARD = "toward"  # to face B's centre
    SAME = "same"  # as B faces
    OPPOSITE = "opposite"  # against B
    RANDOM = "random"  # a seeded uniform angle
    RELATIVE_SIDE = "relative_side"  # its own yaw or a quarter turn more, whichever lines up with B

    @property
    def refines(self) -> bool:
        """Whether it chooses among turns of A's existing yaw, so refines an earlier yaw rather than overriding it."""
        return self is YawMode.RELATIVE_SIDE

    @property
    def has_offset(self) -> bool:
        """Whether the rule takes a small optimisable `yaw_offset` (a random yaw has nothing to fine-tune)."""
        return self is not YawMode.RANDOM


@dataclass(frozen=True)
class YawRule:
    mode: YawMode
    angle: float = 0.0  # the yaw of an ABSOLUTE rule


@dataclass(frozen=True)
class PredicateSpec:
    name: str
    effect: Effect
    summary: str
    formula: str  # the update in symbols, as the prompt shows it
    subject: frozenset[Role]
    target: frozenset[Role]
    params: tuple[ParamSpec, ...] = ()
    determines: frozenset[Axis] = frozenset()
    determines_when_given: tuple[tuple[str, Axis], ...] = ()  # (param, axis) pairs
    edge: EdgeRule | None = None  # the rule of an EDGE effect, and only of one
    yaw: YawRule | None = None  # the rule of a YAW effect, and only of one
    example: tuple[Any, ...] = ()

    def __post_init__(self) -> None:
        for rule, effect, field_name in ((self.edge, Effect.EDGE, "edge"), (self.yaw, Effect.YAW, "yaw")):
            if (rule is not None) != (self.effect is effect):
                raise PhyscensisError(
                    f"predicate {self.name}: a `{field_name}` rule goes with effect {effect} "
                    f"and only with it (its effect is {self.effect})"
                )

    @property
    def solver(self) -> Solver:
        return self.effect.info.solver

    @property
    def placement(self) -> PlacementKind | None:
        return self.effect.info.placement

    @property
    def sets_position(self) -> bool:
        """Whether it is a 2-D position rule (which cannot be mixed with PLACE-ON and friends)."""
        return self.effect.info.sets_position

    @property
    def section(self) -> str:
        """The heading the agent's prompt lists it under: its effect's, except that an edge rule with no gap lines
        A up with B rather than putting it beside B."""
        if self.edge is not None and self.edge.direction == 0:
            return ALIGNING_SECTION
        return self.effect.info.section

    def edge_rule(self) -> EdgeRule:
        if self.edge is None:
            raise PhyscensisError(f"predicate {self.name} has no edge rule (its effect is {self.effect})")
        return self.edge

    def yaw_rule(self) -> YawRule:
        if self.yaw is None:
            raise PhyscensisError(f"predicate {self.name} has no yaw rule (its effect is {self.effect})")
        return self.yaw

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
    "distance",
    ParamType.NUMBER,
    "gap between the two boxes",
    default=0.02,
    low=0.0,
    high=10.0,
    optimisable=True,
    unit="m",
)
_MESSY = ParamSpec(
    "messy",
    ParamType.BOOL,
    "a natural, untidy rest (may lean on neighbours) instead of a tidy, flat one",
    default=False,
)
_YAW_OFFSET = ParamSpec(
    "yaw_offset",
    ParamType.NUMBER,
    "small turn added to the rule's yaw",
    default=0.0,
    low=-math.pi,
    high=math.pi,
    optimisable=True,
    unit="rad",
)


def _relative(name: str, edge: EdgeRule, summary: str, formula: str, example: tuple[Any, ...]) -> PredicateSpec:
    has_distance = edge.direction != 0
    return PredicateSpec(
        name=name,
        effect=Effect.EDGE,
        summary=summary,
        formula=formula,
        subject=_OBJ_OR_GROUP,
        target=_ANY_REF,
        params=(_DISTANCE,) if has_distance else (),
        determines=frozenset({Axis(edge.axis)}),
        edge=edge,
        example=example,
    )


def _facing(
    name: str, rule: YawRule, summary: str, formula: str, example: tuple[Any, ...], target: frozenset[Role] = _ANY_REF
) -> PredicateSpec:
    return PredicateSpec(
        name=name,
        effect=Effect.YAW,
        summary=summary,
        formula=formula,
        subject=_OBJ_OR_GROUP,
        target=target,
        params=(_YAW_OFFSET,) if rule.mode.has_offset else (),
        determines=frozenset({Axis.YAW}),
        yaw=rule,
        example=example,
    )


_SPECS: tuple[PredicateSpec, ...] = (
    _relative(
        "LEFT-OF",
        EdgeRule("y", "min", "max", 1),
        "A stands to the left (+y) of B",
        "A.min_y = B.max_y + distance",
        ("phone_0", "LEFT-OF", "laptop_0", {"distance": 0.1}),
    ),
    _relative(
        "RIGHT-OF",
        EdgeRule("y", "max", "min", -1),
        "A stands to the right (-y) of B",
        "A.max_y = B.min_y - distance",
        ("mouse_0", "RIGHT-OF", "keyboard_0", {"distance": 0.05}),
    ),
    _relative(
        "FRONT-OF",
        EdgeRule("x", "min", "max", 1),
        "A stands in front (+x) of B",
        "A.min_x = B.max_x + distance",
        ("keyboard_0", "FRONT-OF", "monitor_0", {"distance": 0.08}),
    ),
    _relative(
        "BACK-OF",
        EdgeRule("x", "max", "min", -1),
        "A stands behind (-x) B",
        "A.max_x = B.min_x - distance",
        ("glass_0", "BACK-OF", "plate_0", {"distance": 0.03}),
    ),
    _relative(
        "ALIGN-CENTER-LR",
        EdgeRule("y", "center", "center"),
        "A and B share their left/right centre",
        "A.center_y = B.center_y",
        ("keyboard_0", "ALIGN-CENTER-LR", "monitor_0", {}),
    ),
    _relative(
        "ALIGN-CENTER-FB",
        EdgeRule("x", "center", "center"),
        "A and B share their front/back centre",
        "A.center_x = B.center_x",
        ("fork_0", "ALIGN-CENTER-FB", "plate_0", {}),
    ),
    _relative(
        "ALIGN-LEFT",
        EdgeRule("y", "max", "max"),
        "A's left edge lines up with B's",
        "A.max_y = B.max_y",
        ("book_1", "ALIGN-LEFT", "book_0", {}),
    ),
    _relative(
        "ALIGN-RIGHT",
        EdgeRule("y", "min", "min"),
        "A's right edge lines up with B's",
        "A.min_y = B.min_y",
        ("glass_0", "ALIGN-RIGHT", "knife_0", {}),
    ),
    _relative(
        "ALIGN-FRONT",
        EdgeRule("x", "max", "max"),
        "A's front edge lines up with B's",
        "A.max_x = B.max_x",
        ("jar_1", "ALIGN-FRONT", "jar_0", {}),
    ),
    _relative(
        "ALIGN-BACK",
        EdgeRule("x", "min", "min"),
        "A's back edge lines up with B's",
        "A.min_x = B.min_x",
        ("jar_1", "ALIGN-BACK", "jar_0", {}),
    ),
    PredicateSpec(
        name="SYMMETRY-ALONG",
        effect=Effect.SYMMETRY,
        summary="A is B mirrored through the centre of C",
        formula="A.center = 2 * C.center - B.center",
        subject=_OBJ_OR_GROUP,
        target=_ANY_REF,
        params=(ParamSpec("C", ParamType.REFERENCE, "the object, group or root to mirror through", required=True),),
        determines=frozenset({Axis.X, Axis.Y}),
        example=("knife_0", "SYMMETRY-ALONG", "fork_0", {"C": "plate_0"}),
    ),
    _facing(
        "FACING-FRONT",
        YawRule(YawMode.ABSOLUTE, 0.0),
        "A faces the front (+x)",
        "A.yaw = 0",
        ("monitor_0", "FACING-FRONT", "root", {}),
    ),
    _facing(
        "FACING-BACK",
        YawRule(YawMode.ABSOLUTE, math.pi),
        "A faces the back (-x)",
        "A.yaw = pi",
        ("chair_0", "FACING-BACK", "root", {}),
    ),
    _facing(
        "FACING-LEFT",
        YawRule(YawMode.ABSOLUTE, math.pi / 2),
        "A faces left (+y)",
        "A.yaw = pi / 2",
        ("lamp_0", "FACING-LEFT", "root", {}),
    ),
    _facing(
        "FACING-RIGHT",
        YawRule(YawMode.ABSOLUTE, -math.pi / 2),
        "A faces right (-y)",
        "A.yaw = -pi / 2",
        ("lamp_0", "FACING-RIGHT", "root", {}),
    ),
    _facing(
        "FACING-TO",
        YawRule(YawMode.TOWARD),
        "A turns to face B's centre",
        "A.yaw = atan2(B.center_y - A.center_y, B.center_x - A.center_x)",
        ("monitor_0", "FACING-TO", "keyboard_0", {}),
        target=_OBJ_OR_GROUP,
    ),
    _facing(
        "FACING-SAME-AS",
        YawRule(YawMode.SAME),
        "A faces the same way as B",
        "A.yaw = B.yaw",
        ("mouse_0", "FACING-SAME-AS", "keyboard_0", {}),
    ),
    _facing(
        "FACING-OPPOSITE-TO",
        YawRule(YawMode.OPPOSITE),
        "A faces the opposite way to B",
        "A.yaw = B.yaw + pi",
        ("group_setting_1", "FACING-OPPOSITE-TO", "group_setting_0", {}),
        target=_OBJ_OR_GROUP,
    ),
    _facing(
        "RANDOM-ROT",
        YawRule(YawMode.RANDOM),
        "A gets a random yaw (seeded)",
        "A.yaw = uniform(0, 2 pi)",
        ("pen_0", "RANDOM-ROT", "root", {}),
    ),
    _facing(
        "ORIENT-BY-RELATIVE-SIDE",
        YawRule(YawMode.RELATIVE_SIDE),
        "A keeps its yaw or turns a quarter, whichever lines its box up better with B's "
        "(cutlery beside a plate, a mouse beside a keyboard)",
        "A.yaw = the one of {yaw, yaw + pi/2} maximising overlap_x(A, B) + overlap_y(A, B)",
        ("fork_0", "ORIENT-BY-RELATIVE-SIDE", "plate_0", {}),
        target=_OBJ_OR_GROUP,
    ),
    PredicateSpec(
        name="PLACE-ON-BASE",
        effect=Effect.BASE,
        summary="A stands on the support; x and y fix its centre, or leave them out and let other predicates do it",
        formula="A.center_x = x; A.center_y = y; A.min_z = root.max_z",
        subject=_OBJ_OR_GROUP,
        target=frozenset({Role.ROOT}),
        params=(
            ParamSpec(
                "x",
                ParamType.NUMBER,
                "centre x on the support",
                low=-50.0,
                high=50.0,
                optimisable=True,
                bounded_by_support="x",
                unit="m",
            ),
            ParamSpec(
                "y",
                ParamType.NUMBER,
                "centre y on the support",
                low=-50.0,
                high=50.0,
                optimisable=True,
                bounded_by_support="y",
                unit="m",
            ),
        ),
        determines=frozenset({Axis.HEIGHT}),
        determines_when_given=(("x", Axis.X), ("y", Axis.Y)),
        example=("laptop_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}),
    ),
    PredicateSpec(
        name="PLACE-ON",
        effect=Effect.ON,
        summary="A rests on top of object B (never root); the solver finds a supported, collision-free spot",
        formula="A.center = B.center + (x_offset, y_offset); overlap = area(A.bottom & B.top) / area(A.bottom)",
        subject=frozenset({Role.OBJECT}),
        target=frozenset({Role.OBJECT}),
        params=(
            ParamSpec(
                "x_offset", ParamType.NUMBER, "wished x of A's centre relative to B's", low=-5.0, high=5.0, unit="m"
            ),
            ParamSpec(
                "y_offset", ParamType.NUMBER, "wished y of A's centre relative to B's", low=-5.0, high=5.0, unit="m"
            ),
            ParamSpec("overlap", ParamType.NUMBER, "wished share of A's bottom that rests on B", low=0.0, high=1.0),
            ParamSpec(
                "stability",
                ParamType.STABILITY,
                'how fragile the placement should be: "stable", "unstable" or a probability of falling',
            ),
            _MESSY,
        ),
        determines=ALL_AXES,
        example=("cup_0", "PLACE-ON", "notebook_0", {"overlap": 1.0}),
    ),
    PredicateSpec(
        name="PLACE-IN",
        effect=Effect.IN,
        summary="the listed objects are dropped into container B and settle inside it; use it once per container",
        formula="A = an id, a list of ids, or a list of [category, count]; each ends inside B's cavity",
        subject=frozenset({Role.ITEMS}),
        target=frozenset({Role.OBJECT}),
        determines=ALL_AXES,
        example=([["pen", 6], ["pencil", 3]], "PLACE-IN", "pen_holder_0", {}),
    ),
    PredicateSpec(
        name="PLACE-ANYWHERE",
        effect=Effect.ANYWHERE,
        summary="A goes to a random supported, collision-free spot in the scene (good for filling crowded scenes)",
        formula="A = a free spot found by the solver",
        subject=frozenset({Role.OBJECT}),
        target=frozenset({Role.ROOT}),
        params=(
            ParamSpec(
                "stack", ParamType.BOOL, "whether it may rest on other objects, not only on the support", default=True
            ),
            ParamSpec(
                "pack",
                ParamType.BOOL,
                "snug against what is already there and the support's edges, keeping room for more (to fill a "
                "support densely) instead of a random spot",
                default=False,
            ),
            _MESSY,
        ),
        determines=ALL_AXES,
        example=("vase_0", "PLACE-ANYWHERE", "root", {}),
    ),
    PredicateSpec(
        name="GROUP",
        effect=Effect.GROUP,
        summary="a virtual object made of existing objects; its box bounds them and its yaw is its anchor's",
        formula="group.box = bounds(members); group.yaw = anchor.yaw",
        subject=frozenset({Role.NEW_GROUP}),
        target=frozenset({Role.MEMBERS}),
        params=(ParamSpec("anchor", ParamType.OBJECT, "the member whose yaw is the group's (default: the first)"),),
        example=("group_setting_0", "GROUP", ["plate_0", "fork_0", "knife_0", "glass_0"], {"anchor": "plate_0"}),
    ),
    PredicateSpec(
        name="COPY-GROUP",
        effect=Effect.COPY_GROUP,
        summary="copies every member of an existing group with the same relative poses; "
        "the copy of member M in group_N is named M-group_N, and later predicates move the copy as a whole",
        formula="group_new = rigid copy of group_old",
        subject=frozenset({Role.NEW_GROUP}),
        target=frozenset({Role.GROUP}),
        example=("group_setting_1", "COPY-GROUP", "group_setting_0", {}),
    ),
)

PREDICATES: Mapping[str, PredicateSpec] = MappingProxyType({spec.name: spec for spec in _SPECS})


def _key(name: str) -> str:
    return "".join(ch for ch in name.upper() if ch.isalnum())


_BY_KEY: dict[str, PredicateSpec] = {_key(spec.name): spec for spec in _SPECS}


def lookup(name: str) -> PredicateSpec | None:
    """The predicate a name means, ignoring case, dashes, underscores and spaces."""
    return _BY_KEY.get(_key(name))


def registered(*names: str) -> tuple[str, ...]:
    """`names`, each checked to be a registered predicate: code that writes programs takes the names it uses from
    here, so a predicate renamed or removed in the registry fails where it is used, when that module is imported."""
    unknown = [name for name in names if name not in PREDICATES]
    if unknown:
        raise PhyscensisError(f"not registered predicates: {', '.join(unknown)}")
    return names


def closest_name(name: str) -> str | None:
    """The registered predicate name nearest to a misspelt one, if any is close."""
    match = close_match(_key(name), _BY_KEY, cutoff=0.5)
    return _BY_KEY[match].name if match else None


Handler = TypeVar("Handler")


def handler_for(
    table: Mapping[Any, Handler], spec: PredicateSpec, key: Solver | Effect | YawMode | None = None
) -> Handler:
    """The handler a solver's table holds for `spec` (under its effect, or under `key`: its solver or its yaw
    mode); a clear error naming the predicate when the table has none."""
    key = spec.effect if key is None else key
    if key not in table:
        what = {Solver: "solver", Effect: "effect", YawMode: "yaw mode"}[type(key)]
        raise PhyscensisError(f"no {spec.solver.value} solver handles predicate {spec.name} ({what} {key.value})")
    return table[key]


def _one_predicate_per_placement(specs: tuple[PredicateSpec, ...]) -> dict[PlacementKind, PredicateSpec]:
    """The predicate of each placement kind; every kind must have exactly one (checked when this module is
    imported, so a kind without its predicate, or with two, is a clear error rather than a KeyError later)."""
    by_kind: dict[PlacementKind, list[str]] = {kind: [] for kind in PlacementKind}
    for spec in specs:
        if spec.placement is not None:
            by_kind[spec.placement].append(spec.name)
    wrong = {kind.value: names for kind, names in by_kind.items() if len(names) != 1}
    if wrong:
        raise PhyscensisError(f"every placement kind needs exactly one predicate; these do not: {wrong}")
    return {spec.placement: spec for spec in specs if spec.placement is not None}


_BY_PLACEMENT = _one_predicate_per_placement(_SPECS)


def placement_spec(placement: PlacementKind) -> PredicateSpec:
    """The predicate that places an object this way (PLACE-ON for ON, ...)."""
    return _BY_PLACEMENT[placement]


def effect_spec(effect: Effect) -> PredicateSpec:
    """The one predicate with this effect (GROUP for GROUP, COPY-GROUP for COPY_GROUP); a clear error for an effect
    that several predicates, or none, have."""
    specs = [spec for spec in _SPECS if spec.effect is effect]
    if len(specs) != 1:
        raise PhyscensisError(f"effect {effect.value} has {len(specs)} predicates, not exactly one")
    return specs[0]


def placement_names(*, rank: int | None = None) -> list[str]:
    """Names of the placement predicates in registry order; only those of one `rank` when given."""
    return [
        spec.name for spec in _SPECS if spec.placement is not None and (rank is None or spec.placement.rank == rank)
    ]


def axis_rules() -> dict[Axis, list[str]]:
    """For each axis, the predicates (and "X with param" forms) that determine it, the placements that decide
    everything at once left out."""
    rules: dict[Axis, list[str]] = {axis: [] for axis in Axis}
    for spec in _SPECS:
        if spec.placement is not None and spec.placement.decides_everything:
            continue
        for axis in Axis:
            if axis in spec.determines:
                rules[axis].append(spec.name)
        for param, axis in spec.determines_when_given:
            rules[axis].append(f"{spec.name} with {param}")
    return rules


def complete_placements() -> list[str]:
    """Predicates that decide all four axes of their objects by themselves."""
    return [
        spec.name
        for spec in _SPECS
        if spec.placement is not None and spec.placement.decides_everything and spec.determines == ALL_AXES
    ]
