"""Fluid traction from rheology (camcontact.contact.fluid_traction) and its traction_models plugins.

Every expected value is a closed form or an independent calculation named at the test:
* Newtonian Barus film: (1/A) int exp(alpha p) dA over the Hertz pressure is
  line: (pi/2)[I_1(c) + L_1(c)] + 1 (modified Bessel I, modified Struve L), point: 2[e^c (c - 1) + 1]/c^2,
  c = alpha p_h (substitution p = p_h cos(theta); d/dc of the Struve-Bessel form of int e^{c cos} dtheta);
* Eyring at large stress: tau = tau0 [ln(2 eta0 gamma/tau0) + alpha p] (asinh x -> ln 2x), linear in p;
* plateau: tau = tau_L0 + Lambda_L p everywhere, mu = tau_L0/p_mean + Lambda_L, p_mean = (pi/4) p_h (line),
  (2/3) p_h (point);
* thermal: the flash part equals 2/3 of the project's Blok flash_temperature of the same line contact
  (w, E', R) at the converged mu, the film part q h/(12 k).
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from scipy import integrate
from scipy.special import iv, modstruve

import camcontact as cc
from camcontact import registry
from camcontact.contact.contact_temperature import flash_temperature
from camcontact.contact.fluid_traction import (
    POINT_FLASH_FACTOR,
    FluidTractionContact,
    TractionThermal,
    fluid_traction,
    traction_coefficient,
    traction_curve,
)
from camcontact.errors import InputError
from camcontact.models.traction_fluid import (
    EYRING_STRESS,
    LIMITING_SHEAR_SLOPE,
    EyringTraction,
    NewtonianTraction,
)

ALPHA = 2.0e-8  # [1/Pa], a mineral oil's order of magnitude (alpha p_h = 20 at 1 GPa)


def barus(alpha=ALPHA):
    return lambda p: alpha * np.asarray(p, dtype=float)


def mean_exp(c, geometry):
    """(1/A) int exp(c p/p_h) dA over the Hertz pressure (closed forms of the module docstring)."""
    if geometry == "line":
        return math.pi / 2.0 * (iv(1, c) + modstruve(1, c)) + 1.0
    return 2.0 * (math.exp(c) * (c - 1.0) + 1.0) / c**2


MEAN_PRESSURE = {"line": math.pi / 4.0, "point": 2.0 / 3.0}  # p_mean / p_h


@pytest.fixture
def no_runtime_warnings():
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        yield


# ------------------------------------------------------------------------------------- physics
@pytest.mark.parametrize("geometry", ["line", "point"])
@pytest.mark.parametrize("alpha_p", [5.0, 20.0, 60.0])
def test_newtonian_equals_the_analytic_mean_viscosity(geometry, alpha_p, no_runtime_warnings):
    """mu = eta0 (u_s/h) <exp(alpha p)>_A / p_mean, 1e-10 relative (24 Gauss-Legendre nodes)."""
    p_h, h, eta0, u_s = 1.0e9, 0.3e-6, 0.05, 1e-3
    mu = traction_coefficient(u_s, p_h=p_h, film_thickness=h, eta0=eta0, log_viscosity_ratio=barus(alpha_p / p_h),
                              rheology="newtonian", geometry=geometry)
    expected = eta0 * u_s / h * mean_exp(alpha_p, geometry) / (MEAN_PRESSURE[geometry] * p_h)
    assert mu == pytest.approx(expected, rel=1e-10)


def test_newtonian_with_a_roelands_lubricant_matches_an_independent_quadrature():
    """The LubricantState's Roelands law as the callable; scipy.quad of int eta(p) dx over the line contact."""
    state = cc.Lubricant(eta0="0.04 Pa*s", alpha="2.2e-8 1/Pa").at(None)
    p_h, a, h, u_s = 1.2e9, 1.0, 0.5e-6, 2e-3
    mu = traction_coefficient(u_s, p_h=p_h, film_thickness=h, eta0=state.eta0,
                              log_viscosity_ratio=state.log_viscosity_ratio, rheology="newtonian")
    integral, _ = integrate.quad(lambda x: state.viscosity(p_h * math.sqrt(1.0 - x * x)), -a, a, epsabs=0.0,
                                 epsrel=1e-12, limit=200)
    expected = integral * u_s / h / (math.pi * a * p_h / 2.0)
    assert mu == pytest.approx(expected, rel=1e-9)


