"""Elastohydrodynamic lubrication: dimensionless groups and the numerical solvers.

* line contacts, steady: :mod:`.line_problem`, :mod:`.line_multigrid` (FAS multigrid),
  :mod:`.line_reference` (dense Newton reference), :mod:`.line_solution`;
* line contacts, transient with the squeeze term: :mod:`.line_transient`;
* point and elliptical contacts, steady: :mod:`.point_problem`, :mod:`.point_multigrid`,
  :mod:`.point_solution`;
* shared: :mod:`.groups` (Hamrock and Moes groups), :mod:`.film_formulas` (the Moes and
  Nijenbanning central-film formulas, start values), :mod:`.deformation` (MLMI), :mod:`.attempts`
  (the ladder of solver attempts), :mod:`.cycle_monitor` (per-cycle bookkeeping and stop rules).

Importing this package compiles nothing; the numba kernels (``_kernels.py``, ``_fas_kernels.py``,
``_point_kernels.py``) are compiled on first use only.
"""
