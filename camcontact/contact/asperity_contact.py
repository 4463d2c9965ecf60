"""Greenwood–Tripp contact of two rough surfaces: the Gaussian integrals F_n, asperity pressure, real area.

Two nominally flat rough surfaces whose mean planes are a distance ``h`` apart, with Gaussian
surface heights of composite RMS roughness sigma (sigma^2 = sigma_1^2 + sigma_2^2), an areal
asperity density eta and an asperity tip radius beta, carry by elastic (Hertzian) asperity contact
a mean pressure and touch over a real-area fraction (Greenwood & Tripp 1970–71, Eqs. for P and A):

.. math::
    p_a = K\\,E^*\\,F_{5/2}(h/\\sigma), \\qquad
    K = \\frac{16\\sqrt{2}}{15}\\,\\pi\\,(\\eta\\beta\\sigma)^2\\sqrt{\\sigma/\\beta}, \\qquad
    \\frac{A_r}{A} = \\pi^2 (\\eta\\beta\\sigma)^2\\,F_2(h/\\sigma)

with the Gaussian integrals

.. math:: F_n(\\lambda) = \\frac{1}{\\sqrt{2\\pi}} \\int_\\lambda^\\infty (s - \\lambda)^n e^{-s^2/2}\\,ds .

Modulus convention
------------------
The modulus in the Greenwood–Tripp pressure is the Hertz contact modulus of the asperity pairs,
E* with 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Johnson's E*; Greenwood & Williamson 1966 and
Greenwood & Tripp call it E'). The coefficient 16 sqrt(2) pi / 15 follows from summing Hertz loads
(4/3) E* (beta/2)^(1/2) delta^(3/2) of asperity pairs of tip radius beta over their lateral offsets
(derivation in :func:`greenwood_tripp_coefficient`), so it belongs to E*, not to Hamrock's
E' = 2 E*. camcontact's ``E_reduced`` is Hamrock's E' (:mod:`camcontact.ehl.groups`); the
functions here take ``E_reduced`` and use E* = E_reduced / 2 inside. Implementations that put
Hamrock's E' into the formula overstate the asperity pressure by a factor 2.

Evaluating F_n
--------------
F_n(lambda) = Gamma(n+1) e^{-lambda^2/4} D_{-n-1}(lambda) / sqrt(2 pi) with D the parabolic
cylinder function (DLMF 12.5.1, with U(a, z) = D_{-a-1/2}(z)). Evaluated as

* lambda < 3, n = 0, 1, 2: closed forms F_0 = erfc(lambda/sqrt 2)/2, F_1 = phi(lambda) -
  lambda F_0, F_2 = (1 + lambda^2) F_0 - lambda phi(lambda), phi the standard normal density;
* lambda < 3, other n: ``scipy.special.pbdv`` (D_{-n-1}); for half-integer n this equals the
  Bessel closed forms (w = lambda^2/4, lambda > 0; from DLMF 12.7.10
  D_{-1/2}(z) = sqrt(z/(2 pi)) K_{1/4}(w), DLMF 12.8.2 and the recurrence DLMF 12.8.1)

  .. math::
      F_{3/2}(\\lambda) = \\frac{e^{-w}}{4\\sqrt{\\pi}}\\,\\lambda^{1/2}
          \\left[(1 + \\lambda^2) K_{1/4}(w) - \\lambda^2 K_{3/4}(w)\\right], \\quad
      F_{5/2}(\\lambda) = \\frac{e^{-w}}{8\\sqrt{\\pi}}\\,\\lambda^{3/2}
          \\left[(2\\lambda^2 + 3) K_{3/4}(w) - (2\\lambda^2 + 5) K_{1/4}(w)\\right],

  which the tests use as an independent check;
* lambda >= 3, any n: F_n = phi(lambda) lambda^{-n-1} int_0^inf u^n e^{-u} exp(-u^2/(2 lambda^2)) du
  by 40-point generalized Gauss–Laguerre quadrature (no cancellation in the tail, where the
  erfc forms lose digits);
* lambda < -30 (more than 30 sigma of interference, outside any physical use), non-integer n:
  the asymptotic series E[(X - lambda)^n] = sum_k C(n, 2k) (2k-1)!! (-lambda)^(n-2k).

Against adaptive quadrature (scipy.integrate.quad, rel. tol. 1e-13) the result agrees to about
1e-10 relative for lambda in [-8, 12] and about 1e-12 for lambda >= 0. For lambda > 38.5 the integrals are below the smallest
normal double and are returned as 0 (also for lambda = +inf).

References
----------
Greenwood, J.A. & Tripp, J.H. (1970–71) The contact of two nominally flat rough surfaces,
Proc. Instn Mech. Engrs 185:625–633 (asperity pressure and real area, two rough surfaces).
Greenwood, J.A. & Williamson, J.B.P. (1966) Contact of nominally flat surfaces, Proc. R. Soc.
Lond. A 295:300–319 (the F_n integrals, E' = Johnson's E*).
NIST Digital Library of Mathematical Functions (DLMF), §12.5, §12.7, §12.8 (parabolic cylinder
functions).
"""