@pytest.mark.parametrize("geometry", ["line", "point"])
def test_eyring_tends_to_newtonian_at_small_stress(geometry):
    """asinh(x) = x (1 - x^2/6 + ...): with tau0 = 1e18 Pa (x <= 1e-7) the Eyring film is Newtonian to 1e-12."""
    common = dict(p_h=1e9, film_thickness=0.3e-6, eta0=0.05, log_viscosity_ratio=barus(), geometry=geometry)
    newtonian = traction_coefficient(1e-3, rheology="newtonian", **common)
    eyring = traction_coefficient(1e-3, rheology="eyring", eyring_stress=1e18, **common)
    assert eyring == pytest.approx(newtonian, rel=1e-12)


@pytest.mark.parametrize("geometry", ["line", "point"])
def test_eyring_tends_to_the_logarithm_at_large_stress(geometry):
    """eta0 gamma/tau0 = 200 at the contact edge: asinh(x) - ln(2x) < 1/(4 x^2) = 6e-6; tau is then
    tau0 [ln(2 eta0 gamma/tau0) + alpha p], whose mean is linear in p_mean."""
    p_h, h, eta0, u_s, tau0 = 1e9, 5e-8, 1.0, 50.0, 5e6
    mu = traction_coefficient(u_s, p_h=p_h, film_thickness=h, eta0=eta0, log_viscosity_ratio=barus(),
                              eyring_stress=tau0, geometry=geometry)
    p_mean = MEAN_PRESSURE[geometry] * p_h
    expected = tau0 * (math.log(2.0 * eta0 * u_s / h / tau0) + ALPHA * p_mean) / p_mean
    assert mu == pytest.approx(expected, rel=2e-6)


@pytest.mark.parametrize("geometry", ["line", "point"])
@pytest.mark.parametrize("tau_L0", [0.0, 2e6])
def test_limiting_shear_plateau_is_exact(geometry, tau_L0):
    """The film is at tau_L over the whole contact (Eyring stress above tau_L everywhere for these
    values: 5 MPa (6 + 2e-8 p) > 2 MPa + 0.075 p): mu = tau_L0/p_mean + Lambda_L to rounding."""
    p_h = 1e9
    result = fluid_traction(50.0, p_h=p_h, film_thickness=5e-8, eta0=1.0, log_viscosity_ratio=barus(),
                            eyring_stress=5e6, limiting_shear_stress=tau_L0, limiting_shear_slope=0.075,
                            geometry=geometry)
    p_mean = MEAN_PRESSURE[geometry] * p_h
    assert result.coefficient == pytest.approx(tau_L0 / p_mean + 0.075, rel=1e-12)
    assert result.limited_fraction == pytest.approx(1.0, rel=1e-12)
    assert result.regime == "plateau"


def test_sign_symmetry_and_zero_slip():
    kw = dict(p_h=1e9, film_thickness=0.3e-6, eta0=0.05, log_viscosity_ratio=barus(), eyring_stress=5e6,
              limiting_shear_slope=0.075)
    u = np.array([1e-4, 1e-2, 0.3, 3.0])
    forward, backward = traction_coefficient(u, **kw), traction_coefficient(-u, **kw)
    np.testing.assert_allclose(backward, -forward, rtol=1e-15)
    assert np.all(forward > 0.0)
    assert traction_coefficient(0.0, **kw) == 0.0
    result = fluid_traction(np.array([-0.3, 0.3]), **kw)
    assert result.shear_stress[0] == pytest.approx(-result.shear_stress[1], rel=1e-15)


def test_mu_increases_with_slip_when_isothermal():
    """Eyring asinh and the min with tau_L are monotone: the isothermal curve never falls."""
    S = np.linspace(0.0, 2.0, 401)
    r = traction_curve(S, entrainment_speed=2.0, p_h=1e9, film_thickness=0.3e-6, eta0=0.05,
                       log_viscosity_ratio=barus(), eyring_stress=5e6, limiting_shear_slope=0.075)
    assert np.all(np.diff(r.coefficient) >= 0.0)


