"""Sweeps: the same Analysis over many designs and operating points, on any executor, into one table.

A *grid* names scene fields by *paths* — a field of the scene component, or through dots a field of a
component inside it (``"speed"``, ``"cam.base_radius"``, ``"cvt.material.E"``) — and gives the values
to try: a mapping ``{path: [values, ...]}`` (the cartesian product is swept) or a pandas DataFrame
whose columns are paths and whose rows are the cases. :meth:`camcontact.analysis.Analysis.sweep`
sweeps an analysis; :func:`run_sweep` and :func:`sweep_frame` a scene. The cases run on any
:class:`concurrent.futures.Executor` and come back as one tidy table, ``case`` (the case's number)
first and ``error`` last (the machinery, and what the table holds, is described in
:mod:`camcontact.sweep_cases`).

Nothing finished is lost: ``timeout=`` [s] records a case that runs too long as failed
(``"CaseTimeout: case exceeded 5 s"``) and goes on; ``stream="sweep.csv"`` appends every finished
case to the file at once, and :func:`read_sweep` reads it back as the same table; after a SIGINT or a
killed worker process the finished cases are returned (and on disk) with
``frame.attrs["missing_cases"]``, and the same call with ``resume=True`` runs only the missing cases
and returns the complete table.

>>> import camcontact as cc
>>> steel = cc.Material(E="210 GPa", nu=0.3)
>>> contact = cc.LineContact(body1=cc.Body(material=steel, radius="20 mm"),
...                          body2=cc.Body(material=steel, radius="10 mm"), load="1 kN", length="10 mm")
>>> list(sweep_frame(contact, {"load": ["1 kN", "2 kN"]}, outputs=["p_h"]).columns)
['case', 'load [kN]', 'p_h [MPa]', 'error']
"""

from __future__ import annotations

import functools
import os
from collections.abc import Iterable, Mapping
from typing import Any

from .analysis import Analysis
from .sweep_cases import TABLES, cases_of, check_path, evolve_path
from .sweep_cases import run_sweep as run_cases_sweep
from .sweep_stream import read_sweep
from .sweep_xarray import to_xarray

__all__ = ["TABLES", "cases_of", "check_path", "evolve_path", "read_sweep", "run_sweep", "sweep_frame", "to_xarray",
           "worker_count"]


def run_sweep(scene: Any, grid: Any, *, strict: bool = False, **options: Any):
    """The :class:`~camcontact.analysis.Analysis` of ``scene`` over ``grid`` as one DataFrame.

    ``options``: outputs, models, effects, and those of :func:`camcontact.sweep_cases.run_sweep` —
    executor, progress, errors, table, units, chunksize, ``timeout`` [s] per case, ``stream`` (a .csv
    path written as cases finish) and ``resume`` (run only the cases not in ``stream`` yet).
    ``strict=True`` (or ``errors="raise"``) runs every case strictly: a step that fails fails its case
    (without it, the case's row has NaN in that step's outputs, ``failed`` and the reason).
    """
    strict = strict or options.get("errors") == "raise"
    return run_cases_sweep(functools.partial(Analysis, strict=True) if strict else Analysis, scene, grid, **options)


def sweep_frame(scene: Any, grid: Any, *, outputs: Iterable[str] | None = None,
                models: Mapping[str, Any] | None = None, effects: Iterable[str] | None = None,
                units: Mapping[str, str] | None = None, errors: str = "record", **options: Any):
    """:func:`run_sweep` with the scalar outputs of every case (``table="cases"`` unless given)."""
    return run_sweep(scene, grid, outputs=outputs, models=models, effects=effects, units=units, errors=errors,
                     **{"table": "cases", **options})


def worker_count(requested: int, cases: int) -> int:
    """The worker processes worth starting for ``cases`` cases: ``requested`` capped at the number of
    cases and of CPUs (``os.cpu_count()``), at least 1.

    >>> worker_count(64, 1)
    1
    """
    return max(1, min(requested, cases, os.cpu_count() or 1))
