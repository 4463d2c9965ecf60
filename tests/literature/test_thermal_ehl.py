"""The thermal / non-Newtonian line EHL solver (camcontact.ehl.line_thermal) against the published inlet
shear-heating factors (camcontact.models.film_thermal) and against the lumped traction model of the same rheology
(camcontact.contact.fluid_traction).

No published full thermal EHL line-contact solution with its complete input data was available (Sadeghi & Sui 1990,
Kim & Sadeghi 1992, Ghosh & Hamrock 1985, Hsiao & Hamrock 1992, Conry, Wang & Cusano 1987, Salehizadeh & Saka 1991:
abstracts or nothing), so the checks are the published thermal inlet analyses' fits in their range (film: Murch &
Wilson, Wilson & Sheu, Gupta/Zhu & Cheng; rolling traction: Goksem & Hargreaves) and the lumped model. The
solver's own pieces are checked against closed forms in tests/unit/test_line_thermal.py (Nahme's heated Couette film
among them) and its energy balance there. The contact: steel rollers, R = 10 mm, 200 kN/m (p_h = 0.85 GPa), mineral
oil eta0 = 0.04 Pa s, alpha = 20/GPa, beta = 0.03/K, k = 0.14 W/(m K), rho c = 1.74 MJ/(m^3 K); steel effusivity
12.9 kW s^0.5/(m^2 K)."""

from __future__ import annotations

import math

import attrs
import numpy as np
import pytest

from camcontact.contact.fluid_traction import TractionThermal, fluid_traction
from camcontact.ehl.line_thermal import ThermalLineContact, solve_thermal
from camcontact.models.bearing_friction import rolling_resistance_line
from camcontact.models.film_thermal import thermal_reduction

LEVEL = 6  # the film reductions agree with level 10 to 3e-4 (level 8 on the automatic domains: 2e-4)


def _contact(u_m, S, **changes):
    data = dict(R=0.01, w=2e5, E_reduced=2.26e11, u1=u_m * (1 + S / 2), u2=u_m * (1 - S / 2), eta0=0.04, alpha=2e-8,
                beta=0.03, conductivity=0.14, heat_capacity=1.74e6, effusivity_1=12900.0, effusivity_2=12900.0)
    data.update(changes)
    return ThermalLineContact(**data)


def _factor(method, contact):
    p_h = contact.problem().p_h
    return thermal_reduction(method, contact.beta, contact.eta0, contact.u1, contact.u2, contact.conductivity,
                             p_h=p_h, E_reduced=contact.E_reduced)


@pytest.mark.parametrize("u_m, measured, uniform", [(5.0, 0.956, 0.945), (10.0, 0.883, 0.856), (20.0, 0.747, 0.705)])
def test_pure_rolling_film_reduction_follows_murch_wilson(u_m, measured, uniform):
    """Pure rolling over thermal loadings L_m = beta eta0 u_m^2/k = 0.21, 0.86, 3.4: the numerical h_c/h_c,iso is
    5-15 % above Murch & Wilson's (1975) 1/(1 + 0.254 L_m^0.62) (measured 1.049, 1.086, 1.154) and falls with L_m as
    theirs does; the reduction 1 - phi is 49-72 % of theirs (this solver disagrees with their inlet analysis by up to
    a factor 2 in the reduction; Goksem & Hargreaves' rolling traction below says the same). With the viscosity
    uniform across the film at its mean temperature (cross_film=False, the solver's model before the generalised
    Reynolds terms) the film is thinner, 0.945, 0.856, 0.705: in the inlet the walls stay cool and the hot mid-film
    carries little of the Poiseuille (back)flow, so the film's Poiseuille coefficient is that of a cooler, more
    viscous film than its mean temperature's (measured -12 C_P = 0.75-0.85 of exp(beta T_mean) in the inlet at
    L_m = 3.4, on [-4, 1.5]). On the automatic domains (inlets at -9.5, -11.3, -16 b; on [-4, 1.5] the heated
    back-flow leaves the domain, below) the films are 0.3-3 % below those of [-4, 1.5] (0.959, 0.892, 0.771).
    Before the energy equation carried the flow across the film's layers (2026-11-29) the films on [-4, 1.5]
    were 0.957, 0.879, 0.718: that model did not conserve the inlet's energy (tests/unit/test_line_thermal.py)."""
    contact = _contact(u_m, 0.0)
    solution = solve_thermal(contact, LEVEL)
    L_m, murch_wilson = _factor("murch_wilson", contact)
    assert solution.record.converged and not solution.profile_bounded.any()
    assert solution.film_reduction == pytest.approx(measured, abs=2e-3)
    assert 1.0 < solution.film_reduction / murch_wilson < 1.2
    _, wilson_sheu = _factor("wilson_sheu", contact)
    assert solution.film_reduction / wilson_sheu < 1.2
    assert solve_thermal(contact, LEVEL, cross_film=False).film_reduction == pytest.approx(uniform, abs=2e-3)
    assert np.all(solution.ehl.couette_factor == 1.0)  # in pure rolling the entrainment is u_m whatever the profile


