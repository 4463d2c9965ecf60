"""Kinematics step functions (camcontact.steps.kinematics) called alone, with plain SI inputs.

Each expected value is an independent calculation written here (u_m = (u1 + u2)/2, the closed-form
cycloidal law and Tsuha's flat-face relations, Harris's pure-rolling speeds, Delabenetta Eq. 31) or a
published number (Tsuha 2015 Table 6.3, the reference's derived pressure angles; the Saccheto 2008
Tabela A.1 reconstruction).
"""

import math
import warnings

import numpy as np
import pytest

import camcontact as cc
from camcontact.errors import InputError, ValidityWarning
from camcontact.kinematics.follower import FollowerGeometry
from camcontact.kinematics.motion_program import MotionProgram
from camcontact.steps.kinematics import (
    bearing_surface_speeds,
    ball_cone_motion,
    bearing_kinematics,
    follower_motion,
    given_raceway_speeds,
    motion_continuity,
    pure_rolling_raceway,
    raceway_sliding_speed,
    surface_kinematics,
)
from step_checks import assert_provides

OMEGA_1000 = 1000 * math.pi / 30  # 1000 rpm [rad/s]


# ----------------------------------------------------------------------------- surface_kinematics
def test_surface_kinematics_means_and_differences():
    """u_m = (u1 + u2)/2 = 2, u_s = u1 - u2 = 2, slide/roll u_s/u_m = 1 for u1 = 3, u2 = 1 m/s."""
    out = surface_kinematics(3.0, 1.0)
    assert_provides(surface_kinematics, out)
    assert out["u_m"] == 2.0 and out["u_s"] == 2.0 and out["slide_roll_ratio"] == 1.0
    out = surface_kinematics(1.0, 3.0)
    assert out["u_s"] == -2.0 and out["slide_roll_ratio"] == -1.0


def test_surface_kinematics_pure_sliding_and_rest():
    """u1 = -u2: no entrainment, pure sliding, the slide/roll ratio is infinite with the sign of u_s;
    both at rest: ratio 0 (docstring)."""
    out = surface_kinematics(2.0, -2.0)
    assert out["u_m"] == 0.0 and out["u_s"] == 4.0 and out["slide_roll_ratio"] == math.inf
    assert surface_kinematics(-2.0, 2.0)["slide_roll_ratio"] == -math.inf
    assert surface_kinematics(0.0, 0.0)["slide_roll_ratio"] == 0.0


# ----------------------------------------------------------------------------- follower_motion
def _cycloid(x):
    """Unit cycloidal rise y(x) and its derivatives in x (closed form)."""
    two_pi = 2 * math.pi
    return (x - np.sin(two_pi * x) / two_pi, 1 - np.cos(two_pi * x), two_pi * np.sin(two_pi * x),
            two_pi**2 * np.cos(two_pi * x))


