"""Dimensionless EHL groups (Hamrock; Moes) and the speed conventions.

Conventions (DESIGN.md): entrainment speed u_m = (u1 + u2)/2, reduced modulus
E' = 2/[(1 - nu1^2)/E1 + (1 - nu2^2)/E2].

Hamrock groups
    U = eta0 u_m / (E' R), G = alpha E', W' = w / (E' R) (line, w per unit length),
    W = F / (E' Rx^2) (point, U and H on Rx).
Moes groups, line contact (Venner & Lubrecht 2000)
    M = W' (2U)^(-1/2), L = G (2U)^(1/4), H = (h/R) (2U)^(-1/2)
Moes groups, point contact
    M = W (2U)^(-3/4), L = G (2U)^(1/4), H = (h/Rx) (2U)^(-1/2)

2U = eta0 (u1 + u2)/(E' R) is the *sum-speed* group Moes uses. Tsuha (2015) writes the
Moes groups with the *mean* speed in place of the sum (its Eqs. 4.32–4.33 and the factor
noted as erratum 9 of the reference), which halves the speed of every case; the
``convention="tsuha2015"`` switch reproduces its tables, ``"consistent"`` (default) is
physically correct.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError

__all__ = ["CONVENTIONS", "hamrock_line", "hamrock_point", "moes_line", "moes_point", "speed_group"]

CONVENTIONS = ("consistent", "tsuha2015")


def _check(**values) -> None:
    for name, value in values.items():
        array = np.asarray(value, dtype=float)
        if not np.all(np.isfinite(array)):
            raise InputError(f"EHL groups: {name} = {value!r} must be finite")


def hamrock_line(w, R, E_reduced, u_m, eta0, alpha) -> tuple:
    """(U, G, W') of a line contact: w [N/m], R [m], E' [Pa], u_m [m/s], eta0 [Pa*s], alpha [1/Pa]."""
    _check(w=w, R=R, E_reduced=E_reduced, u_m=u_m, eta0=eta0, alpha=alpha)
    U = eta0 * np.abs(u_m) / (E_reduced * R)
    return U, alpha * E_reduced, w / (E_reduced * R)


def hamrock_point(F, Rx, E_reduced, u_m, eta0, alpha) -> tuple:
    """(U, G, W) of a point contact: F [N], Rx [m] (entrainment direction), E' [Pa], u_m [m/s]."""
    _check(F=F, Rx=Rx, E_reduced=E_reduced, u_m=u_m, eta0=eta0, alpha=alpha)
    U = eta0 * np.abs(u_m) / (E_reduced * Rx)
    return U, alpha * E_reduced, F / (E_reduced * Rx * Rx)


def speed_group(U, convention: str = "consistent"):
    """The speed group Moes's formulas expect: 2U (sum speed) or U (``"tsuha2015"``)."""
    if convention == "consistent":
        return 2.0 * U
    if convention == "tsuha2015":
        return U
    raise InputError(f"speed convention {convention!r} unknown; choose one of {CONVENTIONS}")


def moes_line(U, G, W, convention: str = "consistent") -> tuple:
    """Moes (M, L) of a line contact from Hamrock (U, G, W')."""
    s = speed_group(U, convention)
    return W * s**-0.5, G * s**0.25


def moes_point(U, G, W, convention: str = "consistent") -> tuple:
    """Moes (M, L) of a point contact from Hamrock (U, G, W)."""
    s = speed_group(U, convention)
    return W * s**-0.75, G * s**0.25
