"""Requested values the solve did not keep: each explicit parameter of the program against the scene's final value.

The spatial optimiser trades every value it is given against overlaps and overhangs, and a
PLACE-ON goes to the nearest spot where the object rests (then, with a `stability` wish, the
stability search moves it again). A value is reported when the final one differs from the
request by more than its tolerance:

* positions and distances (PLACE-ON-BASE `x`/`y`, `distance`): 5 mm, about what the eye notices on a table;
* angles (`yaw_offset`): 2 degrees, shown in degrees; a facing rule (other than a random one) asks for its
  offset, 0, even when the program leaves it out;
* PLACE-ON `overlap` (share of the object's footprint over the target's, seen from above): 0.1, the voxel
  search's own resolution for a small object (one cell is several per cent of its bottom);
* PLACE-ON `x_offset`/`y_offset`: 1 cm (the search grid's cells are about half a centimetre, the stability
  search may move the object);
* `stability`: its band (see `solver/stability_search.target_band`), reported when the search did not reach it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import shapely

from physcensis.assets.model import Asset
from physcensis.program import Program, Relation
from physcensis.scene import PlacedObject
from physcensis.solver.objects import quaternion_yaw
from physcensis.solver.stability_search import target_band

LENGTH_TOLERANCE_M = 0.005
ANGLE_TOLERANCE_RAD = math.radians(2.0)
OVERLAP_TOLERANCE = 0.1
OFFSET_TOLERANCE_M = 0.01
ANGLE_PARAMS = frozenset({"yaw_offset"})
SPATIAL_WHY = (
    "the layout optimiser moved it to keep the objects apart and on the support (it trades every requested value "
    "against overlaps and overhangs)"
)
SPATIAL_TURN_WHY = "the layout optimiser turned it to keep the objects apart and on the support"


@dataclass(frozen=True)
class Unmet:
    """One requested value the scene does not hold, and why."""

    entry: int
    predicate: str
    object_id: str | None
    parameter: str
    requested: Any
    final: Any
    why: str

    def to_dict(self) -> dict[str, Any]:
        return {
            "entry": self.entry,
            "predicate": self.predicate,
            "object": self.object_id,
            "parameter": self.parameter,
            "requested": self.requested,
            "final": self.final,
            "why": self.why,
        }

    def text(self) -> str:
        who = f"{self.object_id} " if self.object_id else ""
        requested, final = _shown_apart(self.requested, self.final, degrees=self.parameter in ANGLE_PARAMS)
        if self.parameter == "stability" and isinstance(self.requested, str) and isinstance(self.final, float):
            _, low, high = target_band(self.requested)  # "unstable" is p_fail 0.9 or more: 0.8999 must not read 0.9
            final = _shown_apart(low if low > 0.0 else high, self.final)[1]
        return (
            f"{who}(entry #{self.entry} {self.predicate}): {self.parameter} {requested} was asked for, "
            f"the scene has {final}: {self.why}"
        )


def _shown_apart(requested: Any, final: Any, *, degrees: bool = False) -> tuple[str, str]:
    """Both values as text, angles in degrees, with as many digits as it takes for two different numbers to read
    differently (a p_fail of 0.8999 against 0.9 asked for is not "0.9")."""
    if not (isinstance(requested, float | int) and isinstance(final, float | int)):
        return _shown(requested), _shown(final)
    a, b = (math.degrees(requested), math.degrees(final)) if degrees else (float(requested), float(final))
    unit = "°" if degrees else ""
    for digits in range(3, 7):
        shown = f"{a:.{digits}g}{unit}", f"{b:.{digits}g}{unit}"
        if shown[0] != shown[1] or a == b:
            break
    return shown


def _shown(value: Any) -> str:
    return f"{value:.3g}" if isinstance(value, float) else repr(value) if isinstance(value, str) else str(value)


def _tolerance(parameter: str) -> float:
    return ANGLE_TOLERANCE_RAD if parameter in ANGLE_PARAMS else LENGTH_TOLERANCE_M


def spatial_changes(program: Program, params: dict[int, dict[str, float]]) -> list[Unmet]:
    """Explicit numeric values of 2-D predicates that the layout optimiser changed beyond their tolerance."""
    by_index = {rel.index: rel for rel in program.relations}
    changes = []
    for index, finals in params.items():
        rel = by_index.get(index)
        if rel is None:
            continue
        for name, final in finals.items():
            requested = rel.params.get(name, _asked_by_default(rel, name))
            if isinstance(requested, bool) or not isinstance(requested, int | float):
                continue  # a default the program did not give, or not a number
            if abs(float(final) - float(requested)) > _tolerance(name):
                subject = rel.subject if isinstance(rel.subject, str) else None
                why = SPATIAL_TURN_WHY if name in ANGLE_PARAMS else SPATIAL_WHY
                changes.append(
                    Unmet(index, rel.predicate, subject, name, float(requested), round(float(final), 4), why)
                )
    return changes


def _asked_by_default(rel: Relation, name: str) -> float | None:
    """A facing's yaw offset is asked for even when the program leaves it out: FACING-FRONT with no parameters asks
    for the front (a default distance or position is only where the optimiser starts)."""
    spec = rel.spec
    if name not in ANGLE_PARAMS or spec is None or spec.yaw is None or not spec.yaw.mode.has_offset:
        return None
    param = spec.param(name)
    return None if param is None or param.default is None else float(param.default)


def footprint_overlap(obj: PlacedObject, asset: Asset, target: PlacedObject, target_asset: Asset) -> float:
    """Share of the object's footprint (convex hull from above) that lies over the target's."""
    mine, theirs = _footprint(obj, asset), _footprint(target, target_asset)
    area = float(mine.area)
    return float(mine.intersection(theirs).area) / area if area > 0.0 else 0.0


def _footprint(obj: PlacedObject, asset: Asset) -> shapely.Polygon:
    yaw = quaternion_yaw(obj.quaternion)
    c, s = math.cos(yaw), math.sin(yaw)
    hull = np.asarray(asset.footprint(), dtype=float)
    xy = hull @ np.array([[c, s], [-s, c]]) + np.asarray(obj.position[:2])
    return shapely.Polygon(xy)


def final_on_geometry(obj: PlacedObject, asset: Asset, target: PlacedObject, target_asset: Asset) -> dict[str, float]:
    """A PLACE-ON object's overlap and x/y offsets from its target's centre, as the scene holds them."""
    return {
        "overlap": round(footprint_overlap(obj, asset, target, target_asset), 3),
        "x_offset": round(obj.position[0] - target.position[0], 4),
        "y_offset": round(obj.position[1] - target.position[1], 4),
    }


def placement_changes(record: dict[str, Any], params: dict[str, Any]) -> list[Unmet]:
    """A PLACE-ON record's requested overlap, offsets and stability against what the scene holds."""
    if not record.get("ok"):
        return []  # a failed object has its own reason
    changes = []
    searched = record.get("stability")
    moved = searched["moved_m"] if searched else 0.0
    for name, tolerance in (
        ("overlap", OVERLAP_TOLERANCE),
        ("x_offset", OFFSET_TOLERANCE_M),
        ("y_offset", OFFSET_TOLERANCE_M),
    ):
        requested, final = params.get(name), record.get(name)
        if requested is None or final is None or abs(float(final) - float(requested)) <= tolerance:
            continue
        why = _geometry_why(name, float(requested), float(final), record, moved)
        changes.append(_on_change(record, name, float(requested), final, why))
    if searched and not searched["reached"]:
        why = f"the stability search ended ({searched['stop_reason']}); this is the closest standing state it found"
        changes.append(_on_change(record, "stability", searched["target"], round(searched["p_fail"], 4), why))
    return changes


def _on_change(record: dict[str, Any], name: str, requested: Any, final: Any, why: str) -> Unmet:
    return Unmet(record["entry"], record["predicate"], record["object"], name, requested, final, why)


def _geometry_why(name: str, requested: float, final: float, record: dict[str, Any], moved_m: float) -> str:
    searched = record.get("stability")
    before = record.get(f"{name}_placed")
    if searched and moved_m > 0.001 and (before is None or abs(before - final) > 1e-3):
        return f"the stability search moved it {moved_m * 100:.1f} cm to make it {searched['target']}"
    if name != "overlap":
        return (
            "the nearest spot on the target where it rests is there (the offset would leave it unsupported or crowd it)"
        )
    if requested < final:
        return "with less of it over the target its centre of mass would not be supported: it would tip off"
    return "the target's top has no free spot where that much of it fits (the target is smaller or crowded)"
