"""Issue 21 (user experience): units as engineers write them, quantities with units, Jupyter displays, the list
of outputs a scene can give (API and CLI), the top-level exports, LICENSE and py.typed."""

import subprocess
import sys
from pathlib import Path

import attrs
import pytest

import camcontact as cc
from camcontact.cli import main
from camcontact.errors import InputError
from camcontact.report import unexplained_values, unit_label
from camcontact.scene_file import load_scene

ROOT = Path(__file__).resolve().parents[2]
STEEL = cc.Material(E="210 GPa", nu=0.3)


def contact():
    return cc.LineContact(body1=cc.Body(material=STEEL, radius="20 mm"), body2=cc.Body(material=STEEL, radius="10 mm"),
                          load="1 kN", length="10 mm")


@pytest.mark.parametrize("unit, label", [
    ("N*m", "N·m"), ("W/(m*K)", "W/(m·K)"), ("J/(kg*K)", "J/(kg·K)"), ("mm^2/s", "mm²/s"), ("m**3", "m³"),
    ("um", "µm"), ("degC", "°C"), ("", "-"), ("Mrev", "Mrev"), ("W s^0.5/(m^2 K)", "W·s^0.5/(m²·K)"), ("1/GPa", "1/GPa"),
    ("W / (m*K)", "W/(m·K)"), ("mm ** 2", "mm²"), ("micron", "µm"), ("dimensionless", "-"), ("kg m^-3", "kg·m⁻³"),
])
def test_unit_labels_keep_the_order_engineers_write(unit, label):
    assert unit_label(unit) == label


def test_unit_labels_read_back_as_their_units():
    """A column label is a unit pint reads again (report_export.to_pint_frame does): the same quantity."""
    for unit in ("W / (m*K)", "mm ** 2", "W s^0.5/(m^2 K)", "kg m^-3", "N*m", "micron", "degC"):
        assert cc.Q_(1.0, unit_label(unit)).to(unit).magnitude == pytest.approx(1.0)


def test_unknown_unit_is_named():
    with pytest.raises(InputError, match="unknown unit 'furlong_per_fortnite'"):
        unit_label("furlong_per_fortnite")


def test_quantity_returns_pint_values_in_the_report_unit_or_the_one_asked_for():
    result = cc.Analysis(contact(), outputs=["p_h", "b"]).run()
    p_h = result.quantity("p_h")
    assert isinstance(p_h, cc.ureg.Quantity) and str(p_h.units) == "megapascal"
    assert p_h.to("Pa").magnitude == pytest.approx(result["p_h"], rel=1e-12)
    assert result.quantity("b", "um").magnitude == pytest.approx(1e6 * result["b"], rel=1e-12)
    with pytest.raises(InputError, match="Result.quantity: p_h \\[Pa\\] in unit = 'kg'"):
        result.quantity("p_h", "kg")
    with pytest.raises(KeyError, match="h_min"):
        result.quantity("h_min")


def test_quantity_per_variant_and_text_outputs_as_they_are():
    scene = load_scene(ROOT / "tutorials" / "pellet_mill_line_contact.toml")
    result = cc.Analysis(scene.component, outputs=["h_c"], models={"film": ["moes", "grubin"]}).run()
    films = result.quantity("h_c", "nm")
    assert len(films) == 2 and all(f.units == cc.ureg.nanometer for f in films)
    assert films[0].magnitude == pytest.approx(1e9 * result["h_c"][0], rel=1e-12)
    cam = cc.Analysis(load_scene(None).component, outputs=["jump"]).run()
    assert isinstance(cam.quantity("jump"), str)


def test_the_bearing_lives_are_shown_in_millions_of_revolutions():
    scene = load_scene(ROOT / "tutorials" / "pellet_mill_bearing.toml").component
    result = cc.Analysis(scene, outputs=["L10", "L10h"]).run()
    frame = result.summary_frame()  # per roller: to_frame(); the bearing's scalars: summary_frame()
    assert frame.loc[0, "L10 [Mrev]"] == pytest.approx(result["L10"] / 1e6, rel=1e-12)
    assert result.quantity("L10").to("rev_count").magnitude == pytest.approx(result["L10"], rel=1e-12)
    with pytest.raises(InputError, match="L10 \\[revolution_count\\] in unit = 'revolution'"):
        result.quantity("L10", "revolution")  # an angle (2 pi rad), not a count: refused, not off by 2 pi


