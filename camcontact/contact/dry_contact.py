"""Numerical dry (frictionless, elastic half-space) contact of two bodies with any gap: pressure >= 0 on a grid.

The surfaces' separation before deformation is h0(x, y) (the profiles of both bodies, any shape: a
crowned roller, a tilted one, an ellipse); under the load W they approach rigidly by delta and
deform by u = K * p, the half-space response to the pressure (Boussinesq): for a uniform pressure
on a rectangle 2a x 2b, Love (1929) gives the displacement of the surface at (x, y) as
(2/(pi E')) F(x, y) with

    F = (x + a) ln[(y + b + r(+,+)) / (y - b + r(+,-))] + (y + b) ln[(x + a + r(+,+)) / (x - a + r(-,+))]
      + (x - a) ln[(y - b + r(-,-)) / (y + b + r(-,+))] + (y - b) ln[(x - a + r(-,-)) / (x + a + r(+,-))],

r(s, t) = sqrt((x s a)^2 + (y t b)^2) and E' = 2/[(1 - nu1^2)/E1 + (1 - nu2^2)/E2] (Johnson 1985 §3.2
for Love's rectangle). The convolution K * p runs as a discrete convolution by zero-padded FFT
(DC-FFT: the influence coefficients of the cells on a grid twice the size, wrapped, so that the
cyclic product is the linear convolution exactly; Liu, Wang & Liu 2000).

The contact conditions — h = h0 + u - delta >= 0, p >= 0, h p = 0, sum p dA = W — are solved by the
conjugate-gradient method of Polonsky & Keer (1999): conjugate directions on the contact set, the
mean gap there as the unknown approach, a projection to p >= 0, re-entry of points with a negative
gap outside the set (which restarts the conjugacy) and the load imposed by scaling each iteration.
It converges in a few dozen iterations for smooth and edge-loaded contacts alike; the record gives
the relative pressure change per iteration and stops at ``tolerance``.

References: Love, A.E.H. (1929) The stress produced in a semi-infinite solid by pressure on part of
the boundary, Phil. Trans. R. Soc. A 228:377-420; Johnson, K.L. (1985) Contact Mechanics §3.2;
Polonsky, I.A. & Keer, L.M. (1999) A numerical method for solving rough contact problems based on
the multi-level multi-summation and conjugate gradient techniques, Wear 231:206-219; Liu, S., Wang, Q.
& Liu, G. (2000) A versatile method of discrete convolution and FFT (DC-FFT) for contact analyses,
Wear 243:101-111.
"""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..errors import ConvergenceError, InputError

__all__ = ["DryContact", "love_rectangle", "solve_dry_contact"]


def _term(u, v1, v2):
    """u ln[(v1 + sqrt(u^2 + v1^2)) / (v2 + sqrt(u^2 + v2^2))] as u (asinh(v1/|u|) - asinh(v2/|u|)), which keeps
    its digits on long, thin cells (0 where u = 0, its limit)."""
    magnitude = np.abs(u)
    safe = np.where(magnitude > 0.0, magnitude, 1.0)
    return np.where(magnitude > 0.0, u * (np.arcsinh(v1 / safe) - np.arcsinh(v2 / safe)), 0.0)


def love_rectangle(x, y, a: float, b: float):
    """Love's F(x, y) [m] for a unit pressure on the rectangle |x| <= a, |y| <= b (module docstring): the surface
    displacement is (2/(pi E')) F per unit pressure."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    xp, xm, yp, ym = x + a, x - a, y + b, y - b
    return _term(xp, yp, ym) + _term(yp, xp, xm) + _term(xm, ym, yp) + _term(ym, xm, xp)


@attrs.frozen
class DryContact:
    """The pressure of a numerical dry contact (SI): ``x`` [m] (nx,), ``y`` [m] (ny,) cell centres, ``pressure``
    and ``gap`` [Pa, m] (ny, nx), the rigid ``approach`` delta [m], the ``load`` W [N], ``iterations`` and the
    relative pressure change per iteration (``changes``)."""

    x: np.ndarray = attrs.field(repr=False, eq=False)
    y: np.ndarray = attrs.field(repr=False, eq=False)
    pressure: np.ndarray = attrs.field(repr=False, eq=False)
    gap: np.ndarray = attrs.field(repr=False, eq=False)
    approach: float
    load: float
    iterations: int
    changes: tuple = attrs.field(repr=False, eq=False)

    @property
    def p_max(self) -> float:
        """Largest pressure [Pa]."""
        return float(self.pressure.max())

    def along(self) -> np.ndarray:
        """The largest pressure across each row (the pressure along y) [Pa], shape (ny,)."""
        return self.pressure.max(axis=1)

    def load_per_row(self) -> np.ndarray:
        """Load per unit length along y [N/m], shape (ny,)."""
        return self.pressure.sum(axis=1) * (self.x[1] - self.x[0])


class _Convolution:
    """u = K * p on an (ny, nx) grid by zero-padded FFT of Love's influence coefficients."""

    def __init__(self, dx: float, dy: float, nx: int, ny: int, E_reduced: float):
        ix = np.arange(-nx, nx) * dx
        iy = np.arange(-ny, ny) * dy
        kernel = 2.0 / (math.pi * E_reduced) * love_rectangle(ix[None, :], iy[:, None], 0.5 * dx, 0.5 * dy)
        # wrap: index 0 is distance 0, negative distances at the end (linear convolution by a cyclic one)
        self.spectrum = np.fft.rfft2(np.fft.ifftshift(kernel))
        self.shape = (ny, nx)

    def __call__(self, p: np.ndarray) -> np.ndarray:
        ny, nx = self.shape
        padded = np.zeros((2 * ny, 2 * nx))
        padded[:ny, :nx] = p
        return np.fft.irfft2(np.fft.rfft2(padded) * self.spectrum, s=(2 * ny, 2 * nx))[:ny, :nx]


