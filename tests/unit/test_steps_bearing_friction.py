"""Unit tests of the bearing friction steps (camcontact.steps.bearing_friction), each called alone with SI
floats against hand calculations in catalogue units, and of the SphericalRollerBearing.series field.

Hand calculations: the SKF model (SKF "Rolling bearings" 2012, "Friction") and Palmgren's M0 + M1
(Harris & Kotzalas 2007) evaluated term by term below with the formula of the source written out, in the
source's units (N mm, mm, r/min, mm^2/s); the numbers in the comments were worked out separately.
"""

import math

import numpy as np
import pytest

import camcontact as cc
from camcontact.errors import InputError
from camcontact.steps.bearing_friction import (
    palmgren_friction_moment,
    roller_rolling_resistance,
    skf_friction_moment,
)

# 24040-size bearing: d = 200 mm, D = 310 mm (d_m = 255 mm), outer ring at 300 r/min (5 rev/s),
# base-oil viscosity 62.5 mm^2/s at the operating temperature
SIZE = dict(bore=0.200, outer_diameter=0.310)
SPEEDS = dict(n_inner=0.0, n_outer=5.0)
NU = 62.5e-6
# SKF geometry constants of series 240 (R1, R2, R3, R4, S1, S2, S3, S4), as tabulated in the module
R240 = (2.9e-6, 4.87, 4.78e-6, 4.84, 6.95e-3, 240.0, 2.1e-2, 68.0)


def skf(**changes):
    arguments = dict(radial_load=68e3, axial_load=5e3, kinematic_viscosity=NU, bearing_series="240",
                     lubrication="grease", base_oil="mineral", **SIZE, **SPEEDS)
    arguments.update(changes)
    return skf_friction_moment(**arguments)


def test_skf_friction_moment_against_a_hand_calculation():
    R1, R2, R3, R4, S1, S2, S3, S4 = R240
    dm, Fr, Fa, n, nu = 255.0, 68e3, 5e3, 300.0, 62.5
    g_rr_e = R1 * dm**1.85 * (Fr + R2 * Fa) ** 0.54  # 39.43
    g_rr_l = R3 * dm**2.3 * (Fr + R4 * Fa) ** 0.31  # 56.69 > g_rr_e: the "e" pair applies
    assert g_rr_e == pytest.approx(39.4306, rel=1e-4) and g_rr_l == pytest.approx(56.694, rel=1e-4)
    g_sl = S1 * dm**0.25 * (Fr**4 + S2 * Fa**4) ** (1 / 3)  # 77 264 N mm
    phi_ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)  # 0.95578
    phi_rs = math.exp(-6e-8 * nu * n * (200 + 310) * math.sqrt(5.5 / (2 * (310 - 200))))  # grease K_rs, K_Z 5.5
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)  # 0.00172: nearly full film
    mu_sl = phi_bl * 0.15 + (1 - phi_bl) * 0.05  # mineral oil mu_EHL = 0.05
    m_rr = phi_ish * phi_rs * g_rr_e * (nu * n) ** 0.6  # 12 606 N mm
    m_sl = g_sl * mu_sl  # 3 877 N mm
    assert (phi_ish, phi_rs, mu_sl) == pytest.approx((0.955779, 0.913275, 0.0501723), rel=1e-5)
    assert (m_rr, m_sl) == pytest.approx((12606.5, 3876.5), rel=1e-4)
    out = skf()
    assert out["M_rr_skf"] == pytest.approx(m_rr * 1e-3, rel=1e-12)
    assert out["M_sl_skf"] == pytest.approx(m_sl * 1e-3, rel=1e-12)
    assert out["friction_moment_skf"] == pytest.approx(16.483, rel=1e-4)
    assert out["friction_power_skf"] == pytest.approx(out["friction_moment_skf"] * 2 * math.pi * 5.0, rel=1e-12)
    # the inner ring turning instead gives the same moment (relative speed)
    assert skf(n_inner=5.0, n_outer=0.0)["friction_moment_skf"] == pytest.approx(out["friction_moment_skf"])


