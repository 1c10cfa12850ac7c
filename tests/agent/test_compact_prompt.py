"""The compact system prompt fits small models, each prompt's example checks clean, and requests fit the model:
which prompt a server gets, the context probe, and `max_tokens` sized to the program."""

from __future__ import annotations

import json
import re
import socket
import time
from collections.abc import Callable
from dataclasses import replace

import jsonschema
import pytest
from typer.testing import CliRunner

from physcensis.agent import sizing
from physcensis.agent.base import AgentContext, AgentError, Round
from physcensis.agent.llm import LLMAgent
from physcensis.agent.prompt import (
    COMPACT_EXAMPLE,
    COMPACT_EXAMPLE_SUPPORT,
    COMPACT_MAX_TOKENS,
    WORKED_EXAMPLE,
    WORKED_EXAMPLE_SUPPORT,
    compact_system_prompt,
    estimate_tokens,
    messages,
    system_prompt,
    system_prompt_for,
)
from physcensis.api import generate
from physcensis.cli import app
from physcensis.llm import server as server_info
from physcensis.program import check_program, parse_program
from physcensis.program.registry import PREDICATES, placement_names
from physcensis.program.schema import program_schema
from physcensis.scene import Support

from .fake_server import MUG_AND_BOOK, FakeOpenAI

pytestmark = pytest.mark.timeout(30)

FULL_PROMPT_QWEN_TOKENS = 5_400  # the full prompt, counted by Qwen2.5's tokenizer (issue 21)


def _printed_examples(prompt: str) -> list[str]:
    """Every JSON program printed in a prompt: a line "[" up to the next line "]"."""
    return re.findall(r"^\[\n.*?\n\]$", prompt, re.MULTILINE | re.DOTALL)


# -- the compact prompt ------------------------------------------------------------------------------------------


def test_the_estimate_over_counts_the_measured_full_prompt_slightly() -> None:
    estimate = estimate_tokens(system_prompt())
    assert FULL_PROMPT_QWEN_TOKENS <= estimate <= FULL_PROMPT_QWEN_TOKENS * 1.05


def test_the_compact_prompt_fits_its_budget() -> None:
    assert estimate_tokens(compact_system_prompt()) <= COMPACT_MAX_TOKENS
    assert estimate_tokens(compact_system_prompt()) < estimate_tokens(system_prompt()) / 3


def test_each_predicate_is_one_line_with_its_parameters_ranges_and_formula() -> None:
    """A parameter several predicates share unchanged (distance, yaw_offset) is named on their lines and described
    once, on the shared line; the others are described on their predicate's line."""
    lines = compact_system_prompt().splitlines()
    shared = next(ln for ln in lines if ln.startswith("Shared parameters: "))
    for spec in PREDICATES.values():
        line = next((ln for ln in lines if ln.startswith(f"- {spec.name} ")), None)
        assert line is not None, f"{spec.name} has no line"
        assert line.endswith(spec.formula)
        for param in spec.params:
            if f"{param.name}: " not in line:
                assert re.search(rf"[{{;] ?{param.name}[;}}]", line), (spec.name, param.name)
                line = shared
            assert f"{param.name}: " in line, (spec.name, param.name)
            if param.bounded_by_support:  # the support's own range, which the user message gives
                assert f"{param.name}: inside the support's {param.bounded_by_support} range" in line, line
            elif param.low is not None and param.high is not None:
                assert re.search(rf"{param.name}: -?[\w.]+\.\.-?[\w.]+", line), line
            if param.required:
                assert f"{param.name}: id, required" in line or "required" in line
    distance = PREDICATES["LEFT-OF"].param("distance")
    assert distance is not None
    assert f"distance: {distance.low:g}..{distance.high:g}, default {distance.default:g}" in compact_system_prompt()


def test_the_compact_prompt_states_the_coordinate_rules_and_the_output_format() -> None:
    prompt = compact_system_prompt()
    for fact in ("front = +x", "back = -x", "left = +y", "right = -y", "Metres and radians", '"root"'):
        assert fact in prompt, fact
    assert ", ".join(placement_names()) in prompt
    assert "Only the JSON list" in prompt and "whole program" in prompt


