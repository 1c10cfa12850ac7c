"""The final verification's rule for what keeps creeping under MuJoCo's defaults, on scripted engines: a pile that
slides apart over several seconds fails with its reason, fruit that rolls a little further into its bowl stays."""

from __future__ import annotations

from typing import Any, cast

from physcensis.physics.engine import DEFAULT_TOLERANCE, ObjectMotion, SettleResult
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.scene import PlacedObject, Placement, Scene, Support
from physcensis.solver.pipeline import CREPT_M, LONG_CREEP_S, verify

from ..scenes import placed_object


def motion(obj: PlacedObject, dx: float, *, ok: bool = True) -> ObjectMotion:
    x, y, z = obj.position
    reason = None if ok else f"moved {dx * 100:.1f} cm"
    return ObjectMotion(obj.id, dx, 0.0, False, 0.0, 0.0, (x + dx, y, z), obj.quaternion, ok, reason)


class Scripted:
    """Settles by a script: `moves[id]` for a settle of the paper's 4 s, `long[id]` for the longer watch."""

    def __init__(self, moves: dict[str, float], long: dict[str, float] | None = None, strict: Any = None) -> None:
        self.moves, self.long, self.strict = moves, long or {}, strict
        self.calls: list[float] = []

    def defaults_check(self) -> Any:
        return self.strict

    def settle(self, scene: Scene, *, tolerance: Any = DEFAULT_TOLERANCE, duration_s: float = 1.5) -> SettleResult:
        self.calls.append(duration_s)
        script = self.long if duration_s == LONG_CREEP_S else self.moves
        objects = {
            o.id: motion(o, script.get(o.id, 0.0), ok=script.get(o.id, 0.0) <= tolerance.translation_m)
            for o in scene.placed
        }
        return SettleResult(objects, duration_s, 0.0)


def scene_of(*ids: str) -> Scene:
    objects = [placed_object(oid, "ycb_024_bowl", 0.2 * k, 0.0, 0.78) for k, oid in enumerate(ids)]
    return Scene(seed=0, support=Support(kind="table", size=(1.2, 0.8)), objects=objects)


def test_what_keeps_creeping_and_then_slides_apart_fails_and_what_settles_stays() -> None:
    creep = 2 * CREPT_M
    strict = Scripted({"pile": creep, "fruit": creep}, long={"pile": 0.03, "fruit": 0.004})
    scene = scene_of("pile", "fruit", "still")
    verify(scene, cast(MujocoEngine, Scripted({}, strict=strict)), DEFAULT_TOLERANCE)
    status = {o.id: (o.status, o.reason or "") for o in scene.objects}
    assert status["pile"][0] == "failed" and "kept creeping" in status["pile"][1] and "3.0 cm" in status["pile"][1]
    assert status["fruit"][0] == "placed" and status["still"][0] == "placed"
    assert LONG_CREEP_S in strict.calls  # watched longer only once something crept a second time


def test_creeping_once_takes_the_crept_pose_without_a_longer_watch() -> None:
    class OnceThenStill(Scripted):
        def settle(self, scene: Scene, **kwargs: Any) -> SettleResult:
            result = super().settle(scene, **kwargs)
            self.moves = {}  # it found its place: nothing creeps any more
            return result

    scene = scene_of("fruit")
    before = scene.object("fruit").position[0]
    once = OnceThenStill({"fruit": 2 * CREPT_M})
    verify(scene, cast(MujocoEngine, Scripted({}, strict=once)), DEFAULT_TOLERANCE)
    fruit = scene.object("fruit")
    assert fruit.status == "placed" and fruit.position[0] == before + 2 * CREPT_M
    assert LONG_CREEP_S not in once.calls


def test_a_containers_contents_that_slide_deeper_are_not_failed_by_the_longer_watch() -> None:
    creep = 2 * CREPT_M
    strict = Scripted({"pencil": creep, "pile": creep}, long={"pencil": 0.015, "pile": 0.03})
    scene = scene_of("mug", "pencil", "pile")
    scene.objects = [
        o.model_copy(update={"placement": Placement(predicate="PLACE-IN", target="mug")}) if o.id == "pencil" else o
        for o in scene.objects
    ]
    verify(scene, cast(MujocoEngine, Scripted({}, strict=strict)), DEFAULT_TOLERANCE)
    assert scene.object("pencil").status == "placed"
    assert scene.object("pile").status == "failed"
