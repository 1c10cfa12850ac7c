"""MuJoCo engine: build a model from a Scene with MjSpec, settle it, measure it.

Each placed object becomes a free body named by its id with its asset's collision
parts, its visual mesh as display-only geoms, and its own mass, friction and
centre of mass. The support is static geometry with a ground plane under it.
"""

from __future__ import annotations

import logging
import math
import time
from collections import OrderedDict, deque
from collections.abc import Sequence
from dataclasses import dataclass, field

import mujoco
import numpy as np

from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.assets.model import Asset
from physcensis.physics.built import BuiltScene
from physcensis.physics.engine import (
    AT_REST,
    DEFAULT_TOLERANCE,
    SETTLE_CLAMP_M,
    SETTLE_S,
    ObjectMotion,
    RestRule,
    SettleDistance,
    SettleResult,
    Tolerance,
    quaternion_angle,
    spin_axis,
    turn_angle,
)
from physcensis.physics.mujoco_assets import MIN_PART_MASS_KG, add_asset_geoms, add_support_fixture, part_masses
from physcensis.physics.profiles import MUJOCO_DEFAULT, OURS, ContactProfile
from physcensis.physics.render import DEFAULT_VIEW, Camera, render_built
from physcensis.scene import PlacedObject, Scene, Support

TIMESTEP = OURS.timestep
CHECK_EVERY = 50  # steps between explosion checks
MAX_SPEED = 50.0  # m/s or rad/s: beyond this the simulation is treated as blown up
FELL_BELOW_M = 0.05  # an object this far below where it started has fallen off its support
REPORT_PENETRATION_M = 0.002
COM_TOLERANCE_M = 1e-4
REST_SPEED = 0.002  # m/s and rad/s: below this everything counts as at rest
POSED_MODELS = 8  # compiled models an engine keeps for `build_posed`
KEPT_SETTLES = 16  # settles an engine keeps, by start state, for checks that simulate the same settle again
KEPT_INERTIALS = 4096  # assets (and masses at the parts' floor) whose derived inertia is kept
PROBE_MASS_KG = 1.0  # the mass their inertia is derived for and scaled from
COMPILER_EPS = 1e-14  # MuJoCo's compiler leaves a quaternion this close to unit length as it is
# MuJoCo resets the whole state (back to the model's initial pose) after these: a run that met one has diverged
UNSTABLE_WARNINGS = (
    mujoco.mjtWarning.mjWARN_BADQACC,
    mujoco.mjtWarning.mjWARN_BADQPOS,
    mujoco.mjtWarning.mjWARN_BADQVEL,
)

_log = logging.getLogger("physcensis.mujoco")


def _log_mujoco_warning(text: str) -> None:
    # Unstable-state warnings are reported by the engine itself, with the object and what it means.
    _log.log(logging.DEBUG if "unstable" in text else logging.WARNING, "MuJoCo: %s", text.strip())


def route_mujoco_warnings() -> None:
    """MuJoCo prints warnings on stdout (which would corrupt `--json` output) and appends them to MUJOCO_LOG.TXT
    in the working directory; send them to logging instead, unless the application installed its own handler."""
    if mujoco.get_mju_user_warning() is None:
        mujoco.set_mju_user_warning(_log_mujoco_warning)


route_mujoco_warnings()


def _configure(spec: mujoco.MjSpec, profile: ContactProfile) -> None:
    spec.option.timestep = profile.timestep
    spec.option.gravity = [0.0, 0.0, -9.81]
    spec.option.cone = mujoco.mjtCone(profile.cone)
    spec.option.impratio = profile.impratio
    spec.visual.global_.offwidth = 1920
    spec.visual.global_.offheight = 1440
    spec.visual.quality.offsamples = 8
    spec.visual.headlight.ambient = [0.3, 0.3, 0.3]
    spec.visual.headlight.diffuse = [0.4, 0.4, 0.4]
    spec.visual.headlight.specular = [0.05, 0.05, 0.05]
    spec.visual.map.znear = 0.005


