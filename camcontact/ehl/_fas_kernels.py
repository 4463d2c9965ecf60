"""Compiled FAS cycles of the line-contact EHL multigrid solver, with their plain-Python twins.

One call of :func:`fas_cycle` runs a whole V, W or F cycle: the recursion of
:mod:`camcontact.ehl.line_multigrid` is unrolled in Python once into a *schedule* of
operations (:func:`cycle_schedule`) — ``DOWN`` k (pre-relax level k, form the FAS coarse
problem on k - 1), ``SOLVE`` k (coarsest grid, exactly) and ``UP`` k (correct level k from
k - 1, post-relax) — which the kernel executes over flat per-level buffers. Relaxation, films
(MLMI or direct), residuals, the coarsest-grid Newton solve (:func:`coarse_newton`) and the local Newton
solve at the pressure spike (:func:`find_spikes`, :func:`relax_spikes`) all run
compiled, so a cycle costs no Python call per level visit (a W-cycle on 8 levels visits the
coarse grids 255 times). The kernels take the operator's speed ratio s and squeeze coefficient c_t
(:mod:`camcontact.ehl._kernels`): s = 1, c_t = 0 for the steady solver, a step's values for the
transient one (:mod:`camcontact.ehl.line_transient`). As with :mod:`camcontact.ehl._kernels`, each function is plain Python
that :func:`compiled` hands to numba; the tests run the twins on small grids.

For developers: numba's on-disk cache of :func:`fas_cycle` and :func:`coarse_newton` is checked against this file
only, not against the helpers of :mod:`camcontact.ehl._kernels` it inlines (measured: after an edit to
``relax_hybrid`` the cached cycle kept the old smoother, even after touching this file). After editing
``_kernels.py``, delete ``camcontact/ehl/__pycache__/_fas_kernels.*.nbi`` and ``*.nbc``; a fresh clone (CI) has no
cache.
"""

from __future__ import annotations

import math

import numpy as np
from numba.extending import register_jitable

from ..jit import helper

from . import _kernels
from ._kernels import (deformation_direct, flow_factor, kernel_value, law_state, mlmi_apply, relax_hybrid,
                       reynolds_residual, wedge_weight)

__all__ = ["DOWN", "PY", "SOLVE", "UP", "coarse_newton", "compiled", "cycle_schedule", "fas_cycle"]

DOWN, SOLVE, UP = 0, 1, 2


def cycle_schedule(k: int, kind: str, coarsest: int) -> np.ndarray:
    """Operations (op, level index) of one ``kind`` cycle (V, W or F) from level index k down to
    level index ``coarsest``: a V-cycle visits the next coarser level once, a W-cycle twice, an
    F-cycle once as an F and once as a V (Venner & Lubrecht 2000 §3.7)."""
    ops: list[tuple[int, int]] = []

    def visit(k: int, kind: str) -> None:
        if k <= coarsest:
            ops.append((SOLVE, k))
            return
        ops.append((DOWN, k))
        visits = {"V": ("V",), "W": ("W", "W"), "F": ("F", "V")}[kind]
        if k - 1 <= coarsest:
            visits = visits[:1]
        for inner in visits:
            visit(k - 1, inner)
        ops.append((UP, k))

    visit(k, kind)
    return np.array(ops, dtype=np.int64).reshape(-1, 2)


@register_jitable
def solve_dense(A, b):
    """x with A x = b by Gaussian elimination with partial pivoting (A, b overwritten); (x, ok)."""
    n = b.shape[0]
    for k in range(n):
        pivot = k
        for r in range(k + 1, n):
            if abs(A[r, k]) > abs(A[pivot, k]):
                pivot = r
        if not abs(A[pivot, k]) > 0.0:  # also catches NaN
            return b, False
        if pivot != k:
            for c in range(n):
                A[k, c], A[pivot, c] = A[pivot, c], A[k, c]
            b[k], b[pivot] = b[pivot], b[k]
        for r in range(k + 1, n):
            factor = A[r, k] / A[k, k]
            if factor != 0.0:
                for c in range(k, n):
                    A[r, c] -= factor * A[k, c]
                b[r] -= factor * b[k]
    x = np.empty(n)
    for k in range(n - 1, -1, -1):
        value = b[k]
        for c in range(k + 1, n):
            value -= A[k, c] * x[c]
        x[k] = value / A[k, k]
    return x, True


