"""Shared pieces of the benchmark scripts: median timing, CSV, optional plot, printed summary."""

from __future__ import annotations

import argparse
import os
import statistics
import time
from pathlib import Path


def arguments(doc: str, quick_help: str, argv=None) -> argparse.Namespace:
    """The common options of a benchmark script: ``--quick`` (``quick_help``), ``--repeats`` (default 3) and
    ``--out`` (default benchmarks/results); ``doc`` the script's docstring (its first line the description)."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help=quick_help)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "results"))
    return parser.parse_args(argv)


def timed(run, repeats: int):
    """(result of the last of ``repeats`` calls of ``run()``, their median wall time [s])."""
    times, result = [], None
    for _ in range(repeats):
        start = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - start)
    return result, statistics.median(times)


def write_results(frame, out, name, plot, summary):
    """Write ``<name>.csv`` and (with matplotlib) ``<name>.png`` into ``out``; print ``summary(frame)``."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    frame.to_csv(out / f"{name}.csv", index=False)
    try:
        plot(frame, out / f"{name}.png")
    except ImportError:
        print("matplotlib not installed: no plot")
    print(summary(frame).to_string(float_format=lambda v: f"{v:.3g}"))
    print(f"written to {out}")
    return frame
