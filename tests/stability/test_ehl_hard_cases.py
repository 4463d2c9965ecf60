"""Hard line-contact EHL cases (issue 3): each converges or raises ConvergenceError with its record;
nothing returns NaN."""

import warnings

import attrs
import numpy as np
import pytest

from camcontact.errors import ConvergenceError
from camcontact.ehl.line_multigrid import MultigridSettings, solve_multigrid
from camcontact.ehl.line_problem import LineEHLProblem

CASES = {
    "heavy load M=1000 L=10": LineEHLProblem(M=1000, L=10, alpha=2.2e-8, z=0.68),
    # coarse grids close the gap (negative discrete films): converges since closed gaps pass no flow
    "heavy load, low L M=1000 L=2": LineEHLProblem(M=1000, L=2, alpha=2.2e-8, z=0.68),
    "low M high L M=2 L=22": LineEHLProblem(M=2, L=22, alpha=2.2e-8, z=0.68),
    "near rigid M=0.5 L=25": LineEHLProblem(M=0.5, L=25, alpha=2.2e-8, z=0.68),
    "isoviscous L=0": LineEHLProblem(M=20, L=0, viscosity="barus", density="incompressible"),
    "Roelands at p_h = 11.5 GPa (M=1000 L=20)": LineEHLProblem(M=1000, L=20, alpha=2.2e-8, z=0.68),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_hard_case_converges_finite_and_positive(name):
    problem = CASES[name]
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # no overflow / invalid-value warnings
        solution = solve_multigrid(problem, 7)
    assert solution.record.converged, solution.record.summary()
    assert np.all(np.isfinite(solution.P)) and np.all(np.isfinite(solution.H))
    assert solution.H_min > 0 and solution.P.min() >= 0
    assert abs(solution.record.load_errors[-1]) < 1e-5


def test_failure_is_loud_and_carries_the_record():
    """A solve that does not converge (here: two cycles allowed per attempt) ends in ConvergenceError with its
    record under ``strict``, and warns otherwise; never NaN."""
    from camcontact.ehl.line_multigrid import MultigridSettings
    from camcontact.errors import ConvergenceWarning

    problem = LineEHLProblem(M=20, L=10, alpha=1.7e-8, z=0.68)
    short = MultigridSettings(max_cycles=2)
    with pytest.raises(ConvergenceError, match="M = 20") as caught:
        solve_multigrid(problem, 8, settings=short, strict=True)
    assert caught.value.record is not None and not caught.value.record.converged
    with pytest.warns(ConvergenceWarning, match="not converged"):
        solution = solve_multigrid(problem, 8, settings=short)
    assert not solution.record.converged and np.all(np.isfinite(solution.P))


def test_barus_incompressible_at_l20_converges_to_the_discrete_solution():
    """Barus with an incompressible lubricant at L = 20 (viscosity ratio ~e^50 within the contact), M = 20
    and 50: a known failure until the spike's nodes were solved together (``spike_drop``). The multigrid
    solution (direct deformation, level 7) is the discrete problem's: the dense Newton solver started from
    it converges in at most two iterations and moves no pressure by more than 1e-7 (measured: 6e-9, 3e-8).
    (The dense solver alone, by grid sequencing, does not converge here.)"""
    from camcontact.ehl.line_multigrid import MultigridSettings
    from camcontact.ehl.line_reference import solve_reference

    for M in (20.0, 50.0):
        problem = LineEHLProblem(M=M, L=20, viscosity="barus", density="incompressible")
        solution = solve_multigrid(problem, 7, tolerance=1e-10, settings=MultigridSettings(deformation="direct"),
                                   strict=True)
        newton = solve_reference(problem, 7, tolerance=1e-10, initial=solution)
        assert newton.record.cycles <= 2
        assert np.abs(newton.P - solution.P).max() < 1e-7
        assert newton.H_min == pytest.approx(solution.H_min, abs=1e-9)


def test_stagnating_attempt_hands_over_to_the_conservative_settings():
    """The LS-1 roller cam at 9° (thesis convention, M = 2.915, L = 18.51) without the spike solve
    (``spike_drop = 0``): the F-cycles circle in a limit cycle (residual 6e-5 for all 40 cycles before
    the stagnation rule); the attempt stops after 10 cycles, so does the next one (F(2,1) instead of lean cycles),
    and the conservative F-cycles converge. Their film agrees with an independent solve by conservative W-cycles
    at a tighter tolerance. With the default settings (the spike's nodes solved together each cycle) the first
    attempt converges, to the same film."""
    from camcontact.ehl.cycle_monitor import stagnated
    from camcontact.ehl.line_multigrid import ROBUST, STAGNATION, MultigridSettings
    from camcontact.models.film_multigrid import automatic_domain

    assert not stagnated([1e-3 * 0.6**k for k in range(12)], STAGNATION)  # slow but steady: keeps going
    assert stagnated([6e-5, 5.7e-5, 5.9e-5, 6.4e-5, 6.5e-5, 6.3e-5, 6.3e-5, 6.3e-5, 6.4e-5, 6.5e-5], STAGNATION)
    # the automatic domain as it was before it was rounded up to share grids (rounded, [-6.73, 2.52], the
    # conservative F-cycles stagnate too and the W-cycles converge, a longer ladder than this test pins down; the
    # automatic domain is [-16, 2.52] since its inlet follows Grubin's inlet tail, camcontact.ehl.line_domain)
    problem = LineEHLProblem(M=2.9147, L=18.507, domain=(-6.138520038277336, 2.301945014354001))
    assert automatic_domain(2.9147, 18.507)[0] < problem.domain[0]
    pointwise = MultigridSettings(spike_drop=0.0)
    solution = solve_multigrid(problem, 8, settings=pointwise, strict=True)
    record = solution.record
    assert record.message.count("stagnated") == 2 and "converged with settings" in record.message
    assert solution.settings == attrs.evolve(pointwise, cycle_coarsest=1, **ROBUST[1])  # the coarsest resolved
    assert record.cycles < 40 and STAGNATION[0] <= 10
    check = solve_multigrid(problem, 8, tolerance=1e-9, settings=MultigridSettings(**ROBUST[2]), strict=True)
    assert solution.H_min == pytest.approx(check.H_min, abs=1e-6)
    assert solution.H0 == pytest.approx(check.H0, abs=1e-6)
    default = solve_multigrid(problem, 8, strict=True)
    assert default.record.message == "" and default.settings == MultigridSettings(cycle_coarsest=1)
    assert default.H_min == pytest.approx(check.H_min, abs=1e-6) and default.H0 == pytest.approx(check.H0, abs=1e-6)


def test_isoviscous_case_with_a_pressure_scale_is_isoviscous():
    """L = 0 is the isoviscous case whatever the viscosity law: with a pressure scale for the density law the Roelands
    law must not turn piezoviscous (it used the problem's alpha at that scale, alpha p_h = 22 instead of alpha-bar =
    0, and M = 0.5 converged to a 3.4 times too thick film, H_min 13.4). Now L = 0 equals the Barus isoviscous
    solution and the limit L -> 0 at the same scale; the isoviscous Moes-map corner M 0.5..5 converges (it diverged)."""
    from camcontact.models.film_multigrid import automatic_domain

    for M in (0.5, 2.0, 5.0):
        domain = automatic_domain(M, 0.0)
        roelands = solve_multigrid(LineEHLProblem(M=M, L=0.0, pressure_scale=1e9, domain=domain), 7, strict=True)
        barus = solve_multigrid(LineEHLProblem(M=M, L=0.0, viscosity="barus", pressure_scale=1e9, domain=domain), 7,
                                strict=True)
        near = solve_multigrid(LineEHLProblem(M=M, L=1e-4, pressure_scale=1e9, domain=domain), 7, strict=True)
        assert roelands.H_min == pytest.approx(barus.H_min, rel=1e-9)
        assert near.H_min == pytest.approx(roelands.H_min, rel=1e-3)
    assert LineEHLProblem(M=2.0, L=0.0, pressure_scale=1e9).alpha_law == 0.0
    consistent = LineEHLProblem.from_contact(R=0.01, w=2e5, E_reduced=2.3e11, u_m=2.0, eta0=0.05, alpha=2e-8)
    assert consistent.alpha_law == consistent.alpha  # a contact's scale is alpha-bar / alpha: the law is alpha's


def test_cycles_keep_a_converged_spike_only_with_the_spike_solve():
    """M 10, L 20 on level 9 (the viscosity falls by e^10 between two nodes at the spike). From the converged
    solution, further F-cycles with the spike's nodes solved together stay on it; with point relaxation only
    (``spike_drop = 0``) the coarse-grid corrections amplify the spike's node-sized errors (measured from the
    dense Newton solution: 8e-3 after one cycle, divergence after four)."""
    from camcontact.ehl.line_multigrid import LineHierarchy, MultigridSettings

    problem = LineEHLProblem(M=10, L=20, alpha=2.2e-8, z=0.68)
    solution = solve_multigrid(problem, 9, tolerance=1e-10, strict=True)
    assert solution.record.message == ""  # the first attempt, no fallback
    moved = {}
    default = MultigridSettings().spike_drop
    for drop in (default, 0.0):
        hierarchy = LineHierarchy(problem, 9, MultigridSettings(spike_drop=drop), compiled=True)
        P, H0 = solution.P.copy(), solution.H0
        for _ in range(3):
            P, H0 = hierarchy.cycle(8, P, H0, np.zeros(P.size), 0.0)
        moved[drop] = float(np.max(np.abs(P - solution.P))) if np.all(np.isfinite(P)) else np.inf
    assert moved[default] < 1e-6
    assert moved[0.0] > 1e-2


def test_runaway_state_raises_instead_of_being_kept(monkeypatch):
    """M = 3000, L = 0 (isoviscous, film ~4e-5 Hertz units) on level 8 with the classical FAS in every attempt (the
    coarse grids' own films; the ladder's fallbacks without ``film_fas``): every attempt runs off (residuals of
    1e10-1e187, H0 ~ 1e46, finite). Before the runaway rule the last attempt's finite absurd state was kept as the
    one with the smallest residual (H_min 1e36 with a warning); now the solve fails loudly with its record. (The
    default ladder's fallbacks, with the film FAS, converge it.)"""
    from camcontact.ehl import line_multigrid

    monkeypatch.setattr(line_multigrid, "ROBUST", tuple({k: v for k, v in rung.items() if k != "film_fas"}
                                                         for rung in line_multigrid.ROBUST))
    problem = LineEHLProblem(M=3000, L=0, alpha=2.2e-8, z=0.68, pressure_scale=1e9)
    with pytest.raises(ConvergenceError, match="runaway state") as caught:
        solve_multigrid(problem, 8)
    assert "every attempt diverged" in str(caught.value)


def test_runaway_rule_fires_above_its_residual(monkeypatch):
    """The rule itself: with the limit set below an easy case's residuals, every attempt stops at its first cycle
    as a runaway (the record kept, no solution returned)."""
    from camcontact.ehl import line_multigrid

    monkeypatch.setattr(line_multigrid, "RUNAWAY_RESIDUAL", 1e-30)
    with pytest.raises(ConvergenceError, match="runaway state") as caught:
        solve_multigrid(LineEHLProblem(M=20, L=10, alpha=1.7e-8, z=0.68), 6)
    assert caught.value.record is not None and caught.value.record.cycles == 0


def test_a_closed_discrete_film_is_said():
    """M = 3000, L = 0 on level 6 converges to a discrete solution whose film closes (H_min < 0): a solution of
    the discrete equations, not of the contact. The record says so and how to fix it."""
    problem = LineEHLProblem(M=3000, L=0, alpha=2.2e-8, z=0.68, pressure_scale=1e9)
    solution = solve_multigrid(problem, 6)
    assert solution.H_min < 0
    assert "the discrete film closes" in solution.record.message and "more levels" in solution.record.message


def test_heaviest_isoviscous_corner_converges_with_the_film_fas():
    """M = 3000, L = 0 on level 9 (film ~4e-5 Hertz units): the coarse grids' own films close over the contact (the
    225-node grid's by -4e-4 at M = 1000) and, with the classical FAS, every attempt ran away. With the film
    equation's FAS term (``MultigridSettings.film_fas``) the coarse films of the injected state are the fine films:
    the default ladder's last attempt (conservative F-cycles with it) converges it, with a positive film, and so does
    a ladder that starts with it, to the same film."""
    problem = LineEHLProblem(M=3000, L=0, alpha=2.2e-8, z=0.68, pressure_scale=1e9)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        solution = solve_multigrid(problem, 9)
    assert solution.record.converged and solution.H_min > 0.0
    assert "converged with settings" in solution.record.message
    assert solution.settings.film_fas and not MultigridSettings().film_fas
    alone = solve_multigrid(problem, 9, settings=MultigridSettings(film_fas=True))
    assert alone.record.converged and "failed" not in alone.record.message
    assert alone.H_min == pytest.approx(solution.H_min, abs=1e-7)


def test_heaviest_piezoviscous_corner_converges_to_the_dense_solution():
    """M = 3000, L = 30 on level 9: the Petrusevich spike is one node wide (ln eta falls by 33 between two nodes)
    and the classical attempts circle around the discrete solution (H_min between 3.8e-4 and 4.4e-4, period 2);
    the last attempt (conservative F-cycles with the film FAS) converges. Its film equals the dense Newton solution
    of the same grid (measured 2e-7 apart; level 8 gives 3.7e-4, level 10 5.3e-4: the grid, not the solver, sets the
    rest)."""
    from camcontact.ehl.line_reference import solve_reference

    problem = LineEHLProblem(M=3000, L=30, alpha=2.2e-8, z=0.68)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        solution = solve_multigrid(problem, 9)
    assert solution.record.converged and solution.settings.film_fas
    dense = solve_reference(problem, 9, deformation="direct", tolerance=1e-10, strict=True, initial=solution)
    assert abs(solution.H_min - dense.H_min) < 1e-6
    assert abs(solution.H0 - dense.H0) < 1e-6


def test_the_attempts_of_one_solve_share_their_start_solution(monkeypatch):
    """The ladder's attempts differ in their cycles, not in their full-multigrid start: the dense start solution
    (2.1 s for M 3000, L 15-30 on level 6) is computed once per solve, not once per attempt."""
    from camcontact.ehl import line_multigrid

    calls = []
    real_start = line_multigrid._start
    monkeypatch.setattr(line_multigrid, "_start", lambda *args: calls.append(args) or real_start(*args))
    solution = solve_multigrid(LineEHLProblem(M=3000, L=0, alpha=2.2e-8, z=0.68, pressure_scale=1e9), 9)
    assert "converged with settings" in solution.record.message  # more than one attempt ran
    assert len(calls) == 1
    solve_multigrid(LineEHLProblem(M=20, L=10, alpha=1.7e-8, z=0.68), 6)  # a new solve: its own start
    assert len(calls) == 2


def test_isoviscous_exit_converges_to_the_dense_solution():
    """M = 1000, L = 0 on level 9: no spike can form, and point relaxation stalled at the last pressurised node
    before the exit (its residual 5e-3): every attempt stopped with H_min 2.02-2.04e-4, 2-3 % above the dense Newton
    solution of the same grid, and called it converged. The exit zone is now solved together like a spike
    (``find_spikes``): the film equals the dense solution's (measured 1e-8 apart)."""
    from camcontact.ehl.line_reference import solve_reference

    problem = LineEHLProblem(M=1000, L=0, alpha=2.2e-8, z=0.68, pressure_scale=1e9)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        solution = solve_multigrid(problem, 9)
    dense = solve_reference(problem, 9, deformation="direct", tolerance=1e-10, strict=True, initial=solution)
    assert abs(solution.H_min - dense.H_min) < 2e-7  # 1 % of the film would be 2e-6
