"""PLACE-IN: dropping items into a placed container and keeping those that end inside it.

The items that fit the cavity (by volume, standing or lying) are chosen first; long ones a holder can hold on end are
stood on its floor, the rest are dropped from above the opening (spread out, stacked where they overlap) and dropped
again when they bounce out; then the container's contents settle until they rest. What does not end inside fails
with the reason. The voxel search of PLACE-ON and PLACE-ANYWHERE is `physical.PhysicalSolver`'s; this shares its scene,
engine, seed and time budget.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np
import shapely

from physcensis.assets.model import Asset, Cavity
from physcensis.geometry.voxels import quat_to_matrix
from physcensis.physics.engine import SETTLE_S as FINAL_SETTLE_S
from physcensis.physics.engine import Tolerance
from physcensis.physics.mujoco_engine import BuiltScene, MujocoEngine
from physcensis.physics.profiles import MUJOCO_DEFAULT, MUJOCO_DEFAULT_TOLERANCE, UNDER_DEFAULTS
from physcensis.program.registry import PlacementKind, placement_spec
from physcensis.scene import PlacedObject, Placement
from physcensis.solver.objects import compose_yaw, object_rng, physical_properties, yaw_quaternion
from physcensis.solver.packing_in import (
    ON_FLOOR_M,
    com_above_rim_reason,
    floor_order,
    footprint_of,
    is_tall,
    plan_floor_spots,
    stands_below_rim,
)
from physcensis.solver.physical import OUT_OF_TIME, PhysicalSolver, PlaceOutcome

PACKING = 0.6  # share of a cavity that dropped items can fill
PLACE_IN_SETTLES = 3  # rounds of settling a filled container until its contents rest
SETTLE_CONTENTS_S = 1.5  # each settle of a container's contents ...
SETTLE_CONTENTS_PILED_S = FINAL_SETTLE_S  # ... and of things piled in a wide one: as long as the defaults are watched
DROP_ROUNDS = 3  # items that bounce out of a container are dropped again
ON_END_COS = 0.7  # a long item whose long axis is this near vertical stands on end
HELD_ON_END = 0.35  # a holder at least this share of a long item's length deep holds it on end
SLENDER = 0.35  # an item whose middle side is at most this share of its longest is slender (a spoon)
UPRIGHT_TILT_RAD = math.radians(10.0)  # an item set standing in a container that tilts more fell over


class ContainerFilling:
    """PLACE-IN for the scene a `PhysicalSolver` is building: `place_in` adds what ends inside to its scene."""

    def __init__(self, solver: PhysicalSolver) -> None:
        self.solver = solver

    def place_in(
        self, items: Sequence[tuple[str, str, Asset]], container_id: str, predicate: str | None = None
    ) -> list[PlaceOutcome]:
        """Drop the items into a container from above its opening and keep those that end inside; `predicate` is
        recorded as what placed them (PLACE-IN by default)."""
        predicate = predicate or placement_spec(PlacementKind.IN).name
        cavity = OUT_OF_TIME if self.solver.out_of_time() else self._cavity(container_id)
        if isinstance(cavity, str):  # each item is still recorded in the scene, failed, with the reason
            where = self.solver.meant_for(container_id)
            return [
                self.solver.fail(oid, text, item, cavity, predicate, container_id, where) for oid, text, item in items
            ]
        cavity = replace(cavity, empty=not self._holds_anything(container_id))
        fitting, outcomes = self._fitting(items, cavity, predicate)
        stood = self._stand_on_floor(fitting, cavity, predicate)
        stood_ids = {o.id for o in stood}
        kept, why_not = self._drop([i for i in fitting if i[0] not in stood_ids], cavity, predicate, stood)
        kept, unstable, container = self._settle_contents(cavity, kept, why_not)
        kept_ids = {o.id for o in kept} - set(unstable)
        for oid, description, item in fitting:
            if oid in kept_ids:
                outcomes.append(PlaceOutcome(oid, True))
            else:
                why = unstable.get(oid) or why_not.get(oid, f"it did not end inside {container_id} when dropped")
                outcomes.append(
                    self.solver.fail(oid, description, item, why, predicate, container_id, container.position)
                )
        self.solver.scene.objects = [*self.solver.scene.objects, *[o for o in kept if o.id in kept_ids]]
        return outcomes

    def _cavity(self, container_id: str) -> _Cavity | str:
        """The placed container's cavity in the world, or why nothing can be dropped into it."""
        if container_id not in {o.id for o in self.solver.scene.placed}:
            return f"{container_id} is not in the scene (it failed or was never placed)"
        container = self.solver.scene.object(container_id)
        asset = self.solver.engine.catalogue.asset_for(container.asset, container.description)
        if asset.cavity is None:
            return f"{container_id} ({asset.kind}) is not a container: it has no opening to drop things into"
        rotation = quat_to_matrix(container.quaternion)
        opening_world = np.asarray(asset.cavity.opening) @ rotation[:2, :2].T + np.asarray(container.position[:2])
        opening = shapely.Polygon(opening_world)
        return _Cavity(
            container_id,
            container.position,
            opening,
            rim_z=container.position[2] + asset.cavity.rim_height,
            floor_z=container.position[2] + asset.cavity.floor_height,
            deep=asset.cavity.depth > 1.2 * 2 * opening.exterior.distance(opening.centroid),
            lie_length=_longest_flat(opening),
            capacity=cavity_capacity(asset.cavity),
        )

    def _fitting(
        self, items: Sequence[tuple[str, str, Asset]], cavity: _Cavity, predicate: str
    ) -> tuple[list[tuple[str, str, Asset]], list[PlaceOutcome]]:
        """The items that fit in the cavity, in order, and the failures of those that do not: only what can fit
        is dropped; the rest is reported, not spilled."""
        outcomes: list[PlaceOutcome] = []
        fitting: list[tuple[str, str, Asset]] = []
        volume = 0.0
        for oid, description, item in items:
            upright = stands_in(item, cavity) or (is_tall(item) and self._may_stand(item, cavity))
            volume += item_volume(item, cavity.depth if upright else None)
            if volume > cavity.capacity and fitting:
                reason = (
                    f"{cavity.container_id} is full: the items before it already fill its "
                    f"{cavity.capacity * 1e6:.0f} cm^3 cavity"
                )
                outcomes.append(
                    self.solver.fail(oid, description, item, reason, predicate, cavity.container_id, cavity.position)
                )
            else:
                fitting.append((oid, description, item))
        return fitting, outcomes

    def _stand_on_floor(
        self, items: list[tuple[str, str, Asset]], cavity: _Cavity, predicate: str
    ) -> list[PlacedObject]:
        """Set the items that can stand on the cavity's floor (centre of mass below the rim) side by side, tall ones
        first, before anything is dropped: those that found a spot, reached the floor and stayed there upright."""
        standing = [i for i in items if self._may_stand(i[2], cavity)]
        standing = [standing[k] for k in floor_order([i[2] for i in standing])]
        spots = plan_floor_spots(cavity.opening, [footprint_of(i[2]) for i in standing])
        above = cavity.rim_z + 0.002
        objects = [
            self._item_object(standing[s.index], (s.x, s.y, above), yaw_quaternion(s.yaw), predicate, cavity)
            for s in spots
        ]
        if not objects:
            return []
        built = self.solver.engine.build(
            self.solver.scene, objects=objects, visual=False, fixed=self.solver.scene.placed
        )
        lowered = []
        for obj in objects:  # their footprints do not overlap, so each is lowered alone
            z = built.lower_onto_support(obj.id, above, cavity.floor_z - 0.01)
            if z is not None and z < cavity.floor_z + ON_FLOOR_M:
                lowered.append(obj.model_copy(update={"position": (obj.position[0], obj.position[1], z)}))
        if not lowered:
            return []
        built = self.solver.engine.build(
            self.solver.scene, objects=lowered, visual=False, fixed=self.solver.scene.placed
        )
        self.solver.engine.settle_built(
            built, self.solver.scene.support.top_height, duration_s=1.0, tolerance=Tolerance(10.0, 10.0)
        )
        kept, _ = self._inside(built, lowered, cavity)
        return [o for o in kept if _still_upright(o, lowered)]

    def _may_stand(self, item: Asset, cavity: _Cavity) -> bool:
        """Whether an item is set on the floor as it stands (long things for a holder they stand in are dropped on
        end)."""
        return item.rests and not stands_in(item, cavity) and stands_below_rim(item, cavity.floor_z, cavity.rim_z)

    def _item_object(
        self,
        item: tuple[str, str, Asset],
        position: tuple[float, float, float],
        quaternion: tuple[float, float, float, float],
        predicate: str,
        cavity: _Cavity,
    ) -> PlacedObject:
        oid, description, asset = item
        mass, friction, com = physical_properties(asset, oid, self.solver.seed)
        return PlacedObject(
            id=oid,
            description=description,
            asset=asset.id,
            category=asset.category,
            position=position,
            quaternion=quaternion,
            mass=mass,
            friction=friction,
            com=com,
            placement=Placement(predicate=predicate, target=cavity.container_id),
        )

    def _drop(
        self,
        items: list[tuple[str, str, Asset]],
        cavity: _Cavity,
        predicate: str,
        already: Sequence[PlacedObject] = (),
    ) -> tuple[list[PlacedObject], dict[str, str]]:
        """Drop the items into the cavity onto what `already` stands there; what bounced out is dropped again.
        Returns those inside (with `already`) and why each of the others is not."""
        kept: list[PlacedObject] = list(already)
        remaining = list(items)
        why_not: dict[str, str] = {}
        for attempt in range(DROP_ROUNDS):
            if not remaining:
                break
            drops = self._drop_poses(remaining, cavity, attempt)
            new_objects = [
                self._item_object(item, position, quaternion, predicate, cavity)
                for item, (position, quaternion) in zip(remaining, drops, strict=True)
            ]
            # Everything already there is held still so the falling items cannot knock the container away.
            built = self.solver.engine.build(
                self.solver.scene, objects=new_objects, visual=False, fixed=[*self.solver.scene.placed, *kept]
            )
            for obj in new_objects:  # a small push down so light items do not bounce out
                built.data.qvel[built.dof[obj.id] + 2] = -0.3
            top = max(o.position[2] for o in new_objects)
            fall = max(0.5, math.sqrt(2 * max(0.0, top - cavity.floor_z) / 9.81) + 1.5)
            self.solver.engine.settle_built(
                built, self.solver.scene.support.top_height, duration_s=fall, tolerance=Tolerance(10.0, 10.0)
            )
            landed, why_not = self._inside(built, new_objects, cavity, alone=len(new_objects) == 1 and not kept)
            kept += landed
            landed_ids = {o.id for o in landed}
            remaining = [r for r in remaining if r[0] not in landed_ids]
        return kept, why_not

    def _settle_contents(
        self, cavity: _Cavity, kept: list[PlacedObject], why_not: dict[str, str]
    ) -> tuple[list[PlacedObject], dict[str, str], PlacedObject]:
        """Let the container and its contents settle together until they rest, under MuJoCo's defaults and then
        under our contact settings: the contents still inside, the reasons of those that did not rest, and the
        container as the last settle started from. Why an item left the cavity (or rose above its rim) is added to
        `why_not`. Ours go last, so the poses kept rest where the final check starts: pencils leaning in a mug sink
        into each other under the defaults' softer contacts and, kept so, sprang apart under ours."""
        container = self.solver.scene.object(cavity.container_id)
        unstable: dict[str, str] = {}
        engines = [(self.solver.engine, "")]
        if self.solver.strict is not None:
            engines.insert(0, (self.solver.strict, f"{UNDER_DEFAULTS}: "))
        # Round things heaped in a wide container (fruit in a bowl) roll for seconds into the hollows between their
        # neighbours: they settle as long as the final check watches them under the defaults.
        piled = self.solver.strict is not None and not cavity.deep and len(kept) > 1 and self._mostly_compact(kept)
        # Long things leaning in a holder (pencils in a mug) creep into each other under the defaults for as long:
        # settled for less, they passed here and lost one or two of their number to the final check.
        leaning = self.solver.strict is not None and len(kept) > 1 and self._leaning(kept, cavity)
        duration = SETTLE_CONTENTS_PILED_S if piled or leaning else SETTLE_CONTENTS_S
        for _ in range(PLACE_IN_SETTLES):
            if not kept:
                break
            container = self.solver.scene.object(cavity.container_id)
            unstable, moved_out = {}, False
            for engine, prefix in engines:
                kept, still, left = self._settle_once(engine, cavity, kept, duration)
                unstable.update({oid: prefix + why for oid, why in still.items() if oid not in unstable})
                why_not.update(left)
                moved_out = moved_out or bool(left)
            if not unstable and not moved_out:  # what stays settles again without what left
                break
        return kept, unstable, container

    def _leaning(self, objects: list[PlacedObject], cavity: _Cavity) -> bool:
        """Whether several of the objects stand on end in the cavity (long things in a holder)."""
        catalogue = self.solver.engine.catalogue
        return sum(stands_in(catalogue.get(o.asset), cavity) for o in objects) > 1

    def _mostly_compact(self, objects: list[PlacedObject]) -> bool:
        """Whether at least half the objects are compact (fruit, balls, cans), not long or flat (tools, plates)."""
        other = [_flat_or_long(self.solver.engine.catalogue.get(o.asset)) for o in objects]
        return 2 * sum(other) <= len(other)

    def _settle_once(
        self, engine: MujocoEngine, cavity: _Cavity, kept: list[PlacedObject], duration_s: float
    ) -> tuple[list[PlacedObject], dict[str, str], dict[str, str]]:
        """One settle of the container, its neighbours and its contents in `engine`: the contents still inside
        (the scene's objects take their settled poses), why those that moved did not rest, and why those that
        left are not inside."""
        container = self.solver.scene.object(cavity.container_id)
        near = [container] + [
            o
            for o in self.solver.scene.placed
            if o.id != cavity.container_id and np.linalg.norm(np.subtract(o.position[:2], container.position[:2])) < 0.3
        ]
        near_ids = {o.id for o in near}
        others = [o for o in self.solver.scene.placed if o.id not in near_ids]
        built = engine.build(self.solver.scene, objects=[*near, *kept], visual=False, fixed=others)
        tolerance = self.solver.tolerance if engine.profile != MUJOCO_DEFAULT else MUJOCO_DEFAULT_TOLERANCE
        result = engine.settle_built(
            built, self.solver.scene.support.top_height, duration_s=duration_s, tolerance=tolerance
        )
        kept_ids = {o.id for o in kept}
        moved = [m for m in result.objects.values() if not m.ok and m.id in kept_ids]
        unstable = {m.id: m.reason or "it did not come to rest" for m in moved}
        inside, left = self._inside(built, kept, cavity, alone=len(kept) == 1)
        self._take_poses(built, near)
        return inside, unstable, left

    def _holds_anything(self, container_id: str) -> bool:
        """Whether something already placed was put in the container."""
        return any(o.placement is not None and o.placement.target == container_id for o in self.solver.scene.placed)

    def _inside(
        self, built: BuiltScene, items: list[PlacedObject], cavity: _Cavity, alone: bool = False
    ) -> tuple[list[PlacedObject], dict[str, str]]:
        """The items whose bottom came to rest inside the cavity and whose centre of mass is below its rim (long
        ones may lean on the rim, and an item `alone` in a container that held nothing else may sit in its opening: an
        egg in an egg cup), with their settled poses; and why each of the others is not inside."""
        final = built.poses()
        index = {o.id: k for k, o in enumerate(built.objects)}
        kept = []
        why_not: dict[str, str] = {}
        for obj in items:
            pose = final[index[obj.id]]
            asset = self.solver.engine.catalogue.get(obj.asset)
            bottom = _lowest_point(asset, pose)
            turn = quat_to_matrix(pose[3:].tolist())
            com_z = float(pose[2] + (turn @ np.asarray(obj.com))[2])
            within = cavity.opening.buffer(0.01).contains(shapely.Point(bottom[0], bottom[1]))
            if not (within and cavity.floor_z - 0.02 < bottom[2] < cavity.rim_z):
                why_not[obj.id] = f"it did not end inside {cavity.container_id} when dropped"
            elif com_z > cavity.rim_z and not _on_end(asset, turn, cavity) and not (alone and cavity.empty):
                why_not[obj.id] = com_above_rim_reason(com_z, cavity.rim_z, cavity.container_id)
            else:
                kept.append(
                    obj.model_copy(
                        update={
                            "position": tuple(float(v) for v in pose[:3]),
                            "quaternion": tuple(float(v) for v in pose[3:]),
                        }
                    )
                )
        return kept, why_not

    def _take_poses(self, built: BuiltScene, objects: list[PlacedObject]) -> None:
        """Scene objects take the poses they settled to in `built`."""
        final = built.poses()
        index = {o.id: k for k, o in enumerate(built.objects)}
        ids = {o.id for o in objects}
        self.solver.scene.objects = [
            o.model_copy(
                update={
                    "position": tuple(float(v) for v in final[index[o.id]][:3]),
                    "quaternion": tuple(float(v) for v in final[index[o.id]][3:]),
                }
            )
            if o.id in ids and o.id in index
            else o
            for o in self.solver.scene.objects
        ]

    def _drop_poses(
        self,
        items: Sequence[tuple[str, str, Asset]],
        cavity: _Cavity,
        attempt: int = 0,
    ) -> list[tuple[tuple[float, float, float], tuple[float, float, float, float]]]:
        """Collision-free release poses above the opening: spread out, stacked where they overlap."""
        opening, rim_z = cavity.opening, cavity.rim_z
        poses = []
        footprints: list[tuple[shapely.Geometry, float]] = []  # (shape, top z)
        for oid, _, item in items:
            rng = object_rng(self.solver.seed + 1000 * attempt, oid)
            sx, sy, sz = item.size
            upright = stands_in(item, cavity)
            if upright:  # long things go in a holder standing up: lay the long axis along z
                long_axis_x = sx >= sy
                quat = (
                    (math.cos(math.pi / 4), 0.0, math.sin(math.pi / 4), 0.0)
                    if long_axis_x
                    else (math.cos(math.pi / 4), math.sin(math.pi / 4), 0.0, 0.0)
                )
                radius, height = 0.5 * max(min(sx, sy), sz), max(sx, sy)
                base_offset = max(sx, sy) / 2
                lean = float(rng.uniform(-0.15, 0.15))
                quat = compose_yaw(quat, lean + float(rng.uniform(0, 2 * math.pi)))
            else:
                yaw = float(rng.uniform(0, 2 * math.pi))
                quat = yaw_quaternion(yaw)
                radius, height, base_offset = 0.5 * math.hypot(sx, sy), sz, 0.0
            inradius = opening.exterior.distance(opening.centroid)
            inner = opening.buffer(-min(radius, 0.45 * inradius))
            if inner.is_empty or radius >= 0.9 * inradius:  # as wide as the opening (a bowl into a bowl): centred
                inner = opening.centroid.buffer(1e-3)
            point = _sample_in(inner, rng)
            disc = shapely.Point(point).buffer(radius)
            z = rim_z + 0.01
            for shape, top in footprints:
                if shape.intersects(disc):
                    z = max(z, top + 0.005)
            footprints.append((disc, z + height))
            base_z = z + (base_offset if upright else 0.0)
            if upright:
                base_z = z + height / 2  # a turned object's origin (its base centre) sits at mid-height
            poses.append(((float(point[0]), float(point[1]), float(base_z)), quat))
        return poses


