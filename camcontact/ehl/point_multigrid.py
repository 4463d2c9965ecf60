"""FAS multigrid solver of the steady point/elliptical-contact EHL problem (Venner & Lubrecht 2000, ch. 8).

Full Approximation Scheme on the grids n_k = 16 2^(k-1) + 1 nodes per direction
(:mod:`camcontact.ehl.point_problem`) for the discrete problem of :mod:`._point_kernels`:

* **relaxation** — line relaxation along X (:func:`._point_kernels.point_line_relax`, Venner &
  Lubrecht §8.4): the nodes of each row Y_j change together by the solution of a banded system
  (half-bandwidth ``band``) with the exact local linearisation, so that the strong coupling along
  the flow through the wedge and the deformation is implicit; Gauss–Seidel where the Poiseuille
  coefficient dominates the wedge's own response (differential character), Jacobi-distributive
  with the five-point pattern (+1 at the node, -1/4 at its neighbours) elsewhere (integral
  character), cavitation by projection (P <- max(P, 0)); the films are recomputed by FFT
  convolution (DC-FFT) before every sweep. The point-wise sweep
  (:func:`._point_kernels.point_relax`, ``relaxation="point"``) remains for the last two, most
  conservative attempts of :data:`ROBUST`. A Gauss–Seidel change is limited to a factor
  exp(``step_limit``) of epsilon (a trust region on the exponential viscosity). Measured (W-cycles,
  257^2): M = 10..100, L = 5..10, D = 0.25..4 in 2-6 cycles; L = 25 (M = 20) in 20 cycles of the
  second attempt (the first stagnates); M = 1000, L = 10 in 5-9 cycles (the point-wise sweep:
  45-70, residual factor about 0.9 per cycle); M = 3000 (Barus, incompressible) in 11 (257^2) and
  14 (513^2) cycles of the first attempt; Barus, incompressible, M = 20, 100, 1000 at L = 10 on
  513^2 in the first attempt (before the step limit M = 20 needed the second);
* **cavitation boundary** — when H_min alternates from cycle to cycle while the boundary hops
  between nodes, the dry set of the finest grid (and its injections) is frozen, as in the line
  solver; an attempt whose residual has not halved in ``STAGNATION[1]`` cycles stops;
* **coarse-grid correction** — residuals restricted by 9-point full weighting, the solution by
  injection, the coarse problem carrying the FAS right-hand sides of the Reynolds equation and
  of the load balance; bilinear interpolation of the corrections. At the cavitation boundary
  the rules of the line solver (:mod:`.line_multigrid`) apply: no residual from nodes next to
  a dry node, corrections only where a node and its four neighbours are pressurised. The
  attempt with ``spike_mask`` (second of :data:`ROBUST`) also keeps the coarse grids out of the
  outlet spike (:func:`._point_kernels.spike_zone`): the steel ball at M 61, L 29 (R 15 mm, 400 N,
  20 m/s, Roelands) diverged on 513^2 in every other attempt, the coarse problems blowing up at the
  spike; with the mask it converges in 73 cycles (43 on 257^2), H_c 3 % above Hamrock–Dowson. It
  converges slowly (the residual falls by about 0.6 per 10 cycles, near the stagnation rule) and a
  mask reaching one node further downstream stagnated: a last resort, not a default;
* **coarsest grid** — ``coarsest_sweeps`` relaxation sweeps, each followed by the load update
  H0 <- H0 + c (h_x h_y sum P - 2 pi/3 - f_load) (the only place H0 changes);
* **cycles** — V or W, started by full multigrid from the dry Hertz pressure on
  ``start_level`` (with H0 from the Nijenbanning–Venner–Moes central film), converged there by
  cycles, then interpolated up level by level with ``fmg_cycles`` cycles each;
* **safeguards** — a non-finite state raises :class:`~camcontact.errors.ConvergenceError`
  at once (no NaN is ever returned); an attempt that diverges or does not converge is repeated
  with the conservative settings :data:`ROBUST` (smaller relaxation factors, W-cycles).

Every solve returns a :class:`~camcontact.ehl.line_solution.ConvergenceRecord`; not converged:
:class:`~camcontact.errors.ConvergenceWarning`, or :class:`~camcontact.errors.ConvergenceError`
with ``strict=True``.
"""

from __future__ import annotations

import math
import time

import attrs
import numpy as np
import scipy.fft

