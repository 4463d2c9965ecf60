"""Transient isothermal line-contact EHL with the squeeze term, for the cam cycle.

The time-dependent Reynolds equation of a line contact (Tsuha 2015 Eq. 4.2; Venner & Lubrecht
2000 ch. 9-10)

.. math::
    \\frac{\\partial}{\\partial x}\\left(\\frac{\\rho h^3}{12\\eta}\\frac{\\partial p}{\\partial x}\\right)
    - u_m(t)\\frac{\\partial(\\rho h)}{\\partial x} - \\frac{\\partial(\\rho h)}{\\partial t} = 0,\\qquad
    p \\ge 0,\\qquad \\int p\\,dx = w(t)

    h = h_0(t) + \\frac{x^2}{2R(t)} - \\frac{4}{\\pi E'}\\int \\ln|x - x'|\\,p(x')\\,dx'

with u_m = (u1 + u2)/2 (signed), is written in ONE fixed dimensional reference, so that the grid
and the time derivative mean the same over the whole cycle. The reference is a load per length
w_r, a radius R_r and a speed u_r (default: the loaded instant with the largest Hertz half-width,
and the largest |u_m|), with b_r = sqrt(8 w_r R_r/(pi E')), p_r = 2 w_r/(pi b_r):

.. math::
    X = x/b_r,\\quad P = p/p_r,\\quad H = h R_r/b_r^2,\\quad T = t u_r/b_r,\\quad
    s(T) = u_m/u_r,\\quad r(T) = R_r/R

    \\frac{d}{dX}\\left(\\xi\\frac{dP}{dX}\\right) - s\\frac{d(\\bar\\rho H)}{dX}
    - \\frac{d(\\bar\\rho H)}{dT} = 0,\\quad \\xi = \\frac{\\bar\\rho H^3}{\\bar\\eta\\lambda_r},\\quad
    \\lambda_r = \\frac{12 u_r \\eta_0 R_r^2}{b_r^3 p_r}

    H = H_0 + r\\frac{X^2}{2} - \\frac{1}{\\pi}\\int \\ln|X - X'|\\,P\\,dX',\\qquad
    \\int P\\,dX = \\frac{\\pi}{2}\\frac{w}{w_r}

At the reference instant (s = r = 1, w = w_r) this is exactly the steady problem of
:mod:`camcontact.ehl.line_problem` (lambda_r = 3 pi^2/(8 M_r^2), alpha-bar = alpha p_r).

Discretisation: the steady one of :mod:`camcontact.ehl.line_operator` (central Poiseuille term,
second-order upwind wedge, piecewise-constant-pressure deformation, trapezoidal load balance)
with the wedge scaled by s and upwinded in the direction of the flow: backward for u_m > 0,
forward for u_m < 0, absent at u_m = 0 (then only the squeeze term carries the film); a step
with u_m < 0 is solved on the grid mirrored about X = 0 with |u_m|, so that the Gauss-Seidel
sweeps and distributive dipoles follow the flow (sweeping against it diverged). Time:
implicit BDF2 with variable steps (BDF1 on the first step, or throughout with
``scheme="bdf1"``); the history part of d(rho H)/dT goes into the right-hand side of the FAS
problem, the implicit part c_t rho H into the operator
(:mod:`camcontact.ehl._kernels`). Each step is solved by the compiled FAS cycles of
the steady solver (same hierarchy, MLMI, coarsest-grid Newton, free-boundary rules, the
pressure spike's nodes solved together; V-cycles by default), warm-started from the linear
extrapolation of the last two states (``predictor``) and stopped as soon as one cycle
changes H_min and H0 by less than the tolerance; if a step diverges or stalls it is retried with the
conservative settings of :data:`camcontact.ehl.line_multigrid.ROBUST`. Cavitation: P >= 0
(complementarity, as in the steady solver) with, by default, a full film everywhere (the lubricant of a
cavitated region is not tracked); with ``cavitation="mass_conserving"`` the Jakobsson–Floberg–Olsson film
fraction theta (:mod:`camcontact.ehl._kernels`) is solved in every step and carried to the next: the time
derivative acts on the content theta rho H, so that what the contact leaves behind is what it meets when the
entrainment reverses. Both ends of the domain are flooded reservoirs (theta = 1 at the inflow boundary), unless a
starved inflow is given (``oil_layer``): the surfaces then bring a layer of that thickness at whichever end the flow
enters, and each step places the inlet meniscus where its mass balance holds
(:meth:`TransientLineSolver._starved_step`, :func:`meniscus_balance`).

The march starts from the steady solution of the first instant (which needs u_m != 0) or from
a given state. Per step it returns h_c = H(0) b_r^2/R_r, h_min, p_max, H0 and a convergence
record; non-converged steps give a :class:`~camcontact.errors.ConvergenceWarning` (or
:class:`~camcontact.errors.ConvergenceError` with ``strict=True``); a non-finite state always
raises.

References
----------
Venner, C.H. & Lubrecht, A.A. (2000) Multilevel Methods in Lubrication, Elsevier, ch. 9-10.
Tsuha, N.A.H. (2015) MSc thesis, UNICAMP, Eq. 4.2 and §6.2.1 (the squeeze term neglected; u_m
reverses at the nose of the flat-faced follower).
"""

from __future__ import annotations

import math
import time
import warnings

import attrs
import numpy as np

from ..errors import ConvergenceError, ConvergenceWarning, InputError
from .attempts import run_ladder
from .cycle_monitor import CycleMonitor
from .groups import hamrock_line, moes_line
from .line_domain import automatic_domain
from .line_multigrid import WARM_RULES
from .line_multigrid import ROBUST, LineHierarchy, MultigridSettings, coarsest_level, solve_multigrid
from .line_problem import ROELANDS_P0, LineEHLProblem
from .line_solution import ConvergenceRecord
from .line_starved import solve_starved

__all__ = ["MENISCUS_SOLVES", "TransientLineResult", "TransientLineSolver", "TransientScaling", "TransientStep",
           "meniscus_balance", "transient_cycle"]

SCHEMES = ("bdf1", "bdf2")


