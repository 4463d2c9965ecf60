"""EHL traction with creep and spin (family ``traction_models``): the film's rheology over the contact ellipse.

============= ============================================== ==============================================
name          what                                           requires
============= ============================================== ==============================================
ehl_traction  creepage that transmits a force with spin,     normal_force, a_rolling, b_lateral, p_h, h_c,
              capacity, margin, spin moment, creep and       rolling_speed, spin_creepage, tangential_force,
              spin losses (Tevaarwerk & Johnson 1979)        lubricant_state (optional: effusivity)
============= ============================================== ==============================================

The physics is :mod:`camcontact.contact.spin_traction`; the film's shear law comes from a fluid
traction model of :mod:`camcontact.models.traction_fluid` (``fluid``; default: Eyring with the limiting
shear stress, parameters from the lubricant where a scene gives them). Beside
:class:`~camcontact.models.traction.Fastsim` (Kalker's dry creep theory with a Coulomb bound, Saccheto's method) in one model slot.
"""

from __future__ import annotations

from typing import Any

import attrs
import numpy as np

from ..contact.spin_traction import DEFAULT_ANGULAR, DEFAULT_MAX_CREEPAGE, DEFAULT_RADIAL, SpinTractionContact
from ..errors import InputError
from ..units import in_range, number_field
from .base import TractionModel, builtin
from .traction_fluid import EyringTraction, NewtonianTraction

__all__ = ["SPIN_TRACTION_OUTPUTS", "EhlTraction"]

#: outputs of :meth:`EhlTraction.evaluate`
SPIN_TRACTION_OUTPUTS = ("creepage", "traction_capacity", "traction_margin", "gross_slip", "spin_moment",
                         "creep_loss", "spin_loss", "power_loss", "traction_temperature_rise", "traction_regime",
                         "traction_valid")


def _count(low: int):
    def check(instance, attribute, value):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not low <= value <= 1024:
            raise InputError(f"{type(instance).__name__}.{attribute.name} = {value!r}; allowed: an integer, "
                             f"{low} <= n <= 1024")
    return check


def _fluid(instance, attribute, value):
    if value is not None and not isinstance(value, (EyringTraction, NewtonianTraction)):
        raise InputError(f"{type(instance).__name__}.fluid = {value!r}; allowed: None, an EyringTraction or a "
                         "NewtonianTraction (the film's shear law)")


