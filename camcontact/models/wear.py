"""Wear models of a sliding contact (family ``wear_models``).

=================== ============================================== =====================================
name                formula                                        requires
=================== ============================================== =====================================
archard             Q = K N |u_s| / H                               normal_force, sliding_speed, hardness
ferrarese_uehara    q = A_L V (oxidative wear, power balance;       normal_force, R, E_reduced,
                    Ferrarese & Uehara Eqs. 10-13)                  angular_speed
=================== ============================================== =====================================

All inputs are SI floats or arrays (they broadcast); ``wear_rate`` is a worn volume per unit
time [m^3/s]. A normal force of 0 (contact open) gives zero wear, without warnings.
"""

from __future__ import annotations

import attrs
import numpy as np

from ..errors import InputError
from ..units import number_field, positive
from .base import WearModel, builtin, float_or_array
from .ferrarese_uehara_contact import (
    K_Q_PAPER,
    RPM_PER_RAD_PER_S,
    constant_field,
    derived_wear_constant,
    hertz_contact_area,
    k_L_field,
    speed_inputs,
)

__all__ = ["Archard", "FerrareseUeharaWear"]


@builtin
@attrs.frozen
class Archard(WearModel):
    """Archard (1953) adhesive wear: worn volume proportional to load and sliding distance.

    .. math:: \\dot V_w = \\frac{K\\,N\\,|u_s|}{H}

    the rate form of Archard's Q = K N / H (volume per unit sliding distance, as Ferrarese &
    Uehara quote it).

    Parameters
    ----------
    coefficient : float
        Dimensionless wear coefficient K [-], > 0 (typically 1e-8 .. 1e-2); required.

    Inputs (``requires``): ``normal_force`` N [N] (>= 0), ``sliding_speed`` u_s [m/s] (any
    sign) and ``hardness`` H [Pa] of the softer surface (> 0; :class:`~camcontact.Material`
    ``hardness``). Returns ``wear_rate`` [m^3/s].

    A wear depth rate would need the apparent contact area or pressure, which this model does
    not take; it is not provided.

    References
    ----------
    Archard, J.F. (1953) Contact and rubbing of flat surfaces, J. Appl. Phys. 24:981–988;
    Hutchings, I.M. (1992) Tribology: Friction and Wear of Engineering Materials, Edward
    Arnold, ch. 5; the comparison model of Ferrarese & Uehara (after Uehara & Padovese 1999).
    """

    name = "archard"
    reference = "Archard (1953) J. Appl. Phys. 24:981-988; Hutchings (1992) Tribology ch. 5"
    requires = ("normal_force", "sliding_speed", "hardness")
    provides = ("wear_rate",)

    coefficient: float = number_field(validators=[positive()],
                                      doc="dimensionless wear coefficient K [-]")

    def evaluate(self, normal_force, sliding_speed, hardness):
        """Worn volume rate [m^3/s] for N [N], u_s [m/s], H [Pa]."""
        N = np.asarray(normal_force, dtype=float)
        u = np.asarray(sliding_speed, dtype=float)
        H = np.asarray(hardness, dtype=float)
        if not all(np.all(np.isfinite(a)) for a in (N, u, H)):
            raise InputError("wear model 'archard': normal_force, sliding_speed and hardness must be finite "
                             "(got NaN or inf)")
        if np.any(N < 0.0):
            raise InputError(f"wear model 'archard': normal_force = {N.min():.6g} N is negative; "
                             "allowed: normal_force >= 0")
        if np.any(H <= 0.0):
            raise InputError(f"wear model 'archard': hardness = {H.min():.6g} Pa is out of range; "
                             "allowed: hardness > 0 [Pa]")
        return {"wear_rate": float_or_array(self.coefficient * N * np.abs(u) / H)}


