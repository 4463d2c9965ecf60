"""Benchmarks run in quick mode (their timings are reported, never asserted)."""

import importlib.util
from pathlib import Path

import numpy as np
import pytest


BENCHMARKS = Path(__file__).resolve().parents[2] / "benchmarks"


def _load(name):
    spec = importlib.util.spec_from_file_location(name, BENCHMARKS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_hertz_elliptical_quick(tmp_path):
    frame = _load("hertz_elliptical").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "hertz_elliptical.csv").exists()
    exact = frame[frame["method"] == "exact"]
    assert (exact.filter(like="error").abs().to_numpy() == 0).all()
    fits = frame[frame["method"] != "exact"]
    # Hamrock & Brewe (1983) and Brewe & Hamrock (1977) fits: worst errors of a few per cent for r <= 100
    assert fits.filter(like="error").abs().to_numpy().max() < 6.0
    assert (frame["median time [us]"] > 0).all()


def test_accuracy_vs_time_quick(tmp_path):
    frame = _load("accuracy_vs_time").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "accuracy_vs_time.csv").exists()
    grid = frame[frame["method"] == "multigrid"]
    assert set(grid["level"]) == {4, 5, 6, 7} and (grid["status"] == "converged").all()
    # the finest level is closer to the extrapolated reference than the coarsest, at every point
    for (M, L), point in grid.groupby(["M", "L"]):
        errors = point.set_index("level")["error H_c [%]"].abs()
        assert errors[7] < errors[4]
    formulas = frame[frame["method"] != "multigrid"]
    assert set(formulas["method"]) == {"grubin", "dowson_higginson", "dowson_toyoda", "pan_hamrock", "moes"}


def test_ehl_speed_quick(tmp_path):
    frame = _load("ehl_speed").main(["--quick", "--out", str(tmp_path)])
    assert list(frame["nodes"]) == [225, 449, 897] and frame["converged"].all()


def test_cam_cycle_quick(tmp_path):
    frame = _load("cam_cycle").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "cam_cycle.csv").exists()
    assert set(frame["convention"]) == {"thesis", "consistent"} and (frame["angles"] == 24).all()
    assert (frame["h_min over the cycle [um]"] > 0).all()


def test_sweep_scaling_quick(tmp_path):
    frame = _load("sweep_scaling").main(["--quick", "--out", str(tmp_path)])
    assert list(frame["executor"]) == ["serial", "process pool", "process pool"]
    assert frame["identical table"].all() and (frame["cases"] == 8).all()


def test_accuracy_vs_time_cam_quick(tmp_path):
    frame = _load("accuracy_vs_time").main(["--cam", "--quick", "--out", str(tmp_path)])
    assert (tmp_path / "accuracy_vs_time_cam.csv").exists()
    by = frame.set_index("method")
    transient, steady = by.loc["multigrid L5 (transient, squeeze)"], by.loc["multigrid L5 (quasi-steady)"]
    # the squeeze term keeps the film at the reversals above the quasi-steady collapse
    assert transient["h_min near reversal [nm]"] > steady["h_min near reversal [nm]"] > 0
    assert (frame["median time [s]"] > 0).all()


def test_accuracy_vs_time_point_quick(tmp_path):
    frame = _load("accuracy_vs_time").main(["--point", "--quick", "--out", str(tmp_path)])
    assert (tmp_path / "accuracy_vs_time_point.csv").exists()
    by = frame.set_index("method")
    assert set(by.index) == {"multigrid 65x65", "multigrid 129x129", "nijenbanning", "hamrock_dowson"}
    assert by.loc["multigrid 129x129", "error H_c [%]"] == 0.0  # the finest level is the reference here
    # NVM fits numerical solutions: within 5 % of the 129^2 central film (test_point_ehl_literature: 257^2)
    assert abs(by.loc["nijenbanning", "error H_c [%]"]) < 5.0


