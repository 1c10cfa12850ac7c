"""The program's JSON Schema and object form, and structured output against the fake OpenAI server."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import jsonschema
import pytest
from typer.testing import CliRunner

from physcensis.agent.base import AgentContext
from physcensis.agent.llm import LLMAgent
from physcensis.agent.planner import OfflinePlanner
from physcensis.api import generate
from physcensis.bench.prompt_suite import load_suite
from physcensis.cli import app
from physcensis.errors import ProgramParseError
from physcensis.examples import list_examples
from physcensis.llm.client import LLMRequestError, refuses_structured_output
from physcensis.program.parser import load_program, parse_program
from physcensis.program.registry import PREDICATES
from physcensis.program.schema import object_form, program_schema, response_format
from physcensis.scene import Support

from .fake_server import MUG_AND_BOOK, FakeOpenAI, Reply

pytestmark = pytest.mark.timeout(120)

Fake = Callable[..., FakeOpenAI]
SMALL_TABLE = Support(kind="table", size=(0.6, 0.6))
MUG_AND_BOOK_OBJECTS = json.dumps(object_form(json.loads(MUG_AND_BOOK)))


def _validator() -> jsonschema.Draft202012Validator:
    schema = program_schema()
    jsonschema.Draft202012Validator.check_schema(schema)
    return jsonschema.Draft202012Validator(schema)


def _declarations_first(entries: list[Any]) -> list[Any]:
    """The object form lists declarations, then relations; so is a list-form program compared with it."""
    return [e for e in entries if len(e) == 2] + [e for e in entries if len(e) != 2]


def _registry_examples() -> list[list[Any]]:
    """Each predicate's example with declarations of the objects it names."""
    programs = []
    for spec in PREDICATES.values():
        subject, name, target, params = spec.example
        names = [x for x in (subject, target, params.get("C"), params.get("anchor")) if isinstance(x, str)]
        names += [m for m in target if isinstance(m, str)] if isinstance(target, list) else []
        declared = [[n, f"a {n}"] for n in dict.fromkeys(names) if n != "root" and not n.startswith("group_")]
        programs.append([*declared, [subject, name, target, params]])
    return programs


def _bundled() -> list[list[Any]]:
    return [load_program(path).to_json() for path in list_examples()]


# -- the schema and the object form ------------------------------------------------------------------------------


def test_schema_is_valid_and_strict() -> None:
    schema = program_schema()
    jsonschema.Draft202012Validator.check_schema(schema)
    branches = schema["properties"]["relations"]["items"]["anyOf"]
    assert [b["properties"]["predicate"]["enum"] for b in branches] == [[name] for name in PREDICATES]
    for branch, spec in zip(branches, PREDICATES.values(), strict=True):
        params = branch["properties"]["params"]
        assert params["additionalProperties"] is False and params["required"] == [p.name for p in spec.params]
        assert set(branch["required"]) == {"subject", "predicate", "target", "params"}
    assert response_format()["json_schema"]["strict"] is True
    assert response_format()["json_schema"]["schema"] == schema


@pytest.mark.parametrize("program", _bundled() + _registry_examples(), ids=lambda p: str(p[-1][:2]))
def test_object_form_round_trips_and_validates(program: list[Any]) -> None:
    listed = parse_program(_declarations_first(program))
    objects = object_form(program)
    _validator().validate(objects)
    for text in (json.dumps(objects), f"Here is the program:\n```json\n{json.dumps(objects, indent=1)}\n```"):
        parsed = parse_program(text)
        assert parsed.to_json() == listed.to_json()
        assert parsed.read_problems == listed.read_problems


def test_planner_programs_for_the_prompt_suite_validate() -> None:
    validator, planner = _validator(), OfflinePlanner()
    for case in load_suite():
        support = Support.model_validate(case["support"])
        program = json.loads(planner.propose(AgentContext(case["prompt"], support, ())))
        errors = [e.message for e in validator.iter_errors(object_form(program))]
        assert errors == [], case["id"]


