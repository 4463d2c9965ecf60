"""Steady starved line contacts: the meniscus where the inlet layer fills the gap.

A contact fed by a layer of lubricant of content H_oil = h_oil R/b^2 (both surfaces together, at ambient
density; :attr:`LineEHLProblem.supply`) cannot pass more than it is given. In the mass-conserving
(Jakobsson–Floberg–Olsson) model of a steady line contact the layer is carried unpressurised (P = 0,
film fraction theta = H_oil/H) up to a meniscus X_m where it fills the gap; from there on the film is full
and the mass flux F = rho H - xi dP/dX is the same at every section, so that it equals the supply:

.. math::
    F(X_m) = H_{oil}, \\qquad P(X_m) = 0,

with the pressurised region downstream of X_m the flooded solution of the domain [X_m, X_b] (Wolveridge,
Baglin & Archard 1971's inlet-meniscus model of starvation; Chevalier et al. 1998 and Damiens et al.
2004 solve the same steady problem through theta). Behind the exit the lubricant leaves as the film fraction
theta = F/(rho H) (JFO rupture is the Reynolds condition in a steady line contact).

Method. F(X_m) falls monotonically as the meniscus moves downstream. :func:`solve_starved` solves the
flooded contact first (its flux F_ff; a supply of at least F_ff leaves the contact flooded: the surplus turns
back ahead of the domain), then finds X_m with F(X_m) = H_oil: each trial meniscus is a flooded solve of the
domain [X_m, X_b] (:func:`camcontact.ehl.line_multigrid.solve_multigrid`, warm-started from the nearest trial,
by full multigrid if that does not converge), bracketed by moving X_m towards the Hertz inlet edge (by the secant
of the last two trials on ln(-1 - X_m), stretched by :data:`BRACKET_OVERSHOOT`, the step between :data:`MENISCUS_STEP`
and :data:`LARGEST_STEP` of the distance) and found by regula falsi (Illinois) on ln(-1 - X_m) until |F/H_oil - 1| is
below ten times the tolerance (:func:`find_meniscus`; the thermal solver's starved inlet,
:func:`camcontact.ehl.line_thermal.solve_thermal`, searches its meniscus with the same function over thermal
solves). The meniscus is a continuous unknown, not a grid node, so that the flux matches the supply to that
tolerance. The solution is returned on the reduced domain's grid continued upstream at the same
spacing to X_a (P = 0 there, the film from the same deformation integral), with theta from mass conservation:
H_oil/H upstream of the meniscus, 1 in the pressurised film, behind the exit the content that carries F through
every face of the solver's discrete flux (about F/H).

Measured (level 8; supply as a fraction r of F_ff): M = 20, L = 10: r = 0.8 ... 0.1 in 12-23 solves, 1-2 s, the
flux within 8e-7 of the supply; M = 100, L = 10: r = 0.8 ... 0.1; M = 5, L = 5: r = 0.8 and 0.3. Severe
starvation, with the meniscus within about 0.01 b of the Hertz edge (r = 0.05 at M = 20, L = 10; 0.1 at M = 5,
L = 5), does not converge: the flooded solves of so short an inlet stagnate (a warning, or ConvergenceError
with ``strict``).

Why not the film-fraction relaxation of the mass-conserving multigrid cycles
(:mod:`camcontact.ehl._kernels`)? Started from a flooded solution its inlet stays pressurised (the backflow
leaves through the inlet boundary, a second, unphysical fixed point of the discrete problem); started from a
starved guess its meniscus moves by relaxation alone, about one node per 6 to 40 cycles (measured, level 8,
M = 20, L = 10): the coarse grids hold the fine grid's dry nodes at P = 0, a Dirichlet condition where the
fine grid has a flux condition, and cannot move the meniscus.

In a line contact the lubricant cannot leave sideways: below F_ff the whole supply passes, so the central
film is H_c = H_oil/rho_c and H_c/H_c,ff = r to within the density change (measured 0.9997 r). The film
reduction curve that Chevalier et al. (1998) fitted to starved point contacts, r/(1 + r^gamma)^(1/gamma), bends
gradually where r ~ 1; without side flow, the curve here is its limit gamma -> infinity, min(r, 1) (camcontact's
reading: the corpora here hold no published starved line-contact curve to compare with).

References
----------
Wolveridge, P.E., Baglin, K.P. & Archard, J.F. (1971) The starved lubrication of cylinders in line contact.
Proc. IMechE 185, 1159–1169.
Chevalier, F., Lubrecht, A.A., Cann, P.M.E., Colin, F. & Dalmaz, G. (1998) Film thickness in starved EHL point
contacts. J. Tribol. 120, 126–133.
Damiens, B., Venner, C.H., Cann, P.M.E. & Lubrecht, A.A. (2004) Starved lubrication of elliptical EHD
contacts. J. Tribol. 126, 105–111.
"""

