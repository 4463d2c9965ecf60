"""Numba kernels of the line-contact EHL solver, each with its plain-Python twin.

Every kernel is written once, as plain Python on float64 arrays (the *twin*, used by the
tests on small grids and readable as the specification); :func:`compiled` returns the
``numba.njit(cache=True, nogil=True)`` version of the same function, compiled on first use.
Helpers are ``register_jitable`` so that they run both inside compiled code and as Python.

The discrete operator at interior node i (Tsuha 2015 Eqs. 5.38, 5.42 for the steady case; in the fixed
reference scaling of :mod:`camcontact.ehl.line_transient` for the transient one) is

.. math::
    L_i = \\frac{\\xi_{i-1/2}(P_{i-1} - P_i) + \\xi_{i+1/2}(P_{i+1} - P_i)}{h^2}
          - |s|\\,\\frac{1.5\\,c_i q_i - 2\\,c_{i-\\sigma} q_{i-\\sigma} + 0.5\\,c_{i-2\\sigma} q_{i-2\\sigma}}{h}
          - c_t\\,q_i, \\qquad q = \\theta\\bar\\rho H,\\ \\sigma = \\operatorname{sign}(s)

a central Poiseuille term, the wedge scaled by the signed
entrainment speed ratio s = u_m/u_ref and upwinded in the direction of the flow (second order,
first order at the first interior node on the inflow side: i = 1 for s > 0, i = n - 2 for
s < 0; no wedge at s = 0), plus the implicit part c_t q_i of the time derivative
(BDF1: c_t = 1/dT, BDF2: c_t = a_0/dT). The history part of the time derivative is known and
sits in the right-hand side f. The steady operator is the case s = 1, c_t = 0.

theta is the film fraction of the mass-conserving (Jakobsson–Floberg–Olsson) cavitation model in
the complementarity form of Giacopini et al. (2010): P >= 0, theta <= 1, P (1 - theta) = 0, the
lubricant content q = theta rho H transported by the wedge and squeeze terms (the Poiseuille flow
xi dP/dX is that of a full film). theta = 1 at every node is the classical (Reynolds, cavitation by
clipping) operator; :func:`relax_hybrid` with ``update_theta`` solves for theta where P = 0. The
boundary node upstream (X_a for s > 0, X_b for s < 0) holds the supply: its content is the inlet
layer (starvation) or a full film.

phi holds three numbers per node, phi[i] = (a_i, k_i, c_i): the flow factor on the Poiseuille coefficient,
xi = F rho H^3/(eta lambda) with F = a_i sqrt(1 + (k_i eta-bar(P))^2) (:func:`flow_factor`), and the Couette
factor c_i on the wedge's content, c theta rho H (the entrainment flux of a film whose viscosity varies across it,
u_e h = c u_m h: Yang & Wen's 1990 generalised Reynolds equation, its rho*/rho; the squeeze term keeps the
content theta rho H); (1, 0, 1) for the isothermal Newtonian film. The thermal and non-Newtonian solver
(:mod:`camcontact.ehl.line_thermal`) puts in a the Poiseuille coefficient of the film's viscosity profile, in k
the Eyring coefficient of the Reynolds–Eyring flow factor cosh(tau_m/tau0) = sqrt(1 + Lambda^2), Lambda =
k eta-bar, and in c the profile's Couette factor (a and c times the film's density factor exp(-alpha_T dT) where
the lubricant expands as it heats). The Eyring factor's dependence on the pressure is kept in the
kernels (with Lambda >> 1 the Poiseuille flow of a sheared Eyring film no longer depends on the viscosity; a
flow factor frozen at the viscosity of the previous pressure made the Hertz zone of a heavily loaded contact
behave like a contact of 1000 times its load parameter M, and the multigrid diverged: measured, M = 28,
L = 14, S = 0.1). a, k and c are held fixed during a solve.

Importing this module imports numba but compiles nothing.
"""

from __future__ import annotations

import math

import numpy as np
from numba.extending import register_jitable

from ..jit import compile_kernel, helper

__all__ = ["PY", "compiled"]

#: 6th-order interpolation weights from coarse points J0-2..J0+3 to the midpoint of J0, J0+1
INTERP6 = np.array([3.0, -25.0, 150.0, 150.0, -25.0, 3.0]) / 256.0


# ----------------------------------------------------------------------------- deformation kernel
@helper
def _antiderivative(t):
    """F(t) = t (ln|t| - 1), an odd antiderivative of ln|t| (F(0) = 0)."""
    if t == 0.0:
        return 0.0
    return t * (math.log(abs(t)) - 1.0)


