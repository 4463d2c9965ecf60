"""The bearing scene: load distribution, contacts of every roller, films, Lambda, rating life.

A :class:`~camcontact.components.LoadedBearing` becomes the steps

``load_distribution``
    roller loads Q under F_r, F_a with the radial clearance (numerical, ISO/TS 16281 style,
    :mod:`camcontact.contact.load_distribution`);
``kinematics``
    pure rolling: cage speed n_c = [n_i (1 - gamma) + n_o (1 + gamma)]/2, roller speed about its
    axis (d_m / 2 D_w)(1 - gamma^2)|n_i - n_o| and the entrainment speed of both raceway contacts
    u_m = (pi d_m / 2)(1 - gamma^2)|n_i - n_o| (Harris & Kotzalas 2007 ch. 8; gamma = D_w cos(alpha)/d_m);
``hertz``
    line-contact Hertz at the inner and outer raceway of every loaded roller (w = Q / l_we;
    rolling-direction radii of :attr:`SphericalRollerBearing.contact_radii`; the outer raceway is
    concave);
``subsurface``
    stresses below the most loaded contact (frictionless);
``lubricant``, ``film``, ``lambda``
    film of every loaded contact by the film model of the ``film`` slot (a line formula by name,
    default ``"pan_hamrock"``, or ``"multigrid"``), Lambda with the bearing's roughness, regime;
``friction``
    Benedict-Kelley friction at both raceway contacts of every loaded roller with the scene's
    slide/roll ratio (Delabenetta 2021 Eq. 49), the flash temperature of each contact (Eq. 48) and
    the bearing's sliding friction power sum(mu Q |u1 - u2|);
``equivalent_load``, ``rating_life``, ``modified_life``
    ISO 281: P, L10 and L10h; L_nm with a1, kappa and a_ISO (model slot ``life``, default
    ``"iso281"``; needs the lubricant, the fatigue load limit and the contamination factor).

Per-roller outputs are arrays over the index ``roller`` (rows x Z, row by row); unloaded rollers
have no contact: their Hertz and film values are NaN with ``contact_regime`` "unloaded". Only the
steps the requested outputs need run.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from .. import registry
from ..analysis import SceneGraph, Step, checked_request, scene_builder
from ..components.loaded_bearing import LoadedBearing
from ..contact.contact_temperature import flash_temperature
from ..contact.geometry import reduced_modulus
from ..contact.hertz_line import hertz_line
from ..contact.roughness import lambda_ratio, lubrication_regime
from ..contact.subsurface import line_subsurface
from ..errors import InputError
from ..models.friction import Kelley
from ..models.life_iso281 import LIFE_EXPONENT, equivalent_load
from .line_contact import _film_model, lubricant_step

__all__ = ["build_bearing"]

SUPPORTED_EFFECTS = frozenset({"elasticity", "piezoviscosity", "compressibility"})
DEFAULT_EFFECTS = SUPPORTED_EFFECTS
RACES = ("inner", "outer")
PER_ROLLER = frozenset({
    "roller_row", "azimuth", "Q", "roller_approach",
    *(f"{q}_{race}" for q in ("b", "p_h", "h_c", "h_min", "Lambda", "friction_coefficient", "flash_temperature")
      for race in RACES), "contact_regime",
})
DEFAULT_OUTPUTS = (
    "roller_row", "azimuth", "Q", "b_inner", "p_h_inner", "b_outer", "p_h_outer", "h_min_inner", "h_min_outer",
    "Lambda_inner", "Lambda_outer", "contact_regime", "friction_coefficient_inner", "friction_coefficient_outer",
    "flash_temperature_inner", "flash_temperature_outer",
    "Q_max", "loaded_rollers", "load_zone", "delta_r", "delta_a", "p_h_max", "tau_max", "z_tau_max",
    "cage_speed", "u_m", "h_min_bearing", "Lambda_bearing", "friction_power", "P", "L10", "L10h", "kappa", "a_ISO", "L_nm", "L_nmh",
)
HINTS = {
    "lubricant": "set LoadedBearing.lubricant",
    "temperature": "set LoadedBearing.temperature (the lubricant's viscosity depends on it)",
    "sigma": "set SphericalRollerBearing.roughness (RMS of each surface)",
    "E_reduced": "set SphericalRollerBearing.material (Hertz needs E and nu)",
    "fatigue_load_limit": "set SphericalRollerBearing.fatigue_load_limit (P_u from the catalogue)",
    "contamination": "set LoadedBearing.contamination (ISO 281 factor e_C, 0 < e_C <= 1)",
    "slide_roll_ratio": "set LoadedBearing.slide_roll_ratio (the Kelley correlation needs sliding)",
    "effusivity": "give the bearing material density, specific_heat and thermal_conductivity",
}


@scene_builder(LoadedBearing)
def build_bearing(scene: LoadedBearing, *, models: Mapping[str, Any], effects: frozenset | None) -> SceneGraph:
    """Scene graph of a :class:`~camcontact.components.LoadedBearing` (one variant)."""
    effects = checked_request("bearing", models, effects, slots=("film", "life"), supported=SUPPORTED_EFFECTS,
                              default=DEFAULT_EFFECTS)
    bearing = scene.bearing
    b_si = bearing.si
    count = bearing.roller_count
    inputs: dict[str, Any] = {
        "roller": np.arange(count, dtype=float), "radial_load": scene.si.radial_load,
        "axial_load": scene.si.axial_load, "n_inner": scene.si.speed / (2 * math.pi),
        "n_outer": scene.si.outer_speed / (2 * math.pi), "reliability": scene.reliability,
        "C": b_si.C, "contact_angle": b_si.contact_angle,
    }
    if bearing.material is not None:
        material = bearing.material
        inputs["E_reduced"] = reduced_modulus(material.si.E, material.nu, material.si.E, material.nu)
        inputs["nu"] = material.nu
    if bearing.roughness is not None:
        inputs["sigma"] = b_si.roughness
    if scene.lubricant is not None:
        inputs["lubricant"] = scene.lubricant
    if scene.temperature is not None:
        inputs["temperature"] = scene.si.temperature
    if bearing.fatigue_load_limit is not None:
        inputs["fatigue_load_limit"] = b_si.fatigue_load_limit
    if scene.contamination is not None:
        inputs["contamination"] = scene.contamination
    if scene.slide_roll_ratio is not None:
        inputs["slide_roll_ratio"] = scene.slide_roll_ratio
    if bearing.material is not None:
        try:
            inputs["effusivity"] = bearing.material.thermal_effusivity()
        except InputError:
            pass  # only the flash temperature needs it: named up front if asked for

    def run_distribution(s):
        result = bearing.load_distribution_si(s["radial_load"], s["axial_load"])
        rows, Z = result.Q.shape
        return {
            "roller_row": np.repeat(np.arange(1.0, rows + 1), Z), "azimuth": result.azimuths.ravel(),
            "Q": result.Q.ravel(), "roller_approach": result.approach.ravel(), "Q_max": result.Q_max,
            "loaded_rollers": float(result.loaded.sum()), "load_zone": float(result.load_zone.max()),
            "delta_r": result.delta_r, "delta_a": result.delta_a, "force_residual": result.residual,
        }

    gamma = bearing.gamma
    d_m, D_w = bearing.d_m, b_si.roller_diameter

    def run_kinematics(s):
        relative = abs(s["n_inner"] - s["n_outer"])
        return {
            "cage_speed": 2 * math.pi * 0.5 * (s["n_inner"] * (1 - gamma) + s["n_outer"] * (1 + gamma)),
            "roller_speed": 2 * math.pi * d_m / (2 * D_w) * (1 - gamma**2) * relative,
            "u_m": 0.5 * math.pi * d_m * (1 - gamma**2) * relative,
        }

    radii = bearing.contact_radii
    length = b_si.roller_length

    def run_hertz(s):
        Q = s["Q"]
        out: dict[str, Any] = {}
        loaded = Q > 0.0
        for race in RACES:
            b, p = np.full(Q.size, np.nan), np.full(Q.size, np.nan)
            for j in np.flatnonzero(loaded):
                contact = hertz_line(Q[j] / length, radii[race], s["E_reduced"])
                b[j], p[j] = contact.b, contact.p_h
            out[f"b_{race}"], out[f"p_h_{race}"] = b, p
        peaks = [np.nanmax(out[f"p_h_{race}"]) if loaded.any() else 0.0 for race in RACES]
        out["p_h_max"] = float(max(peaks))
        return out

    def run_subsurface(s):
        if not np.any(s["Q"] > 0.0):
            return {"tau_max": 0.0, "z_tau_max": 0.0}
        race = "inner" if np.nanmax(s["p_h_inner"]) >= np.nanmax(s["p_h_outer"]) else "outer"
        j = int(np.nanargmax(s[f"p_h_{race}"]))
        stresses = line_subsurface(s[f"b_{race}"][j], s[f"p_h_{race}"][j], nu=s["nu"])
        return {"tau_max": stresses.principal_shear_max.value, "z_tau_max": stresses.principal_shear_max.z}

    piezo = "piezoviscosity" in effects
    film_model = _film_model(models.get("film", "pan_hamrock"), effects)
    films = tuple(q for q in ("h_c", "h_min") if q in film_model.provides)

    def run_film(s):
        Q = s["Q"]
        alpha = s["alpha"] if piezo else 0.0
        out = {f"{q}_{race}": np.full(Q.size, np.nan) for q in films for race in RACES}
        if s["u_m"] <= 0.0:
            raise InputError("bearing scene: the rings do not turn relative to each other (speed = outer_speed): "
                             "no entrainment, no steady film")
        for j in np.flatnonzero(Q > 0.0):
            for race in RACES:
                state = {"R": radii[race], "w": Q[j] / length, "E_reduced": s["E_reduced"], "u_m": s["u_m"],
                         "eta0": s["eta0"], "alpha": alpha, "lubricant_state": s["lubricant_state"],
                         "density_law": s["density_law"]}
                produced = film_model(state)
                for q in films:
                    out[f"{q}_{race}"][j] = produced[q]
        basis = "h_min" if "h_min" in films else "h_c"
        values = np.concatenate([out[f"{basis}_{race}"] for race in RACES])
        out["h_min_bearing"] = float(np.nanmin(values)) if np.any(np.isfinite(values)) else float("nan")
        return out

    def run_lambda(s):
        basis = "h_min" if "h_min" in films else "h_c"
        out: dict[str, Any] = {}
        for race in RACES:
            out[f"Lambda_{race}"] = lambda_ratio(s[f"{basis}_{race}"], s["sigma"], s["sigma"])
        regimes = []
        for j in range(s["Q"].size):
            if not s["Q"][j] > 0.0:
                regimes.append("unloaded")
            else:
                regimes.append(lubrication_regime(min(out["Lambda_inner"][j], out["Lambda_outer"][j])))
        out["contact_regime"] = np.array(regimes, dtype=object)
        finite = np.concatenate([out[f"Lambda_{race}"] for race in RACES])
        out["Lambda_bearing"] = float(np.nanmin(finite)) if np.any(np.isfinite(finite)) else float("nan")
        return out

    def run_friction(s):
        Q, slip = s["Q"], s["slide_roll_ratio"]
        u1, u2 = s["u_m"] * (1 + 0.5 * slip), s["u_m"] * (1 - 0.5 * slip)
        loaded = Q > 0.0
        out: dict[str, Any] = {}
        power = 0.0
        for race in RACES:
            mu, flash = np.full(Q.size, np.nan), np.full(Q.size, np.nan)
            if loaded.any():
                mu[loaded] = Kelley()({"normal_force": Q[loaded], "contact_length": length, "eta0": s["eta0"],
                                       "u1": u1, "u2": u2})["friction_coefficient"]
                for j in np.flatnonzero(loaded):
                    flash[j] = flash_temperature(Q[j] / length, s["E_reduced"], radii[race], mu[j], u1, u2,
                                                 s["effusivity"], s["effusivity"])
                power += float(np.sum(mu[loaded] * Q[loaded])) * abs(u1 - u2)
            out[f"friction_coefficient_{race}"], out[f"flash_temperature_{race}"] = mu, flash
        out["friction_power"] = power
        return out

    def run_equivalent(s):
        return {"P": equivalent_load(s["radial_load"], s["axial_load"], s["contact_angle"])}

    def run_rating(s):
        if s["P"] <= 0.0:
            return {"L10": math.inf, "L10h": math.inf}
        L10 = (s["C"] / s["P"]) ** LIFE_EXPONENT * 1e6
        relative = abs(s["n_inner"] - s["n_outer"])
        return {"L10": L10, "L10h": L10 / relative if relative > 0 else math.inf}  # seconds (SI)

    life_spec = models.get("life", "iso281")

    def run_modified(s):
        model = registry.get("life_models", life_spec, reliability=s["reliability"], contamination=s["contamination"]) \
            if isinstance(life_spec, str) else life_spec
        viscosity = s["lubricant_state"].kinematic_viscosity
        if viscosity is None:
            raise InputError(f"Lubricant {s['lubricant'].name!r}: its kinematic viscosity at the operating "
                             "temperature is unknown (give its density or kinematic viscosity data), which kappa needs")
        produced = model({"C": s["C"], "P": s["P"], "speed": abs(s["n_inner"] - s["n_outer"]), "pitch_diameter": d_m,
                          "viscosity": viscosity, "fatigue_load_limit": s["fatigue_load_limit"]})
        return {k: produced[k] for k in ("a1", "nu1", "kappa", "a_ISO", "L_nm", "L_nmh")}

    per_race = [f"{q}_{race}" for q in ("b", "p_h") for race in RACES]
    steps = [
        Step("load_distribution", ("radial_load", "axial_load"),
             ("roller_row", "azimuth", "Q", "roller_approach", "Q_max", "loaded_rollers", "load_zone", "delta_r",
              "delta_a", "force_residual"), run_distribution, model="iso_ts_16281_line"),
        Step("kinematics", ("n_inner", "n_outer"), ("cage_speed", "roller_speed", "u_m"), run_kinematics,
             model="pure_rolling"),
        Step("hertz", ("Q", "E_reduced"), (*per_race, "p_h_max"), run_hertz, model="hertz_line"),
        Step("subsurface", ("Q", *per_race, "nu"), ("tau_max", "z_tau_max"), run_subsurface, model="mcewen_line"),
        lubricant_step(scene.lubricant, effects, piezo),
        Step("film", ("Q", "E_reduced", "u_m", "eta0", "alpha", "lubricant_state", "density_law"),
             (*(f"{q}_{race}" for q in films for race in RACES), "h_min_bearing"), run_film,
             model=getattr(film_model, "name", "film"), identity=id(film_model)),
        Step("lambda", ("Q", *(f"{q}_{race}" for q in films for race in RACES), "sigma"),
             ("Lambda_inner", "Lambda_outer", "contact_regime", "Lambda_bearing"), run_lambda),
        Step("friction", ("Q", "u_m", "slide_roll_ratio", "eta0", "E_reduced", "effusivity"),
             (*(f"{q}_{race}" for q in ("friction_coefficient", "flash_temperature") for race in RACES),
              "friction_power"), run_friction, model="kelley"),
        Step("equivalent_load", ("radial_load", "axial_load", "contact_angle"), ("P",), run_equivalent,
             model="iso281"),
        Step("rating_life", ("C", "P", "n_inner", "n_outer"), ("L10", "L10h"), run_rating, model="iso281"),
        Step("modified_life", ("C", "P", "n_inner", "n_outer", "lubricant", "lubricant_state", "fatigue_load_limit",
                               "reliability", "contamination"),
             ("a1", "nu1", "kappa", "a_ISO", "L_nm", "L_nmh"), run_modified, model=str(life_spec)),
    ]
    per_index = frozenset(PER_ROLLER & {o for step in steps for o in step.provides})
    return SceneGraph(kind="bearing", inputs=inputs, steps=tuple(steps), default_outputs=DEFAULT_OUTPUTS,
                      input_hints=HINTS, plotter=_plot, effects=effects, index="roller", per_index=per_index)


def _plot(result, **kwargs):
    from .bearing_plots import plot_bearing

    return plot_bearing(result, **kwargs)
