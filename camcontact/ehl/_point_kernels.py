"""Numba kernels of the point-contact EHL solver, each with its plain-Python twin.

As in :mod:`camcontact.ehl._kernels`, every kernel is plain Python on float64 arrays (the
*twin*, used by the tests on small grids); :func:`compiled` returns its
``numba.njit(cache=True, nogil=True)`` version (:func:`camcontact.jit.compile_kernel`).
The lubricant laws (:func:`._kernels.law_state`) are shared with the line-contact kernels.

Fields are 2-D arrays indexed ``[j, i]`` = (Y_j, X_i); X is the entrainment direction. The
discrete operator at an interior node (Venner & Lubrecht 2000, ch. 8):

.. math::
    L_{ij} = \\frac{\\varepsilon_{i-1/2}(P_{i-1} - P_i) + \\varepsilon_{i+1/2}(P_{i+1} - P_i)}{h_x^2}
           + \\frac{\\varepsilon_{j-1/2}(P_{j-1} - P_j) + \\varepsilon_{j+1/2}(P_{j+1} - P_j)}{h_y^2}
           - \\frac{1.5\\,\\bar\\rho_i H_i - 2\\,\\bar\\rho_{i-1} H_{i-1} + 0.5\\,\\bar\\rho_{i-2} H_{i-2}}{h_x}

(epsilon at half points as the mean of the nodes; first-order upwind wedge at i = 1).
Importing this module imports numba but compiles nothing.
"""

from __future__ import annotations

import math

import numpy as np
from numba.extending import register_jitable

from ._kernels import law_state, log_viscosity
from ..jit import compile_kernel, helper

__all__ = ["PY", "band_solve", "compiled", "deformation_direct_2d", "kernel_rectangle"]

#: stencil nodes (dj, di) of L_ij: the node, its four neighbours and the second upwind node
STENCIL_DJ = (0, 0, 0, -1, 1, 0)
STENCIL_DI = (0, -1, 1, 0, 0, -2)


# ----------------------------------------------------------------------------- deformation
@helper
def _love(u, v):
    """f(u, v) = u asinh(v/|u|) + v asinh(u/|v|): d^2 f/du dv = 1/sqrt(u^2 + v^2), f = 0 on the axes.

    (u ln(v + r) + v ln(u + r) less terms in u or v alone, which cancel in the rectangle sum.)"""
    value = 0.0
    if u != 0.0:
        value += u * math.asinh(v / abs(u))
    if v != 0.0:
        value += v * math.asinh(u / abs(v))
    return value


@helper
def kernel_rectangle(x, y, hx, hy):
    """int int 1/sqrt((x - s)^2 + (y - t)^2) ds dt over the cell |s| <= hx/2, |t| <= hy/2 (Love 1929)."""
    a = 0.5 * hx
    b = 0.5 * hy
    return _love(x + a, y + b) - _love(x - a, y + b) - _love(x + a, y - b) + _love(x - a, y - b)


def deformation_direct_2d(P, hx, hy):
    """w_ij = (2/pi^2) sum_kl K(i - k, j - l) P_kl, O(n^4) (the reference for the FFT sum; small grids)."""
    ny, nx = P.shape
    table = np.empty((ny, nx))
    for dj in range(ny):
        for di in range(nx):
            table[dj, di] = kernel_rectangle(di * hx, dj * hy, hx, hy) * 2.0 / (math.pi * math.pi)
    w = np.zeros((ny, nx))
    for l in range(ny):
        for k in range(nx):
            p = P[l, k]
            if p == 0.0:
                continue
            for j in range(ny):
                for i in range(nx):
                    w[j, i] += table[abs(j - l), abs(i - k)] * p
    return w


# ----------------------------------------------------------------------------- operator
@helper
def point_nodal(P, H, lam, viscosity_code, density_code, params, rho, eps, dle, drh):
    """rho, epsilon = rho H^3/(eta lambda), d ln(epsilon)/dP (at fixed H) and d rho/dP at every node."""
    ny, nx = P.shape
    for j in range(ny):
        for i in range(nx):
            point_nodal_at(j, i, P, H, lam, viscosity_code, density_code, params, rho, eps, dle, drh)