@pytest.mark.parametrize("alpha_p", [60.0, 300.0, 2000.0])
def test_no_overflow_at_huge_piezoviscosity(alpha_p, no_runtime_warnings):
    """eta/eta0 = e^60 .. e^2000 (float64 overflows at e^709): the Eyring stress stays finite and equals
    its logarithmic form; no RuntimeWarning."""
    p_h, h, eta0, u_s, tau0 = 1e9, 0.3e-6, 0.05, 0.1, 5e6
    result = fluid_traction(u_s, p_h=p_h, film_thickness=h, eta0=eta0, log_viscosity_ratio=barus(alpha_p / p_h),
                            eyring_stress=tau0)
    assert np.isfinite(result.coefficient) and result.valid
    # asinh(x) > ln(2x) for x > 0: the logarithmic form is a lower bound, close except near the rim where
    # eta gamma/tau0 is small (3e-3 at the edge here)
    p_mean = MEAN_PRESSURE["line"] * p_h
    lower = tau0 * (math.log(2.0 * eta0 * u_s / h / tau0) + alpha_p / p_h * p_mean) / p_mean
    assert result.coefficient == pytest.approx(lower, rel=1e-3)
    assert result.coefficient >= lower


def test_newtonian_overflow_is_flagged_not_hidden(no_runtime_warnings):
    """A purely Newtonian film at alpha p = 800 has tau = inf: mu inf, valid False (no warning, no NaN)."""
    result = fluid_traction(0.1, p_h=1e9, film_thickness=0.3e-6, eta0=0.05, log_viscosity_ratio=barus(8e-7),
                            rheology="newtonian")
    assert math.isinf(result.coefficient) and not result.valid
    limited = fluid_traction(0.1, p_h=1e9, film_thickness=0.3e-6, eta0=0.05, log_viscosity_ratio=barus(8e-7),
                             rheology="newtonian", limiting_shear_slope=0.075)
    assert limited.valid and limited.coefficient == pytest.approx(0.075, rel=1e-12)


def test_regimes_follow_the_curve_linear_nonlinear_plateau():
    """Evans & Johnson's order along a slip sweep: linear at tiny slip, non-linear (eta gamma > tau0 over half
    the area), plateau (tau_L over half the area); 'open' where p_h = 0."""
    S = np.logspace(-7, 0.3, 60)
    r = traction_curve(S, entrainment_speed=2.0, p_h=0.8e9, film_thickness=0.2e-6, eta0=0.01,
                       log_viscosity_ratio=barus(), eyring_stress=5e6, limiting_shear_slope=0.075)
    order = {"linear": 0, "nonlinear": 1, "plateau": 2}
    codes = np.array([order[g] for g in r.regime])
    assert set(codes) == {0, 1, 2}
    assert np.all(np.diff(codes) >= 0)
    assert np.all(r.nonlinear_fraction[r.regime == "nonlinear"] >= 0.5)
    assert np.all(r.limited_fraction[r.regime == "plateau"] >= 0.5)
    newtonian = traction_curve(S, entrainment_speed=2.0, p_h=0.8e9, film_thickness=0.2e-6, eta0=0.01,
                               log_viscosity_ratio=barus(), rheology="newtonian", limiting_shear_slope=0.075)
    assert set(newtonian.regime) == {"linear", "plateau"} and np.all(newtonian.nonlinear_fraction == 0.0)
    opened = fluid_traction(np.array([0.1, 0.1]), p_h=np.array([0.0, 1e9]), film_thickness=0.3e-6, eta0=0.05,
                            log_viscosity_ratio=barus(), eyring_stress=5e6, limiting_shear_slope=0.075)
    assert list(opened.regime) == ["open", "nonlinear"]
    assert opened.coefficient[0] == 0.0 and opened.shear_stress[0] == 0.0 and opened.valid[0]


def test_limiting_shear_kink_costs_little_accuracy():
    """With tau_L cutting the Eyring stress inside the contact (a kink in tau(x)), 24 nodes agree with 192 to
    1e-4 (2e-5 here; 1e-12 where tau is smooth, the Newtonian test above)."""
    kw = dict(p_h=0.8e9, film_thickness=0.2e-6, eta0=0.01, log_viscosity_ratio=barus(), eyring_stress=5e6,
              limiting_shear_slope=0.075)
    assert traction_coefficient(1.0, **kw) == pytest.approx(traction_coefficient(1.0, n_nodes=192, **kw), rel=1e-4)


