"""The cycle monitor of the multigrid EHL solvers, on synthetic cycle sequences.

Each rule of :mod:`camcontact.ehl.cycle_monitor` separately: convergence (absolute and relative
change test, the load test with its factor and floor), the stagnation window (counted from the
freeze), the freeze of the cavitation set (alternating H_min with a moving boundary, once; not
with the line rules and tolerance None), the messages and their order.
"""

import attrs
import numpy as np
import pytest

from camcontact.ehl import line_multigrid, line_transient, point_multigrid
from camcontact.ehl.cycle_monitor import (CycleMonitor, MonitorRules, alternating, last_pressurised, stagnated,
                                          wet_count)

LINE = line_multigrid.MONITOR_RULES
TRANSIENT = line_transient.MONITOR_RULES
POINT = point_multigrid.MONITOR_RULES


def wet_up_to(last: int, n: int = 12) -> np.ndarray:
    """Pressures > 0 at nodes 1..last, 0 elsewhere (last pressurised node ``last``, ``last`` wet nodes)."""
    P = np.zeros(n)
    P[1:last + 1] = 1.0
    return P


class Freezer:
    def __init__(self):
        self.calls = []

    def __call__(self, P):
        self.calls.append(P.copy())


def run(rules, tolerance, cycles):
    """Feed ``cycles`` (P, watched, residual, load) to a monitor; (monitor, freezer, cycles run)."""
    freezer = Freezer()
    monitor = CycleMonitor(rules, tolerance, freezer)
    for count, (P, watched, residual, load) in enumerate(cycles, start=1):
        if monitor.after_cycle(P, watched, residual, load, float(count)):
            return monitor, freezer, count
    return monitor, freezer, len(monitor.residuals)


def steady(n, H_min=0.1, H0=-0.5, residual=1e-3, load=0.0):
    return [(wet_up_to(6), (H_min, H0), residual * 0.5**k, load) for k in range(n)]


def oscillating(n, boundary_moves=True, size=1e-3, factor=0.95, three=False):
    """H_min alternating by ``size`` from cycle to cycle, the boundary hopping between nodes 6 and 7
    (or fixed at 6), residuals falling slowly by ``factor`` per cycle."""
    out = []
    for k in range(n):
        P = wet_up_to(6 + (k % 2 if boundary_moves else 0))
        H_min = 0.1 + size * (k % 2)
        watched = (H_min, 0.3, -0.5) if three else (H_min, -0.5)
        out.append((P, watched, 1e-3 * factor**k, 0.0))
    return out


# ----------------------------------------------------------------------------- helpers
def test_stagnated_window():
    assert not stagnated([1e-3 * 0.6**k for k in range(12)], (10, 5))  # slow but steady
    flat = [6e-5, 5.7e-5, 5.9e-5, 6.4e-5, 6.5e-5, 6.3e-5, 6.3e-5, 6.3e-5, 6.4e-5, 6.5e-5]
    assert stagnated(flat, (10, 5))
    assert not stagnated(flat[:9], (10, 5))  # fewer cycles than the rule needs
    # the best of the last window is exactly half the best before: not stagnated (strict >)
    assert not stagnated([1.0] * 5 + [0.5] * 5, (10, 5))
    assert stagnated([1.0] * 5 + [0.5000001] * 5, (10, 5))


def test_alternating_needs_three_changes_of_alternating_sign_and_similar_size():
    assert not alternating([1e-3, -1e-3])
    assert alternating([1e-3, -1e-3, 1e-3])
    assert alternating([5.0, 1e-3, -1e-3, 2e-3])  # only the last three count
    assert not alternating([1e-3, 1e-3, -1e-3])  # same sign
    assert not alternating([1e-3, -1e-3, 2.1e-3])  # more than twice the smallest
    assert alternating([1e-3, -1e-3, 2e-3])


def test_boundary_measures():
    assert last_pressurised(wet_up_to(6)) == 6
    assert last_pressurised(np.zeros(5)) == -1
    assert wet_count(wet_up_to(6)) == 6
    P = np.zeros((4, 4))
    P[1, 1] = P[2, 2] = 0.5
    assert wet_count(P) == 2 and last_pressurised(P) == 10  # flat index in 2-D


