"""Stribeck curves of a line contact: its friction against the entrainment speed at a fixed slide-to-roll ratio.

A Stribeck curve is a sweep of the line-contact scene (:mod:`camcontact.scenes.line_contact`) over the
entrainment speed u_m = (u1 + u2)/2 with the slide-to-roll ratio s = (u1 - u2)/u_m held: the surface speeds
of each case are u1 = u_m (1 + s/2), u2 = u_m (1 - s/2). Each case runs the whole scene with the effects
asked for (default ``mixed`` + ``non_newtonian``: Greenwood–Tripp asperity load sharing with the
Johnson–Greenwood–Poon split, the boundary friction of the asperities and the Eyring traction of the film;
``thermal`` adds the inlet film reduction and the contact temperature of the traction), so the curve shows
the three regimes of Stribeck's diagram — boundary (the asperities carry the load: mu -> mu_b), mixed and
full film, where the friction rises again with speed as the film's traction does (Gelinck & Schipper 2000,
Tribol. Int. 33:175–181, the model; Hamrock, Schmid & Jacobson 2004 §1 for the regimes).

>>> import camcontact as cc
>>> steel = cc.Material(E="210 GPa", nu=0.3)
>>> oil = cc.Lubricant(nu40="100 cSt", nu100="11 cSt", density="870 kg/m^3", alpha="22 1/GPa")
>>> contact = cc.LineContact(body1=cc.Body(material=steel, radius="20 mm", speed="2.1 m/s", roughness="0.2 um"),
...                          body2=cc.Body(material=steel, radius="20 mm", speed="1.9 m/s", roughness="0.2 um"),
...                          load="150 N", length="10 mm", lubricant=oil, temperature="60 degC")
>>> curve = stribeck_sweep(contact, [0.001, 0.1, 3.0, 30.0])
>>> list(curve["lubrication_regime"])
['boundary', 'boundary', 'mixed', 'full_film']
>>> [round(mu, 3) for mu in curve["traction_coefficient [-]"]]
[0.114, 0.067, 0.004, 0.007]
"""

from __future__ import annotations

import numbers
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import numpy as np

from ..components.line_contact import LineContact
from ..errors import InputError
from ..steps.kinematics import split_speed
from ..units import to_quantity
from .line_contact import MIXED_OUTPUTS

__all__ = ["STRIBECK_OUTPUTS", "plot_stribeck_curve", "stribeck_sweep"]

#: the outputs of each case (with ``mixed``; without it the asperity columns are left out)
STRIBECK_OUTPUTS = ("u_m", "slide_roll_ratio", "h_c", "Lambda_mixed", "asperity_load_fraction", "lubrication_regime",
                    "traction_coefficient", "fluid_traction_coefficient", "traction_regime", "traction_valid",
                    "mixed_valid")
REGIME_COLOURS = {"boundary": "tab:red", "mixed": "tab:orange", "full_film": "tab:green"}
CURVE_COLOURS = ("tab:blue", "tab:purple", "0.25", "tab:brown", "tab:cyan")


def _speeds(entrainment_speeds: Any) -> np.ndarray:
    """The speeds in m/s (numbers in m/s, or a pint Quantity of any velocity unit), sorted."""
    try:
        if hasattr(entrainment_speeds, "units"):
            entrainment_speeds = to_quantity(entrainment_speeds, "[velocity]",
                                             where="stribeck_sweep.entrainment_speeds")
            entrainment_speeds = entrainment_speeds.to("m/s").magnitude
        speeds = np.asarray(entrainment_speeds, dtype=float).ravel()
    except (TypeError, ValueError):
        raise InputError(f"stribeck_sweep: entrainment_speeds = {entrainment_speeds!r}; allowed: speeds in m/s "
                         "(numbers, or a velocity Quantity array)") from None
    if speeds.size < 2 or not np.all(np.isfinite(speeds)) or np.any(speeds <= 0.0):
        raise InputError(f"stribeck_sweep: entrainment_speeds = {speeds.tolist()!r}; allowed: at least two finite "
                         "speeds > 0 m/s")
    return np.sort(speeds)


