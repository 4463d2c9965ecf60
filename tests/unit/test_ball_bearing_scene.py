"""BallBearing and LoadedBallBearing at the door, and the ball_bearing scene end to end."""

import math

import matplotlib
import numpy as np
import pytest

import camcontact as cc
from camcontact.errors import InputError, StepFailureWarning
from camcontact.scene_file import load_scene

matplotlib.use("Agg")

STEEL = cc.Material(E="207 GPa", nu=0.3)
OIL = cc.Lubricant(name="ISO VG 68", nu40="68 cSt", nu100="8.6 cSt", density="0.87 g/cm^3", alpha="2.2e-8 1/Pa")
FIELDS = dict(designation="6309", bore="45 mm", outer_diameter="100 mm", width="25 mm", ball_count=8,
              ball_diameter="17.462 mm", inner_osculation=0.52, outer_osculation=0.53, C="55.3 kN", C0="31.5 kN",
              fatigue_load_limit="1.34 kN", material=STEEL, roughness="0.1 um")


def loaded(bearing_changes=None, **changes):
    bearing = cc.BallBearing(**(FIELDS | (bearing_changes or {})))
    fields = dict(bearing=bearing, radial_load="10 kN", axial_load="2 kN", speed="3000 rpm", lubricant=OIL,
                  temperature="70 degC", contamination=0.5)
    return cc.LoadedBallBearing(**(fields | changes))


@pytest.mark.parametrize("changes, message", [
    (dict(inner_osculation=0.5), "inner_osculation = 0.5"),
    (dict(outer_osculation=1.2), "outer_osculation = 1.2"),
    (dict(kind="angular_contact"), "needs its contact_angle"),
    (dict(kind="angular_contact", contact_angle="50 deg"), "contact_angle"),
    (dict(contact_angle="15 deg"), "is for an angular_contact bearing"),
    (dict(radial_clearance="1.8 mm"), "not below 2 \\(f_i \\+ f_o - 1\\) D_w"),
    (dict(radial_clearance="0.6 mm"), "free contact angle of 49 deg"),
    (dict(ball_count=14), "do not fit on the pitch circle"),
    (dict(ball_diameter="30 mm"), "section height"),
    (dict(kind="tapered"), "kind = 'tapered'"),
    (dict(ball_count=7.5), "ball_count = 7.5"),
])
def test_bad_bearing_input_is_named(changes, message):
    with pytest.raises(InputError, match=message):
        cc.BallBearing(**(FIELDS | changes))


def test_derived_geometry():
    bearing = cc.BallBearing(**(FIELDS | {"radial_clearance": "15 um"}))
    A = 0.05 * 17.462e-3
    assert bearing.groove_distance == pytest.approx(A)
    assert bearing.free_contact_angle == pytest.approx(math.acos(1 - 15e-6 / (2 * A)))
    assert bearing.rating_contact_angle == 0.0
    radii = bearing.contact_radii(0.0)
    assert radii["inner"][0] == pytest.approx(0.5 * 17.462e-3 * (1 - 17.462 / 72.5))
    assert radii["outer"][1] == pytest.approx(0.53 * 17.462e-3 / 0.06)
    angular = cc.BallBearing(**(FIELDS | {"kind": "angular_contact", "contact_angle": "40 deg"}))
    assert angular.rating_contact_angle == pytest.approx(math.radians(40))


