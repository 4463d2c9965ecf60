"""Contact formulas shared by the Ferrarese & Uehara friction and wear models.

The friction model (:mod:`camcontact.models.friction`) and the oxidative-wear model
(:mod:`camcontact.models.wear`) of Ferrarese & Uehara both start from the same contact
area and speed; this module holds them once, with the two model parameters:

* Eq. 1 (Hutchings 1992), dry Hertz area :func:`hertz_contact_area`;
* Eq. 2, the paper's modulus E = E'/2 (:func:`paper_modulus`);
* Eq. 3, lubricated area A_L = k_L A_HERTZ, 1 <= k_L <= 3 (:func:`k_L_field`);
* Eq. 8 (Hutchings 1992), EHL film :func:`hutchings_film_thickness`;
* Eq. 12, sliding speed V = omega R = (pi/30) n R.

Modulus convention. camcontact's reduced modulus is Hamrock's
E' = 2/[(1-nu1^2)/E1 + (1-nu2^2)/E2]. The paper's E of Eq. 2 is
[(1-nu1^2)/E1 + (1-nu2^2)/E2]^-1 = E'/2 (the classical Hertz E*). The functions here take
``E_reduced`` = E' like every camcontact model and use E = E'/2 inside, in Eq. 1 and Eq. 8
alike (the paper defines one E for all its equations).

The printed constants of the combined Eqs. 9 and 13 disagree with Eqs. 1-8 (see
:data:`K_AT_PAPER` and :data:`K_Q_PAPER`); the models derive their constants from the
component formulas by default and offer the printed ones as ``constant="paper"``.

References
----------
Ferrarese, A. & Uehara, S.H. Friction and wear models in the cam-follower system, Escola
Politecnica da USP (conference paper), Eqs. 1-13.
Hutchings, I.M. (1992) Tribology: Friction and Wear of Engineering Materials, Edward Arnold.
"""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..errors import InputError
from ..units import in_range, number_field
from .base import float_or_array

__all__ = [
    "CONSTANT_MODES",
    "K_AT_PAPER",
    "K_Q_PAPER",
    "RPM_PER_RAD_PER_S",
    "constant_field",
    "derived_friction_constant",
    "derived_wear_constant",
    "hertz_contact_area",
    "hutchings_film_thickness",
    "k_L_field",
    "paper_modulus",
    "speed_inputs",
]

#: ``constant`` parameter values: derive from Eqs. 1-8 / 1, 3, 12, or use the printed constant.
CONSTANT_MODES = ("derived", "paper")

#: Printed constant of Eq. 9 per unit k_L [SI with n in rpm]. It is not what Eqs. 1-8 give
#: (:func:`derived_friction_constant`, 0.4204); it equals pi^2 (3/4)^(2/3) / (30 * 2.8) =
#: 9.6990e-2 to all printed digits, i.e. Eq. 8 evaluated with n R in place of V = (pi/30) n R
#: (the pi/30 lost in the film term): derived/printed = (30/pi)^0.65 = 4.3349.
K_AT_PAPER = 9.699e-2

#: Printed constant of Eq. 13 per unit k_L [SI with n in rpm]: the derived
#: pi^2 (3/4)^(2/3) / 30 = 0.2716 (:func:`derived_wear_constant`) divided by pi.
K_Q_PAPER = 8.644e-2

#: n [rpm] = RPM_PER_RAD_PER_S * omega [rad/s]  (Eq. 12: V = omega R = (pi/30) n R)
RPM_PER_RAD_PER_S = 30.0 / math.pi


def derived_friction_constant(k_L: float = 1.0) -> float:
    """k_at of Eq. 9 obtained from Eqs. 1-8 [SI, n in rpm, E the paper's E = E'/2].

    .. math:: k_{at} = \\frac{\\pi\\,(3/4)^{2/3}\\,(\\pi/30)^{0.35}}{2.8}\\,k_L \\approx 0.4204\\,k_L
    """
    return math.pi * 0.75 ** (2.0 / 3.0) * (math.pi / 30.0) ** 0.35 / 2.8 * k_L


def derived_wear_constant(k_L: float = 1.0) -> float:
    """k_q of Eq. 13 obtained from Eqs. 1, 3 and 12 [SI, n in rpm, E = E'/2].

    .. math:: k_q = \\frac{\\pi^2\\,(3/4)^{2/3}}{30}\\,k_L \\approx 0.2716\\,k_L
    """
    return math.pi**2 * 0.75 ** (2.0 / 3.0) / 30.0 * k_L


def paper_modulus(E_reduced):
    """The paper's E of Eq. 2 [Pa] from camcontact's reduced modulus E' [Pa]: E = E'/2.

    .. math:: E = \\left[\\frac{1-\\nu_1^2}{E_1} + \\frac{1-\\nu_2^2}{E_2}\\right]^{-1} = \\frac{E'}{2}
    """
    return 0.5 * np.asarray(E_reduced, dtype=float)


