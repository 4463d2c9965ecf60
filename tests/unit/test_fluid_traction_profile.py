"""Fluid traction over a numerical line pressure and film (camcontact.contact.fluid_traction.PressureProfile).

Expected values:
* a Hertz-shaped profile P = sqrt(1 - X^2) (zero outside |X| < 1) with a uniform film reproduces the Hertz
  Gauss-Legendre path, up to the trapezoid error (bound below) and the Couette shear of the film outside the
  contact, which the profile counts and the Hertz path does not: tau_c = tau(eta0, u_s/h_c) over the
  1.5 b of [-2, -1] and [1, 1.5], i.e. 0.75 tau_c in the (1/(2b)) int tau dx mean;
* a converged multigrid solution balances its load, h sum P = pi/2 (trapezoid), i.e. sum(weight P) = pi/4;
* a stack of profiles is the same arithmetic as each profile alone (exact).
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from camcontact.contact.fluid_traction import (
    FluidTractionContact,
    PressureProfile,
    TractionThermal,
    fluid_traction,
)
from camcontact.ehl.line_multigrid import solve_multigrid
from camcontact.ehl.line_problem import LineEHLProblem
from camcontact.errors import InputError
from camcontact.models.traction_fluid import EyringTraction, NewtonianTraction

ALPHA = 2.0e-8  # [1/Pa]
P_H, H_C, ETA0, TAU0 = 1.0e9, 0.3e-6, 0.05, 5.0e6
STEEL_EFFUSIVITY = math.sqrt(46.0 * 7850.0 * 470.0)  # [W s^0.5/(m^2 K)]
#: the trapezoid's error at the two square-root edges of a Hertz-like pressure (the edges at +-1 off the nodes)
#: is at most 2 |zeta(-1/2)| sqrt(2) dx^1.5 in int P dX (zeta(-1/2) = -0.208, the generalised-zeta
#: constant of a sqrt(x) end point): dx = 3.5/2048, 4.3e-5 of pi/2, i.e. 2.7e-5 relative; tau(p(X)) has the
#: same square-root edges (and min(tau, tau_L) a kink, an O(dx^2) error), and the Hertz reference at 256
#: Gauss nodes is within 2e-6 of converged at that kink. Measured: 2e-6 to 2.5e-5. Tolerance 4x the bound:
HERTZ_PROFILE_RTOL = 1.0e-4


def barus(p):
    return ALPHA * np.asarray(p, dtype=float)


def hertz_profile(n=2049, domain=(-2.0, 1.5), film=None) -> PressureProfile:
    X = np.linspace(*domain, n)
    P = np.sqrt(np.clip(1.0 - X * X, 0.0, None))
    return PressureProfile(X, P, np.ones(n) if film is None else film(X))


def contact_inputs(rheology, limited):
    kw = {"p_h": P_H, "film_thickness": H_C, "eta0": ETA0, "log_viscosity_ratio": barus, "rheology": rheology}
    if rheology == "eyring":
        kw["eyring_stress"] = TAU0
    if limited:
        kw["limiting_shear_slope"] = 0.075
    return kw


# ------------------------------------------------------------------------------------- Hertz-shaped profile
@pytest.mark.parametrize("rheology, limited", [("newtonian", False), ("eyring", False), ("eyring", True)])
def test_hertz_shaped_profile_equals_the_hertz_quadrature(rheology, limited):
    profile = hertz_profile()
    weight = profile.weights()
    assert np.sum(weight * profile.pressure_ratio) == pytest.approx(math.pi / 4.0, rel=3e-5)
    assert np.sum(weight) == pytest.approx(3.5 / 2.0, rel=1e-14)  # (1/(2b)) int dx over [-2, 1.5]
    u_s = np.logspace(-4, 0, 9)  # linear to plateau
    kw = contact_inputs(rheology, limited)
    hertz = FluidTractionContact(**kw, n_nodes=256).coefficient(u_s)
    if not limited:  # the profile also counts the film's Couette shear outside the contact
        rate = ETA0 * u_s / H_C
        couette = rate if rheology == "newtonian" else TAU0 * np.arcsinh(rate / TAU0)
        hertz = hertz + 0.75 * couette / (math.pi / 4.0 * P_H)
    # (with tau_L0 = 0 the limit Lambda_L p is 0 outside: no Couette shear there, the two paths agree as they are)
    mu = FluidTractionContact(**kw, profile=profile).coefficient(u_s)
    np.testing.assert_allclose(mu, hertz, rtol=HERTZ_PROFILE_RTOL)
    assert FluidTractionContact(**kw, profile=profile).coefficient(-u_s[3]) == pytest.approx(-mu[3], rel=1e-14)


def test_regime_fractions_are_taken_over_the_loaded_nodes():
    """With tau_L0 = 0 the unloaded nodes are 'limited' (tau_L = 0) but not counted: the fractions of the
    Hertz-shaped profile equal the Hertz path's within the node resolution of the Hertz path (<= 0.1)."""
    kw = contact_inputs("eyring", True)
    u_s = np.array([1e-4, 1e-2, 0.3, 1.0, 30.0])
    hertz = fluid_traction(u_s, **kw)
    profiled = fluid_traction(u_s, **kw, profile=hertz_profile())
    assert list(profiled.regime) == list(hertz.regime)
    np.testing.assert_allclose(profiled.limited_fraction, hertz.limited_fraction, atol=0.1)
    np.testing.assert_allclose(profiled.nonlinear_fraction, hertz.nonlinear_fraction, atol=0.1)
    assert profiled.limited_fraction[0] == 0.0 and profiled.limited_fraction[-1] == 1.0
    assert np.all(profiled.valid)