@builtin
@attrs.frozen
class FerrareseUeharaWear(WearModel):
    """Ferrarese & Uehara oxidative wear: removal power equal to friction power.

    .. math::
        \\frac{F_{at}}{A_L}\\,q = F_{at}\\,V \\;\\Rightarrow\\; q = A_L V
        = k_L\\,\\pi\\left(\\frac{3 N R}{4 E}\\right)^{2/3}\\frac{\\pi}{30} n R
        \\qquad \\text{(Eqs. 10–13, with Eqs. 1, 3, 12)}

    Combined (Eq. 13, n in rpm):

    .. math:: q = k_q\\,R^{5/3} E^{-2/3} N^{2/3}\\,n

    With ``constant="derived"`` (default) q = A_L V from Eqs. 1, 3 and 12, which is Eq. 13 with
    k_q = pi^2 (3/4)^(2/3)/30 k_L = 0.2716 k_L. With ``constant="paper"`` it is Eq. 13 with the
    printed k_q = 8.644e-2 k_L, which is the derived constant divided by pi (the pi of Eq. 1
    dropped); use it only to reproduce the paper's numbers.

    E is the paper's modulus of Eq. 2, E = E'/2: the model takes camcontact's ``E_reduced`` = E'
    and halves it. The wear rate does not depend on the friction force or the viscosity (they
    cancel in the power balance), so the model needs no lubricant input.

    q is the volume swept by the lubricated area per unit time, under the paper's assumption
    (to be checked by experiment) that all friction power goes into removing material with
    unchanged properties. Its magnitude is that of a swept volume, not of a measured wear rate
    (1 kN, R = 20 mm, steel pair, 3000 rpm: q ~ 5e-6 m^3/s); the paper uses it to compare
    speeds and valve-train models (cycle means), and so should a user.

    Parameters
    ----------
    k_L : float
        Lubricated-area factor A_L/A_HERTZ [-], 1 <= k_L <= 3 (Eq. 3); required.
    constant : {"derived", "paper"}
        Source of k_q (see above); default ``"derived"``.

    Inputs (``requires``): ``normal_force`` N [N] (>= 0), ``R`` cam radius of curvature at the
    contact [m] (> 0), ``E_reduced`` E' [Pa], ``angular_speed`` omega of the cam [rad/s] (sign
    ignored). Returns ``wear_rate`` q [m^3/s] and ``contact_area`` A_L [m^2] (Eqs. 1, 3).

    References
    ----------
    Ferrarese, A. & Uehara, S.H. Friction and wear models in the cam-follower system, Escola
    Politecnica da USP, Eqs. 1, 3, 10-13.
    Hutchings, I.M. (1992) Tribology: Friction and Wear of Engineering Materials, Edward
    Arnold (Eq. 1 of the paper).
    """

    name = "ferrarese_uehara"
    reference = ("Ferrarese & Uehara, Friction and wear models in the cam-follower system (EPUSP), "
                 "Eqs. 1, 3, 10-13; Hutchings (1992) Tribology (Eq. 1)")
    requires = ("normal_force", "R", "E_reduced", "angular_speed")
    provides = ("wear_rate", "contact_area")
    #: the paper's simulations reach 3000 rpm (= 314.2 rad/s)
    validity = {"angular_speed": (0.0, 3000.0 / RPM_PER_RAD_PER_S)}

    k_L: float = k_L_field()
    constant: str = constant_field()

    @property
    def k_q(self) -> float:
        """k_q of Eq. 13 [SI, n in rpm, E = E'/2] in the selected ``constant`` mode."""
        return K_Q_PAPER * self.k_L if self.constant == "paper" else derived_wear_constant(self.k_L)

    def evaluate(self, normal_force, R, E_reduced, angular_speed):
        """See the class docstring (SI inputs; outputs in m^3/s and m^2)."""
        arrays, V = speed_inputs(f"wear model {self.name!r}", normal_force, R, E_reduced, angular_speed)
        N, R, E_red = (arrays[k] for k in ("normal_force", "R", "E_reduced"))
        area = self.k_L * np.asarray(hertz_contact_area(N, R, E_red))
        if self.constant == "paper":
            n = V / R * RPM_PER_RAD_PER_S  # |omega| in rpm
            rate = self.k_q * R ** (5.0 / 3.0) * arrays["E"] ** (-2.0 / 3.0) * N ** (2.0 / 3.0) * n
        else:
            rate = area * V
        return {"wear_rate": float_or_array(rate), "contact_area": float_or_array(area)}
