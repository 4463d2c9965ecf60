"""Catalogue of the named quantities an Analysis can report: SI unit, display unit, meaning.

Reports hold plain float columns named ``"name [unit]"``; the unit is the display unit
below unless the caller asks for another (``Result.to_frame(units={"h_min": "nm"})``).
"""

from __future__ import annotations

import attrs

from .errors import InputError

__all__ = ["QUANTITIES", "QuantitySpec", "spec"]


@attrs.frozen
class QuantitySpec:
    """A reportable quantity."""

    name: str
    si_unit: str  #: pint unit of the SI value held inside ("" = dimensionless, None = text)
    display_unit: str  #: unit of the report column by default
    description: str


def _q(name: str, si_unit: str | None, display_unit: str | None, description: str) -> QuantitySpec:
    return QuantitySpec(name, si_unit, display_unit if display_unit is not None else si_unit, description)


QUANTITIES: dict[str, QuantitySpec] = {
    q.name: q
    for q in (
        _q("E_reduced", "Pa", "GPa", "reduced modulus E' = 2/[(1-nu1^2)/E1 + (1-nu2^2)/E2]"),
        _q("R", "m", "mm", "reduced radius of curvature 1/R = 1/R1 + 1/R2"),
        _q("w", "N/m", "N/mm", "load per unit length"),
        _q("u_m", "m/s", "m/s", "entrainment speed (u1 + u2)/2"),
        _q("u_s", "m/s", "m/s", "sliding speed u1 - u2"),
        _q("slide_roll_ratio", "", "", "slide-to-roll ratio (u1 - u2)/u_m"),
        _q("b", "m", "um", "Hertz half-width"),
        _q("p_h", "Pa", "MPa", "Hertz maximum pressure"),
        _q("p_mean", "Pa", "MPa", "Hertz mean pressure"),
        _q("approach", "m", "um", "elastic approach of the bodies"),
        _q("tau_max", "Pa", "MPa", "maximum in-plane principal shear stress (body 1)"),
        _q("x_tau_max", "m", "um", "position of tau_max along the rolling direction"),
        _q("z_tau_max", "m", "um", "depth of tau_max"),
        _q("tresca_max", "Pa", "MPa", "maximum 3-D (Tresca) shear stress (body 1)"),
        _q("z_tresca_max", "m", "um", "depth of tresca_max"),
        _q("von_mises_max", "Pa", "MPa", "maximum von Mises stress (body 1)"),
        _q("z_von_mises_max", "m", "um", "depth of von_mises_max"),
        _q("tau_xz_max", "Pa", "MPa", "maximum orthogonal shear stress"),
        _q("x_tau_xz_max", "m", "um", "position of tau_xz_max"),
        _q("z_tau_xz_max", "m", "um", "depth of tau_xz_max"),
        _q("tau_xz_range", "Pa", "MPa", "orthogonal shear range 2 tau_0 (fatigue amplitude)"),
        _q("temperature", "K", "degC", "lubricant (inlet) temperature"),
        _q("eta0", "Pa*s", "mPa*s", "dynamic viscosity at ambient pressure"),
        _q("kinematic_viscosity", "m^2/s", "cSt", "kinematic viscosity at ambient pressure"),
        _q("alpha", "1/Pa", "1/GPa", "pressure-viscosity coefficient"),
        _q("roelands_z", "", "", "Roelands pressure-viscosity index"),
        _q("thermoviscous_coefficient", "1/K", "1/K", "beta = -d ln(nu)/dT"),
        _q("U", "", "", "Hamrock speed parameter eta0 u_m/(E' R)"),
        _q("G", "", "", "Hamrock materials parameter alpha E'"),
        _q("W", "", "", "Hamrock load parameter"),
        _q("M", "", "", "Moes load parameter"),
        _q("L", "", "", "Moes lubricant parameter"),
        _q("h_c_isothermal", "m", "um", "isothermal central film thickness"),
        _q("h_min_isothermal", "m", "um", "isothermal minimum film thickness"),
        _q("thermal_loading", "", "", "thermal loading parameter beta eta0 (u1+u2)^2/k"),
        _q("thermal_factor", "", "", "inlet shear-heating film reduction factor phi_T"),
        _q("h_c", "m", "um", "central film thickness"),
        _q("h_min", "m", "um", "minimum film thickness"),
        _q("sigma", "m", "um", "composite RMS roughness"),
        _q("Lambda_c", "", "", "specific film thickness h_c/sigma"),
        _q("Lambda_min", "", "", "specific film thickness h_min/sigma"),
        _q("regime", None, None, "lubrication regime from Lambda (h_min if available)"),
        _q("film_validity", None, None, "'ok' or where the film model is used outside its fitted range"),
    )
}


def spec(name: str) -> QuantitySpec:
    """The catalogue entry of ``name`` (InputError listing the names if unknown)."""
    try:
        return QUANTITIES[name]
    except KeyError:
        raise InputError(f"unknown quantity {name!r}; known: {', '.join(QUANTITIES)}") from None
