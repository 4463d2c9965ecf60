"""Fluid traction models (family ``traction_models``): the film's rheology integrated over the Hertz contact.

=========== ============================================== ==============================================
name        shear law of the film                          requires
=========== ============================================== ==============================================
newtonian   tau = eta(p) u_s/h, bounded by tau_L           normal_force, p_h, b, h_c, u_s, u_m,
            (Bair & Winer 1979)                            lubricant_state (optional: effusivity)
eyring      tau = tau0 asinh(eta(p) u_s/(h tau0))          as newtonian
            (Johnson & Tevaarwerk 1977), bounded by tau_L
=========== ============================================== ==============================================

mu = int tau dA / int p dA over the Hertz pressure with the central film h_c uniform
(:mod:`camcontact.contact.fluid_traction`, which states the equations, the regime criterion and the lumped
thermal balance), or, given ``profile=`` (a :class:`~camcontact.contact.fluid_traction.PressureProfile`,
e.g. ``LineEHLSolution.traction_profile()``) in :meth:`contact`, :meth:`curve` or :meth:`evaluate`,
int tau dx / int p dx over a numerical line pressure and film h(x) = h_c profile.film_ratio. Both models
take the limiting shear stress tau_L = tau_L0 + Lambda_L p
(``limiting_shear_slope=None`` switches it off) and, with ``thermal=True``, the lumped contact temperature
rise (flash temperature of the surfaces + mean film rise) that lowers the viscosity by exp(-beta dT).

The file name says what it holds: the models of the ``traction_models`` family that derive traction from the
fluid film's rheology (beside :mod:`camcontact.models.traction`, the Coulomb-bounded creep models).

Default parameters and their sources (``[Pa]`` SI):

* ``eyring_stress`` tau0 = 5 MPa: the middle of the 2–10 MPa range of Eyring stresses fitted to mineral oils
  in disc-machine traction by Johnson & Tevaarwerk (1977) (as quoted in the project reference
  ``friction_traction_thermal.md`` §3; the paper's tau0 rises with temperature and pressure, a constant is
  the simplification).
* ``limiting_shear_slope`` Lambda_L = 0.047: measured for a paraffinic mineral oil (M100, ISO VG 100) by
  Höglund (1999, Wear 232:176–184), as tabulated by Arana, Larrañaga & Ulacia (2019, Proc. IMechE J
  233:303–316, Table 2: naphthenic N100 0.053, PAO100 0.035, a polyglycol 0.044), and Bair & Winer's (1979)
  0.047 for the mineral oil LVI 260 (5P4E: 0.088). The project reference's 0.03–0.1 spans these; an earlier
  default of 0.075 had no measured source.
* ``limiting_shear_stress`` tau_L0 = 0 (Bair & Winer's form through the origin).

These defaults are orders of magnitude for a mineral oil, not data of a particular fluid: give the
fluid's values where they are known.
"""

from __future__ import annotations

from typing import Any

import attrs
import numpy as np

from ..contact.fluid_traction import (
    DEFAULT_NODES,
    FluidTraction,
    FluidTractionContact,
    PressureProfile,
    TractionThermal,
    fluid_traction,
)
from ..errors import InputError
from ..units import in_range, number_field, one_of
from .base import TractionModel, builtin, float_or_array

__all__ = ["EYRING_STRESS", "LIMITING_SHEAR_SLOPE", "LIMITING_SHEAR_STRESS", "EyringTraction",
           "NewtonianTraction"]

#: tau0 [Pa]: middle of the 2–10 MPa of Johnson & Tevaarwerk (1977) for mineral oils (see the module docstring)
EYRING_STRESS = 5.0e6
#: Lambda_L [-]: a paraffinic mineral oil, Höglund (1999) / Bair & Winer (1979) (see the module docstring)
LIMITING_SHEAR_SLOPE = 0.047
#: tau_L0 [Pa]
LIMITING_SHEAR_STRESS = 0.0

_REQUIRES = ("normal_force", "p_h", "b", "h_c", "u_s", "u_m", "lubricant_state")
_PROVIDES = ("traction_coefficient", "traction_force", "traction_shear_stress", "traction_regime",
             "traction_valid", "traction_temperature_rise")
#: regime label of points without a usable film or contact data (NaN outputs, traction_valid False)
NO_FILM = "no film"


def _node_count(instance, attribute, value):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not 4 <= value <= 256:
        raise InputError(f"{type(instance).__name__}.{attribute.name} = {value!r}; allowed: an integer, 4 <= n <= 256")


