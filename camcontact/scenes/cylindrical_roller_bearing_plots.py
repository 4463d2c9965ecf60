"""Plots of a cylindrical-roller-bearing result: roller loads (polar), the lamina pressure along the loaded rollers,
Lambda per roller."""

from __future__ import annotations

import math

import numpy as np

from ..contact.geometry import reduced_modulus
from ..errors import InputError
from .bearing_plots import chosen_panels, polar_loads, race_panel
from .plot_layout import panel_axes

__all__ = ["plot_cylindrical_roller_bearing"]


def plot_cylindrical_roller_bearing(result, *, panels=("load", "along", "lambda"), figsize=None, ax=None, fig=None,
                                    columns=3):
    """Panels: ``"load"`` roller loads over the azimuth (polar, the radial load pointing down), ``"along"`` the
    lamina pressure at the inner raceway along each loaded roller [MPa] against the axial position [mm] (the
    misalignment shows as a slope, the profile as the fall at the ends), ``"lambda"`` Lambda per roller at both
    raceways with the regime bands; in a grid of ``columns``, or on the caller's axes (``ax=``) or figure."""
    need = {"load": ("azimuth", "Q"), "along": ("Q",), "lambda": ("azimuth", "Lambda_inner", "Lambda_outer")}
    chosen = chosen_panels(result, panels, need, "cylindrical roller bearing")
    row = result.rows[0]
    fig, axes = panel_axes(len(chosen), ax=ax, fig=fig, figsize=figsize, columns=columns,
                           where="cylindrical roller bearing plot",
                           projections=["polar" if panel == "load" else None for panel in chosen])
    for ax, panel in zip(axes, chosen):
        if panel == "load":
            polar_loads(ax, row["azimuth"], row["Q"], "roller load Q [kN]")
        elif panel == "along":
            _along(ax, result)
        else:
            race_panel(ax, row, row["azimuth"], "lambda", "roller")
    return fig


def _along(ax, result) -> None:
    """The inner-raceway lamina pressure along each loaded roller (Hertz per lamina)."""
    scene = result.scene
    bearing = scene.bearing
    laminae = bearing.lamina_load_distribution_si(scene.si.radial_load, scene.si.misalignment, scene.laminae)
    material = bearing.material
    if material is None:
        raise InputError("cylindrical roller bearing plot: the pressure along the rollers needs "
                         "CylindricalRollerBearing.material")
    pressure = laminae.pressure(bearing.contact_radii["inner"],
                                reduced_modulus(material.si.E, material.nu, material.si.E, material.nu)) * 1e-6
    lines: dict[int, tuple] = {}
    for j in np.flatnonzero(laminae.loaded):
        angle = round(abs(math.degrees(np.angle(np.exp(1j * laminae.azimuth[j])))))
        if angle in lines and np.allclose(lines[angle][1], pressure[j]):
            lines[angle][0].set_label(f"±{angle}°")  # the mirror roller: the same curve, one label for both
            continue
        (line,) = ax.plot(1e3 * laminae.x, pressure[j], lw=1, label=f"{angle}°")
        lines[angle] = (line, pressure[j])
    tilt = f", misalignment {math.degrees(laminae.misalignment) * 60:.3g}'" if laminae.misalignment else ""
    ax.set(xlabel="axial position along the roller [mm]", ylabel="lamina pressure, inner raceway [MPa]",
           title=f"pressure along the rollers{tilt}")
    top = float(pressure.max())
    ax.set_ylim(0.0, 1.35 * top if top > 0 else 1.0)
    ax.legend(fontsize=6, title="roller azimuth", title_fontsize=7, ncol=4, loc="upper center")
