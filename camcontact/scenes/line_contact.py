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

import attrs
import numpy as np

from .. import registry
from ..analysis import SceneGraph, Step, checked_request, scene_builder
from ..components.line_contact import LineContact
from ..contact.geometry import reduced_modulus, reduced_radius
from ..contact.hertz_line import hertz_line, line_approach
from ..contact.roughness import composite_roughness, lambda_ratio, lubrication_regime
from ..contact.subsurface import line_subsurface
from ..ehl.groups import hamrock_line, moes_line
from ..errors import InputError
from ..models.base import FilmModel
from ..models.film_line import LINE_INPUTS
from ..models.film_thermal import inlet_heating_factor, slide_roll_measure, thermal_loading

__all__ = ["DEFAULT_EFFECTS", "SUPPORTED_EFFECTS", "build_line_contact"]

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


def _film_model(spec: Any, effects: frozenset) -> FilmModel:
    """Resolve the film model with the scene's switched-off effects, or explain why not."""
    candidate = registry.get("film_models", spec, requires=LINE_INPUTS, provides=getattr(spec, "provides", ("h_c", "h_min")))
    if getattr(candidate, "geometry", "line") != "line":
        raise InputError(
            f"film model {candidate.name!r} is for {candidate.geometry} contacts; a line contact needs a line model"
        )
    switched_off = sorted({"piezoviscosity", "elasticity"} - effects)
    if not switched_off:
        return candidate
    cannot = [e for e in switched_off if e not in getattr(candidate, "can_disable", ())]
    if cannot:
        able = [
            n for n in registry.available("film_models")
            if getattr(registry.get_class("film_models", n), "geometry", "") == "line"
            and set(switched_off) <= set(getattr(registry.get_class("film_models", n), "can_disable", ()))
        ]
        raise InputError(
            f"film model {candidate.name!r} cannot represent a scene without {', '.join(cannot)}; "
            f"line models that can: {', '.join(able) or '(none)'}"
        )
    flags = {effect: False for effect in switched_off}
    if isinstance(spec, str):
        return registry.get("film_models", spec, **flags)
    if attrs.has(type(candidate)):
        return registry.get("film_models", candidate, **flags)
    return candidate  # a model without such switches: it receives alpha_effective = 0 when piezoviscosity is off


@scene_builder(LineContact)
def build_line_contact(contact: LineContact, *, models: Mapping[str, Any], effects: frozenset | None) -> SceneGraph:
    """Scene graph of a :class:`~camcontact.components.LineContact` (one variant)."""
    effects = checked_request("line_contact", models, effects, slots=("film", "approach"),
                              supported=SUPPORTED_EFFECTS, default=DEFAULT_EFFECTS)
    piezo = "piezoviscosity" in effects
    b1, b2 = contact.body1, contact.body2
    inputs: dict[str, Any] = {
        "E1": b1.material.si.E, "nu1": b1.material.nu, "E2": b2.material.si.E, "nu2": b2.material.nu,
        "R1": b1.signed_radius, "R2": b2.signed_radius, "u1": b1.si.speed, "u2": b2.si.speed,
        "w": contact.w, "friction_coefficient": contact.friction_coefficient,
    }
    if contact.load is not None:
        inputs["F"] = contact.si.load
    if contact.length is not None:
        inputs["length"] = contact.si.length
    if b1.roughness is not None:
        inputs["sigma1"] = b1.si.roughness
    if b2.roughness is not None:
        inputs["sigma2"] = b2.si.roughness
    lubricant = contact.lubricant
    if lubricant is not None:
        inputs["lubricant"] = lubricant
    if contact.temperature is not None:
        inputs["temperature"] = contact.si.temperature

    steps = [
        Step("geometry", ("E1", "nu1", "E2", "nu2", "R1", "R2"), ("E_reduced", "R"),
             lambda s: {"E_reduced": reduced_modulus(s["E1"], s["nu1"], s["E2"], s["nu2"]),
                        "R": reduced_radius(s["R1"], s["R2"])}),
        Step("kinematics", ("u1", "u2"), ("u_m", "u_s", "slide_roll_ratio"), _kinematics),
        Step("hertz", ("w", "R", "E_reduced"), ("b", "p_h", "p_mean"), _hertz, model="hertz_line"),
        _approach_step(models.get("approach", "hamrock")),
        Step("subsurface", ("b", "p_h", "nu1", "friction_coefficient"),
             ("tau_max", "x_tau_max", "z_tau_max", "tresca_max", "z_tresca_max", "von_mises_max",
              "z_von_mises_max", "tau_xz_max", "x_tau_xz_max", "z_tau_xz_max", "tau_xz_range"),
             _subsurface, model="mcewen_line"),
        Step("roughness", ("sigma1", "sigma2"), ("sigma",),
             lambda s: {"sigma": composite_roughness(s["sigma1"], s["sigma2"])}),
    ]
    steps += _film_steps(contact, models.get("film", DEFAULT_FILM), effects, piezo)
    return SceneGraph(
        kind="line_contact", inputs=inputs, steps=tuple(steps), default_outputs=DEFAULT_OUTPUTS,
        input_hints=HINTS, plotter=plot_line_contact, effects=effects,
    )


