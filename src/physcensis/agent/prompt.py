"""The LLM agent's conversation: a system prompt generated from the predicate registry, and the chat layout.

Everything the prompt says about predicates (names, effects, parameters,
defaults, ranges, examples, which axes each one determines, the order they
must come in) is read from `program.registry`, so the prompt cannot disagree
with the parser, the checker or the solvers.
"""

from __future__ import annotations

import functools
import json
import math
from collections.abc import Iterable
from typing import Any

from physcensis.agent.base import AgentContext, Round
from physcensis.assets.supports import SHELF_BOARD, SHELF_SPACING, box_wall_height
from physcensis.ids import GROUP_PREFIX, ID_RULE, PIN_PREFIX, ROOT_ID, copy_member_id
from physcensis.program.registry import (
    AXIS_WORDS,
    PREDICATES,
    STABILITY_WORDS,
    Axis,
    Effect,
    ParamSpec,
    ParamType,
    PlacementKind,
    PredicateSpec,
    Role,
    Solver,
    axis_rules,
    complete_placements,
    effect_spec,
    placement_names,
    placement_spec,
)
from physcensis.program.schema import object_form
from physcensis.scene import Support

# A small desk, 0.7 m deep (x) and 1.4 m wide (y); tests check that it passes `check_program`.
WORKED_EXAMPLE_SUPPORT = Support(kind="table", size=(0.7, 1.4))
WORKED_EXAMPLE_PROMPT = "a tidy home-office desk"
WORKED_EXAMPLE: tuple[tuple[Any, ...], ...] = (
    ("monitor_0", "a 24 inch computer monitor on a stand"),
    ("monitor_0", "PLACE-ON-BASE", "root", {"x": -0.2, "y": 0.0}),
    ("monitor_0", "FACING-FRONT", "root", {}),
    ("keyboard_0", "a slim black computer keyboard"),
    ("keyboard_0", "PLACE-ON-BASE", "root", {}),
    ("keyboard_0", "FRONT-OF", "monitor_0", {"distance": 0.1}),
    ("keyboard_0", "ALIGN-CENTER-LR", "monitor_0", {}),
    ("keyboard_0", "FACING-SAME-AS", "monitor_0", {}),
    ("mouse_0", "a wireless computer mouse"),
    ("mouse_0", "PLACE-ON-BASE", "root", {}),
    ("mouse_0", "LEFT-OF", "keyboard_0", {"distance": 0.05}),
    ("mouse_0", "ALIGN-CENTER-FB", "keyboard_0", {}),
    ("mouse_0", "FACING-SAME-AS", "keyboard_0", {}),
    ("notebook_0", "a spiral notebook with lined pages"),
    ("notebook_0", "PLACE-ON-BASE", "root", {}),
    ("notebook_0", "RIGHT-OF", "keyboard_0", {"distance": 0.08}),
    ("notebook_0", "ALIGN-CENTER-FB", "keyboard_0", {}),
    ("notebook_0", "RANDOM-ROT", "root", {}),
    ("book_0", "a thick hardcover book lying flat"),
    ("book_0", "PLACE-ON-BASE", "root", {}),
    ("book_0", "LEFT-OF", "monitor_0", {"distance": 0.12}),
    ("book_0", "ALIGN-BACK", "monitor_0", {}),
    ("book_0", "FACING-FRONT", "root", {}),
    ("pen_holder_0", "a round metal pen holder"),
    ("pen_holder_0", "PLACE-ON-BASE", "root", {}),
    ("pen_holder_0", "SYMMETRY-ALONG", "book_0", {"C": "monitor_0"}),
    ("pen_holder_0", "FACING-FRONT", "root", {}),
    ("book_1", "a paperback novel"),
    ("book_1", "PLACE-ON", "book_0", {"overlap": 0.9}),
    ("mug_0", "a white ceramic coffee mug"),
    ("mug_0", "PLACE-ON", "notebook_0", {"overlap": 1.0}),
    ("mug_0", "FACING-LEFT", "root", {}),
    ([["pen", 3], ["pencil", 2]], "PLACE-IN", "pen_holder_0", {}),
    ("plant_0", "a small potted plant"),
    ("plant_0", "PLACE-ANYWHERE", "root", {}),
)

_ROLE_WORDS: dict[Role, str] = {
    Role.OBJECT: "an object",
    Role.GROUP: "a group",
    Role.ROOT: f'"{ROOT_ID}"',
    Role.NEW_GROUP: f"a new group id starting with {GROUP_PREFIX}",
    Role.MEMBERS: "a list of ids of objects introduced earlier",
    Role.ITEMS: "an object id, a list of object ids, or a list of [category, count] pairs",
}
_UNIT_WORDS = {"m": "metres", "rad": "radians"}