def test_follower_motion_flat_face_against_closed_form_cycloid():
    """Flat face, cycloidal rise/return (L = 10 mm over 120 deg each), R_b = 40 mm, 50 rad/s: lift and
    its time derivatives from the closed-form cycloid; Tsuha Eqs. 3.30-3.33: R_cam = R_b + f + f'',
    u_follower = f'' omega, u_cam = R_cam omega, u_m their mean, u_s their difference, R = R_cam (flat
    counter-face), pressure angle 0; the profile's polar radius sqrt((R_b + f)^2 + f'^2) (Eq. 3.15)."""
    L, beta, Rb, omega = 0.010, math.radians(120), 0.040, 50.0
    program = MotionProgram.rise_return_dwell("10 mm", "120 deg", "120 deg", "cycloidal", "cycloidal")
    theta = np.radians(np.arange(0.0, 360.0, 7.5))
    out = follower_motion(program, FollowerGeometry("flat", Rb), theta, omega, 0.0, "consistent", math.radians(30))
    assert_provides(follower_motion, out)
    f, f1, f2, f3 = (np.zeros_like(theta) for _ in range(4))
    rise = theta < beta
    back = (theta >= beta) & (theta < 2 * beta)
    y = _cycloid(theta[rise] / beta)
    f[rise], f1[rise], f2[rise], f3[rise] = (L * y[k] / beta**k for k in range(4))
    y = _cycloid((theta[back] - beta) / beta)
    f[back] = L * (1 - y[0])
    f1[back], f2[back], f3[back] = (-L * y[k] / beta**k for k in (1, 2, 3))
    np.testing.assert_allclose(out["lift"], f, atol=1e-12)
    np.testing.assert_allclose(out["follower_velocity"], f1 * omega, atol=1e-10)
    np.testing.assert_allclose(out["follower_acceleration"], f2 * omega**2, atol=1e-8)
    np.testing.assert_allclose(out["follower_jerk"], f3 * omega**3, atol=1e-6)
    R_cam = Rb + f + f2
    np.testing.assert_allclose(out["cam_radius"], R_cam, rtol=1e-12)
    np.testing.assert_allclose(out["R"], R_cam, rtol=1e-12)
    np.testing.assert_allclose(out["u_cam"], R_cam * omega, rtol=1e-12)
    np.testing.assert_allclose(out["u_follower"], f2 * omega, atol=1e-10)
    np.testing.assert_allclose(out["u_m"], 0.5 * (R_cam + f2) * omega, rtol=1e-12)
    np.testing.assert_allclose(out["u_s"], (Rb + f) * omega, rtol=1e-12)
    np.testing.assert_allclose(out["pressure_angle"], 0.0)
    np.testing.assert_allclose(out["angular_speed"], omega)
    np.testing.assert_allclose(np.hypot(out["profile_x"], out["profile_y"]), np.hypot(Rb + f, f1), rtol=1e-12)


def test_follower_motion_roller_against_tsuha_table_6_3():
    """LS-1 roller (R_b 40 mm, R_f 10 mm, offset 5 mm) at 1000 rpm in the thesis convention: R and u_m of
    Tsuha (2015) Table 6.3 (45 deg: 0.00836 m, 5.351 m/s; 90 deg: 0.00770, 3.503 (printed truncated for
    3.5037); 135 deg: 0.00837, 5.378), the reference's derived pressure angles (16.62, -4.10, -25.16 deg)
    and R_cam (0.05110, 0.03346, 0.05136 m); the pressure angle also from tan A_p = (f' - eps)/S (Eq. 3.19)."""
    program = MotionProgram.thesis_ls1()
    theta = np.radians([0.0, 45.0, 90.0, 135.0])
    out = follower_motion(program, FollowerGeometry("roller", 0.040, 0.010, 0.005), theta, OMEGA_1000, 0.0,
                          "thesis", math.radians(30))
    assert out["R"][1:] == pytest.approx([0.00836, 0.00770, 0.00837], abs=5e-6)
    assert out["u_m"] == pytest.approx([4.18879, 5.351, 3.5037, 5.378], abs=1e-3)
    assert np.degrees(out["pressure_angle"][1:]) == pytest.approx([16.62, -4.10, -25.16], abs=0.005)
    assert out["cam_radius"] == pytest.approx([0.04, 0.05110, 0.03346, 0.05136], abs=5e-6)
    np.testing.assert_array_equal(out["u_s"], 0.0)  # a roller rolls
    f, f1 = program.evaluate(theta)[:2]
    S = math.sqrt(0.050**2 - 0.005**2) + f
    np.testing.assert_allclose(np.tan(out["pressure_angle"]), (f1 - 0.005) / S, rtol=1e-12)
    # reduced radius of cam and roller: 1/R = 1/R_cam + 1/R_f
    np.testing.assert_allclose(out["R"], 1 / (1 / out["cam_radius"] + 1 / 0.010), rtol=1e-10)


