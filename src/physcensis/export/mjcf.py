"""MJCF export: `DIR/mjcf/scene.xml` with its mesh files beside it, loadable by plain MuJoCo."""

from __future__ import annotations

import re
from pathlib import Path

import mujoco
import numpy as np
import trimesh

from physcensis.export.bodies import KeptByContent
from physcensis.fileio import atomic_directory, atomic_write_text
from physcensis.physics.mujoco_engine import BuiltScene

MESH_DIR = "meshes"


def export_mjcf(built: BuiltScene, out_dir: str | Path) -> Path:
    """Write the built scene as MJCF (objects are free bodies with their mass, friction and inertia).

    Meshes that exist only as vertices (convex collision parts) are written as the
    STL of their convex hull, which is what MuJoCo uses of them anyway.
    """
    spec = _with_part_masses(built.spec.copy())
    out_dir = Path(out_dir)
    with atomic_directory(out_dir) as staging:
        (staging / MESH_DIR).mkdir()
        used: set[str] = set()
        for mesh in spec.meshes:
            vertices = np.asarray(mesh.uservert, dtype=float).reshape(-1, 3)
            faces = np.asarray(mesh.userface, dtype=np.int64).reshape(-1, 3)
            name = _file_name(mesh.name, used)
            (staging / MESH_DIR / name).write_bytes(_stl(vertices, faces))
            mesh.uservert = []
            mesh.userface = []
            mesh.file = name
        spec.meshdir = MESH_DIR
        spec.modelfiledir = str(staging)  # to_xml compiles, so it must find the files it names
        spec.modelname = "physcensis_scene"
        xml = spec.to_xml()
        atomic_write_text(staging / "scene.xml", xml)
    return out_dir / "scene.xml"


def _stl(vertices: np.ndarray, faces: np.ndarray) -> bytes:
    """The mesh as binary STL (the convex hull of a mesh given only as vertices), kept for the process."""

    def make() -> bytes:
        shape = trimesh.Trimesh(vertices, faces, process=False) if len(faces) else trimesh.Trimesh(vertices).convex_hull
        exported = shape.export(file_type="stl")
        assert isinstance(exported, bytes)  # binary STL
        return exported

    return _STLS.get((vertices.tobytes(), faces.tobytes()), make)


_STLS: KeptByContent[bytes] = KeptByContent(2048)  # mesh files (tens of kilobytes each)


def _with_part_masses(spec: mujoco.MjSpec) -> mujoco.MjSpec:
    """The spec once compiled with every body's inertia from its parts: MuJoCo's XML writer gives each geom the mass
    a compile derived for it, and a body with an explicit inertial from its first compile on has its geoms written
    massless. The file keeps each part's mass beside the body's inertial."""
    explicit = [body for body in spec.bodies if body.explicitinertial]
    for body in explicit:
        body.explicitinertial = False
    spec.compile()
    for body in explicit:
        body.explicitinertial = True
    return spec


def _file_name(mesh_name: str, used: set[str]) -> str:
    base = re.sub(r"[^A-Za-z0-9_.-]", "_", mesh_name) or "mesh"
    name, k = f"{base}.stl", 1
    while name in used:
        name, k = f"{base}_{k}.stl", k + 1
    used.add(name)
    return name