@pytest.mark.parametrize(
    ("prompt", "support", "entries"),
    [
        (compact_system_prompt, COMPACT_EXAMPLE_SUPPORT, COMPACT_EXAMPLE),
        (system_prompt, WORKED_EXAMPLE_SUPPORT, WORKED_EXAMPLE),
    ],
    ids=["compact", "full"],
)
def test_the_example_each_prompt_prints_checks_clean(
    prompt: Callable[[], str], support: Support, entries: tuple[tuple[object, ...], ...]
) -> None:
    (printed,) = _printed_examples(prompt())
    assert json.loads(printed) == json.loads(json.dumps([list(e) for e in entries]))
    report = check_program(parse_program(printed), support)
    assert report.problems == (), report.feedback()
    x, y = (s / 2 for s in support.size)
    assert f"x from {-x:g} to {x:g}" in prompt() and f"y from {-y:g} to {y:g}" in prompt()


def test_the_chat_carries_the_chosen_prompt(desk_context: AgentContext) -> None:
    assert messages(desk_context)[0]["content"] == system_prompt()
    assert messages(desk_context, "compact")[0]["content"] == compact_system_prompt()
    assert system_prompt_for("full") == system_prompt()
    with pytest.raises(ValueError, match="unknown prompt style 'tiny'"):
        system_prompt_for("tiny")


# -- which prompt a server gets ----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "url",
    [
        "http://localhost:8080/v1",
        "http://127.0.0.1:1234/v1",
        "http://127.8.9.10/v1",
        "http://[::1]:11434/v1",
        "http://192.168.1.20:8000/v1",
        "http://10.0.0.5/v1",
        "http://172.16.3.4/v1",
        "http://169.254.1.1/v1",
        "http://gpu-box.local:8000/v1",
        "http://user:pw@localhost/v1",
    ],
)
def test_local_servers_are_recognised(url: str) -> None:
    assert server_info.is_local_server(url)


@pytest.mark.parametrize(
    "url", [None, "", "https://api.openai.com/v1", "http://8.8.8.8/v1", "http://localhost.example.com/v1", "nonsense"]
)
def test_remote_or_unknown_servers_are_not_local(url: str | None) -> None:
    assert not server_info.is_local_server(url)


def test_the_prompt_decision() -> None:
    remote = "https://api.openai.com/v1"
    assert sizing.decide_prompt("auto", "http://127.0.0.1:8080/v1", None).style == "compact"
    assert sizing.decide_prompt("auto", remote, None).style == "full"
    assert sizing.decide_prompt("auto", remote, 4096).style == "compact"
    assert sizing.decide_prompt("auto", remote, 4096).reason == "the server's context is 4096 tokens"
    assert sizing.decide_prompt("auto", remote, 131_072).style == "full"
    assert sizing.decide_prompt("full", "http://127.0.0.1/v1", 2048).style == "full"
    assert sizing.decide_prompt("compact", remote, None).record() == {
        "style": "compact",
        "reason": "--prompt compact",
        "context_tokens": None,
    }
    assert sizing.prompt_choice("auto") == "auto"
    with pytest.raises(ValueError, match="prompt must be one of auto, full, compact, not 'big'"):
        sizing.prompt_choice("big")


# -- the context probe ---------------------------------------------------------------------------------------------


def test_the_probe_reads_llama_cpp_n_ctx(fake_openai: Callable[..., FakeOpenAI]) -> None:
    server = fake_openai(MUG_AND_BOOK)
    server.n_ctx = 2048
    assert server_info.probe_context_tokens(server.base_url, "fake-model") == 2048
    assert "/props" in server.get_paths
    assert server.requests == []  # probing sends no chat


def test_the_probe_finds_nothing_on_a_server_without_those_endpoints(fake_openai: Callable[..., FakeOpenAI]) -> None:
    server = fake_openai(MUG_AND_BOOK)
    assert server_info.probe_context_tokens(server.base_url, "fake-model") is None
    assert server.get_paths == ["/v1/models", "/props", "/api/version"]  # Ollama's /api/show only after its version


def test_the_probe_gives_up_at_once_when_nobody_listens() -> None:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port = sock.getsockname()[1]
    start = time.monotonic()
    assert server_info.probe_context_tokens(f"http://127.0.0.1:{port}/v1", "m") is None
    assert time.monotonic() - start < server_info.PROBE_TIMEOUT_S