# ----------------------------------------------------------------------------- scaling
@attrs.frozen
class TransientScaling:
    """The fixed dimensional reference of a transient march (see the module docstring).

    Attributes: R [m], w [N/m], u [m/s] of the reference; b [m], p_h [Pa], h_scale = b^2/R [m],
    time_scale = b/u [s]; ``problem``: the dimensionless :class:`LineEHLProblem` of the reference
    (its lambda and laws are those of the transient operator; its domain the grid's).
    """

    R: float
    w: float
    u: float
    E_reduced: float
    b: float
    p_h: float
    h_scale: float
    time_scale: float
    problem: LineEHLProblem
    eta0: float
    alpha: float

    @classmethod
    def from_reference(cls, *, R: float, w: float, u: float, E_reduced: float, eta0: float, alpha: float,
                       z: float | None = None, viscosity: str = "roelands", density: str = "dowson_higginson",
                       p0: float = ROELANDS_P0, elastic: bool = True, domain: tuple = (-4.0, 4.0),
                       cavitation: str = "reynolds") -> TransientScaling:
        """Reference from R [m], w [N/m], u > 0 [m/s], E' [Pa], eta0 [Pa*s], alpha [1/Pa]; ``cavitation`` that of
        :class:`LineEHLProblem` (``"mass_conserving"`` carries the film fraction from step to step)."""
        for name, value in (("R", R), ("w", w), ("u", u), ("E_reduced", E_reduced), ("eta0", eta0)):
            if not (isinstance(value, (int, float, np.floating)) and math.isfinite(value) and value > 0):
                raise InputError(f"transient EHL reference: {name} = {value!r} must be finite and > 0")
        if not (math.isfinite(alpha) and alpha >= 0):
            raise InputError(f"transient EHL reference: alpha = {alpha!r} 1/Pa must be finite and >= 0")
        problem = LineEHLProblem.from_contact(R=R, w=w, E_reduced=E_reduced, u_m=u, eta0=eta0, alpha=alpha, z=z,
                                              viscosity=viscosity, density=density, p0=p0, elastic=elastic,
                                              domain=tuple(domain))
        problem = attrs.evolve(problem, cavitation=cavitation)
        b = math.sqrt(8.0 * w * R / (math.pi * E_reduced))
        return cls(R=float(R), w=float(w), u=float(u), E_reduced=float(E_reduced), b=b, p_h=2.0 * w / (math.pi * b),
                   h_scale=b * b / R, time_scale=b / u, problem=problem, eta0=float(eta0), alpha=float(alpha))


# ----------------------------------------------------------------------------- results
@attrs.frozen
class TransientStep:
    """One solved instant: dimensional films and pressure, H0 (reference scaling), the record."""

    #: instant [s]
    time: float
    #: central film h(0) [m]
    h_c: float
    #: minimum film [m]
    h_min: float
    #: maximum pressure [Pa]
    p_max: float
    #: film constant [-] in the reference scaling (H = h R_r/b_r^2)
    H0: float
    #: convergence record of the instant
    record: ConvergenceRecord
    #: P = p/p_r [-] on the reference grid (``keep_fields`` only, else None)
    P: np.ndarray = attrs.field(repr=False, eq=False, default=None)
    #: H = h R_r/b_r^2 [-] on the reference grid (``keep_fields`` only, else None)
    H: np.ndarray = attrs.field(repr=False, eq=False, default=None)
    #: film fraction theta [-] on the reference grid (``keep_fields`` only, else None; 1 unless mass-conserving)
    theta: np.ndarray = attrs.field(repr=False, eq=False, default=None)
    #: position of the minimum film [m] from the contact centre, positive in the direction of positive u_m
    x_min: float = float("nan")


@attrs.frozen
class TransientLineResult:
    """Per-instant results of :func:`transient_cycle` (arrays over ``times``).

    ``h_c``, ``h_min`` [m], ``p_max`` [Pa]; ``H0``, ``H_c``, ``H_min`` in the reference scaling
    (H = h R_r/b_r^2); ``converged`` per instant; ``records`` the convergence record of every
    instant (the first: the steady start); ``X`` the grid (x = X b_r) and, if asked for, ``P``
    and ``H`` (one row per instant); ``wall_time`` the wall-clock time of the march [s].
    """

    times: np.ndarray
    h_c: np.ndarray
    h_min: np.ndarray
    p_max: np.ndarray
    H0: np.ndarray
    converged: np.ndarray
    records: tuple
    scaling: TransientScaling
    scheme: str
    X: np.ndarray
    P: np.ndarray | None = None
    H: np.ndarray | None = None
    wall_time: float = 0.0
    #: film fraction per instant and node (``keep_fields`` only)
    theta: np.ndarray | None = None
    #: position of the minimum film per instant [m] from the contact centre, positive in the direction of positive
    #: u_m (where the film is thinnest: the exit constriction, or upstream as the entrainment reverses)
    x_min: np.ndarray | None = None

    @property
    def H_c(self) -> np.ndarray:
        """Central film per instant in the reference scaling, h_c R_r/b_r^2 [-]."""
        return self.h_c / self.scaling.h_scale

    @property
    def H_min(self) -> np.ndarray:
        """Minimum film per instant in the reference scaling, h_min R_r/b_r^2 [-]."""
        return self.h_min / self.scaling.h_scale

    def to_frame(self):
        """pandas DataFrame, one row per instant."""
        import pandas as pd

        return pd.DataFrame({
            "time [s]": self.times, "h_c [m]": self.h_c, "h_min [m]": self.h_min, "p_max [Pa]": self.p_max,
            "H0 [-]": self.H0, "converged": self.converged,
            "cycles": [r.cycles for r in self.records],
        })


# ----------------------------------------------------------------------------- the hierarchy
class _TransientHierarchy(LineHierarchy):
    """The steady solver's level hierarchy, buffers and compiled cycles, with the operator's speed
    ratio s and squeeze coefficient c_t and the film's curvature set per step."""

    def __init__(self, problem, levels, settings, compiled):
        super().__init__(problem, levels, settings, compiled)
        self.base_parabola = self.parabola.copy()
        self.curvature = 1.0

    def set_conditions(self, curvature: float, s: float, c_t: float) -> None:
        self.curvature, self.s, self.c_t = float(curvature), float(s), float(c_t)
        np.multiply(self.base_parabola, self.curvature, out=self.parabola)
        self.dry_all[:] = False
        self.dry = {}

    def film(self, level, P, H0):
        parabola = self.curvature * level.parabola
        if not self.problem.elastic:
            return H0 + parabola
        return H0 + parabola - level.deform(P) / math.pi


# ----------------------------------------------------------------------------- the marcher
#: the stop rules of a step's cycles: a warm-started steady solve's (:data:`camcontact.ehl.line_multigrid.WARM_RULES`)
#: without its load floor (converged when the changes of (H_min, H0) fall below the tolerance and the load error
#: below 10 x the tolerance, or when fast-contracting cycles leave less than the tolerance to change; measured on
#: the LS-1 flat-follower turn, 720 steps at level 8, tolerance 1e-5: 5.7 -> 4.4 s with the estimate, h_min over
#: the turn 145.063 -> 145.016 nm)
MONITOR_RULES = attrs.evolve(WARM_RULES, load_floor=0.0)
#: the stop rules of a step with mass-conserving cavitation: the plain change test (its lubricant content, watched,
#: settles irregularly; measured: with the estimate a step of the reversal march balanced its lubricant 5.3e-4 of
#: the inflow off, against the 5e-4 the plain test keeps)
MASS_CONSERVING_RULES = attrs.evolve(MONITOR_RULES, estimate_remaining=False)


