"""Traction curves of the ball-cone CVT's contacts: the traction coefficient |F_x|/N a contact transmits
against its creepage, with the contact's spin and without it, and where the drive runs on it.

A traction drive is designed on this curve: the operating point must sit on its rising (stable) part with a
margin below its top, and spin lowers and flattens the curve (Tevaarwerk & Johnson 1979, J. Lubr. Technol.
101:266–273; Loewenthal & Zaretsky 1985, NASA RP-1154 §6.5). Each point is the model
the scene's traction step solves with (:mod:`camcontact.steps.traction`) evaluated at a prescribed
longitudinal creepage: the EHL film's shear over the ellipse (``ehl_traction``: creepages 0 to its
``max_creepage``, where it takes the capacity) or Kalker's FASTSIM with its Coulomb bound (``fastsim``:
creepages 0 to 1.5 times the one that reaches 99 % of Ct N without spin, or of the operating creepage).

Creepages [-] (magnitudes), coefficients F/N [-], spin [1/m]. Only a scene that asks for
``traction_curve_in``/``_out`` (or the CVT plot's ``"traction"`` panel) computes them: 2 x 2 x 41 evaluations
of the traction model.
"""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..contact.fastsim import GrossSlipError, fastsim, solve_creepage
from ..step_graph import step
from .traction import SIDES, ehl_contact, ehl_model_label

__all__ = ["CURVE_POINTS", "TractionCurve", "ball_cone_ehl_traction_curve", "ball_cone_traction_curve",
           "creepage_grid"]

#: points of a traction curve (0 and 40 log-spaced creepages: the curve rises steeply at small creepage)
CURVE_POINTS = 41


@attrs.frozen(eq=False)
class TractionCurve:
    """The traction curve of one contact (SI floats; magnitudes: the transmitted force's sign left out).

    ``coefficient_no_spin`` is None where the scene runs without the ``spin`` effect (the curve has no
    spin then). :meth:`to_frame` gives it as a table."""

    creepage: np.ndarray  #: |nu_x| [-], ascending from 0
    coefficient: np.ndarray  #: |F_x|/N at the contact's spin [-]
    coefficient_no_spin: np.ndarray | None  #: |F_x|/N without spin [-] (None: no spin in the scene)
    #: |nu_x| of the operating point [-]; in gross slip where the capacity is taken (EHL: the curve's top;
    #: FASTSIM: inf, its capacity Ct N is reached at unbounded creep)
    operating_creepage: float
    operating_coefficient: float  #: |F_t|/N the contact must transmit [-]
    capacity_coefficient: float  #: the capacity / N [-] (the curve's top within its creepages)
    gross_slip: bool  #: the contact cannot transmit F_t
    spin: float  #: the contact's spin creepage phi [1/m] (0 without the spin effect)
    model: str  #: the traction model ("ehl_traction (eyring)", "fastsim (parabolic)")

    def to_frame(self):
        """pandas DataFrame: ``creepage [%]``, ``traction_coefficient [-]`` and (with spin)
        ``traction_coefficient_no_spin [-]``, one row per point."""
        import pandas as pd

        columns = {"creepage [%]": 100.0 * self.creepage, "traction_coefficient [-]": self.coefficient}
        if self.coefficient_no_spin is not None:
            columns["traction_coefficient_no_spin [-]"] = self.coefficient_no_spin
        return pd.DataFrame(columns)


def creepage_grid(top: float, points: int = CURVE_POINTS) -> np.ndarray:
    """0 and ``points`` - 1 creepages log-spaced from ``top``/1000 to ``top`` [-]."""
    return np.concatenate(([0.0], np.geomspace(1e-3 * top, top, points - 1)))


def _curve(evaluate, creepage, normal_force, spin, use_spin, **point) -> TractionCurve:
    """The curve of one contact from ``evaluate(nu_x, phi) -> F_x`` at ``creepage`` (and at phi = 0)."""
    with_spin = np.array([abs(evaluate(-nu, spin if use_spin else 0.0)) for nu in creepage]) / normal_force
    no_spin = (np.array([abs(evaluate(-nu, 0.0)) for nu in creepage]) / normal_force
               if use_spin and spin != 0.0 else None)
    return TractionCurve(creepage=creepage, coefficient=with_spin, coefficient_no_spin=no_spin,
                         spin=spin if use_spin else 0.0, **point)


