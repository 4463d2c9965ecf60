"""A lubricated point (elliptical) contact between two bodies curved in two planes: a ball on a plate or in a
raceway groove, crossed cylinders, a crowned roller's middle."""

from __future__ import annotations

import math

import attrs

from ..errors import InputError
from ..units import (Component, Quantity, above_absolute_zero, format_quantity, instance_of, positive,
                     quantity_field, text)
from .line_contact import Body
from .lubricant import Lubricant

__all__ = ["PointContact"]


def _reduced(radius1: float, radius2: float) -> float:
    """1/(1/R1 + 1/R2) [m] of signed radii (inf: straight; the sum of curvatures must be > 0)."""
    curvature = sum(0.0 if math.isinf(r) else 1.0 / r for r in (radius1, radius2))
    return math.inf if curvature == 0.0 else 1.0 / curvature


@attrs.frozen(kw_only=True)
class PointContact(Component):
    """A lubricated point contact: two bodies with principal radii along (``radius``) and across
    (``transverse_radius``) the rolling direction x, the principal planes aligned, a normal load.

    The gap's reduced radii are 1/Rx = 1/R1x + 1/R2x and 1/Ry = 1/R1y + 1/R2y (concave radii negative);
    both must be > 0 (a conforming pair whose curvatures cancel has no Hertz contact). Entrainment is along
    x with u_m = (u1 + u2)/2 of the bodies' speeds.

    Parameters
    ----------
    body1, body2 : Body
        Each with ``radius`` (along rolling) and ``transverse_radius`` (across); None: straight that way.
    load : Quantity or str
        Normal force [force] (> 0).
    lubricant : Lubricant, optional
        Needed for film outputs.
    temperature : Quantity or str, optional
        Bulk (inlet) lubricant temperature, needed when the viscosity depends on temperature.
    contact_stress_limit : Quantity or str
        Peak Hertz pressure above which ``stress_limit_exceeded`` is True [pressure] (default 4.2 GPa:
        ISO 76:2006, the static rating of ball bearings).
    name : str

    Examples
    --------
    A 12.7 mm steel ball on a flat steel plate:

    >>> import camcontact as cc
    >>> steel = cc.Material(E="207 GPa", nu=0.3)
    >>> ball = cc.Body(material=steel, radius="6.35 mm", transverse_radius="6.35 mm", speed="2 m/s")
    >>> contact = cc.PointContact(body1=ball, body2=cc.Body(material=steel, speed="2 m/s"), load="100 N")
    >>> round(contact.reduced_radii[0] * 1e3, 2), round(contact.reduced_radii[1] * 1e3, 2)
    (6.35, 6.35)
    """

    name: str = attrs.field(default="point contact", validator=text)
    body1: Body = attrs.field(validator=instance_of(Body))
    body2: Body = attrs.field(validator=instance_of(Body))
    load: Quantity = quantity_field("[force]", validators=[positive("N")])
    lubricant: Lubricant | None = attrs.field(default=None, validator=attrs.validators.optional(instance_of(Lubricant)))
    temperature: Quantity = quantity_field("[temperature]", optional=True, validators=[above_absolute_zero()])
    contact_stress_limit: Quantity = quantity_field("[pressure]", default="4.2 GPa", validators=[positive("Pa")])

    def __attrs_post_init__(self) -> None:
        where = f"PointContact {self.name!r}"
        Rx, Ry = self.reduced_radii
        for label, value, field in (("Rx (along rolling)", Rx, "radius"), ("Ry (across)", Ry, "transverse_radius")):
            if not (0.0 < value < math.inf):
                shown = [format_quantity(getattr(b, field)) if getattr(b, field) is not None else "None (straight)"
                         for b in (self.body1, self.body2)]
                raise InputError(f"{where}: reduced radius {label} = {value!r} m from body1.{field} = {shown[0]} and "
                                 f"body2.{field} = {shown[1]}; allowed: curvatures whose sum is > 0 in both planes "
                                 "(a point contact is curved both ways; straight across: a LineContact)")

    @property
    def reduced_radii(self) -> tuple[float, float]:
        """(Rx, Ry) [m]: the gap's reduced radii along and across the rolling direction (inf: no curvature;
        negative: the curvatures' sum is < 0)."""
        return (_reduced(self.body1.signed_radius, self.body2.signed_radius),
                _reduced(self.body1.signed_transverse_radius, self.body2.signed_transverse_radius))
