"""The ball-bearing steps (steps.ball_bearing), each on its own, against independent calculations."""

import math
import warnings

import numpy as np
import pytest

import camcontact as cc
from camcontact import registry
from camcontact.contact.ball_load_distribution import ball_race_radii
from camcontact.contact.geometry import reduced_modulus
from camcontact.contact.hertz_elliptical import hertz_elliptical
from camcontact.errors import InputError, ValidityWarning
from camcontact.models.iso281_ball import reference_rating_life
from camcontact.steps.ball_bearing import (ball_bearing_equivalent_load, ball_films, ball_hertz, ball_kinematics,
                                          ball_loads, ball_pair_equivalent_load, ball_pair_loads,
                                          ball_pair_reference_life, ball_pair_static_safety, ball_reference_life,
                                          ball_static_safety, ball_subsurface, ball_truncation)
from tests.unit.step_checks import assert_provides

STEEL = cc.Material(E="207 GPa", nu=0.3)
E_REDUCED = reduced_modulus(207e9, 0.3, 207e9, 0.3)
D, DM = 17.462e-3, 72.5e-3
OSCULATIONS = {"inner": 0.52, "outer": 0.53}


def bearing(**changes):
    fields = dict(designation="6309", bore="45 mm", outer_diameter="100 mm", width="25 mm", ball_count=8,
                  ball_diameter="17.462 mm", inner_osculation=0.52, outer_osculation=0.53, C="55.3 kN", C0="31.5 kN",
                  material=STEEL)
    return cc.BallBearing(**(fields | changes))


def test_ball_loads_balance_and_status():
    out = ball_loads(bearing(radial_clearance="15 um"), 10e3, 2e3, None)
    loaded = out["loaded"]
    assert loaded.dtype == bool and out["loaded_balls"] == loaded.sum() == 5
    assert np.all(np.isnan(out["contact_angle"][~loaded])) and np.all(out["Q"][~loaded] == 0.0)
    radial = np.sum(out["Q"][loaded] * np.cos(out["contact_angle"][loaded]) * np.cos(out["ball_azimuth"][loaded]))
    axial = np.sum(out["Q"][loaded] * np.sin(out["contact_angle"][loaded]))
    assert radial == pytest.approx(10e3, rel=1e-9) and axial == pytest.approx(2e3, rel=1e-9)
    assert out["contact_angle_min"] <= out["contact_angle_max"] and out["ring_tilt"] == 0.0
    assert out["load_zone"] == pytest.approx(math.pi / 2) and out["force_residual"] < 1e-9
    with pytest.raises(InputError, match="needs the material"):
        ball_loads(bearing(material=None), 10e3, 0.0, None)


def test_ball_hertz_at_each_contact_angle():
    Q = np.array([4000.0, 0.0])
    angle = np.array([math.radians(10.0), np.nan])
    out = ball_hertz(Q, angle, D, DM, OSCULATIONS, E_REDUCED, 4.2e9)
    direct = hertz_elliptical(4000.0, *ball_race_radii(D, DM, 0.52, math.radians(10.0), "inner"), E_REDUCED)
    assert out["p_h_inner"][0] == pytest.approx(direct.p_max, rel=1e-12)
    assert out["a_transverse_inner"][0] > 5 * out["a_rolling_inner"][0]  # the ellipse lies across the groove
    assert np.isnan(out["p_h_outer"][1]) and out["p_h_max"] == pytest.approx(direct.p_max)
    assert out["p_h_inner"][0] > out["p_h_outer"][0]  # the inner contact is the more curved one
    with pytest.warns(ValidityWarning, match="contact_stress_limit"):
        assert ball_hertz(Q, angle, D, DM, OSCULATIONS, E_REDUCED, 1e9)["stress_limit_exceeded"] is True


def test_ball_subsurface_below_the_most_loaded_contact():
    """An elongated contact (k ~ 10) is nearly a line contact: Tresca shear 0.30 p_h at 0.786 of the rolling
    semi-axis in the line limit (Johnson 1985 §4.2), a little more (0.31-0.32 p_h) at a/b ~ 0.1 (Johnson Fig. 3.9)."""
    Q = np.array([4000.0])
    hertz = ball_hertz(Q, np.array([0.0]), D, DM, OSCULATIONS, E_REDUCED, 4.2e9)
    keys = ("a_rolling_inner", "a_transverse_inner", "p_h_inner", "a_rolling_outer", "a_transverse_outer", "p_h_outer")
    out = ball_subsurface(Q, *(hertz[k] for k in keys), 0.3)
    assert out["most_loaded_race"] == "inner"
    assert out["tau_max"] / hertz["p_h_inner"][0] == pytest.approx(0.31, rel=0.035)
    assert out["z_tau_max"] / hertz["a_rolling_inner"][0] == pytest.approx(0.786, rel=0.05)
    none = ball_subsurface(np.zeros(1), *(np.full(1, np.nan) for _ in keys), 0.3)
    assert none["tau_max"] == 0.0 and none["most_loaded_race"] == "none"


