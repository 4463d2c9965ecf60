"""Hard cases of the thermal / non-Newtonian line solver (camcontact.ehl.line_thermal): heavy loads, high speeds
and heavy sliding stay stable, and what cannot be solved says so.

Measured over a map at level 7 (w = 50 kN/m, 200 kN/m, 1 MN/m on R = 10 mm, p_h 0.4-1.9 GPa; u_m = 0.5, 5, 20 m/s;
S = 0, 0.3, 1.5; Newtonian and Eyring 5 MPa with a limiting shear stress 0.047 p), with the viscosity varying
across the film (the default) and the energy equation carrying the flow across the film's layers (2026-11-29): 50 of
54 converge with it (median 6 iterations, at most 30; 77 s for the map with the fallbacks). Every Eyring film
converges, the heavy-sliding ones at 20 m/s and S = 1.5 too (before that change they stalled). Four Newtonian films
far beyond any oil's range (hundreds of kelvin) do not: at 200 kN/m, 20 m/s, S = 0.3 a non-finite flow factor, at
1 MN/m, 5 m/s, S = 1.5 a stall (mean change of the factors 2e-2 after 40 iterations); for both solve_thermal returns
the converged solution with the viscosity uniform across the film, which its record and ``cross_film`` say (52 of
54 converge). The other two, at 1 MN/m and 20 m/s with S = 0.3 and 1.5 (p_h 1.9 GPa), run away in both models and
raise ConvergenceError (a non-finite flow factor). Before the change: 48 with the cross-film viscosity, 53 with the
fallback (the Eyring films at 20 m/s, S = 1.5 fell back; the Newtonian film at 1 MN/m, 20 m/s, S = 0.3 converged
by the fallback at 570 K). All of that was on the domain [-4, 1.5]. On the automatic domains (ThermalLineContact's
default since 2026-11-29, inlets -4 to -32 b, with the cycles' coarsest grid at most 1 b apart) all 54 converge, 53
with the cross-film viscosity (the stall at 1 MN/m, 5 m/s, S = 1.5 remains; the two runaways converge), in 36 s."""

import warnings

import pytest

from camcontact.ehl.line_thermal import ThermalLineContact, solve_thermal
from camcontact.errors import ConvergenceError, ConvergenceWarning

LEVEL = 7


def _contact(w, u_m, S, eyring=True, **changes):
    data = dict(R=0.01, w=w, E_reduced=2.26e11, u1=u_m * (1 + S / 2), u2=u_m * (1 - S / 2), eta0=0.04, alpha=2e-8,
                beta=0.03, conductivity=0.14, heat_capacity=1.74e6, effusivity_1=12900.0, effusivity_2=12900.0,
                eyring_stress=5e6 if eyring else None, limiting_shear_slope=0.047 if eyring else None)
    data.update(changes)
    return ThermalLineContact(**data)


@pytest.mark.parametrize("w, u_m, S, eyring", [
    (1e6, 5.0, 1.5, True),     # p_h 1.9 GPa, heavy sliding: 300 K in the film
    (1e6, 20.0, 0.3, True),    # p_h 1.9 GPa at 20 m/s
    (5e4, 20.0, 1.5, False),   # light load, fast, Newtonian: film reduction to 0.53
    (1e6, 0.5, 1.5, False),    # slow, heavy, Newtonian sliding: 450 K (converges, but far out of a real oil's range)
])
def test_hard_contacts_converge(w, u_m, S, eyring):
    solution = solve_thermal(_contact(w, u_m, S, eyring), LEVEL)
    assert solution.record.converged, solution.record.message
    assert 0.4 < solution.film_reduction <= 1.0 and solution.max_temperature_rise > 0


def test_a_stalled_cross_film_iteration_returns_the_uniform_viscosity_solution_and_says_so():
    """Newtonian film at 1 MN/m (p_h 1.9 GPa), 5 m/s and S = 1.5: the iteration with the viscosity varying across the
    film stalls (40 iterations, the mean change of the flow and Couette factors about 2e-2); the one with the viscosity
    uniform at the film's mean temperature converges (550 K), and that is returned, ``cross_film`` False, the record
    saying why, without a ConvergenceWarning. In a scene the film's validity says it (film_valid False)."""
    from camcontact.ehl.line_thermal import UNIFORM_FALLBACK
    from camcontact.models.film_multigrid import Multigrid

    contact = _contact(1e6, 5.0, 1.5, eyring=False)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ConvergenceWarning)
        solution = solve_thermal(contact, LEVEL)
    assert solution.record.converged and not solution.cross_film
    assert solution.record.message.startswith(UNIFORM_FALLBACK) and "after 40 iterations" in solution.record.message
    assert solution.film_reduction == pytest.approx(solve_thermal(contact, LEVEL, cross_film=False).film_reduction)
    messages = Multigrid(levels=LEVEL).check_validity({"ehl_solution": solution})
    assert any("uniform across the film" in message for message in messages)


