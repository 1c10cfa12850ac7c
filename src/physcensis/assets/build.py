"""Turn a category definition and one variant into an Asset (normalised, with mass and centre of mass)."""

from __future__ import annotations

import logging
from typing import cast

import numpy as np
import trimesh

from physcensis.assets.errors import AssetError
from physcensis.assets.model import Asset, Cavity
from physcensis.assets.spec import CategoryDef, Geometry, Variant

log = logging.getLogger(__name__)
MASS_SPREAD = 0.15  # the mass range is the nominal mass +/- this fraction
# Object sets whose objects were weighed (the YCB set's published masses): a placed copy has that mass, no spread.
WEIGHED_SETS = frozenset({"ycb"})


def asset_id(cat: CategoryDef, variant: Variant) -> str:
    return variant.asset_id or f"{cat.id_prefix}_{variant.name}"


def solid_volume_and_com(meshes: list[trimesh.Trimesh]) -> tuple[float, np.ndarray]:
    """Volume and centre of mass of the union of closed meshes (overlaps counted once)."""
    mesh = meshes[0] if len(meshes) == 1 else trimesh.boolean.union(meshes, engine="manifold")
    return float(mesh.volume), np.asarray(mesh.center_mass, dtype=float)


def normalise_geometry(geometry: Geometry) -> tuple[Geometry, np.ndarray]:
    """Translate so the base is at z = 0 and the xy bounds are centred; returns the offset applied."""
    meshes = [m for m, _ in geometry.parts]
    lo = np.min([m.bounds[0] for m in meshes], axis=0)
    hi = np.max([m.bounds[1] for m in meshes], axis=0)
    offset = np.array([-(lo[0] + hi[0]) / 2, -(lo[1] + hi[1]) / 2, -lo[2]])
    parts = []
    for mesh, color in geometry.parts:
        moved = mesh.copy()
        moved.apply_translation(offset)
        parts.append((moved, color))
    collision = tuple(p.translated(offset) for p in geometry.collision)
    cavity = None
    if geometry.cavity is not None:
        c = geometry.cavity
        cavity = Cavity(c.opening + offset[:2], c.floor_height + offset[2], c.depth)
    return Geometry(tuple(parts), collision, cavity), offset


def build_asset(cat: CategoryDef, variant: Variant) -> Asset:
    """Run the generator and attach the annotations; raises AssetError naming the asset."""
    ident = asset_id(cat, variant)
    try:
        geometry, _ = normalise_geometry(cat.geometry(variant))
        return assemble(ident, cat, variant, geometry)
    except AssetError:
        raise
    except Exception as exc:  # any generator bug becomes an error naming the asset
        raise AssetError(f"asset {ident}: generator failed ({exc.__class__.__name__}: {exc})") from exc


def assemble(ident: str, cat: CategoryDef, variant: Variant, geometry: Geometry) -> Asset:
    meshes = [m for m, _ in geometry.parts]
    volume, com = solid_volume_and_com(meshes)
    if volume <= 0:
        raise AssetError(f"asset {ident}: visual mesh has no volume")
    density = variant.density or cat.density
    mass = variant.mass if variant.mass is not None else density * volume
    size = tuple(float(v) for v in variant.size)
    visual = cast(trimesh.Trimesh, trimesh.util.concatenate(meshes))
    return Asset(
        id=ident,
        category=cat.category,
        kind=cat.kind,
        description=variant.description,
        size=size,  # type: ignore[arg-type]
        visual=visual,
        collision=tuple(geometry.collision),
        mass=float(mass),
        mass_range=_mass_range(float(mass), variant),
        friction_range=cat.friction,
        com=tuple(float(v) for v in com),  # type: ignore[arg-type]
        com_shift_range=tuple(float(cat.com_shift * s) for s in size),  # type: ignore[arg-type]
        support_probability=cat.support_probability,
        has_front=cat.has_front,
        cavity=geometry.cavity,
        rgba=tuple(c for _, c in geometry.parts),
        part_faces=tuple(len(m.faces) for m in meshes),
        tags=tuple(dict.fromkeys((*cat.tags, *variant.tags))),
        synonyms=tuple(dict.fromkeys((*cat.synonyms, *variant.synonyms))),
        source="builtin",
    )


def _mass_range(mass: float, variant: Variant) -> tuple[float, float]:
    """The range a placed copy's mass is drawn from: the nominal mass +/- MASS_SPREAD, or exactly the published
    mass of an object from a weighed set."""
    if variant.mass is not None and WEIGHED_SETS.intersection(variant.tags):
        return mass, mass
    return mass * (1 - MASS_SPREAD), mass * (1 + MASS_SPREAD)
