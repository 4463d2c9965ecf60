"""Kalker's creepage coefficients (Saccheto 2008 Tabela 5.1) and FASTSIM against Kalker's theory.

Sources: Saccheto (2008) §5.5, Eqs 5.44–5.49, Tabela 5.1 (reference ``ball_cone_cvt_saccheto2008.md``
§2.8, §3.6 and the errata table); Kalker (1982) Vehicle System Dynamics 11:1–13.

The contact inputs (a = 1 mm along rolling, b = 0.5 mm, N = 1 kN) are arbitrary illustrative
values: the thesis prints no contact semi-axis (reference, "Read this first"). G is the steel the
thesis implies (reference §4.6: E ~ 207 GPa, nu = 0.3). Note that FASTSIM's flexibilities are
*defined* so that its stick solution carries Kalker's linear forces (Eqs 5.48–5.49); the
small-creepage tests therefore check the discretisation and the sign conventions, and the
saturation tests check the Coulomb part against an independent semi-analytic calculation.
"""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from camcontact.contact.fastsim import GrossSlipError, fastsim, solve_creepage
from camcontact.contact.kalker import (
    TABELA_5_1,
    creepage_coefficients,
    dimensionless_flexibilities,
    flexibility_parameters,
)
from camcontact.models.traction import SACCHETO_MU_MIN, TRACTION_FLUIDS

A, B, N, MU = 1.0e-3, 0.5e-3, 1000.0, 0.1
G = 207e9 / (2 * 1.3)
C11, C22, C23 = creepage_coefficients(B / A)
L1, L2, L3 = flexibility_parameters(A, B, G)
NU_REF = MU * N / (C11 * G * A * B)  # creepage at which the linear Fx would reach mu N
PHI_REF = MU * N / (C23 * G * (A * B) ** 1.5)  # spin creepage at which the linear Fy would reach mu N
GRIDS = (10, 20, 40, 80)


# ----------------------------------------------------------------- Tabela 5.1
@pytest.mark.parametrize("row", TABELA_5_1, ids=lambda row: f"b/a={row.b_over_a}")
def test_tabulated_coefficients_are_returned_exactly(row):
    """Saccheto (2008) Tabela 5.1: at a tabulated b/a the printed C11, C22, C23."""
    assert creepage_coefficients(row.b_over_a) == (row.C11, row.C22, row.C23)


def test_interpolation_is_linear_in_log_b_over_a():
    """Half-way in ln(b/a) between 0.1 and 0.3 (b/a = sqrt(0.03)) gives the mean of the two rows."""
    first, second = TABELA_5_1[0], TABELA_5_1[1]
    expected = tuple(0.5 * (getattr(first, c) + getattr(second, c)) for c in ("C11", "C22", "C23"))
    assert creepage_coefficients(math.sqrt(0.1 * 0.3)) == pytest.approx(expected, rel=1e-14)


@pytest.mark.parametrize("row", TABELA_5_1, ids=lambda row: f"b/a={row.b_over_a}")
def test_printed_flexibilities_follow_from_the_coefficients(row):
    """Table consistency: L1 G/a = 8/(3 C11), L2 G/a = 8/(3 C22), L3 G/a = pi sqrt(a/b)/(4 C23)
    hold to the printed 2 decimals (+-0.005), except L1 G/a at b/a = 1 (next test)."""
    l1, l2, l3 = dimensionless_flexibilities(row.C11, row.C22, row.C23, row.b_over_a)
    if row.b_over_a != 1.0:
        assert l1 == pytest.approx(row.L1G_over_a, abs=0.005)
    assert l2 == pytest.approx(row.L2G_over_a, abs=0.005)
    assert l3 == pytest.approx(row.L3G_over_a, abs=0.005)


def test_tabela_5_1_erratum_L1_at_b_over_a_1():
    """Errata table, "Tabela 5.1": L1 G/a is printed 0.62 at b/a = 1, but 8/(3 x 4.10) = 0.650.
    Both stay visible; the library computes L from C (0.650), never from the printed column."""
    row = TABELA_5_1[2]
    assert (row.b_over_a, row.L1G_over_a, row.C11) == (1.0, 0.62, 4.10)
    computed = dimensionless_flexibilities(row.C11, row.C22, row.C23, 1.0)[0]
    assert computed == pytest.approx(0.6504, abs=5e-5)
    assert abs(computed - row.L1G_over_a) > 0.03  # not a rounding difference
    assert flexibility_parameters(1.0, 1.0, 1.0)[0] == pytest.approx(computed, rel=1e-14)


# ----------------------------------------------------------------- small creepage: Kalker's linear theory
def _linear_errors(creepages, linear, component):
    errors = []
    for n in GRIDS:
        result = fastsim(A, B, N, MU, G, *creepages, nx=n, ny=n)
        assert result.full_stick  # creepage small enough that no element reaches mu p
        errors.append(getattr(result, component) / linear - 1.0)
    return errors


