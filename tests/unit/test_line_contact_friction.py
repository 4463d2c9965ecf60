"""The line-contact scene's friction effects (``mixed``, ``non_newtonian``, ``thermal``) and its Stribeck curve.

Independent references: the scene's friction against a direct call of the traction model with the scene's
own Hertz pressure, half-width and film; the scene's load sharing against a direct call of the Greenwood–Tripp/
Johnson–Greenwood–Poon model with the scene's film; the Stribeck curve's limits — at vanishing speed the
asperities carry the load (mu -> the boundary coefficient mu_b = 0.12 of the lubricant), in full film the
friction is the fluid's and rises with speed (Stribeck's diagram; Gelinck & Schipper 2000, Tribol. Int.
33:175–181, Fig. 8 shows the same three branches for their line contact).
"""

import numpy as np
import pytest

import camcontact as cc
from camcontact import registry
from camcontact.errors import InputError
from camcontact.models.film_line import Moes
from camcontact.models.mixed_lubrication import mixed_line_contact
from camcontact.scenes.stribeck import plot_stribeck_curve, stribeck_sweep

STEEL = cc.Material(E="210 GPa", nu=0.3, thermal_conductivity="46 W/m/K", density="7850 kg/m^3",
                    specific_heat="470 J/kg/K")
OIL = cc.Lubricant(nu40="100 cSt", nu100="11 cSt", density="870 kg/m^3", alpha="22 1/GPa",
                   thermal_conductivity="0.13 W/m/K")
BASE = {"elasticity", "piezoviscosity"}


def contact(load="150 N", u1="2.1 m/s", u2="1.9 m/s", material=STEEL, **extra):
    return cc.LineContact(body1=cc.Body(material=material, radius="20 mm", speed=u1, roughness="0.2 um"),
                          body2=cc.Body(material=material, radius="20 mm", speed=u2, roughness="0.2 um"),
                          load=load, length="10 mm", lubricant=OIL, temperature="60 degC", **extra)


def test_non_newtonian_friction_is_the_eyring_traction_of_the_scenes_film():
    result = cc.Analysis(contact("5 kN"), effects=BASE | {"non_newtonian"},
                         outputs=["p_h", "b", "h_c", "u_m", "traction_coefficient", "friction_per_length",
                                  "friction_power_per_length", "traction_regime", "traction_valid"]).run()
    model = registry.get("traction_models", "eyring")
    direct = model.contact(result["p_h"], result["b"], result["h_c"], result["u_m"], OIL.state(333.15)).coefficient(0.2)
    assert result["traction_coefficient"] == pytest.approx(direct, rel=1e-12)
    w = 5e3 / 0.01
    assert result["friction_per_length"] == pytest.approx(direct * w, rel=1e-12)
    assert result["friction_power_per_length"] == pytest.approx(direct * w * 0.2, rel=1e-12)
    # 0.2 m/s of slide above 1 GPa: the Eyring stress reaches the limiting shear stress 0.047 p (Höglund's mineral oil)
    assert result["traction_regime"] == "plateau" and result["traction_valid"] is True


def test_mixed_shares_the_load_on_the_scenes_film_and_adds_boundary_friction():
    scene = contact("5 kN")
    result = cc.Analysis(scene, effects=BASE | {"mixed", "non_newtonian"},
                         outputs=["R", "E_reduced", "u_m", "eta0", "alpha", "h_c", "asperity_load_fraction",
                                  "h_c_mixed", "lubrication_regime", "traction_coefficient",
                                  "fluid_traction_coefficient", "mixed_valid"]).run()
    w, sigma = 5e3 / 0.01, np.hypot(0.2e-6, 0.2e-6)
    radius = sigma / 0.05
    moes = Moes().evaluate(result["R"], w, result["E_reduced"], result["u_m"], result["eta0"], result["alpha"])["h_c"]
    direct = mixed_line_contact(w, result["R"], result["E_reduced"], result["u_m"], result["eta0"], result["alpha"],
                                sigma, 0.05 / (radius * sigma), radius, film_scale=result["h_c"] / moes)
    assert result["asperity_load_fraction"] == pytest.approx(direct["asperity_load_fraction"], rel=1e-9)
    assert result["h_c_mixed"] == pytest.approx(direct["h_c"], rel=1e-9)
    a = result["asperity_load_fraction"]
    assert 0.0 < a < 0.5 and result["lubrication_regime"] == "mixed"
    expected = 0.12 * a + result["fluid_traction_coefficient"] * (1.0 - a)
    assert result["traction_coefficient"] == pytest.approx(expected, rel=1e-12)


def test_thermal_traction_needs_the_materials_thermal_data_up_front():
    bare = cc.Material(E="210 GPa", nu=0.3)
    with pytest.raises(InputError, match="effusivity"):
        cc.Analysis(contact(material=bare), effects=BASE | {"non_newtonian", "thermal"}).run()
    hot = cc.Analysis(contact("5 kN"), effects=BASE | {"non_newtonian", "thermal"},
                      outputs=["traction_coefficient", "traction_temperature_rise"]).run()
    cold = cc.Analysis(contact("5 kN"), effects=BASE | {"non_newtonian"}, outputs=["traction_coefficient"]).run()
    assert hot["traction_temperature_rise"] > 1.0 and hot["traction_coefficient"] < cold["traction_coefficient"]


