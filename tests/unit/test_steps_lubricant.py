"""The lubricant step (camcontact.steps.lubricant) called alone.

Expected values: Walther's law log10 log10(nu + 0.7) = n - m log10 T through nu40 and nu100 (Delabenetta
2021 Eqs. 32-35) and its exact thermoviscous coefficient beta = m (nu + a) ln(nu + a)/(nu T) (Eq. 37),
solved here by hand; the Roelands consistency z = alpha p0/(ln eta0 + 9.67), p0 = 1.96e8 Pa; Tsuha
(2015)'s eta0 = 0.0358352 Pa s from alpha = 2.2e-8 1/Pa and z = 0.68 (reference §0 item 2).
"""

import math

import pytest

import camcontact as cc
from camcontact.errors import InputError
from camcontact.steps.lubricant import check_pressure_viscosity, lubricant_state
from step_checks import assert_provides

OIL = cc.Lubricant(name="VG 460-like", nu40="575 cSt", nu100="50 cSt", density="920 kg/m^3", alpha="2.0e-8 1/Pa",
                   thermal_conductivity="0.13 W/(m K)")


def walther(nu40_cst, nu100_cst, T):
    """(nu [cSt], beta [1/K]) of Walther's law (a = 0.7) through 40 and 100 degC, at T [K]."""
    x1, x2 = math.log10(313.15), math.log10(373.15)
    y1, y2 = (math.log10(math.log10(v + 0.7)) for v in (nu40_cst, nu100_cst))
    m = (y1 - y2) / (x2 - x1)
    n = y1 + m * x1
    nu = 10 ** (10 ** (n - m * math.log10(T))) - 0.7
    return nu, m * (nu + 0.7) * math.log(nu + 0.7) / (nu * T)


def test_lubricant_state_walther_and_roelands_consistency():
    """At 85 degC: nu and beta from Walther by hand, eta0 = nu rho, alpha as given, z = alpha p0/(ln eta0
    + 9.67) (Roelands consistency), the conductivity as given, the density law by the compressibility switch."""
    T = 358.15
    out = lubricant_state(OIL, T, True)
    assert_provides(lubricant_state, out)
    nu_cst, beta = walther(575.0, 50.0, T)
    assert out["kinematic_viscosity"] == pytest.approx(nu_cst * 1e-6, rel=1e-10)
    assert out["eta0"] == pytest.approx(nu_cst * 1e-6 * 920.0, rel=1e-10)
    assert out["thermoviscous_coefficient"] == pytest.approx(beta, rel=1e-8)
    assert out["alpha"] == pytest.approx(2.0e-8, rel=1e-12)
    assert out["roelands_z"] == pytest.approx(2.0e-8 * 1.96e8 / (math.log(out["eta0"]) + 9.67), rel=1e-9)
    assert out["lubricant_conductivity"] == pytest.approx(0.13)
    assert out["density_law"] == "dowson_higginson"
    assert out["lubricant_state"].eta0 == out["eta0"] and out["lubricant_state"].temperature == T
    assert lubricant_state(OIL, T, False)["density_law"] == "incompressible"


def test_lubricant_state_isothermal_tsuha_oil():
    """Tsuha (2015): alpha = 2.2e-8 1/Pa, z = 0.68, no temperature data: eta0 = 0.0358352 Pa s at any
    (None) temperature; no thermal data: beta and conductivity are None."""
    oil = cc.Lubricant(name="Tsuha 2015", alpha="2.2e-8 1/Pa", roelands_z=0.68)
    out = lubricant_state(oil, None, True)
    assert out["eta0"] == pytest.approx(0.0358352, rel=2e-6)
    assert out["roelands_z"] == 0.68 and out["alpha"] == pytest.approx(2.2e-8)
    assert out["thermoviscous_coefficient"] is None and out["lubricant_conductivity"] is None


def test_lubricant_state_needs_a_temperature_for_temperature_data():
    """Viscosity data at 40 and 100 degC but no temperature: InputError."""
    with pytest.raises(InputError, match="give the temperature"):
        lubricant_state(OIL, None, True)


def test_check_pressure_viscosity():
    """The step's check: a lubricant with only eta0 (no alpha, z or correlation) is refused when the
    piezoviscosity effect is on, accepted when it is off; no lubricant yet, or one with alpha: accepted."""
    assert lubricant_state.step.check is check_pressure_viscosity
    plain = cc.Lubricant(name="no alpha", eta0="0.05 Pa*s")
    with pytest.raises(InputError, match="no pressure-viscosity data"):
        check_pressure_viscosity(plain, True)
    assert check_pressure_viscosity(plain, False) is None
    assert check_pressure_viscosity(None, True) is None
    assert check_pressure_viscosity(OIL, True) is None


def test_isothermal_lubricant_state_and_the_choice_of_the_lubricant_step():
    """A lubricant without temperature data (eta0 and alpha given) has its state without a temperature; the
    scene's lubricant step requires the temperature only when the viscosity depends on it or one is given."""
    from camcontact.steps.lubricant import isothermal_lubricant_state, lubricant_step

    fixed = cc.Lubricant(eta0="0.05 Pa*s", alpha="2e-8 1/Pa")
    out = isothermal_lubricant_state(fixed, False)
    assert_provides(isothermal_lubricant_state, out)
    assert out["eta0"] == 0.05 and out["alpha"] == 2e-8 and out["density_law"] == "incompressible"
    assert lubricant_step(fixed, None).requires == ("lubricant", "compressibility")
    assert lubricant_step(fixed, 353.15).requires == ("lubricant", "temperature", "compressibility")
    assert lubricant_step(OIL, None).requires == ("lubricant", "temperature", "compressibility")
    assert lubricant_step(None, None).requires == ("lubricant", "compressibility")  # reported missing: the lubricant
