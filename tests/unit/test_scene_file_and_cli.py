"""TOML scenes (no code execution) and the camcontact command."""

import math
from pathlib import Path

import pandas as pd
import pytest

from camcontact.cli import main
from camcontact.errors import InputError
from camcontact.scene_file import default_scene_text, load_scene, parse_scene

MINIMAL = """
scene = "line_contact"
outputs = ["b", "p_h"]
[contact]
load = "1 kN"
length = "10 mm"
[contact.body1]
radius = "20 mm"
[contact.body1.material]
E = "210 GPa"
nu = 0.3
[contact.body2]
radius = "10 mm"
[contact.body2.material]
E = "210 GPa"
nu = 0.3
"""


def test_minimal_scene_runs():
    scene = parse_scene(MINIMAL)
    result = scene.analysis().run()
    assert result.outputs == ("b", "p_h")


@pytest.mark.parametrize(
    "edit, pattern",
    [
        (("radius = \"20 mm\"", "radiu = \"20 mm\""), r"\[contact\]\.body1: unknown keys \['radiu'\].*allowed: concave, material"),
        (("E = \"210 GPa\"", "E = 210"), r"Material\.E = 210.*bare number"),
        (("scene = \"line_contact\"", "scene = \"gearbox\""), "known scene kinds: line_contact, cam_follower"),
        (("load = \"1 kN\"", "load = \"1 kN\"\nextra = 3"), r"unknown keys \['extra'\]"),
        (("outputs = [\"b\", \"p_h\"]", "outputs = \"b\""), "outputs must be a list"),
        (("[contact]", "[contact\n"), "not valid TOML"),
    ],
)
def test_scene_errors_name_the_key(edit, pattern):
    with pytest.raises(InputError, match=pattern):
        parse_scene(MINIMAL.replace(*edit))


def test_scene_strings_are_never_executed():
    hostile = MINIMAL.replace('load = "1 kN"', 'load = "__import__(\'os\').system(\'echo pwned\')"')
    with pytest.raises(InputError):
        parse_scene(hostile)


PELLET_MILL = Path(__file__).parents[2] / "tutorials" / "pellet_mill_line_contact.toml"


def test_pellet_mill_scene(tmp_path, capsys):
    csv = tmp_path / "report.csv"
    assert main(["run", str(PELLET_MILL), "--csv", str(csv)]) == 0
    out = capsys.readouterr().out
    assert "steps ran in" in out and "Delabenetta" in out
    frame = pd.read_csv(csv)
    assert list(frame["variant"]) == ["grubin", "dowson_higginson", "dowson_toyoda", "pan_hamrock", "moes"]
    # Hertz half-width and peak pressure of Delabenetta (2021) Table 7: 186 um and 826.67 MPa
    assert frame["b [µm]"][0] == pytest.approx(186.24, abs=0.01)
    assert frame["p_h [MPa]"][0] == pytest.approx(826.67, abs=0.01)