def _bool(instance, attribute, value):
    if not isinstance(value, bool):
        raise InputError(f"{type(instance).__name__}.{attribute.name} = {value!r}; allowed: True or False")


@attrs.frozen
class _FluidTraction(TractionModel):
    """Shared part of the fluid traction models (not registered itself)."""

    requires = _REQUIRES
    optional_requires = ("effusivity",)
    provides = _PROVIDES
    rheology = ""

    limiting_shear_stress: float = number_field(default=LIMITING_SHEAR_STRESS, validators=[in_range(0.0, unit="Pa")],
                                                doc="tau_L0 [Pa]")
    limiting_shear_slope: float | None = number_field(default=LIMITING_SHEAR_SLOPE, optional=True,
                                                      validators=[in_range(0.0, 1.0)],
                                                      doc="Lambda_L [-]; None: no limiting shear stress")
    geometry: str = attrs.field(default="line", validator=one_of("line", "point"))
    thermal: bool = attrs.field(default=False, validator=_bool)
    effusivity_1: float | None = number_field(optional=True, validators=[in_range(0.0, lower_inclusive=False)],
                                              doc="effusivity of surface 1 [W s^0.5/(m^2 K)]; None: from the state")
    effusivity_2: float | None = number_field(optional=True, validators=[in_range(0.0, lower_inclusive=False)],
                                              doc="effusivity of surface 2 [W s^0.5/(m^2 K)]; None: as surface 1")
    n_nodes: int = attrs.field(default=DEFAULT_NODES, validator=_node_count)

    # ------------------------------------------------------------------ helpers
    def _rheology(self) -> dict[str, Any]:
        return {"rheology": self.rheology, "limiting_shear_stress": self.limiting_shear_stress,
                "limiting_shear_slope": self.limiting_shear_slope, "geometry": self.geometry,
                "n_nodes": self.n_nodes}

    def _viscosity(self, lubricant_state) -> tuple[float, Any]:
        eta0 = getattr(lubricant_state, "eta0", None)
        law = getattr(lubricant_state, "log_viscosity_ratio", None)
        if eta0 is None or not callable(law):
            raise InputError(f"traction model {self.name!r}: lubricant_state = {lubricant_state!r} must give eta0 "
                             "[Pa*s] and log_viscosity_ratio(p) (a camcontact LubricantState)")
        return eta0, law

    def _thermal(self, lubricant_state, effusivity) -> TractionThermal | None:
        if not self.thermal:
            return None
        first, second = self.effusivity_1, self.effusivity_2
        if first is None and effusivity is not None:
            pair = np.atleast_1d(np.asarray(effusivity, dtype=float))
            first = float(pair[0])
            second = float(pair[-1]) if second is None else second
        if first is None:
            raise InputError(f"traction model {self.name!r} with thermal=True needs the surfaces' effusivity: give "
                             "effusivity_1 (and effusivity_2) or the state's 'effusivity' [W s^0.5/(m^2 K)]")
        return TractionThermal.from_lubricant_state(lubricant_state, first, second)

    def film_rheology(self, lubricant_state, effusivity=None) -> dict[str, Any]:
        """The film's shear law as keyword inputs of the contact-level traction integrals (eta0,
        log_viscosity_ratio, rheology, eyring_stress, limiting_shear_stress, limiting_shear_slope and
        thermal — a :class:`~camcontact.contact.fluid_traction.TractionThermal` or None), e.g. for
        :class:`camcontact.contact.spin_traction.SpinTractionContact`."""
        eta0, law = self._viscosity(lubricant_state)
        rheology = {k: v for k, v in self._rheology().items() if k not in ("geometry", "n_nodes")}
        return {"eta0": eta0, "log_viscosity_ratio": law, "thermal": self._thermal(lubricant_state, effusivity),
                **rheology}

    def contact(self, p_h, b, h_c, u_m, lubricant_state, effusivity=None,
                profile: PressureProfile | None = None) -> FluidTractionContact:
        """The contact prepared once for many sliding speeds (e.g. a roller's traction table): its
        ``coefficient(u_s)`` gives mu [-] cheaply; inputs as :meth:`evaluate` (they broadcast with u_s);
        ``profile``: a numerical line pressure and film instead of the Hertz one (its batch shape
        broadcasts with the inputs)."""
        eta0, law = self._viscosity(lubricant_state)
        return FluidTractionContact(p_h=p_h, film_thickness=h_c, eta0=eta0, log_viscosity_ratio=law,
                                    entrainment_speed=u_m, half_width=b,
                                    thermal=self._thermal(lubricant_state, effusivity), profile=profile,
                                    **self._rheology())

    def curve(self, slide_roll_ratio, *, p_h, b, h_c, u_m, lubricant_state, effusivity=None,
              profile: PressureProfile | None = None) -> FluidTraction:
        """The traction curve at the slide-to-roll ratios S = u_s/u_m [-] of one contact (the regime per
        point identifies the linear, non-linear and plateau parts); ``profile`` as :meth:`contact`."""
        S = np.asarray(slide_roll_ratio, dtype=float)
        return self.contact(p_h, b, h_c, u_m, lubricant_state, effusivity,
                            profile=profile).solve(S * np.asarray(u_m, dtype=float))

    def evaluate(self, normal_force, p_h, b, h_c, u_s, u_m, lubricant_state, effusivity=None,
                 profile: PressureProfile | None = None):
        """Traction at each point (SI inputs: N [N], p_h [Pa], b half-width along rolling [m], h_c [m],
        u_s = u1 - u2 [m/s], u_m [m/s]); see the class docstring for the outputs. ``profile``: a numerical
        line pressure and film (x/b, p/p_h, h/h_c) instead of the Hertz pressure and uniform h_c, one
        for all points or one per point (batch shape broadcasting with the inputs)."""
        eta0, law = self._viscosity(lubricant_state)
        thermal = self._thermal(lubricant_state, effusivity)
        arrays = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (normal_force, p_h, b, h_c, u_s, u_m)))
        N, p, a, h, u, um = arrays
        if np.any(N < 0.0) or np.any(p < 0.0):
            raise InputError(f"traction model {self.name!r}: normal_force and p_h must be >= 0 (got "
                             f"{np.min(N):.6g} N, {np.min(p):.6g} Pa)")
        usable = np.isfinite(N) & np.isfinite(p) & np.isfinite(u) & np.isfinite(h) & (h > 0.0)
        if thermal is not None:
            usable &= np.isfinite(um) & np.isfinite(a) & (a > 0.0)
        shape = N.shape
        mu = np.full(shape, np.nan)
        stress, rise = np.full(shape, np.nan), np.full(shape, np.nan)
        regime = np.full(shape, NO_FILM, dtype=object)
        valid = np.zeros(shape, dtype=bool)
        if profile is not None and not isinstance(profile, PressureProfile):
            raise InputError(f"traction model {self.name!r}: profile = {type(profile).__name__}; allowed: None or a "
                             "PressureProfile")
        if profile is not None and profile.batch_shape:
            try:
                fits = np.broadcast_shapes(profile.batch_shape, shape) == shape
            except ValueError:
                fits = False
            if not fits:
                raise InputError(f"traction model {self.name!r}: the profile's batch shape {profile.batch_shape} "
                                 f"does not broadcast to the inputs' shape {shape}")
        if np.any(usable):
            take = usable
            if profile is not None and profile.batch_shape:  # one profile per point: those of the usable ones
                target = shape + (profile.n,)
                profile = PressureProfile(*(np.broadcast_to(field, target)[take] for field in
                                            (profile.x_ratio, profile.pressure_ratio, profile.film_ratio)))
            result = fluid_traction(u[take], p_h=p[take], film_thickness=h[take], eta0=eta0, log_viscosity_ratio=law,
                                    entrainment_speed=None if thermal is None else um[take],
                                    half_width=None if thermal is None else a[take], thermal=thermal,
                                    profile=profile, **self._rheology())
            mu[take], stress[take], rise[take] = result.coefficient, result.shear_stress, result.temperature_rise
            regime[take], valid[take] = result.regime, result.valid
        regime = regime.astype(str)
        return {"traction_coefficient": float_or_array(mu), "traction_force": float_or_array(mu * N),
                "traction_shear_stress": float_or_array(stress), "traction_regime": regime.item() if regime.ndim == 0
                else regime, "traction_valid": bool(valid) if valid.ndim == 0 else valid,
                "traction_temperature_rise": float_or_array(rise)}


