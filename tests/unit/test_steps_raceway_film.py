"""The raceway contact's lubricant-and-film chain (camcontact.steps.raceway_film.raceway_film_chain) alone.

Thesis convention: Delabenetta (2021) Tables 5 and 8 to the printed digits and its §4.2 full precision
(the same numbers tests/literature checks through the scene). Corrected convention: an independent hand
calculation here: Walther through nu40/nu100 with K = degC + 273.15 (Eqs. 32-35, 37), eta = rho nu, the
Gold alpha (Eq. 36), k and c_p (Eqs. 38-39), Hamrock U, G, W (Eq. 42), Grubin h0 with exact exponents
8/11, -1/11 (Eq. 40), Dowson–Higginson h_min (Eq. 41), phi_T (Eq. 44), starvation 0.7 for a grease (Eq. 43),
Lambda = h_oc/sigma (Eq. 13).
"""

import math

import attrs
import pytest

import camcontact as cc
from camcontact.errors import InputError
from camcontact.scenes.raceway_conventions import CORRECTED, THESIS
from camcontact.steps.raceway_film import raceway_film_chain, raceway_lubricant_state

GREASE = cc.Lubricant(name="NH1 11-572", nu40="575 cSt", nu100="50 cSt", density="0.92 g/cm^3", form="grease",
                      alpha_correlation="gold", upper_temperature="120 degC")
# Delabenetta's contact: 10 kN on 41.35 mm, 200 GPa steel, raceway 149 mm at 300 rpm, roller 13.5 mm at 1900 rpm
E_REDUCED = 200e9 / (1 - 0.3**2)
W = 10e3 / 0.04135
R_CONVEX = 1 / (1 / 0.149 + 1 / 0.0135)  # the thesis sums the curvatures
U1, U2 = 0.149 * 2 * math.pi * 5.0, 0.0135 * 2 * math.pi * 1900 / 60
SIGMA = math.sqrt(2) * 0.23e-6


def chain(convention, lubricant=GREASE, lambda_min=3.0, R=R_CONVEX, temperature=358.15):
    return raceway_film_chain(W, R, E_REDUCED, 0.5 * (U1 + U2), U1, U2, abs(U1 - U2) / (U1 + U2), SIGMA, lubricant,
                              temperature, lambda_min, convention)


def test_thesis_convention_delabenetta_tables_5_and_8():
    """Table 5: T = 84.9 degC (one loop step from 85 degC), n 7.2959, m 2.7469, nu 80.57 cSt (printed
    truncated), eta 0.0741 Pa s, alpha 2.04e-8 1/Pa, beta 0.034 1/K, k 0.1286 W/(m K), c 2000.3 J/(kg K);
    Table 8: h0 1.369 um, h_min 1.035 um, phi_T 0.615, h_oc 1.685 um, Lambda 5.181 (§4.2: 5.1810), full film."""
    out = chain(THESIS)
    assert set(out) == set(raceway_film_chain.step.provides)
    assert out["temperature"] - 273.15 == pytest.approx(84.9, abs=1e-9)
    assert round(out["walther_n"], 4) == 7.2959 and round(out["walther_m"], 4) == 2.7469
    assert math.floor(out["kinematic_viscosity"] * 1e8) / 100 == 80.57
    assert round(out["eta0"], 4) == 0.0741
    assert round(out["alpha"] * 1e8, 2) == 2.04
    assert round(out["thermoviscous_coefficient"], 3) == 0.034
    assert round(out["lubricant_conductivity"], 4) == 0.1286
    assert round(out["lubricant_specific_heat"], 1) == 2000.3
    assert round(out["h_c"] * 1e6, 3) == 1.369 and round(out["h_min"] * 1e6, 3) == 1.035
    assert round(out["thermal_factor"], 3) == 0.615
    assert out["starvation_factor"] == 1.0 and out["roughness_factor"] == 2.0
    assert round(out["h_c_corrected"] * 1e6, 3) == 1.685
    assert out["Lambda_oc"] == pytest.approx(5.1810, abs=5e-5)
    assert out["regime"] == "full film" and out["film_validity"] == "ok"
    assert out["lubricant_pressure_state"] is None


def _walther(T, offset):
    x1, x2 = math.log10(40 + offset), math.log10(100 + offset)
    y1, y2 = (math.log10(math.log10(v + 0.7)) for v in (575.0, 50.0))
    m = (y1 - y2) / (x2 - x1)
    nu = 10 ** (10 ** (y1 + m * x1 - m * math.log10(T))) - 0.7
    return nu, m, m * (nu + 0.7) * math.log(nu + 0.7) / (nu * T)


