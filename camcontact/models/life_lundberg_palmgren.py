"""Lundberg–Palmgren life of a traction contact, after Coy, Loewenthal & Zaretsky (1976).

Saccheto (2008, §5.3–5.4) rates each contact of the ball-cone CVT with the Lundberg–Palmgren
(1947) theory in the form of Coy et al. (1976). The probability of survival S of a stressed
volume V_z after eta stress cycles obeys (Eq. 5.13)

.. math::
    \\ln\\frac{1}{S} \\propto \\frac{\\tau_0^{\\,c}\\, \\eta^{\\,e}\\, V_z}{Z_0^{\\,h}}

with tau_0 the critical shear stress [Pa] at depth Z_0 [m] (which shear: see below). At S = 0.9
this gives the L10 life in millions of stress cycles (Eqs. 5.16, 5.25)

.. math::
    H_{10} = \\left(\\frac{K\\, Z_0^{\\,h}}{\\tau_0^{\\,c}\\, V_z}\\right)^{1/e}, \\qquad
    V_z = 2\\pi R\\, a\\, Z_0 \\quad\\text{(Eq. 5.24)}

where R is the radius of the rolling track on the body (the track length is 2 pi R) and a the
contact semi-axis *transverse* to rolling. Constants (Eqs. 5.14, 5.15, 5.17): c = 31/3,
h = 7/3, e = 10/9 for elliptical contacts and e = 3/2 for line contacts as Saccheto prints it
(Lundberg & Palmgren's roller value is 9/8, which would give the P^-4 law of line contacts;
e = 3/2 gives P'^-3, the same load law as the elliptical contact; keep ``e`` configurable),
and K = 1.428e95 (Coy 1975).

**Which shear.** Lundberg & Palmgren (1947) take for tau_0 the maximum *orthogonal* shear
stress: the amplitude of the reversing shear tau_xz on the planes parallel and normal to the
surface, which swings between +tau_0 and -tau_0 as the load rolls over a point, at its depth
z_0 (frictionless line contact: tau_0 = 0.250 p_0 at z_0 = 0.5 b; Johnson 1985 §4.2). Saccheto
§5.4, presenting Coy et al.'s form, describes tau_0 in the same words; his Ch. 7 simulation, however,
takes "the maximum shear stress of the stress state", the Mohr radius of Eq. 3.71 (0.300 p_0 at
0.786 b frictionless; the reference report §2.7 notes the ambiguity).
camcontact offers both (:data:`camcontact.contact.slice_stress.MEASURES`): the ball-cone scene's
``stress`` slot defaults to ``"orthogonal"`` (Lundberg–Palmgren), and ``stress="max_shear"``
reproduces the thesis. The slice's ``"orthogonal"`` tau_0 is the *peak* |tau_xz|; with surface
traction the reversing shear is lopsided and its peak exceeds its amplitude (half its range,
:attr:`~camcontact.contact.slice_stress.SliceExtremum.orthogonal_range`).

Life ratio orthogonal / Mohr, L_o/L_m = (tau_m/tau_o)^(c/e) (Z_o/Z_m)^((h-1)/e) at equal a and
R (the depth enters V_z once, hence h - 1):

* frictionless: (0.300/0.250)^9.3 = 5.45 from the stress alone (the "about 5x"), times
  (0.5/0.786)^1.2 = 0.58 from the shallower depth: 3.2;
* the Forti operating point (150 W, 60 rpm, 1:1, tutorials/forti_ball_cone_cvt.toml with the
  thesis's clamping, F_n = 1254 N, p_h = 4.32 GPa; FASTSIM traction about 0.088 p in (near) full
  slip): Mohr 0.304 p_h at 0.744 a, peak |tau_xz| 0.278 p_h at 0.457 a: 2.35 x 0.56 = 1.3 — as
  for a Hertz strip in full slip with q = 0.088 p (1.31). The traction's own tau_xz adds to one
  side of the reversing cycle: its amplitude (half range) stays 0.250 p_h and would give about
  3.5. With the axial-balance clamping (F_n = 5015 N, p_h = 6.86 GPa, F_t = 0.022 F_n) the
  ratio is about 1.9. Pinned by tests/unit/test_life_lp_shear_and_units.py.

**Units of K.** Neither Saccheto nor the reference report
(../shared/reference/ball_cone_cvt_saccheto2008.md §2.7, Eq. 5.17) states them, and no source
stating them was found (searched: Coy, Loewenthal & Zaretsky NASA TN D-8362; Loewenthal &
Zaretsky NASA RP-1154 §4.2; Zaretsky's NASA life-prediction reviews; none of their text was
available). The basis is therefore an *assumption*, chosen on this evidence (computed, see
tests/unit/test_life_lp_shear_and_units.py and tests/literature/test_lundberg_palmgren.py):

* dimensions: with H_10 in millions of cycles, K carries stress^c length^(3-h). K read in
  psi and inch equals K psi^c in^(3-h) = 10^38.60 K in Pa and m, so the same contact lives
  10^(38.60/e) = 10^34.74 times longer in the US reading (kgf/mm^2 and mm, Lundberg &
  Palmgren's own units: 10^63 times longer);
* SI (``unit_basis="SI"``, the default: tau_0 in Pa, lengths in m) gives rolling-contact lives
  in the range the theory was calibrated on: a steel ball contact (Rx = 5 mm, Ry = 20 mm,
  R = 23.28 mm, frictionless) at p_0 = 1.43-2.27 GPa lives 9e10-1.4e9 cycles (orthogonal
  shear; 3e10-4e8 with the Mohr shear), and the inner-ring contact of a 6206 ball bearing at
  its rating load (P = C = 19.5 kN, Q_max = 4.37 P/Z = 9.5 kN, p_0 = 4.8 GPa) 1.0e5 inner-ring
  revolutions, a decade below the rating's 1e6 (conservative: the whole track at Q_max);
* psi and inch (``unit_basis="US"``) give 2e43-5e45 cycles and 6e39 revolutions for the same
  contacts: no material lives that long, so the US reading is not plausible for K = 1.428e95.
  (NASA Lewis reports of the period print SI first, psi in parentheses: consistent, not proof.)

Treat absolute lives as indicative; ratios between designs (the scaling laws below) do not
depend on K or its unit basis.

**Consequences checked by the tests** (Hertz scaling: tau_0 ~ p_0 ~ (P rho^2)^(1/3),
Z_0 ~ a ~ (P / rho)^(1/3)): H ~ P^((h - c - 2)/(3e)) = P^-3 (Eqs. 5.21, 5.33); for all lengths
scaled by s: H ~ s^((h + 2c - 5)/(3e)) = s^5.4 at constant load, s^((h - 3)/e) = s^-0.6 at
constant contact pressure, and s^(5.4 + 3) = s^8.4 at constant transmitted torque (the normal
load then falls as 1/s) — the last is Saccheto's Eq. 5.22 "H ~ size^8.4" (Loewenthal & Coy).

**Time.** Eq. 5.18 (hours = H_10 10^6 / (60 c_r omega), omega in rpm) in SI: life [s] = cycles /
(c_r n) with c_r stress cycles per revolution and n the speed [rev/s]; :func:`life_time`.

**System.** The Weibull product of the contact survivals gives (Eq. 5.20; the printed Eq. 5.19
"sum H/H_i = 1" is garbled, it should read sum (H/H_i)^e = 1)

.. math::
    H = \\left(\\sum_i H_i^{-e}\\right)^{-1/e}

for contacts of one type (one e), with all H_i on one time base (seconds, or revolutions of
one shaft — not stress cycles of bodies that turn at different rates); :func:`system_life`.

Saccheto's closed forms (Eqs. 5.31–5.35, constants K_1 = 2.32e19 and K_5 = 4.21e25) are not
implemented: their constants cannot be reproduced from K (reference report §2.7).

References
----------
Lundberg, G. & Palmgren, A. (1947) Dynamic capacity of rolling bearings, Acta Polytechnica,
Mech. Eng. Series 1(3). Coy, J.J., Loewenthal, S.H. & Zaretsky, E.V. (1976) Fatigue life
analysis for traction drives with application to a toroidal type geometry, NASA TN D-8362.
Johnson, K.L. (1985) Contact Mechanics, §4.2. Saccheto, T.J.S. (2008) MSc dissertation,
FEM/UNICAMP, §3.4, §5.3–5.4, Eqs. 3.71, 5.13–5.25.
"""

