"""The computational domain of a steady line contact: an inlet long enough for a flooded film.

A flooded contact takes its lubricant from an inlet of unbounded length; the solver's domain [X_a, X_b] (units of
the Hertz half-width b) cuts it at X_a, which starves the film a little: the pressure the inlet would have built
upstream of X_a is missing. Ertel and Grubin's inlet analysis (Grubin 1949) says how much. The reduced pressure
q = (1 - exp(-alpha p))/alpha builds up in the inlet as dq/dx = 12 eta0 u_m (h - h_e)/h^3 and reaches about 1/alpha
at the Hertz inlet edge; with h = h_e + g(x) and g the gap outside the Hertz contact, the part of that integral
upstream of X_a,

.. math::
    T(X_a) = \\int_{-\\infty}^{X_a} \\frac{g}{(H + g)^3}\\,dX \\Big/ \\int_{-\\infty}^{-1} \\frac{g}{(H + g)^3}\\,dX,

(H = h_c R/b^2, g(X) = (|X|\\sqrt{X^2 - 1} - \\mathrm{arccosh}|X|)/2 for an elastic contact, X^2/2 for a rigid one)
is what the cut removes. Measured against solutions with the inlet at -20.5 b at the same spacing, the central
film is thin by 0.72-0.87 T over H = 0.03-1.3 and inlets of 4 and 9.5 b (M 2-50, L 5-23 and the 200 kN/m roller at
0.5-20 m/s): 0.26 % at H = 0.077 and 7.1 % at H = 1.0 with the inlet at -4 b, 1.2 % on the LS-1 roller cam's
thickest films with the earlier rule X_a = -4 sqrt(2 H). :func:`automatic_domain` lengthens the inlet until
T <= :data:`INLET_TAIL`, so that the cut costs the film about 0.25 %.

The longer domain has the same number of nodes at a given level, so its grid is coarser; for the thick films that
need it the pressure has no sharp spike and the discretisation error stays the smaller effect (module
:mod:`camcontact.models.film_multigrid`).

References
----------
Grubin, A.N. (1949) Fundamentals of the hydrodynamic theory of lubrication of heavily loaded cylindrical surfaces,
Central Scientific Research Institute for Technology and Mechanical Engineering, Book 30, Moscow (DSIR translation
337); as given by Dowson & Higginson (1977) Elasto-Hydrodynamic Lubrication, ch. 5.
"""

from __future__ import annotations

import functools
import math

import numpy as np
from scipy.integrate import quad

from ..errors import InputError
from .film_formulas import moes_line_film

__all__ = ["DOMAIN_RATIO", "INLET_TAIL", "THIN_FILM", "automatic_domain", "inlet_tail_fraction"]

#: the automatic domain's reaches are rounded up to powers of this ratio (see :func:`automatic_domain`)
DOMAIN_RATIO = 2.0 ** 0.25

#: the part T of the Grubin inlet integral the automatic domain may leave upstream of X_a (film about 0.8 T thin)
INLET_TAIL = 3e-3

#: films (H, Hertz units) up to which the inlet at -4 b leaves less than 1e-3 of the integral (T grows with H: 9e-4
#: at H = 0.03), so that :func:`automatic_domain` need not evaluate it: near-zero films (a cam's instants around
#: u_m = 0, H 1e-11) peak within 1e-7 b of the Hertz edge, where the quadrature reports round-off
THIN_FILM = 0.03


def _gap(X: float, elastic: bool) -> float:
    """Gap outside the contact [b^2/R] at X [b] beyond the central film: Hertz (elastic) or the rigid parabola."""
    if not elastic:
        return 0.5 * X * X
    X = abs(X)
    if X <= 1.0:
        return 0.0
    return 0.5 * (X * math.sqrt(X * X - 1.0) - math.acosh(X))


def inlet_tail_fraction(X_a: float, H: float, elastic: bool = True) -> float:
    """T(X_a): the part of Grubin's inlet integral int g/(H + g)^3 dX upstream of X_a [-] (module docstring).

    X_a <= -1 in units of b; H > 0 the central film in units of b^2/R."""
    if X_a > -1.0 or not H > 0.0:
        raise InputError(f"inlet_tail_fraction: needs X_a <= -1 and H > 0, got X_a = {X_a!r}, H = {H!r}")

    def integrand(X):
        g = _gap(X, elastic)
        return g / (H + g) ** 3

    # upstream of X_a by X = X_a/t, t in (0, 1]: the integrand ~ 4/X^4 becomes ~ t^2 (no infinite range to sample)
    upstream = quad(lambda t: integrand(X_a / t) * -X_a / (t * t) if t > 0.0 else 0.0, 0.0, 1.0, limit=200)[0]
    # the integrand peaks where g ~ H (close to the edge for thin films): split there for the quadrature
    edge = -1.0 - min(1.0, 2.0 * H ** (2.0 / 3.0)) if elastic else -math.sqrt(2.0 * H)
    if X_a < edge:
        inlet = quad(integrand, X_a, edge, limit=200)[0] + quad(integrand, edge, -1.0 if elastic else 0.0,
                                                                 limit=200)[0]
    else:
        inlet = quad(integrand, X_a, -1.0 if elastic else 0.0, limit=200)[0]
    return upstream / (upstream + inlet)


@functools.lru_cache(maxsize=4096)
def automatic_domain(M: float, L: float, elastic: bool = True,
                     inlet_tail: float | None = INLET_TAIL) -> tuple[float, float]:
    """Computational domain [X_a, X_b] (units of b): [-4, 1.5] unless the film is thick.

    With H the Moes film (Hertz units), X_a = -4 r_in and X_b = 1.5 r, both reaches powers of
    :data:`DOMAIN_RATIO`: r the smallest at least max(1, sqrt(2 H)) (near-rigid contacts build pressure over a
    length that scales with sqrt(2 H) rather than with b), r_in the smallest at least r with Grubin's inlet tail
    :func:`inlet_tail_fraction`(-4 r_in) <= :data:`INLET_TAIL` (module docstring: the cut then costs the central
    film about 0.25 %). Thin films (H below about 0.08) keep [-4, 1.5]. ``inlet_tail`` None: r_in = r, the
    earlier rule.

    The rounding lets neighbouring contacts (the angles of a cam cycle) share their domain, so a warm
    start from the neighbour's solution starts on the same grid and two neighbours' solutions extrapolate node
    by node (:func:`camcontact.ehl.line_multigrid.extrapolated_start`), and the solves share their grid tables.
    """
    if inlet_tail is not None and not 0.0 < inlet_tail < 1.0:
        raise InputError(f"automatic_domain: inlet_tail = {inlet_tail!r}; allowed: None or 0 < inlet_tail < 1")
    H = float(moes_line_film(M, L, elasticity=elastic)) * math.pi / (8.0 * M)
    reach = math.sqrt(2.0 * H)
    if reach > 1.0:
        reach = DOMAIN_RATIO ** math.ceil(math.log(reach) / math.log(DOMAIN_RATIO) - 1e-9)
    reach = max(reach, 1.0)
    inlet = reach
    if inlet_tail is not None and (H > THIN_FILM or inlet_tail < 1e-3):
        while inlet_tail_fraction(-4.0 * inlet, H, elastic) > inlet_tail:
            inlet *= DOMAIN_RATIO
    return (-4.0 * inlet, 1.5 * reach)