REPAIR_INSTRUCTION = (
    "The program above did not fully work; the feedback lists what went wrong. Write the whole program "
    "again with those problems fixed. Keep the objects and relations that worked as they were, change only "
    "what the feedback points at, and answer with the JSON list alone."
)
ENRICH_INSTRUCTION = (
    "The scene above was built successfully. Make it richer: add more objects that belong in this scene, "
    "placed around the existing ones (the empty regions named in the feedback are good places). Keep every "
    "existing entry unchanged and write the whole program again, old entries and new ones, as one JSON list "
    "and nothing else."
)
CREATE_INSTRUCTION = "Write a new program for the scene from scratch, as one JSON list and nothing else."
REVISE_INSTRUCTION = (
    "The scene above was built, but a vision model looking at its picture doubts that it shows the request (see the "
    "feedback). Write the whole program again so the scene plainly shows what was asked for: add, remove, move or "
    "change objects and relations as needed, and answer with the JSON list alone."
)
_INSTRUCTIONS = {
    "repair": REPAIR_INSTRUCTION,
    "enrich": ENRICH_INSTRUCTION,
    "create": CREATE_INSTRUCTION,
    "revise": REVISE_INSTRUCTION,
}


def _json(value: Any) -> str:
    return json.dumps(value, ensure_ascii=False)


def _number(value: float) -> str:
    """A number as the prompt writes it: pi multiples by name, others plainly."""
    for multiple, word in ((1.0, "pi"), (-1.0, "-pi"), (0.5, "pi/2"), (-0.5, "-pi/2")):
        if math.isclose(value, multiple * math.pi):
            return word
    return f"{value:g}"


def _roles(roles: frozenset[Role]) -> str:
    order = (Role.OBJECT, Role.GROUP, Role.ROOT, Role.NEW_GROUP, Role.MEMBERS, Role.ITEMS)
    words = [_ROLE_WORDS[r] for r in order if r in roles]
    return words[0] if len(words) == 1 else f"{', '.join(words[:-1])} or {words[-1]}"


def _param_type(param: ParamSpec) -> str:
    if param.type is ParamType.NUMBER:
        unit = _UNIT_WORDS.get(param.unit, param.unit)
        return f"number ({unit})" if unit else "number"
    if param.type is ParamType.REFERENCE:
        return f'id of an object, a group or "{ROOT_ID}"'
    if param.type is ParamType.OBJECT:
        return "id of an object"
    if param.type is ParamType.STABILITY:
        words = " or ".join(f'"{w}"' for w in STABILITY_WORDS)
        return f"{words}, or a probability of falling between 0 and 1"
    if param.type is ParamType.BOOL:
        return "true or false"
    return str(param.type)


def _param_line(param: ParamSpec) -> str:
    facts = [_param_type(param)]
    if param.required:
        facts.append("required")
    elif param.default is not None:
        default = param.default
        facts.append(f"default {_number(default) if isinstance(default, float) else _json(default)}")
    else:
        facts.append("optional")
    if param.low is not None and param.high is not None:
        facts.append(f"from {_number(param.low)} to {_number(param.high)}")
    if param.bounded_by_support:
        facts.append(f"must lie on the support along {param.bounded_by_support}")
    if param.optimisable:
        facts.append("the solver fine-tunes it")
    return f"    - {param.name}: {'; '.join(facts)}. {param.description[:1].upper()}{param.description[1:]}."


def _slots(spec: PredicateSpec) -> tuple[str, str]:
    """How the predicate's first and third elements are called in the prompt."""
    subject = "group_name" if Role.NEW_GROUP in spec.subject else ("items" if Role.ITEMS in spec.subject else "A")
    target = "[members]" if Role.MEMBERS in spec.target else "B"
    return subject, target


def _predicate_block(spec: PredicateSpec) -> str:
    subject, target = _slots(spec)
    lines = [
        f"{spec.name}: {spec.summary}.",
        f'  usage: [{subject}, "{spec.name}", {target}, {{params}}]',
        f"  {subject} is {_roles(spec.subject)}; {target} is {_roles(spec.target)}.",
    ]
    lines.append(f"  effect: {spec.formula}")
    if spec.params:
        lines.append("  parameters:")
        lines.extend(_param_line(p) for p in spec.params)
    else:
        lines.append("  parameters: none (write {})")
    lines.append(f"  example: {_json(list(spec.example))}")
    return "\n".join(lines)


