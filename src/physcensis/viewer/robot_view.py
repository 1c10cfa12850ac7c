"""The arm of a recorded episode: the Panda world the episode ran in (robot/world.py, mounted as its attributes say),
put into each recorded state, gives every link's pose at every frame; its meshes are the model's own."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np
import trimesh

from physcensis.viewer.episode import EpisodeTrack
from physcensis.viewer.scene_view import MeshPart, Pose, mesh_part


@dataclass(frozen=True, eq=False)
class RobotLink:
    """One moving body of the arm, with its meshes in its own frame."""

    name: str
    parts: tuple[tuple[MeshPart, Pose], ...]  # each mesh and its pose in the link's frame


@dataclass(frozen=True, eq=False)
class RobotView:
    links: tuple[RobotLink, ...]
    fixed: tuple[MeshPart, ...]  # what stands still, in world coordinates: the pedestal
    poses: np.ndarray  # (T, links, 7): each link's world pose at each frame of the episode

    def link_poses(self, frame: int) -> dict[str, Pose]:
        k = min(max(frame, 0), len(self.poses) - 1)
        return {link.name: self.poses[k, i].copy() for i, link in enumerate(self.links)}


def robot_view(scene_dir: Path, track: EpisodeTrack) -> RobotView:
    """The arm along `track`, in the world the episode was recorded in. Raises PhyscensisError when that world cannot
    be built here (no MJCF export in the folder, no robot extra) or the recorded states do not fit it."""
    from physcensis.robot.panda import Mount
    from physcensis.robot.record import set_state
    from physcensis.robot.world import PREFIX, build_world

    mount = Mount(edge=str(track.attrs.get("mount", "auto")), offset=float(track.attrs.get("mount_offset", 0.0)))
    world = build_world(scene_dir, mount)
    model, data = world.model, world.data
    bodies = sorted(b for b in world.robot_bodies if any(model.geom_bodyid == b))
    links = tuple(
        RobotLink(model.body(b).name.removeprefix(PREFIX), tuple(_geom_part(model, g) for g in _geoms_of(model, b)))
        for b in bodies
    )
    poses = np.zeros((track.frames, len(bodies), 7))
    for k, state in enumerate(track.states):
        set_state(world, state)
        poses[k, :, :3] = data.xpos[bodies]
        poses[k, :, 3:] = data.xquat[bodies]
    pedestal = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "panda_pedestal")
    fixed: tuple[MeshPart, ...] = ()
    if pedestal >= 0:
        part, pose = _geom_part(model, pedestal)
        fixed = (_placed(part, pose),)
    return RobotView(links, fixed, poses)


def _geoms_of(model: mujoco.MjModel, body: int) -> list[int]:
    shown = (int(mujoco.mjtGeom.mjGEOM_MESH), int(mujoco.mjtGeom.mjGEOM_BOX))
    return [int(g) for g in np.flatnonzero(model.geom_bodyid == body) if int(model.geom_type[g]) in shown]


def _geom_part(model: mujoco.MjModel, geom: int) -> tuple[MeshPart, Pose]:
    """A mesh or box geom as a mesh in its own frame, and that frame's pose in its body's."""
    if int(model.geom_type[geom]) == int(mujoco.mjtGeom.mjGEOM_MESH):
        mesh_id = int(model.geom_dataid[geom])
        first, count = int(model.mesh_vertadr[mesh_id]), int(model.mesh_vertnum[mesh_id])
        face_first, face_count = int(model.mesh_faceadr[mesh_id]), int(model.mesh_facenum[mesh_id])
        mesh = trimesh.Trimesh(
            model.mesh_vert[first : first + count].copy(),
            model.mesh_face[face_first : face_first + face_count].copy(),
            process=False,
        )
    else:
        mesh = trimesh.creation.box(extents=2.0 * model.geom_size[geom])
    material = int(model.geom_matid[geom])
    colour = model.mat_rgba[material] if material >= 0 else model.geom_rgba[geom]
    return mesh_part(mesh, colour), np.concatenate([model.geom_pos[geom], model.geom_quat[geom]])


def _placed(part: MeshPart, pose: Pose) -> MeshPart:
    """`part` moved by `pose` (its vertices in the frame `pose` is given in)."""
    rotation = np.zeros(9)
    mujoco.mju_quat2Mat(rotation, np.asarray(pose[3:], dtype=float))
    vertices = part.vertices.astype(float) @ rotation.reshape(3, 3).T + pose[:3]
    return MeshPart(vertices.astype(np.float32), part.faces, part.rgb, part.opacity)
