"""Hertz elliptical (point) contact: exact elliptic integrals, or Hamrock–Brewe fits.

With Rx, Ry the reduced radii of the gap in the x (entrainment) and y directions,
R = (1/Rx + 1/Ry)^-1, the radius ratio r = R_major/R_minor >= 1 and the ellipticity
kappa = a_major/a_minor >= 1 (semi-axes: the major one lies along the larger radius):

.. math::
    r = \\frac{\\kappa^2 \\mathcal{E}(m) - \\mathcal{K}(m)}{\\mathcal{K}(m) - \\mathcal{E}(m)}, \\quad m = 1 - \\kappa^{-2}

    a_{major} = \\left(\\frac{6 \\kappa^2 \\mathcal{E} F R}{\\pi E'}\\right)^{1/3}, \\quad
    a_{minor} = \\left(\\frac{6 \\mathcal{E} F R}{\\pi \\kappa E'}\\right)^{1/3}, \\quad
    \\delta = \\mathcal{K}\\left[\\frac{9}{2 \\mathcal{E} R}\\left(\\frac{F}{\\pi \\kappa E'}\\right)^2\\right]^{1/3}, \\quad
    p_{max} = \\frac{3F}{2\\pi a_{major} a_{minor}}

with K, E the complete elliptic integrals of the first and second kind (parameter m).
``method="exact"`` solves the first relation for kappa by root finding (Carlson form,
see :func:`ellipticity_exact`). Two published closed-form approximations skip the root
and the integrals:

* ``"hamrock_brewe"`` (Hamrock & Brewe 1983): kappa = r^(2/pi), E = 1 + (pi/2 - 1)/r,
  K = pi/2 + (pi/2 - 1) ln r — exact for the circle; errors of a few per cent up to r = 100
  (about -2.7..+2.1 % on a, -4.1..+2.7 % on the approach);
* ``"brewe_hamrock_1977"`` (Brewe & Hamrock 1977, as in Harris & Kotzalas Eqs. 6.33–6.35):
  kappa = 1.0339 r^0.636, E = 1.0003 + 0.5968/r, K = 1.5277 + 0.6023 ln r.

Their cost and accuracy against ``"exact"`` are measured by ``benchmarks/hertz_elliptical.py``.

``"timoshenko_table"`` is the thesis route of Saccheto (2008) Eqs. 3.42-3.44: with the gap
z = A x^2 + B y^2 (A <= B), theta = arccos((B - A)/(A + B)) and the coefficients m, n of its
Tabela 3.1 (Dedini 1985, classical Timoshenko; :data:`TIMOSHENKO_TABLE`, interpolated linearly
in theta from 20 to 90 deg), the semi-axes are a = m c, b = n c with
c = [3 pi F (K1 + K2)/(4 (A + B))]^(1/3), K1 + K2 = 2/(pi E'). Its approach uses the exact
elliptic integrals at the table's ellipticity m/n. The table's 20 deg entry is about 1 % off the
exact value (reference §3.5).

References
----------
Hamrock, B.J. & Brewe, D.E. (1983) Simplified solution for stresses and deformations,
J. Lubr. Technol. 105:171–177. Brewe, D.E. & Hamrock, B.J. (1977) Simplified solution
for elliptical-contact deformation between two elastic solids, J. Lubr. Technol.
99:485–487. Harris & Kotzalas (2007) Rolling Bearing Analysis, 5th ed., Eqs. 6.33–6.35.
Johnson, K.L. (1985) Contact Mechanics, §3.5. Timoshenko's m, n coefficients
(Saccheto 2008, Tabela 3.1) follow as m = (2 kappa^2 E / pi)^(1/3), n = m / kappa.
"""

from __future__ import annotations

import math

import attrs
import numpy as np
from scipy import special
from scipy.optimize import brentq

from ..errors import InputError

__all__ = ["TIMOSHENKO_TABLE", "EllipticalHertz", "ellipticity_exact", "hertz_elliptical", "timoshenko_coefficients"]