def test_follower_motion_with_angular_acceleration():
    """omega^2 = omega0^2 + 2 A theta, S' = f' omega, S'' = f'' omega^2 + f' A (Tsuha Eqs. 3.3-3.4)."""
    program = MotionProgram.thesis_ls1()
    theta = np.radians(np.arange(0.0, 180.0, 15.0))
    omega0, accel = 50.0, 200.0
    out = follower_motion(program, FollowerGeometry("roller", 0.040, 0.010, 0.005), theta, omega0, accel,
                          "consistent", math.radians(40))
    omega = np.sqrt(omega0**2 + 2 * accel * theta)
    f1, f2 = program.evaluate(theta)[1:3]
    np.testing.assert_allclose(out["angular_speed"], omega, rtol=1e-12)
    np.testing.assert_allclose(out["follower_velocity"], f1 * omega, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(out["follower_acceleration"], f2 * omega**2 + f1 * accel, rtol=1e-12, atol=1e-10)


def test_follower_motion_undercut_and_pressure_angle_limit():
    """A flat face on a 5 mm base circle with a 10 mm cycloidal lift: R_cam = R_b + f + f'' < 0 near the
    nose -> InputError naming the angles; the LS-1 roller with a 10 deg limit warns (|A_p| reaches 25 deg)."""
    program = MotionProgram.rise_return_dwell("10 mm", "120 deg", "120 deg", "cycloidal", "cycloidal")
    theta = np.radians(np.arange(0.0, 360.0, 5.0))
    with pytest.raises(InputError, match="undercuts"):
        follower_motion(program, FollowerGeometry("flat", 0.005), theta, 100.0, 0.0, "consistent", 0.5)
    with pytest.warns(ValidityWarning, match="exceeds the limit 10°"):
        follower_motion(MotionProgram.thesis_ls1(), FollowerGeometry("roller", 0.040, 0.010, 0.005),
                        np.radians([45.0, 135.0]), 100.0, 0.0, "consistent", math.radians(10))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # within the limit: no warning
        follower_motion(MotionProgram.thesis_ls1(), FollowerGeometry("roller", 0.040, 0.010, 0.005),
                        np.radians([45.0, 135.0]), 100.0, 0.0, "consistent", math.radians(30))


# ----------------------------------------------------------------------------- motion_continuity
@pytest.mark.parametrize("law, expected", [
    # harmonic y'' = (pi^2/2) cos(pi x): nonzero at x = 0 and 1 -> acceleration jumps at the dwell joints;
    # at the top (90 deg) rise and return both have -pi^2/2 L/beta^2: continuous there
    ("harmonic", "acceleration jumps (infinite jerk) at 0°, 180°"),
    # cycloidal y'' = 2 pi sin(2 pi x) vanishes at both ends, y''' = 4 pi^2 cos(2 pi x) does not
    ("cycloidal", "C2 everywhere (finite jerk); jerk jumps at 0°, 90°, 180°"),
    # 4-5-6-7 polynomial: velocity, acceleration and jerk vanish at both ends
    ("polynomial_4567", "C2 everywhere (finite jerk)"),
])
def test_motion_continuity_from_the_laws_end_derivatives(law, expected):
    """Rise 0-90 deg, return 90-180 deg, dwell: the text follows from each law's end derivatives (comments)."""
    program = MotionProgram.rise_return_dwell("10 mm", "90 deg", "90 deg", law, law)
    out = motion_continuity(program)
    assert_provides(motion_continuity, out)
    assert out["motion_continuity"] == expected


# ----------------------------------------------------------------------------- bearing_kinematics
def test_bearing_kinematics_pure_rolling_in_the_cage_frame():
    """Inner ring 10 rev/s, outer 2 rev/s, d_m 0.255 m, D_w 27 mm, gamma = D_w cos 9 deg / d_m: the cage
    at [n_i (1 - gamma) + n_o (1 + gamma)]/2 rev/s; in the cage frame each raceway's surface speed
    (d_m/2)(1 -+ gamma) 2 pi |n_ring - n_cage| equals u_m and the roller surface speed (D_w/2) omega_R
    (Harris & Kotzalas 2007 ch. 8)."""
    d_m, D_w = 0.255, 0.027
    gamma = D_w * math.cos(math.radians(9)) / d_m
    n_i, n_o = 10.0, 2.0
    out = bearing_kinematics(n_i, n_o, gamma, d_m, D_w)
    assert_provides(bearing_kinematics, out)
    n_c = 0.5 * (n_i * (1 - gamma) + n_o * (1 + gamma))
    assert out["cage_speed"] == pytest.approx(2 * math.pi * n_c, rel=1e-12)
    inner_surface = 0.5 * d_m * (1 - gamma) * 2 * math.pi * abs(n_i - n_c)
    outer_surface = 0.5 * d_m * (1 + gamma) * 2 * math.pi * abs(n_o - n_c)
    assert out["u_m"] == pytest.approx(inner_surface, rel=1e-12)
    assert out["u_m"] == pytest.approx(outer_surface, rel=1e-12)
    assert 0.5 * D_w * out["roller_speed"] == pytest.approx(out["u_m"], rel=1e-12)


def test_bearing_kinematics_rings_turning_together():
    """n_i = n_o: the bearing turns as a rigid body, cage at the ring speed, no rolling, u_m = 0."""
    out = bearing_kinematics(5.0, 5.0, 0.1, 0.2, 0.02)
    assert out["cage_speed"] == pytest.approx(2 * math.pi * 5.0)
    assert out["u_m"] == 0.0 and out["roller_speed"] == 0.0


# ----------------------------------------------------------------------------- raceway contact speeds
def test_pure_rolling_raceway_splits_the_rolling_speed():
    """u = (pi d_m/2)(1 - gamma^2) n, u1 = u (1 + s/2), u2 = u (1 - s/2) for slide/roll s = 0.1, so the
    measure |u1 - u2|/(u1 + u2) (Delabenetta Eq. 45) is s/2."""
    d_m, gamma, n = 0.255, 0.104, 5.0
    out = pure_rolling_raceway(n, 0.1, d_m, gamma)
    assert_provides(pure_rolling_raceway, out)
    u = 0.5 * math.pi * d_m * (1 - gamma**2) * n
    assert out["u_m"] == pytest.approx(u, rel=1e-12)
    assert out["u_raceway"] == pytest.approx(1.05 * u, rel=1e-12)
    assert out["u_roller"] == pytest.approx(0.95 * u, rel=1e-12)
    assert out["slide_roll_measure"] == pytest.approx(0.05, rel=1e-12)
    assert "pure rolling" in out["speed_basis"] and "255 mm" in out["speed_basis"]


def test_given_raceway_speeds_delabenetta_eq_31():
    """Delabenetta (2021) Eq. 31 with its inputs: ring R1 = 149 mm at 300 rpm, roller R2 = 13.5 mm at
    1900 rpm: u1 = 0.149 x 2 pi x 5 = 4.6810 m/s, u2 = 0.0135 x 2 pi x 1900/60 = 2.6861 m/s."""
    out = given_raceway_speeds(0.149, 0.0135, 5.0, 1900 / 60)
    assert_provides(given_raceway_speeds, out)
    u1, u2 = 0.149 * 2 * math.pi * 5.0, 0.0135 * 2 * math.pi * 1900 / 60
    assert out["u_raceway"] == pytest.approx(4.6810, abs=5e-5) and out["u_raceway"] == pytest.approx(u1, rel=1e-12)
    assert out["u_roller"] == pytest.approx(2.6861, abs=5e-5) and out["u_roller"] == pytest.approx(u2, rel=1e-12)
    assert out["u_m"] == pytest.approx(0.5 * (u1 + u2), rel=1e-12)
    assert out["slide_roll_measure"] == pytest.approx((u1 - u2) / (u1 + u2), rel=1e-12)


def test_bearing_surface_speeds_split_the_entrainment_by_the_slide_roll_ratio():
    """u1, u2 = u_m (1 +- s/2): s = 0.02 at 2 m/s gives 2.02 and 1.98 m/s ((u1 - u2)/u_m = s); pure rolling without s."""
    out = bearing_surface_speeds(2.0, slide_roll_ratio=0.02)
    assert_provides(bearing_surface_speeds, out)
    assert out["u1"] == pytest.approx(2.02, rel=1e-12) and out["u2"] == pytest.approx(1.98, rel=1e-12)
    assert bearing_surface_speeds(2.0) == {"u1": 2.0, "u2": 2.0}
    assert bearing_surface_speeds(2.0, slide_roll_ratio=None) == {"u1": 2.0, "u2": 2.0}


def test_raceway_sliding_speed_is_raceway_minus_roller():
    """u_s = u_raceway - u_roller with Delabenetta's Eq. 31 speeds (4.6810 - 2.6861 = 1.9949 m/s); negative when
    the roller's surface is the faster one; 0 in pure rolling."""
    out = raceway_sliding_speed(4.6810, 2.6861)
    assert_provides(raceway_sliding_speed, out)
    assert out["u_s"] == pytest.approx(1.9949, rel=1e-12)
    assert raceway_sliding_speed(1.0, 1.5)["u_s"] == -0.5 and raceway_sliding_speed(2.1, 2.1)["u_s"] == 0.0


def test_raceway_speeds_without_motion_are_refused():
    """Ring (and roller) at rest: no entrainment -> InputError (both speed conventions)."""
    with pytest.raises(InputError, match="do not move"):
        pure_rolling_raceway(0.0, 0.1, 0.255, 0.1)
    with pytest.raises(InputError, match="do not move"):
        given_raceway_speeds(0.149, 0.0135, 0.0, 0.0)


# ----------------------------------------------------------------------------- ball_cone_motion
STEEL = cc.Material(E="207 GPa", nu=0.3)


def cvt(**changes):
    fields = {"cone_angle": "30 deg", "cone_contact_radius": "23.28 mm", "ball_diameter": "14 mm", "ball_count": 9,
                  "tilt_max": "30 deg", "cam_ramp_angle": "10 deg", "cam_radius": "6 mm", "cam_ball_count": 5, "material": STEEL,
                  "traction_coefficient": 0.1}
    fields.update(changes)
    return cc.BallConeCVT(**fields)


def test_ball_cone_motion_against_saccheto_reconstruction():
    """Saccheto (2008) Tabela A.1 reconstruction (r = 7 mm, R_1 = 23.28 mm, alpha = 30 deg), rt = 1.5:
    beta = -19.107 deg, BC = 6.874 mm, DE = 4.583 mm, psi 3.060 / 1.460; omega_out = omega_in DE/BC,
    omega_ball = omega_in R_1/BC, spin creepage psi/R_1; overrange (cos 0 / cos 60 deg)^2 = 4."""
    omega = 2 * math.pi
    out = ball_cone_motion(cvt(), 1.5, omega)
    assert_provides(ball_cone_motion, out)
    assert math.degrees(out["tilt"]) == pytest.approx(-19.107, abs=5e-4)
    assert out["rolling_radius_in"] * 1e3 == pytest.approx(6.874, abs=5e-4)
    assert out["rolling_radius_out"] * 1e3 == pytest.approx(4.583, abs=5e-4)
    assert out["psi_in"] == pytest.approx(3.060, abs=5e-3) and out["psi_out"] == pytest.approx(1.460, abs=5e-3)
    bc, de = out["rolling_radius_in"], out["rolling_radius_out"]
    assert bc / de == pytest.approx(1.5, rel=1e-12) and out["reduction_ratio"] == 1.5
    assert out["output_speed"] == pytest.approx(omega / 1.5, rel=1e-12)
    assert out["ball_speed"] == pytest.approx(omega * 0.02328 / bc, rel=1e-12)
    assert out["rolling_speed_in"] == pytest.approx(omega * 0.02328, rel=1e-12)
    assert out["spin_in"] == pytest.approx(out["psi_in"] / 0.02328, rel=1e-12)
    assert out["psi_total"] == pytest.approx(out["psi_in"] + out["psi_out"], rel=1e-12)
    assert out["overrange"] == pytest.approx(4.0, rel=1e-12)


def test_ball_cone_motion_speed_convention_and_range():
    """In the "speed" convention the ratio 1/1.5 is the same operating point (reduction 1.5); a ratio
    beyond the overrange (reduction 3 > 2) is refused."""
    out = ball_cone_motion(cvt(ratio_convention="speed"), 1 / 1.5, 2 * math.pi)
    assert out["reduction_ratio"] == pytest.approx(1.5) and math.degrees(out["tilt"]) == pytest.approx(-19.107, abs=5e-4)
    with pytest.raises(InputError, match="tilt_max"):
        ball_cone_motion(cvt(), 3.0, 2 * math.pi)
