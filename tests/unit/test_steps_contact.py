"""Contact step functions (camcontact.steps.contact) called alone, with plain SI inputs.

Expected values: the Hertz line-contact closed form b = sqrt(8 w R/(pi E')), p_h = 2 w/(pi b),
p_mean = pi p_h/4 (Johnson 1985 §4.3); Tsuha (2015) spot check p_h = 991.0 MPa, b = 132.25 um;
Delabenetta (2021) Table 7 (E* 109.89 GPa, R_x 0.0248 m, a 186.2393 um, P_m 649.27 MPa, P_o 826.67 MPa,
A_c 15.402 mm^2); Palmgren's steel roller deflection 3.84e-5 Q^0.9/l^0.8 [mm, N, mm]; the Hamrock–Brewe
(1983) elliptical closed forms and the exact elliptic-integral ellipticity relation.
"""

import math

import numpy as np
import pytest
from scipy import special

from camcontact.errors import InputError, ValidityWarning
from camcontact.steps.contact import (
    ball_cone_hertz,
    cycle_hertz,
    force_hertz,
    hamrock_approach,
    line_geometry,
    line_hertz,
    palmgren_approach,
    raceway_geometry,
    roller_hertz,
)
from step_checks import assert_provides

E_STEEL_210 = 210e9 / (1 - 0.3**2)  # E' of two 210 GPa, nu = 0.3 bodies


def hertz(w, R, E):
    """Independent Hertz line contact: (b, p_h, p_mean)."""
    b = math.sqrt(8 * w * R / (math.pi * E))
    p_h = 2 * w / (math.pi * b)
    return b, p_h, math.pi / 4 * p_h


# ----------------------------------------------------------------------------- geometry
def test_line_geometry_reduced_modulus_and_radius():
    """E' = 2/[(1 - nu1^2)/E1 + (1 - nu2^2)/E2]; 1/R = 1/R1 + 1/R2 (flat: inf; concave: negative)."""
    out = line_geometry(210e9, 0.3, 70e9, 0.33, 0.02, 0.01)
    assert_provides(line_geometry, out)
    assert out["E_reduced"] == pytest.approx(2 / ((1 - 0.09) / 210e9 + (1 - 0.33**2) / 70e9), rel=1e-12)
    assert out["R"] == pytest.approx(0.02 * 0.01 / 0.03, rel=1e-12)
    assert line_geometry(210e9, 0.3, 210e9, 0.3, 0.02, math.inf)["R"] == pytest.approx(0.02)
    assert line_geometry(210e9, 0.3, 210e9, 0.3, 0.01, -0.05)["R"] == pytest.approx(1 / (100 - 20))


def test_line_geometry_conforming_surfaces_are_refused():
    """A concave radius tighter than the convex one: curvature sum <= 0, no Hertz contact -> InputError."""
    with pytest.raises(InputError, match="conforming"):
        line_geometry(210e9, 0.3, 210e9, 0.3, 0.05, -0.01)


def test_raceway_geometry_delabenetta_table_7():
    """Delabenetta (2021) Table 7 with its inputs (200 GPa steel, raceway 149 mm, roller 13.5 mm, the
    thesis's convex sum): E* = E'/2 = 109.89 GPa, R_x = 2R = 0.0248 m; concave outer race: 1/R = 1/R2 - 1/R1."""
    out = raceway_geometry(200e9, 0.3, 200e9, 0.3, 0.149, 0.0135, False)
    assert_provides(raceway_geometry, out)
    assert round(out["E_star"] * 1e-9, 2) == 109.89
    assert round(out["R_x"], 4) == 0.0248
    assert out["R_x"] == pytest.approx(2 / (1 / 0.149 + 1 / 0.0135), rel=1e-12)
    assert out["E_reduced"] == pytest.approx(2 * out["E_star"])
    concave = raceway_geometry(200e9, 0.3, 200e9, 0.3, 0.149, 0.0135, True)
    assert concave["R"] == pytest.approx(1 / (1 / 0.0135 - 1 / 0.149), rel=1e-12)


# ----------------------------------------------------------------------------- Hertz line contact
def test_line_hertz_closed_form():
    """w = 1e5 N/m, R = 10 mm, E' = 2.3e11 Pa: the closed form above; p_h = 605.0 MPa (the package's
    documented example, = sqrt(w E'/(2 pi R)))."""
    out = line_hertz(1e5, 0.01, 2.3e11)
    assert_provides(line_hertz, out)
    b, p_h, p_mean = hertz(1e5, 0.01, 2.3e11)
    assert out["b"] == pytest.approx(b, rel=1e-12)
    assert out["p_h"] == pytest.approx(p_h, rel=1e-12)
    assert out["p_mean"] == pytest.approx(p_mean, rel=1e-12)
    assert out["p_h"] == pytest.approx(math.sqrt(1e5 * 2.3e11 / (2 * math.pi * 0.01)), rel=1e-12)
    assert round(out["p_h"] / 1e6, 1) == 605.0


