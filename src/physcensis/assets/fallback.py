"""Generated assets for descriptions the catalogue does not cover (offline stand-in for text-to-3D).

Either the nearest category's generator is re-run at the size the description
asks for ("a 40 cm tall vase", "a huge mug"), or a generic box, cylinder or
sphere is sized from the description's words or dimensions.  Results are marked
`generated=True`.
"""

from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass, replace
from typing import Literal

import numpy as np

from physcensis.assets import collision as col
from physcensis.assets import palette as P
from physcensis.assets import shapes
from physcensis.assets.build import build_asset
from physcensis.assets.model import Asset, Vec3
from physcensis.assets.spec import CategoryDef, Geometry, Variant, builder
from physcensis.assets.text import parse_dimensions, size_factors, words

GENERIC_SIZE: Vec3 = (0.12, 0.1, 0.08)
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

    shape: Literal["box", "cylinder", "sphere"] = "box"


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
    mesh = shapes.rounded_box((x, y, z), 0.08 * min(x, y, z), (0, 0, z / 2))
    return Geometry(((mesh, color),), (col.box_part((x, y, z), (0, 0, z / 2)),))


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
    """A new asset for `description`: the template's generator at the requested size, or a generic shape."""
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
    tokens = set(words(description))
    shape = "sphere" if tokens & SPHERE_WORDS else "cylinder" if tokens & CYLINDER_WORDS else "box"
    base_size: Vec3 = (
        (0.08, 0.08, 0.08) if shape == "sphere" else (0.08, 0.08, 0.12) if shape == "cylinder" else GENERIC_SIZE
    )
    size = sized(description, base_size, round_shape=shape != "box")
    if shape == "sphere":
        d = float(np.mean(size))
        size = (d, d, d) if not parse_dimensions(description) else size
    color = next((COLOR_WORDS[w] for w in words(description) if w in COLOR_WORDS), P.GREY)
    variant = Variant("generated", description, size, (color,), {"shape": shape}, asset_id=ident)
    asset = build_asset(GENERIC, variant)
    return replace(
        asset, generated=True, source="generated", guessed=frozenset({"mass", "friction", "size", "shape", "category"})
    )
