"""EHL traction of an elliptical contact rolling with creep and spin: forces, spin moment, losses, capacity.

The film of an elastohydrodynamic contact shears at the local sliding velocity of the two surfaces. For
a contact rolling at speed V with longitudinal and lateral creepages nu_x, nu_y [-] and spin creepage phi
[1/m] (spin angular velocity over V) the rigid sliding velocity at (x, y) is (Kalker's kinematics, as
:mod:`camcontact.contact.fastsim`)

.. math:: \\mathbf{w}(x, y) = V\\,(\\nu_x - \\phi\\,y,\\ \\nu_y + \\phi\\,x)

and the film's shear stress acts along it with the magnitude of the film's rheology at the local
pressure and shear rate |w|/h (:mod:`camcontact.contact.fluid_traction`: Newtonian or Eyring, Johnson &
Tevaarwerk 1977; bounded by the limiting shear stress tau_L = tau_L0 + Lambda_L p, Bair & Winer 1979):

.. math::
    \\boldsymbol{\\tau} = \\tau\\left(p, \\frac{|\\mathbf{w}|}{h}\\right)\\frac{\\mathbf{w}}{|\\mathbf{w}|},
    \\qquad F_x = -\\int \\tau_x\\,dA, \\quad F_y = -\\int \\tau_y\\,dA, \\quad
    M_z = -\\int (x\\,\\tau_y - y\\,\\tau_x)\\,dA

on the body whose creepages are given, opposing them (Kalker's signs, so the two models swap in one
scene). This is the viscous ("rigid-elastic"-free) film of Tevaarwerk & Johnson's traction analysis with
spin: the film's elastic (Maxwell) compliance and the solids' tangential compliance are left out, so the
creepage is all film shear (the solids' creep of FASTSIM is orders of magnitude smaller in a lubricated
contact). Pressure: the Hertz semi-ellipsoid p = p_h sqrt(1 - x^2/a^2 - y^2/b^2) with the central film
h uniform, or a :class:`PressureField` — the numerical EHL solution's pressure and local film h(x, y)
over its pressurised nodes (the inlet build-up, the constriction and the pressure spike; the cavitated
outlet, where the film has ruptured, carries no shear).

Losses. The power the film dissipates, P = int tau . w dA >= 0, splits exactly into the creep loss
-V (nu_x F_x + nu_y F_y) and the spin loss -V phi M_z (the same identity holds for FASTSIM in steady
rolling: the work of the creep forces and the spin moment on the rigid creepages).

Low-creep limit (the tests' closed form). A Newtonian film, tau = eta(p) |w|/h, gives
F_x = -(V nu_x/h) int eta dA, F_y = -(V nu_y/h) int eta dA and M_z = -(V phi/h) int eta (x^2 + y^2) dA;
for a constant viscosity int eta dA = eta0 pi a b and int eta (x^2 + y^2) dA = eta0 pi a b (a^2 + b^2)/4.

Mixed lubrication (optional). Where the asperities carry a share of the load (Johnson, Greenwood & Poon
1972; :mod:`camcontact.models.mixed_lubrication`), the film carries the rest: the pressure above is the
fluid's (p_h x its share, on the film at that share) and the asperities add a uniform pressure p_a over
the Hertz ellipse that shears with the boundary friction coefficient mu_b along the local sliding,
tau_a = mu_b p_a w/|w| (the Coulomb asperity friction of mixed-lubrication friction models, Gelinck &
Schipper 2000 with the sliding direction of each point). The asperities are rigid-Coulomb: without spin
a force below mu_b p_a pi a b is held with them sticking (creepage -> 0, no loss; their elastic creep is
left out); with spin every point but the pole slides, and F_x(nu_x) stays continuous. Their dissipation
mu_b p_a |w| joins the film's in the losses and the thermal balance.

Thermal (optional). A lumped contact temperature rise dT = C q with q = P/(pi a b) the mean heat flux:
C = the contact-mean flash temperature of a uniform source per unit flux (Jaeger/Blok band source strip
by strip over the ellipse, :func:`camcontact.contact.contact_temperature.band_flash_per_flux` x 2/3 x
:data:`~camcontact.contact.fluid_traction.POINT_FLASH_FACTOR`, both surfaces rolling at V) + the mean
film rise h/(12 k) of a Couette film (the lumped balance of :mod:`camcontact.contact.fluid_traction`,
with the flux of creep and spin instead of mu p u_s). The viscosity falls by exp(-beta dT); the balance
dT = C q(dT) has one root (q falls with dT), found by Brent's method per evaluation.

Capacity. The largest |F_x| the contact transmits with its spin and lateral creepage at
|nu_x| <= ``max_creepage`` (isothermal: the force at the bound, F_x being monotone in nu_x; thermal: the
peak of the traction curve, which falls beyond it). A required force above the capacity is gross slip.

Quadrature: x = a r cos(t), y = b r sin(t) with r = sin(s): p = p_h cos(s) and dA = a b sin(s) cos(s) ds dt
— Gauss–Legendre in s (``n_radial``) and the periodic trapezoid rule in t (``n_angular``). The stress
direction turns round the slip pole (where w = 0; inside the contact when |nu_x| < phi b) so the
integrand has a kink there: the forces converge at first to second order in the node spacing (the tests:
16 x 64 nodes within 0.3 % of 64 x 256 for a pole inside the contact).

References
----------
Johnson, K.L. & Tevaarwerk, J.L. (1977) Proc. R. Soc. Lond. A 356:215–236 (Eyring film).
Johnson, K.L., Greenwood, J.A. & Poon, S.Y. (1972) Wear 19:91–108; Gelinck, E.R.M. & Schipper, D.J. (2000)
Tribol. Int. 33:175–181 (mixed lubrication: load share and asperity friction).
Tevaarwerk, J.L. & Johnson, K.L. (1979) The influence of fluid rheology on the performance of traction
drives, J. Lubr. Technol. 101(3):266–273 (traction with creep, side slip and spin over the contact).
Bair, S. & Winer, W.O. (1979) J. Lubr. Technol. 101:251–257 (limiting shear stress).
Kalker, J.J. (1967) A strip theory for rolling with slip and spin (creepage kinematics).
Loewenthal, S.H. & Zaretsky, E.V. (1985) Design of traction drives, NASA RP-1154 §6.5–6.6 (spin and
contact power loss).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable

import attrs
import numpy as np
from scipy.optimize import brentq, minimize_scalar

from ..errors import InputError
from .contact_temperature import band_flash_per_flux
from .fluid_traction import (BAND_MEAN_OVER_MAX, POINT_FLASH_FACTOR, TractionThermal, check_film_law,
                             film_shear_stress)

__all__ = ["DEFAULT_MAX_CREEPAGE", "CentreLineTraction", "PressureField", "SpinTraction", "SpinTractionContact",
           "TractionMap", "rolling_losses"]

#: largest |nu_x| over which the capacity is sought (5 %: traction drives run at 0.1-3 % creep)
DEFAULT_MAX_CREEPAGE = 0.05
DEFAULT_RADIAL = 16
DEFAULT_ANGULAR = 64


@attrs.frozen
class SpinTraction:
    """The traction of one contact state (SI floats; forces on the body whose creepages are given)."""

    Fx: float  #: longitudinal force [N]
    Fy: float  #: lateral force [N]
    Mz: float  #: spin moment about the contact normal [N m]
    power_loss: float  #: int tau . w dA [W]
    creep_loss: float  #: -V (nu_x Fx + nu_y Fy) [W]
    spin_loss: float  #: -V phi Mz [W]
    limited_fraction: float  #: area share where the limiting shear stress bounds tau [-]
    temperature_rise: float  #: lumped film temperature rise [K] (0 isothermal)
    converged: bool  #: the thermal balance converged (True isothermal)
    creepage_x: float  #: nu_x [-]
    creepage_y: float  #: nu_y [-]
    spin: float  #: phi [1/m]


@attrs.frozen(eq=False)
class CentreLineTraction:
    """Pressure and longitudinal traction on the contact's centre line y = 0 (the record the thesis's 2-D
    slice stress reads, :func:`camcontact.steps.stress.slice_through_centre`; the layout of a
    :class:`~camcontact.contact.fastsim.FastsimResult` strip: one strip, from the leading edge x = +a)."""

    x: np.ndarray  #: (1, n) positions from +a to -a [m]
    y: np.ndarray  #: (1,) the strip's y = 0 [m]
    Tx: np.ndarray  #: (1, n) traction along x on the body [Pa]
    p: np.ndarray  #: (1, n) pressure [Pa] (Hertz, or the pressure field's)


@attrs.frozen(eq=False)
class TractionMap:
    """The film's traction over a contact in one state, for a map (SI, Kalker's frame, on the body)."""

    x: np.ndarray  #: node positions along rolling [m] (the leading edge at +a)
    y: np.ndarray  #: node positions across rolling [m]
    tx: np.ndarray  #: traction along x [Pa]
    ty: np.ndarray  #: traction along y [Pa]
    limited: np.ndarray  #: the limiting shear stress bounds the film there [bool]
    a: float  #: Hertz semi-axis along rolling [m]
    b: float  #: Hertz semi-axis across rolling [m]
    pole: tuple[float, float]  #: slip pole (w = 0): (-nu_y/phi, nu_x/phi) [m] (inf without spin)


@attrs.frozen(eq=False)
class PressureField:
    """Pressure and film of a contact on a uniform rectangular grid (SI): the numerical EHL solution
    (:meth:`camcontact.ehl.point_solution.PointEHLSolution.dimensional` gives x, y, p, h).

    ``x`` runs along the entrainment, the inlet at its smallest values (the solver's frame); the traction
    works in Kalker's frame, whose x points to the leading edge (the inlet), so its nodes are at -x.
    """

    x: np.ndarray = attrs.field(converter=lambda v: np.asarray(v, dtype=float))  #: (nx,) [m]
    y: np.ndarray = attrs.field(converter=lambda v: np.asarray(v, dtype=float))  #: (ny,) [m]
    p: np.ndarray = attrs.field(converter=lambda v: np.asarray(v, dtype=float))  #: (ny, nx) [Pa]
    h: np.ndarray = attrs.field(converter=lambda v: np.asarray(v, dtype=float))  #: (ny, nx) [m]

    def __attrs_post_init__(self):
        x, y, p, h = self.x, self.y, self.p, self.h
        if x.ndim != 1 or y.ndim != 1 or x.size < 3 or y.size < 3 or p.shape != (y.size, x.size) \
                or h.shape != p.shape:
            raise InputError(f"spin traction: pressure field of shapes x {x.shape}, y {y.shape}, p {p.shape}, "
                             f"h {h.shape}; allowed: x (nx,), y (ny,), p and h (ny, nx), nx, ny >= 3")
        steps = np.concatenate([np.diff(x) / (x[1] - x[0]), np.diff(y) / (y[1] - y[0])])
        if not (np.all(np.isfinite(steps)) and np.allclose(steps, 1.0, rtol=1e-6) and x[1] > x[0] and y[1] > y[0]):
            raise InputError("spin traction: pressure field x and y must be uniform and increasing")
        if not (np.all(np.isfinite(p)) and np.all(np.isfinite(h))):
            raise InputError("spin traction: pressure field has non-finite pressures or films")
        if not np.any(p > 0.0) or np.any(h[p > 0.0] <= 0.0):
            raise InputError(f"spin traction: pressure field with max p = {p.max():.4g} Pa and min film "
                             f"{h[p > 0.0].min() if np.any(p > 0.0) else float('nan'):.4g} m where p > 0; allowed: "
                             "a pressurised region with a positive film")

    def nodes(self):
        """Kalker-frame nodes of the pressurised region: (x, y, p, h, dA) as flat arrays."""
        X, Y = np.meshgrid(-self.x, self.y)
        inside = self.p > 0.0
        cell = (self.x[1] - self.x[0]) * (self.y[1] - self.y[0])
        return (X[inside], Y[inside], self.p[inside], self.h[inside], np.full(int(inside.sum()), cell))

    def centre_line(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Pressure and film on y = 0 (the row nearest it) at Kalker-frame positions ``x``."""
        j = int(np.argmin(np.abs(self.y)))
        return (np.interp(-x, self.x, self.p[j], left=0.0, right=0.0),
                np.interp(-x, self.x, self.h[j]))


@functools.lru_cache(maxsize=16)
def _grid(n_radial: int, n_angular: int):
    """Unit-ellipse nodes (X = x/a, Y = y/b), p/p_h and the area weights of dA/(a b) (sum pi)."""
    s, ws = np.polynomial.legendre.leggauss(n_radial)
    s = (s + 1.0) * (math.pi / 4.0)
    ws = ws * (math.pi / 4.0)
    t = (np.arange(n_angular) + 0.5) * (2.0 * math.pi / n_angular)
    r = np.sin(s)[:, None]
    X, Y = r * np.cos(t)[None, :], r * np.sin(t)[None, :]
    ratio = np.broadcast_to(np.cos(s)[:, None], X.shape)
    weight = np.broadcast_to((ws * np.sin(s) * np.cos(s))[:, None] * (2.0 * math.pi / n_angular), X.shape)
    arrays = tuple(np.ascontiguousarray(v).ravel() for v in (X, Y, ratio, weight))
    for array in arrays:
        array.flags.writeable = False
    return arrays


def _number(name: str, value, *, low: float | None = None, low_inclusive: bool = True) -> float:
    """One finite number (>= or > ``low`` when given), or an InputError naming ``name``, the value as given and
    what is allowed."""
    allowed = "a finite number" if low is None else f"finite, {'>=' if low_inclusive else '>'} {low:g}"
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise InputError(f"spin traction: {name} = {value!r}; allowed: {allowed}") from None
    if not (math.isfinite(number) and (low is None or (number >= low if low_inclusive else number > low))):
        raise InputError(f"spin traction: {name} = {value!r}; allowed: {allowed}")
    return number


def rolling_losses(Fx: float, Fy: float, Mz: float, creepage_x: float, creepage_y: float, spin: float,
                   rolling_speed: float) -> dict[str, float]:
    """Creep loss -V (nu_x F_x + nu_y F_y), spin loss -V phi M_z and their sum [W] of a contact rolling at V
    with those creepages under the forces and moment on the body (Kalker's signs): in steady rolling the
    dissipation, for a film (this module) as for FASTSIM."""
    creep = -rolling_speed * (creepage_x * Fx + creepage_y * Fy)
    spin_loss = -rolling_speed * spin * Mz
    return {"creep_loss": creep, "spin_loss": spin_loss, "power_loss": creep + spin_loss}


class SpinTractionContact:
    """One elliptical EHL contact prepared for many creepage states (see the module docstring).

    Parameters
    ----------
    a, b : float
        Hertz semi-axes along and across the rolling direction [m], > 0.
    p_h : float
        Hertz peak pressure [Pa], > 0.
    film_thickness : float
        Central film h [m], > 0.
    rolling_speed : float
        V [m/s], > 0 (the creepages are velocities over V).
    eta0 : float
        Viscosity at the bulk temperature and ambient pressure [Pa s], > 0.
    log_viscosity_ratio : callable
        ln(eta/eta0) of a gauge-pressure array [Pa] (``LubricantState.log_viscosity_ratio``).
    rheology : {"eyring", "newtonian"}
    eyring_stress : float
        tau0 [Pa] (``"eyring"``).
    limiting_shear_stress, limiting_shear_slope : float
        tau_L0 [Pa] and Lambda_L [-]; ``limiting_shear_slope=None``: no limit.
    thermal : TractionThermal, optional
        Lumped contact temperature (module docstring); None: isothermal.
    n_radial, n_angular : int
        Quadrature nodes (default 16 x 64).
    field : PressureField, optional
        The numerical pressure and film: its pressurised nodes replace the Hertz ellipse's quadrature (a, b,
        p_h and the central ``film_thickness`` still set the thermal model's band and film).
    asperity_pressure : float
        p_a [Pa], >= 0: the asperities' uniform pressure over the Hertz ellipse (mixed lubrication; ``p_h``
        and ``film_thickness`` are then the fluid's share and film). Default 0: full film.
    boundary_friction : float
        mu_b [-], >= 0: the asperities' Coulomb coefficient.
    """

    def __init__(self, *, a, b, p_h, film_thickness, rolling_speed, eta0, log_viscosity_ratio: Callable,
                 rheology: str = "eyring", eyring_stress=None, limiting_shear_stress=0.0, limiting_shear_slope=None,
                 thermal: TractionThermal | None = None, n_radial: int = DEFAULT_RADIAL,
                 n_angular: int = DEFAULT_ANGULAR, field: PressureField | None = None, asperity_pressure=0.0,
                 boundary_friction=0.0):
        check_film_law("spin traction", rheology, log_viscosity_ratio, thermal)
        for name, value, low in (("n_radial", n_radial, 4), ("n_angular", n_angular, 8)):
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not low <= value <= 1024:
                raise InputError(f"spin traction: {name} = {value!r}; allowed: an integer, {low} <= n <= 1024")
        if field is not None and not isinstance(field, PressureField):
            raise InputError(f"spin traction: field = {type(field).__name__}; allowed: None or a PressureField")
        self.a, self.b = _number("a", a, low=0.0, low_inclusive=False), _number("b", b, low=0.0, low_inclusive=False)
        self.p_h = _number("p_h", p_h, low=0.0, low_inclusive=False)
        self.h = _number("film_thickness", film_thickness, low=0.0, low_inclusive=False)
        self.V = _number("rolling_speed", rolling_speed, low=0.0, low_inclusive=False)
        eta0 = _number("eta0", eta0, low=0.0, low_inclusive=False)
        self.rheology, self.thermal, self.field = rheology, thermal, field
        if field is None:
            X, Y, ratio, weight = _grid(int(n_radial), int(n_angular))
            self.x, self.y = self.a * X, self.b * Y
            self.dA = self.a * self.b * weight
            pressure, film = self.p_h * ratio, self.h
        else:
            self.x, self.y, pressure, film, self.dA = field.nodes()
        self.area = math.pi * self.a * self.b
        self.asperity_pressure = _number("asperity_pressure", asperity_pressure, low=0.0)
        self.asperity_shear = self.asperity_pressure * _number("boundary_friction", boundary_friction, low=0.0)
        self.normal_force = float(np.sum(pressure * self.dA)) + self.asperity_pressure * self.area
        self.law, self.eta0 = log_viscosity_ratio, eta0
        self.tau0 = (_number("eyring_stress", eyring_stress, low=0.0, low_inclusive=False) if rheology == "eyring"
                     else None)
        self.limit = None
        if limiting_shear_slope is not None:
            self.limit = (_number("limiting_shear_stress", limiting_shear_stress, low=0.0),
                          _number("limiting_shear_slope", limiting_shear_slope, low=0.0))
        self.log_base, self.tau_limit = self._node_values(pressure, film)
        self.per_flux = 0.0
        if thermal is not None:
            flash = band_flash_per_flux(self.a, self.V, self.V, thermal.effusivity_1, thermal.effusivity_2)
            self.per_flux = BAND_MEAN_OVER_MAX * POINT_FLASH_FACTOR * flash + self.h / (12.0 * thermal.oil_conductivity)

    def _node_values(self, pressure: np.ndarray, film):
        """ln(eta(p)/h) at the nodes of pressure ``pressure`` and film ``film`` [m] (minus ln tau0 for eyring:
        + ln|w| gives ln(eta gamma[/tau0])) and tau_L there (None without a limit)."""
        log_ratio = np.asarray(self.law(pressure), dtype=float)
        if log_ratio.shape != pressure.shape or not np.all(np.isfinite(log_ratio)):
            raise InputError("spin traction: log_viscosity_ratio gave non-finite or misshaped values at the contact's "
                             f"pressures (p_h = {self.p_h:.4g} Pa)")
        log_base = math.log(self.eta0) - np.log(film) + log_ratio
        if self.tau0 is not None:
            log_base = log_base - math.log(self.tau0)
        tau_limit = None if self.limit is None else self.limit[0] + self.limit[1] * pressure
        return log_base, tau_limit

    # ------------------------------------------------------------------ one state
    def _field(self, nu_x: float, nu_y: float, phi: float, dT_beta: float, nodes=None):
        """Sliding velocity components and magnitude [m/s], stress magnitude [Pa], limited mask (at the
        quadrature nodes, or at ``nodes`` = (x, y, log_base, tau_limit))."""
        x, y, log_base, tau_limit = nodes if nodes is not None else (self.x, self.y, self.log_base, self.tau_limit)
        wx = self.V * (nu_x - phi * y)
        wy = self.V * (nu_y + phi * x)
        speed = np.hypot(wx, wy)
        with np.errstate(divide="ignore"):
            L = log_base + np.log(speed) - dT_beta
        tau, limited = film_shear_stress(L, self.rheology, self.tau0, tau_limit)
        if self.asperity_shear > 0.0:  # Coulomb asperities inside the Hertz ellipse, where the surfaces slide
            inside = (x / self.a) ** 2 + (y / self.b) ** 2 < 1.0
            tau = tau + np.where(inside & (speed > 0.0), self.asperity_shear, 0.0)
        return wx, wy, speed, tau, np.zeros(tau.shape, dtype=bool) if limited is None else limited

    def _flux(self, nu_x, nu_y, phi, dT_beta) -> float:
        _, _, speed, tau, _ = self._field(nu_x, nu_y, phi, dT_beta)
        return float(np.sum(tau * speed * self.dA)) / self.area

    def _temperature(self, nu_x, nu_y, phi) -> tuple[float, bool]:
        thermal = self.thermal
        if thermal is None:
            return 0.0, True
        beta = thermal.thermoviscous_coefficient
        if beta == 0.0:
            return self.per_flux * self._flux(nu_x, nu_y, phi, 0.0), True
        hot = min(self.per_flux * self._flux(nu_x, nu_y, phi, 0.0), thermal.max_temperature_rise)
        if hot <= 0.0:
            return 0.0, True

        def balance(dT):
            return dT - self.per_flux * self._flux(nu_x, nu_y, phi, beta * dT)

        if balance(hot) < 0.0:  # no root below the cap
            return thermal.max_temperature_rise, False
        try:
            root = brentq(balance, 0.0, hot, xtol=thermal.tolerance, maxiter=thermal.max_iterations)
        except RuntimeError:
            return hot, False
        return float(root), True

    def evaluate(self, creepage_x=0.0, creepage_y=0.0, spin=0.0) -> SpinTraction:
        """:class:`SpinTraction` at nu_x, nu_y [-] and the spin creepage phi [1/m]."""
        nu_x, nu_y, phi = _number("creepage_x", creepage_x), _number("creepage_y", creepage_y), _number("spin", spin)
        dT, converged = self._temperature(nu_x, nu_y, phi)
        beta = 0.0 if self.thermal is None else self.thermal.thermoviscous_coefficient
        wx, wy, speed, tau, limited = self._field(nu_x, nu_y, phi, beta * dT)
        with np.errstate(invalid="ignore", divide="ignore"):
            share = np.where(speed > 0.0, tau / speed, 0.0) * self.dA  # tau/|w| dA
        tx, ty = share * wx, share * wy
        Fx, Fy = -float(np.sum(tx)), -float(np.sum(ty))
        Mz = -float(np.sum(self.x * ty - self.y * tx))
        power = float(np.sum(tau * speed * self.dA))
        losses = rolling_losses(Fx, Fy, Mz, nu_x, nu_y, phi, self.V)
        limited_fraction = float(np.sum(self.dA[limited])) / float(np.sum(self.dA))
        return SpinTraction(Fx, Fy, Mz, power, losses["creep_loss"], losses["spin_loss"], limited_fraction, dT,
                            converged, nu_x, nu_y, phi)

    def _traction_at(self, state: SpinTraction, x, y, pressure, film):
        """Traction (t_x, t_y) on the body [Pa] and the limited mask of ``state`` at the points (x, y) of
        pressure ``pressure`` and film ``film``."""
        beta = 0.0 if self.thermal is None else self.thermal.thermoviscous_coefficient
        nodes = (x, y, *self._node_values(pressure, film))
        wx, wy, speed, tau, limited = self._field(state.creepage_x, state.creepage_y, state.spin,
                                                  beta * state.temperature_rise, nodes)
        with np.errstate(invalid="ignore", divide="ignore"):
            share = -np.where(speed > 0.0, tau / speed, 0.0)
        return share * wx, share * wy, limited

    def centre_line(self, state: SpinTraction, n: int = 41) -> CentreLineTraction:
        """Pressure and traction T_x on y = 0 for a ``state`` of this contact (its creepages and
        temperature rise), at ``n`` element centres from the leading edge x = a (the Hertz pressure, or the
        field's interpolated; with asperities the film's plus theirs, the contact's whole pressure)."""
        x = self.a * (1.0 - (np.arange(n) + 0.5) * (2.0 / n))
        if self.field is None:
            pressure, film = self.p_h * np.sqrt(np.clip(1.0 - (x / self.a) ** 2, 0.0, None)), self.h
        else:
            pressure, film = self.field.centre_line(x)
        tx, _, _ = self._traction_at(state, x, np.zeros(n), pressure, film)
        # the record's pressure is the whole contact's (the film's and the asperities'): readers take Tx/p as the
        # traction coefficient of the surface (the slice stresses, Saccheto §3.4)
        total = pressure + np.where(np.abs(x) < self.a, self.asperity_pressure, 0.0)
        return CentreLineTraction(x[None, :], np.zeros(1), tx[None, :], total[None, :])

    def traction_map(self, state: SpinTraction, n: int = 41) -> TractionMap:
        """The traction of ``state`` over the contact for a map: on an n x n grid of the Hertz ellipse, or on
        (about n^2 of) the pressure field's pressurised nodes."""
        if self.field is None:
            X, Y = np.meshgrid(np.linspace(-1.0, 1.0, n), np.linspace(-1.0, 1.0, n))
            inside = X ** 2 + Y ** 2 < 1.0
            x, y = self.a * X[inside], self.b * Y[inside]
            pressure, film = self.p_h * np.sqrt(1.0 - X[inside] ** 2 - Y[inside] ** 2), self.h
        else:
            x, y, pressure, film, _ = self.field.nodes()
            stride = max(1, math.ceil(x.size / (n * n)))
            x, y, pressure, film = x[::stride], y[::stride], pressure[::stride], film[::stride]
        tx, ty, limited = self._traction_at(state, x, y, pressure, film)
        pole = ((-state.creepage_y / state.spin, state.creepage_x / state.spin) if state.spin != 0.0
                else (math.inf, math.inf))
        return TractionMap(x, y, tx, ty, limited, self.a, self.b, pole)

    # ------------------------------------------------------------------ force control
    def capacity(self, spin=0.0, creepage_y=0.0, max_creepage: float = DEFAULT_MAX_CREEPAGE) -> SpinTraction:
        """The state of largest |F_x| over 0 < nu_x <= ``max_creepage`` (F_x(-nu_x) = -F_x(nu_x): the
        contact is symmetric in y): the bound when isothermal, the traction curve's peak when thermal
        (a log grid, then a bounded search in log nu_x). Its ``-Fx`` is the capacity [N]."""
        top = _number("max_creepage", max_creepage, low=0.0, low_inclusive=False)
        phi, nu_y = _number("spin", spin), _number("creepage_y", creepage_y)
        edge = self.evaluate(top, nu_y, phi)
        if self.thermal is None:
            return edge
        grid = np.geomspace(top * 1e-4, top, 17)
        forces = [-self.evaluate(nu, nu_y, phi).Fx for nu in grid]
        k = int(np.argmax(forces))
        if k == len(grid) - 1:
            return edge
        low, high = math.log(grid[max(k - 1, 0)]), math.log(grid[k + 1])
        best = minimize_scalar(lambda s: self.evaluate(math.exp(s), nu_y, phi).Fx, bounds=(low, high),
                               method="bounded", options={"xatol": 1e-4})
        return self.evaluate(math.exp(best.x), nu_y, phi)

    def solve_creepage(self, force_x, spin=0.0, creepage_y=0.0,
                       max_creepage: float = DEFAULT_MAX_CREEPAGE) -> tuple[SpinTraction, SpinTraction]:
        """The creepage nu_x whose F_x equals ``force_x`` [N] (on the body; Kalker's sign: a positive force
        needs a negative creepage), on the stable branch below the capacity: (state, capacity state).
        Where |force_x| exceeds the capacity the contact slips grossly: the returned state is the
        capacity's (F_x saturated, sign of ``force_x``) — check ``abs(state.Fx) < abs(force_x)``."""
        target = _number("force_x", force_x)
        peak = self.capacity(spin, creepage_y, max_creepage)
        if target == 0.0:  # F_x(0) = 0 for any spin and lateral creep (the contact is symmetric in y)
            return self.evaluate(0.0, creepage_y, spin), peak
        sign = -1.0 if target > 0.0 else 1.0  # the creepage's sign
        top = peak.creepage_x
        if abs(target) >= -peak.Fx:  # beyond the capacity (-peak.Fx >= 0, the positive creepage's mirrored)
            return self.evaluate(sign * top, creepage_y, spin), peak

        def residual(nu):
            return self.evaluate(sign * nu, creepage_y, spin).Fx - target

        nu = brentq(residual, 0.0, top, xtol=1e-15, rtol=1e-12, maxiter=200)
        return self.evaluate(sign * nu, creepage_y, spin), peak
