"""The steady isothermal point (elliptical) contact EHL problem in Hertz dimensionless form.

Scales (Venner & Lubrecht 2000, ch. 8) of the *reference circular contact* on R_x:
a = (3 F R_x / (2 E'))^(1/3), p_h = 3 F / (2 pi a^2); X = x/a, Y = y/a, P = p/p_h,
H = h R_x / a^2. Unknowns: P(X, Y) and the rigid-body constant H0.

.. math::
    \\frac{\\partial}{\\partial X}\\left(\\varepsilon \\frac{\\partial P}{\\partial X}\\right)
    + \\frac{\\partial}{\\partial Y}\\left(\\varepsilon \\frac{\\partial P}{\\partial Y}\\right)
    - \\frac{\\partial(\\bar\\rho H)}{\\partial X} = 0, \\quad
    \\varepsilon = \\frac{\\bar\\rho H^3}{\\bar\\eta \\lambda}, \\quad P \\ge 0

    H = H_0 + \\frac{X^2}{2} + D\\frac{Y^2}{2}
        + \\frac{2}{\\pi^2}\\iint \\frac{P(X', Y')\\,dX'dY'}{\\sqrt{(X - X')^2 + (Y - Y')^2}}, \\qquad
    \\iint P\\,dX\\,dY = \\frac{2\\pi}{3}

with D = R_x/R_y (the gap h = x^2/(2R_x) + y^2/(2R_y)), lambda = 6 eta0 u_s R_x^2/(a^3 p_h)
= (128 pi^3 / (3 M^4))^(1/3) and alpha-bar = alpha p_h = (L/pi)(3M/2)^(1/3), from the Moes
point-contact parameters M = W (2U)^(-3/4), L = G (2U)^(1/4) (sum speed u_s = 2 u_m; U, G, W
of Hamrock on R_x; Nijenbanning, Venner & Moes 1994). The film in Moes's scaling is
H_Moes = (h/R_x)(2U)^(-1/2) = (3M/2)^(2/3) H. For D != 1 the dry contact is the Hertz ellipse
of semi-axes a_x, a_y (in units of a; :func:`camcontact.contact.hertz_elliptical.hertz_elliptical`)
with maximum pressure 1/(a_x a_y) in units of p_h. Viscosity (Roelands or Barus) and density
(Dowson–Higginson or incompressible) laws are those of
:class:`~camcontact.ehl.line_problem.LineEHLProblem`.

Discretisation (:mod:`camcontact.ehl._point_kernels`): uniform grid with the same number of
nodes n_k = coarsest 2^(k-1) + 1 in both directions (default coarsest = 16: 129, 257, 513 at
levels 4, 5, 6), spacings h_x, h_y; central Poiseuille terms with epsilon at the half points as
the mean of the nodes, second-order upwind wedge (first order at the first interior column);
deformation of piecewise-constant pressure over each h_x x h_y cell (exact rectangle integral,
Love 1929), summed by FFT convolution (DC-FFT, Liu, Wang & Liu 2000); load integral h_x h_y sum P.

References
----------
Venner, C.H. & Lubrecht, A.A. (2000) Multilevel Methods in Lubrication, Elsevier, ch. 8.
Nijenbanning, G., Venner, C.H. & Moes, H. (1994) Film thickness in elastohydrodynamically
lubricated elliptic contacts, Wear 176:217–229.
"""

from __future__ import annotations

import math
import numbers

import attrs
import numpy as np

from ..errors import InputError
from .line_problem import DH_A, DH_B, ROELANDS_P0, grid_points, roelands_alpha

__all__ = ["COARSEST", "PointEHLProblem", "point_grid_points"]

COARSEST = 16  #: intervals per direction of grid level 1
D_RANGE = (0.1, 10.0)  #: allowed D = Rx/Ry


def _real(value) -> bool:
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def point_grid_points(level: int, coarsest: int = COARSEST) -> int:
    """Nodes per direction of grid ``level`` (1 = coarsest): coarsest * 2^(level-1) + 1."""
    return grid_points(level, coarsest)