def _predicate_reference(specs: Iterable[PredicateSpec]) -> str:
    """One section per heading of the registry, in the order their first predicates come."""
    by_section: dict[str, list[PredicateSpec]] = {}
    for spec in specs:
        by_section.setdefault(spec.section, []).append(spec)
    return "\n\n".join(
        f"## {title}\n\n" + "\n\n".join(_predicate_block(s) for s in members) for title, members in by_section.items()
    )


def _fully_solved_rule() -> str:
    rules = axis_rules()
    lines = [
        "An object is fully solved when each of these four is determined by at least one of its predicates:",
    ]
    for axis in Axis:
        lines.append(f"- {AXIS_WORDS[axis]}: {', '.join(rules[axis])}")
    complete = ", ".join(complete_placements())
    position = ", ".join(s.name for s in PREDICATES.values() if s.sets_position)
    lines += [
        f"{complete} decide all four at once. Do not combine them with position predicates ({position}); "
        "a turning predicate may still be added to choose the object's yaw.",
        f"Every object takes exactly one of {', '.join(placement_names())}.",
        f"{placement_spec(PlacementKind.BASE).name} without x and y only fixes the height: give the object's x and y "
        "with other predicates (or both parameters).",
        f"The copies made by {effect_spec(Effect.COPY_GROUP).name} are solved as their originals were; move and turn "
        "the new group as a whole.",
        "When a later predicate sets an axis that was already set, it overrides the earlier one.",
    ]
    return "\n".join(lines)


def _ordering_rule() -> str:
    on_in = " and ".join(placement_names(rank=1))
    anywhere = " and ".join(placement_names(rank=2))
    return "\n".join(
        [
            "- Declare an object before any predicate about it, and keep all of one object's entries together.",
            f'- A predicate may refer only to "{ROOT_ID}" or to objects and groups introduced earlier in the list.',
            "- Order the program in three parts: first the objects placed by 2-D predicates (and groups of them), "
            f"then the objects placed by {on_in} (and any predicate about them), "
            f"and last the objects placed by {anywhere}.",
            "- Make a group only after its members are placed; then copy it and place the copy with 2-D predicates.",
            f"- Fill a container with one {placement_spec(PlacementKind.IN).name} entry that lists everything going "
            "into it.",
        ]
    )


def _naming_rule() -> str:
    copy_group = effect_spec(Effect.COPY_GROUP).name
    copy_example = copy_member_id("plate_0", f"{GROUP_PREFIX}setting_1")
    return "\n".join(
        [
            f"- Ids are {ID_RULE}; name objects category_identifier, like cup_0, cup_1 or candle_front.",
            f'- "{ROOT_ID}" is the support and is never declared.',
            f"- Group ids start with {GROUP_PREFIX} (e.g. {GROUP_PREFIX}setting_0) and are never declared with a "
            "description; objects never start with it.",
            f"- {copy_group} names each copy member-newgroup: copying plate_0 into {GROUP_PREFIX}setting_1 makes "
            f"{copy_example}. Refer to copies by these names.",
            "- Use each id once: a new object needs a fresh id.",
        ]
    )


def _conventions() -> str:
    return "\n".join(
        [
            "- Units: metres for lengths and distances, radians for angles.",
            f'- "{ROOT_ID}" is the support (a table top, a shelf board, the floor of a box, or the floor). Its top is '
            "centred on x = 0, y = 0; the user message gives its x and y ranges. Keep every object inside them.",
            "- Directions on the support: front = +x, back = -x, left = +y, right = -y (the sides of a thing that "
            "faces +x). The user looks at the scene from the front (+x), so the user's left and right are mirrored: "
            '"to the left of X" as the user says it is RIGHT-OF X, "to the right of X" is LEFT-OF X; "in front of X" '
            'is FRONT-OF X (towards the user) and "behind X" is BACK-OF X.',
            "- Every object's own front faces +x when its yaw is 0. Yaw turns counter-clockwise seen from above: "
            "pi/2 faces left (+y), pi faces back (-x), -pi/2 faces right (-y).",
            "- Each object has an axis-aligned box around its turned footprint: min_x is its back edge, max_x its "
            "front edge, min_y its right edge, max_y its left edge; center_x and center_y are the box's centre.",
            "- Predicates run in list order. Each one updates A's box or yaw, and later predicates see the update.",
            "- Distances and positions need only be roughly right: the solver fine-tunes the parameters marked so, "
            "to keep objects apart and on the support.",
        ]
    )


