"""Point-contact EHL multigrid solver vs published film formulas (257 x 257 grid, level 5).

Sources and tolerances:

* Nijenbanning, Venner & Moes (1994) Wear 176:217-229, central film fitted to numerical solutions
  (:func:`camcontact.models.film_point.nijenbanning_film`): the oracle for H_c. Its solutions were
  computed for an incompressible lubricant with the Roelands law, so these tests use
  ``density="incompressible"`` (with Dowson–Higginson compressibility the computed central film is
  about 7-10 % lower at M = 20, L = 10 — the known effect of compressibility on h_c).
  Tolerance 5 % for circular and wide (D <= 1) contacts. Measured (level 5): M, L = 10, 5: -2.1 %;
  10, 10: -1.6 %; 20, 5: +0.3 %; 20, 10: +0.5 %; 50, 5: +0.6 %; 50, 10: +0.9 %; 100, 5: -0.5 %;
  100, 10: -0.1 %; M = 20, L = 10 with D = 0.25: +0.5 %, D = 0.5: -1.0 %.
* Elongated along the flow (D = Rx/Ry > 1; Hamrock's k < 1) both formulas extrapolate (Hamrock &
  Dowson fitted k = 1..8, i.e. D <= 1) and they disagree with each other by 13 % at D = 2 and 35 %
  at D = 4. Measured: D = 2: +5.7 % vs NVM, -4.6 % vs HD; D = 4: +14.8 % vs NVM, -14.9 % vs HD.
  Asserted: within 7 % of NVM at D = 2, and between the two formulas at D = 4.
* Hamrock & Dowson (1977) J. Lubr. Technol. 99(2):264 minimum film, converted to Moes groups
  (H = (h/Rx)(2U)^-1/2 with U = (2U)/2, W = M (2U)^(3/4), G = L (2U)^(-1/4); the formula is not a
  function of M and L alone, the residual dependence on 2U is (2U)^0.003: 2U = 1e-11 is used, 1e-12
  changes it by 0.6 %). HD's power law misses the M-dependence of H_min that the Moes-type maps show
  (H_c/H_min grows with M: Lubricants 6(3):80, 2018); measured deviations -16 % (M = 100, L = 5)
  .. +11 % (M = 10, L = 10). Tolerance 20 %.
"""

import warnings

import numpy as np
import pytest

from camcontact.ehl.point_multigrid import solve_point_multigrid
from camcontact.ehl.point_problem import PointEHLProblem
from camcontact.errors import ConvergenceWarning
from camcontact.models.film_point import nijenbanning_film

LEVEL = 5  # 257 x 257


def hamrock_dowson_moes(M, L, D=1.0, speed_group=1e-11):
    """Hamrock–Dowson (1977) (H_c, H_min) in Moes's film scaling at the given 2U (see module docstring)."""
    U, W, G = speed_group / 2, M * speed_group**0.75, L * speed_group**-0.25
    k_min, k_c = 1.03 * (1 / D) ** 0.64, 1.0339 * (1 / D) ** 0.636
    h_min = 3.63 * U**0.68 * G**0.49 * W**-0.073 * (1 - np.exp(-0.68 * k_min))
    h_c = 2.69 * U**0.67 * G**0.53 * W**-0.067 * (1 - 0.61 * np.exp(-0.73 * k_c))
    return h_c / np.sqrt(speed_group), h_min / np.sqrt(speed_group)


def _solve(M, L, D=1.0, level=LEVEL, **kwargs):
    problem = PointEHLProblem(M=M, L=L, D=D, **kwargs)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ConvergenceWarning)
        solution = solve_point_multigrid(problem, level)
    assert solution.record.converged
    assert np.all(np.isfinite(solution.H)) and solution.H_min > 0
    return solution


@pytest.mark.parametrize("M", [10, 20, 50, 100])
@pytest.mark.parametrize("L", [5, 10])
def test_circular_central_film_vs_nijenbanning(M, L):
    """H_c within 5 % of Nijenbanning et al. (1994); H_min within 20 % of Hamrock & Dowson (1977)."""
    solution = _solve(M, L, density="incompressible")
    hc, hmin = solution.moes_film()
    assert hc == pytest.approx(nijenbanning_film(M, L, 1.0), rel=0.05)
    assert hmin == pytest.approx(hamrock_dowson_moes(M, L)[1], rel=0.20)
    assert 1.2 < hc / hmin < 2.5


def test_heavy_load_central_film_vs_nijenbanning():
    """M = 1000, L = 10, incompressible: 257^2 and 513^2 converge (measured with line relaxation: 6-7 and
    6 W-cycles, about 5 s and 20 s; the point-wise sweep needed 53 and 22), the pressure near-Hertzian
    (P_max = 1.006). H_c (Moes) = 3.56 (257^2) and 3.84 (513^2) against Nijenbanning's 4.04: 12 % and
    5 % low — the heavy-load film converges with the grid from below (2.52 on 129^2; the steps 1.04 and
    0.28 shrink about 4x per level, second order, which puts the grid limit near 3.94, 2.5 % below the
    formula). Asserted: 257^2 within 15 %, 513^2 within 6 %, both below the formula, 513^2 above 257^2."""
    formula = float(nijenbanning_film(1000, 10, 1.0))
    films = []
    for level in (5, 6):
        solution = _solve(1000, 10, level=level, density="incompressible")
        hc, hmin = solution.moes_film()
        assert solution.P_max == pytest.approx(1.0, abs=0.02) and 0 < hmin < hc
        films.append(hc)
    assert films[0] == pytest.approx(formula, rel=0.15) and films[1] == pytest.approx(formula, rel=0.06)
    assert films[0] < films[1] < formula


@pytest.mark.parametrize("D", [0.25, 0.5])
def test_wide_elliptical_central_film_vs_nijenbanning(D):
    hc, _ = _solve(20, 10, D, density="incompressible").moes_film()
    assert hc == pytest.approx(nijenbanning_film(20, 10, D), rel=0.05)


def test_elongated_elliptical_contacts_where_the_formulas_extrapolate():
    """D = 2: within 7 % of NVM; D = 4: between NVM (2.66) and HD (3.59), the formulas 35 % apart."""
    hc2, _ = _solve(20, 10, 2.0, density="incompressible").moes_film()
    assert hc2 == pytest.approx(nijenbanning_film(20, 10, 2.0), rel=0.07)
    hc4, _ = _solve(20, 10, 4.0, density="incompressible").moes_film()
    assert nijenbanning_film(20, 10, 4.0) < hc4 < hamrock_dowson_moes(20, 10, 4.0)[0]


def test_grid_convergence_of_the_minimum_film():
    """M = 20, L = 10 (Roelands, Dowson–Higginson): H_min changes by less than 1 % from 129^2 to 257^2
    (measured 0.4 %; 257^2 to 513^2: see benchmarks/point_ehl_speed.py)."""
    coarse = _solve(20, 10, level=4)
    fine = _solve(20, 10, level=5)
    assert abs(fine.H_min / coarse.H_min - 1) < 0.01
    assert abs(fine.H_c / coarse.H_c - 1) < 0.01
