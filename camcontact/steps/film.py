"""Film steps: which film model, the EHL groups, the film of a contact, the thermal correction, Lambda.

Film models are plugins of the ``film_models`` family (formulas of Grubin, Dowson–Higginson,
Pan–Hamrock, Moes, Hamrock–Dowson, Nijenbanning, and the numerical multigrid solvers); one
resolution (:func:`resolve_film_model`) serves every scene. Groups after Hamrock (U, G, W) and Moes
(M, L) (:mod:`camcontact.ehl.groups`); the inlet shear-heating factor after Murch & Wilson as
Delabenetta (2021) Eq. 44 gives it (:mod:`camcontact.models.film_thermal`); Lambda = h / sqrt(sigma1^2 +
sigma2^2) (Delabenetta 2021 Eq. 13). Films and roughness [m], loads per length [N/m], speeds [m/s].
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterable
from typing import Any

import attrs
import numpy as np

from .. import registry
from ..contact.roughness import composite_roughness, lambda_ratio, lubrication_regime, sinusoid_amplitude
from ..contact.spin_traction import PressureField
from ..ehl.groups import hamrock_line, moes_line
from ..errors import ConvergenceWarning, InputError
from ..models.base import FilmModel
from ..models.film_line import LINE_INPUTS
from ..models.film_point import POINT_INPUTS
from ..models.film_thermal import inlet_heating_factor, slide_roll_measure, thermal_loading
from ..step_graph import Step, step
from .contact import RACES

__all__ = [
    "FILMS", "ball_cone_films", "bearing_lubrication", "check_thermal_data", "composite_roughness_step",
    "ehl_groups", "film_parameter", "films_of", "inlet_thermal_correction", "isothermal_films", "line_film", "point_film",
    "lubrication_regime_step", "model_reads", "raceway_lambda_steps", "raceway_roughness", "resolve_film_model",
    "roller_films", "roller_thermal_films",
    "solved_films", "solved_thermal_films", "thermal_films",
]

#: the film thicknesses a film model may give: central and minimum [m]
FILMS = ("h_c", "h_min")


def films_of(model: Any) -> tuple[str, ...]:
    """The films ``model`` gives (h_c and/or h_min); both when there is no model yet (no lubricant)."""
    provides = getattr(model, "provides", FILMS)
    return tuple(q for q in FILMS if q in provides)


def resolve_film_model(spec: Any, *, geometry: str = "line", effects: Iterable[str] = (),
                       where: str = "", contact: str = "", enable: Iterable[str] = ()) -> FilmModel:
    """The film model named (or given) by ``spec`` for a ``geometry`` ("line" or "point") contact.

    Line contacts: a scene without ``piezoviscosity`` or ``elasticity`` among ``effects`` needs a model
    that can switch them off (its ``can_disable``); the model is made with them off, or the InputError
    lists the line models that can. Point contacts: ``"multigrid"`` is the point solver
    ``multigrid_point``; a model without piezoviscosity receives alpha = 0. ``where`` prefixes the
    errors (``"ball_cone_cvt scene: "``), ``contact`` names the contact in them. ``enable``: the effects of
    ``effects`` that the scene lets a line model solve itself — those in the model's ``can_enable`` (the
    multigrid model's ``thermal`` and ``non_newtonian``) are switched on in it.
    """
    if geometry == "point":
        spec = "multigrid_point" if spec == "multigrid" else spec
        model = registry.get("film_models", spec, requires=POINT_INPUTS, provides=FILMS)
        if getattr(model, "geometry", "point") != "point":
            raise InputError(f"{where}film model {model.name!r} is for {model.geometry} contacts; "
                             f"{contact or 'a point contact'} needs a point model (hamrock_dowson, nijenbanning, "
                             "multigrid)")
        return model
    candidate = registry.get("film_models", spec, requires=LINE_INPUTS, provides=getattr(spec, "provides", FILMS))
    if getattr(candidate, "geometry", "line") != "line":
        raise InputError(
            f"{where}film model {candidate.name!r} is for {candidate.geometry} contacts; "
            f"{contact or 'a line contact'} needs a line model"
        )
    switched_on = {e: True for e in enable if e in frozenset(effects) and e in getattr(candidate, "can_enable", ())}
    switched_off = sorted({"piezoviscosity", "elasticity"} - frozenset(effects))
    if not switched_off and not switched_on:
        return candidate
    cannot = [e for e in switched_off if e not in getattr(candidate, "can_disable", ())]
    if cannot:
        able = [
            n for n in registry.available("film_models")
            if getattr(registry.get_class("film_models", n), "geometry", "") == "line"
            and set(switched_off) <= set(getattr(registry.get_class("film_models", n), "can_disable", ()))
        ]
        raise InputError(
            f"{where}film model {candidate.name!r} cannot represent a scene without {', '.join(cannot)}; "
            f"line models that can: {', '.join(able) or '(none)'}"
        )
    flags = {effect: False for effect in switched_off} | switched_on
    if isinstance(spec, str):
        return registry.get("film_models", spec, **flags)
    if attrs.has(type(candidate)):
        return registry.get("film_models", candidate, **flags)
    return candidate  # a model without such switches: it receives alpha_effective = 0 when piezoviscosity is off


#: the state names the film steps hand a film model themselves
FILM_STATE = ("R", "w", "E_reduced", "u_m", "eta0", "alpha", "lubricant_state", "density_law")


@attrs.frozen
class ModelReads:
    """The state names a model reads beyond those its step hands it: required and optional ones."""

    required: tuple[str, ...]
    optional: tuple[str, ...]


def model_reads(model: Any, supplied: Iterable[str] = FILM_STATE) -> ModelReads:
    """What ``model`` reads (its ``requires`` and ``optional_requires``) beyond the ``supplied`` names, so
    that its step declares them: the plan then gives them, or says up front which one is missing."""
    supplied = set(supplied)
    return ModelReads(tuple(n for n in getattr(model, "requires", ()) if n not in supplied),
                      tuple(n for n in getattr(model, "optional_requires", ()) if n not in supplied))


def model_name(film_model) -> str:
    """The step record's model label of a film model."""
    return getattr(film_model, "name", "film")