def test_vectorised_equals_scalar_calls_and_prepared_contact_broadcasts():
    rng = np.random.default_rng(3)
    p_h = rng.uniform(0.3e9, 1.5e9, 7)
    h = rng.uniform(0.1e-6, 1e-6, 7)
    u = rng.uniform(-2.0, 2.0, 7)
    kw = dict(eta0=0.05, log_viscosity_ratio=barus(), eyring_stress=5e6, limiting_shear_slope=0.075)
    vector = traction_coefficient(u, p_h=p_h, film_thickness=h, **kw)
    scalars = [traction_coefficient(u[i], p_h=p_h[i], film_thickness=h[i], **kw) for i in range(7)]
    np.testing.assert_allclose(vector, scalars, rtol=1e-13)
    assert isinstance(scalars[0], float)
    # contact per angle (A, 1) against a table of sliding speeds (A, K), as a roller solver uses it
    table = np.linspace(-1.0, 1.0, 5)[None, :] * np.abs(u)[:, None]
    contact = FluidTractionContact(p_h=p_h[:, None], film_thickness=h[:, None], **kw)
    mu = contact.coefficient(table)
    assert mu.shape == (7, 5)
    for i in range(7):
        np.testing.assert_allclose(mu[i], traction_coefficient(table[i], p_h=p_h[i], film_thickness=h[i], **kw),
                                   rtol=1e-13)
    full = contact.solve(table)
    np.testing.assert_allclose(full.coefficient, mu, rtol=1e-13)
    assert full.regime.shape == (7, 5)


# ------------------------------------------------------------------------------------- thermal
STEEL_EFFUSIVITY = math.sqrt(46.6 * 7850.0 * 475.0)  # k rho c of a bearing steel, order of magnitude only


def hertz_line(w=2.0e5, R=0.02, E_reduced=2.28e11):
    """(a, p_h) of a Hertz line contact: a = sqrt(8 w R/(pi E')), p_h = 2 w/(pi a) (Hamrock E')."""
    a = math.sqrt(8.0 * w * R / (math.pi * E_reduced))
    return a, 2.0 * w / (math.pi * a)


def thermal_case(**thermal_options):
    w, R, E = 2.0e5, 0.02, 2.28e11
    a, p_h = hertz_line(w, R, E)
    thermal = TractionThermal(0.13, 0.03, STEEL_EFFUSIVITY, STEEL_EFFUSIVITY, **thermal_options)
    kw = dict(p_h=p_h, film_thickness=0.3e-6, eta0=0.05, log_viscosity_ratio=barus(), eyring_stress=5e6,
              limiting_shear_slope=0.075, half_width=a)
    return (w, R, E, a, p_h), thermal, kw


def test_thermal_lowers_traction_and_the_plateau_falls_with_slip():
    _, thermal, kw = thermal_case()
    S = np.array([1e-4, 1e-3, 0.01, 0.03, 0.1, 0.3, 0.6, 1.0, 1.5, 1.9])
    hot = traction_curve(S, entrainment_speed=2.0, thermal=thermal, **kw)
    cold = traction_curve(S, entrainment_speed=2.0, **kw)
    assert np.all(hot.converged) and np.all(hot.valid)
    assert np.all(hot.coefficient <= cold.coefficient * (1.0 + 1e-12))
    assert np.all(hot.temperature_rise > 0.0) and np.all(np.diff(hot.temperature_rise) > 0.0)
    peak = int(np.argmax(hot.coefficient))
    assert 0 < peak < S.size - 1
    assert hot.coefficient[-1] < 0.95 * hot.coefficient[peak]  # falls by more than 5 % after its maximum
    assert np.all(np.diff(cold.coefficient) >= 0.0)  # while the isothermal curve does not fall
    # no heat, no change: beta = 0
    flat = TractionThermal(0.13, 0.0, STEEL_EFFUSIVITY, STEEL_EFFUSIVITY)
    np.testing.assert_allclose(traction_curve(S, entrainment_speed=2.0, thermal=flat, **kw).coefficient,
                               cold.coefficient, rtol=1e-14)


