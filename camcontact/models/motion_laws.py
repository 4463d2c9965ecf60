"""Cam motion laws (family ``motion_laws``): normalised unit-lift segments on x in [0, 1].

Every law gives y(x) and its exact derivatives y', y'', y''' with respect to the normalised
cam angle x = (θ − θ_start)/β [-] (β = segment angle). A *rise* law goes y(0) = 0 → y(1) = 1,
a *return* law y(0) = 1 → y(1) = 0 (class attribute ``direction``). Lift and cam-angle
scaling (f' = L y'/β, ...) are done by :class:`camcontact.kinematics.motion_program.Segment`.

===================== ========= =================================================================
name                  direction y(x)
===================== ========= =================================================================
cycloidal (= C-5)     rise      x − sin(2πx)/(2π)
harmonic (= H-5)      rise      [1 − cos(πx)]/2
polynomial_345        rise      10x³ − 15x⁴ + 6x⁵
polynomial_4567       rise      35x⁴ − 84x⁵ + 70x⁶ − 20x⁷
modified_trapezoid    rise      cycloidal-jerk ramps of 1/8, constant acceleration (C_a = 4.888)
modified_sine         rise      quarter sines of period 1/2 and 3/2 (C_a = 5.528)
C-1, C-2              rise      x ∓ sin(πx)/π (half cycloids)
C-3, C-4              return    1 − x ± sin(πx)/π
C-5, C-6              rise/ret. full cycloid and its time reverse
H-1, H-2              rise      1 − cos(πx/2), sin(πx/2) (half harmonics)
H-3, H-4              return    cos(πx/2), 1 − sin(πx/2)
H-5, H-6              rise/ret. [1 ∓ cos(πx)]/2
P-1, P-2              rise/ret. 8th-degree polynomial (Tsuha 2015 ch. 6) and P-1(1 − x)
===================== ========= =================================================================

The C-/H-/P- series follow Mabie & Reinholtz (1987) as tabulated in the Tsuha (2015)
reference (§2.1). **Caution (from that reference):** the name-to-formula assignment of the
C- and H- laws was recalled from Mabie & Reinholtz and has not been checked against the book;
the formulas themselves are what the table gives. P-1 is confirmed by Rothbart (2004) p. 112
and by exact reproduction of the thesis tables.
"""

from __future__ import annotations

import abc
import math
from typing import ClassVar

import numpy as np
from numpy.polynomial import Polynomial

from ..errors import InputError
from .base import MotionLaw, builtin

__all__ = [
    "C1", "C2", "C3", "C4", "C5", "C6",
    "H1", "H2", "H3", "H4", "H5", "H6",
    "P1", "P2",
    "Cycloidal", "Harmonic", "ModifiedSine", "ModifiedTrapezoid", "Polynomial345", "Polynomial4567",
]

PI = math.pi

MABIE = (
    "Mabie, H.H. & Reinholtz, C.F. (1987) Mechanisms and Dynamics of Machinery, 4th ed., Wiley; "
    "as tabulated in the Tsuha (2015) reference §2.1 (name-to-formula assignment not checked against the book)"
)
HANDBOOKS = (
    "Rothbart, H.A. (2004) Cam Design Handbook, McGraw-Hill, ch. 3; "
    "Norton, R.L. (2009) Cam Design and Manufacturing Handbook, 2nd ed., Industrial Press"
)


def _checked_x(x, name: str) -> np.ndarray:
    """``x`` as a float array, or :class:`InputError` naming the first value outside [0, 1]."""
    array = np.asarray(x, dtype=float)
    inside = (array >= 0.0) & (array <= 1.0)  # NaN is outside too
    if not np.all(inside):
        value = array[~inside].flat[0] if array.ndim else float(array)
        raise InputError(
            f"motion law {name!r}: x = {value!r} is outside [0, 1] "
            "(x is the normalised segment angle (θ − start)/β)"
        )
    return array


class _Law(MotionLaw):
    """Shared machinery: checks x, returns four float arrays shaped like x.

    Subclasses implement the classmethod :meth:`_shape` (x already checked).
    """

    validity = {"x": (0.0, 1.0)}
    direction: ClassVar[str] = "rise"

    @classmethod
    @abc.abstractmethod
    def _shape(cls, x: np.ndarray) -> tuple:
        """(y, dy/dx, d2y/dx2, d3y/dx3) of the law at checked ``x``; every concrete law implements it."""

    def derivatives(self, x):
        """(y, dy/dx, d²y/dx², d³y/dx³) [-] at normalised angles ``x`` in [0, 1] [-]."""
        x = _checked_x(x, self.name)
        zeros = np.zeros_like(x)
        return tuple(np.asarray(np.asarray(value, dtype=float) + zeros) for value in self._shape(x))

    # laws hold no parameters: two instances of one law are equal
    def __eq__(self, other) -> bool:
        return type(other) is type(self)

    def __hash__(self) -> int:
        return hash(type(self))


