"""Multigrid and the dense Newton reference solve the same discrete problem; solver features."""

import math
import warnings

import attrs
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
    # tolerance 1e-10: the lean cycles' stop at 1e-9 leaves the spike's pressures 1.2e-6 from their converged values
    # (the films converged), which the next cycles remove (1.6e-7, 2.2e-8: no kick, which would not shrink)
    solution = solve_multigrid(TABLE51, level, tolerance=1e-10)
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


def test_extrapolated_start_continues_a_sequence_of_equal_steps():
    """Along M = 19, 20, 21 (equal steps) the start for M = 21 from the solutions at 19 and 20 is their linear
    extrapolation, nearer to the converged film than the last solution (H0 5.6e-4 off instead of 5.0e-3); at the
    cam cycle's tolerance 1e-5 its solve needs less work than the warm start from the last solution alone (3 F(1,1)
    cycles instead of 4) and gives the same film. The spike, whose pressure jumps between nodes,
    keeps the last solution's pressures; a pair on another grid gives the last solution itself."""
    from camcontact.ehl.line_multigrid import SPIKE_CHANGE, WarmStart, extrapolated_start

    problems = [LineEHLProblem(M=M, L=10, alpha=1.7e-8, z=0.68) for M in (19.0, 20.0, 21.0)]
    first, last = (solve_multigrid(p, 8, tolerance=1e-10) for p in problems[:2])
    target = solve_multigrid(problems[2], 8, tolerance=1e-10)
    start = extrapolated_start(last, first, problems[2], 8)
    assert isinstance(start, WarmStart) and start.P[0] == start.P[-1] == 0.0 and np.all(start.P >= 0.0)
    assert start.H0 == pytest.approx(2 * last.H0 - first.H0)
    assert abs(start.H0 - target.H0) < 0.2 * abs(last.H0 - target.H0)
    change = last.P - first.P
    jumps = np.abs(change) > SPIKE_CHANGE * last.P.max()
    smooth = np.convolve(jumps, np.ones(7), mode="same") == 0
    np.testing.assert_array_equal(start.P[smooth][1:-1], np.maximum(2 * last.P - first.P, 0.0)[smooth][1:-1])
    assert jumps.any()  # level 8: the spike moves by a node between M = 19 and 20
    np.testing.assert_array_equal(start.P[jumps], last.P[jumps])
    plain = solve_multigrid(problems[2], 8, tolerance=1e-5, initial=last)  # the cam cycle's tolerance
    predicted = solve_multigrid(problems[2], 8, tolerance=1e-5, initial=last, before=first)
    assert predicted.record.converged and plain.record.converged
    assert predicted.record.work_units[-1] < plain.record.work_units[-1]
    assert predicted.H_min == pytest.approx(target.H_min, abs=1e-5)
    coarser = solve_multigrid(problems[0], 7)
    assert extrapolated_start(last, coarser, problems[2], 8) is last


def test_a_warm_start_on_another_domain_maps_its_inlet():
    """A warm start on a shorter or longer inlet: the new inlet's upstream half takes the start's inlet mapped
    linearly (its boundary on the start's boundary, the middle fixed), the rest the start's own nodes; from it the
    solve converges to the cold solution of the new domain."""
    from camcontact.ehl.line_multigrid import inlet_mapped

    X_start = np.linspace(-4.0, 1.5, 113)
    same = inlet_mapped(X_start.copy(), X_start)
    np.testing.assert_array_equal(same, X_start)
    for X in (np.linspace(-5.0, 1.8, 113), np.linspace(-3.5, 1.4, 113)):
        mapped = inlet_mapped(X, X_start)
        assert mapped[0] == pytest.approx(X_start[0]) and np.all(np.diff(mapped) > 0)
        middle = 0.5 * X_start[0]
        np.testing.assert_array_equal(mapped[X >= middle], X[X >= middle])
    longer = LineEHLProblem(M=20, L=10, alpha=1.7e-8, z=0.68, domain=(-5.0, 1.8))
    start = solve_multigrid(TABLE51, 7)
    warm = solve_multigrid(longer, 7, initial=start)
    cold = solve_multigrid(longer, 7)
    assert warm.record.converged and warm.H_min == pytest.approx(cold.H_min, abs=1e-6)


