"""Numerical dry contact (contact.dry_contact) and roller profiles / laminae (contact.roller_profile) against
closed forms: Hertz's circle and line contact, Love's rectangle, Lundberg's uniform pressure."""

import math

import numpy as np
import pytest

from camcontact.contact.dry_contact import love_rectangle, solve_dry_contact
from camcontact.contact.hertz_elliptical import hertz_elliptical
from camcontact.contact.hertz_line import hertz_line, line_approach
from camcontact.contact.load_distribution import line_contact_stiffness
from camcontact.contact.roller_profile import RollerProfile, roller_dry_contact, solve_laminae
from camcontact.errors import InputError

E = 2.27e11  # E' of steel on steel [Pa]


def cells(half: float, n: int) -> np.ndarray:
    return (np.arange(n) + 0.5) * (2 * half / n) - half


def test_love_rectangle_on_long_thin_cells():
    """The asinh form keeps its digits where the logarithms of differences would cancel (dy/dx = 1e5): far from a
    1 um x 100 mm strip the displacement is the point load's area/r, and no value is NaN."""
    a, b = 0.5e-6, 0.05
    values = love_rectangle(np.array([1.0, 0.0, 3e-6]), np.array([0.0, 0.0, 0.01]), a, b)
    assert np.all(np.isfinite(values)) and values[0] == pytest.approx(4 * a * b / 1.0, rel=1e-3)


def test_love_rectangle_centre_and_far_field():
    """At the centre of a square 2a x 2a, F is the integral of dA/r: 8 a int_0^(pi/4) sec = 8 a ln(1 + sqrt 2); far
    away F -> area/r, a point load's P/r."""
    a = 1e-3
    assert love_rectangle(0.0, 0.0, a, a) == pytest.approx(8 * a * math.log(1 + math.sqrt(2)), rel=1e-12)
    far = 1.0
    assert love_rectangle(far, 0.0, a, a) == pytest.approx(4 * a * a / far, rel=1e-5)


def test_sphere_on_flat_converges_to_hertz():
    """A 10 mm radius sphere under 100 N: p0 and the approach within 0.05 % and 0.01 % of Hertz on 64 x 64 cells."""
    R, W = 0.01, 100.0
    hertz = hertz_elliptical(W, R, R, E)
    x = cells(1.5 * hertz.a_x, 64)
    X, Y = np.meshgrid(x, x)
    result = solve_dry_contact(x, x, (X**2 + Y**2) / (2 * R), W, E)
    assert result.p_max == pytest.approx(hertz.p_max, rel=5e-4)
    assert result.approach == pytest.approx(hertz.approach, rel=1e-4)
    assert result.pressure.sum() * (x[1] - x[0]) ** 2 == pytest.approx(W, rel=1e-12)
    assert result.gap.min() > -1e-8 * hertz.approach and result.changes[-1] < 1e-8
    inside = np.hypot(X, Y) < 0.9 * hertz.a_x
    assert np.all(result.pressure[inside] > 0) and np.all(result.pressure[np.hypot(X, Y) > 1.1 * hertz.a_x] == 0)


def test_long_roller_middle_and_edge_stress():
    """A straight roller (R 5 mm, l 10 mm, 5 kN): the pressure in the middle is close to (a few per cent below)
    the 2-D Hertz value of the mean load per length, while the ends carry a peak well above it (the edge stress:
    its height grows as the grid resolves the corner, its place is the last cell)."""
    W, l, R = 5000.0, 0.01, 0.005
    result = roller_dry_contact(W, l, R, E, RollerProfile())
    along = result.along()
    p_h = hertz_line(W / l, R, E).p_h
    middle = float(np.interp(0.0, result.y, along))
    assert 0.92 < middle / p_h < 0.98
    assert along.max() > 2.0 * p_h and abs(result.y[np.argmax(along)]) > 0.49 * l
    assert result.load_per_row().sum() * (result.y[1] - result.y[0]) == pytest.approx(W, rel=1e-10)


def test_lundberg_profile_gives_uniform_pressure():
    """Lundberg's logarithmic profile for the load it was designed for: uniform pressure at the Hertz value of the
    mean load per length over the middle 80 % of the roller (within 0.5 %)."""
    W, l, R = 5000.0, 0.01, 0.005
    result = roller_dry_contact(W, l, R, E, RollerProfile(kind="lundberg", design_load=W))
    along = result.along()
    middle = np.abs(result.y) < 0.4 * l
    assert along[middle] / hertz_line(W / l, R, E).p_h == pytest.approx(np.ones(middle.sum()), abs=5e-3)