from __future__ import annotations

import math
import time
import warnings

import attrs
import numpy as np

from ..errors import ConvergenceError, ConvergenceWarning, InputError, not_converged
from .deformation import Deformation
from .line_multigrid import MultigridSettings, solve_multigrid
from .line_problem import LineEHLProblem
from .line_solution import ConvergenceRecord, LineEHLSolution

__all__ = ["BRACKET_OVERSHOOT", "LARGEST_STEP", "MAX_MENISCUS_SOLVES", "MENISCUS_STEP", "MIN_MENISCUS_GAP",
           "find_meniscus", "solve_starved", "wet_flux"]


def wet_flux(solution: LineEHLSolution) -> float:
    """The mass flux F [-] (units of rho_0 u_m b^2/R) through the pressurised film: at the face nearest X = 0."""
    return float(solution.mass_flux[min(int(np.searchsorted(solution.X, 0.0)), solution.X.size - 2)])


def solve_starved(problem: LineEHLProblem, levels: int = 9, *, tolerance: float | None = 1e-7,
                  settings: MultigridSettings | None = None, strict: bool = False,
                  compiled: bool = True) -> LineEHLSolution:
    """Solve a steady line contact with a starved inlet (``problem.supply``) on ``levels`` grid levels.

    Returns the solution on the grid of the reduced domain [X_m, X_b] extended upstream at the same spacing
    to X_a (unpressurised, theta = supply/H there), with its film fraction ``theta``; the record's message
    gives X_m, the solves and flux/supply - 1. A supply of at least the flooded contact's flux returns the
    flooded solution (message "flooded"). Not converged (the chosen solve, or the flux not within ten times
    ``tolerance`` of the supply after :data:`MAX_MENISCUS_SOLVES`): :class:`ConvergenceWarning`, or
    :class:`ConvergenceError` with ``strict``.
    """
    if problem.supply is None:
        raise InputError("solve_starved: the problem has no supply (a flooded inlet); use solve_multigrid")
    start = time.perf_counter()
    supply = float(problem.supply)
    base = attrs.evolve(problem, supply=None, cavitation="reynolds")
    flooded = solve_multigrid(base, levels, tolerance=tolerance, settings=settings, strict=strict, compiled=compiled)
    F_ff = wet_flux(flooded)
    if supply >= F_ff:
        return _result(problem, flooded, supply, start, f"flooded: supply {supply:.6g} >= the flooded flux {F_ff:.6g}",
                       flooded.record.converged, strict)
    X_a, X_b = problem.domain
    target = max(10.0 * (tolerance or 1e-9), 1e-9)  # |F/supply - 1| of a converged meniscus
    solutions: dict[float, LineEHLSolution] = {}

    def flux_error(x_m: float) -> float:
        near = min(solutions, key=lambda x: abs(x - x_m)) if solutions else None
        reduced = attrs.evolve(base, domain=(x_m, X_b))
        with warnings.catch_warnings():  # the verdict is the chosen solve's, in the returned record
            warnings.simplefilter("ignore", ConvergenceWarning)
            try:
                solution = solve_multigrid(reduced, levels, tolerance=tolerance, settings=settings,
                                           initial=None if near is None else solutions[near], compiled=compiled)
            except ConvergenceError:
                solution = None
            if solution is None or not solution.record.converged:  # a warm start too far away: full multigrid
                solution = solve_multigrid(reduced, levels, tolerance=tolerance, settings=settings, compiled=compiled)
        solutions[x_m] = solution
        return wet_flux(solution) / supply - 1.0

    x_m, error = find_meniscus(flux_error, X_a, F_ff / supply - 1.0, target=target, supply=supply,
                               record=flooded.record, caller="solve_starved")
    chosen = solutions[x_m]
    converged = chosen.record.converged and abs(error) <= target
    message = (f"meniscus at X = {x_m:.6g}; flux/supply - 1 = {error:.3g}; {len(solutions) + 1} solves")
    return _result(problem, _extended(chosen, X_a), supply, start, message, converged, strict, x_m)


