"""A plot of a sweep's table: each output against the first swept value, one line per combination of the other
swept values (cam studies: their cycle summaries, one point per case).

``camcontact sweep --plot study.png`` draws it for a scene file's ``[sweep]``; :func:`plot_sweep` for any table of
:func:`camcontact.sweep.run_sweep` / :meth:`camcontact.analysis.Analysis.sweep`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from .errors import InputError
from .report_export import split_header
from .scenes.plot_layout import panel_axes

__all__ = ["plot_sweep"]

#: columns of a sweep table that are neither swept values nor outputs
STATUS = ("case", "variant", "failed", "error", "not_given")


def _setting(header: str, value: Any) -> str:
    """``"follower.roller_radius [mm]"``, 8.0 -> ``"follower.roller_radius 8 mm"``; text as it is."""
    if not isinstance(value, (int, float, np.number)):
        return str(value)
    name, unit = split_header(header)
    return f"{name} {value:g}" + (f" {unit}" if unit else "")


def plot_sweep(frame: Any, outputs: Sequence[str] | None = None, *, x: str | None = None, ax: Any = None,
               fig: Any = None, figsize: tuple[float, float] | None = None, columns: int = 3,
               max_panels: int = 9) -> Any:
    """Figure of the sweep table ``frame``: a panel per output column (``outputs``: headers; default the numeric
    outputs, at most ``max_panels``) against ``x`` (default the first swept column, ``frame.attrs["dimensions"]``),
    a line per combination of the other swept columns and variants; failed cases are left out (their rows have
    no values). A per-index table (cam angle, roller) is plotted by its cases' summaries: the outputs that do
    not vary along the index, one point per case."""
    dims = list(frame.attrs.get("dimensions", []))
    index = frame.attrs.get("index")
    swept = [d for d in dims if d not in (index, "variant")]
    if x is None:
        if not swept:
            raise InputError("plot_sweep: the table records no swept columns (a table read from a file): give x=")
        x = swept[0]
    if x not in frame.columns:
        raise InputError(f"plot_sweep: x = {x!r} is not a column; allowed: {list(frame.columns)}")
    numeric = [c for c in frame.columns if c not in (*STATUS, *dims, index) and frame[c].dtype.kind in "fi"
               and frame[c].notna().any()]
    if index is not None:  # one row per case and variant: the summaries (outputs that vary along the index out)
        keys = ["case", *(["variant"] if "variant" in frame else [])]
        varying = frame.groupby(keys)[numeric].nunique(dropna=False).max()
        numeric = [c for c in numeric if varying[c] <= 1]
        frame = frame.drop_duplicates(subset=keys)
    others = [d for d in swept if d != x] + (["variant"] if "variant" in frame.columns else [])
    chosen = list(outputs) if outputs is not None else numeric[:max_panels]
    unknown = [c for c in chosen if c not in numeric]
    if unknown or not chosen:
        raise InputError(f"plot_sweep: outputs {unknown or chosen}; allowed: numeric output columns {numeric}")
    fig, axes = panel_axes(len(chosen), ax=ax, fig=fig, figsize=figsize, columns=columns, where="sweep plot")
    groups = list(frame.groupby(others, sort=True)) if others else [((), frame)]
    for axis, column in zip(axes, chosen):
        for key, part in groups:
            key = key if isinstance(key, tuple) else (key,)
            label = ", ".join(_setting(name, value) for name, value in zip(others, key))
            part = part.sort_values(x)
            axis.plot(part[x], part[column], marker="o", ms=3, label=label or None)
        axis.set(xlabel=x, ylabel=column, title=split_header(column)[0])
        if others:
            axis.legend(fontsize=7)
    return fig