@register_jitable
def pattern_work():
    """Work arrays of :func:`pattern_derivative`: pattern offsets (dj, di), weights (5 entries) and
    the changes of P, epsilon and rho H at the six stencil nodes."""
    return (np.zeros(5, dtype=np.int64), np.zeros(5, dtype=np.int64), np.zeros(5), np.zeros(6), np.zeros(6),
            np.zeros(6))


@register_jitable
def nodal_arrays(P, H, lam, viscosity_code, density_code, params):
    """(rho, epsilon, d ln epsilon/dP, d rho/dP) as new arrays (:func:`point_nodal`)."""
    ny, nx = P.shape
    rho = np.empty((ny, nx))
    eps = np.empty((ny, nx))
    dle = np.empty((ny, nx))
    drh = np.empty((ny, nx))
    point_nodal(P, H, lam, viscosity_code, density_code, params, rho, eps, dle, drh)
    return rho, eps, dle, drh


@helper
def point_nodal_at(j, i, P, H, lam, viscosity_code, density_code, params, rho, eps, dle, drh):
    p = P[j, i]
    gap = max(H[j, i], 0.0)  # a closed gap passes no pressure flow
    if p <= 0.0:
        rho[j, i] = 1.0
        eps[j, i] = gap * gap * gap / lam
        dle[j, i] = 0.0
        drh[j, i] = 0.0
        return
    r, d_r, log_eta, dlog_eta = law_state(p, viscosity_code, density_code, params)
    rho[j, i] = r
    eps[j, i] = r * gap * gap * gap * math.exp(-log_eta) / lam
    dle[j, i] = d_r / r - dlog_eta
    drh[j, i] = d_r


@helper
def point_operator_at(j, i, P, H, rho, eps, hx, hy):
    """L_ij (module docstring) at an interior node."""
    e = eps[j, i]
    p = P[j, i]
    poiseuille = ((0.5 * (eps[j, i - 1] + e)) * (P[j, i - 1] - p) + (0.5 * (eps[j, i + 1] + e)) * (P[j, i + 1] - p)) / (hx * hx)
    poiseuille += ((0.5 * (eps[j - 1, i] + e)) * (P[j - 1, i] - p) + (0.5 * (eps[j + 1, i] + e)) * (P[j + 1, i] - p)) / (hy * hy)
    if i == 1:
        wedge = rho[j, 1] * H[j, 1] - rho[j, 0] * H[j, 0]
    else:
        wedge = 1.5 * rho[j, i] * H[j, i] - 2.0 * rho[j, i - 1] * H[j, i - 1] + 0.5 * rho[j, i - 2] * H[j, i - 2]
    return poiseuille - wedge / hx


def point_residual(P, H, hx, hy, lam, viscosity_code, density_code, params, out):
    """out = L(P, H) at interior nodes, 0 on the boundary."""
    ny, nx = P.shape
    rho, eps, dle, drh = nodal_arrays(P, H, lam, viscosity_code, density_code, params)
    for j in range(ny):
        for i in range(nx):
            if j == 0 or i == 0 or j == ny - 1 or i == nx - 1:
                out[j, i] = 0.0
            else:
                out[j, i] = point_operator_at(j, i, P, H, rho, eps, hx, hy)


