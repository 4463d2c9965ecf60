"""Plots of a bearing result: polar load distribution, contact pressure and film per roller."""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .plot_layout import panel_axes

__all__ = ["plot_bearing"]


def plot_bearing(result, *, panels=("load", "pressure", "film"), figsize=None, ax=None, fig=None, columns=3):
    """Panels: ``"load"`` roller loads over the azimuth (polar, one trace per row), ``"pressure"``
    Hertz p_h at the inner and outer raceway against the azimuth, ``"film"`` h_min per contact; in a grid of
    ``columns`` per row, or on the caller's axes (``ax=``, one per panel; the load panel's polar) or figure
    (``fig=``)."""
    need = {"load": ("azimuth", "Q", "roller_row"), "pressure": ("azimuth", "p_h_inner", "p_h_outer", "roller_row"),
            "film": ("azimuth", "h_min_inner", "h_min_outer", "roller_row")}
    chosen = [p for p in panels if all(k in result.outputs for k in need[p])]
    if not chosen:
        raise InputError(f"nothing to plot: the panels {list(panels)} need the outputs {need}")
    row = result.rows[0]
    fig, axes = panel_axes(len(chosen), ax=ax, fig=fig, figsize=figsize, columns=columns, where="bearing plot",
                           projections=["polar" if panel == "load" else None for panel in chosen])
    rows = np.asarray(row["roller_row"])
    azimuth = np.asarray(row["azimuth"])
    for ax, panel in zip(axes, chosen):
        if panel == "load":
            for k in np.unique(rows):
                mask = rows == k
                order = np.argsort(azimuth[mask])
                angles = np.append(azimuth[mask][order], azimuth[mask][order][0] + 2 * np.pi)
                loads = np.append(row["Q"][mask][order], row["Q"][mask][order][0]) * 1e-3
                ax.plot(angles, loads, marker="o", ms=3, label=f"row {int(k)}")
            ax.set_theta_zero_location("S")  # the radial load points down
            ax.set_title("roller load Q [kN]", fontsize=10, pad=14)
            ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0))
            continue
        degrees = np.degrees(np.angle(np.exp(1j * azimuth)))
        for race, style in (("inner", "o"), ("outer", "s")):
            key, scale, unit = (f"p_h_{race}", 1e-6, "MPa") if panel == "pressure" else (f"h_min_{race}", 1e6, "µm")
            for k in np.unique(rows):
                mask = rows == k
                order = np.argsort(degrees[mask])
                ax.plot(degrees[mask][order], np.asarray(row[key])[mask][order] * scale, marker=style, ms=3,
                        label=f"{race}, row {int(k)}")
        ax.set(xlabel="azimuth [deg] (0: load line)",
               ylabel="p_h [MPa]" if panel == "pressure" else "h_min [µm]",
               title="Hertz pressure per contact" if panel == "pressure" else "minimum film per contact")
        ax.legend(fontsize=7)
    return fig