def test_ball_kinematics_pure_rolling():
    """Inner ring at 50 rev/s: cage pi n_i (1 - gamma) [rad/s] and u_m = (pi d_m / 2)(1 - gamma^2) n_i."""
    Q = np.array([1.0, 0.0])
    out = ball_kinematics(50.0, 0.0, np.array([0.0, np.nan]), Q, 0.0, D, DM)
    gamma = D / DM
    assert out["cage_speed"] == pytest.approx(math.pi * 50.0 * (1 - gamma))
    assert out["u_m"] == pytest.approx(np.full(2, 0.5 * math.pi * DM * (1 - gamma**2) * 50.0))
    # the surface speed of the inner ring relative to the cage equals that of the ball's surface
    omega_ball = out["ball_speed"][0]
    assert omega_ball * D / 2 == pytest.approx((2 * math.pi * 50.0 - out["cage_speed"]) * DM / 2 * (1 - gamma))


def test_ball_films_per_contact_and_validity():
    model = registry.get("film_models", "hamrock_dowson")
    Q = np.array([4000.0, 0.0])
    out = ball_films(model, Q, np.array([0.0, np.nan]), np.array([5.0, 5.0]), D, DM, OSCULATIONS, E_REDUCED, 0.02,
                     2e-8, True, None, None)
    Rx, Ry = ball_race_radii(D, DM, 0.52, 0.0, "inner")
    direct = model({"Rx": Rx, "Ry": Ry, "F": 4000.0, "E_reduced": E_REDUCED, "u_m": 5.0, "eta0": 0.02, "alpha": 2e-8,
                    "lubricant_state": None, "density_law": None})
    assert out["h_min_inner"][0] == pytest.approx(direct["h_min"], rel=1e-12) and np.isnan(out["h_min_inner"][1])
    assert out["h_min_bearing"] == pytest.approx(min(out["h_min_inner"][0], out["h_min_outer"][0]))
    assert out["film_valid"] is False and "hamrock_dowson (inner raceway, 1 of 1 loaded balls" in out["film_validity"]
    with pytest.raises(InputError, match="no entrainment"):
        ball_films(model, Q, np.zeros(2), np.zeros(2), D, DM, OSCULATIONS, E_REDUCED, 0.02, 2e-8, True, None, None)


def test_equivalent_loads_and_static_safety():
    out = ball_bearing_equivalent_load(4000.0, 4000.0, "deep_groove", 0.0, 31.5e3, None, 8, D)
    assert out["X"] == 0.56 and 1.31 < out["Y"] < 1.45 and out["P"] > 4000.0
    static = ball_static_safety(4000.0, 4000.0, "deep_groove", 0.0, 31.5e3)
    assert static["P0"] == pytest.approx(0.6 * 4000 + 0.5 * 4000) and static["s0"] == pytest.approx(31.5e3 / 4400)
    assert ball_static_safety(0.0, 0.0, "deep_groove", 0.0, 31.5e3)["s0"] == math.inf


def test_no_warning_below_the_limit():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = ball_hertz(np.array([100.0]), np.array([0.0]), D, DM, OSCULATIONS, E_REDUCED, 4.2e9)
    assert out["stress_limit_exceeded"] is False


def test_reference_life_in_time_and_the_turning_ring():
    """L10r in revolutions and hours of the relative speed; the ring that turns against the load takes the cubic
    mean of the ball loads, so an outer ring turning instead gives another (here shorter: the inner contact, the
    more curved one, then sees the higher equivalent load of the stationary ring) life."""
    Q = np.array([5000.0, 3000.0, 100.0, 0.0, 0.0, 0.0, 100.0, 3000.0])
    out = ball_reference_life(Q, 55.3e3, D, DM, 0.0, OSCULATIONS, 50.0, 0.0)
    life = reference_rating_life(Q, C=55.3e3, ball_diameter=D, pitch_diameter=DM, contact_angle=0.0,
                                 inner_osculation=0.52, outer_osculation=0.53)
    assert out["L10r"] == pytest.approx(life["L10r"] * 1e6) and out["L10rh"] == pytest.approx(out["L10r"] / 50.0)
    assert life["Q_ei"] == pytest.approx(np.mean(Q**3) ** (1 / 3)) and life["Q_ee"] > life["Q_ei"]
    outer = ball_reference_life(Q, 55.3e3, D, DM, 0.0, OSCULATIONS, 0.0, 50.0)
    assert outer["L10r"] < out["L10r"]
    assert ball_reference_life(np.zeros(8), 55.3e3, D, DM, 0.0, OSCULATIONS, 50.0, 0.0)["L10r"] == math.inf


