"""Sweeps lose nothing: a timeout per case, the table streamed to a CSV file as cases finish, resume from it,
and a partial table (every finished case on disk) after a SIGINT or a killed worker process.

The scene is a cheap Hertz line contact swept over the load (p_h only). Slow, interrupting, killing and
raising cases come from runners defined here at module level (an Analysis that misbehaves for one
load), so they pickle into worker processes. No test asserts a time.
"""

from __future__ import annotations

import multiprocessing
import os
import shlex
import signal
import threading
import time
import warnings
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import pandas as pd
import pytest
from cli_corpus import LINE

import camcontact as cc
from camcontact.cli import main
from camcontact.errors import (
    CamcontactWarning,
    CaseTimeout,
    InputError,
    SweepInterruptedWarning,
)
from camcontact.sweep import read_sweep, worker_count
from camcontact.sweep_cases import CaseAlarm
from camcontact.sweep_cases import run_sweep as run_cases_sweep

STEEL = cc.Material(E="210 GPa", nu=0.3)
LOADS = ["1 kN", "2 kN", "3 kN", "4 kN", "5 kN", "6 kN"]
GRID = {"load": LOADS}
OUTPUTS = ["p_h"]


def contact():
    return cc.LineContact(body1=cc.Body(material=STEEL, radius="20 mm"), body2=cc.Body(material=STEEL, radius="10 mm"),
                          load="1 kN", length="10 mm")


def kilonewtons(analysis: cc.Analysis) -> float:
    return float(analysis.scene.load.to("kN").magnitude)


class SigintAt4kN(cc.Analysis):
    """Sends this process a real SIGINT when the 4 kN case runs (as Ctrl-C does)."""

    def run(self):
        if kilonewtons(self) == 4.0:
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(30)  # the signal's KeyboardInterrupt arrives here
        return super().run()


class KeyboardInterruptAt3kN(cc.Analysis):
    """Raises KeyboardInterrupt when the 3 kN case runs (a SIGINT, simulated)."""

    def run(self):
        if kilonewtons(self) == 3.0:
            raise KeyboardInterrupt
        return super().run()


class KillsWorkerAt4kN(cc.Analysis):
    """Kills its worker process (SIGKILL) when the 4 kN case runs there."""

    def run(self):
        if kilonewtons(self) == 4.0 and multiprocessing.parent_process() is not None:
            os.kill(os.getpid(), signal.SIGKILL)
        return super().run()


class SleepsAt2kN(cc.Analysis):
    """Sleeps (far longer than the tests' timeouts) when the 2 kN case runs."""

    def run(self):
        if kilonewtons(self) == 2.0:
            time.sleep(60)
        return super().run()


class SwallowsTimeoutsAt2kN(cc.Analysis):
    """At 2 kN catches the first CaseTimeouts (as an analysis isolating a failing step does) and goes on."""

    def run(self):
        if kilonewtons(self) == 2.0:
            for _ in range(3):
                try:
                    time.sleep(60)
                except CaseTimeout:
                    pass
        return super().run()


class FailsBelow4kN(cc.Analysis):
    """Fails for every load below 4 kN: a resume that ran a case already on disk would show it."""

    def run(self):
        if kilonewtons(self) < 4.0:
            raise AssertionError("this case was on disk already and must not run again")
        return super().run()


class DividesByZeroAt3kN(cc.Analysis):
    def run(self):
        if kilonewtons(self) == 3.0:
            return 1 / 0
        return super().run()


class LockedError(Exception):
    """An exception that does not survive pickling (it holds a lock)."""

    def __init__(self, message):
        super().__init__(message)
        self.lock = threading.Lock()


class UnpicklableErrorAt3kN(cc.Analysis):
    def run(self):
        if kilonewtons(self) == 3.0:
            raise LockedError("no film at 3 kN")
        return super().run()


class ReportedRows:
    """A result whose rows carry the report's own ``failed``/``error`` (a step failed inside the analysis)."""

    index = None

    def __init__(self, frame):
        self.frame = frame

    def to_frame(self, units=None):
        return self.frame


