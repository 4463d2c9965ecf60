"""Inputs the line kernels' tests share."""

import numpy as np


def PLAIN(n: int) -> np.ndarray:  # noqa: N802 - reads as the constant it stands for
    """The flow factors (a, k) = (1, 0) of an isothermal Newtonian film at n nodes, shape (n, 2)."""
    phi = np.zeros((n, 2))
    phi[:, 0] = 1.0
    return phi
