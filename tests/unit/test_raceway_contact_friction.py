"""The raceway-contact scene's friction effects (``non_newtonian``, ``mixed``, ``thermal``).

Delabenetta's pellet-mill contact (tutorial 5): in the thesis's convention the ring and roller speeds of its
Eq. 31 slide (4.68 against 2.69 m/s, slide/roll 54 %) and Benedict–Kelley gives mu 0.0375 (Table 8); in the
corrected one the contact rolls purely and Kelley has no value. Independent references here: the traction
model called directly with the scene's Hertz pressure, half-width, corrected film h_oc and the chain's oil;
Greenwood–Tripp/Johnson–Greenwood–Poon called directly on h_oc; Blok's flash temperature with the EHL
coefficient; at zero slip the fluid transmits no traction (Johnson & Tevaarwerk 1977: tau -> 0 with the
shear rate), so a purely rolling contact has mu = 0 where Kelley's correlation has none.
"""

import math

import attrs
import numpy as np
import pytest

import camcontact as cc
from camcontact import registry
from camcontact.contact.contact_temperature import flash_temperature
from camcontact.errors import InputError
from camcontact.models.film_line import Moes
from camcontact.models.mixed_lubrication import mixed_line_contact

STEEL = cc.Material(E="200 GPa", nu=0.3, density="7810 kg/m^3", specific_heat="464 J/(kg K)",
                    thermal_conductivity="42.4 W/(m K)", yield_strength="400 MPa")
GREASE = cc.Lubricant(name="NH1 11-572", nu40="575 cSt", nu100="50 cSt", density="0.92 g/cm^3", form="grease",
                      alpha_correlation="gold", upper_temperature="120 degC")
BOTH = {"convention": ["thesis", "corrected"]}
SHOWN = ["p_h", "b", "w", "u_m", "u_raceway", "u_roller", "E_reduced", "R", "eta0", "alpha", "temperature",
         "h_c_corrected", "friction_coefficient", "friction_valid", "friction_per_length", "friction_power_per_length",
         "fluid_traction_coefficient", "traction_regime", "flash_temperature"]


def contact(**changes):
    fields = dict(raceway_radius="149 mm", roller_radius="13.5 mm", length="41.35 mm", load="10 kN",
                  ring_speed="300 rpm", roller_speed="1900 rpm", raceway_material=STEEL, roller_material=STEEL,
                  raceway_roughness="0.23 um", roller_roughness="0.23 um", lubricant=GREASE, temperature="85 degC")
    return cc.RacewayContact(**(fields | changes))


def rows(result, single="thesis"):
    """Report rows by convention (``single``: the name of a one-variant run's row)."""
    frame = result.to_frame(units={})
    names = frame["variant"] if "variant" in frame else [single]
    return {variant: frame.iloc[i] for i, variant in enumerate(names)}


def si(row, name):
    """A row's value in SI (the report's columns carry display units)."""
    column = next(c for c in row.index if c == name or c.startswith(f"{name} ["))
    value = row[column]
    if " [" not in column:
        return value
    unit = column[column.index("[") + 1:-1]
    return cc.Q_(value, unit).to_base_units().magnitude if unit != "°C" else value + 273.15


def test_default_is_the_thesis_kelley_friction_and_effects_replace_it_by_the_films():
    """No effect: Kelley (Table 8 mu 0.0375, its validity text); with ``non_newtonian`` the friction is the
    Eyring traction of the chain's film at the contact's sliding speed, in both conventions."""
    kelley = rows(cc.Analysis(contact(), models=BOTH).run())
    assert kelley["thesis"]["friction_coefficient [-]"] == pytest.approx(0.0375, abs=5e-5)
    assert "friction_validity" in kelley["thesis"].index
    result = cc.Analysis(contact(slide_roll_ratio=0.05), models=BOTH, effects={"non_newtonian"}, outputs=SHOWN).run()
    model = registry.get("traction_models", "eyring")
    for variant, row in rows(result).items():
        state = GREASE.state(si(row, "temperature"))
        state = attrs.evolve(state, eta0=si(row, "eta0"), alpha=si(row, "alpha"))
        u_s = si(row, "u_raceway") - si(row, "u_roller")
        direct = model.contact(si(row, "p_h"), si(row, "b"), si(row, "h_c_corrected"), si(row, "u_m"),
                               state).coefficient(u_s)
        assert row["friction_coefficient [-]"] == pytest.approx(abs(direct), rel=1e-9), variant
        assert si(row, "friction_per_length") == pytest.approx(abs(direct) * si(row, "w"), rel=1e-9)
        assert si(row, "friction_power_per_length") == pytest.approx(abs(direct) * si(row, "w") * abs(u_s), rel=1e-9)
        assert row["friction_valid"] and row["traction_regime"] == "nonlinear"
        # the temperatures follow the EHL coefficient (Blok, Delabenetta Eq. 48)
        effusivity = STEEL.thermal_effusivity()
        flash = flash_temperature(si(row, "w"), si(row, "E_reduced"), si(row, "R"), abs(direct), si(row, "u_raceway"),
                                  si(row, "u_roller"), effusivity, effusivity)
        assert si(row, "flash_temperature") == pytest.approx(flash, rel=1e-9)
    thesis = rows(result)["thesis"]["friction_coefficient [-]"]
    assert 0.02 < thesis < 0.06  # 54 % slide/roll at 0.83 GPa: the Eyring plateau of a mineral oil


