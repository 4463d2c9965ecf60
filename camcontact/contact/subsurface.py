"""Subsurface stresses under a Hertz line contact, with sliding friction (plane strain).

Closed-form field of McEwen (1949) in the m, n form of Johnson (1985, §2.8 and §7.1):
half-width b, peak pressure p_h, surface traction q = mu p acting in +x on the body,
z measured into the body, compression negative. With

.. math::
    m^2 = \\tfrac12\\left[\\sqrt{(b^2 - x^2 + z^2)^2 + 4x^2z^2} + (b^2 - x^2 + z^2)\\right], \\quad
    n^2 = \\tfrac12\\left[\\sqrt{(b^2 - x^2 + z^2)^2 + 4x^2z^2} - (b^2 - x^2 + z^2)\\right]

(sign m = sign z, sign n = sign x) the normal-pressure part is

.. math::
    \\sigma_x = -\\frac{p_h}{b}\\left[m\\left(1 + \\frac{z^2 + n^2}{m^2 + n^2}\\right) - 2z\\right], \\quad
    \\sigma_z = -\\frac{p_h}{b}\\, m \\left(1 - \\frac{z^2 + n^2}{m^2 + n^2}\\right), \\quad
    \\tau_{xz} = -\\frac{p_h}{b}\\, n\\, \\frac{m^2 - z^2}{m^2 + n^2}

and the traction part

.. math::
    \\sigma_x = \\frac{\\mu p_h}{b}\\left[n\\left(2 - \\frac{z^2 - m^2}{m^2 + n^2}\\right) - 2x\\right], \\quad
    \\sigma_z = -\\frac{\\mu p_h}{b}\\, n\\, \\frac{m^2 - z^2}{m^2 + n^2}, \\quad
    \\tau_{xz} = -\\frac{\\mu p_h}{b}\\left[m\\left(1 + \\frac{z^2 + n^2}{m^2 + n^2}\\right) - 2z\\right]

with sigma_y = nu (sigma_x + sigma_z). The signs follow the Flamant line-load convention
(Johnson 1985, Eq. 2.23); ``tests/literature`` checks the closed form against direct
quadrature of the Flamant solution. Derived measures: the in-plane principal shear
tau_1 = sqrt(((sigma_x - sigma_z)/2)^2 + tau_xz^2), the Tresca maximum shear over all
three principal stresses and the von Mises stress.

Frictionless extremes (classical): tau_1,max = 0.300 p_h at z = 0.786 b; |tau_xz|max =
0.250 p_h at x = +-0.866 b, z = 0.5 b; von Mises 0.557 p_h at z = 0.70 b (nu = 0.3).
"""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..errors import InputError

__all__ = ["LineSubsurface", "StressExtremum", "line_contact_stresses", "line_subsurface"]

MEASURES = ("principal_shear", "tresca", "von_mises", "tau_xz")


def line_contact_stresses(x, z, b: float, p_h: float, *, friction: float = 0.0, nu: float = 0.3) -> dict:
    """Stress field [Pa] at points (x, z) [m] under a Hertz line contact with traction mu p.

    Returns a dict of arrays: ``sigma_x``, ``sigma_y``, ``sigma_z``, ``tau_xz``,
    ``principal_shear`` (in-plane), ``tresca`` (3-D maximum shear) and ``von_mises``.
    """
    x = np.asarray(x, dtype=float)
    z = np.asarray(z, dtype=float)
    if np.any(z < 0):
        raise InputError("line_contact_stresses: depth z must be >= 0 (measured into the body)")
    q = b * b - x * x + z * z
    root = np.sqrt(q * q + 4.0 * x * x * z * z)
    m = np.sqrt(np.clip(0.5 * (root + q), 0.0, None))  # z >= 0, so m >= 0
    n = np.sign(x) * np.sqrt(np.clip(0.5 * (root - q), 0.0, None))
    d = np.maximum(m * m + n * n, 1e-300 + 1e-30 * b * b)  # m^2 + n^2 = root; 0 only at the contact edges
    a1 = m * (1.0 + (z * z + n * n) / d) - 2.0 * z
    a2 = (m * m - z * z) / d
    scale = p_h / b
    sigma_x = -scale * a1
    sigma_z = -scale * m * (1.0 - (z * z + n * n) / d)
    tau_xz = -scale * n * a2
    if friction:
        mu = float(friction)
        sigma_x = sigma_x + mu * scale * (n * (2.0 - (z * z - m * m) / d) - 2.0 * x)
        sigma_z = sigma_z - mu * scale * n * a2
        tau_xz = tau_xz - mu * scale * a1
    sigma_y = nu * (sigma_x + sigma_z)
    half_difference = 0.5 * (sigma_x - sigma_z)
    principal_shear = np.sqrt(half_difference**2 + tau_xz**2)
    centre = 0.5 * (sigma_x + sigma_z)
    s1, s3 = centre + principal_shear, centre - principal_shear
    high = np.maximum(np.maximum(s1, s3), sigma_y)
    low = np.minimum(np.minimum(s1, s3), sigma_y)
    von_mises = np.sqrt(0.5 * ((s1 - s3) ** 2 + (s1 - sigma_y) ** 2 + (s3 - sigma_y) ** 2))
    return {
        "sigma_x": sigma_x,
        "sigma_y": sigma_y,
        "sigma_z": sigma_z,
        "tau_xz": tau_xz,
        "principal_shear": principal_shear,
        "tresca": 0.5 * (high - low),
        "von_mises": von_mises,
    }


