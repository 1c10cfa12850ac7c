"""Feedback for the agent, as text and as data: grammar problems, solver failures, crowding, metrics."""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, field
from typing import Any

from physcensis.assets.catalogue import Catalogue
from physcensis.feedback.regions import (
    compactness,
    coverage,
    crowding_words,
    describe_region,
    empty_regions,
)
from physcensis.program import CheckReport
from physcensis.solver.pipeline import Solution


@dataclass
class Feedback:
    """What one round tells the agent."""

    kind: str  # "grammar", "solver" or "success"
    text: str
    failed: list[str] = field(default_factory=list)
    data: dict[str, Any] = field(default_factory=dict)


def grammar_feedback(report: CheckReport | None, parse_error: str | None = None) -> Feedback:
    """The program could not be read or checked: every problem, with its entry index."""
    if parse_error:
        text = (
            f"Your reply could not be read as a program: {parse_error}. Reply with one JSON list of entries "
            '[id, "description"] and [A, "PREDICATE", B, {params}].'
        )
        return Feedback("grammar", text, data={"parse_error": parse_error})
    assert report is not None
    lines = [f"The program has {report.summary()}; fix them and keep everything else:"]
    lines += [f"- {p}" for p in report.problems]
    return Feedback("grammar", "\n".join(lines), data={"problems": [p.to_dict() for p in report.problems]})


def scene_metrics(solution: Solution, catalogue: Catalogue | None = None) -> dict[str, Any]:
    scene = solution.scene
    placements = scene.metrics.get("placements", [])
    fragile = {p["object"]: p["p_fail"] for p in placements if p.get("p_fail") is not None}
    return {
        "objects_placed": len(scene.placed),
        "objects_failed": sum(o.status == "failed" for o in scene.objects),
        "coverage": round(coverage(scene, catalogue), 3),
        "compactness": round(compactness(scene, catalogue), 3),
        "settle_distance_m": scene.metrics.get("settle_distance_m"),
        "p_fail": fragile,
    }


def solver_feedback(solution: Solution, catalogue: Catalogue | None = None) -> Feedback:
    """The program was valid but some objects could not be placed: which, why, and where there is room."""
    failed = [o for o in solution.scene.objects if o.status == "failed"]
    lines = [f"The scene was solved but {len(failed)} object(s) could not be placed:"]
    lines += [f"- {o.id} ({o.placement.predicate if o.placement else 'placement'}): {o.reason}" for o in failed]
    lines += _room_lines(solution, catalogue)
    lines.append(
        "Revise the program: move or shrink what failed, stack it with PLACE-ON, put it in a container "
        "with PLACE-IN, use PLACE-ANYWHERE, or remove it. Keep the objects that worked."
    )
    lines += _fallback_lines(solution)
    lines += _warning_lines(solution)
    metrics = {**scene_metrics(solution, catalogue), "fallbacks": solution.fallbacks(), "warnings": solution.warnings}
    return Feedback("solver", "\n".join(lines), failed=[o.id for o in failed], data=metrics)


def success_feedback(solution: Solution, catalogue: Catalogue | None = None, *, enrich: bool = False) -> Feedback:
    """Every object was placed: the metrics, and (when enriching) where more could go."""
    metrics = scene_metrics(solution, catalogue)
    lines = [
        f"All {metrics['objects_placed']} objects were placed and rest stably "
        f"(coverage {metrics['coverage']:.0%}, compactness {metrics['compactness']:.2f}, settle distance "
        f"{(metrics['settle_distance_m'] or 0) * 1000:.2f} mm)."
    ]
    if metrics["p_fail"]:
        lines.append(
            "Probability of falling of the fragile placements: "
            + ", ".join(f"{k} {v:.2f}" for k, v in metrics["p_fail"].items())
        )
    lines += _fallback_lines(solution)
    lines += _warning_lines(solution)
    if enrich:
        lines += _room_lines(solution, catalogue)
        lines.append(
            "Add more objects that suit the scene around the existing ones (stack some with PLACE-ON, "
            "fill containers with PLACE-IN, use PLACE-ANYWHERE in crowded places); write the whole program "
            "again with the new objects at the end."
        )
    data = {**metrics, "fallbacks": solution.fallbacks(), "warnings": solution.warnings}
    return Feedback("success", "\n".join(lines), data=data)