from __future__ import annotations

import math
from typing import Any

import attrs
import numpy as np

from ..errors import InputError
from ..units import in_range, number_field, one_of
from .base import LifeModel, builtin, float_or_array

__all__ = [
    "ELLIPTICAL_E",
    "LINE_E",
    "UNIT_BASES",
    "LundbergPalmgren",
    "life_constant_si",
    "life_time",
    "lundberg_palmgren_life",
    "stressed_volume",
    "system_life",
]

#: Coy (1975) constant of Eq. 5.17 (units unstated in the sources; SI assumed on the evidence of
#: the module docstring, "US" = psi and inch offered)
K_COY = 1.428e95
#: unit bases of K: "SI" (tau_0 in Pa, lengths in m; the default) and "US" (psi, inch); H_10 in
#: millions of stress cycles in both
UNIT_BASES = ("SI", "US")
#: 1 psi [Pa] (1 lbf/in^2 = 0.45359237 kg x 9.80665 m/s^2 / 0.0254^2 m^2)
PSI = 0.45359237 * 9.80665 / 0.0254**2
#: 1 inch [m]
INCH = 0.0254
#: stress exponent c (Eq. 5.14)
C_STRESS = 31.0 / 3.0
#: depth exponent h (Eq. 5.14)
H_DEPTH = 7.0 / 3.0
#: Weibull slope e of elliptical contacts (Eq. 5.14)
ELLIPTICAL_E = 10.0 / 9.0
#: Weibull slope e of line contacts as printed by Saccheto (Eq. 5.15)
LINE_E = 3.0 / 2.0


