"""Hertz line and elliptical contact, approach and subsurface stresses against published values."""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from camcontact.contact.geometry import reduced_modulus, reduced_radius, relative_curvature
from camcontact.contact.hertz_elliptical import ellipticity_exact, hertz_elliptical
from camcontact.contact.hertz_line import hertz_line, line_approach
from camcontact.contact.subsurface import line_contact_stresses, line_subsurface
from camcontact.errors import InputError

# Saccheto (2008) Tabela 3.1 (Hertz/Timoshenko m, n coefficients), reference §3.5.
THETA = [30, 35, 40, 45, 50, 55, 60, 65, 70, 75, 80, 85, 90]
M_TABLE = [2.731, 2.397, 2.136, 1.926, 1.754, 1.611, 1.486, 1.378, 1.284, 1.202, 1.128, 1.061, 1.000]
N_TABLE = [0.493, 0.530, 0.567, 0.604, 0.641, 0.678, 0.717, 0.759, 0.802, 0.846, 0.893, 0.944, 1.000]


def _m_n(theta_deg):
    c = math.cos(math.radians(theta_deg))
    ratio = (1 + c) / (1 - c) if theta_deg != 90 else 1.0  # cos(theta) = (B - A)/(A + B)
    kappa, _, big_e = ellipticity_exact(ratio)
    m = (2 * kappa**2 * big_e / math.pi) ** (1 / 3)  # a = m (3 F R / E')^(1/3)
    return m, m / kappa


@pytest.mark.parametrize("theta, m_table, n_table", list(zip(THETA, M_TABLE, N_TABLE)))
def test_timoshenko_m_n_table(theta, m_table, n_table):
    """Saccheto (2008) Tabela 3.1. The reference (§3.5) says exact integrals reproduce it within ±0.002;
    the largest difference is n(70°) = 0.7999 vs the printed 0.802 (0.0021), so ±0.0025 is used."""
    m, n = _m_n(theta)
    assert m == pytest.approx(m_table, abs=0.0025)
    assert n == pytest.approx(n_table, abs=0.0025)


def test_timoshenko_table_20_degrees_is_off_by_one_percent():
    """The printed 20° entry (3.778, 0.408) is ~1 % off the exact 3.816, 0.412 (reference §3.5)."""
    m, n = _m_n(20)
    assert m == pytest.approx(3.816, abs=0.001) and n == pytest.approx(0.412, abs=0.001)
    assert abs(m - 3.778) / 3.778 == pytest.approx(0.010, abs=0.001)


def test_circular_contact_equals_johnson_closed_form():
    """Sphere on flat: a = (3FR/(4E*))^(1/3), p0 = 3F/(2 pi a^2), delta = a^2/R (Johnson 1985 §4.2)."""
    F, R, E_red = 1000.0, 0.01, 2.3077e11
    result = hertz_elliptical(F, R, R, E_red)
    a = (3 * F * R / (4 * E_red / 2)) ** (1 / 3)
    assert result.a_x == pytest.approx(a, rel=1e-12) and result.a_y == pytest.approx(a, rel=1e-12)
    assert result.p_max == pytest.approx(3 * F / (2 * math.pi * a * a), rel=1e-12)
    assert result.approach == pytest.approx(a * a / R, rel=1e-12)


def _eng_tools_6206():
    """eng-tools.dev 'Hertz contact' quick example: 6206 ball/inner race, Fr = 1000 N, Z = 9,
    D = 9.525 mm, inner groove radius 4.89 mm, pitch 46.0 mm, E = 210 GPa, nu = 0.3;
    ball load Q = 5 Fr / Z (Stribeck)."""
    D, r_groove, dm = 9.525e-3, 4.89e-3, 46.0e-3
    Rx = D * (dm - D) / (2 * dm)
    Ry = r_groove * D / (2 * r_groove - D)
    E_red = reduced_modulus(210e9, 0.3, 210e9, 0.3)
    return 5 * 1000.0 / 9, Rx, Ry, E_red