@helper
def pattern_derivative(j, i, P, H, rho, eps, dle, drh, hx, hy, Kd, pdj, pdi, pw, npat, dP, dE, dRH):
    """dL_ij/dt for the pressure change t * pw[q] at the nodes (j + pdj[q], i + pdi[q]), q < npat.

    Linearises L_ij exactly in the local terms: the Poiseuille coefficients and the pressure
    differences, epsilon's dependence on P (viscosity, density) and on the films, and the wedge's
    dependence on rho(P) and on the films; the films of the stencil nodes change through the local
    deformation coefficients ``Kd[|dj|, |di|]`` (= dH/dP between nodes that far apart).
    ``dP``, ``dE``, ``dRH`` (length 6) are work arrays: the changes of P, epsilon and rho H at the
    stencil nodes.
    """
    for s in range(6):
        dP[s] = 0.0
        dE[s] = 0.0
        dRH[s] = 0.0
    count = 5 if i == 1 else 6
    for s in range(count):
        sj = STENCIL_DJ[s]
        si = STENCIL_DI[s]
        dp = 0.0
        dh = 0.0
        for q in range(npat):
            dj = sj - pdj[q]
            di = si - pdi[q]
            if dj == 0 and di == 0:
                dp += pw[q]
            dh += pw[q] * Kd[abs(dj), abs(di)]
        m_j = j + sj
        m_i = i + si
        e = eps[m_j, m_i]
        h = H[m_j, m_i]
        dP[s] = dp
        dE[s] = e * dle[m_j, m_i] * dp + (3.0 * e / h * dh if h > 0.0 else 0.0)
        dRH[s] = drh[m_j, m_i] * dp * h + rho[m_j, m_i] * dh
    e0 = eps[j, i]
    p0 = P[j, i]
    result = 0.0
    # Poiseuille: faces towards stencil nodes 1..4
    for s in range(1, 5):
        sj = STENCIL_DJ[s]
        si = STENCIL_DI[s]
        scale = 1.0 / (hx * hx) if sj == 0 else 1.0 / (hy * hy)
        face = 0.5 * (eps[j + sj, i + si] + e0)
        d_face = 0.5 * (dE[s] + dE[0])
        result += scale * (d_face * (P[j + sj, i + si] - p0) + face * (dP[s] - dP[0]))
    if i == 1:
        wedge = dRH[0] - dRH[1]
    else:
        wedge = 1.5 * dRH[0] - 2.0 * dRH[1] + 0.5 * dRH[5]
    return result - wedge / hx


@helper
def choose_regimes(rho, eps, hx, hy, Kd, switch, jacobi):
    """jacobi[j, i] = True where the node relaxes distributively: the Poiseuille coefficient
    sum(epsilon faces)/h^2 is below ``switch`` x the wedge's own response 1.5 rho K_00 / h_x
    (integral character); Gauss–Seidel (False) elsewhere (Venner & Lubrecht 2000 §8.4)."""
    ny, nx = eps.shape
    for j in range(1, ny - 1):
        for i in range(1, nx - 1):
            coefficient = (0.5 * (eps[j, i - 1] + 2.0 * eps[j, i] + eps[j, i + 1]) / (hx * hx)
                           + 0.5 * (eps[j - 1, i] + 2.0 * eps[j, i] + eps[j + 1, i]) / (hy * hy))
            if i == 1:
                d_wedge = rho[j, 1] * Kd[0, 0] - rho[j, 0] * Kd[0, 1]
            else:
                d_wedge = 1.5 * rho[j, i] * Kd[0, 0] - 2.0 * rho[j, i - 1] * Kd[0, 1] + 0.5 * rho[j, i - 2] * Kd[0, 2]
            jacobi[j, i] = coefficient < switch * abs(d_wedge / hx)


@helper
def distributive_pattern(j, k, offset, jacobi, pdj, pdi, pw, start):
    """Write the change pattern of node (j, k) at entries start.. of (pdj, pdi, pw), offsets
    relative to column k - ``offset``: +1 at the node and, if it relaxes distributively, -1/4 at
    each of its four interior neighbours that do too. Returns the next free entry."""
    ny, nx = jacobi.shape
    pdj[start] = 0
    pdi[start] = offset
    pw[start] = 1.0
    npat = start + 1
    if jacobi[j, k]:
        for q in range(4):
            dj = STENCIL_DJ[q + 1]
            di = STENCIL_DI[q + 1]
            if 0 < j + dj < ny - 1 and 0 < k + di < nx - 1 and jacobi[j + dj, k + di]:
                pdj[npat] = dj
                pdi[npat] = offset + di
                pw[npat] = -0.25
                npat += 1
    return npat


@helper
def apply_distributive(P, delta, jacobi, omega_jacobi, dry):
    """P += omega delta at each distributive node and -omega delta/4 at its distributive interior
    neighbours; then P <- 0 where negative (cavitation), dry or on the boundary."""
    ny, nx = P.shape
    for j in range(1, ny - 1):
        for i in range(1, nx - 1):
            value = delta[j, i]
            if value == 0.0:
                continue
            P[j, i] += omega_jacobi * value
            for q in range(4):
                dj = STENCIL_DJ[q + 1]
                di = STENCIL_DI[q + 1]
                if 0 < j + dj < ny - 1 and 0 < i + di < nx - 1 and jacobi[j + dj, i + di]:
                    P[j + dj, i + di] -= 0.25 * omega_jacobi * value
    for j in range(ny):
        for i in range(nx):
            if P[j, i] < 0.0 or dry[j, i] or j == 0 or i == 0 or j == ny - 1 or i == nx - 1:
                P[j, i] = 0.0


