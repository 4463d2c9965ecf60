"""Efficiency and traction-margin maps of a ball-cone CVT over ratio x power (and ball size).

A traction drive is designed on two maps: where it transmits the power at all (the traction margin
1 - F_t/capacity of its weaker contact > 0; below it the balls slip grossly) and how much of the power
it loses there (efficiency 1 - n (P_in + P_out)/P, creep and spin losses of every contact). Both follow
from the scene (:mod:`camcontact.scenes.ball_cone_cvt`) swept over its operating points; the Hertz
pressure against the CVT's contact-stress limit marks the points the balls and cones would not survive.

:func:`cvt_map` is that sweep (one table row per ratio x power [x ball diameter]);
:func:`plot_cvt_map` draws it: efficiency and traction margin as filled contours over the ratio and the
power, the margin's zero line (the gross-slip boundary), gross-slip points marked x, points above the
stress limit circled, one row of panels per ball diameter.

Status is data in the table: ``gross_slip`` (either contact), ``stress_limit_exceeded`` (booleans) and
``traction_margin`` (the smaller of the two contacts'), beside the per-contact columns.
"""

from __future__ import annotations

import numbers
import warnings
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import numpy as np

from ..components.ball_cone_cvt import LoadedBallConeCVT
from ..errors import InputError, ValidityWarning
from ..sweep_cases import evolve_path
from .plot_layout import panel_axes

__all__ = ["MAP_OUTPUTS", "cvt_map", "plot_cvt_map"]

#: the scene outputs of each map point
MAP_OUTPUTS = ("efficiency", "power_loss", "traction_margin_in", "traction_margin_out", "gross_slip_in",
               "gross_slip_out", "stress_limit_exceeded", "p_h", "normal_force", "creepage_in", "creepage_out",
               "creep_loss_in", "creep_loss_out", "spin_loss_in", "spin_loss_out")
RATIO, POWER, BALL = "ratio [-]", "power [W]", "cvt.ball_diameter [mm]"


def _axis(scene: LoadedBallConeCVT, path: str, values: Any, name: str, unit: str | None = None,
          per_si: float = 1.0) -> list[Any]:
    """The values of one map axis, each checked by the component itself (an InputError naming the field, the
    value and what is allowed, before anything runs); with ``unit`` (plain numbers are in it) each as a
    string in ``unit`` (``per_si`` of them per SI unit), so that the table's column has one unit."""
    if hasattr(values, "units"):  # a Quantity (array): one quantity per value
        values = [magnitude * values.units for magnitude in np.atleast_1d(values.magnitude)]
    if isinstance(values, (str, bytes)) or not isinstance(values, Iterable):
        raise InputError(f"cvt_map: {name} = {values!r}; allowed: a list of values (or a Quantity array)")
    values = list(values)
    if not values:
        raise InputError(f"cvt_map: {name} is empty; allowed: at least one value")
    checked = []
    for value in values:
        if unit is not None and isinstance(value, numbers.Real) and not isinstance(value, bool):
            value = f"{float(value)!r} {unit}"
        evolved = evolve_path(scene, path, value)
        if unit is not None:
            owner = evolved
            for head in path.split(".")[:-1]:
                owner = getattr(owner, head)
            value = f"{getattr(owner.si, path.split('.')[-1]) * per_si!r} {unit}"
        checked.append(value)
    return checked