def test_results_components_and_analyses_show_their_values():
    result = cc.Analysis(contact(), outputs=["p_h", "b"]).run()
    text = repr(result)
    assert text.startswith("<Result of a line_contact scene") and "p_h [MPa]" in text and "742.2" in text
    html = result._repr_html_()
    assert "<table" in html and "p_h [MPa]" in html and "<summary>steps</summary>" in html and "hertz" in html
    cam = load_scene(None).analysis().run()
    html = cam._repr_html_()
    assert "h_min_cycle [µm]" in html and "per cam_angle (360 rows" in html
    assert "per cam_angle: to_frame()" in repr(cam)
    component = contact()._repr_html_()
    assert "<b>LineContact</b>" in component and "1 kN" in component and "<details><summary>Body" in component
    assert repr(cc.Analysis(contact())).startswith("<Analysis of a line_contact scene: steps ")


def test_available_outputs_lists_what_a_scene_can_give_and_what_the_rest_needs():
    analysis = load_scene(None).analysis()
    table = analysis.available_outputs()
    assert list(table.columns) == ["output", "unit", "description", "step", "default", "per_index", "available",
                                   "missing"]
    by = table.set_index("output")
    # every output of the default report is listed as a default, available output
    planned = set(analysis.run().outputs) - {"cam_angle"}
    assert planned <= set(by.index[by["default"] & by["available"]])
    assert by.loc["h_min", "per_index"] and not by.loc["h_min_cycle", "per_index"] and by.loc["h_min", "unit"] == "µm"
    wear = by.loc["wear_rate"]
    assert not wear["available"] and "Material.hardness" in wear["missing"]
    with pytest.raises(InputError, match="variant 'grubin'"):
        analysis.available_outputs("grubin")


def test_cli_outputs_prints_the_list(capsys):
    assert main(["outputs"]) == 0
    out = capsys.readouterr().out
    assert "LS-1" in out and "h_min_cycle" in out and "need more input (3):" in out and "wear_rate" in out
    assert main(["outputs", str(ROOT / "tutorials" / "forti_ball_cone_cvt.toml")]) == 0
    assert "traction_margin_in" in capsys.readouterr().out
    assert main(["outputs", "no_such_scene.toml"]) == 2


def test_user_facing_classes_are_exported_and_the_import_stays_cheap():
    for name in ("MotionProgram", "Segment", "load_scene", "sweep_frame", "cvt_map", "stribeck_sweep"):
        assert name in cc.__all__ and hasattr(cc, name) and name in dir(cc)
    with pytest.raises(AttributeError, match="no attribute 'Nope'"):
        cc.Nope  # noqa: B018
    code = "import sys, camcontact; print('numba' in sys.modules, 'camcontact.kinematics.motion_program' in sys.modules)"
    assert subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split() == [
        "False", "False"]


def test_license_and_typing_marker_ship():
    assert "MIT License" in (ROOT / "LICENSE").read_text()
    assert (ROOT / "camcontact" / "py.typed").exists()
    assert '"camcontact" = ["py.typed"]' in (ROOT / "pyproject.toml").read_text()


