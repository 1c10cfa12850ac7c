"""The Franka Panda arm with its parallel-jaw hand, as a MuJoCo spec ready to attach to a scene.

Source: the Panda URDF and meshes that ship inside the `pybullet` wheel (`pybullet_data/franka_panda`, the real
kinematics and collision meshes). mujoco-menagerie's PyPI package fetches its meshes from GitHub on first use, which an
offline machine cannot do.
The URDF's inertias are placeholders (0.1 kg m^2 on every link), so each link gets the inertia of its collision mesh at
the URDF's mass; the arm is position-controlled with gravity compensation, like menagerie's model.
"""

from __future__ import annotations

import functools
import os
from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np

from physcensis.errors import PhyscensisError

ARM_JOINTS: tuple[str, ...] = tuple(f"joint{i}" for i in range(1, 8))
FINGER_JOINTS: tuple[str, str] = ("finger_joint1", "finger_joint2")
ARM_ACTUATORS: tuple[str, ...] = tuple(f"actuator{i}" for i in range(1, 8))
GRIPPER_ACTUATOR = "gripper"
HAND_BODY = "hand"
FINGER_BODIES: tuple[str, str] = ("left_finger", "right_finger")
TCP_SITE = "tcp"
# A ready pose: elbow up, hand pointing down, fingers 0.59 m in front of the base and 0.49 m above it.
HOME_Q = np.array([0.0, -0.3, 0.0, -2.2, 0.0, 2.0, np.pi / 4])
FINGER_OPEN = 0.04  # metres per finger: the hand opens to 8 cm
FINGER_CLOSED = 0.0
# Between the fingertip pads, measured from the hand's origin along its z axis (Franka's documented TCP).
TCP_OFFSET = 0.1034
# Menagerie's gains for the Panda's position actuators, and the joints' torque limits (N m).
ARM_KP = (4500.0, 4500.0, 3500.0, 3500.0, 2000.0, 2000.0, 2000.0)
ARM_KV = (450.0, 450.0, 350.0, 350.0, 200.0, 200.0, 200.0)
ARM_FORCE = (87.0, 87.0, 87.0, 87.0, 12.0, 12.0, 12.0)
GRIP_FORCE = 70.0  # N, the hand's continuous grasp force
FINGER_FRICTION = (1.5, 0.01, 0.0002)
FINGER_SOLREF = 0.005  # s: contact time constant of the finger pads (two physics steps of the robot world)
PEDESTAL_SIZE = (0.12, 0.12)
MOUNT_EDGES = ("auto", "front", "back", "left", "right")  # half extents of the box the arm is mounted on

_URDF_BODY_NAMES = {
    "panda_link0": "link0",
    **{f"panda_link{i}": f"link{i}" for i in range(1, 8)},
    "panda_hand": HAND_BODY,
    "panda_leftfinger": FINGER_BODIES[0],
    "panda_rightfinger": FINGER_BODIES[1],
}
_URDF_MASS = {  # the URDF's link masses; its hand and fingers are merged into link7/8 in some variants
    "link0": 2.9,
    "link1": 2.7,
    "link2": 2.73,
    "link3": 2.04,
    "link4": 2.08,
    "link5": 3.0,
    "link6": 1.3,
    "link7": 0.2,
    HAND_BODY: 0.81,
    FINGER_BODIES[0]: 0.1,
    FINGER_BODIES[1]: 0.1,
}


class RobotModelError(PhyscensisError):
    """The robot's model cannot be loaded (missing extra, unreadable file)."""


