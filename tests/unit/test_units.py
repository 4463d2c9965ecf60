"""Units at the door: parsing, bare numbers, wrong dimensions, NaN/inf, SI views."""

import math

import numpy as np
import pytest

import camcontact as cc
from camcontact.errors import InputError
from camcontact.units import Q_, parse_quantity, si_value, to_float, to_quantity, ureg


def test_one_application_registry():
    import pint

    assert pint.get_application_registry().get() is ureg
    assert Q_(1, "mm")._REGISTRY is ureg
    assert cc.Q_ is Q_ and cc.ureg is ureg


@pytest.mark.parametrize(
    "text, dimension, si",
    [
        ("15 mm", "[length]", 0.015),
        ("85 degC", "[temperature]", 358.15),
        ("84.9 °C", "[temperature]", 358.05),
        ("2.2e-8 1/Pa", "1/[pressure]", 2.2e-8),
        ("22 1/GPa", "1/[pressure]", 2.2e-8),
        ("575 cSt", "[kinematic_viscosity]", 575e-6),
        ("0.92 g/cm^3", "[density]", 920.0),
        ("1000 rpm", "1/[time]", 1000 * 2 * math.pi / 60),
        ("10 kN", "[force]", 1e4),
    ],
)
def test_strings_with_units_are_parsed(text, dimension, si):
    assert si_value(to_quantity(text, dimension, where="X.f")) == pytest.approx(si, rel=1e-12)


def test_quantities_and_tuples_are_accepted():
    assert si_value(to_quantity(Q_(210, "GPa"), "[pressure]", where="X.E")) == 210e9
    assert si_value(to_quantity((15, "mm"), "[length]", where="X.r")) == 0.015
    array = to_quantity(Q_(np.array([1.0, 2.0]), "mm"), "[length]", where="X.r")
    np.testing.assert_allclose(si_value(array), [0.001, 0.002])


def test_bare_number_for_dimensional_field_names_field_and_dimension():
    with pytest.raises(InputError, match=r"Material\.E = 210.*bare number.*\[pressure\]"):
        cc.Material(E=210, nu=0.3)


def test_wrong_dimension_names_field_value_and_expected():
    with pytest.raises(InputError, match=r"Material\.E = 200.*mm.*expected \[pressure\]"):
        cc.Material(E="200 mm", nu=0.3)


@pytest.mark.parametrize("bad", ["nan GPa", "inf GPa", Q_(float("nan"), "GPa"), Q_(float("inf"), "GPa")])
def test_nan_and_inf_are_rejected(bad):
    with pytest.raises(InputError, match="finite"):
        cc.Material(E=bad, nu=0.3)


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), "nan"])
def test_nan_dimensionless_rejected(bad):
    with pytest.raises(InputError, match="Material.nu"):
        cc.Material(E="210 GPa", nu=bad)


def test_unparseable_string_is_an_input_error():
    with pytest.raises(InputError, match="cannot read"):
        parse_quantity("15 furlongs per fortnightx", where="Body.radius")


def test_to_float_rejects_dimensional_quantities():
    with pytest.raises(InputError):
        to_float("3 mm", where="X.nu")
    assert to_float("0.3", where="X.nu") == 0.3
    assert to_float(Q_(30, "percent"), where="X.nu") == pytest.approx(0.3)


@pytest.mark.parametrize(
    "kwargs, pattern",
    [
        (dict(E="-1 GPa", nu=0.3), r"Material\.E = -1.* out of range; allowed: 0 < E"),
        (dict(E="0 GPa", nu=0.3), r"Material\.E"),
        (dict(E="210 GPa", nu=0.5), r"Material\.nu = 0\.5 .*0 <= nu < 0\.5"),
        (dict(E="210 GPa", nu=-0.1), r"Material\.nu"),
        (dict(E="210 GPa", nu=0.3, density="-5 kg/m^3"), r"Material\.density"),
    ],
)
def test_range_validators_name_value_and_range(kwargs, pattern):
    with pytest.raises(InputError, match=pattern):
        cc.Material(**kwargs)


def test_temperature_above_absolute_zero():
    with pytest.raises(InputError, match=r"reference_temperature.*0 < reference_temperature \[K\]"):
        cc.Lubricant(eta0="0.04 Pa*s", reference_temperature="-300 degC")


def test_si_view_is_cached_and_read_only(steel):
    view = steel.si
    assert view is steel.si
    assert view.E == 210e9 and view["nu"] == 0.3 and view.density is None
    with pytest.raises(AttributeError):
        view.E = 1.0
    with pytest.raises(AttributeError, match="no field"):
        view.radius


def test_readable_repr():
    text = repr(cc.Material(E="210 GPa", nu=0.3, name="steel"))
    assert "E=210" in text and "GPa" in text and "Quantity" not in text


def test_components_are_frozen(steel):
    import attrs

    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        steel.E = Q_(1, "GPa")
