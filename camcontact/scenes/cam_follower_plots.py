"""Plots of a cam–follower cycle: SVAJ diagram, cam profile, force breakdown, Hertz pressure and film."""

from __future__ import annotations

import numpy as np

from ..errors import InputError

__all__ = ["plot_cam_follower"]

PANELS = {
    "svaj": ("lift", "follower_velocity", "follower_acceleration"),
    "profile": ("profile_x", "profile_y"),
    "forces": ("contact_force",),
    "pressure": ("p_h",),
    "film": ("h_min",),
}


def plot_cam_follower(result, *, panels=None, figsize=None):
    """Figure with the panels the result has outputs for (or ``panels``, names of :data:`PANELS`).

    One line per variant (film model) in the film panel.
    """
    import matplotlib.pyplot as plt

    outputs = set(result.outputs)
    chosen = [p for p in (panels or PANELS) if set(PANELS.get(p, ("?",))) <= outputs]
    if panels is not None and (unknown := sorted(set(panels) - set(PANELS))):
        raise InputError(f"unknown cam_follower plot panels {unknown}; choose from {sorted(PANELS)}")
    if not chosen:
        raise InputError(f"nothing to plot: ask for the outputs of at least one panel {PANELS}")
    fig, axes = plt.subplots(1, len(chosen), figsize=figsize or (4.2 * len(chosen), 3.8), squeeze=False)
    row = result.rows[0]
    degrees = np.degrees(row["cam_angle"])
    for ax, panel in zip(axes[0], chosen):
        if panel == "svaj":
            for key, scale, label in (("lift", 1e3, "s [mm]"), ("follower_velocity", 1.0, "v [m/s]"),
                                      ("follower_acceleration", 1e-2, "a [100 m/s²]"),
                                      ("follower_jerk", 1e-5, "j [1e5 m/s³]")):
                if key in row:
                    ax.plot(degrees, scale * np.asarray(row[key]), label=label)
            ax.axhline(0.0, color="0.7", lw=0.8)
            ax.set(xlabel="cam angle [deg]", title="SVAJ diagram")
            ax.legend(fontsize=8)
        elif panel == "profile":
            x, y = 1e3 * np.asarray(row["profile_x"]), 1e3 * np.asarray(row["profile_y"])
            ax.plot(np.append(x, x[0]), np.append(y, y[0]))
            ax.plot([0.0], [0.0], "k+")
            ax.set_aspect("equal")
            ax.set(xlabel="x [mm]", ylabel="y [mm]", title="cam profile (contact points)")
        elif panel == "forces":
            for key in ("contact_force", "inertia_force", "spring_force", "damping_force", "preload_force"):
                if key in row:
                    ax.plot(degrees, row[key], label=key.replace("_force", "").replace("contact", "total"),
                            lw=2.0 if key == "contact_force" else 1.0)
            ax.axhline(0.0, color="0.7", lw=0.8)
            ax.set(xlabel="cam angle [deg]", ylabel="force [N]", title="contact force")
            ax.legend(fontsize=8)
        elif panel == "pressure":
            ax.plot(degrees, 1e-6 * np.asarray(row["p_h"]))
            ax.set(xlabel="cam angle [deg]", ylabel="p_h [MPa]", title="Hertz pressure")
        else:
            for label, variant_row in zip(result.variants, result.rows):
                for key, style in (("h_min", "-"), ("h_c", "--")):
                    if key in variant_row:
                        ax.plot(degrees, 1e6 * np.asarray(variant_row[key], dtype=float), style,
                                label=f"{key} {label}".strip())
            ax.set(xlabel="cam angle [deg]", ylabel="film [µm]", title="film over the cycle")
            ax.legend(fontsize=8)
    fig.tight_layout()
    return fig
