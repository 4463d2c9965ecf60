"""Plots of a ball-bearing result: polar load distribution, contact angle, pressure and Lambda per ball."""

from __future__ import annotations

import numpy as np

from .bearing_plots import CONTACT_PANELS, chosen_panels, polar_loads, race_panel
from .plot_layout import panel_axes

__all__ = ["plot_ball_bearing"]

PANELS = ("load", "contact_angle", "pressure", "lambda")


def plot_ball_bearing(result, *, panels=PANELS, figsize=None, ax=None, fig=None, columns=2):
    """Panels: ``"load"`` ball loads over the azimuth (polar, the radial load pointing down),
    ``"contact_angle"`` each loaded ball's contact angle against the azimuth (the free contact angle dashed),
    ``"pressure"`` Hertz p_h at the inner and outer raceway, ``"film"`` h_min per contact and ``"lambda"``
    Lambda per contact with the regime bands (a pair of bearings: one trace per bearing); in a grid of ``columns``
    per row, or on the caller's axes (``ax=``, one per panel; the load panel's polar) or figure (``fig=``)."""
    need = {"load": ("ball_azimuth", "Q"), "contact_angle": ("ball_azimuth", "contact_angle")} | {
        panel: ("ball_azimuth", f"{key}_inner", f"{key}_outer") for panel, (key, *_) in CONTACT_PANELS.items()}
    chosen = chosen_panels(result, panels, need, "ball bearing")
    row = result.rows[0]
    fig, axes = panel_axes(len(chosen), ax=ax, fig=fig, figsize=figsize, columns=columns, where="ball bearing plot",
                           projections=["polar" if panel == "load" else None for panel in chosen])
    azimuth = np.asarray(row["ball_azimuth"], dtype=float)
    # a pair of bearings: one trace per bearing (ball_row 0 / 1)
    rows = np.asarray(row["ball_row"], dtype=int) if "ball_row" in result.outputs else np.zeros(azimuth.size, dtype=int)
    paired = rows.max() > 0
    bearings = [(rows == k, f"bearing {k}" if paired else None) for k in np.unique(rows)]
    for ax, panel in zip(axes, chosen):
        if panel == "load":
            for mask, name in bearings:
                polar_loads(ax, azimuth[mask], np.asarray(row["Q"], dtype=float)[mask], "ball load Q [kN]", label=name)
        elif panel == "contact_angle":
            for mask, name in bearings:
                degrees = np.degrees(np.angle(np.exp(1j * azimuth[mask])))
                order = np.argsort(degrees)
                ax.plot(degrees[order], np.degrees(np.asarray(row["contact_angle"], dtype=float)[mask])[order],
                        marker="o", ms=3, label="loaded balls" + (f", {name}" if name else ""))
            free = result.scene.bearing.free_contact_angle if result.scene is not None else None
            if free is not None:
                ax.axhline(np.degrees(free), color="0.5", ls="--", lw=1, label="free contact angle")
            ax.set(xlabel="azimuth [deg] (0: load line)", ylabel="contact angle [deg]", title="contact angle per ball")
            ax.legend(fontsize=7)
        else:
            race_panel(ax, row, azimuth, panel, "ball",
                       groups=[(mask, f", {name}" if name else "") for mask, name in bearings])
    return fig