def build_scene(
    scene: Scene,
    catalogue: Catalogue | None = None,
    *,
    objects: Sequence[PlacedObject] | None = None,
    visual: bool = True,
    fixed: Sequence[PlacedObject] = (),
    profile: ContactProfile = OURS,
) -> BuiltScene:
    """Compile `scene` (its placed objects, or `objects`) into a MuJoCo model under `profile`'s contact settings;
    `fixed` objects are added as static geometry (already at rest and far from what is being tested, so they need
    not be simulated)."""
    catalogue = catalogue or default_catalogue()
    chosen = list(scene.placed if objects is None else objects)
    assets = {o.id: catalogue.asset_for(o.asset, o.description) for o in chosen}
    spec = mujoco.MjSpec()
    _configure(spec, profile)
    if visual:
        _add_lights_and_floor(spec, scene)
    add_support_fixture(spec, scene.support, floor=True, solref=profile.solref)
    if visual and spec.geom("support_ground") is not None:
        spec.geom("support_ground").material = "floor_tiles"
        spec.geom("support_ground").rgba = [1.0, 1.0, 1.0, 1.0]
    for obj in fixed:
        body = spec.worldbody.add_body(name=obj.id, pos=list(obj.position), quat=list(obj.quaternion))
        add_asset_geoms(
            spec,
            body,
            catalogue.asset_for(obj.asset, obj.description),
            obj.id,
            friction=obj.friction,
            solref=profile.solref,
            visual=visual,
            static=True,
        )
    for obj in chosen:
        body = spec.worldbody.add_body(name=obj.id, pos=list(obj.position), quat=list(obj.quaternion))
        body.add_freejoint()
        add_asset_geoms(
            spec,
            body,
            assets[obj.id],
            obj.id,
            mass=obj.mass,
            friction=obj.friction,
            solref=profile.solref,
            visual=visual,
        )
        # The centre of mass comes from the collision parts unless the scene moved it (stability search, and the
        # visual mesh's own centre): then the body keeps the parts' inertia about the scene's centre of mass.
        if not any(obj.com):
            continue
        derived = derived_inertial(assets[obj.id], obj.mass)
        if np.linalg.norm(np.asarray(obj.com) - derived.ipos) > COM_TOLERANCE_M:
            body.explicitinertial = True
            body.mass = obj.mass
            body.ipos = list(obj.com)
            body.iquat = list(derived.iquat)
            body.inertia = list(derived.inertia)
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    return BuiltScene(model, data, spec, chosen, assets)


@dataclass(frozen=True)
class _Compiled:
    """What `build_posed` keeps of a build: the compiled model and the maps into it (not its simulation state)."""

    model: mujoco.MjModel
    spec: mujoco.MjSpec
    assets: dict[str, Asset]
    body: dict[str, int]
    qpos: dict[str, int]


def _unit_as_compiled(quaternion: Sequence[float]) -> np.ndarray:
    """The quaternion normalised to the last bit as MuJoCo's compiler does it: kept when its norm is within 1e-14
    of one, else divided by its norm (summed in order)."""
    q = [float(v) for v in quaternion]
    norm = math.sqrt(sum(v * v for v in q))
    return np.array(q if abs(norm - 1.0) < COMPILER_EPS else [v / norm for v in q])


def _structure(support: Support, objects: Sequence[PlacedObject]) -> tuple:
    """All that `build_scene` compiles into a model but the objects' poses."""
    bodies = tuple((o.id, o.asset, o.description, o.mass, o.friction, tuple(o.com)) for o in objects)
    return (support.kind, tuple(support.size), support.height, bodies)


@dataclass(frozen=True)
class Inertial:
    """A body's inertial frame and principal inertia as MuJoCo derives them from its collision parts."""

    ipos: np.ndarray
    iquat: np.ndarray
    inertia: np.ndarray