def test_cli_quiet_and_verbose(tmp_path, capsys):
    import logging

    from camcontact.cli import _configure_logging

    csv = tmp_path / "quiet.csv"
    assert main(["run", "-q", "--csv", str(csv)]) == 0
    captured = capsys.readouterr()
    assert captured.out == "" and csv.stat().st_size > 0
    logger = logging.getLogger("camcontact")
    before = (logger.level, list(logger.handlers))
    try:
        assert main(["-v", "run", "--csv", str(tmp_path / "loud.csv")]) == 0
        err = capsys.readouterr().err
        assert "camcontact: step kinematics (roller follower" in err and "camcontact: step normal_force ran in" in err
        assert (logger.level, list(logger.handlers)) == before  # main() leaves the logger as it found it
    finally:
        _configure_logging(0)
        logger.setLevel(before[0])
    assert main(["run", "-v", "-q"]) == 2
    assert "-v and -q: choose one" in capsys.readouterr().err
    # the listing commands only print: -q there is refused, not silently ignored
    for argv in (["-q", "plugins"], ["outputs", "-q"], ["default-scene", "--quiet"]):
        assert main(argv) == 2
        captured = capsys.readouterr()
        assert captured.out == "" and f"-q with {argv[-1] if argv[0] == '-q' else argv[0]}" in captured.err


def test_cam_plot_is_a_grid_of_every_panel_and_draws_on_the_callers_axes(tmp_path):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    result = cc.load_scene().analysis().run()
    figure = result.plot()
    titles = [ax.get_title() for ax in figure.axes]
    # the default report has what the README promises: SVAJ with jerk, the profile, the force breakdown, Lambda
    for title in ("SVAJ diagram", "cam profile (contact points)", "contact force", "film parameter"):
        assert title in titles
    width, height = figure.get_size_inches()
    assert width / height < 2.0  # a grid, not one strip
    svaj = figure.axes[titles.index("SVAJ diagram")]
    assert any("j [" in text.get_text() for text in svaj.get_legend().get_texts())
    figure.savefig(tmp_path / "cam.png")
    fig, axes = plt.subplots(1, 2)
    assert result.plot(panels=("lambda", "pressure"), ax=axes) is fig and axes[0].get_title() == "film parameter"
    own = plt.figure()
    assert result.plot(panels=("film",), fig=own) is own and len(own.axes) == 1
    with pytest.raises(InputError, match="ax= gives 2 axes for 1 panels"):
        result.plot(panels=("film",), ax=axes)
    with pytest.raises(InputError, match="give ax= or fig=, not both"):
        result.plot(panels=("film",), ax=axes[0], fig=own)
    with pytest.raises(InputError, match="fig= already has 1 axes"):
        result.plot(panels=("film",), fig=own)  # a second call would stack its panels on the first's
    with pytest.raises(InputError, match="figsize= with fig="):
        result.plot(panels=("film",), fig=plt.figure(), figsize=(4, 3))
    left, right = plt.figure().subfigures(1, 2)
    result.plot(panels=("film",), fig=left)
    result.plot(panels=("lambda",), fig=right)
    assert [ax.get_title() for ax in left.figure.axes] == ["film over the cycle", "film parameter"]
    plt.close("all")


def test_run_says_it_runs_the_base_case_of_a_sweep_file(tmp_path, capsys):
    scene = ROOT / "tutorials" / "ls1_speed_sweep.toml"
    assert main(["run", str(scene), "--csv", str(tmp_path / "base.csv")]) == 0
    out = capsys.readouterr().out
    assert "[sweep] table of 9 cases over speed, follower.roller_radius: this runs the base case; camcontact sweep" in out
    assert "th row" not in out  # the per-angle table says "one row in N of M", not "every 2th row"


def test_every_scene_plot_takes_the_callers_axes(tmp_path):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    bearing = cc.Analysis(load_scene(ROOT / "tutorials" / "pellet_mill_bearing.toml").component).run()
    fig = plt.figure()
    axes = [fig.add_subplot(1, 2, 1, projection="polar"), fig.add_subplot(1, 2, 2)]
    assert bearing.plot(panels=("load", "film"), ax=axes) is fig and axes[0].get_title() == "roller load Q [kN]"
    flat = plt.subplots(1, 2)[1]
    with pytest.raises(InputError, match="a panel needs a polar Axes, got a rectilinear one"):
        bearing.plot(panels=("load", "film"), ax=flat)
    for name in ("pellet_mill_line_contact", "pellet_mill_raceway_contact", "forti_ball_cone_cvt"):
        scene = load_scene(ROOT / "tutorials" / f"{name}.toml")
        result = scene.analysis().run()
        figure = result.plot()
        figure.savefig(tmp_path / f"{name}.png")
        own = plt.figure()
        assert result.plot(fig=own) is own and len(own.axes) == len(figure.axes)  # panels and colour bars
    plt.close("all")


