"""Valve-train ODE hard cases: violent jumps, free flight, no damping, chattering guards — finite or loud."""

from __future__ import annotations

import math

import numpy as np
import pytest

from camcontact.dynamics import LumpedValveTrain, simulate, valve_train_ode
from camcontact.errors import ConvergenceError, InputError

LIFT, BETA = 8e-3, math.radians(70.0)


def cycloidal_lift(theta):
    """Cycloidal rise and return over 70° each, 8 mm, then dwell (as in tests/unit/test_valve_train_ode.py)."""
    theta = np.mod(np.asarray(theta, dtype=float), 2.0 * math.pi)
    y, d1, d2 = np.zeros_like(theta), np.zeros_like(theta), np.zeros_like(theta)
    for sign, mask, x in ((1.0, theta < BETA, theta / BETA),
                          (-1.0, (theta >= BETA) & (theta < 2 * BETA), (theta - BETA) / BETA)):
        x = x[mask]
        rise = LIFT * (x - np.sin(2 * np.pi * x) / (2 * np.pi))
        y[mask] = rise if sign > 0 else LIFT - rise
        d1[mask] = sign * LIFT / BETA * (1 - np.cos(2 * np.pi * x))
        d2[mask] = sign * 2 * np.pi * LIFT / BETA**2 * np.sin(2 * np.pi * x)
    return y, d1, d2


def rpm(n: float) -> float:
    return n * math.pi / 30.0


def assert_finite(response):
    for name in ("time", "lift", "displacement", "velocity", "contact_force", "seat_force"):
        assert np.all(np.isfinite(getattr(response, name))), name
    assert not response.to_frame().isna().any().any()
    assert not response.jumps.isna().any().any() and not response.seat_bounces.isna().any().any()
    assert np.all(response.contact_force >= 0.0) and np.all(response.seat_force >= 0.0)


@pytest.mark.parametrize("factory", [LumpedValveTrain.ferrarese_2dof, LumpedValveTrain.ferrarese_5dof])
def test_free_flight_without_any_spring(factory):
    """No preload, return or pressure spring: thrown off at the start of the rise's deceleration, the train
    flies on at constant speed and never returns. The jump is reported as not complete, and the values stay
    finite (the gap grows to ~85 mm in one revolution)."""
    train = factory(return_spring_preload=0.0, return_spring_stiffness=0.0, pressure_spring_stiffness=0.0)
    r = simulate(train, cycloidal_lift, rpm(3000), cycles=1)
    assert len(r.jumps) == 1 and not bool(r.jumps["complete"].iloc[0])
    assert r.jumps["end angle [deg]"].iloc[0] == pytest.approx(360.0)
    assert r.jumps["max gap [m]"].iloc[0] > 10 * LIFT
    assert r.contact_open[-1] and r.contact_force[-1] == 0.0
    assert_finite(r)


@pytest.mark.parametrize("factory", [LumpedValveTrain.ferrarese_2dof, LumpedValveTrain.ferrarese_5dof])
def test_ten_thousand_rpm(factory):
    """Far beyond the design speed (peak deceleration 3.7e4 m/s², 5 kN of inertia against ~400 N of
    springs): large jumps and seat bounces, all reported, nothing non-finite."""
    r = simulate(factory(), cycloidal_lift, rpm(10000))
    assert r.jumped and r.jumps["max gap [m]"].max() > 1e-3
    assert_finite(r)


@pytest.mark.parametrize("factory", [LumpedValveTrain.ferrarese_2dof, LumpedValveTrain.ferrarese_5dof])
def test_undamped_train_stays_finite(factory):
    """No contact, seat or stem damping: the stem modes ring for the whole run and the valve bounces on
    the seat; the event location still works and energy does not blow up."""
    r = simulate(factory(contact_damping=0.0, seat_damping=0.0, stem_damping_ratio=0.0), cycloidal_lift, rpm(3000))
    assert len(r.seat_bounces) > 0
    assert np.max(np.abs(r.velocity)) < 20.0  # [m/s]; the cam's peak lift velocity is 2 L ω/β = 4.1 m/s
    assert_finite(r)


def test_start_on_the_flank_of_the_cam():
    """Starting mid-rise (static equilibrium at y(35°), all masses at the cam's velocity) is a transient,
    not a failure."""
    r = simulate(LumpedValveTrain.ferrarese_2dof(), cycloidal_lift, rpm(3000), start_angle=math.radians(35.0))
    assert not r.seated[0] and r.angle[0] == pytest.approx(math.radians(35.0))
    assert_finite(r)


def test_too_many_events_is_a_convergence_error():
    with pytest.raises(ConvergenceError, match=r"more than max_events = 3 contact switches by θ = \d+"):
        simulate(LumpedValveTrain.ferrarese_2dof(return_spring_preload=100.0), cycloidal_lift, rpm(3000),
                 max_events=3)


def test_chattering_guard(monkeypatch):
    """Switches closer together than ``min_event_interval``, more than ``ZENO_RUN`` of them in a row, are
    reported as Zeno chattering. Made to trip here with an absurd interval (every switch is 'too close')
    and a short run."""
    monkeypatch.setattr(valve_train_ode, "ZENO_RUN", 5)
    train = LumpedValveTrain.ferrarese_2dof(return_spring_preload=100.0)
    with pytest.raises(ConvergenceError, match=r"chattering \(Zeno\) near θ = .* more than 5 consecutive"):
        simulate(train, cycloidal_lift, rpm(3000), min_event_interval=1.0)
    simulate(train, cycloidal_lift, rpm(3000))  # the default interval (1 ns) lets the same run pass


def test_non_finite_lift_is_refused_up_front():
    """The lift is tabulated once before integrating; a NaN anywhere in it is bad input, never a NaN result."""
    def bad(theta):
        y, d1, d2 = cycloidal_lift(theta)
        return y, np.where(np.abs(theta - 0.5) < 1e-3, np.nan, d1), d2

    with pytest.raises(InputError, match="non-finite dy/dθ"):
        simulate(LumpedValveTrain.ferrarese_2dof(), bad, rpm(3000))
