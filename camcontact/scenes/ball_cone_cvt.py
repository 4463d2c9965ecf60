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

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from .. import registry
from ..analysis import SceneGraph, Step, checked_request, scene_builder
from ..components.ball_cone_cvt import LoadedBallConeCVT
from ..contact.fastsim import GrossSlipError, fastsim, solve_creepage
from ..contact.geometry import reduced_modulus
from ..contact.hertz_elliptical import METHODS as HERTZ_METHODS
from ..contact.hertz_elliptical import hertz_elliptical
from ..contact.roughness import lambda_ratio
from ..contact.slice_stress import MEASURES, slice_extremum
from ..dynamics.ball_cone_loads import ball_cone_loads
from ..errors import InputError
from ..kinematics.ball_cone import ball_cone_kinematics
from ..models.film_point import POINT_INPUTS
from ..models.life_lundberg_palmgren import LundbergPalmgren, life_time, system_life
from ..models.traction import Fastsim
from .line_contact import lubricant_step

__all__ = ["SIDES", "build_ball_cone_cvt"]

SIDES = ("in", "out")
SLOTS = ("hertz", "film", "traction", "stress", "life")
SUPPORTED_EFFECTS = frozenset({"elasticity", "piezoviscosity", "spin"})
DEFAULT_EFFECTS = SUPPORTED_EFFECTS
#: the pressure the thesis names as the threshold of EHL (§6.5, after Dowson) [Pa]
EHL_PRESSURE = 1.1e9
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


