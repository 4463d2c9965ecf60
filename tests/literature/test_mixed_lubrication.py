"""Mixed lubrication by load sharing (camcontact.models.mixed_lubrication) against its sources.

Sources and what is checked (tolerances per test):
* Johnson, Greenwood & Poon (1972) Wear 19:91–108 — load split W/gamma_1 + W/gamma_2 = W with
  1/gamma_1 + 1/gamma_2 = 1; the film of the fluid share is the smooth film at load W/gamma_1 and
  modulus E'/gamma_1; the asperities carry the Greenwood–Tripp pressure over the Hertz area; the
  limits (fast: asperity share -> 0 and film -> smooth formula; slow: asperity share -> 1).
* Gelinck & Schipper (2000) Tribol. Int. 33:175–181 — the same with Moes's line-contact film and
  mu = mu_b W_C/W + F_fluid/W (Stribeck curve shape).
* Greenwood & Tripp (1970–71) Proc. IMechE 185:625–633, F_5/2 — the engineering power fit
  F_5/2(lam) = 4.4086e-5 (4 - lam)^6.804 (lam < 4), usually attributed to Hu, Cheng, Arai,
  Kobayashi & Aoyama (1994) J. Tribol. 116:470–478 and printed with 5 significant digits in the
  coefficient and 4 in the exponent; it was found reproduced in public piston-ring and bearing
  codes, not read in the paper itself. The fit's own accuracy is not stated where it is printed.

Not available: no published *measured* Stribeck curve with its test conditions and surface
parameters (Lu, Khonsari & Gelinck 2006 J. Tribol. 128:789; Gelinck & Schipper 2000; Akchurin et
al. 2015 Tribol. Lett. 59:19) could be read in the search corpora (only abstracts). No comparison
with measurements is made here; nothing below is digitised from a figure.
"""

import math

import numpy as np
import pytest

from camcontact.contact.asperity_contact import (
    asperity_pressure,
    greenwood_tripp_coefficient,
    greenwood_tripp_integral,
)
from camcontact.errors import InputError
from camcontact.models.film_line import Moes
from camcontact.models.film_point import Nijenbanning
from camcontact.models.mixed_lubrication import (
    BOUNDARY_ASPERITY_FRACTION,
    MIXED_REGIMES,
    mixed_friction_coefficient,
    mixed_line_contact,
    mixed_point_contact,
    mixed_regime,
    stribeck_curve_line,
    stribeck_curve_point,
)

E_RED = 2.3077e11  # Hamrock's E' of steel on steel (210 GPa, nu = 0.3)
SIGMA = 0.2e-6  # composite RMS roughness [m]
BETA = SIGMA / 0.05  # asperity radius 4 um: sigma/beta = 0.05
ETA = 0.05 / (BETA * SIGMA)  # eta beta sigma = 0.05
LINE = {"w": 1e4, "R": 0.01, "E_reduced": E_RED, "eta0": 0.05, "alpha": 2e-8, "sigma": SIGMA,
        "asperity_density": ETA, "asperity_radius": BETA}
SPEEDS = np.concatenate([[0.0], np.logspace(-8, 1.5, 39)])


def line(u_m, **changes):
    return mixed_line_contact(u_m=u_m, **{**LINE, **changes})


def test_printed_power_fit_of_f_five_halves():
    """The printed fit 4.4086e-5 (4 - lam)^6.804 lies within 6 % of the exact F_5/2 for
    0.75 <= lam <= 1.75 (its best range) and 10 % for 0.5 <= lam <= 2; beyond lam = 2 it falls
    away (-35 % at 2.5, -74 % at 3): the fit, not the integral, is the approximation."""
    lam = np.linspace(0.5, 2.0, 31)
    fit = 4.4086e-5 * (4.0 - lam) ** 6.804
    exact = greenwood_tripp_integral(2.5, lam)
    assert np.max(np.abs(fit / exact - 1.0)) < 0.10
    core = (lam >= 0.75) & (lam <= 1.75)
    assert np.max(np.abs(fit[core] / exact[core] - 1.0)) < 0.06
    assert 4.4086e-5 * 1.5**6.804 / greenwood_tripp_integral(2.5, 2.5) == pytest.approx(0.654, abs=0.01)


