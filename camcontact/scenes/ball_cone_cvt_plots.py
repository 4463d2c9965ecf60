"""Plots of a ball-cone CVT result: stick/slip maps with the traction of both contacts (FASTSIM), the
contact losses and efficiency, lives per track."""

from __future__ import annotations

import numpy as np

from ..errors import InputError

__all__ = ["plot_ball_cone_cvt"]

SECONDS_PER_HOUR = 3600.0
TRACKS = ("life_cone_in", "life_ball_in", "life_ball_out", "life_cone_out", "life_system")


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
    ax.quiver(y * scale, field.x * scale, field.Ty, field.Tx, angles="xy", color="k", width=0.004)
    t = np.linspace(0, 2 * np.pi, 200)
    ax.plot(row["a_transverse"] * scale * np.cos(t), row["a_rolling"] * scale * np.sin(t), "k-", lw=0.8)
    ax.set_aspect("equal")
    ax.set(xlabel="y (across rolling) [mm]", ylabel="x (rolling) [mm]",
           title=f"FASTSIM, {side}put contact: slip {100 * row[f'slip_fraction_{side}']:.0f} % of the area\n"
                 f"(blue stick, orange slip; {row[f'traction_regime_{side}'][:12]})")


LOSSES = ("creep_loss_in", "spin_loss_in", "creep_loss_out", "spin_loss_out", "efficiency")


def _losses(ax, result):
    """Creep and spin loss of one input and one output contact [W] per variant, the efficiency in the legend."""
    labels = [v or "result" for v in result.variants]
    width = 0.8 / len(labels)
    names = LOSSES[:4]
    for k, (label, row) in enumerate(zip(labels, result.rows)):
        ax.bar(np.arange(len(names)) + k * width, [row[n] for n in names], width=width,
               label=f"{label}: efficiency {100 * row['efficiency']:.1f} %")
    ax.set_xticks(np.arange(len(names)) + 0.4 - width / 2, [n.replace("_loss_", " ") for n in names])
    ax.set(ylabel="power loss per contact [W]", title="contact losses (creep, spin)")
    ax.legend(fontsize=8)


def plot_ball_cone_cvt(result, *, panels=("in", "out", "losses", "life"), figsize=(16.0, 4.6)):
    """Panels ``"in"``/``"out"``: stick/slip map and traction arrows of the first variant's input and
    output contacts (FASTSIM's outputs); ``"losses"``: creep and spin loss per contact and the drive's
    efficiency, per variant; ``"life"``: L10 [h] per track and of the system, per variant (log scale)."""
    import matplotlib.pyplot as plt

    contact_needs = ("a_rolling", "a_transverse", "normal_force")
    need = {"in": contact_needs + ("creepage_in", "spin_in", "slip_fraction_in", "traction_regime_in"),
            "out": contact_needs + ("creepage_out", "spin_out", "slip_fraction_out", "traction_regime_out"),
            "life": TRACKS, "losses": LOSSES}
    chosen = [p for p in panels if all(k in result.outputs for k in need[p])]
    if not chosen:
        raise InputError(f"nothing to plot: the panels {list(panels)} need the outputs {need}")
    fig, axes = plt.subplots(1, len(chosen), figsize=figsize, squeeze=False)
    for ax, panel in zip(axes[0], chosen):
        if panel in ("in", "out"):  # the first variant that ran FASTSIM
            row = next(r for r in result.rows if r.get(f"slip_fraction_{panel}") is not None)
            _contact_map(ax, row, panel, result)
        elif panel == "losses":
            _losses(ax, result)
        else:
            labels = [v or "result" for v in result.variants]
            width = 0.8 / len(labels)
            for k, (label, row) in enumerate(zip(labels, result.rows)):
                ax.bar(np.arange(len(TRACKS)) + k * width, [row[t] / SECONDS_PER_HOUR for t in TRACKS], width=width,
                       label=label)
            ax.set_xticks(np.arange(len(TRACKS)) + 0.4 - width / 2, [t.replace("life_", "") for t in TRACKS])
            ax.set_yscale("log")
            ax.set(ylabel="L10 [h]", title="Lundberg-Palmgren life per track")
            if len(labels) > 1:
                ax.legend(fontsize=8)
    fig.tight_layout()
    return fig
