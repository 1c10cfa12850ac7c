"""The system prompt is generated from the registry, and the chat has the layout the loop expects."""

from __future__ import annotations

import json
import re
from dataclasses import replace

import pytest

from physcensis.agent.base import AgentContext, Round
from physcensis.agent.prompt import (
    ENRICH_INSTRUCTION,
    REPAIR_INSTRUCTION,
    WORKED_EXAMPLE,
    WORKED_EXAMPLE_SUPPORT,
    axis_rules,
    complete_placements,
    describe_support,
    messages,
    system_prompt,
)
from physcensis.program import check_program, parse_program
from physcensis.program.registry import ALL_AXES, PREDICATES, Axis, PlacementKind, placement_names, placement_spec
from physcensis.scene import Support

pytestmark = pytest.mark.timeout(30)


def _block(prompt: str, name: str) -> str:
    """The reference block of one predicate: from its heading line to the next blank line."""
    match = re.search(rf"^{re.escape(name)}: .*?(?=\n\n|\Z)", prompt, re.MULTILINE | re.DOTALL)
    assert match is not None, f"{name} has no block in the system prompt"
    return match.group(0)


def test_every_predicate_has_its_effect_parameters_and_example() -> None:
    prompt = system_prompt()
    for spec in PREDICATES.values():
        block = _block(prompt, spec.name)
        assert spec.formula in block
        assert json.dumps(list(spec.example)) in block
        for param in spec.params:
            line = next((ln for ln in block.splitlines() if ln.strip().startswith(f"- {param.name}:")), None)
            assert line is not None, f"{spec.name} does not list {param.name}"
            if param.low is not None and param.high is not None:
                assert "from " in line, line
            if param.default is not None:
                assert "default" in line, line
        if not spec.params:
            assert "parameters: none" in block


def test_each_predicate_is_listed_under_the_heading_of_its_effect() -> None:
    reference = system_prompt().split("# Predicates\n\n")[1].split("\n# ")[0]
    headings = re.findall(r"^## (.+)$", reference, re.MULTILINE)
    assert headings == list(dict.fromkeys(spec.section for spec in PREDICATES.values()))  # in registry order
    for spec in PREDICATES.values():
        before = reference[: reference.index(_block(reference, spec.name))]
        assert before.rsplit("## ", 1)[1].split("\n", 1)[0] == spec.section, spec.name


def test_parameter_defaults_and_ranges_are_the_registry_values() -> None:
    left_of = _block(system_prompt(), "LEFT-OF")
    distance = PREDICATES["LEFT-OF"].param("distance")
    assert distance is not None
    assert f"default {distance.default:g}" in left_of
    assert f"from {distance.low:g} to {distance.high:g}" in left_of
    assert "from -pi to pi" in _block(system_prompt(), "FACING-TO")


def test_fully_solved_rule_follows_the_registry() -> None:
    rules = axis_rules()
    for spec in PREDICATES.values():
        for axis in spec.determines:
            if spec.determines != ALL_AXES:
                assert spec.name in rules[axis]
        for param, axis in spec.determines_when_given:
            assert f"{spec.name} with {param}" in rules[axis]
    assert set(complete_placements()) == {placement_spec(k).name for k in PlacementKind if k.decides_everything}
    assert {"PLACE-ON", "PLACE-IN", "PLACE-ANYWHERE"} <= set(complete_placements())
    section = system_prompt().split("# Fully solved objects")[1].split("\n# ")[0]
    for axis in Axis:
        line = next(ln for ln in section.splitlines() if ln.startswith(f"- {axis.value} "))
        for name in rules[axis]:
            assert name in line


def test_conventions_ordering_naming_and_output_are_stated() -> None:
    prompt = system_prompt()
    for fact in ("front = +x", "back = -x", "left = +y", "right = -y", "metres", "radians", '"root"'):
        assert fact in prompt, fact
    order = prompt.split("# Order")[1]
    assert {"PLACE-ON", "PLACE-IN"} <= set(placement_names(rank=PlacementKind.ON.rank))
    assert "PLACE-ANYWHERE" in placement_names(rank=PlacementKind.ANYWHERE.rank)
    on_and_in = " and ".join(placement_names(rank=PlacementKind.ON.rank))  # PLACE-ON and PLACE-IN
    anywhere = " and ".join(placement_names(rank=PlacementKind.ANYWHERE.rank))
    assert order.index("2-D predicates") < order.index(on_and_in) < order.index(anywhere)
    assert "group_" in prompt and "plate_0-group_setting_1" in prompt and "1-64 characters" in prompt
    assert "JSON list" in prompt.split("# Output")[1]


