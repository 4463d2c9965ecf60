"""Result of a line-contact EHL solve: fields, derived film values, convergence record."""

from __future__ import annotations

import math

import attrs
import numpy as np

from .line_problem import LineEHLProblem

__all__ = ["ConvergenceRecord", "LineEHLSolution"]


@attrs.frozen
class ConvergenceRecord:
    """What a solver did: per-cycle (or per-iteration) history and the verdict.

    ``residuals`` are h-scaled mean absolute complementarity residuals of the Reynolds
    equation on the finest grid; ``load_errors`` the load-balance errors
    h sum P - pi/2; ``work_units`` the cumulative work in finest-grid relaxation sweeps;
    ``wall_time`` the wall-clock time of the solve [s].
    """

    method: str
    levels: int
    nodes: int
    residuals: tuple[float, ...]
    load_errors: tuple[float, ...]
    work_units: tuple[float, ...]
    wall_time: float
    converged: bool
    message: str = ""
    tolerance: float = float("nan")

    @property
    def cycles(self) -> int:
        """Number of cycles (or iterations) recorded [-]."""
        return len(self.residuals)

    def to_frame(self):
        """pandas DataFrame with one row per cycle."""
        import pandas as pd

        return pd.DataFrame({
            "cycle": np.arange(1, self.cycles + 1),
            "residual [-]": self.residuals,
            "load error [-]": self.load_errors,
            "work units [-]": self.work_units,
        })

    def summary(self) -> str:
        """One line: method, verdict, cycles, last residual, grid and wall time (in ms)."""
        state = "converged" if self.converged else "NOT converged"
        last = f"{self.residuals[-1]:.3g}" if self.residuals else "n/a"
        return (f"{self.method}: {state} in {self.cycles} cycles, residual {last}, "
                f"{self.nodes} nodes / {self.levels} levels, {1e3 * self.wall_time:.1f} ms. {self.message}")


