"""Shared check of the step-function unit tests (tests/unit/test_steps_*.py)."""

from __future__ import annotations


def assert_provides(function, out, subset=None) -> None:
    """The step returned its declared names, or ``subset`` of them (what the scene binds for a film model
    that gives fewer films)."""
    expected = set(function.step.provides) if subset is None else set(subset)
    assert set(out) == expected and expected <= set(function.step.provides), (sorted(out), sorted(expected))
