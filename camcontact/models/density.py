"""Density–pressure laws (family ``density_laws``): Dowson–Higginson, incompressible."""

from __future__ import annotations

import attrs
import numpy as np

from .base import DensityLaw, builtin

__all__ = ["DowsonHigginsonDensity", "Incompressible"]


@builtin
@attrs.frozen
class DowsonHigginsonDensity(DensityLaw):
    """Dowson–Higginson compressibility rho/rho0 = (a + b p)/(a + p).

    .. math:: \\frac{\\rho}{\\rho_0} = \\frac{5.9\\times10^8 + 1.34\\,p}{5.9\\times10^8 + p}

    p gauge pressure [Pa]; rho/rho0 -> 1.34 as p -> inf.

    Parameters
    ----------
    a : float
        Pressure constant [Pa], default 5.9e8.
    b : float
        Asymptotic density ratio [-], default 1.34.

    References
    ----------
    Dowson, D. & Higginson, G.R. (1966) Elasto-hydrodynamic Lubrication, Pergamon, in the
    form of Venner & Lubrecht (2000) and Tsuha (2015) Eq. 4.7.
    """

    name = "dowson_higginson"
    reference = "Dowson & Higginson (1966) Elastohydrodynamic Lubrication; Tsuha (2015) Eq. 4.7"

    a: float = 5.9e8
    b: float = 1.34

    def density_ratio(self, pressure):
        pressure = np.asarray(pressure, dtype=float)
        ratio = (self.a + self.b * pressure) / (self.a + pressure)
        return float(ratio) if ratio.ndim == 0 else ratio


@builtin
@attrs.frozen
class Incompressible(DensityLaw):
    """Incompressible lubricant, rho/rho0 = 1 (scenes without the ``compressibility`` effect)."""

    name = "incompressible"
    reference = "constant density (no compressibility)"

    def density_ratio(self, pressure):
        ratio = np.ones_like(np.asarray(pressure, dtype=float))
        return float(ratio) if ratio.ndim == 0 else ratio
