"""The bearing scene (LoadedBearing): steps on demand, per-roller reports, kinematics, bad input."""

import math

import numpy as np
import pytest

import camcontact as cc
from camcontact.errors import InputError

STEEL = cc.Material(E="210 GPa", nu=0.3)
OIL = cc.Lubricant(name="mineral base oil", nu40="575 mm^2/s", nu100="50 mm^2/s", density="920 kg/m^3",
                   alpha="2.0e-8 1/Pa")


def bearing(**changes):
    arguments = dict(designation="test", bore="200 mm", outer_diameter="310 mm", width="109 mm", rollers_per_row=25,
                     roller_diameter="27 mm", roller_length="41.35 mm", contact_angle="9 deg", C="1700 kN",
                     C0="2120 kN", radial_clearance="0.1 mm", fatigue_load_limit="200 kN", material=STEEL,
                     roughness="0.23 um")
    arguments.update(changes)
    return cc.SphericalRollerBearing(**arguments)


def scene(**changes):
    arguments = dict(bearing=bearing(), radial_load="150 kN", axial_load="10 kN", outer_speed="300 rpm",
                     lubricant=OIL, temperature="85 degC", contamination=0.5)
    arguments.update(changes)
    return cc.LoadedBearing(**arguments)


def test_only_the_needed_steps_run():
    analysis = cc.Analysis(scene(), outputs=["Q_max"])
    assert analysis.steps() == ["load_distribution"]
    assert cc.Analysis(scene(), outputs=["L10h"]).steps() == ["equivalent_load", "rating_life"]
    result = cc.Analysis(scene(), outputs=["Q_max", "L10h"]).run()
    assert {r.step for r in result.records} == {"load_distribution", "equivalent_load", "rating_life"}


def test_full_report_per_roller_and_summary():
    result = cc.Analysis(scene()).run()
    frame = result.to_frame()
    assert len(frame) == 50 and "Q [kN]" in frame and "contact_regime" in frame
    Q = np.asarray(result["Q"])
    unloaded = Q == 0.0
    assert unloaded.any() and (~unloaded).any()
    regimes = np.asarray(result["contact_regime"])
    assert set(regimes[unloaded]) == {"unloaded"} and "unloaded" not in set(regimes[~unloaded])
    assert np.all(np.isnan(np.asarray(result["h_min_inner"])[unloaded]))
    assert np.all(np.isfinite(np.asarray(result["h_min_inner"])[~unloaded]))
    summary = result.summary_frame()
    assert summary["L_nmh [h]"].iloc[0] > summary["L10h [h]"].iloc[0] > 0  # a_ISO > 1 for this clean, thick-film case
    # the roller loads balance the applied load (radial and axial components)
    alpha = math.radians(9)
    rows = np.asarray(result["roller_row"])
    azimuth = np.asarray(result["azimuth"])
    assert np.sum(Q * np.cos(azimuth)) * math.cos(alpha) == pytest.approx(150e3, rel=1e-9)
    assert np.sum(Q * np.where(rows == 1, 1.0, -1.0)) * math.sin(alpha) == pytest.approx(10e3, rel=1e-9)


def test_pure_rolling_kinematics():
    """Outer ring at 300 rpm, inner fixed: cage at 150 (1 + gamma) rpm, u_m = (pi d_m/2)(1 - gamma^2) n."""
    result = cc.Analysis(scene(), outputs=["cage_speed", "roller_speed", "u_m"]).run()
    gamma = 0.027 * math.cos(math.radians(9)) / 0.255
    assert result["cage_speed"] * 30 / math.pi == pytest.approx(150 * (1 + gamma))
    assert result["u_m"] == pytest.approx(0.5 * math.pi * 0.255 * (1 - gamma**2) * 5.0)
    # the roller surface moves with the raceways: pi D_w n_R = u_m
    assert 0.5 * 0.027 * result["roller_speed"] == pytest.approx(result["u_m"])


@pytest.mark.parametrize("changes", [dict(radial_load="0 kN", axial_load="80 kN"), dict(radial_load="0 kN"),
                                     dict(bearing=bearing(radial_clearance="1 mm"), radial_load="2 kN")])