class StepFailsAt2kN(cc.Analysis):
    """At 2 kN the report says a step failed (its p_h NaN, ``failed`` True, the reason in ``error``), as an
    Analysis without ``strict`` reports it; the other loads report ``failed`` False and no error."""

    def run(self):
        frame = super().run().to_frame()
        failing = kilonewtons(self) == 2.0
        if failing:
            frame["p_h [MPa]"] = float("nan")
        frame["failed"] = failing
        frame["error"] = "hertz: ConvergenceError: no" if failing else ""
        return ReportedRows(frame)


def sweep(runner=cc.Analysis, grid=GRID, **options):
    return run_cases_sweep(runner, contact(), grid, outputs=OUTPUTS, progress=False, **options)


@pytest.fixture(scope="module")
def uninterrupted():
    """The table of the whole sweep, in memory, never interrupted."""
    return sweep()


def test_the_stream_file_reads_back_as_the_returned_table(tmp_path, uninterrupted):
    """``case`` first, floats exact, ``error`` "" (not NaN) for a case that ran and the reason for one that
    failed (a negative load), the failing case kept with its parameters; the streamed file reads back as the
    table the sweep returns and as the in-memory table of the same sweep without a stream."""
    grid = {"load": ["1 kN", "-1 kN", "3 kN"]}
    in_memory = sweep(grid=grid)
    assert list(in_memory.columns) == ["case", "load [kN]", "p_h [MPa]", "error"]
    assert list(in_memory["case"]) == [0, 1, 2] and in_memory["error"][0] == ""
    assert in_memory["error"][1].startswith("InputError: LineContact.load = -1 kN")
    streamed = sweep(grid=grid, stream=tmp_path / "sweep.csv")
    back = read_sweep(tmp_path / "sweep.csv")
    pd.testing.assert_frame_equal(streamed, in_memory)
    pd.testing.assert_frame_equal(back, in_memory)
    assert back["p_h [MPa]"][2] == in_memory["p_h [MPa]"][2]  # bit for bit
    assert in_memory.attrs == {"missing_cases": [], "interrupted": False, "executor_broken": False,
                               "dimensions": ["load [kN]"], "index": None}  # the grid's, for to_xarray
    assert uninterrupted["error"].eq("").all() and len(uninterrupted) == len(LOADS)


def test_rows_keep_their_own_failed_flag_and_error_text(tmp_path):
    """A report row's own ``failed``/``error`` stay (the step's reason is not overwritten by ""); a case that
    failed as a whole gets failed True; ``failed`` is bool and comes before ``error``, the last column."""
    grid = {"load": ["1 kN", "2 kN", "-1 kN"]}
    frame = sweep(StepFailsAt2kN, grid=grid, table="cases", stream=tmp_path / "sweep.csv")
    assert list(frame.columns) == ["case", "load [kN]", "p_h [MPa]", "failed", "error"]
    assert frame["failed"].dtype == bool and list(frame["failed"]) == [False, True, True]
    assert list(frame["error"][:2]) == ["", "hertz: ConvergenceError: no"]
    assert frame["error"][2].startswith("InputError: LineContact.load = -1 kN")
    pd.testing.assert_frame_equal(read_sweep(tmp_path / "sweep.csv"), frame)
    pd.testing.assert_frame_equal(sweep(StepFailsAt2kN, grid=grid, table="cases"), frame)


