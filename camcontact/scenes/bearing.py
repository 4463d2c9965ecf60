"""The bearing scene: load distribution, contacts of every roller, films, Lambda, rating life.

A :class:`~camcontact.components.LoadedBearing` becomes the steps

``load_distribution``
    roller loads Q under F_r, F_a with the radial clearance (numerical, ISO/TS 16281 style,
    :mod:`camcontact.contact.load_distribution`), the number of loaded rollers, the load-zone
    half-angle psi_l = arccos(P_d / (2 delta_r)) (Harris & Kotzalas ch. 7) and the azimuth of the
    last loaded roller;
``kinematics``
    pure rolling: cage speed n_c = [n_i (1 - gamma) + n_o (1 + gamma)]/2, roller speed about its
    axis (d_m / 2 D_w)(1 - gamma^2)|n_i - n_o| and the entrainment speed of both raceway contacts
    u_m = (pi d_m / 2)(1 - gamma^2)|n_i - n_o| (Harris & Kotzalas 2007 ch. 8; gamma = D_w cos(alpha)/d_m);
``hertz``
    line-contact Hertz at the inner and outer raceway of every loaded roller (w = Q / l_we;
    rolling-direction radii of :attr:`SphericalRollerBearing.contact_radii`; the outer raceway is
    concave); with the bearing's conformities (:attr:`SphericalRollerBearing.conformity_inner` / ``_outer``) each
    contact is instead the finite line it is, sliced into ``LoadedBearing.laminae`` laminae with the gap
    y^2 / (2 R_y) across rolling (:mod:`camcontact.steps.raceway_laminae`, ISO/TS 16281): its peak pressure, its
    loaded length ``contact_length_<race>`` (over which the films, the mixed lubrication and the friction then
    spread the load) and whether it reaches the roller's ends (``edge_loaded_<race>``);
``subsurface``
    stresses below the most loaded contact (frictionless);
``lubricant``, ``film``, ``lambda_inner``, ``lambda_outer``, ``lubrication``
    film of every loaded contact by the film model of the ``film`` slot (a line formula by name,
    default ``"pan_hamrock"``, or ``"multigrid"``), Lambda with the bearing's roughness, regime;
``friction``
    friction at both raceway contacts of every loaded roller with the scene's slide/roll ratio: by default
    the film's fluid traction (model slot ``friction``: Eyring with the limiting shear stress and the
    lubricant's rheology, :mod:`camcontact.models.traction_fluid`, or any ``traction_models`` model), which
    falls to zero with the slip; ``"kelley"``: the Benedict-Kelley correlation (Delabenetta 2021 Eq. 49,
    which rises as the slip falls); whether each contact lies inside the model's validity
    (``friction_valid_inner`` / ``_outer``, with the reason in ``friction_validity``), the flash temperature
    of each contact (Eq. 48) and the bearing's sliding friction power sum(mu Q |u1 - u2|);
``friction_moment_skf``, ``friction_moment_palmgren``, ``rolling_resistance``
    the bearing's frictional moment and power by the SKF model (SKF "Rolling bearings" 2012, needs
    ``SphericalRollerBearing.series``) and by Palmgren's M0 + M1, side by side, from the loads, the
    relative ring speed and the lubricant's kinematic viscosity; the hydrodynamic rolling resistance of
    every loaded contact (Goksem & Hargreaves 1978) and its moment and power
    (:mod:`camcontact.steps.bearing_friction`);
``equivalent_load``, ``rating_life``, ``modified_life``
    ISO 281: P, L10 and L10h; L_nm with a1, kappa and a_ISO (model slot ``life``, default
    ``"iso281"``; needs the lubricant, the fatigue load limit and the contamination factor).

Effects: ``elasticity``, ``piezoviscosity`` and ``compressibility`` (on by default) as the line scene;
``thermal``: the inlet shear-heating reduction phi_T of every raceway film (Delabenetta 2021 Eq. 44, the
Wilson–Sheu slide/roll form, at the scene's slide/roll ratio, pure rolling without one; needs the lubricant's
thermal conductivity and
temperature-dependent viscosity: ``thermal_loading``, ``thermal_factor``) and the contact temperature rise of
the fluid traction (needs the material's thermal data); ``mixed``: Greenwood–Tripp asperity load sharing at
each raceway contact of every roller on its film (``asperity_load_fraction_<race>``, ``h_c_mixed_<race>``,
``lubrication_regime_<race>``, ``mixed_valid_<race>``; asperity parameters
``SphericalRollerBearing.asperity_density`` / ``asperity_radius`` or the orders-of-magnitude defaults), and
the fluid friction gains the asperities' boundary friction mu_b f_a + mu_fluid (1 - f_a) (asked for, so a
missing ``slide_roll_ratio`` is named up front).

Per-roller outputs are arrays over the index ``roller`` (rows x Z, row by row); unloaded rollers
have no contact: their Hertz and film values are NaN with ``contact_regime`` "unloaded". Only the
steps the requested outputs need run.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from ..components.loaded_bearing import LoadedBearing
from ..contact.geometry import reduced_modulus
from ..errors import InputError
from ..models.bearing_friction import SKF_SERIES
from ..step_graph import SceneGraph, Step, checked_request, given, scene_builder
from ..steps.bearing_friction import palmgren_friction_moment, roller_rolling_resistance, skf_friction_moment
from ..steps.contact import RACES, roller_hertz
from ..steps.ehl_friction import ROLLER_MIXED_OUTPUTS, ehl_friction_inputs, fluid_traction_model, roller_mixed
from ..steps.film import (bearing_lubrication, films_of, inlet_thermal_correction, raceway_lambda_steps,
                          resolve_film_model, roller_films, roller_thermal_films)
from ..steps.forces import load_distribution
from ..steps.friction import roller_fluid_friction, roller_friction
from ..steps.kinematics import bearing_kinematics, bearing_surface_speeds
from ..steps.life import bearing_equivalent_load, modified_rating_life, rating_life
from ..steps.lubricant import lubricant_inputs, lubricant_step
from ..steps.raceway_laminae import conformal_roller_hertz
from ..steps.stress import most_loaded_subsurface
from .bearing_plots import plot_bearing

__all__ = ["build_bearing", "bearing_inputs"]

SUPPORTED_EFFECTS = frozenset({"elasticity", "piezoviscosity", "compressibility", "thermal", "mixed"})
DEFAULT_EFFECTS = frozenset({"elasticity", "piezoviscosity", "compressibility"})
PER_ROLLER = frozenset({
    "roller_row", "azimuth", "Q", "loaded", "roller_approach",
    *(f"{q}_{race}" for q in ("b", "p_h", "h_c", "h_min", "Lambda", "friction_coefficient", "friction_valid",
                              "flash_temperature", "rolling_resistance", "contact_length", "edge_loaded")
      for race in RACES), "contact_regime", *ROLLER_MIXED_OUTPUTS,
})
#: what the effects add to the default report
EFFECT_OUTPUTS = {"thermal": ("thermal_factor",),
                  "mixed": (*(f"{q}_{race}" for q in ("asperity_load_fraction", "lubrication_regime",
                                                      "friction_coefficient") for race in RACES), "friction_power")}
DEFAULT_OUTPUTS = (
    "roller_row", "azimuth", "Q", "loaded", "b_inner", "p_h_inner", "b_outer", "p_h_outer", "h_min_inner", "h_min_outer",
    "Lambda_inner", "Lambda_outer", "contact_regime", "friction_coefficient_inner", "friction_coefficient_outer",
    "friction_valid_inner", "friction_valid_outer", "flash_temperature_inner", "flash_temperature_outer",
    "Q_max", "loaded_rollers", "load_zone", "last_loaded_azimuth", "delta_r", "delta_a", "p_h_max", "tau_max",
    "z_tau_max", "cage_speed", "u_m", "h_min_bearing", "Lambda_bearing", "viscosity_extrapolated", "friction_power", "friction_validity", "P",
    "L10", "L10h", "kappa", "a_ISO", "L_nm", "L_nmh",
    "friction_moment_skf", "friction_power_skf", "friction_moment_palmgren", "friction_power_palmgren",
)
HINTS = {
    "lubricant": "set LoadedBearing.lubricant",
    "temperature": "set LoadedBearing.temperature (the lubricant's viscosity depends on it)",
    "sigma": "set SphericalRollerBearing.roughness (RMS of each surface)",
    "E_reduced": "set SphericalRollerBearing.material (Hertz needs E and nu)",
    "fatigue_load_limit": "set SphericalRollerBearing.fatigue_load_limit (P_u from the catalogue)",
    "contamination": "set LoadedBearing.contamination (ISO 281 factor e_C, 0 < e_C <= 1)",
    "slide_roll_ratio": "set LoadedBearing.slide_roll_ratio (the raceway friction needs sliding)",
    "effusivity": "give the bearing material density, specific_heat and thermal_conductivity",
    "bearing_series": f"set SphericalRollerBearing.series, which the SKF friction model needs (one of "
                      f"{', '.join(SKF_SERIES)}; e.g. '240' for a 24040)",
    "lubrication": "set LoadedBearing.lubricant (its form, grease or oil, sets the lubrication method)",
    "base_oil": "set LoadedBearing.lubricant (its base oil sets the SKF model's mu_EHL)",
    "asperity_density": "give SphericalRollerBearing.asperity_density and asperity_radius",
}
#: what the conformities add to the default report (the finite-line contacts)
CONFORMAL_OUTPUTS = tuple(f"{q}_{race}" for q in ("contact_length", "edge_loaded") for race in RACES)


def bearing_inputs(scene: LoadedBearing, effects: frozenset) -> dict[str, Any]:
    """The graph inputs of a loaded bearing (SI): loads, ring speeds [rev/s], geometry, material,
    lubricant, life data and switches."""
    bearing = scene.bearing
    b_si = bearing.si
    inputs: dict[str, Any] = {
        "roller": np.arange(bearing.roller_count, dtype=float), "bearing": bearing,
        "radial_load": scene.si.radial_load, "axial_load": scene.si.axial_load,
        "n_inner": scene.si.speed / (2 * math.pi), "n_outer": scene.si.outer_speed / (2 * math.pi),
        "reliability": scene.reliability, "C": b_si.C, "contact_angle": b_si.contact_angle, "rolling_element": "roller",
        "gamma": bearing.gamma, "pitch_diameter": bearing.d_m, "roller_diameter": b_si.roller_diameter,
        "contact_radii": bearing.contact_radii, "roller_length": b_si.roller_length,
        "bore": b_si.bore, "outer_diameter": b_si.outer_diameter, "laminae": scene.laminae,
        "piezoviscosity": "piezoviscosity" in effects, "compressibility": "compressibility" in effects,
        **lubricant_inputs(scene.lubricant, scene.si.temperature),
    }
    material = bearing.material
    if material is not None:
        inputs["E_reduced"] = reduced_modulus(material.si.E, material.nu, material.si.E, material.nu)
        inputs["nu"] = material.nu
        try:
            inputs["effusivity"] = material.thermal_effusivity()
        except InputError:
            pass  # only the flash temperature needs it: named up front if asked for
    return inputs | given(sigma=b_si.roughness, fatigue_load_limit=b_si.fatigue_load_limit,
                          contamination=scene.contamination, slide_roll_ratio=scene.slide_roll_ratio,
                          bearing_series=bearing.series, lubrication=getattr(scene.lubricant, "form", None),
                          base_oil=getattr(scene.lubricant, "base_oil", None), raceway_profiles=bearing.raceway_profiles())


def film_steps(film_model: Any, thermal: bool) -> list[Step]:
    """The films of every roller at both raceways and, with ``thermal``, their inlet shear-heating reduction
    phi_T (Wilson & Sheu's slide/roll form as Delabenetta Eq. 44; one factor for both races: same speeds, same
    oil) on the isothermal films."""
    films = (*(f"{q}_{race}" for q in films_of(film_model) for race in RACES), "h_min_bearing")
    if not thermal:
        return [Step.of(roller_films, provides=films)]
    isothermal = tuple(f"{q}_isothermal" for q in films)
    return [Step.of(roller_films, provides=films, rename=dict(zip(films, isothermal))),
            Step.of(bearing_surface_speeds, optional=("slide_roll_ratio",)), Step.of(inlet_thermal_correction),
            Step.of(roller_thermal_films, extra=isothermal, provides=films)]


def friction_step(choice: Any, mixed: bool) -> Step:
    """The raceway contacts' friction: the film's fluid traction (default: Eyring with the limiting shear stress,
    or the ``traction_models`` model given; with ``mixed`` plus the asperities' boundary friction on their share)
    or, with ``models={"friction": "kelley"}``, the Benedict–Kelley correlation of Delabenetta (2021) Eq. 49, which
    rises as the slip falls (valid for 1 %-200 % slide/roll)."""
    if choice == "kelley":
        return Step.of(roller_friction)
    reads = (*(f"{q}_{race}" for q in ("asperity_load_fraction", "h_c_mixed") for race in RACES), "boundary_friction")
    return Step.of(roller_fluid_friction, extra=reads if mixed else ())


def moment_steps(scene: LoadedBearing) -> list[Step]:
    """The SKF and Palmgren frictional-moment steps when the lubricant gives its kinematic viscosity at the
    scene's temperature (it needs a density or kinematic data); without it the moments are not offered."""
    try:
        known = scene.lubricant is not None and scene.lubricant.state(scene.si.temperature).kinematic_viscosity
    except InputError:
        known = False
    return [Step.of(skf_friction_moment), Step.of(palmgren_friction_moment)] if known else []


def friction_inputs(scene: LoadedBearing, effects: frozenset) -> dict[str, Any]:
    """The boundary friction and, with ``mixed``, the asperity parameters of the raceway contacts
    (:func:`camcontact.steps.ehl_friction.ehl_friction_inputs`; both surfaces of the bearing's roughness)."""
    if "mixed" not in effects:
        return {}
    bearing = scene.bearing
    roughness = bearing.si.roughness
    if roughness == 0.0:
        raise InputError(f"bearing scene: the 'mixed' effect needs rough surfaces; SphericalRollerBearing "
                         f"{bearing.designation!r}.roughness = {bearing.roughness} (allowed: > 0)")
    return ehl_friction_inputs(scene.lubricant, (), (roughness, roughness), effects,
                               asperity_density=bearing.si.asperity_density, asperity_radius=bearing.si.asperity_radius)


@scene_builder(LoadedBearing)
def build_bearing(scene: LoadedBearing, *, models: Mapping[str, Any], effects: frozenset | None) -> SceneGraph:
    """Scene graph of a :class:`~camcontact.components.LoadedBearing` (one variant)."""
    effects = checked_request("bearing", models, effects, slots=("film", "life", "friction"),
                              supported=SUPPORTED_EFFECTS, default=DEFAULT_EFFECTS)
    film_model = resolve_film_model(models.get("film", "pan_hamrock"), effects=effects)
    basis = "h_min" if "h_min" in films_of(film_model) else "h_c"
    mixed = "mixed" in effects
    steps = [
        Step.of(load_distribution), Step.of(bearing_kinematics),
        Step.of(conformal_roller_hertz if scene.bearing.conformal else roller_hertz),
        Step.of(most_loaded_subsurface),
        lubricant_step(scene.lubricant, scene.si.temperature), *film_steps(film_model, "thermal" in effects),
        *raceway_lambda_steps(basis),
        *([Step.of(roller_mixed)] if mixed else []),
        Step.of(bearing_lubrication), friction_step(models.get("friction"), mixed), Step.of(bearing_equivalent_load),
        Step.of(rating_life), Step.of(modified_rating_life), *moment_steps(scene), Step.of(roller_rolling_resistance),
    ]
    inputs = {**bearing_inputs(scene, effects), "film_model": film_model, "life_model": models.get("life", "iso281"),
              "traction_model": fluid_traction_model(scene.lubricant, effects | {"non_newtonian"},
                                                     None if models.get("friction") == "kelley" else models.get("friction")),
              **friction_inputs(scene, effects)}
    per_index = frozenset(PER_ROLLER & {o for step in steps for o in step.provides})
    added = tuple(q for effect in sorted(effects & EFFECT_OUTPUTS.keys()) for q in EFFECT_OUTPUTS[effect])
    conformal = CONFORMAL_OUTPUTS if scene.bearing.conformal else ()
    return SceneGraph(kind="bearing", inputs=inputs, steps=tuple(steps),
                      default_outputs=DEFAULT_OUTPUTS + conformal + added,
                      input_hints=HINTS, plotter=plot_bearing, effects=effects, index="roller", per_index=per_index,
                      effect_outputs=frozenset(added))
