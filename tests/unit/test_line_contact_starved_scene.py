"""Starvation as a scene input: LineContact.oil_layer with the film model 'multigrid'.

The pellet-mill line contact of the default scene (Delabenetta 2021 inputs), isothermal. Checks: the layer is
validated at the door; a formula film model refuses it (the formulas are for flooded contacts) instead of
ignoring it; a layer thicker than the flooded contact can pass leaves the flooded film; a thinner one sets the
central film by mass conservation, rho_c h_c = h_oil (no side flow in a line contact; rho_c from the
Dowson–Higginson law at the central pressure of the solution).
"""

import math
import tomllib
from pathlib import Path

import attrs
import numpy as np
import pytest

import camcontact as cc
from camcontact.ehl.line_problem import DH_A, DH_B

SCENE = Path(__file__).resolve().parents[2] / "tutorials" / "pellet_mill_line_contact.toml"
OUTPUTS = ["h_c", "h_min", "p_h", "film_validity"]
ISOTHERMAL = {"elasticity", "piezoviscosity", "compressibility"}


@pytest.fixture(scope="module")
def contact():
    return cc.load_scene(SCENE).component


def _run(contact, layer):
    return cc.Analysis(attrs.evolve(contact, oil_layer=layer), outputs=OUTPUTS, models={"film": "multigrid"},
                       effects=ISOTHERMAL).run()


def test_oil_layer_is_validated_and_refused_by_the_formulas(contact):
    with pytest.raises(cc.InputError, match="oil_layer"):
        attrs.evolve(contact, oil_layer="-1 um")
    with pytest.raises(cc.InputError, match="oil_layer = 0.5 µm .*needs the film model 'multigrid', not 'moes'"):
        cc.Analysis(attrs.evolve(contact, oil_layer="0.5 um"), outputs=["h_c"], models={"film": "moes"})


def test_a_thick_layer_leaves_the_contact_flooded(contact):
    flooded, thick = _run(contact, None), _run(contact, "3 um")
    assert float(thick["h_c"]) == pytest.approx(float(flooded["h_c"]), rel=1e-12)
    assert thick["film_validity"] == "ok"


@pytest.mark.parametrize("layer", [0.5e-6, 0.2e-6])
def test_a_thin_layer_sets_the_film_by_mass_conservation(contact, layer):
    flooded, starved = _run(contact, None), _run(contact, f"{layer} m")
    h_c = float(starved["h_c"])
    p_c = float(starved["p_h"])  # the central pressure of a starved contact is Hertz's (within 1 %)
    rho_c = (DH_A + DH_B * p_c) / (DH_A + p_c)
    assert rho_c * h_c == pytest.approx(layer, rel=1e-2)
    assert h_c < float(flooded["h_c"]) and starved["film_validity"] == "ok"
    assert math.isfinite(float(starved["h_min"])) and float(starved["h_min"]) <= h_c * (1 + 1e-9)


def test_oil_layer_reads_from_a_scene_file(tmp_path, contact):
    data = tomllib.loads(SCENE.read_text(encoding="utf-8"))
    text = SCENE.read_text(encoding="utf-8").replace('name = "roller / outer ring"\n',
                                                    'name = "roller / outer ring"\noil_layer = "0.5 um"\n', 1)
    path = tmp_path / "starved.toml"
    path.write_text(text, encoding="utf-8")
    scene = cc.load_scene(path)
    assert scene.component.oil_layer == cc.Q_(0.5, "um") and data["contact"]["name"] == "roller / outer ring"
    assert np.isclose(scene.component.si.oil_layer, 5e-7)
