"""1-DOF valve train under prescribed follower motion: contact force, torque, jump and k_min.

Tsuha (2015) §3.5 and §6.1: with the follower kept on the cam, the force the cam must
supply along the follower axis is

.. math:: F = m \\ddot S + c \\dot S + k f + F_{pl}, \\qquad T_c = F \\dot S / \\omega

(Eqs. 3.46 and 3.47, with the preload of its Chapter 6 and the spring deflection measured as
the lift f). F < 0 means the spring cannot hold the follower on the cam: the follower jumps.
The smallest spring stiffness that keeps F >= 0 over a cycle with c = 2 ζ sqrt(k m) is
:func:`minimum_stiffness`.
"""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..errors import InputError

__all__ = ["ForceBreakdown", "contact_force", "minimum_stiffness"]


@attrs.frozen
class ForceBreakdown:
    """Axial cam force and its parts (arrays over cam angle) [N], and the cam torque [N m]."""

    inertia: np.ndarray
    damping: np.ndarray
    spring: np.ndarray
    preload: np.ndarray
    total: np.ndarray
    torque: np.ndarray

    @property
    def jumps(self) -> np.ndarray:
        """Boolean mask of the angles where F < 0 (loss of contact)."""
        return self.total < 0.0


def contact_force(lift, velocity, acceleration, omega, *, mass: float, stiffness: float, damping: float,
                  preload: float) -> ForceBreakdown:
    """Prescribed-motion force F = m S̈ + c Ṡ + k f + F_pl [N] and torque T = F Ṡ/ω [N m].

    ``lift`` f [m], ``velocity`` Ṡ [m/s], ``acceleration`` S̈ [m/s²], ``omega`` [rad/s];
    m [kg], k [N/m], c [N s/m], F_pl [N].
    """
    lift, velocity, acceleration, omega = (np.asarray(v, dtype=float) for v in (lift, velocity, acceleration, omega))
    inertia = mass * acceleration
    damping_force = damping * velocity
    spring = stiffness * lift
    preload_force = np.full_like(lift, preload)
    total = inertia + damping_force + spring + preload_force
    return ForceBreakdown(inertia, damping_force, spring, preload_force, total, total * velocity / omega)


def minimum_stiffness(lift, lift_rate, lift_acceleration, omega: float, *, mass: float, damping_ratio: float,
                      preload: float) -> float:
    """Smallest k [N/m] with m S̈ + 2 ζ sqrt(k m) Ṡ + k f + F_pl >= 0 at every angle (Tsuha 2015 §6.1).

    Parameters
    ----------
    lift, lift_rate, lift_acceleration : array
        f [m], f' [m/rad], f'' [m/rad²] over the angles of a cycle.
    omega : float
        Cam speed [rad/s] (constant).
    mass : float
        m [kg]; ``damping_ratio`` ζ [-]; ``preload`` F_pl [N].

    Notes
    -----
    With s = sqrt(k) the condition per angle is the quadratic f s² + 2 ζ sqrt(m) Ṡ s + (m S̈ + F_pl) >= 0.
    Where f > 0 it holds for s at or above the larger root; where f = 0 (dwell, base circle) it
    does not depend on k and must hold by itself (else no stiffness helps: InputError).
    """
    f = np.asarray(lift, dtype=float)
    v = np.asarray(lift_rate, dtype=float) * omega
    a = np.asarray(lift_acceleration, dtype=float) * omega**2
    c0 = mass * a + preload
    c1 = 2.0 * damping_ratio * math.sqrt(mass) * v
    required = 0.0
    on_base = f <= 1e-15
    damped_only = on_base & (c0 + 0.0 < 0.0) & (c1 <= 0.0)
    if np.any(damped_only):
        angle = int(np.flatnonzero(damped_only)[0])
        raise InputError(
            f"no spring stiffness keeps contact at sample {angle}: the lift is zero there and "
            f"m S̈ + F_pl = {c0[angle]:.4g} N < 0; raise the preload"
        )
    # on the base circle with velocity: c1 s + c0 >= 0 -> s >= -c0/c1 for c1 > 0
    linear = on_base & (c0 < 0.0) & (c1 > 0.0)
    if np.any(linear):
        required = max(required, float(np.max((-c0[linear] / c1[linear]) ** 2)))
    lifted = ~on_base
    disc = c1[lifted] ** 2 - 4.0 * f[lifted] * c0[lifted]
    roots = np.where(disc > 0.0, (-c1[lifted] + np.sqrt(np.clip(disc, 0.0, None))) / (2.0 * f[lifted]), 0.0)
    if roots.size:
        required = max(required, float(np.max(np.clip(roots, 0.0, None)) ** 2))
    return required
