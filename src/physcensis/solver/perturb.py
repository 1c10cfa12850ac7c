"""The perturbation model of the stability measure: what is perturbed, by how much, and the kernel estimate.

A perturbation of one object is x = [Δp (3), Δr (3), Δc (3), Δμ, Δm]: a position
shift (m), a small rotation as an axis-angle vector (rad, world frame, about the
object's origin), a centre-of-mass shift (m, object frame), a change of friction
coefficient and a relative change of mass. x ~ N(0, Σ) with Σ diagonal; the
standard deviations come from `PerturbationScales` and the asset's ranges.
p_fail(x) is the failure rate of labelled samples weighted by the Mahalanobis
kernel exp(-½ (x_j - x)ᵀ Σ⁻¹ (x_j - x)).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.spatial.transform import Rotation

from physcensis.assets.model import Asset

POSITION, ROTATION, COM, FRICTION, MASS = slice(0, 3), slice(3, 6), slice(6, 9), 9, 10
MIN_FRICTION = 0.05
MIN_MASS_FRACTION = 0.2


@dataclass(frozen=True)
class PerturbationScales:
    """Standard deviations of the perturbation, per dimension group."""

    position_m: float = 0.005  # horizontal
    height_m: float = 0.005  # vertical: a positive Δz releases the object that high above its support
    rotation_rad: float = math.radians(3.0)
    com_fraction: float = 0.25  # of the asset's centre-of-mass shift range, per axis
    friction: float = 0.1
    mass_fraction: float = 0.1  # of the object's mass

    def sigma(self, asset: Asset) -> np.ndarray:
        """The 11 standard deviations for one asset (a zero means that dimension is not perturbed)."""
        return np.array(
            [
                self.position_m,
                self.position_m,
                self.height_m,
                *[self.rotation_rad] * 3,
                *(self.com_fraction * np.asarray(asset.com_shift_range, dtype=float)),
                self.friction,
                self.mass_fraction,
            ]
        )


def sample(rng: np.random.Generator, sigma: np.ndarray, n: int) -> np.ndarray:
    """n perturbations x ~ N(0, diag(sigma²)), (n, 11)."""
    return rng.standard_normal((n, len(sigma))) * sigma


def _standardised(x: np.ndarray, sigma: np.ndarray) -> np.ndarray:
    used = sigma > 0
    return np.asarray(x)[..., used] / sigma[used]


def kernel_weights(samples: np.ndarray, query: np.ndarray, sigma: np.ndarray) -> np.ndarray:
    """w_j = exp(-½ d_M(query, x_j)²) for every sample, (n,)."""
    d = _standardised(samples, sigma) - _standardised(query, sigma)
    return np.exp(-0.5 * np.einsum("ij,ij->i", d, d))


def p_fail(samples: np.ndarray, fell: np.ndarray, query: np.ndarray, sigma: np.ndarray) -> float:
    """Kernel-weighted failure rate of the labelled samples around `query`."""
    w = kernel_weights(samples, query, sigma)
    return float(w @ fell / w.sum())


def com_projection(position: np.ndarray, quat: np.ndarray, com: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Where each perturbed copy's centre of mass lies over the ground plane at its start, (n, 2): the quantity
    that decides most of whether a resting object tips."""
    w, qx, qy, qz = quat
    turn = Rotation.from_rotvec(x[:, ROTATION]) * Rotation.from_quat([qx, qy, qz, w])
    world = turn.apply(np.asarray(com, dtype=float) + x[:, COM]) + np.asarray(position, dtype=float) + x[:, POSITION]
    return world[:, :2]


def rate_near(points: np.ndarray, at: np.ndarray, fell: np.ndarray, bandwidth: float) -> np.ndarray:
    """Gaussian-kernel failure rate of labelled `points` (n, k) around each query point of `at` (m, k), (m,)."""
    d2 = np.sum((at[:, None, :] - points[None, :, :]) ** 2, axis=2)
    w = np.exp(-0.5 * d2 / bandwidth**2)
    return w @ fell / np.maximum(w.sum(axis=1), 1e-300)


def effective_samples(samples: np.ndarray, query: np.ndarray, sigma: np.ndarray) -> float:
    """Kish's effective sample size of the kernel weights at `query`: how many samples the estimate rests on."""
    w = kernel_weights(samples, query, sigma)
    return float(w.sum() ** 2 / (w @ w))


def rigid_motion(
    pivot: np.ndarray, shift: np.ndarray, rotvec: np.ndarray, positions: np.ndarray, quats: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Move bodies rigidly with a perturbed object: rotate them by each row of `rotvec` about `pivot`, then
    shift by `shift`. positions (m, 3) and quats [w, x, y, z] (m, 4) -> (n, m, 3) and (n, m, 4)."""
    turn = Rotation.from_rotvec(rotvec)
    n, m = len(rotvec), len(positions)
    offsets = np.asarray(positions) - pivot
    moved = np.stack([turn.apply(offsets[k]) for k in range(m)], axis=1) + pivot + shift[:, None, :]
    xyzw = np.roll(np.asarray(quats, dtype=float), -1, axis=1)
    new = np.stack([(turn * Rotation.from_quat(xyzw[k])).as_quat() for k in range(m)], axis=1)
    new = np.roll(new.reshape(n, m, 4), 1, axis=2)
    return moved, new * np.sign(new[..., :1] + 1e-12)


def perturbed_params(
    mass: float, com: np.ndarray, friction: float, x: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Mass (n,), centre of mass (n, 3) and friction (n,) of the perturbed copies, kept physical. (MuJoCo uses
    the larger coefficient of two touching geoms, so friction lowered below its partner's changes nothing.)"""
    masses = mass * np.maximum(1.0 + x[:, MASS], MIN_MASS_FRACTION)
    frictions = np.maximum(friction + x[:, FRICTION], MIN_FRICTION)
    return masses, np.asarray(com, dtype=float) + x[:, COM], frictions


def feasible_com(asset: Asset, com: np.ndarray) -> np.ndarray:
    """A centre of mass clipped to the asset's feasible range around its nominal one."""
    centre, reach = np.asarray(asset.com, dtype=float), np.asarray(asset.com_shift_range, dtype=float)
    return np.clip(com, centre - reach, centre + reach)
