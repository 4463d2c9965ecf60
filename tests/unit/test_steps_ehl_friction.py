"""Unit tests of the EHL friction steps (camcontact/steps/ehl_friction.py) with SI floats, and of the cam scene's
EHL friction effects (``mixed``, ``non_newtonian``, ``thermal``).

Independent references: the mixed step against a direct call of the load-sharing model it wraps; the friction
of a contact as mu_b W_a + mu_fluid W_f written out with the fluid coefficient of a direct call of the traction
model; a limiting-shear plateau mu = Lambda_L (tau_L0 = 0) at large slip; the roller's traction table
non-decreasing and equal to the plateau capacity at its ends.
"""

import attrs
import numpy as np
import pytest

import camcontact as cc
from camcontact import registry
from camcontact.errors import InputError
from camcontact.models.film_point import Nijenbanning
from camcontact.models.mixed_lubrication import mixed_line_contact, mixed_point_contact
from camcontact.scene_file import load_scene
from camcontact.models.film_line import Moes
from camcontact.steps.ehl_friction import (FLUID_TRACTION_LIMIT, ball_cone_mixed, contact_ehl_friction, ehl_sliding_friction,
                                           fluid_traction_table, mixed_contact, mixed_film_cycle, roller_mixed)
from step_checks import assert_provides

OIL = cc.Lubricant(alpha="2.2e-8 1/Pa", roelands_z=0.68)
STATE = OIL.state(None)
E = 210e9 / (1 - 0.3**2)
W = np.array([0.0, 1.0e5, 2.0e5])  # N/m (first: contact open)
R = np.full(3, 0.008)
U = np.array([2.0, 0.05, 3.0])


def test_mixed_film_cycle_wraps_the_load_sharing_model_and_marks_open_contacts():
    moes = np.r_[np.nan, Moes().evaluate(R[1:], W[1:], E, np.abs(U[1:]), STATE.eta0, STATE.alpha)["h_c"]]
    density = 0.05 / (6e-6 * 0.3e-6)
    out = mixed_film_cycle(W, R, E, U, STATE.eta0, STATE.alpha, moes, 0.3e-6, density, 6e-6, True)
    assert_provides(mixed_film_cycle, out)
    direct = mixed_line_contact(W[1:], R[1:], E, U[1:], STATE.eta0, STATE.alpha, 0.3e-6, density, 6e-6)
    np.testing.assert_allclose(out["asperity_load_fraction"][1:], direct["asperity_load_fraction"])
    np.testing.assert_allclose(out["h_c_mixed"][1:], direct["h_c"])
    assert out["lubrication_regime"][0] == "open" and out["asperity_load_fraction"][0] == 0.0
    assert out["asperity_load_fraction"][1] > out["asperity_load_fraction"][2]  # slower: more asperity load
    assert out["mixed_valid"].dtype == bool and not out["mixed_valid"][0]


def test_roller_mixed_is_the_load_sharing_of_each_roller_contact():
    """Rollers of 0, 4.135 and 8.27 kN on 41.35 mm (w = 0, 1e5, 2e5 N/m) at the inner (R 8 mm) and outer
    (R 12 mm) raceway, 2 m/s, both surfaces 0.2 um RMS (composite 0.283 um): each race equals
    mixed_film_cycle with its radius; the unloaded roller is "unloaded" with no share (NaN)."""
    Q = W * 41.35e-3
    films = {race: np.r_[np.nan, Moes().evaluate(np.full(2, r), W[1:], E, 2.0, STATE.eta0, STATE.alpha)["h_c"]]
             for race, r in (("inner", 0.008), ("outer", 0.012))}
    sigma = np.hypot(0.2e-6, 0.2e-6)
    density, radius = 0.05 / (6e-6 * sigma), 6e-6
    lengths = np.where(Q > 0.0, 41.35e-3, np.nan)
    out = roller_mixed(Q, lengths, lengths, {"inner": 0.008, "outer": 0.012}, E, 2.0, STATE.eta0, STATE.alpha, True,
                       films["inner"], films["outer"], 0.2e-6, density, radius)
    assert_provides(roller_mixed, out)
    for race, r in (("inner", 0.008), ("outer", 0.012)):
        direct = mixed_film_cycle(W, np.full(3, r), E, np.full(3, 2.0), STATE.eta0, STATE.alpha, films[race], sigma,
                                  density, radius, True)
        np.testing.assert_allclose(out[f"asperity_load_fraction_{race}"][1:], direct["asperity_load_fraction"][1:])
        np.testing.assert_allclose(out[f"h_c_mixed_{race}"][1:], direct["h_c_mixed"][1:])
        assert out[f"lubrication_regime_{race}"][0] == "unloaded"
        assert np.isnan(out[f"asperity_load_fraction_{race}"][0]) and not out[f"mixed_valid_{race}"][0]
    # the conformal outer contact carries a thicker film: a smaller asperity share at equal load
    assert np.all(out["asperity_load_fraction_outer"][1:] < out["asperity_load_fraction_inner"][1:])