# ----------------------------------------------------------------------------- pairs of angular-contact bearings
def angular(**changes):
    """A 7208 BE-like 40 deg angular-contact bearing (Z 13, D_w 11.906 mm, C 36.4 kN, C0 26 kN, B 18 mm)."""
    fields = dict(designation="7208 BE", kind="angular_contact", bore="40 mm", outer_diameter="80 mm", width="18 mm",
                  ball_count=13, ball_diameter="11.906 mm", contact_angle="40 deg", inner_osculation=0.52,
                  outer_osculation=0.53, C="36.4 kN", C0="26 kN", material=STEEL)
    return cc.BallBearing(**(fields | changes))


def test_ball_pair_loads_per_bearing_and_the_relieved_preload():
    """The 2Z balls of both bearings (row 0 first) as the component's pair solver gives them; each bearing's axial load
    on its own flanks differs by the applied F_a (they balance it); the pair balances F_r; with 10 um of preload both
    rows stay loaded under 5 kN + 2 kN, while 5 um (F_0 about 0.18 kN) is relieved under 6 kN axial (row 1 unloaded)."""
    pair = angular()
    out = ball_pair_loads(pair, 5e3, 2e3, None, "back_to_back", 10e-6, 18e-3)
    direct = pair.pair_load_distribution("5 kN", "2 kN", arrangement="back_to_back", preload="10 um")
    np.testing.assert_array_equal(out["Q"], direct.Q)
    assert out["ball_row"].tolist() == [0.0] * 13 + [1.0] * 13 and out["Q"].size == 26
    assert out["axial_load_row0"] - out["axial_load_row1"] == pytest.approx(2e3, rel=1e-9)
    loaded = out["loaded"]
    radial = np.sum(out["Q"][loaded] * np.cos(out["contact_angle"][loaded]) * np.cos(out["ball_azimuth"][loaded]))
    assert radial == pytest.approx(5e3, rel=1e-9) and out["preload_relieved"] is False
    assert out["loaded_balls"] == loaded.sum() and np.all(np.isnan(out["contact_angle"][~loaded]))
    relieved = ball_pair_loads(pair, 0.0, 6e3, None, "back_to_back", 5e-6, 18e-3)
    assert relieved["preload_relieved"] is True and relieved["axial_load_row1"] == 0.0
    assert relieved["axial_load_row0"] == pytest.approx(6e3, rel=1e-9)
    with pytest.raises(InputError, match="pairs are of angular_contact"):
        ball_pair_loads(bearing(radial_clearance="10 um"), 5e3, 2e3, None, "back_to_back", 0.0, 18e-3)


def test_ball_pair_equivalent_load_with_the_double_row_factors():
    """Back to back (or face to face) at 40 deg: F_a/F_r <= e = 1.14 gives P = F_r + 0.55 F_a, above it
    P = 0.57 F_r + 0.93 F_a (ISO 281 Table 3, double row), an axial load of either sign; in tandem the single row's
    X = 0.35, Y = 0.57; at 27.5 deg halfway between the 25 and 30 deg rows; outside 25..40 deg refused."""
    forty = math.radians(40.0)
    low = ball_pair_equivalent_load(10e3, -2e3, "back_to_back", forty, 26e3, None, 13, 11.906e-3)
    assert (low["X"], low["Y"], low["e"]) == (1.0, 0.55, 1.14) and low["P"] == pytest.approx(10e3 + 0.55 * 2e3)
    high = ball_pair_equivalent_load(10e3, 20e3, "face_to_face", forty, 26e3, None, 13, 11.906e-3)
    assert high["P"] == pytest.approx(0.57 * 10e3 + 0.93 * 20e3)
    tandem = ball_pair_equivalent_load(10e3, 20e3, "tandem", forty, 26e3, None, 13, 11.906e-3)
    assert tandem["P"] == pytest.approx(0.35 * 10e3 + 0.57 * 20e3)
    mid = ball_pair_equivalent_load(10e3, 2e3, "back_to_back", math.radians(27.5), 26e3, None, 13, 11.906e-3)
    assert mid["Y"] == pytest.approx(0.5 * (0.92 + 0.78)) and mid["e"] == pytest.approx(0.74)
    with pytest.raises(InputError, match="contact angle 20 deg"):
        ball_pair_equivalent_load(10e3, 2e3, "back_to_back", math.radians(20.0), 26e3, None, 13, 11.906e-3)
    with pytest.raises(InputError, match="tandem pair points away"):
        ball_pair_equivalent_load(10e3, -2e3, "tandem", forty, 26e3, None, 13, 11.906e-3)


