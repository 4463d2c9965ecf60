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
    composite roughness, amplitude sigma / sqrt 2 and the roughness stress 5.172 ((amp/lambda)(R_x/a))^0.931 p0
    (Eqs. 29, 30, 8);
``film``
    lubricant properties at the working temperature (Walther m, n; nu, eta, Gold alpha, beta, k, c;
    Eqs. 32-39), Hamrock U, G, W (Eq. 42), Grubin h0 and Dowson-Higginson h_min (Eqs. 40, 41), the
    inlet-heating, starvation and roughness factors, h_oc and Lambda (Eqs. 43, 44, 46, 13), with the
    thesis's temperature loop where the convention runs it;
``friction``
    Benedict-Kelley mu (Eq. 49); pure rolling lies outside that correlation: mu is then NaN with the
    reason in ``friction_validity`` and there is no frictional heating;
``temperatures``
    flash temperature (Eq. 48), surface maximum (Eq. 47), viscosity at the mean pressure and the
    Couette film rise (App. D), the lubricant's maximum temperature and its check against the
    lubricant's upper service temperature;
``checks``
    the plastic-deformation and fatigue rules of the thesis's §4.1 (or Tresca).

Model slot ``convention``: ``"thesis"`` (default), ``"corrected"`` or a
:class:`~camcontact.scenes.raceway_conventions.RacewayConvention`; a list runs them side by side
(one row each). Source: ../shared/reference/spherical_roller_bearing_delabenetta2021.md.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from ..analysis import SceneGraph, Step, checked_request, scene_builder
from ..components.raceway_contact import RacewayContact
from ..contact.contact_temperature import couette_temperature_rise, flash_temperature
from ..contact.geometry import reduced_modulus, reduced_radius
from ..contact.hertz_line import hertz_line
from ..contact.roughness import composite_roughness, lubrication_regime
from ..contact.subsurface import line_subsurface
from ..ehl.groups import hamrock_line
from ..errors import InputError
from ..models.film_line import DowsonHigginson, Grubin
from ..models.film_thermal import inlet_heating_factor, slide_roll_measure, thermal_loading
from ..models.friction import Kelley
from ..models.oil_thermal_properties import oil_specific_heat, oil_thermal_conductivity
from ..models.pressure_viscosity_coefficient import gold_alpha
from ..models.viscosity_pressure import ROELANDS_P0, Roelands
from ..models.viscosity_temperature import Walther
from .raceway_conventions import RacewayConvention, resolve_convention

__all__ = ["build_raceway_contact", "roughness_stress", "thesis_temperature_loop"]

CST = 1e-6  # m^2/s per cSt
CELSIUS = 273.15
#: the thesis's loop step [K] and the most steps it may take before giving up
LOOP_STEP, LOOP_LIMIT = 0.1, 3000
#: the EHD range of the film the thesis checks (§4.2.3) [m]
EHD_RANGE = (0.1e-6, 15e-6)
DEFAULT_OUTPUTS = (
    # Table 7 (Hertz, stresses)
    "E_star", "R_x", "b", "contact_area", "p_mean", "p_h", "tau_max", "z_tau_max", "tau_oct_max", "tau_roughness",
    "tau_xz_max", "x_tau_xz_max", "z_tau_xz_max", "tau_xz_range",
    # Table 5 (lubricant at the working temperature)
    "temperature", "walther_n", "walther_m", "kinematic_viscosity", "eta0", "alpha", "roelands_z",
    "thermoviscous_coefficient", "lubricant_conductivity", "lubricant_specific_heat",
    # kinematics, Table 8 (film, friction, temperatures)
    "u_raceway", "u_roller", "slide_roll_measure", "speed_basis", "h_c", "h_min", "thermal_loading",
    "thermal_factor", "starvation_factor", "roughness_factor", "h_c_corrected", "Lambda_oc", "regime",
    "film_validity", "friction_coefficient", "friction_validity", "flash_temperature", "surface_temperature_max",
    "viscosity_at_mean_pressure", "film_temperature_rise", "lubricant_temperature_max",
    "lubricant_temperature_check", "yield_check", "fatigue_check",
)
HINTS = {
    "effusivity": "give density, specific_heat and thermal_conductivity of both materials (flash temperature)",
    "yield_strength": "give RacewayContact.raceway_material.yield_strength",
    "roughness_wavelength": "give RacewayContact.roughness_wavelength (roughness stress)",
    "roller_speed": "give RacewayContact.roller_speed (this convention does not derive the rolling speed)",
}
#: Thesis stress constants (Eqs. 7, 9, 10)
THESIS_STRESS = {"tau_max": 0.30, "z_tau_max": 0.7861, "tau_oct": 0.27, "tau_xz": 0.25, "x_tau_xz": 0.85,
                 "z_tau_xz": 0.42}


