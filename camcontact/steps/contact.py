"""Contact steps: reduced modulus and radius, Hertz pressure and half-width, elastic approach.

Hertz line contact after Johnson (1985) §4.3 (:func:`camcontact.contact.hertz_line.hertz_line`),
elliptical contact with exact elliptic integrals or the Hamrock–Brewe fits
(:func:`camcontact.contact.hertz_elliptical.hertz_elliptical`). Forces [N], loads per length
[N/m], radii [m], moduli and pressures [Pa].
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from ..contact.geometry import reduced_modulus, reduced_radius
from ..contact.hertz_elliptical import hertz_elliptical
from ..contact.hertz_line import hertz_line, line_approach
from ..errors import ValidityWarning
from ..step_graph import step

__all__ = [
    "APPROACHES", "EHL_PRESSURE", "RACES", "ball_cone_hertz", "cycle_hertz", "force_hertz", "hamrock_approach",
    "line_geometry", "line_hertz", "palmgren_approach", "point_geometry", "point_hertz", "raceway_geometry", "roller_hertz",
]

#: the raceways of a bearing, in the order of the per-race outputs
RACES = ("inner", "outer")
#: the pressure Saccheto (2008) §6.5 names as the threshold of EHL, after Dowson [Pa]
EHL_PRESSURE = 1.1e9


@step("geometry", provides=("E_reduced", "R"))
def line_geometry(E1, nu1, E2, nu2, R1, R2):
    """Reduced modulus E' = 2/[(1-nu1^2)/E1 + (1-nu2^2)/E2] [Pa] and radius 1/R = 1/R1 + 1/R2 [m]
    (signed radii: negative for a concave surface, ``inf`` for a flat one)."""
    return {"E_reduced": reduced_modulus(E1, nu1, E2, nu2), "R": reduced_radius(R1, R2)}


@step("geometry", provides=("E_reduced", "R", "E_star", "R_x"),
      model=lambda concave: f"{'concave' if concave else 'convex'} raceway")
def raceway_geometry(E1, nu1, E2, nu2, R1, R2, concave):
    """E', R of a roller on a raceway (``concave``: the outer raceway's curvature counts negative)
    and Seabra's E* = E'/2, R_x = 2R (Delabenetta 2021 Eqs. 1, 3): moduli E1, E2 [Pa], Poisson's ratios
    nu1, nu2 [-], radii R1, R2 [m] in; E_reduced, E_star [Pa], R, R_x [m] out."""
    E_reduced = reduced_modulus(E1, nu1, E2, nu2)
    R = reduced_radius(-R1 if concave else R1, R2)
    return {"E_reduced": E_reduced, "R": R, "E_star": 0.5 * E_reduced, "R_x": 2.0 * R}


@step("hertz", provides=("b", "p_h", "p_mean"), model="hertz_line")
def line_hertz(w, R, E_reduced):
    """Half-width b [m], maximum and mean pressure [Pa] of a line contact under w [N/m]."""
    result = hertz_line(w, R, E_reduced)
    return {"b": result.b, "p_h": result.p_h, "p_mean": result.p_mean}


@step("hertz", provides=("w", "b", "p_mean", "p_h", "contact_area"), model="hertz_line")
def force_hertz(F, length, R, E_reduced):
    """Line contact under a force F [N] over ``length`` [m]: w = F/length, b, p_mean, p_h and the
    contact area 2 b length [m^2] (Delabenetta 2021 Eqs. 2, 4)."""
    w = F / length
    result = hertz_line(w, R, E_reduced)
    return {"w": w, "b": result.b, "p_mean": result.p_mean, "p_h": result.p_h,
            "contact_area": 2.0 * result.b * length}


@step("approach", provides=("approach",), model="hamrock")
def hamrock_approach(w, R, E_reduced):
    """Elastic approach [m] of a line contact, Hamrock's formula in w [N/m] and R [m]."""
    return {"approach": line_approach("hamrock", E_reduced=E_reduced, w=w, R=R)}


@step("approach", provides=("approach",), model="palmgren")
def palmgren_approach(F, length, E_reduced):
    """Elastic approach [m] of a roller, Palmgren's formula in the force F [N] and the length [m]."""
    return {"approach": line_approach("palmgren", E_reduced=E_reduced, force=F, length=length)}


#: the approach steps by model name (the line-contact scene's ``approach`` slot)
APPROACHES = {"hamrock": hamrock_approach, "palmgren": palmgren_approach}


@step("hertz", provides=("w", "b", "p_h", "approach"), model="hertz_line")
def cycle_hertz(normal_force, width, R, E_reduced, cam_angle):
    """Hertz line contact at every cam angle: w = N/width [N/m], b [m], p_h [Pa] and Hamrock's
    approach [m]; zero where the contact carries no load."""
    n = cam_angle.size
    w = normal_force / width
    b, p_h, approach = np.zeros(n), np.zeros(n), np.zeros(n)
    for i in np.flatnonzero(w > 0.0):
        hz = hertz_line(float(w[i]), float(R[i]), E_reduced)
        b[i], p_h[i] = hz.b, hz.p_h
        approach[i] = line_approach("hamrock", E_reduced=E_reduced, w=float(w[i]), R=float(R[i]))
    return {"w": w, "b": b, "p_h": p_h, "approach": approach}


@step("hertz", provides=("b_inner", "b_outer", "p_h_inner", "p_h_outer", "p_h_max", "contact_length_inner",
                         "contact_length_outer"), model="hertz_line")
