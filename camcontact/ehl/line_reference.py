"""Dense Newton / complementarity reference solver for the line-contact EHL problem.

Solves the *same* discrete equations as the multigrid solver (:mod:`.line_operator`), with a
semi-smooth Newton method: each interior node contributes the Fischer–Burmeister equation
phi(P_i, -s_i L_i) = 0, phi(a, b) = a + b - sqrt(a^2 + b^2), which holds exactly when
P_i >= 0, L_i <= 0 and P_i L_i = 0 (s_i = 1/|dL_i/dP_i| scales the residual); the load
balance closes the system for H0. The Jacobian is assembled exactly and densely (the
deformation couples every node), so the cost is O(n^3) per iteration: meant for n up to about
2000, as an independent check of the multigrid solution (Tsuha 2015 reference §0 used the
same approach to reproduce its Table 5.1).
"""

from __future__ import annotations

import math
import time

import numpy as np

from ..errors import InputError, not_converged
from .film_formulas import moes_line_film
from .line_operator import LineGrid
from .line_problem import LineEHLProblem, grid_points, kernel_coefficients
from .line_solution import ConvergenceRecord, LineEHLSolution

__all__ = ["newton_complementarity", "solve_reference"]


def _jacobian(grid: LineGrid, P: np.ndarray, H: np.ndarray, K_over_pi: np.ndarray):
    """dL/dP (interior rows, all columns) and dL/dH0 of the discrete operator (vectorised)."""
    problem, h, n = grid.problem, grid.h, grid.n
    rho = problem.density_ratio(P)
    active = P >= 0.0  # the laws use max(P, 0): right-hand derivatives at 0, none below
    drho = problem.ddensity_ratio(P) * active
    e = np.exp(-problem.log_viscosity(P))
    dlogeta = problem.dlog_viscosity(P) * active
    open_gap = np.maximum(H, 0.0)  # closed gaps (H <= 0) pass no pressure flow
    xi = rho * open_gap**3 * e / problem.lam
    dxi_dH = 3.0 * rho * open_gap**2 * e / problem.lam
    with np.errstate(divide="ignore", invalid="ignore"):
        dxi_dP = xi * (np.where(rho > 0, drho / rho, 0.0) - dlogeta)
    half = 0.5 * (xi[1:] + xi[:-1])
    i = np.arange(1, n - 1)
    hh = h * h
    a = (P[i - 1] - P[i]) / hh
    c = (P[i + 1] - P[i]) / hh
    direct = np.zeros((n, n))  # explicit dependence on P (same node / neighbours)
    dL_dH = np.zeros((n, n))  # dependence through the nodal films H_m
    direct[i, i - 1] += half[i - 1] / hh
    direct[i, i] -= (half[i - 1] + half[i]) / hh
    direct[i, i + 1] += half[i] / hh
    for offset, weight in ((-1, 0.5 * a), (0, 0.5 * (a + c)), (1, 0.5 * c)):
        m = i + offset
        direct[i, m] += weight * dxi_dP[m]
        dL_dH[i, m] += weight * dxi_dH[m]
    # wedge: first-order at i = 1, second-order upwind elsewhere
    wedge = [((0, 1.0), (1, -1.0))] + [((0, 1.5), (1, -2.0), (2, 0.5))] * (n - 3)
    for k, weight in ((0, 1.5), (1, -2.0), (2, 0.5)):
        rows = i[1:]
        m = rows - k
        direct[rows, m] -= weight * drho[m] * H[m] / h
        dL_dH[rows, m] -= weight * rho[m] / h
    for k, weight in wedge[0]:
        m = 1 - k
        direct[1, m] -= weight * drho[m] * H[m] / h
        dL_dH[1, m] -= weight * rho[m] / h
    if problem.elastic:
        J_P = direct - dL_dH @ K_over_pi
    else:
        J_P = direct
    J_H0 = dL_dH.sum(axis=1)
    return J_P, J_H0


def _fischer_burmeister(a, b):
    r = np.hypot(a, b)  # no overflow for huge residuals of a wild iterate
    phi = a + b - r
    safe = np.where(r > 0, r, 1.0)
    da = np.where(r > 0, 1.0 - a / safe, 1.0 - 1.0 / math.sqrt(2.0))
    db = np.where(r > 0, 1.0 - b / safe, 1.0 - 1.0 / math.sqrt(2.0))
    return phi, da, db


def _initial_guess(grid: LineGrid):
    X = grid.X
    P = np.where(np.abs(X) < 1.0, np.sqrt(np.clip(1.0 - X * X, 0.0, None)), 0.0)
    P *= 0.5 * math.pi / (grid.h * P.sum())
    # choose H0 so that the film at the centre is the Moes estimate (in Hertz units)
    target = moes_line_film(grid.problem.M, grid.problem.L) * math.pi / (8.0 * grid.problem.M)
    H_zero = grid.film(P, 0.0)
    H0 = target - float(np.interp(0.0, X, H_zero))
    return P, H0