def roughness_stress(amplitude: float, wavelength: float, R_x: float, a: float, p0: float) -> float:
    """Stress due to a sinusoidal roughness [Pa]: 5.172 ((amp/lambda)(R_x/a))^0.931 p0
    (Delabenetta 2021 Eq. 8, after Seabra 2003; R_x = 2R', a the Hertz half-width)."""
    return 5.172 * ((amplitude / wavelength) * (R_x / a)) ** 0.931 * p0


def thesis_temperature_loop(start_celsius: float, lambda_min: float, lambda_at) -> tuple[float, Any]:
    """The thesis's temperature loop (Appendix D): ``T -= 0.1`` (first step before any evaluation)
    while Lambda <= lambda_min; returns (theta [°C], what ``lambda_at(theta)`` returned last).

    ``lambda_at(theta)`` returns (Lambda, anything). After :data:`LOOP_LIMIT` steps without
    Lambda > lambda_min an InputError names the input.
    """
    theta = start_celsius
    where = f"RacewayContact.lambda_min = {lambda_min:g}: the thesis's temperature loop"
    for _ in range(LOOP_LIMIT):
        theta -= LOOP_STEP
        try:
            lam, payload = lambda_at(theta)
        except InputError as exc:
            raise InputError(f"{where} reached {theta:.1f} °C without Lambda above it, where: {exc}") from None
        if lam > lambda_min:
            return theta, payload
    raise InputError(f"{where} reached {theta:.1f} °C ({LOOP_LIMIT} steps of {LOOP_STEP} K) with Lambda = "
                     f"{lam:.4g} still not above it")


