"""Sweeps: the same Analysis over many designs and operating points, on any executor, into one table.

A *grid* names scene fields by *paths* — a field of the scene component, or through dots a field of a
component inside it (``"speed"``, ``"cam.base_radius"``, ``"cvt.material.E"``) — and gives the values
to try: a mapping ``{path: [values, ...]}`` (the cartesian product is swept) or a pandas DataFrame
whose columns are paths and whose rows are the cases. :meth:`camcontact.analysis.Analysis.sweep`
sweeps an analysis; :func:`sweep_frame` a scene's scalar outputs. The cases run on any
:class:`concurrent.futures.Executor` and come back as one tidy table (the machinery, and what the
table holds, is described in :mod:`camcontact.sweep_cases`).

>>> import camcontact as cc
>>> steel = cc.Material(E="210 GPa", nu=0.3)
>>> contact = cc.LineContact(body1=cc.Body(material=steel, radius="20 mm"),
...                          body2=cc.Body(material=steel, radius="10 mm"), load="1 kN", length="10 mm")
>>> list(sweep_frame(contact, {"load": ["1 kN", "2 kN"]}, outputs=["p_h"]).columns)
['load [kN]', 'p_h [MPa]', 'error']
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

from .analysis import Analysis
from .sweep_cases import TABLES, cases_of, check_path, evolve_path
from .sweep_cases import run_sweep as run_cases_sweep

__all__ = ["TABLES", "cases_of", "check_path", "evolve_path", "run_sweep", "sweep_frame"]


def run_sweep(scene: Any, grid: Any, **options: Any):
    """The :class:`~camcontact.analysis.Analysis` of ``scene`` over ``grid`` as one DataFrame
    (``options``: those of :meth:`~camcontact.analysis.Analysis.sweep` and outputs, models, effects)."""
    return run_cases_sweep(Analysis, scene, grid, **options)


def sweep_frame(scene: Any, grid: Any, *, outputs: Iterable[str] | None = None,
                models: Mapping[str, Any] | None = None, effects: Iterable[str] | None = None,
                units: Mapping[str, str] | None = None, errors: str = "record", **options: Any):
    """:func:`run_sweep` with the scalar outputs of every case (``table="cases"`` unless given)."""
    return run_sweep(scene, grid, outputs=outputs, models=models, effects=effects, units=units, errors=errors,
                     **{"table": "cases", **options})