from __future__ import annotations

import functools
import math

import numpy as np
from scipy import special

from ..errors import InputError

__all__ = [
    "ROUGHNESS_VALIDITY",
    "asperity_load_per_area",
    "asperity_pressure",
    "greenwood_tripp_coefficient",
    "greenwood_tripp_integral",
    "real_contact_area_fraction",
]

#: Ranges of the Greenwood–Tripp surface groups, as data for validity flags. The project reference
#: (../shared/reference/friction_traction_thermal.md §2) quotes eta*beta*sigma ~ 0.03–0.05 and
#: sigma/beta ~ 1e-4–1e-3, values typical of conformal contacts (piston rings, MPa); under a Hertz
#: pressure of a GPa the asperities only carry the load at h >= 0 with sigma/beta of order 1e-2
#: (small measured summit radii). The bounds below bracket both and are this module's convention,
#: not a published range. Values outside are accepted (no error).
ROUGHNESS_VALIDITY = {"eta_beta_sigma": (0.01, 0.1), "sigma_over_beta": (1e-5, 0.1)}

_UNDERFLOW_LAMBDA = 38.5  # F_n(lambda) < 1e-308 beyond this for every n used here
_ASYMPTOTIC_LAMBDA = -30.0  # below: the asymptotic series (pbdv overflows near -37)
_LAGUERRE_LAMBDA = 3.0  # at and above: generalized Gauss-Laguerre quadrature
_LAGUERRE_POINTS = 40
_SQRT_2PI = math.sqrt(2.0 * math.pi)


def _as_float_array(name: str, value) -> np.ndarray:
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{name} = {value!r} is not a number or an array of numbers") from exc
    return array


def _check_positive(function: str, **values) -> dict[str, np.ndarray]:
    checked = {}
    for name, value in values.items():
        array = _as_float_array(f"{function}: {name}", value)
        if not np.all(np.isfinite(array)) or np.any(array <= 0.0):
            raise InputError(f"{function}: {name} = {value!r}; allowed: finite and > 0")
        checked[name] = array
    return checked


def _result(array: np.ndarray):
    return float(array) if array.ndim == 0 else array


def _integer_order(n: int, lam: np.ndarray) -> np.ndarray:
    """F_0, F_1, F_2 in closed form (erfc and the normal density)."""
    f0 = 0.5 * special.erfc(lam / math.sqrt(2.0))
    if n == 0:
        return f0
    phi = np.exp(-0.5 * lam * lam) / _SQRT_2PI
    if n == 1:
        return phi - lam * f0
    return (1.0 + lam * lam) * f0 - lam * phi


@functools.lru_cache(maxsize=32)
def _laguerre_rule(n: float) -> tuple[np.ndarray, np.ndarray]:
    """Generalized Gauss–Laguerre nodes and weights for the weight u^n e^{-u} (40 points)."""
    return special.roots_genlaguerre(_LAGUERRE_POINTS, n)


def _gauss_laguerre(n: float, lam: np.ndarray) -> np.ndarray:
    """F_n = phi(lam) lam^{-n-1} int_0^inf u^n e^{-u} exp(-u^2 / (2 lam^2)) du for lam >= 3.

    (substitution u = lam t in F_n = phi(lam) int t^n e^{-lam t - t^2/2} dt); the factor
    exp(-u^2/(2 lam^2)) is smooth on the scale of the rule, which reaches ~1e-14 relative.
    """
    nodes, weights = _laguerre_rule(n)
    with np.errstate(under="ignore"):
        phi = np.exp(-0.5 * lam * lam) / _SQRT_2PI
        smooth = np.exp(-np.square(nodes[None, :] / lam[:, None]) * 0.5) @ weights
        return phi * lam ** (-n - 1.0) * smooth


