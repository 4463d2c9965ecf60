"""Sweep cases: a grid of field values -> cases -> one analysis each, on any executor, into one table.

The machinery behind :meth:`camcontact.analysis.Analysis.sweep` and :func:`camcontact.sweep.sweep_frame`
(the user-facing functions and the full description are in :mod:`camcontact.sweep`). It does not import
the analysis: every function that runs cases takes the *runner*, a picklable callable
``runner(scene, outputs=..., models=..., effects=...)`` with a ``run()`` returning a result, i.e. the
:class:`~camcontact.analysis.Analysis` class.

A *grid* names scene fields by *paths* — a field of the scene component, or through dots a field of a
component inside it (``"speed"``, ``"cam.base_radius"``, ``"cvt.material.E"``) — and gives the values
to try: a mapping ``{path: [values, ...]}`` (the cartesian product is swept) or a pandas DataFrame
whose columns are paths and whose rows are the cases. Values are what the field accepts
(Quantities, strings with units, numbers).

Each case is one run of the runner (an :class:`~camcontact.analysis.Analysis`) with the sweep's outputs,
models and effects, by :func:`run_case` — a plain top-level function of picklable arguments, so any
:class:`concurrent.futures.Executor` runs it: none (serial, in this process), a
``ProcessPoolExecutor``, or ``dask.distributed.Client.get_executor()`` (the ``[dask]`` extra). The
rows come back in case order whatever the executor, so every executor gives the same table.

The table is tidy: one row per case (and variant), or per case × index value (cam angle, roller) for
a scene with an index when ``table="index"``; the swept values first, in columns ``"path [unit]"``
(magnitudes in the unit of the path's first value; plain numbers ``"path [-]"``), then the outputs
``"name [unit]"``, then ``error``: empty, or ``"ExceptionType: message"`` of a case that failed —
its parameters stay in the row, and the other cases are not lost.

>>> import camcontact as cc
>>> steel = cc.Material(E="210 GPa", nu=0.3)
>>> evolve_path(steel, "E", "200 GPa").si.E
200000000000.0
"""

from __future__ import annotations

import itertools
import sys
from collections.abc import Iterable, Mapping, Sequence
from concurrent.futures import Executor, as_completed
from typing import Any

import attrs
import pint

from .errors import InputError
from .units import to_quantity, ureg

__all__ = ["TABLES", "cases_of", "check_path", "evolve_path", "has_index", "run_case", "run_cases", "run_sweep"]

TABLES = ("auto", "cases", "index")


def check_path(component: Any, path: str) -> None:
    """InputError unless ``path`` names a field of ``component`` (through nested components)."""
    current = component
    for depth, head in enumerate(path.split(".")):
        if not attrs.has(type(current)):
            raise InputError(f"sweep path {path!r}: {'.'.join(path.split('.')[:depth])} is not a component "
                             f"({type(current).__name__}) and has no field {head!r}")
        names = [field.name for field in attrs.fields(type(current))]
        if head not in names:
            raise InputError(f"sweep path {path!r}: {type(current).__name__} has no field {head!r}; "
                             f"fields: {', '.join(names)}")
        current = getattr(current, head)


def evolve_path(component: Any, path: str, value: Any) -> Any:
    """A copy of ``component`` with the field at the dotted ``path`` set to ``value`` (validated anew)."""
    check_path(component, path)
    head, _, rest = path.partition(".")
    new = value if not rest else evolve_path(getattr(component, head), rest, value)
    return attrs.evolve(component, **{head: new})


def cases_of(grid: Any) -> tuple[list[str], list[tuple]]:
    """(paths, cases) of a grid: a mapping of path -> values (cartesian product) or a DataFrame of cases."""
    import pandas as pd

    if isinstance(grid, pd.DataFrame):
        paths = [str(c) for c in grid.columns]
        cases = [tuple(row) for row in grid.itertuples(index=False, name=None)]
    elif isinstance(grid, Mapping):
        paths = [str(p) for p in grid]
        values = []
        for path in paths:
            entry = grid[path]
            if isinstance(entry, (str, bytes)) or not isinstance(entry, Iterable):
                raise InputError(f"sweep grid: {path!r} = {entry!r}; give a list of values")
            values.append(list(entry))
        cases = list(itertools.product(*values))
    else:
        raise InputError(f"sweep grid: expected a mapping {{path: [values]}} or a DataFrame of cases, got "
                         f"{type(grid).__name__}")
    if not paths or not cases:
        raise InputError("sweep grid: no cases (give at least one path with at least one value)")
    return paths, cases


def _parameter_columns(paths: Sequence[str], cases: Sequence[tuple]) -> list[tuple[str, Any]]:
    """Per path: (column header, converter of a value to the cell) — units in the header."""
    columns = []
    for k, path in enumerate(paths):
        values = [case[k] for case in cases]
        unit = None
        if all(isinstance(v, (str, pint.Quantity)) for v in values):
            try:
                quantities = [v if isinstance(v, pint.Quantity) else ureg.Quantity(v) for v in values]
                if all(not q.dimensionless for q in quantities):
                    unit = quantities[0].units
            except Exception:  # noqa: BLE001  (not quantities: text values such as names)
                unit = None
        if unit is not None:
            label = f"{unit:~P}".replace(" ", "")

            def cell(v, unit=unit, path=path):
                q = v if isinstance(v, pint.Quantity) else to_quantity(v, str(unit.dimensionality), where=path)
                return float(q.to(unit).magnitude)

            columns.append((f"{path} [{label}]", cell))
        elif all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
            columns.append((f"{path} [-]", lambda v: v))
        else:
            columns.append((path, lambda v: v if isinstance(v, (int, float, str, bool)) else str(v)))
    return columns