@builtin
@attrs.frozen
class NewtonianTraction(_FluidTraction):
    """Newtonian film traction bounded by the limiting shear stress.

    .. math:: \\tau = \\min\\left(\\eta(p)\\,\\frac{u_s}{h},\\ \\tau_{L0} + \\Lambda_L p\\right), \\qquad
              \\mu = \\frac{\\int\\tau\\,dA}{\\int p\\,dA}

    Parameters
    ----------
    limiting_shear_stress : float
        tau_L0 [Pa] >= 0 (default 0).
    limiting_shear_slope : float or None
        Lambda_L [-], 0..1 (default 0.047); None: a purely Newtonian film (mu grows with eta(p) without bound).
    geometry : {"line", "point"}
        Hertz pressure shape (default "line").
    thermal : bool
        Lumped contact temperature rise (default False).
    effusivity_1, effusivity_2 : float, optional
        Surface effusivities [W s^0.5/(m^2 K)] for ``thermal`` (default: the state's ``effusivity``).
    n_nodes : int
        Quadrature nodes across the contact (default 24).

    Inputs (``requires``): ``normal_force`` N [N] (>= 0), ``p_h`` [Pa] (>= 0; 0 = contact open: mu 0, regime
    "open"), ``b`` Hertz semi-axis along the rolling direction [m], ``h_c`` central film [m], ``u_s`` = u1 - u2
    [m/s], ``u_m`` = (u1 + u2)/2 [m/s], ``lubricant_state`` (eta0, log_viscosity_ratio; with ``thermal`` its
    thermal_conductivity and thermoviscous_coefficient); optional ``effusivity`` [W s^0.5/(m^2 K)] (one value
    or a pair) when ``thermal`` and the model's effusivities are not set.

    Returns ``traction_coefficient`` mu [-] (sign of u_s), ``traction_force`` mu N [N], ``traction_shear_stress``
    mean film shear stress [Pa], ``traction_regime`` ("linear", "nonlinear", "plateau", "open", or "no film"
    where h_c is missing/non-positive or an input is NaN: NaN outputs there), ``traction_valid`` (finite mu and
    converged thermal balance) and ``traction_temperature_rise`` dT [K] (0 when isothermal).

    References
    ----------
    Bair, S. & Winer, W.O. (1979) J. Lubr. Technol. 101:251–257 (limiting shear stress); Evans, C.R. &
    Johnson, K.L. (1986) Proc. IMechE C 200(5):313–324 (traction regimes, thermal balance).
    """

    name = "newtonian"
    reference = ("Newtonian film, mu = int tau dA / int p dA over the Hertz pressure; tau_L = tau_L0 + Lambda_L p: "
                 "Bair & Winer (1979) J. Lubr. Technol. 101:251-257; regimes and thermal: Evans & Johnson (1986) "
                 "Proc. IMechE C 200(5):313-324")
    rheology = "newtonian"


