"""The colours of an imported mesh: one colour per face from its file, then a few coloured parts.

A face's colour is the mean of its vertex colours (PLY), its own colour, or its material's: the
base-colour texture (glTF `baseColorTexture`, OBJ `map_Kd`) sampled at the face's UV centroid and
multiplied by the base colour factor, else the base colour (`baseColorFactor`, `Kd`).  A texture
larger than MAX_TEXTURE_SIDE or unreadable gives way to the base colour, with the reason logged.
The faces are then quantised to at most MAX_COLOURS colours (k-means with a fixed seed) and
reordered into one contiguous run per colour: the `part_faces` / `rgba` of an `Asset`.
"""

from __future__ import annotations

import logging

import numpy as np
import trimesh
from scipy.cluster.vq import kmeans2

log = logging.getLogger(__name__)
DEFAULT_RGBA = (0.7, 0.7, 0.7, 1.0)
MAX_COLOURS = 8
MAX_TEXTURE_SIDE = 4096
SEED = 0
MIN_PART_FACES = 4  # fewer faces of a colour (a speck) take the nearest colour
MIN_PART_SHARE = 0.002


def face_colours(mesh: trimesh.Trimesh) -> np.ndarray | None:
    """(F, 4) colours in [0, 1] of the mesh's faces from its visual, or None when the file gives none."""
    visual = mesh.visual
    if isinstance(visual, trimesh.visual.TextureVisuals):
        return _material_colours(mesh, visual)
    if isinstance(visual, trimesh.visual.ColorVisuals):
        if visual.kind == "face":
            return np.asarray(visual.face_colors, dtype=float)[: len(mesh.faces)] / 255.0
        if visual.kind == "vertex":
            vertex = np.asarray(visual.vertex_colors, dtype=float) / 255.0
            return vertex[np.asarray(mesh.faces)].mean(axis=1)
    return None


def _material_colours(mesh: trimesh.Trimesh, visual: trimesh.visual.TextureVisuals) -> np.ndarray | None:
    material = visual.material
    if material is None:
        return None
    factor, image = _base_colour(material)
    colours = np.tile(factor, (len(mesh.faces), 1))
    uv = None if visual.uv is None else np.asarray(visual.uv, dtype=float)
    if image is None or uv is None or len(uv) != len(mesh.vertices):
        return colours
    texels = _sample(image, uv[np.asarray(mesh.faces)].mean(axis=1))
    return colours if texels is None else colours * texels


def _base_colour(material: object) -> tuple[np.ndarray, object | None]:
    """The material's base colour (RGBA in [0, 1]) and its base-colour texture (a PIL image or None)."""
    if isinstance(material, trimesh.visual.material.PBRMaterial):
        factor = material.baseColorFactor
        rgba = np.ones(4) if factor is None else np.asarray(factor, dtype=float) / 255.0
        return rgba, material.baseColorTexture
    if isinstance(material, trimesh.visual.material.SimpleMaterial):
        diffuse = material.diffuse
        rgba = np.ones(4) if diffuse is None else np.asarray(diffuse, dtype=float) / 255.0
        return (np.ones(4) if material.image is not None else rgba), material.image
    return np.asarray(DEFAULT_RGBA), None


def _sample(image: object, uv: np.ndarray) -> np.ndarray | None:
    """RGBA in [0, 1] of the texture at each UV (repeating, v upwards); None for an oversized or unreadable one."""
    size = getattr(image, "size", None)
    if not size or max(size) > MAX_TEXTURE_SIDE:
        log.warning("texture of size %s is over %d pixels a side: base colour used", size, MAX_TEXTURE_SIDE)
        return None
    try:
        pixels: np.ndarray = np.asarray(image.convert("RGBA"), dtype=np.float64) / 255.0  # type: ignore[attr-defined]
    except Exception as exc:  # a truncated or corrupt image: the colour falls back, the import goes on
        log.warning("texture cannot be read (%s): base colour used", exc.__class__.__name__)
        return None
    height, width = pixels.shape[:2]
    wrapped = np.mod(np.nan_to_num(uv), 1.0)
    columns = np.clip((wrapped[:, 0] * width).astype(int), 0, width - 1)
    rows = np.clip(((1.0 - wrapped[:, 1]) * height).astype(int), 0, height - 1)
    return np.asarray(pixels[rows, columns])


