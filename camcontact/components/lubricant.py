"""Lubricant: viscosity data, pressure–viscosity data and the laws that use them.

A :class:`Lubricant` is pure data, validated at construction. :meth:`Lubricant.at` evaluates
it at a temperature and returns a :class:`LubricantState` of SI floats plus the resolved
law objects, which is what models use.

Viscosity can be given in one of four ways:

1. ``eta0`` (dynamic) with an optional ``reference_temperature``: the viscosity is known at
   that temperature only (or, without a reference temperature, assumed the same at any);
2. ``nu40`` and ``nu100`` (kinematic, ISO grade data) with ``density``: a viscosity–temperature
   law (``walther`` by default) is fitted through them;
3. ``viscosity_data``: (temperature, viscosity) pairs, kinematic or dynamic, for laws that
   need more points (``vogel`` needs three);
4. none of these, with the ``roelands`` law and both ``alpha`` and ``roelands_z``: eta0
   follows from the Roelands consistency relation (Tsuha 2015 Eq. 4.6).

Pressure–viscosity: ``alpha`` [1/pressure] or (Roelands only) ``roelands_z``; with z given,
alpha follows eta0(T) through the consistency relation. Density is taken independent of
temperature (as Delabenetta 2021 Eq. 35); its pressure dependence is the ``density_law``.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from typing import Any

import attrs
import numpy as np
import pint

from .. import registry
from ..errors import InputError, UnknownModelError
from ..models.base import DensityLaw, ViscosityPressureLaw, ViscosityTemperatureLaw
from ..models.pressure_viscosity_coefficient import gold_alpha
from ..models.viscosity_pressure import roelands_consistent
from ..units import (Component, Quantity, above_absolute_zero, format_quantity, in_range, non_negative, number_field,
                     one_of, positive, quantity_field, si_value, text, to_quantity)

__all__ = ["Lubricant", "LubricantState"]

_T40 = 313.15
_T100 = 373.15


def _viscosity_points(value: Any, instance: Any, field: attrs.Attribute) -> tuple:
    """Convert {T: viscosity} or [(T, viscosity), ...] to a tuple of Quantity pairs."""
    where = f"{type(instance).__name__}.{field.name}"
    if value is None:
        return ()
    if isinstance(value, (str, bytes)) or not isinstance(value, (Mapping, list, tuple)):
        raise InputError(f"{where} = {value!r}; allowed: a mapping {{temperature: viscosity}} or a sequence of "
                         "(temperature, viscosity) pairs")
    pairs = list(value.items()) if isinstance(value, Mapping) else list(value)
    points = []
    for i, pair in enumerate(pairs):
        try:
            temperature, viscosity = pair
        except (TypeError, ValueError):
            raise InputError(f"{where}[{i}] = {pair!r}: expected a (temperature, viscosity) pair") from None
        t = to_quantity(temperature, "[temperature]", where=f"{where}[{i}] temperature")
        v = _viscosity_quantity(viscosity, f"{where}[{i}] viscosity")
        points.append((t, v))
    kinds = {_is_kinematic(v) for _, v in points}
    if len(kinds) > 1:
        raise InputError(f"{where}: mix of kinematic and dynamic viscosities; give all of one kind")
    return tuple(points)


def _viscosity_quantity(value: Any, where: str) -> pint.Quantity:
    try:
        quantity = to_quantity(value, "[kinematic_viscosity]", where=where)
    except InputError:
        quantity = to_quantity(value, "[viscosity]", where=where)
    if not si_value(quantity) > 0:
        raise InputError(f"{where} = {format_quantity(quantity)} must be > 0")
    return quantity


def _is_kinematic(quantity: pint.Quantity) -> bool:
    return quantity.check("[kinematic_viscosity]")


@attrs.frozen
class LubricantState:
    """A lubricant evaluated at one temperature (SI floats) with its resolved laws."""

    name: str
    temperature: float | None  #: [K], None for an isothermal lubricant
    eta0: float  #: dynamic viscosity at ambient pressure [Pa*s]
    kinematic_viscosity: float | None  #: [m^2/s]
    density: float | None  #: at ambient pressure [kg/m^3]
    alpha: float | None  #: pressure–viscosity coefficient [1/Pa]
    roelands_z: float | None  #: Roelands index [-] (roelands law only)
    thermoviscous_coefficient: float | None  #: beta = -d ln(nu)/dT [1/K]
    thermal_conductivity: float | None  #: [W/(m K)]
    specific_heat: float | None  #: [J/(kg K)]
    pressure_law: ViscosityPressureLaw
    density_law: DensityLaw
    thermal_expansivity: float = 0.0  #: alpha_T = -d ln(rho)/dT [1/K]

    def _alpha(self) -> float:
        if self.alpha is None:
            raise InputError(
                f"Lubricant {self.name!r} has no pressure–viscosity data: give alpha "
                "(or roelands_z), or switch the 'piezoviscosity' effect off"
            )
        return self.alpha

    def log_viscosity_ratio(self, pressure):
        """ln(eta/eta0) [-] at gauge pressure [Pa]."""
        return self.pressure_law.log_viscosity_ratio(pressure, self.eta0, self._alpha())

    def viscosity(self, pressure):
        """Dynamic viscosity [Pa*s] at gauge pressure [Pa]."""
        return self.pressure_law.viscosity(pressure, self.eta0, self._alpha())

    def density_ratio(self, pressure):
        """rho(p)/rho0 [-] at gauge pressure [Pa]."""
        return self.density_law.density_ratio(pressure)


@attrs.frozen(kw_only=True)
class Lubricant(Component):
    """A Newtonian lubricant (oil, or the base oil of a grease).

    Parameters
    ----------
    name : str
        Label used in reports.
    eta0 : Quantity or str, optional
        Dynamic viscosity at ambient pressure [Pa*s] at ``reference_temperature``.
    reference_temperature : Quantity or str, optional
        Temperature at which ``eta0`` holds (e.g. ``"40 degC"``).
    nu40, nu100 : Quantity or str, optional
        Kinematic viscosities at 40 °C and 100 °C (e.g. ``"575 cSt"``); need ``density``.
    viscosity_data : mapping or sequence of pairs, optional
        (temperature, viscosity) points, all kinematic or all dynamic.
    density : Quantity or str, optional
        Density at ambient pressure [kg/m^3] (needed for kinematic data).
    alpha : Quantity or str, optional
        Pressure–viscosity coefficient [1/Pa], e.g. ``"2.2e-8 1/Pa"`` or ``"22 1/GPa"``.
    roelands_z : float, optional
        Roelands index z (with ``viscosity_pressure_law="roelands"``).
    alpha_correlation : str, optional
        ``"gold"``: alpha(T) from the Gold correlation of Delabenetta (2021) Eq. 36 (needs
        kinematic data fitted by the ``walther`` law); instead of ``alpha``/``roelands_z``.
    base_oil : str
        ``"mineral"`` (default) or ``"ester"``: the class of base oil (for ``alpha_correlation``).
    viscosity_pressure_law : str
        ``"roelands"`` (default) or ``"barus"``, or any plugin of kind ``"pressure"``.
    viscosity_temperature_law : str
        ``"walther"`` (default), ``"astm_d341"`` (Walther with the low-viscosity term),
        ``"vogel"``, or any plugin of kind ``"temperature"``.
    density_law : str
        ``"dowson_higginson"`` (default) or ``"incompressible"``.
    thermal_conductivity : Quantity or str, optional
        [W/(m K)], needed by the ``thermal`` effect.
    specific_heat : Quantity or str, optional
        [J/(kg K)].
    thermal_expansivity : Quantity or str, optional
        Volumetric thermal expansivity α_T = −d ln ρ/dT [1/temperature] (>= 0) for the ``thermal`` film solver
        (film model ``multigrid``, :class:`camcontact.ehl.line_thermal.ThermalLineContact`): the film does the
        compression work α_T T u dp/dx (heats as it runs into the pressure, cools as it leaves it) and expands as it
        heats, ρ = ρ_DH(p) exp(−α_T (T − T0)). Mineral oils: 6–7e-4 1/K at ambient pressure (6.5e-4 in the thermal
        EHL analyses since Sadeghi & Dow 1987). Needs the oil's temperature (the contact's ``temperature``). The
        steady line-contact solve takes it; the cam turn's transient march refuses it (InputError from the film
        step).
        Default None: not modelled. It is not on by default because the one constant α_T of that law, right in
        the inlet, overstates the expansion of a hot Hertz zone at GPa pressures, where the expansivity of real
        oils is lower, and there it raises a sliding film's h_c by 6–16 % (measured, S = 1; README).
    eyring_stress : Quantity or str, optional
        Eyring stress τ0 [pressure] (> 0) of the film's rheology (Johnson & Tevaarwerk 1977), used by the
        ``non_newtonian`` effect; default: the traction model's (5 MPa, a mineral-oil order of magnitude).
    limiting_shear_stress : Quantity or str, optional
        τ_L0 [pressure] (>= 0) of the limiting shear stress τ_L = τ_L0 + Λ_L p (Bair & Winer 1979);
        default: the traction model's (0).
    limiting_shear_slope : float, optional
        Λ_L [-] (0 <= Λ_L <= 0.3); default: the traction model's (0.047, a paraffinic mineral oil: Höglund 1999).
    boundary_friction : float
        Friction coefficient of the asperity contacts under this lubricant's boundary films, for the
        ``mixed`` effect (0 <= μ_b <= 1). Default 0.12: measured asperity friction of steel line contacts
        in oil, 0.12–0.135 (Masjedi & Khonsari 2014, Tribol. Int. 70:179), ZDDP tribofilms 0.09–0.14
        (Zhang, Ueda, Campen & Spikes 2021, Tribol. Lett. 69).
    thermoviscous_coefficient : Quantity or str, optional
        Temperature–viscosity coefficient β = −d ln η/dT [1/temperature] (> 0) of a lubricant given without
        a viscosity–temperature law (``eta0``, or Roelands' consistency relation), for the ``thermal``
        effect; with temperature data the law's β is used (giving both is an error). Mineral oils: about
        0.02–0.05 1/K near 40–100 °C.
    form : str
        ``"oil"`` (default) or ``"grease"``: a grease is described by its base oil's data; the
        form sets the starvation factor of the corrected film (0.7 for grease, Delabenetta 2021
        App. D comment) where a scene uses one.
    upper_temperature : Quantity or str, optional
        Upper service temperature from the data sheet (e.g. ``"120 degC"``), checked by the
        scenes that predict lubricant temperatures.

    Examples
    --------
    Tsuha (2015): alpha = 2.2e-8 1/Pa and z = 0.68, eta0 from the consistency relation:

    >>> oil = Lubricant(alpha="2.2e-8 1/Pa", roelands_z=0.68)
    >>> round(oil.at(None).eta0, 6)
    0.035835
    """

    name: str = attrs.field(default="lubricant", validator=text)
    eta0: Quantity = quantity_field("[viscosity]", optional=True, validators=[positive("Pa*s")])
    reference_temperature: Quantity = quantity_field(
        "[temperature]", optional=True, validators=[above_absolute_zero()]
    )
    nu40: Quantity = quantity_field("[kinematic_viscosity]", optional=True, validators=[positive("m^2/s")])
    nu100: Quantity = quantity_field("[kinematic_viscosity]", optional=True, validators=[positive("m^2/s")])
    viscosity_data: tuple = attrs.field(
        default=(),
        converter=attrs.Converter(_viscosity_points, takes_self=True, takes_field=True),
        repr=lambda points: "(" + ", ".join(f"({format_quantity(t)}, {format_quantity(v)})" for t, v in points) + ")",
        eq=False,
        metadata={"doc": "(temperature, viscosity) points"},
    )
    density: Quantity = quantity_field("[density]", optional=True, validators=[positive("kg/m^3")])
    alpha: Quantity = quantity_field("1/[pressure]", optional=True, validators=[non_negative("1/Pa")])
    roelands_z: float = number_field(
        optional=True, validators=[in_range(0.0, 2.0, lower_inclusive=False)]
    )
    alpha_correlation: str | None = attrs.field(
        default=None, validator=attrs.validators.optional(one_of("gold"))
    )
    base_oil: str = attrs.field(default="mineral", validator=one_of("mineral", "ester"))
    viscosity_pressure_law: str = "roelands"
    viscosity_temperature_law: str = "walther"
    density_law: str = "dowson_higginson"
    thermal_conductivity: Quantity = quantity_field(
        "[power]/[length]/[temperature]", optional=True, validators=[positive("W/(m K)")]
    )
    specific_heat: Quantity = quantity_field(
        "[energy]/[mass]/[temperature]", optional=True, validators=[positive("J/(kg K)")]
    )
    thermal_expansivity: Quantity = quantity_field("1/[temperature]", optional=True,
                                                   validators=[non_negative("1/K")])
    eyring_stress: Quantity = quantity_field("[pressure]", optional=True, validators=[positive("Pa")])
    limiting_shear_stress: Quantity = quantity_field("[pressure]", optional=True, validators=[non_negative("Pa")])
    limiting_shear_slope: float = number_field(optional=True, validators=[in_range(0.0, 0.3)])
    boundary_friction: float = number_field(default=0.12, validators=[in_range(0.0, 1.0)])
    thermoviscous_coefficient: Quantity = quantity_field("1/[temperature]", optional=True,
                                                         validators=[positive("1/K")])
    form: str = attrs.field(default="oil", validator=one_of("oil", "grease"))
    upper_temperature: Quantity = quantity_field("[temperature]", optional=True, validators=[above_absolute_zero()])

    # ------------------------------------------------------------------ validation
    def __attrs_post_init__(self) -> None:
        where = f"Lubricant {self.name!r}"
        if self.thermoviscous_coefficient is not None and self._points() is not None:
            raise InputError(f"{where}: thermoviscous_coefficient = {format_quantity(self.thermoviscous_coefficient)} "
                             "is given with viscosity–temperature data, whose law gives β; drop one of them")
        self._law("viscosity_pressure_law", "pressure")
        self._law("viscosity_temperature_law", "temperature")
        self._registered("density_law", "density_laws")
        kinematic_data = self.nu40 is not None or bool(
            self.viscosity_data and _is_kinematic(self.viscosity_data[0][1])
        )
        if (self.nu40 is None) != (self.nu100 is None):
            raise InputError(f"{where}: give both nu40 and nu100 (or neither)")
        sources = [
            label
            for label, present in (
                ("eta0", self.eta0 is not None),
                ("nu40/nu100", self.nu40 is not None),
                ("viscosity_data", bool(self.viscosity_data)),
            )
            if present
        ]
        if len(sources) > 1:
            raise InputError(f"{where}: viscosity given several ways ({', '.join(sources)}); give one")
        if self.roelands_z is not None and self.viscosity_pressure_law != "roelands":
            raise InputError(
                f"{where}: roelands_z = {self.roelands_z} applies only to viscosity_pressure_law='roelands' "
                f"(got {self.viscosity_pressure_law!r}); give alpha instead"
            )
        if not sources:
            if not (self.viscosity_pressure_law == "roelands" and self.alpha is not None and self.roelands_z is not None):
                raise InputError(
                    f"{where}: no viscosity given; give eta0, nu40 and nu100, viscosity_data, or "
                    "(with the roelands law) both alpha and roelands_z"
                )
        elif self.alpha is not None and self.roelands_z is not None:
            raise InputError(
                f"{where}: with the viscosity given ({sources[0]}) give alpha or roelands_z, not both: they are "
                "tied by the Roelands consistency relation"
            )
        if self.alpha_correlation is not None:
            if self.alpha is not None or self.roelands_z is not None:
                raise InputError(f"{where}: alpha_correlation replaces alpha and roelands_z; give only one")
            if self.viscosity_temperature_law not in ("walther", "astm_d341") or not kinematic_data:
                raise InputError(
                    f"{where}: alpha_correlation='gold' needs kinematic viscosity data (nu40/nu100 or "
                    "viscosity_data) fitted with viscosity_temperature_law='walther' or 'astm_d341'"
                )
        if self.eta0 is None and self.reference_temperature is not None:
            raise InputError(f"{where}: reference_temperature applies to eta0, which is not given")
        if kinematic_data and self.density is None:
            raise InputError(f"{where}: kinematic viscosity data need the density to give dynamic viscosity")
        points = self._points()
        if points is not None:
            law = registry.get_class("viscosity_laws", self.viscosity_temperature_law)
            if len(points[0]) < law.points_needed:
                raise InputError(
                    f"{where}: viscosity_temperature_law {self.viscosity_temperature_law!r} needs "
                    f"{law.points_needed} viscosity points, the data give {len(points[0])}; add "
                    "viscosity_data or choose 'walther'"
                )

    def _registered(self, field: str, family: str):
        """The registered class a law field names, or an InputError naming the field and the laws there are."""
        name = getattr(self, field)
        if isinstance(name, str):
            try:
                return registry.get_class(family, name)
            except UnknownModelError:
                pass
        raise UnknownModelError(f"Lubricant.{field} = {name!r}: no {family} model of that name; available: "
                                f"{', '.join(registry.available(family))}")

    def _law(self, field: str, kind: str):
        name = getattr(self, field)
        cls = self._registered(field, "viscosity_laws")
        if getattr(cls, "kind", None) != kind:
            options = [n for n in registry.available("viscosity_laws")
                       if getattr(registry.get_class("viscosity_laws", n), "kind", None) == kind]
            raise InputError(
                f"Lubricant.{field} = {name!r} is a {getattr(cls, 'kind', '?')} law; "
                f"{kind} laws: {', '.join(options)}"
            )
        return cls

    def _points(self) -> tuple[np.ndarray, np.ndarray] | None:
        """(temperatures [K], kinematic-or-dynamic viscosities [SI]) of the temperature law."""
        if self.nu40 is not None:
            return np.array([_T40, _T100]), np.array([self.si.nu40, self.si.nu100])
        if self.viscosity_data:
            return (np.array([si_value(t) for t, _ in self.viscosity_data]),
                    np.array([si_value(v) for _, v in self.viscosity_data]))
        return None

    @functools.cached_property
    def temperature_law(self) -> ViscosityTemperatureLaw | None:
        """The viscosity–temperature law fitted to the data (None without temperature data)."""
        points = self._points()
        if points is None:
            return None
        return registry.get("viscosity_laws", self.viscosity_temperature_law).fit(*points)

    def extrapolates(self, temperature: float | None) -> bool:
        """True when ``temperature`` [K] lies outside the temperatures of the viscosity data (40 and 100 °C
        for nu40/nu100; the span of viscosity_data), where the viscosity–temperature law is extrapolated;
        False without temperature data (the viscosity is the one given)."""
        points = self._points()
        if points is None or temperature is None:
            return False
        temperatures = points[0]
        return bool(temperature < temperatures.min() - 1e-9 or temperature > temperatures.max() + 1e-9)

    @property
    def isothermal(self) -> bool:
        """True when the viscosity does not depend on temperature (no temperature data)."""
        return self._points() is None and self.reference_temperature is None

    # ------------------------------------------------------------------ evaluation
    def at(self, temperature: Any) -> LubricantState:
        """The lubricant at ``temperature`` (Quantity/str; None for an isothermal lubricant)."""
        if temperature is None:
            return self.state(None)
        quantity = to_quantity(temperature, "[temperature]", where=f"Lubricant {self.name!r} temperature")
        return self.state(si_value(quantity))

    def state(self, temperature: float | None) -> LubricantState:
        """:meth:`at` on SI input: temperature [K] or None."""
        where = f"Lubricant {self.name!r}"
        if temperature is not None and not temperature > 0:
            raise InputError(f"{where}: temperature {temperature!r} K must be above absolute zero")
        pressure_law = registry.get("viscosity_laws", self.viscosity_pressure_law)
        density_law = registry.get("density_laws", self.density_law)
        law = self.temperature_law
        kinematic = None
        beta = self.si.thermoviscous_coefficient
        density = self.si.density
        if law is not None:
            if temperature is None:
                raise InputError(f"{where}: the viscosity depends on temperature; give the temperature")
            value = law.viscosity(temperature)
            beta = law.thermoviscous_coefficient(temperature)
            points_kinematic = self.nu40 is not None or _is_kinematic(self.viscosity_data[0][1])
            if points_kinematic:
                kinematic, eta0 = value, value * density
            else:
                eta0 = value
                kinematic = eta0 / density if density else None
        elif self.eta0 is not None:
            reference = self.si.reference_temperature
            if reference is not None and temperature is not None and abs(temperature - reference) > 1e-9:
                raise InputError(
                    f"{where}: viscosity known only at {format_quantity(self.reference_temperature)} "
                    f"(eta0); give nu40/nu100 or viscosity_data to evaluate it at {temperature - 273.15:.6g} °C"
                )
            eta0 = self.si.eta0
            kinematic = eta0 / density if density else None
        else:  # Roelands consistency: eta0 from alpha and z
            eta0, _, _ = roelands_consistent(alpha=self.si.alpha, z=self.roelands_z, law=pressure_law)
            kinematic = eta0 / density if density else None
        alpha, z = self.si.alpha, self.roelands_z
        if self.alpha_correlation == "gold":
            alpha = gold_alpha(kinematic / 1e-6, law.m, density / 1000.0, self.base_oil)
        if self.viscosity_pressure_law == "roelands" and (alpha is not None or z is not None):
            eta0, alpha, z = roelands_consistent(eta0=eta0, alpha=alpha, z=z, law=pressure_law)
        return LubricantState(
            name=self.name, temperature=temperature, eta0=float(eta0),
            kinematic_viscosity=None if kinematic is None else float(kinematic),
            density=density, alpha=alpha, roelands_z=z,
            thermoviscous_coefficient=None if beta is None else float(beta),
            thermal_conductivity=self.si.thermal_conductivity, specific_heat=self.si.specific_heat,
            pressure_law=pressure_law, density_law=density_law,
            thermal_expansivity=float(self.si.thermal_expansivity or 0.0),
        )
