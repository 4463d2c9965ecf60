"""Traction steps: the creepage and slip of the ball-cone CVT's contacts under the tangential force they
must transmit, with spin (Kalker's FASTSIM, :mod:`camcontact.contact.fastsim`; Saccheto 2008 §3.3).

Forces [N], semi-axes [m], shear modulus [Pa], spin [1/m]; creepages [-].
"""

from __future__ import annotations

from ..contact.fastsim import GrossSlipError, fastsim, solve_creepage
from ..step_graph import step

__all__ = ["ball_cone_traction", "transmitted_traction"]


def transmitted_traction(model, tangential_force: float, a_rolling: float, a_transverse: float, normal_force: float,
                         traction_coefficient: float, shear_modulus: float, spin: float) -> dict:
    """FASTSIM creepage that transmits ``tangential_force`` at one contact, or the saturated (gross-slip)
    traction when the contact cannot: creepage, slip fraction, regime text and the FASTSIM result."""
    a, b, N, mu, G = a_rolling, a_transverse, normal_force, traction_coefficient, shear_modulus
    grid = {"nx": model.nx, "ny": model.ny, "compiled": model.compiled}
    try:
        solution = solve_creepage(tangential_force, a, b, N, mu, G, spin=spin, **grid)
        result, creepage, regime = solution.result, solution.creepage, "partial slip"
    except GrossSlipError as exc:
        # the contact cannot transmit F_t: traction saturated at Ct p everywhere (creepage far past the limit)
        creepage = -1e3 * mu * N / (G * a * b)
        result = fastsim(a, b, N, mu, G, creepage_x=creepage, spin=spin, **grid)
        regime = f"gross slip: F_t/F_n = {exc.traction_needed:.4g} >= Ct = {mu:.4g}"
    return {"creepage": creepage, "slip_fraction": result.slip_fraction, "traction_regime": regime,
            "fastsim": result}


@step("traction", provides=("creepage_in", "creepage_out", "slip_fraction_in", "slip_fraction_out",
                            "traction_regime_in", "traction_regime_out", "fastsim_in", "fastsim_out"),
      model=lambda traction_model: traction_model.name)
def ball_cone_traction(traction_model, a_rolling, a_transverse, normal_force, traction_coefficient, shear_modulus,
                       tangential_force_in, tangential_force_out, spin_in, spin_out, spin):
    """:func:`transmitted_traction` at the CVT's input and output contact; the spin creepage enters
    only with the ``spin`` effect."""
    out = {}
    for side, force, phi in (("in", tangential_force_in, spin_in), ("out", tangential_force_out, spin_out)):
        solution = transmitted_traction(traction_model, force, a_rolling, a_transverse, normal_force,
                                        traction_coefficient, shear_modulus, phi if spin else 0.0)
        out.update({f"{key}_{side}": value for key, value in solution.items()})
    return out
