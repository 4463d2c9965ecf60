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
  semi-smooth Newton method of :mod:`.line_reference` (compiled: :func:`._fas_kernels.coarse_newton`),
  so the load balance is met there;
* **cycles** — V, F (default: W-like coarse treatment at O(n) cost in 1-D) or W, each run as
  one compiled call (:mod:`._fas_kernels`: the recursion unrolled into a schedule); started by
  full multigrid from an exact Newton solution on a start level (level 3, raised until the
  discrete solution has positive films; parameter continuation when Newton needs it), or warm from a
  neighbouring solution (extrapolated from two, :func:`extrapolated_start`); lean by default: one pre-sweep and
  no post-sweep while the cycles contract fast (:attr:`MultigridSettings.lean`);
* **the pressure spike** — where the viscosity falls by more than e^``spike_drop`` between two nodes just past a
  pressure maximum (the Petrusevich spike of a piezoviscous contact), the six nodes around the fall are solved
  together by a local Newton after the pre-sweeps of every level and again after its post-sweeps
  (:func:`._fas_kernels.relax_spikes`). Point relaxation leaves node-sized errors there that the coarse grids
  cannot represent and amplify: measured at M 10, L 20 on level 9, one cycle started from the dense Newton
  solution moved the spike by 8e-3 and the cycles diverged; with the local solve they converge by x0.35 per
  cycle to the dense solution's H_min (to 1e-6). Over the Moes map of ``benchmarks/stability_map.py``
  (level 9) 106 of 108 cases converged, 104 in the first attempt (before: 100, with warnings at M 5-10,
  L 20-30 and errors at M 5-10, L 30), and the LS-1 cam's transient march at level 8 no longer diverges;
  with the film equation's FAS term in the last fallback attempt (:attr:`MultigridSettings.film_fas`) all 108 do;
* **safeguards** — if the cycles start alternating between two states while the free
  boundary moves (it hops between nodes), the cavitated set is frozen and the complementarity
  checked afterwards; if an attempt diverges or stagnates, further ones run with
  conservative settings (F-, then W-cycles). Where a coarse grid is too coarse for a very thin
  film its discrete film can close (H <= 0); xi is then 0 (a closed gap passes no pressure flow), not negative,
  which keeps heavy-load, low-L cases (M = 1000, L = 2) convergent.

