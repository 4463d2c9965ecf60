"""Unit tests of the roller-follower steps and their dynamics (camcontact/steps/roller.py,
camcontact/dynamics/roller_follower.py), with SI floats against closed forms.

Independent references: a roller driven at a cam surface speed u(t) = U (1 + e sin(theta)) rolls without
slip when the traction is ample, and then F_t = (I/R) d(u/R)/dt + T_pin / R exactly; with a traction
limit below that requirement it slips; the camshaft torque of a tangential force is F_t p with p the
tangent's distance from the cam axis.
"""

import math

import numpy as np
import pytest

from camcontact.dynamics.roller_follower import (check_full_turn, pin_friction_torque, required_traction,
                                                 roller_cycle, slip_grid, solid_roller_inertia)
from camcontact.errors import InputError
from camcontact.kinematics.follower import FollowerGeometry
from camcontact.steps.roller import (cam_friction_torque, check_roller, coulomb_traction_table, roller_spin,
                                     sliding_tangential_force)

from step_checks import assert_provides

N_ANGLES = 360
THETA = np.arange(N_ANGLES) * 2 * math.pi / N_ANGLES
OMEGA = 300.0  # rad/s
R_F, INERTIA = 0.01, solid_roller_inertia(0.01, 0.015, 7850.0)


def _drive(eccentricity=0.2, load=2000.0):
    u_cam = 12.0 * (1.0 + eccentricity * np.sin(THETA))
    return u_cam, np.full(N_ANGLES, load)


def _exact_requirement(u_cam, pin):
    # d(u/R)/dt = omega U e cos(theta) / R
    return INERTIA * OMEGA * 12.0 * 0.2 * np.cos(THETA) / R_F**2 + pin / R_F


def test_solid_roller_inertia_is_half_m_r_squared():
    mass = 7850.0 * math.pi * 0.01**2 * 0.015
    assert solid_roller_inertia(0.01, 0.015, 7850.0) == pytest.approx(0.5 * mass * 0.01**2, rel=1e-14)
    with pytest.raises(InputError, match="width"):
        solid_roller_inertia(0.01, 0.0, 7850.0)


def test_required_traction_matches_the_closed_form():
    u_cam, N = _drive()
    pin = pin_friction_torque(N, 0.0025, 0.004)
    got = required_traction(THETA, OMEGA, u_cam, pin, R_F, INERTIA)
    exact = _exact_requirement(u_cam, pin)
    # second-order central differences at 1 degree: relative error (1 - sin(h)/h) ~ 5e-5
    assert np.max(np.abs(got - exact)) < 1e-4 * np.max(np.abs(exact))


@pytest.mark.parametrize("compiled", [False, True])
def test_ample_traction_rolls_and_transmits_the_requirement(compiled):
    u_cam, N = _drive()
    pin = pin_friction_torque(N, 0.0025, 0.004)
    grid = slip_grid(u_cam)
    force = 0.1 * N[:, None] * np.clip(grid / (1e-4 * u_cam[:, None]), -1.0, 1.0)
    cycle = roller_cycle(THETA, OMEGA, u_cam, pin, grid, force, radius=R_F, inertia=INERTIA, compiled=compiled)
    exact = _exact_requirement(u_cam, pin)
    # implicit Euler with 8 substeps per degree lags by ~1/16 degree: force error ~ omega_r' h/2
    assert np.max(np.abs(cycle.traction_force - exact)) < 0.01 * np.max(np.abs(exact))
    assert np.max(np.abs(cycle.sliding_speed / u_cam)) < 1e-4  # within the regularised stick creep
    assert cycle.converged


def test_twin_and_kernel_agree():
    u_cam, N = _drive(0.5)
    pin = pin_friction_torque(N, 0.0025, 0.004)
    grid = slip_grid(u_cam)
    force = 0.002 * N[:, None] * np.tanh(grid / (1e-3 * u_cam[:, None]))
    a = roller_cycle(THETA, OMEGA, u_cam, pin, grid, force, radius=R_F, inertia=INERTIA, compiled=False)
    b = roller_cycle(THETA, OMEGA, u_cam, pin, grid, force, radius=R_F, inertia=INERTIA, compiled=True)
    np.testing.assert_allclose(a.roller_speed, b.roller_speed, rtol=1e-12)
    np.testing.assert_allclose(a.traction_force, b.traction_force, rtol=1e-9, atol=1e-12)