def derived_inertial(asset: Asset, mass: float) -> Inertial:
    """What MuJoCo's compiler derives for `asset` with `mass` spread over its collision parts by their volumes. The
    frame does not depend on the mass and the inertia grows with it, so one small compile per asset is kept and
    scaled (every scene draws its own masses); a mass that leaves some part at the parts' floor is compiled as is."""
    floored = min(part_masses(asset.collision, min(float(mass), PROBE_MASS_KG)), default=1.0) < MIN_PART_MASS_KG
    probe = float(mass) if floored else PROBE_MASS_KG
    key = (asset.id, asset.size, asset.mass, len(asset.collision), probe)
    if (known := _INERTIALS.get(key)) is None:
        spec = mujoco.MjSpec()
        body = spec.worldbody.add_body(name="probe")
        body.add_freejoint()
        add_asset_geoms(spec, body, asset, "probe", mass=probe, visual=False)
        model = spec.compile()
        known = Inertial(model.body_ipos[1].copy(), model.body_iquat[1].copy(), model.body_inertia[1].copy())
        _INERTIALS[key] = known
        if len(_INERTIALS) > KEPT_INERTIALS:
            _INERTIALS.popitem(last=False)
    else:
        _INERTIALS.move_to_end(key)
    return known if floored else Inertial(known.ipos, known.iquat, known.inertia * (float(mass) / PROBE_MASS_KG))


_INERTIALS: OrderedDict[tuple, Inertial] = OrderedDict()


def _add_lights_and_floor(spec: mujoco.MjSpec, scene: Scene) -> None:
    spec.add_texture(
        name="sky",
        type=mujoco.mjtTexture.mjTEXTURE_SKYBOX,
        builtin=mujoco.mjtBuiltin.mjBUILTIN_GRADIENT,
        width=256,
        height=256,
        rgb1=[0.92, 0.94, 0.97],
        rgb2=[0.72, 0.76, 0.82],
    )
    spec.add_texture(
        name="tiles",
        type=mujoco.mjtTexture.mjTEXTURE_2D,
        builtin=mujoco.mjtBuiltin.mjBUILTIN_CHECKER,
        width=64,
        height=64,
        rgb1=[0.80, 0.79, 0.76],
        rgb2=[0.74, 0.73, 0.70],
    )
    floor = spec.add_material(name="floor_tiles")
    floor.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = "tiles"
    floor.texrepeat = [12, 12]
    top = scene.support.top_height
    reach = max(scene.support.size) + top + 1.0
    # A tight scene extent keeps the shadow map sharp (no speckled "acne" on flat tops).
    spec.stat.extent = max(scene.support.size) + 0.5
    spec.stat.center = [0.0, 0.0, top]
    spec.visual.quality.shadowsize = 2048  # 4096 changes 0.7 % of a dining render's pixels and costs 0.1 s a picture
    spec.visual.map.shadowclip = 6.0  # shadows mapped this far around: a level view sees speckles beyond it
    for direction, diffuse in (([-0.3, 0.4, -1.0], 0.55), ([0.5, -0.3, -0.8], 0.3)):
        light = spec.worldbody.add_light(
            type=mujoco.mjtLightType.mjLIGHT_DIRECTIONAL, dir=direction, castshadow=diffuse > 0.5
        )
        light.diffuse = [diffuse] * 3
        light.specular = [0.1] * 3
        light.pos = [0.0, 0.0, top + reach]


