"""The lubricant step: the lubricant's state at the scene temperature, shared by every scene with a film.

:meth:`camcontact.components.Lubricant.state` evaluates the viscosity-temperature law (Walther,
ASTM D341, Vogel), the pressure-viscosity data (alpha, Roelands z), the thermal data and the
density law; the ``compressibility`` effect decides whether the numerical film sees the
lubricant's density law or an incompressible one.
"""

from __future__ import annotations

from typing import Any

from ..errors import InputError
from ..step_graph import Step, step

__all__ = ["LUBRICANT_OUTPUTS", "check_pressure_viscosity", "isothermal_lubricant_state", "lubricant_inputs",
           "lubricant_label", "lubricant_state", "lubricant_step"]

LUBRICANT_OUTPUTS = ("lubricant_state", "eta0", "alpha", "roelands_z", "kinematic_viscosity",
                     "thermoviscous_coefficient", "lubricant_conductivity", "density_law", "viscosity_extrapolated")


def lubricant_inputs(lubricant: Any, temperature: float | None) -> dict[str, Any]:
    """The graph inputs of a scene's lubricant: ``lubricant`` and ``temperature`` [K], each when given
    (an input left out is reported up front, with the scene's hint, when an output needs it)."""
    return {name: value for name, value in (("lubricant", lubricant), ("temperature", temperature))
            if value is not None}


def lubricant_step(lubricant: Any, temperature: float | None) -> Step:
    """The lubricant step of a scene: :func:`isothermal_lubricant_state` for a lubricant whose viscosity
    does not depend on the temperature when none is given (and when there is no lubricant: the step then
    reports the lubricant missing), else :func:`lubricant_state` (which requires the temperature)."""
    isothermal = lubricant is None or (lubricant.isothermal and temperature is None)
    return Step.of(isothermal_lubricant_state if isothermal else lubricant_state)


def lubricant_label(lubricant) -> str:
    """``"<viscosity-temperature law>/<viscosity-pressure law>"`` of a lubricant (the step record's model)."""
    return "" if lubricant is None else f"{lubricant.viscosity_temperature_law}/{lubricant.viscosity_pressure_law}"


def check_pressure_viscosity(lubricant, piezoviscosity) -> None:
    """InputError when the ``piezoviscosity`` effect is on and the lubricant has no pressure-viscosity data."""
    if piezoviscosity and lubricant is not None and lubricant.alpha is None and lubricant.roelands_z is None \
            and lubricant.alpha_correlation is None:
        raise InputError(
            f"Lubricant {lubricant.name!r} has no pressure-viscosity data (alpha or roelands_z), which "
            "the 'piezoviscosity' effect needs; give it or switch the effect off"
        )


@step("lubricant", provides=LUBRICANT_OUTPUTS, model=lubricant_label, check=check_pressure_viscosity)
def lubricant_state(lubricant, temperature, compressibility):
    """The lubricant at ``temperature`` [K]: its state object, eta0
    [Pa s], alpha [1/Pa], Roelands z, kinematic viscosity [m^2/s], beta [1/K], conductivity [W/(m K)],
    the density law the numerical film uses (``"incompressible"`` unless ``compressibility``) and
    ``viscosity_extrapolated``: True when the temperature lies outside the viscosity data's temperatures
    (:meth:`~camcontact.components.Lubricant.extrapolates`: a 1000 °C oil from 40/100 °C data is said so)."""
    state = lubricant.state(temperature)
    return _outputs(lubricant, state, compressibility)


@step("lubricant", provides=LUBRICANT_OUTPUTS, model=lubricant_label, check=check_pressure_viscosity)
def isothermal_lubricant_state(lubricant, compressibility):
    """:func:`lubricant_state` of a lubricant whose viscosity does not depend on the temperature, when the
    scene gives none."""
    return _outputs(lubricant, lubricant.state(None), compressibility)


def _outputs(lubricant, state, compressibility) -> dict:
    return {
        "lubricant_state": state, "eta0": state.eta0, "alpha": state.alpha,
        "roelands_z": state.roelands_z, "kinematic_viscosity": state.kinematic_viscosity,
        "thermoviscous_coefficient": state.thermoviscous_coefficient,
        "lubricant_conductivity": state.thermal_conductivity,
        "density_law": lubricant.density_law if compressibility else "incompressible",
        "viscosity_extrapolated": lubricant.extrapolates(state.temperature),
    }