def test_load_split_and_gamma_relation():
    """1/gamma_1 + 1/gamma_2 = 1 and W_H + W_C = W at every speed (to rounding)."""
    r = line(SPEEDS)
    with np.errstate(divide="ignore"):
        np.testing.assert_allclose(1.0 / r["gamma1"] + 1.0 / r["gamma2"], 1.0, rtol=1e-12)
    np.testing.assert_allclose(r["fluid_load"] + r["asperity_load"], LINE["w"], rtol=1e-12)
    np.testing.assert_allclose(r["asperity_load_fraction"] + r["fluid_load_fraction"], 1.0, rtol=1e-12)


def test_solution_satisfies_both_jgp_equations():
    """h_c is Moes's film at (w/gamma_1, E'/gamma_1), and W_C = 2 b K (E'/2) F_5/2(h_c/sigma)."""
    speeds = np.logspace(-5, 0.5, 12)
    r = line(speeds)
    phi = r["fluid_load_fraction"]
    film = Moes().evaluate(LINE["R"], LINE["w"] * phi, E_RED * phi, speeds, LINE["eta0"], LINE["alpha"])["h_c"]
    np.testing.assert_allclose(r["h_c"], film, rtol=1e-9)
    b = math.sqrt(8 * LINE["w"] * LINE["R"] / (math.pi * E_RED))
    K = greenwood_tripp_coefficient(SIGMA, ETA, BETA)
    carried = 2 * b * K * 0.5 * E_RED * greenwood_tripp_integral(2.5, r["h_c"] / SIGMA)
    np.testing.assert_allclose(r["asperity_load"], carried, rtol=1e-9)
    np.testing.assert_allclose(r["hertz_half_width"], b, rtol=1e-14)


def test_fast_limit_is_the_smooth_full_film():
    """Fast: asperity share -> 0 (< 1e-10 at Lambda > 6) and h_c -> the smooth Moes film (1e-9)."""
    speeds = np.array([3.0, 10.0, 30.0])
    r = line(speeds)
    assert np.all(r["asperity_load_fraction"] < 1e-10)
    smooth = Moes().evaluate(LINE["R"], LINE["w"], E_RED, speeds, LINE["eta0"], LINE["alpha"])["h_c"]
    np.testing.assert_allclose(r["h_c"], smooth, rtol=1e-9)
    np.testing.assert_allclose(r["h_c_smooth"], smooth, rtol=1e-14)
    assert list(r["regime"]) == ["full_film"] * 3


def test_slow_limit_is_boundary_lubrication():
    """Slow: asperity share -> 1 and h_c -> the separation at which the asperities alone carry w;
    u_m = 0 is that limit (asperity capacity here 1.25 > 1)."""
    r = line(np.array([0.0, 1e-8, 1e-6]))
    assert r["asperity_capacity"][0] == pytest.approx(1.2517, rel=1e-3)
    assert r["asperity_load_fraction"][0] == 1.0
    assert r["asperity_load_fraction"][1] > 1 - 1e-6
    assert r["asperity_load_fraction"][2] > 1 - 1e-4
    b = r["hertz_half_width"][0]
    alone = 2 * b * asperity_pressure(r["h_c"][0], SIGMA, ETA, BETA, E_RED)
    assert alone == pytest.approx(LINE["w"], rel=1e-10)
    np.testing.assert_allclose(r["h_c"][1:], r["h_c"][0], rtol=1e-3)
    assert list(r["regime"]) == ["boundary"] * 3


def test_asperity_share_falls_and_film_rises_with_speed():
    r = line(SPEEDS[1:])
    assert np.all(np.diff(r["asperity_load_fraction"]) <= 0.0)
    assert np.all(np.diff(r["h_c"]) >= 0.0)
    assert np.all(r["h_c"] >= r["h_c_smooth"] * (1 - 1e-9))  # unloading the fluid never thins the film
    assert np.all(np.isfinite(r["real_area_fraction"])) and np.all(r["real_area_fraction"] < 0.02)


