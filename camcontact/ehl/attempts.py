"""The ladder of solver attempts shared by the multigrid EHL solvers.

A solve runs with the given settings first and, if that attempt diverges (ConvergenceError) or ends
unconverged, with each more conservative variant in turn; the first converged solution is kept,
otherwise the one with the smallest final residual. The record's message says what was tried, so
every report shows what the solution cost; not converged: a ConvergenceWarning, or a
ConvergenceError with ``strict``.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable, Mapping
from typing import Any

import attrs

from ..errors import ConvergenceError, not_converged

__all__ = ["describe_settings", "run_ladder"]


def describe_settings(attempt: Any, given: Any) -> str:
    """'the given settings' or the fields in which an attempt's settings differ from the given ones."""
    changes = {name: getattr(attempt, name) for name in attrs.fields_dict(type(given))
               if getattr(attempt, name) != getattr(given, name)}
    return "the given settings" if not changes else "settings " + ", ".join(f"{k}={v}" for k, v in changes.items())


def run_ladder(settings: Any, robust: Iterable[Mapping[str, Any]], solve: Callable[[Any], Any], label: str, *,
               strict: bool, size: str) -> Any:
    """Run ``solve(attempt)`` over ``settings`` and its ``robust`` variants (see the module docstring).

    ``solve`` returns a solution with ``record`` (a ConvergenceRecord) and ``settings``, or raises
    ConvergenceError; ``label`` names the problem in messages (``"line EHL multigrid (M = 20, L = 10)"``),
    ``size`` the grid (``"3585 nodes"``).
    """
    ladder = [settings] + [c for c in (attrs.evolve(settings, **r) for r in robust) if c != settings]
    start = time.perf_counter()
    tried: list[str] = []
    kept = None
    last_record = None
    for attempt in ladder:
        try:
            solution = solve(attempt)
        except ConvergenceError as exc:
            last_record = exc.record
            tried.append(f"{describe_settings(attempt, settings)} failed ({str(exc).split(': ', 1)[-1]})")
            continue
        if solution.record.converged:
            kept = solution
            break
        tried.append(f"{describe_settings(attempt, settings)} did not converge ({solution.record.message})")
        if kept is None or solution.record.residuals[-1] < kept.record.residuals[-1]:
            kept = solution
    if kept is None:
        raise ConvergenceError(f"{label}: every attempt diverged: " + "; ".join(tried), last_record)
    if tried:
        note = "; ".join(tried) + ("" if kept.record.converged else "; kept the smallest residual")
        if kept.record.converged:
            note += f"; converged with {describe_settings(kept.settings, settings)}"
        if kept.record.message:
            note += f" ({kept.record.message})"
        kept = attrs.evolve(kept, record=attrs.evolve(kept.record, message=note,
                                                      wall_time=time.perf_counter() - start))
    if not kept.record.converged:
        not_converged(f"{label.rstrip(')')}, {size}): not converged: {kept.record.message}", kept.record,
                      strict=strict, stacklevel=3)
    return kept
