"""The public prompt suite against any OpenAI-compatible endpoint: how well a real model plays the agent.

`python -m physcensis.bench llm --base-url URL --model NAME [--out DIR]` generates every prompt of the suite with
that model and reports, per prompt and in total: whether the first reply parsed and checked clean, the rounds to the
first success, whether the prompt's expect block was met, tokens and seconds. Each prompt's record (the transcript
and report, also for a prompt that ended without a scene) is written under `--out`.
"""

from __future__ import annotations

import argparse
import json
import logging
import statistics
import sys
import time
from pathlib import Path
from typing import Any

from physcensis.agent.hint import HINT_MODES
from physcensis.bench.prompt_suite import SUITES, check_expectations, load_suite
from physcensis.errors import PhyscensisError
from physcensis.fileio import atomic_write_text
from physcensis.machine import machine_info
from physcensis.program.schema import STRUCTURED_MODES
from physcensis.scene import Support
from physcensis.settings import LLM_WRITES

PROMPT_STYLES = ("auto", "full", "compact")


def first_reply_clean(transcript: list[dict[str, Any]]) -> bool:
    """Whether the model's first reply parsed and passed the checker (a solver failure still counts as clean)."""
    first = next((row for row in transcript if row.get("round") == 1 and "agent" in row), None)
    return first is not None and first.get("feedback_kind") not in (None, "grammar")


def _first_graph_clean(transcript: list[dict[str, Any]], graph: dict[str, Any]) -> bool:
    """Whether the model's first scene graph was used as it came (`--llm-writes graph`)."""
    replies = [row for row in transcript if "graph_request" in row and not row.get("error")]  # refusals aside
    return len(replies) == 1 and graph["source"] == "model"


def rounds_to_success(transcript: list[dict[str, Any]]) -> int | None:
    """The round of the first of the model's replies that gave a scene with every object placed, or None (a program
    the loop repaired itself, `loop-repair`, is not the model's)."""
    return next(
        (
            int(row["round"])
            for row in transcript
            if row.get("feedback_kind") == "success" and row.get("agent") != "loop-repair"
        ),
        None,
    )


def tokens_used(transcript: list[dict[str, Any]]) -> dict[str, int]:
    """Prompt and completion tokens over every request the server reported usage for."""
    totals = {"prompt_tokens": 0, "completion_tokens": 0}
    for row in transcript:
        usage = row.get("usage") or {}
        for key in totals:
            value = usage.get(key)
            if isinstance(value, int):
                totals[key] += value
    return totals


def run_case(case: dict[str, Any], options: argparse.Namespace) -> dict[str, Any]:
    """One prompt with the model; its record is written to `options.out / id` whatever the outcome."""
    from physcensis.api import generate, write_generated

    support = Support(kind=case["support"]["kind"], size=tuple(case["support"]["size"]))
    begun = time.perf_counter()
    generated = generate(
        case["prompt"],
        support=support,
        seed=options.seed,
        llm=options.model,
        base_url=options.base_url,
        llm_timeout_s=options.llm_timeout,
        structured=options.structured,
        prompt_style=options.prompt,
        hint=options.hint,
        llm_writes=options.llm_writes,
        temperature=options.temperature,
        time_budget_s=options.time_budget,
        min_objects=case.get("expect", {}).get("min_objects", 0),
        stream=options.stream,
    )
    wall_s = time.perf_counter() - begun  # with --llm-writes graph, the graph's request comes before the rounds
    transcript = generated.transcript
    scene = generated.solution.scene if generated.solution else None
    graph = generated.scene_graph if options.llm_writes == "graph" else None
    problems = check_expectations(scene, case.get("expect", {})) if scene else ["no scene"]
    write_generated(generated, options.out / case["id"], exports=("none",))  # the record, scene and pictures
    return {
        "id": case["id"],
        "first_reply_clean": _first_graph_clean(transcript, graph) if graph else first_reply_clean(transcript),
        "rounds_to_success": rounds_to_success(transcript),
        "rounds": generated.result.rounds,
        "expect_met": not problems,
        "problems": problems,
        "objects": len(scene.placed) if scene else 0,
        "seconds": round(wall_s, 1),
        "graph_source": graph["source"] if graph else None,
        "tokens": tokens_used(transcript),
        "stop_reason": generated.result.stop_reason,
        "record": (options.out / case["id"] / "transcript.jsonl").is_file(),
    }