def _parabolic_cylinder(n: float, lam: np.ndarray) -> np.ndarray:
    d, _ = special.pbdv(-n - 1.0, lam)
    with np.errstate(under="ignore"):
        return special.gamma(n + 1.0) / _SQRT_2PI * np.exp(-0.25 * lam * lam) * d


def _asymptotic_negative(n: float, lam: np.ndarray, terms: int = 12) -> np.ndarray:
    """E[(X - lam)^n] for lam << 0 (P(X < lam) ~ 1e-197 at lam = -30 is neglected)."""
    c = -lam
    total = np.zeros_like(c)
    for k in range(terms):
        double_factorial = 2.0**k * special.gamma(k + 0.5) / math.sqrt(math.pi)  # (2k-1)!!
        coefficient = special.binom(n, 2 * k) * double_factorial
        if coefficient == 0.0:
            break
        total = total + coefficient * c ** (n - 2 * k)
    return total


def _single_order(n: float, lam: np.ndarray) -> np.ndarray:
    out = np.zeros_like(lam)
    tail = (lam >= _LAGUERRE_LAMBDA) & (lam < _UNDERFLOW_LAMBDA)  # +inf and beyond stay 0
    out[tail] = _gauss_laguerre(n, lam[tail])
    body = lam < _LAGUERRE_LAMBDA
    if n in (0.0, 1.0, 2.0):
        out[body] = _integer_order(int(n), lam[body])
        return out
    far_inside = lam < _ASYMPTOTIC_LAMBDA
    out[far_inside] = _asymptotic_negative(n, lam[far_inside])
    middle = body & ~far_inside
    out[middle] = _parabolic_cylinder(n, lam[middle])
    return out


def greenwood_tripp_integral(n, lam):
    """Gaussian integral F_n(lambda) of Greenwood & Williamson / Greenwood & Tripp [-].

    .. math:: F_n(\\lambda) = \\frac{1}{\\sqrt{2\\pi}} \\int_\\lambda^\\infty (s - \\lambda)^n e^{-s^2/2}\\,ds
              = \\frac{\\Gamma(n+1)}{\\sqrt{2\\pi}}\\,e^{-\\lambda^2/4}\\,D_{-n-1}(\\lambda)

    Parameters
    ----------
    n : float or array_like
        Order, n > -1 (Greenwood–Williamson: 0 number of contacts, 1 area, 3/2 load;
        Greenwood–Tripp: 2 area, 5/2 load; n = -1/2 appears in dF_(1/2)/dlambda).
    lam : float or array_like
        Dimensionless separation lambda = h/sigma [-]; any real value, +inf gives 0. Broadcast
        against ``n``.

    Returns
    -------
    float or ndarray
        F_n(lambda) [-], finite and >= 0 (0 for lambda > 38.5, where it underflows).

    Raises
    ------
    InputError
        n negative or not finite; lambda NaN or -inf.

    References
    ----------
    Greenwood & Williamson (1966) Proc. R. Soc. A 295:300, Eqs. for F_n; Greenwood & Tripp
    (1970–71) Proc. IMechE 185:625; DLMF §12 (see the module docstring for the closed forms).
    """
    n_array = _as_float_array("greenwood_tripp_integral: n", n)
    lam_array = _as_float_array("greenwood_tripp_integral: lam", lam)
    if not np.all(np.isfinite(n_array)) or np.any(n_array <= -1.0):
        raise InputError(f"greenwood_tripp_integral: n = {n!r}; allowed: finite and > -1 (the integral diverges at n <= -1)")
    if np.any(np.isnan(lam_array)) or np.any(lam_array == -np.inf):
        raise InputError(f"greenwood_tripp_integral: lam = {lam!r}; allowed: real numbers or +inf (not NaN, -inf)")
    n_b, lam_b = np.broadcast_arrays(n_array, lam_array)
    out = np.empty(lam_b.shape, dtype=float)
    for order in np.unique(n_b):
        mask = n_b == order
        out[mask] = _single_order(float(order), np.asarray(lam_b[mask], dtype=float))
    return _result(out)


