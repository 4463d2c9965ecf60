"""Plots of a ball-cone CVT result: maps of the traction over both contacts (FASTSIM: stick and slip; EHL:
the film's shear stress, where the limiting shear bounds it and the slip pole of the spin), the traction
curves with the operating points, the contact losses and efficiency, lives per track."""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .plot_layout import panel_axes

__all__ = ["plot_ball_cone_cvt"]

SECONDS_PER_HOUR = 3600.0
TRACKS = ("life_cone_in", "life_ball_in", "life_ball_out", "life_cone_out", "life_system")


def _outline(ax, a, b):
    """The Hertz ellipse of semi-axes a (rolling, vertical) and b (across, horizontal), in the map's units."""
    t = np.linspace(0, 2 * np.pi, 200)
    ax.plot(b * np.cos(t), a * np.sin(t), "k-", lw=0.8)


def _contact_map(ax, row, side, result):
    """FASTSIM again at the solved creepage (57 us): stick (light) and slip (dark) elements, traction arrows."""
    from ..contact.fastsim import fastsim

    cvt = result.scene.cvt
    shear = cvt.material.si.E / (2.0 * (1.0 + cvt.material.nu))
    spin = row[f"spin_{side}"] if "spin" in result.effects else 0.0
    # the pressure of the FASTSIM that ran for this row's variant (its step's model label "fastsim (<pressure>)")
    variant = result.variants[result.rows.index(row)]
    label = next((r.model for r in result.records if r.step == "traction" and r.variant == variant), "")
    pressure = "hertz" if "(hertz)" in label else "parabolic"
    field = fastsim(row["a_rolling"], row["a_transverse"], row["normal_force"], cvt.traction_coefficient, shear,
                    creepage_x=row[f"creepage_{side}"], spin=spin, nx=24, ny=24, pressure=pressure)
    y = np.broadcast_to(field.y[:, None], field.x.shape)
    scale = 1e3
    ax.scatter(field.y[:, None].repeat(field.x.shape[1], 1) * scale, field.x * scale, c=np.where(field.stick, 0.8, 0.3),
               cmap="RdYlBu", vmin=0, vmax=1, s=12, marker="s")
    arrows = ax.quiver(y * scale, field.x * scale, field.Ty, field.Tx, angles="xy", color="k", width=0.004)
    _arrow_key(ax, arrows, np.hypot(field.Tx, field.Ty))
    _outline(ax, row["a_rolling"] * scale, row["a_transverse"] * scale)
    ax.set_aspect("equal")
    ax.set(xlabel="y (across rolling) [mm]", ylabel="x (rolling) [mm]",
           title=f"FASTSIM, {side}put contact ({row[f'traction_regime_{side}']})\n"
                 f"slip (orange) {100 * row[f'slip_fraction_{side}']:.0f} % of the area, stick blue")


def _arrow_key(ax, arrows, magnitudes):
    """The arrows' scale: a key arrow of a round traction [MPa] above the map."""
    top = float(np.nanmax(magnitudes)) if np.size(magnitudes) else 0.0
    if top > 0.0:
        key = float(f"{0.5 * top / 1e6:.1g}")
        ax.quiverkey(arrows, 0.8, 0.04, key * 1e6, f"{key:g} MPa", labelpos="E", coordinates="axes",
                     fontproperties={"size": 7})