def test_thermal_balance_reuses_blok_and_closes():
    """At the converged point: flash = 2/3 flash_temperature(w, E', R, mu, u1, u2, e, e) of the same line
    contact (Blok, Delabenetta Eq. 48), film = tau_mean |u_s| h/(12 k), dT = flash + film, and mu is the
    traction at that dT."""
    (w, R, E, _, _), thermal, kw = thermal_case()
    u_m, S = 2.0, np.array([0.05, 0.5, 1.2])
    result = traction_curve(S, entrainment_speed=u_m, thermal=thermal, **kw)
    u_s = S * u_m
    for i in range(S.size):
        mu = result.coefficient[i]
        u1, u2 = u_m + u_s[i] / 2.0, u_m - u_s[i] / 2.0
        flash = 2.0 / 3.0 * flash_temperature(w, E, R, mu, u1, u2, STEEL_EFFUSIVITY, STEEL_EFFUSIVITY)
        film = abs(result.shear_stress[i] * u_s[i]) * kw["film_thickness"] / (12.0 * thermal.oil_conductivity)
        assert result.flash_temperature[i] == pytest.approx(flash, rel=1e-9)
        assert result.film_temperature_rise[i] == pytest.approx(film, rel=1e-9)
        assert result.temperature_rise[i] == pytest.approx(flash + film, abs=2 * thermal.tolerance)
        contact = FluidTractionContact(thermal=thermal, entrainment_speed=u_m, **kw)
        assert contact.coefficient(u_s[i], result.temperature_rise[i]) == pytest.approx(mu, rel=1e-12)


def test_point_flash_factor_is_the_strip_average():
    """Mean over the ellipse of band means ~ sqrt(a(y)), area-weighted by a(y): an independent quadrature."""
    num, _ = integrate.quad(lambda t: (1.0 - t * t) ** 0.75, -1.0, 1.0)
    den, _ = integrate.quad(lambda t: (1.0 - t * t) ** 0.5, -1.0, 1.0)
    assert POINT_FLASH_FACTOR == pytest.approx(num / den, rel=1e-10)


def test_thermal_reports_non_convergence_at_the_cap():
    _, thermal, kw = thermal_case(max_temperature_rise=1.0)
    result = traction_curve(np.array([0.001, 1.0]), entrainment_speed=2.0, thermal=thermal, **kw)
    assert result.converged[0] and result.valid[0]
    assert not result.converged[1] and not result.valid[1]
    assert result.temperature_rise[1] == 1.0


def test_thermal_point_contact_and_reversed_surface_converge():
    """Point geometry; S = 2.5 (one surface moves backwards: Blok's formula with the surface speeds'
    magnitudes); entrainment reversal u_m < 0."""
    _, thermal, kw = thermal_case()
    for geometry in ("line", "point"):
        r = fluid_traction(np.array([5.0, 1.0, -1.0]), entrainment_speed=np.array([2.0, -2.0, -2.0]),
                           thermal=thermal, geometry=geometry, **kw)
        assert np.all(r.converged) and np.all(np.isfinite(r.coefficient))
        assert r.coefficient[1] == pytest.approx(-r.coefficient[2], rel=1e-12)


# ------------------------------------------------------------------------------------- inputs
@pytest.mark.parametrize("change, field", [
    ({"film_thickness": 0.0}, "film_thickness"),
    ({"film_thickness": np.nan}, "film_thickness"),
    ({"p_h": -1.0}, "p_h"),
    ({"eta0": 0.0}, "eta0"),
    ({"eyring_stress": None}, "eyring_stress"),
    ({"eyring_stress": -1.0}, "eyring_stress"),
    ({"limiting_shear_slope": -0.1}, "limiting_shear_slope"),
    ({"limiting_shear_stress": -1.0, "limiting_shear_slope": 0.07}, "limiting_shear_stress"),
    ({"rheology": "bingham"}, "rheology"),
    ({"geometry": "conformal"}, "geometry"),
    ({"n_nodes": 2}, "n_nodes"),
    ({"log_viscosity_ratio": 3.0}, "log_viscosity_ratio"),
    ({"log_viscosity_ratio": lambda p: np.full(np.shape(p), np.nan)}, "log_viscosity_ratio"),
    ({"thermal": TractionThermal(0.13, 0.03, 1e4, 1e4)}, "half_width"),
    ({"thermal": "hot"}, "thermal"),
])
def test_bad_inputs_name_the_field(change, field):
    kw = dict(p_h=1e9, film_thickness=0.3e-6, eta0=0.05, log_viscosity_ratio=barus(), eyring_stress=5e6)
    kw.update(change)
    with pytest.raises(InputError, match=field):
        fluid_traction(0.1, **kw)