def test_ball_pair_static_safety():
    """ISO 76 for a pair at 40 deg: back to back P0 = F_r + 2 x 0.26 F_a against 2 C0; in tandem the single row's
    max(0.5 F_r + 0.26 F_a, F_r)."""
    forty = math.radians(40.0)
    out = ball_pair_static_safety(10e3, 5e3, "back_to_back", forty, 52e3)
    assert out["P0"] == pytest.approx(10e3 + 0.52 * 5e3) and out["s0"] == pytest.approx(52e3 / 12.6e3)
    assert ball_pair_static_safety(10e3, 5e3, "tandem", forty, 52e3)["P0"] == pytest.approx(10e3)
    assert ball_pair_static_safety(10e3, 40e3, "tandem", forty, 52e3)["P0"] == pytest.approx(5e3 + 0.26 * 40e3)
    assert ball_pair_static_safety(0.0, 0.0, "face_to_face", forty, 52e3)["s0"] == math.inf


def test_ball_pair_reference_life_is_the_components():
    """L_10r of the pair from the load step's ball loads and rows equals BallBearing.pair_reference_life's (the same
    combination of both bearings' lives), in hours at the relative speed; with the rows swapped the same."""
    bearing = angular()
    loads = ball_pair_loads(bearing, 5e3, 2e3, None, "back_to_back", 10e-6, 18e-3)
    osculations = {"inner": 0.52, "outer": 0.53}
    out = ball_pair_reference_life(loads["Q"], loads["ball_row"], 36.4e3, 11.906e-3, bearing.d_m, math.radians(40.0),
                                   osculations, 50.0, 0.0)
    expected = bearing.pair_reference_life("5 kN", "2 kN", preload="10 um")
    assert out["L10r"] == pytest.approx(expected["L10r"], rel=1e-12)
    assert out["L10rh"] == pytest.approx(out["L10r"] / 50.0)
    rows = expected["L10r_rows"]
    assert out["L10r"] == pytest.approx((rows[0] ** (-10 / 9) + rows[1] ** (-10 / 9)) ** -0.9, rel=1e-12)
    swapped = ball_pair_reference_life(loads["Q"], 1.0 - loads["ball_row"], 36.4e3, 11.906e-3, bearing.d_m,
                                       math.radians(40.0), osculations, 50.0, 0.0)
    assert swapped["L10r"] == pytest.approx(out["L10r"], rel=1e-12)


# ----------------------------------------------------------------------------- shoulder truncation
def test_ball_truncation_margin_and_flag():
    """theta_s - |alpha| - a_y / (f D) per loaded ball and race, by hand: a 40 deg contact with a 2 mm half-width in a
    groove of r = 0.52 x 12.7 mm against a 50 deg shoulder keeps 10 deg - 17.4 deg < 0 (truncated); the same ball at
    20 deg keeps 12.6 deg; an unloaded ball has no margin (NaN) and is not truncated."""
    Q = np.array([1000.0, 800.0, 0.0])
    alpha = np.radians([40.0, 20.0, np.nan])
    a_y = np.array([2e-3, 2e-3, np.nan])
    shoulders = {"inner": math.radians(50.0), "outer": math.radians(60.0)}
    osculations = {"inner": 0.52, "outer": 0.53}
    out = ball_truncation(Q, alpha, a_y, a_y, shoulders, osculations, 12.7e-3)
    assert_provides(ball_truncation, out)
    for race, f in osculations.items():
        expected = shoulders[race] - alpha[:2] - 2e-3 / (f * 12.7e-3)
        np.testing.assert_allclose(out[f"truncation_margin_{race}"][:2], expected, rtol=1e-12)
        assert math.isnan(out[f"truncation_margin_{race}"][2]) and not out[f"truncated_{race}"][2]
    assert out["truncated_inner"].tolist() == [True, False, False]
    assert out["truncated_outer"].tolist() == [bool(60.0 - 40.0 - math.degrees(2e-3 / (0.53 * 12.7e-3)) < 0), False,
                                               False]
    assert out["truncated_balls"] == 1.0
