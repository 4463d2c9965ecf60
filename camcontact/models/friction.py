"""Friction models of a sliding contact (family ``friction_models``).

=================== ============================================== =====================================
name                formula                                        requires
=================== ============================================== =====================================
coulomb             F = mu N, P = F |u_s|                           normal_force, sliding_speed
ferrarese_uehara    F = A_L eta0 V / h (Newtonian shear of the      normal_force, R, E_reduced, eta0,
                    EHL film; Ferrarese & Uehara Eqs. 1-9, 11)      angular_speed
kelley              mu = 0.0127 log10[C F_n/(eta0 l abs(u1 - u2)   normal_force, contact_length, eta0,
                    (u1 + u2)^2)] (Benedict & Kelley 1961;         u1, u2
                    Delabenetta 2021 Eq. 49)
=================== ============================================== =====================================

All inputs are SI floats or arrays (e.g. over cam angles; they broadcast). Forces and powers
are magnitudes (speed signs are ignored). A normal force of 0 means the contact is open (a
valve-train jump) and gives zero friction force, coefficient and power, without warnings.
"""

from __future__ import annotations

import attrs
import numpy as np

from ..errors import InputError
from ..units import in_range, number_field
from .base import FrictionModel, builtin, float_or_array
from .ferrarese_uehara_contact import (
    K_AT_PAPER,
    RPM_PER_RAD_PER_S,
    constant_field,
    derived_friction_constant,
    hertz_contact_area,
    hutchings_film_thickness,
    k_L_field,
    speed_inputs,
)

__all__ = ["Coulomb", "FerrareseUeharaFriction", "Kelley"]


@builtin
@attrs.frozen
class Coulomb(FrictionModel):
    """Coulomb (dry, constant-coefficient) friction.

    .. math:: F = \\mu N, \\qquad P = F\\,|u_s|

    Parameters
    ----------
    coefficient : float
        Friction coefficient mu [-], 0 <= mu <= 2 (above 1 only for clean, unlubricated metals).

    Inputs (``requires``): ``normal_force`` N [N] (>= 0; 0 = contact open) and
    ``sliding_speed`` u_s [m/s] (any sign). Returns ``friction_force`` [N],
    ``friction_coefficient`` [-] (mu, 0 where N = 0) and ``friction_power`` [W].

    References
    ----------
    Coulomb, C.A. (1785) Théorie des machines simples, Mém. Math. Phys. Acad. Sci. 10:161–332;
    the comparison model of Ferrarese & Uehara (after Uehara & Padovese 1999).
    """

    name = "coulomb"
    reference = "Coulomb (1785); comparison model of Ferrarese & Uehara (Uehara & Padovese 1999)"
    requires = ("normal_force", "sliding_speed")
    provides = ("friction_force", "friction_coefficient", "friction_power")

    coefficient: float = number_field(validators=[in_range(0.0, 2.0)],
                                      doc="friction coefficient mu [-]")

    def evaluate(self, normal_force, sliding_speed):
        """Friction force [N], coefficient [-] and power [W] for N [N], u_s [m/s]."""
        N = np.asarray(normal_force, dtype=float)
        u = np.asarray(sliding_speed, dtype=float)
        if not (np.all(np.isfinite(N)) and np.all(np.isfinite(u))):
            raise InputError("friction model 'coulomb': normal_force and sliding_speed must be finite (got NaN or inf)")
        if np.any(N < 0.0):
            raise InputError(f"friction model 'coulomb': normal_force = {N.min():.6g} N is negative; "
                             "allowed: normal_force >= 0")
        N, u = np.broadcast_arrays(N, u)
        force = self.coefficient * N
        return {
            "friction_force": float_or_array(force),
            "friction_coefficient": float_or_array(np.where(N > 0.0, self.coefficient, 0.0)),
            "friction_power": float_or_array(force * np.abs(u)),
        }


