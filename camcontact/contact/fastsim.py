"""FASTSIM: Kalker's simplified theory of rolling contact with creep and spin, and its inverse.

:func:`fastsim` gives the tangential tractions, creep forces, spin moment and stick/slip map of an
elliptical Hertz contact x^2/a^2 + y^2/b^2 <= 1 (a along the rolling direction x, b lateral)
rolling with creepages nu_x, nu_y [-] and spin creepage phi [1/m] (spin angular velocity over
rolling speed), for a Coulomb bound |T| <= mu p (Saccheto 2008 Eqs 5.36–5.54).
:func:`solve_creepage` is the force-controlled (inverse) problem: the creepage that transmits a
required tangential force.

Sign conventions (Kalker's, used throughout):

* x is the rolling direction; the material flows through the contact in -x, entering at the
  leading edge x = +a(y), a(y) = a sqrt(1 - y^2/b^2), where the traction is zero.
* rigid slip per rolling speed: w/V = (nu_x - phi y, nu_y + phi x) (Kalker; Saccheto's Eq. 5.41
  prints -phi x, his Eq. 5.45 +phi x — the latter is used).
* T, Fx, Fy, Mz are the traction, forces and moment about +z acting **on the body whose
  creepages are given, opposing the creepage**: for small creepage (Eqs 5.48–5.49)

  .. math:: F_x = -C_{11} G a b \\nu_x, \\qquad F_y = -C_{22} G a b \\nu_y - C_{23} G (a b)^{3/2} \\phi

In stick the traction follows the simplified-theory ODE along each strip (Eqs 5.44–5.47,
corrected form)

.. math::
    T_x = \\left(\\frac{\\nu_x}{L_1} - \\frac{\\phi y}{L_3}\\right)(x - a(y)), \\qquad
    T_y = \\frac{\\nu_y}{L_2}(x - a(y)) + \\frac{\\phi}{2 L_3}\\left(x^2 - a(y)^2\\right)

and where |T| would exceed mu p the element slips with T = mu p T_pred/|T_pred| (the direction
of the predicted traction, standard FASTSIM). L1, L2, L3 come from Kalker's C_ij
(:mod:`camcontact.contact.kalker`). The discretisation is described in
:mod:`camcontact.contact._fastsim_kernels`.

Pressure of the traction bound (option ``pressure``)
----------------------------------------------------
``"parabolic"`` (default) — Kalker's FASTSIM (Kalker 1982, 1990):

.. math:: p = \\frac{2N}{\\pi a b}\\left(1 - \\frac{x^2}{a^2} - \\frac{y^2}{b^2}\\right)

(peak 2N/(pi a b); it carries N). The flexibilities L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G),
L3 = pi a sqrt(a/b)/(4 C23 G) make the simplified theory reproduce Kalker's linear creep
coefficients whatever the bound; Kalker took this bound for FASTSIM because with it the
simplified theory's creep-force curve up to saturation stays close to his exact theory (it is
also the "parabolic traction bound" that Vollebregt's CONTACT uses with FASTSIM). For pure
longitudinal creepage a strip of half-length a(y) and peak P(y) = 2N/(pi a b)(1 - y^2/b^2) then
carries, in closed form, (4/3) mu P(y) a(y) (1 - (1 - u)^3), u = min(1, nu_x a(y)/(2 L1 mu P(y))).

``"hertz"`` — the semi-ellipsoidal Hertz pressure

.. math:: p = \\frac{3N}{2 \\pi a b}\\sqrt{1 - \\frac{x^2}{a^2} - \\frac{y^2}{b^2}}

as the bound, with the same flexibilities: the reading of Saccheto's (2008) simulation (his
Eqs 5.36 and 5.50–5.52 bound the traction by Ct times the local normal pressure, his §3.3 Hertz
pressure), which the thesis convention reproduces (``Fastsim(pressure="hertz")``). L1..L3 are not
calibrated for it. The Hertz bound is lower in the middle (peak 3N/(2 pi a b) against
2N/(pi a b)) and higher towards the edge, so partial slip and the force near saturation differ:
at the Forti CVT's input contact (Saccheto 2008, 150 W, 60 rpm, 1:1, thesis clamping, with spin)
the creepage that transmits F_t is 0.0583 with "hertz" and 0.0536 with "parabolic".

Both carry N exactly on the grid (:mod:`camcontact.contact._fastsim_kernels`), so full slip
gives mu N with either; they agree in the linear limit (the stick tractions do not involve p).

References
----------
Kalker, J.J. (1982) A fast algorithm for the simplified theory of rolling contact, Vehicle System
Dynamics 11:1–13 (the parabolic traction bound). Kalker, J.J. (1990) Three-dimensional elastic
bodies in rolling contact, Kluwer (simplified theory, FASTSIM). Vollebregt, E.A.H., User guide for
CONTACT, VORtech technical report TR09-03 (FASTSIM with the parabolic traction bound).
Saccheto, T.J.S. (2008) MSc dissertation, FEM/UNICAMP, §5.5, Eqs 5.36–5.54, Tabela 5.1.
"""

