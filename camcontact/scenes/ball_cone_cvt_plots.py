"""Plots of a ball-cone CVT result: stick/slip maps with the traction of both contacts, lives per track."""

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
    field = fastsim(row["a_rolling"], row["a_transverse"], row["normal_force"], cvt.traction_coefficient, shear,
                    creepage_x=row[f"creepage_{side}"], spin=spin, nx=24, ny=24)
    y = np.broadcast_to(field.y[:, None], field.x.shape)
    scale = 1e3
    ax.scatter(field.y[:, None].repeat(field.x.shape[1], 1) * scale, field.x * scale, c=np.where(field.stick, 0.8, 0.3),
               cmap="RdYlBu", vmin=0, vmax=1, s=12, marker="s")
    ax.quiver(y * scale, field.x * scale, field.Ty, field.Tx, angles="xy", color="k", width=0.004)
    t = np.linspace(0, 2 * np.pi, 200)
    ax.plot(row["a_transverse"] * scale * np.cos(t), row["a_rolling"] * scale * np.sin(t), "k-", lw=0.8)
    ax.set_aspect("equal")
    ax.set(xlabel="y (across rolling) [mm]", ylabel="x (rolling) [mm]",
           title=f"{side}put contact: slip {100 * row[f'slip_fraction_{side}']:.0f} % of the area\n"
                 f"(blue stick, orange slip; {row[f'traction_regime_{side}'][:12]})")


def plot_ball_cone_cvt(result, *, panels=("in", "out", "life"), figsize=(14.0, 4.6)):
    """Panels ``"in"``/``"out"``: stick/slip map and traction arrows of the first variant's input and
    output contacts (needs the traction outputs); ``"life"``: L10 [h] per track and of the system, per
    variant (log scale)."""
    import matplotlib.pyplot as plt

    contact_needs = ("a_rolling", "a_transverse", "normal_force")
    need = {"in": contact_needs + ("creepage_in", "spin_in", "slip_fraction_in", "traction_regime_in"),
            "out": contact_needs + ("creepage_out", "spin_out", "slip_fraction_out", "traction_regime_out"),
            "life": TRACKS}
    chosen = [p for p in panels if all(k in result.outputs for k in need[p])]
    if not chosen:
        raise InputError(f"nothing to plot: the panels {list(panels)} need the outputs {need}")
    fig, axes = plt.subplots(1, len(chosen), figsize=figsize, squeeze=False)
    for ax, panel in zip(axes[0], chosen):
        if panel in ("in", "out"):
            _contact_map(ax, result.rows[0], panel, result)
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
