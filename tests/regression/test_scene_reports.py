"""Golden reports: the complete reports of the default scene, every tutorial scene file and the cam
scene with the lumped dynamics and with the multigrid film are what they were when frozen
(tests/regression/scene_reports.py; floats to 1e-12 relative to their column's largest magnitude,
text exactly; outputs a scene refuses are refused with the same message)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import camcontact as cc
from camcontact.report import unexplained_values

from .scene_reports import GOLDEN, cases, load, report

CASES = cases()
RTOL = 1e-12


def test_every_golden_file_has_its_case():
    assert sorted(p.stem for p in GOLDEN.glob("*.json")) == sorted(CASES)


def _number(cell):
    if isinstance(cell, dict) and "float" in cell:
        return float(cell["float"])
    return cell


def assert_same_frame(name: str, frozen: dict, now: dict) -> None:
    assert now["columns"] == frozen["columns"], name
    assert len(now["rows"]) == len(frozen["rows"]), name
    for k, column in enumerate(frozen["columns"]):
        old = [_number(row[k]) for row in frozen["rows"]]
        new = [_number(row[k]) for row in now["rows"]]
        numeric = [v for v in old if isinstance(v, float) and math.isfinite(v)]
        scale = max((abs(v) for v in numeric), default=0.0)
        for i, (a, b) in enumerate(zip(old, new)):
            where = f"{name}: {column}, row {i}"
            if isinstance(a, float):
                assert isinstance(b, float), f"{where}: {b!r} instead of {a!r}"
                if math.isnan(a):
                    assert math.isnan(b), f"{where}: {b!r} instead of NaN"
                else:
                    assert b == a or abs(b - a) <= RTOL * scale, f"{where}: {b!r} instead of {a!r}"
            else:
                assert b == a, f"{where}: {b!r} instead of {a!r}"


@pytest.mark.parametrize("name", sorted(CASES))
def test_report_is_unchanged(name):
    component, models, effects = CASES[name]
    frozen = load(name)
    now = report(component, models, effects, frozen["outputs"])
    assert sorted(now) == sorted(k for k in frozen if k.endswith("_frame"))
    for frame in now:
        assert_same_frame(f"{name} {frame}", frozen[frame], now[frame])
    for output, message in frozen["refused"].items():
        with pytest.raises(cc.InputError) as error:
            cc.Analysis(component, outputs=[output], models=models, effects=effects, strict=True).run()
        assert str(error.value) == message


def test_golden_comparison_fails_on_a_changed_value():
    frozen = {"columns": ["a [m]", "b"], "rows": [[1.0, "x"], [{"float": "nan"}, "y"]]}
    assert_same_frame("same", frozen, {"columns": ["a [m]", "b"], "rows": [[1.0 + 1e-13, "x"], [{"float": "nan"}, "y"]]})
    for changed in ([[1.0 + 1e-9, "x"], [{"float": "nan"}, "y"]], [[1.0, "x"], [0.0, "y"]],
                    [[1.0, "z"], [{"float": "nan"}, "y"]]):
        with pytest.raises(AssertionError):
            assert_same_frame("changed", frozen, {"columns": ["a [m]", "b"], "rows": changed})
    assert np.isnan(_number({"float": "nan"}))


@pytest.mark.parametrize("name", sorted(CASES))
def test_every_nan_of_the_complete_report_has_its_reason(name):
    """Issue 18: no silent NaN. Every NaN or infinite number of the complete report (every output the scene
    can give) has its reason in the same row: a failed step, an output this variant's models do not give,
    an unloaded roller, gross slip, a correlation outside its validity (camcontact.report.unexplained_values)."""
    component, models, effects = CASES[name]
    frozen = load(name)
    result = cc.Analysis(component, outputs=frozen["outputs"], models=models, effects=effects).run()
    frames = [result.to_frame()] + ([result.summary_frame()] if result.index is not None else [])
    for frame in frames:
        assert unexplained_values(frame) == []