def test_cli_scene_file_units_and_plot(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    path = tmp_path / "s.toml"
    path.write_text(MINIMAL)
    png = tmp_path / "s.png"
    assert main(["run", str(path), "--csv", str(tmp_path / "r.csv"), "--units", "p_h=GPa", "--plot", str(png)]) == 0
    assert "p_h [GPa]" in capsys.readouterr().out
    assert png.stat().st_size > 1000


def test_cli_reports_input_errors_with_exit_code_2(tmp_path, capsys):
    path = tmp_path / "bad.toml"
    path.write_text(MINIMAL.replace('E = "210 GPa"', 'E = "210 mm"'))
    assert main(["run", str(path)]) == 2
    assert "Material.E = 210" in capsys.readouterr().err
    assert main(["run", str(tmp_path / "missing.toml")]) == 2
    assert main(["run", str(path), "--units", "p_h"]) == 2


def test_default_scene_is_printable_and_loads(capsys):
    assert main(["default-scene"]) == 0
    assert capsys.readouterr().out == default_scene_text()
    assert load_scene().kind == "cam_follower"


def test_default_scene_is_the_ls1_cam_cycle(tmp_path, capsys):
    """The main job: the LS-1 roller valve train of Tsuha (2015) at 1000 rpm, every degree. Its nose
    force 3087.99 N and k_min 9.42e4 N/m at 3000 rpm are the thesis's (Tables 6.3, §6.1); the rest is
    checked in tests/literature/test_tsuha_cam_cycle.py."""
    csv = tmp_path / "cam.csv"
    assert main(["run", "--csv", str(csv)]) == 0
    out = capsys.readouterr().out
    assert "LS-1" in out and "cycle summary" in out and "steps ran in" in out
    frame = pd.read_csv(csv)
    assert len(frame) == 360 and frame["cam_angle [deg]"].iloc[90] == pytest.approx(90.0)
    assert frame["contact_force [N]"].iloc[90] == pytest.approx(3087.99, abs=0.01)
    assert frame["h_min [µm]"].notna().all() and (frame["film_regime"] == "ok").all()
    summary = pd.read_csv(tmp_path / "cam_summary.csv")
    assert summary["k_min [N/m]"][0] == pytest.approx(9.42e4, rel=2e-3)
    assert summary["jump"][0].startswith("no jump")


def test_cam_scene_file_errors_name_the_key():
    text = default_scene_text().replace('law = "P-2"', 'law = "P-9"')
    with pytest.raises(InputError, match="P-9"):
        parse_scene(text)
    text = default_scene_text().replace('base_radius = "40 mm"', 'base_radius = "40 mm"\nradius = 3')
    with pytest.raises(InputError, match=r"\[contact\]\.cam: unknown keys \['radius'\]"):
        parse_scene(text)


TUTORIALS = Path(__file__).parents[2] / "tutorials"


def test_raceway_contact_scene_file_runs_both_conventions(tmp_path, capsys):
    """The pellet-mill contact file: thesis and corrected rows; the thesis row gives Table 8's
    Lambda = 5.181 and T_maxL = 130.5 °C (Delabenetta 2021), the corrected row Lambda about 2."""
    csv = tmp_path / "raceway.csv"
    assert main(["run", str(TUTORIALS / "pellet_mill_raceway_contact.toml"), "--csv", str(csv)]) == 0
    frame = pd.read_csv(csv)
    assert list(frame["variant"]) == ["thesis", "corrected"]
    assert round(frame["Lambda_oc [-]"][0], 3) == 5.181
    assert round(frame["lubricant_temperature_max [°C]"][0], 1) == 130.5
    assert frame["h_c [µm]"][0] == pytest.approx(1.369, abs=5e-4)  # report units from the file
    assert 1.5 < frame["Lambda_oc [-]"][1] < 2.5 and frame["regime"][1] == "mixed"


def test_bearing_scene_file_runs(tmp_path, capsys):
    csv = tmp_path / "bearing.csv"
    assert main(["run", str(TUTORIALS / "pellet_mill_bearing.toml"), "--csv", str(csv)]) == 0
    frame = pd.read_csv(csv)
    assert len(frame) == 50 and "Q [kN]" in frame
    summary = pd.read_csv(tmp_path / "bearing_summary.csv")
    assert summary["Q_max [kN]"][0] == pytest.approx(10.0, rel=0.02)  # the load was chosen for it
    assert summary["L_nmh [h]"][0] > 0


def test_bearing_and_raceway_scene_errors_name_the_key():
    text = (TUTORIALS / "pellet_mill_bearing.toml").read_text(encoding="utf-8")
    with pytest.raises(InputError, match=r"\[contact\]\.bearing: unknown keys \['osculation'\]"):
        parse_scene(text.replace('roughness = "0.23 um"', 'roughness = "0.23 um"\nosculation = 0.97'))
    text = (TUTORIALS / "pellet_mill_raceway_contact.toml").read_text(encoding="utf-8")
    with pytest.raises(InputError, match="RacewayContact.raceway = 'left'"):
        parse_scene(text.replace('raceway = "outer"', 'raceway = "left"'))


def test_ball_cone_cvt_scene_file_runs(tmp_path, capsys):
    """The Forti CVT file: two Hertz variants (exact, Tabela 3.1) agree to 0.3 % on the semi-axes;
    mu_min = tan(10 deg) 6/(sin(30 deg) 24) = 0.088163 (Saccheto Eq. 6.19)."""
    csv = tmp_path / "cvt.csv"
    assert main(["run", str(TUTORIALS / "forti_ball_cone_cvt.toml"), "--csv", str(csv)]) == 0
    frame = pd.read_csv(csv)
    assert list(frame["variant"]) == ["exact", "timoshenko_table"]
    assert frame["a_rolling [µm]"][1] == pytest.approx(frame["a_rolling [µm]"][0], rel=3e-3)
    assert frame["mu_min [-]"][0] == pytest.approx(math.tan(math.radians(10)) * 6 / (0.5 * 24), rel=1e-6)
    assert "h_min_in [nm]" in frame


def test_cli_sweep_serial_and_on_two_workers_give_the_same_table(tmp_path, capsys):
    """`camcontact sweep` over the [sweep] table of tutorials/ls1_speed_sweep.toml (3 speeds x 3 roller
    radii): 9 rows, the same serially and on 2 worker processes; a larger roller lowers the peak
    pressure (Hertz, p ~ R^-1/2 at equal load) at every speed."""
    serial, pooled = tmp_path / "serial.csv", tmp_path / "pooled.csv"
    scene = str(TUTORIALS / "ls1_speed_sweep.toml")
    assert main(["sweep", scene, "--csv", str(serial), "--no-progress"]) == 0
    assert main(["sweep", scene, "--workers", "2", "--csv", str(pooled), "--no-progress"]) == 0
    a, b = pd.read_csv(serial), pd.read_csv(pooled)
    pd.testing.assert_frame_equal(a, b)
    assert len(a) == 9 and list(a.columns[:3]) == ["case", "speed [rpm]", "follower.roller_radius [mm]"]
    for _, group in a.groupby("speed [rpm]"):
        assert (group.sort_values("follower.roller_radius [mm]")["p_h_max [MPa]"].diff().dropna() < 0).all()
    assert "9 rows (0 failed cases)" in capsys.readouterr().out


def test_sweep_table_errors_are_named(tmp_path):
    text = (TUTORIALS / "ls1_speed_sweep.toml").read_text(encoding="utf-8")
    with pytest.raises(InputError, match="sweep path 'follower.radius': Follower has no field 'radius'"):
        parse_scene(text.replace('"follower.roller_radius" =', '"follower.radius" ='))
    with pytest.raises(InputError, match=r"\[sweep\] must be a table of path = \[value, ...\]"):
        parse_scene(text.replace('speed = ["500 rpm", "1500 rpm", "3000 rpm"]', 'speed = "500 rpm"'))
    plain = tmp_path / "plain.toml"
    plain.write_text(default_scene_text(), encoding="utf-8")
    assert main(["sweep", str(plain)]) == 2


# ------------------------------------------------------------------ reliability of the command (issue 18)
LINE_SCENE = MINIMAL.replace('outputs = ["b", "p_h"]', 'outputs = ["b", "p_h"]\n[report]\nunits = { b = "um" }')


def _scene_file(tmp_path, text=LINE_SCENE, name="s.toml"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return str(path)


@pytest.mark.parametrize("units", [["--units", "p_h=GPa", "--units", "b=mm"], ["--units", "p_h=GPa,b=mm"],
                                   ["--units", " p_h = GPa , b = mm "]])
def test_cli_units_repeated_or_comma_separated_before_or_after_the_scene(tmp_path, capsys, units):
    scene, csv = _scene_file(tmp_path), str(tmp_path / "r.csv")
    for argv in (["run", *units, scene, "--csv", csv], ["run", scene, "--csv", csv, *units]):
        assert main(argv) == 0
        assert list(pd.read_csv(csv).columns) == ["b [mm]", "p_h [GPa]"]
    assert "steps ran in" in capsys.readouterr().out


def test_cli_checks_units_and_paths_before_running(tmp_path, capsys, monkeypatch):
    """A bad unit or output path is refused before the analysis runs (no long run wasted)."""
    from camcontact.analysis import Analysis

    def never(self):
        raise AssertionError("the analysis ran")

    monkeypatch.setattr(Analysis, "run", never)
    scene = _scene_file(tmp_path)
    for extra, message in [(["--units", "p_h=mm"], "--units: p_h = 'mm' has dimension [length]; p_h is [Pa]"),
                           (["--units", "h_min=nm"], "--units: 'h_min' is not an output of this analysis; outputs: b, p_h"),
                           (["--csv", str(tmp_path / "no" / "r.csv")], "the directory"),
                           (["--plot", str(tmp_path)], "is a directory")]:
        assert main(["run", scene, *extra]) == 2
        err = capsys.readouterr().err
        assert err.startswith("camcontact: error: ") and message in err and err.count("\n") == 1
    bad = _scene_file(tmp_path, LINE_SCENE.replace('b = "um"', 'b = "GPa"'), "bad.toml")
    assert main(["run", bad]) == 2
    assert "bad.toml [report] units: b = 'GPa' has dimension" in capsys.readouterr().err


def test_cli_exit_codes_and_debug(tmp_path, capsys, monkeypatch):
    """2 bad input, 1 a failure while running (its type and message, a hint at --debug), 130 Ctrl-C; --debug
    (before or after the command) prints the traceback too."""
    from camcontact.analysis import Analysis

    scene = _scene_file(tmp_path)
    assert main(["run", str(tmp_path / "missing.toml")]) == 2
    assert capsys.readouterr().err.count("\n") == 1
    for argv in (["--debug", "run", str(tmp_path / "missing.toml")], ["run", str(tmp_path / "missing.toml"), "--debug"]):
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert "Traceback" in err and err.splitlines()[-1].startswith("camcontact: error: cannot read scene file")

    def boom(self):
        raise ZeroDivisionError("float division by zero")

    monkeypatch.setattr(Analysis, "run", boom)
    assert main(["run", scene, "--csv", str(tmp_path / "r.csv")]) == 1
    assert capsys.readouterr().err == ("camcontact: error: ZeroDivisionError: float division by zero (run with --debug "
                                       "for the traceback)\n")

    def interrupted(self):
        raise KeyboardInterrupt

    monkeypatch.setattr(Analysis, "run", interrupted)
    assert main(["run", scene, "--csv", str(tmp_path / "r.csv")]) == 130
    assert capsys.readouterr().err == "camcontact: error: interrupted\n"
    assert main(["--help"]) == 0 and main(["run", "--help"]) == 0
    assert main([]) == 2
    assert capsys.readouterr().err.startswith("camcontact: error: the following arguments are required: command")


def test_scene_file_reading_is_bounded(tmp_path):
    """Regular UTF-8 files of at most MAX_SCENE_BYTES (a UTF-8 byte-order mark is skipped); nesting at most
    MAX_NESTING; a [sweep] of at most MAX_SWEEP_CASES cases — refused before anything is built."""
    from camcontact.scene_file import MAX_NESTING, MAX_SCENE_BYTES, MAX_SWEEP_CASES

    bom = tmp_path / "bom.toml"
    bom.write_bytes(b"\xef\xbb\xbf" + MINIMAL.encode())
    assert load_scene(bom).kind == "line_contact"
    latin = tmp_path / "latin.toml"
    latin.write_bytes(MINIMAL.replace("1 kN", "1 kN  # °").encode("latin-1"))
    with pytest.raises(InputError, match=r"latin.toml: not UTF-8 text: byte 0xb0 at byte offset \d+ \(line 5\)"):
        load_scene(latin)
    big = tmp_path / "big.toml"
    big.write_bytes(b"#" * (MAX_SCENE_BYTES + 1))
    with pytest.raises(InputError, match=f"allowed: at most {MAX_SCENE_BYTES}"):
        load_scene(big)
    with pytest.raises(InputError, match="is not a regular file"):
        load_scene("/dev/zero")
    with pytest.raises(InputError, match="nested too deep"):
        parse_scene("x = " + "[" * 10_000 + "]" * 10_000)
    with pytest.raises(InputError, match=f"nested deeper than {MAX_NESTING}"):
        parse_scene(MINIMAL + "\n[contact.lubricant]\n" + "x = " + "[" * 20 + "]" * 20)
    grid = "\n[sweep]\n" + "\n".join(f'"body{k}.radius" = [' + ", ".join(['"1 mm"'] * 400) + "]" for k in (1, 2))
    with pytest.raises(InputError, match=f"makes 1.6e\\+05 cases \\(400 x 400\\); allowed: at most {MAX_SWEEP_CASES}"):
        parse_scene(MINIMAL.replace("[contact]\n", grid + "\n[contact]\n"))


def test_sweep_values_are_checked_one_by_one_up_front():
    grid = '[sweep]\nload = ["1 kN", "2 mm"]\n'
    with pytest.raises(InputError, match=r"\[sweep\]: 'load' = '2 mm': LineContact.load = 2 mm: wrong dimension"):
        parse_scene(MINIMAL.replace("[contact]\n", grid + "[contact]\n"))
    # a value valid on its own passes (checks across fields are each case's own)
    grid = '[sweep]\n"body1.radius" = ["5 mm", "50 mm"]\n'
    assert parse_scene(MINIMAL.replace("[contact]\n", grid + "[contact]\n")).sweep == {"body1.radius": ["5 mm", "50 mm"]}


def test_check_report_unit():
    from camcontact.scene_file import check_report_unit

    check_report_unit("h_min", "nm", "here")
    check_report_unit("surface_temperature_max", "degF", "here")
    for unit, message in [("GPa", "has dimension"), ("furlongs_per_nm", "cannot read"), ("10**3 nm", "not a unit expression"),
                          (3, "allowed: a unit as a string")]:
        with pytest.raises(InputError, match=f"here: h_min.*{message}"):
            check_report_unit("h_min", unit, "here")
    with pytest.raises(InputError, match="here: unknown quantity 'zz'"):
        check_report_unit("zz", "nm", "here")