@register_jitable
def dense_state(P, H0, f, parabola, K_over_pi, theta, phi, h, lam, viscosity_code, density_code, params, elastic, s,
                c_t, H, L):
    """Film H and L - f (interior; 0 at the ends) on a grid with the dense deformation matrix K/pi and the
    film fractions theta and flow factors phi."""
    n = P.shape[0]
    for i in range(n):
        value = H0 + parabola[i]
        if elastic:
            for j in range(n):
                if P[j] != 0.0:
                    value -= K_over_pi[i, j] * P[j]
        H[i] = value
    reynolds_residual(P, H, theta, phi, h, lam, viscosity_code, density_code, params, s, c_t, L)
    for i in range(1, n - 1):
        L[i] -= f[i]


@helper
def fischer_burmeister(a, b):
    """(phi, d phi/da, d phi/db) of phi(a, b) = a + b - sqrt(a^2 + b^2)."""
    r = math.hypot(a, b)
    if r > 0.0:
        return a + b - r, 1.0 - a / r, 1.0 - b / r
    return 0.0, 1.0 - 1.0 / math.sqrt(2.0), 1.0 - 1.0 / math.sqrt(2.0)


@register_jitable
def coarse_newton(P, H0, f, f_load, parabola, K_over_pi, theta, phi, pinned, h, lam, viscosity_code, density_code,
                  params, elastic, s, c_t, tolerance, max_iterations, load_equation=True, hold_start=False):
    """Semi-smooth Newton for the complementarity problem L(P, H0) = f, load = f_load on a small grid
    (film fractions theta given: the injected ones of a mass-conserving solve, else 1; flow factors phi on the
    Poiseuille coefficient given (:func:`camcontact.ehl._kernels.flow_factor`); nodes with ``pinned``
    set are held at P = 0 by the equation P_i = 0 in place of their complementarity condition).

    The coarsest-grid solver of the multigrid cycles: the same method as the dense reference
    :func:`camcontact.ehl.line_reference.newton_complementarity` (Fischer–Burmeister equation
    FB(P_i, -s_i (L_i - f_i)) = 0 with s_i = 1/|dL_i/dP_i| per interior node, the trapezoidal
    load balance h sum P - pi/2 = f_load for H0, exact Jacobian, backtracking on
    |FB|^2 + load^2), written with loops so that it compiles; meant for n up to about 100
    (dense Jacobian; its deformation part is K/pi times a five-diagonal matrix, O(n^2): the local
    band spans i - 2..i + 2 for either flow direction).

    Without ``load_equation`` H0 is held and only the pressures are solved for (the local spike solve,
    :func:`relax_spikes`); with ``hold_start`` the ``pinned`` nodes are held at their start values instead of
    at 0.

    Returns (P >= 0, H0, iterations, status): status 0 converged (max |FB| and |load error|
    below ``tolerance``), 1 non-finite Jacobian, 2 singular Newton matrix, 3 line search failed,
    4 iteration limit. P and H0 are the last accepted iterate.
    """
    n = P.shape[0]
    m = n - 2
    P = P.copy()
    held = P.copy() if hold_start else np.zeros(n)
    H = np.empty(n)
    L = np.empty(n)
    H_new = np.empty(n)
    L_new = np.empty(n)
    rho = np.empty(n)
    drho = np.empty(n)
    xi = np.empty(n)
    dxi_dP = np.empty(n)
    dxi_dH = np.empty(n)
    direct = np.zeros((n, 5))  # dL_i/dP_m at fixed films, m = i - 2 + c
    dL_dH = np.zeros((n, 5))  # dL_i/dH_m, m = i - 2 + c
    J = np.empty((n, n))
    J_H0 = np.empty(n)
    scale = np.empty(n)
    fb = np.empty(m)
    da = np.empty(m)
    db = np.empty(m)
    size = m + 1 if load_equation else m
    A = np.empty((size, size))
    rhs = np.empty(size)
    P_new = np.empty(n)
    hh = h * h
    dense_state(P, H0, f, parabola, K_over_pi, theta, phi, h, lam, viscosity_code, density_code, params, elastic, s,
                c_t, H, L)
    status = 4
    iterations = 0
    for _ in range(max_iterations):
        iterations += 1
        # --- Jacobian of L with respect to P (through the films too) and H0
        for j in range(n):
            r, d_r, log_eta, dlog_eta = law_state(P[j], viscosity_code, density_code, params)
            e = math.exp(-log_eta)
            gap = max(H[j], 0.0)
            rho[j] = r * theta[j] * phi[j, 2]
            drho[j] = d_r * theta[j] * phi[j, 2]
            factor, share = flow_factor(phi, j, log_eta)
            xi[j] = factor * r * gap * gap * gap * e / lam
            dxi_dH[j] = 3.0 * factor * r * gap * gap * e / lam
            dxi_dP[j] = xi[j] * (d_r / r - (1.0 - share) * dlog_eta)
        for i in range(n):
            for c in range(5):
                direct[i, c] = 0.0
                dL_dH[i, c] = 0.0
        for i in range(1, n - 1):
            left = 0.5 * (xi[i - 1] + xi[i])
            right = 0.5 * (xi[i] + xi[i + 1])
            direct[i, 1] += left / hh
            direct[i, 2] -= (left + right) / hh
            direct[i, 3] += right / hh
            a = (P[i - 1] - P[i]) / hh
            c = (P[i + 1] - P[i]) / hh
            for q in range(3):
                weight = 0.5 * a if q == 0 else (0.5 * (a + c) if q == 1 else 0.5 * c)
                direct[i, q + 1] += weight * dxi_dP[i - 1 + q]
                dL_dH[i, q + 1] += weight * dxi_dH[i - 1 + q]
            for k in range(3):
                weight, mm = wedge_weight(i, k, n, s, P, theta)
                coefficient = abs(s) * weight / h
                if k == 0:
                    coefficient += c_t / phi[i, 2]
                if coefficient == 0.0:
                    continue
                c_index = mm - i + 2
                direct[i, c_index] -= coefficient * drho[mm] * H[mm]
                dL_dH[i, c_index] -= coefficient * rho[mm]
        finite = True
        for i in range(n):
            total = 0.0
            for j in range(n):
                J[i, j] = 0.0
            for c in range(5):
                mm = i - 2 + c
                if mm < 0 or mm >= n:
                    continue
                J[i, mm] += direct[i, c]
                total += dL_dH[i, c]
                if elastic and dL_dH[i, c] != 0.0:
                    for j in range(n):
                        J[i, j] -= dL_dH[i, c] * K_over_pi[mm, j]
            J_H0[i] = total
            for j in range(n):
                if not math.isfinite(J[i, j]):
                    finite = False
        if not finite:
            status = 1
            break
        # --- Fischer-Burmeister residual and load
        residual = 0.0
        merit = 0.0
        for k in range(m):
            i = k + 1
            scale[i] = 1.0 / max(abs(J[i, i]), 1e-300)
            if pinned[i]:  # held at P = 0 (or its start value): the equation P_i = 0
                fb[k], da[k], db[k] = P[i] - held[i], 1.0, 0.0
            else:
                fb[k], da[k], db[k] = fischer_burmeister(P[i], -scale[i] * L[i])
            residual = max(residual, abs(fb[k]))
            merit += fb[k] * fb[k]
        load = h * (P.sum() - 0.5 * (P[0] + P[n - 1])) - 0.5 * math.pi - f_load if load_equation else 0.0
        merit += load * load
        if residual < tolerance and abs(load) < tolerance:
            status = 0
            break
        # --- Newton step for (P_1..P_{n-2}, H0)
        for k in range(m):
            i = k + 1
            factor = -db[k] * scale[i]
            for l in range(m):
                A[k, l] = factor * J[i, l + 1]
            A[k, k] += da[k]
            if load_equation:
                A[k, m] = factor * J_H0[i]
            rhs[k] = -fb[k]
        if load_equation:
            for l in range(m):
                A[m, l] = h
            A[m, m] = 0.0
            rhs[m] = -load
        step, ok = solve_dense(A, rhs)
        if not ok:
            status = 2
            break
        # --- backtracking on the merit function
        t = 1.0
        accepted = False
        while t > 1e-6:
            P_new[0] = P[0]
            P_new[n - 1] = P[n - 1]
            for k in range(m):
                P_new[k + 1] = P[k + 1] + t * step[k]
            H0_new = H0 + t * step[m] if load_equation else H0
            dense_state(P_new, H0_new, f, parabola, K_over_pi, theta, phi, h, lam, viscosity_code, density_code, params,
                        elastic, s, c_t, H_new, L_new)
            trial = 0.0
            for k in range(m):
                if pinned[k + 1]:
                    value = P_new[k + 1] - held[k + 1]
                else:
                    value, _, _ = fischer_burmeister(P_new[k + 1], -scale[k + 1] * L_new[k + 1])
                trial += value * value
            if load_equation:
                load_new = h * (P_new.sum() - 0.5 * (P_new[0] + P_new[n - 1])) - 0.5 * math.pi - f_load
                trial += load_new * load_new
            if math.isfinite(trial) and trial <= (1.0 - 1e-4 * t) * merit:
                accepted = True
                break
            t *= 0.5
        if not accepted:
            status = 3
            break
        for i in range(n):
            P[i] = P_new[i]
            H[i] = H_new[i]
            L[i] = L_new[i]
        H0 = H0_new
    for i in range(n):
        if P[i] < 0.0:
            P[i] = 0.0
    return P, H0, iterations, status