from __future__ import annotations

import math

import attrs
import numpy as np
from scipy.optimize import brentq

from ..errors import ConvergenceError, InputError
from . import _fastsim_kernels
from .kalker import flexibility_parameters

__all__ = [
    "DEFAULT_NX",
    "DEFAULT_NY",
    "DEFAULT_PRESSURE",
    "PRESSURES",
    "CreepageSolution",
    "FastsimResult",
    "GrossSlipError",
    "check_pressure",
    "fastsim",
    "solve_creepage",
]

#: default number of elements per strip (along x) and of strips (along y)
DEFAULT_NX = 40
DEFAULT_NY = 40
#: most bracket expansions (doublings) :func:`solve_creepage` tries before giving up
MAX_BRACKET_EXPANSIONS = 200
DIRECTIONS = ("x", "y")
#: pressure shapes of the traction bound: Kalker's parabolic one (FASTSIM) and the Hertz semi-ellipsoid
PRESSURES = ("parabolic", "hertz")
#: Kalker's FASTSIM
DEFAULT_PRESSURE = "parabolic"


class GrossSlipError(InputError):
    """The required tangential force is at or above what the contact can transmit (mu N).

    Attributes ``required_force`` [N], ``limit`` = mu N [N] and ``traction_needed`` = |F|/N [-]
    (Saccheto's mu_min) describe the case.
    """

    def __init__(self, message: str, required_force: float, limit: float, traction_needed: float):
        super().__init__(message)
        self.required_force = required_force
        self.limit = limit
        self.traction_needed = traction_needed


