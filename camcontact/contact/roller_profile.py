"""Roller profiles (crowning) and the slicing (lamina) model of a roller on its raceway, with misalignment.

A profile is the drop c(y) [m] of the roller's (or the raceway's) generatrix below the straight line at the
axial position y (|y| <= l/2, l the effective contact length), so the undeformed separation of the
roller and its raceway is x^2/(2R) + c(y) - theta y for a misalignment (tilt) theta of the roller against
the raceway. Profiles (:class:`RollerProfile`):

* ``"straight"``: c = 0 (the edges load up: edge stress);
* ``"crowned"``: a circular crown over the whole length, c = c_e (2y/l)^2 with the drop c_e at the ends;
* ``"lundberg"``: Lundberg's (1939) logarithmic profile for the design load Q_d, which gives a uniform
  pressure along an aligned roller on a half-space, c = (2 Q_d / (pi l E')) ln[1 / (1 - (2y/l)^2)];
* ``"johns_gohar"``: Johns & Gohar's (1981) finite version of it,
  c = (2 Q_d / (pi l E')) ln[1 / (1 - (1 - 0.3033 b/a)(2y/l)^2)] with a = l/2 and b the Hertz
  half-width under Q_d (finite at the ends, for manufacture);
* ``"iso_ts_16281"``: the reference profile of ISO/TS 16281 for a roller of diameter D_we when the real one
  is unknown, 0.00035 D_we ln[1/(1 - (2y/l)^2)] (:func:`camcontact.contact.lamina_load_distribution.iso_default_profile`;
  Lundberg's for about 3000 MPa).

The slicing model (ISO/TS 16281:2008's laminae) cuts the contact into n slices of width l/n that each
carry q_k = K_s max(delta - c_k + theta y_k, 0)^(10/9) without interaction, with K_s = K_l w/l the slice's share
(width w = l/n) of the stiffness of the one roller-raceway contact after Palmgren, delta = 3.81 (2/(pi E'))^0.9
Q^0.9 / l^0.8 (:func:`camcontact.contact.hertz_line.line_approach`, ``"palmgren"``: 3.84e-5 Q^0.9 / l^0.8
[mm, N, mm] for steel), so that an aligned straight roller approaches by Palmgren's delta whatever the number
of slices (applying the law to each slice's own width would scale the approach by n^(-0.1));
delta follows from sum q_k = Q; each slice's Hertz pressure p_k = sqrt(q_k E' / (2 pi R w)) (Johnson 1985 §4.3
with E' = 2/[(1 - nu1^2)/E1 + (1 - nu2^2)/E2]). It ignores how
one slice's pressure deforms its neighbours, so it sees no edge stress on a straight roller: the
numerical half-space contact (:func:`camcontact.contact.dry_contact.solve_dry_contact`, via
:func:`roller_dry_contact`) does.

References: Lundberg, G. (1939) Elastische Berührung zweier Halbräume, Forschung auf dem Gebiete des
Ingenieurwesens 10:201-211; Johns, P.M. & Gohar, R. (1981) Roller bearings under radial and eccentric
loads, Tribology International 14:131-136; Fujiwara, H. & Kawase, T. (2007) Logarithmic profiles of
rollers in roller bearings and optimization of the profiles, NTN Technical Review 75 (their Eqs. 1-2);
ISO/TS 16281:2008 (laminae); Palmgren (1959) for the slice stiffness.
"""

from __future__ import annotations

import math

import attrs
import numpy as np
from scipy.optimize import brentq

from ..errors import ConvergenceError, InputError
from .dry_contact import DryContact, solve_dry_contact
from .hertz_line import hertz_line, hertz_line_arrays, line_approach
from .lamina_load_distribution import iso_default_profile, loaded_length

__all__ = ["PROFILE_KINDS", "LaminaResult", "RollerProfile", "roller_dry_contact", "solve_laminae"]

PROFILE_KINDS = ("straight", "crowned", "lundberg", "johns_gohar", "iso_ts_16281")