@dataclass(frozen=True)
class Mount:
    """Where the arm's base stands: at the middle of one of the support's edges (plus `offset` along it), facing
    across the support. Edges in the project's coordinates: front +x, back -x, left +y, right -y; `auto` takes a
    longer edge (right when the support is deeper than wide, else front), so the far side is nearest in reach."""

    edge: str = "auto"
    offset: float = 0.0  # along the edge, metres (+ towards +x on left/right, towards +y on front/back)
    clearance: float = 0.08  # from the support's edge to the base's axis, metres

    def side(self, support_size: tuple[float, float]) -> str:
        if self.edge not in MOUNT_EDGES:
            raise RobotModelError(f"robot mount edge {self.edge!r} is not one of: {', '.join(MOUNT_EDGES)}")
        if self.edge != "auto":
            return self.edge
        return "right" if support_size[0] >= support_size[1] else "front"

    def pose(self, support_size: tuple[float, float], top_height: float) -> tuple[np.ndarray, float]:
        """(base position, yaw) for a support whose top is centred on x = y = 0."""
        side = self.side(support_size)
        across, along = (0, 1) if side in ("front", "back") else (1, 0)
        length = support_size[along]
        if not np.isfinite(self.offset) or abs(self.offset) > length / 2.0:
            raise RobotModelError(
                f"robot mount offset {self.offset:g} m is off the {length:g} m {side} edge (at most "
                f"{length / 2.0:g} m either way)"
            )
        sign = 1.0 if side in ("front", "left") else -1.0
        position = np.zeros(3)
        position[across] = sign * (support_size[across] / 2.0 + self.clearance)
        position[along] = self.offset
        position[2] = top_height
        facing = -sign * np.eye(2)[across]  # towards the support's centre
        return position, float(np.arctan2(facing[1], facing[0]))


def _pybullet_panda_dir() -> Path:
    try:
        import pybullet_data
    except ImportError as err:
        raise RobotModelError(
            "the robot needs the Panda model shipped with pybullet: pip install 'physcensis[robot]'"
        ) from err
    folder = Path(pybullet_data.getDataPath()) / "franka_panda"
    if not (folder / "panda.urdf").is_file():
        raise RobotModelError(f"{folder / 'panda.urdf'} is missing from the pybullet_data install")
    return folder


def _spec_from_urdf(folder: Path) -> mujoco.MjSpec:
    text = (folder / "panda.urdf").read_text().replace("package://", "")
    spec = mujoco.MjSpec.from_string(text)
    spec.meshdir = str(folder) + os.sep
    spec.compiler.fusestatic = False
    spec.compiler.discardvisual = False
    for body in spec.bodies:
        if body.name in _URDF_BODY_NAMES:
            body.name = _URDF_BODY_NAMES[body.name]
    for joint in spec.joints:
        joint.name = joint.name.removeprefix("panda_")
    spec.delete(spec.body("panda_grasptarget"))  # a marker link; the `tcp` site replaces it
    link8 = spec.body("panda_link8")  # the massless flange frame: no placeholder inertia either
    link8.fullinertia = [np.nan] * 6
    link8.inertia = [0.0, 0.0, 0.0]
    for equality in list(spec.equalities):  # the URDF's finger mimic; _add_controls writes its own coupling
        spec.delete(equality)
    return spec


def _mesh_inertias(spec: mujoco.MjSpec) -> None:
    """Replace the URDF's placeholder inertias by those of each link's collision mesh at the link's mass."""
    probe = spec.copy()
    for body in probe.bodies:
        if body.name in _URDF_MASS:
            body.explicitinertial = False
    probe.compiler.inertiafromgeom = mujoco.mjtInertiaFromGeom.mjINERTIAFROMGEOM_TRUE
    model = probe.compile()
    for body in spec.bodies:
        if body.name not in _URDF_MASS:
            continue
        index = model.body(body.name).id
        geom_mass = float(model.body_mass[index])
        if geom_mass <= 0.0:
            continue
        scale = _URDF_MASS[body.name] / geom_mass
        body.explicitinertial = True
        body.mass = _URDF_MASS[body.name]
        body.ipos = model.body_ipos[index].copy()
        body.iquat = model.body_iquat[index].copy()
        body.inertia = model.body_inertia[index] * scale
        body.fullinertia = [np.nan] * 6  # the URDF gave a full tensor; the diagonal above replaces it


