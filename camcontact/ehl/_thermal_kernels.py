"""Numba kernels of the thermal, non-Newtonian line EHL solver (:mod:`camcontact.ehl.line_thermal`), each with
its plain-Python twin (see :mod:`camcontact.jit`).

Film rheology (per node; first for a viscosity eta uniform across the film, below for one varying across it): an
Eyring fluid, du/dz = (tau0/eta)
sinh(tau/tau0), under the shear stress tau(z) = tau_m + p' (z - h/2) of a thin film (p' = dp/dx, tau_m the
mid-plane stress). Integrated across the film in closed form, with s = h p'/(2 tau0) and
Lambda = eta (u2 - u1)/(tau0 h):

.. math::
    \\sinh\\frac{\\tau_m}{\\tau_0} = \\Lambda\\,\\frac{s}{\\sinh s}, \\qquad
    q = u_m h - \\Phi\\,\\frac{h^3 p'}{12\\eta}, \\qquad
    \\Phi = \\cosh\\frac{\\tau_m}{\\tau_0}\\,g(s) = \\sqrt{g(s)^2 + (\\Lambda\\,r(s))^2},

g(s) = 3 (s cosh s - sinh s)/s^3, r(s) = 3 (s coth s - 1)/s^2 (both 1 at s = 0): the Poiseuille flow of the
film is Phi times the Newtonian one. (Derivation checked independently by numerical integration of the
velocity profile, to 1e-13.) The dissipation per unit area is, for any rheology with tau linear in z,
Q = tau_m (u2 - u1) + p' (u_m h - q). A Newtonian film is the limit tau0 -> infinity: tau_m = eta (u2 - u1)/h,
Phi = 1 (tau0 <= 0 selects it here).

The kernels use the limit s -> 0, the Reynolds–Eyring equation of Conry, Wang & Cusano (1987):
sinh(tau_m/tau0) = Lambda, Phi = cosh(tau_m/tau0) = sqrt(1 + Lambda^2). The full closed form was tried first:
at the pressure spike of an isothermal start s reaches 20-60 (wall stresses of 20-60 tau0, far above any
limiting shear stress), Phi ~ e^44 there, and the multigrid solve with even 30 % of that flow factor
diverged (measured: M = 6.7, L = 16.5, S = 0.5, level 8). With s -> 0 the flow factor depends on the film and
the sliding only, not on the pressure gradient the spike feeds back on.

The dissipation is evaluated at each node's Poiseuille flux q_P = -Phi h^3 p'/(12 eta) (that of the current
pressure solution, which the mass balance fixes) rather than at its pressure gradient:
Q = tau_m (u2 - u1) + 12 eta q_P^2/(Phi h^3), which falls as the temperature rises. At a fixed p' the
Poiseuille heat would rise as the viscosity falls, and the first energy model ran away to 1000 K at the
pressure spike of an isothermal start (measured: S = 0.02, level 8); the spike's flow then adjusts in the
Reynolds solve.

Viscosity varying across the film (:func:`film_profile`; Yang & Wen's 1990 generalised Reynolds equation, here in
the same s -> 0 limit): with inv(zeta) = eta_ref/eta(zeta), F0 = int_0^zeta inv and F1 = int_0^zeta zeta inv, the
Couette stress tau_c is that of the harmonic-mean viscosity eta_ref/F0(1), the Poiseuille flux is
q_P = Phi p' h^3 C_P/eta_ref with C_P = -int (zeta - zeta*)^2 inv (zeta* = F1(1)/F0(1); -1/12 uniform), and the
entrainment flux is h (u1 + (u2 - u1)(1 - zeta*)), u_m h only in pure rolling or for a symmetric profile. The
solver takes a = -12 C_P (against the uniform film at eta_ref), the Eyring coefficient at the harmonic mean and the
Couette factor c = (u1 + (u2 - u1)(1 - zeta*))/u_m (:mod:`camcontact.ehl._kernels`). The dissipation at a film
point is (tau_c + delta)(du inv/(h F0(1)) + Phi delta inv/eta_ref), delta = p' h (zeta - zeta*), which integrates
to the uniform film's Q when inv is uniform. Checked against Nahme's closed form of a heated Couette film
(tests/unit/test_line_thermal.py).

Energy (:func:`layer_sweep`): the temperature at N + 1 Chebyshev–Lobatto points across the film (the two
surfaces included) at every node of a uniform grid along x,

.. math::
    \\rho c\\,\\Big(u(\\zeta)\\,\\frac{\\partial T}{\\partial x}
    + \\frac{\\omega}{h}\\frac{\\partial T}{\\partial\\zeta}\\Big)
    = \\frac{k}{h^2}\\frac{\\partial^2 T}{\\partial\\zeta^2} + \\tau\\dot\\gamma
    + \\alpha_T\\,T\\,u\\,\\frac{\\partial p}{\\partial x}, \\qquad
    T_j(x) - T_0 = \\frac{1}{e_j\\sqrt{\\pi u_j}}\\int_{-\\infty}^{x}\\frac{q_j(s)}{\\sqrt{x - s}}\\,ds

with the film's velocity profile u(zeta) = u1 + (u2 - u1) F0/F0(1) + (q_P/h)(F1 - zeta* F0)/C_P (u1 + (u2 - u1) zeta +
6 (q_P/h) zeta (1 - zeta) for a uniform viscosity; its reverse flow in the inlet included: the x-derivative is
upwinded by the sign of u at each film point, and downstream and upstream sweeps alternate), the local dissipation tau
gamma-dot of the film's linear stress profile, and each surface a half-space moving at u_j under the heat flux q_j it
takes from the film (Jaeger 1942, high Peclet number; e_j its effusivity), q_j piecewise constant on the cells of the
grid. The flow across the film's layers, omega = h dzeta/dt = -dG/dx - zeta dh/dt (G = h int_0^zeta u, the flux
below the layer; continuity in zeta = z/h), carries heat between them (:func:`layer_fluxes`): in a converging film it
is of the order of the convection along x (the layers of the inlet exchange fluid where its reverse flow turns), and
without it the sweeps did not conserve energy (measured on a rigid inlet wedge: 20 W/m convected out of a balance of
-0.2 W/m; with it within 1 %, tests/unit/test_line_thermal.py; against a conservative finite-volume solution on 160
layers the peak is now 0.25 % off, then 27 %: tests/unit/test_line_thermal_energy_reference.py). It is collocated
where conduction holds it and blends into upwinding between neighbouring film points where its cell Peclet number
exceeds :data:`CELL_PECLET` (a thick inlet). The compression work alpha_T T u dp/dx (alpha_T the lubricant's thermal
expansivity, T = T0 + the point's rise, p the pressure solution's, not the gradient the held Poiseuille flux implies
at the trial temperature: that one grows as a film cools, and the outlet's expansion cooling ran away to -366 K with
it, measured) is integrated over each cell along the flow, the fluid arriving from its upstream neighbour at (T0 + T)
exp(alpha_T dp/(rho c)): exact for adiabatic compression, and stable where a cell's pressure rise exceeds rho
c/alpha_T (2.7 GPa for a mineral oil), where the implicit source made the node's system singular (measured: a cam
turn's spike of 2.5 GPa per node, film temperatures of -39000 K). Conduction along x is neglected (thin film). The
viscosity at film point j is eta_iso exp(-beta (t + d_j)): t the film's mean temperature rise, d_j the point's rise
above the mean in the node's present temperatures (lagged from sweep to sweep, beta |d_j| bounded by
:data:`PROFILE_BOUND`; d_j = 0 without ``cross``: the viscosity uniform at the mean). The system of a node is linear
for a given t, and t is found as the root of t = mean(T(t)) by the Illinois method.
"""

