"""What mass-conserving cavitation and starvation cost against the Reynolds (clipping) model of the line solver.

Per case (medians of ``--repeats`` runs, interleaved): the film, the spread of the discrete mass flux through the
domain, the cycles (or solves) and the wall time of

* ``steady``: the flooded line contact M = 20, L = 10 (Roelands, Dowson–Higginson) with each cavitation model;
* ``starved``: the same contact fed by an inlet layer of 0.8, 0.4 and 0.2 of the flooded flux
  (:func:`camcontact.ehl.line_starved.solve_starved`: a flooded solve plus the meniscus search);
* ``transient``: a reciprocating contact through an entrainment reversal (u_m = 2 cos(2 pi t/8 ms) m/s over 4 ms,
  R 20 mm, w 200 kN/m, E' 226 GPa, eta0 0.05 Pa s, alpha 20/GPa, 81 BDF2 steps) with each model: the march time,
  the non-converged steps and the thinnest film after the reversal.

    python benchmarks/cavitation_cost.py            # level 10 steady/starved, level 8 transient, 3 repeats
    python benchmarks/cavitation_cost.py --quick    # level 6, one repeat (the tests run this)

Writes ``cavitation_cost.csv`` into ``--out``. Timings are reported, never asserted.
"""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import numpy as np
import pandas as pd

from camcontact.ehl.line_multigrid import solve_multigrid
from camcontact.ehl.line_problem import LineEHLProblem
from camcontact.ehl.line_starved import solve_starved, wet_flux
from camcontact.ehl.line_transient import transient_cycle
from camcontact.errors import ConvergenceWarning

sys.path.insert(0, str(Path(__file__).resolve().parent))  # the shared benchmarks/_output.py
from _output import arguments, timed  # noqa: E402

CASE = dict(M=20.0, L=10.0)
SUPPLIES = (0.8, 0.4, 0.2)


def flux_spread(solution) -> float:
    """(max - min)/mean of the discrete mass flux over the faces downstream of the meniscus (all faces if flooded)."""
    F = solution.mass_flux
    meniscus = solution.inlet_meniscus
    if meniscus is not None:
        F = F[solution.X[:-1] > meniscus + 2.0 * (solution.X[1] - solution.X[0])]
    return float(np.ptp(F) / np.mean(F))


def steady_rows(level: int, repeats: int) -> list[dict]:
    rows = []
    for cavitation in ("reynolds", "mass_conserving"):
        problem = LineEHLProblem(**CASE, cavitation=cavitation)
        solution, seconds = timed(lambda: solve_multigrid(problem, level), repeats)
        spread = flux_spread(solution) if cavitation == "mass_conserving" else float("nan")
        rows.append({"case": "steady", "model": cavitation, "supply [-]": 1.0, "H_c": solution.H_c,
                     "H_min": solution.H_min, "flux spread": spread, "cycles or solves": solution.record.cycles,
                     "converged": solution.record.converged, "time [s]": seconds})
    return rows


def starved_rows(level: int, repeats: int) -> list[dict]:
    flooded = solve_multigrid(LineEHLProblem(**CASE), level)
    rows = []
    for fraction in SUPPLIES:
        problem = LineEHLProblem(**CASE, cavitation="mass_conserving", supply=fraction * wet_flux(flooded))
        solution, seconds = timed(lambda: solve_starved(problem, level), repeats)
        solves = int(solution.record.message.split(" solves")[0].rsplit(" ", 1)[-1])
        rows.append({"case": "starved", "model": "mass_conserving", "supply [-]": fraction,
                     "H_c": solution.H_c, "H_min": solution.H_min, "flux spread": flux_spread(solution),
                     "cycles or solves": solves, "converged": solution.record.converged, "time [s]": seconds,
                     "meniscus X": solution.inlet_meniscus, "H_c / H_c,flooded": solution.H_c / flooded.H_c})
    return rows


def transient_rows(level: int, repeats: int, steps: int) -> list[dict]:
    times = np.linspace(0.0, 0.004, steps)
    u_m = 2.0 * np.cos(2.0 * np.pi * times / 0.008)
    rows = []
    for cavitation in ("reynolds", "mass_conserving"):
        def run():
            return transient_cycle(times, 2e5, 0.02, u_m, E_reduced=2.26e11, eta0=0.05, alpha=2e-8, levels=level,
                                   cavitation=cavitation)
        result, seconds = timed(run, repeats)
        after = u_m < 0.0
        rows.append({"case": "transient", "model": cavitation, "supply [-]": 1.0, "H_c": float("nan"),
                     "H_min": float(result.H_min[after].min()), "flux spread": float("nan"),
                     "cycles or solves": sum(r.cycles for r in result.records),
                     "converged": bool(result.converged.all()), "time [s]": seconds,
                     "not converged steps": int((~result.converged).sum()),
                     "h_min after reversal [nm]": float(result.h_min[after].min() * 1e9)})
    return rows


def main(argv=None) -> pd.DataFrame:
    args = arguments(__doc__, "level 6, one repeat, 21 transient steps", argv)
    steady_level, transient_level = (6, 6) if args.quick else (10, 8)
    repeats = 1 if args.quick else args.repeats
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        rows = (steady_rows(steady_level, repeats) + starved_rows(steady_level, repeats)
                + transient_rows(transient_level, repeats, 21 if args.quick else 81))
    frame = pd.DataFrame(rows)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    frame.to_csv(out / "cavitation_cost.csv", index=False)
    with pd.option_context("display.width", 200, "display.max_columns", 20):
        print(frame.to_string(float_format=lambda v: f"{v:.4g}"))
    print(f"written to {out}")
    return frame


if __name__ == "__main__":
    main()