@attrs.frozen
class PointEHLProblem:
    """Dimensionless point/elliptical-contact EHL problem (see the module docstring).

    Parameters
    ----------
    M, L : float
        Moes point-contact load and lubricant parameters (sum speed, groups on R_x); M > 0, L >= 0.
    D : float
        Radius ratio R_x/R_y (1 circular; < 1 wide contact, the major axis across the flow;
        > 1 the major axis along the flow), 0.1 <= D <= 10.
    viscosity : str
        ``"roelands"`` or ``"barus"``.
    density : str
        ``"dowson_higginson"`` or ``"incompressible"``.
    alpha : float
        Pressure–viscosity coefficient [1/Pa]; fixes p_h = alpha-bar/alpha for the laws.
    z, p0 : float
        Roelands index [-] and reference pressure [Pa].
    pressure_scale : float, optional
        p_h [Pa] given directly (needed for L = 0 with a compressible density law).
    elastic : bool
        False for rigid surfaces.
    domain : ((float, float), (float, float))
        ((X_a, X_b), (Y_a, Y_b)) in units of the dry Hertz semi-axes a_x, a_y (so the default
        X in [-4.5, 1.5] a_x, Y in [-3, 3] a_y follows the contact's ellipticity).
    """

    M: float
    L: float
    D: float = 1.0
    viscosity: str = "roelands"
    density: str = "dowson_higginson"
    alpha: float = 2.2e-8
    z: float = 0.68
    p0: float = ROELANDS_P0
    pressure_scale: float | None = None
    elastic: bool = True
    domain: tuple = ((-4.5, 1.5), (-3.0, 3.0))

    def __attrs_post_init__(self):
        name = "PointEHLProblem"
        if not (_real(self.M) and math.isfinite(self.M) and self.M > 0):
            raise InputError(f"{name}.M = {self.M!r} must be finite and > 0")
        if not (_real(self.L) and math.isfinite(self.L) and self.L >= 0):
            raise InputError(f"{name}.L = {self.L!r} must be finite and >= 0")
        if not (_real(self.D) and D_RANGE[0] <= self.D <= D_RANGE[1]):
            raise InputError(f"{name}.D = Rx/Ry = {self.D!r} must lie in [{D_RANGE[0]}, {D_RANGE[1]}]")
        if self.viscosity not in ("roelands", "barus"):
            raise InputError(f"{name}.viscosity = {self.viscosity!r}; allowed: 'roelands', 'barus'")
        if self.density not in ("dowson_higginson", "incompressible"):
            raise InputError(f"{name}.density = {self.density!r}; allowed: 'dowson_higginson', 'incompressible'")
        for field in ("alpha", "z", "p0"):
            value = getattr(self, field)
            if not (math.isfinite(value) and value > 0):
                raise InputError(f"{name}.{field} = {value!r} must be finite and > 0")
        if self.pressure_scale is None and self.L == 0 and self.density == "dowson_higginson":
            raise InputError(f"{name}: with L = 0 the pressure scale p_h cannot follow from alpha-bar; the "
                             "Dowson-Higginson density needs it (the viscosity is isoviscous at L = 0 and needs none): "
                             "give pressure_scale [Pa] or use density='incompressible'")
        if self.pressure_scale is not None and not (math.isfinite(self.pressure_scale) and self.pressure_scale > 0):
            raise InputError(f"{name}.pressure_scale = {self.pressure_scale!r} must be finite and > 0 [Pa]")
        try:
            (xa, xb), (ya, yb) = self.domain
            valid = xa < -1.0 and xb > 1.0 and ya < -1.0 and yb > 1.0
        except (TypeError, ValueError):
            valid = False
        if not valid:
            raise InputError(f"{name}.domain = {self.domain!r} must be ((X_a, X_b), (Y_a, Y_b)) in units of the "
                             "Hertz semi-axes and contain the dry contact: X_a, Y_a < -1 and X_b, Y_b > 1")

    # ---------------------------------------------------------------- parameters
    @property
    def lam(self) -> float:
        """lambda = (128 pi^3 / (3 M^4))^(1/3)."""
        return (128.0 * math.pi**3 / (3.0 * self.M**4)) ** (1.0 / 3.0)

    @property
    def alpha_bar(self) -> float:
        """alpha p_h = (L / pi) (3 M / 2)^(1/3)."""
        return self.L / math.pi * (1.5 * self.M) ** (1.0 / 3.0)

    @property
    def p_h(self) -> float:
        """Reference Hertz pressure [Pa]: ``pressure_scale`` if given, else alpha-bar / alpha."""
        return self.pressure_scale if self.pressure_scale is not None else self.alpha_bar / self.alpha

    @property
    def moes_factor(self) -> float:
        """H_Moes / H = (3 M / 2)^(2/3)."""
        return (1.5 * self.M) ** (2.0 / 3.0)

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
        """[alpha-bar, p_h/p0, alpha p0 / z, z, p_h/5.9e8, 1.34] (the layout of :mod:`._kernels`)."""
        return np.array([self.alpha_bar, self.p_h / self.p0, self.alpha_law * self.p0 / self.z, self.z,
                         self.p_h / DH_A, DH_B])

    @property
    def semi_axes(self) -> tuple[float, float]:
        """Dry Hertz semi-axes (a_x, a_y) in units of the reference radius a (exact elliptic integrals)."""
        if self.D == 1.0:
            return 1.0, 1.0
        from ..contact.hertz_elliptical import hertz_elliptical

        contact = hertz_elliptical(1.0, 1.0, 1.0 / self.D, 1.0, method="exact")
        reference = 1.5 ** (1.0 / 3.0)
        return contact.a_x / reference, contact.a_y / reference

    @property
    def extent(self) -> tuple[float, float, float, float]:
        """(X_a, X_b, Y_a, Y_b) of the computational domain in units of a."""
        ax, ay = self.semi_axes
        (xa, xb), (ya, yb) = self.domain
        return xa * ax, xb * ax, ya * ay, yb * ay

    def grid(self, level: int, coarsest: int = COARSEST) -> tuple[np.ndarray, np.ndarray]:
        """Nodes (X, Y) of grid ``level`` (1-D arrays; fields are indexed [j, i] = (Y_j, X_i))."""
        n = point_grid_points(level, coarsest)
        xa, xb, ya, yb = self.extent
        return np.linspace(xa, xb, n), np.linspace(ya, yb, n)

    def hertz_pressure(self, X: np.ndarray, Y: np.ndarray) -> np.ndarray:
        """Dry Hertz pressure P(Y_j, X_i) on the grid: (1/(a_x a_y)) sqrt(1 - (X/a_x)^2 - (Y/a_y)^2)."""
        ax, ay = self.semi_axes
        s = 1.0 - (X[None, :] / ax) ** 2 - (Y[:, None] / ay) ** 2
        return np.sqrt(np.clip(s, 0.0, None)) / (ax * ay)

    # ---------------------------------------------------------------- dimensional link
    @classmethod
    def from_contact(cls, *, Rx: float, Ry: float, F: float, E_reduced: float, u_m: float, eta0: float,
                     alpha: float, z: float | None = None, viscosity: str = "roelands",
                     density: str = "dowson_higginson", p0: float = ROELANDS_P0, **kwargs) -> PointEHLProblem:
        """Problem of a dimensional contact (SI): Rx, Ry [m], F [N], E' [Pa], u_m [m/s] (mean
        entrainment speed), eta0 [Pa*s], alpha [1/Pa]. Moes groups with the sum speed 2 u_m; z
        defaults to the Roelands value consistent with eta0 and alpha (alpha p0 = z (ln eta0 + 9.67))."""
        from .groups import hamrock_point, moes_point

        for label, value in (("Rx", Rx), ("Ry", Ry), ("F", F), ("E_reduced", E_reduced), ("eta0", eta0)):
            if not (math.isfinite(value) and value > 0):
                raise InputError(f"point EHL: {label} = {value!r} must be finite and > 0")
        if not u_m:
            raise InputError("point EHL: entrainment speed u_m = 0 has no steady solution")
        U, G, W = hamrock_point(F, Rx, E_reduced, u_m, eta0, alpha)
        M, L = moes_point(U, G, W)
        if alpha > 0 and z is None and viscosity == "roelands":
            margin = math.log(eta0) + 9.67
            if margin <= 0:
                raise InputError(f"point EHL: eta0 = {eta0!r} Pa*s is below the Roelands eta_inf")
            z = alpha * p0 / margin
        a = (1.5 * F * Rx / E_reduced) ** (1.0 / 3.0)
        return cls(M=float(M), L=float(L), D=Rx / Ry, viscosity=viscosity if alpha > 0 else "barus",
                   density=density, alpha=alpha if alpha > 0 else 1.0, z=z if z else 0.68, p0=p0,
                   pressure_scale=1.5 * F / (math.pi * a * a), **kwargs)

    @staticmethod
    def scales(Rx: float, F: float, E_reduced: float) -> dict:
        """Scales of a dimensional contact: a [m], p_h [Pa], h_scale = a^2/R_x [m]."""
        a = (1.5 * F * Rx / E_reduced) ** (1.0 / 3.0)
        return {"a": a, "p_h": 1.5 * F / (math.pi * a * a), "h_scale": a * a / Rx}