def test_scene_reports_per_ball_and_summary():
    result = cc.Analysis(loaded()).run()
    frame, summary = result.to_frame(), result.summary_frame()
    assert len(frame) == 8 and frame["loaded [-]" if "loaded [-]" in frame else "loaded"].sum() == 5
    unloaded = frame[~frame["loaded"].astype(bool)]
    assert unloaded["p_h_inner [MPa]"].isna().all() and (unloaded["contact_regime"] == "unloaded").all()
    assert result["Q_max"] == pytest.approx(np.max(result["Q"]))
    assert result["p_h_max"] == pytest.approx(np.nanmax(result["p_h_inner"]))
    assert result["Lambda_bearing"] == pytest.approx(np.nanmin(np.concatenate([result["Lambda_inner"],
                                                                            result["Lambda_outer"]])))
    assert result["L10"] == pytest.approx(5.53**3 * 1e6, rel=1e-9)
    assert math.degrees(result["contact_angle_min"]) > math.degrees(cc.BallBearing(**FIELDS).free_contact_angle)
    assert "Q_max [kN]" in summary.columns and result["film_valid"] is False  # k ~ 9.9 > Hamrock-Dowson's 8
    assert "hamrock_dowson (inner raceway" in result["film_validity"]


def test_every_nan_has_its_reason_beside_it():
    from camcontact.report import unexplained_values

    result = cc.Analysis(loaded()).run()
    assert unexplained_values(result.to_frame()) == [] and unexplained_values(result.summary_frame()) == []


def test_only_the_steps_asked_for_run():
    result = cc.Analysis(loaded(lubricant=None, temperature=None), outputs=["Q_max", "p_h_max"]).run()
    ran = {record.step for record in result.records}
    assert ran == {"load_distribution", "hertz"}


def test_missing_inputs_are_named():
    with pytest.raises(InputError, match="LoadedBallBearing.lubricant"):
        cc.Analysis(loaded(lubricant=None), outputs=["h_min_bearing"]).run()
    with pytest.raises(InputError, match="BallBearing.material"):
        cc.Analysis(loaded({"material": None}), outputs=["Q_max"]).run()


def test_moment_load_and_angular_contact_scene():
    free = cc.Analysis(loaded(moment="0 N*m"), outputs=["ring_tilt", "tilting_moment"]).run()
    assert free["ring_tilt"] != 0.0 and abs(free["tilting_moment"]) < 1e-6
    angular = loaded({"kind": "angular_contact", "contact_angle": "40 deg"}, radial_load="5 kN", axial_load="8 kN")
    result = cc.Analysis(angular, outputs=["contact_angle_min", "contact_angle_max", "P", "X", "Y"]).run()
    assert math.radians(40) < result["contact_angle_min"] <= result["contact_angle_max"]
    assert (result["X"], result["Y"]) == (0.35, 0.57)
    radial_only = loaded({"kind": "angular_contact", "contact_angle": "40 deg"}, axial_load="0 N")
    with pytest.raises(InputError, match="needs an axial load"):
        cc.Analysis(radial_only, outputs=["Q_max"], strict=True).run()
    with pytest.warns(StepFailureWarning, match="needs an axial load"):
        lenient = cc.Analysis(radial_only, outputs=["Q_max", "P"]).run()
    assert lenient.summary_frame()["Q_max [kN]"].isna().all()
    assert lenient["P"] == pytest.approx(10e3)  # F_a/F_r = 0 <= e; P needs no load distribution
    assert any("needs an axial load" in failure.reason for failure in lenient.failures)


def test_numerical_point_film_in_the_bearing_is_refused_without_elasticity():
    with pytest.raises(InputError, match="elasticity"):
        cc.Analysis(loaded(), effects=["piezoviscosity"]).run()


def test_plot_renders(tmp_path):
    result = cc.Analysis(loaded()).run()
    fig = result.plot()
    assert len(fig.axes) == 4
    titles = [ax.get_title() for ax in fig.axes]
    assert "contact angle per ball" in titles and "ball load Q [kN]" in titles
    fig.savefig(tmp_path / "ball.png")
    with pytest.raises(InputError, match="unknown ball bearing plot panels"):
        result.plot(panels=["polar"])


def test_tutorial_scene_file():
    scene = load_scene("tutorials/deep_groove_ball_bearing.toml")
    assert isinstance(scene.component, cc.LoadedBallBearing)
    result = scene.analysis().run()
    assert result["loaded_balls"] == 5 and result["P"] == pytest.approx(10e3)