@scene_builder(RacewayContact)
def build_raceway_contact(contact: RacewayContact, *, models: Mapping[str, Any],
                          effects: frozenset | None) -> SceneGraph:
    """Scene graph of a :class:`~camcontact.components.RacewayContact` (one variant)."""
    checked_request("raceway_contact", models, effects, slots=("convention",), supported=(), default=())
    convention = resolve_convention(models.get("convention", "thesis"))
    si = contact.si
    m1, m2 = contact.raceway_material, contact.roller_material
    inputs: dict[str, Any] = {
        "E1": m1.si.E, "nu1": m1.nu, "E2": m2.si.E, "nu2": m2.nu, "F": si.load, "length": si.length,
        "R1": si.raceway_radius, "R2": si.roller_radius, "ring_speed": si.ring_speed / (2 * math.pi),
        "sigma1": si.raceway_roughness, "sigma2": si.roller_roughness, "lubricant": contact.lubricant,
        "temperature_start": si.temperature, "lambda_min": contact.lambda_min,
        "slide_roll_ratio": contact.slide_roll_ratio,
    }
    if contact.roller_speed is not None:
        inputs["roller_speed"] = si.roller_speed / (2 * math.pi)
    if contact.roughness_wavelength is not None:
        inputs["roughness_wavelength"] = si.roughness_wavelength
    if m1.yield_strength is not None:
        inputs["yield_strength"] = m1.si.yield_strength
    try:
        inputs["effusivity"] = (m1.thermal_effusivity(), m2.thermal_effusivity())
    except InputError:
        pass  # only the temperatures need it: reported up front if they are asked for

    concave = contact.raceway == "outer" and not convention.convex_raceway
    steps = [
        Step("geometry", ("E1", "nu1", "E2", "nu2", "R1", "R2"), ("E_reduced", "R", "E_star", "R_x"),
             lambda s: _geometry(s, concave), model=f"{'concave' if concave else 'convex'} raceway"),
        _kinematics_step(contact, convention),
        Step("hertz", ("F", "length", "R", "E_reduced"), ("w", "b", "p_mean", "p_h", "contact_area"), _hertz,
             model="hertz_line"),
        Step("subsurface", ("b", "p_h", "nu1"),
             ("tau_max", "z_tau_max", "tresca_max", "tau_oct_max", "tau_xz_max", "x_tau_xz_max", "z_tau_xz_max",
              "tau_xz_range"),
             lambda s: _subsurface(s, convention), model=convention.stress),
        Step("roughness", ("sigma1", "sigma2"), ("sigma", "roughness_amplitude"),
             lambda s: {"sigma": composite_roughness(s["sigma1"], s["sigma2"]),
                        "roughness_amplitude": composite_roughness(s["sigma1"], s["sigma2"]) / math.sqrt(2.0)}),
        Step("roughness_stress", ("roughness_amplitude", "roughness_wavelength", "R_x", "b", "p_h"),
             ("tau_roughness",),
             lambda s: {"tau_roughness": roughness_stress(s["roughness_amplitude"], s["roughness_wavelength"],
                                                          s["R_x"], s["b"], s["p_h"])}, model="seabra_eq8"),
        _film_step(contact, convention),
        Step("friction", ("F", "length", "eta0", "u_raceway", "u_roller"), ("friction_coefficient", "friction_validity"),
             _friction, model="kelley"),
        _temperature_step(contact, convention),
        Step("checks", ("tau_max", "tresca_max", "tau_xz_range", "yield_strength"), ("yield_check", "fatigue_check"),
             lambda s: _checks(s, convention), model=convention.yield_rule),
    ]
    return SceneGraph(kind="raceway_contact", inputs=inputs, steps=tuple(steps), default_outputs=DEFAULT_OUTPUTS,
                      input_hints=HINTS, plotter=_plot, effects=frozenset())


# ----------------------------------------------------------------------------- steps
def _geometry(s, concave: bool) -> dict:
    E_reduced = reduced_modulus(s["E1"], s["nu1"], s["E2"], s["nu2"])
    R = reduced_radius(-s["R1"] if concave else s["R1"], s["R2"])
    return {"E_reduced": E_reduced, "R": R, "E_star": 0.5 * E_reduced, "R_x": 2.0 * R}


def _kinematics_step(contact: RacewayContact, convention: RacewayConvention) -> Step:
    provides = ("u_raceway", "u_roller", "u_m", "slide_roll_measure", "speed_basis")
    if convention.derive_rolling_speed:
        d_m = contact.pitch_diameter
        gamma = 2.0 * contact.si.roller_radius / d_m

        def run(s):
            rolling = 0.5 * math.pi * d_m * (1.0 - gamma**2) * s["ring_speed"]
            slip = s["slide_roll_ratio"]
            u1, u2 = rolling * (1.0 + 0.5 * slip), rolling * (1.0 - 0.5 * slip)
            return {"u_raceway": u1, "u_roller": u2, "u_m": rolling, "slide_roll_measure": _slide_roll(u1, u2),
                    "speed_basis": f"pure rolling in the cage frame (d_m = {d_m * 1e3:.4g} mm), slide/roll {slip:g}"}

        return Step("kinematics", ("ring_speed", "slide_roll_ratio"), provides, run, model="pure_rolling")

    def run_given(s):
        u1 = s["R1"] * 2 * math.pi * s["ring_speed"]
        u2 = s["R2"] * 2 * math.pi * s["roller_speed"]
        return {"u_raceway": u1, "u_roller": u2, "u_m": 0.5 * (u1 + u2), "slide_roll_measure": _slide_roll(u1, u2),
                "speed_basis": "given ring and roller speeds, ground frame (Delabenetta Eq. 31)"}

    return Step("kinematics", ("R1", "R2", "ring_speed", "roller_speed"), provides, run_given, model="given_speeds")