def test_a_sigint_keeps_every_finished_case_on_disk_and_resume_gives_the_same_table(tmp_path, uninterrupted):
    """A real SIGINT during the 4th case: the 3 finished cases are returned and on disk, the others listed as
    missing, a warning says how to resume; the resumed sweep runs only the missing cases (a runner that fails
    for the finished ones shows it) and returns the uninterrupted table."""
    path = tmp_path / "sweep.csv"
    with pytest.warns(SweepInterruptedWarning, match=r"\(SIGINT\): 3 of 6 cases missing.*resume=True"):
        partial = sweep(SigintAt4kN, stream=path)
    assert partial.attrs["missing_cases"] == [3, 4, 5] and partial.attrs["interrupted"]
    assert not partial.attrs["executor_broken"]
    pd.testing.assert_frame_equal(partial, uninterrupted.iloc[:3])
    pd.testing.assert_frame_equal(read_sweep(path), partial)
    resumed = sweep(FailsBelow4kN, stream=path, resume=True)
    pd.testing.assert_frame_equal(resumed, uninterrupted)
    assert resumed.attrs["missing_cases"] == []
    pd.testing.assert_frame_equal(read_sweep(path), uninterrupted)


def test_a_keyboard_interrupt_without_a_stream_returns_the_finished_cases(uninterrupted):
    with pytest.warns(SweepInterruptedWarning, match="4 of 6 cases missing.*give stream="):
        partial = sweep(KeyboardInterruptAt3kN)
    assert partial.attrs["missing_cases"] == [2, 3, 4, 5]
    pd.testing.assert_frame_equal(partial, uninterrupted.iloc[:2])


def test_a_killed_worker_keeps_every_finished_case_on_disk_and_resume_gives_the_same_table(tmp_path,
                                                                                         uninterrupted):
    """A worker process killed (SIGKILL) in the 4 kN case breaks the pool: every case that finished is
    returned and on disk, the killed case and those not run are missing (not failed); resuming (serially
    here) runs only those and gives the uninterrupted table."""
    path = tmp_path / "sweep.csv"
    with ProcessPoolExecutor(max_workers=2) as pool, \
            pytest.warns(SweepInterruptedWarning, match="the executor broke: a worker process died"):
        partial = sweep(KillsWorkerAt4kN, executor=pool, chunksize=1, stream=path)
    missing = partial.attrs["missing_cases"]
    assert 3 in missing and partial.attrs["executor_broken"] and not partial.attrs["interrupted"]
    assert sorted([*partial["case"], *missing]) == list(range(len(LOADS)))
    assert partial["error"].eq("").all()  # nothing recorded as failed
    pd.testing.assert_frame_equal(partial, uninterrupted[uninterrupted["case"].isin(partial["case"])]
                                  .reset_index(drop=True))
    pd.testing.assert_frame_equal(read_sweep(path), partial)
    resumed = sweep(stream=path, resume=True)
    pd.testing.assert_frame_equal(resumed, uninterrupted)


def test_a_case_past_the_timeout_is_recorded_and_the_others_complete(uninterrupted):
    """Serially and in worker processes, the 2 kN case (asleep) is recorded as a CaseTimeout and the others
    complete, as they do in the sweep without the slow case; a case whose analysis catches the timeout (as
    its per-step isolation does) is still recorded as timed out. The alarm is disarmed afterwards."""
    handler = signal.getsignal(signal.SIGALRM)
    expected = uninterrupted.copy()
    expected.loc[1, "p_h [MPa]"] = float("nan")
    expected.loc[1, "error"] = "CaseTimeout: case exceeded 0.3 s"
    for runner in (SleepsAt2kN, SwallowsTimeoutsAt2kN):
        pd.testing.assert_frame_equal(sweep(runner, timeout=0.3), expected)
    with ProcessPoolExecutor(max_workers=2) as pool:
        pd.testing.assert_frame_equal(sweep(SleepsAt2kN, timeout=0.3, executor=pool, chunksize=1), expected)
    assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0) and signal.getsignal(signal.SIGALRM) is handler
    with pytest.raises(CaseTimeout, match="case exceeded 0.3 s") as raised:
        sweep(SleepsAt2kN, timeout=0.3, errors="raise")
    assert raised.value.__notes__ == ["sweep case 1: {'load': '2 kN'}"]