@attrs.frozen
class LineEHLSolution:
    """Converged (or best) discrete solution of a :class:`~camcontact.ehl.line_problem.LineEHLProblem`.

    Dimensionless fields on the grid: ``X`` (x/b), ``P`` (p/p_h), ``H`` (h R/b^2), and ``H0``.
    """

    problem: LineEHLProblem
    level: int
    X: np.ndarray = attrs.field(repr=False, eq=False)
    P: np.ndarray = attrs.field(repr=False, eq=False)
    H: np.ndarray = attrs.field(repr=False, eq=False)
    H0: float
    record: ConvergenceRecord
    #: the solver settings that produced the solution (multigrid: the attempt that was kept)
    settings: object = attrs.field(default=None, eq=False)
    #: film fraction per node of a mass-conserving solve (None: a full film, the Reynolds cavitation model)
    theta: np.ndarray | None = attrs.field(default=None, repr=False, eq=False)
    #: flow factors (a, k) of the Poiseuille coefficient and Couette factor c of the wedge per node, shape (n, 3) (or
    #: (n, 2): c = 1) (None: (1, 0, 1), the isothermal Newtonian film; see
    #: :func:`camcontact.ehl.line_multigrid.solve_multigrid`)
    flow_factor: np.ndarray | None = attrs.field(default=None, repr=False, eq=False)

    @property
    def poiseuille_factor(self) -> np.ndarray:
        """F = a sqrt(1 + (k eta-bar(P))^2) [-] per node: the factor on the Poiseuille coefficient (1 isothermal
        Newtonian; :func:`camcontact.ehl._kernels.flow_factor`)."""
        if self.flow_factor is None:
            return np.ones_like(self.P)
        return self.problem.poiseuille_factor(self.P, self.flow_factor[:, 0], self.flow_factor[:, 1])

    @property
    def couette_factor(self) -> np.ndarray:
        """c [-] per node: the factor on the wedge's entrainment flux, u_e = c u_m (1: a film whose viscosity does
        not vary across it; :func:`camcontact.ehl.line_multigrid.solve_multigrid`)."""
        if self.flow_factor is None or self.flow_factor.shape[1] < 3:
            return np.ones_like(self.P)
        return self.flow_factor[:, 2]

    @property
    def film_fraction(self) -> np.ndarray:
        """theta [-] per node: the fraction of the gap filled with lubricant (1 where P > 0; all 1 unless
        the problem's cavitation is mass-conserving)."""
        return np.ones_like(self.P) if self.theta is None else self.theta

    @property
    def inlet_meniscus(self) -> float | None:
        """X where the film becomes full when the inlet is starved (the film fraction at X_a below 1), else None."""
        if self.theta is None or not self.theta[0] < 1.0:
            return None
        full = np.flatnonzero(self.theta >= 1.0)
        return float(self.X[full[0]]) if full.size else None

    @property
    def content(self) -> np.ndarray:
        """Lubricant content q = theta rho H per node [-] (mass per area in units of rho_0 b^2/R)."""
        return self.film_fraction * self.problem.density_ratio(self.P) * self.H

    @property
    def mass_flux(self) -> np.ndarray:
        """Discrete mass flux F = q - xi dP/dX [-] through the n - 1 cell faces, in units of rho_0 u_m b^2/R,
        in the conservative form of the solver's operator: F_(i+1/2) = G_i - xi_(i+1/2) (P_(i+1) - P_i)/h with
        the limited upwind wedge flux G_i = q_i + phi_i (q_i - q_(i-1))/2, phi_i = 1 where node i - 1 carries a
        full film and 0 elsewhere (:func:`camcontact.ehl._kernels.wedge_weight`; G_0 = q_0 + phi_1 (q_1 - q_0)/2 for the
        first-order first node),
        so that F_(i+1/2) - F_(i-1/2) = -h L_i: constant where the discrete Reynolds equation holds,
        through pressurised and cavitated nodes alike (mass conservation). Steady operator (s = 1); the wedge
        carries c q (c the Couette factor, :attr:`couette_factor`)."""
        problem, P, H = self.problem, self.P, self.H
        h = float(self.X[1] - self.X[0])
        q = self.content * self.couette_factor
        xi = problem.flow_coefficient(P, H)
        if self.flow_factor is not None:
            xi = xi * self.poiseuille_factor
        full = (P > 0.0) | (self.film_fraction >= 1.0)
        phi = np.where(full[:-2], 0.5, 0.0)  # limiter of faces 1..n-2: the upstream node (kernels' wedge_weight)
        G = np.empty(P.size - 1)
        G[1:] = q[1:-1] + phi * (q[1:-1] - q[:-2])
        G[0] = q[0] + phi[0] * (q[1] - q[0])
        return G - 0.5 * (xi[:-1] + xi[1:]) * np.diff(P) / h

    @property
    def H_min(self) -> float:
        """Minimum film H_min = min H over the grid."""
        return float(self.H.min())

    @property
    def X_min(self) -> float:
        """Position of the minimum film."""
        return float(self.X[int(np.argmin(self.H))])

    @property
    def H_c(self) -> float:
        """Central film H(0), linearly interpolated between the nodes around X = 0."""
        return float(np.interp(0.0, self.X, self.H))

    @property
    def P_max(self) -> float:
        """Maximum pressure P_max = max P over the grid (p_max/p_h) [-]."""
        return float(self.P.max())

    @property
    def rolling_moment(self) -> float:
        """T = (1/2) int H dP/dX dX [-], in units of p_h b^2 per unit length: the moment about the roller's centre of
        the Poiseuille shear stresses tau(y = h) = (h/2) dp/dx that resist pure rolling (entrainment towards +X),
        Biboulet & Houpert (2010) Eqs. 23 and 43 (their T_t^x, whose factor 1 + (H0 - H)/R-bar^2 is 1 to within
        (b/R)^2; their X runs against the entrainment, hence their sign). The hydrodynamic rolling force is
        T/R-bar (f = t/R dimensionally, :meth:`dimensional`); its fully flooded EHL value is about
        1.45 M^-3/2 (their Eq. 41). Summed exactly for pressures linear between the nodes (the film at the
        cells' midpoints); upstream of a starved inlet's meniscus P = 0 adds nothing.

        Biboulet, N. & Houpert, L. (2010) Hydrodynamic force and moment in pure rolling lubricated contacts.
        Part 1: line contacts. Proc. IMechE J 224, 765-775."""
        return float(0.5 * np.sum(0.5 * (self.H[1:] + self.H[:-1]) * np.diff(self.P)))

    @property
    def spike(self) -> tuple[float, float] | None:
        """(P_s, X_s) of the pressure spike: the most downstream of two or more local maxima of P
        higher than 5 % of the maximum pressure (None when there is a single maximum, i.e. no
        distinct spike)."""
        P = self.P
        interior = np.arange(1, P.size - 1)
        significant = P[interior] > 0.05 * P.max()
        peaks = interior[(P[interior] > P[interior - 1]) & (P[interior] >= P[interior + 1]) & significant]
        if peaks.size < 2:
            return None
        last = int(peaks[-1])
        return float(P[last]), float(self.X[last])

    # ---------------------------------------------------------------- dimensional
    def dimensional(self, R: float, w: float, E_reduced: float) -> dict:
        """SI fields and films of the contact the problem came from: R [m], w [N/m], E' [Pa]; with the hydrodynamic
        ``rolling_moment`` t [N m/m] and ``rolling_force`` t/R [N/m] per unit length (:attr:`rolling_moment`)."""
        scales = self.problem.scales(R, w, E_reduced)
        spike = self.spike
        return {
            "x": self.X * scales["b"], "p": self.P * scales["p_h"], "h": self.H * scales["h_scale"],
            "h_min": self.H_min * scales["h_scale"], "x_min": self.X_min * scales["b"],
            "h_c": self.H_c * scales["h_scale"], "p_max": self.P_max * scales["p_h"],
            "p_spike": None if spike is None else spike[0] * scales["p_h"],
            "x_spike": None if spike is None else spike[1] * scales["b"],
            "b": scales["b"], "p_h": scales["p_h"],
            "rolling_moment": self.rolling_moment * scales["p_h"] * scales["b"] ** 2,
            "rolling_force": self.rolling_moment * scales["p_h"] * scales["b"] ** 2 / R,
        }

    def traction_profile(self):
        """The pressure and film of this solution for the fluid traction of the same contact, a
        :class:`camcontact.contact.fluid_traction.PressureProfile`: x/b = X, p/p_h = P (the problem's
        pressure scale is the Hertz p_h, ``from_contact``) and h(x)/h_c = H/H_c, H_c = H(0) interpolated
        (:attr:`H_c`, the central film that :meth:`dimensional` and the multigrid film model report as
        h_c = H_c b^2/R). Use with ``p_h`` and ``film_thickness = h_c`` of :meth:`dimensional`."""
        from ..contact.fluid_traction import PressureProfile

        return PressureProfile(x_ratio=self.X, pressure_ratio=self.P, film_ratio=self.H / self.H_c)

    def moes_film(self) -> tuple[float, float]:
        """(H_c, H_min) in Moes's scaling H_Moes = (h/R)(2U)^-1/2 = (8 M / pi) H."""
        factor = 8.0 * self.problem.M / math.pi
        return self.H_c * factor, self.H_min * factor

    def plot(self, ax=None):
        """Pressure and film over X (matplotlib); with a film fraction (mass-conserving cavitation, starved
        inlet), theta on the pressure axis, dashed, and the meniscus marked."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 4))
        ax.plot(self.X, self.P, label="P = p/p_h")
        title = f"M = {self.problem.M:.4g}, L = {self.problem.L:.4g}, {self.X.size} nodes"
        if self.theta is not None:
            ax.plot(self.X, self.theta, color="tab:green", linestyle="--", label="θ (film fraction)")
            if self.inlet_meniscus is not None:
                ax.axvline(self.inlet_meniscus, color="0.5", linewidth=0.8)
                title += f", starved: meniscus X = {self.inlet_meniscus:.3g}"
        ax.set(xlabel="X = x/b", ylabel="P, θ" if self.theta is not None else "P", title=title)
        twin = ax.twinx()
        twin.plot(self.X, self.H, color="tab:orange", label="H = h R/b²")
        twin.set_ylabel("H")
        twin.set_ylim(0, max(4 * self.H_min, 1e-12) if self.H_min > 0 else None)
        lines = ax.get_legend_handles_labels()[0] + twin.get_legend_handles_labels()[0]
        ax.legend(lines, [line.get_label() for line in lines], loc="upper left", fontsize=8)
        return ax