#: the bracketing moves the meniscus at least this fraction of its distance to the Hertz inlet edge per solve, and
#: at most LARGEST_STEP of it; in between, to the secant's root stretched by BRACKET_OVERSHOOT (:func:`find_meniscus`)
MENISCUS_STEP = 0.3
LARGEST_STEP = 0.75
BRACKET_OVERSHOOT = 1.3
#: the closest approach of the meniscus to the Hertz inlet edge [b] (a supply too small for it is refused)
MIN_MENISCUS_GAP = 1e-4
#: regula-falsi solves at most (each a multigrid solve warm-started from the nearest meniscus)
MAX_MENISCUS_SOLVES = 30


def find_meniscus(flux_error, X_a: float, flooded_error: float, *, target: float, supply: float, record,
                  caller: str) -> tuple[float, float]:
    """The meniscus X_m [-] where a starved contact's flux meets its supply, and the error there.

    ``flux_error(X_m)`` is F/supply - 1 of the flooded solve of the domain [X_m, X_b] (it keeps its solution,
    keyed by the X_m it was called with; the returned X_m is one of those); ``flooded_error`` is that of the whole
    domain from ``X_a`` (> 0: the supply is below the flooded flux). The distance d = -1 - X_m to the Hertz inlet
    edge shrinks until the flux falls below the supply: to the root of the secant on ln d through the last two
    trials, stretched by :data:`BRACKET_OVERSHOOT` (near the root F is convex in ln d, so the secant falls short
    of it; farther out, where F is concave and the secant overshoots, LARGEST_STEP bounds the step),
    each step between :data:`MENISCUS_STEP` and :data:`LARGEST_STEP` of d (the first: MENISCUS_STEP); then regula
    falsi (Illinois) on ln d, where F varies smoothly, until |F/supply - 1| <= ``target`` or
    :data:`MAX_MENISCUS_SOLVES`. (Fixed steps of 0.3 took 7, 10 and 15 thermal solves for layers of 0.8, 0.5 and 0.2
    of the flooded film, measured at S = 0, level 6.)
    ConvergenceError (with ``record``, the flooded solve's) where a meniscus :data:`MIN_MENISCUS_GAP` ahead of the
    Hertz edge still passes more than ``supply``; ``caller`` names the solver in that message.
    """
    d_low, g_low = -1.0 - X_a, flooded_error
    d_high, g_high = d_low, g_low
    previous = None
    while g_high >= 0.0:
        if d_high != d_low:
            previous = (d_low, g_low)
        d_low, g_low = d_high, g_high
        ratio = 1.0 - MENISCUS_STEP
        if previous is not None and previous[1] > g_low:  # the secant's root on ln d, stretched, within the limits
            slope = (math.log(previous[0]) - math.log(d_low)) / (previous[1] - g_low)
            ratio = min(max(math.exp(-BRACKET_OVERSHOOT * g_low * slope), 1.0 - LARGEST_STEP), 1.0 - MENISCUS_STEP)
        d_high = d_low * ratio
        if d_high < MIN_MENISCUS_GAP:
            raise ConvergenceError(f"{caller}: supply {supply:.6g} is below the flux of a contact whose meniscus "
                                   f"is {MIN_MENISCUS_GAP:g} b ahead of the Hertz edge: no steady film", record)
        g_high = flux_error(-1.0 - d_high)
    a, b, ga, gb = math.log(d_low), math.log(d_high), g_low, g_high
    side = 0
    for _ in range(MAX_MENISCUS_SOLVES):
        c = (a * gb - b * ga) / (gb - ga)
        gc = flux_error(-1.0 - math.exp(c))
        if abs(gc) <= target:
            break
        if gc * gb < 0.0:
            a, ga = b, gb
            side = 0
        else:
            ga = 0.5 * ga if side == -1 else ga
            side = -1
        b, gb = c, gc
    return -1.0 - math.exp(c), gc