@helper
def gauss_seidel_at(j, i, r, P, H, rho, eps, dle, drh, hx, hy, lam, viscosity_code, density_code, params, Kd,
                    omega_gs, pdj, pdi, pw, work_p, work_e, work_rh):
    """Point Gauss–Seidel at (j, i) with residual r: P += omega_gs r / (dL/dP), clipped at 0; the
    node's own film follows through K_00 and its epsilon and rho are recomputed. Skips a node whose
    derivative is not negative. (pdj, pdi, pw: pattern work arrays, entry 0 is used.)"""
    pdj[0] = 0
    pdi[0] = 0
    pw[0] = 1.0
    d = pattern_derivative(j, i, P, H, rho, eps, dle, drh, hx, hy, Kd, pdj, pdi, pw, 1, work_p, work_e, work_rh)
    if not d < 0.0:
        return
    new = P[j, i] + omega_gs * r / d
    if new < 0.0:
        new = 0.0
    change = new - P[j, i]
    if change != 0.0:
        P[j, i] = new
        H[j, i] += Kd[0, 0] * change
        point_nodal_at(j, i, P, H, lam, viscosity_code, density_code, params, rho, eps, dle, drh)


def point_relax(P, H, f, hx, hy, lam, viscosity_code, density_code, params, Kd, omega_gs, omega_jacobi, switch,
                dry):
    """One hybrid Gauss–Seidel / Jacobi-distributive point sweep for L(P) = f, in place on P and H.

    The regime of each node is fixed from the state at the start of the sweep (Venner &
    Lubrecht 2000 §8.4, here point-wise): Gauss–Seidel where the Poiseuille coefficient
    sum(epsilon faces)/h^2 >= ``switch`` x the wedge's own response (1.5 rho K_00 / h_x; the
    equation is differential there), Jacobi-distributive elsewhere (integral character). Rows
    are swept in +Y, nodes in +X (the entrainment direction). With r = f - L and the exact local
    derivatives of :func:`pattern_derivative`:

    * Gauss–Seidel: P_ij += omega_gs r / (dL_ij/dP_ij) at once, clipped at 0; the node's own
      film follows through K_00, its epsilon and rho are recomputed;
    * Jacobi-distributive: delta_ij = r / (dL_ij/d pattern) with the pattern +1 at the node and
      -1/4 at each of its distributive interior neighbours (so the change is mostly invisible to
      the far field of the deformation integral); applied after the sweep as +omega_jacobi delta
      at the node and -omega_jacobi delta/4 at those neighbours.

    A derivative that is not negative (the operator is monotone decreasing in P_ij) skips the
    node. Negative pressures are set to 0 (cavitation) and nodes flagged ``dry`` are held at 0.
    Returns the number of distributive nodes.
    """
    ny, nx = P.shape
    rho, eps, dle, drh = nodal_arrays(P, H, lam, viscosity_code, density_code, params)
    jacobi = np.zeros((ny, nx), dtype=np.bool_)
    delta = np.zeros((ny, nx))
    pdj, pdi, pw, work_p, work_e, work_rh = pattern_work()
    count = 0
    choose_regimes(rho, eps, hx, hy, Kd, switch, jacobi)
    for j in range(1, ny - 1):
        for i in range(1, nx - 1):
            if dry[j, i]:
                continue
            r = f[j, i] - point_operator_at(j, i, P, H, rho, eps, hx, hy)
            if not jacobi[j, i]:
                gauss_seidel_at(j, i, r, P, H, rho, eps, dle, drh, hx, hy, lam, viscosity_code, density_code, params,
                                Kd, omega_gs, pdj, pdi, pw, work_p, work_e, work_rh)
            else:
                npat = distributive_pattern(j, i, 0, jacobi, pdj, pdi, pw, 0)
                d = pattern_derivative(j, i, P, H, rho, eps, dle, drh, hx, hy, Kd, pdj, pdi, pw, npat, work_p, work_e, work_rh)
                if d < 0.0:
                    delta[j, i] = r / d
                count += 1
    apply_distributive(P, delta, jacobi, omega_jacobi, dry)
    return count


