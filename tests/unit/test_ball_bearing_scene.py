"""BallBearing and LoadedBallBearing at the door, and the ball_bearing scene end to end."""

import math
import warnings

import matplotlib
import attrs
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


ANGULAR = dict(designation="7208 BE", kind="angular_contact", bore="40 mm", outer_diameter="80 mm", width="18 mm",
               ball_count=13, ball_diameter="11.906 mm", contact_angle="40 deg", C="36.4 kN", C0="26 kN",
               fatigue_load_limit="1.1 kN")


def paired(arrangement="back_to_back", bearing_changes=None, **changes):
    """A pair of 7208 BE-like 40 deg bearings under the pair's loads (default 5 kN + 2 kN, 10 um preload)."""
    fields = dict(radial_load="5 kN", axial_load="2 kN", arrangement=arrangement,
                  preload="0 um" if arrangement == "tandem" else "10 um")
    return loaded(ANGULAR | (bearing_changes or {}), **(fields | changes))


@pytest.mark.parametrize("scene", [
    lambda: loaded(),
    lambda: paired("back_to_back"),
    lambda: paired("face_to_face", moment="20 N*m"),
    lambda: paired("tandem", axial_load="6 kN"),
    lambda: paired("back_to_back", axial_load="8 kN", preload="2 um"),  # preload relieved: bearing 1 unloaded
    lambda: paired("back_to_back", {"contact_angle": "15 deg"}),  # P refused below 25 deg: NaN with the failure
], ids=["single", "back_to_back", "face_to_face_moment", "tandem", "relieved", "refused_iso281"])
def test_every_nan_has_its_reason_beside_it(scene):
    from camcontact.report import unexplained_values

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", StepFailureWarning)
        result = cc.Analysis(scene()).run()
    frame, summary = result.to_frame(), result.summary_frame()
    assert unexplained_values(frame) == [] and unexplained_values(summary) == []
    if result.scene.arrangement != "single":
        assert len(frame) == 26 and set(frame["ball_row [-]"]) == {0.0, 1.0}


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


# ----------------------------------------------------------------------------- pairs of angular-contact bearings
@pytest.mark.parametrize("bearing_changes, changes, message", [
    ({}, dict(arrangement="back_to_back"), "arrangement = 'back_to_back' is for angular_contact bearings"),
    (ANGULAR, dict(arrangement="tandem", preload="2 um"), "preload = 2 µm needs a pair clamped"),
    (ANGULAR, dict(arrangement="back_to_back", preload="-2 um"), "LoadedBallBearing.preload = -2 µm is out of range"),
    (ANGULAR, dict(preload="2 um"), "preload = 2 µm needs a pair"),
    (ANGULAR, dict(arrangement="DB"), "LoadedBallBearing.arrangement = 'DB'; allowed: 'single', 'back_to_back'"),
    (ANGULAR, dict(arrangement="back_to_back", row_spacing="0 mm"), "LoadedBallBearing.row_spacing = 0 mm"),
    (ANGULAR, dict(row_spacing="20 mm"), "row_spacing = 20 mm is the distance between the bearings of a pair"),
    (ANGULAR, dict(arrangement="back_to_back", preload=2e-6), "LoadedBallBearing.preload"),
])
def test_bad_pair_input_is_named(bearing_changes, changes, message):
    with pytest.raises(InputError, match=message):
        loaded(bearing_changes, **changes)