def cvt_map(scene: LoadedBallConeCVT, ratios: Sequence[float], powers: Any, *, ball_diameters: Any = None,
            models: Mapping[str, Any] | None = None, effects: Iterable[str] | None = None,
            progress: bool | None = False, executor: Any = None):
    """The CVT of ``scene`` over ratio x power (x ball diameter): one pandas DataFrame row per point.

    Parameters
    ----------
    scene : LoadedBallConeCVT
        The CVT and the operating point the others are varied from (input speed, temperature).
    ratios : sequence of float
        Ratios in the CVT's ratio convention, each within its tilt range (:attr:`BallConeCVT.ratio_range`).
    powers : sequence of Quantity, str or float, or a power Quantity array
        Transmitted powers (> 0; numbers are W).
    ball_diameters : sequence of Quantity or str, optional
        Ball diameters (lengths); default the CVT's own.
    models, effects
        The scene's model slots and effects (default: the scene's, EHL traction with spin).
    progress, executor
        As :meth:`camcontact.analysis.Analysis.sweep`.

    Returns
    -------
    pandas.DataFrame
        ``ratio [-]``, ``power [W]`` (``cvt.ball_diameter [mm]`` when given), the :data:`MAP_OUTPUTS`
        as ``"name [unit]"``, ``traction_margin [-]`` (the smaller contact's), ``gross_slip`` (either
        contact slips grossly) and ``error`` (empty, or why a point failed: its row stays, with NaN).
        The stress-limit warnings of the points are not repeated: ``stress_limit_exceeded`` holds them.
    """
    from ..analysis import Analysis

    if not isinstance(scene, LoadedBallConeCVT):
        raise InputError(f"cvt_map: scene = {type(scene).__name__}; allowed: a LoadedBallConeCVT")
    grid = {"ratio": _axis(scene, "ratio", ratios, "ratios"),
            "power": _axis(scene, "power", powers, "powers", unit="W")}
    if ball_diameters is not None:
        grid["cvt.ball_diameter"] = _axis(scene, "cvt.ball_diameter", ball_diameters, "ball_diameters", unit="mm",
                                          per_si=1e3)
    analysis = Analysis(scene, outputs=list(MAP_OUTPUTS), models=dict(models or {}),
                        effects=None if effects is None else set(effects))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)  # the stress limit: the stress_limit_exceeded column
        frame = analysis.sweep(grid, progress=progress, executor=executor, table="cases",
                               units={"power_loss": "W", "normal_force": "N", "p_h": "MPa"})
    margins = frame[["traction_margin_in [-]", "traction_margin_out [-]"]].to_numpy(dtype=float)
    at = frame.columns.get_loc("traction_margin_out [-]") + 1
    frame.insert(at, "traction_margin [-]", np.min(margins, axis=1))
    slips = frame[["gross_slip_in", "gross_slip_out"]]
    frame.insert(frame.columns.get_loc("gross_slip_out") + 1, "gross_slip",
                 slips.fillna(False).astype(bool).any(axis=1))
    return frame


def _grid_of(frame, column: str, ratios: np.ndarray, powers: np.ndarray) -> np.ndarray:
    """``column`` of a map as a (power, ratio) array (NaN where a point failed)."""
    table = frame.pivot_table(index=POWER, columns=RATIO, values=column, aggfunc="first", dropna=False)
    return table.reindex(index=powers, columns=ratios).to_numpy(dtype=float)