from __future__ import annotations

import math

import numpy as np
from numba.extending import register_jitable

from ..jit import compile_kernel, helper
from ._fas_kernels import solve_dense

__all__ = ["PY", "compiled"]

#: largest temperature rise the march looks for [K]: a node whose balance has no root below it (a Newtonian
#: film in heavy sliding, thermal runaway) is reported at this rise and counted as not converged
MAX_RISE = 1000.0
#: largest |beta (T_j - T_mean)| the film's viscosity profile takes (a viscosity e^2 = 7.4 times the mean's at most,
#: e^4 = 55 from the film's coolest to its hottest point): the nine film points do not resolve the shear bands of
#: a film sheared far beyond its Eyring stress, and an unbounded profile fed them (measured at level 7: p_h 1.9 GPa
#: and S = 1.5, beta (T_j - T_mean) from -6.3 to 3.7 and no convergence in 40 iterations; a Newtonian film at
#: 20 m/s and S = 0.3 overflowed). The film-forming inlet stays well inside it (measured: within +-0.8 up to a
#: thermal loading of 3.4)
PROFILE_BOUND = 2.0
#: the flow across the film's layers is collocated where its cell Peclet number Pe = |omega| rho c h dzeta/k is below
#: this (conduction-dominated) and blends into upwinding between neighbouring film points above it (weight 1 - 2/Pe,
#: continuous in Pe): collocated everywhere, the sweeps diverged in an inlet of 16 b (film 300 um thick there, Pe
#: in the thousands; measured)
CELL_PECLET = 2.0