def _slide_roll(u1: float, u2: float) -> float:
    if u1 + u2 <= 0.0:
        raise InputError("raceway_contact: the surfaces do not move (ring_speed = 0): no entrainment, no film")
    return float(slide_roll_measure(u1, u2))


def _hertz(s) -> dict:
    w = s["F"] / s["length"]
    result = hertz_line(w, s["R"], s["E_reduced"])
    return {"w": w, "b": result.b, "p_mean": result.p_mean, "p_h": result.p_h,
            "contact_area": 2.0 * result.b * s["length"]}


def _subsurface(s, convention: RacewayConvention) -> dict:
    b, p0 = s["b"], s["p_h"]
    if convention.stress == "thesis_constants":
        c = THESIS_STRESS
        # the thesis's Z_0 = 78.12 um is 0.42 x a with a rounded to whole micrometres (erratum 4)
        # in plane strain the in-plane principal shear is the largest shear below the surface
        return {"tau_max": c["tau_max"] * p0, "z_tau_max": c["z_tau_max"] * b, "tresca_max": c["tau_max"] * p0,
                "tau_oct_max": c["tau_oct"] * p0,
                "tau_xz_max": c["tau_xz"] * p0, "x_tau_xz_max": c["x_tau_xz"] * b,
                "z_tau_xz_max": c["z_tau_xz"] * round(b * 1e6) * 1e-6, "tau_xz_range": 2.0 * c["tau_xz"] * p0}
    field = line_subsurface(b, p0, nu=s["nu1"])
    return {"tau_max": field.principal_shear_max.value, "z_tau_max": field.principal_shear_max.z,
            "tresca_max": field.tresca_max.value,
            "tau_oct_max": math.sqrt(2.0) / 3.0 * field.von_mises_max.value,
            "tau_xz_max": field.tau_xz_max.value, "x_tau_xz_max": abs(field.tau_xz_max.x),
            "z_tau_xz_max": field.tau_xz_max.z, "tau_xz_range": field.orthogonal_shear_range}


def _lubricant_properties(lubricant, theta: float, convention: RacewayConvention) -> dict:
    """Lubricant state at theta [°C] in the convention's way (SI floats)."""
    kelvin = theta + convention.celsius_offset
    if convention.lubricant_data == "thesis":
        missing = [f for f in ("nu40", "nu100", "density") if getattr(lubricant, f) is None]
        if missing:
            raise InputError(f"Lubricant {lubricant.name!r}: the thesis convention needs {', '.join(missing)} "
                             "(Walther through nu40 and nu100, Eqs. 32-35)")
        offset = convention.celsius_offset
        law = Walther(a=0.7).fit([40.0 + offset, 100.0 + offset], [lubricant.si.nu40, lubricant.si.nu100])
        nu = float(law.viscosity(kelvin))
        gravity = lubricant.si.density / 1000.0
        return {"walther_m": law.m, "walther_n": law.n, "kinematic_viscosity": nu, "eta0": nu * lubricant.si.density,
                "alpha": gold_alpha(nu / CST, law.m, gravity, "mineral"),
                "thermoviscous_coefficient": float(law.thermoviscous_coefficient(kelvin)),
                "lubricant_conductivity": oil_thermal_conductivity(theta, gravity),
                "lubricant_specific_heat": oil_specific_heat(theta, gravity), "pressure_law": None}
    state = lubricant.state(theta + CELSIUS)
    if state.alpha is None:
        raise InputError(f"Lubricant {lubricant.name!r} has no pressure-viscosity data (alpha, roelands_z or "
                         "alpha_correlation), which the film needs")
    if state.thermoviscous_coefficient is None:
        raise InputError(f"Lubricant {lubricant.name!r}: the inlet-heating factor needs temperature-dependent "
                         "viscosity data (nu40/nu100 or viscosity_data)")
    gravity = None if state.density is None else state.density / 1000.0
    conductivity, heat = state.thermal_conductivity, state.specific_heat
    if (conductivity is None or heat is None) and gravity is None:
        raise InputError(f"Lubricant {lubricant.name!r}: give thermal_conductivity and specific_heat, or its density "
                         "for the correlations of Delabenetta Eqs. 38-39")
    law = lubricant.temperature_law
    return {"walther_m": getattr(law, "m", math.nan), "walther_n": getattr(law, "n", math.nan),
            "kinematic_viscosity": state.kinematic_viscosity, "eta0": state.eta0, "alpha": state.alpha,
            "thermoviscous_coefficient": state.thermoviscous_coefficient,
            "lubricant_conductivity": conductivity if conductivity is not None else oil_thermal_conductivity(theta, gravity),
            "lubricant_specific_heat": heat if heat is not None else oil_specific_heat(theta, gravity),
            "pressure_law": state}


