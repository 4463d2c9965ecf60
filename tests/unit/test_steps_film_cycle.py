"""Film-over-the-cycle step functions (camcontact.steps.film_cycle) called alone, with plain SI arrays.

Expected values: Hamrock/Moes groups per angle and Tsuha (2015) Table 6.3 (M, L in the thesis's
mean-speed convention); the Pan–Hamrock (1989) formula written out here; for the numerical film a direct
steady solve of the same multigrid model (coarse, ``levels=5``) and the Hertz scaling H = h R/b^2 of its
dimensionless films; a transient march through a constant state has no squeeze, so it equals the steady
film.
"""

import math

import attrs
from types import SimpleNamespace

import numpy as np
import pytest

import camcontact as cc
from camcontact import registry
from camcontact.errors import InputError
from camcontact.steps.film_cycle import (
    STEADY_M_LIMIT,
    check_squeeze,
    cycle_ehl_groups,
    numerical_film_details,
    quasi_steady_films,
    thermal_transient_films,
    transient_films,
)
from step_checks import assert_provides

E_STEEL = 210e9 / (1 - 0.3**2)
OIL = cc.Lubricant(name="Tsuha 2015", alpha="2.2e-8 1/Pa", roelands_z=0.68)
STATE = OIL.state(None)  # eta0 = 0.0358352 Pa s (Roelands consistency)


def pan_hamrock(w, R, u, eta=STATE.eta0, alpha=STATE.alpha, E=E_STEEL):
    """Pan & Hamrock (1989): (h_c, h_min) [m] with U = eta u/(E' R), G = alpha E', W = w/(E' R)."""
    U, G, W = eta * u / (E * R), alpha * E, w / (E * R)
    return 2.922 * W**-0.166 * U**0.692 * G**0.470 * R, 1.714 * W**-0.128 * U**0.694 * G**0.568 * R


def _groups(w, R, u, factor=1.0, piezo=True):
    return cycle_ehl_groups(w, R, E_STEEL, u, STATE.eta0, STATE.alpha, piezo, factor)


def _quasi(model, w, R, u, open_=None, factor=1.0):
    g = _groups(w, R, u, factor)
    open_ = np.zeros(w.size, bool) if open_ is None else open_
    return quasi_steady_films(model, w, R, E_STEEL, u, STATE.eta0, g["alpha_effective"], g["U"], g["G"], g["W"],
                              g["M"], g["L"], STATE, "incompressible", open_, factor)


# ----------------------------------------------------------------------------- cycle_ehl_groups
def test_cycle_ehl_groups_tsuha_table_6_3_and_special_angles():
    """Thesis factor 0.5 on u_m: Table 6.3 at 0 deg (1000 N, R 8 mm, u_m 4.18879 m/s) M = 4.005, L = 15.245
    and at 90 deg (3087.99 N, 7.69892 mm, 3.5037 m/s) M = 13.784, L = 14.720 (15 mm cam); a loaded contact
    without entrainment has M = inf (G = alpha E'), an unloaded one M = 0, U = W = 0."""
    w = np.array([1000.0, 3087.99, 2000.0, 0.0]) / 0.015
    R = np.array([0.008, 0.00769892, 0.009, 0.009])
    u = np.array([4.1887902, 3.5036962, 0.0, 3.0])
    out = _groups(w, R, u, factor=0.5)
    assert_provides(cycle_ehl_groups, out)
    assert out["M"][:2] == pytest.approx([4.005, 13.784], abs=0.002)
    assert out["L"][:2] == pytest.approx([15.245, 14.720], abs=0.002)
    U = STATE.eta0 * 0.5 * u[0] / (E_STEEL * R[0])
    assert out["U"][0] == pytest.approx(U, rel=1e-12)
    assert out["W"][0] == pytest.approx(w[0] / (E_STEEL * R[0]), rel=1e-12)
    assert out["M"][2] == math.inf and out["G"][2] == pytest.approx(STATE.alpha * E_STEEL)
    assert out["M"][3] == 0.0 and out["U"][3] == 0.0 and out["W"][3] == 0.0
    off = _groups(w, R, u, piezo=False)
    assert off["alpha_effective"] == 0.0 and np.all(off["L"] == 0.0) and np.all(off["G"] == 0.0)


