"""How long parsing and checking take on a very large program (target: 10,000 objects in < 1 s)."""

from __future__ import annotations

import json
import statistics
import time
from typing import Any

from physcensis.program import check_program, parse_program


def large_program(n_objects: int) -> list[list[Any]]:
    """A row of cups, each placed relative to the previous one: five entries per object."""
    program: list[list[Any]] = []
    for i in range(n_objects):
        oid = f"cup_{i}"
        program.append([oid, f"a small ceramic cup number {i}"])
        program.append([oid, "PLACE-ON-BASE", "root", {"x": 0.0} if i == 0 else {}])
        if i == 0:
            program.append([oid, "ALIGN-CENTER-LR", "root", {}])
        else:
            program.append([oid, "LEFT-OF", f"cup_{i - 1}", {"distance": 0.01}])
            program.append([oid, "ALIGN-CENTER-FB", f"cup_{i - 1}", {}])
        program.append([oid, "FACING-FRONT", "root", {}])
    return program


def _median_seconds(fn: Any, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def run(n_objects: int = 10_000, repeats: int = 5) -> dict[str, Any]:
    text = json.dumps(large_program(n_objects))
    program = parse_program(text)
    report = check_program(program)
    assert report.ok, report.feedback()[:500]
    llm_text = "Here is the program:\n```json\n" + text.replace("}]", "},]") + "\n```"  # forces the lenient reader
    parse_s = _median_seconds(lambda: parse_program(text), repeats)
    lenient_s = _median_seconds(lambda: parse_program(llm_text), repeats)
    check_s = _median_seconds(lambda: check_program(program), repeats)
    return {
        "objects": n_objects,
        "entries": len(program.entries),
        "parse_median_s": round(parse_s, 4),
        "lenient_parse_median_s": round(lenient_s, 4),
        "check_median_s": round(check_s, 4),
        "parse_and_check_median_s": round(parse_s + check_s, 4),
        "target_s": 1.0,
        "repeats": repeats,
    }
