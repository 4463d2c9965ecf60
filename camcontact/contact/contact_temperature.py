"""Contact temperatures of a line contact: Blok/Jaeger flash temperature and the Couette film rise.

* Flash temperature of a band heat source of half-width b moving over both surfaces
  (Delabenetta 2021 Eq. 48, after Blok; reference §2.10):

  .. math:: T_F = 0.893\\left(\\frac{F_n}{l}\\right)^{3/4}\\left(\\frac{E^*}{R_x}\\right)^{1/4}
            \\frac{\\mu\\,|u_1 - u_2|}{e_1\\sqrt{u_1} + e_2\\sqrt{u_2}}

  with the thesis's Seabra conventions E* = E'/2 and R_x = 2R', i.e. E*/R_x = E'/(4R'), and the
  thermal effusivities e_i = sqrt(rho_i c_i k_i) (Eq. 50). The text prints |u + u2|; its code and
  tables use |u1 - u2| (reference erratum 14).
* Temperature rise in the middle of a Couette film with an exponential viscosity–temperature law
  (Delabenetta 2021 App. D, "Tfmax"):

  .. math:: \\Delta T_f = \\frac{1}{\\beta}\\ln\\left(\\frac{\\beta\\,(u_1 - u_2)^2\\,\\eta_p}{8k} + 1\\right)

  a rise above the surface temperature; the thesis reports it as the lubricant's maximum
  temperature "T_maxL" and compares it with the grease's absolute service limit (erratum 15):
  the absolute maximum is the surface maximum plus this rise.
"""

from __future__ import annotations

import math

from ..errors import InputError

__all__ = ["band_flash_per_flux", "couette_temperature_rise", "flash_temperature"]


def flash_temperature(w: float, E_reduced: float, R: float, mu: float, u1: float, u2: float,
                      effusivity1: float, effusivity2: float) -> float:
    """Flash temperature T_F [K] for load per length w [N/m], E' [Pa], R' [m], friction mu [-],
    surface speeds u1, u2 [m/s] (>= 0) and effusivities [W s^0.5/(m^2 K)] (Delabenetta Eq. 48)."""
    for name, value in (("w", w), ("E_reduced", E_reduced), ("R", R), ("effusivity1", effusivity1),
                        ("effusivity2", effusivity2)):
        if not (math.isfinite(value) and value > 0.0):
            raise InputError(f"flash_temperature: {name} = {value!r}; allowed > 0")
    if u1 < 0.0 or u2 < 0.0 or u1 + u2 == 0.0 or not (math.isfinite(u1) and math.isfinite(u2)):
        raise InputError(f"flash_temperature: u1 = {u1!r}, u2 = {u2!r} m/s; allowed: >= 0, not both 0")
    if not (math.isfinite(mu) and mu >= 0.0):
        raise InputError(f"flash_temperature: mu = {mu!r}; allowed >= 0")
    return (0.893 * w**0.75 * (E_reduced / (4.0 * R)) ** 0.25 * mu * abs(u1 - u2)
            / (effusivity1 * math.sqrt(u1) + effusivity2 * math.sqrt(u2)))


def band_flash_per_flux(half_width: float, u1: float, u2: float, effusivity1: float, effusivity2: float) -> float:
    """Maximum (exit) flash temperature per unit heat flux [K m^2/W] of a uniform band source of
    half-width a [m] moving at high Peclet number through two surfaces at u1, u2 [m/s] with Blok's
    partition (equal surface temperatures): 2 sqrt(2a/pi) / (e1 sqrt(u1) + e2 sqrt(u2)) (Jaeger 1942,
    Blok 1937). It is the source behind :func:`flash_temperature`: with q = mu p_mean |u1 - u2| and
    p_mean = w/(2a) the two agree to the rounding of Delabenetta's 0.893 (2 sqrt(2/pi) = 1.59577 against
    0.893 x 2^(3/4) x 4^(1/4) / pi^(1/4) = 1.59533). Usable where the surfaces roll at equal speed
    (spin and creep losses), where the flux is not mu p |u1 - u2|."""
    for name, value in (("half_width", half_width), ("effusivity1", effusivity1), ("effusivity2", effusivity2)):
        if not (math.isfinite(value) and value > 0.0):
            raise InputError(f"band_flash_per_flux: {name} = {value!r}; allowed > 0")
    if u1 < 0.0 or u2 < 0.0 or u1 + u2 == 0.0 or not (math.isfinite(u1) and math.isfinite(u2)):
        raise InputError(f"band_flash_per_flux: u1 = {u1!r}, u2 = {u2!r} m/s; allowed: >= 0, not both 0")
    return 2.0 * math.sqrt(2.0 * half_width / math.pi) / (effusivity1 * math.sqrt(u1) + effusivity2 * math.sqrt(u2))


def couette_temperature_rise(beta: float, sliding_speed: float, eta: float, conductivity: float) -> float:
    """Mid-film temperature rise [K] of a Couette film: ln(beta du^2 eta/(8k) + 1)/beta, with the
    thermoviscous coefficient beta [1/K], sliding speed du [m/s], viscosity eta [Pa*s] and the
    lubricant's conductivity k [W/(m K)]."""
    for name, value in (("beta", beta), ("eta", eta), ("conductivity", conductivity)):
        if not (math.isfinite(value) and value > 0.0):
            raise InputError(f"couette_temperature_rise: {name} = {value!r}; allowed > 0")
    if not math.isfinite(sliding_speed):
        raise InputError(f"couette_temperature_rise: sliding_speed = {sliding_speed!r}; must be finite")
    return math.log1p(beta * sliding_speed**2 * eta / (8.0 * conductivity)) / beta
