"""Internal load distribution of a spherical roller bearing (camcontact.contact.load_distribution).

Checks with independent numbers: Stribeck's relation for line contact with zero clearance
(Q_max = 4.08 F_r / (Z cos alpha) per row, NSK catalogue E728 §5.1 / Harris & Kotzalas ch. 7; the
exact discrete value for Z rollers is Z / sum_j max(cos psi_j, 0)^(19/9), because with zero
clearance the approach of roller j is delta_max cos psi_j), force balance, the load zone against
the clearance, a pure axial load shared equally by one row, and degenerate inputs.
"""

import math

import numpy as np
import pytest

import camcontact as cc
from camcontact.contact.load_distribution import line_contact_stiffness, solve_load_distribution
from camcontact.errors import InputError

ALPHA = math.radians(10.0)
K = line_contact_stiffness(0.04)


@pytest.mark.parametrize("Z", [12, 25, 60])
def test_stribeck_relation_for_zero_clearance(Z):
    result = solve_load_distribution(100e3, 0.0, rollers_per_row=Z, contact_angle=ALPHA, stiffness=K)
    psi = 2 * np.pi * np.arange(Z) / Z
    exact = Z / np.sum(np.clip(np.cos(psi), 0.0, None) ** (19 / 9))
    per_row = 0.5 * 100e3
    assert result.Q_max * Z * math.cos(ALPHA) / per_row == pytest.approx(exact, rel=1e-9)
    assert result.Q_max * Z * math.cos(ALPHA) / per_row == pytest.approx(4.08, rel=0.005)  # Stribeck
    assert np.degrees(result.load_zone).max() < 90.0 + 360.0 / Z  # half the rollers loaded


@pytest.mark.parametrize("Fr, Fa, clearance", [(100e3, 0.0, 0.0), (100e3, 20e3, 50e-6), (10e3, 40e3, 150e-6),
                                              (0.0, 50e3, 0.0), (1.0, 0.0, 1e-3), (250e3, -30e3, -10e-6)])
def test_roller_loads_balance_the_applied_load(Fr, Fa, clearance):
    result = solve_load_distribution(Fr, Fa, rollers_per_row=25, contact_angle=ALPHA, stiffness=K,
                                     clearance=clearance)
    radial, axial = result.force_balance()
    assert radial == pytest.approx(Fr, rel=1e-9, abs=1e-9 * max(Fr, Fa, 1.0))
    assert axial == pytest.approx(Fa, rel=1e-9, abs=1e-9 * max(Fr, Fa, 1.0))
    assert np.all(np.isfinite(result.Q)) and np.all(result.Q >= 0.0)


def test_load_zone_shrinks_with_clearance_and_grows_with_preload():
    zones, loaded, peaks = [], [], []
    for clearance in (-20e-6, 0.0, 20e-6, 100e-6, 300e-6):
        result = solve_load_distribution(100e3, 0.0, rollers_per_row=25, contact_angle=ALPHA, stiffness=K,
                                         clearance=clearance)
        zones.append(result.load_zone.max())
        loaded.append(int(result.loaded.sum()))
        peaks.append(result.Q_max)
    assert zones == sorted(zones, reverse=True) and loaded == sorted(loaded, reverse=True)
    assert peaks[1:] == sorted(peaks[1:])  # with play: fewer rollers carry the load
    assert peaks[0] > peaks[1]  # a preload adds internal load to every roller
    assert zones[0] == pytest.approx(math.pi, abs=2 * math.pi / 25)  # preload: all rollers loaded
    assert loaded[-1] < loaded[1] / 2


def test_pure_axial_load_is_shared_equally_by_one_row():
    result = solve_load_distribution(0.0, 50e3, rollers_per_row=25, contact_angle=ALPHA, stiffness=K)
    assert np.allclose(result.Q[0], 50e3 / (25 * math.sin(ALPHA)), rtol=1e-9)
    assert np.all(result.Q[1] == 0.0) and result.delta_r == pytest.approx(0.0, abs=1e-15)


def test_zero_load_and_a_tiny_load_in_a_large_clearance():
    zero = solve_load_distribution(0.0, 0.0, rollers_per_row=25, contact_angle=ALPHA, stiffness=K, clearance=1e-4)
    assert zero.Q_max == 0.0 and zero.iterations == 0
    tiny = solve_load_distribution(1.0, 0.0, rollers_per_row=25, contact_angle=ALPHA, stiffness=K, clearance=1e-3)
    assert tiny.loaded.sum() == 2  # one roller per row, at the load line
    assert tiny.Q_max == pytest.approx(0.5 / math.cos(ALPHA), rel=1e-6)