@builtin
@attrs.frozen
class EyringTraction(_FluidTraction):
    """Eyring film traction (Johnson & Tevaarwerk) bounded by the limiting shear stress.

    .. math:: \\tau = \\min\\left(\\tau_0\\,\\mathrm{asinh}\\frac{\\eta(p)\\,u_s}{h\\,\\tau_0},\\
              \\tau_{L0} + \\Lambda_L p\\right), \\qquad \\mu = \\frac{\\int\\tau\\,dA}{\\int p\\,dA}

    Parameters
    ----------
    eyring_stress : float
        tau0 [Pa] > 0 (default 5 MPa, see the module docstring).
    limiting_shear_stress, limiting_shear_slope, geometry, thermal, effusivity_1, effusivity_2, n_nodes
        As :class:`NewtonianTraction`.

    Inputs (``requires``) and outputs: as :class:`NewtonianTraction`.

    References
    ----------
    Johnson, K.L. & Tevaarwerk, J.L. (1977) Proc. R. Soc. Lond. A 356:215–236 (Eyring film);
    Bair, S. & Winer, W.O. (1979) J. Lubr. Technol. 101:251–257; Evans, C.R. & Johnson, K.L. (1986)
    Proc. IMechE C 200(5):313–324.
    """

    name = "eyring"
    reference = ("Eyring film tau = tau0 asinh(eta gamma/tau0): Johnson & Tevaarwerk (1977) Proc. R. Soc. A "
                 "356:215-236; tau_L = tau_L0 + Lambda_L p: Bair & Winer (1979); regimes and thermal: Evans & "
                 "Johnson (1986) Proc. IMechE C 200(5):313-324")
    rheology = "eyring"

    eyring_stress: float = number_field(default=EYRING_STRESS, validators=[in_range(0.0, lower_inclusive=False,
                                                                                    unit="Pa")],
                                        doc="tau0 [Pa]")

    def _rheology(self) -> dict[str, Any]:
        return {**super()._rheology(), "eyring_stress": self.eyring_stress}