@scene_builder(LoadedBallConeCVT)
def build_ball_cone_cvt(scene: LoadedBallConeCVT, *, models: Mapping[str, Any],
                        effects: frozenset | None) -> SceneGraph:
    """Scene graph of a :class:`~camcontact.components.LoadedBallConeCVT` (one variant)."""
    effects = checked_request("ball_cone_cvt", models, effects, slots=SLOTS, supported=SUPPORTED_EFFECTS,
                              default=DEFAULT_EFFECTS)
    cvt = scene.cvt
    si = cvt.si
    material = cvt.material
    hertz_method = models.get("hertz", "exact")
    if hertz_method not in HERTZ_METHODS:
        raise InputError(f"ball_cone_cvt scene: hertz = {hertz_method!r}; allowed: {', '.join(HERTZ_METHODS)}")
    measure = models.get("stress", "max_shear")
    if measure not in MEASURES:
        raise InputError(f"ball_cone_cvt scene: stress = {measure!r}; allowed: {', '.join(MEASURES)}")
    traction = _resolve(models.get("traction", "fastsim"), "traction_models", Fastsim)
    life = _resolve(models.get("life", "lundberg_palmgren"), "life_models", LundbergPalmgren)
    spin = "spin" in effects
    inputs: dict[str, Any] = {
        "power": scene.si.power, "input_speed": scene.si.input_speed, "ratio": scene.ratio,
        "E_reduced": reduced_modulus(material.si.E, material.nu, material.si.E, material.nu),
        "shear_modulus": material.si.E / (2.0 * (1.0 + material.nu)), "nu": material.nu,
        "traction_coefficient": cvt.traction_coefficient,
    }
    if cvt.lubricant is not None:
        inputs["lubricant"] = cvt.lubricant
    if scene.temperature is not None:
        inputs["temperature"] = scene.si.temperature
    if cvt.roughness is not None:
        inputs["sigma"] = si.roughness
    r, alpha, R_cont = cvt.ball_radius, si.cone_angle, si.cone_contact_radius

    def run_kinematics(s):
        beta = cvt.tilt(s["ratio"])
        out = ball_cone_kinematics(r, alpha, R_cont, beta, s["input_speed"])
        return {**out, "tilt": beta, "reduction_ratio": cvt.reduction_ratio(s["ratio"]), "overrange": cvt.overrange}

    def run_loads(s):
        out = ball_cone_loads(s["power"], s["input_speed"], ball_count=cvt.ball_count, cone_radius=R_cont,
                              cone_angle=alpha, cam_angle=si.cam_ramp_angle, cam_radius=si.cam_radius,
                              cam_ball_count=cvt.cam_ball_count, reduction_ratio=s["reduction_ratio"],
                              clamping=cvt.clamping)
        ct = s["traction_coefficient"]
        worst = max(out["traction_needed_in"], out["traction_needed_out"])
        side = "input" if out["traction_needed_in"] >= out["traction_needed_out"] else "output"
        out["traction_check"] = (f"ok: needs {worst:.4g} at the {side} contact < Ct = {ct:.4g}" if worst < ct else
                                 f"gross slip: the {side} contact needs F_t/F_n = {worst:.4g} >= Ct = {ct:.4g}")
        return out

    def run_hertz(s):
        # the cone's track: curvature cos(alpha)/R_cont along rolling, straight along the generator
        Rx = 1.0 / (1.0 / r + math.cos(alpha) / R_cont)
        contact = hertz_elliptical(s["normal_force"], Rx, r, s["E_reduced"], method=hertz_method)
        check = (f"p_h = {contact.p_max * 1e-9:.3g} GPa " +
                 ("above" if contact.p_max > EHL_PRESSURE else "below") + " the thesis's 1.1 GPa EHL threshold")
        return {"Rx": Rx, "Ry": r, "a_rolling": contact.a_x, "a_transverse": contact.a_y, "p_h": contact.p_max,
                "approach": contact.approach, "pressure_check": check}

    film_spec = models.get("film", "hamrock_dowson")
    film_spec = "multigrid_point" if film_spec == "multigrid" else film_spec  # the numerical film of a point contact
    film_model = registry.get("film_models", film_spec, requires=POINT_INPUTS, provides=("h_c", "h_min"))
    if getattr(film_model, "geometry", "point") != "point":
        raise InputError(f"ball_cone_cvt scene: film model {film_model.name!r} is for {film_model.geometry} contacts; "
                         "the ball-cone contact needs a point model (hamrock_dowson, nijenbanning, multigrid)")
    piezo = "piezoviscosity" in effects

    def run_film(s):
        out = {}
        for side in SIDES:
            produced = film_model({"Rx": s["Rx"], "Ry": s["Ry"], "F": s["normal_force"], "E_reduced": s["E_reduced"],
                                   "u_m": s[f"rolling_speed_{side}"], "eta0": s["eta0"],
                                   "alpha": s["alpha"] if piezo else 0.0, "lubricant_state": s["lubricant_state"],
                                   "density_law": s["density_law"]})
            out[f"h_c_{side}"], out[f"h_min_{side}"] = float(produced["h_c"]), float(produced["h_min"])
        return out

    def run_lambda(s):
        return {f"Lambda_{side}": lambda_ratio(s[f"h_min_{side}"], s["sigma"], s["sigma"]) for side in SIDES}

    def run_traction(s):
        out: dict[str, Any] = {}
        for side in SIDES:
            solution = _traction(s, side, traction, spin)
            out.update({f"{key}_{side}": value for key, value in solution.items()})
        return out

    def run_stresses(s):
        out = {}
        for side in SIDES:
            extremum = _slice(s, s[f"fastsim_{side}"], measure)
            out[f"tau0_{side}"], out[f"z0_{side}"] = extremum.tau0, extremum.z0
        return out

    def run_life(s):
        a = s["a_transverse"]
        n_in, n_out, n_ball = (s["input_speed"] / (2 * math.pi), s["output_speed"] / (2 * math.pi),
                               s["ball_speed"] / (2 * math.pi))
        tracks = {  # (side, track radius, stress cycles per revolution, speed [rev/s])
            "life_cone_in": ("in", R_cont, cvt.ball_count, n_in),
            "life_ball_in": ("in", s["rolling_radius_in"], 1, n_ball),
            "life_ball_out": ("out", s["rolling_radius_out"], 1, n_ball),
            "life_cone_out": ("out", R_cont, cvt.ball_count, n_out),
        }
        out = {}
        for key, (side, radius, per_revolution, speed) in tracks.items():
            cycles = life.life(s[f"tau0_{side}"], s[f"z0_{side}"], a, radius)
            out[key.replace("life_", "cycles_")] = float(cycles)
            out[key] = float(life_time(cycles, per_revolution, speed))
        lives = [out["life_cone_in"], out["life_cone_out"]] + [out["life_ball_in"], out["life_ball_out"]] * cvt.ball_count
        out["life_system"] = float(system_life(np.array(lives), life.e))
        return out

    per_side = lambda stem: tuple(f"{stem}_{side}" for side in SIDES)  # noqa: E731
    steps = [
        Step("kinematics", ("ratio", "input_speed"),
             ("tilt", "reduction_ratio", "overrange", "output_speed", "ball_speed", *per_side("rolling_radius"),
              *per_side("rolling_speed"), "psi_in", "psi_out", "psi_total", *per_side("spin"), *per_side("spin_roll")),
             run_kinematics, model=f"ball_cone ({cvt.ratio_convention} ratio)"),
        Step("loads", ("power", "input_speed", "reduction_ratio", "traction_coefficient"),
             ("torque", "output_torque", "cam_axial_force", "cam_ball_force", "normal_force", "ball_axial_resultant",
              *per_side("tangential_force"), *per_side("traction_needed"), "mu_min", "traction_check"),
             run_loads, model=f"saccheto_6.5 ({cvt.clamping})"),
        Step("hertz", ("normal_force", "E_reduced"),
             ("Rx", "Ry", "a_rolling", "a_transverse", "p_h", "approach", "pressure_check"), run_hertz,
             model=f"hertz_elliptical ({hertz_method})"),
        lubricant_step(cvt.lubricant, frozenset(), piezo),
        Step("film", ("Rx", "Ry", "normal_force", "E_reduced", *per_side("rolling_speed"), "eta0", "alpha",
                      "lubricant_state", "density_law"),
             (*per_side("h_c"), *per_side("h_min")), run_film, model=film_model.name, identity=id(film_model)),
        Step("lambda", (*per_side("h_min"), "sigma"), per_side("Lambda"), run_lambda),
        Step("traction", ("a_rolling", "a_transverse", "normal_force", "traction_coefficient", "shear_modulus",
                          *per_side("tangential_force"), *per_side("spin")),
             (*per_side("creepage"), *per_side("slip_fraction"), *per_side("traction_regime"), *per_side("fastsim")),
             run_traction, model=traction.name, identity=id(traction)),
        Step("stresses", ("a_rolling", "p_h", *per_side("fastsim")), (*per_side("tau0"), *per_side("z0")),
             run_stresses, model=f"slice_2d ({measure})"),
        Step("life", ("a_transverse", *per_side("tau0"), *per_side("z0"), *per_side("rolling_radius"), "input_speed",
                      "output_speed", "ball_speed"),
             ("life_cone_in", "life_ball_in", "life_ball_out", "life_cone_out", "life_system", "cycles_cone_in",
              "cycles_ball_in", "cycles_ball_out", "cycles_cone_out"), run_life,
             model=life.name, identity=id(life)),
    ]
    return SceneGraph(kind="ball_cone_cvt", inputs=inputs, steps=tuple(steps), default_outputs=DEFAULT_OUTPUTS,
                      input_hints=HINTS, plotter=_plot, effects=effects)