@pytest.mark.parametrize(
    ("relation", "why"),
    [
        ({"subject": "cup_0", "predicate": "PLACE-ON", "target": "plate_0", "params": {"distance": 0.1}}, "param"),
        ({"subject": "cup_0", "predicate": "FLOAT-ABOVE", "target": "root", "params": {}}, "predicate"),
        ({"subject": "cup 0", "predicate": "PLACE-ANYWHERE", "target": "root", "params": {"stack": None}}, "id"),
        ({"subject": "cup_0", "predicate": "LEFT-OF", "target": "plate_0", "params": {"distance": 99.0}}, "range"),
    ],
)
def test_schema_refuses_what_the_checker_would(relation: dict[str, Any], why: str) -> None:
    program = {"objects": [{"id": "cup_0", "description": "a mug"}], "relations": [relation]}
    assert not _validator().is_valid(program), why


def test_object_form_inside_the_envelope_keeps_support_and_prompt() -> None:
    objects = object_form(json.loads(MUG_AND_BOOK))
    program = parse_program({"program": objects, "support": {"kind": "table", "size": [0.6, 0.6]}, "prompt": "hi"})
    flat = parse_program({**objects, "support": {"kind": "table", "size": [0.6, 0.6]}, "prompt": "hi"})
    assert program.to_json() == flat.to_json() == parse_program(_declarations_first(json.loads(MUG_AND_BOOK))).to_json()
    assert program.support == flat.support == SMALL_TABLE and program.prompt == flat.prompt == "hi"
    assert not any(p.rule == "unknown-key" for p in flat.read_problems)


def test_broken_object_form_is_reported() -> None:
    with pytest.raises(ProgramParseError, match='"objects" of an object-form program must be a list'):
        parse_program('{"objects": "cup_0", "relations": []}')
    program = parse_program({"objects": [{"id": "cup_0", "description": "a mug"}], "relations": ["cup_0"]})
    assert [p.rule for p in program.read_problems] == ["bad-entry"]


# -- structured output over the wire -----------------------------------------------------------------------------


def _agent(server: FakeOpenAI, structured: str, prompt: str = "full") -> LLMAgent:
    """The fake server is local, so `auto` would pick the compact prompt and its guided steps (test_guided.py);
    these tests are about the flat object form, which the full prompt asks for."""
    return LLMAgent(
        "fake-model",
        base_url=server.base_url,
        timeout_s=5.0,
        max_retries=1,
        structured=structured,
        prompt=prompt,
        hint="off",  # test_hint.py tests the draft
    )


@pytest.mark.parametrize("mode", ["auto", "on"])
def test_the_schema_is_sent_and_the_object_form_is_solved(fake_openai: Fake, mode: str) -> None:
    server = fake_openai(MUG_AND_BOOK_OBJECTS)
    generated = generate("a mug and a book", agent=_agent(server, mode), support=SMALL_TABLE)
    assert generated.solution is not None
    assert {p.id for p in generated.solution.scene.placed} == {"mug_0", "book_0"}
    [body] = server.requests
    assert body["response_format"] == response_format()
    assert '"relations"' in body["messages"][0]["content"]  # the system prompt describes the object form


def test_off_never_sends_the_schema(fake_openai: Fake) -> None:
    server = fake_openai(MUG_AND_BOOK)
    generated = generate("a mug and a book", agent=_agent(server, "off"), support=SMALL_TABLE)
    assert generated.solution is not None
    assert "response_format" not in server.requests[0]
    assert '"relations"' not in server.requests[0]["messages"][0]["content"]


def test_auto_falls_back_to_plain_text_once_refused(fake_openai: Fake) -> None:
    server = fake_openai("[oops", MUG_AND_BOOK, refuse_response_format=True)
    agent = _agent(server, "auto")
    generated = generate("a mug and a book", agent=agent, support=SMALL_TABLE)
    assert generated.solution is not None
    # both ways of sending the schema refused once each, then never asked again
    assert [body.get("response_format", {}).get("type") for body in server.requests] == [
        "json_schema",
        "json_object",
        None,
        None,
    ]
    [note] = [row["note"] for row in generated.transcript if "structured output" in row.get("note", "")]
    assert note.startswith("structured output refused by the server, falling back to plain text")
    assert "HTTP 400" in note and generated.transcript[0].get("note")  # the run's notes come first


