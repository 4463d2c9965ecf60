"""Stress steps: the field below a contact, the roughness stress and the yield and fatigue checks.

Line contact with friction: McEwen's closed form (:mod:`camcontact.contact.subsurface`); Delabenetta
(2021) Eqs. 7-10 and §4.1 for the raceway contact's constants and rules, Eq. 8 (after Seabra) for its
roughness stress and Johnson (1985) §13.2 for the pressure that flattens the roughness sinusoid; the
2-D slice through a CVT
contact (Saccheto 2008 §3.4) by :func:`camcontact.contact.slice_stress.slice_extremum`. Lengths [m],
stresses and pressures [Pa].
"""

from __future__ import annotations

import math

import numpy as np

from ..contact.roughness import sinusoid_full_contact_pressure
from ..contact.slice_stress import slice_extremum
from ..contact.subsurface import line_subsurface
from ..contact.subsurface_point import point_subsurface
from ..step_graph import step

__all__ = [
    "THESIS_STRESS", "ball_cone_slice_stresses", "line_subsurface_stresses", "most_loaded_subsurface", "point_subsurface_stresses",
    "raceway_checks", "raceway_subsurface", "roughness_full_contact_pressure", "roughness_stress",
    "roughness_stress_step", "slice_through_centre",
]

LINE_SUBSURFACE = ("tau_max", "x_tau_max", "z_tau_max", "tresca_max", "z_tresca_max", "von_mises_max",
                   "z_von_mises_max", "tau_xz_max", "x_tau_xz_max", "z_tau_xz_max", "tau_xz_range")
#: Thesis stress constants (Delabenetta 2021 Eqs. 7, 9, 10)
THESIS_STRESS = {"tau_max": 0.30, "z_tau_max": 0.7861, "tau_oct": 0.27, "tau_xz": 0.25, "x_tau_xz": 0.85,
                 "z_tau_xz": 0.42}


@step("subsurface", provides=LINE_SUBSURFACE, model="mcewen_line")
def line_subsurface_stresses(b, p_h, nu1, friction_coefficient):
    """Extremes of the stress field below a line contact with surface friction (body 1):
    in-plane principal shear, Tresca, von Mises, the orthogonal shear and its range 2 tau_0 [Pa], with
    their positions [m]; from the half-width b [m], p_h [Pa], nu1 [-] and the friction coefficient [-]."""
    result = line_subsurface(b, p_h, friction=friction_coefficient, nu=nu1)
    return {
        "tau_max": result.principal_shear_max.value, "x_tau_max": result.principal_shear_max.x,
        "z_tau_max": result.principal_shear_max.z,
        "tresca_max": result.tresca_max.value, "z_tresca_max": result.tresca_max.z,
        "von_mises_max": result.von_mises_max.value, "z_von_mises_max": result.von_mises_max.z,
        "tau_xz_max": result.tau_xz_max.value, "x_tau_xz_max": result.tau_xz_max.x,
        "z_tau_xz_max": result.tau_xz_max.z, "tau_xz_range": result.orthogonal_shear_range,
    }


@step("subsurface", provides=("tau_max", "z_tau_max", "tresca_max", "tau_oct_max", "tau_xz_max", "x_tau_xz_max",
                              "z_tau_xz_max", "tau_xz_range"), model=lambda convention: convention.stress)
def raceway_subsurface(b, p_h, nu1, convention):
    """Frictionless subsurface stresses of the raceway contact: the thesis's constants (Eqs. 7, 9, 10,
    ``convention.stress == "thesis_constants"``) or the extremes of the exact field. From the half-width
    b [m], p_h [Pa] and nu1 [-]; stresses [Pa], positions [m]."""
    if convention.stress == "thesis_constants":
        c = THESIS_STRESS
        # the thesis's Z_0 = 78.12 um is 0.42 x a with a rounded to whole micrometres (erratum 4)
        # in plane strain the in-plane principal shear is the largest shear below the surface
        return {"tau_max": c["tau_max"] * p_h, "z_tau_max": c["z_tau_max"] * b, "tresca_max": c["tau_max"] * p_h,
                "tau_oct_max": c["tau_oct"] * p_h,
                "tau_xz_max": c["tau_xz"] * p_h, "x_tau_xz_max": c["x_tau_xz"] * b,
                "z_tau_xz_max": c["z_tau_xz"] * round(b * 1e6) * 1e-6, "tau_xz_range": 2.0 * c["tau_xz"] * p_h}
    field = line_subsurface(b, p_h, nu=nu1)
    return {"tau_max": field.principal_shear_max.value, "z_tau_max": field.principal_shear_max.z,
            "tresca_max": field.tresca_max.value,
            "tau_oct_max": math.sqrt(2.0) / 3.0 * field.von_mises_max.value,
            "tau_xz_max": field.tau_xz_max.value, "x_tau_xz_max": abs(field.tau_xz_max.x),
            "z_tau_xz_max": field.tau_xz_max.z, "tau_xz_range": field.orthogonal_shear_range}


