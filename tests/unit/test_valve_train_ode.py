"""Lumped 2-DOF / 5-DOF valve trains (Ferrarese & Uehara): statics, quasi-static force, 2- vs 5-DOF,
seat contact, bad inputs, finiteness.

The cam lift used here is written inline (cycloidal rise and return, then dwell) so these tests do
not depend on the motion-law modules:

    rise,   x = θ/β ∈ [0, 1]:        y = L (x − sin 2πx / 2π),  y' = (L/β)(1 − cos 2πx),  y'' = (2π L/β²) sin 2πx
    return, x = (θ − β)/β ∈ [0, 1]:  y = L − (the rise),         y' = −(rise y'),           y'' = −(rise y'')
    dwell (θ >= 2β):                 y = y' = y'' = 0

with L = 8 mm, β = 70°. Peak deceleration |y''| ω² = 2π L ω²/β² = 0.0337 ω² m/s²
(3324 m/s² at 3000 rpm, 92 m/s² at 500 rpm).
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from camcontact.dynamics import LumpedValveTrain, ValveTrainResponse, simulate, valve_train_ode
from camcontact.errors import InputError

LIFT = 8e-3  # [m]
BETA = math.radians(70.0)  # rise = return span [rad]


def rpm(n: float) -> float:
    return n * math.pi / 30.0


def cycloidal_lift(theta):
    """(y [m], y' [m/rad], y'' [m/rad²]) of the cycloidal rise–return–dwell above (exact derivatives)."""
    theta = np.mod(np.asarray(theta, dtype=float), 2.0 * math.pi)
    y, d1, d2 = np.zeros_like(theta), np.zeros_like(theta), np.zeros_like(theta)
    rise = theta < BETA
    x = theta[rise] / BETA
    y[rise] = LIFT * (x - np.sin(2 * np.pi * x) / (2 * np.pi))
    d1[rise] = LIFT / BETA * (1 - np.cos(2 * np.pi * x))
    d2[rise] = 2 * np.pi * LIFT / BETA**2 * np.sin(2 * np.pi * x)
    ret = (theta >= BETA) & (theta < 2 * BETA)
    x = (theta[ret] - BETA) / BETA
    y[ret] = LIFT * (1 - (x - np.sin(2 * np.pi * x) / (2 * np.pi)))
    d1[ret] = -LIFT / BETA * (1 - np.cos(2 * np.pi * x))
    d2[ret] = -2 * np.pi * LIFT / BETA**2 * np.sin(2 * np.pi * x)
    return y, d1, d2


def assert_all_finite(response: ValveTrainResponse) -> None:
    for name in ("time", "angle", "lift", "lift_velocity", "lift_acceleration", "displacement", "velocity",
                 "contact_force", "seat_force"):
        assert np.all(np.isfinite(getattr(response, name))), name
    frame = response.to_frame()
    assert not frame.isna().any().any()
    for table in (response.jumps, response.seat_bounces, response.events):
        assert not table.isna().any().any()


@pytest.fixture(scope="module")
def two_dof():
    return LumpedValveTrain.ferrarese_2dof()


@pytest.fixture(scope="module")
def five_dof():
    return LumpedValveTrain.ferrarese_5dof()


# ---------------------------------------------------------------------------------------------
# parameter sets
# ---------------------------------------------------------------------------------------------

def test_ferrarese_parameter_sets_in_si(two_dof, five_dof):
    """Table 2 in kN/m → N/m; Table 1 springs; masses lump the same 135.9 g (see the classmethod notes)."""
    assert five_dof.masses == pytest.approx((0.0797, 0.0086, 0.0086, 0.0086, 0.0304))
    assert five_dof.stem_stiffness == pytest.approx((1.25e8, 5.03e8, 5.03e8, 5.03e8))
    assert two_dof.masses == pytest.approx((0.1055, 0.0304))
    for train in (two_dof, five_dof):
        assert train.contact_stiffness == 1.05e6 and train.contact_damping == 635.0
        assert train.seat_stiffness == 1.31e7 and train.seat_damping == 963.0
        assert train.return_spring_stiffness == 3.34e3 and train.pressure_spring_stiffness == 13.35e3
        assert train.total_mass == pytest.approx(0.1359)
    # Table 1 components: 136.8 g; both lumpings 135.9 g (the lumped valve is 64.8 g, not 65.7 g)
    assert sum(valve_train_ode.TABLE1_MASSES.values()) == pytest.approx(0.1368)
    assert sum(valve_train_ode.TABLE1_MASSES.values()) - five_dof.total_mass == pytest.approx(0.9e-3)
    assert five_dof.masses[0] == pytest.approx(valve_train_ode.TABLE1_MASSES["bucket"]
                                               + valve_train_ode.TABLE1_MASSES["shim"] + 8.6e-3)
    # 2-DOF m1 = 5-DOF m1 + m2 + m3 + m4; 2-DOF stem = series of the 5-DOF stem
    assert two_dof.masses[0] == pytest.approx(sum(five_dof.masses[:4]))
    assert two_dof.stem_stiffness[0] == pytest.approx(1.0 / (1 / 1.25e8 + 3 / 5.03e8))
    assert two_dof.series_stem_stiffness == pytest.approx(five_dof.series_stem_stiffness)


def test_natural_frequencies_are_sane(two_dof, five_dof):
    """First mode (follower on the cam, valve open) ≈ sqrt((k_c + k_r + k_p)/Σm)/2π: the whole train as one
    rigid body on the contact, return and pressure springs, 446 Hz for both models (the stem is stiff, so k_p
    in series with it is k_p); the stem modes lie far above."""
    rigid = math.sqrt((1.05e6 + 3.34e3 + 13.35e3) / 0.1359) / (2 * math.pi)
    f2, f5 = two_dof.natural_frequencies(), five_dof.natural_frequencies()
    assert f2[0] == pytest.approx(rigid, rel=5e-3) and f5[0] == pytest.approx(f2[0], rel=1e-3)
    assert f2[1] > 8e3 and f5[1] > 8e3 and np.all(np.diff(f5) > 0)
    assert two_dof.natural_frequencies(seated=True)[0] > 1.5e3


def test_static_equilibrium_on_base_circle_shares_the_preload(two_dof):
    """Base circle, zero lash: mass 1 rests on the contact (k_c) in parallel with the stem–seat chain
    k_chain = (1/k_s + 1/k_v)^-1 and the return spring, so x1 = −F_r0/(k_c + k_r + k_chain) and the cam
    carries N0 = k_c |x1|; the seat carries k_chain |x1|, and N0 + seat = F_r0 + k_r x1 (force balance on
    the whole train: the spring force at x1)."""
    F0 = two_dof.return_spring_preload
    k_chain = 1.0 / (1.0 / two_dof.stem_stiffness[0] + 1.0 / two_dof.seat_stiffness)
    x1 = -F0 / (1.05e6 + 3.34e3 + k_chain)
    static = two_dof.static_equilibrium(0.0)
    assert static.seated
    assert static.displacement[0] == pytest.approx(x1, rel=1e-12)
    assert static.contact_force == pytest.approx(-1.05e6 * x1, rel=1e-12)
    assert static.seat_force == pytest.approx(-k_chain * x1, rel=1e-9)
    assert static.contact_force + static.seat_force == pytest.approx(F0 + 3.34e3 * x1, rel=1e-12)


def test_doubling_the_mass_halves_the_squared_frequency():
    train = LumpedValveTrain(masses=(0.1,), contact_stiffness=1e6, seat_stiffness=1e7, return_spring_stiffness=0.0)
    heavy = LumpedValveTrain(masses=(0.2,), contact_stiffness=1e6, seat_stiffness=1e7, return_spring_stiffness=0.0)
    assert train.natural_frequencies()[0] == pytest.approx(math.sqrt(1e6 / 0.1) / (2 * math.pi))
    assert heavy.natural_frequencies()[0] ** 2 == pytest.approx(train.natural_frequencies()[0] ** 2 / 2)


# ---------------------------------------------------------------------------------------------
# quasi-static run
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("factory", [LumpedValveTrain.ferrarese_2dof, LumpedValveTrain.ferrarese_5dof])
def test_quasi_static_contact_force(factory):
    """At ω = 1e-3 rad/s inertia (m ÿ < 1e-7 N) and damping (c_c ẏ < 0.01 N) vanish, so N follows the statics.

    Independent calculation, valve open (follower on the cam, seat inactive): the return spring k_r on
    mass 1 is in parallel with the stem (series Σ1/k_i) in series with the pressure spring k_p, so the
    train resists x1 with k_e = k_r + (1/k_p + Σ1/k_i)^-1; with the contact in series,
    N = F_r0 + k_e x1, x1 = y − N/k_c  =>  N = (F_r0 + k_e y)/(1 + k_e/k_c). Roughly N ≈ F_r0 + (k_r + k_p) y,
    1.6 % high because of the contact compliance. Valve seated (near the base circle): the chain ends on the
    seat, k_chain = (Σ1/k_i + 1/k_v)^-1, and N = k_c ((k_r + k_chain) y + F_r0)/(k_c + k_r + k_chain).
    """
    train = factory()
    response = simulate(train, cycloidal_lift, 1e-3, cycles=1, points_per_cycle=720)
    F0, kr, kp, kc, kv = 250.0, 3.34e3, 13.35e3, 1.05e6, 1.31e7
    ks = train.series_stem_stiffness
    ke = kr + 1.0 / (1.0 / kp + 1.0 / ks)
    k_chain = 1.0 / (1.0 / ks + 1.0 / kv)
    y = response.lift
    N_open = (F0 + ke * y) / (1.0 + ke / kc)
    N_seated = kc * ((kr + k_chain) * y + F0) / (kc + kr + k_chain)
    open_ = ~response.seated
    assert not response.contact_open.any() and response.jumps.empty
    # the valve opens once the cam has taken over the seat load: y ≈ N_open(0)/k_c = 0.24 mm
    assert y[open_].min() == pytest.approx(F0 / (1 + ke / kc) / kc, rel=0.05)
    lifted = open_ & (y > 0.5e-3)
    np.testing.assert_allclose(response.contact_force[lifted], N_open[lifted], rtol=1e-5)
    np.testing.assert_allclose(response.contact_force[~open_], N_seated[~open_], atol=0.02)
    approx = F0 + (kr + kp) * y[lifted]
    np.testing.assert_allclose(response.contact_force[lifted], approx, rtol=0.02)
    # base circle: the preload split of the static equilibrium
    base = y == 0.0
    assert response.contact_force[base] == pytest.approx(train.static_equilibrium(0.0).contact_force, rel=1e-6)
    assert_all_finite(response)


# ---------------------------------------------------------------------------------------------
# 2-DOF vs 5-DOF, jump, seat
# ---------------------------------------------------------------------------------------------

def test_two_and_five_dof_agree_at_low_speed(two_dof, five_dof):
    """500 rpm: cam harmonics (8.3 Hz) far below every mode, so the stiff stem hardly matters: both models
    give the same N(θ) to well under 1 % of its peak (the peak ~378 N)."""
    r2 = simulate(two_dof, cycloidal_lift, rpm(500))
    r5 = simulate(five_dof, cycloidal_lift, rpm(500))
    grid = np.linspace(0.0, r2.angle[-1], 2 * 720 + 1)
    N2 = np.interp(grid, r2.angle, r2.contact_force)
    N5 = np.interp(grid, r5.angle, r5.contact_force)
    assert np.max(np.abs(N2 - N5)) < 0.5e-2 * N2.max()
    assert r2.cycle_mean("N") == pytest.approx(r5.cycle_mean("N"), rel=1e-3)
    assert r2.jumps.empty and r5.jumps.empty
    for r in (r2, r5):
        assert_all_finite(r)


@pytest.mark.parametrize("factory", [LumpedValveTrain.ferrarese_2dof, LumpedValveTrain.ferrarese_5dof])
def test_weak_spring_jumps_at_high_speed_strong_spring_does_not(factory):
    """3000 rpm: the follower side needs m ÿ ≈ 0.136 kg × 3324 m/s² ≈ 450 N of spring force at the peak
    deceleration (θ = 52.5°). With F_r0 = 100 N (+ ≈ 110 N from k_r, k_p at that lift) it cannot: the
    follower leaves the cam during the rise's deceleration (θ between 35° and 70°) and the gap opens by
    millimetres. With F_r0 = 800 N the margin is > 300 N: no gap ever opens and the valve never bounces.

    (With any preload the heavily damped contact, ζ ≈ 1, unloads for a few degrees just after the valve
    seats at this speed, N = 0 without a gap: a "contact" event, not a jump. So the strong-spring check on
    N > 0 covers the lift up to 115°, before seating.)"""
    weak = simulate(factory(return_spring_preload=100.0), cycloidal_lift, rpm(3000))
    assert weak.jumped and weak.contact_open.any()
    first = weak.jumps.iloc[0]
    assert 35.0 < first["start angle [deg]"] < 70.0
    assert first["end angle [deg]"] > first["start angle [deg]"] and first["duration [s]"] > 0
    assert first["max gap [m]"] > 1e-4 and bool(first["complete"])
    assert set(weak.jumps["cycle"]) == {1, 2}
    assert np.all(weak.contact_force[weak.contact_open] == 0.0)
    # the jump table agrees with the flag array and the gap
    start = math.radians(first["start angle [deg]"])
    end = math.radians(first["end angle [deg]"])
    inside = (weak.angle > start + 1e-9) & (weak.angle < end - 1e-9)
    assert weak.contact_open[inside].all()
    gap = weak.displacement[:, 0] - weak.lift
    assert np.max(gap[inside]) == pytest.approx(first["max gap [m]"])
    assert np.all(gap[~weak.contact_open] < 1e-12)
    events = weak.events
    assert {"contact", "gap", "seat", "valve open"} <= set(events["switch"])
    # the force unloads before the gap opens
    unload = events[(events["switch"] == "contact") & ~events["active"]]["angle [deg]"].iloc[0]
    assert unload <= first["start angle [deg]"]
    assert_all_finite(weak)

    strong = simulate(factory(return_spring_preload=800.0), cycloidal_lift, rpm(3000))
    assert not strong.jumped and not strong.contact_open.any()
    assert strong.seat_bounces.empty
    lifting = (np.degrees(strong.angle) % 360.0 > 1.0) & (np.degrees(strong.angle) % 360.0 < 115.0)
    assert strong.contact_force[lifting].min() > 50.0
    assert_all_finite(strong)


def test_seat_force_only_while_seated(two_dof):
    r = simulate(two_dof, cycloidal_lift, rpm(2000))
    lifted = r.displacement[:, -1] > 1e-12  # the valve-open switch has a hysteresis of ~1e-14 m
    assert lifted.any() and (~lifted).any()
    assert np.all(r.seat_force[lifted] == 0.0)
    assert np.all(r.seat_force[~r.seated] == 0.0)
    assert np.all(r.seat_force >= 0.0) and np.all(r.contact_force >= 0.0)
    # on the base circle the seat carries most of the preload (see the static test)
    dwell = r.angle % (2 * math.pi) > math.radians(200.0)
    assert np.all(r.seat_force[dwell] > 200.0)
    assert r.seated[dwell].all() and not r.seated[r.lift > 1e-3].any()
    assert_all_finite(r)


def test_response_tables_and_cycle_mean(two_dof):
    r = simulate(two_dof, cycloidal_lift, rpm(1000), cycles=2, points_per_cycle=360)
    frame = r.to_frame()
    for column in ("time [s]", "angle [deg]", "lift [m]", "x1 [m]", "x2 [m]", "v1 [m/s]", "N [N]",
                   "seat force [N]", "contact open [-]", "seated [-]"):
        assert column in frame.columns
    assert len(frame) == r.time.size and np.all(np.diff(r.time) > 0)
    assert r.angle[0] == 0.0 and r.angle[-1] == pytest.approx(4 * math.pi)
    assert r.displacement.shape == (r.time.size, 2)
    # cycle mean by trapezoid in time, by name, by column and by array
    trapezoid = getattr(np, "trapezoid", None) or np.trapz
    expected = trapezoid(r.contact_force, r.time) / r.time[-1]
    assert r.cycle_mean("N") == pytest.approx(expected)
    assert r.cycle_mean("N [N]") == pytest.approx(expected)
    assert r.cycle_mean(r.contact_force) == pytest.approx(expected)
    assert r.cycle_mean("N", skip_cycles=1) == pytest.approx(expected, rel=1e-3)  # periodic: no start transient
    assert list(r.events.columns) == ["time [s]", "angle [deg]", "switch", "active"]
    assert {"seat", "valve open"} <= set(r.events["switch"]) <= {"contact", "gap", "seat", "valve open"}
    assert np.all(np.diff(r.events["time [s]"]) >= 0.0)
    assert list(r.jumps.columns) == ["cycle", "start angle [deg]", "end angle [deg]", "duration [s]",
                                     "max gap [m]", "complete"]
    assert isinstance(r.seat_bounces, pd.DataFrame) and "max lift [m]" in r.seat_bounces.columns
    with pytest.raises(InputError, match="quantity"):
        r.cycle_mean("friction")
    with pytest.raises(InputError, match="skip_cycles"):
        r.cycle_mean("N", skip_cycles=2)
    with pytest.raises(InputError, match="shape"):
        r.cycle_mean(np.ones(3))


def test_methods_agree(two_dof):
    """LSODA and Radau (each with its own error control) give the same response."""
    a = simulate(two_dof, cycloidal_lift, rpm(3000), method="LSODA")
    b = simulate(two_dof, cycloidal_lift, rpm(3000), method="Radau")
    assert a.record.method == "LSODA" and b.record.method == "Radau"
    assert a.cycle_mean("N") == pytest.approx(b.cycle_mean("N"), rel=1e-5)
    assert len(a.jumps) == len(b.jumps)
    np.testing.assert_allclose(a.jumps["start angle [deg]"], b.jumps["start angle [deg]"], atol=1e-3)


def test_motion_program_lift():
    """MotionProgram.rise_return_dwell(...).evaluate (4 arrays) drives the model like the inline cycloid."""
    motion_program = pytest.importorskip("camcontact.kinematics.motion_program")
    program = motion_program.MotionProgram.rise_return_dwell("8 mm", "70 deg", "70 deg", "cycloidal", "cycloidal")
    train = LumpedValveTrain.ferrarese_2dof()
    from_program = simulate(train, program.evaluate, rpm(1500))
    inline = simulate(train, cycloidal_lift, rpm(1500))
    theta = np.linspace(0.0, 2 * math.pi, 3601)
    for mine, theirs in zip(cycloidal_lift(theta), program.evaluate(theta)[:3]):
        np.testing.assert_allclose(theirs, mine, rtol=1e-9, atol=1e-15)
    assert from_program.cycle_mean("N") == pytest.approx(inline.cycle_mean("N"), rel=1e-6)
    assert simulate(train, program, rpm(1500)).cycle_mean("N") == pytest.approx(inline.cycle_mean("N"), rel=1e-6)
    assert_all_finite(from_program)


# ---------------------------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------------------------

BASE = dict(masses=(0.1, 0.03), stem_stiffness=(7e7,), contact_stiffness=1e6, seat_stiffness=1e7,
            return_spring_stiffness=3e3)


@pytest.mark.parametrize(
    ("change", "pattern"),
    [
        (dict(masses=(-0.1, 0.03)), r"masses = .*-0\.1.* must be finite and > 0 \[kg\]"),
        (dict(masses=(0.1, 0.0)), r"masses .* > 0 \[kg\]"),
        (dict(masses=()), r"masses = \(\): give at least one mass"),
        (dict(stem_stiffness=(7e7, 7e7)), r"stem_stiffness = .*2 values for 2 masses; expected 1"),
        (dict(stem_stiffness=(-7e7,)), r"stem_stiffness = .*-70000000\.0.* > 0 \[N/m\]"),
        (dict(contact_stiffness=0.0), r"contact_stiffness = 0\.0: must be finite and > 0 \[N/m\]"),
        (dict(seat_stiffness=math.nan), r"seat_stiffness = nan"),
        (dict(contact_damping=-1.0), r"contact_damping = -1\.0: must be finite and >= 0"),
        (dict(return_spring_preload=-5.0), r"return_spring_preload = -5\.0: .*>= 0 \[N\]"),
        (dict(stem_damping=(1.0, 2.0)), r"stem_damping = .*expected 1"),
        (dict(stem_damping_ratio=1.5), r"stem_damping_ratio = 1\.5"),
        (dict(masses="heavy"), r"masses = 'heavy': expected a sequence of numbers"),
        (dict(contact_stiffness="stiff"), r"contact_stiffness = 'stiff': expected a number"),
    ],
)
def test_bad_train_input(change, pattern):
    with pytest.raises(InputError, match=pattern):
        LumpedValveTrain(**{**BASE, **change})


@pytest.mark.parametrize(
    ("kwargs", "pattern"),
    [
        (dict(speed=0.0), r"speed = 0\.0: cam speed ω must be finite and > 0"),
        (dict(speed=-10.0), r"speed = -10\.0"),
        (dict(speed=math.inf), r"speed = inf"),
        (dict(cycles=0), r"cycles = 0: allowed cycles >= 1"),
        (dict(cycles=1.5), r"cycles = 1\.5: expected an integer"),
        (dict(cycles=math.inf), r"cycles = inf: expected an integer"),
        (dict(points_per_cycle=4), r"points_per_cycle = 4"),
        (dict(method="RK45"), r"method = 'RK45'; allowed: auto, LSODA, Radau, BDF"),
        (dict(rtol=0.0), r"rtol"),
        (dict(atol=(1.0, 2.0, 3.0)), r"atol"),
    ],
)
def test_bad_simulate_input(two_dof, kwargs, pattern):
    args = dict(speed=rpm(1000))
    args.update(kwargs)
    with pytest.raises(InputError, match=pattern):
        simulate(two_dof, cycloidal_lift, **args)


def test_bad_lift_callable(two_dof):
    with pytest.raises(InputError, match="expected a callable"):
        simulate(two_dof, 8e-3, rpm(1000))
    with pytest.raises(InputError, match="at least 3 arrays"):
        simulate(two_dof, lambda theta: (theta, theta), rpm(1000))
    with pytest.raises(InputError, match="non-finite y"):
        simulate(two_dof, lambda theta: (theta * np.nan, theta, theta), rpm(1000))
    with pytest.raises(InputError, match="expected a LumpedValveTrain"):
        simulate("2dof", cycloidal_lift, rpm(1000))