# ----------------------------------------------------------------------------- quasi_steady_films
def test_quasi_steady_films_formula_per_angle_with_lost_contact_and_rest():
    """Pan–Hamrock at |u_m| x factor per angle (formula by hand); a jump (contact open) gives NaN and says
    so; u_m = 0 gives no steady film (0, with the reason); no numerical solutions are kept."""
    w = np.array([1.5e5, 2.0e5, 1.0e5, 1.0e5])
    R = np.array([0.010, 0.008, 0.012, 0.012])
    u = np.array([2.0, 3.0, 1.0, 0.0])
    open_ = np.array([False, False, True, False])
    out = _quasi(registry.get("film_models", "pan_hamrock"), w, R, u, open_, factor=0.5)
    assert_provides(quasi_steady_films, out)
    for i in (0, 1):
        h_c, h_min = pan_hamrock(w[i], R[i], 0.5 * u[i])
        assert out["h_c"][i] == pytest.approx(h_c, rel=1e-12) and out["h_min"][i] == pytest.approx(h_min, rel=1e-12)
        assert out["film_regime"][i] == "ok"
    assert math.isnan(out["h_min"][2]) and out["film_regime"][2] == "contact lost (jump): no film"
    assert out["h_min"][3] == 0.0 and out["film_regime"][3].startswith("u_m = 0: no steady film")
    assert out["film_solutions"] == [None] * 4


def test_quasi_steady_films_flags_an_entrainment_reversal():
    """u_m changes sign between the 2nd and 3rd angle: both bracketing angles say 'entrainment reversal';
    the film uses |u_m| (same film at +-1 m/s)."""
    w, R = np.full(4, 1.5e5), np.full(4, 0.01)
    out = _quasi(registry.get("film_models", "pan_hamrock"), w, R, np.array([2.0, 1.0, -1.0, -2.0]))
    regimes = list(out["film_regime"])
    assert regimes[0] == "ok" and regimes[3] == "ok"
    assert all(r.startswith("u_m ≈ 0: entrainment reversal") for r in regimes[1:3])
    assert out["h_c"][1] == out["h_c"][2] == pytest.approx(pan_hamrock(1.5e5, 0.01, 1.0)[0], rel=1e-12)


def test_quasi_steady_films_numerical_with_fallback():
    """Multigrid (levels = 5): each angle equals a direct steady solve of the same model (rel 1e-6: warm
    start vs cold start, both converged); at u_m = 1e-5 m/s M exceeds the steady limit 2000 and the angle
    falls back to the Pan–Hamrock formula (by hand) with the reason."""
    model = registry.get("film_models", "multigrid", levels=5)
    w = np.array([1.5e5, 2.0e5, 1.5e5])
    R = np.array([0.010, 0.009, 0.010])
    u = np.array([2.0, 1.5, 1e-5])
    out = _quasi(model, w, R, u)
    assert _groups(w, R, u)["M"][2] > STEADY_M_LIMIT
    for i in (0, 1):
        steady = model({"R": R[i], "w": w[i], "E_reduced": E_STEEL, "u_m": u[i], "eta0": STATE.eta0,
                        "alpha": STATE.alpha, "lubricant_state": STATE, "density_law": "incompressible"})
        assert out["h_c"][i] == pytest.approx(steady["h_c"], rel=1e-6)
        assert out["h_min"][i] == pytest.approx(steady["h_min"], rel=1e-6)
        assert out["film_regime"][i] == "ok" and out["film_solutions"][i] is not None
    h_c, h_min = pan_hamrock(w[2], R[2], u[2])
    assert out["h_min"][2] == pytest.approx(h_min, rel=1e-12) and out["h_c"][2] == pytest.approx(h_c, rel=1e-12)
    assert out["film_solutions"][2] is None
    assert "Pan–Hamrock formula" in out["film_regime"][2] and "M = " in out["film_regime"][2]


# ----------------------------------------------------------------------------- transient_films
def _transient(model, w, R, u, open_=None, omega=None, theta=None):
    n = w.size
    theta = np.linspace(0, 2 * math.pi, n, endpoint=False) if theta is None else theta
    omega = np.full(n, 10.0) if omega is None else omega
    open_ = np.zeros(n, bool) if open_ is None else open_
    return transient_films(model, w, R, E_STEEL, u, STATE.eta0, STATE.alpha, STATE, "incompressible", open_, 1.0,
                           True, theta, omega)


