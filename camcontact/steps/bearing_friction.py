"""Bearing friction steps: the frictional moment and power of the whole bearing by the SKF model and by
Palmgren's, side by side, and the hydrodynamic rolling resistance of every roller's raceway contacts.

Models: :mod:`camcontact.models.bearing_friction` (SKF "Rolling bearings" 2012, "Friction"; Palmgren 1959
after Harris & Kotzalas 2007; Goksem & Hargreaves 1978). The power is the moment times the relative
angular speed of the rings, 2 pi |n_i - n_o|. Forces [N], moments [N m], powers [W], speeds [rev/s]
unless named otherwise, viscosity [m^2/s].
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from ..models.bearing_friction import (
    SKF_SERIES,
    palmgren_default_f0,
    palmgren_frictional_moment,
    rolling_resistance_line,
    skf_frictional_moment,
)
from ..step_graph import step
from .contact import RACES

__all__ = ["LUBRICATION_METHODS", "palmgren_friction_moment", "roller_rolling_resistance", "skf_friction_moment"]

#: the lubrication method each model assumes for a Lubricant.form: (SKF K_rs key, Palmgren f0 key); an
#: oil-lubricated bearing is taken as a low-level oil bath (SKF: no drag losses modelled)
LUBRICATION_METHODS = {"grease": ("grease", "grease"), "oil": ("oil_bath_low", "oil_bath")}


def _method(lubrication: str, model: int) -> str:
    if lubrication not in LUBRICATION_METHODS:
        raise InputError(f"bearing friction: lubrication = {lubrication!r} (Lubricant.form); allowed: "
                         f"{', '.join(LUBRICATION_METHODS)}")
    return LUBRICATION_METHODS[lubrication][model]


def _viscosity(kinematic_viscosity) -> float:
    if kinematic_viscosity is None:
        raise InputError("bearing friction: the lubricant's kinematic viscosity at the operating temperature is "
                         "unknown (give Lubricant.density or kinematic viscosity data), which the moment needs")
    return float(kinematic_viscosity)


@step("friction_moment_skf", provides=("friction_moment_skf", "friction_power_skf", "M_rr_skf", "M_sl_skf"),
      model="skf")
def skf_friction_moment(radial_load, axial_load, n_inner, n_outer, kinematic_viscosity, bore, outer_diameter,
                        bearing_series, lubrication, base_oil):
    """Frictional moment [N m] of the bearing by the SKF model, its rolling part phi_ish phi_rs M_rr and
    sliding part M_sl [N m], and the power M 2 pi |n_i - n_o| [W]; ``bearing_series`` one of the SKF
    series (SphericalRollerBearing.series), ``lubrication`` the Lubricant.form, ``base_oil`` its base oil."""
    if bearing_series is None:
        raise InputError(f"SphericalRollerBearing.series is not given; the SKF friction model needs it, one of "
                         f"{', '.join(SKF_SERIES)}")
    relative = abs(n_inner - n_outer)
    out = skf_frictional_moment(radial_load, axial_load, relative, _viscosity(kinematic_viscosity), bore,
                                outer_diameter, bearing_series, _method(lubrication, 0), base_oil)
    moment = out["friction_moment"]
    return {"friction_moment_skf": moment, "friction_power_skf": moment * 2.0 * math.pi * relative,
            "M_rr_skf": out["rolling_moment"], "M_sl_skf": out["sliding_moment"]}


@step("friction_moment_palmgren",
      provides=("friction_moment_palmgren", "friction_power_palmgren", "M0_palmgren", "M1_palmgren"),
      model="palmgren")
def palmgren_friction_moment(radial_load, axial_load, n_inner, n_outer, kinematic_viscosity, pitch_diameter,
                             contact_angle, lubrication):
    """Palmgren's frictional moment M = M0 + M1 [N m] of the bearing (f0 the middle of the spherical roller
    bearing's range for ``lubrication``, f1 = 0.00045), its parts and the power M 2 pi |n_i - n_o| [W]."""
    relative = abs(n_inner - n_outer)
    out = palmgren_frictional_moment(radial_load, axial_load, relative, _viscosity(kinematic_viscosity),
                                     pitch_diameter, contact_angle, palmgren_default_f0(_method(lubrication, 1)))
    moment = out["friction_moment"]
    return {"friction_moment_palmgren": moment, "friction_power_palmgren": moment * 2.0 * math.pi * relative,
            "M0_palmgren": out["load_independent_moment"], "M1_palmgren": out["load_moment"]}


@step("rolling_resistance", provides=("rolling_resistance_inner", "rolling_resistance_outer",
                                      "rolling_resistance_moment", "rolling_resistance_power"),
      model="goksem_hargreaves")
def roller_rolling_resistance(Q, u_m, eta0, alpha, piezoviscosity, E_reduced, contact_radii, contact_length_inner,
                              contact_length_outer, pitch_diameter, gamma):
    """Hydrodynamic rolling resistance F_R [N] of the inner and outer raceway contact of every loaded roller
    (Goksem & Hargreaves 1978, w = Q / l over each contact's length l [m]; NaN for unloaded rollers), the power sum(F_R u_m) [W] and the
    moment on the rings sum(F_R) d_m (1 - gamma^2) / 4 [N m] (power / relative angular speed, since
    u_m = (pi d_m / 2)(1 - gamma^2)|n_i - n_o|)."""
    if not piezoviscosity:
        raise InputError("rolling resistance: the Goksem-Hargreaves fit is for piezoviscous EHL films; switch the "
                         "'piezoviscosity' effect on")
    loaded = Q > 0.0
    out, total = {}, 0.0
    lengths = {"inner": contact_length_inner, "outer": contact_length_outer}
    for race in RACES:
        force = np.full(Q.size, np.nan)
        if loaded.any():
            length = lengths[race][loaded]
            force[loaded] = rolling_resistance_line(Q[loaded] / length, contact_radii[race], E_reduced, eta0,
                                                    alpha, u_m, length)
            total += float(np.sum(force[loaded]))
        out[f"rolling_resistance_{race}"] = force
    out["rolling_resistance_power"] = total * abs(u_m)
    out["rolling_resistance_moment"] = total * pitch_diameter * (1.0 - gamma**2) / 4.0
    return out