def test_line_hertz_refuses_no_load():
    """w = 0: no Hertz contact (InputError naming the load)."""
    with pytest.raises(InputError, match="load per length"):
        line_hertz(0.0, 0.01, 2.3e11)


def test_force_hertz_delabenetta_table_7():
    """F = 10 kN on l = 41.35 mm (Delabenetta 2021): a = 186.2393 um (§4.2 full precision), P_m = 649.27 MPa,
    P_o = 826.67 MPa, A_c = 2 a l = 15.402 mm^2 (Table 7)."""
    geometry = raceway_geometry(200e9, 0.3, 200e9, 0.3, 0.149, 0.0135, False)
    out = force_hertz(10e3, 0.04135, geometry["R"], geometry["E_reduced"])
    assert_provides(force_hertz, out)
    assert out["w"] == pytest.approx(10e3 / 0.04135, rel=1e-12)
    assert out["b"] == pytest.approx(1.862393e-4, rel=1e-6)
    assert round(out["p_mean"] * 1e-6, 2) == 649.27
    assert round(out["p_h"] * 1e-6, 2) == 826.67
    assert out["contact_area"] * 1e6 == pytest.approx(15.402, abs=5e-4)


# ----------------------------------------------------------------------------- approach
def test_hamrock_approach_two_forms():
    """delta = (2w/(pi E'))[ln(2 pi E' R/w) - 1] = (2w/(pi E'))[2 ln(4R/b) - 1] with the Hertz b."""
    w, R = 2e5, 0.008
    out = hamrock_approach(w, R, E_STEEL_210)
    assert_provides(hamrock_approach, out)
    scale = 2 * w / (math.pi * E_STEEL_210)
    assert out["approach"] == pytest.approx(scale * (math.log(2 * math.pi * E_STEEL_210 * R / w) - 1), rel=1e-12)
    b = hertz(w, R, E_STEEL_210)[0]
    assert out["approach"] == pytest.approx(scale * (2 * math.log(4 * R / b) - 1), rel=1e-12)


def test_palmgren_approach_steel_roller():
    """3.81 (2/(pi E'))^0.9 F^0.9/l^0.8 (Tsuha Eq. 4.19); for steel rollers it is Palmgren's
    3.84e-5 Q^0.9/l^0.8 [mm, N, mm] (Harris) within 2 %."""
    F, length = 5e3, 0.02
    out = palmgren_approach(F, length, E_STEEL_210)
    assert_provides(palmgren_approach, out)
    assert out["approach"] == pytest.approx(3.81 * (2 / (math.pi * E_STEEL_210)) ** 0.9 * F**0.9 / length**0.8,
                                            rel=1e-12)
    assert out["approach"] * 1e3 == pytest.approx(3.84e-5 * F**0.9 / (length * 1e3) ** 0.8, rel=0.02)
    with pytest.raises(InputError, match="palmgren"):
        palmgren_approach(0.0, length, E_STEEL_210)


# ----------------------------------------------------------------------------- per cam angle / per roller
def test_cycle_hertz_tsuha_spot_check_and_unloaded_angles():
    """Tsuha (2015) reference §8 item 7: F = 3087.99 N on 15 mm, R = 7.69892 mm, E' of 210 GPa steel:
    p_h = 991.0 MPa, b = 132.25 um; per angle the closed form and Hamrock's approach; zero load -> zeros."""
    N = np.array([3087.99, 0.0, 1500.0])
    R = np.array([0.00769892, 0.008, 0.0095])
    out = cycle_hertz(N, 0.015, R, E_STEEL_210, np.radians([90.0, 200.0, 30.0]))
    assert_provides(cycle_hertz, out)
    assert out["p_h"][0] == pytest.approx(991.0e6, abs=0.05e6)
    assert out["b"][0] == pytest.approx(132.25e-6, abs=0.005e-6)
    np.testing.assert_allclose(out["w"], N / 0.015)
    assert out["b"][1] == 0.0 and out["p_h"][1] == 0.0 and out["approach"][1] == 0.0
    b, p_h, _ = hertz(1e5, 0.0095, E_STEEL_210)
    assert out["b"][2] == pytest.approx(b, rel=1e-12) and out["p_h"][2] == pytest.approx(p_h, rel=1e-12)
    assert out["approach"][2] == pytest.approx(
        2e5 / (math.pi * E_STEEL_210) * (math.log(2 * math.pi * E_STEEL_210 * 0.0095 / 1e5) - 1), rel=1e-12)


