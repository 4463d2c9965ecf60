"""EHL kernels: numba versions equal their plain-Python twins; deformation methods agree."""

import math

import numpy as np
import pytest

from camcontact.ehl import _kernels
from camcontact.ehl.deformation import Deformation, default_correction
from camcontact.ehl.line_problem import LineEHLProblem, kernel_coefficients


def _state(n=113):
    problem = LineEHLProblem(M=20, L=10, alpha=1.7e-8, z=0.68)
    X = np.linspace(-4.0, 1.5, n)
    h = X[1] - X[0]
    P = np.where(np.abs(X) < 1, np.sqrt(np.clip(1 - X * X, 0, None)), 0.0)
    P += 0.05 * np.exp(-((X - 0.9) / 0.05) ** 2)
    H = 0.08 + 0.5 * X * X - Deformation(n, h, "direct")(P) / math.pi + 0.5
    return problem, X, h, P, H


def test_kernel_value_matches_closed_form_table():
    """K(d) of Tsuha (2015) Eq. 5.46, scalar kernel vs vectorised table."""
    h = 0.01
    table = kernel_coefficients(h, 40)
    np.testing.assert_allclose([_kernels.kernel_value(float(d), h) for d in range(40)], table, rtol=1e-13, atol=1e-16)
    # K(0) = 2 (h/2)(ln(h/2) - 1) (Tsuha Eq. 5.47)
    assert table[0] == pytest.approx(h * (math.log(h / 2) - 1))


@pytest.mark.parametrize("name", ["reynolds_residual"])
def test_residual_twin(name):
    problem, X, h, P, H = _state()
    codes, params = problem.law_codes, problem.law_parameters
    python, compiled = np.empty(X.size), np.empty(X.size)
    _kernels.PY[name](P, H, h, problem.lam, *codes, params, python)
    _kernels.compiled(name)(P, H, h, problem.lam, *codes, params, compiled)
    np.testing.assert_allclose(compiled, python, rtol=1e-12, atol=1e-12)


def test_relaxation_twin_gives_the_same_sweep():
    problem, X, h, P, H = _state()
    K = np.array([_kernels.kernel_value(float(d), h) for d in range(16)])
    codes, params = problem.law_codes, problem.law_parameters
    dry = np.zeros(X.size, dtype=bool)
    results = []
    for function in (_kernels.PY["relax_hybrid"], _kernels.compiled("relax_hybrid")):
        P_, H_ = P.copy(), H.copy()
        count = function(P_, H_, np.zeros(X.size), h, problem.lam, *codes, params, K, 0.7, 0.3, 4.0, 0, 1, X.size - 2, dry)
        results.append((P_, H_, count))
    np.testing.assert_allclose(results[1][0], results[0][0], rtol=1e-12, atol=1e-14)
    assert results[0][2] == results[1][2] > 0
    assert np.all(results[0][0] >= 0)


@pytest.mark.parametrize("n", [57, 449, 3585])
def test_deformation_methods_agree(n):
    X = np.linspace(-4, 1.5, n)
    h = X[1] - X[0]
    P = np.where(np.abs(X) < 1, np.sqrt(np.clip(1 - X * X, 0, None)), 0.0)
    direct = Deformation(n, h, "direct")(P)
    table = kernel_coefficients(h, n)
    explicit = np.array([np.dot(table[np.abs(i - np.arange(n))], P) for i in range(n)])
    np.testing.assert_allclose(direct, explicit, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(Deformation(n, h, "fft")(P), direct, rtol=1e-10, atol=1e-12)
    mlmi = Deformation(n, h, "mlmi")(P)
    assert np.max(np.abs(mlmi - direct)) / np.max(np.abs(direct)) < 1e-6


def test_mlmi_error_falls_with_the_correction_width():
    """Measured (module doc of deformation.py): ~2e-4 at width 6, ~9e-6 at 10, ~5e-7 at 16."""
    n = 449
    X = np.linspace(-4, 1.5, n)
    h = X[1] - X[0]
    P = np.where(np.abs(X) < 1, np.sqrt(np.clip(1 - X * X, 0, None)), 0.0)
    direct = Deformation(n, h, "direct")(P)
    errors = [np.max(np.abs(Deformation(n, h, "mlmi", correction=m)(P) - direct)) for m in (6, 10, 16)]
    assert errors[0] > errors[1] > errors[2]
    assert errors[2] / np.max(np.abs(direct)) < 1e-6
    assert default_correction(n) == 16 and default_correction(10**9) == math.ceil(3 + math.log(10**9))


def test_mlmi_twin_equals_compiled():
    n = 225
    X = np.linspace(-4, 1.5, n)
    h = X[1] - X[0]
    P = np.where(np.abs(X) < 1, np.sqrt(np.clip(1 - X * X, 0, None)), 0.0)
    np.testing.assert_allclose(Deformation(n, h, "mlmi", compiled=False)(P), Deformation(n, h, "mlmi")(P),
                               rtol=1e-12, atol=1e-14)
