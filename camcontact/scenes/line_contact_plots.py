"""Plots of a line-contact result: Hertz pressure, stresses below the centre, films per model."""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .plot_layout import panel_axes

__all__ = ["plot_line_contact"]


def plot_line_contact(result, *, figsize=None, ax=None, fig=None, columns=3):
    """Three panels: Hertz pressure, stresses along the depth at x = 0, films per model; on the caller's axes
    (``ax=``, one per panel) or figure (``fig=``) when given."""
    row0 = result.rows[0]
    panels = [p for p, need in (("pressure", ("b", "p_h")), ("stress", ("b", "p_h")), ("film", ("h_c",)))
              if all(k in result.outputs for k in need) or (p == "film" and "h_min" in result.outputs)]
    if not panels:
        raise InputError("nothing to plot: ask for b and p_h, or for film outputs")
    fig, axes = panel_axes(len(panels), ax=ax, fig=fig, figsize=figsize, columns=columns, where="line_contact plot")
    for ax, panel in zip(axes, panels):
        if panel == "pressure":
            x = np.linspace(-1.5, 1.5, 301)
            ax.plot(x, row0["p_h"] * 1e-6 * np.sqrt(np.clip(1 - x**2, 0, None)))
            ax.set(xlabel="x / b [-]", ylabel="p [MPa]", title=f"Hertz pressure, b = {row0['b'] * 1e6:.4g} µm")
        elif panel == "stress":
            from ..contact.subsurface import line_contact_stresses

            z = np.linspace(1e-4, 3.0, 300)
            contact = result.scene
            field = line_contact_stresses(np.zeros_like(z), z, 1.0, 1.0,
                                          friction=contact.friction_coefficient, nu=contact.body1.material.nu)
            for key, label in (("principal_shear", "τ₁ (principal shear)"), ("von_mises", "von Mises"),
                               ("tresca", "Tresca")):
                ax.plot(field[key], z, label=label)
            ax.invert_yaxis()
            ax.set(xlabel="stress / p_h [-]", ylabel="z / b [-]", title="stresses below the centre")
            ax.legend(fontsize=8)
        else:
            labels = list(result.variants) if result.variants != ("",) else ["film"]
            positions = np.arange(len(labels))
            for offset, key in ((-0.2, "h_c"), (0.2, "h_min")):
                if key in result.outputs:
                    values = [1e6 * r[key] if r.get(key) is not None else np.nan for r in result.rows]
                    ax.bar(positions + offset, values, width=0.4, label=key)
            ax.set_xticks(positions, labels, rotation=30, ha="right", fontsize=8)
            ax.set(ylabel="film [µm]", title="film thickness")
            ax.set_ylim(top=1.25 * ax.get_ylim()[1])  # room for the legend above the bars
            ax.legend(fontsize=8, loc="upper center", ncols=2)
    return fig
