"""Hertz line contact (two parallel cylinders, or a cylinder on a plane).

.. math::
    b = \\sqrt{\\frac{8 w R}{\\pi E'}}, \\qquad p_h = \\frac{2 w}{\\pi b} = \\sqrt{\\frac{w E'}{2 \\pi R}},
    \\qquad p_{mean} = \\frac{\\pi}{4} p_h

with w the load per unit length [N/m], R the reduced radius [m] and E' the reduced
modulus [Pa] (Hamrock convention; Tsuha 2015 Eqs. 4.16–4.18; Delabenetta 2021 Eqs. 2–4 in
Johnson's E* = E'/2 and R_x = 2R notation, with the pi that its print omits).

The elastic approach of a line contact depends on where it is measured; two published
forms are offered by :func:`line_approach`:

* ``"palmgren"`` — Palmgren (1959) / Harris empirical relation for steel rollers, written
  for any E' by Tsuha (2015) Eq. 4.19: delta = 3.81 [2/(pi E')]^0.9 F^0.9 / l^0.8 [m];
* ``"hamrock"`` — elastic approach of a cylinder pair in reduced form,
  delta = (2w/(pi E')) [ln(2 pi E' R / w) - 1] = (2w/(pi E')) [2 ln(4R/b) - 1]
  (the maximum elastic deformation of a rectangular conjunction in the reduced radius and
  modulus: Hamrock, Schmid & Jacobson (2004) *Fundamentals of Fluid Film Lubrication*, 2nd ed.,
  ch. 17; the equation number is not checked against the print here).
"""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..errors import InputError

__all__ = ["LineHertz", "hertz_line", "hertz_line_arrays", "line_approach"]


@attrs.frozen
class LineHertz:
    """Result of :func:`hertz_line` (SI floats)."""

    w: float  #: load per unit length [N/m]
    R: float  #: reduced radius [m]
    E_reduced: float  #: reduced modulus E' [Pa]
    b: float  #: half-width of the contact strip [m]
    p_h: float  #: maximum (Hertz) pressure [Pa]
    p_mean: float  #: mean pressure over the strip [Pa]

    def pressure(self, x):
        """Hertz pressure p(x) [Pa] at positions x [m] (zero outside |x| < b)."""
        xi = np.asarray(x, dtype=float) / self.b
        return self.p_h * np.sqrt(np.clip(1.0 - xi * xi, 0.0, None))


def hertz_line_arrays(w, R: float, E_reduced: float) -> tuple[np.ndarray, np.ndarray]:
    """(b, p_h) [m, Pa] of line contacts under the loads per length ``w`` [N/m] (an array, >= 0: 0 gives 0), radius R
    [m] and E' [Pa]: the formulas of :func:`hertz_line` elementwise, for slices and laminae."""
    w = np.asarray(w, dtype=float)
    return np.sqrt(8.0 * w * R / (math.pi * E_reduced)), np.sqrt(w * E_reduced / (2.0 * math.pi * R))


def hertz_line(w: float, R: float, E_reduced: float) -> LineHertz:
    """Hertz line contact from load per length w [N/m], reduced radius R [m], E' [Pa]."""
    for label, value in (("load per length w", w), ("reduced radius R", R), ("reduced modulus E'", E_reduced)):
        if not (value > 0.0 and math.isfinite(value)):
            raise InputError(f"Hertz line contact: {label} = {value!r} must be finite and > 0")
    b = math.sqrt(8.0 * w * R / (math.pi * E_reduced))
    p_h = 2.0 * w / (math.pi * b)
    return LineHertz(w=w, R=R, E_reduced=E_reduced, b=b, p_h=p_h, p_mean=0.25 * math.pi * p_h)


def line_approach(
    method: str,
    *,
    E_reduced: float,
    w: float | None = None,
    R: float | None = None,
    force: float | None = None,
    length: float | None = None,
) -> float:
    """Elastic approach delta [m] of a line contact.

    ``method="hamrock"`` needs the load per length ``w`` [N/m] and reduced radius ``R`` [m];
    ``method="palmgren"`` needs the total ``force`` [N] and contact ``length`` [m]. Both need
    the reduced modulus ``E_reduced`` [Pa].
    """
    if not E_reduced > 0:
        raise InputError(f"line approach: E_reduced = {E_reduced!r} Pa must be > 0")
    if method == "palmgren":
        if not (force is not None and length is not None and force > 0 and length > 0):
            raise InputError(f"line approach 'palmgren' needs force > 0 [N] and length > 0 [m]; got {force!r}, {length!r}")
        return 3.81 * (2.0 / (math.pi * E_reduced)) ** 0.9 * force**0.9 / length**0.8
    if method == "hamrock":
        if not (w is not None and R is not None and w > 0 and R > 0):
            raise InputError(f"line approach 'hamrock' needs w > 0 [N/m] and R > 0 [m]; got {w!r}, {R!r}")
        return 2.0 * w / (math.pi * E_reduced) * (math.log(2.0 * math.pi * E_reduced * R / w) - 1.0)
    raise InputError(f"line approach method {method!r} unknown; choose 'hamrock' or 'palmgren'")