def test_on_fails_with_one_clear_line_when_refused(fake_openai: Fake, desk_context: AgentContext) -> None:
    server = fake_openai(MUG_AND_BOOK, refuse_response_format=True)
    with pytest.raises(LLMRequestError, match="refused structured output.*--structured auto or off") as info:
        _agent(server, "on").propose(desk_context)
    assert "\n" not in str(info.value) and info.value.status == 400
    assert len(server.requests) == 2  # each way of sending the schema once
    generated = generate("a mug and a book", agent=_agent(server, "on"), support=SMALL_TABLE)
    assert generated.solution is None
    assert "refused structured output" in generated.transcript[-1]["error"]


def test_a_server_that_takes_only_json_object_gets_the_schema_that_way(fake_openai: Fake) -> None:
    """llama-cpp-python's server answers `json_schema` with a 500 (its validation error) and takes `json_object`
    with a `schema`: the refusal is not retried, and the run goes on with the schema in that dialect."""
    server = fake_openai(json.dumps(object_form(json.loads(MUG_AND_BOOK))), refuse_json_schema=True)
    generated = generate("a mug and a book", agent=_agent(server, "auto"), support=SMALL_TABLE)
    assert generated.solution is not None and generated.solution.ok
    formats = [body.get("response_format", {}) for body in server.requests]
    assert [f.get("type") for f in formats] == ["json_schema", "json_object"]
    assert formats[1]["schema"] == program_schema()
    assert not [row for row in generated.transcript if "falling back" in row.get("note", "")]


def test_other_bad_requests_are_not_taken_for_a_refusal(fake_openai: Fake, desk_context: AgentContext) -> None:
    server = fake_openai(Reply(status=400, error="temperature is not supported by this model"))
    with pytest.raises(LLMRequestError, match="temperature") as info:
        _agent(server, "auto").propose(desk_context)
    assert not refuses_structured_output(info.value)
    assert len(server.requests) == 1


def test_a_bad_mode_is_refused() -> None:
    with pytest.raises(Exception, match="structured output must be one of auto, on, off, not 'maybe'"):
        LLMAgent("fake-model", base_url="http://127.0.0.1:9/v1", structured="maybe")


def test_batch_passes_the_mode_from_the_command_to_generate(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    import physcensis.api
    import physcensis.batch
    from physcensis.batch import BatchError, Options
    from physcensis.batch.worker import Task, make_scene

    seen: dict[str, Any] = {}

    def fake_run_batch(specs: object, out: object, **kwargs: object) -> object:
        seen.update(kwargs)
        raise BatchError("stop here")

    def fake_generate(prompt: str, **kwargs: object) -> object:
        seen.update(kwargs)
        raise BatchError("no server here")

    monkeypatch.setattr(physcensis.batch, "run_batch", fake_run_batch)
    monkeypatch.setattr(physcensis.api, "generate", fake_generate)
    prompts = tmp_path / "p.txt"
    prompts.write_text("a cup\n")
    args = ["batch", str(prompts), "--out", str(tmp_path / "out"), "--export", "none"]
    CliRunner().invoke(app, [*args, "--structured", "off"])
    assert seen["options"].settings.models.structured == "off"
    CliRunner().invoke(app, args)
    assert seen["options"].settings.models.structured == "auto"
    make_scene(Task("desk_000", "desk", "a mug", "table:0.6x0.6", seed=1), Options.of(exports=("none",), llm="m"))
    assert seen["settings"].models.structured == "auto"
    refused = CliRunner().invoke(app, [*args, "--structured", "maybe"])
    assert refused.exit_code != 0 and "'maybe' is not one of auto, on, off" in refused.output
    CliRunner().invoke(app, [*args, "--no-stream"])  # plain replies, for servers that count tokens only then
    assert seen["options"].settings.models.stream is False
    make_scene(Task("desk_000", "desk", "a mug", "table:0.6x0.6", seed=1), seen["options"])
    assert seen["settings"].models.stream is False
