"""Loading one untrusted mesh file of a user library: bounded, confined to the library, checked before use.

Every problem becomes an `AssetError` with a plain reason: a file too large or not a
regular file, a parser failure, no triangles, faces that refer to missing vertices,
NaN or infinite coordinates, or more triangles than MAX_FACES once a glTF scene's
instances are counted.  Files a mesh refers to (glTF buffers) are read through
`LibraryResolver`: inside the library folder and size-bounded too (material
libraries and textures as well).  Each geometry's colours (vertex colours,
materials, textures) become face colours before a scene is merged into one mesh,
so they survive it (see `colours.py`).
"""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np
import trimesh
from trimesh.resolvers import Resolver

from physcensis.assets.colours import keep_face_colours
from physcensis.assets.errors import AssetError
from physcensis.fileio import BoundError, read_bounded

MESH_SUFFIXES = (".glb", ".gltf", ".obj", ".stl", ".ply")
MAX_MESH_BYTES = 100_000_000  # one mesh file, and each file it refers to
MAX_FACES = 2_000_000  # triangles after a scene's instances are expanded
MAX_COORDINATE = 1e12  # in the file's units; anything larger overflows volumes and inertia


def first_line(exc: BaseException) -> str:
    """`Class: first line of the message`, for one-line reasons."""
    text = str(exc).strip()
    return f"{exc.__class__.__name__}: {text.splitlines()[0] if text else 'no details'}"


def confined_path(root: Path, relative: str) -> Path:
    """The resolved path of `relative` under `root`; AssetError if it leaves `root` or cannot be resolved."""
    try:
        path = (root / relative).resolve()
    except RuntimeError:  # Python 3.11 raises this for a symlink loop
        raise AssetError(f"path {relative!r} is a symlink loop") from None
    except (OSError, ValueError) as exc:  # embedded NUL byte, name too long, ...
        raise AssetError(f"path {relative!r} cannot be resolved ({first_line(exc)})") from None
    if not path.is_relative_to(root):
        raise AssetError(f"path {relative!r} points outside the library folder; refused")
    return path


class LibraryResolver(Resolver):
    """Files a mesh refers to (glTF buffers), read from `base` but never outside `root` nor beyond the size bound."""

    def __init__(self, root: Path, base: Path) -> None:
        self.root = root
        self.base = base

    def get(self, key: str) -> bytes:
        path = confined_path(self.root, str(self.base.relative_to(self.root) / key.strip()))
        try:
            return read_bounded(path, MAX_MESH_BYTES, f"file {key!r} the mesh refers to")
        except BoundError as exc:
            raise AssetError(str(exc)) from None

    def write(self, name: str, data: str | bytes) -> None:
        raise AssetError("writing next to a library mesh is not allowed")

    def namespaced(self, namespace: str) -> LibraryResolver:
        return LibraryResolver(self.root, confined_path(self.root, str(self.base.relative_to(self.root) / namespace)))

    def keys(self) -> list[str]:
        return []


def load_mesh_file(path: Path, root: Path) -> trimesh.Trimesh:
    """The checked, vertex-merged triangle mesh in `path` (a resolved path inside the resolved `root`)."""
    suffix = path.suffix.lower()
    if suffix not in MESH_SUFFIXES:
        raise AssetError(f"unsupported mesh format {path.suffix!r} (use {', '.join(MESH_SUFFIXES)})")
    try:
        data = read_bounded(path, MAX_MESH_BYTES, "mesh file")
    except BoundError as exc:
        raise AssetError(str(exc)) from None
    scene = _parse(data, suffix, LibraryResolver(root, path.parent))
    faces = _instanced_face_count(scene)
    if faces > MAX_FACES:
        raise AssetError(f"the mesh has {faces:,} triangles, over the limit of {MAX_FACES:,}")
    try:
        for geometry in scene.geometry.values():
            if isinstance(geometry, trimesh.Trimesh):
                keep_face_colours(geometry)
        mesh = scene.to_mesh()
    except Exception as exc:  # a broken scene graph or index is the file's fault
        raise AssetError(f"cannot read mesh ({first_line(exc)})") from None
    check_mesh_arrays(mesh)
    mesh.process()  # merge duplicate vertices (STL stores three per triangle)
    return mesh


def _parse(data: bytes, suffix: str, resolver: LibraryResolver) -> trimesh.Scene:
    try:
        return trimesh.load_scene(
            io.BytesIO(data), file_type=suffix[1:], resolver=resolver, process=False, skip_materials=False
        )
    except AssetError:
        raise
    except Exception as exc:  # any parser failure is the file's fault: report it
        raise AssetError(f"cannot read mesh ({first_line(exc)})") from None


def _instanced_face_count(scene: trimesh.Scene) -> int:
    counts = {name: len(getattr(geometry, "faces", ())) for name, geometry in scene.geometry.items()}
    total = 0
    for node in scene.graph.nodes_geometry:
        total += counts.get(scene.graph[node][1], 0)
        if total > MAX_FACES:
            break
    return total


def check_mesh_arrays(mesh: trimesh.Trimesh) -> None:
    """Refuse meshes without triangles, with faces naming missing vertices, or with NaN / huge coordinates."""
    if not isinstance(mesh, trimesh.Trimesh) or len(mesh.faces) == 0:
        raise AssetError("the file holds no triangles (an empty mesh or a point cloud)")
    vertices = np.asarray(mesh.vertices, dtype=float)
    faces = np.asarray(mesh.faces)
    if faces.min() < 0:
        raise AssetError("a face has a negative vertex index")
    if faces.max() >= len(vertices):
        raise AssetError(f"a face refers to vertex {int(faces.max()) + 1} but the file has only {len(vertices)}")
    bad = ~np.isfinite(vertices).all(axis=1)
    if bad.any():
        raise AssetError(f"{int(bad.sum())} of {len(vertices)} vertices have NaN or infinite coordinates")
    largest = float(np.abs(vertices).max())
    if largest > MAX_COORDINATE:
        raise AssetError(f"a vertex coordinate is {largest:.3g}, beyond {MAX_COORDINATE:.0g} (wrong unit or junk)")
