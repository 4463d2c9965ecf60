"""Sweeps: tidy tables, errors kept per case, any executor gives the same table, progress, exports."""

import math
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pandas as pd
import pytest

import camcontact as cc
from camcontact.errors import InputError
from camcontact.report_export import split_header, to_pint_frame, write_csv, write_parquet
from camcontact.scene_file import load_scene

STEEL = cc.Material(E="210 GPa", nu=0.3)
OIL = cc.Lubricant(name="oil", eta0="0.04 Pa*s", alpha="2e-8 1/Pa")


def contact():
    return cc.LineContact(body1=cc.Body(material=STEEL, radius="20 mm", speed="2 m/s", roughness="0.2 um"),
                          body2=cc.Body(material=STEEL, radius="10 mm", speed="2 m/s", roughness="0.2 um"),
                          load="1 kN", length="10 mm", lubricant=OIL)


GRID = {"load": ["0.5 kN", "1 kN", "-1 kN", "4 kN"], "body1.radius": ["20 mm", "40 mm"]}
OUTPUTS = ["b", "p_h", "h_min", "regime"]


def serial():
    return cc.Analysis(contact(), outputs=OUTPUTS).sweep(GRID, progress=False)


def test_tidy_table_with_units_in_headers_and_errors_per_case():
    """8 cases: one row each; swept values in 'path [unit]' columns in the unit of the first value; the
    negative load fails with its parameters kept, the 6 others complete. p_h ~ sqrt(w/R): quadrupling the
    load doubles it (Hertz, independent of this table)."""
    frame = serial()
    assert list(frame.columns) == ["case", "load [kN]", "body1.radius [mm]", "b [µm]", "p_h [MPa]", "h_min [µm]",
                                   "regime", "error"]
    assert list(frame["case"]) == list(range(8))
    assert len(frame) == 8
    failed = frame[frame["error"] != ""]
    assert list(failed["load [kN]"]) == [-1.0, -1.0] and list(failed["body1.radius [mm]"]) == [20.0, 40.0]
    assert failed["error"].str.startswith("InputError: LineContact.load = -1 kN").all()
    assert failed["p_h [MPa]"].isna().all()
    ok = frame[frame["error"] == ""]
    assert ok["p_h [MPa]"].notna().all()
    by = ok.set_index(["load [kN]", "body1.radius [mm]"])["p_h [MPa]"]
    assert by[(4.0, 20.0)] / by[(1.0, 20.0)] == pytest.approx(2.0, rel=1e-12)


def test_process_pool_and_dask_give_the_same_table():
    """The same sweep on a local process pool (2 workers) and on a dask.distributed LocalCluster
    (2 worker processes) gives the identical table, failing cases included."""
    expected = serial()
    with ProcessPoolExecutor(max_workers=2) as pool:
        pooled = cc.Analysis(contact(), outputs=OUTPUTS).sweep(GRID, executor=pool, progress=False)
    pd.testing.assert_frame_equal(pooled, expected)
    distributed = pytest.importorskip("dask.distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            dasked = cc.Analysis(contact(), outputs=OUTPUTS).sweep(GRID, executor=client.get_executor(),
                                                                    progress=False)
    pd.testing.assert_frame_equal(dasked, expected)


def test_cases_from_a_dataframe_and_errors_raise():
    cases = pd.DataFrame({"load": ["1 kN", "2 kN"], "body1.speed": ["1 m/s", "3 m/s"]})
    frame = cc.Analysis(contact(), outputs=["h_min"]).sweep(cases, progress=False)
    assert list(frame["load [kN]"]) == [1.0, 2.0] and list(frame["body1.speed [m/s]"]) == [1.0, 3.0]
    with pytest.raises(InputError, match="LineContact.load = -1 kN") as raised:  # the case's own exception
        cc.Analysis(contact(), outputs=["p_h"]).sweep(GRID, progress=False, errors="raise")
    assert raised.value.__notes__ == ["sweep case 4: {'load': '-1 kN', 'body1.radius': '20 mm'}"]
    with pytest.raises(InputError, match="sweep path 'body1.radiuss': Body has no field 'radiuss'"):
        cc.Analysis(contact(), outputs=["p_h"]).sweep({"body1.radiuss": ["1 mm"]}, progress=False)
    with pytest.raises(InputError, match="sweep path 'load.unit': load is not a component"):
        cc.Analysis(contact(), outputs=["p_h"]).sweep({"load.unit": ["N"]}, progress=False)
    with pytest.raises(InputError, match="give a list of values"):
        cc.Analysis(contact(), outputs=["p_h"]).sweep({"load": "1 kN"})
    with pytest.raises(InputError, match="table = 'wide'"):
        cc.Analysis(contact(), outputs=["p_h"]).sweep({"load": ["1 kN"]}, table="wide")


