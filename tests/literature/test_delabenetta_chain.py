"""Delabenetta (2021) pellet-mill contact in thesis mode: Tables 5, 7 and 8 (NH1 11-572).

Source: ../shared/reference/spherical_roller_bearing_delabenetta2021.md — Tables 5, 7, 8 as
printed (§4.1) and the full-precision reproduction of the thesis's Appendix D (§4.2).
Thesis mode keeps the thesis's choices: convex sum of curvatures (R_x = 2R'), T = theta + 273,
working temperature 84.9 °C (its temperature loop, §5.2), mineral-oil C_alpha, Grubin exponents
rounded to three decimals, phi_A = 1 and phi_R = 2 (its Eq. 43).
"""

import pytest

from camcontact.contact.geometry import reduced_modulus, reduced_radius
from camcontact.contact.hertz_line import hertz_line
from camcontact.contact.roughness import composite_roughness, lambda_ratio, lubrication_regime
from camcontact.contact.subsurface import line_subsurface
from camcontact.ehl.groups import hamrock_line
from camcontact.models.film_line import DowsonHigginson, Grubin
from camcontact.models.film_thermal import inlet_heating_factor, slide_roll_measure, thermal_loading
from camcontact.models.pressure_viscosity_coefficient import gold_alpha
from camcontact.models.viscosity_pressure import Roelands
from camcontact.models.viscosity_temperature import Walther

CST = 1e-6
F_N, LENGTH = 10e3, 41.35e-3  # N, m (Table 4, Table 1)
R1, R2 = 0.149, 0.0135  # m (Table 1)
U1, U2 = 0.149 * 300 * 2 * 3.141592653589793 / 60, 0.0135 * 1900 * 2 * 3.141592653589793 / 60  # Eq. 31
T_WORK = 84.9 + 273.0  # K, thesis convention theta + 273 and its 84.9 °C


@pytest.fixture(scope="module")
def chain():
    E_red = reduced_modulus(200e9, 0.3, 200e9, 0.3)
    R = reduced_radius(R1, R2)  # thesis mode: both convex (its erratum 2)
    w = F_N / LENGTH
    hertz = hertz_line(w, R, E_red)
    stresses = line_subsurface(hertz.b, hertz.p_h)
    law = Walther(a=0.7).fit([40 + 273.0, 100 + 273.0], [575 * CST, 50 * CST])
    nu = law.viscosity(T_WORK)
    eta = nu * 920.0  # Eq. 35: eta = nu * SG
    alpha = gold_alpha(nu / CST, law.m, 0.92, "mineral")
    U, G, W = hamrock_line(w, R, E_red, 0.5 * (U1 + U2), eta, alpha)
    state = dict(R=R, w=w, E_reduced=E_red, u_m=0.5 * (U1 + U2), eta0=eta, alpha=alpha)
    h0 = Grubin(exponent_digits=3)(state)["h_c"]
    hm = DowsonHigginson()(state)["h_min"]
    conductivity = 0.12 * (1 - 0.0005 * 84.9 / 3) / 0.92  # Eq. 38 as coded (0.0005/3, erratum 11)
    L = thermal_loading(law.thermoviscous_coefficient(T_WORK), eta, U1, U2, conductivity)
    phi_t = inlet_heating_factor(L, slide_roll_measure(U1, U2))
    h_oc = phi_t * 1.0 * 2.0 * h0  # Eq. 43 with phi_A = 1, phi_R = 2 (thesis values)
    return dict(E_red=E_red, R=R, hertz=hertz, stresses=stresses, law=law, nu=nu, eta=eta, alpha=alpha,
                U=U, G=G, W=W, h0=h0, hm=hm, k=conductivity, L=L, phi_t=phi_t, h_oc=h_oc, state=state)


def test_table7_hertz(chain):
    """Table 7: E* = 109.89 GPa, R_x = 0.0248 m, a = 186 um, P_m = 649.27 MPa, P_o = 826.67 MPa."""
    assert chain["E_red"] / 2 * 1e-9 == pytest.approx(109.89, abs=0.005)
    assert 2 * chain["R"] == pytest.approx(2.475692e-2, rel=1e-6)
    assert chain["hertz"].b == pytest.approx(1.862393e-4, rel=1e-6)
    assert chain["hertz"].p_mean * 1e-6 == pytest.approx(649.27, abs=0.005)
    assert chain["hertz"].p_h * 1e-6 == pytest.approx(826.67, abs=0.005)