def _program_format() -> str:
    return "\n".join(
        [
            "A program is a JSON list of entries of two shapes:",
            '- a declaration, ["object_id", "one sentence describing the object"]: the sentence is used to find '
            "a 3D asset, so say what it is, its size, material and colour where they matter;",
            '- a predicate, [A, "PREDICATE", B, {params}]: relates A to B. Write {} when there are no parameters.',
        ]
    )


def _output_format() -> str:
    return "\n".join(
        [
            "Answer with the program and nothing else: a single JSON list of entries, with double-quoted strings, "
            "commas between entries, no comments and no explanation before or after it.",
            "Every round, write the whole program again, not only the changes.",
        ]
    )


def _worked_example() -> str:
    x, y = (s / 2 for s in WORKED_EXAMPLE_SUPPORT.size)
    body = ",\n".join(f"  {_json(list(entry))}" for entry in WORKED_EXAMPLE)
    return (
        f'For "{WORKED_EXAMPLE_PROMPT}" on a {WORKED_EXAMPLE_SUPPORT.kind} whose top spans x from {-x:g} to {x:g} '
        f"and y from {-y:g} to {y:g}:\n[\n{body}\n]\n"
        "The monitor stands at the back, the keyboard in front of it and the mouse to its right as the user sees "
        "it (LEFT-OF), the notebook to its left (RIGHT-OF); the book and "
        "the pen holder mirror each other about the monitor; a second book lies on the first, the mug stands on "
        "the notebook, pens and pencils go into the holder, and the plant takes any free spot."
    )


@functools.cache
def system_prompt(structured: bool = False) -> str:
    """The system message: conventions, every predicate, the rules and an example, all from the registry; with
    `structured`, the output section asks for the object form the server's JSON Schema enforces."""
    sections = [
        "You arrange objects into a physically valid scene by writing a predicate program. You choose the "
        "objects that suit the request, describe each in one sentence, and relate them with predicates; a solver "
        "turns the program into a 3D scene and a physics engine checks that everything rests where it should. "
        "After each attempt you receive feedback: problems to fix, or a successful result with a request to add "
        "more objects.",
        "# Conventions\n\n" + _conventions(),
        "# Program format\n\n" + _program_format(),
        "# Predicates\n\n" + _predicate_reference(PREDICATES.values()),
        "# Fully solved objects\n\n" + _fully_solved_rule(),
        "# Order\n\n" + _ordering_rule(),
        "# Names\n\n" + _naming_rule(),
        "# Worked example\n\n" + _worked_example(),
        "# Output\n\n" + (object_form_instructions() if structured else _output_format()),
    ]
    return "\n\n".join(sections) + "\n"


# -- the compact system prompt, for small and local models -------------------------------------------------------

PROMPT_STYLES = ("full", "compact")
COMPACT_MAX_TOKENS = 1_500

# A small table, 0.6 m deep (x) and 0.8 m wide (y); tests check that it passes `check_program`.
COMPACT_EXAMPLE_SUPPORT = Support(kind="table", size=(0.6, 0.8))
COMPACT_EXAMPLE_PROMPT = "a laptop workspace"
COMPACT_EXAMPLE: tuple[tuple[Any, ...], ...] = (
    ("laptop_0", "a silver laptop, open"),
    ("laptop_0", "PLACE-ON-BASE", "root", {"x": -0.1, "y": 0.0}),
    ("laptop_0", "FACING-FRONT", "root", {}),
    ("mug_0", "a white ceramic mug"),
    ("mug_0", "PLACE-ON-BASE", "root", {}),
    ("mug_0", "RIGHT-OF", "laptop_0", {"distance": 0.08}),
    ("mug_0", "ALIGN-CENTER-FB", "laptop_0", {}),
    ("mug_0", "FACING-SAME-AS", "laptop_0", {}),
    ("book_0", "a red hardcover book lying flat"),
    ("book_0", "PLACE-ON-BASE", "root", {}),
    ("book_0", "LEFT-OF", "laptop_0", {"distance": 0.08}),
    ("book_0", "ALIGN-BACK", "laptop_0", {}),
    ("book_0", "RANDOM-ROT", "root", {}),
    ("notebook_0", "a small spiral notebook"),
    ("notebook_0", "PLACE-ON", "book_0", {"overlap": 0.9}),
    ("pen_0", "a blue ballpoint pen"),
    ("pen_0", "PLACE-ANYWHERE", "root", {}),
)


def estimate_tokens(text: str) -> int:
    """A tokenizer-free token count that over-counts BPE tokenizers on this kind of text (English, JSON, names).

    max(characters / 3.2, words * 1.4): for the full system prompt it gives about 5,420 where Qwen2.5's tokenizer
    counted 5,400 (issue 21), so a prompt within a budget by this estimate is within it for real.
    """
    return math.ceil(max(len(text) / 3.2, len(text.split()) * 1.4))