from ..errors import ConvergenceError, InputError
from . import _point_kernels
from .attempts import run_ladder
from .cycle_monitor import CycleMonitor, MonitorRules
from .film_formulas import nijenbanning_film
from .line_solution import ConvergenceRecord
from .point_problem import PointEHLProblem, point_grid_points
from .point_solution import PointEHLSolution

__all__ = ["PointMultigridSettings", "ROBUST", "point_deformation_fft", "solve_point_multigrid"]

LOAD = 2.0 * math.pi / 3.0  #: the load integral of P over the plane
TWO_OVER_PI2 = 2.0 / math.pi**2


@attrs.frozen
class PointMultigridSettings:
    """Numerical settings of :func:`solve_point_multigrid`."""

    cycle: str = attrs.field(default="W", validator=attrs.validators.in_(("V", "W")))
    #: "line": line relaxation along X (banded line systems); "point": the point-wise sweep
    relaxation: str = attrs.field(default="line", validator=attrs.validators.in_(("line", "point")))
    #: half-bandwidth of the line systems (coupling along X kept implicit), 2..4 (1 diverges: the
    #: distributive patterns of the neighbours reach two columns)
    band: int = attrs.field(default=2, validator=attrs.validators.in_((2, 3, 4)))
    pre_sweeps: int = 1
    post_sweeps: int = 1
    coarsest_sweeps: int = 10
    omega_gs: float = 1.0
    omega_jacobi: float = 0.6
    #: Gauss–Seidel where sum(eps faces)/h^2 >= switch x the wedge's own response
    switch: float = 1.0
    #: largest change of ln(epsilon) (viscosity and density) per node and line sweep at a
    #: Gauss–Seidel node (:func:`._point_kernels.point_line_relax`); inf: no limit
    step_limit: float = attrs.field(default=2.0, validator=attrs.validators.gt(0.0))
    h0_relaxation: float = 0.05
    #: > 0: nodes around a fall of ln(eta) by more than this between neighbours along X (the outlet spike,
    #: :func:`._point_kernels.spike_zone`) pass no residual to the coarse grid and take no coarse correction;
    #: the fine sweeps alone converge them (an attempt of :data:`ROBUST`; 0: off)
    spike_mask: float = attrs.field(default=0.0, validator=attrs.validators.ge(0.0))
    max_cycles: int = 80
    #: FMG starts here (level 2: 33 x 33) from the dry Hertz pressure
    start_level: int = 2
    start_cycles: int = 30
    fmg_cycles: int = 1
    #: the coarsest level of the cycles (1: 17 x 17)
    cycle_coarsest: int = 1
    correct_pressurised_only: bool = True
    freeze_free_boundary: bool = True
    workers: int = 2  #: FFT threads (scipy.fft)


#: conservative settings of the further attempts after a failed one
ROBUST = ({"omega_gs": 0.6, "omega_jacobi": 0.4, "pre_sweeps": 2},
          {"spike_mask": 2.0},
          {"relaxation": "point", "omega_gs": 0.6, "omega_jacobi": 0.4, "pre_sweeps": 2},
          {"relaxation": "point", "omega_gs": 0.4, "omega_jacobi": 0.15, "switch": 4.0, "h0_relaxation": 0.01,
           "pre_sweeps": 3, "post_sweeps": 2})


def _kernel_table(nx: int, ny: int, hx: float, hy: float) -> np.ndarray:
    """(2/pi^2) x the rectangle kernel at offsets (dj hy, di hx), dj < ny, di < nx (vectorised Love formula)."""
    x = np.arange(nx)[None, :] * hx
    y = np.arange(ny)[:, None] * hy
    a, b = 0.5 * hx, 0.5 * hy

    def love(u, v):
        return u * np.arcsinh(v / np.abs(u)) + v * np.arcsinh(u / np.abs(v))

    return TWO_OVER_PI2 * (love(x + a, y + b) - love(x - a, y + b) - love(x + a, y - b) + love(x - a, y - b))


