"""Film step functions (camcontact.steps.film) called alone, with plain SI inputs and film-model objects.

Expected values: Hamrock's groups U = eta0 u_m/(E' R), G = alpha E', W = w/(E' R) and Moes's M = W (2U)^-1/2,
L = G (2U)^1/4 (Venner & Lubrecht 2000); Tsuha (2015) Table 6.3 (M, L at 0 and 90 deg); the Pan–Hamrock
(1989), Moes (1992, as Venner & Lubrecht give it) and Hamrock–Dowson (1977) formulas written out here;
Delabenetta (2021) Eq. 44 and its Table 8 phi_T = 0.615; Lambda = h/sqrt(s1^2 + s2^2) and Cheng's regimes.
"""

import math
from types import SimpleNamespace

import numpy as np
import pytest

import camcontact as cc
from camcontact import registry
from camcontact.errors import InputError
from camcontact.steps.film import (
    ball_cone_films,
    bearing_lubrication,
    check_thermal_data,
    composite_roughness_step,
    ehl_groups,
    film_parameter,
    inlet_thermal_correction,
    isothermal_films,
    line_film,
    lubrication_regime_step,
    raceway_roughness,
    roller_films,
    roller_thermal_films,
    solved_films,
    solved_thermal_films,
    thermal_films,
)
from step_checks import assert_provides

E_STEEL = 210e9 / (1 - 0.3**2)
ETA_TSUHA, ALPHA_TSUHA = 0.0358352, 2.2e-8  # Tsuha (2015), reference §0 item 2


def groups(w, R, E, u, eta, alpha):
    U, G, W = eta * u / (E * R), alpha * E, w / (E * R)
    return U, G, W, W * (2 * U) ** -0.5, G * (2 * U) ** 0.25


def pan_hamrock(w, R, E, u, eta, alpha):
    """Pan & Hamrock (1989): (h_c, h_min) [m]."""
    U, G, W = groups(w, R, E, u, eta, alpha)[:3]
    return (2.922 * W**-0.166 * U**0.692 * G**0.470 * R, 1.714 * W**-0.128 * U**0.694 * G**0.568 * R)


def moes_h_c(w, R, E, u, eta, alpha):
    """Moes (1992) central film as Venner & Lubrecht (2000) give it: H = [(H_RI^7/3 + H_EI^7/3)^(3s/7) +
    (H_RP^-7/2 + H_EP^-7/2)^(-2s/7)]^(1/s), s = (7 + 8 exp(-2 H_EI/H_RI))/5, h_c = H R (2U)^1/2."""
    U, _, _, M, L = groups(w, R, E, u, eta, alpha)
    h_ri, h_ei = 3 / M, 2.621 * M**-0.2
    s = (7 + 8 * math.exp(-2 * h_ei / h_ri)) / 5
    H = (h_ri ** (7 / 3) + h_ei ** (7 / 3)) ** (3 * s / 7)
    if L > 0:
        H += ((1.287 * L ** (2 / 3)) ** -3.5 + (1.311 * M**-0.125 * L**0.75) ** -3.5) ** (-2 * s / 7)
    return H ** (1 / s) * R * math.sqrt(2 * U)


# ----------------------------------------------------------------------------- ehl_groups
def test_ehl_groups_tsuha_table_6_3():
    """Tsuha (2015) Table 6.3 (roller, thesis convention: the film sees u_m/2): 90 deg (F = 3087.99 N on
    15 mm, R = 7.69892 mm, u_m = 3.5037 m/s) M = 13.784, L = 14.720; 0 deg (1000 N, 8 mm, 4.18879 m/s)
    M = 4.005, L = 15.245 (+-0.002 as tests/literature); the groups' definitions exactly."""
    out = ehl_groups(3087.99 / 0.015, 0.00769892, E_STEEL, 0.5 * 3.5036962, ETA_TSUHA, ALPHA_TSUHA, True)
    assert_provides(ehl_groups, out)
    assert out["M"] == pytest.approx(13.784, abs=0.002) and out["L"] == pytest.approx(14.720, abs=0.002)
    U, G, W, M, L = groups(3087.99 / 0.015, 0.00769892, E_STEEL, 0.5 * 3.5036962, ETA_TSUHA, ALPHA_TSUHA)
    for key, value in zip("UGWML", (U, G, W, M, L)):
        assert out[key] == pytest.approx(value, rel=1e-12), key
    base = ehl_groups(1000 / 0.015, 0.008, E_STEEL, 0.5 * 4.1887902, ETA_TSUHA, ALPHA_TSUHA, True)
    assert base["M"] == pytest.approx(4.005, abs=0.002) and base["L"] == pytest.approx(15.245, abs=0.002)