class MujocoEngine:
    """The default engine: deterministic, CPU, headless rendering with EGL; `profile` says which contact settings
    it simulates with (ours by default, or MuJoCo's defaults)."""

    def __init__(self, catalogue: Catalogue | None = None, profile: ContactProfile = OURS) -> None:
        self.catalogue = catalogue or default_catalogue()
        self.profile = profile
        self._posed: OrderedDict[tuple, _Compiled] = OrderedDict()
        self._settled: OrderedDict[tuple, _Simulated] = OrderedDict()
        self._siblings: dict[ContactProfile, MujocoEngine] = {}

    def with_profile(self, profile: ContactProfile) -> MujocoEngine:
        """The same engine (same catalogue) under other contact settings (one per profile, kept)."""
        if profile == self.profile:
            return self
        if profile not in self._siblings:
            self._siblings[profile] = MujocoEngine(self.catalogue, profile)
        return self._siblings[profile]

    def defaults_check(self) -> MujocoEngine | None:
        """The same engine under MuJoCo's default contact settings, which a scene must rest under too; None when
        this engine already runs them."""
        return None if self.profile == MUJOCO_DEFAULT else self.with_profile(MUJOCO_DEFAULT)

    def build(
        self,
        scene: Scene,
        *,
        objects: Sequence[PlacedObject] | None = None,
        visual: bool = True,
        fixed: Sequence[PlacedObject] = (),
    ) -> BuiltScene:
        return build_scene(scene, self.catalogue, objects=objects, visual=visual, fixed=fixed, profile=self.profile)

    def build_posed(self, scene: Scene, objects: Sequence[PlacedObject] | None = None) -> BuiltScene:
        """`build(scene, objects=objects, visual=False)` for checks that simulate the same objects at other poses: the
        compiled model is kept per structure (the support and each object's asset, mass, friction and centre of
        mass) and the poses are written into it as compiling them would, to the last bit of the simulation (all but
        the statistics that frame a camera). The model is shared by later calls: step the data, never change the
        model, let go of it before the next call, and keep an engine to one thread."""
        chosen = list(scene.placed if objects is None else objects)
        key = _structure(scene.support, chosen)
        kept = self._posed.get(key)
        if kept is None:
            built = self.build(scene, objects=chosen, visual=False)
            self._posed[key] = _Compiled(built.model, built.spec, built.assets, built.body, built.qpos)
            if len(self._posed) > POSED_MODELS:
                self._posed.popitem(last=False)
            return built
        self._posed.move_to_end(key)
        model, spec = kept.model, kept.spec
        for obj in chosen:
            quat = _unit_as_compiled(obj.quaternion)
            body, address = kept.body[obj.id], kept.qpos[obj.id]
            model.body_pos[body] = obj.position
            model.body_quat[body] = quat
            for initial in (model.qpos0, model.qpos_spring):
                initial[address : address + 3] = obj.position
                initial[address + 3 : address + 7] = quat
            spec.body(obj.id).pos = list(obj.position)
            spec.body(obj.id).quat = list(obj.quaternion)
        data = mujoco.MjData(model)
        mujoco.mj_setConst(model, data)  # what the compiler derives at the initial pose (inverse weights)
        mujoco.mj_forward(model, data)
        return BuiltScene(model, data, spec, chosen, kept.assets)

    def settle(
        self,
        scene: Scene,
        *,
        duration_s: float = 1.5,
        tolerance: Tolerance = DEFAULT_TOLERANCE,
        objects: Sequence[PlacedObject] | None = None,
        rest: RestRule | None = AT_REST,
    ) -> SettleResult:
        """Let the objects (the scene's placed ones by default) fall for `duration_s`, or until they are at rest by
        `rest` (None: the whole time), and judge how far each moved. A settle from the same start that this engine
        simulated lately is not simulated again."""
        start = time.perf_counter()
        chosen = list(scene.placed if objects is None else objects)
        simulated = self._simulated(scene, chosen, int(round(duration_s / self.profile.timestep)), rest)
        return simulated.judged(tolerance, scene.support.top_height, time.perf_counter() - start)

    def settle_built(
        self,
        built: BuiltScene,
        support_top: float,
        *,
        duration_s: float = 1.5,
        tolerance: Tolerance = DEFAULT_TOLERANCE,
        stop_at_rest_s: float | None = None,
        rest: RestRule | None = None,
    ) -> SettleResult:
        """Settle an already built model from its current state; with `stop_at_rest_s`, stop once that much time
        has passed and nothing moves faster than REST_SPEED any more; with `rest`, once everything is at rest by
        it."""
        start = time.perf_counter()
        step = float(built.model.opt.timestep)
        rest_after = None if stop_at_rest_s is None else int(round(stop_at_rest_s / step))
        simulated = _simulate(built, int(round(duration_s / step)), rest=rest, rest_after=rest_after)
        return simulated.judged(tolerance, support_top, time.perf_counter() - start)

    def settle_distance(
        self, scene: Scene, duration_s: float = SETTLE_S, *, rest: RestRule | None = None
    ) -> SettleDistance:
        """The paper's settle distance: how far each placed object moves in `duration_s` of free fall; with `rest`,
        the free fall stops once everything is at rest by it (what is left of the time could add no more than its
        speeds allow)."""
        steps = max(1, int(round(duration_s / self.profile.timestep)))
        simulated = self._simulated(scene, list(scene.placed), steps, rest)
        if simulated.run.unstable:  # what the others did before it was stopped is no settle distance either
            return SettleDistance({oid: SETTLE_CLAMP_M for oid in simulated.ids}, diverged=simulated.run.message)
        moved = np.linalg.norm(simulated.final[:, :3] - simulated.initial[:, :3], axis=1)
        return SettleDistance({oid: min(SETTLE_CLAMP_M, float(m)) for oid, m in zip(simulated.ids, moved, strict=True)})

    def _simulated(self, scene: Scene, chosen: list[PlacedObject], steps: int, rest: RestRule | None) -> _Simulated:
        """The settle of `chosen` from their poses for `steps` (or until at rest by `rest`): kept, and taken from
        what was kept when the same start was settled as long, or ended early within `steps`."""
        start = tuple((*o.position, *o.quaternion) for o in chosen)
        key = (_structure(scene.support, chosen), start, rest)
        kept = self._settled.get(key)
        if kept is not None and kept.answers(steps):
            self._settled.move_to_end(key)
            return kept
        simulated = _simulate(self.build_posed(scene, chosen), steps, rest=rest)
        self._settled[key] = simulated
        if len(self._settled) > KEPT_SETTLES:
            self._settled.popitem(last=False)
        return simulated

    def render(
        self, scene: Scene, *, view: str | Camera = DEFAULT_VIEW, size: tuple[int, int] | None = None
    ) -> np.ndarray:
        """An RGB picture of the scene, (height, width, 3) uint8, of `size` (width, height) or as suits the scene."""
        return render_built(self.build(scene), scene, view=view, size=size)