class _FFTDeformation:
    """w = (2/pi^2) K * P on an ny x nx grid by zero-padded FFT convolution (exact linear convolution).

    The circular convolution of length N reproduces the linear one at the grid's nodes when the
    offsets -(n-1)..(n-1) map onto distinct slots, N >= 2n - 1. With ``zero_rim`` (the solver's
    pressures vanish on the boundary) the two largest offsets, +-(n-1), join only boundary nodes
    and share a slot without effect, so N >= 2n - 3 suffices: 1024 (a power of two) at n = 513
    instead of 1080, about 20 % less time per transform. Grids under :data:`THREADED_NODES` nodes
    per direction transform on one thread: below that the threads' start-up costs more (measured
    0.7 ms against 0.06 ms per deformation at 17^2) than they save.
    """

    def __init__(self, nx: int, ny: int, hx: float, hy: float, workers: int, zero_rim: bool = False):
        table = _kernel_table(nx, ny, hx, hy)
        least = (2 * ny - 3, 2 * nx - 3) if zero_rim and min(nx, ny) >= 3 else (2 * ny - 1, 2 * nx - 1)
        self.shape = tuple(scipy.fft.next_fast_len(size, real=True) for size in least)
        full = np.zeros(self.shape)
        full[:ny, :nx] = table
        full[self.shape[0] - ny + 1:, :nx] = table[1:][::-1]
        full[:, self.shape[1] - nx + 1:] = full[:, 1:nx][:, ::-1]
        self.spectrum = scipy.fft.rfft2(full, workers=1)
        self.nx, self.ny, self.zero_rim = nx, ny, zero_rim
        self.workers = workers if min(nx, ny) >= THREADED_NODES else 1
        self.local = table[:4, :8].copy()  # dH/dP between nodes (|dj|, |di|) apart, for the relaxation

    def __call__(self, P: np.ndarray) -> np.ndarray:
        if self.zero_rim and (P[0].any() or P[-1].any() or P[:, 0].any() or P[:, -1].any()):
            raise ValueError("_FFTDeformation(zero_rim=True) needs zero pressures on the grid's boundary")
        spectrum = scipy.fft.rfft2(P, s=self.shape, workers=self.workers)
        spectrum *= self.spectrum
        return scipy.fft.irfft2(spectrum, s=self.shape, workers=self.workers)[:self.ny, :self.nx]


#: grids with fewer nodes per direction transform on one thread (:class:`_FFTDeformation`)
THREADED_NODES = 257


def point_deformation_fft(P: np.ndarray, hx: float, hy: float) -> np.ndarray:
    """Deformation (2/pi^2) sum K P of pressures P[j, i] by DC-FFT (the solver's method; the shorter
    padding of :class:`_FFTDeformation` when P vanishes on the boundary)."""
    P = np.asarray(P, dtype=float)
    ny, nx = P.shape
    zero_rim = not (P[0].any() or P[-1].any() or P[:, 0].any() or P[:, -1].any())
    return _FFTDeformation(nx, ny, hx, hy, 1, zero_rim=zero_rim)(P)


class _Level:
    def __init__(self, problem: PointEHLProblem, level: int, workers: int):
        self.k = level
        self.X, self.Y = problem.grid(level)
        self.n = self.X.size
        self.hx = float(self.X[1] - self.X[0])
        self.hy = float(self.Y[1] - self.Y[0])
        self.geometry = 0.5 * self.X[None, :] ** 2 + 0.5 * problem.D * self.Y[:, None] ** 2
        self.deform = (_FFTDeformation(self.n, self.n, self.hx, self.hy, workers, zero_rim=True)
                       if problem.elastic else None)
        self.Kd = self.deform.local if problem.elastic else np.zeros((4, 8))
        self.dry = np.zeros((self.n, self.n), dtype=np.bool_)  # nodes held at P = 0 (frozen cavitation)