def test_ball_cone_mixed_shares_the_load_of_each_cvt_contact_on_its_film():
    """The CVT's contacts (5 kN, Rx 5.6 mm, Ry 7 mm, 0.15 / 0.3 m/s, both surfaces 0.1 um): with the Nijenbanning
    film as the scene's, each side equals a direct call of the point load-sharing model with the composite
    roughness sqrt 2 sigma; a scene film 0.6 x Nijenbanning (another formula, a thermal reduction) thins the mixed
    film and raises the asperity share; the capacity < 1 at Lambda < 1 is flagged (mixed_valid False)."""
    N, Rx, Ry, speeds = 5.0e3, 5.6e-3, 7.0e-3, {"in": 0.15, "out": 0.3}
    sigma = np.hypot(0.1e-6, 0.1e-6)
    density, radius = 0.05 / (2.8e-6 * sigma), 2.8e-6
    films = {side: Nijenbanning().evaluate(Rx, Ry, N, E, u, STATE.eta0, STATE.alpha)["h_c"]
             for side, u in speeds.items()}
    args = (N, Rx, Ry, E, speeds["in"], speeds["out"], STATE.eta0, STATE.alpha, True)
    out = ball_cone_mixed(*args, films["in"], films["out"], 0.1e-6, density, radius)
    assert_provides(ball_cone_mixed, out)
    for side, u in speeds.items():
        direct = mixed_point_contact(N, Rx, Ry, E, u, STATE.eta0, STATE.alpha, sigma, density, radius)
        assert out[f"asperity_load_fraction_{side}"] == pytest.approx(direct["asperity_load_fraction"], rel=1e-9)
        assert out[f"h_c_mixed_{side}"] == pytest.approx(direct["h_c"], rel=1e-9)
        assert out[f"Lambda_mixed_{side}"] == pytest.approx(direct["h_c"] / sigma, rel=1e-9)
        assert out[f"mixed_valid_{side}"] == (direct["asperity_capacity"] >= 1 or direct["lambda_ratio"] >= 1)
    assert out["asperity_load_fraction_in"] > out["asperity_load_fraction_out"]  # slower: thinner film
    thin = ball_cone_mixed(*args, 0.6 * films["in"], 0.6 * films["out"], 0.1e-6, density, radius)
    assert thin["h_c_mixed_in"] < out["h_c_mixed_in"]
    assert thin["asperity_load_fraction_in"] > out["asperity_load_fraction_in"]
    with pytest.raises(InputError, match="h_c = 0.0"):
        ball_cone_mixed(*args, 0.0, films["out"], 0.1e-6, density, radius)