def test_heavy_sliding_eyring_films_converge_with_the_cross_film_viscosity():
    """The Eyring films at 20 m/s and S = 1.5 (30 m/s of sliding), which stalled with the cross-film viscosity until
    the energy equation carried the flow across the film's layers, converge with it (measured 24 iterations at
    200 kN/m)."""
    solution = solve_thermal(_contact(2e5, 20.0, 1.5), LEVEL)
    assert solution.record.converged and solution.cross_film
    assert 0.4 < solution.film_reduction < 0.7 and 200.0 < solution.max_temperature_rise < 350.0


def test_a_heavily_loaded_incompressible_eyring_film_converges():
    """M = 28, L = 14, incompressible, S = 0.1 (the line-contact scene's friction test case): the Eyring flow factor
    reaches e^14 in the Hertz zone. Frozen per node, it made the Hertz zone behave like a contact of 1000 times the
    load parameter and the multigrid diverged with every step; with its pressure dependence in the kernels the
    iteration converges in about 10 iterations."""
    contact = ThermalLineContact(R=0.01, w=5e5, E_reduced=2.3077e11, u1=2.1, u2=1.9, eta0=0.03436, alpha=2.2e-8,
                                 beta=0.0, conductivity=1.0, heat_capacity=1.0, effusivity_1=1.0, effusivity_2=1.0,
                                 eyring_stress=5e6, limiting_shear_slope=0.047, density="incompressible")
    solution = solve_thermal(contact, LEVEL, thermal=False)
    assert solution.record.converged and solution.record.cycles < 20
    assert solution.film_reduction == pytest.approx(1.0, abs=1e-2)


def test_a_thermal_runaway_fails_loudly():
    """Newtonian film, 1 MN/m, 20 m/s, S = 0.3, p_h 1.9 GPa: at the edge of thermal runaway. Which way it goes has
    depended on the multigrid solves inside (with the lean cycles it failed at iteration 3, with the finest level
    post-smoothed it converged at a 570 K rise) and on the energy model (with the flow across the film's layers
    both viscosity models meet a non-finite flow factor at iteration 2; on the automatic domain, inlet at -6.7 b, it
    converges: h_c/h_c,iso 0.711). Any outcome but a silent one is allowed:
    converged, the film is thinner and warmer; not converged, a ConvergenceWarning and the record say why; run away,
    ConvergenceError with the record."""
    contact = _contact(1e6, 20.0, 0.3, eyring=False)
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            solution = solve_thermal(contact, LEVEL)
    except ConvergenceError as error:
        assert "non-finite flow factor" in str(error) and error.record is not None
        return
    if solution.record.converged:
        assert 0.4 < solution.film_reduction < 1.0 and 100.0 < solution.max_temperature_rise < 1000.0
        assert not any(issubclass(w.category, ConvergenceWarning) for w in caught)
    else:
        assert any(issubclass(w.category, ConvergenceWarning) and "thermal line EHL did not converge" in str(w.message)
                   for w in caught)
        assert "stopped:" in solution.record.message or "iterations" in solution.record.message


def test_an_unconverged_thermal_solve_is_flagged_not_hidden():
    """An Eyring film at 1 MN/m, 20 m/s, S = 0.3 with 3 iterations allowed (it needs 13): the solve warns (strict:
    raises) and its record says why; the uniform-viscosity fallback does not hide it (it is not converged either)."""
    contact = _contact(1e6, 20.0, 0.3)
    with pytest.warns(ConvergenceWarning, match="thermal line EHL did not converge"):
        solution = solve_thermal(contact, LEVEL, max_iterations=3)
    assert not solution.record.converged and "after 3 iterations" in solution.record.message
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(ConvergenceError):
            solve_thermal(contact, LEVEL, max_iterations=3, strict=True)
