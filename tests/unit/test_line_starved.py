"""Steady starved line contacts (camcontact.ehl.line_starved): the meniscus where the supply fills the gap.

Checks independent of the solver's own stop test: mass conservation counted on the returned fields (the
discrete flux through the pressurised film equals the supply; upstream of the meniscus the unpressurised
layer carries exactly the supply, theta H = H_oil); the central film follows from the flux, rho_c H_c = H_oil
up to the small Poiseuille flow at X = 0, so that below the flooded flux the film falls in proportion to the
supply (a line contact has no side flow); a supply above the flooded flux leaves the flooded solution.
"""

import math

import numpy as np
import pytest

from camcontact.ehl.line_multigrid import solve_multigrid
from camcontact.ehl.line_problem import LineEHLProblem
from camcontact.ehl.line_starved import solve_starved, wet_flux
from camcontact.errors import InputError

LEVEL = 7
CASE = dict(M=20.0, L=10.0)


@pytest.fixture(scope="module")
def flooded():
    return solve_multigrid(LineEHLProblem(**CASE), LEVEL, strict=True)


def _starved(fraction, flooded):
    supply = fraction * wet_flux(flooded)
    return supply, solve_starved(LineEHLProblem(**CASE, cavitation="mass_conserving", supply=supply), LEVEL,
                                 strict=True)


def test_starved_inputs_are_validated_at_the_door():
    with pytest.raises(InputError, match="mass_conserving"):
        LineEHLProblem(**CASE, supply=0.05)
    for bad in (0.0, -1.0, math.inf, math.nan):
        with pytest.raises(InputError, match="supply"):
            LineEHLProblem(**CASE, cavitation="mass_conserving", supply=bad)
    with pytest.raises(InputError, match="solve_starved"):
        solve_multigrid(LineEHLProblem(**CASE, cavitation="mass_conserving", supply=0.05), LEVEL)
    with pytest.raises(InputError, match="no supply"):
        solve_starved(LineEHLProblem(**CASE), LEVEL)


def test_a_supply_above_the_flooded_flux_leaves_the_contact_flooded(flooded):
    supply, starved = _starved(1.2, flooded)
    assert "flooded" in starved.record.message and starved.inlet_meniscus is None
    np.testing.assert_array_equal(starved.H, flooded.H)
    assert starved.film_fraction[0] == 1.0


@pytest.mark.parametrize("fraction", [0.8, 0.4])
def test_the_starved_film_carries_exactly_the_supply(fraction, flooded):
    supply, starved = _starved(fraction, flooded)
    X_m = starved.inlet_meniscus
    assert -1.6 < X_m < -1.0 and starved.X[0] >= LineEHLProblem(**CASE).domain[0]
    inlet = starved.X < X_m
    # upstream of the meniscus: no pressure, the layer's content unchanged
    assert np.all(starved.P[inlet] == 0.0) and np.all(starved.film_fraction[inlet] < 1.0)
    np.testing.assert_allclose((starved.film_fraction * starved.H)[inlet], supply, rtol=1e-12)
    # through the pressurised film and the cavitated exit: the supply (the meniscus search stops within 10 x the
    # tolerance 1e-7; the film itself is converged to about that: measured within 6e-6)
    F = starved.mass_flux
    downstream = np.flatnonzero(starved.X[:-1] > X_m + 2 * (starved.X[1] - starved.X[0]))
    np.testing.assert_allclose(F[downstream], supply, rtol=1e-5)
    # the central film from the flux at X = 0: rho_c H_c = H_oil up to the Poiseuille flow there
    rho_c = float(starved.problem.density_ratio(np.interp(0.0, starved.X, starved.P)))
    assert rho_c * starved.H_c == pytest.approx(supply, rel=2e-3)
    # no side flow: the film falls in proportion to the supply
    assert starved.H_c / flooded.H_c == pytest.approx(fraction, rel=3e-3)
    assert starved.H_min < flooded.H_min


def test_less_supply_moves_the_meniscus_towards_the_contact(flooded):
    menisci = [_starved(fraction, flooded)[1].inlet_meniscus for fraction in (0.9, 0.6, 0.3)]
    assert menisci[0] < menisci[1] < menisci[2] < -1.0


def test_the_meniscus_bracket_follows_the_secant_of_its_trials():
    """find_meniscus on the flux curve a thermal starved solve measured (steel rollers, S = 0, a layer of 0.2 of the
    flooded film, level 6: F/supply - 1 at eleven menisci from X = -3.1 to -1.06, interpolated monotonically in
    ln(-1 - X)): the bracket's secant steps reach the root in 8 calls; the fixed steps of 0.3 before 2026-11-29 took
    14 (measured in the solver: 16 thermal solves then, 10 now)."""
    from scipy.interpolate import PchipInterpolator

    from camcontact.ehl.line_starved import find_meniscus

    measured = [(-3.1, 5.08323), (-2.47, 4.78062), (-2.029, 4.31445), (-1.7203, 3.70377), (-1.5042, 3.01087),
                (-1.3529, 2.30922), (-1.2471, 1.65603), (-1.1729, 1.08364), (-1.1211, 0.6035), (-1.0847, 0.21352),
                (-1.0593, -0.09551)]
    ln_d = np.log([-1.0 - X for X, _ in measured])[::-1]
    curve = PchipInterpolator(ln_d, [g for _, g in measured][::-1], extrapolate=True)
    calls = []

    def flux_error(X_m):
        calls.append(X_m)
        return float(curve(math.log(-1.0 - X_m)))

    X_m, error = find_meniscus(flux_error, -3.1, 5.08323, target=1e-4, supply=1.0, record=None, caller="test")
    assert abs(error) <= 1e-4 and X_m == pytest.approx(-1.0669, abs=2e-4)
    assert len(calls) <= 8  # measured 8; fixed steps: 14