def test_progress_bar_on_request(capsys):
    cc.Analysis(contact(), outputs=["p_h"]).sweep({"load": ["1 kN", "2 kN", "3 kN"]}, progress=True)
    err = capsys.readouterr().err
    assert "sweep" in err and "3/3" in err


def test_indexed_scene_gives_rows_per_case_and_angle():
    """A cam cycle every 30 deg at two speeds: 2 x 12 rows with the speed column, or one summary row per
    case with table='cases'."""
    import attrs

    scene = load_scene()
    cam = attrs.evolve(scene.component, angle_step="30 deg")
    analysis = cc.Analysis(cam, outputs=["cam_angle", "h_min", "p_h", "h_min_cycle", "jump_margin"],
                           models=scene.models)
    per_angle = analysis.sweep({"speed": ["1000 rpm", "3000 rpm"]}, progress=False)
    assert len(per_angle) == 24 and list(per_angle.columns[:3]) == ["case", "speed [rpm]", "cam_angle [deg]"]
    summary = analysis.sweep({"speed": ["1000 rpm", "3000 rpm"]}, progress=False, table="cases")
    assert len(summary) == 2 and "h_min_cycle [µm]" in summary and "h_min [µm]" not in summary
    # the jump margin is the smallest contact force over the cycle: the 1000 N preload in the dwell at
    # 1000 rpm; at 3000 rpm the deceleration of the lift (inertia ~ speed^2) takes the force below it
    assert summary["jump_margin [N]"][0] == pytest.approx(1000.0) and 0 < summary["jump_margin [N]"][1] < 1000.0


def test_exports_round_trip(tmp_path):
    frame = serial()
    back = pd.read_csv(write_csv(frame, tmp_path / "sweep.csv"), keep_default_na=False, na_values=[""])
    assert list(back.columns) == list(frame.columns)
    assert np.allclose(back["p_h [MPa]"].to_numpy(dtype=float), frame["p_h [MPa]"].to_numpy(dtype=float),
                       equal_nan=True)
    pytest.importorskip("pyarrow")
    parquet = pd.read_parquet(write_parquet(frame, tmp_path / "sweep.parquet"))
    pd.testing.assert_frame_equal(parquet, frame)


def test_pint_pandas_frame_carries_the_units():
    pytest.importorskip("pint_pandas")
    frame = serial()
    typed = to_pint_frame(frame)
    assert str(typed["p_h"].dtype).startswith("pint[megapascal]") and typed["regime"].dtype == frame["regime"].dtype
    gigapascal = typed["p_h"].pint.to("GPa").pint.magnitude.to_numpy(dtype=float)
    assert np.allclose(gigapascal, frame["p_h [MPa]"].to_numpy(dtype=float) / 1e3, equal_nan=True)
    assert split_header("h_min [µm]") == ("h_min", "µm") and split_header("regime") == ("regime", None)
    assert split_header("ratio [-]") == ("ratio", "")


def test_degrees_celsius_and_compound_units_parse():
    pytest.importorskip("pint_pandas")
    typed = to_pint_frame(pd.DataFrame({"T [°C]": [20.0], "eta0 [mPa·s]": [3.0], "alpha [1/GPa]": [20.0]}))
    assert typed["eta0"].pint.to("Pa*s").pint.magnitude[0] == pytest.approx(3e-3)
    assert math.isclose(typed["alpha"].pint.to("1/Pa").pint.magnitude[0], 2e-8)


def test_a_grid_of_more_than_max_sweep_cases_is_refused_before_any_case_is_built():
    """MAX_SWEEP_CASES = 100 000: a 1000 x 1000 grid, an endless iterable (read at most 100 001 values) and a
    DataFrame of 100 001 rows are InputErrors before anything is allocated or run."""
    from camcontact.sweep_cases import MAX_SWEEP_CASES, cases_of

    assert MAX_SWEEP_CASES == 100_000
    with pytest.raises(InputError, match=r"sweep grid makes 1e\+06 cases \(1000 x 1000\); allowed: at most 100000"):
        cases_of({"load": ["1 kN"] * 1000, "length": ["1 mm"] * 1000})
    with pytest.raises(InputError, match=r"sweep grid makes 1e\+05 cases \(100001\); allowed: at most 100000"):
        cases_of({"load": iter(int, 1)})  # never ends
    with pytest.raises(InputError, match=r"\(100001\); allowed"):
        cases_of(pd.DataFrame({"load": np.ones(100_001)}))
    assert len(cases_of({"load": ["1 kN"] * 100, "length": ["1 mm"] * 1000})[1]) == 100_000
