"""Components: attrs classes with pint-typed fields, validated at construction."""

from .cam import Cam, Follower, ValveTrain
from .cam_follower import CamFollower
from .line_contact import Body, LineContact
from .loaded_bearing import LoadedBearing
from .lubricant import Lubricant, LubricantState
from .material import Material
from .raceway_contact import RacewayContact
from .spherical_roller_bearing import SphericalRollerBearing

__all__ = ["Body", "Cam", "CamFollower", "Follower", "LineContact", "LoadedBearing", "Lubricant", "LubricantState", "Material",
           "RacewayContact", "SphericalRollerBearing", "ValveTrain"]