def test_ehl_groups_without_piezoviscosity_and_without_entrainment():
    """piezoviscosity off: alpha_effective = 0, G = L = 0; u_m = 0: InputError (no steady film)."""
    out = ehl_groups(2e5, 0.008, E_STEEL, 2.0, 0.05, 2e-8, False)
    assert out["alpha_effective"] == 0.0 and out["G"] == 0.0 and out["L"] == 0.0
    with pytest.raises(InputError, match="u_m = \\(u1 \\+ u2\\)/2 = 0"):
        ehl_groups(2e5, 0.008, E_STEEL, 0.0, 0.05, 2e-8, True)


# ----------------------------------------------------------------------------- line_film
def _line_film(model, w=2e5, R=0.01, u=2.0, eta=0.05, alpha=2e-8):
    g = ehl_groups(w, R, E_STEEL, u, eta, alpha, True)
    return line_film(model, R, w, E_STEEL, u, eta, g["alpha_effective"], g["U"], g["G"], g["W"], g["M"], g["L"],
                     None, "incompressible")


def test_line_film_pan_hamrock_formula_and_validity():
    """Pan–Hamrock gives h_c and h_min (formula above); inside Dowson's range (W' 3e-5..3e-4, U 1e-13..1e-8)
    the validity is 'ok', at W' = 1e-3 it names W."""
    out = _line_film(registry.get("film_models", "pan_hamrock"))
    assert_provides(line_film, out)
    h_c, h_min = pan_hamrock(2e5, 0.01, E_STEEL, 2.0, 0.05, 2e-8)
    assert out["h_c_isothermal"] == pytest.approx(h_c, rel=1e-12)
    assert out["h_min_isothermal"] == pytest.approx(h_min, rel=1e-12)
    assert out["film_validity"] == "ok" and out["film_valid"] is True
    heavy = _line_film(registry.get("film_models", "pan_hamrock"), w=E_STEEL * 0.01 * 1e-3)
    # the status as a boolean, the reason as text naming the model
    assert heavy["film_validity"].startswith("pan_hamrock: W = 0.001 above the validated range")
    assert heavy["film_valid"] is False


def test_line_film_moes_gives_only_h_c():
    """The Moes model provides h_c only: the step returns h_c_isothermal (Moes formula above) and the validity."""
    out = _line_film(registry.get("film_models", "moes"))
    assert_provides(line_film, out, subset=("h_c_isothermal", "film_validity", "film_valid", "film_solution"))
    assert out["film_solution"] is None  # a formula leaves no numerical solution
    assert out["h_c_isothermal"] == pytest.approx(moes_h_c(2e5, 0.01, E_STEEL, 2.0, 0.05, 2e-8), rel=1e-12)


def test_line_film_reports_a_numerical_solution_that_did_not_converge():
    """A film model whose record says 'not converged' (a stand-in for the multigrid solver): the step
    passes its films through and names the failure in film_validity."""

    class Stalled:
        name, provides = "stalled", ("h_c", "h_min")

        def __call__(self, state):
            return {"h_c": 2e-7, "h_min": 1e-7, "convergence": SimpleNamespace(converged=False, message="stalled at 1e-3")}

        def check_validity(self, values):
            return []

    out = _line_film(Stalled())
    assert out["h_c_isothermal"] == 2e-7 and out["h_min_isothermal"] == 1e-7
    assert out["film_validity"] == "numerical solution not converged: stalled at 1e-3"


# ----------------------------------------------------------------------------- thermal correction
def test_isothermal_and_thermal_films():
    """Without correction h = h_isothermal; with it h = phi_T h_isothermal; only the films given come out."""
    out = isothermal_films(h_c_isothermal=2e-7, h_min_isothermal=1.5e-7)
    assert_provides(isothermal_films, out)
    assert out == {"h_c": 2e-7, "h_min": 1.5e-7}
    out = thermal_films(0.8, h_c_isothermal=2e-7, h_min_isothermal=1.5e-7)
    assert_provides(thermal_films, out)
    assert out["h_c"] == pytest.approx(1.6e-7) and out["h_min"] == pytest.approx(1.2e-7)
    assert_provides(thermal_films, thermal_films(0.5, h_c_isothermal=2e-7), subset=("h_c",))


