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
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError

__all__ = ["DELABENETTA_CONSTANTS", "inlet_heating_factor", "slide_roll_measure", "thermal_loading"]

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