def test_pair_scene_under_pure_radial_load_is_the_components_pair():
    """Back to back without axial load: the scene's 2Z ball loads and contact angles are
    BallBearing.pair_load_distribution's (row spacing the width B by default, or as given), both bearings share the
    radial load alike, and each ball's Hertz pressure is its own."""
    scene = paired(radial_load="6 kN", axial_load="0 N", preload="5 um")
    result = cc.Analysis(scene).run()
    direct = scene.bearing.pair_load_distribution("6 kN", "0 N", arrangement="back_to_back", preload="5 um")
    np.testing.assert_allclose(result["Q"], direct.Q, rtol=1e-12)
    np.testing.assert_allclose(result["contact_angle"], direct.contact_angle, rtol=1e-12)
    assert result["ball_row"].tolist() == direct.row.tolist() == [0] * 13 + [1] * 13
    np.testing.assert_allclose(result["Q"][:13], result["Q"][13:], rtol=1e-9)
    assert result["axial_load_row0"] == pytest.approx(result["axial_load_row1"], rel=1e-9)
    assert result["preload_relieved"] is False and result["p_h_inner"].shape == (26,)
    frame = result.to_frame()
    assert list(frame["ball_row [-]"]) == [0.0] * 13 + [1.0] * 13
    spaced = cc.Analysis(attrs.evolve(scene, moment="50 N*m", row_spacing="36 mm"), outputs=["ring_tilt"]).run()
    wider = scene.bearing.pair_load_distribution("6 kN", "0 N", "50 N*m", preload="5 um", row_spacing="36 mm")
    assert spaced["ring_tilt"] == pytest.approx(wider.tilt, rel=1e-12)


def test_tandem_pair_under_twice_the_load_is_the_single_bearing():
    """A tandem pair under (2 F_r, 2 F_a) carries the ball loads of one bearing under (F_r, F_a) in each row, so the
    per-ball Hertz pressures and films repeat those of the single scene."""
    pair = cc.Analysis(paired("tandem", radial_load="4 kN", axial_load="6 kN")).run()
    single = cc.Analysis(loaded(ANGULAR, radial_load="2 kN", axial_load="3 kN")).run()
    np.testing.assert_allclose(pair["Q"], np.tile(single["Q"], 2), rtol=1e-9)
    np.testing.assert_allclose(pair["p_h_inner"], np.tile(single["p_h_inner"], 2), rtol=1e-9)
    np.testing.assert_allclose(pair["h_min_outer"], np.tile(single["h_min_outer"], 2), rtol=1e-9)
    assert pair["axial_load_row0"] == pytest.approx(3e3, rel=1e-9) == pair["axial_load_row1"]
    assert pair["loaded_balls"] == 2 * single["loaded_balls"] and pair["Lambda_bearing"] == single["Lambda_bearing"]
    # ISO 281: the single row's X/Y with the pair's loads (F_a/F_r = 1.5 > e = 1.14) against 2^0.7 C
    assert pair["P"] == pytest.approx(0.35 * 4e3 + 0.57 * 6e3) and pair["X"] == 0.35
    assert pair["L10"] == pytest.approx((2**0.7 * 36.4e3 / pair["P"]) ** 3 * 1e6, rel=1e-12)
    assert pair["s0"] == pytest.approx(2 * 26e3 / max(0.5 * 4e3 + 0.26 * 6e3, 4e3))


def test_pair_steps_and_the_refused_contact_angle():
    """A pair runs its own load and ISO steps, its modified life with the pair's P_u = 2 P_u and C = 2^0.7 C; a
    back-to-back pair at 15 deg has no confirmed double-row factors: strict refuses it naming the angle, otherwise P
    and L10 are NaN with the failure and the rest (ball loads, ISO 76) is reported."""
    from camcontact.models.life_iso281 import a_iso_ball

    result = cc.Analysis(paired(), outputs=["Q_max", "P", "L10", "a1", "a_ISO", "kappa", "L_nm", "L10r", "s0"]).run()
    assert {r.model for r in result.records if r.step in ("load_distribution", "equivalent_load", "static_safety",
                                                         "reference_life")} == {
        "harris_ball_rigid_rings (pair)", "iso281_ball_pair", "iso76_ball_pair", "iso_ts_16281_ball_pair"}
    assert result["L_nm"] == pytest.approx(result["a1"] * result["a_ISO"] * result["L10"], rel=1e-12)
    assert result["a_ISO"] == pytest.approx(a_iso_ball(result["kappa"], 0.5 * 2 * 1.1e3 / result["P"]), rel=1e-12)
    low = paired(bearing_changes={"contact_angle": "15 deg"})
    with pytest.raises(InputError, match="contact angle 15 deg"):
        cc.Analysis(low, outputs=["L10"], strict=True).run()
    with pytest.warns(StepFailureWarning, match="implemented from 25 to 40 deg"):
        lenient = cc.Analysis(low, outputs=["Q_max", "L10", "s0"]).run()
    summary = lenient.summary_frame()
    assert summary["L10 [Mrev]"].isna().all() and (summary["Q_max [kN]"] > 0.0).all() and (summary["s0 [-]"] > 0).all()
    assert any("contact angle 15 deg" in failure.reason for failure in lenient.failures)


