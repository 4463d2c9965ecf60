"""Inlet shear-heating (thermal) reduction of the isothermal film thickness.

.. math::
    \\phi_T = \\left\\{1 + c_1\\left[(1 + c_2 V_e^{c_3}) L^{c_4}\\right]\\right\\}^{-1}, \\qquad
    L = \\frac{\\beta\\,\\eta_0\\,(u_1 + u_2)^2}{k}, \\qquad V_e = \\left|\\frac{u_1 - u_2}{u_1 + u_2}\\right|

L is the thermal loading parameter [-] (beta = -d ln(eta)/dT [1/K], eta0 [Pa*s], surface
speeds [m/s], lubricant conductivity k [W/(m K)]); V_e the slide-to-roll measure of
Delabenetta (2021) Eq. 45. The default constants (c1, c2, c3, c4) = (0.1, 14.8, 0.83, 0.64)
are those printed and used by Delabenetta (2021) Eq. 44 (a factor of the Murch–Wilson /
Wilson–Sheu family); they are parameters so other published sets can be used.
The corrected central film is h_c,T = phi_T h_c.

Other published factors (:data:`THERMAL_FACTORS`, :func:`thermal_reduction`), with L on the mean
(entrainment) speed u_m = (u1 + u2)/2, L_m = beta eta0 u_m^2 / k, as their sources define it:

=============== =============================================================== ==========================
name            phi_T                                                           source
=============== =============================================================== ==========================
murch_wilson    1 / (1 + 0.254 L_m^0.62) (pure rolling)                         Murch & Wilson (1975), as
                                                                                printed by Wilson & Sheu
                                                                                (1983) Eq. 9
wilson_sheu     1 / (1 + 0.241 (1 + 14.8 Z^0.83) L_m^0.64),                     Wilson & Sheu (1983)
                Z = abs(u1 - u2) / (u1 + u2)                                    Eqs. 5-7
zhu_cheng       [1 - 13.2 (p_h/E') L_m^0.42] / [1 + 0.213 (1 + 2.23 S^0.83)     Zhou & Hoeprich (1991)
                L_m^0.64], S = abs(u1 - u2) / u_m                               Eq. 21 (Zhu & Cheng 1988;
                                                                                the "Gupta et al." factor)
delabenetta     the form above with (0.1, 14.8, 0.83, 0.64), L on (u1 + u2)     Delabenetta (2021) Eq. 44
=============== =============================================================== ==========================

Delabenetta's Eq. 44 is Wilson & Sheu's Eq. 7 written with L on the speed sum: 0.241 / 4^0.64 = 0.0992
(printed 0.1) with V_e = Z. Zhou & Hoeprich call S "the ratio of sliding to rolling velocity" without
saying whether the rolling velocity is the mean or the sum; the mean is taken here (S is then the usual
slide-to-roll ratio, twice Z); their E' is taken as camcontact's E'. All factors tend to 1 where the
entrainment vanishes (L_m ~ u_m^2 falls faster than Z^0.83 grows): phi_T = 1 at u1 + u2 = 0.

References: Murch, L.E. & Wilson, W.R.D. (1975) A thermal elastohydrodynamic inlet zone analysis, ASME J.
Lubr. Technol. 97:212-216; Wilson, W.R.D. & Sheu, S. (1983) Effect of inlet shear heating due to sliding
on elastohydrodynamic film thickness, ASME J. Lubr. Technol. 105:187-188; Zhou, R.S. & Hoeprich, M.R.
(1991) Torque of tapered roller bearings, ASME J. Tribol. 113:590-597.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError

__all__ = ["DELABENETTA_CONSTANTS", "THERMAL_FACTORS", "inlet_heating_factor", "slide_roll_measure",
           "thermal_loading", "thermal_reduction"]

DELABENETTA_CONSTANTS = (0.1, 14.8, 0.83, 0.64)


def thermal_loading(beta, eta0, u1, u2, conductivity):
    """Thermal loading L = beta eta0 (u1 + u2)^2 / k [-] (Delabenetta 2021 Eq. 46)."""
    if np.any(np.asarray(conductivity, dtype=float) <= 0):
        raise InputError(f"thermal loading: lubricant thermal conductivity {conductivity!r} W/(m K) must be > 0")
    return beta * eta0 * (np.asarray(u1, dtype=float) + u2) ** 2 / conductivity


def slide_roll_measure(u1, u2):
    """V_e = |(u1 - u2)/(u1 + u2)| [-] (Delabenetta 2021 Eq. 45)."""
    total = np.asarray(u1, dtype=float) + u2
    if np.any(total == 0):
        raise InputError("slide/roll measure: u1 + u2 = 0 (no entrainment)")
    return np.abs((np.asarray(u1, dtype=float) - u2) / total)


def inlet_heating_factor(L, V_e, constants=DELABENETTA_CONSTANTS):
    """Film reduction factor phi_T [-] for thermal loading L and slide/roll V_e (see module)."""
    c1, c2, c3, c4 = constants
    L = np.asarray(L, dtype=float)
    if np.any(L < 0):
        raise InputError(f"inlet heating factor: thermal loading L = {L!r} must be >= 0")
    phi = 1.0 / (1.0 + c1 * (1.0 + c2 * np.asarray(V_e, dtype=float) ** c3) * L**c4)
    return float(phi) if phi.ndim == 0 else phi


#: the inlet shear-heating factors by name (module table): name -> (source, needs p_h/E')
THERMAL_FACTORS = {
    "wilson_sheu": "Wilson & Sheu (1983) Eqs. 5-7",
    "murch_wilson": "Murch & Wilson (1975), Wilson & Sheu (1983) Eq. 9",
    "zhu_cheng": "Zhou & Hoeprich (1991) Eq. 21 (Zhu & Cheng 1988)",
    "delabenetta": "Delabenetta (2021) Eq. 44",
}


def thermal_reduction(method: str, beta, eta0, u1, u2, conductivity, p_h=None, E_reduced=None):
    """(L_m, phi_T): the thermal loading on the mean speed beta eta0 u_m^2 / k [-] and the inlet
    shear-heating factor of ``method`` (a key of :data:`THERMAL_FACTORS`; module table) for surface
    speeds u1, u2 [m/s] (arrays broadcast), beta [1/K], eta0 [Pa*s], k [W/(m K)]; ``zhu_cheng`` also
    needs p_h and E' [Pa]. phi_T = 1 where u1 + u2 = 0; NaN where Zhu & Cheng's numerator is negative
    (outside the fit)."""
    if method not in THERMAL_FACTORS:
        raise InputError(f"thermal factor {method!r} unknown; allowed: {', '.join(THERMAL_FACTORS)}")
    if not (np.all(np.asarray(beta, dtype=float) > 0) and np.all(np.asarray(eta0, dtype=float) > 0)):
        raise InputError(f"thermal factor: beta = {beta!r} 1/K and eta0 = {eta0!r} Pa*s must be > 0")
    u1, u2 = np.broadcast_arrays(np.asarray(u1, dtype=float), np.asarray(u2, dtype=float))
    total = u1 + u2
    L_m = thermal_loading(beta, eta0, u1, u2, conductivity) / 4.0
    moving = total != 0.0
    ratio = np.abs(u1 - u2) / np.where(moving, np.abs(total), 1.0)  # Z (= S / 2)
    if method == "murch_wilson":
        phi = 1.0 / (1.0 + 0.254 * L_m**0.62)
    elif method == "wilson_sheu":
        phi = 1.0 / (1.0 + 0.241 * (1.0 + 14.8 * ratio**0.83) * L_m**0.64)
    elif method == "delabenetta":
        phi = inlet_heating_factor(4.0 * L_m, ratio)
    else:
        if p_h is None or E_reduced is None:
            raise InputError("thermal factor 'zhu_cheng' needs the Hertz pressure p_h and E'")
        numerator = 1.0 - 13.2 * (np.asarray(p_h, dtype=float) / E_reduced) * L_m**0.42
        phi = np.where(numerator >= 0.0, numerator, np.nan) / (
            1.0 + 0.213 * (1.0 + 2.23 * (2.0 * ratio) ** 0.83) * L_m**0.64)
    phi = np.where(moving, phi, 1.0)
    return (float(L_m) if L_m.ndim == 0 else L_m), (float(phi) if np.ndim(phi) == 0 else phi)
