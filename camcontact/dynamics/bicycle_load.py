"""The cyclist's load on a bicycle transmission (Saccheto 2008 §7.2, after Forti 2003).

Road-load power at speed V (Eq. 7.1):

.. math:: P = m g \\sin\\theta\\,V + m g f_0 \\cos\\theta\\,V + \\tfrac12 \\rho C_d A_f V^3

with the mass m of cyclist and bicycle, road slope theta, rolling-resistance coefficient f_0, air
density rho, drag coefficient C_d and frontal area A_f. The thesis gives m = 75 kg, C_d = 0.75-0.9
and a flat road; rho, A_f and f_0 are not given, so they are required arguments here.

The optimal pedalling cadence against power (Tabela 7.1, Forti 2003) is :data:`OPTIMAL_CADENCE`;
:func:`optimal_cadence` interpolates it linearly inside its range (122.6-245.1 W) and refuses to
extrapolate. The thesis runs its matrix at the reference input speed of 60 rpm.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError

__all__ = ["GRAVITY", "OPTIMAL_CADENCE", "cyclist_power", "optimal_cadence"]

GRAVITY = 9.80665  # m/s^2
#: Tabela 7.1: (power [W], optimal cadence [rpm])
OPTIMAL_CADENCE = ((122.6, 48.3), (163.4, 54.2), (196.1, 58.0), (204.2, 59.0), (245.1, 61.3))


def cyclist_power(speed: float, *, mass: float, rolling_resistance: float, drag_coefficient: float,
                  frontal_area: float, air_density: float, slope: float = 0.0) -> float:
    """Power [W] to ride at ``speed`` [m/s] (Eq. 7.1); mass [kg], slope [rad], the rest as in the module."""
    for label, value in (("speed", speed), ("mass", mass), ("rolling_resistance", rolling_resistance),
                         ("drag_coefficient", drag_coefficient), ("frontal_area", frontal_area),
                         ("air_density", air_density)):
        if not (math.isfinite(value) and value >= 0.0):
            raise InputError(f"cyclist_power: {label} = {value!r}; allowed: finite and >= 0")
    if not abs(slope) < 0.5 * math.pi:
        raise InputError(f"cyclist_power: slope = {slope!r} rad; allowed: |slope| < pi/2")
    weight = mass * GRAVITY
    return (weight * math.sin(slope) * speed + weight * rolling_resistance * math.cos(slope) * speed
            + 0.5 * air_density * drag_coefficient * frontal_area * speed**3)


def optimal_cadence(power: float) -> float:
    """Optimal cadence [rpm] at ``power`` [W], interpolated in Tabela 7.1 (122.6-245.1 W)."""
    powers, cadences = np.array(OPTIMAL_CADENCE).T
    if not powers[0] <= power <= powers[-1]:
        raise InputError(f"optimal_cadence: power = {power!r} W; Tabela 7.1 covers {powers[0]}-{powers[-1]} W")
    return float(np.interp(power, powers, cadences))
