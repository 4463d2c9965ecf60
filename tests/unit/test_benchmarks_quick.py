"""Benchmarks run in quick mode (their timings are reported, never asserted)."""

import importlib.util
from pathlib import Path

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