@helper
def film_state(eta, h, flux, du, tau0, limit):
    """(tau_m [Pa], Phi [-], Q [W/m^2]): mid-plane shear stress, Poiseuille flow factor and dissipation per
    unit area of a film of viscosity eta [Pa s] and thickness h [m] carrying the Poiseuille volume flux
    ``flux`` = -Phi h^3 p'/(12 eta) [m^2/s] at the sliding speed du = u2 - u1 [m/s]; Eyring stress tau0 [Pa]
    (<= 0: Newtonian). Eyring: the Reynolds–Eyring form (s -> 0, module docstring), sinh(tau_m/tau0) =
    eta du/(tau0 h), Phi = cosh(tau_m/tau0). |tau_m| is bounded by the limiting shear stress ``limit`` [Pa]
    (inf: none; Bair & Winer 1979, the film then slips in a plane and dissipates limit |du|; its Poiseuille
    flow keeps the Eyring factor). Q = tau_m du + 12 eta flux^2/(Phi h^3)."""
    if h <= 0.0 or eta <= 0.0:
        return 0.0, 1.0, 0.0
    if tau0 <= 0.0:
        tau_m = eta * du / h
        phi = 1.0
    else:
        lam = eta * du / (tau0 * h)
        tau_m = tau0 * math.asinh(lam)
        phi = math.sqrt(1.0 + lam * lam)
    if abs(tau_m) > limit:
        tau_m = limit if du > 0.0 else -limit
    return tau_m, phi, tau_m * du + 12.0 * eta * flux * flux / (phi * h * h * h)


@helper
def profile_offset(beta, deviation):
    """beta times a film point's temperature above the film's mean, bounded by +-:data:`PROFILE_BOUND`."""
    return min(max(beta * deviation, -PROFILE_BOUND), PROFILE_BOUND)


@helper
def inverse_viscosity(T, i, t, beta, cross, weights, inv):
    """inv_j = eta_iso/eta at node i's film points, in place: exp(beta (t + d_j)) for the film's mean temperature
    rise t [K] and the points' present rises d_j above the mean of T[i] (bounded, :func:`profile_offset`); d_j = 0
    without ``cross`` (the viscosity uniform at the mean)."""
    N = inv.shape[0] - 1
    present = 0.0
    if cross:
        for j in range(N + 1):
            present += weights[j] * T[i, j]
    for j in range(N + 1):
        inv[j] = math.exp(beta * t + (profile_offset(beta, T[i, j] - present) if cross else 0.0))