@builtin
@attrs.frozen
class FerrareseUeharaFriction(FrictionModel):
    """Ferrarese & Uehara friction: Newtonian shear of the EHL film over the lubricated area.

    .. math::
        A_{HERTZ} &= \\pi\\left(\\frac{3 N R}{4 E}\\right)^{2/3}, \\qquad
        A_L = k_L A_{HERTZ} \\qquad \\text{(Eqs. 1, 3)}\\\\
        h &= 2.8\\,R^{0.77}\\mu^{0.65}V^{0.65}E^{-0.44}N^{-0.21}, \\qquad V = \\omega R
        = \\tfrac{\\pi}{30} n R \\qquad \\text{(Eqs. 8, 12)}\\\\
        F_{at} &= \\tau A_L = A_L\\,\\mu\\,\\frac{V}{h}, \\qquad P_{at} = F_{at} V
        \\qquad \\text{(Eqs. 4–7, 11)}

    Combined (Eq. 9, n in rpm):

    .. math:: F_{at} = k_{at}\\,\\mu^{0.35} R^{0.247} E^{-0.227} N^{0.877} n^{0.35}

    With ``constant="derived"`` (default) the force is computed from the component equations
    above, which give the exponents of Eq. 9 exactly (0.35, 2/3 - 0.77 + 0.35 = 0.2467,
    -2/3 + 0.44 = -0.2267, 2/3 + 0.21 = 0.8767) and
    k_at = pi (3/4)^(2/3) (pi/30)^0.35 / 2.8 k_L = 0.4204 k_L. With ``constant="paper"`` it is
    Eq. 9 as printed, exponents rounded as printed and k_at = 9.699e-2 k_L. The printed
    constant disagrees with the paper's own Eqs. 1-8 by a factor 4.335 (it equals
    pi^2 (3/4)^(2/3)/(30 x 2.8) k_L, i.e. Eq. 8 evaluated with n R in place of V); use it only
    to reproduce the paper's numbers.

    Here mu is the lubricant's dynamic viscosity ``eta0`` [Pa*s] (the paper's symbol), E the
    paper's modulus of Eq. 2, E = [(1-nu1^2)/E1 + (1-nu2^2)/E2]^-1 = E'/2: the model takes
    camcontact's ``E_reduced`` = E' and halves it. Eq. 1 is the circular Hertz area of a
    sphere of radius R on a flat, which the paper applies to the cam.

    Parameters
    ----------
    k_L : float
        Lubricated-area factor A_L/A_HERTZ [-], 1 <= k_L <= 3 (EHL regime, Eq. 3); required.
    constant : {"derived", "paper"}
        Source of k_at (see above); default ``"derived"``.

    Inputs (``requires``): ``normal_force`` N [N] (>= 0), ``R`` cam radius of curvature at the
    contact [m] (> 0), ``E_reduced`` E' [Pa], ``eta0`` lubricant viscosity [Pa*s],
    ``angular_speed`` omega of the cam [rad/s] (sign ignored). Returns ``friction_force``
    F_at [N], ``friction_coefficient`` F_at/N [-], ``friction_power`` F_at V [W],
    ``contact_area`` A_L [m^2] (the lubricated area, Eqs. 1 and 3, in both modes) and
    ``film_thickness_hutchings`` h [m] (Eq. 8).

    N = 0 (contact open) gives zero force, coefficient, power and area and h = inf, without
    warnings; note that F_at/N ~ N^-0.123 grows without bound as N -> 0+, so the reported
    coefficient at very small loads is large and at N = 0 is set to 0 (no contact).
    omega = 0 gives zero friction (F_at ~ n^0.35).

    References
    ----------
    Ferrarese, A. & Uehara, S.H. Friction and wear models in the cam-follower system, Escola
    Politecnica da USP, Eqs. 1-9, 11, 12.
    Hutchings, I.M. (1992) Tribology: Friction and Wear of Engineering Materials, Edward
    Arnold (Eqs. 1 and 8 of the paper).
    """

    name = "ferrarese_uehara"
    reference = ("Ferrarese & Uehara, Friction and wear models in the cam-follower system (EPUSP), "
                 "Eqs. 1-9, 11, 12; Hutchings (1992) Tribology (Eqs. 1, 8)")
    requires = ("normal_force", "R", "E_reduced", "eta0", "angular_speed")
    provides = ("friction_force", "friction_coefficient", "friction_power", "contact_area",
                "film_thickness_hutchings")
    #: the paper's simulations reach 3000 rpm (= 314.2 rad/s)
    validity = {"angular_speed": (0.0, 3000.0 / RPM_PER_RAD_PER_S)}

    k_L: float = k_L_field()
    constant: str = constant_field()

    @property
    def k_at(self) -> float:
        """k_at of Eq. 9 [SI, n in rpm, E = E'/2] in the selected ``constant`` mode."""
        return K_AT_PAPER * self.k_L if self.constant == "paper" else derived_friction_constant(self.k_L)

    def evaluate(self, normal_force, R, E_reduced, eta0, angular_speed):
        """See the class docstring (SI inputs, outputs in N, -, W, m^2, m)."""
        arrays, V = speed_inputs(f"friction model {self.name!r}", normal_force, R, E_reduced, angular_speed, eta0=eta0)
        N, R, E_red, eta = (arrays[k] for k in ("normal_force", "R", "E_reduced", "eta0"))
        area = self.k_L * np.asarray(hertz_contact_area(N, R, E_red))
        h = np.asarray(hutchings_film_thickness(R, eta, V, E_red, N))
        loaded = N > 0.0
        sheared = loaded & (V > 0.0)
        if self.constant == "paper":
            n = V / R * RPM_PER_RAD_PER_S  # |omega| in rpm
            force = (self.k_at * eta**0.35 * R**0.247 * arrays["E"] ** -0.227
                     * N**0.877 * n**0.35)
        else:
            force = np.where(sheared, area * eta * V / np.where(sheared, h, 1.0), 0.0)
        coefficient = np.where(loaded, force / np.where(loaded, N, 1.0), 0.0)
        return {
            "friction_force": float_or_array(force),
            "friction_coefficient": float_or_array(coefficient),
            "friction_power": float_or_array(force * V),
            "contact_area": float_or_array(area),
            "film_thickness_hutchings": float_or_array(h),
        }



