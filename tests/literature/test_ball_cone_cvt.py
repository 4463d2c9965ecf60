"""Ball-cone CVT of Saccheto (2008): geometry, ratio, spin table, loads and mu_min.

Source: ../shared/reference/ball_cone_cvt_saccheto2008.md — Tabela A.1 (spin factors, §4.1) and its
exact reconstruction (§4.2, marked DERIVED there: r = 7 mm, R_1 = 23.28 mm), the overrange relation
and Tabela 7.3 cone angles (§2.10), the loads of §6.5 / Eqs. 6.11-6.19 and mu_min = 0.08813
(§2.11, §3.1 note on R_eixo).
"""

import math

import pytest

import camcontact as cc
from camcontact.components.ball_cone_cvt import BallConeCVT, LoadedBallConeCVT
from camcontact.dynamics.ball_cone_loads import ball_cone_loads, minimum_traction
from camcontact.dynamics.bicycle_load import cyclist_power, optimal_cadence
from camcontact.errors import InputError
from camcontact.kinematics.ball_cone import ball_cone_kinematics, ratio_of_tilt, spin_coefficients, tilt_of_ratio

STEEL = cc.Material(E="207 GPa", nu=0.3)
ALPHA = math.radians(30.0)


def forti(**changes):
    fields = dict(cone_angle="30 deg", cone_contact_radius="24 mm", ball_diameter="14 mm", ball_count=9,
                  tilt_max="30 deg", cam_ramp_angle="10 deg", cam_radius="6 mm", cam_ball_count=5, material=STEEL,
                  traction_coefficient=0.095, cone_small_diameter="42 mm")
    fields.update(changes)
    return BallConeCVT(**fields)


@pytest.mark.parametrize("rt, psi_in, psi_out", [(0.5, 0.5, 3.38), (1.0, 2.42, 2.42), (2.0, 3.38, 0.5)])
def test_spin_factor_table_a1(rt, psi_in, psi_out):
    """Tabela A.1 (printed to 2-3 digits; totals 3.88 / 4.84 / 3.88) with the reconstruction's
    R_1 = 23.28 mm (reference §4.2)."""
    beta = tilt_of_ratio(ALPHA, rt)
    a, b = spin_coefficients(7e-3, ALPHA, 23.28e-3, beta)
    assert round(a, 2) == psi_in and round(b, 2) == psi_out
    assert round(a + b, 2) == {0.5: 3.88, 1.0: 4.84, 2.0: 3.88}[rt]


def test_spin_reconstruction_predictions():
    """Reference §4.2 (DERIVED) rows: rt 0.75 -> beta 13.898 deg, BC 5.044, DE 6.725 mm, psi 1.780/2.900;
    rt 1.5 -> beta -19.107 deg, BC 6.874, DE 4.583 mm, psi 3.060/1.460."""
    for rt, beta_deg, bc, de, pin, pout in ((0.75, 13.898, 5.044, 6.725, 1.780, 2.900),
                                           (1.5, -19.107, 6.874, 4.583, 3.060, 1.460)):
        beta = tilt_of_ratio(ALPHA, rt)
        k = ball_cone_kinematics(7e-3, ALPHA, 23.28e-3, beta, 2 * math.pi)
        assert math.degrees(beta) == pytest.approx(beta_deg, abs=5e-4)
        assert k["rolling_radius_in"] * 1e3 == pytest.approx(bc, abs=5e-4)
        assert k["rolling_radius_out"] * 1e3 == pytest.approx(de, abs=5e-4)
        assert k["psi_in"] == pytest.approx(pin, abs=5e-3) and k["psi_out"] == pytest.approx(pout, abs=5e-3)


def test_ratio_tilt_and_thesis_equations():
    """Eq. 6.2 rt = (c1 - y tan beta)/(c1 + y tan beta) with y = r sin alpha, c1 = r cos alpha equals the
    closed form cos(alpha + beta)/cos(alpha - beta); Eq. 6.3 inverts it; the speed convention is the inverse."""
    r = 7e-3
    y, c1 = r * math.sin(ALPHA), r * math.cos(ALPHA)
    for beta_deg in (-30, -12.5, 0, 7, 30):
        beta = math.radians(beta_deg)
        rt = (c1 - y * math.tan(beta)) / (c1 + y * math.tan(beta))
        assert ratio_of_tilt(ALPHA, beta) == pytest.approx(rt, rel=1e-12)
        assert ratio_of_tilt(ALPHA, beta, "speed") == pytest.approx(1 / rt, rel=1e-12)
        assert math.tan(tilt_of_ratio(ALPHA, rt)) == pytest.approx(c1 * (1 - rt) / (y * (rt + 1)), abs=1e-12)