@attrs.frozen(kw_only=True)
class RollerProfile:
    """A roller profile (module docstring): ``kind`` one of :data:`PROFILE_KINDS`; ``crown_drop`` c_e [m] of a
    ``"crowned"`` one; ``design_load`` Q_d [N] of a logarithmic one (Lundberg, Johns-Gohar); ``roller_diameter``
    D_we [m] of the ISO/TS 16281 one."""

    kind: str = "straight"
    crown_drop: float = 0.0
    design_load: float = 0.0
    roller_diameter: float = 0.0

    def __attrs_post_init__(self) -> None:
        if self.kind not in PROFILE_KINDS:
            raise InputError(f"RollerProfile.kind = {self.kind!r}; allowed: {', '.join(PROFILE_KINDS)}")
        if self.kind == "crowned" and not (self.crown_drop > 0.0 and math.isfinite(self.crown_drop)):
            raise InputError(f"RollerProfile.crown_drop = {self.crown_drop!r} m; a crowned profile needs a drop > 0 at "
                             "the ends")
        if self.kind in ("lundberg", "johns_gohar") and not (self.design_load > 0.0 and math.isfinite(self.design_load)):
            raise InputError(f"RollerProfile.design_load = {self.design_load!r} N; a logarithmic profile is designed for "
                             "a load > 0")
        if self.kind == "iso_ts_16281" and not (self.roller_diameter > 0.0 and math.isfinite(self.roller_diameter)):
            raise InputError(f"RollerProfile.roller_diameter = {self.roller_diameter!r} m; the ISO/TS 16281 profile "
                             "scales with the roller diameter (> 0)")

    @property
    def label(self) -> str:
        """A short name for plots and reports."""
        if self.kind == "crowned":
            return f"crowned ({self.crown_drop * 1e6:.3g} µm)"
        if self.kind in ("lundberg", "johns_gohar"):
            name = "Lundberg" if self.kind == "lundberg" else "Johns-Gohar"
            return f"{name} ({self.design_load * 1e-3:.3g} kN)"
        if self.kind == "iso_ts_16281":
            return "ISO/TS 16281"
        return "straight"

    def drop(self, y, length: float, E_reduced: float, R: float) -> np.ndarray:
        """c(y) [m] at the axial positions y [m] (|y| < l/2) of a contact of length l [m], E' [Pa] and reduced
        radius R [m] (for Johns-Gohar's Hertz half-width)."""
        s = 2.0 * np.asarray(y, dtype=float) / length
        if np.any(np.abs(s) >= 1.0):
            raise InputError("RollerProfile.drop: positions must lie inside the contact length (|2y/l| < 1)")
        if self.kind == "straight":
            return np.zeros_like(s)
        if self.kind == "crowned":
            return self.crown_drop * s**2
        if self.kind == "iso_ts_16281":
            return iso_default_profile(0.5 * s * length, self.roller_diameter, length)
        scale = 2.0 * self.design_load / (math.pi * length * E_reduced)
        if self.kind == "lundberg":
            return scale * np.log(1.0 / (1.0 - s**2))
        b = hertz_line(self.design_load / length, R, E_reduced).b
        return scale * np.log(1.0 / (1.0 - (1.0 - 0.3033 * b / (0.5 * length)) * s**2))


@attrs.frozen
class LaminaResult:
    """Slice loads of a roller contact (SI): centres ``y`` [m], ``load`` q_k [N], ``load_per_length`` [N/m],
    Hertz ``pressure`` [Pa] and ``approach`` delta - c_k + theta y_k [m] per slice; the roller's ``delta`` [m]; the
    convergence record: ``residual`` |sum q_k - Q| / Q [-] and ``iterations`` of the root search on delta."""

    y: np.ndarray = attrs.field(repr=False, eq=False)
    load: np.ndarray = attrs.field(repr=False, eq=False)
    load_per_length: np.ndarray = attrs.field(repr=False, eq=False)
    pressure: np.ndarray = attrs.field(repr=False, eq=False)
    approach: np.ndarray = attrs.field(repr=False, eq=False)
    delta: float
    residual: float = 0.0
    iterations: int = 0

    @property
    def loaded_length(self) -> float:
        """Length of the loaded contact along the roller [m]: from where the approach delta - c + theta y crosses zero
        (linear between the lamina centres, so the slices' width does not quantise it) or the roller's end, to the
        same at the other side; 0 without load."""
        return loaded_length(self.y, self.approach)

    def to_frame(self):
        """One row per lamina: y [mm], load [N], load per length [N/mm], pressure [MPa], approach [um]."""
        import pandas as pd

        return pd.DataFrame({"lamina": np.arange(self.y.size), "y [mm]": 1e3 * self.y, "load [N]": self.load,
                             "load per length [N/mm]": 1e-3 * self.load_per_length, "pressure [MPa]": 1e-6 * self.pressure,
                             "approach [um]": 1e6 * self.approach, "loaded": self.load > 0.0})


