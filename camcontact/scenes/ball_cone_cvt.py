"""The ball-cone CVT scene: ratio and spin, forces, Hertz, film, traction with spin, stresses and life.

A :class:`~camcontact.components.LoadedBallConeCVT` becomes the steps

``kinematics``
    ball tilt for the ratio, rolling radii BC and DE, ball and output speeds, rolling speeds, the
    thesis's spin coefficients psi and the spin creepages psi/R_cont (Saccheto 2008 Eqs. 5.55-5.57,
    6.1-6.3; :mod:`camcontact.kinematics.ball_cone`);
``loads``
    torque, loading-cam force, normal and tangential force per contact, mu_min and the check of the
    needed traction against the fluid's Ct (Eqs. 6.11-6.19; :mod:`camcontact.dynamics.ball_cone_loads`);
``hertz``
    the ball-cone contact (same at both cones: ball radius r against the cone's track, whose
    rolling-direction curvature is cos(alpha)/R_cont and which is straight along its generator) by
    exact elliptic integrals or the thesis's m, n table (model slot ``hertz``);
``film``
    the EHL film of each contact by a point-contact film model (slot ``film``, default
    ``"hamrock_dowson"``; ``"multigrid"`` is the numerical point-contact solution), pure rolling at
    the rolling speed; Lambda with the roughness;
``mixed`` (the ``mixed`` effect)
    Greenwood–Tripp asperity load sharing at each contact on its film (Johnson, Greenwood & Poon 1972,
    :func:`camcontact.steps.ehl_friction.ball_cone_mixed`): the asperities' share of the normal force, the
    film at the fluid's share, Lambda of it, the regime and ``mixed_valid``; the EHL traction then shears
    the film at the fluid's share and adds the asperities' Coulomb friction (the lubricant's
    ``boundary_friction``) along the local sliding. Needs the ``ehl_traction`` model and a film formula;
    asperity parameters ``BallConeCVT.asperity_density``/``asperity_radius`` (defaults: orders of magnitude);
``traction``
    the creepage that transmits F_t at each contact with its spin, the capacity and margin, gross
    slip (boolean), the spin moment and the creep and spin losses (:mod:`camcontact.steps.traction`).
    Model slot ``traction``: ``"ehl_traction"`` (default) — the EHL film's shear over the Hertz
    ellipse with the local sliding of creep and spin (Eyring bounded by the limiting shear stress,
    the lubricant's parameters; ``thermal`` effect: the lumped contact temperature), on each
    contact's central film; or ``"fastsim"`` — Kalker's dry creep theory with the Coulomb bound
    Ct p (Saccheto's method; its slip share of the area; ``Fastsim(pressure="hertz")`` is the
    thesis's reading);
``traction_curve`` (only when asked for: ``traction_curve_in``/``_out`` or the plot's ``"traction"`` panel)
    each contact's traction coefficient |F_x|/N against its creepage, with its spin and without, the
    operating point and the capacity on it (:mod:`camcontact.steps.traction_curve`);
``losses``
    the drive's contact power loss n (P_in + P_out) and efficiency 1 - loss/power;
``stresses``
    the thesis's 2-D slice along the rolling direction through the contact centre: Hertz pressure
    and the traction model's traction of the central strip -> tau0 and its depth z0 (slot ``stress``:
    ``"orthogonal"``, Lundberg-Palmgren's shear, the default, or ``"max_shear"``, the thesis's Mohr radius);
``life``
    Lundberg-Palmgren after Coy & Loewenthal (Eqs. 5.16-5.25) per track: the input and output cone
    (track R_cont, n stress cycles per revolution) and one ball's input and output track (BC, DE; one
    cycle per ball revolution), in seconds; the system L10 combines the two cones and the n balls'
    tracks (Eq. 5.20). The ball-"batente" contact is left out: the thesis gives no geometry for it.

Only the steps the requested outputs need run. Reference: ../shared/reference/ball_cone_cvt_saccheto2008.md.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from .. import registry
from ..components.ball_cone_cvt import LoadedBallConeCVT
from ..contact.geometry import reduced_modulus
from ..contact.hertz_elliptical import METHODS as HERTZ_METHODS
from ..contact.slice_stress import MEASURES
from ..errors import InputError
from ..units import format_quantity
from ..models.film_multigrid_point import MultigridPoint
from ..models.life_lundberg_palmgren import LundbergPalmgren
from ..models.traction import Fastsim
from ..models.traction_spin import EhlTraction
from ..step_graph import SceneGraph, Step, checked_request, given, scene_builder
from ..steps.contact import ball_cone_hertz
from ..steps.film import ball_cone_films, film_parameter, films_of, resolve_film_model
from ..steps.forces import ball_cone_contact_forces
from ..steps.kinematics import ball_cone_motion
from ..steps.life import ball_cone_life
from ..steps.lubricant import lubricant_inputs, lubricant_step
from ..steps.stress import ball_cone_slice_stresses
from ..steps.ehl_friction import BALL_CONE_MIXED_OUTPUTS, ball_cone_mixed, ehl_friction_inputs, fluid_traction_model
from ..steps.traction import ball_cone_efficiency, ball_cone_ehl_traction, ball_cone_traction
from ..steps.traction_curve import ball_cone_ehl_traction_curve, ball_cone_traction_curve
from .ball_cone_cvt_plots import plot_ball_cone_cvt

__all__ = ["SIDES", "ball_cone_cvt_inputs", "build_ball_cone_cvt"]

SIDES = ("in", "out")
SLOTS = ("hertz", "film", "traction", "stress", "life")
SUPPORTED_EFFECTS = frozenset({"elasticity", "piezoviscosity", "spin", "thermal", "mixed"})
DEFAULT_EFFECTS = frozenset({"elasticity", "piezoviscosity", "spin"})
#: the traction models the slot takes
TRACTION_MODELS = (EhlTraction, Fastsim)
DEFAULT_OUTPUTS = (
    "tilt", "reduction_ratio", "overrange", "output_speed", "ball_speed", "rolling_radius_in", "rolling_radius_out",
    "rolling_speed_in", "rolling_speed_out", "psi_in", "psi_out", "psi_total", "spin_in", "spin_out",
    "spin_roll_in", "spin_roll_out",
    "torque", "output_torque", "cam_axial_force", "normal_force", "tangential_force_in", "tangential_force_out",
    "traction_needed_in", "traction_needed_out", "mu_min", "traction_check", "traction_sufficient",
    "Rx", "Ry", "a_rolling", "a_transverse", "p_h", "approach", "pressure_check", "stress_limit_exceeded",
    "h_c_in", "h_min_in", "h_c_out", "h_min_out", "Lambda_in", "Lambda_out", "viscosity_extrapolated",
    "creepage_in", "creepage_out", "traction_regime_in", "traction_regime_out", "gross_slip_in", "gross_slip_out",
    "traction_capacity_in", "traction_capacity_out", "traction_margin_in", "traction_margin_out",
    "spin_moment_in", "spin_moment_out", "creep_loss_in", "creep_loss_out", "spin_loss_in", "spin_loss_out",
    "power_loss_in", "power_loss_out", "power_loss", "efficiency", "tau0_in", "z0_in", "tau0_out", "z0_out",
    "cycles_cone_in", "cycles_ball_in", "cycles_ball_out", "cycles_cone_out",
    "life_cone_in", "life_ball_in", "life_ball_out", "life_cone_out", "life_system",
)
#: the default outputs only one traction model gives
MODEL_OUTPUTS = {Fastsim: ("slip_fraction_in", "slip_fraction_out"),
                 EhlTraction: ("traction_temperature_rise_in", "traction_temperature_rise_out", "traction_valid_in",
                               "traction_valid_out")}
HINTS = {
    "lubricant": "set BallConeCVT.lubricant (the traction fluid's viscosity data)",
    "temperature": "set LoadedBallConeCVT.temperature",
    "sigma": "set BallConeCVT.roughness (RMS of each surface)",
    "effusivity": "give the CVT's Material its thermal data (conductivity, density, specific heat) for the "
                  "thermal traction",
    "asperity_density": "give BallConeCVT.asperity_density and asperity_radius",
}
#: what the EHL traction reads from the mixed step and the lubricant with ``mixed``
MIXED_TRACTION_READS = (*(f"{q}_{side}" for q in ("asperity_load_fraction", "h_c_mixed") for side in SIDES),
                        "boundary_friction")


def ball_cone_cvt_inputs(scene: LoadedBallConeCVT, effects: frozenset) -> dict[str, Any]:
    """The graph inputs of a ball-cone CVT operating point (SI): power, speed, ratio, geometry, material,
    loading cam, traction fluid and switches."""
    cvt = scene.cvt
    si, material = cvt.si, cvt.material
    return {
        "cvt": cvt, "power": scene.si.power, "input_speed": scene.si.input_speed, "ratio": scene.ratio,
        "E_reduced": reduced_modulus(material.si.E, material.nu, material.si.E, material.nu),
        "shear_modulus": material.si.E / (2.0 * (1.0 + material.nu)), "nu": material.nu,
        "traction_coefficient": cvt.traction_coefficient, "ball_radius": cvt.ball_radius, "ball_count": cvt.ball_count,
        "cone_angle": si.cone_angle, "cone_contact_radius": si.cone_contact_radius, "cam_ramp_angle": si.cam_ramp_angle,
        "cam_radius": si.cam_radius, "cam_ball_count": cvt.cam_ball_count, "clamping": cvt.clamping,
        "contact_stress_limit": si.contact_stress_limit,
        "piezoviscosity": "piezoviscosity" in effects, "compressibility": False, "spin": "spin" in effects,
        **lubricant_inputs(cvt.lubricant, scene.si.temperature),
    } | given(sigma=si.roughness, effusivity=_effusivity(material))


def _effusivity(material):
    """The balls' and cones' thermal effusivity [W s^0.5/(m^2 K)], or None without thermal data."""
    try:
        return material.thermal_effusivity()
    except InputError:
        return None


def slot_models(models: Mapping[str, Any]) -> dict[str, Any]:
    """The models of the slots as graph inputs, checked (InputError naming the slot and what is allowed)."""
    chosen = {"hertz_method": models.get("hertz", "exact"), "stress_measure": models.get("stress", "orthogonal")}
    for slot, value, allowed in (("hertz", chosen["hertz_method"], HERTZ_METHODS),
                                 ("stress", chosen["stress_measure"], MEASURES)):
        if value not in allowed:
            raise InputError(f"ball_cone_cvt scene: {slot} = {value!r}; allowed: {', '.join(allowed)}")
    for slot, family, classes, default in (("traction", "traction_models", TRACTION_MODELS, "ehl_traction"),
                                           ("life", "life_models", (LundbergPalmgren,), "lundberg_palmgren")):
        spec = models.get(slot, default)
        kind = registry.get_class(family, spec) if isinstance(spec, str) else spec
        names = " or ".join(cls.__name__ for cls in classes)  # "EhlTraction or Fastsim"
        if isinstance(kind, type) and not issubclass(kind, classes):
            raise InputError(f"ball_cone_cvt scene: the {family} slot needs a {names} model, got {spec!r}")
        model = registry.get(family, spec)
        if not isinstance(model, classes):
            raise InputError(f"ball_cone_cvt scene: the {family} slot needs a {names} model, got {model!r}")
        chosen[f"{slot}_model"] = model
    return chosen


def mixed_inputs(scene: LoadedBallConeCVT, effects: frozenset, traction: Any, film_model: Any) -> dict[str, Any]:
    """The boundary friction and asperity parameters of the ``mixed`` effect ({} without it), or an InputError
    for what it cannot honour: a dry-contact traction model (FASTSIM has no film to share the load with), the
    numerical film (its pressure is the smooth surfaces' of the whole load), smooth surfaces."""
    if "mixed" not in effects:
        return {}
    cvt = scene.cvt
    if not isinstance(traction, EhlTraction):
        raise InputError(f"ball_cone_cvt scene: the 'mixed' effect shares the load between the film and the asperities "
                         f"and needs the traction model 'ehl_traction', got {traction!r} (FASTSIM is a dry contact "
                         "theory with a Coulomb bound)")
    if isinstance(film_model, MultigridPoint):
        raise InputError("ball_cone_cvt scene: the 'mixed' effect needs a film formula (film = 'hamrock_dowson' or "
                         "'nijenbanning'); the numerical point film is of smooth surfaces under the whole load")
    if cvt.roughness is not None and cvt.si.roughness == 0.0:
        raise InputError(f"ball_cone_cvt scene: the 'mixed' effect needs rough surfaces; BallConeCVT {cvt.name!r}"
                         f".roughness = {format_quantity(cvt.roughness)} (allowed: > 0)")
    roughness = None if cvt.roughness is None else cvt.si.roughness
    return ehl_friction_inputs(cvt.lubricant, (), (roughness, roughness), effects,
                               asperity_density=cvt.si.asperity_density, asperity_radius=cvt.si.asperity_radius)


@scene_builder(LoadedBallConeCVT)
def build_ball_cone_cvt(scene: LoadedBallConeCVT, *, models: Mapping[str, Any],
                        effects: frozenset | None) -> SceneGraph:
    """Scene graph of a :class:`~camcontact.components.LoadedBallConeCVT` (one variant)."""
    effects = checked_request("ball_cone_cvt", models, effects, slots=SLOTS, supported=SUPPORTED_EFFECTS,
                              default=DEFAULT_EFFECTS)
    chosen = slot_models(models)
    film_model = resolve_film_model(models.get("film", "hamrock_dowson"), geometry="point",
                                    where="ball_cone_cvt scene: ", contact="the ball-cone contact")
    traction = chosen["traction_model"]
    ehl = isinstance(traction, EhlTraction)
    # what the EHL traction (and its curve) read beside the contact: the numerical film's pressure, the
    # surfaces' effusivity for a thermal fluid, the mixed step's shares
    ehl_optional = ("pressure_field_in", "pressure_field_out", "numerical_pressure") + (
        () if "thermal" in effects else ("effusivity",))
    ehl_extra = (("effusivity",) if "thermal" in effects else ()) + (MIXED_TRACTION_READS if "mixed" in effects else ())
    steps = [
        Step.of(ball_cone_motion), Step.of(ball_cone_contact_forces), Step.of(ball_cone_hertz),
        lubricant_step(scene.cvt.lubricant, scene.si.temperature),
        Step.of(ball_cone_films, provides=tuple(f"{q}_{side}" for q in (*films_of(film_model), "pressure_field")
                                                for side in SIDES)),
        *(Step.of(film_parameter, name=f"lambda_{side}", rename={"h": f"h_min_{side}", "sigma1": "sigma",
                                                                "sigma2": "sigma", "Lambda": f"Lambda_{side}"})
          for side in SIDES),
        *([Step.of(ball_cone_mixed)] if "mixed" in effects else []),
        *((Step.of(function, optional=ehl_optional, extra=ehl_extra)
           for function in (ball_cone_ehl_traction, ball_cone_ehl_traction_curve)) if ehl
          else (Step.of(ball_cone_traction), Step.of(ball_cone_traction_curve))),
        Step.of(ball_cone_efficiency), Step.of(ball_cone_slice_stresses), Step.of(ball_cone_life),
    ]
    inputs = {**ball_cone_cvt_inputs(scene, effects), **chosen, "film_model": film_model,
              "numerical_pressure": isinstance(film_model, MultigridPoint),
              **mixed_inputs(scene, effects, traction, film_model)}
    if ehl:
        inputs["fluid_model"] = fluid_traction_model(scene.cvt.lubricant, effects | {"non_newtonian"},
                                                     traction.fluid or "eyring")
    return SceneGraph(kind="ball_cone_cvt", inputs=inputs, steps=tuple(steps),
                      default_outputs=DEFAULT_OUTPUTS + MODEL_OUTPUTS[type(traction)]
                      + (BALL_CONE_MIXED_OUTPUTS if "mixed" in effects else ()), input_hints=HINTS,
                      plotter=plot_ball_cone_cvt, effects=effects,
                      effect_outputs=frozenset(BALL_CONE_MIXED_OUTPUTS) if "mixed" in effects else frozenset())