class _Solver:
    def __init__(self, problem: PointEHLProblem, levels: int, settings: PointMultigridSettings, compiled: bool):
        self.problem, self.settings = problem, settings
        kernel = _point_kernels.compiled if compiled else _point_kernels.PY.__getitem__
        self._relax = kernel("point_line_relax" if settings.relaxation == "line" else "point_relax")
        self._residual = kernel("point_residual")
        self._restrict = kernel("restrict_full_weighting")
        self._prolong = kernel("prolong_bilinear")
        self._spike_zone = kernel("spike_zone")
        self.levels = [_Level(problem, k, settings.workers) for k in range(1, levels + 1)]
        self.codes = problem.law_codes
        self.params = problem.law_parameters
        self.lam = problem.lam
        self.work = 0.0
        self.coarsest = min(max(settings.cycle_coarsest, 1), levels) - 1

    # ------------------------------------------------------------------ operator pieces
    def film(self, k: int, P: np.ndarray, H0: float) -> np.ndarray:
        level = self.levels[k]
        if level.deform is None:
            return H0 + level.geometry
        return H0 + level.geometry + level.deform(P)

    def operator(self, k: int, P: np.ndarray, H: np.ndarray) -> np.ndarray:
        level = self.levels[k]
        out = np.empty_like(P)
        self._residual(P, H, level.hx, level.hy, self.lam, self.codes[0], self.codes[1], self.params, out)
        return out

    def load(self, k: int, P: np.ndarray) -> float:
        level = self.levels[k]
        return float(level.hx * level.hy * P.sum() - LOAD)

    def relax(self, k: int, P: np.ndarray, H0: float, f: np.ndarray, sweeps: int) -> None:
        level, s = self.levels[k], self.settings
        extra = (s.band, s.step_limit) if s.relaxation == "line" else ()
        for _ in range(sweeps):
            H = self.film(k, P, H0)
            self._relax(P, H, f, level.hx, level.hy, self.lam, self.codes[0], self.codes[1], self.params, level.Kd,
                        s.omega_gs, s.omega_jacobi, s.switch, level.dry, *extra)
            self.work += (level.n / self.levels[-1].n) ** 2

    def complementarity(self, k: int, P: np.ndarray, H0: float, f: np.ndarray) -> np.ndarray:
        """f - L(P) where P > 0; at dry nodes only the part that would take pressure (f - L < 0)."""
        r = f - self.operator(k, P, self.film(k, P, H0))
        return np.where(P > 0.0, r, np.minimum(r, 0.0))

    def freeze_dry(self, P: np.ndarray) -> None:
        """Hold the currently cavitated nodes of the finest grid (and their injections) at P = 0."""
        dry = P <= 0.0
        for level in reversed(self.levels):
            level.dry = np.ascontiguousarray(dry)
            dry = dry[::2, ::2]

    # ------------------------------------------------------------------ cycles
    def cycle(self, k: int, P: np.ndarray, H0: float, f: np.ndarray, f_load: float, kind: str) -> float:
        """One FAS ``kind`` cycle on level index k, in place on P; returns the new H0."""
        s = self.settings
        if k <= self.coarsest:
            for _ in range(s.coarsest_sweeps):
                self.relax(k, P, H0, f, 1)
                H0 += s.h0_relaxation * (self.load(k, P) - f_load)
            return H0
        self.relax(k, P, H0, f, s.pre_sweeps)
        H = self.film(k, P, H0)
        r = f - self.operator(k, P, H)
        wet = P > 0.0
        r[~wet] = 0.0
        if s.freeze_free_boundary:
            beside_dry = np.zeros_like(wet)
            beside_dry[1:-1, 1:-1] = ~(wet[:-2, 1:-1] & wet[2:, 1:-1] & wet[1:-1, :-2] & wet[1:-1, 2:])
            r[beside_dry & wet] = 0.0
        spike = None
        if s.spike_mask > 0.0:
            spike = np.empty(P.shape, dtype=np.bool_)
            self._spike_zone(P, self.codes[0], self.params, s.spike_mask, spike)
            r[spike] = 0.0
        r_load = f_load - self.load(k, P)
        Pc = np.ascontiguousarray(P[::2, ::2])
        Pc_old = Pc.copy()
        fc = np.empty_like(Pc)
        self._restrict(r, fc)
        fc += self.operator(k - 1, Pc, self.film(k - 1, Pc, H0))
        fc_load = self.load(k - 1, Pc) + r_load
        H0c = H0
        for _ in range(2 if kind == "W" and k - 1 > self.coarsest else 1):
            H0c = self.cycle(k - 1, Pc, H0c, fc, fc_load, kind)
        correction = np.empty_like(P)
        self._prolong(Pc - Pc_old, correction)
        if s.correct_pressurised_only:
            keep = np.zeros_like(wet)
            keep[1:-1, 1:-1] = wet[1:-1, 1:-1] & wet[:-2, 1:-1] & wet[2:, 1:-1] & wet[1:-1, :-2] & wet[1:-1, 2:]
            correction[~keep] = 0.0
        if spike is not None:
            correction[spike] = 0.0
        np.maximum(P + correction, 0.0, out=P)
        H0 = H0c
        self.relax(k, P, H0, f, s.post_sweeps)
        return H0