def test_bad_sliding_speed_and_thermal_data_name_the_field():
    kw = dict(p_h=1e9, film_thickness=0.3e-6, eta0=0.05, log_viscosity_ratio=barus(), eyring_stress=5e6)
    with pytest.raises(InputError, match="sliding_speed"):
        fluid_traction(np.inf, **kw)
    with pytest.raises(InputError, match="broadcast"):
        FluidTractionContact(**{**kw, "p_h": np.ones(3) * 1e9}).coefficient(np.ones(4))
    for field, values in (("oil_conductivity", (0.0, 0.03, 1e4, 1e4)),
                          ("thermoviscous_coefficient", (0.1, -1, 1e4, 1e4)),
                          ("effusivity_2", (0.1, 0.03, 1e4, np.nan))):
        with pytest.raises(InputError, match=field):
            TractionThermal(*values)
    with pytest.raises(InputError, match="max_iterations"):
        TractionThermal(0.1, 0.03, 1e4, 1e4, max_iterations=0)
    isothermal_oil = cc.Lubricant(eta0="0.05 Pa*s", alpha="2e-8 1/Pa").at(None)
    with pytest.raises(InputError, match="thermal_conductivity"):
        TractionThermal.from_lubricant_state(isothermal_oil, 1e4)


# ------------------------------------------------------------------------------------- models
@pytest.fixture
def oil_state():
    """A mineral oil with temperature data (walther fit) and conductivity: eta0 and beta at 60 degC."""
    oil = cc.Lubricant(nu40="100 cSt", nu100="11 cSt", density="870 kg/m^3", alpha="2.0e-8 1/Pa",
                       thermal_conductivity="0.13 W/(m K)", name="ISO VG 100")
    return oil.at("60 degC")


def model_state(oil_state, **changes):
    state = {"normal_force": np.array([800.0, 800.0, 0.0, 800.0]), "p_h": np.array([1.0e9, 1.0e9, 0.0, 1.0e9]),
             "b": np.array([2e-4, 2e-4, 0.0, 2e-4]), "h_c": np.array([0.3e-6, 0.3e-6, 0.3e-6, np.nan]),
             "u_s": np.array([0.05, -1.0, 0.1, 0.1]), "u_m": 2.0, "lubricant_state": oil_state}
    state.update(changes)
    return state


def test_models_are_registered_with_sourced_defaults():
    assert {"newtonian", "eyring"} <= set(registry.available("traction_models"))
    eyring = registry.get("traction_models", "eyring")
    assert isinstance(eyring, EyringTraction) and isinstance(registry.get("traction_models", "newtonian"),
                                                             NewtonianTraction)
    assert eyring.eyring_stress == EYRING_STRESS == 5e6 and eyring.limiting_shear_slope == LIMITING_SHEAR_SLOPE
    assert "Johnson & Tevaarwerk (1977)" in eyring.reference and "Bair & Winer (1979)" in eyring.reference
    assert {"traction_coefficient", "traction_force", "traction_valid", "traction_regime",
            "traction_temperature_rise"} <= set(eyring.provides)


