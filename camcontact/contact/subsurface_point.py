"""Stresses below the centre of a frictionless elliptical Hertz contact: the largest shear and its depth.

Below the centre of the ellipse the shear stresses vanish by symmetry, so sigma_x, sigma_y, sigma_z are the
principal stresses; the largest principal shear (sigma_1 - sigma_3)/2 of a frictionless Hertz contact lies
on this axis (Johnson 1985 §3.4–3.5; Harris & Kotzalas 2007 §6.5, Fig. 6.9). They are found here by
integrating Boussinesq's point-force stresses (Johnson 1985 Eq. 3.19) over the Hertz pressure
p = p_h sqrt(1 - (x/a_x)^2 - (y/a_y)^2) in polar coordinates round the axis (Gauss–Legendre panels: in the
angle graded towards the major axis, in the radius on the depth's scale near the axis and in r = R sin(phi)
towards the boundary R, where the pressure's square-root edge becomes smooth). Checked against the circle's closed form (Johnson Eq. 3.45:
0.31 p_h at 0.48 a for nu = 0.3) and the line contact's limit (0.300 p_h at 0.786 b) in the tests.

Lengths [m], stresses [Pa] (compression negative), nu [-].

References
----------
Johnson, K.L. (1985) Contact Mechanics, Cambridge University Press, Eqs. 3.19 and 3.45, §3.5.
Harris, T.A. & Kotzalas, M.N. (2007) Rolling Bearing Analysis, 5th ed., §6.5.
"""

from __future__ import annotations

import math

import attrs
import numpy as np
from scipy.optimize import minimize_scalar

from ..errors import InputError

__all__ = ["PointSubsurface", "point_axis_stresses", "point_subsurface"]

#: Gauss-Legendre nodes per panel (radial and angular)
N_GAUSS = 32


@attrs.frozen
class PointSubsurface:
    """Extremes of the stresses on the axis below the centre of an elliptical Hertz contact (SI)."""

    tresca_max: float  #: largest principal shear (sigma_1 - sigma_3)/2 [Pa]
    z_tresca_max: float  #: its depth [m]
    von_mises_max: float  #: largest von Mises stress [Pa]
    z_von_mises_max: float  #: its depth [m]


def _gauss(low: float, high: float, n: int = N_GAUSS):
    g, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (high - low) * g + 0.5 * (high + low), 0.5 * (high - low) * w


def _angles(a_x: float, a_y: float):
    """Angular nodes and weights over the quadrant [0, pi/2], panels graded round the angle where the
    boundary radius R(t) falls (atan(a_y/a_x)): a long ellipse's far reach is a narrow range of angles."""
    corner = math.atan2(a_y, a_x)
    cuts = sorted({0.0, math.pi / 2, *(min(max(math.atan(math.tan(corner) * c), 0.0), math.pi / 2)
                                       for c in (1 / 16, 1 / 4, 1.0, 4.0, 16.0))})
    parts = [_gauss(lo, hi) for lo, hi in zip(cuts[:-1], cuts[1:]) if hi > lo]
    return np.concatenate([t for t, _ in parts]), np.concatenate([w for _, w in parts])


def _nodes(a_x: float, a_y: float, depth: float):
    """Surface nodes (x^2, y^2) in polar coordinates round the axis and their weights (p/p_h dA) [m^2].

    Per angle t the radius runs to the boundary R(t) in two panels split at r1 = min(8 z, R/2):
    Gauss-Legendre in r below it (the kernel's scale is the depth z), r = R sin(phi) beyond it (the
    pressure's square-root edge becomes smooth)."""
    t, w_t = _angles(a_x, a_y)
    R = 1.0 / np.sqrt((np.cos(t) / a_x) ** 2 + (np.sin(t) / a_y) ** 2)
    split = np.minimum(8.0 * depth, 0.5 * R)
    g, w = np.polynomial.legendre.leggauss(N_GAUSS)
    r1 = 0.5 * split[:, None] * (g + 1.0)
    w1 = 0.5 * split[:, None] * w * np.sqrt(1.0 - (r1 / R[:, None]) ** 2) * r1
    low = np.arcsin(split / R)[:, None]
    phi = low + 0.5 * (0.5 * math.pi - low) * (g + 1.0)
    r2 = R[:, None] * np.sin(phi)
    w2 = 0.5 * (0.5 * math.pi - low) * w * R[:, None] * np.cos(phi) ** 2 * r2
    r = np.concatenate([r1, r2], axis=1)
    weight = 4.0 * w_t[:, None] * np.concatenate([w1, w2], axis=1)  # four quadrants: the kernel is even in x, y
    return ((r * np.cos(t)[:, None]) ** 2).ravel(), ((r * np.sin(t)[:, None]) ** 2).ravel(), weight.ravel()