Mass-conserving cavitation (``LineEHLProblem(cavitation="mass_conserving")``: Jakobsson–Floberg–Olsson through
the film fraction theta, Elrod 1981, in the complementarity form of Giacopini et al. 2010). The sweeps of the
finest grid solve for theta where P = 0 (:func:`camcontact.ehl._kernels.relax_hybrid`); the coarse grids take
theta by injection and hold every node injected from a cavitated fine node at P = 0 (projected FAS: they
correct the pressurised region only; measured: letting them pressurise those nodes left M = 1000, L = 10
stagnating). The wedge flux is first order behind a partly filled node. The solution carries theta
(``film_fraction``) and its discrete mass flux (``mass_flux``). Measured on level 8 at tolerance 1e-10 over
M in {2, 5, 20, 100, 1000} x L in {0, 2, 5, 10, 20}: 24 of 25 converge (M = 5, L = 20 stagnates, as it takes the
Reynolds model 27 cycles); their films equal the Reynolds model's within 4e-7 (JFO rupture is the Reynolds
condition in a steady line contact) and the mass flux is constant through contact and cavitated exit to
2e-9 ... 2e-5 (the stop rule also watches the domain's lubricant content). A starved inlet (``supply``) is
solved by :func:`camcontact.ehl.line_starved.solve_starved`.

Every solve returns a :class:`~camcontact.ehl.line_solution.ConvergenceRecord` (residual and
load error per cycle, work units, wall time, converged flag, notes). Not converged: a
:class:`~camcontact.errors.ConvergenceWarning`, or :class:`~camcontact.errors.ConvergenceError`
with ``strict=True``; a non-finite or runaway state (:data:`RUNAWAY_RESIDUAL`) always raises, so no NaN or
absurd film is ever returned.
"""

from __future__ import annotations

import functools
import math
import time

import attrs
import numpy as np

from ..errors import ConvergenceError, InputError
from . import _fas_kernels, _kernels
from .attempts import run_ladder
from .cycle_monitor import CycleMonitor, MonitorRules
from .deformation import DIRECT_BELOW, Deformation
from .line_problem import LineEHLProblem, grid_points, kernel_coefficients
from .line_solution import ConvergenceRecord, LineEHLSolution

__all__ = ["COARSEST_SPACING", "MONITOR_RULES", "RUNAWAY_RESIDUAL", "STEADY_COARSEST_SPACING", "WARM_RULES",
           "LineHierarchy", "MultigridSettings", "WarmStart", "coarsest_level", "extrapolated_start", "inlet_mapped",
           "solve_multigrid", "with_coarsest"]

#: the transient march's coarsest grid has at most this spacing (units of b_r; :mod:`camcontact.ehl.line_transient`).
#: A coarser one (wide domains: reversal, squeeze) slows the H0 correction: measured convergence factor 0.3 per
#: cycle with a spacing of 1.7 on a rigid squeeze film, 0.01 with 0.43.
COARSEST_SPACING = 0.45

#: the steady solver's coarsest grid has at most this spacing (units of b; :attr:`MultigridSettings.cycle_coarsest`
#: None). The default domain [-4, 1.5] (0.39) and the automatic domains up to 14 b wide keep the 15-node grid; on
#: wider ones (thick films' long inlets) a coarser grid stalls the thermal solver's multigrid solves: at 50 kN/m,
#: 20 m/s, S = 1.5 on [-32, 5] (level 7) the fixed point failed with a coarsest spacing of 2.6 and 1.3 and converges
#: in 8-9 iterations with 0.66 (Newtonian and Eyring). (0.45 as in the march cost the LS-1 cam cycle 30 % more.)
STEADY_COARSEST_SPACING = 1.0


def coarsest_level(domain, spacing: float = COARSEST_SPACING) -> int:
    """The first level whose spacing is at most ``spacing`` (the cycles' coarsest)."""
    width = float(domain[1] - domain[0])
    level = 1
    while width / (14 * 2 ** (level - 1)) > spacing:
        level += 1
    return level


def with_coarsest(settings: MultigridSettings, problem: LineEHLProblem, levels: int) -> MultigridSettings:
    """``settings`` with ``cycle_coarsest`` None replaced by :func:`coarsest_level` of the problem's domain at
    :data:`STEADY_COARSEST_SPACING`, below the finest level ``levels`` (the transient march gives its own)."""
    if settings.cycle_coarsest is not None:
        return settings
    coarsest = coarsest_level(problem.domain, STEADY_COARSEST_SPACING)
    return attrs.evolve(settings, cycle_coarsest=max(1, min(coarsest, int(levels) - 1)))


@attrs.frozen
class MultigridSettings:
    """Numerical settings of :func:`solve_multigrid` (defaults tested across the Moes map).

    The default cycles are lean F-cycles (:attr:`lean`): the full-multigrid start runs one F(1,1)-cycle per level
    below the finest, the finest grid F(1,0)-cycles while they contract fast and F(2,1) once they stall. A cycle's
    progress is limited by the coarse grids' corrections and the pressure spike, not by the smoothing, until the last
    digits. Measured against F(2,1) throughout (M 20, L 10 of Tsuha's Table 5.1, tolerance 1e-5,
    ``benchmarks/ehl_speed.py``): level 12 in 16 work units instead of 36 (0.096 s against 0.17 s), H_min 3.6e-10
    from a tight solution (F(2,1): 7.4e-8; the discretisation error 2.6e-7); level 14 in 0.37 s against 0.62 s
    (1.0e-9 off; discretisation error 2.1e-8); level 8 in 45 instead of 59 work units (with a post-sweep in the
    finest level's full-multigrid cycle, whose result nothing interpolates: 29, but levels 12-14 20 % slower). Over
    the LS-1 cam cycle (level 8, the 180 lift angles warm-started from extrapolated starts; consistent
    / thesis convention, tolerance 1e-5): 2961 / 3678 work units against 6661 / 7824 (1.57 / 1.72 s against 2.24 /
    2.58 s), the films within 3.8e-5 / 3.7e-5 of tightly converged ones (Hertz units, 0.07 nm; F(2,1) 3.4e-5 /
    1.0e-5); at tolerance 1e-7 6.4e-7 / 1.1e-6 off (F(2,1) 3.2e-7 / 6.3e-7). Tried and dropped: F(1,0) throughout
    (its unsmoothed states carry the coarse correction's error at the free boundary and the spike: a warm start of
    the M 20, L 10 contact on level 7 stopped at tolerance 1e-7 4.2e-7 off, lean 4.7e-8); F(1,1) throughout (the
    spike's pressures at tolerance 1e-9 1.8e-6 off, lean 4.7e-7, F(2,1) 2.0e-7); a full-multigrid start with one
    pre-sweep throughout (M = 3000 diverged at L = 2-20: the ladder's next attempt, :data:`ROBUST`, is F(2,1));
    V-cycles (35 % more cycles than F over the cam cycle, one thesis-convention angle 6.9e-4 off; a full-multigrid
    start by V-cycles missed H0 by 2e-4 on level 12, by F-cycles by 2e-8).
    """

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
    deformation: str = attrs.field(default="mlmi", validator=attrs.validators.in_(("mlmi", "direct")))
    #: FMG starts here with the dense Newton solver: the 15-node coarsest grid's own discrete
    #: solution can be unphysical (negative films), though it serves well as an FAS coarse grid
    start_level: int = 3
    #: the coarsest level the cycles descend to (1 = the 15-node grid); None: :func:`coarsest_level` of the
    #: problem's domain (below the finest level), so that wide domains keep a coarse spacing of at most
    #: :data:`STEADY_COARSEST_SPACING`
    cycle_coarsest: int | None = None
    #: apply coarse-grid corrections only where a node and both neighbours are pressurised
    correct_pressurised_only: bool = True
    #: no residual restriction at nodes next to a cavitated node
    freeze_free_boundary: bool = True
    #: coarse nodes injected from cavitated fine nodes keep their own (unmodified) right-hand side,
    #: so they stay cavitated with a margin instead of sitting exactly on the complementarity edge
    dry_keeps_own_equation: bool = True
    #: a fall of ln(eta-bar) by more than this between neighbours, just past a pressure maximum, marks the
    #: Petrusevich spike, whose nodes each cycle then solves together by Newton
    #: (:func:`camcontact.ehl._fas_kernels.relax_spikes`); 0: off
    spike_drop: float = attrs.field(default=2.0, validator=attrs.validators.ge(0.0))
    #: lean cycles where the smoothing does not limit them (class docstring): the full-multigrid start's cycles with
    #: one pre-sweep (and ``post_sweeps`` below the finest level: their results are interpolated to the next level),
    #: the finest grid's with one pre-sweep and none after while they contract fast, and with
    #: ``pre_sweeps`` and ``post_sweeps`` from the cycle after one that changed the watched films by more than
    #: :data:`STALL` times the change of the cycle before. False: (``pre_sweeps``, ``post_sweeps``) throughout
    lean: bool = True
    #: FAS for the film equation too: each coarse level's film is H0 + X^2/2 - K P/pi plus the FAS term
    #: H_fine(injected) - (H0 + X^2/2 - K_c P_c/pi) taken at the restriction, so the coarse film of the injected state
    #: is the fine film, not the coarse grid's own discretisation of the elastic integral. That one misses a thin film
    #: by more than the film (measured, M 1000, L 0 on level 9: H_min 2e-4, the film of the injected pressures on the
    #: 225-node grid -4e-4, 21 nodes closed), and corrections solved for a closed coarse film ran away (M 3000, L 0
    #: diverged in every attempt). The ladder's last attempt (:data:`ROBUST`) uses it: over the Moes map of
    #: ``benchmarks/stability_map.py`` (level 9) 108 of 108 then converge instead of 106 (M 3000 at L 0 and L 30 in
    #: that attempt). With it in every attempt the map converged as well, M 3000 with L 1-25 in the first attempt and
    #: M 1000 in 91-176 instead of 209-232 work units, the other films within 6e-7; but a warm start then stops
    #: further from the converged film (M 21, L 10 from M 20 on level 7: 4.1e-7 instead of 5e-8 at tolerance 1e-7),
    #: the transient march's steps stop with their mass balance 1.3e-3 instead of 5e-4 of the inflow off (tolerance
    #: 1e-9), and the meniscus search of a starved solve runs more failing attempts (see :data:`ROBUST`)
    film_fas: bool = False


class _Level:
    def __init__(self, domain: tuple, level: int, deformation: str, compiled: bool):
        self.k = level
        self.n = grid_points(level)
        self.X = np.linspace(domain[0], domain[1], self.n)
        self.h = float(self.X[1] - self.X[0])
        self.parabola = 0.5 * self.X**2
        self.deform = Deformation(self.n, self.h, deformation if self.n > _DIRECT_UP_TO else "direct",
                                  compiled=compiled)
        self.K = np.array([_kernels.kernel_value(float(d), self.h) for d in range(16)])


_DIRECT_UP_TO = 64  #: levels with at most this many nodes evaluate the deformation directly


class _Grids:
    """The grids of a hierarchy and their tables for the compiled cycles: per level the nodes, the parabola, the
    local kernel K(0..15), the MLMI correction tables, the dense K/pi of the coarsest levels the cycles solve
    exactly, and K(0 .. n - 1). They depend on the domain, the levels and the deformation settings only, not on
    the problem's loads or laws, so the solves of one domain share them (:func:`_grids`); nothing writes to them."""

    def __init__(self, domain: tuple, levels: int, deformation: str, cycle_coarsest: int, compiled: bool):
        self.levels = [_Level(domain, k, deformation, compiled) for k in range(1, levels + 1)]
        grids = self.levels
        self.n_of = np.array([level.n for level in grids], dtype=np.int64)
        self.offsets = np.concatenate([[0], np.cumsum(self.n_of)[:-1]]).astype(np.int64)
        self.h_of = np.array([level.h for level in grids])
        self.parabola = np.concatenate([level.parabola for level in grids])
        self.K_local = np.array([level.K for level in grids])
        self.mlmi_on = np.array([level.deform.method == "mlmi" for level in grids])
        self.m_of = np.array([level.deform.correction for level in grids], dtype=np.int64)
        tables = [level.deform._mlmi_tables() if on else None for level, on in zip(grids, self.mlmi_on)]
        depth = max([t[0].shape[0] for t in tables if t is not None], default=1)
        width = 2 * int(self.m_of.max()) + 1
        self.c1s = np.zeros((len(grids), depth, width))
        self.c2s = np.zeros((len(grids), depth, width))
        for k, t in enumerate(tables):
            if t is not None:
                self.c1s[k, : t[0].shape[0], : t[0].shape[1]] = t[0]
                self.c2s[k, : t[1].shape[0], : t[1].shape[1]] = t[1]
        solve_levels = min(max(cycle_coarsest, 1), len(grids))
        size = int(self.n_of[solve_levels - 1])
        self.K_dense = np.zeros((solve_levels, size, size))
        for k in range(min(solve_levels, len(grids))):
            n = grids[k].n
            table = kernel_coefficients(grids[k].h, n)
            self.K_dense[k, :n, :n] = table[np.abs(np.arange(n)[:, None] - np.arange(n)[None, :])] / math.pi
        #: K(0 .. n - 1) of every level, flat like the pressures (the cycles' exact film updates for local changes)
        self.K_tables = np.concatenate([kernel_coefficients(level.h, level.n) for level in grids])


@functools.lru_cache(maxsize=32)
def _grids(domain: tuple, levels: int, deformation: str, cycle_coarsest: int, compiled: bool) -> _Grids:
    """The shared :class:`_Grids` of a domain (measured: building them took 1.4 ms of a 12 ms warm-started level-8
    solve of the LS-1 cam cycle, whose lift angles share a few domains, :func:`~camcontact.ehl.line_domain.
    automatic_domain`)."""
    return _Grids(domain, levels, deformation, cycle_coarsest, compiled)


@functools.lru_cache(maxsize=256)
def _schedule(k: int, kind: str, coarsest: int) -> np.ndarray:
    """The shared :func:`camcontact.ehl._fas_kernels.cycle_schedule` of every hierarchy (unrolling the nine F-cycles
    of a full-multigrid start to level 12 takes 0.22 ms, 0.2 % of the solve; cached so that no solve repeats it)."""
    return _fas_kernels.cycle_schedule(k, kind, coarsest)


class LineHierarchy:
    """The level hierarchy of one solve: per-level buffers for the compiled cycles
    (:func:`camcontact.ehl._fas_kernels.fas_cycle`) and the finest-grid operator pieces the
    outer iteration checks convergence with (the transient solver extends it with its time terms)."""

    def __init__(self, problem: LineEHLProblem, levels: int, settings: MultigridSettings, compiled: bool):
        self.problem = problem
        self.settings = settings = with_coarsest(settings, problem, levels)
        self.kernel = _kernels.compiled if compiled else _kernels.PY.__getitem__
        self.cycle_kernel = _fas_kernels.compiled("fas_cycle") if compiled else _fas_kernels.fas_cycle
        self.grids = _grids(tuple(float(x) for x in problem.domain), int(levels), settings.deformation,
                            int(settings.cycle_coarsest), bool(compiled))
        self.levels = self.grids.levels
        self.viscosity_code, self.density_code = problem.law_codes
        self.params = problem.law_parameters
        self.lam = problem.lam
        #: signed entrainment speed ratio and implicit squeeze coefficient of the operator (steady: 1, 0;
        #: see :mod:`camcontact.ehl._kernels`)
        self.s, self.c_t = 1.0, 0.0
        #: mass-conserving cavitation (film fractions solved where P = 0) and the inlet layer's content
        #: h_oil R/b^2 the kernels take at the upstream boundary (infinite: a flooded inlet; a starved steady
        #: contact is solved by :func:`camcontact.ehl.line_starved.solve_starved`)
        self.mass_conserving = problem.cavitation == "mass_conserving"
        self.supply = math.inf
        self.work = 0.0
        #: frozen cavitation sets per level number (set when the cycles start to alternate)
        self.dry: dict[int, np.ndarray] = {}
        self._buffers()

    def _buffers(self) -> None:
        """Flat per-level buffers for the compiled cycle, beside the shared tables of the grids."""
        levels, s, grids = self.levels, self.settings, self.grids
        self.n_of, self.offsets, self.h_of = grids.n_of, grids.offsets, grids.h_of
        self.parabola = grids.parabola.copy()  # the hierarchy's own: the transient solver scales it per step
        self.K_local, self.mlmi_on, self.m_of, self.c1s, self.c2s = (grids.K_local, grids.mlmi_on, grids.m_of,
                                                                     grids.c1s, grids.c2s)
        self.K_dense, self.K_tables = grids.K_dense, grids.K_tables
        total = int(self.n_of.sum())
        self.P_all, self.P_old, self.f_all = np.zeros(total), np.zeros(total), np.zeros(total)
        self.dry_all = np.zeros(total, dtype=np.bool_)
        #: film fractions per level (1: full film); the cycles solve for them on their top level when the
        #: problem's cavitation is mass-conserving
        self.theta_all = np.ones(total)
        #: flow factors (a, k) and Couette factor c per node and level (:mod:`camcontact.ehl._kernels`; (1, 0, 1):
        #: isothermal Newtonian film), set on the finest level by :meth:`set_flow_factor`, restricted to the coarse ones
        self.phi_all = np.zeros((total, 3))
        self.phi_all[:, 0] = 1.0
        self.phi_all[:, 2] = 1.0
        self.H0s, self.loads = np.zeros(len(levels)), np.zeros(len(levels))
        self.real_settings = np.array([s.omega_gs, s.omega_jacobi, s.switch, s.h0_relaxation, s.spike_drop])
        #: entry 7: the first node the top level relaxes (1: all; a starved transient step holds the nodes
        #: upstream of its meniscus, :meth:`camcontact.ehl.line_transient.TransientLineSolver._starved_step`)
        self.int_settings = np.array([s.pre_sweeps, s.post_sweeps, s.coarsest_sweeps, s.window,
                                      s.correct_pressurised_only, s.freeze_free_boundary, s.dry_keeps_own_equation, 1,
                                      s.film_fas],
                                     dtype=np.int64)

    # ------------------------------------------------------------------ operator pieces
    def film(self, level: _Level, P: np.ndarray, H0: float) -> np.ndarray:
        """Film H [-] on ``level`` for pressures P and H0: H0 + X^2/2 - (1/pi) (deformation), or rigid."""
        if not self.problem.elastic:
            return H0 + level.parabola
        return H0 + level.parabola - level.deform(P) / math.pi

    def theta(self, level: _Level) -> np.ndarray:
        """The film fractions of ``level`` (a view into the cycles' buffer; 1 where the film is full)."""
        index = level.k - 1
        o = int(self.offsets[index])
        return self.theta_all[o:o + level.n]

    def flow_factor(self, level: _Level) -> np.ndarray:
        """The flow factors (a, k) and Couette factors c of ``level``, shape (n, 3) (a view into the cycles'
        buffer)."""
        o = int(self.offsets[level.k - 1])
        return self.phi_all[o:o + level.n]

    def set_flow_factor(self, factor: np.ndarray, eyring: np.ndarray | None = None,
                        couette: np.ndarray | None = None) -> None:
        """Flow factors a = ``factor``, Eyring coefficients k = ``eyring`` (None: 0) and Couette factors c =
        ``couette`` (None: 1) of the finest grid; each coarser level takes the full-weighting restriction of ln a,
        of k and of ln c of the level above. Only the finest grid's factors define the solution; the coarse ones only
        steer its corrections."""
        values = np.column_stack([np.log(factor), np.zeros(factor.size) if eyring is None else eyring,
                                  np.zeros(factor.size) if couette is None else np.log(couette)])
        for index in range(len(self.levels) - 1, -1, -1):
            self.flow_factor(self.levels[index])[:] = np.column_stack([np.exp(values[:, 0]), values[:, 1],
                                                                       np.exp(values[:, 2])])
            coarse = values[::2].copy()
            coarse[1:-1] = 0.25 * values[1:-2:2] + 0.5 * values[2:-1:2] + 0.25 * values[3::2]
            values = coarse

    def watched(self, level: _Level, P: np.ndarray, H: np.ndarray, H0: float) -> tuple[float, ...]:
        """The values whose changes from cycle to cycle decide convergence: (H_min, H0), and with mass-conserving
        cavitation also the lubricant content h sum theta rho H of the grid (the films settle before the film
        fractions of the cavitated regions do: measured, a transient step whose films had converged to 1e-6
        still lost 29 % of its inflow)."""
        if not self.mass_conserving:
            return float(H.min()), H0
        rho = self.problem.density_ratio(P)
        return float(H.min()), H0, float(level.h * np.sum(self.theta(level) * rho * np.maximum(H, 0.0)))

    def residual(self, level: _Level, P: np.ndarray, H: np.ndarray) -> np.ndarray:
        """Reynolds operator L_i(P, H, theta) [-] at the interior nodes of ``level`` (boundary entries 0)."""
        out = np.empty(level.n)
        self.kernel("reynolds_residual")(P, H, self.theta(level), self.flow_factor(level), level.h, self.lam,
                                         self.viscosity_code, self.density_code, self.params, self.s, self.c_t, out)
        return out

    def load(self, level: _Level, P: np.ndarray) -> float:
        """Load-balance error [-]: trapezoidal integral of P dX minus pi/2."""
        return float(level.h * (P.sum() - 0.5 * (P[0] + P[-1])) - 0.5 * math.pi)

    def freeze_dry(self, P: np.ndarray) -> None:
        """Hold the currently cavitated nodes of the finest grid (and their injections) at P = 0."""
        self.hold_dry(P <= 0.0)

    def hold_dry(self, dry: np.ndarray) -> None:
        """Hold the nodes of the finest grid where ``dry`` is set (and their injections) at P = 0; with mass-conserving
        cavitation they keep solving for their film fraction (clipped at 1). Their pressures must be 0 already."""
        dry = np.asarray(dry, dtype=np.bool_)
        for index in range(len(self.levels) - 1, -1, -1):
            level = self.levels[index]
            self.dry[level.k] = dry.copy()
            self.dry_all[self.offsets[index]:self.offsets[index] + level.n] = dry
            dry = dry[::2]

    # ------------------------------------------------------------------ transfers
    @staticmethod
    def prolong_cubic(c: np.ndarray) -> np.ndarray:
        """Coarse values ``c`` interpolated to the next finer grid (2 n - 1 nodes): cubic inside,
        linear at the two end intervals."""
        fine = np.empty(2 * c.size - 1)
        fine[0::2] = c
        fine[1::2] = 0.5 * (c[:-1] + c[1:])
        if c.size >= 4:
            fine[3:-3:2] = (-c[:-3] + 9.0 * c[1:-2] + 9.0 * c[2:-1] - c[3:]) / 16.0
        return fine

    # ------------------------------------------------------------------ cycles
    def cycle(self, k: int, P: np.ndarray, H0: float, f: np.ndarray, f_load: float,
              kind: str | None = None) -> tuple[np.ndarray, float]:
        """One FAS cycle on level index k: ``kind`` V (one coarse visit), W (two) or F (an F then a V).

        Pre-relaxation, restriction (full weighting of the residuals, injection of the solution),
        the coarse visits, linear prolongation of the corrections and post-relaxation, with the
        free-boundary rules of the module docstring; compiled as one call.
        """
        kind = kind or self.settings.cycle
        schedule = _schedule(k, kind, self.settings.cycle_coarsest - 1)
        o, n = int(self.offsets[k]), int(self.n_of[k])
        self.P_all[o:o + n] = P
        self.f_all[o:o + n] = f
        self.H0s[k], self.loads[k] = H0, f_load
        self.work += self.cycle_kernel(
            schedule, self.P_all, self.P_old, self.f_all, self.H0s, self.loads, self.dry_all, self.theta_all,
            self.phi_all, self.n_of, self.offsets, self.h_of, self.parabola, self.K_local, self.mlmi_on, self.m_of,
            self.c1s, self.c2s, _kernels.INTERP6, DIRECT_BELOW, self.K_dense, self.lam, self.viscosity_code,
            self.density_code, self.params, self.problem.elastic, self.real_settings, self.int_settings, self.s, self.c_t,
            self.mass_conserving, self.supply, self.K_tables,
        )
        return self.P_all[o:o + n].copy(), float(self.H0s[k])


#: the further attempts after a divergence or stagnation: F(2,1)-cycles throughout instead of lean ones (the
#: full-multigrid start of the heaviest loads, M = 3000, needs two pre-sweeps: measured on level 9, one diverged at
#: L = 2-20, two converged in 0.9-2.0 s), then the conservative settings, smaller relaxation factors and Gauss–Seidel only where the equation is clearly
#: differential, first with F-cycles, then with W-cycles (twice the work per cycle, the most robust); last, the
#: conservative F-cycles with the film equation's FAS term (:attr:`MultigridSettings.film_fas`): M 3000, L 0 on level 9
#: converges there instead of running away in every attempt, M 3000, L 30 to the dense Newton film instead of circling.
#: (With the film FAS in every fallback the Moes map converged as well, but a starved solve's meniscus search, whose
#: trial meniscus positions fail by design, ran more failing attempts: the LS-1 flat follower's march at a 0.1 um layer,
#: level 8, took 24.8 s instead of 15.9 s for the same films)
ROBUST = ({"lean": False},
          {"cycle": "F", "lean": False, "omega_gs": 0.5, "omega_jacobi": 0.2, "switch": 8.0},
          {"cycle": "W", "lean": False, "omega_gs": 0.5, "omega_jacobi": 0.2, "switch": 8.0},
          {"cycle": "F", "lean": False, "omega_gs": 0.5, "omega_jacobi": 0.2, "switch": 8.0, "film_fas": True})


def solve_multigrid(
    problem: LineEHLProblem,
    levels: int = 9,
    *,
    tolerance: float | None = 1e-7,
    settings: MultigridSettings | None = None,
    initial: LineEHLSolution | None = None,
    before: LineEHLSolution | None = None,
    strict: bool = False,
    compiled: bool = True,
    flow_factor: np.ndarray | None = None,
    eyring: np.ndarray | None = None,
    couette: np.ndarray | None = None,
) -> LineEHLSolution:
    """Solve the line-contact problem on ``levels`` grid levels by FAS multigrid.

    If the first attempt diverges, stagnates (:data:`STAGNATION`) or does not converge, further
    attempts run with the conservative settings :data:`ROBUST` (smaller relaxation factors,
    first with F-cycles, then with W-cycles); the record says which attempts ran and the
    solution's ``settings`` are those of the attempt kept. (Starting a warm start directly
    with the settings its neighbour needed was measured slower over the LS-1 cam cycle: the
    conservative settings then stay in use where the given ones would converge.)

    Parameters
    ----------
    problem : LineEHLProblem
    levels : int
        Finest level (n = 14 2^(levels-1) + 1 nodes; 9 gives 3585, 12 gives 28673).
    tolerance : float, optional
        Stop when the change of H_min and H0 between cycles falls below it and the load error
        below ten times it (None: run ``settings.max_cycles`` cycles). After a full-multigrid start the first
        cycle's change counts from the full-multigrid result, so a start already within the tolerance takes one
        cycle (level 12, M 20, L 10, tolerance 1e-5: one cycle instead of two, H_min 7e-8 from the tight solution
        where the discretisation error is 5e-7); a warm start's first cycle only sets the reference (measured: a
        starved solve's meniscus search, warm-started, otherwise stopped one cycle early with the mass flux 1.9e-5
        off the supply beside the meniscus), except an extrapolated start's (``before``), whose first cycle's change
        counts from the prediction; a warm-started solve stops also when fast-contracting cycles leave less than
        the tolerance to change (:data:`WARM_RULES`).
    settings : MultigridSettings, optional
    initial : LineEHLSolution, optional
        Warm start (interpolated onto the finest grid; FMG is then skipped).
    before : LineEHLSolution, optional
        The solution before ``initial`` along a continuation of equal steps (the cam angle before the previous
        one): where both lie on this problem's grid, the warm start is their linear extrapolation, the pressures
        2 P(initial) - P(before) clipped at 0 and H0 likewise (:func:`extrapolated_start`). Ignored without
        ``initial``.
    strict : bool
        Raise :class:`ConvergenceError` instead of warning when not converged.
    compiled : bool
        Use the numba kernels (False: the plain-Python twins, slow; for tests).
    flow_factor, eyring : array, optional
        Per node of the finest grid, the factor a > 0 and the Eyring coefficient k >= 0 of the flow factor on
        the Poiseuille coefficient, xi = a sqrt(1 + (k eta-bar(P))^2) rho H^3/(eta lambda)
        (:func:`camcontact.ehl._kernels.flow_factor`; None: a = 1, k = 0, the isothermal Newtonian film); the
        thermal and non-Newtonian solver (:mod:`camcontact.ehl.line_thermal`) gives the film's viscosity at its
        temperature and the Reynolds–Eyring flow enhancement through them.
    couette : array, optional
        Per node of the finest grid, the Couette factor c > 0 on the wedge's content, q = c rho H (the entrainment
        flux u_e h = c u_m h of a film whose viscosity varies across it: Yang & Wen's 1990 generalised Reynolds
        equation; None: 1).

        The factors are held fixed during the solve and kept on the solution (``flow_factor``, shape (n, 3):
        a, k, c). (A full multigrid start solves its start level without them; the cycles on the levels above
        take them.)
    """
    if not (isinstance(levels, (int, np.integer)) and 1 <= levels <= 16):
        raise InputError(f"solve_multigrid: levels = {levels!r}; allowed 1..16")
    factors = None
    if flow_factor is not None or eyring is not None or couette is not None:
        n = grid_points(levels)
        factors = [np.ones(n) if flow_factor is None else np.asarray(flow_factor, dtype=float),
                   np.zeros(n) if eyring is None else np.asarray(eyring, dtype=float),
                   np.ones(n) if couette is None else np.asarray(couette, dtype=float)]
        for name, value, low in (("flow_factor", factors[0], 0.0), ("eyring", factors[1], None),
                                 ("couette", factors[2], 0.0)):
            good = np.isfinite(value) & ((value > low) if low is not None else (value >= 0.0))
            if value.shape != (n,) or not np.all(good):
                raise InputError(f"solve_multigrid: {name} of shape {value.shape}; allowed: finite values "
                                 f"{'> 0' if low is not None else '>= 0'}, one per node of level {levels} ({n} nodes)")
    if problem.supply is not None:
        raise InputError(f"solve_multigrid: the problem has a starved inlet (supply = {problem.supply!r}); solve it "
                         "with camcontact.ehl.line_starved.solve_starved, which finds its meniscus")
    # resolved before the attempts, so that their settings (and the record's account of them) are concrete
    settings = with_coarsest(settings or MultigridSettings(), problem, levels)
    if initial is not None and before is not None:
        initial = extrapolated_start(initial, before, problem, levels)
    starts: dict = {}  # the full-multigrid start solutions, shared by the attempts (:func:`_shared_start`)
    return run_ladder(settings, ROBUST,
                      lambda attempt: _solve_once(problem, levels, tolerance, attempt, initial, compiled, factors,
                                                  starts),
                      f"line EHL multigrid (M = {problem.M:.4g}, L = {problem.L:.4g})", strict=strict,
                      size=f"{grid_points(levels)} nodes")


@attrs.frozen
class WarmStart:
    """A warm start of :func:`solve_multigrid` that is not a solution: pressures P [-] on nodes X [-] (units of b),
    H0 [-] and, for mass-conserving cavitation, the film fractions (None: a full film)."""

    X: np.ndarray = attrs.field(eq=False)
    P: np.ndarray = attrs.field(eq=False)
    H0: float
    film_fraction: np.ndarray | None = attrs.field(default=None, eq=False)


def extrapolated_start(last, before, problem: LineEHLProblem, levels: int):
    """The linear extrapolation of two consecutive solutions of a continuation of equal steps (``before``, then
    ``last``) to the next one, ``problem`` on ``levels``: a :class:`WarmStart` with P = max(2 P_last - P_before, 0)
    and H0 = 2 H0_last - H0_before (the film fractions of ``last``); ``last`` itself where the two do not lie on the
    grid of ``problem`` (another domain or level: nothing to extrapolate node by node).

    Where the pressure changed by more than :data:`SPIKE_CHANGE` times its maximum from ``before`` to ``last`` (the
    pressure spike, which jumps from node to node rather than moving smoothly) and three nodes either side, the
    start keeps ``last``'s pressures. Measured on the LS-1 roller cycle (level 8, the 180 lift angles, tolerance
    1e-5, F(1,1)-cycles; consistent / thesis convention): from the last angle's solution 5989 / 6364 work
    units, from the plain extrapolation 5386 / 6362 (it put a few spikes so far off that the first cycle moved
    H_min by 1e-2), with the spike kept 4725 / 5628; the films within 3.1e-5 / 2.9e-5 of the tightly converged
    ones (Hertz units; 0.06 nm), against 8.7e-6 / 1.9e-5 from the last solution. The start from the last angle
    was 1.6e-3-1.6e-2 off in H_min or H0, the extrapolated one 1.4e-4-3.3e-4.
    """
    n = grid_points(levels)
    X = np.linspace(problem.domain[0], problem.domain[1], n)
    same = all(getattr(sol, "X", None) is not None and sol.X.size == n and np.array_equal(sol.X, X)
               for sol in (last, before))
    if not same:
        return last
    change = last.P - before.P
    jumps = np.abs(change) > SPIKE_CHANGE * float(np.max(last.P))
    kept = np.convolve(jumps, np.ones(7), mode="same") > 0.0  # and three nodes either side
    P = np.maximum(np.where(kept, last.P, last.P + change), 0.0)
    P[0] = P[-1] = 0.0
    return WarmStart(X=last.X, P=P, H0=2.0 * float(last.H0) - float(before.H0),
                     film_fraction=getattr(last, "film_fraction", None))


def inlet_mapped(X: np.ndarray, X_start: np.ndarray) -> np.ndarray:
    """Where each node of X [-] takes its warm-start values on the warm start's nodes ``X_start`` [-]: X itself
    where both inlets start at the same X; else the inlet's upstream half, [X[0], m] with m = X_start[0]/2, is
    mapped linearly onto the warm start's [X_start[0], m] (stretched for a longer inlet, compressed for a shorter
    one), so that the new inlet starts from the start's inlet pressures, rising from 0 at its boundary.

    Why: the coarse grids correct only pressurised nodes (:class:`MultigridSettings`), so the zeros that plain
    interpolation puts into a longer inlet are filled by the relaxation alone, about a node per sweep; and a
    shorter inlet cut off from the start's converges as slowly. Measured on the LS-1 roller cycle (level 8,
    tolerance 1e-5) at the angles where :func:`~camcontact.models.film_multigrid.automatic_domain` changes the
    domain: 4-9 cycles (34-79 work units) from the interpolated start, 2-5 cycles (50-87, with its full
    multigrid) from a cold start, 4-6 cycles (34-52) from the mapped one.
    """
    middle = 0.5 * float(X_start[0])
    if X[0] == X_start[0] or not (X[0] < middle and X_start[0] < middle):
        return X
    out = X.copy()
    inlet = X < middle
    out[inlet] = middle + (X[inlet] - middle) * (float(X_start[0]) - middle) / (float(X[0]) - middle)
    return out


#: the share of the largest pressure by which a node's pressure must change between two solutions for
#: :func:`extrapolated_start` to take it for the spike and not extrapolate it (0.1-0.3 measured alike, 0.5 as none)
SPIKE_CHANGE = 0.2


def _solve_once(problem, levels, tolerance, settings, initial, compiled, factors=None,
                starts: dict | None = None) -> LineEHLSolution:
    """One multigrid attempt (see :func:`solve_multigrid`); raises ConvergenceError on divergence. ``starts``: the
    full-multigrid start solutions of earlier attempts of the same solve (:func:`_shared_start`)."""
    if not (isinstance(levels, (int, np.integer)) and 1 <= levels <= 16):
        raise InputError(f"solve_multigrid: levels = {levels!r}; allowed 1..16")
    settings = settings or MultigridSettings()
    start = time.perf_counter()
    solver = LineHierarchy(problem, int(levels), settings, compiled)
    if factors is not None:
        solver.set_flow_factor(*factors)
    finest = solver.levels[-1]
    if initial is not None:
        X_from = inlet_mapped(finest.X, initial.X)
        P = np.maximum(np.interp(X_from, initial.X, initial.P), 0.0)
        P[0] = P[-1] = 0.0
        H0 = float(initial.H0)
        if solver.mass_conserving and initial.film_fraction is not None:
            solver.theta(finest)[:] = np.interp(X_from, initial.X, initial.film_fraction)
    reference = None  # a warm start's first cycle only sets the reference (see tolerance above) ...
    if isinstance(initial, WarmStart):  # ... unless it is a prediction: the first cycle's change counts from it
        reference = solver.watched(finest, P, solver.film(finest, P, H0), H0)
    if initial is None:  # full multigrid start: exact solve on the start level, then up level by level
        first, coarse = _shared_start({} if starts is None else starts, problem,
                                      min(settings.start_level, len(solver.levels)), len(solver.levels))
        P, H0 = coarse.P.copy(), coarse.H0
        solver.work += coarse.record.cycles * coarse.X.size / finest.n
        if settings.lean:  # F(1, post_sweeps) on the way up
            solver.int_settings[0] = 1
        for k in range(first, len(solver.levels)):
            P = np.maximum(solver.prolong_cubic(P), 0.0)
            P[0] = P[-1] = 0.0
            if solver.mass_conserving:  # the film fractions found on the level below
                below = solver.theta(solver.levels[k - 1])
                solver.theta(solver.levels[k])[:] = np.minimum(np.interp(solver.levels[k].X, solver.levels[k - 1].X,
                                                                         below), 1.0)
            zero = np.zeros(solver.levels[k].n)
            if settings.lean and k == len(solver.levels) - 1:  # the finest's result is not interpolated: lean
                solver.int_settings[1] = 0
            for _ in range(settings.fmg_cycles):
                P, H0 = solver.cycle(k, P, H0, zero, 0.0)
            if not (np.all(np.isfinite(P)) and math.isfinite(H0) and np.max(P) < RUNAWAY_PRESSURE):
                # diverged on the way up: the attempt ends here, not after the finest grid's cycles
                raise ConvergenceError(
                    f"line EHL multigrid diverged (M = {problem.M:.4g}, L = {problem.L:.4g}) in its full-multigrid "
                    f"start on level {k + 1} (max P = {np.max(P):.3g}, H0 = {H0:.4g})",
                    _record(solver, [], [], [], start, False, "diverged in the full-multigrid start", tolerance))
        if first < len(solver.levels):  # the full multigrid result: the first cycle's change is measured from it
            reference = solver.watched(finest, P, solver.film(finest, P, H0), H0)
    return _converge_finest(solver, P, H0, tolerance, start, reference, WARM_RULES if initial is not None else None)


def _converge_finest(solver: LineHierarchy, P: np.ndarray, H0: float, tolerance: float | None,
                    start: float, reference: tuple | None = None, rules: MonitorRules | None = None) -> LineEHLSolution:
    """Cycles on the finest grid of ``solver`` from (P, H0) until ``rules`` (None: :data:`MONITOR_RULES`) stop them; the
    solution with its record (wall time counted from ``start``, a :func:`time.perf_counter` value). ``reference``:
    the watched values of the start state, from which the first cycle's change is measured (None: from the first
    cycle on).
    Raises ConvergenceError on a non-finite state or a runaway one (:data:`RUNAWAY_RESIDUAL`)."""
    problem, settings, levels = solver.problem, solver.settings, len(solver.levels)
    finest = solver.levels[-1]
    zero = np.zeros(finest.n)
    watch = CycleMonitor(rules or MONITOR_RULES, tolerance, solver.freeze_dry, start=reference)
    change = None  # the last cycle's largest change of the watched films
    if settings.lean:  # F(1,0) until the cycles stall
        solver.int_settings[0], solver.int_settings[1] = 1, 0
    for _ in range(settings.max_cycles):
        P, H0 = solver.cycle(len(solver.levels) - 1, P, H0, zero, 0.0)
        H = solver.film(finest, P, H0)
        if not (np.all(np.isfinite(P)) and np.all(np.isfinite(H)) and math.isfinite(H0)):
            raise ConvergenceError(
                f"line EHL multigrid diverged (M = {problem.M:.4g}, L = {problem.L:.4g}): non-finite state",
                _record(solver, watch.residuals, watch.loads, watch.works, start, False, "non-finite state",
                        tolerance),
            )
        r = solver.residual(finest, P, H)
        r = np.where((P > 0.0) | (solver.theta(finest) < 1.0), r, np.maximum(r, 0.0))
        residual = float(np.mean(np.abs(r[1:-1])) * finest.h)
        if residual > RUNAWAY_RESIDUAL:
            raise ConvergenceError(
                f"line EHL multigrid diverged (M = {problem.M:.4g}, L = {problem.L:.4g}): residual {residual:.3g} "
                f"(H0 = {H0:.4g}, H_min = {H.min():.4g}): a runaway state",
                _record(solver, watch.residuals, watch.loads, watch.works, start, False, "runaway state", tolerance),
            )
        if watch.after_cycle(P, solver.watched(finest, P, H, H0), residual, solver.load(finest, P), solver.work):
            break
        change, last_change = watch.last_change, change
        if settings.lean and change is not None and last_change is not None and change > STALL * last_change:
            solver.int_settings[0], solver.int_settings[1] = settings.pre_sweeps, settings.post_sweeps
    else:
        watch.out_of_cycles(settings.max_cycles)
    converged, message = watch.converged, watch.message
    residuals, loads, works = watch.residuals, watch.loads, watch.works
    if solver.dry and converged:
        H_check = solver.film(finest, P, H0)
        wants = (solver.residual(finest, P, H_check) > 0.0) & solver.dry[finest.k]
        message += f"; {int(wants.sum())} frozen dry nodes would take pressure" if wants.any() else "; complementarity holds"
    H = solver.film(finest, P, H0)
    if H.min() <= 0.0:  # a solution of the discrete equations, not of the contact: say so
        message = (message + "; " if message else "") + (
            f"the discrete film closes (H_min = {H.min():.3g} <= 0): the grid is too coarse for this film, "
            "refine it (more levels)")
    record = _record(solver, residuals, loads, works, start, converged, message, tolerance)
    theta = solver.theta(finest).copy() if solver.mass_conserving else None
    phi = solver.flow_factor(finest)
    plain = np.all(phi[:, 0] == 1.0) and np.all(phi[:, 1] == 0.0) and np.all(phi[:, 2] == 1.0)
    return LineEHLSolution(problem=problem, level=int(levels), X=finest.X, P=P, H=H, H0=float(H0), record=record,
                           settings=settings, theta=theta, flow_factor=None if plain else phi.copy())


#: lean cycles become F(``pre_sweeps``, ``post_sweeps``) (:attr:`MultigridSettings.lean`) after a cycle whose largest
#: change of the watched films is more than this share of the cycle's before (the cheap cycles stall: smoothing
#: limits them now; 0.5 came too late for a single warm start's last digits, 4.2e-7 off at tolerance 1e-7 instead of
#: 4.7e-8; see :class:`MultigridSettings`)
STALL = 0.3

#: a finest-grid residual above this is a runaway state, however finite: an attempt that reaches it has diverged
#: (measured over the Moes map of ``benchmarks/stability_map.py``: converging cases start below 1e-2; M = 3000,
#: L = 0 on level 9 without the film FAS (:attr:`MultigridSettings.film_fas`) ran off to residuals of 1e39-1e169
#: with H0 ~ 1e36 and, finite, was kept as the attempt with the smallest residual)
RUNAWAY_RESIDUAL = 1e6

#: a full-multigrid start whose pressures exceed this (Hertz units; the Petrusevich spike of the hardest cases of the
#: Moes map reaches about 10) on a level has diverged there
RUNAWAY_PRESSURE = 1e6

_MAX_START_LEVEL = 6  # the dense start solver stays below ~1 s


#: (cycles, window): an attempt stops as stagnated once it has run ``cycles`` cycles and the
#: smallest residual of the last ``window`` cycles is not half the smallest before them (a limit
#: cycle of the free boundary or of H0; measured: the LS-1 cam's hard angles circle at a
#: residual of 6e-5 for all 40 cycles)
STAGNATION = (10, 5)

#: the stop rules of the steady line cycles (:class:`~camcontact.ehl.cycle_monitor.CycleMonitor`):
#: converged when the changes of (H_min, H0) fall below the tolerance and the load error below
#: 10 max(tolerance, 1e-9); :data:`STAGNATION`; the dry set frozen when H_min alternates while the
#: last pressurised node moves, only when a tolerance is given
MONITOR_RULES = MonitorRules(stagnation=STAGNATION, load_factor=10.0, load_floor=1e-9, boundary="last_pressurised",
                             freeze_needs_tolerance=True)


#: the stop rules of a warm-started solve (a cam angle from its neighbour, a starved meniscus step): also converged
#: when fast-contracting cycles leave less than the tolerance to change (``estimate_remaining``; measured over the
#: LS-1 roller cycle at level 8, tolerance 1e-5: 4.56 -> 4.05 F-cycles per angle; at 1e-7 the films of the frozen
#: cam report move by at most 4e-7 relative, its spike pressures by 3e-5). A cold start keeps the plain change test:
#: its tests hold the default tolerance to pressures equal to the dense Newton solution's to 1e-7 and a fixed point
#: to 1e-6, which the earlier stop misses at the spike (2e-7, 5e-6), whose pressures settle after the watched films
WARM_RULES = attrs.evolve(MONITOR_RULES, estimate_remaining=True)


def _shared_start(starts: dict, problem: LineEHLProblem, level: int, finest: int) -> tuple[int, LineEHLSolution]:
    """:func:`_start`, computed once per solve: its result (or its ConvergenceError) is kept in ``starts`` under
    ``level`` for the solve's later attempts, which differ in their cycles, not in their start.
    Measured on level 9: the dense start of M 3000, L 15-30 (level 6, by continuation) takes 2.1 s, which each of
    the ladder's attempts repeated (M 3000, L 30, three attempts: 6.1 s in all)."""
    if level not in starts:
        try:
            starts[level] = _start(problem, level, finest)
        except ConvergenceError as failure:
            starts[level] = failure
    kept = starts[level]
    if isinstance(kept, ConvergenceError):
        raise kept
    return kept


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
