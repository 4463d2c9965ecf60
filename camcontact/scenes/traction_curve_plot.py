"""The traction curve of a lubricated contact: traction coefficient against the slide-to-roll ratio, with the
linear, non-linear and plateau regions of each fluid traction model marked (Evans & Johnson 1986)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from ..errors import InputError

__all__ = ["plot_traction_curve"]

REGIME_MARKERS = {"linear": "o", "nonlinear": "s", "plateau": "^"}


def plot_traction_curve(models: Any | Sequence[Any], *, p_h: float, b: float, h_c: float, u_m: float,
                        lubricant_state: Any, effusivity: Any = None, slide_roll=None, ax=None):
    """Figure of mu(S) for one traction model or several (e.g. isothermal and thermal Eyring), S = u_s/u_m in
    ``slide_roll`` (default 0..1), at Hertz pressure p_h [Pa], half-width b [m], central film h_c [m] and
    entrainment speed u_m [m/s]; markers show each point's regime. Returns the matplotlib figure."""
    import matplotlib.pyplot as plt

    models = list(models) if isinstance(models, (list, tuple)) else [models]
    if not models or not all(hasattr(m, "curve") for m in models):
        raise InputError("plot_traction_curve: give fluid traction models (registry 'traction_models' "
                         "'newtonian' or 'eyring'), e.g. registry.get('traction_models', 'eyring')")
    S = np.linspace(0.0, 1.0, 201) if slide_roll is None else np.asarray(slide_roll, dtype=float)
    fig = ax.figure if ax is not None else plt.subplots(figsize=(6.0, 4.0))[1].figure
    ax = ax or fig.axes[0]
    for model in models:
        curve = model.curve(S, p_h=p_h, b=b, h_c=h_c, u_m=u_m, lubricant_state=lubricant_state,
                            effusivity=effusivity)
        label = f"{model.name}{' thermal' if getattr(model, 'thermal', False) else ''}"
        line, = ax.plot(S, curve.coefficient, label=label)
        for regime, marker in REGIME_MARKERS.items():
            chosen = np.asarray(curve.regime) == regime
            if chosen.any():
                step = max(1, int(chosen.sum() // 12))
                ax.plot(S[chosen][::step], curve.coefficient[chosen][::step], marker, color=line.get_color(),
                        ms=4, label=f"{label}: {regime}")
    ax.set(xlabel="slide-to-roll ratio S = u_s / u_m [-]", ylabel="traction coefficient [-]",
           title=f"traction curve (p_h {p_h * 1e-9:.3g} GPa, u_m {u_m:.3g} m/s, h_c {h_c * 1e9:.4g} nm)")
    ax.legend(fontsize=7)
    return fig
