"""The axes a scene plot draws its panels on: a grid of at most ``columns`` panels per row in a new figure, the
axes the caller passes (``ax=`` one Axes or a sequence, one per panel), or new axes in the caller's figure
(``fig=``). Every scene plotter takes these, so its panels can go into a report's own layout."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from ..errors import InputError

__all__ = ["LAMBDA_BANDS", "lambda_bands", "panel_axes"]

#: width and height of one panel [in]
PANEL_SIZE = (4.6, 3.6)
#: Lambda bands: boundary below 1, mixed between 1 and 3, full film above 3 (Hamrock, Schmid & Jacobson 2004)
LAMBDA_BANDS = ((0.0, 1.0, "tab:red", "boundary"), (1.0, 3.0, "tab:orange", "mixed"))


def lambda_bands(ax: Any, *, vertical: bool = False, labelled: bool = True) -> None:
    """Shade the Lambda regime bands on ``ax``: across the y axis (Lambda on y), or along x (``vertical``)."""
    span = ax.axvspan if vertical else ax.axhspan
    for low, high, colour, name in LAMBDA_BANDS:
        span(low, high, color=colour, alpha=0.12, **({"label": name} if labelled else {}))


def panel_axes(count: int, *, ax: Any = None, fig: Any = None, figsize: tuple[float, float] | None = None,
               columns: int = 3, where: str = "plot",
               projections: Sequence[str | None] | None = None) -> tuple[Any, list[Any]]:
    """(figure, axes) for ``count`` panels; ``ax`` (an Axes, or one per panel) or ``fig`` (a Figure to add a grid
    to) are the caller's; otherwise a new figure of ceil(count/columns) rows (``figsize``: its size [in]).
    ``projections``: per panel None or a projection name (``"polar"``); a caller's Axes must have it."""
    import matplotlib.pyplot as plt

    projections = list(projections) if projections is not None else [None] * count
    if ax is not None and fig is not None:
        raise InputError(f"{where}: give ax= or fig=, not both")
    if ax is not None:
        axes = list(ax.flat) if hasattr(ax, "flat") else list(ax) if isinstance(ax, Sequence) else [ax]
        if len(axes) != count:
            raise InputError(f"{where}: ax= gives {len(axes)} axes for {count} panels; allowed: one Axes per panel")
        for axis, projection in zip(axes, projections):
            if projection is not None and axis.name != projection:
                raise InputError(f"{where}: a panel needs a {projection} Axes, got a {axis.name} one "
                                 f"(plt.subplot(projection={projection!r}))")
        return axes[0].figure, axes
    cols = max(1, min(columns, count))
    rows = math.ceil(count / cols)
    if fig is not None:
        if fig.axes:
            raise InputError(f"{where}: fig= already has {len(fig.axes)} axes, which the panels would cover; give an "
                             "empty figure (or a subfigure), or the axes to draw on as ax=")
        if figsize is not None:
            raise InputError(f"{where}: figsize= with fig=: the figure has its size (fig.set_size_inches)")
        if hasattr(fig, "set_layout_engine") and fig.get_layout_engine() is None:  # a SubFigure has its parent's
            fig.set_layout_engine("constrained")
    else:
        fig = plt.figure(figsize=figsize or (PANEL_SIZE[0] * cols, PANEL_SIZE[1] * rows), layout="constrained")
        fig.get_layout_engine().set(wspace=0.08, hspace=0.06)  # room between a twin axis' label and the next panel
    grid = fig.add_gridspec(rows, cols)
    return fig, [fig.add_subplot(grid[k // cols, k % cols], projection=projection)
                 for k, projection in enumerate(projections)]
