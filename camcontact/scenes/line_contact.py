"""The lubricated line-contact scene: Hertz, subsurface stress, lubricant, film, Lambda.

Model slots (``Analysis(models=...)``):

``film``
    a line film model of the ``film_models`` family (default ``"pan_hamrock"``, which gives
    both h_c and h_min); a list makes one variant per model.
``approach``
    ``"hamrock"`` (default) or ``"palmgren"`` (needs ``load`` and ``length``).

Effects: ``elasticity``, ``piezoviscosity`` and ``compressibility`` (on by default; the last
only changes the density law handed to the numerical solver) and ``thermal`` (inlet
shear-heating reduction of the film, needs the lubricant's thermal conductivity and a
temperature law).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from ..components.line_contact import LineContact
from ..errors import InputError
from ..step_graph import SceneGraph, Step, checked_request, given, scene_builder
from ..steps.contact import APPROACHES, line_geometry, line_hertz
from ..steps.film import (composite_roughness_step, ehl_groups, film_parameter, films_of, inlet_thermal_correction,
                          isothermal_films, line_film, lubrication_regime_step, model_reads, resolve_film_model,
                          thermal_films)
from ..steps.kinematics import surface_kinematics
from ..steps.lubricant import lubricant_inputs, lubricant_step
from ..steps.stress import line_subsurface_stresses
from .line_contact_plots import plot_line_contact

__all__ = ["DEFAULT_EFFECTS", "SUPPORTED_EFFECTS", "build_line_contact", "film_steps", "line_contact_inputs"]

SUPPORTED_EFFECTS = frozenset({"elasticity", "piezoviscosity", "compressibility", "thermal"})
#: compressibility is on by default: numerical EHL conventionally includes it (with an
#: incompressible lubricant the pressure spike grows without bound under grid refinement at
#: high L); the film formulas are not affected by it
DEFAULT_EFFECTS = frozenset({"elasticity", "piezoviscosity", "compressibility"})
DEFAULT_FILM = "pan_hamrock"
DEFAULT_OUTPUTS = (
    "E_reduced", "R", "w", "u_m", "b", "p_h", "approach", "tau_max", "z_tau_max", "tau_xz_range",
    "eta0", "alpha", "M", "L", "h_c", "h_min", "Lambda_c", "Lambda_min", "regime", "film_validity",
)
HINTS = {
    "lubricant": "set LineContact.lubricant",
    "temperature": "set LineContact.temperature (the lubricant's viscosity depends on it)",
    "sigma1": "set the roughness of body1 (Body.roughness, RMS)",
    "sigma2": "set the roughness of body2 (Body.roughness, RMS)",
    "F": "give LineContact.load with length (the palmgren approach needs the total force)",
    "length": "give LineContact.length",
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
    return inputs | given(F=contact.si.load, length=contact.si.length, sigma1=b1.si.roughness, sigma2=b2.si.roughness)


def film_steps(film_model: Any, thermal: bool) -> list[Step]:
    """EHL groups, the film by ``film_model`` (with the further state names it reads), its thermal
    correction and Lambda per film."""
    films = films_of(film_model)
    isothermal = tuple(f"{q}_isothermal" for q in films)
    basis = "h_min" if "h_min" in films else "h_c"
    reads = model_reads(film_model)
    steps = [
        Step.of(ehl_groups),
        Step.of(line_film, provides=(*isothermal, "film_validity"), extra=reads.required, optional=reads.optional),
        Step.of(thermal_films if thermal else isothermal_films, extra=isothermal, provides=films),
        *(Step.of(film_parameter, name="lambda" if q == basis else f"lambda_{q[2:]}",
                  rename={"h": q, "Lambda": f"Lambda_{q[2:]}"}) for q in films),
        Step.of(lubrication_regime_step, rename={"Lambda": f"Lambda_{basis[2:]}"}),
    ]
    return steps + ([Step.of(inlet_thermal_correction)] if thermal else [])


@scene_builder(LineContact)
def build_line_contact(contact: LineContact, *, models: Mapping[str, Any], effects: frozenset | None) -> SceneGraph:
    """Scene graph of a :class:`~camcontact.components.LineContact` (one variant)."""
    effects = checked_request("line_contact", models, effects, slots=("film", "approach"),
                              supported=SUPPORTED_EFFECTS, default=DEFAULT_EFFECTS)
    approach = models.get("approach", "hamrock")
    if approach not in APPROACHES:
        raise InputError(f"line_contact scene: approach model {approach!r} unknown; choose 'hamrock' or 'palmgren'")
    film_model = resolve_film_model(models.get("film", DEFAULT_FILM), effects=effects)
    steps = [Step.of(line_geometry), Step.of(surface_kinematics), Step.of(line_hertz), Step.of(APPROACHES[approach]),
             Step.of(line_subsurface_stresses), Step.of(composite_roughness_step),
             lubricant_step(contact.lubricant, contact.si.temperature), *film_steps(film_model, "thermal" in effects)]
    return SceneGraph(
        kind="line_contact", inputs={**line_contact_inputs(contact, effects), "film_model": film_model},
        steps=tuple(steps), default_outputs=DEFAULT_OUTPUTS, input_hints=HINTS, plotter=plot_line_contact,
        effects=effects,
    )