def test_transient_films_constant_state_equals_the_steady_film():
    """Constant load, radius and speed over 8 angles: no squeeze term, so the transient film at every angle is
    the steady multigrid film of the same model (levels = 5; rel 1e-5), on the model's domain if it gives one and
    by default on the same automatic domain: the march's inlet (march_inlet) is the steady automatic domain's, here
    -8 (H_c 0.33). At level 8 the film there is 1.3 % thicker than on [-4, 1.5], as Grubin's inlet tail says (0.8 of
    T(-4) - T(-8) = 1.5 %)."""
    from camcontact.ehl.line_domain import inlet_tail_fraction

    n = 8
    inputs = {"R": 0.01, "w": 1.5e5, "E_reduced": E_STEEL, "u_m": 2.0, "eta0": STATE.eta0, "alpha": STATE.alpha,
              "lubricant_state": STATE, "density_law": "incompressible"}
    for domain in ((-4.0, 1.5), None):
        model = registry.get("film_models", "multigrid", levels=5, domain=domain)
        out = _transient(model, np.full(n, 1.5e5), np.full(n, 0.01), np.full(n, 2.0))
        assert_provides(transient_films, out)
        steady = model(inputs)
        np.testing.assert_allclose(out["h_c"], steady["h_c"], rtol=1e-5)
        np.testing.assert_allclose(out["h_min"], steady["h_min"], rtol=1e-5)
        assert set(out["film_regime"]) == {"transient (squeeze)"}
    longer = registry.get("film_models", "multigrid", levels=8)(inputs)
    cut = registry.get("film_models", "multigrid", levels=8, domain=(-4.0, 1.5))(inputs)
    X_a, H_c = longer["ehl_solution"].problem.domain[0], longer["ehl_solution"].H_c
    assert X_a == pytest.approx(-8.0)
    tail = inlet_tail_fraction(-4.0, H_c) - inlet_tail_fraction(X_a, H_c)
    assert longer["h_c"] / cut["h_c"] - 1.0 == pytest.approx(0.8 * tail, rel=0.25)


def test_transient_films_refuses_lost_contact_and_varying_speed():
    """The transient needs contact at every angle and one cam speed; its check needs the multigrid model."""
    model = registry.get("film_models", "multigrid", levels=5)
    w, R, u = np.full(4, 1.5e5), np.full(4, 0.01), np.full(4, 2.0)
    with pytest.raises(InputError, match="needs contact at every angle"):
        _transient(model, w, R, u, open_=np.array([False, True, False, False]))
    with pytest.raises(InputError, match="constant cam speed"):
        _transient(model, w, R, u, omega=np.array([10.0, 11.0, 12.0, 13.0]))
    assert transient_films.step.check is check_squeeze
    with pytest.raises(InputError, match="'squeeze' effect"):
        check_squeeze(registry.get("film_models", "pan_hamrock"))
    assert check_squeeze(model) is None


def test_thermal_transient_films_settle_on_the_steady_thermal_film():
    """Constant load, radius and rolling surface speeds (2 m/s) over 12 angles: the march's first film is the
    isothermal steady one (its start; film_regime says so), and with the lagged energy coupling the films settle
    on the steady thermal solution of the same contact (solve_thermal; last angle within 1e-4) with its film
    temperature rise (1.66 K: rolling heats only through the inlet's back-flow shear); the step's outputs are
    complete. (With sliding and a Newtonian film without limiting shear stress the rise runs to 100-300 K: the
    scenes bound the film by the traction model's limiting shear stress, with_traction_rheology.) The model's domain
    [-4, 1.5] is the march's (units of its reference half-width) and the steady solve's."""
    from camcontact.ehl.line_thermal import solve_thermal

    oil = cc.Lubricant(name="Tsuha 2015", alpha="2.2e-8 1/Pa", roelands_z=0.68, thermal_conductivity="0.14 W/(m*K)",
                       thermoviscous_coefficient="0.03 1/K", specific_heat="2000 J/(kg*K)", density="870 kg/m^3")
    state = oil.state(None)
    model = attrs.evolve(registry.get("film_models", "multigrid", levels=5, domain=(-4.0, 1.5)), thermal=True)
    n, w, R, u1, u2 = 12, 1.5e5, 0.01, 2.0, 2.0
    effusivity = (12900.0, 12900.0)
    out = thermal_transient_films(model, np.full(n, w), np.full(n, R), E_STEEL, np.full(n, u1), np.full(n, u2),
                                  state.eta0, state.alpha, state, "incompressible", np.zeros(n, bool), 1.0, True,
                                  np.linspace(0, 2 * math.pi, n, endpoint=False), np.full(n, 10.0),
                                  effusivity=effusivity)
    assert_provides(thermal_transient_films, out)
    problem = model.problem(R, w, E_STEEL, 0.5 * (u1 + u2), state.eta0, state.alpha, state, "incompressible")
    contact = model.thermal_contact(problem, R, w, E_STEEL, u1, u2, state.eta0, state.alpha, state, effusivity)
    steady = solve_thermal(contact, 5, tolerance=1e-8)
    start = int(np.flatnonzero([r.endswith("the march's start") for r in out["film_regime"]])[0])
    assert out["h_c"][start] == pytest.approx(steady.isothermal.H_c * steady.scales["h_scale"], rel=1e-4)
    last = (start - 1) % n  # the march goes round from its start
    assert out["h_c"][last] == pytest.approx(steady.h_c, rel=1e-4)
    assert out["h_c"][last] < out["h_c"][start]  # the heated film is thinner
    assert out["film_temperature_rise"][last] == pytest.approx(steady.max_temperature_rise, rel=1e-3)
    assert out["film_valid"].all()