@helper
def band_solve(A, rhs, m, bw, x):
    """Solve the banded system sum_c A[q, bw + c - q] x_c = rhs_q, q < m, half-bandwidth ``bw``, by
    Gaussian elimination without pivoting (A and rhs are overwritten). The line matrices of the
    relaxation have negative dominant diagonals; returns False (x untouched) at the first pivot
    that is not negative, so the caller can fall back."""
    for q in range(m):
        pivot = A[q, bw]
        if not pivot < 0.0:
            return False
        for r in range(q + 1, min(q + bw + 1, m)):
            factor = A[r, bw + q - r] / pivot
            if factor == 0.0:
                continue
            for c in range(q, min(q + bw + 1, m)):
                A[r, bw + c - r] -= factor * A[q, bw + c - q]
            rhs[r] -= factor * rhs[q]
    for q in range(m - 1, -1, -1):
        s = rhs[q]
        for c in range(q + 1, min(q + bw + 1, m)):
            s -= A[q, bw + c - q] * x[c]
        x[q] = s / A[q, bw]
    return True


@helper
def face_sensitivities(P, H, eps, dle, nj, ni, p0, e0, scale):
    """One Poiseuille face of L (scale 1/h^2) towards node (nj, ni): (dL/dP_n, dL/dH_n, dL/d epsilon at
    either end, the face coefficient) for :func:`node_sensitivities`."""
    e = eps[nj, ni]
    h = H[nj, ni]
    half = 0.5 * scale * (P[nj, ni] - p0)
    face = 0.5 * (e + e0) * scale
    return half * e * dle[nj, ni] + face, (half * 3.0 * e / h if h > 0.0 else 0.0), half, face


@helper
def node_sensitivities(j, i, P, H, rho, eps, dle, drh, hx, hy, a, b):
    """The local derivatives of L_ij (module docstring) at an interior node: ``a[s]`` = dL_ij/dP and
    ``b[s]`` = dL_ij/dH at stencil node s (:data:`STENCIL_DJ`, :data:`STENCIL_DI`), each at fixed
    other values. epsilon = rho H^3/(eta lambda) moves with P through d ln(epsilon)/dP (``dle``) and
    with H as 3 epsilon/H (0 for a closed gap); the wedge's rho H with P through d rho/dP (``drh``).
    At i = 1 the wedge is first-order upwind and the sixth node (i - 2) does not exist (a[5] = b[5] = 0).
    """
    e0 = eps[j, i]
    p0 = P[j, i]
    sx = 1.0 / (hx * hx)
    sy = 1.0 / (hy * hy)
    a[1], b[1], half1, face1 = face_sensitivities(P, H, eps, dle, j, i - 1, p0, e0, sx)
    a[2], b[2], half2, face2 = face_sensitivities(P, H, eps, dle, j, i + 1, p0, e0, sx)
    a[3], b[3], half3, face3 = face_sensitivities(P, H, eps, dle, j - 1, i, p0, e0, sy)
    a[4], b[4], half4, face4 = face_sensitivities(P, H, eps, dle, j + 1, i, p0, e0, sy)
    gap0 = half1 + half2 + half3 + half4  # d L/d epsilon_0
    a0 = gap0 * e0 * dle[j, i] - (face1 + face2 + face3 + face4)
    h0 = H[j, i]
    b0 = gap0 * 3.0 * e0 / h0 if h0 > 0.0 else 0.0
    if i == 1:
        a[0] = a0 - drh[j, 1] * h0 / hx
        b[0] = b0 - rho[j, 1] / hx
        a[1] += drh[j, 0] * H[j, 0] / hx
        b[1] += rho[j, 0] / hx
        a[5] = 0.0
        b[5] = 0.0
    else:
        a[0] = a0 - 1.5 * drh[j, i] * h0 / hx
        b[0] = b0 - 1.5 * rho[j, i] / hx
        a[1] += 2.0 * drh[j, i - 1] * H[j, i - 1] / hx
        b[1] += 2.0 * rho[j, i - 1] / hx
        a[5] = -0.5 * drh[j, i - 2] * H[j, i - 2] / hx
        b[5] = -0.5 * rho[j, i - 2] / hx