class _Reversed(_Law):
    """A return law that is a rise law run backwards in time: y(x) = y_rise(1 − x)."""

    direction = "return"
    forward: ClassVar[type[_Law]]

    @classmethod
    def _shape(cls, x):
        y, d1, d2, d3 = cls.forward._shape(1.0 - x)
        return y, -d1, d2, -d3


class _PolynomialLaw(_Law):
    """A polynomial law from ``coefficients`` (ascending powers of x, constant first)."""

    coefficients: ClassVar[tuple[float, ...]] = ()
    _polynomials: ClassVar[tuple[Polynomial, ...]] = ()

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        if "coefficients" in cls.__dict__:
            p = Polynomial(cls.coefficients)
            cls._polynomials = (p, p.deriv(1), p.deriv(2), p.deriv(3))

    @classmethod
    def _shape(cls, x):
        return tuple(p(x) for p in cls._polynomials)


class _SineRampLaw(_Law):
    """A law built from acceleration pieces a = c0 + cs sin(w u) + cc cos(w u), u = x − x_start.

    ``pieces`` holds (x_start, x_end, c0, cs, cc, w) with a unit acceleration amplitude; the
    velocity and displacement are integrated exactly piece by piece from y(0) = y'(0) = 0,
    and the whole law is scaled so that y(1) = 1 (the scale is the acceleration coefficient C_a).
    """

    pieces: ClassVar[tuple[tuple[float, ...], ...]] = ()
    _starts: ClassVar[np.ndarray]
    _initial: ClassVar[list[tuple[float, float]]]
    peak_acceleration: ClassVar[float]

    @staticmethod
    def _piece(u, v0, y0, c0, cs, cc, w):
        s, c = np.sin(w * u), np.cos(w * u)
        y = y0 + v0 * u + c0 * u**2 / 2.0 + cs / w * (u - s / w) + cc / w**2 * (1.0 - c)
        v = v0 + c0 * u + cs / w * (1.0 - c) + cc / w * s
        a = c0 + cs * s + cc * c
        j = w * (cs * c - cc * s)
        return y, v, a, j

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        if "pieces" not in cls.__dict__:
            return
        initial, v0, y0 = [], 0.0, 0.0
        for x0, x1, *terms in cls.pieces:
            initial.append((v0, y0))
            y0, v0, _, _ = cls._piece(x1 - x0, v0, y0, *terms)
        cls._starts = np.array([piece[0] for piece in cls.pieces])
        cls._initial = initial
        cls.peak_acceleration = 1.0 / y0

    @classmethod
    def _shape(cls, x):
        index = np.clip(np.searchsorted(cls._starts, x, side="right") - 1, 0, len(cls.pieces) - 1)
        out = [np.zeros_like(x) for _ in range(4)]
        for k, (x0, _x1, *terms) in enumerate(cls.pieces):
            mask = index == k
            if np.any(mask):
                values = cls._piece(x[mask] - x0, *cls._initial[k], *terms)
                for array, value in zip(out, values):
                    array[mask] = value * cls.peak_acceleration
        return tuple(out)


# ----------------------------------------------------------------- full-period rise laws
@builtin
class Cycloidal(_Law):
    """Cycloidal rise: zero velocity and acceleration at both ends (finite jerk with dwells).

    .. math:: y = x - \\frac{\\sin 2\\pi x}{2\\pi}, \\quad y' = 1 - \\cos 2\\pi x, \\quad
        y'' = 2\\pi \\sin 2\\pi x, \\quad y''' = 4\\pi^2 \\cos 2\\pi x

    Peaks: y' = 2, y'' = 2π, y''' = 4π². Same curve as C-5.

    References
    ----------
    Rothbart (2004) Cam Design Handbook ch. 3; Norton (2009) Cam Design and Manufacturing
    Handbook; Mabie & Reinholtz (1987) C-5 (Tsuha 2015 reference §2.1).
    """

    name = "cycloidal"
    reference = HANDBOOKS + "; = C-5 of Mabie & Reinholtz (1987)"

    @classmethod
    def _shape(cls, x):
        s, c = np.sin(2 * PI * x), np.cos(2 * PI * x)
        return x - s / (2 * PI), 1.0 - c, 2 * PI * s, 4 * PI**2 * c


