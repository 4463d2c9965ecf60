"""Speed of the line-contact multigrid solver: wall time per level and its growth with n.

Target (issue 3, 2-core machine, single thread): M = 20, L = 10 (Tsuha 2015 Table 5.1 case),
level 12 = 28,673 nodes solved to a converged load balance with the algebraic change per cycle
below the discretisation error in under 2 s; the time per doubling of n from level 8 to 12 at
most 2.3 (linear growth).

    python benchmarks/ehl_speed.py            # levels 8..12, median of 5 runs each
    python benchmarks/ehl_speed.py --quick    # levels 5..7, 1 run (the tests run this)

The discretisation error of H_min at a level is estimated as |H_min(k) - H_min(k-1)| / 3
(second-order convergence); the solver's tolerance (change of H_min and H0 per cycle) must be
below it. Numba compilation is excluded (one warm-up solve first). Prints a table and writes
``ehl_speed.csv`` into ``--out``.
"""

from __future__ import annotations

import argparse
import os
import statistics
import time
from pathlib import Path

import pandas as pd

from camcontact.ehl.line_multigrid import solve_multigrid
from camcontact.ehl.line_problem import LineEHLProblem, grid_points

TARGET_SECONDS, TARGET_RATIO = 2.0, 2.3


def main(argv: list[str] | None = None) -> pd.DataFrame:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--out", default=str(Path(__file__).parent / "results"))
    args = parser.parse_args(argv)
    os.environ.setdefault("NUMBA_NUM_THREADS", "1")
    levels, repeats = (range(5, 8), 1) if args.quick else (range(8, 13), 5)
    problem = LineEHLProblem(M=20, L=10, alpha=1.7e-8, z=0.68)
    solve_multigrid(problem, 5)  # compile / load the kernels
    rows, previous = [], None
    for level in levels:
        times, solution = [], None
        for _ in range(repeats):
            start = time.perf_counter()
            solution = solve_multigrid(problem, level)
            times.append(time.perf_counter() - start)
        median = statistics.median(times)
        discretisation = abs(solution.H_min - previous.H_min) / 3.0 if previous else float("nan")
        rows.append({
            "level": level, "nodes": grid_points(level), "median time [s]": median,
            "ratio to previous level": median / rows[-1]["median time [s]"] if rows else float("nan"),
            "cycles": solution.record.cycles, "work units": solution.record.work_units[-1],
            "time per work unit [ms]": 1e3 * median / solution.record.work_units[-1],
            "converged": solution.record.converged, "H_min": solution.H_min,
            "load error": solution.record.load_errors[-1], "tolerance": solution.record.tolerance,
            "discretisation error estimate": discretisation,
        })
        previous = solution
    frame = pd.DataFrame(rows)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    frame.to_csv(out / "ehl_speed.csv", index=False)
    print(frame.to_string(index=False, float_format=lambda v: f"{v:.4g}"))
    if not args.quick:
        last = frame.iloc[-1]
        ratios = frame["ratio to previous level"].dropna()
        print(f"level 12: {last['median time [s]']:.3f} s (target < {TARGET_SECONDS} s): "
              f"{'met' if last['median time [s]'] < TARGET_SECONDS else 'NOT met'}")
        print(f"time ratio per level doubling 8 -> 12: max {ratios.max():.2f}, geometric mean "
              f"{(frame['median time [s]'].iloc[-1] / frame['median time [s]'].iloc[0]) ** (1 / (len(frame) - 1)):.2f} "
              f"(target <= {TARGET_RATIO})")
        per_unit = frame["time per work unit [ms]"]
        unit_ratios = (per_unit / per_unit.shift()).dropna()
        print(f"time per work unit (one finest-grid sweep equivalent) per level doubling: max {unit_ratios.max():.2f}, "
              f"geometric mean {(per_unit.iloc[-1] / per_unit.iloc[0]) ** (1 / (len(frame) - 1)):.2f}; the number of "
              f"cycles varies from level to level ({', '.join(str(c) for c in frame['cycles'])})")
        print(f"tolerance {last['tolerance']:.1e} vs discretisation error {last['discretisation error estimate']:.1e}")
    return frame


if __name__ == "__main__":
    main()