@helper
def point_heat(tau_c, delta, inv_j, du, h, total, Phi, eta_iso):
    """Dissipation per volume [W/m^3] at a film point (module docstring): stress tau_c + delta times the shear rate
    inv_j (du/(h F0(1)) + Phi delta/eta_iso), inv_j = eta_iso/eta there, total = F0(1)."""
    return (tau_c + delta) * inv_j * (du / (h * total) + Phi * delta / eta_iso)


@helper
def film_profile(inv, eta_ref, h, flux, du, tau0, limit, zeta, integral, weights, F0, F1):
    """The film of a viscosity varying across it, eta(zeta) = eta_ref / inv(zeta) at the film points zeta_j
    (Yang & Wen 1990, in the Reynolds–Eyring limit of Conry et al. 1987: the stress's Poiseuille part is a small
    perturbation of the uniform Couette stress tau_c).

    Fills F0_j = int_0^zeta_j inv and F1_j = int_0^zeta_j zeta inv (``integral`` the collocation's antiderivative
    matrix) and returns (tau_c [Pa], Phi [-], F0(1) [-], C_P [-], zeta* [-]):

    * the Couette stress tau_c and Eyring factor Phi = cosh(tau_c/tau0) of :func:`film_state` at the film's
      Couette viscosity eta_ref/F0(1) (the harmonic mean), which shears the film by du in all;
    * the Poiseuille flux q_P = Phi p' h^3 C_P/eta_ref with C_P = -int (zeta - zeta*)^2 inv (-1/12 for a uniform
      viscosity; the integral of the Poiseuille velocity h^2 p' (F1 - zeta* F0)/eta_ref by parts, in this form
      free of cancellation), zeta* = F1(1)/F0(1): the Poiseuille stress p' h (zeta - zeta*) adds no net shear;
    * the entrainment (Couette) flux h (u1 + du m), m = 1 - zeta* (1/2 uniform), and the velocity
      u(zeta) = u1 + du F0/F0(1) + (q_P/h)(F1 - zeta* F0)/C_P.

    The film's integrals are the collocation's quadrature (``weights``). Uniform inv gives the uniform film."""
    N = inv.shape[0] - 1
    for j in range(N + 1):
        s0 = 0.0
        s1 = 0.0
        for c in range(N + 1):
            s0 += integral[j, c] * inv[c]
            s1 += integral[j, c] * zeta[c] * inv[c]
        F0[j] = s0
        F1[j] = s1
    total = 0.0
    first = 0.0
    for j in range(N + 1):
        total += weights[j] * inv[j]
        first += weights[j] * zeta[j] * inv[j]
    z_star = first / total
    C_P = 0.0
    for j in range(N + 1):
        C_P -= weights[j] * (zeta[j] - z_star) * (zeta[j] - z_star) * inv[j]
    tau_c, Phi, _ = film_state(eta_ref / total, h, flux, du, tau0, limit)
    return tau_c, Phi, total, C_P, z_star


@register_jitable
def jaeger_weights(dx, n):
    """w_d = int over cell j = i - d of 1/sqrt(x_i - s) ds [m^0.5], cells [x_j - dx/2, x_j + dx/2] cut at x_i:
    w_0 = 2 sqrt(dx/2), w_d = 2 (sqrt((d + 1/2) dx) - sqrt((d - 1/2) dx))."""
    w = np.empty(n)
    w[0] = 2.0 * math.sqrt(0.5 * dx)
    for d in range(1, n):
        w[d] = 2.0 * (math.sqrt((d + 0.5) * dx) - math.sqrt((d - 0.5) * dx))
    return w