def model_version(film_model) -> str:
    return getattr(film_model, "version", "")


# ----------------------------------------------------------------------------- one line contact
@step("ehl_groups", provides=("alpha_effective", "U", "G", "W", "M", "L"))
def ehl_groups(w, R, E_reduced, u_m, eta0, alpha, piezoviscosity):
    """Hamrock's U, G, W and Moes's M, L [-] of a line contact with w [N/m], R [m], E' [Pa], u_m [m/s],
    eta0 [Pa s], alpha [1/Pa]; alpha_effective [1/Pa] = alpha, or 0 without the ``piezoviscosity`` effect.
    InputError when u_m = 0 (no steady film)."""
    alpha = alpha if piezoviscosity else 0.0
    U, G, W = hamrock_line(w, R, E_reduced, u_m, eta0, alpha)
    if U == 0.0:
        raise InputError(
            "line contact: entrainment speed u_m = (u1 + u2)/2 = 0 gives no steady EHL film; "
            "give the bodies' surface speeds"
        )
    M, L = moes_line(U, G, W)
    return {"alpha_effective": alpha, "U": U, "G": G, "W": W, "M": M, "L": L}


@step("film", provides=("h_c_isothermal", "h_min_isothermal", "film_validity", "film_valid", "film_solution"),
      model=model_name,
      version=model_version)
def line_film(film_model, R, w, E_reduced, u_m, eta0, alpha_effective, U, G, W, M, L, lubricant_state, density_law,
              **inputs):
    """The isothermal films [m] of a line contact by ``film_model`` (a model that solves the thermal or
    non-Newtonian film itself gives its isothermal Newtonian films as ``h_c_isothermal``...), the model's validity note
    ("ok", its range warnings named by the model, or the numerical solver's non-convergence), ``film_valid``
    (True where "ok") and its numerical solution
    (``film_solution``, None for a formula); ``inputs``: the further state names the model reads
    (:func:`model_reads`)."""
    state = {**inputs, "R": R, "w": w, "E_reduced": E_reduced, "u_m": u_m, "eta0": eta0, "alpha": alpha_effective,
             "lubricant_state": lubricant_state, "density_law": density_law}
    produced = film_model(state)
    messages = [f"{film_model.name}: {message}"
                for message in film_model.check_validity({"U": U, "G": G, "W": W, "M": M, "L": L} | dict(produced))]
    record = produced.get("convergence")
    if record is not None and not record.converged:
        messages.append(f"numerical solution not converged: {record.message}")
    result = {f"{q}_isothermal": produced.get(f"{q}_isothermal", produced[q]) for q in films_of(film_model)}
    result["film_validity"] = "ok" if not messages else "; ".join(messages)
    result["film_valid"] = not messages
    result["film_solution"] = produced.get("ehl_solution")
    return result