METHODS = ("exact", "hamrock_brewe", "brewe_hamrock_1977", "timoshenko_table")
#: Saccheto (2008) Tabela 3.1: theta [deg], m, n (reference §3.5)
TIMOSHENKO_TABLE = (
    (20.0, 30.0, 35.0, 40.0, 45.0, 50.0, 55.0, 60.0, 65.0, 70.0, 75.0, 80.0, 85.0, 90.0),
    (3.778, 2.731, 2.397, 2.136, 1.926, 1.754, 1.611, 1.486, 1.378, 1.284, 1.202, 1.128, 1.061, 1.000),
    (0.408, 0.493, 0.530, 0.567, 0.604, 0.641, 0.678, 0.717, 0.759, 0.802, 0.846, 0.893, 0.944, 1.000),
)


def timoshenko_coefficients(theta: float) -> tuple[float, float]:
    """(m, n) of Tabela 3.1 at theta [rad], linear interpolation (20..90 deg; InputError outside)."""
    degrees = math.degrees(theta)
    angles, m_values, n_values = TIMOSHENKO_TABLE
    if not angles[0] - 1e-9 <= degrees <= angles[-1] + 1e-9:
        raise InputError(f"Timoshenko table: theta = {degrees:.4g} deg is outside the table (20..90 deg): the contact "
                         "is too elongated for it; use method='exact'")
    return float(np.interp(degrees, angles, m_values)), float(np.interp(degrees, angles, n_values))


@attrs.frozen
class EllipticalHertz:
    """Result of :func:`hertz_elliptical` (SI floats)."""

    F: float  #: normal load [N]
    Rx: float  #: reduced radius along x (entrainment) [m]
    Ry: float  #: reduced radius along y [m]
    E_reduced: float  #: reduced modulus E' [Pa]
    a_x: float  #: semi-axis along x [m]
    a_y: float  #: semi-axis along y [m]
    p_max: float  #: maximum pressure [Pa]
    p_mean: float  #: mean pressure F/(pi a_x a_y) [Pa]
    approach: float  #: elastic approach of distant points [m]
    kappa: float  #: ellipticity a_major/a_minor >= 1 [-]
    elliptic_K: float  #: complete elliptic integral of the first kind [-]
    elliptic_E: float  #: complete elliptic integral of the second kind [-]
    method: str  #: "exact" or "hamrock_brewe"

    @property
    def ellipticity(self) -> float:
        """Hamrock's k = a_y / a_x (< 1 when the major axis lies along x)."""
        return self.a_y / self.a_x


def _carlson(kappa: float) -> tuple[float, float, float]:
    """(R_F, R_D, m) at y = 1/kappa^2: K = R_F, K - E = (m/3) R_D (no cancellation near kappa = 1)."""
    y = 1.0 / (kappa * kappa)
    return float(special.elliprf(0.0, y, 1.0)), float(special.elliprd(0.0, y, 1.0)), 1.0 - y


def _ratio_of_kappa(kappa: float) -> float:
    """Radius ratio r(kappa) = kappa^2 (3 R_F / R_D - 1), the Hertz relation in Carlson form."""
    r_f, r_d, _ = _carlson(kappa)
    return kappa * kappa * (3.0 * r_f / r_d - 1.0)


def ellipticity_exact(radius_ratio: float) -> tuple[float, float, float]:
    """(kappa, K, E) for radius ratio r = R_major/R_minor >= 1, by root finding.

    The Hertz relation r = (kappa^2 E - K)/(K - E) is evaluated in Carlson's symmetric
    form r = kappa^2 (3 R_F(0, y, 1)/R_D(0, y, 1) - 1), y = 1/kappa^2, which has no
    cancellation as kappa -> 1. Valid for 1 <= r <= 1e8; r = 1 is the circle
    (kappa = 1, K = E = pi/2).
    """
    r = float(radius_ratio)
    if not (r >= 1.0 and math.isfinite(r)):
        raise InputError(f"radius ratio {r!r} must be finite and >= 1")
    if r > 1e8:
        raise InputError(
            f"radius ratio {r:.3g} > 1e8: the contact is a line contact for practical purposes; "
            "use the line-contact model"
        )
    if r == 1.0:
        kappa = 1.0
    else:
        # r - 1 ~ 1.5 (kappa - 1) near the circle and kappa ~ r^0.64 far from it: bracket both
        low = 1.0 + (r - 1.0) / 3.0 if r < 1.5 else 1.0 + 1e-3
        high = max(1.0 + (r - 1.0), 2.0 * 1.0339 * r**0.636)
        while _ratio_of_kappa(high) < r:
            high *= 2.0
        log_kappa = brentq(lambda s: math.log(_ratio_of_kappa(math.exp(s)) / r),
                           math.log(low), math.log(high), xtol=1e-15, rtol=1e-15, maxiter=200)
        kappa = math.exp(log_kappa)
    r_f, r_d, m = _carlson(kappa)
    return kappa, r_f, r_f - m / 3.0 * r_d


