"""The steady isothermal line-contact EHL problem in Hertz dimensionless form.

Unknowns: pressure P(X) = p/p_h and the rigid-body constant H0; X = x/b, H = h R/b^2.

.. math::
    \\frac{d}{dX}\\left(\\xi \\frac{dP}{dX}\\right) - \\frac{d(\\bar\\rho H)}{dX} = 0,\\quad
    \\xi = \\frac{\\bar\\rho H^3}{\\bar\\eta \\lambda},\\quad P \\ge 0 \\ (\\text{cavitation}),\\quad
    P(X_a) = P(X_b) = 0

    H(X) = H_0 + \\frac{X^2}{2} - \\frac{1}{\\pi}\\int \\ln|X - X'|\\,P(X')\\,dX', \\qquad
    \\int P\\,dX = \\frac{\\pi}{2}

with lambda = 3 pi^2/(8 M^2) and alpha-bar = alpha p_h = L sqrt(M/(2 pi)) from the Moes
parameters M = W'(2U)^-1/2, L = G(2U)^1/4 (sum speed; Tsuha 2015 reference §0 item 7, which
corrects its printed Eqs. 4.34-4.35). Viscosity: Roelands
eta-bar = exp{(alpha p0/z)[-1 + (1 + P p_h/p0)^z]} or Barus exp(alpha-bar P); density:
Dowson–Higginson (5.9e8 + 1.34 P p_h)/(5.9e8 + P p_h) or incompressible (Tsuha 2015 Eqs.
4.20–4.28; Venner & Lubrecht 2000).

Discretisation (Tsuha 2015 §5.3, which reproduces its Table 5.1): uniform grid on
[X_a, X_b] (default [-4, 1.5]) with n_k = 14 * 2^(k-1) + 1 nodes at level k; central
Poiseuille term with xi at half points as the mean of the nodes; second-order upwind wedge
(first order at the first interior node); deformation with piecewise-constant pressure,
K_ij = int_{X_j - h/2}^{X_j + h/2} ln|X_i - X'| dX'; trapezoidal load balance.
"""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..errors import InputError

__all__ = ["CAVITATION_MODELS", "LineEHLProblem", "grid_points", "kernel_coefficients", "roelands_alpha"]

ROELANDS_P0 = 1.96e8
#: cavitation models of the line problems: clipping with the Reynolds exit condition, or mass-conserving (JFO)
CAVITATION_MODELS = ("reynolds", "mass_conserving")
DH_A, DH_B = 5.9e8, 1.34


def grid_points(level: int, coarsest: int = 14) -> int:
    """Nodes of grid level ``level`` (1 = coarsest): coarsest * 2^(level-1) + 1."""
    if level < 1:
        raise InputError(f"grid level {level!r} must be >= 1")
    return coarsest * 2 ** (level - 1) + 1


def kernel_coefficients(h: float, count: int) -> np.ndarray:
    """K(d) = int_{-h/2}^{h/2} ln|d h - s| ds for d = 0..count-1 (Tsuha 2015 Eq. 5.46, in X units).

    The deformation matrix is Toeplitz and symmetric: K_ij = K(|i - j|).
    """
    d = np.arange(count, dtype=float)

    def antiderivative(t):
        t = np.abs(t)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(t > 0, t * (np.log(t) - 1.0), 0.0)

    upper = (d + 0.5) * h
    lower = (d - 0.5) * h
    # int_{lower}^{upper} ln|t| dt, split at 0 for d = 0 (odd antiderivative)
    return np.where(d == 0, 2.0 * antiderivative(0.5 * h), antiderivative(upper) - np.sign(lower) * antiderivative(lower))


