"""The lubricated line-contact scene: Hertz, subsurface stress, lubricant, film, Lambda.

Model slots (``Analysis(models=...)``):

``film``
    a line film model of the ``film_models`` family (default ``"pan_hamrock"``, which gives
    both h_c and h_min); a list makes one variant per model.
``approach``
    ``"hamrock"`` (default) or ``"palmgren"`` (needs ``load`` and ``length``).
``traction``
    the fluid's rheology for the friction (a ``traction_models`` name or model; default ``"eyring"``
    with ``non_newtonian``, else ``"newtonian"``; :func:`camcontact.steps.ehl_friction.fluid_traction_model`).

Effects: ``elasticity``, ``piezoviscosity`` and ``compressibility`` (on by default; the last
only changes the density law handed to the numerical solver), ``thermal`` (inlet
shear-heating reduction of the film, needs the lubricant's thermal conductivity and a
temperature law; with friction also the contact temperature rise of the traction, which needs the
materials' thermal data), ``non_newtonian`` (the friction of the contact at its sliding speed from the
fluid's rheology, :func:`camcontact.steps.ehl_friction.contact_ehl_friction`) and ``mixed`` (Greenwood–Tripp
asperity load sharing: the asperities' share, the film at the fluid's share, the lubrication regime and the
boundary friction of the asperities in the friction). Friction is per unit length of the contact. A Stribeck
curve (friction against speed) is a sweep of the scene: :func:`camcontact.scenes.stribeck.stribeck_sweep`.

Starvation: ``LineContact.oil_layer`` (the lubricant layer ahead of the contact) with the film model
``multigrid`` solves the starved contact (:func:`camcontact.ehl.line_starved.solve_starved`; with ``thermal`` /
``non_newtonian`` the starved thermal solve of :func:`camcontact.ehl.line_thermal.solve_thermal`); a formula film
model refuses the layer (the formulas are for flooded contacts).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any


from ..components.line_contact import LineContact
from ..errors import InputError
from ..step_graph import SceneGraph, Step, checked_request, given, scene_builder
from ..units import format_quantity
from ..steps.contact import APPROACHES, line_geometry, line_hertz
from ..steps.ehl_friction import (EHL_EFFECTS, MIXED_FRICTION_READS, contact_ehl_friction, ehl_friction_inputs,
                                  fluid_traction_model, mixed_contact)
from ..steps.film import (composite_roughness_step, ehl_groups, film_parameter, films_of, inlet_thermal_correction,
                          isothermal_films, line_film, lubrication_regime_step, model_name, model_reads,
                          resolve_film_model, solved_films, solved_thermal_films, thermal_films,
                          with_traction_rheology)
from ..steps.kinematics import surface_kinematics
from ..steps.lubricant import lubricant_inputs, lubricant_step
from ..steps.stress import line_subsurface_stresses
from .line_contact_plots import plot_line_contact

__all__ = ["DEFAULT_EFFECTS", "MIXED_OUTPUTS", "SUPPORTED_EFFECTS", "build_line_contact", "film_steps", "friction_steps",
           "line_contact_inputs"]

SUPPORTED_EFFECTS = frozenset({"elasticity", "piezoviscosity", "compressibility", "thermal", "mixed", "non_newtonian"})
#: compressibility is on by default: numerical EHL conventionally includes it (with an
#: incompressible lubricant the pressure spike grows without bound under grid refinement at
#: high L); the film formulas are not affected by it
DEFAULT_EFFECTS = frozenset({"elasticity", "piezoviscosity", "compressibility"})
DEFAULT_FILM = "pan_hamrock"
DEFAULT_OUTPUTS = (
    "E_reduced", "R", "w", "u_m", "b", "p_h", "approach", "tau_max", "z_tau_max", "tau_xz_range",
    "eta0", "alpha", "viscosity_extrapolated", "M", "L", "h_c", "h_min", "Lambda_c", "Lambda_min", "regime", "film_validity", "film_valid",
)
MIXED_OUTPUTS = ("asperity_load_fraction", "h_c_mixed", "Lambda_mixed", "lubrication_regime", "mixed_valid")
FRICTION_OUTPUTS = ("traction_coefficient", "friction_per_length", "friction_power_per_length",
                    "fluid_traction_coefficient", "traction_regime", "traction_temperature_rise", "traction_valid")
HINTS = {
    "lubricant": "set LineContact.lubricant",
    "temperature": "set LineContact.temperature (the lubricant's viscosity depends on it)",
    "sigma1": "set the roughness of body1 (Body.roughness, RMS)",
    "sigma2": "set the roughness of body2 (Body.roughness, RMS)",
    "F": "give LineContact.load with length (the palmgren approach needs the total force)",
    "length": "give LineContact.length",
    "asperity_density": "give LineContact.asperity_density and asperity_radius (the defaults need a composite "
                        "roughness sigma > 0)",
    "effusivity": "give both materials thermal_conductivity, density and specific_heat (the thermal traction's "
                  "flash temperature), or leave out the thermal effect",
}


def line_contact_inputs(contact: LineContact, effects: frozenset) -> dict[str, Any]:
    """The graph inputs of a line contact (SI): bodies, load, speeds, roughness, lubricant, switches."""
    b1, b2 = contact.body1, contact.body2
    inputs = {
        "E1": b1.material.si.E, "nu1": b1.material.nu, "E2": b2.material.si.E, "nu2": b2.material.nu,
        "R1": b1.signed_radius, "R2": b2.signed_radius, "u1": b1.si.speed, "u2": b2.si.speed,
        "w": contact.w, "friction_coefficient": contact.friction_coefficient,
        "piezoviscosity": "piezoviscosity" in effects, "compressibility": "compressibility" in effects,
        **lubricant_inputs(contact.lubricant, contact.si.temperature),
    }
    return inputs | given(F=contact.si.load, length=contact.si.length, sigma1=b1.si.roughness, sigma2=b2.si.roughness,
                          oil_layer=contact.si.oil_layer)


def film_steps(film_model: Any, thermal: bool) -> list[Step]:
    """EHL groups, the film by ``film_model`` (with the further state names it reads), its thermal
    correction and Lambda per film. A model that solves the thermal or non-Newtonian film itself (the
    ``multigrid`` model switched on by :func:`camcontact.steps.film.resolve_film_model`) gives the films of its
    solution, with its numerical thermal factor in place of the formula's."""
    films = films_of(film_model)
    isothermal = tuple(f"{q}_isothermal" for q in films)
    basis = "h_min" if "h_min" in films else "h_c"
    reads = model_reads(film_model)
    solved_thermal = getattr(film_model, "thermal", False) is True
    solved = solved_thermal or getattr(film_model, "non_newtonian", False) is True
    if solved:
        thickness = Step.of(solved_thermal_films if solved_thermal else solved_films)
    else:
        thickness = Step.of(thermal_films if thermal else isothermal_films, extra=isothermal, provides=films)
    steps = [
        Step.of(ehl_groups),
        Step.of(line_film, provides=(*isothermal, "film_validity", "film_valid", "film_solution"), extra=reads.required,
                optional=reads.optional),
        thickness,
        *(Step.of(film_parameter, name="lambda" if q == basis else f"lambda_{q[2:]}",
                  rename={"h": q, "Lambda": f"Lambda_{q[2:]}"}) for q in films),
        Step.of(lubrication_regime_step, rename={"Lambda": f"Lambda_{basis[2:]}"}),
    ]
    return steps + ([Step.of(inlet_thermal_correction)] if thermal and not solved_thermal else [])


