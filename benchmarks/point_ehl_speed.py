"""Speed of the point-contact multigrid solver: wall time per grid, and H_c, H_min per grid.

Targets (issue, 2-core machine): circular contact M = 20, L = 10 (Roelands, Dowson–Higginson)
converged on 257 x 257 in under 5 s and on 513 x 513 in under 20 s.

    python benchmarks/point_ehl_speed.py            # 129^2, 257^2, 513^2; median of 3 runs each
    python benchmarks/point_ehl_speed.py --quick    # 65^2, 129^2; 1 run (the tests run this)
    python benchmarks/point_ehl_speed.py --heavy    # also M = 1000, L = 10 (incompressible) per grid
    python benchmarks/point_ehl_speed.py --relaxation point   # the point-wise sweep instead of lines

The grid-convergence columns give the change of H_c and H_min from the previous (coarser) grid.
Numba compilation is excluded (one warm-up solve first). Prints a table and writes
``point_ehl_speed.csv`` (and a plot with matplotlib) into ``--out``.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import pandas as pd

sys.path.insert(0, str(Path(__file__).resolve().parent))  # the shared benchmarks/_output.py

from _output import write_results  # noqa: E402

from camcontact.ehl.point_multigrid import PointMultigridSettings, solve_point_multigrid  # noqa: E402
from camcontact.ehl.point_problem import PointEHLProblem, point_grid_points  # noqa: E402
from camcontact.models.film_point import nijenbanning_film  # noqa: E402

TARGETS = {5: 5.0, 6: 20.0}  #: level -> target wall time [s]


def main(argv: list[str] | None = None) -> pd.DataFrame:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--repeats", type=int, default=None)
    parser.add_argument("--out", default=str(Path(__file__).parent / "results"))
    parser.add_argument("--heavy", action="store_true", help="also M = 1000, L = 10 (incompressible)")
    parser.add_argument("--relaxation", choices=("line", "point"), default="line")
    args = parser.parse_args(argv)
    levels = (3, 4) if args.quick else (4, 5, 6)
    repeats = args.repeats or (1 if args.quick else 3)
    settings = PointMultigridSettings(relaxation=args.relaxation)
    cases = [("M = 20, L = 10", PointEHLProblem(M=20, L=10))]
    if args.heavy:
        cases.append(("M = 1000, L = 10, incompressible", PointEHLProblem(M=1000, L=10, density="incompressible")))
    solve_point_multigrid(cases[0][1], 2, settings=settings)  # compile / load the kernels
    rows = []
    for label, problem in cases:
        previous = None
        for level in levels:
            times, solution = [], None
            for _ in range(repeats):
                start = time.perf_counter()
                solution = solve_point_multigrid(problem, level, settings=settings)
                times.append(time.perf_counter() - start)
            hc, hmin = solution.moes_film()
            rows.append({
                "problem": label, "relaxation": args.relaxation, "level": level,
                "nodes per direction": point_grid_points(level), "median time [s]": statistics.median(times),
                "target [s]": TARGETS.get(level, float("nan")) if problem.M == 20 else float("nan"),
                "cycles": solution.record.cycles, "work units": solution.record.work_units[-1],
                "converged": solution.record.converged, "H_c": solution.H_c, "H_min": solution.H_min,
                "H_c Moes": hc, "H_min Moes": hmin,
                "H_c Nijenbanning": float(nijenbanning_film(problem.M, problem.L, problem.D)),
                "load error": solution.record.load_errors[-1],
                "change H_c [%]": 100 * (solution.H_c / previous["H_c"] - 1) if previous else float("nan"),
                "change H_min [%]": 100 * (solution.H_min / previous["H_min"] - 1) if previous else float("nan"),
            })
            previous = rows[-1]
    frame = pd.DataFrame(rows)
    return write_results(frame, args.out, "point_ehl_speed", _plot, lambda f: f)


def _plot(frame: pd.DataFrame, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5, 4))
    for label, rows in frame.groupby("problem", sort=False):
        ax.loglog(rows["nodes per direction"] ** 2, rows["median time [s]"], "o-", label=label)
    targets = frame.dropna(subset=["target [s]"])
    ax.loglog(targets["nodes per direction"] ** 2, targets["target [s]"], "k_", markersize=20, label="target")
    ax.set(xlabel="nodes", ylabel="wall time [s]",
           title=f"point EHL multigrid ({frame['relaxation'].iloc[0]} relaxation)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


if __name__ == "__main__":
    main()
