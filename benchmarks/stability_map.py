"""Stability of the line-contact multigrid solver over the Moes map: converged, attempts, work units, time.

Issue 19's map: level 9 (3585 nodes), M in {0.5, 1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 3000} x L in
{0, 1, 2, 5, 10, 15, 20, 25, 30} (108 cases), Roelands (z 0.68) and Dowson–Higginson with alpha = 2.2e-8 1/Pa,
which sets the pressure scale p_h = alpha-bar / alpha the two laws need. At L = 0 (isoviscous: alpha-bar = 0) that
scale does not follow from L, so those cases take p_h = 1 GPa (``--isoviscous-pressure``); the viscosity law does
not use it there, only the density law. Per case: the status (``converged``, ``warning``: not converged after every
attempt, ``error``: every attempt diverged or failed), the attempts the solver's ladder ran, the work units (finest-
grid relaxation sweeps), the wall time, H_min and H0, and the record's message.

    python benchmarks/stability_map.py            # level 9, the whole map (about 25 s)
    python benchmarks/stability_map.py --quick    # level 6, a 4 x 3 corner of the map (the tests run this)

Prints the status, attempts, work units and time as M x L tables and writes ``stability_map.csv`` into ``--out``.
Timings are reported, never asserted.
"""

from __future__ import annotations

import argparse
import os
import time
import warnings
from pathlib import Path

import pandas as pd

from camcontact.ehl.line_multigrid import solve_multigrid
from camcontact.ehl.line_problem import LineEHLProblem
from camcontact.errors import ConvergenceError, ConvergenceWarning

M_VALUES = (0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0, 3000.0)
L_VALUES = (0.0, 1.0, 2.0, 5.0, 10.0, 15.0, 20.0, 25.0, 30.0)
QUICK = ((0.5, 10.0, 100.0, 1000.0), (0.0, 10.0, 25.0))


def attempts_of(message: str) -> int:
    """Attempts the ladder ran, from the record's message: its top-level parts ("; " outside parentheses) name each
    attempt that failed or did not converge; the kept one adds one unless every attempt failed."""
    parts, depth, current = [], 0, ""
    for char in message:
        depth += (char == "(") - (char == ")")
        current += char
        if depth == 0 and current.endswith("; "):
            parts.append(current)
            current = ""
    parts.append(current)
    named = sum(1 for part in parts if " failed (" in part or " did not converge (" in part)
    kept_a_failed_one = "every attempt diverged" in message or "kept the smallest residual" in message
    return named + (0 if kept_a_failed_one else 1)


def solve_case(M: float, L: float, level: int, isoviscous_pressure: float) -> dict:
    """One case of the map: its status, attempts, work units, time and films."""
    problem = LineEHLProblem(M=M, L=L, alpha=2.2e-8, z=0.68,
                             pressure_scale=isoviscous_pressure if L == 0.0 else None)
    start = time.perf_counter()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ConvergenceWarning)
        try:
            solution = solve_multigrid(problem, level)
        except ConvergenceError as error:
            record = error.record
            return {"M": M, "L": L, "status": "error", "attempts": attempts_of(str(error)),
                    "work units": record.work_units[-1] if record is not None and record.work_units else float("nan"),
                    "time [s]": time.perf_counter() - start, "H_min": float("nan"), "H0": float("nan"),
                    "message": str(error)[:300]}
    record = solution.record
    warned = any(issubclass(w.category, ConvergenceWarning) for w in caught)
    return {"M": M, "L": L, "status": "warning" if warned or not record.converged else "converged",
            "attempts": attempts_of(record.message), "work units": record.work_units[-1] if record.work_units else 0.0,
            "time [s]": time.perf_counter() - start, "H_min": solution.H_min, "H0": solution.H0,
            "message": record.message[:300]}


def main(argv: list[str] | None = None) -> pd.DataFrame:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--level", type=int, default=None)
    parser.add_argument("--isoviscous-pressure", type=float, default=1e9, help="p_h [Pa] of the L = 0 cases")
    parser.add_argument("--out", default=str(Path(__file__).parent / "results"))
    args = parser.parse_args(argv)
    os.environ.setdefault("NUMBA_NUM_THREADS", "1")
    level = args.level or (6 if args.quick else 9)
    M_values, L_values = QUICK if args.quick else (M_VALUES, L_VALUES)
    solve_multigrid(LineEHLProblem(M=20, L=10), 5)  # compile / load the kernels first
    rows = []
    for M in M_values:
        for L in L_values:
            row = solve_case(M, L, level, args.isoviscous_pressure)
            rows.append(row)
            print(f"M {M:g}, L {L:g}: {row['status']}, {row['attempts']} attempt(s), {row['work units']:.0f} WU, "
                  f"{row['time [s]']:.2f} s", flush=True)
    frame = pd.DataFrame(rows)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    frame.to_csv(out / "stability_map.csv", index=False)
    for column in ("status", "attempts", "work units", "time [s]"):
        table = frame.pivot(index="M", columns="L", values=column)
        print(f"\n{column} (rows M, columns L):")
        print(table.to_string(float_format=lambda v: f"{v:.3g}"))
    counts = frame["status"].value_counts().to_dict()
    print(f"\nlevel {level}: {len(frame)} cases: {counts}; written to {out}")
    return frame


if __name__ == "__main__":
    main()