def summary(rows: list[dict[str, Any]]) -> dict[str, Any]:
    """Shares over the prompts run, and medians of rounds and seconds."""
    n = len(rows)
    successes = [r["rounds_to_success"] for r in rows if r["rounds_to_success"] is not None]
    return {
        "prompts": n,
        "first_reply_clean": sum(r["first_reply_clean"] for r in rows) / n if n else 0.0,
        "expect_met": sum(r["expect_met"] for r in rows) / n if n else 0.0,
        "with_record": sum(r["record"] for r in rows) / n if n else 0.0,
        "median_rounds_to_success": statistics.median(successes) if successes else None,
        "median_seconds": statistics.median(r["seconds"] for r in rows) if n else None,
        "tokens": {k: sum(r["tokens"][k] for r in rows) for k in ("prompt_tokens", "completion_tokens")},
    }


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="python -m physcensis.bench llm", description=__doc__)
    parser.add_argument("--base-url", required=True, help="the server, e.g. http://127.0.0.1:8080/v1")
    parser.add_argument("--model", required=True, help="the model name the server knows")
    parser.add_argument("--out", type=Path, default=Path("bench/results/llm"), help="records and llm.json go here")
    parser.add_argument("--suite", choices=sorted(SUITES), default="public", help="which prompt suite")
    parser.add_argument("--only", nargs="*", help="run only these prompt ids")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--structured", choices=STRUCTURED_MODES, default="auto")
    parser.add_argument("--prompt", choices=PROMPT_STYLES, default="auto", help="the system prompt's style")
    parser.add_argument("--temperature", type=float, default=0.7, help="the model's sampling temperature")
    parser.add_argument("--hint", choices=HINT_MODES, default="auto", help="the offline reading as a draft")
    parser.add_argument(
        "--llm-writes", choices=LLM_WRITES, default="program", help="the whole program, or only the scene graph"
    )
    parser.add_argument("--llm-timeout", type=float, default=300.0, help="seconds per request, retries included")
    parser.add_argument("--time-budget", type=float, default=900.0, help="seconds per prompt")
    parser.add_argument(
        "--stream",
        action="store_true",
        help="stream replies (off by default: some servers, llama-cpp-python's among them, count tokens only then)",
    )
    args = parser.parse_args(argv)
    known = {c["id"] for c in load_suite(SUITES[args.suite])}
    unknown = sorted(set(args.only or ()) - known)
    if unknown:
        parser.error(f"unknown prompt id(s) {', '.join(unknown)}")
    return args


def main(argv: list[str] | None = None) -> int:
    options = parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(message)s")
    cases = [c for c in load_suite(SUITES[options.suite]) if not options.only or c["id"] in options.only]
    rows = []
    for index, case in enumerate(cases, 1):
        try:
            row = run_case(case, options)
        except PhyscensisError as exc:  # a folder that cannot be written, a refused option: stop with one line
            print(f"error: {case['id']}: {exc}", file=sys.stderr)
            return 2
        rows.append(row)
        logging.info("[%d/%d] %s", index, len(cases), json.dumps(row))
    record = {
        "benchmark": "llm",
        "machine": machine_info(),
        "model": options.model,
        "structured": options.structured,
        "prompt": options.prompt,
        "hint": options.hint,
        "suite": options.suite,
        "llm_writes": options.llm_writes,
        "temperature": options.temperature,
        "summary": summary(rows),
        "prompts": rows,
    }
    atomic_write_text(options.out / "llm.json", json.dumps(record, indent=2) + "\n")
    logging.info("summary: %s", json.dumps(record["summary"]))
    return 0