def test_soft_asperities_cannot_reach_boundary_and_say_so():
    """sigma/beta = 1e-3 and eta beta sigma = 0.04 (piston-ring-like values) under a 0.7 GPa line
    contact: the asperities carry at most 2.5 % of the load at h = 0 (asperity_capacity), so the
    slow limit saturates there instead of reaching 1; the result reports the capacity."""
    beta = SIGMA / 1e-3
    r = line(np.array([0.0, 1e-6, 1e-2]), w=2e5, asperity_radius=beta, asperity_density=0.04 / (beta * SIGMA))
    capacity = r["asperity_capacity"][0]
    assert capacity == pytest.approx(0.0253, rel=0.01)
    assert r["asperity_load_fraction"][0] == pytest.approx(capacity, rel=1e-12)
    assert r["asperity_load_fraction"][1] == pytest.approx(capacity, rel=2e-3)
    assert r["h_c"][0] == 0.0


def test_point_contact_limits_and_split():
    F, Rx, Ry = 20.0, 0.05, 0.1  # mean Hertz pressure ~0.15 GPa: asperity capacity > 1
    speeds = np.array([0.0, 1e-6, 1e-2, 0.3, 10.0])
    r = mixed_point_contact(F, Rx, Ry, E_RED, speeds, 0.05, 2e-8, SIGMA, ETA, BETA)
    assert r["asperity_capacity"][0] > 1.0
    assert r["asperity_load_fraction"][0] == 1.0 and r["asperity_load_fraction"][1] > 1 - 1e-4
    assert r["asperity_load_fraction"][-1] < 1e-10
    assert np.all(np.diff(r["asperity_load_fraction"]) <= 0.0)
    smooth = Nijenbanning().evaluate(Rx, Ry, F, E_RED, 10.0, 0.05, 2e-8)["h_c"]
    assert r["h_c"][-1] == pytest.approx(smooth, rel=1e-9)
    phi = r["fluid_load_fraction"][2]
    film = Nijenbanning().evaluate(Rx, Ry, F * phi, E_RED * phi, 1e-2, 0.05, 2e-8)["h_c"]
    assert r["h_c"][2] == pytest.approx(film, rel=1e-9)
    np.testing.assert_allclose(r["fluid_load"] + r["asperity_load"], F, rtol=1e-12)


def test_many_operating_points_in_one_call():
    rng = np.random.default_rng(3)
    speeds = 10.0 ** rng.uniform(-7, 1.5, 300)
    loads = rng.uniform(2e3, 5e5, 300)
    r = mixed_line_contact(loads, 0.01, E_RED, speeds, 0.05, 2e-8, SIGMA, ETA, BETA)
    for key in ("asperity_load_fraction", "h_c", "lambda_ratio", "real_area_fraction", "asperity_capacity"):
        assert np.all(np.isfinite(r[key])), key
    assert set(np.unique(r["regime"])) <= set(MIXED_REGIMES)


# ------------------------------------------------------------------------------ friction, Stribeck
def eyring_newtonian_scaffold(slide_to_roll, tau0=5e6):
    """Local test scaffold, not a project model: Newtonian film shear with Barus viscosity limited by
    an Eyring stress, tau = tau0 asinh(eta(p_H) u_s / (h_c tau0)), integrated over the Hertz strip
    with the fluid's share of the Hertz pressure, divided by the fluid load."""
    nodes, weights = np.polynomial.legendre.leggauss(64)

    def traction(r):
        u = np.atleast_1d(np.abs(r["u_m"]))
        h = np.atleast_1d(r["h_c"])
        phi = np.atleast_1d(r["fluid_load_fraction"])
        b = np.atleast_1d(r["hertz_half_width"])
        p_h = 2.0 * r["w"] / (math.pi * b)
        mu = np.zeros(u.shape)
        moving = (phi > 0) & (h > 0) & (u > 0)
        pressure = (p_h * phi)[moving, None] * np.sqrt(1.0 - nodes**2)[None, :]
        eta = r["eta0"] * np.exp(r["alpha"] * pressure)
        tau = tau0 * np.arcsinh(eta * slide_to_roll * u[moving, None] / (h[moving, None] * tau0))
        force = (tau @ weights) * b[moving]
        mu[moving] = force / (phi[moving] * r["w"])
        return mu

    return traction