def solve_point_multigrid(
    problem: PointEHLProblem,
    levels: int = 5,
    *,
    tolerance: float | None = 1e-5,
    settings: PointMultigridSettings | None = None,
    strict: bool = False,
    compiled: bool = True,
) -> PointEHLSolution:
    """Solve the point-contact problem on ``levels`` grid levels by FAS multigrid.

    Parameters
    ----------
    problem : PointEHLProblem
    levels : int
        Finest level: 16 2^(levels-1) + 1 nodes per direction (4: 129^2, 5: 257^2, 6: 513^2).
    tolerance : float, optional
        Stop when the changes of H_min, H_c and H0 between cycles fall below ``tolerance`` times
        max(H_c, 0.01) (relative) and the load error below ``tolerance`` (None: run
        ``settings.max_cycles`` cycles).
    settings : PointMultigridSettings, optional
    strict : bool
        Raise :class:`ConvergenceError` instead of warning when not converged.
    compiled : bool
        Use the numba kernels (False: the plain-Python twins; very slow, tiny grids only).

    If an attempt diverges or does not converge, further attempts run with the conservative
    settings :data:`ROBUST`; the record says which ran.
    """
    if not (isinstance(levels, (int, np.integer)) and 1 <= levels <= 8):
        raise InputError(f"solve_point_multigrid: levels = {levels!r}; allowed 1..8")
    if not isinstance(problem, PointEHLProblem):
        raise InputError(f"solve_point_multigrid: problem must be a PointEHLProblem, got {type(problem).__name__}")
    if tolerance is not None and not (math.isfinite(tolerance) and tolerance > 0):
        raise InputError(f"solve_point_multigrid: tolerance = {tolerance!r} must be > 0 (or None)")
    settings = settings or PointMultigridSettings()
    n = point_grid_points(int(levels))
    return run_ladder(settings, ROBUST, lambda attempt: _solve_once(problem, int(levels), tolerance, attempt, compiled),
                      f"point EHL multigrid (M = {problem.M:.4g}, L = {problem.L:.4g}, D = {problem.D:.3g})",
                      strict=strict, size=f"{n}x{n}")


