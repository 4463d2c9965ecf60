"""Inlet shear-heating film reduction factors against their printed formulas, and the cam scene's phi_T.

Sources (camcontact/models/film_thermal.py): Murch & Wilson (1975) as printed by Wilson & Sheu (1983)
Eq. 9, C = (1 + 0.254 L^0.62)^-1; Wilson & Sheu (1983) Eq. 7, C = (1 + 0.241 (1 + 14.8 Z^0.83) L^0.64)^-1
with Z = (U1 - U2)/(U1 + U2) (Eq. 5) and L = mu0 alpha_T U^2 / k on the mean speed U (Eq. 6); Zhou &
Hoeprich (1991) Eq. 21 (Zhu & Cheng). The values below are the printed formulas evaluated by hand at
round arguments (no table of phi_T(L) is printed in the sources available: Wilson & Sheu's Fig. 1 is a
plot).
"""

import attrs
import numpy as np
import pytest

import camcontact as cc
from camcontact.models.film_thermal import inlet_heating_factor, thermal_reduction
from camcontact.scene_file import load_scene


def _speeds(L, Z=0.0):
    """Surface speeds with beta eta0 / k = 1 giving the mean-speed loading L and Z."""
    u_m = np.sqrt(L)
    return u_m * (1 + Z), u_m * (1 - Z)


@pytest.mark.parametrize("L, expected", [(0.1, 0.9426), (1.0, 0.7974), (10.0, 0.4857), (100.0, 0.1847)])
def test_murch_wilson(L, expected):
    # 1/(1 + 0.254 L^0.62); also = 3.94/(3.94 + L^0.62) within 0.08 %
    L_m, phi = thermal_reduction("murch_wilson", 1.0, 1.0, *_speeds(L), 1.0)
    assert L_m == pytest.approx(L, rel=1e-12)
    assert phi == pytest.approx(expected, abs=6e-5)
    assert phi == pytest.approx(3.94 / (3.94 + L**0.62), rel=8e-4)


@pytest.mark.parametrize("L, Z, expected", [(1.0, 0.0, 1 / 1.241), (1.0, 1.0, 1 / (1 + 0.241 * 15.8)),
                                            (0.2, 0.5, 1 / (1 + 0.241 * (1 + 14.8 * 0.5**0.83) * 0.2**0.64))])
def test_wilson_sheu(L, Z, expected):
    assert thermal_reduction("wilson_sheu", 1.0, 1.0, *_speeds(L, Z), 1.0)[1] == pytest.approx(expected, rel=1e-12)


def test_zhu_cheng_with_its_pressure_term():
    L, S, p_over_E = 2.0, 0.5, 0.004
    expected = (1 - 13.2 * p_over_E * L**0.42) / (1 + 0.213 * (1 + 2.23 * S**0.83) * L**0.64)
    u1, u2 = _speeds(L, S / 2)
    assert thermal_reduction("zhu_cheng", 1.0, 1.0, u1, u2, 1.0, p_over_E, 1.0)[1] == pytest.approx(expected, 1e-12)
    with pytest.raises(cc.InputError, match="p_h"):
        thermal_reduction("zhu_cheng", 1.0, 1.0, u1, u2, 1.0)


def test_delabenetta_eq44_is_wilson_sheu_on_the_speed_sum():
    # 0.241 / 4^0.64 = 0.0992, printed 0.1 by Delabenetta: the two agree within 1 % of (1 - phi)
    assert 0.241 / 4**0.64 == pytest.approx(0.1, abs=8e-4)
    for L, Z in [(0.3, 0.0), (1.0, 0.2), (5.0, 0.05)]:
        ws = thermal_reduction("wilson_sheu", 1.0, 1.0, *_speeds(L, Z), 1.0)[1]
        de = thermal_reduction("delabenetta", 1.0, 1.0, *_speeds(L, Z), 1.0)[1]
        assert de == pytest.approx(inlet_heating_factor(4 * L, Z), rel=1e-12)
        assert 1 - de == pytest.approx(1 - ws, rel=0.01)


def test_no_entrainment_no_reduction_and_bad_names():
    assert thermal_reduction("wilson_sheu", 0.03, 0.04, 1.0, -1.0, 0.13)[1] == 1.0
    # approaching reversal the factor tends to 1 (L ~ u_m^2 falls faster than Z^0.83 grows)
    phis = [thermal_reduction("wilson_sheu", 0.03, 0.04, 1.0 + e, -1.0 + e, 0.13)[1] for e in (1e-1, 1e-3, 1e-5)]
    assert phis[0] < phis[1] < phis[2] < 1.0
    with pytest.raises(cc.InputError, match="allowed"):
        thermal_reduction("gupta", 0.03, 0.04, 1.0, 1.0, 0.13)


@pytest.fixture(scope="module")
def thermal_ls1():
    scene = load_scene().component
    oil = attrs.evolve(scene.lubricant, thermoviscous_coefficient="0.03 1/K", thermal_conductivity="0.13 W/m/K")
    return attrs.evolve(scene, lubricant=oil)


EFFECTS = {"elasticity", "piezoviscosity", "compressibility", "thermal"}


def test_cam_scene_reports_phi_t_over_the_cycle(thermal_ls1):
    """The issue's independent estimate (beta 0.03 1/K, k 0.13 W/(m K), the LS-1 oil at 1000 rpm): phi_T
    about 0.5-0.7 on the flat follower's flanks, about 0.9 for the roller."""
    out = ["cam_angle", "thermal_factor", "h_min", "h_min_isothermal", "u_m"]
    roller = cc.Analysis(thermal_ls1, effects=EFFECTS, outputs=out).run()
    assert np.all((np.asarray(roller["thermal_factor"]) > 0.88) & (np.asarray(roller["thermal_factor"]) < 0.95))
    np.testing.assert_allclose(roller["h_min"], np.asarray(roller["thermal_factor"]) * roller["h_min_isothermal"])
    flat = attrs.evolve(thermal_ls1, follower=cc.Follower.flat(material=thermal_ls1.follower.material))
    result = cc.Analysis(flat, effects=EFFECTS, outputs=out).run()
    theta = np.degrees(np.asarray(result["cam_angle"]))
    flanks = ((theta > 10) & (theta < 50)) | ((theta > 130) & (theta < 170))
    phi = np.asarray(result["thermal_factor"])
    assert np.all((phi[flanks] > 0.5) & (phi[flanks] < 0.7))


def test_thermal_needs_the_lubricants_thermal_data():
    scene = load_scene().component
    with pytest.raises(cc.InputError, match="thermal_conductivity"):
        cc.Analysis(scene, effects=EFFECTS, outputs=["h_min"]).run()