@attrs.frozen(eq=False)
class FastsimResult:
    """Result of :func:`fastsim` (SI floats and ndarrays; grids are (ny, nx), strip-major).

    ``x[j, i]``, ``y[j]`` are the element centres [m]; element (j, i) has area dx[j] * dy.
    """

    Fx: float  #: creep force along x (rolling) on the body [N]
    Fy: float  #: lateral creep force on the body [N]
    Mz: float  #: spin moment sum (x Ty - y Tx) dA about the contact centre [N*m]
    slip_fraction: float  #: slipping area / contact area [-]
    stick: np.ndarray  #: True where the element sticks, (ny, nx)
    Tx: np.ndarray  #: traction along x [Pa], (ny, nx)
    Ty: np.ndarray  #: lateral traction [Pa], (ny, nx)
    p: np.ndarray  #: pressure p of the traction bound mu p [Pa], (ny, nx): parabolic or Hertz (``pressure``)
    x: np.ndarray  #: element-centre x [m], (ny, nx)
    y: np.ndarray  #: strip-centre y [m], (ny,)
    dx: np.ndarray  #: element length of each strip [m], (ny,)
    dy: float  #: strip width [m]
    L1: float  #: longitudinal flexibility [m/Pa]
    L2: float  #: lateral flexibility [m/Pa]
    L3: float  #: spin flexibility [m/Pa]
    a: float  #: semi-axis along rolling [m]
    b: float  #: lateral semi-axis [m]
    normal_force: float  #: N [N]
    mu: float  #: traction coefficient [-]
    creepage_x: float  #: nu_x [-]
    creepage_y: float  #: nu_y [-]
    spin: float  #: phi [1/m]
    pressure: str  #: shape of the traction bound, "parabolic" or "hertz"

    @property
    def force(self) -> float:
        """|F| = sqrt(Fx^2 + Fy^2) [N]."""
        return math.hypot(self.Fx, self.Fy)

    @property
    def traction_ratio(self) -> float:
        """|F|/(mu N) [-] (0 where mu N = 0); 1 at gross sliding without spin."""
        limit = self.mu * self.normal_force
        return self.force / limit if limit > 0.0 else 0.0

    @property
    def full_slip(self) -> bool:
        """True when every element slips (gross sliding)."""
        return not bool(self.stick.any())

    @property
    def full_stick(self) -> bool:
        """True when no element slips."""
        return bool(self.stick.all())


@attrs.frozen(eq=False)
class CreepageSolution:
    """Result of :func:`solve_creepage`."""

    creepage: float  #: the creepage found (nu_x or nu_y per ``direction``) [-]
    direction: str  #: "x" or "y"
    required_force: float  #: the target force component [N]
    result: FastsimResult  #: FASTSIM at the creepage found
    bracket: tuple[float, float]  #: creepage bracket handed to brentq [-]
    evaluations: tuple[tuple[float, float], ...]  #: every (creepage [-], force [N]) evaluated, in order
    iterations: int  #: brentq iterations (0 when the first guess was exact)
    converged: bool  #: brentq's flag

    @property
    def force(self) -> float:
        """The force component found along ``direction`` [N]."""
        return self.result.Fx if self.direction == "x" else self.result.Fy

    @property
    def force_error(self) -> float:
        """force - required_force [N]."""
        return self.force - self.required_force


# ----------------------------------------------------------------- input checks
def _finite(value, name: str, unit: str) -> float:
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{name} = {value!r}: expected a plain number in {unit}") from None
    if not math.isfinite(number):
        raise InputError(f"{name} = {value!r} {unit}: must be finite (got NaN or inf)")
    return number


def _at_least(value, name: str, unit: str, low: float, strict: bool) -> float:
    number = _finite(value, name, unit)
    if number < low or (strict and number == low):
        raise InputError(f"{name} = {number!r} {unit} is out of range; allowed: {name} {'>' if strict else '>='} {low:g}")
    return number


def check_pressure(value, name: str = "pressure") -> str:
    """``value`` if it is one of :data:`PRESSURES`, else an InputError naming ``name``, the value
    and the allowed values."""
    if not (isinstance(value, str) and value in PRESSURES):
        raise InputError(f"{name} = {value!r}; allowed: 'parabolic' (Kalker's FASTSIM, p = 2N/(pi a b) "
                         "(1 - x^2/a^2 - y^2/b^2)) or 'hertz' (the semi-ellipsoidal Hertz pressure, "
                         "Saccheto 2008's reading)")
    return value


def _count(value, name: str) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
        raise InputError(f"{name} = {value!r}; allowed: an integer >= 1 (number of {'elements per strip' if name == 'nx' else 'strips'})")
    return int(value)


