"""Ball-cone CVT (issue 17, errors 1-2): the clamping in axial balance by default, the thesis's Eq. 6.17 as a
named reading, and the contact-stress limit (ISO 76:2006) as a warning and a boolean column.

Independent check of the statics: the forces of the two cones on a ball are built from the contact
geometry (normal leaning alpha off radial, :func:`contact_force_vectors`); the input cone's axial
equilibrium under the loading cam's thrust F_2 m and its n ball contacts is summed here.
"""

import math
import warnings

import pytest

import camcontact as cc
from camcontact.components.ball_cone_cvt import BallConeCVT, LoadedBallConeCVT
from camcontact.dynamics.ball_cone_loads import axial_residuals, ball_cone_loads, contact_force_vectors
from camcontact.errors import InputError, ValidityWarning

ALPHA = math.radians(30.0)
STEEL = cc.Material(E="207 GPa", nu=0.3)
FORTI = dict(cone_angle="30 deg", cone_contact_radius="24 mm", ball_diameter="14 mm", ball_count=9,
             tilt_max="30 deg", cam_ramp_angle="10 deg", cam_radius="6 mm", cam_ball_count=5, material=STEEL,
             traction_coefficient=0.095)


def _loads(clamping, ratio=1.0, power=150.0):
    return ball_cone_loads(power, 2 * math.pi, ball_count=9, cone_radius=24e-3, cone_angle=ALPHA,
                           cam_angle=math.radians(10), cam_radius=6e-3, cam_ball_count=5, reduction_ratio=ratio,
                           clamping=clamping)


@pytest.mark.parametrize("ratio", [0.5, 1.0, 2.0])
@pytest.mark.parametrize("power", [10.0, 150.0, 300.0])
def test_axial_balance_holds_each_ball_and_the_cone(ratio, power):
    """Default clamping: the cone's n contacts carry the cam's thrust, n F_n sin(alpha) = F_2 m, and each ball is
    pushed equally from both sides; residuals below 1e-9 of the thrust (the issue's must-show)."""
    loads = _loads("axial_balance", ratio, power)
    residual = axial_residuals(loads, ball_count=9, cone_angle=ALPHA)
    thrust = loads["cam_axial_force"]
    assert abs(residual["cone"]) <= 1e-9 * thrust and abs(residual["ball"]) <= 1e-9 * thrust
    # by hand: the vectors' axial parts summed over the nine balls against the thrust
    vectors = contact_force_vectors(loads["normal_force"], loads["tangential_force_in"],
                                    loads["tangential_force_out"], ALPHA)
    assert abs(9 * vectors["input"][0] - thrust) <= 1e-9 * thrust
    # the ring takes Eq. 6.18's radial 2 F_n cos(alpha) and the cage the tangential difference
    assert vectors["ring"][1] == pytest.approx(-loads["ball_axial_resultant"], rel=1e-12)
    assert vectors["ring"][2] == pytest.approx(loads["tangential_force_out"] - loads["tangential_force_in"], abs=1e-9)


def test_thesis_clamping_is_kept_and_its_imbalance_shown():
    """Eq. 6.17 gives 1254 N at 150 W (the thesis's "about 1200 N"); the cam's thrust T/(R_cam tan eta) = 22 565 N is
    2507 N per ball, of which the thesis's contact carries 627 N axially (sin^2(30 deg) = 1/4): 3/4 of the thrust
    has no reaction. Axial balance gives 5014 N (the issue's value)."""
    thesis, balanced = _loads("thesis"), _loads("axial_balance")
    assert thesis["normal_force"] == pytest.approx(1253.63, abs=0.01)
    assert balanced["normal_force"] == pytest.approx(5014.5, abs=0.1)
    residual = axial_residuals(thesis, ball_count=9, cone_angle=ALPHA)["cone"]
    assert residual == pytest.approx(0.75 * thesis["cam_axial_force"], rel=1e-12)
    assert thesis["cam_axial_force"] / 9 == pytest.approx(2507.3, abs=0.1)
    assert thesis["normal_force"] * math.sin(ALPHA) == pytest.approx(626.8, abs=0.1)


def test_component_default_clamping_and_named_error():
    assert BallConeCVT(**FORTI).clamping == "axial_balance"
    with pytest.raises(InputError, match="clamping.*'axial'"):
        BallConeCVT(clamping="axial", **FORTI)
    with pytest.raises(InputError, match="clamping = 'x'"):
        _loads("x")


def _run(outputs, **changes):
    point = LoadedBallConeCVT(cvt=BallConeCVT(**{**FORTI, **changes}), power="150 W", input_speed="60 rpm")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        row = cc.Analysis(point, outputs=outputs).run().rows[0]
    return row, [w for w in caught if issubclass(w.category, ValidityWarning)]


def test_stress_limit_flag_and_warning():
    """p_h = 6.86 GPa (balanced) and 4.32 GPa (thesis) both exceed ISO 76's 4.2 GPa for ball contacts: a
    boolean column and a ValidityWarning naming the limit and its source; a raised limit clears both."""
    outputs = ["p_h", "stress_limit_exceeded", "normal_force"]
    row, caught = _run(outputs)
    assert row["p_h"] == pytest.approx(6.86e9, rel=2e-3) and row["stress_limit_exceeded"] is True
    assert len(caught) == 1 and "4.2 GPa" in str(caught[0].message) and "ISO 76" in str(caught[0].message)
    row, caught = _run(outputs, clamping="thesis")
    assert row["p_h"] == pytest.approx(4.32e9, rel=2e-3) and row["stress_limit_exceeded"] is True
    row, caught = _run(outputs, clamping="thesis", contact_stress_limit="5 GPa")
    assert row["stress_limit_exceeded"] is False and not caught


def test_stress_limit_is_validated():
    with pytest.raises(InputError, match="contact_stress_limit"):
        BallConeCVT(contact_stress_limit="-1 GPa", **FORTI)
    with pytest.raises(InputError, match="contact_stress_limit"):
        BallConeCVT(contact_stress_limit="3 mm", **FORTI)