def _check(load: float, length: float, R: float, E_reduced: float, where: str) -> None:
    for name, value in (("load", load), ("length", length), ("R", R), ("E_reduced", E_reduced)):
        if not (value > 0.0 and math.isfinite(value)):
            raise InputError(f"{where}: {name} = {value!r}; allowed: finite and > 0")


def solve_laminae(load: float, length: float, R: float, E_reduced: float, profile: RollerProfile, *,
                  misalignment: float = 0.0, laminae: int = 30) -> LaminaResult:
    """Slice loads and pressures of a roller of effective length ``length`` [m] on its raceway under ``load`` [N]
    (reduced radius R [m] along rolling, E' [Pa]) with its ``profile`` and a ``misalignment`` theta [rad]
    (module docstring); ``laminae`` slices (ISO/TS 16281 asks for at least 30)."""
    _check(load, length, R, E_reduced, "laminae")
    if not (isinstance(laminae, int) and laminae >= 5):
        raise InputError(f"laminae = {laminae!r}; allowed: an integer >= 5")
    if not math.isfinite(misalignment):
        raise InputError(f"laminae: misalignment = {misalignment!r} rad; must be finite")
    width = length / laminae
    y = (np.arange(laminae) + 0.5) * width - 0.5 * length
    gap = profile.drop(y, length, E_reduced, R) - misalignment * y
    # the slice's share of the contact's Palmgren stiffness: Q = K delta^(10/9), K = (delta at 1 N)^(-10/9)
    stiffness = line_approach("palmgren", E_reduced=E_reduced, force=1.0, length=length) ** (-10.0 / 9.0) * width / length

    def carried(delta: float) -> float:
        return float(np.sum(stiffness * np.maximum(delta - gap, 0.0) ** (10.0 / 9.0))) - load

    low = float(gap.min())
    high = low + (load / stiffness) ** 0.9 + 1e-12
    while carried(high) < 0.0:
        high = low + 2.0 * (high - low)
    delta, info = brentq(carried, low, high, xtol=1e-16, rtol=1e-14, full_output=True)
    approach = delta - gap
    q = stiffness * np.maximum(approach, 0.0) ** (10.0 / 9.0)
    residual = abs(float(q.sum()) - load) / load
    if not residual <= 1e-8:
        raise ConvergenceError(f"laminae: load imbalance {residual:.3g} of Q = {load:g} N after {info.iterations} "
                               "iterations on the approach")
    per_length = q / width
    pressure = hertz_line_arrays(per_length, R, E_reduced)[1]
    return LaminaResult(y=y, load=q, load_per_length=per_length, pressure=pressure, approach=approach, delta=delta,
                        residual=residual, iterations=info.iterations)


def roller_dry_contact(load: float, length: float, R: float, E_reduced: float, profile: RollerProfile, *,
                       misalignment: float = 0.0, cells_along: int = 200, cells_across: int = 32,
                       tolerance: float = 1e-8) -> DryContact:
    """The numerical dry contact of the roller on its raceway (half-space, :func:`solve_dry_contact`): the
    separation x^2/(2R) + c(y) - theta y over |x| <= 2 b_Hertz (b under the mean load per length; widened at the
    same cell size until the contact stays clear of the grid's sides, up to 1.6^3 = 4.1 times, else a
    ConvergenceError) and the roller's length |y| <= l/2 in ``cells_across`` x
    ``cells_along`` cells; pressure along the roller with its edge stress."""
    _check(load, length, R, E_reduced, "roller dry contact")
    half = 2.0 * hertz_line(load / length, R, E_reduced).b
    y = (np.arange(cells_along) + 0.5) * (length / cells_along) - 0.5 * length
    drop = profile.drop(y, length, E_reduced, R) - misalignment * y
    across = cells_across
    for _ in range(4):
        x = (np.arange(across) + 0.5) * (2.0 * half / across) - half
        result = solve_dry_contact(x, y, x[None, :] ** 2 / (2.0 * R) + drop[:, None], load, E_reduced,
                                   tolerance=tolerance)
        edge = max(float(result.pressure[:, 0].max()), float(result.pressure[:, -1].max()))
        if edge <= 1e-3 * result.p_max:
            return result
        # the contact reached the grid's side (a concentrated load widens it): widen the grid, same cell size
        half *= 1.6
        across = int(math.ceil(1.6 * across))
    raise ConvergenceError(f"roller dry contact: the contact still reaches the sides of a grid {2e6 * half / 1.6:.4g} um "
                           f"wide (load {load:g} N, misalignment {misalignment:g} rad): the load concentrates too much "
                           "for this model; reduce the misalignment or check the profile")