def newton_complementarity(grid: LineGrid, P: np.ndarray, H0: float, *, f: np.ndarray | None = None,
                           f_load: float = 0.0, K_over_pi: np.ndarray | None = None, tolerance: float = 1e-10,
                           max_iterations: int = 200):
    """Semi-smooth Newton for L(P, H0) = f (complementarity) and h sum P - pi/2 = f_load on one grid.

    Returns (P, H0, residual history, load-error history, converged, message). ``f`` and
    ``f_load`` are the FAS right-hand sides when used as the coarsest-grid solver of the
    multigrid cycles (zero for the plain problem).
    """
    n = grid.n
    problem = grid.problem
    f = np.zeros(n) if f is None else f
    if problem.elastic and K_over_pi is None:
        table = kernel_coefficients(grid.h, n)
        K_over_pi = table[np.abs(np.arange(n)[:, None] - np.arange(n)[None, :])] / math.pi
    P = P.copy()
    interior = np.arange(1, n - 1)
    m = interior.size

    def state(P, H0):
        H = grid.film(P, H0)
        return H, grid.residual(P, H) - f

    residuals, loads = [], []
    H, L = state(P, H0)
    message = ""
    converged = False
    for _ in range(max_iterations):
        with np.errstate(over="ignore", invalid="ignore"):
            J_P, J_H0 = _jacobian(grid, P, H, K_over_pi)
        if not (np.all(np.isfinite(J_P)) and np.all(np.isfinite(J_H0))):
            message = "non-finite Newton matrix (pressures beyond the viscosity law's range)"
            break
        scale = 1.0 / np.maximum(np.abs(np.diag(J_P))[interior], 1e-300)
        phi, da, db = _fischer_burmeister(P[interior], -scale * L[interior])
        load = grid.load_error(P) - f_load
        residual = float(np.max(np.abs(phi))) if phi.size else 0.0
        residuals.append(residual)
        loads.append(load)
        if residual < tolerance and abs(load) < tolerance:
            converged = True
            break
        A = np.zeros((m + 1, m + 1))
        A[:m, :m] = -(db * scale)[:, None] * J_P[np.ix_(interior, interior)]
        A[np.arange(m), np.arange(m)] += da
        A[:m, m] = -db * scale * J_H0[interior]
        A[m, :m] = grid.h
        try:
            step = np.linalg.solve(A, -np.concatenate([phi, [load]]))
        except np.linalg.LinAlgError:
            message = "singular Newton matrix"
            break
        merit = float(phi @ phi + load * load)
        t = 1.0
        while t > 1e-6:
            P_new = P.copy()
            P_new[interior] += t * step[:m]
            H0_new = H0 + t * step[m]
            with np.errstate(over="ignore", invalid="ignore"):  # a wild trial step is simply rejected
                H_new, L_new = state(P_new, H0_new)
                phi_new, _, _ = _fischer_burmeister(P_new[interior], -scale * L_new[interior])
                load_new = grid.load_error(P_new) - f_load
                trial = float(phi_new @ phi_new + load_new * load_new)  # ** would raise OverflowError
            if np.isfinite(trial) and trial <= (1 - 1e-4 * t) * merit:
                break
            t *= 0.5
        else:
            message = "line search failed"
            break
        P, H0, H, L = P_new, H0_new, H_new, L_new
    else:
        message = f"no convergence in {max_iterations} iterations"
    return np.maximum(P, 0.0), float(H0), residuals, loads, converged, message


def solve_reference(
    problem: LineEHLProblem,
    level: int | None = None,
    *,
    n: int | None = None,
    deformation: str = "direct",
    initial: LineEHLSolution | None = None,
    tolerance: float = 1e-10,
    max_iterations: int = 200,
    strict: bool = True,
) -> LineEHLSolution:
    """Solve the discrete problem on one grid by semi-smooth Newton (dense; n <~ 2000).

    Parameters
    ----------
    problem : LineEHLProblem
    level, n : int
        Grid level (n = 14 2^(level-1) + 1) or the node count directly.
    deformation : str
        ``"direct"`` (default), ``"fft"`` or ``"mlmi"`` for the film evaluation.
    initial : LineEHLSolution, optional
        Warm start (interpolated onto this grid); without it, levels above 4 start from the
        solution one level down (grid sequencing).
    tolerance : float
        On max |phi| and |load error|.
    strict : bool
        Raise :class:`~camcontact.errors.ConvergenceError` if not converged (else warn).
    """
    if (level is None) == (n is None):
        raise InputError("solve_reference: give exactly one of level and n")
    if initial is None and level is not None and level > 4:
        # grid sequencing: the coarser solution is a good start (Newton is local)
        initial = solve_reference(problem, level - 1, deformation=deformation, tolerance=max(tolerance, 1e-8),
                                  max_iterations=max_iterations, strict=strict)
    n = grid_points(level) if n is None else int(n)
    if n > 4000:
        raise InputError(f"solve_reference: n = {n} is too large for the dense solver (<= 4000)")
    start = time.perf_counter()
    grid = LineGrid(problem, n, deformation)
    if initial is None:
        P, H0 = _initial_guess(grid)
    else:
        P = np.maximum(np.interp(grid.X, initial.X, initial.P), 0.0)
        P[0] = P[-1] = 0.0
        H0 = initial.H0
    P, H0, residuals, loads, converged, message = newton_complementarity(
        grid, P, H0, tolerance=tolerance, max_iterations=max_iterations
    )
    H = grid.film(P, H0)
    record = ConvergenceRecord(
        method="dense Newton (Fischer-Burmeister)", levels=1, nodes=n, residuals=tuple(residuals),
        load_errors=tuple(loads), work_units=tuple(float(k + 1) for k in range(len(residuals))),
        wall_time=time.perf_counter() - start, converged=converged, message=message, tolerance=tolerance,
    )
    solution = LineEHLSolution(problem=problem, level=level or 0, X=grid.X, P=P, H=H, H0=float(H0), record=record)
    if not converged:
        not_converged(f"line EHL reference solver did not converge (M = {problem.M:.4g}, L = {problem.L:.4g}, "
                      f"n = {n}): {message}", record, strict=strict)
    return solution
