"""Thermal conductivity and specific heat of a mineral oil from its specific gravity.

Cragoe-type correlations as printed and coded by Delabenetta (2021), Eqs. 38-39 (reference
§2.8), with the temperature theta in °C and the specific gravity SG (density at 20 °C in g/cm^3):

.. math::
    k = \\frac{0.12\\,(1 - c_k\\,\\theta)}{SG}\\ [\\mathrm{W/(m\\,K)}], \\qquad
    c_p = \\frac{1000\\,(1.63 + 0.0034\\,\\theta)}{\\sqrt{SG}}\\ [\\mathrm{J/(kg\\,K)}]

The thesis's text prints c_k = 0.005/3; its code (and its Table 5: k = 0.1286 W/(m K) for
NH1 11-572 at 84.9 °C) uses c_k = 0.0005/3 (reference erratum 11), the default here.
"""

from __future__ import annotations

import math

from ..errors import InputError

__all__ = ["CONDUCTIVITY_SLOPE", "oil_specific_heat", "oil_thermal_conductivity"]

#: c_k of Eq. 38 as the thesis's code uses it [1/°C]
CONDUCTIVITY_SLOPE = 0.0005 / 3.0


def _check(theta_c: float, specific_gravity: float, where: str) -> None:
    if not (math.isfinite(theta_c) and theta_c > -273.15):
        raise InputError(f"{where}: temperature {theta_c!r} °C must be finite and above absolute zero")
    if not (math.isfinite(specific_gravity) and specific_gravity > 0.0):
        raise InputError(f"{where}: specific gravity {specific_gravity!r} must be > 0")


def oil_thermal_conductivity(theta_c: float, specific_gravity: float, slope: float = CONDUCTIVITY_SLOPE) -> float:
    """k [W/(m K)] at theta [°C] for specific gravity SG [-] (Delabenetta 2021 Eq. 38)."""
    _check(theta_c, specific_gravity, "oil_thermal_conductivity")
    return 0.12 * (1.0 - slope * theta_c) / specific_gravity


def oil_specific_heat(theta_c: float, specific_gravity: float) -> float:
    """c_p [J/(kg K)] at theta [°C] for specific gravity SG [-] (Delabenetta 2021 Eq. 39)."""
    _check(theta_c, specific_gravity, "oil_specific_heat")
    return 1000.0 * (1.63 + 0.0034 * theta_c) / math.sqrt(specific_gravity)
