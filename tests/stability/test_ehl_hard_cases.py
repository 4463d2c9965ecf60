"""Hard line-contact EHL cases (issue 3): each converges or raises ConvergenceError with its record;
nothing returns NaN."""

import warnings

import numpy as np
import pytest

from camcontact.errors import ConvergenceError
from camcontact.ehl.line_multigrid import solve_multigrid
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
    """A case the solver cannot do (Barus, incompressible, L = 20 at M = 20: viscosity ratio ~e^50
    within the contact) ends in ConvergenceError with its record, not in NaN."""
    problem = LineEHLProblem(M=20, L=20, viscosity="barus", density="incompressible")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            solution = solve_multigrid(problem, 8, strict=True)
        except ConvergenceError as error:
            assert error.record is not None and not error.record.converged
            assert "M = 20" in str(error)
        else:  # should it converge one day, it must be a real solution
            assert solution.record.converged and np.all(np.isfinite(solution.P))
