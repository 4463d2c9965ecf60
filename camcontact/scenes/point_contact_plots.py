"""Plots of a point-contact result: pressure and film through the centre, stresses below it, films per model."""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .plot_layout import panel_axes

__all__ = ["plot_point_contact"]

NEEDS = {"pressure": ("a_rolling", "a_transverse", "p_h"), "stress": ("a_rolling", "a_transverse", "p_h"),
         "film": ()}


def _solutions(result):
    """(variant, numerical film solution) of each variant whose film model is the point solver: from the
    result where it was asked for, else solved again with the variant's models (formulas give none)."""
    from ..analysis import Analysis

    found = []
    for k, (label, row) in enumerate(zip(result.variants, result.rows)):
        model = next((r.model for r in result.records if r.step == "film" and r.variant == label), "")
        if "film_solution" in row:
            solution = row["film_solution"]
        elif model == "multigrid_point":
            models = result.variant_models[k] if result.variant_models else {}
            solution = Analysis(result.scene, outputs=["film_solution"], models=models,
                                effects=result.effects).run()["film_solution"]
        else:
            solution = None
        if solution is not None:
            found.append((label, solution))
    return found


def _pressure(ax, result):
    """Hertz pressure along and across rolling through the centre [MPa] against position [µm]; each numerical
    variant's centre-line pressure and film (on a twin axis) along rolling."""
    row = result.rows[0]
    a, b = row["a_rolling"], row["a_transverse"]
    s = np.linspace(-1.5, 1.5, 301)
    hertz = row["p_h"] * 1e-6 * np.sqrt(np.clip(1.0 - s**2, 0.0, None))
    ax.plot(s * a * 1e6, hertz, "k-", label="Hertz, along rolling (x)")
    ax.plot(s * b * 1e6, hertz, "k--", lw=1.0, label="Hertz, across (y)")
    from ..contact.geometry import reduced_modulus

    m1, m2 = result.scene.body1.material, result.scene.body2.material
    modulus = reduced_modulus(m1.si.E, m1.nu, m2.si.E, m2.nu)
    twin = None
    for label, solution in _solutions(result):
        fields = solution.dimensional(result.scene.reduced_radii[0], result.scene.si.load, modulus)
        X, P, H = solution.centreline
        ax.plot(X * fields["a"] * 1e6, P * fields["p_h"] * 1e-6, label=f"{label or 'numerical'}: pressure")
        twin = twin or ax.twinx()
        twin.plot(X * fields["a"] * 1e6, H * (fields["h_c"] / solution.H_c) * 1e6, ":",
                  label=f"{label or 'numerical'}: film")
    ax.set(xlabel="position from the centre [µm]", ylabel="p [MPa]",
           title=f"pressure through the centre\na = {a * 1e6:.4g} µm (rolling), b = {b * 1e6:.4g} µm")
    handles, labels = ax.get_legend_handles_labels()
    if twin is not None:
        twin.set_ylabel("film h [µm] (dotted)")
        low = np.nanmin([line.get_ydata().min() for line in twin.get_lines()])
        twin.set_ylim(0.0, 4.0 * low)
        more = twin.get_legend_handles_labels()
        handles, labels = handles + more[0], labels + more[1]
    ax.legend(handles, labels, fontsize=7, loc="upper left")


def _stresses(ax, result):
    """Tresca shear and von Mises stress / p_h on the axis below the centre against depth / minor semi-axis."""
    from ..contact.subsurface_point import point_axis_stresses

    row = result.rows[0]
    a, b, p_h = row["a_rolling"], row["a_transverse"], row["p_h"]
    minor = min(a, b)
    zeta = np.linspace(0.02, 3.0, 120)
    sx, sy, sz = point_axis_stresses(zeta * minor, a, b, 1.0, result.scene.body1.material.nu)
    tresca = 0.5 * np.max(np.abs([sx - sy, sy - sz, sz - sx]), axis=0)
    mises = np.sqrt(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2))
    ax.plot(tresca, zeta, label="Tresca shear (σ1 - σ3)/2")
    ax.plot(mises, zeta, label="von Mises")
    for key, colour in (("tresca_max", "tab:blue"), ("von_mises_max", "tab:orange")):
        if key in row:
            ax.plot(row[key] / p_h, row[f"z_{key}"] / minor, "o", color=colour, mec="k")
    ax.invert_yaxis()
    ax.set(xlabel="stress / p_h [-]", ylabel="depth z / minor semi-axis [-]",
           title=f"stresses below the centre (p_h {p_h * 1e-6:.4g} MPa)")
    ax.legend(fontsize=8, loc="lower right")


def _films(ax, result):
    """Central and minimum film per variant [µm], with Lambda of the smaller where known."""
    labels = [v or "film" for v in result.variants]
    positions = np.arange(len(labels))
    for offset, key in ((-0.2, "h_c"), (0.2, "h_min")):
        values = [1e6 * r[key] if r.get(key) is not None else np.nan for r in result.rows]
        ax.bar(positions + offset, values, width=0.4, label=key)
    for k, row in enumerate(result.rows):
        name = next((q for q in ("Lambda_min", "Lambda_c") if q in row and np.isfinite(row[q])), None)
        if name is not None:
            top = np.nanmax([row.get(q, np.nan) for q in ("h_c", "h_min")]) * 1e6
            ax.annotate(f"Λ_{name[7:]} = {row[name]:.3g}", (k, top), ha="center", va="bottom", fontsize=8)
    ax.set_xticks(positions, labels, rotation=20, ha="right", fontsize=8)
    ax.set(ylabel="film [µm]", title="film thickness per model")
    ax.set_ylim(top=1.3 * ax.get_ylim()[1])  # room for the legend above the bars
    ax.legend(fontsize=8, loc="upper center", ncols=2)


def plot_point_contact(result, *, panels=("pressure", "stress", "film"), figsize=None, ax=None, fig=None, columns=3):
    """Panels ``"pressure"``: the Hertz pressure along and across rolling through the centre, and each
    numerical variant's centre-line pressure and film; ``"stress"``: Tresca shear and von Mises stress below
    the centre against depth (the maxima marked); ``"film"``: h_c and h_min per variant with Lambda. In a grid
    of ``columns`` per row, or on the caller's axes (``ax=``, one per panel) or figure (``fig=``)."""
    unknown = [p for p in panels if p not in NEEDS]
    if unknown:
        raise InputError(f"point_contact plot: panels {unknown}; allowed: {', '.join(NEEDS)}")
    chosen = [p for p in panels if all(k in result.outputs for k in NEEDS[p])
              and (p != "film" or {"h_c", "h_min"} & set(result.outputs))]
    if not chosen:
        raise InputError(f"nothing to plot: the panels {list(panels)} need the outputs {NEEDS} (film: h_c or h_min)")
    fig, axes = panel_axes(len(chosen), ax=ax, fig=fig, figsize=figsize, columns=columns, where="point_contact plot")
    draw = {"pressure": _pressure, "stress": _stresses, "film": _films}
    for axis, panel in zip(axes, chosen):
        draw[panel](axis, result)
    return fig
