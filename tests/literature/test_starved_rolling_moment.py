"""Hydrodynamic rolling moment of fully flooded and starved EHL line contacts against Biboulet & Houpert (2010).

Source: Biboulet, N. & Houpert, L. (2010) Hydrodynamic force and moment in pure rolling lubricated contacts.
Part 1: line contacts. Proc. IMechE J 224, 765-775. Their multigrid line-contact solutions (Barus viscosity,
Dowson–Higginson density, Moes M and L as camcontact defines them: lambda-bar = 3 pi^2/(8 M^2), alpha-bar =
L sqrt(M/(2 pi))) give, in Hertz units p_h b^2 per unit length,

* Eq. 42, the fully flooded moment over L = 4-16, M = 0.2-200:
  T* = M^-3/2 1.4 sqrt(M) / (1 + ((1.4/1.45) sqrt(M))^10)^(1/10);
* Eq. 44, starvation by a truncated inlet: T/T* = (S^2 + 162.8 S)/(S^2 + 193.1 S + 1257), S = H_a/H_m*, the film
  at the inlet boundary over the fully flooded minimum film, fitted to their IVR and EHL results down to S = 2.

camcontact's starved contact (:func:`camcontact.ehl.line_starved.solve_starved`) is fed a supply layer and
finds its meniscus by mass conservation; its pressurised film is the flooded solution of the domain that
starts at the meniscus, which is the source's truncated inlet, so H_a = H(X_meniscus).

What is found (level 8, inlet domain [-8, 2]):

* flooded, T/T* of Eq. 42: 0.977 (M 10, L 10), 1.000 (20, 10), 0.982 (50, 16), 0.988 (100, 10); level 9 gives
  0.976, 0.998, 0.975, 0.978. The moment converges slowly with the inlet length (M 10: 0.861 on [-4, 1.5], 1.028
  on [-16, 2]), as the source says;
* starved: T/T* falls with S on nearly one curve for both cases (the source's finding; the two within 0.055 of
  each other at equal S), but above Eq. 44: by 0.065-0.092 at M 20, L 10 and by 0.018-0.042 at M 100, L 10 for
  S = 4-38 (S 7.2: 0.543 against Eq. 44's 0.454). An independent check of our reading of Eq. 44: the rigid
  isoviscous (IVR) starved cylinder, integrated below from Martin's solution with scipy, lies within 0.045 of
  Eq. 44 for S = 7-900. The EHL points of Eq. 44's fit are in the source's Fig. 6, which is not readable
  here; the disagreement is stated, not tuned away.
"""

import math

import attrs
import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from camcontact.ehl.line_multigrid import solve_multigrid
from camcontact.ehl.line_problem import LineEHLProblem
from camcontact.ehl.line_starved import solve_starved, wet_flux

LEVEL = 8
DOMAIN = (-8.0, 2.0)
SUPPLIES = (0.99, 0.95, 0.9, 0.8)  # supply / flooded flux


def moment_flooded(M):
    """Biboulet & Houpert (2010) Eq. 42."""
    return M ** -1.5 * 1.4 * math.sqrt(M) / (1.0 + ((1.4 / 1.45) * math.sqrt(M)) ** 10) ** 0.1


def moment_starved_ratio(S):
    """Biboulet & Houpert (2010) Eq. 44."""
    return (S * S + 162.8 * S) / (S * S + 193.1 * S + 1257.0)


def _problem(M, L, **extra):
    return LineEHLProblem(M=M, L=L, viscosity="barus", density="dowson_higginson", alpha=2e-8, domain=DOMAIN,
                          cavitation="mass_conserving", **extra)


@pytest.fixture(scope="module")
def starved_curves():
    """(S, T/T*) per case from camcontact's starved solves."""
    curves = {}
    for M, L in ((20.0, 10.0), (100.0, 10.0)):
        flooded = solve_multigrid(_problem(M, L), LEVEL, tolerance=1e-8, strict=True)
        points = []
        for fraction in SUPPLIES:
            solution = solve_starved(_problem(M, L, supply=fraction * wet_flux(flooded)), LEVEL, tolerance=1e-8,
                                     strict=True)
            H_a = float(np.interp(solution.inlet_meniscus, solution.X, solution.H))
            points.append((H_a / flooded.H_min, solution.rolling_moment / flooded.rolling_moment))
        curves[(M, L)] = (flooded, np.array(points))
    return curves