@register_jitable
def level_film(k, P, H0, n_of, h_of, parabola, offsets, mlmi_on, m_of, c1s, c2s, weights, direct_below, elastic):
    """H = H0 + X^2/2 - w/pi on level k (w by MLMI or directly)."""
    n = n_of[k]
    o = offsets[k]
    H = np.empty(n)
    if not elastic:
        for i in range(n):
            H[i] = H0 + parabola[o + i]
        return H
    if mlmi_on[k]:
        m = m_of[k]
        w = mlmi_apply(P, h_of[k], m, c1s[k, :, :2 * m + 1], c2s[k, :, :2 * m + 1], weights, direct_below)
    else:
        w = deformation_direct(P, h_of[k])
    for i in range(n):
        H[i] = H0 + parabola[o + i] - w[i] / math.pi
    return H


@helper
def level_load(P, h):
    """h sum (P_j + P_{j+1})/2 - pi/2 (trapezoidal load balance)."""
    return h * (P.sum() - 0.5 * (P[0] + P[P.shape[0] - 1])) - 0.5 * math.pi


@helper
def find_spikes(P, viscosity_code, params, drop, marked):
    """Mark the nodes of the pressure spikes of one level in ``marked`` (one bool per node, cleared first); True if
    any. A spike edge is a fall of ln(eta-bar) by more than ``drop`` from node i to i + 1 (flow towards +x)
    within two nodes of a pressure maximum (max(P_i, P_i-1, P_i-2) > P_i-3; an outlet that falls monotonically
    is not one); its nodes i - 2 .. i + 3 are marked (:func:`relax_spikes` solves them).

    Where no spike can form (ln(eta-bar) of the level's largest pressure does not exceed ``drop``: isoviscous and
    weakly piezoviscous contacts), the last pressurised node i before the exit's cavitation (flow towards +x) is
    marked instead, with i - 3 .. i + 1: there point relaxation stalls as at a spike. Measured, M 1000, L 0 on
    level 9: every attempt stopped with the residual of that node at 5e-3 and H_min 2.0e-4, 2 % above the dense
    Newton solution of the same grid (1.97991e-4); with the zone solved, 1.97982e-4. Over the Moes map only the
    L = 0 and weakly piezoviscous cases move, by at most 1.3e-7 (M 1000, L 0 excepted)."""
    n = P.shape[0]
    found = False
    for i in range(marked.shape[0]):
        marked[i] = False
    # ln(eta-bar) >= 0 rises with P, so only a node whose pressure falls to the next one and whose own ln(eta-bar)
    # exceeds the drop can start a fall: elsewhere no viscosity is evaluated (the same spikes; measured, the search
    # evaluated it at a sixth of the nodes of the M 20, L 10 contact on level 9 instead of at all)
    floor = _kernels.pressure_of_log_viscosity(drop, viscosity_code, params)
    for i in range(4, n - 5):
        if not (P[i] > floor and P[i + 1] < P[i]):
            continue
        here = _kernels.log_viscosity(P[i], viscosity_code, params)
        below = _kernels.log_viscosity(P[i + 1], viscosity_code, params)
        if here - below > drop and max(P[i], P[i - 1], P[i - 2]) > P[i - 3]:
            for m in range(i - 2, i + 4):
                marked[m] = True
            found = True
    largest = 0.0
    for i in range(n):
        largest = max(largest, P[i])
    if not largest > floor:  # no spike can form: the exit's cavitation boundary instead (docstring)
        for i in range(n - 6, 4, -1):
            if P[i] > 0.0 and P[i + 1] <= 0.0 and P[i - 1] > 0.0:
                for m in range(i - 3, i + 2):
                    marked[m] = True
                found = True
                break
    return found