@register_jitable
def layer_fluxes(h, flux, u1, du, zeta, G):
    """G[i, j] = h int_0^zeta_j u dzeta [m^2/s], in place: the volume flux between surface 1 and film point j at
    every node, of the velocity profile u = u1 + du zeta + 6 (q_P/h) zeta (1 - zeta) of a film of uniform viscosity
    (q_P = ``flux``): G = h (u1 zeta + du zeta^2/2) + q_P zeta^2 (3 - 2 zeta). The flow across the film's layers is
    omega = h dzeta/dt = -dG/dx - zeta dh/dt = -dG/dx + zeta dq/dx (continuity in the film's coordinate zeta = z/h,
    whose surfaces stay at 0 and 1; q = G(1) the node's flux, dh/dt = -dq/dx), zero at both surfaces. Taken from the
    uniform profile, not the node's temperatures: differentiated along x, the temperature profiles' node-to-node
    changes fed back on themselves and the sweeps oscillated at the inlet's reverse-flow layers (measured: 7 K at u_m
    20 m/s); the shift of the layers' flux by the viscosity profile is left out of omega."""
    n = h.shape[0]
    N = zeta.shape[0] - 1
    for i in range(n):
        hi = max(h[i], 0.0)
        for j in range(N + 1):
            z = zeta[j]
            G[i, j] = hi * (u1 * z + 0.5 * du * z * z) + flux[i] * z * z * (3.0 - 2.0 * z)


@register_jitable
def layer_node(i, t, dx, film, params, A1, A2, collocation, T, A, b):
    """Temperature rises at the film points of node i (returned, with their film mean) for the film viscosity
    eta_iso[i] exp(-beta (t + d_j)) (t the film's mean temperature rise assumed; d_j the node's present
    profile about its mean with ``cross`` set, else 0; see :func:`layer_sweep`). ``film`` = (h, eta_iso, flux,
    limit, G) per node (G the layers' fluxes of :func:`layer_fluxes`), ``params`` = (u1, du, tau0, beta, k, rho c, c1,
    c2, cross, alpha_T, p, T0) with c_j = C_j w_0 (alpha_T [1/K] the lubricant's expansivity, p [Pa] the pressure
    per node, T0 [K] the inlet temperature), ``collocation`` =
    (zeta, D, D2, weights, integral, inv, F0, F1); A and b are work arrays."""
    h, eta_iso, flux, limit, G = film
    u1, du, tau0, beta, conductivity, heat_capacity, c1, c2, cross, expansivity, pressure, T0 = params
    zeta, D, D2, weights, integral, inv, F0, F1 = collocation
    N = zeta.shape[0] - 1
    n = h.shape[0]
    hi = h[i]
    inverse_viscosity(T, i, t, beta, cross, weights, inv)
    tau_c, Phi, total, C_P, z_star = film_profile(inv, eta_iso[i], hi, flux[i], du, tau0, limit[i], zeta, integral,
                                                  weights, F0, F1)
    gradient = flux[i] * eta_iso[i] / (Phi * hi * hi * hi * C_P)
    kh = conductivity / hi
    for r in range(N + 1):
        for c in range(N + 1):
            A[r, c] = 0.0
    A[0, 0] = 1.0
    A[N, N] = 1.0
    for c in range(N + 1):
        A[0, c] -= c1 * kh * D[0, c]
        A[N, c] += c2 * kh * D[N, c]
    b[0] = A1
    b[N] = A2
    above = i + 1 if i + 1 < n else i
    for j in range(1, N):
        u = u1 + du * F0[j] / total + (flux[i] / hi) * (F1[j] - z_star * F0[j]) / C_P
        delta = gradient * hi * (zeta[j] - z_star)
        carry = heat_capacity * abs(u) / dx
        upstream = i - 1 if u >= 0.0 else (i + 1 if i + 1 < n else i)
        neighbour = T[upstream, j]
        # the flow across the film's layers, omega = h dzeta/dt = -dG/dx + zeta dq/dx (G the flux below the layer, q the
        # film's; zero at both surfaces; dq/dx = -dh/dt in a squeezed film, 0 in a steady full one): collocated
        # where the conduction holds it (cell Peclet number below CELL_PECLET), else upwinded between neighbouring
        # film points (monotone where the flow dominates: a thick inlet)
        across = -heat_capacity * (G[above, j] - G[i - 1, j] - zeta[j] * (G[above, N] - G[i - 1, N])) / (
            (above - i + 1) * dx * hi)
        diffusion = conductivity / (hi * hi)
        gap = zeta[j] - zeta[j - 1] if across > 0.0 else zeta[j + 1] - zeta[j]
        peclet = abs(across) * gap / diffusion
        upwind = 1.0 - CELL_PECLET / peclet if peclet > CELL_PECLET else 0.0  # continuous in the Peclet number
        for c in range(N + 1):
            A[j, c] = -diffusion * D2[j, c] + (1.0 - upwind) * across * D[j, c]
        if across > 0.0:
            A[j, j] += upwind * across / gap
            A[j, j - 1] -= upwind * across / gap
        else:
            A[j, j] -= upwind * across / gap
            A[j, j + 1] += upwind * across / gap
        # compression work alpha_T T u dp/dx, integrated over the cell along the flow: the fluid arrives from its
        # upstream neighbour at (T0 + T) exp(alpha_T dp/(rho c)), dp the pressure change on the way (heats where the
        # flow runs up the pressure, cools where it runs down it; stable for any dp)
        adiabatic = math.exp(expansivity * (pressure[i] - pressure[upstream]) / heat_capacity)
        A[j, j] += carry
        b[j] = (point_heat(tau_c, delta, inv[j], du, hi, total, Phi, eta_iso[i])
                + carry * (adiabatic * (neighbour + T0) - T0))
    x, ok = solve_dense(A, b)
    mean = 0.0
    for j in range(N + 1):
        mean += weights[j] * x[j]
    if not ok:
        mean = math.nan
    return x, mean