def test_a_timeout_where_no_alarm_is_possible_warns_once(monkeypatch, uninterrupted):
    monkeypatch.setattr(CaseAlarm, "warned", False)
    with ThreadPoolExecutor(max_workers=1) as pool, \
            pytest.warns(CamcontactWarning, match="sweep timeout not applied: cases run in thread") as caught:
        frame = sweep(timeout=5, executor=pool, chunksize=1)
    assert sum("timeout not applied" in str(w.message) for w in caught) == 1
    pd.testing.assert_frame_equal(frame, uninterrupted)


def test_errors_raise_keeps_the_exception_type_serially_and_through_a_process_pool():
    with pytest.raises(ZeroDivisionError) as raised:
        sweep(DividesByZeroAt3kN, errors="raise")
    assert raised.value.__notes__ == ["sweep case 2: {'load': '3 kN'}"]
    with ProcessPoolExecutor(max_workers=2) as pool:
        with pytest.raises(ZeroDivisionError) as raised:
            sweep(DividesByZeroAt3kN, errors="raise", executor=pool, chunksize=1)
        assert raised.value.__notes__ == ["sweep case 2: {'load': '3 kN'}"]
        with pytest.raises(RuntimeError, match="LockedError: no film at 3 kN") as raised:  # does not pickle
            sweep(UnpicklableErrorAt3kN, errors="raise", executor=pool, chunksize=1)
        assert raised.value.__notes__ == ["sweep case 2: {'load': '3 kN'}"]
    assert sweep(DividesByZeroAt3kN)["error"][2] == "ZeroDivisionError: division by zero"


def test_resume_refuses_a_file_of_another_sweep_and_the_options_are_checked(tmp_path):
    path = tmp_path / "sweep.csv"
    sweep(grid={"load": ["1 kN", "2 kN"]}, stream=path)
    with pytest.raises(InputError, match=r"sweep\.csv' belongs to another sweep: case 0 has load \[kN\] = 1.0 "
                                         r"there, 10.0 in this grid"):
        sweep(grid={"load": ["10 kN", "20 kN"]}, stream=path, resume=True)
    with pytest.raises(InputError, match=r"belongs to another sweep: no column\(s\) 'length \[mm\]'"):
        sweep(grid={"length": ["10 mm", "20 mm"]}, stream=path, resume=True)
    with pytest.raises(InputError, match="belongs to another sweep: case 1 there, this grid has cases 0 to 0"):
        sweep(grid={"load": ["1 kN"]}, stream=path, resume=True)
    for timeout in (0, -1.0, float("nan"), float("inf"), True, "5 s"):
        with pytest.raises(InputError, match=r"sweep: timeout = .*; allowed: None or a finite number of seconds > 0"):
            sweep(timeout=timeout)
    with pytest.raises(InputError, match="resume = True needs stream"):
        sweep(resume=True)
    with pytest.raises(InputError, match=r"stream = '.*sweep\.parquet'; allowed: a path ending in \.csv"):
        sweep(stream=tmp_path / "sweep.parquet")
    with pytest.raises(InputError, match=r"stream = '.*missing/sweep\.csv' cannot be written"):
        sweep(stream=tmp_path / "missing" / "sweep.csv")


def test_a_torn_last_line_is_dropped_on_resume(tmp_path, uninterrupted):
    """A stop in the middle of a write leaves a line without its end: resume drops it with the rows of the
    case written last, runs those again and gives the uninterrupted table."""
    path = tmp_path / "sweep.csv"
    sweep(grid={"load": LOADS[:3]}, stream=path)
    with open(path, "a", encoding="utf-8") as file:
        file.write("3,4.0,1484.")
    pd.testing.assert_frame_equal(sweep(stream=path, resume=True), uninterrupted)


# ----------------------------------------------------------------------------- the command
#: the corpus's line-contact scene (tests/cli_corpus.py), Hertz only, over four loads
SCENE = LINE.replace('outputs = ["b", "p_h", "h_c", "regime"]', 'outputs = ["p_h"]').replace(
    'load = ["1 kN", "2 kN"]', 'load = ["1 kN", "2 kN", "3 kN", "4 kN"]').replace(
    'units = { h_c = "um", p_h = "MPa" }', 'units = { p_h = "MPa" }')