@builtin
class Harmonic(_Law):
    """Simple harmonic rise: non-zero acceleration at the ends (infinite jerk next to a dwell).

    .. math:: y = \\tfrac12 (1 - \\cos \\pi x), \\quad y' = \\tfrac{\\pi}{2} \\sin \\pi x, \\quad
        y'' = \\tfrac{\\pi^2}{2} \\cos \\pi x, \\quad y''' = -\\tfrac{\\pi^3}{2} \\sin \\pi x

    Peaks: y' = π/2, y'' = π²/2, y''' = π³/2. Same curve as H-5.

    References
    ----------
    Rothbart (2004) Cam Design Handbook ch. 3; Norton (2009) Cam Design and Manufacturing
    Handbook; Mabie & Reinholtz (1987) H-5 (Tsuha 2015 reference §2.1).
    """

    name = "harmonic"
    reference = HANDBOOKS + "; = H-5 of Mabie & Reinholtz (1987)"

    @classmethod
    def _shape(cls, x):
        s, c = np.sin(PI * x), np.cos(PI * x)
        return 0.5 * (1.0 - c), PI / 2 * s, PI**2 / 2 * c, -(PI**3) / 2 * s


@builtin
class Polynomial345(_PolynomialLaw):
    """3-4-5 polynomial rise: y' = y'' = 0 at both ends.

    .. math:: y = 10 x^3 - 15 x^4 + 6 x^5

    Peaks: y' = 15/8, y'' = 10/√3, y''' = 60.

    References
    ----------
    Rothbart (2004) Cam Design Handbook ch. 3; Norton (2009) Cam Design and Manufacturing Handbook.
    """

    name = "polynomial_345"
    reference = HANDBOOKS + " (3-4-5 polynomial)"
    coefficients = (0.0, 0.0, 0.0, 10.0, -15.0, 6.0)


@builtin
class Polynomial4567(_PolynomialLaw):
    """4-5-6-7 polynomial rise: y' = y'' = y''' = 0 at both ends (continuous jerk with dwells).

    .. math:: y = 35 x^4 - 84 x^5 + 70 x^6 - 20 x^7

    Peaks: y' = 35/16, y'' = 7.513, y''' = 52.5.

    References
    ----------
    Rothbart (2004) Cam Design Handbook ch. 3; Norton (2009) Cam Design and Manufacturing Handbook.
    """

    name = "polynomial_4567"
    reference = HANDBOOKS + " (4-5-6-7 polynomial)"
    coefficients = (0.0, 0.0, 0.0, 0.0, 35.0, -84.0, 70.0, -20.0)


@builtin
class ModifiedTrapezoid(_SineRampLaw):
    """Modified trapezoid rise: constant acceleration joined by cycloidal-jerk (sine) ramps of 1/8.

    .. math::
        \\frac{y''}{C_a} = \\begin{cases}
            \\sin 4\\pi x & 0 \\le x < 1/8 \\\\
            1 & 1/8 \\le x < 3/8 \\\\
            \\cos 4\\pi (x - 3/8) & 3/8 \\le x < 5/8 \\\\
            -1 & 5/8 \\le x < 7/8 \\\\
            -\\cos 4\\pi (x - 7/8) & 7/8 \\le x \\le 1
        \\end{cases}, \\qquad C_a = \\frac{8\\pi}{\\pi + 2} = 4.8881

    y' and y are its exact integrals from y(0) = y'(0) = 0. Peaks: y' = 2, y'' = 4.888,
    y''' = 4π C_a = 61.43.

    References
    ----------
    Rothbart (2004) Cam Design Handbook ch. 3 (modified trapezoidal curve); Norton (2009) Cam
    Design and Manufacturing Handbook (modified trapezoid). Not in Tsuha (2015).
    """

    name = "modified_trapezoid"
    reference = HANDBOOKS + " (modified trapezoid)"
    pieces = (
        (0.0, 1 / 8, 0.0, 1.0, 0.0, 4 * PI),
        (1 / 8, 3 / 8, 1.0, 0.0, 0.0, 4 * PI),
        (3 / 8, 5 / 8, 0.0, 0.0, 1.0, 4 * PI),
        (5 / 8, 7 / 8, -1.0, 0.0, 0.0, 4 * PI),
        (7 / 8, 1.0, 0.0, 0.0, -1.0, 4 * PI),
    )


