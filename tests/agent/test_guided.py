"""The guided two-step form for small models: its schemas, the claim that what they accept checks clean, and the two
requests of a round against the fake server."""

from __future__ import annotations

import json
import random
from collections.abc import Callable
from typing import Any

import jsonschema
import pytest

from physcensis.agent.base import AgentContext
from physcensis.agent.guided import joined, objects_schema, placements_schema, unique_objects, without_the_support
from physcensis.agent.llm import LLMAgent
from physcensis.agent.loop import generate_scene
from physcensis.agent.prompt import COMPACT_EXAMPLE_SUPPORT, GUIDED_EXAMPLE, guided_system_prompt, messages
from physcensis.api import generate
from physcensis.ids import ROOT_ID
from physcensis.program import check_program, parse_program
from physcensis.program.registry import PREDICATES, PlacementKind, placement_spec
from physcensis.program.schema import list_form, response_format
from physcensis.scene import Support

from .fake_server import FakeOpenAI

pytestmark = pytest.mark.timeout(120)

Fake = Callable[..., FakeOpenAI]
TABLE = Support(kind="table", size=(0.8, 0.6))
ON = placement_spec(PlacementKind.ON).name
BASE = placement_spec(PlacementKind.BASE).name


def _split(program: dict[str, Any]) -> tuple[dict[str, Any], dict[str, Any]]:
    """A guided-form program as the replies of its two steps: the objects, and the placements by id."""
    objects = [{"id": o["id"], "description": o["description"]} for o in program["objects"]]
    placements = {o["id"]: {k: v for k, v in o.items() if k not in ("id", "description")} for o in program["objects"]}
    return {"objects": objects}, placements


def _validator(schema: dict[str, Any]) -> jsonschema.Draft202012Validator:
    jsonschema.Draft202012Validator.check_schema(schema)
    return jsonschema.Draft202012Validator(schema)


def test_the_prompt_example_is_what_the_two_schemas_accept_and_it_checks_clean() -> None:
    objects, placements = _split(GUIDED_EXAMPLE)
    _validator(objects_schema()).validate(objects)
    ids = [o["id"] for o in objects["objects"]]
    _validator(placements_schema(ids, COMPACT_EXAMPLE_SUPPORT)).validate(placements)
    report = check_program(parse_program(json.dumps(GUIDED_EXAMPLE)), COMPACT_EXAMPLE_SUPPORT)
    assert report.ok and not report.warnings, report.feedback()
    assert json.dumps(GUIDED_EXAMPLE["objects"][0], separators=(",", ":")) in guided_system_prompt()


def test_targets_are_only_objects_listed_before_and_positions_stay_on_the_support() -> None:
    validator = _validator(placements_schema(["book_0", "book_1"], TABLE))
    on_self = {"predicate": ON, "target": "book_1", "params": dict.fromkeys(("x_offset", "y_offset", "overlap"))}
    on_self["params"] |= {"stability": None, "messy": None}
    on_below = {**on_self, "target": "book_0"}
    standing = {
        "place": {"predicate": BASE, "target": ROOT_ID, "params": {"x": 0.0, "y": 0.0}},
        "facing": {"predicate": "RANDOM-ROT", "target": ROOT_ID, "params": {}},
        "relations": [],
    }
    assert validator.is_valid({"book_0": standing, "book_1": {"place": on_below}})
    assert not validator.is_valid({"book_0": standing, "book_1": {"place": on_self}})  # itself
    assert not validator.is_valid({"book_0": {"place": on_below}, "book_1": {"place": on_below}})  # the first: nothing
    off = {**standing, "place": {**standing["place"], "params": {"x": 0.41, "y": 0.0}}}  # the table is 0.8 m deep
    assert not validator.is_valid({"book_0": off, "book_1": {"place": on_below}})
    assert not validator.is_valid({"book_0": standing})  # every listed object is placed


def _instance(schema: dict[str, Any], rng: random.Random) -> Any:
    """A random value the schema accepts (of the schema subset the guided schemas use)."""
    if "anyOf" in schema:
        return _instance(rng.choice(schema["anyOf"]), rng)
    if "enum" in schema:
        return rng.choice(schema["enum"])
    kind = schema.get("type")
    if isinstance(kind, list):
        kind = rng.choice(kind)
    if kind == "object":
        return {name: _instance(sub, rng) for name, sub in schema["properties"].items()}
    if kind == "array":
        return [_instance(schema["items"], rng) for _ in range(rng.randint(0, schema.get("maxItems", 2)))]
    if kind == "number":
        return round(rng.uniform(schema.get("minimum", -1.0), schema.get("maximum", 1.0)), 3)
    if kind == "integer":
        return rng.randint(schema.get("minimum", 0), schema.get("maximum", 5))
    if kind == "boolean":
        return rng.random() < 0.5
    if kind == "null":
        return None
    return f"thing {rng.randint(0, 9)}"  # a string: the description