@helper
def kernel_value(d, h):
    """K(d) = int_{(d - 1/2) h}^{(d + 1/2) h} ln|t| dt for real d (Tsuha 2015 Eq. 5.46)."""
    return _antiderivative((d + 0.5) * h) - _antiderivative((d - 0.5) * h)


@register_jitable
def deformation_direct(P, h):
    """w_i = sum_j K(i - j) P_j on a uniform grid (O(n^2)); H = H0 + X^2/2 - w/pi."""
    n = P.shape[0]
    table = np.empty(n)
    for d in range(n):
        table[d] = kernel_value(float(d), h)
    w = np.zeros(n)
    for j in range(n):
        pj = P[j]
        if pj == 0.0:
            continue
        for i in range(n):
            w[i] += table[abs(i - j)] * pj
    return w


# ----------------------------------------------------------------------------- MLMI pieces
@register_jitable
def mlmi_anterpolate(u, first, weights):
    """Coarse 'charges' U = Pi^T u of fine values u on fine indices first..first+len(u)-1.

    Returns (U, J_first): U on coarse indices J_first.. (fine index 2J). Even fine points
    inject; odd ones (midpoints of J0, J0+1) spread with the 6-point weights to J0-2..J0+3.
    """
    last = first + u.shape[0] - 1
    j_first = (first - 1) // 2 - 2
    j_last = last // 2 + 3
    U = np.zeros(j_last - j_first + 1)
    for k in range(u.shape[0]):
        value = u[k]
        if value == 0.0:
            continue
        j = first + k
        if j % 2 == 0:
            U[j // 2 - j_first] += value
        else:
            j0 = (j - 1) // 2
            for s in range(6):
                U[j0 - 2 + s - j_first] += weights[s] * value
    return U, j_first


@register_jitable
def mlmi_direct(U, u_first, out_first, out_count, h, stride):
    """W(I) = sum_J K(stride (I - J)) U(J) for I = out_first..out_first+out_count-1 (fine kernel of width h).

    The kernel values are tabulated once per offset I - J (two logarithms each, not per pair).
    """
    lowest = out_first - (u_first + U.shape[0] - 1)
    table = np.empty(out_count + U.shape[0] - 1)
    for k in range(table.shape[0]):
        table[k] = kernel_value(float(stride * (lowest + k)), h)
    W = np.zeros(out_count)
    for k in range(U.shape[0]):
        value = U[k]
        if value == 0.0:
            continue
        base = out_first - (u_first + k) - lowest
        row = table[base:base + out_count]  # a view: its index cannot be negative, so the loop vectorises
        for o in range(out_count):
            W[o] += row[o] * value
    return W


@register_jitable
def mlmi_correction_tables(h, stride, m, weights):
    """c1(d), c2(e) for d, e in [-m, m]: exact kernel minus its interpolated approximation.

    c1(d) = K(d) - sum_s w_s K(d + 1 - 2(s - 2)) (source-side, odd source points);
    c2(e) = K(e) - sum_s w_s K(e - 1 + 2(s - 2)) (target-side, odd target points);
    K(d) = kernel_value(stride * d, h).
    """
    c1 = np.zeros(2 * m + 1)
    c2 = np.zeros(2 * m + 1)
    for k in range(2 * m + 1):
        d = k - m
        exact = kernel_value(float(stride * d), h)
        approx1 = 0.0
        approx2 = 0.0
        for s in range(6):
            shift = 2 * (s - 2)
            approx1 += weights[s] * kernel_value(float(stride * (d + 1 - shift)), h)
            approx2 += weights[s] * kernel_value(float(stride * (d - 1 + shift)), h)
        c1[k] = exact - approx1
        c2[k] = exact - approx2
    return c1, c2


@register_jitable
def mlmi_interpolate_correct(W, w_first, U, u_coarse_first, u, u_first, out_first, out_count, c1, c2, m, weights):
    """Fine result on out_first.. from coarse W (on w_first..), with both local corrections.

    even i: V(i) = W(i/2); odd i: V(i) = sum_s w_s W(i0 - 2 + s) + sum_J c2(i - 2J) U(J);
    then w(i) = V(i) + sum_{odd j, |i - j| <= m} c1(i - j) u(j).

    Evaluated on the even and the odd targets as two contiguous arrays, one correction offset at a time over all
    targets (a loop of multiply-adds over contiguous memory, 1.25x faster than the per-target sums over strided
    sources it replaces at 28,673 nodes; the same sums, in another order).
    """
    out_last = out_first + out_count - 1
    e0 = out_first if out_first % 2 == 0 else out_first + 1  # even targets e0 + 2a, odd targets o0 + 2a
    o0 = out_first if out_first % 2 != 0 else out_first + 1
    ne = (out_last - e0) // 2 + 1 if out_last >= e0 else 0
    no = (out_last - o0) // 2 + 1 if out_last >= o0 else 0
    even = np.empty(ne)
    odd = np.empty(no)
    # the loops below run over views (slices) indexed from 0: numba then omits its wrap-around test for negative
    # indices and the loops vectorise (measured, the whole MLMI film: 55 -> 13-15 ns per node at 1793 and 28,673
    # nodes); every sum is the same, in the same order (bitwise the same film)
    W_even = W[e0 // 2 - w_first:]
    for a in range(ne):
        even[a] = W_even[a]
    shift = (o0 - 1) // 2 - 2 - w_first
    W0, W1, W2 = W[shift:shift + no], W[shift + 1:shift + 1 + no], W[shift + 2:shift + 2 + no]
    W3, W4, W5 = W[shift + 3:shift + 3 + no], W[shift + 4:shift + 4 + no], W[shift + 5:shift + 5 + no]
    for a in range(no):
        odd[a] = (weights[0] * W0[a] + weights[1] * W1[a] + weights[2] * W2[a] + weights[3] * W3[a]
                  + weights[4] * W4[a] + weights[5] * W5[a])
    # target-side correction of the odd targets over the coarse sources J, e = i - 2J odd in [-m, m]
    U_last = u_coarse_first + U.shape[0] - 1
    for e in range(-m, m + 1):
        if e % 2 == 0:
            continue
        c = c2[e + m]
        J0 = (o0 - e) // 2  # J of target a is J0 + a
        low, high = max(0, u_coarse_first - J0), min(no - 1, U_last - J0) + 1
        if high <= low:
            continue
        _add_scaled(odd[low:high], c, U[J0 - u_coarse_first + low:J0 - u_coarse_first + high])
    # source-side correction over the odd fine sources j = j0 + 2q (contiguous copy uo)
    u_last = u_first + u.shape[0] - 1
    j0 = u_first if u_first % 2 != 0 else u_first + 1
    nq = (u_last - j0) // 2 + 1 if u_last >= j0 else 0
    uo = np.empty(nq)
    u_odd = u[j0 - u_first:]
    for q in range(nq):
        uo[q] = u_odd[2 * q]
    for d in range(-m, m + 1):
        c = c1[d + m]
        if d % 2 != 0:  # target i = j + d is even
            t0, count, target = e0, ne, even
        else:
            t0, count, target = o0, no, odd
        shift = (t0 - j0 - d) // 2  # source q of target a is a + shift
        low, high = max(0, -shift), min(count - 1, nq - 1 - shift) + 1
        if high <= low:
            continue
        _add_scaled(target[low:high], c, uo[low + shift:high + shift])
    out = np.empty(out_count)
    out_even, out_odd = out[e0 - out_first:], out[o0 - out_first:]
    for a in range(ne):
        out_even[2 * a] = even[a]
    for a in range(no):
        out_odd[2 * a] = odd[a]
    return out


@helper
def _add_scaled(target, c, source):
    """target += c source, element by element (two views of one length)."""
    for a in range(target.shape[0]):
        target[a] += c * source[a]


@register_jitable
def mlmi_apply(P, h, m, c1s, c2s, weights, direct_below):
    """w = K P by multilevel multi-integration, all levels in one call (no Python recursion).

    Anterpolates P level by level (:func:`mlmi_anterpolate`) until at most ``direct_below``
    source points remain, sums directly there (:func:`mlmi_direct`) and interpolates back with
    the local corrections (:func:`mlmi_interpolate_correct`). ``c1s[d]``, ``c2s[d]`` are the
    correction tables of stride 2^d (:func:`mlmi_correction_tables`), ``m`` their width.
    """
    sources = [P.copy()]
    firsts = [0]
    out_firsts = [0]
    out_counts = [P.shape[0]]
    u = sources[0]
    while u.shape[0] > direct_below:
        depth = len(sources) - 1
        U, coarse_first = mlmi_anterpolate(u, firsts[depth], weights)
        out_last = out_firsts[depth] + out_counts[depth] - 1
        w_first = (out_firsts[depth] - 1) // 2 - 2
        sources.append(U)
        firsts.append(coarse_first)
        out_firsts.append(w_first)
        out_counts.append(out_last // 2 + 3 - w_first + 1)
        u = U
    deepest = len(sources) - 1
    W = mlmi_direct(u, firsts[deepest], out_firsts[deepest], out_counts[deepest], h, 1 << deepest)
    for depth in range(deepest - 1, -1, -1):
        W = mlmi_interpolate_correct(W, out_firsts[depth + 1], sources[depth + 1], firsts[depth + 1],
                                     sources[depth], firsts[depth], out_firsts[depth], out_counts[depth],
                                     c1s[depth], c2s[depth], m, weights)
    return W


# ----------------------------------------------------------------------------- lubricant laws
# law codes: viscosity 0 = Barus, 1 = Roelands; density 0 = incompressible, 1 = Dowson-Higginson
# params = [alpha_bar, p_h/p0, alpha p0/z, z, p_h/5.9e8, 1.34]


@helper
def log_viscosity(P, viscosity_code, params):
    """ln(eta-bar) at dimensionless pressure P (negative P counts as 0)."""
    if P <= 0.0:
        return 0.0
    if viscosity_code == 0:
        return params[0] * P
    return params[2] * math.expm1(params[3] * math.log1p(P * params[1]))


@helper
def pressure_of_log_viscosity(level, viscosity_code, params):
    """A dimensionless pressure at or below which ln(eta-bar) <= ``level`` (>= 0): the inverse of
    :func:`log_viscosity`, lowered by 1e-9 relative against rounding; infinite for an isoviscous lubricant."""
    if viscosity_code == 0:
        return level / params[0] * (1.0 - 1e-9) if params[0] > 0.0 else math.inf
    if not (params[1] > 0.0 and params[2] > 0.0 and params[3] > 0.0):
        return math.inf
    return math.expm1(math.log1p(level / params[2]) / params[3]) / params[1] * (1.0 - 1e-9)


@helper
def density_ratio(P, density_code, params):
    if density_code == 0 or P <= 0.0:
        return 1.0
    q = P * params[4]
    return (1.0 + params[5] * q) / (1.0 + q)


@helper
def full_film(j, P, theta):
    """True where node j carries a full film: pressurised, or its film fraction theta = 1."""
    return P[j] > 0.0 or theta[j] >= 1.0


@helper
def wedge_weight(i, k, n, s, P, theta):
    """(weight, node) of term k = 0, 1, 2 of the upwind wedge stencil at node i for speed ratio s.

    The wedge is the difference G_i - G_(i-sigma) of the upwind fluxes G_j = q_j + phi_j (q_j - q_(j-sigma))/2,
    second order (phi_j = 1) where the upstream node j - sigma carries a full film (:func:`full_film`), first
    order (phi_j = 0) where it is partly filled (second-order upwinding across the jump of theta at a
    reformation front overshoots). phi_j does not depend on node j itself, so that node i's equation is
    linear in its own content: with a limiter that also looked at node i, a node at the rupture could be
    "full" (second order, wanting no pressure) and "partly filled" (first order, wanting pressure) at once
    and stay at P = 0, theta = 1 with a residual (measured: 0.13 at M = 20, L = 5, level 8, the mass flux
    then off by 0.6 %). With a full film throughout, the weights are 1.5, -2, 0.5 on nodes i, i - sigma,
    i - 2 sigma. First order
    (1, -1) when the second upstream node is outside the grid; (0, i) for an unused term or s = 0. The
    limiter keeps the scheme conservative (:attr:`camcontact.ehl.line_solution.LineEHLSolution.mass_flux`).
    """
    w0, w1, w2, m1, m2 = wedge_stencil(i, n, s, P, theta)
    if k == 0:
        return w0, i
    if k == 1:
        return w1, m1
    return w2, m2


@helper
def wedge_stencil(i, n, s, P, theta):
    """The three terms of :func:`wedge_weight` at node i at once: (w0, w1, w2, m1, m2), the weights of nodes i, m1
    and m2 (what the sweeps use: one evaluation per node instead of one per term and use; an unused term has
    weight 0 at node i)."""
    if s == 0.0:
        return 0.0, 0.0, 0.0, i, i
    sigma = 1 if s > 0.0 else -1
    if (i - 2 * sigma < 0) or (i - 2 * sigma > n - 1):
        return 1.0, -1.0, 0.0, i - sigma, i
    up = i - sigma
    phi_i = 1.0 if full_film(up, P, theta) else 0.0
    phi_up = 1.0 if full_film(up - sigma, P, theta) else 0.0
    return 1.0 + 0.5 * phi_i, -1.0 - 0.5 * (phi_i + phi_up), 0.5 * phi_up, up, up - sigma


@helper
def local_derivatives(i, P, H, rho, theta, xi, dlx, drh, h, K, s, c_t, couette_i):
    """(dL_i/dP_i, dL_i/dP_{i-1}) of the discrete operator, local terms only.

    Includes the Poiseuille coefficients, their dependence on P (through rho and eta) and on
    the films H_{i-1..i+1} (through K), and the dependence of the wedge and squeeze terms on
    rho(P) and on the films. ``dlx`` = d ln(xi)/dP at fixed H and ``drh`` = d rho/dP hold the
    nodal law derivatives.
    """
    w0, w1, w2, m1, m2 = wedge_stencil(i, P.shape[0], s, P, theta)
    return derivatives_with(i, P, H, rho, xi, dlx, drh, h, K, s, c_t, couette_i, w0, w1, w2, m1, m2)


@helper
def derivatives_with(i, P, H, rho, xi, dlx, drh, h, K, s, c_t, couette_i, w0, w1, w2, m1, m2):
    """:func:`local_derivatives` with the node's wedge stencil given (:func:`wedge_stencil`); ``couette_i`` the
    node's Couette factor (rho holds it for the wedge; the squeeze content is rho/c)."""
    inv_pi = 1.0 / math.pi
    hh = h * h
    left = 0.5 * (xi[i - 1] + xi[i])
    right = 0.5 * (xi[i] + xi[i + 1])
    a = (P[i - 1] - P[i]) / hh
    c = (P[i + 1] - P[i]) / hh
    d_i = -(left + right) / hh
    d_im1 = left / hh
    # coefficients of xi_m in L_i: m = i-1, i, i+1
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
    # wedge and squeeze: -sum_k c_k d(rho_m H_m), c_k = |s| w_k / h (+ c_t/c_i at m = i)
    d_i, d_im1 = _wedge_term(abs(s) * w0 / h + c_t / couette_i, i, i, rho, drh, H, K, inv_pi, d_i, d_im1)
    d_i, d_im1 = _wedge_term(abs(s) * w1 / h, m1, i, rho, drh, H, K, inv_pi, d_i, d_im1)
    return _wedge_term(abs(s) * w2 / h, m2, i, rho, drh, H, K, inv_pi, d_i, d_im1)


@helper
def _wedge_term(coefficient, m, i, rho, drh, H, K, inv_pi, d_i, d_im1):
    """(d_i, d_im1) plus the derivatives of the wedge/squeeze term -coefficient rho_m H_m of L_i."""
    if coefficient == 0.0:
        return d_i, d_im1
    d_i += inv_pi * coefficient * rho[m] * K[abs(m - i)]
    d_im1 += inv_pi * coefficient * rho[m] * K[abs(m - i + 1)]
    if m == i:
        d_i -= coefficient * drh[m] * H[m]
    elif m == i - 1:
        d_im1 -= coefficient * drh[m] * H[m]
    return d_i, d_im1


# ----------------------------------------------------------------------------- EHL operator
@helper
def flow_factor(phi, i, log_eta):
    """(F, s) at node i with ln(eta-bar) = log_eta: the flow factor F = a sqrt(1 + Lambda^2), Lambda = k eta-bar
    (module docstring) and s = Lambda^2/(1 + Lambda^2) = d ln F / d ln eta-bar."""
    k = phi[i, 1]
    if k == 0.0:
        return phi[i, 0], 0.0
    lam2 = k * math.exp(log_eta)
    lam2 *= lam2
    return phi[i, 0] * math.sqrt(1.0 + lam2), lam2 / (1.0 + lam2)


@helper
def nodal_coefficients(P, H, theta, phi, lam, viscosity_code, density_code, params, rho, xi):
    """Fill rho (theta times the density ratio: the content factor of the wedge) and xi = F rho_law H^3 /
    (eta lambda) (a full film's, F the node's flow factor, :func:`flow_factor`) at every node."""
    for i in range(P.shape[0]):
        r = density_ratio(P[i], density_code, params)
        rho[i] = r * theta[i] * phi[i, 2]
        hi = max(H[i], 0.0)  # a closed gap (H <= 0) passes no pressure flow
        log_eta = log_viscosity(P[i], viscosity_code, params)
        xi[i] = flow_factor(phi, i, log_eta)[0] * r * hi * hi * hi * math.exp(-log_eta) / lam


@helper
def law_state(p, viscosity_code, density_code, params):
    """(rho, d rho/dP, ln eta, d ln eta/dP) at P; right-hand derivatives at P = 0, none below."""
    if p < 0.0:
        return 1.0, 0.0, 0.0, 0.0
    if viscosity_code == 0:
        log_eta = params[0] * p
        dlog_eta = params[0]
    else:
        base = p * params[1]
        power = math.exp(params[3] * math.log1p(base))
        log_eta = params[2] * (power - 1.0)
        dlog_eta = params[2] * params[3] * params[1] * power / (1.0 + base)
    if density_code == 1:
        q = p * params[4]
        r = (1.0 + params[5] * q) / (1.0 + q)
        d_r = params[4] * (params[5] - 1.0) / ((1.0 + q) * (1.0 + q))
    else:
        r = 1.0
        d_r = 0.0
    return r, d_r, log_eta, dlog_eta


@helper
def nodal_laws(P, H, theta, phi, lam, viscosity_code, density_code, params, rho, xi, dlx, drh):
    """:func:`nodal_coefficients` plus d ln(xi)/dP and d (theta rho)/dP (a and k of the flow factor held fixed),
    sharing one log1p and exp per node."""
    for i in range(P.shape[0]):
        p = P[i]
        hi = max(H[i], 0.0)  # a closed gap (H <= 0) passes no pressure flow
        if p <= 0.0:
            rho[i] = theta[i] * phi[i, 2]
            xi[i] = flow_factor(phi, i, 0.0)[0] * hi * hi * hi / lam
            dlx[i] = 0.0
            drh[i] = 0.0
            continue
        r, d_r, log_eta, dlog_eta = law_state(p, viscosity_code, density_code, params)
        rho[i] = r * theta[i] * phi[i, 2]
        factor, share = flow_factor(phi, i, log_eta)
        xi[i] = factor * r * hi * hi * hi * math.exp(-log_eta) / lam
        dlx[i] = d_r / r - (1.0 - share) * dlog_eta
        drh[i] = d_r * theta[i] * phi[i, 2]


@helper
def operator_at(i, P, H, rho, theta, xi, h, s, c_t, couette_i):
    """L_i of the module docstring (central Poiseuille, signed upwind wedge, implicit squeeze)."""
    w0, w1, w2, m1, m2 = wedge_stencil(i, P.shape[0], s, P, theta)
    return operator_with(i, P, H, rho, xi, h, s, c_t, couette_i, w0, w1, w2, m1, m2)


@helper
def operator_with(i, P, H, rho, xi, h, s, c_t, couette_i, w0, w1, w2, m1, m2):
    """:func:`operator_at` with the node's wedge stencil given (:func:`wedge_stencil`); ``couette_i`` the node's
    Couette factor (rho holds it for the wedge; the squeeze content is rho/c)."""
    left = 0.5 * (xi[i - 1] + xi[i])
    right = 0.5 * (xi[i] + xi[i + 1])
    poiseuille = (left * (P[i - 1] - P[i]) + right * (P[i + 1] - P[i])) / (h * h)
    wedge = 0.0
    if w0 != 0.0:
        wedge += w0 * rho[i] * H[i]
    if w1 != 0.0:
        wedge += w1 * rho[m1] * H[m1]
    if w2 != 0.0:
        wedge += w2 * rho[m2] * H[m2]
    return poiseuille - abs(s) * wedge / h - c_t * rho[i] / couette_i * H[i]


@register_jitable
def reynolds_residual(P, H, theta, phi, h, lam, viscosity_code, density_code, params, s, c_t, out):
    """out_i = L_i(P, H, theta) at interior nodes (flow factors phi); boundary entries 0."""
    n = P.shape[0]
    rho = np.empty(n)
    xi = np.empty(n)
    nodal_coefficients(P, H, theta, phi, lam, viscosity_code, density_code, params, rho, xi)
    out[0] = 0.0
    out[n - 1] = 0.0
    for i in range(1, n - 1):
        out[i] = operator_at(i, P, H, rho, theta, xi, h, s, c_t, phi[i, 2])


@helper
def refresh_coefficients(m, i, change, new, P, H, theta, phi, lam, viscosity_code, density_code, params, K, rho, xi,
                         dlx):
    """rho and xi of node m after the Gauss–Seidel change ``change`` of node i to ``new`` (its film already
    updated): xi scaled by (H_new/H_old)^3 exp(d ln xi/dP dP) for a small change of a wet node, else from the laws
    (see :func:`relax_hybrid`)."""
    r_m = density_ratio(P[m], density_code, params)
    rho[m] = r_m * theta[m] * phi[m, 2]
    hm = max(H[m], 0.0)
    before = H[m] + (1.0 / math.pi) * K[abs(m - i)] * change
    step = dlx[m] * change if m == i else 0.0
    if P[m] > 0.0 and before > 0.0 and (m != i or new > change) and abs(step) < 0.03:
        ratio = hm / before  # a small change of a wet node: xi scaled
        xi[m] *= ratio * ratio * ratio * math.exp(step)
    else:
        log_eta = log_viscosity(P[m], viscosity_code, params)
        xi[m] = flow_factor(phi, m, log_eta)[0] * r_m * hm * hm * hm * math.exp(-log_eta) / lam


@register_jitable
def relax_hybrid(P, H, theta, phi, f, h, lam, viscosity_code, density_code, params, K, omega_gs, omega_jacobi, switch,
                 window, first, last, dry, s, c_t, update_theta, supply):
    """One hybrid Gauss–Seidel / Jacobi-distributive sweep for L(P, theta) = f, in place on P and H
    (and theta with ``update_theta``).

    The regime of each node is fixed from the state at the start of the sweep: Gauss–Seidel
    where (xi_{i-1/2} + xi_{i+1/2})/h^2 >= switch * |d (wedge_i + squeeze_i) / d P_i| through the
    films, i.e. |(|s| sum_k w_k rho_m K(|m - i|)/h + c_t rho_i K(0)) / pi| (the equation is
    differential there), Jacobi-distributive elsewhere (integral character; Venner 1991,
    Tsuha 2015 Eqs. 5.54–5.59). With r_i = f_i - L_i and the exact local derivatives
    d_i = dL_i/dP_i, o_i = dL_i/dP_{i-1} (:func:`local_derivatives`):

    * Gauss–Seidel: P_i += omega_gs r_i / d_i at once (clipped at 0); the film of the node
      and of its ``window`` neighbours is updated through K, xi of i-1..i+1 (within the window) updated: scaled
      by (H_new/H_old)^3 exp(d ln xi/dP dP) (the pressure factor at the changed node only), the first-order
      change of its laws, and evaluated from the laws where that step |d ln xi/dP dP| exceeds 0.03, where the
      node wets or dries or where the gap was closed. Only the sweep's next nodes see the scaled values; the next
      sweep and every residual evaluate the laws (the converged solution is the same; measured: the sweep 135 ->
      83 ns per node at 28,673 nodes, level 12 0.36 -> 0.31 s, the same cycles over the LS-1 cam; with a
      threshold of 0.1 M = 3000, L = 25 on level 9 needed the second attempt); with the default ``window`` 0 the
      node's own update is straight-line code (:func:`refresh_coefficients`; 119 -> 89 ns per node at 28,673
      nodes, bitwise the same sweep);
    * Jacobi-distributive: delta_i = r_i / (d_i - o_i) applied after the sweep as
      +omega_jacobi delta_i at i and -omega_jacobi delta_i at i-1; the first node of a
      distributive region (left neighbour Gauss–Seidel) takes delta_i = r_i / d_i at i only.

    Negative pressures are set to zero (cavitation). K holds K(d) for d = 0..window+3.
    Only nodes first..last (clipped to the interior) are relaxed; nodes with ``dry`` set are
    held at P = 0 (a frozen cavitation set). Returns the number of distributive nodes.

    Mass-conserving cavitation (``update_theta``; Elrod 1981's switch between the pressure and the
    film fraction as the unknown, in the complementarity form of Giacopini et al. 2010): the
    upstream boundary node first takes the film fraction of the supply, theta = min(1, supply / H)
    (``supply`` the inlet layer's content h_oil R/b^2; infinite: flooded). Every node with P = 0 is
    relaxed point-wise (whatever its regime): L_i = f_i is solved for its content q_i = theta_i H_i
    (rho = 1 at P = 0), the other nodes as they are: theta_i = (L_i(q_i = 0) - f_i)/(c H_i),
    c = dL_i/dq_i = |s| w_0/h + c_t.
    theta_i < 1 keeps the node cavitated with that film fraction (clipped at 0); otherwise theta_i = 1
    and the node takes pressure by the Gauss–Seidel step. Nodes pressurised after the sweep have
    theta = 1. Frozen ``dry`` nodes keep P = 0 and take the film fraction (clipped at 1). The sweep runs
    from ``first`` to ``last`` whatever the sign of s, so the content marches downstream in one sweep
    only for s > 0. Without ``update_theta``, theta is a given coefficient.
    """
    n = P.shape[0]
    if update_theta and s != 0.0:
        b = 0 if s > 0.0 else n - 1
        theta[b] = 1.0 if not (H[b] > supply) else supply / H[b]
    rho = np.empty(n)
    xi = np.empty(n)
    dlx = np.empty(n)
    drh = np.empty(n)
    nodal_laws(P, H, theta, phi, lam, viscosity_code, density_code, params, rho, xi, dlx, drh)
    delta = np.zeros(n)
    jacobi = np.zeros(n, dtype=np.bool_)
    count = 0
    inv_pi = 1.0 / math.pi
    first = max(first, 1)
    last = min(last, n - 2)
    # the regime of every node is decided from the state at the start of the sweep
    for i in range(1, n - 1):
        coefficient = 0.5 * (xi[i - 1] + 2.0 * xi[i] + xi[i + 1]) / (h * h)
        d_integral = c_t * rho[i] / phi[i, 2] * K[0]
        w0, w1, w2, m1, m2 = wedge_stencil(i, n, s, P, theta)
        if w0 != 0.0:
            d_integral += abs(s) * w0 * rho[i] * K[0] / h
        if w1 != 0.0:
            d_integral += abs(s) * w1 * rho[m1] * K[abs(m1 - i)] / h
        if w2 != 0.0:
            d_integral += abs(s) * w2 * rho[m2] * K[abs(m2 - i)] / h
        jacobi[i] = coefficient < switch * abs(inv_pi * d_integral)
        if update_theta and P[i] <= 0.0:  # cavitated nodes solve for their film fraction (below)
            jacobi[i] = False
    for i in range(first, last + 1):
        if dry[i] and not update_theta:
            continue
        if update_theta and P[i] <= 0.0:  # a cavitated node: its film fraction first
            rho[i] = 0.0  # its own content out of L_i (the weights do not depend on it, see wedge_weight)
            weight, _ = wedge_weight(i, 0, n, s, P, theta)
            own = abs(s) * weight / h * phi[i, 2] + c_t
            if own > 0.0 and H[i] > 0.0:
                rest = operator_at(i, P, H, rho, theta, xi, h, s, c_t, phi[i, 2])  # L_i without its own content
                fraction = (rest - f[i]) / (own * H[i])
                if fraction < 1.0 or dry[i]:
                    theta[i] = min(max(fraction, 0.0), 1.0)
                    rho[i] = theta[i] * phi[i, 2]
                    continue
            theta[i] = 1.0
            rho[i] = phi[i, 2]
            if dry[i]:
                continue
        w0, w1, w2, m1, m2 = wedge_stencil(i, n, s, P, theta)
        r = f[i] - operator_with(i, P, H, rho, xi, h, s, c_t, phi[i, 2], w0, w1, w2, m1, m2)
        diagonal, off_diagonal = derivatives_with(i, P, H, rho, xi, dlx, drh, h, K, s, c_t, phi[i, 2], w0, w1, w2,
                                                  m1, m2)
        if not jacobi[i]:
            if diagonal == 0.0:
                continue
            new = P[i] + omega_gs * r / diagonal
            if new < 0.0:
                new = 0.0
            change = new - P[i]
            if change != 0.0:
                P[i] = new
                if window == 0:  # the default: the film and coefficients of node i only (straight-line code)
                    H[i] -= inv_pi * K[0] * change
                    refresh_coefficients(i, i, change, new, P, H, theta, phi, lam, viscosity_code, density_code,
                                         params, K, rho, xi, dlx)
                    continue
                low = max(i - window, 0)
                high = min(i + window, n - 1)
                for m in range(low, high + 1):
                    H[m] -= inv_pi * K[abs(m - i)] * change
                for m in range(max(low, i - 1), min(high, i + 1) + 1):
                    refresh_coefficients(m, i, change, new, P, H, theta, phi, lam, viscosity_code, density_code,
                                         params, K, rho, xi, dlx)
        elif jacobi[i - 1]:
            dipole = diagonal - off_diagonal
            if dipole != 0.0:
                delta[i] = r / dipole
            count += 1
        else:  # first node of a Jacobi region: its left neighbour is relaxed by Gauss-Seidel
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
        elif update_theta and P[i] > 0.0:
            theta[i] = 1.0
    return count


# ----------------------------------------------------------------------------- registry of kernels
PY = {
    "nodal_coefficients": nodal_coefficients,
    "reynolds_residual": reynolds_residual,
    "relax_hybrid": relax_hybrid,
    "deformation_direct": deformation_direct,
    "mlmi_anterpolate": mlmi_anterpolate,
    "mlmi_direct": mlmi_direct,
    "mlmi_correction_tables": mlmi_correction_tables,
    "mlmi_interpolate_correct": mlmi_interpolate_correct,
    "mlmi_apply": mlmi_apply,
}


def compiled(name: str, table: dict | None = None):
    """The compiled twin of kernel ``name`` of ``table`` (default :data:`PY`); see :mod:`camcontact.jit`."""
    return compile_kernel((PY if table is None else table)[name])