def test_mixed_film_cycle_shares_the_load_on_the_scenes_own_film():
    """A scene film 0.6 x Moes (a thermal reduction, another film model) thins the mixed film by the same
    factor at equal share and raises the asperity share; an angle without a film is "unknown", not a guess."""
    moes = Moes().evaluate(R[1:], W[1:], E, np.abs(U[1:]), STATE.eta0, STATE.alpha)["h_c"]
    density = 0.05 / (6e-6 * 0.3e-6)
    full = mixed_film_cycle(W[1:], R[1:], E, U[1:], STATE.eta0, STATE.alpha, moes, 0.3e-6, density, 6e-6, True)
    thin = mixed_film_cycle(W[1:], R[1:], E, U[1:], STATE.eta0, STATE.alpha, 0.6 * moes, 0.3e-6, density, 6e-6,
                            True)
    assert np.all(thin["asperity_load_fraction"] > full["asperity_load_fraction"])
    assert np.all(thin["h_c_mixed"] < full["h_c_mixed"])
    lost = mixed_film_cycle(W[1:], R[1:], E, U[1:], STATE.eta0, STATE.alpha, np.array([np.nan, moes[1]]), 0.3e-6,
                            density, 6e-6, True)
    assert lost["lubrication_regime"][0] == "unknown" and np.isnan(lost["asperity_load_fraction"][0])
    assert lost["h_c_mixed"][1] == pytest.approx(full["h_c_mixed"][1], rel=1e-12)
    # the load sharing runs on the scene's film itself: the smooth film of the model equals the scene's h_c
    direct = mixed_line_contact(W[1:], R[1:], E, np.abs(U[1:]), STATE.eta0, STATE.alpha, 0.3e-6, density, 6e-6,
                                film_scale=0.6)
    np.testing.assert_allclose(direct["h_c_smooth"], 0.6 * moes, rtol=1e-12)
    np.testing.assert_allclose(thin["h_c_mixed"], direct["h_c"], rtol=1e-12)
    # no entrainment (u_m = 0, the film step's h_c = 0): boundary lubrication, the asperities' share, not unknown
    still = mixed_film_cycle(W[1:2], R[1:2], E, np.array([0.0]), STATE.eta0, STATE.alpha, np.array([0.0]), 0.3e-6,
                             density, 6e-6, True)
    assert still["lubrication_regime"][0] == "boundary" and still["asperity_load_fraction"][0] > 0.0


def _contact():
    N = np.array([0.0, 1500.0, 3000.0])
    p_h = np.array([0.0, 0.8e9, 1.1e9])
    b = np.array([0.0, 1.2e-4, 1.6e-4])
    h = np.array([np.nan, 0.4e-6, 0.5e-6])
    return N, p_h, b, h


def test_ehl_sliding_friction_is_boundary_plus_fluid():
    model = registry.get("traction_models", "eyring")
    N, p_h, b, h = _contact()
    u_s, u_m = np.array([1.0, 2.0, -3.0]), np.array([1.0, 4.0, 2.0])
    f_a = np.array([0.0, 0.2, 0.1])
    out = ehl_sliding_friction(model, N, p_h, b, h, u_s, u_m, STATE, asperity_load_fraction=f_a,
                               boundary_friction=0.12)
    assert_provides(ehl_sliding_friction, out)
    fluid = model.contact(p_h[1:], b[1:], h[1:], u_m[1:], STATE).coefficient(u_s[1:])
    expected = np.abs(0.12 * f_a[1:] * N[1:] * np.sign(u_s[1:]) + fluid * (1 - f_a[1:]) * N[1:])
    np.testing.assert_allclose(out["friction_force"][1:], expected, rtol=1e-12)
    np.testing.assert_allclose(out["friction_power"], out["friction_force"] * np.abs(u_s))
    assert out["friction_force"][0] == 0.0 and out["traction_regime"][0] == "open"
    assert out["traction_valid"].all()


def test_newtonian_film_without_a_limit_is_flagged_outside_its_validity():
    model = registry.get("traction_models", "newtonian", limiting_shear_slope=None)
    N, p_h, b, h = _contact()
    out = ehl_sliding_friction(model, N, p_h, b, h, np.full(3, 2.0), np.full(3, 3.0), STATE)
    assert np.all(out["fluid_traction_coefficient"][1:] > FLUID_TRACTION_LIMIT)
    assert not out["traction_valid"][1:].any()


