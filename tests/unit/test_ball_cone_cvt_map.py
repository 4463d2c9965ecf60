"""Efficiency and traction-margin maps of the ball-cone CVT (camcontact.scenes.ball_cone_cvt_map, issue 17).

The map is the scene swept over ratio x power (x ball diameter): each row must equal the scene run alone at that
point; the columns it adds (the weaker contact's margin, either contact's gross slip) follow from the per-contact
ones; bad axes are named before anything runs; the plot marks gross slip and the stress limit.
"""

import math
import sys
from pathlib import Path

import numpy as np
import pytest

import camcontact as cc
from camcontact.errors import InputError
from camcontact.scenes.ball_cone_cvt_map import MAP_OUTPUTS, cvt_map, plot_cvt_map

sys.path.insert(0, str(Path(__file__).parent))
from test_ball_cone_cvt_scene import cvt, point  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore::camcontact.errors.ValidityWarning")


def test_rows_are_the_scene_run_alone():
    """Each point of a 2 x 2 x 2 map equals Analysis(point).run() at it (1e-12); margin = the smaller contact's;
    power numbers are W."""
    frame = cvt_map(point(), [0.8, 1.6], [40.0, 300.0], ball_diameters=["14 mm", "18 mm"])
    assert len(frame) == 8 and set(frame["error"]) == {""}
    for _, row in frame.iterrows():
        scene = point(ratio=row["ratio [-]"], power=f"{row['power [W]']} W",
                      cvt=cvt(ball_diameter=f"{row['cvt.ball_diameter [mm]']} mm"))
        alone = cc.Analysis(scene, outputs=list(MAP_OUTPUTS)).run()
        assert row["efficiency [-]"] == pytest.approx(alone["efficiency"], rel=1e-12)
        assert row["p_h [MPa]"] == pytest.approx(alone["p_h"] / 1e6, rel=1e-12)
        assert row["traction_margin [-]"] == min(alone["traction_margin_in"], alone["traction_margin_out"])
        assert row["gross_slip"] == (alone["gross_slip_in"] or alone["gross_slip_out"])
        assert row["stress_limit_exceeded"] == alone["stress_limit_exceeded"]


def test_trends_and_the_thesis_clamping_slips():
    """Balanced clamping: the efficiency falls with power at each ratio (the spin loss grows faster than the power:
    F_n grows with the torque and the film's shear with it) and a larger ball lowers p_h. The thesis's clamping
    (Eq. 6.17, a quarter of the thrust balanced) cannot hold the balls with the EHL film's traction: gross slip at
    every point, efficiency NaN there (the drive does not transmit the power)."""
    frame = cvt_map(point(), [0.5, 1.0, 2.0], ["20 W", "150 W", "600 W"], ball_diameters=["14 mm", "20 mm"])
    for (ratio, ball), part in frame.groupby(["ratio [-]", "cvt.ball_diameter [mm]"]):
        efficiency = part.sort_values("power [W]")["efficiency [-]"].to_numpy()
        assert np.all(np.diff(efficiency) < 0), (ratio, ball)
    small, large = (frame[frame["cvt.ball_diameter [mm]"] == d]["p_h [MPa]"].to_numpy() for d in (14.0, 20.0))
    assert np.all(large < small)
    thesis = cvt_map(point(cvt=cvt(clamping="thesis")), [0.5, 1.0, 2.0], ["20 W", "600 W"])
    assert thesis["gross_slip"].all() and (thesis["traction_margin [-]"] < 0).all()
    assert thesis["efficiency [-]"].isna().all() and thesis["power_loss [W]"].isna().all()


@pytest.mark.parametrize("axes, match", [
    (dict(ratios=[1.0, 2.5]), r"ratio = 2.5 .* allowed: 0.5 .. 2"),
    (dict(powers=["0 W"]), r"LoadedBallConeCVT.power = 0 W .* allowed: 0 < power"),
    (dict(powers=[-5.0]), r"LoadedBallConeCVT.power = -5 W"),
    (dict(powers=[]), "powers is empty"),
    (dict(ratios=1.0), "ratios = 1.0; allowed: a list"),
    (dict(ball_diameters=["-14 mm"]), "ball_diameter"),
])
def test_bad_axes_are_named_before_anything_runs(axes, match):
    chosen = dict(ratios=[1.0], powers=[150.0]) | axes
    with pytest.raises(InputError, match=match):
        cvt_map(point(), **chosen)
    with pytest.raises(InputError, match="LoadedBallConeCVT"):
        cvt_map(point().cvt, [1.0], [150.0])


def test_power_quantity_array_and_plot(tmp_path):
    """A pint array of powers is one axis; the plot draws efficiency and margin per ball diameter (a colour bar
    each), the gross-slip points and the stress-limit hatching; a frame without two ratios is refused."""
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    from camcontact.units import Q_

    frame = cvt_map(point(cvt=cvt(traction_coefficient=0.1)), np.linspace(0.5, 2.0, 4), Q_([0.03, 0.3], "kW"),
                    models={"traction": "fastsim"}, ball_diameters=["12 mm", "16 mm"])
    assert sorted(set(frame["power [W]"])) == pytest.approx([30.0, 300.0])
    figure = plot_cvt_map(frame)
    assert len(figure.axes) == 8  # 2 rows x (efficiency, margin) + colour bars
    assert "ball 12 mm" in figure.axes[0].get_title()
    figure.savefig(tmp_path / "map.png")
    thesis = cvt_map(point(cvt=cvt(clamping="thesis")), [0.5, 1.0, 2.0], ["20 W", "200 W"])
    figure = plot_cvt_map(thesis)
    labels = [t.get_text() for t in figure.axes[1].get_legend().get_texts()]  # the margin panel
    assert "gross slip" in labels and "p_h above stress limit" in labels
    # the side that cannot transmit the power is hatched on both panels (the feasible side is the clear one)
    for panel in figure.axes[:2]:
        assert "margin < 0: gross slip (infeasible)" in [t.get_text() for t in panel.get_legend().get_texts()]
    # on the caller's axes (two per ball diameter) or figure; a wrong count of axes is named
    import matplotlib.pyplot as plt

    mine, axes = plt.subplots(1, 2, figsize=(10, 4), layout="constrained")
    assert plot_cvt_map(thesis, ax=axes) is mine and axes[1].get_title().startswith("traction margin")
    with pytest.raises(InputError, match="ax= gives 1 axes for 2 panels"):
        plot_cvt_map(thesis, ax=axes[0])
    assert len(plot_cvt_map(thesis, fig=plt.figure(figsize=(10, 4))).axes) == 3  # no efficiency: one colour bar
    plt.close("all")
    with pytest.raises(InputError, match="a map needs at least two"):
        plot_cvt_map(thesis[thesis["ratio [-]"] == 1.0])
    with pytest.raises(InputError, match="lacks"):
        plot_cvt_map(thesis.drop(columns=["gross_slip"]))
    assert math.isnan(thesis["efficiency [-]"].iloc[0])