def test_table7_subsurface_stresses(chain):
    """Table 7: tau_max = 248 MPa at Z_s = 146.4 um; tau_xz,max = 206.67 MPa. The thesis takes
    0.30 p0 and 0.7861 a (its Eq. 7); the exact field gives 0.30028 p0 at 0.78615 a."""
    s = chain["stresses"]
    assert s.principal_shear_max.value * 1e-6 == pytest.approx(248, abs=0.5)
    assert s.principal_shear_max.z * 1e6 == pytest.approx(146.4, abs=0.05)
    assert s.tau_xz_max.value * 1e-6 == pytest.approx(206.67, abs=0.005)
    assert s.orthogonal_shear_range * 1e-6 == pytest.approx(413.3, abs=0.05)  # §4.1: 2 tau_0 = 413.3 MPa


def test_table7_orthogonal_shear_depth_disagrees_with_the_thesis(chain):
    """The thesis prints Z_0 = 78.12 um = 0.42 x 186 um (its Eq. 10 constants and a rounded a;
    reference erratum 4). The exact extremum lies at z = 0.5 a = 93.12 um, x = 0.866 a. Both kept."""
    s = chain["stresses"]
    assert s.tau_xz_max.z * 1e6 == pytest.approx(0.5 * 186.2393, abs=0.05)
    thesis_z0 = 0.42 * 186.0
    assert thesis_z0 == pytest.approx(78.12)
    assert abs(s.tau_xz_max.z * 1e6 - thesis_z0) > 14.0


def test_table5_viscosity_chain(chain):
    """Table 5 / §4.2: n = 7.29586, m = 2.74686, nu = 80.5760 cSt, eta = 0.07413 Pa*s,
    alpha = 2.03546e-8 1/Pa, beta = 0.03405 1/K, k = 0.12859 W/(m K), Roelands Z = 0.56444."""
    assert chain["law"].n == pytest.approx(7.29586, abs=5e-6)
    assert chain["law"].m == pytest.approx(2.74686, abs=5e-6)
    assert chain["nu"] / CST == pytest.approx(80.5760, abs=5e-4)
    assert chain["eta"] == pytest.approx(0.07413, abs=5e-6)
    assert chain["alpha"] == pytest.approx(2.03546e-8, rel=5e-6)
    assert chain["law"].thermoviscous_coefficient(T_WORK) == pytest.approx(0.03405, abs=5e-6)
    assert chain["k"] == pytest.approx(0.12859, abs=5e-6)
    assert Roelands().z(chain["eta"], chain["alpha"]) == pytest.approx(0.56444, abs=5e-5)


def test_dimensionless_groups(chain):
    """§4.2: U = 1.00369e-10, G = 4473.54, W = 8.88933e-5."""
    assert chain["U"] == pytest.approx(1.00369e-10, rel=1e-5)
    assert chain["G"] == pytest.approx(4473.54, abs=0.01)
    assert chain["W"] == pytest.approx(8.88933e-5, rel=1e-5)


def test_table8_films_and_lambda(chain):
    """Table 8 (printed) and §4.2: h0 = 1.36944e-6 m (1.369 um), h_m = 1.03522e-6 m (1.035 um),
    L = 1.06524, phi_T = 0.61530 (0.615), h_oc = 1.68523e-6 m (1.685 um), Lambda = 5.1810 (5.181)."""
    assert chain["h0"] == pytest.approx(1.36944e-6, rel=1e-5)
    assert chain["hm"] == pytest.approx(1.03522e-6, rel=1e-5)
    assert chain["L"] == pytest.approx(1.06524, abs=5e-5)
    assert chain["phi_t"] == pytest.approx(0.61530, abs=5e-6)
    assert chain["h_oc"] == pytest.approx(1.68523e-6, rel=1e-5)
    sigma = composite_roughness(0.23e-6, 0.23e-6)
    assert sigma == pytest.approx(3.252691e-7, rel=1e-6)
    assert lambda_ratio(chain["h_oc"], 0.23e-6, 0.23e-6) == pytest.approx(5.1810, abs=5e-5)


