"""Component construction and validation: Material, Lubricant, Body, LineContact."""

import math

import pytest

import camcontact as cc
from camcontact.errors import InputError, UnknownModelError


def test_lubricant_needs_a_viscosity():
    with pytest.raises(InputError, match="no viscosity given"):
        cc.Lubricant(alpha="2e-8 1/Pa")


def test_lubricant_rejects_two_viscosity_sources():
    with pytest.raises(InputError, match="several ways"):
        cc.Lubricant(eta0="0.04 Pa*s", nu40="100 cSt", nu100="10 cSt", density="900 kg/m^3")


def test_lubricant_kinematic_data_need_density():
    with pytest.raises(InputError, match="density"):
        cc.Lubricant(nu40="100 cSt", nu100="10 cSt")


def test_lubricant_needs_both_nu40_and_nu100():
    with pytest.raises(InputError, match="both nu40 and nu100"):
        cc.Lubricant(nu40="100 cSt", density="900 kg/m^3")


def test_lubricant_law_kind_is_checked():
    with pytest.raises(InputError, match="is a temperature law; pressure laws: barus, roelands"):
        cc.Lubricant(eta0="0.04 Pa*s", viscosity_pressure_law="walther")
    with pytest.raises(UnknownModelError, match="available: astm_d341, barus, roelands, vogel, walther"):
        cc.Lubricant(eta0="0.04 Pa*s", viscosity_temperature_law="arrhenius")


def test_vogel_needs_three_points():
    with pytest.raises(InputError, match="needs 3 viscosity points, the data give 2"):
        cc.Lubricant(nu40="100 cSt", nu100="10 cSt", density="900 kg/m^3", viscosity_temperature_law="vogel")


def test_alpha_and_z_are_not_both_given_with_a_viscosity():
    with pytest.raises(InputError, match="not both"):
        cc.Lubricant(eta0="0.04 Pa*s", alpha="2.2e-8 1/Pa", roelands_z=0.68)


def test_roelands_z_only_with_roelands():
    with pytest.raises(InputError, match="applies only to viscosity_pressure_law='roelands'"):
        cc.Lubricant(eta0="0.04 Pa*s", roelands_z=0.6, viscosity_pressure_law="barus")


def test_viscosity_known_at_one_temperature_only():
    oil = cc.Lubricant(eta0="0.04 Pa*s", reference_temperature="40 degC", alpha="2e-8 1/Pa")
    assert oil.at("40 degC").eta0 == pytest.approx(0.04)
    with pytest.raises(InputError, match="known only at 40"):
        oil.at("80 degC")


def test_temperature_dependent_lubricant_needs_temperature():
    oil = cc.Lubricant(nu40="100 cSt", nu100="10 cSt", density="900 kg/m^3", alpha="2e-8 1/Pa")
    with pytest.raises(InputError, match="give the temperature"):
        oil.at(None)


def test_lubricant_state_dynamic_viscosity_is_nu_times_rho():
    oil = cc.Lubricant(nu40="100 cSt", nu100="10 cSt", density="900 kg/m^3", alpha="2e-8 1/Pa")
    state = oil.at("40 degC")
    assert state.kinematic_viscosity == pytest.approx(100e-6, rel=1e-12)
    assert state.eta0 == pytest.approx(0.09, rel=1e-12)


def test_pressure_viscosity_missing_is_reported_when_used():
    oil = cc.Lubricant(eta0="0.04 Pa*s")
    with pytest.raises(InputError, match="no pressure–viscosity data"):
        oil.at(None).viscosity(1e8)


def test_viscosity_data_mapping_and_mixed_kinds():
    oil = cc.Lubricant(viscosity_data={"40 degC": "0.09 Pa*s", "100 degC": "0.009 Pa*s"}, alpha="2e-8 1/Pa",
                       viscosity_temperature_law="walther", density="900 kg/m^3")
    assert oil.at("40 degC").eta0 == pytest.approx(0.09, rel=1e-9)
    with pytest.raises(InputError, match="mix of kinematic and dynamic"):
        cc.Lubricant(viscosity_data=[("40 degC", "100 cSt"), ("100 degC", "0.009 Pa*s")], density="900 kg/m^3")
    with pytest.raises(InputError, match=r"viscosity_data\[0\]"):
        cc.Lubricant(viscosity_data=[("40 degC", "3 mm")], density="900 kg/m^3")


def test_gold_correlation_needs_walther_kinematic_data():
    with pytest.raises(InputError, match="alpha_correlation='gold' needs kinematic"):
        cc.Lubricant(eta0="0.04 Pa*s", alpha_correlation="gold")
    with pytest.raises(InputError, match="replaces alpha"):
        cc.Lubricant(nu40="100 cSt", nu100="10 cSt", density="900 kg/m^3", alpha_correlation="gold",
                     alpha="2e-8 1/Pa")


def test_body_signed_radius(steel):
    assert cc.Body(material=steel, radius="10 mm").signed_radius == pytest.approx(0.01)
    assert cc.Body(material=steel, radius="10 mm", concave=True).signed_radius == pytest.approx(-0.01)
    assert math.isinf(cc.Body(material=steel).signed_radius)
    with pytest.raises(InputError, match="concave=True needs a radius"):
        cc.Body(material=steel, concave=True)
    with pytest.raises(InputError, match="Body.material = 'steel': expected a Material"):
        cc.Body(material="steel", radius="1 mm")


def test_line_contact_load_forms(steel):
    b1, b2 = cc.Body(material=steel, radius="20 mm"), cc.Body(material=steel, radius="10 mm")
    assert cc.LineContact(body1=b1, body2=b2, load="1 kN", length="10 mm").w == pytest.approx(1e5)
    assert cc.LineContact(body1=b1, body2=b2, load_per_length="100 N/mm").w == pytest.approx(1e5)
    with pytest.raises(InputError, match="give load and length, or load_per_length"):
        cc.LineContact(body1=b1, body2=b2, load="1 kN")
    with pytest.raises(InputError, match="not both"):
        cc.LineContact(body1=b1, body2=b2, load="1 kN", length="1 mm", load_per_length="1 N/mm")
    with pytest.raises(InputError, match="both bodies are flat"):
        cc.LineContact(body1=cc.Body(material=steel), body2=cc.Body(material=steel), load_per_length="1 N/mm")
    with pytest.raises(InputError, match="friction_coefficient = 2.0 is out of range"):
        cc.LineContact(body1=b1, body2=b2, load_per_length="1 N/mm", friction_coefficient=2.0)