def stribeck_sweep(contact: LineContact, entrainment_speeds: Any = None, *, slide_roll_ratio: float | None = None,
                   effects: Iterable[str] = ("mixed", "non_newtonian"), models: Mapping[str, Any] | None = None,
                   progress: bool | None = False, executor: Any = None):
    """The friction of ``contact`` over entrainment speeds: one pandas DataFrame row per speed.

    Parameters
    ----------
    contact : LineContact
        The contact (with a lubricant, a temperature and both roughnesses).
    entrainment_speeds : array_like or Quantity, optional
        Entrainment speeds u_m [m/s] (numbers in m/s), at least two, > 0; default 40 speeds log-spaced over
        1e-4 ... 1e2 times the contact's own u_m.
    slide_roll_ratio : float, optional
        s = (u1 - u2)/u_m [-], finite, |s| < 2 (both surfaces moving forward); default the contact's own.
    effects : iterable of str
        Effects beyond elasticity and piezoviscosity (line-contact scene); at least one of ``mixed`` and
        ``non_newtonian``, which give the friction.
    models : mapping, optional
        The scene's model slots (``film``, ``traction``).

    Returns
    -------
    pandas.DataFrame
        Columns ``entrainment speed [m/s]``, the outputs of :data:`STRIBECK_OUTPUTS` the effects give (as
        ``"name [unit]"``) and ``error`` (empty, or why a case failed: its row stays, with NaN outputs).
    """
    if not isinstance(contact, LineContact):
        raise InputError(f"stribeck_sweep: contact = {type(contact).__name__}; allowed: a LineContact")
    effects = set(effects)
    if not effects & {"mixed", "non_newtonian"}:
        raise InputError(f"stribeck_sweep: effects = {sorted(effects)}; a Stribeck curve needs the friction of "
                         "'mixed' and/or 'non_newtonian'")
    u1, u2 = contact.body1.si.speed, contact.body2.si.speed
    own = 0.5 * (u1 + u2)
    if slide_roll_ratio is None:
        if own <= 0.0:
            raise InputError(f"stribeck_sweep: the contact's entrainment speed is {own:.6g} m/s; give "
                             "slide_roll_ratio (and entrainment_speeds)")
        slide_roll_ratio = (u1 - u2) / own
    if isinstance(slide_roll_ratio, bool) or not isinstance(slide_roll_ratio, numbers.Real) \
            or not np.isfinite(slide_roll_ratio) or abs(slide_roll_ratio) >= 2.0:
        raise InputError(f"stribeck_sweep: slide_roll_ratio = {slide_roll_ratio!r}; allowed: a number with "
                         "|s| < 2 (both surfaces moving in the entrainment direction)")
    if entrainment_speeds is None:
        if own <= 0.0:
            raise InputError("stribeck_sweep: give entrainment_speeds (the contact has no entrainment of its own)")
        entrainment_speeds = own * np.logspace(-4.0, 2.0, 40)
    speeds = _speeds(entrainment_speeds)
    s = float(slide_roll_ratio)
    import pandas as pd

    from ..analysis import Analysis

    pairs = [split_speed(u, s) for u in speeds]
    grid = pd.DataFrame({"body1.speed": [f"{float(u1)!r} m/s" for u1, _ in pairs],
                         "body2.speed": [f"{float(u2)!r} m/s" for _, u2 in pairs]})
    outputs = [q for q in STRIBECK_OUTPUTS if "mixed" in effects or q not in MIXED_OUTPUTS]
    analysis = Analysis(contact, outputs=outputs, models=dict(models or {}),
                        effects=effects | {"elasticity", "piezoviscosity"})
    frame = analysis.sweep(grid, progress=progress, executor=executor, table="cases")
    frame = frame.drop(columns=[c for c in frame.columns if c.startswith(("body1.speed", "body2.speed"))])
    frame.insert(0, "entrainment speed [m/s]", speeds)
    return frame


def plot_stribeck_curve(curves: Any, *, labels: Sequence[str] | None = None, ax: Any = None, figsize=(6.4, 4.2)):
    """Friction coefficient against the entrainment speed (log axis), points coloured by the lubrication
    regime (hollow where the mixed model is outside its validity, ``mixed_valid`` False), for one or several
    :func:`stribeck_sweep` frames; the film parameter Lambda (dotted) on a second axis where the frame has it.
    Returns the Figure."""
    import matplotlib.pyplot as plt

    frames = list(curves) if isinstance(curves, (list, tuple)) else [curves]
    labels = list(labels) if labels is not None else [""] * len(frames)
    if len(labels) != len(frames):
        raise InputError(f"plot_stribeck_curve: {len(labels)} labels for {len(frames)} curves")
    if ax is None:
        fig, ax = plt.subplots(figsize=figsize)
    else:
        fig = ax.figure
    lam_ax = None
    for k, (frame, label) in enumerate(zip(frames, labels)):
        if "traction_coefficient [-]" not in frame.columns:
            raise InputError("plot_stribeck_curve: the frame has no 'traction_coefficient [-]' (a stribeck_sweep)")
        u = frame["entrainment speed [m/s]"].to_numpy(dtype=float)
        mu = frame["traction_coefficient [-]"].to_numpy(dtype=float)
        if not np.any(np.isfinite(mu)):
            reasons = sorted(set(frame["error"])) if "error" in frame else []
            raise InputError(f"plot_stribeck_curve: curve {label or k} has no finite friction coefficient "
                             f"(every case failed: {reasons[:3]})")
        line, = ax.plot(u, mu, "-", lw=1.2, color=CURVE_COLOURS[k % len(CURVE_COLOURS)], label=f"μ {label}".strip())
        regimes = frame["lubrication_regime"].to_numpy(dtype=object) if "lubrication_regime" in frame else None
        valid = frame["mixed_valid"].to_numpy(dtype=bool) if "mixed_valid" in frame else np.ones(u.size, dtype=bool)
        if regimes is not None:
            for regime, colour in REGIME_COLOURS.items():
                for inside in (True, False):
                    chosen = (regimes == regime) & (valid == inside)
                    if chosen.any():
                        ax.plot(u[chosen], mu[chosen], "o", ms=4, color=colour, mfc=colour if inside else "none",
                                label=regime if inside else f"{regime}, asperity capacity < 1 (share a lower bound)")
        lam = frame["Lambda_mixed [-]"].to_numpy(dtype=float) if "Lambda_mixed [-]" in frame.columns else None
        if lam is not None and np.any(np.isfinite(lam) & (lam > 0.0)):
            lam_ax = lam_ax or ax.twinx()
            lam_ax.plot(u, lam, ":", color=line.get_color())
    if lam_ax is not None:
        lam_ax.set_yscale("log")
        lam_ax.set_ylabel("Λ = h_c / σ (dotted) [-]")
    ax.set_xscale("log")
    ax.set(xlabel="entrainment speed u_m [m/s]", ylabel="friction coefficient μ [-]", title="Stribeck curve")
    handles, names = ax.get_legend_handles_labels()
    unique = dict(zip(names, handles))
    ax.legend(unique.values(), unique.keys(), fontsize=8)
    fig.tight_layout()
    return fig