def point_axis_stresses(z, a_x: float, a_y: float, p_h: float, nu: float = 0.3) -> tuple[np.ndarray, np.ndarray,
                                                                                          np.ndarray]:
    """(sigma_x, sigma_y, sigma_z) [Pa] at depths ``z`` [m] (> 0) below the centre of an elliptical Hertz
    contact of semi-axes a_x, a_y [m] and peak pressure p_h [Pa]; Poisson's ratio nu [-]. Boussinesq's
    point-force stresses (Johnson 1985 Eq. 3.19) integrated over the pressure."""
    z = np.atleast_1d(np.asarray(z, dtype=float))
    if not (np.all(np.isfinite(z)) and np.all(z > 0.0)):
        raise InputError(f"point_axis_stresses: z = {z!r} m; allowed: depths > 0")
    for name, value in (("a_x", a_x), ("a_y", a_y)):
        if not (math.isfinite(value) and value > 0.0):
            raise InputError(f"point_axis_stresses: {name} = {value!r} m; allowed: > 0")
    if not -1.0 < nu < 0.5:
        raise InputError(f"point_axis_stresses: nu = {nu!r}; allowed: -1 < nu < 0.5")
    out = np.empty((3, z.size))
    for k, depth in enumerate(z):
        x2, y2, weight = _nodes(a_x, a_y, depth)
        r2 = x2 + y2
        rho = np.sqrt(r2 + depth * depth)
        one_minus = r2 / (rho * (rho + depth))  # 1 - z/rho without cancellation
        inv_r2 = 1.0 / r2
        c = (1.0 - 2.0 * nu) * inv_r2
        sx = c * (one_minus * (x2 - y2) * inv_r2 + depth * y2 / rho**3) - 3.0 * depth * x2 / rho**5
        sy = c * (one_minus * (y2 - x2) * inv_r2 + depth * x2 / rho**3) - 3.0 * depth * y2 / rho**5
        sz = -3.0 * depth**3 / rho**5
        out[:, k] = p_h / (2.0 * math.pi) * np.array([weight @ sx, weight @ sy, weight @ sz])
    return out[0], out[1], out[2]


def _tresca(sx, sy, sz):
    return 0.5 * np.max(np.abs(np.array([sx - sy, sy - sz, sz - sx])), axis=0)


def _von_mises(sx, sy, sz):
    return np.sqrt(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2))


def point_subsurface(a_x: float, a_y: float, p_h: float, nu: float = 0.3) -> PointSubsurface:
    """The largest principal shear and von Mises stress below an elliptical Hertz contact and their depths:
    each a bounded search over 0.02 to 3 times the minor semi-axis (to 1e-6 of it) on
    :func:`point_axis_stresses`. Semi-axes [m], p_h [Pa], nu [-]."""
    minor = min(a_x, a_y)
    found = []
    for measure in (_tresca, _von_mises):
        best = minimize_scalar(lambda zeta: -measure(*point_axis_stresses(zeta * minor, a_x, a_y, p_h, nu))[0],
                               bounds=(0.02, 3.0), method="bounded", options={"xatol": 1e-6})
        found += [-float(best.fun), float(best.x) * minor]
    return PointSubsurface(*found)
