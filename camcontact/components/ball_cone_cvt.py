"""The ball-cone traction CVT (Forti's "TrackBall" of Saccheto 2008) and its operating point.

:class:`BallConeCVT` is the design: cones, balls, ball tilt range, loading cam, material and
traction fluid. :class:`LoadedBallConeCVT` puts it at an operating point (power, input speed,
ratio, lubricant temperature) for an :class:`~camcontact.analysis.Analysis` (see
:mod:`camcontact.scenes.ball_cone_cvt`). Reference: ``ball_cone_cvt_saccheto2008.md`` §2.9-2.11, §3.1.
"""

from __future__ import annotations

import math

import attrs

from ..errors import InputError
from ..kinematics.ball_cone import overrange, ratio_of_tilt, tilt_of_ratio
from ..units import (ANGLE, Component, Quantity, above_absolute_zero, format_quantity, in_range, instance_of,
                     non_negative, number_field, one_of, positive, quantity_field, text)
from .lubricant import Lubricant
from .material import Material

__all__ = ["ISO76_BALL_CONTACT_STRESS", "BallConeCVT", "LoadedBallConeCVT"]

#: ISO 76:2006 §6.1.1: the basic static load rating of a ball bearing (other than self-aligning)
#: corresponds to a calculated contact stress of 4200 MPa at the centre of the most heavily loaded
#: contact (4600 MPa self-aligning ball, 4000 MPa roller bearings)
ISO76_BALL_CONTACT_STRESS = "4200 MPa"

_RIGHT = math.pi / 2
#: the most balls (of the loading cam or between the cones) a design may have
MAX_COUNT = 1000


def _count(instance, attribute, value):
    if not (isinstance(value, int) and not isinstance(value, bool) and 1 <= value <= MAX_COUNT):
        raise InputError(f"{type(instance).__name__}.{attribute.name} = {value!r}; allowed: an integer "
                         f"1 .. {MAX_COUNT}")


def _open_angle():
    return [in_range(0.0, _RIGHT, lower_inclusive=False, upper_inclusive=False, unit="rad")]


