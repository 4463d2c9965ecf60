"""Mixed lubrication by load sharing: fluid film and Greenwood–Tripp asperities carry the load together.

Johnson, Greenwood & Poon (1972) split the load W of a lubricated rough contact between the
fluid film and the asperities,

.. math:: W = W_H + W_C, \\qquad W_H = W/\\gamma_1, \\qquad W_C = W/\\gamma_2, \\qquad
          \\frac{1}{\\gamma_1} + \\frac{1}{\\gamma_2} = 1 .

*Fluid part.* The fluid pressure is taken as 1/gamma_1 of the total with the total's (Hertzian)
shape, so the elastic deformation the whole pressure causes equals that of the fluid pressure on
bodies of modulus E'/gamma_1: the film is the smooth-surface central film evaluated with the load
W/gamma_1 *and* the modulus E'/gamma_1 (JGP 1972; Gelinck & Schipper 2000 with Moes's line
formula, Eqs. for H_c(gamma_1)). In Hamrock groups U -> gamma_1 U, G -> G/gamma_1, W' unchanged;
in Moes groups M -> M gamma_1^{-1/2}, L -> L gamma_1^{-3/4} (line; M -> M gamma_1^{-3/4} for
the point contact) and h = H R (2 gamma_1 U)^{1/2}. The smooth films are the project's Moes (line)
and Nijenbanning (point) formulas, called with (W/gamma_1, E'/gamma_1).

*Asperity part.* The asperity pressure is uniform over the Hertz contact of the *total* load
(the Hertz area of W/gamma_2 on modulus E'/gamma_2 is the same area) and follows Greenwood–Tripp
at the separation h = h_c (:mod:`camcontact.contact.asperity_contact`):
W_C = A_Hertz K E* F_{5/2}(h_c/sigma), E* = E'/2.

*Solution.* With a = 1/gamma_2 the asperity load fraction, the residual
a W - W_C(h_c(gamma_1(a))) increases monotonically with a (the film grows, or stays, as the fluid
is unloaded), so it has one root; it is found by bisection in s = logit(a), vectorised over all
operating points, to |ds| < 1e-12 (a from 1e-300 to 1 - 1e-26). Where the fluid share falls below
1e-26, or u_m = 0 (no entrainment), the asperities carry the whole load and h_c solves
W = A_Hertz p_a(h_c) alone.

*Asperity capacity.* The smooth film formulas give h_c > 0 for every gamma_1, so the asperities can
take at most C = A_Hertz p_a(h = 0)/W of the load (output ``asperity_capacity``). Only where C >= 1
does the model reach boundary lubrication (asperity fraction -> 1) as the speed falls; where C < 1
(soft or sparse asperities against a Hertz pressure of GPa: with eta beta sigma = 0.04 and
sigma/beta = 1e-3, p_a(0) is about 17 MPa for steel) the asperity fraction saturates at C while
h_c -> 0, and the fluid nominally carries the rest on a vanishing film: outside the model's
validity, to be flagged by the caller (``asperity_capacity < 1`` together with a small Lambda).
At u_m = 0 the result is this limit u_m -> 0+: fraction min(C, 1), h_c the asperity-only
separation when C >= 1, else 0.

*Friction.* mu = (mu_b W_C + F_fluid)/W = mu_b a + mu_fluid (1 - a) (Gelinck & Schipper 2000;
../shared/reference/friction_traction_thermal.md §2), with mu_b the boundary friction coefficient
of the asperity contacts and mu_fluid the traction coefficient of the fluid-carried load (an input:
the fluid traction model lives elsewhere).

*Regime.* From the specific film thickness Lambda = h_c/sigma of the mixed solution, with the
bands the project uses elsewhere (Cheng 1983, via :mod:`camcontact.contact.roughness`):
Lambda <= 1 boundary, 1 < Lambda < 3 mixed, Lambda >= 3 full film; in addition a contact whose
asperities carry at least ``BOUNDARY_ASPERITY_FRACTION`` = 0.95 of the load is "boundary" (fluid
share below 5 %), because under light loads the asperities alone can hold the surfaces more than
one sigma apart. The 0.95 is this module's convention, not a published constant.

Conventions: entrainment speed u_m = (u1 + u2)/2 [m/s] (its sign is ignored, as by the film
formulas); E_reduced = Hamrock's E' = 2/[(1-nu1^2)/E1 + (1-nu2^2)/E2] [Pa]; sigma the composite
RMS roughness [m]; asperity_density eta [1/m^2]; asperity_radius beta [m].

References
----------
Johnson, K.L., Greenwood, J.A. & Poon, S.Y. (1972) A simple theory of asperity contact in
elastohydrodynamic lubrication, Wear 19:91–108.
Gelinck, E.R.M. & Schipper, D.J. (2000) Calculation of Stribeck curves for line contacts,
Tribol. Int. 33:175–181.
Greenwood, J.A. & Tripp, J.H. (1970–71) The contact of two nominally flat rough surfaces,
Proc. Instn Mech. Engrs 185:625–633.
Moes, H. (1992) Wear 159:57–66; Nijenbanning, Venner & Moes (1994) Wear 176:217–229.
Cheng, H.S. (1983) in CRC Handbook of Lubrication vol. II (Lambda bands; as quoted by
Delabenetta 2021 §2.3).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping

import numpy as np
from scipy import special

from ..contact.asperity_contact import asperity_pressure, real_contact_area_fraction
from ..contact.hertz_elliptical import hertz_elliptical
from ..errors import InputError
from .film_line import Moes
from .film_point import Nijenbanning

__all__ = [
    "BOUNDARY_ASPERITY_FRACTION",
    "LAMBDA_BOUNDARY",
    "LAMBDA_FULL_FILM",
    "MIXED_REGIMES",
    "mixed_friction_coefficient",
    "mixed_line_contact",
    "mixed_point_contact",
    "mixed_regime",
    "stribeck_curve_line",
    "stribeck_curve_point",
]

#: Regime labels of :func:`mixed_regime`.
MIXED_REGIMES = ("boundary", "mixed", "full_film")
#: Lambda bands (Cheng 1983): Lambda <= 1 boundary, Lambda >= 3 full film.
LAMBDA_BOUNDARY = 1.0
LAMBDA_FULL_FILM = 3.0
#: Asperity load fraction from which a contact counts as boundary whatever its Lambda (convention).
BOUNDARY_ASPERITY_FRACTION = 0.95

_S_LOW, _S_HIGH = -700.0, 60.0  # logit of the asperity fraction: 1e-304 .. 1 - 9e-27
_BISECTIONS = 64
_LAMBDA_HIGH = 38.0  # separation / sigma above which the asperity pressure underflows to 0


def _array(function: str, name: str, value) -> np.ndarray:
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{function}: {name} = {value!r} is not a number or an array of numbers") from exc


def _positive(function: str, name: str, value, unit: str) -> np.ndarray:
    array = _array(function, name, value)
    if not np.all(np.isfinite(array)) or np.any(array <= 0.0):
        raise InputError(f"{function}: {name} = {value!r} {unit}; allowed: finite and > 0")
    return array


def _non_negative(function: str, name: str, value, unit: str) -> np.ndarray:
    array = _array(function, name, value)
    if not np.all(np.isfinite(array)) or np.any(array < 0.0):
        raise InputError(f"{function}: {name} = {value!r} {unit}; allowed: finite and >= 0")
    return array


def _finite(function: str, name: str, value, unit: str) -> np.ndarray:
    array = _array(function, name, value)
    if not np.all(np.isfinite(array)):
        raise InputError(f"{function}: {name} = {value!r} {unit}; allowed: finite")
    return array


def _out(value):
    array = np.asarray(value)
    if array.ndim == 0:
        return array.item()
    return array


def _solve_load_share(load, area, film_of_fluid_fraction, sigma, density, radius, E_reduced, moving):
    """Asperity load fraction a and central film h_c (arrays of the broadcast shape).

    ``film_of_fluid_fraction(mask, phi)`` returns the smooth central film of the points ``mask``
    evaluated with load phi W and modulus phi E' (phi = 1/gamma_1).
    """
    shape = load.shape

    def asperity_fraction_at(h, mask):
        return area[mask] * asperity_pressure(h, sigma[mask], density[mask], radius[mask], E_reduced[mask]) / load[mask]

    fraction = np.ones(shape)
    film = np.zeros(shape)
    share = moving.copy()
    if np.any(share):
        # full film: asperity share below ~1e-304 even at the smooth film
        h_smooth = film_of_fluid_fraction(share, np.ones(np.count_nonzero(share)))
        a_smooth = asperity_fraction_at(h_smooth, share)
        full = np.zeros(shape, dtype=bool)
        full[share] = a_smooth <= special.expit(_S_LOW)
        fraction[full] = a_smooth[full[share]]
        film[full] = h_smooth[full[share]]
        share &= ~full
    if np.any(share):
        # boundary: even a fluid share of 1e-26 leaves the asperity load above W
        s_high = np.full(np.count_nonzero(share), _S_HIGH)
        h_high = film_of_fluid_fraction(share, special.expit(-s_high))
        residual_high = special.expit(s_high) - asperity_fraction_at(h_high, share)
        unbracketed = np.zeros(shape, dtype=bool)
        unbracketed[share] = residual_high <= 0.0
        share &= ~unbracketed
    else:
        unbracketed = np.zeros(shape, dtype=bool)
    if np.any(share):
        low = np.full(np.count_nonzero(share), _S_LOW)
        high = np.full(np.count_nonzero(share), _S_HIGH)
        for _ in range(_BISECTIONS):
            mid = 0.5 * (low + high)
            h_mid = film_of_fluid_fraction(share, special.expit(-mid))
            positive = special.expit(mid) - asperity_fraction_at(h_mid, share) > 0.0
            high = np.where(positive, mid, high)
            low = np.where(positive, low, mid)
            if np.all(high - low < 1e-12):
                break
        s_root = 0.5 * (low + high)
        fraction[share] = special.expit(s_root)
        film[share] = film_of_fluid_fraction(share, special.expit(-s_root))
    boundary = ~moving | unbracketed
    if np.any(boundary):
        capacity = asperity_fraction_at(np.zeros(np.count_nonzero(boundary)), boundary)
        carried = np.zeros(shape, dtype=bool)
        carried[boundary] = capacity >= 1.0
        fraction[boundary] = np.minimum(capacity, 1.0)
        film[boundary] = 0.0
        if np.any(carried):
            film[carried] = _asperity_only_separation(load[carried], area[carried], sigma[carried],
                                                      density[carried], radius[carried], E_reduced[carried])
    return fraction, film


def _asperity_only_separation(load, area, sigma, density, radius, E_reduced):
    """Separation h >= 0 at which the Greenwood–Tripp asperities alone carry ``load`` over ``area``.

    Called only where they carry at least the load at h = 0 (asperity capacity >= 1).
    """
    low = np.zeros(load.shape)
    high = np.full(load.shape, _LAMBDA_HIGH)
    for _ in range(_BISECTIONS):
        mid = 0.5 * (low + high)
        carries = area * asperity_pressure(mid * sigma, sigma, density, radius, E_reduced) >= load
        low = np.where(carries, mid, low)
        high = np.where(carries, high, mid)
        if np.all(high - low < 1e-13):
            break
    return 0.5 * (low + high) * sigma


def _assemble(load, area, fraction, film, smooth_film, sigma, density, radius, E_reduced, extra):
    lam = film / sigma
    with np.errstate(over="ignore"):  # a vanishing asperity share: gamma2 -> inf, as it should
        gamma2 = np.divide(1.0, fraction, out=np.full(fraction.shape, np.inf), where=fraction > 0.0)
    result = {
        "asperity_load_fraction": fraction,
        "fluid_load_fraction": 1.0 - fraction,
        "asperity_load": fraction * load,
        "fluid_load": (1.0 - fraction) * load,
        "gamma1": np.divide(1.0, 1.0 - fraction, out=np.full(fraction.shape, np.inf), where=fraction < 1.0),
        "gamma2": gamma2,
        "h_c": film,
        "h_c_smooth": smooth_film,
        "lambda_ratio": lam,
        "asperity_pressure": fraction * load / area,
        "real_area_fraction": real_contact_area_fraction(film, sigma, density, radius),
        "asperity_capacity": area * asperity_pressure(0.0, sigma, density, radius, E_reduced) / load,
        "regime": mixed_regime(lam, fraction),
    }
    result.update(extra)
    return {key: _out(value) for key, value in result.items()}


def mixed_line_contact(w, R, E_reduced, u_m, eta0, alpha, sigma, asperity_density, asperity_radius, *,
                       piezoviscosity: bool = True, film_scale=1.0):
    """Load sharing of a rough lubricated line contact (Johnson–Greenwood–Poon; Gelinck–Schipper).

    Solves W/gamma_2 = 2 b p_a(h_c) with h_c the Moes (1992) central film at load w/gamma_1 and
    modulus E'/gamma_1, 1/gamma_1 + 1/gamma_2 = 1 (module docstring). All inputs broadcast.

    Parameters
    ----------
    w : float or array_like
        Load per unit length [N/m], > 0.
    R : float or array_like
        Reduced radius [m], > 0.
    E_reduced : float or array_like
        Hamrock's reduced modulus E' [Pa], > 0 (Greenwood–Tripp uses E'/2 inside).
    u_m : float or array_like
        Entrainment (mean) speed (u1 + u2)/2 [m/s], finite; its sign is ignored; 0 gives boundary
        lubrication (no film).
    eta0 : float or array_like
        Viscosity at the inlet [Pa*s], > 0.
    alpha : float or array_like
        Pressure-viscosity coefficient [1/Pa], >= 0.
    sigma, asperity_density, asperity_radius : float or array_like
        Composite RMS roughness [m], asperity density [1/m^2] and tip radius [m], > 0 (as
        :func:`camcontact.contact.asperity_contact.asperity_pressure`).
    piezoviscosity : bool
        False evaluates the film with alpha = 0 (Moes's isoviscous asymptotes).
    film_scale : float or array_like
        Factor on the Moes film at every load share [-], > 0: a scene whose smooth film comes from another
        model (a numerical solution, a thermal reduction) passes h_c(scene) / h_c(Moes, full load), so
        that the load sharing runs on its film (the ratio taken independent of the load share, as the
        films' load exponents are close: W^-0.1 to W^-0.13).

    Returns
    -------
    dict
        ``asperity_load_fraction`` 1/gamma_2 [-], ``fluid_load_fraction`` 1/gamma_1 [-],
        ``asperity_load``, ``fluid_load`` [N/m], ``gamma1``, ``gamma2`` [-] (inf where a share is 0),
        ``h_c`` mixed central film = mean-plane separation [m], ``h_c_smooth`` Moes film of the
        smooth contact (x ``film_scale``) [m], ``lambda_ratio`` h_c/sigma [-], ``asperity_pressure`` mean over the
        Hertz strip [Pa], ``real_area_fraction`` A_r/A_Hertz [-], ``asperity_capacity`` share of
        the load the asperities carry at h = 0 [-] (< 1: no boundary limit, see the module
        docstring), ``regime`` ("boundary", "mixed", "full_film"), ``hertz_half_width`` b [m],
        ``hersey_number`` eta0 |u_m| / w [-].
        Floats for scalar inputs, arrays otherwise.

    References
    ----------
    Johnson, Greenwood & Poon (1972) Wear 19:91–108; Gelinck & Schipper (2000) Tribol. Int.
    33:175–181; Moes (1992) Wear 159:57–66 (film); Greenwood & Tripp (1970–71) Proc. IMechE 185.
    """
    name = "mixed_line_contact"
    arrays = np.broadcast_arrays(
        _positive(name, "w", w, "N/m"), _positive(name, "R", R, "m"),
        _positive(name, "E_reduced", E_reduced, "Pa"), _finite(name, "u_m", u_m, "m/s"),
        _positive(name, "eta0", eta0, "Pa*s"), _non_negative(name, "alpha", alpha, "1/Pa"),
        _positive(name, "sigma", sigma, "m"), _positive(name, "asperity_density", asperity_density, "1/m^2"),
        _positive(name, "asperity_radius", asperity_radius, "m"), _positive(name, "film_scale", film_scale, "-"),
    )
    w_, R_, E_, u_, eta_, alpha_, sigma_, density_, radius_, scale_ = (np.array(a, dtype=float) for a in arrays)
    speed = np.abs(u_)
    film_model = Moes(piezoviscosity=piezoviscosity)
    half_width = np.sqrt(8.0 * w_ * R_ / (math.pi * E_))  # Hertz strip (camcontact.contact.hertz_line)
    area = 2.0 * half_width
    moving = speed > 0.0

    def film_of_fluid_fraction(mask, phi):
        return scale_[mask] * np.asarray(film_model.evaluate(R_[mask], w_[mask] * phi, E_[mask] * phi, speed[mask],
                                                             eta_[mask], alpha_[mask])["h_c"], dtype=float)

    fraction, film = _solve_load_share(w_, area, film_of_fluid_fraction, sigma_, density_, radius_, E_, moving)
    smooth = np.zeros(w_.shape)
    if np.any(moving):
        smooth[moving] = film_of_fluid_fraction(moving, np.ones(np.count_nonzero(moving)))
    extra = {"hertz_half_width": half_width, "hersey_number": eta_ * speed / w_}
    return _assemble(w_, area, fraction, film, smooth, sigma_, density_, radius_, E_, extra)


def mixed_point_contact(F, Rx, Ry, E_reduced, u_m, eta0, alpha, sigma, asperity_density, asperity_radius, *,
                        piezoviscosity: bool = True, film_scale=1.0):
    """Load sharing of a rough lubricated elliptical contact (JGP 1972 with the Nijenbanning film).

    As :func:`mixed_line_contact` with the load F [N], reduced radii Rx (entrainment direction)
    and Ry [m], the Nijenbanning–Venner–Moes (1994) central film at load F/gamma_1 and modulus
    E'/gamma_1, and the asperity pressure uniform over the Hertz ellipse pi a_x a_y of the full
    load (:func:`camcontact.contact.hertz_elliptical.hertz_elliptical`, exact ellipticity).
    ``film_scale`` [-], > 0, as for the line: h_c(scene) / h_c(Nijenbanning, full load) puts the load
    sharing on a scene's own film (another formula, a numerical solution).

    Returns
    -------
    dict
        Keys as :func:`mixed_line_contact` with loads in [N], plus ``hertz_area`` [m^2],
        ``hertz_semi_axes`` (a_x, a_y) [m] and no ``hersey_number``.

    References
    ----------
    Johnson, Greenwood & Poon (1972) Wear 19:91–108; Nijenbanning, Venner & Moes (1994) Wear
    176:217–229; Greenwood & Tripp (1970–71) Proc. IMechE 185:625–633.
    """
    name = "mixed_point_contact"
    arrays = np.broadcast_arrays(
        _positive(name, "F", F, "N"), _positive(name, "Rx", Rx, "m"), _positive(name, "Ry", Ry, "m"),
        _positive(name, "E_reduced", E_reduced, "Pa"), _finite(name, "u_m", u_m, "m/s"),
        _positive(name, "eta0", eta0, "Pa*s"), _non_negative(name, "alpha", alpha, "1/Pa"),
        _positive(name, "sigma", sigma, "m"), _positive(name, "asperity_density", asperity_density, "1/m^2"),
        _positive(name, "asperity_radius", asperity_radius, "m"), _positive(name, "film_scale", film_scale, "-"),
    )
    F_, Rx_, Ry_, E_, u_, eta_, alpha_, sigma_, density_, radius_, scale_ = (np.array(a, dtype=float) for a in arrays)
    speed = np.abs(u_)
    film_model = Nijenbanning(piezoviscosity=piezoviscosity)
    a_x = np.empty(F_.shape)
    a_y = np.empty(F_.shape)
    for index in np.ndindex(F_.shape):
        hertz = hertz_elliptical(float(F_[index]), float(Rx_[index]), float(Ry_[index]), float(E_[index]))
        a_x[index], a_y[index] = hertz.a_x, hertz.a_y
    area = math.pi * a_x * a_y
    moving = speed > 0.0

    def film_of_fluid_fraction(mask, phi):
        return scale_[mask] * np.asarray(film_model.evaluate(Rx_[mask], Ry_[mask], F_[mask] * phi, E_[mask] * phi,
                                                             speed[mask], eta_[mask], alpha_[mask])["h_c"], dtype=float)

    fraction, film = _solve_load_share(F_, area, film_of_fluid_fraction, sigma_, density_, radius_, E_, moving)
    smooth = np.zeros(F_.shape)
    if np.any(moving):
        smooth[moving] = film_of_fluid_fraction(moving, np.ones(np.count_nonzero(moving)))
    result = _assemble(F_, area, fraction, film, smooth, sigma_, density_, radius_, E_, {"hertz_area": area})
    result["hertz_semi_axes"] = (_out(a_x), _out(a_y))
    return result


def mixed_regime(lambda_ratio, asperity_load_fraction=None):
    """Lubrication regime label per operating point: "boundary", "mixed" or "full_film".

    "full_film" where Lambda >= 3, "boundary" where Lambda <= 1 or (if given) the asperity load
    fraction >= 0.95, "mixed" otherwise (bands: Cheng 1983, as :mod:`camcontact.contact.roughness`;
    the 0.95 is a convention of this module, see its docstring).

    Parameters
    ----------
    lambda_ratio : float or array_like
        Specific film thickness h_c/sigma [-] (finite).
    asperity_load_fraction : float or array_like, optional
        Share of the load carried by the asperities, 0..1 [-].
    """
    lam = _finite("mixed_regime", "lambda_ratio", lambda_ratio, "")
    boundary = lam <= LAMBDA_BOUNDARY
    if asperity_load_fraction is not None:
        fraction = _finite("mixed_regime", "asperity_load_fraction", asperity_load_fraction, "")
        if np.any(fraction < 0.0) or np.any(fraction > 1.0):
            raise InputError(f"mixed_regime: asperity_load_fraction = {asperity_load_fraction!r}; allowed: 0..1")
        boundary = boundary | (fraction >= BOUNDARY_ASPERITY_FRACTION)
    labels = np.where(boundary, MIXED_REGIMES[0], np.where(lam >= LAMBDA_FULL_FILM, MIXED_REGIMES[2], MIXED_REGIMES[1]))
    return str(labels) if labels.ndim == 0 else labels


def mixed_friction_coefficient(asperity_load_fraction, boundary_friction, *, fluid_traction_coefficient=None,
                               fluid_traction_force=None, load=None):
    """Friction coefficient of a mixed-lubricated contact, mu = (mu_b W_C + F_fluid)/W [-].

    .. math:: \\mu = \\mu_b\\,\\frac{W_C}{W} + \\frac{F_{fluid}}{W}
              = \\mu_b\\,\\frac{1}{\\gamma_2} + \\mu_{fluid}\\,\\frac{1}{\\gamma_1}

    Give exactly one of ``fluid_traction_coefficient`` (mu_fluid = F_fluid / W_H, the traction
    coefficient of the fluid-carried load) or ``fluid_traction_force`` F_fluid [N or N/m] together
    with the total ``load`` W in the same unit. Arrays broadcast.

    Parameters
    ----------
    asperity_load_fraction : float or array_like
        W_C/W = 1/gamma_2, 0..1 [-].
    boundary_friction : float or array_like
        Boundary friction coefficient mu_b of the asperity contacts, 0..1 [-] (about 0.1–0.13
        for steel in oil, ../shared/reference/friction_traction_thermal.md §2).
    fluid_traction_coefficient : float or array_like, optional
        mu_fluid >= 0 [-].
    fluid_traction_force : float or array_like, optional
        F_fluid >= 0 [N] (or [N/m] per unit length).
    load : float or array_like, optional
        W > 0, same unit as ``fluid_traction_force``.

    References
    ----------
    Gelinck & Schipper (2000) Tribol. Int. 33:175–181 (friction of the load-sharing model).
    """
    name = "mixed_friction_coefficient"
    fraction = _finite(name, "asperity_load_fraction", asperity_load_fraction, "")
    if np.any(fraction < 0.0) or np.any(fraction > 1.0):
        raise InputError(f"{name}: asperity_load_fraction = {asperity_load_fraction!r}; allowed: 0..1")
    mu_b = _non_negative(name, "boundary_friction", boundary_friction, "")
    if np.any(mu_b > 1.0):
        raise InputError(f"{name}: boundary_friction = {boundary_friction!r}; allowed: 0..1")
    if (fluid_traction_coefficient is None) == (fluid_traction_force is None):
        raise InputError(f"{name}: give exactly one of fluid_traction_coefficient or fluid_traction_force "
                         f"(got {fluid_traction_coefficient!r} and {fluid_traction_force!r})")
    if fluid_traction_coefficient is not None:
        mu_fluid = _non_negative(name, "fluid_traction_coefficient", fluid_traction_coefficient, "")
        return _out(mu_b * fraction + mu_fluid * (1.0 - fraction))
    if load is None:
        raise InputError(f"{name}: fluid_traction_force needs the total load (load=None given)")
    force = _non_negative(name, "fluid_traction_force", fluid_traction_force, "N")
    total = _positive(name, "load", load, "N")
    return _out(mu_b * fraction + force / total)


FluidTraction = Callable[[Mapping[str, object]], object]


def _stribeck(result: dict, speeds, boundary_friction, fluid_traction) -> dict:
    if callable(fluid_traction):
        mu_fluid = fluid_traction(result)
    else:
        mu_fluid = fluid_traction
    mu_fluid = np.broadcast_to(_non_negative("stribeck curve", "fluid traction coefficient", mu_fluid, ""),
                               np.shape(speeds))
    result["fluid_traction_coefficient"] = _out(mu_fluid)
    result["friction_coefficient"] = mixed_friction_coefficient(
        result["asperity_load_fraction"], boundary_friction, fluid_traction_coefficient=mu_fluid)
    return result


def stribeck_curve_line(u_m, w, R, E_reduced, eta0, alpha, sigma, asperity_density, asperity_radius,
                        boundary_friction, fluid_traction):
    """Stribeck curve of a rough line contact: friction coefficient against entrainment speed.

    Runs :func:`mixed_line_contact` over the speeds ``u_m`` [m/s] (other inputs scalars or
    broadcastable) and combines the shares with :func:`mixed_friction_coefficient`.

    Parameters
    ----------
    u_m : array_like
        Entrainment speeds (u1 + u2)/2 [m/s].
    w, R, E_reduced, eta0, alpha, sigma, asperity_density, asperity_radius
        As :func:`mixed_line_contact`.
    boundary_friction : float
        mu_b [-].
    fluid_traction : float, array_like or callable
        Traction coefficient of the fluid-carried load mu_fluid [-], or a callable taking the
        result mapping of :func:`mixed_line_contact` plus the inputs (keys ``u_m``, ``w``,
        ``R``, ``E_reduced``, ``eta0``, ``alpha``, ``sigma``) and returning mu_fluid (scalar or an
        array over the speeds). Example (Newtonian film shear at a slide-to-roll ratio S over the
        Hertz strip): ``lambda r: r["eta0"] * S * r["u_m"] / r["h_c"] * 2 * r["hertz_half_width"]
        / r["w"]``.

    Returns
    -------
    dict
        The :func:`mixed_line_contact` result plus ``u_m``, ``fluid_traction_coefficient`` and
        ``friction_coefficient`` [-].

    References
    ----------
    Gelinck & Schipper (2000) Tribol. Int. 33:175–181.
    """
    speeds = _finite("stribeck_curve_line", "u_m", u_m, "m/s")
    result = mixed_line_contact(w, R, E_reduced, speeds, eta0, alpha, sigma, asperity_density, asperity_radius)
    result.update({"u_m": _out(speeds), "w": w, "R": R, "E_reduced": E_reduced, "eta0": eta0, "alpha": alpha,
                   "sigma": sigma})
    return _stribeck(result, speeds, boundary_friction, fluid_traction)


def stribeck_curve_point(u_m, F, Rx, Ry, E_reduced, eta0, alpha, sigma, asperity_density, asperity_radius,
                         boundary_friction, fluid_traction):
    """Stribeck curve of a rough elliptical contact (as :func:`stribeck_curve_line`, load F [N]).

    The callable ``fluid_traction`` receives the :func:`mixed_point_contact` result plus ``u_m``,
    ``F``, ``Rx``, ``Ry``, ``E_reduced``, ``eta0``, ``alpha``, ``sigma``.

    References
    ----------
    Johnson, Greenwood & Poon (1972) Wear 19:91–108; Gelinck & Schipper (2000) Tribol. Int. 33:175–181.
    """
    speeds = _finite("stribeck_curve_point", "u_m", u_m, "m/s")
    result = mixed_point_contact(F, Rx, Ry, E_reduced, speeds, eta0, alpha, sigma, asperity_density, asperity_radius)
    result.update({"u_m": _out(speeds), "F": F, "Rx": Rx, "Ry": Ry, "E_reduced": E_reduced, "eta0": eta0,
                   "alpha": alpha, "sigma": sigma})
    return _stribeck(result, speeds, boundary_friction, fluid_traction)
