"""Kalker's creepage coefficients and the flexibility parameters of his simplified theory.

Contact ellipse x^2/a^2 + y^2/b^2 <= 1 with **a the semi-axis along the rolling direction x**
and b the lateral one (Kalker's convention; Saccheto 2008 §5.5 — note that his §3.3 Hertz
formulas call "a" the semi-axis parallel to the rotation axis instead).

Kalker's exact linear theory gives the creep forces on a body for small creepages nu_x, nu_y
[-] and spin creepage phi [1/m] (Saccheto 2008 Eqs 5.48–5.49):

.. math::
    F_x = -C_{11}\\,G\\,a\\,b\\,\\nu_x, \\qquad
    F_y = -C_{22}\\,G\\,a\\,b\\,\\nu_y - C_{23}\\,G\\,(a b)^{3/2}\\,\\phi

The simplified theory replaces the half-space by springs, u = L T, with one flexibility per
creepage term; choosing them so that its total forces equal the linear theory's gives

.. math::
    L_1 = \\frac{8 a}{3 C_{11} G}, \\qquad
    L_2 = \\frac{8 a}{3 C_{22} G}, \\qquad
    L_3 = \\frac{\\pi a \\sqrt{a/b}}{4 C_{23} G}

(G the combined shear modulus [Pa], L in [m/Pa]).

The coefficients are Saccheto's Tabela 5.1 (after Kalker 1982) at b/a = 0.1, 0.3, 1, 3.33, 10,
interpolated linearly in ln(b/a) (:func:`creepage_coefficients`); outside that range an
:class:`~camcontact.errors.InputError` is raised (pass your own coefficients instead). The table
states no Poisson's ratio; its values resemble Kalker's nu = 0.25 table.

The printed L columns are kept as data (:data:`TABELA_5_1`) but **not used**: L is always computed
from C with the formulas above. The table is self-consistent to 2 decimals except L1 G/a at
b/a = 1, printed 0.62 where 8/(3 x 4.10) = 0.650 (reference errata table, "Tabela 5.1").

References
----------
Kalker, J.J. (1982) A fast algorithm for the simplified theory of rolling contact, Vehicle System
Dynamics 11:1–13. Kalker, J.J. (1967) On the rolling contact of two elastic bodies in the
presence of dry friction, PhD thesis, TH Delft (the C_ij tables).
Saccheto, T.J.S. (2008) MSc dissertation, FEM/UNICAMP, §5.5, Eqs 5.42–5.49, Tabela 5.1.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ..errors import InputError

__all__ = [
    "B_OVER_A_RANGE",
    "TABELA_5_1",
    "KalkerRow",
    "creepage_coefficients",
    "dimensionless_flexibilities",
    "flexibility_parameters",
]


class KalkerRow(NamedTuple):
    """One row of Saccheto (2008) Tabela 5.1, as printed."""

    b_over_a: float  #: lateral / rolling semi-axis [-]
    L1G_over_a: float  #: printed L1 G / a [-]
    C11: float  #: longitudinal creepage coefficient [-]
    L2G_over_a: float  #: printed L2 G / a [-]
    C22: float  #: lateral creepage coefficient [-]
    L3G_over_a: float  #: printed L3 G / a [-]
    C23: float  #: lateral-spin creepage coefficient [-]


#: Saccheto (2008) Tabela 5.1 (Kalker 1982), re-assembled from the OCR split (reference §3.6).
TABELA_5_1: tuple[KalkerRow, ...] = (
    KalkerRow(0.1, 0.23, 11.60, 0.21, 12.70, 0.17, 14.61),
    KalkerRow(0.3, 0.42, 6.35, 0.42, 6.35, 0.33, 4.35),
    KalkerRow(1.0, 0.62, 4.10, 0.73, 3.65, 0.53, 1.48),
    KalkerRow(3.33, 0.78, 3.42, 0.97, 2.75, 0.60, 0.72),
    KalkerRow(10.0, 0.81, 3.30, 1.06, 2.52, 0.53, 0.47),
)

#: b/a range covered by the table (inclusive)
B_OVER_A_RANGE: tuple[float, float] = (TABELA_5_1[0].b_over_a, TABELA_5_1[-1].b_over_a)

_LOG_B_OVER_A = np.log([row.b_over_a for row in TABELA_5_1])
_COLUMNS = {name: np.array([getattr(row, name) for row in TABELA_5_1]) for name in ("C11", "C22", "C23")}


def _check_b_over_a(b_over_a: float) -> float:
    value = float(b_over_a)
    low, high = B_OVER_A_RANGE
    if not (math.isfinite(value) and low <= value <= high):
        raise InputError(f"b/a = {value!r} (lateral over rolling semi-axis) is outside Kalker's table "
                         f"(Saccheto 2008 Tabela 5.1); allowed: {low:g} <= b/a <= {high:g}, or pass the "
                         "creepage coefficients (C11, C22, C23) yourself")
    return value


def creepage_coefficients(b_over_a: float) -> tuple[float, float, float]:
    """Kalker's creepage coefficients (C11, C22, C23) [-] at the semi-axis ratio b/a.

    Linear interpolation in ln(b/a) between the rows of Saccheto (2008) Tabela 5.1; at a
    tabulated b/a the printed values are returned exactly.

    Parameters
    ----------
    b_over_a : float
        Lateral semi-axis b over rolling semi-axis a [-], 0.1 <= b/a <= 10.

    Returns
    -------
    tuple of float
        (C11, C22, C23) [-].

    Raises
    ------
    InputError
        b/a outside [0.1, 10] or not finite.
    """
    log_ratio = math.log(_check_b_over_a(b_over_a))
    return tuple(float(np.interp(log_ratio, _LOG_B_OVER_A, _COLUMNS[name])) for name in ("C11", "C22", "C23"))


def dimensionless_flexibilities(C11: float, C22: float, C23: float, b_over_a: float) -> tuple[float, float, float]:
    """(L1 G/a, L2 G/a, L3 G/a) [-] from the creepage coefficients (Saccheto 2008 Eqs 5.48–5.49).

    .. math:: \\frac{L_1 G}{a} = \\frac{8}{3 C_{11}}, \\quad \\frac{L_2 G}{a} = \\frac{8}{3 C_{22}},
              \\quad \\frac{L_3 G}{a} = \\frac{\\pi}{4 C_{23}}\\sqrt{\\frac{a}{b}}
    """
    return 8.0 / (3.0 * C11), 8.0 / (3.0 * C22), math.pi / (4.0 * C23 * math.sqrt(b_over_a))


def _positive(value: float, name: str, unit: str) -> float:
    number = float(value)
    if not (math.isfinite(number) and number > 0.0):
        raise InputError(f"{name} = {value!r} {unit}; allowed: a finite {name} > 0")
    return number


def flexibility_parameters(a: float, b: float, shear_modulus: float, *,
                           coefficients: tuple[float, float, float] | None = None) -> tuple[float, float, float]:
    """Flexibility parameters (L1, L2, L3) [m/Pa] of Kalker's simplified theory.

    .. math:: L_1 = \\frac{8 a}{3 C_{11} G}, \\quad L_2 = \\frac{8 a}{3 C_{22} G}, \\quad
              L_3 = \\frac{\\pi a \\sqrt{a/b}}{4 C_{23} G}

    Parameters
    ----------
    a : float
        Semi-axis along the rolling direction [m] (> 0).
    b : float
        Lateral semi-axis [m] (> 0).
    shear_modulus : float
        Combined shear modulus G [Pa] (> 0); for two bodies 2/G = 1/G1 + 1/G2.
    coefficients : tuple of float, optional
        (C11, C22, C23) [-]; default: :func:`creepage_coefficients` at b/a (0.1 <= b/a <= 10).

    Returns
    -------
    tuple of float
        (L1, L2, L3) [m/Pa].

    References
    ----------
    Kalker (1982) Vehicle System Dynamics 11:1–13; Saccheto (2008) Eqs 5.48–5.49, Tabela 5.1.
    """
    a = _positive(a, "a", "m")
    b = _positive(b, "b", "m")
    G = _positive(shear_modulus, "shear_modulus", "Pa")
    if coefficients is None:
        C11, C22, C23 = creepage_coefficients(b / a)
    else:
        if len(coefficients) != 3:
            raise InputError(f"coefficients = {coefficients!r}; allowed: a tuple (C11, C22, C23) of three numbers > 0")
        C11, C22, C23 = (_positive(c, name, "[-]") for c, name in zip(coefficients, ("C11", "C22", "C23")))
    l1, l2, l3 = dimensionless_flexibilities(C11, C22, C23, b / a)
    return l1 * a / G, l2 * a / G, l3 * a / G