def test_the_probe_reads_vllm_and_ollama_answers() -> None:
    models = {"data": [{"id": "other", "max_model_len": 1024}, {"id": "qwen", "max_model_len": 32768}]}
    assert server_info._from_models(models, "qwen") == 32768
    assert server_info._from_models(models, "unknown") == 1024
    assert server_info._from_models({"data": [{"id": "gpt-4o"}]}, "gpt-4o") is None
    assert server_info._from_ollama_show({"parameters": "stop <|im_end|>\nnum_ctx 8192\n"}) == 8192
    assert server_info._from_ollama_show({"parameters": "temperature 0.2"}) is None
    assert server_info._from_props({"n_ctx": 4096}) == 4096
    assert server_info._from_props({"default_generation_settings": {"n_ctx": True}}) is None
    assert server_info._from_props(["n_ctx", 4]) is None


# -- max_tokens ----------------------------------------------------------------------------------------------------


def test_objects_asked_for_adds_up_the_numbers_named() -> None:
    assert sizing.objects_asked_for("two plates and 6 cups") == 8
    assert sizing.objects_asked_for("a messy desk") == 0
    assert sizing.objects_asked_for("a dozen eggs in a carton") == 12
    assert sizing.objects_asked_for("a 2026 calendar") == 0  # a year, not a count


def test_the_reply_budget_follows_the_program_and_stays_within_bounds(desk_context: AgentContext) -> None:
    chat = messages(desk_context, "compact")
    small = sizing.reply_token_budget(desk_context, chat)
    expected = sizing.REPLY_BASE_TOKENS + sizing.TOKENS_PER_OBJECT * sizing.DEFAULT_OBJECTS
    assert small == expected
    shelf = replace(desk_context, prompt="a shelf with 40 books")
    assert sizing.reply_token_budget(shelf, chat) == sizing.REPLY_BASE_TOKENS + sizing.TOKENS_PER_OBJECT * 44
    huge = replace(desk_context, prompt="a floor with 999 cans")
    assert sizing.reply_token_budget(huge, chat) == sizing.MAX_REPLY_TOKENS
    program = json.dumps([[f"cup_{i}", "a cup"] for i in range(20)])
    enrich = replace(desk_context, request="enrich", history=(Round(program, "ok", True),))
    assert sizing.expected_objects(enrich) == 20 + sizing.ENRICH_EXTRA_OBJECTS


def test_the_reply_budget_leaves_the_chat_its_room_in_a_small_context(desk_context: AgentContext) -> None:
    chat = messages(desk_context, "compact")
    used = sum(estimate_tokens(m["content"]) for m in chat)
    budget = sizing.reply_token_budget(desk_context, chat, context_tokens=2048)
    assert budget == 2048 - used - sizing.CONTEXT_MARGIN_TOKENS
    assert 0 < budget < sizing.REPLY_BASE_TOKENS + sizing.TOKENS_PER_OBJECT * sizing.DEFAULT_OBJECTS
    assert sizing.reply_token_budget(desk_context, chat, context_tokens=100) == 1
    roomy = sizing.reply_token_budget(desk_context, chat, context_tokens=128_000)
    assert roomy == sizing.reply_token_budget(desk_context, chat)


# -- the agent: the prompt it sends and the max_tokens it asks for -------------------------------------------------


def _system(server: FakeOpenAI, i: int = 0) -> str:
    return str(server.messages[i][0]["content"])


def test_a_local_server_gets_the_compact_prompt_under_auto(
    fake_openai: Callable[..., FakeOpenAI], desk_context: AgentContext
) -> None:
    server = fake_openai(MUG_AND_BOOK, MUG_AND_BOOK)
    agent = LLMAgent("fake-model", base_url=server.base_url, max_retries=0, hint="off")  # test_hint.py: the draft
    agent.propose(desk_context)
    agent.propose(replace(desk_context, request="repair", history=(Round(MUG_AND_BOOK, "fix it"),)))
    assert _system(server, 0).startswith(compact_system_prompt(structured=True))
    assert _system(server, 1).startswith(compact_system_prompt(structured=True))
    assert agent.prompt_decision is not None and agent.prompt_decision.reason == "a local server"
    assert server.get_paths.count("/props") == 1  # probed once per run, not per request
    assert any(note.startswith("system prompt: compact (a local server") for note in agent.transcript_notes)


def test_prompt_full_sends_the_full_prompt_to_a_local_server(
    fake_openai: Callable[..., FakeOpenAI], desk_context: AgentContext
) -> None:
    server = fake_openai(MUG_AND_BOOK)
    LLMAgent("fake-model", base_url=server.base_url, max_retries=0, prompt="full").propose(desk_context)
    assert _system(server).startswith(system_prompt(structured=True))


