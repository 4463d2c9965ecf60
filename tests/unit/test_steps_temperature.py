"""Raceway contact temperatures (camcontact.steps.temperature.raceway_temperatures) called alone.

Thesis convention: Delabenetta (2021) Table 8 and §4.2 (T_F = 22.4234 K, T_max = 107.3 degC, eta_p =
638.29 Pa s with its log10 Roelands form and c = 4.2, T_maxL = 130.51 degC reported as the Couette rise,
"exceeds ... 120 degC by 10.5 K"), with every input computed here by hand (Walther, Gold alpha, Eq. 38,
Hertz, Kelley). Corrected convention: Blok's flash temperature (Eq. 48), Roelands in its ln form
ln(eta_p/eta0) = (ln eta0 + 9.67)[(1 + p/p0)^z - 1] and the Couette rise ln(beta du^2 eta_p/(8k) + 1)/beta
(App. D), absolute: T_smax + rise.
"""

import math

import attrs
import pytest

import camcontact as cc
from camcontact.scenes.raceway_conventions import CORRECTED, THESIS
from camcontact.steps.temperature import raceway_temperatures

E_REDUCED = 200e9 / (1 - 0.3**2)
R_CONVEX = 1 / (1 / 0.149 + 1 / 0.0135)
W = 10e3 / 0.04135
U1, U2 = 0.149 * 2 * math.pi * 5.0, 0.0135 * 2 * math.pi * 1900 / 60
E_STEEL = math.sqrt(7810 * 464 * 42.4)  # effusivity sqrt(rho c k) of Delabenetta's AISI 52100 (Eq. 50)


def thesis_oil(theta):
    """NH1 11-572 base oil at theta [degC] the thesis's way: (eta0, alpha, beta, k)."""
    x1, x2 = math.log10(313.0), math.log10(373.0)
    y1, y2 = (math.log10(math.log10(v + 0.7)) for v in (575.0, 50.0))
    m = (y1 - y2) / (x2 - x1)
    T = theta + 273.0
    nu = 10 ** (10 ** (y1 + m * x1 - m * math.log10(T))) - 0.7
    log_nu = math.log10(nu)
    alpha = (1.216 + 4.143 * log_nu**3.0627 + 2.848e-4 * m**5.1903 * log_nu**1.5976
             - 3.999 * log_nu**3.0975 * 0.92**0.1162) * 1e-8
    beta = m * (nu + 0.7) * math.log(nu + 0.7) / (nu * T)
    return nu * 1e-6 * 920, alpha, beta, 0.12 * (1 - 0.0005 / 3 * theta) / 0.92


def p_mean(R):
    b = math.sqrt(8 * W * R / (math.pi * E_REDUCED))
    return math.pi / 4 * 2 * W / (math.pi * b)


def test_thesis_convention_delabenetta_table_8():
    """The thesis's contact at 84.9 degC with mu = Kelley (0.03748): the printed temperatures and text."""
    eta, alpha, beta, k = thesis_oil(84.9)
    mu = 0.0127 * math.log10(29.66e-3 * 10e3 / (eta * 0.04135 * (U1 - U2) * (U1 + U2) ** 2))
    z = alpha * 1.96e8 / (math.log(eta) + 9.67)  # Roelands consistency
    out = raceway_temperatures(W, E_REDUCED, R_CONVEX, mu, U1, U2, (E_STEEL, E_STEEL), eta, alpha, z,
                               p_mean(R_CONVEX), beta, k, None, 84.9 + 273.15, 120 + 273.15, THESIS)
    assert set(out) == set(raceway_temperatures.step.provides)
    assert out["flash_temperature"] == pytest.approx(22.4234, abs=5e-4)
    assert round(out["surface_temperature_max"] - 273.15, 1) == 107.3
    assert out["viscosity_at_mean_pressure"] == pytest.approx(638.29, abs=0.01)
    assert out["lubricant_temperature_max"] - 273.15 == pytest.approx(130.51, abs=0.005)
    assert out["film_temperature_rise"] == pytest.approx(out["lubricant_temperature_max"] - 273.15, rel=1e-12)
    assert out["lubricant_temperature_check"].startswith("exceeds the upper service temperature 120 °C by 10.5 K")


