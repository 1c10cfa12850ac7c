"""Contact settings a scene is simulated under.

`OURS` is what placement and verification run with: an elliptic friction cone with impratio 10 and stiff contacts on
a 2 ms step, so thin walls hold and nothing creeps. `MUJOCO_DEFAULT` is what a user gets who loads the MJCF without
its `<option>` block, or builds a robot environment with MuJoCo's defaults: a pyramidal cone, impratio 1, MuJoCo's
default solref/solimp, and the paper's 0.01 s step. A scene is only accepted if it rests under both.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco

from physcensis.physics.engine import Tolerance


@dataclass(frozen=True)
class ContactProfile:
    """How MuJoCo is configured for a scene: the step, the friction cone and the contact stiffness."""

    name: str
    timestep: float
    cone: int  # mujoco.mjtCone
    impratio: float
    solref: tuple[float, float] | None  # on every collision geom; None keeps MuJoCo's default (0.02, 1)


OURS = ContactProfile(
    name="mujoco",
    timestep=0.002,  # stiff contacts (solref 0.005) need a step of at most 2.5 ms
    cone=int(mujoco.mjtCone.mjCONE_ELLIPTIC),
    impratio=10.0,  # stiffer friction: stacks and leaning objects do not creep
    solref=(0.005, 1.0),  # stiff contacts keep thin walls from interpenetrating
)
MUJOCO_DEFAULT = ContactProfile(
    name="mujoco-default",
    timestep=0.01,  # the paper's settle step
    cone=int(mujoco.mjtCone.mjCONE_PYRAMIDAL),
    impratio=1.0,
    solref=None,
)
PROFILES = {p.name: p for p in (OURS, MUJOCO_DEFAULT)}
UNDER_DEFAULTS = "under MuJoCo's default contact settings"  # how a failure's reason names MUJOCO_DEFAULT

# Under MuJoCo's defaults an object is judged by how far it moves, as the settle distance judges it: with no torsional
# friction (MuJoCo's default condim 3) a round pen leaning in a holder spins about its own axis without going anywhere.
MUJOCO_DEFAULT_TOLERANCE = Tolerance(translation_m=0.01, rotation_rad=math.pi)