@dataclass
class _Run:
    """How a simulation went: steps done, the objects it went wrong around, why it was stopped (None: it was not)
    and whether it stopped because everything was at rest."""

    steps: int
    bad: np.ndarray
    reason: str | None = None
    timestep: float = TIMESTEP
    at_rest: bool = False

    @property
    def unstable(self) -> bool:
        return self.reason is not None

    @property
    def message(self) -> str:
        return f"the simulation diverged within {self.steps * self.timestep:.2f} s ({self.reason})"


@dataclass
class _Simulated:
    """One settle simulated from a start state: all that judging it under any tolerance needs."""

    ids: list[str]
    spins: list[np.ndarray | None]
    initial: np.ndarray
    initial_depth: np.ndarray
    initial_partners: list[dict[int, float]]
    final: np.ndarray
    depth: np.ndarray
    run: _Run
    asked: int  # steps asked for

    def answers(self, steps: int) -> bool:
        """Whether a settle of `steps` from the same start ends where this one did: as long, or this one ended
        early (at rest, or blown up) within them (the checks fall on the same steps up to there)."""
        return steps == self.asked or self.run.steps < self.asked and self.run.steps <= steps

    def judged(self, tolerance: Tolerance, support_top: float, wall_s: float) -> SettleResult:
        motions = {}
        for k, oid in enumerate(self.ids):
            motions[oid] = _motion(
                oid,
                self.initial[k],
                self.final[k],
                self.spins[k],
                self.run.reason if self.run.bad[k] else None,
                float(self.depth[k]),
                float(self.initial_depth[k]),
                self.initial_partners[k],
                self.ids,
                tolerance,
                support_top,
            )
        messages = [self.run.message] if self.run.reason else []
        return SettleResult(motions, self.run.steps * self.run.timestep, wall_s, self.run.unstable, messages)


def _simulate(
    built: BuiltScene, steps: int, *, rest: RestRule | None = None, rest_after: int | None = None
) -> _Simulated:
    """Settle a built model from its current state and note where everything started and ended."""
    mujoco.mj_forward(built.model, built.data)
    initial = built.poses()
    initial_depth, initial_partners = built.penetrations()
    run = _run(built, steps, rest=rest, rest_after=rest_after)
    final = built.poses()
    mujoco.mj_forward(built.model, built.data)
    depth, _ = built.penetrations()
    ids = [o.id for o in built.objects]
    spins = [spin_axis(built.assets[oid].size) for oid in ids]
    return _Simulated(ids, spins, initial, initial_depth, initial_partners, final, depth, run, steps)


_Check = tuple[float, np.ndarray, np.ndarray, np.ndarray]  # time, poses (n, 7), speeds, spins