def _compact_param(param: ParamSpec) -> str:
    if param.bounded_by_support:
        words = f"inside the support's {param.bounded_by_support} range"
    elif param.type is ParamType.NUMBER and param.low is not None and param.high is not None:
        words = f"{_number(param.low)}..{_number(param.high)}"
    elif param.type is ParamType.STABILITY:
        words = " | ".join(f'"{w}"' for w in STABILITY_WORDS) + " | 0..1"
    elif param.type is ParamType.BOOL:
        words = "true | false"
    elif param.type in (ParamType.REFERENCE, ParamType.OBJECT):
        words = "id"
    else:
        words = str(param.type)
    if param.required:
        words += ", required"
    elif param.default is not None:
        default = param.default
        words += f", default {_number(default) if isinstance(default, float) else _json(default)}"
    return f"{param.name}: {words}"


def _shared_params() -> list[ParamSpec]:
    """Parameters that several predicates take unchanged (distance, yaw_offset, messy): described once."""
    uses: dict[ParamSpec, int] = {}
    for spec in PREDICATES.values():
        for param in spec.params:
            uses[param] = uses.get(param, 0) + 1
    return [param for param, count in uses.items() if count > 1]


def _compact_predicates() -> str:
    shared = _shared_params()
    lines = [_compact_line(spec, shared) for spec in PREDICATES.values()]
    if shared:
        lines.append("Shared parameters: " + "; ".join(_compact_param(p) for p in shared))
    return "\n".join(lines)


def _compact_line(spec: PredicateSpec, shared: list[ParamSpec]) -> str:
    """One predicate in one line: its shape when not [A, B], its parameters with ranges (shared ones by name), and
    its formula."""
    subject, target = _slots(spec)
    if spec.target == frozenset({Role.ROOT}):
        target = f'"{ROOT_ID}"'
    shape = "" if (subject, target) == ("A", "B") else f" [{subject}, {target}]"
    params = "; ".join(p.name if p in shared else _compact_param(p) for p in spec.params)
    return f"- {spec.name}{shape} {{{params}}}: {spec.formula}"


def _compact_rules() -> str:
    base = placement_spec(PlacementKind.BASE).name
    complete = ", ".join(complete_placements())
    on_in = " and ".join(placement_names(rank=1))
    anywhere = " and ".join(placement_names(rank=2))
    copy_group = effect_spec(Effect.COPY_GROUP).name
    return "\n".join(
        [
            f"- Every object takes exactly one of {', '.join(placement_names())}.",
            f"- {base} fixes only the height: also set x and y (its x, y or predicates like LEFT-OF, ALIGN-*) "
            "and a yaw (FACING-*, RANDOM-ROT).",
            f"- {complete} set everything: add no position predicates to those objects.",
            f'- Declare an object before using it; refer only to "{ROOT_ID}" or ids introduced earlier. '
            "Keep an object's entries together.",
            f"- Order: objects placed by 2-D predicates first, then {on_in}, then {anywhere}.",
            f"- Ids: {ID_RULE}, like cup_0; each id once. Groups start with {GROUP_PREFIX}; {copy_group} names "
            f"copies member-newgroup ({copy_member_id('plate_0', f'{GROUP_PREFIX}setting_1')}).",
        ]
    )


def _compact_conventions() -> str:
    return "\n".join(
        [
            f'- Metres and radians. "{ROOT_ID}" is the support; its top is centred on x = 0, y = 0, and the user '
            "message gives its ranges: keep objects inside.",
            "- front = +x, back = -x, left = +y, right = -y; the user is at +x: their left is RIGHT-OF. Yaw 0 "
            "faces +x.",
            "- Each object has a box: min_x back edge, max_x front edge, min_y right edge, max_y left edge. "
            "Predicates run in order; later ones see the update.",
        ]
    )


def _compact_example() -> str:
    x, y = (s / 2 for s in COMPACT_EXAMPLE_SUPPORT.size)
    body = ",\n".join(_json(list(entry)) for entry in COMPACT_EXAMPLE)
    return (
        f'"{COMPACT_EXAMPLE_PROMPT}" on a {COMPACT_EXAMPLE_SUPPORT.kind}, x from {-x:g} to {x:g}, '
        f"y from {-y:g} to {y:g}:\n[\n{body}\n]"
    )