def test_solved_films_are_the_thermal_solutions():
    """A model that solved the thermal / non-Newtonian film gives its solution's films, and the thermal variant its
    numerical factor h_c/h_c,isothermal in place of the formula's (a stand-in solution with the three values)."""
    solution = SimpleNamespace(h_c=8.1e-7, h_min=6.3e-7, film_reduction=0.937)
    out = solved_films(solution)
    assert_provides(solved_films, out)
    assert out == {"h_c": 8.1e-7, "h_min": 6.3e-7}
    out = solved_thermal_films(solution)
    assert_provides(solved_thermal_films, out)
    assert out["thermal_factor"] == 0.937 and out["h_c"] == 8.1e-7


def test_roller_thermal_films_scale_every_raceway_film():
    """A bearing's films per roller and race and its thinnest film, each times phi_T (NaN stays NaN)."""
    isothermal = {"h_c_inner_isothermal": np.array([3e-7, np.nan]), "h_c_outer_isothermal": np.array([4e-7, np.nan]),
                  "h_min_inner_isothermal": np.array([2e-7, np.nan]), "h_min_outer_isothermal": np.array([3e-7, np.nan]),
                  "h_min_bearing_isothermal": 2e-7}
    out = roller_thermal_films(0.9, **isothermal)
    assert_provides(roller_thermal_films, out)
    np.testing.assert_allclose(out["h_c_inner"], [2.7e-7, np.nan])
    assert out["h_min_bearing"] == pytest.approx(1.8e-7) and np.isnan(out["h_min_outer"][1])


def _thesis_oil(theta):
    """NH1 11-572 base oil at theta [degC] as Delabenetta's code: Walther through 575/50 cSt at 40/100 degC
    with K = degC + 273, beta = m (nu + 0.7) ln(nu + 0.7)/(nu T), eta = 920 nu, k from Eq. 38 (slope 0.0005/3)."""
    x1, x2 = math.log10(313.0), math.log10(373.0)
    y1, y2 = (math.log10(math.log10(v + 0.7)) for v in (575.0, 50.0))
    m = (y1 - y2) / (x2 - x1)
    T = theta + 273.0
    nu = 10 ** (10 ** (y1 + m * x1 - m * math.log10(T))) - 0.7
    return nu * 1e-6 * 920, m * (nu + 0.7) * math.log(nu + 0.7) / (nu * T), 0.12 * (1 - 0.0005 / 3 * theta) / 0.92


def test_inlet_thermal_correction_delabenetta_eq_44():
    """L = beta eta0 (u1 + u2)^2/k, V_e = |u1 - u2|/(u1 + u2), phi_T = 1/(1 + 0.1 (1 + 14.8 V_e^0.83) L^0.64)
    (Delabenetta Eqs. 44-46); with its contact at 84.9 degC (u1 = 4.681, u2 = 2.686 m/s) phi_T = 0.615
    (Table 8)."""
    eta, beta, k = _thesis_oil(84.9)
    u1, u2 = 0.149 * 2 * math.pi * 5, 0.0135 * 2 * math.pi * 1900 / 60
    out = inlet_thermal_correction(beta, eta, u1, u2, k)
    assert_provides(inlet_thermal_correction, out)
    L = beta * eta * (u1 + u2) ** 2 / k
    V = (u1 - u2) / (u1 + u2)
    assert out["thermal_loading"] == pytest.approx(L, rel=1e-12)
    assert out["thermal_factor"] == pytest.approx(1 / (1 + 0.1 * (1 + 14.8 * V**0.83) * L**0.64), rel=1e-12)
    assert round(out["thermal_factor"], 3) == 0.615


