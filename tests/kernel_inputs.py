"""Inputs the line kernels' tests share."""

import numpy as np


def PLAIN(n: int) -> np.ndarray:  # noqa: N802 - reads as the constant it stands for
    """The flow and Couette factors (a, k, c) = (1, 0, 1) of an isothermal Newtonian film at n nodes, shape (n, 3)."""
    phi = np.zeros((n, 3))
    phi[:, 0] = 1.0
    phi[:, 2] = 1.0
    return phi
