"""The ball-cone CVT's ``mixed`` effect (issue 16): Greenwood–Tripp asperity load sharing at each contact and the
EHL traction of the film's share plus the asperities' Coulomb friction along the local sliding.

Independent references: the traction step's creepage against a hand-built EhlTraction contact with the mixed
step's share and film and the lubricant's boundary friction (the wiring); the trends the model must show (a
rougher surface gives the asperities more load; boundary friction adds capacity and, with spin, loss); the
contact-level closed forms are in tests/unit/test_spin_traction.py.
"""

import attrs
import pytest

import camcontact as cc
from camcontact.errors import InputError
from camcontact.models.film_multigrid_point import MultigridPoint
from camcontact.models.traction_fluid import EyringTraction
from camcontact.models.traction_spin import EhlTraction
from camcontact.report import unexplained_values
from test_ball_cone_cvt_scene import FLUID, cvt, point

MIXED = ["elasticity", "piezoviscosity", "spin", "mixed"]


def test_mixed_runs_its_step_and_reports_each_contact():
    analysis = cc.Analysis(point(), effects=MIXED)
    assert analysis.steps()[analysis.steps().index("mixed") + 1] == "traction"
    result = analysis.run()
    frame = result.to_frame()
    for side in ("in", "out"):
        assert {f"asperity_load_fraction_{side} [-]", f"h_c_mixed_{side} [µm]", f"lubrication_regime_{side}",
                f"mixed_valid_{side}"} <= set(frame.columns)
    row = result.rows[0]
    # 6.9 GPa, Lambda ~ 0.1: the asperities take a few % (their capacity at contact is ~4 %), which the model
    # cannot push to boundary lubrication: flagged, not hidden
    assert 0.0 < row["asperity_load_fraction_in"] <= row["asperity_capacity_in"] < 1.0
    assert row["lubrication_regime_in"] == "boundary" and not row["mixed_valid_in"]
    assert unexplained_values(frame) == []
    assert "mixed" not in cc.Analysis(point()).steps()  # not asked for: not run
    # the slice stresses read the surface's traction coefficient over the whole pressure: a few % of the load
    # on asperities (mu_b 0.12 against the film's ~0.07) moves tau0 by well under 1 %, not by 1/(1 - f)
    plain = cc.Analysis(point(), outputs=["tau0_in"]).run()
    assert row["tau0_in"] == pytest.approx(plain["tau0_in"], rel=0.01)


def test_traction_shears_the_fluid_share_and_the_asperities():
    """The scene's creepage and loss equal those of an EhlTraction contact built by hand with the mixed step's
    share f and film and the lubricant's boundary friction 0.12 (f of the Hertz load on the asperities)."""
    result = cc.Analysis(point(), effects=MIXED, outputs=[
        "creepage_in", "power_loss_in", "traction_capacity_in", "asperity_load_fraction_in", "h_c_mixed_in",
        "a_rolling", "a_transverse", "p_h", "rolling_speed_in", "spin_in", "tangential_force_in",
        "lubricant_state"]).run()
    row = result.rows[0]
    model = EhlTraction(fluid=EyringTraction(limiting_shear_slope=0.088))
    contact = model.contact(row["a_rolling"], row["a_transverse"], row["p_h"], row["h_c_mixed_in"],
                            row["rolling_speed_in"], row["lubricant_state"],
                            asperity_load_fraction=row["asperity_load_fraction_in"], boundary_friction=0.12)
    hand = model.solve(row["tangential_force_in"], row["spin_in"], contact)
    assert FLUID.boundary_friction == 0.12
    for name in ("creepage", "power_loss", "traction_capacity"):
        assert row[f"{name}_in"] == pytest.approx(hand[name], rel=1e-9)


def test_rougher_surfaces_and_boundary_friction_act_as_they_should():
    def run(lubricant=FLUID, roughness="0.1 um"):
        scene = point(cvt=cvt(lubricant=lubricant, roughness=roughness))
        return cc.Analysis(scene, effects=MIXED, outputs=["asperity_load_fraction_in", "traction_capacity_in",
                                                          "efficiency"]).run().rows[0]

    smooth, rough = run(), run(roughness="0.2 um")
    assert rough["asperity_load_fraction_in"] > smooth["asperity_load_fraction_in"]
    slippery = run(lubricant=attrs.evolve(FLUID, boundary_friction=0.0))
    grippy = run(lubricant=attrs.evolve(FLUID, boundary_friction=0.3))
    # the asperities' Coulomb friction adds capacity, and with spin every sliding asperity dissipates
    assert slippery["traction_capacity_in"] < smooth["traction_capacity_in"] < grippy["traction_capacity_in"]
    assert slippery["efficiency"] > smooth["efficiency"] > grippy["efficiency"]


def test_what_mixed_cannot_honour_is_refused_by_name():
    with pytest.raises(InputError, match="needs the traction model 'ehl_traction'.*FASTSIM"):
        cc.Analysis(point(), effects=MIXED, models={"traction": "fastsim"})
    with pytest.raises(InputError, match="needs a film formula"):
        cc.Analysis(point(), effects=MIXED, models={"film": MultigridPoint(levels=3)})
    with pytest.raises(InputError, match="roughness = 0 µm.*allowed: > 0"):
        cc.Analysis(point(cvt=cvt(roughness="0 um")), effects=MIXED)
    with pytest.raises(InputError, match="sigma: set BallConeCVT.roughness"):
        cc.Analysis(point(cvt=cvt(roughness=None)), effects=MIXED).run()
    with pytest.raises(InputError, match="BallConeCVT.asperity_density"):
        cvt(asperity_density="0 1/mm^2")
    with pytest.raises(InputError, match="BallConeCVT.asperity_radius"):
        cvt(asperity_radius="-3 um")
