"""Plots of a roller-raceway contact result: stress field, films and temperatures per convention."""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .plot_layout import panel_axes

__all__ = ["plot_raceway_contact"]

CELSIUS = 273.15


def plot_raceway_contact(result, *, panels=("stress", "film", "temperature"), figsize=None, ax=None, fig=None,
                         columns=3):
    """Panels: ``"stress"`` contours of tau_xz / p0 below the contact of the first variant over
    x in [-3a, 3a], z in [0, 3a] (the thesis's Fig. 24, frictionless), ``"film"`` h_c, h_min and the
    corrected h_oc per convention with Lambda written on top, ``"temperature"`` surface and lubricant
    maxima per convention against the lubricant's upper service temperature. On the caller's axes (``ax=``, one
    per panel) or figure (``fig=``) when given."""
    need = {"stress": ("b", "p_h"), "film": ("h_c", "h_min", "h_c_corrected", "Lambda_oc"),
            "temperature": ("surface_temperature_max", "lubricant_temperature_max")}
    chosen = [p for p in panels if all(k in result.outputs for k in need[p])]
    if not chosen:
        raise InputError(f"nothing to plot: the panels {list(panels)} need the outputs {need}")
    fig, axes = panel_axes(len(chosen), ax=ax, fig=fig, figsize=figsize, columns=columns,
                           where="raceway_contact plot")
    labels = [v or "result" for v in result.variants]
    positions = np.arange(len(labels))
    for ax, panel in zip(axes, chosen):
        if panel == "stress":
            from ..contact.subsurface import line_contact_stresses

            x, z = np.meshgrid(np.linspace(-3.0, 3.0, 241), np.linspace(1e-4, 3.0, 121))
            field = line_contact_stresses(x, z, 1.0, 1.0, nu=result.scene.raceway_material.nu)
            filled = ax.contourf(x, z, field["tau_xz"], levels=21, cmap="RdBu_r")
            ax.contour(x, z, field["principal_shear"], levels=[0.2, 0.25, 0.29], colors="k", linewidths=0.7)
            fig.colorbar(filled, ax=ax, label="tau_xz / p0 [-]")
            ax.invert_yaxis()
            row = result.rows[0]
            ax.set(xlabel="x / a [-]", ylabel="z / a [-]",
                   title=f"{labels[0]}: a = {row['b'] * 1e6:.4g} µm, p0 = {row['p_h'] * 1e-6:.4g} MPa\n"
                         "(black: principal shear 0.20, 0.25, 0.29 p0)")
        elif panel == "film":
            for offset, key in ((-0.27, "h_c"), (0.0, "h_min"), (0.27, "h_c_corrected")):
                ax.bar(positions + offset, [1e6 * r[key] for r in result.rows], width=0.27, label=key)
            for k, r in enumerate(result.rows):
                ax.annotate(f"Λ = {r['Lambda_oc']:.3g}", (k + 0.27, 1e6 * r["h_c_corrected"]), ha="center",
                            va="bottom", fontsize=8)
            ax.set_xticks(positions, labels)
            ax.set(ylabel="film [µm]", title="films (h_oc = φ_T φ_A φ_R h_c)")
            ax.legend(fontsize=8)
        else:
            for offset, key, label in ((-0.2, "surface_temperature_max", "surface max T + T_F"),
                                       (0.2, "lubricant_temperature_max", "lubricant max (as reported)")):
                ax.bar(positions + offset, [r[key] - CELSIUS for r in result.rows], width=0.4, label=label)
            upper = result.scene.lubricant.si.upper_temperature
            if upper is not None:
                ax.axhline(upper - CELSIUS, color="r", linestyle="--", label="upper service temperature")
            ax.set_xticks(positions, labels)
            ax.set(ylabel="temperature [°C]", title="temperatures")
            ax.set_ylim(top=1.45 * ax.get_ylim()[1])  # room for the legend above the bars and the limit
            ax.legend(fontsize=8, loc="upper center")
    return fig
