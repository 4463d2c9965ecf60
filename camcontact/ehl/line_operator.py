"""The discrete line-contact EHL operator (numpy): film, Reynolds residual, load balance.

Discretisation of Tsuha (2015) §5.3 (Eqs. 5.38–5.50), see :mod:`camcontact.ehl.line_problem`.
For interior nodes i = 1..n-2

.. math::
    L_i = \\frac{\\xi_{i-1/2}(P_{i-1} - P_i) + \\xi_{i+1/2}(P_{i+1} - P_i)}{h^2}
          - \\frac{1.5\\,\\bar\\rho_i H_i - 2\\,\\bar\\rho_{i-1} H_{i-1} + 0.5\\,\\bar\\rho_{i-2} H_{i-2}}{h}

(first-order wedge (rho H)_1 - (rho H)_0 at i = 1), xi_{i+-1/2} the mean of the nodal xi.
The discrete solution satisfies the complementarity conditions P_i >= 0, L_i <= 0,
P_i L_i = 0, and the load balance h sum_j (P_j + P_{j+1})/2 = pi/2.
"""

from __future__ import annotations

import math

import numpy as np

from .deformation import Deformation
from .line_problem import LineEHLProblem

__all__ = ["LineGrid"]


class LineGrid:
    """One grid of a :class:`LineEHLProblem`: nodes, spacing, deformation operator and residuals."""

    def __init__(self, problem: LineEHLProblem, n: int, deformation: str = "mlmi", compiled: bool = True,
                 correction: int | None = None):
        self.problem = problem
        self.n = int(n)
        self.X = np.linspace(problem.domain[0], problem.domain[1], self.n)
        self.h = float(self.X[1] - self.X[0])
        self.deformation = Deformation(self.n, self.h, deformation, correction=correction, compiled=compiled)
        self.parabola = 0.5 * self.X**2

    def film(self, P: np.ndarray, H0: float) -> np.ndarray:
        """H = H0 + X^2/2 - (1/pi) sum_j K_ij P_j (no deformation for rigid problems)."""
        if not self.problem.elastic:
            return H0 + self.parabola
        return H0 + self.parabola - self.deformation(P) / math.pi

    def xi(self, P: np.ndarray, H: np.ndarray) -> np.ndarray:
        """xi = rho H^3 / (eta lambda) at the nodes; zero where the gap is closed (H <= 0)."""
        return self.problem.flow_coefficient(P, H)

    def residual(self, P: np.ndarray, H: np.ndarray) -> np.ndarray:
        """L_i at interior nodes (zeros at the two boundary nodes)."""
        h = self.h
        xi = self.xi(P, H)
        q = self.problem.density_ratio(P) * H
        half = 0.5 * (xi[1:] + xi[:-1])  # xi_{i+1/2} for i = 0..n-2
        L = np.zeros(self.n)
        i = np.arange(1, self.n - 1)
        poiseuille = (half[i - 1] * (P[i - 1] - P[i]) + half[i] * (P[i + 1] - P[i])) / (h * h)
        wedge = np.empty(i.size)
        wedge[0] = q[1] - q[0]
        wedge[1:] = 1.5 * q[2:-1] - 2.0 * q[1:-2] + 0.5 * q[:-3]
        L[1:-1] = poiseuille - wedge / h
        return L

    def complementarity_residual(self, P: np.ndarray, H: np.ndarray) -> np.ndarray:
        """L_i where P_i > 0, max(L_i, 0) where P_i = 0 (zero for an exact discrete solution)."""
        L = self.residual(P, H)
        return np.where(P > 0.0, L, np.maximum(L, 0.0))

    def load_error(self, P: np.ndarray) -> float:
        """h sum_j (P_j + P_{j+1})/2 - pi/2 (trapezoidal load balance, Tsuha Eq. 5.50)."""
        return float(self.h * (P.sum() - 0.5 * (P[0] + P[-1])) - 0.5 * math.pi)
