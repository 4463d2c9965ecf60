"""What accuracy costs in time: elliptical Hertz contact, exact versus the closed-form fits.

For radius ratios r = R_major/R_minor from 1 to 100 this measures, per method
(``exact``: root-solved ellipticity with elliptic integrals; ``hamrock_brewe`` (1983) and
``brewe_hamrock_1977`` fits; ``timoshenko_table``, Saccheto's m, n table, only up to the ratio its
20 deg end covers, r = (1 + cos 20°)/(1 - cos 20°) = 32.2), the relative error of the semi-axes, the peak pressure and the
approach against ``exact``, and the median wall time of one call (several repeats).

    python benchmarks/hertz_elliptical.py            # full: 25 ratios, 7 repeats
    python benchmarks/hertz_elliptical.py --quick    # 5 ratios, 3 repeats (run by the tests)

Writes ``hertz_elliptical.csv`` and, with matplotlib, ``hertz_elliptical.png`` (error vs time)
into ``--out`` (default ``benchmarks/results``) and prints a summary table.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import timeit
from pathlib import Path

import numpy as np
import pandas as pd

sys.path.insert(0, str(Path(__file__).resolve().parent))  # the shared benchmarks/_output.py
from _output import write_results  # noqa: E402

from camcontact.contact.hertz_elliptical import METHODS, hertz_elliptical

LOAD, RX, E_REDUCED = 1000.0, 0.005, 2.3077e11
#: the largest radius ratio the Timoshenko table covers (theta = 20 deg)
TABLE_LIMIT = (1 + np.cos(np.radians(20))) / (1 - np.cos(np.radians(20)))


def measure(ratios, repeats: int, calls: int) -> pd.DataFrame:
    rows = []
    for ratio in ratios:
        exact = hertz_elliptical(LOAD, RX, RX * ratio, E_REDUCED)
        for method in METHODS:
            if method == "timoshenko_table" and ratio > TABLE_LIMIT:
                continue
            result = hertz_elliptical(LOAD, RX, RX * ratio, E_REDUCED, method=method)
            timer = timeit.Timer(lambda: hertz_elliptical(LOAD, RX, RX * ratio, E_REDUCED, method=method))
            seconds = statistics.median(t / calls for t in timer.repeat(repeat=repeats, number=calls))
            rows.append({
                "radius ratio [-]": ratio,
                "method": method,
                "error a_major [%]": 100 * (result.a_y / exact.a_y - 1),
                "error a_minor [%]": 100 * (result.a_x / exact.a_x - 1),
                "error p_max [%]": 100 * (result.p_max / exact.p_max - 1),
                "error approach [%]": 100 * (result.approach / exact.approach - 1),
                "median time [us]": 1e6 * seconds,
            })
    return pd.DataFrame(rows)


def summary(frame: pd.DataFrame) -> pd.DataFrame:
    errors = [c for c in frame.columns if c.startswith("error")]
    grouped = frame.groupby("method")
    table = grouped[errors].agg(lambda s: s.abs().max())
    table.columns = [c.replace("error", "max |error|") for c in errors]
    table["median time [us]"] = grouped["median time [us]"].median()
    return table.sort_values("median time [us]")


def plot(frame: pd.DataFrame, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 4))
    for method, group in frame.groupby("method"):
        worst = group[[c for c in frame.columns if c.startswith("error")]].abs().max(axis=1)
        ax.scatter(group["median time [us]"], np.maximum(worst, 1e-14), label=method, s=18)
    ax.set(xscale="log", yscale="log", xlabel="median time per call [µs]",
           ylabel="worst relative error vs exact [%]", title="Elliptical Hertz: accuracy vs time")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv: list[str] | None = None) -> pd.DataFrame:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="few ratios and repeats (for the tests)")
    parser.add_argument("--out", default=str(Path(__file__).parent / "results"), help="output folder")
    args = parser.parse_args(argv)
    ratios = np.logspace(0, 2, 5 if args.quick else 25)
    frame = measure(ratios, repeats=3 if args.quick else 7, calls=20 if args.quick else 200)
    return write_results(frame, args.out, "hertz_elliptical", plot, summary)


if __name__ == "__main__":
    main()
