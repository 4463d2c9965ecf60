"""FAS multigrid solver of the steady line-contact EHL problem (Venner & Lubrecht 2000).

Full Approximation Scheme on the grid hierarchy n_k = 14 2^(k-1) + 1 (Tsuha 2015 §5.1) for
the discrete problem of :mod:`camcontact.ehl.line_operator`:

* **relaxation** — the point-wise hybrid sweep :func:`camcontact.ehl._kernels.relax_hybrid`:
  Gauss–Seidel where the Poiseuille coefficient exceeds ``switch`` times the wedge's own
  response (differential character), Jacobi-distributive with dipole changes elsewhere
  (integral character), the regime fixed per node at the start of the sweep; the divisors are
  the exact local derivatives of the discrete operator, including how xi and the density vary
  with P (needed at the Petrusevich spike, where the viscosity changes by orders of magnitude
  between neighbours); under-relaxation, cavitation by clipping; the film recomputed after
  every sweep by MLMI (or FFT/direct);
* **coarse-grid correction** — residuals restricted by full weighting, the solution by
  injection, the coarse problem carrying the FAS right-hand sides of the Reynolds equation and
  of the load balance; linear interpolation of the corrections. At the cavitation boundary
  nothing is transferred: no residual from nodes next to a dry node, no correction except
  where a node and both its neighbours are pressurised (free-boundary nodes are left to the
  smoother; otherwise the boundary hops between two nodes from cycle to cycle). Coarse nodes
  injected from cavitated fine nodes (away from the boundary) keep the coarse grid's own
  right-hand side instead of the FAS one: with the FAS one they sit exactly on the
  complementarity edge, the coarse grids fill the outlet with small pressures and every cycle
  disturbs a converged solution (level 12: 6 instead of 2 cycles);
* **coarsest grid** — its FAS problem (pressures and H0 together) solved exactly by the
  semi-smooth Newton method of :mod:`.line_reference`, so the load balance is met there;
* **cycles** — V, F (default: W-like coarse treatment at O(n) cost in 1-D) or W; started by
  full multigrid from an exact Newton solution on a start level (level 3, raised until the
  discrete solution has positive films; parameter continuation when Newton needs it);
* **safeguards** — if the cycles start alternating between two states while the free
  boundary moves (it hops between nodes), the cavitated set is frozen and the complementarity
  checked afterwards; if an attempt diverges or stagnates, a second one runs with
  conservative settings. Where a coarse grid is too coarse for a very thin film its discrete
  film can close (H <= 0); xi is then 0 (a closed gap passes no pressure flow), not negative,
  which keeps heavy-load, low-L cases (M = 1000, L = 2) convergent.

Every solve returns a :class:`~camcontact.ehl.line_solution.ConvergenceRecord` (residual and
load error per cycle, work units, wall time, converged flag, notes). Not converged: a
:class:`~camcontact.errors.ConvergenceWarning`, or :class:`~camcontact.errors.ConvergenceError`
with ``strict=True``; a non-finite state always raises, so no NaN is ever returned.
"""

from __future__ import annotations

import math
import time
import warnings

import attrs
import numpy as np

from ..errors import ConvergenceError, ConvergenceWarning, InputError
from . import _kernels
from .deformation import Deformation
from .line_operator import LineGrid
from .line_problem import LineEHLProblem, grid_points, kernel_coefficients
from .line_reference import newton_complementarity
from .line_solution import ConvergenceRecord, LineEHLSolution

__all__ = ["MultigridSettings", "solve_multigrid"]


@attrs.frozen
class MultigridSettings:
    """Numerical settings of :func:`solve_multigrid` (defaults tested across the Moes map)."""

    cycle: str = attrs.field(default="F", validator=attrs.validators.in_(("V", "F", "W")))
    pre_sweeps: int = 2
    post_sweeps: int = 1
    coarsest_sweeps: int = 20
    omega_gs: float = 0.7
    omega_jacobi: float = 0.3
    switch: float = 4.0  #: Gauss–Seidel where the Poiseuille coefficient >= switch x wedge response
    window: int = 0  #: films updated around a Gauss–Seidel change (0: only at the node; measured fastest and as robust)
    h0_relaxation: float = 0.05  #: H0 <- H0 + c (h sum P - pi/2 - f_g) on the coarsest grid
    fmg_cycles: int = 1
    max_cycles: int = 40
    deformation: str = "mlmi"
    #: FMG starts here with the dense Newton solver: the 15-node coarsest grid's own discrete
    #: solution can be unphysical (negative films), though it serves well as an FAS coarse grid
    start_level: int = 3
    #: the coarsest level the cycles descend to (1 = the 15-node grid)
    cycle_coarsest: int = 1
    #: apply coarse-grid corrections only where a node and both neighbours are pressurised
    correct_pressurised_only: bool = True
    #: no residual restriction at nodes next to a cavitated node
    freeze_free_boundary: bool = True
    #: coarse nodes injected from cavitated fine nodes keep their own (unmodified) right-hand side,
    #: so they stay cavitated with a margin instead of sitting exactly on the complementarity edge
    dry_keeps_own_equation: bool = True


