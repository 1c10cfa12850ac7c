"""The guided steps and the LLM agent against hostile cases found in review: replies both schemas accept, OpenAI's
schema limits, the time budget shared by a reply's requests, refusals, and what the record keeps."""

from __future__ import annotations

import json
from typing import Any

import jsonschema
import pytest

from physcensis.agent.base import AgentContext
from physcensis.agent.guided import joined, objects_schema, placements_schema, unique_objects
from physcensis.agent.llm import LLMAgent
from physcensis.agent.loop import generate_scene
from physcensis.program import check_program, parse_program
from physcensis.scene import Support

from .fake_server import FakeOpenAI, Reply

pytestmark = pytest.mark.timeout(120)

TABLE = Support(kind="table", size=(0.8, 0.6))
STANDING = {
    "place": {"predicate": "PLACE-ON-BASE", "target": "root", "params": {"x": 0.0, "y": 0.0}},
    "facing": {"predicate": "FACING-FRONT", "target": "root", "params": {"yaw_offset": None}},
    "relations": [],
}


def _valid(schema: dict[str, Any], value: Any) -> None:
    jsonschema.Draft202012Validator.check_schema(schema)
    jsonschema.Draft202012Validator(schema).validate(value)


def _checked(objects_reply: dict[str, Any], placements: dict[str, Any], support: Support = TABLE) -> Any:
    """Both steps validated against their schemas, then joined and checked as the agent does."""
    _valid(objects_schema(), objects_reply)
    objects = unique_objects(json.dumps(objects_reply))
    ids = [oid for oid, _ in objects]
    listed = [o["id"] for o in objects_reply["objects"]]
    placements = {new: placements[old] for new, old in zip(ids, listed, strict=True)}  # step 2 asks for the new ids
    _valid(placements_schema(ids, support), placements)
    return check_program(parse_program(joined(objects, json.dumps(placements), support)), support)


# -- guided: replies both schemas accept that the checker rejects -------------------------------------------------


@pytest.mark.parametrize("oid", ["Root", "ROOT", "support", "scene", "world", "ground"])
def test_reserved_ids_are_renamed_so_the_program_checks(oid: str) -> None:
    report = _checked({"objects": [{"id": oid, "description": "a wooden crate"}]}, {oid: STANDING})
    assert report.ok, report.feedback()


def test_a_blank_description_is_made_from_the_id() -> None:
    report = _checked({"objects": [{"id": "cup_0", "description": "   "}]}, {"cup_0": STANDING})
    assert report.ok, report.feedback()


def test_support_bounds_are_rounded_inward() -> None:
    """A 0.33333 m deep table: x within +-0.166665 m. The schema's bound is rounded inward, so the schema refuses
    0.1667, and a server that lets it through gets it clipped to a position the checker accepts."""
    support = Support(kind="table", size=(0.33333, 0.6))
    at_edge = {**STANDING, "place": {**STANDING["place"], "params": {"x": 0.1667, "y": 0.0}}}
    assert not jsonschema.Draft202012Validator(placements_schema(["cup_0"], support)).is_valid({"cup_0": at_edge})
    program = joined([("cup_0", "a white mug")], json.dumps({"cup_0": at_edge}), support)
    assert check_program(parse_program(program), support).ok


def test_a_truncated_placements_reply_keeps_the_placements_received_whole() -> None:
    """max_tokens cut the reply (finish_reason length) after the first object's placement was complete."""
    whole = json.dumps({"cup_0": STANDING, "book_0": STANDING}, separators=(",", ":"))
    truncated = whole[: whole.index('"book_0"') + 20]
    program = json.loads(joined([("cup_0", "a mug"), ("book_0", "a book")], truncated, TABLE))
    assert program["objects"][0].get("place") is not None  # cup_0's placement was received whole
    assert program["objects"][1]["place"] is None  # book_0's was cut: the checker will name it


# -- guided: OpenAI strict mode limits -----------------------------------------------------------------------------


def _enum_values(schema: Any) -> int:
    if isinstance(schema, dict):
        return len(schema.get("enum", [])) + sum(_enum_values(v) for v in schema.values())
    if isinstance(schema, list):
        return sum(_enum_values(v) for v in schema)
    return 0


OPENAI_MAX_ENUM_VALUES = 1000  # "A schema may have up to 1000 enum values across all enum properties" (was 500)


def test_the_placements_schema_of_nine_objects_is_within_openai_strict_limits() -> None:
    ids = [f"book_{i}" for i in range(9)]
    assert _enum_values(placements_schema(ids, TABLE)) <= OPENAI_MAX_ENUM_VALUES


class OpenAILike(FakeOpenAI):
    """Answers as api.openai.com does: a strict schema over the enum limit is a 400, and `schema` beside
    `json_object` is an unknown parameter."""

    def _record(self, body: Any, headers: dict[str, str]) -> object:
        action = super()._record(body, headers)
        fmt = body.get("response_format") if isinstance(body, dict) else None
        if isinstance(fmt, dict) and fmt.get("type") == "json_schema":
            n = _enum_values(fmt["json_schema"]["schema"])
            if n > OPENAI_MAX_ENUM_VALUES:
                return Reply(
                    status=400,
                    error=f"Invalid schema for response_format 'program': Expected at most 1000 enum values in total "
                    f"within a single schema when using structured outputs, but received {n}. Consider reducing the "
                    "number of enums, or use 'strict: false' to opt out of structured outputs.",
                )
        if isinstance(fmt, dict) and fmt.get("type") == "json_object" and "schema" in fmt:
            return Reply(status=400, error="Unknown parameter: 'response_format.schema'.")
        return action