@pytest.mark.parametrize("M, L", [(10.0, 10.0), (20.0, 10.0), (50.0, 16.0), (100.0, 10.0)])
def test_fully_flooded_moment_matches_eq_42(M, L):
    solution = solve_multigrid(LineEHLProblem(M=M, L=L, viscosity="barus", density="dowson_higginson", alpha=2e-8,
                                              domain=DOMAIN), LEVEL, tolerance=1e-8, strict=True)
    assert solution.rolling_moment == pytest.approx(moment_flooded(M), rel=0.035)


def test_moment_is_the_rolling_force_times_the_radius_dimensionally():
    solution = solve_multigrid(LineEHLProblem(M=20.0, L=10.0), 6, strict=True)
    R, w, E = 0.02, 2.0e5, 2.26e11
    values = solution.dimensional(R, w, E)
    assert values["rolling_moment"] == pytest.approx(solution.rolling_moment * values["p_h"] * values["b"] ** 2)
    assert values["rolling_force"] == pytest.approx(values["rolling_moment"] / R)
    assert values["rolling_force"] > 0.0  # it resists the rolling


def test_starved_moment_falls_on_one_curve_of_S_above_eq_44(starved_curves):
    S_grid = np.array([5.0, 8.0, 12.0, 20.0, 30.0])
    on_grid = []
    for flooded, points in starved_curves.values():
        S, ratio = points[:, 0], points[:, 1]
        assert np.all(np.diff(S) < 0) and np.all(np.diff(ratio) < 0)  # less supply: shorter inlet, smaller moment
        assert S.min() > 2.0  # the source's range
        on_grid.append(np.interp(np.log(S_grid), np.log(S[::-1]), ratio[::-1]))
        # the published fit is lower: stated (measured offsets in the module docstring)
        offset = ratio - moment_starved_ratio(S)
        assert np.all(offset > 0.0) and np.all(offset < 0.15)
    on_grid = np.array(on_grid)
    assert np.ptp(on_grid, axis=0).max() < 0.07  # nearly one curve of S, as the source found (measured 0.055)


def _ivr(xi_a):
    """(A, B, xi_e) of the rigid isoviscous cylinder fed from xi_a = x_a/sqrt(2 R h0) (Martin's solution with the
    Reynolds exit condition at xi_e): p ~ Pi(xi) = int (s^2 - xi_e^2)/(1 + s^2)^3 ds, load ~ A/h0 with
    A = int Pi dxi, moment ~ h0^-1/2 B with B = int (s^2 - xi_e^2)/(1 + s^2)^2 ds."""
    def pi_(x, e):
        return quad(lambda s: (s * s - e * e) / (1.0 + s * s) ** 3, xi_a, x, epsabs=1e-14, epsrel=1e-12,
                    limit=400)[0]

    e = brentq(lambda e: pi_(e, e), 1e-6, 5.0, xtol=1e-14)
    A = quad(lambda x: pi_(x, e), xi_a, e, epsabs=1e-13, limit=400)[0]
    B = quad(lambda s: (s * s - e * e) / (1.0 + s * s) ** 2, xi_a, e, epsabs=1e-13, limit=400)[0]
    return A, B, e


def test_our_reading_of_eq_44_holds_for_the_rigid_isoviscous_cylinder():
    """An independent calculation in the IVR regime, which Eq. 44 also fits: at equal load h0 = c A, so
    T/T* = sqrt(A*/A) B/B* and S = h(x_a)/h0* = (A/A*) (1 + xi_a^2); the flooded exit xi_e = 0.475 (Martin)."""
    A_inf, B_inf, e_inf = _ivr(-1e4)  # B's tail beyond: 1e-4 of B
    assert e_inf == pytest.approx(0.4751, abs=1e-4)
    for xi_a in (-30.0, -10.0, -6.0, -4.0, -3.0):
        A, B, _ = _ivr(xi_a)
        S = A / A_inf * (1.0 + xi_a * xi_a)
        assert math.sqrt(A_inf / A) * B / B_inf == pytest.approx(moment_starved_ratio(S), abs=0.045)
