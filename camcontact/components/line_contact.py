"""A lubricated line contact between two bodies: the first scene of camcontact."""

from __future__ import annotations

import math

import attrs

from ..errors import InputError
from ..units import (Component, Quantity, above_absolute_zero, boolean, format_quantity, in_range, instance_of,
                     non_negative, number_field, positive, quantity_field, text)
from .lubricant import Lubricant
from .material import Material

__all__ = ["Body", "LineContact"]



@attrs.frozen(kw_only=True)
class Body(Component):
    """One body of a contact: material, curvature in the rolling plane, surface speed, roughness.

    Parameters
    ----------
    material : Material
    radius : Quantity or str, optional
        Radius of curvature in the rolling plane [length] (> 0); None for a flat surface.
    concave : bool
        True for a concave surface (e.g. an outer raceway); the radius then counts negative.
    speed : Quantity or str
        Surface speed in the rolling direction [velocity] (sign gives the direction).
    roughness : Quantity or str, optional
        RMS roughness Rq [length] (>= 0), needed for Lambda.
    transverse_radius : Quantity or str, optional
        Radius of curvature across the rolling direction [length] (> 0), for a :class:`PointContact`
        (a ball: its radius; a raceway groove: the groove radius with ``transverse_concave``); None: straight
        across (a cylinder or a flat). A line contact refuses it.
    transverse_concave : bool
        True for a surface concave across the rolling direction (a raceway groove).
    name : str
    """

    name: str = attrs.field(default="body", validator=text)
    material: Material = attrs.field(validator=instance_of(Material))
    radius: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    concave: bool = attrs.field(default=False, validator=boolean)
    speed: Quantity = quantity_field("[velocity]", default="0 m/s")
    roughness: Quantity = quantity_field("[length]", optional=True, validators=[non_negative("m")])
    transverse_radius: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    transverse_concave: bool = attrs.field(default=False, validator=boolean)

    def __attrs_post_init__(self) -> None:
        if self.concave and self.radius is None:
            raise InputError(f"Body {self.name!r}: concave=True needs a radius (a flat surface is neither)")
        if self.transverse_concave and self.transverse_radius is None:
            raise InputError(f"Body {self.name!r}: transverse_concave=True needs a transverse_radius (a surface "
                             "straight across is neither)")

    @property
    def signed_radius(self) -> float:
        """Radius [m], negative when concave, inf when flat."""
        if self.radius is None:
            return math.inf
        return -self.si.radius if self.concave else self.si.radius

    @property
    def signed_transverse_radius(self) -> float:
        """Radius across the rolling direction [m], negative when concave, inf when straight across."""
        if self.transverse_radius is None:
            return math.inf
        return -self.si.transverse_radius if self.transverse_concave else self.si.transverse_radius


@attrs.frozen(kw_only=True)
class LineContact(Component):
    """A lubricated line contact (two cylinders, or cylinder on plane).

    Load is given as ``load`` with ``length`` (total force over the contact length) or as
    ``load_per_length`` (``length`` then optional).

    Parameters
    ----------
    body1, body2 : Body
    load : Quantity or str, optional
        Normal force [N] (> 0), with ``length``.
    length : Quantity or str, optional
        Effective contact length [m] (> 0).
    load_per_length : Quantity or str, optional
        Normal load per unit length [N/m] (> 0).
    lubricant : Lubricant, optional
        Needed for film outputs.
    temperature : Quantity or str, optional
        Bulk (inlet) lubricant temperature, needed when the viscosity depends on temperature.
    friction_coefficient : float, optional
        Surface traction coefficient for the subsurface stresses (0 <= mu <= 1); default 0.
    asperity_density : Quantity or str, optional
        Summit density η of the pair's composite roughness [1/length²] (> 0), for the ``mixed`` effect
        (Greenwood–Tripp); default: η β σ = 0.05 with the composite σ.
    asperity_radius : Quantity or str, optional
        Summit radius β [length] (> 0) for ``mixed``; default: σ/β = 0.05 (orders of magnitude of ground
        steel surfaces as Stribeck-curve models use them, Gelinck & Schipper 2000; not data).
    oil_layer : Quantity or str, optional
        Starved lubrication: the lubricant layer carried into the contact [length] (> 0), both surfaces
        together, ahead of the contact (at ambient density). None (default): a flooded inlet. Needs the film
        model ``multigrid``, which then solves the starved steady contact
        (:func:`camcontact.ehl.line_starved.solve_starved`); the film formulas are for flooded contacts.
    name : str
    """

    name: str = attrs.field(default="line contact", validator=text)
    body1: Body = attrs.field(validator=instance_of(Body))
    body2: Body = attrs.field(validator=instance_of(Body))
    load: Quantity = quantity_field("[force]", optional=True, validators=[positive("N")])
    length: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    load_per_length: Quantity = quantity_field("[force]/[length]", optional=True, validators=[positive("N/m")])
    lubricant: Lubricant | None = attrs.field(default=None, validator=attrs.validators.optional(instance_of(Lubricant)))
    temperature: Quantity = quantity_field("[temperature]", optional=True, validators=[above_absolute_zero()])
    friction_coefficient: float = number_field(default=0.0, validators=[in_range(0.0, 1.0)])
    asperity_density: Quantity = quantity_field("1/[length]**2", optional=True, validators=[positive("1/m^2")])
    asperity_radius: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    oil_layer: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])

    def __attrs_post_init__(self) -> None:
        where = f"LineContact {self.name!r}"
        if self.load_per_length is None:
            if self.load is None or self.length is None:
                raise InputError(f"{where}: give load and length, or load_per_length")
        elif self.load is not None:
            raise InputError(f"{where}: give load (with length) or load_per_length, not both")
        if self.body1.radius is None and self.body2.radius is None:
            raise InputError(f"{where}: both bodies are flat; a line contact needs at least one curved body")
        for body in (self.body1, self.body2):
            if body.transverse_radius is not None:
                raise InputError(f"{where}: Body {body.name!r}.transverse_radius = "
                                 f"{format_quantity(body.transverse_radius)}; a line contact is straight across (allowed: None; "
                                 "a body curved both ways makes a PointContact)")

    @property
    def w(self) -> float:
        """Load per unit length [N/m]."""
        return self.si.load_per_length if self.load_per_length is not None else self.si.load / self.si.length