@pytest.mark.parametrize("u_m, isothermal_ratio, thermal_ratio", [(5.0, 1.077, 0.962), (10.0, 1.031, 0.911),
                                                                  (20.0, 0.951, 0.851)])
def test_rolling_traction_against_goksem_hargreaves(u_m, isothermal_ratio, thermal_ratio):
    """The rolling (Poiseuille) force per unit length, int h/2 dp/dx dx, in pure rolling. Goksem & Hargreaves (1978,
    J. Lubr. Technol. 100:346-358, fitted to their isothermal and thermal inlet solutions), as Aihara (1987, J.
    Tribol. 109:471-478) prints them: isothermal t_r0 = 4.318 (G U)^0.658 W^0.0126 R/alpha (Eq. 19,
    camcontact.models.bearing_friction.rolling_resistance_line) and, with inlet shear heating, Aihara's fit of their
    thermal result t_r/t_r0 = 1/(1 + 0.29 L^0.78), L = eta0 beta u^2/k (Eq. 21, for L up to several tens). Their own
    thermal fit, Eq. 20, t_r = (R W/alpha) exp[(52/79 + L^(20/63)/94) ln D - 114/701 - ln(1 + (86/209) L^(70/99))],
    does not reduce to Eq. 19 at L = 0 with D = (9 pi/2)^(1/2) G U/W^(3/2) as the copy at hand prints it (0.465 of
    it here); with D pi times that it does, to 0.4 % (camcontact's reading: a factor pi lost in the copy), and then
    gives 0.888, 0.749, 0.529 for the cases here.

    The rolling force depends on the inlet's length: far upstream dp/dx = 12 eta0 u_m/h^2 (isoviscous, h >> h_e), so
    the inlet upstream of x_a adds 6 eta0 u_m int dx/h, which falls only as 1/|x_a| (12 eta0 u_m R/|x_a| on the rigid
    parabola): on the automatic domains the isothermal force is 22-50 % above that of [-4, 1.5] (measured: the
    difference within 10 % of this tail on the Hertz gap). Eq. 19's inlet length is not known here; on [-4, 1.5] the
    solver is within 8 % of it (measured 1.077, 1.031, 0.951 at L = 0.21, 0.86, 3.4), a check of the fit the
    bearing-friction model uses, on the automatic domain 31-43 % above it. Thermal, on the automatic domain (the
    ratio is within 5e-3 of that on [-4, 1.5]): the solver's force falls with L as theirs does, but by 35-47 % of the
    reduction of Eq. 21 (measured t_r/t_r0 0.962, 0.911, 0.851 against 0.920, 0.795, 0.569) and about a third of
    Eq. 20's: the same disagreement with an inlet analysis as the film's against Murch & Wilson's (above)."""
    from scipy.integrate import quad

    contact = _contact(u_m, 0.0)
    solution = solve_thermal(contact, LEVEL)
    isothermal = solve_thermal(contact, LEVEL, thermal=False, non_newtonian=False)
    cut = solve_thermal(attrs.evolve(contact, domain=(-4.0, 1.5)), LEVEL, thermal=False, non_newtonian=False)
    fit = rolling_resistance_line(contact.w, contact.R, contact.E_reduced, contact.eta0, contact.alpha, contact.u_m,
                                  1.0)
    assert cut.rolling_force / fit == pytest.approx(isothermal_ratio, abs=3e-3)
    X_a, b = contact.problem().domain[0], contact.problem().scales(contact.R, contact.w, contact.E_reduced)["b"]

    def gap(X):  # the Hertz gap outside the contact [b^2/R], X < -1
        return 0.5 * (-X * math.sqrt(X * X - 1.0) - math.acosh(-X))

    tail = 6.0 * contact.eta0 * contact.u_m * contact.R / b * quad(lambda X: 1.0 / gap(X), X_a, -4.0)[0]
    assert isothermal.rolling_force - cut.rolling_force == pytest.approx(tail, rel=0.1)
    ratio = solution.rolling_force / isothermal.rolling_force
    assert ratio == pytest.approx(thermal_ratio, abs=3e-3)
    L = contact.eta0 * contact.beta * contact.u_m**2 / contact.conductivity
    goksem_hargreaves = 1.0 / (1.0 + 0.29 * L**0.78)
    assert goksem_hargreaves < ratio < 1.0
    assert 0.3 < (1.0 - ratio) / (1.0 - goksem_hargreaves) < 0.5
    # Eq. 20 in camcontact's reading (D pi times the copy's): Eq. 19 at L = 0, and a larger reduction than Eq. 21's
    E, R = contact.E_reduced, contact.R
    G, U, W = contact.alpha * E, contact.eta0 * contact.u_m / (E * R), contact.w / (E * R)
    D = math.pi * math.sqrt(4.5 * math.pi) * G * U / W**1.5

    def equation_20(L):
        return R * W / contact.alpha * math.exp((52 / 79 + L ** (20 / 63) / 94) * math.log(D) - 114 / 701
                                                - math.log(1 + 86 / 209 * L ** (70 / 99)))

    assert equation_20(0.0) == pytest.approx(fit, rel=6e-3)  # measured 0.4 %: its exponent 52/79 against 0.658
    assert equation_20(L) / equation_20(0.0) < goksem_hargreaves < ratio


