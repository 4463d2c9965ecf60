"""Spherical roller bearing contacts as finite lines: the conformity's gap, the laminae against the elliptical Hertz
contact and the numerical half-space contact, and the bearing scene with the conformities."""

import math

import numpy as np
import pytest

import camcontact as cc
from camcontact.contact.hertz_elliptical import hertz_elliptical
from camcontact.contact.hertz_line import hertz_line
from camcontact.contact.roller_profile import roller_dry_contact
from camcontact.errors import InputError
from camcontact.steps.raceway_laminae import CONFORMAL_HERTZ, conformal_roller_hertz
from tests.unit.test_bearing_scene import bearing, scene

E = 210e9 / (1 - 0.3**2)  # E' of two steel bodies (E 210 GPa, nu 0.3)


def conformal(f_i=0.98, f_o=0.98, **changes):
    return bearing(conformity_inner=f_i, conformity_outer=f_o, **changes)


def test_conformity_geometry():
    """d_m 255 mm, alpha 9 deg, D_w 27 mm: r_o = d_m / (2 cos alpha) + D_w / 2, R_r = f_o r_o, R_y = R_r / (1 - f), and
    the crown of each contact drops l^2 / (8 R_y) at the roller's ends."""
    b = conformal(0.97, 0.98)
    r_o = 0.255 / (2 * math.cos(math.radians(9))) + 0.0135
    assert b.outer_raceway_radius == pytest.approx(r_o, rel=1e-12)
    assert b.roller_contour_radius == pytest.approx(0.98 * r_o, rel=1e-12)
    assert b.axial_radii["outer"] == pytest.approx(0.98 * r_o / 0.02, rel=1e-12)
    assert b.axial_radii["inner"] == pytest.approx(0.98 * r_o / 0.03, rel=1e-12)
    drops = {race: p.crown_drop for race, p in b.raceway_profiles().items()}
    assert drops["outer"] == pytest.approx(0.04135**2 / (8 * b.axial_radii["outer"]), rel=1e-12)
    assert drops["inner"] > drops["outer"]  # the less conformal raceway opens faster
    assert not bearing().conformal and bearing().raceway_profiles() is None and bearing().axial_radii is None


@pytest.mark.parametrize("changes, field", [
    ({"conformity_inner": 0.98}, "give both"),
    ({"conformity_inner": 1.0, "conformity_outer": 0.98}, "conformity_inner"),
    ({"conformity_inner": 0.98, "conformity_outer": 0.5}, "conformity_outer"),
    ({"conformity_inner": 0.98, "conformity_outer": float("nan")}, "conformity_outer"),
])
def test_bad_conformity_is_named(changes, field):
    with pytest.raises(InputError, match=field):
        bearing(**changes)


def one_roller(Q, b):
    return conformal_roller_hertz(np.array([Q, 0.0]), E, b.contact_radii, b.si.roller_length, b.raceway_profiles(), 60)


def test_a_lightly_loaded_roller_is_the_elliptical_hertz_contact():
    """5 kN on a roller of the 24040-like bearing (f 0.98, R_y 6.99 m, R_x 12.1 mm at the inner race): the Hertz
    ellipse (2a_y 21.5 mm) is shorter than the roller (41.35 mm), so the contact does not reach its ends. The numerical
    half-space contact equals the exact elliptical Hertz to 0.3 % in peak pressure; the laminae (no interaction
    between slices) lie 3.4 % below it over a 10 % longer contact (their 10/9 law spreads the load further), the same
    with 30 or 60 laminae; the ideal line of length l_we lies 41 % below: the conformity, not the roller length, sets
    the pressure of a lightly loaded roller."""
    b = conformal()
    out = one_roller(5e3, b)
    R_x, R_y = b.contact_radii["inner"], b.axial_radii["inner"]
    exact = hertz_elliptical(5e3, R_x, R_y, E, method="exact")
    numerical = roller_dry_contact(5e3, b.si.roller_length, R_x, E, b.raceway_profiles()["inner"], cells_along=160)
    assert numerical.p_max == pytest.approx(exact.p_max, rel=0.003)
    assert 0.94 < out["p_h_inner"][0] / exact.p_max < 0.97
    assert 2 * exact.a_y < b.si.roller_length and not out["edge_loaded_inner"][0]
    assert 1.05 < out["contact_length_inner"][0] / (2 * exact.a_y) < 1.15
    coarse = conformal_roller_hertz(np.array([5e3]), E, b.contact_radii, b.si.roller_length, b.raceway_profiles(), 30)
    assert coarse["contact_length_inner"][0] == pytest.approx(out["contact_length_inner"][0], rel=0.01)
    line = hertz_line(5e3 / b.si.roller_length, R_x, E).p_h
    assert line < 0.6 * exact.p_max
    assert math.isnan(out["p_h_inner"][1]) and math.isnan(out["contact_length_outer"][1])  # unloaded: no contact
    assert not out["edge_loaded_outer"][1] and out["raceway_laminae"]["inner"][1] is None
    assert set(out) == set(CONFORMAL_HERTZ) and out["p_h_max"] == max(out["p_h_inner"][0], out["p_h_outer"][0])


