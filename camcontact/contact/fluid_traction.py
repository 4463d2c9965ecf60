"""Fluid traction of a lubricated Hertz contact from the lubricant's rheology, isothermal or with a
lumped contact temperature rise.

The traction coefficient is the mean shear stress of the film over the contact divided by the mean
pressure,

.. math::
    \\mu = \\frac{\\int \\tau\\,dA}{\\int p\\,dA}, \\qquad
    \\dot\\gamma = \\frac{u_s}{h}, \\qquad \\eta(p) = \\eta_0\\,e^{\\ln(\\eta/\\eta_0)(p)}\\,e^{-\\beta\\,\\Delta T}

over the Hertz pressure (line: p = p_h sqrt(1 - x^2/a^2) on |x| < a; point: p = p_h sqrt(1 - x^2/a^2 -
y^2/b^2) on the ellipse) with the central film h uniform over the contact (Johnson & Tevaarwerk 1977;
Evans & Johnson 1986). Shear stress of the film:

* ``"newtonian"``: :math:`\\tau = \\eta\\dot\\gamma`;
* ``"eyring"`` (Johnson & Tevaarwerk 1977, the non-linear viscous element of their model):
  :math:`\\dot\\gamma = (\\tau_0/\\eta)\\sinh(\\tau/\\tau_0)`, i.e. :math:`\\tau = \\tau_0\\,\\mathrm{asinh}
  (\\eta\\dot\\gamma/\\tau_0)`, computed from the logarithm ln(eta gamma/tau0) so that it never
  overflows: asinh(e^L) = L + ln 2 (error < e^(-2L)/4) for L > 20;
* a limiting shear stress on top of either (Bair & Winer 1979):
  :math:`|\\tau| \\le \\tau_L = \\tau_{L0} + \\Lambda_L\\,p`.

The elastic (Maxwell) compliance of the film (J&T's linear-elastic regime at very small slip) is not
modelled: the "linear" regime here is the linear-viscous one.

Integration: by the substitution p = p_h cos(theta) the contact integrals become smooth integrals over
theta in [0, pi/2] (line: dA/A = cos(theta) dtheta; point: dA/A = 2 sin(theta) cos(theta) dtheta),
evaluated with a fixed Gauss–Legendre rule (24 nodes by default: 1e-12 relative for a Barus film at
alpha p_h = 60, the analytic integrals of the tests). The lateral semi-axis b does not enter: mu of a
semi-ellipsoidal pressure is independent of a and b. Every input broadcasts; the isothermal path has no
Python loop over points.

Regimes (categorical, per point): the traction-regime map of Evans & Johnson (1986) separates the
linear viscous, the non-linear (Eyring) viscous and the plastic (limiting shear stress) regimes by the
shear stress relative to tau0 and to tau_L. Here, evaluated on the film as it is (after the thermal
reduction): ``"plateau"`` where the limiting shear stress bounds tau over at least half the contact
area, else ``"nonlinear"`` where eta gamma > tau0 over at least half the area (the Eyring stress-rate
relation is then more than 12 % below linear: asinh(1) = 0.88), else ``"linear"``; ``"open"`` where
p_h = 0 (no contact: mu = 0). The half-area threshold is camcontact's reading of the map, which the
source draws as boundaries at the mean pressure.

Thermal (lumped energy balance). The shear heat q = tau_mean |u_s| per unit area [W/m^2] raises

* the surfaces: the contact-mean flash temperature of a uniform band source of half-width a moving
  through both surfaces at high Peclet number, with Blok's partition (equal surface temperatures) —
  :func:`camcontact.contact.contact_temperature.flash_temperature` (Blok; Delabenetta 2021 Eq. 48),
  which gives the maximum (exit) value theta_max of that source; the contact mean is 2/3 of it
  (theta ~ sqrt(x + a) along the band). A point contact is taken strip by strip (strips of half-length
  a sqrt(1 - y^2/b^2), negligible lateral conduction at high Peclet): its mean is
  B(1/2, 7/4)/(pi/2) = 0.9153 times the band value of the same a and mean flux;
* the film above its surfaces: uniform dissipation in a Couette film conducting to both walls gives a
  parabolic profile, midplane rise q h/(8 k) and mean rise q h/(12 k). The mean is used: under a
  stress uniform across the film the sliding speed integrates the local rate, u_s/h = <gamma(z)>,
  and gamma ~ 1/eta(T(z)), so the film shears like a uniform film at the mean of exp(beta dT) across
  it — to first order in beta dT the mean rise, not the midplane maximum.

The viscosity everywhere in the contact is reduced by exp(-beta dT), dT = flash + film, beta the
temperature–viscosity coefficient -d ln(eta)/dT. tau0 and tau_L are taken independent of
temperature. Since tau_mean falls as dT rises, dT = C tau_mean(dT) (C [K/Pa] from the two terms)
has exactly one root per point; it is bracketed in [0, C tau_mean(0)] and solved by the Illinois
(modified regula falsi) method on all points at once, with a convergence flag per point. The balance
has the structure of the thermal analyses of EHL traction (Johnson & Greenwood 1980; Evans & Johnson
1986: film temperature = bulk + surface flash temperature + rise across the film); its details here
(contact-mean flash temperature of a uniform source, mean film rise, one temperature for the whole
contact, temperature-independent tau0 and tau_L) are camcontact's lumped simplification, not those
papers' equations. With heating, mu(u_s) rises, peaks and falls: it is not monotone in u_s.

Numerical pressure and film (line contacts). With ``profile`` (a :class:`PressureProfile`: x/b, p/p_h and
f = h(x)/h_c at the nodes of e.g. a multigrid EHL solution,
:meth:`camcontact.ehl.line_solution.LineEHLSolution.traction_profile`) the integrals are taken over that
pressure and film instead (h_c the ``film_thickness``),

.. math::
    \\mu = \\frac{\\int \\tau(p(x), u_s/h(x))\\,dx}{\\int p\\,dx}, \\qquad h(x) = h_c\\,f(x),

by the trapezoid rule on the profile's nodes, with the weights of (1/(2b)) int f dx (b the Hertz
half-width), so that sum(weight p/p_h) = pi/4 for the Hertz pressure and for the load balance of a
converged EHL solution, and the mean pressure and mean shear stress of the thermal balance keep their
meaning (per unit area of the Hertz band 2b). Every node counts: the inlet and outlet nodes with
p ~ 0 contribute their Couette shear tau(eta0, u_s/h(x)) (zero where a limiting shear stress through
the origin, tau_L0 = 0, bounds it by Lambda_L p). The regime's area fractions are taken over the
loaded nodes of the Hertz band (p > 0, |x| <= b), as the Hertz path takes them over the Hertz area (the
long, lightly loaded inlet of a numerical solution would otherwise outvote the contact). The trapezoid
rule is second order for the smooth parts and O(dx^1.5) at the square-root edges of a Hertz-like pressure (mu within 3e-5 of the Hertz path at 2049 nodes on
[-2, 1.5], the tests). The thermal balance keeps the central film h_c in its film-rise term. A profile
may carry a leading batch shape (e.g. one profile per cam angle) that broadcasts with the other
contact inputs. Over a multigrid solution (M = 20, L = 10, Roelands) the Eyring mu is 2-5 % below the
Hertz/central-film value: the numerical pressure carries part of the load at low pressure in the
inlet and outlet, and tau grows faster than linearly with p (the tests).

Validity: full-film EHL (no asperity load: Lambda well above 1, see the ``mixed`` effect), the Hertz
pressure and the central film (or the given profile) standing for the real ones, small-strain
elasticity of the film ignored, and for the thermal part a high Peclet number u a/(2 chi) of the
surfaces (Blok's formula). The area fractions behind the regime come from the quadrature nodes (a
resolution of one node weight, <= 0.1).

Cost (2-core machine, 24 nodes, 10^4 points): 5 ms per :meth:`FluidTractionContact.coefficient` call,
10 ms for :func:`traction_coefficient` including the viscosity law (Roelands) on every node, 60 ms with
the thermal balance (one Python call of the flash formula per point, 1-4 Illinois iterations). A
profile of 1001 nodes: 0.3 ms per ``coefficient`` call at 41 sliding speeds; 360 profiles x 41 speeds,
0.2 s.

References
----------
Johnson, K.L. & Tevaarwerk, J.L. (1977) Shear behaviour of elastohydrodynamic oil films, Proc. R. Soc.
Lond. A 356:215–236.
Bair, S. & Winer, W.O. (1979) Shear strength measurements of lubricants at high pressure, J. Lubr.
Technol. 101:251–257.
Johnson, K.L. & Greenwood, J.A. (1980) Thermal analysis of an Eyring fluid in elastohydrodynamic
traction, Wear 61:353.
Evans, C.R. & Johnson, K.L. (1986) Regimes of traction in elastohydrodynamic lubrication, Proc. IMechE
C 200(5):313–324.
Blok, H. (1937) Theoretical study of temperature rise at surfaces of actual contact under oiliness
lubricating conditions, Proc. General Discussion on Lubrication, IMechE 2:222–235; Delabenetta (2021)
Eq. 48.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from typing import NamedTuple

import attrs
import numpy as np

from ..errors import InputError
from .contact_temperature import flash_temperature

__all__ = [
    "DEFAULT_NODES",
    "GEOMETRIES",
    "POINT_FLASH_FACTOR",
    "REGIMES",
    "RHEOLOGIES",
    "FluidTraction",
    "FluidTractionContact",
    "PressureProfile",
    "TractionThermal",
    "asinh_exp",
    "check_film_law",
    "film_shear_stress",
    "fluid_traction",
    "traction_coefficient",
    "traction_curve",
]

#: Gauss–Legendre nodes across the contact (see the module docstring for the accuracy)
DEFAULT_NODES = 24
RHEOLOGIES = ("newtonian", "eyring")
GEOMETRIES = ("line", "point")
#: regime labels of :attr:`FluidTraction.regime`
REGIMES = ("linear", "nonlinear", "plateau", "open")
#: contact-mean flash temperature of an elliptical (strip-wise) source over that of a band of the same
#: half-width a and mean flux: B(1/2, 7/4) / (pi/2)
POINT_FLASH_FACTOR = math.gamma(0.5) * math.gamma(1.75) / math.gamma(2.25) / (math.pi / 2.0)
#: mean over the band of a high-Peclet uniform source's temperature (~ sqrt(x + a)) over its maximum
BAND_MEAN_OVER_MAX = 2.0 / 3.0
_ASINH_SWITCH = 20.0  # asinh(e^L) = L + ln 2 above this L (relative error < 1e-18)
_LN2 = math.log(2.0)


# --------------------------------------------------------------------------------------- inputs
def _finite(name: str, value, *, low: float | None = None, low_inclusive: bool = True) -> np.ndarray:
    """``value`` as a float array; InputError naming ``name``, the value and the allowed range."""
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"fluid traction: {name} = {value!r}; allowed: a number or an array of numbers") from None
    allowed = "finite" if low is None else f"finite, {'>=' if low_inclusive else '>'} {low:g}"
    finite = np.isfinite(array)
    if not np.all(finite):
        raise InputError(f"fluid traction: {name} = {float(array[~finite].flat[0])!r}; allowed: {allowed}")
    if low is not None:
        bad = array < low if low_inclusive else array <= low
        if np.any(bad):
            raise InputError(f"fluid traction: {name} = {float(array[bad].flat[0]):.6g}; allowed: {allowed}")
    return array


def check_film_law(where: str, rheology: str, log_viscosity_ratio, thermal) -> None:
    """InputError (prefixed ``where``) unless the film's shear law is usable: ``rheology`` one of
    :data:`RHEOLOGIES`, ``log_viscosity_ratio`` a callable, ``thermal`` None or a :class:`TractionThermal`."""
    if rheology not in RHEOLOGIES:
        raise InputError(f"{where}: rheology = {rheology!r}; allowed: {', '.join(map(repr, RHEOLOGIES))}")
    if not callable(log_viscosity_ratio):
        raise InputError(f"{where}: log_viscosity_ratio = {log_viscosity_ratio!r}; allowed: a callable of the gauge "
                         "pressure [Pa] giving ln(eta/eta0) (e.g. LubricantState.log_viscosity_ratio)")
    if thermal is not None and not isinstance(thermal, TractionThermal):
        raise InputError(f"{where}: thermal = {thermal!r}; allowed: None or a TractionThermal")


@attrs.frozen
class TractionThermal:
    """Thermal data of the lumped contact temperature (SI floats).

    Parameters
    ----------
    oil_conductivity : float
        Lubricant thermal conductivity k [W/(m K)], > 0.
    thermoviscous_coefficient : float
        beta = -d ln(eta)/dT [1/K], >= 0 (the lubricant state's ``thermoviscous_coefficient``).
    effusivity_1, effusivity_2 : float
        Thermal effusivities sqrt(k rho c) of the surfaces moving at u_m + u_s/2 and u_m - u_s/2
        [W s^0.5/(m^2 K)], > 0 (:meth:`camcontact.Material.thermal_effusivity`).
    max_temperature_rise : float
        Upper end of the bracket [K] (default 500): a point whose balance has no root below it is
        reported at this rise, not converged.
    tolerance : float
        Absolute tolerance on the temperature rise [K] (default 1e-4).
    max_iterations : int
        Illinois iterations at most (default 60).
    """

    oil_conductivity: float = attrs.field(converter=float)
    thermoviscous_coefficient: float = attrs.field(converter=float)
    effusivity_1: float = attrs.field(converter=float)
    effusivity_2: float = attrs.field(converter=float)
    max_temperature_rise: float = attrs.field(default=500.0, converter=float)
    tolerance: float = attrs.field(default=1e-4, converter=float)
    max_iterations: int = attrs.field(default=60)

    def __attrs_post_init__(self) -> None:
        for name, low, inclusive in (("oil_conductivity", 0.0, False), ("thermoviscous_coefficient", 0.0, True),
                                     ("effusivity_1", 0.0, False), ("effusivity_2", 0.0, False),
                                     ("max_temperature_rise", 0.0, False), ("tolerance", 0.0, False)):
            value = getattr(self, name)
            if not (math.isfinite(value) and (value >= low if inclusive else value > low)):
                raise InputError(f"TractionThermal.{name} = {value!r}; allowed: finite, "
                                 f"{'>=' if inclusive else '>'} {low:g}")
        if isinstance(self.max_iterations, bool) or not isinstance(self.max_iterations, int) \
                or self.max_iterations < 1:
            raise InputError(f"TractionThermal.max_iterations = {self.max_iterations!r}; allowed: an integer >= 1")

    @classmethod
    def from_lubricant_state(cls, lubricant_state, effusivity_1: float, effusivity_2: float | None = None,
                             **options) -> TractionThermal:
        """The thermal data from a lubricant state (anything with ``thermal_conductivity`` [W/(m K)] and
        ``thermoviscous_coefficient`` [1/K]) and the surfaces' effusivities (``effusivity_2`` defaults
        to ``effusivity_1``: both bodies of one material)."""
        missing = [n for n in ("thermal_conductivity", "thermoviscous_coefficient")
                   if getattr(lubricant_state, n, None) is None]
        if missing:
            name = getattr(lubricant_state, "name", "?")
            raise InputError(f"the traction temperature needs the lubricant's {' and '.join(missing)} "
                             f"(lubricant {name!r}: give thermal_conductivity and temperature-dependent "
                             "viscosity data)")
        return cls(lubricant_state.thermal_conductivity, lubricant_state.thermoviscous_coefficient,
                   effusivity_1, effusivity_1 if effusivity_2 is None else effusivity_2, **options)


def _profile_array(name: str, value) -> np.ndarray:
    try:
        array = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"PressureProfile.{name} = {value!r}; allowed: an array of numbers of shape (..., n), "
                         "n >= 3") from None
    if array.ndim < 1 or array.shape[-1] < 3:
        raise InputError(f"PressureProfile.{name} has shape {array.shape}; allowed: (..., n) with n >= 3 nodes")
    finite = np.isfinite(array)
    if not np.all(finite):
        raise InputError(f"PressureProfile.{name} = {float(array[~finite].flat[0])!r}; allowed: finite")
    return array


@attrs.frozen(eq=False)
class PressureProfile:
    """A line contact's pressure and film along the rolling direction, for :class:`FluidTractionContact`
    (``profile=``) instead of the Hertz pressure with a uniform central film.

    Parameters
    ----------
    x_ratio : array (..., n)
        x/b [-] at the nodes (b the Hertz half-width), strictly increasing along the last axis.
    pressure_ratio : array (..., n)
        p/p_h [-] at the nodes, >= 0, positive somewhere (p_h the contact's ``p_h``).
    film_ratio : array (..., n)
        h(x)/h_c [-] at the nodes, > 0 (h_c the contact's ``film_thickness``).

    The three arrays broadcast to one shape (..., n), n >= 3; the leading (batch) shape, e.g. one profile
    per cam angle, broadcasts with the contact's other inputs. Stored as read-only float arrays of that
    shape. :meth:`camcontact.ehl.line_solution.LineEHLSolution.traction_profile` builds one from a
    numerical EHL solution.
    """

    x_ratio: np.ndarray
    pressure_ratio: np.ndarray
    film_ratio: np.ndarray

    def __attrs_post_init__(self) -> None:
        arrays = {name: _profile_array(name, getattr(self, name))
                  for name in ("x_ratio", "pressure_ratio", "film_ratio")}
        counts = {name: a.shape[-1] for name, a in arrays.items()}
        if len(set(counts.values())) > 1:
            raise InputError(f"PressureProfile: the fields have different node counts {counts}; allowed: the same "
                             "n for x_ratio, pressure_ratio and film_ratio")
        try:
            shape = np.broadcast_shapes(*(a.shape for a in arrays.values()))
        except ValueError:
            raise InputError("PressureProfile: the fields' shapes do not broadcast to one shape: "
                             f"{ {name: a.shape for name, a in arrays.items()} }") from None
        x, p, h = arrays["x_ratio"], arrays["pressure_ratio"], arrays["film_ratio"]
        step = np.diff(x, axis=-1)
        if np.any(step <= 0.0):
            index = np.unravel_index(int(np.argmax(step <= 0.0)), step.shape)
            raise InputError(f"PressureProfile.x_ratio = {float(x[index]):.6g} followed by "
                             f"{float(x[index[:-1] + (index[-1] + 1,)]):.6g}; allowed: strictly increasing along "
                             "the last axis")
        if np.any(p < 0.0):
            raise InputError(f"PressureProfile.pressure_ratio = {float(p[p < 0.0].flat[0]):.6g}; allowed: finite, >= 0")
        if np.any(np.all(p == 0.0, axis=-1)):
            raise InputError("PressureProfile.pressure_ratio = 0 at every node of a profile; allowed: >= 0 and "
                             "positive somewhere (no load: give p_h = 0 for an open contact)")
        if np.any(h <= 0.0):
            raise InputError(f"PressureProfile.film_ratio = {float(h[h <= 0.0].flat[0]):.6g}; allowed: finite, > 0")
        for name, array in arrays.items():
            array = np.broadcast_to(array, shape)
            object.__setattr__(self, name, array)  # a read-only view (frozen record)

    @property
    def n(self) -> int:
        """Nodes per profile."""
        return self.x_ratio.shape[-1]

    @property
    def batch_shape(self) -> tuple[int, ...]:
        """The leading shape (one profile per entry)."""
        return self.x_ratio.shape[:-1]

    def weights(self) -> np.ndarray:
        """Trapezoid weights of (1/(2b)) int f dx at the nodes, shape (..., n): sum(weights * pressure_ratio)
        is the mean pressure over the Hertz band 2b in units of p_h (pi/4 for a Hertz pressure)."""
        step = 0.25 * np.diff(self.x_ratio, axis=-1)  # (1/2) dX/2 per end of each interval
        weight = np.zeros(self.x_ratio.shape)
        weight[..., :-1] += step
        weight[..., 1:] += step
        weight.flags.writeable = False
        return weight


class FluidTraction(NamedTuple):
    """Result of :func:`fluid_traction` (arrays of the broadcast input shape)."""

    coefficient: np.ndarray  #: traction coefficient mu = int tau dA / int p dA [-], sign of u_s
    shear_stress: np.ndarray  #: mean film shear stress int tau dA / A [Pa], sign of u_s
    regime: np.ndarray  #: "linear", "nonlinear", "plateau" or "open" (see the module docstring)
    limited_fraction: np.ndarray  #: area fraction where the limiting shear stress bounds tau [-]
    nonlinear_fraction: np.ndarray  #: area fraction where eta gamma > tau0 (0 for "newtonian") [-]
    temperature_rise: np.ndarray  #: lumped film temperature rise dT = flash + film [K] (0: isothermal)
    flash_temperature: np.ndarray  #: contact-mean surface flash temperature rise [K]
    film_temperature_rise: np.ndarray  #: mean rise of the film above its surfaces q h/(12 k) [K]
    converged: np.ndarray  #: the thermal balance converged (True when isothermal) [bool]
    iterations: np.ndarray  #: Illinois iterations of the thermal balance [-]
    valid: np.ndarray  #: finite mu and converged balance [bool]


@functools.lru_cache(maxsize=32)
def _nodes(n_nodes: int, geometry: str) -> tuple[np.ndarray, np.ndarray]:
    """p/p_h at the nodes and the weights of (1/A) int f dA (they sum to 1 up to the rule's error)."""
    x, w = np.polynomial.legendre.leggauss(n_nodes)
    theta = (x + 1.0) * (math.pi / 4.0)
    w = w * (math.pi / 4.0)
    ratio = np.cos(theta)
    weight = w * ratio if geometry == "line" else 2.0 * w * np.sin(theta) * ratio
    ratio.flags.writeable = False
    weight.flags.writeable = False
    return ratio, weight


def _weighted(values: np.ndarray, weight: np.ndarray) -> np.ndarray:
    """sum over the nodes (last axis) of values * weight: a matrix product for the shared Hertz weights,
    a broadcast sum for per-batch (profile) weights."""
    if weight.ndim == 1:
        return values @ weight
    return np.einsum("...i,...i->...", values, weight)


def asinh_exp(L: np.ndarray) -> np.ndarray:
    """asinh(exp(L)) without overflow (the Eyring stress tau0 asinh(eta gamma/tau0) from L = ln(eta gamma/tau0))."""
    with np.errstate(over="ignore", under="ignore"):
        out = np.arcsinh(np.exp(np.minimum(L, _ASINH_SWITCH)))
    return np.where(L > _ASINH_SWITCH, L + _LN2, out)


def film_shear_stress(L: np.ndarray, rheology: str, tau0, tau_limit) -> tuple[np.ndarray, np.ndarray | None]:
    """The film's shear stress tau >= 0 [Pa] from L = ln(eta gamma) (newtonian: tau = e^L) or
    L = ln(eta gamma/tau0) (eyring: tau = tau0 asinh(e^L)), bounded by ``tau_limit`` (None: no bound),
    and the mask where the bound holds (None without one)."""
    if rheology == "eyring":
        tau = tau0 * asinh_exp(L)
    else:
        with np.errstate(over="ignore"):
            tau = np.exp(L)
    limited = None
    if tau_limit is not None:
        limited = tau >= tau_limit
        tau = np.minimum(tau, tau_limit)
    return tau, limited


class FluidTractionContact:
    """A contact prepared once for many sliding speeds (the roller solver's inner loop).

    Takes the keyword inputs of :func:`fluid_traction` except ``sliding_speed``; the pressure-dependent
    part (ln eta at the quadrature nodes, tau_L) is computed here once. :meth:`coefficient` is the
    fast path (mu only), :meth:`solve` gives the full :class:`FluidTraction`. Contact inputs and the
    sliding speed broadcast against each other.

    With ``profile`` (a :class:`PressureProfile`, line geometry) the nodes are the profile's, with
    trapezoid weights of (1/(2b)) int f dx (:meth:`PressureProfile.weights`): :attr:`ratio` and
    :attr:`weight` then have the profile's shape (..., n) and the film at the nodes is
    ``film_thickness * profile.film_ratio``; ``n_nodes`` is not used.
    """

    def __init__(self, *, p_h, film_thickness, eta0, log_viscosity_ratio: Callable, rheology: str = "eyring",
                 eyring_stress=None, limiting_shear_stress=0.0, limiting_shear_slope=None, geometry: str = "line",
                 entrainment_speed=None, half_width=None, thermal: TractionThermal | None = None,
                 n_nodes: int = DEFAULT_NODES, profile: PressureProfile | None = None):
        check_film_law("fluid traction", rheology, log_viscosity_ratio, thermal)
        if geometry not in GEOMETRIES:
            raise InputError(f"fluid traction: geometry = {geometry!r}; allowed: {', '.join(map(repr, GEOMETRIES))}")
        if isinstance(n_nodes, bool) or not isinstance(n_nodes, (int, np.integer)) or not 4 <= n_nodes <= 256:
            raise InputError(f"fluid traction: n_nodes = {n_nodes!r}; allowed: an integer, 4 <= n_nodes <= 256")
        if profile is not None:
            if not isinstance(profile, PressureProfile):
                raise InputError(f"fluid traction: profile = {type(profile).__name__}; allowed: None or a "
                                 "PressureProfile (x/b, p/p_h, h/h_c at the nodes)")
            if geometry != "line":
                raise InputError(f"fluid traction: profile with geometry = {geometry!r}; allowed: a profile only "
                                 "with geometry 'line' (a pressure along the rolling direction)")
        self.rheology, self.geometry, self.thermal, self.profile = rheology, geometry, thermal, profile
        p_h = _finite("p_h", p_h, low=0.0)
        h = _finite("film_thickness", film_thickness, low=0.0, low_inclusive=False)
        eta0 = _finite("eta0", eta0, low=0.0, low_inclusive=False)
        arrays = [p_h, h, eta0]
        if rheology == "eyring":
            if eyring_stress is None:
                raise InputError("fluid traction: rheology 'eyring' needs eyring_stress (tau0 [Pa], > 0)")
            arrays.append(_finite("eyring_stress", eyring_stress, low=0.0, low_inclusive=False))
        self.limited = limiting_shear_slope is not None
        if self.limited:
            arrays.append(_finite("limiting_shear_stress", limiting_shear_stress, low=0.0))
            arrays.append(_finite("limiting_shear_slope", limiting_shear_slope, low=0.0))
        if thermal is not None:
            if entrainment_speed is None or half_width is None:
                raise InputError("fluid traction: the thermal balance needs entrainment_speed [m/s] and "
                                 "half_width [m] (the Hertz semi-axis along the rolling direction)")
            arrays.append(_finite("entrainment_speed", entrainment_speed))
            arrays.append(_finite("half_width", half_width, low=0.0, low_inclusive=False))
        # the profile's batch shape takes part in the broadcast as a zero-stride placeholder
        batch = [] if profile is None else [np.broadcast_to(0.0, profile.batch_shape)]
        try:
            arrays = np.broadcast_arrays(*arrays, *batch)[:len(arrays)]
        except ValueError:
            raise InputError("fluid traction: the contact inputs do not broadcast to one shape: "
                             f"{[np.shape(a) for a in arrays + batch]}"
                             f"{' (the last: the profile batch)' if profile is not None else ''}") from None
        self.shape = arrays[0].shape
        p_h, h, eta0 = arrays[:3]
        rest = iter(arrays[3:])
        if profile is None:
            self.ratio, self.weight = _nodes(int(n_nodes), geometry)
            #: mean pressure by the same rule as the shear stress (exact plateau ratio)
            self.mean_pressure = p_h * float(np.sum(self.weight * self.ratio))
            #: the loaded nodes of a profile within the Hertz band (p > 0, |x| <= b), over which the regime
            #: fractions run, as the Hertz path's run over the Hertz area (None: all nodes)
            self.loaded = None
        else:
            self.ratio, self.weight = profile.pressure_ratio, profile.weights()
            self.mean_pressure = p_h * np.sum(self.weight * self.ratio, axis=-1)
            self.loaded = (self.ratio > 0.0) & (np.abs(profile.x_ratio) <= 1.0)
        self.p_h = p_h
        self.open = p_h == 0.0
        pressure = p_h[..., None] * self.ratio
        uniform = p_h.size > 0 and np.all(p_h == p_h.flat[0])
        log_ratio = np.asarray(log_viscosity_ratio(p_h.flat[0] * self.ratio if uniform else pressure), dtype=float)
        if not np.all(np.isfinite(log_ratio)):
            raise InputError("fluid traction: log_viscosity_ratio returned non-finite ln(eta/eta0) at "
                             f"p <= {float(np.max(pressure)) if pressure.size else 0.0:.6g} Pa")
        #: ln(eta(p)/h) at the nodes [ln(Pa s/m)], minus ln(tau0) for eyring: + ln|u_s| gives ln(eta gamma[/tau0])
        self.log_base = (np.log(eta0) - np.log(h))[..., None] + log_ratio
        if profile is not None:
            self.log_base = self.log_base - np.log(profile.film_ratio)
        self.tau0 = None
        if rheology == "eyring":
            tau0 = next(rest)
            self.tau0 = tau0[..., None]
            self.log_base = self.log_base - np.log(self.tau0)
        self.tau_limit = None
        if self.limited:
            tau_L0, slope = next(rest), next(rest)
            self.tau_limit = tau_L0[..., None] + slope[..., None] * pressure
        if thermal is not None:
            self.u_m, self.half_width = next(rest), next(rest)
            self.film_thickness = h

    # ------------------------------------------------------------------ kernel
    def _stress(self, log_rate, log_base, tau0, tau_limit, dT_beta):
        """tau (>= 0) at the nodes, the limited mask and ln(eta gamma/tau0) (eyring) for the given
        ln|gamma h| = ln|u_s| (trailing axis of the nodes added here) and beta dT."""
        L = log_base + (log_rate - dT_beta)[..., None]
        tau, limited = film_shear_stress(L, self.rheology, tau0, tau_limit)
        return tau, limited, L

    def _log_rate(self, sliding_speed):
        speed = _finite("sliding_speed", sliding_speed)
        try:
            shape = np.broadcast_shapes(self.shape, speed.shape)
        except ValueError:
            raise InputError(f"fluid traction: sliding_speed of shape {speed.shape} does not broadcast with the "
                             f"contact's shape {self.shape}") from None
        with np.errstate(divide="ignore"):
            log_rate = np.log(np.abs(speed))
        return speed, log_rate, shape

    def coefficient(self, sliding_speed, temperature_rise=0.0):
        """mu [-] (sign of u_s) for the sliding speed u_s [m/s] at a given film temperature rise [K]
        (isothermal by default; with :attr:`thermal` use :meth:`solve` for the balanced rise)."""
        speed, log_rate, shape = self._log_rate(sliding_speed)
        beta = 0.0 if self.thermal is None else self.thermal.thermoviscous_coefficient
        tau, _, _ = self._stress(log_rate, self.log_base, self.tau0, self.tau_limit,
                                 beta * np.asarray(temperature_rise, dtype=float))
        mean = _weighted(tau, self.weight)
        with np.errstate(invalid="ignore", divide="ignore"):
            mu = np.where(self.open, 0.0, np.sign(speed) * mean / self.mean_pressure)
        mu = np.broadcast_to(mu, shape)
        return float(mu) if mu.ndim == 0 else np.array(mu)

    # ------------------------------------------------------------------ full result
    def solve(self, sliding_speed) -> FluidTraction:
        """:class:`FluidTraction` for the sliding speed u_s = u1 - u2 [m/s] (thermal balance included
        when the contact has :attr:`thermal`)."""
        speed, log_rate, shape = self._log_rate(sliding_speed)
        n = self.ratio.shape[-1]

        def flat(array, trailing=False):
            if array is None:
                return None
            target = shape + ((n,) if trailing else ())
            return np.broadcast_to(array, target).reshape((-1, n) if trailing else (-1,))

        log_base, tau0 = flat(self.log_base, True), flat(self.tau0, True) if self.tau0 is not None else None
        tau_limit = flat(self.tau_limit, True)
        speed_f, log_rate_f = flat(speed), flat(log_rate)
        mean_pressure, open_ = flat(self.mean_pressure), flat(self.open)
        # per-point weights only for a batch of profiles (one profile: the shared row, a matrix product)
        weight = self.weight if self.weight.ndim == 1 else flat(self.weight, True)
        size = speed_f.size
        dT = np.zeros(size)
        flash = np.zeros(size)
        film = np.zeros(size)
        converged = np.ones(size, dtype=bool)
        iterations = np.zeros(size, dtype=int)
        beta = 0.0
        if self.thermal is not None:
            beta = self.thermal.thermoviscous_coefficient
            flash_per_stress, film_per_stress = self._thermal_coefficients(
                speed_f, flat(self.u_m), flat(self.half_width), flat(self.film_thickness), mean_pressure, open_)
            per_stress = flash_per_stress + film_per_stress
            dT, converged, iterations = self._balance(per_stress, beta, log_rate_f, log_base, tau0, tau_limit,
                                                      weight)
        tau, limited, L = self._stress(log_rate_f, log_base, tau0, tau_limit, beta * dT)
        mean = _weighted(tau, weight)
        if self.thermal is not None:  # the two parts of the balance at the final stress (sum = dT within tolerance)
            flash = np.where(flash_per_stress > 0.0, flash_per_stress * mean, 0.0)
            film = np.where(film_per_stress > 0.0, film_per_stress * mean, 0.0)
        if self.loaded is None:
            total, area = float(np.sum(weight)), weight
        else:  # area fractions of the loaded part of the profile's Hertz band
            area = np.where(self.loaded if self.loaded.ndim == 1 else flat(self.loaded, True), weight, 0.0)
            total = np.sum(area, axis=-1)
        limited_fraction = _weighted(limited, area) / total if limited is not None else np.zeros(size)
        nonlinear_fraction = _weighted(L > 0.0, area) / total if self.rheology == "eyring" else np.zeros(size)
        with np.errstate(invalid="ignore", divide="ignore"):
            mu = np.where(open_, 0.0, np.sign(speed_f) * mean / mean_pressure)
        shear = np.where(open_, 0.0, np.sign(speed_f) * mean)
        regime = np.where(limited_fraction >= 0.5, "plateau",
                          np.where(nonlinear_fraction >= 0.5, "nonlinear", "linear"))
        regime = np.where(open_, "open", regime)
        limited_fraction = np.where(open_, 0.0, limited_fraction)
        nonlinear_fraction = np.where(open_, 0.0, nonlinear_fraction)
        valid = np.isfinite(mu) & converged

        def out(array):
            return np.asarray(array).reshape(shape)

        return FluidTraction(out(mu), out(shear), out(regime), out(limited_fraction), out(nonlinear_fraction),
                             out(dT), out(flash), out(film), out(converged), out(iterations), out(valid))

    def _thermal_coefficients(self, speed, u_m, half_width, h, mean_pressure, open_):
        """dT per unit mean shear stress [K/Pa] of the surfaces (flash) and of the film, per point."""
        thermal = self.thermal
        u1, u2 = np.abs(u_m + 0.5 * speed), np.abs(u_m - 0.5 * speed)
        flash = np.zeros(speed.size)
        shape_factor = BAND_MEAN_OVER_MAX * (1.0 if self.geometry == "line" else POINT_FLASH_FACTOR)
        heated = (speed != 0.0) & ~open_
        for i in np.flatnonzero(heated):
            a, p_mean = float(half_width[i]), float(mean_pressure[i])
            # Blok's band source of half-width a with the uniform flux mu p_mean |u_s|: the load per length
            # w = 2 a p_mean and any (E', R) of that half-width, a^2 = 8 w R/(pi E'): R = a, E' = 16 p_mean/pi
            theta_max = flash_temperature(2.0 * a * p_mean, 16.0 * p_mean / math.pi, a, 1.0, float(u1[i]),
                                          float(u2[i]), thermal.effusivity_1, thermal.effusivity_2)
            flash[i] = shape_factor * theta_max / p_mean  # mu = tau_mean/p_mean
        film = np.where(heated, np.abs(speed) * h / (12.0 * thermal.oil_conductivity), 0.0)
        return flash, film

    def _balance(self, per_stress, beta, log_rate, log_base, tau0, tau_limit, weight):
        """Root of f(dT) = dT - C tau_mean(dT) per point (increasing in dT): Illinois on the bracket
        [0, min(C tau_mean(0), max rise)]; ``weight`` (n,) shared or (points, n) per point."""
        thermal = self.thermal
        size = per_stress.size
        iterations = np.zeros(size, dtype=int)

        def f(index, dT):
            tau, _, _ = self._stress(log_rate[index], log_base[index], None if tau0 is None else tau0[index],
                                     None if tau_limit is None else tau_limit[index], beta * dT)
            return dT - per_stress[index] * _weighted(tau, weight if weight.ndim == 1 else weight[index])

        everything = np.arange(size)
        lo = np.zeros(size)
        f_lo = f(everything, lo)
        with np.errstate(invalid="ignore", over="ignore"):
            hi = np.minimum(-f_lo, thermal.max_temperature_rise)
        hi = np.where(np.isfinite(hi), hi, thermal.max_temperature_rise)
        done = (f_lo >= 0.0) | (per_stress == 0.0)  # no heat: dT = 0
        dT = np.where(done, 0.0, hi)
        converged = done.copy()
        active = np.flatnonzero(~done)
        f_hi = np.zeros(size)
        if active.size:
            f_hi[active] = f(active, hi[active])
        # no root below the cap: report the cap, not converged
        capped = active[f_hi[active] < 0.0]
        active = active[f_hi[active] >= 0.0]
        exact = active[f_hi[active] == 0.0]
        converged[exact] = True
        active = active[f_hi[active] > 0.0]
        a, fa, b, fb = lo.copy(), f_lo.copy(), hi.copy(), f_hi.copy()
        tol = thermal.tolerance
        for _ in range(thermal.max_iterations):
            if not active.size:
                break
            iterations[active] += 1
            ia = active
            c = b[ia] - fb[ia] * (b[ia] - a[ia]) / (fb[ia] - fa[ia])
            c = np.clip(c, np.minimum(a[ia], b[ia]), np.maximum(a[ia], b[ia]))
            fc = f(ia, c)
            flip = fc * fb[ia] < 0.0
            a[ia] = np.where(flip, b[ia], a[ia])
            fa[ia] = np.where(flip, fb[ia], 0.5 * fa[ia])
            b[ia], fb[ia] = c, fc
            dT[ia] = c
            finished = (np.abs(fc) <= 0.1 * tol) | (np.abs(b[ia] - a[ia]) <= tol)
            converged[ia[finished]] = True
            active = ia[~finished]
        dT[capped] = thermal.max_temperature_rise
        return dT, converged, iterations


def fluid_traction(sliding_speed, *, p_h, film_thickness, eta0, log_viscosity_ratio: Callable,
                   rheology: str = "eyring", eyring_stress=None, limiting_shear_stress=0.0,
                   limiting_shear_slope=None, geometry: str = "line", entrainment_speed=None, half_width=None,
                   thermal: TractionThermal | None = None, n_nodes: int = DEFAULT_NODES,
                   profile: PressureProfile | None = None) -> FluidTraction:
    """Traction of a lubricated Hertz contact from the film's rheology (see the module docstring).

    Parameters
    ----------
    sliding_speed : float or array
        u_s = u1 - u2 [m/s] (signed; mu takes its sign: the film drags surface 1, moving at
        u_m + u_s/2, back by mu N and surface 2 forward by mu N).
    p_h : float or array
        Hertz maximum pressure [Pa], >= 0 (0: contact open, mu = 0, regime "open").
    film_thickness : float or array
        Central film h [m], > 0, taken uniform over the contact.
    eta0 : float or array
        Viscosity at ambient pressure (and the bulk temperature) [Pa*s], > 0.
    log_viscosity_ratio : callable
        ln(eta/eta0) [-] of a gauge-pressure ndarray [Pa], elementwise (Barus, Roelands:
        ``LubricantState.log_viscosity_ratio``). Called once per call (on the nodes only when p_h is
        the same for every point).
    rheology : {"eyring", "newtonian"}
        Shear law of the film.
    eyring_stress : float or array
        tau0 [Pa], > 0 (``"eyring"`` only).
    limiting_shear_stress, limiting_shear_slope : float or array
        tau_L0 [Pa] >= 0 and Lambda_L [-] >= 0 of tau_L = tau_L0 + Lambda_L p; ``limiting_shear_slope=None``
        (default) applies no limit.
    geometry : {"line", "point"}
        Semi-elliptical (line) or semi-ellipsoidal (point) Hertz pressure.
    entrainment_speed : float or array
        u_m = (u1 + u2)/2 [m/s]; needed by ``thermal`` (the surface speeds u_m +- u_s/2).
    half_width : float or array
        Hertz semi-axis a along the rolling direction [m], > 0; needed by ``thermal``.
    thermal : TractionThermal, optional
        Lumped contact temperature (see the module docstring); None: isothermal.
    n_nodes : int
        Gauss–Legendre nodes across the contact (default 24).
    profile : PressureProfile, optional
        A numerical line pressure and film (x/b, p/p_h, h/h_c at its nodes) instead of the Hertz pressure
        and the uniform central film (``geometry="line"`` only; ``n_nodes`` then unused): mu = int tau dx /
        int p dx by the trapezoid rule (see the module docstring).

    Returns
    -------
    FluidTraction
        mu [-], mean shear stress [Pa], regime, limited and non-linear area fractions [-], temperature
        rises [K], convergence flag, iterations, validity; arrays of the broadcast shape of the inputs.
    """
    contact = FluidTractionContact(p_h=p_h, film_thickness=film_thickness, eta0=eta0,
                                   log_viscosity_ratio=log_viscosity_ratio, rheology=rheology,
                                   eyring_stress=eyring_stress, limiting_shear_stress=limiting_shear_stress,
                                   limiting_shear_slope=limiting_shear_slope, geometry=geometry,
                                   entrainment_speed=entrainment_speed, half_width=half_width, thermal=thermal,
                                   n_nodes=n_nodes, profile=profile)
    return contact.solve(sliding_speed)


def traction_coefficient(sliding_speed, **contact):
    """mu [-] alone, sign of u_s (a float for scalar inputs, else an ndarray); ``contact``: the keyword
    parameters of :func:`fluid_traction`. Isothermal contacts take the fast path (no regime bookkeeping); with
    ``thermal`` it is the mu of the balanced temperature (check convergence with :func:`fluid_traction`). For
    many calls on one contact, build a :class:`FluidTractionContact` once and call its ``coefficient``."""
    prepared = FluidTractionContact(**contact)
    if prepared.thermal is None:
        return prepared.coefficient(sliding_speed)
    mu = prepared.solve(sliding_speed).coefficient
    return float(mu) if mu.ndim == 0 else mu


def traction_curve(slide_roll_ratio, *, entrainment_speed, **contact) -> FluidTraction:
    """The traction curve: :func:`fluid_traction` at the sliding speeds u_s = S u_m for the
    slide-to-roll ratios S = (u1 - u2)/u_m [-] (project convention, u_m = (u1 + u2)/2), with the
    linear / non-linear / plateau regime per point in :attr:`FluidTraction.regime`."""
    S = _finite("slide_roll_ratio", slide_roll_ratio)
    u_m = _finite("entrainment_speed", entrainment_speed)
    return fluid_traction(S * u_m, entrainment_speed=u_m, **contact)
