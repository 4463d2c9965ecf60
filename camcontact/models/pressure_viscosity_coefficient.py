"""Correlations for the pressure–viscosity coefficient alpha.

``gold`` — the correlation Delabenetta (2021) uses (its Eq. 36, attributed in the source
literature to Gold et al.; the thesis does not name it), in the form of the thesis's
Appendix D code, which reproduces its Table 5:

.. math::
    \\alpha = \\left[C_\\alpha + 4.143\\,(\\log_{10}\\nu)^{3.0627}
      + 2.848\\times10^{-4}\\, m^{5.1903} (\\log_{10}\\nu)^{1.5976}
      - 3.999\\,(\\log_{10}\\nu)^{3.0975}\\,\\rho^{0.1162}\\right]\\times 10^{-8}\\ \\mathrm{Pa^{-1}}

nu is the kinematic viscosity [cSt] at the working temperature, m the Walther/ASTM D341
slope, rho the specific gravity [g/cm^3]; C_alpha = 1.216 for mineral oils and 0.914 for
esters. The printed factor 1e-11 is an erratum (reference erratum 9): 1e-8 reproduces the
tabulated 2.04e-8 1/Pa.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError

__all__ = ["GOLD_C_ALPHA", "gold_alpha"]

#: C_alpha of the correlation per base-oil class (Delabenetta 2021, §2.8 of the reference)
GOLD_C_ALPHA = {"mineral": 1.216, "ester": 0.914}


def gold_alpha(nu_cst, walther_m: float, specific_gravity: float, oil: str = "mineral"):
    """Pressure–viscosity coefficient alpha [1/Pa] (Delabenetta 2021 Eq. 36, see module).

    Parameters
    ----------
    nu_cst : float or array
        Kinematic viscosity at the working temperature [cSt] (> 1).
    walther_m : float
        Slope m of the Walther / ASTM D341 law [-].
    specific_gravity : float
        Density in g/cm^3 [-].
    oil : str
        ``"mineral"`` (C_alpha = 1.216) or ``"ester"`` (0.914).
    """
    if oil not in GOLD_C_ALPHA:
        raise InputError(f"gold_alpha: oil = {oil!r} unknown; choose one of {sorted(GOLD_C_ALPHA)}")
    log_nu = np.log10(np.asarray(nu_cst, dtype=float))
    if np.any(log_nu <= 0):
        raise InputError(f"gold_alpha: kinematic viscosity {nu_cst!r} cSt must exceed 1 cSt")
    value = (
        GOLD_C_ALPHA[oil]
        + 4.143 * log_nu**3.0627
        + 2.848e-4 * walther_m**5.1903 * log_nu**1.5976
        - 3.999 * log_nu**3.0975 * specific_gravity**0.1162
    ) * 1e-8
    if np.any(value <= 0):
        raise InputError(f"gold_alpha: the correlation gives alpha <= 0 for nu = {nu_cst!r} cSt (outside its range)")
    return float(value) if np.ndim(value) == 0 else value