def test_accuracy_vs_time_friction_quick(tmp_path):
    frame = _load("accuracy_vs_time").main(["--friction", "--quick", "--out", str(tmp_path)])
    assert (tmp_path / "accuracy_vs_time_friction.csv").exists()
    by = frame.set_index("rung")
    assert len(by) == 6 and (frame["time per angle [ms]"] > 0).all()
    # the Newtonian film sits on the limiting-shear plateau (Lambda_L = 0.047, + boundary friction where asperities
    # touch);
    # Eyring's non-linear viscous traction lies below it, and so does the friction power
    assert 0.045 < by.loc["mixed, newtonian fluid", "peak coefficient"] < 0.06
    assert by.loc["eyring isothermal", "peak coefficient"] < 0.1
    assert by.loc["eyring isothermal", "friction power mean [W]"] < by.loc["mixed, newtonian fluid",
                                                                           "friction power mean [W]"]
    # the contact temperature lowers the friction power
    assert by.loc["mixed + eyring + thermal", "friction power mean [W]"] < by.loc["mixed + eyring isothermal",
                                                                                 "friction power mean [W]"]


def test_accuracy_vs_time_traction_quick(tmp_path):
    frame = _load("accuracy_vs_time").main(["--traction", "--quick", "--out", str(tmp_path)])
    assert (tmp_path / "accuracy_vs_time_traction.csv").exists()
    by = frame.set_index("rung")
    assert len(by) == 9 and (frame["median time [ms]"] > 0).all()
    # the constant-Ct check and FASTSIM share the Coulomb capacity Ct N; the film's traction is lower
    ct = by.loc["constant Ct (thesis check)", "capacity in [N]"]
    assert by.loc["FASTSIM, Kalker's parabolic pressure", "capacity in [N]"] == ct
    assert by.loc["EHL Eyring isothermal, Hertz pressure", "capacity in [N]"] < ct
    # the numerical pressure moves the EHL rung by little at this moderate load (p_h 1.9 GPa)
    hertz, numerical = (by.loc[f"EHL Eyring isothermal, {p} pressure", "efficiency [%]"] for p in ("Hertz", "numerical"))
    assert abs(hertz - numerical) < 1.0
    # at 3000 rpm the film is thick enough that the asperities carry a trace: the mixed rung is the film's
    mixed = by.loc["EHL Eyring + asperities (mixed), Hertz pressure"]
    assert 0.0 < mixed["asperity share in [%]"] < 1.0 and frame["asperity share in [%]"].notna().sum() == 2
    assert abs(mixed["efficiency [%]"] - hertz) < 0.1


def test_stability_map_quick(tmp_path):
    """benchmarks/stability_map.py --quick: a 4 x 3 corner of the Moes map at level 6, each case with its status,
    attempts and work units (timings reported, never asserted)."""
    frame = _load("stability_map").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "stability_map.csv").exists() and len(frame) == 12
    assert set(frame["status"]) <= {"converged", "warning", "error"}
    assert (frame["attempts"] >= 1).all() and (frame["attempts"] <= 3).all()
    converged = frame[frame["status"] == "converged"]
    # finite films (at level 6 the discrete film of M = 1000 closes, H_min just below 0: too coarse a grid for it)
    assert len(converged) >= 10 and (converged["work units"] > 0).all() and np.isfinite(converged["H_min"]).all()


def test_cavitation_cost_quick(tmp_path):
    """benchmarks/cavitation_cost.py --quick: the mass-conserving and starved line solves and the transient
    reversal with both cavitation models, their films, mass-flux spreads and costs (timings never asserted)."""
    frame = _load("cavitation_cost").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "cavitation_cost.csv").exists()
    assert list(frame["case"]) == ["steady"] * 2 + ["starved"] * 3 + ["transient"] * 2
    steady = frame[frame["case"] == "steady"]
    assert steady["H_min"].iloc[1] == pytest.approx(steady["H_min"].iloc[0], rel=1e-4)
    starved = frame[frame["case"] == "starved"]
    assert starved["converged"].all() and (starved["flux spread"] < 1e-4).all()
    np.testing.assert_allclose(starved["H_c / H_c,flooded"], starved["supply [-]"], rtol=5e-3)
    transient = frame[frame["case"] == "transient"]
    assert (transient["h_min after reversal [nm]"] > 0).all()