def test_rules_are_validated():
    with pytest.raises(ValueError, match="cycles > window"):
        MonitorRules(stagnation=(5, 5))
    with pytest.raises(ValueError):
        MonitorRules(stagnation=(10, 5), boundary="outlet")
    with pytest.raises(ValueError):
        MonitorRules(stagnation=(10, 5), load_factor=0.0)


def test_the_solvers_rules():
    assert (LINE.stagnation, LINE.load_factor, LINE.load_floor, LINE.relative_to) == ((10, 5), 10.0, 1e-9, None)
    assert LINE.boundary == "last_pressurised" and LINE.freeze_needs_tolerance
    assert TRANSIENT == MonitorRules(stagnation=(10, 5), load_factor=10.0, load_floor=0.0, estimate_remaining=True)
    assert not LINE.estimate_remaining and not POINT.estimate_remaining
    assert line_transient.MASS_CONSERVING_RULES == attrs.evolve(TRANSIENT, estimate_remaining=False)
    assert line_multigrid.WARM_RULES == attrs.evolve(LINE, estimate_remaining=True)
    assert (POINT.stagnation, POINT.load_factor, POINT.load_floor, POINT.relative_to) == ((20, 10), 1.0, 0.0, 1)
    assert POINT.scale_floor == 0.01 and POINT.boundary == "wet_count" and not POINT.freeze_needs_tolerance


# ----------------------------------------------------------------------------- convergence
def test_converges_on_the_second_equal_cycle_not_the_first():
    monitor, freezer, count = run(LINE, 1e-6, steady(5))
    assert count == 2 and monitor.converged and monitor.message == ""
    assert monitor.residuals == [1e-3, 5e-4] and monitor.works == [1.0, 2.0]
    monitor, _, count = run(LINE, 1e-6, steady(1))
    assert count == 1 and not monitor.converged


def test_a_warm_start_that_one_cycle_does_not_change_converges_after_that_cycle():
    """With the start's watched values given, the first cycle's change is measured from them."""
    freezer = Freezer()
    monitor = CycleMonitor(LINE, 1e-6, freezer, start=(0.1, -0.5 + 5e-7))
    assert monitor.after_cycle(wet_up_to(6), (0.1, -0.5), 1e-3, 0.0, 1.0) and monitor.converged
    monitor = CycleMonitor(LINE, 1e-6, freezer, start=(0.1, -0.5 + 5e-6))
    assert not monitor.after_cycle(wet_up_to(6), (0.1, -0.5), 1e-3, 0.0, 1.0) and not monitor.converged


def test_change_of_any_watched_value_blocks_convergence():
    cycles = [(wet_up_to(6), (0.1, -0.5), 1e-3, 0.0), (wet_up_to(6), (0.1, -0.5 + 2e-6), 1e-3, 0.0),
              (wet_up_to(6), (0.1, -0.5 + 2e-6 + 5e-7), 1e-3, 0.0)]
    monitor, _, count = run(LINE, 1e-6, cycles)
    assert count == 3 and monitor.converged


@pytest.mark.parametrize("rules, load, converged", [
    (LINE, 9.9e-9, True),  # 10 max(1e-12, 1e-9) = 1e-8: the steady load floor
    (LINE, 1.1e-8, False),
    (TRANSIENT, 9.9e-9, False),  # no floor: 10 x 1e-12
    (TRANSIENT, 9.9e-12, True),
])
def test_line_load_test_with_and_without_the_floor(rules, load, converged):
    monitor, _, _ = run(rules, 1e-12, steady(2, load=load))
    assert monitor.converged is converged


@pytest.mark.parametrize("load, converged", [(9e-6, True), (2e-5, False)])
def test_point_load_test_is_the_tolerance_itself(load, converged):
    cycles = [(wet_up_to(6), (0.1, 0.3, -0.5), 1e-3, load)] * 2
    monitor, _, _ = run(POINT, 1e-5, cycles)
    assert monitor.converged is converged
    # the line rules would accept up to 10 x the tolerance
    assert run(LINE, 1e-5, [(wet_up_to(6), (0.1, -0.5), 1e-3, load)] * 2)[0].converged