@step("subsurface", provides=("tau_max", "z_tau_max"), model="mcewen_line")
def most_loaded_subsurface(Q, b_inner, b_outer, p_h_inner, p_h_outer, nu):
    """Largest principal shear tau_max [Pa] and its depth z_tau_max [m] below the most loaded raceway
    contact of a bearing (frictionless); zero when no roller is loaded. Inputs per roller: loads Q [N],
    half-widths b_inner, b_outer [m], Hertz pressures p_h_inner, p_h_outer [Pa]; nu [-]."""
    if not np.any(Q > 0.0):
        return {"tau_max": 0.0, "z_tau_max": 0.0}
    b, p_h = {"inner": b_inner, "outer": b_outer}, {"inner": p_h_inner, "outer": p_h_outer}
    race = "inner" if np.nanmax(p_h_inner) >= np.nanmax(p_h_outer) else "outer"
    j = int(np.nanargmax(p_h[race]))
    stresses = line_subsurface(b[race][j], p_h[race][j], nu=nu)
    return {"tau_max": stresses.principal_shear_max.value, "z_tau_max": stresses.principal_shear_max.z}


def roughness_stress(amplitude: float, wavelength: float, R_x: float, a: float, p0: float) -> float:
    """Stress due to a sinusoidal roughness [Pa]: 5.172 ((amp/lambda)(R_x/a))^0.931 p0
    (Delabenetta 2021 Eq. 8, after Seabra 2003; R_x = 2R', a the Hertz half-width)."""
    return 5.172 * ((amplitude / wavelength) * (R_x / a)) ** 0.931 * p0


@step("roughness_stress", provides=("tau_roughness",), model="seabra_eq8")
def roughness_stress_step(roughness_amplitude, roughness_wavelength, R_x, b, p_h):
    """The roughness stress [Pa] of the raceway contact (:func:`roughness_stress`) with the amplitude
    [m] of the convention (sigma / sqrt 2 in the thesis's reading, sqrt 2 sigma for a sinusoid of RMS
    sigma: the stress then rises by 2^0.931)."""
    return {"tau_roughness": roughness_stress(roughness_amplitude, roughness_wavelength, R_x, b, p_h)}


@step("roughness_contact", provides=("p_full_contact_roughness",), model="johnson_wavy_surface")
def roughness_full_contact_pressure(roughness_amplitude, roughness_wavelength, E_star):
    """Mean pressure [Pa] that flattens the roughness sinusoid (amplitude [m], wavelength [m]) completely,
    p* = pi E* A / lambda with E* = E'/2 [Pa] (Johnson 1985 §13.2,
    :func:`camcontact.contact.roughness.sinusoid_full_contact_pressure`); to set against the Hertz
    pressure: below p* the roughness is not flattened."""
    return {"p_full_contact_roughness": sinusoid_full_contact_pressure(roughness_amplitude, roughness_wavelength,
                                                                       E_star)}