def solve_dry_contact(x: np.ndarray, y: np.ndarray, separation: np.ndarray, load: float, E_reduced: float, *,
                      tolerance: float = 1e-8, max_iterations: int = 2000) -> DryContact:
    """Pressure of a frictionless elastic contact on the uniform grid of cell centres ``x`` (nx,), ``y`` (ny,) [m]
    with the undeformed separation ``separation`` (ny, nx) [m] (where a cell may touch: use a large value, not
    inf, where it cannot), the normal ``load`` [N] and E' [Pa] (module docstring).

    Raises InputError for bad input (naming it) and ConvergenceError with the record when the relative pressure
    change does not fall below ``tolerance`` in ``max_iterations``.
    """
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    h0 = np.asarray(separation, dtype=float)
    if x.ndim != 1 or y.ndim != 1 or x.size < 4 or y.size < 4 or h0.shape != (y.size, x.size):
        raise InputError(f"dry contact: x ({x.shape}), y ({y.shape}) and separation ({h0.shape}) must be 1-D grids of "
                         "at least 4 cells and a (ny, nx) array")
    dx, dy = x[1] - x[0], y[1] - y[0]
    if not (dx > 0 and dy > 0 and np.allclose(np.diff(x), dx) and np.allclose(np.diff(y), dy)):
        raise InputError("dry contact: x and y must be uniform and increasing")
    if not (load > 0.0 and math.isfinite(load) and E_reduced > 0.0 and np.all(np.isfinite(h0))):
        raise InputError(f"dry contact: load = {load!r} N and E_reduced = {E_reduced!r} Pa must be > 0 and the "
                         "separation finite")
    area = dx * dy
    convolve = _Convolution(dx, dy, x.size, y.size, E_reduced)
    # start: the load spread over the cells that touch first (within a tenth of the separations' range)
    low = h0 - h0.min()
    p = np.where(low <= 0.1 * max(float(np.ptp(low)), 1e-30) + 1e-30, 1.0, 0.0)
    p *= load / (area * p.sum())
    t = np.zeros_like(p)
    G_old, delta_restart = 1.0, False
    changes: list[float] = []
    for iteration in range(1, max_iterations + 1):
        u = convolve(p)
        g = h0 + u
        contact = p > 0.0
        g_mean = float(g[contact].mean())
        g = g - g_mean
        G = float(np.sum(g[contact] ** 2))
        factor = 0.0 if delta_restart else G / G_old
        t = np.where(contact, g + factor * t, 0.0)
        G_old = G
        r = convolve(t)
        r = r - float(r[contact].mean())
        denominator = float(np.sum(r[contact] * t[contact]))
        tau = float(np.sum(g[contact] * t[contact])) / denominator if denominator != 0.0 else 0.0
        p_old = p
        p = np.where(contact, p - tau * t, 0.0)
        p = np.maximum(p, 0.0)
        reenter = (p == 0.0) & (g < 0.0)
        delta_restart = bool(reenter.any())
        if delta_restart:
            p = np.where(reenter, p - tau * g, p)
        total = float(p.sum()) * area
        if total <= 0.0:
            raise ConvergenceError(f"dry contact: the pressure vanished at iteration {iteration}")
        p *= load / total
        change = float(np.sum(np.abs(p - p_old))) * area / load
        changes.append(change)
        if change < tolerance:
            u = convolve(p)
            approach = float(np.mean((h0 + u)[p > 0.0]))
            return DryContact(x=x, y=y, pressure=p, gap=h0 + u - approach, approach=approach, load=load,
                              iterations=iteration, changes=tuple(changes))
    raise ConvergenceError(f"dry contact did not converge in {max_iterations} iterations (relative pressure change "
                           f"{changes[-1]:.3g}, tolerance {tolerance:g})")