@step("film_thickness", provides=FILMS, model="isothermal")
def isothermal_films(**isothermal):
    """The films [m] without a thermal correction (``h_c_isothermal`` -> ``h_c``, ...)."""
    return {name.removesuffix("_isothermal"): 1.0 * value for name, value in isothermal.items()}


def solves_rheology(film_model: Any) -> bool:
    """Whether ``film_model`` solves the thermal or non-Newtonian film itself (the ``multigrid`` model with
    those switched on by :func:`resolve_film_model`)."""
    return getattr(film_model, "thermal", False) is True or getattr(film_model, "non_newtonian", False) is True


def with_traction_rheology(film_model: Any, traction: Any) -> Any:
    """A film model that solves the thermal / non-Newtonian film (:func:`solves_rheology`) with the rheology of
    the scene's fluid ``traction`` model: its Eyring stress (none: a Newtonian traction model was asked for, the
    film is then Newtonian) and its limiting shear stress, which also bounds a Newtonian film's heat; any other
    model unchanged."""
    if not solves_rheology(film_model):
        return film_model
    eyring = getattr(traction, "eyring_stress", None) if film_model.non_newtonian else None
    return attrs.evolve(film_model, non_newtonian=eyring is not None, eyring_stress=eyring,
                        limiting_shear_stress=getattr(traction, "limiting_shear_stress", 0.0) or 0.0,
                        limiting_shear_slope=getattr(traction, "limiting_shear_slope", None))


@step("film_thickness", provides=FILMS, model="thermal")
def thermal_films(thermal_factor, **isothermal):
    """The films [m] reduced by the inlet shear-heating factor phi_T (``h_c = phi_T h_c_isothermal``, ...)."""
    return {name.removesuffix("_isothermal"): thermal_factor * value for name, value in isothermal.items()}


@step("film_thickness", provides=FILMS, model="numerical")
def solved_films(film_solution):
    """The films [m] of a model that solved the non-Newtonian (or thermal) film itself: those of its solution
    (:class:`camcontact.ehl.line_thermal.ThermalLineSolution`), no formula factor."""
    return {"h_c": film_solution.h_c, "h_min": film_solution.h_min}


@step("film_thickness", provides=(*FILMS, "thermal_factor"), model="numerical thermal")
def solved_thermal_films(film_solution):
    """:func:`solved_films` of a thermal solution, with its numerical thermal factor h_c/h_c,isothermal [-] in
    place of the inlet shear-heating formula's."""
    return solved_films(film_solution) | {"thermal_factor": film_solution.film_reduction}


@step("film_thickness", provides=("h_c_inner", "h_c_outer", "h_min_inner", "h_min_outer", "h_min_bearing"),
      model="thermal")
def roller_thermal_films(thermal_factor, **isothermal):
    """:func:`thermal_films` of a bearing's raceway films (``h_c_inner_isothermal`` -> ``h_c_inner``, ...,
    ``h_min_bearing``): one factor phi_T for all contacts."""
    return thermal_films(thermal_factor, **isothermal)


def check_thermal_data(lubricant) -> None:
    """InputError when the lubricant lacks what the inlet thermal correction needs."""
    if lubricant is None:
        return
    missing = []
    if lubricant.thermal_conductivity is None:
        missing.append("thermal_conductivity")
    if lubricant.temperature_law is None and lubricant.thermoviscous_coefficient is None:
        missing.append("temperature-dependent viscosity data (nu40/nu100 or viscosity_data) or its "
                       "thermoviscous_coefficient")
    if missing:
        raise InputError(f"the 'thermal' effect needs Lubricant {lubricant.name!r} {' and '.join(missing)}")


@step("thermal", provides=("thermal_loading", "thermal_factor"), model="delabenetta_eq44", check=check_thermal_data)
def inlet_thermal_correction(thermoviscous_coefficient, eta0, u1, u2, lubricant_conductivity):
    """Thermal loading L = beta eta0 (u1 + u2)^2 / k [-] (Delabenetta 2021 Eq. 46) and the inlet
    shear-heating factor phi_T of the film (Murch & Wilson 1975 as Delabenetta 2021 Eq. 44 gives it,
    with the slide/roll measure)."""
    L_th = thermal_loading(thermoviscous_coefficient, eta0, u1, u2, lubricant_conductivity)
    return {"thermal_loading": float(L_th), "thermal_factor": inlet_heating_factor(L_th, slide_roll_measure(u1, u2))}