def test_pair_plot_draws_each_bearing(tmp_path):
    fig = cc.Analysis(paired()).run().plot()
    labels = [line.get_label() for line in fig.axes[0].get_lines()]
    assert labels[:2] == ["bearing 0", "bearing 1"]
    assert "inner, bearing 1" in [line.get_label() for line in fig.axes[2].get_lines()]
    fig.savefig(tmp_path / "pair.png")


def test_shoulder_truncation_under_a_growing_axial_load():
    """The 6309 with assumed shoulder diameters of a low land (0.15 D_w above each groove's bottom: 60.3 mm inner,
    84.7 mm outer; 0.2 D_w is more usual and keeps 4.5 deg even at 30 kN): the scene's margin is the shoulder angle of the geometry (computed here from the
    groove radii and centres) minus |alpha| and the ellipse's half-width over the groove radius; it shrinks as the
    axial load raises the contact angles, and a heavy thrust runs the ellipses over the shoulders (truncated), which
    pure radial load does not. Without shoulder diameters the outputs are not offered, with the hint."""
    D = 17.462e-3
    bearing = cc.BallBearing(designation="6309", bore="45 mm", outer_diameter="100 mm", width="25 mm", ball_count=8,
                             ball_diameter="17.462 mm", inner_osculation=0.52, outer_osculation=0.53,
                             radial_clearance="15 um", C="55.3 kN", C0="31.5 kN", material=cc.Material(E="207 GPa", nu=0.3),
                             inner_shoulder_diameter=f"{55.032 + 0.3 * 17.462} mm",
                             outer_shoulder_diameter=f"{89.971 - 0.3 * 17.462} mm")
    d_m, c = 72.5e-3, math.cos(bearing.free_contact_angle)
    rho_i, rho_o = d_m / 2 + 0.02 * D * c, d_m / 2 - 0.03 * D * c
    theta_i = math.acos((rho_i - bearing.si.inner_shoulder_diameter / 2) / (0.52 * D))
    theta_o = math.acos((bearing.si.outer_shoulder_diameter / 2 - rho_o) / (0.53 * D))
    assert bearing.shoulder_angles == pytest.approx({"inner": theta_i, "outer": theta_o}, rel=1e-12)
    wanted = ["contact_angle", "a_transverse_inner", "truncation_margin_inner", "truncated_inner", "truncated_balls",
              "loaded"]
    margins = []
    for axial in ("0 kN", "5 kN", "30 kN"):
        scene = cc.LoadedBallBearing(bearing=bearing, radial_load="2 kN", axial_load=axial, speed="3000 rpm")
        result = cc.Analysis(scene, outputs=wanted).run()
        loaded = np.asarray(result["loaded"])
        alpha, width = np.asarray(result["contact_angle"])[loaded], np.asarray(result["a_transverse_inner"])[loaded]
        margin = np.asarray(result["truncation_margin_inner"])[loaded]
        np.testing.assert_allclose(margin, theta_i - np.abs(alpha) - width / (0.52 * D), rtol=1e-12)
        margins.append(margin.min())
    assert margins[0] > margins[1] > margins[2] and margins[0] > 0.0 > margins[2]
    assert result["truncated_balls"] > 0 and np.asarray(result["truncated_inner"]).any()
    plain = cc.LoadedBallBearing(bearing=attrs.evolve(bearing, inner_shoulder_diameter=None,
                                                      outer_shoulder_diameter=None), radial_load="2 kN", speed="3000 rpm")
    with pytest.raises(InputError, match="shoulder_diameter"):
        cc.Analysis(plain, outputs=["truncated_inner"])
    with pytest.raises(InputError, match="give both or neither"):
        attrs.evolve(bearing, outer_shoulder_diameter=None)
    with pytest.raises(InputError, match="inner_shoulder_diameter"):
        attrs.evolve(bearing, inner_shoulder_diameter="80 mm")
