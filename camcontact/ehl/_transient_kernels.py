"""Kernels of the transient line-contact EHL solver (squeeze term, signed entrainment), with twins.

The transient discrete operator at interior node i, in the fixed reference scaling of
:mod:`camcontact.ehl.line_transient`, is

.. math::
    L_i = \\frac{\\xi_{i-1/2}(P_{i-1} - P_i) + \\xi_{i+1/2}(P_{i+1} - P_i)}{h^2}
          - |s|\\,\\frac{1.5\\,q_i - 2\\,q_{i-\\sigma} + 0.5\\,q_{i-2\\sigma}}{h}
          - c_t\\,q_i, \\qquad q = \\bar\\rho H,\\ \\sigma = \\operatorname{sign}(s)

i.e. the steady operator of :mod:`camcontact.ehl._kernels` with the wedge scaled by the signed
entrainment speed ratio s = u_m/u_ref and upwinded in the direction of the flow (second order,
first order at the first interior node on the inflow side: i = 1 for s > 0, i = n - 2 for
s < 0; no wedge at s = 0), plus the implicit part c_t q_i of the time derivative
(BDF1: c_t = 1/dT, BDF2: c_t = a_0/dT). The history part of the time derivative is known and
sits in the right-hand side f. With s = 1, c_t = 0 the operator equals the steady one.

Each function is plain Python (the twin, used by the tests on small grids); :func:`compiled`
hands it to numba (``njit(cache=True, nogil=True)``). The FAS cycle :func:`transient_fas_cycle`
is :func:`camcontact.ehl._fas_kernels.fas_cycle` with these operator pieces; the film, load,
MLMI and dense-solver helpers are shared with the steady solver unchanged.
"""

from __future__ import annotations

import math

import numpy as np
from numba.extending import register_jitable

from . import _kernels
from ._fas_kernels import DOWN, SOLVE, UP, fischer_burmeister, level_film, level_load, solve_dense
from ._kernels import density_ratio, law_state, log_viscosity, nodal_coefficients, nodal_laws

__all__ = ["PY", "compiled"]


@register_jitable
def wedge_weight(i, k, n, s):
    """(weight, node) of term k = 0, 1, 2 of the upwind wedge stencil at node i for speed ratio s.

    Weights 1.5, -2, 0.5 on nodes i, i - sigma, i - 2 sigma; first order (1, -1) when the second
    upstream node is outside the grid; (0, i) for an unused term or s = 0.
    """
    if s == 0.0:
        return 0.0, i
    sigma = 1 if s > 0.0 else -1
    first_order = (i - 2 * sigma < 0) or (i - 2 * sigma > n - 1)
    if first_order:
        if k == 0:
            return 1.0, i
        if k == 1:
            return -1.0, i - sigma
        return 0.0, i
    if k == 0:
        return 1.5, i
    if k == 1:
        return -2.0, i - sigma
    return 0.5, i - 2 * sigma


@register_jitable
def transient_operator_at(i, P, H, rho, xi, h, s, c_t):
    """L_i of the module docstring (central Poiseuille, signed upwind wedge, implicit squeeze)."""
    n = P.shape[0]
    left = 0.5 * (xi[i - 1] + xi[i])
    right = 0.5 * (xi[i] + xi[i + 1])
    poiseuille = (left * (P[i - 1] - P[i]) + right * (P[i + 1] - P[i])) / (h * h)
    wedge = 0.0
    for k in range(3):
        weight, m = wedge_weight(i, k, n, s)
        if weight != 0.0:
            wedge += weight * rho[m] * H[m]
    return poiseuille - abs(s) * wedge / h - c_t * rho[i] * H[i]


@register_jitable
def transient_residual(P, H, h, lam, viscosity_code, density_code, params, s, c_t, out):
    """out_i = L_i(P, H) at interior nodes; boundary entries 0."""
    n = P.shape[0]
    rho = np.empty(n)
    xi = np.empty(n)
    nodal_coefficients(P, H, lam, viscosity_code, density_code, params, rho, xi)
    out[0] = 0.0
    out[n - 1] = 0.0
    for i in range(1, n - 1):
        out[i] = transient_operator_at(i, P, H, rho, xi, h, s, c_t)