@pytest.mark.parametrize("component, creepages, linear", [
    ("Fx", (1e-3 * NU_REF, 0.0, 0.0), -C11 * G * A * B * 1e-3 * NU_REF),
    ("Fy", (0.0, 1e-3 * NU_REF, 0.0), -C22 * G * A * B * 1e-3 * NU_REF),
])
def test_small_creepage_gives_kalker_linear_force(component, creepages, linear):
    """(a) Eqs 5.48–5.49: Fx = -C11 G a b nu_x, Fy = -C22 G a b nu_y (force on the body opposes
    the creepage). The sampled stick tractions are exact, so the only error is the mid-point rule
    in y on int (1 - y^2/b^2) dy: it overestimates by h^2/(6b) on 4b/3, i.e. exactly 1/(2 ny^2)
    relative (0.5 %, 0.125 %, 0.031 %, 0.0078 % on 10^2..80^2 grids)."""
    errors = _linear_errors(creepages, linear, component)
    np.testing.assert_allclose(errors, [1.0 / (2 * n * n) for n in GRIDS], rtol=1e-6)
    assert abs(errors[GRIDS.index(40)]) < 0.01  # the default 40 x 40 grid: well inside 1 %


def test_small_spin_gives_kalker_linear_lateral_force():
    """(a) Eq. 5.49: pure spin Fy = -C23 G (ab)^1.5 phi. Measured errors 0.65 %, 0.15 %, 0.036 %,
    0.0086 % on 10^2..80^2 grids: below 1 % from 10 x 10 and falling ~4x per doubling (the
    mid-point rules on x^2 - a(y)^2 and on (1 - y^2/b^2)^1.5)."""
    phi = 1e-3 * PHI_REF
    errors = _linear_errors((0.0, 0.0, phi), -C23 * G * (A * B) ** 1.5 * phi, "Fy")
    assert all(0.0 < e < 0.01 for e in errors)
    assert all(e1 / e2 > 3.5 for e1, e2 in zip(errors, errors[1:]))