@dataclass(frozen=True)
class _Cavity:
    """A placed container's cavity in the world: where dropped items must end."""

    container_id: str
    position: tuple[float, float, float]  # the container's, when the drop starts
    opening: shapely.Polygon
    rim_z: float
    floor_z: float
    deep: bool  # deeper than wide: long items go in upright
    lie_length: float  # the longest item that lies flat inside (a round opening's diameter, a box's diagonal)
    capacity: float  # the volume its items may take, m^3
    empty: bool = False  # it held nothing before this PLACE-IN: a lone item may sit in its opening (an egg in a cup)

    @property
    def depth(self) -> float:
        return self.rim_z - self.floor_z


def _lowest_point(asset: Asset, pose: np.ndarray) -> np.ndarray:
    """Mean of the lowest corners of the asset's box at a pose (its 'bottom' in the world)."""
    sx, sy, sz = asset.size
    corners = np.array([[x, y, z] for x in (-sx / 2, sx / 2) for y in (-sy / 2, sy / 2) for z in (0.0, sz)])
    world = corners @ quat_to_matrix(pose[3:].tolist()).T + pose[:3]
    return world[np.argsort(world[:, 2])[:4]].mean(axis=0)


def _still_upright(obj: PlacedObject, placed: Sequence[PlacedObject]) -> bool:
    """Whether an item set standing on a floor still stands as it was set (tilted by less than UPRIGHT_TILT_RAD)."""
    start = next(o for o in placed if o.id == obj.id)
    up_now = quat_to_matrix(list(obj.quaternion))[:, 2]
    up_then = quat_to_matrix(list(start.quaternion))[:, 2]
    return float(up_now @ up_then) > math.cos(UPRIGHT_TILT_RAD)


