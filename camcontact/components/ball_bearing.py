"""Ball bearing: catalogue geometry, ratings and the internal geometry of its ball-raceway contacts.

A single-row deep-groove or angular-contact ball bearing: Z balls of diameter D_w on the pitch
diameter d_m, inner and outer raceway grooves of radii f_i D_w and f_o D_w (the osculations f > 0.5),
and either a diametral clearance P_d (deep groove: the free contact angle follows,
alpha_0 = arccos(1 - P_d / (2 (f_i + f_o - 1) D_w)), Harris & Kotzalas 2007 Eq. 2.9) or a nominal
contact angle alpha_0 (angular contact). A ball touches each raceway in an elliptical contact with the
reduced radii R_x = (D_w/2)(1 -/+ gamma) along rolling (inner/outer, gamma = D_w cos(alpha)/d_m) and
R_y = f D_w/(2 f - 1) across (Harris & Kotzalas ch. 2; the major axis of the ellipse lies across).

The ratings C (dynamic), C0 (static) and P_u (fatigue load limit) come from the catalogue; without a C
the ISO 281:2007 rating C_r = b_m f_c (cos alpha)^0.7 Z^(2/3) D_w^1.8 is used
(:func:`camcontact.models.iso281_ball.dynamic_load_rating`). :meth:`BallBearing.load_distribution`
distributes radial, axial and moment loads over the balls with the contact angle changing under load
(:mod:`camcontact.contact.ball_load_distribution`).
"""

from __future__ import annotations

import math

import attrs

from ..errors import InputError
from ..units import (ANGLE, Component, Quantity, in_range, instance_of, integer_in_range, non_negative, number_field,
                     one_of, positive, quantity_field, text)
from .bearing_envelope import check_bearing_envelope, pitch_diameter_of
from .material import Material

__all__ = ["BallBearing", "BALL_BEARING_KINDS"]

#: the ball bearing types this component describes
BALL_BEARING_KINDS = ("deep_groove", "angular_contact")
#: ISO 281 treats radial ball bearings up to this nominal contact angle (above: thrust bearings)
MAX_CONTACT_ANGLE = 45.0
MAX_BALLS = 1000


def _osculation():
    return [in_range(0.5, 1.0, lower_inclusive=False, upper_inclusive=False)]


