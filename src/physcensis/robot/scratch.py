"""Small scratch MuJoCo models built from parts of a compiled scene: an object copied with its collision geoms, mass,
inertia and friction, or the scene's other collision geoms frozen where they are now.

Copies are made from the compiled model (not the scene's files), so they collide exactly like the originals: mesh
geoms keep the compiled vertices (already in the geom's frame) and the contact parameters.
"""

from __future__ import annotations

import mujoco
import numpy as np

from physcensis.robot.convex import collision_geoms


def _mesh_name(prefix: str, geom: int) -> str:
    return f"{prefix}mesh{geom}"


def _copy_geom(
    spec: mujoco.MjSpec, parent: mujoco.MjsBody, model: mujoco.MjModel, geom: int, pos, quat, prefix: str
) -> mujoco.MjsGeom:
    kind = mujoco.mjtGeom(int(model.geom_type[geom]))
    copy = parent.add_geom(type=kind, pos=list(pos), quat=list(quat), size=model.geom_size[geom].tolist())
    if kind == mujoco.mjtGeom.mjGEOM_MESH:
        mesh = int(model.geom_dataid[geom])
        start, count = int(model.mesh_vertadr[mesh]), int(model.mesh_vertnum[mesh])
        name = _mesh_name(prefix, geom)
        spec.add_mesh(name=name, uservert=model.mesh_vert[start : start + count].ravel().tolist())
        copy.meshname = name
    copy.friction = model.geom_friction[geom].tolist()
    copy.condim = int(model.geom_condim[geom])
    copy.solref = model.geom_solref[geom].tolist()
    copy.solimp = model.geom_solimp[geom].tolist()
    copy.margin = float(model.geom_margin[geom])
    copy.contype = int(model.geom_contype[geom])
    copy.conaffinity = int(model.geom_conaffinity[geom])
    copy.priority = int(model.geom_priority[geom])
    copy.mass = 0.0  # the body's inertial is copied whole
    return copy


def add_object_copy(spec: mujoco.MjSpec, model: mujoco.MjModel, body: int, name: str) -> mujoco.MjsBody:
    """A free body `name` with the original body's collision geoms (in its own frame), mass and inertia."""
    copy = spec.worldbody.add_body(name=name)
    copy.add_freejoint(name=name + "_free")
    copy.explicitinertial = True
    copy.mass = float(model.body_mass[body])
    copy.ipos = model.body_ipos[body].tolist()
    copy.iquat = model.body_iquat[body].tolist()
    copy.inertia = model.body_inertia[body].tolist()
    for geom in collision_geoms(model, body):
        _copy_geom(spec, copy, model, geom, model.geom_pos[geom], model.geom_quat[geom], name + "/")
    return copy


OWNER_SEPARATOR = "::"


def add_frozen_geoms(spec: mujoco.MjSpec, model: mujoco.MjModel, data: mujoco.MjData, bodies: list[int]) -> None:
    """The bodies' collision geoms as static world geoms at their current poses (world-body geoms included), each
    named `<body name>::<geom id>` so a contact can say whose part it touched."""
    for body in bodies:
        for geom in collision_geoms(model, body):
            quat = np.zeros(4)
            mujoco.mju_mat2Quat(quat, data.geom_xmat[geom])
            copy = _copy_geom(spec, spec.worldbody, model, geom, data.geom_xpos[geom], quat, f"frozen{body}/")
            copy.name = f"{model.body(body).name}{OWNER_SEPARATOR}{geom}"


def frozen_owner(model: mujoco.MjModel, geom: int) -> str:
    """The original body's name of a frozen geom ('' for any other geom)."""
    name = model.geom(geom).name
    return name.split(OWNER_SEPARATOR)[0] if OWNER_SEPARATOR in name else ""


def copy_options(spec: mujoco.MjSpec, model: mujoco.MjModel) -> None:
    """The scene's integrator, step, friction cone and gravity."""
    spec.option.timestep = float(model.opt.timestep)
    spec.option.integrator = int(model.opt.integrator)
    spec.option.cone = int(model.opt.cone)
    spec.option.impratio = float(model.opt.impratio)
    spec.option.gravity = model.opt.gravity.tolist()
    spec.option.noslip_iterations = int(model.opt.noslip_iterations)