def test_exact_grubin_exponents_and_phi_r_change_the_conclusion(chain):
    """Grubin with exact exponents (8/11, 1/11) gives 0.5 % less than the thesis's rounded ones, and
    without the thesis's phi_R = 2 (reference erratum 13) Lambda drops from 5.18 (full film) to about
    2.6: the mixed regime. Both values are kept visible here."""
    exact = Grubin()(chain["state"])["h_c"]
    assert exact / chain["h0"] == pytest.approx(0.99518, abs=1e-5)
    lam = lambda_ratio(chain["phi_t"] * chain["h0"], 0.23e-6, 0.23e-6)
    assert lam == pytest.approx(5.1810 / 2, abs=5e-5)
    assert lubrication_regime(lam) == "mixed" and lubrication_regime(5.1810) == "full film"


def test_table8_friction_and_temperatures(chain):
    """Table 8 (printed) and §4.2 (full precision): mu_Kelly = 0.03748 (0.037), T_F = 22.4234 °C
    (22.42), T_max = T + T_F = 107.3234 °C (107.3), T_maxL = 130.51 °C (130.5). Effusivity of
    AISI 52100 sqrt(7810 x 464 x 42.4) = 12395.6 (Table 6: 1.239e4).

    The lubricant's maximum temperature needs eta at the mean Hertz pressure by Roelands: the
    thesis's code writes it in log10 form with 4.2 (9.67/ln 10 = 4.19957, rounded), giving
    eta_p = 638.30 Pa s (§4.2: 638.29); camcontact's Roelands law keeps 9.67 in the ln form and
    gives 637.60 Pa s (-0.11 %), so T_maxL is 130.48 °C here against the thesis's 130.51 — the
    printed 130.5 either way. As the reference notes (erratum 15), T_maxL is a temperature rise
    above the surface that the thesis compares with the grease's absolute limit (120 °C); the
    absolute mid-film maximum is T_max + T_maxL = 237.8 °C."""
    import math

    import camcontact as cc
    from camcontact.contact.contact_temperature import couette_temperature_rise, flash_temperature

    kelley = cc.registry.get("friction_models", "kelley")
    mu = kelley({"normal_force": F_N, "contact_length": LENGTH, "eta0": chain["eta"], "u1": U1, "u2": U2})[
        "friction_coefficient"]
    assert mu == pytest.approx(0.03748, abs=5e-6) and round(mu, 3) == 0.037
    steel = cc.Material(E="200 GPa", nu=0.3, density="7810 kg/m^3", specific_heat="464 J/(kg K)",
                        thermal_conductivity="42.4 W/(m K)")
    e = steel.thermal_effusivity()
    assert e == pytest.approx(12395.6, abs=0.05)
    T_F = flash_temperature(F_N / LENGTH, chain["E_red"], chain["R"], mu, U1, U2, e, e)
    assert T_F == pytest.approx(22.4234, abs=5e-4) and round(T_F, 2) == 22.42
    T_max = 84.9 + T_F
    assert T_max == pytest.approx(107.3234, abs=5e-4) and round(T_max, 1) == 107.3
    eta_p = chain["eta"] * Roelands().viscosity_ratio(chain["hertz"].p_mean, chain["eta"], chain["alpha"])
    assert eta_p == pytest.approx(638.29, rel=2e-3)
    beta = chain["law"].thermoviscous_coefficient(T_WORK)
    assert beta == pytest.approx(0.03405, abs=5e-6)
    rise = couette_temperature_rise(beta, abs(U1 - U2), eta_p, chain["k"])
    assert rise == pytest.approx(130.51, abs=0.05) and round(rise, 1) == 130.5
    assert T_max + rise == pytest.approx(237.8, abs=0.1)
    assert math.isclose(rise - 120.0, 10.5, abs_tol=0.05)  # "T_sup exceeded by 10.5 °C" (§4.1)
