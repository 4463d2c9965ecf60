"""A ball bearing in service: the scene component of a ball bearing analysis.

:class:`LoadedBallBearing` puts a :class:`~camcontact.components.BallBearing` under its operating
conditions — radial, axial and (optionally) tilting-moment load, ring speeds, lubricant and
temperature, and the life requirements — so that an :class:`~camcontact.analysis.Analysis` can
distribute the load over the balls with their contact angles, evaluate both elliptical contacts of
every ball and the rating life (see :mod:`camcontact.scenes.ball_bearing`).
"""

from __future__ import annotations

import attrs

from ..units import Quantity, instance_of, non_negative, positive, quantity_field, text
from .ball_bearing import BallBearing
from .bearing_service import BearingService

__all__ = ["LoadedBallBearing"]


@attrs.frozen(kw_only=True)
class LoadedBallBearing(BearingService):
    """A ball bearing under load, speed and lubrication.

    Parameters
    ----------
    bearing : BallBearing
    radial_load : Quantity or str
        F_r [force] (>= 0; defines azimuth 0).
    axial_load : Quantity or str
        F_a [force]; default 0 (an angular-contact bearing takes it on the flanks of its contact angle:
        positive).
    moment : Quantity or str, optional
        Tilting moment [force x length] on the inner ring in the plane of the radial load (about the axis
        normal to it; positive: it presses the ball on the load line, azimuth 0, onto the flank of the axial
        load's direction); None (default): the shaft holds the inner ring square (no tilt) and the moment the
        balls exert is reported (``tilting_moment``). A moment out of that plane is not modelled.
    speed : Quantity or str
        Inner-ring speed [1/time] (e.g. "3000 rpm").
    outer_speed : Quantity or str
        Outer-ring speed [1/time]; default 0.
    lubricant : Lubricant, optional
        Needed for films, Lambda and the modified life.
    temperature : Quantity or str, optional
        Operating temperature of the lubricant [temperature].
    reliability : float
        Required reliability [%] for L_nm (90..99.95; default 90).
    contamination : float, optional
        ISO 281 contamination factor e_C (0 < e_C <= 1) for a_ISO.
    contact_stress_limit : Quantity or str
        Peak Hertz pressure above which ``stress_limit_exceeded`` is True [pressure] (default 4.2 GPa, the
        static rating of ball bearings in ISO 76:2006).
    name : str

    Examples
    --------
    >>> import camcontact as cc
    >>> bearing = cc.BallBearing(designation="6309", bore="45 mm", outer_diameter="100 mm", width="25 mm",
    ...                          ball_count=8, ball_diameter="17.462 mm", inner_osculation=0.52,
    ...                          outer_osculation=0.53, C="55.3 kN", C0="31.5 kN")
    >>> cc.LoadedBallBearing(bearing=bearing, radial_load="10 kN", speed="3000 rpm").radial_load
    <Quantity(10.0, 'kilonewton')>
    """

    name: str = attrs.field(default="ball bearing", validator=text)
    bearing: BallBearing = attrs.field(validator=instance_of(BallBearing))
    radial_load: Quantity = quantity_field("[force]", validators=[non_negative("N")])
    axial_load: Quantity = quantity_field("[force]", default="0 N")
    moment: Quantity = quantity_field("[force] * [length]", optional=True)
    contact_stress_limit: Quantity = quantity_field("[pressure]", default="4.2 GPa", validators=[positive("Pa")])
