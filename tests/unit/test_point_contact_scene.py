"""The point-contact scene (camcontact.scenes.point_contact): a ball on a flat plate and a ball in a groove.

Independent checks: the films of the Hamrock–Dowson model called directly (1e-12) and, for the same
contact, the numerical point multigrid (Venner & Lubrecht FMG, validated against their C code elsewhere):
its h_min within 2 % of Hamrock–Dowson's and its h_c within 2 % of Nijenbanning, Venner & Moes (1994) (which
fits numerical solutions of this kind; Hamrock–Dowson's central film lies 15 % lower here — its fit is
known to underestimate h_c at high M); the scene's Hertz against the circle's closed form.
"""

import math
import warnings

import pytest

import camcontact as cc
from camcontact import registry
from camcontact.errors import InputError, ValidityWarning

STEEL = cc.Material(E="207 GPa", nu=0.3)
OIL = cc.Lubricant(nu40="68 cSt", nu100="8.6 cSt", density="0.87 g/cm^3", alpha="2.2e-8 1/Pa")


def ball_on_flat(**changes):
    fields = dict(body1=cc.Body(material=STEEL, radius="6.35 mm", transverse_radius="6.35 mm", speed="2 m/s",
                                roughness="0.05 um"),
                  body2=cc.Body(material=STEEL, speed="2 m/s", roughness="0.05 um"), load="50 N", lubricant=OIL,
                  temperature="40 degC")
    fields.update(changes)
    return cc.PointContact(**fields)


def test_only_the_needed_steps_run_and_the_hertz_is_the_circles():
    contact = ball_on_flat()
    assert cc.Analysis(contact, outputs=["p_h"]).steps() == ["geometry", "hertz"]
    result = cc.Analysis(contact).run()
    E_reduced = 207e9 / (1 - 0.3**2)
    a = (3 * 50.0 * 6.35e-3 / (2 * E_reduced)) ** (1 / 3)
    assert result["a_rolling"] == pytest.approx(a, rel=1e-9) and result["Rx"] == result["Ry"] == 6.35e-3
    assert result["p_h"] == pytest.approx(3 * 50.0 / (2 * math.pi * a * a), rel=1e-9)
    assert result["z_tresca_max"] / a == pytest.approx(0.48, abs=0.005)
    assert result["regime"] == "full film" and result["film_valid"] and result["stress_limit_exceeded"] is False


def test_films_against_hamrock_dowson_and_the_point_multigrid():
    contact = ball_on_flat()
    result = cc.Analysis(contact, models={"film": ["hamrock_dowson", "nijenbanning", "multigrid"]}).run()
    hd, nvm, numerical = result.rows
    direct = registry.get("film_models", "hamrock_dowson").evaluate(
        Rx=6.35e-3, Ry=6.35e-3, F=50.0, E_reduced=207e9 / (1 - 0.3**2), u_m=2.0, eta0=hd["eta0"], alpha=hd["alpha"])
    assert hd["h_min"] == pytest.approx(float(direct["h_min"]), rel=1e-12)
    assert hd["h_c"] == pytest.approx(float(direct["h_c"]), rel=1e-12)
    assert numerical["h_min"] == pytest.approx(hd["h_min"], rel=0.02)
    assert numerical["h_c"] == pytest.approx(nvm["h_c"], rel=0.02)
    assert hd["h_c"] < 0.9 * numerical["h_c"]
    assert "h_min" not in nvm or math.isnan(nvm.get("h_min", math.nan))  # Nijenbanning gives h_c only
    assert nvm["Lambda_c"] == pytest.approx(nvm["h_c"] / math.hypot(0.05e-6, 0.05e-6), rel=1e-12)
    assert [r.model for r in result.records if r.step == "film"] == ["hamrock_dowson", "nijenbanning",
                                                                    "multigrid_point"]


def test_a_ball_in_a_groove_is_elliptical():
    """A groove of radius 6.604 mm across rolling (conformity r/D = 0.52 for the 12.7 mm ball, concave) on a
    20 mm raceway: Ry from the conforming curvatures, a wide ellipse across rolling."""
    ball = cc.Body(material=STEEL, radius="6.35 mm", transverse_radius="6.35 mm", speed="3 m/s")
    groove = cc.Body(material=STEEL, radius="20 mm", transverse_radius="6.604 mm", transverse_concave=True,
                     speed="3 m/s")
    result = cc.Analysis(ball_on_flat(body1=ball, body2=groove, load="1 kN"),
                         outputs=["Rx", "Ry", "a_rolling", "a_transverse", "ellipticity", "h_min"]).run()
    assert result["Ry"] == pytest.approx(1 / (1 / 6.35e-3 - 1 / 6.604e-3), rel=1e-12)
    assert result["ellipticity"] > 5.0 and result["a_transverse"] > 5 * result["a_rolling"]
    assert result["h_min"] > 0.0


def test_bad_input_is_named():
    flat = cc.Body(material=STEEL, speed="1 m/s")
    cylinder = cc.Body(material=STEEL, radius="10 mm", speed="1 m/s")
    with pytest.raises(InputError, match=r"reduced radius Ry \(across\) = inf m .*straight.*LineContact"):
        cc.PointContact(body1=cylinder, body2=flat, load="10 N")
    with pytest.raises(InputError, match="transverse_concave=True needs a transverse_radius"):
        cc.Body(material=STEEL, radius="10 mm", transverse_concave=True)
    with pytest.raises(InputError, match="a line contact is straight across"):
        cc.LineContact(body1=ball_on_flat().body1, body2=flat, load="10 N", length="5 mm")
    with pytest.raises(InputError, match="hertz = 'round'"):
        cc.Analysis(ball_on_flat(), models={"hertz": "round"})
    with pytest.raises(InputError, match="needs a point model"):
        cc.Analysis(ball_on_flat(), models={"film": "moes"})
    with pytest.raises(InputError, match="leaving out 'elasticity'"):
        cc.Analysis(ball_on_flat(), effects={"piezoviscosity"})
    with warnings.catch_warnings():
        warnings.simplefilter("error", ValidityWarning)
        with pytest.raises(ValidityWarning, match="PointContact.contact_stress_limit"):
            cc.Analysis(ball_on_flat(load="5 kN"), outputs=["p_h"], strict=True).run()


def test_plot_draws_the_numerical_pressure_beside_hertz(tmp_path):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    result = cc.Analysis(ball_on_flat(), models={"film": ["hamrock_dowson", "multigrid"]}).run()
    figure = result.plot()
    pressure, stress, film = figure.axes[:3]
    assert [line.get_label() for line in pressure.get_lines()][:3] == [
        "Hertz, along rolling (x)", "Hertz, across (y)", "multigrid: pressure"]
    assert stress.get_xlabel() == "stress / p_h [-]" and film.get_title() == "film thickness per model"
    figure.savefig(tmp_path / "point.png")
    with pytest.raises(InputError, match="panels \\['map'\\]"):
        result.plot(panels=("map",))


def test_the_tutorial_scene_file_is_this_contact():
    scene = cc.load_scene("tutorials/ball_on_flat_point_contact.toml")
    assert scene.kind == "point_contact" and scene.models["film"] == ["hamrock_dowson", "nijenbanning", "multigrid"]
    contact = scene.component
    assert contact.reduced_radii == ball_on_flat().reduced_radii and contact.si.load == 50.0
    result = cc.Analysis(contact, outputs=["h_min"]).run()
    assert result["h_min"] == pytest.approx(cc.Analysis(ball_on_flat(), outputs=["h_min"]).run()["h_min"], rel=1e-12)