# The compact example in the guided form (program/schema.py): what a small model writes when the server enforces
# the guided schema. Tests check that it is valid under the schema on COMPACT_EXAMPLE_SUPPORT and passes the checker.
def _standing(oid: str, what: str, xy: tuple[float, float], facing: Any, relations: list[Any]) -> dict[str, Any]:
    params = {"x": xy[0], "y": xy[1]}
    place = {"predicate": placement_spec(PlacementKind.BASE).name, "target": ROOT_ID, "params": params}
    return {"id": oid, "description": what, "place": place, "facing": facing, "relations": relations}


def _bare(name: str, target: str, **params: Any) -> dict[str, Any]:
    spec = PREDICATES[name]
    return {"predicate": name, "target": target, "params": {p.name: params.get(p.name) for p in spec.params}}


GUIDED_EXAMPLE: dict[str, Any] = {
    "objects": [
        _standing("laptop_0", "a silver laptop, open", (-0.1, 0.0), _bare("FACING-FRONT", ROOT_ID), []),
        _standing(
            "mug_0",
            "a white ceramic mug",
            (-0.1, -0.25),
            _bare("FACING-SAME-AS", "laptop_0"),
            [_bare("RIGHT-OF", "laptop_0", distance=0.08)],
        ),
        _standing("book_0", "a red hardcover book lying flat", (0.1, 0.25), _bare("RANDOM-ROT", ROOT_ID), []),
        {
            "id": "notebook_0",
            "description": "a small spiral notebook",
            "place": _bare("PLACE-ON", "book_0", overlap=0.9),
        },
        {"id": "pen_0", "description": "a blue ballpoint pen", "place": _bare("PLACE-ANYWHERE", ROOT_ID)},
    ]
}


def _guided_format() -> str:
    base = placement_spec(PlacementKind.BASE).name
    on, into, anywhere = (placement_spec(k).name for k in (PlacementKind.ON, PlacementKind.IN, PlacementKind.ANYWHERE))
    return "\n".join(
        [
            '- One JSON object {"objects": [...]} with one entry per object: {"id", "description": "one sentence: '
            'what it is, size, material, colour", "place": how it is placed, ...}.',
            f'- Standing on the support: "place" is {{"predicate": "{base}", "target": "{ROOT_ID}", "params": '
            '{"x", "y"}} (its centre, inside the support), "facing" is one turning predicate, and "relations" '
            "lists 2-D predicates to other objects ([] when none); a relation that sets x or y replaces that number.",
            f'- On another object: "place" is {on} with that object as "target"; inside a container: {into}; '
            f'anywhere with room: {anywhere} on "{ROOT_ID}". These need nothing else.',
            '- "params" holds every parameter of the predicate, null when not set. A is the object, B the "target".',
        ]
    )


def _guided_predicates() -> str:
    """The predicates the guided form uses (no groups), one line each, PLACE-IN with one object as its subject."""
    shared = _shared_params()
    lines = []
    for spec in PREDICATES.values():
        if spec.solver is Solver.GROUP:
            continue
        if Role.ITEMS in spec.subject:
            lines.append(f"- {spec.name} {{}}: A ends inside container B")
        else:
            lines.append(_compact_line(spec, shared))
    lines.append("Shared parameters: " + "; ".join(_compact_param(p) for p in shared))
    return "\n".join(lines)


def _guided_rules() -> str:
    on = placement_spec(PlacementKind.ON).name
    return "\n".join(
        [
            "- One entry for every object the description asks for: five books are five entries.",
            f'- The support (the table, shelf, box or floor) is "{ROOT_ID}", never an object of its own.',
            f'- A "target" is "{ROOT_ID}" or an object listed before this one, never the object itself.',
            f"- A stack: the bottom object stands on the support, each one above is {on} the one below it.",
            f"- Ids: {ID_RULE}, like cup_0; each id once.",
        ]
    )


@functools.cache
def guided_system_prompt() -> str:
    """The compact system message when the server enforces the guided schema: the guided form instead of the list,
    its predicates and rules, and the example in that form."""
    x, y = (s / 2 for s in COMPACT_EXAMPLE_SUPPORT.size)
    example = "\n".join(json.dumps(o, separators=(",", ":")) for o in GUIDED_EXAMPLE["objects"])
    sections = [
        "You write a program that a solver turns into a physically valid 3D scene. After each attempt you get "
        "feedback: fix the problems, or add objects when asked.",
        "# Format\n\n" + _guided_format(),
        "# Coordinates\n\n" + _compact_conventions(),
        "# Predicates\n\n" + _guided_predicates(),
        "# Rules\n\n" + _guided_rules(),
        f'# Example\n\n"{COMPACT_EXAMPLE_PROMPT}" on a {COMPACT_EXAMPLE_SUPPORT.kind}, x from {-x:g} to {x:g}, '
        f'y from {-y:g} to {y:g}:\n{{"objects": [\n{example.replace(chr(10), "," + chr(10))}\n]}}',
        "# Output\n\nOnly the JSON object, no other text. Every round, write the whole program again.",
    ]
    return "\n\n".join(sections) + "\n"