def roelands_alpha(alpha: float, alpha_bar: float, pressure_scale: float | None) -> float:
    """alpha [1/Pa] of the Roelands law of a problem with the dimensionless alpha-bar and, if given, a pressure scale
    p_h [Pa]: alpha-bar / p_h, so that the law is the one L describes whatever the scale - ``alpha`` itself when
    p_h = alpha-bar / alpha (as from a contact), 0 at L = 0 (isoviscous: the scale then only serves the density law).
    Taking ``alpha`` at a scale that does not match (L = 0, or the continuation path of a start solution, which
    changes M and L at a fixed scale) would leave the law that of alpha at p_h, whatever L."""
    if pressure_scale is None or math.isclose(alpha * pressure_scale, alpha_bar, rel_tol=1e-9):
        return alpha
    return alpha_bar / pressure_scale


@attrs.frozen
class LineEHLProblem:
    """Dimensionless line-contact EHL problem (see the module docstring).

    Parameters
    ----------
    M, L : float
        Moes load and lubricant parameters (sum-speed convention), M > 0, L >= 0.
    viscosity : str
        ``"roelands"`` or ``"barus"``.
    density : str
        ``"dowson_higginson"`` or ``"incompressible"``.
    alpha : float
        Pressure–viscosity coefficient [1/Pa]; with alpha-bar it fixes the pressure scale
        p_h = alpha-bar/alpha that the Roelands and Dowson–Higginson laws need.
    pressure_scale : float, optional
        p_h [Pa] given directly (needed when L = 0 and the density law is compressible).
    z : float
        Roelands index (the Roelands law uses alpha p0 / z as its exponent factor).
    p0 : float
        Roelands reference pressure [Pa].
    elastic : bool
        False for rigid surfaces (no deformation term).
    domain : (float, float)
        (X_a, X_b) in units of the Hertz half-width b.
    cavitation : str
        ``"reynolds"`` (default): cavitation by clipping, P >= 0 with the Reynolds (Swift–Stieber) exit
        condition and a full film everywhere; ``"mass_conserving"``: the Jakobsson–Floberg–Olsson model
        through the film fraction theta (Elrod 1981; complementarity form of Giacopini et al. 2010),
        which conserves the lubricant through cavitated and starved regions. Steady and flooded, both
        give the same pressure (JFO rupture is the Reynolds condition in a steady line contact); the
        mass-conserving one also gives the film fraction behind the exit
        (:attr:`~camcontact.ehl.line_solution.LineEHLSolution.mass_flux` is then constant), and it is the
        model of a starved inlet.
    supply : float, optional
        Starvation: the content of the inlet layer H_oil = h_oil R/b^2 [-] carried into the domain at
        X_a (h_oil the lubricant layer on both surfaces together, ahead of the contact, at ambient
        density); None: flooded. Needs ``cavitation="mass_conserving"``; solved by
        :func:`camcontact.ehl.line_starved.solve_starved`.
    """

    M: float
    L: float
    viscosity: str = "roelands"
    density: str = "dowson_higginson"
    alpha: float = 2.2e-8
    z: float = 0.68
    p0: float = ROELANDS_P0
    elastic: bool = True
    domain: tuple = (-4.0, 1.5)
    pressure_scale: float | None = None
    cavitation: str = "reynolds"
    supply: float | None = None

    def __attrs_post_init__(self):
        if not (self.M > 0 and math.isfinite(self.M)):
            raise InputError(f"LineEHLProblem.M = {self.M!r} must be finite and > 0")
        if not (self.L >= 0 and math.isfinite(self.L)):
            raise InputError(f"LineEHLProblem.L = {self.L!r} must be finite and >= 0")
        if self.viscosity not in ("roelands", "barus"):
            raise InputError(f"LineEHLProblem.viscosity = {self.viscosity!r}; allowed: 'roelands', 'barus'")
        if self.density not in ("dowson_higginson", "incompressible"):
            raise InputError(f"LineEHLProblem.density = {self.density!r}; allowed: 'dowson_higginson', 'incompressible'")
        if not (self.alpha > 0 and self.z > 0 and self.p0 > 0):
            raise InputError(f"LineEHLProblem: alpha = {self.alpha!r}, z = {self.z!r}, p0 = {self.p0!r} must be > 0")
        if self.pressure_scale is None and self.L == 0 and self.density == "dowson_higginson":
            raise InputError(
                "LineEHLProblem: with L = 0 the pressure scale p_h cannot follow from alpha-bar; the "
                "Dowson-Higginson density needs it (the viscosity is isoviscous at L = 0 and needs none): give "
                "pressure_scale [Pa] or use density='incompressible'"
            )
        if self.pressure_scale is not None and not self.pressure_scale > 0:
            raise InputError(f"LineEHLProblem.pressure_scale = {self.pressure_scale!r} must be > 0")
        if self.cavitation not in CAVITATION_MODELS:
            raise InputError(f"LineEHLProblem.cavitation = {self.cavitation!r}; allowed: {', '.join(CAVITATION_MODELS)}")
        if self.supply is not None:
            if not (isinstance(self.supply, (int, float)) and math.isfinite(self.supply) and self.supply > 0):
                raise InputError(f"LineEHLProblem.supply = {self.supply!r} must be a finite inlet layer H_oil > 0 "
                                 "(None: flooded)")
            if self.cavitation != "mass_conserving":
                raise InputError("LineEHLProblem.supply: a starved inlet needs cavitation='mass_conserving' (with "
                                 "the Reynolds condition the lubricant is not conserved and the supply has no effect)")
        xa, xb = self.domain
        if not (xa < -1.0 and xb > 1.0):
            raise InputError(f"LineEHLProblem.domain = {self.domain!r} must contain the Hertz contact [-1, 1]")

    # ---------------------------------------------------------------- parameters
    @property
    def lam(self) -> float:
        """lambda = 3 pi^2 / (8 M^2)."""
        return 3.0 * math.pi**2 / (8.0 * self.M**2)

    @property
    def alpha_bar(self) -> float:
        """alpha p_h = L sqrt(M / (2 pi))."""
        return self.L * math.sqrt(self.M / (2.0 * math.pi))

    @property
    def p_h(self) -> float:
        """Hertz pressure [Pa]: ``pressure_scale`` if given, else alpha-bar / alpha."""
        return self.pressure_scale if self.pressure_scale is not None else self.alpha_bar / self.alpha

    @property
    def alpha_law(self) -> float:
        """alpha [1/Pa] of the Roelands law (:func:`roelands_alpha`)."""
        return roelands_alpha(self.alpha, self.alpha_bar, self.pressure_scale)

    @property
    def law_codes(self) -> tuple[int, int]:
        """(viscosity, density) codes for the kernels: (0 Barus / 1 Roelands, 0 incompressible / 1 DH)."""
        return (1 if self.viscosity == "roelands" else 0, 1 if self.density == "dowson_higginson" else 0)

    @property
    def law_parameters(self) -> np.ndarray:
        """[alpha-bar, p_h/p0, alpha p0 / z, z, p_h/DH_A, DH_B] for the kernels."""
        return np.array([
            self.alpha_bar, self.p_h / self.p0, self.alpha_law * self.p0 / self.z, self.z,
            self.p_h / DH_A, DH_B,
        ])

    def grid(self, level: int, coarsest: int = 14) -> np.ndarray:
        """Nodes X of grid ``level``."""
        return np.linspace(self.domain[0], self.domain[1], grid_points(level, coarsest))

    # ---------------------------------------------------------------- lubricant laws (vectorised)
    def log_viscosity(self, P):
        """ln(eta-bar) at dimensionless pressure P."""
        P = np.maximum(np.asarray(P, dtype=float), 0.0)
        if self.viscosity == "barus":
            return self.alpha_bar * P
        return self.alpha_law * self.p0 / self.z * np.expm1(self.z * np.log1p(P * self.p_h / self.p0))

    def dlog_viscosity(self, P):
        """d ln(eta-bar) / dP."""
        P = np.maximum(np.asarray(P, dtype=float), 0.0)
        if self.viscosity == "barus":
            return np.full_like(P, self.alpha_bar)
        ratio = self.p_h / self.p0
        return self.alpha_law * self.p0 * ratio * (1.0 + P * ratio) ** (self.z - 1.0)

    def density_ratio(self, P):
        """rho-bar = rho/rho_0 [-] at dimensionless pressure P (Dowson–Higginson, or 1 if incompressible)."""
        P = np.maximum(np.asarray(P, dtype=float), 0.0)
        if self.density == "incompressible":
            return np.ones_like(P)
        p = P * self.p_h
        return (DH_A + DH_B * p) / (DH_A + p)

    def flow_coefficient(self, P, H):
        """xi = rho-bar H^3 / (eta-bar lambda) [-], the Poiseuille coefficient of a full film at P and H; zero where
        the gap is closed (H <= 0)."""
        return self.density_ratio(P) * np.maximum(H, 0.0) ** 3 * np.exp(-self.log_viscosity(P)) / self.lam

    def poiseuille_factor(self, P, a, k):
        """F = a sqrt(1 + (k eta-bar(P))^2) [-]: the flow factor on the Poiseuille coefficient of a film with the
        per-node factors a and Eyring coefficients k (:func:`camcontact.ehl._kernels.flow_factor`, vectorised)."""
        return a * np.sqrt(1.0 + (k * np.exp(self.log_viscosity(P))) ** 2)

    def ddensity_ratio(self, P):
        """d rho-bar / dP [-] (0 if incompressible)."""
        P = np.maximum(np.asarray(P, dtype=float), 0.0)
        if self.density == "incompressible":
            return np.zeros_like(P)
        p = P * self.p_h
        return self.p_h * DH_A * (DH_B - 1.0) / (DH_A + p) ** 2

    # ---------------------------------------------------------------- dimensional link
    @classmethod
    def from_contact(cls, *, R: float, w: float, E_reduced: float, u_m: float, eta0: float, alpha: float,
                     z: float | None = None, viscosity: str = "roelands", density: str = "dowson_higginson",
                     p0: float = ROELANDS_P0, elastic: bool = True, domain: tuple = (-4.0, 1.5)) -> LineEHLProblem:
        """Problem of a dimensional contact (SI): R [m], w [N/m], E' [Pa], u_m [m/s], eta0 [Pa*s], alpha [1/Pa].

        Moes groups with the sum speed 2 u_m; z defaults to the Roelands value consistent with
        eta0 and alpha (alpha p0 = z (ln eta0 + 9.67)).
        """
        if not u_m:
            raise InputError("line EHL: entrainment speed u_m = 0 has no steady solution")
        U = eta0 * abs(u_m) / (E_reduced * R)
        W = w / (E_reduced * R)
        M = W * (2.0 * U) ** -0.5
        L = alpha * E_reduced * (2.0 * U) ** 0.25
        if alpha > 0 and z is None and viscosity == "roelands":
            margin = math.log(eta0) + 9.67
            if margin <= 0:
                raise InputError(f"line EHL: eta0 = {eta0!r} Pa*s is below the Roelands eta_inf")
            z = alpha * p0 / margin
        b = math.sqrt(8.0 * w * R / (math.pi * E_reduced))
        return cls(M=M, L=L, viscosity=viscosity if alpha > 0 else "barus", density=density,
                   alpha=alpha if alpha > 0 else 1.0, z=z if z else 0.68, p0=p0, elastic=elastic,
                   domain=domain, pressure_scale=2.0 * w / (math.pi * b))

    def scales(self, R: float, w: float, E_reduced: float) -> dict:
        """Hertz scales of a dimensional contact: b [m], p_h [Pa] and h_scale = b^2/R [m]."""
        b = math.sqrt(8.0 * w * R / (math.pi * E_reduced))
        return {"b": b, "p_h": 2.0 * w / (math.pi * b), "h_scale": b * b / R}
