"""A bearing in service: the scene component of a bearing analysis.

:class:`LoadedBearing` puts a :class:`~camcontact.components.SphericalRollerBearing` under its
operating conditions — radial and axial load, ring speeds, lubricant and temperature, and the
life requirements (reliability, contamination factor) — so that an
:class:`~camcontact.analysis.Analysis` can distribute the load over the rollers, evaluate every
roller–raceway contact and the rating life (see :mod:`camcontact.scenes.bearing`).
"""

from __future__ import annotations

import attrs

from ..units import Quantity, in_range, instance_of, integer_in_range, non_negative, number_field, quantity_field, text
from .bearing_service import BearingService
from .spherical_roller_bearing import SphericalRollerBearing

__all__ = ["LoadedBearing"]


@attrs.frozen(kw_only=True)
class LoadedBearing(BearingService):
    """A spherical roller bearing under load, speed and lubrication.

    Parameters
    ----------
    bearing : SphericalRollerBearing
    radial_load : Quantity or str
        F_r [force] (>= 0; defines azimuth 0).
    axial_load : Quantity or str
        F_a [force] (positive: carried by the first row); default 0.
    speed : Quantity or str
        Inner-ring speed [1/time] (e.g. "300 rpm").
    outer_speed : Quantity or str
        Outer-ring speed [1/time]; default 0 (a rotating outer ring, e.g. a pellet-mill roller
        shell on a fixed shaft, is speed 0 and outer_speed > 0).
    lubricant : Lubricant, optional
        Needed for films, Lambda and the modified life (its kinematic viscosity at ``temperature``).
    temperature : Quantity or str, optional
        Operating temperature of the lubricant [temperature].
    reliability : float
        Required reliability [%] for L_nm (90..99.95; default 90).
    contamination : float, optional
        ISO 281 contamination factor e_C (0 < e_C <= 1) for a_ISO; no default (it is a judgement
        on the application's cleanliness).
    slide_roll_ratio : float, optional
        (u_ring - u_roller)/u_m at every raceway contact (0 < s < 2) for the Kelley friction and the
        flash temperature; pure rolling (no value) has no sliding friction in that correlation.
    laminae : int
        Laminae per raceway contact (>= 30, ISO/TS 16281; default 30) when the bearing's conformities make the
        contacts finite lines (:attr:`SphericalRollerBearing.conformity_inner`).
    name : str
    """

    name: str = attrs.field(default="bearing", validator=text)
    bearing: SphericalRollerBearing = attrs.field(validator=instance_of(SphericalRollerBearing))
    radial_load: Quantity = quantity_field("[force]", validators=[non_negative("N")])
    axial_load: Quantity = quantity_field("[force]", default="0 N")
    slide_roll_ratio: float = number_field(optional=True, validators=[in_range(0.0, 2.0, lower_inclusive=False,
                                                                                upper_inclusive=False)])
    laminae: int = attrs.field(default=30, validator=integer_in_range(30, 1000))
