"""Broken plugins are isolated: at discovery (sys.exit, KeyboardInterrupt on import) and at run time (NaN,
negative and raising models), the other models and variants keep their rows and the report names the plugin.

The distribution ``camcontact-broken`` (tests/plugins/broken_dist) is never installed: the tests put its
directory, which holds the package and its ``.dist-info`` with the entry points, on ``sys.path``, where
``importlib.metadata`` finds it like an installed distribution.
"""

from __future__ import annotations

import os
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
from cli_corpus import LINE  # a valid line-contact scene file (tests/cli_corpus.py)

import camcontact as cc
from camcontact import registry
from camcontact.errors import PluginError, PluginLoadWarning, StepFailureWarning
from camcontact.models.base import FilmModel

HERE = Path(__file__).parent
BROKEN = HERE / "broken_dist"
INTERRUPTING = HERE / "interrupting_dist"
SOURCE = "camcontact-broken 0.1.0"


@pytest.fixture
def broken(clean_registry, monkeypatch):
    """The registry with camcontact-broken on the path and entry-point discovery on."""
    monkeypatch.delenv("CAMCONTACT_DISABLE_PLUGIN_AUTOLOAD", raising=False)
    monkeypatch.syspath_prepend(str(BROKEN))
    for name in [m for m in sys.modules if m.startswith("camcontact_broken")]:
        monkeypatch.delitem(sys.modules, name)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        rows = {row.name: row for row in registry.entries("film_models")}
    return rows, caught


@pytest.fixture
def contact(oiled_contact):
    return oiled_contact


def test_a_plugin_that_exits_or_interrupts_on_import_fails_alone(broken):
    rows, caught = broken
    assert rows["exits_on_import"].status == "failed: SystemExit: camcontact_broken.exits: leaving on import"
    assert rows["interrupts_on_import"].status.startswith("failed: PluginLoadError: entry point "
                                                          "camcontact_broken.interrupts:InterruptFilm raised "
                                                          "KeyboardInterrupt on import (no Ctrl-C was pressed)")
    # the others load, the built-ins are untouched
    for name in ("nan_film", "raising_film", "negative_film", "first_twin", "second_twin"):
        assert rows[name].status == "ok" and rows[name].source == SOURCE
    assert rows["moes"].status == "ok"
    messages = [str(w.message) for w in caught if issubclass(w.category, PluginLoadWarning)]
    assert len(messages) == 2 and all(SOURCE in m for m in messages)


def test_the_users_own_ctrl_c_while_a_plugin_loads_is_not_swallowed(clean_registry, monkeypatch):
    monkeypatch.delenv("CAMCONTACT_DISABLE_PLUGIN_AUTOLOAD", raising=False)
    monkeypatch.syspath_prepend(str(INTERRUPTING))
    monkeypatch.delitem(sys.modules, "camcontact_interrupting", raising=False)
    with pytest.raises(KeyboardInterrupt):
        registry.available("film_models")


def test_models_are_reached_by_their_entry_point_names(broken, contact):
    """Both classes are named 'twin'; keyed by class name one of them was unreachable."""
    result = cc.Analysis(contact, outputs=["h_c"], models={"film": ["first_twin", "second_twin"]}).run()
    assert result["h_c"] == [1e-6, 2e-6]