def _kinematics(s):
    u_m = 0.5 * (s["u1"] + s["u2"])
    u_s = s["u1"] - s["u2"]
    if u_m != 0:
        ratio = u_s / u_m
    else:  # no entrainment: pure sliding (infinite ratio) or no motion at all (zero)
        ratio = 0.0 if u_s == 0 else float(np.copysign(np.inf, u_s))
    return {"u_m": u_m, "u_s": u_s, "slide_roll_ratio": ratio}


def _hertz(s):
    result = hertz_line(s["w"], s["R"], s["E_reduced"])
    return {"b": result.b, "p_h": result.p_h, "p_mean": result.p_mean}


def _approach_step(method: str) -> Step:
    if method == "hamrock":
        return Step("approach", ("w", "R", "E_reduced"), ("approach",),
                    lambda s: {"approach": line_approach("hamrock", E_reduced=s["E_reduced"], w=s["w"], R=s["R"])},
                    model="hamrock")
    if method == "palmgren":
        return Step("approach", ("F", "length", "E_reduced"), ("approach",),
                    lambda s: {"approach": line_approach("palmgren", E_reduced=s["E_reduced"],
                                                         force=s["F"], length=s["length"])},
                    model="palmgren")
    raise InputError(f"line_contact scene: approach model {method!r} unknown; choose 'hamrock' or 'palmgren'")


def _subsurface(s):
    result = line_subsurface(s["b"], s["p_h"], friction=s["friction_coefficient"], nu=s["nu1"])
    return {
        "tau_max": result.principal_shear_max.value, "x_tau_max": result.principal_shear_max.x,
        "z_tau_max": result.principal_shear_max.z,
        "tresca_max": result.tresca_max.value, "z_tresca_max": result.tresca_max.z,
        "von_mises_max": result.von_mises_max.value, "z_von_mises_max": result.von_mises_max.z,
        "tau_xz_max": result.tau_xz_max.value, "x_tau_xz_max": result.tau_xz_max.x,
        "z_tau_xz_max": result.tau_xz_max.z, "tau_xz_range": result.orthogonal_shear_range,
    }


def lubricant_step(lubricant, effects: frozenset, piezo: bool) -> Step:
    """The step that evaluates the lubricant's state at the scene temperature (shared by the scenes).

    ``lubricant`` may be None: the step then exists and its missing input is reported up front.
    """
    if lubricant is None:
        density_law, lubricant_requires = "incompressible", ("lubricant",)
    else:
        density_law = lubricant.density_law if "compressibility" in effects else "incompressible"
        lubricant_requires = ("lubricant",) if lubricant.isothermal else ("lubricant", "temperature")

    def run_lubricant(s):
        state = s["lubricant"].state(s.get("temperature"))
        return {
            "lubricant_state": state, "eta0": state.eta0, "alpha": state.alpha,
            "roelands_z": state.roelands_z, "kinematic_viscosity": state.kinematic_viscosity,
            "thermoviscous_coefficient": state.thermoviscous_coefficient,
            "lubricant_conductivity": state.thermal_conductivity, "density_law": density_law,
        }

    def check_piezo():
        if piezo and lubricant is not None and lubricant.alpha is None and lubricant.roelands_z is None and lubricant.alpha_correlation is None:
            raise InputError(
                f"Lubricant {lubricant.name!r} has no pressure-viscosity data (alpha or roelands_z), which "
                "the 'piezoviscosity' effect needs; give it or switch the effect off"
            )

    return Step("lubricant", lubricant_requires,
                ("lubricant_state", "eta0", "alpha", "roelands_z", "kinematic_viscosity", "thermoviscous_coefficient",
                 "lubricant_conductivity", "density_law"),
                run_lubricant, check=check_piezo,
                model="" if lubricant is None else f"{lubricant.viscosity_temperature_law}/{lubricant.viscosity_pressure_law}")