def greenwood_tripp_coefficient(sigma, asperity_density, asperity_radius):
    """Greenwood–Tripp load coefficient K = (16 sqrt2 / 15) pi (eta beta sigma)^2 sqrt(sigma/beta) [-].

    Derivation (why it goes with Johnson's E*): asperity pairs of tip radius beta each, heights
    summing to z (variance sigma^2 = composite), lateral offset r, overlap
    delta = z - h - r^2/(4 beta); a pair carries (4/3) E* (beta/2)^{1/2} delta^{3/2}. With eta^2
    2 pi r dr pairs per unit area and offset, the r-integral gives (8 pi / 5) beta delta^{5/2}, so
    p = (4/3)(8 pi/5) eta^2 beta^{3/2} 2^{-1/2} E* sigma^{5/2} F_{5/2} = K E* F_{5/2}.

    Parameters
    ----------
    sigma : float or array_like
        Composite RMS roughness sqrt(sigma_1^2 + sigma_2^2) [m], > 0.
    asperity_density : float or array_like
        Areal asperity density eta [1/m^2], > 0.
    asperity_radius : float or array_like
        Asperity tip radius beta [m], > 0.

    References
    ----------
    Greenwood & Tripp (1970–71) Proc. IMechE 185:625–633 (load of two rough surfaces).
    """
    values = _check_positive("greenwood_tripp_coefficient", sigma=sigma, asperity_density=asperity_density,
                             asperity_radius=asperity_radius)
    s, eta, beta = values["sigma"], values["asperity_density"], values["asperity_radius"]
    return _result(16.0 * math.sqrt(2.0) / 15.0 * math.pi * (eta * beta * s) ** 2 * np.sqrt(s / beta))


def asperity_pressure(separation, sigma, asperity_density, asperity_radius, E_reduced):
    """Mean asperity contact pressure p_a [Pa] of Greenwood & Tripp at mean-plane separation h.

    .. math:: p_a = K\\,E^*\\,F_{5/2}(h/\\sigma), \\qquad E^* = E'/2

    Parameters
    ----------
    separation : float or array_like
        Distance h between the mean planes of the two rough surfaces [m] (the film thickness of
        a lubricated contact); may be negative (deep contact), +inf gives 0.
    sigma : float or array_like
        Composite RMS roughness [m], > 0.
    asperity_density : float or array_like
        Areal asperity density eta [1/m^2], > 0.
    asperity_radius : float or array_like
        Asperity tip radius beta [m], > 0.
    E_reduced : float or array_like
        camcontact's reduced modulus, Hamrock's E' = 2/[(1-nu1^2)/E1 + (1-nu2^2)/E2] [Pa], > 0.
        Converted inside to the Hertz contact modulus E* = E'/2 that the formula uses.

    Returns
    -------
    float or ndarray
        p_a [Pa] (load carried by the asperities per unit nominal area).

    References
    ----------
    Greenwood & Tripp (1970–71) Proc. IMechE 185:625–633; modulus: see the module docstring.
    """
    values = _check_positive("asperity_pressure", E_reduced=E_reduced)
    lam = _separation_ratio("asperity_pressure", separation, sigma)
    K = greenwood_tripp_coefficient(sigma, asperity_density, asperity_radius)
    return _result(np.asarray(K * 0.5 * values["E_reduced"] * greenwood_tripp_integral(2.5, lam), dtype=float))


#: Alias: the asperity pressure is the asperity load per unit nominal area.
asperity_load_per_area = asperity_pressure


def real_contact_area_fraction(separation, sigma, asperity_density, asperity_radius):
    """Real (asperity) contact area over nominal area, A_r/A = pi^2 (eta beta sigma)^2 F_2(h/sigma) [-].

    Parameters as :func:`asperity_pressure` (no modulus: the Hertz contact radius of an asperity
    pair, a^2 = (beta/2) delta, does not depend on it). The elastic model is meaningful while
    the fraction is small (a few per cent); values are returned as computed, not capped at 1.

    References
    ----------
    Greenwood & Tripp (1970–71) Proc. IMechE 185:625–633 (real area of two rough surfaces).
    """
    lam = _separation_ratio("real_contact_area_fraction", separation, sigma)
    values = _check_positive("real_contact_area_fraction", asperity_density=asperity_density,
                             asperity_radius=asperity_radius)
    s = np.asarray(sigma, dtype=float)
    rough = values["asperity_density"] * values["asperity_radius"] * s
    return _result(np.asarray(math.pi**2 * rough**2 * greenwood_tripp_integral(2.0, lam), dtype=float))


def _separation_ratio(function: str, separation, sigma) -> np.ndarray:
    h = _as_float_array(f"{function}: separation", separation)
    if np.any(np.isnan(h)) or np.any(h == -np.inf):
        raise InputError(f"{function}: separation = {separation!r} m; allowed: real numbers or +inf")
    s = _check_positive(function, sigma=sigma)["sigma"]
    with np.errstate(invalid="ignore"):
        return h / s
