"""The single roller-raceway contact scene: Delabenetta's failure-analysis chain, thesis or corrected.

A :class:`~camcontact.components.RacewayContact` becomes the steps

``geometry``
    E* = E'/2 and R_x = 2R' (Seabra's conventions, Delabenetta Eqs. 1, 3), the raceway convex or
    concave by the convention;
``kinematics``
    surface speeds of the raceway and the roller, entrainment speed and slide/roll V_e (Eqs. 31, 45);
``hertz``
    half-width a, mean and maximum pressure, contact area (Eqs. 2, 4 with pi, as the thesis's code);
``subsurface``
    tau_max and its depth, tau_oct, the orthogonal shear tau_0, its position and range (Eqs. 7, 9, 10,
    or the exact field);
``roughness``
    composite roughness sigma (Eq. 29) and the amplitude A of the sinusoid standing for it: sigma / sqrt 2
    in the thesis's reading (Eq. 30, reproduces its 1.59 GPa), sqrt 2 sigma (a sinusoid of RMS sigma)
    in the corrected convention; the roughness stress 5.172 ((A/lambda)(R_x/a))^0.931 p0 (Eq. 8) and
    Johnson's full-contact pressure p* = pi E* A / lambda of the sinusoid (Johnson 1985 §13.2);
``film``
    lubricant properties at the working temperature (Walther m, n; nu, eta, Gold alpha, beta, k, c;
    Eqs. 32-39), Hamrock U, G, W (Eq. 42), Grubin h0 and Dowson-Higginson h_min (Eqs. 40, 41), the
    inlet-heating, starvation and roughness factors, h_oc and Lambda (Eqs. 43, 44, 46, 13), with the
    thesis's temperature loop where the convention runs it;
``friction``
    Benedict-Kelley mu (Eq. 49) with ``friction_valid`` (True inside the correlation's validity,
    :attr:`camcontact.models.friction.Kelley.validity`); pure rolling lies outside that correlation:
    mu is then NaN with the reason in ``friction_validity`` and there is no frictional heating;
``temperatures``
    flash temperature (Eq. 48), surface maximum (Eq. 47), viscosity at the mean pressure and the
    Couette film rise (App. D), the lubricant's maximum temperature and its check against the
    lubricant's upper service temperature;
``checks``
    the plastic-deformation and fatigue rules of the thesis's §4.1 (or Tresca).

Model slots: ``convention``: ``"thesis"`` (default), ``"corrected"`` or a
:class:`~camcontact.scenes.raceway_conventions.RacewayConvention`; a list runs them side by side
(one row each). ``traction``: the fluid's rheology of the EHL friction (a ``traction_models`` name or
model; default ``"eyring"`` with ``non_newtonian``, else ``"newtonian"``, both bounded by the limiting
shear stress: :func:`camcontact.steps.ehl_friction.fluid_traction_model`).

Effects (none by default: the chain is the thesis's): ``non_newtonian`` and ``mixed`` replace the
Benedict–Kelley correlation by the EHL friction of the film (as the line-contact scene:
:func:`camcontact.steps.ehl_friction.contact_ehl_friction` at the sliding speed u_raceway - u_roller, over
the Hertz pressure with the corrected central film h_oc, the lubricant at the chain's working temperature);
``mixed`` adds Greenwood–Tripp asperity load sharing on h_oc (the asperities' share, the film at the
fluid's share, the lubrication regime, the boundary friction of the asperities; without ``non_newtonian`` the
fluid is Newtonian up to the limiting shear stress); the flash temperature (Eq. 48, and so the surface
maximum) then follows the EHL friction coefficient, while the Couette film rise stays the chain's (Newtonian at
the mean pressure, App. D). ``thermal`` makes the traction thermal (its contact temperature rise; needs
``non_newtonian`` or ``mixed``: the chain always applies its inlet-heating factor, Eq. 44). ``mixed`` needs
rough surfaces (a composite sigma > 0). Source: ../shared/reference/spherical_roller_bearing_delabenetta2021.md.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from ..components.raceway_contact import RacewayContact
from ..errors import InputError
from ..step_graph import SceneGraph, Step, checked_request, given, scene_builder
from ..steps.contact import force_hertz, raceway_geometry
from ..steps.ehl_friction import (EHL_EFFECTS, MIXED_FRICTION_READS, contact_ehl_friction, ehl_friction_inputs,
                                  fluid_traction_model, mixed_contact)
from ..steps.film import raceway_roughness
from ..steps.friction import raceway_kelley_friction
from ..steps.kinematics import given_raceway_speeds, pure_rolling_raceway, raceway_sliding_speed
from ..steps.raceway_film import raceway_film_chain, raceway_lubricant_state, thesis_temperature_loop
from ..steps.stress import (
    raceway_checks,
    raceway_subsurface,
    roughness_full_contact_pressure,
    roughness_stress,
    roughness_stress_step,
)
from ..steps.temperature import raceway_temperatures
from .raceway_contact_plots import plot_raceway_contact
from .raceway_conventions import resolve_convention

# roughness_stress and thesis_temperature_loop stay importable here: the scene's public functions
__all__ = ["SUPPORTED_EFFECTS", "build_raceway_contact", "raceway_contact_inputs", "roughness_stress",
           "thesis_temperature_loop"]

SUPPORTED_EFFECTS = frozenset({"mixed", "non_newtonian", "thermal"})

DEFAULT_OUTPUTS = (
    # Table 7 (Hertz, stresses)
    "E_star", "R_x", "b", "contact_area", "p_mean", "p_h", "tau_max", "z_tau_max", "tau_oct_max", "tau_roughness",
    "roughness_amplitude", "p_full_contact_roughness", "tau_xz_max", "x_tau_xz_max", "z_tau_xz_max", "tau_xz_range",
    # Table 5 (lubricant at the working temperature)
    "temperature", "walther_n", "walther_m", "kinematic_viscosity", "eta0", "alpha", "roelands_z",
    "thermoviscous_coefficient", "lubricant_conductivity", "lubricant_specific_heat",
    # kinematics, Table 8 (film, friction, temperatures)
    "u_raceway", "u_roller", "slide_roll_measure", "speed_basis", "h_c", "h_min", "thermal_loading",
    "thermal_factor", "starvation_factor", "roughness_factor", "h_c_corrected", "Lambda_oc", "regime",
    "film_validity", "friction_coefficient", "friction_valid", "friction_validity", "flash_temperature",
    "surface_temperature_max", "viscosity_at_mean_pressure", "film_temperature_rise", "lubricant_temperature_max",
    "lubricant_temperature_check", "yield_check", "fatigue_check",
)
#: the outputs the EHL friction effects add (``friction_coefficient`` and ``friction_valid`` then come from them)
EHL_OUTPUTS = ("friction_per_length", "friction_power_per_length", "fluid_traction_coefficient", "traction_regime",
               "traction_temperature_rise")
MIXED_OUTPUTS = ("asperity_load_fraction", "h_c_mixed", "Lambda_mixed", "lubrication_regime", "mixed_valid")
#: the EHL friction step under the chain's names: its film is the corrected h_oc, its coefficient the scene's
EHL_NAMES = {"h_c": "h_c_corrected", "traction_coefficient": "friction_coefficient", "traction_valid": "friction_valid"}
HINTS = {
    "effusivity": "give density, specific_heat and thermal_conductivity of both materials (flash temperature)",
    "yield_strength": "give RacewayContact.raceway_material.yield_strength",
    "roughness_wavelength": "give RacewayContact.roughness_wavelength (roughness stress)",
    "roller_speed": "give RacewayContact.roller_speed (this convention does not derive the rolling speed)",
    "asperity_density": "give RacewayContact.asperity_density and asperity_radius",
}


def raceway_contact_inputs(contact: RacewayContact) -> dict[str, Any]:
    """The graph inputs of a roller-raceway contact (SI; ring and roller speeds in rev/s)."""
    si = contact.si
    m1, m2 = contact.raceway_material, contact.roller_material
    inputs = {
        "E1": m1.si.E, "nu1": m1.nu, "E2": m2.si.E, "nu2": m2.nu, "F": si.load, "length": si.length,
        "R1": si.raceway_radius, "R2": si.roller_radius, "ring_speed": si.ring_speed / (2 * math.pi),
        "sigma1": si.raceway_roughness, "sigma2": si.roller_roughness, "lubricant": contact.lubricant,
        "temperature_start": si.temperature, "lambda_min": contact.lambda_min,
        "slide_roll_ratio": contact.slide_roll_ratio, "pitch_diameter": contact.pitch_diameter,
        "gamma": 2.0 * si.roller_radius / contact.pitch_diameter,
        "upper_temperature": contact.lubricant.si.upper_temperature,
    } | given(roller_speed=None if si.roller_speed is None else si.roller_speed / (2 * math.pi),
              roughness_wavelength=si.roughness_wavelength, yield_strength=m1.si.yield_strength)
    try:
        inputs["effusivity"] = (m1.thermal_effusivity(), m2.thermal_effusivity())
    except InputError:
        pass  # only the temperatures need it: reported up front if they are asked for
    return inputs


def check_friction_request(contact: RacewayContact, models: Mapping[str, Any], effects: frozenset) -> None:
    """InputError for a friction request the scene cannot honour: ``thermal`` or a ``traction`` model without
    the EHL friction (``non_newtonian`` / ``mixed``), ``mixed`` on smooth surfaces."""
    ehl = bool(effects & EHL_EFFECTS)
    if "thermal" in effects and not ehl:
        raise InputError("raceway_contact scene: the 'thermal' effect makes the EHL friction's traction thermal and "
                         "needs 'non_newtonian' or 'mixed' with it (the chain always applies its inlet-heating "
                         "factor, Delabenetta Eq. 44)")
    if "traction" in models and not ehl:
        raise InputError(f"raceway_contact scene: model slot traction = {models['traction']!r} is the fluid of the EHL "
                         "friction; switch it on with effects 'non_newtonian' or 'mixed' (the chain's own friction "
                         "is Benedict-Kelley)")
    if "mixed" in effects and contact.si.raceway_roughness == 0.0 and contact.si.roller_roughness == 0.0:
        raise InputError("raceway_contact scene: the 'mixed' effect needs rough surfaces; RacewayContact."
                         "raceway_roughness and roller_roughness are both 0 (allowed: a composite RMS > 0)")


def friction_steps(effects: frozenset, thermal_traction: bool) -> list[Step]:
    """The friction of the contact: Benedict–Kelley (Eq. 49, the thesis's), or with ``non_newtonian`` /
    ``mixed`` the EHL friction of the film (and the asperity load sharing)."""
    if not effects & EHL_EFFECTS:
        return [Step.of(raceway_kelley_friction)]
    reads = (MIXED_FRICTION_READS if "mixed" in effects else ()) + (("effusivity",) if thermal_traction else ())
    mixed = [Step.of(mixed_contact, rename={"alpha_effective": "alpha", "h_c": "h_c_corrected"})]
    return [Step.of(raceway_sliding_speed), Step.of(raceway_lubricant_state),
            *(mixed if "mixed" in effects else []), Step.of(contact_ehl_friction, rename=EHL_NAMES, extra=reads)]


def default_outputs(effects: frozenset) -> tuple[str, ...]:
    """The thesis's tables, with the EHL friction's outputs in place of Kelley's validity text."""
    if not effects & EHL_EFFECTS:
        return DEFAULT_OUTPUTS
    added = EHL_OUTPUTS + (MIXED_OUTPUTS if "mixed" in effects else ())
    return tuple(q for q in DEFAULT_OUTPUTS if q != "friction_validity") + added


@scene_builder(RacewayContact)
def build_raceway_contact(contact: RacewayContact, *, models: Mapping[str, Any],
                          effects: frozenset | None) -> SceneGraph:
    """Scene graph of a :class:`~camcontact.components.RacewayContact` (one variant)."""
    effects = checked_request("raceway_contact", models, effects, slots=("convention", "traction"),
                              supported=SUPPORTED_EFFECTS, default=())
    convention = resolve_convention(models.get("convention", "thesis"))
    ehl = bool(effects & EHL_EFFECTS)
    check_friction_request(contact, models, effects)
    traction = fluid_traction_model(contact.lubricant, effects, models.get("traction")) if ehl else None
    steps = [
        Step.of(raceway_geometry),
        Step.of(pure_rolling_raceway if convention.derive_rolling_speed else given_raceway_speeds),
        Step.of(force_hertz), Step.of(raceway_subsurface), Step.of(raceway_roughness), Step.of(roughness_stress_step),
        Step.of(roughness_full_contact_pressure),
        Step.of(raceway_film_chain), *friction_steps(effects, ehl and traction.thermal), Step.of(raceway_temperatures),
        Step.of(raceway_checks),
    ]
    concave = contact.raceway == "outer" and not convention.convex_raceway
    friction = ehl_friction_inputs(contact.lubricant, (contact.raceway_material, contact.roller_material),
                                   (contact.si.raceway_roughness, contact.si.roller_roughness), effects,
                                   asperity_density=contact.si.asperity_density,
                                   asperity_radius=contact.si.asperity_radius) if ehl else {}
    inputs = {**raceway_contact_inputs(contact), "convention": convention, "concave": concave,
              **({"piezoviscosity": True, "traction_model": traction, **friction} if ehl else {})}
    asked = default_outputs(effects)
    return SceneGraph(kind="raceway_contact", inputs=inputs, steps=tuple(steps), default_outputs=asked,
                      input_hints=HINTS, plotter=plot_raceway_contact, effects=effects,
                      effect_outputs=frozenset(asked) - frozenset(DEFAULT_OUTPUTS))