def test_hard_load_cases_stay_finite_and_flagged(changes):
    """Pure axial load, no load at all, a clearance much larger than the elastic approach."""
    result = cc.Analysis(scene(**changes), outputs=["Q", "p_h_inner", "h_min_inner", "contact_regime", "L10h",
                                                    "force_residual"]).run()
    Q = np.asarray(result["Q"])
    assert np.all(np.isfinite(Q)) and result["force_residual"] < 1e-5
    regimes = np.asarray(result["contact_regime"])
    assert np.all((regimes == "unloaded") == (Q == 0.0))
    assert np.all(np.isfinite(np.asarray(result["h_min_inner"])[Q > 0]))
    assert result["L10h"] > 0


def test_missing_and_bad_inputs_are_named():
    with pytest.raises(InputError, match="contamination"):
        cc.Analysis(scene(contamination=None), outputs=["L_nm"])
    with pytest.raises(InputError, match="fatigue_load_limit"):
        cc.Analysis(scene(bearing=bearing(fatigue_load_limit=None)), outputs=["L_nm"])
    no_density = cc.Lubricant(name="grease without base-oil data", eta0="0.07 Pa*s", alpha="2e-8 1/Pa")
    with pytest.raises(InputError, match="kinematic viscosity"):
        cc.Analysis(scene(lubricant=no_density), outputs=["kappa"], strict=True).run()
    with pytest.raises(InputError, match="no entrainment"):
        cc.Analysis(scene(speed="300 rpm"), outputs=["h_min_bearing"], strict=True).run()
    with pytest.raises(InputError, match="unknown model slots"):
        cc.Analysis(scene(), models={"wear": "archard"})


def test_kelley_friction_and_flash_temperature_per_contact():
    """Each loaded contact gets the Kelley mu of its own roller load (Delabenetta Eq. 49 evaluated by
    hand here) and a flash temperature; unloaded rollers have none; the friction power is
    sum(mu Q |u1 - u2|) over both raceways. Without a slide/roll ratio the step cannot run (named)."""
    thermal_steel = cc.Material(E="210 GPa", nu=0.3, density="7810 kg/m^3", specific_heat="464 J/(kg K)",
                                thermal_conductivity="42.4 W/(m K)")
    case = scene(bearing=bearing(material=thermal_steel), slide_roll_ratio=0.05)
    result = cc.Analysis(case, outputs=["Q", "u_m", "eta0", "friction_coefficient_inner", "friction_coefficient_outer",
                                        "flash_temperature_inner", "friction_power"], models={"friction": "kelley"}).run()
    Q, u_m, eta = np.asarray(result["Q"]), result["u_m"], result["eta0"]
    u1, u2 = u_m * 1.025, u_m * 0.975
    loaded = Q > 0
    expected = 0.0127 * np.log10(29.66e-3 * Q[loaded] / (eta * 41.35e-3 * (u1 - u2) * (u1 + u2) ** 2))
    mu = np.asarray(result["friction_coefficient_inner"])
    assert mu[loaded] == pytest.approx(expected, rel=1e-12)
    assert np.all(np.isnan(mu[~loaded])) and np.all(np.isnan(np.asarray(result["flash_temperature_inner"])[~loaded]))
    assert np.all(np.asarray(result["flash_temperature_inner"])[loaded] > 0)
    power = 2 * np.sum(expected * Q[loaded]) * (u1 - u2)  # the same mu at both raceways (same Q, l, speeds)
    assert result["friction_power"] == pytest.approx(power, rel=1e-12)
    with pytest.raises(InputError, match="slide_roll_ratio: set LoadedBearing.slide_roll_ratio"):
        cc.Analysis(scene(), outputs=["friction_power"])
    with pytest.raises(InputError, match="effusivity"):
        cc.Analysis(scene(slide_roll_ratio=0.05), outputs=["flash_temperature_outer"])