FILM_OUTPUTS = (
    "temperature", "walther_m", "walther_n", "kinematic_viscosity", "eta0", "alpha", "roelands_z",
    "thermoviscous_coefficient", "lubricant_conductivity", "lubricant_specific_heat", "lubricant_pressure_state",
    "U", "G", "W", "h_c", "h_min", "thermal_loading", "thermal_factor", "starvation_factor", "roughness_factor",
    "h_c_corrected", "Lambda_oc", "regime", "film_validity",
)


def _film_step(contact: RacewayContact, convention: RacewayConvention) -> Step:
    lubricant = contact.lubricant
    grubin = Grubin(exponent_digits=convention.grubin_exponent_digits)
    dowson = DowsonHigginson()
    starvation = convention.starvation_factor
    if starvation is None:
        starvation = 0.7 if lubricant.form == "grease" else 1.0

    def chain(s, theta: float) -> dict:
        props = _lubricant_properties(lubricant, theta, convention)
        U, G, W = hamrock_line(s["w"], s["R"], s["E_reduced"], s["u_m"], props["eta0"], props["alpha"])
        state = {"R": s["R"], "w": s["w"], "E_reduced": s["E_reduced"], "u_m": s["u_m"], "eta0": props["eta0"],
                 "alpha": props["alpha"]}
        h0, hm = grubin(state)["h_c"], dowson(state)["h_min"]
        L = float(thermal_loading(props["thermoviscous_coefficient"], props["eta0"], s["u_raceway"], s["u_roller"],
                                  props["lubricant_conductivity"]))
        phi_t = float(inlet_heating_factor(L, s["slide_roll_measure"]))
        h_oc = phi_t * starvation * convention.roughness_factor * h0
        z = Roelands().z(props["eta0"], props["alpha"])
        messages = grubin.check_validity({"U": U, "G": G, "W": W}) + dowson.check_validity({"U": U, "G": G, "W": W})
        if not EHD_RANGE[0] < h_oc < EHD_RANGE[1]:
            messages.append(f"h_oc = {h_oc * 1e6:.4g} um outside the EHD range 0.1-15 um (Delabenetta §4.2.3)")
        pressure_state = props.pop("pressure_law")
        return {**props, "temperature": theta + CELSIUS, "roelands_z": z, "lubricant_pressure_state": pressure_state,
                "U": U, "G": G, "W": W, "h_c": h0, "h_min": hm, "thermal_loading": L, "thermal_factor": phi_t,
                "starvation_factor": starvation, "roughness_factor": convention.roughness_factor,
                "h_c_corrected": h_oc, "Lambda_oc": h_oc / s["sigma"], "regime": lubrication_regime(h_oc / s["sigma"]),
                "film_validity": "; ".join(dict.fromkeys(messages)) or "ok"}

    def run(s):
        start = s["temperature_start"] - CELSIUS
        if not convention.temperature_loop:
            return chain(s, start)

        def lambda_at(theta):
            result = chain(s, theta)
            return result["Lambda_oc"], result

        return thesis_temperature_loop(start, s["lambda_min"], lambda_at)[1]

    return Step("film", ("w", "R", "E_reduced", "u_m", "u_raceway", "u_roller", "slide_roll_measure", "sigma",
                         "lubricant", "temperature_start", "lambda_min"), FILM_OUTPUTS, run,
                model=f"{grubin.name}/{dowson.name}")


