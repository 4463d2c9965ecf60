"""The two conventions of the single roller-raceway contact analysis: the thesis's and the corrected.

Delabenetta (2021) assesses one roller / outer-ring contact in closed form (reference
``spherical_roller_bearing_delabenetta2021.md``). Its tables follow from choices, some
undocumented and some wrong, that the reference lists (§5.2, §6). A :class:`RacewayConvention`
holds each such choice as a switch, so that

* ``"thesis"`` (:data:`THESIS`) reproduces the thesis's Tables 5, 7 and 8 to the printed digits,
* ``"corrected"`` (:data:`CORRECTED`) fixes the modelling errors, and
* any single switch can be flipped (``attrs.evolve(THESIS, roughness_factor=1.0)``) to see what
  one choice does to the conclusion.

==============================  ===========================  ===========================  ========
switch                          thesis                       corrected                    erratum
==============================  ===========================  ===========================  ========
convex_raceway                  True (curvatures summed)     False (outer race concave)   2
derive_rolling_speed            False (catalogue speed)      True (pure rolling)          27
temperature_loop                True (84.9 °C from 85 °C)    False                        28, §5.2
celsius_offset                  273.0                        273.15                       28
lubricant_data                  "thesis" (mineral C_alpha)   "lubricant" (its own laws)   §5.2
grubin_exponent_digits          3 (0.727, 0.091)             None (8/11, 1/11)            12
starvation_factor               1.0                          None (grease 0.7, oil 1.0)   13
roughness_factor                2.0 ("gamma = 2")            1.0                          13
roughness_amplitude             "thesis" (sigma/sqrt 2)      "sinusoid" (sqrt 2 sigma)    Eq. 30
roelands_log10_constant         4.2 (the code's log10 form)  None (ln form, 9.67)         §2.10
stress                          "thesis_constants"           "field"                      4
yield_rule                      "thesis" (tau vs sigma_y)    "tresca" (tau vs sigma_y/2)  5
absolute_lubricant_temperature  False (a rise as "T_maxL")   True (T_smax + rise)         15
==============================  ===========================  ===========================  ========
"""

from __future__ import annotations

from typing import Any

import attrs

from ..errors import InputError
from ..units import one_of

__all__ = ["CONVENTIONS", "CORRECTED", "THESIS", "RacewayConvention", "resolve_convention"]


