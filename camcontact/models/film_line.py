"""Film-thickness formulas for line contacts (family ``film_models``, geometry ``"line"``).

All take the reduced radius ``R`` [m], load per unit length ``w`` [N/m], reduced modulus
``E_reduced`` = E' [Pa], entrainment speed ``u_m`` = (u1+u2)/2 [m/s], ``eta0`` [Pa*s] and
``alpha`` [1/Pa], and return films in metres together with the dimensionless groups
(Hamrock U, G, W'; see :mod:`camcontact.ehl.groups`):

============== ======================================================= ==============
name           formula (H = h/R)                                        provides
============== ======================================================= ==============
grubin         H = 1.95 (G U)^(8/11) W'^(-1/11)                          h_c
dowson_higg... H_min = 2.65 U^0.70 G^0.54 W'^-0.13                       h_min
dowson_toyoda  H_c = 3.06 U^0.69 G^0.56 W'^-0.10                         h_c
pan_hamrock    H_min = 1.714 W'^-0.128 U^0.694 G^0.568,                  h_min, h_c
               H_c = 2.922 W'^-0.166 U^0.692 G^0.470
moes           Moes (1992) interpolation over the four EHL regimes       h_c
============== ======================================================= ==============
"""

from __future__ import annotations

from typing import ClassVar

import attrs
import numpy as np

from ..ehl.film_formulas import moes_line_film
from ..ehl.groups import hamrock_line, moes_line
from ..errors import InputError
from .base import FilmModel, builtin

__all__ = ["DowsonHigginson", "DowsonToyoda", "Grubin", "LinePowerLaw", "Moes", "PanHamrock"]

LINE_INPUTS = ("R", "w", "E_reduced", "u_m", "eta0", "alpha")

#: Dowson's practical parameter ranges of line-contact EHL (W' 3e-5..3e-4, U 1e-13..1e-8),
#: as quoted by Saccheto (2008) §4.2; the validity of the power-law formulas below.
DOWSON_RANGE = {"W": (3e-5, 3e-4), "U": (1e-13, 1e-8)}


def _line_groups(R, w, E_reduced, u_m, eta0, alpha, model: str) -> tuple:
    u = np.asarray(u_m, dtype=float)
    if np.any(u == 0.0):
        raise InputError(
            f"film model {model!r}: entrainment speed u_m = 0 gives no steady EHL film "
            "(the film then lives on squeeze alone; use a transient solution)"
        )
    for label, value in (("R", R), ("w", w), ("E_reduced", E_reduced), ("eta0", eta0)):
        if np.any(np.asarray(value, dtype=float) <= 0.0):
            raise InputError(f"film model {model!r}: {label} = {value!r} must be > 0")
    if np.any(np.asarray(alpha, dtype=float) < 0.0):
        raise InputError(f"film model {model!r}: alpha = {alpha!r} must be >= 0")
    return hamrock_line(w, R, E_reduced, u, eta0, alpha)


class LinePowerLaw(FilmModel):
    """A line-contact film formula of power-law form H = c U^a G^b W'^d.

    Subclasses set ``terms``: ``{"h_c" or "h_min": (c, a, b, d)}``.
    """

    geometry = "line"
    requires = LINE_INPUTS
    terms: ClassVar[dict[str, tuple[float, float, float, float]]] = {}

    def evaluate(self, R, w, E_reduced, u_m, eta0, alpha):
        """Films [m] and groups for R [m], w [N/m], E' [Pa], u_m [m/s], eta0 [Pa*s], alpha [1/Pa]."""
        U, G, W = _line_groups(R, w, E_reduced, u_m, eta0, alpha, self.name)
        if np.any(np.asarray(G) == 0.0):
            raise InputError(
                f"film model {self.name!r} is fitted to piezoviscous solutions and gives no film at "
                "alpha = 0; use 'moes' for an isoviscous scene"
            )
        result = {"U": U, "G": G, "W": W}
        for quantity, (c, a, b, d) in self.terms.items():
            result[quantity] = c * U**a * G**b * W**d * R
        return result


@builtin
@attrs.frozen
class Grubin(LinePowerLaw):
    """Grubin (1949) inlet-zone estimate of the central film of a line contact.

    .. math:: \\frac{h_c}{R} = 1.95\\,(G U)^{8/11}\\,W'^{-1/11}

    Delabenetta (2021) Eq. 40 writes it as 0.975 R_x (UG)^0.727 W^-0.091 with R_x = 2R and
    attributes it to Dowson–Higginson (its erratum 12). Its exponents are rounded to three
    decimals, which lowers the film by about 0.5 %; ``exponent_digits=3`` reproduces that.

    Parameters
    ----------
    exponent_digits : int, optional
        None (default): exact exponents 8/11 and -1/11; 3: rounded as Delabenetta (2021).

    References
    ----------
    Grubin, A.N. (1949) TsNIITMASh book 30, Moscow (DSIR translation 337); as in Saccheto
    (2008) Eq. 4.41 and Delabenetta (2021) Eq. 40.
    """

    name = "grubin"
    reference = "Grubin (1949) TsNIITMASh 30; Saccheto (2008) Eq. 4.41; Delabenetta (2021) Eq. 40"
    provides = ("h_c",)
    validity = DOWSON_RANGE

    exponent_digits: int | None = None

    @property
    def terms(self):  # type: ignore[override]
        """``{"h_c": (1.95, a, a, d)}``, the (c, a, b, d) of H_c = c U^a G^b W'^d with a = 8/11, d = -1/11 [-]
        (rounded to ``exponent_digits`` if set)."""
        a, d = 8.0 / 11.0, -1.0 / 11.0
        if self.exponent_digits is not None:
            a, d = round(a, self.exponent_digits), round(d, self.exponent_digits)
        return {"h_c": (1.95, a, a, d)}


