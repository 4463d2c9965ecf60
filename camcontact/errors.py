"""Exceptions and warnings raised by camcontact.

Every error that is caused by user input derives from :class:`InputError`
(a :class:`ValueError`), so callers can catch bad input in one place. The
message always names the component (class), the field, the offending value
and what is allowed.
"""

from __future__ import annotations

import warnings

__all__ = [
    "CamcontactWarning",
    "CaseTimeout",
    "ConvergenceError",
    "ConvergenceWarning",
    "InputError",
    "ModelOutputError",
    "PluginError",
    "PluginLoadError",
    "PluginLoadWarning",
    "PluginNameClashWarning",
    "StepFailureWarning",
    "SweepInterruptedWarning",
    "UnknownModelError",
    "ValidityWarning",
    "not_converged",
]


class InputError(ValueError):
    """Bad user input: wrong unit, bare number for a dimensional field, out-of-range value, ..."""


class UnknownModelError(InputError, LookupError):
    """A model name that no registered plugin of the family provides."""


class CaseTimeout(Exception):
    """A sweep case ran longer than the sweep's ``timeout`` [s]: it is recorded as failed
    (``"CaseTimeout: case exceeded 5 s"``) and the sweep goes on."""


class ConvergenceError(RuntimeError):
    """A solver did not converge; ``record`` holds its convergence record."""

    def __init__(self, message: str, record: object = None):
        super().__init__(message)
        self.record = record


class ModelOutputError(RuntimeError):
    """A model that is not built in (a plugin, a user's class or function) gave outputs that are not
    finite or have an impossible sign (a negative film, a negative friction coefficient): the message
    names the model, the output and the value."""


class PluginError(RuntimeError):
    """A model that is not built in failed inside a step of an analysis.

    The message names the model, where it comes from (``source``: the distribution and version of its
    entry point, or "given in code") and the step; the plugin's own exception is the ``__cause__``.
    """

    def __init__(self, message: str, *, model: str = "", source: str = "", step: str = ""):
        super().__init__(message)
        self.model = model
        self.source = source
        self.step = step


class PluginLoadError(ImportError):
    """A plugin entry point could not be loaded or does not fit its family."""


class CamcontactWarning(UserWarning):
    """Base class of the warnings camcontact emits."""


class ConvergenceWarning(CamcontactWarning, RuntimeWarning):
    """A solver stopped before its tolerance was met (``strict=False``)."""


class PluginLoadWarning(CamcontactWarning):
    """A third-party plugin failed to load; it is listed as failed and skipped."""


class PluginNameClashWarning(CamcontactWarning):
    """Two plugins of one family share a name; the built-in (or first) one wins."""


class StepFailureWarning(CamcontactWarning):
    """A step of an analysis failed (``strict=False``): its outputs are NaN, the report says why, and the
    other steps ran."""


class ValidityWarning(CamcontactWarning):
    """A model is used outside the range of parameters it was fitted or validated on."""


class SweepInterruptedWarning(CamcontactWarning):
    """A sweep stopped early (SIGINT, a broken process pool): the table holds the finished cases,
    ``frame.attrs["missing_cases"]`` lists the others, and ``stream=..., resume=True`` runs them."""


def not_converged(text: str, record: object, *, strict: bool, stacklevel: int = 2) -> None:
    """The end of a solve that did not converge: :class:`ConvergenceError` with ``record`` (its convergence
    record) when ``strict``, else a :class:`ConvergenceWarning` with ``text`` attributed ``stacklevel`` frames up
    from the caller (as :func:`warnings.warn` counts them from the caller)."""
    if strict:
        raise ConvergenceError(text, record)
    warnings.warn(text, ConvergenceWarning, stacklevel=stacklevel + 1)
