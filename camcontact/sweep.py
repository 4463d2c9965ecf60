"""Parameter sweeps of a scene: the cartesian product of field values, one Analysis per case, one tidy table.

A grid maps *paths* of scene fields to the values to try; a path names a field of the scene
component or, through dots, of a component inside it (``"power"``, ``"cvt.ball_diameter"``,
``"cvt.material.E"``). Values are what the field accepts (Quantities, strings with units, numbers).

>>> from camcontact.sweep import evolve_path
>>> import camcontact as cc
>>> steel = cc.Material(E="210 GPa", nu=0.3)
>>> evolve_path(steel, "E", "200 GPa").si.E
200000000000.0
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import attrs

from .analysis import Analysis
from .errors import InputError

__all__ = ["evolve_path", "sweep_frame"]


def evolve_path(component: Any, path: str, value: Any) -> Any:
    """A copy of ``component`` with the field at the dotted ``path`` set to ``value`` (validated anew)."""
    head, _, rest = path.partition(".")
    if not attrs.has(type(component)):
        raise InputError(f"sweep path {path!r}: {type(component).__name__} has no fields")
    names = [field.name for field in attrs.fields(type(component))]
    if head not in names:
        raise InputError(f"sweep path {path!r}: {type(component).__name__} has no field {head!r}; "
                         f"fields: {', '.join(names)}")
    new = value if not rest else evolve_path(getattr(component, head), rest, value)
    return attrs.evolve(component, **{head: new})


def _label(value: Any) -> Any:
    """A table-friendly form of a swept value (numbers stay numbers, the rest becomes text)."""
    return value if isinstance(value, (int, float, str)) else str(value)


def sweep_frame(scene: Any, grid: Mapping[str, Sequence[Any]], *, outputs: Iterable[str] | None = None,
                models: Mapping[str, Any] | None = None, effects: Iterable[str] | None = None,
                units: Mapping[str, str] | None = None, errors: str = "record"):
    """Run ``scene`` over the cartesian product of ``grid`` and return one pandas DataFrame.

    One row per case: the swept values in columns named by their paths, then the scalar outputs
    (``"name [unit]"``, :meth:`~camcontact.analysis.Result.summary_frame` for scenes with an
    index) and ``error``: empty, or the message of the :class:`~camcontact.errors.InputError`
    that case raised (``errors="raise"`` re-raises it instead). A case that fails loses nothing
    of the others.
    """
    import pandas as pd

    if errors not in ("record", "raise"):
        raise InputError(f"sweep_frame: errors = {errors!r}; allowed: 'record', 'raise'")
    paths = list(grid)
    if not paths:
        raise InputError("sweep_frame: the grid is empty; give {path: [values, ...]}")
    rows = []
    for combination in itertools.product(*(grid[p] for p in paths)):
        row: dict[str, Any] = {path: _label(value) for path, value in zip(paths, combination)}
        try:
            case = scene
            for path, value in zip(paths, combination):
                case = evolve_path(case, path, value)
            result = Analysis(case, outputs=outputs, models=models, effects=effects).run()
            frame = result.summary_frame(units) if result.index is not None else result.to_frame(units)
            for _, values in frame.iterrows():
                rows.append({**row, **values.to_dict(), "error": ""})
        except InputError as exc:
            if errors == "raise":
                raise
            rows.append({**row, "error": str(exc)})
    return pd.DataFrame(rows)