def test_scarce_traction_slips_and_caps_the_force():
    u_cam, N = _drive(0.5)
    limit = 0.002  # mu N = 4 N, below the ~ 27 N the roller needs
    out = coulomb_traction_table(N, u_cam, limit)
    assert_provides(coulomb_traction_table, out)
    spin = roller_spin(THETA, np.full(N_ANGLES, OMEGA), u_cam, np.zeros(N_ANGLES), N, out["traction_grid"], out["traction_table"], R_F,
                       INERTIA, 0.004, 0.0025)
    assert_provides(roller_spin, spin)
    assert np.max(np.abs(spin["tangential_force"])) <= limit * 2000.0 * (1 + 1e-12)
    assert spin["roller_slipping"].any() and spin["traction_exceeded"].any()
    assert np.max(np.abs(spin["roller_slip"])) > 0.01
    # energy: the power lost is |F_t u_s| + T_pin omega_r >= 0 everywhere
    assert np.all(spin["friction_power"] >= 0.0)
    np.testing.assert_allclose(spin["traction_available"], limit * 2000.0)


def test_roller_spin_without_slip_reports_zero_slip_and_the_pin_loss():
    u_cam, N = _drive(0.0)  # constant surface speed: only the pin torque is needed
    grid = coulomb_traction_table(N, u_cam, 0.05)
    spin = roller_spin(THETA, np.full(N_ANGLES, OMEGA), u_cam, np.zeros(N_ANGLES), N, grid["traction_grid"], grid["traction_table"], R_F,
                       INERTIA, 0.004, 0.0025)
    pin = 0.0025 * 2000.0 * 0.004
    np.testing.assert_allclose(spin["tangential_force"], pin / R_F, rtol=1e-6)
    np.testing.assert_allclose(spin["friction_power"], pin * 12.0 / R_F, rtol=1e-4)
    assert not spin["roller_slipping"].any() and not spin["traction_exceeded"].any()
    np.testing.assert_allclose(spin["friction_coefficient"], pin / R_F / 2000.0, rtol=1e-6)


def test_roller_dynamics_needs_a_full_turn_and_a_positive_roller():
    with pytest.raises(InputError, match="full turn"):
        check_full_turn(np.radians([0.0, 10.0, 20.0]))
    with pytest.raises(InputError, match="roller_inertia"):
        check_roller(0.01, 0.0)
    u_cam, N = _drive()
    with pytest.raises(InputError, match="non-decreasing"):
        grid = slip_grid(u_cam)
        roller_cycle(THETA, OMEGA, u_cam, 0.0, grid, -grid, radius=R_F, inertia=INERTIA)


def test_sliding_tangential_force_takes_the_sign_of_sliding():
    out = sliding_tangential_force(np.array([10.0, 10.0, 0.0]), np.array([2.0, -1.0, 0.0]))
    assert_provides(sliding_tangential_force, out)
    np.testing.assert_array_equal(out["tangential_force"], [10.0, -10.0, 0.0])


def test_cam_friction_torque_flat_and_roller_arms():
    flat = FollowerGeometry("flat", 0.03)
    out = cam_friction_torque(np.array([100.0]), np.array([5.0]), np.array([0.01]), np.array([0.0]), flat)
    assert_provides(cam_friction_torque, out)
    # flat face: the tangent is the face, at R_o + f from the axis
    assert out["friction_torque"][0] == pytest.approx(100.0 * 0.04)
    assert out["cam_torque_with_friction"][0] == pytest.approx(5.0 + 4.0)
    roller = FollowerGeometry("roller", 0.04, 0.01, 0.005)
    A = 0.2
    out = cam_friction_torque(np.array([10.0]), np.array([0.0]), np.array([0.002]), np.array([A]), roller)
    S = math.sqrt(0.05**2 - 0.005**2) + 0.002
    # independent: the contact point and the unit normal towards the roller centre
    contact = np.array([0.005 + 0.01 * math.sin(A), S - 0.01 * math.cos(A)])
    normal = np.array([-math.sin(A), math.cos(A)])
    assert out["friction_arm"][0] == pytest.approx(float(contact @ normal), rel=1e-12)
    assert out["friction_torque"][0] == pytest.approx(10.0 * float(contact @ normal), rel=1e-12)


def test_the_contact_point_travelling_round_the_rim_changes_the_rolling_spin():
    """A roller whose contact point travels round its rim at dA/dt = omega dA/dtheta rolls at
    omega_r = u_cam / R - dA/dt: with a constant u_cam and A = 0.3 sin(theta) the spin follows the rim rate."""
    from camcontact.dynamics.roller_follower import rim_rate

    u_cam, N = _drive(0.0)
    A = 0.3 * np.sin(THETA)
    np.testing.assert_allclose(rim_rate(THETA, OMEGA, A), OMEGA * 0.3 * np.cos(THETA), rtol=1e-4, atol=1e-9)
    grid = coulomb_traction_table(N, u_cam, 0.1)
    spin = roller_spin(THETA, np.full(N_ANGLES, OMEGA), u_cam, A, N, grid["traction_grid"], grid["traction_table"],
                       R_F, INERTIA, 0.004, 0.0025)
    expected = u_cam / R_F - OMEGA * 0.3 * np.cos(THETA)
    np.testing.assert_allclose(spin["roller_speed"], expected, rtol=2e-3)
    assert np.max(np.abs(spin["roller_slip"])) < 1e-3