def keep_face_colours(mesh: trimesh.Trimesh) -> None:
    """In place: the mesh's visual becomes plain face colours (textures sampled), which survive concatenation."""
    colours = face_colours(mesh)
    if colours is None:
        colours = np.tile(DEFAULT_RGBA, (len(mesh.faces), 1))
    mesh.visual = trimesh.visual.ColorVisuals(mesh, face_colors=np.round(np.clip(colours, 0, 1) * 255).astype(np.uint8))


def coloured_parts(
    mesh: trimesh.Trimesh, colours: np.ndarray | None, explicit: tuple[float, ...] | None = None
) -> tuple[trimesh.Trimesh, tuple[int, ...], tuple[tuple[float, float, float, float], ...]]:
    """A plain copy of the mesh with its faces in contiguous runs of one colour, the runs' lengths and colours.

    `colours` are the first faces' colours (faces added later, filling holes, take the commonest); an entry's
    explicit colour wins; a mesh without colours is one grey part."""
    if explicit is not None or colours is None or len(colours) == 0:
        plain = trimesh.Trimesh(mesh.vertices, mesh.faces, process=False)
        colour = tuple(float(c) for c in (explicit or DEFAULT_RGBA))
        return plain, (len(mesh.faces),), ((colour[0], colour[1], colour[2], colour[3]),)
    palette, labels = quantise(colours[: len(mesh.faces)])
    counts = np.bincount(labels, minlength=len(palette))
    labels = np.concatenate([labels, np.full(len(mesh.faces) - len(labels), int(np.argmax(counts)))])
    labels = _merge_specks(np.asarray(mesh.faces), palette, labels)
    order = np.argsort(labels, kind="stable")
    counts = np.bincount(labels, minlength=len(palette))
    used = np.flatnonzero(counts)
    plain = trimesh.Trimesh(mesh.vertices, np.asarray(mesh.faces)[order], process=False)
    rgba = tuple(tuple(float(round(c, 4)) for c in palette[i]) for i in used)
    return plain, tuple(int(counts[i]) for i in used), rgba  # type: ignore[return-value]


def _merge_specks(faces: np.ndarray, palette: np.ndarray, labels: np.ndarray) -> np.ndarray:
    """Labels with every colour of too few faces (a renderer needs 4 vertices a part) given its nearest kept colour."""
    minimum = max(MIN_PART_FACES, int(MIN_PART_SHARE * len(faces)))
    counts = np.bincount(labels, minlength=len(palette))
    kept = [i for i in range(len(palette)) if counts[i] >= minimum and len(np.unique(faces[labels == i])) >= 4]
    if not kept:
        return np.full_like(labels, int(np.argmax(counts)))
    distance = np.linalg.norm(palette[:, None, :3] - palette[None, kept, :3], axis=2)
    nearest = np.asarray(kept)[np.argmin(distance, axis=1)]
    return nearest[labels]


def quantise(colours: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """At most MAX_COLOURS palette colours (RGBA in [0, 1]) and each face's palette index; deterministic."""
    colours = np.clip(np.nan_to_num(np.asarray(colours, dtype=float)), 0.0, 1.0)
    rounded = np.round(colours * 255) / 255
    unique, labels = np.unique(rounded, axis=0, return_inverse=True)
    if len(unique) <= MAX_COLOURS:
        return unique, labels.reshape(-1)
    centroids, labels = kmeans2(rounded, MAX_COLOURS, minit="++", seed=SEED)
    return np.clip(centroids, 0.0, 1.0), labels
