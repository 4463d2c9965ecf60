"""Ball-bearing load distribution with the contact angle changing under load (contact.ball_load_distribution).

Checks that can fail: Stribeck's zero-clearance limit and the half-loaded combined load of NSK's technical
report, Harris's closed-form equation of a thrust-loaded angular-contact bearing solved independently here,
and reference displacements of a deep-groove bearing under radial, axial, combined and moment loads; pairs of
angular-contact bearings: the preload's lift-off at 2^(3/2) F_0, back-to-back against face-to-face tilt, tandem as
two single bearings, and the pair's L_10r beside ISO 281.
"""

import math

import attrs
import numpy as np
import pytest
from scipy.optimize import brentq

from camcontact.contact.ball_load_distribution import (ball_race_radii, ball_stiffness, solve_ball_load_distribution,
                                                       solve_ball_pair_load_distribution)
from camcontact.contact.geometry import reduced_modulus
from camcontact.contact.hertz_elliptical import hertz_elliptical
from camcontact.errors import InputError

STEEL = reduced_modulus(210e9, 0.3, 210e9, 0.3)
#: the deep-groove bearing of the reference cases: Z = 7, D_w = 11.5 mm, D_pw = 43.5 mm, f_i 0.52, f_o 0.53
REFERENCE = dict(ball_count=7, ball_diameter=11.5e-3, pitch_diameter=43.5e-3, inner_osculation=0.52,
                 outer_osculation=0.53, E_reduced=STEEL)


def test_stribeck_zero_clearance_limit():
    """NSK technical report E728 ch. 5 Eq. (4): with zero clearance (epsilon = 0.5) Q_max = 4.37 F_r/(Z cos alpha)
    for point contact: the continuous load integral 1/J_r(0.5) = 4.3706, which the discrete balls approach."""
    bearing = dict(ball_diameter=12.7e-3, pitch_diameter=65e-3, inner_osculation=0.52, outer_osculation=0.52,
                   E_reduced=STEEL)
    for Z, tolerance in ((16, 1e-3), (100, 2e-4), (1000, 2e-4)):
        result = solve_ball_load_distribution(1000.0, 0.0, ball_count=Z, **bearing)
        assert result.Q_max * Z / 1000.0 == pytest.approx(4.37, rel=tolerance + 0.0015)
        assert result.load_zone == pytest.approx(math.pi / 2, abs=2 * math.pi / Z)
        assert np.nanmax(np.abs(result.contact_angle)) == 0.0


def test_half_loaded_combined_load_of_angular_contact_bearing():
    """NSK E728 ch. 5: a bearing with the balls of one half loaded (epsilon = 0.5) carries F_a = 1.216 F_r tan(alpha)
    (point contact, the contact angle held). Under a light load the angle barely changes, so with that F_a the
    balls at +/-90 deg from the load line are just at the edge of contact (deformation ~0 against the largest)."""
    alpha = math.radians(40.0)
    Fr = 50.0
    result = solve_ball_load_distribution(Fr, 1.216 * Fr * math.tan(alpha), ball_count=400, ball_diameter=12.7e-3,
                                          pitch_diameter=65e-3, inner_osculation=0.52, outer_osculation=0.52,
                                          E_reduced=STEEL, free_contact_angle=alpha)
    quarter = result.approach[100]  # psi = 90 deg
    assert abs(quarter) < 0.01 * result.approach.max()
    assert np.nanmax(np.abs(result.contact_angle - alpha)) < math.radians(0.3)


