"""ISO/TS 16281:2008 basic reference rating life L_10r of a radial roller bearing from its lamina loads.

With the lamina loads q_jk (roller j, lamina k; :mod:`camcontact.contact.lamina_load_distribution`),
Z rollers in i rows, n_s laminae, gamma = D_we cos(alpha) / D_pw and lambda nu = 0.83:

* the roller loads the rings carry for 10^6 revolutions (Eqs. 47-48)
  Q_ci = C_r / (lambda nu 0.378 Z cos(alpha) i^(7/9)) [1 + (1.038 ((1 - gamma)/(1 + gamma))^(143/108))^(9/2)]^(2/9),
  Q_ce = C_r / (lambda nu 0.364 Z cos(alpha) i^(7/9)) [1 + (1.038 ((1 - gamma)/(1 + gamma))^(143/108))^(-9/2)]^(2/9),
  and per lamina q_c = Q_c n_s^(-7/9) (Eqs. 56-57);
* the equivalent lamina loads of the ring turning against the load, q_ke = f_k ((1/Z) sum_j q_jk^4)^(1/4),
  and of the standing ring, f_k ((1/Z) sum_j q_jk^(9/2))^(2/9) (Eqs. 61-64), with the edge-stress factor of
  the approximate profile f_k = 1 - 0.01 / ln(1.985 |2k - n_s - 1| / (2 n_s - 2)) (Eq. 60; ``edge_factor``);
* L_10r = (sum_k [(q_kei / q_ci)^(9/2) + (q_kee / q_ce)^(9/2)])^(-8/9) [10^6 revolutions] (Eq. 65).

For a straight aligned roller with f = 1 every lamina of a roller carries Q_j/n_s and L_10r is the roller-level
Lundberg-Palmgren combination [(Q_ei/Q_ci)^(9/2) + (Q_ee/Q_ce)^(9/2)]^(-8/9) whatever n_s (tested). The
exponents are the roller's (4 for the turning ring), not ISO 281's 10/3 of the bearing, and the ratings carry
no lambda nu reduction: L_10r exceeds ISO 281's L10 for light loads and falls below it as edge loading or
misalignment concentrate the lamina loads.

Sources: ISO/TS 16281:2008 Eqs. 47-65, as transcribed by independent public implementations quoting the
standard (its text was not at hand); Eq. 60 holds, the standard says, for the approximate profile of
Eqs. 42-44 under medium load and a misalignment below 4'.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError

__all__ = ["LAMBDA_NU", "edge_factor", "roller_reference_rating_life"]

LAMBDA_NU = 0.83


def edge_factor(laminae: int) -> np.ndarray:
    """f_k of ISO/TS 16281 Eq. 60 for the n_s laminae: just above 1 in the middle, rising towards the ends (2.33 at
    the end laminae for n_s = 30), the edge stress of the reference profile on the equivalent lamina loads."""
    k = np.arange(1, laminae + 1)
    distance = np.abs(2 * k - laminae - 1) / (2.0 * laminae - 2.0)
    with np.errstate(divide="ignore"):
        factor = 1.0 - 0.01 / np.log(1.985 * distance)
    return np.where(distance > 0.0, factor, 1.0)


def roller_reference_rating_life(q, *, C: float, roller_diameter: float, pitch_diameter: float,
                                 contact_angle: float = 0.0, rows: int = 1, inner_rotates: bool = True,
                                 with_edge_factor: bool = True) -> dict[str, float]:
    """L_10r [10^6 revolutions] of a radial roller bearing from its lamina loads ``q`` [N] (Z, n_s), C_r [N], D_we
    and D_pw [m], the contact angle [rad] and rows (module docstring); also Q_ci, Q_ce, q_ci, q_ce [N]."""
    q = np.asarray(q, dtype=float)
    if q.ndim != 2 or q.shape[0] < 3 or q.shape[1] < 2 or np.any(~np.isfinite(q)) or np.any(q < 0.0):
        raise InputError(f"ISO/TS 16281 L_10r: the lamina loads must be a finite, non-negative (rollers, laminae) array "
                         f"(got shape {q.shape})")
    if not (C > 0.0 and 0.0 <= contact_angle < 0.5 * math.pi):
        raise InputError(f"ISO/TS 16281 L_10r: C = {C!r} N (> 0), contact_angle = {contact_angle!r} rad (0..pi/2)")
    Z, n = q.shape
    gamma = roller_diameter * math.cos(contact_angle) / pitch_diameter
    ratio = 1.038 * ((1.0 - gamma) / (1.0 + gamma)) ** (143.0 / 108.0)
    scale = C / (LAMBDA_NU * Z * math.cos(contact_angle) * rows ** (7.0 / 9.0))
    Q_ci = scale / 0.378 * (1.0 + ratio**4.5) ** (2.0 / 9.0)
    Q_ce = scale / 0.364 * (1.0 + ratio**-4.5) ** (2.0 / 9.0)
    q_ci, q_ce = Q_ci * n ** (-7.0 / 9.0), Q_ce * n ** (-7.0 / 9.0)
    f = edge_factor(n) if with_edge_factor else np.ones(n)
    turning = f * np.mean(q**4, axis=0) ** 0.25
    standing = f * np.mean(q**4.5, axis=0) ** (2.0 / 9.0)
    q_ei, q_ee = (turning, standing) if inner_rotates else (standing, turning)
    total = float(np.sum((q_ei / q_ci) ** 4.5 + (q_ee / q_ce) ** 4.5))
    L10r = math.inf if total == 0.0 else total ** (-8.0 / 9.0)
    return {"L10r": L10r, "Q_ci": Q_ci, "Q_ce": Q_ce, "q_ci": q_ci, "q_ce": q_ce}