# ----------------------------------------------------------------------------- roughness and Lambda
@step("roughness", provides=("sigma",))
def composite_roughness_step(sigma1, sigma2):
    """Composite RMS roughness sqrt(sigma1^2 + sigma2^2) [m] (Delabenetta 2021 Eq. 29)."""
    return {"sigma": composite_roughness(sigma1, sigma2)}


@step("roughness", provides=("sigma", "roughness_amplitude"),
      model=lambda convention: f"amplitude {convention.roughness_amplitude}")
def raceway_roughness(sigma1, sigma2, convention):
    """Composite RMS roughness sigma [m] (Delabenetta 2021 Eq. 29) and the amplitude [m] of the sinusoid
    that stands for it, by ``convention.roughness_amplitude``:

    * ``"sinusoid"``: sqrt(2) sigma, the amplitude of a sinusoid whose RMS is sigma
      (:func:`camcontact.contact.roughness.sinusoid_amplitude`);
    * ``"thesis"``: sigma / sqrt 2, the thesis's reading (its Eq. 30), half of that; it reproduces
      the thesis's roughness stress 1.59 GPa (Table 7).
    """
    sigma = composite_roughness(sigma1, sigma2)
    if convention.roughness_amplitude == "thesis":
        amplitude = sigma / math.sqrt(2.0)
    else:
        amplitude = sinusoid_amplitude(sigma)
    return {"sigma": sigma, "roughness_amplitude": amplitude}


@step("lambda", provides=("Lambda",))
def film_parameter(h, sigma1, sigma2):
    """Specific film thickness Lambda = h / sqrt(sigma1^2 + sigma2^2) [-] of a film h [m] (a float, or an
    array over angles or rollers); bound per film and scene with ``rename``."""
    return {"Lambda": lambda_ratio(h, sigma1, sigma2)}


@step("regime", provides=("regime",))
def lubrication_regime_step(Lambda):
    """'full film' (Lambda >= 3), 'mixed' (1 < Lambda < 3) or 'boundary' (Lambda <= 1)."""
    return {"regime": lubrication_regime(Lambda)}


# ----------------------------------------------------------------------------- bearing rollers
@step("film", provides=("h_c_inner", "h_c_outer", "h_min_inner", "h_min_outer", "h_min_bearing"),
      model=model_name, version=model_version)
def roller_films(film_model, Q, E_reduced, u_m, eta0, alpha, piezoviscosity, lubricant_state, density_law,
                 contact_radii, contact_length_inner, contact_length_outer):
    """Films [m] at the inner and outer raceway of every loaded roller (w = Q / l over each contact's length l [m]:
    l_we for an ideal line, the loaded laminae of a profiled or conformal one), NaN for unloaded
    ones, and the thinnest film of the bearing (h_min, or h_c for a model without h_min)."""
    films = films_of(film_model)
    alpha = alpha if piezoviscosity else 0.0
    out = {f"{q}_{race}": np.full(Q.size, np.nan) for q in films for race in RACES}
    if u_m <= 0.0:
        raise InputError("bearing scene: the rings do not turn relative to each other (speed = outer_speed): "
                         "no entrainment, no steady film")
    lengths = {"inner": contact_length_inner, "outer": contact_length_outer}
    for j in np.flatnonzero(Q > 0.0):
        for race in RACES:
            state = {"R": contact_radii[race], "w": Q[j] / lengths[race][j], "E_reduced": E_reduced, "u_m": u_m,
                     "eta0": eta0, "alpha": alpha, "lubricant_state": lubricant_state, "density_law": density_law}
            produced = film_model(state)
            for q in films:
                out[f"{q}_{race}"][j] = produced[q]
    basis = "h_min" if "h_min" in films else "h_c"
    values = np.concatenate([out[f"{basis}_{race}"] for race in RACES])
    out["h_min_bearing"] = float(np.nanmin(values)) if np.any(np.isfinite(values)) else float("nan")
    return out


def raceway_lambda_steps(basis: str) -> list:
    """The steps ``lambda_inner`` and ``lambda_outer`` of a bearing scene: :func:`film_parameter` of the film
    ``<basis>_<race>`` (h_min or h_c) with the bearing's roughness ``sigma`` on both surfaces, as ``Lambda_<race>``."""
    return [Step.of(film_parameter, name=f"lambda_{race}", rename={"h": f"{basis}_{race}", "sigma1": "sigma",
                                                                  "sigma2": "sigma", "Lambda": f"Lambda_{race}"})
            for race in RACES]