def run_case(runner: Any, scene: Any, paths: Sequence[str], values: Sequence[Any], outputs, models, effects,
             table: str, units) -> list[dict[str, Any]] | str:
    """One case: the scene with ``values`` at ``paths``, analysed by ``runner``; its report rows (dicts),
    or the error text ``"ExceptionType: message"`` when the case fails (the sweep keeps it with the case)."""
    try:
        case = scene
        for path, value in zip(paths, values):
            case = evolve_path(case, path, value)
        result = runner(case, outputs=outputs, models=models, effects=effects).run()
        if result.index is not None and table == "index":
            frame = result.to_frame(units)
        elif result.index is not None:
            frame = result.summary_frame(units)
        else:
            frame = result.to_frame(units)
        return frame.to_dict(orient="records")
    except Exception as exc:  # noqa: BLE001  (a failing case is reported, the others go on)
        return f"{type(exc).__name__}: {exc}"


def run_cases(runner: Any, scene: Any, paths: Sequence[str], chunk: Sequence[Sequence[Any]], *rest: Any) -> list:
    """:func:`run_case` for a chunk of cases (one task of an executor: less shipping per case)."""
    return [run_case(runner, scene, paths, values, *rest) for values in chunk]


def _chunk_size(cases: int, requested: int | None) -> int:
    if requested is not None:
        if not (isinstance(requested, int) and requested >= 1):
            raise InputError(f"sweep: chunksize = {requested!r}; allowed: an integer >= 1")
        return requested
    return max(1, min(16, cases // 32))  # about 32+ tasks: balanced over workers, little shipping


def _progress(total: int, enabled: bool | None):
    if enabled is None:
        enabled = total > 1 and sys.stderr.isatty()
    if not enabled:
        return None
    from tqdm.auto import tqdm

    return tqdm(total=total, desc="sweep", unit="case", file=sys.stderr)


def run_sweep(runner: Any, scene: Any, grid: Any, *, outputs=None, models=None, effects=None, executor: Executor | None = None,
              progress: bool | None = None, errors: str = "record", table: str = "auto", units=None,
              chunksize: int | None = None):
    """The sweep of ``scene`` over ``grid`` (see :mod:`camcontact.sweep`) as a pandas DataFrame, each case
    run by ``runner`` (the :class:`~camcontact.analysis.Analysis` class).

    ``executor``: None runs the cases here, one after the other; any ``concurrent.futures.Executor``
    runs them there, ``chunksize`` cases per task (default: about 32 tasks or more, at most 16 cases
    each). ``progress``: a tqdm bar on stderr (None: when stderr is a terminal).
    ``errors="raise"`` raises an InputError naming the first failing case instead of recording it.
    ``table``: ``"cases"`` (one row per case and variant; cycle summaries for indexed scenes),
    ``"index"`` (per case and index value) or ``"auto"`` (``"index"`` when outputs per index value are
    asked for, or by default).
    """
    import pandas as pd

    if errors not in ("record", "raise"):
        raise InputError(f"sweep: errors = {errors!r}; allowed: 'record', 'raise'")
    if table not in TABLES:
        raise InputError(f"sweep: table = {table!r}; allowed: {', '.join(map(repr, TABLES))}")
    paths, cases = cases_of(grid)
    for path in paths:  # a wrong path is the grid's error, not a case's: said before anything runs
        check_path(scene, path)
    columns = _parameter_columns(paths, cases)
    if table == "auto":
        table = "index" if has_index(runner(scene, outputs=outputs, models=models, effects=effects)) else "cases"
    outputs = None if outputs is None else list(outputs)
    models = None if models is None else dict(models)
    effects = None if effects is None else list(effects)
    units = None if units is None else dict(units)
    rest = (outputs, models, effects, table, units)
    bar = _progress(len(cases), progress)
    produced: list[Any] = [None] * len(cases)
    try:
        if executor is None:
            for k, values in enumerate(cases):
                produced[k] = run_case(runner, scene, paths, values, *rest)
                if bar is not None:
                    bar.update(1)
        else:
            size = _chunk_size(len(cases), chunksize)
            starts = range(0, len(cases), size)
            futures = {executor.submit(run_cases, runner, scene, paths, cases[i:i + size], *rest): i for i in starts}
            for future in as_completed(futures):
                start = futures[future]
                outcomes = future.result()
                produced[start:start + len(outcomes)] = outcomes
                if bar is not None:
                    bar.update(len(outcomes))
    finally:
        if bar is not None:
            bar.close()
    rows = []
    for case, outcome in zip(cases, produced):
        parameters = {header: cell(value) for (header, cell), value in zip(columns, case)}
        if isinstance(outcome, str):
            if errors == "raise":
                raise InputError(f"sweep case {dict(zip(paths, case))} failed: {outcome}")
            rows.append({**parameters, "error": outcome})
        else:
            rows.extend({**parameters, **row, "error": ""} for row in outcome)
    frame = pd.DataFrame(rows)
    ordered = [c for c in frame.columns if c != "error"] + ["error"]
    return frame[ordered]


def has_index(analysis: Any) -> bool:
    """True when a planned analysis reports outputs per index value (cam angle, roller)."""
    return any(graph.index is not None and set(planned) & graph.per_index
               for graph, planned, _ in analysis.plans.values())
