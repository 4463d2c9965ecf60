"""camcontact: lubricated contacts of machine elements, in physical units.

Importing the package is cheap: it loads no plugin (entry points are looked up on first
use of a model family) and compiles no numba kernel.

>>> import camcontact as cc
>>> steel = cc.Material(E="210 GPa", nu=0.3)
"""

from . import registry, step_graph
from .analysis import Analysis, Result
from .components import (BallConeCVT, Body, Cam, CamFollower, Follower, LineContact, LoadedBallConeCVT, LoadedBearing,
                         Lubricant, Material, RacewayContact, SphericalRollerBearing, ValveTrain)
from .errors import ConvergenceError, ConvergenceWarning, InputError, PluginLoadWarning, UnknownModelError
from .units import Q_, ureg

__version__ = "0.1.0"


def _register_builtin_scenes() -> None:
    """Import the built-in scene builders (on the first scene lookup of an Analysis, not at import)."""
    from . import scenes  # noqa: F401


step_graph.add_scene_loader(_register_builtin_scenes)

__all__ = [
    "Analysis",
    "BallConeCVT",
    "Body",
    "Cam",
    "CamFollower",
    "ConvergenceError",
    "ConvergenceWarning",
    "Follower",
    "InputError",
    "LineContact",
    "LoadedBallConeCVT",
    "LoadedBearing",
    "Lubricant",
    "Material",
    "PluginLoadWarning",
    "RacewayContact",
    "SphericalRollerBearing",
    "Q_",
    "Result",
    "UnknownModelError",
    "ValveTrain",
    "__version__",
    "registry",
    "ureg",
]
