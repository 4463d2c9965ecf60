"""Cycle summaries (camcontact.steps.summaries) called alone, on plain arrays over a cam turn.

Expected values: minima and maxima by inspection of the arrays; means over a turn from the analytic
integral of a periodic signal (r(t) = r0 (1 + sin(omega t)) has mean r0 and integral r0 T over the period
T = 2 pi/omega; equally spaced samples of a whole turn reproduce both exactly).
"""

import math

import numpy as np
import pytest

from camcontact.errors import InputError
from camcontact.steps.summaries import (
    friction_power_mean,
    friction_torque_mean,
    h_min_cycle,
    jump_margin,
    peak_contact_force,
    peak_pressure,
    wear_rate_mean,
)
from step_checks import assert_provides

THETA = np.linspace(0.0, 2 * math.pi, 72, endpoint=False)  # 5 deg steps over one turn


def test_extremes_of_force_and_pressure():
    """jump_margin = smallest contact force (negative: the follower jumps), contact_force_max the largest,
    p_h_max the largest Hertz pressure."""
    force = np.array([900.0, 2500.0, -12.5, 1000.0])
    out = jump_margin(force)
    assert_provides(jump_margin, out)
    assert out["jump_margin"] == -12.5
    out = peak_contact_force(force)
    assert_provides(peak_contact_force, out)
    assert out["contact_force_max"] == 2500.0
    out = peak_pressure(np.array([0.0, 1.1e9, 0.9e9]))
    assert_provides(peak_pressure, out)
    assert out["p_h_max"] == 1.1e9


def test_h_min_cycle_ignores_angles_without_film():
    """The thinnest film over the angles that have one (NaN where contact is lost); 0 when none has one."""
    out = h_min_cycle(np.array([3e-7, np.nan, 1.2e-7, 2e-7]))
    assert_provides(h_min_cycle, out)
    assert out["h_min_cycle"] == 1.2e-7
    assert h_min_cycle(np.full(3, np.nan))["h_min_cycle"] == 0.0


def test_friction_power_mean_of_a_periodic_signal():
    """P(theta) = 40 (1 + sin theta) W: mean 40 W over the turn, 40 x 2 pi / 100 J per turn at 100 rad/s."""
    out = friction_power_mean(40.0 * (1 + np.sin(THETA)), 100.0, THETA)
    assert_provides(friction_power_mean, out)
    assert out["friction_power_mean"] == pytest.approx(40.0, rel=1e-12)
    assert out["friction_energy_per_cycle"] == pytest.approx(40.0 * 2 * math.pi / 100.0, rel=1e-12)


def test_friction_energy_follows_the_cam_speed_over_the_turn():
    """A cam accelerating from 100 to 200 rad/s over the turn (omega^2 = omega0^2 + 2 a theta) under a constant
    50 W: the energy is P times the turn's duration, int dtheta/omega = 2 pi (omega1 - omega0)/(omega1^2 -
    omega0^2) x 2 = 4 pi/300 s (exact for the linear-in-time speed), and the time mean is 50 W."""
    theta = np.linspace(0.0, 2.0 * math.pi, 20001)[:-1]
    a = (200.0**2 - 100.0**2) / (4.0 * math.pi)
    omega = np.sqrt(100.0**2 + 2.0 * a * theta)
    out = friction_power_mean(np.full(theta.size, 50.0), omega, theta)
    assert out["friction_power_mean"] == pytest.approx(50.0, rel=1e-12)
    assert out["friction_energy_per_cycle"] == pytest.approx(50.0 * 4.0 * math.pi / 300.0, rel=1e-4)
    # the speed at theta = 0 alone would give 50 x 2 pi/100 J, 50 % more
    assert out["friction_energy_per_cycle"] < 0.7 * 50.0 * 2.0 * math.pi / 100.0
    # a power proportional to the speed, P = 0.5 omega W (a friction torque of 0.5 N m): energy = 0.5 x 2 pi J
    # whatever the speed law, and the time mean = energy / (4 pi/300 s) = 75 W, not the angle mean of P
    # (0.5 x mean omega over the angles = 77.8 W)
    torque = friction_power_mean(0.5 * omega, omega, theta)
    assert torque["friction_energy_per_cycle"] == pytest.approx(math.pi, rel=1e-12)
    assert torque["friction_power_mean"] == pytest.approx(math.pi / (4.0 * math.pi / 300.0), rel=1e-4)
    assert abs(torque["friction_power_mean"] - float(np.mean(0.5 * omega))) > 2.0
    wear = wear_rate_mean(1e-12 * omega, omega, theta)
    assert wear["wear_volume_per_cycle"] == pytest.approx(2e-12 * math.pi, rel=1e-12)
    assert wear["wear_rate_mean"] == pytest.approx(2e-12 * math.pi / (4.0 * math.pi / 300.0), rel=1e-4)


def test_friction_torque_mean_and_peak_drive_torque():
    """T_f = 2 (1 + cos theta) N m: mean 2 N m; drive torque 10 sin theta + T_f peaks near 10.2 N m."""
    friction = 2.0 * (1 + np.cos(THETA))
    out = friction_torque_mean(friction, 10.0 * np.sin(THETA) + friction, THETA)
    assert_provides(friction_torque_mean, out)
    assert out["friction_torque_mean"] == pytest.approx(2.0, rel=1e-12)
    assert out["cam_torque_with_friction_max"] == pytest.approx(np.max(10.0 * np.sin(THETA) + friction))


def test_wear_rate_mean_and_volume_per_turn():
    """r = 2e-12 (1 + sin theta) m^3/s at omega = 100 rad/s: mean 2e-12 m^3/s, volume per turn
    integral r dt = 2e-12 x 2 pi/100 m^3."""
    out = wear_rate_mean(2e-12 * (1 + np.sin(THETA)), 100.0, THETA)
    assert_provides(wear_rate_mean, out)
    assert out["wear_rate_mean"] == pytest.approx(2e-12, rel=1e-12)
    assert out["wear_volume_per_cycle"] == pytest.approx(2e-12 * 2 * math.pi / 100.0, rel=1e-12)


def test_means_need_equally_spaced_angles():
    """Unequally spaced angles are not a time mean at constant speed: InputError."""
    theta = np.radians([0.0, 10.0, 30.0, 90.0])
    with pytest.raises(InputError, match="equally spaced"):
        friction_power_mean(np.ones(4), 100.0, theta)
    with pytest.raises(InputError, match="equally spaced"):
        wear_rate_mean(np.ones(4), 100.0, theta)