@dataclass
class _RestWatch:
    """Tells when every free body has been at rest by `rule` for a whole window (see `RestRule`)."""

    rule: RestRule
    checks: deque[_Check] = field(default_factory=deque)  # the checks of the current window, oldest first

    def at_rest(self, t: float, poses: np.ndarray, speeds: np.ndarray, spins: np.ndarray) -> bool:
        rule = self.rule
        if (speeds >= rule.jitter_m_s).any() or (spins >= rule.jitter_rad_s).any():
            self.checks.clear()
            return False
        self.checks.append((t, poses, speeds, spins))
        while t - self.checks[0][0] > rule.window_s + 1e-9:
            self.checks.popleft()
        if t - self.checks[0][0] < rule.window_s - 1e-9:
            return False
        return self._still() and not self._speeding_up()

    def _still(self) -> bool:
        """No body went further from where the window began than the rule allows over the window."""
        t0, start = self.checks[0][0], self.checks[0][1]
        elapsed = self.checks[-1][0] - t0
        for _, poses, _, _ in self.checks:
            moved = np.linalg.norm(poses[:, :3] - start[:, :3], axis=1)
            dot = np.abs(np.sum(poses[:, 3:] * start[:, 3:], axis=1)) / np.linalg.norm(poses[:, 3:], axis=1)
            turned = 2.0 * np.arccos(np.clip(dot, 0.0, 1.0))
            if (moved > self.rule.speed_m_s * elapsed).any() or (turned > self.rule.spin_rad_s * elapsed).any():
                return False
        return True

    def _speeding_up(self) -> bool:
        """Some body is faster in the window's later half than twice its fastest in the earlier half (tipping over,
        from nearly still); an oscillation in place is as fast in both."""
        middle = (self.checks[0][0] + self.checks[-1][0]) / 2
        early = [c for c in self.checks if c[0] <= middle]
        late = [c for c in self.checks if c[0] > middle]
        rule = self.rule

        def faster(before: list[np.ndarray], after: list[np.ndarray], floor: float) -> bool:
            return bool((np.max(after, axis=0) > 2.0 * np.max(before, axis=0) + floor).any())

        return faster([c[2] for c in early], [c[2] for c in late], rule.speed_floor_m_s) or faster(
            [c[3] for c in early], [c[3] for c in late], rule.spin_floor_rad_s
        )


def _run(
    built: BuiltScene,
    steps: int,
    *,
    rest_after: int | None = None,
    rest_speed: float = REST_SPEED,
    rest: RestRule | None = None,
) -> _Run:
    """Step the model; stop early if it blows up (NaN, runaway speeds, or a state MuJoCo had to reset), (with
    `rest_after` steps done) once everything is slower than `rest_speed`, or once everything is at rest by `rest`.
    On a blow-up the state before it is restored."""
    model, data = built.model, built.data
    timestep = float(model.opt.timestep)
    every = CHECK_EVERY if rest is None else max(1, min(CHECK_EVERY, int(round(rest.check_s / timestep))))
    watch = None if rest is None else _RestWatch(rest)
    dofs = np.array(list(built.dof.values()), dtype=int).reshape(-1, 1)
    qpos = np.array(list(built.qpos.values()), dtype=int).reshape(-1, 1)
    bad = np.zeros(len(built.objects), dtype=bool)
    last_good = data.qpos.copy()
    for warning in UNSTABLE_WARNINGS:
        data.warning[warning].number = 0
    done = 0
    while done < steps:
        chunk = min(every, steps - done)
        mujoco.mj_step(model, data, nstep=chunk)
        done += chunk
        velocity = data.qvel[dofs + np.arange(6)]
        speeds = np.abs(velocity).max(axis=1)
        poses = data.qpos[qpos + np.arange(7)]
        bad = ~np.isfinite(poses).all(axis=1) | (speeds > MAX_SPEED) | ~np.isfinite(speeds)
        reason = _mujoco_reset(built, bad) or _runaway(built, bad, speeds)
        if reason:
            data.qpos[:] = last_good  # nothing with NaN is ever reported
            data.qvel[:] = 0.0
            mujoco.mj_forward(model, data)
            return _Run(done, bad, reason, timestep)
        last_good[:] = data.qpos
        if rest_after is not None and done >= rest_after and (speeds < rest_speed).all():
            break
        if watch is not None and done < steps:
            linear = np.linalg.norm(velocity[:, :3], axis=1)
            angular = np.linalg.norm(velocity[:, 3:], axis=1)
            if watch.at_rest(done * timestep, poses, linear, angular):
                return _Run(done, bad, timestep=timestep, at_rest=True)
    return _Run(done, bad, timestep=timestep)


