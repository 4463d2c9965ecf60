"""Speed of the line-contact multigrid solver: wall time per level at discretisation accuracy, and against Newton.

Targets. Issue 3 (2-core machine, single thread): M = 20, L = 10 (Tsuha 2015 Table 5.1 case), level 12 = 28,673
nodes in under 2 s, the time per doubling of n from level 8 to 12 at most 2.3 (linear growth). Issue 19: level 12
in 0.1 s and level 14 in 0.4 s at discretisation accuracy; the dense semi-smooth Newton solver
(:func:`camcontact.ehl.line_reference.solve_reference`) at least 50 times slower at n = 1793 (level 8) for the
same H_min to 1e-6.

    python benchmarks/ehl_speed.py            # levels 8..14, median of 5 runs (3 at levels 13-14), Newton at level 8
    python benchmarks/ehl_speed.py --quick    # levels 5..7, 1 run, Newton at level 5 (the tests run this)

Per level: a tight solve (tolerance 1e-10) gives the discrete solution's H_min; its change from the level below,
/3 (second order), estimates the discretisation error; each timed tolerance (1e-5 and the default 1e-7) reports
its median time, cycles, work units, time per node and work unit and its algebraic error |H_min - H_min(tight)|,
and whether that error is below the discretisation error ("at discretisation accuracy"). Numba compilation is
excluded (one warm-up solve first). Prints the tables and writes ``ehl_speed.csv`` and ``ehl_speed_newton.csv``
into ``--out``.
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
from camcontact.ehl.line_reference import solve_reference

TARGET_SECONDS, TARGET_RATIO = 2.0, 2.3  # issue 3
TARGETS_AT_DISCRETISATION = {12: 0.1, 14: 0.4}  # issue 19 [s]
TARGET_NEWTON_RATIO, NEWTON_AGREEMENT = 50.0, 1e-6  # issue 19
TOLERANCES = (1e-5, 1e-7)
TIGHT = 1e-10


def _median_solve(problem, level, tolerance, repeats):
    times, solution = [], None
    for _ in range(repeats):
        start = time.perf_counter()
        solution = solve_multigrid(problem, level, tolerance=tolerance)
        times.append(time.perf_counter() - start)
    return statistics.median(times), solution


def main(argv: list[str] | None = None) -> pd.DataFrame:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--out", default=str(Path(__file__).parent / "results"))
    args = parser.parse_args(argv)
    os.environ.setdefault("NUMBA_NUM_THREADS", "1")
    levels, newton_level = (range(5, 8), 5) if args.quick else (range(8, 15), 8)
    problem = LineEHLProblem(M=20, L=10, alpha=1.7e-8, z=0.68)
    solve_multigrid(problem, 5)  # compile / load the kernels
    solve_reference(problem, 4)
    rows, previous_tight = [], None
    for level in levels:
        repeats = 1 if args.quick else (5 if level <= 12 else 3)
        tight = solve_multigrid(problem, level, tolerance=TIGHT)
        discretisation = abs(tight.H_min - previous_tight.H_min) / 3.0 if previous_tight else float("nan")
        row = {"level": level, "nodes": grid_points(level), "H_min (tight)": tight.H_min,
               "discretisation error estimate": discretisation, "converged": tight.record.converged}
        for tolerance in TOLERANCES:
            median, solution = _median_solve(problem, level, tolerance, repeats)
            algebraic = abs(solution.H_min - tight.H_min)
            work = solution.record.work_units[-1]
            row.update({
                f"time, tol {tolerance:g} [s]": median, f"cycles, tol {tolerance:g}": solution.record.cycles,
                f"work units, tol {tolerance:g}": work,
                f"ns per node and work unit, tol {tolerance:g}": 1e9 * median / work / grid_points(level),
                f"algebraic error, tol {tolerance:g}": algebraic,
                f"at discretisation accuracy, tol {tolerance:g}": bool(algebraic < discretisation),
            })
            row["converged"] = row["converged"] and solution.record.converged
        rows.append(row)
        previous_tight = tight
    frame = pd.DataFrame(rows)
    default = TOLERANCES[-1]
    frame["ratio to previous level"] = frame[f"time, tol {default:g} [s]"] / frame[f"time, tol {default:g} [s]"].shift()
    newton = _newton_comparison(problem, newton_level, 1 if args.quick else 3)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    frame.to_csv(out / "ehl_speed.csv", index=False)
    newton.to_csv(out / "ehl_speed_newton.csv", index=False)
    with pd.option_context("display.width", 200, "display.max_columns", 40):
        print(frame.to_string(index=False, float_format=lambda v: f"{v:.4g}"))
        print(newton.to_string(index=False, float_format=lambda v: f"{v:.4g}"))
    if not args.quick:
        _verdicts(frame, newton)
    return frame


def _newton_comparison(problem, level, repeats) -> pd.DataFrame:
    """The dense Newton solver (grid sequencing from level 4, direct deformation, tolerance 1e-10) against the
    multigrid at each timed tolerance, on one level: times, ratio, |H_min difference|."""
    times, dense = [], None
    for _ in range(repeats):
        start = time.perf_counter()
        dense = solve_reference(problem, level)
        times.append(time.perf_counter() - start)
    dense_time = statistics.median(times)
    rows = []
    for tolerance in TOLERANCES:
        median, solution = _median_solve(problem, level, tolerance, max(repeats, 3))
        rows.append({"level": level, "nodes": grid_points(level), "multigrid tolerance": tolerance,
                     "dense Newton time [s]": dense_time, "multigrid time [s]": median, "ratio": dense_time / median,
                     "|H_min difference|": abs(solution.H_min - dense.H_min)})
    return pd.DataFrame(rows)


def _verdicts(frame: pd.DataFrame, newton: pd.DataFrame) -> None:
    default = TOLERANCES[-1]
    last = frame[frame["level"] == 12].iloc[0]
    seconds = last[f"time, tol {default:g} [s]"]
    print(f"issue 3: level 12 in {seconds:.3f} s at tol {default:g} (target < {TARGET_SECONDS} s): "
          f"{'met' if seconds < TARGET_SECONDS else 'NOT met'}; time ratio per level doubling 8 -> 12: max "
          f"{frame[frame['level'] <= 12]['ratio to previous level'].max():.2f} (target <= {TARGET_RATIO})")
    for level, target in TARGETS_AT_DISCRETISATION.items():
        row = frame[frame["level"] == level].iloc[0]
        fits = [t for t in TOLERANCES if row[f"at discretisation accuracy, tol {t:g}"]]
        if not fits:
            print(f"issue 19: level {level}: no timed tolerance reaches discretisation accuracy")
            continue
        seconds = row[f"time, tol {fits[0]:g} [s]"]
        print(f"issue 19: level {level} at discretisation accuracy (tol {fits[0]:g}: algebraic error "
              f"{row[f'algebraic error, tol {fits[0]:g}']:.1e} < {row['discretisation error estimate']:.1e}) in "
              f"{seconds:.3f} s (target <= {target} s): {'met' if seconds <= target else 'NOT met'}")
    agreeing = newton[newton["|H_min difference|"] < NEWTON_AGREEMENT]
    if agreeing.empty:
        print(f"issue 19: no multigrid tolerance gives the dense Newton H_min to {NEWTON_AGREEMENT:g}")
    else:
        best = agreeing.loc[agreeing["ratio"].idxmax()]
        print(f"issue 19: dense Newton / multigrid at n = {int(best['nodes'])} (same H_min to {NEWTON_AGREEMENT:g}, "
              f"tol {best['multigrid tolerance']:g}): {best['ratio']:.0f}x (target >= {TARGET_NEWTON_RATIO:g}x): "
              f"{'met' if best['ratio'] >= TARGET_NEWTON_RATIO else 'NOT met'}")


if __name__ == "__main__":
    main()