def _friction(s) -> dict:
    if s["u_raceway"] == s["u_roller"]:
        return {"friction_coefficient": math.nan,
                "friction_validity": "pure rolling: the Kelley correlation needs sliding (no frictional heating)"}
    mu = Kelley()({"normal_force": s["F"], "contact_length": s["length"], "eta0": s["eta0"],
                   "u1": s["u_raceway"], "u2": s["u_roller"]})["friction_coefficient"]
    return {"friction_coefficient": float(mu), "friction_validity": "ok"}


def _temperature_step(contact: RacewayContact, convention: RacewayConvention) -> Step:
    upper = contact.lubricant.si.upper_temperature

    def run(s):
        mu = s["friction_coefficient"]
        sliding = abs(s["u_raceway"] - s["u_roller"])
        if math.isnan(mu):  # pure rolling: no frictional heat in these models (mu |du| -> 0)
            flash = 0.0
        else:
            flash = flash_temperature(s["w"], s["E_reduced"], s["R"], mu, s["u_raceway"], s["u_roller"],
                                      *s["effusivity"])
        if convention.roelands_log10_constant is not None:
            c = convention.roelands_log10_constant
            z = s["roelands_z"]
            eta_p = 10.0 ** ((math.log10(s["eta0"]) + c) * (1.0 + s["p_mean"] / ROELANDS_P0) ** z - c)
        elif s["lubricant_pressure_state"] is not None:
            eta_p = float(s["lubricant_pressure_state"].viscosity(s["p_mean"]))
        else:
            eta_p = float(Roelands().viscosity(s["p_mean"], s["eta0"], s["alpha"]))
        rise = couette_temperature_rise(s["thermoviscous_coefficient"], sliding, eta_p, s["lubricant_conductivity"])
        surface = s["temperature"] + flash
        lubricant_max = surface + rise if convention.absolute_lubricant_temperature else CELSIUS + rise
        if upper is None:
            check = "no upper service temperature given"
        else:
            label = "T_smax + rise" if convention.absolute_lubricant_temperature else "the rise, as the thesis"
            verdict = "exceeds" if lubricant_max > upper else "within"
            check = (f"{verdict} the upper service temperature {upper - CELSIUS:.4g} °C by "
                     f"{abs(lubricant_max - upper):.3g} K ({label})")
        return {"flash_temperature": flash, "surface_temperature_max": surface, "viscosity_at_mean_pressure": eta_p,
                "film_temperature_rise": rise, "lubricant_temperature_max": lubricant_max,
                "lubricant_temperature_check": check}

    return Step("temperatures", ("w", "E_reduced", "R", "friction_coefficient", "u_raceway", "u_roller", "effusivity",
                                 "eta0", "alpha", "roelands_z", "p_mean", "thermoviscous_coefficient", "lubricant_conductivity",
                                 "lubricant_pressure_state", "temperature"),
                ("flash_temperature", "surface_temperature_max", "viscosity_at_mean_pressure", "film_temperature_rise",
                 "lubricant_temperature_max", "lubricant_temperature_check"), run, model="blok_couette")


def _checks(s, convention: RacewayConvention) -> dict:
    yield_strength = s["yield_strength"]
    if convention.yield_rule == "thesis":
        shear, limit, label = s["tau_max"], yield_strength, "tau_max vs sigma_y (thesis §4.1)"
    else:
        shear = s["tresca_max"]
        limit, label = 0.5 * yield_strength, "Tresca: tau_max vs sigma_y / 2"
    plastic = "plastic deformation" if shear >= limit else "no plastic deformation"
    fatigue = ("fatigue probable (2 tau_0 > sigma_y, thesis §4.1 rule)" if s["tau_xz_range"] > yield_strength
               else "no fatigue by the thesis's rule (2 tau_0 <= sigma_y)")
    return {"yield_check": f"{plastic}: {shear * 1e-6:.4g} MPa vs {limit * 1e-6:.4g} MPa ({label})",
            "fatigue_check": f"{fatigue}: 2 tau_0 = {s['tau_xz_range'] * 1e-6:.4g} MPa, sigma_y = "
                             f"{yield_strength * 1e-6:.4g} MPa"}


def _plot(result, **kwargs):
    from .raceway_contact_plots import plot_raceway_contact

    return plot_raceway_contact(result, **kwargs)