@builtin
class DowsonHigginson(LinePowerLaw):
    """Dowson–Higginson (1977) minimum film of an isothermal line contact.

    .. math:: \\frac{h_{min}}{R} = 2.65\\,U^{0.70}\\,G^{0.54}\\,W'^{-0.13}

    References
    ----------
    Dowson, D. & Higginson, G.R. (1977) Elasto-hydrodynamic Lubrication, SI ed., Pergamon;
    Delabenetta (2021) Eq. 41 (in R_x = 2R notation: 1.325 R_x ...); Tsuha (2015) §2.12 check.
    Validity: Dowson's ranges W' 3e-5..3e-4 and U 1e-13..1e-8 (Saccheto 2008 §4.2).
    """

    name = "dowson_higginson"
    reference = "Dowson & Higginson (1977) Elasto-hydrodynamic Lubrication; Delabenetta (2021) Eq. 41"
    provides = ("h_min",)
    terms = {"h_min": (2.65, 0.70, 0.54, -0.13)}
    validity = DOWSON_RANGE


@builtin
class DowsonToyoda(LinePowerLaw):
    """Dowson–Toyoda (1979) central film of an isothermal line contact.

    .. math:: \\frac{h_c}{R} = 3.06\\,U^{0.69}\\,G^{0.56}\\,W'^{-0.10}

    References
    ----------
    Dowson, D. & Toyoda, S. (1979) A central film thickness formula for elastohydrodynamic
    line contacts, Proc. 5th Leeds–Lyon Symp., 60–65.
    """

    name = "dowson_toyoda"
    reference = "Dowson & Toyoda (1979) Proc. 5th Leeds-Lyon Symp. 60-65"
    provides = ("h_c",)
    terms = {"h_c": (3.06, 0.69, 0.56, -0.10)}
    validity = DOWSON_RANGE


@builtin
class PanHamrock(LinePowerLaw):
    """Pan–Hamrock (1989) minimum and central films of a line contact.

    .. math::
        \\frac{h_{min}}{R} = 1.714\\,W'^{-0.128}\\,U^{0.694}\\,G^{0.568}, \\qquad
        \\frac{h_c}{R} = 2.922\\,W'^{-0.166}\\,U^{0.692}\\,G^{0.470}

    References
    ----------
    Pan, P. & Hamrock, B.J. (1989) Simple formulas for performance parameters used in
    elastohydrodynamically lubricated line contacts, J. Tribol. 111:246–251.
    """

    name = "pan_hamrock"
    reference = "Pan & Hamrock (1989) J. Tribol. 111:246-251"
    provides = ("h_min", "h_c")
    terms = {
        "h_min": (1.714, 0.694, 0.568, -0.128),
        "h_c": (2.922, 0.692, 0.470, -0.166),
    }
    #: the fitted range of Pan & Hamrock's own solutions is not in the project's references
    validity = DOWSON_RANGE


@builtin
@attrs.frozen
class Moes(FilmModel):
    """Moes (1992) central film of a line contact, valid over all four EHL regimes.

    Film from :func:`~camcontact.ehl.film_formulas.moes_line_film` in the Moes groups M = W'(2U)^-1/2, L = G(2U)^1/4,
    h_c = H R (2U)^1/2 (sum speed 2u_m). It can represent a scene without piezoviscosity
    (alpha = 0, L = 0) and without elasticity (rigid asymptotes).

    Moes's H is the film where dp/dx = 0 (the "Couette" film). Under EHL conditions that
    is the central film; in the rigid-isoviscous limit it is 1.226 times the film at the
    centre (H_RI = 3/M against Martin's 2.447/M: the factor is 1 + X_e^2 with Martin's
    outlet X_e = 0.4751). The interpolation is built from the four asymptotes and has no
    range restriction; independent numerical solutions (Barus, incompressible) lie within
    about -7 % .. +5.5 % of it for M = 10..200, L = 0..20.

    Parameters
    ----------
    piezoviscosity, elasticity : bool
        Set False to switch the effect off (the Analysis does this from the scene).

    References
    ----------
    Moes, H. (1992) Optimum similarity analysis with applications to elastohydrodynamic
    lubrication, Wear 159:57–66; as given by Venner & Lubrecht (2000) Multilevel Methods
    in Lubrication, Elsevier, ch. 8.
    """

    name = "moes"
    reference = "Moes (1992) Wear 159:57-66; Venner & Lubrecht (2000) ch. 8"
    geometry = "line"
    requires = LINE_INPUTS
    provides = ("h_c",)
    can_disable = ("piezoviscosity", "elasticity")

    piezoviscosity: bool = True
    elasticity: bool = True

    def evaluate(self, R, w, E_reduced, u_m, eta0, alpha):
        """Central film [m] and groups for R [m], w [N/m], E' [Pa], u_m [m/s], eta0 [Pa*s], alpha [1/Pa]."""
        if not self.piezoviscosity:
            alpha = 0.0 * np.asarray(alpha, dtype=float)
        U, G, W = _line_groups(R, w, E_reduced, u_m, eta0, alpha, self.name)
        M, L = moes_line(U, G, W)
        H = moes_line_film(M, L, elasticity=self.elasticity)
        return {"h_c": H * R * np.sqrt(2.0 * U), "U": U, "G": G, "W": W, "M": M, "L": L}
