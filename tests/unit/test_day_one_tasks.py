"""Issue 21: a new user's three day-one tasks, done with what the README and ``help()`` show (top-level names,
``Analysis``, ``sweep_frame``, ``load_scene``, report frames) — each the way a valve-train, bearing or drive
engineer would write it in a notebook."""

from pathlib import Path

import attrs
import numpy as np
import pytest

import camcontact as cc

TUTORIALS = Path(__file__).resolve().parents[2] / "tutorials"


def test_roller_follower_lambda_for_two_oils_at_three_speeds_and_pick_one():
    """The LS-1 roller follower (the default scene) with a light and a heavy oil at 1000/2000/3000 rpm: the
    smallest Lambda over each turn, and the oil that keeps the larger one at the slowest speed."""
    follower = cc.load_scene().component
    oils = {"SAE 5W-20 like": cc.Lubricant(name="light", nu40="45 cSt", nu100="8 cSt", density="850 kg/m^3",
                                          alpha="20 1/GPa"),
            "SAE 15W-40 like": cc.Lubricant(name="heavy", nu40="110 cSt", nu100="14.5 cSt", density="870 kg/m^3",
                                           alpha="22 1/GPa")}
    table = {}
    for label, oil in oils.items():
        scene = attrs.evolve(follower, lubricant=oil, temperature="90 degC")  # the oil's viscosity at 90 °C
        frame = cc.sweep_frame(scene, {"speed": ["1000 rpm", "2000 rpm", "3000 rpm"]},
                               outputs=["h_min_cycle", "Lambda_min"], table="index", progress=False)
        table[label] = frame.groupby("speed [rpm]")["Lambda_min [-]"].min()
    for lam in table.values():
        assert list(lam.index) == [1000.0, 2000.0, 3000.0] and np.all(np.diff(lam.to_numpy()) > 0)  # faster: thicker
    pick = max(table, key=lambda label: table[label].loc[1000.0])
    assert pick == "SAE 15W-40 like" and table[pick].loc[1000.0] > table["SAE 5W-20 like"].loc[1000.0]


def test_spherical_roller_bearing_life_and_per_roller_table():
    scene = cc.load_scene(TUTORIALS / "pellet_mill_bearing.toml").component
    result = cc.Analysis(scene).run()
    summary, rollers = result.summary_frame(), result.to_frame()
    assert summary.loc[0, "L10h [h]"] > 0 and summary.loc[0, "L_nmh [h]"] > 0 and "L10 [Mrev]" in summary
    assert len(rollers) == scene.bearing.roller_count * 1 and {"Q [kN]", "p_h_inner [MPa]", "loaded"} <= set(
        rollers.columns)
    assert rollers["loaded"].dtype == bool and rollers["loaded"].any() and not rollers["loaded"].all()
    assert result.quantity("L10h").to("h").magnitude == pytest.approx(summary.loc[0, "L10h [h]"], rel=1e-12)


def test_cvt_operating_points_that_slip_are_a_boolean_column():
    """The Forti CVT over power x ratio with the thesis's clamping (Eq. 6.17, a quarter of the thrust) and the
    balanced one: the thesis's slips at every point, the balanced drive at none of them."""
    point = cc.load_scene(TUTORIALS / "forti_ball_cone_cvt.toml").component
    frame = cc.sweep_frame(point, {"power": ["50 W", "600 W", "1500 W"], "ratio": [0.5, 1.0, 2.0],
                                   "cvt.clamping": ["thesis", "axial_balance"]},
                           outputs=["gross_slip_in", "gross_slip_out", "efficiency"], progress=False)
    slipping = frame[frame["gross_slip_in"] | frame["gross_slip_out"]]
    assert frame["gross_slip_in"].dtype == bool and frame["gross_slip_out"].dtype == bool
    assert set(slipping["cvt.clamping"]) == {"thesis"} and len(slipping) == 9
    assert slipping["efficiency [-]"].isna().all() and frame.loc[~frame.index.isin(slipping.index),
                                                                  "efficiency [-]"].notna().all()
