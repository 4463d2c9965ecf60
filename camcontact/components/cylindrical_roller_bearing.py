"""Cylindrical roller bearing: catalogue geometry and ratings, profiled rollers, the lamina loads under a radial load
and a misalignment, and the ISO/TS 16281 reference rating life.

A single-row radial bearing of Z cylindrical rollers (diameter D_we, effective length L_we) on the pitch
diameter D_pw with a radial clearance; its rollers carry a :class:`~camcontact.contact.roller_profile.RollerProfile`
(default: ISO/TS 16281's reference profile). :meth:`CylindricalRollerBearing.lamina_load_distribution` slices
every roller into laminae (:mod:`camcontact.contact.lamina_load_distribution`) and
:meth:`CylindricalRollerBearing.reference_life` gives L_10r (:mod:`camcontact.models.iso_ts16281_roller`) beside
ISO 281's L10 = (C/F_r)^(10/3).
"""

from __future__ import annotations

import math

import attrs

from ..errors import InputError
from ..units import (ANGLE, Component, Quantity, instance_of, integer_in_range, non_negative, positive, quantity_field,
                     si_value, text, to_quantity)
from .bearing_envelope import check_bearing_envelope, pitch_diameter_of
from .material import Material

__all__ = ["CylindricalRollerBearing"]


def _profile(instance, attribute, value):
    from ..contact.roller_profile import RollerProfile

    if value is not None and not isinstance(value, RollerProfile):
        raise InputError(f"CylindricalRollerBearing.profile = {value!r}: expected a RollerProfile or None (ISO/TS 16281's)")