#: solves of a starved step at most in its search for the meniscus (:meth:`TransientLineSolver._starved_step`)
MENISCUS_SOLVES = 8
#: a starved step places its meniscus by its mass balance (:meth:`TransientLineSolver._starved_step`) when the
#: surfaces travel at least this many nodes in the step; slower, the film fractions' relaxation moves the meniscus
#: (measured on the LS-1 flat follower, level 8: around the reversals, where the layer barely moves, the held
#: layer's search diverged)
MENISCUS_MIN_TRAVEL = 10.0


def _checked_oil_layer(oil_layer, scaling: TransientScaling) -> float:
    if not (isinstance(oil_layer, (int, float, np.floating)) and math.isfinite(oil_layer) and oil_layer > 0):
        raise InputError(f"transient EHL: oil_layer = {oil_layer!r} m must be finite and > 0")
    if scaling.problem.cavitation != "mass_conserving":
        raise InputError(f"transient EHL: a starved inflow (oil_layer = {oil_layer!r} m) needs cavitation = "
                         f"'mass_conserving', not {scaling.problem.cavitation!r} (clipping does not conserve the "
                         "lubricant, so the layer would have no effect)")
    return float(oil_layer)


def meniscus_balance(P: np.ndarray, H: np.ndarray, problem: LineEHLProblem, s: float, j: int, h: float,
                     layer: float, shift: float, dT: float, factor: np.ndarray | None = None,
                     couette: np.ndarray | None = None) -> float:
    """The mass balance of an inlet meniscus before node j of a step solved with the nodes before j held (arrays in
    the flow's frame, inflow at index 0; s the speed ratio, h the spacing, reference scaling):

    .. math::
        g = F_{j+1/2} - |s|\\,q_{layer} - \\frac{\\Delta X_m}{\\Delta T}\\,(H_{j-1} - q_{layer}),\\qquad
        F_{j+1/2} = |s|\\,\\tfrac{1}{2}(3 q_j - q_{j-1}) - \\xi_{j+1/2}\\,\\frac{P_{j+1} - P_j}{h}

    F the discrete flux of the film through the face after node j as the kernels' conservative wedge has it (the
    held node j - 1 full, q = rho H; :func:`camcontact.ehl._kernels.wedge_weight`), q_layer the content the
    layer brings, and the last term the lubricant the pool ahead of the contact gives up as its meniscus moves
    downstream by ``shift`` = Delta X_m in the step Delta T (implicit Euler). g = 0 is the meniscus's
    conservation of mass (steady: the film passes exactly what the layer brings, the condition of
    :func:`camcontact.ehl.line_starved.solve_starved`); g > 0: the meniscus lies too far upstream. ``factor``: the
    flow factors of nodes j and j + 1 on the Poiseuille coefficient (a thermal or Eyring film,
    :func:`camcontact.ehl._kernels.flow_factor`; None: 1); ``couette``: the Couette factors of nodes j - 1 and j on
    the wedge's content (None: 1)."""
    rho = problem.density_ratio(P[j - 1:j + 2])
    q = rho * H[j - 1:j + 2]
    if couette is not None:
        q[:2] = q[:2] * couette
    xi = problem.flow_coefficient(P[j:j + 2], H[j:j + 2])
    if factor is not None:
        xi = xi * factor
    flux = abs(s) * 0.5 * (3.0 * q[1] - q[0]) - 0.5 * float(xi[0] + xi[1]) * float(P[j + 1] - P[j]) / h
    return float(flux - abs(s) * layer - shift / dT * (H[j - 1] - layer))


@attrs.frozen
class _Attempt:
    """One attempt of :meth:`TransientLineSolver._solve`, as :func:`camcontact.ehl.attempts.run_ladder` wants it."""

    P: np.ndarray = attrs.field(eq=False)
    H0: float
    H: np.ndarray = attrs.field(eq=False)
    record: ConvergenceRecord
    settings: MultigridSettings
    theta: np.ndarray = attrs.field(eq=False)