def test_palmgren_stiffness_of_a_roller():
    """Two line contacts in series, delta = 2 x 3.84e-5 Q^0.9 / l^0.8 [mm, N, mm] (Palmgren)."""
    Q = 10e3
    delta_mm = 2 * 3.84e-5 * Q**0.9 / 40.0**0.8
    assert K * (delta_mm * 1e-3) ** (10 / 9) == pytest.approx(Q, rel=1e-12)


@pytest.mark.parametrize("kwargs, match", [
    (dict(radial_load=-1.0), "radial_load = -1"),
    (dict(rollers_per_row=2), "rollers_per_row = 2"),
    (dict(contact_angle=0.0, axial_load=1e3), "cannot carry it"),
    (dict(contact_angle=math.pi / 2), "contact_angle"),
    (dict(stiffness=0.0), "stiffness = 0"),
    (dict(radial_load=float("nan")), "radial_load = nan"),
])
def test_bad_input_names_the_argument(kwargs, match):
    arguments = dict(radial_load=1e3, axial_load=0.0, rollers_per_row=25, contact_angle=ALPHA, stiffness=K)
    arguments.update(kwargs)
    radial, axial = arguments.pop("radial_load"), arguments.pop("axial_load")
    with pytest.raises(InputError, match=match):
        solve_load_distribution(radial, axial, **arguments)


def test_bearing_component_geometry_and_distribution():
    bearing = cc.SphericalRollerBearing(
        designation="test", bore="200 mm", outer_diameter="310 mm", width="109 mm", rollers_per_row=25,
        roller_diameter="27 mm", roller_length="41.35 mm", contact_angle="9 deg", C="1700 kN", C0="2120 kN",
        radial_clearance="0.1 mm")
    gamma = 0.027 * math.cos(math.radians(9)) / 0.255
    assert bearing.gamma == pytest.approx(gamma)
    assert bearing.contact_radii["inner"] == pytest.approx(0.0135 * (1 - gamma))
    assert bearing.contact_radii["outer"] == pytest.approx(0.0135 * (1 + gamma))
    frame = bearing.load_distribution("100 kN", "10 kN").to_frame()
    assert list(frame.columns) == ["row", "roller", "azimuth [deg]", "approach [um]", "Q [N]", "loaded"]
    assert len(frame) == 50 and frame["Q [N]"].max() > 0
    with pytest.raises(InputError, match="bare number"):
        bearing.load_distribution(1000)


@pytest.mark.parametrize("changes, match", [
    (dict(rollers_per_row=40), "do not fit"),
    (dict(bore="320 mm"), "smaller than outer_diameter"),
    (dict(roller_diameter="60 mm"), "section height"),
    (dict(contact_angle="50 deg"), "contact_angle"),
    (dict(rows=3), "rows = 3"),
    (dict(C0="-1 kN"), "C0"),
    (dict(roller_length="120 mm"), "exceeds the width"),
])
def test_bearing_component_rejects_inconsistent_geometry(changes, match):
    arguments = dict(designation="test", bore="200 mm", outer_diameter="310 mm", width="109 mm",
                     rollers_per_row=25, roller_diameter="27 mm", roller_length="41.35 mm", contact_angle="9 deg",
                     C="1700 kN", C0="2120 kN")
    arguments.update(changes)
    with pytest.raises(InputError, match=match):
        cc.SphericalRollerBearing(**arguments)


def test_contact_temperature_inputs_are_checked():
    from camcontact.contact.contact_temperature import couette_temperature_rise, flash_temperature

    assert flash_temperature(2.4e5, 2.2e11, 0.0124, 0.04, 3.0, 3.0, 1.2e4, 1.2e4) == 0.0  # no sliding, no heat
    assert couette_temperature_rise(0.03, 0.0, 600.0, 0.13) == 0.0
    with pytest.raises(InputError, match="u1 = -1"):
        flash_temperature(2.4e5, 2.2e11, 0.0124, 0.04, -1.0, 3.0, 1.2e4, 1.2e4)
    with pytest.raises(InputError, match="effusivity2 = 0"):
        flash_temperature(2.4e5, 2.2e11, 0.0124, 0.04, 1.0, 3.0, 1.2e4, 0.0)
    with pytest.raises(InputError, match="beta = 0"):
        couette_temperature_rise(0.0, 1.0, 600.0, 0.13)