@attrs.frozen(kw_only=True)
class CylindricalRollerBearing(Component):
    """A single-row cylindrical roller bearing from catalogue data.

    Parameters
    ----------
    designation : str
        Catalogue designation (e.g. "NU 206").
    bore, outer_diameter, width : Quantity or str
        d, D, B [length].
    roller_count : int
        Z (3..1000).
    roller_diameter, roller_length : Quantity or str
        D_we and the effective contact length L_we [length] (L_we <= B).
    pitch_diameter : Quantity or str, optional
        D_pw [length]; default (d + D)/2.
    radial_clearance : Quantity or str
        Radial operating clearance s [length] (default 0; negative: preload).
    C, C0 : Quantity or str
        Basic dynamic and static radial load ratings [force].
    fatigue_load_limit : Quantity or str, optional
        P_u [force].
    profile : RollerProfile, optional
        The rollers' profile (drop at each contact); None: ISO/TS 16281's reference profile for D_we.
    material : Material, optional
        Rings and rollers (E' for a logarithmic profile designed for a load).
    name : str

    Examples
    --------
    >>> import camcontact as cc
    >>> bearing = cc.CylindricalRollerBearing(designation="NU 206", bore="30 mm", outer_diameter="62 mm",
    ...                                       width="16 mm", roller_count=13, roller_diameter="9 mm",
    ...                                       roller_length="10 mm", C="44 kN", C0="36.5 kN")
    >>> bearing.roller_profile.label
    'ISO/TS 16281'
    """

    name: str = attrs.field(default="cylindrical roller bearing", validator=text)
    designation: str = attrs.field(default="", validator=text)
    bore: Quantity = quantity_field("[length]", validators=[positive("m")])
    outer_diameter: Quantity = quantity_field("[length]", validators=[positive("m")])
    width: Quantity = quantity_field("[length]", validators=[positive("m")])
    roller_count: int = attrs.field(validator=integer_in_range(3, 1000))
    roller_diameter: Quantity = quantity_field("[length]", validators=[positive("m")])
    roller_length: Quantity = quantity_field("[length]", validators=[positive("m")])
    pitch_diameter: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    radial_clearance: Quantity = quantity_field("[length]", default="0 mm")
    C: Quantity = quantity_field("[force]", validators=[positive("N")])
    C0: Quantity = quantity_field("[force]", validators=[positive("N")])
    fatigue_load_limit: Quantity = quantity_field("[force]", optional=True, validators=[positive("N")])
    profile: object = attrs.field(default=None, validator=_profile)
    material: Material | None = attrs.field(default=None, validator=attrs.validators.optional(instance_of(Material)))
    roughness: Quantity = quantity_field("[length]", optional=True, validators=[non_negative("m")])

    def __attrs_post_init__(self) -> None:
        where = f"CylindricalRollerBearing {self.designation or self.name!r}"
        check_bearing_envelope(where, self, "roller_diameter", "roller_count")
        if not self.si.roller_length <= self.si.width:
            raise InputError(f"{where}: roller_length = {self.roller_length} exceeds the width {self.width}")
        if self.roller_profile.kind in ("lundberg", "johns_gohar") and self.material is None:
            raise InputError(f"{where}: a {self.roller_profile.label} profile needs the material (its drop scales with "
                             "1/E'); set CylindricalRollerBearing.material")

    @property
    def d_m(self) -> float:
        """Pitch diameter D_pw [m] ((d + D)/2 unless given)."""
        return pitch_diameter_of(self)

    @property
    def roller_profile(self):
        """The rollers' profile: the one given, or ISO/TS 16281's for D_we."""
        from ..contact.roller_profile import RollerProfile

        return self.profile if self.profile is not None else RollerProfile(kind="iso_ts_16281",
                                                                           roller_diameter=self.si.roller_diameter)

    @property
    def inner_contact_radius(self) -> float:
        """Reduced radius along rolling of the roller on the inner ring [m]: (D_we/2)(1 - D_we/D_pw)."""
        return self.contact_radii["inner"]

    def lamina_load_distribution(self, radial_load, misalignment="0 rad", laminae: int = 30):
        """Roller and lamina loads under F_r [force] with the misalignment [angle] (Quantities or strings) by
        :func:`camcontact.contact.lamina_load_distribution.solve_lamina_load_distribution`."""
        Fr = si_value(to_quantity(radial_load, "[force]", where="lamina_load_distribution(radial_load)"))
        tilt = si_value(to_quantity(misalignment, ANGLE, where="lamina_load_distribution(misalignment)"))
        return self.lamina_load_distribution_si(Fr, tilt, laminae)

    def lamina_load_distribution_si(self, radial_load: float, misalignment: float = 0.0, laminae: int = 30):
        """:meth:`lamina_load_distribution` for SI values [N, rad] (the scene's entry)."""
        from ..contact.geometry import reduced_modulus
        from ..contact.lamina_load_distribution import solve_lamina_load_distribution

        m = self.material
        E = reduced_modulus(m.si.E, m.nu, m.si.E, m.nu) if m is not None else math.nan
        profile, length, R = self.roller_profile, self.si.roller_length, self.inner_contact_radius
        return solve_lamina_load_distribution(radial_load, roller_count=self.roller_count, roller_length=length,
                                              profile_drop=lambda x: profile.drop(x, length, E, R),
                                              clearance=self.si.radial_clearance, misalignment=misalignment,
                                              laminae=laminae)

    @property
    def contact_radii(self) -> dict[str, float]:
        """Reduced radii along rolling [m] of the inner and outer roller-raceway contacts: (D_we/2)(1 -/+ D_we/D_pw)."""
        gamma = self.si.roller_diameter / self.d_m
        half = 0.5 * self.si.roller_diameter
        return {"inner": half * (1.0 - gamma), "outer": half * (1.0 + gamma)}

    def reference_life(self, radial_load, misalignment="0 rad", *, inner_rotates: bool = True, laminae: int = 30,
                       edge_factor: bool | None = None) -> dict:
        """ISO/TS 16281 L_10r [revolutions] from the lamina loads beside ISO 281's L10 = (C/F_r)^(10/3) [revolutions]
        (``L10r``, ``L10``, their ratio ``L10r/L10``, the ``distribution``). ``edge_factor``: ISO/TS 16281's Eq. 60
        factor on the lamina loads, which the standard states for its reference profile only: by default applied
        with that profile and not with another (whose edge stress the numerical contact of
        :func:`camcontact.compare_roller_profiles` shows instead)."""
        from ..models.iso_ts16281_roller import roller_reference_rating_life

        distribution = self.lamina_load_distribution(radial_load, misalignment, laminae)
        life = roller_reference_rating_life(distribution.q, C=self.si.C, roller_diameter=self.si.roller_diameter,
                                            pitch_diameter=self.d_m, inner_rotates=inner_rotates,
                                            with_edge_factor=(self.roller_profile.kind == "iso_ts_16281"
                                                              if edge_factor is None else edge_factor))
        Fr = distribution.radial_load
        L10 = (self.si.C / Fr) ** (10.0 / 3.0) * 1e6 if Fr > 0 else math.inf
        L10r = life["L10r"] * 1e6
        return {"L10r": L10r, "L10": L10, "L10r/L10": L10r / L10, "distribution": distribution}
