"""Plots of a bearing result: polar load distribution, contact pressure and film per roller, the pressure along the
most loaded roller of a bearing with its conformities."""

from __future__ import annotations

import numpy as np

from ..contact.geometry import reduced_modulus
from ..contact.roller_profile import solve_laminae
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


def polar_loads(ax, azimuth, loads, title: str, label: str | None = None) -> None:
    """Rolling-element loads [N] over their azimuth [rad] on a polar Axes, in azimuth order, closed, in kN, the radial
    load down (``label``: the trace's, with a legend)."""
    order = np.argsort(np.asarray(azimuth, dtype=float))
    azimuth = np.asarray(azimuth, dtype=float)[order]
    kilo = np.asarray(loads, dtype=float)[order] * 1e-3
    ax.plot(np.append(azimuth, azimuth[0] + 2 * np.pi), np.append(kilo, kilo[0]), marker="o", ms=3, label=label)
    ax.set_theta_zero_location("S")  # the radial load points down
    ax.set_title(title, fontsize=10, pad=14)
    if label is not None:
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0))


def race_panel(ax, row, azimuth, panel: str, element: str, groups=None) -> None:
    """One of :data:`CONTACT_PANELS` per rolling element (one row of elements; or one trace per group of ``groups``,
    (mask, label suffix) pairs, e.g. the bearings of a pair) at the inner and outer raceway against the azimuth [deg]
    (``azimuth`` [rad]), titled per ``element``; Lambda with its regime bands."""
    every = np.ones(np.size(azimuth), dtype=bool)
    key, scale, label, title = CONTACT_PANELS[panel]
    top = 0.0
    for race, style in (("inner", "o"), ("outer", "s")):
        for mask, suffix in groups or [(every, "")]:
            degrees = np.degrees(np.angle(np.exp(1j * np.asarray(azimuth, dtype=float)[mask])))
            order = np.argsort(degrees)
            values = np.asarray(row[f"{key}_{race}"], dtype=float)[mask][order] * scale
            top = max(top, float(np.nanmax(values, initial=0.0)))
            ax.plot(degrees[order], values, marker=style, ms=3, label=race + suffix)
    if panel == "lambda":
        lambda_bands(ax)
        ax.set_ylim(0.0, max(3.0, 1.1 * top))
    ax.set(xlabel="azimuth [deg] (0: load line)", ylabel=label, title=title.replace("per contact", f"per {element}"))
    ax.legend(fontsize=7)


def plot_bearing(result, *, panels=None, figsize=None, ax=None, fig=None, columns=2):
    """Panels: ``"load"`` roller loads over the azimuth (polar, one trace per row), ``"pressure"``
    Hertz p_h at the inner and outer raceway against the azimuth, ``"film"`` h_min per contact, ``"lambda"``
    Lambda per contact with the regime bands (boundary below 1, mixed to 3), ``"along"`` (a bearing with its
    conformities: the default adds it) the lamina pressure along the most loaded roller at both raceways with the
    roller's ends marked; in a grid of ``columns`` per row, or on the caller's axes (``ax=``, one per panel; the
    load panel's polar) or figure (``fig=``)."""
    if panels is None:
        panels = ("load", "pressure", "film", "lambda") + (("along",) if result.scene.bearing.conformal else ())
    need = {"load": ("azimuth", "Q", "roller_row"), "along": ("Q",)} | {
        panel: ("azimuth", f"{key}_inner", f"{key}_outer", "roller_row") for panel, (key, *_) in CONTACT_PANELS.items()}
    chosen = chosen_panels(result, panels, need, "bearing")
    row = result.rows[0]
    fig, axes = panel_axes(len(chosen), ax=ax, fig=fig, figsize=figsize, columns=columns, where="bearing plot",
                           projections=["polar" if panel == "load" else None for panel in chosen])
    rows = np.asarray(row["roller_row"])
    azimuth = np.asarray(row["azimuth"], dtype=float)
    groups = [(rows == k, f"row {int(k)}") for k in np.unique(rows)]
    for ax, panel in zip(axes, chosen):
        if panel == "load":
            for mask, name in groups:
                polar_loads(ax, azimuth[mask], np.asarray(row["Q"], dtype=float)[mask], "roller load Q [kN]", label=name)
        elif panel == "along":
            _along_most_loaded(ax, result)
        else:
            race_panel(ax, row, azimuth, panel, "contact", groups=[(mask, f", {name}") for mask, name in groups])
    return fig


def _along_most_loaded(ax, result) -> None:
    """The lamina pressure along the most loaded roller of a spherical roller bearing with its conformities, at both
    raceways (:func:`camcontact.contact.roller_profile.solve_laminae` with each raceway's gap), roller ends dashed."""
    scene = result.scene
    bearing = scene.bearing
    if not bearing.conformal:
        raise InputError("bearing plot: the pressure along the roller needs the conformities "
                         "(SphericalRollerBearing.conformity_inner / conformity_outer); without them the contacts are "
                         "ideal lines of uniform pressure")
    if bearing.material is None:
        raise InputError("bearing plot: the pressure along the roller needs SphericalRollerBearing.material")
    Q = np.asarray(result.rows[0]["Q"], dtype=float)
    j = int(np.argmax(Q))
    length = bearing.si.roller_length
    E_reduced = reduced_modulus(bearing.material.si.E, bearing.material.nu, bearing.material.si.E, bearing.material.nu)
    top = 0.0
    for race, profile in bearing.raceway_profiles().items():
        laminae = solve_laminae(float(Q[j]), length, bearing.contact_radii[race], E_reduced, profile,
                                laminae=scene.laminae)
        ax.step(1e3 * laminae.y, 1e-6 * laminae.pressure, where="mid", label=f"{race} (f = "
                f"{getattr(bearing, f'conformity_{race}'):.3g})")
        top = max(top, 1e-6 * float(laminae.pressure.max()))
    for end in (-0.5e3 * length, 0.5e3 * length):
        ax.axvline(end, color="0.5", ls="--", lw=0.8)
    ax.set(xlabel="axial position along the roller [mm] (dashed: its ends)", ylabel="lamina pressure [MPa]",
           title=f"pressure along the most loaded roller (Q = {1e-3 * Q[j]:.3g} kN)", ylim=(0.0, 1.2 * top or 1.0))
    ax.legend(fontsize=7, title="raceway", title_fontsize=7)
