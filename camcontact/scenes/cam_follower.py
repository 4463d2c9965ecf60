"""The cam–follower scene: motion law → kinematics → dynamics → Hertz → film → friction and wear, per cam angle.

Per-angle outputs are arrays over the scene's cam angles (``Result.to_frame()`` gives one row per
angle, like Tsuha 2015 Tables 6.3/6.4); cycle summaries are scalars (``Result.summary_frame()``).
Only the steps the requested outputs need run: asking for kinematics runs no dynamics, no Hertz,
no lubricant and no film.

Model slots (``Analysis(models=...)``): ``film`` (any line film model, formula or
``"multigrid"``, warm-started from the previous angle; default ``"pan_hamrock"``), ``friction``
(``friction_models``; default: a roller's spin dynamics with its traction limited to mu N — the tangential
force accelerates the roller and overcomes its pin friction, :mod:`camcontact.steps.roller` — and
``"coulomb"`` for a flat-faced follower; a model chosen here applies to either), ``wear`` (``wear_models``; default ``"archard"``).

Effects: ``elasticity``, ``piezoviscosity``, ``compressibility`` (on by default), ``dynamics``
(off by default: the contact force is the prescribed-motion 1-DOF force of Tsuha 2015 Eq. 3.46;
on: the valve train's lumped 2-DOF/5-DOF model is integrated over ``CamFollower.cycles`` turns with
unilateral contact and the last turn is reported) and ``squeeze`` (off by default: the film is
quasi-steady, angle by angle; on: the numerical film — film model ``"multigrid"`` — is solved as one
transient over the turn with the squeeze term, implicit BDF2 steps from angle to angle through any
entrainment reversal, :func:`camcontact.ehl.line_transient.transient_cycle`; it starts from the
steady film at the steadiest angle, e.g. on the base circle) and ``thermal`` (off by default: the films are
reduced by the inlet shear-heating factor phi_T of the model slot ``thermal``, default ``"wilson_sheu"``
with its slide-to-roll term, :func:`camcontact.models.film_thermal.thermal_reduction`; needs the
lubricant's thermal conductivity and its temperature–viscosity coefficient). With both ``squeeze`` and
``thermal`` (or ``non_newtonian``) the ``multigrid`` film is the thermal (Eyring) transient itself,
:func:`camcontact.ehl.line_thermal.thermal_transient_cycle`: the energy equation across the film and the
surfaces' flash temperatures after every step, with ``film_temperature_rise`` [K] per angle (and
``film_thermal``, where the energy equation ran) in place of the formula's ``thermal_factor`` (needs the
lubricant's density, specific heat, conductivity and temperature–viscosity coefficient and both materials'
thermal data). A starved contact (``CamFollower.oil_layer``, the layer the surfaces bring) is solved by the
transient march only (isothermal, or thermal / Eyring): ``squeeze`` with ``Multigrid(cavitation="mass_conserving")``
(:func:`check_starved` refuses anything else); its films come with ``x_min``, where the film is thinnest.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from ..components.cam_follower import CamFollower
from ..contact.geometry import reduced_modulus
from ..errors import InputError
from ..step_graph import SceneGraph, Step, checked_request, given, scene_builder
from ..units import format_quantity
from ..steps.contact import cycle_hertz
from ..steps.film import (film_parameter, films_of, resolve_film_model, solves_rheology, thermal_films,
                          with_traction_rheology)
from ..steps.film_cycle import (cycle_ehl_groups, cycle_inlet_thermal, numerical_film_details, quasi_steady_films,
                                thermal_transient_films, transient_films)
from ..steps.forces import (FORCES_1DOF, jump_report, lumped_dynamics, minimum_spring_stiffness, normal_force,
                            prescribed_motion_forces, valve_train_natural_frequency)
from ..steps.friction import SlotModel, cam_wear
from ..steps.kinematics import FOLLOWER_KINEMATICS, follower_motion, motion_continuity
from ..steps.lubricant import lubricant_inputs, lubricant_step
from ..steps.roller import ROLLER_OUTPUTS
from ..dynamics.roller_follower import full_turn
from ..steps.ehl_friction import fluid_traction_model
from .cam_follower_friction import effect_outputs, friction_inputs, friction_steps
from ..steps.summaries import (friction_power_mean, friction_torque_mean, h_min_cycle, jump_margin,
                               peak_contact_force, peak_pressure, wear_rate_mean)
from .cam_follower_plots import plot_cam_follower

__all__ = ["DEFAULT_EFFECTS", "SUPPORTED_EFFECTS", "build_cam_follower", "cam_follower_inputs"]

SUPPORTED_EFFECTS = frozenset({"elasticity", "piezoviscosity", "compressibility", "dynamics", "squeeze", "thermal",
                               "mixed", "non_newtonian"})
DEFAULT_EFFECTS = frozenset({"elasticity", "piezoviscosity", "compressibility"})
DEFAULT_MODELS = {"film": "pan_hamrock", "friction": "coulomb", "wear": "archard", "thermal": "wilson_sheu",
                  "traction": None}
PER_ANGLE = frozenset((
    "cam_angle", *FOLLOWER_KINEMATICS, *FORCES_1DOF, "normal_force", "w", "b", "p_h", "approach", "U", "G", "W", "M",
    "L", "h_c", "h_min", "x_min", "h_c_isothermal", "h_min_isothermal", "thermal_loading_m", "thermal_factor", "thermal_valid", "film_temperature_rise", "film_thermal", "film_regime", "film_valid", "H0", "H_min", "H_c", "spike_pressure", "pressure_spike", "Lambda_min", "friction_force",
    "friction_coefficient", "friction_power", "wear_rate", "contact_open", "tangential_force", "friction_torque",
    "cam_torque_with_friction", "friction_arm", *(q for q in ROLLER_OUTPUTS if q != "roller_cycle"),
    "asperity_load_fraction", "h_c_mixed", "Lambda_mixed", "lubrication_regime", "asperity_capacity", "mixed_valid",
    "fluid_traction_coefficient", "traction_regime", "traction_temperature_rise", "traction_valid",
))
DEFAULT_OUTPUTS = (
    "cam_angle", "lift", "follower_velocity", "follower_acceleration", "follower_jerk", "pressure_angle", "cam_radius",
    "R", "u_m", "profile_x", "profile_y", "contact_force", "inertia_force", "spring_force", "damping_force",
    "preload_force", "cam_torque", "w", "b", "p_h", "M", "L", "h_c", "h_min", "Lambda_min", "film_regime", "film_valid",
    "friction_force",
    "friction_coefficient", "friction_power", "friction_torque", "cam_torque_with_friction", "wear_rate",
    "motion_continuity", "natural_frequency", "k_min", "jump_margin", "jump", "contact_force_max", "p_h_max", "h_min_cycle", "viscosity_extrapolated",
    "friction_power_mean", "friction_energy_per_cycle", "friction_torque_mean", "wear_rate_mean",
)
HINTS = {
    "lubricant": "set CamFollower.lubricant",
    "temperature": "set CamFollower.temperature (the lubricant's viscosity depends on it)",
    "hardness": "give the cam material a hardness (Material.hardness), which the wear model needs",
    "sigma1": "give the cam a roughness (Cam.roughness)",
    "sigma2": "give the follower a roughness (Follower.roughness)",
    "coulomb_coefficient": "give CamFollower.friction_coefficient (for the default 'coulomb' model) or pass a "
                           "friction model, e.g. models={'friction': registry.get('friction_models', "
                           "'ferrarese_uehara', k_L=2)}",
    "traction_limit_coefficient": "give CamFollower.friction_coefficient (the roller's traction limit mu N), or "
                                  "switch the 'non_newtonian' effect on for fluid traction",
    "roller_inertia": "the roller's spin dynamics integrate over a cam turn: sample the turn uniformly with at "
                      "least 36 angles (CamFollower.angle_step <= 10 deg, not angles), or choose a friction model, e.g. "
                      "models={'friction': 'coulomb'}",
    "effusivity": "give the cam and follower materials density, specific_heat and thermal_conductivity (the "
                  "thermal traction's flash temperature needs them)",
    "sigma": "give the cam and the follower a roughness (the 'mixed' effect needs the composite roughness)",
    "archard_coefficient": "give CamFollower.wear_coefficient (for the default 'archard' model) or pass a wear model",
}


def cam_follower_inputs(scene: CamFollower, effects: frozenset) -> dict[str, Any]:
    """The graph inputs of a cam–follower scene (SI): motion, geometry, valve train, lubricant, switches."""
    cam, follower, train = scene.cam, scene.follower, scene.valve_train
    inputs = {
        "cam_angle": scene.cam_angles, "program": cam.program, "geometry": scene.geometry,
        "speed": scene.si.speed, "angular_acceleration": scene.si.angular_acceleration,
        "max_speed": scene.si.max_speed,
        "E_reduced": reduced_modulus(cam.material.si.E, cam.material.nu, follower.material.si.E, follower.material.nu),
        "width": cam.si.width, "convention": scene.convention, "max_pressure_angle": follower.si.max_pressure_angle,
        "mass": train.si.mass, "stiffness": train.si.stiffness, "damping": train.c, "damping_ratio": train.zeta,
        "preload": train.si.preload, "lumped_model": train.lumped, "cycles": scene.cycles,
        # the thesis convention feeds the films the mean speed where Moes uses the sum (u_m / 2)
        "film_speed_factor": 0.5 if scene.convention == "thesis" else 1.0,
        "piezoviscosity": "piezoviscosity" in effects, "compressibility": "compressibility" in effects,
        **lubricant_inputs(scene.lubricant, scene.si.temperature),
    }
    if follower.kind == "roller":
        inputs |= {"roller_radius": follower.si.roller_radius, "pin_radius": follower.pin_radius_si,
                   "pin_friction_coefficient": follower.pin_friction_coefficient}
        if full_turn(scene.cam_angles):  # the spin dynamics integrate over the turn (else named up front)
            inputs["roller_inertia"] = follower.roller_inertia_si(cam.si.width)
    return inputs | given(hardness=cam.material.si.hardness, sigma1=cam.si.roughness, sigma2=follower.si.roughness,
                          traction_limit_coefficient=scene.friction_coefficient, oil_layer=scene.si.oil_layer)


def cycle_film_steps(film_model: Any, effects: frozenset) -> list[Step]:
    """The film over the turn (quasi-steady, or transient with ``squeeze``); with ``thermal`` the film
    step gives the isothermal films and the inlet shear-heating factor reduces them, unless the film model
    solves the thermal (or non-Newtonian) film itself: the ``multigrid`` model in a transient march
    (``squeeze``), :func:`camcontact.steps.film_cycle.thermal_transient_films`."""
    films = films_of(film_model)
    if "squeeze" in effects and solves_rheology(film_model):
        reads = ({"extra": ("effusivity",), "optional": ("oil_layer",)} if film_model.thermal
                 else {"optional": ("effusivity", "oil_layer")})
        return [Step.of(thermal_transient_films, **reads)]
    film = transient_films if "squeeze" in effects else quasi_steady_films
    # the transient march: a starved inflow (CamFollower.oil_layer) and where its film is thinnest
    starved = {"optional": ("oil_layer",)} if "squeeze" in effects else {}
    provides = (*films, "film_regime", "film_valid", "film_solutions") + (("x_min",) if "squeeze" in effects else ())
    if "thermal" not in effects:
        return [Step.of(film, provides=provides, **starved)]
    isothermal = {name: f"{name}_isothermal" for name in films}
    return [Step.of(film, provides=provides, rename=isothermal, **starved),
            Step.of(cycle_inlet_thermal), Step.of(thermal_films, extra=tuple(isothermal.values()), provides=films)]


def check_starved(scene: CamFollower, model: Any, effects: frozenset) -> None:
    """InputError unless a starved cam contact (``oil_layer``) is solved by the mass-conserving transient march
    (``model``: the scene's resolved film model)."""
    conserving = getattr(model, "name", "") == "multigrid" and getattr(model, "cavitation", "") == "mass_conserving"
    if not ("squeeze" in effects and conserving):
        raise InputError(
            f"CamFollower {scene.name!r}: oil_layer = {format_quantity(scene.oil_layer)} (a starved contact) is solved "
            "by the transient march only: effects including 'squeeze' and "
            "models={'film': Multigrid(cavitation='mass_conserving')}; got "
            f"effects {sorted(effects)} and the film model {getattr(model, 'name', model)!r}"
            + (f" with cavitation {model.cavitation!r}" if getattr(model, "name", "") == "multigrid" else ""))


@scene_builder(CamFollower)
def build_cam_follower(scene: CamFollower, *, models: Mapping[str, Any], effects: frozenset | None) -> SceneGraph:
    """Scene graph of a :class:`~camcontact.components.CamFollower` (one variant)."""
    effects = checked_request("cam_follower", models, effects, slots=sorted(DEFAULT_MODELS),
                              supported=SUPPORTED_EFFECTS, default=DEFAULT_EFFECTS)
    chosen, models = models, {**DEFAULT_MODELS, **models}
    traction = fluid_traction_model(scene.lubricant, effects, models["traction"])
    # the transient march solves the thermal / non-Newtonian film itself with the multigrid model (a quasi-steady
    # turn corrects its films by the inlet shear-heating formula)
    film_model = (with_traction_rheology(
        resolve_film_model(models["film"], effects=effects,
                           enable=("thermal", "non_newtonian") if "squeeze" in effects else ()), traction)
        if scene.lubricant is not None else None)
    if scene.oil_layer is not None and film_model is not None:
        check_starved(scene, film_model, effects)
    friction = SlotModel("friction_models", models["friction"], "friction", scene.friction_coefficient,
                         "coulomb_coefficient")
    wear = SlotModel("wear_models", models["wear"], "wear", scene.wear_coefficient, "archard_coefficient")
    steps = [
        Step.of(follower_motion), Step.of(motion_continuity), Step.of(valve_train_natural_frequency),
        Step.of(minimum_spring_stiffness), Step.of(jump_margin),
        Step.of(lumped_dynamics if "dynamics" in effects else prescribed_motion_forces),
        Step.of(normal_force), Step.of(jump_report), Step.of(cycle_hertz),
        lubricant_step(scene.lubricant, scene.si.temperature),
        Step.of(cycle_ehl_groups),
        *cycle_film_steps(film_model, effects), Step.of(numerical_film_details), Step.of(film_parameter, rename={"h": "h_min", "Lambda": "Lambda_min"}),
        *friction_steps(scene, friction, chosen, effects, traction.thermal), Step.of(cam_wear, extra=wear.requires, optional=wear.optional),
        Step.of(peak_contact_force), Step.of(peak_pressure), Step.of(h_min_cycle), Step.of(friction_power_mean),
        Step.of(friction_torque_mean), Step.of(wear_rate_mean),
    ]
    inputs = {**cam_follower_inputs(scene, effects), "film_model": film_model, "friction_model": friction,
              "wear_model": wear, "thermal_model": models["thermal"], "traction_model": traction,
              **friction_inputs(scene, effects)}
    asked = effect_outputs(effects, solves_rheology(film_model) and "squeeze" in effects)
    return SceneGraph(kind="cam_follower", inputs=inputs, steps=tuple(steps),
                      default_outputs=DEFAULT_OUTPUTS + tuple(q for q in asked if q not in DEFAULT_OUTPUTS),
                      input_hints=HINTS, plotter=plot_cam_follower, effects=effects, index="cam_angle",
                      per_index=PER_ANGLE, effect_outputs=frozenset(asked))