def roller_hertz(Q, E_reduced, contact_radii, roller_length):
    """Hertz line contact at the inner and outer raceway of every loaded roller (w = Q / l_we; the
    rolling-direction radii ``contact_radii[race]`` [m]); NaN for unloaded rollers; the peak pressure; the contacts'
    length, l_we [m] (an ideal line)."""
    loaded = Q > 0.0
    length = np.where(loaded, roller_length, np.nan)
    out = {"contact_length_inner": length, "contact_length_outer": length.copy()}
    for race in RACES:
        b, p = np.full(Q.size, np.nan), np.full(Q.size, np.nan)
        for j in np.flatnonzero(loaded):
            contact = hertz_line(Q[j] / roller_length, contact_radii[race], E_reduced)
            b[j], p[j] = contact.b, contact.p_h
        out[f"b_{race}"], out[f"p_h_{race}"] = b, p
    peaks = [np.nanmax(out[f"p_h_{race}"]) if loaded.any() else 0.0 for race in RACES]
    out["p_h_max"] = float(max(peaks))
    return out


@step("hertz", provides=("Rx", "Ry", "a_rolling", "a_transverse", "p_h", "approach", "pressure_check",
                         "stress_limit_exceeded"),
      model=lambda hertz_method: f"hertz_elliptical ({hertz_method})")
def ball_cone_hertz(normal_force, E_reduced, ball_radius, cone_angle, cone_contact_radius, hertz_method,
                    contact_stress_limit):
    """Elliptical Hertz contact of a ball [radius m] on the cone's track: curvature cos(alpha)/R_cont
    along rolling, straight along the generator (Saccheto 2008 §3.1); semi-axes [m], p_h [Pa],
    approach [m], p_h against the thesis's 1.1 GPa EHL threshold (text) and against
    ``contact_stress_limit`` [Pa] (``stress_limit_exceeded``, with a :class:`ValidityWarning` naming
    the limit; ISO 76:2006 gives 4.2 GPa for ball contacts)."""
    Rx = 1.0 / (1.0 / ball_radius + math.cos(cone_angle) / cone_contact_radius)
    contact = hertz_elliptical(normal_force, Rx, ball_radius, E_reduced, method=hertz_method)
    check = (f"p_h = {contact.p_max * 1e-9:.3g} GPa " +
             ("above" if contact.p_max > EHL_PRESSURE else "below") + " the thesis's 1.1 GPa EHL threshold")
    exceeded = bool(contact.p_max > contact_stress_limit)
    if exceeded:
        warnings.warn(f"ball-cone contact: p_h = {contact.p_max * 1e-9:.3g} GPa exceeds the contact stress limit "
                      f"{contact_stress_limit * 1e-9:.3g} GPa (BallConeCVT.contact_stress_limit; default: ISO 76:2006, "
                      "static rating of ball bearings, 4.2 GPa)", ValidityWarning, stacklevel=2)
    return {"Rx": Rx, "Ry": ball_radius, "a_rolling": contact.a_x, "a_transverse": contact.a_y, "p_h": contact.p_max,
            "approach": contact.approach, "pressure_check": check, "stress_limit_exceeded": exceeded}


@step("geometry", provides=("E_reduced", "Rx", "Ry"))
def point_geometry(E1, nu1, E2, nu2, R1x, R2x, R1y, R2y):
    """Reduced modulus E' [Pa] and the gap's reduced radii Rx along and Ry across rolling [m] of two bodies
    with moduli E1, E2 [Pa], Poisson's ratios nu1, nu2 [-] and signed principal radii [m] (negative
    concave, ``inf`` straight): 1/Rx = 1/R1x + 1/R2x, 1/Ry = 1/R1y + 1/R2y."""
    return {"E_reduced": reduced_modulus(E1, nu1, E2, nu2), "Rx": reduced_radius(R1x, R2x),
            "Ry": reduced_radius(R1y, R2y)}


@step("hertz", provides=("a_rolling", "a_transverse", "ellipticity", "p_h", "p_mean", "approach",
                         "stress_limit_exceeded"),
      model=lambda hertz_method: f"hertz_elliptical ({hertz_method})")
def point_hertz(F, Rx, Ry, E_reduced, hertz_method, contact_stress_limit):
    """Elliptical Hertz contact of a point contact (:func:`~camcontact.contact.hertz_elliptical.hertz_elliptical`)
    under F [N] with reduced radii Rx (rolling), Ry [m] and E' [Pa]: semi-axes along and across rolling [m],
    Hamrock's ellipticity k = a_transverse/a_rolling [-], peak and mean pressure [Pa], approach [m], and p_h
    against ``contact_stress_limit`` [Pa] (``stress_limit_exceeded``, with a :class:`ValidityWarning` naming
    the limit)."""
    contact = hertz_elliptical(F, Rx, Ry, E_reduced, method=hertz_method)
    exceeded = bool(contact.p_max > contact_stress_limit)
    if exceeded:
        warnings.warn(f"point contact: p_h = {contact.p_max * 1e-9:.3g} GPa exceeds the contact stress limit "
                      f"{contact_stress_limit * 1e-9:.3g} GPa (PointContact.contact_stress_limit; default: ISO 76:2006, "
                      "static rating of ball bearings, 4.2 GPa)", ValidityWarning, stacklevel=2)
    return {"a_rolling": contact.a_x, "a_transverse": contact.a_y, "ellipticity": contact.ellipticity,
            "p_h": contact.p_max, "p_mean": contact.p_mean, "approach": contact.approach,
            "stress_limit_exceeded": exceeded}
