"""Viscosity–pressure laws (family ``viscosity_laws``, kind ``"pressure"``): Barus, Roelands.

Both take the ambient-pressure viscosity eta0 [Pa*s] and the pressure–viscosity
coefficient alpha = d(ln eta)/dp at p = 0 [1/Pa]. Roelands is parameterised by its
index z; the consistency relation alpha*p0 = z*(ln eta0 + 9.67) (Venner 1991, as
used by Tsuha 2015 Eq. 4.6) converts between alpha and z, and
:func:`roelands_consistent` derives whichever of eta0, alpha, z is missing.
"""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..errors import InputError
from .base import ViscosityPressureLaw, builtin

__all__ = ["Barus", "Roelands", "roelands_consistent"]

#: Roelands reference pressure p0 [Pa] and ln of the asymptotic viscosity ln(eta_inf) = -9.67
#: (eta in Pa*s), Roelands (1966); Tsuha (2015) Eq. 4.5.
ROELANDS_P0 = 1.96e8
ROELANDS_LN_ETA_INF = -9.67


@builtin
@attrs.frozen
class Barus(ViscosityPressureLaw):
    """Barus exponential law eta = eta0 exp(alpha p).

    .. math:: \\eta(p) = \\eta_0 \\exp(\\alpha p)

    Parameters of :meth:`log_viscosity_ratio`: p [Pa], eta0 [Pa*s], alpha [1/Pa].
    Valid only for moderate pressures: it overestimates the viscosity at EHL pressures
    (Tsuha 2015 §4.2, citing Hamrock, Schmid & Jacobson 2004).

    References
    ----------
    Barus, C. (1893) Am. J. Sci. 45:87–96. As written in Tsuha (2015) Eq. 4.4.
    """

    name = "barus"
    reference = "Barus (1893) Am. J. Sci. 45:87; Tsuha (2015) Eq. 4.4"

    def log_viscosity_ratio(self, pressure, eta0, alpha):
        return alpha * np.asarray(pressure, dtype=float)


def _ln_eta_margin(eta0: float, ln_eta_inf: float) -> float:
    margin = math.log(eta0) - ln_eta_inf
    if not margin > 0.0:
        raise InputError(
            f"Roelands law: eta0 = {eta0:.4g} Pa*s must exceed eta_inf = exp({ln_eta_inf}) = "
            f"{math.exp(ln_eta_inf):.4g} Pa*s for the law to be defined"
        )
    return margin


@builtin
@attrs.frozen
class Roelands(ViscosityPressureLaw):
    """Roelands (1966) pressure–viscosity law with the alpha–z consistency relation.

    .. math::
        \\eta(p) = \\eta_0 \\exp\\left\\{(\\ln\\eta_0 + 9.67)\\left[-1 + (1 + p/p_0)^z\\right]\\right\\},
        \\qquad z = \\frac{\\alpha p_0}{\\ln\\eta_0 + 9.67}

    with p0 = 1.96e8 Pa and eta in Pa*s. The law is written with alpha so that it shares
    the signature of :class:`Barus`; its slope at p = 0 equals alpha.

    Parameters
    ----------
    p0 : float
        Reference pressure [Pa], default 1.96e8.
    ln_eta_inf : float
        ln of the asymptotic viscosity [ln(Pa*s)], default -9.67.

    References
    ----------
    Roelands, C.J.A. (1966) Correlational aspects of the viscosity–temperature–pressure
    relationship of lubricating oils, PhD thesis, TH Delft. Consistency relation:
    Venner (1991), as Tsuha (2015) Eqs. 4.5–4.6.
    """

    name = "roelands"
    reference = "Roelands (1966) thesis TH Delft; Tsuha (2015) Eqs. 4.5-4.6 (alpha-z consistency, Venner 1991)"
    #: typical range of z for lubricating oils (Tsuha 2015 §4.2)
    validity = {"roelands_z": (0.5, 0.7)}

    p0: float = ROELANDS_P0
    ln_eta_inf: float = ROELANDS_LN_ETA_INF

    def z(self, eta0: float, alpha: float) -> float:
        """Roelands index z [-] consistent with eta0 [Pa*s] and alpha [1/Pa]."""
        return alpha * self.p0 / _ln_eta_margin(eta0, self.ln_eta_inf)

    def alpha(self, eta0: float, z: float) -> float:
        """Pressure–viscosity coefficient alpha [1/Pa] from eta0 [Pa*s] and z [-]."""
        return z * _ln_eta_margin(eta0, self.ln_eta_inf) / self.p0

    def eta0(self, alpha: float, z: float) -> float:
        """Ambient viscosity eta0 [Pa*s] consistent with alpha [1/Pa] and z [-]."""
        if not (alpha > 0.0 and z > 0.0):
            raise InputError(f"Roelands law: alpha = {alpha:g} 1/Pa and z = {z:g} must both be > 0")
        return math.exp(alpha * self.p0 / z + self.ln_eta_inf)

    def log_viscosity_ratio(self, pressure, eta0, alpha):
        pressure = np.asarray(pressure, dtype=float)
        if np.any(pressure <= -self.p0):
            raise InputError(
                f"Roelands law: pressure {pressure.min():.4g} Pa is at or below -p0 = {-self.p0:g} Pa"
            )
        margin = _ln_eta_margin(eta0, self.ln_eta_inf)
        z = alpha * self.p0 / margin
        return margin * np.expm1(z * np.log1p(pressure / self.p0))


def roelands_consistent(
    eta0: float | None = None,
    alpha: float | None = None,
    z: float | None = None,
    *,
    law: Roelands | None = None,
) -> tuple[float, float, float]:
    """Complete (eta0 [Pa*s], alpha [1/Pa], z [-]) from any two via the consistency relation.

    If all three are given they must agree to 1e-6 relative; otherwise an
    :class:`~camcontact.errors.InputError` names the inconsistent set.

    Examples
    --------
    Tsuha (2015) never states eta0; alpha = 2.2e-8 1/Pa and z = 0.68 give 0.035835 Pa*s:

    >>> round(roelands_consistent(alpha=2.2e-8, z=0.68)[0], 6)
    0.035835
    """
    law = law or Roelands()
    given = sum(v is not None for v in (eta0, alpha, z))
    if given < 2:
        raise InputError(
            "Roelands consistency needs two of eta0, alpha, z; "
            f"got eta0={eta0!r}, alpha={alpha!r}, z={z!r}"
        )
    if eta0 is None:
        eta0 = law.eta0(alpha, z)
    elif alpha is None:
        alpha = law.alpha(eta0, z)
    elif z is None:
        z = law.z(eta0, alpha)
    else:
        z_consistent = law.z(eta0, alpha)
        if abs(z_consistent - z) > 1e-6 * abs(z):
            raise InputError(
                f"eta0 = {eta0:g} Pa*s, alpha = {alpha:g} 1/Pa and z = {z:g} are not consistent: "
                f"alpha*p0/(ln eta0 + 9.67) = {z_consistent:.6g}; give only two of them"
            )
    return float(eta0), float(alpha), float(z)