@pytest.mark.parametrize("u_m, film, rolling", [(5.0, 0.9445, 0.942), (10.0, 0.855, 0.857), (20.0, 0.700, 0.779)])
def test_compression_work_closes_part_of_the_gap_to_the_inlet_analyses(u_m, film, rolling):
    """With the lubricant's compression work and thermal expansion (expansivity 6.5e-4 1/K, T0 = 353 K;
    ThermalLineContact.thermal_expansivity) the inlet's layers that run into the pressure heat, and pure rolling
    loses more film and rolling force: h_c/h_c,iso 0.9445, 0.855, 0.700 at L_m = 0.21, 0.86, 3.4 (0.956, 0.883, 0.747
    without), the reduction 62-85 % of Murch & Wilson's (49-72 % without); t_r/t_r0 0.942, 0.857, 0.779 (0.962,
    0.911, 0.851 without), 51-73 % of the reduction of Goksem & Hargreaves' Eq. 21 (35-47 % without). Whether those
    inlet analyses included the compression work is not known here; the remaining gap is stated, not explained. The
    film expands again at the outlet and its mean temperature falls below T0 there (measured: 19, 33 and 38 K), the
    expansion cooling that thermal EHL analyses with compressive heating describe; without the work it stays above
    T0 everywhere. (On [-4, 1.5]: 0.947, 0.864, 0.723 and 0.938, 0.843, 0.756.)"""
    contact = _contact(u_m, 0.0, thermal_expansivity=6.5e-4, temperature=353.0)
    solution = solve_thermal(contact, LEVEL)
    isothermal = solve_thermal(contact, LEVEL, thermal=False, non_newtonian=False)
    assert solution.record.converged and not solution.profile_bounded.any()
    assert solution.film_reduction == pytest.approx(film, abs=2e-3)
    ratio = solution.rolling_force / isothermal.rolling_force
    assert ratio == pytest.approx(rolling, abs=3e-3)
    _, murch_wilson = _factor("murch_wilson", contact)
    assert murch_wilson < solution.film_reduction < solve_thermal(_contact(u_m, 0.0), LEVEL).film_reduction
    L = contact.eta0 * contact.beta * contact.u_m**2 / contact.conductivity
    assert 0.5 < (1.0 - ratio) * (1.0 + 0.29 * L**0.78) / (0.29 * L**0.78) < 0.8  # share of Eq. 21's reduction
    assert solution.temperature_rise[solution.wet].min() < -15.0