def test_kelley_validity_and_load_zone_in_the_report():
    """Per roller, booleans say whether each raceway contact lies inside the Kelley correlation's validity
    (slide-to-roll ratio in [0.01, 2]): 0.2 % slip flags every loaded contact, 5 % none; unloaded
    rollers are False; the reason is text in the summary. The summary gives Harris's load zone
    arccos((c/2 - s delta_a tan alpha)/delta_r) of the wider row, the last loaded roller's azimuth
    (inside it) and the count of loaded rollers."""
    thermal_steel = cc.Material(E="210 GPa", nu=0.3, density="7810 kg/m^3", specific_heat="464 J/(kg K)",
                                thermal_conductivity="42.4 W/(m K)")
    names = ["Q", "friction_valid_inner", "friction_valid_outer", "friction_validity", "load_zone",
             "last_loaded_azimuth", "loaded_rollers", "delta_r", "delta_a"]
    for slip, inside in ((0.002, False), (0.05, True)):
        result = cc.Analysis(scene(bearing=bearing(material=thermal_steel), slide_roll_ratio=slip), outputs=names,
                             models={"friction": "kelley"}).run()
        loaded = np.asarray(result["Q"]) > 0
        frame = result.to_frame()
        for race in ("inner", "outer"):
            column = frame[f"friction_valid_{race}"]
            assert column.dtype == bool
            np.testing.assert_array_equal(column.to_numpy(), loaded & inside)
        assert (result["friction_validity"] == "ok") is inside
    zones = [math.acos((0.05e-3 - s * result["delta_a"] * math.tan(math.radians(9))) / result["delta_r"])
             for s in (1.0, -1.0)]
    assert result["load_zone"] == pytest.approx(max(zones), rel=1e-12)
    assert result["last_loaded_azimuth"] <= result["load_zone"] < result["last_loaded_azimuth"] + 2 * math.pi / 25
    assert result["loaded_rollers"] == float(loaded.sum())
    summary = result.summary_frame()
    assert summary["load_zone [deg]"].iloc[0] == pytest.approx(math.degrees(max(zones)), rel=1e-12)


def test_fluid_traction_is_the_default_bearing_friction_and_falls_with_the_slip():
    """Issue 16 error 4: EHL traction falls to zero with the slip where Kelley's correlation rises; the default
    raceway friction is the film's Eyring traction (limiting shear stress), equal to a direct call of the model
    at each contact, valid at 0.2 % slip."""
    from camcontact import registry

    thermal_steel = cc.Material(E="210 GPa", nu=0.3, density="7810 kg/m^3", specific_heat="464 J/(kg K)",
                                thermal_conductivity="42.4 W/(m K)")
    names = ["Q", "u_m", "p_h_inner", "b_inner", "h_c_inner", "friction_coefficient_inner", "friction_valid_inner"]
    mus = {}
    for slip in (0.002, 0.05):
        case = scene(bearing=bearing(material=thermal_steel), slide_roll_ratio=slip)
        result = cc.Analysis(case, outputs=names).run()
        loaded = np.asarray(result["Q"]) > 0
        mu = np.asarray(result["friction_coefficient_inner"])[loaded]
        state = case.lubricant.state(case.si.temperature)
        direct = registry.get("traction_models", "eyring").contact(
            np.asarray(result["p_h_inner"])[loaded], np.asarray(result["b_inner"])[loaded],
            np.asarray(result["h_c_inner"])[loaded], result["u_m"], state).coefficient(slip * result["u_m"])
        np.testing.assert_allclose(mu, np.abs(direct), rtol=1e-12)
        assert np.asarray(result["friction_valid_inner"])[loaded].all()
        mus[slip] = mu
    assert np.all(mus[0.002] < mus[0.05]) and np.all(mus[0.05] < 0.08)


def test_numerical_film_in_the_bearing_scene():
    from camcontact.models.film_multigrid import Multigrid

    result = cc.Analysis(scene(radial_load="60 kN"), outputs=["h_min_inner", "h_min_outer", "Q"],
                         models={"film": [Multigrid(levels=5), "pan_hamrock"]}).run()
    numeric, formula = (np.asarray(v) for v in result["h_min_inner"])
    loaded = np.asarray(result["Q"][0]) > 0
    assert np.allclose(numeric[loaded], formula[loaded], rtol=0.25)


def test_bearing_plot(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    result = cc.Analysis(scene()).run()
    figure = result.plot()
    figure.savefig(tmp_path / "bearing.png")
    titles = [ax.get_title() for ax in figure.axes]
    assert titles == ["roller load Q [kN]", "Hertz pressure per contact", "minimum film per contact",
                      "film parameter per contact"]
    # Lambda per roller with its regime bands (the plot's y range covers the mixed band at least)
    lam = figure.axes[3]
    assert lam.get_ylim()[1] >= 3.0 and {"boundary", "mixed"} <= {t.get_text() for t in lam.get_legend().get_texts()}
    with pytest.raises(cc.InputError, match="unknown bearing plot panels \\['kappa'\\]"):
        result.plot(panels=("kappa",))
