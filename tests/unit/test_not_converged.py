"""camcontact.errors.not_converged: the one ending of a solve that did not converge (the multigrid attempt ladder,
the starved, thermal and reference line solvers): strict raises ConvergenceError with the record, else a
ConvergenceWarning points at the line that called the solver."""

import inspect
import warnings

import pytest

from camcontact.errors import ConvergenceError, ConvergenceWarning, not_converged

RECORD = object()


def _solver(strict):
    not_converged("a solver did not converge: why", RECORD, strict=strict)


def test_strict_raises_with_the_record():
    with pytest.raises(ConvergenceError, match="why") as caught:
        _solver(strict=True)
    assert caught.value.record is RECORD


def test_the_warning_points_at_the_solvers_caller():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        line = inspect.currentframe().f_lineno + 1
        _solver(strict=False)
    assert len(caught) == 1 and issubclass(caught[0].category, ConvergenceWarning)
    assert caught[0].filename == __file__ and caught[0].lineno == line
