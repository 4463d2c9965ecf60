"""Per-cycle bookkeeping and stop rules of the multigrid EHL solvers (line steady, line transient, point).

After every cycle on the finest grid a solver hands its :class:`CycleMonitor` the residual, the
load error, the work so far, the pressures and the watched film values; the monitor records them
and decides:

* **converged** — the largest change of the watched values since the previous cycle below the
  tolerance (relative to max(|value|, ``scale_floor``) of one watched value, or absolute) and the
  load error below ``load_factor`` max(tolerance, ``load_floor``); with ``estimate_remaining`` also when
  fast cycles leave less than that to change (the last change times rate/(1 - rate), a geometric
  sequence's remainder; the a-posteriori estimate of the remaining change);
* **stagnated** — :func:`stagnated`: the residual has not halved in the last ``window`` cycles
  (counted since the freeze below);
* **freeze** — once, when H_min alternates from cycle to cycle (:func:`alternating`) while the
  cavitation boundary moves (its measure differs among the last three cycles): the solver holds
  the cavitated set at P = 0 and the cycles go on (the boundary hopping between nodes is a limit
  cycle the cycles do not leave by themselves; see the solvers' module docstrings).

What differs between the solvers is data, a :class:`MonitorRules`; the solvers' own rules are
:data:`camcontact.ehl.line_multigrid.MONITOR_RULES`,
:data:`camcontact.ehl.line_transient.MONITOR_RULES` and
:data:`camcontact.ehl.point_multigrid.MONITOR_RULES`. Tolerance None: no convergence or
stagnation test (a fixed number of cycles); the freeze then still runs where the rules allow it.

All quantities are dimensionless (the solvers' scalings); a cycle's residual is the h-scaled mean
absolute complementarity residual of the Reynolds equation on the finest grid.

References
----------
Venner, C.H. & Lubrecht, A.A. (2000) Multilevel Methods in Lubrication, Elsevier (the FAS solvers
whose cycles are monitored here).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import attrs
import numpy as np

__all__ = ["BOUNDARY_MEASURES", "CycleMonitor", "MonitorRules", "alternating", "last_pressurised", "stagnated",
           "wet_count"]


def stagnated(residuals: Sequence[float], rule: tuple[int, int]) -> bool:
    """True after ``rule[0]`` cycles when the last ``rule[1]`` did not halve the best residual before them."""
    cycles, window = rule
    return len(residuals) >= cycles and min(residuals[-window:]) > 0.5 * min(residuals[:-window])


def alternating(changes: Sequence[float]) -> bool:
    """True when the last three cycle-to-cycle changes alternate in sign with similar size (within 2x)."""
    if len(changes) < 3:
        return False
    a, b, c = changes[-3:]
    same_size = max(abs(a), abs(b), abs(c)) <= 2.0 * min(abs(a), abs(b), abs(c)) + 1e-15
    return a * b < 0 and b * c < 0 and same_size


def last_pressurised(P: np.ndarray) -> int:
    """Flat index of the last node with P > 0 (-1 if none): the outlet boundary of a line contact."""
    wet = np.flatnonzero(P > 0.0)
    return int(wet[-1]) if wet.size else -1


def wet_count(P: np.ndarray) -> int:
    """Number of nodes with P != 0 (the pressurised area of a point contact, in nodes)."""
    return int(np.count_nonzero(P))


#: name -> measure of the cavitation boundary, compared over the last three cycles
BOUNDARY_MEASURES: dict[str, Callable[[np.ndarray], int]] = {
    "last_pressurised": last_pressurised,
    "wet_count": wet_count,
}


def _check_stagnation(instance, attribute, value) -> None:
    cycles, window = value
    if not (isinstance(cycles, int) and isinstance(window, int) and cycles > window >= 1):
        raise ValueError(f"{attribute.name} = {value!r}: (cycles, window) with cycles > window >= 1")


@attrs.frozen
class MonitorRules:
    """The stop and freeze rules of one solver (see the module docstring).

    Attributes
    ----------
    stagnation : (int, int)
        (cycles, window) of :func:`stagnated`; cycles > window >= 1, so it cannot fire on the
        first cycle.
    load_factor, load_floor : float
        Converged only when |load error| < load_factor max(tolerance, load_floor).
    relative_to : int or None
        Index of the watched value whose size max(|value|, ``scale_floor``) scales the change
        test (None: the change is compared with the tolerance itself).
    scale_floor : float
        See ``relative_to``.
    boundary : str
        Key of :data:`BOUNDARY_MEASURES`: how the cavitation boundary is measured.
    freeze_needs_tolerance : bool
        True: the H_min changes are recorded (and the set frozen) only when a tolerance is given,
        so a fixed number of cycles never freezes; False: whenever there is a previous cycle.
    """

    stagnation: tuple[int, int] = attrs.field(converter=tuple, validator=_check_stagnation)
    load_factor: float = attrs.field(default=1.0, validator=attrs.validators.gt(0.0))
    load_floor: float = attrs.field(default=0.0, validator=attrs.validators.ge(0.0))
    relative_to: int | None = None
    scale_floor: float = attrs.field(default=0.01, validator=attrs.validators.gt(0.0))
    boundary: str = attrs.field(default="last_pressurised", validator=attrs.validators.in_(tuple(BOUNDARY_MEASURES)))
    freeze_needs_tolerance: bool = True
    #: also converged when the cycles contract fast: the last change times rate/(1 - rate), the remaining change
    #: of a geometric sequence with the rate = last change / the one before, is below the limit, with rate <= 0.5
    #: and the last change below 3 x the limit (:data:`FAST_RATE`, :data:`FAST_REACH`); never stricter than the
    #: change test
    estimate_remaining: bool = False


#: the largest contraction rate per cycle, and the largest multiple of the limit a last change may have, for which
#: :attr:`MonitorRules.estimate_remaining` extrapolates the remaining change
FAST_RATE, FAST_REACH = 0.5, 3.0


class CycleMonitor:
    """Records the cycles of one solver attempt and applies its :class:`MonitorRules`.

    Parameters
    ----------
    rules : MonitorRules
    tolerance : float or None
        Convergence tolerance (None: a fixed number of cycles, no convergence or stagnation test).
    freeze : callable
        ``freeze(P)`` holds the cavitated nodes of P (and their coarse-grid injections) at P = 0.
    start : tuple, optional
        The watched values of the state the cycles start from (a warm start): the first cycle's change is
        measured from it, so a start that one cycle no longer changes by more than the tolerance has converged
        after that cycle (without: the first cycle only sets the reference, at least two cycles run).

    After the attempt: :attr:`residuals`, :attr:`loads`, :attr:`works` (one entry per cycle),
    :attr:`converged` and :attr:`message` (notes joined by "; ").
    """

    def __init__(self, rules: MonitorRules, tolerance: float | None, freeze: Callable[[np.ndarray], None],
                 start: tuple | None = None):
        self.rules, self.tolerance, self.freeze = rules, tolerance, freeze
        self.residuals: list[float] = []
        self.loads: list[float] = []
        self.works: list[float] = []
        self.changes: list[float] = []  # of H_min from cycle to cycle
        self.boundaries: list[int] = []  # the boundary measure after each cycle
        self.frozen_at = 0  # cycles run when the set was frozen (0: not frozen); stagnation counts from here
        self.previous: tuple | None = start
        self.last_change: float | None = None  # the largest watched change of the previous cycle
        self.converged = False
        self.message = ""

    def record(self, residual: float, load: float, work: float) -> None:
        """Record the residual, load error and cumulative work of a cycle."""
        self.residuals.append(residual)
        self.loads.append(load)
        self.works.append(work)

    def decide(self, P: np.ndarray, watched: tuple) -> bool:
        """Apply the rules after the last :meth:`record`; True when the attempt stops here.

        ``watched``: the film values whose changes decide convergence, H_min first (its changes
        are the ones tested for alternation), e.g. (H_min, H0) or (H_min, H_c, H0).
        """
        rules, tolerance = self.rules, self.tolerance
        self.boundaries.append(BOUNDARY_MEASURES[rules.boundary](P))
        previous, self.previous = self.previous, watched
        if tolerance is not None and previous is not None and self._converged(watched, previous, tolerance):
            self.converged = True
            return True
        if tolerance is not None and stagnated(self.residuals[self.frozen_at:], rules.stagnation):
            self.note(f"stagnated: residual not halved in the last {rules.stagnation[1]} cycles")
            return True
        if previous is None or (tolerance is None and rules.freeze_needs_tolerance):
            return False
        self.changes.append(watched[0] - previous[0])
        if not self.frozen_at and alternating(self.changes) and len(set(self.boundaries[-3:])) > 1:
            # the cavitation boundary hops between nodes from cycle to cycle: hold the dry set and
            # let the cycles converge
            self.freeze(P)
            self.frozen_at = len(self.residuals)
            self.note(f"cavitation set frozen after cycle {self.frozen_at} (boundary oscillation)")
        return False

    def after_cycle(self, P: np.ndarray, watched: tuple, residual: float, load: float, work: float) -> bool:
        """:meth:`record` and :meth:`decide` in one call."""
        self.record(residual, load, work)
        return self.decide(P, watched)

    def out_of_cycles(self, cycles: int) -> None:
        """The attempt ran all its ``cycles``: converged by definition with tolerance None, else a note."""
        if self.tolerance is None:
            self.converged = True
            self.note(f"fixed number of cycles ({cycles})")
        else:
            self.note(f"no convergence to {self.tolerance:g} in {cycles} cycles")

    def note(self, text: str) -> None:
        """Append ``text`` to the message."""
        self.message = (self.message + "; " if self.message else "") + text

    def _converged(self, watched: tuple, previous: tuple, tolerance: float) -> bool:
        rules = self.rules
        change = max(abs(now - before) for now, before in zip(watched, previous))
        before, self.last_change = self.last_change, change
        limit = tolerance if rules.relative_to is None else tolerance * max(abs(watched[rules.relative_to]),
                                                                             rules.scale_floor)
        settled = change < limit
        if not settled and rules.estimate_remaining and before:
            rate = change / before
            settled = rate <= FAST_RATE and change < FAST_REACH * limit and change * rate / (1.0 - rate) < limit
        return settled and abs(self.loads[-1]) < max(tolerance, rules.load_floor) * rules.load_factor