def test_load_zone_is_harris_arccos_of_clearance_over_twice_the_displacement():
    """Harris & Kotzalas (ch. 7): the loaded arc of a radially loaded bearing with diametral clearance P_d
    ends at psi_l = arccos(P_d / (2 delta_r)). By hand from the solved delta_r for 100 um clearance; the
    contact angle cancels (ring displacement and clearance both project with cos alpha on the normal);
    the last loaded roller lies inside psi_l, the next one outside; zero clearance: exactly 90 deg."""
    for clearance in (50e-6, 100e-6, 300e-6):
        result = solve_load_distribution(100e3, 0.0, rollers_per_row=25, contact_angle=ALPHA, stiffness=K,
                                         clearance=clearance)
        by_hand = math.acos(clearance / (2.0 * result.delta_r))
        np.testing.assert_allclose(result.load_zone, [by_hand, by_hand], rtol=1e-12)
        pitch = 2 * math.pi / 25
        assert np.all(result.last_loaded_azimuth <= result.load_zone)
        assert np.all(result.load_zone < result.last_loaded_azimuth + pitch)
        # the roller count follows: per row 1 + 2 floor(psi_l / pitch) rollers inside the load zone
        assert result.loaded.sum() == 2 * (1 + 2 * math.floor(by_hand / pitch))
    zero = solve_load_distribution(100e3, 0.0, rollers_per_row=25, contact_angle=ALPHA, stiffness=K, clearance=0.0)
    np.testing.assert_allclose(np.degrees(zero.load_zone), [90.0, 90.0], rtol=1e-14)
    assert np.degrees(zero.last_loaded_azimuth) == pytest.approx([86.4, 86.4])


def test_load_zone_with_axial_load_and_edge_cases():
    """With an axial displacement each row's approach is cos(alpha)(delta_r cos psi + s delta_a tan alpha
    - c/2), so cos psi_l = (c/2 - s delta_a tan alpha)/delta_r per row: the row that carries the axial
    load has the wider zone. A preload that loads every roller gives pi; a pure axial load loads one row
    whole (pi) and leaves the other unloaded (0); no load: 0."""
    result = solve_load_distribution(100e3, 20e3, rollers_per_row=25, contact_angle=ALPHA, stiffness=K,
                                     clearance=50e-6)
    expected = [math.acos((25e-6 - s * result.delta_a * math.tan(ALPHA)) / result.delta_r) for s in (1.0, -1.0)]
    np.testing.assert_allclose(result.load_zone, expected, rtol=1e-12)
    assert result.load_zone[0] > result.load_zone[1]
    preload = solve_load_distribution(10e3, 0.0, rollers_per_row=25, contact_angle=ALPHA, stiffness=K,
                                      clearance=-50e-6)
    assert preload.loaded.all() and np.all(preload.load_zone == math.pi)
    axial = solve_load_distribution(0.0, 50e3, rollers_per_row=25, contact_angle=ALPHA, stiffness=K)
    np.testing.assert_array_equal(axial.load_zone, [math.pi, 0.0])
    none = solve_load_distribution(0.0, 0.0, rollers_per_row=25, contact_angle=ALPHA, stiffness=K, clearance=1e-4)
    np.testing.assert_array_equal(none.load_zone, [0.0, 0.0])


def test_tutorial_5_load_zone_40_6_deg_with_ten_loaded_rollers():
    """Tutorial 5 (24040 CC/W33 as assumed there: 2 x 25 rollers of 27 x 41.35 mm, alpha 10 deg, 0.1 mm
    clearance) under the radial load that puts 10 kN on the most loaded roller: ten loaded rollers
    (five per row, the last at +-28.8 deg, the old load_zone), Harris's load zone
    arccos(0.1 mm / (2 delta_r)) = 40.6 deg (issue 16, error 5)."""
    from scipy.optimize import brentq

    bearing = cc.SphericalRollerBearing(
        designation="24040 CC/W33", bore="200 mm", outer_diameter="310 mm", width="109 mm", rollers_per_row=25,
        roller_diameter="27 mm", roller_length="41.35 mm", contact_angle="10 deg", C="1700 kN", C0="2120 kN",
        radial_clearance="0.1 mm")
    radial = brentq(lambda F: bearing.load_distribution_si(F).Q_max - 10e3, 10e3, 500e3, xtol=1.0)
    result = bearing.load_distribution_si(radial)
    assert radial == pytest.approx(67.8e3, rel=2e-3)
    assert result.loaded.sum() == 10
    np.testing.assert_allclose(np.degrees(result.last_loaded_azimuth), [28.8, 28.8])
    np.testing.assert_allclose(result.load_zone, math.acos(0.1e-3 / (2 * result.delta_r)), rtol=1e-12)
    assert round(float(np.degrees(result.load_zone.max())), 1) == 40.6