@pytest.mark.parametrize("H_c, change, converged", [
    (0.5, 4e-6, True),  # limit 1e-5 x 0.5
    (0.5, 6e-6, False),
    (0.001, 9e-8, True),  # |H_c| below the floor 0.01: limit 1e-5 x 0.01
    (0.001, 2e-7, False),
    (-0.5, 4e-6, True),  # the size of H_c
])
def test_point_change_test_is_relative_to_the_central_film(H_c, change, converged):
    cycles = [(wet_up_to(6), (0.1, H_c, -0.5), 1e-3, 0.0), (wet_up_to(6), (0.1 + change, H_c, -0.5), 1e-3, 0.0)]
    monitor, _, _ = run(POINT, 1e-5, cycles)
    assert monitor.converged is converged


def test_no_tolerance_means_no_convergence_test():
    monitor, _, count = run(LINE, None, steady(8))
    assert count == 8 and not monitor.converged
    monitor.out_of_cycles(8)
    assert monitor.converged and monitor.message == "fixed number of cycles (8)"


def test_out_of_cycles_with_a_tolerance():
    monitor, _, _ = run(LINE, 1e-12, oscillating(3, boundary_moves=False))
    monitor.out_of_cycles(3)
    assert not monitor.converged and monitor.message == "no convergence to 1e-12 in 3 cycles"


# ----------------------------------------------------------------------------- stagnation
def test_line_stagnation_after_ten_cycles():
    flat = [(wet_up_to(6), (0.1 + 1e-3 * k, -0.5), 6e-5, 0.0) for k in range(40)]
    monitor, freezer, count = run(LINE, 1e-9, flat)
    assert count == 10 and not monitor.converged and not freezer.calls
    assert monitor.message == "stagnated: residual not halved in the last 5 cycles"


def test_point_stagnation_has_its_own_longer_window():
    flat = [(wet_up_to(6), (0.1 + 1e-3 * k, 0.3, -0.5), 6e-5, 0.0) for k in range(40)]
    monitor, _, count = run(POINT, 1e-9, flat)
    assert count == 20 and monitor.message == "stagnated: residual not halved in the last 10 cycles"


def test_falling_residuals_do_not_stagnate_and_no_tolerance_never_stagnates():
    falling = [(wet_up_to(6), (0.1 + 1e-3 * k, -0.5), 1e-3 * 0.8**k, 0.0) for k in range(40)]
    monitor, _, count = run(LINE, 1e-9, falling)
    assert count == 40 and monitor.message == ""
    flat = [(wet_up_to(6), (0.1 + 1e-3 * k, -0.5), 6e-5, 0.0) for k in range(40)]
    for rules in (LINE, POINT):
        cycles = flat if rules is LINE else [(P, (w[0], 0.3, w[1]), r, q) for P, w, r, q in flat]
        monitor, _, count = run(rules, None, cycles)
        assert count == 40 and monitor.message == ""


# ----------------------------------------------------------------------------- freeze
def test_line_freezes_once_when_h_min_alternates_and_the_boundary_moves():
    monitor, freezer, count = run(LINE, 1e-9, oscillating(9))
    assert count == 9 and not monitor.converged
    assert len(freezer.calls) == 1 and monitor.frozen_at == 4  # three changes after four cycles
    np.testing.assert_array_equal(freezer.calls[0], wet_up_to(7))  # the pressures of cycle 4
    assert monitor.message == "cavitation set frozen after cycle 4 (boundary oscillation)"


def test_no_freeze_with_a_fixed_boundary_or_without_alternation():
    monitor, freezer, _ = run(LINE, 1e-9, oscillating(9, boundary_moves=False))
    assert not freezer.calls and monitor.message == ""
    drifting = [(wet_up_to(6 + k % 2), (0.1 + 1e-3 * k, -0.5), 1e-3 * 0.95**k, 0.0) for k in range(9)]
    monitor, freezer, _ = run(LINE, 1e-9, drifting)
    assert not freezer.calls


