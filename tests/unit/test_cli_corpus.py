"""The bad scene / CLI corpus (tests/cli_corpus.py): every case a non-zero exit with one clear line, no
traceback, in bounded time; and scene files full of code that would create a marker file: nothing runs.

In-process calls (``camcontact.cli.main``, stdout/stderr captured, a SIGALRM bound per call) for most
cases; a child process (``python -m camcontact``, 60 s timeout) for those that need a real stdout or
could block if the checks went wrong: a FIFO as the scene, ``--csv /dev/full``, a closed stdout.
"""

from __future__ import annotations

import signal
from contextlib import contextmanager

import cli_corpus
import pytest
from cli_corpus import (
    CASES,
    MARKER_PAYLOADS,
    Case,
    Outcome,
    marker_cases,
    prepare,
    problems,
    run_subprocess,
)

from camcontact.cli import main

#: the time bound of one in-process call [s] (the slowest case takes well under a second)
IN_PROCESS_SECONDS = 20
#: the time bound of one child process [s]
SUBPROCESS_SECONDS = 60
MARKER = "MARKER"


class _Hang(BaseException):
    """Raised by SIGALRM: not an Exception, so camcontact's handler lets it through."""


@contextmanager
def _time_bound(seconds: int):
    def alarm(signum, frame):
        raise _Hang(f"no exit within {seconds} s")

    previous = signal.signal(signal.SIGALRM, alarm)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


def _in_process(case: Case, tmp_path, capsys) -> Outcome:
    argv = prepare(case, tmp_path)
    capsys.readouterr()
    try:
        with _time_bound(IN_PROCESS_SECONDS):
            status = main(argv)
    except _Hang:
        status = None
    captured = capsys.readouterr()
    return Outcome(status, captured.out, captured.err, 0.0)


def test_the_corpus_is_large_and_covers_the_issue():
    names = {case.name for case in CASES}
    assert len(CASES) >= 100
    for name in ("FIFO as scene", "/dev/zero as scene", "deep nesting: 10000 arrays", "expression (10**10**8) N",
                 "sweep 10 paths x 100 values (1e20 cases)", "--csv to /dev/full", "stdout closed (broken pipe)",
                 "latin-1 degree sign", "--units unknown unit", "plugins --family nonexistent"):
        assert name in names


@pytest.mark.parametrize("case", [c for c in CASES if not c.subprocess], ids=lambda c: c.name)
def test_corpus_case_in_process(case, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    outcome = _in_process(case, tmp_path, capsys)
    assert problems(case, outcome) == [], outcome.stderr[:500]
    assert not (tmp_path / "report.csv").exists()  # nothing ran


@pytest.mark.parametrize("case", [c for c in CASES if c.subprocess], ids=lambda c: c.name)
def test_corpus_case_in_a_child_process(case, tmp_path):
    outcome = run_subprocess(case, tmp_path, timeout=SUBPROCESS_SECONDS)
    assert problems(case, outcome) == [], outcome.stderr[:500]
    if case.closed_stdout:  # the report was written before anything was printed: nothing lost
        assert (tmp_path / "report.csv").stat().st_size > 0
    if case.status == cli_corpus.FAILURE:
        assert "/dev/full" in outcome.stderr and "No space left" in outcome.stderr


@pytest.mark.parametrize("payload", range(len(MARKER_PAYLOADS)))
def test_nothing_in_a_scene_file_is_executed(payload, tmp_path, capsys, monkeypatch):
    """Code that would create MARKER (relative: in the working directory, tmp_path) in every string slot of
    a scene file and the command line, run and swept: MARKER never appears; each call ends with status 2
    and one error line, except the free-text labels (names), which run as text (status 0)."""
    monkeypatch.chdir(tmp_path)
    cases = [c for c in marker_cases(MARKER) if c.name.startswith(f"marker {payload} ")]
    assert len(cases) > 20 and any(c.argv[0] == "sweep" for c in cases)
    failures = {}
    for number, case in enumerate(cases):
        work = tmp_path / f"case{number}"
        work.mkdir()
        outcome = _in_process(case, work, capsys)
        found = problems(case, outcome)
        if case.status == 0 and outcome.status == 0:
            assert "camcontact" in outcome.stdout and (work / "report.csv").exists()
        if found:
            failures[case.name] = found
        assert not (tmp_path / MARKER).exists(), case.name
    assert failures == {}


def test_nothing_executes_in_a_child_process_either(tmp_path):
    cases = [c for c in marker_cases(MARKER) if c.name in ("marker 0 in quantity", "marker 4 in sweep value")]
    assert len(cases) == 2
    for case in cases:
        outcome = run_subprocess(case, tmp_path, timeout=SUBPROCESS_SECONDS)
        assert problems(case, outcome) == [], outcome.stderr
        assert not (tmp_path / MARKER).exists()