@pytest.fixture()
def scene_file(tmp_path):
    path = tmp_path / "hertz.toml"
    path.write_text(SCENE, encoding="utf-8")
    return path


def test_cli_caps_the_workers_at_the_cases_and_the_cpus(scene_file, tmp_path, capsys):
    csv = tmp_path / "table.csv"
    assert main(["sweep", str(scene_file), "--workers", "64", "--csv", str(csv), "--no-progress"]) == 0
    workers = worker_count(64, 4)
    assert workers == min(4, os.cpu_count() or 1)
    out = capsys.readouterr().out
    assert f"on {workers} worker processes; --workers 64 capped to {workers} ({os.cpu_count()} CPUs, 4 cases)" in out
    assert "4 rows (0 failed cases)" in out and len(read_sweep(csv)) == 4
    assert main(["sweep", str(scene_file), "--workers", "1", "--csv", str(csv), "--no-progress"]) == 0
    assert "capped" not in capsys.readouterr().out


def test_cli_resumes_from_its_csv_file(scene_file, tmp_path, capsys):
    """The CSV file cut after two cases (an interrupted sweep) and `--resume`: the complete table again."""
    csv = tmp_path / "sweep.csv"
    assert main(["sweep", str(scene_file), "--csv", str(csv), "--no-progress"]) == 0
    whole = read_sweep(csv)
    lines = csv.read_text(encoding="utf-8").splitlines(keepends=True)
    csv.write_text("".join(lines[:3]), encoding="utf-8")
    assert len(read_sweep(csv)) == 2
    assert main(["sweep", str(scene_file), "--csv", str(csv), "--resume", "--no-progress", "--timeout", "60"]) == 0
    pd.testing.assert_frame_equal(read_sweep(csv), whole)
    assert "4 rows (0 failed cases)" in capsys.readouterr().out
    assert main(["sweep", str(scene_file), "--csv", str(csv), "--timeout", "0"]) == 2
    assert "timeout = 0.0; allowed" in capsys.readouterr().err


@pytest.mark.parametrize(("runner", "workers", "status"), [(SigintAt4kN, "0", 130), (KillsWorkerAt4kN, "2", 1)])
def test_cli_interrupted_says_what_is_on_disk_and_how_to_resume(scene_file, tmp_path, capsys, monkeypatch, runner,
                                                                workers, status):
    """A SIGINT (exit 130) or a killed worker (exit 1): one line with the cases on disk and the command that
    resumes; that command completes the table."""
    import camcontact.sweep as sweeps

    csv = tmp_path / "sweep.csv"
    monkeypatch.setattr(sweeps, "run_sweep", lambda scene, grid, strict=False, **options: run_cases_sweep(
        runner, scene, grid, **options))
    with warnings.catch_warnings():
        warnings.simplefilter("error", SweepInterruptedWarning)  # the command says it in its own line instead
        assert main(["sweep", str(scene_file), "--csv", str(csv), "--no-progress", "--workers", workers]) == status
    err = capsys.readouterr().err.strip().splitlines()
    on_disk = len(read_sweep(csv))
    assert on_disk < 4 and len(err) == 1
    assert err[0].startswith(f"camcontact: interrupted: {on_disk} of 4 cases on disk in {csv}; resume with: ")
    command = shlex.split(err[0].split("resume with: ")[1])
    assert command[:2] == ["camcontact", "sweep"] and "--resume" in command
    monkeypatch.undo()
    assert main(command[1:]) == 0
    capsys.readouterr()
    assert main(["sweep", str(scene_file), "--csv", str(tmp_path / "whole.csv"), "--no-progress"]) == 0
    pd.testing.assert_frame_equal(read_sweep(csv), read_sweep(tmp_path / "whole.csv"))