def test_overrange_and_tabela_7_3_cone_angles():
    """Overrange 4 / 6.25 / 9 with 2 beta_max = 60 deg needs alpha = 30 / 36.6 (~37) / 40.9 (~41) deg
    (Tabela 7.3; the sin(alpha) = y/r relation of reference §2.10 with Eqs. 6.8-6.10)."""
    tilt = math.radians(30)
    for value, alpha_deg, y_over_r in ((4.0, 30.0, 0.5), (6.25, 36.6, 0.5960), (9.0, 40.9, 0.6547)):
        alpha = BallConeCVT.cone_angle_for_overrange(value, tilt)
        assert math.degrees(alpha) == pytest.approx(alpha_deg, abs=0.05)
        assert math.sin(alpha) == pytest.approx(y_over_r, abs=5e-4)
    # Eq. 6.8 (overrange 4): y = sqrt(r^2/(9 tan^2 beta + 1)) = r/2 at beta_max = 30 deg
    assert math.sqrt(1 / (9 * math.tan(tilt) ** 2 + 1)) == pytest.approx(0.5)
    cvt = forti()
    assert cvt.overrange == pytest.approx(4.0) and cvt.ratio_range == pytest.approx((0.5, 2.0))


def test_mu_min_with_the_documented_cam_radius():
    """mu_min = tan(eta) R_eixo/(sin(alpha) R_cont) (Eq. 6.19) = 0.08813 in the thesis. Its Tabela 6.1
    prints R_eixo = 12 mm, which gives twice the value; R_eixo = 6 mm (12 mm read as a diameter) with
    R_cont = 24 mm gives 0.088163 — R_cont is not printed, and 24.009 mm would give 0.08813 exactly
    (reference §3.1 note). Both readings kept visible."""
    eta = math.radians(10)
    thesis = dict(clamping="thesis")
    assert minimum_traction(ALPHA, eta, 6e-3, 24e-3, **thesis) == pytest.approx(0.08813, rel=5e-4)
    assert minimum_traction(ALPHA, eta, 6e-3, 24.009e-3, **thesis) == pytest.approx(0.08813, abs=5e-6)
    assert minimum_traction(ALPHA, eta, 12e-3, 24e-3, **thesis) == pytest.approx(2 * 0.088163, rel=1e-4)
    # the default (axial balance) needs sin^2(alpha) = 1/4 of that: four times the normal force
    assert minimum_traction(ALPHA, eta, 6e-3, 24e-3) == pytest.approx(0.088163 * 0.25, rel=1e-4)


def test_loads_at_150_w():
    """150 W at 60 rpm: T = 23.873 N m; F_t = T/(R_cont n) = 110.5 N; F_n (Eq. 6.17) = 1254 N — the
    thesis's "about 1200 N at 150 W" (reference §3.1 note); F_t/F_n = mu_min; Eq. 6.18 F_an = 2 F_n cos(alpha);
    the output contact carries F_t x rt (ball torque balance BC F_t,in = DE F_t,out)."""
    loads = ball_cone_loads(150.0, 2 * math.pi, ball_count=9, cone_radius=24e-3, cone_angle=ALPHA,
                            cam_angle=math.radians(10), cam_radius=6e-3, cam_ball_count=5, reduction_ratio=2.0,
                            clamping="thesis")
    assert loads["torque"] == pytest.approx(150 / (2 * math.pi))
    assert loads["tangential_force_in"] == pytest.approx(23.8732 / (0.024 * 9), rel=1e-5)
    assert loads["normal_force"] == pytest.approx(1253.63, abs=0.01) and abs(loads["normal_force"] - 1200) < 60
    assert loads["traction_needed_in"] == pytest.approx(loads["mu_min"], rel=1e-12)
    assert loads["ball_axial_resultant"] == pytest.approx(2 * 1253.63 * math.cos(ALPHA), abs=0.02)
    assert loads["tangential_force_out"] == pytest.approx(2 * loads["tangential_force_in"])
    balance = ball_cone_loads(150.0, 2 * math.pi, ball_count=9, cone_radius=24e-3, cone_angle=ALPHA,
                              cam_angle=math.radians(10), cam_radius=6e-3, cam_ball_count=5, reduction_ratio=1.0,
                              clamping="axial_balance")
    assert balance["normal_force"] == pytest.approx(loads["normal_force"] / math.sin(ALPHA) ** 2)


