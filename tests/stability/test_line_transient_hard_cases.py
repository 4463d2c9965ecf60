"""Transient line EHL hard cases: pure squeeze, entrainment reversal, sudden load step.

They must stay finite and positive and converge at every step (or fail loudly, which these
cases must not). Contact: R = 20 mm, w = 200 kN/m, E' = 226 GPa, eta0 = 0.0358 Pa*s,
alpha = 2.2e-8 1/Pa (Roelands, Dowson-Higginson); M ~ 8, L ~ 12 at u_m = 2 m/s.
"""

import numpy as np
import pytest

from camcontact.ehl.line_multigrid import solve_multigrid
from camcontact.ehl.line_problem import LineEHLProblem
from camcontact.ehl.line_transient import TransientScaling, transient_cycle

R, W, E, ETA0, ALPHA = 0.02, 2e5, 2.26e11, 0.0358, 2.2e-8
U = 2.0
LUBRICANT = dict(E_reduced=E, eta0=ETA0, alpha=ALPHA)


def _time_scale(w=W, u=U):
    return TransientScaling.from_reference(R=R, w=w, u=u, **LUBRICANT).time_scale


def test_pure_squeeze_thins_the_film_and_keeps_it_positive():
    """Steady film at u_m = 2 m/s, then u_m = 0 under the same load: only the squeeze term carries
    the film. h_min falls at every step, ever more slowly (squeeze films decay like a power of t;
    the rigid closed form is checked in the unit tests), stays positive; the centre keeps a
    trapped pocket (h_c nearly constant: measured 606 -> 597 nm while h_min falls 518 -> 101 nm
    over T = 25 at level 7)."""
    n = 41
    times = np.arange(n) * 0.5 * _time_scale()
    u_m = np.where(np.arange(n) == 0, U, 0.0)
    result = transient_cycle(times, W, R, u_m, levels=6, domain=(-4.0, 4.0), **LUBRICANT)
    assert result.converged.all()
    assert np.all(np.isfinite(result.h_min)) and np.all(result.h_min > 0)
    drops = -np.diff(result.h_min)
    assert np.all(drops > 0)
    assert drops[-1] < 0.2 * drops[0]
    assert result.h_min[-1] < 0.4 * result.h_min[0]
    assert result.h_c[-1] == pytest.approx(result.h_c[0], rel=0.05)  # the trapped pocket


@pytest.mark.parametrize("scheme", ["bdf1", "bdf2"])
def test_entrainment_reversal_gives_finite_positive_films(scheme):
    """u_m falls linearly from +2 to -2 m/s through an instant with u_m = 0 exactly: every step
    converges, films stay finite and positive, the film at u_m = 0 (squeeze only) is continuous
    with its neighbours, and the reversed-flow solutions recover (h_min grows again)."""
    n = 41
    times = np.linspace(0.0, 40.0 * _time_scale(), n)
    u_m = U * np.linspace(1.0, -1.0, n)
    assert u_m[20] == 0.0
    result = transient_cycle(times, W, R, u_m, levels=6, scheme=scheme, **LUBRICANT)
    assert result.scaling.problem.domain == (-4.0, 4.0)
    assert result.converged.all()
    assert np.all(np.isfinite(result.h_min)) and np.all(result.h_min > 0) and np.all(result.h_c > 0)
    assert np.all(np.isfinite(result.p_max)) and np.all(result.p_max > 0)
    at_zero = result.h_min[20]
    assert 0.7 < at_zero / result.h_min[19] < 1.3 and 0.7 < at_zero / result.h_min[21] < 1.3
    assert result.h_min[-1] > 2.0 * result.h_min.min()


def test_sudden_load_step_is_stable_and_settles_on_the_new_steady_film():
    """Load doubled from one step to the next at u_m = 2 m/s: the march stays converged and positive
    and settles on the steady solution of the doubled load (the reference; within 1e-3)."""
    n = 46
    dt = 0.5 * _time_scale(2 * W)
    times = np.arange(n) * dt
    w = np.where(np.arange(n) < 5, W, 2 * W)
    result = transient_cycle(times, w, R, U, levels=6, **LUBRICANT)
    domain = result.scaling.problem.domain  # the automatic inlet (march_inlet) of the load before the step
    assert result.scaling.w == 2 * W and domain[0] < -4.0 and domain[1] == 1.5
    assert result.converged.all()
    assert np.all(result.h_min > 0) and np.all(np.isfinite(result.p_max))
    steady = solve_multigrid(LineEHLProblem.from_contact(R=R, w=2 * W, u_m=U, domain=domain, **LUBRICANT), 6,
                             tolerance=1e-8)
    h_scale = result.scaling.h_scale
    assert result.h_min[-1] / h_scale == pytest.approx(steady.H_min, rel=1e-3)
    assert result.h_c[-1] / h_scale == pytest.approx(steady.H_c, rel=1e-3)
    # the film lags the load: just after the step it is still thicker than the new steady film
    assert result.h_c[5] > 1.02 * result.h_c[-1]