def test_model_evaluates_the_physics_and_reports_gaps(oil_state):
    model = registry.get("traction_models", "eyring")
    out = model(model_state(oil_state))
    direct = traction_coefficient(np.array([0.05, -1.0]), p_h=1e9, film_thickness=0.3e-6, eta0=oil_state.eta0,
                                  log_viscosity_ratio=oil_state.log_viscosity_ratio, eyring_stress=5e6,
                                  limiting_shear_slope=LIMITING_SHEAR_SLOPE)
    np.testing.assert_allclose(out["traction_coefficient"][:2], direct, rtol=1e-14)
    np.testing.assert_allclose(out["traction_force"][:2], 800.0 * direct, rtol=1e-14)
    # 1 m/s of slide at 1 GPa reaches the limiting shear stress (Lambda_L 0.047 p): plateau; 0.05 m/s does not
    assert list(out["traction_regime"]) == ["nonlinear", "plateau", "open", "no film"]
    assert list(out["traction_valid"]) == [True, True, True, False]
    assert out["traction_coefficient"][2] == 0.0 and math.isnan(out["traction_coefficient"][3])
    np.testing.assert_array_equal(out["traction_temperature_rise"][:3], 0.0)
    low_limit = EyringTraction(limiting_shear_slope=0.03)(model_state(oil_state))
    assert low_limit["traction_regime"][1] == "plateau"
    scalar = model(model_state(oil_state, normal_force=800.0, p_h=1e9, b=2e-4, h_c=0.3e-6, u_s=0.05))
    assert isinstance(scalar["traction_coefficient"], float) and scalar["traction_regime"] == "nonlinear"
    assert scalar["traction_coefficient"] == pytest.approx(direct[0], rel=1e-14)


def test_thermal_model_uses_the_lubricant_and_the_effusivity(oil_state):
    hot = EyringTraction(thermal=True)
    with pytest.raises(InputError, match="effusivity"):
        hot(model_state(oil_state))
    out = hot({**model_state(oil_state), "effusivity": (STEEL_EFFUSIVITY, STEEL_EFFUSIVITY)})
    cold = EyringTraction()(model_state(oil_state))
    assert np.all(out["traction_temperature_rise"][:2] > 0.0)
    assert abs(out["traction_coefficient"][1]) < abs(cold["traction_coefficient"][1])
    same = EyringTraction(thermal=True, effusivity_1=STEEL_EFFUSIVITY)(model_state(oil_state))
    np.testing.assert_allclose(same["traction_coefficient"][:3], out["traction_coefficient"][:3], rtol=1e-12)
    isothermal_oil = cc.Lubricant(eta0="0.05 Pa*s", alpha="2e-8 1/Pa").at(None)
    with pytest.raises(InputError, match="thermal_conductivity"):
        hot(model_state(isothermal_oil, effusivity=STEEL_EFFUSIVITY))


def test_model_contact_and_curve_for_a_roller_table(oil_state):
    model = NewtonianTraction(limiting_shear_slope=0.07)
    contact = model.contact(p_h=np.array([[0.8e9], [1.2e9]]), b=2e-4, h_c=0.3e-6, u_m=2.0, lubricant_state=oil_state)
    table = np.array([[-0.1, 0.0, 0.1], [-0.2, 0.0, 0.2]])
    mu = contact.coefficient(table)
    assert mu.shape == (2, 3) and mu[0, 1] == 0.0 and mu[1, 0] == pytest.approx(-mu[1, 2], rel=1e-14)
    curve = EyringTraction(limiting_shear_slope=0.03).curve(np.logspace(-6, 0.3, 25), p_h=1e9, b=2e-4, h_c=0.3e-6,
                                                            u_m=2.0, lubricant_state=oil_state)
    assert list(dict.fromkeys(curve.regime)) == ["linear", "nonlinear", "plateau"]


@pytest.mark.parametrize("options, field", [
    ({"eyring_stress": 0.0}, "eyring_stress"),
    ({"limiting_shear_slope": -0.1}, "limiting_shear_slope"),
    ({"limiting_shear_stress": -1.0}, "limiting_shear_stress"),
    ({"geometry": "conformal"}, "geometry"),
    ({"thermal": "yes"}, "thermal"),
    ({"n_nodes": 2}, "n_nodes"),
    ({"effusivity_1": -5.0}, "effusivity_1"),
])
def test_model_parameters_are_validated(options, field):
    with pytest.raises(InputError, match=field):
        EyringTraction(**options)


def test_model_rejects_negative_loads(oil_state):
    with pytest.raises(InputError, match="normal_force"):
        EyringTraction()(model_state(oil_state, normal_force=-1.0))
