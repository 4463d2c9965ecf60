"""What every bearing in service shares: ring speeds, lubricant and its temperature, the life requirements."""

from __future__ import annotations

import attrs

from ..units import Component, Quantity, above_absolute_zero, in_range, instance_of, number_field, quantity_field
from .lubricant import Lubricant

__all__ = ["BearingService"]


@attrs.frozen(kw_only=True)
class BearingService(Component):
    """The operating fields of a loaded bearing (the scene components of the bearing scenes derive from it):
    ``speed`` and ``outer_speed`` [1/time] (default 0), ``lubricant`` and its ``temperature`` [temperature]
    (optional), ``reliability`` [%] (90..99.95, default 90) and the ISO 281 ``contamination`` factor e_C
    (0 < e_C <= 1, optional)."""

    speed: Quantity = quantity_field("1/[time]", default="0 rpm")
    outer_speed: Quantity = quantity_field("1/[time]", default="0 rpm")
    lubricant: Lubricant | None = attrs.field(default=None, validator=attrs.validators.optional(instance_of(Lubricant)))
    temperature: Quantity = quantity_field("[temperature]", optional=True, validators=[above_absolute_zero()])
    reliability: float = number_field(default=90.0, validators=[in_range(90.0, 99.95)])
    contamination: float = number_field(optional=True, validators=[in_range(0.0, 1.0, lower_inclusive=False)])