def _checked(a, b, normal_force, mu, shear_modulus, creepage_x, creepage_y, spin, nx, ny):
    return (
        _at_least(a, "a", "[m]", 0.0, True), _at_least(b, "b", "[m]", 0.0, True),
        _at_least(normal_force, "normal_force", "[N]", 0.0, False), _at_least(mu, "mu", "[-]", 0.0, False),
        _at_least(shear_modulus, "shear_modulus", "[Pa]", 0.0, True),
        _finite(creepage_x, "creepage_x", "[-]"), _finite(creepage_y, "creepage_y", "[-]"),
        _finite(spin, "spin", "[1/m]"), _count(nx, "nx"), _count(ny, "ny"),
    )


# ----------------------------------------------------------------- forward problem
def _run(a, b, normal_force, mu, flexibilities, creepage_x, creepage_y, spin, nx, ny, use_compiled,
         pressure) -> FastsimResult:
    x, p, Tx, Ty = (np.empty((ny, nx)) for _ in range(4))
    y = np.empty(ny)
    stick = np.empty((ny, nx), dtype=np.bool_)
    kernel = _fastsim_kernels.compiled("fastsim_strips") if use_compiled else _fastsim_kernels.PY["fastsim_strips"]
    L1, L2, L3 = flexibilities
    Fx, Fy, Mz, slip_area, area = kernel(a, b, normal_force, mu, L1, L2, L3, creepage_x, creepage_y, spin,
                                         pressure == "parabolic", x, y, p, Tx, Ty, stick)
    return FastsimResult(
        Fx=float(Fx), Fy=float(Fy), Mz=float(Mz), slip_fraction=float(slip_area / area), stick=stick,
        Tx=Tx, Ty=Ty, p=p, x=x, y=y, dx=2.0 * a * np.sqrt(1.0 - (y / b) ** 2) / nx, dy=2.0 * b / ny,
        L1=L1, L2=L2, L3=L3, a=a, b=b, normal_force=normal_force, mu=mu,
        creepage_x=creepage_x, creepage_y=creepage_y, spin=spin, pressure=pressure,
    )


def fastsim(a: float, b: float, normal_force: float, mu: float, shear_modulus: float,
            creepage_x: float = 0.0, creepage_y: float = 0.0, spin: float = 0.0, *,
            nx: int = DEFAULT_NX, ny: int = DEFAULT_NY, compiled: bool = True,
            coefficients: tuple[float, float, float] | None = None,
            pressure: str = DEFAULT_PRESSURE) -> FastsimResult:
    """Kalker's FASTSIM: creep forces and stick/slip of an elliptical Hertz contact.

    .. math::
        T^{pred}_i = T_{i-1} - h\\left(\\frac{\\nu_x}{L_1} - \\frac{\\phi y}{L_3},\\;
        \\frac{\\nu_y}{L_2} + \\frac{\\phi \\bar x}{L_3}\\right), \\qquad
        T_i = \\begin{cases} T^{pred}_i & |T^{pred}_i| \\le \\mu p_i \\\\
        \\mu p_i\\,T^{pred}_i/|T^{pred}_i| & \\text{otherwise} \\end{cases}

    marched along each strip from the leading edge x = +a(y) (T = 0), with Kalker's parabolic
    pressure p = 2N/(pi a b) (1 - x^2/a^2 - y^2/b^2) (default) or the Hertz pressure
    p = 3N/(2 pi a b) sqrt(1 - x^2/a^2 - y^2/b^2) (``pressure="hertz"``), normalised on the grid to
    carry exactly N (module docstring).

    Parameters
    ----------
    a : float
        Contact semi-axis along the rolling direction x [m] (> 0).
    b : float
        Lateral contact semi-axis [m] (> 0); b/a within 0.1..10 unless ``coefficients`` is given.
    normal_force : float
        N [N] (>= 0; 0 gives zero traction everywhere).
    mu : float
        Traction (Coulomb) coefficient Ct [-] (>= 0).
    shear_modulus : float
        Combined shear modulus G [Pa] (> 0), 2/G = 1/G1 + 1/G2.
    creepage_x, creepage_y : float
        Longitudinal and lateral creepage nu_x, nu_y [-] (rigid slip velocity / rolling speed).
    spin : float
        Spin creepage phi [1/m] (spin angular velocity / rolling speed).
    nx, ny : int
        Elements per strip and number of strips (>= 1); default 40 x 40.
    compiled : bool
        Use the numba kernel (default) or its plain-Python twin.
    coefficients : tuple of float, optional
        Kalker's (C11, C22, C23) [-]; default: Saccheto (2008) Tabela 5.1 interpolated at b/a.
    pressure : {"parabolic", "hertz"}
        Pressure of the traction bound: "parabolic", Kalker's FASTSIM (default), or "hertz", the
        semi-ellipsoidal Hertz pressure (Saccheto 2008's reading).

    Returns
    -------
    FastsimResult
        Forces Fx, Fy [N] and spin moment Mz [N*m] on the body (sign conventions in the module
        docstring), slip fraction, traction/pressure fields and the flexibilities used.

    Raises
    ------
    InputError
        An argument out of range (the message names it), or b/a outside Kalker's table.

    References
    ----------
    Kalker (1982) Vehicle System Dynamics 11:1–13; Saccheto (2008) Eqs 5.36–5.54, Tabela 5.1.
    """
    a, b, N, mu, G, nu_x, nu_y, phi, nx, ny = _checked(a, b, normal_force, mu, shear_modulus,
                                                       creepage_x, creepage_y, spin, nx, ny)
    pressure = check_pressure(pressure)
    flexibilities = flexibility_parameters(a, b, G, coefficients=coefficients)
    return _run(a, b, N, mu, flexibilities, nu_x, nu_y, phi, nx, ny, compiled, pressure)