@register_jitable
def stencil_kernel_table(Kd, bw):
    """KS[dj + 1, di + bw + 1, s] = Kd[|s_j - dj|, |s_i - di|]: the film change at stencil node s per
    unit pressure change at (dj, di), |dj| <= 1, |di| <= bw + 1 (for :func:`response_table`)."""
    KS = np.empty((3, 2 * bw + 3, 6))
    for row in range(3):
        for column in range(2 * bw + 3):
            for s in range(6):
                KS[row, column, s] = Kd[abs(STENCIL_DJ[s] - row + 1), abs(STENCIL_DI[s] - column + bw + 1)]
    return KS


@helper
def response_table(a, b, KS, bw, G, full):
    """G[dj + 1, di + bw + 1] = dL_ij/dP at node (j + dj, i + di), from the sensitivities of
    :func:`node_sensitivities`: the films' response sum_s b[s] KS[dj + 1, di + bw + 1, s]
    (:func:`stencil_kernel_table`) plus the direct a[s] where that node is stencil node s. ``full``:
    |dj| <= 1, |di| <= bw + 1 (every pattern of a line system's column reaches only these nodes);
    otherwise only dj = 0, |di| <= bw (enough when no column of the row relaxes distributively)."""
    rows = range(3) if full else range(1, 2)
    last = 2 * bw + 3 if full else 2 * bw + 2
    first = 0 if full else 1
    for row in rows:
        for column in range(first, last):
            value = 0.0
            for s in range(6):
                value += b[s] * KS[row, column, s]
            G[row, column] = value
    G[1, bw + 1] += a[0]
    G[1, bw] += a[1]
    G[1, bw + 2] += a[2]
    if full:
        G[0, bw + 1] += a[3]
        G[2, bw + 1] += a[4]
    G[1, bw - 1] += a[5]


@helper
def pattern_response(G, bw, offset, j, k, jacobi):
    """dL/dt of the row's node for the change pattern of node (j, k) (:func:`distributive_pattern`),
    k = i + ``offset``, from the response table G of :func:`response_table`."""
    ny, nx = jacobi.shape
    value = G[1, offset + bw + 1]
    if jacobi[j, k]:
        for q in range(4):
            dj = STENCIL_DJ[q + 1]
            di = STENCIL_DI[q + 1]
            if 0 < j + dj < ny - 1 and 0 < k + di < nx - 1 and jacobi[j + dj, k + di]:
                value -= 0.25 * G[1 + dj, offset + di + bw + 1]
    return value