def _positive(where: str, **values) -> dict:
    """The values as float arrays, after checking that each is finite and > 0."""
    out = {}
    for key, value in values.items():
        try:
            array = np.asarray(value, dtype=float)
        except (TypeError, ValueError):
            raise InputError(f"{where}: {key} = {value!r} is not a number") from None
        if array.size == 0 or not np.all(np.isfinite(array) & (array > 0.0)):
            bad = array[~(np.isfinite(array) & (array > 0.0))] if array.size else array
            shown = bad.flat[0] if bad.size else value
            raise InputError(f"{where}: {key} = {shown!r}; allowed: finite and > 0")
        out[key] = array
    return out


def stressed_volume(z0, a_transverse, track_radius):
    """Stressed volume V_z = 2 pi R a Z_0 [m^3] (Saccheto Eq. 5.24).

    Parameters
    ----------
    z0 : float or array
        Depth Z_0 of the critical shear stress [m].
    a_transverse : float or array
        Contact semi-axis transverse to rolling [m].
    track_radius : float or array
        Radius R of the rolling track on the body [m].
    """
    v = _positive("stressed_volume", z0=z0, a_transverse=a_transverse, track_radius=track_radius)
    return float_or_array(2.0 * math.pi * v["track_radius"] * v["a_transverse"] * v["z0"])


def _log_unit_factor(where: str, unit_basis: str, c: float, h: float) -> float:
    """ln of the factor that turns K given in ``unit_basis`` into Pa^c m^(3-h) (0 for SI)."""
    if unit_basis not in UNIT_BASES:
        raise InputError(f"{where}: unit_basis = {unit_basis!r}; allowed: {', '.join(map(repr, UNIT_BASES))}")
    return c * math.log(PSI) + (3.0 - h) * math.log(INCH) if unit_basis == "US" else 0.0


def life_constant_si(K: float = K_COY, unit_basis: str = "SI", *, c: float = C_STRESS, h: float = H_DEPTH) -> float:
    """The life constant K of Eq. 5.16 expressed in SI, Pa^c m^(3-h) (H_10 in millions of cycles).

    ``unit_basis`` is the basis K is given in: ``"SI"`` (Pa, m: returned unchanged) or ``"US"``
    (psi, inch: K psi^c in^(3-h), i.e. 10^38.60 K for c = 31/3, h = 7/3). May overflow to inf
    for large K and c; :func:`lundberg_palmgren_life` works in logarithms instead.
    """
    _check_constants("life_constant_si", K=K, c=c, h=h)
    return K * math.exp(_log_unit_factor("life_constant_si", unit_basis, c, h))


