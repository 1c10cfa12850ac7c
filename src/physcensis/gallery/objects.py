"""What the report's 3-D viewer shows for an object picked in a scene: its id, asset, category, mass, friction, the
program's statements about it (the predicates that placed it) and its p_fail when the scene records one.

Taken from the scene folder's scene.json (objects, program, metrics) and report.json (its metrics, which a solve
writes too); like everything on a card, plain data shown as text. Only placed objects are listed: they are the ones
scene.glb holds, as nodes named by their ids (export/glb.py).
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from typing import Any

MAX_OBJECTS = 10_000  # per scene: a scene.json written by hand could list any number
MAX_STATEMENTS = 50  # program statements shown per object


def scene_objects(scene_json: Mapping[str, Any], report: Mapping[str, Any]) -> list[dict[str, Any]]:
    """One entry per placed object of the scene, in the scene's order; an id seen twice is kept once."""
    objects = scene_json.get("objects")
    if not isinstance(objects, list):
        return []
    statements = _statements(scene_json.get("program"))
    risks = _p_fail(report.get("metrics")) | _p_fail(scene_json.get("metrics"))
    listed: dict[str, dict[str, Any]] = {}
    for obj in objects[:MAX_OBJECTS]:
        if not isinstance(obj, Mapping) or not isinstance(obj.get("id"), str) or obj["id"] in listed:
            continue
        if obj.get("status", "placed") != "placed":
            continue
        oid = obj["id"]
        listed[oid] = {
            "id": oid,
            "asset": _text(obj.get("asset")),
            "category": _text(obj.get("category")),
            "description": _text(obj.get("description")),
            "mass": _number(obj.get("mass")),
            "friction": _number(obj.get("friction")),
            "predicates": statements.get(oid, []) or _placement_line(obj.get("placement")),
            "p_fail": risks.get(oid),
        }
    return list(listed.values())


def _statements(program: Any) -> dict[str, list[str]]:
    """Per subject, its program statements other than the description: `PREDICATE target {params}`."""
    lines: dict[str, list[str]] = {}
    if not isinstance(program, list):
        return lines
    for entry in program:
        if not isinstance(entry, list) or len(entry) < 3 or not isinstance(entry[0], str):
            continue  # a description ([id, text]) or not a statement
        mine = lines.setdefault(entry[0], [])
        if len(mine) < MAX_STATEMENTS:
            mine.append(_statement_line(entry[1], entry[2], entry[3] if len(entry) > 3 else None))
    return lines


def _statement_line(predicate: Any, target: Any, params: Any) -> str:
    line = f"{_text(predicate)} {_text(target)}".strip()
    if isinstance(params, Mapping) and params:
        line += " " + json.dumps(params, default=str, separators=(", ", ": "))
    return line


def _placement_line(placement: Any) -> list[str]:
    """The object's own placement record, for a scene.json without a program."""
    if not isinstance(placement, Mapping) or not placement.get("predicate"):
        return []
    return [_statement_line(placement.get("predicate"), placement.get("target"), None)]


def _p_fail(metrics: Any) -> dict[str, float]:
    """p_fail per object where the scene measured it: the placement records of a PLACE-ON with a stability wish."""
    placements = metrics.get("placements") if isinstance(metrics, Mapping) else None
    found: dict[str, float] = {}
    for record in placements if isinstance(placements, list) else []:
        if isinstance(record, Mapping) and isinstance(record.get("object"), str):
            value = _number(record.get("p_fail"))
            if value is not None:
                found[record["object"]] = value
    return found


def _number(value: Any) -> float | None:
    if isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value):
        return float(value)
    return None


def _text(value: Any) -> str:
    return "" if value is None else value if isinstance(value, str) else json.dumps(value, default=str)