@step("lubrication", provides=("contact_regime", "Lambda_bearing"))
def bearing_lubrication(Q, Lambda_inner, Lambda_outer):
    """Per roller the regime of its thinner contact ("unloaded" without load) and the bearing's
    smallest Lambda [-]."""
    regimes = [lubrication_regime(min(Lambda_inner[j], Lambda_outer[j])) if Q[j] > 0.0 else "unloaded"
               for j in range(Q.size)]
    finite = np.concatenate([Lambda_inner, Lambda_outer])
    return {"contact_regime": np.array(regimes, dtype=object),
            "Lambda_bearing": float(np.nanmin(finite)) if np.any(np.isfinite(finite)) else float("nan")}


# ----------------------------------------------------------------------------- ball-cone contacts
@step("film", provides=("h_c_in", "h_min_in", "h_c_out", "h_min_out", "pressure_field_in", "pressure_field_out"),
      model=model_name, version=model_version)
def ball_cone_films(film_model, Rx, Ry, normal_force, E_reduced, rolling_speed_in, rolling_speed_out, eta0, alpha,
                    piezoviscosity, lubricant_state, density_law):
    """Central and minimum films [m] at the CVT's input and output contact (those the point film model gives)
    and, where the model is the numerical solver, its pressure and film over the grid
    (``pressure_field_in``/``_out``, a :class:`~camcontact.contact.spin_traction.PressureField`; None for a
    formula, and with a ConvergenceWarning for a solution that did not converge)."""
    out = {}
    for side, speed in (("in", rolling_speed_in), ("out", rolling_speed_out)):
        produced = film_model({"Rx": Rx, "Ry": Ry, "F": normal_force, "E_reduced": E_reduced, "u_m": speed,
                               "eta0": eta0, "alpha": alpha if piezoviscosity else 0.0,
                               "lubricant_state": lubricant_state, "density_law": density_law})
        solution = produced.get("ehl_solution")
        field = None
        if solution is not None and solution.record.converged:
            values = solution.dimensional(Rx, normal_force, E_reduced)
            field = PressureField(values["x"], values["y"], values["p"], values["h"])
        elif solution is not None:
            warnings.warn(f"ball-cone {side}put contact: the numerical film did not converge; its pressure is not "
                          "passed on (the EHL traction falls back to the Hertz pressure, traction_valid False)",
                          ConvergenceWarning, stacklevel=2)
        out[f"pressure_field_{side}"] = field
        out.update({f"{q}_{side}": float(produced[q]) for q in films_of(film_model)})
    return out


# ----------------------------------------------------------------------------- one point contact
@step("film", provides=("h_c_isothermal", "h_min_isothermal", "film_validity", "film_valid", "film_solution"),
      model=model_name, version=model_version)
def point_film(film_model, Rx, Ry, F, E_reduced, u_m, eta0, alpha, piezoviscosity, lubricant_state, density_law):
    """The isothermal films [m] of a point contact by a point ``film_model`` (Hamrock–Dowson, Nijenbanning or
    the numerical ``multigrid_point``) with reduced radii Rx, Ry [m], load F [N], E' [Pa], u_m [m/s],
    eta0 [Pa s] and alpha [1/Pa] (0 without ``piezoviscosity``); the validity note ("ok", the model's range
    warnings named by it, or the numerical solver's non-convergence), ``film_valid`` and the numerical
    solution (``film_solution``, None for a formula). Only the films the model gives (the scene binds
    the step to them)."""
    produced = film_model({"Rx": Rx, "Ry": Ry, "F": F, "E_reduced": E_reduced, "u_m": u_m, "eta0": eta0,
                           "alpha": alpha if piezoviscosity else 0.0, "lubricant_state": lubricant_state,
                           "density_law": density_law})
    messages = [f"{film_model.name}: {message}" for message in film_model.check_validity(dict(produced))]
    record = produced.get("convergence")
    if record is not None and not record.converged:
        messages.append(f"numerical solution not converged: {record.message}")
    result = {f"{q}_isothermal": float(produced[q]) for q in films_of(film_model)}
    result["film_validity"] = "ok" if not messages else "; ".join(messages)
    result["film_valid"] = not messages
    result["film_solution"] = produced.get("ehl_solution")
    return result
