"""The checks every rolling bearing's catalogue geometry must pass: rings, pitch circle and rolling elements."""

from __future__ import annotations

import math

from ..errors import InputError

__all__ = ["check_bearing_envelope", "pitch_diameter_of"]


def pitch_diameter_of(bearing) -> float:
    """The bearing's pitch diameter d_m [m]: its ``pitch_diameter`` if given, else (bore + outer diameter)/2."""
    if bearing.pitch_diameter is not None:
        return bearing.si.pitch_diameter
    return 0.5 * (bearing.si.bore + bearing.si.outer_diameter)


def check_bearing_envelope(where: str, bearing, element: str, count_field: str) -> None:
    """InputError (prefixed ``where``) unless bore < d_m < outer diameter, the rolling element's diameter (field
    ``element`` of ``bearing``, e.g. "ball_diameter") is smaller than the section height (D - d)/2, and as many
    of them as the field ``count_field`` says (per row) fit on the pitch circle (count x diameter < pi d_m)."""
    si = bearing.si
    d, D, d_m = si.bore, si.outer_diameter, bearing.d_m
    if not d < D:
        raise InputError(f"{where}: bore = {bearing.bore} must be smaller than outer_diameter = {bearing.outer_diameter}")
    if not d < d_m < D:
        raise InputError(f"{where}: pitch_diameter = {d_m * 1e3:.4g} mm must lie between the bore "
                         f"({d * 1e3:.4g} mm) and the outer diameter ({D * 1e3:.4g} mm)")
    diameter = getattr(si, element)
    if not diameter < 0.5 * (D - d):
        raise InputError(f"{where}: {element} = {getattr(bearing, element)} must be smaller than the section height "
                         f"(D - d)/2 = {0.5e3 * (D - d):.4g} mm")
    count = getattr(bearing, count_field)
    if count * diameter >= math.pi * d_m:
        raise InputError(f"{where}: {count_field} = {count} of {element} = {getattr(bearing, element)} do not fit on "
                         f"the pitch circle (pi d_m = {math.pi * d_m * 1e3:.4g} mm, d_m the pitch_diameter or "
                         "(bore + outer_diameter)/2)")