def test_skf_heavy_load_uses_the_second_pair():
    R1, R2, R3, R4, S1, S2, S3, S4 = R240
    dm, Fr, n, nu = 255.0, 1e6, 300.0, 62.5
    assert R1 * dm**1.85 * Fr**0.54 > R3 * dm**2.3 * Fr**0.31  # 142.7 > 118.7: G_rr,l and G_sl,l
    m_rr = R3 * dm**2.3 * Fr**0.31 * (nu * n) ** 0.6
    phi_ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    phi_rs = math.exp(-6e-8 * nu * n * 510 * math.sqrt(5.5 / 220))
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    m_sl = S3 * dm**0.94 * Fr * (phi_bl * 0.15 + (1 - phi_bl) * 0.05)
    out = skf(radial_load=1e6, axial_load=0.0)
    assert out["M_rr_skf"] == pytest.approx(phi_ish * phi_rs * m_rr * 1e-3, rel=1e-12)
    assert out["M_sl_skf"] == pytest.approx(m_sl * 1e-3, rel=1e-12)


def test_skf_oil_and_synthetic_base_oil_change_the_constants():
    grease, oil = skf(), skf(lubrication="oil")
    assert oil["M_rr_skf"] > grease["M_rr_skf"]  # K_rs 3e-8 < 6e-8: less starvation
    assert skf(base_oil="ester")["M_sl_skf"] < grease["M_sl_skf"]  # mu_EHL 0.04 < 0.05
    at_rest = skf(n_outer=0.0)
    assert at_rest["M_rr_skf"] == 0.0 and at_rest["friction_power_skf"] == 0.0
    assert at_rest["M_sl_skf"] == pytest.approx(77263.99 * 0.15e-3, rel=1e-5)  # boundary mu_bl = 0.15


@pytest.mark.parametrize("change, field", [
    ({"bearing_series": None}, "SphericalRollerBearing.series"),
    ({"bearing_series": "2404"}, "series = '2404'"),
    ({"lubrication": "wax"}, "lubrication = 'wax'"),
    ({"base_oil": "castor"}, "base_oil = 'castor'"),
    ({"kinematic_viscosity": None}, "kinematic viscosity"),
    ({"radial_load": -1.0}, "radial_load"),
])
def test_skf_bad_input_names_the_field(change, field):
    with pytest.raises(InputError, match=field) as info:
        skf(**change)
    if "series" in field:
        assert "240" in str(info.value) and "222 E" in str(info.value)  # the allowed values are listed


def palmgren(**changes):
    arguments = dict(radial_load=68e3, axial_load=0.0, kinematic_viscosity=NU, pitch_diameter=0.255,
                     contact_angle=math.radians(10), lubrication="grease", **SPEEDS)
    arguments.update(changes)
    return palmgren_friction_moment(**arguments)


def test_palmgren_friction_moment_against_a_hand_calculation():
    # nu n = 62.5 x 300 = 18 750 >= 2000: M0 = 1e-7 f0 (nu n)^(2/3) d_m^3, f0 = 5.25 (grease, middle of 3.5-7)
    m0 = 1e-7 * 5.25 * 18750 ** (2 / 3) * 255.0**3  # 6 143.9 N mm
    m1 = 0.00045 * 68e3 * 255.0  # f1 P1 d_m = 7 803 N mm, P1 = F_r (no axial load)
    out = palmgren()
    assert (out["M0_palmgren"], out["M1_palmgren"]) == pytest.approx((m0 * 1e-3, m1 * 1e-3), rel=1e-12)
    assert out["friction_moment_palmgren"] == pytest.approx(13.947, rel=1e-4)
    assert out["friction_power_palmgren"] == pytest.approx(13.947 * 2 * math.pi * 5.0, rel=1e-4)
    # oil bath: same f0 range as grease; below nu n = 2000 the constant 160e-7 f0 d_m^3
    slow = palmgren(kinematic_viscosity=1e-6, n_outer=1.0)  # nu n = 1 x 60 = 60
    assert slow["M0_palmgren"] == pytest.approx(160e-7 * 5.25 * 255.0**3 * 1e-3, rel=1e-12)
    # an axial load above F_r / (2 Y): P1 = 2 Y F_a, Y = 0.67 cot(10 deg) = 3.80
    axial = palmgren(radial_load=10e3, axial_load=30e3)
    assert axial["M1_palmgren"] == pytest.approx(0.00045 * 227985.53 * 255.0 * 1e-3, rel=1e-6)