def test_thrust_load_matches_harris_equation():
    """Pure thrust on an angular-contact bearing: every ball at the same angle alpha with
    F_a = Z K_n(alpha) A^1.5 sin(alpha) (cos(alpha_0)/cos(alpha) - 1)^1.5 (Harris & Kotzalas 2007, ch. 7, the
    thrust-loaded ball bearing; K_n here at the loaded angle), solved by brentq: the solver's angle and axial
    displacement delta_a = A sin(alpha)/cos(alpha) cos(alpha_0) - A sin(alpha_0) agree."""
    D, d_m, f, Z, alpha0 = 22.23e-3, 125.3e-3, 0.5232, 16, math.radians(40.0)
    A = (2 * f - 1) * D
    Fa = 22250.0

    def balance(alpha):
        K = ball_stiffness(D, d_m, f, f, alpha, STEEL)
        return Z * K * A**1.5 * math.sin(alpha) * (math.cos(alpha0) / math.cos(alpha) - 1.0) ** 1.5 - Fa

    alpha = brentq(balance, alpha0 + 1e-9, math.radians(60.0), xtol=1e-14)
    result = solve_ball_load_distribution(0.0, Fa, ball_count=Z, ball_diameter=D, pitch_diameter=d_m,
                                          inner_osculation=f, outer_osculation=f, E_reduced=STEEL,
                                          free_contact_angle=alpha0)
    assert result.contact_angle == pytest.approx(np.full(Z, alpha), abs=1e-10)
    assert result.delta_a == pytest.approx(A * math.cos(alpha0) * math.tan(alpha) - A * math.sin(alpha0), rel=1e-8)
    assert result.Q == pytest.approx(np.full(Z, Fa / (Z * math.sin(alpha))), rel=1e-9)
    assert 40.0 < math.degrees(alpha) < 42.0  # the angle rises from 40 deg under load


def test_stiffness_is_two_hertz_contacts_in_series():
    """K_n from the exact elliptical Hertz approaches: delta(Q) of both contacts adds up to (Q/K_n)^(2/3)."""
    D, d_m, alpha = 12.7e-3, 65e-3, math.radians(15.0)
    K = ball_stiffness(D, d_m, 0.52, 0.53, alpha, STEEL)
    Q = 2500.0
    total = sum(hertz_elliptical(Q, *ball_race_radii(D, d_m, f, alpha, race), STEEL).approach
                for race, f in (("inner", 0.52), ("outer", 0.53)))
    assert (Q / K) ** (2 / 3) == pytest.approx(total, rel=1e-12)
    Rx, Ry = ball_race_radii(D, d_m, 0.52, 0.0, "inner")
    assert Rx == pytest.approx(0.5 * D * (1 - D / d_m)) and Ry == pytest.approx(0.52 * D / 0.04)


@pytest.mark.parametrize("case, loads, clearance, expected", [
    ("radial, no clearance", (1000.0, 0.0, None), 0.0, {"delta_r": 15.1101e-6}),
    ("axial, no clearance", (0.0, 1000.0, None), 0.0, {"delta_a": 133.5381e-6}),
    ("radial, 10 um clearance", (1000.0, 0.0, None), 10e-6, {"delta_r": 21.223e-6}),
    ("axial, 10 um clearance", (0.0, 1000.0, None), 10e-6, {"delta_a": 149.1717e-6}),
    ("radial and axial, tilt free", (1000.0, 1000.0, 0.0), 10e-6,
     {"delta_r": 19.5923e-6, "delta_a": 146.4603e-6, "tilt": 2.6872e-3}),
    ("moment 1 N m", (0.0, 0.0, 1.0), 0.0, {"tilt": 3.6957e-3}),
])
def test_reference_displacements(case, loads, clearance, expected):
    """Reference displacements of a deep-groove ball bearing (Z 7, D_w 11.5 mm, D_pw 43.5 mm, f_i 0.52, f_o 0.53,
    E 210 GPa, nu 0.3), as the ISO/TS 16281 test file of the public repository minzhun/ISO16281
    (Test_BallBearing.py, examples 1-6; its variable names mark them as MASTA's), with their moment lever, the
    pitch radius: to 0.02 % (the axial ones differ by 5e-5 because K_n here follows each ball's contact angle;
    held at the nominal angle they agree to 1e-6), the pure moment's tilt to 0.05 %. These displacements check
    K_n too (delta_r ~ K_n^(-2/3)). With the default lever, the groove-centre radius R_i, the tilt is smaller by
    (D_pw/2)/R_i. Their example 7 puts the moment about the radial load's axis (out of its plane), which this
    planar model does not take."""
    result = solve_ball_load_distribution(*loads, clearance=clearance, moment_lever="pitch", **REFERENCE)
    got = {"delta_r": result.delta_r, "delta_a": result.delta_a, "tilt": abs(result.tilt)}
    for key, value in expected.items():
        assert got[key] == pytest.approx(value, rel=5e-4 if case.startswith("moment") else 2e-4), key
    radial, axial = (float(np.sum(result.Q * np.cos(result.contact_angle) * np.cos(result.azimuth),
                                  where=result.loaded)),
                     float(np.sum(result.Q * np.sin(result.contact_angle), where=result.loaded)))
    assert radial == pytest.approx(loads[0], abs=1e-7 * 1000) and axial == pytest.approx(loads[1], abs=1e-7 * 1000)
    if loads[2] == 0.0:  # no moment: the lever only rescales the tilt
        groove = solve_ball_load_distribution(*loads, clearance=clearance, **REFERENCE)
        locus = 0.5 * 43.5e-3 + 0.02 * 11.5e-3 * math.cos(groove.free_contact_angle)
        assert abs(groove.tilt) / abs(result.tilt) == pytest.approx(0.5 * 43.5e-3 / locus, rel=1e-9)
        assert groove.delta_r == pytest.approx(result.delta_r, rel=1e-9)


