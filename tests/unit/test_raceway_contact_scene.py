"""RacewayContact scene: steps on demand, the thesis's temperature loop, bad input named, plots."""

import math

import attrs
import pytest

import camcontact as cc
from camcontact.errors import InputError
from camcontact.models.oil_thermal_properties import oil_specific_heat, oil_thermal_conductivity
from camcontact.scenes.raceway_contact import thesis_temperature_loop
from camcontact.scenes.raceway_conventions import THESIS, RacewayConvention

STEEL = cc.Material(E="200 GPa", nu=0.3, density="7810 kg/m^3", specific_heat="464 J/(kg K)",
                    thermal_conductivity="42.4 W/(m K)", yield_strength="400 MPa")
OIL = cc.Lubricant(name="ISO VG 460-like", nu40="575 cSt", nu100="50 cSt", density="0.92 g/cm^3",
                   alpha_correlation="gold")


def contact(**changes):
    fields = dict(raceway_radius="149 mm", roller_radius="13.5 mm", length="41.35 mm", load="10 kN",
                  ring_speed="300 rpm", roller_speed="1900 rpm", raceway_material=STEEL, roller_material=STEEL,
                  raceway_roughness="0.23 um", roller_roughness="0.23 um", lubricant=OIL, temperature="85 degC")
    fields.update(changes)
    return cc.RacewayContact(**fields)


def test_only_the_needed_steps_run():
    analysis = cc.Analysis(contact(), outputs=["p_h"])
    assert analysis.steps() == ["geometry", "hertz"]
    analysis = cc.Analysis(contact(), outputs=["Lambda_oc"], models={"convention": "corrected"})
    assert sorted(analysis.steps()) == ["film", "geometry", "hertz", "kinematics", "roughness"]
    assert analysis.steps()[-1] == "film"


def test_default_report_leaves_out_what_the_inputs_cannot_give():
    """No roughness wavelength: no roughness stress; the rest of the chain is there."""
    result = cc.Analysis(contact()).run()
    assert "tau_roughness" not in result.outputs and "Lambda_oc" in result.outputs
    frame = result.to_frame()
    assert frame.shape[0] == 1 and "lubricant_temperature_max [°C]" in frame.columns


def test_oil_form_gets_no_starvation_factor_and_grease_gets_0_7():
    corrected = {"convention": "corrected"}
    oil = cc.Analysis(contact(), outputs=["starvation_factor"], models=corrected).run()
    grease = cc.Analysis(contact(lubricant=attrs.evolve(OIL, form="grease")), outputs=["starvation_factor"],
                         models=corrected).run()
    assert oil["starvation_factor"] == 1.0 and grease["starvation_factor"] == 0.7


def test_temperature_loop_steps_down_until_lambda_exceeds_lambda_min():
    """lambda_min = 5.3 > Lambda(84.9 °C) = 5.181: the loop goes on down in 0.1 K steps and stops at
    the first temperature where Lambda > 5.3 (the one above it still gives Lambda <= 5.3)."""
    result = cc.Analysis(contact(lambda_min=5.3), outputs=["temperature", "Lambda_oc"]).run()
    theta = result["temperature"] - 273.15
    assert result["Lambda_oc"] > 5.3 and theta < 84.9
    assert round((85.0 - theta) / 0.1, 6) == round((85.0 - theta) / 0.1)  # on the 0.1 K grid
    previous = cc.Analysis(contact(lambda_min=0.0, temperature=f"{theta + 0.1 + 0.1} degC"),
                           outputs=["Lambda_oc"]).run()
    assert previous["Lambda_oc"] <= 5.3


def test_temperature_loop_that_cannot_end_names_lambda_min():
    with pytest.raises(InputError, match="lambda_min = 1e\\+06: the thesis's temperature loop reached .* °C"):
        cc.Analysis(contact(lambda_min=1e6), outputs=["Lambda_oc"], strict=True).run()
    calls = []

    def never(theta):
        calls.append(theta)
        return 1.0, None

    with pytest.raises(InputError, match="3000 steps of 0.1 K"):
        thesis_temperature_loop(85.0, 1.5, never)
    assert len(calls) == 3000

    def lambda_at(theta):
        calls.append(theta)
        return (1.0 if len(calls) < 3 else 2.0), theta

    calls.clear()
    theta, payload = thesis_temperature_loop(85.0, 1.5, lambda_at)
    assert len(calls) == 3 and theta == pytest.approx(84.7) and payload == theta


@pytest.mark.parametrize("changes, match", [
    (dict(raceway_radius="10 mm"), "raceway_radius .* must exceed roller_radius"),
    (dict(load="-1 kN"), "RacewayContact.load"),
    (dict(ring_speed="-3 rpm"), "RacewayContact.ring_speed"),
    (dict(raceway="middle"), "RacewayContact.raceway = 'middle'; allowed: 'outer', 'inner'"),
    (dict(slide_roll_ratio=2.5), "RacewayContact.slide_roll_ratio"),
    (dict(length=3.0), "RacewayContact.length"),
])
def test_bad_fields_are_named(changes, match):
    with pytest.raises(InputError, match=match):
        contact(**changes)