def _on_end(asset: Asset, turn: np.ndarray, cavity: _Cavity) -> bool:
    """Whether a long item stands on end in its holder (a toothbrush in a tumbler, a spoon in a mug): held by the
    walls, its centre of mass may be above the rim."""
    long_axis = turn[:, int(np.argmax(asset.size))]
    return stands_in(asset, cavity) and abs(float(long_axis[2])) > ON_END_COS


def stands_in(item: Asset, cavity: _Cavity) -> bool:
    """Whether a long item (a pen, a toothbrush, a spoon) goes into a holder standing up: a deep one, or one it is
    too long to lie in that holds a good part of its length (spoons in a mug lay across its rim); never an
    imported item that rests in no pose: it goes in as it lies."""
    if not (item.rests and _flat_or_long(item)):
        return False
    long_side = max(item.size[0], item.size[1])
    slender = sorted(item.size)[1] <= SLENDER * long_side  # a spoon, a pencil; not a bowl, a plate or a phone
    return cavity.deep or (slender and long_side > cavity.lie_length and cavity.depth >= HELD_ON_END * long_side)


def _flat_or_long(item: Asset) -> bool:
    """Whether an item is long or wide for its height (a pen, a banana, a plate), not compact (an apple, a can)."""
    sx, sy, sz = item.size
    return max(sx, sy) > 2.0 * sz


def _longest_flat(opening: shapely.Polygon) -> float:
    """About the longest thing that lies flat inside an opening: a round one's diameter, a box's diagonal."""
    return 2.0 * float(shapely.minimum_bounding_radius(opening))


def item_volume(asset: Asset, standing_depth: float | None = None) -> float:
    """Space an item takes in a heap: its box, a little less for round things. Standing in a holder `standing_depth`
    deep, only the part below the rim counts: its cross-section times that depth."""
    short, middle, longest = sorted(asset.size)
    roundness = 0.6 if not asset.has_front else 0.8
    length = longest if standing_depth is None else min(longest, standing_depth)
    return short * middle * length * roundness


def cavity_capacity(cavity: Cavity) -> float:
    """The volume dropped items may fill in a cavity, m^3: a share (PACKING) of its opening times its depth."""
    return float(shapely.Polygon(cavity.opening).area * cavity.depth * PACKING)


def _sample_in(polygon: shapely.Geometry, rng: np.random.Generator) -> np.ndarray:
    minx, miny, maxx, maxy = polygon.bounds
    for _ in range(200):
        point = rng.uniform([minx, miny], [maxx, maxy])
        if polygon.contains(shapely.Point(point)):
            return point
    return np.array(polygon.representative_point().coords[0])