def test_check_thermal_data():
    """The thermal step's check refuses a lubricant without conductivity or temperature data, naming what
    is missing; a complete one or none at all passes."""
    assert inlet_thermal_correction.step.check is check_thermal_data
    with pytest.raises(InputError, match="thermal_conductivity and temperature-dependent viscosity data"):
        check_thermal_data(cc.Lubricant(name="bare", eta0="0.05 Pa*s"))
    with pytest.raises(InputError, match="needs Lubricant 'no k' thermal_conductivity$"):
        check_thermal_data(cc.Lubricant(name="no k", nu40="100 cSt", nu100="10 cSt", density="880 kg/m^3"))
    complete = cc.Lubricant(name="ok", nu40="100 cSt", nu100="10 cSt", density="880 kg/m^3",
                            thermal_conductivity="0.13 W/(m K)")
    assert check_thermal_data(complete) is None and check_thermal_data(None) is None


# ----------------------------------------------------------------------------- roughness, Lambda, regime
def test_composite_and_raceway_roughness():
    """sigma = sqrt(s1^2 + s2^2) (Delabenetta Eq. 29); the amplitude of the sinusoid standing for it:
    the thesis's reading sigma/sqrt 2 (Eq. 30, 0.23 um for two 0.23 um surfaces) in the thesis
    convention, sqrt 2 sigma (a sinusoid of RMS sigma: 0.46 um) in the corrected one, exactly twice
    as much; a negative roughness is refused."""
    from camcontact.scenes.raceway_conventions import CORRECTED, THESIS

    out = composite_roughness_step(0.3e-6, 0.4e-6)
    assert_provides(composite_roughness_step, out)
    assert out["sigma"] == pytest.approx(0.5e-6, rel=1e-12)
    thesis = raceway_roughness(0.23e-6, 0.23e-6, THESIS)
    assert_provides(raceway_roughness, thesis)
    assert thesis["sigma"] == pytest.approx(math.sqrt(2) * 0.23e-6, rel=1e-12)
    assert thesis["roughness_amplitude"] == pytest.approx(0.23e-6, rel=1e-12)
    corrected = raceway_roughness(0.23e-6, 0.23e-6, CORRECTED)
    assert corrected["sigma"] == thesis["sigma"]
    assert corrected["roughness_amplitude"] == pytest.approx(0.46e-6, rel=1e-12)
    assert corrected["roughness_amplitude"] == pytest.approx(math.sqrt(2) * corrected["sigma"], rel=1e-15)
    assert corrected["roughness_amplitude"] / thesis["roughness_amplitude"] == pytest.approx(2.0, rel=1e-15)
    # the RMS of A cos(x) over a period is A / sqrt 2: the sinusoid with amplitude sqrt 2 sigma has RMS sigma
    x = np.linspace(0.0, 2 * np.pi, 20001)[:-1]
    rms = np.sqrt(np.mean((corrected["roughness_amplitude"] * np.cos(x)) ** 2))
    assert rms == pytest.approx(corrected["sigma"], rel=1e-12)
    with pytest.raises(InputError, match="roughness"):
        composite_roughness_step(-1e-7, 1e-7)


def test_film_parameter_scalar_array_and_smooth_surfaces():
    """Lambda = h/sqrt(s1^2 + s2^2) for a float and per angle; two ideally smooth surfaces: InputError."""
    out = film_parameter(1.0e-6, 0.3e-6, 0.4e-6)
    assert_provides(film_parameter, out)
    assert out["Lambda"] == pytest.approx(2.0, rel=1e-12)
    np.testing.assert_allclose(film_parameter(np.array([0.5e-6, 1.5e-6]), 0.3e-6, 0.4e-6)["Lambda"], [1.0, 3.0])
    with pytest.raises(InputError, match="zero roughness"):
        film_parameter(1e-6, 0.0, 0.0)


def test_lubrication_regime_boundaries():
    """Lambda <= 1 boundary, 1 < Lambda < 3 mixed, Lambda >= 3 full film (Cheng, Delabenetta §2.3)."""
    out = lubrication_regime_step(3.0)
    assert_provides(lubrication_regime_step, out)
    assert out["regime"] == "full film"
    assert list(lubrication_regime_step(np.array([0.5, 1.0, 1.01, 2.99, 3.0, 7.0]))["regime"]) == [
        "boundary", "boundary", "mixed", "mixed", "full film", "full film"]


# ----------------------------------------------------------------------------- bearing rollers
RADII = {"inner": 0.0121, "outer": 0.0149}


