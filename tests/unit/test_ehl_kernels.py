"""EHL kernels: numba versions equal their plain-Python twins; deformation methods agree."""

import math

import numpy as np

from tests.kernel_inputs import PLAIN
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
    full = np.ones(X.size)
    # flow and Couette factors varying node to node
    phi = np.column_stack([1.0 + 0.5 * np.sin(3.0 * X), 1e-3 * (1.0 + X**2), 1.0 + 0.1 * np.cos(2.0 * X)])
    _kernels.PY[name](P, H, full, phi, h, problem.lam, *codes, params, 1.0, 0.0, python)
    _kernels.compiled(name)(P, H, full, phi, h, problem.lam, *codes, params, 1.0, 0.0, compiled)
    np.testing.assert_allclose(compiled, python, rtol=1e-12, atol=1e-12)


def test_residual_with_couette_factors_is_the_generalised_operator():
    """The residual with flow factors (a, k) and Couette factors c, written out here with numpy for a full film
    (second-order upwind weights 1.5, -2, 0.5 from the third node on): the wedge carries c rho H, the squeeze term
    c_t rho H does not (its content is the film's, Yang & Wen's rho_e h)."""
    problem, X, h, P, H = _state()
    codes, params = problem.law_codes, problem.law_parameters
    a, k, c = 1.0 + 0.5 * np.sin(3.0 * X), 1e-3 * (1.0 + X**2), 1.0 + 0.1 * np.cos(2.0 * X)
    s, c_t = 0.8, 2.5
    out = np.empty(X.size)
    _kernels.compiled("reynolds_residual")(P, H, np.ones(X.size), np.column_stack([a, k, c]), h, problem.lam, *codes,
                                          params, s, c_t, out)
    xi = problem.flow_coefficient(P, H) * problem.poiseuille_factor(P, a, k)
    q = problem.density_ratio(P) * H
    i = np.arange(2, X.size - 1)
    poiseuille = (0.5 * (xi[i - 1] + xi[i]) * (P[i - 1] - P[i]) + 0.5 * (xi[i] + xi[i + 1]) * (P[i + 1] - P[i])) / h**2
    wedge = s * (1.5 * c[i] * q[i] - 2.0 * c[i - 1] * q[i - 1] + 0.5 * c[i - 2] * q[i - 2]) / h
    np.testing.assert_allclose(out[i], poiseuille - wedge - c_t * q[i], rtol=1e-10, atol=1e-10 * np.abs(wedge).max())


def test_relaxation_twin_gives_the_same_sweep():
    problem, X, h, P, H = _state()
    K = np.array([_kernels.kernel_value(float(d), h) for d in range(16)])
    codes, params = problem.law_codes, problem.law_parameters
    dry = np.zeros(X.size, dtype=bool)
    results = []
    for function in (_kernels.PY["relax_hybrid"], _kernels.compiled("relax_hybrid")):
        P_, H_ = P.copy(), H.copy()
        count = function(P_, H_, np.ones(X.size), PLAIN(X.size), np.zeros(X.size), h, problem.lam, *codes, params, K, 0.7, 0.3, 4.0,
                         0, 1, X.size - 2, dry, 1.0, 0.0, False, math.inf)
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


@pytest.mark.parametrize("compiled", [False, True])
def test_film_update_for_a_local_pressure_change_equals_the_direct_film(compiled):
    """The cycle's exact film update (``deformation_change``): H at the target nodes moves by -(1/pi) K dP, as the
    direct deformation of the changed pressures says; other nodes keep their film. Both uses of the cycle: a few
    changed nodes into every target (after the spike zones' Newton solve), every changed node into a few targets
    (the zones' films after the post-sweeps)."""
    from camcontact.ehl import _fas_kernels

    kernel = _kernels.compiled("deformation_change", _fas_kernels.PY) if compiled else _fas_kernels.deformation_change
    _, X, h, P, H = _state()
    n = X.size
    table = kernel_coefficients(h, n)
    direct = Deformation(n, h, "direct")
    rng = np.random.default_rng(3)
    for changed, targets in ((np.isin(np.arange(n), [40, 41, 42, 60]), np.ones(n, dtype=bool)),
                             (P > 0, np.isin(np.arange(n), [50, 51, 52, 53, 99]))):
        change = np.where(changed, 0.01 * rng.standard_normal(n), 0.0)
        updated = H.copy()
        kernel(updated, change, table, targets)
        expected = H - direct(change) / math.pi
        np.testing.assert_allclose(updated[targets], expected[targets], rtol=0, atol=1e-14)
        np.testing.assert_array_equal(updated[~targets], H[~targets])