def test_tilt_held_reports_the_moment_and_free_tilt_carries_none():
    """Without a moment the shaft holds the ring square and the balls' moment is reported; with moment = 0 the tilt
    is solved so that the balls exert none."""
    held = solve_ball_load_distribution(1000.0, 1000.0, clearance=10e-6, **REFERENCE)
    free = solve_ball_load_distribution(1000.0, 1000.0, 0.0, clearance=10e-6, **REFERENCE)
    assert held.tilt == 0.0 and abs(held.moment) > 1.0
    assert free.tilt != 0.0 and abs(free.moment) < 1e-6
    assert held.residual < 1e-9 and free.residual < 1e-9


def test_clearance_raises_the_largest_ball_load():
    """A clearance narrows the load zone and raises Q_max above Stribeck's zero-clearance value (towards the
    ~5 F_r/Z of a normal clearance)."""
    tight = solve_ball_load_distribution(1000.0, 0.0, clearance=0.0, **REFERENCE)
    loose = solve_ball_load_distribution(1000.0, 0.0, clearance=20e-6, **REFERENCE)
    assert loose.Q_max > tight.Q_max and loose.load_zone <= tight.load_zone
    assert 4.2 < tight.Q_max * 7 / 1000 < 4.7


@pytest.mark.parametrize("kwargs, message", [
    (dict(inner_osculation=0.5), "inner_osculation = 0.5"),
    (dict(outer_osculation=0.49), "outer_osculation = 0.49"),
    (dict(clearance=1.2e-3), "balls would fall out"),
    (dict(free_contact_angle=math.radians(95.0)), "free_contact_angle = 95"),
    (dict(free_contact_angle=0.5, clearance=1e-5), "not a clearance"),
    (dict(ball_count=2), "ball_count = 2"),
    (dict(pitch_diameter=10e-3), "must exceed ball_diameter"),
    (dict(moment_lever="shaft"), "moment_lever = 'shaft'"),
])
def test_bad_input_is_named(kwargs, message):
    with pytest.raises(InputError, match=message):
        solve_ball_load_distribution(1000.0, 0.0, **(REFERENCE | kwargs))


def test_angular_contact_bearing_needs_axial_load():
    """Its balls touch one flank only: a radial load alone, a moment alone or an axial load the wrong way has no
    equilibrium, and the error says why."""
    angular = REFERENCE | {"free_contact_angle": math.radians(40.0)}
    with pytest.raises(InputError, match="a radial load needs an axial load"):
        solve_ball_load_distribution(1000.0, 0.0, **angular)
    with pytest.raises(InputError, match="a moment needs an axial load"):
        solve_ball_load_distribution(0.0, 0.0, 5.0, **angular)
    with pytest.raises(InputError, match="F_a < 0 pushes the balls off"):
        solve_ball_load_distribution(0.0, -1000.0, **angular)
    carried = solve_ball_load_distribution(1000.0, 1500.0, free_contact_angle=math.radians(40.0), **REFERENCE)
    assert carried.residual < 1e-9 and np.all(carried.contact_angle[carried.loaded] > 0.0)


def test_frame_and_zero_load():
    result = solve_ball_load_distribution(0.0, 0.0, **REFERENCE)
    assert result.Q_max == 0.0 and result.load_zone == 0.0 and not result.loaded.any()
    frame = solve_ball_load_distribution(1000.0, 0.0, **REFERENCE).to_frame()
    assert list(frame.columns) == ["ball", "azimuth [deg]", "contact angle [deg]", "approach [um]", "Q [N]", "loaded"]
    assert frame["loaded"].sum() == 3