@pytest.mark.parametrize("seed", range(40))
def test_any_reply_the_schemas_accept_checks_clean(seed: int) -> None:
    """The point of the guided form: whatever a model writes within the two schemas is a complete program whose
    references resolve, so the checker finds no error."""
    rng = random.Random(seed)
    support = Support(kind=rng.choice(["table", "floor"]), size=(rng.uniform(0.4, 2.0), rng.uniform(0.4, 2.0)))
    ids = [f"{rng.choice(['cup', 'book', 'bowl'])}_{i}" for i in range(rng.randint(1, 7))]
    schema = placements_schema(ids, support)
    placements = _instance(schema, rng)
    _validator(schema).validate(placements)
    program = joined([(oid, f"a {oid.split('_')[0]}") for oid in ids], json.dumps(placements))
    report = check_program(parse_program(program), support)
    assert report.ok, report.feedback()


def test_ids_listed_twice_or_named_root_are_kept_under_fresh_names() -> None:
    reply = json.dumps(
        {"objects": [{"id": i, "description": f"a thing {n}"} for n, i in enumerate(["cup_0", "cup_0", ROOT_ID])]}
    )
    assert [oid for oid, _ in unique_objects(reply)] == ["cup_0", "cup_1", f"{ROOT_ID}_0"]
    assert unique_objects("not json") == [] and unique_objects('["cup_0"]') == []


def test_an_object_the_placements_reply_misses_is_reported_by_name() -> None:
    program = joined([("cup_0", "a mug"), ("book_0", "a book")], json.dumps({"cup_0": {"place": None}}))
    report = check_program(parse_program(program), TABLE)
    assert not report.ok
    assert {p.object for p in report.errors} == {"cup_0", "book_0"}


def test_a_round_is_two_requests_each_with_its_schema_and_the_program_solves(fake: Fake) -> None:
    objects, placements = _split(_STACK)
    server = fake(json.dumps(objects), json.dumps(placements))
    generated = generate("two books, one on the other", agent=_agent(server, hint="auto"), support=TABLE)
    assert generated.solution is not None and generated.solution.ok
    scene = generated.solution.scene
    assert {o.id for o in scene.placed} == {"book_0", "book_1"}
    lower, upper = (next(o for o in scene.placed if o.id == i) for i in ("book_0", "book_1"))
    assert upper.position[2] > lower.position[2] + 0.01  # the second book rests on the first
    first, second = server.requests
    # the offline reading's draft (two books) was shown, so the objects step asks for at least two
    assert first["response_format"] == response_format("json_schema", objects_schema(local=True, least=2))
    assert second["response_format"] == response_format("json_schema", placements_schema(["book_0", "book_1"], TABLE))
    assert first["seed"] != second["seed"]
    assert "Step 1 of 2" in first["messages"][-1]["content"]
    assert second["messages"][-2] == {"role": "assistant", "content": json.dumps(objects, separators=(",", ":"))}
    assert "Step 2 of 2" in second["messages"][-1]["content"]
    assert first["max_tokens"] < 4096 and second["max_tokens"] >= 2 * 100
    assert generated.transcript[-1]["usage"]["total_tokens"] > 0  # the two requests' tokens together
    assert list_form(json.loads(generated.transcript[-1]["program"]))[0] == ["book_0", "a red book"]


def test_a_first_step_that_is_not_an_object_list_is_judged_by_the_loop(fake: Fake) -> None:
    server = fake("I would rather not.", repeat_last=True)
    result = generate_scene("a mug", _agent(server), support=TABLE, retries=0)
    assert result.solution is None
    assert result.transcript[-1]["feedback_kind"] == "grammar"
    assert len(server.requests) == 1  # no placements step without objects


_STACK: dict[str, Any] = {
    "objects": [
        {
            "id": "book_0",
            "description": "a red book",
            "place": {"predicate": BASE, "target": ROOT_ID, "params": {"x": 0.0, "y": 0.0}},
            "facing": {"predicate": "FACING-FRONT", "target": ROOT_ID, "params": {"yaw_offset": None}},
            "relations": [],
        },
        {
            "id": "book_1",
            "description": "a blue book",
            "place": {
                "predicate": ON,
                "target": "book_0",
                "params": {p.name: None for p in PREDICATES[ON].params},
            },
        },
    ]
}


def _agent(server: FakeOpenAI, hint: str = "off") -> LLMAgent:
    """Without the draft unless a test is about it (test_hint.py tests the draft itself)."""
    return LLMAgent("fake-model", base_url=server.base_url, timeout_s=10.0, max_retries=0, prompt="compact", hint=hint)


@pytest.fixture
def fake(fake_openai: Fake) -> Fake:
    return fake_openai


