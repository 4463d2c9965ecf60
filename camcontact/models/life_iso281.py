"""Rating life of a radial roller (or ball) bearing after ISO 281:2007: L10, a1, kappa, a_ISO, L_nm.

Ball bearings (``ISO281(rolling_element="ball")``): L10 = (C/P)^3 and a_ISO of radial ball bearings
(:mod:`camcontact.models.iso281_ball`, which also gives their C_r and P); the rest as below.

* Basic rating life L10 = (C/P)^(10/3) [10^6 revolutions]; L10h = 10^6 L10 / (60 n) [h] (held in
  seconds, SI, like every camcontact value; reports show hours).
* Dynamic equivalent load of a radial roller bearing with contact angle alpha != 0 (spherical
  roller bearings): e = 1.5 tan(alpha); P = F_r + Y1 F_a for F_a/F_r <= e (Y1 = 0.45 cot alpha),
  P = 0.67 F_r + Y2 F_a otherwise (Y2 = 0.67 cot alpha); catalogue values of e, Y1, Y2 replace them
  when given (SKF's spherical-roller-bearing tables list them per bearing).
* Reliability factor a1 of ISO 281:2007 Table 12 (90 % ... 99.95 %); between the tabulated
  reliabilities the Weibull form behind the table, a1 = 0.95 (ln(100/R)/ln(100/90))^(2/3) + 0.05
  (slope 1.5, minimum life 0.05 L10), which rounds to every tabulated value.
* Rated viscosity nu1 = 45000 n^-0.83 d_m^-0.5 (n < 1000 r/min) or 4500 n^-0.5 d_m^-0.5
  (n >= 1000 r/min) [mm^2/s, r/min, mm]; kappa = nu / nu1, used up to 4, below 0.1 not covered.
* Life modification factor of radial roller bearings
  a_ISO = 0.1 [1 - (1.5859 - c2 / kappa^c3) (e_C C_u / P)^0.4]^-9.185 with
  (c2, c3) = (1.3993, 0.054381) for 0.1 <= kappa < 0.4, (1.2348, 0.19087) for 0.4 <= kappa < 1 and
  (1.2348, 0.071739) for 1 <= kappa <= 4; capped at 50. L_nm = a1 a_ISO L10.

Sources: ISO 281:2007 (L10, the dynamic equivalent load, Table 12, the nu1 relations and a_ISO of
radial roller bearings); the SKF Rolling bearings catalogue ("Basic rating life"; "Loads" of
spherical roller bearings) and its worked example "Vibrating screen" (tested). The reference
folder holds no ISO 281 data: Delabenetta (2021) computes no life (reference §2.14). The a_ISO
constants are continuous across the kappa bands to 1e-6 (tested). SKF's own kappa uses a revised
nu1 diagram and its a_SKF is not a_ISO.
"""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..errors import InputError
from ..units import in_range, number_field, one_of
from .base import LifeModel, builtin

__all__ = ["A_ISO_FORMS", "ISO281", "a_iso", "a_iso_ball", "a_iso_roller", "equivalent_load", "rated_viscosity",
           "reliability_factor"]

#: ISO 281:2007 Table 12: reliability [%] -> a1
A1_TABLE = {90.0: 1.0, 95.0: 0.64, 96.0: 0.55, 97.0: 0.47, 98.0: 0.37, 99.0: 0.25, 99.2: 0.22, 99.4: 0.19,
            99.6: 0.16, 99.8: 0.12, 99.9: 0.093, 99.92: 0.087, 99.94: 0.08, 99.95: 0.077}
#: a_ISO of radial roller bearings: (lower kappa, c2, c3) per band
A_ISO_BANDS = ((0.1, 1.3993, 0.054381), (0.4, 1.2348, 0.19087), (1.0, 1.2348, 0.071739))
A_ISO_CAP = 50.0
LIFE_EXPONENT = 10.0 / 3.0