def point_line_relax(P, H, f, hx, hy, lam, viscosity_code, density_code, params, Kd, omega_gs, omega_jacobi,
                     switch, dry, bw, step_limit):
    """One sweep of line relaxation along X (the entrainment direction) for L(P) = f, in place on P and H.

    Venner & Lubrecht (2000, §8.4) relax point contacts line by line: all nodes of a row Y_j
    change together, by the solution of a banded system, so that the strong coupling along X
    through the film (the wedge and the deformation) is taken implicitly — the point-wise sweep
    (:func:`point_relax`) converges slowly at heavy load because of it. Regimes as in
    :func:`point_relax` (:func:`choose_regimes`, fixed at the start of the sweep). For row j the
    unknowns are the changes delta_k of its interior nodes, each with its pattern
    (:func:`distributive_pattern`: +1 at a Gauss–Seidel node; +1 at the node and -1/4 at its
    distributive neighbours for a distributive one). Row i of the system is

        sum_k dL_ji/d(pattern of k) delta_k = f_ji - L_ji,   |k - i| <= bw,

    the exact local linearisation (film changes through the deformation coefficients Kd, which must
    reach |di| <= bw + 3 and |dj| <= 2), assembled per node from dL/dP and dL/dH at its six stencil
    nodes (:func:`node_sensitivities`, :func:`response_table`, :func:`pattern_response`; the same
    derivatives as :func:`pattern_derivative` column by column, at a fraction of the cost). Nodes that are
    dry, or cavitated (P = 0) and pushed further down (f - L > 0), or whose own derivative is
    not negative, are held (delta = 0). The system is solved by :func:`band_solve`; if a pivot
    fails the row falls back to the point-wise changes r/A_ii. Gauss–Seidel nodes take
    P += omega_gs delta at once (clipped at 0), their change limited to |d ln(epsilon)/dP| |dP| <=
    ``step_limit`` (a trust region: the linearisation of the exponential viscosity fails for larger
    steps; at the outlet pressure spike of Barus M = 20, L = 10 on 513^2 unlimited steps make
    the coarse problems blow up, a limit of 2, a factor e^2 in epsilon per sweep, converges in two
    cycles), and the films of rows j..j+2 follow through Kd;
    distributive changes are applied after the sweep with omega_jacobi
    (:func:`apply_distributive`). Returns the number of distributive nodes.
    """
    ny, nx = P.shape
    rho, eps, dle, drh = nodal_arrays(P, H, lam, viscosity_code, density_code, params)
    jacobi = np.zeros((ny, nx), dtype=np.bool_)
    choose_regimes(rho, eps, hx, hy, Kd, switch, jacobi)
    delta = np.zeros((ny, nx))
    m = nx - 2
    width = 2 * bw + 1
    A = np.zeros((m, width))
    rhs = np.zeros(m)
    x = np.zeros(m)
    diag = np.zeros(m)
    residual = np.zeros(m)
    active = np.zeros(m, dtype=np.bool_)
    change = np.zeros(nx)
    a = np.zeros(6)
    b = np.zeros(6)
    G = np.zeros((3, 2 * bw + 3))
    KS = stencil_kernel_table(Kd, bw)
    reach = Kd.shape[1]
    count = 0
    for j in range(1, ny - 1):
        any_active = False
        for q in range(m):
            i = q + 1
            r = f[j, i] - point_operator_at(j, i, P, H, rho, eps, hx, hy)
            residual[q] = r
            active[q] = False
            if dry[j, i] or (P[j, i] <= 0.0 and r > 0.0):
                continue
            node_sensitivities(j, i, P, H, rho, eps, dle, drh, hx, hy, a, b)
            full = False
            for k in range(max(1, i - bw), min(nx - 1, i + bw + 1)):
                full = full or jacobi[j, k]
            response_table(a, b, KS, bw, G, full)
            d = pattern_response(G, bw, 0, j, i, jacobi) if full else G[1, bw + 1]
            if d < 0.0:
                active[q] = True
                diag[q] = d
                any_active = True
                for c in range(max(0, q - bw), min(m, q + bw + 1)):
                    if full:
                        A[q, bw + c - q] = pattern_response(G, bw, c - q, j, c + 1, jacobi)
                    else:  # no distributive column: the patterns are single nodes
                        A[q, bw + c - q] = G[1, c - q + bw + 1]
        if not any_active:
            continue
        for q in range(m):
            x[q] = 0.0
            if not active[q]:
                for c in range(width):
                    A[q, c] = 0.0
                A[q, bw] = -1.0
                rhs[q] = 0.0
                continue
            rhs[q] = residual[q]
            for c in range(width):
                column = q + c - bw
                if column < 0 or column >= m or not active[column]:
                    A[q, c] = 0.0
        if not band_solve(A, rhs, m, bw, x):
            for q in range(m):
                x[q] = residual[q] / diag[q] if active[q] else 0.0
        moved = False
        for q in range(m):
            i = q + 1
            change[i] = 0.0
            if not active[q]:
                continue
            if jacobi[j, i]:
                delta[j, i] = x[q]
                count += 1
                continue
            step = omega_gs * x[q]
            slope = abs(dle[j, i])
            if slope * abs(step) > step_limit:  # trust region of the exponential viscosity
                step = math.copysign(step_limit / slope, step)
            new = P[j, i] + step
            if new < 0.0:
                new = 0.0
            change[i] = new - P[j, i]
            if change[i] != 0.0:
                P[j, i] = new
                moved = True
        if not moved:
            continue
        first = nx
        last = 0
        for i in range(1, nx - 1):
            if change[i] != 0.0:
                first = min(first, i)
                last = i
        for jj in range(j, min(j + 3, ny)):
            dj = jj - j
            for i in range(max(0, first - reach + 1), min(nx, last + reach)):
                dh = 0.0
                for k in range(max(1, i - reach + 1), min(nx - 1, i + reach)):
                    if change[k] != 0.0:
                        dh += Kd[dj, abs(i - k)] * change[k]
                if dh == 0.0:
                    continue
                old = H[jj, i]
                H[jj, i] = old + dh
                if (jj == j and change[i] != 0.0) or old <= 0.0 or P[jj, i] <= 0.0:
                    point_nodal_at(jj, i, P, H, lam, viscosity_code, density_code, params, rho, eps, dle, drh)
                else:  # P unchanged: only the gap term of epsilon moves
                    ratio = max(H[jj, i], 0.0) / old
                    eps[jj, i] *= ratio * ratio * ratio
    apply_distributive(P, delta, jacobi, omega_jacobi, dry)
    return count