def test_beside_root_is_never_offered_but_lining_up_with_its_edge_is() -> None:
    """LEFT-OF root puts an object past the support's edge; ALIGN-LEFT root puts it against that edge."""
    schema = json.dumps(placements_schema(["mug_0", "book_0"], TABLE))
    branches = placements_schema(["mug_0", "book_0"], TABLE)["properties"]["book_0"]["anyOf"]
    relations = branches[0]["properties"]["relations"]["items"]["anyOf"]
    targets = {
        name: r["properties"]["target"]["enum"] for r in relations for name in r["properties"]["predicate"]["enum"]
    }
    assert targets["LEFT-OF"] == ["mug_0"] and targets["ALIGN-LEFT"] == [ROOT_ID, "mug_0"]
    assert '"book_0"' not in json.dumps(branches)  # never itself
    assert '"minimum": -0.4' in schema and '"maximum": 0.3' in schema


def test_the_compact_request_leaves_out_the_category_list(desk_context: AgentContext) -> None:
    """Small models copy the catalogue's categories into the scene; the full prompt's request keeps them."""
    compact, full = (messages(desk_context, style)[1]["content"] for style in ("compact", "full"))
    assert "categories" not in compact and "categories" in full
    for text in (compact, full):
        assert text.rstrip().endswith(f'"{desk_context.prompt}". Write the program for it.')


def test_numbers_a_server_let_through_out_of_range_are_brought_within_the_schema() -> None:
    """llama-cpp-python enforces a schema's structure but not its numeric bounds: a standing position off the
    support, or a parameter past its range, is clipped to what the schema allows."""
    standing = {
        "place": {"predicate": BASE, "target": ROOT_ID, "params": {"x": -50.0, "y": 0.6}},
        "facing": {"predicate": "FACING-FRONT", "target": ROOT_ID, "params": {"yaw_offset": 9.0}},
        "relations": [],
    }
    program = json.loads(joined([("lamp_0", "a desk lamp")], json.dumps({"lamp_0": standing}), TABLE))
    lamp = program["objects"][0]
    assert lamp["place"]["params"] == {"x": -0.4, "y": 0.3}
    assert lamp["facing"]["params"]["yaw_offset"] == pytest.approx(3.14159, abs=1e-4)
    assert check_program(parse_program(json.dumps(program)), TABLE).ok


def test_local_servers_get_one_sentence_descriptions() -> None:
    """llama.cpp enforces maxLength (small models otherwise write paragraphs); OpenAI's strict subset is not sent it."""
    local, remote = (objects_schema(local=flag)["properties"]["objects"]["items"] for flag in (True, False))
    assert local["properties"]["description"]["maxLength"] == 160
    assert "maxLength" not in remote["properties"]["description"]
    assert not jsonschema.Draft202012Validator(objects_schema(local=True)).is_valid(
        {"objects": [{"id": "cup_0", "description": "a mug " * 40}]}
    )


def test_a_standing_object_takes_at_most_three_relations() -> None:
    """A small model once wrote ten ALIGN-* relations per object until its token budget ran out mid-reply."""
    align = {"predicate": "ALIGN-LEFT", "target": ROOT_ID, "params": {}}
    many = {**_STACK["objects"][0], "relations": [align] * 4}
    placements = {"book_0": {k: v for k, v in many.items() if k in ("place", "facing", "relations")}}
    validator = jsonschema.Draft202012Validator(placements_schema(["book_0"], TABLE))
    assert not validator.is_valid(placements)
    placements["book_0"]["relations"] = [align] * 3
    assert validator.is_valid(placements)


def test_an_object_that_is_the_support_is_dropped_and_copied_draft_places_are_cut() -> None:
    """Small models list the table they were told is root ("table_0", then everything PLACE-ON it) and copy the
    draft's "(stands at x .., y ..)" into descriptions, where retrieval would read it as words."""
    listed = [
        ("table_0", "a dining table, 1.2 m wide"),
        ("kitchen_counter_0", "the counter"),
        ("cup_0", "a white coffee cup, stands at x 0.23, y -0.13"),
        ("book_1", "a red book (on book_0)"),
        ("apple_0", "an apple (in bowl_0)"),
        ("saucer_0", "a saucer on a tray"),  # words, not a draft's id: kept
        ("timetable_0", "a printed timetable"),
    ]
    kept = dict(without_the_support(listed, TABLE))
    assert kept == {
        "cup_0": "a white coffee cup",
        "book_1": "a red book",
        "apple_0": "an apple",
        "saucer_0": "a saucer on a tray",
        "timetable_0": "a printed timetable",
    }
    box = Support(kind="box", size=(0.4, 0.3))
    assert without_the_support([("box_0", "a small box")], box) == [("box_0", "a small box")]  # boxes go in boxes