@register_jitable
def node_temperatures(i, dx, film, params, A1, A2, collocation, T, A, b, tolerance, max_iterations):
    """(temperature rises at node i's film points, failed): the root Tm = mean(T(Tm)) of :func:`layer_node` by the
    Illinois method on a bracket widened from the node's present mean (see :func:`layer_sweep`); failed where no
    root lies within +-:data:`MAX_RISE` or the balance is not finite."""
    N = T.shape[1] - 1
    beta = params[3]
    weights = collocation[3]
    failed = False
    previous = 0.0
    for j in range(N + 1):
        previous += weights[j] * T[i, j]
    # F(t) = t - mean(T(t)) increases with t: bracket the root from the previous mean, then Illinois
    low = min(max(previous, -MAX_RISE), MAX_RISE)
    x, mean = layer_node(i, low, dx, film, params, A1, A2, collocation, T, A, b)
    f_low = low - mean
    if beta == 0.0 or f_low == 0.0 or not math.isfinite(f_low):
        T_new = x
        if not math.isfinite(f_low):
            failed = True
    else:
        step = abs(f_low) + 1.0
        high = low
        f_high = f_low
        sign = 1.0 if f_low < 0.0 else -1.0  # the root lies above (F < 0) or below
        while f_high * f_low > 0.0 and abs(high) < MAX_RISE:
            low, f_low = high, f_high
            high = min(max(low + sign * step, -MAX_RISE), MAX_RISE)
            step *= 2.0
            x, mean = layer_node(i, high, dx, film, params, A1, A2, collocation, T, A, b)
            f_high = high - mean
        T_new = x
        if f_high * f_low > 0.0 or not math.isfinite(f_high):
            failed = True  # no root within +-MAX_RISE: kept at the bound
        else:
            side = 0
            for _ in range(max_iterations):
                if abs(f_high) <= tolerance or abs(high - low) <= tolerance:
                    break
                t = (low * f_high - high * f_low) / (f_high - f_low)
                x, mean = layer_node(i, t, dx, film, params, A1, A2, collocation, T, A, b)
                f_t = t - mean
                T_new = x
                if f_t * f_high > 0.0:
                    high, f_high = t, f_t
                    if side == 1:
                        f_low *= 0.5
                    side = 1
                else:
                    low, f_low = t, f_t
                    if side == -1:
                        f_high *= 0.5
                    side = -1
                if abs(f_t) <= tolerance:
                    break
    return T_new, failed