@register_jitable
def transient_local_derivatives(i, P, H, rho, xi, dlx, drh, h, K, s, c_t):
    """(dL_i/dP_i, dL_i/dP_{i-1}) of the transient operator, local terms only (as
    :func:`camcontact.ehl._kernels.local_derivatives`, plus the signed wedge and the squeeze)."""
    n = P.shape[0]
    inv_pi = 1.0 / math.pi
    hh = h * h
    left = 0.5 * (xi[i - 1] + xi[i])
    right = 0.5 * (xi[i] + xi[i + 1])
    a = (P[i - 1] - P[i]) / hh
    c = (P[i + 1] - P[i]) / hh
    d_i = -(left + right) / hh
    d_im1 = left / hh
    for q in range(3):
        m = i - 1 + q
        weight = 0.5 * a if q == 0 else (0.5 * (a + c) if q == 1 else 0.5 * c)
        if weight == 0.0:
            continue
        dxi_dp = xi[m] * dlx[m]
        dxi_dh = 3.0 * xi[m] / H[m] if H[m] > 0.0 else 0.0
        if m == i:
            d_i += weight * dxi_dp
        elif m == i - 1:
            d_im1 += weight * dxi_dp
        d_i -= weight * dxi_dh * inv_pi * K[abs(m - i)]
        d_im1 -= weight * dxi_dh * inv_pi * K[abs(m - i + 1)]
    # wedge and squeeze: -sum_k c_k d(rho_m H_m), c_k = |s| w_k / h (+ c_t at m = i)
    for k in range(3):
        weight, m = wedge_weight(i, k, n, s)
        coefficient = abs(s) * weight / h
        if k == 0:
            coefficient += c_t
        if coefficient == 0.0:
            continue
        d_i += inv_pi * coefficient * rho[m] * K[abs(m - i)]
        d_im1 += inv_pi * coefficient * rho[m] * K[abs(m - i + 1)]
        if m == i:
            d_i -= coefficient * drh[m] * H[m]
        elif m == i - 1:
            d_im1 -= coefficient * drh[m] * H[m]
    return d_i, d_im1


@register_jitable
def transient_relax(P, H, f, h, lam, viscosity_code, density_code, params, K, omega_gs, omega_jacobi, switch,
                    window, first, last, dry, s, c_t):
    """One hybrid Gauss–Seidel / Jacobi-distributive sweep for L(P) = f (transient operator).

    As :func:`camcontact.ehl._kernels.relax_hybrid`; the integral response a node's regime is
    judged against is that of the signed wedge plus the squeeze term,
    |(|s| sum_k w_k rho_m K(|m - i|)/h + c_t rho_i K(0)) / pi|. Returns the number of
    distributive nodes.
    """
    n = P.shape[0]
    rho = np.empty(n)
    xi = np.empty(n)
    dlx = np.empty(n)
    drh = np.empty(n)
    nodal_laws(P, H, lam, viscosity_code, density_code, params, rho, xi, dlx, drh)
    delta = np.zeros(n)
    jacobi = np.zeros(n, dtype=np.bool_)
    count = 0
    inv_pi = 1.0 / math.pi
    first = max(first, 1)
    last = min(last, n - 2)
    for i in range(1, n - 1):
        coefficient = 0.5 * (xi[i - 1] + 2.0 * xi[i] + xi[i + 1]) / (h * h)
        d_integral = c_t * rho[i] * K[0]
        for k in range(3):
            weight, m = wedge_weight(i, k, n, s)
            if weight != 0.0:
                d_integral += abs(s) * weight * rho[m] * K[abs(m - i)] / h
        jacobi[i] = coefficient < switch * abs(inv_pi * d_integral)
    for i in range(first, last + 1):
        if dry[i]:
            continue
        r = f[i] - transient_operator_at(i, P, H, rho, xi, h, s, c_t)
        diagonal, off_diagonal = transient_local_derivatives(i, P, H, rho, xi, dlx, drh, h, K, s, c_t)
        if not jacobi[i]:
            if diagonal == 0.0:
                continue
            new = P[i] + omega_gs * r / diagonal
            if new < 0.0:
                new = 0.0
            change = new - P[i]
            if change != 0.0:
                P[i] = new
                low = max(i - window, 0)
                high = min(i + window, n - 1)
                for m in range(low, high + 1):
                    H[m] -= inv_pi * K[abs(m - i)] * change
                for m in range(max(low, i - 1), min(high, i + 1) + 1):
                    r_m = density_ratio(P[m], density_code, params)
                    rho[m] = r_m
                    hm = max(H[m], 0.0)
                    xi[m] = r_m * hm * hm * hm * math.exp(-log_viscosity(P[m], viscosity_code, params)) / lam
        elif jacobi[i - 1]:
            dipole = diagonal - off_diagonal
            if dipole != 0.0:
                delta[i] = r / dipole
            count += 1
        else:
            if diagonal != 0.0:
                delta[i] = r / diagonal
            count += 1
    for i in range(first, last + 1):
        if jacobi[i]:
            P[i] += omega_jacobi * delta[i]
            if jacobi[i - 1]:
                P[i - 1] -= omega_jacobi * delta[i]
    for i in range(max(first - 1, 1), last + 1):
        if P[i] < 0.0 or dry[i]:
            P[i] = 0.0
    return count