class _Level:
    def __init__(self, problem: LineEHLProblem, level: int, deformation: str, compiled: bool):
        self.k = level
        self.n = grid_points(level)
        self.X = np.linspace(problem.domain[0], problem.domain[1], self.n)
        self.h = float(self.X[1] - self.X[0])
        self.parabola = 0.5 * self.X**2
        self.deform = Deformation(self.n, self.h, deformation if self.n > 64 else "direct", compiled=compiled)
        self.K = np.array([_kernels.kernel_value(float(d), self.h) for d in range(16)])


class _Solver:
    def __init__(self, problem: LineEHLProblem, levels: int, settings: MultigridSettings, compiled: bool):
        self.problem = problem
        self.settings = settings
        self.kernel = _kernels.compiled if compiled else _kernels.PY.__getitem__
        self.levels = [_Level(problem, k, settings.deformation, compiled) for k in range(1, levels + 1)]
        self.viscosity_code, self.density_code = problem.law_codes
        self.params = problem.law_parameters
        self.lam = problem.lam
        self.work = 0.0
        self._coarse_grids: dict = {}
        self._coarse_kernels: dict = {}
        #: frozen cavitation sets per level number (set when the cycles start to alternate)
        self.dry: dict[int, np.ndarray] = {}

    # ------------------------------------------------------------------ operator pieces
    def film(self, level: _Level, P: np.ndarray, H0: float) -> np.ndarray:
        if not self.problem.elastic:
            return H0 + level.parabola
        return H0 + level.parabola - level.deform(P) / math.pi

    def residual(self, level: _Level, P: np.ndarray, H: np.ndarray) -> np.ndarray:
        out = np.empty(level.n)
        self.kernel("reynolds_residual")(P, H, level.h, self.lam, self.viscosity_code, self.density_code,
                                         self.params, out)
        return out

    def load(self, level: _Level, P: np.ndarray) -> float:
        return float(level.h * (P.sum() - 0.5 * (P[0] + P[-1])) - 0.5 * math.pi)

    def relax(self, level: _Level, P: np.ndarray, H0: float, f: np.ndarray, first: int = 1,
              last: int | None = None) -> np.ndarray:
        H = self.film(level, P, H0)
        s = self.settings
        K = level.K if self.problem.elastic else np.zeros_like(level.K)
        last = level.n - 2 if last is None else last
        dry = self.dry.get(level.k)
        if dry is None:
            dry = np.zeros(level.n, dtype=np.bool_)
        self.kernel("relax_hybrid")(P, H, f, level.h, self.lam, self.viscosity_code, self.density_code,
                                    self.params, K, s.omega_gs, s.omega_jacobi, s.switch, s.window,
                                    first, last, dry)
        self.work += (last - first + 1) / self.levels[-1].n
        return P

    def freeze_dry(self, P: np.ndarray) -> None:
        """Hold the currently cavitated nodes of the finest grid (and their injections) at P = 0."""
        dry = P <= 0.0
        for level in reversed(self.levels):
            self.dry[level.k] = dry.copy()
            dry = dry[::2]

    # ------------------------------------------------------------------ transfers
    @staticmethod
    def restrict_full_weighting(r: np.ndarray) -> np.ndarray:
        coarse = np.zeros((r.size + 1) // 2)
        coarse[1:-1] = 0.25 * r[1:-2:2] + 0.5 * r[2:-1:2] + 0.25 * r[3::2]
        return coarse

    @staticmethod
    def prolong_linear(c: np.ndarray) -> np.ndarray:
        fine = np.empty(2 * c.size - 1)
        fine[0::2] = c
        fine[1::2] = 0.5 * (c[:-1] + c[1:])
        return fine

    @staticmethod
    def prolong_cubic(c: np.ndarray) -> np.ndarray:
        fine = _Solver.prolong_linear(c)
        if c.size >= 4:
            fine[3:-3:2] = (-c[:-3] + 9.0 * c[1:-2] + 9.0 * c[2:-1] - c[3:]) / 16.0
        return fine

    # ------------------------------------------------------------------ cycles
    def coarse_solve(self, k: int, P: np.ndarray, H0: float, f: np.ndarray, f_load: float) -> tuple[np.ndarray, float]:
        """Solve the coarsest FAS problem (pressure and H0 together) exactly by Newton."""
        level = self.levels[k]
        grid = self._coarse_grids.get(k)
        if grid is None:
            grid = self._coarse_grids[k] = LineGrid(self.problem, level.n, "direct")
        if k not in self._coarse_kernels and self.problem.elastic:
            table = kernel_coefficients(grid.h, grid.n)
            self._coarse_kernels[k] = table[np.abs(np.arange(grid.n)[:, None] - np.arange(grid.n)[None, :])] / math.pi
        P_new, H0_new, residuals, _, converged, _ = newton_complementarity(
            grid, P, H0, f=f, f_load=f_load, K_over_pi=self._coarse_kernels.get(k), tolerance=1e-11,
            max_iterations=60,
        )
        self.work += len(residuals) * level.n / self.levels[-1].n
        if not converged:  # fall back to relaxation sweeps with H0 updates
            for _ in range(self.settings.coarsest_sweeps):
                P = self.relax(level, P, H0, f)
                H0 += self.settings.h0_relaxation * (self.load(level, P) - f_load)
            return P, H0
        return P_new, H0_new

    def cycle(self, k: int, P: np.ndarray, H0: float, f: np.ndarray, f_load: float,
              kind: str | None = None) -> tuple[np.ndarray, float]:
        """One FAS cycle on level index k: ``kind`` V (one coarse visit), W (two) or F (an F then a V)."""
        kind = kind or self.settings.cycle
        if k <= self.settings.cycle_coarsest - 1:
            return self.coarse_solve(k, P, H0, f, f_load)
        s = self.settings
        fine, coarse = self.levels[k], self.levels[k - 1]
        for _ in range(s.pre_sweeps):
            P = self.relax(fine, P, H0, f)
        H = self.film(fine, P, H0)
        r = f - self.residual(fine, P, H)
        r[P <= 0.0] = 0.0
        if s.freeze_free_boundary:  # no residual transfer at nodes beside the cavitation boundary
            dry = P <= 0.0
            r[1:][dry[:-1]] = 0.0
            r[:-1][dry[1:]] = 0.0
        r_load = f_load - self.load(fine, P)
        Pc = P[::2].copy()
        Pc_old = Pc.copy()
        Hc = self.film(coarse, Pc, H0)
        fc = self.residual(coarse, Pc, Hc) + self.restrict_full_weighting(r)
        if s.dry_keeps_own_equation:  # cavitated coarse nodes keep the unmodified equation
            dry_c = Pc <= 0.0
            deep = dry_c.copy()  # dry with both neighbours dry: away from the free boundary
            deep[1:] &= dry_c[:-1]
            deep[:-1] &= dry_c[1:]
            fc[deep] = f[::2][deep]
        fc_load = self.load(coarse, Pc) + r_load
        H0c = H0
        visits = {"V": ("V",), "W": ("W", "W"), "F": ("F", "V")}[kind]
        if k - 1 <= s.cycle_coarsest - 1:
            visits = visits[:1]
        for visit in visits:
            Pc, H0c = self.cycle(k - 1, Pc, H0c, fc, fc_load, visit)
        correction = self.prolong_linear(Pc - Pc_old)
        if s.correct_pressurised_only:  # interior of the pressurised region: the node and both neighbours wet
            wet = P > 0.0
            interior = wet.copy()
            interior[1:] &= wet[:-1]
            interior[:-1] &= wet[1:]
            correction = np.where(interior, correction, 0.0)
        P = np.maximum(P + correction, 0.0)
        P[0] = P[-1] = 0.0
        H0 = H0 + (H0c - H0)
        for _ in range(s.post_sweeps):
            P = self.relax(fine, P, H0, f)
        return P, H0


#: the conservative settings of the second attempt after a divergence or stagnation
ROBUST = {"cycle": "W", "omega_gs": 0.5, "omega_jacobi": 0.2, "switch": 8.0}


def solve_multigrid(
    problem: LineEHLProblem,
    levels: int = 9,
    *,
    tolerance: float | None = 1e-7,
    settings: MultigridSettings | None = None,
    initial: LineEHLSolution | None = None,
    strict: bool = False,
    compiled: bool = True,
) -> LineEHLSolution:
    """Solve the line-contact problem on ``levels`` grid levels by FAS multigrid.

    If the first attempt diverges or does not converge, a second one runs with the conservative
    settings :data:`ROBUST` (W-cycles, smaller relaxation factors); the record says so.

    Parameters
    ----------
    problem : LineEHLProblem
    levels : int
        Finest level (n = 14 2^(levels-1) + 1 nodes; 9 gives 3585, 12 gives 28673).
    tolerance : float, optional
        Stop when the change of H_min and H0 between cycles falls below it and the load error
        below ten times it (None: run ``settings.max_cycles`` cycles).
    settings : MultigridSettings, optional
    initial : LineEHLSolution, optional
        Warm start (interpolated onto the finest grid; FMG is then skipped).
    strict : bool
        Raise :class:`ConvergenceError` instead of warning when not converged.
    compiled : bool
        Use the numba kernels (False: the plain-Python twins, slow; for tests).
    """
    if not (isinstance(levels, (int, np.integer)) and 1 <= levels <= 16):
        raise InputError(f"solve_multigrid: levels = {levels!r}; allowed 1..16")
    settings = settings or MultigridSettings()
    start = time.perf_counter()
    try:
        first = _solve_once(problem, levels, tolerance, settings, initial, compiled)
    except ConvergenceError as exc:
        first, failure = None, exc
    else:
        failure = None
        if first.record.converged:
            return first
    robust = attrs.evolve(settings, **ROBUST)
    try:
        second = _solve_once(problem, levels, tolerance, robust, initial, compiled)
    except ConvergenceError as exc:
        if first is None:
            raise ConvergenceError(f"{failure}; retry with robust settings: {exc}", exc.record) from None
        second = None
    best = second if second is not None and (second.record.converged or first is None) else first
    note = ("first attempt " + (f"failed ({failure})" if first is None else "did not converge")
            + f"; retried with {ROBUST}")
    record = attrs.evolve(best.record, message=f"{best.record.message}; {note}".strip("; "),
                          wall_time=time.perf_counter() - start)
    best = attrs.evolve(best, record=record)
    if not best.record.converged:
        text = f"line EHL multigrid (M = {problem.M:.4g}, L = {problem.L:.4g}, {best.X.size} nodes): {record.message}"
        if strict:
            raise ConvergenceError(text, record)
        warnings.warn(text, ConvergenceWarning, stacklevel=2)
    return best


def _solve_once(problem, levels, tolerance, settings, initial, compiled) -> LineEHLSolution:
    """One multigrid attempt (see :func:`solve_multigrid`); raises ConvergenceError on divergence."""
    if not (isinstance(levels, (int, np.integer)) and 1 <= levels <= 16):
        raise InputError(f"solve_multigrid: levels = {levels!r}; allowed 1..16")
    settings = settings or MultigridSettings()
    start = time.perf_counter()
    solver = _Solver(problem, int(levels), settings, compiled)
    finest = solver.levels[-1]
    if initial is not None:
        P = np.maximum(np.interp(finest.X, initial.X, initial.P), 0.0)
        P[0] = P[-1] = 0.0
        H0 = float(initial.H0)
    else:  # full multigrid start: exact solve on the start level, then up level by level
        first, coarse = _start(problem, min(settings.start_level, len(solver.levels)), len(solver.levels))
        P, H0 = coarse.P.copy(), coarse.H0
        solver.work += coarse.record.cycles * coarse.X.size / finest.n
        for k in range(first, len(solver.levels)):
            P = np.maximum(solver.prolong_cubic(P), 0.0)
            P[0] = P[-1] = 0.0
            zero = np.zeros(solver.levels[k].n)
            for _ in range(settings.fmg_cycles):
                P, H0 = solver.cycle(k, P, H0, zero, 0.0)
    zero = np.zeros(finest.n)
    residuals, loads, works = [], [], []
    changes: list[float] = []
    boundaries: list[int] = []  # last pressurised node after each cycle
    converged = False
    message = ""
    previous = None
    for _ in range(settings.max_cycles):
        P, H0 = solver.cycle(len(solver.levels) - 1, P, H0, zero, 0.0)
        H = solver.film(finest, P, H0)
        if not (np.all(np.isfinite(P)) and np.all(np.isfinite(H)) and math.isfinite(H0)):
            raise ConvergenceError(
                f"line EHL multigrid diverged (M = {problem.M:.4g}, L = {problem.L:.4g}): non-finite state",
                _record(solver, residuals, loads, works, start, False, "non-finite state", tolerance),
            )
        r = solver.residual(finest, P, H)
        r = np.where(P > 0.0, r, np.maximum(r, 0.0))
        residuals.append(float(np.mean(np.abs(r[1:-1])) * finest.h))
        loads.append(solver.load(finest, P))
        works.append(solver.work)
        current = (float(H.min()), H0)
        wet = np.flatnonzero(P > 0.0)
        boundaries.append(int(wet[-1]) if wet.size else -1)
        if tolerance is not None and previous is not None:
            change = max(abs(current[0] - previous[0]), abs(current[1] - previous[1]))
            changes.append(current[0] - previous[0])
            if change < tolerance and abs(loads[-1]) < max(tolerance, 1e-9) * 10:
                converged = True
                break
            if not solver.dry and _alternating(changes) and len(set(boundaries[-3:])) > 1:
                # the cavitation boundary hops between two nodes from cycle to cycle: freeze the
                # dry set of the finest grid (and its restrictions) and let the cycles converge
                solver.freeze_dry(P)
                message = f"cavitation set frozen after cycle {len(residuals)} (boundary oscillation)"
        previous = current
    else:
        if tolerance is None:
            converged = True
            message = f"fixed number of cycles ({settings.max_cycles})"
        else:
            message = (message + "; " if message else "") + f"no convergence to {tolerance:g} in {settings.max_cycles} cycles"
    if solver.dry and converged:
        H_check = solver.film(finest, P, H0)
        wants = (solver.residual(finest, P, H_check) > 0.0) & solver.dry[finest.k]
        message += f"; {int(wants.sum())} frozen dry nodes would take pressure" if wants.any() else "; complementarity holds"
    H = solver.film(finest, P, H0)
    record = _record(solver, residuals, loads, works, start, converged, message, tolerance)
    return LineEHLSolution(problem=problem, level=int(levels), X=finest.X, P=P, H=H, H0=float(H0), record=record)


_MAX_START_LEVEL = 6  # the dense start solver stays below ~1 s


def _alternating(changes: list[float]) -> bool:
    """True when the last three cycle-to-cycle changes alternate in sign with similar size."""
    if len(changes) < 3:
        return False
    a, b, c = changes[-3:]
    same_size = max(abs(a), abs(b), abs(c)) <= 2.0 * min(abs(a), abs(b), abs(c)) + 1e-15
    return a * b < 0 and b * c < 0 and same_size


def _start(problem: LineEHLProblem, level: int, finest: int) -> tuple[int, LineEHLSolution]:
    """(level, exact solution) to start FMG from: the first level from ``level`` up whose discrete
    solution exists and is physical (positive films). Grids too coarse for a thin film either have
    a negative-film solution or none that Newton can reach."""
    last = max(level, min(finest, _MAX_START_LEVEL))
    previous: LineEHLSolution | None = None
    failure: ConvergenceError | None = None
    for current in range(level, last + 1):
        try:
            solution = _start_solution(problem, current, initial=previous)
        except ConvergenceError as exc:
            failure = exc
            continue
        if solution.H_min > 0.0 or current == last:
            return current, solution
        previous = solution
    raise ConvergenceError(
        f"line EHL multigrid (M = {problem.M:.4g}, L = {problem.L:.4g}): no start solution on levels "
        f"{level}..{last}: {failure}", getattr(failure, "record", None),
    )


def _start_solution(problem: LineEHLProblem, level: int, initial: LineEHLSolution | None = None) -> LineEHLSolution:
    """Exact solution on the FMG start level; by parameter continuation when a direct Newton fails.

    The continuation path starts from an easy neighbour (M <= 20, L <= 5), raises L to its
    value, then M (geometric steps), each step started from the previous solution.
    """
    from .line_reference import solve_reference

    try:
        return solve_reference(problem, level, deformation="direct", tolerance=1e-9, strict=True, initial=initial)
    except ConvergenceError:
        pass
    M0, L0 = min(problem.M, 20.0), min(problem.L, 5.0)
    path = [(M0, L) for L in np.linspace(L0, problem.L, 6)] + [(M, problem.L) for M in np.geomspace(M0, problem.M, 8)]
    solution = None
    for M, L in path:
        step = attrs.evolve(problem, M=float(M), L=float(L))
        solution = solve_reference(step, level, deformation="direct", tolerance=1e-9, strict=True, initial=solution)
    return attrs.evolve(solution, problem=problem)


def _record(solver, residuals, loads, works, start, converged, message, tolerance) -> ConvergenceRecord:
    return ConvergenceRecord(
        method=f"FAS multigrid, {solver.settings.cycle}-cycles, {solver.settings.deformation} deformation",
        levels=len(solver.levels), nodes=solver.levels[-1].n, residuals=tuple(residuals), load_errors=tuple(loads),
        work_units=tuple(works), wall_time=time.perf_counter() - start, converged=converged, message=message,
        tolerance=float("nan") if tolerance is None else tolerance,
    )
