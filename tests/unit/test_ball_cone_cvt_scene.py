"""Ball-cone CVT scene: steps on demand, consistency of the chain, gross slip flagged, bad input named."""

import math

import numpy as np
import pytest

import camcontact as cc
from camcontact.contact.fastsim import fastsim
from camcontact.errors import InputError
from camcontact.models.life_lundberg_palmgren import system_life
from camcontact.sweep import evolve_path, sweep_frame

STEEL = cc.Material(E="207 GPa", nu=0.3)
# a traction fluid: its limiting shear stress rises as 0.088 p (Bair & Winer 1979, the polyphenyl ether 5P4E), not
# as a mineral oil's 0.047 p (the traction models' default)
FLUID = cc.Lubricant(name="traction fluid", nu40="30 cSt", nu100="5.5 cSt", density="0.90 g/cm^3",
                     alpha="2.5e-8 1/Pa", limiting_shear_slope=0.088)


def cvt(**changes):
    fields = dict(cone_angle="30 deg", cone_contact_radius="24 mm", ball_diameter="14 mm", ball_count=9,
                  tilt_max="30 deg", cam_ramp_angle="10 deg", cam_radius="6 mm", cam_ball_count=5, material=STEEL,
                  traction_coefficient=0.1, lubricant=FLUID, roughness="0.1 um")
    fields.update(changes)
    return cc.BallConeCVT(**fields)


def point(**changes):
    fields = dict(cvt=cvt(), power="150 W", input_speed="60 rpm", ratio=1.0, temperature="60 degC")
    fields.update(changes)
    return cc.LoadedBallConeCVT(**fields)


#: the thesis's dry creep theory (the scene's default traction model is the EHL film's, ehl_traction)
FASTSIM = {"traction": "fastsim"}


def test_only_the_needed_steps_run():
    assert cc.Analysis(point(), outputs=["psi_total"]).steps() == ["kinematics"]
    assert cc.Analysis(point(), outputs=["p_h"]).steps() == ["kinematics", "loads", "hertz"]
    assert "film" not in cc.Analysis(point(), outputs=["life_system"], models=FASTSIM).steps()
    # the EHL traction (default) shears the film: the life needs it through the traction's surface stresses
    assert cc.Analysis(point(), outputs=["life_system"]).steps() == [
        "kinematics", "loads", "hertz", "lubricant", "film", "traction", "stresses", "life"]
    assert cc.Analysis(point(), outputs=["efficiency"]).steps()[-1] == "losses"


def test_chain_is_consistent():
    """The FASTSIM creepage found transmits F_t (1e-9); the system life is the Weibull combination of
    the two cones and 9 balls x 2 tracks (Eq. 5.20); ball tracks turn once per ball revolution, cone
    tracks see 9 balls per revolution; the Hertz pressure is 3 N/(2 pi a b)."""
    result = cc.Analysis(point(ratio=1.5), models=FASTSIM).run()
    row = result.rows[0]
    shear = 207e9 / 2.6
    check = fastsim(row["a_rolling"], row["a_transverse"], row["normal_force"], 0.1, shear,
                    creepage_x=row["creepage_in"], spin=row["spin_in"])
    assert row["efficiency"] == pytest.approx(1 - 9 * (row["power_loss_in"] + row["power_loss_out"]) / 150.0)
    assert check.Fx == pytest.approx(row["tangential_force_in"], rel=1e-9)
    lives = [row["life_cone_in"], row["life_cone_out"]] + [row["life_ball_in"], row["life_ball_out"]] * 9
    assert row["life_system"] == pytest.approx(system_life(np.array(lives), 10 / 9), rel=1e-12)
    assert row["p_h"] == pytest.approx(1.5 * row["normal_force"] / (math.pi * row["a_rolling"] * row["a_transverse"]))
    assert row["output_speed"] == pytest.approx(2 * math.pi / 1.5)  # 60 rpm in, reduction 1.5
    assert row["Rx"] == pytest.approx(1 / (1 / 7e-3 + math.cos(math.radians(30)) / 24e-3)) and row["Ry"] == 7e-3


