"""Temperature steps of a raceway contact: Blok's flash temperature, the surface maximum, the viscosity at
the mean pressure and the Couette film rise (Delabenetta 2021 Eqs. 47, 48 and Appendix D).

Temperatures [K], viscosities [Pa s], pressures [Pa], speeds [m/s]; the convention object
(:class:`camcontact.scenes.raceway_conventions.RacewayConvention`) decides the thesis's log10 Roelands
form and whether the lubricant's maximum is absolute or a rise.
"""

from __future__ import annotations

import math

from ..contact.contact_temperature import couette_temperature_rise, flash_temperature
from ..models.viscosity_pressure import ROELANDS_P0, Roelands
from ..step_graph import step
from .raceway_film import CELSIUS

__all__ = ["raceway_temperatures"]


@step("temperatures", provides=("flash_temperature", "surface_temperature_max", "viscosity_at_mean_pressure",
                                "film_temperature_rise", "lubricant_temperature_max", "lubricant_temperature_check"),
      model="blok_couette")
def raceway_temperatures(w, E_reduced, R, friction_coefficient, u_raceway, u_roller, effusivity, eta0, alpha,
                         roelands_z, p_mean, thermoviscous_coefficient, lubricant_conductivity,
                         lubricant_pressure_state, temperature, upper_temperature, convention):
    """Flash temperature (0 at pure rolling: no frictional heat), surface maximum, viscosity at the mean
    pressure (the thesis's log10 Roelands form with its constant, or the lubricant's law), the Couette
    rise across the film and the lubricant's maximum temperature against ``upper_temperature`` [K]
    (None: not given), as text."""
    mu = friction_coefficient
    sliding = abs(u_raceway - u_roller)
    if math.isnan(mu):  # pure rolling: no frictional heat in these models (mu |du| -> 0)
        flash = 0.0
    else:
        flash = flash_temperature(w, E_reduced, R, mu, u_raceway, u_roller, *effusivity)
    if convention.roelands_log10_constant is not None:
        c = convention.roelands_log10_constant
        eta_p = 10.0 ** ((math.log10(eta0) + c) * (1.0 + p_mean / ROELANDS_P0) ** roelands_z - c)
    elif lubricant_pressure_state is not None:
        eta_p = float(lubricant_pressure_state.viscosity(p_mean))
    else:
        eta_p = float(Roelands().viscosity(p_mean, eta0, alpha))
    rise = couette_temperature_rise(thermoviscous_coefficient, sliding, eta_p, lubricant_conductivity)
    surface = temperature + flash
    lubricant_max = surface + rise if convention.absolute_lubricant_temperature else CELSIUS + rise
    if upper_temperature is None:
        check = "no upper service temperature given"
    else:
        label = "T_smax + rise" if convention.absolute_lubricant_temperature else "the rise, as the thesis"
        verdict = "exceeds" if lubricant_max > upper_temperature else "within"
        check = (f"{verdict} the upper service temperature {upper_temperature - CELSIUS:.4g} °C by "
                 f"{abs(lubricant_max - upper_temperature):.3g} K ({label})")
    return {"flash_temperature": flash, "surface_temperature_max": surface, "viscosity_at_mean_pressure": eta_p,
            "film_temperature_rise": rise, "lubricant_temperature_max": lubricant_max,
            "lubricant_temperature_check": check}
