"""Plots of a cylindrical-roller-bearing result: roller loads (polar), the lamina pressure along the loaded rollers,
Lambda per roller."""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from .plot_layout import lambda_bands, panel_axes

__all__ = ["plot_cylindrical_roller_bearing"]


def plot_cylindrical_roller_bearing(result, *, panels=("load", "along", "lambda"), figsize=None, ax=None, fig=None,
                                    columns=3):
    """Panels: ``"load"`` roller loads over the azimuth (polar, the radial load pointing down), ``"along"`` the
    lamina pressure at the inner raceway along each loaded roller [MPa] against the axial position [mm] (the
    misalignment shows as a slope, the profile as the fall at the ends), ``"lambda"`` Lambda per roller at both
    raceways with the regime bands; in a grid of ``columns``, or on the caller's axes (``ax=``) or figure."""
    need = {"load": ("azimuth", "Q"), "along": ("Q",), "lambda": ("azimuth", "Lambda_inner", "Lambda_outer")}
    if unknown := sorted(set(panels) - set(need)):
        raise InputError(f"unknown cylindrical roller bearing plot panels {unknown}; choose from {sorted(need)}")
    chosen = [p for p in panels if all(k in result.outputs for k in need[p])]
    if not chosen:
        raise InputError(f"nothing to plot: the panels {list(panels)} need the outputs {need}")
    row = result.rows[0]
    fig, axes = panel_axes(len(chosen), ax=ax, fig=fig, figsize=figsize, columns=columns,
                           where="cylindrical roller bearing plot",
                           projections=["polar" if panel == "load" else None for panel in chosen])
    azimuth = np.asarray(row["azimuth"], dtype=float)
    degrees = np.degrees(np.angle(np.exp(1j * azimuth)))
    order = np.argsort(degrees)
    for ax, panel in zip(axes, chosen):
        if panel == "load":
            loads = np.asarray(row["Q"], dtype=float) * 1e-3
            ax.plot(np.append(azimuth, azimuth[0] + 2 * np.pi), np.append(loads, loads[0]), marker="o", ms=3)
            ax.set_theta_zero_location("S")
            ax.set_title("roller load Q [kN]", fontsize=10, pad=14)
        elif panel == "along":
            _along(ax, result)
        else:
            for race, style in (("inner", "o"), ("outer", "s")):
                ax.plot(degrees[order], np.asarray(row[f"Lambda_{race}"], dtype=float)[order], marker=style, ms=3,
                        label=race)
            lambda_bands(ax)
            top = np.nanmax(np.concatenate([row["Lambda_inner"], row["Lambda_outer"]]), initial=0.0)
            ax.set_ylim(0.0, max(3.0, 1.1 * top))
            ax.set(xlabel="azimuth [deg] (0: load line)", ylabel="Λ = h / σ [-]", title="film parameter per roller")
            ax.legend(fontsize=7)
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
    E = material.si.E / (1.0 - material.nu**2)
    R = bearing.contact_radii["inner"]
    width = laminae.x[1] - laminae.x[0]
    top, drawn = 0.0, {}
    for j in np.flatnonzero(laminae.loaded):
        p = np.sqrt(laminae.q[j] / width * E / (2.0 * math.pi * R)) * 1e-6
        angle = round(abs(math.degrees(np.angle(np.exp(1j * laminae.azimuth[j])))))
        top = max(top, float(p.max()))
        if angle in drawn and np.allclose(drawn[angle], p):
            continue  # the mirror roller of an aligned bearing: the same curve
        drawn[angle] = p
        sign = "±" if angle and np.allclose(p, _mirror(laminae, j, E, R, width)) else ""
        ax.plot(1e3 * laminae.x, p, lw=1, label=f"{sign}{angle}°")
    tilt = f", misalignment {math.degrees(laminae.misalignment) * 60:.3g}'" if laminae.misalignment else ""
    ax.set(xlabel="axial position along the roller [mm]", ylabel="lamina pressure, inner raceway [MPa]",
           title=f"pressure along the rollers{tilt}")
    ax.set_ylim(0.0, 1.35 * top if top > 0 else 1.0)
    ax.legend(fontsize=6, title="roller azimuth", title_fontsize=7, ncol=4, loc="upper center")


def _mirror(laminae, j: int, E: float, R: float, width: float) -> np.ndarray:
    """The lamina pressure of the roller mirrored about the load line (NaN when there is none)."""
    target = np.angle(np.exp(-1j * laminae.azimuth[j]))
    match = np.flatnonzero(np.isclose(np.angle(np.exp(1j * laminae.azimuth)), target, atol=1e-9))
    if match.size == 0:
        return np.full(laminae.x.size, np.nan)
    return np.sqrt(laminae.q[match[0]] / width * E / (2.0 * math.pi * R)) * 1e-6