@builtin
@attrs.frozen
class Kelley(FrictionModel):
    """Benedict–Kelley friction coefficient of a rolling–sliding EHL line contact (SI form).

    .. math:: \\mu = 0.0127\\,\\log_{10}\\left[\\frac{C\\,F_n}{\\eta_0\\,l\\,|u_1 - u_2|\\,(u_1 + u_2)^2}\\right]

    with C = 29.66e-3 (the code of Delabenetta 2021 App. D; its text prints 29.662e-3) for F_n
    [N], eta0 [Pa*s], contact length l [m] and surface speeds u1, u2 [m/s] (Delabenetta 2021 Eq.
    49, after Benedict & Kelley 1961; the thesis calls it "Kelly"). The coefficient is clipped at
    0 where the logarithm's argument falls below 1 (very fast sliding or a light load); pure
    rolling (u1 = u2) is outside the correlation: InputError.

    Validity (:attr:`validity`, checked by :meth:`inside_validity` per contact): the slide-to-roll
    ratio S = |u1 - u2| / u_m, u_m = (u1 + u2)/2, within [0.01, 2]. Benedict & Kelley fitted the
    formula to disc-machine measurements that simulate gear-tooth contacts, i.e. with substantial
    sliding; their coefficient falls with the sliding speed and grows without bound as it goes
    to zero (0.066 at S = 2 %, 0.079 at S = 0.2 % on the most loaded roller of tutorial 5), whereas EHL
    traction is proportional to the slip in the linear region of a traction curve and vanishes
    with it (Johnson & Tevaarwerk 1977; Evans & Johnson 1986). The correlation can therefore only
    stand for the region beyond the traction maximum. The lower bound 1 % is a judgement of where
    measured traction curves of mineral oils at rolling-bearing pressures leave the linear region
    (the paper's own test range was not available to this implementation); the upper bound 2 is
    kinematic: beyond it the surfaces move in opposite directions and the entrainment term
    (u1 + u2)^2 of the formula goes to zero.

    Parameters
    ----------
    constant : float
        C [m^2/s^2] (makes the argument dimensionless in SI); default 29.66e-3.

    Inputs (``requires``): ``normal_force`` F_n [N] (>= 0), ``contact_length`` l [m], ``eta0``
    [Pa*s], ``u1``, ``u2`` surface speeds [m/s]. Returns ``friction_coefficient`` [-],
    ``friction_force`` mu F_n [N] and ``friction_power`` mu F_n |u1 - u2| [W].

    References
    ----------
    Benedict, G.H. & Kelley, B.W. (1961) Instantaneous coefficients of gear tooth friction, ASLE
    Trans. 4:59–70; Delabenetta (2021) Eq. 49 (reference §2.10), Table 8: mu = 0.037.
    Johnson, K.L. & Tevaarwerk, J.L. (1977) Shear behaviour of elastohydrodynamic oil films, Proc.
    R. Soc. Lond. A 356:215–236; Evans, C.R. & Johnson, K.L. (1986) Regimes of traction in
    elastohydrodynamic lubrication, Proc. IMechE C 200:313–324 (the shape of traction curves behind
    the lower bound of the validity).
    """

    name = "kelley"
    reference = "Benedict & Kelley (1961); Delabenetta (2021) Eq. 49, Table 8"
    requires = ("normal_force", "contact_length", "eta0", "u1", "u2")
    provides = ("friction_coefficient", "friction_force", "friction_power")
    #: slide-to-roll ratio S = |u1 - u2| / u_m [-] (see the class docstring for the sources of the bounds)
    validity = {"slide_roll_ratio": (0.01, 2.0)}

    constant: float = number_field(default=29.66e-3, validators=[in_range(0.0, lower_inclusive=False)])

    @staticmethod
    def validity_values(u1, u2) -> dict:
        """The quantities :attr:`validity` ranges, from the surface speeds u1, u2 [m/s]:
        ``slide_roll_ratio`` S = |u1 - u2| / u_m [-] (inf where u_m = 0)."""
        u1, u2 = np.asarray(u1, dtype=float), np.asarray(u2, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = np.where(u1 + u2 != 0.0, np.abs(u1 - u2) / np.abs(0.5 * (u1 + u2)), np.inf)
        return {"slide_roll_ratio": float_or_array(ratio)}

    def inside_validity(self, u1, u2):
        """True where the contact lies inside :attr:`validity` (bool, or a bool array over the inputs);
        :meth:`check_validity` with :meth:`validity_values` gives the reason as text."""
        inside = np.ones(np.broadcast(np.asarray(u1), np.asarray(u2)).shape, dtype=bool)
        for key, value in self.validity_values(u1, u2).items():
            low, high = self.validity[key]
            value = np.asarray(value, dtype=float)
            if low is not None:
                inside &= value >= low
            if high is not None:
                inside &= value <= high
        return bool(inside) if inside.ndim == 0 else inside

    def evaluate(self, normal_force, contact_length, eta0, u1, u2):
        """Coefficient [-], force [N] and power [W] for SI inputs (scalars or arrays)."""
        F, l, eta = (np.asarray(v, dtype=float) for v in (normal_force, contact_length, eta0))
        u1, u2 = np.asarray(u1, dtype=float), np.asarray(u2, dtype=float)
        if not all(np.all(np.isfinite(v)) for v in (F, l, eta, u1, u2)):
            raise InputError("friction model 'kelley': inputs must be finite (got NaN or inf)")
        if np.any(F < 0) or np.any(l <= 0) or np.any(eta <= 0):
            raise InputError(f"friction model 'kelley': normal_force = {F.min():.6g} N, contact_length = "
                             f"{l.min():.6g} m, eta0 = {eta.min():.6g} Pa*s; allowed F >= 0, l > 0, eta0 > 0")
        sliding = np.abs(u1 - u2)
        if np.any(sliding == 0.0) or np.any(u1 + u2 == 0.0):
            raise InputError("friction model 'kelley': the correlation needs sliding (u1 != u2) and rolling "
                             f"(u1 + u2 != 0); got u1 = {u1}, u2 = {u2} m/s")
        with np.errstate(divide="ignore"):
            argument = self.constant * F / (eta * l * sliding * (u1 + u2) ** 2)
            mu = np.where(argument > 1.0, 0.0127 * np.log10(np.where(argument > 0, argument, 1.0)), 0.0)
        return {"friction_coefficient": float_or_array(mu), "friction_force": float_or_array(mu * F),
                "friction_power": float_or_array(mu * F * sliding)}