@pytest.mark.parametrize("change, field", [
    ({"lubrication": "wax"}, "lubrication = 'wax'"),
    ({"kinematic_viscosity": None}, "kinematic viscosity"),
    ({"pitch_diameter": 0.0}, "pitch_diameter"),
    ({"contact_angle": 0.0}, "contact_angle"),
])
def test_palmgren_bad_input_names_the_field(change, field):
    with pytest.raises(InputError, match=field):
        palmgren(**change)


def rolling(**changes):
    arguments = dict(Q=np.array([10e3, 4e3, 0.0]), u_m=2.0, eta0=0.06, alpha=1.8e-8, piezoviscosity=True,
                     E_reduced=2.2e11, contact_radii={"inner": 0.0115, "outer": 0.0155},
                     contact_length_inner=np.array([0.04135, 0.04135, np.nan]),
                     contact_length_outer=np.array([0.04135, 0.04135, np.nan]), pitch_diameter=0.255, gamma=0.104)
    arguments.update(changes)
    return roller_rolling_resistance(**arguments)


def test_roller_rolling_resistance_against_the_formula():
    out = rolling()
    l, E, eta0, alpha, u = 0.04135, 2.2e11, 0.06, 1.8e-8, 2.0
    total = 0.0
    for race, R in (("inner", 0.0115), ("outer", 0.0155)):
        for j, Q in enumerate((10e3, 4e3)):
            U, G, W = eta0 * u / (E * R), alpha * E, Q / l / (E * R)
            expected = 4.318 * (G * U) ** 0.658 * W**0.0126 * R * l / alpha  # Goksem & Hargreaves 1978
            assert out[f"rolling_resistance_{race}"][j] == pytest.approx(expected, rel=1e-12)
            total += expected
        assert math.isnan(out[f"rolling_resistance_{race}"][2])  # unloaded roller: no contact
    assert out["rolling_resistance_power"] == pytest.approx(total * u, rel=1e-12)
    assert out["rolling_resistance_moment"] == pytest.approx(total * 0.255 * (1 - 0.104**2) / 4, rel=1e-12)
    # a few newtons per contact: 1e-4..1e-3 of the roller load
    assert 1e-4 < out["rolling_resistance_inner"][0] / 10e3 < 1e-3
    # a shorter contact (a conformal roller's loaded length) carries the same load at a higher w over less length
    short = rolling(contact_length_inner=np.array([0.02, 0.04135, np.nan]))["rolling_resistance_inner"][0]
    U, G, W = eta0 * u / (E * 0.0115), alpha * E, 10e3 / 0.02 / (E * 0.0115)
    assert short == pytest.approx(4.318 * (G * U) ** 0.658 * W**0.0126 * 0.0115 * 0.02 / alpha, rel=1e-12)


@pytest.mark.parametrize("change, field", [({"piezoviscosity": False}, "piezoviscosity"),
                                           ({"alpha": 0.0}, "alpha")])
def test_roller_rolling_resistance_bad_input_names_the_field(change, field):
    with pytest.raises(InputError, match=field):
        rolling(**change)


def test_bearing_series_is_validated_at_the_door():
    geometry = dict(designation="24040 CC/W33", bore="200 mm", outer_diameter="310 mm", width="109 mm",
                    rollers_per_row=25, roller_diameter="27 mm", roller_length="41.35 mm", contact_angle="10 deg",
                    C="1700 kN", C0="2120 kN")
    assert cc.SphericalRollerBearing(**geometry).series is None
    assert cc.SphericalRollerBearing(**geometry, series="240").series == "240"
    with pytest.raises(InputError, match=r"SphericalRollerBearing.series = '24040'; allowed: .*240"):
        cc.SphericalRollerBearing(**geometry, series="24040")