def _resolve(spec: Any, family: str, cls: type) -> Any:
    model = registry.get(family, spec)
    if not isinstance(model, cls):
        raise InputError(f"ball_cone_cvt scene: the {family} slot needs a {cls.__name__} model, got {model!r}")
    return model


def _traction(s, side: str, model: Fastsim, spin: bool) -> dict:
    """FASTSIM creepage that transmits F_t at one contact, or the saturated (gross-slip) traction."""
    a, b, N, mu, G = s["a_rolling"], s["a_transverse"], s["normal_force"], s["traction_coefficient"], s["shear_modulus"]
    phi = s[f"spin_{side}"] if spin else 0.0
    grid = {"nx": model.nx, "ny": model.ny, "compiled": model.compiled}
    try:
        solution = solve_creepage(s[f"tangential_force_{side}"], a, b, N, mu, G, spin=phi, **grid)
        result, creepage, regime = solution.result, solution.creepage, "partial slip"
    except GrossSlipError as exc:
        # the contact cannot transmit F_t: traction saturated at Ct p everywhere (creepage far past the limit)
        creepage = -1e3 * mu * N / (G * a * b)
        result = fastsim(a, b, N, mu, G, creepage_x=creepage, spin=phi, **grid)
        regime = f"gross slip: F_t/F_n = {exc.traction_needed:.4g} >= Ct = {mu:.4g}"
    return {"creepage": creepage, "slip_fraction": result.slip_fraction, "traction_regime": regime,
            "fastsim": result}


def _slice(s, result, measure: str):
    """tau0 and z0 of the 2-D slice through the contact centre along rolling (Saccheto §3.4 method):
    Hertz pressure on the centre line and the traction ratio Tx/p of FASTSIM's central strip."""
    a, p0 = s["a_rolling"], s["p_h"]
    j = int(np.argmin(np.abs(result.y)))
    x_strip = result.x[j][::-1]  # FASTSIM marches from the leading edge (+a) to the trailing edge
    ratio = np.divide(result.Tx[j], result.p[j], out=np.zeros_like(result.Tx[j]), where=result.p[j] > 0)[::-1]
    nodes = np.concatenate(([-a], np.clip(x_strip, -a, a), [a]))
    keep = np.concatenate(([True], np.diff(nodes) > 0))
    nodes = nodes[keep]
    pressure = p0 * np.sqrt(np.clip(1.0 - (nodes / a) ** 2, 0.0, None))
    traction = np.concatenate(([0.0], ratio, [0.0]))[keep] * pressure
    x = np.linspace(-1.3 * a, 1.3 * a, 53)
    z = np.linspace(0.02 * a, 1.5 * a, 37)
    return slice_extremum(nodes, pressure, traction, measure=measure, x=x, z=z)


def _plot(result, **kwargs):
    from .ball_cone_cvt_plots import plot_ball_cone_cvt

    return plot_ball_cone_cvt(result, **kwargs)
