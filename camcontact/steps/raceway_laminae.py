"""Raceway contacts of a spherical roller bearing as finite lines: the conformity's gap sliced into laminae.

With the conformities f_i, f_o (:class:`~camcontact.components.SphericalRollerBearing`) the gap across rolling of
each raceway contact grows as y^2 / (2 R_y), R_y = R_r / (1 - f). ISO/TS 16281:2008 slices such a contact into
laminae, each a line contact carrying its share of the roller's Palmgren stiffness
(:func:`camcontact.contact.roller_profile.solve_laminae`); the largest lamina pressure is the contact's Hertz
pressure, the loaded laminae its length, and a contact whose end laminae carry load is ``edge_loaded``: there the
real, half-space pressure rises at the roller's end (the laminae do not see it; the numerical dry contact
:func:`camcontact.contact.roller_profile.roller_dry_contact` does). The slicing of a contact shorter than the roller
is an approximation of the elliptical Hertz contact: 2-7 % below its peak pressure and 6-18 % longer for f = 0.97-0.99
and 0.5-10 kN on a 27 mm roller, whatever the number of laminae (the slices' 10/9 law spreads the load further
than Hertz's ellipse; the loaded length is interpolated where the approach crosses zero, so the slices' width does
not add to it; tests/unit/test_steps_raceway_laminae.py). The films, mixed lubrication and friction spread the
roller's load over that length, so their load per length is as much below Hertz's mean (films about 1-2 % thicker). Forces [N], lengths [m], pressures [Pa].
"""

from __future__ import annotations

import numpy as np

from ..contact.hertz_line import hertz_line_arrays
from ..contact.roller_profile import solve_laminae
from ..step_graph import step
from .contact import RACES

__all__ = ["CONFORMAL_HERTZ", "conformal_roller_hertz"]

#: what :func:`conformal_roller_hertz` provides
CONFORMAL_HERTZ = (*(f"{q}_{race}" for q in ("b", "p_h", "contact_length", "edge_loaded") for race in RACES),
                   "p_h_max", "raceway_laminae")


@step("hertz", provides=CONFORMAL_HERTZ, model="laminae (conformity)")
def conformal_roller_hertz(Q, E_reduced, contact_radii, roller_length, raceway_profiles, laminae):
    """Every loaded roller's inner and outer contact sliced into ``laminae`` along its length l_we [m] with the
    conformity's gap ``raceway_profiles[race]`` (rolling-direction radii ``contact_radii[race]`` [m]): the largest
    lamina pressure p_h [Pa] with its half-width b [m], the loaded length [m]
    (:attr:`~camcontact.contact.roller_profile.LaminaResult.loaded_length`), whether the end laminae carry load
    (``edge_loaded``), NaN / False for unloaded rollers; the peak pressure and the lamina results per race
    (``raceway_laminae[race][roller]``, None where unloaded)."""
    out = {}
    for race in RACES:
        b, p, length = (np.full(Q.size, np.nan) for _ in range(3))
        edge = np.zeros(Q.size, dtype=bool)
        results = [None] * Q.size
        for j in np.flatnonzero(Q > 0.0):
            result = solve_laminae(float(Q[j]), roller_length, contact_radii[race], E_reduced, raceway_profiles[race],
                                   laminae=laminae)
            k = int(np.argmax(result.load))
            b[j], p[j] = (float(v) for v in hertz_line_arrays(result.load_per_length[k], contact_radii[race], E_reduced))
            length[j] = result.loaded_length
            edge[j] = result.load[0] > 0.0 or result.load[-1] > 0.0
            results[j] = result
        out |= {f"b_{race}": b, f"p_h_{race}": p, f"contact_length_{race}": length, f"edge_loaded_{race}": edge}
        out.setdefault("raceway_laminae", {})[race] = results
    peaks = np.concatenate([out[f"p_h_{race}"] for race in RACES])
    out["p_h_max"] = float(np.nanmax(peaks)) if np.any(np.isfinite(peaks)) else 0.0
    return out
