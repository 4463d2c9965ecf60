"""Multigrid central film against the Moes (1992) formula across the Moes map.

The formula (Venner & Lubrecht 2000) interpolates numerical solutions; with the Barus viscosity
and an incompressible lubricant — the setting in which an independent solver (helper check,
X in [-4.5, 1.5], 1201 nodes) found it within -7..+5.5 % — our level-8 solutions lie within 5 %
for M = 5..200, L = 2..15 (the region tested here; the full map with its time cost is in
benchmarks/accuracy_vs_time.py). With Roelands and Dowson–Higginson the numerical films are up
to ~25 % thinner than the formula at high M and L (kept visible in the benchmark).
"""

import pytest

from camcontact.ehl.line_multigrid import solve_multigrid
from camcontact.ehl.line_problem import LineEHLProblem
from camcontact.models.film_line import moes_line_film


@pytest.mark.parametrize("M, L", [(5, 2), (10, 10), (20, 15), (50, 5), (100, 10), (200, 15)])
def test_moes_formula_within_five_percent(M, L):
    problem = LineEHLProblem(M=M, L=L, viscosity="barus", density="incompressible", alpha=2.2e-8)
    solution = solve_multigrid(problem, 8)
    assert solution.record.converged
    H_c, _ = solution.moes_film()
    assert H_c == pytest.approx(moes_line_film(M, L), rel=0.05)
