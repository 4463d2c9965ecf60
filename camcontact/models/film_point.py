"""Film-thickness formulas for point (elliptical) contacts (family ``film_models``, geometry ``"point"``).

Inputs: reduced radii ``Rx`` (entrainment direction) and ``Ry`` [m], load ``F`` [N],
``E_reduced`` = E' [Pa], ``u_m`` = (u1+u2)/2 [m/s], ``eta0`` [Pa*s], ``alpha`` [1/Pa].
Groups on Rx: U = eta0 u_m/(E' Rx), G = alpha E', W = F/(E' Rx^2), H = h/Rx.
"""

from __future__ import annotations

import attrs
import numpy as np

from ..ehl.film_formulas import nijenbanning_film
from ..ehl.groups import hamrock_point, moes_point
from ..errors import InputError
from .base import FilmModel, builtin

__all__ = ["HamrockDowson", "Nijenbanning", "nijenbanning_film"]

POINT_INPUTS = ("Rx", "Ry", "F", "E_reduced", "u_m", "eta0", "alpha")


def _point_groups(Rx, Ry, F, E_reduced, u_m, eta0, alpha, model: str) -> tuple:
    u = np.asarray(u_m, dtype=float)
    if np.any(u == 0.0):
        raise InputError(
            f"film model {model!r}: entrainment speed u_m = 0 gives no steady EHL film "
            "(use a transient solution)"
        )
    for label, value in (("Rx", Rx), ("Ry", Ry), ("F", F), ("E_reduced", E_reduced), ("eta0", eta0)):
        if np.any(np.asarray(value, dtype=float) <= 0.0):
            raise InputError(f"film model {model!r}: {label} = {value!r} must be > 0")
    if np.any(np.asarray(alpha, dtype=float) < 0.0):
        raise InputError(f"film model {model!r}: alpha = {alpha!r} must be >= 0")
    return hamrock_point(F, Rx, E_reduced, u, eta0, alpha)


@builtin
class HamrockDowson(FilmModel):
    """Hamrock–Dowson (1977) minimum and central films of an elliptical contact.

    .. math::
        \\frac{h_{min}}{R_x} = 3.63\\,U^{0.68} G^{0.49} W^{-0.073}\\left(1 - e^{-0.68 k}\\right), \\quad
        \\frac{h_c}{R_x} = 2.69\\,U^{0.67} G^{0.53} W^{-0.067}\\left(1 - 0.61\\,e^{-0.73 k}\\right)

    with the ellipticity fit k = 1.03 (Ry/Rx)^0.64 that the paper pairs with its formulas.
    Fitted to 34 numerical solutions with k from 1 to 8 (entrainment along the minor axis,
    Ry >= Rx), U over about two decades and W over one (abstract of Part III). The
    central-film formula is the companion fit of the same work as commonly quoted.

    References
    ----------
    Hamrock, B.J. & Dowson, D. (1977) Isothermal elastohydrodynamic lubrication of point
    contacts, Part III — Fully flooded results, J. Lubr. Technol. 99(2):264–276.
    """

    name = "hamrock_dowson"
    reference = "Hamrock & Dowson (1977) J. Lubr. Technol. 99(2):264-276 (Part III)"
    geometry = "point"
    requires = POINT_INPUTS
    provides = ("h_min", "h_c")
    validity = {"k": (1.0, 8.0)}

    def evaluate(self, Rx, Ry, F, E_reduced, u_m, eta0, alpha):
        U, G, W = _point_groups(Rx, Ry, F, E_reduced, u_m, eta0, alpha, self.name)
        if np.any(np.asarray(G) == 0.0):
            raise InputError("film model 'hamrock_dowson' gives no film at alpha = 0 (fitted to piezoviscous solutions)")
        k = 1.03 * (np.asarray(Ry, dtype=float) / np.asarray(Rx, dtype=float)) ** 0.64
        h_min = 3.63 * U**0.68 * G**0.49 * W**-0.073 * (1.0 - np.exp(-0.68 * k)) * Rx
        h_c = 2.69 * U**0.67 * G**0.53 * W**-0.067 * (1.0 - 0.61 * np.exp(-0.73 * k)) * Rx
        return {"h_min": h_min, "h_c": h_c, "U": U, "G": G, "W": W, "k": k}


@builtin
@attrs.frozen
class Nijenbanning(FilmModel):
    """Nijenbanning, Venner & Moes (1994) central film of an elliptical contact.

    Film from :func:`~camcontact.ehl.film_formulas.nijenbanning_film` with the Moes point-contact groups (sum speed) and
    D = Rx/Ry; h_c = H Rx (2U)^1/2. Handles the isoviscous case (alpha = 0, L = 0). The
    reference gives no numeric validity range; the interpolation is built to hold over the
    EHL regimes, and for wide ellipses it approaches the Moes line-contact formula.

    References
    ----------
    Nijenbanning, G., Venner, C.H. & Moes, H. (1994) Film thickness in elastohydrodynamically
    lubricated elliptic contacts, Wear 176:217–229.
    """

    name = "nijenbanning"
    reference = "Nijenbanning, Venner & Moes (1994) Wear 176:217-229"
    geometry = "point"
    requires = POINT_INPUTS
    provides = ("h_c",)
    can_disable = ("piezoviscosity",)

    piezoviscosity: bool = True

    def evaluate(self, Rx, Ry, F, E_reduced, u_m, eta0, alpha):
        if not self.piezoviscosity:
            alpha = 0.0 * np.asarray(alpha, dtype=float)
        U, G, W = _point_groups(Rx, Ry, F, E_reduced, u_m, eta0, alpha, self.name)
        M, L = moes_point(U, G, W)
        D = np.asarray(Rx, dtype=float) / np.asarray(Ry, dtype=float)
        H = nijenbanning_film(M, L, D)
        return {"h_c": H * Rx * np.sqrt(2.0 * U), "U": U, "G": G, "W": W, "M": M, "L": L, "D": D}