class TransientLineSolver:
    """Implicit time march of the transient line contact in a fixed reference scaling.

    Parameters
    ----------
    scaling : TransientScaling
        The reference (its ``problem.domain`` is the grid's domain in units of b_r).
    levels : int
        Finest grid level (n = 14 2^(levels-1) + 1 nodes over the domain).
    scheme : str
        ``"bdf2"`` (default; variable-step BDF2, BDF1 on the first step) or ``"bdf1"``.
    tolerance : float
        Per step: stop when the change of H_min and H0 between cycles falls below it and the
        load error below ten times it (reference scaling).
    settings : MultigridSettings, optional
        Cycle settings; a step that fails is retried with :data:`~.line_multigrid.ROBUST`.
        Default: V(2,1)-cycles (not lean: the steps run their own cycles) and the cycles' coarsest level from
        :func:`coarsest_level`
        (a warm-started step needs little coarse-grid work; measured on the LS-1 roller turn, 720 steps, level 8,
        5 % slip: V 16.4 s, 4.3 cycles per step, against F 22.4 s, 3.3 cycles; h_min the same to 0.002 nm).
    strict : bool
        Raise ConvergenceError for a non-converged step instead of warning.
    compiled : bool
        numba kernels (False: the plain-Python twins, slow; for tests).
    keep_fields : bool
        Keep P and H of every step in the returned :class:`TransientStep`.
    predictor : bool
        Start each step from the linear extrapolation in time of the last two states (P clipped at 0, H0), when
        the last step converged and the flow kept its direction; else from the last state. Either way the
        cycles stop as soon as one of them changes H_min and H0 by less than the tolerance (the change of the
        first cycle is measured from the start). Measured on the LS-1 roller turn (720 steps, level 7, 5 %
        slip, F-cycles): 2.7 instead of 3.6 cycles per step with both, 3.1 with the stop rule alone; h_min the
        same to 1e-3 nm.
    oil_layer : float, optional
        A starved inflow [m]: the lubricant layer (both surfaces together, at ambient density) that the surfaces
        carry into the domain at its inflow end, whichever end that is (needs the scaling's cavitation
        ``"mass_conserving"``; None: both ends are flooded reservoirs). The inlet meniscus, where the layer fills
        the gap, is placed where its mass balance holds (:func:`meniscus_balance`; see :meth:`_starved_step`); the steady start is
        the starved steady solution (:func:`~camcontact.ehl.line_starved.solve_starved`).
    """

    def __init__(self, scaling: TransientScaling, levels: int = 8, *, scheme: str = "bdf2", tolerance: float = 1e-6,
                 settings: MultigridSettings | None = None, strict: bool = False, compiled: bool = True,
                 keep_fields: bool = False, predictor: bool = True, oil_layer: float | None = None):
        if not (isinstance(levels, (int, np.integer)) and 2 <= levels <= 16):
            raise InputError(f"transient EHL: levels = {levels!r}; allowed 2..16")
        if scheme not in SCHEMES:
            raise InputError(f"transient EHL: scheme = {scheme!r}; allowed: {', '.join(SCHEMES)}")
        if not (tolerance > 0 and math.isfinite(tolerance)):
            raise InputError(f"transient EHL: tolerance = {tolerance!r} must be finite and > 0")
        self.scaling = scaling
        self.problem = scaling.problem
        self.levels = int(levels)
        self.scheme = scheme
        self.tolerance = float(tolerance)
        coarsest = max(1, min(coarsest_level(scaling.problem.domain), int(levels) - 1))
        if settings is None:
            settings = MultigridSettings(cycle="V", pre_sweeps=2, lean=False, cycle_coarsest=coarsest)
        elif settings.cycle_coarsest is None:  # the march's coarse spacing (COARSEST_SPACING), not the steady one
            settings = attrs.evolve(settings, cycle_coarsest=coarsest)
        self.settings = settings
        self.strict = strict
        self.compiled = compiled
        self.keep_fields = keep_fields
        self.predictor = bool(predictor)
        #: the inflow's lubricant layer as content h_oil R_r/b_r^2 (infinite: flooded ends) and the tracked inlet
        #: meniscus X_m [-] of the current state (None: none tracked; see ``oil_layer``)
        self.oil_layer = None if oil_layer is None else _checked_oil_layer(oil_layer, scaling)
        self.supply = math.inf if self.oil_layer is None else self.oil_layer / scaling.h_scale
        self.meniscus: float | None = None
        #: (P, H0, speed ratio s) before the last step, if that step converged: the predictor's second state
        self.before: tuple[np.ndarray, float, float | None] | None = None
        self.s_current: float | None = None  #: the speed ratio of the current state (None: a given state)
        self._hierarchies: dict = {}
        first = self._hierarchy(self.settings)
        self.X = first.levels[-1].X.copy()
        self.n = self.X.size
        # state: P, H0 and the history of q = rho H (last two) with their time steps
        self.time: float | None = None
        self.P: np.ndarray | None = None
        self.H0 = 0.0
        self.q_history: list[np.ndarray] = []
        self.dt_previous: float | None = None
        #: film fraction on the reference grid (1: full film; below 1 where a mass-conserving march cavitates)
        self.theta = np.ones(self.n)
        #: flow factors (a, k) and optionally Couette factors c on the reference grid for the next steps
        #: (:mod:`camcontact.ehl._kernels`; None: the isothermal Newtonian film), set by the thermal march
        #: (:mod:`camcontact.ehl.line_thermal`)
        self.flow: tuple | None = None

    def _hierarchy(self, settings, mirrored: bool = False) -> _TransientHierarchy:
        """The level hierarchy of ``settings``; ``mirrored``: of the domain reflected about X = 0
        (solves with u_m < 0 run there, so that the sweeps follow the flow)."""
        key = (settings, mirrored)
        hierarchy = self._hierarchies.get(key)
        if hierarchy is None:
            problem = self.problem
            if mirrored:
                problem = attrs.evolve(problem, domain=(-problem.domain[1], -problem.domain[0]))
            hierarchy = self._hierarchies[key] = _TransientHierarchy(problem, self.levels, settings, self.compiled)
            hierarchy.supply = self.supply
        return hierarchy

    # ------------------------------------------------------------------ conditions
    def _conditions(self, w: float, R: float, u_m: float) -> tuple[float, float, float]:
        for name, value, positive in (("w", w, True), ("R", R, True), ("u_m", u_m, False)):
            if not math.isfinite(value) or (positive and not value > 0):
                raise InputError(f"transient EHL: {name} = {value!r} must be finite" + (" and > 0" if positive else ""))
        sc = self.scaling
        return sc.R / R, u_m / sc.u, 0.5 * math.pi * (w / sc.w - 1.0)

    def film(self, P: np.ndarray, H0: float, R: float) -> np.ndarray:
        """Film H [-] (reference scaling) on the finest grid for P (p/p_r), H0 and the radius R [m]."""
        hierarchy = self._hierarchy(self.settings)
        hierarchy.curvature = self.scaling.R / R
        return hierarchy.film(hierarchy.levels[-1], P, H0)

    def density(self, P: np.ndarray) -> np.ndarray:
        """Density ratio rho-bar [-] at P (p/p_r)."""
        return self.problem.density_ratio(P)

    def content(self, P: np.ndarray, H: np.ndarray) -> np.ndarray:
        """Lubricant content q = theta rho-bar H [-] per node (the film fraction of the current state)."""
        return self.theta * self.density(P) * H

    # ------------------------------------------------------------------ starts
    def set_state(self, time_: float, P: np.ndarray, H0: float, R: float) -> None:
        """Start the march from a given state on this solver's grid (``X``): P (p/p_r), H0, radius R [m]."""
        P = np.asarray(P, dtype=float)
        if P.shape != (self.n,) or not np.all(np.isfinite(P)) or not math.isfinite(H0):
            raise InputError(f"transient EHL: initial P must be {self.n} finite values and H0 finite")
        if not math.isfinite(time_):
            raise InputError(f"transient EHL: initial time {time_!r} must be finite")
        self.P = np.maximum(P, 0.0)
        self.P[0] = self.P[-1] = 0.0
        self.H0 = float(H0)
        self.time = float(time_)
        H = self.film(self.P, self.H0, R)
        self.theta = np.ones(self.n)
        self.q_history = [self.content(self.P, H)]
        self.dt_previous = None
        self.before, self.s_current = None, None
        self.meniscus = None

    def steady_start(self, time_: float, w: float, R: float, u_m: float) -> TransientStep:
        """Start at ``time_`` [s] from the steady solution of the instant with load w [N/m], radius R [m]
        and entrainment speed u_m [m/s] (needs u_m != 0).

        Solved with :func:`solve_multigrid` in the instant's own Hertz scaling (mirrored when
        u_m < 0), mapped onto the reference grid and converged there with the steady
        (c_t = 0) operator.
        """
        curvature, s, f_load = self._conditions(w, R, u_m)
        if u_m == 0.0:
            raise InputError("transient EHL: the steady start needs u_m != 0 at the first instant "
                             "(give an initial state with set_state instead)")
        sc = self.scaling
        own = LineEHLProblem.from_contact(R=R, w=w, E_reduced=sc.E_reduced, u_m=abs(u_m), eta0=sc.eta0,
                                          alpha=sc.alpha, z=self.problem.z, viscosity=self.problem.viscosity,
                                          density=self.problem.density, p0=self.problem.p0,
                                          elastic=self.problem.elastic)
        b0 = math.sqrt(8.0 * w * R / (math.pi * sc.E_reduced))
        sigma = 1.0 if u_m > 0 else -1.0
        xa, xb = self.problem.domain
        lo, hi = sorted((sigma * xa * sc.b / b0, sigma * xb * sc.b / b0))
        own = attrs.evolve(own, domain=(min(lo, -1.5), max(hi, 1.2)))
        start = time.perf_counter()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ConvergenceWarning)
            if self.oil_layer is None:
                steady = solve_multigrid(own, self.levels, tolerance=min(self.tolerance, 1e-7))
            else:
                own = attrs.evolve(own, cavitation="mass_conserving", supply=self.oil_layer * R / (b0 * b0))
                steady = solve_starved(own, self.levels, tolerance=min(self.tolerance, 1e-7))
        p_own = 2.0 * w / (math.pi * b0)
        X_own = sigma * self.X * sc.b / b0  # the reference nodes in the instant's own units
        P = np.interp(X_own, steady.X, steady.P, left=0.0, right=0.0) * p_own / sc.p_h
        P[0] = P[-1] = 0.0
        H_c = steady.H_c * (b0 * b0 / R) / sc.h_scale
        H_rel = self.film(P, 0.0, R)
        H0 = H_c - float(np.interp(0.0, self.X, H_rel))
        self.theta = np.ones(self.n)
        if self.oil_layer is None or steady.inlet_meniscus is None:
            step = self._solve(P, H0, curvature, s, 0.0, np.zeros(self.n), f_load, start, "steady start")
        else:  # the starved start: its meniscus found again on this grid, as a step's (steady: dT infinite)
            self.theta = np.minimum(np.interp(X_own, steady.X, steady.film_fraction), 1.0)
            self.meniscus = sigma * steady.inlet_meniscus * b0 / sc.b
            self.P, self.H0, self.s_current = P, H0, s
            step = self._starved_step(P, H0, curvature, s, 0.0, np.zeros(self.n), f_load, start, "steady start",
                                      math.inf, R)
        self.P, self.H0, self.time = step[0], step[1], float(time_)
        H = step[2]
        self.q_history = [self.content(self.P, H)]
        self.dt_previous = None
        self.before, self.s_current = None, s
        return self._report(time_, H, step[3])

    # ------------------------------------------------------------------ time step
    def step(self, time_: float, w: float, R: float, u_m: float) -> TransientStep:
        """Advance to ``time_`` [s] with load w [N/m], radius R [m] and entrainment speed u_m [m/s]."""
        if self.P is None:
            raise InputError("transient EHL: start the march first (steady_start or set_state)")
        dt = float(time_) - self.time
        if not (dt > 0 and math.isfinite(dt)):
            raise InputError(f"transient EHL: times must increase; step to {time_!r} from {self.time!r}")
        curvature, s, f_load = self._conditions(w, R, u_m)
        dT = dt / self.scaling.time_scale
        if self.scheme == "bdf1" or len(self.q_history) < 2 or self.dt_previous is None:
            a0, history = 1.0, -self.q_history[-1]
        else:
            omega = dt / self.dt_previous
            a0 = (1.0 + 2.0 * omega) / (1.0 + omega)
            history = -(1.0 + omega) * self.q_history[-1] + omega * omega / (1.0 + omega) * self.q_history[-2]
        f = history / dT
        f[0] = f[-1] = 0.0
        start = time.perf_counter()
        P_start, H0_start = self._predicted(dt, s)
        before = (self.P, self.H0, self.s_current)
        label = f"t = {time_:.6g} s"
        if self.oil_layer is None or abs(s) * dT < MENISCUS_MIN_TRAVEL * (self.X[1] - self.X[0]):
            # flooded ends, or so slow a flow that the film fractions' relaxation keeps up with the meniscus
            P, H0, H, record = self._solve(P_start, H0_start, curvature, s, a0 / dT, f, f_load, start, label)
            self.meniscus = None
        else:
            P, H0, H, record = self._starved_step(P_start, H0_start, curvature, s, a0 / dT, f, f_load, start, label,
                                                  dT, R)
        self.before = before if record.converged else None
        self.s_current = s
        self.P, self.H0 = P, H0
        self.q_history = [self.q_history[-1], self.content(P, H)]
        self.dt_previous = dt
        self.time = float(time_)
        return self._report(time_, H, record)

    def _predicted(self, dt: float, s: float) -> tuple[np.ndarray, float]:
        """The start (P, H0) of a step of dt [s] to speed ratio s: the last two states extrapolated linearly in time
        (see ``predictor``), or the last state."""
        if not (self.predictor and self.before is not None and self.dt_previous is not None):
            return self.P, self.H0
        P_before, H0_before, s_before = self.before
        if not (s_before is not None and self.s_current is not None and s_before * s > 0 and self.s_current * s > 0):
            return self.P, self.H0
        ratio = dt / self.dt_previous
        P = np.maximum(self.P + ratio * (self.P - P_before), 0.0)
        P[0] = P[-1] = 0.0
        return P, self.H0 + ratio * (self.H0 - H0_before)

    def _report(self, time_, H, record) -> TransientStep:
        sc = self.scaling
        return TransientStep(
            time=float(time_), h_c=float(np.interp(0.0, self.X, H)) * sc.h_scale, h_min=float(H.min()) * sc.h_scale,
            p_max=float(self.P.max()) * sc.p_h, H0=self.H0, record=record,
            P=self.P.copy() if self.keep_fields else None, H=H.copy() if self.keep_fields else None,
            theta=self.theta.copy() if self.keep_fields else None, x_min=float(self.X[int(np.argmin(H))]) * sc.b,
        )

    def _starved_step(self, P, H0, curvature, s, c_t, f, f_load, start, label, dT, R):
        """A step with a starved inflow: the contact fed through an inlet meniscus where its mass balance holds
        (:func:`meniscus_balance`).

        The layer upstream of the meniscus is unpressurised and moves with the surfaces: its content at the
        step's end is the last state's content at X - s dT (the supply beyond the inflow end; after a reversal,
        the film the contact left on that side). Those nodes are held (the top level relaxes only from the
        first node j after the meniscus on, the two held nodes before it full, as the truncated inlet of
        :func:`camcontact.ehl.line_starved.solve_starved`), the step is solved, and the balance g of node j picks
        the next trial by secant steps over the node index, from the last step's meniscus (after a reversal, or
        from a state without one, from the first pressurised node seen from the new inflow end), at most
        :data:`MENISCUS_SOLVES` solves. The meniscus lies between the two nodes where g changes sign: the step's
        state is the two held solutions weighted linearly so that g vanishes (the meniscus between nodes, as
        solve_starved's is a continuous unknown; measured at level 7, M ~ 4: the nearer node alone put rho_c h_c
        1.7 % off the layer). A step whose search does not bracket the sign change keeps its smallest |g| and
        is flagged not converged.

        Why not let the film fractions' relaxation find the meniscus (the mass-conserving kernels can): it moves
        it by about a node per 6-40 cycles (:mod:`camcontact.ehl.line_starved`) and its front between a partly
        filled node and the first pressurised one does not converge while it moves (measured: the LS-1 flat
        follower, level 8, 1 degree steps: 166-176 of the 180 lift steps stagnated, held or not at their
        meniscus, the films 3-10 % off between 10 and 39 cycles per step). Node positions: the meniscus is
        placed between nodes by that weighting. Mass: the held layer moves by the exact shift, not by the kernels'
        upwind transport, and the meniscus closes the balance through g = 0, so the lubricant is conserved over
        the step as a whole (measured: the content's change equals the layer's inflow minus the exit film's
        outflow within 4.2e-4 of the inflow, BDF1, tolerance 1e-9), not node by node in the layer. Tried and
        dropped for the flooded mass-conserving march's reversals (whose contact meets the film it left behind,
        the same kind of front): 18 -> 5 unconverged of the LS-1 flat follower's 360 steps, but the films 26 %
        apart just after the second reversal and its node-by-node balance test broken; not adopted without a
        check of which is right."""
        sign = 1.0 if s > 0.0 else -1.0
        frame = (lambda a: a) if sign > 0.0 else (lambda a: a[::-1].copy())
        h = float(self.X[1] - self.X[0])
        X_flow = frame(sign * self.X)
        H_last = self.film(self.P, self.H0, R)
        tracked = self.meniscus is not None and self.s_current is not None and self.s_current * s > 0.0
        if tracked:
            j = int(np.searchsorted(X_flow, sign * self.meniscus))
        else:
            wet = np.flatnonzero(frame(self.P) > 0.0)
            j = int(wet[0]) if wet.size else -1
        if j < 4:  # pressurised up to the inflow end (or nowhere): no meniscus in the domain
            self.meniscus = None
            return self._solve(P, H0, curvature, s, c_t, f, f_load, start, label)
        X_before = sign * self.meniscus if tracked else X_flow[j] - 0.5 * h  # the meniscus at the step's start
        layer = np.interp(X_flow - abs(s) * dT, X_flow, np.maximum(frame(self.content(self.P, H_last)), 0.0),
                          left=self.supply)
        H_held = frame(H_last)
        theta_start = self.theta.copy()
        last = self.X.size - 3
        tried: dict[int, tuple] = {}

        def balance(j: int) -> float:
            theta = np.ones(self.X.size)
            theta[:j] = np.clip(layer[:j] / np.maximum(H_held[:j], 1e-300), 0.0, 1.0)
            theta[j - 2:j] = 1.0  # the truncated inlet: the film enters node j full
            self.theta = frame(theta)
            solved = [k for k in tried if tried[k] is not None]
            near = min(solved, key=lambda k: abs(k - j)) if solved else None
            start_P = frame(P if near is None else tried[near][0][0])
            start_P[:j] = 0.0
            try:
                result = self._solve(frame(start_P), H0 if near is None else tried[near][0][1], curvature, s, c_t,
                                     f, f_load, start, label, held=j)
            except ConvergenceError:  # held into the contact: taken as a meniscus too far downstream
                tried[j] = None
                return -math.inf
            P_f, H_f = frame(result[0]), frame(result[2])
            factor = None
            if self.flow is not None:  # the film's flow factors (thermal / Eyring march), a sqrt(1 + (k eta-bar)^2)
                a = frame(self.flow[0])[j:j + 2]
                k = np.zeros(2) if self.flow[1] is None else frame(self.flow[1])[j:j + 2]
                factor = self.problem.poiseuille_factor(P_f[j:j + 2], a, k)
            couette = None if self.flow is None or len(self.flow) < 3 else frame(self.flow[2])[j - 1:j + 1]
            g = meniscus_balance(P_f, H_f, self.problem, s, j, h, float(layer[j - 1]), X_flow[j] - 0.5 * h - X_before,
                                 dT, factor, couette)
            theta = frame(self.theta)
            theta[:j] = np.clip(layer[:j] / np.maximum(H_f[:j], 1e-300), 0.0, 1.0)  # the held layer, as it is
            tried[j] = (result, frame(theta), g)
            return g

        g = balance(j)
        low = high = None  # the nearest nodes with g > 0 (meniscus too far upstream) and g <= 0
        j_other, g_other = None, None
        for _ in range(MENISCUS_SOLVES - 1):
            if g > 0.0:
                low = j if low is None else max(low, j)
            else:
                high = j if high is None else min(high, j)
            if low is not None and high is not None and high - low <= 1:
                break
            if j_other is None or g == g_other or not (math.isfinite(g) and math.isfinite(g_other)):
                step = 2.0 if g > 0.0 else -2.0
            else:  # secant over the node index, inside the bracket once there is one
                step = -g * (j - j_other) / (g - g_other)
            j_next = int(round(j + max(min(step, 64.0), -64.0)))
            if low is not None and high is not None and not low < j_next < high:
                j_next = (low + high) // 2
            elif j_next == j:
                j_next = j + (1 if g > 0.0 else -1)
            j_next = min(max(j_next, 4), last)
            if j_next in tried:
                break
            j_other, g_other = j, g
            j, g = j_next, balance(j_next)
        if all(value is None for value in tried.values()):  # every trial failed: the film fractions alone
            self.theta = theta_start
            self.meniscus = None
            return self._solve(P, H0, curvature, s, c_t, f, f_load, start, label)
        pair = [k for k in tried if k + 1 in tried and tried[k] is not None and tried[k + 1] is not None
                and tried[k][2] * tried[k + 1][2] <= 0.0]
        if pair:  # between the two nodes: the states weighted so that the balance vanishes
            k = pair[0]
            (first, theta_first, g_first), (second, theta_second, g_second) = tried[k], tried[k + 1]
            weight = g_first / (g_first - g_second) if g_first != g_second else 0.0
            kept = first if weight <= 0.5 else second
            result = (first[0] + weight * (second[0] - first[0]), first[1] + weight * (second[1] - first[1]),
                      first[2] + weight * (second[2] - first[2]),
                      attrs.evolve(kept[3], converged=first[3].converged and second[3].converged))
            self.theta = theta_first + weight * (theta_second - theta_first)
            self.meniscus = sign * (X_flow[k] - 0.5 * h + weight * h)
            return result
        chosen = min((k for k in tried if tried[k] is not None), key=lambda k: abs(tried[k][2]))
        result, theta, g = tried[chosen]
        note = f"starved meniscus not bracketed in {len(tried)} solves (mass balance {g:.3g})"
        result = (*result[:3], attrs.evolve(result[3], converged=False,
                                            message=(result[3].message + "; " if result[3].message else "") + note))
        self.theta = theta
        self.meniscus = sign * (X_flow[chosen] - 0.5 * h)
        return result

    def _solve(self, P, H0, curvature, s, c_t, f, f_load, start, label, held=None):
        """Converge one instant; the robustness ladder on failure; warn/raise when not converged. ``held``: the
        nodes before this index, counted from the inflow end, are held unpressurised with their film fractions
        (the layer upstream of a starved meniscus; their pressures 0 in P)."""
        if c_t == 0.0 and s == 0.0:
            raise InputError("transient EHL: u_m = 0 without a time step has no solution")
        # reversed flow (s < 0) is solved on the mirrored grid with s > 0: the Gauss-Seidel sweeps
        # and the distributive dipoles of the relaxation then run in the direction of the flow
        # (measured: sweeping against the flow diverges a few steps after a reversal)
        mirrored = s < 0.0
        flip = (lambda a: a[::-1].copy()) if mirrored else (lambda a: a.copy())

        def attempt(settings):
            hierarchy = self._hierarchy(settings, mirrored)
            hierarchy.set_conditions(curvature, abs(s), c_t)
            if held is not None:  # in the flow's frame, the solve's
                hierarchy.hold_dry(np.arange(self.n) < held)
                hierarchy.int_settings[7] = held
            theta = hierarchy.theta(hierarchy.levels[-1])
            theta[:] = flip(self.theta)  # every attempt starts from the film fraction of the last step
            if self.flow is None:
                hierarchy.set_flow_factor(np.ones(self.n))
            else:
                hierarchy.set_flow_factor(flip(self.flow[0]), None if self.flow[1] is None else flip(self.flow[1]),
                                          None if len(self.flow) < 3 else flip(self.flow[2]))
            try:
                P_new, H0_new, H, record = self._cycles(hierarchy, flip(P), H0, flip(f), f_load)
            finally:
                hierarchy.int_settings[7] = 1
            return _Attempt(P=flip(P_new), H0=H0_new, H=flip(H), record=record, settings=settings,
                            theta=flip(theta))

        kept = run_ladder(self.settings, ROBUST, attempt, f"transient line EHL ({label})", strict=self.strict,
                          size=f"{self.n} nodes")
        record = attrs.evolve(kept.record, wall_time=time.perf_counter() - start)
        self.theta = kept.theta
        return kept.P, kept.H0, kept.H, record

    def _cycles(self, hierarchy, P, H0, f, f_load):
        settings = hierarchy.settings
        finest = hierarchy.levels[-1]
        k = len(hierarchy.levels) - 1
        tol = self.tolerance
        rules = MONITOR_RULES if not hierarchy.mass_conserving else MASS_CONSERVING_RULES
        watch = CycleMonitor(rules, tol, hierarchy.freeze_dry,
                             start=hierarchy.watched(finest, P, hierarchy.film(finest, P, H0), H0))
        work0 = hierarchy.work
        for _ in range(settings.max_cycles):
            P, H0 = hierarchy.cycle(k, P, H0, f, f_load)
            H = hierarchy.film(finest, P, H0)
            if not (np.all(np.isfinite(P)) and np.all(np.isfinite(H)) and math.isfinite(H0)):
                raise ConvergenceError("non-finite state")
            r = hierarchy.residual(finest, P, H) - f
            r[0] = r[-1] = 0.0
            r[:hierarchy.int_settings[7]] = 0.0  # held nodes (a starved inlet's layer) solve no equation
            r = np.where((P > 0.0) | (hierarchy.theta(finest) < 1.0), r, np.maximum(r, 0.0))
            if watch.after_cycle(P, hierarchy.watched(finest, P, H, H0), float(np.mean(np.abs(r[1:-1])) * finest.h),
                                 hierarchy.load(finest, P) - f_load, hierarchy.work - work0):
                break
        else:
            watch.out_of_cycles(settings.max_cycles)
        record = ConvergenceRecord(
            method=f"transient FAS multigrid ({self.scheme}), {settings.cycle}-cycles",
            levels=len(hierarchy.levels), nodes=finest.n, residuals=tuple(watch.residuals),
            load_errors=tuple(watch.loads), work_units=tuple(watch.works), wall_time=0.0, converged=watch.converged,
            message=watch.message, tolerance=tol,
        )
        return P, H0, H, record


