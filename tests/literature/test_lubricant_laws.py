"""Viscosity–temperature, viscosity–pressure and density laws against published values."""

import math

import numpy as np
import pytest

from camcontact import registry
from camcontact.errors import InputError
from camcontact.models.density import DowsonHigginsonDensity
from camcontact.models.pressure_viscosity_coefficient import gold_alpha
from camcontact.models.viscosity_pressure import Barus, Roelands, roelands_consistent
from camcontact.models.viscosity_temperature import AstmD341, Vogel, Walther

CST = 1e-6


def test_astm_d341_olezol_example_1():
    """olezol.com ASTM D341 example 1: SAE-140 oil, 404 cSt at 40 °C, 28 cSt at 100 °C
    -> 132.126 cSt at 60 °C (T = °C + 273.15)."""
    law = Walther().fit([313.15, 373.15], [404 * CST, 28 * CST])
    assert law.viscosity(333.15) / CST == pytest.approx(132.126, abs=0.001)


def test_astm_d341_olezol_example_2():
    """olezol.com example 2: 68 cSt at 40 °C, 14.85 cSt at 80 °C -> 8.8 cSt at 100 °C."""
    law = Walther().fit([313.15, 353.15], [68 * CST, 14.85 * CST])
    assert law.viscosity(373.15) / CST == pytest.approx(8.8, abs=0.05)


def test_astm_d341_scribd_calculator():
    """Scribd 'Viscosity vs Temperature Calculator': 32 cSt at 40 °C, 5.4 cSt at 100 °C with T = °C + 273
    -> A = 9.5259, B = 3.7449, 8.5 cSt at 80 °C."""
    law = Walther().fit([313.0, 373.0], [32 * CST, 5.4 * CST])
    assert law.n == pytest.approx(9.5259, abs=5e-5) and law.m == pytest.approx(3.7449, abs=5e-5)
    assert law.viscosity(353.0) / CST == pytest.approx(8.5, abs=0.05)


def test_astm_d341_low_viscosity_term():
    """ASTM D341 with Z = nu + 0.7 + exp(-1.47 - 1.84 nu - 0.51 nu^2): 1.5 cSt at 20 °C and 0.6 cSt at
    100 °C give 0.88816 cSt at 60 °C (independent evaluation with the standard's approximate inverse,
    which is good to ~2e-4 cSt) against 0.85272 cSt for the plain nu + 0.7 form."""
    low = AstmD341().fit([293.15, 373.15], [1.5 * CST, 0.6 * CST])
    assert low.viscosity(333.15) / CST == pytest.approx(0.88816, abs=2e-4)
    plain = Walther().fit([293.15, 373.15], [1.5 * CST, 0.6 * CST])
    assert plain.viscosity(333.15) / CST == pytest.approx(0.85272, abs=1e-5)
    # the exact Newton inverse round-trips, and beta is the derivative
    nu = np.array([0.3, 0.5, 1.0, 2.0, 5.0])
    np.testing.assert_allclose(low._nu_from_z(low._z(nu)), nu, rtol=1e-12)
    T, dT = 333.15, 1e-4
    numeric = -(math.log(low.viscosity(T + dT)) - math.log(low.viscosity(T - dT))) / (2 * dT)
    assert low.thermoviscous_coefficient(T) == pytest.approx(numeric, rel=1e-6)


def test_astm_d341_equals_walther_for_ordinary_oils():
    """The extra term is < 1e-5 cSt above 3 cSt: olezol example 1 (132.126 cSt) is unchanged."""
    law = AstmD341().fit([313.15, 373.15], [404 * CST, 28 * CST])
    assert law.viscosity(333.15) / CST == pytest.approx(132.126, abs=0.001)


def test_walther_thermoviscous_coefficient_is_the_derivative():
    """beta = -d ln(nu)/dT (Delabenetta Eq. 37) against a central finite difference."""
    law = Walther().fit([313.15, 373.15], [575 * CST, 50 * CST])
    T, dT = 358.0, 1e-3
    numeric = -(math.log(law.viscosity(T + dT)) - math.log(law.viscosity(T - dT))) / (2 * dT)
    assert law.thermoviscous_coefficient(T) == pytest.approx(numeric, rel=1e-7)


def test_walther_least_squares_with_more_points_reproduces_exact_data():
    exact = Walther().fit([313.15, 373.15], [100 * CST, 10 * CST])
    T = np.array([300.0, 330.0, 360.0, 390.0])
    refit = Walther().fit(T, exact.viscosity(T))
    assert refit.m == pytest.approx(exact.m, rel=1e-10) and refit.n == pytest.approx(exact.n, rel=1e-10)


def test_walther_rejects_increasing_viscosity_and_unfitted_use():
    with pytest.raises(InputError, match="does not decrease"):
        Walther().fit([313.15, 373.15], [10 * CST, 100 * CST])
    with pytest.raises(InputError, match="not fitted"):
        Walther().viscosity(300.0)


def test_vogel_three_point_fit_is_exact():
    """Closed-form three-point fit; the VG32 points (32 cSt at 40 °C, 8.533215 at 80 °C, 5.4 at 100 °C)
    give A = 0.0984698 cSt, B = 780.980 K, C = 178.120 K (helper's independent derivation)."""
    T = [313.15, 353.15, 373.15]
    nu = [32 * CST, 8.533215 * CST, 5.4 * CST]
    law = Vogel().fit(T, nu)
    np.testing.assert_allclose(law.viscosity(np.array(T)), nu, rtol=1e-12)
    assert law.A / CST == pytest.approx(0.0984698, rel=1e-5)
    assert law.B == pytest.approx(780.980, abs=1e-3) and law.C == pytest.approx(178.120, abs=1e-3)
    assert law.thermoviscous_coefficient(330.0) == pytest.approx(law.B / (330.0 - law.C) ** 2)