def equivalent_load(radial: float, axial: float, contact_angle: float, e: float | None = None,
                    Y1: float | None = None, Y2: float | None = None) -> float:
    """Dynamic equivalent load P [N] of a radial roller bearing (alpha != 0) from F_r, F_a [N]."""
    if radial < 0.0 or not math.isfinite(radial) or not math.isfinite(axial):
        raise InputError(f"equivalent_load: radial = {radial!r} N, axial = {axial!r} N; allowed: finite, radial >= 0")
    if not 0.0 < contact_angle < 0.5 * math.pi:
        raise InputError(f"equivalent_load: contact_angle = {contact_angle!r} rad; allowed 0 < alpha < pi/2")
    cot = 1.0 / math.tan(contact_angle)
    e = 1.5 * math.tan(contact_angle) if e is None else e
    Y1 = 0.45 * cot if Y1 is None else Y1
    Y2 = 0.67 * cot if Y2 is None else Y2
    axial = abs(axial)
    if radial == 0.0 or axial / radial > e:
        return 0.67 * radial + Y2 * axial
    return radial + Y1 * axial


def reliability_factor(reliability: float) -> float:
    """a1 for a reliability [%] in 90..99.95 (ISO 281:2007 Table 12, its Weibull form between)."""
    if not (90.0 <= reliability <= 99.95):
        raise InputError(f"reliability = {reliability!r} %; ISO 281 covers 90 <= reliability <= 99.95 %")
    if reliability in A1_TABLE:
        return A1_TABLE[reliability]
    return 0.95 * (math.log(100.0 / reliability) / math.log(100.0 / 90.0)) ** (2.0 / 3.0) + 0.05


def rated_viscosity(speed_rpm: float, pitch_diameter_mm: float) -> float:
    """nu1 [mm^2/s] for the speed n [r/min] and pitch diameter d_m [mm] (ISO 281:2007)."""
    if not (speed_rpm > 0.0 and pitch_diameter_mm > 0.0):
        raise InputError(f"rated_viscosity: speed = {speed_rpm!r} r/min, d_m = {pitch_diameter_mm!r} mm; "
                         "both must be > 0")
    if speed_rpm < 1000.0:
        return 45000.0 * speed_rpm**-0.83 * pitch_diameter_mm**-0.5
    return 4500.0 * speed_rpm**-0.5 * pitch_diameter_mm**-0.5


#: a_ISO = 0.1 [1 - (base - c2 / kappa^c3)^e1 (e_C C_u / P)^e2]^e3 per rolling element: (base, bands, e1, e2, e3)
A_ISO_FORMS = {"roller": (1.5859, A_ISO_BANDS, 1.0, 0.4, -9.185),
               "ball": (2.5671, ((0.1, 2.2649, 0.054381), (0.4, 1.9987, 0.19087), (1.0, 1.9987, 0.071739)),
                        0.83, 1.0 / 3.0, -9.3)}


def a_iso(kappa: float, contamination_load_ratio: float, rolling_element: str = "roller") -> float:
    """a_ISO of a radial roller or ball bearing (ISO 281:2007 Eqs. 31-36: :data:`A_ISO_FORMS`) for kappa and
    e_C C_u / P (capped at 50). kappa above 4 counts as 4; below 0.1 ISO 281 gives no factor: InputError."""
    if not math.isfinite(kappa) or kappa < 0.1:
        raise InputError(f"a_ISO: kappa = {kappa!r} is below 0.1, where ISO 281 gives no life modification "
                         "factor (the lubricant is too thin for the speed: raise its viscosity or check nu1)")
    if not (contamination_load_ratio >= 0.0 and math.isfinite(contamination_load_ratio)):
        raise InputError(f"a_ISO: e_C C_u / P = {contamination_load_ratio!r}; allowed: finite and >= 0")
    base, bands, e1, e2, e3 = A_ISO_FORMS[rolling_element]
    kappa = min(kappa, 4.0)
    c2, c3 = next((c2, c3) for low, c2, c3 in reversed(bands) if kappa >= low)
    bracket = 1.0 - (base - c2 / kappa**c3) ** e1 * contamination_load_ratio**e2
    if bracket <= 0.0:
        return A_ISO_CAP
    return min(0.1 * bracket**e3, A_ISO_CAP)


def a_iso_roller(kappa: float, contamination_load_ratio: float) -> float:
    """a_ISO of a radial roller bearing (:func:`a_iso`)."""
    return a_iso(kappa, contamination_load_ratio, "roller")


