"""The documentation site builds with warnings as errors (issue 21): the API reference from the docstrings, the
tutorials executed into a gallery, the plugin page and the accuracy-vs-time page with the benchmarks' quick
results. Needs the ``docs`` extra (the README's install command has it); without Sphinx the test is skipped."""

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def test_docs_site_builds_without_warnings(tmp_path):
    pytest.importorskip("sphinx")
    pytest.importorskip("numpydoc")
    pytest.importorskip("sphinx_gallery")
    pytest.importorskip("matplotlib")
    out = tmp_path / "html"
    completed = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-E", "-q", "-b", "html",
                                str(ROOT / "docs"), str(out)], capture_output=True, text=True, timeout=900,
                               env={**__import__("os").environ, "MPLBACKEND": "Agg"})
    assert completed.returncode == 0, completed.stderr[-5000:]
    assert completed.stderr.strip() == "", completed.stderr[-5000:]
    # every tutorial executed, with its printed output and figures
    tutorials = sorted(p.stem for p in (ROOT / "tutorials").glob("[0-9][0-9]_*.py"))
    for name in tutorials:
        page = (out / "tutorials" / f"{name}.html").read_text(encoding="utf-8")
        assert "sphx-glr-script-out" in page and "sphinx_gallery_start_ignore" not in page, name
    assert "<img" in (out / "tutorials" / "06_ball_cone_cvt.html").read_text(encoding="utf-8")
    # the API reference: the classes users start from, with their units and references
    analysis = (out / "_generated" / "api" / "camcontact.Analysis.html").read_text(encoding="utf-8")
    assert "available_outputs" in analysis
    assert "Johnson, Greenwood" in (out / "_generated" / "api" / "camcontact.models.mixed_lubrication.html").read_text(
        encoding="utf-8")
    assert "camcontact-extras" in (out / "plugins.html").read_text(encoding="utf-8")
    accuracy = (out / "accuracy.html").read_text(encoding="utf-8")
    assert "accuracy_vs_time.png" in accuracy and "EHL Eyring + asperities" in accuracy