def _add_controls(spec: mujoco.MjSpec) -> None:
    for body in spec.bodies:
        if body.name in _URDF_MASS:
            body.gravcomp = 1.0
    for name, joint_name, kp, kv, force in zip(ARM_ACTUATORS, ARM_JOINTS, ARM_KP, ARM_KV, ARM_FORCE, strict=True):
        joint = spec.joint(joint_name)
        actuator = spec.add_actuator(name=name, target=joint_name, trntype=mujoco.mjtTrn.mjTRN_JOINT)
        actuator.set_to_position(kp=kp, kv=kv)
        actuator.ctrlrange = joint.range
        actuator.ctrllimited = mujoco.mjtLimited.mjLIMITED_TRUE
        actuator.forcerange = [-force, force]
        actuator.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
        joint.armature = 0.1
        joint.damping = [1.0, 0.0, 0.0]
    for name in FINGER_JOINTS:
        spec.joint(name).range = [0.0, FINGER_OPEN]
        spec.joint(name).armature = 0.01
        spec.joint(name).actfrcrange = [-GRIP_FORCE, GRIP_FORCE]  # the URDF's 20 N effort would cap the grasp force
    spec.add_equality(
        type=mujoco.mjtEq.mjEQ_JOINT,
        name1=FINGER_JOINTS[1],
        name2=FINGER_JOINTS[0],
        data=[0.0, 1.0, 0.0, 0.0, 0.0] + [0.0] * 7,
        solref=[FINGER_SOLREF, 1.0],  # the fingers stay mirrored under the grasp force
    )
    gripper = spec.add_actuator(name=GRIPPER_ACTUATOR, target=FINGER_JOINTS[0], trntype=mujoco.mjtTrn.mjTRN_JOINT)
    # Stiff enough that closing on a thin wall (a few mm short of the target) still squeezes with tens of newtons,
    # clipped at the hand's force; kv keeps the finger critically damped.
    gripper.set_to_position(kp=20000.0, kv=100.0)
    gripper.ctrlrange = [FINGER_CLOSED, FINGER_OPEN]
    gripper.ctrllimited = mujoco.mjtLimited.mjLIMITED_TRUE
    gripper.forcerange = [-GRIP_FORCE, GRIP_FORCE]
    gripper.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE


def _dress(spec: mujoco.MjSpec) -> None:
    """Finger friction, colours and the TCP site."""
    for geom in spec.geoms:
        parent = geom.parent.name
        geom.rgba = [0.95, 0.95, 0.95, 1.0] if parent not in (HAND_BODY, *FINGER_BODIES) else [0.25, 0.25, 0.27, 1.0]
        if parent in FINGER_BODIES:
            geom.friction = list(FINGER_FRICTION)
            geom.condim = 4
            geom.priority = 1
            # As stiff as the scene's thin walls: at MuJoCo's default (0.02 s) a 70 N pinch sinks a pad 4-5 mm into
            # a cup's wall and the grip closes through it.
            geom.solref = [FINGER_SOLREF, 1.0]
            geom.solimp = [0.95, 0.99, 0.001, 0.5, 2.0]
    spec.body(HAND_BODY).add_site(
        name=TCP_SITE, pos=[0.0, 0.0, TCP_OFFSET], size=[0.005, 0.005, 0.005], rgba=[1, 0, 0, 0]
    )


@functools.lru_cache(maxsize=1)
def _panda_xml() -> str:
    spec = _spec_from_urdf(_pybullet_panda_dir())
    _mesh_inertias(spec)
    _add_controls(spec)
    _dress(spec)
    spec.compile()  # fail here, with the source named, rather than inside a scene
    return spec.to_xml()


def panda_spec() -> mujoco.MjSpec:
    """A fresh, editable spec of the arm and hand (base body `link0` at the origin, facing +x)."""
    try:
        return mujoco.MjSpec.from_string(_panda_xml())
    except ValueError as err:
        raise RobotModelError(f"the Panda model does not compile: {err}") from err