@functools.cache
def compact_system_prompt(structured: bool = False) -> str:
    """The system message for small models: each predicate in one line, the rules, one short example; with
    `structured`, the guided form the server enforces (`guided_system_prompt`)."""
    if structured:
        return guided_system_prompt()
    sections = [
        "You write a predicate program that a solver turns into a physically valid 3D scene. After each attempt "
        "you get feedback: fix the problems, or add objects when asked.",
        "# Format\n\n"
        '- A JSON list. Declare an object: ["id", "one sentence: what it is, size, material, colour"].\n'
        '- Relate it: [A, "PREDICATE", B, {params}], {} when none. Parameters are optional unless marked.',
        "# Coordinates\n\n" + _compact_conventions(),
        "# Predicates\n\n" + _compact_predicates(),
        "# Rules\n\n" + _compact_rules(),
        "# Example\n\n" + _compact_example(),
        "# Output\n\nOnly the JSON list, no other text. Every round, write the whole program again.",
    ]
    return "\n\n".join(sections) + "\n"


def system_prompt_for(style: str, structured: bool = False) -> str:
    """The system message of a prompt style ("full" or "compact"), asking for the object form when `structured`."""
    if style not in PROMPT_STYLES:
        raise ValueError(f"unknown prompt style {style!r}; choose one of {', '.join(PROMPT_STYLES)}")
    return compact_system_prompt(structured) if style == "compact" else system_prompt(structured)


# -- the object form, when the server enforces the program's JSON Schema ------------------------------------------

_OBJECT_FORM_EXAMPLE = [
    ["cup_0", "a white mug"],
    ["cup_0", "PLACE-ON-BASE", "root", {"x": 0.1, "y": 0.0}],
    ["cup_0", "FACING-FRONT", "root", {}],
]


def object_form_instructions() -> str:
    """The output section when the server enforces the program's JSON Schema: the object form, by example."""
    example = json.dumps(object_form(_OBJECT_FORM_EXAMPLE), separators=(",", ":"))
    return (
        'Only ONE JSON object, not the list: declarations go to "objects" as {"id", "description"}, entries to '
        '"relations" as {"subject", "predicate", "target", "params"} (PLACE-IN counts as {"category", "count"}); '
        "every parameter of the predicate, null when not set. Write the whole program every round. "
        f"Example:\n{example}"
    )


def describe_support(support: Support) -> str:
    """The support's kind, height and x/y extent in words for the first user message."""
    x, y = (s / 2 for s in support.size)
    kind = {
        "table": "a table top",
        "shelf": (
            f"a shelf board, open at the front (+x) with a back panel at -x; the next board is "
            f"{SHELF_SPACING - SHELF_BOARD:.2f} m above it, so nothing taller fits"
        ),
        "box": f"the inside floor of an open box whose walls are {box_wall_height(support):.2f} m high",
        "floor": "an area of floor",
    }[support.kind]
    return (
        f'The support ("{ROOT_ID}") is {kind}, {support.top_height:.2f} m above the ground. '
        f"Its top spans x from {-x:.2f} to {x:.2f} m (back to front) and y from {-y:.2f} to {y:.2f} m "
        f"(right to left), {support.size[0]:.2f} m deep and {support.size[1]:.2f} m wide."
    )


def first_user_message(context: AgentContext, categories: bool = True, hint: str = "") -> str:
    """The support, the catalogue's categories (unless `categories` is False: small models copy the list into the
    scene), the offline reading's draft objects (`hint`, agent/hint.py), then the description last, nearest the
    reply."""
    parts = [describe_support(context.support)]
    if context.vocabulary and categories:
        parts.append(
            "Object categories the asset catalogue has (prefer them; other objects are approximated): "
            + ", ".join(sorted(set(context.vocabulary)))
            + "."
        )
    if context.own_assets:
        parts.append(own_assets_line(context.own_assets))
    if hint:
        parts.append(hint)
    parts.append(f'The scene description is: "{context.prompt}". Write the program for it.')
    return "\n".join(parts)


MAX_OWN_ASSETS_LISTED = 100  # a library of thousands is found by description; the list is for the user's few