def test_vogel_least_squares_and_singularity():
    truth = Vogel(A=1e-7, B=800.0, C=170.0)
    T = np.linspace(300, 400, 6)
    fitted = Vogel().fit(T, truth.viscosity(T))
    assert fitted.B == pytest.approx(800.0, rel=1e-6) and fitted.C == pytest.approx(170.0, rel=1e-6)
    with pytest.raises(InputError, match="singular point"):
        truth.viscosity(160.0)


def test_roelands_consistency_tsuha_eta0():
    """Tsuha (2015): alpha = 2.2e-8 1/Pa, z = 0.68 -> eta0 = exp(alpha p0/z - 9.67) = 0.0358352 Pa*s
    (reference §0 item 2)."""
    eta0, alpha, z = roelands_consistent(alpha=2.2e-8, z=0.68)
    assert eta0 == pytest.approx(0.0358352, rel=1e-5)


def test_roelands_consistency_venner_case():
    """Venner (1991) case as quoted in public EHL code: z = 0.68, eta0 = 0.04 Pa*s with 'alpha = 2.2e-8';
    the consistency relation gives 2.238e-8 1/Pa."""
    _, alpha, _ = roelands_consistent(eta0=0.04, z=0.68)
    assert alpha == pytest.approx(2.2381e-8, rel=1e-4)
    with pytest.raises(InputError, match="not consistent"):
        roelands_consistent(eta0=0.04, alpha=2.0e-8, z=0.68)
    with pytest.raises(InputError, match="needs two"):
        roelands_consistent(eta0=0.04)


def test_roelands_slope_at_zero_is_alpha_and_it_stays_below_barus():
    law, eta0, alpha = Roelands(), 0.04, 2.2e-8
    dp = 1.0
    slope = (law.log_viscosity_ratio(dp, eta0, alpha) - law.log_viscosity_ratio(-dp, eta0, alpha)) / (2 * dp)
    assert slope == pytest.approx(alpha, rel=1e-8)
    p = np.array([0.2e9, 0.5e9, 1e9, 2e9])
    assert np.all(law.log_viscosity_ratio(p, eta0, alpha) < Barus().log_viscosity_ratio(p, eta0, alpha))


def test_roelands_numbers_at_1_gpa():
    """eta0 = 0.2 Pa*s, alpha = 1.77e-8 1/Pa. Independent evaluation of Roelands (1966) in its
    eta_inf form eta = eta0 (eta_inf/eta0)^(1 - (1 + p/p0)^z), eta_inf = exp(-9.67) Pa*s, with the
    consistent z = alpha p0 / (ln eta0 + 9.67) = 0.430392: 2659.98 Pa*s at 1 GPa. (Codes that take
    z with 5.1e-9 ~ 1/p0 get z = 0.430564 and 2667.8 Pa*s.)"""
    law = Roelands()
    z = 1.77e-8 * 1.96e8 / (math.log(0.2) + 9.67)
    assert law.z(0.2, 1.77e-8) == pytest.approx(z, rel=1e-12) == pytest.approx(0.430392, abs=1e-6)
    expected = 0.2 * (math.exp(-9.67) / 0.2) ** (1 - (1 + 1e9 / 1.96e8) ** z)
    assert law.viscosity(1e9, 0.2, 1.77e-8) == pytest.approx(expected, rel=1e-12)
    assert expected == pytest.approx(2659.98, abs=0.01)


def test_viscosity_overflow_is_an_error_not_inf():
    with pytest.raises(InputError, match="overflows"):
        Barus().viscosity_ratio(1e11, 0.04, 2.2e-8)
    assert np.isfinite(Roelands().log_viscosity_ratio(50e9, 0.04, 2.2e-8))


def test_roelands_undefined_for_tiny_eta0():
    with pytest.raises(InputError, match="must exceed eta_inf"):
        Roelands().z(1e-5, 2e-8)


def test_dowson_higginson_density():
    """rho/rho0 = (5.9e8 + 1.34 p)/(5.9e8 + p): 1.2138365 at 1 GPa, limit 1.34 (Tsuha Eq. 4.7)."""
    law = DowsonHigginsonDensity()
    assert law.density_ratio(1e9) == pytest.approx(1.2138365, rel=1e-7)
    assert law.density_ratio(1e15) == pytest.approx(1.34, rel=1e-5)
    assert law.density_ratio(0.0) == 1.0


def test_registry_resolves_lubricant_laws():
    assert registry.get("viscosity_laws", "roelands").kind == "pressure"
    assert registry.get("viscosity_laws", "walther").kind == "temperature"
    assert registry.get("density_laws", "incompressible").density_ratio(np.array([0.0, 1e9])).tolist() == [1.0, 1.0]


def test_gold_alpha_delabenetta_table5():
    """Delabenetta (2021) Eq. 36 for NH1 11-572 at 84.9 °C: nu = 80.5760 cSt, m = 2.74686, SG 0.92
    -> alpha = 2.03546e-8 1/Pa (reference §4.2; Table 5 prints 2.04E-08)."""
    assert gold_alpha(80.5760, 2.74686, 0.92, "mineral") == pytest.approx(2.03546e-8, rel=2e-5)
    with pytest.raises(InputError, match="oil = 'vegetable'"):
        gold_alpha(80.0, 2.7, 0.92, "vegetable")
