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

from ._kernels import law_state
from ..jit import compile_kernel

__all__ = ["PY", "compiled", "deformation_direct_2d", "kernel_rectangle"]

#: stencil nodes (dj, di) of L_ij: the node, its four neighbours and the second upwind node
STENCIL_DJ = (0, 0, 0, -1, 1, 0)
STENCIL_DI = (0, -1, 1, 0, 0, -2)


# ----------------------------------------------------------------------------- deformation
@register_jitable
def _love(u, v):
    """f(u, v) = u asinh(v/|u|) + v asinh(u/|v|): d^2 f/du dv = 1/sqrt(u^2 + v^2), f = 0 on the axes.

    (u ln(v + r) + v ln(u + r) less terms in u or v alone, which cancel in the rectangle sum.)"""
    value = 0.0
    if u != 0.0:
        value += u * math.asinh(v / abs(u))
    if v != 0.0:
        value += v * math.asinh(u / abs(v))
    return value


@register_jitable
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
@register_jitable
def point_nodal(P, H, lam, viscosity_code, density_code, params, rho, eps, dle, drh):
    """rho, epsilon = rho H^3/(eta lambda), d ln(epsilon)/dP (at fixed H) and d rho/dP at every node."""
    ny, nx = P.shape
    for j in range(ny):
        for i in range(nx):
            point_nodal_at(j, i, P, H, lam, viscosity_code, density_code, params, rho, eps, dle, drh)


@register_jitable
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


@register_jitable
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
    rho = np.empty((ny, nx))
    eps = np.empty((ny, nx))
    dle = np.empty((ny, nx))
    drh = np.empty((ny, nx))
    point_nodal(P, H, lam, viscosity_code, density_code, params, rho, eps, dle, drh)
    for j in range(ny):
        for i in range(nx):
            if j == 0 or i == 0 or j == ny - 1 or i == nx - 1:
                out[j, i] = 0.0
            else:
                out[j, i] = point_operator_at(j, i, P, H, rho, eps, hx, hy)


@register_jitable
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
    rho = np.empty((ny, nx))
    eps = np.empty((ny, nx))
    dle = np.empty((ny, nx))
    drh = np.empty((ny, nx))
    point_nodal(P, H, lam, viscosity_code, density_code, params, rho, eps, dle, drh)
    jacobi = np.zeros((ny, nx), dtype=np.bool_)
    delta = np.zeros((ny, nx))
    pdj = np.zeros(5, dtype=np.int64)
    pdi = np.zeros(5, dtype=np.int64)
    pw = np.zeros(5)
    work_p = np.zeros(6)
    work_e = np.zeros(6)
    work_rh = np.zeros(6)
    count = 0
    for j in range(1, ny - 1):
        for i in range(1, nx - 1):
            coefficient = (0.5 * (eps[j, i - 1] + 2.0 * eps[j, i] + eps[j, i + 1]) / (hx * hx)
                           + 0.5 * (eps[j - 1, i] + 2.0 * eps[j, i] + eps[j + 1, i]) / (hy * hy))
            if i == 1:
                d_wedge = rho[j, 1] * Kd[0, 0] - rho[j, 0] * Kd[0, 1]
            else:
                d_wedge = 1.5 * rho[j, i] * Kd[0, 0] - 2.0 * rho[j, i - 1] * Kd[0, 1] + 0.5 * rho[j, i - 2] * Kd[0, 2]
            jacobi[j, i] = coefficient < switch * abs(d_wedge / hx)
    for j in range(1, ny - 1):
        for i in range(1, nx - 1):
            if dry[j, i]:
                continue
            r = f[j, i] - point_operator_at(j, i, P, H, rho, eps, hx, hy)
            pw[0] = 1.0
            if not jacobi[j, i]:
                d = pattern_derivative(j, i, P, H, rho, eps, dle, drh, hx, hy, Kd, pdj, pdi, pw, 1, work_p, work_e, work_rh)
                if not d < 0.0:
                    continue
                new = P[j, i] + omega_gs * r / d
                if new < 0.0:
                    new = 0.0
                change = new - P[j, i]
                if change != 0.0:
                    P[j, i] = new
                    H[j, i] += Kd[0, 0] * change
                    point_nodal_at(j, i, P, H, lam, viscosity_code, density_code, params, rho, eps, dle, drh)
            else:
                npat = 1
                for q in range(4):
                    dj = STENCIL_DJ[q + 1]
                    di = STENCIL_DI[q + 1]
                    if 0 < j + dj < ny - 1 and 0 < i + di < nx - 1 and jacobi[j + dj, i + di]:
                        pdj[npat] = dj
                        pdi[npat] = di
                        pw[npat] = -0.25
                        npat += 1
                d = pattern_derivative(j, i, P, H, rho, eps, dle, drh, hx, hy, Kd, pdj, pdi, pw, npat, work_p, work_e, work_rh)
                for q in range(5):
                    pdj[q] = 0
                    pdi[q] = 0
                    pw[q] = 0.0
                if d < 0.0:
                    delta[j, i] = r / d
                count += 1
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
    return count


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
    "deformation_direct_2d": deformation_direct_2d,
    "restrict_full_weighting": restrict_full_weighting,
    "prolong_bilinear": prolong_bilinear,
}


def compiled(name: str):
    """The numba-compiled twin of kernel ``name`` of this module."""
    return compile_kernel(PY[name])