def hertz_elliptical(
    F: float, Rx: float, Ry: float, E_reduced: float, *, method: str = "exact"
) -> EllipticalHertz:
    """Hertz elliptical contact for load F [N], reduced radii Rx, Ry [m] and E' [Pa].

    ``method`` is ``"exact"`` (elliptic integrals, root-solved ellipticity),
    ``"hamrock_brewe"`` (1983 fits), ``"brewe_hamrock_1977"`` or ``"timoshenko_table"`` (Saccheto's
    m, n table; see the module docstring).
    """
    for label, value in (("load F", F), ("radius Rx", Rx), ("radius Ry", Ry), ("reduced modulus E'", E_reduced)):
        if not (value > 0.0 and math.isfinite(value)):
            raise InputError(f"Hertz elliptical contact: {label} = {value!r} must be finite and > 0")
    if method not in METHODS:
        raise InputError(f"Hertz elliptical contact: method {method!r} unknown; choose one of {METHODS}")
    r = max(Rx, Ry) / min(Rx, Ry)
    R = 1.0 / (1.0 / Rx + 1.0 / Ry)
    if method == "timoshenko_table":
        A, B = 0.5 / max(Rx, Ry), 0.5 / min(Rx, Ry)
        m, n = timoshenko_coefficients(math.acos((B - A) / (A + B)))
        scale = (3.0 * math.pi * F * 2.0 / (math.pi * E_reduced) / (4.0 * (A + B))) ** (1.0 / 3.0)
        a_major, a_minor = m * scale, n * scale
        kappa = m / n
        r_f, r_d, mm = _carlson(kappa)
        big_k, big_e = r_f, r_f - mm / 3.0 * r_d
        approach = big_k * (4.5 / (big_e * R) * (F / (math.pi * kappa * E_reduced)) ** 2) ** (1.0 / 3.0)
        return _result(F, Rx, Ry, E_reduced, a_major, a_minor, approach, kappa, big_k, big_e, method)
    if method == "exact":
        kappa, big_k, big_e = ellipticity_exact(r)
    elif method == "hamrock_brewe":
        kappa = r ** (2.0 / math.pi)
        big_e = 1.0 + (0.5 * math.pi - 1.0) / r
        big_k = 0.5 * math.pi + (0.5 * math.pi - 1.0) * math.log(r)
    else:
        kappa = 1.0339 * r**0.636
        big_e = 1.0003 + 0.5968 / r
        big_k = 1.5277 + 0.6023 * math.log(r)
    a_major = (6.0 * kappa * kappa * big_e * F * R / (math.pi * E_reduced)) ** (1.0 / 3.0)
    a_minor = (6.0 * big_e * F * R / (math.pi * kappa * E_reduced)) ** (1.0 / 3.0)
    approach = big_k * (4.5 / (big_e * R) * (F / (math.pi * kappa * E_reduced)) ** 2) ** (1.0 / 3.0)
    return _result(F, Rx, Ry, E_reduced, a_major, a_minor, approach, kappa, big_k, big_e, method)


def _result(F, Rx, Ry, E_reduced, a_major, a_minor, approach, kappa, big_k, big_e, method) -> EllipticalHertz:
    a_x, a_y = (a_minor, a_major) if Ry >= Rx else (a_major, a_minor)
    p_max = 1.5 * F / (math.pi * a_x * a_y)
    return EllipticalHertz(
        F=F, Rx=Rx, Ry=Ry, E_reduced=E_reduced, a_x=a_x, a_y=a_y, p_max=p_max,
        p_mean=F / (math.pi * a_x * a_y), approach=approach, kappa=kappa,
        elliptic_K=float(big_k), elliptic_E=float(big_e), method=method,
    )


def hertz_pressure(result: EllipticalHertz, x, y):
    """Hertz pressure p(x, y) [Pa] of an elliptical contact (zero outside the ellipse)."""
    s = 1.0 - (np.asarray(x, dtype=float) / result.a_x) ** 2 - (np.asarray(y, dtype=float) / result.a_y) ** 2
    return result.p_max * np.sqrt(np.clip(s, 0.0, None))
