"""A ball bearing in service: the scene component of a ball bearing analysis.

:class:`LoadedBallBearing` puts a :class:`~camcontact.components.BallBearing` under its operating
conditions — radial, axial and (optionally) tilting-moment load, ring speeds, lubricant and
temperature, and the life requirements — so that an :class:`~camcontact.analysis.Analysis` can
distribute the load over the balls with their contact angles, evaluate both elliptical contacts of
every ball and the rating life (see :mod:`camcontact.scenes.ball_bearing`). An angular-contact bearing may
be one of a pair (``arrangement``: back to back, face to face or in tandem, with an axial ``preload``).
"""

from __future__ import annotations

import attrs

from ..contact.ball_load_distribution import OPPOSED_ARRANGEMENTS, PAIR_ARRANGEMENTS
from ..errors import InputError
from ..units import Quantity, format_quantity, instance_of, non_negative, one_of, positive, quantity_field, text
from .ball_bearing import BallBearing
from .bearing_service import BearingService

__all__ = ["ARRANGEMENTS", "LoadedBallBearing"]

#: one bearing, or one of a pair of identical angular-contact bearings on one shaft
ARRANGEMENTS = ("single", *PAIR_ARRANGEMENTS)


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
    arrangement : str
        "single" (default) or, for an ``angular_contact`` bearing, a pair of two of them on one shaft:
        "back_to_back" (DB, O), "face_to_face" (DF, X) or "tandem" (DT); the loads are then the pair's, positive F_a
        pressing the first bearing (row 0) onto its flanks, and the balls of both bearings are reported
        (``ball_row`` 0 or 1).
    preload : Quantity or str
        Axial preload of a DB / DF pair [length] (the interference of the clamped pair; default 0, >= 0).
    row_spacing : Quantity or str, optional
        Axial distance between the two bearings' ball centres [length] (> 0; default the bearing width B).
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
    arrangement: str = attrs.field(default="single", validator=one_of(*ARRANGEMENTS))
    preload: Quantity = quantity_field("[length]", default="0 um", validators=[non_negative("m")])
    row_spacing: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    contact_stress_limit: Quantity = quantity_field("[pressure]", default="4.2 GPa", validators=[positive("Pa")])

    def __attrs_post_init__(self) -> None:
        where = f"LoadedBallBearing {self.name!r}"
        if self.arrangement != "single" and self.bearing.kind != "angular_contact":
            raise InputError(f"{where}: arrangement = {self.arrangement!r} is for angular_contact bearings; "
                             f"BallBearing {self.bearing.designation or self.bearing.name!r} is {self.bearing.kind} "
                             "(allowed: 'single')")
        if self.si.preload != 0.0 and self.arrangement not in OPPOSED_ARRANGEMENTS:
            raise InputError(f"{where}: preload = {format_quantity(self.preload)} needs a pair clamped against each "
                             f"other (arrangement 'back_to_back' or 'face_to_face'); with arrangement = "
                             f"{self.arrangement!r} allowed: '0 um'")
        if self.row_spacing is not None and self.arrangement == "single":
            raise InputError(f"{where}: row_spacing = {format_quantity(self.row_spacing)} is the distance between the "
                             "bearings of a pair; arrangement = 'single' has one row (set the arrangement, or leave "
                             "row_spacing None)")

    @property
    def paired(self) -> bool:
        """True for one of a pair of bearings (``arrangement`` other than "single")."""
        return self.arrangement != "single"