@builtin
class ModifiedSine(_SineRampLaw):
    """Modified sine rise: quarter sine waves of period 1/2 at the ends, half cosine of period 3/2 between.

    .. math::
        \\frac{y''}{C_a} = \\begin{cases}
            \\sin 4\\pi x & 0 \\le x < 1/8 \\\\
            \\cos \\tfrac{4\\pi}{3} (x - 1/8) & 1/8 \\le x < 7/8 \\\\
            -\\cos 4\\pi (x - 7/8) & 7/8 \\le x \\le 1
        \\end{cases}, \\qquad C_a = \\frac{4\\pi^2}{\\pi + 4} = 5.5280

    y' and y are its exact integrals from y(0) = y'(0) = 0. Peaks: y' = 4π/(π + 4) = 1.760,
    y'' = 5.528, y''' = 4π C_a = 69.47.

    References
    ----------
    Rothbart (2004) Cam Design Handbook ch. 3 (modified sine curve); Norton (2009) Cam Design
    and Manufacturing Handbook (modified sine). Not in Tsuha (2015).
    """

    name = "modified_sine"
    reference = HANDBOOKS + " (modified sine)"
    pieces = (
        (0.0, 1 / 8, 0.0, 1.0, 0.0, 4 * PI),
        (1 / 8, 7 / 8, 0.0, 0.0, 1.0, 4 * PI / 3),
        (7 / 8, 1.0, 0.0, 0.0, -1.0, 4 * PI),
    )


# ----------------------------------------------------------------- Mabie & Reinholtz series
@builtin
class C1(_Law):
    """C-1, half-cycloid rise starting from a dwell (y' = 0 at x = 0, y' = 2 at x = 1).

    .. math:: y = x - \\frac{\\sin \\pi x}{\\pi}, \\quad y' = 1 - \\cos \\pi x, \\quad
        y'' = \\pi \\sin \\pi x, \\quad y''' = \\pi^2 \\cos \\pi x

    The C/H name-to-formula assignment is recalled from Mabie & Reinholtz (1987) by the
    Tsuha (2015) reference (§2.1), not checked against the book.

    References
    ----------
    Mabie & Reinholtz (1987) Mechanisms and Dynamics of Machinery; Tsuha (2015) reference §2.1 table.
    """

    name = "C-1"
    reference = MABIE + ": C-1 = x - sin(pi x)/pi"

    @classmethod
    def _shape(cls, x):
        s, c = np.sin(PI * x), np.cos(PI * x)
        return x - s / PI, 1.0 - c, PI * s, PI**2 * c


@builtin
class C2(_Law):
    """C-2, half-cycloid rise ending at a dwell (y' = 2 at x = 0, y' = 0 at x = 1).

    .. math:: y = x + \\frac{\\sin \\pi x}{\\pi}, \\quad y' = 1 + \\cos \\pi x, \\quad
        y'' = -\\pi \\sin \\pi x, \\quad y''' = -\\pi^2 \\cos \\pi x

    The C/H name-to-formula assignment is recalled from Mabie & Reinholtz (1987) by the
    Tsuha (2015) reference (§2.1), not checked against the book.

    References
    ----------
    Mabie & Reinholtz (1987) Mechanisms and Dynamics of Machinery; Tsuha (2015) reference §2.1 table.
    """

    name = "C-2"
    reference = MABIE + ": C-2 = x + sin(pi x)/pi"

    @classmethod
    def _shape(cls, x):
        s, c = np.sin(PI * x), np.cos(PI * x)
        return x + s / PI, 1.0 + c, -PI * s, -(PI**2) * c


@builtin
class C3(_Reversed):
    """C-3, half-cycloid return starting from a dwell; C-2 run backwards.

    .. math:: y = 1 - x + \\frac{\\sin \\pi x}{\\pi} = y_{C2}(1 - x)

    The C/H name-to-formula assignment is recalled from Mabie & Reinholtz (1987) by the
    Tsuha (2015) reference (§2.1), not checked against the book.

    References
    ----------
    Mabie & Reinholtz (1987) Mechanisms and Dynamics of Machinery; Tsuha (2015) reference §2.1 table.
    """

    name = "C-3"
    reference = MABIE + ": C-3 = 1 - x + sin(pi x)/pi"
    forward = C2


