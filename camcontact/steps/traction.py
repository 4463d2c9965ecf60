"""Traction steps: the creepage of the ball-cone CVT's contacts under the tangential force they must
transmit, with spin; their capacity, margin, gross slip, spin moment and losses; the drive's efficiency.

Two models in one slot: Kalker's FASTSIM with a Coulomb bound Ct p (:mod:`camcontact.contact.fastsim`;
Saccheto 2008 §3.3, the thesis's method; capacity Ct N, reached at unbounded creep) and the EHL film's
traction with spin (:mod:`camcontact.contact.spin_traction`, model ``ehl_traction``; capacity the
largest force at |creepage| <= its ``max_creepage``). Losses per contact: the creep loss -V (nu_x F_x +
nu_y F_y) and the spin loss -V phi M_z (in steady rolling the work of the creep forces and the spin
moment on the rigid creepages is the dissipation, for both models; Loewenthal & Zaretsky 1985, NASA
RP-1154 §6.6). Efficiency 1 - n (P_in + P_out)/P: the contact losses only (no bearing, churning or
windage losses); none (NaN) where a contact slips grossly and the drive does not transmit the power.

Forces [N], semi-axes [m], shear modulus [Pa], spin [1/m], speeds [m/s], powers [W]; creepages [-].
"""

from __future__ import annotations

import math

from ..contact.fastsim import GrossSlipError, fastsim, solve_creepage
from ..contact.spin_traction import rolling_losses
from ..errors import InputError
from ..step_graph import step

__all__ = ["CONTACT_TRACTION", "EHL_TRACTION", "FASTSIM_TRACTION", "ball_cone_ehl_traction", "ball_cone_efficiency",
           "ball_cone_traction", "ehl_contact", "ehl_model_label", "transmitted_traction"]

SIDES = ("in", "out")
#: per-contact outputs both traction models give (with the suffix _in / _out)
CONTACT_TRACTION = ("creepage", "traction_regime", "gross_slip", "traction_capacity", "traction_margin",
                    "spin_moment", "creep_loss", "spin_loss", "power_loss", "surface_traction")
#: the FASTSIM step's and the EHL step's outputs
FASTSIM_TRACTION = tuple(f"{q}_{side}" for q in CONTACT_TRACTION + ("slip_fraction",) for side in SIDES)
EHL_TRACTION = tuple(f"{q}_{side}" for q in CONTACT_TRACTION + ("traction_temperature_rise", "traction_valid",
                                                                  "traction_map")
                     for side in SIDES)


def transmitted_traction(model, tangential_force: float, a_rolling: float, a_transverse: float, normal_force: float,
                         traction_coefficient: float, shear_modulus: float, spin: float, rolling_speed: float) -> dict:
    """FASTSIM at one contact: the creepage that transmits ``tangential_force``, or the saturated traction
    where the contact cannot (gross slip: creepage far past the limit, Ct p everywhere); slip fraction,
    regime ("partial slip" / "gross slip") and ``gross_slip``, capacity Ct N and margin 1 - F_t/(Ct N),
    spin moment, losses (:func:`~camcontact.contact.spin_traction.rolling_losses`) and the FASTSIM result
    (``surface_traction``).

    Inputs: forces [N], semi-axes ``a_rolling``, ``a_transverse`` [m], traction coefficient Ct [-],
    ``shear_modulus`` [Pa], ``spin`` [1/m], ``rolling_speed`` [m/s]. Out: creepage, slip fraction, margin [-],
    capacity [N], spin moment [N m], losses [W]."""
    a, b, N, mu, G = a_rolling, a_transverse, normal_force, traction_coefficient, shear_modulus
    grid = {"nx": model.nx, "ny": model.ny, "compiled": model.compiled, "pressure": model.pressure}
    try:
        solution = solve_creepage(tangential_force, a, b, N, mu, G, spin=spin, **grid)
        result, creepage, gross = solution.result, solution.creepage, False
    except GrossSlipError:
        creepage = -1e3 * mu * N / (G * a * b)
        result = fastsim(a, b, N, mu, G, creepage_x=creepage, spin=spin, **grid)
        gross = True
    capacity = mu * N
    return {"creepage": creepage, "slip_fraction": result.slip_fraction,
            "traction_regime": "gross slip" if gross else "partial slip", "gross_slip": gross,
            "traction_capacity": capacity, "traction_margin": 1.0 - abs(tangential_force) / capacity,
            "spin_moment": result.Mz, "surface_traction": result,
            **rolling_losses(result.Fx, result.Fy, result.Mz, creepage, 0.0, spin, rolling_speed)}


@step("traction", provides=FASTSIM_TRACTION, model=lambda traction_model: f"fastsim ({traction_model.pressure})")
def ball_cone_traction(traction_model, a_rolling, a_transverse, normal_force, traction_coefficient, shear_modulus,
                       tangential_force_in, tangential_force_out, spin_in, spin_out, spin, rolling_speed_in,
                       rolling_speed_out):
    """FASTSIM (:func:`transmitted_traction`) at the CVT's input and output contact: creepage, slip
    fraction, regime ("partial slip" / "gross slip") and ``gross_slip``, capacity Ct N and margin
    1 - F_t/(Ct N), spin moment, creep and spin losses, and the FASTSIM result (``surface_traction``);
    the spin creepage enters only with the ``spin`` effect. Units as :func:`transmitted_traction`
    (forces [N], semi-axes [m], ``shear_modulus`` [Pa], spins [1/m], rolling speeds [m/s])."""
    out = {}
    for side, force, phi, speed in (("in", tangential_force_in, spin_in, rolling_speed_in),
                                    ("out", tangential_force_out, spin_out, rolling_speed_out)):
        solution = transmitted_traction(traction_model, force, a_rolling, a_transverse, normal_force,
                                        traction_coefficient, shear_modulus, phi if spin else 0.0, speed)
        out.update({f"{key}_{side}": value for key, value in solution.items()})
    return out