@step("checks", provides=("yield_check", "fatigue_check"), model=lambda convention: convention.yield_rule)
def raceway_checks(tau_max, tresca_max, tau_xz_range, yield_strength, convention):
    """The plastic-deformation and fatigue rules of Delabenetta (2021) §4.1: tau_max against the yield
    strength (the thesis) or the Tresca shear against half of it; fatigue when 2 tau_0 > sigma_y.
    Stresses and yield strength in [Pa]; the verdicts as text (in MPa)."""
    if convention.yield_rule == "thesis":
        shear, limit, label = tau_max, yield_strength, "tau_max vs sigma_y (thesis §4.1)"
    else:
        shear = tresca_max
        limit, label = 0.5 * yield_strength, "Tresca: tau_max vs sigma_y / 2"
    plastic = "plastic deformation" if shear >= limit else "no plastic deformation"
    fatigue = ("fatigue probable (2 tau_0 > sigma_y, thesis §4.1 rule)" if tau_xz_range > yield_strength
               else "no fatigue by the thesis's rule (2 tau_0 <= sigma_y)")
    return {"yield_check": f"{plastic}: {shear * 1e-6:.4g} MPa vs {limit * 1e-6:.4g} MPa ({label})",
            "fatigue_check": f"{fatigue}: 2 tau_0 = {tau_xz_range * 1e-6:.4g} MPa, sigma_y = "
                             f"{yield_strength * 1e-6:.4g} MPa"}


def slice_through_centre(a_rolling: float, p_h: float, result, measure: str):
    """tau0 [Pa] and z0 [m] of the 2-D slice through a contact's centre along rolling (Saccheto 2008 §3.4):
    Hertz pressure (``p_h`` [Pa], semi-axis ``a_rolling`` [m]) on the centre line and the traction ratio
    Tx/p of the traction model's central strip (``result``: a FASTSIM result, or the EHL model's
    :class:`~camcontact.contact.spin_traction.CentreLineTraction`)."""
    a, p0 = a_rolling, p_h
    j = int(np.argmin(np.abs(result.y)))
    x_strip = result.x[j][::-1]  # FASTSIM marches from the leading edge (+a) to the trailing edge
    ratio = np.divide(result.Tx[j], result.p[j], out=np.zeros_like(result.Tx[j]), where=result.p[j] > 0)[::-1]
    nodes = np.concatenate(([-a], np.clip(x_strip, -a, a), [a]))
    keep = np.concatenate(([True], np.diff(nodes) > 0))
    nodes = nodes[keep]
    pressure = p0 * np.sqrt(np.clip(1.0 - (nodes / a) ** 2, 0.0, None))
    traction = np.concatenate(([0.0], ratio, [0.0]))[keep] * pressure
    x = np.linspace(-1.3 * a, 1.3 * a, 53)
    z = np.linspace(0.02 * a, 1.5 * a, 37)
    return slice_extremum(nodes, pressure, traction, measure=measure, x=x, z=z)


@step("stresses", provides=("tau0_in", "z0_in", "tau0_out", "z0_out"),
      model=lambda stress_measure: f"slice_2d ({stress_measure})")
def ball_cone_slice_stresses(a_rolling, p_h, surface_traction_in, surface_traction_out, stress_measure):
    """tau0 [Pa] and its depth z0 [m] at the CVT's input and output contact (:func:`slice_through_centre`;
    ``stress_measure`` "max_shear", the Mohr radius the thesis's simulation used, or "orthogonal")."""
    out = {}
    for side, result in (("in", surface_traction_in), ("out", surface_traction_out)):
        extremum = slice_through_centre(a_rolling, p_h, result, stress_measure)
        out[f"tau0_{side}"], out[f"z0_{side}"] = extremum.tau0, extremum.z0
    return out


@step("subsurface", provides=("tresca_max", "z_tresca_max", "von_mises_max", "z_von_mises_max"),
      model="boussinesq_axis")
def point_subsurface_stresses(a_rolling, a_transverse, p_h, nu1):
    """The largest principal (Tresca) shear and von Mises stress [Pa] below a frictionless elliptical Hertz
    contact and their depths [m] (:func:`~camcontact.contact.subsurface_point.point_subsurface`: Boussinesq's
    stresses integrated over the Hertz pressure on the axis; Johnson 1985 Eqs. 3.19, 3.45), from the
    semi-axes [m], p_h [Pa] and body 1's Poisson ratio nu1 [-]."""
    found = point_subsurface(a_rolling, a_transverse, p_h, nu1)
    return {"tresca_max": found.tresca_max, "z_tresca_max": found.z_tresca_max,
            "von_mises_max": found.von_mises_max, "z_von_mises_max": found.z_von_mises_max}
