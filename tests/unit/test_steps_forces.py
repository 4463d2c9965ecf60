"""Force and dynamics step functions (camcontact.steps.forces) called alone, with plain SI inputs.

Expected values: Tsuha (2015) Table 6.3 forces, the 67.6-67.7 Hz natural frequency and k_min =
9.42e4 N/m of the LS-1 valve train; independent bisection of the 1-DOF no-jump condition; the
quasi-static forces of a lumped valve train (its docstring's closed forms); the load-deflection law and
force balance of a roller bearing (Harris & Kotzalas ch. 7, Stribeck); Saccheto (2008) §6.5 loads.
"""

import math

import numpy as np
import pytest

import camcontact as cc
from camcontact.dynamics.valve_train_ode import LumpedValveTrain
from camcontact.errors import InputError
from camcontact.kinematics.motion_program import MotionProgram
from camcontact.steps.forces import (
    ball_cone_contact_forces,
    check_lumped_model,
    jump_report,
    load_distribution,
    lumped_dynamics,
    minimum_spring_stiffness,
    normal_force,
    prescribed_motion_forces,
    valve_train_natural_frequency,
)
from step_checks import assert_provides

# LS-1 equivalent valve train, Tsuha (2015) Table 6.1 as the thesis rounds it
MASS, STIFFNESS, ZETA, PRELOAD = 0.662, 1.199e5, 0.06, 1000.0
DAMPING = 2 * ZETA * math.sqrt(STIFFNESS * MASS)  # 33.808 N s/m unrounded
OMEGA_1000 = 1000 * math.pi / 30


# ----------------------------------------------------------------------------- 1-DOF valve train
def test_natural_frequency_of_the_ls1_valve_train():
    """sqrt(k/m)/2 pi = sqrt(1.199e5/0.662)/2 pi = 67.73 Hz; Tsuha (2015) gives 67.6-67.7 Hz."""
    out = valve_train_natural_frequency(MASS, STIFFNESS)
    assert_provides(valve_train_natural_frequency, out)
    assert out["natural_frequency"] == pytest.approx(math.sqrt(STIFFNESS / MASS) / (2 * math.pi), rel=1e-12)
    assert out["natural_frequency"] == pytest.approx(67.65, abs=0.1)