def test_published_calculator_example_brewe_hamrock_1977():
    """Printed: k = 12.19, a x b = 1.368 x 0.112 mm, p0 = 1728 MPa (1977 fits)."""
    F, Rx, Ry, E_red = _eng_tools_6206()
    result = hertz_elliptical(F, Rx, Ry, E_red, method="brewe_hamrock_1977")
    assert result.kappa == pytest.approx(12.19, abs=0.005)
    assert result.a_y * 1e3 == pytest.approx(1.368, abs=0.0005)
    assert result.a_x * 1e3 == pytest.approx(0.112, abs=0.0005)
    assert result.p_max * 1e-6 == pytest.approx(1728, abs=0.5)


def test_exact_solution_of_the_same_example_differs_by_the_fit_error():
    """Exact elliptic integrals for the same inputs give k = 11.834, p0 = 1746 MPa (helper check)."""
    F, Rx, Ry, E_red = _eng_tools_6206()
    exact = hertz_elliptical(F, Rx, Ry, E_red)
    assert exact.kappa == pytest.approx(11.834, abs=0.001)
    assert exact.p_max * 1e-6 == pytest.approx(1746.0, abs=0.5)
    # and the exact kappa satisfies the Hertz relation r = (k^2 E - K)/(K - E) directly
    k, K, E = exact.kappa, exact.elliptic_K, exact.elliptic_E
    assert (k * k * E - K) / (K - E) == pytest.approx(Ry / Rx, rel=1e-10)


@pytest.mark.parametrize("ratio", [1.0, 2.0, 5.0, 10.0, 50.0, 100.0])
def test_hamrock_brewe_fits_accuracy(ratio):
    """Hamrock & Brewe (1983) fits: a within 3 % and the approach within 5 % of exact for r <= 100."""
    exact = hertz_elliptical(100.0, 0.01, 0.01 * ratio, 2.3e11)
    fit = hertz_elliptical(100.0, 0.01, 0.01 * ratio, 2.3e11, method="hamrock_brewe")
    assert fit.a_y == pytest.approx(exact.a_y, rel=0.03)
    assert fit.approach == pytest.approx(exact.approach, rel=0.05)


def test_major_axis_follows_the_larger_radius():
    along_y = hertz_elliptical(100.0, 0.01, 0.05, 2.3e11)
    along_x = hertz_elliptical(100.0, 0.05, 0.01, 2.3e11)
    assert along_y.a_y > along_y.a_x and along_x.a_x > along_x.a_y
    assert along_y.a_y == pytest.approx(along_x.a_x, rel=1e-14)


def test_relative_curvature_reduces_to_sums_when_aligned():
    a, b = relative_curvature(0.01, 0.02, 0.03, math.inf, psi=0.0)
    assert {round(a, 12), round(b, 12)} == {round(1 / (1 / 0.02), 12), round(1 / (1 / 0.01 + 1 / 0.03), 12)}


def test_reduced_radius_of_concave_race_and_errors():
    """Delabenetta (2021) erratum 2: concave outer race R' = 1/(1/13.5 - 1/149) mm -> R_x = 2R' = 29.69 mm."""
    assert 2 * reduced_radius(0.0135, -0.149) * 1e3 == pytest.approx(29.69, abs=0.01)
    with pytest.raises(InputError, match="conforming"):
        reduced_radius(0.01, -0.005)


def test_line_contact_hertz_delabenetta_table7():
    """Delabenetta (2021) Table 7 / reference §4.2: a = 1.862393e-4 m, p0 = 8.266721e8 Pa,
    p_m = 6.492667e8 Pa for Fn = 10 kN, l = 41.35 mm, R1 = 149 mm, R2 = 13.5 mm (convex sum),
    E = 200 GPa, nu = 0.3 (E* = 1.098901e11 Pa)."""
    E_red = reduced_modulus(200e9, 0.3, 200e9, 0.3)
    assert E_red / 2 == pytest.approx(1.098901e11, rel=1e-6)
    result = hertz_line(10e3 / 41.35e-3, reduced_radius(0.149, 0.0135), E_red)
    assert result.b == pytest.approx(1.862393e-4, rel=1e-6)
    assert result.p_h == pytest.approx(8.266721e8, rel=1e-6)
    assert result.p_mean == pytest.approx(6.492667e8, rel=1e-6)