# ----------------------------------------------------------------------------- numerical_film_details
def test_numerical_film_details_bookkeeping():
    """Per angle the solution's H0, H_min, H_c and spike height; 0 where there is no solution, NaN spike
    where the solution has no distinct spike; all None (a formula film): InputError."""
    spiky = SimpleNamespace(H0=-0.3, H_min=0.2, H_c=0.3, spike=(1.4, 0.9))
    flat = SimpleNamespace(H0=-0.5, H_min=0.4, H_c=0.45, spike=None)
    out = numerical_film_details([spiky, None, flat])
    assert_provides(numerical_film_details, out)
    np.testing.assert_array_equal(out["H0"], [-0.3, 0.0, -0.5])
    np.testing.assert_array_equal(out["H_min"], [0.2, 0.0, 0.4])
    np.testing.assert_array_equal(out["H_c"], [0.3, 0.0, 0.45])
    assert out["spike_pressure"][0] == 1.4 and out["spike_pressure"][1] == 0.0 and math.isnan(out["spike_pressure"][2])
    assert list(out["pressure_spike"]) == [True, True, False]  # the NaN's reason beside it
    with pytest.raises(InputError, match="use the film model 'multigrid'"):
        numerical_film_details([None, None])


def test_numerical_film_details_of_a_real_solution_scale_with_hertz():
    """H = h R/b^2 with the Hertz half-width b = sqrt(8 w R/(pi E')): the details of a multigrid
    quasi-steady film give back its dimensional h_min and h_c (rel 1e-9)."""
    model = registry.get("film_models", "multigrid", levels=5)
    w, R, u = np.array([1.5e5]), np.array([0.01]), np.array([2.0])
    films = _quasi(model, w, R, u)
    out = numerical_film_details(films["film_solutions"])
    b2 = 8 * w[0] * R[0] / (math.pi * E_STEEL)
    assert out["H_min"][0] * b2 / R[0] == pytest.approx(films["h_min"][0], rel=1e-9)
    assert out["H_c"][0] * b2 / R[0] == pytest.approx(films["h_c"][0], rel=1e-9)
    assert out["H0"][0] < 0.0 < out["H_min"][0] < out["H_c"][0]


def test_cycle_inlet_thermal_per_angle_with_reversal():
    from camcontact.steps.film_cycle import cycle_inlet_thermal

    u_cam, u_follower = np.array([4.0, 2.0, 1.0]), np.array([4.0, -1.0, -1.0])
    out = cycle_inlet_thermal("wilson_sheu", u_cam, u_follower, 0.03, 0.04, 0.13, np.full(3, 1e9), 2.2e11)
    assert_provides(cycle_inlet_thermal, out)
    L = 0.03 * 0.04 * ((u_cam + u_follower) / 2) ** 2 / 0.13
    np.testing.assert_allclose(out["thermal_loading_m"], L, rtol=1e-12)
    Z = np.abs(u_cam - u_follower)[:2] / np.abs(u_cam + u_follower)[:2]
    assert out["thermal_factor"][0] == pytest.approx(1 / (1 + 0.241 * L[0] ** 0.64), rel=1e-12)
    assert out["thermal_factor"][1] == pytest.approx(1 / (1 + 0.241 * (1 + 14.8 * Z[1] ** 0.83) * L[1] ** 0.64))
    assert out["thermal_factor"][2] == 1.0  # u1 + u2 = 0: no entrainment, no inlet heating
    np.testing.assert_array_equal(out["thermal_valid"], [True, False, False])  # Z = 0, 3, inf


def test_a_reversing_march_takes_the_model_domain_symmetric():
    """The film model's domain is the march's as given while the entrainment keeps its direction; through a reversal
    either end becomes the inlet, so it is made symmetric ([-4, 1.5] -> [-4, 4]); None leaves the march its own."""
    from camcontact.steps.film_cycle import march_domain

    model = registry.get("film_models", "multigrid", levels=5, domain=(-4.0, 1.5))
    assert march_domain(model, np.array([1.0, 2.0, 0.0])) == (-4.0, 1.5)
    assert march_domain(model, np.array([1.0, -2.0])) == (-4.0, 4.0)
    assert march_domain(registry.get("film_models", "multigrid", levels=5), np.array([1.0, -2.0])) is None
