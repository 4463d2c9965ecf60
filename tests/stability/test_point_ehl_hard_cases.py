"""Hard corners of the point-contact multigrid solver (issue 19).

The steel ball of the issue: R 15 mm on a flat, 400 N, u_m 20 m/s, eta0 0.055 Pa s, alpha 25.7/GPa (Roelands),
E 206 GPa, nu 0.3: M 61, L 29. Its outlet spike made the coarse problems blow up (513^2) or the cycles stall
(257^2) in every attempt until the attempt with ``spike_mask`` kept the coarse grids out of the spike."""

import numpy as np
import pytest

from camcontact.ehl import _point_kernels
from camcontact.ehl.point_multigrid import ROBUST, PointMultigridSettings, solve_point_multigrid
from camcontact.ehl.point_problem import PointEHLProblem
from camcontact.models.film_point import HamrockDowson

E_REDUCED = 206e9 / (1 - 0.3**2)
BALL = dict(Rx=0.015, Ry=0.015, F=400.0, E_reduced=E_REDUCED, u_m=20.0, eta0=0.055, alpha=25.7e-9)


def test_ball_at_high_l_converges_with_its_film_near_hamrock_dowson():
    """257^2: converged (the record names the spike-mask attempt), H_c within 5 % of Hamrock–Dowson (measured
    +2.8 %; 513^2: +3.1 %, 73 cycles). H_min lies 17 % above the formula's, whose minimum-film fit is the
    least certain part of it at this L (outside its fitted G and U range)."""
    problem = PointEHLProblem.from_contact(**BALL)
    assert problem.M == pytest.approx(61.2, abs=0.1) and problem.L == pytest.approx(29.4, abs=0.1)
    solution = solve_point_multigrid(problem, 5, strict=True)
    assert solution.record.converged and "spike_mask=2.0" in solution.record.message
    h_scale = PointEHLProblem.scales(BALL["Rx"], BALL["F"], E_REDUCED)["h_scale"]
    formula = HamrockDowson().evaluate(**BALL)
    assert solution.H_c * h_scale == pytest.approx(formula["h_c"], rel=0.05)
    assert np.all(np.isfinite(solution.P)) and solution.H_min > 0


def test_spike_zone_marks_the_fall_of_the_viscosity_and_its_twin():
    """The zone covers nodes i-2..i+2 of rows j-1..j+1 around a fall of ln(eta) by more than the drop from i to
    i+1 (a step of P from 2 to 0 at Barus alpha-bar 17.8: a fall of 35.7), nothing elsewhere; compiled = Python."""
    problem = PointEHLProblem(M=20, L=10, viscosity="barus", density="incompressible")
    P = np.full((9, 12), 0.5)
    P[4, 7:] = 0.0
    P[4, 6] = 2.0
    masks = []
    for kernel in (_point_kernels.PY["spike_zone"], _point_kernels.compiled("spike_zone")):
        mask = np.ones(P.shape, dtype=bool)
        kernel(P, problem.law_codes[0], problem.law_parameters, 2.0, mask)
        masks.append(mask)
    np.testing.assert_array_equal(masks[0], masks[1])
    expected = np.zeros(P.shape, dtype=bool)
    expected[3:6, 4:9] = True
    np.testing.assert_array_equal(masks[0], expected)


def test_spike_mask_is_an_attempt_of_the_ladder_not_the_default():
    assert PointMultigridSettings().spike_mask == 0.0
    assert {"spike_mask": 2.0} in ROBUST