def spike_zone(P, viscosity_code, params, drop, mask):
    """mask[j, i] = True at the nodes i - 2 .. i + 2 of rows j - 1 .. j + 1 around every fall of ln(eta) by more
    than ``drop`` from node (j, i) to (j, i + 1): the outlet pressure spike, where the viscosity falls by orders
    of magnitude within a node (the multigrid cycle keeps the coarse grids out of it with
    ``PointMultigridSettings.spike_mask``; the line solver's twin is :func:`._fas_kernels.find_spikes`). False
    elsewhere."""
    ny, nx = P.shape
    for j in range(ny):
        for i in range(nx):
            mask[j, i] = False
    for j in range(ny):
        here = log_viscosity(P[j, 0], viscosity_code, params)
        for i in range(nx - 1):
            below = log_viscosity(P[j, i + 1], viscosity_code, params)
            if here - below > drop:
                for jj in range(max(j - 1, 0), min(j + 2, ny)):
                    for ii in range(max(i - 2, 0), min(i + 3, nx)):
                        mask[jj, ii] = True
            here = below


# ----------------------------------------------------------------------------- grid transfers
def restrict_full_weighting(r, out):
    """out (coarse, (n+1)/2 per direction) = 9-point full weighting of the fine residual r at interior
    coarse nodes (weights 1/4 centre, 1/8 edges, 1/16 corners); 0 on the coarse boundary."""
    ny, nx = out.shape
    for J in range(ny):
        for I in range(nx):
            if J == 0 or I == 0 or J == ny - 1 or I == nx - 1:
                out[J, I] = 0.0
                continue
            j = 2 * J
            i = 2 * I
            out[J, I] = (0.25 * r[j, i]
                         + 0.125 * (r[j, i - 1] + r[j, i + 1] + r[j - 1, i] + r[j + 1, i])
                         + 0.0625 * (r[j - 1, i - 1] + r[j - 1, i + 1] + r[j + 1, i - 1] + r[j + 1, i + 1]))


def prolong_bilinear(c, out):
    """out (fine, 2n - 1 per direction) = bilinear interpolation of the coarse field c."""
    ny, nx = out.shape
    for j in range(ny):
        J = j // 2
        for i in range(nx):
            I = i // 2
            if j % 2 == 0:
                if i % 2 == 0:
                    out[j, i] = c[J, I]
                else:
                    out[j, i] = 0.5 * (c[J, I] + c[J, I + 1])
            else:
                if i % 2 == 0:
                    out[j, i] = 0.5 * (c[J, I] + c[J + 1, I])
                else:
                    out[j, i] = 0.25 * (c[J, I] + c[J, I + 1] + c[J + 1, I] + c[J + 1, I + 1])


PY = {
    "point_residual": point_residual,
    "point_relax": point_relax,
    "point_line_relax": point_line_relax,
    "spike_zone": spike_zone,
    "band_solve": band_solve,
    "deformation_direct_2d": deformation_direct_2d,
    "restrict_full_weighting": restrict_full_weighting,
    "prolong_bilinear": prolong_bilinear,
}


def compiled(name: str):
    """The numba-compiled twin of kernel ``name`` of this module."""
    return compile_kernel(PY[name])