def _ehl_map(ax, row, side, result):
    """The EHL traction of the variant of ``row`` evaluated again for its map: the film's shear stress |tau|
    (colour), its direction (arrows), where the limiting shear stress bounds it (dashed) and the slip pole."""
    import matplotlib.pyplot as plt
    from matplotlib.tri import LinearTriInterpolator, Triangulation

    from ..analysis import Analysis

    k = result.rows.index(row)
    models = result.variant_models[k] if result.variant_models else {}
    again = Analysis(result.scene, outputs=[f"traction_map_{side}"], models=models, effects=result.effects).run()
    field = again[f"traction_map_{side}"]
    scale = 1e3
    tau = np.hypot(field.tx, field.ty) / 1e6
    shaded = ax.tricontourf(field.y * scale, field.x * scale, tau, levels=12, cmap="viridis")
    ax.figure.colorbar(shaded, ax=ax, label="film shear stress |τ| [MPa]", shrink=0.85)
    handles = []
    if field.limited.any() and not field.limited.all():
        ax.tricontour(field.y * scale, field.x * scale, field.limited.astype(float), levels=[0.5], colors="w",
                      linestyles="--", linewidths=1.2)
        handles.append(plt.Line2D([], [], color="k", ls="--", label=f"τ = τ_L outside ({100 * field.limited.mean():.0f} %)"))
    # arrows on a coarse lattice over the ellipse, the traction interpolated linearly between the map's nodes
    triangles = Triangulation(field.y * scale, field.x * scale)
    Yc, Xc = np.meshgrid(np.linspace(-0.9, 0.9, 11) * field.b * scale, np.linspace(-0.9, 0.9, 11) * field.a * scale)
    inside = (Xc / (field.a * scale)) ** 2 + (Yc / (field.b * scale)) ** 2 < 0.85
    ty, tx = (LinearTriInterpolator(triangles, t)(Yc[inside], Xc[inside]) for t in (field.ty, field.tx))
    arrows = ax.quiver(Yc[inside], Xc[inside], ty, tx, angles="xy", color="w", edgecolor="k", linewidth=0.3,
                       width=0.006)
    _arrow_key(ax, arrows, np.hypot(field.tx, field.ty))
    pole_x, pole_y = field.pole
    if abs(pole_x) <= 1.2 * field.a and abs(pole_y) <= 1.2 * field.b:
        handles += ax.plot(pole_y * scale, pole_x * scale, "+", color="magenta", ms=12, mew=2, label="slip pole")
    if handles:
        ax.legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(0.0, -0.16), frameon=False)
    _outline(ax, field.a * scale, field.b * scale)
    ax.set_aspect("equal")
    ax.set(xlabel="y (across rolling) [mm]", ylabel="x (rolling, leading edge up) [mm]",
           title=f"EHL traction, {side}put contact ({row[f'traction_regime_{side}']})\n"
                 f"creepage {100 * abs(row[f'creepage_{side}']):.2f} %, margin {100 * row[f'traction_margin_{side}']:.0f} %")


def _traction_curves(ax, result):
    """Traction coefficient |F_x|/N against creepage of the first variant's input (thick) and output (thin)
    contact, with their spin (solid) and without (dashed), the coefficient the power needs (dotted) and the
    operating point on each curve (or a cross at the curve's end for gross slip)."""
    import matplotlib.pyplot as plt
    from matplotlib.ticker import FuncFormatter

    from ..analysis import Analysis

    names = [f"traction_curve_{side}" for side in ("in", "out")]
    row = result.rows[0]
    if not all(name in row for name in names):  # the curves are computed only when asked for
        models = result.variant_models[0] if result.variant_models else {}
        row = Analysis(result.scene, outputs=names, models=models, effects=result.effects).run().rows[0]
    handles = []
    for side, colour, width in (("in", "tab:blue", 3.0), ("out", "tab:orange", 1.3)):
        curve = row[f"traction_curve_{side}"]
        x = 100.0 * curve.creepage[1:]  # log axis: from the first creepage > 0
        spin = f", spin {curve.spin:.3g} 1/m" if curve.spin else ""
        handles += ax.plot(x, curve.coefficient[1:], color=colour, lw=width, label=f"{side}put contact{spin}")
        if curve.coefficient_no_spin is not None:
            ax.plot(x, curve.coefficient_no_spin[1:], "--", color=colour, lw=width / 2)
        ax.axhline(curve.operating_coefficient, color=colour, ls=":", lw=width / 2)
        if curve.gross_slip:
            handles += ax.plot(x[-1], curve.coefficient[-1], "X", color="crimson", ms=9, zorder=5,
                               label=f"{side}put: gross slip, needs {curve.operating_coefficient:.3g}")
        else:
            handles += ax.plot(100.0 * curve.operating_creepage, curve.operating_coefficient, "o", color=colour,
                               mec="k", zorder=5, label=f"{side}put operating point, {curve.operating_coefficient:.3g}")
    if curve.coefficient_no_spin is not None:
        handles.append(plt.Line2D([], [], color="grey", ls="--", lw=1.0, label="without spin"))
    handles.append(plt.Line2D([], [], color="grey", ls=":", lw=1.0, label="needed |F_t|/N"))
    ax.set_xscale("log")
    ax.xaxis.set_major_formatter(FuncFormatter(lambda value, _: f"{value:g}"))
    ax.set_ylim(bottom=0.0)
    ax.set(xlabel="creepage |ν_x| [%]", ylabel="traction coefficient |F_x|/N [-]",
           title=f"traction curves\n{curve.model}")
    ax.legend(handles=handles, fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=2, frameon=False)


