"""Viscosity–temperature laws (family ``viscosity_laws``, kind ``"temperature"``).

* ``walther`` — Walther double-log law on kinematic viscosity, nu + a (2+ points);
* ``astm_d341`` — the same with ASTM D341's low-viscosity term (below about 2 cSt);
* ``vogel`` — Vogel (Vogel–Fulcher–Tammann) exponential law (3+ points).

A law is fitted to (temperature [K], viscosity) points with :meth:`fit`, which returns a
fitted copy; :meth:`viscosity` then gives the viscosity at T [K] in the unit of the data
(SI: m^2/s for kinematic data), and :meth:`thermoviscous_coefficient` gives
beta = -d(ln nu)/dT [1/K].
"""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..errors import InputError
from .base import ViscosityTemperatureLaw, builtin

__all__ = ["AstmD341", "Vogel", "Walther"]

_CST = 1e-6  # 1 cSt = 1 mm^2/s = 1e-6 m^2/s


def _points(law: str, temperatures, viscosities, needed: int) -> tuple[np.ndarray, np.ndarray]:
    t = np.atleast_1d(np.asarray(temperatures, dtype=float))
    v = np.atleast_1d(np.asarray(viscosities, dtype=float))
    if t.shape != v.shape or t.ndim != 1:
        raise InputError(f"{law}: temperatures and viscosities must be 1-D of equal length")
    if t.size < needed:
        raise InputError(
            f"{law} needs at least {needed} (temperature, viscosity) points to be fitted; got {t.size}"
        )
    if np.any(t <= 0) or np.any(v <= 0):
        raise InputError(f"{law}: temperatures [K] and viscosities must be > 0; got T={t}, viscosity={v}")
    if np.unique(t).size != t.size:
        raise InputError(f"{law}: the temperatures of the points must differ; got {t} K")
    order = np.argsort(t)
    return t[order], v[order]


def _require_fitted(law, *params) -> None:
    if any(p is None for p in params):
        raise InputError(f"the {law.name} viscosity law is not fitted yet; call .fit(temperatures, viscosities)")


