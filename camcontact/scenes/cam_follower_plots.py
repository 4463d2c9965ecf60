"""Plots of a cam–follower cycle: SVAJ diagram, cam profile, force breakdown, Hertz pressure, film, the film
parameter Lambda with its regime bands, friction (force, camshaft torque) over the turn, and the film
temperature rise of the thermal transient film."""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .plot_layout import lambda_bands, panel_axes

__all__ = ["plot_cam_follower"]

PANELS = {
    "svaj": ("lift", "follower_velocity", "follower_acceleration"),
    "profile": ("profile_x", "profile_y"),
    "forces": ("contact_force",),
    "pressure": ("p_h",),
    "film": ("h_min",),
    "lambda": ("Lambda_min",),
    "friction": ("friction_force",),
    "stribeck": ("friction_coefficient", "Lambda_min"),
    "film_temperature": ("film_temperature_rise",),
}


def _lambda_panel(ax, result, degrees) -> None:
    top = 3.0
    for label, row in zip(result.variants, result.rows):
        values = np.asarray(row["Lambda_min"], dtype=float)
        top = max(top, float(np.nanmax(values)) * 1.05)
        ax.plot(degrees, values, label=f"Λ_min {label}".strip())
    lambda_bands(ax)
    ax.set(xlabel="cam angle [deg]", ylabel="Λ = h_min / σ [-]", title="film parameter", ylim=(0.0, top))
    ax.legend(fontsize=8)


def _stribeck_panel(ax, result) -> None:
    """Friction coefficient against the film parameter over the turn (the cycle's Stribeck view), coloured
    by the lubrication regime where the ``mixed`` effect gives one."""
    for label, row in zip(result.variants, result.rows):
        lam = np.asarray(row.get("Lambda_mixed", row["Lambda_min"]), dtype=float)
        mu = np.asarray(row["friction_coefficient"], dtype=float)
        regimes = np.asarray(row.get("lubrication_regime", np.full(lam.size, "")), dtype=object)
        for regime in dict.fromkeys(regimes):
            chosen = regimes == regime
            ax.plot(lam[chosen], mu[chosen], ".", label=f"{regime or 'angles'} {label}".strip())
    lambda_bands(ax, vertical=True, labelled=False)
    ax.set(xlabel="Λ [-]", ylabel="friction coefficient [-]", title="Stribeck view of the turn")
    ax.legend(fontsize=8)


def _friction_panel(ax, result, degrees) -> None:
    torque_ax = ax.twinx() if any("friction_torque" in row for row in result.rows) else None
    lines = []
    for label, row in zip(result.variants, result.rows):
        lines += ax.plot(degrees, row["friction_force"], label=f"force {label}".strip())
        if torque_ax is not None and "friction_torque" in row:
            lines += torque_ax.plot(degrees, row["friction_torque"], "--", color=lines[-1].get_color(),
                                    label=f"camshaft torque {label}".strip())
    ax.axhline(0.0, color="0.7", lw=0.8)
    ax.set(xlabel="cam angle [deg]", ylabel="friction force [N]", title="friction over the turn")
    if torque_ax is not None:
        torque_ax.set_ylabel("camshaft friction torque [N·m] (dashed)")
    ax.legend(lines, [line.get_label() for line in lines], fontsize=8)


def plot_cam_follower(result, *, panels=None, figsize=None, ax=None, fig=None, columns=3):
    """Figure with the panels the result has outputs for (or ``panels``, names of :data:`PANELS`), in a grid of
    ``columns`` per row, or on the caller's axes (``ax=``, one per panel) or figure (``fig=``).

    One line per variant (film model) in the film, Lambda and friction panels.
    """
    outputs = set(result.outputs)
    chosen = [p for p in (panels or PANELS) if set(PANELS.get(p, ("?",))) <= outputs]
    if panels is not None and (unknown := sorted(set(panels) - set(PANELS))):
        raise InputError(f"unknown cam_follower plot panels {unknown}; choose from {sorted(PANELS)}")
    if not chosen:
        raise InputError(f"nothing to plot: ask for the outputs of at least one panel {PANELS}")
    fig, axes = panel_axes(len(chosen), ax=ax, fig=fig, figsize=figsize, columns=columns, where="cam_follower plot")
    row = result.rows[0]
    degrees = np.degrees(row["cam_angle"])
    for ax, panel in zip(axes, chosen):
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
        elif panel == "lambda":
            _lambda_panel(ax, result, degrees)
        elif panel == "friction":
            _friction_panel(ax, result, degrees)
        elif panel == "stribeck":
            _stribeck_panel(ax, result)
        elif panel == "film_temperature":
            for label, variant_row in zip(result.variants, result.rows):
                ax.plot(degrees, np.asarray(variant_row["film_temperature_rise"], dtype=float), label=label or None)
            ax.set(xlabel="cam angle [deg]", ylabel="largest film temperature rise [K]",
                   title="film temperature (thermal transient)")
            if any(result.variants):
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
    return fig
