"""Mass-conserving (JFO) cavitation of the line-contact EHL solver: the film fraction theta.

Checks: the classical operator is the theta = 1 case (the default solves are unchanged, which the
golden reports and the other EHL tests hold bitwise); the kernels' theta update conserves the
lubricant through a cavitated region exactly (an independent count of the content, not the
solver's residual); a flooded steady contact gives the film of the Reynolds exit condition (JFO
rupture is the Reynolds condition in a steady line contact: Jakobsson & Floberg 1957, Elrod
1981) and carries the same mass flux through its cavitated outlet as through the contact.
"""

import math

import numpy as np

from tests.kernel_inputs import PLAIN
import pytest

from camcontact.ehl import _kernels
from camcontact.ehl.line_multigrid import solve_multigrid
from camcontact.errors import InputError
from camcontact.ehl.line_problem import LineEHLProblem


def _relax(kernel, P, H, theta, h, problem, sweeps=1, supply=math.inf, s=1.0):
    K = np.array([_kernels.kernel_value(float(d), h) for d in range(16)])
    dry = np.zeros(P.size, dtype=np.bool_)
    for _ in range(sweeps):
        kernel(P, H, theta, PLAIN(P.size), np.zeros(P.size), h, problem.lam, *problem.law_codes, problem.law_parameters, K, 0.7, 0.3,
               4.0, 0, 1, P.size - 2, dry, s, 0.0, True, supply)


def test_cavitation_model_is_validated_at_the_door():
    with pytest.raises(InputError, match="cavitation"):
        LineEHLProblem(M=20, L=10, cavitation="elrod")


def test_a_starved_layer_crosses_an_unpressurised_gap_with_its_content_unchanged():
    """With no pressure anywhere, L_i = 0 is pure transport: the content theta H must stay the inlet layer's
    at every node (mass conservation, counted independently of the operator) whatever the gap, in one
    Gauss–Seidel sweep along the flow; theta = min(1, supply/H) at the inlet. (The downstream boundary
    node has no equation and keeps its theta.)"""
    n = 101
    X = np.linspace(-4.0, 1.5, n)
    h = X[1] - X[0]
    H = 0.3 + 0.5 * X**2
    problem = LineEHLProblem(M=20, L=10)
    supply = 0.2  # below the smallest gap: partly filled everywhere
    for kernel in (_kernels.PY["relax_hybrid"], _kernels.compiled("relax_hybrid")):
        P, theta = np.zeros(n), np.ones(n)
        _relax(kernel, P, H.copy(), theta, h, problem, supply=supply)
        np.testing.assert_array_equal(P, 0.0)
        np.testing.assert_allclose((theta * H)[:-1], supply, rtol=1e-13)
        assert np.all(theta[:-1] < 1.0)


def test_theta_twins_give_the_same_sweep_and_residual():
    """Compiled and plain-Python kernels agree with film fractions below 1 (an outlet-like cavitated tail)."""
    problem = LineEHLProblem(M=20, L=10)
    start = solve_multigrid(problem, 4)  # a converged classical state (113 nodes), its outlet then cavitates
    n, X, P, H = start.X.size, start.X, start.P, start.H
    h = X[1] - X[0]
    results = []
    for name in ("PY", "compiled"):
        relax = _kernels.PY["relax_hybrid"] if name == "PY" else _kernels.compiled("relax_hybrid")
        residual = _kernels.PY["reynolds_residual"] if name == "PY" else _kernels.compiled("reynolds_residual")
        P_, H_, theta = P.copy(), H.copy(), np.ones(n)
        _relax(relax, P_, H_, theta, h, problem, sweeps=3)
        out = np.empty(n)
        residual(P_, H_, theta, PLAIN(P_.size), h, problem.lam, *problem.law_codes, problem.law_parameters, 1.0, 0.0, out)
        results.append((P_, theta, out))
    assert (results[0][1] < 1.0).sum() > 5  # the cavitated outlet has partly filled nodes
    for a, b in zip(results[0], results[1]):
        np.testing.assert_allclose(b, a, rtol=1e-12, atol=1e-13)


@pytest.fixture(scope="module")
def flooded_pair():
    problem = dict(M=20.0, L=10.0)
    reynolds = solve_multigrid(LineEHLProblem(**problem), 7, tolerance=1e-9, strict=True)
    conserving = solve_multigrid(LineEHLProblem(**problem, cavitation="mass_conserving"), 7, tolerance=1e-9,
                                 strict=True)
    return reynolds, conserving


def test_flooded_steady_contact_has_the_film_of_the_reynolds_condition(flooded_pair):
    """JFO rupture is the Reynolds (zero pressure and gradient) exit condition in a steady line contact:
    the two models give the same film and pressure (measured 1e-9 on level 7, M = 20, L = 10)."""
    reynolds, conserving = flooded_pair
    assert conserving.H_min == pytest.approx(reynolds.H_min, rel=1e-6)
    assert conserving.H_c == pytest.approx(reynolds.H_c, rel=1e-6)
    np.testing.assert_allclose(conserving.P, reynolds.P, atol=1e-6)
    assert reynolds.theta is None and np.all(reynolds.film_fraction == 1.0)


