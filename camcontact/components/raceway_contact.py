"""One roller against one raceway: the scene of a single-contact failure analysis.

:class:`RacewayContact` holds what Delabenetta (2021) needs to assess the roller / outer-ring
contact of the pellet-mill bearing (reference ``spherical_roller_bearing_delabenetta2021.md``,
§3): the two radii, the effective length, the roller load, the ring and roller speeds, both
surfaces (material, roughness), the roughness wavelength, the lubricant and its temperature.
:mod:`camcontact.scenes.raceway_contact` evaluates it in the thesis's convention (its tables to
the printed digits) or in the corrected one (its modelling errors fixed), side by side.
"""

from __future__ import annotations

import attrs

from ..errors import InputError
from ..units import (Component, Quantity, above_absolute_zero, in_range, instance_of, non_negative, number_field,
                     one_of, positive, quantity_field, text)
from .lubricant import Lubricant
from .material import Material

__all__ = ["RacewayContact"]


@attrs.frozen(kw_only=True)
class RacewayContact(Component):
    """A loaded roller on a raceway of a rolling bearing, lubricated.

    Parameters
    ----------
    raceway : str
        ``"outer"`` (default; the raceway is concave) or ``"inner"`` (convex).
    raceway_radius : Quantity or str
        Radius of the raceway in the rolling direction at the contact [length] (Delabenetta's
        R1 = 149 mm).
    roller_radius : Quantity or str
        Roller radius at the contact [length] (R2 = 13.5 mm).
    length : Quantity or str
        Effective contact length l [length] (41.35 mm; the thesis calls it a semi-width but
        uses it as the full length, erratum 3).
    load : Quantity or str
        Normal load on the roller F_n [force] (> 0).
    ring_speed : Quantity or str
        Speed of the rotating ring relative to the other (fixed) ring [1/time], e.g. "300 rpm".
    roller_speed : Quantity or str, optional
        Roller speed about its own axis [1/time] as the thesis takes it (the catalogue speed
        limit, 1900 rpm; erratum 27). Only a convention that does not derive the rolling speed
        uses it.
    raceway_material, roller_material : Material
        E, nu; density, specific heat and conductivity for the flash temperature; the yield
        strength for the plastic and fatigue checks.
    raceway_roughness, roller_roughness : Quantity or str
        RMS roughness of each surface [length] (Lambda).
    roughness_wavelength : Quantity or str, optional
        Wavelength of a sinusoidal roughness [length] for the roughness stress (Eq. 8).
    lubricant : Lubricant
        A grease is described by its base oil (``Lubricant(form="grease", ...)``).
    temperature : Quantity or str
        Working temperature of the lubricant [temperature].
    slide_roll_ratio : float
        (u_raceway - u_roller)/u_m imposed on the pure-rolling speeds by a convention that derives
        them (0 <= s < 2; default 0, pure rolling).
    lambda_min : float
        The thesis's temperature loop input (its "initial estimate" of Lambda): the loop lowers
        the temperature in 0.1 K steps, starting one step below ``temperature``, until Lambda
        exceeds it. Default 0 (one step: the thesis's 84.9 °C from 85 °C).
    asperity_density, asperity_radius : Quantity or str, optional
        Summit density η [1/length²] and radius β [length] (> 0) of the composite roughness of the raceway
        contact for the ``mixed`` effect (Greenwood–Tripp), as :class:`~camcontact.components.LineContact`'s
        (defaults there: η β σ = σ/β = 0.05, orders of magnitude, not data).
    name : str
    """

    name: str = attrs.field(default="roller / raceway", validator=text)
    raceway: str = attrs.field(default="outer", validator=one_of("outer", "inner"))
    raceway_radius: Quantity = quantity_field("[length]", validators=[positive("m")])
    roller_radius: Quantity = quantity_field("[length]", validators=[positive("m")])
    length: Quantity = quantity_field("[length]", validators=[positive("m")])
    load: Quantity = quantity_field("[force]", validators=[positive("N")])
    ring_speed: Quantity = quantity_field("1/[time]", validators=[non_negative("1/s")])
    roller_speed: Quantity = quantity_field("1/[time]", optional=True, validators=[non_negative("1/s")])
    raceway_material: Material = attrs.field(validator=instance_of(Material))
    roller_material: Material = attrs.field(validator=instance_of(Material))
    raceway_roughness: Quantity = quantity_field("[length]", validators=[non_negative("m")])
    roller_roughness: Quantity = quantity_field("[length]", validators=[non_negative("m")])
    roughness_wavelength: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    lubricant: Lubricant = attrs.field(validator=instance_of(Lubricant))
    temperature: Quantity = quantity_field("[temperature]", validators=[above_absolute_zero()])
    slide_roll_ratio: float = number_field(default=0.0, validators=[in_range(0.0, 2.0, upper_inclusive=False)])
    lambda_min: float = number_field(default=0.0, validators=[in_range(0.0)])
    asperity_density: Quantity = quantity_field("1/[length]**2", optional=True, validators=[positive("1/m^2")])
    asperity_radius: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])

    def __attrs_post_init__(self) -> None:
        if self.raceway == "outer" and not self.si.raceway_radius > self.si.roller_radius:
            raise InputError(
                f"RacewayContact {self.name!r}: raceway_radius = {self.raceway_radius} must exceed roller_radius = "
                f"{self.roller_radius} for a roller inside an outer raceway"
            )

    @property
    def pitch_diameter(self) -> float:
        """d_m [m] implied by the radii: 2(R1 - R2) on an outer, 2(R1 + R2) on an inner raceway
        (the rolling plane of the contact; the contact angle does not enter)."""
        R1, R2 = self.si.raceway_radius, self.si.roller_radius
        return 2.0 * (R1 - R2) if self.raceway == "outer" else 2.0 * (R1 + R2)