# ----------------------------------------------------------------------------- pairs of angular-contact bearings
#: a 7208 B-like angular-contact bearing (Z 13, D_w 11.9 mm, d_m 60 mm, 40 deg), paired with 18 mm between the rows
PAIR = dict(ball_count=13, ball_diameter=11.9e-3, pitch_diameter=60e-3, inner_osculation=0.52, outer_osculation=0.53,
            E_reduced=STEEL, free_contact_angle=math.radians(40.0), row_spacing=18e-3)


def test_preloaded_pair_relieves_one_row_at_2_83_times_the_preload():
    """A back-to-back pair preloaded by delta_p: each row carries F_0 at no load; an axial load F_a adds to one row
    and relieves the other, which lifts off at F_a = 2^(3/2) F_0 = 2.83 F_0 for a constant contact angle (Harris &
    Kotzalas 2007, ch. 8: the loaded row's deflection doubles its preload deflection, F ~ delta^(3/2)). The contact
    angle grows under load, which raises the lift-off a little: 2.847 at 5 um (F_0 182 N), 2.97 at 40 um (4.3 kN)."""
    lifts = []
    for preload in (5e-6, 40e-6):
        F0 = solve_ball_pair_load_distribution(0.0, 0.0, arrangement="back_to_back", preload=preload,
                                               **PAIR).row_axial_loads
        assert F0[0] == pytest.approx(F0[1], rel=1e-12) and F0[0] > 0.0

        def second_row(Fa):
            return solve_ball_pair_load_distribution(0.0, Fa, arrangement="back_to_back", preload=preload,
                                                     **PAIR).row_axial_loads[1] - 1e-9 * F0[0]

        lifts.append(brentq(second_row, 2.0 * F0[0], 4.0 * F0[0], xtol=1e-7 * F0[0]) / F0[0])
        below = solve_ball_pair_load_distribution(0.0, 2.0 * F0[0], arrangement="back_to_back", preload=preload,
                                                  **PAIR)
        assert below.row_axial_loads[0] - below.row_axial_loads[1] == pytest.approx(2.0 * F0[0], rel=1e-9)
    assert lifts[0] == pytest.approx(2.0**1.5, rel=0.01)
    assert 2.0**1.5 < lifts[0] < lifts[1] < 3.0


def test_back_to_back_pair_is_stiffer_against_tilt_than_face_to_face():
    """50 N m on a pair preloaded by 10 um: the rows' contact lines meet outside a back-to-back pair and inside a
    face-to-face one, so the former tilts about a quarter as much (0.22 vs 0.84 mrad); both carry the applied
    moment exactly; under F_r + F_a with the tilt held row 0 carries F_a in both."""
    db = solve_ball_pair_load_distribution(0.0, 0.0, 50.0, arrangement="back_to_back", preload=10e-6, **PAIR)
    df = solve_ball_pair_load_distribution(0.0, 0.0, 50.0, arrangement="face_to_face", preload=10e-6, **PAIR)
    assert db.moment == pytest.approx(50.0, rel=1e-9) and df.moment == pytest.approx(50.0, rel=1e-9)
    assert 3.0 < df.tilt / db.tilt < 5.0 and db.tilt > 0.0
    assert db.residual < 1e-9 and db.row.tolist() == [0] * 13 + [1] * 13 and db.arrangement == "back_to_back"
    rows_db = solve_ball_pair_load_distribution(5000.0, 2000.0, arrangement="back_to_back", **PAIR).row_axial_loads
    rows_df = solve_ball_pair_load_distribution(5000.0, 2000.0, arrangement="face_to_face", **PAIR).row_axial_loads
    assert rows_db[0] - rows_db[1] == pytest.approx(2000.0, rel=1e-9)
    assert rows_db == pytest.approx(rows_df, rel=1e-9)  # row 0 takes the positive F_a either way


