"""Multigrid and the dense Newton reference solve the same discrete problem; solver features."""

import math
import warnings

import numpy as np
import pytest

import camcontact as cc
from camcontact.errors import ConvergenceError, InputError
from camcontact.ehl.line_multigrid import MultigridSettings, solve_multigrid
from camcontact.ehl.line_problem import LineEHLProblem, grid_points
from camcontact.ehl.line_reference import solve_reference

TABLE51 = LineEHLProblem(M=20, L=10, alpha=1.7e-8, z=0.68)


def test_grid_sizes():
    """n_k = 14 2^(k-1) + 1: 449, 897, 1793, 3585 at levels 6-9 and 28673 at level 12 (Tsuha §0 item 8)."""
    assert [grid_points(k) for k in (1, 6, 7, 8, 9, 12)] == [15, 449, 897, 1793, 3585, 28673]


@pytest.mark.parametrize("level", [5, 6])
def test_multigrid_converges_to_the_newton_solution(level):
    """Same discrete equations, direct deformation in both: the solutions coincide."""
    reference = solve_reference(TABLE51, level)
    multigrid = solve_multigrid(TABLE51, level, tolerance=1e-11, settings=MultigridSettings(deformation="direct"))
    assert multigrid.record.converged and reference.record.converged
    np.testing.assert_allclose(multigrid.P, reference.P, atol=1e-7)
    assert multigrid.H0 == pytest.approx(reference.H0, abs=1e-9)
    assert multigrid.H_min == pytest.approx(reference.H_min, abs=1e-9)


def test_a_converged_solution_is_a_fixed_point_of_the_cycle():
    """Further cycles from a converged solution leave it (nearly) unchanged. Before cavitated
    coarse nodes kept their own equation, the FAS coarse problem placed them exactly on the
    complementarity edge, the coarse grids filled the outlet with small pressures and each cycle
    kicked a converged level-10 solution by ~5e-6 (the free boundary moved by 3 nodes)."""
    from camcontact.ehl.line_multigrid import LineHierarchy

    level = 10
    solution = solve_multigrid(TABLE51, level, tolerance=1e-9)
    assert solution.record.converged
    solver = LineHierarchy(TABLE51, level, MultigridSettings(), compiled=True)
    P, H0 = solution.P.copy(), solution.H0
    for _ in range(3):
        P_next, H0 = solver.cycle(level - 1, P, H0, np.zeros(P.size), 0.0)
        assert np.abs(P_next - P).max() < 1e-6
        P = P_next


def test_convergence_record_is_complete():
    solution = solve_multigrid(TABLE51, 7)
    record = solution.record
    assert record.converged and record.levels == 7 and record.nodes == 897
    assert len(record.residuals) == len(record.load_errors) == len(record.work_units) == record.cycles >= 1
    assert record.wall_time > 0 and record.work_units[-1] > record.work_units[0]
    frame = record.to_frame()
    assert list(frame.columns) == ["cycle", "residual [-]", "load error [-]", "work units [-]"]
    assert "converged" in record.summary()
    assert abs(record.load_errors[-1]) < 1e-6


def test_warm_start_from_a_neighbouring_solution():
    cold = solve_multigrid(LineEHLProblem(M=21, L=10, alpha=1.7e-8, z=0.68), 7)
    base = solve_multigrid(TABLE51, 7)
    warm = solve_multigrid(LineEHLProblem(M=21, L=10, alpha=1.7e-8, z=0.68), 7, initial=base)
    assert warm.record.converged
    assert warm.H_min == pytest.approx(cold.H_min, abs=2e-7)
    assert warm.record.work_units[-1] < cold.record.work_units[-1]