@attrs.frozen(kw_only=True)
class BallBearing(Component):
    """A single-row deep-groove or angular-contact ball bearing from catalogue data.

    Parameters
    ----------
    designation : str
        Catalogue designation (e.g. "6309").
    kind : str
        "deep_groove" (radial; contact angle from the clearance, both flanks) or "angular_contact"
        (its balls touch one flank of each groove at the nominal ``contact_angle``).
    bore, outer_diameter, width : Quantity or str
        d, D, B [length].
    ball_count : int
        Z (3..1000).
    ball_diameter : Quantity or str
        D_w [length].
    pitch_diameter : Quantity or str, optional
        d_m [length]; default (d + D)/2.
    inner_osculation, outer_osculation : float
        f_i = r_i / D_w and f_o = r_o / D_w, the groove radii over the ball diameter (0.5 < f < 1;
        typically 0.515-0.53; ISO 281's f_c assumes f_i <= 0.52 and f_o <= 0.53).
    contact_angle : Quantity or str, optional
        Nominal (free) contact angle alpha_0 of an angular-contact bearing [angle], 0 < alpha_0 <= 45°.
        None for a deep-groove bearing (its free contact angle follows from the clearance).
    radial_clearance : Quantity or str
        Diametral (radial internal) clearance P_d of a deep-groove bearing [length] (default 0;
        negative: preload). Must be below 2 (f_i + f_o - 1) D_w.
    C, C0 : Quantity or str
        Basic dynamic and static load ratings [force]; C None: ISO 281's C_r from the geometry.
    fatigue_load_limit : Quantity or str, optional
        P_u [force] (for a_ISO).
    f0 : float, optional
        ISO 76 factor f_0 (catalogues list it) for the axial-load factors of ISO 281 (f_0 F_a / C_0r); None:
        f_0 F_a / C_0r = F_a / (Z D_w^2 cos alpha) [N/mm^2] from ISO 76's C_0r = f_0 Z D_w^2 cos(alpha).
    material : Material, optional
        Rings and balls (needed for the load distribution's Hertz stiffness, stresses and films).
    roughness : Quantity or str, optional
        RMS roughness of each surface [length] (composite = sqrt(2) times it).
    inner_shoulder_diameter, outer_shoulder_diameter : Quantity or str, optional
        Diameters of the inner ring's and the outer ring's shoulders (lands) beside the grooves [length], both or
        neither (catalogues print them, e.g. SKF's d_1 and D_2, as approximate values): of an angular-contact
        bearing the shoulders on the side its contact angle points to (the thrust side); a deep-groove bearing's are
        alike on both sides. With them the scene checks whether each contact ellipse runs over a shoulder
        (:attr:`shoulder_angles`).
    name : str

    Examples
    --------
    >>> import camcontact as cc
    >>> bearing = cc.BallBearing(designation="6309", bore="45 mm", outer_diameter="100 mm", width="25 mm",
    ...                          ball_count=8, ball_diameter="17.462 mm", inner_osculation=0.52,
    ...                          outer_osculation=0.53, C="55.3 kN", C0="31.5 kN")
    >>> round(bearing.d_m * 1e3, 1), round(bearing.gamma, 4)
    (72.5, 0.2409)
    """

    name: str = attrs.field(default="bearing", validator=text)
    designation: str = attrs.field(default="", validator=text)
    kind: str = attrs.field(default="deep_groove", validator=one_of(*BALL_BEARING_KINDS))
    bore: Quantity = quantity_field("[length]", validators=[positive("m")])
    outer_diameter: Quantity = quantity_field("[length]", validators=[positive("m")])
    width: Quantity = quantity_field("[length]", validators=[positive("m")])
    ball_count: int = attrs.field(validator=integer_in_range(3, MAX_BALLS))
    ball_diameter: Quantity = quantity_field("[length]", validators=[positive("m")])
    pitch_diameter: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    inner_osculation: float = number_field(validators=_osculation())
    outer_osculation: float = number_field(validators=_osculation())
    contact_angle: Quantity = quantity_field(ANGLE, optional=True, validators=[
        in_range(0.0, math.radians(MAX_CONTACT_ANGLE), lower_inclusive=False, unit="rad")])
    radial_clearance: Quantity = quantity_field("[length]", default="0 mm")
    C: Quantity = quantity_field("[force]", optional=True, validators=[positive("N")])
    C0: Quantity = quantity_field("[force]", validators=[positive("N")])
    fatigue_load_limit: Quantity = quantity_field("[force]", optional=True, validators=[positive("N")])
    f0: float = number_field(optional=True, validators=[positive()])
    material: Material | None = attrs.field(default=None, validator=attrs.validators.optional(instance_of(Material)))
    roughness: Quantity = quantity_field("[length]", optional=True, validators=[non_negative("m")])
    inner_shoulder_diameter: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    outer_shoulder_diameter: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])

    def __attrs_post_init__(self) -> None:
        si, where = self.si, f"BallBearing {self.designation or self.name!r}"
        check_bearing_envelope(where, self, "ball_diameter", "ball_count")
        if self.kind == "angular_contact":
            if self.contact_angle is None:
                raise InputError(f"{where}: an angular_contact bearing needs its contact_angle (nominal, e.g. '40 deg'; "
                                 f"allowed 0 < alpha_0 <= {MAX_CONTACT_ANGLE:g} deg)")
            if si.radial_clearance != 0.0:
                raise InputError(f"{where}: radial_clearance = {self.radial_clearance} is for a deep_groove bearing; an "
                                 "angular_contact bearing is set by its contact_angle")
        else:
            if self.contact_angle is not None:
                raise InputError(f"{where}: contact_angle = {self.contact_angle} is for an angular_contact bearing; a "
                                 "deep_groove bearing's free contact angle follows from its radial_clearance")
            limit = 2.0 * self.groove_distance
            if not si.radial_clearance < limit:
                raise InputError(f"{where}: radial_clearance = {self.radial_clearance} is not below 2 (f_i + f_o - 1) D_w "
                                 f"= {limit * 1e3:.4g} mm: the balls would not stay in their grooves")
            if self.free_contact_angle > math.radians(MAX_CONTACT_ANGLE):
                raise InputError(f"{where}: radial_clearance = {self.radial_clearance} gives a free contact angle of "
                                 f"{math.degrees(self.free_contact_angle):.3g} deg, above the {MAX_CONTACT_ANGLE:g} deg of "
                                 "a radial bearing (the clearance is too large for the grooves)")
        self._check_shoulders(where)

    def _check_shoulders(self, where: str) -> None:
        if (self.inner_shoulder_diameter is None) != (self.outer_shoulder_diameter is None):
            raise InputError(f"{where}: inner_shoulder_diameter = {self.inner_shoulder_diameter}, outer_shoulder_diameter "
                             f"= {self.outer_shoulder_diameter}; give both or neither")
        if self.inner_shoulder_diameter is None:
            return
        centres, radii = self.groove_centre_radii, self.groove_radii
        bounds = {"inner": (2.0 * (centres["inner"] - radii["inner"]), 2.0 * centres["inner"]),
                  "outer": (2.0 * centres["outer"], 2.0 * (centres["outer"] + radii["outer"]))}
        for race, (low, high) in bounds.items():
            field = f"{race}_shoulder_diameter"
            value = getattr(self.si, field)
            if not low < value < high:
                raise InputError(f"{where}: {field} = {getattr(self, field)}; allowed between {low * 1e3:.4g} and "
                                 f"{high * 1e3:.4g} mm (the shoulder must rise above the groove's bottom and stay below "
                                 "the groove's curvature centre)")

    # ------------------------------------------------------------------ derived geometry (SI)
    @property
    def d_m(self) -> float:
        """Pitch diameter [m] ((d + D)/2 unless given)."""
        return pitch_diameter_of(self)

    @property
    def groove_distance(self) -> float:
        """A = (f_i + f_o - 1) D_w [m], the distance of the groove curvature centres (Harris & Kotzalas Eq. 2.4)."""
        return (self.inner_osculation + self.outer_osculation - 1.0) * self.si.ball_diameter

    @property
    def free_contact_angle(self) -> float:
        """alpha_0 [rad]: the nominal angle of an angular-contact bearing; of a deep-groove bearing
        arccos(1 - P_d / (2A)) (0 without clearance; Harris & Kotzalas Eq. 2.9)."""
        if self.kind == "angular_contact":
            return self.si.contact_angle
        return math.acos(max(-1.0, min(1.0, 1.0 - self.si.radial_clearance / (2.0 * self.groove_distance))))

    @property
    def groove_radii(self) -> dict[str, float]:
        """Groove radii r = f D_w [m] of the inner and outer raceway."""
        D = self.si.ball_diameter
        return {"inner": self.inner_osculation * D, "outer": self.outer_osculation * D}

    @property
    def groove_centre_radii(self) -> dict[str, float]:
        """Radii [m] of the circles the grooves' curvature centres lie on (radial section, unloaded, at the free contact
        angle alpha_0): d_m/2 + (f_i - 1/2) D_w cos(alpha_0) inner, d_m/2 - (f_o - 1/2) D_w cos(alpha_0) outer (Harris &
        Kotzalas 2007, ch. 2)."""
        D, c = self.si.ball_diameter, math.cos(self.free_contact_angle)
        return {"inner": 0.5 * self.d_m + (self.inner_osculation - 0.5) * D * c,
                "outer": 0.5 * self.d_m - (self.outer_osculation - 0.5) * D * c}

    @property
    def shoulder_angles(self) -> dict[str, float] | None:
        """The angle [rad] from the radial direction, seen from each groove's curvature centre, at which the groove
        meets its shoulder: cos(theta) = (rho_i - d_s/2) / r_i inner, (D_s/2 - rho_o) / r_o outer (rho the centre
        radii of :attr:`groove_centre_radii`, r the groove radii). A contact whose ellipse reaches past it (contact
        angle plus the ellipse's half-width across rolling over r) is truncated by the shoulder (Harris & Kotzalas
        2007, ch. 7: the truncation of the contact ellipse under heavy axial load). None without the shoulders."""
        if self.inner_shoulder_diameter is None:
            return None
        centres, radii = self.groove_centre_radii, self.groove_radii
        return {"inner": math.acos((centres["inner"] - 0.5 * self.si.inner_shoulder_diameter) / radii["inner"]),
                "outer": math.acos((0.5 * self.si.outer_shoulder_diameter - centres["outer"]) / radii["outer"])}

    @property
    def rating_contact_angle(self) -> float:
        """The nominal contact angle ISO 281 rates the bearing with [rad] (0 for a deep-groove bearing)."""
        return self.free_contact_angle if self.kind == "angular_contact" else 0.0

    @property
    def gamma(self) -> float:
        """gamma = D_w cos(alpha_0) / d_m [-]."""
        return self.si.ball_diameter * math.cos(self.free_contact_angle) / self.d_m

    def contact_radii(self, contact_angle: float | None = None) -> dict[str, tuple[float, float]]:
        """(R_x, R_y) [m] of the inner and outer ball-raceway contacts at ``contact_angle`` [rad]
        (default the free one)."""
        from ..contact.ball_load_distribution import ball_race_radii

        alpha = self.free_contact_angle if contact_angle is None else contact_angle
        return {race: ball_race_radii(self.si.ball_diameter, self.d_m, f, alpha, race)
                for race, f in (("inner", self.inner_osculation), ("outer", self.outer_osculation))}

    @property
    def dynamic_load_rating(self) -> float:
        """C [N]: the catalogue's, or ISO 281's C_r from the geometry when none is given."""
        if self.C is not None:
            return self.si.C
        return self.iso_dynamic_load_rating

    @property
    def iso_dynamic_load_rating(self) -> float:
        """ISO 281:2007 C_r [N] from the geometry (:func:`camcontact.models.iso281_ball.dynamic_load_rating`)."""
        from ..models.iso281_ball import dynamic_load_rating

        return dynamic_load_rating(self.si.ball_diameter, self.d_m, self.ball_count, self.rating_contact_angle,
                                   inner_osculation=self.inner_osculation, outer_osculation=self.outer_osculation)

    # ------------------------------------------------------------------ analysis helpers
    def load_distribution(self, radial_load, axial_load="0 N", moment=None):
        """Ball loads and contact angles under F_r, F_a [force] and, if given, a tilting moment [force x length]
        in the plane of F_r (Quantities or strings) by
        :func:`camcontact.contact.ball_load_distribution.solve_ball_load_distribution`."""
        from ..units import si_value, to_quantity

        Fr = si_value(to_quantity(radial_load, "[force]", where="load_distribution(radial_load)"))
        Fa = si_value(to_quantity(axial_load, "[force]", where="load_distribution(axial_load)"))
        M = None if moment is None else si_value(to_quantity(moment, "[force] * [length]", where="load_distribution(moment)"))
        return self.load_distribution_si(Fr, Fa, M)

    def load_distribution_si(self, radial_load: float, axial_load: float = 0.0, moment: float | None = None):
        """:meth:`load_distribution` for SI loads [N, N m] (the scene's entry); needs the material."""
        from ..contact.ball_load_distribution import solve_ball_load_distribution

        angular = self.kind == "angular_contact"
        return solve_ball_load_distribution(
            radial_load, axial_load, moment, **self._ball_geometry("load distribution"),
            clearance=0.0 if angular else self.si.radial_clearance,
            free_contact_angle=self.si.contact_angle if angular else None)

    def _ball_geometry(self, what: str) -> dict:
        from ..contact.geometry import reduced_modulus

        if self.material is None:
            raise InputError(f"BallBearing {self.designation or self.name!r}: the {what} needs the material "
                             "(the Hertz stiffness of each ball's contacts); set BallBearing.material")
        m = self.material
        return dict(ball_count=self.ball_count, ball_diameter=self.si.ball_diameter, pitch_diameter=self.d_m,
                    inner_osculation=self.inner_osculation, outer_osculation=self.outer_osculation,
                    E_reduced=reduced_modulus(m.si.E, m.nu, m.si.E, m.nu))

    def pair_load_distribution(self, radial_load, axial_load="0 N", moment=None, *, arrangement="back_to_back",
                               preload="0 um", row_spacing=None):
        """Ball loads and contact angles of two of these angular-contact bearings mounted as a pair
        (``arrangement`` "back_to_back", "face_to_face" or "tandem"; axial ``preload`` [length] of the clamped pair,
        DB / DF only; ``row_spacing`` [length] between the rows' ball centres, default the width B of two bearings
        side by side) under F_r, F_a [force] and a tilting moment [force x length] in the plane of F_r (None holds
        the tilt at zero) by :func:`camcontact.contact.ball_load_distribution.solve_ball_pair_load_distribution`;
        positive F_a loads the first bearing (row 0)."""
        from ..units import si_value, to_quantity

        Fr = si_value(to_quantity(radial_load, "[force]", where="pair_load_distribution(radial_load)"))
        Fa = si_value(to_quantity(axial_load, "[force]", where="pair_load_distribution(axial_load)"))
        M = None if moment is None else si_value(to_quantity(moment, "[force] * [length]",
                                                             where="pair_load_distribution(moment)"))
        spacing = None if row_spacing is None else si_value(
            to_quantity(row_spacing, "[length]", where="pair_load_distribution(row_spacing)"))
        return self.pair_load_distribution_si(
            Fr, Fa, M, arrangement=arrangement, row_spacing=spacing,
            preload=si_value(to_quantity(preload, "[length]", where="pair_load_distribution(preload)")))

    def pair_load_distribution_si(self, radial_load: float, axial_load: float = 0.0, moment: float | None = None, *,
                                  arrangement: str = "back_to_back", preload: float = 0.0,
                                  row_spacing: float | None = None):
        """:meth:`pair_load_distribution` for SI loads [N, N m] and lengths [m] (the scene's entry); needs the
        material."""
        from ..contact.ball_load_distribution import solve_ball_pair_load_distribution

        where = f"BallBearing {self.designation or self.name!r}"
        if self.kind != "angular_contact":
            raise InputError(f"{where}: kind = {self.kind!r}; pairs are of angular_contact bearings (a deep-groove "
                             "bearing carries both axial directions itself)")
        return solve_ball_pair_load_distribution(
            radial_load, axial_load, moment, arrangement=arrangement,
            row_spacing=self.si.width if row_spacing is None else row_spacing, preload=preload,
            free_contact_angle=self.si.contact_angle, **self._ball_geometry("pair load distribution"))

    def pair_reference_life(self, radial_load, axial_load="0 N", moment=None, *, arrangement="back_to_back",
                            preload="0 um", row_spacing=None, inner_rotates=True) -> dict:
        """ISO/TS 16281 L_10r [revolutions] of the pair of :meth:`pair_load_distribution`: each bearing's from its
        ball loads with this bearing's C (:attr:`dynamic_load_rating`), combined as the two rings of a bearing are,
        L_10r = (sum_k L_k^(-10/9))^(-9/10) (the Weibull slope 10/9 of ball bearings;
        :func:`camcontact.models.iso281_ball.pair_reference_rating_life`). Returns ``L10r``, ``L10r_rows`` (per
        bearing) and the ``distribution``."""
        from ..models.iso281_ball import pair_reference_rating_life

        result = self.pair_load_distribution(radial_load, axial_load, moment, arrangement=arrangement,
                                             preload=preload, row_spacing=row_spacing)
        life = pair_reference_rating_life(result.Q, result.row, C=self.dynamic_load_rating,
                                          ball_diameter=self.si.ball_diameter, pitch_diameter=self.d_m,
                                          contact_angle=self.si.contact_angle, inner_osculation=self.inner_osculation,
                                          outer_osculation=self.outer_osculation, inner_rotates=inner_rotates)
        return {"L10r": life["L10r"] * 1e6, "L10r_rows": tuple(1e6 * L for L in life["L10r_rows"]),
                "distribution": result}