def test_roller_hertz_per_race_with_unloaded_rollers():
    """w = Q/l per roller, the rolling-direction radius of each race; NaN without load; p_h_max the peak
    (the inner race, with the smaller radius, has the higher pressure)."""
    Q = np.array([20e3, 0.0, 5e3])
    radii = {"inner": 0.0121, "outer": 0.0149}
    out = roller_hertz(Q, E_STEEL_210, radii, 0.04)
    assert_provides(roller_hertz, out)
    for race in ("inner", "outer"):
        for j in (0, 2):
            b, p_h, _ = hertz(Q[j] / 0.04, radii[race], E_STEEL_210)
            assert out[f"b_{race}"][j] == pytest.approx(b, rel=1e-12)
            assert out[f"p_h_{race}"][j] == pytest.approx(p_h, rel=1e-12)
        assert math.isnan(out[f"b_{race}"][1]) and math.isnan(out[f"p_h_{race}"][1])
    assert out["p_h_max"] == pytest.approx(hertz(5e5, 0.0121, E_STEEL_210)[1], rel=1e-12)
    assert roller_hertz(np.zeros(3), E_STEEL_210, radii, 0.04)["p_h_max"] == 0.0


# ----------------------------------------------------------------------------- ball on cone
def test_ball_cone_hertz_hamrock_brewe_closed_form():
    """Rx = 1/(1/r + cos(alpha)/R_cont), Ry = r; with the Hamrock–Brewe (1983) fits kappa = (Ry/Rx)^(2/pi),
    E = 1 + (pi/2 - 1)/r_ratio, K = pi/2 + (pi/2 - 1) ln r_ratio: a_major = (6 kappa^2 E F R/(pi E'))^(1/3)
    (along y, the larger radius), a_minor = (6 E F R/(pi kappa E'))^(1/3), p_max = 3F/(2 pi a b),
    delta = K [9/(2 E R) (F/(pi kappa E'))^2]^(1/3)."""
    F, r, alpha, Rc = 1254.0, 7e-3, math.radians(30), 24e-3
    E = 207e9 / (1 - 0.09)
    out = ball_cone_hertz(F, E, r, alpha, Rc, "hamrock_brewe", 4.2e9)
    assert_provides(ball_cone_hertz, out)
    Rx = 1 / (1 / r + math.cos(alpha) / Rc)
    ratio, R = r / Rx, 1 / (1 / Rx + 1 / r)
    kappa = ratio ** (2 / math.pi)
    big_e, big_k = 1 + (math.pi / 2 - 1) / ratio, math.pi / 2 + (math.pi / 2 - 1) * math.log(ratio)
    a_major = (6 * kappa**2 * big_e * F * R / (math.pi * E)) ** (1 / 3)
    a_minor = (6 * big_e * F * R / (math.pi * kappa * E)) ** (1 / 3)
    assert out["Rx"] == pytest.approx(Rx, rel=1e-12) and out["Ry"] == r
    assert out["a_transverse"] == pytest.approx(a_major, rel=1e-9)
    assert out["a_rolling"] == pytest.approx(a_minor, rel=1e-9)
    assert out["p_h"] == pytest.approx(3 * F / (2 * math.pi * a_major * a_minor), rel=1e-9)
    assert out["approach"] == pytest.approx(
        big_k * (4.5 / (big_e * R) * (F / (math.pi * kappa * E)) ** 2) ** (1 / 3), rel=1e-9)
    assert out["pressure_check"].startswith(f"p_h = {out['p_h'] * 1e-9:.3g} GPa above the thesis's 1.1 GPa")


def test_ball_cone_hertz_exact_ellipticity_and_threshold():
    """Exact method: the semi-axis ratio kappa satisfies Ry/Rx = (kappa^2 E(m) - K(m))/(K(m) - E(m)),
    m = 1 - 1/kappa^2 (scipy's complete elliptic integrals), p_h = 3F/(2 pi a b); a light load stays
    below the 1.1 GPa EHL threshold."""
    F, r, alpha, Rc = 1254.0, 7e-3, math.radians(30), 24e-3
    E = 207e9 / (1 - 0.09)
    out = ball_cone_hertz(F, E, r, alpha, Rc, "exact", 4.2e9)
    kappa = out["a_transverse"] / out["a_rolling"]
    m = 1 - kappa**-2
    K, Ee = special.ellipk(m), special.ellipe(m)
    assert (kappa**2 * Ee - K) / (K - Ee) == pytest.approx(out["Ry"] / out["Rx"], rel=1e-8)
    assert out["p_h"] == pytest.approx(1.5 * F / (math.pi * out["a_rolling"] * out["a_transverse"]), rel=1e-12)
    light = ball_cone_hertz(5.0, E, r, alpha, Rc, "exact", 4.2e9)
    assert "below the thesis's 1.1 GPa EHL threshold" in light["pressure_check"]
    # the stress limit (ISO 76 4.2 GPa by default in the component): 4.3 GPa at 1254 N exceeds it, with a warning
    assert not light["stress_limit_exceeded"] and out["stress_limit_exceeded"]
    with pytest.warns(ValidityWarning, match="exceeds the contact stress limit 4.2 GPa"):
        ball_cone_hertz(F, E, r, alpha, Rc, "exact", 4.2e9)
