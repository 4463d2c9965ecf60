"""Material: elastic, mass, hardness and thermal properties of a solid body."""

from __future__ import annotations

import math

import attrs

from ..units import Component, Quantity, in_range, number_field, positive, quantity_field, text

__all__ = ["Material"]


@attrs.frozen(kw_only=True)
class Material(Component):
    """An isotropic elastic solid.

    Parameters
    ----------
    E : Quantity or str
        Young's modulus [pressure], > 0, e.g. ``"210 GPa"``.
    nu : float
        Poisson's ratio [-], 0 <= nu < 0.5.
    density : Quantity or str, optional
        [mass/volume], > 0.
    hardness : Quantity or str, optional
        Indentation hardness as a pressure (e.g. ``"7.5 GPa"``), used by wear models.
    yield_strength, tensile_strength : Quantity or str, optional
        [pressure], > 0.
    thermal_conductivity : Quantity or str, optional
        [W/(m K)], > 0.
    specific_heat : Quantity or str, optional
        [J/(kg K)], > 0.
    name : str
        Label used in reports.

    Examples
    --------
    >>> Material(E="200 GPa", nu=0.3, density="7810 kg/m^3", name="AISI 52100")
    Material(name='AISI 52100', E=200 GPa, nu=0.3, density=7810 kg/m³, hardness=None, yield_strength=None, tensile_strength=None, thermal_conductivity=None, specific_heat=None)
    """

    name: str = attrs.field(default="material", validator=text)
    E: Quantity = quantity_field("[pressure]", validators=[positive("Pa")], doc="Young's modulus")
    nu: float = number_field(validators=[in_range(0.0, 0.5, upper_inclusive=False)], doc="Poisson's ratio")
    density: Quantity = quantity_field("[density]", optional=True, validators=[positive("kg/m^3")])
    hardness: Quantity = quantity_field("[pressure]", optional=True, validators=[positive("Pa")])
    yield_strength: Quantity = quantity_field("[pressure]", optional=True, validators=[positive("Pa")])
    tensile_strength: Quantity = quantity_field("[pressure]", optional=True, validators=[positive("Pa")])
    thermal_conductivity: Quantity = quantity_field(
        "[power]/[length]/[temperature]", optional=True, validators=[positive("W/(m K)")]
    )
    specific_heat: Quantity = quantity_field(
        "[energy]/[mass]/[temperature]", optional=True, validators=[positive("J/(kg K)")]
    )

    @property
    def plane_strain_compliance(self) -> float:
        """(1 - nu^2)/E [1/Pa]: this body's share of 2/E'."""
        return (1.0 - self.nu**2) / self.si.E

    def thermal_effusivity(self) -> float:
        """sqrt(rho c k) [W s^0.5/(m^2 K)] (Delabenetta 2021 Eq. 50); needs the thermal data."""
        from ..errors import InputError

        missing = [n for n in ("density", "specific_heat", "thermal_conductivity") if getattr(self, n) is None]
        if missing:
            raise InputError(f"Material {self.name!r}: thermal effusivity needs {', '.join(missing)}")
        return math.sqrt(self.si.density * self.si.specific_heat * self.si.thermal_conductivity)