def a_iso_ball(kappa: float, contamination_load_ratio: float) -> float:
    """a_ISO of a radial ball bearing (:func:`a_iso`): 0.1 [1 - (2.5671 - c2 / kappa^c3)^0.83 (e_C C_u / P)^(1/3)]^-9.3
    with (c2, c3) = (2.2649, 0.054381) for 0.1 <= kappa < 0.4, (1.9987, 0.19087) for 0.4 <= kappa < 1 and
    (1.9987, 0.071739) for 1 <= kappa <= 4 (ISO 281:2007 Eqs. 31-33, as transcribed in independent public
    implementations; the 0.019087 some codes carry is not continuous at kappa = 0.4)."""
    return a_iso(kappa, contamination_load_ratio, "ball")


#: L10 exponent p of ISO 281 per rolling element
LIFE_EXPONENTS = {"roller": LIFE_EXPONENT, "ball": 3.0}


@builtin
@attrs.frozen
class ISO281(LifeModel):
    """Modified rating life of a radial roller (or ball) bearing, ISO 281:2007 (L10, a1, kappa, a_ISO, L_nm).

    Inputs (``requires``, SI): ``C`` dynamic load rating [N], ``P`` dynamic equivalent load [N],
    ``speed`` inner-ring speed [1/s] (revolutions per second), ``pitch_diameter`` d_m [m],
    ``viscosity`` kinematic viscosity of the (base) oil at the operating temperature [m^2/s],
    ``fatigue_load_limit`` C_u [N]. Returns ``L10`` and ``L_nm`` [revolutions], ``L10h`` and
    ``L_nmh`` [s] (operating time; reports show hours), ``a1``, ``nu1`` [m^2/s], ``kappa``, ``a_ISO``.

    Parameters
    ----------
    reliability : float
        Required reliability [%] (90..99.95; 90 gives a1 = 1).
    contamination : float
        e_C, the contamination factor (0 < e_C <= 1; 1 = extreme cleanliness).
    rolling_element : str
        "roller" (default: L10 = (C/P)^(10/3), a_ISO of roller bearings) or "ball" (L10 = (C/P)^3, a_ISO of
        ball bearings, :func:`a_iso_ball`).
    """

    name = "iso281"
    reference = "ISO 281:2007, L10 = (C/P)^(10/3), Table 12 (a1), nu1, a_ISO of radial roller bearings"
    requires = ("C", "P", "speed", "pitch_diameter", "viscosity", "fatigue_load_limit")
    provides = ("L10", "L10h", "a1", "nu1", "kappa", "a_ISO", "L_nm", "L_nmh")

    reliability: float = number_field(default=90.0, validators=[in_range(90.0, 99.95)])
    contamination: float = number_field(default=1.0, validators=[in_range(0.0, 1.0, lower_inclusive=False)])
    rolling_element: str = attrs.field(default="roller", validator=one_of(*LIFE_EXPONENTS))

    def evaluate(self, C, P, speed, pitch_diameter, viscosity, fatigue_load_limit):
        """Rating lives and factors (see the class docstring) for SI inputs."""
        values = {"C": C, "P": P, "speed": speed, "pitch_diameter": pitch_diameter, "viscosity": viscosity,
                  "fatigue_load_limit": fatigue_load_limit}
        for key, value in values.items():
            if value is None or not (np.isfinite(value) and value > 0.0):
                raise InputError(f"life model 'iso281': {key} = {value!r}; needs a finite value > 0")
        L10 = (C / P) ** LIFE_EXPONENTS[self.rolling_element] * 1e6
        rpm = 60.0 * speed
        nu1 = rated_viscosity(rpm, 1e3 * pitch_diameter) * 1e-6
        kappa = viscosity / nu1
        a1 = reliability_factor(self.reliability)
        a_iso_value = a_iso(kappa, self.contamination * fatigue_load_limit / P, self.rolling_element)
        L_nm = a1 * a_iso_value * L10
        return {"L10": L10, "L10h": L10 / speed, "a1": a1, "nu1": nu1, "kappa": kappa, "a_ISO": a_iso_value,
                "L_nm": L_nm, "L_nmh": L_nm / speed}
