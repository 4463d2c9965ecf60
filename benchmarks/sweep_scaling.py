"""Sweep throughput against workers: the same 200-case valve-train sweep serial, on 1 and 2 processes, on Dask.

The LS-1 roller valve train of the main job (Pan–Hamrock films, every 2 degrees of a cam turn) over
20 speeds (500-3000 rpm) × 10 roller radii (6-15 mm) = 200 cases, run by :meth:`Analysis.sweep`
with no executor (serial, here), a ``ProcessPoolExecutor`` of 1 and of 2 workers and, when the
``[dask]`` extra is installed, a ``dask.distributed`` LocalCluster of 2 worker processes. Each
configuration runs ``--repeats`` times; the table gives the median wall time, the throughput
(cases/s) and the speed-up against serial and against 1 worker, and checks that every executor
returns the identical table.

    python benchmarks/sweep_scaling.py            # full: 200 cases, 3 repeats
    python benchmarks/sweep_scaling.py --quick    # 8 cases, 1 repeat, no Dask (run by the tests)

Writes ``sweep_scaling.csv`` (and ``sweep_scaling.png`` with matplotlib) into ``--out``.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import attrs
import numpy as np
import pandas as pd

sys.path.insert(0, str(Path(__file__).resolve().parent))  # the shared benchmarks/_output.py
from _output import write_results  # noqa: E402

import camcontact as cc  # noqa: E402
from camcontact.scene_file import load_scene  # noqa: E402


def study(quick: bool):
    scene = load_scene()
    roller = attrs.evolve(scene.component, angle_step="2 deg", max_speed=None)
    analysis = cc.Analysis(roller, outputs=["h_min_cycle", "p_h_max", "jump_margin"], models=scene.models)
    speeds = np.linspace(500, 3000, 2 if quick else 20)
    radii = np.linspace(6, 15, 4 if quick else 10)
    grid = {"speed": [f"{n:g} rpm" for n in speeds], "follower.roller_radius": [f"{r:g} mm" for r in radii]}
    return analysis, grid


def _timed(run, repeats):
    times, frame = [], None
    for _ in range(repeats):
        start = time.perf_counter()
        frame = run()
        times.append(time.perf_counter() - start)
    return statistics.median(times), frame


def measure(quick: bool, repeats: int, dask: bool) -> pd.DataFrame:
    analysis, grid = study(quick)
    cases = int(np.prod([len(v) for v in grid.values()]))
    rows, reference = [], None

    def record(label, workers, run):
        nonlocal reference
        seconds, frame = _timed(run, repeats)
        identical = True if reference is None else frame.equals(reference)
        reference = frame if reference is None else reference
        rows.append({"executor": label, "workers": workers, "cases": cases, "median time [s]": seconds,
                     "cases per second": cases / seconds, "identical table": identical})

    analysis.sweep({k: v[:1] for k, v in grid.items()}, progress=False)  # warm this process as the workers
    record("serial", 1, lambda: analysis.sweep(grid, progress=False))
    for workers in (1, 2):
        with ProcessPoolExecutor(max_workers=workers) as pool:
            analysis.sweep({k: v[:1] for k, v in grid.items()}, executor=pool, progress=False)  # warm the workers
            record("process pool", workers, lambda: analysis.sweep(grid, executor=pool, progress=False))
    if dask:
        try:
            from dask.distributed import Client, LocalCluster
        except ImportError:
            print("dask.distributed not installed (the [dask] extra): no Dask row")
        else:
            with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
                    Client(cluster) as client:
                executor = client.get_executor()
                analysis.sweep({k: v[:1] for k, v in grid.items()}, executor=executor, progress=False)
                record("dask LocalCluster", 2, lambda: analysis.sweep(grid, executor=executor, progress=False))
    frame = pd.DataFrame(rows)
    serial = frame.loc[frame["executor"] == "serial", "median time [s]"].iloc[0]
    one = frame.loc[(frame["executor"] == "process pool") & (frame["workers"] == 1), "median time [s]"].iloc[0]
    frame["speed-up vs serial"] = serial / frame["median time [s]"]
    frame["speed-up vs 1 worker"] = one / frame["median time [s]"]
    return frame


def summary(frame: pd.DataFrame) -> pd.DataFrame:
    return frame.set_index(["executor", "workers"])


def plot(frame: pd.DataFrame, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 3.5))
    labels = [f"{e}\n{w} worker{'s' if w > 1 else ''}" for e, w in zip(frame["executor"], frame["workers"])]
    ax.bar(labels, frame["cases per second"])
    ax.set(ylabel="cases per second", title=f"{frame['cases'].iloc[0]}-case valve-train sweep")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv: list[str] | None = None) -> pd.DataFrame:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="8 cases, 1 repeat, no Dask (for the tests)")
    parser.add_argument("--repeats", type=int, default=None, help="runs per configuration (default 3, quick 1)")
    parser.add_argument("--no-dask", action="store_true", help="leave out the Dask LocalCluster row")
    parser.add_argument("--out", default=str(Path(__file__).parent / "results"), help="output folder")
    args = parser.parse_args(argv)
    repeats = args.repeats or (1 if args.quick else 3)
    frame = measure(args.quick, repeats, dask=not (args.quick or args.no_dask))
    return write_results(frame, args.out, "sweep_scaling", plot, summary)


if __name__ == "__main__":
    main()
