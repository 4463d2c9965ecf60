"""Lazy numba compilation of camcontact's kernels.

Every kernel is written once as plain Python on float64 arrays (its *twin*, used by the tests and
readable as the specification). :func:`compile_kernel` returns its ``numba.njit(cache=True,
nogil=True)`` version, compiled on the first request and kept for the process (numba caches it on
disk beside the kernel's module). The compiled kernels release the GIL, so calls in different
threads run in parallel. Importing this module imports neither numba nor compiles anything.
"""

from __future__ import annotations

from collections.abc import Callable

__all__ = ["compile_kernel"]

_COMPILED: dict[Callable, Callable] = {}


def compile_kernel(python: Callable) -> Callable:
    """The compiled twin of the plain-Python kernel ``python``."""
    function = _COMPILED.get(python)
    if function is None:
        import numba

        function = numba.njit(cache=True, nogil=True)(python)
        _COMPILED[python] = function
    return function