@attrs.frozen
class StressExtremum:
    """An extreme value of a stress measure and where it occurs."""

    value: float  #: [Pa] (signed for tau_xz)
    x: float  #: position along the rolling direction [m]
    z: float  #: depth below the surface [m]


@attrs.frozen
class LineSubsurface:
    """Extremes of the subsurface stress field of a line contact (SI)."""

    b: float  #: half-width [m]
    p_h: float  #: peak pressure [Pa]
    friction: float  #: traction coefficient mu [-]
    nu: float  #: Poisson's ratio [-]
    principal_shear_max: StressExtremum  #: max in-plane principal shear tau_1
    tresca_max: StressExtremum  #: max 3-D (Tresca) shear
    von_mises_max: StressExtremum  #: max von Mises stress
    tau_xz_max: StressExtremum  #: max orthogonal shear (positive)
    tau_xz_min: StressExtremum  #: min orthogonal shear (negative)

    @property
    def orthogonal_shear_range(self) -> float:
        """Range 2 tau_0 = tau_xz,max - tau_xz,min [Pa] (the fatigue-relevant amplitude)."""
        return self.tau_xz_max.value - self.tau_xz_min.value

    def field(self, x, z) -> dict:
        """The stress field at (x, z) [m] (see :func:`line_contact_stresses`)."""
        return line_contact_stresses(x, z, self.b, self.p_h, friction=self.friction, nu=self.nu)


def _extremum(b: float, p_h: float, friction: float, nu: float, measure: str, sign: float) -> StressExtremum:
    """Global extremum of ``sign * measure`` over x in [-2b, 2b], z in [0, 2b].

    A 161 x 161 grid locates the candidates (the best few, so that a surface peak and a
    subsurface peak of similar height are both followed); each is refined by repeatedly
    zooming a 21 x 21 grid around it (spacing / 10 per round, to ~1e-9 b).
    """

    def values(x, z):
        return sign * line_contact_stresses(x, z, 1.0, 1.0, friction=friction, nu=nu)[measure]

    xs = np.linspace(-2.0, 2.0, 161)
    zs = np.linspace(0.0, 2.0, 161)
    grid_x, grid_z = np.meshgrid(xs, zs)
    coarse = values(grid_x, grid_z)
    best = (-np.inf, 0.0, 0.0)
    for index in np.argsort(coarse, axis=None)[::-1][:4]:
        cx, cz, half = float(grid_x.flat[index]), float(grid_z.flat[index]), float(xs[1] - xs[0])
        for _ in range(9):
            local_x, local_z = np.meshgrid(
                np.clip(np.linspace(cx - half, cx + half, 21), -2.0, 2.0),
                np.clip(np.linspace(cz - half, cz + half, 21), 0.0, 2.0),
            )
            local = values(local_x, local_z)
            k = int(np.argmax(local))
            cx, cz, half = float(local_x.flat[k]), float(local_z.flat[k]), half / 10.0
        value = float(values(cx, cz))
        if value > best[0]:
            best = (value, cx, cz)
    return StressExtremum(value=sign * best[0] * p_h, x=best[1] * b, z=best[2] * b)


def line_subsurface(b: float, p_h: float, *, friction: float = 0.0, nu: float = 0.3) -> LineSubsurface:
    """Maximum shear, Tresca, von Mises and orthogonal-shear extremes and their depths.

    Parameters
    ----------
    b : float
        Hertz half-width [m].
    p_h : float
        Hertz peak pressure [Pa].
    friction : float
        Surface traction coefficient mu [-] (traction mu p in +x), 0 <= mu <= 1.
    nu : float
        Poisson's ratio of the body [-] (enters sigma_y, hence Tresca and von Mises).
    """
    if not (b > 0 and p_h > 0 and math.isfinite(b) and math.isfinite(p_h)):
        raise InputError(f"line_subsurface: b = {b!r} m and p_h = {p_h!r} Pa must be finite and > 0")
    if not 0.0 <= friction <= 1.0:
        raise InputError(f"line_subsurface: friction = {friction!r} out of range; allowed 0 <= friction <= 1")
    if not 0.0 <= nu < 0.5:
        raise InputError(f"line_subsurface: nu = {nu!r} out of range; allowed 0 <= nu < 0.5")
    return LineSubsurface(
        b=b, p_h=p_h, friction=friction, nu=nu,
        principal_shear_max=_extremum(b, p_h, friction, nu, "principal_shear", 1.0),
        tresca_max=_extremum(b, p_h, friction, nu, "tresca", 1.0),
        von_mises_max=_extremum(b, p_h, friction, nu, "von_mises", 1.0),
        tau_xz_max=_extremum(b, p_h, friction, nu, "tau_xz", 1.0),
        tau_xz_min=_extremum(b, p_h, friction, nu, "tau_xz", -1.0),
    )
