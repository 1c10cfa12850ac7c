"""The clutter protocol run by a peer: NVlabs scene_synthesizer (`pip install physcensis[peer]`).

The same table, the same ten YCB assets on the same collision hulls (our assets' collision parts as trimesh meshes),
the same seeded order and the same stopping rules as `bench/clutter.py`; each object is placed with the peer's
public `Scene.place_object` (its default sampler: uniform positions and yaws, 100 tries, collision-checked with FCL,
1 mm above the support). `no-stack` offers only the table's support surface; `with-stack` labels every support
surface the peer finds (table and placed objects) again after each placement. Every final scene is converted to our
`Scene` and measured the same way as ours (`clutter.measure_under_mujoco_defaults`).
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from types import ModuleType
from typing import Any

import numpy as np
import trimesh

from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.assets.model import Asset
from physcensis.bench.clutter import (
    CLUTTER_TABLE,
    YCB_DINING,
    AttemptLoop,
    DefaultsMeasure,
    count_statistics,
    measure_under_mujoco_defaults,
    summarise_under_defaults,
)
from physcensis.export.bodies import part_mesh
from physcensis.machine import machine_info
from physcensis.scene import PlacedObject, Scene
from physcensis.solver.objects import physical_properties

PEERS = ("scene-synthesizer",)
PEER_VERSION = "1.15.0"
PEER_MODES = ("no-stack", "with-stack")
INSTALL_HINT = "pip install 'physcensis[peer]'"
TABLE_ID = "table"
TABLE_THICKNESS_M = 0.05
TABLE_SUPPORT = "table"
ANY_SUPPORT = "surfaces"
EDGE_SLACK_M = 1e-4


class PeerUnavailable(RuntimeError):
    """The peer's package is not installed."""


def load_scene_synthesizer() -> ModuleType:
    """The peer's package, imported on first use (it is an optional extra)."""
    try:
        import scene_synthesizer
    except ImportError as exc:
        raise PeerUnavailable(f"the peer scene-synthesizer is not installed: {INSTALL_HINT}") from exc
    return scene_synthesizer


@dataclass
class PeerScene:
    seed: int
    placed: int  # what the peer placed
    attempts: int
    seconds: float  # the peer's placement only (the re-simulation is ours)
    defaults: DefaultsMeasure
    scene: Scene
    stop_reason: str


def peer_asset(synth: ModuleType, asset: Asset) -> Any:
    """Our asset's collision hulls as one scene_synthesizer asset, in our asset frame (base centre at the origin)."""
    hulls = trimesh.Scene()
    for i, part in enumerate(asset.collision):
        hulls.add_geometry(part_mesh(part).copy(), geom_name=f"hull_{i}")
    return synth.TrimeshSceneAsset(hulls)


def peer_table(synth: ModuleType, seed: int) -> Any:
    """The peer's scene: the protocol's table, its top where ours is (centred on x = y = 0, at the support's top
    height), labelled as a support."""
    scene = synth.Scene(seed=seed)
    x, y = CLUTTER_TABLE.size
    table = synth.BoxMeshAsset(extents=[x, y, TABLE_THICKNESS_M])
    centre = trimesh.transformations.translation_matrix([0.0, 0.0, CLUTTER_TABLE.top_height - TABLE_THICKNESS_M / 2])
    scene.add_object(table, obj_id=TABLE_ID, transform=centre)
    scene.label_support(TABLE_SUPPORT, obj_ids=TABLE_ID)
    return scene


@dataclass(frozen=True)
class PlacementRule:
    stack: bool
    valid: Callable[[Any, Any, np.ndarray], bool] | None  # None: the peer's own rule (objects may overhang)


def hull_points(asset: Asset) -> np.ndarray:
    """(N, 4) homogeneous vertices of the asset's collision hulls in its frame."""
    points = np.vstack([part_mesh(part).vertices for part in asset.collision])
    return np.hstack([points, np.ones((len(points), 1))])


def within_table_edges(points: np.ndarray) -> Callable[[Any, Any, np.ndarray], bool]:
    """A `valid_placement_fn` for the peer: every hull vertex over the table top (the peer's own rule only keeps the
    object's reference point inside the support polygon, so without it objects stick out past the edge)."""
    half = np.asarray(CLUTTER_TABLE.half_extents) + EDGE_SLACK_M

    def valid(_asset: Any, _support: Any, world: np.ndarray) -> bool:
        xy = (points @ np.asarray(world, dtype=float).T)[:, :2]
        return bool((np.abs(xy) <= half).all())

    return valid


