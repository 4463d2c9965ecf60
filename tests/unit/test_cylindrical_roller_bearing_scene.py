"""The cylindrical_roller_bearing scene end to end: per-roller report, lives, misalignment, plot."""

import matplotlib
import numpy as np
import pytest

import camcontact as cc
from camcontact.errors import InputError

matplotlib.use("Agg")
STEEL = cc.Material(E="207 GPa", nu=0.3)
OIL = cc.Lubricant(name="ISO VG 68", nu40="68 cSt", nu100="8.6 cSt", density="0.87 g/cm^3", alpha="2.2e-8 1/Pa")


def scene(**changes):
    bearing = cc.CylindricalRollerBearing(designation="NU 206", bore="30 mm", outer_diameter="62 mm", width="16 mm",
                                          roller_count=13, roller_diameter="9 mm", roller_length="10 mm", C="44 kN",
                                          C0="36.5 kN", fatigue_load_limit="4.55 kN", material=STEEL,
                                          roughness="0.1 um")
    fields = dict(bearing=bearing, radial_load="8.8 kN", speed="3000 rpm", lubricant=OIL, temperature="70 degC",
                  contamination=0.5)
    return cc.LoadedCylindricalRollerBearing(**(fields | changes))


def test_report_per_roller_and_lives():
    result = cc.Analysis(scene()).run()
    frame = result.to_frame()
    assert len(frame) == 13 and frame["loaded"].sum() == 7
    assert (frame.loc[~frame["loaded"].astype(bool), "contact_regime"] == "unloaded").all()
    assert result["P"] == 8800.0 and result["L10"] == pytest.approx((44 / 8.8) ** (10 / 3) * 1e6, rel=1e-12)
    assert result["L_nm"] == pytest.approx(result["a_ISO"] * result["L10"], rel=1e-12)
    assert result["L10r"] / result["L10"] == pytest.approx(3.41, rel=0.02)  # tests/literature/test_iso_ts16281_roller
    assert result["Lambda_bearing"] == pytest.approx(np.nanmin(np.concatenate([result["Lambda_inner"],
                                                                            result["Lambda_outer"]])))


def test_every_nan_has_its_reason_beside_it():
    from camcontact.report import unexplained_values

    result = cc.Analysis(scene()).run()
    assert unexplained_values(result.to_frame()) == [] and unexplained_values(result.summary_frame()) == []


def test_misalignment_lowers_l10r_only():
    aligned = cc.Analysis(scene(), outputs=["L10", "L10r", "lamina_moment"]).run()
    tilted = cc.Analysis(scene(misalignment="4 arcmin"), outputs=["L10", "L10r", "lamina_moment"]).run()
    assert tilted["L10"] == aligned["L10"] and tilted["L10r"] == pytest.approx(0.875 * aligned["L10r"], rel=0.01)
    assert abs(tilted["lamina_moment"]) > 1.0 > abs(aligned["lamina_moment"])


def test_only_what_is_asked_runs_and_missing_inputs_are_named():
    result = cc.Analysis(scene(lubricant=None, temperature=None), outputs=["Q_max", "L10r"]).run()
    assert {record.step for record in result.records} == {"load_distribution", "reference_life"}
    with pytest.raises(InputError, match="LoadedCylindricalRollerBearing.lubricant"):
        cc.Analysis(scene(lubricant=None), outputs=["h_min_bearing"]).run()
    with pytest.raises(InputError, match="laminae = 10"):
        scene(laminae=10)


def test_plot(tmp_path):
    result = cc.Analysis(scene(misalignment="2 arcmin")).run()
    fig = result.plot()
    titles = [ax.get_title() for ax in fig.axes]
    assert "roller load Q [kN]" in titles and "pressure along the rollers, misalignment 2'" in titles
    along = next(ax for ax in fig.axes if ax.get_title().startswith("pressure along"))
    assert [t.get_text() for t in along.get_legend().get_texts()] == ["0°", "±28°", "±55°", "±83°"]
    fig.savefig(tmp_path / "crb.png")