def test_a_remote_server_reporting_a_small_context_gets_the_compact_prompt(
    fake_openai: Callable[..., FakeOpenAI], desk_context: AgentContext, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(sizing, "is_local_server", lambda url: False)  # as if the fake server were far away
    small = fake_openai(MUG_AND_BOOK)
    small.n_ctx = 4096
    agent = LLMAgent("fake-model", base_url=small.base_url, max_retries=0, hint="off")  # test_hint.py: the draft
    agent.propose(desk_context)
    assert _system(small).startswith(compact_system_prompt(structured=True))
    assert agent.prompt_decision == sizing.PromptDecision("compact", "the server's context is 4096 tokens", 4096)
    sent = small.requests[0]
    used = sum(estimate_tokens(str(m["content"])) for m in sent["messages"])
    assert 0 < sent["max_tokens"] <= 4096 - used

    large = fake_openai(MUG_AND_BOOK)
    large.n_ctx = 65_536
    LLMAgent("fake-model", base_url=large.base_url, max_retries=0).propose(desk_context)
    assert _system(large).startswith(system_prompt(structured=True))
    silent = fake_openai(MUG_AND_BOOK)  # reports no context: a remote server gets the full prompt
    LLMAgent("fake-model", base_url=silent.base_url, max_retries=0).propose(desk_context)
    assert _system(silent).startswith(system_prompt(structured=True))


def test_every_request_carries_max_tokens_sized_to_the_program(
    fake_openai: Callable[..., FakeOpenAI], desk_context: AgentContext
) -> None:
    server = fake_openai(MUG_AND_BOOK, MUG_AND_BOOK)
    # one request a round; no draft (test_hint.py tests it)
    agent = LLMAgent("fake-model", base_url=server.base_url, max_retries=0, structured="off", hint="off")
    agent.propose(desk_context)
    agent.propose(replace(desk_context, prompt="a shelf with 30 books"))
    first, second = (body["max_tokens"] for body in server.requests)
    assert sizing.MIN_REPLY_TOKENS <= first < second <= sizing.MAX_REPLY_TOKENS
    assert second == sizing.REPLY_BASE_TOKENS + sizing.TOKENS_PER_OBJECT * 34
    fixed = fake_openai(MUG_AND_BOOK)
    LLMAgent("fake-model", base_url=fixed.base_url, max_retries=0, max_tokens=300, hint="off").propose(desk_context)
    assert fixed.requests[0]["max_tokens"] == 300  # the caller's own limit wins


def test_an_unknown_prompt_setting_is_one_clear_error() -> None:
    with pytest.raises(AgentError, match="prompt must be one of auto, full, compact, not 'short'"):
        LLMAgent("fake-model", base_url="http://127.0.0.1:9/v1", prompt="short")


def test_generate_notes_the_prompt_in_the_transcript(fake_openai: Callable[..., FakeOpenAI]) -> None:
    server = fake_openai(MUG_AND_BOOK)
    generated = generate(
        "a mug and a book",
        support=Support.parse("table:0.6x0.6"),
        llm="fake-model",
        base_url=server.base_url,
        prompt_style="compact",
        hint="off",  # test_hint.py tests the draft
    )
    notes = [row["note"] for row in generated.transcript if "note" in row]
    assert "system prompt: compact (--prompt compact)" in notes
    assert _system(server).startswith(compact_system_prompt(structured=True))


def test_the_cli_refuses_an_unknown_prompt_style() -> None:
    result = CliRunner().invoke(app, ["generate", "a desk", "--llm", "m", "--prompt", "tiny"])
    assert result.exit_code == 2
    assert "--prompt" in result.output and "'tiny' is not one of auto, full, compact" in result.output


def test_structured_output_replaces_the_output_section_and_stays_within_budget() -> None:
    """With structured output the full system message asks for the object form instead of the list (not both); the
    compact one becomes the guided form's (test_guided.py checks its example), still within the small-model
    budget; its object-form example is a program that checks clean."""
    plain, structured = system_prompt_for("full"), system_prompt_for("full", structured=True)
    assert "Only the JSON list" not in structured and "ONE JSON object" in structured
    assert "ONE JSON object" not in plain
    guided = system_prompt_for("compact", structured=True)
    assert "Only the JSON list" not in guided and "Only the JSON object" in guided
    assert estimate_tokens(guided) <= COMPACT_MAX_TOKENS
    example = json.loads(structured.split("Example:\n")[-1].strip())
    jsonschema.validate(example, program_schema())
    program = parse_program(example)
    assert check_program(program, Support(kind="table", size=(0.8, 1.2))).ok
