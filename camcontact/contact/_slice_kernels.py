"""Kernel of the plane-strain slice stresses under piecewise-linear surface loads, with its twin.

:func:`slice_field` is plain Python on float64 arrays (the *twin*, used by the tests on small
grids and readable as the specification); :func:`compiled` returns the
``numba.njit(cache=True, nogil=True)`` version of the same function, compiled on first use and
cached on disk. Importing this module imports neither numba nor anything heavy and compiles
nothing (numba is imported inside :func:`compiled`).

The mathematics is in :mod:`camcontact.contact.slice_stress`: for a load f(s) that is linear
between nodes s_0 < ... < s_N, twice integrating by parts turns each line-load convolution

.. math::
    \\int_{s_0}^{s_N} f(s)\\, g(x - s, z)\\, ds
    = f_0\\, G(x - s_0) - f_N\\, G(x - s_N) + \\sum_{k=0}^{N} \\Delta b_k\\, H(x - s_k)

into a sum over the nodes, with G the first and H = -int G dt the second antiderivative of the
kernel g in t = x - s, and Delta b_k = (slope left of s_k) - (slope right of s_k) (zero slope
outside [s_0, s_N]). The four kernels of Johnson (1985) Eq. 2.23 (z >= 0, r^2 = t^2 + z^2,
A = atan2(t, z)) and their antiderivatives (constants that cancel because sum Delta b_k = 0
are dropped from H):

=============  ==========================  ===================================
kernel g       G = int g dt                H (second antiderivative, sign above)
=============  ==========================  ===================================
z t^2 / r^4    -z t / (2 r^2) + A / 2      (z ln r^2 - t A) / 2
z^3 / r^4      z t / (2 r^2) + A / 2       -t A / 2
z^2 t / r^4    -z^2 / (2 r^2)              z A / 2
t^3 / r^4      ln(r^2) / 2 + z^2/(2 r^2)   t - 3 z A / 2 - t ln(r^2) / 2
=============  ==========================  ===================================

H is continuous on z >= 0 (z ln r^2 and t ln r^2 -> 0 at r = 0), so the surface z = 0 and the
points just below the nodes need no special quadrature: the result is the exact integral of the
piecewise-linear load. Only the end terms f_0 G, f_N G are singular, at the surface points
x = s_0, s_N, when the load jumps there (a step load has a logarithmically infinite sigma_x at
its edge): the kernel then returns +-inf for sigma_x (and takes z^2/r^2 = z t/r^2 = 0 at r = 0).

Lengths are scaled by the span s_N - s_0 and measured from s_0 inside the kernel (the line-load
kernels are homogeneous of degree -1, so the integrals are scale and shift invariant); this
keeps the logarithms and the sums well conditioned for any unit.
"""

from __future__ import annotations

import math

import numpy as np

from ..jit import compile_kernel

__all__ = ["PY", "compiled", "slice_field"]


def slice_field(s, p, q, x, z, sigma_x, sigma_z, tau_xz):
    """Stresses [Pa] at the points (x[i], z[i]) [m] under nodal loads p, q [Pa] at nodes s [m].

    ``s`` strictly increasing (at least two nodes); ``p`` normal pressure (compression > 0),
    ``q`` tangential traction on the body in +x; both linear between the nodes and zero outside
    [s_0, s_N]. ``x``, ``z`` (z >= 0, into the body) are 1-D arrays of equal length; the results
    are written into ``sigma_x``, ``sigma_z``, ``tau_xz`` (compression negative, Johnson 1985
    Eq. 2.23 signs).
    """
    n = s.shape[0]
    origin = s[0]
    scale = s[n - 1] - s[0]
    u = np.empty(n)
    for k in range(n):
        u[k] = (s[k] - origin) / scale
    # slope jumps Delta b_k = slope_{k-1} - slope_k (slopes per scaled length)
    jump_p = np.zeros(n)
    jump_q = np.zeros(n)
    for j in range(n - 1):
        width = u[j + 1] - u[j]
        slope_p = (p[j + 1] - p[j]) / width
        slope_q = (q[j + 1] - q[j]) / width
        jump_p[j] -= slope_p
        jump_p[j + 1] += slope_p
        jump_q[j] -= slope_q
        jump_q[j + 1] += slope_q
    # only nodes where the slope changes contribute to the sums
    active = np.empty(n, dtype=np.int64)
    count = 0
    for k in range(n):
        if jump_p[k] != 0.0 or jump_q[k] != 0.0:
            active[count] = k
            count += 1
    ends = (p[0] != 0.0) or (q[0] != 0.0) or (p[n - 1] != 0.0) or (q[n - 1] != 0.0)
    factor = -2.0 / math.pi
    for i in range(x.shape[0]):
        xi = (x[i] - origin) / scale
        zi = z[i] / scale
        # integrals of p against kernels a, b, c and of q against kernels a, c, d
        pa = 0.0
        pb = 0.0
        pc = 0.0
        qa = 0.0
        qc = 0.0
        qd = 0.0
        for m in range(count):
            k = active[m]
            t = xi - u[k]
            r2 = t * t + zi * zi
            angle = math.atan2(t, zi)
            log_r2 = math.log(r2) if r2 > 0.0 else 0.0
            h_a = 0.5 * (zi * log_r2 - t * angle)
            h_b = -0.5 * t * angle
            h_c = 0.5 * zi * angle
            h_d = t - 1.5 * zi * angle - 0.5 * t * log_r2
            jp = jump_p[k]
            jq = jump_q[k]
            pa += jp * h_a
            pb += jp * h_b
            pc += jp * h_c
            qa += jq * h_a
            qc += jq * h_c
            qd += jq * h_d
        if ends:
            for end in range(2):
                k = 0 if end == 0 else n - 1
                sign = 1.0 if end == 0 else -1.0
                fp = sign * p[k]
                fq = sign * q[k]
                if fp == 0.0 and fq == 0.0:
                    continue
                t = xi - u[k]
                r2 = t * t + zi * zi
                angle = math.atan2(t, zi)
                if r2 > 0.0:
                    zt = zi * t / r2
                    zz = zi * zi / r2
                    half_log = 0.5 * math.log(r2)
                else:
                    zt = 0.0
                    zz = 0.0
                    half_log = -math.inf
                g_a = -0.5 * zt + 0.5 * angle
                g_b = 0.5 * zt + 0.5 * angle
                g_c = -0.5 * zz
                pa += fp * g_a
                pb += fp * g_b
                pc += fp * g_c
                qa += fq * g_a
                qc += fq * g_c
                if fq != 0.0:
                    qd += fq * (half_log + 0.5 * zz)
        sigma_x[i] = factor * (pa + qd)
        sigma_z[i] = factor * (pb + qc)
        tau_xz[i] = factor * (pc + qa)


#: name -> plain-Python twin
PY = {"slice_field": slice_field}


def compiled(name: str):
    """The compiled twin of kernel ``name`` of :data:`PY`; see :mod:`camcontact.jit`."""
    return compile_kernel(PY[name])