@register_jitable
def transient_dense_state(P, H0, f, parabola, K_over_pi, h, lam, viscosity_code, density_code, params, elastic,
                          s, c_t, H, L):
    """Film H and L - f (interior; 0 at the ends) with the dense deformation matrix K/pi."""
    n = P.shape[0]
    for i in range(n):
        value = H0 + parabola[i]
        if elastic:
            for j in range(n):
                if P[j] != 0.0:
                    value -= K_over_pi[i, j] * P[j]
        H[i] = value
    transient_residual(P, H, h, lam, viscosity_code, density_code, params, s, c_t, L)
    for i in range(1, n - 1):
        L[i] -= f[i]


@register_jitable
def transient_coarse_newton(P, H0, f, f_load, parabola, K_over_pi, h, lam, viscosity_code, density_code, params,
                            elastic, s, c_t, tolerance, max_iterations):
    """Semi-smooth Newton (Fischer–Burmeister) for L(P, H0) = f, load = f_load on a small grid.

    :func:`camcontact.ehl._fas_kernels.coarse_newton` for the transient operator (the local
    Jacobian band spans i - 2..i + 2 for either flow direction). Returns (P, H0, iterations,
    status) with the status codes of the steady kernel.
    """
    n = P.shape[0]
    m = n - 2
    P = P.copy()
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
    phi = np.empty(m)
    da = np.empty(m)
    db = np.empty(m)
    A = np.empty((m + 1, m + 1))
    rhs = np.empty(m + 1)
    P_new = np.empty(n)
    hh = h * h
    transient_dense_state(P, H0, f, parabola, K_over_pi, h, lam, viscosity_code, density_code, params, elastic,
                          s, c_t, H, L)
    status = 4
    iterations = 0
    for _ in range(max_iterations):
        iterations += 1
        for j in range(n):
            r, d_r, log_eta, dlog_eta = law_state(P[j], viscosity_code, density_code, params)
            e = math.exp(-log_eta)
            gap = max(H[j], 0.0)
            rho[j] = r
            drho[j] = d_r
            xi[j] = r * gap * gap * gap * e / lam
            dxi_dH[j] = 3.0 * r * gap * gap * e / lam
            dxi_dP[j] = xi[j] * (d_r / r - dlog_eta)
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
                weight, mm = wedge_weight(i, k, n, s)
                coefficient = abs(s) * weight / h
                if k == 0:
                    coefficient += c_t
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
        residual = 0.0
        merit = 0.0
        for k in range(m):
            i = k + 1
            scale[i] = 1.0 / max(abs(J[i, i]), 1e-300)
            phi[k], da[k], db[k] = fischer_burmeister(P[i], -scale[i] * L[i])
            residual = max(residual, abs(phi[k]))
            merit += phi[k] * phi[k]
        load = h * (P.sum() - 0.5 * (P[0] + P[n - 1])) - 0.5 * math.pi - f_load
        merit += load * load
        if residual < tolerance and abs(load) < tolerance:
            status = 0
            break
        for k in range(m):
            i = k + 1
            factor = -db[k] * scale[i]
            for l in range(m):
                A[k, l] = factor * J[i, l + 1]
            A[k, k] += da[k]
            A[k, m] = factor * J_H0[i]
            rhs[k] = -phi[k]
        for l in range(m):
            A[m, l] = h
        A[m, m] = 0.0
        rhs[m] = -load
        step, ok = solve_dense(A, rhs)
        if not ok:
            status = 2
            break
        t = 1.0
        accepted = False
        while t > 1e-6:
            P_new[0] = P[0]
            P_new[n - 1] = P[n - 1]
            for k in range(m):
                P_new[k + 1] = P[k + 1] + t * step[k]
            H0_new = H0 + t * step[m]
            transient_dense_state(P_new, H0_new, f, parabola, K_over_pi, h, lam, viscosity_code, density_code,
                                  params, elastic, s, c_t, H_new, L_new)
            trial = 0.0
            for k in range(m):
                value, _, _ = fischer_burmeister(P_new[k + 1], -scale[k + 1] * L_new[k + 1])
                trial += value * value
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


