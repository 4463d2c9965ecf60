"""The cam scene's friction: which steps give the friction of each follower under each effect.

================================ =============================================================================
follower / choice                 friction steps
================================ =============================================================================
roller, no friction model chosen  the roller's spin dynamics (:mod:`camcontact.steps.roller`) on the contact's
                                  traction curve: a Coulomb limit mu N; with ``non_newtonian`` and/or ``mixed``
                                  the fluid traction of the film (+ the asperities' boundary friction)
flat face, no model chosen        Coulomb mu N; with ``non_newtonian`` and/or ``mixed`` the EHL friction
                                  mu_b W_asperity + mu_fluid(u_s) W_fluid (:mod:`camcontact.steps.ehl_friction`)
any, ``models={"friction": m}``   the friction model m per angle (the roller then assumed rolling)
================================ =============================================================================

The fluid's rheology is the model slot ``traction``: default ``"eyring"`` with ``non_newtonian`` (the
lubricant's ``eyring_stress`` and limiting shear stress when it gives them), else ``"newtonian"`` without a
limiting shear stress; with ``thermal`` its contact temperature rise lowers the viscosity (the materials'
thermal data are needed). ``mixed`` adds Greenwood–Tripp asperity load sharing with the pair's asperity
parameters (``CamFollower.asperity_density`` / ``asperity_radius``) and the lubricant's ``boundary_friction``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from ..components.cam_follower import CamFollower
from ..errors import InputError
from ..step_graph import Step
from ..steps.ehl_friction import ehl_sliding_friction, fluid_traction_table, mixed_film_cycle
from ..steps.film import composite_roughness_step
from ..steps.friction import SlotModel, cam_friction
from ..steps.roller import cam_friction_torque, coulomb_traction_table, roller_spin, sliding_tangential_force

__all__ = ["ASPERITY_DEFAULTS", "EHL_EFFECTS", "friction_inputs", "friction_steps"]

#: effects that replace Coulomb friction by the EHL friction of the film
EHL_EFFECTS = frozenset({"mixed", "non_newtonian"})
#: (eta beta sigma, sigma / beta) when the scene gives no asperity parameters (see CamFollower)
ASPERITY_DEFAULTS = (0.05, 0.05)


def friction_inputs(scene: CamFollower, effects: frozenset) -> dict[str, Any]:
    """The graph inputs of the EHL friction: asperity parameters, boundary friction, surface effusivities."""
    inputs: dict[str, Any] = {}
    if scene.lubricant is not None:
        inputs["boundary_friction"] = scene.lubricant.boundary_friction
    cam, follower = scene.cam.material, scene.follower.material
    try:
        inputs["effusivity"] = (cam.thermal_effusivity(), follower.thermal_effusivity())
    except InputError:
        pass  # only a thermal traction model needs it: reported up front as missing
    if "mixed" in effects and scene.cam.roughness is not None and scene.follower.roughness is not None:
        sigma = math.hypot(scene.cam.si.roughness, scene.follower.si.roughness)
        product, ratio = ASPERITY_DEFAULTS
        radius = scene.si.asperity_radius if scene.asperity_radius is not None else sigma / ratio
        density = (scene.si.asperity_density if scene.asperity_density is not None
                   else product / (radius * sigma) if sigma > 0 else None)
        inputs |= {"asperity_radius": radius} | ({"asperity_density": density} if density else {})
    return inputs


def friction_steps(scene: CamFollower, friction: SlotModel, chosen: Mapping[str, Any], effects: frozenset,
                   thermal_traction: bool) -> list[Step]:
    """The friction steps of the module table, with the camshaft torque of the tangential force."""
    ehl = bool(effects & EHL_EFFECTS) and "friction" not in chosen
    reads = ("asperity_load_fraction", "h_c_mixed", "boundary_friction") if "mixed" in effects else ()
    extra = ("effusivity",) if thermal_traction else ()
    mixed = [Step.of(composite_roughness_step), Step.of(mixed_film_cycle)] if "mixed" in effects else []
    if scene.follower.kind == "roller" and "friction" not in chosen:
        table = Step.of(fluid_traction_table, extra=reads + extra) if ehl else Step.of(coulomb_traction_table)
        return [*mixed, table, Step.of(roller_spin), Step.of(cam_friction_torque)]
    if ehl:
        sliding = Step.of(ehl_sliding_friction, extra=reads + extra)
    else:
        sliding = Step.of(cam_friction, extra=friction.requires, optional=friction.optional)
    return [*mixed, sliding, Step.of(sliding_tangential_force), Step.of(cam_friction_torque)]
