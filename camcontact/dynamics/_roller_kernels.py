"""Kernels of the roller follower's spin dynamics (plain Python twins; compiled by :mod:`camcontact.jit`).

The roller's angular speed omega_r obeys I domega_r/dt = R F_t(u_s) - T_pin - R F_rr with the sliding
speed u_s = u_cam - R omega_r; F_t(u_s) is tabulated per cam angle (monotone non-decreasing in u_s). One
implicit Euler step of length h solves, for s = u_s at the step's end,

    R F(s) + I s / (R h) = I (u_cam / R - omega_prev) / h + T_pin + R F_rr,

whose left side increases strictly with s: the root is found exactly on the piecewise-linear table.
"""

from __future__ import annotations

from ..jit import compile_kernel

__all__ = ["PY", "compiled", "march_roller"]


def march_roller(dt, u_cam, pin_torque, resistance, grid, force, radius, inertia, turns, substeps, out):
    """Implicit-Euler march of the roller's spin over ``turns`` periodic cycles of the cam angles.

    ``dt[k]`` [s] is the time from angle k to k+1 (the last wraps to angle 0); ``u_cam``, ``pin_torque``
    [N m] and ``resistance`` (rolling-resistance force [N]) are per angle and vary linearly between angles;
    ``grid[k]``/``force[k]`` tabulate the traction force on the roller [N] against the sliding speed [m/s]
    at angle k. The march starts in pure rolling at angle 0. ``out`` (4 x n) receives the last turn's
    omega_r [rad/s], sliding speed [m/s], traction force [N] and the change of omega_r from the turn
    before [rad/s]; returns the largest such change."""
    n = u_cam.size
    m = grid.shape[1]
    w = u_cam[0] / radius
    change = 0.0
    for turn in range(turns):
        change = 0.0
        for k in range(n):
            k1 = k + 1 if k + 1 < n else 0
            h = dt[k] / substeps
            stiffness = inertia / (radius * h)
            s = 0.0
            for j in range(1, substeps + 1):
                f = j / substeps
                uc = u_cam[k] + f * (u_cam[k1] - u_cam[k])
                torque = pin_torque[k] + f * (pin_torque[k1] - pin_torque[k])
                resist = resistance[k] + f * (resistance[k1] - resistance[k])
                rhs = inertia * (uc / radius - w) / h + torque + radius * resist
                # the root of radius F(s) + stiffness s = rhs on the table (constant F beyond its ends)
                if rhs <= radius * force[k1, 0] + stiffness * grid[k1, 0]:
                    s = (rhs - radius * force[k1, 0]) / stiffness
                elif rhs >= radius * force[k1, m - 1] + stiffness * grid[k1, m - 1]:
                    s = (rhs - radius * force[k1, m - 1]) / stiffness
                else:
                    lo, hi = 0, m - 1
                    while hi - lo > 1:
                        mid = (lo + hi) // 2
                        if radius * force[k1, mid] + stiffness * grid[k1, mid] <= rhs:
                            lo = mid
                        else:
                            hi = mid
                    g0 = radius * force[k1, lo] + stiffness * grid[k1, lo]
                    g1 = radius * force[k1, hi] + stiffness * grid[k1, hi]
                    s = grid[k1, lo] + (rhs - g0) / (g1 - g0) * (grid[k1, hi] - grid[k1, lo])
                w = (uc - s) / radius
            delta = abs(w - out[0, k1])
            if turn > 0 and delta > change:
                change = delta
            out[3, k1] = delta
            out[0, k1] = w
            out[1, k1] = s
            # the traction force at s (linear between nodes, constant beyond)
            if s <= grid[k1, 0]:
                out[2, k1] = force[k1, 0]
            elif s >= grid[k1, m - 1]:
                out[2, k1] = force[k1, m - 1]
            else:
                lo, hi = 0, m - 1
                while hi - lo > 1:
                    mid = (lo + hi) // 2
                    if grid[k1, mid] <= s:
                        lo = mid
                    else:
                        hi = mid
                t = (s - grid[k1, lo]) / (grid[k1, hi] - grid[k1, lo])
                out[2, k1] = force[k1, lo] + t * (force[k1, hi] - force[k1, lo])
    return change


PY = {"march_roller": march_roller}


def compiled(name: str):
    """The numba-compiled kernel ``name`` of :data:`PY`."""
    return compile_kernel(PY[name])
