"""Generated assets for descriptions the catalogue does not cover (offline stand-in for text-to-3D).

Either the nearest category's generator is re-run at the size the description
asks for ("a 40 cm tall vase", "a huge mug"), or a stand-in is made for the
unknown noun from a prior per kind of thing (`KINDS`: appliance, container,
bottle-like, tool, toy, food, soft item, electronics, furniture-like, flat item,
ornament): the kind is chosen from the noun and the description's words, and
gives the stand-in's shape (box, cylinder, flat slab, rounded), a typical size
range and a density.  The size within the range is fixed by the noun (so the
same noun always gets the same stand-in), then the description's size words and
dimensions apply.  Results are marked `generated=True`; a stand-in's category is
its noun and `stand_in_note` says what it is.
"""

from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
import trimesh

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.build import build_asset
from physcensis.assets.kinds import GENERIC_KIND, KindPrior, Shape, head_noun, kind_of
from physcensis.assets.model import Asset, Vec3
from physcensis.assets.spec import CategoryDef, Geometry, Variant, builder
from physcensis.assets.text import parse_dimensions, size_factors, words

SPHERE_WORDS = frozenset({"ball", "sphere", "globe", "orb", "spherical", "marble", "bead"})
CYLINDER_WORDS = frozenset(
    {
        "cylinder",
        "cylindrical",
        "tube",
        "can",
        "tin",
        "roll",
        "jar",
        "bottle",
        "pillar",
        "disc",
        "disk",
        "puck",
        "canister",
        "pot",
    }
)
SLAB_WORDS = frozenset({"sheet", "slab", "plank", "panel", "flat", "mat", "card"})
STAND_IN_TAG = "stand-in"
COLOR_WORDS = {
    "red": P.RED,
    "blue": P.BLUE,
    "green": P.GREEN,
    "yellow": P.YELLOW,
    "orange": P.ORANGE,
    "purple": P.PURPLE,
    "pink": P.PINK,
    "black": P.CHARCOAL,
    "white": P.WHITE,
    "grey": P.GREY,
    "brown": P.BROWN,
    "wooden": P.WOOD,
    "wood": P.WOOD,
    "metal": P.STEEL,
    "silver": P.SILVER,
    "gold": P.GOLD,
}
MIN_SIZE, MAX_SIZE = 0.005, 3.0


@dataclass(frozen=True)
class GenericShape:
    """The generic stand-in's shape."""

    shape: Shape = "box"


@builder(GenericShape)
def _generic(v: Variant, p: GenericShape) -> Geometry:
    x, y, z = v.size
    color = v.color(0, P.GREY)
    shape = p.shape
    if shape == "sphere":
        mesh = shapes.ellipsoid((x / 2, y / 2, z / 2), (0, 0, z / 2), 3)
        part = col.sphere_part(x / 2, (0, 0, z / 2)) if np.allclose((x, y), z) else col.hull_part(mesh)
        return Geometry(((mesh, color),), (part,))
    if shape == "cylinder":
        mesh = shapes.cylinder(x / 2, z, (0, 0, z / 2), sections=32)
        mesh.apply_scale((1.0, y / x, 1.0))
        part = col.cylinder_part(x / 2, z, (0, 0, z / 2)) if np.isclose(x, y) else col.hull_part(mesh)
        return Geometry(((mesh, color),), (part,))
    if shape == "rounded":
        return Geometry(((_dome(x, y, z), color),), (col.hull_part(_dome(x, y, z)),))
    radius = 0.08 * min(x, y, z) if shape == "box" else 0.35 * z
    mesh = shapes.rounded_box((x, y, z), radius, (0, 0, z / 2))
    return Geometry(((mesh, color),), (col.box_part((x, y, z), (0, 0, z / 2)),))


def _dome(x: float, y: float, z: float) -> trimesh.Trimesh:
    """A lump with a flat base (it stands, unlike an ellipsoid): straight sides for the lower third, a rounded top."""
    angles = np.linspace(0.0, np.pi / 2, 9)
    profile = [(0.0, 0.0), (0.5, 0.0), (0.5, z / 3)]
    profile += [(0.5 * np.cos(a), z / 3 + (2 * z / 3) * np.sin(a)) for a in angles[1:-1]]
    profile.append((0.0, z))
    mesh = shapes.lathe(profile, sections=32)
    mesh.apply_scale((x, y, 1.0))
    return mesh


GENERIC = CategoryDef(
    category="object",
    kind="generic object",
    build=_generic,
    variants=(),
    density=500.0,
    mass_limits=(0.001, 200.0),
    friction=(0.4, 0.8),
    support_probability=0.5,
    has_front=False,
    prefix="gen",
)