def lundberg_palmgren_life(tau0, z0, a_transverse, track_radius, *, K: float = K_COY, c: float = C_STRESS,
                           h: float = H_DEPTH, e: float = ELLIPTICAL_E, unit_basis: str = "SI"):
    """L10 life [stress cycles] of one contact (Saccheto Eqs. 5.16, 5.24, 5.25).

    .. math::
        L_{10} = 10^6 \\left(\\frac{K Z_0^{\\,h}}{\\tau_0^{\\,c}\\, 2\\pi R\\, a\\, Z_0}\\right)^{1/e}

    evaluated in logarithms (no overflow of tau_0^c). The inputs are SI whatever ``unit_basis``:
    it only says in which units K is given (``"US"``: K in psi^c in^(3-h), the same as feeding
    tau_0 in psi and the lengths in inches to the SI formula).

    Parameters
    ----------
    tau0 : float or array
        Critical shear stress tau_0 [Pa] (> 0).
    z0 : float or array
        Its depth Z_0 [m] (> 0).
    a_transverse : float or array
        Contact semi-axis transverse to rolling [m].
    track_radius : float or array
        Radius of the rolling track on the body [m].
    K, c, h, e : float
        Life constant, stress, depth and Weibull exponents.
    unit_basis : str
        Basis of K: ``"SI"`` (Pa, m; default) or ``"US"`` (psi, inch); see the module docstring.

    Returns
    -------
    float or ndarray
        L10 [stress cycles] (= 10^6 H_10 of Eq. 5.16).
    """
    _check_constants("lundberg_palmgren_life", K=K, c=c, h=h, e=e)
    log_k = math.log(K) + _log_unit_factor("lundberg_palmgren_life", unit_basis, c, h)
    v = _positive("lundberg_palmgren_life", tau0=tau0, z0=z0, a_transverse=a_transverse, track_radius=track_radius)
    log_volume = math.log(2.0 * math.pi) + np.log(v["track_radius"]) + np.log(v["a_transverse"]) + np.log(v["z0"])
    log_h10 = (log_k + h * np.log(v["z0"]) - c * np.log(v["tau0"]) - log_volume) / e
    return float_or_array(np.exp(log_h10 + math.log(1e6)))


def life_time(cycles, cycles_per_revolution, speed):
    """Operating time [s] to accumulate ``cycles`` stress cycles (Saccheto Eq. 5.18 in SI).

    .. math::
        t = \\frac{L}{c_r\\, n}

    Parameters
    ----------
    cycles : float or array
        Life [stress cycles].
    cycles_per_revolution : float or array
        c_r, stress cycles per revolution of the reference shaft [-] (e.g. 9 balls passing a
        cone track per cone revolution, 1 per ball revolution on a ball track).
    speed : float or array
        n, speed of that shaft [rev/s].
    """
    v = _positive("life_time", cycles=cycles, cycles_per_revolution=cycles_per_revolution, speed=speed)
    return float_or_array(v["cycles"] / (v["cycles_per_revolution"] * v["speed"]))


def system_life(lives, e: float = ELLIPTICAL_E, *, axis: int = 0):
    """Weibull combination of contact lives, H = (sum H_i^-e)^(-1/e) (Saccheto Eq. 5.20).

    Parameters
    ----------
    lives : array_like
        Lives H_i of the contacts [s or revolutions of one shaft], > 0, along ``axis``.
    e : float
        Weibull slope shared by the contacts (10/9 elliptical, 3/2 line as printed).

    Returns
    -------
    float or ndarray
        System life, in the unit of ``lives``; it is below the shortest contact life, and n
        equal lives H give H n^(-1/e).
    """
    _check_constants("system_life", e=e)
    v = _positive("system_life", lives=lives)["lives"]
    if v.ndim == 0:
        return float(v)
    # scale by the shortest life so that H_i^-e cannot overflow
    shortest = np.min(v, axis=axis, keepdims=True)
    total = np.sum((v / shortest) ** (-e), axis=axis, keepdims=True)
    return float_or_array(np.squeeze(shortest * total ** (-1.0 / e), axis=axis))


def _check_constants(where: str, **constants) -> None:
    for key, value in constants.items():
        low_ok = value >= 0.0 if key == "h" else value > 0.0
        if not (isinstance(value, (int, float, np.floating, np.integer)) and math.isfinite(value) and low_ok):
            raise InputError(f"{where}: {key} = {value!r}; allowed: finite and {'>= 0' if key == 'h' else '> 0'}")