def test_derived_quantities_and_dimensional_values():
    solution = solve_multigrid(TABLE51, 6)
    assert solution.X[np.argmin(solution.H)] == solution.X_min
    assert solution.H_c == pytest.approx(np.interp(0.0, solution.X, solution.H))
    P_s, X_s = solution.spike
    assert 0.5 < X_s < 1.0 and P_s == pytest.approx(solution.P[np.argmin(np.abs(solution.X - X_s))])
    # a contact with this M and L: R = 10 mm, w = 200 N/mm, E' = 2.2e11 Pa
    R, w, E = 0.01, 2e5, 2.2e11
    values = solution.dimensional(R, w, E)
    b = math.sqrt(8 * w * R / (math.pi * E))
    assert values["b"] == pytest.approx(b)
    assert values["h_min"] == pytest.approx(solution.H_min * b * b / R)
    assert values["p_max"] == pytest.approx(solution.P_max * 2 * w / (math.pi * b))
    H_c, H_min = solution.moes_film()
    assert H_c == pytest.approx(solution.H_c * 8 * 20 / math.pi)


def test_rigid_isoviscous_limit_is_martin():
    """No elasticity, no piezoviscosity: h0 = 4.895 eta0 u_m R / w (independent integration, see the
    extras plugin tests), i.e. H0 = 0.9611/M^2 in Hertz units (H = h R/b^2, b^2 = 8 w R/(pi E')).
    The discrete solution on 897 nodes of [-12, 4] lies 0.9 % below (grid and finite inlet)."""
    problem = LineEHLProblem(M=2.0, L=0.0, viscosity="barus", density="incompressible", elastic=False,
                             domain=(-12.0, 4.0))
    solution = solve_multigrid(problem, 7)
    assert solution.record.converged
    assert solution.H_c == pytest.approx(0.9611 / 4.0, rel=0.015)


def test_bad_inputs():
    with pytest.raises(InputError, match="M = -1"):
        LineEHLProblem(M=-1, L=10)
    with pytest.raises(InputError, match="domain"):
        LineEHLProblem(M=20, L=10, domain=(-0.5, 1.5))
    with pytest.raises(InputError, match="pressure_scale"):
        LineEHLProblem(M=20, L=0)
    with pytest.raises(InputError, match="levels = 0"):
        solve_multigrid(TABLE51, 0)
    with pytest.raises(InputError, match="too large for the dense solver"):
        solve_reference(TABLE51, n=5000)
    with pytest.raises(InputError, match="u_m = 0"):
        LineEHLProblem.from_contact(R=0.01, w=1e5, E_reduced=2.2e11, u_m=0.0, eta0=0.04, alpha=2e-8)


def test_strict_raises_with_the_record():
    settings = MultigridSettings(max_cycles=1)
    with pytest.raises(ConvergenceError) as info:
        solve_multigrid(TABLE51, 8, tolerance=1e-14, settings=settings, strict=True)
    assert info.value.record is not None and not info.value.record.converged
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        solution = solve_multigrid(TABLE51, 8, tolerance=1e-14, settings=settings)
    assert not solution.record.converged and any("multigrid" in str(w.message) for w in caught)
    assert np.all(np.isfinite(solution.P))


def test_multigrid_film_model_in_an_analysis(steel):
    oil = cc.Lubricant(alpha="2.2e-8 1/Pa", roelands_z=0.68)
    contact = cc.LineContact(body1=cc.Body(material=steel, radius="33.46 mm", speed="3.503 m/s"),
                             body2=cc.Body(material=steel, radius="10 mm", speed="3.503 m/s"),
                             load="3087.99 N", length="15 mm", lubricant=oil)
    from camcontact.models.film_multigrid import Multigrid

    result = cc.Analysis(contact, outputs=["h_c", "h_min", "film_validity", "M", "L"],
                         models={"film": [Multigrid(levels=7), "pan_hamrock"]}).run()
    numeric, formula = result.rows
    assert numeric["film_validity"] == "ok"
    assert 0.0 < numeric["h_min"] < numeric["h_c"]
    # Pan & Hamrock fit numerical solutions: within 20 % of ours
    assert numeric["h_c"] == pytest.approx(formula["h_c"], rel=0.2)
    film = [r for r in result.records if r.step == "film" and r.model == "multigrid"]
    assert film and film[0].wall_time > 0
