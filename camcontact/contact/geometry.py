"""Contact geometry: reduced modulus and reduced (relative) radii of curvature.

Conventions (DESIGN.md, Hamrock):

* reduced modulus E' = 2 / [(1 - nu1^2)/E1 + (1 - nu2^2)/E2] (note: Johnson's E* = E'/2);
* radii are signed: a convex surface has R > 0, a concave one (an outer raceway) R < 0,
  a flat one R = inf; the reduced radius is 1/R = 1/R1 + 1/R2.

All functions take and return SI floats.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError

__all__ = ["reduced_modulus", "reduced_radius", "relative_curvature"]


def reduced_modulus(E1: float, nu1: float, E2: float, nu2: float) -> float:
    """Reduced (plane-strain) modulus E' [Pa] of two elastic bodies.

    .. math:: \\frac{2}{E'} = \\frac{1 - \\nu_1^2}{E_1} + \\frac{1 - \\nu_2^2}{E_2}

    References: Tsuha (2015) Eq. 4.14; Hamrock, Schmid & Jacobson (2004) *Fundamentals of Fluid Film
    Lubrication*, 2nd ed., ch. 17 (the effective elastic modulus).
    """
    return 2.0 / ((1.0 - nu1**2) / E1 + (1.0 - nu2**2) / E2)


def _curvature(radius: float) -> float:
    return 0.0 if math.isinf(radius) else 1.0 / radius


def reduced_radius(R1: float, R2: float) -> float:
    """Reduced radius R [m] from signed radii (concave < 0, flat = inf).

    .. math:: \\frac{1}{R} = \\frac{1}{R_1} + \\frac{1}{R_2}

    Raises :class:`~camcontact.errors.InputError` when the surfaces conform or the
    concave one is tighter than the convex one (no Hertzian contact).
    """
    curvature = _curvature(R1) + _curvature(R2)
    if not curvature > 0.0:
        raise InputError(
            f"radii R1 = {R1:g} m and R2 = {R2:g} m give curvature sum {curvature:g} 1/m <= 0: "
            "the surfaces are conforming (a concave radius must be larger in magnitude than the convex one)"
        )
    return 1.0 / curvature


def relative_curvature(
    R1: float, R1p: float, R2: float, R2p: float, psi: float = 0.0
) -> tuple[float, float]:
    """Principal reduced radii (R_a, R_b) [m] of two bodies with crossed principal planes.

    Body 1 has principal radii R1, R1p, body 2 R2, R2p (signed); psi [rad] is the angle
    between the planes of R1 and R2. With curvature sums A + B and difference B - A
    (Hertz; Timoshenko & Goodier; corrected form of Saccheto 2008 Eq. 3.38):

    .. math::
        A + B = \\tfrac12\\left(\\tfrac1{R_1} + \\tfrac1{R_1'} + \\tfrac1{R_2} + \\tfrac1{R_2'}\\right),\\quad
        B - A = \\tfrac12\\sqrt{\\left(\\tfrac1{R_1}-\\tfrac1{R_1'}\\right)^2 + \\left(\\tfrac1{R_2}-\\tfrac1{R_2'}\\right)^2
                + 2\\left(\\tfrac1{R_1}-\\tfrac1{R_1'}\\right)\\left(\\tfrac1{R_2}-\\tfrac1{R_2'}\\right)\\cos 2\\psi}

    Returns R_a = 1/(2A) >= R_b = 1/(2B), the Hamrock radii of the relative gap along its
    principal directions (for psi = 0 these are 1/(1/R1 + 1/R2) and 1/(1/R1p + 1/R2p)).
    """
    k1, k1p, k2, k2p = (_curvature(r) for r in (R1, R1p, R2, R2p))
    total = 0.5 * (k1 + k1p + k2 + k2p)
    d1, d2 = k1 - k1p, k2 - k2p
    difference = 0.5 * math.sqrt(max(d1 * d1 + d2 * d2 + 2.0 * d1 * d2 * math.cos(2.0 * psi), 0.0))
    a_sum = 0.5 * (total - difference)
    b_sum = 0.5 * (total + difference)
    if not a_sum > 0.0:
        raise InputError(
            f"principal radii ({R1:g}, {R1p:g}) and ({R2:g}, {R2p:g}) m give a non-positive "
            "relative curvature: the surfaces conform and Hertz theory does not apply"
        )
    return float(1.0 / (2.0 * a_sum)), float(1.0 / (2.0 * b_sum))


def as_array(value) -> np.ndarray:
    """Float array view of a scalar or array input."""
    return np.asarray(value, dtype=float)