def test_laminae_of_a_straight_aligned_roller_are_hertz():
    """Without profile and tilt every lamina carries Q/n and its pressure is the Hertz pressure of the mean load
    per length; the approach is Palmgren's of the one contact (3.81 (2/(pi E'))^0.9 Q^0.9 / l^0.8, within 6 % of the
    numerical half-space approach), for any number of laminae."""
    W, l, R = 5000.0, 0.01, 0.005
    result = solve_laminae(W, l, R, E, RollerProfile(), laminae=40)
    assert result.load == pytest.approx(np.full(40, W / 40), rel=1e-10)
    assert result.pressure == pytest.approx(np.full(40, hertz_line(W / l, R, E).p_h), rel=1e-10)
    assert result.delta == pytest.approx(line_approach("palmgren", E_reduced=E, force=W, length=l), rel=1e-9)
    assert result.delta == pytest.approx(0.5 * (W / line_contact_stiffness(l)) ** 0.9, rel=0.01)  # steel: one of two
    assert result.delta == pytest.approx(roller_dry_contact(W, l, R, E, RollerProfile()).approach, rel=0.06)
    assert solve_laminae(W, l, R, E, RollerProfile(), laminae=7).delta == pytest.approx(result.delta, rel=1e-9)
    assert result.residual <= 1e-10 and 1 <= result.iterations <= 100  # the convergence record


def test_misalignment_loads_one_end_and_crowning_relieves_it():
    """A tilt moves load to one end in both models; the numerical peak at that end is far above the laminae's, and a
    logarithmic crown lowers it."""
    W, l, R, tilt = 5000.0, 0.01, 0.005, 5e-4
    straight = solve_laminae(W, l, R, E, RollerProfile(), misalignment=tilt)
    assert straight.load[-1] > straight.load[0] and straight.load.sum() == pytest.approx(W)
    numerical = roller_dry_contact(W, l, R, E, RollerProfile(), misalignment=tilt).along()
    crowned = roller_dry_contact(W, l, R, E, RollerProfile(kind="johns_gohar", design_load=W), misalignment=tilt).along()
    assert numerical[-1] > numerical[0] and numerical.max() > 1.3 * straight.pressure.max()
    assert crowned.max() < 0.6 * numerical.max()


def test_johns_gohar_is_finite_at_the_ends_and_bad_profiles_are_named():
    l, R, W = 0.01, 0.005, 5000.0
    ends = np.array([-0.499999 * l, 0.499999 * l])
    assert np.all(np.isfinite(RollerProfile(kind="johns_gohar", design_load=W).drop(ends, l, E, R)))
    assert RollerProfile(kind="lundberg", design_load=W).drop(ends, l, E, R)[0] > 2 * RollerProfile(
        kind="johns_gohar", design_load=W).drop(ends, l, E, R)[0]
    assert RollerProfile(kind="crowned", crown_drop=1e-5).drop(np.array([0.25 * l]), l, E, R)[0] == pytest.approx(2.5e-6)
    with pytest.raises(InputError, match="kind = 'barrel'"):
        RollerProfile(kind="barrel")
    with pytest.raises(InputError, match="design_load"):
        RollerProfile(kind="lundberg")
    with pytest.raises(InputError, match="crown_drop"):
        RollerProfile(kind="crowned")
    with pytest.raises(InputError, match="inside the contact length"):
        RollerProfile().drop(np.array([0.6 * l]), l, E, R)
    with pytest.raises(InputError, match="laminae = 3"):
        solve_laminae(W, l, R, E, RollerProfile(), laminae=3)
    with pytest.raises(InputError, match="load = -1"):
        solve_laminae(-1.0, l, R, E, RollerProfile())
    with pytest.raises(InputError, match="must be 1-D grids"):
        solve_dry_contact(np.zeros(3), np.zeros(3), np.zeros((3, 3)), 1.0, E)


def test_loaded_length_is_interpolated_where_the_approach_crosses_zero():
    """A circular crown y^2 / (2 R_y) loads |y| < sqrt(2 R_y delta): the loaded length follows from the approach's zero
    crossing between the lamina centres (error of the linear interpolation only), not from counting whole laminae; a
    straight roller is loaded over its whole length; no load, no length."""
    l, R, R_y = 0.02, 0.006, 3.0
    profile = RollerProfile(kind="crowned", crown_drop=l**2 / (8 * R_y))
    for laminae in (30, 60):
        result = solve_laminae(3000.0, l, R, E, profile, laminae=laminae)
        assert result.loaded_length == pytest.approx(2 * math.sqrt(2 * R_y * result.delta), rel=2e-3)
        assert result.loaded_length < l
    assert solve_laminae(3000.0, l, R, E, RollerProfile()).loaded_length == pytest.approx(l, rel=1e-12)