def test_the_prompt_is_in_our_own_words() -> None:
    prompt = system_prompt().lower()
    for sentence in (
        "you are a helpful agent that helps placing a scene",
        "notes for the agent",
        "output must be a plain list of predicates",
    ):
        assert sentence not in prompt


def test_worked_example_checks_clean() -> None:
    program = parse_program([list(entry) for entry in WORKED_EXAMPLE])
    report = check_program(program, WORKED_EXAMPLE_SUPPORT)
    assert report.problems == (), report.feedback()


def test_worked_example_as_printed_in_the_prompt_parses_to_the_same_program() -> None:
    text = system_prompt().split("# Worked example")[1].split("\n# ")[0]
    printed = text[text.index("\n[") + 1 : text.index("\n]") + 2]
    assert json.loads(printed) == json.loads(json.dumps([list(e) for e in WORKED_EXAMPLE]))
    program = parse_program(printed)
    assert check_program(program, WORKED_EXAMPLE_SUPPORT).ok


def test_support_extent_is_given_in_metres_both_ways() -> None:
    text = describe_support(Support(kind="table", size=(0.7, 1.4)))
    assert "x from -0.35 to 0.35 m" in text and "y from -0.70 to 0.70 m" in text
    assert "table" in text and "0.75 m above the ground" in text
    assert "walls" in describe_support(Support(kind="box", size=(0.4, 0.3)))
    assert "shelf" in describe_support(Support(kind="shelf", size=(0.3, 1.0)))


def test_create_layout(desk_context: AgentContext) -> None:
    chat = messages(replace(desk_context, notes={"density": "as many as possible"}))
    assert [m["role"] for m in chat] == ["system", "user"]
    assert chat[0]["content"] == system_prompt()
    user = chat[1]["content"]
    assert '"a small desk with a laptop and a mug"' in user
    assert "x from -0.35 to 0.35 m" in user
    assert "laptop, mug, notebook, pen" in user
    assert user.endswith("Notes for this request: density: as many as possible.")


def test_repair_layout(desk_context: AgentContext) -> None:
    context = replace(
        desk_context,
        request="repair",
        history=(Round('[["mug_0", "a mug"]]', "error at #1 mug_0: mug_0 has no predicates"),),
    )
    chat = messages(context)
    assert [m["role"] for m in chat] == ["system", "user", "assistant", "user"]
    assert chat[2]["content"] == '[["mug_0", "a mug"]]'
    assert "mug_0 has no predicates" in chat[3]["content"]
    assert chat[3]["content"].endswith(REPAIR_INSTRUCTION)


def test_enrich_after_repair_layout(desk_context: AgentContext) -> None:
    history = (
        Round("not a program", "the reply holds no program list", ok=False),
        Round('[["cup_0", "a cup"]]', "every object was placed; empty region at the back left", ok=True),
    )
    chat = messages(replace(desk_context, request="enrich", history=history))
    assert [m["role"] for m in chat] == ["system", "user", "assistant", "user", "assistant", "user"]
    assert chat[2]["content"] == "not a program"
    assert "holds no program" in chat[3]["content"] and chat[3]["content"].endswith(REPAIR_INSTRUCTION)
    assert "empty region at the back left" in chat[5]["content"]
    assert chat[5]["content"].endswith(ENRICH_INSTRUCTION)
    noted = messages(replace(desk_context, request="enrich", history=history, notes={"density": "high", "x": ""}))
    assert noted[5]["content"].endswith(ENRICH_INSTRUCTION + "\nNotes for this request: density: high.")
    assert "Notes" not in noted[1]["content"]
    assert "around the existing ones" in ENRICH_INSTRUCTION and "whole program" in ENRICH_INSTRUCTION


def test_empty_reply_still_makes_a_valid_assistant_turn(desk_context: AgentContext) -> None:
    chat = messages(replace(desk_context, request="repair", history=(Round("", "no program"),)))
    assert chat[2]["content"]
