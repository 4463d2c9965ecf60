"""Life steps: ISO 281 rating life of a roller bearing, Lundberg–Palmgren life of traction contacts.

ISO 281:2007 (P = F_r + Y F_a, L10 = (C/P)^(10/3) 10^6 revolutions, L_nm with a1, kappa, a_ISO;
:mod:`camcontact.models.life_iso281`); Lundberg–Palmgren after Coy & Loewenthal (Saccheto 2008 Eqs.
5.16-5.25, :mod:`camcontact.models.life_lundberg_palmgren`) with Weibull's system life (Eq. 5.20).
Forces [N], speeds [rev/s] unless named otherwise, lives in revolutions, cycles or seconds.
"""

from __future__ import annotations

import inspect
import math

import numpy as np

from .. import registry
from ..errors import InputError
from ..models.life_iso281 import LIFE_EXPONENTS, equivalent_load
from ..models.life_lundberg_palmgren import life_time, system_life
from ..step_graph import step

__all__ = ["ball_cone_life", "bearing_equivalent_load", "check_rating_life_model", "modified_rating_life",
           "rating_life"]


@step("equivalent_load", provides=("P",), model="iso281")
def bearing_equivalent_load(radial_load, axial_load, contact_angle):
    """Dynamic equivalent load P [N] of a radial roller bearing (ISO 281:2007 §6.2)."""
    return {"P": equivalent_load(radial_load, axial_load, contact_angle)}


@step("rating_life", provides=("L10", "L10h"), model="iso281")
def rating_life(C, P, n_inner, n_outer, rolling_element):
    """Basic rating life L10 = (C/P)^p 10^6 [revolutions] (p = 10/3 for a ``rolling_element`` "roller", 3 for a
    "ball") and in time [s] at the rings' relative speed |n_i - n_o| [rev/s] (infinite without load or motion)."""
    if P <= 0.0:
        return {"L10": math.inf, "L10h": math.inf}
    L10 = (C / P) ** LIFE_EXPONENTS[rolling_element] * 1e6
    relative = abs(n_inner - n_outer)
    return {"L10": L10, "L10h": L10 / relative if relative > 0 else math.inf}  # seconds (SI)


def check_rating_life_model(life_model) -> None:
    """InputError unless the life model (a name or an instance) is an ISO 281 modified rating life: a model
    made from the scene's ``reliability`` and ``contamination``."""
    if not isinstance(life_model, str):
        return
    parameters = inspect.signature(registry.get_class("life_models", life_model)).parameters
    if not {"reliability", "contamination"} <= set(parameters):
        raise InputError(f"bearing scene: life model {life_model!r} is not an ISO 281 modified rating life (it takes "
                         f"no reliability and contamination); the life slot takes 'iso281' or a model instance")


@step("modified_life", provides=("a1", "nu1", "kappa", "a_ISO", "L_nm", "L_nmh"),
      model=lambda life_model: str(life_model), check=check_rating_life_model)
def modified_rating_life(life_model, C, P, n_inner, n_outer, lubricant, lubricant_state, fatigue_load_limit,
                         reliability, contamination, pitch_diameter, rolling_element):
    """ISO 281 modified rating life L_nm with a1 (``reliability``), kappa = nu/nu1 and a_ISO (``contamination``
    e_C, fatigue load limit P_u [N]) of a bearing with ``rolling_element`` "roller" or "ball"; ``life_model`` a
    life model name (made with these) or instance."""
    if isinstance(life_model, str):
        made = {"reliability": reliability, "contamination": contamination}
        if "rolling_element" in inspect.signature(registry.get_class("life_models", life_model)).parameters:
            made["rolling_element"] = rolling_element
        model = registry.get("life_models", life_model, **made)
    else:
        model = life_model
        given_element = getattr(model, "rolling_element", rolling_element)
        if given_element != rolling_element:
            raise InputError(f"life model {model!r}: rolling_element = {given_element!r}, but the bearing's rolling "
                             f"elements are {rolling_element}s (make it with rolling_element={rolling_element!r})")
    viscosity = lubricant_state.kinematic_viscosity
    if viscosity is None:
        raise InputError(f"Lubricant {lubricant.name!r}: its kinematic viscosity at the operating "
                         "temperature is unknown (give its density or kinematic viscosity data), which kappa needs")
    produced = model({"C": C, "P": P, "speed": abs(n_inner - n_outer), "pitch_diameter": pitch_diameter,
                      "viscosity": viscosity, "fatigue_load_limit": fatigue_load_limit})
    return {k: produced[k] for k in ("a1", "nu1", "kappa", "a_ISO", "L_nm", "L_nmh")}


@step("life", provides=("life_cone_in", "life_ball_in", "life_ball_out", "life_cone_out", "life_system",
                        "cycles_cone_in", "cycles_ball_in", "cycles_ball_out", "cycles_cone_out"),
      model=lambda life_model: life_model.name)
def ball_cone_life(life_model, a_transverse, tau0_in, z0_in, tau0_out, z0_out, rolling_radius_in, rolling_radius_out,
                   input_speed, output_speed, ball_speed, cone_contact_radius, ball_count):
    """Lundberg–Palmgren life per track of the CVT in stress cycles and seconds: the input and output cone
    (track R_cont, n stress cycles per revolution) and one ball's input and output track (one cycle per
    ball revolution); the system life of the two cones and the n balls' tracks (Eq. 5.20). Speeds [rad/s]."""
    a = a_transverse
    n_in, n_out, n_ball = input_speed / (2 * math.pi), output_speed / (2 * math.pi), ball_speed / (2 * math.pi)
    stresses = {"in": (tau0_in, z0_in), "out": (tau0_out, z0_out)}
    tracks = {  # (side, track radius, stress cycles per revolution, speed [rev/s])
        "life_cone_in": ("in", cone_contact_radius, ball_count, n_in),
        "life_ball_in": ("in", rolling_radius_in, 1, n_ball),
        "life_ball_out": ("out", rolling_radius_out, 1, n_ball),
        "life_cone_out": ("out", cone_contact_radius, ball_count, n_out),
    }
    out = {}
    for key, (side, radius, per_revolution, speed) in tracks.items():
        cycles = life_model.life(*stresses[side], a, radius)
        out[key.replace("life_", "cycles_")] = float(cycles)
        out[key] = float(life_time(cycles, per_revolution, speed))
    lives = [out["life_cone_in"], out["life_cone_out"]] + [out["life_ball_in"], out["life_ball_out"]] * ball_count
    out["life_system"] = float(system_life(np.array(lives), life_model.e))
    return out