@builtin
class C4(_Reversed):
    """C-4, half-cycloid return ending at a dwell; C-1 run backwards.

    .. math:: y = 1 - x - \\frac{\\sin \\pi x}{\\pi} = y_{C1}(1 - x)

    The C/H name-to-formula assignment is recalled from Mabie & Reinholtz (1987) by the
    Tsuha (2015) reference (§2.1), not checked against the book.

    References
    ----------
    Mabie & Reinholtz (1987) Mechanisms and Dynamics of Machinery; Tsuha (2015) reference §2.1 table.
    """

    name = "C-4"
    reference = MABIE + ": C-4 = 1 - x - sin(pi x)/pi"
    forward = C1


@builtin
class C5(Cycloidal):
    """C-5, full cycloidal rise (the ``cycloidal`` law).

    .. math:: y = x - \\frac{\\sin 2\\pi x}{2\\pi}

    The C/H name-to-formula assignment is recalled from Mabie & Reinholtz (1987) by the
    Tsuha (2015) reference (§2.1), not checked against the book.

    References
    ----------
    Mabie & Reinholtz (1987) Mechanisms and Dynamics of Machinery; Tsuha (2015) reference §2.1 table.
    """

    name = "C-5"
    reference = MABIE + ": C-5 = x - sin(2 pi x)/(2 pi)"


@builtin
class C6(_Reversed):
    """C-6, full cycloidal return; C-5 run backwards.

    .. math:: y = 1 - x + \\frac{\\sin 2\\pi x}{2\\pi} = y_{C5}(1 - x)

    The C/H name-to-formula assignment is recalled from Mabie & Reinholtz (1987) by the
    Tsuha (2015) reference (§2.1), not checked against the book.

    References
    ----------
    Mabie & Reinholtz (1987) Mechanisms and Dynamics of Machinery; Tsuha (2015) reference §2.1 table.
    """

    name = "C-6"
    reference = MABIE + ": C-6 = 1 - x + sin(2 pi x)/(2 pi)"
    forward = Cycloidal


@builtin
class H1(_Law):
    """H-1, half-harmonic rise starting from a dwell (y' = 0 at x = 0, y' = π/2 at x = 1).

    .. math:: y = 1 - \\cos \\tfrac{\\pi x}{2}, \\quad y' = \\tfrac{\\pi}{2} \\sin \\tfrac{\\pi x}{2}, \\quad
        y'' = \\tfrac{\\pi^2}{4} \\cos \\tfrac{\\pi x}{2}, \\quad y''' = -\\tfrac{\\pi^3}{8} \\sin \\tfrac{\\pi x}{2}

    The C/H name-to-formula assignment is recalled from Mabie & Reinholtz (1987) by the
    Tsuha (2015) reference (§2.1), not checked against the book.

    References
    ----------
    Mabie & Reinholtz (1987) Mechanisms and Dynamics of Machinery; Tsuha (2015) reference §2.1 table.
    """

    name = "H-1"
    reference = MABIE + ": H-1 = 1 - cos(pi x/2)"

    @classmethod
    def _shape(cls, x):
        s, c = np.sin(PI * x / 2), np.cos(PI * x / 2)
        return 1.0 - c, PI / 2 * s, PI**2 / 4 * c, -(PI**3) / 8 * s


@builtin
class H2(_Law):
    """H-2, half-harmonic rise ending at a dwell (y' = π/2 at x = 0, y' = 0 at x = 1).

    .. math:: y = \\sin \\tfrac{\\pi x}{2}, \\quad y' = \\tfrac{\\pi}{2} \\cos \\tfrac{\\pi x}{2}, \\quad
        y'' = -\\tfrac{\\pi^2}{4} \\sin \\tfrac{\\pi x}{2}, \\quad y''' = -\\tfrac{\\pi^3}{8} \\cos \\tfrac{\\pi x}{2}

    The C/H name-to-formula assignment is recalled from Mabie & Reinholtz (1987) by the
    Tsuha (2015) reference (§2.1), not checked against the book.

    References
    ----------
    Mabie & Reinholtz (1987) Mechanisms and Dynamics of Machinery; Tsuha (2015) reference §2.1 table.
    """

    name = "H-2"
    reference = MABIE + ": H-2 = sin(pi x/2)"

    @classmethod
    def _shape(cls, x):
        s, c = np.sin(PI * x / 2), np.cos(PI * x / 2)
        return s, PI / 2 * c, -(PI**2) / 4 * s, -(PI**3) / 8 * c


