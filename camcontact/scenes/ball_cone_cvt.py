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
``traction``
    FASTSIM (Kalker's simplified theory) on the contact ellipse with the contact's spin: the
    longitudinal creepage that transmits F_t, the slip share of the area, the traction regime
    (partial slip, or gross slip when F_t exceeds what Ct and the spin leave: then the traction is
    saturated and the contact flagged);
``stresses``
    the thesis's 2-D slice along the rolling direction through the contact centre: Hertz pressure
    and the FASTSIM traction of the central strip -> tau0 and its depth z0 (slot ``stress``:
    ``"max_shear"``, the Mohr radius the thesis's simulation used, or ``"orthogonal"``);
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
from ..models.life_lundberg_palmgren import LundbergPalmgren
from ..models.traction import Fastsim
from ..step_graph import SceneGraph, Step, checked_request, given, scene_builder
from ..steps.contact import ball_cone_hertz
from ..steps.film import ball_cone_films, film_parameter, films_of, resolve_film_model
from ..steps.forces import ball_cone_contact_forces
from ..steps.kinematics import ball_cone_motion
from ..steps.life import ball_cone_life
from ..steps.lubricant import lubricant_inputs, lubricant_step
from ..steps.stress import ball_cone_slice_stresses
from ..steps.traction import ball_cone_traction
from .ball_cone_cvt_plots import plot_ball_cone_cvt

__all__ = ["SIDES", "ball_cone_cvt_inputs", "build_ball_cone_cvt"]

SIDES = ("in", "out")
SLOTS = ("hertz", "film", "traction", "stress", "life")
SUPPORTED_EFFECTS = frozenset({"elasticity", "piezoviscosity", "spin"})
DEFAULT_EFFECTS = SUPPORTED_EFFECTS
DEFAULT_OUTPUTS = (
    "tilt", "reduction_ratio", "overrange", "output_speed", "ball_speed", "rolling_radius_in", "rolling_radius_out",
    "rolling_speed_in", "rolling_speed_out", "psi_in", "psi_out", "psi_total", "spin_in", "spin_out",
    "spin_roll_in", "spin_roll_out",
    "torque", "output_torque", "cam_axial_force", "normal_force", "tangential_force_in", "tangential_force_out",
    "traction_needed_in", "traction_needed_out", "mu_min", "traction_check",
    "Rx", "Ry", "a_rolling", "a_transverse", "p_h", "approach", "pressure_check",
    "h_c_in", "h_min_in", "h_c_out", "h_min_out", "Lambda_in", "Lambda_out",
    "creepage_in", "creepage_out", "slip_fraction_in", "slip_fraction_out", "traction_regime_in",
    "traction_regime_out", "tau0_in", "z0_in", "tau0_out", "z0_out",
    "cycles_cone_in", "cycles_ball_in", "cycles_ball_out", "cycles_cone_out",
    "life_cone_in", "life_ball_in", "life_ball_out", "life_cone_out", "life_system",
)
HINTS = {
    "lubricant": "set BallConeCVT.lubricant (the traction fluid's viscosity data)",
    "temperature": "set LoadedBallConeCVT.temperature",
    "sigma": "set BallConeCVT.roughness (RMS of each surface)",
}


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
        "piezoviscosity": "piezoviscosity" in effects, "compressibility": False, "spin": "spin" in effects,
        **lubricant_inputs(cvt.lubricant, scene.si.temperature),
    } | given(sigma=si.roughness)


def slot_models(models: Mapping[str, Any]) -> dict[str, Any]:
    """The models of the slots as graph inputs, checked (InputError naming the slot and what is allowed)."""
    chosen = {"hertz_method": models.get("hertz", "exact"), "stress_measure": models.get("stress", "max_shear")}
    for slot, value, allowed in (("hertz", chosen["hertz_method"], HERTZ_METHODS),
                                 ("stress", chosen["stress_measure"], MEASURES)):
        if value not in allowed:
            raise InputError(f"ball_cone_cvt scene: {slot} = {value!r}; allowed: {', '.join(allowed)}")
    for slot, family, cls, default in (("traction", "traction_models", Fastsim, "fastsim"),
                                       ("life", "life_models", LundbergPalmgren, "lundberg_palmgren")):
        spec = models.get(slot, default)
        kind = registry.get_class(family, spec) if isinstance(spec, str) else spec
        if isinstance(kind, type) and not issubclass(kind, cls):
            raise InputError(f"ball_cone_cvt scene: the {family} slot needs a {cls.__name__} model, got {spec!r}")
        model = registry.get(family, spec)
        if not isinstance(model, cls):
            raise InputError(f"ball_cone_cvt scene: the {family} slot needs a {cls.__name__} model, got {model!r}")
        chosen[f"{slot}_model"] = model
    return chosen


@scene_builder(LoadedBallConeCVT)
def build_ball_cone_cvt(scene: LoadedBallConeCVT, *, models: Mapping[str, Any],
                        effects: frozenset | None) -> SceneGraph:
    """Scene graph of a :class:`~camcontact.components.LoadedBallConeCVT` (one variant)."""
    effects = checked_request("ball_cone_cvt", models, effects, slots=SLOTS, supported=SUPPORTED_EFFECTS,
                              default=DEFAULT_EFFECTS)
    chosen = slot_models(models)
    film_model = resolve_film_model(models.get("film", "hamrock_dowson"), geometry="point",
                                    where="ball_cone_cvt scene: ", contact="the ball-cone contact")
    steps = [
        Step.of(ball_cone_motion), Step.of(ball_cone_contact_forces), Step.of(ball_cone_hertz),
        lubricant_step(scene.cvt.lubricant, scene.si.temperature),
        Step.of(ball_cone_films, provides=tuple(f"{q}_{side}" for q in films_of(film_model) for side in SIDES)),
        *(Step.of(film_parameter, name=f"lambda_{side}", rename={"h": f"h_min_{side}", "sigma1": "sigma",
                                                                "sigma2": "sigma", "Lambda": f"Lambda_{side}"})
          for side in SIDES),
        Step.of(ball_cone_traction), Step.of(ball_cone_slice_stresses), Step.of(ball_cone_life),
    ]
    inputs = {**ball_cone_cvt_inputs(scene, effects), **chosen, "film_model": film_model}
    return SceneGraph(kind="ball_cone_cvt", inputs=inputs, steps=tuple(steps), default_outputs=DEFAULT_OUTPUTS,
                      input_hints=HINTS, plotter=plot_ball_cone_cvt, effects=effects)