def _mujoco_reset(built: BuiltScene, bad: np.ndarray) -> str | None:
    """Why MuJoCo reset the state during the last steps (NaN or huge accelerations, positions, velocities), marking
    the object it names in `bad` (every object when it names none); None if it did not."""
    for warning in UNSTABLE_WARNINGS:
        stat = built.data.warning[warning]
        if stat.number == 0:
            continue
        text = mujoco.mju_warningText(warning, stat.lastinfo).removesuffix(" The simulation is unstable.").rstrip(".")
        culprit = _object_of_dof(built, int(stat.lastinfo))
        if culprit is None:
            bad[:] = True
            return f"MuJoCo: {text}"
        bad[list(built.body).index(culprit)] = True
        return f"MuJoCo: {text}, which belongs to {culprit}"
    return None


def _object_of_dof(built: BuiltScene, dof: int) -> str | None:
    if not 0 <= dof < built.model.nv:
        return None
    body = int(built.model.dof_bodyid[dof])
    return next((oid for oid, bid in built.body.items() if bid == body), None)


def _runaway(built: BuiltScene, bad: np.ndarray, speeds: np.ndarray) -> str | None:
    if not bad.any():
        return None
    k = int(np.argmax(bad))
    oid = built.objects[k].id
    if not np.isfinite(speeds[k]) or not np.isfinite(built.data.qpos[built.qpos[oid] : built.qpos[oid] + 7]).all():
        return f"the state of {oid} became NaN"
    return f"{oid} reached {speeds[k]:.3g} m/s"


def _motion(
    oid: str,
    start: np.ndarray,
    end: np.ndarray,
    spin: np.ndarray | None,
    blew_up: str | None,
    depth: float,
    initial_depth: float,
    partners: dict[int, float],
    ids: list[str],
    tolerance: Tolerance,
    support_top: float,
) -> ObjectMotion:
    translation = float(np.linalg.norm(end[:3] - start[:3]))
    sideways = float(np.linalg.norm(end[:2] - start[:2]))
    drop = float(start[2] - end[2])
    quat = end[3:] / np.linalg.norm(end[3:])
    rotation = quaternion_angle(start[3:], quat)
    turned = turn_angle(start[3:], quat, spin)  # what the check judges
    # Off the support: below its top (on the floor), or down and away from a stack.
    fell = end[2] < support_top - FELL_BELOW_M or (drop > FELL_BELOW_M and sideways > FELL_BELOW_M)
    reason = None
    if blew_up:
        reason = f"the simulation blew up around it ({blew_up}; it was probably placed deep inside another object)"
    elif fell:
        reason = f"fell off its support (ended {drop:.2f} m lower and {sideways:.2f} m to the side)"
    elif drop > tolerance.translation_m and sideways < tolerance.translation_m:
        reason = f"dropped {drop * 100:.1f} cm while settling: it was floating above what should carry it"
    elif translation > tolerance.translation_m or turned > tolerance.rotation_rad:
        reason = (
            f"moved {translation * 100:.1f} cm and turned {math.degrees(rotation):.0f} deg while settling: "
            "it was not resting where it was put"
        )
    if reason and initial_depth > REPORT_PENETRATION_M:
        worst = max(partners, key=lambda k: partners[k])
        who = "the support" if worst < 0 else ids[worst]
        reason += f"; it started {initial_depth * 100:.1f} cm inside {who}"
    return ObjectMotion(
        id=oid,
        translation_m=translation,
        rotation_rad=rotation,
        left_support=fell,
        penetration_m=depth,
        initial_penetration_m=initial_depth,
        position=tuple(float(v) for v in end[:3]),  # type: ignore[arg-type]
        quaternion=tuple(float(v) for v in quat),  # type: ignore[arg-type]
        ok=reason is None,
        reason=reason,
    )