def test_tandem_pair_shares_the_load_as_two_single_bearings():
    """With the tilt held, a tandem pair under 2 F_r, 2 F_a is two single bearings each under F_r, F_a: the same ball
    loads, the same axial displacement and twice the moment."""
    geometry = {k: v for k, v in PAIR.items() if k != "row_spacing"}
    single = solve_ball_load_distribution(5000.0, 2000.0, **geometry)
    tandem = solve_ball_pair_load_distribution(10e3, 4000.0, arrangement="tandem", **PAIR)
    np.testing.assert_allclose(tandem.Q, np.tile(single.Q, 2), rtol=1e-9)
    assert tandem.delta_a == pytest.approx(single.delta_a, rel=1e-9)
    assert tandem.moment == pytest.approx(2.0 * single.moment, rel=1e-9)


@pytest.mark.parametrize("changes, message", [
    ({"arrangement": "DB"}, "arrangement = 'DB'"),
    ({"arrangement": "tandem", "preload": 1e-6}, "preload"),
    ({"row_spacing": 0.0}, "row_spacing"),
    ({"preload": -1e-6}, "preload"),
])
def test_pair_bad_input_is_named(changes, message):
    arguments = {**PAIR, "arrangement": "back_to_back", **changes}
    with pytest.raises(InputError, match=message):
        solve_ball_pair_load_distribution(1000.0, 500.0, **arguments)


def test_tandem_pair_without_axial_load_is_refused():
    with pytest.raises(InputError, match="cannot carry"):
        solve_ball_pair_load_distribution(1000.0, -500.0, arrangement="tandem", **PAIR)


def test_pair_without_preload_carries_a_pure_moment_and_refuses_balls_over_their_shoulders():
    """A pair without preload under a moment alone: the balls of one side of each row take it (either sign, either
    arrangement); a tandem pair under 1 kN axial and 50 N m would need contact angles beyond 90 deg, which no groove
    allows: refused with the reason, not returned as an equilibrium."""
    for arrangement in ("back_to_back", "face_to_face"):
        for M in (50.0, -50.0):
            result = solve_ball_pair_load_distribution(0.0, 0.0, M, arrangement=arrangement, **PAIR)
            assert result.moment == pytest.approx(M, rel=1e-8) and math.copysign(1.0, result.tilt) == math.copysign(1.0, M)
    with pytest.raises(InputError, match="90 deg"):
        solve_ball_pair_load_distribution(0.0, 1000.0, 50.0, arrangement="tandem", **PAIR)


def test_pair_of_catalogue_bearings_and_its_reference_life():
    """Two 7208 BE-like bearings (C 36.4 kN) back to back under pure radial load: L_10r of the pair (each bearing's
    from its ball loads, combined with the Weibull slope 10/9) lies 14-19 % below ISO 281's L10 of the pair,
    (2^0.7 C / F_r)^3 (ISO 281 §5.1.2 and Table 3: X = 1 for a pair of 40 deg bearings without axial load) - the
    same consistency as the single bearing's; both bearings share the load, and deep-groove bearings are refused."""
    import camcontact as cc

    bearing = cc.BallBearing(designation="7208 BE", kind="angular_contact", bore="40 mm", outer_diameter="80 mm",
                             width="18 mm", ball_count=13, ball_diameter="11.906 mm", contact_angle="40 deg",
                             inner_osculation=0.52, outer_osculation=0.53, C="36.4 kN", C0="26 kN",
                             material=cc.Material(E="207 GPa", nu=0.3))
    for Fr in (2e3, 5e3, 10e3):
        life = bearing.pair_reference_life(f"{Fr} N")
        assert 0.8 < life["L10r"] / ((2**0.7 * 36.4e3 / Fr) ** 3 * 1e6) < 0.87
        assert life["L10r_rows"][0] == pytest.approx(life["L10r_rows"][1], rel=1e-9)
        assert life["L10r"] == pytest.approx(life["L10r_rows"][0] * 2 ** -0.9, rel=1e-9)
    spread = bearing.pair_load_distribution("0 N", "0 N", "100 N*m", preload="5 um", row_spacing="36 mm")
    assert spread.tilt < bearing.pair_load_distribution("0 N", "0 N", "100 N*m", preload="5 um").tilt
    assert bearing.pair_reference_life("0 N")["L10r"] == math.inf  # no load, no fatigue
    deep = attrs.evolve(bearing, kind="deep_groove", contact_angle=None)
    with pytest.raises(InputError, match="pairs are of angular_contact"):
        deep.pair_load_distribution("1 kN")
