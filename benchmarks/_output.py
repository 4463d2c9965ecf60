"""Shared output of the benchmark scripts: CSV, optional plot, printed summary."""

from __future__ import annotations

from pathlib import Path


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