@register_jitable
def layer_sweep(direction, dx, h, eta_iso, flux, limit, u1, du, tau0, beta, conductivity, heat_capacity, C1, C2, zeta,
                D, D2, weights, integral, T, q1, q2, tolerance, max_iterations, cross, expansivity, pressure, T0):
    """One sweep of the cross-film energy equation over the nodes 1..n-1 (``direction`` +1: downstream, -1:
    upstream), in place on the temperature rises T[i, j] [K] at the film points zeta_j (0 and 1 the
    surfaces) and the surface heat fluxes q1, q2 [W/m^2]. Returns (largest change of T [K], nodes whose film
    temperature found no root below :data:`MAX_RISE` or did not converge).

    At node i the film points solve (rho c) (|u_j| (T_ij - T_(i -+ 1)j)/dx + (omega_j/h) dT/dzeta) = (k/h^2)
    d^2T/dzeta^2 + Q_j + alpha_T (T0 + T) u_j dp/dx (the compression work of a lubricant of expansivity
    ``expansivity`` [1/K], 0 without; ``pressure`` [Pa] per node, T0 [K] the inlet temperature; integrated over the
    cell along the flow: the upstream temperature T0 + T_(i -+ 1)j enters times exp(alpha_T dp/(rho c))) (upwind
    in x by the sign of u_j: the inlet's reverse flow takes the downstream neighbour; omega_j the flow across the
    layers from :func:`layer_fluxes` at the start of the sweep, central in x), the surfaces
    T_i0 = A_1 + C_1 w_0 q_1, q_1 = (k/h) dT/dzeta(0) and T_iN = A_2 + C_2 w_0 q_2, q_2 = -(k/h) dT/dzeta(1)
    (Jaeger, A_j the upstream history), all together as one dense (N+1) system with the collocation
    derivative matrices D, D2 (d/dzeta) and the antiderivative matrix ``integral``. Velocity u_j and dissipation
    Q_j of the film's viscosity profile (module docstring, :func:`film_profile`; ``limit`` the node's limiting
    shear stress [Pa]), q_P = ``flux`` the node's Poiseuille flux (held), the viscosity eta_iso exp(-beta (Tm +
    d_j)) at the film's mean temperature rise Tm and the node's present profile d_j about it (``cross``; else
    uniform): the system is linear for a given Tm, and Tm = mean(T(Tm)) (one root: the dissipation falls as Tm
    rises) is solved by the Illinois method on a bracket widened from the node's previous mean, to ``tolerance``
    [K] (:func:`node_temperatures`). Node 0 (inlet)
    holds T = 0 where the flow enters and takes its neighbour's temperature where it leaves (reverse flow).
    """
    n = h.shape[0]
    N = zeta.shape[0] - 1
    w = jaeger_weights(dx, n)
    G = np.empty((n, N + 1))
    collocation = (zeta, D, D2, weights, integral, np.empty(N + 1), np.empty(N + 1), np.empty(N + 1))
    layer_fluxes(h, flux, u1, du, zeta, G)
    film = (h, eta_iso, flux, limit, G)
    params = (u1, du, tau0, beta, conductivity, heat_capacity, C1 * w[0], C2 * w[0], cross, expansivity, pressure, T0)
    A = np.empty((N + 1, N + 1))
    b = np.empty(N + 1)
    largest = 0.0
    failed = 0
    start = 1 if direction > 0 else n - 1
    stop = n if direction > 0 else 0
    for i in range(start, stop, direction):
        if h[i] <= 0.0:
            continue
        A1 = 0.0
        A2 = 0.0
        for m in range(1, i):
            A1 += w[i - m] * q1[m]
            A2 += w[i - m] * q2[m]
        A1 *= C1
        A2 *= C2
        T_new, bad = node_temperatures(i, dx, film, params, A1, A2, collocation, T, A, b, tolerance, max_iterations)
        if bad:
            failed += 1
        for j in range(N + 1):
            change = abs(T_new[j] - T[i, j])
            if change > largest:
                largest = change
            T[i, j] = T_new[j]
        d0 = 0.0
        dN = 0.0
        for c in range(N + 1):
            d0 += D[0, c] * T_new[c]
            dN += D[N, c] * T_new[c]
        q1[i] = conductivity / h[i] * d0
        q2[i] = -conductivity / h[i] * dN
    # the inlet node: zero where the flow enters, the neighbour's temperature where it leaves
    for j in range(N + 1):
        T[0, j] = 0.0
    if h[0] > 0.0:
        for j in range(1, N):
            u0 = u1 + du * zeta[j] + 6.0 * (flux[0] / h[0]) * zeta[j] * (1.0 - zeta[j])
            if u0 < 0.0:
                T[0, j] = T[1, j]
    return largest, failed