def test_palmgren_approach_tsuha_eq_4_19():
    """Tsuha (2015) Eq. 4.19 at F = 1000 N, l = 15 mm, E' = 2.3077e11 Pa: 2.171 um (reference §2.10,
    derived); Harris' steel rule 3.84e-5 Q^0.9 / l^0.8 mm gives 2.205 um, 1.6 % more."""
    delta = line_approach("palmgren", E_reduced=2.3077e11, force=1000.0, length=0.015)
    assert delta * 1e6 == pytest.approx(2.17, abs=0.01)
    harris = 3.84e-5 * 1000.0**0.9 / 15.0**0.8 * 1e-3
    assert delta == pytest.approx(harris, rel=0.02)


def test_hamrock_line_approach_equals_logarithmic_form():
    """delta = (2w/(pi E'))[ln(2 pi E' R/w) - 1] = (2w/(pi E'))[2 ln(4R/b) - 1]: 2.923 um for
    1 kN over 10 mm, R = 7.5 mm, E = 210 GPa (helper's independent table)."""
    E_red = reduced_modulus(210e9, 0.3, 210e9, 0.3)
    w, R = 1e5, 7.5e-3
    delta = line_approach("hamrock", E_reduced=E_red, w=w, R=R)
    b = hertz_line(w, R, E_red).b
    assert delta == pytest.approx(2 * w / (math.pi * E_red) * (2 * math.log(4 * R / b) - 1), rel=1e-12)
    assert delta * 1e6 == pytest.approx(2.923, abs=0.001)


# -------------------------------------------------------------------- subsurface stresses
def _flamant(x, z, mu):
    """Direct quadrature of the Flamant line-load solution (Johnson 1985 Eq. 2.23) for the
    Hertz pressure p0 sqrt(1 - s^2) and traction mu p (b = p0 = 1)."""
    def p(s):
        return math.sqrt(max(1 - s * s, 0.0))

    def integral(kernel):
        return quad(lambda s: p(s) * kernel(x - s), -1, 1, limit=200, points=[x] if -1 < x < 1 else None)[0]

    r4 = lambda d: (d * d + z * z) ** 2  # noqa: E731
    sx = -2 * z / math.pi * integral(lambda d: d * d / r4(d)) - 2 * mu / math.pi * integral(lambda d: d**3 / r4(d))
    sz = -2 * z**3 / math.pi * integral(lambda d: 1 / r4(d)) - 2 * z * z * mu / math.pi * integral(lambda d: d / r4(d))
    txz = -2 * z * z / math.pi * integral(lambda d: d / r4(d)) - 2 * z * mu / math.pi * integral(lambda d: d * d / r4(d))
    return sx, sz, txz


@pytest.mark.parametrize("mu", [0.0, 0.1, 0.3])
@pytest.mark.parametrize("x, z", [(0.0, 0.5), (0.5, 0.3), (-0.8, 0.7), (1.3, 0.4), (0.2, 1.5)])
def test_closed_form_field_equals_flamant_quadrature(x, z, mu):
    field = line_contact_stresses(x, z, 1.0, 1.0, friction=mu)
    sx, sz, txz = _flamant(x, z, mu)
    assert float(field["sigma_x"]) == pytest.approx(sx, abs=1e-8)
    assert float(field["sigma_z"]) == pytest.approx(sz, abs=1e-8)
    assert float(field["tau_xz"]) == pytest.approx(txz, abs=1e-8)


def test_frictionless_extremes_classical_values():
    """0.300 p0 at z = 0.786 b (CRC Mechanical Engineering Handbook; Delabenetta Eq. 7: 0.30,
    0.7861); |tau_xz| = 0.25 p0 at x = +-0.866 b, z = 0.5 b (Johnson 1985 §4.2; Saccheto §3.3)."""
    result = line_subsurface(1.0, 1.0)
    assert result.principal_shear_max.value == pytest.approx(0.3003, abs=1e-4)
    assert result.principal_shear_max.z == pytest.approx(0.7861, abs=2e-4)
    assert result.tau_xz_max.value == pytest.approx(0.25, abs=1e-6)
    assert abs(result.tau_xz_max.x) == pytest.approx(math.sqrt(3) / 2, abs=1e-4)
    assert result.tau_xz_max.z == pytest.approx(0.5, abs=1e-4)
    assert result.orthogonal_shear_range == pytest.approx(0.5, abs=1e-6)


