"""The ball-bearing scene: ball loads and contact angles, both contacts of every ball, films, Lambda, life.

A :class:`~camcontact.components.LoadedBallBearing` becomes the steps (:mod:`camcontact.steps.ball_bearing`)

``load_distribution``
    ball loads Q and contact angles under F_r, F_a and a tilting moment with the contact angle changing
    under load (rigid rings, Harris & Kotzalas 2007 ch. 7; Newton on the inner ring's displacements,
    :mod:`camcontact.contact.ball_load_distribution`), the rings' displacements, the loaded balls and
    the angle of the last loaded ball;
``kinematics``
    pure rolling at each ball's contact angle: entrainment speed per ball and the cage speed;
``hertz``
    exact elliptical Hertz at the inner and outer raceway of every loaded ball at its contact angle
    (R_x = (D/2)(1 -/+ gamma), R_y = f D/(2f - 1)); p_h against the contact stress limit (ISO 76's
    4.2 GPa);
``truncation``
    with the rings' shoulder diameters (``BallBearing.inner_shoulder_diameter`` / ``outer_shoulder_diameter``): per
    ball and race the angle left between the contact ellipse's edge (|alpha| + a_y / (f D)) and the shoulder
    (``truncation_margin_<race>``), ``truncated_<race>`` and the number of truncated balls;
``subsurface``
    the largest Tresca shear and von Mises stress and their depths below the contact of highest pressure;
``lubricant``, ``film``, ``lambda_inner``, ``lambda_outer``, ``lubrication``
    films of every loaded contact by a point film model (slot ``film``: ``"hamrock_dowson"`` by default,
    ``"nijenbanning"`` or ``"multigrid"``, the numerical point solver, per contact), the model's validity
    per contact, Lambda with the bearing's roughness and the regime per ball;
``equivalent_load``, ``static_safety``, ``rating_life``, ``modified_life``
    ISO 281 for radial ball bearings: P = X F_r + Y F_a (Table 3), L10 = (C/P)^3 and L10h, L_nm with a1,
    kappa and a_ISO of ball bearings (slot ``life``, default ``"iso281"``); ISO 76: P0 and s0 = C0/P0;
``reference_life``
    ISO/TS 16281 basic reference rating life L_10r from the ball loads of the load distribution (so it feels
    the clearance, the axial load's contact angles and a moment, which P does not).

Effects: ``elasticity`` and ``piezoviscosity`` (alpha = 0 without it). Per-ball outputs are arrays over the
index ``ball``; an unloaded ball has no contact: its contact angle, Hertz and film values are NaN with
``contact_regime`` "unloaded".

A pair of angular-contact bearings (``LoadedBallBearing.arrangement`` "back_to_back", "face_to_face" or "tandem")
distributes the pair's loads over the 2Z balls of both bearings (``ball_pair_loads``: ``ball_row`` per ball, each
bearing's axial load ``axial_load_row0`` / ``_row1`` and ``preload_relieved``); contacts, films and Lambda are per
ball as for one bearing; ISO 281 rates the pair (double-row X/Y back to back and face to face, single-row in tandem;
C = 2^0.7 C, C0 = 2 C0, P_u = 2 P_u: graph inputs ``C_pair``, ``C0_pair``, ``fatigue_load_limit_pair``) and L_10r
combines both bearings' reference lives.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from ..components.loaded_ball_bearing import LoadedBallBearing
from ..contact.geometry import reduced_modulus
from ..errors import InputError
from ..models.iso281_ball import pair_load_ratings
from ..step_graph import SceneGraph, Step, checked_request, given, scene_builder
from ..steps.ball_bearing import (ball_bearing_equivalent_load, ball_films, ball_hertz, ball_kinematics, ball_loads,
                                  ball_pair_equivalent_load, ball_pair_loads, ball_pair_reference_life,
                                  ball_pair_static_safety, ball_reference_life, ball_static_safety, ball_subsurface,
                                  ball_truncation)
from ..steps.contact import RACES
from ..steps.film import bearing_lubrication, films_of, raceway_lambda_steps, resolve_film_model
from ..steps.life import modified_rating_life, rating_life
from ..steps.lubricant import lubricant_inputs, lubricant_step
from .ball_bearing_plots import plot_ball_bearing

__all__ = ["DEFAULT_OUTPUTS", "arrangement_steps", "ball_bearing_inputs", "build_ball_bearing"]

SUPPORTED_EFFECTS = frozenset({"elasticity", "piezoviscosity"})
DEFAULT_FILM = "hamrock_dowson"
PER_BALL = frozenset({
    "ball_row", "ball_azimuth", "Q", "contact_angle", "loaded", "ball_approach", "u_m", "ball_speed", "contact_regime",
    *(f"{q}_{race}" for q in ("a_rolling", "a_transverse", "p_h", "h_c", "h_min", "Lambda", "truncation_margin",
                              "truncated") for race in RACES),
})
DEFAULT_OUTPUTS = (
    "ball_row", "ball_azimuth", "Q", "contact_angle", "loaded", "p_h_inner", "p_h_outer", "a_transverse_inner",
    "a_transverse_outer", "h_min_inner", "h_min_outer", "Lambda_inner", "Lambda_outer", "contact_regime",
    "Q_max", "loaded_balls", "load_zone", "delta_r", "delta_a", "contact_angle_max", "contact_angle_min",
    "tilting_moment", "axial_load_row0", "axial_load_row1", "preload_relieved", "truncated_inner", "truncated_outer",
    "truncated_balls", "p_h_max", "stress_limit_exceeded",
    "tau_max", "z_tau_max", "cage_speed", "h_min_bearing", "Lambda_bearing", "film_valid", "film_validity",
    "viscosity_extrapolated", "P", "X", "Y", "P0", "s0", "L10", "L10h", "kappa", "a_ISO", "L_nm", "L_nmh", "L10r",
    "L10rh",
)
HINTS = {
    "lubricant": "set LoadedBallBearing.lubricant",
    "temperature": "set LoadedBallBearing.temperature (the lubricant's viscosity depends on it)",
    "sigma": "set BallBearing.roughness (RMS of each surface)",
    "E_reduced": "set BallBearing.material (Hertz needs E and nu)",
    "fatigue_load_limit": "set BallBearing.fatigue_load_limit (P_u from the catalogue)",
    "fatigue_load_limit_pair": "set BallBearing.fatigue_load_limit (P_u of one bearing; the pair's is 2 P_u)",
    "shoulder_angles": "set BallBearing.inner_shoulder_diameter and outer_shoulder_diameter (the rings' lands)",
    "contamination": "set LoadedBallBearing.contamination (ISO 281 factor e_C, 0 < e_C <= 1)",
}


def ball_bearing_inputs(scene: LoadedBallBearing, effects: frozenset) -> dict[str, Any]:
    """The graph inputs of a loaded ball bearing (SI): loads, ring speeds [rev/s], geometry, material,
    lubricant, ratings (of one bearing; a pair's too) and switches."""
    bearing = scene.bearing
    b_si = bearing.si
    inputs: dict[str, Any] = {
        "ball": np.arange(bearing.ball_count * (2 if scene.paired else 1), dtype=float), "bearing": bearing,
        "kind": bearing.kind, "arrangement": scene.arrangement, "preload": scene.si.preload,
        "row_spacing": scene.si.row_spacing,  # None: the bearing's width (BallBearing.pair_load_distribution_si)
        "radial_load": scene.si.radial_load, "axial_load": scene.si.axial_load,
        "moment": None if scene.moment is None else scene.si.moment,
        "n_inner": scene.si.speed / (2 * np.pi), "n_outer": scene.si.outer_speed / (2 * np.pi),
        "reliability": scene.reliability, "C": bearing.dynamic_load_rating, "C0": b_si.C0, "f0": bearing.f0,
        "rating_contact_angle": bearing.rating_contact_angle, "free_contact_angle": bearing.free_contact_angle,
        "ball_count": bearing.ball_count, "ball_diameter": b_si.ball_diameter, "pitch_diameter": bearing.d_m,
        "osculations": {"inner": bearing.inner_osculation, "outer": bearing.outer_osculation},
        "contact_stress_limit": scene.si.contact_stress_limit, "rolling_element": "ball",
        "piezoviscosity": "piezoviscosity" in effects, "compressibility": False,
        **lubricant_inputs(scene.lubricant, scene.si.temperature),
    }
    material = bearing.material
    if material is not None:
        inputs["E_reduced"] = reduced_modulus(material.si.E, material.nu, material.si.E, material.nu)
        inputs["nu"] = material.nu
    inputs |= given(sigma=b_si.roughness, fatigue_load_limit=b_si.fatigue_load_limit, contamination=scene.contamination,
                    shoulder_angles=bearing.shoulder_angles)
    if scene.paired:
        pair = pair_load_ratings(inputs["C"], b_si.C0, b_si.fatigue_load_limit)
        inputs |= given(C_pair=pair["C"], C0_pair=pair["C0"], fatigue_load_limit_pair=pair["fatigue_load_limit"])
    return inputs


#: the ratings a pair's ISO 281 life takes in place of one bearing's
PAIR_RATINGS = {"C": "C_pair", "fatigue_load_limit": "fatigue_load_limit_pair"}


def arrangement_steps(scene: LoadedBallBearing) -> tuple[Step, ...]:
    """The load distribution and the ISO 281 / ISO 76 / ISO/TS 16281 steps of one bearing, or of a pair (its own
    steps, and the rating lives against the pair's ratings :data:`PAIR_RATINGS`)."""
    if not scene.paired:
        return (Step.of(ball_loads), Step.of(ball_bearing_equivalent_load), Step.of(ball_static_safety),
                Step.of(rating_life), Step.of(modified_rating_life), Step.of(ball_reference_life))
    return (Step.of(ball_pair_loads), Step.of(ball_pair_equivalent_load), Step.of(ball_pair_static_safety),
            Step.of(rating_life, rename=PAIR_RATINGS), Step.of(modified_rating_life, rename=PAIR_RATINGS),
            Step.of(ball_pair_reference_life))


@scene_builder(LoadedBallBearing)
def build_ball_bearing(scene: LoadedBallBearing, *, models: Mapping[str, Any], effects: frozenset | None) -> SceneGraph:
    """Scene graph of a :class:`~camcontact.components.LoadedBallBearing` (one variant)."""
    effects = checked_request("ball_bearing", models, effects, slots=("film", "life"), supported=SUPPORTED_EFFECTS,
                              default=SUPPORTED_EFFECTS)
    if "elasticity" not in effects:
        raise InputError("ball_bearing scene: the point film models are elastohydrodynamic; leaving out 'elasticity' "
                         "is not supported (allowed effects: elasticity with or without piezoviscosity)")
    if scene.bearing.material is None:
        raise InputError(f"ball_bearing scene: BallBearing {scene.bearing.designation or scene.bearing.name!r} has no "
                         "material; the ball loads need the Hertz stiffness of its contacts (set BallBearing.material)")
    film_model = resolve_film_model(models.get("film", DEFAULT_FILM), geometry="point", where="ball_bearing scene: ")
    films = films_of(film_model)
    basis = "h_min" if "h_min" in films else "h_c"
    steps = [
        *arrangement_steps(scene), Step.of(ball_kinematics), Step.of(ball_hertz), Step.of(ball_truncation),
        Step.of(ball_subsurface),
        lubricant_step(scene.lubricant, scene.si.temperature),
        Step.of(ball_films, provides=(*(f"{q}_{race}" for q in films for race in RACES), "h_min_bearing",
                                      "film_validity", "film_valid")),
        *raceway_lambda_steps(basis), Step.of(bearing_lubrication),
    ]
    steps_provide = {o for s in steps for o in s.provides}
    return SceneGraph(kind="ball_bearing",
                      inputs={**ball_bearing_inputs(scene, effects), "film_model": film_model,
                              "life_model": models.get("life", "iso281")},
                      steps=tuple(steps), default_outputs=tuple(o for o in DEFAULT_OUTPUTS if o in steps_provide),
                      input_hints=HINTS, plotter=plot_ball_bearing, effects=effects, index="ball",
                      per_index=frozenset(PER_BALL & steps_provide))
