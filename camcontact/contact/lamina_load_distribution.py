"""Roller and lamina loads of a single-row radial roller bearing with profiled rollers and misalignment
(the slicing method of ISO/TS 16281:2008).

The Z rollers (azimuth phi_j from the radial load's direction) are cut into n_s laminae of width
L_we/n_s at the axial positions x_k = (k - n_s/2 - 1/2) L_we/n_s. With the inner ring displaced by
delta_r and tilted against the outer ring by the misalignment psi, lamina k of roller j is compressed by

    delta_jk = max(delta_r cos(phi_j) - s/2 - x_k tan(psi_j) - 2 P(x_k), 0),   tan(psi_j) = tan(psi) cos(phi_j)

(s the radial clearance, P the roller's profile drop, acting at both its contacts) and carries
q_jk = c_s delta_jk^(10/9) with c_s = c_L / n_s, c_L = 35948 L_we^(8/9) [N, mm] the stiffness of a steel
roller between both raceways; the roller load is Q_j = sum_k q_jk and delta_r balances
F_r = sum_j Q_j cos(phi_j) (a monotone equation in delta_r, solved by bracketing). The misalignment is
imposed (a shaft deflection or a housing error), and the moment the laminae then exert,
M = sum_j cos(phi_j) sum_k q_jk x_k, is reported. The ring moves along the load line only: a roller layout
that is not symmetric about it leaves sum_j Q_j sin(phi_j) unbalanced (small for Z >= 10), and without a radial
load delta_r stays 0, so a preloaded and tilted bearing carries a small radial reaction then.

ISO/TS 16281's default profile, when the real one is unknown, is the logarithmic
P(x) = 0.00035 D_we ln[1 / (1 - (2x/L_we)^2)] for L_we <= 2.5 D_we; longer rollers are straight in the
middle and crowned by 0.0005 D_we ln[1 / (1 - ((2|x| - (L_we - 2.5 D_we)) / (2.5 D_we))^2)] over the
outer 2.5 D_we (:func:`iso_default_profile`; it equals Lundberg's profile designed for about 3000 MPa).

Sources: ISO/TS 16281:2008 Eqs. 35-46 (stiffness, lamina deflection and equilibrium) and 42-44 (default
profile), as transcribed by independent public implementations that quote the standard's equation
numbers (the standard's text was not at hand); the constant 35948 is ISO's, about 4 % below Palmgren's
doubled line-contact law (:func:`camcontact.contact.load_distribution.line_contact_stiffness`).
"""

from __future__ import annotations

import math

import attrs
import numpy as np
from scipy.optimize import brentq

from ..errors import ConvergenceError, InputError
from .hertz_line import hertz_line_arrays

__all__ = ["ISO_LAMINA_STIFFNESS", "LaminaLoadDistribution", "iso_default_profile", "loaded_length",
           "solve_lamina_load_distribution"]

#: c_L = 35948 L_we^(8/9) [N/mm^(10/9)], a steel roller between both raceways (ISO/TS 16281)
ISO_LAMINA_STIFFNESS = 35948.0
#: the fewest laminae ISO/TS 16281 allows
MIN_LAMINAE = 30


def iso_default_profile(x, roller_diameter: float, roller_length: float) -> np.ndarray:
    """ISO/TS 16281's reference profile drop P(x) [m] of a cylindrical roller (module docstring) at the axial
    positions x [m] (|x| < L_we/2), D_we and L_we [m]."""
    x = np.abs(np.asarray(x, dtype=float))
    D, L = roller_diameter, roller_length
    if np.any(x >= 0.5 * L):
        raise InputError("iso_default_profile: positions must lie inside the roller length (|2x/L_we| < 1)")
    if L <= 2.5 * D:
        return 0.00035 * D * np.log(1.0 / (1.0 - (2.0 * x / L) ** 2))
    flat = 0.5 * (L - 2.5 * D)
    s = np.clip((2.0 * x - 2.0 * flat) / (2.5 * D), 0.0, None)
    return np.where(x <= flat, 0.0, 0.0005 * D * np.log(1.0 / (1.0 - s**2)))