def place_one(peer: Any, oid: str, asset: Any, rule: PlacementRule) -> bool:
    """One object with the peer's `place_object` on the table, or with stacking on any support surface it finds."""
    support = TABLE_SUPPORT
    if rule.stack:
        peer.label_support(ANY_SUPPORT)  # the table and every placed object, as they are now
        support = ANY_SUPPORT
    if rule.valid is None:
        return bool(peer.place_object(oid, asset, support_id=support))
    return bool(peer.place_object(oid, asset, support_id=support, valid_placement_fn=rule.valid))


def placed_object(peer: Any, oid: str, asset: Asset, seed: int) -> PlacedObject:
    """The peer's object as ours: its pose, our asset id, and the mass and friction our solver would draw."""
    matrix = np.asarray(peer.get_transform(oid), dtype=float)
    w, x, y, z = trimesh.transformations.quaternion_from_matrix(matrix)
    mass, friction, com = physical_properties(asset, oid, seed)
    return PlacedObject(
        id=oid,
        description=asset.description,
        asset=asset.id,
        category=asset.category,
        position=(float(matrix[0, 3]), float(matrix[1, 3]), float(matrix[2, 3])),
        quaternion=(float(w), float(x), float(y), float(z)),
        mass=mass,
        friction=friction,
        com=com,
    )


def run_peer_scene(
    mode: str,
    seed: int,
    *,
    patience: int = 1,
    overhang: bool = False,
    catalogue: Catalogue | None = None,
    synth: ModuleType | None = None,
) -> PeerScene:
    """One scene of the protocol placed by the peer, then measured under MuJoCo's defaults."""
    if mode not in PEER_MODES:
        raise ValueError(f"the peer runs {' or '.join(PEER_MODES)}, not {mode!r}")
    synth = synth or load_scene_synthesizer()
    catalogue = catalogue or default_catalogue()
    start = time.perf_counter()
    assets = [catalogue.get(a) for a in YCB_DINING]
    hulls = [peer_asset(synth, a) for a in assets]
    rules = [
        PlacementRule(mode == "with-stack", None if overhang else within_table_edges(hull_points(a))) for a in assets
    ]
    order = list(np.random.default_rng(seed).permutation(len(assets)))
    peer = peer_table(synth, seed)
    scene = Scene(seed=seed, prompt=f"clutter benchmark ({mode}), scene_synthesizer", support=CLUTTER_TABLE)
    loop = AttemptLoop(order, patience)
    while (k := loop.next_asset()) is not None:
        oid = f"{assets[k].kind.replace(' ', '_')}_{loop.attempts}"
        ok = place_one(peer, oid, hulls[k], rules[k])
        if ok:
            scene.objects.append(placed_object(peer, oid, assets[k], seed))
        loop.record(k, ok)
    seconds = time.perf_counter() - start
    placed = len(scene.objects)
    defaults = measure_under_mujoco_defaults(scene, catalogue)
    return PeerScene(seed, placed, loop.attempts, seconds, defaults, scene, loop.stop or "")


def run_peer(
    mode: str,
    scenes: int,
    seed: int = 0,
    *,
    patience: int = 1,
    overhang: bool = False,
    progress: Callable[[int, PeerScene], None] | None = None,
) -> dict[str, Any]:
    """Many peer scenes: the same summary as `clutter.run` (counts placed by the peer), plus the `mujoco_default`
    block (what still rests and the settle distance under MuJoCo's default contact settings)."""
    synth = load_scene_synthesizer()
    catalogue = default_catalogue()
    rows = []
    for i in range(scenes):
        rows.append(
            run_peer_scene(mode, seed + i, patience=patience, overhang=overhang, catalogue=catalogue, synth=synth)
        )
        if progress:
            progress(i, rows[-1])
    counts = [r.placed for r in rows]
    defaults = summarise_under_defaults([r.defaults for r in rows])
    return {
        "mode": mode,
        "peer": f"scene-synthesizer {getattr(synth, '__version__', PEER_VERSION)}",
        "scenes": scenes,
        "seed": seed,
        "patience": patience,
        "overhang": overhang,
        **count_statistics(counts, [r.seconds for r in rows]),
        "mean_settle_distance_m": defaults["mean_settle_distance_m"],
        "counts": counts,
        "mujoco_default": defaults,
        "machine": machine_info(),
    }
