"""Components: attrs classes with pint-typed fields, validated at construction."""

from .cam import Cam, Follower, ValveTrain
from .cam_follower import CamFollower
from .line_contact import Body, LineContact
from .lubricant import Lubricant, LubricantState
from .material import Material

__all__ = ["Body", "Cam", "CamFollower", "Follower", "LineContact", "Lubricant", "LubricantState", "Material",
           "ValveTrain"]