@register_jitable
def deformation_change(H, change, K_table, targets):
    """H_i -= (1/pi) sum_j K(|i - j|) change_j at the nodes i with ``targets`` set (one level; ``K_table`` its
    K(0 .. n - 1)): the exact film update for a pressure change, over the nonzero entries of ``change`` only
    (work: targets x changed nodes). The cycle updates a level's film with it where a full evaluation would be
    wasted: after the spike zones' Newton solve (a few nodes change) and for the films of the spike zones after
    the post-sweeps (a few targets)."""
    sources = np.flatnonzero(change != 0.0)
    for i in np.flatnonzero(targets):
        value = 0.0
        for j in sources:
            value += K_table[abs(i - j)] * change[j]
        H[i] -= value / math.pi


@register_jitable
def relax_spikes(P, H, H0, f, theta, phi, dry, h, lam, viscosity_code, density_code, params, elastic, s, c_t,
                 marked):
    """Solve the nodes around each pressure spike of one level together, by Newton; in place on P. Returns the work
    in node updates.

    The nodes of each run of ``marked`` (:func:`find_spikes`) are the unknowns of
    :func:`coarse_newton` on the zone i - 4 .. i + 5 without the load equation: H0 and every other pressure
    held (the two nodes on either side, because the second-order upwind wedge of the first unknown reaches two
    nodes back), the deformation of the rest of the level frozen in the zone's films, the zone's own through the
    dense K/pi. Zones with a closed film (H <= 0, a coarse grid's) or a partly filled node are left alone, as
    is a zone whose Newton does not converge (tolerance 1e-12, 30 iterations). The zones are those ``marked`` by
    :func:`find_spikes`: the cycle finds them after the pre-sweeps and solves the same zones after the
    post-sweeps (finding them anew there, after the coarse-grid correction, diverged at M 5, L 30).

    Why: across the Petrusevich spike of a heavily piezoviscous contact (M 5-10, L 20-30 on level 9) the
    viscosity falls by e^10 between two nodes. Point relaxation leaves errors of a node's size there, the
    coarse grids cannot represent them and return corrections that amplify them: started from the dense
    Newton solution, one cycle moved the spike by 8e-3 and the next few diverged. With the spike solved
    together after the pre-sweeps (before the restriction) and after the post-sweeps, every cycle starts from
    and ends with a settled spike (measured, M 10, L 20, level 9: residual x0.35 per cycle, H_min equal to the
    dense Newton solution's to 1e-6; before: divergence).
    """
    n = P.shape[0]
    work = 0.0
    i = 0
    while i < n:
        if not marked[i]:
            i += 1
            continue
        j = i
        while j + 1 < n and marked[j + 1]:
            j += 1
        a, b = i - 2, j + 2
        i = j + 1
        m = b - a + 1
        usable = True
        for q in range(a, b + 1):
            if not (H[q] > 0.0 and theta[q] >= 1.0):
                usable = False
        if not usable:
            continue
        K_over_pi = np.zeros((m, m))
        if elastic:
            table = np.empty(m)  # K(d)/pi for d = 0 .. m - 1
            for d in range(m):
                table[d] = kernel_value(float(d), h) / math.pi
            for q in range(m):
                for r in range(m):
                    K_over_pi[q, r] = table[abs(q - r)]
        P_zone = P[a:b + 1].copy()
        rest = np.empty(m)  # H - H0 without the zone's own deformation
        for q in range(m):
            value = H[a + q] - H0
            for r in range(m):
                value += K_over_pi[q, r] * P_zone[r]
            rest[q] = value
        held = dry[a:b + 1].copy()
        held[1] = True
        held[m - 2] = True
        P_new, _, iterations, status = coarse_newton(P_zone, H0, f[a:b + 1], 0.0, rest, K_over_pi, theta[a:b + 1],
                                                     phi[a:b + 1], held, h, lam, viscosity_code, density_code,
                                                     params, elastic, s, c_t, 1e-12, 30, False, True)
        work += iterations * (m - 4)
        if status == 0:
            for q in range(2, m - 2):
                P[a + q] = P_new[q]
    return work


