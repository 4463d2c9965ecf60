"""Exceptions and warnings raised by camcontact.

Every error that is caused by user input derives from :class:`InputError`
(a :class:`ValueError`), so callers can catch bad input in one place. The
message always names the component (class), the field, the offending value
and what is allowed.
"""

from __future__ import annotations

__all__ = [
    "CamcontactWarning",
    "ConvergenceError",
    "ConvergenceWarning",
    "InputError",
    "PluginLoadError",
    "PluginLoadWarning",
    "PluginNameClashWarning",
    "UnknownModelError",
    "ValidityWarning",
]


class InputError(ValueError):
    """Bad user input: wrong unit, bare number for a dimensional field, out-of-range value, ..."""


class UnknownModelError(InputError, LookupError):
    """A model name that no registered plugin of the family provides."""


class ConvergenceError(RuntimeError):
    """A solver did not converge; ``record`` holds its convergence record."""

    def __init__(self, message: str, record: object = None):
        super().__init__(message)
        self.record = record


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


class ValidityWarning(CamcontactWarning):
    """A model is used outside the range of parameters it was fitted or validated on."""
