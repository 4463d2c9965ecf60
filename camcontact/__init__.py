"""camcontact: lubricated contacts of machine elements, in physical units.

Importing the package is cheap: it loads no plugin (entry points are looked up on first
use of a model family) and compiles no numba kernel.

>>> import camcontact as cc
>>> steel = cc.Material(E="210 GPa", nu=0.3)
"""

from . import registry, step_graph
from .analysis import Analysis, Result
from .components import (BallBearing, BallConeCVT, Body, Cam, CamFollower, CylindricalRollerBearing, Follower,
                         LineContact, LoadedBallBearing, LoadedBallConeCVT, LoadedBearing,
                         LoadedCylindricalRollerBearing, Lubricant, Material, PointContact, RacewayContact,
                         SphericalRollerBearing, ValveTrain)
from .errors import ConvergenceError, ConvergenceWarning, InputError, PluginLoadWarning, UnknownModelError
from .units import Q_, ureg

__version__ = "0.1.0"


def _register_builtin_scenes() -> None:
    """Import the built-in scene builders (on the first scene lookup of an Analysis, not at import)."""
    from . import scenes  # noqa: F401


step_graph.add_scene_loader(_register_builtin_scenes)

#: user-facing names of deeper modules, imported on first use (``cc.MotionProgram``) to keep the import cheap
_LAZY = {
    "MotionProgram": "kinematics.motion_program", "Segment": "kinematics.motion_program",
    "load_scene": "scene_file", "sweep_frame": "sweep", "run_sweep": "sweep", "read_sweep": "sweep", "to_xarray": "sweep",
    "cvt_map": "scenes.ball_cone_cvt_map", "plot_cvt_map": "scenes.ball_cone_cvt_map",
    "stribeck_sweep": "scenes.stribeck", "plot_stribeck_curve": "scenes.stribeck",
    "RollerProfile": "contact.roller_profile", "compare_roller_profiles": "scenes.roller_profile_study",
}


def __getattr__(name: str):
    if name in _LAZY:
        import importlib

        value = getattr(importlib.import_module(f".{_LAZY[name]}", __name__), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'camcontact' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))

__all__ = [
    "Analysis",
    "BallBearing",
    "BallConeCVT",
    "Body",
    "Cam",
    "CamFollower",
    "ConvergenceError",
    "ConvergenceWarning",
    "CylindricalRollerBearing",
    "Follower",
    "InputError",
    "LineContact",
    "LoadedBallBearing",
    "LoadedBallConeCVT",
    "LoadedBearing",
    "LoadedCylindricalRollerBearing",
    "Lubricant",
    "Material",
    "MotionProgram",
    "PluginLoadWarning",
    "PointContact",
    "RacewayContact",
    "RollerProfile",
    "Segment",
    "SphericalRollerBearing",
    "Q_",
    "Result",
    "UnknownModelError",
    "ValveTrain",
    "__version__",
    "compare_roller_profiles",
    "cvt_map",
    "load_scene",
    "plot_cvt_map",
    "plot_stribeck_curve",
    "read_sweep",
    "registry",
    "run_sweep",
    "stribeck_sweep",
    "sweep_frame",
    "to_xarray",
    "ureg",
]