def test_stribeck_curve_shape_with_a_newtonian_eyring_scaffold():
    """mu -> mu_b when the asperities carry everything, falls through the mixed regime to the fluid
    traction, and in full film equals the fluid traction coefficient (Gelinck & Schipper 2000)."""
    mu_b = 0.12
    curve = stribeck_curve_line(SPEEDS, boundary_friction=mu_b, fluid_traction=eyring_newtonian_scaffold(0.05),
                                **LINE)
    mu = curve["friction_coefficient"]
    assert mu[0] == pytest.approx(mu_b, rel=1e-12)
    assert mu[1] == pytest.approx(mu_b, rel=1e-5)
    mixed = curve["regime"] == "mixed"
    assert np.any(mixed)
    first_full = np.argmax(curve["regime"] == "full_film")
    assert np.all(np.diff(mu[:first_full]) < 0.0)  # falls from boundary through mixed
    full = curve["asperity_load_fraction"] < 1e-12
    np.testing.assert_allclose(mu[full], curve["fluid_traction_coefficient"][full], rtol=1e-9)
    assert 0.0 < mu.min() < 0.06


def test_stribeck_accepts_a_constant_fluid_traction_and_point_contacts():
    curve = stribeck_curve_point(SPEEDS, 20.0, 0.01, 0.02, E_RED, 0.05, 2e-8, SIGMA, ETA, BETA, 0.1, 0.02)
    expected = 0.1 * curve["asperity_load_fraction"] + 0.02 * curve["fluid_load_fraction"]
    np.testing.assert_allclose(curve["friction_coefficient"], expected, rtol=1e-14)


def test_friction_coefficient_from_coefficient_or_force():
    assert mixed_friction_coefficient(0.25, 0.12, fluid_traction_coefficient=0.04) == pytest.approx(0.06)
    # W = 1000 N, asperities 250 N at mu_b 0.12 (30 N), fluid traction force 30 N -> 60 N / 1000 N
    assert mixed_friction_coefficient(0.25, 0.12, fluid_traction_force=30.0, load=1000.0) == pytest.approx(0.06)
    np.testing.assert_allclose(
        mixed_friction_coefficient(np.array([0.0, 1.0]), 0.1, fluid_traction_coefficient=np.array([0.03, 0.5])),
        [0.03, 0.1])


@pytest.mark.parametrize(("kwargs", "text"), [
    ({"asperity_load_fraction": 1.5, "boundary_friction": 0.1, "fluid_traction_coefficient": 0.0}, "0..1"),
    ({"asperity_load_fraction": 0.5, "boundary_friction": -0.1, "fluid_traction_coefficient": 0.0},
     "boundary_friction = -0.1"),
    ({"asperity_load_fraction": 0.5, "boundary_friction": 0.1}, "exactly one"),
    ({"asperity_load_fraction": 0.5, "boundary_friction": 0.1, "fluid_traction_force": 3.0}, "total load"),
    ({"asperity_load_fraction": 0.5, "boundary_friction": 0.1, "fluid_traction_coefficient": float("nan")},
     "fluid_traction_coefficient = nan"),
])
def test_friction_rejects_bad_inputs(kwargs, text):
    with pytest.raises(InputError, match=text):
        mixed_friction_coefficient(**kwargs)


def test_regime_labels_and_thresholds():
    """Lambda <= 1 boundary, 1 < Lambda < 3 mixed, Lambda >= 3 full film (Cheng 1983); asperity
    share >= 0.95 is boundary whatever Lambda (this module's convention)."""
    lam = np.array([0.5, 1.0, 1.01, 2.99, 3.0, 8.0])
    assert list(mixed_regime(lam)) == ["boundary", "boundary", "mixed", "mixed", "full_film", "full_film"]
    assert mixed_regime(2.0, BOUNDARY_ASPERITY_FRACTION) == "boundary"
    assert mixed_regime(2.0, 0.5) == "mixed"


@pytest.mark.parametrize(("change", "text"), [
    ({"w": 0.0}, "w = 0.0"),
    ({"R": -0.01}, "R = -0.01"),
    ({"E_reduced": float("inf")}, "E_reduced = inf"),
    ({"eta0": 0.0}, "eta0 = 0.0"),
    ({"alpha": -1e-8}, "alpha = -1e-08"),
    ({"sigma": 0.0}, "sigma = 0.0"),
    ({"asperity_density": -1.0}, "asperity_density = -1.0"),
    ({"asperity_radius": float("nan")}, "asperity_radius = nan"),
])
def test_line_contact_rejects_bad_inputs_by_name(change, text):
    with pytest.raises(InputError, match=text):
        line(1.0, **change)
    with pytest.raises(InputError, match="u_m = nan"):
        line(float("nan"))