# ----------------------------------------------------------------------------- cam-cycle driver
def automatic_transient_domain(u_m: np.ndarray, inlet: float = 4.0) -> tuple[float, float]:
    """[X_a, X_b] in units of b_r: (-inlet, 1.5) if u_m >= 0 throughout, (-1.5, inlet) if <= 0, else (-4, 4) (a
    reversal: either end is the inlet; :func:`march_inlet` gives ``inlet``)."""
    if np.all(u_m >= 0.0):
        return (-inlet, 1.5)
    if np.all(u_m <= 0.0):
        return (-1.5, inlet)
    return (-4.0, 4.0)


def march_inlet(w: np.ndarray, R: np.ndarray, u_m: np.ndarray, *, E_reduced: float, eta0: float, alpha: float,
                elastic: bool, reference: dict) -> float:
    """The inlet length [b_r] a march in one direction needs: the largest over its instants (u_m != 0) of the steady
    automatic domain's inlet (:func:`camcontact.ehl.line_domain.automatic_domain`, in units of the instant's own
    half-width b) times b/b_r, at least 4. M and L are taken to three digits, so that the instants of a smooth
    cycle share the domain's cached evaluations (its reaches are rounded up to powers of 2^(1/4) anyway)."""
    moving = u_m != 0.0
    if not np.any(moving):
        return 4.0
    w, R = w[moving], R[moving]
    M, L = moes_line(*hamrock_line(w, R, E_reduced, u_m[moving], eta0, alpha))
    b_ratio = np.sqrt(w * R / (reference["w"] * reference["R"]))
    inlet = 4.0
    for M_i, L_i, ratio in zip(_three_digits(M), _three_digits(L), b_ratio):
        inlet = max(inlet, -automatic_domain(M_i, L_i, elastic)[0] * ratio)
    return inlet