def _arrays(model: str, **inputs) -> dict[str, np.ndarray]:
    """Inputs as float arrays, checked: finite, N >= 0, the others > 0 (angular speed: any sign)."""
    arrays = {}
    for key, value in inputs.items():
        try:
            array = np.asarray(value, dtype=float)
        except (TypeError, ValueError):
            raise InputError(f"{model}: {key} = {value!r} is not a number or array of numbers") from None
        if not np.all(np.isfinite(array)):
            raise InputError(f"{model}: {key} contains NaN or inf")
        if key == "normal_force":
            if np.any(array < 0.0):
                raise InputError(
                    f"{model}: normal_force = {array.min():.6g} N is negative; allowed: normal_force >= 0 "
                    "(0 = contact open; a unilateral contact cannot pull)"
                )
        elif key != "angular_speed" and np.any(array <= 0.0):
            raise InputError(f"{model}: {key} = {array.min():.6g} is out of range; allowed: {key} > 0")
        arrays[key] = array
    return arrays


def speed_inputs(model: str, normal_force, R, E_reduced, angular_speed, **more):
    """Checked, broadcast SI arrays of the inputs and the sliding speed V = |omega| R (Eq. 12).

    Returns ``(arrays, V)``; ``arrays`` maps the input names (and ``"E"`` = E'/2) to arrays.
    """
    arrays = _arrays(model, normal_force=normal_force, R=R, E_reduced=E_reduced,
                     angular_speed=angular_speed, **more)
    names = list(arrays)
    broadcast = np.broadcast_arrays(*arrays.values())
    arrays = dict(zip(names, broadcast))
    arrays["E"] = paper_modulus(arrays["E_reduced"])
    V = np.abs(arrays["angular_speed"]) * arrays["R"]
    return arrays, V


def hertz_contact_area(normal_force, R, E_reduced):
    """Dry Hertz contact area A_HERTZ [m^2] of Eq. 1 (Hutchings 1992).

    .. math:: A_{HERTZ} = \\pi\\left(\\frac{3 N R}{4 E}\\right)^{2/3}, \\qquad E = E'/2

    the circular Hertz contact of a sphere of radius R on a flat (a = (3NR/4E)^(1/3)), which
    the paper applies to the cam of radius of curvature R.

    Parameters
    ----------
    normal_force : float or array
        Normal force N [N], >= 0 (0 gives 0).
    R : float or array
        Radius of curvature of the cam at the contact [m], > 0.
    E_reduced : float or array
        Reduced modulus E' [Pa] (Hamrock; the paper's E is E'/2).
    """
    N = np.asarray(normal_force, dtype=float)
    E = paper_modulus(E_reduced)
    return float_or_array(math.pi * (0.75 * N * np.asarray(R, dtype=float) / E) ** (2.0 / 3.0))


def hutchings_film_thickness(R, eta0, V, E_reduced, normal_force):
    """EHL film thickness h [m] of Eq. 8 (Hutchings 1992, non-conformal contact).

    .. math:: h = 2.8\\,R^{0.77}\\,\\mu^{0.65}\\,V^{0.65}\\,E^{-0.44}\\,N^{-0.21}, \\qquad E = E'/2

    An empirical fit, given by the paper in SI: R [m], mu = ``eta0`` [Pa*s] (the paper's mu
    is the lubricant's dynamic viscosity), V [m/s], E [Pa], N [N]. Although empirical, it is
    dimensionally homogeneous with a dimensionless 2.8: mu V is a force per length, and the
    exponents give force^(0.65-0.44-0.21) = force^0 and length^(0.77-0.65+0.88) = length^1, so
    any consistent unit system gives the same film.

    ``normal_force`` = 0 (contact open) gives h = inf (the limit of Eq. 8), without a
    division warning; V = 0 gives h = 0.
    """
    N = np.asarray(normal_force, dtype=float)
    E = paper_modulus(E_reduced)
    loaded = N > 0.0
    N_safe = np.where(loaded, N, 1.0)
    h = (2.8 * np.asarray(R, dtype=float) ** 0.77 * np.asarray(eta0, dtype=float) ** 0.65
         * np.abs(np.asarray(V, dtype=float)) ** 0.65 * E**-0.44 * N_safe**-0.21)
    return float_or_array(np.where(loaded, h, np.inf))


# ------------------------------------------------------------------ parameters
def _check_constant_mode(instance, attribute, value):
    if value not in CONSTANT_MODES:
        raise InputError(
            f"{type(instance).__name__}.{attribute.name} = {value!r} is not allowed; choose "
            f"{' or '.join(repr(m) for m in CONSTANT_MODES)} ('derived' from the component "
            "equations, 'paper' for the constant printed by Ferrarese & Uehara)"
        )


def k_L_field():
    """attrs field of the lubricated-area factor k_L [-] (Eq. 3), required, 1 <= k_L <= 3."""
    return number_field(validators=[in_range(1.0, 3.0)],
                        doc="lubricated-area factor k_L = A_L/A_HERTZ [-], Eq. 3")


def constant_field():
    """attrs field ``constant``: ``"derived"`` (default) or ``"paper"``."""
    return attrs.field(default="derived", validator=_check_constant_mode)