def test_corrected_convention_by_hand():
    """Corrected convention at 85 degC, no loop, concave outer race (1/R = 1/R2 - 1/R1): every film quantity
    from the hand calculation of the module docstring."""
    R = 1 / (1 / 0.0135 - 1 / 0.149)
    out = chain(CORRECTED, R=R)
    theta, T = 85.0, 358.15
    nu, m, beta = _walther(T, 273.15)
    eta = nu * 1e-6 * 920.0
    log_nu, sg = math.log10(nu), 0.92
    alpha = (1.216 + 4.143 * log_nu**3.0627 + 2.848e-4 * m**5.1903 * log_nu**1.5976
             - 3.999 * log_nu**3.0975 * sg**0.1162) * 1e-8
    k = 0.12 * (1 - 0.0005 / 3 * theta) / sg
    c_p = 1000 * (1.63 + 0.0034 * theta) / math.sqrt(sg)
    assert out["temperature"] == pytest.approx(T)
    assert out["eta0"] == pytest.approx(eta, rel=1e-9)
    assert out["thermoviscous_coefficient"] == pytest.approx(beta, rel=1e-8)
    assert out["alpha"] == pytest.approx(alpha, rel=1e-9)
    assert out["roelands_z"] == pytest.approx(alpha * 1.96e8 / (math.log(eta) + 9.67), rel=1e-9)
    assert out["lubricant_conductivity"] == pytest.approx(k, rel=1e-12)
    assert out["lubricant_specific_heat"] == pytest.approx(c_p, rel=1e-12)
    U, G, Wp = eta * 0.5 * (U1 + U2) / (E_REDUCED * R), alpha * E_REDUCED, W / (E_REDUCED * R)
    assert (out["U"], out["G"], out["W"]) == pytest.approx((U, G, Wp), rel=1e-9)
    h0 = 1.95 * (G * U) ** (8 / 11) * Wp ** (-1 / 11) * R
    assert out["h_c"] == pytest.approx(h0, rel=1e-9)
    assert out["h_min"] == pytest.approx(2.65 * U**0.70 * G**0.54 * Wp**-0.13 * R, rel=1e-9)
    L = beta * eta * (U1 + U2) ** 2 / k
    phi = 1 / (1 + 0.1 * (1 + 14.8 * ((U1 - U2) / (U1 + U2)) ** 0.83) * L**0.64)
    assert out["thermal_loading"] == pytest.approx(L, rel=1e-9)
    assert out["thermal_factor"] == pytest.approx(phi, rel=1e-9)
    assert out["starvation_factor"] == 0.7 and out["roughness_factor"] == 1.0
    assert out["h_c_corrected"] == pytest.approx(phi * 0.7 * h0, rel=1e-9)
    assert out["Lambda_oc"] == pytest.approx(phi * 0.7 * h0 / SIGMA, rel=1e-9)
    assert out["regime"] == "mixed"
    assert out["lubricant_pressure_state"].temperature == pytest.approx(T)


def test_temperature_loop_steps_down_until_lambda_exceeds_lambda_min():
    """lambda_min = 5.3 > Lambda(84.9 degC) = 5.181: the thesis's loop lowers T in 0.1 K steps and stops at the
    first Lambda above 5.3 (the step before is still <= 5.3); oil (form 'oil') gets no starvation factor in the
    corrected convention."""
    out = chain(THESIS, lambda_min=5.3)
    theta = out["temperature"] - 273.15
    assert out["Lambda_oc"] > 5.3 and theta < 84.9
    steps = (85.0 - theta) / 0.1
    assert steps == pytest.approx(round(steps), abs=1e-6)
    before = chain(THESIS, lambda_min=0.0, temperature=out["temperature"] + 0.2)  # loop steps once: theta + 0.1
    assert before["Lambda_oc"] <= 5.3
    assert chain(CORRECTED, lubricant=attrs.evolve(GREASE, form="oil"))["starvation_factor"] == 1.0


def test_refusals_name_the_input():
    """The thesis convention needs nu40/nu100 and density; a loop that never reaches lambda_min names it."""
    plain = cc.Lubricant(name="eta only", eta0="0.05 Pa*s", alpha="2e-8 1/Pa")
    with pytest.raises(InputError, match="thesis convention needs nu40, nu100, density"):
        chain(THESIS, lubricant=plain)
    with pytest.raises(InputError, match="lambda_min = 1e\\+06: the thesis's temperature loop"):
        chain(THESIS, lambda_min=1e6)


def test_lubricant_state_of_the_friction_is_the_chains_oil():
    """The EHL friction's lubricant state carries the chain's eta0, alpha, beta, k and c at its working
    temperature (thesis: Walther a = 0.7 through nu40/nu100 with K = degC + 273, Gold alpha: eta0 0.0741 Pa s,
    where the lubricant's own Walther law gives 0.3 % less), and the lubricant's pressure law: its
    viscosity at 0.5 GPa is Roelands's (the lubricant's default law) with the chain's eta0 and alpha:
    eta0 exp{(ln eta0 + 9.67)[(1 + p/p0)^z - 1]}, z = alpha p0/(ln eta0 + 9.67), p0 = 1.96e8 Pa."""
    out = chain(THESIS)
    names = ("eta0", "alpha", "thermoviscous_coefficient", "lubricant_conductivity", "lubricant_specific_heat")
    state = raceway_lubricant_state(GREASE, out["temperature"], *(out[n] for n in names))["lubricant_state"]
    assert (state.eta0, state.alpha, state.thermoviscous_coefficient, state.thermal_conductivity,
            state.specific_heat) == tuple(out[n] for n in names)
    assert state.eta0 == pytest.approx(0.0741, abs=5e-5)
    assert GREASE.state(out["temperature"]).eta0 == pytest.approx(state.eta0, rel=5e-3)
    assert state.eta0 != GREASE.state(out["temperature"]).eta0
    margin, p0 = math.log(out["eta0"]) + 9.67, 1.96e8
    z = out["alpha"] * p0 / margin
    roelands = out["eta0"] * math.exp(margin * ((1 + 0.5e9 / p0) ** z - 1))
    assert float(state.viscosity(0.5e9)) == pytest.approx(roelands, rel=1e-9)