def test_solves_of_one_domain_share_their_grid_tables():
    """The grids and kernel tables depend on the domain and levels only: two hierarchies of one domain share them
    (built once), another domain has its own; the transient solver's per-step scaling of its parabola leaves the
    shared one alone."""
    from camcontact.ehl.line_multigrid import LineHierarchy
    from camcontact.ehl.line_transient import _TransientHierarchy

    settings = MultigridSettings()
    a = LineHierarchy(TABLE51, 6, settings, compiled=True)
    b = LineHierarchy(LineEHLProblem(M=5, L=3), 6, settings, compiled=True)
    c = LineHierarchy(LineEHLProblem(M=5, L=3, domain=(-5.0, 1.5)), 6, settings, compiled=True)
    assert a.grids is b.grids and a.c1s is b.c1s and a.levels is b.levels
    assert c.grids is not a.grids and c.levels[-1].X[0] == -5.0
    shared = a.grids.parabola.copy()
    transient = _TransientHierarchy(TABLE51, 6, settings, compiled=True)
    transient.set_conditions(0.5, 1.0, 0.0)
    np.testing.assert_array_equal(a.grids.parabola, shared)
    np.testing.assert_allclose(transient.parabola, 0.5 * shared)


def test_automatic_domain_is_rounded_up_so_that_neighbours_share_it():
    """Thick films get the domain [-4 r_in, 1.5 r] with both reaches powers of 2^(1/4): r never shorter than
    sqrt(2 H), r_in the shortest that leaves at most INLET_TAIL of Grubin's inlet integral upstream (and never
    shorter than r), the same for neighbouring contacts; thin films keep [-4, 1.5]."""
    from camcontact.ehl.film_formulas import moes_line_film
    from camcontact.ehl.line_domain import DOMAIN_RATIO, INLET_TAIL, automatic_domain, inlet_tail_fraction

    assert automatic_domain(50.0, 10.0) == (-4.0, 1.5)
    for M, L in ((2.0, 20.0), (3.0, 18.0), (0.5, 5.0), (1.0, 0.0), (10.0, 13.0), (20.0, 10.0)):
        H = moes_line_film(M, L) * math.pi / (8.0 * M)
        reach = math.sqrt(2.0 * H)
        inlet, outlet = automatic_domain(M, L)
        rounded, rounded_in = outlet / 1.5, -inlet / 4.0
        for r in (rounded, rounded_in):
            assert math.log(r) / math.log(DOMAIN_RATIO) == pytest.approx(round(math.log(r) / math.log(DOMAIN_RATIO)))
        assert rounded == 1.0 if reach <= 1.0 else reach <= rounded < DOMAIN_RATIO * reach
        assert rounded_in >= rounded and inlet_tail_fraction(inlet, H) <= INLET_TAIL
        assert rounded_in == rounded or inlet_tail_fraction(inlet / DOMAIN_RATIO, H) > INLET_TAIL
    assert automatic_domain(3.0, 18.0) == automatic_domain(3.05, 18.1)
    assert automatic_domain(3.0, 18.0, inlet_tail=None)[0] == pytest.approx(-4.0 * DOMAIN_RATIO**3)  # earlier rule
    with pytest.raises(ValueError, match="inlet_tail"):
        automatic_domain(3.0, 18.0, inlet_tail=0.0)


@pytest.mark.parametrize("M, L", [(10.5, 13.1), (3.33, 23.3)])
def test_a_cut_inlet_thins_the_film_by_grubins_missing_tail(M, L):
    """Cutting the inlet at X_a leaves out the part T of Grubin's inlet integral upstream of X_a
    (camcontact.ehl.line_domain): the central film is thin by about 0.8 T (measured 0.72-0.87 T over H_c 0.03-1.3),
    here against a solution with the inlet at -20.5 b on the same spacing. With the inlet at -4 b that is 1.0 %
    (H_c 0.24) and 7.1 % (H_c 1.02, the roller at 20 m/s); on the automatic domain 0.1-0.2 %."""
    from camcontact.ehl.line_domain import automatic_domain, inlet_tail_fraction

    problem = LineEHLProblem(M=M, L=L)
    reference = solve_multigrid(attrs.evolve(problem, domain=(-20.5, 1.5)), 9, strict=True)  # spacing of level 7
    for X_a, level in ((-4.0, 7), (-9.5, 8)):
        cut = solve_multigrid(attrs.evolve(problem, domain=(X_a, 1.5)), level, strict=True)
        loss = 1.0 - cut.H_c / reference.H_c
        assert 0.65 < loss / inlet_tail_fraction(X_a, reference.H_c) < 0.95
    automatic = solve_multigrid(attrs.evolve(problem, domain=automatic_domain(M, L)), 8, strict=True)
    assert 0.0 < 1.0 - automatic.H_c / reference.H_c < 3e-3


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