def test_on_axis_principal_shear_closed_form():
    """On x = 0: tau_1/p0 = zeta (1 - zeta/sqrt(1 + zeta^2)) (from the m, n form at x = 0)."""
    zeta = np.linspace(0.01, 3.0, 50)
    tau = line_contact_stresses(np.zeros_like(zeta), zeta, 1.0, 1.0)["principal_shear"]
    np.testing.assert_allclose(tau, zeta * (1 - zeta / np.sqrt(1 + zeta**2)), rtol=1e-12)


def test_von_mises_against_green_2005_fit():
    """Green (2005) Int. J. Appl. Mech. Eng. 10(3):451 fits: p0/sigma_VM = 1.164 + 2.975 nu - 2.906 nu^2,
    depth 0.223 + 2.321 nu - 2.397 nu^2 (fit accuracy ~0.1 %)."""
    for nu in (0.25, 0.3):
        result = line_subsurface(1.0, 1.0, nu=nu)
        assert result.von_mises_max.value == pytest.approx(1 / (1.164 + 2.975 * nu - 2.906 * nu**2), rel=2e-3)
        assert result.von_mises_max.z == pytest.approx(0.223 + 2.321 * nu - 2.397 * nu**2, abs=3e-3)


def test_friction_moves_the_maximum_towards_the_surface():
    """With traction the peak grows and rises. On the surface inside the contact tau_1 = mu p0 exactly:
    there sigma_z = -p, sigma_x = -p - 2 mu p0 x/b and tau_xz = -mu p, so
    ((sigma_x - sigma_z)/2)^2 + tau_xz^2 = mu^2 p0^2 (x^2/b^2 + 1 - x^2/b^2)."""
    depths = [line_subsurface(1.0, 1.0, friction=mu).principal_shear_max.z for mu in (0.0, 0.1, 0.2, 0.25)]
    assert all(d2 < d1 for d1, d2 in zip(depths, depths[1:]))
    surface = line_contact_stresses(np.linspace(-0.9, 0.9, 7), np.zeros(7), 1.0, 1.0, friction=0.2)
    np.testing.assert_allclose(surface["principal_shear"], 0.2, atol=1e-12)


def test_subsurface_bad_input():
    with pytest.raises(InputError, match="friction = 1.5 out of range"):
        line_subsurface(1.0, 1.0, friction=1.5)
    with pytest.raises(InputError, match="depth z must be >= 0"):
        line_contact_stresses(0.0, -1.0, 1.0, 1.0)


@pytest.mark.parametrize("Rx, Ry", [(5.588e-3, 7e-3), (7e-3, 5.588e-3), (0.01, 0.01), (2e-3, 0.02)])
def test_timoshenko_table_route_matches_the_exact_solution(Rx, Ry):
    """Saccheto (2008) Eqs. 3.42-3.44 with its Tabela 3.1 (method "timoshenko_table") against the exact
    elliptic integrals: the table holds m, n to about +-0.002 (reference §3.5), so the semi-axes agree
    to 0.3 % and the pressure to 0.6 %; the ball-cone contact of the thesis (r = 7 mm on a 30 deg cone
    at R_cont = 24 mm: Rx = 5.588 mm, Ry = 7 mm) is one of the cases."""
    exact = hertz_elliptical(1250.0, Rx, Ry, 2 * 207e9 / (2 * (1 - 0.09)))
    table = hertz_elliptical(1250.0, Rx, Ry, 2 * 207e9 / (2 * (1 - 0.09)), method="timoshenko_table")
    assert table.a_x == pytest.approx(exact.a_x, rel=3e-3) and table.a_y == pytest.approx(exact.a_y, rel=3e-3)
    assert table.p_max == pytest.approx(exact.p_max, rel=6e-3)
    assert table.approach == pytest.approx(exact.approach, rel=1e-2)


def test_timoshenko_table_refuses_contacts_beyond_it():
    """Radius ratio 40: theta = arccos(39/41) = 18 deg, below the table's 20 deg."""
    with pytest.raises(InputError, match="outside the table"):
        hertz_elliptical(100.0, 1e-3, 0.04, 2.3e11, method="timoshenko_table")