def test_prescribed_motion_forces_tsuha_table_6_3():
    """F = m S'' + c S' + k f + F_pl (Tsuha Eq. 3.46) of the LS-1 at 1000 rpm against Table 6.3
    (0 deg 1000.000, 45 deg 2170.113, 90 deg 3087.990, 135 deg 2011.174 N; +-0.01 N as in
    tests/literature); the parts add up and the torque is F S'/omega (Eq. 3.47)."""
    program = MotionProgram.thesis_ls1()
    theta = np.radians([0.0, 45.0, 90.0, 135.0])
    f, f1, f2 = program.evaluate(theta)[:3]
    v, a = f1 * OMEGA_1000, f2 * OMEGA_1000**2
    out = prescribed_motion_forces(f, v, a, np.full(4, OMEGA_1000), MASS, STIFFNESS, DAMPING, PRELOAD)
    assert_provides(prescribed_motion_forces, out)
    assert out["contact_force"] == pytest.approx([1000.000, 2170.113, 3087.990, 2011.174], abs=0.01)
    np.testing.assert_allclose(out["inertia_force"], MASS * a, rtol=1e-12)
    np.testing.assert_allclose(out["damping_force"], DAMPING * v, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(out["spring_force"], STIFFNESS * f, rtol=1e-12)
    np.testing.assert_allclose(out["preload_force"], PRELOAD)
    np.testing.assert_allclose(out["cam_torque"], out["contact_force"] * v / OMEGA_1000, rtol=1e-12, atol=1e-12)


def _k_min_by_bisection(program, omega):
    """Smallest k with m S'' + 2 zeta sqrt(k m) S' + k f + F_pl >= 0 at 20001 angles, by bisection."""
    theta = np.linspace(0.0, 2 * math.pi, 20001)
    f, f1, f2 = program.evaluate(theta)[:3]
    v, a = f1 * omega, f2 * omega**2

    def holds(k):
        return np.min(MASS * a + 2 * ZETA * math.sqrt(k * MASS) * v + k * f + PRELOAD) >= 0.0

    low, high = 0.0, 1e7
    for _ in range(80):
        mid = 0.5 * (low + high)
        low, high = (low, mid) if holds(mid) else (mid, high)
    return high


def test_minimum_spring_stiffness_tsuha_and_bisection():
    """LS-1 at 3000 rpm: k_min = 9.42e4 N/m (Tsuha 2015 §6.1; rtol 2e-3 as tests/literature) and the
    same as an independent bisection of the no-jump condition (rtol 1e-3: different angle samples);
    ``max_speed`` None falls back to ``speed``."""
    program = MotionProgram.thesis_ls1()
    omega = 3000 * math.pi / 30
    out = minimum_spring_stiffness(program, OMEGA_1000, omega, MASS, ZETA, PRELOAD)
    assert_provides(minimum_spring_stiffness, out)
    assert out["k_min"] == pytest.approx(9.42e4, rel=2e-3)
    assert out["k_min"] == pytest.approx(_k_min_by_bisection(program, omega), rel=1e-3)
    assert minimum_spring_stiffness(program, omega, None, MASS, ZETA, PRELOAD)["k_min"] == out["k_min"]
    # at 2000 rpm a softer spring suffices (1.25e4 N/m by the bisection); at 1000 rpm the 1000 N preload
    # alone exceeds the largest deceleration force m |S''| = 0.662 x 468 = 310 N: k_min = 0
    omega2 = 2000 * math.pi / 30
    middle = minimum_spring_stiffness(program, omega2, None, MASS, ZETA, PRELOAD)["k_min"]
    assert middle == pytest.approx(_k_min_by_bisection(program, omega2), rel=1e-3)
    assert minimum_spring_stiffness(program, OMEGA_1000, None, MASS, ZETA, PRELOAD)["k_min"] == 0.0


def test_minimum_spring_stiffness_negative_preload_cannot_be_helped():
    """On the base circle f = 0 and S'' = 0: the condition reads F_pl >= 0, which no stiffness fixes for
    F_pl = -10 N -> InputError asking for preload."""
    with pytest.raises(InputError, match="raise the preload"):
        minimum_spring_stiffness(MotionProgram.thesis_ls1(), OMEGA_1000, None, MASS, ZETA, -10.0)


# ----------------------------------------------------------------------------- lumped model
def test_lumped_dynamics_is_quasi_static_at_low_speed():
    """Ferrarese 2-DOF train on a cycloidal 8 mm lift (120 deg up, 120 deg down) at 10 rad/s, 2 turns:
    the inertia is negligible, so the contact force is the model's quasi-static value (class docstring):
    seated N_0 = F_r0 k_c/(k_c + k_r + k_chain), k_chain = (1/k_stem + 1/k_v)^-1; open
    N = (F_r0 + k_e y)/(1 + k_e/k_c), k_e = k_r + (1/k_p + 1/k_stem)^-1 (to 0.5 N: m y'' ~ 0.2 N);
    the torque is N v/omega."""
    train = LumpedValveTrain.ferrarese_2dof()
    program = MotionProgram.rise_return_dwell("8 mm", "120 deg", "120 deg", "cycloidal", "cycloidal")
    theta = np.radians(np.arange(0.0, 360.0, 15.0))
    speed = 10.0
    f, f1 = program.evaluate(theta)[:2]
    v = f1 * speed
    out = lumped_dynamics(train, program, theta, speed, v, np.full(theta.size, speed), 2)
    assert_provides(lumped_dynamics, out)
    k_c, k_r, k_p, k_v = (train.contact_stiffness, train.return_spring_stiffness, train.pressure_spring_stiffness,
                          train.seat_stiffness)
    k_stem = train.stem_stiffness[0]
    seated = train.return_spring_preload * k_c / (k_c + k_r + 1 / (1 / k_stem + 1 / k_v))
    k_e = k_r + 1 / (1 / k_p + 1 / k_stem)
    lifted = (train.return_spring_preload + k_e * f) / (1 + k_e / k_c)
    on_base = f == 0.0
    open_ = f > 1e-3
    np.testing.assert_allclose(out["contact_force"][on_base], seated, atol=0.05)
    np.testing.assert_allclose(out["contact_force"][open_], lifted[open_], atol=0.5)
    np.testing.assert_allclose(out["cam_torque"], out["contact_force"] * v / speed, rtol=1e-12)
    assert out["valve_train_response"].contact_force.size > theta.size


def test_check_lumped_model_refuses_what_the_dynamics_cannot_run():
    """No lumped model, or a cam that accelerates: InputError; a model at constant speed passes."""
    with pytest.raises(InputError, match="lumped model"):
        check_lumped_model(None, 0.0)
    with pytest.raises(InputError, match="angular_acceleration must be 0"):
        check_lumped_model(LumpedValveTrain.ferrarese_2dof(), 5.0)
    assert check_lumped_model(LumpedValveTrain.ferrarese_2dof(), 0.0) is None
    assert lumped_dynamics.step.check is check_lumped_model


# ----------------------------------------------------------------------------- normal force, jump
def test_normal_force_conventions_and_open_contact():
    """Consistent convention: N = F / cos(A_p), clipped at 0 where F <= 0 (flagged open); the thesis
    takes the axial force itself."""
    F = np.array([1000.0, 500.0, 0.0, -20.0])
    pa = np.radians([0.0, 30.0, 10.0, -20.0])
    out = normal_force(F, pa, "consistent")
    assert_provides(normal_force, out)
    np.testing.assert_allclose(out["normal_force"], [1000.0, 500.0 / math.cos(math.radians(30)), 0.0, 0.0])
    np.testing.assert_array_equal(out["contact_open"], [False, False, True, True])
    np.testing.assert_allclose(normal_force(F, pa, "thesis")["normal_force"], [1000.0, 500.0, 0.0, 0.0])


def test_jump_report_text():
    """No open angle: 'no jump' with the smallest force; open angles: their count, the first angle and the
    smallest force."""
    theta = np.radians([0.0, 10.0, 20.0, 30.0])
    out = jump_report(np.zeros(4, bool), np.array([5.0, 3.5, 4.0, 9.0]), theta)
    assert_provides(jump_report, out)
    assert out["jump"] == "no jump (minimum contact force 3.5 N)"
    out = jump_report(np.array([False, True, True, False]), np.array([5.0, -1.0, -2.5, 9.0]), theta)
    assert out["jump"] == "JUMP: the follower leaves the cam at 2 angles, from 10° (contact force -2.5 N)"


# ----------------------------------------------------------------------------- bearing load distribution
STEEL = cc.Material(E="210 GPa", nu=0.3)


def bearing(**changes):
    arguments = {"designation": "test", "bore": "200 mm", "outer_diameter": "310 mm", "width": "109 mm", "rollers_per_row": 25,
                     "roller_diameter": "27 mm", "roller_length": "41.35 mm", "contact_angle": "9 deg", "C": "1700 kN",
                     "C0": "2120 kN", "radial_clearance": "0.1 mm", "fatigue_load_limit": "200 kN", "material": STEEL,
                     "roughness": "0.23 um"}
    arguments.update(changes)
    return cc.SphericalRollerBearing(**arguments)


def _palmgren_stiffness(length):
    """K_n [N/m^(10/9)] of two line contacts in series, delta = 2 x 3.84e-5 Q^0.9/l^0.8 [mm, N, mm]."""
    return ((length * 1e3) ** 0.8 / (2 * 3.84e-5)) ** (10 / 9) * 1e3 ** (10 / 9)


def test_load_distribution_balance_and_load_deflection_law():
    """150 kN radial, 10 kN axial, 0.1 mm clearance: the roller loads balance the applied loads
    (sum Q cos psi cos alpha = F_r, sum s Q sin alpha = F_a) and follow Q = K delta^(10/9) with
    delta = delta_r cos psi cos alpha + s delta_a sin alpha - (c/2) cos alpha (Harris & Kotzalas ch. 7,
    Palmgren's K); rows listed row by row."""
    alpha = math.radians(9)
    out = load_distribution(bearing(), 150e3, 10e3)
    assert_provides(load_distribution, out)
    Q, psi, row = out["Q"], out["azimuth"], out["roller_row"]
    np.testing.assert_array_equal(row, np.repeat([1.0, 2.0], 25))
    s = np.where(row == 1, 1.0, -1.0)
    assert np.sum(Q * np.cos(psi)) * math.cos(alpha) == pytest.approx(150e3, rel=1e-8)
    assert np.sum(Q * s) * math.sin(alpha) == pytest.approx(10e3, rel=1e-8)
    delta = (out["delta_r"] * np.cos(psi) * math.cos(alpha) + s * out["delta_a"] * math.sin(alpha)
             - 0.5e-4 * math.cos(alpha))
    np.testing.assert_allclose(Q, _palmgren_stiffness(0.04135) * np.clip(delta, 0, None) ** (10 / 9), rtol=1e-8,
                               atol=1e-6)
    np.testing.assert_allclose(out["roller_approach"], delta, rtol=1e-9, atol=1e-15)
    assert out["Q_max"] == pytest.approx(Q.max()) and out["loaded_rollers"] == float(np.sum(Q > 0))
    loaded_angles = np.abs(np.angle(np.exp(1j * psi[Q > 0])))
    assert out["last_loaded_azimuth"] == pytest.approx(loaded_angles.max())
    # load zone (Harris & Kotzalas ch. 7) per row: the approach vanishes where
    # delta_r cos psi + s delta_a tan alpha - c/2 = 0; the larger of the two rows is reported
    zones = [math.acos((0.5e-4 - sign * out["delta_a"] * math.tan(alpha)) / out["delta_r"]) for sign in (1, -1)]
    assert out["load_zone"] == pytest.approx(max(zones), rel=1e-12)
    assert out["last_loaded_azimuth"] <= out["load_zone"] < out["last_loaded_azimuth"] + 2 * math.pi / 25
    assert out["force_residual"] < 1e-8


def test_load_distribution_stribeck_and_no_load():
    """Zero clearance, radial load only: Stribeck's Q_max = 4.08 F_r/(Z cos alpha) for line contact,
    here Z = 2 x 25 rollers (within 2 %: 4.08 is the continuous-integral value); Harris's load zone
    arccos(P_d/(2 delta_r)) is 90 deg exactly with zero clearance, the last loaded roller at 86.4 deg;
    no load: nothing loaded."""
    out = load_distribution(bearing(radial_clearance="0 mm"), 100e3, 0.0)
    assert out["Q_max"] == pytest.approx(4.08 * 100e3 / (50 * math.cos(math.radians(9))), rel=0.02)
    assert out["load_zone"] == pytest.approx(math.pi / 2, rel=1e-12)  # arccos(0): half the ring loaded
    assert out["last_loaded_azimuth"] == pytest.approx(math.radians(86.4))  # the last roller inside 90 deg
    none = load_distribution(bearing(), 0.0, 0.0)
    assert none["loaded_rollers"] == 0.0 and none["Q_max"] == 0.0 and np.all(none["Q"] == 0.0)
    assert none["load_zone"] == 0.0 and none["last_loaded_azimuth"] == 0.0


# ----------------------------------------------------------------------------- ball-cone CVT loads
def _cvt_loads(**changes):
    arguments = {"power": 150.0, "input_speed": 2 * math.pi, "reduction_ratio": 2.0, "traction_coefficient": 0.1,
                     "ball_count": 9, "cone_contact_radius": 24e-3, "cone_angle": math.radians(30),
                     "cam_ramp_angle": math.radians(10), "cam_radius": 6e-3, "cam_ball_count": 5, "clamping": "thesis"}
    arguments.update(changes)
    return ball_cone_contact_forces(**arguments)


def test_ball_cone_contact_forces_saccheto_6_5():
    """150 W at 60 rpm (Saccheto 2008 §6.5): T = P/omega = 23.873 N m, F_t = T/(R_cont n) = 110.5 N,
    F_cam = T/(R_cam tan eta), F_n = F_cam sin alpha / n = 1254 N (Eq. 6.17; "about 1200 N"), mu_min =
    tan(eta) R_cam/(sin(alpha) R_cont) = 0.08813 (printed, rel 5e-4 with R_cont = 24 mm), output F_t x rt."""
    out = _cvt_loads()
    assert_provides(ball_cone_contact_forces, out)
    T = 150.0 / (2 * math.pi)
    cam = T / (6e-3 * math.tan(math.radians(10)))
    Fn = cam * math.sin(math.radians(30)) / 9
    assert out["torque"] == pytest.approx(T, rel=1e-12) and out["output_torque"] == pytest.approx(2 * T)
    assert out["tangential_force_in"] == pytest.approx(T / (0.024 * 9), rel=1e-12)
    assert out["tangential_force_out"] == pytest.approx(2 * T / (0.024 * 9), rel=1e-12)
    assert out["cam_axial_force"] == pytest.approx(cam, rel=1e-12)
    assert out["cam_ball_force"] == pytest.approx(cam / 5, rel=1e-12)
    assert out["normal_force"] == pytest.approx(Fn, rel=1e-12) and out["normal_force"] == pytest.approx(1254, abs=0.5)
    assert out["ball_axial_resultant"] == pytest.approx(2 * Fn * math.cos(math.radians(30)), rel=1e-12)
    assert out["mu_min"] == pytest.approx(0.08813, rel=5e-4)
    assert out["traction_needed_in"] == pytest.approx(out["mu_min"], rel=1e-12)
    assert out["traction_needed_out"] == pytest.approx(2 * out["mu_min"], rel=1e-12)
    # the output contact needs 0.176 > Ct = 0.1
    assert out["traction_check"].startswith("gross slip: the output contact needs F_t/F_n = 0.1763")


def test_ball_cone_contact_forces_traction_ok_and_axial_balance():
    """At 1:1 both contacts need mu_min = 0.088163 (R_cont = 24 mm) < Ct = 0.1: 'ok'; the axial-balance clamping gives
    F_n = F_cam/(n sin alpha) (four times the thesis's at 30 deg); zero power is refused."""
    out = _cvt_loads(reduction_ratio=1.0)
    assert out["traction_check"].startswith("ok: needs 0.08816 at the input contact < Ct = 0.1")
    balanced = _cvt_loads(clamping="axial_balance")
    cam = 150.0 / (2 * math.pi) / (6e-3 * math.tan(math.radians(10)))
    assert balanced["normal_force"] == pytest.approx(cam / (9 * math.sin(math.radians(30))), rel=1e-12)
    with pytest.raises(InputError, match="power"):
        _cvt_loads(power=0.0)
