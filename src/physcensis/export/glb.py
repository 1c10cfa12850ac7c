"""glTF binary export: the whole scene with its colours, for viewers, Blender and web pages.

The node tree is `world -> support | ground | <object id>`, each object node
carrying its pose and one child mesh per coloured part (glTF gives each mesh one
material).  glTF is y-up; a root rotation turns the z-up scene upright, so
viewers show it standing.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import trimesh

from physcensis.assets.model import RGBA, Asset
from physcensis.export.bodies import GROUND_RGBA, ExportScene, ground_slab
from physcensis.fileio import atomic_write_bytes

ROOT = "scene"  # under trimesh's and glTF loaders' own "world" base frame
Z_UP_TO_Y_UP = np.array([[1.0, 0, 0, 0], [0, 0, 1, 0], [0, -1, 0, 0], [0, 0, 0, 1]])


def scene_graph(export: ExportScene) -> trimesh.Scene:
    """A trimesh Scene with one node per object (named by its id) under a y-up root node."""
    scene = trimesh.Scene()
    scene.graph.update(frame_from=scene.graph.base_frame, frame_to=ROOT, matrix=Z_UP_TO_Y_UP)
    _add_asset(scene, "support", export.support, np.eye(4))
    if export.ground:
        scene.graph.update(frame_from=ROOT, frame_to="ground", matrix=np.eye(4))
        scene.add_geometry(
            _coloured(ground_slab(), GROUND_RGBA),
            node_name="ground_mesh",
            geom_name="ground_mesh",
            parent_node_name="ground",
        )
    for body in export.bodies:
        _add_asset(scene, body.id, body.asset, body.transform)
    return scene


def export_glb(export: ExportScene, path: str | Path) -> Path:
    path = Path(path)
    atomic_write_bytes(path, scene_graph(export).export(file_type="glb"))
    return path


def _add_asset(scene: trimesh.Scene, node: str, asset: Asset, transform: np.ndarray) -> None:
    scene.graph.update(frame_from=ROOT, frame_to=node, matrix=transform)
    for k, (mesh, color) in enumerate(_parts_by_colour(asset)):
        name = f"{node}_part{k}"
        scene.add_geometry(_coloured(mesh, color), node_name=name, geom_name=name, parent_node_name=node)


def _parts_by_colour(asset: Asset) -> list[tuple[trimesh.Trimesh, RGBA]]:
    """The visual parts merged by colour: one glTF mesh (and material) per colour, not per part."""
    groups: dict[RGBA, list[trimesh.Trimesh]] = {}
    for mesh, color in asset.visual_parts():
        groups.setdefault((*color,), []).append(mesh)  # a tuple even where the asset holds lists: a dict key
    return [(_merged(meshes), color) for color, meshes in groups.items()]


def _merged(meshes: list[trimesh.Trimesh]) -> trimesh.Trimesh:
    merged = trimesh.util.concatenate(meshes)
    if not isinstance(merged, trimesh.Trimesh):  # trimesh types the result as any Geometry
        raise TypeError(f"merging {len(meshes)} meshes gave a {type(merged).__name__}, not a mesh")
    return merged


def _coloured(mesh: trimesh.Trimesh, color: RGBA) -> trimesh.Trimesh:
    material = trimesh.visual.material.PBRMaterial(
        baseColorFactor=[int(round(255 * c)) for c in color],
        metallicFactor=0.0,
        roughnessFactor=0.7,
        alphaMode="BLEND" if color[3] < 1.0 else "OPAQUE",
    )
    coloured = mesh.copy()
    coloured.visual = trimesh.visual.TextureVisuals(material=material)
    return coloured