@builtin
@attrs.frozen
class LundbergPalmgren(LifeModel):
    """Lundberg–Palmgren L10 of a traction contact, Coy et al. (1976) form (Saccheto Eqs. 5.13–5.25).

    Inputs (``requires``, SI): ``tau0`` critical shear stress [Pa] (the maximum orthogonal shear
    of Lundberg & Palmgren, or the Mohr maximum shear of Saccheto's simulation; see the module
    docstring and :func:`camcontact.contact.slice_stress.slice_extremum`), ``z0`` its
    depth [m], ``a_transverse`` contact semi-axis transverse to rolling [m], ``track_radius``
    radius of the rolling track on the body [m]. Optional input (``optional_requires``):
    ``stress_cycle_rate`` c_r n [1/s], stress cycles per second of the contact.

    Returns (``provides``): ``L10`` [stress cycles], ``stressed_volume`` V_z [m^3]; and, when
    ``stress_cycle_rate`` is given (``optional_provides``), ``L10h`` [s] = L10 / (c_r n)
    (operating time, held in seconds like every camcontact time; reports show hours).

    Parameters
    ----------
    K : float
        Life constant (default 1.428e95, Coy 1975, Eq. 5.17), > 0, in the units of ``unit_basis``.
    c : float
        Stress exponent (default 31/3), > 0.
    h : float
        Depth exponent (default 7/3), >= 0.
    e : float
        Weibull slope (default 10/9, elliptical; :meth:`line_contact` gives 3/2 as printed in
        Eq. 5.15), > 0.
    unit_basis : str
        Units K is given in (the sources do not state them): ``"SI"`` (default; tau_0 in Pa,
        lengths in m — the reading the plausibility of the lives supports, and camcontact's
        reading of the thesis so far) or ``"US"`` (psi, inch: 10^34.7 times longer lives with
        the default constants). H_10 is in millions of stress cycles in both; inputs stay SI.
    """

    name = "lundberg_palmgren"
    reference = ("Lundberg & Palmgren (1947); Coy, Loewenthal & Zaretsky (1976) NASA TN D-8362; "
                 "Saccheto (2008) Eqs. 5.13-5.20, 5.24-5.25 (K = 1.428e95; its units are unstated: "
                 "SI assumed on plausibility, psi/inch selectable)")
    requires = ("tau0", "z0", "a_transverse", "track_radius")
    optional_requires = ("stress_cycle_rate",)
    provides = ("L10", "stressed_volume")
    optional_provides = ("L10h",)

    K: float = number_field(default=K_COY, validators=[in_range(0.0, None, lower_inclusive=False)])
    c: float = number_field(default=C_STRESS, validators=[in_range(0.0, None, lower_inclusive=False)])
    h: float = number_field(default=H_DEPTH, validators=[in_range(0.0, None)])
    e: float = number_field(default=ELLIPTICAL_E, validators=[in_range(0.0, None, lower_inclusive=False)])
    unit_basis: str = attrs.field(default="SI", validator=one_of(*UNIT_BASES))

    @classmethod
    def line_contact(cls, **overrides: Any) -> LundbergPalmgren:
        """The model with Saccheto's line-contact slope e = 3/2 (Eq. 5.15)."""
        return cls(**{"e": LINE_E, **overrides})

    def life(self, tau0, z0, a_transverse, track_radius):
        """L10 [stress cycles] (see :func:`lundberg_palmgren_life`) with this model's constants."""
        return lundberg_palmgren_life(tau0, z0, a_transverse, track_radius, K=self.K, c=self.c, h=self.h, e=self.e,
                                      unit_basis=self.unit_basis)

    def system_life(self, lives, *, axis: int = 0):
        """Weibull combination of contact lives with this model's e (see :func:`system_life`)."""
        return system_life(lives, self.e, axis=axis)

    def evaluate(self, tau0, z0, a_transverse, track_radius, stress_cycle_rate=None):
        """L10 [cycles], stressed volume [m^3] and, with ``stress_cycle_rate`` [1/s], L10h [s]."""
        L10 = self.life(tau0, z0, a_transverse, track_radius)
        result = {"L10": L10, "stressed_volume": stressed_volume(z0, a_transverse, track_radius)}
        if stress_cycle_rate is not None:
            rate = _positive(f"life model {self.name!r}", stress_cycle_rate=stress_cycle_rate)["stress_cycle_rate"]
            result["L10h"] = float_or_array(np.asarray(L10) / rate)
        return result