@builtin
@attrs.frozen
class EhlTraction(TractionModel):
    """EHL traction of an elliptical contact with creep and spin, force-controlled.

    .. math:: \\mathbf{w} = V(\\nu_x - \\phi y,\\ \\nu_y + \\phi x), \\qquad
              \\boldsymbol\\tau = \\tau(p, |\\mathbf{w}|/h)\\,\\hat{\\mathbf{w}}, \\qquad
              F_x(\\nu_x) = F_t

    Parameters
    ----------
    fluid : EyringTraction or NewtonianTraction, optional
        The film's shear law (its ``thermal`` switches the lumped contact temperature). None: the
        scene's (Eyring bounded by the limiting shear stress, the lubricant's parameters), or
        ``EyringTraction()`` when evaluated alone.
    max_creepage : float
        Largest |nu_x| for the capacity (default 0.05), 0 < value <= 1.
    n_radial, n_angular : int
        Quadrature nodes over the ellipse (default 16 x 64).

    Inputs (``requires``): ``normal_force`` N [N], ``a_rolling``, ``b_lateral`` semi-axes [m], ``p_h`` [Pa],
    ``h_c`` central film [m], ``rolling_speed`` V [m/s], ``spin_creepage`` phi [1/m], ``tangential_force`` the
    force to transmit [N] (on the body; creepage of the opposite sign), ``lubricant_state``; optional
    ``effusivity`` for a thermal fluid. Returns ``creepage`` nu_x [-], ``traction_capacity`` [N],
    ``traction_margin`` 1 - |F_t|/capacity [-], ``gross_slip`` [bool], ``spin_moment`` [N m], ``creep_loss``,
    ``spin_loss``, ``power_loss`` [W], ``traction_temperature_rise`` [K], ``traction_regime`` ("viscous",
    "plateau" where the limiting shear stress bounds at least half the area, "gross slip") and
    ``traction_valid`` (the thermal balance converged).

    References
    ----------
    Tevaarwerk, J.L. & Johnson, K.L. (1979) J. Lubr. Technol. 101(3):266–273; Johnson & Tevaarwerk (1977)
    Proc. R. Soc. A 356:215–236; Bair & Winer (1979) J. Lubr. Technol. 101:251–257; Loewenthal & Zaretsky
    (1985) NASA RP-1154 §6.5–6.6.
    """

    name = "ehl_traction"
    reference = ("viscous EHL film with creep and spin over the Hertz ellipse: Tevaarwerk & Johnson (1979) J. Lubr. "
                 "Technol. 101:266-273; Eyring film Johnson & Tevaarwerk (1977); limiting shear stress Bair & Winer "
                 "(1979); losses Loewenthal & Zaretsky (1985) NASA RP-1154 §6.6")
    requires = ("normal_force", "a_rolling", "b_lateral", "p_h", "h_c", "rolling_speed", "spin_creepage",
                "tangential_force", "lubricant_state")
    optional_requires = ("effusivity",)
    provides = SPIN_TRACTION_OUTPUTS

    fluid: Any = attrs.field(default=None, validator=_fluid)
    max_creepage: float = number_field(default=DEFAULT_MAX_CREEPAGE, validators=[in_range(0.0, 1.0,
                                                                                          lower_inclusive=False)],
                                       doc="largest |nu_x| for the capacity [-]")
    n_radial: int = attrs.field(default=DEFAULT_RADIAL, validator=_count(4))
    n_angular: int = attrs.field(default=DEFAULT_ANGULAR, validator=_count(8))

    def contact(self, a_rolling, b_lateral, p_h, h_c, rolling_speed, lubricant_state, effusivity=None,
                fluid=None, field=None, asperity_load_fraction=0.0, boundary_friction=0.0) -> SpinTractionContact:
        """The contact prepared for many creepage states; ``fluid`` overrides :attr:`fluid`; ``field`` (a
        :class:`~camcontact.contact.spin_traction.PressureField`) puts it on a numerical pressure and film.

        Inputs: Hertz semi-axes ``a_rolling``, ``b_lateral`` [m], ``p_h`` [Pa], central film ``h_c`` [m],
        ``rolling_speed`` [m/s], the surfaces' ``effusivity`` [W s^0.5/(m^2 K)] (for a thermal fluid).

        Mixed lubrication: ``asperity_load_fraction`` f [-] of the Hertz load (p_h over the ellipse) is carried
        by the asperities at the uniform pressure f 2 p_h / 3 with the Coulomb coefficient ``boundary_friction``
        mu_b [-]; the film carries (1 - f) p_h with the Hertz shape on its film ``h_c`` (the film at the fluid's
        share; Johnson, Greenwood & Poon 1972). Not with a ``field`` (a smooth surfaces' numerical pressure)."""
        share = float(asperity_load_fraction)
        if not 0.0 <= share < 1.0:
            raise InputError(f"traction model 'ehl_traction': asperity_load_fraction = {asperity_load_fraction!r}; "
                             "allowed: 0 <= f < 1 (the film carries the rest)")
        if share > 0.0 and field is not None:
            raise InputError("traction model 'ehl_traction': an asperity_load_fraction with a numerical pressure field;"
                             " allowed: one of them (the field is the smooth surfaces' pressure of the whole load)")
        shear_law = fluid or self.fluid or EyringTraction()
        return SpinTractionContact(a=a_rolling, b=b_lateral, p_h=(1.0 - share) * p_h, film_thickness=h_c,
                                   rolling_speed=rolling_speed, n_radial=self.n_radial, n_angular=self.n_angular,
                                   field=field, asperity_pressure=share * 2.0 * p_h / 3.0,
                                   boundary_friction=boundary_friction,
                                   **shear_law.film_rheology(lubricant_state, effusivity))

    def solve(self, tangential_force, spin_creepage, contact: SpinTractionContact) -> dict[str, Any]:
        """The outputs of one contact (see the class docstring) and the solved state (``state``)."""
        state, peak = contact.solve_creepage(tangential_force, spin=spin_creepage, max_creepage=self.max_creepage)
        capacity = -peak.Fx
        gross = bool(abs(tangential_force) > capacity)
        regime = "gross slip" if gross else ("plateau" if state.limited_fraction >= 0.5 else "viscous")
        return {"creepage": state.creepage_x, "traction_capacity": capacity,
                "traction_margin": 1.0 - abs(tangential_force) / capacity if capacity > 0.0 else -np.inf,
                "gross_slip": gross, "spin_moment": state.Mz, "creep_loss": state.creep_loss,
                "spin_loss": state.spin_loss, "power_loss": state.power_loss,
                "traction_temperature_rise": state.temperature_rise, "traction_regime": regime,
                "traction_valid": bool(state.converged and peak.converged), "state": state}

    def evaluate(self, normal_force, a_rolling, b_lateral, p_h, h_c, rolling_speed, spin_creepage, tangential_force,
                 lubricant_state, effusivity=None):
        """One contact (SI floats); see the class docstring. ``normal_force`` is checked against the
        integral of p_h over the ellipse (a Hertz pressure of another load is an input error)."""
        contact = self.contact(a_rolling, b_lateral, p_h, h_c, rolling_speed, lubricant_state, effusivity)
        if not abs(contact.normal_force - normal_force) <= 1e-3 * abs(normal_force):
            raise InputError(f"traction model 'ehl_traction': normal_force = {normal_force!r} N but the Hertz pressure "
                             f"p_h = {p_h:.6g} Pa over the {a_rolling:.4g} x {b_lateral:.4g} m ellipse carries "
                             f"{contact.normal_force:.6g} N; allowed: consistent inputs (2/3 pi a b p_h = N)")
        out = self.solve(tangential_force, spin_creepage, contact)
        out.pop("state")
        return out
