"""Result of a point-contact EHL solve: fields, film values, convergence record."""

from __future__ import annotations

import attrs
import numpy as np

from .line_solution import ConvergenceRecord
from .point_problem import PointEHLProblem

__all__ = ["ConvergenceRecord", "PointEHLSolution"]


@attrs.frozen
class PointEHLSolution:
    """Converged (or best) discrete solution of a :class:`~camcontact.ehl.point_problem.PointEHLProblem`.

    Dimensionless fields, indexed ``[j, i]`` = (Y_j, X_i): ``P`` (p/p_h) and ``H`` (h R_x/a^2) on the
    nodes ``X`` (x/a, entrainment direction) and ``Y`` (y/a); ``H0`` the film constant.
    """

    problem: PointEHLProblem
    level: int
    X: np.ndarray = attrs.field(repr=False, eq=False)
    Y: np.ndarray = attrs.field(repr=False, eq=False)
    P: np.ndarray = attrs.field(repr=False, eq=False)
    H: np.ndarray = attrs.field(repr=False, eq=False)
    H0: float
    record: ConvergenceRecord
    settings: object = attrs.field(default=None, eq=False)

    @property
    def H_min(self) -> float:
        """Minimum film over the grid."""
        return float(self.H.min())

    @property
    def min_location(self) -> tuple[float, float]:
        """(X, Y) of the minimum film."""
        j, i = np.unravel_index(int(np.argmin(self.H)), self.H.shape)
        return float(self.X[i]), float(self.Y[j])

    @property
    def H_c(self) -> float:
        """Central film H(0, 0) (the Hertz centre), bilinearly interpolated."""
        i = int(np.clip(np.searchsorted(self.X, 0.0) - 1, 0, self.X.size - 2))
        j = int(np.clip(np.searchsorted(self.Y, 0.0) - 1, 0, self.Y.size - 2))
        s = (0.0 - self.X[i]) / (self.X[i + 1] - self.X[i])
        t = (0.0 - self.Y[j]) / (self.Y[j + 1] - self.Y[j])
        H = self.H
        return float((1 - s) * (1 - t) * H[j, i] + s * (1 - t) * H[j, i + 1]
                     + (1 - s) * t * H[j + 1, i] + s * t * H[j + 1, i + 1])

    @property
    def P_max(self) -> float:
        """Maximum pressure P_max = max P over the grid (p_max/p_h) [-]."""
        return float(self.P.max())

    @property
    def centreline(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(X, P, H) along the row nearest Y = 0."""
        j = int(np.argmin(np.abs(self.Y)))
        return self.X, self.P[j], self.H[j]

    def moes_film(self) -> tuple[float, float]:
        """(H_c, H_min) in Moes's scaling (h/R_x)(2U)^-1/2 = (3M/2)^(2/3) H (Nijenbanning et al. 1994)."""
        factor = self.problem.moes_factor
        return self.H_c * factor, self.H_min * factor

    def dimensional(self, Rx: float, F: float, E_reduced: float) -> dict:
        """SI fields and films of the contact the problem came from: R_x [m], F [N], E' [Pa]."""
        scales = self.problem.scales(Rx, F, E_reduced)
        return {"x": self.X * scales["a"], "y": self.Y * scales["a"], "p": self.P * scales["p_h"],
                "h": self.H * scales["h_scale"], "h_c": self.H_c * scales["h_scale"],
                "h_min": self.H_min * scales["h_scale"], "p_max": self.P_max * scales["p_h"],
                "a": scales["a"], "p_h": scales["p_h"]}

    def plot(self, ax=None):
        """Pressure and film along the centreline Y = 0 (matplotlib)."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 4))
        X, P, H = self.centreline
        ax.plot(X, P, label="P = p/p_h")
        ax.set(xlabel="X = x/a", ylabel="P",
               title=f"M = {self.problem.M:.4g}, L = {self.problem.L:.4g}, D = {self.problem.D:.3g}, "
                     f"{self.X.size}x{self.Y.size}")
        twin = ax.twinx()
        twin.plot(X, H, color="tab:orange")
        twin.set_ylabel("H")
        twin.set_ylim(0, max(4 * self.H_min, 1e-12) if self.H_min > 0 else None)
        return ax
