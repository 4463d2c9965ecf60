"""The cam–follower scene component: cam, follower, valve train and operating conditions."""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..errors import InputError
from ..units import (Component, Quantity, above_absolute_zero, in_range, instance_of, number_field, positive,
                     one_of, quantity_field, text)
from .cam import Cam, Follower, ValveTrain
from .lubricant import Lubricant

__all__ = ["CamFollower"]

CONVENTIONS = ("consistent", "thesis")
#: the most cam angles a report holds (a 0.00036-degree step over a turn): bounded before anything is allocated
MAX_ANGLES = 1_000_000
#: the most cam turns of the valve-train dynamics
MAX_CYCLES = 1000


@attrs.frozen(kw_only=True)
class CamFollower(Component):
    """A cam driving a translating follower through a valve train, run over a cam cycle.

    Parameters
    ----------
    cam : Cam
    follower : Follower
    valve_train : ValveTrain
        Equivalent 1-DOF system (prescribed motion); its ``lumped`` model is integrated when the
        scene's effects include ``"dynamics"``.
    speed : Quantity or str
        Cam speed [1/time] (> 0), e.g. ``"1000 rpm"``.
    angular_acceleration : Quantity or str
        Constant cam angular acceleration [1/time²] (Tsuha 2015 Eq. 3.4; default 0).
    angles : Quantity or str, optional
        Cam angles to report [angle] (an array Quantity); default every ``angle_step`` over a turn.
    angle_step : Quantity or str
        Default sampling of the cycle [angle] (default 1°; 0.00036° .. 180°, at most 10⁶ angles a turn).
    max_speed : Quantity or str, optional
        Highest cam speed the design must run without jump [1/time]; k_min is computed at it
        (Tsuha 2015 §6.1 uses 3000 rpm). Default: ``speed``.
    lubricant : Lubricant, optional
        Needed for film, friction and wear outputs.
    temperature : Quantity or str, optional
        Lubricant temperature when its viscosity depends on temperature.
    convention : {"consistent", "thesis"}
        ``"consistent"`` (default): exact surface speeds, Moes/Hamrock groups with u_m = (u1+u2)/2
        as camcontact's film models define them, normal force F/cos A_p. ``"thesis"``: the
        conventions that reproduce Tsuha (2015) Tables 6.3–6.11 — roller u_m = R_cam ω, the mean
        speed used where Moes uses the sum (films fed u_m/2, reference §0 item 10), axial force F.
    friction_coefficient : float, optional
        Coulomb friction coefficient μ for the default friction model ``coulomb`` (0 <= μ <= 1).
    wear_coefficient : float, optional
        Archard wear coefficient K for the default wear model ``archard`` (> 0; needs the cam
        material's hardness).
    cycles : int
        Cam revolutions integrated by the ``dynamics`` effect (the last one is reported; default 3; 1 .. 1000).
    asperity_density : Quantity or str, optional
        Summit density η of the pair's composite roughness [1/length²] (> 0), for the ``mixed`` effect
        (Greenwood–Tripp); default: η β σ = 0.05 with the composite σ.
    asperity_radius : Quantity or str, optional
        Summit radius β [length] (> 0) for ``mixed``; default: σ/β = 0.05. Both defaults are orders of
        magnitude of ground steel surfaces as Stribeck-curve models use them (Gelinck & Schipper 2000),
        not data: give measured values where known (:mod:`camcontact.contact.asperity_contact`).
    oil_layer : Quantity or str, optional
        The lubricant layer the surfaces carry into the contact, both together, at ambient density [length]
        (> 0): a starved contact (splash or mist lubrication). Solved by the transient march only (isothermal, or
        with ``thermal`` / ``non_newtonian``): the effect ``squeeze`` with the film model
        ``Multigrid(cavitation="mass_conserving")``
        (:class:`~camcontact.ehl.line_transient.TransientLineSolver`'s ``oil_layer``). Default: flooded.
    name : str
    """

    name: str = attrs.field(default="cam–follower", validator=text)
    cam: Cam = attrs.field(validator=instance_of(Cam))
    follower: Follower = attrs.field(validator=instance_of(Follower))
    valve_train: ValveTrain = attrs.field(validator=instance_of(ValveTrain))
    speed: Quantity = quantity_field("1/[time]", validators=[positive("rad/s")])
    angular_acceleration: Quantity = quantity_field("1/[time]**2", default="0 rad/s**2")
    angles: Quantity = quantity_field("[angle]", optional=True, array=True)
    angle_step: Quantity = quantity_field(
        "[angle]", default="1 deg", validators=[in_range(2.0 * math.pi / MAX_ANGLES, math.pi, unit="rad")]
    )
    max_speed: Quantity = quantity_field("1/[time]", optional=True, validators=[positive("rad/s")])
    lubricant: Lubricant | None = attrs.field(default=None, validator=attrs.validators.optional(instance_of(Lubricant)))
    temperature: Quantity = quantity_field("[temperature]", optional=True, validators=[above_absolute_zero()])
    convention: str = attrs.field(default="consistent", validator=one_of(*CONVENTIONS))
    friction_coefficient: float = number_field(optional=True, validators=[in_range(0.0, 1.0)])
    wear_coefficient: float = number_field(optional=True, validators=[in_range(0.0, lower_inclusive=False)])
    cycles: int = attrs.field(default=3)
    asperity_density: Quantity = quantity_field("1/[length]**2", optional=True, validators=[positive("1/m^2")])
    asperity_radius: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    oil_layer: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])

    @cycles.validator
    def _check_cycles(self, attribute, value):
        if isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= MAX_CYCLES:
            raise InputError(f"CamFollower.cycles = {value!r}; allowed: an integer 1 .. {MAX_CYCLES}")

    def __attrs_post_init__(self) -> None:
        if self.angles is not None:
            theta = np.atleast_1d(self.si.angles)
            if theta.ndim != 1 or not 0 < theta.size <= MAX_ANGLES:
                raise InputError(f"CamFollower.angles = {self.angles}: give a 1-D array of 1 .. {MAX_ANGLES} angles")

    @property
    def cam_angles(self) -> np.ndarray:
        """Cam angles of the report [rad]."""
        if self.angles is not None:
            return np.atleast_1d(np.asarray(self.si.angles, dtype=float))
        step = self.si.angle_step
        count = max(int(round(2.0 * math.pi / step)), 1)
        return np.arange(count) * (2.0 * math.pi / count)

    @property
    def geometry(self):
        """SI :class:`~camcontact.kinematics.follower.FollowerGeometry` of the pair."""
        from ..kinematics.follower import FollowerGeometry

        follower = self.follower
        if follower.kind == "flat":
            return FollowerGeometry("flat", self.cam.si.base_radius)
        return FollowerGeometry("roller", self.cam.si.base_radius, follower.si.roller_radius, follower.si.offset)
