"""Components: attrs classes with pint-typed fields, validated at construction."""

from .ball_bearing import BallBearing
from .ball_cone_cvt import BallConeCVT, LoadedBallConeCVT
from .cam import Cam, Follower, ValveTrain
from .cam_follower import CamFollower
from .cylindrical_roller_bearing import CylindricalRollerBearing
from .line_contact import Body, LineContact
from .loaded_ball_bearing import LoadedBallBearing
from .loaded_bearing import LoadedBearing
from .loaded_cylindrical_roller_bearing import LoadedCylindricalRollerBearing
from .lubricant import Lubricant, LubricantState
from .material import Material
from .point_contact import PointContact
from .raceway_contact import RacewayContact
from .spherical_roller_bearing import SphericalRollerBearing

__all__ = ["BallBearing", "BallConeCVT", "Body", "Cam", "CamFollower", "CylindricalRollerBearing", "Follower", "LineContact", "LoadedBallBearing",
           "LoadedBallConeCVT", "LoadedBearing", "LoadedCylindricalRollerBearing", "Lubricant", "LubricantState", "Material", "PointContact", "RacewayContact", "SphericalRollerBearing", "ValveTrain"]
