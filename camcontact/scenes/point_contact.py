"""The lubricated point-contact scene: elliptical Hertz, subsurface stress, lubricant, film, Lambda.

A :class:`~camcontact.components.PointContact` becomes the steps ``kinematics`` (u_m, u_s), ``hertz``
(elliptical Hertz by exact elliptic integrals or a published fit, slot ``hertz``; p_h against the contact
stress limit), ``subsurface`` (the largest Tresca shear and von Mises stress below the centre and their
depths, :mod:`camcontact.contact.subsurface_point`), ``roughness``, ``lubricant``, ``film`` (a point film model,
slot ``film``: ``"hamrock_dowson"`` (default; h_c and h_min), ``"nijenbanning"`` (h_c) or ``"multigrid"``, the
numerical point solution; a list makes one variant per model) and ``lambda`` (Lambda of each film and the
regime of the smaller). Effects: ``elasticity`` and ``piezoviscosity`` (alpha = 0 without it).

Entrainment is along the bodies' ``radius`` plane (x); Rx, Ry are the gap's reduced radii.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from ..components.point_contact import PointContact
from ..contact.hertz_elliptical import METHODS as HERTZ_METHODS
from ..errors import InputError
from ..step_graph import SceneGraph, Step, checked_request, given, scene_builder
from ..steps.contact import point_geometry, point_hertz
from ..steps.film import (composite_roughness_step, film_parameter, films_of, isothermal_films,
                          lubrication_regime_step, point_film, resolve_film_model)
from ..steps.kinematics import surface_kinematics
from ..steps.lubricant import lubricant_inputs, lubricant_step
from ..steps.stress import point_subsurface_stresses
from .point_contact_plots import plot_point_contact

__all__ = ["DEFAULT_OUTPUTS", "build_point_contact", "point_contact_inputs"]

SUPPORTED_EFFECTS = frozenset({"elasticity", "piezoviscosity"})
DEFAULT_FILM = "hamrock_dowson"
DEFAULT_OUTPUTS = (
    "E_reduced", "Rx", "Ry", "u_m", "a_rolling", "a_transverse", "ellipticity", "p_h", "p_mean", "approach",
    "stress_limit_exceeded", "tresca_max", "z_tresca_max", "von_mises_max", "z_von_mises_max", "eta0", "alpha",
    "viscosity_extrapolated", "h_c", "h_min", "Lambda_c", "Lambda_min", "regime", "film_validity", "film_valid",
)
HINTS = {
    "lubricant": "set PointContact.lubricant",
    "temperature": "set PointContact.temperature (the lubricant's viscosity depends on it)",
    "sigma1": "set the roughness of body1 (Body.roughness, RMS)",
    "sigma2": "set the roughness of body2 (Body.roughness, RMS)",
}


def point_contact_inputs(contact: PointContact, effects: frozenset) -> dict[str, Any]:
    """The graph inputs of a point contact (SI): reduced radii and modulus, load, speeds, roughness,
    lubricant, switches."""
    b1, b2 = contact.body1, contact.body2
    inputs = {
        "E1": b1.material.si.E, "nu1": b1.material.nu, "E2": b2.material.si.E, "nu2": b2.material.nu,
        "R1x": b1.signed_radius, "R2x": b2.signed_radius, "R1y": b1.signed_transverse_radius,
        "R2y": b2.signed_transverse_radius, "F": contact.si.load, "u1": b1.si.speed, "u2": b2.si.speed,
        "contact_stress_limit": contact.si.contact_stress_limit, "piezoviscosity": "piezoviscosity" in effects,
        "compressibility": False, **lubricant_inputs(contact.lubricant, contact.si.temperature),
    }
    return inputs | given(sigma1=b1.si.roughness, sigma2=b2.si.roughness)


@scene_builder(PointContact)
def build_point_contact(contact: PointContact, *, models: Mapping[str, Any], effects: frozenset | None) -> SceneGraph:
    """Scene graph of a :class:`~camcontact.components.PointContact` (one variant)."""
    effects = checked_request("point_contact", models, effects, slots=("film", "hertz"), supported=SUPPORTED_EFFECTS,
                              default=SUPPORTED_EFFECTS)
    if "elasticity" not in effects:
        raise InputError("point_contact scene: the point film models are elastohydrodynamic; leaving out "
                         "'elasticity' is not supported (allowed effects: elasticity with or without piezoviscosity)")
    method = models.get("hertz", "exact")
    if method not in HERTZ_METHODS:
        raise InputError(f"point_contact scene: hertz = {method!r}; allowed: {', '.join(HERTZ_METHODS)}")
    film_model = resolve_film_model(models.get("film", DEFAULT_FILM), geometry="point", where="point_contact scene: ")
    films = films_of(film_model)
    basis = "h_min" if "h_min" in films else "h_c"
    steps = [
        Step.of(point_geometry), Step.of(surface_kinematics), Step.of(point_hertz), Step.of(point_subsurface_stresses),
        Step.of(composite_roughness_step), lubricant_step(contact.lubricant, contact.si.temperature),
        Step.of(point_film, provides=(*(f"{q}_isothermal" for q in films), "film_validity", "film_valid",
                                      "film_solution")),
        Step.of(isothermal_films, extra=tuple(f"{q}_isothermal" for q in films), provides=films),
        *(Step.of(film_parameter, name="lambda" if q == basis else f"lambda_{q[2:]}",
                  rename={"h": q, "Lambda": f"Lambda_{q[2:]}"}) for q in films),
        Step.of(lubrication_regime_step, rename={"Lambda": f"Lambda_{basis[2:]}"}),
    ]
    return SceneGraph(kind="point_contact",
                      inputs={**point_contact_inputs(contact, effects), "film_model": film_model, "hertz_method": method},
                      steps=tuple(steps), default_outputs=DEFAULT_OUTPUTS, input_hints=HINTS,
                      plotter=plot_point_contact, effects=effects)
