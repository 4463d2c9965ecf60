"""Transient line EHL with a starved inflow (``oil_layer``): the inlet meniscus placed by its mass balance.

Checks independent of the solver's own meniscus search: at constant conditions the march holds the steady
starved solution (:func:`camcontact.ehl.line_starved.solve_starved`, whose meniscus is a continuous unknown);
the central film carries what the layer brings (rho_c h_c = h_oil, a line contact has no side flow), so it does
not grow with speed, where a flooded film does (~u^0.7); a layer the flooded contact cannot pass leaves the
flooded march unchanged; the film through a reversal stays finite and flagged where not converged.
"""

import math
import warnings

import attrs
import numpy as np
import pytest

from camcontact.ehl.line_problem import LineEHLProblem
from camcontact.ehl.line_starved import solve_starved
from camcontact.ehl.line_transient import TransientScaling, TransientLineSolver, meniscus_balance, transient_cycle
from camcontact.errors import InputError

# R 20 mm, w 200 kN/m, E' 226 GPa, eta0 0.05 Pa s, alpha 20/GPa; flooded h_c ~ 0.37 um at 2 m/s
CONTACT = dict(E_reduced=2.26e11, eta0=0.05, alpha=2e-8)
R, W = 0.02, 2e5
LEVEL = 7
LAYER = 0.2e-6  # [m], about half the flooded film at 2 m/s


def _march(u_m, oil_layer, cavitation="mass_conserving", times=None, tolerance=1e-7, **extra):
    times = np.linspace(0.0, 0.002, np.size(u_m)) if times is None else times
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return transient_cycle(times, W, R, u_m, levels=LEVEL, tolerance=tolerance, cavitation=cavitation,
                               oil_layer=oil_layer, keep_fields=True, **CONTACT, **extra)


def _density_at_centre(result, k):
    return float(result.scaling.problem.density_ratio(np.interp(0.0, result.X, result.P[k])))


def test_oil_layer_is_validated_at_the_door():
    scaling = TransientScaling.from_reference(R=R, w=W, u=2.0, cavitation="reynolds", **CONTACT)
    with pytest.raises(InputError, match="mass_conserving"):
        TransientLineSolver(scaling, 5, oil_layer=1e-7)
    scaling = TransientScaling.from_reference(R=R, w=W, u=2.0, cavitation="mass_conserving", **CONTACT)
    for bad in (0.0, -1e-7, math.inf, math.nan):
        with pytest.raises(InputError, match="oil_layer"):
            TransientLineSolver(scaling, 5, oil_layer=bad)


def test_constant_conditions_hold_the_steady_starved_film():
    """The march from the starved start at constant load and speed keeps its film, which is the steady starved
    solution's (solved by solve_starved in the contact's own scaling, on the same level) to the meniscus's node
    resolution, and the central film carries the layer: rho_c h_c = h_oil."""
    u = np.full(11, 2.0)
    result = _march(u, LAYER)
    assert result.converged.all()
    np.testing.assert_allclose(result.h_c, result.h_c[0], rtol=2e-3)
    own = LineEHLProblem.from_contact(R=R, w=W, u_m=2.0, **CONTACT)
    b = math.sqrt(8.0 * W * R / (math.pi * CONTACT["E_reduced"]))
    scale = b * b / R
    steady = solve_starved(attrs.evolve(own, cavitation="mass_conserving", supply=LAYER / scale), LEVEL,
                           tolerance=1e-8)
    assert result.h_c[-1] == pytest.approx(steady.H_c * scale, rel=5e-3)
    for k in (0, u.size - 1):
        assert _density_at_centre(result, k) * result.h_c[k] == pytest.approx(LAYER, rel=5e-3)
    # upstream of the meniscus the layer is carried unpressurised: theta H = h_oil (to 1e-4: the state between
    # the two nodes around the meniscus weights theta and H separately)
    k = u.size - 1
    upstream = result.X < -1.5
    assert np.all(result.P[k][upstream] == 0.0)
    np.testing.assert_allclose(result.theta[k][upstream] * result.H[k][upstream] * result.scaling.h_scale, LAYER,
                               rtol=1e-4)


def test_a_starved_film_does_not_grow_with_speed():
    """The speed doubles halfway: the flooded film thickens by about 2^0.7, the starved one stays at what the
    layer brings (rho_c h_c = h_oil before and after, within the density change)."""
    u = np.where(np.arange(21) < 10, 2.0, 4.0)
    starved = _march(u, LAYER)
    flooded = _march(u, None)
    assert starved.converged.all() and flooded.converged.all()
    assert flooded.h_c[-1] / flooded.h_c[0] > 1.4
    for k in (0, 20):
        assert _density_at_centre(starved, k) * starved.h_c[k] == pytest.approx(LAYER, rel=1e-2)
    assert np.all(starved.h_c < flooded.h_c)