@attrs.frozen(kw_only=True)
class BallConeCVT(Component):
    """A ball-cone traction CVT: n balls between an input and an output cone, clamped by a loading cam.

    Parameters
    ----------
    cone_angle : Quantity or str
        alpha: angle between the cone axis and the tangent plane at the contact [angle] (30 deg).
    cone_contact_radius : Quantity or str
        R_cont: radius of the cones' contact track [length] (not printed by the thesis: about
        24 mm reproduces its mu_min, 23.28 mm its spin table — reference §3.1, §4.2).
    ball_diameter : Quantity or str
        [length] (14 mm).
    ball_count : int
        n (9).
    tilt_max : Quantity or str
        beta_max: largest ball tilt either way [angle] (30 deg; the ratio range and overrange follow).
    cam_ramp_angle : Quantity or str
        eta: ramp angle of the loading cam ("proportional device") [angle] (10 deg; Forti asks tan eta > 1/8).
    cam_radius : Quantity or str
        R_cam: radius of the cam's balls [length] (6 mm reproduces the thesis; its table prints 12 mm,
        most likely the diameter).
    cam_ball_count : int
        m (5).
    material : Material
        Balls and cones (E = 207 GPa, nu = 0.3 implied by the thesis, reference §4.6).
    traction_coefficient : float
        Ct, the traction fluid's limiting traction coefficient (0 < Ct <= 1).
    lubricant : Lubricant, optional
        The traction fluid's viscosity data, for the EHL film.
    cone_small_diameter : Quantity or str, optional
        Smallest cone diameter [length] (42 mm); checked against the contact radius.
    roughness : Quantity or str, optional
        RMS roughness of each surface [length], for Lambda.
    ratio_convention : str
        ``"reduction"`` (default): ratio = omega_in/omega_out = BC/DE (thesis Eq. 6.2, > 1 for a
        reduction); ``"speed"``: omega_out/omega_in (its appendix P-4).
    clamping : str
        ``"axial_balance"`` (default: the cone's n contacts carry the loading cam's thrust, 5014 N per
        contact at the thesis's 150 W, 60 rpm) or ``"thesis"`` (Saccheto's Eq. 6.17, 1254 N: statically
        impossible, kept to reproduce the thesis's tables; see :mod:`camcontact.dynamics.ball_cone_loads`).
    contact_stress_limit : Quantity or str
        Largest allowed Hertz peak pressure [pressure] (default 4.2 GPa: the contact stress behind the
        static load rating of ball bearings other than self-aligning, ISO 76:2006 §6.1.1). Above it
        the report flags ``stress_limit_exceeded`` and warns; set a lower value for a design-practice
        limit (e.g. a traction drive's fatigue rating).
    asperity_density, asperity_radius : Quantity or str, optional
        Summit density η [1/length²] and radius β [length] (> 0) of the composite roughness of the ball-cone
        contacts for the ``mixed`` effect (Greenwood–Tripp), as :class:`~camcontact.components.LineContact`'s
        (defaults there: η β σ = σ/β = 0.05, orders of magnitude, not data).
    name : str
    """

    name: str = attrs.field(default="ball-cone CVT", validator=text)
    cone_angle: Quantity = quantity_field(ANGLE, validators=_open_angle())
    cone_contact_radius: Quantity = quantity_field("[length]", validators=[positive("m")])
    ball_diameter: Quantity = quantity_field("[length]", validators=[positive("m")])
    ball_count: int = attrs.field(validator=_count)
    tilt_max: Quantity = quantity_field(ANGLE, validators=_open_angle())
    cam_ramp_angle: Quantity = quantity_field(ANGLE, validators=_open_angle())
    cam_radius: Quantity = quantity_field("[length]", validators=[positive("m")])
    cam_ball_count: int = attrs.field(validator=_count)
    material: Material = attrs.field(validator=instance_of(Material))
    traction_coefficient: float = number_field(validators=[in_range(0.0, 1.0, lower_inclusive=False)])
    lubricant: Lubricant | None = attrs.field(default=None, validator=attrs.validators.optional(instance_of(Lubricant)))
    cone_small_diameter: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    roughness: Quantity = quantity_field("[length]", optional=True, validators=[non_negative("m")])
    ratio_convention: str = attrs.field(default="reduction", validator=one_of("reduction", "speed"))
    clamping: str = attrs.field(default="axial_balance", validator=one_of("axial_balance", "thesis"))
    contact_stress_limit: Quantity = quantity_field("[pressure]", default=ISO76_BALL_CONTACT_STRESS,
                                                    validators=[positive("Pa")])
    asperity_density: Quantity = quantity_field("1/[length]**2", optional=True, validators=[positive("1/m^2")])
    asperity_radius: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])

    def __attrs_post_init__(self) -> None:
        si, where = self.si, f"BallConeCVT {self.name!r}"
        if not si.cone_angle + si.tilt_max < _RIGHT:
            raise InputError(f"{where}: cone_angle + tilt_max = {math.degrees(si.cone_angle + si.tilt_max):.4g} deg "
                             "must stay below 90 deg (a contact would reach the ball's axis)")
        if self.cone_small_diameter is not None and not si.cone_small_diameter <= 2.0 * si.cone_contact_radius:
            raise InputError(f"{where}: cone_contact_radius = {format_quantity(self.cone_contact_radius)} is inside "
                             f"the smallest cone diameter cone_small_diameter = "
                             f"{format_quantity(self.cone_small_diameter)}")
        r = 0.5 * si.ball_diameter
        if not self.ball_centre_radius * math.sin(math.pi / self.ball_count) > r:
            raise InputError(f"{where}: ball_count = {self.ball_count} balls of ball_diameter = "
                             f"{format_quantity(self.ball_diameter)} do not fit around the cone (ball centres on a "
                             f"{2e3 * self.ball_centre_radius:.4g} mm circle)")

    # ------------------------------------------------------------------ derived (SI)
    @property
    def ball_radius(self) -> float:
        """r [m]."""
        return 0.5 * self.si.ball_diameter

    @property
    def contact_offset(self) -> float:
        """y = r sin(alpha) [m]: the contacts' offset from the ball's equator (reference §2.10)."""
        return self.ball_radius * math.sin(self.si.cone_angle)

    @property
    def ball_centre_radius(self) -> float:
        """Radius of the circle of ball centres [m]: R_cont + r cos(alpha) (the normal leans alpha off radial)."""
        return self.si.cone_contact_radius + self.ball_radius * math.cos(self.si.cone_angle)

    @property
    def overrange(self) -> float:
        """Largest over smallest ratio [-] (4 for alpha = beta_max = 30 deg)."""
        return overrange(self.si.cone_angle, self.si.tilt_max)

    @property
    def ratio_range(self) -> tuple[float, float]:
        """(smallest, largest) ratio in this CVT's ratio convention."""
        ends = [self.ratio(sign * self.si.tilt_max) for sign in (1.0, -1.0)]
        return min(ends), max(ends)

    def ratio(self, tilt: float) -> float:
        """Ratio at ball tilt beta [rad] (SI) in :attr:`ratio_convention`."""
        return ratio_of_tilt(self.si.cone_angle, tilt, self.ratio_convention)

    def tilt(self, ratio: float) -> float:
        """Ball tilt beta [rad] for ``ratio`` (in :attr:`ratio_convention`); InputError outside the range."""
        low, high = self.ratio_range
        if not low * (1 - 1e-12) <= ratio <= high * (1 + 1e-12):
            raise InputError(f"BallConeCVT {self.name!r}: ratio = {ratio!r} ({self.ratio_convention}) needs a tilt "
                             f"beyond tilt_max = {format_quantity(self.tilt_max)}; allowed: {low:.6g} .. {high:.6g}")
        beta = tilt_of_ratio(self.si.cone_angle, ratio, self.ratio_convention)
        return max(-self.si.tilt_max, min(self.si.tilt_max, beta))

    def reduction_ratio(self, ratio: float) -> float:
        """omega_in/omega_out for ``ratio`` given in this CVT's convention."""
        return ratio if self.ratio_convention == "reduction" else 1.0 / ratio

    @classmethod
    def cone_angle_for_overrange(cls, value: float, tilt_max: float) -> float:
        """alpha [rad] that gives overrange ``value`` with tilt_max [rad] (the thesis: 4, 6.25, 9 at 30 deg
        give alpha = 30, 36.6, 40.9 deg; reference §2.10)."""
        from scipy.optimize import brentq

        if not value > 1.0:
            raise InputError(f"overrange = {value!r}; allowed > 1")
        upper = _RIGHT - tilt_max
        return brentq(lambda a: overrange(a, tilt_max) - value, 1e-9, upper * (1 - 1e-12), xtol=1e-14)


