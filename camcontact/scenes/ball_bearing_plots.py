"""Plots of a ball-bearing result: polar load distribution, contact angle, pressure and Lambda per ball."""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .bearing_plots import CONTACT_PANELS
from .plot_layout import lambda_bands, panel_axes

__all__ = ["plot_ball_bearing"]

PANELS = ("load", "contact_angle", "pressure", "lambda")


def plot_ball_bearing(result, *, panels=PANELS, figsize=None, ax=None, fig=None, columns=2):
    """Panels: ``"load"`` ball loads over the azimuth (polar, the radial load pointing down),
    ``"contact_angle"`` each loaded ball's contact angle against the azimuth (the free contact angle dashed),
    ``"pressure"`` Hertz p_h at the inner and outer raceway, ``"film"`` h_min per contact and ``"lambda"``
    Lambda per contact with the regime bands; in a grid of ``columns`` per row, or on the caller's axes
    (``ax=``, one per panel; the load panel's polar) or figure (``fig=``)."""
    need = {"load": ("ball_azimuth", "Q"), "contact_angle": ("ball_azimuth", "contact_angle")} | {
        panel: ("ball_azimuth", f"{key}_inner", f"{key}_outer") for panel, (key, *_) in CONTACT_PANELS.items()}
    if unknown := sorted(set(panels) - set(need)):
        raise InputError(f"unknown ball bearing plot panels {unknown}; choose from {sorted(need)}")
    chosen = [p for p in panels if all(k in result.outputs for k in need[p])]
    if not chosen:
        raise InputError(f"nothing to plot: the panels {list(panels)} need the outputs {need}")
    row = result.rows[0]
    fig, axes = panel_axes(len(chosen), ax=ax, fig=fig, figsize=figsize, columns=columns, where="ball bearing plot",
                           projections=["polar" if panel == "load" else None for panel in chosen])
    azimuth = np.asarray(row["ball_azimuth"], dtype=float)
    degrees = np.degrees(np.angle(np.exp(1j * azimuth)))
    order = np.argsort(degrees)
    for ax, panel in zip(axes, chosen):
        if panel == "load":
            loads = np.asarray(row["Q"], dtype=float) * 1e-3
            ax.plot(np.append(azimuth, azimuth[0] + 2 * np.pi), np.append(loads, loads[0]), marker="o", ms=3)
            ax.set_theta_zero_location("S")  # the radial load points down
            ax.set_title("ball load Q [kN]", fontsize=10, pad=14)
            continue
        if panel == "contact_angle":
            ax.plot(degrees[order], np.degrees(np.asarray(row["contact_angle"], dtype=float))[order], marker="o", ms=3,
                    label="loaded balls")
            free = result.scene.bearing.free_contact_angle if result.scene is not None else None
            if free is not None:
                ax.axhline(np.degrees(free), color="0.5", ls="--", lw=1, label="free contact angle")
            ax.set(xlabel="azimuth [deg] (0: load line)", ylabel="contact angle [deg]", title="contact angle per ball")
            ax.legend(fontsize=7)
            continue
        key, scale, label, title = CONTACT_PANELS[panel]
        top = 0.0
        for race, style in (("inner", "o"), ("outer", "s")):
            values = np.asarray(row[f"{key}_{race}"], dtype=float)[order] * scale
            top = max(top, float(np.nanmax(values, initial=0.0)))
            ax.plot(degrees[order], values, marker=style, ms=3, label=race)
        if panel == "lambda":
            lambda_bands(ax)
            ax.set_ylim(0.0, max(3.0, 1.1 * top))
        ax.set(xlabel="azimuth [deg] (0: load line)", ylabel=label, title=title.replace("per contact", "per ball"))
        ax.legend(fontsize=7)
    return fig