def _start_H0(problem: PointEHLProblem, solver: _Solver, k: int, P: np.ndarray) -> float:
    """H0 that puts the film at the centre of the dry Hertz pressure at the NVM central film."""
    level = solver.levels[k]
    estimate = nijenbanning_film(problem.M, problem.L, problem.D) / problem.moes_factor
    centre = (level.n // 2, int(np.argmin(np.abs(level.X))))
    deformation = level.deform(P)[centre] if level.deform is not None else 0.0
    return float(estimate - deformation - level.geometry[centre])


#: stop an attempt after this many cycles when the last window of them did not halve the residual
#: (the point-wise fallback converges at about 0.9 per cycle, hence the long window)
STAGNATION = (20, 10)

#: the stop rules of the cycles (:class:`~camcontact.ehl.cycle_monitor.CycleMonitor`): converged when
#: the changes of (H_min, H_c, H0) fall below the tolerance times max(|H_c|, 0.01) and the load error
#: below the tolerance; :data:`STAGNATION`; the dry set frozen when H_min alternates while the number
#: of wet nodes changes, also with tolerance None
MONITOR_RULES = MonitorRules(stagnation=STAGNATION, load_factor=1.0, load_floor=0.0, relative_to=1, scale_floor=0.01,
                             boundary="wet_count", freeze_needs_tolerance=False)

#: a pressure this many times p_h means the iteration has blown up (hard cases peak at about 10)
BLOW_UP = 1e4


def _finite(P: np.ndarray, H0: float) -> bool:
    return bool(np.all(np.isfinite(P)) and math.isfinite(H0) and P.max() <= BLOW_UP)


def _divergence(P: np.ndarray, watched: tuple, residuals: list[float], loads: list[float]) -> str:
    """Why the cycle just recorded has diverged (non-finite film or residual, blow-up, residual grown
    1e3-fold from its best), or "" when it has not."""
    if not (np.all(np.isfinite(watched)) and math.isfinite(residuals[-1]) and math.isfinite(loads[-1])):
        return "diverged: non-finite residual or film"
    if P.max() > BLOW_UP:
        return f"diverged: maximum pressure {P.max():.3g} p_h"
    if len(residuals) > 3 and residuals[-1] > 1e3 * min(residuals):
        return f"diverged: residual grew from {min(residuals):.3g} to {residuals[-1]:.3g}"
    return ""


def _solve_once(problem: PointEHLProblem, levels: int, tolerance: float | None,
                settings: PointMultigridSettings, compiled: bool) -> PointEHLSolution:
    start = time.perf_counter()
    solver = _Solver(problem, levels, settings, compiled)
    top = levels - 1
    first = min(max(settings.start_level, 1), levels) - 1
    level = solver.levels[first]
    P = problem.hertz_pressure(level.X, level.Y)
    P[0, :] = P[-1, :] = P[:, 0] = P[:, -1] = 0.0
    H0 = _start_H0(problem, solver, first, P)
    watch = CycleMonitor(MONITOR_RULES, tolerance, solver.freeze_dry)

    def fail(text: str) -> ConvergenceError:
        return ConvergenceError(
            f"point EHL multigrid (M = {problem.M:.4g}, L = {problem.L:.4g}, D = {problem.D:.3g}): {text}",
            _record(solver, watch, start, False, text, tolerance))

    # full multigrid: converge the start level, then up one level at a time
    zero = np.zeros_like(P)
    previous = None
    for _ in range(settings.start_cycles):
        H0 = solver.cycle(first, P, H0, zero, 0.0, settings.cycle)
        if not _finite(P, H0):
            raise fail(f"non-finite or blown-up state on the start level {first + 1}")
        H = solver.film(first, P, H0)
        current = np.array([H.min(), H0])
        if previous is not None and np.max(np.abs(current - previous)) < 1e-6 and abs(solver.load(first, P)) < 1e-6:
            break
        previous = current
    for k in range(first + 1, levels):
        fine = np.empty((solver.levels[k].n, solver.levels[k].n))
        solver._prolong(P, fine)
        P = fine
        zero = np.zeros_like(P)
        for _ in range(settings.fmg_cycles):
            H0 = solver.cycle(k, P, H0, zero, 0.0, settings.cycle)
        if not _finite(P, H0):
            raise fail(f"non-finite or blown-up state after the FMG step to level {k + 1}")
    finest = solver.levels[top]
    zero = np.zeros_like(P)
    for _ in range(settings.max_cycles):
        H0 = solver.cycle(top, P, H0, zero, 0.0, settings.cycle)
        if not _finite(P, H0):
            raise fail("diverged: non-finite state")
        H = solver.film(top, P, H0)
        r = solver.complementarity(top, P, H0, zero)
        watch.record(float(np.mean(np.abs(r[1:-1, 1:-1])) * finest.hx), solver.load(top, P), solver.work)
        watched = (H.min(), _centre(finest, H), H0)
        trouble = _divergence(P, watched, watch.residuals, watch.loads)
        if trouble:
            raise fail(trouble)
        if watch.decide(P, watched):
            break
    else:
        watch.out_of_cycles(settings.max_cycles)
    if H.min() <= 0.0:
        watch.converged = False
        watch.note(f"film closed: H_min = {H.min():.3g} <= 0 (the grid is too coarse for this load: "
                   f"M = {problem.M:.4g}; finer levels, or a film formula)")
    record = _record(solver, watch, start, watch.converged, watch.message, tolerance)
    return PointEHLSolution(problem=problem, level=levels, X=finest.X, Y=finest.Y, P=P, H=H, H0=float(H0),
                            record=record, settings=settings)


def _centre(level: _Level, H: np.ndarray) -> float:
    """H at the Hertz centre (0, 0), bilinear."""
    i = int(np.clip(np.searchsorted(level.X, 0.0) - 1, 0, level.n - 2))
    j = int(np.clip(np.searchsorted(level.Y, 0.0) - 1, 0, level.n - 2))
    s = (0.0 - level.X[i]) / level.hx
    t = (0.0 - level.Y[j]) / level.hy
    return float((1 - s) * (1 - t) * H[j, i] + s * (1 - t) * H[j, i + 1] + (1 - s) * t * H[j + 1, i]
                 + s * t * H[j + 1, i + 1])


def _record(solver, watch, start, converged, message, tolerance) -> ConvergenceRecord:
    s = solver.settings
    return ConvergenceRecord(
        method=f"point FAS multigrid, {s.cycle}-cycles, FFT deformation", levels=len(solver.levels),
        nodes=solver.levels[-1].n ** 2, residuals=tuple(watch.residuals), load_errors=tuple(watch.loads),
        work_units=tuple(watch.works), wall_time=time.perf_counter() - start, converged=converged, message=message,
        tolerance=float("nan") if tolerance is None else tolerance)


