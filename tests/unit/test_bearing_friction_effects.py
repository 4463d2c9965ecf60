"""The bearing scene's ``thermal`` and ``mixed`` effects (issue 16: every line scene can switch them on).

Independent references: the inlet shear-heating factor phi_T (Delabenetta 2021 Eq. 44, the slide/roll form of
Wilson & Sheu) computed here from the lubricant's beta, eta0 and k at the pure-rolling speeds of the scene; the
Greenwood–Tripp/Johnson–Greenwood–Poon load sharing called directly on each roller contact (w = Q / l, the
race's rolling radius, the composite roughness sqrt 2 sigma, the default asperity parameters); the friction
mu_b f_a + mu_fluid(h at the fluid's share) (1 - f_a) with the traction model called directly.
"""

import math

import attrs
import numpy as np
import pytest

import camcontact as cc
from camcontact import registry
from camcontact.errors import InputError
from camcontact.models.film_line import Moes
from camcontact.models.film_thermal import inlet_heating_factor, thermal_loading
from camcontact.models.mixed_lubrication import mixed_line_contact
from camcontact.report import unexplained_values

STEEL = cc.Material(E="210 GPa", nu=0.3, density="7810 kg/m^3", specific_heat="464 J/(kg K)",
                    thermal_conductivity="42.4 W/(m K)")
OIL = cc.Lubricant(name="mineral base oil", nu40="575 mm^2/s", nu100="50 mm^2/s", density="920 kg/m^3",
                   alpha="2.0e-8 1/Pa", thermal_conductivity="0.13 W/(m K)")
BASE = {"elasticity", "piezoviscosity"}


def scene(lubricant=OIL, **changes):
    fields = dict(designation="test", bore="200 mm", outer_diameter="310 mm", width="109 mm", rollers_per_row=25,
                  roller_diameter="27 mm", roller_length="41.35 mm", contact_angle="9 deg", C="1700 kN", C0="2120 kN",
                  radial_clearance="0.1 mm", fatigue_load_limit="200 kN", material=STEEL, roughness="0.23 um")
    bearing = cc.SphericalRollerBearing(**(fields | changes))
    return cc.LoadedBearing(bearing=bearing, radial_load="150 kN", axial_load="10 kN", outer_speed="300 rpm",
                            lubricant=lubricant, temperature="85 degC", contamination=0.5, slide_roll_ratio=0.02)


def test_thermal_reduces_every_roller_film_by_the_inlet_heating_factor():
    films = ["h_c_inner", "h_min_outer", "h_min_bearing", "u_m", "eta0"]
    isothermal = cc.Analysis(scene(), effects=BASE, outputs=films).run()
    thermal = cc.Analysis(scene(), effects=BASE | {"thermal"}, outputs=films + ["thermal_factor",
                                                                                "thermal_loading"]).run()
    state = OIL.state(358.15)
    u_m = thermal["u_m"]
    u1, u2 = u_m * 1.01, u_m * 0.99  # slide/roll 0.02 about the entrainment speed
    L = thermal_loading(state.thermoviscous_coefficient, state.eta0, u1, u2, 0.13)
    phi = float(inlet_heating_factor(L, (u1 - u2) / (u1 + u2)))
    assert thermal["thermal_loading"] == pytest.approx(float(L), rel=1e-12)
    assert thermal["thermal_factor"] == pytest.approx(phi, rel=1e-12) and 0.8 < phi < 1.0
    for name in ("h_c_inner", "h_min_outer"):
        np.testing.assert_allclose(np.asarray(thermal[name]), phi * np.asarray(isothermal[name]), rtol=1e-12)
    assert thermal["h_min_bearing"] == pytest.approx(phi * isothermal["h_min_bearing"], rel=1e-12)


def test_thermal_needs_the_oils_conductivity_and_makes_the_traction_thermal():
    without = attrs.evolve(OIL, thermal_conductivity=None)
    with pytest.raises(InputError, match="'thermal' effect needs Lubricant 'mineral base oil' thermal_conductivity"):
        cc.Analysis(scene(lubricant=without), effects=BASE | {"thermal"}, outputs=["h_min_bearing"])
    names = ["Q", "u_m", "p_h_inner", "b_inner", "h_c_inner", "friction_coefficient_inner"]
    result = cc.Analysis(scene(), effects=BASE | {"thermal"}, outputs=names).run()
    loaded = np.asarray(result["Q"]) > 0.0
    model = registry.get("traction_models", "eyring", thermal=True)
    contact = model.contact(*(np.asarray(result[n])[loaded] for n in ("p_h_inner", "b_inner", "h_c_inner")),
                            result["u_m"], OIL.state(358.15), STEEL.thermal_effusivity())
    direct = contact.solve(np.full(loaded.sum(), 0.02 * result["u_m"]))
    np.testing.assert_allclose(np.asarray(result["friction_coefficient_inner"])[loaded], np.abs(direct.coefficient),
                               rtol=1e-9)
    assert np.all(np.asarray(direct.temperature_rise) > 0.0)


