"""Composite roughness, specific film thickness Lambda and the lubrication regime.

.. math:: \\sigma = \\sqrt{\\sigma_1^2 + \\sigma_2^2}, \\qquad \\Lambda = h / \\sigma

sigma_i are the RMS roughnesses (Rq) of the two surfaces [m]. Regimes for rolling contacts
(Cheng 1983, as Delabenetta 2021 §2.3 with its erratum 20 corrected): Lambda >= 3 full
film, 1 < Lambda < 3 mixed, Lambda <= 1 boundary.

A roughness of RMS sigma modelled as a sinusoid z = A cos(2 pi x / lambda) has the amplitude
A = sqrt(2) sigma (the RMS of A cos is A / sqrt 2); pressing it flat against a smooth elastic body
takes the mean pressure p* = pi E* A / lambda (Johnson 1985 §13.2, Westergaard's wavy surface).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError

__all__ = ["REGIMES", "composite_roughness", "lambda_ratio", "lubrication_regime", "sinusoid_amplitude",
           "sinusoid_full_contact_pressure"]

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


def sinusoid_amplitude(sigma: float) -> float:
    """Amplitude A [m] of the sinusoid z = A cos(2 pi x / lambda) whose RMS is ``sigma`` [m].

    .. math:: A = \\sqrt{2}\\,\\sigma

    (the mean of cos^2 over a period is 1/2, so RMS = A / sqrt 2). Delabenetta (2021) Eq. 30 writes
    amp = sigma / sqrt 2 instead, a factor 2 lower (kept as the thesis convention's reading by the
    raceway scene).
    """
    if not (sigma >= 0 and math.isfinite(sigma)):
        raise InputError(f"roughness: sigma = {sigma!r} m must be finite and >= 0")
    return math.sqrt(2.0) * sigma


def sinusoid_full_contact_pressure(amplitude: float, wavelength: float, E_star: float) -> float:
    """Mean pressure p* [Pa] that flattens a 2-D sinusoidal surface of ``amplitude`` A [m] and
    ``wavelength`` lambda [m] completely against a smooth elastic body (full contact).

    .. math:: p^* = \\frac{\\pi E^* A}{\\lambda}

    E* [Pa] is Johnson's contact modulus 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, i.e. half of
    Hamrock's E' (the project's ``E_reduced``). Below p* the waves touch only near their crests; at
    p* the pressure is p* (1 + cos(2 pi x / lambda)): 2 p* on the crests, zero in the valleys.

    References
    ----------
    Johnson, K.L. (1985) *Contact Mechanics*, Cambridge University Press, §13.2 (elastic contact of
    wavy surfaces, after Westergaard 1939).
    """
    for name, value in (("amplitude", amplitude), ("wavelength", wavelength), ("E_star", E_star)):
        if not math.isfinite(value):
            raise InputError(f"sinusoid_full_contact_pressure: {name} = {value!r}; must be finite")
    if amplitude < 0 or not wavelength > 0 or not E_star > 0:
        raise InputError(f"sinusoid_full_contact_pressure: amplitude = {amplitude!r} m, wavelength = {wavelength!r} m, "
                         f"E_star = {E_star!r} Pa; allowed amplitude >= 0, wavelength > 0, E_star > 0")
    return math.pi * E_star * amplitude / wavelength
