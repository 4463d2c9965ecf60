"""Plots of a bearing result: polar load distribution, contact pressure and film per roller."""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .plot_layout import lambda_bands, panel_axes

__all__ = ["chosen_panels", "plot_bearing", "polar_loads", "race_panel"]


#: (output key, scale to the axis unit, axis label, title) of the per-contact panels
CONTACT_PANELS = {"pressure": ("p_h", 1e-6, "p_h [MPa]", "Hertz pressure per contact"),
                  "film": ("h_min", 1e6, "h_min [µm]", "minimum film per contact"),
                  "lambda": ("Lambda", 1.0, "Λ = h / σ [-]", "film parameter per contact")}


def chosen_panels(result, panels, need: dict, what: str) -> list[str]:
    """The ``panels`` whose outputs (``need[panel]``) the result holds; InputError (naming ``what`` plot) for an
    unknown panel or when none can be drawn."""
    if unknown := sorted(set(panels) - set(need)):
        raise InputError(f"unknown {what} plot panels {unknown}; choose from {sorted(need)}")
    chosen = [p for p in panels if all(k in result.outputs for k in need[p])]
    if not chosen:
        raise InputError(f"nothing to plot: the panels {list(panels)} need the outputs {need}")
    return chosen


def polar_loads(ax, azimuth, loads, title: str) -> None:
    """Rolling-element loads [N] over their azimuth [rad] on a polar Axes, closed, in kN, the radial load down."""
    azimuth = np.asarray(azimuth, dtype=float)
    kilo = np.asarray(loads, dtype=float) * 1e-3
    ax.plot(np.append(azimuth, azimuth[0] + 2 * np.pi), np.append(kilo, kilo[0]), marker="o", ms=3)
    ax.set_theta_zero_location("S")  # the radial load points down
    ax.set_title(title, fontsize=10, pad=14)


def race_panel(ax, row, azimuth, panel: str, element: str) -> None:
    """One of :data:`CONTACT_PANELS` per rolling element (one row of elements) at the inner and outer raceway against
    the azimuth [deg] (``azimuth`` [rad]), titled per ``element``; Lambda with its regime bands."""
    degrees = np.degrees(np.angle(np.exp(1j * np.asarray(azimuth, dtype=float))))
    order = np.argsort(degrees)
    key, scale, label, title = CONTACT_PANELS[panel]
    top = 0.0
    for race, style in (("inner", "o"), ("outer", "s")):
        values = np.asarray(row[f"{key}_{race}"], dtype=float)[order] * scale
        top = max(top, float(np.nanmax(values, initial=0.0)))
        ax.plot(degrees[order], values, marker=style, ms=3, label=race)
    if panel == "lambda":
        lambda_bands(ax)
        ax.set_ylim(0.0, max(3.0, 1.1 * top))
    ax.set(xlabel="azimuth [deg] (0: load line)", ylabel=label, title=title.replace("per contact", f"per {element}"))
    ax.legend(fontsize=7)


def plot_bearing(result, *, panels=("load", "pressure", "film", "lambda"), figsize=None, ax=None, fig=None,
                 columns=2):
    """Panels: ``"load"`` roller loads over the azimuth (polar, one trace per row), ``"pressure"``
    Hertz p_h at the inner and outer raceway against the azimuth, ``"film"`` h_min per contact, ``"lambda"``
    Lambda per contact with the regime bands (boundary below 1, mixed to 3); in a grid of ``columns`` per
    row, or on the caller's axes (``ax=``, one per panel; the load panel's polar) or figure (``fig=``)."""
    need = {"load": ("azimuth", "Q", "roller_row")} | {
        panel: ("azimuth", f"{key}_inner", f"{key}_outer", "roller_row") for panel, (key, *_) in CONTACT_PANELS.items()}
    chosen = chosen_panels(result, panels, need, "bearing")
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
        key, scale, label, title = CONTACT_PANELS[panel]
        top = 0.0
        for race, style in (("inner", "o"), ("outer", "s")):
            for k in np.unique(rows):
                mask = rows == k
                order = np.argsort(degrees[mask])
                values = np.asarray(row[f"{key}_{race}"], dtype=float)[mask][order] * scale
                top = max(top, float(np.nanmax(values, initial=0.0)))
                ax.plot(degrees[mask][order], values, marker=style, ms=3, label=f"{race}, row {int(k)}")
        if panel == "lambda":
            lambda_bands(ax)
            ax.set_ylim(0.0, max(3.0, 1.1 * top))
        ax.set(xlabel="azimuth [deg] (0: load line)", ylabel=label, title=title)
        ax.legend(fontsize=7)
    return fig