def test_a_longer_inlet_keeps_more_of_the_heated_backflow():
    """The inlet's reverse flow carries heated oil upstream; with the domain's inlet at -4 b it leaves the domain
    there, on the automatic domain (inlet at -11.3 b) it turns back into the contact: L_m = 0.86, h_c/h_c,iso 0.892
    (-4 b) against 0.883 (automatic, measured), the reduction 8 % larger, still far from Murch & Wilson's 0.812 (at
    L_m = 3.4: 0.771 against 0.747; the isothermal film itself is 2-7 % thicker with the longer inlet). An inlet at
    -16 b (level 8, about the same spacing) adds nothing: 0.883."""
    near = solve_thermal(_contact(10.0, 0.0, domain=(-4.0, 1.5)), LEVEL)
    automatic = solve_thermal(_contact(10.0, 0.0), LEVEL)
    far = solve_thermal(_contact(10.0, 0.0, domain=(-16.0, 1.5)), LEVEL + 2)
    assert automatic.contact.problem().domain[0] == pytest.approx(-8.0 * 2**0.5)
    assert automatic.film_reduction == pytest.approx(0.883, abs=2e-3)
    assert far.film_reduction == pytest.approx(automatic.film_reduction, abs=1e-3)
    assert automatic.film_reduction < near.film_reduction - 0.005


def test_sliding_reduces_the_film_less_than_the_sliding_factors_say():
    """With sliding (L_m = 0.21) the numerical film falls from 0.956 (S = 0) to 0.939 (S = 0.5) and 0.8725 (S = 1) of
    the isothermal one (Newtonian; an Eyring film, tau0 5 MPa: 0.943 and 0.885). Gupta et al. (1992; the same
    factor Zhou & Hoeprich 1991 quote from Zhu & Cheng, private communication 1988) give 0.900, 0.824, 0.775 and
    Wilson & Sheu (1983) 0.544 at S = 1: they disagree with each other by 1.4x and both with this solver. The
    solver's reduction at S = 1 is 2.9x its rolling one (Gupta's: 2.3x), most of it from the Hertz zone: there the
    hot film's viscosity profile shifts the entrainment (Couette factor 0.985-1.08) and the Newtonian film, sheared
    far beyond any oil's Eyring stress (230 K), reaches the bound of its profile (PROFILE_BOUND) at 59 nodes, which
    the record says. The formula factors stay available (film effect ``thermal``)."""
    reductions = {S: solve_thermal(_contact(5.0, S), LEVEL) for S in (0.0, 0.5, 1.0)}
    films = {S: solution.film_reduction for S, solution in reductions.items()}
    assert films[0.0] > films[0.5] > films[1.0]
    assert films[0.5] == pytest.approx(0.939, abs=3e-3) and films[1.0] == pytest.approx(0.8725, abs=3e-3)
    assert reductions[1.0].profile_bounded.any() and "profile bounded" in reductions[1.0].record.message
    eyring = solve_thermal(_contact(5.0, 1.0, eyring_stress=5e6), LEVEL).film_reduction
    assert eyring == pytest.approx(0.885, abs=3e-3)
    _, gupta = _factor("zhu_cheng", _contact(5.0, 1.0))
    _, wilson_sheu = _factor("wilson_sheu", _contact(5.0, 1.0))
    assert gupta == pytest.approx(0.775, abs=1e-3) and wilson_sheu == pytest.approx(0.544, abs=1e-3)
    assert films[1.0] > gupta > wilson_sheu
    assert 2.0 < (1.0 - films[1.0]) / (1.0 - films[0.0]) < 3.5


