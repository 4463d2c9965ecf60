"""The cylindrical-roller-bearing steps (steps.roller_bearing) on their own."""

import math

import numpy as np
import pytest

import camcontact as cc
from camcontact.contact.hertz_line import hertz_line
from camcontact.models.iso_ts16281_roller import roller_reference_rating_life
from camcontact.steps.roller_bearing import lamina_hertz, lamina_loads, lamina_reference_life, radial_equivalent_load

STEEL = cc.Material(E="207 GPa", nu=0.3)
E_REDUCED = 207e9 / (1 - 0.3**2)


def nu_206(**changes):
    fields = dict(designation="NU 206", bore="30 mm", outer_diameter="62 mm", width="16 mm", roller_count=13,
                  roller_diameter="9 mm", roller_length="10 mm", C="44 kN", C0="36.5 kN", material=STEEL)
    return cc.CylindricalRollerBearing(**(fields | changes))


def test_lamina_loads_balance_and_peak_position():
    out = lamina_loads(nu_206(), 8800.0, math.radians(2 / 60), 30)
    loaded = out["loaded"]
    assert loaded.dtype == bool and out["loaded_rollers"] == loaded.sum() == 7
    assert np.sum(out["Q"] * np.cos(out["azimuth"])) == pytest.approx(8800.0, rel=1e-10)
    assert np.all(np.isnan(out["x_q_max"][~loaded])) and np.all(out["x_q_max"][loaded] < 0.0)  # tilt: one end
    assert out["lamina_moment"] < 0.0 and out["lamina_loads"].q.shape == (13, 30)
    aligned = lamina_loads(nu_206(), 8800.0, 0.0, 30)
    assert abs(aligned["lamina_moment"]) < 1e-9 and np.nanmax(np.abs(aligned["x_q_max"])) < 0.2e-3


def test_lamina_hertz_is_the_most_loaded_lamina():
    """Each roller's pressure is the Hertz line pressure of its most loaded lamina (per length)."""
    bearing = nu_206()
    loads = lamina_loads(bearing, 8800.0, 0.0, 30)
    out = lamina_hertz(loads["lamina_loads"], E_REDUCED, bearing.contact_radii)
    result = loads["lamina_loads"]
    w = result.q[0].max() / (result.x[1] - result.x[0])
    expected = hertz_line(w, bearing.contact_radii["inner"], E_REDUCED)
    assert out["p_h_inner"][0] == pytest.approx(expected.p_h, rel=1e-12)
    assert out["b_inner"][0] == pytest.approx(expected.b, rel=1e-12)
    assert out["p_h_max"] == pytest.approx(np.nanmax(out["p_h_inner"])) and np.isnan(out["p_h_outer"][6])
    # the loaded length: where the compression crosses zero, between the lamina centres (by hand for the lightly loaded
    # roller whose crowned ends lift), not a count of whole laminae; NaN for an unloaded roller
    width = result.x[1] - result.x[0]
    j = int(np.argmin(np.where(result.loaded, result.Q, np.inf)))
    c = result.compression[j]
    k = int(np.flatnonzero(c > 0.0)[-1])
    right = result.x[k + 1] + (result.x[k] - result.x[k + 1]) * c[k + 1] / (c[k + 1] - c[k])
    k0 = int(np.flatnonzero(c > 0.0)[0])
    left = result.x[k0 - 1] + (result.x[k0] - result.x[k0 - 1]) * c[k0 - 1] / (c[k0 - 1] - c[k0])
    assert out["contact_length_inner"][j] == pytest.approx(right - left, rel=1e-12)
    counted = width * np.count_nonzero(c > 0.0)
    assert abs(out["contact_length_inner"][j] - counted) < width and out["contact_length_inner"][j] < 0.01
    assert np.isnan(out["contact_length_outer"][6])


def test_equivalent_load_and_reference_life():
    assert radial_equivalent_load(8800.0) == {"P": 8800.0}
    bearing = nu_206()
    loads = lamina_loads(bearing, 8800.0, 0.0, 30)["lamina_loads"]
    out = lamina_reference_life(loads, bearing, 50.0, 0.0)
    life = roller_reference_rating_life(loads.q, C=44e3, roller_diameter=9e-3, pitch_diameter=bearing.d_m)
    assert out["L10r"] == pytest.approx(life["L10r"] * 1e6) and out["L10rh"] == pytest.approx(out["L10r"] / 50.0)
    straight = nu_206(profile=cc.RollerProfile())
    no_edge = lamina_reference_life(lamina_loads(straight, 8800.0, 0.0, 30)["lamina_loads"], straight, 50.0, 0.0)
    assert no_edge["L10r"] > out["L10r"]  # the edge factor is for ISO's profile only