def own_assets_line(assets: tuple[tuple[str, str], ...]) -> str:
    """The user's own assets, and how to pin one: an object whose description is "asset:ID" gets exactly that one."""
    shown = ", ".join(f"{asset_id} ({description})" for asset_id, description in assets[:MAX_OWN_ASSETS_LISTED])
    more = len(assets) - MAX_OWN_ASSETS_LISTED
    return (
        f"The user's own assets (to use one exactly, write the object's description as \"{PIN_PREFIX}ID\"): {shown}"
        + (f" and {more} more (describe them in words)." if more > 0 else ".")
    )


def notes_line(notes: dict[str, str]) -> str:
    """The request's notes (e.g. density wishes) as one line; empty values are left out."""
    items = [f"{key}: {value}" for key, value in notes.items() if str(value).strip()]
    return "Notes for this request: " + "; ".join(items) + "." if items else ""


# What one round may add to the conversation, and what all rounds together may take: a runaway reply must not
# make every later request huge. The system prompt and the scene request are always sent whole.
HISTORY_REPLY_CHARS = 16_000
HISTORY_FEEDBACK_CHARS = 16_000
HISTORY_ROUNDS_CHARS = 64_000
_CUT_NOTE_CHARS = 120  # room kept for the note that says where and how much was cut


def clip_text(text: str, limit: int, what: str = "reply") -> str:
    """`text` if it has at most `limit` characters, else its start and a note saying it was cut and how long it
    was; the result never exceeds `limit`, so clipping again changes nothing."""
    if len(text) <= limit:
        return text
    keep = max(0, limit - _CUT_NOTE_CHARS)
    return f"{text[:keep]}\n[... cut here: the {what} was {len(text)} characters long; only the first {keep} are kept]"


def feedback_message(round_: Round, request: str) -> str:
    """The user turn after an assistant's program: its feedback and what to do next."""
    feedback = clip_text(round_.feedback.strip(), HISTORY_FEEDBACK_CHARS, "feedback") or "(no feedback)"
    instruction = _INSTRUCTIONS.get(request, REPAIR_INSTRUCTION)
    return f"Feedback on your program:\n{feedback}\n\n{instruction}"


def _round_turns(context: AgentContext) -> list[tuple[dict[str, str], dict[str, str]]]:
    """One (assistant program, user feedback) pair per round, each within its caps."""
    last = len(context.history) - 1
    turns = []
    for i, round_ in enumerate(context.history):
        request = context.request if i == last else ("enrich" if round_.ok else "repair")
        program = clip_text(round_.program_text.strip(), HISTORY_REPLY_CHARS, "reply") or "(no output)"
        turns.append(
            ({"role": "assistant", "content": program}, {"role": "user", "content": feedback_message(round_, request)})
        )
    return turns


def _latest_within_budget(turns: list[tuple[dict[str, str], dict[str, str]]]) -> int:
    """How many of the latest rounds fit in `HISTORY_ROUNDS_CHARS` (always at least the last one)."""
    total, kept = 0, 0
    for program, feedback in reversed(turns):
        total += len(program["content"]) + len(feedback["content"])
        if kept and total > HISTORY_ROUNDS_CHARS:
            break
        kept += 1
    return kept


def messages(
    context: AgentContext, style: str = "full", structured: bool = False, hint: str = ""
) -> list[dict[str, str]]:
    """The chat for one request: system (the `style` of system prompt, asking for the object form when
    `structured`), the scene request (with the offline reading's draft, `hint`), then one (program, feedback) pair
    per round.

    The instruction after each round's feedback is what was asked next: the current request after the
    last round, and repair or enrich (by whether the round succeeded) after earlier ones. Each reply and
    feedback is cut to its cap, and only the latest rounds that fit the total budget are sent.
    """
    turns = _round_turns(context)
    kept = _latest_within_budget(turns)
    request = first_user_message(context, categories=style != "compact", hint=hint)
    if kept < len(turns):
        left_out = len(turns) - kept
        request += (
            f"\n(The first {left_out} of {len(turns)} earlier attempts are left out to keep this "
            "conversation short; the latest ones follow.)"
        )
    chat = [
        {"role": "system", "content": system_prompt_for(style, structured)},
        {"role": "user", "content": request},
    ]
    for program, feedback in turns[len(turns) - kept :]:
        chat += [program, feedback]
    notes = notes_line(context.notes)
    if notes:  # they belong to the current request, so they go into the last user turn
        chat[-1] = {"role": "user", "content": f"{chat[-1]['content']}\n{notes}"}
    return chat
