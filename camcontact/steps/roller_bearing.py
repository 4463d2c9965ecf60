"""Cylindrical-roller-bearing steps: roller and lamina loads under a radial load and a misalignment, the Hertz
pressure along every roller, and ISO/TS 16281's reference rating life from the lamina loads.

Lamina loads after ISO/TS 16281 (:mod:`camcontact.contact.lamina_load_distribution`); each lamina's Hertz line
contact at both raceways (Johnson 1985 §4.3: p = sqrt(w E' / (2 pi R)) with w the lamina load per length);
L_10r after :mod:`camcontact.models.iso_ts16281_roller`. Forces [N], lengths [m], pressures [Pa], angles
[rad], ring speeds n [rev/s].
"""

from __future__ import annotations

import math

import numpy as np

from ..contact.hertz_line import hertz_line_arrays
from ..models.iso_ts16281_roller import roller_reference_rating_life
from ..step_graph import step
from .contact import RACES

__all__ = ["LAMINA_LOADS", "lamina_hertz", "lamina_loads", "lamina_reference_life", "radial_equivalent_load"]

LAMINA_LOADS = ("azimuth", "Q", "loaded", "x_q_max", "Q_max", "loaded_rollers", "delta_r", "lamina_moment",
                "lamina_loads")


@step("load_distribution", provides=LAMINA_LOADS, model="iso_ts_16281_laminae")
def lamina_loads(bearing, radial_load, misalignment, laminae):
    """Roller loads Q [N] of ``bearing`` under F_r [N] and the misalignment [rad] from its lamina loads (ISO/TS 16281
    slicing with the rollers' profile), per roller with the axial position of its most loaded lamina [m]; the
    inner ring's displacement [m], the moment the laminae exert [N m] and the lamina loads themselves
    (``lamina_loads``, a :class:`~camcontact.contact.lamina_load_distribution.LaminaLoadDistribution`)."""
    result = bearing.lamina_load_distribution_si(radial_load, misalignment, laminae)
    loaded = result.loaded
    x_peak = np.where(loaded, result.x[np.argmax(result.q, axis=1)], np.nan)
    return {"azimuth": result.azimuth, "Q": result.Q, "loaded": loaded.astype(bool), "x_q_max": x_peak,
            "Q_max": float(result.Q.max()), "loaded_rollers": float(loaded.sum()), "delta_r": result.delta_r,
            "lamina_moment": result.moment, "lamina_loads": result}


@step("hertz", provides=("p_h_inner", "p_h_outer", "b_inner", "b_outer", "p_h_max", "contact_length_inner",
                         "contact_length_outer"), model="hertz_line per lamina")
def lamina_hertz(lamina_loads, E_reduced, contact_radii):
    """The largest Hertz pressure along every roller at the inner and outer raceway [Pa] (each lamina a line contact
    under its load per length, the rolling-direction radii ``contact_radii[race]`` [m]) with the half-width there
    [m], NaN for unloaded rollers, and the bearing's peak pressure; the loaded length of every roller [m] (where its
    laminae's compression crosses zero, interpolated; the same at both raceways)."""
    result = lamina_loads
    w = result.load_per_length.max(axis=1)
    length = np.where(result.loaded, result.loaded_lengths, np.nan)
    out = {"contact_length_inner": length, "contact_length_outer": length.copy()}
    for race in RACES:
        b, p = hertz_line_arrays(w, contact_radii[race], E_reduced)
        out[f"p_h_{race}"] = np.where(result.loaded, p, np.nan)
        out[f"b_{race}"] = np.where(result.loaded, b, np.nan)
    peaks = np.concatenate([out[f"p_h_{race}"] for race in RACES])
    out["p_h_max"] = float(np.nanmax(peaks)) if np.any(np.isfinite(peaks)) else 0.0
    return out


@step("equivalent_load", provides=("P",), model="iso281")
def radial_equivalent_load(radial_load):
    """Dynamic equivalent load P = F_r [N] of a cylindrical roller bearing (nominal contact angle 0; ISO 281 §6.2)."""
    return {"P": float(radial_load)}


@step("reference_life", provides=("L10r", "L10rh"), model="iso_ts_16281_roller")
def lamina_reference_life(lamina_loads, bearing, n_inner, n_outer):
    """ISO/TS 16281 L_10r [revolutions] from the lamina loads (the ring that turns faster turns against the load; the
    Eq. 60 edge factor with the ISO reference profile only) and in time [s] at |n_i - n_o| [rev/s]."""
    life = roller_reference_rating_life(lamina_loads.q, C=bearing.si.C, roller_diameter=bearing.si.roller_diameter,
                                        pitch_diameter=bearing.d_m, inner_rotates=abs(n_inner) >= abs(n_outer),
                                        with_edge_factor=bearing.roller_profile.kind == "iso_ts_16281")
    L10r = life["L10r"] * 1e6
    relative = abs(n_inner - n_outer)
    return {"L10r": L10r, "L10rh": L10r / relative if relative > 0 else math.inf}