def sized(description: str, base: Vec3, round_shape: bool = False) -> Vec3:
    """The size a description asks for, starting from `base`: explicit dimensions win, then size words."""
    dims = parse_dimensions(description)
    x, y, z = base
    if {"x", "y", "z"} <= dims.keys():
        return _clamp((dims["x"], dims["y"], dims["z"]))
    if {"x", "y"} <= dims.keys():
        return _clamp((dims["x"], dims["y"], z * dims["x"] / x))
    scale = None
    if "height" in dims:
        scale = dims["height"] / z
    elif "length" in dims:
        scale = dims["length"] / x
    elif "width" in dims:
        scale = dims["width"] / y
    elif "diameter" in dims:
        scale = dims["diameter"] / max(x, y)
    elif "size" in dims:
        scale = dims["size"] / max(x, y, z)
    if scale is not None:
        return _clamp((x * scale, y * scale, z * scale))
    fx, fy, fz = size_factors(description)
    if round_shape:
        fx = fy = max(fx, fy) if fx * fy > 1 else min(fx, fy)
    return _clamp((x * fx, y * fy, z * fz))


def _clamp(size: tuple[float, float, float]) -> Vec3:
    return tuple(float(np.clip(s, MIN_SIZE, MAX_SIZE)) for s in size)  # type: ignore[return-value]


def generated_id(description: str) -> str:
    slug = "_".join(w for w in re.findall(r"[a-z]+", description.lower()) if len(w) > 2)[:40].strip("_") or "object"
    digest = hashlib.sha1(description.encode("utf-8")).hexdigest()[:8]
    return f"gen_{slug}_{digest}"


def generate(description: str, template: tuple[CategoryDef, Variant] | None = None) -> Asset:
    """A new asset for `description`: the template's generator at the requested size, or a stand-in of its kind."""
    ident = generated_id(description)
    if template is not None:
        cat, base = template
        size = sized(description, base.size, round_shape=bool(np.isclose(base.size[0], base.size[1])))
        variant = replace(
            base,
            description=description,
            size=size,
            asset_id=ident,
            mass=None if base.mass is None else base.mass * np.prod(np.asarray(size) / np.asarray(base.size)),
        )
        asset = build_asset(cat, variant)
        return replace(
            asset,
            generated=True,
            source=f"generated:{cat.id_prefix}_{base.name}" if base.asset_id is None else f"generated:{base.asset_id}",
            guessed=frozenset({"mass", "friction", "size"}),
        )
    return stand_in(description)


def stand_in(description: str) -> Asset:
    """A stand-in for a noun the catalogue does not know, from its kind's prior (see `kinds.KINDS`): the kind's
    shape and density, a size within its range fixed by the noun, then the description's size words and dimensions.
    Its category is the noun; `stand_in_note` says what it became."""
    noun = head_noun(description)
    kind = kind_of(description)
    shape = _shape(description, kind)
    size = _stand_in_size(description, noun, kind, shape)
    color = next((COLOR_WORDS[w] for w in words(description) if w in COLOR_WORDS), P.GREY)
    variant = Variant(
        "generated",
        description,
        size,
        (color,),
        {"shape": shape},
        density=kind.density,
        asset_id=generated_id(description),
    )
    asset = build_asset(GENERIC, variant)
    return replace(
        asset,
        category=noun,
        kind=f"{kind.name} stand-in",
        tags=(STAND_IN_TAG, f"kind:{kind.name}", f"shape:{shape}"),
        generated=True,
        source="generated",
        guessed=frozenset({"mass", "friction", "size", "shape", "category"}),
    )


def _shape(description: str, kind: KindPrior) -> Shape:
    tokens = set(words(description))
    if tokens & SPHERE_WORDS:
        return "sphere"
    if tokens & CYLINDER_WORDS:
        return "cylinder"
    if tokens & SLAB_WORDS and kind is GENERIC_KIND:
        return "slab"
    return kind.shape


def _stand_in_size(description: str, noun: str, kind: KindPrior, shape: Shape) -> Vec3:
    x, y, z = kind.size_for(noun)
    if shape == "sphere":
        x = y = z = float(np.mean((x, y, z)))
    elif shape in ("cylinder", "rounded") and kind.shape not in ("cylinder", "rounded"):
        x = y = float(np.sqrt(x * y))  # a box kind drawn round: the same footprint area
    size = sized(description, (x, y, z), round_shape=shape != "box" and shape != "slab")
    if shape == "sphere" and not parse_dimensions(description):
        d = float(np.mean(size))
        return (d, d, d)
    return size


def stand_in_info(asset: Asset) -> dict[str, Any] | None:
    """What a stand-in asset is, for the agent and the report: its noun, kind, shape, size and a sentence ("'hookah'
    not in the catalogue: a 0.30 m cylinder stand-in (kind: container)"); None for any other asset."""
    if STAND_IN_TAG not in asset.tags:
        return None
    tags = dict(t.split(":", 1) for t in asset.tags if ":" in t)
    kind, shape = tags.get("kind", GENERIC_KIND.name), tags.get("shape", "box")
    words_for_shape = {"slab": "flat slab", "rounded": "rounded"}.get(shape, shape)
    note = (
        f"'{asset.category}' not in the catalogue: a {max(asset.size):.2f} m {words_for_shape} stand-in (kind: {kind})"
    )
    return {
        "noun": asset.category,
        "kind": kind,
        "shape": shape,
        "size_m": [round(s, 3) for s in asset.size],
        "mass_kg": round(asset.mass, 3),
        "note": note,
    }


def stand_in_note(asset: Asset) -> str | None:
    info = stand_in_info(asset)
    return None if info is None else str(info["note"])