def _roller_films(model, Q, u_m=3.0, piezoviscosity=True, lengths=None):
    lengths = lengths or {race: np.where(Q > 0.0, 0.04, np.nan) for race in RADII}
    return roller_films(model, Q, E_STEEL, u_m, 0.06, 2e-8, piezoviscosity, None, "incompressible", RADII,
                        lengths["inner"], lengths["outer"])


def test_roller_films_pan_hamrock_per_race():
    """w = Q/l per loaded roller and race (Pan–Hamrock by hand), NaN for the unloaded one; h_min_bearing the
    thinnest h_min (the most loaded roller at the inner race, with the smaller radius)."""
    Q = np.array([20e3, 0.0, 5e3])
    out = _roller_films(registry.get("film_models", "pan_hamrock"), Q)
    assert_provides(roller_films, out)
    for race, R in RADII.items():
        for j in (0, 2):
            h_c, h_min = pan_hamrock(Q[j] / 0.04, R, E_STEEL, 3.0, 0.06, 2e-8)
            assert out[f"h_c_{race}"][j] == pytest.approx(h_c, rel=1e-12)
            assert out[f"h_min_{race}"][j] == pytest.approx(h_min, rel=1e-12)
        assert math.isnan(out[f"h_min_{race}"][1])
    # a shorter contact (a conformal roller's loaded length) spreads the same load over less length: w = Q / l
    short = _roller_films(registry.get("film_models", "pan_hamrock"), Q,
                          lengths={"inner": np.array([0.02, np.nan, 0.04]), "outer": np.array([0.04, np.nan, 0.04])})
    assert short["h_c_inner"][0] == pytest.approx(pan_hamrock(Q[0] / 0.02, RADII["inner"], E_STEEL, 3.0, 0.06, 2e-8)[0],
                                                  rel=1e-12)
    assert short["h_c_outer"][0] == pytest.approx(out["h_c_outer"][0], rel=1e-12)
    assert out["h_min_bearing"] == pytest.approx(pan_hamrock(5e5, 0.0121, E_STEEL, 3.0, 0.06, 2e-8)[1], rel=1e-12)


def test_roller_films_moes_isoviscous_gives_h_c_only():
    """Moes without piezoviscosity (alpha = 0, L = 0): only h_c per race; the bearing's thinnest film is
    then the thinnest h_c."""
    Q = np.array([20e3, 5e3])
    out = _roller_films(registry.get("film_models", "moes", piezoviscosity=False), Q, piezoviscosity=False)
    assert_provides(roller_films, out, subset=("h_c_inner", "h_c_outer", "h_min_bearing"))
    assert out["h_c_inner"][0] == pytest.approx(moes_h_c(5e5, 0.0121, E_STEEL, 3.0, 0.06, 0.0), rel=1e-12)
    assert out["h_min_bearing"] == pytest.approx(min(np.min(out["h_c_inner"]), np.min(out["h_c_outer"])))


def test_roller_films_rings_not_turning():
    """u_m = 0 (inner and outer ring at the same speed): no entrainment -> InputError."""
    with pytest.raises(InputError, match="rings do not turn"):
        _roller_films(registry.get("film_models", "pan_hamrock"), np.array([1e4]), u_m=0.0)


def test_bearing_lubrication_regime_of_the_thinner_contact():
    """Per roller the regime of min(Lambda_inner, Lambda_outer), 'unloaded' without load; Lambda_bearing
    the smallest finite Lambda; NaN when no roller is loaded."""
    Q = np.array([1e4, 0.0, 2e3, 5e3])
    inner = np.array([2.5, np.nan, 4.0, 0.8])
    outer = np.array([3.5, np.nan, 3.2, 1.2])
    out = bearing_lubrication(Q, inner, outer)
    assert_provides(bearing_lubrication, out)
    assert list(out["contact_regime"]) == ["mixed", "unloaded", "full film", "boundary"]
    assert out["Lambda_bearing"] == 0.8
    empty = bearing_lubrication(np.zeros(2), np.full(2, np.nan), np.full(2, np.nan))
    assert math.isnan(empty["Lambda_bearing"]) and list(empty["contact_regime"]) == ["unloaded", "unloaded"]


