"""Composite roughness, specific film thickness Lambda and the lubrication regime.

.. math:: \\sigma = \\sqrt{\\sigma_1^2 + \\sigma_2^2}, \\qquad \\Lambda = h / \\sigma

sigma_i are the RMS roughnesses (Rq) of the two surfaces [m]. Regimes for rolling contacts
(Cheng 1983, as Delabenetta 2021 §2.3 with its erratum 20 corrected): Lambda >= 3 full
film, 1 < Lambda < 3 mixed, Lambda <= 1 boundary.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError

__all__ = ["REGIMES", "composite_roughness", "lambda_ratio", "lubrication_regime"]

REGIMES = ("boundary", "mixed", "full film")


def composite_roughness(sigma1: float, sigma2: float) -> float:
    """Composite RMS roughness sqrt(sigma1^2 + sigma2^2) [m] (Delabenetta 2021 Eq. 29)."""
    if not (sigma1 >= 0 and sigma2 >= 0 and math.isfinite(sigma1) and math.isfinite(sigma2)):
        raise InputError(f"roughness: sigma1 = {sigma1!r} m and sigma2 = {sigma2!r} m must be finite and >= 0")
    return math.hypot(sigma1, sigma2)


def lambda_ratio(h, sigma1: float, sigma2: float):
    """Specific film thickness Lambda = h / sqrt(sigma1^2 + sigma2^2) [-] (Delabenetta 2021 Eq. 13)."""
    sigma = composite_roughness(sigma1, sigma2)
    if sigma == 0.0:
        raise InputError("roughness: both surfaces have zero roughness, so Lambda is unbounded; give Rq > 0")
    value = np.asarray(h, dtype=float) / sigma
    return float(value) if value.ndim == 0 else value


def lubrication_regime(lam) -> str | np.ndarray:
    """'full film' (Lambda >= 3), 'mixed' (1 < Lambda < 3) or 'boundary' (Lambda <= 1)."""
    lam_array = np.asarray(lam, dtype=float)
    labels = np.where(lam_array >= 3.0, REGIMES[2], np.where(lam_array > 1.0, REGIMES[1], REGIMES[0]))
    return str(labels) if labels.ndim == 0 else labels
