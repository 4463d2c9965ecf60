"""ISO 281:2007 rating life of radial roller bearings (camcontact.models.life_iso281).

Published numbers: the SKF Rolling bearings catalogue, example "Vibrating screen" (spherical roller
bearing 22328 CCJA/W33VA405, n = 756 r/min, C/P = 7.3, a_SKF = 1.3 read from SKF's diagram):
L10mh = 1.3 x (10^6 / (60 x 756)) x 7.3^(10/3) = 21 500 h as printed — the product of the printed
factors is 21 628 h, so the printed value is rounded (0.6 %). ISO 281:2007 Table 12 (a1). Where
no printed life exists, independent properties: the a1 table is the Weibull form
0.95 (ln(100/R)/ln(100/90))^(2/3) + 0.05 rounded; a_ISO is continuous across its kappa bands; the
two branches of P meet at F_a/F_r = e.
"""

import math

import pytest

import camcontact as cc
from camcontact.errors import InputError
from camcontact.models.life_iso281 import (A1_TABLE, a_iso_roller, equivalent_load, rated_viscosity,
                                           reliability_factor)


def skf_vibrating_screen():
    model = cc.registry.get("life_models", "iso281")
    P = 186e3
    return model({"C": 7.3 * P, "P": P, "speed": 756 / 60, "pitch_diameter": 0.220, "viscosity": 40e-6,
                  "fatigue_load_limit": 132e3})


def test_basic_rating_life_of_the_skf_vibrating_screen_example():
    life = skf_vibrating_screen()
    assert life["L10"] == pytest.approx(7.3 ** (10 / 3) * 1e6)
    hours = life["L10h"] / 3600.0  # held in seconds (SI)
    assert hours == pytest.approx(1e6 / (60 * 756) * 7.3 ** (10 / 3))
    # SKF multiplies by its a_SKF = 1.3 and prints 21 500 h (its factors give 21 628 h)
    assert 1.3 * hours == pytest.approx(21_500, rel=0.01)


def test_rated_viscosity_formula_versus_skfs_revised_diagram():
    """ISO 281 nu1 for n = 756 r/min, d_m = 220 mm is 12.4 mm^2/s; SKF's example reads 10 mm^2/s from
    its revised diagram (kappa = 4 there, 3.2 here with nu = 40 mm^2/s): both kept visible."""
    assert rated_viscosity(756, 220) == pytest.approx(12.38, abs=0.01)
    assert skf_vibrating_screen()["kappa"] == pytest.approx(40 / 12.383, rel=1e-3)
    assert 40 / 10 == 4.0  # SKF's kappa with its nu1 = 10


def test_reliability_factor_table_and_its_weibull_form():
    for reliability, a1 in A1_TABLE.items():
        weibull = 0.95 * (math.log(100 / reliability) / math.log(100 / 90)) ** (2 / 3) + 0.05
        digits = 3 if a1 < 0.1 else 2
        assert round(weibull, digits) == pytest.approx(a1)
        assert reliability_factor(reliability) == a1
    assert A1_TABLE[99.0] < reliability_factor(98.5) < A1_TABLE[98.0]
    with pytest.raises(InputError, match="reliability = 99.99"):
        reliability_factor(99.99)


@pytest.mark.parametrize("edge", [0.4, 1.0])
def test_a_iso_is_continuous_across_its_kappa_bands(edge):
    for ratio in (0.05, 0.2, 0.5, 1.0):
        below, above = a_iso_roller(edge * (1 - 1e-12), ratio), a_iso_roller(edge, ratio)
        assert below == pytest.approx(above, rel=1e-5)


def test_a_iso_limits_and_trends():
    assert a_iso_roller(8.0, 0.3) == a_iso_roller(4.0, 0.3)  # kappa > 4 counts as 4
    assert a_iso_roller(4.0, 5.0) == 50.0  # cap
    values = [a_iso_roller(k, 0.3) for k in (0.1, 0.2, 0.5, 1.0, 2.0, 4.0)]
    assert values == sorted(values)
    assert a_iso_roller(1.0, 0.0) == pytest.approx(0.1)  # no fatigue load limit margin: 0.1
    with pytest.raises(InputError, match="kappa = 0.05"):
        a_iso_roller(0.05, 0.3)


def test_equivalent_load_branches_meet_at_e():
    alpha = math.radians(10)
    e = 1.5 * math.tan(alpha)
    Fr = 100e3
    assert equivalent_load(Fr, e * Fr * (1 - 1e-12), alpha) == pytest.approx(equivalent_load(Fr, e * Fr * 1.000001, alpha),
                                                                              rel=1e-5)
    assert equivalent_load(Fr, 0.0, alpha) == Fr
    assert equivalent_load(0.0, 10e3, alpha) == pytest.approx(0.67 / math.tan(alpha) * 10e3)
    # catalogue factors replace the generic ones
    assert equivalent_load(Fr, 5e3, alpha, e=0.3, Y1=2.2, Y2=3.3) == pytest.approx(Fr + 2.2 * 5e3)


def test_missing_inputs_are_named():
    model = cc.registry.get("life_models", "iso281", reliability=99.0, contamination=0.5)
    state = {"C": 1e6, "P": 1e5, "speed": 5.0, "pitch_diameter": 0.25, "viscosity": 80e-6, "fatigue_load_limit": None}
    with pytest.raises(InputError, match="fatigue_load_limit = None"):
        model(state)
    state.update(fatigue_load_limit=2e5, viscosity=1e-7)  # a very thin oil: kappa below 0.1
    with pytest.raises(InputError, match="kappa"):
        model(state)
    state.update(viscosity=80e-6)
    life = model(state)
    assert life["a1"] == 0.25 and life["L_nm"] == pytest.approx(0.25 * life["a_ISO"] * life["L10"])
    with pytest.raises(InputError, match="reliability"):
        cc.registry.get("life_models", "iso281", reliability=80.0)