@builtin
@attrs.frozen
class Walther(ViscosityTemperatureLaw):
    """Walther / ASTM D341 viscosity–temperature relation (kinematic viscosity).

    .. math:: \\log_{10}\\log_{10}(\\nu + a) = n - m \\log_{10} T

    nu in cSt (mm^2/s), T in K, a = 0.7 for mineral oils. Two points (e.g. 40 and 100 °C)
    fix m and n exactly (Delabenetta 2021, Eqs. 32–34); more points are fitted by least
    squares in the (log10 T, log10 log10(nu + a)) plane. The thermo-viscosity coefficient
    is the exact derivative of the law (Delabenetta 2021, Eq. 37):

    .. math:: \\beta = -\\frac{1}{\\nu}\\frac{d\\nu}{dT} = \\frac{m (\\nu + a)\\ln(\\nu + a)}{\\nu T}

    Parameters
    ----------
    a : float
        Walther constant [cSt], 0.7 (ASTM D341 for nu >= 2 cSt).
    m, n : float
        Slope and intercept; ``None`` until fitted.

    References
    ----------
    Walther, C. (1931) Erdöl und Teer 7:382–384; ASTM D341 (viscosity–temperature charts);
    Delabenetta (2021) Eqs. 32–34 and 37.
    """

    name = "walther"
    reference = "Walther (1931); ASTM D341; Delabenetta (2021) Eqs. 32-34, 37"
    #: the plain form (a = 0.7) holds down to 2 cSt; below, ASTM D341 adds a correction term
    validity = {"kinematic_viscosity_cSt": (2.0, None)}
    points_needed = 2

    a: float = 0.7
    m: float | None = None
    n: float | None = None

    def fit(self, temperatures, viscosities) -> Walther:
        """Fit to temperatures [K] and kinematic viscosities [m^2/s]."""
        t, nu = _points(self.name, temperatures, viscosities, self.points_needed)
        x = np.log10(t)
        y = np.log10(np.log10(self._z(nu / _CST)))
        if t.size == 2:
            m = (y[0] - y[1]) / (x[1] - x[0])
            n = y[0] + m * x[0]
        else:
            slope, intercept = np.polyfit(x, y, 1)
            m, n = -slope, intercept
        if not m > 0:
            raise InputError(
                f"walther fit gives slope m = {m:.4g} <= 0: the viscosity data {nu / _CST} cSt at "
                f"{t} K does not decrease with temperature"
            )
        return attrs.evolve(self, m=float(m), n=float(n))

    def viscosity(self, temperature):
        """Kinematic viscosity [m^2/s] at ``temperature`` [K]."""
        _require_fitted(self, self.m, self.n)
        t = np.asarray(temperature, dtype=float)
        nu_cst = self._nu_from_z(10.0 ** (10.0 ** (self.n - self.m * np.log10(t))))
        return float(nu_cst * _CST) if nu_cst.ndim == 0 else nu_cst * _CST

    def thermoviscous_coefficient(self, temperature):
        """beta = -d(ln nu)/dT [1/K] at ``temperature`` [K] (Delabenetta 2021, Eq. 37).

        From dZ/dT = -m Z ln Z / T and dnu/dT = (dZ/dT)/(dZ/dnu).
        """
        t = np.asarray(temperature, dtype=float)
        nu_cst = np.asarray(self.viscosity(t)) / _CST
        z = self._z(nu_cst)
        beta = self.m * z * np.log(z) / (nu_cst * t * self._dz_dnu(nu_cst))
        return float(beta) if beta.ndim == 0 else beta

    # Z(nu) of the double-log law (nu in cSt), its inverse and derivative
    def _z(self, nu_cst):
        return nu_cst + self.a

    def _nu_from_z(self, z):
        return np.asarray(z - self.a, dtype=float)

    def _dz_dnu(self, nu_cst):
        return np.ones_like(nu_cst)


@builtin
@attrs.frozen
class AstmD341(Walther):
    """ASTM D341 viscosity–temperature relation with its low-viscosity term.

    .. math::
        \\log_{10}\\log_{10} Z = n - m \\log_{10} T, \\qquad
        Z = \\nu + 0.7 + \\exp(-1.47 - 1.84\\,\\nu - 0.51\\,\\nu^2)

    (nu in cSt, natural exponential). Above about 3 cSt the extra term is below 1e-5 cSt and
    the law equals ``walther``; it matters when data or predictions fall below 2 cSt. Z(nu)
    is inverted exactly by Newton iteration (the standard's polynomial inverse is
    approximate, to about 2e-4 cSt).

    References
    ----------
    ASTM D341 (2009 and later editions), Eqs. 1–3, as reproduced by the ASTM D341 pages of
    technicaltoolboxes.com and ttwiki.
    """

    name = "astm_d341"
    reference = "ASTM D341 Eqs. 1-3 (low-viscosity Z term)"
    validity = {}

    def _z(self, nu_cst):
        nu_cst = np.asarray(nu_cst, dtype=float)
        return nu_cst + 0.7 + np.exp(-1.47 - 1.84 * nu_cst - 0.51 * nu_cst**2)

    def _dz_dnu(self, nu_cst):
        nu_cst = np.asarray(nu_cst, dtype=float)
        return 1.0 - (1.84 + 1.02 * nu_cst) * np.exp(-1.47 - 1.84 * nu_cst - 0.51 * nu_cst**2)

    def _nu_from_z(self, z):
        z = np.asarray(z, dtype=float)
        if np.any(z <= 0.7 + np.exp(-1.47)):
            raise InputError(f"astm_d341: Z = {np.min(z):.6g} is below its value at nu = 0; the law is not defined there")
        nu = np.maximum(z - 0.7, 0.0)
        for _ in range(60):  # Z(nu) is increasing and convex enough: Newton converges in a few steps
            step = (self._z(nu) - z) / self._dz_dnu(nu)
            nu = np.maximum(nu - step, 0.0)
            if np.all(np.abs(step) <= 1e-14 * np.maximum(nu, 1.0)):
                return nu
        raise InputError(f"astm_d341: inverting Z = {z!r} did not converge")


