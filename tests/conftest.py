"""Shared fixtures. Every number in a test names its source or the calculation behind it."""

from __future__ import annotations

import pytest

import camcontact as cc
from camcontact import registry


@pytest.fixture
def steel():
    """Bearing steel, E = 210 GPa, nu = 0.3 (Tsuha 2015 Table 6.2)."""
    return cc.Material(E="210 GPa", nu=0.3, name="steel")


@pytest.fixture(scope="session")
def thermal_steel_ls1():
    """The default LS-1 scene (1000 rpm) with a flat-faced follower, both bodies steel with thermal data
    (rho 7850 kg/m^3, c 460 J/(kg K), k 47 W/(m K): textbook values for bearing steel) and the oil's
    temperature-viscosity coefficient beta = 0.03 1/K and conductivity 0.13 W/(m K) (mineral oil orders of
    magnitude): what the thermal traction and the inlet correction need."""
    import attrs

    from camcontact.scene_file import load_scene

    scene = load_scene().component
    steel = cc.Material(E="210 GPa", nu=0.3, density="7850 kg/m^3", specific_heat="460 J/kg/K",
                        thermal_conductivity="47 W/m/K")
    oil = attrs.evolve(scene.lubricant, thermoviscous_coefficient="0.03 1/K", thermal_conductivity="0.13 W/m/K")
    return attrs.evolve(scene, lubricant=oil, cam=attrs.evolve(scene.cam, material=steel),
                        follower=cc.Follower.flat(material=steel, roughness="0.2 um"))


@pytest.fixture
def oiled_contact(steel):
    """A lubricated steel line contact, 3 kN on 15 mm, R 40/10 mm, 3 m/s, an ISO VG 100 oil at 80 degC (the
    README's first example): p_h 958 MPa, films of a few tenths of a micron by the formulas."""
    oil = cc.Lubricant(nu40="100 cSt", nu100="11 cSt", density="870 kg/m^3", alpha="22 1/GPa")
    return cc.LineContact(body1=cc.Body(material=steel, radius="40 mm", speed="3 m/s", roughness="0.2 um"),
                          body2=cc.Body(material=steel, radius="10 mm", speed="3 m/s", roughness="0.2 um"),
                          load="3 kN", length="15 mm", lubricant=oil, temperature="80 degC")


@pytest.fixture
def clean_registry():
    """Forget discovered plugins before and after a test that fakes entry points."""
    registry.reset()
    yield registry
    registry.reset()