def friction_steps(effects: frozenset, thermal_traction: bool) -> list[Step]:
    """With ``mixed`` / ``non_newtonian``: the asperity load sharing and the contact's EHL friction."""
    if not effects & EHL_EFFECTS:
        return []
    reads = MIXED_FRICTION_READS if "mixed" in effects else ()
    friction = Step.of(contact_ehl_friction, extra=reads + (("effusivity",) if thermal_traction else ()),
                       optional=("film_solution",))
    return [*([Step.of(mixed_contact)] if "mixed" in effects else []), friction]


@scene_builder(LineContact)
def build_line_contact(contact: LineContact, *, models: Mapping[str, Any], effects: frozenset | None) -> SceneGraph:
    """Scene graph of a :class:`~camcontact.components.LineContact` (one variant)."""
    effects = checked_request("line_contact", models, effects, slots=("film", "approach", "traction"),
                              supported=SUPPORTED_EFFECTS, default=DEFAULT_EFFECTS)
    approach = models.get("approach", "hamrock")
    if approach not in APPROACHES:
        raise InputError(f"line_contact scene: approach model {approach!r} unknown; choose 'hamrock' or 'palmgren'")
    traction = fluid_traction_model(contact.lubricant, effects, models.get("traction"))
    film_model = resolve_film_model(models.get("film", DEFAULT_FILM), effects=effects,
                                    enable=("thermal", "non_newtonian"))
    film_model = with_traction_rheology(film_model, traction)  # the solved film's rheology is the traction model's
    if contact.oil_layer is not None and "oil_layer" not in getattr(film_model, "optional_requires", ()):
        raise InputError(f"LineContact {contact.name!r}: oil_layer = {format_quantity(contact.oil_layer)} (a starved "
                         f"inlet) needs the film model 'multigrid', not {model_name(film_model)!r}: the film formulas "
                         "are for flooded contacts")
    steps = [Step.of(line_geometry), Step.of(surface_kinematics), Step.of(line_hertz), Step.of(APPROACHES[approach]),
             Step.of(line_subsurface_stresses), Step.of(composite_roughness_step),
             lubricant_step(contact.lubricant, contact.si.temperature), *film_steps(film_model, "thermal" in effects)]
    asked = (MIXED_OUTPUTS if "mixed" in effects else ()) + (FRICTION_OUTPUTS if effects & EHL_EFFECTS else ())
    bodies = (contact.body1, contact.body2)
    friction = ehl_friction_inputs(contact.lubricant, tuple(b.material for b in bodies),
                                   tuple(b.si.roughness for b in bodies), effects,
                                   asperity_density=contact.si.asperity_density,
                                   asperity_radius=contact.si.asperity_radius)
    return SceneGraph(
        kind="line_contact",
        inputs={**line_contact_inputs(contact, effects), "film_model": film_model, "traction_model": traction,
                **friction},
        steps=tuple(steps + friction_steps(effects, traction.thermal)), default_outputs=DEFAULT_OUTPUTS + asked,
        input_hints=HINTS, plotter=plot_line_contact, effects=effects, effect_outputs=frozenset(asked),
    )