# ------------------------------------------------------------------------------------- multigrid solution
@pytest.fixture(scope="module")
def multigrid_case():
    """A moderate line contact: M = 20.05, L = 9.99 (R 20 mm, w 455 kN/m, E' 220 GPa, u_m 1.17 m/s, eta0
    0.05 Pa s, alpha 2e-8 1/Pa: p_h = 0.89 GPa), 897 nodes on [-4, 1.5] (7 levels, ~0.1 s)."""
    R, w, E, u_m, eta0, alpha = 0.02, 4.55e5, 2.2e11, 1.17, 0.05, 2e-8
    problem = LineEHLProblem.from_contact(R=R, w=w, E_reduced=E, u_m=u_m, eta0=eta0, alpha=alpha)
    solution = solve_multigrid(problem, 7, strict=True)
    values = solution.dimensional(R, w, E)
    # the traction uses the solver's own (Roelands) viscosity law: one lubricant for film and traction
    state = SimpleNamespace(eta0=eta0, log_viscosity_ratio=lambda p: problem.log_viscosity(np.asarray(p) / problem.p_h))
    return problem, solution, values, state, u_m


def test_solution_profile_is_the_dimensional_solution(multigrid_case):
    problem, solution, values, _, _ = multigrid_case
    assert problem.M == pytest.approx(20.05, abs=0.01) and problem.L == pytest.approx(9.99, abs=0.01)
    profile = solution.traction_profile()
    assert profile.batch_shape == () and profile.n == solution.X.size == 897
    # P is p/p_h with the Hertz p_h, film_ratio is h/h_c with the h_c = H(0) b^2/R that the film model reports
    np.testing.assert_allclose(values["p_h"] * profile.pressure_ratio, values["p"], rtol=1e-14)
    np.testing.assert_allclose(values["h_c"] * profile.film_ratio, values["h"], rtol=1e-14)
    np.testing.assert_allclose(profile.x_ratio * values["b"], values["x"], rtol=1e-14)
    assert np.interp(0.0, profile.x_ratio, profile.film_ratio) == pytest.approx(1.0, rel=1e-14)
    assert values["p_h"] == pytest.approx(problem.p_h, rel=1e-14)


