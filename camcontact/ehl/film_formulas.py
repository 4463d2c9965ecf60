"""Closed-form central-film formulas in the Moes groups, used by the EHL solvers as start values.

* :func:`moes_line_film` — Moes (1992) central film of a line contact, H = (h_c/R)(2U)^(-1/2)
  as a function of M = W'(2U)^(-1/2) and L = G(2U)^(1/4);
* :func:`nijenbanning_film` — Nijenbanning–Venner–Moes (1994) central film of an elliptical
  contact, H = (h_c/Rx)(2U)^(-1/2) as a function of M = W(2U)^(-3/4), L = G(2U)^(1/4) and
  D = Rx/Ry.

Both are dimensionless (the groups of :mod:`camcontact.ehl.groups`); the film models of
:mod:`camcontact.models.film_line` (``moes``) and :mod:`camcontact.models.film_point`
(``nijenbanning``) evaluate them in physical units.

References
----------
Moes, H. (1992) Optimum similarity analysis with applications to elastohydrodynamic
lubrication, Wear 159:57–66; as given by Venner & Lubrecht (2000) Multilevel Methods
in Lubrication, Elsevier, ch. 8.

Nijenbanning, G., Venner, C.H. & Moes, H. (1994) Film thickness in elastohydrodynamically
lubricated elliptic contacts, Wear 176:217–229.
"""

from __future__ import annotations

import numpy as np

__all__ = ["moes_line_film", "nijenbanning_film"]


def moes_line_film(M, L, *, elasticity: bool = True):
    """Moes (1992) dimensionless central film H_c = (h_c/R)(2U)^(-1/2) of a line contact.

    .. math::
        H = \\left[\\left(H_{RI}^{7/3} + H_{EI}^{7/3}\\right)^{3s/7}
            + \\left(H_{RP}^{-7/2} + H_{EP}^{-7/2}\\right)^{-2s/7}\\right]^{1/s},
        \\quad s = \\frac{7 + 8\\,e^{-2 H_{EI}/H_{RI}}}{5}

    with H_RI = 3 M^-1, H_EI = 2.621 M^-1/5, H_RP = 1.287 L^2/3, H_EP = 1.311 M^-1/8 L^3/4.
    L = 0 gives the isoviscous limits; ``elasticity=False`` the rigid asymptotes (H_EI and
    H_EP dropped, s = 3).
    """
    M = np.asarray(M, dtype=float)
    L = np.asarray(L, dtype=float)
    h_ri = 3.0 / M
    h_rp = 1.287 * L ** (2.0 / 3.0)
    if elasticity:
        h_ei = 2.621 * M ** -0.2
        h_ep = 1.311 * M ** -0.125 * L**0.75
        s = (7.0 + 8.0 * np.exp(-2.0 * h_ei / h_ri)) / 5.0
        isoviscous = (h_ri ** (7.0 / 3.0) + h_ei ** (7.0 / 3.0)) ** (3.0 * s / 7.0)
        with np.errstate(divide="ignore"):
            piezo_sum = np.where(L > 0.0, h_rp ** -3.5 + h_ep ** -3.5, np.inf)
    else:
        s = np.full_like(M, 3.0)
        isoviscous = h_ri**s
        with np.errstate(divide="ignore"):
            piezo_sum = np.where(L > 0.0, h_rp ** -3.5, np.inf)
    piezoviscous = np.where(np.isinf(piezo_sum), 0.0, piezo_sum ** (-2.0 * s / 7.0))
    H = (isoviscous + piezoviscous) ** (1.0 / s)
    return float(H) if H.ndim == 0 else H


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