def fas_cycle(schedule, P_all, P_old, f_all, H0s, loads, dry_all, theta_all, phi_all, n_of, offsets, h_of, parabola,
              K_local, mlmi_on, m_of, c1s, c2s, weights, direct_below, K_dense, lam, viscosity_code, density_code, params,
              elastic, real_settings, int_settings, s, c_t, mass_conserving, supply, K_tables):
    """Execute one cycle ``schedule`` (:func:`cycle_schedule`) in place on the level buffers, for the
    operator of speed ratio s and squeeze coefficient c_t (steady: s = 1, c_t = 0).

    Level k's pressures, FAS right-hand sides and frozen-dry flags are the slices
    ``offsets[k]:offsets[k] + n_of[k]`` of ``P_all``, ``f_all`` and ``dry_all`` (``P_old``
    keeps the injected coarse pressures a correction is measured from); ``H0s[k]`` and
    ``loads[k]`` are its film constant and load right-hand side. ``K_local[k]`` holds
    K(0..15) of level k for the relaxation, ``c1s``/``c2s`` its MLMI tables (``mlmi_on``),
    ``K_dense[k]`` the dense K/pi of a coarsest level. ``real_settings`` = (omega_gs,
    omega_jacobi, switch, h0_relaxation); ``int_settings`` = (pre_sweeps, post_sweeps,
    coarsest_sweeps, window, correct_pressurised_only, freeze_free_boundary,
    dry_keeps_own_equation, first_top, film_fas): the cycle's top level relaxes its nodes from ``first_top`` on (1:
    all; the nodes before it are held as they are, a truncated inlet); with ``film_fas`` each coarse level's film
    carries the FAS term of the film equation, so that the injected state's coarse film is the fine film
    (:attr:`camcontact.ehl.line_multigrid.MultigridSettings.film_fas`). Returns the work done in finest-grid
    relaxation units.

    ``phi_all`` holds the flow factors' (a, k) per node and level (shape (total, 2); (1, 0) for the isothermal
    Newtonian film; see :mod:`camcontact.ehl._kernels`), given on every level (the hierarchy restricts the finest
    level's, :meth:`camcontact.ehl.line_multigrid.LineHierarchy.set_flow_factor`).

    ``K_tables`` holds K(0 .. n - 1) of every level, flat like the pressures: with it the spike zones' Newton solve
    costs no extra full film (:func:`deformation_change`: after the pre-sweeps the restriction takes the spike
    film updated for the zones' change, after the post-sweeps only the zones' films are formed).

    ``theta_all`` holds the film fractions per level (all 1 for the classical operator). With
    ``mass_conserving`` the sweeps of the cycle's top level solve for theta where P = 0 with the inlet
    ``supply`` (:func:`camcontact.ehl._kernels.relax_hybrid`); the coarse levels take theta by injection as a
    coefficient and hold every node injected from a cavitated fine node at P = 0 (projected FAS: they correct
    the pressurised region only, their Newton solve too). Measured: coarse levels that could pressurise those
    nodes left M = 1000, L = 10 (level 8) stagnating; coarse levels that also solved for theta made the
    transient steps after an entrainment reversal stagnate (level 6) instead of converging slowly.
    """
    omega_gs, omega_jacobi, switch, h0_relaxation = real_settings[0], real_settings[1], real_settings[2], real_settings[3]
    spike_drop = real_settings[4]
    pre, post, coarsest_sweeps, window = int_settings[0], int_settings[1], int_settings[2], int_settings[3]
    pressurised_only = int_settings[4] != 0
    freeze_boundary = int_settings[5] != 0
    dry_own = int_settings[6] != 0
    first_top = int_settings[7]
    film_fas = int_settings[8] != 0
    n_finest = n_of[n_of.shape[0] - 1]
    top = schedule[0, 1]
    # the nodes each level holds at P = 0: the frozen set, and (mass-conserving) on the coarse levels every node
    # injected from a cavitated fine node (projected FAS: the coarse grids correct the pressurised region only)
    pin_all = dry_all.copy()
    spikes_all = np.zeros(P_all.shape[0], dtype=np.bool_)  # the spike zones found before each restriction
    zero_K = np.zeros(K_local.shape[1])
    # per level H - H0 - deformation: the parabola, plus the film FAS term on the coarse levels (else never written)
    shape = parabola.copy() if film_fas else parabola
    work = 0.0
    for step in range(schedule.shape[0]):
        op = schedule[step, 0]
        k = schedule[step, 1]
        n = n_of[k]
        o = offsets[k]
        h = h_of[k]
        P = P_all[o:o + n]
        f = f_all[o:o + n]
        theta = theta_all[o:o + n]
        phi = phi_all[o:o + n]
        update_theta = mass_conserving and k == top
        dry = pin_all[o:o + n] if mass_conserving and k != top else dry_all[o:o + n]
        K = K_local[k] if elastic else zero_K
        sweeps = pre if op == DOWN else (post if op == UP else 0)
        if op == UP:  # coarse-grid correction from level k - 1 first, then the post-sweeps
            oc = offsets[k - 1]
            correction = np.empty(n)
            for i in range(n):
                if i % 2 == 0:
                    change = P_all[oc + i // 2] - P_old[oc + i // 2]
                else:
                    j = i // 2
                    change = 0.5 * (P_all[oc + j] - P_old[oc + j] + P_all[oc + j + 1] - P_old[oc + j + 1])
                if pressurised_only:  # only where the node and both neighbours are wet
                    if not (P[i] > 0.0 and (i == 0 or P[i - 1] > 0.0) and (i == n - 1 or P[i + 1] > 0.0)):
                        change = 0.0
                correction[i] = change  # applied after the mask has seen the whole old state
            for i in range(n):
                P[i] = max(P[i] + correction[i], 0.0)
            P[0] = 0.0
            P[n - 1] = 0.0
            H0s[k] = H0s[k - 1]
        K_table = K_tables[o:o + n]
        marked = spikes_all[o:o + n]
        H_before = np.empty(0)  # the film the last sweep started from, and its pressures
        P_before = np.empty(0)
        for sweep in range(sweeps):
            H = level_film(k, P, H0s[k], n_of, h_of, shape, offsets, mlmi_on, m_of, c1s, c2s, weights,
                           direct_below, elastic)
            if op == UP and sweep == sweeps - 1 and spike_drop > 0.0 and marked.any():
                H_before = H.copy()
                P_before = P.copy()
            relax_hybrid(P, H, theta, phi, f, h, lam, viscosity_code, density_code, params, K, omega_gs, omega_jacobi,
                         switch, window, first_top if k == top else 1, n - 2, dry, s, c_t, update_theta, supply)
            work += (n - 2) / n_finest
        film_now = np.empty(0)  # this level's film of its current pressures, when the spike solve leaves it
        if spike_drop > 0.0 and op != SOLVE:  # after the pre-sweeps (before the restriction) and the post-sweeps
            if find_spikes(P, viscosity_code, params, spike_drop, marked) if op == DOWN else marked.any():
                if H_before.shape[0] == n:  # only the zones' films are read: the last sweep's film plus its change
                    H = H_before
                    zones = np.zeros(n, dtype=np.bool_)
                    for i in range(n):
                        if marked[i]:
                            for q in range(max(i - 2, 0), min(i + 2, n - 1) + 1):
                                zones[q] = True
                    if elastic:
                        deformation_change(H, P - P_before, K_table, zones)
                else:
                    H = level_film(k, P, H0s[k], n_of, h_of, shape, offsets, mlmi_on, m_of, c1s, c2s, weights,
                                   direct_below, elastic)
                P_spikes = P.copy()
                work += relax_spikes(P, H, H0s[k], f, theta, phi, dry, h, lam, viscosity_code, density_code, params,
                                     elastic, s, c_t, marked) / n_finest
                if op == DOWN:  # the restriction's film: the full film plus the change of the zones' pressures
                    film_now = H
                    if elastic:
                        deformation_change(film_now, P - P_spikes, K_table, np.ones(n, dtype=np.bool_))
        if op == SOLVE:
            P_new, H0_new, iterations, status = coarse_newton(
                P, H0s[k], f, loads[k], shape[o:o + n], K_dense[k, :n, :n], theta, phi, dry, h, lam, viscosity_code,
                density_code, params, elastic, s, c_t, 1e-11, 60)
            work += iterations * n / n_finest
            if status == 0:
                for i in range(n):
                    P[i] = P_new[i]
                H0s[k] = H0_new
            else:  # relaxation sweeps with H0 updates instead
                for _ in range(coarsest_sweeps):
                    H = level_film(k, P, H0s[k], n_of, h_of, shape, offsets, mlmi_on, m_of, c1s, c2s, weights,
                                   direct_below, elastic)
                    relax_hybrid(P, H, theta, phi, f, h, lam, viscosity_code, density_code, params, K, omega_gs,
                                 omega_jacobi, switch, window, 1, n - 2, dry, s, c_t, update_theta, supply)
                    work += (n - 2) / n_finest
                    H0s[k] += h0_relaxation * (level_load(P, h) - loads[k])
        elif op == DOWN:  # the FAS problem of level k - 1
            if film_now.shape[0] == n:
                H = film_now
            else:
                H = level_film(k, P, H0s[k], n_of, h_of, shape, offsets, mlmi_on, m_of, c1s, c2s, weights,
                               direct_below, elastic)
            r = np.empty(n)
            reynolds_residual(P, H, theta, phi, h, lam, viscosity_code, density_code, params, s, c_t, r)
            for i in range(n):
                r[i] = 0.0 if P[i] <= 0.0 else f[i] - r[i]
            if freeze_boundary:  # no residual transfer at nodes beside the cavitation boundary
                for i in range(n):
                    if (i > 0 and P[i - 1] <= 0.0) or (i < n - 1 and P[i + 1] <= 0.0):
                        r[i] = 0.0
            r_load = loads[k] - level_load(P, h)
            nc = n_of[k - 1]
            oc = offsets[k - 1]
            Pc = P_all[oc:oc + nc]
            for j in range(nc):
                Pc[j] = P[2 * j]
                P_old[oc + j] = P[2 * j]
                theta_all[oc + j] = theta[2 * j]
                if mass_conserving:
                    pin_all[oc + j] = dry_all[oc + j] or not P[2 * j] > 0.0
            theta_c = theta_all[oc:oc + nc]
            phi_c = phi_all[oc:oc + nc]
            Hc = level_film(k - 1, Pc, H0s[k], n_of, h_of, parabola, offsets, mlmi_on, m_of, c1s, c2s, weights,
                            direct_below, elastic)
            if film_fas:
                for j in range(nc):  # the film equation's FAS term: the injected state's coarse film is the fine one
                    shape[oc + j] = parabola[oc + j] + (H[2 * j] - Hc[j])
                    Hc[j] = H[2 * j]
            fc = f_all[oc:oc + nc]
            reynolds_residual(Pc, Hc, theta_c, phi_c, h_of[k - 1], lam, viscosity_code, density_code, params, s, c_t,
                              fc)
            for j in range(1, nc - 1):
                fc[j] += 0.25 * r[2 * j - 1] + 0.5 * r[2 * j] + 0.25 * r[2 * j + 1]
            if dry_own:  # coarse nodes dry with both neighbours dry keep their own equation
                for j in range(nc):
                    if Pc[j] <= 0.0 and (j == 0 or Pc[j - 1] <= 0.0) and (j == nc - 1 or Pc[j + 1] <= 0.0):
                        fc[j] = f[2 * j]
            loads[k - 1] = level_load(Pc, h_of[k - 1]) + r_load
            H0s[k - 1] = H0s[k]
    return work


PY = {"coarse_newton": coarse_newton, "deformation_change": deformation_change, "fas_cycle": fas_cycle}


def compiled(name: str):
    """The numba-compiled twin of kernel ``name`` of this module."""
    return _kernels.compiled(name, PY)