def _extended(solution: LineEHLSolution, X_a: float) -> LineEHLSolution:
    """The reduced-domain solution on its grid continued upstream at the same spacing to X_a (P = 0 there),
    the film there from the same deformation integral."""
    X, h = solution.X, float(solution.X[1] - solution.X[0])
    count = int(math.floor((X[0] - X_a) / h + 1e-9))
    if count <= 0:
        return solution
    X_ext = np.concatenate([X[0] - h * np.arange(count, 0, -1), X])
    P_ext = np.concatenate([np.zeros(count), solution.P])
    H_ext = solution.H0 + 0.5 * X_ext**2
    if solution.problem.elastic:
        H_ext = H_ext - Deformation(X_ext.size, h, "fft")(P_ext) / math.pi
    return attrs.evolve(solution, X=X_ext, P=P_ext, H=H_ext)


def _result(problem, solution, supply, start, message, converged, strict,
            meniscus: float | None = None) -> LineEHLSolution:
    record = solution.record
    record = ConvergenceRecord(
        method=f"starved inlet: meniscus by regula falsi over {record.method}", levels=record.levels,
        nodes=solution.X.size, residuals=record.residuals, load_errors=record.load_errors,
        work_units=record.work_units, wall_time=time.perf_counter() - start, converged=bool(converged),
        message=f"{message}; last solve: {record.message}" if record.message else message, tolerance=record.tolerance,
    )
    if not converged:
        not_converged(f"line EHL starved inlet (M = {problem.M:.4g}, L = {problem.L:.4g}): not converged: "
                      f"{record.message}", record, strict=strict, stacklevel=3)
    flux = wet_flux(solution)
    P, H = solution.P, np.maximum(solution.H, 1e-300)
    theta = np.ones_like(P)
    if meniscus is not None:
        inlet = solution.X < meniscus - 1e-12
        theta[inlet] = np.minimum(supply / H[inlet], 1.0)
    wet = np.flatnonzero(P > 0.0)
    if wet.size:
        theta = _exit_film_fraction(solution, theta, int(wet[-1]) + 1, flux)
    return attrs.evolve(solution, problem=problem, record=record, theta=theta)


def _exit_film_fraction(solution: LineEHLSolution, theta: np.ndarray, first: int, flux: float) -> np.ndarray:
    """theta behind the exit (nodes ``first``..): the content q_i that carries ``flux`` through every face in the
    discrete form of :attr:`~camcontact.ehl.line_solution.LineEHLSolution.mass_flux`, marched downstream:
    G_i = flux + xi_(i+1/2) (P_(i+1) - P_i)/h, q_i = (G_i + phi_i q_(i-1)/2)/(1 + phi_i/2)."""
    problem, P, H, X = solution.problem, solution.P, np.maximum(solution.H, 1e-300), solution.X
    h = float(X[1] - X[0])
    xi = problem.flow_coefficient(P, H)
    theta = theta.copy()
    q_previous = float(problem.density_ratio(P[first - 1]) * H[first - 1])
    full_previous = True
    for i in range(first, P.size):
        G = flux if i == P.size - 1 else flux + 0.5 * (xi[i] + xi[i + 1]) * (P[i + 1] - P[i]) / h
        phi = 1.0 if full_previous else 0.0
        q = (G + 0.5 * phi * q_previous) / (1.0 + 0.5 * phi)
        theta[i] = min(q / H[i], 1.0)
        q_previous, full_previous = theta[i] * H[i], theta[i] >= 1.0
    return theta
