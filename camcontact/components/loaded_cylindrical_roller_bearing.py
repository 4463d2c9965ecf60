"""A cylindrical roller bearing in service: the scene component of its analysis (radial load, misalignment,
speeds, lubricant, life requirements; see :mod:`camcontact.scenes.cylindrical_roller_bearing`)."""

from __future__ import annotations

import attrs

from ..units import ANGLE, Quantity, instance_of, integer_in_range, non_negative, quantity_field, text
from .bearing_service import BearingService
from .cylindrical_roller_bearing import CylindricalRollerBearing

__all__ = ["LoadedCylindricalRollerBearing"]


@attrs.frozen(kw_only=True)
class LoadedCylindricalRollerBearing(BearingService):
    """A cylindrical roller bearing under a radial load and a misalignment, with speeds and lubrication.

    Parameters
    ----------
    bearing : CylindricalRollerBearing
    radial_load : Quantity or str
        F_r [force] (>= 0; defines azimuth 0).
    misalignment : Quantity or str
        Tilt of the inner ring against the outer [angle] (default 0; ISO/TS 16281's edge factor holds below 4').
    speed, outer_speed : Quantity or str
        Inner- and outer-ring speeds [1/time] (default 0).
    lubricant : Lubricant, optional
        Needed for films, Lambda and the modified life.
    temperature : Quantity or str, optional
        Operating temperature of the lubricant [temperature].
    reliability : float
        Required reliability [%] for L_nm (90..99.95; default 90).
    contamination : float, optional
        ISO 281 contamination factor e_C (0 < e_C <= 1).
    laminae : int
        Slices per roller (>= 30, ISO/TS 16281; default 30).
    name : str
    """

    name: str = attrs.field(default="cylindrical roller bearing", validator=text)
    bearing: CylindricalRollerBearing = attrs.field(validator=instance_of(CylindricalRollerBearing))
    radial_load: Quantity = quantity_field("[force]", validators=[non_negative("N")])
    misalignment: Quantity = quantity_field(ANGLE, default="0 rad")
    laminae: int = attrs.field(default=30, validator=integer_in_range(30, 1000))
