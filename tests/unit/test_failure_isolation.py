"""Per-step failure isolation (issue 18): a step that fails leaves NaN in its own outputs with the reason and
keeps everything else; ``strict=True`` raises. (Broken plugins: tests/plugins/test_broken_plugins.py.)"""

from __future__ import annotations

import attrs
import numpy as np
import pytest

import camcontact as cc
from camcontact.errors import ConvergenceError, InputError, StepFailureWarning
from camcontact.scene_file import load_scene


@pytest.fixture
def contact(oiled_contact):
    return oiled_contact


def test_a_multigrid_film_that_diverges_keeps_the_other_variant_and_the_contact(contact):
    """At 10 MN on 15 mm (p_h 55 GPa, M = 4.9e4) every attempt of the line solver diverges: it raised
    ConvergenceError out of run() although the film model is not strict, and took the formula's row with it."""
    crushed = attrs.evolve(contact, load="10 MN")
    with pytest.warns(StepFailureWarning, match="step 'film' \\(multigrid\\): ConvergenceError: .*every attempt diverged"):
        result = cc.Analysis(crushed, outputs=["p_h", "h_c", "regime"], models={"film": ["moes", "multigrid"]}).run()
    frame = result.to_frame().set_index("variant")
    assert frame.loc["moes", "h_c [µm]"] > 0 and not frame.loc["moes", "failed"]
    assert np.isnan(frame.loc["multigrid", "h_c [µm]"]) and frame.loc["multigrid", "failed"]
    assert frame["p_h [MPa]"].nunique() == 1 and frame["p_h [MPa]"].iloc[0] > 5e4
    # the step record says which step failed and how long it tried
    steps = result.steps_frame()
    failed = steps[steps["error"] != ""]
    assert list(failed["step"]) == ["film"] and list(failed["model"]) == ["multigrid"]
    with pytest.raises(ConvergenceError, match="every attempt diverged"):
        cc.Analysis(crushed, outputs=["h_c"], models={"film": "multigrid"}, strict=True).run()


def test_a_bearing_outside_the_iso281_range_keeps_every_roller():
    """At 0.01 rpm kappa = 0.000486 < 0.1: ISO 281 gives no a_ISO. The modified life is NaN with the reason; the
    load distribution, the films, L10 and the friction are all there (they were lost with the InputError)."""
    scene = load_scene("tutorials/pellet_mill_bearing.toml").component
    with pytest.warns(StepFailureWarning, match="kappa = 0.000485"):
        result = cc.Analysis(attrs.evolve(scene, outer_speed="0.01 rpm")).run()
    summary = result.summary_frame()
    assert summary.loc[0, "failed"] and "step 'modified_life' (iso281): InputError: a_ISO: kappa" in summary.loc[0, "error"]
    assert np.isnan(summary.loc[0, "L_nm [Mrev]"]) and summary.loc[0, "L10 [Mrev]"] > 0
    rollers = result.to_frame()
    assert rollers["failed"].all()  # the variant failed a step; its per-roller rows say so too
    assert (rollers["h_min_inner [µm]"].dropna() > 0).all() and len(rollers["h_min_inner [µm]"].dropna()) > 0
    with pytest.raises(InputError, match="kappa = 0.000485"):
        cc.Analysis(attrs.evolve(scene, outer_speed="0.01 rpm"), strict=True).run()


def test_a_shared_step_that_fails_fails_in_every_variant(steel):
    """u_m = 0: the EHL groups (shared by both film variants) fail; each variant's row says so, the step runs
    once, and the outputs that do not need it (Hertz) are in both rows."""
    oil = cc.Lubricant(alpha="2.2e-8 1/Pa", roelands_z=0.68)
    still = cc.LineContact(body1=cc.Body(material=steel, radius="20 mm", speed="1 m/s"),
                           body2=cc.Body(material=steel, radius="10 mm", speed="-1 m/s"),
                           load="1 kN", length="10 mm", lubricant=oil)
    with pytest.warns(StepFailureWarning) as caught:
        result = cc.Analysis(still, outputs=["b", "h_c"], models={"film": ["moes", "grubin"]}).run()
    assert len(caught) == 1
    frame = result.to_frame()
    assert list(frame["failed"]) == [True, True] and (frame["b [µm]"] > 0).all() and frame["h_c [µm]"].isna().all()
    assert [r.step for r in result.records].count("ehl_groups") == 1
    primary = [(f.step, f.variant) for f in result.failures if not f.skipped]
    assert primary == [("ehl_groups", "moes"), ("ehl_groups", "grubin")]
    assert result["h_c"] == [None, None]


def test_no_failure_no_status_columns_and_strict_must_be_a_boolean(contact):
    frame = cc.Analysis(contact, outputs=["h_c"]).run().to_frame()
    assert list(frame.columns) == ["h_c [µm]"]
    with pytest.raises(InputError, match=r"Analysis.strict = 'yes'; allowed: True or False"):
        cc.Analysis(contact, strict="yes")


def test_a_sweep_case_with_a_failed_step_says_why_and_errors_raise_keeps_its_type(contact):
    """body2 at -3 m/s: u_m = 0, no film. The case keeps its Hertz values; its row is failed with the step's
    reason in `error`; errors="raise" runs the cases strictly and raises the step's own InputError."""
    analysis = cc.Analysis(contact, outputs=["p_h", "h_c"])
    grid = {"body2.speed": ["3 m/s", "-3 m/s"]}
    with pytest.warns(StepFailureWarning):
        frame = analysis.sweep(grid, progress=False)
    assert list(frame["failed"]) == [False, True]
    assert frame.loc[0, "error"] == "" and frame.loc[1, "error"].startswith("step 'ehl_groups': InputError: line contact: "
                                                                            "entrainment speed u_m")
    assert frame["p_h [MPa]"].notna().all() and np.isnan(frame.loc[1, "h_c [µm]"])
    with pytest.raises(InputError, match="entrainment speed") as info:
        analysis.sweep(grid, progress=False, errors="raise")
    assert any("sweep case 1" in note for note in info.value.__notes__)