def test_closed_gap_passes_no_pressure_flow():
    """Where the film is closed (H <= 0, e.g. on a coarse grid too coarse for a very thin film)
    xi = rho H^3/(eta lambda) is 0, not negative: the numpy operator, the Python kernel and the
    compiled kernel agree on a state with closed nodes, and the closed nodes carry only the wedge."""
    from camcontact.ehl.line_operator import LineGrid

    problem, X, h, P, H = _state()
    H = H - 1.3  # close the gap over the middle of the contact
    closed = H <= 0.0
    assert 5 < closed.sum() < X.size - 5
    grid = LineGrid(problem, X.size, "direct")
    np.testing.assert_array_equal(grid.xi(P, H)[closed], 0.0)
    assert np.all(grid.xi(P, H)[~closed] > 0.0)
    codes, params = problem.law_codes, problem.law_parameters
    python, compiled = np.empty(X.size), np.empty(X.size)
    full = np.ones(X.size)
    _kernels.PY["reynolds_residual"](P, H, full, PLAIN(X.size), h, problem.lam, *codes, params, 1.0, 0.0, python)
    _kernels.compiled("reynolds_residual")(P, H, full, PLAIN(X.size), h, problem.lam, *codes, params, 1.0, 0.0, compiled)
    np.testing.assert_allclose(python, grid.residual(P, H), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(compiled, python, rtol=1e-12, atol=1e-12)
    # a node whose three films are all closed: L_i is the wedge term alone
    i = int(np.flatnonzero(closed[:-2] & closed[1:-1] & closed[2:])[0]) + 1
    rho = problem.density_ratio(P)
    wedge = (1.5 * rho[i] * H[i] - 2.0 * rho[i - 1] * H[i - 1] + 0.5 * rho[i - 2] * H[i - 2]) / h
    assert python[i] == pytest.approx(-wedge, rel=1e-12)


@pytest.mark.parametrize("problem", [LineEHLProblem(M=20, L=10, alpha=1.7e-8, z=0.68),
                                     LineEHLProblem(M=20, L=0, viscosity="barus", density="incompressible")],
                         ids=["roelands-dowson-higginson", "isoviscous"])
def test_newton_jacobian_matches_finite_differences(problem):
    """The reference solver's analytic Jacobian dL/dP (deformation included) and dL/dH0 equal
    central differences of the operator, also with some closed-gap nodes."""
    from camcontact.ehl.line_operator import LineGrid
    from camcontact.ehl.line_reference import _jacobian

    grid = LineGrid(problem, 57, "direct")
    X = grid.X
    P = np.where(np.abs(X) < 1, np.sqrt(np.clip(1 - X * X, 0, None)), 0.0) * 0.8 + 0.01
    P[0] = P[-1] = 0.0
    K_over_pi = kernel_coefficients(grid.h, grid.n)[np.abs(np.arange(grid.n)[:, None] - np.arange(grid.n)[None, :])] / math.pi
    lowest = float(grid.film(P, 0.0).min())
    for H0, closed in ((0.1 - lowest, False), (-0.03 - lowest, True)):  # open everywhere / partly closed
        H = grid.film(P, H0)
        assert bool(np.any(H <= 0.0)) == closed
        J_P, J_H0 = _jacobian(grid, P, H, K_over_pi)
        step = 1e-7
        for j in (5, 20, 28, 40):
            up, down = P.copy(), P.copy()
            up[j] += step
            down[j] -= step
            numeric = (grid.residual(up, grid.film(up, H0)) - grid.residual(down, grid.film(down, H0))) / (2 * step)
            np.testing.assert_allclose(J_P[1:-1, j], numeric[1:-1], rtol=1e-5, atol=1e-6 * np.abs(numeric).max())
        numeric = (grid.residual(P, grid.film(P, H0 + 1e-7)) - grid.residual(P, grid.film(P, H0 - 1e-7))) / 2e-7
        np.testing.assert_allclose(J_H0[1:-1], numeric[1:-1], rtol=1e-5, atol=1e-6 * np.abs(numeric).max())


@pytest.mark.parametrize("M, L, n", [(20, 10, 15), (2.9, 18.5, 15), (200, 5, 29)])
def test_coarse_newton_kernel_equals_the_dense_reference_newton(M, L, n):
    """The compiled coarsest-grid solver and its twin reproduce the vectorised reference
    (same Fischer–Burmeister Newton, same iterations) for a FAS right-hand side."""
    from camcontact.ehl import _fas_kernels
    from camcontact.ehl.line_operator import LineGrid
    from camcontact.ehl.line_reference import newton_complementarity

    problem = LineEHLProblem(M=M, L=L)
    grid = LineGrid(problem, n, "direct")
    K = kernel_coefficients(grid.h, n)[np.abs(np.arange(n)[:, None] - np.arange(n)[None, :])] / math.pi
    P0 = np.where(np.abs(grid.X) < 1, np.sqrt(np.clip(1 - grid.X**2, 0, None)), 0.0)
    f = np.zeros(n)
    f[1:-1] = 1e-3 * np.random.default_rng(1).standard_normal(n - 2)
    P_ref, H0_ref, residuals, _, converged, _ = newton_complementarity(grid, P0, 0.3, f=f, f_load=0.01, K_over_pi=K,
                                                                      tolerance=1e-11, max_iterations=60)
    assert converged
    for function in (_fas_kernels.coarse_newton, _fas_kernels.compiled("coarse_newton")):
        P, H0, iterations, status = function(P0, 0.3, f, 0.01, grid.parabola, K, np.ones(n), PLAIN(n), np.zeros(n, dtype=bool),
                                             grid.h, problem.lam,
                                             *problem.law_codes, problem.law_parameters, True, 1.0, 0.0, 1e-11, 60)
        assert status == 0 and iterations == len(residuals)
        np.testing.assert_allclose(P, P_ref, atol=1e-12)
        assert H0 == pytest.approx(H0_ref, abs=1e-12)


def test_dense_solver_reports_a_singular_matrix_instead_of_raising():
    """The coarse Newton's elimination returns ok = False for a singular (or NaN) matrix; the
    kernel then reports status 2 and the cycle falls back to relaxation sweeps."""
    from camcontact.ehl._fas_kernels import solve_dense

    x, ok = solve_dense(np.array([[2.0, 1.0], [1.0, 1.0]]), np.array([3.0, 2.0]))
    assert ok and np.allclose(x, [1.0, 1.0])
    assert not solve_dense(np.array([[1.0, 2.0], [2.0, 4.0]]), np.array([1.0, 2.0]))[1]
    assert not solve_dense(np.array([[np.nan, 0.0], [0.0, 1.0]]), np.array([1.0, 2.0]))[1]


@pytest.mark.parametrize("kind", ["V", "F", "W"])
def test_compiled_cycle_equals_its_twin(kind):
    """One FAS cycle (schedule executor) compiled and as plain Python from the same state."""
    from camcontact.ehl.line_multigrid import LineHierarchy, MultigridSettings

    problem = LineEHLProblem(M=20, L=10, alpha=1.7e-8, z=0.68)
    settings = MultigridSettings(cycle=kind)
    results = []
    for compiled in (False, True):
        solver = LineHierarchy(problem, 4, settings, compiled=compiled)
        X = solver.levels[-1].X
        P = np.where(np.abs(X) < 1, np.sqrt(np.clip(1 - X * X, 0, None)), 0.0)
        results.append(solver.cycle(3, P, 0.2, np.zeros(X.size), 0.0) + (solver.work,))
    (P_py, H0_py, work_py), (P_nb, H0_nb, work_nb) = results
    np.testing.assert_allclose(P_nb, P_py, rtol=1e-11, atol=1e-12)
    assert H0_nb == pytest.approx(H0_py, abs=1e-12) and work_nb == pytest.approx(work_py)


def test_cycle_schedules_visit_the_coarse_grids_as_v_f_w_cycles():
    """Coarsest-grid solves of one cycle from level index 3 down to 0: a V-cycle solves once; a
    W-cycle visits each coarser level twice except the coarsest (2 x 2 x 1 = 4); an F-cycle is
    F(k) = F(k-1) + V(k-1) with F(1) = 1 (1 + 1 + 1 = 3)."""
    from camcontact.ehl._fas_kernels import DOWN, SOLVE, UP, cycle_schedule

    def solves(kind):
        schedule = cycle_schedule(3, kind, 0)
        assert (schedule[:, 0] == DOWN).sum() == (schedule[:, 0] == UP).sum()
        return int((schedule[:, 0] == SOLVE).sum())

    assert (solves("V"), solves("W"), solves("F")) == (1, 4, 3)


def test_spike_zone_solve_twin_and_detection():
    """The local Newton at the pressure spike (``relax_spikes``), compiled and as plain Python, inside one F-cycle
    from a perturbed spike (M 10, L 20, level 6): the same pressures. The detection marks the nodes around the
    fall of ln(eta-bar) just past the pressure maximum (one zone) and nothing at a monotonic outlet."""
    from camcontact.ehl import _fas_kernels
    from camcontact.ehl.line_multigrid import LineHierarchy, MultigridSettings, solve_multigrid

    problem = LineEHLProblem(M=10, L=20, alpha=2.2e-8, z=0.68)
    solution = solve_multigrid(problem, 6, tolerance=1e-9, strict=True)
    settings = MultigridSettings()
    hierarchy = LineHierarchy(problem, 6, settings, compiled=True)
    finest = hierarchy.levels[-1]
    marked = np.zeros(finest.n, dtype=np.bool_)
    assert _fas_kernels.find_spikes(solution.P, hierarchy.viscosity_code, hierarchy.params, settings.spike_drop,
                                    marked)
    peak = int(np.argmax(solution.P))
    nodes = np.flatnonzero(marked)  # six per falling edge; two neighbouring edges merge into one zone
    assert 6 <= nodes.size <= 8 and np.all(np.diff(nodes) == 1) and nodes[0] <= peak + 1 <= nodes[-1]
    monotonic = np.where(finest.X < 0.5, 1.0, np.maximum(1.0 - 4.0 * (finest.X - 0.5), 0.0))  # falls past X = 0.5
    assert not _fas_kernels.find_spikes(monotonic, hierarchy.viscosity_code, hierarchy.params, settings.spike_drop,
                                        marked)
    assert not marked.any()
    start = solution.P.copy()
    start[peak - 3:peak + 4] *= 1.0 + 0.02 * np.sin(np.arange(7))
    results = []
    for compiled in (False, True):
        solver = LineHierarchy(problem, 6, settings, compiled=compiled)
        results.append(solver.cycle(5, start.copy(), solution.H0, np.zeros(finest.n), 0.0) + (solver.work,))
    (P_py, H0_py, work_py), (P_nb, H0_nb, work_nb) = results
    np.testing.assert_allclose(P_nb, P_py, rtol=1e-10, atol=1e-12)
    assert H0_nb == pytest.approx(H0_py, abs=1e-12) and work_nb == pytest.approx(work_py)