# ----------------------------------------------------------------------------- ball-cone films
def test_ball_cone_films_hamrock_dowson():
    """Hamrock & Dowson (1977): H_min = 3.63 U^0.68 G^0.49 W^-0.073 (1 - e^-0.68k), H_c = 2.69 U^0.67 G^0.53
    W^-0.067 (1 - 0.61 e^-0.73k), k = 1.03 (Ry/Rx)^0.64, U = eta0 u/(E' Rx), W = F/(E' Rx^2), H = h/Rx;
    each side at its own rolling speed; without piezoviscosity the formula has no film: InputError."""
    Rx, Ry, F, eta, alpha = 5.1e-3, 7e-3, 1254.0, 0.02, 2.5e-8
    E = 207e9 / 0.91
    model = registry.get("film_models", "hamrock_dowson")
    out = ball_cone_films(model, Rx, Ry, F, E, 0.146, 0.073, eta, alpha, True, None, "incompressible")
    assert_provides(ball_cone_films, out)
    k = 1.03 * (Ry / Rx) ** 0.64
    for side, u in (("in", 0.146), ("out", 0.073)):
        U, G, W = eta * u / (E * Rx), alpha * E, F / (E * Rx**2)
        h_min = 3.63 * U**0.68 * G**0.49 * W**-0.073 * (1 - math.exp(-0.68 * k)) * Rx
        h_c = 2.69 * U**0.67 * G**0.53 * W**-0.067 * (1 - 0.61 * math.exp(-0.73 * k)) * Rx
        assert out[f"h_min_{side}"] == pytest.approx(h_min, rel=1e-12)
        assert out[f"h_c_{side}"] == pytest.approx(h_c, rel=1e-12)
    with pytest.raises(InputError, match="alpha = 0"):
        ball_cone_films(model, Rx, Ry, F, E, 0.146, 0.073, eta, alpha, False, None, "incompressible")


def test_ball_cone_films_pass_on_a_converged_numerical_pressure_only():
    """A numerical point film's solution becomes the side's PressureField (SI: x = X a, p = P p_h, h = H a^2/Rx of
    the solver's scales); one that did not converge passes None with a ConvergenceWarning naming the fallback."""
    from types import SimpleNamespace

    from camcontact.contact.spin_traction import PressureField
    from camcontact.errors import ConvergenceWarning
    from camcontact.ehl.point_problem import PointEHLProblem

    Rx, Ry, F, E = 5.1e-3, 7e-3, 1254.0, 207e9 / 0.91
    X = Y = np.linspace(-2.0, 2.0, 9)
    P = np.clip(1 - X[None, :] ** 2 - Y[:, None] ** 2, 0.0, None) ** 0.5
    H = np.full(P.shape, 0.3)

    class Numerical:
        provides = ("h_c", "h_min")
        name = "numerical stub"
        converged = True

        def __call__(self, state):
            scales = PointEHLProblem.scales(Rx, F, E)
            solution = SimpleNamespace(record=SimpleNamespace(converged=self.converged),
                                       dimensional=lambda *_: {"x": X * scales["a"], "y": Y * scales["a"],
                                                               "p": P * scales["p_h"], "h": H * scales["h_scale"]})
            return {"h_c": 1e-7, "h_min": 8e-8, "ehl_solution": solution}

    model = Numerical()
    out = ball_cone_films(model, Rx, Ry, F, E, 0.146, 0.073, 0.02, 2.5e-8, True, None, "incompressible")
    field = out["pressure_field_in"]
    scales = PointEHLProblem.scales(Rx, F, E)
    assert isinstance(field, PressureField) and field.p.max() == pytest.approx(scales["p_h"])
    assert field.h[0, 0] == pytest.approx(0.3 * scales["a"] ** 2 / Rx) and field.x[-1] == pytest.approx(2 * scales["a"])
    model.converged = False
    with pytest.warns(ConvergenceWarning, match="falls back to the Hertz pressure"):
        out = ball_cone_films(model, Rx, Ry, F, E, 0.146, 0.073, 0.02, 2.5e-8, True, None, "incompressible")
    assert out["pressure_field_in"] is None and out["pressure_field_out"] is None
    formula = ball_cone_films(registry.get("film_models", "hamrock_dowson"), Rx, Ry, F, E, 0.146, 0.073, 0.02, 2.5e-8,
                              True, None, "incompressible")
    assert formula["pressure_field_in"] is None