def test_a_layer_the_flooded_contact_cannot_pass_leaves_it_flooded():
    u = np.full(6, 2.0)
    flooded = _march(u, None)
    plenty = _march(u, 200e-6)  # fills the gap at the inlet end (68 um at -8 b; 50 um did not: a meniscus there)
    np.testing.assert_allclose(plenty.h_min, flooded.h_min, rtol=1e-9)


def test_through_a_reversal_the_starved_film_stays_finite_and_below_the_flooded_one():
    """u_m = 2 cos(2 pi t / 8 ms) over 4 ms (one reversal at 2 ms), BDF1: away from the reversal the starved
    film carries the layer; every film is finite and positive; steps that do not converge are flagged."""
    times = np.linspace(0.0, 0.004, 41)
    u = 2.0 * np.cos(2.0 * np.pi * times / 0.008)
    starved = _march(u, LAYER, times=times, scheme="bdf1")
    flooded = _march(u, None, times=times, scheme="bdf1")
    assert np.all(np.isfinite(starved.h_min)) and np.all(starved.h_min > 0.0)
    assert (~starved.converged).sum() <= 3
    fast = np.abs(u) > 1.0
    assert np.all(starved.h_c[fast] < flooded.h_c[fast])
    assert starved.h_min.min() <= flooded.h_min.min() * 1.001


def test_meniscus_balance_is_the_flux_after_the_meniscus_minus_what_the_layer_brings():
    """A hand-made state in the flow's frame: the balance is the discrete flux through the face after node j
    (second-order upwind content, the Poiseuille backflow of the rising pressure) minus the layer, and the
    pool's share when the meniscus moves."""
    problem = LineEHLProblem(M=20.0, L=10.0)
    X = np.linspace(-4.0, 1.5, 57)
    h = X[1] - X[0]
    H = 0.5 + 0.5 * X * X
    P = np.where(X > -2.0, 0.01 * (X + 2.0), 0.0)
    j = int(np.flatnonzero(P > 0.0)[0])
    q = problem.density_ratio(P) * H
    xi = problem.flow_coefficient(P, H)
    flux = 0.7 * 0.5 * (3.0 * q[j] - q[j - 1]) - 0.5 * (xi[j] + xi[j + 1]) * (P[j + 1] - P[j]) / h
    assert meniscus_balance(P, H, problem, 0.7, j, h, 0.3, 0.0, 1.0) == pytest.approx(flux - 0.7 * 0.3, rel=1e-12)
    assert (meniscus_balance(P, H, problem, 0.7, j, h, 0.3, 0.1, 2.0)
            == pytest.approx(flux - 0.7 * 0.3 - 0.05 * (H[j - 1] - 0.3), rel=1e-12))


def test_the_starved_march_conserves_the_lubricant_over_the_domain_step_by_step():
    """BDF1 steps while the speed rises 2 -> 4 m/s (tolerance 1e-9): the change of the lubricant content of the
    interior nodes equals what the layer brings in, |s| h_oil, minus what the cavitated exit film carries out
    through the last face (first-order upwind behind a partly filled node, no pressure), within 1e-3 of the inflow
    (measured 0.7-4.2e-4). The layer upstream of the meniscus is carried by the exact shift, not by the kernels'
    transport, and the meniscus closes the balance through its g = 0 (:func:`meniscus_balance`), so this is the
    check of the whole step, not of each node. On the domain [-4, 1.5] (the automatic inlet of this march, -8 b,
    at this level's twice coarser spacing: up to 1.03e-3 at one step)."""
    times = np.linspace(0.0, 0.002, 41)
    u = np.linspace(2.0, 4.0, 41)
    result = _march(u, LAYER, times=times, scheme="bdf1", tolerance=1e-9, domain=(-4.0, 1.5))
    assert result.converged.all()
    scaling, problem, X = result.scaling, result.scaling.problem, result.X
    h = X[1] - X[0]
    for k in range(1, u.size):
        s = u[k] / scaling.u
        dT = (times[k] - times[k - 1]) / scaling.time_scale
        q = result.theta[k] * problem.density_ratio(result.P[k]) * result.H[k]
        q_old = result.theta[k - 1] * problem.density_ratio(result.P[k - 1]) * result.H[k - 1]
        inflow = abs(s) * LAYER / scaling.h_scale
        assert result.P[k][-3:].max() == 0.0 and result.theta[k][-3] < 1.0  # a cavitated, unpressurised exit
        storage = h * np.sum((q - q_old)[1:-1]) / dT
        assert storage == pytest.approx(inflow - abs(s) * q[-2], abs=1e-3 * inflow)