def test_stick_tractions_are_the_corrected_eqs_5_46_5_47():
    """Errata "Eqs 5.46/5.47": in stick T_x = (nu_x/L1 - phi y/L3)(x - a(y)) and
    T_y = (nu_y/L2)(x - a(y)) + (phi/(2 L3))(x^2 - a(y)^2); the marching scheme reproduces them at
    the element centres to rounding (its spin increment is taken at each step's mid-point)."""
    nu_x, nu_y, phi = 1e-3 * NU_REF, -2e-3 * NU_REF, 1e-3 * PHI_REF
    result = fastsim(A, B, N, MU, G, nu_x, nu_y, phi, nx=17, ny=13)
    assert result.full_stick
    x, y = result.x, result.y[:, None]
    edge = A * np.sqrt(1.0 - (y / B) ** 2)
    Tx = (nu_x / L1 - phi * y / L3) * (x - edge)
    Ty = nu_y / L2 * (x - edge) + phi / (2 * L3) * (x**2 - edge**2)
    scale = np.max(np.abs(Tx)) + np.max(np.abs(Ty))
    np.testing.assert_allclose(result.Tx, Tx, rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(result.Ty, Ty, rtol=0, atol=1e-12 * scale)


def test_spin_moment_in_stick():
    """Mz = int (x T_y - y T_x) dA with the stick tractions above and pure spin: the x T_y part
    integrates to 0 (odd in x) and -y T_x = (phi/L3) y^2 (x - a(y)) integrates to
    -(2 phi a^2/L3) int y^2 (1 - y^2/b^2) dy = -8 phi a^2 b^3/(15 L3) (independent calculation; the
    spin moment is not in the thesis). The sums over x are exact; the mid-point rule in y on the
    quartic f = y^2 - y^4/b^2 overestimates by exactly 2.5/ny^2 - 3.5/ny^4 relative (Euler-Maclaurin:
    -(h^2/24) [f'] + (7 h^4/5760) [f'''] with h = 2b/ny), i.e. 0.156 % at the default 40 x 40."""
    phi = 1e-3 * PHI_REF
    expected = -8.0 * phi * A**2 * B**3 / (15.0 * L3)
    for n in GRIDS:
        result = fastsim(A, B, N, MU, G, spin=phi, nx=n, ny=n)
        assert result.full_stick
        assert result.Mz == pytest.approx(expected * (1 + 2.5 / n**2 - 3.5 / n**4), rel=1e-9)


# ----------------------------------------------------------------- large creepage: Coulomb saturation
def _continuum_fx(nu):
    """Continuum FASTSIM Fx for pure longitudinal creepage with the Hertz bound (``pressure="hertz"``;
    independent semi-analytic calculation; the parabolic bound's closed form is checked in
    tests/unit/test_fastsim_pressure.py).

    On the strip at y (half-length a_y, pressure P_y sqrt(1 - x^2/a_y^2), P_y = 3N/(2 pi a b)
    sqrt(1 - y^2/b^2)) the stick traction k s (k = nu/L1, s = a_y - x the distance from the
    leading edge) meets the bound mu P_y sqrt(s (2 a_y - s))/a_y at s* = 2 a_y c/(k^2 + c),
    c = (mu P_y/a_y)^2; behind it the strip slips all the way (the bound is concave) with |T| = mu p.
    Strip force: k s*^2/2 + mu P_y a_y [g(1 - s*/a_y) + pi/4], g(t) = (t sqrt(1 - t^2) + asin t)/2.
    """
    k, p0 = nu / L1, 3.0 * N / (2.0 * math.pi * A * B)

    def strip(y):
        half, peak = A * math.sqrt(1 - (y / B) ** 2), p0 * math.sqrt(1 - (y / B) ** 2)
        c = (MU * peak / half) ** 2
        s = 2 * half * c / (k * k + c)
        t = 1.0 - s / half
        g = (t * math.sqrt(max(1.0 - t * t, 0.0)) + math.asin(t)) / 2
        return k * s * s / 2 + MU * peak * half * (g + math.pi / 4)

    return -quad(strip, -B, B, epsabs=0.0, epsrel=1e-12, limit=200)[0]


@pytest.mark.parametrize("multiple", [0.5, 1.0, 2.0, 3.0])
def test_creep_force_curve_converges_to_the_continuum_solution(multiple):
    """(b) Partial slip with the Hertz bound (``pressure="hertz"``; the default is Kalker's parabolic
    bound since issue 17): the discrete Fx converges to the semi-analytic continuum value. Measured
    relative differences at 40^2 / 160^2: 0.16 %/0.017 % (0.5 nu_ref), 0.048 %/0.004 % (1),
    0.003 %/0.004 % (2), 0.04 %/0.005 % (3); allowed 0.5 % at the default grid, 0.05 % at 160^2."""
    nu = multiple * NU_REF
    reference = _continuum_fx(nu)
    assert max(-MU * N, -C11 * G * A * B * nu) < reference < 0.0  # below both the Coulomb and the linear force
    assert fastsim(A, B, N, MU, G, nu, pressure="hertz").Fx == pytest.approx(reference, rel=5e-3)
    assert fastsim(A, B, N, MU, G, nu, nx=160, ny=160, pressure="hertz").Fx == pytest.approx(reference, rel=5e-4)


def test_large_creepage_saturates_at_mu_n():
    """(b) nu_x = 50 nu_ref: every element slips in -x, so Fx = -mu N exactly (the sampled pressure
    carries N exactly) and the slip fraction is 1; the slip fraction grows monotonically with nu."""
    result = fastsim(A, B, N, MU, G, 50 * NU_REF)
    assert result.full_slip and result.slip_fraction == 1.0
    assert result.Fx == pytest.approx(-MU * N, rel=1e-12)
    assert result.traction_ratio == pytest.approx(1.0, rel=1e-12)
    fractions = [fastsim(A, B, N, MU, G, m * NU_REF).slip_fraction for m in (0.3, 1, 2, 5, 20)]
    assert fractions == sorted(fractions) and fractions[-1] == 1.0


def test_spin_takes_part_of_the_adhesion():
    """With spin, |F| < mu N at any finite creepage (part of the bound is spent on the spin traction)
    and |F|/(mu N) -> 1 as nu_x -> infinity."""
    ratios = [fastsim(A, B, N, MU, G, m * NU_REF, 0.0, 2 * PHI_REF).traction_ratio for m in (1, 10, 100, 1000)]
    assert all(r < 1.0 for r in ratios) and ratios == sorted(ratios)
    assert ratios[-1] == pytest.approx(1.0, abs=1e-3)


# ----------------------------------------------------------------- the CVT use: traction needed vs available
@pytest.mark.parametrize("fluid", ["santotrac_40_50_70", "santotrac_50"])
def test_saccheto_mu_min_is_transmitted_by_traction_fluids(fluid):
    """Saccheto (2008) §7.3: the contact needs F_t/N = mu_min = 0.08813 (Eq. 6.19). With Ct = 0.100
    (Tabela 4.3) or 0.095 (Tabela 4.2) the inverse FASTSIM finds the creepage that transmits it,
    to 1e-9, with the traction ratio mu_min/Ct (0.8813, 0.9277)."""
    ct = TRACTION_FLUIDS[fluid].low
    required = -SACCHETO_MU_MIN * N  # force on the body; the creepage comes out positive
    solution = solve_creepage(required, A, B, N, ct, G, spin=0.5 * PHI_REF)
    assert solution.result.Fx == pytest.approx(required, rel=1e-9)
    assert solution.creepage > 0.0
    assert solution.result.traction_ratio >= SACCHETO_MU_MIN / ct  # plus the spin-induced Fy


def test_saccheto_mu_min_above_ct_is_gross_slip():
    """Saccheto (2008) §5 item 6 / Eq. 6.19 check mu_min < Ct: Santotrac 30 (Ct = 0.084, Tabela 4.3)
    cannot transmit mu_min = 0.08813: a clear GrossSlipError, never a NaN."""
    ct = TRACTION_FLUIDS["santotrac_30"].low
    with pytest.raises(GrossSlipError, match="mu_min"):
        solve_creepage(SACCHETO_MU_MIN * N, A, B, N, ct, G)