def test_multigrid_load_balance_and_eyring_traction(multigrid_case):
    _, solution, values, state, u_m = multigrid_case
    record = solution.record
    assert record.converged
    profile = solution.traction_profile()
    load = float(np.sum(profile.weights() * profile.pressure_ratio))
    # the weights are half the solver's trapezoid load balance h sum P (its last load error) ...
    assert load - math.pi / 4.0 == pytest.approx(0.5 * record.load_errors[-1], abs=1e-13)
    # ... which converged to within 10 x its tolerance
    assert abs(load - math.pi / 4.0) <= 0.5 * 10.0 * record.tolerance
    model = EyringTraction()  # tau0 = 5 MPa, tau_L = 0.075 p
    inputs = {"p_h": values["p_h"], "b": values["b"], "h_c": values["h_c"], "u_m": u_m, "lubricant_state": state}
    u_s = u_m * np.array([1e-3, 0.01, 0.05, 0.2])
    hertz = model.contact(**inputs).coefficient(u_s)
    numerical = model.contact(**inputs, profile=profile).coefficient(u_s)
    change = numerical / hertz - 1.0
    # Lower over the numerical pressure and film (measured -5.3 % at S = 0.001 to -1.7 % at S = 0.05..0.2).
    # The pressure decides it: the EHL pressure carries 1.9 % of the load at low pressure in the inlet
    # (X < -1, pressurised back to X = -4) and the outlet, and its maximum is 0.8 % below p_h. The film's
    # shear stress is a convex function of p over the contact (the Eyring stress tau0 asinh(eta(p) gamma/tau0)
    # ~ tau0 ln(2 eta gamma/tau0) only where eta gamma > tau0, next to nothing below: a hinge in ln eta(p)),
    # so moving part of the same load int p dx from the centre to the low-pressure flanks lowers int tau dx.
    # The film acts the other way only locally: the constriction (h_min = 0.87 h_c) and the spike raise
    # tau over ~0.1 b at the outlet, where the pressure is already low, while the film is thicker than h_c
    # at the inlet edge (net -0.3 %); the Couette shear of the unloaded inlet and outlet adds < 0.2 %.
    assert np.all(change < -0.005) and np.all(change > -0.30)
    uniform_film = PressureProfile(profile.x_ratio, profile.pressure_ratio, np.ones(profile.n))
    pressure_only = model.contact(**inputs, profile=uniform_film).coefficient(u_s) / hertz - 1.0
    assert np.all(pressure_only < 0.0)  # the pressure alone gives the sign
    # the same through the model's curve and evaluate
    curve = model.curve(u_s / u_m, **inputs, profile=profile)
    np.testing.assert_allclose(curve.coefficient, numerical, rtol=1e-14)
    out = model.evaluate(1000.0, values["p_h"], values["b"], values["h_c"], u_s, u_m, state, profile=profile)
    np.testing.assert_allclose(out["traction_coefficient"], numerical, rtol=1e-14)


# ------------------------------------------------------------------------------------- batches
def two_profiles():
    X = np.linspace(-3.0, 1.5, 801)
    first = np.sqrt(np.clip(1.0 - X * X, 0.0, None))
    second = 1.1 * np.sqrt(np.clip(1.0 - (X / 0.95) ** 2, 0.0, None)) * (1.0 + 0.2 * X)
    return X, (first, np.ones_like(X)), (second, 1.0 + 0.3 * X * X)


