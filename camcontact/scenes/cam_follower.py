"""The cam–follower scene: motion law → kinematics → dynamics → Hertz → film → friction and wear, per cam angle.

Per-angle outputs are arrays over the scene's cam angles (``Result.to_frame()`` gives one row per
angle, like Tsuha 2015 Tables 6.3/6.4); cycle summaries are scalars (``Result.summary_frame()``).
Only the steps the requested outputs need run: asking for kinematics runs no dynamics, no Hertz,
no lubricant and no film.

Model slots (``Analysis(models=...)``): ``film`` (any line film model, formula or
``"multigrid"``, warm-started from the previous angle; default ``"pan_hamrock"``), ``friction``
(``friction_models``; default ``"coulomb"``), ``wear`` (``wear_models``; default ``"archard"``).

Effects: ``elasticity``, ``piezoviscosity``, ``compressibility`` (on by default), ``dynamics``
(off by default: the contact force is the prescribed-motion 1-DOF force of Tsuha 2015 Eq. 3.46;
on: the valve train's lumped 2-DOF/5-DOF model is integrated over ``CamFollower.cycles`` turns with
unilateral contact and the last turn is reported) and ``squeeze`` (off by default: the film is
quasi-steady, angle by angle; on: the numerical film — film model ``"multigrid"`` — is solved as one
transient over the turn with the squeeze term, implicit BDF2 steps from angle to angle through any
entrainment reversal, :func:`camcontact.ehl.line_transient.transient_cycle`; it starts from the
steady film at the steadiest angle, e.g. on the base circle).
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Mapping
from typing import Any

import numpy as np

from .. import registry
from ..analysis import SceneGraph, Step, checked_request, scene_builder
from ..components.cam_follower import CamFollower
from ..contact.geometry import reduced_modulus
from ..contact.hertz_line import hertz_line, line_approach
from ..contact.roughness import lambda_ratio
from ..dynamics.prescribed_motion import contact_force, minimum_stiffness
from ..ehl.groups import hamrock_line, moes_line
from ..errors import InputError, ValidityWarning
from ..kinematics.follower import follower_kinematics, undercut_angles
from ..models.film_line import LINE_INPUTS
from .line_contact import _film_model, lubricant_step

__all__ = ["DEFAULT_EFFECTS", "SUPPORTED_EFFECTS", "build_cam_follower"]

SUPPORTED_EFFECTS = frozenset({"elasticity", "piezoviscosity", "compressibility", "dynamics", "squeeze"})
DEFAULT_EFFECTS = frozenset({"elasticity", "piezoviscosity", "compressibility"})
DEFAULT_MODELS = {"film": "pan_hamrock", "friction": "coulomb", "wear": "archard"}
#: beyond this Moes M (entrainment speed near zero) no steady solution is attempted: the steady
#: film tends to zero and the real film lives on squeeze (the ``squeeze`` effect solves it transiently)
STEADY_M_LIMIT = 2000.0

KINEMATICS = ("lift", "follower_velocity", "follower_acceleration", "follower_jerk", "pressure_angle", "cam_radius",
              "R", "u_cam", "u_follower", "u_m", "u_s", "angular_speed", "profile_x", "profile_y")
FORCES_1DOF = ("contact_force", "inertia_force", "damping_force", "spring_force", "preload_force", "cam_torque")
PER_ANGLE = frozenset((
    "cam_angle", *KINEMATICS, *FORCES_1DOF, "normal_force", "w", "b", "p_h", "approach", "U", "G", "W", "M", "L",
    "h_c", "h_min", "film_regime", "H0", "H_min", "H_c", "spike_pressure", "Lambda_min", "friction_force",
    "friction_coefficient", "friction_power", "wear_rate", "contact_open",
))
DEFAULT_OUTPUTS = (
    "cam_angle", "lift", "follower_velocity", "follower_acceleration", "pressure_angle", "cam_radius", "R", "u_m",
    "contact_force", "cam_torque", "w", "b", "p_h", "M", "L", "h_c", "h_min", "film_regime", "friction_force",
    "friction_power", "wear_rate",
    "motion_continuity", "natural_frequency", "k_min", "jump_margin", "jump", "contact_force_max", "p_h_max", "h_min_cycle",
    "friction_power_mean", "wear_rate_mean",
)
HINTS = {
    "lubricant": "set CamFollower.lubricant",
    "temperature": "set CamFollower.temperature (the lubricant's viscosity depends on it)",
    "hardness": "give the cam material a hardness (Material.hardness), which the wear model needs",
    "sigma1": "give the cam a roughness (Cam.roughness)",
    "sigma2": "give the follower a roughness (Follower.roughness)",
    "coulomb_coefficient": "give CamFollower.friction_coefficient (for the default 'coulomb' model) or pass a "
                           "friction model, e.g. models={'friction': registry.get('friction_models', "
                           "'ferrarese_uehara', k_L=2)}",
    "archard_coefficient": "give CamFollower.wear_coefficient (for the default 'archard' model) or pass a wear model",
}


def _degrees(theta) -> str:
    return ", ".join(f"{math.degrees(t):.4g}°" for t in np.atleast_1d(theta))


@scene_builder(CamFollower)
def build_cam_follower(scene: CamFollower, *, models: Mapping[str, Any], effects: frozenset | None) -> SceneGraph:
    """Scene graph of a :class:`~camcontact.components.CamFollower` (one variant)."""
    effects = checked_request("cam_follower", models, effects, slots=sorted(DEFAULT_MODELS),
                              supported=SUPPORTED_EFFECTS, default=DEFAULT_EFFECTS)
    models = {**DEFAULT_MODELS, **models}
    cam, follower, train = scene.cam, scene.follower, scene.valve_train
    thesis = scene.convention == "thesis"
    inputs: dict[str, Any] = {
        "cam_angle": scene.cam_angles, "program": cam.program, "geometry": scene.geometry,
        "speed": scene.si.speed, "angular_acceleration": scene.si.angular_acceleration,
        "E_reduced": reduced_modulus(cam.material.si.E, cam.material.nu, follower.material.si.E, follower.material.nu),
        "width": cam.si.width,
    }
    if scene.lubricant is not None:
        inputs["lubricant"] = scene.lubricant
    if scene.temperature is not None:
        inputs["temperature"] = scene.si.temperature
    if cam.material.hardness is not None:
        inputs["hardness"] = cam.material.si.hardness
    if cam.roughness is not None:
        inputs["sigma1"] = cam.si.roughness
    if follower.roughness is not None:
        inputs["sigma2"] = follower.si.roughness

    def run_kinematics(s):
        k = follower_kinematics(s["program"], s["geometry"], s["cam_angle"], s["speed"], s["angular_acceleration"],
                                scene.convention)
        bad = undercut_angles(k, s["geometry"])
        if bad.size:
            what = "R_cam <= 0" if s["geometry"].kind == "flat" else "pitch-curve radius <= roller radius"
            raise InputError(f"the cam profile undercuts (cusp, {what}) at {_degrees(bad[:8])}"
                             f"{' …' if bad.size > 8 else ''}; raise the base radius or lower the lift/acceleration")
        limit = follower.si.max_pressure_angle
        over = np.abs(k.pressure_angle) > limit
        if np.any(over):
            worst = int(np.argmax(np.abs(k.pressure_angle)))
            warnings.warn(
                f"pressure angle {math.degrees(k.pressure_angle[worst]):.4g}° at {_degrees(k.theta[worst])} exceeds "
                f"the limit {math.degrees(limit):.4g}° (at {int(over.sum())} of {over.size} angles)",
                ValidityWarning, stacklevel=2)
        return {"lift": k.lift, "follower_velocity": k.velocity, "follower_acceleration": k.acceleration,
                "follower_jerk": k.jerk, "pressure_angle": k.pressure_angle, "cam_radius": k.cam_radius,
                "R": k.reduced_radius, "u_cam": k.u_cam, "u_follower": k.u_follower, "u_m": k.u_m, "u_s": k.u_s,
                "angular_speed": k.omega, "profile_x": k.profile_x, "profile_y": k.profile_y}

    def run_continuity(s):
        table = s["program"].continuity()
        infinite = table.loc[~table["jerk_finite"], "angle [deg]"].tolist()
        if infinite:
            return {"motion_continuity": "acceleration jumps (infinite jerk) at " + ", ".join(f"{a:.4g}°" for a in infinite)}
        jumps = table.loc[~table["jerk_continuous"], "angle [deg]"].tolist()
        text = "C2 everywhere (finite jerk)"
        return {"motion_continuity": text + (f"; jerk jumps at {', '.join(f'{a:.4g}°' for a in jumps)}" if jumps else "")}

    def run_natural(s):
        return {"natural_frequency": train.natural_frequency / (2.0 * math.pi)}

    def run_k_min(s):
        omega = scene.si.max_speed if scene.max_speed is not None else s["speed"]
        theta = np.linspace(0.0, 2.0 * math.pi, 7201)
        f, f1, f2 = s["program"].evaluate(theta)[:3]
        return {"k_min": minimum_stiffness(f, f1, f2, omega, mass=train.si.mass, damping_ratio=train.zeta,
                                           preload=train.si.preload)}

    def run_force(s):
        forces = contact_force(s["lift"], s["follower_velocity"], s["follower_acceleration"], s["angular_speed"],
                               mass=train.si.mass, stiffness=train.si.stiffness, damping=train.c,
                               preload=train.si.preload)
        return {"contact_force": forces.total, "inertia_force": forces.inertia, "damping_force": forces.damping,
                "spring_force": forces.spring, "preload_force": forces.preload, "cam_torque": forces.torque}

    def check_dynamics():
        if train.lumped is None:
            raise InputError("the 'dynamics' effect integrates the valve train's lumped model; give "
                             "ValveTrain(lumped=LumpedValveTrain.ferrarese_2dof()) or similar, or drop the effect")
        if scene.si.angular_acceleration != 0.0:
            raise InputError("the 'dynamics' effect runs at constant cam speed; angular_acceleration must be 0")

    def run_ode(s):
        from ..dynamics.valve_train_ode import simulate

        response = simulate(train.lumped, s["program"].evaluate, s["speed"], cycles=scene.cycles)
        period = 2.0 * math.pi
        last = response.angle >= response.angle[-1] - period - 1e-12
        angle = np.mod(response.angle[last] - (response.angle[-1] - period), period)
        order = np.argsort(angle, kind="stable")
        N = np.interp(np.mod(s["cam_angle"], period), angle[order], response.contact_force[last][order], period=period)
        return {"contact_force": N, "cam_torque": N * s["follower_velocity"] / s["angular_speed"],
                "valve_train_response": response}

    def run_normal(s):
        axial = s["contact_force"]
        normal = axial if thesis else axial / np.cos(s["pressure_angle"])
        return {"normal_force": np.clip(normal, 0.0, None), "contact_open": axial <= 0.0}

    def run_jump(s):
        open_ = s["contact_open"]
        if not np.any(open_):
            margin = float(np.min(s["contact_force"]))
            return {"jump": f"no jump (minimum contact force {margin:.4g} N)"}
        return {"jump": f"JUMP: the follower leaves the cam at {int(open_.sum())} angles, from "
                        f"{_degrees(s['cam_angle'][open_][:1])} (contact force {float(np.min(s['contact_force'])):.4g} N)"}

    def run_hertz(s):
        n = s["cam_angle"].size
        w = s["normal_force"] / s["width"]
        b, p_h, approach = np.zeros(n), np.zeros(n), np.zeros(n)
        for i in np.flatnonzero(w > 0.0):
            hz = hertz_line(float(w[i]), float(s["R"][i]), s["E_reduced"])
            b[i], p_h[i] = hz.b, hz.p_h
            approach[i] = line_approach("hamrock", E_reduced=s["E_reduced"], w=float(w[i]), R=float(s["R"][i]))
        return {"w": w, "b": b, "p_h": p_h, "approach": approach}

    piezo = "piezoviscosity" in effects
    film_model = _film_model(models["film"], effects) if scene.lubricant is not None else None

    def film_speed(s):
        """The entrainment speed handed to the film models: |u_m|, or |u_m|/2 in the thesis convention."""
        return np.abs(s["u_m"]) * (0.5 if thesis else 1.0)

    def run_groups(s):
        alpha = s["alpha"] if piezo else 0.0
        u = film_speed(s)
        n = u.size
        U, G, W, M, L = (np.zeros(n) for _ in range(5))
        for i in range(n):
            if s["w"][i] > 0.0 and u[i] > 0.0:
                U[i], G[i], W[i] = hamrock_line(float(s["w"][i]), float(s["R"][i]), s["E_reduced"], float(u[i]),
                                                s["eta0"], alpha)
                M[i], L[i] = moes_line(U[i], G[i], W[i])
            else:
                G[i] = alpha * s["E_reduced"]
                M[i] = math.inf if s["w"][i] > 0.0 else 0.0
        return {"alpha_effective": alpha, "U": U, "G": G, "W": W, "M": M, "L": L}

    squeeze = "squeeze" in effects

    def run_film(s):
        if squeeze:
            return _transient_films(film_model, s, 0.5 if thesis else 1.0, piezo)
        return _cycle_films(film_model, s, film_speed(s))

    def check_squeeze():
        if squeeze and getattr(film_model, "name", "") != "multigrid":
            raise InputError("the 'squeeze' effect solves the film numerically over the turn: use the film model "
                             "'multigrid' (models={'film': 'multigrid'}), or leave the effect off for the "
                             f"quasi-steady {getattr(film_model, 'name', 'formula')} film")

    def run_ehl_details(s):
        solutions = s["film_solutions"]
        if all(sol is None for sol in solutions):
            raise InputError("H0, H_min, H_c and spike_pressure come from the numerical solution: use the film model "
                             "'multigrid'")
        pick = (lambda attr: np.array([getattr(sol, attr) if sol is not None else 0.0 for sol in solutions]))
        return {"H0": pick("H0"), "H_min": pick("H_min"), "H_c": pick("H_c"),
                "spike_pressure": np.array([_spike_height(sol) for sol in solutions])}

    def model_state(s):
        return {**s, **{alias: s[name] for alias, name in _ALIASES.items()}}

    friction_model = _LazyModel("friction_models", models["friction"], "friction",
                                scene.friction_coefficient, "coulomb_coefficient")
    wear_model = _LazyModel("wear_models", models["wear"], "wear", scene.wear_coefficient, "archard_coefficient")

    def run_friction(s):
        produced = friction_model(model_state(s))
        force = np.asarray(produced["friction_force"], dtype=float) * np.ones(s["cam_angle"].size)
        if "friction_power" in produced:
            power = np.asarray(produced["friction_power"], dtype=float) * np.ones_like(force)
        else:
            power = force * np.abs(s["u_s"])
        with np.errstate(divide="ignore", invalid="ignore"):
            mu = np.where(s["normal_force"] > 0.0, force / s["normal_force"], 0.0)
        return {"friction_force": force, "friction_coefficient": mu, "friction_power": power}

    def run_wear(s):
        produced = wear_model(model_state(s))
        return {"wear_rate": np.asarray(produced["wear_rate"], dtype=float) * np.ones(s["cam_angle"].size)}

    def mean_over_cycle(s, values):
        theta = s["cam_angle"]
        if theta.size > 1 and not np.allclose(np.diff(theta), theta[1] - theta[0]):
            raise InputError("cycle means need equally spaced cam angles over a full turn (use angle_step)")
        return float(np.mean(values))

    def lambda_min(s):
        return {"Lambda_min": np.array([lambda_ratio(h, s["sigma1"], s["sigma2"]) for h in s["h_min"]])}

    summary = [
        Step("contact_force_max", ("contact_force",), ("contact_force_max",),
             lambda s: {"contact_force_max": float(np.max(s["contact_force"]))}),
        Step("p_h_max", ("p_h",), ("p_h_max",), lambda s: {"p_h_max": float(np.max(s["p_h"]))}),
        Step("h_min_cycle", ("h_min", "film_regime"), ("h_min_cycle",),
             lambda s: {"h_min_cycle": float(np.nanmin(s["h_min"])) if np.any(np.isfinite(s["h_min"])) else 0.0}),
        Step("friction_power_mean", ("friction_power",), ("friction_power_mean",),
             lambda s: {"friction_power_mean": mean_over_cycle(s, s["friction_power"])}),
        Step("wear_rate_mean", ("wear_rate", "speed"), ("wear_rate_mean", "wear_volume_per_cycle"),
             lambda s: {"wear_rate_mean": mean_over_cycle(s, s["wear_rate"]),
                        "wear_volume_per_cycle": mean_over_cycle(s, s["wear_rate"]) * 2.0 * math.pi / s["speed"]}),
    ]
    dynamics = "dynamics" in effects
    force_step = (
        Step("dynamics", ("program", "cam_angle", "speed", "follower_velocity", "angular_speed"),
             ("contact_force", "cam_torque", "valve_train_response"), run_ode, model="lumped ODE",
             check=check_dynamics)
        if dynamics else
        Step("dynamics", ("lift", "follower_velocity", "follower_acceleration", "angular_speed"), FORCES_1DOF,
             run_force, model="1-DOF prescribed motion")
    )
    film_name = getattr(film_model, "name", str(models["film"]))
    steps = [
        Step("kinematics", ("program", "geometry", "cam_angle", "speed", "angular_acceleration"), KINEMATICS,
             run_kinematics, model=f"{scene.follower.kind} follower ({scene.convention})"),
        Step("continuity", ("program",), ("motion_continuity",), run_continuity),
        Step("natural_frequency", (), ("natural_frequency",), run_natural),
        Step("k_min", ("program", "speed"), ("k_min",), run_k_min),
        Step("jump_margin", ("contact_force",), ("jump_margin",),
             lambda s: {"jump_margin": float(np.min(s["contact_force"]))}),
        force_step,
        Step("normal_force", ("contact_force", "pressure_angle"), ("normal_force", "contact_open"), run_normal),
        Step("jump", ("contact_open", "contact_force", "cam_angle"), ("jump",), run_jump),
        Step("hertz", ("normal_force", "width", "R", "E_reduced", "cam_angle"), ("w", "b", "p_h", "approach"),
             run_hertz, model="hertz_line"),
        lubricant_step(scene.lubricant, effects, piezo),
        Step("ehl_groups", ("w", "R", "E_reduced", "u_m", "eta0", "alpha"),
             ("alpha_effective", "U", "G", "W", "M", "L"), run_groups),
        Step("film", ("w", "R", "E_reduced", "u_m", "eta0", "alpha_effective", "M", "L", "lubricant_state",
                      "density_law", "contact_open"),
             (*_films(film_model), "film_regime", "film_solutions"), run_film,
             model=f"{film_name} (transient, squeeze)" if squeeze else film_name,
             version=getattr(film_model, "version", ""), check=check_squeeze),
        Step("ehl_details", ("film_solutions",), ("H0", "H_min", "H_c", "spike_pressure"), run_ehl_details),
        Step("lambda", ("h_min", "sigma1", "sigma2"), ("Lambda_min",), lambda_min),
        Step("friction", tuple(dict.fromkeys(("normal_force", "u_s", "angular_speed", "cam_angle",
                                              *_model_requires(friction_model)))),
             ("friction_force", "friction_coefficient", "friction_power"), run_friction,
             model=friction_model.name, version=friction_model.version, check=friction_model.check),
        Step("wear", tuple(dict.fromkeys(("normal_force", "u_s", "angular_speed", "cam_angle",
                                          *_model_requires(wear_model)))),
             ("wear_rate",), run_wear, model=wear_model.name, version=wear_model.version, check=wear_model.check),
        *summary,
    ]
    from .cam_follower_plots import plot_cam_follower

    return SceneGraph(kind="cam_follower", inputs=inputs, steps=tuple(steps), default_outputs=DEFAULT_OUTPUTS,
                      input_hints=HINTS, plotter=plot_cam_follower, effects=effects, index="cam_angle",
                      per_index=PER_ANGLE)


class _LazyModel:
    """A model slot resolved when its step is planned (an unasked friction model needs no parameters).

    The default models ``coulomb`` and ``archard`` take their coefficient from the scene
    (``CamFollower.friction_coefficient`` / ``wear_coefficient``); without it their step requires the
    pseudo-input ``coefficient_input``, which the plan reports as missing with a hint.
    """

    #: names of the models whose only parameter ``coefficient`` the scene may supply
    SCENE_COEFFICIENT = ("coulomb", "archard")

    def __init__(self, family: str, spec: Any, slot: str, coefficient: float | None = None,
                 coefficient_input: str = ""):
        self.family, self.spec, self.slot = family, spec, slot
        self._model = None
        kind = registry.get_class(family, spec) if isinstance(spec, str) else spec
        self.name = getattr(kind, "name", str(spec))
        self.version = getattr(kind, "version", "")
        self.requires = tuple(getattr(kind, "requires", ()))
        self.parameters = {}
        if isinstance(spec, str) and spec in self.SCENE_COEFFICIENT:
            if coefficient is None:
                self.requires += (coefficient_input,)
            else:
                self.parameters = {"coefficient": coefficient}

    def check(self) -> None:
        self.model  # noqa: B018  (resolves now, before anything runs)

    @property
    def model(self):
        if self._model is None:
            try:
                self._model = registry.get(self.family, self.spec, **self.parameters)
            except TypeError as exc:
                raise InputError(
                    f"{self.slot} model {self.name!r} needs parameters ({exc}); pass an instance, e.g. "
                    f"models={{'{self.slot}': camcontact.registry.get('{self.family}', '{self.name}', ...)}}"
                ) from None
        return self._model

    def __call__(self, state):
        return self.model(state)


#: state names the scene provides under other names for the friction and wear models
_ALIASES = {"sliding_speed": "u_s"}


def _model_requires(model) -> tuple[str, ...]:
    return tuple(_ALIASES.get(name, name) for name in model.requires)


def _cycle_films(model, s, u_film) -> dict:
    """Films at every angle: steady solutions, warm-started, cached (a dwell is solved once).

    Numerical solves run as warm-started chains along the cycle: the distinct contact states in
    angle order are cut into :func:`_chain_count` arcs, solved side by side in threads (the
    compiled kernels release the GIL), each arc warm-started angle by angle from a cold start.
    """
    n = u_film.size
    films = _films(model)
    values = {q: np.zeros(n) for q in films}
    regime = np.empty(n, dtype=object)
    solutions: list = [None] * n
    numerical = getattr(model, "name", "") == "multigrid"
    fallback = registry.get("film_models", "pan_hamrock") if numerical else None
    # the samples on both sides of a sign change of u_m bracket an entrainment reversal
    sign = np.sign(np.asarray(s["u_m"], dtype=float))
    reversal = np.zeros(n, dtype=bool)
    change = sign[:-1] * sign[1:] < 0.0
    reversal[:-1] |= change
    reversal[1:] |= change
    # --- plan: which angles need which solve (identical inputs share one)
    keys: list = [None] * n
    states: dict = {}  # key -> (state, model to use, note)
    for i in range(n):
        if s["contact_open"][i] or s["w"][i] <= 0.0:
            for q in films:
                values[q][i] = np.nan
            regime[i] = "contact lost (jump): no film"
            continue
        if u_film[i] == 0.0:
            regime[i] = "u_m = 0: no steady film (the squeeze film needs the transient solution: effect 'squeeze')"
            continue
        state = {"R": float(s["R"][i]), "w": float(s["w"][i]), "E_reduced": s["E_reduced"], "u_m": float(u_film[i]),
                 "eta0": s["eta0"], "alpha": s["alpha_effective"], "lubricant_state": s["lubricant_state"],
                 "density_law": s["density_law"]}
        key = keys[i] = tuple(state[k] for k in LINE_INPUTS)
        if key in states:
            continue
        use, note = model, ""
        if numerical and s["M"][i] > STEADY_M_LIMIT:
            use, note = fallback, (f"u_m ≈ 0 (|u_m| = {abs(s['u_m'][i]):.3g} m/s, M = {s['M'][i]:.4g} > "
                                   f"{STEADY_M_LIMIT:g}): Pan–Hamrock formula; squeeze film: effect 'squeeze'")
        states[key] = (state, use, note)
    # --- solve: formulas directly, the numerical film in warm-started chains
    cache: dict = {}
    chain = [key for key, (_, use, _) in states.items() if use is model and numerical]
    for key, (state, use, note) in states.items():
        if key not in chain:
            cache[key] = (use(state), use, note)
    if chain:
        arcs = [list(arc) for arc in np.array_split(np.arange(len(chain)), _chain_count(model, len(chain)))]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the record says it; the regime column reports it
            if len(arcs) == 1:
                results = [_solve_chain(model, fallback, [states[chain[j]][0] for j in arcs[0]])]
            else:
                from concurrent.futures import ThreadPoolExecutor

                with ThreadPoolExecutor(len(arcs)) as pool:
                    results = list(pool.map(
                        lambda arc: _solve_chain(model, fallback, [states[chain[j]][0] for j in arc]), arcs))
        for arc, produced_arc in zip(arcs, results):
            for j, entry in zip(arc, produced_arc):
                cache[chain[j]] = entry
    # --- fill the angles
    for i in range(n):
        if keys[i] is None:
            continue
        produced, use, note = cache[keys[i]]
        for q in films:
            values[q][i] = produced[q]
        messages = [note] if note else []
        record = produced.get("convergence")
        if record is not None:
            solutions[i] = produced.get("ehl_solution")
            if not record.converged:
                messages.append(f"not converged: {record.message}")
        elif use is model:
            messages += use.check_validity({k: s[k][i] for k in ("U", "G", "W", "M", "L")})
        if (s["M"][i] > STEADY_M_LIMIT or reversal[i]) and not note:
            messages.insert(0, f"u_m ≈ 0: entrainment reversal (u_m = {s['u_m'][i]:.3g} m/s, M = {s['M'][i]:.4g}); "
                               "the steady film → 0 there; squeeze film: effect 'squeeze'")
        regime[i] = "; ".join(messages) if messages else "ok"
    return {**values, "film_regime": regime, "film_solutions": solutions}


def _steadiest(w: np.ndarray, R: np.ndarray, u: np.ndarray) -> int:
    """The angle whose neighbours differ least in w, R and u (the base circle of a cam): the transient
    march starts there from the steady film, so its start is the periodic state."""
    def change(a):
        scale = np.max(np.abs(a)) or 1.0
        return (np.abs(a - np.roll(a, 1)) + np.abs(np.roll(a, -1) - a)) / scale

    score = change(w) + change(R) + change(u)
    score[u == 0.0] = np.inf
    return int(np.argmin(score))


def _transient_films(model, s, speed_factor: float, piezo: bool) -> dict:
    """Films over the turn from one transient march with the squeeze term (the ``squeeze`` effect)."""
    from ..ehl.line_transient import transient_cycle

    theta, omega = np.asarray(s["cam_angle"], dtype=float), float(s["angular_speed"][0])
    open_ = np.asarray(s["contact_open"]) | (np.asarray(s["w"]) <= 0.0)
    if np.any(open_):
        raise InputError(f"the squeeze (transient) film needs contact at every angle; the follower leaves the cam at "
                         f"{_degrees(theta[open_][:3])}: stiffen the spring or lower the speed")
    if not np.allclose(s["angular_speed"], omega) or theta.size < 3:
        raise InputError("the squeeze (transient) film needs a constant cam speed and at least 3 angles over the turn")
    u = np.asarray(s["u_m"], dtype=float) * speed_factor
    start = _steadiest(np.asarray(s["w"]), np.asarray(s["R"]), u)
    order = np.roll(np.arange(theta.size), -start)
    times = np.mod(theta[order] - theta[start], 2.0 * np.pi) / omega
    state = s["lubricant_state"]
    roelands = getattr(state.pressure_law, "name", "roelands") == "roelands"
    result = transient_cycle(
        times, np.asarray(s["w"])[order], np.asarray(s["R"])[order], u[order], E_reduced=s["E_reduced"],
        eta0=s["eta0"], alpha=s["alpha_effective"] if piezo else 0.0,
        z=state.roelands_z if roelands and piezo else None, viscosity="roelands" if roelands and piezo else "barus",
        density=s["density_law"], levels=model.levels, tolerance=max(model.tolerance, 1e-6),
        strict=model.strict)
    films = {"h_c": np.empty(theta.size), "h_min": np.empty(theta.size)}
    films["h_c"][order], films["h_min"][order] = result.h_c, result.h_min
    regime = np.empty(theta.size, dtype=object)
    for k, i in enumerate(order):
        note = "transient (squeeze)" + (" at u_m = 0" if u[i] == 0.0 else "")
        regime[i] = note if result.converged[k] else f"{note}: not converged: {result.records[k].message}"
    return {**films, "film_regime": regime, "film_solutions": [None] * theta.size}


#: the fewest distinct angles per warm-started chain (each chain starts cold, ~0.1-0.4 s at level 8)
MIN_CHAIN = 16


def _chain_count(model, solves: int) -> int:
    """How many warm-started chains (threads) the numerical film of a cycle uses: the model's
    ``threads`` (None: the CPUs, at most 4), but no chain shorter than :data:`MIN_CHAIN`."""
    import os

    threads = getattr(model, "threads", 1)
    threads = min(os.cpu_count() or 1, 4) if threads is None else int(threads)
    return max(1, min(threads, solves // MIN_CHAIN))


def _solve_chain(model, fallback, states) -> list:
    """Solve the states in order, each warm-started from the last numerical solution before it;
    an angle the solver cannot do falls back to the Pan–Hamrock formula with the reason."""
    previous = None
    out = []
    for state in states:
        produced, failure = _solve_numerically(model, state, previous)
        if produced is None:
            out.append((fallback(state), fallback, f"multigrid failed ({failure}): Pan–Hamrock formula"))
            continue
        previous = produced["ehl_solution"]
        out.append((produced, model, ""))
    return out


def _solve_numerically(model, state, previous):
    """Multigrid film warm-started from ``previous``; if that diverges or does not converge, once
    more from a cold (full-multigrid) start, keeping a converged result if either gives one.
    The caller silences the solver's ConvergenceWarning (the regime column reports it).

    Returns (produced, None) or (None, failure message).
    """
    from ..errors import ConvergenceError

    failure = None
    best = None
    for initial in ((previous, None) if previous is not None else (None,)):
        try:
            produced = model.evaluate(**state, initial=initial)
        except ConvergenceError as exc:
            failure = str(exc).split(";")[0]
            continue
        if produced["convergence"].converged:
            return produced, None
        best = best or produced  # not converged: the record says so in the regime column
    return (best, None) if best is not None else (None, failure)


def _spike_height(solution) -> float:
    """P_s of the numerical solution's pressure spike; NaN when it has no distinct spike (a single
    pressure maximum), 0 where no numerical solution was made (contact lost, u_m = 0, formula fallback)."""
    if solution is None:
        return 0.0
    spike = solution.spike
    return math.nan if spike is None else spike[0]


def _films(model) -> tuple[str, ...]:
    """The films a model gives (h_c and/or h_min); a scene without lubricant plans with both."""
    provides = getattr(model, "provides", ("h_c", "h_min"))
    return tuple(q for q in ("h_c", "h_min") if q in provides)