@attrs.frozen(kw_only=True)
class RacewayConvention:
    """The modelling choices of the single-contact chain (see the module table).

    Parameters
    ----------
    name : str
    convex_raceway : bool
        Treat the raceway as convex whatever its side (the thesis sums the curvatures of the roller
        and the outer ring, Eq. 1).
    derive_rolling_speed : bool
        True: surface speeds of pure rolling in the cage frame, u = (pi d_m / 2)(1 - gamma^2) n with
        the contact's ``slide_roll_ratio``; False: ring surface speed R1 * ring_speed and roller
        surface speed R2 * roller_speed, both in the ground frame, as the thesis (Eq. 31).
    temperature_loop : bool
        Run the thesis's loop (Appendix D): T -= 0.1 K until Lambda > lambda_min.
    celsius_offset : float
        Kelvin = °C + offset in the viscosity and thermoviscous laws (the thesis uses 273).
    lubricant_data : str
        ``"thesis"``: Walther through nu40 and nu100 (a = 0.7), the Gold alpha with the mineral-oil
        constant for every oil, conductivity and specific heat from Eqs. 38-39; ``"lubricant"``: the
        Lubricant's own laws and data (Eqs. 38-39 only where it gives no conductivity or specific heat).
    grubin_exponent_digits : int or None
        Grubin exponents rounded to this many decimals (the thesis's Eq. 40 has 3), or exact.
    starvation_factor : float or None
        phi_A of Eq. 43; None: 0.7 for a grease, 1.0 for an oil (the thesis code's own comment).
    roughness_factor : float
        phi_R of Eq. 43 (the thesis reads 2 from a figure of the orientation parameter).
    roughness_amplitude : str
        Amplitude A of the sinusoid that stands for the composite roughness sigma in the roughness
        stress (Eq. 8) and Johnson's full-contact pressure: ``"thesis"``: A = sigma / sqrt 2, the
        thesis's reading (its Eq. 30; it reproduces its tau_max,r = 1.59 GPa); ``"sinusoid"``:
        A = sqrt 2 sigma, the amplitude of a sinusoid whose RMS is sigma (RMS of A cos x is
        A / sqrt 2), twice the thesis's value.
    roelands_log10_constant : float or None
        The thesis evaluates eta at the mean pressure as log10 eta_p = (log10 eta0 + c)(1 + p/p0)^Z - c
        with c = 4.2; None uses the lubricant's pressure-viscosity law.
    stress : str
        ``"thesis_constants"``: tau_max = 0.30 p0 at 0.7861 a, tau_oct = 0.27 p0, tau_xz = 0.25 p0 at
        (0.85 a, 0.42 a) with a rounded to whole micrometres (Eqs. 7, 9, 10; erratum 4);
        ``"field"``: extremes of the exact subsurface field.
    yield_rule : str
        ``"thesis"``: tau_max against the yield strength; ``"tresca"``: the Tresca shear against
        half of it.
    absolute_lubricant_temperature : bool
        False: report the Couette rise as the lubricant's maximum temperature, as the thesis
        (erratum 15); True: the surface maximum plus the rise.
    """

    name: str
    convex_raceway: bool
    derive_rolling_speed: bool
    temperature_loop: bool
    celsius_offset: float
    lubricant_data: str = attrs.field(validator=one_of("thesis", "lubricant"))
    grubin_exponent_digits: int | None
    starvation_factor: float | None
    roughness_factor: float
    roughness_amplitude: str = attrs.field(validator=one_of("thesis", "sinusoid"))
    roelands_log10_constant: float | None
    stress: str = attrs.field(validator=one_of("thesis_constants", "field"))
    yield_rule: str = attrs.field(validator=one_of("thesis", "tresca"))
    absolute_lubricant_temperature: bool

    def __attrs_post_init__(self) -> None:
        for field in ("starvation_factor", "roughness_factor"):
            value = getattr(self, field)
            if value is not None and not value > 0.0:
                raise InputError(f"RacewayConvention.{field} = {value!r}; allowed > 0")


THESIS = RacewayConvention(
    name="thesis", convex_raceway=True, derive_rolling_speed=False, temperature_loop=True, celsius_offset=273.0,
    lubricant_data="thesis", grubin_exponent_digits=3, starvation_factor=1.0, roughness_factor=2.0,
    roughness_amplitude="thesis", roelands_log10_constant=4.2, stress="thesis_constants", yield_rule="thesis",
    absolute_lubricant_temperature=False,
)
CORRECTED = RacewayConvention(
    name="corrected", convex_raceway=False, derive_rolling_speed=True, temperature_loop=False,
    celsius_offset=273.15, lubricant_data="lubricant", grubin_exponent_digits=None, starvation_factor=None,
    roughness_factor=1.0, roughness_amplitude="sinusoid", roelands_log10_constant=None, stress="field",
    yield_rule="tresca", absolute_lubricant_temperature=True,
)
CONVENTIONS = {"thesis": THESIS, "corrected": CORRECTED}


def resolve_convention(spec: Any) -> RacewayConvention:
    """A convention from its name or as given (a :class:`RacewayConvention`)."""
    if isinstance(spec, RacewayConvention):
        return spec
    if isinstance(spec, str) and spec in CONVENTIONS:
        return CONVENTIONS[spec]
    raise InputError(f"raceway_contact scene: convention {spec!r}; allowed: {', '.join(map(repr, CONVENTIONS))} "
                     "or a RacewayConvention")