def test_fluid_traction_table_is_monotone_and_reaches_the_plateau():
    model = registry.get("traction_models", "eyring", limiting_shear_slope=0.075)
    N, p_h, b, h = _contact()
    u = np.array([5.0, 5.0, 5.0])
    out = fluid_traction_table(model, N, p_h, b, h, u, u, STATE, asperity_load_fraction=np.zeros(3),
                               boundary_friction=0.12)
    assert_provides(fluid_traction_table, out)
    table = out["traction_table"]
    assert np.all(np.diff(table, axis=1) >= 0.0)
    assert np.all(table[0] == 0.0)  # open contact: no traction
    # towards the plateau tau = Lambda_L p at the largest slip (S = 3.2): at most Lambda_L, the low-pressure edges
    # of the contact still below tau_L (Eyring)
    ratio = table[1:, -1] / N[1:]
    assert np.all(ratio <= 0.075 * (1 + 1e-9)) and np.all(ratio > 0.07)


BASE = {"elasticity", "piezoviscosity", "compressibility"}
OUT = ["cam_angle", "friction_coefficient", "friction_power_mean", "lubrication_regime", "asperity_load_fraction",
       "traction_regime", "traction_valid", "traction_temperature_rise"]


def test_flat_follower_ehl_friction_ladder(thermal_steel_ls1):
    """Coulomb (0.05) -> Eyring isothermal -> + thermal: the fluid's friction lies in the measured EHL range
    and the contact temperature lowers it; mixed adds asperity friction where the film is thin (the nose)."""
    def run(effects, outputs=OUT):
        return cc.Analysis(thermal_steel_ls1, effects=BASE | effects, outputs=outputs).run()

    eyring = run({"non_newtonian"}, OUT[:3] + OUT[5:])
    mu = np.asarray(eyring["friction_coefficient"])
    assert 0.005 < mu.min() and mu.max() <= 0.0751  # bounded by the limiting shear stress Lambda_L = 0.075
    assert eyring["traction_valid"].all()
    hot = run({"non_newtonian", "thermal"}, OUT[:3] + OUT[5:])
    assert hot["friction_power_mean"] < eyring["friction_power_mean"]
    assert np.max(hot["traction_temperature_rise"]) > 1.0
    mixed = run({"non_newtonian", "mixed"})
    regimes = set(mixed["lubrication_regime"])
    assert {"mixed", "full_film"} <= regimes
    assert np.max(mixed["asperity_load_fraction"]) > 0.1
    newtonian = run({"mixed"}, OUT[:3] + OUT[5:] + ["fluid_traction_coefficient"])
    # the Newtonian film (bounded by the limiting shear stress by default) sits on its plateau Lambda_L = 0.075
    # wherever it shears, above Eyring's non-linear viscous traction
    assert np.max(newtonian["fluid_traction_coefficient"]) <= 0.0751 and newtonian["traction_valid"].all()
    assert newtonian["friction_power_mean"] > eyring["friction_power_mean"]


def test_roller_with_fluid_traction_rolls_at_1000_rpm(thermal_steel_ls1):
    scene = load_scene().component
    result = cc.Analysis(scene, effects=BASE | {"non_newtonian"},
                         outputs=["tangential_force", "traction_available", "roller_slipping"]).run()
    assert not np.asarray(result["roller_slipping"]).any()
    # the film can transmit several times what the roller needs (about 0.07 N against at most 8.6 N)
    assert np.min(result["traction_available"]) > 5 * np.max(np.abs(result["tangential_force"]))


def test_thermal_traction_without_material_thermal_data_is_named_up_front():
    scene = load_scene().component
    oil = attrs.evolve(scene.lubricant, thermoviscous_coefficient="0.03 1/K", thermal_conductivity="0.13 W/m/K")
    with pytest.raises(cc.InputError, match="effusivity|specific_heat"):
        cc.Analysis(attrs.evolve(scene, lubricant=oil), effects=BASE | {"non_newtonian", "thermal"},
                    outputs=["friction_force"]).run()