@attrs.frozen(kw_only=True)
class LoadedBallConeCVT(Component):
    """A :class:`BallConeCVT` at an operating point.

    Parameters
    ----------
    cvt : BallConeCVT
    power : Quantity or str
        Transmitted power [power] (> 0).
    input_speed : Quantity or str
        Input cone speed [1/time] (the thesis's reference cadence: 60 rpm).
    ratio : float
        In the CVT's ratio convention (1 = 1:1); must lie within its tilt range.
    temperature : Quantity or str, optional
        Lubricant temperature [temperature], for the film.
    name : str
    """

    name: str = attrs.field(default="operating point", validator=text)
    cvt: BallConeCVT = attrs.field(validator=instance_of(BallConeCVT))
    power: Quantity = quantity_field("[power]", validators=[positive("W")])
    input_speed: Quantity = quantity_field("1/[time]", validators=[positive("1/s")])
    ratio: float = number_field(default=1.0, validators=[in_range(0.0, lower_inclusive=False)])
    temperature: Quantity = quantity_field("[temperature]", optional=True, validators=[above_absolute_zero()])

    def __attrs_post_init__(self) -> None:
        try:
            self.cvt.tilt(self.ratio)
        except InputError as error:  # a ratio beyond the tilt range
            raise InputError(f"LoadedBallConeCVT.ratio = {self.ratio!r}: {error}") from None
