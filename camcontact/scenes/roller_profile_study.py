"""Roller profiles compared: the pressure along a roller on its raceway for several profiles, by the slicing
(lamina) model and by the numerical half-space contact, with and without misalignment.

:func:`compare_roller_profiles` takes the contact in units (load, effective length, reduced radius along
rolling, the two materials or E') and a list of :class:`~camcontact.contact.roller_profile.RollerProfile`;
it returns a :class:`ProfileComparison` with one summary row per profile (pressure in the middle and its
peak by both methods, the edge-stress ratio peak/middle of the numerical solution, where the peak sits; the
ratio is NaN where a tilt unloads the middle, ``middle loaded`` False),
the pressure along the roller per profile and method (``along_frame``) and the laminae (``lamina_frame``);
:meth:`ProfileComparison.plot` draws the pressure along the roller, numerical solid and laminae dashed,
against the Hertz pressure of the mean load per length.
"""

from __future__ import annotations

from collections.abc import Sequence

import attrs
import numpy as np
import pandas as pd

from ..contact.geometry import reduced_modulus
from ..contact.hertz_line import hertz_line
from ..contact.roller_profile import RollerProfile, roller_dry_contact, solve_laminae
from ..errors import InputError
from ..units import ANGLE, si_value, to_quantity
from .plot_layout import panel_axes

__all__ = ["ProfileComparison", "compare_roller_profiles"]


@attrs.frozen
class ProfileComparison:
    """The outcome of :func:`compare_roller_profiles` (frames in display units, results in SI)."""

    summary: pd.DataFrame = attrs.field(repr=False)
    along_frame: pd.DataFrame = attrs.field(repr=False)
    lamina_frame: pd.DataFrame = attrs.field(repr=False)
    hertz_pressure: float
    misalignment: float

    def plot(self, *, ax=None, fig=None, figsize=None):
        """The pressure along the roller [MPa] against the axial position [mm]: numerical (solid) and laminae
        (dashed) per profile, the Hertz pressure of the mean load per length dotted."""
        fig, (ax,) = panel_axes(1, ax=ax, fig=fig, figsize=figsize or (7.5, 4.5), columns=1,
                                where="roller profile plot")
        colours = iter(["C0", "C1", "C2", "C3", "C4", "C5", "C6", "C7"])
        for profile, group in self.along_frame.groupby("profile", sort=False):
            colour = next(colours)
            numerical = group[group["method"] == "numerical"]
            laminae = group[group["method"] == "laminae"]
            ax.plot(numerical["y [mm]"], numerical["pressure [MPa]"], color=colour, label=f"{profile}: numerical")
            ax.plot(laminae["y [mm]"], laminae["pressure [MPa]"], color=colour, ls="--", label=f"{profile}: laminae")
        ax.axhline(self.hertz_pressure * 1e-6, color="0.4", ls=":", lw=1, label="Hertz, mean load per length")
        tilt = f", misalignment {self.misalignment * 1e3:.3g} mrad" if self.misalignment else ""
        ax.set(xlabel="axial position y along the roller [mm]", ylabel="contact pressure p [MPa]",
               title=f"pressure along the roller{tilt}")
        ax.set_ylim(bottom=0.0)
        ax.legend(fontsize=7, loc="upper center", ncol=2)
        return fig


def compare_roller_profiles(load, length, reduced_radius, profiles: Sequence[RollerProfile], *, material=None,
                            E_reduced=None, misalignment="0 rad", laminae: int = 40, cells_along: int = 200,
                            cells_across: int = 32) -> ProfileComparison:
    """Pressure along a roller on its raceway for each of ``profiles`` by the laminae and the numerical dry contact.

    Parameters
    ----------
    load : Quantity or str
        Roller load Q [force] on this raceway.
    length : Quantity or str
        Effective contact length l_we [length].
    reduced_radius : Quantity or str
        Reduced radius R along rolling [length] (e.g. ``SphericalRollerBearing.contact_radii``).
    profiles : sequence of RollerProfile
        The profiles to compare (:class:`~camcontact.contact.roller_profile.RollerProfile`; design loads and
        crown drops in SI: N, m).
    material : Material, optional
        The material of roller and ring (E' of the pair); or ``E_reduced`` [pressure].
    misalignment : Quantity or str
        Tilt of the roller against the raceway [angle] (default 0).
    laminae, cells_along, cells_across : int
        Slices of the lamina model; cells of the numerical grid along and across the roller.
    """
    Q = si_value(to_quantity(load, "[force]", where="compare_roller_profiles(load)"))
    l_we = si_value(to_quantity(length, "[length]", where="compare_roller_profiles(length)"))
    R = si_value(to_quantity(reduced_radius, "[length]", where="compare_roller_profiles(reduced_radius)"))
    tilt = si_value(to_quantity(misalignment, ANGLE, where="compare_roller_profiles(misalignment)"))
    if (material is None) == (E_reduced is None):
        raise InputError("compare_roller_profiles: give the material (roller and ring) or E_reduced, one of them")
    E = (reduced_modulus(material.si.E, material.nu, material.si.E, material.nu) if material is not None
         else si_value(to_quantity(E_reduced, "[pressure]", where="compare_roller_profiles(E_reduced)")))
    if not profiles or not all(isinstance(p, RollerProfile) for p in profiles):
        raise InputError(f"compare_roller_profiles: profiles = {profiles!r}; allowed: a non-empty list of RollerProfile")
    p_hertz = hertz_line(Q / l_we, R, E).p_h
    rows, along, lamina_frames = [], [], []
    for profile in profiles:
        lam = solve_laminae(Q, l_we, R, E, profile, misalignment=tilt, laminae=laminae)
        num = roller_dry_contact(Q, l_we, R, E, profile, misalignment=tilt, cells_along=cells_along,
                                 cells_across=cells_across)
        p_num = num.along()
        k = int(np.argmax(p_num))
        j = int(np.argmax(lam.pressure))
        middle_num = float(np.interp(0.0, num.y, p_num))
        rows.append({
            "profile": profile.label, "p_middle numerical [MPa]": 1e-6 * middle_num,
            "p_middle laminae [MPa]": 1e-6 * float(np.interp(0.0, lam.y, lam.pressure)),
            "p_max numerical [MPa]": 1e-6 * float(p_num[k]), "y at p_max numerical [mm]": 1e3 * float(num.y[k]),
            "p_max laminae [MPa]": 1e-6 * float(lam.pressure[j]), "y at p_max laminae [mm]": 1e3 * float(lam.y[j]),
            "numerical at the laminae's peak [MPa]": 1e-6 * float(np.interp(lam.y[j], num.y, p_num)),
            "edge stress ratio [-]": float(p_num[k] / middle_num) if middle_num > 0.0 else float("nan"),
            "middle loaded": middle_num > 0.0, "dry contact iterations [-]": num.iterations,
        })
        along.append(pd.DataFrame({"profile": profile.label, "method": "numerical", "y [mm]": 1e3 * num.y,
                                   "pressure [MPa]": 1e-6 * p_num}))
        along.append(pd.DataFrame({"profile": profile.label, "method": "laminae", "y [mm]": 1e3 * lam.y,
                                   "pressure [MPa]": 1e-6 * lam.pressure}))
        lamina_frames.append(lam.to_frame().assign(profile=profile.label))
    return ProfileComparison(summary=pd.DataFrame(rows).set_index("profile"), along_frame=pd.concat(along, ignore_index=True),
                             lamina_frame=pd.concat(lamina_frames, ignore_index=True), hertz_pressure=p_hertz,
                             misalignment=tilt)