def test_loads_grow_linearly_with_power_and_not_with_ratio():
    """Figs 7.4-7.6 (text): normal and clamping forces grow with power, independent of the ratio."""
    common = dict(ball_count=9, cone_radius=24e-3, cone_angle=ALPHA, cam_angle=math.radians(10), cam_radius=6e-3,
                  cam_ball_count=5)
    f50 = ball_cone_loads(50.0, 2 * math.pi, reduction_ratio=0.5, **common)
    assert f50["normal_force"] == pytest.approx(
        ball_cone_loads(50.0, 2 * math.pi, reduction_ratio=2.0, **common)["normal_force"])
    f200 = ball_cone_loads(200.0, 2 * math.pi, reduction_ratio=2.0, **common)
    assert f200["normal_force"] == pytest.approx(4 * f50["normal_force"])
    assert f200["cam_axial_force"] == pytest.approx(4 * f50["cam_axial_force"])


def test_bicycle_load_model_and_cadence_table():
    """Eq. 7.1 evaluated by hand for 75 kg, flat road, V = 5 m/s, f0 = 0.005, Cd 0.8, A 0.5 m^2,
    rho 1.2 kg/m^3: 75 g 0.005 5 + 0.5 1.2 0.8 0.5 125 = 18.39 + 30 W; Tabela 7.1 end points."""
    power = cyclist_power(5.0, mass=75.0, rolling_resistance=0.005, drag_coefficient=0.8, frontal_area=0.5,
                          air_density=1.2)
    assert power == pytest.approx(75 * 9.80665 * 0.005 * 5 + 30.0)
    assert optimal_cadence(122.6) == 48.3 and optimal_cadence(245.1) == 61.3
    assert optimal_cadence(200.15) == pytest.approx(58.5)
    with pytest.raises(InputError, match="Tabela 7.1 covers"):
        optimal_cadence(300.0)


@pytest.mark.parametrize("changes, match", [
    (dict(cone_angle="70 deg"), "cone_angle \\+ tilt_max = 100 deg must stay below 90"),
    (dict(ball_count=20), "ball_count = 20 balls of ball_diameter = 14 mm do not fit"),
    (dict(cone_contact_radius="20 mm"), "inside the smallest cone diameter"),
    (dict(traction_coefficient=0.0), "traction_coefficient"),
    (dict(ratio_convention="torque"), "ratio_convention = 'torque'"),
    (dict(ball_count=0), "ball_count = 0"),
])
def test_bad_design_is_named(changes, match):
    with pytest.raises(InputError, match=match):
        forti(**changes)


def test_tilt_outside_the_range_is_named():
    with pytest.raises(InputError, match="ratio = 2.5 \\(reduction\\) needs a tilt beyond tilt_max"):
        LoadedBallConeCVT(cvt=forti(), power="150 W", input_speed="60 rpm", ratio=2.5)
    speed = forti(ratio_convention="speed")
    assert speed.tilt(2.0) == pytest.approx(math.radians(30))  # output twice as fast: amplification, beta > 0
    with pytest.raises(InputError, match="allowed: 0.5 .. 2"):
        speed.tilt(0.4)


def test_spin_to_roll_ratio_is_the_spin_over_the_ball_speed():
    """phi = psi omega_cone (Eq. 5.57) over omega_ball = omega_in R_1/BC (P-1): psi BC/R_1 at the input
    contact; at 1:1 with R_1 = 23.28 mm, 2.42 x 6.062/23.28 = 0.630."""
    k = ball_cone_kinematics(7e-3, ALPHA, 23.28e-3, 0.0, 2 * math.pi)
    assert k["spin_roll_in"] == pytest.approx(k["psi_in"] * 7e-3 * math.cos(ALPHA) / 23.28e-3, rel=1e-12)
    assert round(k["spin_roll_in"], 3) == 0.630 and k["spin_roll_out"] == pytest.approx(k["spin_roll_in"])