def transient_fas_cycle(schedule, P_all, P_old, f_all, H0s, loads, dry_all, n_of, offsets, h_of, parabola, K_local,
                        mlmi_on, m_of, c1s, c2s, weights, direct_below, K_dense, lam, viscosity_code, density_code,
                        params, elastic, real_settings, int_settings, s, c_t):
    """One FAS cycle ``schedule`` for the transient operator (speed ratio s, squeeze coefficient c_t).

    Identical in structure and buffers to :func:`camcontact.ehl._fas_kernels.fas_cycle` (see
    there); relaxation, residuals and the coarsest-grid Newton use the transient operator.
    Returns the work done in finest-grid relaxation units.
    """
    omega_gs, omega_jacobi, switch, h0_relaxation = real_settings[0], real_settings[1], real_settings[2], real_settings[3]
    pre, post, coarsest_sweeps, window = int_settings[0], int_settings[1], int_settings[2], int_settings[3]
    pressurised_only = int_settings[4] != 0
    freeze_boundary = int_settings[5] != 0
    dry_own = int_settings[6] != 0
    n_finest = n_of[n_of.shape[0] - 1]
    zero_K = np.zeros(K_local.shape[1])
    work = 0.0
    for step in range(schedule.shape[0]):
        op = schedule[step, 0]
        k = schedule[step, 1]
        n = n_of[k]
        o = offsets[k]
        h = h_of[k]
        P = P_all[o:o + n]
        f = f_all[o:o + n]
        dry = dry_all[o:o + n]
        K = K_local[k] if elastic else zero_K
        sweeps = pre if op == DOWN else (post if op == UP else 0)
        if op == UP:
            oc = offsets[k - 1]
            correction = np.empty(n)
            for i in range(n):
                if i % 2 == 0:
                    change = P_all[oc + i // 2] - P_old[oc + i // 2]
                else:
                    j = i // 2
                    change = 0.5 * (P_all[oc + j] - P_old[oc + j] + P_all[oc + j + 1] - P_old[oc + j + 1])
                if pressurised_only:
                    if not (P[i] > 0.0 and (i == 0 or P[i - 1] > 0.0) and (i == n - 1 or P[i + 1] > 0.0)):
                        change = 0.0
                correction[i] = change
            for i in range(n):
                P[i] = max(P[i] + correction[i], 0.0)
            P[0] = 0.0
            P[n - 1] = 0.0
            H0s[k] = H0s[k - 1]
        for _ in range(sweeps):
            H = level_film(k, P, H0s[k], n_of, h_of, parabola, offsets, mlmi_on, m_of, c1s, c2s, weights,
                           direct_below, elastic)
            transient_relax(P, H, f, h, lam, viscosity_code, density_code, params, K, omega_gs, omega_jacobi, switch,
                            window, 1, n - 2, dry, s, c_t)
            work += (n - 2) / n_finest
        if op == SOLVE:
            P_new, H0_new, iterations, status = transient_coarse_newton(
                P, H0s[k], f, loads[k], parabola[o:o + n], K_dense[k, :n, :n], h, lam, viscosity_code,
                density_code, params, elastic, s, c_t, 1e-11, 60)
            work += iterations * n / n_finest
            if status == 0:
                for i in range(n):
                    P[i] = P_new[i]
                H0s[k] = H0_new
            else:
                for _ in range(coarsest_sweeps):
                    H = level_film(k, P, H0s[k], n_of, h_of, parabola, offsets, mlmi_on, m_of, c1s, c2s, weights,
                                   direct_below, elastic)
                    transient_relax(P, H, f, h, lam, viscosity_code, density_code, params, K, omega_gs, omega_jacobi,
                                    switch, window, 1, n - 2, dry, s, c_t)
                    work += (n - 2) / n_finest
                    H0s[k] += h0_relaxation * (level_load(P, h) - loads[k])
        elif op == DOWN:
            H = level_film(k, P, H0s[k], n_of, h_of, parabola, offsets, mlmi_on, m_of, c1s, c2s, weights,
                           direct_below, elastic)
            r = np.empty(n)
            transient_residual(P, H, h, lam, viscosity_code, density_code, params, s, c_t, r)
            for i in range(n):
                r[i] = 0.0 if P[i] <= 0.0 else f[i] - r[i]
            if freeze_boundary:
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
            Hc = level_film(k - 1, Pc, H0s[k], n_of, h_of, parabola, offsets, mlmi_on, m_of, c1s, c2s, weights,
                            direct_below, elastic)
            fc = f_all[oc:oc + nc]
            transient_residual(Pc, Hc, h_of[k - 1], lam, viscosity_code, density_code, params, s, c_t, fc)
            for j in range(1, nc - 1):
                fc[j] += 0.25 * r[2 * j - 1] + 0.5 * r[2 * j] + 0.25 * r[2 * j + 1]
            if dry_own:
                for j in range(nc):
                    if Pc[j] <= 0.0 and (j == 0 or Pc[j - 1] <= 0.0) and (j == nc - 1 or Pc[j + 1] <= 0.0):
                        fc[j] = f[2 * j]
            loads[k - 1] = level_load(Pc, h_of[k - 1]) + r_load
            H0s[k - 1] = H0s[k]
    return work


PY = {
    "transient_residual": transient_residual,
    "transient_relax": transient_relax,
    "transient_coarse_newton": transient_coarse_newton,
    "transient_fas_cycle": transient_fas_cycle,
}


def compiled(name: str):
    """The numba-compiled twin of kernel ``name`` of this module."""
    return _kernels.compiled(name, PY)