def test_traction_curve_plot_marks_regimes_and_the_thermal_fall():
    import matplotlib

    matplotlib.use("Agg")
    from camcontact.scenes.traction_curve_plot import plot_traction_curve

    oil = cc.Lubricant(alpha="2.2e-8 1/Pa", roelands_z=0.68, thermoviscous_coefficient="0.03 1/K",
                       thermal_conductivity="0.13 W/m/K")
    models = [registry.get("traction_models", "eyring"), registry.get("traction_models", "eyring", thermal=True)]
    fig = plot_traction_curve(models, p_h=1.0e9, b=2e-4, h_c=0.5e-6, u_m=5.0, lubricant_state=oil.state(None),
                              effusivity=1.3e4, slide_roll=np.linspace(0.0, 0.5, 101))
    lines = fig.axes[0].get_lines()
    isothermal, thermal = lines[0].get_ydata(), next(l for l in lines if l.get_label() == "eyring thermal").get_ydata()
    assert np.all(np.diff(isothermal) >= 0) and thermal[-1] < thermal.max()  # the thermal plateau falls
    with pytest.raises(cc.InputError, match="traction models"):
        plot_traction_curve("eyring", p_h=1e9, b=2e-4, h_c=5e-7, u_m=5.0, lubricant_state=oil.state(None))


def test_a_jumping_valve_train_with_every_friction_effect_keeps_its_open_angles_finite(thermal_steel_ls1):
    """Contact lost (a weak spring at 3000 rpm): the open angles carry no friction, no NaN, no error."""
    jumping = attrs.evolve(thermal_steel_ls1, speed="3000 rpm",
                           valve_train=attrs.evolve(thermal_steel_ls1.valve_train, preload="100 N"))
    for follower in (jumping.follower, load_scene().component.follower):
        case = attrs.evolve(jumping, follower=attrs.evolve(follower, material=jumping.cam.material))
        result = cc.Analysis(case, effects=BASE | {"non_newtonian", "thermal", "mixed"},
                             outputs=["contact_open", "friction_force", "friction_torque"]).run()
        open_ = np.asarray(result["contact_open"])
        assert open_.any()
        force = np.asarray(result["friction_force"])
        assert np.all(np.isfinite(force)) and np.all(force[open_] == 0.0)


def test_one_contact_steps_are_the_cycle_steps_at_one_angle():
    """mixed_contact and contact_ehl_friction (the line-contact scene's steps) give the scalars of the per-angle
    steps at a single angle, with the line scene's names (per unit length)."""
    density = 0.05 / (6e-6 * 0.3e-6)
    moes = Moes().evaluate(R[1], W[1], E, U[1], STATE.eta0, STATE.alpha)["h_c"]
    one = mixed_contact(W[1], R[1], E, U[1], STATE.eta0, STATE.alpha, moes, 0.3e-6, density, 6e-6, True)
    assert_provides(mixed_contact, one)
    cycle = mixed_film_cycle(W[1:2], R[1:2], E, U[1:2], STATE.eta0, STATE.alpha, [moes], 0.3e-6, density, 6e-6, True)
    assert isinstance(one["asperity_load_fraction"], float)
    assert one["asperity_load_fraction"] == cycle["asperity_load_fraction"][0]
    assert one["lubrication_regime"] == cycle["lubrication_regime"][0]
    model = registry.get("traction_models", "eyring")
    extra = {"asperity_load_fraction": one["asperity_load_fraction"], "h_c_mixed": one["h_c_mixed"],
             "boundary_friction": 0.12}
    line = contact_ehl_friction(model, W[1], 0.8e9, 1.2e-4, moes, 0.1, U[1], STATE, **extra)
    assert_provides(contact_ehl_friction, line)
    per_angle = ehl_sliding_friction(model, W[1:2], np.array([0.8e9]), np.array([1.2e-4]), np.array([moes]),
                                     np.array([0.1]), U[1:2], STATE, **extra)
    assert line["friction_per_length"] == per_angle["friction_force"][0]
    assert line["traction_coefficient"] == per_angle["friction_coefficient"][0]
    assert line["traction_regime"] == per_angle["traction_regime"][0]
