"""The paper's LLM-only baseline: the model writes every object's pose itself, as coordinates (no predicates, no
solver), and the scene is physics-checked like any other.

The objects are the agent's first program's (so the scene is judged against the same relations as every method);
the model is told the support, the frame, each object's size, and answers under a JSON Schema. A reply that misses
objects or gives impossible numbers goes back to it with what is wrong, for up to `ATTEMPTS` replies; objects it
never places are left out (and count against it: placed / requested, settle over requested).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from typing import Any

from physcensis.assets.model import Asset
from physcensis.errors import PhyscensisError
from physcensis.scene import Support

ATTEMPTS = 3
MAX_REACH_M = 5.0  # a pose farther from the support's centre than this is no pose on it
MAX_HEIGHT_M = 3.0

SYSTEM = """You lay out objects on a support by writing where each one goes, as numbers.
Frame: metres; the support's top is centred at x = 0, y = 0. x runs from the back (negative) to the front
(positive, towards the person looking at the scene); y from that person's left (negative) to their right (positive).
z is the height of the object's bottom above the support's top: 0 for something standing on the support, the top
of the thing below for something resting on another object. yaw is in degrees about the vertical: 0 turns the
object's front towards the person, 90 to their right.
Give every object listed exactly once, by its id, where the request and common sense put it, without overlaps.
Answer with JSON only: {"poses": [{"id": ..., "x": ..., "y": ..., "z": ..., "yaw": ...}, ...]}."""


@dataclass(frozen=True)
class Pose:
    x: float
    y: float
    z: float  # above the support's top
    yaw: float  # radians


def layout_schema(ids: list[str]) -> dict[str, Any]:
    """The JSON Schema of a reply: one pose per id (ids as an enum)."""
    number = {"type": "number"}
    pose = {
        "type": "object",
        "properties": {"id": {"type": "string", "enum": ids}, "x": number, "y": number, "z": number, "yaw": number},
        "required": ["id", "x", "y", "z", "yaw"],
        "additionalProperties": False,
    }
    return {
        "type": "object",
        "properties": {"poses": {"type": "array", "items": pose}},
        "required": ["poses"],
        "additionalProperties": False,
    }


def layout_messages(prompt: str, support: Support, objects: list[tuple[str, str, Asset]]) -> list[dict[str, Any]]:
    """The chat asking for the poses of `objects` ((id, description, asset)) for `prompt` on `support`."""
    hx, hy = support.half_extents
    lines = [
        f"- {oid}: {description}, {asset.size[0]:.2f} m deep, {asset.size[1]:.2f} m wide, {asset.size[2]:.2f} m tall"
        for oid, description, asset in objects
    ]
    user = (
        f"Request: {prompt}\nSupport: a {support.kind} top {2 * hx:.2f} m deep (x from {-hx:.2f} to {hx:.2f}) and "
        f"{2 * hy:.2f} m wide (y from {-hy:.2f} to {hy:.2f}).\nObjects:\n" + "\n".join(lines)
    )
    return [{"role": "system", "content": SYSTEM}, {"role": "user", "content": user}]


class LayoutReplyError(PhyscensisError):
    """A reply that gives no usable poses; the message says what is wrong (it goes back to the model)."""


def read_layout(reply: str, ids: list[str]) -> tuple[dict[str, Pose], list[str]]:
    """The poses a reply gives for `ids`, and the problems of those it does not give usably (LayoutReplyError
    when it is no layout at all)."""
    text = reply.strip()
    if text.startswith("```"):
        text = text.strip("`").removeprefix("json").strip()
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise LayoutReplyError(f"the reply is not JSON ({exc.msg} at character {exc.pos})") from None
    entries = data.get("poses") if isinstance(data, dict) else None
    if not isinstance(entries, list):
        raise LayoutReplyError('the reply has no "poses" list')
    poses: dict[str, Pose] = {}
    problems: list[str] = []
    for k, entry in enumerate(entries):
        oid = entry.get("id") if isinstance(entry, dict) else None
        if oid not in ids:
            problems.append(f"poses[{k}]: {oid!r} is not one of the objects listed")
            continue
        if oid in poses:
            problems.append(f"{oid}: given twice")
            continue
        values = [entry.get(key) for key in ("x", "y", "z", "yaw")]
        if not all(isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v) for v in values):
            problems.append(f"{oid}: x, y, z and yaw must all be numbers")
            continue
        x, y, z, yaw = (float(v) for v in values)
        if math.hypot(x, y) > MAX_REACH_M or not 0.0 <= z <= MAX_HEIGHT_M:
            problems.append(f"{oid}: ({x:g}, {y:g}, {z:g}) is not on the support (z from 0 to {MAX_HEIGHT_M:g} m)")
            continue
        poses[oid] = Pose(x, y, z, math.radians(yaw))
    problems += [f"{oid}: no pose given" for oid in ids if oid not in poses and not _named(problems, oid)]
    return poses, problems


def _named(problems: list[str], oid: str) -> bool:
    return any(p.startswith(f"{oid}:") for p in problems)
