"""Elastohydrodynamic lubrication: dimensionless groups and (from issue 3 on) numerical solvers.

Importing this package compiles nothing; numba kernels live in ``_kernels.py`` and are
compiled on first use only.
"""
