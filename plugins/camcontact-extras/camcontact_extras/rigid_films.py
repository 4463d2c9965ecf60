"""Rigid-surface line-contact films: Martin (isoviscous) and Blok (piezoviscous).

Both use the entrainment speed u_m = (u1 + u2)/2. Their published coefficients follow from
the rigid Reynolds problem with Reynolds (Swift–Stieber) outlet conditions; the tests of
this package re-derive them by numerical integration (4.895 and 1.666).
"""

from __future__ import annotations

import attrs
import numpy as np

from camcontact.errors import InputError
from camcontact.models.base import FilmModel

__all__ = ["Blok", "Martin"]

LINE_INPUTS = ("R", "w", "E_reduced", "u_m", "eta0", "alpha")


def _check(R, w, u_m, eta0, model):
    if np.any(np.asarray(u_m, dtype=float) == 0.0):
        raise InputError(f"film model {model!r}: entrainment speed u_m = 0 gives no hydrodynamic film")
    for label, value in (("R", R), ("w", w), ("eta0", eta0)):
        if np.any(np.asarray(value, dtype=float) <= 0.0):
            raise InputError(f"film model {model!r}: {label} = {value!r} must be > 0")


@attrs.frozen
class Martin(FilmModel):
    """Martin (1916) rigid-isoviscous line contact.

    .. math:: h_{min} = h_c = 4.9\\,\\frac{\\eta_0 u_m R}{w}

    Rigid cylinder on a plane, constant viscosity, Reynolds outlet condition; the film is
    thinnest at the centre. Ignores alpha and E' (it represents scenes with the
    ``piezoviscosity`` and ``elasticity`` effects switched off).

    References
    ----------
    Martin, H.M. (1916) Lubrication of gear teeth, Engineering 102:119–121; as Saccheto
    (2008) Eqs. 4.44–4.45 (H_min = 4.9 U/W).
    """

    name = "martin"
    reference = "Martin (1916) Engineering 102:119-121; Saccheto (2008) Eqs. 4.44-4.45"
    geometry = "line"
    requires = LINE_INPUTS
    provides = ("h_c", "h_min")
    can_disable = ("piezoviscosity", "elasticity")
    coefficient = 4.9

    piezoviscosity: bool = True
    elasticity: bool = True

    def evaluate(self, R, w, E_reduced, u_m, eta0, alpha):
        """Film [m]: R [m], w [N/m], u_m [m/s], eta0 [Pa*s]; E' and alpha are not used."""
        _check(R, w, u_m, eta0, self.name)
        h = self.coefficient * eta0 * np.abs(u_m) * R / w
        return {"h_c": h, "h_min": h}


@attrs.frozen
class Blok(FilmModel):
    """Blok rigid-piezoviscous line contact (Barus viscosity), independent of the load.

    .. math:: h_{min} = h_c = 1.66\\,(\\alpha \\eta_0 u_m)^{2/3} R^{1/3}

    The film at which the reduced pressure reaches 1/alpha, i.e. the pressure becomes
    unbounded; ignores E' (it represents scenes with ``elasticity`` switched off).

    References
    ----------
    Blok's rigid-piezoviscous solution as given by Saccheto (2008) Eq. 4.47 (with Martin's
    and Dowson–Higginson's in its Table of practical film formulas, §4.3).
    """

    name = "blok"
    reference = "Blok rigid-piezoviscous film, as Saccheto (2008) Eq. 4.47"
    geometry = "line"
    requires = LINE_INPUTS
    provides = ("h_c", "h_min")
    can_disable = ("elasticity",)
    coefficient = 1.66

    elasticity: bool = True

    def evaluate(self, R, w, E_reduced, u_m, eta0, alpha):
        """Film [m]: R [m], u_m [m/s], eta0 [Pa*s], alpha [1/Pa] (> 0); w and E' are not used."""
        _check(R, w, u_m, eta0, self.name)
        if np.any(np.asarray(alpha, dtype=float) <= 0.0):
            raise InputError("film model 'blok' is piezoviscous: alpha must be > 0 (use 'martin' for alpha = 0)")
        h = self.coefficient * (alpha * eta0 * np.abs(u_m)) ** (2.0 / 3.0) * R ** (1.0 / 3.0)
        return {"h_c": h, "h_min": h}