@pytest.mark.parametrize("S", [0.1, 0.5, 1.0])
def test_isothermal_eyring_traction_is_the_lumped_models_on_the_same_film(S):
    """Without the energy equation the solver's traction int tau_m dx / w equals the lumped Eyring model's over the
    solver's own pressure and film (fluid_traction with the solution's traction_profile) to 1e-3: the same stress
    tau0 asinh(eta u_s/(tau0 h)), here integrated over the wet film only. On the Hertz pressure with the central
    film the lumped model gives 5-6 % more (measured 0.0356 vs 0.0337 at S = 0.1)."""
    contact = _contact(5.0, S, eyring_stress=5e6)
    solution = solve_thermal(contact, LEVEL, thermal=False)
    problem = contact.problem()
    scales = problem.scales(contact.R, contact.w, contact.E_reduced)
    lumped = fluid_traction(contact.sliding_speed, p_h=scales["p_h"], film_thickness=solution.h_c, eta0=contact.eta0,
                            log_viscosity_ratio=lambda p: problem.log_viscosity(np.asarray(p) / scales["p_h"]),
                            rheology="eyring", eyring_stress=5e6, profile=solution.ehl.traction_profile())
    assert solution.traction_coefficient == pytest.approx(float(lumped.coefficient), rel=1e-3)


@pytest.mark.parametrize("S, measured, lumped_value", [(0.5, 0.0334, 0.0377), (1.0, 0.0288, 0.0353)])
def test_thermal_eyring_traction_is_below_the_lumped_thermal_model(S, measured, lumped_value):
    """With the energy equation the numerical traction is 11-19 % below the lumped thermal Eyring model (one
    contact temperature from a flash temperature and the film's mean rise, on the Hertz pressure): S = 0.5:
    0.0334 vs 0.0377, S = 1: 0.0288 vs 0.0353 (measured). The film's shear concentrates in its hot mid-layer, whose
    low viscosity one mean temperature does not see (the Couette stress follows the harmonic mean of the viscosity
    across the film): with the viscosity uniform at the mean temperature (cross_film=False) the traction is 0.0354
    and 0.0328, 6-7 % below the lumped model. Both fall below the isothermal values (0.0442, 0.0494)."""
    contact = _contact(5.0, S, eyring_stress=5e6)
    solution = solve_thermal(contact, LEVEL)
    problem = contact.problem()
    scales = problem.scales(contact.R, contact.w, contact.E_reduced)
    lumped = fluid_traction(contact.sliding_speed, p_h=scales["p_h"], film_thickness=solution.h_c, eta0=contact.eta0,
                            log_viscosity_ratio=lambda p: problem.log_viscosity(np.asarray(p) / scales["p_h"]),
                            rheology="eyring", eyring_stress=5e6, entrainment_speed=contact.u_m,
                            half_width=scales["b"], thermal=TractionThermal(0.14, 0.03, 12900.0, 12900.0))
    assert solution.traction_coefficient == pytest.approx(measured, rel=1e-2)
    assert float(lumped.coefficient) == pytest.approx(lumped_value, rel=1e-2)
    assert 0.8 < solution.traction_coefficient / float(lumped.coefficient) < 0.92
    uniform = solve_thermal(contact, LEVEL, cross_film=False)
    assert 0.92 < uniform.traction_coefficient / float(lumped.coefficient) < 0.96