def test_pure_rolling_has_no_fluid_traction_where_kelley_has_no_value():
    kelley = rows(cc.Analysis(contact(), models={"convention": "corrected"}).run(), "corrected")["corrected"]
    assert math.isnan(kelley["friction_coefficient [-]"]) and not kelley["friction_valid"]
    ehl = rows(cc.Analysis(contact(), models={"convention": "corrected"}, effects={"non_newtonian"}).run(),
               "corrected")["corrected"]
    assert ehl["friction_coefficient [-]"] == 0.0 and ehl["friction_valid"] and ehl["flash_temperature [K]"] == 0.0
    assert ehl["traction_regime"] == "linear" and "friction_validity" not in ehl.index


def test_mixed_shares_the_load_on_the_corrected_film():
    """Corrected convention, Lambda_oc 1.98 (mixed): the asperities carry a share, computed on h_oc with the
    default asperity parameters (eta beta sigma = sigma/beta = 0.05); mu = mu_b share + mu_fluid (1 - share).
    The thesis's Lambda 5.18 is full film: a vanishing asperity share (< 1e-6)."""
    outputs = SHOWN + ["sigma", "asperity_load_fraction", "h_c_mixed", "Lambda_mixed", "lubrication_regime",
                       "mixed_valid"]
    result = cc.Analysis(contact(slide_roll_ratio=0.05), models=BOTH, effects={"mixed", "non_newtonian"},
                         outputs=outputs).run()
    thesis, corrected = rows(result)["thesis"], rows(result)["corrected"]
    assert thesis["asperity_load_fraction [-]"] < 1e-6 and thesis["lubrication_regime"] == "full_film"
    row = corrected
    w, R, E, u_m, eta0, alpha, h = (si(row, n) for n in ("w", "R", "E_reduced", "u_m", "eta0", "alpha",
                                                          "h_c_corrected"))
    sigma = math.hypot(0.23e-6, 0.23e-6)
    radius = sigma / 0.05
    moes = Moes().evaluate(R, w, E, u_m, eta0, alpha)["h_c"]
    direct = mixed_line_contact(w, R, E, u_m, eta0, alpha, sigma, 0.05 / (radius * sigma), radius,
                                film_scale=h / moes)
    share = row["asperity_load_fraction [-]"]
    assert share == pytest.approx(direct["asperity_load_fraction"], rel=1e-9) and 0.0 < share < 0.05
    assert si(row, "h_c_mixed") == pytest.approx(direct["h_c"], rel=1e-9)
    assert row["lubrication_regime"] == "mixed" and row["mixed_valid"]
    mu_b = GREASE.boundary_friction
    expected = mu_b * share + row["fluid_traction_coefficient [-]"] * (1.0 - share)
    assert row["friction_coefficient [-]"] == pytest.approx(expected, rel=1e-9)


def test_thermal_traction_falls_below_the_isothermal_and_needs_the_fluid_friction():
    """At the thesis's 54 % slide/roll the shear heats the film: the thermal Eyring coefficient is below the
    isothermal one, with a positive contact temperature rise; ``thermal`` alone is refused by name. The flash
    temperature follows the coefficient; the Couette film rise (Newtonian at the mean pressure) does not."""
    def friction(effects):
        return rows(cc.Analysis(contact(), effects=effects,
                                outputs=["friction_coefficient", "traction_temperature_rise"]).run())["thesis"]
    isothermal, thermal = friction({"non_newtonian"}), friction({"non_newtonian", "thermal"})
    temperatures = {name: rows(cc.Analysis(contact(), effects=effects,
                                           outputs=["flash_temperature", "film_temperature_rise"]).run())["thesis"]
                    for name, effects in (("isothermal", {"non_newtonian"}), ("thermal", {"non_newtonian", "thermal"}))}
    assert temperatures["thermal"]["flash_temperature [K]"] < temperatures["isothermal"]["flash_temperature [K]"]
    assert (temperatures["thermal"]["film_temperature_rise [K]"]
            == temperatures["isothermal"]["film_temperature_rise [K]"])
    assert thermal["friction_coefficient [-]"] < 0.9 * isothermal["friction_coefficient [-]"]
    assert isothermal["traction_temperature_rise [K]"] == 0.0 < thermal["traction_temperature_rise [K]"]
    with pytest.raises(InputError, match="'thermal' effect .* needs 'non_newtonian' or 'mixed'"):
        cc.Analysis(contact(), effects={"thermal"})


def test_friction_fields_and_model_slot_are_checked():
    with pytest.raises(InputError, match="RacewayContact.asperity_density"):
        contact(asperity_density="-1 1/mm^2")
    with pytest.raises(InputError, match="RacewayContact.asperity_radius"):
        contact(asperity_radius="0 um")
    smooth = contact(raceway_roughness="0 um", roller_roughness="0 um")
    with pytest.raises(InputError, match="'mixed' effect needs rough surfaces; RacewayContact.raceway_roughness"):
        cc.Analysis(smooth, effects={"mixed"}, outputs=["asperity_load_fraction"])
    with pytest.raises(InputError, match="model slot traction = 'eyring' .* switch it on with effects"):
        cc.Analysis(contact(), models={"traction": "eyring"})
    newtonian = cc.Analysis(contact(), effects={"non_newtonian"}, models={"traction": "newtonian"},
                            outputs=["friction_coefficient"]).run()
    eyring = cc.Analysis(contact(), effects={"non_newtonian"}, outputs=["friction_coefficient"]).run()
    assert newtonian["friction_coefficient"] != eyring["friction_coefficient"]
    assert np.isfinite(newtonian["friction_coefficient"])