def loaded_length(x: np.ndarray, approach: np.ndarray) -> float:
    """Length of a roller's loaded contact [m] from the approach (compression) of its laminae at their centres ``x``
    [m] (equally spaced; positive: loaded): from where the approach crosses zero, linear between the centres, or the
    roller's end half a lamina beyond the last centre, to the same at the other side - so the laminae's width does
    not quantise it; 0 without a loaded lamina."""
    loaded = np.flatnonzero(approach > 0.0)
    if loaded.size == 0:
        return 0.0
    half_width = 0.5 * (x[1] - x[0])

    def edge(inside: int, outside: int, end: float) -> float:
        if outside < 0 or outside >= x.size:
            return end
        return x[outside] + (x[inside] - x[outside]) * approach[outside] / (approach[outside] - approach[inside])

    first, last = int(loaded[0]), int(loaded[-1])
    return float(edge(last, last + 1, x[-1] + half_width) - edge(first, first - 1, x[0] - half_width))


@attrs.frozen
class LaminaLoadDistribution:
    """Roller and lamina loads in equilibrium (SI): ``q`` [N] (Z, n_s) per lamina, ``Q`` [N] (Z,) per roller,
    ``azimuth`` [rad] (Z,), ``x`` [m] (n_s,) lamina centres, ``compression`` [m] (Z, n_s) (negative: open),
    ``delta_r`` [m], ``misalignment`` [rad], ``moment`` [N m] the laminae exert, ``clearance`` [m]; the convergence
    record: ``residual`` |sum Q cos(phi) - F_r| / F_r [-] and ``iterations`` of the root search on delta_r."""

    q: np.ndarray = attrs.field(repr=False, eq=False)
    Q: np.ndarray = attrs.field(repr=False, eq=False)
    azimuth: np.ndarray = attrs.field(repr=False, eq=False)
    x: np.ndarray = attrs.field(repr=False, eq=False)
    compression: np.ndarray = attrs.field(repr=False, eq=False)
    delta_r: float
    misalignment: float
    moment: float
    radial_load: float
    clearance: float
    residual: float = 0.0
    iterations: int = 0

    @property
    def loaded(self) -> np.ndarray:
        """Rollers in contact (Q > 0)."""
        return self.Q > 0.0

    @property
    def loaded_lengths(self) -> np.ndarray:
        """Each roller's loaded length [m] (:func:`loaded_length` of its compressions; 0 for an unloaded roller)."""
        return np.array([loaded_length(self.x, c) for c in self.compression])

    @property
    def load_per_length(self) -> np.ndarray:
        """Lamina load per unit length [N/m], shape (Z, n_s)."""
        return self.q / (self.x[1] - self.x[0])

    def pressure(self, R: float, E_reduced: float) -> np.ndarray:
        """Hertz pressure of every lamina [Pa], (Z, n_s), as a line contact of reduced radius R [m] and E' [Pa]."""
        return hertz_line_arrays(self.load_per_length, R, E_reduced)[1]

    def roller_frame(self):
        """One row per roller: azimuth [deg], Q [N], loaded, laminae in contact, the largest lamina load [N] and
        its axial position [mm]."""
        import pandas as pd

        k = np.argmax(self.q, axis=1)
        return pd.DataFrame({"roller": np.arange(self.Q.size), "azimuth [deg]": np.degrees(self.azimuth),
                             "Q [N]": self.Q, "loaded": self.loaded, "laminae in contact": (self.q > 0).sum(axis=1),
                             "q_max [N]": self.q.max(axis=1), "x at q_max [mm]": 1e3 * self.x[k]})

    def lamina_frame(self):
        """One row per roller and lamina: roller, lamina, x [mm], compression [um], q [N]."""
        import pandas as pd

        Z, n = self.q.shape
        return pd.DataFrame({"roller": np.repeat(np.arange(Z), n), "lamina": np.tile(np.arange(n), Z),
                             "x [mm]": np.tile(1e3 * self.x, Z), "compression [um]": 1e6 * self.compression.ravel(),
                             "q [N]": self.q.ravel()})


