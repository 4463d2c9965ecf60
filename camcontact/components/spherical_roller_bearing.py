"""Spherical roller bearing: catalogue geometry, ratings and the internal geometry of its contacts.

A double-row self-aligning bearing: ``rows`` rows of ``rollers_per_row`` barrel rollers (diameter
D_w, effective length l_we) on the pitch diameter d_m, contact angle ±alpha, radial internal
clearance c_r. The rolling-direction radii of the roller–raceway line contacts follow from
gamma = D_w cos(alpha) / d_m (Harris & Kotzalas 2007, ch. 2 and 7):

    inner contact  R_x = (D_w / 2)(1 - gamma) (roller against a convex raceway)
    outer contact  R_x = (D_w / 2)(1 + gamma) (roller against a concave raceway)

Across the rolling direction the barrel roller (contour radius R_r) runs in raceways of contour radius r_race
slightly larger: the conformity f = R_r / r_race < 1 (Harris & Kotzalas 2007, ch. 2, the osculation of the roller
to its raceway). The outer raceway is a sphere about the bearing centre, r_o = d_m / (2 cos alpha) + D_w / 2 (the
contact normal through the roller's middle passes through that centre), so f_o fixes R_r = f_o r_o and
f_i the inner raceway's contour radius r_i = R_r / f_i. Across rolling each contact then has the radius
R_y = R_r / (1 - f) (1/R_y = 1/R_r - 1/r_race): the raceway gap grows as y^2 / (2 R_y) from the roller's middle, so
the contact is as long as the load makes it, and reaches the roller's ends (l_we) only under a heavy load - the
finite line it really is. ISO/TS 16281:2008 slices such a contact into laminae with this gap as the profile
(:meth:`SphericalRollerBearing.raceway_profiles`, :func:`camcontact.steps.raceway_laminae.conformal_roller_hertz`).
Without the conformities (catalogues do not print them) the contacts are ideal lines of length l_we, which
underestimates the pressure of a lightly loaded roller. The load distribution over the rollers keeps Palmgren's
stiffness of a roller on its full length either way (with zero clearance the distribution does not depend on the
stiffness; with clearance a conformal roller, softer under light load, spreads the load zone a little wider).

The ratings C (dynamic) and C0 (static) and, if known, the fatigue load limit P_u come from the
catalogue; :meth:`SphericalRollerBearing.load_distribution` distributes radial and axial loads
over the rollers (:mod:`camcontact.contact.load_distribution`).
"""

from __future__ import annotations

import math

import attrs

from ..errors import InputError
from ..units import (ANGLE, Component, Quantity, in_range, instance_of, integer_in_range, non_negative, number_field,
                     positive, quantity_field, text)
from .bearing_envelope import check_bearing_envelope, pitch_diameter_of
from .material import Material

__all__ = ["SphericalRollerBearing"]

#: the most rollers per row a bearing may have
MAX_ROLLERS = 1000
#: a conformity R_r / r_race: below 1 (equal radii would make the contact as long as the roller at any load) and above
#: 0.5 (a roller's contour radius half its raceway's is a ball in a groove, not a spherical roller bearing)
_CONFORMITY = in_range(0.5, 1.0, lower_inclusive=False, upper_inclusive=False)


def _series(instance, attribute, value):
    from ..models.bearing_friction import SKF_SERIES

    if value is not None and not (isinstance(value, str) and value in SKF_SERIES):
        raise InputError(f"{type(instance).__name__}.{attribute.name} = {value!r}; allowed: {', '.join(SKF_SERIES)} "
                         "(the series of the SKF friction model's geometry constants)")