def test_status_is_data_beside_its_reason():
    """Booleans for the status, text only as the reason: the cam film's validity per angle (the reason names
    the film model), the line film's, the CVT's traction need against Ct."""
    cam = cc.Analysis(load_scene().component).run().to_frame()
    assert cam["film_valid"].dtype == bool and cam["film_valid"].all() and (cam["film_regime"] == "ok").all()
    contact = load_scene(ROOT / "tutorials" / "pellet_mill_line_contact.toml").component
    light = attrs.evolve(contact, load="10 N")  # W' far below Pan-Hamrock's fitted range
    line = cc.Analysis(light, outputs=["film_valid", "film_validity"], models={"film": ["moes", "pan_hamrock"]}).run()
    assert line["film_valid"] == [True, False]
    assert line["film_validity"][1].startswith("pan_hamrock: W = ")
    cvt = load_scene(ROOT / "tutorials" / "forti_ball_cone_cvt.toml").component
    for ct, sufficient in ((0.095, True), (0.05, False)):
        scene = attrs.evolve(cvt, cvt=attrs.evolve(cvt.cvt, traction_coefficient=ct))
        result = cc.Analysis(scene, outputs=["traction_sufficient", "traction_check"]).run()
        assert result["traction_sufficient"] is sufficient
        assert result["traction_check"].startswith("ok" if sufficient else "gross slip")


def test_gridded_sweeps_become_labelled_arrays_with_numeric_angles_and_summaries():
    """A cam study over speed x roller radius: per-angle rows carry their case's cycle summaries (one call), the
    swept angles are numbers, and to_xarray gives a Dataset over (speed, roller radius, cam angle) with units."""
    pytest.importorskip("xarray")
    follower = load_scene().component
    frame = cc.Analysis(follower, outputs=["h_min", "h_min_cycle"]).sweep(
        {"speed": ["1000 rpm", "3000 rpm"], "follower.roller_radius": ["12 mm", "15 mm"]}, progress=False)
    assert frame.attrs["dimensions"] == ["speed [rpm]", "follower.roller_radius [mm]", "cam_angle [deg]"]
    per_case = frame.groupby("case")
    assert (per_case["h_min_cycle [µm]"].nunique() == 1).all()  # the case's summary on each of its rows
    assert per_case["h_min [µm]"].min().to_numpy() == pytest.approx(per_case["h_min_cycle [µm]"].first().to_numpy())
    ds = cc.to_xarray(frame)
    assert dict(ds.sizes) == {"speed": 2, "follower.roller_radius": 2, "cam_angle": 360}
    assert ds["h_min"].attrs["units"] == "µm" and ds["speed"].attrs["units"] == "rpm"
    # the summary does not vary along the cam angle: kept without it, one number per case
    assert ds["h_min_cycle"].dims == ("speed", "follower.roller_radius") and ds["h_min"].dims[-1] == "cam_angle"
    fast = float(ds["h_min_cycle"].sel(speed=3000.0, **{"follower.roller_radius": 15.0}))
    slow = float(ds["h_min_cycle"].sel(speed=1000.0, **{"follower.roller_radius": 15.0}))
    assert fast > slow
    read_back = frame.copy()
    read_back.attrs = {}  # as read_sweep gives it from a CSV file: the dimensions are named by hand
    with pytest.raises(InputError, match="give dims="):
        cc.to_xarray(read_back)
    assert dict(cc.to_xarray(read_back, dims=frame.attrs["dimensions"]).sizes) == dict(ds.sizes)
    with pytest.raises(InputError, match="rows repeat a combination"):
        cc.to_xarray(frame, dims=["speed [rpm]"])
    cvt = load_scene(ROOT / "tutorials" / "forti_ball_cone_cvt.toml").component
    angles = cc.sweep_frame(cvt, {"cvt.cone_angle": ["25 deg", "30 deg"]}, outputs=["efficiency"], progress=False)
    assert angles["cvt.cone_angle [deg]"].tolist() == [25.0, 30.0]
    raceway = load_scene(ROOT / "tutorials" / "pellet_mill_raceway_contact.toml").component
    slip = cc.sweep_frame(raceway, {"slide_roll_ratio": ["5 %", "10 %"]}, outputs=["h_min"], progress=False)
    assert slip["slide_roll_ratio [%]"].tolist() == [5.0, 10.0] and slip["error"].eq("").all()