def test_the_cavitated_outlet_carries_the_contact_s_mass_flux(flooded_pair):
    """Mass conservation to 1e-6 through the contact and its cavitated outlet: the discrete flux
    F = q - xi dP/dX is the same at every face (the Reynolds model, which fills the outlet, creates
    lubricant there: its flux grows 4x downstream), and in the outlet, where P = 0, the content theta rho H
    alone carries it (so theta falls as the gap opens; from the second dry node on, where the upwind flux no
    longer reaches back into the pressurised film)."""
    reynolds, conserving = flooded_pair
    F = conserving.mass_flux
    assert np.ptp(F) / F.mean() < 1e-6
    outlet = (conserving.X > conserving.X[np.flatnonzero(conserving.P > 0)[-1]]) & (np.arange(F.size + 1) < F.size)
    assert outlet.sum() > 50
    theta = conserving.film_fraction
    tail = np.flatnonzero(outlet)[1:]
    np.testing.assert_allclose((theta * conserving.H)[tail], F.mean(), rtol=1e-6)
    assert np.all(np.diff(theta[outlet]) < 0) and theta[outlet].min() < 0.3
    assert reynolds.mass_flux[-1] > 4.0 * reynolds.mass_flux[0]


# ----------------------------------------------------------------------------- transient: reversal
def _reciprocating(cavitation, tolerance=1e-9, steps=41):
    """A line contact whose entrainment reverses (u_m = 2 cos(2 pi t / 8 ms) m/s over 4 ms; R 20 mm,
    w 200 kN/m, E' 226 GPa, eta0 0.05 Pa s, alpha 20/GPa), BDF1, level 6."""
    from camcontact.ehl.line_transient import transient_cycle

    times = np.linspace(0.0, 0.004, steps)
    u_m = 2.0 * np.cos(2.0 * np.pi * times / 0.008)
    return u_m, transient_cycle(times, 2e5, 0.02, u_m, E_reduced=2.26e11, eta0=0.05, alpha=2e-8, levels=6,
                                scheme="bdf1", tolerance=tolerance, cavitation=cavitation, keep_fields=True)


@pytest.fixture(scope="module")
def reversal():
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return _reciprocating("reynolds"), _reciprocating("mass_conserving")


def test_the_transient_march_conserves_the_lubricant_step_by_step(reversal):
    """Discrete mass balance of each converged BDF1 step, counted on the returned fields: the change of the
    content theta rho H over the interior nodes equals the flux in minus the flux out through the end faces
    (limited upwind wedge flux times s minus the Poiseuille flux; on the grid mirrored for u_m < 0, as
    solved). The balance holds as well as the step's equations are converged: measured within 3.8e-5 of the
    inflow at tolerance 1e-9 (the inflow is small near the reversal; at tolerance 1e-8 the steps stop a cycle
    earlier since the multigrid solves the pressure spike together (``spike_drop``), and the worst step is
    5.2e-4 off). The four steps right after the reversal
    stagnate (the reformation front of the returning film) and are flagged, not checked."""
    _, (u_m, result) = reversal
    scaling, problem, X = result.scaling, result.scaling.problem, result.X
    h = X[1] - X[0]
    checked = 0
    for k in range(1, u_m.size):
        if not (result.converged[k] and result.converged[k - 1]):
            continue
        s = u_m[k] / scaling.u
        dT = (result.times[k] - result.times[k - 1]) / scaling.time_scale
        order = slice(None, None, -1) if s < 0 else slice(None)
        P, H, theta = result.P[k][order], result.H[k][order], result.theta[k][order]
        q = theta * problem.density_ratio(P) * H
        q_old = (result.theta[k - 1] * problem.density_ratio(result.P[k - 1]) * result.H[k - 1])[order]
        xi = problem.density_ratio(P) * np.maximum(H, 0.0) ** 3 * np.exp(-problem.log_viscosity(P)) / problem.lam
        full = (P > 0.0) | (theta >= 1.0)
        phi = np.where(full[:-2], 0.5, 0.0)
        G = np.empty(q.size - 1)
        G[1:] = q[1:-1] + phi * (q[1:-1] - q[:-2])
        G[0] = q[0] + phi[0] * (q[1] - q[0])
        F = abs(s) * G - 0.5 * (xi[:-1] + xi[1:]) * np.diff(P) / h
        storage = np.sum(h * (q - q_old)[1:-1]) / dT
        assert storage == pytest.approx(F[0] - F[-1], abs=5e-4 * abs(F[0]))
        checked += 1
    assert checked >= 30 and (~result.converged).sum() <= 5


def test_after_a_reversal_the_contact_meets_the_film_it_left_behind(reversal):
    """Until the entrainment reverses, both models give the same film (what leaves the contact does not come
    back); after it, the mass-conserving contact is fed by its own partly filled exit film and runs up to
    several per cent thinner than with the Reynolds model's flooded exit, until fresh lubricant arrives
    from the far reservoir (measured: -6.8 % at u_m = -0.77 m/s, within 0.1 % again at -2 m/s)."""
    (u_m, reynolds), (_, conserving) = reversal
    forward = u_m > 0.0
    assert reynolds.converged.all()
    np.testing.assert_allclose(conserving.h_min[forward], reynolds.h_min[forward], rtol=1e-5)
    ratio = conserving.h_min / reynolds.h_min
    after = (u_m < -0.4) & (u_m > -1.0)
    assert ratio[after].min() < 0.95
    assert abs(ratio[-1] - 1.0) < 2e-3
    assert conserving.theta[forward].min() < 0.2 and np.all(reynolds.theta == 1.0)