def _warning_lines(solution: Solution) -> list[str]:
    """Values the program asked for that the scene does not hold: requested, final and why, so the next program can
    ask for something that can be met."""
    if not solution.warnings:
        return []
    lines = ["Some requested values could not be kept:"]
    lines += [f"- {w['text']}" for w in solution.warnings]
    return lines


def _fallback_lines(solution: Solution) -> list[str]:
    """Which nouns the catalogue does not know and the stand-in each became (a describable object may do better)."""
    rows = solution.fallbacks()
    if not rows:
        return []
    lines = ["Some objects are not in the asset catalogue and were given stand-in shapes:"]
    lines += [f"- {row['note']}: {', '.join(row['objects'])}" for row in rows]
    return lines


def _room_lines(solution: Solution, catalogue: Catalogue | None) -> list[str]:
    scene = solution.scene
    covered = coverage(scene, catalogue)
    lines = [f"The {scene.support.kind} is {crowding_words(covered)} ({covered:.0%} of its top is covered)."]
    regions = empty_regions(scene, catalogue)
    if regions:
        lines += [f"There is {describe_region(r, scene, catalogue)}." for r in regions]
    else:
        lines.append("There is no empty region left large enough for another object on the support itself.")
    return lines


def repeat_feedback(
    previous: Feedback, first_round: int, repeats: int, entries: list[Any] | None = None, dropped: bool = False
) -> Feedback:
    """A reply that is the same program as one that already failed: say so, and change strategy.

    Names the first error (preferring one the checker can correct, with the exact corrected entry), asks for fewer
    objects, and, when `dropped`, says that the loop dropped the failing objects itself."""
    lines = [
        f"Your reply is the same program as round {first_round}, which failed because:",
        _indented(previous.text),
        "Sending it again cannot work. Change strategy:",
    ]
    first = _first_error(previous, entries or [])
    if first is not None:
        problem, entry, fixed = first
        lines.append(f"- Fix this error first: {problem['message']}")
        if entry is not None:
            lines.append(f"  The entry is {_compact(entry)}" + (f"; write it as {_compact(fixed)}." if fixed else "."))
    elif previous.failed:
        lines.append(f"- Remove or move the objects that failed: {', '.join(previous.failed)}.")
    lines.append("- Use fewer objects: keep only the main ones with simple placements (PLACE-ON-BASE with x and y).")
    if dropped:
        lines.append(
            "The failing objects were dropped from your program for you, or moved to free spots (PLACE-ANYWHERE); "
            "continue from that program."
        )
    data = {"repeat_of_round": first_round, "repeats": repeats}
    return Feedback(previous.kind, "\n".join(lines), failed=list(previous.failed), data={**previous.data, **data})


def _indented(text: str) -> str:
    return "\n".join(f"  {line}" for line in text.strip().splitlines())


def _first_error(
    feedback: Feedback, entries: list[Any]
) -> tuple[dict[str, Any], list[Any] | None, list[Any] | None] | None:
    """(problem, its entry, the corrected entry) of the first error the checker can correct, else of the first."""
    found = []
    for problem in feedback.data.get("problems", []):
        if problem.get("severity") != "error":
            continue
        index = problem.get("index")
        entry = entries[index - 1] if isinstance(index, int) and 0 < index <= len(entries) else None
        fixed = corrected_entry(entry, problem) if isinstance(entry, list) else None
        if fixed is not None:
            return problem, entry, fixed
        found.append((problem, entry if isinstance(entry, list) else None, None))
    return found[0] if found else None


def _compact(entry: Any) -> str:
    return json.dumps(entry, ensure_ascii=False)


_SUGGESTION = re.compile(r"did you mean '?([^'?]+)'?\?")
_QUOTED = re.compile(r"'([^']*)'")


def corrected_entry(entry: list[Any], problem: dict[str, Any]) -> list[Any] | None:
    """`entry` with the checker's "did you mean" suggestion applied to the name it flagged, or None when the
    checker suggested nothing (or the flagged name is not in the entry)."""
    message = str(problem.get("message", ""))
    suggestion, wrong = _SUGGESTION.search(message), _QUOTED.search(message)
    if suggestion is None or wrong is None:
        return None
    old, new = wrong.group(1), suggestion.group(1)
    fixed = [_renamed(part, old, new) for part in entry]
    return fixed if fixed != entry else None


def _renamed(part: Any, old: str, new: str) -> Any:
    if part == old:
        return new
    if isinstance(part, dict):
        return {(new if key == old else key): value for key, value in part.items()}
    return part