def plot_cvt_map(frame, *, figsize: tuple[float, float] | None = None, ax: Any = None, fig: Any = None):
    """Efficiency (left) and traction margin (right) of a :func:`cvt_map` over ratio (x) and power (y, log
    when the powers span more than a decade), one row per ball diameter: filled contours with labelled
    lines; on both panels the margin's zero line (the gross-slip boundary, bold) with the side where the
    drive cannot transmit the power hatched (the feasible side is the clear one), gross-slip points ``x``
    and points above the contact-stress limit hatched the other way. On new axes (``figsize`` [in]), the
    caller's (``ax=``: two per ball diameter, row by row) or the caller's figure (``fig=``). Returns the
    Figure."""
    import matplotlib.pyplot as plt
    from matplotlib.patches import Patch
    from matplotlib.ticker import FuncFormatter, MaxNLocator

    needed = (RATIO, POWER, "efficiency [-]", "traction_margin [-]", "gross_slip", "stress_limit_exceeded")
    missing = [c for c in needed if c not in frame.columns]
    if missing:
        raise InputError(f"plot_cvt_map: the frame lacks {missing}; allowed: a cvt_map frame")
    ratios = np.unique(frame[RATIO].to_numpy(dtype=float))
    powers = np.unique(frame[POWER].to_numpy(dtype=float))
    if ratios.size < 2 or powers.size < 2:
        raise InputError(f"plot_cvt_map: {ratios.size} ratio(s) x {powers.size} power(s); a map needs at least "
                         "two of each")
    balls = np.unique(frame[BALL].to_numpy(dtype=float)) if BALL in frame.columns else np.array([np.nan])
    fig, axes = panel_axes(2 * balls.size, ax=ax, fig=fig, columns=2, where="plot_cvt_map",
                           figsize=figsize or (None if ax is not None or fig is not None else (11.0, 4.2 * balls.size)))
    R, W = np.meshgrid(ratios, powers)
    plain = FuncFormatter(lambda value, _: f"{value:g}")
    for row, ball in zip(np.reshape(axes, (balls.size, 2)), balls):
        part = frame if np.isnan(ball) else frame[frame[BALL] == ball]
        slip = _grid_of(part, "gross_slip", ratios, powers) > 0.5
        over = _grid_of(part, "stress_limit_exceeded", ratios, powers)
        margin = 100.0 * _grid_of(part, "traction_margin [-]", ratios, powers)
        for ax, column, title, cmap in ((row[0], "efficiency [-]", "drive efficiency", "viridis"),
                                        (row[1], "traction_margin [-]", "traction margin 1 - F_t/capacity",
                                         "RdYlGn")):
            values = 100.0 * _grid_of(part, column, ratios, powers)
            finite = values[np.isfinite(values)]
            if finite.size:
                levels = MaxNLocator(nbins=10).tick_values(finite.min(), finite.max())
                filled = ax.contourf(R, W, values, levels=levels, cmap=cmap, extend="both")
                lines = ax.contour(R, W, values, levels=levels[::2], colors="k", linewidths=0.5)
                ax.clabel(lines, fmt="%g", fontsize=7)
                ax.figure.colorbar(filled, ax=ax, label=f"{title} [%]")
            else:  # e.g. no efficiency anywhere: the drive slips at every point
                ax.text(0.5, 0.5, f"no finite {column}", transform=ax.transAxes, ha="center",
                        bbox={"facecolor": "w", "edgecolor": "none"})
            handles = []
            if np.nanmin(margin, initial=np.inf) < 0.0:  # the side that cannot transmit the power
                ax.contourf(R, W, np.nan_to_num(margin, nan=-1.0), levels=[-np.inf, 0.0], colors="none",
                            hatches=["\\\\"])
                handles.append(Patch(facecolor="none", edgecolor="k", hatch="\\\\",
                                     label="margin < 0: gross slip (infeasible)"))
                if np.nanmax(margin, initial=-np.inf) > 0.0:
                    ax.contour(R, W, margin, levels=[0.0], colors="k", linewidths=2.0)
                    handles.append(plt.Line2D([], [], color="k", lw=2.0, label="margin 0 (gross-slip boundary)"))
            if np.nanmax(over, initial=0.0) > 0.5:
                ax.contourf(R, W, np.nan_to_num(over), levels=[0.5, 1.5], colors="none", hatches=["///"])
                handles.append(Patch(facecolor="none", edgecolor="k", hatch="///", label="p_h above stress limit"))
            if slip.any():
                handles.append(ax.plot(R[slip], W[slip], "x", color="crimson", ms=7, mew=1.5,
                                       label="gross slip")[0])
            if powers.max() > 10.0 * powers.min():
                ax.set_yscale("log")
                ax.yaxis.set_major_formatter(plain)
                ax.yaxis.set_minor_formatter(FuncFormatter(
                    lambda value, _: f"{value:g}" if str(f"{value:g}")[0] in "25" else ""))
            where = "" if np.isnan(ball) else f", ball {ball:g} mm"
            ax.set(xlabel="ratio [-]", ylabel="power [W]", title=f"{title} [%]{where}")
            if handles:
                ax.legend(handles=handles, fontsize=7, loc="lower right", framealpha=0.85)
    return fig