@attrs.frozen(kw_only=True)
class SphericalRollerBearing(Component):
    """A spherical roller bearing from catalogue data.

    Parameters
    ----------
    designation : str
        Catalogue designation (e.g. "24040 CC/W33").
    bore, outer_diameter, width : Quantity or str
        d, D, B [length].
    rollers_per_row : int
        Z (>= 3).
    roller_diameter, roller_length : Quantity or str
        D_w (largest diameter of the barrel roller) and the effective contact length l_we [length].
    pitch_diameter : Quantity or str
        d_m [length]; default (d + D)/2.
    contact_angle : Quantity or str
        alpha [angle], 0 < alpha < 45°.
    C, C0 : Quantity or str
        Basic dynamic and static load ratings [force].
    fatigue_load_limit : Quantity or str, optional
        P_u [force] (for a_ISO).
    radial_clearance : Quantity or str
        Radial internal clearance c_r [length] (default 0; negative = interference/preload): the total
        radial play of one ring against the other, i.e. the diametral clearance P_d of Harris &
        Kotzalas (ch. 7), which sets the load zone psi_l = arccos(P_d / (2 delta_r)).
    rows : int
        1 or 2 (default 2).
    row_offset : Quantity or str
        Azimuth offset between the rollers of the two rows [angle] (default 0: in line).
    material : Material, optional
        Rings and rollers (needed for Hertz contact and subsurface stresses).
    roughness : Quantity or str, optional
        RMS roughness of each surface [length] (composite = sqrt(2) times it).
    series : str, optional
        Dimension series as the SKF friction model names it (e.g. "240" for a 24040 CC/W33, "222 E" for a
        22220 E); one of :data:`camcontact.models.bearing_friction.SKF_SERIES`. Needed by the SKF
        frictional moment only.
    asperity_density, asperity_radius : Quantity or str, optional
        Summit density η [1/length²] and radius β [length] (> 0) of the composite roughness of the raceway
        contact for the ``mixed`` effect (Greenwood–Tripp), as :class:`~camcontact.components.LineContact`'s
        (defaults there: η β σ = σ/β = 0.05, orders of magnitude, not data).
    conformity_inner, conformity_outer : float, optional
        f_i, f_o = R_r / r_race [-] (0.5 < f < 1, both or neither; module docstring): the roller's contour radius over
        the raceway's, across the rolling direction. With them the raceway contacts are finite lines sliced into
        laminae; without them, ideal lines of length l_we.
    name : str
    """

    name: str = attrs.field(default="bearing", validator=text)
    designation: str = attrs.field(default="", validator=text)
    bore: Quantity = quantity_field("[length]", validators=[positive("m")])
    outer_diameter: Quantity = quantity_field("[length]", validators=[positive("m")])
    width: Quantity = quantity_field("[length]", validators=[positive("m")])
    rollers_per_row: int = attrs.field(validator=integer_in_range(3, MAX_ROLLERS))
    roller_diameter: Quantity = quantity_field("[length]", validators=[positive("m")])
    roller_length: Quantity = quantity_field("[length]", validators=[positive("m")])
    pitch_diameter: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    contact_angle: Quantity = quantity_field(
        ANGLE, validators=[in_range(0.0, math.pi / 4, lower_inclusive=False, upper_inclusive=False, unit="rad")])
    C: Quantity = quantity_field("[force]", validators=[positive("N")])
    C0: Quantity = quantity_field("[force]", validators=[positive("N")])
    fatigue_load_limit: Quantity = quantity_field("[force]", optional=True, validators=[positive("N")])
    radial_clearance: Quantity = quantity_field("[length]", default="0 mm")
    rows: int = attrs.field(default=2, validator=integer_in_range(1, 2))
    row_offset: Quantity = quantity_field(ANGLE, default="0 deg")
    material: Material | None = attrs.field(default=None, validator=attrs.validators.optional(instance_of(Material)))
    roughness: Quantity = quantity_field("[length]", optional=True, validators=[non_negative("m")])
    series: str | None = attrs.field(default=None, validator=_series)
    asperity_density: Quantity = quantity_field("1/[length]**2", optional=True, validators=[positive("1/m^2")])
    asperity_radius: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    conformity_inner: float | None = number_field(optional=True, validators=[_CONFORMITY])
    conformity_outer: float | None = number_field(optional=True, validators=[_CONFORMITY])

    def __attrs_post_init__(self) -> None:
        si, where = self.si, f"SphericalRollerBearing {self.designation!r}"
        check_bearing_envelope(where, self, "roller_diameter", "rollers_per_row")
        if not si.roller_length <= si.width:
            raise InputError(f"{where}: roller_length = {self.roller_length} exceeds the width {self.width}")
        if (self.conformity_inner is None) != (self.conformity_outer is None):
            raise InputError(f"{where}: conformity_inner = {self.conformity_inner!r}, conformity_outer = "
                             f"{self.conformity_outer!r}; give both (R_r / r_race of each raceway) or neither")

    # ------------------------------------------------------------------ derived geometry (SI)
    @property
    def d_m(self) -> float:
        """Pitch diameter [m] ((d + D)/2 unless given)."""
        return pitch_diameter_of(self)

    @property
    def gamma(self) -> float:
        """gamma = D_w cos(alpha) / d_m."""
        return self.si.roller_diameter * math.cos(self.si.contact_angle) / self.d_m

    @property
    def contact_radii(self) -> dict[str, float]:
        """Reduced radii in the rolling direction [m] of the inner and outer line contacts
        (1/R = 1/R_roller ± 1/R_race; the outer raceway is concave)."""
        half = 0.5 * self.si.roller_diameter
        return {"inner": half * (1.0 - self.gamma), "outer": half * (1.0 + self.gamma)}

    @property
    def conformal(self) -> bool:
        """Whether the conformities are given (the contacts are finite lines, module docstring)."""
        return self.conformity_outer is not None

    @property
    def outer_raceway_radius(self) -> float:
        """Radius r_o [m] of the spherical outer raceway, d_m / (2 cos alpha) + D_w / 2."""
        return 0.5 * self.d_m / math.cos(self.si.contact_angle) + 0.5 * self.si.roller_diameter

    @property
    def roller_contour_radius(self) -> float | None:
        """The roller's contour radius R_r = f_o r_o [m] (None without the conformities)."""
        return self.conformity_outer * self.outer_raceway_radius if self.conformal else None

    @property
    def axial_radii(self) -> dict[str, float] | None:
        """Reduced radii across rolling [m] of the inner and outer contact, R_y = R_r / (1 - f) (None without the
        conformities)."""
        if not self.conformal:
            return None
        R_r = self.roller_contour_radius
        return {"inner": R_r / (1.0 - self.conformity_inner), "outer": R_r / (1.0 - self.conformity_outer)}

    def raceway_profiles(self) -> dict | None:
        """The gap across rolling of each raceway contact as a roller profile: a crown y^2 / (2 R_y), i.e.
        :class:`~camcontact.contact.roller_profile.RollerProfile` ``"crowned"`` with the drop l_we^2 / (8 R_y) at the
        roller's ends (None without the conformities)."""
        from ..contact.roller_profile import RollerProfile

        if not self.conformal:
            return None
        length = self.si.roller_length
        return {race: RollerProfile(kind="crowned", crown_drop=length**2 / (8.0 * R_y))
                for race, R_y in self.axial_radii.items()}

    @property
    def stiffness(self) -> float:
        """K_n [N/m^(10/9)] of one roller, inner and outer contact in series (Palmgren 1959)."""
        from ..contact.load_distribution import line_contact_stiffness

        return line_contact_stiffness(self.si.roller_length)

    @property
    def roller_count(self) -> int:
        """Total number of rollers, rows x rollers per row [-]."""
        return self.rows * self.rollers_per_row

    # ------------------------------------------------------------------ analysis helpers
    def load_distribution(self, radial_load, axial_load="0 N"):
        """Roller loads under F_r and F_a [force] (Quantities or strings) by
        :func:`camcontact.contact.load_distribution.solve_load_distribution`."""
        from ..units import si_value, to_quantity

        Fr = si_value(to_quantity(radial_load, "[force]", where="load_distribution(radial_load)"))
        Fa = si_value(to_quantity(axial_load, "[force]", where="load_distribution(axial_load)"))
        return self.load_distribution_si(Fr, Fa)

    def load_distribution_si(self, radial_load: float, axial_load: float = 0.0):
        """:meth:`load_distribution` for SI forces [N] (the scenes' entry)."""
        from ..contact.load_distribution import solve_load_distribution

        return solve_load_distribution(
            radial_load, axial_load, rollers_per_row=self.rollers_per_row, contact_angle=self.si.contact_angle,
            stiffness=self.stiffness, clearance=self.si.radial_clearance, rows=self.rows,
            row_offset=self.si.row_offset,
        )