@step("traction_curve", provides=tuple(f"traction_curve_{side}" for side in SIDES), model=ehl_model_label)
def ball_cone_ehl_traction_curve(traction_model, fluid_model, a_rolling, a_transverse, normal_force, p_h, h_c_in,
                                 h_c_out, tangential_force_in, tangential_force_out, spin_in, spin_out, spin,
                                 rolling_speed_in, rolling_speed_out, lubricant_state, creepage_in, creepage_out,
                                 traction_capacity_in, traction_capacity_out, gross_slip_in, gross_slip_out,
                                 **inputs):
    """The EHL traction curve (:class:`TractionCurve`) of the CVT's input and output contact: |F_x|/N at
    |nu_x| from 0 to the model's ``max_creepage`` on the contact the traction step solved (same film, mixed
    share, pressure field, thermal fluid; :func:`~camcontact.steps.traction.ehl_contact`), with the contact's
    spin and without it, and the step's operating creepage, needed coefficient |F_t|/N and capacity/N.
    ``inputs`` as :func:`~camcontact.steps.traction.ball_cone_ehl_traction`. Inputs (SI): semi-axes
    ``a_rolling``, ``a_transverse`` [m], ``p_h`` [Pa], central films ``h_c_in``, ``h_c_out`` [m], forces and
    capacities [N], spins [1/m], rolling speeds [m/s], the traction step's creepages [-]."""
    grid = creepage_grid(traction_model.max_creepage)
    label = ehl_model_label(fluid_model, inputs.get("numerical_pressure"))
    out = {}
    for side, h, speed, phi, force, nu, capacity, gross in (
            ("in", h_c_in, rolling_speed_in, spin_in, tangential_force_in, creepage_in, traction_capacity_in,
             gross_slip_in),
            ("out", h_c_out, rolling_speed_out, spin_out, tangential_force_out, creepage_out, traction_capacity_out,
             gross_slip_out)):
        contact = ehl_contact(side, traction_model, fluid_model, a_rolling, a_transverse, p_h, h, speed,
                              lubricant_state, inputs)
        out[f"traction_curve_{side}"] = _curve(
            lambda nu_x, phi_: contact.evaluate(nu_x, 0.0, phi_).Fx, grid, normal_force, phi, spin,
            operating_creepage=abs(nu), operating_coefficient=abs(force) / normal_force,
            capacity_coefficient=capacity / normal_force, gross_slip=bool(gross), model=label)
    return out


@step("traction_curve", provides=tuple(f"traction_curve_{side}" for side in SIDES),
      model=lambda traction_model: f"fastsim ({traction_model.pressure})")
def ball_cone_traction_curve(traction_model, a_rolling, a_transverse, normal_force, traction_coefficient,
                             shear_modulus, tangential_force_in, tangential_force_out, spin_in, spin_out, spin,
                             creepage_in, creepage_out, gross_slip_in, gross_slip_out):
    """FASTSIM's traction curve (:class:`TractionCurve`) of the CVT's input and output contact: |F_x|/N at
    |nu_x| from 0 to 1.5 times the larger of the creepage that reaches 99 % of Ct N without spin and the
    operating one (not in gross slip: that creepage is nominal), with the contact's spin and without it;
    the capacity is Ct N (Kalker 1982, Vehicle Syst. Dyn. 11:1–13; Saccheto 2008 §3.3). Inputs (SI):
    semi-axes ``a_rolling``, ``a_transverse`` [m], forces [N], Ct [-], ``shear_modulus`` [Pa], spins [1/m],
    the traction step's creepages [-]."""
    a, b, N, mu, G = a_rolling, a_transverse, normal_force, traction_coefficient, shear_modulus
    grid = {"nx": traction_model.nx, "ny": traction_model.ny, "compiled": traction_model.compiled,
            "pressure": traction_model.pressure}
    try:
        saturation = abs(solve_creepage(0.99 * mu * N, a, b, N, mu, G, **grid).creepage)
    except GrossSlipError:  # FASTSIM's discrete traction tops out just below 0.99 Ct N on a coarse grid
        saturation = 10.0 * mu * N / (G * a * b)
    out = {}
    for side, phi, force, nu, gross in (("in", spin_in, tangential_force_in, creepage_in, gross_slip_in),
                                        ("out", spin_out, tangential_force_out, creepage_out, gross_slip_out)):
        top = 1.5 * max(saturation, 0.0 if gross else abs(nu))
        out[f"traction_curve_{side}"] = _curve(
            lambda nu_x, phi_: fastsim(a, b, N, mu, G, creepage_x=nu_x, spin=phi_, **grid).Fx, creepage_grid(top),
            N, phi, spin, operating_creepage=math.inf if gross else abs(nu), operating_coefficient=abs(force) / N, capacity_coefficient=mu,
            gross_slip=bool(gross), model=f"fastsim ({traction_model.pressure})")
    return out
