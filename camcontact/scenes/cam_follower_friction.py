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

The fluid's rheology is the model slot ``traction``: default ``"eyring"`` with ``non_newtonian``, else
``"newtonian"``, both bounded by the lubricant's limiting shear stress (its ``eyring_stress`` and limiting
shear stress when it gives them; :func:`camcontact.steps.ehl_friction.fluid_traction_model`); with ``thermal``
its contact temperature rise lowers the viscosity (the materials' thermal data are needed). ``mixed`` adds Greenwood–Tripp asperity load sharing with the pair's asperity
parameters (``CamFollower.asperity_density`` / ``asperity_radius``) and the lubricant's ``boundary_friction``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from ..components.cam_follower import CamFollower
from ..step_graph import Step
from ..steps.ehl_friction import (EHL_EFFECTS, MIXED_FRICTION_READS, ehl_friction_inputs, ehl_sliding_friction,
                                  fluid_traction_table, mixed_film_cycle)
from ..steps.film import composite_roughness_step
from ..steps.friction import SlotModel, cam_friction
from ..steps.roller import cam_friction_torque, coulomb_traction_table, roller_spin, sliding_tangential_force

__all__ = ["effect_outputs", "friction_inputs", "friction_steps"]


def effect_outputs(effects: frozenset, solved_film: bool = False) -> tuple[str, ...]:
    """The per-angle outputs the asked-for effects add to the default report (the scene names the missing
    input of any of them, and of the friction they change, up front instead of leaving them out);
    ``solved_film``: the film model solves the thermal film itself (its film temperature rise instead of
    the inlet formula's factor)."""
    mixed = ("asperity_load_fraction", "Lambda_mixed", "lubrication_regime", "mixed_valid") if "mixed" in effects else ()
    fluid = (("friction_force", "friction_coefficient", "friction_power", "fluid_traction_coefficient",
              "traction_regime", "traction_valid") + (("traction_temperature_rise",) if "thermal" in effects else ())
             if effects & EHL_EFFECTS else ())
    thermal = (() if "thermal" not in effects else ("film_temperature_rise", "film_thermal") if solved_film
               else ("thermal_factor", "thermal_valid"))
    return mixed + fluid + thermal


def friction_inputs(scene: CamFollower, effects: frozenset) -> dict[str, Any]:
    """The graph inputs of the EHL friction (:func:`camcontact.steps.ehl_friction.ehl_friction_inputs`)."""
    bodies = (scene.cam, scene.follower)
    return ehl_friction_inputs(scene.lubricant, tuple(b.material for b in bodies), tuple(b.si.roughness for b in bodies),
                               effects, asperity_density=scene.si.asperity_density, asperity_radius=scene.si.asperity_radius)


def friction_steps(scene: CamFollower, friction: SlotModel, chosen: Mapping[str, Any], effects: frozenset,
                   thermal_traction: bool) -> list[Step]:
    """The friction steps of the module table, with the camshaft torque of the tangential force."""
    ehl = bool(effects & EHL_EFFECTS) and "friction" not in chosen
    reads = MIXED_FRICTION_READS if "mixed" in effects else ()
    extra = ("effusivity",) if thermal_traction else ()
    mixed = [Step.of(composite_roughness_step), Step.of(mixed_film_cycle)] if "mixed" in effects else []
    if scene.follower.kind == "roller" and "friction" not in chosen:
        table = Step.of(fluid_traction_table, extra=reads + extra) if ehl else Step.of(coulomb_traction_table)
        return [*mixed, table, Step.of(roller_spin), Step.of(cam_friction_torque)]
    if ehl:
        sliding = Step.of(ehl_sliding_friction, extra=reads + extra, optional=("film_solutions",))
    else:
        sliding = Step.of(cam_friction, extra=friction.requires, optional=friction.optional)
    return [*mixed, sliding, Step.of(sliding_tangential_force), Step.of(cam_friction_torque)]