# ----------------------------------------------------------------- inverse problem
def _gross_slip(required: float, N: float, mu: float, detail: str) -> GrossSlipError:
    limit = mu * N
    needed = abs(required) / N if N > 0.0 else math.inf
    return GrossSlipError(
        f"required_force = {required:.6g} N needs a traction coefficient |F|/N = {needed:.6g} (mu_min) but "
        f"mu = {mu:.6g} gives a limit mu N = {limit:.6g} N: gross slip, {detail}; allowed: "
        f"|required_force| < mu * normal_force", required, limit, needed)


def solve_creepage(required_force: float, a: float, b: float, normal_force: float, mu: float,
                   shear_modulus: float, spin: float = 0.0, direction: str = "x", *,
                   other_creepage: float = 0.0, nx: int = DEFAULT_NX, ny: int = DEFAULT_NY,
                   compiled: bool = True, coefficients: tuple[float, float, float] | None = None,
                   pressure: str = DEFAULT_PRESSURE, maxiter: int = 200) -> CreepageSolution:
    """The creepage at which FASTSIM transmits a required force (force-controlled FASTSIM).

    Solves F_d(nu_d) = required_force for nu_d (d = ``direction``: nu_x and Fx, or nu_y and Fy)
    at the given spin and the other creepage held at ``other_creepage``, with
    :func:`scipy.optimize.brentq` on a bracket grown by doubling from Kalker's linear-theory
    guess nu = -F/(C G a b). F is the force **on the body** whose creepage is solved (module
    docstring), so a positive required force comes with a negative creepage.

    The force the contact can transmit is bounded by mu N (reached without spin at a finite
    creepage, with spin only as nu -> infinity since part of the adhesion goes to the spin).
    ``|required_force| >= mu N`` (Saccheto's mu_min = F_t/N at or above Ct) therefore has no
    creepage: :class:`GrossSlipError` (an :class:`~camcontact.errors.InputError`) is raised,
    never a NaN. The same error is raised if no bracket is found within 200 doublings (a force
    within rounding of the limit with spin).

    Parameters
    ----------
    required_force : float
        Target force component F_d on the body [N], |F| < mu N.
    a, b, normal_force, mu, shear_modulus, nx, ny, compiled, coefficients, pressure
        As in :func:`fastsim` (``pressure``: "parabolic", Kalker's, default, or "hertz").
    spin : float
        Spin creepage phi [1/m].
    direction : {"x", "y"}
        Solve nu_x for Fx (default, the rolling direction) or nu_y for Fy.
    other_creepage : float
        The creepage of the other direction [-] (nu_y when direction is "x"), held fixed.
    maxiter : int
        brentq's iteration limit.

    Returns
    -------
    CreepageSolution
        The creepage [-], the FastsimResult there, the bracket and every (creepage, force) evaluated.

    Raises
    ------
    GrossSlipError
        |required_force| >= mu N.
    InputError
        Other bad input (named).
    ConvergenceError
        brentq did not converge within ``maxiter`` (``record`` holds the evaluations).

    References
    ----------
    Saccheto (2008) §5.5 (the creepages follow from the required traction; reference §2.8);
    Kalker (1982).
    """
    if direction not in DIRECTIONS:
        raise InputError(f"direction = {direction!r}; allowed: 'x' (rolling, solves creepage_x) or 'y' (lateral)")
    required = _finite(required_force, "required_force", "[N]")
    a, b, N, mu, G, _, _, phi, nx, ny = _checked(a, b, normal_force, mu, shear_modulus, 0.0, 0.0, spin, nx, ny)
    other = _finite(other_creepage, "other_creepage", "[-]")
    pressure = check_pressure(pressure)
    flexibilities = flexibility_parameters(a, b, G, coefficients=coefficients)
    limit = mu * N
    if abs(required) >= limit and required != 0.0:
        raise _gross_slip(required, N, mu, "no creepage transmits it")
    evaluations: list[tuple[float, float]] = []

    def run(nu: float) -> FastsimResult:
        creepages = (nu, other) if direction == "x" else (other, nu)
        return _run(a, b, N, mu, flexibilities, *creepages, phi, nx, ny, compiled, pressure)

    def residual(nu: float) -> float:
        result = run(nu)
        force = result.Fx if direction == "x" else result.Fy
        evaluations.append((nu, force))
        return force - required

    # linear theory: F = -k nu with k = C G a b = 8 a^2 b / (3 L)
    stiffness = 8.0 * a * a * b / (3.0 * flexibilities[0 if direction == "x" else 1])
    guess = -required / stiffness
    scale = max(abs(guess), limit / stiffness, 1e-300)
    if residual(guess) == 0.0:
        return CreepageSolution(guess, direction, required, run(guess), (guess, guess), tuple(evaluations), 0, True)
    low, high = _bracket(residual, guess, evaluations[-1][1] - required, scale, required, N, mu)
    root, info = brentq(residual, low, high, xtol=1e-14 * scale, rtol=4.0 * np.finfo(float).eps,
                        maxiter=maxiter, full_output=True, disp=False)
    if not info.converged:
        raise ConvergenceError(f"solve_creepage: brentq stopped after {info.iterations} iterations "
                               f"({info.flag}) on the bracket [{low:.6g}, {high:.6g}]", tuple(evaluations))
    return CreepageSolution(float(root), direction, required, run(root), (low, high), tuple(evaluations),
                            info.iterations, True)


def _bracket(residual, guess: float, value: float, scale: float, required: float, N: float, mu: float):
    """[low, high] around the root of the decreasing ``residual``, grown by doubling from ``guess``."""
    toward = 1.0 if value > 0.0 else -1.0  # residual decreases with the creepage
    inner, step = guess, 0.5 * scale
    for _ in range(MAX_BRACKET_EXPANSIONS):
        outer = guess + toward * step
        if residual(outer) * toward <= 0.0:
            return (inner, outer) if toward > 0.0 else (outer, inner)
        inner, step = outer, 2.0 * step
    raise _gross_slip(required, N, mu, f"no bracket within {MAX_BRACKET_EXPANSIONS} doublings of the creepage "
                      "(the force is within rounding of the spin-reduced limit)")
