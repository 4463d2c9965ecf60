"""Elastic deformation integral of a line contact: direct, FFT and multilevel multi-integration.

For pressures P_j on a uniform grid of spacing h the deformation sum is

.. math:: w_i = \\sum_j K(i - j)\\,P_j, \\qquad K(d) = \\int_{(d-1/2)h}^{(d+1/2)h} \\ln|t|\\,dt

and H_i = H0 + X_i^2/2 - w_i/pi (Tsuha 2015 Eqs. 5.44–5.48). Three evaluations:

``direct``
    the O(n^2) sum (the reference);
``fft``
    the same Toeplitz product by zero-padded FFT convolution, O(n log n), exact to rounding;
``mlmi``
    multilevel multi-integration (Brandt & Lubrecht 1990; Venner & Lubrecht 2000 ch. 5):
    the pressures are anterpolated to a grid twice as coarse with the transpose of 6th-order
    interpolation, the product is evaluated there recursively, interpolated back with the
    6th-order stencil (1/256)[3 -25 150 150 -25 3], and the kernel's near-singular part is
    corrected exactly within ``correction`` points on both the source and the target side.
    O(n) work; its error falls off fast with the correction width.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from . import _kernels

__all__ = ["METHODS", "Deformation", "default_correction"]

METHODS = ("mlmi", "fft", "direct")
DIRECT_BELOW = 48  #: MLMI evaluates directly once a level has this few source points


def default_correction(n: int) -> int:
    """MLMI correction width: Tsuha's 3 + ln n (Eq. 5.37), but at least 16 points.

    Measured against the direct sum (tests/unit/test_ehl_deformation.py): relative error
    about 2e-4 with 6 points, 9e-6 with 10 and 5e-7 with 16, falling roughly as width^-6.
    16 keeps the deformation error well below what 4-significant-digit films need.
    """
    return max(16, int(math.ceil(3.0 + math.log(n))))


class Deformation:
    """w = K P on a uniform grid of ``n`` points and spacing ``h``.

    Parameters
    ----------
    n, h : int, float
        Grid size and spacing (X units).
    method : str
        ``"mlmi"`` (default), ``"fft"`` or ``"direct"``.
    correction : int, optional
        MLMI correction width (default :func:`default_correction`).
    compiled : bool
        Use the numba kernels (True) or their plain-Python twins (False, slow; for tests).
    """

    def __init__(self, n: int, h: float, method: str = "mlmi", correction: int | None = None, compiled: bool = True):
        if method not in METHODS:
            raise InputError(f"deformation method {method!r} unknown; choose one of {METHODS}")
        self.n, self.h, self.method = int(n), float(h), method
        self.correction = default_correction(n) if correction is None else int(correction)
        self._kernel = _kernels.compiled if compiled else _kernels.PY.__getitem__
        self._tables: tuple[np.ndarray, np.ndarray] | None = None
        self._fft_kernel = None
        if method == "fft":
            size = 1 << int(math.ceil(math.log2(2 * n)))
            table = np.array([_kernels.kernel_value(float(d), self.h) for d in range(n)])
            circulant = np.zeros(size)
            circulant[:n] = table
            circulant[size - n + 1:] = table[1:][::-1]
            self._fft_size = size
            self._fft_kernel = np.fft.rfft(circulant)

    def __call__(self, P: np.ndarray) -> np.ndarray:
        """w = K P [X units] for pressures P (length n)."""
        P = np.ascontiguousarray(P, dtype=float)
        if P.shape != (self.n,):
            raise InputError(f"deformation: expected {self.n} pressures, got shape {P.shape}")
        if self.method == "direct":
            return self._kernel("deformation_direct")(P, self.h)
        if self.method == "fft":
            spectrum = np.fft.rfft(P, self._fft_size) * self._fft_kernel
            return np.fft.irfft(spectrum, self._fft_size)[: self.n]
        return self._mlmi(P)

    def _mlmi_tables(self) -> tuple[np.ndarray, np.ndarray]:
        """Correction tables (c1, c2) of strides 1, 2, 4, ... (rows), enough for every MLMI level."""
        if self._tables is None:
            depths = max(1, int(math.ceil(math.log2(max(self.n, 2)))) + 1)
            pairs = [self._kernel("mlmi_correction_tables")(self.h, 1 << d, self.correction, _kernels.INTERP6)
                     for d in range(depths)]
            self._tables = (np.array([c1 for c1, _ in pairs]), np.array([c2 for _, c2 in pairs]))
        return self._tables

    def _mlmi(self, P: np.ndarray) -> np.ndarray:
        c1s, c2s = self._mlmi_tables()
        return self._kernel("mlmi_apply")(P, self.h, self.correction, c1s, c2s, _kernels.INTERP6, DIRECT_BELOW)