def test_stacked_profiles_equal_each_alone():
    X, (P1, F1), (P2, F2) = two_profiles()
    kw = contact_inputs("eyring", True)
    u_s = np.array([1e-4, 1e-2, 0.3, 3.0])
    alone = [fluid_traction(u_s, **kw, profile=PressureProfile(X, P, F)) for P, F in ((P1, F1), (P2, F2))]
    stacked = PressureProfile(X, np.stack([P1, P2])[:, None, :], np.stack([F1, F2])[:, None, :])
    assert stacked.batch_shape == (2, 1)
    both = fluid_traction(u_s, **kw, profile=stacked)
    assert both.coefficient.shape == (2, 4)
    for i in range(2):
        for field in ("coefficient", "shear_stress", "limited_fraction", "nonlinear_fraction"):
            np.testing.assert_allclose(getattr(both, field)[i], getattr(alone[i], field), rtol=1e-14, atol=0.0)
        assert list(both.regime[i]) == list(alone[i].regime)
    assert not np.allclose(alone[0].coefficient, alone[1].coefficient, rtol=1e-3)  # two different contacts
    # the prepared contact's fast path, with a p_h per profile
    contact = FluidTractionContact(**{**kw, "p_h": np.array([[0.8e9], [1.2e9]])}, profile=stacked)
    for i, (P, F, p_h) in enumerate(((P1, F1, 0.8e9), (P2, F2, 1.2e9))):
        single = FluidTractionContact(**{**kw, "p_h": p_h}, profile=PressureProfile(X, P, F))
        np.testing.assert_allclose(contact.coefficient(u_s)[i], single.coefficient(u_s), rtol=1e-14)
    # one profile per point through the model (the unusable point with h_c = NaN is left out)
    state = SimpleNamespace(eta0=ETA0, log_viscosity_ratio=barus)
    per_point = PressureProfile(X, np.stack([P1, P2, P1]), np.stack([F1, F2, F1]))
    out = NewtonianTraction().evaluate(np.full(3, 500.0), P_H, 2e-4, np.array([H_C, H_C, np.nan]), 0.05, 2.0, state,
                                       profile=per_point)
    for i, (P, F) in enumerate(((P1, F1), (P2, F2))):
        one = NewtonianTraction().evaluate(500.0, P_H, 2e-4, H_C, 0.05, 2.0, state, profile=PressureProfile(X, P, F))
        assert out["traction_coefficient"][i] == pytest.approx(one["traction_coefficient"], rel=1e-14)
    assert math.isnan(out["traction_coefficient"][2]) and out["traction_regime"][2] == "no film"


# ------------------------------------------------------------------------------------- thermal
def test_thermal_balance_on_a_hertz_shaped_profile_matches_the_hertz_path():
    """tau_L0 = 0: no shear outside the contact, so the heat, the balance and its rise are the Hertz
    path's up to the quadrature (1e-4 on mu) and the balance's tolerance (1e-4 K)."""
    thermal = TractionThermal(0.13, 0.03, STEEL_EFFUSIVITY, STEEL_EFFUSIVITY)
    kw = dict(contact_inputs("eyring", True), thermal=thermal, entrainment_speed=2.0, half_width=2e-4)
    u_s = 2.0 * np.array([1e-3, 0.01, 0.1, 0.5, 1.0])
    hertz = fluid_traction(u_s, **kw, n_nodes=256)
    profiled = fluid_traction(u_s, **kw, profile=hertz_profile())
    assert np.all(profiled.converged) and np.all(profiled.valid)
    assert profiled.temperature_rise[-1] > 10.0  # a hot case: the balance matters
    np.testing.assert_allclose(profiled.temperature_rise, hertz.temperature_rise, rtol=1e-3,
                               atol=2.0 * thermal.tolerance)
    np.testing.assert_allclose(profiled.coefficient, hertz.coefficient, rtol=HERTZ_PROFILE_RTOL)
    # the film-rise term keeps the central film: q h_c/(12 k)
    np.testing.assert_allclose(profiled.film_temperature_rise,
                               np.abs(profiled.shear_stress * u_s) * H_C / (12.0 * thermal.oil_conductivity),
                               rtol=1e-12)
    # a film profile thinner than h_c changes mu but not the film-rise formula's h
    thin = fluid_traction(u_s, **kw, profile=hertz_profile(film=lambda X: np.full_like(X, 0.8)))
    np.testing.assert_allclose(thin.film_temperature_rise,
                               np.abs(thin.shear_stress * u_s) * H_C / (12.0 * thermal.oil_conductivity), rtol=1e-12)