def test_openai_with_the_compact_prompt_keeps_structured_output_for_a_ten_object_scene() -> None:
    """Past OpenAI's enum budget the placements step names targets by the id pattern instead, and stays strict."""
    objects = {"objects": [{"id": f"book_{i}", "description": "a red hardcover book"} for i in range(16)]}
    placements = {f"book_{i}": STANDING for i in range(16)}
    with OpenAILike([json.dumps(objects), json.dumps(placements)], no_stream=True) as server:
        agent = LLMAgent(
            "gpt-4o-mini",
            base_url=server.base_url,
            timeout_s=10.0,
            max_retries=0,
            max_tokens=4000,  # no context probe
            prompt="compact",
            structured="on",
            hint="off",  # test_hint.py tests the draft
        )
        agent.base_url = "https://api.openai.com/v1"  # the fake is on loopback: let the agent take it for OpenAI
        text = agent.propose(AgentContext("sixteen books on a table", TABLE, ()))
    kinds = [(r.get("response_format") or {}).get("type") for r in server.requests]
    assert kinds == ["json_schema", "json_schema"] and agent._send_schema
    assert check_program(parse_program(text), TABLE).ok


# -- the loop ----------------------------------------------------------------------------------------------------


def test_two_guided_requests_stay_within_the_time_budget(fake_openai: Any) -> None:
    objects = {"objects": [{"id": "cup_0", "description": "a white mug"}]}
    server = fake_openai(
        Reply(content=json.dumps(objects), delay_s=1.2), Reply(content=json.dumps({"cup_0": STANDING}), delay_s=1.4)
    )
    # no draft: a timing test, and a draft's time counts against the reply's limit
    agent = LLMAgent(
        "fake-model", base_url=server.base_url, timeout_s=30.0, max_retries=0, prompt="compact", hint="off"
    )
    result = generate_scene("a mug", agent, support=TABLE, time_budget_s=1.5)
    first = next(row for row in result.transcript if row.get("round") == 1)
    assert first["seconds"] <= 1.5 + 0.3, f"round 1's requests took {first['seconds']} s of a 1.5 s budget"


class Same:
    """An agent that always writes the same failing program: book_0 is never placed, cup_0 rests on it."""

    name = "same"
    program = json.dumps([["book_0", "a red book"], ["cup_0", "a white mug"], ["cup_0", "PLACE-ON", "book_0", {}]])

    def propose(self, context: AgentContext) -> str:
        return self.program


def test_repeat_feedback_says_objects_were_dropped_only_when_the_loop_dropped_them() -> None:
    result = generate_scene("a mug on a book", Same(), support=TABLE, retries=2, time_budget_s=None)
    repeated = next(row for row in result.transcript if "repeat_of_round" in row)
    claims = "dropped from your program for you" in repeated["feedback"]
    loop_rounds = [row for row in result.transcript if row.get("agent") == "loop-repair"]
    assert not claims or loop_rounds, "the feedback says the loop dropped objects; it dropped nothing"


# -- the model's refusal ------------------------------------------------------------------------------------------


def test_an_openai_refusal_is_kept_in_the_record(fake_openai: Any) -> None:
    refusal = "I'm sorry, I cannot help with that request."
    body = {
        "id": "x",
        "object": "chat.completion",
        "created": 0,
        "model": "m",
        "choices": [
            {
                "index": 0,
                "message": {"role": "assistant", "content": None, "refusal": refusal},
                "finish_reason": "stop",
            }
        ],
    }
    server = fake_openai(Reply(body=body))
    agent = LLMAgent("m", base_url=server.base_url, timeout_s=10.0, max_retries=0, stream=False)
    text = agent.complete([{"role": "user", "content": "hi"}])
    assert refusal in text and refusal in json.dumps(agent.calls[-1]), "the refusal text is dropped"


def test_a_guided_round_whose_second_step_fails_keeps_the_first_steps_reply_in_the_record(fake_openai: Any) -> None:
    objects = {"objects": [{"id": "cup_0", "description": "a white mug"}]}
    server = fake_openai(json.dumps(objects), Reply(status=400, error="context length exceeded"))
    agent = LLMAgent(
        "fake-model", base_url=server.base_url, timeout_s=10.0, max_retries=0, prompt="compact", hint="off"
    )
    result = generate_scene("a mug", agent, support=TABLE, time_budget_s=None)
    [row] = [row for row in result.transcript if row.get("round") == 1]
    first, second = row["requests"]
    assert "a white mug" in first["reply"] and first["usage"]["total_tokens"] > 0
    assert "context length exceeded" in second["error"]
    row = result.transcript[-1]
    assert isinstance(row.get("requests"), list) and len(row["requests"]) == 2, "no per-request tokens and seconds"