def test_line_rules_never_freeze_without_a_tolerance_the_point_rules_do():
    monitor, freezer, count = run(LINE, None, oscillating(9))
    assert count == 9 and not freezer.calls and monitor.changes == []
    monitor, freezer, count = run(POINT, None, oscillating(9, three=True))
    assert count == 9 and len(freezer.calls) == 1 and monitor.frozen_at == 4
    monitor.out_of_cycles(9)
    assert monitor.converged
    assert monitor.message == ("cavitation set frozen after cycle 4 (boundary oscillation); "
                               "fixed number of cycles (9)")


def test_point_boundary_is_the_wet_count():
    """The same number of wet nodes with the pressurised zone shifted: no freeze for the point
    (its measure does not move), a freeze for the line (the last pressurised node moves)."""
    cycles = []
    for k in range(9):
        P = np.zeros(12)
        P[1 + k % 2:7 + k % 2] = 1.0  # six wet nodes, shifted by one every other cycle
        cycles.append((P, (0.1 + 1e-3 * (k % 2), 0.3, -0.5), 1e-3 * 0.95**k, 0.0))
    _, freezer, _ = run(POINT, 1e-9, cycles)
    assert not freezer.calls
    _, freezer, _ = run(LINE, 1e-9, [(P, (w[0], w[2]), r, q) for P, w, r, q in cycles])
    assert len(freezer.calls) == 1


def test_stagnation_counts_from_the_freeze_and_the_messages_join_in_order():
    """Frozen after cycle 4, then flat residuals: the stagnation window of the line rules (10 cycles)
    starts at the freeze, so the attempt stops at cycle 4 + 10 (at cycle 10 without the freeze)."""
    cycles = oscillating(4) + [(wet_up_to(6), (0.1 + 1e-3 * k, -0.5), 1e-3, 0.0) for k in range(30)]
    monitor, freezer, count = run(LINE, 1e-9, cycles)
    assert len(freezer.calls) == 1 and count == 14
    assert monitor.message == ("cavitation set frozen after cycle 4 (boundary oscillation); "
                               "stagnated: residual not halved in the last 5 cycles")


def contracting(rate, first=1e-3, n=12):
    """H_min approaching 0.1 geometrically: the change of cycle k is first * rate^k."""
    values = 0.1 - first * rate ** np.arange(n) / (1.0 - rate)
    return [(wet_up_to(6), (float(v), -0.5), 1e-3 * rate**k, 0.0) for k, v in enumerate(values)]


def test_the_remaining_change_estimate_stops_fast_cycles_earlier_never_slow_ones():
    """With ``estimate_remaining`` a sequence contracting by 0.2 per cycle stops when change * 0.2/0.8 < tolerance
    (and the change is below 3 x the tolerance): changes 1e-3, 2e-4, 4e-5, 8e-6, 1.6e-6, 3.2e-7 stop at 1.6e-6
    (remainder 4e-7 < 1e-6) instead of at 3.2e-7 (the plain test); a slow sequence (rate 0.8) stops where the plain
    test does, and a fast one (rate 0.01) only once its change is below FAST_REACH x the tolerance."""
    from camcontact.ehl.cycle_monitor import FAST_RATE, FAST_REACH

    assert (FAST_RATE, FAST_REACH) == (0.5, 3.0)
    estimating = attrs.evolve(LINE, estimate_remaining=True)
    plain, _, plain_count = run(LINE, 1e-6, contracting(0.2))
    fast, _, fast_count = run(estimating, 1e-6, contracting(0.2))
    assert plain.converged and fast.converged and (plain_count, fast_count) == (7, 6)
    assert fast.last_change == pytest.approx(1e-3 * 0.2**4)
    _, _, slow_plain = run(LINE, 1e-6, contracting(0.8, n=60))
    _, _, slow_estimating = run(estimating, 1e-6, contracting(0.8, n=60))
    assert slow_plain == slow_estimating
    # rate 0.01 from 2e-2: changes 2e-2, 2e-4, 2e-6 (< 3e-6: stops), 2e-8 (the plain test's stop)
    assert [run(rules, 1e-6, contracting(0.01, first=2e-2))[2] for rules in (LINE, estimating)] == [5, 4]
    # from 5e-2: the change 5e-6 is beyond 3 x 1e-6, so both stop at the change 5e-8
    assert [run(rules, 1e-6, contracting(0.01, first=5e-2))[2] for rules in (LINE, estimating)] == [5, 5]