def test_xarray_of_a_cam_study_keeps_failures_and_summaries_without_the_angle():
    pytest.importorskip("xarray")
    follower = load_scene().component
    # the default report of two film models, one of which (grubin) gives no h_min: NaN with its reason
    frame = cc.Analysis(follower, models={"film": ["pan_hamrock", "grubin"]}).sweep(
        {"speed": ["1000 rpm", "0 rpm", "3000 rpm"]}, progress=False)
    assert unexplained_values(frame) == []  # the summary's not_given joined to the per-angle rows'
    assert frame.loc[frame["variant"] == "grubin", "not_given"].str.contains("h_min_cycle").all()
    ds = cc.to_xarray(frame)
    assert set(ds.dims) == {"speed", "variant", "cam_angle"} and ds["h_min_cycle"].dims == ("speed", "variant")
    assert float(ds["h_min_cycle"].sel(speed=3000.0, variant="pan_hamrock")) > 0
    assert len(ds.attrs["failed_cases"]) == 1 and ds.attrs["failed_cases"][0].startswith("case 1: ")


def test_quiet_sweep_still_says_which_cases_failed(tmp_path, capsys):
    text = (ROOT / "tutorials" / "forti_ball_cone_cvt.toml").read_text(encoding="utf-8")
    scene = tmp_path / "swept.toml"
    scene.write_text(text + '\n[sweep]\nratio = [1.0, 3.0]\n', encoding="utf-8")  # 3:1 needs a tilt beyond 30 deg
    assert main(["sweep", str(scene), "-q", "--csv", str(tmp_path / "swept.csv")]) == 0
    captured = capsys.readouterr()
    assert captured.out == "" and "camcontact: warning: 1 of 2 cases failed" in captured.err


def test_sweep_plot_draws_each_output_against_the_first_swept_value(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from camcontact.sweep_plot import plot_sweep

    png = tmp_path / "study.png"
    assert main(["sweep", str(ROOT / "tutorials" / "ls1_speed_sweep.toml"), "--csv", str(tmp_path / "s.csv"),
                 "--plot", str(png), "--no-progress"]) == 0
    assert png.stat().st_size > 0 and f"plot written to {png}" in capsys.readouterr().out
    frame = cc.Analysis(load_scene().component, outputs=["h_min", "h_min_cycle", "p_h_max"]).sweep(
        {"speed": ["1000 rpm", "2000 rpm"], "follower.roller_radius": ["12 mm", "15 mm"]}, progress=False)
    figure = plot_sweep(frame)
    # per-angle table: plotted by its cases' summaries; one line per roller radius, two points each
    titles = [ax.get_title() for ax in figure.axes]
    assert titles == ["h_min_cycle", "p_h_max"]  # h_min varies along the cam angle: not a case's value
    lines = figure.axes[0].get_lines()
    assert len(lines) == 2 and all(len(line.get_xdata()) == 2 for line in lines)
    assert [t.get_text() for t in figure.axes[0].get_legend().get_texts()] == [
        "follower.roller_radius 12 mm", "follower.roller_radius 15 mm"]
    with pytest.raises(InputError, match="x = 'load' is not a column"):
        plot_sweep(frame, x="load")
    with pytest.raises(InputError, match="numeric output columns"):
        plot_sweep(frame, outputs=["jump"])
    plt.close("all")