def test_a_heavily_loaded_roller_reaches_its_ends():
    """80 kN: the contact spans the roller and is edge loaded at both races; the laminae give the pressure in the
    middle (2.69 GPa, within 5 % of the half-space contact's 2.65 GPa there), not the rise at the roller's sharp ends
    (3.26 GPa) that the half-space contact shows - the reason for the flag: real rollers relieve their ends."""
    b = conformal()
    out = one_roller(80e3, b)
    assert out["edge_loaded_inner"][0] and out["edge_loaded_outer"][0]
    assert out["contact_length_inner"][0] == pytest.approx(b.si.roller_length, rel=1e-12)
    profile = b.raceway_profiles()["inner"]
    numerical = roller_dry_contact(80e3, b.si.roller_length, b.contact_radii["inner"], E, profile, cells_along=160)
    middle = numerical.pressure[numerical.y.size // 2].max()
    laminae = out["raceway_laminae"]["inner"][0]
    assert laminae.pressure[laminae.y.size // 2] == pytest.approx(middle, rel=0.05)
    assert numerical.p_max > 1.15 * out["p_h_inner"][0]


def test_full_conformity_is_the_ideal_line():
    """f -> 1 (R_y 1.4 km: a crown of 0.15 um) makes the contact the ideal line of length l_we at any load."""
    b = conformal(0.99999, 0.99999)
    out = one_roller(20e3, b)
    for race in ("inner", "outer"):
        expected = hertz_line(20e3 / b.si.roller_length, b.contact_radii[race], E).p_h
        assert out[f"p_h_{race}"][0] == pytest.approx(expected, rel=0.01)


def test_the_bearing_scene_with_conformities():
    """The scene slices the contacts when the conformities are given: the default report gains the contact lengths
    and the edge flags; the lightly loaded rollers press harder than the ideal lines and their films spread the load
    over the loaded length (thinner, as w = Q / l grows); without conformities the contacts are l_we long."""
    light = dict(radial_load="40 kN", axial_load="0 kN")
    plain = cc.Analysis(scene(**light), outputs=["loaded", "p_h_inner", "p_h_outer", "h_min_inner", "h_min_outer",
                                                 "contact_length_inner", "contact_length_outer", "tau_max"]).run()
    sliced = cc.Analysis(scene(bearing=conformal(), **light)).run()
    assert "hertz: laminae (conformity)" in [f"{r.step}: {r.model}" for r in sliced.records]
    loaded = np.asarray(sliced["loaded"])
    for race in ("inner", "outer"):
        length = np.asarray(sliced[f"contact_length_{race}"])
        assert np.all(length[loaded] < 0.04135) and np.all(np.isnan(length[~loaded]))
        assert np.all(np.asarray(sliced[f"p_h_{race}"])[loaded] > np.asarray(plain[f"p_h_{race}"])[loaded])
        assert np.all(np.asarray(sliced[f"h_min_{race}"])[loaded] < np.asarray(plain[f"h_min_{race}"])[loaded])
        assert not np.asarray(sliced[f"edge_loaded_{race}"]).any()
        assert np.all(np.asarray(plain[f"contact_length_{race}"])[loaded] == pytest.approx(0.04135))
    assert "contact_length_inner [mm]" in sliced.to_frame() and "edge_loaded_outer" in sliced.to_frame()
    assert "contact_length_inner [mm]" not in cc.Analysis(scene(**light)).run().to_frame()  # ideal lines: l_we
    assert sliced["tau_max"] > plain["tau_max"]  # the subsurface stress follows the higher pressure
    heavy = cc.Analysis(scene(bearing=conformal(), radial_load="400 kN"), outputs=["edge_loaded_inner"]).run()
    assert np.asarray(heavy["edge_loaded_inner"]).any()
