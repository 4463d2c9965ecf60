"""The raceway contact's lubricant-and-film chain (Delabenetta 2021), in the thesis's or the corrected way.

Lubricant properties at the working temperature (Walther m, n; nu, eta, Gold alpha, beta, k, c;
Eqs. 32-39), Hamrock U, G, W (Eq. 42), Grubin h0 and Dowson–Higginson h_min (Eqs. 40, 41), the
inlet-heating, starvation and roughness factors, h_oc and Lambda (Eqs. 43, 44, 46, 13), with the
thesis's temperature loop (Appendix D) where the convention runs it. The convention object
(:class:`camcontact.scenes.raceway_conventions.RacewayConvention`) holds each choice as a switch.
Temperatures [K] (the loop steps in °C as the thesis), films [m], viscosities [Pa s].
"""

from __future__ import annotations

import math
from typing import Any

import attrs

from ..contact.roughness import lubrication_regime
from ..ehl.groups import hamrock_line
from ..errors import InputError
from ..models.film_line import DowsonHigginson, Grubin
from ..models.film_thermal import inlet_heating_factor, thermal_loading
from ..models.oil_thermal_properties import oil_specific_heat, oil_thermal_conductivity
from ..models.pressure_viscosity_coefficient import gold_alpha
from ..models.viscosity_pressure import Roelands
from ..models.viscosity_temperature import Walther
from ..step_graph import step

__all__ = ["CELSIUS", "EHD_RANGE", "FILM_OUTPUTS", "LOOP_LIMIT", "LOOP_STEP", "raceway_film_chain", "raceway_lubricant_state",
           "raceway_lubricant_properties", "thesis_temperature_loop"]

CST = 1e-6  # m^2/s per cSt
CELSIUS = 273.15
#: the thesis's loop step [K] and the most steps it may take before giving up
LOOP_STEP, LOOP_LIMIT = 0.1, 3000
#: the EHD range of the film the thesis checks (§4.2.3) [m]
EHD_RANGE = (0.1e-6, 15e-6)
FILM_OUTPUTS = (
    "temperature", "walther_m", "walther_n", "kinematic_viscosity", "eta0", "alpha", "roelands_z",
    "thermoviscous_coefficient", "lubricant_conductivity", "lubricant_specific_heat", "lubricant_pressure_state",
    "U", "G", "W", "h_c", "h_min", "thermal_loading", "thermal_factor", "starvation_factor", "roughness_factor",
    "h_c_corrected", "Lambda_oc", "regime", "film_validity",
)


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


def raceway_lubricant_properties(lubricant, theta: float, convention) -> dict:
    """Lubricant state at theta [°C] in the convention's way (SI floats): the thesis's Walther fit through
    nu40/nu100, Gold alpha and the oil correlations, or the lubricant's own laws."""
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


def _film_at(theta: float, lubricant, convention, starvation: float, grubin, dowson, w, R, E_reduced, u_m,
             u_raceway, u_roller, slide_roll_measure, sigma) -> dict:
    """The chain at theta [°C]."""
    props = raceway_lubricant_properties(lubricant, theta, convention)
    U, G, W = hamrock_line(w, R, E_reduced, u_m, props["eta0"], props["alpha"])
    state = {"R": R, "w": w, "E_reduced": E_reduced, "u_m": u_m, "eta0": props["eta0"], "alpha": props["alpha"]}
    h0, hm = grubin(state)["h_c"], dowson(state)["h_min"]
    L = float(thermal_loading(props["thermoviscous_coefficient"], props["eta0"], u_raceway, u_roller,
                              props["lubricant_conductivity"]))
    phi_t = float(inlet_heating_factor(L, slide_roll_measure))
    h_oc = phi_t * starvation * convention.roughness_factor * h0
    z = Roelands().z(props["eta0"], props["alpha"])
    messages = grubin.check_validity({"U": U, "G": G, "W": W}) + dowson.check_validity({"U": U, "G": G, "W": W})
    if not EHD_RANGE[0] < h_oc < EHD_RANGE[1]:
        messages.append(f"h_oc = {h_oc * 1e6:.4g} um outside the EHD range 0.1-15 um (Delabenetta §4.2.3)")
    pressure_state = props.pop("pressure_law")
    return {**props, "temperature": theta + CELSIUS, "roelands_z": z, "lubricant_pressure_state": pressure_state,
            "U": U, "G": G, "W": W, "h_c": h0, "h_min": hm, "thermal_loading": L, "thermal_factor": phi_t,
            "starvation_factor": starvation, "roughness_factor": convention.roughness_factor,
            "h_c_corrected": h_oc, "Lambda_oc": h_oc / sigma, "regime": lubrication_regime(h_oc / sigma),
            "film_validity": "; ".join(dict.fromkeys(messages)) or "ok"}


def _film_label(convention) -> str:
    return f"{Grubin(exponent_digits=convention.grubin_exponent_digits).name}/{DowsonHigginson().name}"


@step("film", provides=FILM_OUTPUTS, model=_film_label)
def raceway_film_chain(w, R, E_reduced, u_m, u_raceway, u_roller, slide_roll_measure, sigma, lubricant,
                       temperature_start, lambda_min, convention):
    """The lubricant at the working temperature and the films of the raceway contact (module docstring);
    the thesis's loop lowers the temperature from ``temperature_start`` [K] until Lambda > lambda_min
    where the convention runs it. Starvation phi_A: the convention's, or 0.7 for a grease, 1 for an oil."""
    starvation = convention.starvation_factor
    if starvation is None:
        starvation = 0.7 if lubricant.form == "grease" else 1.0
    films = (Grubin(exponent_digits=convention.grubin_exponent_digits), DowsonHigginson())
    contact = (*films, w, R, E_reduced, u_m, u_raceway, u_roller, slide_roll_measure, sigma)
    start = temperature_start - CELSIUS
    if not convention.temperature_loop:
        return _film_at(start, lubricant, convention, starvation, *contact)

    def lambda_at(theta):
        result = _film_at(theta, lubricant, convention, starvation, *contact)
        return result["Lambda_oc"], result

    return thesis_temperature_loop(start, lambda_min, lambda_at)[1]


@step("traction_lubricant", provides=("lubricant_state",), model="chain's working temperature")
def raceway_lubricant_state(lubricant, temperature, eta0, alpha, thermoviscous_coefficient, lubricant_conductivity,
                            lubricant_specific_heat):
    """The lubricant state the EHL friction of the raceway contact shears: the lubricant's laws (pressure-viscosity,
    density) at the chain's working ``temperature`` [K] with the chain's own eta0 [Pa s], alpha [1/Pa], beta
    [1/K], conductivity [W/(m K)] and specific heat [J/(kg K)] — so the friction and the film see one oil, in
    the thesis's lubricant data (Walther through nu40/nu100, Gold alpha, Eqs. 32-39) as in the lubricant's."""
    state = lubricant.state(temperature)
    return {"lubricant_state": attrs.evolve(state, eta0=eta0, alpha=alpha,
                                            thermoviscous_coefficient=thermoviscous_coefficient,
                                            thermal_conductivity=lubricant_conductivity,
                                            specific_heat=lubricant_specific_heat)}
