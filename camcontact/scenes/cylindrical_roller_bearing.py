"""The cylindrical-roller-bearing scene: lamina loads under a radial load and a misalignment, the pressure along
every roller, films, Lambda, ISO 281 and ISO/TS 16281 lives.

A :class:`~camcontact.components.LoadedCylindricalRollerBearing` becomes the steps

``load_distribution``
    roller and lamina loads (ISO/TS 16281 slicing with the rollers' profile, the clearance and the imposed
    misalignment; :mod:`camcontact.steps.roller_bearing`): per roller Q and the axial position of its most
    loaded lamina, the ring's displacement and the laminae's moment;
``kinematics``
    pure rolling (cage speed, roller speed, entrainment speed u_m of both raceway contacts);
``hertz``
    the largest lamina pressure along every roller at both raceways (each lamina a Hertz line contact) and the
    loaded length of every roller ``contact_length_<race>`` (where its laminae's compression crosses zero);
``lubricant``, ``film``, ``lambda_inner``, ``lambda_outer``, ``lubrication``
    films of every loaded roller at both raceways by a line film model (slot ``film``, default
    ``"pan_hamrock"``; the mean load per length over the loaded length), Lambda with the bearing's roughness, the regime;
``equivalent_load``, ``rating_life``, ``modified_life``, ``reference_life``
    ISO 281 (P = F_r, L10 = (C/P)^(10/3), L_nm with a1, kappa and a_ISO of roller bearings; slot ``life``) and
    ISO/TS 16281's L_10r from the lamina loads (which sees the misalignment and the profile).

Effects: ``elasticity``, ``piezoviscosity`` and ``compressibility`` as the line scene. Per-roller outputs are
arrays over the index ``roller``; an unloaded roller has no contact (NaN with ``contact_regime`` "unloaded").
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from ..components.loaded_cylindrical_roller_bearing import LoadedCylindricalRollerBearing
from ..contact.geometry import reduced_modulus
from ..step_graph import SceneGraph, Step, checked_request, given, scene_builder
from ..steps.contact import RACES
from ..steps.film import bearing_lubrication, films_of, raceway_lambda_steps, resolve_film_model, roller_films
from ..steps.kinematics import bearing_kinematics
from ..steps.life import modified_rating_life, rating_life
from ..steps.lubricant import lubricant_inputs, lubricant_step
from ..steps.roller_bearing import lamina_hertz, lamina_loads, lamina_reference_life, radial_equivalent_load
from .cylindrical_roller_bearing_plots import plot_cylindrical_roller_bearing

__all__ = ["DEFAULT_OUTPUTS", "build_cylindrical_roller_bearing", "cylindrical_bearing_inputs"]

SUPPORTED_EFFECTS = frozenset({"elasticity", "piezoviscosity", "compressibility"})
PER_ROLLER = frozenset({"azimuth", "Q", "loaded", "x_q_max", "contact_regime",
                        *(f"{q}_{race}" for q in ("b", "p_h", "h_c", "h_min", "Lambda", "contact_length")
                          for race in RACES)})
DEFAULT_OUTPUTS = (
    "azimuth", "Q", "loaded", "x_q_max", "p_h_inner", "p_h_outer", "h_min_inner", "h_min_outer", "Lambda_inner",
    "Lambda_outer", "contact_regime", "Q_max", "loaded_rollers", "delta_r", "lamina_moment", "p_h_max", "u_m",
    "h_min_bearing", "Lambda_bearing", "viscosity_extrapolated", "P", "L10", "L10h", "kappa", "a_ISO", "L_nm",
    "L_nmh", "L10r", "L10rh",
)
HINTS = {
    "lubricant": "set LoadedCylindricalRollerBearing.lubricant",
    "temperature": "set LoadedCylindricalRollerBearing.temperature (the lubricant's viscosity depends on it)",
    "sigma": "set CylindricalRollerBearing.roughness (RMS of each surface)",
    "E_reduced": "set CylindricalRollerBearing.material (Hertz needs E and nu)",
    "fatigue_load_limit": "set CylindricalRollerBearing.fatigue_load_limit (P_u from the catalogue)",
    "contamination": "set LoadedCylindricalRollerBearing.contamination (ISO 281 factor e_C, 0 < e_C <= 1)",
}


def cylindrical_bearing_inputs(scene: LoadedCylindricalRollerBearing, effects: frozenset) -> dict[str, Any]:
    """The graph inputs of a loaded cylindrical roller bearing (SI)."""
    bearing = scene.bearing
    b_si = bearing.si
    inputs: dict[str, Any] = {
        "roller": np.arange(bearing.roller_count, dtype=float), "bearing": bearing,
        "radial_load": scene.si.radial_load, "misalignment": scene.si.misalignment, "laminae": scene.laminae,
        "n_inner": scene.si.speed / (2 * np.pi), "n_outer": scene.si.outer_speed / (2 * np.pi),
        "reliability": scene.reliability, "C": b_si.C, "gamma": b_si.roller_diameter / bearing.d_m,
        "pitch_diameter": bearing.d_m, "roller_diameter": b_si.roller_diameter, "contact_radii": bearing.contact_radii,
        "roller_length": b_si.roller_length, "rolling_element": "roller",
        "piezoviscosity": "piezoviscosity" in effects, "compressibility": "compressibility" in effects,
        **lubricant_inputs(scene.lubricant, scene.si.temperature),
    }
    material = bearing.material
    if material is not None:
        inputs["E_reduced"] = reduced_modulus(material.si.E, material.nu, material.si.E, material.nu)
    return inputs | given(sigma=b_si.roughness, fatigue_load_limit=b_si.fatigue_load_limit,
                          contamination=scene.contamination)


@scene_builder(LoadedCylindricalRollerBearing)
def build_cylindrical_roller_bearing(scene: LoadedCylindricalRollerBearing, *, models: Mapping[str, Any],
                                     effects: frozenset | None) -> SceneGraph:
    """Scene graph of a :class:`~camcontact.components.LoadedCylindricalRollerBearing` (one variant)."""
    effects = checked_request("cylindrical_roller_bearing", models, effects, slots=("film", "life"),
                              supported=SUPPORTED_EFFECTS, default=SUPPORTED_EFFECTS)
    film_model = resolve_film_model(models.get("film", "pan_hamrock"), effects=effects)
    films = films_of(film_model)
    basis = "h_min" if "h_min" in films else "h_c"
    steps = [
        Step.of(lamina_loads), Step.of(bearing_kinematics), Step.of(lamina_hertz),
        lubricant_step(scene.lubricant, scene.si.temperature),
        Step.of(roller_films, provides=(*(f"{q}_{race}" for q in films for race in RACES), "h_min_bearing")),
        *raceway_lambda_steps(basis),
        Step.of(bearing_lubrication), Step.of(radial_equivalent_load), Step.of(rating_life),
        Step.of(modified_rating_life), Step.of(lamina_reference_life),
    ]
    provided = {o for s in steps for o in s.provides}
    return SceneGraph(kind="cylindrical_roller_bearing",
                      inputs={**cylindrical_bearing_inputs(scene, effects), "film_model": film_model,
                              "life_model": models.get("life", "iso281")},
                      steps=tuple(steps), default_outputs=tuple(o for o in DEFAULT_OUTPUTS if o in provided),
                      input_hints=HINTS, plotter=plot_cylindrical_roller_bearing, effects=effects, index="roller",
                      per_index=frozenset(PER_ROLLER & provided))