def _film_steps(contact: LineContact, film_spec: Any, effects: frozenset, piezo: bool) -> list[Step]:
    lubricant = contact.lubricant

    def run_groups(s):
        alpha = s["alpha"] if piezo else 0.0
        U, G, W = hamrock_line(s["w"], s["R"], s["E_reduced"], s["u_m"], s["eta0"], alpha)
        if U == 0.0:
            raise InputError(
                "line contact: entrainment speed u_m = (u1 + u2)/2 = 0 gives no steady EHL film; "
                "give the bodies' surface speeds"
            )
        M, L = moes_line(U, G, W)
        return {"alpha_effective": alpha, "U": U, "G": G, "W": W, "M": M, "L": L}

    model = _film_model(film_spec, effects)
    films = tuple(q for q in ("h_c", "h_min") if q in model.provides)

    def run_film(s):
        state = {**s, "alpha": s["alpha_effective"]}
        produced = model(state)
        messages = model.check_validity({k: s[k] for k in ("U", "G", "W", "M", "L")} | dict(produced))
        record = produced.get("convergence")
        if record is not None and not record.converged:
            messages.append(f"numerical solution not converged: {record.message}")
        result = {f"{q}_isothermal": produced[q] for q in films}
        result["film_validity"] = "ok" if not messages else "; ".join(messages)
        return result

    thermal = "thermal" in effects

    def check_thermal():
        if lubricant is None:
            return
        missing = []
        if lubricant.thermal_conductivity is None:
            missing.append("thermal_conductivity")
        if lubricant.temperature_law is None:
            missing.append("temperature-dependent viscosity data (nu40/nu100 or viscosity_data)")
        if missing:
            raise InputError(f"the 'thermal' effect needs Lubricant {lubricant.name!r} {' and '.join(missing)}")

    def run_thermal(s):
        L_th = thermal_loading(s["thermoviscous_coefficient"], s["eta0"], s["u1"], s["u2"], s["lubricant_conductivity"])
        return {"thermal_loading": float(L_th),
                "thermal_factor": inlet_heating_factor(L_th, slide_roll_measure(s["u1"], s["u2"]))}

    def run_final(s):
        factor = s["thermal_factor"] if thermal else 1.0
        return {q: factor * s[f"{q}_isothermal"] for q in films}

    def run_lambda(s):
        result = {f"Lambda_{q[2:]}": lambda_ratio(s[q], s["sigma1"], s["sigma2"]) for q in films}
        basis = result.get("Lambda_min", result.get("Lambda_c"))
        result["regime"] = lubrication_regime(basis)
        return result

    model_name = getattr(model, "name", "film")
    steps = [
        lubricant_step(lubricant, effects, piezo),
        Step("ehl_groups", ("w", "R", "E_reduced", "u_m", "eta0", "alpha"),
             ("alpha_effective", "U", "G", "W", "M", "L"), run_groups),
        Step("film", (*LINE_INPUTS[:4], "eta0", "alpha_effective", "U", "G", "W", "M", "L",
                      *(("lubricant_state", "density_law") if "lubricant_state" in model.requires else ())),
             (*(f"{q}_isothermal" for q in films), "film_validity"), run_film,
             model=model_name, version=getattr(model, "version", ""), identity=id(model)),
        Step("film_thickness", (*(f"{q}_isothermal" for q in films), *(("thermal_factor",) if thermal else ())),
             films, run_final, model="thermal" if thermal else "isothermal"),
        Step("lambda", (*films, "sigma1", "sigma2"), (*(f"Lambda_{q[2:]}" for q in films), "regime"), run_lambda),
    ]
    if thermal:
        steps.append(Step("thermal", ("thermoviscous_coefficient", "eta0", "u1", "u2", "lubricant_conductivity"),
                          ("thermal_loading", "thermal_factor"), run_thermal, model="delabenetta_eq44",
                          check=check_thermal))
    return steps


def plot_line_contact(result, *, figsize=(11.0, 3.6)):
    """Three panels: Hertz pressure, stresses along the depth at x = 0, films per model."""
    import matplotlib.pyplot as plt

    row0 = result.rows[0]
    panels = [p for p, need in (("pressure", ("b", "p_h")), ("stress", ("b", "p_h")), ("film", ("h_c",)))
              if all(k in result.outputs for k in need) or (p == "film" and "h_min" in result.outputs)]
    if not panels:
        raise InputError("nothing to plot: ask for b and p_h, or for film outputs")
    fig, axes = plt.subplots(1, len(panels), figsize=figsize, squeeze=False)
    for ax, panel in zip(axes[0], panels):
        if panel == "pressure":
            x = np.linspace(-1.5, 1.5, 301)
            ax.plot(x, row0["p_h"] * 1e-6 * np.sqrt(np.clip(1 - x**2, 0, None)))
            ax.set(xlabel="x / b [-]", ylabel="p [MPa]", title=f"Hertz pressure, b = {row0['b'] * 1e6:.4g} µm")
        elif panel == "stress":
            from ..contact.subsurface import line_contact_stresses

            z = np.linspace(1e-4, 3.0, 300)
            contact = result.scene
            field = line_contact_stresses(np.zeros_like(z), z, 1.0, 1.0,
                                          friction=contact.friction_coefficient, nu=contact.body1.material.nu)
            for key, label in (("principal_shear", "τ₁ (principal shear)"), ("von_mises", "von Mises"),
                               ("tresca", "Tresca")):
                ax.plot(field[key], z, label=label)
            ax.invert_yaxis()
            ax.set(xlabel="stress / p_h [-]", ylabel="z / b [-]", title="stresses below the centre")
            ax.legend(fontsize=8)
        else:
            labels = list(result.variants) if result.variants != ("",) else ["film"]
            positions = np.arange(len(labels))
            for offset, key in ((-0.2, "h_c"), (0.2, "h_min")):
                if key in result.outputs:
                    values = [1e6 * r[key] if r.get(key) is not None else np.nan for r in result.rows]
                    ax.bar(positions + offset, values, width=0.4, label=key)
            ax.set_xticks(positions, labels, rotation=30, ha="right", fontsize=8)
            ax.set(ylabel="film [µm]", title="film thickness")
            ax.legend(fontsize=8)
    fig.tight_layout()
    return fig