def test_mixed_shares_each_roller_contact_and_adds_boundary_friction():
    names = ["Q", "u_m", "E_reduced", "eta0", "alpha", "p_h_inner", "b_inner", "h_c_inner", "asperity_load_fraction_inner",
             "h_c_mixed_inner", "lubrication_regime_inner", "mixed_valid_inner", "friction_coefficient_inner",
             "friction_valid_inner"]
    case = scene()
    result = cc.Analysis(case, effects=BASE | {"mixed"}, outputs=names).run()
    Q = np.asarray(result["Q"])
    loaded = Q > 0.0
    sigma = math.hypot(0.23e-6, 0.23e-6)
    radius = sigma / 0.05
    R = case.bearing.contact_radii["inner"]
    w = Q[loaded] / 41.35e-3
    h_c = np.asarray(result["h_c_inner"])[loaded]
    moes = Moes().evaluate(np.full(w.size, R), w, result["E_reduced"], result["u_m"], result["eta0"],
                           result["alpha"])["h_c"]
    direct = mixed_line_contact(w, np.full(w.size, R), result["E_reduced"], np.full(w.size, result["u_m"]),
                                result["eta0"], result["alpha"], sigma, 0.05 / (radius * sigma), radius,
                                film_scale=h_c / moes)
    share = np.asarray(result["asperity_load_fraction_inner"])[loaded]
    np.testing.assert_allclose(share, direct["asperity_load_fraction"], rtol=1e-9)
    assert np.all((share > 0.0) & (share < 0.05))  # Lambda about 1.5: mixed, the fluid carries almost all
    h_mixed = np.asarray(result["h_c_mixed_inner"])[loaded]
    np.testing.assert_allclose(h_mixed, direct["h_c"], rtol=1e-9)
    regimes = np.asarray(result["lubrication_regime_inner"])
    assert set(regimes[loaded]) == {"mixed"} and set(regimes[~loaded]) == {"unloaded"}
    assert np.isnan(np.asarray(result["asperity_load_fraction_inner"])[~loaded]).all()
    fluid = registry.get("traction_models", "eyring").contact(
        np.asarray(result["p_h_inner"])[loaded], np.asarray(result["b_inner"])[loaded], h_mixed, result["u_m"],
        OIL.state(358.15)).coefficient(0.02 * result["u_m"])
    expected = OIL.boundary_friction * share + np.abs(fluid) * (1.0 - share)
    np.testing.assert_allclose(np.asarray(result["friction_coefficient_inner"])[loaded], expected, rtol=1e-9)
    plain = cc.Analysis(case, effects=BASE, outputs=["friction_coefficient_inner"]).run()
    assert np.all(expected > np.asarray(plain["friction_coefficient_inner"])[loaded])


def test_mixed_report_explains_every_nan_and_the_fields_are_checked():
    result = cc.Analysis(scene(), effects=BASE | {"mixed", "thermal"}).run()
    frame = result.to_frame()
    assert {"asperity_load_fraction_inner [-]", "lubrication_regime_outer"} <= set(frame.columns)
    assert unexplained_values(frame) == []
    with pytest.raises(InputError, match="SphericalRollerBearing.asperity_density"):
        scene(asperity_density="0 1/mm^2")
    with pytest.raises(InputError, match="SphericalRollerBearing.asperity_radius"):
        scene(asperity_radius="-2 um")
    with pytest.raises(InputError, match="'mixed' effect needs rough surfaces; SphericalRollerBearing 'test'.roughness"):
        cc.Analysis(scene(roughness="0 um"), effects=BASE | {"mixed"})
    no_slip = attrs.evolve(scene(), slide_roll_ratio=None)
    with pytest.raises(InputError, match="slide_roll_ratio: set LoadedBearing.slide_roll_ratio"):
        cc.Analysis(no_slip, effects=BASE | {"mixed"})  # the friction mixed promises needs the sliding
    kelley = cc.Analysis(scene(), effects=BASE | {"mixed"}, models={"friction": "kelley"},
                         outputs=["asperity_load_fraction_inner", "friction_coefficient_inner"]).run()
    alone = cc.Analysis(scene(), effects=BASE, models={"friction": "kelley"},
                        outputs=["friction_coefficient_inner"]).run()
    np.testing.assert_array_equal(np.asarray(kelley["friction_coefficient_inner"]),
                                  np.asarray(alone["friction_coefficient_inner"]))