@builtin
class H3(_Reversed):
    """H-3, half-harmonic return starting from a dwell; H-2 run backwards.

    .. math:: y = \\cos \\tfrac{\\pi x}{2} = y_{H2}(1 - x)

    The C/H name-to-formula assignment is recalled from Mabie & Reinholtz (1987) by the
    Tsuha (2015) reference (§2.1), not checked against the book.

    References
    ----------
    Mabie & Reinholtz (1987) Mechanisms and Dynamics of Machinery; Tsuha (2015) reference §2.1 table.
    """

    name = "H-3"
    reference = MABIE + ": H-3 = cos(pi x/2)"
    forward = H2


@builtin
class H4(_Reversed):
    """H-4, half-harmonic return ending at a dwell; H-1 run backwards.

    .. math:: y = 1 - \\sin \\tfrac{\\pi x}{2} = y_{H1}(1 - x)

    The C/H name-to-formula assignment is recalled from Mabie & Reinholtz (1987) by the
    Tsuha (2015) reference (§2.1), not checked against the book.

    References
    ----------
    Mabie & Reinholtz (1987) Mechanisms and Dynamics of Machinery; Tsuha (2015) reference §2.1 table.
    """

    name = "H-4"
    reference = MABIE + ": H-4 = 1 - sin(pi x/2)"
    forward = H1


@builtin
class H5(Harmonic):
    """H-5, full harmonic rise (the ``harmonic`` law).

    .. math:: y = \\tfrac12 (1 - \\cos \\pi x)

    The C/H name-to-formula assignment is recalled from Mabie & Reinholtz (1987) by the
    Tsuha (2015) reference (§2.1), not checked against the book.

    References
    ----------
    Mabie & Reinholtz (1987) Mechanisms and Dynamics of Machinery; Tsuha (2015) reference §2.1 table.
    """

    name = "H-5"
    reference = MABIE + ": H-5 = (1 - cos(pi x))/2"


@builtin
class H6(_Reversed):
    """H-6, full harmonic return; H-5 run backwards.

    .. math:: y = \\tfrac12 (1 + \\cos \\pi x) = y_{H5}(1 - x)

    The C/H name-to-formula assignment is recalled from Mabie & Reinholtz (1987) by the
    Tsuha (2015) reference (§2.1), not checked against the book.

    References
    ----------
    Mabie & Reinholtz (1987) Mechanisms and Dynamics of Machinery; Tsuha (2015) reference §2.1 table.
    """

    name = "H-6"
    reference = MABIE + ": H-6 = (1 + cos(pi x))/2"
    forward = Harmonic


@builtin
class P1(_PolynomialLaw):
    """P-1, eighth-degree polynomial rise: y' = y'' = 0 at x = 0; y' = y''' = 0, y'' = −5.268 at x = 1.

    .. math:: y = 6.09755 x^3 - 20.78040 x^5 + 26.73155 x^6 - 13.60965 x^7 + 2.56095 x^8

    The rise of the Tsuha (2015) chapter-6 cams (0–90°, with P-2 over 90–180°), established
    by exact reproduction of the thesis tables (reference §0 item 1).

    References
    ----------
    Rothbart (2004) Cam Design Handbook p. 112; Mabie & Reinholtz (1987); Tsuha (2015)
    reference §0 item 1 and §2.1 table.
    """

    name = "P-1"
    reference = "Rothbart (2004) Cam Design Handbook p. 112; Mabie & Reinholtz (1987); Tsuha (2015) reference §0 item 1, §2.1"
    coefficients = (0.0, 0.0, 0.0, 6.09755, 0.0, -20.78040, 26.73155, -13.60965, 2.56095)


@builtin
class P2(_Reversed):
    """P-2, eighth-degree polynomial return: P-1 run backwards.

    .. math:: y = y_{P1}(1 - x) = 1 - 2.63415 x^2 + 2.78055 x^5 + 3.17060 x^6 - 6.87795 x^7 + 2.56095 x^8

    (the expanded coefficients are those printed in the reference, rounded to 5 decimals;
    the law is computed as P-1(1 − x)).

    References
    ----------
    Rothbart (2004) Cam Design Handbook p. 112; Mabie & Reinholtz (1987); Tsuha (2015)
    reference §0 item 1 and §2.1 table.
    """

    name = "P-2"
    reference = "Rothbart (2004) Cam Design Handbook p. 112; Mabie & Reinholtz (1987); Tsuha (2015) reference §0 item 1, §2.1"
    forward = P1