# ------------------------------------------------------------------------------------- inputs
X5 = np.linspace(-2.0, 1.5, 5)
P5 = np.array([0.0, 0.5, 1.0, 0.5, 0.0])
F5 = np.ones(5)


@pytest.mark.parametrize("fields, match", [
    ((np.where(X5 > 1, np.nan, X5), P5, F5), r"x_ratio = nan; allowed: finite"),
    ((X5, np.where(P5 == 1.0, np.inf, P5), F5), r"pressure_ratio = inf; allowed: finite"),
    ((X5, P5 - 0.25, F5), r"pressure_ratio = -0.25; allowed: finite, >= 0"),
    ((X5, np.zeros(5), F5), r"pressure_ratio = 0 at every node"),
    ((X5, P5, np.where(P5 == 1.0, 0.0, F5)), r"film_ratio = 0; allowed: finite, > 0"),
    ((X5[::-1], P5, F5), r"x_ratio = 1.5 followed by 0.625; allowed: strictly increasing"),
    ((np.array([-1.0, 0.0, 0.0, 1.0, 2.0]), P5, F5), r"x_ratio = 0 followed by 0; allowed: strictly increasing"),
    ((X5[:2], P5[:2], F5[:2]), r"x_ratio has shape \(2,\); allowed: \(\.\.\., n\) with n >= 3"),
    ((X5, P5[:4], F5), r"different node counts"),
    ((X5, np.stack([P5, P5]), np.stack([F5, F5, F5])), r"do not broadcast"),
    ((X5, P5, "thick"), r"film_ratio = 'thick'"),
])
def test_bad_profiles_name_the_field(fields, match):
    with pytest.raises(InputError, match=match):
        PressureProfile(*fields)


def test_bad_profile_use_names_the_field():
    kw = contact_inputs("eyring", False)
    with pytest.raises(InputError, match="profile = tuple; allowed: None or a PressureProfile"):
        FluidTractionContact(**kw, profile=(X5, P5, F5))
    with pytest.raises(InputError, match="profile with geometry = 'point'"):
        FluidTractionContact(**kw, geometry="point", profile=PressureProfile(X5, P5, F5))
    stacked = PressureProfile(X5, np.stack([P5, P5, P5]), F5)
    with pytest.raises(InputError, match="profile batch"):
        FluidTractionContact(**{**kw, "p_h": np.full(2, P_H)}, profile=stacked)
    state = SimpleNamespace(eta0=ETA0, log_viscosity_ratio=barus)
    with pytest.raises(InputError, match="batch shape"):
        EyringTraction().evaluate(np.full(2, 500.0), P_H, 2e-4, H_C, 0.05, 2.0, state, profile=stacked)
    with pytest.raises(InputError, match="profile = list"):
        EyringTraction().evaluate(500.0, P_H, 2e-4, H_C, 0.05, 2.0, state, profile=[X5, P5, F5])
    profile = PressureProfile(X5, P5, F5)
    with pytest.raises(ValueError):  # read-only record
        profile.pressure_ratio[0] = 1.0
    with pytest.raises(AttributeError):
        profile.film_ratio = F5


def test_multigrid_regime_counts_the_hertz_band_not_the_inlet(multigrid_case):
    """The regime of a numerical profile is decided over the Hertz band |x| <= b, as over the Hertz area in
    the Hertz path: the long pressurised inlet of the solution (X down to -4, p << p_h, linear viscous)
    must not outvote the contact. At S = 0.05 both paths call the contact non-linear (Eyring)."""
    _, solution, values, state, u_m = multigrid_case
    model = EyringTraction()
    inputs = {"p_h": values["p_h"], "b": values["b"], "h_c": values["h_c"], "u_m": u_m, "lubricant_state": state}
    hertz = model.contact(**inputs).solve(0.05 * u_m)
    numerical = model.contact(**inputs, profile=solution.traction_profile()).solve(0.05 * u_m)
    assert hertz.regime == "nonlinear" and numerical.regime == "nonlinear"
    assert numerical.nonlinear_fraction == pytest.approx(hertz.nonlinear_fraction, abs=0.1)
