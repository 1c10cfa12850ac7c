"""The final verification's rules under MuJoCo's defaults, on scripted engines: a pile that slides apart over several
seconds fails with its reason, fruit that rolls a little further into its bowl stays; the scene as it would be written
is verified under the defaults alone, and what tips over there fails."""

from __future__ import annotations

import math
from typing import Any, cast

from physcensis.physics.engine import DEFAULT_TOLERANCE, SETTLE_S, ObjectMotion, SettleResult
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.scene import PlacedObject, Placement, Scene, Support
from physcensis.solver.pipeline import CREPT_M, LONG_CREEP_S, VERIFY_ROUNDS, verify

from ..scenes import placed_object


def motion(obj: PlacedObject, dx: float, *, ok: bool = True, turn: float = 0.0) -> ObjectMotion:
    x, y, z = obj.position
    reason = None if ok else f"moved {dx * 100:.1f} cm and turned {math.degrees(turn):.0f} deg"
    return ObjectMotion(obj.id, dx, turn, False, 0.0, 0.0, (x + dx, y, z), obj.quaternion, ok, reason)


class Scripted:
    """Settles by a script: `moves[id]` for a settle of the paper's 4 s (the defaults' check of each round),
    `long[id]` for the longer watch; a settle of the engine's own length moves nothing (the scene is at rest)."""

    def __init__(self, moves: dict[str, float], long: dict[str, float] | None = None, strict: Any = None) -> None:
        self.moves, self.long, self.strict = moves, long or {}, strict
        self.calls: list[float] = []

    def defaults_check(self) -> Any:
        return self.strict

    def settle(self, scene: Scene, *, tolerance: Any = DEFAULT_TOLERANCE, duration_s: float = 1.5) -> SettleResult:
        self.calls.append(duration_s)
        scripts = {LONG_CREEP_S: self.long, SETTLE_S: self.moves}
        return self.scripted(scene, tolerance, duration_s, scripts.get(duration_s, {}), {})

    @staticmethod
    def scripted(
        scene: Scene, tolerance: Any, duration_s: float, moves: dict[str, float], turns: dict[str, float]
    ) -> SettleResult:
        def moved(o: PlacedObject) -> ObjectMotion:
            dx, turn = moves.get(o.id, 0.0), turns.get(o.id, 0.0)
            return motion(o, dx, ok=dx <= tolerance.translation_m and turn <= tolerance.rotation_rad, turn=turn)

        return SettleResult({o.id: moved(o) for o in scene.placed}, duration_s, 0.0)


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


class Tipping(Scripted):
    """MuJoCo's defaults for the final check (a settle of the engine's own length): `tipping` moves `per_round` and
    turns 5 degrees in each, except in round `falls_in` (it moves 2 cm) and round `turns_in` (it turns 15 degrees
    where it stands); `contents` moves 2 cm in the first."""

    def __init__(self, per_round: float, falls_in: int | None = None, turns_in: int | None = None) -> None:
        super().__init__({})
        self.per_round, self.falls_in, self.turns_in, self.rounds = per_round, falls_in, turns_in, 0

    def settle(self, scene: Scene, *, tolerance: Any = DEFAULT_TOLERANCE, duration_s: float = 1.5) -> SettleResult:
        if duration_s in (SETTLE_S, LONG_CREEP_S):
            return super().settle(scene, tolerance=tolerance, duration_s=duration_s)
        self.rounds += 1
        falls, turns = self.rounds == self.falls_in, self.rounds == self.turns_in
        moves = {"tipping": 0.02 if falls else self.per_round, "contents": 0.02 if self.rounds == 1 else 0.0}
        return self.scripted(scene, tolerance, duration_s, moves, {"tipping": math.radians(15.0 if turns else 5.0)})


class LosesOnePerCheck(Scripted):
    """MuJoCo's defaults for the final check: in each check's first round, the first object left moves 2 cm."""

    def settle(self, scene: Scene, *, tolerance: Any = DEFAULT_TOLERANCE, duration_s: float = 1.5) -> SettleResult:
        if duration_s in (SETTLE_S, LONG_CREEP_S):
            return super().settle(scene, tolerance=tolerance, duration_s=duration_s)
        self.calls.append(duration_s)
        return self.scripted(scene, tolerance, duration_s, {scene.placed[0].id: 0.02}, {})


def scene_with_contents(*ids: str) -> Scene:
    scene = scene_of(*ids, "contents")
    scene.objects = [
        o.model_copy(update={"placement": Placement(predicate="PLACE-IN", target=ids[0])}) if o.id == "contents" else o
        for o in scene.objects
    ]
    return scene


def test_what_tips_over_in_the_third_round_under_the_defaults_alone_fails_with_why_and_the_rest_settles_again() -> None:
    scene = scene_with_contents("tipping", "still")
    ours = Scripted({}, strict=Tipping(per_round=0.002, falls_in=3))
    verify(scene, cast(MujocoEngine, ours), DEFAULT_TOLERANCE)
    tipping = scene.object("tipping")
    assert tipping.status == "failed" and "default contact settings, within 4.5 s" in (tipping.reason or "")
    assert scene.object("still").status == "placed" and scene.object("contents").status == "placed"
    assert tipping.position == scene_of("tipping").object("tipping").position  # the scene itself was not moved there
    assert len(ours.calls) == 2  # settled, checked, and once it lost the bottle settled (and checked) again


def test_what_turns_too_far_in_a_round_under_the_defaults_alone_fails_though_it_stays_in_place() -> None:
    scene = scene_with_contents("tipping", "still")
    verify(scene, cast(MujocoEngine, Scripted({}, strict=Tipping(per_round=0.002, turns_in=2))), DEFAULT_TOLERANCE)
    tipping = scene.object("tipping")
    assert tipping.status == "failed" and "turned 15 deg" in (tipping.reason or "")


def test_the_final_check_fails_objects_at_most_twice_and_the_scene_settles_after_each() -> None:
    scene = scene_of("a", "b", "c", "d")
    defaults = LosesOnePerCheck({})
    ours = Scripted({}, strict=defaults)
    verify(scene, cast(MujocoEngine, ours), DEFAULT_TOLERANCE)
    assert [o.status for o in scene.objects] == ["failed", "failed", "placed", "placed"]
    assert defaults.calls.count(SETTLE_S) == 3  # each settle round is checked under the defaults too
    assert len(defaults.calls) - 3 == 2 and len(ours.calls) == 3  # two final checks, three rounds of settling


def test_what_creeps_a_little_every_round_under_the_defaults_alone_stays_and_a_settled_scene_is_checked_once() -> None:
    scene = scene_with_contents("tipping", "still")
    defaults = Tipping(per_round=0.002)
    verify(scene, cast(MujocoEngine, Scripted({}, strict=defaults)), DEFAULT_TOLERANCE)
    assert all(o.status == "placed" for o in scene.objects)
    assert defaults.rounds == VERIFY_ROUNDS  # it never came to rest, and never moved too far in a round

    calm = Tipping(per_round=0.0)
    verify(scene_of("a", "b"), cast(MujocoEngine, Scripted({}, strict=calm)), DEFAULT_TOLERANCE)
    assert calm.rounds == 1