def test_missing_inputs_are_named_before_running():
    with pytest.raises(InputError, match="roller_speed: give RacewayContact.roller_speed"):
        cc.Analysis(contact(roller_speed=None), outputs=["h_c"])
    with pytest.raises(InputError, match="roughness_wavelength"):
        cc.Analysis(contact(), outputs=["tau_roughness"])
    bare = cc.Material(E="200 GPa", nu=0.3)
    with pytest.raises(InputError, match="effusivity: give density, specific_heat and thermal_conductivity"):
        cc.Analysis(contact(roller_material=bare), outputs=["flash_temperature"])
    with pytest.raises(InputError, match="yield_strength"):
        cc.Analysis(contact(raceway_material=bare), outputs=["yield_check"])
    with pytest.raises(InputError, match="unknown model slots \\['film'\\]"):
        cc.Analysis(contact(), models={"film": "grubin"})
    with pytest.raises(InputError, match="convention 'book'"):
        cc.Analysis(contact(), models={"convention": "book"})
    with pytest.raises(InputError, match="do not apply to a raceway_contact scene"):
        cc.Analysis(contact(), effects=["elasticity"])


def test_lubricant_without_the_data_a_convention_needs():
    eta_only = cc.Lubricant(name="eta only", eta0="0.07 Pa*s", alpha="2e-8 1/Pa")
    with pytest.raises(InputError, match="'eta only': the thesis convention needs nu40, nu100, density"):
        cc.Analysis(contact(lubricant=eta_only), outputs=["h_c"], strict=True).run()
    no_alpha = cc.Lubricant(name="no alpha", nu40="575 cSt", nu100="50 cSt", density="0.92 g/cm^3")
    with pytest.raises(InputError, match="'no alpha' has no pressure-viscosity data"):
        cc.Analysis(contact(lubricant=no_alpha), outputs=["h_c"], models={"convention": "corrected"}, strict=True).run()


def test_ring_at_rest_fails_loudly():
    with pytest.raises(InputError, match="ring_speed = 0"):
        cc.Analysis(contact(ring_speed="0 rpm"), outputs=["h_c"], models={"convention": "corrected"}, strict=True).run()


def test_inner_raceway_is_convex_and_derives_its_pitch_diameter():
    """On an inner raceway the radii add (d_m = 2(R1 + R2)); both conventions then agree on R_x."""
    inner = contact(raceway="inner", raceway_radius="120 mm")
    assert inner.pitch_diameter == pytest.approx(0.267)
    result = cc.Analysis(inner, outputs=["R_x"], models={"convention": ["thesis", "corrected"]}).run()
    assert result["R_x"][0] == pytest.approx(result["R_x"][1]) == pytest.approx(2 / (1 / 0.120 + 1 / 0.0135))


def test_convention_validation():
    with pytest.raises(InputError, match="RacewayConvention.roughness_factor = 0.0"):
        attrs.evolve(THESIS, roughness_factor=0.0)
    with pytest.raises(InputError, match="RacewayConvention.stress = 'exact'"):
        RacewayConvention(**{**attrs.asdict(THESIS), "stress": "exact"})
    with pytest.raises(InputError, match="RacewayConvention.roughness_amplitude = 'rms'"):
        attrs.evolve(THESIS, roughness_amplitude="rms")


def test_oil_thermal_property_correlations():
    """Delabenetta Eqs. 38-39 as coded: k = 0.12(1 - 0.0005 theta/3)/SG, c = 1000(1.63 + 0.0034 theta)/sqrt(SG);
    at 0 °C they reduce to 0.12/SG and 1630/sqrt(SG)."""
    assert oil_thermal_conductivity(0.0, 0.8) == pytest.approx(0.15)
    assert oil_specific_heat(0.0, 0.64) == pytest.approx(1630 / 0.8)
    assert oil_thermal_conductivity(84.9, 0.92) == pytest.approx(0.12 * (1 - 0.0005 * 84.9 / 3) / 0.92)
    with pytest.raises(InputError, match="specific gravity"):
        oil_specific_heat(20.0, 0.0)
    with pytest.raises(InputError, match="temperature"):
        oil_thermal_conductivity(math.nan, 0.9)


def test_lubricant_form_and_upper_temperature_are_validated():
    with pytest.raises(InputError, match="Lubricant.form = 'paste'; allowed: 'oil', 'grease'"):
        cc.Lubricant(eta0="0.1 Pa*s", form="paste")
    with pytest.raises(InputError, match="Lubricant.upper_temperature"):
        cc.Lubricant(eta0="0.1 Pa*s", upper_temperature=120)


def test_plot(tmp_path):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    lubricant = attrs.evolve(OIL, upper_temperature="120 degC")
    result = cc.Analysis(contact(lubricant=lubricant), models={"convention": ["thesis", "corrected"]}).run()
    figure = result.plot()
    assert len(figure.axes) == 4  # three panels and the colour bar
    figure.savefig(tmp_path / "raceway.png")
    with pytest.raises(InputError, match="nothing to plot"):
        cc.Analysis(contact(), outputs=["R_x"]).run().plot()