def test_symmetric_at_one_to_one():
    row = cc.Analysis(point(), models=FASTSIM).run().rows[0]
    for stem in ("psi", "h_min", "tau0", "z0", "slip_fraction"):
        assert row[f"{stem}_in"] == pytest.approx(row[f"{stem}_out"], rel=1e-9)
    assert row["life_cone_in"] == pytest.approx(row["life_cone_out"], rel=1e-9)


def test_gross_slip_is_flagged_and_finite():
    """Ratio 2 (reduction): the output contact needs 2 mu_min = 0.0441 (axial-balance clamping) > Ct = 0.04 ->
    gross slip flagged, traction saturated, everything finite."""
    row = cc.Analysis(point(ratio=2.0, cvt=cvt(traction_coefficient=0.04)), models=FASTSIM).run().rows[0]
    assert row["traction_check"].startswith("gross slip: the output contact needs F_t/F_n = 0.04408")
    assert row["traction_regime_out"].startswith("gross slip") and row["traction_regime_in"] == "partial slip"
    assert row["slip_fraction_out"] == 1.0
    assert all(np.isfinite(row[k]) for k in ("tau0_out", "z0_out", "life_system", "creepage_out"))


def test_spin_effect_can_be_switched_off():
    """Without spin the same force needs less slip (spin takes part of the adhesion)."""
    spinning = cc.Analysis(point(power="50 W"), outputs=["slip_fraction_in"], models=FASTSIM).run()
    plain = cc.Analysis(point(power="50 W"), outputs=["slip_fraction_in"], effects=["elasticity", "piezoviscosity"],
                        models=FASTSIM).run()
    assert plain["slip_fraction_in"] < spinning["slip_fraction_in"]


def test_model_slots_and_bad_input():
    table = cc.Analysis(point(), outputs=["a_rolling"], models={"hertz": ["exact", "timoshenko_table"]}).run()
    assert table["a_rolling"][1] == pytest.approx(table["a_rolling"][0], rel=3e-3)
    with pytest.raises(InputError, match="hertz = 'book'"):
        cc.Analysis(point(), models={"hertz": "book"})
    with pytest.raises(InputError, match="stress = 'tresca'"):
        cc.Analysis(point(), models={"stress": "tresca"})
    with pytest.raises(InputError, match="unknown model slots \\['friction'\\]"):
        cc.Analysis(point(), models={"friction": "kelley"})
    with pytest.raises(InputError, match="needs a LundbergPalmgren model"):
        cc.Analysis(point(), models={"life": "iso281"})
    with pytest.raises(InputError, match="do not apply to a ball_cone_cvt scene"):
        cc.Analysis(point(), effects=["compressibility"])
    with pytest.raises(InputError, match="needs a EhlTraction or Fastsim model"):
        cc.Analysis(point(), models={"traction": "eyring"})
    with pytest.raises(InputError, match="sigma: set BallConeCVT.roughness"):
        cc.Analysis(point(cvt=cvt(roughness=None)), outputs=["Lambda_in"])
    with pytest.raises(InputError, match="LoadedBallConeCVT.power"):
        point(power="0 W")


def test_sweep_frame_records_failed_cases_and_keeps_the_others():
    frame = sweep_frame(point(), {"ratio": [1.0, 3.0], "power": ["50 W", "100 W"]}, outputs=["normal_force"])
    assert len(frame) == 4 and list(frame.columns[:3]) == ["case", "ratio [-]", "power [W]"]
    failed = frame[frame["error"] != ""]
    assert set(failed["ratio [-]"]) == {3.0} and failed["error"].str.contains("needs a tilt beyond tilt_max").all()
    assert failed["error"].str.startswith("InputError: ").all() and set(failed["power [W]"]) == {50.0, 100.0}
    assert frame.loc[frame["error"] == "", "normal_force [N]"].notna().all()
    with pytest.raises(InputError, match="sweep path 'cvt.balls': BallConeCVT has no field 'balls'"):
        evolve_path(point(), "cvt.balls", 3)