def solve_lamina_load_distribution(radial_load: float, *, roller_count: int, roller_length: float, profile_drop,
                                   clearance: float = 0.0, misalignment: float = 0.0, laminae: int = MIN_LAMINAE,
                                   first_azimuth: float = 0.0) -> LaminaLoadDistribution:
    """Roller and lamina loads of a single-row radial roller bearing (module docstring): F_r [N], Z, L_we [m], the
    roller's profile drop P(x_k) [m] at the n_s lamina centres (an array, or a function of x [m]), the radial
    clearance s [m], the imposed misalignment psi [rad], n_s (>= 30) and the azimuth of the first roller from
    the load line [rad]."""
    Fr = float(radial_load)
    if not (Fr >= 0.0 and math.isfinite(Fr)):
        raise InputError(f"lamina load distribution: radial_load = {radial_load!r} N; allowed: finite and >= 0")
    if not (isinstance(roller_count, (int, np.integer)) and roller_count >= 3):
        raise InputError(f"lamina load distribution: roller_count = {roller_count!r}; allowed: an integer >= 3")
    if not (isinstance(laminae, (int, np.integer)) and laminae >= MIN_LAMINAE):
        raise InputError(f"lamina load distribution: laminae = {laminae!r}; ISO/TS 16281 asks for at least {MIN_LAMINAE}")
    if not (roller_length > 0.0 and math.isfinite(clearance) and abs(misalignment) < 0.05):
        raise InputError(f"lamina load distribution: roller_length = {roller_length!r} m (> 0), clearance = "
                         f"{clearance!r} m (finite), misalignment = {misalignment!r} rad (|psi| < 0.05)")
    n = int(laminae)
    x = (np.arange(1, n + 1) - 0.5 * n - 0.5) * roller_length / n
    drop = np.asarray(profile_drop(x) if callable(profile_drop) else profile_drop, dtype=float)
    if drop.shape != (n,) or not np.all(np.isfinite(drop)):
        raise InputError(f"lamina load distribution: profile_drop gives {drop.shape} values; needs {n} finite ones")
    Z = int(roller_count)
    azimuth = first_azimuth + 2.0 * math.pi * np.arange(Z) / Z
    cos_phi = np.cos(azimuth)
    c_s = ISO_LAMINA_STIFFNESS * (1e3 * roller_length) ** (8.0 / 9.0) / n * 1e3 ** (10.0 / 9.0)  # N / m^(10/9)
    tilt = np.tan(misalignment) * cos_phi

    def compression(delta_r: float) -> np.ndarray:
        return (delta_r * cos_phi - 0.5 * clearance)[:, None] - x[None, :] * tilt[:, None] - 2.0 * drop[None, :]

    def loads(delta_r: float) -> np.ndarray:
        return c_s * np.maximum(compression(delta_r), 0.0) ** (10.0 / 9.0)

    iterations = 0
    if Fr == 0.0:
        delta_r = 0.0
    else:
        def balance(delta_r: float) -> float:
            return float(np.sum(loads(delta_r).sum(axis=1) * cos_phi)) - Fr

        low = 0.5 * clearance + 2.0 * float(drop.min()) - abs(tilt).max() * 0.5 * roller_length
        high = max(low, 0.0) + 1e-9
        while balance(high) < 0.0:
            high = 2.0 * high + 1e-9
        delta_r, info = brentq(balance, low, high, xtol=1e-18, rtol=1e-14, full_output=True)
        iterations = info.iterations
    q = loads(delta_r)
    Q = q.sum(axis=1)
    residual = abs(float(np.sum(Q * cos_phi)) - Fr) / Fr if Fr > 0.0 else 0.0
    if not residual <= 1e-8:
        raise ConvergenceError(f"lamina load distribution: force imbalance {residual:.3g} of F_r = {Fr:g} N after "
                               f"{iterations} iterations on delta_r")
    moment = float(np.sum(cos_phi * (q * x[None, :]).sum(axis=1)))
    return LaminaLoadDistribution(q=q, Q=Q, azimuth=azimuth, x=x, compression=compression(delta_r), delta_r=delta_r,
                                  misalignment=float(misalignment), moment=moment, radial_load=Fr,
                                  clearance=float(clearance), residual=residual, iterations=iterations)