def test_nan_negative_and_raising_plugins_leave_the_other_variants_whole(broken, contact):
    reference = cc.Analysis(contact, outputs=["p_h", "h_c", "h_min"], models={"film": "pan_hamrock"}).run()
    models = {"film": ["pan_hamrock", "nan_film", "raising_film", "negative_film"]}
    with pytest.warns(StepFailureWarning) as caught:
        result = cc.Analysis(contact, outputs=["p_h", "h_c", "h_min"], models=models).run()
    assert len(caught) == 3
    frame = result.to_frame().set_index("variant")
    assert list(frame["failed"]) == [False, True, True, True]
    # the working variant's row is the one it gives alone
    assert frame.loc["pan_hamrock", "h_c [µm]"] == 1e6 * reference["h_c"]
    assert frame.loc["pan_hamrock", "error"] == ""
    # every row keeps what does not depend on the film model; every NaN has its reason
    assert np.allclose(frame["p_h [MPa]"], 1e-6 * reference["p_h"])
    assert frame.loc[["nan_film", "raising_film", "negative_film"], "h_c [µm]"].isna().all()
    plugin = "plugin {!r} (film_models) from " + SOURCE + " failed: "
    assert frame.loc["nan_film", "error"].startswith("step 'film' (nan_film): " + plugin.format("nan_film")
                                                     + "ModelOutputError: model 'nan_film' (film_models, ")
    assert "gave h_c = nan (not finite); h_min = -inf (not finite)" in frame.loc["nan_film", "error"]
    assert frame.loc["raising_film", "error"] == ("step 'film' (raising_film): " + plugin.format("raising_film")
                                                  + "KeyError: 'h_c'")
    assert "h_c = -1e-07 (allowed: > 0)" in frame.loc["negative_film", "error"]
    # the skipped steps downstream are in the failure record, not repeated in the report
    skipped = [f for f in result.failures if f.skipped]
    assert {f.step for f in skipped} == {"film_thickness"}
    assert all("which step 'film' could not give" in f.reason for f in skipped)


def test_strict_raises_a_plugin_error_naming_plugin_distribution_and_step(broken, contact):
    with pytest.raises(PluginError, match=r"plugin 'raising_film' \(film_models\) from camcontact-broken 0.1.0 "
                                          r"failed: KeyError: 'h_c' \(step 'film'\)") as info:
        cc.Analysis(contact, outputs=["h_c"], models={"film": "raising_film"}, strict=True).run()
    assert info.value.source.endswith(SOURCE) and info.value.step == "film"
    assert isinstance(info.value.__cause__, KeyError)


class ZeroFilm(FilmModel):
    """A user's own film model (not built in, not from an entry point) that gives a closed film."""

    name = "zero_film"
    requires = ("R", "w", "E_reduced", "u_m", "eta0", "alpha")
    provides = ("h_c",)

    def evaluate(self, R, w, E_reduced, u_m, eta0, alpha):
        return {"h_c": 0.0}


def test_a_users_own_model_is_checked_and_named(contact):
    with pytest.warns(StepFailureWarning, match=r"model 'zero_film' \(film_models, [\w.]*ZeroFilm\) "
                                                r"failed: ModelOutputError: .*h_c = 0.0 \(allowed: > 0\)"):
        result = cc.Analysis(contact, outputs=["b", "h_c"], models={"film": ZeroFilm()}).run()
    assert result["b"] > 0 and result["h_c"] is None and result.failures[0].step == "film"


def test_the_command_line_survives_the_broken_distribution(tmp_path):
    """In a fresh process with camcontact-broken on the path: `camcontact plugins` lists the failures,
    and a scene with a working and a broken film model reports both rows and exits 0."""
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(BROKEN), os.environ.get("PYTHONPATH", "")]),
           "CAMCONTACT_DISABLE_PLUGIN_AUTOLOAD": ""}
    listing = subprocess.run([sys.executable, "-m", "camcontact", "plugins", "--family", "film_models"],
                             capture_output=True, text=True, env=env, timeout=120, cwd=tmp_path)
    assert listing.returncode == 0, listing.stderr
    assert "failed: SystemExit" in listing.stdout and "nan_film" in listing.stdout
    scene = tmp_path / "scene.toml"
    scene.write_text(LINE.replace('film = "moes"', 'film = ["moes", "raising_film"]'))
    run = subprocess.run([sys.executable, "-m", "camcontact", "run", str(scene), "--csv", str(tmp_path / "r.csv")],
                         capture_output=True, text=True, env=env, timeout=120, cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert "Traceback" not in run.stderr
    report = (tmp_path / "r.csv").read_text()
    assert "moes" in report and "plugin 'raising_film' (film_models) from camcontact-broken 0.1.0" in report