def test_plot(tmp_path):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    figure = cc.Analysis(point(power="50 W"), models=FASTSIM).run().plot()
    assert len(figure.axes) == 5 and figure.axes[2].get_title() == "traction curves\nfastsim (parabolic)"
    assert figure.axes[2].get_xscale() == "log" and len(figure.axes[2].get_lines()) >= 6  # 2 x (spin, none, needed)
    figure.savefig(tmp_path / "cvt.png")
    # the EHL traction (default) and FASTSIM side by side: losses and lives of both variants
    both = cc.Analysis(point(), models={"traction": ["ehl_traction", "fastsim"]}).run()
    figure = both.plot(panels=("losses", "life"))
    assert len(figure.axes) == 2 and "efficiency" in figure.axes[0].get_legend().get_texts()[0].get_text()
    figure.savefig(tmp_path / "cvt_models.png")


def test_plot_of_the_ehl_traction_maps_the_film_shear(tmp_path):
    """The default (EHL) traction's contact panels: the film shear stress over the ellipse (a colour bar each),
    evaluated again with the variant's models; its traction map transmits the contact's force."""
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    result = cc.Analysis(point(power="50 W")).run()
    figure = result.plot(panels=("in", "out"))
    assert len(figure.axes) == 4 and "EHL traction, input contact" in figure.axes[0].get_title()
    figure.savefig(tmp_path / "cvt_ehl.png")
    again = cc.Analysis(point(power="50 W"), outputs=["traction_map_in", "tangential_force_in", "a_rolling",
                                                       "a_transverse"]).run()
    field, (a, b) = again["traction_map_in"], (again["a_rolling"], again["a_transverse"])
    cell = (2 * a / 40) * (2 * b / 40)  # the map's 41 x 41 lattice over the ellipse
    assert np.sum(field.tx) * cell == pytest.approx(again["tangential_force_in"], rel=0.05)  # F_x = int t_x dA


def test_ehl_traction_on_the_numerical_pressure():
    """film = multigrid: the traction is taken over the numerical pressure and film (step label says so); at a
    point the solver converges on 65^2 (3000 rpm, 150 W: M ~ 300, p_h 1.9 GPa) creepage, capacity and efficiency
    within 3 % of the Hertz pressure's. (A solution that does not converge: tests/unit/test_steps_traction.py.)"""
    from camcontact.models.film_multigrid_point import MultigridPoint

    outputs = ["creepage_in", "traction_capacity_in", "efficiency", "traction_valid_in"]
    scene = point(power="150 W", input_speed="3000 rpm")
    hertz = cc.Analysis(scene, outputs=outputs).run()
    numerical = cc.Analysis(scene, outputs=outputs, models={"film": MultigridPoint(levels=3)}).run()
    assert any(r.model == "ehl_traction (eyring, numerical pressure)" for r in numerical.records)
    for name in outputs[:3]:
        assert numerical[name] == pytest.approx(hertz[name], rel=0.03) and numerical[name] != hertz[name]
    assert numerical["traction_valid_in"]


def test_lives_in_cycles_and_hours_agree():
    """Hours = cycles / (stress cycles per revolution x speed) (Eq. 5.18): 9 per cone revolution at 60 rpm,
    one per ball revolution."""
    row = cc.Analysis(point(ratio=1.5)).run().rows[0]
    assert row["life_cone_in"] == pytest.approx(row["cycles_cone_in"] / (9 * 1.0), rel=1e-12)
    assert row["life_cone_out"] == pytest.approx(row["cycles_cone_out"] / (9 * row["output_speed"] / (2 * math.pi)))
    assert row["life_ball_in"] == pytest.approx(row["cycles_ball_in"] / (row["ball_speed"] / (2 * math.pi)))