@register_jitable
def film_fields(eta_iso, h, flux, limit, du, tau0, beta, T, cross, zeta, integral, weights, tau, phi, Q, a, total, m):
    """The film at every node, in place: its mid-plane shear stress tau [Pa] (the mean of the two surfaces'),
    Eyring factor phi [-], dissipation per unit area Q [W/m^2], and the generalised Reynolds factors of its
    viscosity profile (:func:`film_profile`): a = -12 C_P (the Poiseuille coefficient against a uniform film at
    eta_iso), total = F0(1) (eta_iso over the Couette viscosity) and m = 1 - zeta* (the entrainment flux's share of
    the sliding speed). The viscosity
    eta_iso exp(-beta T_j) at the film points' temperature rises T[i, j]; without ``cross`` uniform at their mean."""
    n = h.shape[0]
    N = zeta.shape[0] - 1
    inv = np.empty(N + 1)
    F0 = np.empty(N + 1)
    F1 = np.empty(N + 1)
    for i in range(n):
        mean = 0.0
        for j in range(N + 1):
            mean += weights[j] * T[i, j]
        inverse_viscosity(T, i, mean, beta, cross, weights, inv)
        hi = h[i]
        if hi <= 0.0:
            tau[i], phi[i], Q[i], a[i], total[i], m[i] = 0.0, 1.0, 0.0, 1.0, 1.0, 0.5
            continue
        tau_c, Phi, F_total, C_P, z_star = film_profile(inv, eta_iso[i], hi, flux[i], du, tau0, limit[i], zeta,
                                                        integral, weights, F0, F1)
        gradient = flux[i] * eta_iso[i] / (Phi * hi * hi * hi * C_P)
        heat = 0.0
        for j in range(N + 1):
            delta = gradient * hi * (zeta[j] - z_star)
            heat += weights[j] * point_heat(tau_c, delta, inv[j], du, hi, F_total, Phi, eta_iso[i])
        tau[i] = tau_c + gradient * hi * (0.5 - z_star)
        phi[i] = Phi
        Q[i] = heat * hi
        a[i] = -12.0 * C_P
        total[i] = F_total
        m[i] = 1.0 - z_star


PY = {"film_state": film_state, "layer_sweep": layer_sweep, "film_fields": film_fields}


def compiled(name: str):
    """The numba-compiled twin of kernel ``name`` of this module."""
    return compile_kernel(PY[name])