def test_corrected_convention_by_hand():
    """Corrected convention with the lubricant's Roelands law: flash temperature, ln-form eta_p, Couette
    rise and the absolute maximum T + T_F + rise (about 222.6 degC), checked against a 200 degC limit
    (exceeded by the difference) and within a 250 degC one."""
    grease = cc.Lubricant(name="NH1 11-572", nu40="575 cSt", nu100="50 cSt", density="0.92 g/cm^3",
                          alpha_correlation="gold")
    state = grease.state(358.15)
    R = 1 / (1 / 0.0135 - 1 / 0.149)
    k, mu = 0.1286, 0.04
    out = raceway_temperatures(W, E_REDUCED, R, mu, U1, U2, (E_STEEL, 0.8 * E_STEEL), state.eta0, state.alpha,
                               state.roelands_z, p_mean(R), state.thermoviscous_coefficient, k, state, 358.15,
                               473.15, CORRECTED)
    flash = (0.893 * W**0.75 * (E_REDUCED / (4 * R)) ** 0.25 * mu * (U1 - U2)
             / (E_STEEL * math.sqrt(U1) + 0.8 * E_STEEL * math.sqrt(U2)))
    eta_p = state.eta0 * math.exp((math.log(state.eta0) + 9.67) * ((1 + p_mean(R) / 1.96e8) ** state.roelands_z - 1))
    beta = state.thermoviscous_coefficient
    rise = math.log(beta * (U1 - U2) ** 2 * eta_p / (8 * k) + 1) / beta
    assert out["flash_temperature"] == pytest.approx(flash, rel=1e-12)
    assert out["viscosity_at_mean_pressure"] == pytest.approx(eta_p, rel=1e-9)
    assert out["film_temperature_rise"] == pytest.approx(rise, rel=1e-9)
    assert out["surface_temperature_max"] == pytest.approx(358.15 + flash, rel=1e-12)
    assert out["lubricant_temperature_max"] == pytest.approx(358.15 + flash + rise, rel=1e-12)
    gap = 358.15 + flash + rise - 473.15
    assert out["lubricant_temperature_check"] == (f"exceeds the upper service temperature 200 °C by {gap:.3g} K "
                                                  "(T_smax + rise)")
    cooler = raceway_temperatures(W, E_REDUCED, R, mu, U1, U2, (E_STEEL, 0.8 * E_STEEL), state.eta0, state.alpha,
                                  state.roelands_z, p_mean(R), state.thermoviscous_coefficient, k, state, 358.15,
                                  523.15, CORRECTED)
    assert cooler["lubricant_temperature_check"].startswith("within the upper service temperature 250 °C")
    # without the lubricant's pressure state: Roelands (ln form) from eta0 and alpha
    bare = raceway_temperatures(W, E_REDUCED, R, mu, U1, U2, (E_STEEL, E_STEEL), state.eta0, state.alpha,
                                state.roelands_z, p_mean(R), beta, k, None, 358.15, None, CORRECTED)
    assert bare["viscosity_at_mean_pressure"] == pytest.approx(eta_p, rel=1e-9)


def test_pure_rolling_has_no_frictional_heat():
    """mu = NaN (pure rolling, outside Kelley): flash temperature 0, no sliding so no Couette rise; the
    surface stays at T; no upper temperature: said so."""
    eta, alpha, beta, k = thesis_oil(85.0)
    z = alpha * 1.96e8 / (math.log(eta) + 9.67)
    convention = attrs.evolve(CORRECTED, roelands_log10_constant=None)
    out = raceway_temperatures(W, E_REDUCED, R_CONVEX, math.nan, 3.0, 3.0, (E_STEEL, E_STEEL), eta, alpha, z,
                               p_mean(R_CONVEX), beta, k, None, 358.15, None, convention)
    assert out["flash_temperature"] == 0.0 and out["film_temperature_rise"] == 0.0
    assert out["surface_temperature_max"] == 358.15 and out["lubricant_temperature_max"] == 358.15
    assert out["lubricant_temperature_check"] == "no upper service temperature given"