@builtin
@attrs.frozen
class Vogel(ViscosityTemperatureLaw):
    """Vogel (Vogel–Fulcher–Tammann) law nu = A exp(B / (T - C)).

    .. math:: \\nu(T) = A \\exp\\left(\\frac{B}{T - C}\\right), \\qquad \\beta = \\frac{B}{(T - C)^2}

    Three points determine A, B, C exactly (closed form: the ratio of log-viscosity
    differences is linear in C); more points are fitted by nonlinear least squares in
    ln nu. The same form applies to dynamic viscosity; :meth:`viscosity` returns the unit
    of the fitted data.

    Parameters
    ----------
    A : float
        Pre-factor [unit of the data]; ``None`` until fitted.
    B : float
        [K]; ``None`` until fitted.
    C : float
        [K], must stay below every temperature used; ``None`` until fitted.

    References
    ----------
    Vogel, H. (1921) Physikalische Zeitschrift 22:645–646.
    """

    name = "vogel"
    reference = "Vogel (1921) Phys. Z. 22:645"
    points_needed = 3

    A: float | None = None
    B: float | None = None
    C: float | None = None

    def fit(self, temperatures, viscosities) -> Vogel:
        """Fit to temperatures [K] and viscosities (any consistent unit, e.g. m^2/s)."""
        t, v = _points(self.name, temperatures, viscosities, self.points_needed)
        ln_v = np.log(v)
        i, j, k = 0, t.size // 2, t.size - 1
        if t.size > 3:
            j = int(np.argmin(np.abs(t - 0.5 * (t[0] + t[-1]))))
            j = min(max(j, 1), t.size - 2)
        ratio = (ln_v[i] - ln_v[j]) / (ln_v[j] - ln_v[k])
        denominator = (t[j] - t[i]) - ratio * (t[k] - t[j])
        if denominator == 0.0:
            raise InputError("vogel: the three points are collinear in 1/T and cannot fix C")
        c = ((t[j] - t[i]) * t[k] - ratio * (t[k] - t[j]) * t[i]) / denominator
        b = (ln_v[i] - ln_v[k]) / (1.0 / (t[i] - c) - 1.0 / (t[k] - c))
        ln_a = ln_v[i] - b / (t[i] - c)
        if t.size > 3:
            from scipy.optimize import least_squares

            def residual(params):
                return params[0] + params[1] / (t - params[2]) - ln_v

            solution = least_squares(residual, x0=[ln_a, b, c], method="lm")
            ln_a, b, c = solution.x
        if not (c < t.min() and b > 0):
            raise InputError(
                f"vogel fit gives B = {b:.4g} K, C = {c:.4g} K: the data do not follow a Vogel law "
                f"(need B > 0 and C below every data temperature {t.min():.4g} K)"
            )
        return attrs.evolve(self, A=float(math.exp(ln_a)), B=float(b), C=float(c))

    def _check_temperature(self, t: np.ndarray) -> None:
        if np.any(t <= self.C):
            raise InputError(
                f"vogel law: temperature {t.min():.4g} K is at or below its singular point C = {self.C:.4g} K"
            )

    def viscosity(self, temperature):
        _require_fitted(self, self.A, self.B, self.C)
        t = np.asarray(temperature, dtype=float)
        self._check_temperature(t)
        value = self.A * np.exp(self.B / (t - self.C))
        return float(value) if value.ndim == 0 else value

    def thermoviscous_coefficient(self, temperature):
        """beta = -d(ln nu)/dT = B/(T - C)^2 [1/K]."""
        _require_fitted(self, self.A, self.B, self.C)
        t = np.asarray(temperature, dtype=float)
        self._check_temperature(t)
        beta = self.B / (t - self.C) ** 2
        return float(beta) if beta.ndim == 0 else beta
