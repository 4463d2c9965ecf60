"""FASTSIM (Kalker 1982) strip kernel, with its plain-Python twin.

The kernel is written once, as plain Python on float64 arrays (the *twin*, readable as the
specification and used by the tests); :func:`compiled` returns the
``numba.njit(cache=True, nogil=True)`` version of the same function, compiled on first use.
Importing this module neither compiles anything nor imports numba (:func:`compiled` does).

Conventions (Kalker's): x is the rolling direction; the material flows through the contact in
the -x direction, entering at the leading edge x = +a(y) and leaving at the trailing edge
x = -a(y), a(y) = a sqrt(1 - y^2/b^2). The rigid slip per rolling speed V is
(nu_x - phi y, nu_y + phi x) and T is the traction acting on the body (opposing the creepage),
so that in stick

.. math::
    \\frac{\\partial T_x}{\\partial x} = \\frac{\\nu_x}{L_1} - \\frac{\\phi y}{L_3}, \\qquad
    \\frac{\\partial T_y}{\\partial x} = \\frac{\\nu_y}{L_2} + \\frac{\\phi x}{L_3}

with T = 0 at the leading edge (Saccheto 2008 Eqs 5.44–5.47, corrected form).

Grid: ``ny`` strips of equal width dy = 2b/ny at centres y_j; strip j holds ``nx`` elements of
length dx_j = 2 a(y_j)/nx with centres x_ij = a(y_j) - (i + 1/2) dx_j. The traction is sampled
at the element centres. Marching from the leading edge, the predictor adds the exact stick
increment between successive centres (the spin term taken at the mid-point of the step, which
makes the predictor exact for the linear-in-x spin rate):

.. math::
    T^{pred}_i = T_{i-1} - h \\left(\\frac{\\nu_x}{L_1} - \\frac{\\phi y_j}{L_3},\\;
                 \\frac{\\nu_y}{L_2} + \\frac{\\phi \\bar x}{L_3}\\right)

(h = dx_j/2 for the first element, from the leading edge; dx_j after; x-bar the mid-point of
the step). Coulomb (Eqs 5.36–5.37, 5.50–5.52): if |T_pred| <= mu p the element sticks,
T = T_pred; otherwise it slips and T = mu p T_pred/|T_pred|. Forces are sums of T dA with
dA = dx_j dy (mid-point rule); in full stick the sampled tractions are exact and the force
error is the mid-point rule's, O(1/ny^2 + 1/nx^2).

Pressure (the traction bound mu p), selected by ``parabolic``:

* ``parabolic`` true — Kalker's FASTSIM: the shape 1 - x^2/a^2 - y^2/b^2 (continuous scale
  2N/(pi a b)). The flexibilities L1..L3 of :mod:`camcontact.contact.kalker` are Kalker's
  calibration for this bound (Kalker 1982).
* ``parabolic`` false — the semi-ellipsoidal Hertz shape sqrt(1 - x^2/a^2 - y^2/b^2) (continuous
  scale 3N/(2 pi a b)).

Either shape is sampled at the element centres and scaled so that its discrete sum carries
exactly ``normal_force``; the grid scale differs from the continuous one by the quadrature error
of the shape (Hertz: -1.5 % at 10 x 10, -0.15 % at 40 x 40, -0.017 % at 160 x 160; parabolic:
-0.65 %, -0.036 %, -0.002 %). With this normalisation the saturated force of full slip is
exactly mu N on every grid, so the inverse solve can reach any force below mu N. The stick
tractions do not depend on the pressure, so neither does the linear (small-creepage) limit.
"""

from __future__ import annotations

import math

from ..jit import compile_kernel

__all__ = ["PY", "compiled", "fastsim_strips"]


def fastsim_strips(a, b, normal_force, mu, L1, L2, L3, nu_x, nu_y, phi, parabolic, x, y, p, Tx, Ty, stick):
    """FASTSIM on a strip grid; fills the (ny, nx) arrays and returns the totals.

    Parameters
    ----------
    a, b : float
        Semi-axes along x (rolling) and y [m] (> 0).
    normal_force : float
        N [N] (>= 0).
    mu : float
        Traction (Coulomb) coefficient [-] (>= 0).
    L1, L2, L3 : float
        Flexibility parameters [m/Pa] (> 0).
    nu_x, nu_y, phi : float
        Longitudinal, lateral creepage [-] and spin creepage [1/m].
    parabolic : bool
        True: Kalker's parabolic pressure (FASTSIM); False: the semi-ellipsoidal Hertz pressure.
    x, y, p, Tx, Ty, stick : ndarray
        Outputs, float64 of shape (ny, nx) except ``y`` (ny,): element-centre x and strip-centre
        y [m], pressure p [Pa], tractions Tx, Ty [Pa] (float64) and the stick flag (bool).

    Returns
    -------
    tuple of float
        (Fx [N], Fy [N], Mz [N*m], slip_area [m^2], area [m^2]); Mz = sum (x Ty - y Tx) dA.
    """
    ny, nx = p.shape
    dy = 2.0 * b / ny
    shape_sum = 0.0
    for j in range(ny):
        y_j = -b + (j + 0.5) * dy
        y[j] = y_j
        half = a * math.sqrt(1.0 - (y_j / b) ** 2)
        dx = 2.0 * half / nx
        for i in range(nx):
            x_ij = half - (i + 0.5) * dx
            x[j, i] = x_ij
            s = 1.0 - (x_ij / a) ** 2 - (y_j / b) ** 2
            if s <= 0.0:
                p[j, i] = 0.0
            elif parabolic:
                p[j, i] = s
            else:
                p[j, i] = math.sqrt(s)
            shape_sum += p[j, i] * dx * dy
    scale = normal_force / shape_sum if shape_sum > 0.0 else 0.0
    rate_x = nu_x / L1
    rate_y = nu_y / L2
    spin_rate = phi / L3
    Fx = 0.0
    Fy = 0.0
    Mz = 0.0
    slip_area = 0.0
    area = 0.0
    for j in range(ny):
        y_j = y[j]
        half = a * math.sqrt(1.0 - (y_j / b) ** 2)
        dx = 2.0 * half / nx
        dA = dx * dy
        tx = 0.0
        ty = 0.0
        previous = half  # leading edge, T = 0
        for i in range(nx):
            x_ij = x[j, i]
            step = previous - x_ij
            tx -= step * (rate_x - spin_rate * y_j)
            ty -= step * (rate_y + spin_rate * 0.5 * (previous + x_ij))
            pressure = scale * p[j, i]
            p[j, i] = pressure
            bound = mu * pressure
            magnitude = math.sqrt(tx * tx + ty * ty)
            if magnitude <= bound:
                stick[j, i] = True
            else:
                stick[j, i] = False
                factor = bound / magnitude
                tx *= factor
                ty *= factor
                slip_area += dA
            Tx[j, i] = tx
            Ty[j, i] = ty
            Fx += tx * dA
            Fy += ty * dA
            Mz += (x_ij * ty - y_j * tx) * dA
            area += dA
            previous = x_ij
    return Fx, Fy, Mz, slip_area, area


# ----------------------------------------------------------------------------- registry of kernels
PY = {"fastsim_strips": fastsim_strips}


def compiled(name: str):
    """The compiled twin of kernel ``name`` of :data:`PY`; see :mod:`camcontact.jit`."""
    return compile_kernel(PY[name])