LOSSES = ("creep_loss_in", "spin_loss_in", "creep_loss_out", "spin_loss_out", "efficiency")


def _losses(ax, result):
    """Creep and spin loss of one input and one output contact [W] per variant, the efficiency in the legend."""
    labels = [v or "result" for v in result.variants]
    width = 0.8 / len(labels)
    names = LOSSES[:4]
    for k, (label, row) in enumerate(zip(labels, result.rows)):
        ax.bar(np.arange(len(names)) + k * width, [row[n] for n in names], width=width,
               label=f"{label}: efficiency {100 * row['efficiency']:.1f} %" if np.isfinite(row["efficiency"])
               else f"{label}: gross slip, no efficiency")
    ax.set_xticks(np.arange(len(names)) + 0.4 - width / 2, [n.replace("_loss_", " ") for n in names])
    ax.set(ylabel="power loss per contact [W]", title="contact losses (creep, spin)")
    ax.set_ylim(top=1.3 * ax.get_ylim()[1])  # room for the legend above the bars
    ax.legend(fontsize=8, loc="upper center")


def plot_ball_cone_cvt(result, *, panels=("in", "out", "traction", "losses", "life"), figsize=None, ax=None, fig=None,
                       columns=3):
    """Panels ``"in"``/``"out"``: the traction map of the first variant's input and output contact (FASTSIM:
    stick/slip elements and traction arrows; EHL traction: the film's shear stress, evaluated again for the
    map); ``"traction"``: the first variant's traction curves (:mod:`camcontact.steps.traction_curve`,
    computed again when the result has none) with the operating points; ``"losses"``: creep and spin loss per contact and the drive's
    efficiency, per variant; ``"life"``: L10 [h] per track and of the system, per variant (log scale). In a grid
    of ``columns`` per row, or on the caller's axes (``ax=``, one per panel) or figure (``fig=``)."""
    from matplotlib.ticker import LogFormatter

    contact_needs = ("a_rolling", "a_transverse", "normal_force")
    need = {side: contact_needs + tuple(f"{q}_{side}" for q in ("creepage", "spin", "traction_regime",
                                                                 "traction_margin"))
            for side in ("in", "out")} | {"life": TRACKS, "losses": LOSSES, "traction": ()}
    chosen = [p for p in panels if all(k in result.outputs for k in need[p])]
    if not chosen:
        raise InputError(f"nothing to plot: the panels {list(panels)} need the outputs {need}")
    fig, axes = panel_axes(len(chosen), ax=ax, fig=fig, figsize=figsize, columns=columns, where="ball_cone_cvt plot")
    for ax, panel in zip(axes, chosen):
        if panel in ("in", "out"):  # the first variant's contact, by its traction model
            row = result.rows[0]
            if row.get(f"slip_fraction_{panel}") is not None:
                _contact_map(ax, row, panel, result)
            else:
                _ehl_map(ax, row, panel, result)
        elif panel == "losses":
            _losses(ax, result)
        elif panel == "traction":
            _traction_curves(ax, result)
        else:
            labels = [v or "result" for v in result.variants]
            width = 0.8 / len(labels)
            for k, (label, row) in enumerate(zip(labels, result.rows)):
                ax.bar(np.arange(len(TRACKS)) + k * width, [row[t] / SECONDS_PER_HOUR for t in TRACKS], width=width,
                       label=label)
            ax.set_xticks(np.arange(len(TRACKS)) + 0.4 - width / 2, [t.replace("life_", "") for t in TRACKS],
                          rotation=20)
            ax.set_yscale("log")
            ax.yaxis.set_major_formatter(LogFormatter(labelOnlyBase=False, minor_thresholds=(2, 0.5)))
            ax.yaxis.set_minor_formatter(LogFormatter(labelOnlyBase=False, minor_thresholds=(2, 0.5)))
            ax.set(ylabel="L10 [h]", title="Lundberg-Palmgren life per track")
            if len(labels) > 1:
                ax.legend(fontsize=8)
    return fig
