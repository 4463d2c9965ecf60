"""Lazy numba compilation of camcontact's kernels.

Every kernel is written once as plain Python on float64 arrays (its *twin*, used by the tests and
readable as the specification). :func:`compile_kernel` returns its ``numba.njit(cache=True,
nogil=True)`` version, compiled on the first request and kept for the process (numba caches it on
disk beside the kernel's module). The compiled kernels release the GIL, so calls in different
threads run in parallel. Importing this module imports neither numba nor compiles anything.

Kernels call small *helpers* per node (the operator at a node, the lubricant laws, a stencil).
:func:`helper` registers them for compiled callers without numba's reference counting (NRT): a
helper that takes arrays and branches makes numba emit an atomic incref/decref pair per array
argument and call that its pruning pass cannot remove (numba issue #2350), and those dominated
the sweeps: the point contact's nodal laws cost 97 ns per node with them, 3-48 ns without
(513^2, Barus and Roelands). A helper must therefore allocate nothing (no ``np.empty``, no
slicing copies); the kernels that allocate stay ordinary compiled functions.
"""

from __future__ import annotations

from collections.abc import Callable

__all__ = ["compile_kernel", "helper"]

_COMPILED: dict[Callable, Callable] = {}


def compile_kernel(python: Callable) -> Callable:
    """The compiled twin of the plain-Python kernel ``python``."""
    function = _COMPILED.get(python)
    if function is None:
        import numba

        function = numba.njit(cache=True, nogil=True)(python)
        _COMPILED[python] = function
    return function


def helper(python: Callable) -> Callable:
    """Register the plain-Python helper ``python`` for compiled kernels without reference counting
    (``numba.extending.register_jitable(_nrt=False)``); it stays callable from Python unchanged.
    Imports numba (kernel modules import it anyway)."""
    from numba.extending import register_jitable

    return register_jitable(_nrt=False)(python)