def ehl_contact(side: str, traction_model, fluid_model, a_rolling: float, a_transverse: float, p_h: float, h_c: float,
                rolling_speed: float, lubricant_state, inputs: dict):
    """The :class:`~camcontact.contact.spin_traction.SpinTractionContact` of one CVT contact (``side`` "in" or
    "out") as the EHL traction step solves it: on its central film h_c [m] (with ``mixed``: the film at the
    fluid's share, the asperities' share and the lubricant's ``boundary_friction`` from ``inputs``), on the
    numerical pressure field where ``inputs`` has one; an InputError for a film that is not > 0."""
    mixed = {}
    if f"asperity_load_fraction_{side}" in inputs:
        h_c = inputs[f"h_c_mixed_{side}"]
        mixed = {"asperity_load_fraction": inputs[f"asperity_load_fraction_{side}"],
                 "boundary_friction": inputs["boundary_friction"]}
    if not h_c > 0.0:  # a film model that failed (a numerical film that closed)
        raise InputError(f"traction step: the {side}put contact's central film h_c = {h_c!r} m; the EHL traction "
                         "needs a film > 0 (a numerical film that did not converge: finer levels, or a film "
                         "formula)")
    return traction_model.contact(a_rolling, a_transverse, p_h, h_c, rolling_speed, lubricant_state,
                                  inputs.get("effusivity"), fluid=fluid_model,
                                  field=inputs.get(f"pressure_field_{side}"), **mixed)


def ehl_model_label(fluid_model, numerical_pressure) -> str:
    """The EHL traction's model label in the step records: the fluid, thermal, numerical pressure."""
    return (f"ehl_traction ({fluid_model.name}{', thermal' if fluid_model.thermal else ''}"
            f"{', numerical pressure' if numerical_pressure else ''})")


@step("traction", provides=EHL_TRACTION,
      model=ehl_model_label)
def ball_cone_ehl_traction(traction_model, fluid_model, a_rolling, a_transverse, p_h, h_c_in, h_c_out,
                           tangential_force_in, tangential_force_out, spin_in, spin_out, spin, rolling_speed_in,
                           rolling_speed_out, lubricant_state, **inputs):
    """The EHL film's traction with spin (:class:`~camcontact.models.traction_spin.EhlTraction`) at the CVT's
    input and output contact, on each contact's central film: creepage, regime ("viscous", "plateau",
    "gross slip") and ``gross_slip``, capacity and margin, spin moment, creep and spin losses, the lumped
    temperature rise (thermal fluid), ``traction_valid``, the centre-line traction for the slice
    stresses (``surface_traction``) and the traction over the contact for its map (``traction_map``).
    Inputs (SI): semi-axes ``a_rolling``, ``a_transverse`` [m], ``p_h`` [Pa], central films ``h_c_in``,
    ``h_c_out`` [m], forces [N], spins [1/m], rolling speeds [m/s]; out: capacity [N], spin moment [N m],
    losses [W], temperature rise [K]. ``inputs``: ``effusivity`` of the surfaces [W s^0.5/(m^2 K)] for a thermal fluid;
    ``pressure_field_in``/``_out``, the numerical film's pressure and film (the traction is then taken
    over them instead of the Hertz pressure and the central film; None: Hertz) and ``numerical_pressure``
    (the scene's film is numerical: a side without a field — its solution did not converge — falls back
    to the Hertz pressure with ``traction_valid`` False). Mixed lubrication (the ``mixed`` effect):
    ``asperity_load_fraction_in``/``_out`` and ``h_c_mixed_in``/``_out`` of the mixed step and the lubricant's
    ``boundary_friction`` — the film carries its share on its own film, the asperities the rest with
    Coulomb friction along the local sliding (:meth:`~camcontact.models.traction_spin.EhlTraction.contact`)."""
    out = {}
    for side, force, phi, speed, h in (("in", tangential_force_in, spin_in, rolling_speed_in, h_c_in),
                                       ("out", tangential_force_out, spin_out, rolling_speed_out, h_c_out)):
        contact = ehl_contact(side, traction_model, fluid_model, a_rolling, a_transverse, p_h, h, speed,
                              lubricant_state, inputs)
        solution = traction_model.solve(force, phi if spin else 0.0, contact)
        state = solution.pop("state")
        solution["surface_traction"], solution["traction_map"] = contact.centre_line(state), contact.traction_map(state)
        if inputs.get("numerical_pressure") and contact.field is None:
            solution["traction_valid"] = False
        out.update({f"{key}_{side}": value for key, value in solution.items()})
    return out


@step("losses", provides=("power_loss", "efficiency"))
def ball_cone_efficiency(power, ball_count, power_loss_in, power_loss_out, gross_slip_in, gross_slip_out):
    """The drive's contact losses n (P_in + P_out) [W] and efficiency 1 - losses/power [-] (no bearing,
    churning or windage losses). Where a contact slips grossly the drive does not transmit the power: both
    NaN (the ``gross_slip`` columns say why; the contacts' own losses are those at their capacity)."""
    if gross_slip_in or gross_slip_out:
        return {"power_loss": math.nan, "efficiency": math.nan}
    loss = ball_count * (power_loss_in + power_loss_out)
    return {"power_loss": loss, "efficiency": 1.0 - loss / power}