def test_without_friction_effects_the_scene_reports_no_friction():
    result = cc.Analysis(contact()).run()
    assert "traction_coefficient" not in result.outputs and "asperity_load_fraction" not in result.outputs


def test_stribeck_curve_has_boundary_mixed_and_full_film_branches():
    curve = stribeck_sweep(contact(), np.logspace(-4, 2, 25))
    assert (curve["error"] == "").all() and curve["mixed_valid"].all()
    mu = curve["traction_coefficient [-]"].to_numpy()
    regimes = list(curve["lubrication_regime"])
    # the regimes come in Stribeck's order as the speed rises
    order = {"boundary": 0, "mixed": 1, "full_film": 2}
    assert [order[r] for r in regimes] == sorted(order[r] for r in regimes) and set(regimes) == set(order)
    # boundary: the asperities carry almost everything, mu tends to mu_b = 0.12
    assert curve["asperity_load_fraction [-]"].iloc[0] > 0.95 and mu[0] == pytest.approx(0.12, rel=0.03)
    # one minimum, at the mixed/full-film transition, below 0.01; then the fluid's traction rises with speed
    k = int(np.argmin(mu))
    assert regimes[k] in ("mixed", "full_film") and mu[k] < 0.01
    assert np.all(np.diff(mu[:k + 1]) < 0.0) and np.all(np.diff(mu[k:]) > 0.0)


def test_stribeck_sweep_keeps_the_slide_roll_ratio_and_checks_its_inputs():
    curve = stribeck_sweep(contact(), [0.1, 1.0], slide_roll_ratio=0.5)
    np.testing.assert_allclose(curve["slide_roll_ratio [-]"], 0.5)
    np.testing.assert_allclose(curve["u_m [m/s]"], [0.1, 1.0])
    with pytest.raises(InputError, match="slide_roll_ratio"):
        stribeck_sweep(contact(), [0.1, 1.0], slide_roll_ratio=2.5)
    with pytest.raises(InputError, match="entrainment_speeds"):
        stribeck_sweep(contact(), [0.1, -1.0])
    with pytest.raises(InputError, match="needs the friction"):
        stribeck_sweep(contact(), [0.1, 1.0], effects={"thermal"})
    with pytest.raises(InputError, match="slide_roll_ratio"):
        stribeck_sweep(contact(u1="0 m/s", u2="0 m/s"), [0.1, 1.0])


def test_stribeck_plot_draws_every_curve():
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    speeds = np.logspace(-3, 1, 6)
    curves = [stribeck_sweep(contact(), speeds), stribeck_sweep(contact(), speeds, effects={"non_newtonian"})]
    fig = plot_stribeck_curve(curves, labels=["mixed", "smooth"])
    ax = fig.axes[0]
    assert ax.get_xscale() == "log"
    assert {"μ mixed", "μ smooth"} <= {line.get_label() for line in ax.lines}
    with pytest.raises(InputError, match="labels"):
        plot_stribeck_curve(curves, labels=["one"])
    failed = curves[0].assign(**{"traction_coefficient [-]": np.nan, "Lambda_mixed [-]": np.nan, "error": "boom"})
    with pytest.raises(InputError, match="no finite friction coefficient"):
        plot_stribeck_curve(failed)


def test_with_a_numerical_film_the_traction_runs_over_its_pressure():
    """film="multigrid" with non_newtonian: the film is the Eyring film of the thermal / non-Newtonian solver
    (isothermal here) and the contact's traction is that solver's own; it equals the traction model's over the
    solution's pressure and film profile (an independent call with the solution the scene kept) to 2e-3 — the
    same Eyring stress bounded by the same limiting shear stress, the solver integrating over the wet film only —
    and is a few per cent from the Hertz path's. (The case, M = 28, L = 14, incompressible, made the solver's first
    flow factor diverge: it now carries the Eyring factor's pressure dependence in the kernels.)"""
    from camcontact.models.film_multigrid import Multigrid

    result = cc.Analysis(contact("5 kN"), effects=BASE | {"non_newtonian"}, models={"film": Multigrid(levels=7)},
                         outputs=["p_h", "b", "h_c", "u_m", "traction_coefficient", "film_solution"]).run()
    solution = result["film_solution"]
    assert solution.record.converged and solution.rheology == "eyring" and not solution.thermal
    assert result["traction_coefficient"] == pytest.approx(solution.traction_coefficient, rel=1e-12)
    model = registry.get("traction_models", "eyring")
    state = OIL.state(333.15)
    args = (result["p_h"], result["b"], result["h_c"], result["u_m"], state)
    numerical = model.contact(*args, profile=solution.traction_profile()).coefficient(0.2)
    assert result["traction_coefficient"] == pytest.approx(numerical, rel=2e-3)
    hertz = model.contact(*args).coefficient(0.2)
    assert 0.0 < abs(numerical / hertz - 1.0) < 0.1