def _three_digits(values: np.ndarray) -> list[float]:
    return [float(f"{v:.3g}") for v in values]


def _as_series(name, value, n):
    array = np.asarray(value, dtype=float)
    if array.ndim == 0:
        array = np.full(n, float(array))
    if array.shape != (n,):
        raise InputError(f"transient_cycle: {name} must be a scalar or have the length of times ({n}), "
                         f"got shape {array.shape}")
    if not np.all(np.isfinite(array)):
        raise InputError(f"transient_cycle: {name} has non-finite values")
    return array


def transient_cycle(times, w, R, u_m, *, E_reduced: float, eta0: float, alpha: float, z: float | None = None,
                    viscosity: str = "roelands", density: str = "dowson_higginson", p0: float = ROELANDS_P0,
                    elastic: bool = True, levels: int = 8, scheme: str = "bdf2", tolerance: float = 1e-6,
                    reference: dict | None = None, domain: tuple | None = None,
                    settings: MultigridSettings | None = None, initial: tuple | None = None,
                    keep_fields: bool = False, strict: bool = False, compiled: bool = True,
                    cavitation: str = "reynolds", after_step=None, predictor: bool = True,
                    oil_layer: float | None = None) -> TransientLineResult:
    """Transient line-contact films over a sequence of instants (e.g. a cam cycle).

    Parameters
    ----------
    times : array [s]
        Strictly increasing instants (steps may vary; BDF2 uses variable-step coefficients).
    w : array or float [N/m]
        Load per unit length (> 0) at each instant.
    R : array or float [m]
        Reduced radius of curvature (> 0) at each instant.
    u_m : array or float [m/s]
        Signed entrainment speed (u1 + u2)/2; may pass through zero and change sign. The first
        instant needs u_m != 0 unless ``initial`` is given.
    E_reduced : float [Pa]
        E' = 2/[(1-nu1^2)/E1 + (1-nu2^2)/E2].
    eta0 [Pa*s], alpha [1/Pa], z, viscosity, density, p0 [Pa]
        Lubricant: ``"roelands"`` (z defaults to alpha p0/(ln eta0 + 9.67)) or ``"barus"``;
        ``"dowson_higginson"`` or ``"incompressible"``.
    elastic : bool
        False: rigid surfaces.
    levels : int
        Finest grid level (8: 1793 nodes).
    scheme : ``"bdf2"`` or ``"bdf1"``
    tolerance : float
        Per-step convergence tolerance (reference scaling).
    reference : dict, optional
        ``{"w": ..., "R": ..., "u": ...}`` (SI); default: w and R of the instant with the
        largest Hertz half-width, u = max |u_m|.
    domain : (float, float), optional
        [X_a, X_b] in units of b_r; default :func:`automatic_transient_domain` with the inlet :func:`march_inlet`.
    initial : (P, H0), optional
        Start state on the reference grid (P = p/p_r at the nodes, H0) instead of the steady start.
    keep_fields : bool
        Return P and H at every instant.
    strict : bool
        Raise ConvergenceError at the first non-converged step (default: one ConvergenceWarning
        listing them).
    cavitation : ``"reynolds"`` or ``"mass_conserving"``
        Cavitation by clipping (the lubricant of a cavitated region is not tracked), or the
        Jakobsson–Floberg–Olsson film fraction carried from step to step: the history of the time
        derivative is the content theta rho H, so that lubricant left behind the contact is what returns
        to it when the entrainment reverses (both domain ends are flooded reservoirs, unless ``oil_layer``).
    after_step : callable, optional
        ``after_step(i, solver)`` after the start (i = 0) and after each step i: it may read the
        :class:`TransientLineSolver`'s state and set its ``flow`` factors for the next steps (the thermal march,
        :func:`camcontact.ehl.line_thermal.thermal_transient_cycle`).
    predictor : bool
        Start each step from the linear extrapolation of the last two states (:class:`TransientLineSolver`).
    oil_layer : float, optional
        A starved inflow [m]: the lubricant layer the surfaces bring to the contact (both together), with
        ``cavitation="mass_conserving"`` (:class:`TransientLineSolver`); None: flooded domain ends.

    Returns
    -------
    TransientLineResult
    """
    start = time.perf_counter()
    times = np.asarray(times, dtype=float)
    if times.ndim != 1 or times.size < 1 or not np.all(np.isfinite(times)):
        raise InputError("transient_cycle: times must be a non-empty 1-D array of finite values [s]")
    if times.size > 1 and not np.all(np.diff(times) > 0):
        raise InputError("transient_cycle: times must be strictly increasing")
    n = times.size
    w = _as_series("w", w, n)
    R = _as_series("R", R, n)
    u_m = _as_series("u_m", u_m, n)
    if not np.all(w > 0):
        raise InputError(f"transient_cycle: w must be > 0 N/m at every instant (min {w.min()!r})")
    if not np.all(R > 0):
        raise InputError(f"transient_cycle: R must be > 0 m at every instant (min {R.min()!r})")
    if not np.any(u_m != 0.0) and initial is None:
        raise InputError("transient_cycle: u_m = 0 at every instant: give an initial state")
    for name, value in (("E_reduced", E_reduced), ("eta0", eta0)):
        if not (math.isfinite(value) and value > 0):
            raise InputError(f"transient_cycle: {name} = {value!r} must be finite and > 0")
    if reference is None:
        widths = w * R
        j = int(np.argmax(widths))
        reference = {"w": float(w[j]), "R": float(R[j]), "u": float(np.abs(u_m).max())}
    if domain is None:
        # (alpha is checked by the scaling below: a bad one reaches it as the isoviscous 0 here)
        inlet = march_inlet(w, R, u_m, E_reduced=E_reduced, eta0=eta0, alpha=alpha if alpha > 0 else 0.0,
                            elastic=elastic, reference=reference)
        domain = automatic_transient_domain(u_m, inlet)
    scaling = TransientScaling.from_reference(R=reference["R"], w=reference["w"], u=reference["u"],
                                              E_reduced=E_reduced, eta0=eta0, alpha=alpha, z=z, viscosity=viscosity,
                                              density=density, p0=p0, elastic=elastic, domain=tuple(domain),
                                              cavitation=cavitation)
    solver = TransientLineSolver(scaling, levels, scheme=scheme, tolerance=tolerance, settings=settings,
                                 strict=strict, compiled=compiled, keep_fields=keep_fields, predictor=predictor,
                                 oil_layer=oil_layer)
    steps = []
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ConvergenceWarning)
        if initial is None:
            steps.append(solver.steady_start(times[0], w[0], R[0], u_m[0]))
        else:
            solver.set_state(times[0], initial[0], initial[1], R[0])
            H = solver.film(solver.P, solver.H0, R[0])
            empty = ConvergenceRecord(method="given initial state", levels=levels, nodes=solver.n, residuals=(),
                                      load_errors=(), work_units=(), wall_time=0.0, converged=True)
            steps.append(solver._report(times[0], H, empty))
        if after_step is not None:
            after_step(0, solver)
        for i in range(1, n):
            steps.append(solver.step(times[i], w[i], R[i], u_m[i]))
            if after_step is not None:
                after_step(i, solver)
    others = [c for c in caught if not issubclass(c.category, ConvergenceWarning)]
    for c in others:
        warnings.warn_explicit(c.message, c.category, c.filename, c.lineno)
    converged = np.array([s.record.converged for s in steps])
    if not converged.all():
        bad = np.flatnonzero(~converged)
        warnings.warn(f"transient line EHL: {bad.size} of {n} instants not converged (indices "
                      f"{', '.join(map(str, bad[:10]))}{', ...' if bad.size > 10 else ''}); see the records",
                      ConvergenceWarning, stacklevel=2)
    return TransientLineResult(
        times=times, h_c=np.array([s.h_c for s in steps]), h_min=np.array([s.h_min for s in steps]),
        p_max=np.array([s.p_max for s in steps]), H0=np.array([s.H0 for s in steps]), converged=converged,
        records=tuple(s.record for s in steps), scaling=scaling, scheme=scheme, X=solver.X,
        P=np.array([s.P for s in steps]) if keep_fields else None,
        H=np.array([s.H for s in steps]) if keep_fields else None, wall_time=time.perf_counter() - start,
        theta=np.array([s.theta for s in steps]) if keep_fields else None, x_min=np.array([s.x_min for s in steps]),
    )
