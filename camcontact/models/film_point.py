"""Film-thickness formulas for point (elliptical) contacts (family ``film_models``, geometry ``"point"``).

Inputs: reduced radii ``Rx`` (entrainment direction) and ``Ry`` [m], load ``F`` [N],
``E_reduced`` = E' [Pa], ``u_m`` = (u1+u2)/2 [m/s], ``eta0`` [Pa*s], ``alpha`` [1/Pa].
Groups on Rx: U = eta0 u_m/(E' Rx), G = alpha E', W = F/(E' Rx^2), H = h/Rx.
"""

from __future__ import annotations

import attrs
import numpy as np

from ..ehl.groups import hamrock_point, moes_point
from ..errors import InputError
from ..registry import builtin
from .base import FilmModel

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


def nijenbanning_film(M, L, D):
    """Nijenbanning–Venner–Moes (1994) dimensionless central film of an elliptical contact.

    H = (h_c/Rx)(2U)^(-1/2), with M = W(2U)^(-3/4), L = G(2U)^(1/4), D = Rx/Ry:

    .. math::
        H = \\left\\{\\left[H_{RI}^{3s/2} + \\left(H_{EI}^{-4} + H_{00}^{-4}\\right)^{-3s/8}\\right]^{2/(3s)}
            + \\left(H_{RP}^{-8} + H_{EP}^{-8}\\right)^{-s/8}\\right\\}^{1/s}

    H_RI = 145(1 + 0.796 D^(14/15))^(-15/7) D^-1 M^-2,
    H_EI = 3.18(1 + 0.006 ln D + 0.63 D^(4/7))^(-14/25) D^(-1/15) M^(-2/15),
    H_RP = 1.29(1 + 0.691 D)^(-2/3) L^(2/3),
    H_EP = 1.48(1 + 0.006 ln D + 0.63 D^(4/7))^(-7/20) D^(-1/24) M^(-1/12) L^(3/4),
    H_00 = 1.8 D^-1, s = 1.5(1 + exp(-1.2 H_EI/H_RI)).
    """
    M = np.asarray(M, dtype=float)
    L = np.asarray(L, dtype=float)
    D = np.asarray(D, dtype=float)
    log_d = np.log(D)
    geometric = 1.0 + 0.006 * log_d + 0.63 * D ** (4.0 / 7.0)
    h_ri = 145.0 * (1.0 + 0.796 * D ** (14.0 / 15.0)) ** (-15.0 / 7.0) / D / M**2
    h_ei = 3.18 * geometric ** (-14.0 / 25.0) * D ** (-1.0 / 15.0) * M ** (-2.0 / 15.0)
    h_rp = 1.29 * (1.0 + 0.691 * D) ** (-2.0 / 3.0) * L ** (2.0 / 3.0)
    h_ep = 1.48 * geometric ** (-7.0 / 20.0) * D ** (-1.0 / 24.0) * M ** (-1.0 / 12.0) * L**0.75
    h_00 = 1.8 / D
    s = 1.5 * (1.0 + np.exp(-1.2 * h_ei / h_ri))
    isoviscous = (h_ri ** (1.5 * s) + (h_ei**-4 + h_00**-4) ** (-3.0 * s / 8.0)) ** (2.0 / (3.0 * s))
    with np.errstate(divide="ignore"):
        piezo_sum = np.where(L > 0.0, h_rp**-8 + h_ep**-8, np.inf)
    piezoviscous = np.where(np.isinf(piezo_sum), 0.0, piezo_sum ** (-s / 8.0))
    H = (isoviscous + piezoviscous) ** (1.0 / s)
    return float(H) if H.ndim == 0 else H


@builtin
@attrs.frozen
class Nijenbanning(FilmModel):
    """Nijenbanning, Venner & Moes (1994) central film of an elliptical contact.

    Film from :func:`nijenbanning_film` with the Moes point-contact groups (sum speed) and
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