def test_thermal_ehl_cost_quick(tmp_path):
    """benchmarks/thermal_ehl_cost.py --quick: the rungs (isothermal, formula factors, thermal solver, thermal solver
    with a starved inlet, with compression work) for the film and the traction at three slide-to-roll ratios (timings
    never asserted)."""
    frame = _load("thermal_ehl_cost").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "thermal_ehl_cost.csv").exists()
    assert list(frame["rung"]) == ["isothermal", "formula", "thermal", "thermal starved", "thermal expanding"] * 3
    thermal = frame[frame["rung"] == "thermal"]
    assert thermal["converged"].all() and (thermal["h_c / iso [-]"] < 1.0).all()
    # the thermal solver's traction is below the isothermal one once the film heats (S > 0)
    sliding = frame[frame["S [-]"] > 0].set_index(["S [-]", "rung"])["traction [-]"]
    for S in (0.5, 1.0):
        assert 0 < sliding[(S, "thermal")] < sliding[(S, "isothermal")]
        # the starved film, half as thick and less heated in its inlet, shears harder than the flooded one
        assert sliding[(S, "thermal starved")] > sliding[(S, "thermal")]
    starved = frame[frame["rung"] == "thermal starved"]
    assert starved["converged"].all() and (starved["h_c [nm]"] < 0.6 * thermal["h_c [nm]"].to_numpy()).all()
    # compression work: the rolling film thins more; the sliding films' hot Hertz zones expand and thicken
    expanding = frame[frame["rung"] == "thermal expanding"].set_index("S [-]")
    plain = thermal.set_index("S [-]")
    assert expanding["converged"].all()
    assert expanding.loc[0.0, "h_c / iso [-]"] < plain.loc[0.0, "h_c / iso [-]"]
    assert expanding.loc[1.0, "h_c / iso [-]"] > plain.loc[1.0, "h_c / iso [-]"]


def test_thermal_cam_cycle_quick(tmp_path):
    """benchmarks/thermal_cam_cycle.py --quick: the LS-1 roller turn marched isothermal and thermal, rolling and
    with 5 % slip: films, temperatures, traction and costs (timings never asserted)."""
    frame = _load("thermal_cam_cycle").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "thermal_cam_cycle.csv").exists() and list(frame["slip"]) == [0.0, 0.05]
    assert (frame["not converged (thermal)"] == 0).all()
    # the inlet heating thins the film a few per cent; slip heats the film more and carries a traction
    assert (frame["h_min thermal [nm]"] < frame["h_min isothermal [nm]"]).all()
    assert frame["max film rise [K]"].iloc[1] > frame["max film rise [K]"].iloc[0] > 0
    traction = frame["mean traction [-]"]
    assert traction.iloc[0] == pytest.approx(0.0, abs=1e-12) and traction.iloc[1] > 0


def test_starved_cam_cycle_quick(tmp_path):
    """benchmarks/starved_cam_cycle.py --quick: the LS-1 flat follower's transient turn with clipping, with
    mass-conserving cavitation and with a 0.3 um oil layer; the starved flanks carry the layer, the thinnest film
    of every run lies just after the second reversal (timings never asserted)."""
    frame = _load("starved_cam_cycle").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "starved_cam_cycle.csv").exists() and (tmp_path / "starved_cam_cycle_turns.csv").exists()
    assert list(frame["run"]) == ["reynolds", "flooded", "starved 0.3 um"]
    by_run = frame.set_index("run")
    assert by_run.loc["starved 0.3 um", "h_c fastest flank [nm]"] == pytest.approx(275.0, rel=0.03)
    assert by_run.loc["flooded", "h_c fastest flank [nm]"] > 2000.0
    assert (frame["at cam angle [deg]"].between(100.0, 125.0)).all()
    assert by_run.loc["starved 0.3 um", "h_min over turn [nm]"] < by_run.loc["flooded", "h_min over turn [nm]"]
    assert (frame["not converged"] <= 8).all()
